#!/bin/bash
# Two heat validation tutorials at their coarsest resolution, through their own Allrun and
# comparison scripts, on copies laid out as in the project (tutorials/validation/<case> beside
# an etc/ with RunFunctions and a platforms/bin that is $SPHCAST_BIN):
# - semiInfiniteConduction at 12 particles across the heated length 4 sqrt(alpha t): the erf
#   profile's L2 error / jump. tests/unit/thermal/ConductionValidationTest.cpp measures 0.37 %
#   on the same lattice; through the tools 0.375 % (1.16 % at t = 25 s, 6 across). With the held
#   surface on the first held layer's centres it was 0.99 % (and 1.88 %), a held surface dx/2
#   off the body's particles gives 6.0 %. Bounds: 0.6 % and 1.8 %.
# - stefanProblem at 12.5 particles across the frozen layer: the worst front error over four
#   writes against Neumann's solution: 2.9 % (the front moves by whole lattice columns through a
#   4 K mushy range; 0.62 % at 50 across). With the harmonic mean of kappa across that range it
#   was 4.8 %, with the held surface on the held layer's centres too 4.3 %. Bound: 4 %. The
#   energyBalance books close to round-off, about 1e-16 of the heat content a step (2.5e-15
#   measured over 2,136 steps); bound 1e-12.
# - stefanProblem restarted from its second write: the held box's surface, placed at the start,
#   is read back with the cloud, and the end is the uninterrupted run's bytes.
# About 5 s on one thread.
. "$SPHCAST_TEST_TOOLS"
findVtkPython

# runTutorial CASE RESOLUTION: the tutorial's Allrun at RESOLUTION in a copy; prints its log.
runTutorial() { (runValidationTutorial "$1" "$2" && cat log.compare*) || exit 1; }

# below BOUND VALUE WHAT: fails unless VALUE < BOUND.
below() {
    [ -n "$2" ] || fail "$3: no value printed"
    awk -v b="$1" -v v="$2" 'BEGIN { exit !(v < b) }' || fail "$3: $2, not below $1"
}

runTutorial semiInfiniteConduction 12
log=$scratch/tutorials/validation/semiInfiniteConduction/log.compareWithErf
below 0.006 "$(awk '/^t = 100 s:/ { print $NF }' "$log")" "semi-infinite body, erf L2 at t = 100 s"
below 0.018 "$(awk '/^t = 25 s:/ { print $NF }' "$log")" "semi-infinite body, erf L2 at t = 25 s (6 particles across)"

runTutorial stefanProblem 12.5
log=$scratch/tutorials/validation/stefanProblem/log.compareWithNeumann
[ "$(grep -c '^t = ' "$log")" -eq 4 ] || fail "stefanProblem: not four written times"
below 0.04 "$(awk '/^worst front error/ { print $NF }' "$log")" "Neumann front, worst error"
below 1e-12 "$(awk '/^energyBalance:/ { print $NF }' "$log")" "energyBalance relative imbalance"

# The held box's surface, placed at the start (no normal or wallDistance from setCastFields), is
# written with the cloud: a restart from the second write reads it back instead of placing it
# again, and ends on the uninterrupted run's bytes.
case=$scratch/tutorials/validation/stefanProblem
grep -q "held surface of cloud 'wall' placed midway" "$case/log.sphCastFoam" ||
    fail "stefanProblem: the held box's surface was not placed"
mkdir -p "$scratch/uninterrupted"
cp "$case/10.6619/melt.vtp" "$case/10.6619/wall.vtp" "$scratch/uninterrupted/"
(cd "$case" && rm -rf 7.99643 10.6619 && setEntry system/controlDict startFrom latestTime &&
    sphCastFoam > log.restart 2>&1) || fail "stefanProblem restart: $(tail -3 "$case/log.restart")"
! grep -q "held surface of cloud" "$case/log.restart" ||
    fail "stefanProblem restart: the held surface was placed again"
for cloud in melt wall; do
    cmp -s "$case/10.6619/$cloud.vtp" "$scratch/uninterrupted/$cloud.vtp" ||
        fail "stefanProblem restart: $cloud at the end differs from the uninterrupted run"
done
pass "heat tutorials through the tools: erf profile within 0.6 %, Neumann front within 4 %, books closed, a held box's restart bit for bit"
