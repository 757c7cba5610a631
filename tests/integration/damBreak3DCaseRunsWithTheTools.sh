#!/bin/bash
# The SPHERIC Test 2 tutorial, very coarse (dx = 80 mm), through the whole tool chain: the gmsh
# tank-minus-obstacle geometry gives tank and obstacle walls, the water column is filled, a few
# steps run, the function objects write P, H and the front, and compareWithExperiment reads them.
. "$SPHCAST_TEST_TOOLS"
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/damBreak3D" && pwd)
mkdir -p "$scratch/case"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/validationData" \
    "$tutorial/compareWithExperiment" "$scratch/case/"
rm -rf "$scratch/case/constant/particles"
cd "$scratch/case"
sed -i 's/0\.04;/0.08;/; s/ 0\.1;/ 0.2;/' system/particleizeMoldDict
sed -i 's/0\.04;/0.08;/' system/setCastFieldsDict
sed -i 's/ 0\.1;/ 0.2;/' system/sphSchemes
setEntry system/controlDict endTime 0.02
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
grep -q "Patch obstacle (shell, fixedWall) -> cloud obstacle: [1-9]" log.particleizeMold ||
    fail "no obstacle particles: $(grep Patch log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
for f in pressure/0/p heights/0/height front/0/front; do
    [ -f "postProcessing/$f" ] || fail "no postProcessing/$f"
done
# The sensors on the obstacle are dry; H4 stands in the column (0.55 m, whole 80 mm layers: 0.56).
awk '!/^#/ { last = $0 } END { split(last, v); if (v[2] != "nan") exit 1 }' \
    postProcessing/pressure/0/p || fail "P1 is wet at the start: $(tail -1 postProcessing/pressure/0/p)"
awk '!/^#/ { h = $5 } END { if (h < 0.5 || h > 0.6) exit 1 }' postProcessing/heights/0/height ||
    fail "H4: $(tail -1 postProcessing/heights/0/height)"
python3 compareWithExperiment > log.compare 2>&1 || fail "compareWithExperiment: $(tail -3 log.compare)"
grep -q "^P1: " log.compare || fail "no P1 comparison: $(cat log.compare)"
pass "damBreak3D: walls and obstacle from gmsh, water, probes, heights and the comparison script"
