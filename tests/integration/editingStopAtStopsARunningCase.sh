#!/bin/bash
# runTimeModifiable: editing system/controlDict to `stopAt writeNow;` while sphCastFoam runs
# stops it cleanly, writing the current time, and the case restarts from there.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/case" 0.0025 100 50
cd "$scratch/case"
setCastFields > /dev/null || fail "setCastFields"
sphCastFoam > log.run 2>&1 &
pid=$!
sleep 1
setEntry system/controlDict stopAt writeNow       # edited in place: a key given twice is an error
for poll in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid"; fail "still running 10 s after the edit"; fi
wait "$pid" || fail "sphCastFoam failed: $(tail -5 log.run)"
grep -q "^Stopping: stopAt writeNow at time" log.run || fail "no stop message: $(tail -5 log.run)"
grep -q "^End" log.run || fail "no End"
latest=$(ls -d [0-9]* | sort -g | tail -1)
[ "$latest" != 0 ] || fail "nothing written at the stop"
setEntry system/controlDict stopAt endTime
setEntry system/controlDict endTime "$(awk -v t="$latest" 'BEGIN { print t + 0.01 }')"
sphCastFoam > log.restart 2>&1 || fail "restart failed: $(tail -5 log.restart)"
grep -q "Starting from time $latest " log.restart || fail "restart did not start from $latest"
pass "stopped at $latest by editing stopAt, restarted from there"
