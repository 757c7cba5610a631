#!/bin/bash
# The Poiseuille flow tutorial (Morris, Fox & Zhu 1997) through the whole tool chain at 10 and
# 20 rows across (80 and 320 water particles, a few seconds on one thread): the plates from
# particleizeMold in 2D, spanning the periodic interval so that their lattice is periodic, the
# water from setCastFields, sphCastFoam to steady state with the probes, compareWithSeries
# against the series solution. Bounds of tests/unit/sph/PoiseuilleFlowTest.cpp, which builds
# the same case by hand and measures there the same errors as this case (10, 20 rows: 0.0136,
# 0.0043 at t = 0.1 s; 0.0244, 0.0123 at steady state).
. "$SPHCAST_TEST_TOOLS"
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/poiseuilleFlow" && pwd)

# runChannel ROWS: the tutorial at ROWS rows across in $scratch/ROWS; leaves log.compare there.
runChannel() {
    local rows=$1 plate=$(( 3 * 8 * $1 / 10 ))   # Lx = 0.8 mm: 8 rows/10 columns, 3 layers
    mkdir -p "$scratch/$rows"
    cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/setResolution" \
        "$tutorial/compareWithSeries" "$scratch/$rows/"
    rm -rf "$scratch/$rows/constant/particles"
    cd "$scratch/$rows" || fail "cannot enter $scratch/$rows"
    python3 setResolution "$rows" > log.setResolution 2>&1 || fail "setResolution: $(cat log.setResolution)"
    particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
    for patch in lowerPlate upperPlate; do
        grep -q "Patch $patch (shell, fixedWall) -> cloud plates: $plate particles; nearest-neighbour distance / dx: min 1, mean 1, max 1" \
            log.particleizeMold || fail "$rows rows, $patch: $(grep Patch log.particleizeMold)"
    done
    setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
    sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
    python3 compareWithSeries > log.compare 2>&1 || fail "compareWithSeries: $(tail -3 log.compare)"
    head -3 log.compare
}

# error ROWS TIME: the largest |v - v_exact| / v_max printed for t = TIME.
error() { awk -v t="t = $2" 'index($0, t) == 1 { print $NF }' "$scratch/$1/log.compare"; }

runChannel 10
runChannel 20
for t in "0.1 s" "1 s (steady)"; do
    e=$(error 20 "$t")
    [ -n "$e" ] || fail "no error at t = $t: $(cat "$scratch/20/log.compare")"
    awk -v e="$e" 'BEGIN { exit !(e < 0.02) }' || fail "20 rows, t = $t: error $e, not below 0.02"
done
awk -v a="$(error 10 "1 s (steady)")" -v b="$(error 20 "1 s (steady)")" 'BEGIN { exit !(b < a) }' ||
    fail "the steady error does not fall from 10 to 20 rows"
pass "poiseuilleFlow: periodic plates from 2D gmsh curves; 20 rows within 0.02 v_max of the series, closer than 10"
