#!/bin/bash
# Hard cases for the walls, built with the tools as a user builds them: metal sloshing in a closed
# sphere and in a horizontal cylinder (curved walls all round), a jet into the concave corner of a
# box, and a column falling into an open cone. At the default maxCo every written time must have
# no metal particle behind the mold surface (measured from the shape's own formula, not from the
# wall particles; at least 0.1 dx in front of it: the clearance of 0.25 dx less the error of the
# surface estimate on a curve of radius 10 dx) and the density within the water hammer's bound
# for an impact at speed v on a rigid wall, |rho / rho_s - 1| <= v / c, times 1.5 for the
# focusing at concave walls and corners; and the runs must end without a health-check stop.
# Coarse (R / dx = 10, h = 2.5 dx) to stay within half a CI minute each.
. "$SPHCAST_TEST_TOOLS"
here=$(cd "$(dirname "$0")" && pwd)
python=python3
python3 -c 'import vtk' 2>/dev/null || python=/usr/bin/python3

# runMoldCase NAME SHAPE PARAMETERS... --max-deviation F: runs the tools, then the check.
runMoldCase() {
    local name=$1; shift
    (
        cd "$scratch/$name" || exit 1
        particleizeMold > log.particleizeMold 2>&1 || fail "$name: particleizeMold: $(tail -3 log.particleizeMold)"
        setCastFields > log.setCastFields 2>&1 || fail "$name: setCastFields: $(tail -3 log.setCastFields)"
        sphCastFoam > log.sphCastFoam 2>&1 || fail "$name: sphCastFoam stopped: $(tail -5 log.sphCastFoam)"
        grep "^Run health\|^Time spent" log.sphCastFoam
        "$python" "$here/checkAgainstAnalyticWalls.py" . metal "$@" --spacing 0.004 --min-gap 0.1 > log.check ||
            fail "$name: $(grep FAIL log.check | head -3; tail -1 log.check)"
        echo "$name: $(tail -1 log.check)"
    ) || exit 1
}

# The closed sphere of radius 40 mm, half full, the metal thrown sideways at 0.6 m/s: it runs up
# the wall and falls back: |U| <= 0.9 m/s (0.6 m/s, and the fall of the surface), c = 12 m/s,
# so 1.5 v / c = 11 %.
makeSloshingSphereCase "$scratch/sphere" 0.3
runMoldCase sphere sphere 0.04 --max-deviation 0.11

# A horizontal cylinder (radius 40 mm, 40 mm long, axis y), half full, sloshing across its axis:
# the same speeds and bound as the sphere.
makeMoldCase "$scratch/cylinder" 'SetFactory("OpenCASCADE");
Cylinder(1) = {0, -0.02, 0, 0, 0.04, 0, 0.04};
Physical Surface("moldWall") = Surface{:};' \
    'half { type intersection; regions { c { type cylinder; point1 (0 -0.02 0); point2 (0 0.02 0);
            radius 0.04; } b { type box; min (-0.05 -0.05 -0.05); max (0.05 0.05 0); } } }' \
    '(0.6 0 0)' 12 0.3
runMoldCase cylinder horizontalCylinder 0.04 0.04 --max-deviation 0.11

# A jet (20 mm cube at 1.5 m/s) into the concave corner of a closed box, 45 degrees down: it
# arrives at about 1.8 m/s (1.5 m/s and 40 mm of fall), c = 20 m/s, so 1.5 v / c = 13.5 %.
makeMoldCase "$scratch/corner" 'SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.1, 0.04, 0.08};
Physical Surface("moldWall") = Surface{:};' \
    'jet { type box; min (0.02 0.01 0.04); max (0.04 0.03 0.06); }' '(1.06 0 -1.06)' 20 0.15
runMoldCase corner box 0 0 0 0.1 0.04 0.08 --max-deviation 0.135

# A column (radius 15 mm) falling 30 mm into an open cone, radius 20 mm at the floor, 40 mm at
# the rim 80 mm higher: the conical casting's mold, coarse. It lands at 0.93 m/s (0.5 m/s and
# 30 mm of fall), c = 12 m/s, so 1.5 v / c = 11.6 %.
makeMoldCase "$scratch/cone" 'SetFactory("OpenCASCADE");
Cone(1) = {0, 0, 0, 0, 0, 0.08, 0.02, 0.04};
eps = 1e-4;
top() = Surface In BoundingBox{-0.05, -0.05, 0.08 - eps, 0.05, 0.05, 0.08 + eps};
wall() = Surface{:};
wall() -= top();
Physical Surface("moldWall") = wall();' \
    'column { type cylinder; point1 (0 0 0.03); point2 (0 0 0.07); radius 0.015; }' '(0 0 -0.5)' \
    12 0.3
runMoldCase cone cone 0.02 0.04 0.08 --max-deviation 0.116
# and its shell ends flush with the open rim: no mold particle above z = 0.08 (a lip of 72 wall
# particles up to 0.58 dx above it, into the opening, before the side test of particleizeMold)
"$python" - "$scratch/cone/constant/particles/mold.vtp" <<'PYTHON' || fail "cone: wall particles above the open rim"
import sys, vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput()
above = [data.GetPoint(i)[2] for i in range(data.GetNumberOfPoints()) if data.GetPoint(i)[2] > 0.08]
print(f"cone: {data.GetNumberOfPoints()} wall particles, {len(above)} above the open rim")
sys.exit(1 if above else 0)
PYTHON
pass "metal stays in front of curved, concave and open walls"
