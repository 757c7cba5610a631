#!/bin/bash
# Metal that leaves the domain is spilled, not fatal (solver/MetalSpill.h): the heated sloshing
# sphere (AC4CH at 900 K thrown sideways at 0.6 m/s in an iron mold) with the case's domain cut
# at z = 15 mm, a rim 15 mm above the melt's surface at rest, so the metal that climbs the far
# wall spills over it.
# - The run goes on to its end; the log names the spill; the books close in the written state:
#   particles held + spilled = the start's count, mass held + spilled = the start's mass (to
#   1e-12), and the energyBalance's relative imbalance below 1e-12 with lost_spilled the heat
#   the spilled metal carried (> 0); castPostProcess reports the spill.
# - The domain is kept at a restart: continued from 0.04 s with healthChecks' domain removed
#   from controlDict (the run's own, written with the metal, takes its place), the run ends
#   with the same bits as the uninterrupted one.
# - A pour over a tank's rim (a shell, open at the top) spills over it and runs on, held +
#   spilled = the start's + the poured mass.
# - On 2 ranks (-parallel, where built with MPI) the spill is booked alike: particles held +
#   spilled = the start's count, the books closed to 1e-10 (the decomposed run's own round-off,
#   1.3e-11 here with or without a spill).
# - A spill above healthChecks maxSpilledFraction stops the run with the fraction in the
#   message, exits non-zero and leaves the last good state, itself within the limit.
. "$SPHCAST_TEST_TOOLS"
findVtkPython || exit 77
case=$scratch/spill
makeHeatedSloshingSphere "$case" auto
cd "$case" || fail "no case"
domain='domain { lower (-1 -1 -1); upper (1 1 0.015); }'
echo "healthChecks { maxSpilledFraction 0.5; $domain }" >> system/controlDict
cp -r "$case" "$scratch/restarted"
cp -r "$case" "$scratch/limited"
cp -r "$case" "$scratch/np2"
sphCastFoam > log.sphCastFoam 2>&1 || fail "the run with a spill stopped: $(tail -5 log.sphCastFoam)"
grep -q "particle(s) of cloud .metal. left the domain and were spilled" log.sphCastFoam ||
    fail "no spill in the log (the rim too high?)"
"$python" - <<'PY' || fail "the books"
from cloudFields import cloud_totals
n0, m0, _ = cloud_totals("0/metal.vtp")
n, m, a = cloud_totals("0.1/metal.vtp")
spilled, spilledMass = a.get("spilledParticles", 0), a.get("spilledMass", 0)
print(f"start {n0} particles {m0:.9g} kg; at 0.1 s {n} held + {spilled:.0f} spilled, "
      f"{m:.9g} + {spilledMass:.9g} kg ({100 * spilledMass / m0:.2f} %), heat {a.get('heatLost.spilled', 0):.6g} J")
assert spilled > 0 and n + spilled == n0, "particles held + spilled != the start's"
assert abs(m + spilledMass - m0) < 1e-12 * m0, "mass held + spilled != the start's"
rows = [l.split() for l in open("postProcessing/balance/0/energyBalance") if not l.startswith("#")]
worst = max(abs(float(r[-1])) for r in rows)
lostSpilled = float(rows[-1][-3])
print(f"worst relative imbalance {worst:.2e}, lost_spilled {lostSpilled:.6g} J")
assert worst < 1e-12, "the books do not close with the spill"
assert abs(lostSpilled - a["heatLost.spilled"]) <= 1e-9 * lostSpilled, "lost_spilled is not the spill's heat"
PY
cat > system/castPostProcessDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object castPostProcessDict; }
history { type timeSeries; }
DICT
castPostProcess -latestTime > log.castPostProcess 2>&1 || fail "castPostProcess: $(tail -3 log.castPostProcess)"
grep -q '\*\*Metal spilled\*\*' postProcessing/castReport.md || fail "the report has no spill"
pass "the spilled metal is removed and booked, the books closed, the run goes on to its end"

cd "$scratch/restarted" || fail "no copy"
setEntry system/controlDict endTime 0.04
sphCastFoam > log.first 2>&1 || fail "the first part: $(tail -5 log.first)"
sed -i "s/healthChecks .*/healthChecks { maxSpilledFraction 0.5; }/" system/controlDict
setEntry system/controlDict endTime 0.1
sphCastFoam > log.second 2>&1 || fail "the restart: $(tail -5 log.second)"
grep -q "domain (-1 -1 -1) (1 1 0.015)" log.second || fail "the restart's domain: $(grep 'domain (' log.second)"
sameTimeFolder "$case/0.1" 0.1 || fail "the restarted run differs from the uninterrupted one"
pass "a restart keeps the run's domain and spills the same, bit for bit"

cd "$scratch/limited" || fail "no copy"
sed -i "s/maxSpilledFraction 0.5/maxSpilledFraction 0.002/" system/controlDict
if sphCastFoam > log.sphCastFoam 2> err.log; then fail "a spill above the limit ran on"; fi
grep -q "above healthChecks maxSpilledFraction 0.2 %: the mold leaks" err.log ||
    fail "the message: $(cat err.log)"
last=$(sed -n 's/.*The last good state, time \([^,]*\), is written.*/\1/p' err.log)
[ -n "$last" ] && [ -f "$last/metal.vtp" ] || fail "no last good state: $(cat err.log)"
pass "a spill above maxSpilledFraction stops the run: $(grep -o 'at time [0-9.e-]* (step [0-9]*)' err.log | head -1)"

# A pour over a rim: the coarse hydrostatic tank (dx 10 mm, open at the top, walls one shell)
# filled to 90 mm and poured into from 140 mm for 0.3 s, overflowing its 100 mm rim; the
# water runs over the rim and out of the domain, which the case ends at the shell's outside. Measured before the open-rim
# rule (particles/WallSurfaceDistance.h): 44 particles spilled, then at 0.467 s a particle
# 0.23 dx above the rim was read 0.93 dx behind the side and stopped the run.
coarseWaterTank "$scratch/overflow"
sed -i 's/max (0.1 0.1 0.05)/max (0.1 0.1 0.09)/' system/setCastFieldsDict
setEntry system/controlDict endTime 0.6
setEntry system/controlDict writeInterval 0.3
# the domain ends at the shell's outside (three layers of 10 mm): a shell has no outer surface,
# and water run down its outside was measured pressed to 20.2 % above rho_s at 0.588 s
echo "healthChecks { maxSpilledFraction 0.6; domain { lower (-0.03 -0.03 -1); upper (0.13 0.13 1); } }" \
    >> system/controlDict
cat > constant/inlets <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object inlets; }
tap { centre (0.05 0.05 0.14); direction (0 0 -1); radius 0.04; speed 0.5; endTime 0.3; }
DICT
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold: $(tail -3 log.particleizeMold)"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields: $(tail -3 log.setCastFields)"
sphCastFoam > log.sphCastFoam 2>&1 || fail "the overflowing tank stopped: $(tail -5 log.sphCastFoam)"
"$python" - <<'PY' || fail "the overflow's books"
import re
from cloudFields import cloud_totals
n0, m0, _ = cloud_totals("0/water.vtp")
n, m, a = cloud_totals("0.6/water.vtp")
log = open("log.sphCastFoam").read()
perLayer = int(re.search(r"^Inlet tap: ([0-9]+) particles a layer", log, re.M).group(1))
layers = int(re.findall(r"^Inlet tap: poured [0-9.e+-]+ kg in ([0-9]+) layers", log, re.M)[-1])
pouredMass = float(re.findall(r"^Inlet tap: poured ([0-9.e+-]+) kg", log, re.M)[-1])  # 6 digits
spilled, count = a.get("spilledMass", 0), a.get("spilledParticles", 0)
print(f"start {n0} particles {m0:.6g} kg, poured {layers} x {perLayer}; at 0.6 s {n} held, "
      f"{count:.0f} spilled ({spilled:.6g} kg, {100 * spilled / (m + spilled):.1f} %)")
assert count > 100, "the tank did not overflow"
assert n + count == n0 + layers * perLayer, "held + spilled != the start's + the poured particles"
assert abs(m + spilled - m0 - pouredMass) < 1e-6 * (m0 + pouredMass), "held + spilled != start + poured mass"
PY
pass "a pour over a shell's rim spills, books it and runs on"

sphCastFoam -help 2>&1 | grep -q -- "-parallel" || exit 0
cd "$scratch/np2" || fail "no copy"
cat > system/decomposeParDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method recursiveBisection;
DICT
OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 SPHCAST_CHECK_COLLECTIVES=1 \
    timeout 300 mpirun --oversubscribe -np 2 sphCastFoam -parallel > log.sphCastFoam 2>&1 ||
    fail "2 ranks: $(tail -5 log.sphCastFoam)"
"$python" - <<'PY' || fail "the books on 2 ranks"
import os
from cloudFields import cloud_totals
n, _, a = cloud_totals("0.1/metal.pvtp")
n0, _, _ = cloud_totals("0/metal.pvtp" if os.path.exists("0/metal.pvtp") else "0/metal.vtp")
spilled = a["spilledParticles"]
rows = [l.split() for l in open("postProcessing/balance/0/energyBalance") if not l.startswith("#")]
worst = max(abs(float(r[-1])) for r in rows)
print(f"2 ranks: {n} held + {spilled:.0f} spilled of {n0}; worst relative imbalance {worst:.2e}")
assert spilled > 0 and n + spilled == n0, "particles held + spilled != the start's"
assert worst < 1e-10, "the books do not close on 2 ranks"
PY
pass "on 2 ranks the spill is booked and the books close"
