#!/bin/bash
# A tutorial copied out of sphCast runs, as OpenFOAM users run theirs (issue #28):
#     source <sphCast>/etc/bashrc; cp -r $SPHCAST_TUTORIALS/validation/freeFall ~/run/; ~/run/freeFall/Allrun
# The installation is laid out as a user has it (the repository's etc/ and the two tutorials,
# the tools under test, $SPHCAST_BIN, as its platforms/bin) in a scratch folder; the run folder
# lies elsewhere, so no ../../../etc reaches sphCast's.
# - etc/bashrc, sourced through a relative symbolic link from another folder, twice, under
#   `set -eu`: SPHCAST_PROJECT is the installation, SPHCAST_TUTORIALS its tutorials, its
#   platforms/bin once on PATH and first; sourcing another installation's swaps the PATH entry;
#   an installation not yet built warns and leaves the shell running; run instead of sourced it
#   says to source it.
# - Without etc/bashrc the copied Allrun stops at once with "source <sphCast>/etc/bashrc first",
#   not a bash "No such file or directory", and writes nothing; inside the installation a
#   tutorial still runs without it (../../../etc).
# - With it: freeFall's Allrun runs setCastFields, sphCastFoam and castPostProcess in the copy
#   (the centroid on the parabola to 1e-12 m at the 26 written times, freeFall.pvd), and
#   Allclean brings the copy back to what was copied, a dictionary edited after keepOriginal
#   included; poiseuilleFlow, copied under another name,
#   runs at 10 rows with its comparison script importing etc/functionObjectSeries.py through
#   $SPHCAST_PROJECT (PYTHONPATH unset).
# About 4 s on one thread.
. "$SPHCAST_TEST_TOOLS"
project=$(cd "$(dirname "$0")/../.." && pwd)

# makeInstallation DIR BIN: sphCast's etc/ and the two tutorials in DIR, BIN (if any) as its
# platforms/bin.
makeInstallation() {
    mkdir -p "$1/tutorials/validation" "$1/platforms"
    cp -r "$project/etc" "$1/"
    cp -r "$project/tutorials/validation/freeFall" "$project/tutorials/validation/poiseuilleFlow" \
        "$1/tutorials/validation/"
    [ -z "$2" ] || ln -s "$2" "$1/platforms/bin"
    (cd "$1/tutorials/validation/freeFall" && ./Allclean > /dev/null 2>&1)
    (cd "$1/tutorials/validation/poiseuilleFlow" && ./Allclean > /dev/null 2>&1)
}
install=$scratch/opt/sphCast
makeInstallation "$install" "$SPHCAST_BIN"
[ -f "$install/etc/bashrc" ] || fail "sphCast has no etc/bashrc"
home=$scratch/home/user
mkdir -p "$home/run" "$home/elsewhere"
ln -s ../../opt/sphCast/etc/bashrc "$home/sphCastrc"     # a relative link to it

# --- etc/bashrc in a clean bash --------------------------------------------------------------
cleanBash() {  # COMMANDS: run in a bash without the user's rc files, SPHCAST_* unset
    env -u SPHCAST_PROJECT -u SPHCAST_TUTORIALS HOME="$home" PATH="/usr/bin:/bin" \
        bash --norc --noprofile -c "$1"
}
out=$(cleanBash "set -eu; cd '$home/elsewhere'; source ../sphCastrc; source ../sphCastrc
echo \"project=\$SPHCAST_PROJECT\"; echo \"tutorials=\$SPHCAST_TUTORIALS\"; echo \"path=\$PATH\"
echo \"foam=\$(command -v sphCastFoam)\"; echo alive" 2>&1) || fail "sourcing etc/bashrc: $out"
echo "$out" | grep -qx "project=$install" || fail "SPHCAST_PROJECT is not $install: $out"
echo "$out" | grep -qx "tutorials=$install/tutorials" || fail "SPHCAST_TUTORIALS: $out"
echo "$out" | grep -qx "path=$install/platforms/bin:/usr/bin:/bin" ||
    fail "platforms/bin not once and first on PATH after sourcing twice: $out"
echo "$out" | grep -qx "foam=$install/platforms/bin/sphCastFoam" || fail "sphCastFoam not found: $out"
echo "$out" | grep -q "Warning\|Error" && fail "etc/bashrc of a built sphCast warns: $out"
pass "etc/bashrc through a relative link, from another folder, twice, under set -eu"

other=$scratch/opt/sphCastNotBuilt
makeInstallation "$other" ""
out=$(cleanBash "set -eu; source '$install/etc/bashrc'; source '$other/etc/bashrc'
echo \"project=\$SPHCAST_PROJECT\"; echo \"path=\$PATH\"; echo alive" 2>&1) ||
    fail "etc/bashrc of an installation not built ends the shell: $out"
echo "$out" | grep -qx alive || fail "the shell did not go on after etc/bashrc: $out"
echo "$out" | grep -q "^Warning: sphCast is not built yet: run $other/Allwmake" ||
    fail "no warning that the tools are not built: $out"
echo "$out" | grep -qx "project=$other" || fail "SPHCAST_PROJECT not switched to $other: $out"
echo "$out" | grep -qx "path=$other/platforms/bin:/usr/bin:/bin" ||
    fail "the first installation's platforms/bin not replaced on PATH: $out"
out=$(cleanBash "bash '$install/etc/bashrc'" 2>&1) && fail "running etc/bashrc (not sourcing it) succeeded"
echo "$out" | grep -q "source it" || fail "running etc/bashrc does not say to source it: $out"
pass "etc/bashrc warns when not built, leaves the shell running, and switches installations"

# --- a copied tutorial without etc/bashrc: a clear message ---------------------------------
cp -r "$install/tutorials/validation/freeFall" "$home/run/"
cd "$home/run/freeFall" || fail "no copy of freeFall"
before=$(ls -A)
out=$(cleanBash "'$home/run/freeFall/Allrun'" 2>&1) && fail "the copied Allrun ran without etc/bashrc"
echo "$out" | grep -q "source <sphCast>/etc/bashrc first" ||
    fail "no 'source <sphCast>/etc/bashrc first' from the copied Allrun: $out"
echo "$out" | grep -q "No such file\|command not found" && fail "a bash error, not a clear message: $out"
[ "$(ls -A)" = "$before" ] || fail "the failed Allrun wrote into the case: $(ls -A)"
out=$(cleanBash "'$home/run/freeFall/Allclean'" 2>&1) && fail "the copied Allclean ran without etc/bashrc"
echo "$out" | grep -q "source <sphCast>/etc/bashrc first" || fail "Allclean's message: $out"
pass "without etc/bashrc the copied Allrun and Allclean say: $(echo "$out" | head -1)"

# --- inside the installation, without etc/bashrc: ../../../etc, as before -------------------------
out=$(cleanBash "'$install/tutorials/validation/freeFall/Allrun' && '$install/tutorials/validation/freeFall/Allclean'" 2>&1) ||
    fail "freeFall in its own tutorials folder without etc/bashrc: $out"
pass "a tutorial inside sphCast still runs without etc/bashrc (../../../etc/RunFunctions)"

# --- with etc/bashrc: the copy runs and cleans --------------------------------------------------
source "$home/sphCastrc"
[ "$SPHCAST_PROJECT" = "$install" ] || fail "SPHCAST_PROJECT=$SPHCAST_PROJECT"
./Allrun > log.Allrun 2>&1 || { cat log.Allrun >&2; fail "the copied freeFall's Allrun"; }
for app in setCastFields sphCastFoam castPostProcess; do
    [ -s "log.$app" ] || fail "Allrun did not run $app"
done
grep -q '^End' log.sphCastFoam || fail "sphCastFoam did not end: $(tail -5 log.sphCastFoam)"
[ -f freeFall.pvd ] || fail "no freeFall.pvd"
csv=postProcessing/cloudSummary/metal.csv
[ "$(wc -l < "$csv")" -eq 27 ] || fail "$csv: not a header and 26 written times"
onTheParabola "$csv" ||
    fail "the copied freeFall's centroid is off the parabola"
./Allclean > "$scratch/log.Allclean" 2>&1 || fail "the copied Allclean: $(cat "$scratch/log.Allclean")"
diff -r "$install/tutorials/validation/freeFall" . > /dev/null ||
    fail "Allclean left: $(diff -rq "$install/tutorials/validation/freeFall" .)"
pass "the copied freeFall runs (centroid on the parabola) and cleans, outside the repository"

# An Allrun that edits a dictionary between its stages (the presses' endTime) keeps the case's own
# with keepOriginal; Allclean puts it back, also after a run stopped between the edit and its end.
(. "$install/etc/RunFunctions" && keepOriginal system/controlDict &&
    sed -i 's/^endTime .*/endTime 400;/' system/controlDict) || fail "keepOriginal and the edit"
grep -q '^endTime 400;' system/controlDict || fail "the edit did not take"
./Allclean > "$scratch/log.Allclean" 2>&1 || fail "the copied Allclean: $(cat "$scratch/log.Allclean")"
diff -r "$install/tutorials/validation/freeFall" . > /dev/null ||
    fail "Allclean did not put back the edited controlDict: $(diff -r "$install/tutorials/validation/freeFall" .)"
pass "Allclean puts back a dictionary an Allrun edited (keepOriginal)"

cp -r "$SPHCAST_TUTORIALS/validation/poiseuilleFlow" "$home/run/myChannel"
cd "$home/run/myChannel" || fail "no copy of poiseuilleFlow"
env -u PYTHONPATH ./Allrun 10 > log.Allrun 2>&1 || { cat log.Allrun >&2; fail "the copied poiseuilleFlow"; }
grep -q "Error\|Traceback" log.Allrun && { cat log.Allrun >&2; fail "errors in the copied poiseuilleFlow"; }
grep -q "t = 0.1 s" log.compareWithSeries || fail "no comparison: $(cat log.compareWithSeries)"
pass "a renamed copy of poiseuilleFlow runs with its comparison (etc/functionObjectSeries.py)"
