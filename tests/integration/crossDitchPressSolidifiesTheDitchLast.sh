#!/bin/bash
# The crossDitchPress tutorial end to end, coarse (./setResolution 4: dx = 4 mm, about 4.5
# minutes on one core): the ladle pours its mass; the punch is held to 0.2 s, let go, falls on
# the metal and rests on it above its end stop (the metal carries its weight); the casting
# solidifies through both molds, and the punch stays on it above its end stop, carried by the
# solid metal to the end (before 2026-12-06 frozen metal gave a body no force, and the punch sank
# through the casting to its end stop). castPostProcess reports the gap against the volume
# balance and the last particle to freeze, which must lie over the ditch's crossing, in the
# ditch or the plate above it (the paper's Fig. 18; with the punch inside the casting it lay at
# the ditch's bottom, and with the punch on it, in the plate: 6 mm up at 4 mm, 4.2 mm up at 3 mm).
# No health stop (no particle through a mold), the heat books closed.
# At 4 mm, as at the tutorial's 3 mm, the ditch's sides lie half-way between lattice planes;
# pressAtASpacingThatDividesNothingHoldsTheMetal runs the press at 4.5 mm, where they do not.
. "$SPHCAST_TEST_TOOLS"
tutorial="$(dirname "$SPHCAST_TEST_TOOLS")/../../tutorials/crossDitchPress"
mkdir -p "$scratch/press"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/setResolution" "$scratch/press/"
cd "$scratch/press"
./setResolution 4 > /dev/null || fail "setResolution 4"
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"

sphCastFoam > log.press 2>&1 || fail "pour and press: $(tail -5 log.press)"
grep -q "^Inlet ladle: poured .* kg in .* layers, done" log.press || fail "the ladle did not finish"
history=postProcessing/dynamicBodies/0/upperMold.dat
# columns: time, travel x y z, velocity x y z, the metal's force x y z, the total force x y z,
# at the end stop (1/0); the end stop is 20.25 - 2 x 4 = 12.25 mm down
awk '!/^#/ && $1 < 0.1999 && $4 != 0 { bad = 1 } END { exit bad }' "$history" ||
    fail "the punch moved before its release at 0.2 s"
# The metal's force on the resting punch is read as its mean over the last 0.1 s: in the
# acoustic steps it jitters about the punch's weight with a standard deviation of 0.8 N (5.0 to
# 9.7 N from 0.3 to 0.6 s, 2026-12-07), so one step's value is a sample of that jitter.
awk '!/^#/ { z = $4; v = $7; stop = $14; if ($1 >= 0.4999) { n++; sum += $10 } }
     END { fz = n > 0 ? sum / n : 0
           printf "travel %.5f m, velocity %.2g m/s, metal force %.3f N (the mean of %d steps from 0.5 s)\n", z, v, fz, n
           exit !(z < -0.005 && z > -0.01225 && stop == 0 && v > -0.01 && v < 0.01 && n > 0 && fz > 7.0 && fz < 8.7) }' \
    "$history" > press.txt || fail "the punch does not rest on the metal at 0.6 s: $(cat press.txt)"
pass "pour and press: the punch rests on the metal above its stop, $(cat press.txt)"

setEntry system/controlDict endTime 400
setEntry system/controlDict writeInterval 5
sphCastFoam > log.solidify 2>&1 || fail "solidification: $(tail -5 log.solidify)"
grep -q "^Stopping: the casting is solid (endWhenSolid)" log.solidify ||
    fail "the casting did not solidify: $(grep -m1 Stopping log.solidify)"
history=postProcessing/dynamicBodies/0.6/upperMold.dat  # the second run's, from 0.6 s
awk '!/^#/ { z = $4; v = $7; fz = $10; if ($14 == 1) stopped = 1 }
     END { printf "travel %.5f m, velocity %.2g m/s, metal force %.3f N\n", z, v, fz
           exit !(!stopped && z > -0.01225 && z < -0.005 && v > -1e-3 && v < 1e-3 && fz > 7.0 && fz < 8.7) }' \
    "$history" > stop.txt ||
    fail "the punch is not carried by the solid casting above its end stop: $(cat stop.txt)"
pass "solidified; the solid casting carries the punch above its end stop: $(cat stop.txt)"

castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess: $(tail -5 log.castPostProcess)"
report=postProcessing/castReport.md
grep -q "^The gap at t = .*: the punch's face [0-9.]* mm above the floor" "$report" ||
    fail "no gap line: $(grep -m1 'The gap' "$report")"
last=$(sed -n 's/^- Last to solidify: (\([^)]*\)) m.*/\1/p' "$report")
echo "$last" | awk '{ exit !($1 > -0.012 && $1 < 0.012 && $2 > -0.012 && $2 < 0.012) }' ||
    fail "the last particle to freeze ($last) is not over the ditch's crossing"
imbalance=$(sed -n 's/.*imbalance [^(]*(\([0-9.e+-]*\) of the start.s heat content.*/\1/p' "$report")
awk -v x="$imbalance" 'BEGIN { exit !(x != "" && x < 1e-10 && x > -1e-10) }' ||
    fail "heat books open: $(grep -m1 imbalance "$report")"
pass "the last particle to freeze at ($last) m, over the ditch's crossing; heat books closed to $imbalance"
