#!/bin/bash
# A pouring inlet through the whole tool chain: setCastFields writes an empty water cloud
# (regions {}), constant/inlets pours into the tank through a disk 8 spacings across for 0.15 s.
# The mass poured is the inlet's rate times the pour's layers, every particle stays in the tank,
# the inlet's state is in uniform/inlets, and a run stopped at 0.1 s (mid-pour) and restarted
# writes the uninterrupted run's 0.2 and 0.3 byte for byte. Bad inlets are refused at their line.
. "$SPHCAST_TEST_TOOLS"
coarseWaterTank "$scratch/whole"  # the tank at dx = 10 mm
sed -i 's/column { type box; min (0 0 0); max (0.1 0.1 0.05); }//; s/rho hydrostatic;/rho standard;/' \
    system/setCastFieldsDict
setEntry system/controlDict endTime 0.3
cat > constant/inlets <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object inlets; }
tap
{
    centre      (0.05 0.05 0.09);
    direction   (0 0 -1);
    radius      0.04;
    speed       0.5;
    endTime     0.15;
}
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
grep -q "no regions: an empty cloud" log.setCastFields || fail "no empty cloud: $(tail -3 log.setCastFields)"
cp -r "$scratch/whole" "$scratch/stopped"
cp -r "$scratch/whole" "$scratch/bad"

sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
expectTimeStepping log.sphCastFoam
line=$(grep -m1 "^Inlet tap: .* particles a layer" log.sphCastFoam) || fail "no inlet line"
perLayer=$(echo "$line" | sed 's/^Inlet tap: \([0-9]*\) particles.*/\1/')
[ "$perLayer" -ge 45 ] || fail "only $perLayer particles a layer: $line"
# 0.15 s at 0.5 m/s through layers 0.01 m apart: 8 layers (the first at t = 0), then done
final=$(grep "^Inlet tap: poured" log.sphCastFoam | tail -1)
echo "$final" | grep -q "in 8 layers, done" || fail "not 8 layers: $final"
grep -q "^ *emittedLayers *8;" 0.3/uniform/inlets || fail "0.3/uniform/inlets: $(cat 0.3/uniform/inlets)"
awk -F, 'NR > 1 && ($10 < 0 || $11 < 0 || $12 < 0 || $13 > 0.1 || $14 > 0.1) { bad = 1 } END { exit bad }' \
    <(castPostProcess > /dev/null 2>&1; cat postProcessing/cloudSummary/water.csv) ||
    fail "water left the tank"

cd "$scratch/stopped"
setEntry system/controlDict endTime 0.1
sphCastFoam > log.1 2>&1 || fail "first part: $(tail -5 log.1)"
setEntry system/controlDict endTime 0.3
sphCastFoam > log.2 2>&1 || fail "restart: $(tail -5 log.2)"
for t in 0.2 0.3; do
    sameTimeFolder "$scratch/whole/$t" "$t" || fail "time $t differs from the uninterrupted run"
done

cd "$scratch/bad"
sed -i 's/speed       0.5;/speed 0.5; massRate 0.1;/' constant/inlets
sphCastFoam > log.bad 2>&1 && fail "an inlet with speed and massRate ran"
grep -q "inlets:2:.*inlet 'tap' needs either 'speed' (m/s) or 'massRate'" log.bad ||
    fail "the error does not name the inlet: $(grep -m1 -A1 -i error log.bad)"
sed -i 's/speed 0.5; massRate 0.1;/speed 0.5;/' constant/inlets
sed -i 's/model *weaklyCompressible;/model none;/' constant/physicsModels
sphCastFoam > log.bad 2>&1 && fail "an inlet without a flow ran"
grep -q "inlets:2:.*inlet 'tap' feeds the flow's fluid, but constant/physicsModels has no flow" log.bad ||
    fail "an inlet without a flow: $(grep -m1 -A1 -i error log.bad)"
pass "pouring: $perLayer particles a layer, 8 layers, the water stays in the tank, restart mid-pour bit for bit, bad inlets refused"
