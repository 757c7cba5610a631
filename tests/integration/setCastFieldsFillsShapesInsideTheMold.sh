#!/bin/bash
# setCastFields fills shapes and gmsh volumes on the lattice, keeps the metal clear of the mold
# particles particleizeMold wrote, sets fields on an existing cloud, and names a wrong region type
# with the valid ones.
. "$SPHCAST_TEST_TOOLS"
mkdir -p "$scratch/cast/system" "$scratch/cast/constant/geometry"
cd "$scratch/cast"
header='FoamFile { version 2.0; format ascii; class dictionary; object setCastFieldsDict; }'
count() { sed -n "s/^Cloud $1: \([0-9]*\) particles$/\1/p" log.setCastFields; }

# A sphere of radius 10 dx minus a cylinder of radius 4 dx through it: 4188.8 - ~1005 dx^3.
cat > system/setCastFieldsDict <<DICT
$header
spacing 0.001;
clouds
{
    ball { regions { r { type sphere; centre (0 0 0); radius 0.01; } } fields { T 900; } }
    holed
    {
        regions
        {
            r
            {
                type difference;
                regions
                {
                    ball  { type sphere; centre (0 0 0); radius 0.01; }
                    hole  { type cylinder; point1 (0 0 -0.02); point2 (0 0 0.02); radius 0.004; }
                }
            }
        }
    }
    frustum { regions { r { type cone; point1 (0 0 0); point2 (0 0 0.01); radius1 0.01; radius2 0.005; } } }
}
DICT
setCastFields > log.setCastFields 2>&1 || fail "setCastFields failed: $(cat log.setCastFields)"
ball=$(count ball); holed=$(count holed); frustum=$(count frustum)
awk -v n="$ball" 'BEGIN { exit !(n > 4188.8 * 0.98 && n < 4188.8 * 1.02) }' || fail "sphere: $ball particles"
# sphere minus the cylinder's part inside it: 4188.8 - pi 16 (2 sqrt(84)) - cap corrections ~ 3265
awk -v n="$holed" 'BEGIN { exit !(n > 3150 && n < 3350) }' || fail "difference: $holed particles"
awk -v n="$frustum" 'BEGIN { exit !(n > 1832.6 * 0.97 && n < 1832.6 * 1.03) }' || fail "cone: $frustum particles"
pass "sphere ($ball of 4189 dx^3), difference ($holed), cone ($frustum of 1833 dx^3)"

# A cylindrical mold (shell) filled through its gmsh volume, metal kept 0.75 dx from the wall.
cat > constant/geometry/pot.geo <<'GEO'
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.04, 0.02};
Physical Surface("potWall") = {1, 3};
Physical Volume("cavity") = {1};
GEO
cat > system/particleizeMoldDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }
geometry ("pot.geo");
spacing 0.002;
supportRadius 0.004;
patches { potWall { cloud pot; type fixedTemperature; } }
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold failed: $(cat log.particleizeMold)"
cat > system/setCastFieldsDict <<DICT
$header
spacing 0.002;
clouds
{
    metal { regions { melt { type gmshVolume; file "pot.geo"; group cavity; } } fields { T 970; } }
}
setFields { pot { fields { T 300; } } }
DICT
setCastFields > log.setCastFields 2>&1 || fail "setCastFields failed: $(cat log.setCastFields)"
metal=$(count metal)
# pi 10^2 20 = 6283 dx^3 of cavity; the ring nearest the wall is on the lattice within dx/2.
awk -v n="$metal" 'BEGIN { exit !(n > 5500 && n <= 6400) }' || fail "gmshVolume: $metal particles"
grep -q "Cloud metal: left out [0-9]* particles closer than moldClearance 0.0015 m" log.setCastFields ||
    fail "no clearance line: $(cat log.setCastFields)"
[ -s 0/metal.vtp ] && [ -s 0/pot.vtp ] || fail "0/ lacks metal.vtp or pot.vtp: $(ls 0)"
pass "gmsh volume filled ($metal particles) clear of the mold; the mold cloud's T set in 0/pot.vtp"

# A wrong type names the valid ones; nothing is written.
rm -rf 0
sed -i 's/type gmshVolume/type pyramid/' system/setCastFieldsDict
if setCastFields > log.setCastFields 2>&1; then fail "unknown region type accepted"; fi
grep -qF "unknown type 'pyramid'" log.setCastFields || fail "wrong message: $(cat log.setCastFields)"
grep -qF "(box cylinder cone sphere gmshVolume gmshSurface union intersection difference)" log.setCastFields ||
    fail "valid types not listed: $(cat log.setCastFields)"
[ -e 0 ] && fail "0/ written after an error"
pass "unknown region type lists the valid ones; nothing written"

# The pot's metal at the hydrostatic density of an aluminium table at 953 K, relaxed against the
# pot's wall particles.
cat > constant/physicalProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }
metal
{
    density   [1 -3 0 0 0 0 0] table ((300 2700) (853 2550) (903 2380) (1000 2350));
    viscosity [1 -1 -1 0 0 0 0] 1.28e-3;
}
DICT
cat > constant/g <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object g; }
dimensions [0 1 -2 0 0 0 0];
value      (0 0 -9.81);
DICT
cat > system/sphSchemes <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }
densityScheme riemann;
viscousForm   Morris;
supportRadius 0.004;
soundSpeed    [0 1 -1 0 0 0 0] 10;
DICT
cat > system/setCastFieldsDict <<DICT
$header
spacing 0.002;
relaxation { iterations 50; }
clouds
{
    metal
    {
        regions { melt { type gmshVolume; file "pot.geo"; group cavity; } }
        fields { T 953; rho hydrostatic; }
    }
}
DICT
setCastFields > log.setCastFields 2>&1 || fail "setCastFields failed: $(cat log.setCastFields)"
# rho_s(953 K) = 2380 + (2350 - 2380) 50 / 97 = 2364.54; deepest particle ~0.04 m: +0.0392 %
grep -q "Cloud metal: rho hydrostatic from rho_s = 2364.5.* kg/m^3 at T = 953 K" log.setCastFields ||
    fail "no hydrostatic line: $(cat log.setCastFields)"
grep -q "Cloud metal: after relaxation: number density" log.setCastFields ||
    fail "no relaxation statistics: $(cat log.setCastFields)"
[ -s 0/metal.vtp ] || fail "0/metal.vtp not written"
pass "hydrostatic density from the rho_s(T) table, packing relaxed: $(grep 'after relaxation' log.setCastFields)"

# A table whose temperatures go back names its row; nothing is written.
rm -rf 0
sed -i 's/(903 2380)/(803 2380)/' constant/physicalProperties
if setCastFields > log.setCastFields 2>&1; then fail "decreasing table accepted"; fi
grep -q "physicalProperties:4:.*row 3 has T = 803 K after 853 K" log.setCastFields ||
    fail "wrong message: $(cat log.setCastFields)"
[ -e 0 ] && fail "0/ written after an error"
pass "a table whose temperatures go back is refused at its row; nothing written"
