#!/bin/bash
# particleizeMold loads a gmsh .geo through the gmsh library; a patch the dictionary names but
# the mesh lacks is an error listing the groups present, and nothing is written. With valid
# patches it writes constant/particles/<cloud>.vtp and constant/particles/patches.
. "$SPHCAST_TEST_TOOLS"
mkdir -p "$scratch/mold/system" "$scratch/mold/constant/geometry"
cd "$scratch/mold"
cat > constant/geometry/box.geo <<'GEO'
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.1, 0.1, 0.1};
Physical Surface("moldWall") = {1, 2, 3, 4, 5, 6};
Physical Volume("cavity") = {1};
GEO
cat > system/particleizeMoldDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }
geometry ("box.geo");
spacing 0.01;
patches
{
    moldWall { cloud mold; type fixedTemperature; }
    lowerMold { cloud mold; type fixedWall; }
}
DICT
if particleizeMold > out.log 2> err.log; then fail "particleizeMold succeeded"; fi
grep -q "physical group moldWall" out.log || fail "moldWall not listed: $(cat out.log)"
grep -qF "patch 'lowerMold' is not a physical group of the geometry; the groups present are ( moldWall cavity )" err.log ||
    grep -qF "patch 'lowerMold' is not a physical group of the geometry; the groups present are ( cavity moldWall )" err.log ||
    fail "wrong message: $(cat err.log)"
grep -q "particleizeMoldDict:7:" err.log || fail "no file:line in: $(cat err.log)"
[ -e constant/particles ] && fail "constant/particles written after an error"
pass "physical groups read with gmsh; a missing one is named with those present; nothing written"

sed -i '/lowerMold/d' system/particleizeMoldDict
particleizeMold > out.log 2> err.log || fail "particleizeMold failed: $(cat err.log)"
[ -s constant/particles/mold.vtp ] || fail "no constant/particles/mold.vtp"
grep -q "particles" constant/particles/patches || fail "no patch list: $(ls constant/particles)"
grep -q "Patch moldWall (shell, fixedTemperature) -> cloud mold: [0-9]* particles; nearest-neighbour distance / dx: min" out.log ||
    fail "no spacing statistics in: $(cat out.log)"
pass "valid patches give constant/particles/mold.vtp, the patch list and spacing statistics"
