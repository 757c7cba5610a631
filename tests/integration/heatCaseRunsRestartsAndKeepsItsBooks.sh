#!/bin/bash
# A case with heat and no flow: an AC4CH block at 900 K on an iron plate at 300 K, conduction,
# contact, air and radiation (doc/physics.md §10.2). The iron plate is written to every time folder
# (its T changes), a restart reproduces the uninterrupted run bit for bit, the energyBalance
# function object closes the books to round-off, and bad heat input stops before anything is
# written, naming file, line and key.
. "$SPHCAST_TEST_TOOLS"
etc=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../etc" && pwd)
case=$scratch/whole
mkdir -p "$case/system" "$case/constant"
cat > "$case/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom       latestTime;
stopAt          endTime;
endTime         2;
deltaT          1;
adjustTimeStep  yes;
maxCo           0.25;
writeControl    adjustableRunTime;
writeInterval   0.5;
logInterval     100;
functions { balance { type energyBalance; clouds (metal mold); } }
DICT
cat > "$case/system/setCastFieldsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setCastFieldsDict; }
spacing 0.0025;
clouds
{
    metal { material AC4CH; regions { block { type box; min (0 0 0); max (0.02 0.02 0.02); } } fields { T 900; } }
    mold  { material iron;  regions { plate { type box; min (-0.005 -0.005 -0.0075); max (0.025 0.025 0); } } fields { T 300; } }
}
DICT
cat > "$case/system/sphSchemes" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }
supportRadius 0.0075;
DICT
cat > "$case/constant/physicalProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }
AC4CH { #includeEtc "materials/AC4CH" }
iron  { #includeEtc "materials/iron" }
DICT
cat > "$case/constant/physicsModels" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicsModels; }
materials { metal AC4CH; mold iron; }
heatTransfer
{
    clouds      (metal mold);
    conduction  on;
    moldContact { coefficients ((AC4CH iron 3000)); }
    atmosphere  { T 300; coefficients ((AC4CH 20) (iron 20)); }
    radiation   { T 300; materials (iron); }
}
DICT
cat > "$case/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0]; value (0 0 -9.81);
DICT
cp -r "$case" "$scratch/stopped"
(cd "$case" && setCastFields > log.setCastFields 2>&1 && sphCastFoam > log 2>&1) ||
    { cat "$case/log" >&2; fail "whole run"; }
for t in 0 0.5 1 1.5 2; do
    [ -f "$case/$t/mold.vtp" ] || fail "time $t has no mold.vtp (the mold carries heat)"
done
grep -q "mold.vtp" "$case/whole.pvd" || grep -q "mold" "$case"/*.pvd || fail "the .pvd lists no mold"
grep -q "heat conduction" "$case/log" || grep -q "limit" "$case/log" || fail "the log names no heat limit"

# the books: relativeImbalance (last column) at round-off on every row
python3 - "$case/postProcessing/balance/0/energyBalance" <<'PY' || fail "energy balance"
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
worst = max(abs(float(r[-1])) for r in rows)
lost = [float(x) for x in rows[-1][3:6]]
print(f"{len(rows)} rows, worst relative imbalance {worst:.3e}, lost (air, radiation, held) {lost}")
assert len(rows) > 10, "too few rows"
assert lost[0] > 0 and lost[1] > 0, "no heat left through the air or by radiation"
assert worst < 1e-12, "the books do not close (round-off is about 1e-16 a step)"
PY

cd "$scratch/stopped"
setCastFields > /dev/null 2>&1 || fail "setCastFields"
setEntry system/controlDict endTime 1
sphCastFoam > log.1 2>&1 || fail "first part"
setEntry system/controlDict endTime 2
sphCastFoam > log.2 2>&1 || fail "restart"
grep -q "Starting from time 1 " log.2 || fail "restart did not start from 1"
for t in 1.5 2; do
    sameTimeFolder "$case/$t" "$t" || fail "time $t differs from the uninterrupted run"
done

# bad input: each stops with file, line and key, and writes nothing
expectError() {
    local what=$1 pattern=$2
    local before
    before=$(ls -d [0-9]* | sort | tr '\n' ' ')
    if sphCastFoam > log.bad 2>&1; then fail "$what: ran"; fi
    grep -q -- "$pattern" log.bad || { cat log.bad >&2; fail "$what: no '$pattern' in the message"; }
    [ "$(ls -d [0-9]* | sort | tr '\n' ' ')" = "$before" ] || fail "$what: time folders changed"
}
cp constant/physicsModels physicsModels.good
sed -i 's/conduction  on;/convection on;/' constant/physicsModels
expectError "unknown path" "physicsModels:.*unknown key 'convection'"
cp physicsModels.good constant/physicsModels
sed -i 's/AC4CH iron 3000/AC4CH steel 3000/' constant/physicsModels
expectError "contact with an absent material" "physicsModels:.*'steel', which no heat cloud has"
cp physicsModels.good constant/physicsModels
sed -i 's/materials (iron);/materials (iron AC4CH);/' constant/physicsModels
expectError "radiation without emissivity" "emissivity"
cp physicsModels.good constant/physicsModels
sed -i 's/clouds      (metal mold);/clouds (metal mold); fixedTemperature { moldd 300; }/' constant/physicsModels
expectError "held cloud that does not exist" "did you mean 'mold'"
cp physicsModels.good constant/physicsModels
sed -i 's/clouds      (metal mold);/clouds (metal mould);/' constant/physicsModels
expectError "heat cloud that does not exist" "physicsModels:.*'mould'"
pass "heat case: mold written, restart bit for bit, books closed, bad input refused"
