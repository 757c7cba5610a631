#!/bin/bash
# The whole tool chain on a weakly compressible flow case: particleizeMold makes an open tank
# from gmsh geometry, setCastFields fills it with water, sphCastFoam runs the SPH flow. No
# particle leaves the tank, and a run stopped at 0.1 s and restarted gives the same 0.2 s files,
# byte for byte, as an uninterrupted run.
. "$SPHCAST_TEST_TOOLS"
coarseWaterTank "$scratch/whole"  # dx = 10 mm (500 water particles), to 0.2 s
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
cp -r "$scratch/whole" "$scratch/stopped"
# The first frame carries p, as the later ones: ParaView can colour the whole series by it.
grep -qa '<DataArray [^>]*Name="p"' 0/water.vtp || fail "0/water.vtp has no p"

sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
expectTimeStepping log.sphCastFoam
grep -q "^Density range " log.sphCastFoam || fail "no density range in the log"
grep -q "fluid water: 500 particles" log.sphCastFoam || fail "not 500 water particles"
castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess failed"
# Columns of cloudSummary: minX minY minZ maxX maxY = 10 11 12 13 14; the tank is [0, 0.1]^2 x z > 0.
awk -F, 'NR > 1 && ($10 < 0 || $11 < 0 || $12 < 0 || $13 > 0.1 || $14 > 0.1) { print; bad = 1 }
         END { exit bad }' postProcessing/cloudSummary/water.csv || fail "water left the tank"

cd "$scratch/stopped"
setEntry system/controlDict endTime 0.1
sphCastFoam > log.1 2>&1 || fail "first part: $(tail -5 log.1)"
setEntry system/controlDict endTime 0.2
sphCastFoam > log.2 2>&1 || fail "restart: $(tail -5 log.2)"
for t in 0.15 0.2; do
    sameTimeFolder "$scratch/whole/$t" "$t" || fail "time $t differs from the uninterrupted run"
done
pass "flow case: water stays in the tank; restart at 0.1 reproduces 0.15 and 0.2 bit for bit"
