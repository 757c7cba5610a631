#!/bin/bash
# tutorials/validation/gradedDie at dx = 3 mm (about 20 s on one thread): a block of AC4CH
# solidifying in the pocket of an iron die that loses heat to the air, conduction only, the die
# particleized at 3 mm and graded (3 mm within 3 layers of the pocket, up to 12 mm).
# compareGraded --check: the graded die at least 3 times fewer particles (measured 3.07), the
# casting solid within 1 % of the uniform die's time (measured -0.67 %), the heat books of both
# closed within 1e-10 (measured 2.6e-13 and 1.1e-13). Without the first-moment correction of the
# graded conduction, or with the coarser particles' exposed area summed at h, the casting is solid
# 1.7 to 1.9 % early at 2 mm (doc/validation.md §3.1). The graded run restarted from 10 s ends
# in the same bytes as the run that went on (the graded pairs and their correction are made
# again from the same places). Decomposed on 2 ranks (-parallel, in a build with MPI), the
# graded die is the serial run within round-off: solid at the same time, every T within 1e-6 K,
# the books closed; restarted decomposed from 10 s, the same halo and the same temperatures.
. "$SPHCAST_TEST_TOOLS"
findVtkPython
runValidationTutorial gradedDie 3
cat log.compareGraded
"$python" compareGraded --check > /dev/null || fail "the graded die against the uniform one"
final=$(ls -d graded/[0-9]* | sort -g | tail -1)
cp -r graded restarted
rm -rf restarted/20 "restarted/${final#graded/}"
(cd restarted && sphCastFoam > log.restart 2>&1) || fail "the graded run restarted from 10 s"
for cloud in die metal; do
    cmp -s "$final/$cloud.vtp" "restarted/${final#graded/}/$cloud.vtp" ||
        fail "the restarted graded run's $cloud at ${final#graded/} s differs from the continued run's"
done
# runDecomposed CASE LOG: sphCastFoam in CASE on 2 ranks of one thread.
runDecomposed() {
    (cd "$1" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
        timeout 300 mpirun --oversubscribe -np 2 sphCastFoam -parallel > "$2" 2>&1)
}
# temperaturesWithin A B TOLERANCE: every particle of the die and the metal in time folder A
# and in B (a serial .vtp or a decomposed .pvtp) with its T within TOLERANCE K (0: the bits).
temperaturesWithin() {
    "$python" - "$@" <<'PY'
import os
import sys
from cloudFields import read_cloud
def path(folder, cloud):
    pieces = os.path.join(folder, cloud + ".pvtp")
    return pieces if os.path.exists(pieces) else os.path.join(folder, cloud + ".vtp")
first, second, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
for cloud in ("die", "metal"):
    a = read_cloud(path(first, cloud), ("T",))
    b = read_cloud(path(second, cloud), ("T",))
    assert a.keys() == b.keys(), cloud + ": not the same particles"
    worst = max(abs(a[k]["T"] - b[k]["T"]) for k in a)
    print("%s against %s: %s T within %.3g K" % (second, first, cloud, worst))
    assert worst <= tolerance, cloud
PY
}
if command -v mpirun > /dev/null && [ -f graded/0/die.vtp ]; then
    cp -r graded decomposed
    rm -rf decomposed/[1-9]* decomposed/0.* decomposed/postProcessing decomposed/log.*
    cat > decomposed/system/decomposeParDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method recursiveBisection;
DICT
    runDecomposed decomposed log.sphCastFoam ||
        fail "the graded die decomposed on 2 ranks: $(tail -5 decomposed/log.sphCastFoam)"
    # the same casting as the serial graded run's: solid at the same time, every particle's T
    # within round-off (measured: the same step, 3.4e-13 K), the books closed
    solid() { sed -n 's/.*the casting is solid (endWhenSolid) at time \([0-9.e+-]*\).*/\1/p' "$1"; }
    [ -n "$(solid graded/log.sphCastFoam)" ] &&
        [ "$(solid graded/log.sphCastFoam)" = "$(solid decomposed/log.sphCastFoam)" ] ||
        fail "the decomposed graded die solid at $(solid decomposed/log.sphCastFoam) s, the serial at $(solid graded/log.sphCastFoam) s"
    temperaturesWithin "$final" "decomposed/${final#graded/}" 1e-6 ||
        fail "the decomposed graded die's temperatures"
    # restarted decomposed from 10 s: the particles' reaches (supportReach) read back with the
    # pieces, the same halo, the same temperatures to the bit
    cp -r decomposed restartedDecomposed
    rm -rf restartedDecomposed/20 "restartedDecomposed/${final#graded/}"
    runDecomposed restartedDecomposed log.restart ||
        fail "the decomposed graded die restarted from 10 s: $(tail -5 restartedDecomposed/log.restart)"
    halo() { sed -n 's/^Decomposition: .*halos \([0-9]*\) particles.*/\1/p' "$1"; }
    [ "$(halo decomposed/log.sphCastFoam)" = "$(halo restartedDecomposed/log.restart)" ] ||
        fail "the restarted decomposed run's halo $(halo restartedDecomposed/log.restart), the first's $(halo decomposed/log.sphCastFoam)"
    temperaturesWithin "decomposed/${final#graded/}" "restartedDecomposed/${final#graded/}" 0 ||
        fail "the restarted decomposed graded die's temperatures"
    "$python" - <<'PY' || fail "the decomposed graded die's books"
import glob
path = glob.glob("decomposed/postProcessing/balance/*/energyBalance")[0]
rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
worst = max(abs(float(r[-1])) for r in rows)
print("decomposed on 2 ranks: the books within %.3g" % worst)
assert worst < 1e-10
PY
fi
pass "a graded die: 3 times fewer particles, the casting solid within 1 % of the uniform die's time, restarts to the same bytes, decomposed on 2 ranks the serial run's, restarted decomposed the same"
