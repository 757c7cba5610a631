#!/bin/bash
# A run stopped at t1 = 0.1 and restarted from latestTime gives, at t2 = 0.2, files identical
# byte for byte to those of an uninterrupted run.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/whole" 0.005 0.2 0.05
cp -r "$scratch/whole" "$scratch/stopped"
(cd "$scratch/whole" && setCastFields > /dev/null && sphCastFoam > log 2>&1) || fail "whole run"

cd "$scratch/stopped"
setCastFields > /dev/null || fail "setCastFields"
setEntry system/controlDict endTime 0.1
sphCastFoam > log.1 2>&1 || fail "first part"
# As if killed between the two renames that replace a time folder: 0.1 is set aside, its
# replacement unfinished. The restart must put 0.1 back before it looks for latestTime.
mv 0.1 .0.1.replaced && mkdir -p .0.1.writing
setEntry system/controlDict endTime 0.2
sphCastFoam > log.2 2>&1 || fail "restart"
grep -q "Starting from time 0.1 " log.2 || fail "restart did not start from 0.1"
grep -q "Repaired interrupted write: .0.1.replaced" log.2 || fail "no repair reported"
for t in 0.15 0.2; do
    sameTimeFolder "$scratch/whole/$t" "$t" || fail "time $t differs from the uninterrupted run"
done
pass "restart at 0.1 (after a repaired interrupted write) reproduces 0.15 and 0.2 bit for bit"
