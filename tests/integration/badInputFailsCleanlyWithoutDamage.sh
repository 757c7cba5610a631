#!/bin/bash
# Bad input: a clear message naming file, line and key, a non-zero exit, and no change to any
# file already written.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/case" 0.005 0.1 0.05
cd "$scratch/case"
setCastFields > /dev/null || fail "setCastFields"
sphCastFoam > /dev/null 2>&1 || fail "first run"
before=$(find . -path ./system -prune -o -type f -print0 | sort -z | xargs -0 md5sum)

# expectFailure MESSAGE COMMAND...: the command fails and its stderr holds MESSAGE.
expectFailure() {
    local message=$1; shift
    if "$@" > out.log 2> err.log; then fail "'$*' succeeded on bad input"; fi
    grep -qF -- "$message" err.log || fail "'$*': expected '$message', got: $(cat err.log)"
    rm -f out.log err.log
}

cp system/controlDict controlDict.good
setEntry system/controlDict endTime 0.3
sed -i 's/^deltaT .*/deltaT 1e-4/' system/controlDict       # missing ';'
expectFailure "system/controlDict:" sphCastFoam
cp controlDict.good system/controlDict
sed -i 's/^endTime /endTme /' system/controlDict
expectFailure "unknown key 'endTme' in controlDict; did you mean 'endTime'?" sphCastFoam
cp controlDict.good system/controlDict
sed -i 's/^writeControl .*/writeControl sometimes;/' system/controlDict
expectFailure "unknown writeControl 'sometimes'" sphCastFoam
cp controlDict.good system/controlDict
mv constant/g g.good
expectFailure "constant/g" sphCastFoam
mv g.good constant/g
sed -i 's/^spacing .*/spacing 1e-5;/' system/setCastFieldsDict
expectFailure "more than maxParticles" setCastFields
expectFailure "unrecognised option" sphCastFoam -bogus
expectFailure "does not exist" sphCastFoam -case "$scratch/nowhere"
rm controlDict.good

after=$(find . -path ./system -prune -o -type f -print0 | sort -z | xargs -0 md5sum)
[ "$before" = "$after" ] || fail "results on disk changed"
sphCastFoam -help | grep -q -- "-case" || fail "-help does not list -case"
pass "7 kinds of bad input rejected with clear messages; results untouched"
