#!/bin/bash
# tutorials/validation/coolingCurve at 10 particles across (1,000 particles, about 15 s): a 10 mm
# AC4CH cube cooled by the air through its freezing range, solidifying without a flow
# (solidification { cloud body; }), and castPostProcess's analyses of it.
# - The centre thermocouple (a probes function object, every step) breaks its slope at the
#   liquidus and the solidus within 1 K (measured 0.000 and 0.013 K: the lines through the
#   samples either side of each kink meet there); its local freezing time is the lumped cube's
#   within 2 % (0.23 %) and its solidus time within 3 % (1.2 %: the centre lags the cube's mean
#   by the surface's cooling reaching it); the solidification map at the centre particles is the
#   thermocouple's within 0.5 % (0.003 %). compareWithLumped --check.
# - castReport.md has the three analyses' sections, the maps their fields, the plots are drawn
#   where gnuplot is installed; -latestTime keeps the time series' other rows; every file VTK
#   wrote (clouds, maps, the cavities' voxels, the .pvd indices) is well-formed XML.
# - Bad entries (an unknown type, a thermocouple outside the casting, a -time that matches
#   nothing) stop with file, line and key, and leave postProcessing/ as it was; so do a
#   solidification without a flow that names no cloud, or asks for the cooling mode.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial coolingCurve 10
cat log.compareWithLumped
"$python" compareWithLumped --check > /dev/null || fail "the cooling curve against the lumped cube"

report=postProcessing/castReport.md
for section in "## history (timeSeries)" "## coolingCurves (thermocouples)" \
               "## solidification (solidificationMaps)" "## cavities (shrinkageCavities)"; do
    grep -qF "$section" "$report" || fail "$report has no '$section'"
done
grep -q "^At time 40: 0 enclosed cavities" "$report" || fail "cavities found in a solid cube"
maps=$(ls postProcessing/solidification/*/body.vtp) || fail "no solidification map"
[ -f postProcessing/solidification/solidification.pvd ] || fail "no .pvd beside the maps"
expectWellFormedXml "$PWD"     # the time folders' clouds, the maps, the cavities' voxels
"$python" - "$maps" <<'PY' || fail "the maps' fields"
import sys, vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput().GetPointData()
for name in ("solidificationTime", "localFreezingTime", "coolingRate", "temperatureGradient",
             "niyama", "temperatureAtFillEnd", "solidFractionAtFillEnd"):
    array = data.GetArray(name)
    assert array is not None, name
    assert min(array.GetTuple1(i) for i in range(array.GetNumberOfTuples())) >= 0, name
PY
if command -v gnuplot > /dev/null; then
    for png in history/temperature_body.png coolingCurves/coolingCurves.png history/energyBalance.png; do
        [ -s "postProcessing/$png" ] || fail "gnuplot is installed but $png was not drawn"
    done
fi
rows=$(wc -l < postProcessing/history/body.csv)
castPostProcess -latestTime > /dev/null 2>&1 || fail "castPostProcess -latestTime"
[ "$(wc -l < postProcessing/history/body.csv)" -eq "$rows" ] || fail "-latestTime lost rows"
pass "castPostProcess: cooling curve, maps, report and time series of the cooling cube"

# bad entries: named, non-zero, nothing written over
snapshot() { find postProcessing -type f -exec md5sum {} + | sort; }
before=$(snapshot)
expectFailure() {  # TEXT_EXPECTED ARGS...: castPostProcess fails saying TEXT_EXPECTED
    local expected=$1
    shift
    castPostProcess "$@" > log.bad 2>&1 && fail "castPostProcess $* should fail"
    grep -qF "$expected" log.bad || fail "castPostProcess $*: no '$expected' in: $(tail -5 log.bad)"
    [ "$(snapshot)" = "$before" ] || fail "castPostProcess $* changed postProcessing/"
}
cp system/castPostProcessDict good
printf 'FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }\n
maps { type solidificationMap; cloud body; }\n' > system/castPostProcessDict
expectFailure "castPostProcessDict:3:"
expectFailure "did you mean 'solidificationMaps'?"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }\n
TC\n{\n    type thermocouples;\n    cloud body;\n    locations { centre (0.005 0.005 0.005);
        outside (0.05 0 0); }\n}\n' > system/castPostProcessDict
expectFailure "castPostProcessDict:8:9: thermocouple 'outside'"
cp good system/castPostProcessDict
expectFailure "no time folder matches -time 99" -time 99
pass "bad castPostProcess input is named (file, line, key) and writes nothing"

# solidification without a flow: the cloud must be named, the cooling mode is refused
cp constant/physicsModels models.good
sed -i 's|^    cloud           body;.*||' constant/physicsModels
sphCastFoam > log.bad 2>&1 && fail "solidification without a flow and without a cloud ran"
grep -q "physicsModels:[0-9]*:[0-9]*: solidification without a flow needs the 'cloud'" log.bad ||
    fail "no clear error for a missing cloud: $(tail -3 log.bad)"
cp models.good constant/physicsModels
sed -i 's|^    endWhenSolid .*|    cooling { flowStepsPerHeatStep 10; }|' constant/physicsModels
sphCastFoam > log.bad 2>&1 && fail "the cooling mode without a flow ran"
grep -q "physicsModels:[0-9]*:[0-9]*: 'cooling' in physicsModels/solidification needs a flow" log.bad ||
    fail "no clear error for cooling without a flow: $(tail -3 log.bad)"
pass "solidification without a flow: a missing cloud and the cooling mode are named"
