#!/bin/bash
# doc/firstCase.md, followed as a new user follows it: every `<!-- file: PATH -->` code block is
# written to PATH at the point of the walkthrough where it stands (in the folder the commands
# have reached), every `<!-- run -->` block is run, in order, in one bash (set -e -o pipefail),
# with HOME a scratch folder that holds sphCast as the walkthrough's ~/sphCast (the repository's
# etc/, the tools under test, $SPHCAST_BIN, as its platforms/bin): so `source ~/sphCast/etc/bashrc`
# and the case in ~/run/myFirstCasting run as written, outside the repository, at the doc's own
# resolution. Then the casting engineer's checks on the result:
# - the run ended because the casting is solid (endWhenSolid), every metal particle at solid
#   fraction 1, and no health warning;
# - no metal lost: the same particles, and their mass, at the end as at time 0;
# - the last metal to freeze lies in the riser: the report's last particle to solidify 10 mm or
#   more above the plate and within the riser's radius (measured 26.5 mm above, 14 mm off the
#   axis), and the latest 2 % of the solidification-time map 8 mm or more above it; the
#   thermocouples reach the solidus at the plate's far end, under the riser and in the riser in
#   that order (13.3, 20.3, 30.9 s);
# - the riser fed the plate: its top sank on the axis by more than 2 mm (5.7 mm), no enclosed
#   cavity, the envelope shrank by 50 to 150 % of what the mass balance of rho_s asks for (7.59
#   of 7.65 cm^3), and no liquid was cut off from the riser at the written times (hotSpots).
# The doc's own resolution (dx = 4 mm, 1,776 metal particles): about 50 s on one thread.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
project=$(cd "$(dirname "$0")/../.." && pwd)
doc=$project/doc/firstCase.md
[ -f "$doc" ] || fail "no $doc"

home=$scratch/home
mkdir -p "$home/sphCast/platforms"
cp -r "$project/etc" "$home/sphCast/"
ln -s "$SPHCAST_BIN" "$home/sphCast/platforms/bin"

# The walkthrough as one script: run blocks as they are, file blocks as here-documents.
"$python" - "$doc" "$scratch/walkthrough.sh" <<'PY' || fail "doc/firstCase.md: its blocks"
import re, sys
lines = open(sys.argv[1]).read().split('\n')
out, marker, files, runs, i = ['set -e -o pipefail'], None, 0, 0, 0
while i < len(lines):
    line = lines[i]
    m = re.fullmatch(r'<!-- (file: (\S+)|run) -->', line.strip())
    if m:
        assert marker is None, f'line {i + 1}: a marker follows the marker of line {marker[2]}'
        marker = (m.group(1), m.group(2), i + 1)
    elif line.startswith('```'):
        fence = re.match(r'`+', line).group(0)
        end = next(j for j in range(i + 1, len(lines)) if lines[j].startswith(fence))
        body = lines[i + 1:end]
        if marker and marker[1]:
            path = marker[1]
            assert 'SPHCAST_DOC_EOF' not in body, path
            out += [f'mkdir -p "$(dirname {path})"', f"cat > {path} <<'SPHCAST_DOC_EOF'"] + body
            out.append('SPHCAST_DOC_EOF')
            files += 1
        elif marker:
            out += body
            runs += 1
        marker, i = None, end
    elif line.strip() and marker:
        raise SystemExit(f'line {marker[2]}: marker not followed by a code block')
    i += 1
assert files >= 9 and runs >= 5, f'{files} files and {runs} run blocks'
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
print(f'doc/firstCase.md: {files} files, {runs} run blocks')
PY
grep -q "source ~/sphCast/etc/bashrc" "$scratch/walkthrough.sh" || fail "the walkthrough sources no etc/bashrc"
start=$(date +%s)
(cd "$home" && env -u SPHCAST_PROJECT -u SPHCAST_TUTORIALS HOME="$home" PATH="/usr/bin:/bin" \
    bash "$scratch/walkthrough.sh" > "$scratch/walkthrough.log" 2>&1) ||
    { tail -40 "$scratch/walkthrough.log" >&2; fail "the walkthrough's commands stopped"; }
echo "the walkthrough ran in $(( $(date +%s) - start )) s"
case=$home/run/myFirstCasting
cd "$case" || fail "no ~/run/myFirstCasting"
for log in particleizeMold setCastFields sphCastFoam castPostProcess; do
    [ -s "log.$log" ] || fail "the walkthrough wrote no log.$log"
done
grep -q "^Run health: no warnings" log.sphCastFoam || fail "health warnings: $(grep -i warn log.sphCastFoam | head -5)"
grep -q "^Stopping: the casting is solid (endWhenSolid)" log.sphCastFoam ||
    fail "the run did not end solid: $(tail -5 log.sphCastFoam)"
report=postProcessing/castReport.md
[ -s "$report" ] || fail "no $report"

"$python" - "$case" <<'PY' || fail "the casting's checks"
import csv, glob, math, os, re, sys
from cloudFields import read_cloud
case = sys.argv[1]
os.chdir(case)
times = sorted((d for d in os.listdir('.') if re.fullmatch(r'[0-9.eE+-]+', d) and os.path.isdir(d)), key=float)
first, last = times[0], times[-1]
start = read_cloud(f'{first}/metal.vtp', ['mass', 'rho'])
end = read_cloud(f'{last}/metal.vtp', ['mass', 'rho', 'solidFraction'])
print(f'{len(start)} metal particles; written times {first} to {last} s')
assert set(start) == set(end), 'metal particles lost or gained'
m0, m1 = sum(p['mass'] for p in start.values()), sum(p['mass'] for p in end.values())
assert abs(m1 - m0) <= 1e-12 * m0, f'mass {m0} kg at the start, {m1} kg at the end'
fs = min(p['solidFraction'] for p in end.values())
assert fs >= 1 - 1e-9, f'not all solid at {last} s: smallest solid fraction {fs}'
v0 = sum(p['mass'] / p['rho'] for p in start.values())
v1 = sum(p['mass'] / p['rho'] for p in end.values())
print(f'mass {m0:.4f} kg kept; all solid at {last} s; the melt\'s volume fell {100 * (1 - v1 / v0):.2f} %')

PLATE_TOP, RISER_R = 0.016, 0.016      # mold.geo: the plate's top, the riser's radius
def in_riser(x, margin):
    return x[2] > PLATE_TOP + margin and math.hypot(x[0], x[1]) < RISER_R
# The report's last particle to solidify, and the latest 2 % of the map.
text = open('postProcessing/castReport.md').read()
m = re.search(r'^- Last to solidify: \(([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\) m', text, re.M)
assert m, 'the report names no last particle to solidify with its position'
lastParticle = tuple(float(v) for v in m.groups())
print(f'report: last particle to solidify at {lastParticle}')
assert in_riser(lastParticle, 0.01), 'the last particle to solidify is not in the riser'
maps = sorted(glob.glob('postProcessing/solidification/*/metal.vtp'), key=lambda p: float(p.split('/')[-2]))
solid = read_cloud(maps[-1], ['solidificationTime'])
order = sorted(solid.values(), key=lambda p: p['solidificationTime'])
latest = order[-max(1, len(order) // 50):]
outside = [p['x'] for p in latest if not in_riser(p['x'], 0.008)]
assert not outside, f'of the latest 2 % to solidify, {len(outside)} lie outside the riser: {outside[:3]}'
print(f'the latest {len(latest)} particles to solidify all lie in the riser, 8 mm or more above the plate')

# The thermocouples: plate end, under the riser, riser centre reach the solidus in that order.
rows = list(csv.DictReader(open('postProcessing/coolingCurves/breaks.csv')))
solidus = [float(r['solidusTime']) for r in rows]
print('thermocouples reach the solidus at ' + ', '.join(f'{t:.2f}' for t in solidus) + ' s')
assert solidus == sorted(solidus) and solidus[0] < solidus[-1], 'not plate end, then under the riser, then the riser'

# Feeding: the riser's top sank, no enclosed cavity, the volume fell as the mass balance asks.
def top_near_axis(cloud):
    return max(p['x'][2] for p in cloud.values() if math.hypot(p['x'][0], p['x'][1]) < 0.006)
sink = top_near_axis(start) - top_near_axis(end)
print(f"the riser's top sank {1e3 * sink:.1f} mm on its axis")
assert sink > 0.002, 'the riser did not feed the plate: its top did not sink'
last = list(csv.DictReader(open('postProcessing/cavities/cavities.csv')))[-1]
asked, envelope = float(last['massBalanceShrinkage']), -float(last['envelopeChange'])
print(f'cavities: {last["cavities"]} enclosed; the mass balance asks for {1e6 * asked:.2f} cm^3, '
      f'the envelope shrank by {1e6 * envelope:.2f} cm^3')
assert int(last['cavities']) == 0, 'an enclosed cavity'
assert 0.5 * asked < envelope < 1.5 * asked, 'the envelope did not shrink as the mass balance asks'
PY
grep -q "^0 isolated liquid regions" "$report" || fail "hot spots: $(grep -A2 "## hotSpots" "$report")"
pass "doc/firstCase.md runs as written; the casting solidifies completely, keeps its mass, freezes last in the riser, which feeds the plate"
