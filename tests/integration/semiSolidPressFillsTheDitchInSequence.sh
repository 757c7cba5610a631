#!/bin/bash
# The semiSolidPress tutorial's press, coarse (dx = 4 mm, the first 0.3 s, about a minute on two
# cores): a slug of AC4CH at f_s 0.40 pressed by the 800 g punch, let go at once. A mush is
# pressed quasi-statically and fills the ditch in sequence, where the liquid press's melt lands
# on its punch at 0.18 m/s with three times its weight and fills the ditch within 0.1 s
# (tutorials/crossDitchPress/README.md): the punch never faster than 0.06 m/s (measured 0.024),
# the metal's force on it within 15 % of its weight from 0.05 s on (7.77 .. 8.01 N of 7.85), the
# ditch filling at each written time, at 0.3 s between a quarter and 80 % full (measured 1.1 /
# 30.1 / 46.8 % at 0.1 / 0.2 / 0.3 s), the structure broken down somewhere but nowhere below 0.5
# (0.984: the kinetics' time is about 100 s at these shear rates). No health warning stops it.
# Restarted from its 0.2 s it writes the same 0.3 s, byte for byte.
# At 4 mm the slug is 16 mm high (4 layers) and 121.6 mm across, the tutorial's volume: with the
# tutorial's 18 mm its fifth layer would touch the punch. The cooling mode is kept off
# (stillSpeed 1e-4 m/s): the punch, in the kernel's reach of the slug from the start, moved at
# 0.019 m/s at 0.004 s, below the tutorial's 0.02, and the mode would slow the press 30 times.
. "$SPHCAST_TEST_TOOLS"
findVtkPython || exit 77
root="$(dirname "$SPHCAST_TEST_TOOLS")/../.."
mkdir -p "$scratch/press"
cp -r "$root/tutorials/semiSolidPress/system" "$root/tutorials/semiSolidPress/constant" "$scratch/press/"
cp -r "$root/tutorials/crossDitchPress/constant/geometry" "$scratch/press/constant/"
cd "$scratch/press"
# dx = 4 mm (a spacing that divides the ditch's 12 mm half-width), h = 3 dx, the end stop 2 dx
# above the pocket floor
sed -i 's/^spacing .*/spacing [0 1 0 0 0 0 0] 0.004;/' system/particleizeMoldDict system/setCastFieldsDict
sed -i 's/^supportRadius .*/supportRadius [0 1 0 0 0 0 0] 0.012;/' system/particleizeMoldDict system/sphSchemes
sed -i 's/^\( *endStop *\)([^)]*);/\1(0 0 -0.01225);/' constant/dynamicBodies
sed -i 's/point2 (0 0 0.018); radius 0.0573;/point2 (0 0 0.016); radius 0.0608;/' system/setCastFieldsDict
sed -i 's/^\( *stillSpeed *\)[0-9.e-]*;/\1 1e-4;/' constant/physicsModels
grep -q "radius 0.0608" system/setCastFieldsDict || fail "the slug's entry changed: update this test"
setEntry system/controlDict endTime 0.3
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
sphCastFoam > log.press 2>&1 || fail "the press: $(tail -5 log.press)"
grep -q "^Stopping: reached endTime at time 0.3" log.press || fail "the press stopped early"
! grep -q "^Cooling from" log.press || fail "the cooling mode began during the press: $(grep "^Cooling from" log.press)"

history=postProcessing/dynamicBodies/0/upperMold.dat
# columns: time, travel x y z, velocity x y z, the metal's force x y z, the total force x y z,
# at the end stop (1/0)
awk '!/^#/ { if (-$7 > fastest) fastest = -$7
             if ($1 >= 0.05 && ($10 < lowest || !seen)) lowest = $10
             if ($1 >= 0.05 && ($10 > highest || !seen)) { highest = $10; seen = 1 }
             z = $4 }
     END { printf "travel %.2f mm at 0.3 s, fastest %.3f m/s, the force from 0.05 s %.2f .. %.2f N\n",
                  -1000 * z, fastest, lowest, highest
           exit !(z < -0.002 && fastest < 0.06 && lowest > 0.85 * 7.848 && highest < 1.15 * 7.848) }' \
    "$history" > press.txt || fail "the punch does not press quasi-statically: $(cat press.txt)"
pass "a quasi-static press: $(cat press.txt)"

# the ditch (below the pocket floor, z < 0) holds 68.85 cm^3 at the written times
"$python" - "$(dirname "$SPHCAST_TEST_TOOLS")" > ditch.txt <<'PY' ||
import sys
sys.path.insert(0, sys.argv[1])
from cloudFields import read_cloud
fill = []
for t in ("0.1", "0.2", "0.3"):
    cloud = read_cloud(t + "/metal.vtp", ["mass", "rho", "structure"])
    volume = sum(p["mass"] / p["rho"] for p in cloud.values() if p["x"][2] < 0)
    fill.append(volume / 68.85e-6)
    lowest = min(p["structure"] for p in cloud.values())
print("ditch full at 0.1 / 0.2 / 0.3 s: %s; the structure at 0.3 s down to %.3f"
      % (" / ".join("%.1f %%" % (100 * f) for f in fill), lowest))
sys.exit(not (fill[0] < fill[1] < fill[2] and 0.25 <= fill[2] <= 0.8 and 0.5 < lowest < 1))
PY
    fail "the ditch does not fill in sequence: $(cat ditch.txt)"
pass "$(cat ditch.txt)"

# Restarted from its written 0.2 s, after the punch has moved (#49: the domain is the one the run
# started with, the punch's state from uniform/, the implicit viscosity from the written fields),
# the press writes the uninterrupted run's 0.3 s byte for byte.
moved=$(awk '!/^#/ && $1 >= 0.2 { printf "%.2f", -1000 * $4; exit }' "$history")
mkdir -p "$scratch/restart"
cp -r system constant 0.2 "$scratch/restart/"
cd "$scratch/restart" || fail "no restart case"
sphCastFoam > log.restart 2>&1 || fail "the restart: $(tail -5 log.restart)"
sameTimeFolder "$scratch/press/0.3" 0.3 ||
    fail "the restart from 0.2 s differs at 0.3 s: $(diff -rq "$scratch/press/0.3" 0.3)"
pass "restarted at 0.2 s, the punch $moved mm down, the press writes the same 0.3 s"
