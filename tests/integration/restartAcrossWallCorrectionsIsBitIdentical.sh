#!/bin/bash
# A restart reproduces the uninterrupted run bit for bit where the wall clearance moves
# particles every step (metal sloshing in a sphere): the restarted cloud keeps the order it was
# written in, although a moved particle may have changed cell since the last reorder.
. "$SPHCAST_TEST_TOOLS"
makeSloshingSphereCase "$scratch/a" 0.06
cd "$scratch/a"
particleizeMold > log.particleizeMold 2>&1 || fail "particleizeMold"
setCastFields > log.setCastFields 2>&1 || fail "setCastFields"
sphCastFoam > log.sphCastFoam 2>&1 || fail "sphCastFoam: $(tail -3 log.sphCastFoam)"
moved=$(grep -c "moved back from walls [1-9]" log.sphCastFoam)
[ "$moved" -gt 0 ] || fail "the wall clearance never acted: the test tests nothing"
mkdir ../b && cp -r constant system 0 0.02 ../b/ && cd ../b
sphCastFoam > log.sphCastFoam 2>&1 || fail "restart: $(tail -3 log.sphCastFoam)"
sameTimeFolder ../a/0.04 0.04 && sameTimeFolder ../a/0.06 0.06 ||
    fail "the restart from 0.02 differs from the uninterrupted run"
pass "restart from 0.02 identical at 0.04 and 0.06 with the wall clearance acting"
