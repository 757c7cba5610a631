#!/bin/bash
# controlDict functions on the coarse water tank: probes (p, U), surfaceHeights and front write
# postProcessing/<name>/<startTime>/<field>. A run that went to 0.15 s and is restarted from its
# 0.1 s folder writes a new folder 0.1 (the old one is kept, as OpenFOAM does); joining the two
# (each folder's rows before the next folder's `# startTime`) gives the uninterrupted run's rows,
# byte for byte, with no time twice. Bad function entries stop sphCastFoam before it writes.
. "$SPHCAST_TEST_TOOLS"
coarseWaterTank "$scratch/whole"  # dx = 10 mm (500 water particles), to 0.2 s
cat >> system/controlDict <<'DICT'
functions
{
    P   { type probes; cloud water; fields (p U);
          probeLocations ((0.05 0.05 0.01) (0.05 0.05 0.3)); }
    H   { type surfaceHeights; cloud water; locations ((0.05 0.05 0)); writeInterval 3; }
    F   { type front; cloud water; direction (1 0 0); writeControl writeTime; }
}
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -5 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -5 log.setCastFields)"
cp -r "$scratch/whole" "$scratch/restarted"
cp -r "$scratch/whole" "$scratch/bad"

sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -5 log.sphCastFoam)"
for f in P/0/p P/0/U H/0/height F/0/front; do
    [ -f "postProcessing/$f" ] || fail "no postProcessing/$f"
done
sed -n 2p postProcessing/P/0/p | grep -q '^# Probe 0 (0.05 0.05 0.01)$' || fail "probe header"
# The probe above the water has no fluid within h: nan. At the end, the one 1 cm above the
# floor reads about rho g (H - z) = 1000 * 9.81 * 0.04 = 392 Pa.
awk '!/^#/ && $3 != "nan" { bad = 1 } END { if ($2 < 300 || $2 > 480) bad = 1; exit bad }' \
    postProcessing/P/0/p || fail "probe values: $(tail -2 postProcessing/P/0/p)"
steps=$(awk '/^index/ { print $2 + 0 }' 0.2/uniform/time)
rows=$(grep -vc '^#' postProcessing/P/0/p)
[ "$rows" -eq $((steps + 1)) ] || fail "$rows probe rows for $steps steps and the start"
[ "$(grep -vc '^#' postProcessing/F/0/front)" -eq 5 ] || fail "front: not the start and 4 writes"

# joined DIR NAME FIELD: the rows of every start folder, each before the next folder's startTime.
joined() {
    local dir=$1 name=$2 field=$3 starts k cut
    starts=($(ls "$dir/postProcessing/$name" | sort -g))
    for ((k = 0; k < ${#starts[@]}; ++k)); do
        cut=inf
        if ((k + 1 < ${#starts[@]})); then
            cut=$(awk '/^# startTime / { print $3; exit }' "$dir/postProcessing/$name/${starts[k + 1]}/$field")
        fi
        grep -v '^#' "$dir/postProcessing/$name/${starts[k]}/$field" |
            awk -v cut="$cut" 'cut == "inf" || $1 + 0 < cut - 1e-10 * (cut < 0 ? -cut : cut)'
    done
}

cd "$scratch/restarted"
setEntry system/controlDict endTime 0.15
sphCastFoam > log.1 2>&1 || fail "first part: $(tail -5 log.1)"
setEntry system/controlDict endTime 0.2
setEntry system/controlDict startFrom startTime
echo "startTime 0.1;" >> system/controlDict
sphCastFoam > log.2 2>&1 || fail "restart: $(tail -5 log.2)"
[ -d postProcessing/P/0.1 ] || fail "the restart did not write postProcessing/P/0.1"
grep -v '^#' postProcessing/P/0.1/p | head -1 | grep -q '^0\.1 ' || fail "folder 0.1 starts elsewhere"
head -1 postProcessing/H/0.1/height | grep -q '^# startTime 0.1' || fail "no startTime in the header"
for object in P/p P/U H/height F/front; do
    name=${object%/*} field=${object#*/}
    joined "$scratch/whole" "$name" "$field" > whole.rows
    joined . "$name" "$field" > restarted.rows
    cmp -s whole.rows restarted.rows || fail "$object: the joined restart differs: $(diff whole.rows restarted.rows | head -5)"
    [ -z "$(awk '{print $1}' restarted.rows | sort | uniq -d)" ] || fail "$object: a time twice"
done

cd "$scratch/bad"
sed -i 's/type front;/type frnt;/' system/controlDict
sphCastFoam > log.bad 2>&1 && fail "an unknown function type was accepted"
grep -q "controlDict:[0-9]*:[0-9]*: unknown type 'frnt'" log.bad || fail "error: $(tail -3 log.bad)"
[ ! -d postProcessing ] || fail "a failed start wrote postProcessing"
pass "function objects: OpenFOAM-style files; a restart from 0.1 joins to the uninterrupted rows"
