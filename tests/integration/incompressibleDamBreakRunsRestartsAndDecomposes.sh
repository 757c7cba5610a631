#!/bin/bash
# flow { model incompressible; } through the tool chain (doc/physics.md §9.2): the 2D dam break
# tutorial (a/dx = 20, 800 water particles) with its pressure solved for rho_s. The front within
# the weakly compressible bounds of damBreak2DCaseRunsWithTheTools (measured 1.08 % RMS); a run
# stopped at 0.1 s and restarted on 1 thread ends on the bits of the uninterrupted run on 2;
# `mpirun -np 2 -parallel` within 1e-9 m of its front at every step; the step log shows the solve, not a Mach number;
# a misspelt pressureSolverCoeffs key names file, line and the valid keys.
. "$SPHCAST_TEST_TOOLS"
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/damBreak2D" && pwd)
mkdir -p "$scratch/case"
cp -r "$tutorial/system" "$tutorial/constant" "$tutorial/validationData" \
    "$tutorial/compareWithExperiment" "$scratch/case/"
rm -rf "$scratch/case/constant/particles"
cd "$scratch/case"
sed -i 's/model       weaklyCompressible;/model       incompressible;/' constant/physicsModels
sed -i '/^timeStepping/d' system/sphSchemes
grep -q "model       incompressible;" constant/physicsModels || fail "the tutorial's flow entry moved"
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
cp -r . ../restarted
OMP_NUM_THREADS=2 sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
grep -q "^Flow: incompressible SPH (2D)" log.sphCastFoam || fail "$(grep '^Flow' log.sphCastFoam)"
grep -q "no sound speed: the pressure is solved" log.sphCastFoam || fail "sound speed line"
! grep -q "Mach" log.sphCastFoam || fail "a Mach number in the incompressible log"
grep -q "^Pressure solves (incompressible): " log.sphCastFoam || fail "no pressure solves logged"
python3 compareWithExperiment > log.compare 2>&1 || fail "compareWithExperiment: $(tail -3 log.compare)"
grep converged log.compare
awk '/^against the converged/ { found = 1; rms = $7; largest = $10; if (rms >= 1.5 || largest >= 3) exit 1 }
     END { if (!found) exit 1 }' log.compare || fail "converged front: $(grep converged log.compare)"
# stopped at 0.1 s (a write time), restarted on another thread count
cd ../restarted
sed -i 's/^endTime .*/endTime 0.1;/' system/controlDict
OMP_NUM_THREADS=1 sphCastFoam > log.first 2>&1 || fail "first half: $(tail -5 log.first)"
sed -i 's/^endTime .*/endTime 0.25;/' system/controlDict
OMP_NUM_THREADS=1 sphCastFoam > log.second 2>&1 || fail "restart: $(tail -5 log.second)"
cmp -s ../case/0.25/water.vtp 0.25/water.vtp ||
    fail "the restarted run (1 thread) differs from the uninterrupted one (2 threads) at 0.25 s"
if command -v mpirun > /dev/null; then
    mkdir -p ../parallel && cp -r ../case/system ../case/constant ../parallel/ && cp -r ../restarted/0 ../parallel/
    cd ../parallel
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\n' \
        > system/decomposeParDict
    OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 SPHCAST_CHECK_COLLECTIVES=1 \
        timeout 300 mpirun --oversubscribe -np 2 sphCastFoam -parallel > log.parallel 2>&1 ||
        fail "mpirun -np 2: $(tail -5 log.parallel)"
    # the front function object at every step within 1e-9 m (2e-7 dx) of the serial run's
    python3 - "$scratch/case" "$scratch/parallel" <<'PY' || fail "2 ranks against the serial run"
import os, sys
from functionObjectSeries import read_series
def front(case):
    os.chdir(case)
    return read_series("front", "front")[0]
serial, parallel = front(sys.argv[1]), front(sys.argv[2])
worst = max(abs(r[1] - s[1]) for r, s in zip(parallel, serial))
print("2 ranks: %d front rows within %.2g m of the serial run's" % (len(parallel), worst))
if len(parallel) != len(serial) or worst > 1e-9:
    sys.exit(1)
PY
fi
# a misspelt key of pressureSolverCoeffs
cd ../case
printf 'pressureSolverCoeffs { tolerance 1e-3; }\n' >> system/sphSchemes
line=$(grep -n "pressureSolverCoeffs" system/sphSchemes | cut -d: -f1)
sed -i 's/^endTime .*/endTime 0.3;/' system/controlDict
if sphCastFoam > log.bad 2>&1; then fail "a misspelt pressureSolverCoeffs key accepted"; fi
grep -q "sphSchemes:$line" log.bad || fail "no file and line: $(tail -5 log.bad)"
grep -q "densityTolerance" log.bad || fail "the valid keys not named: $(tail -5 log.bad)"
pass "incompressible dam break: the front within 1.5 % RMS of the converged one; restart and threads bit for bit; 2 ranks; a bad key named"
