#!/bin/bash
# The paper's filling test (tutorials/validation/cylinderFilling), coarse (dx = 5 mm, 880
# particles) and only to t = 0.025 s: the column strikes the floor at 1 m/s and must produce the
# acoustic water hammer, rho_s (1 + v/c) = 2448 kg/m^3 (the sampled peak lies within a factor of
# about 2 of the jump 48), and the riemann scheme must then settle: the density spread of all
# particles over 0.015..0.025 s below the paper's 16 kg/m^3 (2392..2408 at t = 0.08 s; this case
# gives 6.2). The fieldMinMax function object gives the range; compareWithPaper reads it.
. "$SPHCAST_TEST_TOOLS"
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/cylinderFilling" && pwd)
mkdir -p "$scratch/case"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/compareWithPaper" "$scratch/case/"
rm -rf "$scratch/case/constant/particles"
cd "$scratch/case"
sed -i 's/0\.00125;/0.005;/; s/0\.00375;/0.015;/' system/particleizeMoldDict
sed -i 's/0\.00125;/0.005;/' system/setCastFieldsDict
sed -i 's/0\.00375;/0.015;/' system/sphSchemes
setEntry system/controlDict endTime 0.025
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
grep -q "^Cloud metal: 880 particles$" log.setCastFields ||
    fail "metal count: $(grep 'Cloud metal' log.setCastFields)"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
rho=postProcessing/density/0/rho
[ -f "$rho" ] || fail "no $rho"
peak=$(awk '!/^#/ && $1 < 0.012 && $3 > m { m = $3 } END { print m }' "$rho")
awk -v m="$peak" 'BEGIN { exit !(m > 2424 && m < 2500) }' ||
    fail "impact peak rho $peak kg/m^3, expected 2424..2500 (water hammer 2448)"
read -r low high < <(awk '!/^#/ && $1 >= 0.015 { if (lo == "" || $2 < lo) lo = $2; if ($3 > hi) hi = $3 }
                           END { print lo, hi }' "$rho")
awk -v lo="$low" -v hi="$high" 'BEGIN { exit !(hi - lo < 16 && lo > 2390 && hi < 2410) }' ||
    fail "after the impact rho $low .. $high kg/m^3: spread over 16 or off 2400"
python3 compareWithPaper > log.compare 2>&1 || fail "compareWithPaper: $(tail -3 log.compare)"
grep -q "^densityScheme riemann, t = 0.025" log.compare || fail "compareWithPaper: $(head -3 log.compare)"
pass "impact peak $peak kg/m^3 (water hammer 2448); 0.015..0.025 s: $low .. $high kg/m^3"
