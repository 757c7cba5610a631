#!/bin/bash
# tutorials/stability/Allrun quick (the hard cases at the default settings): a jet of molten
# aluminium onto a wall at 5 and 20 m/s, 10^4 steps at rest, AC4CH at 970 K landing on a wall
# held at 300 K, and a melt sliding over a mushy front across which mu jumps by 10^7, each run by
# the tools under test with its own Allrun and checked by checkStability (no NaN, nothing through
# a wall, density and energy bounded, the step never collapsing). Every case must be stable, and
# the checker must fail a bound the run breaks (the 20 m/s jet's 12.5 % hammer against 5 %).
. "$SPHCAST_TEST_TOOLS"
findVtkPython
project=$(cd "$(dirname "$0")/../.." && pwd)
cp -r "$project/tutorials/stability" "$scratch/"
rm -rf "$scratch/stability/runs"
export PYTHON=$python SPHCAST_PROJECT=$project SPHCAST_RUN_BIN=$SPHCAST_BIN
"$scratch/stability/Allrun" quick > "$scratch/log.Allrun" 2>&1 ||
    fail "the quick suite: $(cat "$scratch/log.Allrun")"
cat "$scratch/log.Allrun"
stable=$(grep -c "^| .* | stable | [0-9]* particles" "$scratch/stability/runs/stability.md")
[ "$stable" -eq 5 ] || fail "$stable stable cases of 5: $(cat "$scratch/stability/runs/stability.md")"
cd "$scratch/stability/runs/jetOntoWall-20" || fail "no jet copy"
if "$python" ../checkStability --box 0 0 0.1 0.1 --density 0.05 > log.narrow 2>&1; then
    fail "a density bound the jet breaks passed: $(cat log.narrow)"
fi
grep -q "^FAILED: density 0.12[0-9]* beyond 0.05" log.narrow || fail "the narrow bound: $(cat log.narrow)"
pass "the stability suite's quick cases hold at the defaults; a broken bound fails"
