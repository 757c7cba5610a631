# Sourced by the integration tests: a scratch folder, the built tools on PATH, small cases.
set -u
export PATH="$SPHCAST_BIN:$PATH"
# the tools under test are $SPHCAST_BIN's: a copied tutorial would take etc/RunFunctions (and the
# platforms/bin beside it) from the $SPHCAST_PROJECT of a user's etc/bashrc instead
unset SPHCAST_PROJECT SPHCAST_TUTORIALS
# the tutorials' comparison scripts, run on copies of the cases, import etc/functionObjectSeries.py;
# the tests' own scripts import cloudFields.py from here
export PYTHONPATH="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../etc" && pwd):$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)${PYTHONPATH:+:$PYTHONPATH}"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
scratch=$(mktemp -d "${TMPDIR:-/tmp}/sphCastIntegration.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

# expectWellFormedXml DIR...: every VTK XML file under the folders (.vtp, .pvtp, .vti, .pvd)
# parses with Python's strict XML parser (expat, as Debian's ParaView reads them), at least one
# of each of .vtp and .pvd; prints how many were read.
expectWellFormedXml() {
    python3 - "$@" <<'PY' || fail "a file VTK wrote is not well-formed XML"
import os, sys
import xml.etree.ElementTree as ElementTree
counts = {}
for top in sys.argv[1:]:
    for folder, _, files in os.walk(top):
        for name in files:
            extension = os.path.splitext(name)[1]
            if extension not in (".vtp", ".pvtp", ".vti", ".pvd"):
                continue
            path = os.path.join(folder, name)
            try:
                ElementTree.parse(path)
            except ElementTree.ParseError as error:
                sys.exit("%s: %s" % (path, error))
            counts[extension] = counts.get(extension, 0) + 1
print("well-formed XML: " + ", ".join("%d %s" % (n, e) for e, n in sorted(counts.items())))
if ".vtp" not in counts or ".pvd" not in counts:
    sys.exit("no .vtp or no .pvd under " + " ".join(sys.argv[1:]))
PY
}

# makeFreeFallCase DIR SPACING ENDTIME WRITEINTERVAL: a block thrown upwards, gravity only.
makeFreeFallCase() {
    local dir=$1 spacing=$2 endTime=$3 writeInterval=$4
    mkdir -p "$dir/system" "$dir/constant"
    cat > "$dir/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     sphCastFoam;
startFrom       latestTime;
stopAt          endTime;
endTime         $endTime;
deltaT          1e-4;
adjustTimeStep  yes;
maxCo           0.25;
maxDeltaT       1e-3;
writeControl    adjustableRunTime;
writeInterval   $writeInterval;
logInterval     1000;
DICT
    cat > "$dir/system/setCastFieldsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setCastFieldsDict; }
spacing $spacing;
clouds
{
    metal
    {
        regions { ingot { type box; min (0 0 0.2); max (0.05 0.05 0.25); } }
        fields  { U (1 0 2); T 953; }
    }
}
DICT
    cat > "$dir/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0];
value (0 0 -9.81);
DICT
}

# onTheParabola CSV: the centroid of the thrown block (makeFreeFallCase's, the freeFall
# tutorial's; castPostProcess's cloud summary, time in column 1, x in 3, z in 5) on its exact
# parabola, x = 0.025 + t, z = 0.225 + 2 t - g t^2 / 2, within 1e-12 m at every row; prints the
# largest error.
onTheParabola() {
    awk -F, 'NR > 1 {
        t = $1; x = 0.025 + t; z = 0.225 + 2 * t - 0.5 * 9.81 * t * t
        ex = $3 - x; ez = $5 - z; if (ex < 0) ex = -ex; if (ez < 0) ez = -ez
        if (ex > worst) worst = ex; if (ez > worst) worst = ez
    } END { printf "largest centroid error %.3g m\n", worst; exit (worst > 1e-12) }' "$1"
}

# setEntry FILE KEY VALUE: replaces "KEY ...;" in a dictionary.
setEntry() { sed -i "s/^$2 .*/$2 $3;/" "$1"; }

# sameTimeFolder A B: every file of two time folders identical, byte for byte.
sameTimeFolder() {
    diff -r "$1" "$2" > /dev/null
}

# coarseWaterTank DIR: the hydrostaticTank tutorial in DIR at dx = 10 mm (500 water particles),
# h = 30 mm, to 0.2 s with writes every 0.05 s; the working directory becomes DIR.
coarseWaterTank() {
    local tutorial
    tutorial=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../tutorials/validation/hydrostaticTank" && pwd)
    mkdir -p "$1"
    cp -r "$tutorial/system" "$tutorial/constant" "$1/"
    rm -rf "$1/constant/particles"
    cd "$1" || fail "cannot enter $1"
    sed -i 's/0\.005;/0.01;/; s/0\.015;/0.03;/' system/particleizeMoldDict
    sed -i 's/0\.005;/0.01;/' system/setCastFieldsDict
    sed -i 's/0\.015;/0.03;/' system/sphSchemes
    setEntry system/controlDict endTime 0.2
    setEntry system/controlDict writeInterval 0.05
    # the tests registered again with SPHCAST_TIME_STEPPING=dualCriteria (CMakeLists.txt)
    if [ -n "${SPHCAST_TIME_STEPPING:-}" ]; then
        echo "timeStepping $SPHCAST_TIME_STEPPING;" >> system/sphSchemes
    fi
}

# expectTimeStepping LOG: with SPHCAST_TIME_STEPPING=dualCriteria, the run's log shows that its
# steps were advection steps of acoustic sub-steps (else nothing to check)
expectTimeStepping() {
    [ "${SPHCAST_TIME_STEPPING:-}" = dualCriteria ] || return 0
    grep -q "^    time stepping: dualCriteria" "$1" || fail "$1: not dualCriteria's steps"
    grep -q "^Time stepping (dualCriteria): [1-9][0-9]* advection steps" "$1" ||
        fail "$1: no advection steps counted"
    pass "$(grep '^Time stepping (dualCriteria)' "$1")"
}

# makeMoldCase DIR GEO REGIONS U SOUNDSPEED ENDTIME: a case whose mold is the Physical Surface
# "moldWall" of the .geo text GEO, filled with REGIONS (setCastFieldsDict syntax) moving at U;
# dx = 4 mm, h = 10 mm, metal of 2400 kg/m^3, writes every 0.02 s.
makeMoldCase() {
    local dir=$1 geo=$2 regions=$3 velocity=$4 soundSpeed=$5 endTime=$6
    mkdir -p "$dir/system" "$dir/constant/geometry"
    echo "$geo" > "$dir/constant/geometry/mold.geo"
    cat > "$dir/system/particleizeMoldDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }
geometry        ("mold.geo");
spacing         0.004;
supportRadius   0.01;
patches { moldWall { cloud mold; type fixedWall; mode shell; } }
DICT
    cat > "$dir/system/setCastFieldsDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setCastFieldsDict; }
spacing         0.004;
clouds { metal { regions { $regions } fields { U $velocity; } } }
DICT
    cat > "$dir/system/sphSchemes" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object sphSchemes; }
densityScheme   riemann;
viscousForm     Morris;
supportRadius   0.01;
soundSpeed      $soundSpeed;
DICT
    cat > "$dir/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     sphCastFoam;
startFrom       latestTime;
stopAt          endTime;
endTime         $endTime;
deltaT          1e-5;
adjustTimeStep  yes;
writeControl    adjustableRunTime;
writeInterval   0.02;
logInterval     1000;
DICT
    cat > "$dir/constant/physicsModels" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicsModels; }
flow { model weaklyCompressible; fluid metal; walls (mold); }
DICT
    cat > "$dir/constant/physicalProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }
metal { density 2400; viscosity 1.28e-3; }
DICT
    cat > "$dir/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0];
value (0 0 -9.81);
DICT
}

# makeSloshingSphereCase DIR ENDTIME: makeMoldCase's closed sphere of radius 40 mm, its lower
# half full of metal thrown sideways at 0.6 m/s (c = 12 m/s): curved walls all round.
makeSloshingSphereCase() {
    makeMoldCase "$1" 'SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 0.04};
Physical Surface("moldWall") = Surface{:};' \
    'half { type intersection; regions { s { type sphere; centre (0 0 0); radius 0.04; }
            b { type box; min (-0.05 -0.05 -0.05); max (0.05 0.05 0); } } }' '(0.6 0 0)' 12 "$2"
}

# makeHeatedSloshingSphere DIR INTERVAL: the sloshing sphere (to 0.1 s) as AC4CH at 900 K in an
# iron mold at 300 K (conduction, contact, air), heatTransfer's interval INTERVAL, the energyBalance
# function object `balance`; particleized and filled. The working directory stays where it was.
makeHeatedSloshingSphere() {
    makeSloshingSphereCase "$1" 0.1
    cd "$1" || fail "cannot enter $1"
    sed -i 's/fields { U (0.6 0 0); }/fields { U (0.6 0 0); T 900; }/' system/setCastFieldsDict
    echo 'setFields { mold { fields { T 300; } } }' >> system/setCastFieldsDict
    cat > constant/physicalProperties <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }
AC4CH { #includeEtc "materials/AC4CH" }
iron  { #includeEtc "materials/iron" }
DICT
    cat >> constant/physicsModels <<DICT
materials { metal AC4CH; mold iron; }
heatTransfer
{
    clouds      (metal mold);
    conduction  on;
    moldContact { coefficients ((AC4CH iron 3000)); }
    atmosphere  { T 300; coefficients ((AC4CH 20)); }
    interval    $2;
}
DICT
    sed -i 's/^logInterval .*/logInterval 500;\nfunctions { balance { type energyBalance; clouds (metal mold); } }/' system/controlDict
    particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
    setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
    cd - > /dev/null || exit 1
}

# makeChillMold DIR HEIGHT REGIONS U ENDTIME SOLIDIFICATION: makeMoldCase's open cylinder of
# radius 20 mm and height HEIGHT (m), held at 300 K (a chill conducting like the melt), with
# AC4CH at 970 K in REGIONS moving at U (c = 20 m/s); SOLIDIFICATION is the body of
# physicsModels' solidification entry. The working directory stays where it was.
makeChillMold() {
    local height=$2
    makeMoldCase "$1" "SetFactory(\"OpenCASCADE\");
Cylinder(1) = {0, 0, 0, 0, 0, $height, 0.02};
top() = Surface In BoundingBox{-0.03, -0.03, $height - 1e-4, 0.03, 0.03, $height + 1e-4};
wall() = Surface{:};
wall() -= top();
Physical Surface(\"moldWall\") = wall();" "$3" "$4" 20 "$5"
    sed -i "s/fields { U $4; }/fields { U $4; T 970; }/" "$1/system/setCastFieldsDict"
    cat > "$1/constant/physicalProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }
metal { #includeEtc "materials/AC4CH" }
mold  { density 7874; conductivity 86.05; specificHeat 640; }
DICT
    cat >> "$1/constant/physicsModels" <<DICT
heatTransfer { clouds (metal mold); fixedTemperature { mold 300; } conduction on; }
solidification { $6 }
DICT
}

# makeChillCup DIR ENDTIME SOLIDIFICATION: makeChillMold's cylinder 45 mm high with AC4CH from
# 6 to 30 mm up dropped at 0.5 m/s.
makeChillCup() {
    makeChillMold "$1" 0.045 \
        'melt { type cylinder; point1 (0 0 0.006); point2 (0 0 0.03); radius 0.02; }' \
        '(0 0 -0.5)' "$2" "$3"
}

# makeRheologyCup DIR ENDTIME WRITEINTERVAL RHEOLOGY: the chill cup (makeChillCup, frozenSolid)
# with the physicsModels entry RHEOLOGY, logged every 50 steps, particleized and filled.
makeRheologyCup() {
    makeChillCup "$1" "$2" "model frozenSolid;"
    cd "$1" || fail "cannot enter $1"
    echo "$4" >> constant/physicsModels
    setEntry system/controlDict writeInterval "$3"
    setEntry system/controlDict logInterval 50
    particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
    setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
    cd - > /dev/null || exit 1
}

# findVtkPython: sets `python` to the first of $PYTHON, python3 and /usr/bin/python3 that imports
# vtk (the tutorials' comparison scripts read .vtp clouds with it); without one the test is
# skipped (exit status 77).
findVtkPython() {
    python=
    local candidate
    for candidate in ${PYTHON:-} python3 /usr/bin/python3; do
        "$candidate" -c 'import vtk' 2> /dev/null && { python=$candidate; return 0; }
    done
    echo "SKIP: no python3 with the vtk module to read the .vtp clouds"
    exit 77
}

# preprocessTutorialCase PATH DIR [SPACING]: the system/ and constant/ of tutorials/PATH in DIR
# (its setResolution SPACING first, when given; without the particles a run in the tutorial
# left), then particleizeMold and setCastFields; a failure fails the test with its log. Leaves
# the working directory in DIR.
preprocessTutorialCase() {
    local tutorial dir=$2 spacing=${3:-}
    tutorial=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../tutorials/$1" && pwd)
    mkdir -p "$dir"
    cp -r "$tutorial/system" "$tutorial/constant" "$dir/"
    rm -rf "$dir/constant/particles"
    cd "$dir" || fail "cannot enter $dir"
    if [ -n "$spacing" ]; then
        cp "$tutorial/setResolution" . && ./setResolution "$spacing" > /dev/null ||
            fail "$1: setResolution $spacing"
    fi
    particleizeMold > log.particleizeMold 2>&1 || fail "$1: particleizeMold: $(tail -5 log.particleizeMold)"
    setCastFields > log.setCastFields 2>&1 || fail "$1: setCastFields: $(tail -5 log.setCastFields)"
}

# copyTutorial PATH: tutorials/PATH copied into the scratch folder, laid out as in the project
# (beside an etc/ with RunFunctions and functionObjectSeries.py and a platforms/bin that is
# $SPHCAST_BIN), and cleaned. Leaves the working directory in the copy.
copyTutorial() {
    local path=$1 project
    project=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
    mkdir -p "$scratch/etc" "$scratch/platforms" "$scratch/tutorials/$(dirname "$path")"
    cp "$project/etc/RunFunctions" "$project/etc/functionObjectSeries.py" "$scratch/etc/"
    [ -e "$scratch/platforms/bin" ] || ln -s "$SPHCAST_BIN" "$scratch/platforms/bin"
    cp -r "$project/tutorials/$path" "$scratch/tutorials/$(dirname "$path")/"
    cd "$scratch/tutorials/$path" || fail "cannot enter the copy of $path"
    ./Allclean > /dev/null || fail "$path: Allclean"
}

# runValidationTutorial CASE ARGS...: tutorials/validation/CASE copied (copyTutorial) and run
# with `Allrun ARGS` (PYTHON=$python: call findVtkPython first); a failed Allrun fails the test
# with its log. Leaves the working directory in the copy.
runValidationTutorial() {
    local case=$1
    shift
    copyTutorial "validation/$case"
    PYTHON=$python ./Allrun "$@" > log.Allrun 2>&1 ||
        { cat log.Allrun >&2; fail "$case: Allrun $*"; }
}
