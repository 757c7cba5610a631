#!/bin/bash
# A flow run whose water leaves the domain (here: no walls at all, so it falls out of its own
# box grown by half) stops with a message saying how many, where and when, writes the last good
# state, and exits non-zero.
. "$SPHCAST_TEST_TOOLS"
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
grep -q "particle(s) of cloud 'water' left the domain" err.log || fail "message: $(cat err.log)"
grep -q "at time 0.0[0-9]* (step [0-9]*)" err.log || fail "no time and step: $(cat err.log)"
last=$(sed -n 's/.*The last good state, time \([^,]*\), is written.*/\1/p' err.log)
[ -n "$last" ] && [ -f "$last/water.vtp" ] || fail "last good state not written: $(cat err.log)"
castPostProcess -latestTime > /dev/null 2>&1 || fail "the last good state does not read back"
awk -F, 'NR == 2 && $12 < -0.025 - 1e-9 { exit 1 }' postProcessing/cloudSummary/water.csv ||
    fail "the written state is already outside the domain"
pass "stopped at $(grep -o 'at time [^ ]*' err.log | head -1), last good state $last written"
