#!/bin/bash
# tutorials/conicalMold at dx = 4.5 mm (3,372 melt particles; about 45 s on one core): AC4CH at
# 970 K in a cone held at 300 K, solidified to the end, against enthalpyReference.py's conduction
# and level-drop feeding. compareWithReference --check: solid within 5 % of the reference and
# f_s = 0.9 within 10 % (measured +0.3 % and +1.8 %; +29 % solid with the held surface on the mold's
# first layer, half a spacing behind the wall), the melt's volume lost within 10 % of the share
# the reference's feeding draws (4.8 % and 4.9 %), the sink's mean distance from the reference's
# funnel, r = 0 to 40 mm, below 1 mm (0.64 mm; it does not fall with dx), the last particles to
# freeze within a quarter of the top's radius of the axis and a tenth of the height of the top
# there; the cooling mode's flow steps are of its own maxCo (1, not controlDict's 0.25).
# With the cavitation floor at 0 instead of -5,000 Pa the melt feeds by gravity alone and
# fails: 2.9 % lost, the sink 0.92 mm off.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
copyTutorial conicalMold
./setResolution 4.5 > /dev/null || fail "setResolution 4.5"
PYTHON=$python ./Allrun > log.Allrun 2>&1 || { cat log.Allrun >&2; fail "conicalMold: Allrun"; }
cat log.compareWithReference
grep -q "^Run health: no warnings" log.sphCastFoam || fail "health warnings in the cone"
# the log's account of the work skipped: frozen metal away from the melt computes no flow rates
# (about half of the particle-steps in this cone), and the cooling mode's flow steps against
# the acoustic steps of controlDict's maxCo over the same time (hundreds of times more)
awk '/flow rates of frozen metal with no melt within two neighbour hops:/ {
         found = 1; share = $17; sub(/\(/, "", share); if (share < 20 || share > 80) exit 1 }
     END { if (!found) exit 1 }' log.sphCastFoam ||
    fail "no sensible account of the skipped flow rates: $(grep -A3 'Work skipped' log.sphCastFoam)"
awk '/the cooling mode: / { found = 1; if ($15 + 0 < 50 * $4) exit 1 } END { if (!found) exit 1 }' \
    log.sphCastFoam || fail "no sensible account of the cooling mode: $(grep 'the cooling mode' log.sphCastFoam)"
# the cooling mode's flow steps take its own maxCo (1), not controlDict's (0.25): at most
# dx / c = 9e-05 s at c = 50 m/s and dx = 4.5 mm (less by the melt's |U| / c, 2 % in the mode,
# where |U| < movingSpeed = 1 m/s), on every log line of the mode
awk '/cooling: heat steps of/ { n++; step = $0; sub(/.*\(the last /, "", step); sub(/ s\).*/, "", step); step += 0
                                if (step < 9e-5 * 0.975 || step > 9e-5 * 1.000001) bad = step }
     END { if (bad != "") print "a flow step of " bad " s"; exit (n == 0 || bad != "") }' \
    log.sphCastFoam || fail "the cooling mode's flow steps are not dx / c"
"$python" compareWithReference --check > /dev/null || fail "the cone against the reference"
pass "conicalMold solidifies, feeds its shrinkage and leaves its sink as the reference does"
