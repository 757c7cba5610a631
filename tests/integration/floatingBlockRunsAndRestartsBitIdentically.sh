#!/bin/bash
# A rigid body through the whole tool chain: particleizeMold fills a block (mode volume) beside
# the tank's shell, constant/dynamicBodies makes it a body of half the water's density, held for
# 0.02 s, sliding along z; it falls into the water and floats. Its state is in every time
# folder's uniform/dynamicBodies, its history in postProcessing/dynamicBodies, and a run stopped
# at 0.1 s and restarted writes the uninterrupted run's 0.15 and 0.2 byte for byte (block.vtp and
# the body's state too). castPostProcess's bodyMotion reports it. Pressed by a press's curve
# (appliedPressure against time) it logs and reports the load and floats deeper. Errors in
# constant/dynamicBodies name the file, the line and the key.
. "$SPHCAST_TEST_TOOLS"
coarseWaterTank "$scratch/whole"  # dx = 10 mm: 500 water particles, the water's surface at 0.05
cat > constant/geometry/block.geo <<'GEO'
SetFactory("OpenCASCADE");
Box(1) = {0.03, 0.03, 0.07, 0.04, 0.04, 0.02};
Physical Volume("block") = {1};
GEO
sed -i 's/^geometry .*/geometry ("tank.geo" "block.geo");/' system/particleizeMoldDict
sed -i 's/^\( *tankWall { cloud tank; type fixedWall; mode shell; }\)/\1\n    block { cloud block; type rigidBody; mode volume; }/' system/particleizeMoldDict
sed -i 's/walls *(tank);/walls (tank block);/' constant/physicsModels
cat > constant/dynamicBodies <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object dynamicBodies; }
block
{
    density         500;
    translation     (0 0 1);
    rotation        locked;
    releaseTime     0.02;
}
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
cp -r "$scratch/whole" "$scratch/stopped"
cp -r "$scratch/whole" "$scratch/bad"
cp -r "$scratch/whole" "$scratch/pressed"

sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
expectTimeStepping log.sphCastFoam
grep -q "^Body block: cloud block (32 particles), mass 0.016 kg" log.sphCastFoam ||
    fail "no body line: $(grep -m1 '^Body' log.sphCastFoam)"
for t in 0 0.1 0.2; do
    [ -f "$t/block.vtp" ] || fail "time $t has no block.vtp"
    grep -q "^ *displacement" "$t/uniform/dynamicBodies" || fail "time $t has no body state"
done
history=postProcessing/dynamicBodies/0/block.dat
[ -f "$history" ] || fail "no $history"
# held to 0.02 s, then it falls 0.02 m onto the water (0.064 s) and floats: density 500 gives a
# draft of half its 0.02 m height, a displacement of -0.03 at rest; it never reaches the floor
awk '!/^#/ && $1 < 0.0199 && $4 != 0 { bad = 1 } END { exit bad }' "$history" ||
    fail "the block moved before its release"
awk '!/^#/ && ($2 != 0 || $3 != 0) { bad = 1 } END { exit bad }' "$history" ||
    fail "the block left its axis"
awk '!/^#/ { if ($4 < lowest) lowest = $4; last = $4 }
     END { printf "lowest %.4f, last %.4f\n", lowest, last; exit !(lowest > -0.06 && last < -0.015) }' \
    "$history" > depth.txt || fail "the block did not float: $(cat depth.txt)"

# castPostProcess's bodyMotion: the history as a CSV, plots, a line of the report; with `gap`,
# the block's bottom (z = 0.07 at the start) above the tank's floor, which must be 70 mm plus the
# final travel, and the water's volume (500 particles of 1 cm^3 at rho_s within 0.1 %) over the
# tank's 0.01 m^2, which must be 50 mm
cat > system/castPostProcessDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }
float { type bodyMotion; body block;
        gap { cloud water; faceStart (0 0 0.07); floorPoint (0 0 0); area 0.01; } }
DICT
castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess: $(tail -5 log.castPostProcess)"
grep -q "^Body block: travelled .* mm by t = 0.2 s, never at an end stop" postProcessing/castReport.md ||
    fail "no body line in the report: $(grep -m1 Body postProcessing/castReport.md)"
gapLine=$(grep -m1 "^The gap at t = 0.2 s" postProcessing/castReport.md) ||
    fail "no gap line in the report: $(grep -m1 gap postProcessing/castReport.md)"
lastTravel=$(awk '!/^#/ { z = $4 } END { printf "%.6f", z }' "$history")
echo "$gapLine" | awk -v travel="$lastTravel" '{
    for (i = 1; i <= NF; ++i) {
        if ($i == "face") face = $(i + 1)
        if ($(i + 1) == "mm" && $(i + 2) == "over") spread = $i
    }
    expected = 70 + 1000 * travel
    exit !(face > expected - 0.01 && face < expected + 0.01 && spread > 49.95 && spread < 50.05) }' ||
    fail "gap or volume balance off (travel $lastTravel m): $gapLine"
pass "bodyMotion's gap: $gapLine"
rows=$(grep -c . postProcessing/float/block.csv)
steps=$(grep -vc '^#' postProcessing/dynamicBodies/0/block.dat)
[ "$rows" -eq $((steps + 1)) ] || fail "block.csv has $rows lines for $steps steps"

cd "$scratch/stopped"
setEntry system/controlDict endTime 0.1
sphCastFoam > log.1 2>&1 || fail "first part: $(tail -5 log.1)"
setEntry system/controlDict endTime 0.2
sphCastFoam > log.2 2>&1 || fail "restart: $(tail -5 log.2)"
for t in 0.15 0.2; do
    sameTimeFolder "$scratch/whole/$t" "$t" || fail "time $t differs from the uninterrupted run"
done

# a press's curve on the block: 0 to 50 Pa on its 16 cm^2 top from 0.05 to 0.1 s, then held
# (0.08 N, half its weight): logged with the run (the history's load the curve's within 1e-9 N,
# its times printed to 10 digits), reported, and it floats deeper
cd "$scratch/pressed"
sed -i 's/^ *releaseTime *0.02;/&\n    appliedPressure ((0.05 0) (0.1 50));\n    pressedArea 0.0016;\n    pressDirection (0 0 -1);/' constant/dynamicBodies
sphCastFoam > log.sphCastFoam 2>&1 || fail "pressed: $(tail -5 log.sphCastFoam)"
grep -q "pressed at 50 Pa from t = 0.1 s (2 points) on 0.0016 m^2 along (0 0 -1): 0.08 N" log.sphCastFoam ||
    fail "the log does not state the press's curve: $(grep -m1 '^Body' log.sphCastFoam)"
awk '!/^#/ { load = -$17; exact = $1 <= 0.05 ? 0 : $1 >= 0.1 ? 0.08 : 0.08 * ($1 - 0.05) / 0.05
             d = load - exact; if (d < 0) d = -d; if (d > 1e-9) bad = 1 } END { exit bad }' \
    postProcessing/dynamicBodies/0/block.dat || fail "the history's applied load is not the curve's"
cp ../whole/system/castPostProcessDict system/
castPostProcess > log.castPostProcess 2>&1 || fail "pressed castPostProcess: $(tail -5 log.castPostProcess)"
grep -q "the press's largest load 0.08 N at t = 0.1.* s, 0.08 N at the end" postProcessing/castReport.md ||
    fail "no press's load in the report: $(grep -m1 Body postProcessing/castReport.md)"
freeLast=$(awk '!/^#/ { z = $4 } END { print z }' ../whole/postProcessing/dynamicBodies/0/block.dat)
awk -v free="$freeLast" '!/^#/ { z = $4 } END { printf "pressed block at %.4f m, free %.4f m\n", z, free; exit !(z < free - 0.002) }' \
    postProcessing/dynamicBodies/0/block.dat || fail "the pressed block does not float deeper"

cd "$scratch/bad"
sed -i 's/^block$/blocks/' constant/dynamicBodies
sphCastFoam > log.bad 2>&1 && fail "a body of a cloud that is no wall ran"
grep -q "dynamicBodies:2:.*body 'blocks' moves cloud 'blocks', which is not one of the flow's walls" log.bad ||
    fail "the error does not name the body: $(grep -m1 -i error log.bad)"
sed -i 's/^blocks$/block/; s/density *500;/density 500; mass 0.1;/' constant/dynamicBodies
sphCastFoam > log.bad 2>&1 && fail "a body with mass and density ran"
grep -q "needs either 'mass' (kg) or 'density'" log.bad || fail "mass and density: $(grep -m1 -i error log.bad)"
[ ! -d 0.05 ] || fail "a refused run wrote a time"
pass "floating block: held, falls, floats at $(cat "$scratch/whole/depth.txt"); restart bit for bit; bad bodies refused"
