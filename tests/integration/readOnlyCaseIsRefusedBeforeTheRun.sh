#!/bin/bash
# A case folder that cannot be written is refused before the run starts, with a message naming
# the folder; not at the first write, after "Starting time loop", as an unexpected error.
. "$SPHCAST_TEST_TOOLS"
makeFreeFallCase "$scratch/case" 0.005 0.1 0.05
cd "$scratch/case"
setCastFields > /dev/null || fail "setCastFields"

# readOnly COMMAND...: runs the command while the case folder is read-only. Root writes through
# permissions, so as root the folder is bind-mounted read-only in a mount namespace of its own.
if [ "$(id -u)" -eq 0 ]; then
    unshare --mount sh -c 'mount --bind "$1" "$1" && mount -o remount,ro,bind "$1"' sh . \
        2> /dev/null || { echo "SKIP: no read-only bind mount possible here"; exit 77; }
    readOnly() {
        unshare --mount sh -c 'mount --bind "$1" "$1" && mount -o remount,ro,bind "$1" &&
                               shift && exec "$@"' sh "$scratch/case" "$@"
    }
else
    readOnly() { chmod a-w "$scratch/case"; "$@"; local status=$?; chmod u+w "$scratch/case"; return $status; }
fi

for tool in sphCastFoam castPostProcess setCastFields; do
    if readOnly "$tool" > out.log 2> err.log; then fail "$tool ran in a read-only case"; fi
    grep -qF "case folder '$scratch/case' is not writable" err.log ||
        fail "$tool: expected the folder named as not writable, got: $(cat err.log)"
    ! grep -q "Starting time loop" out.log || fail "$tool started the time loop"
    ! grep -q "unexpected" err.log || fail "$tool: reported as unexpected"
done
rm -f out.log err.log
[ ! -d 0.05 ] || fail "a time was written"
pass "a read-only case is refused before the run, naming the folder"
