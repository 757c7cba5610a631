#!/bin/bash
# castPostProcess's 3D views (type view) on conicalMold at 6 mm, solidified to the end:
# - Without an X display (DISPLAY unset) the views are skipped with a note in the report and a
#   warning, castPostProcess succeeds, and the numbers are there: the reconstructed surface of
#   the cut-open casting encloses the volume of the particles on the kept side (sum m / rho)
#   within 8 % (the level 1/2 of the kernel sum rounds the casting's convex edges over about a
#   kernel, an error of first order in the spacing: -6.5 % at 6 mm, -2.3 % at the tutorial's
#   3 mm; a wrong kernel or particle volume would be tens of per cent off).
# - A slice's picture is drawn without a display, its colour bar labelled (low, field, high).
# - Under xvfb-run (Debian package xvfb) the casting cut open is drawn by solidusTime: a
#   1000 x 750 PNG with the metal coloured from blue (first frozen, at the walls) to red (the
#   last, at the top of the axis), the black ball at the last particle to freeze; by T a frame
#   at every written time, and their GIF where ffmpeg is installed (else the report says why).
# - A void planted in a block is drawn and measured, a droplet beside it is not a void (below).
# - A clip with a zero normal and a size out of range stop castPostProcess
#   with file, line and key.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
command -v xvfb-run > /dev/null || fail "xvfb-run is missing (Debian package xvfb, which ./Allwmake installs)"
preprocessTutorialCase conicalMold "$scratch/cone" 6
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
cat > system/castPostProcessDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }
casting { type view; cloud metal; field solidusTime; clip ((0 0 0) (0 1 0)); }
cooling { type view; cloud metal; field T; clip ((0 0 0) (0 1 0)); times all; }
section { type slice; point (0 0 0); normal (0 1 0); thickness 0.012; field T; }
DICT
report=postProcessing/castReport.md
env -u DISPLAY castPostProcess > log.noDisplay 2>&1 || fail "castPostProcess without a display: $(tail -5 log.noDisplay)"
grep -q "Not drawn: no X display" $report || fail "no note of the missing display in $report"
grep -q "no X display, not drawn" log.noDisplay || fail "no warning of the missing display"
[ ! -e postProcessing/casting/*/solidusTime.png ] 2>/dev/null || fail "a picture without a display"
# the slice needs no display, its colour bar labelled (FreeType): dark text under the bar
"$python" - postProcessing/section/*/T.png <<'PY' || fail "the slice's colour bar has no labels"
import sys, vtk
reader = vtk.vtkPNGReader(); reader.SetFileName(sys.argv[1]); reader.Update()
image = reader.GetOutput(); width = image.GetDimensions()[0]
pixels = image.GetPointData().GetScalars()
dark = sum(1 for k in range(22 * width) if max(pixels.GetTuple3(k)[:3]) < 100)
print("the slice: %d dark pixels in the label rows" % dark)
sys.exit(0 if dark > 60 else 1)
PY
volumes=$(grep -A2 "^## casting" $report | sed -n 's/.* it encloses \([0-9.e+-]*\) cm^3; the particles on the kept side hold \([0-9.e+-]*\) cm^3.*/\1 \2/p')
[ -n "$volumes" ] || fail "no volumes in the report: $(grep -A2 '^## casting' $report)"
awk -v v="$volumes" 'BEGIN { split(v, a, " "); r = a[1] / a[2]; printf "surface %s cm^3, particles %s cm^3: %+.2f %%\n", a[1], a[2], 100 * (r - 1); exit !(r > 0.92 && r < 1.08) }' ||
    fail "the surface's volume is not the particles'"

xvfb-run -a -n $((100 + RANDOM % 800)) castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess under xvfb-run: $(tail -5 log.castPostProcess)"
last=$(ls -d [0-9]* | sort -g | tail -1)
picture=postProcessing/casting/$last/solidusTime.png
[ -f "$picture" ] || fail "no $picture: $(ls postProcessing/casting)"
grep -qF "![casting/$last/solidusTime.png](casting/$last/solidusTime.png)" $report || fail "the picture is not in the report"
"$python" - "$picture" "$(ls -d [0-9]* | wc -l)" <<'PY' || fail "the picture of the casting"
import glob, sys, vtk
reader = vtk.vtkPNGReader()
reader.SetFileName(sys.argv[1])
reader.Update()
image = reader.GetOutput()
width, height, _ = image.GetDimensions()
pixels = image.GetPointData().GetScalars()
blue = red = black = coloured = 0
for k in range(width * height):
    r, g, b = pixels.GetTuple3(k)[:3]
    if max(r, g, b) < 40:
        black += 1
    elif b > 150 and r < 80 and g < 80:
        blue += 1
    elif r > 150 and b < 80 and g < 80:
        red += 1
    if not (r > 245 and g > 245 and b > 245):
        coloured += 1
share = coloured / (width * height)
print("%d x %d pixels: %.0f %% drawn, %d blue, %d red, %d black" % (width, height, 100 * share, blue, red, black))
frames = len(glob.glob("postProcessing/cooling/*/T.png"))
print("%d frames by T of %s written times" % (frames, sys.argv[2]))
ok = (width, height) == (1000, 750) and 0.15 < share < 0.9 and blue > 1000 and red > 100 and black > 20
sys.exit(0 if ok and frames == int(sys.argv[2]) else 1)
PY
if command -v ffmpeg > /dev/null; then
    [ -s postProcessing/cooling/cooling.gif ] || fail "ffmpeg is installed but no cooling.gif"
    grep -qF "![cooling/cooling.gif](cooling/cooling.gif)" $report || fail "the GIF is not in the report"
else
    grep -q "ffmpeg is not on the PATH" $report || fail "no note that ffmpeg is missing"
fi

# a block of 30^3 particles (dx = 2 mm, h = 3 dx) with a spherical void of 6 dx radius planted
# at its centre, and a droplet of 27 particles beside it: the void is drawn in magenta and
# measured within 10 % of the particles taken out (the level 1/2 of the kernel sum bulges into
# a concave wall: -5.4 % measured), the droplet is metal, not a void, and the metal's volume is
# the particles' within 3 %
mkdir -p "$scratch/void/system" "$scratch/void/1" && cd "$scratch/void"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }\nsupportRadius 0.006;\n' > system/sphSchemes
printf 'FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }\nblock { type view; cloud metal; field T; }\n' > system/castPostProcessDict
planted=$("$python" - <<'PY'
import math, vtk
dx, n = 0.002, 30
centre = (n * dx / 2,) * 3
points, T, volume = vtk.vtkPoints(), vtk.vtkDoubleArray(), vtk.vtkDoubleArray()
T.SetName("T"); volume.SetName("volume")
taken = 0
def add(x):
    points.InsertNextPoint(x); T.InsertNextValue(900 + 1e3 * x[2]); volume.InsertNextValue(dx ** 3)
for k in range(n):
    for j in range(n):
        for i in range(n):
            x = ((i + .5) * dx, (j + .5) * dx, (k + .5) * dx)
            if math.dist(x, centre) < 6 * dx: taken += 1
            else: add(x)
for k in range(3):
    for j in range(3):
        for i in range(3):
            add(((i + .5 + n + 5) * dx, (j + .5) * dx, (k + .5) * dx))
cloud = vtk.vtkPolyData(); cloud.SetPoints(points)
cloud.GetPointData().AddArray(T); cloud.GetPointData().AddArray(volume)
spacing = vtk.vtkDoubleArray(); spacing.SetName("spacing"); spacing.InsertNextValue(dx)
cloud.GetFieldData().AddArray(spacing)
writer = vtk.vtkXMLPolyDataWriter(); writer.SetInputData(cloud); writer.SetFileName("1/metal.vtp"); writer.Write()
print(taken * dx ** 3 * 1e6)
PY
)
xvfb-run -a -n $((100 + RANDOM % 800)) castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess on the block: $(tail -5 log.castPostProcess)"
line=$(grep -A2 "^## block" $report | grep "enclosed in the metal")
echo "$line"
echo "$line" | awk -v planted="$planted" '{
    if (!match($0, /1 void enclosed in the metal \(magenta\): [0-9.]+ cm\^3/)) exit 1
    split(substr($0, RSTART, RLENGTH), w, " "); found = w[8]
    match($0, /it encloses [0-9.]+ cm\^3; the particles hold [0-9.]+/); split(substr($0, RSTART, RLENGTH), v, " ")
    printf "void %s cm^3 of %.4g planted (%+.1f %%); metal %s of %s cm^3\n", found, planted, 100 * (found / planted - 1), v[3], v[8]
    exit !(found > 0.9 * planted && found < 1.1 * planted && v[3] > 0.97 * v[8] && v[3] < 1.03 * v[8]) }' ||
    fail "the planted void and the metal's volume: $line"
"$python" - postProcessing/block/1/T.png <<'PY' || fail "no magenta void in the picture"
import sys, vtk
reader = vtk.vtkPNGReader(); reader.SetFileName(sys.argv[1]); reader.Update()
pixels = reader.GetOutput().GetPointData().GetScalars()
magenta = sum(1 for k in range(pixels.GetNumberOfTuples())
              if pixels.GetTuple3(k)[0] > 150 and pixels.GetTuple3(k)[2] > 100 and pixels.GetTuple3(k)[1] < 90)
print("%d magenta pixels" % magenta)
sys.exit(0 if magenta > 2000 else 1)
PY

cd "$scratch/cone"
expectFailure() {  # TEXT_EXPECTED ENTRY: castPostProcess with the entry fails saying TEXT_EXPECTED
    local expected=$1 entry=$2
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }\n%s\n' "$entry" > system/castPostProcessDict
    env -u DISPLAY castPostProcess > log.bad 2>&1 && fail "castPostProcess should refuse: $entry"
    grep -qF "$expected" log.bad || fail "no '$expected' for '$entry' in: $(tail -3 log.bad)"
}
expectFailure "castPostProcessDict:2" "v { type view; cloud metal; field T; clip ((0 0 0) (0 0 0)); }"
expectFailure "'size'" "v { type view; cloud metal; field T; size (10 10); }"
expectFailure "clip" "v { type view; cloud metal; field T; clip ((0 0 0) (0 0 0)); }"
pass "the cone's views: skipped with a note without a display, drawn under xvfb-run, bad entries refused"
