#!/bin/bash
# Solidification to the end on a small cup: AC4CH at 970 K dropped at 0.5 m/s onto the floor of
# a mold held at 300 K (a thermal shock at first contact, and an impact), frozen as it solidifies,
# cooled to the end in the cooling mode (heat steps with ten flow steps each) and stopped by
# endWhenSolid (the log's ETA following the solid fraction). T stays within [300, 970] K, nothing passes the mold, frozen particles do not
# move, a restart in the cooling mode reproduces the uninterrupted run bit for bit, the mode
# starts earlier with a stillFraction, and bad solidification input (a frozen fraction, the
# cooling mode's maxCo and stillFraction, a material without a freezing range) stops with file,
# line and key.
. "$SPHCAST_TEST_TOOLS"

makeCup() {  # DIR
    makeChillCup "$1" 100 "model frozenSolid; frozenSolidFraction 0.5; endWhenSolid yes;
        cooling { flowStepsPerHeatStep 10; stillSpeed 0.02; }"
    cd "$1" || fail "cannot enter $1"
    setEntry system/controlDict writeInterval 0.5
    setEntry system/controlDict logInterval 20
    particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
    setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
    cd - > /dev/null || exit 1
}

makeCup "$scratch/cup"
cp -r "$scratch/cup" "$scratch/stopped"
cp -r "$scratch/cup" "$scratch/bad"
cp -r "$scratch/cup" "$scratch/fraction"
cd "$scratch/cup" || exit 1
sphCastFoam > log 2>&1 || { tail -20 log >&2; fail "the solidifying cup did not run"; }
grep -q "^Cooling from time" log || fail "the cooling mode never started"
# stillFraction 0.3: the mode starts once all but 30 % of the melt is below stillSpeed, earlier
# than once every particle is (the default, 0)
cd "$scratch/fraction" || exit 1
sed -i 's/stillSpeed 0.02;/stillSpeed 0.02; stillFraction 0.3;/' constant/physicsModels
setEntry system/controlDict endTime 1
sphCastFoam > log 2>&1 || fail "stillFraction 0.3: $(tail -5 log)"
every=$(sed -n 's/^Cooling from time \([0-9.e+-]*\):.*/\1/p' ../cup/log | head -1)
most=$(sed -n 's/^Cooling from time \([0-9.e+-]*\):.*/\1/p' log | head -1)
awk -v every="$every" -v most="$most" 'BEGIN { printf "the cooling mode from %s s (every particle still), %s s (70 %%)\n", every, most
    exit !(most != "" && most + 0 < every + 0) }' || fail "stillFraction 0.3 did not start the cooling mode earlier"
grep -q "^Cooling from time .*: the melt is still (max|U| .* m/s, [1-9][0-9]* of [0-9]* particles at 0.02 m/s or faster)" log ||
    fail "the log does not count the particles still moving: $(grep -m1 '^Cooling from' log)"
cd "$scratch/cup" || exit 1
grep -q "cooling: heat steps of" log || fail "the log does not say how the cooling steps"
grep -q "^Stopping: the casting is solid (endWhenSolid)" log || fail "the run did not end solid"
# The ETA follows the solid fraction, not endTime (100 s, which gave an hour for a 30 s run):
# once a tenth is solid, every ETA names that end and stays below four times the whole run's
# wall time (+ 10 s for ClockTime's whole seconds). It cannot foresee the cooling mode, which
# runs the second half several times faster per solid fraction: measured on an idle machine
# 37 s at 10 s of a 29 s run, 31 s at 24 s, then 4 s once the cooling mode ran; on a loaded
# one 242 s at 28 s of an 89 s run.
awk '/^Solidification: solid fraction/ { solid = $4 }
     /ClockTime = / { clock = $(NF - 1) }
     /ETA [0-9]+:/ && solid >= 0.1 { split($0, a, "ETA "); split(a[2], hms, /[: ]/);
         eta[n] = hms[1] * 3600 + hms[2] * 60 + hms[3]; at[n] = clock; named[n++] = /all solid/ }
     END { if (n == 0) exit 1
           for (i = 0; i < n; i++) {
               if (!named[i] || eta[i] > 4 * clock + 10) {
                   printf "ETA %d s at %d s, the run ended at %d s\n", eta[i], at[i], clock; exit 1 } } }' \
    log || fail "the ETA does not follow the solid fraction (endWhenSolid)"
last=$(ls -d [0-9]* | sort -g | tail -1)
# T of every log line within [300, 970] K
awk '/^T metal/ { if ($3 < 300 - 1e-9 || $5 > 970 + 1e-9) bad = 1; n++ }
     END { exit (bad || n < 5) }' log || fail "T left [300, 970] K (or too few log lines)"
/usr/bin/python3 - "$last" <<'PY' || fail "the solid cup"
import sys, glob, math
from cloudFields import read_cloud
def read(time):
    return read_cloud(f"{time}/metal.vtp", ("T", "solidFraction", "frozen", "rho", "restDensity"))
times = sorted((t for t in glob.glob("[0-9]*") if t != "0"), key=float)
end = read(sys.argv[1])
assert all(p["solidFraction"] == 1 for p in end.values()), "not all solid at the end"
worst = max(math.hypot(p["x"][0], p["x"][1]) for p in end.values())
lowest = min(p["x"][2] for p in end.values())
print(f"{len(end)} particles, solid at t = {sys.argv[1]} s; outermost r {1e3 * worst:.2f} mm, "
      f"lowest z {1e3 * lowest:.2f} mm")
assert worst < 0.02 and lowest > 0, "a particle passed the mold"
compression = max(p["rho"] / p["restDensity"] - 1 for p in end.values())
print(f"largest compression {100 * compression:.3f} %")
assert compression < 0.03
for t in times:
    cloud = read(t)
    assert all(300 - 1e-9 <= p["T"] <= 970 + 1e-9 for p in cloud.values()), f"T out at {t}"
# particles frozen at a write keep their place to the end (bit for bit)
for t in times[:-1]:
    cloud = read(t)
    moved = [k for k, p in cloud.items() if p["frozen"] == 1 and end[k]["x"] != p["x"]]
    assert not moved, f"{len(moved)} particles frozen at {t} s moved later"
print(f"frozen particles of {len(times) - 1} writes stayed put")
PY
# A restart in the cooling mode goes on bit for bit.
cd "$scratch/stopped" || exit 1
setEntry system/controlDict endTime 1
sphCastFoam > log.1 2>&1 || fail "first part"
grep -q "^Cooling from time" log.1 || fail "the first part never reached the cooling mode"
setEntry system/controlDict endTime 1.5
sphCastFoam > log.2 2>&1 || fail "restart"
sameTimeFolder "$scratch/cup/1.5" 1.5 || fail "the restarted run differs at 1.5 s"
# Bad input names file, line and key.
cd "$scratch/bad" || exit 1
sed -i 's/frozenSolidFraction 0.5;/frozenSolidFraction 1.5;/' constant/physicsModels
if sphCastFoam > log.bad 2>&1; then fail "frozenSolidFraction 1.5 ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: 'frozenSolidFraction' must lie in (0, 1]" log.bad ||
    { cat log.bad >&2; fail "no clear error for frozenSolidFraction 1.5"; }
sed -i 's/frozenSolidFraction 1.5;/frozenSolidFraction 0.5;/' constant/physicsModels
sed -i 's/flowStepsPerHeatStep 10;/flowStepsPerHeatStep 10; maxCo 1.5;/' constant/physicsModels
if sphCastFoam > log.bad 2>&1; then fail "the cooling mode's maxCo 1.5 ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: 'maxCo' must be in (0, 1]" log.bad ||
    { cat log.bad >&2; fail "no clear error for the cooling mode's maxCo 1.5"; }
sed -i 's/ maxCo 1.5;//' constant/physicsModels
sed -i 's/stillSpeed 0.02;/stillSpeed 0.02; stillFraction 0.7;/' constant/physicsModels
if sphCastFoam > log.bad 2>&1; then fail "the cooling mode's stillFraction 0.7 ran"; fi
grep -q "physicsModels:[0-9]*:[0-9]*: 'stillFraction' must be in \[0, 0.5)" log.bad ||
    { cat log.bad >&2; fail "no clear error for stillFraction 0.7"; }
sed -i 's/ stillFraction 0.7;//' constant/physicsModels
sed -i 's/^metal .*/metal { density 2400; viscosity 1e-3; conductivity 90; specificHeat 900; }/' \
    constant/physicalProperties
if sphCastFoam > log.bad 2>&1; then fail "a material without a freezing range ran"; fi
grep -q "physicalProperties:[0-9]*:[0-9]*: material 'metal' in .* has no 'liquidus' and 'solidus', which solidification needs" log.bad ||
    { cat log.bad >&2; fail "no clear error for a material without liquidus"; }
pass "melt solidifies in a chill mold: T within [300, 970] K, frozen stay put, restart bit for bit, bad input"
