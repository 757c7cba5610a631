#!/bin/bash
# A yield-stress mush as an elastic solid below tau0 through the tools: the chill cup's AC4CH
# dropped at 0.5 m/s onto a mold held at 300 K, with rheology elastoViscoplastic. The log names
# the law and its elastic step limit's place; the stress is written with the metal (its two
# vectors) and is non-zero where the impact loaded it; a restart reproduces the uninterrupted
# run bit for bit (the stress is read back); an unknown coefficient is an error naming file and
# line.
. "$SPHCAST_TEST_TOOLS"

makeRheologyCup "$scratch/cup" 0.2 0.1 'rheology { model elastoViscoplastic;
    elastoViscoplasticCoeffs { tau0 50; k 1; n 1; G 5000; etaS 0.01; } }'
cp -r "$scratch/cup" "$scratch/stopped"
cd "$scratch/cup" || exit 1
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the elasto-viscoplastic cup did not run"; }
grep -q "^Rheology: elasto-viscoplastic" log || fail "the log does not name the rheology"
/usr/bin/python3 - <<'PY' || fail "the mush's stress"
import math
from cloudFields import read_cloud
cloud = read_cloud("0.2/metal.vtp", ("stressDiagonal", "stressShear", "viscosity"))
def magnitude(p):
    d, s = p["stressDiagonal"], p["stressShear"]
    return math.sqrt(0.5 * sum(x * x for x in d) + sum(x * x for x in s))
largest = max(magnitude(p) for p in cloud.values())
print(f"{len(cloud)} particles; the largest |tau| {largest:.2f} Pa (tau0 50)")
assert largest > 1, "no stress anywhere after the impact"
assert all(math.isfinite(magnitude(p)) for p in cloud.values())
assert all(abs(p["viscosity"] - 0.01) < 1e-9 for p in cloud.values()), "viscosity is not etaS"
PY
cd "$scratch/stopped" || exit 1
setEntry system/controlDict endTime 0.1
sphCastFoam > log.1 2>&1 || fail "first part"
setEntry system/controlDict endTime 0.2
sphCastFoam > log.2 2>&1 || fail "restart"
sameTimeFolder "$scratch/cup/0.2" 0.2 || fail "the restarted run differs at 0.2 s"
sed -i 's/G 5000;/G 5000; lambda 1;/' constant/physicsModels
rm -rf 0.2
if sphCastFoam > log.bad 2>&1; then fail "an unknown coefficient ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: .*lambda" log.bad ||
    { cat log.bad >&2; fail "no clear error for the unknown coefficient"; }
pass "an elasto-viscoplastic mush runs, writes its stress and restarts bit for bit"
