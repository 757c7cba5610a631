#!/bin/bash
# castPostProcess -latestTime or -time replaces the cloudSummary rows of those times only: the
# rows of the whole run, written by castPostProcess without options, stay.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/case" 0.005 0.2 0.05
cd "$scratch/case"
setCastFields > /dev/null || fail "setCastFields"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
castPostProcess > /dev/null 2>&1 || fail "castPostProcess"
csv=postProcessing/cloudSummary/metal.csv
[ "$(wc -l < "$csv")" -eq 6 ] || fail "$csv should have a header and 5 rows"
cp "$csv" whole.csv

castPostProcess -latestTime > /dev/null 2>&1 || fail "castPostProcess -latestTime"
cmp -s "$csv" whole.csv || fail "-latestTime changed the other rows: $(diff whole.csv "$csv")"

# A row of 0.1 spoilt, then -time 0.1 puts it back and leaves the rest alone.
sed -i '4s/^\(0\.1[0-9]*\),1000,/\1,999,/' "$csv"
grep -q '^0\.1[0-9]*,999,' "$csv" || fail "could not spoil the row of 0.1: $(cat "$csv")"
castPostProcess -time 0.1 > /dev/null 2>&1 || fail "castPostProcess -time 0.1"
cmp -s "$csv" whole.csv || fail "-time 0.1 did not restore just its row: $(diff whole.csv "$csv")"

# A later time folder (a continued run) is added in time order.
cp -r 0.2 0.25
castPostProcess -latestTime > /dev/null 2>&1 || fail "castPostProcess -latestTime (0.25)"
[ "$(wc -l < "$csv")" -eq 7 ] && [ "$(tail -n 1 "$csv" | cut -d, -f1)" = 0.25 ] ||
    fail "0.25 not appended: $(cat "$csv")"
head -n 6 "$csv" | cmp -s - whole.csv || fail "appending 0.25 changed the earlier rows"
# -help names every analysis type doc/castPostProcess.md describes (a bold **type** there).
help=$(castPostProcess -help 2>&1) || fail "castPostProcess -help"
for type in $(grep -oE '^\*\*[a-zA-Z]+\*\*' "$(dirname "$SPHCAST_TEST_TOOLS")/../../doc/castPostProcess.md" | tr -d '*'); do
    grep -q "\b$type\b" <<< "$help" || fail "castPostProcess -help does not list $type: $help"
done
pass "-latestTime and -time update their rows of the cloud summary and keep the others; -help lists every analysis"
