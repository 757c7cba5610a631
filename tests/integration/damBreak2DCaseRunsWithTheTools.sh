#!/bin/bash
# The 2D dam break tutorial (Martin & Moyce 1952) through the whole tool chain at its own
# resolution, a/dx = 20 (800 water particles, a few seconds on one thread): particleizeMold in
# 2D makes the tank from the gmsh curves, setCastFields the column, sphCastFoam runs to
# T = 3.5 with the front function object, and compareWithExperiment must find the front within
# the bounds of tests/unit/sph/DamBreak2DTest.cpp, which builds the same case by hand.
. "$SPHCAST_TEST_TOOLS"
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/damBreak2D" && pwd)
mkdir -p "$scratch/case"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/validationData" \
    "$tutorial/compareWithExperiment" "$scratch/case/"
rm -rf "$scratch/case/constant/particles"
cd "$scratch/case"
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
# floor 100 x 3, two sides 60 x 3, two corner squares 3 x 3, all exactly dx apart
grep -q "Patch tankWall (shell, fixedWall) -> cloud tank: 678 particles; nearest-neighbour distance / dx: min 1, mean 1, max 1" \
    log.particleizeMold || fail "tank walls: $(grep Patch log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
grep -q "Cloud water: 800 particles" log.setCastFields || fail "water: $(grep Cloud log.setCastFields)"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
python3 compareWithExperiment > log.compare 2>&1 || fail "compareWithExperiment: $(tail -3 log.compare)"
cat log.compare
# DamBreak2DTest: largest |Z - Z_measured| < 0.25 over T = 0.83 .. 3.35 (measured there 0.184),
# surge speed within 12 % of the measured 1.37 (1.27 there).
awk '/^largest/ { found = 1; if ($5 >= 0.25) exit 1 } END { if (!found) exit 1 }' log.compare ||
    fail "front error: $(grep largest log.compare)"
grep -q "over 5 measured points" log.compare || fail "not 5 measured points: $(grep largest log.compare)"
awk '/^surge speed/ { found = 1; r = $NF; sub(/\)/, "", r); if (r < 0.88 || r > 1.12) exit 1 }
     END { if (!found) exit 1 }' log.compare || fail "surge speed: $(grep surge log.compare)"
pass "damBreak2D: tank from 2D gmsh curves, the column, the front within 0.25 a of Martin & Moyce"
