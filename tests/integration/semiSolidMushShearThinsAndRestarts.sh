#!/bin/bash
# A semi-solid mush through the tools: the chill cup's AC4CH dropped at 0.5 m/s onto a mold held at
# 300 K, with rheology thixotropicSemiSolid. The mush keeps its table's viscosity at rest
# (solved implicitly: no step limit from it), its structure breaks down where the impact shears
# it (structure below 1, within [0, 1]), the metal freezes at the model's maxPacking, a restart
# reproduces the uninterrupted run bit for bit (the structure is read back), the written viscosity
# is the one the flow took (not the table's at rest), and a
# frozenSolidFraction written beside the rheology is an error naming file and line.
. "$SPHCAST_TEST_TOOLS"

makeRheologyCup "$scratch/cup" 0.6 0.3 \
    'rheology { model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { b 0.05; } }'
cp -r "$scratch/cup" "$scratch/stopped"
cd "$scratch/cup" || exit 1
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the semi-solid cup did not run"; }
grep -q "^Rheology: thixotropic semi-solid" log || fail "the log does not name the rheology"
grep -q "the metal freezes at f_s 0.6" log || fail "the freezing fraction is not the model's"
grep -q "^Viscosity solved implicitly in" log || fail "the mush's viscosity was not solved"
/usr/bin/python3 - <<'PY' || fail "the mush's structure"
from cloudFields import read_cloud
cloud = read_cloud("0.6/metal.vtp", ("structure", "shearRate", "solidFraction", "viscosity"))
structure = [p["structure"] for p in cloud.values()]
assert all(0 <= s <= 1 for s in structure), "structure outside [0, 1]"
mush = [p for p in cloud.values() if 0 < p["solidFraction"] < 0.6]
broken = min(structure)
print(f"{len(cloud)} particles, {len(mush)} in the mush at 0.6 s; structure {broken:.3f} .. "
      f"{max(structure):.3f}, largest shear rate {max(p['shearRate'] for p in cloud.values()):.3g} 1/s")
assert broken < 0.999, "no shear broke the structure anywhere"
# the written viscosity is the one the flow took: below the table's mu(T) (AC4CH, log-linear in
# T) where the structure broke down, mu(T) where the metal is liquid
import math
table = ((803.0, 4.88e4), (830.44, 4.73e4), (848, 2.154e3), (873, 1.86e2), (888.64, 1.57e-3),
         (973, 1.28e-3))
def mu(T):
    if T <= table[0][0]: return table[0][1]
    for (t0, m0), (t1, m1) in zip(table, table[1:]):
        if T <= t1:
            return math.exp(math.log(m0) + (T - t0) / (t1 - t0) * (math.log(m1) - math.log(m0)))
    return table[-1][1]
cloud = read_cloud("0.6/metal.vtp", ("structure", "solidFraction", "viscosity", "T"))
thinned = [p for p in cloud.values() if 0 < p["solidFraction"] < 0.6 and p["structure"] < 0.99]
assert thinned, "no mush particle with a broken structure at 0.6 s"
assert all(p["viscosity"] < 0.99 * mu(p["T"]) for p in thinned), \
    "the written viscosity is the table's at rest where the structure broke down"
liquid = [p for p in cloud.values() if p["solidFraction"] == 0]
# (within 1 %: the flow took mu at the last flow step's T, 0.14 % from the written T here)
assert all(abs(p["viscosity"] / mu(p["T"]) - 1) < 1e-2 for p in liquid), "liquid not at mu(T)"
print(f"{len(thinned)} thinned mush particles below mu(T); {len(liquid)} liquid at mu(T)")
PY
cd "$scratch/stopped" || exit 1
setEntry system/controlDict endTime 0.3
sphCastFoam > log.1 2>&1 || fail "first part"
setEntry system/controlDict endTime 0.6
sphCastFoam > log.2 2>&1 || fail "restart"
sameTimeFolder "$scratch/cup/0.6" 0.6 || fail "the restarted run differs at 0.6 s"
sed -i 's/model frozenSolid;/model frozenSolid; frozenSolidFraction 0.5;/' constant/physicsModels
rm -rf 0.6
if sphCastFoam > log.bad 2>&1; then fail "frozenSolidFraction beside the rheology ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: 'frozenSolidFraction' is set by rheology" log.bad ||
    { cat log.bad >&2; fail "no clear error for frozenSolidFraction beside the rheology"; }
pass "a semi-solid mush shear-thins, freezes at maxPacking, restarts bit for bit"
