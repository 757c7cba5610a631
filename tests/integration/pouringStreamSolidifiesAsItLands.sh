#!/bin/bash
# A pouring stream that solidifies as it lands (the hard case of the solidification issue): a
# column of AC4CH at 970 K, 10 mm across (5 particles) and 70 mm long, falling at 1 m/s onto the
# floor of a cup of radius 20 mm held at 300 K (dx = 2 mm, h = 5 mm, c = 20 m/s, the cavitation
# floor at -5 kPa). It lands over about 50 ms at 1.2 to 1.65 m/s, the first melt freezes on the
# floor at once (a thermal shock of 670 K) and the rest of the stream lands on that frozen splat.
# The run must not explode: T within [300, 970] K, every log line's max|U| below twice the
# fastest landing speed, compression below 5 % at every write (the health check warns above 3
# %: the landing on frozen metal, a wall whose density follows the continuity equation, gives
# short peaks; splashes expand freely under the floor), nothing through the mold, frozen
# particles where they froze, solid at the end.
. "$SPHCAST_TEST_TOOLS"
findVtkPython

makeChillMold "$scratch/stream" 0.1 \
    'stream { type cylinder; point1 (0 0 0.02); point2 (0 0 0.09); radius 0.005; }' '(0 0 -1)' 3 \
    'model frozenSolid; frozenSolidFraction 0.5; cavitationPressure -5000; endWhenSolid yes;
     cooling { flowStepsPerHeatStep 10; stillSpeed 0.02; }'
cd "$scratch/stream" || exit 1
sed -i 's/0\.004;/0.002;/' system/particleizeMoldDict system/setCastFieldsDict
sed -i 's/0\.01;/0.005;/' system/particleizeMoldDict system/sphSchemes
setEntry system/controlDict logInterval 50
setEntry system/controlDict writeInterval 0.025
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the stream's run failed"; }
grep -q "^Stopping: the casting is solid (endWhenSolid)" log || fail "the stream did not end solid"
# every log line: T within [300, 970] K and max|U| below twice the fastest landing speed
awk '/^T metal/ { if ($3 < 300 - 1e-9 || $5 > 970 + 1e-9) badT = 1; n++ }
     /max\|U\|/ { for (i = 1; i < NF; i++)
                     if ($i == "max|U|" && $(i + 1) > fastest) fastest = $(i + 1) }
     END { printf "fastest log line: max|U| %.3f m/s\n", fastest
           exit (badT || n < 5 || fastest > 3.3) }' log ||
    fail "T left [300, 970] K or the melt moved faster than 3.3 m/s (or too few log lines)"
last=$(ls -d [0-9]* | sort -g | tail -1)
"$python" - "$last" <<'PY' || fail "the stream"
import sys, glob, math
from cloudFields import read_cloud
def read(time):
    return read_cloud(f"{time}/metal.vtp", ("T", "solidFraction", "frozen", "rho", "restDensity"))
times = sorted((t for t in glob.glob("[0-9]*") if t != "0"), key=float)
end = read(sys.argv[1])
low = high = 0.0
for t in times:
    cloud = read(t)
    for p in cloud.values():
        assert all(math.isfinite(v) for v in (*p["x"], p["T"], p["rho"])), f"not finite at {t}"
        assert 300 - 1e-9 <= p["T"] <= 970 + 1e-9, f"T {p['T']} K at {t}"
        assert math.hypot(p["x"][0], p["x"][1]) < 0.02 and p["x"][2] > 0, \
            f"a particle passed the mold at {t}: {p['x']}"
        deviation = p["rho"] / p["restDensity"] - 1
        low, high = min(low, deviation), max(high, deviation)
    moved = [k for k, p in cloud.items() if p["frozen"] == 1 and end[k]["x"] != p["x"]]
    assert not moved, f"{len(moved)} particles frozen at {t} s moved later"
assert all(p["solidFraction"] == 1 for p in end.values()), "not all solid at the end"
print(f"{len(end)} particles, solid at t = {sys.argv[1]} s, {len(times)} writes; density "
      f"{100 * low:+.2f} .. {100 * high:+.2f} % of rho_s; highest z at the end "
      f"{1e3 * max(p['x'][2] for p in end.values()):.1f} mm, widest r "
      f"{1e3 * max(math.hypot(p['x'][0], p['x'][1]) for p in end.values()):.1f} mm")
assert high <= 0.05, "compressed more than 5 %"
PY
pass "a stream landing on a 300 K floor solidifies as it lands without exploding"
