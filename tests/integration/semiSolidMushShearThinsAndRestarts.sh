#!/bin/bash
# A semi-solid mush through the tools: the chill cup's AC4CH dropped at 0.5 m/s onto a mold held at
# 300 K, with rheology thixotropicSemiSolid. The mush keeps its table's viscosity at rest
# (solved implicitly: no step limit from it), its structure breaks down where the impact shears
# it (structure below 1, within [0, 1]), the metal freezes at the model's maxPacking, a restart
# reproduces the uninterrupted run bit for bit (the structure is read back), and a
# frozenSolidFraction written beside the rheology is an error naming file and line.
. "$SPHCAST_TEST_TOOLS"

makeCup() {  # DIR
    makeChillCup "$1" 0.6 "model frozenSolid;"
    cd "$1" || fail "cannot enter $1"
    echo 'rheology { model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { b 0.05; } }' \
        >> constant/physicsModels
    setEntry system/controlDict writeInterval 0.3
    setEntry system/controlDict logInterval 50
    particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
    setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
    cd - > /dev/null || exit 1
}

makeCup "$scratch/cup"
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
