#!/bin/bash
# A hard case held long: the chill cup of meltSolidifiesInAChillMoldAndRestarts (AC4CH at 970 K
# dropped at 0.5 m/s onto a floor held at 300 K) with every step acoustic, no cooling mode, for
# 10^5 steps (5 s at 5e-5 s a step: the melt is solid from about 3.9 s on). The density stays
# bounded (the health checks stop the run above 20 % compression), nothing goes non-finite,
# nothing passes the mold, and T stays within [300, 970] K.
. "$SPHCAST_TEST_TOOLS"

makeChillCup "$scratch/cup" 5 "model frozenSolid;"
cd "$scratch/cup" || exit 1
setEntry system/controlDict writeInterval 1
setEntry system/controlDict logInterval 5000
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the held melt stopped"; }
steps=$(awk '/^Step /{ n = $2 } END { print n }' log)
[ "$steps" -ge 100000 ] || fail "only $steps steps"
grep -q "^Run health: no warnings" log || { grep -i warn log | head >&2; fail "warnings"; }
awk '/^T metal/ { if ($3 < 300 - 1e-9 || $5 > 970 + 1e-9) bad = 1 } END { exit bad }' log ||
    fail "T left [300, 970] K"
/usr/bin/python3 - <<'PY' || fail "the held cup"
import math, vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName("5/metal.vtp")
reader.Update()
out = reader.GetOutput()
data = out.GetPointData()
rho, rest, f = (data.GetArray(n) for n in ("rho", "restDensity", "solidFraction"))
n = out.GetNumberOfPoints()
worst = max(math.hypot(*out.GetPoint(i)[:2]) for i in range(n))
lowest = min(out.GetPoint(i)[2] for i in range(n))
deviation = [rho.GetTuple1(i) / rest.GetTuple1(i) - 1 for i in range(n)]
print(f"{n} particles after 1e5 steps: outermost r {1e3 * worst:.2f} mm, lowest z "
      f"{1e3 * lowest:.2f} mm, rho / rho_s - 1 in [{min(deviation):.4f}, {max(deviation):.4f}], "
      f"all solid: {all(f.GetTuple1(i) == 1 for i in range(n))}")
assert worst < 0.02 and lowest > 0, "a particle passed the mold"
assert all(math.isfinite(d) for d in deviation)
assert max(deviation) < 0.03 and min(deviation) > -0.1, "density out of bounds"
PY
pass "a solidifying melt held for $steps steps stays bounded, inside the mold, within [300, 970] K"
