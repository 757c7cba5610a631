#!/bin/bash
# The cooling mode (doc/physics.md §10.5) runs the flow's time hundreds of times slower than the
# heat's, so it must not run while a body has motion ahead: the chill cup's melt, dropped in and
# still from 0.61 s (when the cooling mode begins without a body: measured), under a steel lid
# held above it until 1 s. The mode begins only once the lid has fallen onto the melt and come to
# rest (measured: 1.83 s; the lid needs 0.045 s to fall its 10 mm, so 1.05 s at the earliest),
# not at the release, when the lid is still at rest but about to fall (the first version of the
# rule began it at 1 s); the lid falls in real time and the cup solidifies.
. "$SPHCAST_TEST_TOOLS"
makeChillCup "$scratch/cup" 100 "model frozenSolid; frozenSolidFraction 0.5; endWhenSolid yes;
    cooling { flowStepsPerHeatStep 10; stillSpeed 0.02; }"
cd "$scratch/cup" || exit 1
setEntry system/controlDict writeInterval 0.5
cat > constant/geometry/lid.geo <<'GEO'
SetFactory("OpenCASCADE");
Box(1) = {-0.008, -0.008, 0.034, 0.016, 0.016, 0.008};
Physical Volume("lid") = {1};
GEO
sed -i 's/^geometry .*/geometry ("mold.geo" "lid.geo");/' system/particleizeMoldDict
sed -i 's/^patches { moldWall { cloud mold; type fixedWall; mode shell; } }/patches { moldWall { cloud mold; type fixedWall; mode shell; } lid { cloud lid; type rigidBody; mode volume; } }/' \
    system/particleizeMoldDict
sed -i 's/walls (mold);/walls (mold lid);/' constant/physicsModels
cat > constant/dynamicBodies <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object dynamicBodies; }
lid { density 7874; translation (0 0 1); rotation locked; releaseTime 1; }
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
sphCastFoam > log 2>&1 || fail "sphCastFoam: $(tail -5 log)"
grep -q "^Stopping: the casting is solid (endWhenSolid)" log || fail "the cup did not solidify"
start=$(sed -n 's/^Cooling from time \([0-9.e+-]*\):.*/\1/p' log | head -1)
[ -n "$start" ] || fail "the cooling mode never began"
awk -v t="$start" 'BEGIN { exit !(t > 1.05) }' ||
    fail "the cooling mode began at $start s, before the lid released at 1 s had landed"
history=postProcessing/dynamicBodies/0/lid.dat
awk '!/^#/ { if ($1 < 0.9999 && $4 != 0) early = 1; if ($1 > 1.05 && $4 < -0.002) fell = 1 }
     END { exit (early || !fell) }' "$history" ||
    fail "the lid moved before its release, or did not fall after it"
pass "the cooling mode began at $start s, after the lid released at 1 s had landed; solid"
