#!/bin/bash
# The crossDitchPress tutorial's molds (dimensions assumed in its README.md) particleize as full
# volumes, at a coarse spacing here: the geometry's volumes are the README's (lower mold
# 873.04 cm^3, upper mold 102.17 cm^3, which is 0.802 kg of iron), both are the lattice (every
# nearest neighbour dx away, `./setResolution 3 uniform`), and the punch starts flush with the
# lower mold's top; graded (the tutorial's default) keeps dx at the faces and has fewer particles.
. "$SPHCAST_TEST_TOOLS"
tutorial="$(dirname "$SPHCAST_TEST_TOOLS")/../../tutorials/crossDitchPress"
mkdir -p "$scratch/press"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/setResolution" "$scratch/press/"
cd "$scratch/press"
./setResolution 3 uniform > /dev/null || fail "setResolution 3 uniform"
particleizeMold > out.log 2> err.log || fail "particleizeMold failed: $(cat err.log)"

# "Volume NAME: N lattice points x dx^3 = ... m^3 of the geometry's V m^3; ..."
geometryVolume() { sed -n "s/^Volume $1: .* of the geometry's \([0-9.e+-]*\) m^3.*/\1/p" out.log; }
within() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a / b - 1; exit !(d < tol && d > -tol) }'; }
lower=$(geometryVolume lowerMold); upper=$(geometryVolume upperMold)
within "$lower" 8.730366e-4 1e-5 || fail "lower mold volume $lower m^3, README says 8.73037e-4: $(cat out.log)"
within "$upper" 1.021663e-4 1e-5 || fail "upper mold volume $upper m^3, README says 1.02166e-4"
within "$(awk -v v="$upper" 'BEGIN { print v * 7850 }')" 0.8 0.005 || fail "upper mold is not 0.8 kg of iron"
pass "mold volumes as in the README: lower $lower m^3, upper $upper m^3 (0.8 kg of iron)"

grep -q "physical group upperMold .* bounds (-0.06975[0-9]* -0.06975[0-9]* 0.02024[0-9]*)" out.log ||
    grep -q "physical group upperMold .* bounds (-0.06975[0-9]* -0.06975[0-9]* 0.02025[0-9]*)" out.log ||
    fail "upper mold does not start flush with the lower mold's top: $(grep upperMold out.log)"
[ -s constant/particles/lowerMold.vtp ] && [ -s constant/particles/upperMold.vtp ] ||
    fail "no mold clouds: $(ls constant/particles)"
grep -q "Patch lowerMold (volume, fixedWall) -> cloud lowerMold: [0-9]* particles; nearest-neighbour distance / dx: min 1, mean 1, max 1" out.log ||
    fail "lower mold is not the lattice: $(grep Patch out.log)"
pass "both molds particleized as volumes on the lattice; the punch starts at the pocket's top"

# graded: the lower mold's particles nearest the cavity dx apart, fewer than on the lattice
# (19,444 against 32,676 at 3 mm); the punch, 1.75 spacings thick, has nothing to grade
count() { sed -n "s/^Patch $1 .* -> cloud $1: \([0-9]*\) particles;.*/\1/p" "$2"; }
uniformLower=$(count lowerMold out.log)
./setResolution 3 > /dev/null || fail "setResolution 3"
particleizeMold > graded.log 2> err.log || fail "particleizeMold, graded: $(cat err.log)"
gradedLower=$(count lowerMold graded.log)
grep -q "Patch lowerMold (volume, fixedWall) -> cloud lowerMold: [0-9]* particles; nearest-neighbour distance / dx: min 1," graded.log ||
    fail "the graded lower mold has no particle dx from another: $(grep Patch graded.log)"
[ -n "$gradedLower" ] && [ "$gradedLower" -lt $((uniformLower * 2 / 3)) ] ||
    fail "graded lower mold: $gradedLower particles against $uniformLower on the lattice"
pass "graded by default: the lower mold $gradedLower particles against $uniformLower on the lattice"
