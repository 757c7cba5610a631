#!/bin/bash
# Flow and heat together: a half-full sphere of AC4CH at 900 K sloshing in an iron mold at
# 300 K (conduction, contact, air). With `interval auto` the heat takes steps of its own, a
# tenth of its stable step (CastingSolver::heatStepsWithFlow): the temperatures stay within 5 %
# of the largest change of T of the run with heat at every flow step (measured 0.8 % at 0.2 s:
# the error is first order in the heat step), a restart reproduces the uninterrupted run bit
# for bit, and the energy books close in both.
. "$SPHCAST_TEST_TOOLS"

makeHeatedSloshingSphere "$scratch/auto" auto
cp -r "$scratch/auto" "$scratch/stopped"
makeHeatedSloshingSphere "$scratch/everyStep" everyStep
(cd "$scratch/auto" && sphCastFoam > log 2>&1) || fail "run with interval auto"
(cd "$scratch/everyStep" && sphCastFoam > log 2>&1) || fail "run with heat every step"
grep -q "^Heat: .* heat steps in .* steps (interval auto" "$scratch/auto/log" || fail "no heat line in the log"

cd "$scratch/stopped" || exit 1
setEntry system/controlDict endTime 0.06
sphCastFoam > log.1 2>&1 || fail "first part"
setEntry system/controlDict endTime 0.1
sphCastFoam > log.2 2>&1 || fail "restart"
for t in 0.08 0.1; do
    sameTimeFolder "$scratch/auto/$t" "$t" || fail "time $t differs from the uninterrupted run"
done

/usr/bin/python3 - "$scratch/everyStep" "$scratch/auto" <<'PY' || fail "temperatures or books"
import sys, vtk
def temperatures(case, cloud):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(f"{case}/0.1/{cloud}.vtp")
    reader.Update()
    data = reader.GetOutput().GetPointData()
    ids, T = data.GetArray("id"), data.GetArray("T")
    return {int(ids.GetTuple1(i)): T.GetTuple1(i) for i in range(T.GetNumberOfTuples())}
for cloud, start in (("metal", 900.0), ("mold", 300.0)):
    reference, auto = temperatures(sys.argv[1], cloud), temperatures(sys.argv[2], cloud)
    change = max(abs(T - start) for T in reference.values())
    worst = max(abs(auto[k] - reference[k]) for k in reference)
    print(f"{cloud}: largest change of T {change:.2f} K, largest difference {worst:.3f} K")
    assert change > 5, "the test must move heat to mean anything"
    assert worst < 0.05 * change, "interval auto strays from heat at every step"
for case in sys.argv[1:]:
    rows = [l.split() for l in open(f"{case}/postProcessing/balance/0/energyBalance")
            if l.strip() and not l.startswith("#")]
    worst = max(abs(float(r[-1])) for r in rows)
    print(f"{case}: worst relative imbalance {worst:.2e}")
    assert worst < 1e-12, "the books do not close (round-off is about 1e-16 a step)"
PY
# a mold patch held at a temperature (the patch of constant/particles/patches), and one that
# does not exist
cd "$scratch/auto" || exit 1
rm -rf 0.* postProcessing
sed -i 's/    clouds      (metal mold);/    clouds (metal mold); fixedTemperature { moldWall 300; }/' constant/physicsModels
setEntry system/controlDict endTime 0.02
sphCastFoam > log.held 2>&1 || fail "run with a held patch"
grep -q "patch moldWall held at 300 K" log.held || fail "the log does not name the held patch"
/usr/bin/python3 - <<'PY' || fail "the held patch moved"
import vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName("0.02/mold.vtp")
reader.Update()
T = reader.GetOutput().GetPointData().GetArray("T")
values = {T.GetTuple1(i) for i in range(T.GetNumberOfTuples())}
assert values == {300.0}, f"held mold temperatures {sorted(values)[:3]}..."
PY
rm -rf 0.* postProcessing
sed -i 's/fixedTemperature { moldWall 300; }/fixedTemperature { moldWal 300; }/' constant/physicsModels
if sphCastFoam > log.bad 2>&1; then fail "an unknown held patch ran"; fi
grep -q "physicsModels:.*unknown key 'moldWal'.*did you mean 'moldWall'" log.bad ||
    { cat log.bad >&2; fail "no clear error for an unknown held patch"; }
pass "flow with heat: interval auto within 5 % of every step, restart bit for bit, books closed, held patch"
