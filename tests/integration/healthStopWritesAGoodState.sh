#!/bin/bash
# A run stopped by its health checks writes the last state that passed every check, says what
# went wrong, where and when, and that state restarts. Forced here with a density bound of 2 %
# on metal sloshing in a sphere (it reaches ~9 % at c = 12 m/s): the written state must hold no
# density deviation above 2 %, no particle behind the mold surface, nothing non-finite.
. "$SPHCAST_TEST_TOOLS"
here=$(cd "$(dirname "$0")" && pwd)
python=python3
python3 -c 'import vtk' 2>/dev/null || python=/usr/bin/python3
makeSloshingSphereCase "$scratch/case" 0.3
cd "$scratch/case"
cat >> system/controlDict <<DICT
healthChecks { warnDensityDeviation 0.01; maxDensityDeviation 0.02; }
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
if sphCastFoam > log.sphCastFoam 2> err.log; then fail "the run did not stop"; fi
grep -q "Warning: time .* deviates by" err.log || fail "no warning before the stop: $(head -5 err.log)"
grep -q "FATAL ERROR" err.log || fail "no error: $(tail -5 err.log)"
grep -q "at time [0-9.e-]* (step [0-9]*): the density of particle id [0-9]* (index [0-9]*) of cloud 'metal' at (.*) deviates by [0-9.]* % from rho_s (healthChecks maxDensityDeviation 2 %)" err.log ||
    fail "message: $(grep -A2 FATAL err.log)"
last=$(sed -n 's/.*The last good state, time \([^,]*\), is written.*/\1/p' err.log)
[ -n "$last" ] && [ -f "$last/metal.vtp" ] || fail "last good state not written: $(cat err.log)"
grep -q "^Time spent" log.sphCastFoam || fail "no time summary at the stop"
mkdir good && cp -r "$last" good/ && cp -r constant system good/
"$python" "$here/checkAgainstAnalyticWalls.py" good metal sphere 0.04 --spacing 0.004 \
    --max-deviation 0.02 --min-gap 0 --min-times 1 > log.check || fail "the written state: $(cat log.check)"
# it restarts, with the default thresholds, and runs on for 0.02 s
sed -i "/^healthChecks/d; s/^endTime .*/endTime $(awk -v t="$last" 'BEGIN { print t + 0.02 }');/" system/controlDict
sphCastFoam > log.restart 2>&1 || fail "restart from $last: $(tail -5 log.restart)"
pass "stopped at $(grep -o 'at time [^ ]*' err.log | head -1), state $last written: $(tail -1 log.check)"
