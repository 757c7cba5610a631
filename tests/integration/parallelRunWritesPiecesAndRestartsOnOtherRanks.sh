#!/bin/bash
# The 2D dam break tutorial (a/dx = 20, 0 .. 0.25 s) as a cluster user runs it:
# `mpirun -np 2` and `-np 4 sphCastFoam -parallel` after the serial particleizeMold and
# setCastFields. Each written time holds water.pvtp with a piece per rank, which the .pvd lists;
# castPostProcess reads them, and its cloud summary (count, centroid, mean velocity, extent)
# equals the serial run's within 1e-9 m or m/s at every time; the front function object within
# 1e-10 m; every file written is well-formed XML. The 2 ranks read a decomposeParDict copied
# from OpenFOAM (method scotch, run as recursive bisection), the 4 hierarchical cuts. A run
# stopped at 0.1 on 2 ranks goes on from there on 4. A decomposeParDict for
# another number of ranks is refused with its file and line, on every rank, without a hang.
# conicalMold at 6 mm on 2 ranks solidifies at the serial run's time, with its time series.
# (The particle-by-particle comparison with the serial run, on 1, 2 and 4 ranks and across
# restarts, is tests/unit/parallel/ParallelSolverTest.cpp.)
. "$SPHCAST_TEST_TOOLS"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(timeout 300 mpirun --oversubscribe)
preprocessTutorialCase validation/damBreak2D "$scratch/serial"
# 2 ranks: OpenFOAM's own damBreak decomposeParDict as a user copies it, with method scotch (a
# partitioner of a mesh's cells, run as recursive bisection); 4 ranks: hierarchical cuts
for ranks in 2 4; do cp -r "$scratch/serial" "$scratch/np$ranks"; done
cat > "$scratch/np2/system/decomposeParDict" <<'DICT'
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      decomposeParDict;
}
numberOfSubdomains 2;
method          scotch;
simpleCoeffs
{
    n               (2 1 1);
    delta           0.001;
}
hierarchicalCoeffs
{
    n               (1 1 1);
    delta           0.001;
    order           xyz;
}
manualCoeffs
{
    dataFile        "";
}
distributed     no;
roots           ( );
DICT
cat > "$scratch/np4/system/decomposeParDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 4;
method hierarchical;
hierarchicalCoeffs { n (2 2 1); order yxz; }
DICT
cp -r "$scratch/np2" "$scratch/restart"
sphCastFoam > log.sphCastFoam 2>&1 || fail "serial: $(tail -5 log.sphCastFoam)"
castPostProcess > log.castPostProcess 2>&1 || fail "serial castPostProcess"
for ranks in 2 4; do
    cd "$scratch/np$ranks"
    "${mpirun[@]}" -np $ranks sphCastFoam -parallel > log.sphCastFoam 2>&1 ||
        fail "-np $ranks: $(tail -8 log.sphCastFoam)"
    method=("recursive bisection (" "hierarchical cuts n (2 2 1), order yxz (y < ")
    grep -qF "Decomposition: $ranks subdomains by ${method[ranks / 4]}" log.sphCastFoam ||
        fail "-np $ranks: no decomposition line: $(grep -A1 '^Decomposition' log.sphCastFoam)"
    [ $ranks = 4 ] || grep -qF "(decomposeParDict: method scotch (a partitioner of a mesh's cells): recursive bisection" log.sphCastFoam ||
        fail "-np 2: the log does not say how scotch ran: $(grep -A1 '^Decomposition' log.sphCastFoam)"
    # the surge carries the water across the cuts: space is cut again as it goes (8 times on
    # 2 ranks), every cloud redistributed, and the results stay the serial run's
    grep -q "^Decomposition at the end: [1-9][0-9]* re-balances" log.sphCastFoam ||
        fail "-np $ranks: no re-balance: $(grep 'Decomposition at the end' log.sphCastFoam)"
    [ "$(grep -c '^Time = ' log.sphCastFoam)" -gt 0 ] && [ "$(grep -c '^End$' log.sphCastFoam)" = 1 ] ||
        fail "-np $ranks: the log is not one rank's"
    for time in 0.05 0.1 0.15 0.2 0.25; do
        [ -f $time/water.pvtp ] && [ -f $time/water/water_$((ranks - 1)).vtp ] ||
            fail "-np $ranks: $time/water.pvtp and its pieces: $(ls $time)"
        grep -q "file=\"$time/water.pvtp\"" np$ranks.pvd || fail "-np $ranks: the .pvd lists no $time/water.pvtp"
    done
    castPostProcess > log.castPostProcess 2>&1 || fail "-np $ranks castPostProcess: $(tail -5 log.castPostProcess)"
    # the serial tool on the pieces: the summary within round-off of the serial run's
    paste -d, "$scratch/serial/postProcessing/cloudSummary/water.csv" postProcessing/cloudSummary/water.csv |
        awk -F, 'NR > 1 { n++; half = NF / 2; if ($1 != $(half + 1) || $2 != $(half + 2)) exit 1
                 for (k = 3; k <= half; k++) { d = $k - $(half + k); if (d < 0) d = -d; if (d > 1e-9) exit 1 } }
                 END { if (n != 6) exit 1 }' ||
        fail "-np $ranks: cloud summary off the serial one: $(tail -2 postProcessing/cloudSummary/water.csv)"
done
# every file VTK wrote (the pieces, the .pvtp and .pvd indices) opens in a strict XML parser
expectWellFormedXml "$scratch/serial" "$scratch/np2" "$scratch/np4"
python3 - "$scratch/serial" "$scratch/np2" "$scratch/np4" <<'PY' || fail "front function object"
import os, sys
from functionObjectSeries import read_series
def front(case):
    os.chdir(case)
    return read_series("front", "front")[0]
serial = front(sys.argv[1])
for case in sys.argv[2:]:
    rows = front(case)
    worst = max(abs(r[1] - s[1]) for r, s in zip(rows, serial))
    print("%s: %d front rows within %.2g m of the serial run's" % (case, len(rows), worst))
    if len(rows) != len(serial) or worst > 1e-10:
        sys.exit(1)
PY

# 2 ranks to 0.1, then 4 ranks on from there
cd "$scratch/restart"
sed -i 's/^endTime .*/endTime 0.1;/' system/controlDict
"${mpirun[@]}" -np 2 sphCastFoam -parallel > log.first 2>&1 || fail "2 ranks to 0.1: $(tail -5 log.first)"
sed -i 's/^endTime .*/endTime 0.25;/' system/controlDict
sed -i 's/numberOfSubdomains 2/numberOfSubdomains 4/' system/decomposeParDict
"${mpirun[@]}" -np 4 sphCastFoam -parallel > log.second 2>&1 || fail "4 ranks from 0.1: $(tail -5 log.second)"
grep -q "Starting from time 0.1" log.second || fail "the 4 ranks did not start from 0.1"
[ -f 0.25/water/water_3.vtp ] || fail "the 4 ranks wrote no 4 pieces"
grep -q "fluid water: 800 particles" log.second || fail "particles lost: $(grep 'fluid water' log.second)"

# 4 subdomains on 2 ranks: refused, naming the file and line, once, and no rank hangs
cd "$scratch/np4"
if "${mpirun[@]}" -np 2 sphCastFoam -parallel > log.wrong 2>&1; then
    fail "4 subdomains on 2 ranks ran"
fi
grep -q "decomposeParDict:2.*numberOfSubdomains 4 in decomposeParDict, but mpirun started 2 ranks" log.wrong ||
    fail "wrong rank count: $(grep -m3 -A2 'FATAL' log.wrong)"
[ "$(grep -c 'FATAL ERROR' log.wrong)" = 1 ] || fail "the error printed $(grep -c 'FATAL ERROR' log.wrong) times"

# conicalMold at 6 mm (flow, conduction into the held mold, solidification, the cooling mode) on
# 2 ranks: solid at the serial run's time to its printed digits, and castPostProcess's time
# series of the metal within round-off
preprocessTutorialCase conicalMold "$scratch/coneSerial" 6
cp -r "$scratch/coneSerial" "$scratch/coneParallel"
cp "$scratch/np2/system/decomposeParDict" "$scratch/coneParallel/system/"
sphCastFoam > log.sphCastFoam 2>&1 || fail "cone serial: $(tail -5 log.sphCastFoam)"
castPostProcess > log.castPostProcess 2>&1 || fail "cone serial castPostProcess"
cd "$scratch/coneParallel"
"${mpirun[@]}" -np 2 sphCastFoam -parallel > log.sphCastFoam 2>&1 || fail "cone on 2 ranks: $(tail -8 log.sphCastFoam)"
castPostProcess > log.castPostProcess 2>&1 || fail "cone on 2 ranks: castPostProcess"
solid=$(grep "^Stopping: the casting is solid" "$scratch/coneSerial/log.sphCastFoam")
[ -n "$solid" ] && grep -qxF "$solid" log.sphCastFoam ||
    fail "cone: serially '$solid', on 2 ranks '$(grep '^Stopping' log.sphCastFoam)'"
# castPostProcessDict's time series of the metal (T range and mean, solid fraction, counts,
# density range, energies): within 1e-6 of the serial one's, relative to each value (measured:
# 1.1e-7 the internal energy, 4e-8 the highest T, the counts equal; round-off grows over the
# 11.5 s of flow, as in the dam break)
paste -d, "$scratch/coneSerial/postProcessing/history/metal.csv" postProcessing/history/metal.csv |
    awk -F, 'NR > 1 { n++; half = NF / 2; if ($1 != $(half + 1) || $2 != $(half + 2)) exit 1
             for (k = 3; k <= half; k++) { d = $k - $(half + k); if (d < 0) d = -d
                 scale = $k < 0 ? -$k : $k; if (d > 1e-6 * (scale > 1 ? scale : 1)) exit 1 } }
             END { if (n < 3) exit 1 }' ||
    fail "cone: time series on 2 ranks off the serial one: $(tail -1 postProcessing/history/metal.csv)"
pass "dam break on 2 and 4 ranks: pieces, .pvd, castPostProcess and front as the serial run's; 2 then 4 ranks; the cone solid on 2 ranks as serially ($solid)"
