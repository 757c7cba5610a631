#!/bin/bash
# The cooling mode (doc/physics.md §10.5) runs the flow's time hundreds of times slower than the
# heat's, so a body let go must end it: the chill cup's melt, dropped in and still from 0.61 s
# (measured), cools in the mode under a steel lid held above it until 1 s. The lid is held
# through the heat step in which 1 s falls; at the next step the mode pauses ("body lid was let
# go"), the lid falls in real time (10 mm: 0.045 s) onto the melt, and the mode begins again only
# once everything is still (measured: 1.83 s); the cup solidifies.
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
grep "^Cooling from time\|^Cooling paused at time" log | sed 's/: .*//; s/ from time / from /; s/ paused at time / paused /' > modes.txt
# first cooling before the release, then paused within a heat step after it, then again later
awk 'NR == 1 && !($2 == "from" && $3 < 1) { bad = 1 }
     NR == 2 && !($2 == "paused" && $3 >= 1 && $3 < 1.1) { bad = 1 }
     NR == 3 && !($2 == "from" && $3 > 1.05) { bad = 1 }
     END { exit (bad || NR < 3) }' modes.txt ||
    fail "the cooling mode did not pause at the lid's release and wait for it to land: $(tr '\n' ';' < modes.txt)"
grep -q "^Cooling paused at time .*: body lid was let go" log || fail "the pause does not name the lid"
history=postProcessing/dynamicBodies/0/lid.dat
awk '!/^#/ { if ($1 < 0.9999 && $4 != 0) early = 1; if ($1 > 1.05 && $4 < -0.002) fell = 1 }
     END { exit (early || !fell) }' "$history" ||
    fail "the lid moved before its release, or did not fall after it"
pass "cooling, then paused at the lid's release and again once it had landed: $(tr '\n' ';' < modes.txt); solid"
