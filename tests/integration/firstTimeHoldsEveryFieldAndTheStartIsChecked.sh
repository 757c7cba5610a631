#!/bin/bash
# What a new user meets at the start of a casting run (issue #28), on makeChillCup's small cup
# (AC4CH at 970 K dropped at 0.5 m/s into a mold held at 300 K):
# - The first time lists every cloud and field the run writes: setCastFields wrote 0/ with the
#   metal alone; sphCastFoam writes it again with the held mold and its T (300 K) and the
#   metal's solidFraction and the rest, the same fields as every later time; a run started
#   again from that 0/ reproduces the first run bit for bit.
# - The log compares c with the fall the metal can make (sqrt(|U0|^2 + 2 g H)) and warns, naming
#   the c that would do, when the Mach number would pass 0.1.
# - cavitationPressure must be 0 or negative.
. "$SPHCAST_TEST_TOOLS"
makeChillCup "$scratch/cup" 0.02 "model frozenSolid; frozenSolidFraction 0.5;"
cd "$scratch/cup" || exit 1
setEntry system/controlDict writeInterval 0.01
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
[ ! -f 0/mold.vtp ] || fail "setCastFields wrote the mold (the test needs the solver to add it)"
cp -r "$scratch/cup" "$scratch/again"
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the cup did not run"; }
grep -q "written again with every cloud and field" log || fail "the log does not say 0 was rewritten"

/usr/bin/python3 - <<'PY' || fail "the first time's fields"
import vtk
def fields(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput().GetPointData()
    return reader.GetOutput(), {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}
for cloud in ("metal", "mold"):
    _, first = fields(f"0/{cloud}.vtp")
    _, last = fields(f"0.02/{cloud}.vtp")
    assert first == last, f"{cloud}: 0 lacks {sorted(last - first)}, has {sorted(first - last)}"
    print(f"{cloud}: {len(first)} fields at 0 and at 0.02")
mold, _ = fields("0/mold.vtp")
T = mold.GetPointData().GetArray("T")
values = [T.GetTuple1(i) for i in range(T.GetNumberOfTuples())]
assert values and min(values) == 300 and max(values) == 300, "the held mold's T at 0"
_, metal = fields("0/metal.vtp")
assert "solidFraction" in metal
PY
grep -q "0/mold.vtp\|\"0/mold.vtp\"\|file=\"0/mold.vtp\"" ./*.pvd || fail "the .pvd does not list the mold at 0"

# The rewritten 0 starts the same run: bit for bit at 0.02 s.
cd "$scratch/again" || exit 1
cp "$scratch/cup/0/"*.vtp 0/
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the run from the rewritten 0"; }
grep -q "written again" log && fail "a complete first time was written again"
sameTimeFolder "$scratch/cup/0.02" 0.02 || fail "the run from the rewritten 0 differs at 0.02 s"

# The sound-speed check: the cup's metal, its top 30 mm up, thrown down at 0.5 m/s, can fall
# to the lowest wall particle 10 mm below the floor: sqrt(0.25 + 2 g 0.04) = 1.02 m/s, Mach
# 0.051 at c = 20 m/s; at c = 5 m/s Mach 0.20 warns and asks for 10.2 m/s.
grep -q "Sound speed: c = 20 m/s .* = 1.02 m/s (|U0| up to 0.5 m/s, a fall H = 0.04 m.*Mach up to 0.05" \
    "$scratch/cup/log" || fail "no sound-speed line: $(grep 'Sound speed' "$scratch/cup/log")"
grep -q "Warning: Sound speed" "$scratch/cup/log" && fail "a Mach warning at Mach 0.05"
rm -rf 0.0* ./*.pvd
setEntry system/sphSchemes soundSpeed 5
setEntry system/controlDict endTime 0.001
sphCastFoam > log.c5 2>&1 || { tail -20 log.c5 >&2; fail "c = 5 m/s"; }
grep -q "Warning: Sound speed: c = 5 m/s .*Mach up to 0.20., above 0.1.*at least 10.2 m/s" log.c5 ||
    fail "no Mach warning at c = 5 m/s: $(grep -A2 'Sound speed' log.c5)"
setEntry system/sphSchemes soundSpeed 20

# cavitationPressure above 0 is refused at its key.
sed -i 's/frozenSolidFraction 0.5;/frozenSolidFraction 0.5; cavitationPressure 5000;/' \
    constant/physicsModels
if sphCastFoam > log.bad 2>&1; then fail "cavitationPressure 5000 ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: 'cavitationPressure' .* must be 0 or negative" log.bad ||
    { cat log.bad >&2; fail "no clear error for cavitationPressure 5000"; }
pass "the first time holds every field (held mold with T), restarts bit for bit; Mach check; cavitationPressure > 0 refused"
