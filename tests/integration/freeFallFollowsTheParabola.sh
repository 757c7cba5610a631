#!/bin/bash
# Ballistic motion: the centroid of a block thrown with U = (1 0 2) m/s from z0 = 0.225 m follows
# x = x0 + t, z = z0 + 2 t - 9.81 t^2 / 2 to rounding (1e-12 m), at every written time.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/freeFall" 0.005 0.4 0.05
cd "$scratch/freeFall"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
castPostProcess > log.castPostProcess 2>&1 || fail "castPostProcess: $(tail -5 log.castPostProcess)"

grep -q '^End' log.sphCastFoam || fail "no End in the log"
grep -q '^ExecutionTime = .* s  ClockTime = .* s' log.sphCastFoam || fail "no ExecutionTime line"
grep -q '^Progress .*% of endTime .* steps/s  ETA' log.sphCastFoam || fail "no progress line"
times=$(ls -d [0-9]* | sort -g | tr '\n' ' ')
[ "$times" = "0 0.05 0.1 0.15 0.2 0.25 0.3 0.35 0.4 " ] || fail "time folders: $times"
grep -c '<DataSet' freeFall.pvd | grep -qx 9 || fail "freeFall.pvd does not list 9 datasets"

csv=postProcessing/cloudSummary/metal.csv
[ "$(wc -l < "$csv")" -eq 10 ] || fail "$csv should have a header and 9 rows"
awk -F, 'NR > 1 && $2 != 1000 { print "particle count " $2; bad = 1 } END { exit bad }' "$csv" ||
    fail "particles lost"
onTheParabola "$csv" || fail "centroid off the parabola"
pass "centroid on the parabola at 9 written times"
