#!/bin/bash
# SIGKILL at random moments (many of them inside a time-folder write of 125,000 particles):
# after each kill every time folder in the case is complete and readable, the run restarts from
# latestTime, and the final time is identical byte for byte to an uninterrupted run's.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/whole" 0.001 0.1 0.005
cp -r "$scratch/whole" "$scratch/killed"
(cd "$scratch/whole" && setCastFields > /dev/null && sphCastFoam > log 2>&1) || fail "whole run"

cd "$scratch/killed"
setCastFields > /dev/null || fail "setCastFields"
kills=0
midWrite=0
for attempt in 1 2 3 4 5 6; do
    sphCastFoam > "log.$attempt" 2>&1 &
    pid=$!
    if [ $attempt -le 3 ]; then
        # Kill while a time folder is being written: wait for its hidden folder to appear.
        for poll in $(seq 1000); do
            ls -a | grep -q '\.writing$' && break
            sleep 0.005
        done
        ls -a | grep -q '\.writing$' && midWrite=$((midWrite + 1))
    else
        sleep "0.$(( RANDOM % 9 + 1 ))"
    fi
    if kill -9 "$pid" 2>/dev/null; then kills=$((kills + 1)); fi
    wait "$pid" 2>/dev/null
    # Every visible time folder must be complete: castPostProcess reads them all.
    castPostProcess > "log.post.$attempt" 2>&1 ||
        fail "after kill $attempt: $(tail -3 "log.post.$attempt")"
done
sphCastFoam > log.final 2>&1 || fail "final restart: $(tail -5 log.final)"
grep -q '^End' log.final || fail "final restart did not finish"
sameTimeFolder "$scratch/whole/0.1" 0.1 || fail "final time differs from the uninterrupted run"
ls -a | grep -q '^\..*\.\(writing\|replaced\|purged\)$' && fail "leftover hidden folders"
repairs=$(cat log.* | grep -c "Repaired interrupted write")
[ "$midWrite" -ge 1 ] || fail "no kill landed inside a write"
pass "$kills kills ($midWrite inside a write, $repairs repairs), every time folder complete after each, final state bit-identical"
