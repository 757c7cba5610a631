#!/bin/bash
# tutorials/validation/Allreport quick --check (the speed-against-error report's quick level):
# 16 points of 10 cases (nine validation tutorials and conicalMold), each run with its own Allrun
# at its resolution by the tools under test; every error must lie in its recorded band
# (tutorials/validation/reportBands), and the report must be written with a figure per case.
. "$SPHCAST_TEST_TOOLS"
validation=$(cd "$(dirname "$0")/../../tutorials/validation" && pwd)
findVtkPython
export PYTHON=$python SPHCAST_RUN_BIN=$SPHCAST_BIN
"$python" "$validation/Allreport" quick --check --runs "$scratch/runs" > "$scratch/log.Allreport" 2>&1 ||
    fail "Allreport quick --check: $(tail -20 "$scratch/log.Allreport")"
cat "$scratch/log.Allreport"
grep -q "every error within its band" "$scratch/log.Allreport" || fail "no band check"
points=$(grep -c " s CPU " "$scratch/log.Allreport")
[ "$points" -eq 16 ] || fail "$points points, not 16"
report=$scratch/runs/speedAccuracy.md
[ -f "$report" ] || fail "no report"
figures=$(grep -c '^!\[.*\](images/speedAccuracy/.*\.png)$' "$report")
[ "$figures" -eq 10 ] || fail "$figures figures in the report, not 10"
for image in $(grep -o 'images/speedAccuracy/[A-Za-z0-9]*\.png' "$report"); do
    [ -s "$scratch/runs/$image" ] || fail "missing $image"
done
# a band that the recorded error lies outside must fail: the check can fail
sed 's/^\(damBreak2D  *default  *20  *\)[0-9.]*  *[0-9.]*/\1 0.1 0.2/' "$validation/reportBands" \
    > "$scratch/reportBands.narrow"
grep -q "^damBreak2D *default *20 *0.1 0.2" "$scratch/reportBands.narrow" || fail "narrowing the band"
if "$python" "$validation/Allreport" quick --check --cases damBreak2D --runs "$scratch/narrow" \
        --bands "$scratch/reportBands.narrow" > "$scratch/log.narrow" 2>&1; then
    fail "a band the error lies outside passed: $(cat "$scratch/log.narrow")"
fi
grep -q "damBreak2D default 20: error 0.[56][0-9]* % outside its band \[0.1, 0.2\] %" "$scratch/log.narrow" ||
    fail "the narrowed band's failure: $(tail -3 "$scratch/log.narrow")"
pass "Allreport quick: 16 points within their bands, 10 figures; a band the error leaves fails"
