#!/bin/bash
# A flow run whose water leaves the domain (here: no walls at all, so it falls out of its own
# box grown by half) spills it (solver/MetalSpill.h), warning each time the spill grows by half,
# until more than healthChecks maxSpilledFraction (5 %) of it has spilled; then it stops with a
# message saying how much, where and when, writes the last good state (within the limit), and
# exits non-zero.
. "$SPHCAST_TEST_TOOLS"
findVtkPython || exit 77
tutorial=$(cd "$(dirname "$0")/../../tutorials/validation/hydrostaticTank" && pwd)
mkdir -p "$scratch/case"
cp -r "$tutorial/system" "$tutorial/constant" "$scratch/case/"
rm -rf "$scratch/case/constant/particles"
cd "$scratch/case"
sed -i 's/0\.005;/0.01;/' system/setCastFieldsDict
sed -i 's/0\.015;/0.03;/' system/sphSchemes
sed -i 's/walls .*/walls ();/' constant/physicsModels
setEntry system/controlDict endTime 1
setEntry system/controlDict writeInterval 0.5
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
if sphCastFoam > log.sphCastFoam 2> err.log; then fail "sphCastFoam succeeded"; fi
grep -q "Warning: time [0-9.]*: [0-9]* particle(s) of cloud 'water' left the domain and were spilled" err.log ||
    fail "no warning of the first spill: $(cat err.log)"
grep -q "particle(s) of cloud 'water' left the domain and were spilled (the first, particle id [0-9]* (index [0-9]*) of cloud 'water' at (.*)); spilled in all [0-9]* particles, .* above healthChecks maxSpilledFraction 5 %" err.log ||
    fail "message: $(cat err.log)"
grep -q "at time 0.0[0-9]* (step [0-9]*)" err.log || fail "no time and step: $(cat err.log)"
last=$(sed -n 's/.*The last good state, time \([^,]*\), is written.*/\1/p' err.log)
[ -n "$last" ] && [ -f "$last/water.vtp" ] || fail "last good state not written: $(cat err.log)"
castPostProcess -latestTime > /dev/null 2>&1 || fail "the last good state does not read back"
awk -F, 'NR == 2 && $12 < -0.025 - 1e-9 { exit 1 }' postProcessing/cloudSummary/water.csv ||
    fail "the written state is already outside the domain"
"$python" - "$last/water.vtp" <<'PY' || fail "the last good state's spill"
import sys
from cloudFields import cloud_totals
_, held, attributes = cloud_totals(sys.argv[1])
spilled = attributes["spilledMass"]
print(f"last good state: {100 * spilled / (held + spilled):.2f} % spilled")
assert 0 < spilled <= 0.05 * (held + spilled), "the last good state is not within the limit"
PY
pass "stopped $(grep -o 'at time [^ ]*' err.log | head -1), last good state $last written"
