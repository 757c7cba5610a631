#!/bin/bash
# The crossDitchPress tutorial at dx = 4.5 mm, a spacing that divides neither the ditch's sides
# (12 mm from the axis) nor the pocket's (69.75 mm): the lower mold's faces lie anywhere between
# lattice planes, its first layer up to a spacing behind them, and the punch is 1.17 dx thick.
# Before the wall-surface patches of doc/physics.md §7.2 a particle slipped through a vertical
# convex edge of the ditch at 0.07 s, and later metal sat up to 0.3 dx inside the iron there
# unseen. The pour and the first 0.1 s of the press (to 0.3 s): no health stop, and at every
# written time no metal particle inside the lower mold or the punch, measured against the
# molds' own boxes (not the wall particles).
. "$SPHCAST_TEST_TOOLS"
here=$(cd "$(dirname "$0")" && pwd)
python=python3
python3 -c 'import vtk' 2>/dev/null || python=/usr/bin/python3
preprocessTutorialCase crossDitchPress "$scratch/press" 4.5
setEntry system/controlDict endTime 0.3
sphCastFoam > log.sphCastFoam 2>&1 || fail "pour and press: $(tail -5 log.sphCastFoam)"
grep "^Time spent" log.sphCastFoam | tail -1
"$python" - . "$here" <<'PYTHON' || fail "metal inside a mold: $(tail -3 log.check 2>/dev/null)"
import os, sys
sys.path.insert(0, sys.argv[2])
from cloudFields import read_cloud
case, dx = sys.argv[1], 0.0045
# the cavity (tutorials/crossDitchPress/constant/geometry/lowerMold.geo): the pocket and the two
# arms of the ditch; the punch fills the pocket's square above its face, 5.25 mm thick
half, depth, arm, top = 69.75e-3, 11.25e-3, 12e-3, 20.25e-3
cavity = [((-half, -half, 0.0), (half, half, top)), ((-half, -arm, -depth), (half, arm, 0.0)),
          ((-arm, -half, -depth), (arm, half, 0.0))]
def outside(p, box):
    return sum(max(lo - x, 0.0, x - hi) ** 2 for x, lo, hi in zip(p, *box)) ** 0.5
history = os.path.join(case, "postProcessing/dynamicBodies/0/upperMold.dat")
travel = [tuple(map(float, l.split()[:4])) for l in open(history) if not l.startswith("#")]
def face(t):  # the punch's face at time t
    return top + min(travel, key=lambda row: abs(row[0] - t))[3]
worst, count = 0.0, 0
times = sorted((d for d in os.listdir(case) if d.replace(".", "", 1).isdigit() and float(d) > 0),
               key=float)
for t in times:
    metal = read_cloud(os.path.join(case, t, "metal.vtp"), [])
    z = face(float(t))
    for record in metal.values():
        p = record["x"]
        inLower = p[2] <= top and min(outside(p, box) for box in cavity) > 0.0
        inPunch = (abs(p[0]) < half and abs(p[1]) < half and z < p[2] < z + 5.25e-3)
        depth = (min(outside(p, box) for box in cavity) if inLower else
                 min(p[2] - z, half - abs(p[0]), half - abs(p[1])) if inPunch else 0.0)
        if depth > 0.0:
            count += 1
            worst = max(worst, depth)
    print(f"time {t}: {len(metal)} metal particles, the punch's face at {z * 1e3:.2f} mm")
print(f"{count} metal particles inside a mold at the written times, the deepest {worst / dx:.3f} dx")
sys.exit(1 if count else 0)
PYTHON
pass "at dx = 4.5 mm no metal inside the lower mold or the punch to 0.3 s"
