#!/bin/sh
# Replay tests, tig/vis style: every cases/NAME.keys runs headless (no tty,
# stdin at EOF, TERM unset) and its final screen must match cases/NAME.screen,
# each screen it :dumps (FILE.txt) must match cases/FILE.txt, its exit status
# cases/NAME.status (default 0) and its stderr cases/NAME.stderr (default
# empty, else exactly). Then checks that say why the screens matter. Prints
# TAP; exits 1 when any case failed.
#   tests/replay/run.sh            run
#   tests/replay/run.sh --update   rewrite the expected files (then read them!)
#   cases/NAME.args                extra command-line arguments for the case
#   cases/NAME.data, NAME.scene    copied beside the script (the args may name them)
#
# How a screen matches its golden (screencmp.awk says it in full): text
# exactly, every number within one unit of its last printed digit, and
# within more where cases/NAME.tol (for NAME.screen and every FILE.txt the
# case dumps) says so, one rule a line:
#     REGEX  TOLERANCE      TOLERANCE: N% | N (printed unit) | * | line
# e.g. "point +[0-9]+ of  *" (how many continuation points there are is a
# floating-point accident: never asserted exactly), "F +-?[0-9.]+ nN  0.5%".
# A golden must pass against the program built with another BLAS and at
# -O0 (make check-fp): give a number the tolerance it needs there, and say
# why in a comment in the .tol file.
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=${ADHERE_SRC:-$(cd "$here/../.." && pwd)}
bin=${ADHERE_BIN:-$src/adhere}
update=0
[ "${1:-}" = --update ] && update=1
# What a screen looks like must not depend on the caller's terminal.
export LC_ALL=C.UTF-8
unset TERM LINES COLUMNS
work=$(mktemp -d)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
echo "# work in $work"
n=0
failed=0
pass() { n=$((n + 1)); echo "ok $n - $*"; }
fail() { n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - $*"; }
check() { what=$1; shift; if "$@"; then pass "$what"; else fail "$what"; fi; }

if [ ! -x "$bin" ]; then
    echo "not ok 1 - $bin is not built"
    echo "1..1"
    exit 1
fi

# run_case NAME [DIR]: runs cases/NAME.keys in DIR (default $work/NAME); sets rc.
run_case() {
    d=${2:-$work/$1}
    mkdir -p "$d"
    cp "$here/cases/$1.keys" "$d/"
    [ -f "$here/cases/$1.data" ] && cp "$here/cases/$1.data" "$d/"
    [ -f "$here/cases/$1.scene" ] && cp "$here/cases/$1.scene" "$d/"
    args=""
    [ -f "$here/cases/$1.args" ] && args=$(cat "$here/cases/$1.args")
    t0=$(date +%s)
    # shellcheck disable=SC2086
    (cd "$d" && timeout 60 "$bin" --replay="$1.keys" --screen="$1.screen" --no-clock $args \
        </dev/null >stdout 2>stderr)
    rc=$?
    echo "# $1: exit $rc in $(($(date +%s) - t0)) s"
}

same_file() {  # expected got: byte for byte
    if [ -f "$1" ] && [ -f "$2" ] && cmp -s "$1" "$2"; then return 0; fi
    diff -u "$1" "$2" 2>&1 | head -40 | sed 's/^/#   /'
    return 1
}
same_screen() {  # NAME expected got: text exactly, numbers within tolerance
    if [ ! -f "$2" ] || [ ! -f "$3" ]; then
        echo "#   missing: $(ls "$2" "$3" 2>&1 >/dev/null)"
        return 1
    fi
    tol=""
    [ -f "$here/cases/$1.tol" ] && tol="$here/cases/$1.tol"
    awk -v tolfile="$tol" -f "$here/screencmp.awk" "$2" "$3"
}

for keys in "$here"/cases/*.keys; do
    name=$(basename "$keys" .keys)
    run_case "$name"
    d=$work/$name
    want_rc=0
    [ -f "$here/cases/$name.status" ] && want_rc=$(cat "$here/cases/$name.status")
    if [ "$update" = 1 ]; then
        [ "$rc" = 0 ] || echo "$rc" >"$here/cases/$name.status"
        if [ -s "$d/stderr" ]; then cp "$d/stderr" "$here/cases/$name.stderr"; else rm -f "$here/cases/$name.stderr"; fi
        [ -f "$d/$name.screen" ] && cp "$d/$name.screen" "$here/cases/"
        for f in "$d"/*.txt; do [ -f "$f" ] && cp "$f" "$here/cases/"; done
        want_rc=$rc
    fi
    check "$name: exit status $rc, want $want_rc" [ "$rc" = "$want_rc" ]
    if [ -f "$here/cases/$name.stderr" ]; then
        check "$name: stderr as expected" same_file "$here/cases/$name.stderr" "$d/stderr"
    else
        check "$name: nothing on stderr" sh -c "[ ! -s '$d/stderr' ] || { sed 's/^/#   /' '$d/stderr'; false; }"
    fi
    if [ -f "$here/cases/$name.screen" ]; then
        check "$name: final screen as expected" same_screen "$name" "$here/cases/$name.screen" "$d/$name.screen"
    else
        check "$name: no screen written (the script failed)" [ ! -e "$d/$name.screen" ]
    fi
    for f in "$d"/*.txt; do
        [ -f "$f" ] || continue
        check "$name: :dump $(basename "$f") as expected" same_screen "$name" "$here/cases/$(basename "$f")" "$f"
    done
done

# --- what the screens mean -------------------------------------------------
W=$work
sigma() { grep -o 'σ [0-9.e+-]*' "$1" | head -1; }
gamma() { grep -o 'γ [0-9.e+-]* mJ/m²' "$1" | head -1; }
# The State panel's numbers (h0, F, delta, gap, a, iterations) with no
# status line, no history counts: what undo must restore exactly.
state() { sed -n '3,8p' "$1"; }

check "the first screen shows sigma 7.503 (Figure 4) and gamma" \
    sh -c "grep -q 'σ 7.503' '$W/start/start.screen' && grep -q 'γ 7.958 mJ/m²' '$W/start/start.screen'"
check ":set E 1GPa changes sigma" [ "$(sigma "$W/set-e/set-e.screen")" != "$(sigma "$W/start/start.screen")" ]
check ":set E 1GPa leaves gamma (it has no E in it)" [ "$(gamma "$W/set-e/set-e.screen")" = "$(gamma "$W/start/start.screen")" ]
# a number said back is compared digit for digit here, not within its last
# digit: %.17g's 5.0000000999999998e-05 is within that of 5.0000001e-05
SE=$W/set-echo
check ":set says a value back in its shortest exact digits, not %.17g's" \
    sh -c "grep -q '^solver.time_tol = 5.0000001e-05: ' '$SE/set-echo-tol.txt' && ! grep -q '0000000999' '$SE/set-echo-tol.txt'"
check ":set takes NAME=VALUE and NAME = VALUE, as a scene writes it" \
    sh -c "grep -q '^solver.time_tol = 0.001: ' '$SE/set-echo-eq.txt' && grep -q '^solver.time_tol = 2.5e-05: ' '$SE/set-echo.screen' && grep -q '^ >E0 *2 GPa' '$SE/set-echo.screen'"
P=$W/panel-edit
check "editing R in the panel changes sigma" [ "$(sigma "$P/panel-R.txt")" != "$(sigma "$P/panel-0.txt")" ]
check "editing z0 in the panel changes sigma" [ "$(sigma "$P/panel-z0.txt")" != "$(sigma "$P/panel-R.txt")" ]
check "editing z0 in the panel changes gamma" [ "$(gamma "$P/panel-z0.txt")" != "$(gamma "$P/panel-R.txt")" ]
check "editing A in the panel changes sigma" [ "$(sigma "$P/panel-A.txt")" != "$(sigma "$P/panel-z0.txt")" ]
check "editing A in the panel changes gamma" [ "$(gamma "$P/panel-A.txt")" != "$(gamma "$P/panel-z0.txt")" ]
check "a bad typed value is named on the status line" grep -q "error: A: '5nm' is a length (m, nm, um, ...), but an energy" "$P/panel-edit.screen"
check "a bad typed value changes nothing" sh -c "grep -q '>A     2e-19 J' '$P/panel-edit.screen' && [ \"\$(sed -n 3,15p '$P/panel-edit.screen')\" = \"\$(sed -n 3,15p '$P/panel-A.txt')\" ]"

K=$W/scale-reset
check "+ doubles E" grep -q "^  E     600 MPa" "$K/scale.txt"
check "a count of 2 before - quarters A" grep -q "^ >A     2.5e-20 J" "$K/scale.txt"
check "and sigma follows both" [ "$(sigma "$K/scale.txt")" = "σ 0.9378" ]
check "x forgets the path" sh -c "grep -q 'path   0 states' '$K/scale-reset.screen' && grep -q '^reset: the path is forgotten' '$K/scale-reset.screen'"

S=$W/steps
check "30 steps of 0.5 nm reach contact" sh -c "grep 'contact radius' '$S/steps-in.txt' | grep -vq 'not in contact'"
check "3 steps back are on the unloading branch" grep -q "branch unloading" "$S/steps.screen"
C=$W/contact
check "r stops at the turning point, in contact" sh -c "grep -q 'at the turning point h0 = -2 nm' '$C/contact-turn.txt' && grep 'contact radius' '$C/contact-turn.txt' | grep -vq 'not in'"
check "r again unloads until the jump-out, out of contact" sh -c "grep -q 'jumped out at h0' '$C/contact.screen' && grep -q 'not in contact' '$C/contact.screen'"
check "the status line names the jump-out (where they separate) and the pull-off (the minimum force, in N and πγR, and where), not only the force after the jump" \
    grep -Eq "^jumped out at h0 = [0-9.]+ nm: pull-off -[0-9.]+ nN \([0-9.]+ πγR\) at [0-9.]+ nm; F after the jump -[0-9.]+ nN" "$C/contact.screen"
check "the pull-off's position is the force minimum's, before the jump-out" \
    sh -c "grep -q 'pull-off -868.8 nN = 3.48 πγR at 7.75 nm' '$C/contact.screen' && grep -q 'jump-in 2.75 nm, jump-out 11 nm' '$C/contact.screen'"
check "the preview shows both branches" sh -c "grep -q 'o' '$C/contact.screen' && sed -n '16,30p' '$C/contact.screen' | grep -q '+'"
# One drive, two drivers: the screen's r and --batch step the same core
# object, so the same scene gives the same rows, every one, bit for bit
# (all columns but the wall time): the contact case (one turn, r to the
# turn, r to pull-off) and Figure 5's eight turns (one loading branch, then
# every unloading branch from its turn's state, pausing at each pull-off).
# rows FILE: the data rows of a force table, without the seconds column
rows() { grep -v '^#' "$1" | cut -f1-12; }
same_rows() {  # tui.tsv batch-dir
    if [ ! -s "$1" ] || [ ! -s "$2/force.tsv" ]; then
        echo "#   missing: $1 or $2/force.tsv ($(head -c 300 "$2.err" 2>/dev/null))"
        return 1
    fi
    [ "$(rows "$1" | head -1 | cut -f1,2)" = "$(printf 'h0\tF')" ] || { echo "#   $1 has no force-table header"; return 1; }
    rows "$1" >"$1.cmp"
    rows "$2/force.tsv" >"$2.cmp"
    cmp -s "$1.cmp" "$2.cmp" && return 0
    diff "$1.cmp" "$2.cmp" | head -6 | sed 's/^/#   /'
    echo "#   $(($(wc -l <"$1.cmp") - 1)) rows on the screen's path, $(($(wc -l <"$2.cmp") - 1)) in --batch's force.tsv"
    return 1
}
"$bin" --batch --nodes=100 --spacing=10nm --force --eps=10pm --step=0.25nm --turn=-2nm --no-plot -o "$work/batch" \
    </dev/null >/dev/null 2>"$work/batch.err"
check "the contact case: the screen's rows are --batch's, every one ($(($(rows "$work/batch/force.tsv" 2>/dev/null | wc -l) - 1)) rows)" \
    same_rows "$C/contact-rows.tsv" "$work/batch"
MB=$work/multiturn-batch
# shellcheck disable=SC2046
"$bin" --batch $(cat "$here/cases/multiturn.args") --no-plot -o "$MB" </dev/null >/dev/null 2>"$MB.err"
M=$W/multiturn
check "fig5's eight turns: the screen's rows are --batch's, every one ($(($(rows "$MB/force.tsv" 2>/dev/null | wc -l) - 1)) rows)" \
    same_rows "$M/multiturn-rows.tsv" "$MB"
check "--batch unloaded all eight turns" [ "$(grep -vc '^#' "$MB/turns.tsv" 2>/dev/null)" = 9 ]
# pull-off of turn K in turns.tsv, 4 digits as the screen prints it (mN)
pulloff() { awk -F'\t' -v k="$1" '/^#/ { next } $1 == "turn_h0" { for (i = 1; i <= NF; i++) if ($i == "pulloff_F") c = i; next }
                                  ++n == k { printf "%.4g", $c * 1e3 }' "$MB/turns.tsv"; }
check "r pauses at turn 1 of 8 on the way in" grep -q "^at turn 1 of 8, h0 = 2 nm" "$M/multiturn-turn1.txt"
check "and at turn 8, then unloads turn 1 first" grep -q "^at turn 8 of 8, h0 = -10 nm.*r to unload turn 1" "$M/multiturn-turn8.txt"
check "turn 1 pulls off at --batch's $(pulloff 1) mN, and r goes on with turn 2" \
    grep -q "(turn 1 of 8): pull-off $(pulloff 1) mN.*r unloads turn 2" "$M/multiturn-pull1.txt"
check "turn 8 pulls off last, at --batch's $(pulloff 8) mN" grep -q "pull-off $(pulloff 8) mN" "$M/multiturn-pull8.txt"
check "then r says the protocol is complete" grep -q "^the protocol is complete" "$M/multiturn-complete.txt"
check "one state back, r unloads turn 8 again to the same pull-off" grep -q "pull-off $(pulloff 8) mN" "$M/multiturn-again.txt"
check "the turn field shows the list; the state the turn of the branch on screen (turn 1: 2 nm, turn 8: -10 nm)" \
    sh -c "grep -q '^  turn  2 … -10 nm   8 turning points' '$M/multiturn-pull1.txt' && grep -q 'branch unloading from turn 1 of 8, 2 nm' '$M/multiturn-pull1.txt' && grep -q 'branch unloading from turn 8 of 8, -10 nm' '$M/multiturn-pull8.txt'"

# A soft material set on the screen gets --batch's grid for it, and the
# same rows.
SO=$W/soft
SB2=$work/soft-batch
# shellcheck disable=SC2046
"$bin" --batch -E 0.1GPa $(cat "$here/cases/soft.args") --no-plot -o "$SB2" </dev/null >/dev/null 2>"$SB2.err"
check "E 300 MPa: the paper's 1000 uniform nodes" grep -q "^  N     1000 *grid nodes *branch\|^  N     1000 " "$SO/soft-0.txt"
check ":set E 0.1GPa: graded rings, as --batch chooses ($(awk -F'\t' '$1 == "nodes" {print $2}' "$SB2/summary.tsv" 2>/dev/null) of them)" \
    grep -q "^  N     $(awk -F'\t' '$1 == "nodes" {print $2}' "$SB2/summary.tsv" 2>/dev/null) *grid nodes (rings" "$SO/soft-E.txt"
check "and resolved" grep -q "resolved" "$SO/soft-E.txt"
check "the soft contact's rows are --batch -E 0.1GPa's, every one" same_rows "$SO/soft-rows.tsv" "$SB2"

# The protocol is the configuration's whole, on the screen as in --batch:
# a dwell and profiles from a scene, and (by :set, keys without a field)
# no unloading, a dwell and profiles.
PR=$W/protocol
PB=$work/protocol-batch
"$bin" --batch "$here/cases/protocol.scene" --nodes=100 --spacing=10nm --force --eps=10pm --step=0.25nm --no-plot \
    -o "$PB" </dev/null >/dev/null 2>"$PB.err"
check "dwell and profiles: the screen's rows are --batch's, every one ($(($(rows "$PB/force.tsv" 2>/dev/null | wc -l) - 1)) rows)" \
    same_rows "$PR/protocol-rows.tsv" "$PB"
check "each turn's unloading begins after the dwell: 5000 iterations, twice" \
    [ "$(awk -F'\t' '!/^#/ && $8 == -1 && $7 == 5000' "$PR/protocol-rows.tsv" | wc -l)" = 2 ]
check "p draws the profiles the scene asked for, as --batch stores them" \
    sh -c "[ -s '$PB/profiles.tsv' ] && [ \"\$(grep -v '^#' '$PR/adhere-plots/profiles.tsv' | cut -f1-4 | sort -u)\" = \"\$(grep -v '^#' '$PB/profiles.tsv' | cut -f1-4 | sort -u)\" ]"
LO=$W/loadonly
LB=$work/loadonly-batch
printf '[protocol]\nturns = -2nm\nunload = no\ndwell = 3000\n[output]\nprofiles = 2nm, -1nm\n' >"$work/loadonly.scene"
"$bin" --batch "$work/loadonly.scene" --nodes=100 --spacing=10nm --force --eps=10pm --step=0.25nm --no-plot \
    -o "$LB" </dev/null >/dev/null 2>"$LB.err"
check "protocol.unload no: the screen's rows are --batch's, every one ($(($(rows "$LB/force.tsv" 2>/dev/null | wc -l) - 1)) rows)" \
    same_rows "$LO/loadonly-rows.tsv" "$LB"
check "all of them loading, the last at the turn" \
    sh -c "! awk -F'\t' '!/^#/ && \$8 == -1' '$LO/loadonly-rows.tsv' | grep -q . && [ \"\$(tail -1 '$LO/loadonly-rows.tsv' | cut -f1)\" = -2.0000000000000001e-09 ]"
check "r stops at the turn, and says the protocol ends there" \
    grep -q "^at the turning point h0 = -2 nm .*the protocol ends here (protocol.unload = no)" "$LO/loadonly-turn.txt"
check "and r again says it is complete, loading only" grep -q "^the protocol is complete: it loads only" "$LO/loadonly-complete.txt"

HT=$W/handturns
check "b at turn 1 then r: turn 1 pulls off, and r loads on to turn 2 (never reached yet)" \
    grep -q "(turn 1 of 2): pull-off .*; r loads on to turn 2 of 2" "$HT/handturns-pull1.txt"
check "r reaches turn 2 and unloads it next" grep -q "^at turn 2 of 2, h0 = -2 nm .*unload turn 2 of 2" "$HT/handturns-turn2.txt"
check "then the protocol is complete" grep -q "^the protocol is complete" "$HT/handturns-complete.txt"
check "b undone at the start: r loads to the turn (the undone step by hand is not replayed)" \
    grep -q "^at turn 1 of 2, h0 = -1 nm" "$HT/handturns-undo.txt"
check "+ on the turn field doubles the whole list: turn 1 of 2 is now at -2 nm" \
    grep -q "^at turn 1 of 2, h0 = -2 nm" "$HT/handturns-scaled.txt"
check "a turn set where the loading branch is: r unloads from there to the jump-out" \
    grep -q "^jumped out at h0 = " "$HT/handturns-here.txt"

U=$W/undo
check "undo gives back the earlier state's numbers exactly" [ "$(state "$U/undo-back.txt")" = "$(state "$U/undo-32.txt")" ]
check "redo gives back the later state's numbers exactly" [ "$(state "$U/undo-redo.txt")" = "$(state "$U/undo-33.txt")" ]
check "the two states differ (the check above can fail)" [ "$(state "$U/undo-33.txt")" != "$(state "$U/undo-32.txt")" ]
check "undo then the same step again gives the same numbers and iterations" \
    [ "$(state "$W/undo-restep/restep-again.txt")" = "$(state "$W/undo-restep/restep-first.txt")" ]
check "undo says how far it went" grep -q "undid 3 steps" "$U/undo-30.txt"
check "a new step drops what could be redone" grep -q "error: nothing to redo" "$U/undo.screen"

# The cycle's numbers on the state panel, and edits on the undo history.
EU=$W/edit-undo
check "after a cycle the panel shows max load, pull-off in N and in πγR, jumps, hysteresis" \
    sh -c "grep -q 'load   max -[0-9.]* nN; a [0-9.]* nm at the turn' '$EU/edit-cycle.txt' && grep -q 'pull-off -[0-9.]* nN = [0-9.]* πγR at [0-9.]* nm' '$EU/edit-cycle.txt' && grep -q 'jump-in [0-9.]* nm, jump-out [0-9.]* nm' '$EU/edit-cycle.txt' && grep -q 'hysteresis [0-9.]* fJ' '$EU/edit-cycle.txt'"
check "beside the JKR, DMT and Maugis-Dugdale predictions" \
    sh -c "grep -q 'pull-off JKR -375 nN DMT -500 nN' '$EU/edit-cycle.txt' && grep -q 'M-D -375.8 nN = 1.5 πγR (λ 7.06)' '$EU/edit-cycle.txt'"
check "the label 'before any solve' does not stay after solving" sh -c "! grep -q 'before any solve' '$EU/edit-cycle.txt'"
check "z0 and d show in nm" sh -c "grep -q '^  z0    0.5 nm ' '$EU/edit-cycle.txt' && grep -q '^  d     0.25 nm ' '$EU/edit-cycle.txt'"
check "a bare 20 typed into R (shown in µm) is 20 µm, and the echo says so" \
    sh -c "grep -q '^ >R     20 µm ' '$EU/edit-r.txt' && grep -q '^R = 20 µm: σ = 10.61' '$EU/edit-r.txt'"
check "the edit starts a new path" grep -q "path   0 states" "$EU/edit-r.txt"
check "u after the edit restores the parameters and their path" \
    sh -c "grep -q '^ >R     10 µm ' '$EU/edit-undo.txt' && grep -q 'path   130 states' '$EU/edit-undo.txt' && grep -q '^undid the edit: R = 10 µm again, with its path (130 states)' '$EU/edit-undo.txt'"
check "with the path's numbers exactly (state and cycle)" [ "$(sed -n '3,18p' "$EU/edit-undo.txt" | cut -c46-)" = "$(sed -n '3,18p' "$EU/edit-cycle.txt" | cut -c46-)" ]
check "U puts the edit back" sh -c "grep -q '^ >R     20 µm ' '$EU/edit-redo.txt' && grep -q '^redid the edit: R = 20 µm' '$EU/edit-redo.txt'"
check "+ doubles A, and u takes it back with the path" \
    sh -c "grep -q '^ >A     2e-19 J' '$EU/edit-plus.txt' && grep -q '^ >A     1e-19 J' '$EU/edit-undo.screen' && grep -q 'path   130 states' '$EU/edit-undo.screen'"

MD=$W/measured
check "--data draws the measured curve in the preview before any step, named in its key" \
    sh -c "grep -q 'x measured' '$MD/measured-0.txt' && sed -n '20,29p' '$MD/measured-0.txt' | cut -c12- | grep -q 'x'"
check "and under the computed path after a cycle" \
    sh -c "sed -n '20,29p' '$MD/measured.screen' | cut -c12- | grep -q 'x' && sed -n '20,29p' '$MD/measured.screen' | cut -c12- | grep -q 'o'"

EG=$W/edit-grid
check "u after an N edit and two steps: back on the N = 100 path, its numbers exactly" \
    sh -c "grep -q '^undid the edit: N = 100 again, with its path (6 states)' '$EG/edit-grid-back.txt' && [ \"\$(sed -n '3,8p' '$EG/edit-grid-back.txt' | cut -c46-)\" = \"\$(sed -n '3,8p' '$EG/edit-grid-5.txt' | cut -c46-)\" ]"
check "and a step goes on from it on the rebuilt grid" grep -q "path   7 states" "$EG/edit-grid.screen"

# A contact past the graded grid's fine band: f is refused with the drive's
# reason, b still steps out.
ES=$W/edgestop
check "f at the fine band's limit is refused with the reason, no step taken" \
    sh -c "grep -q '^error: no approach from here: the contact radius .* left the graded grid.s fine band' '$ES/edgestop-refused.txt' && grep -q ' h0     -9.5 nm ' '$ES/edgestop-refused.txt'"
check "b from there retracts by d (to -9 nm)" grep -q " h0     -9 nm " "$ES/edgestop.screen"

# Each mode on its own automatic grid, as --batch --mode chooses it.
MG=$W/modegrid
plan_nodes() { "$bin" --plan "$@" | sed -n 's/^kernel: .*N = \([0-9]*\),.*/\1/p; s/^kernel: .* grid of \([0-9]*\) .*/\1/p'; }
shown_nodes() { sed -n 's/^  N  *\([0-9]*\)  *grid nodes.*/\1/p' "$1"; }
rn=$(plan_nodes) sn=$(plan_nodes --mode=static)
check "relaxation shows --batch's grid ($rn nodes), resolved" \
    sh -c "[ -n '$rn' ] && [ '$(shown_nodes "$MG/modegrid-relax.txt")' = '$rn' ] && grep -q 'ℓ/Δ [0-9.]* resolved' '$MG/modegrid-relax.txt'"
check "m shows --batch --mode=static's finer grid ($sn nodes), resolved, not the relaxation's as UNRESOLVED" \
    sh -c "[ -n '$sn' ] && [ '$sn' != '$rn' ] && [ '$(shown_nodes "$MG/modegrid-static.txt")' = '$sn' ] && grep -q 'ℓ/Δ [0-9.]* resolved' '$MG/modegrid-static.txt'"
check "the curve is solved there (2 points)" grep -q "point  2 of 2," "$MG/modegrid-static2.txt"
was=$(state "$MG/modegrid-relax.txt" | cut -c46-) back=$(state "$MG/modegrid-back.txt" | cut -c46-)
check "m back: the relaxation's grid again and its path as it was" \
    sh -c "[ '$(shown_nodes "$MG/modegrid-back.txt")' = '$rn' ] && [ -n '$was' ] && [ '$was' = '$back' ] && grep -q 'path   4 states' '$MG/modegrid-back.txt'"

# Static mode (m): the equilibrium curve point by point, walked back and
# forth without solving again, followed to its end as --batch --mode=static.
ST=$W/static
at() { sed -n 's/.*point  \([0-9]* of [0-9]*\), .*/\1/p' "$1"; }
check "m shows static mode before any solve" sh -c "grep -q 'mode   static (m: relaxation), idle' '$ST/static-0.txt' && grep -q 'start, not solved yet' '$ST/static-0.txt' && grep -q ' f next  b back ' '$ST/static-0.txt'"
check "and relaxation says m switches (the mode is on screen)" grep -q "mode   relaxation (m: static), idle" "$W/start/start.screen"
check "5f solves five points of the curve ($(at "$ST/static-5.txt"))" [ "$(at "$ST/static-5.txt")" = "5 of 5" ]
check "b and u walk back two points, no point dropped ($(at "$ST/static-back.txt"))" [ "$(at "$ST/static-back.txt")" = "3 of 5" ]
check "the point walked back to has other numbers (the checks around can fail)" [ "$(state "$ST/static-back.txt")" != "$(state "$ST/static-5.txt")" ]
check "U and f walk forward to the same numbers" [ "$(state "$ST/static-fwd.txt")" = "$(state "$ST/static-5.txt")" ]
check "and say the point was kept, not solved again" grep -q "^point 5 (kept, not solved again)" "$ST/static-fwd.txt"
SB=$work/static-batch
"$bin" --batch --mode=static --nodes=100 --spacing=10nm --force --no-plot -o "$SB" </dev/null >/dev/null 2>"$work/static-batch.err"
sval() { awk -F'\t' -v k="$1" '$1 == k {print $2}' "$SB/summary.tsv"; }
if [ -s "$SB/summary.tsv" ]; then
    pts=$(sval points) folds=$(sval folds)
    nN() { awk -v v="$1" 'BEGIN {printf "%.4g nN", v * 1e9}'; }
    nm() { awk -v v="$1" 'BEGIN {printf "%.4g nm", v * 1e9}'; }
    check "r follows the curve to its end: --batch --mode=static's $pts points" grep -q "point  $pts of $pts," "$ST/static-end.txt"
    # both step the drive's static rule: the same points, every one (Newton
    # iteration counts too); no seconds column to mask in the comparison
    check "and the screen's points are --batch --mode=static's rows, every one" same_rows "$ST/static-rows.tsv" "$SB"
    check "its physical folds, jump-in $(nm "$(sval jump_in_h0)") and jump-out $(nm "$(sval jump_out_h0)"), apart from its $((folds - 2)) lattice folds ($folds in all)" \
        grep -q "folds  jump-in $(nm "$(sval jump_in_h0)"), out $(nm "$(sval jump_out_h0)"), +$((folds - 2)) lattice" "$ST/static-end.txt"
    check "and its pull-off $(nN "$(sval pulloff_F)") (the minimum force) and force at the jump-out $(nN "$(sval pulloff_F_disp)")" \
        grep -q "pull-off $(nN "$(sval pulloff_F)"); F at the jump-out $(nN "$(sval pulloff_F_disp)")" "$ST/static-end.txt"
else
    fail "--batch --mode=static with the static case's settings wrote no summary: $(head -c 300 "$work/static-batch.err")"
fi
# One static curve under a spring, whoever builds its settings: the
# screen's m takes --batch --mode=static --spring's closer points (the
# snap points are read off between them), the same rows, every one.
SS=$work/staticspring-batch
"$bin" --batch --mode=static --nodes=100 --spacing=10nm --force --turn=-1nm --spring=1 --no-plot -o "$SS" \
    </dev/null >/dev/null 2>"$SS.err"
check "under a spring the screen's static curve is --batch --mode=static --spring's rows, every one ($(($(rows "$SS/force.tsv" 2>/dev/null | wc -l) - 1)) rows)" \
    same_rows "$W/staticspring/staticspring-rows.tsv" "$SS"
check "the end of the curve is said, on the state and status lines" \
    sh -c "grep -q 'curve  complete, ends at h0 = -5 nm' '$ST/static-end.txt' && grep -q '^curve complete at h0 = -5 nm' '$ST/static-end.txt'"
check "the preview marks stable (*) and unstable (.) points" \
    sh -c "sed -n '17,30p' '$ST/static-end.txt' | cut -c12- | grep -q '[*]' && sed -n '17,30p' '$ST/static-end.txt' | cut -c12- | grep -q '[.]'"
check "p in static mode writes force.png as a PNG, into static/ beside the relaxation's" \
    sh -c "[ \"\$(head -c 8 '$ST/adhere-plots/static/force.png' | od -An -tx1 | tr -d ' ')\" = 89504e470d0a1a0a ] && grep -q '^plots: wrote force.png' '$ST/static-plots.txt' && grep -q 'adhere-plots/static' '$ST/static-plots.txt'"
check "its profiles: first contact, pull-off and the curve's end (3)" \
    [ "$(grep -v '^#' "$ST/adhere-plots/static/profiles.tsv" | tail -n +2 | cut -f1 | sort -u | wc -l)" -eq 3 ]
# A start in contact (1 TPa from 0.1 nm): the pull-off is past the start,
# where the unloading goes on; its profile is kept there, at the curve's
# point of least force, within a tenth of z0 of --batch's pull-off from the
# automatic start (an independent run: the curve from out of contact); the
# screen kept the start's (0.1 nm). A curve without folds says so in words.
SC=$W/staticcontact
SB=$work/staticcontact-batch
"$bin" --batch --mode=static --nodes=200 -E 1TPa --turn=-1nm --no-plot -o "$SB" </dev/null >/dev/null 2>"$SB.err"
sc_pull=$(awk -F'\t' '$1 == "pulloff_h0" { print $2 }' "$SB/summary.tsv" 2>/dev/null)
check "a start in contact: the pull-off's profile is past the start, at the pull-off from the automatic start (${sc_pull:-none} m)" \
    sh -c "[ -n '$sc_pull' ] && grep -v '^#' '$SC/adhere-plots/static/profiles.tsv' | tail -n +2 | cut -f1 | sort -u | awk -v p='$sc_pull' 'BEGIN { n = 0 } { d = \$1 - p; if (d < 0) d = -d; if (d < 0.05e-9) n++ } END { exit n != 1 }'"
check "a curve without folds says there were no jumps, in words (no nan)" \
    sh -c "grep -q '^curve complete at h0 = -1 nm ([0-9]* points; no jumps): pull-off -4' '$SC/staticcontact-end.txt' && grep -q 'folds  none: no jumps' '$SC/staticcontact-end.txt' && ! grep -qi 'nan' '$SC/staticcontact-end.txt'"
check "its contact.tsv has no speed: a curve of equilibria does not move in time" \
    sh -c "grep -q '^# the static equilibrium curve: nothing moves along it' '$ST/adhere-plots/static/contact.tsv' && ! awk -F'\t' '!/^#/ && \$1 != \"h0\" && \$6 != \"nan\"' '$ST/adhere-plots/static/contact.tsv' | grep -q ."
check "p back in relaxation keeps both: the path's plots in adhere-plots/, the curve's in static/" \
    sh -c "[ -s '$ST/adhere-plots/force.png' ] && [ -s '$ST/adhere-plots/static/force.png' ] && [ -s '$ST/adhere-plots/static/contact.png' ] && grep -q '^plots: wrote force.png' '$ST/static-relaxplots.txt'"
check "changing eps keeps the curve ($(at "$ST/static-eps.txt")) and says why" \
    sh -c "[ '$(at "$ST/static-eps.txt")' = '$(at "$ST/static-end.txt")' ] && grep -q '^eps = 2 pm: the equilibrium curve does not depend on it and is kept' '$ST/static-eps.txt'"
check "changing E drops the curve and says it starts again" \
    sh -c "grep -q 'start, not solved yet' '$ST/static-restart.txt' && grep -q 'the curve starts again from the start' '$ST/static-restart.txt'"
check "and sigma follows E at once" [ "$(sigma "$ST/static-restart.txt")" != "$(sigma "$ST/static-end.txt")" ]
check "m back to relaxation shows its own (empty) path" \
    sh -c "grep -q 'mode   relaxation (m: static), idle' '$ST/static-relax.txt' && grep -q 'path   0 states' '$ST/static-relax.txt'"
check "m to static again finds the curve as it was ($(at "$ST/static-again.txt"), nothing solved)" \
    sh -c "[ '$(at "$ST/static-again.txt")' = '3 of 3' ] && grep -q 'nothing solved again' '$ST/static-again.txt'"
check "and m back finds the relaxation path (2 states) as it was" \
    sh -c "grep -q 'path   2 states' '$ST/static-relaxback.txt' && grep -q 'relaxation: back on the path' '$ST/static-relaxback.txt'"
# One check of every limit, in the core: :set refuses what --batch refuses,
# with the core's same sentence, each driver naming what to change in
# parentheses after it in its own words (the CLI its flags, the screen its
# fields and keys, never a flag), and takes what --batch takes. A sentence
# that opens with the value refused names it in each driver's words first
# (--eps=1e-25m, the screen's eps = 1e-25 m): the same from "is" on.
for lim in "R 5nm|--radius=5nm" "eps 1e-25m|--eps=1e-25m"; do
    set_=${lim%%|*}; flag=${lim#*|}
    out=$("$bin" --batch --no-plot -o "$work/lim-out" "$flag" </dev/null 2>&1 >/dev/null)
    brc=$?
    want=$(sed 's/^[^:]*:[0-9]*: //' "$here/cases/limit-${set_%% *}.stderr")
    check ":set $set_ and $flag are refused alike ($brc: $out; the screen: $want)" \
        sh -c 'core() { s=$(printf "%s" "$1" | sed "s/ ([^()]*)\$//"); printf "%s" "${s#* is }"; }
               [ "$1" = 2 ] && [ "$(core "$2")" = "$(core "$3")" ] && case "$3" in *--*) false ;; esac &&
               { [ "${2%% is *}" = "adhere: $4" ] || [ "${2%% is *}" = "adhere: ${3%% is *}" ]; }' \
        _ "$brc" "$out" "$want" "$flag"
done
# A solid's start: :set protocol.start is refused as --batch --start is,
# with the same sentence from "is not allowed" on (each names the start in
# its own words first: --start=400pm, the screen's start = 400 pm), and the
# screen stays up (it steps from the automatic start); --batch writes nothing.
VS=$W/visco-start
out=$("$bin" --batch --no-plot -o "$work/vs-out" visco -N 150 --force --start=0.4nm </dev/null 2>&1 >/dev/null)
brc=$?
said=$(sed -n '/^error: start = 400 pm/,/(:set protocol.start)$/p' "$VS/visco-start-refused.txt" | tr '\n' ' ' | sed 's/ $//')
check ":set protocol.start 0.4nm and --start=0.4nm are refused alike in a solid's physical time ($brc: $out; the screen: $said)" \
    sh -c 'core() { printf "%s" "$1" | sed -e "s/ ([^()]*)\$//" -e "s/^[^:]*: [^ ]* \(= [^ ]* [^ ]* \)\{0,1\}is not allowed/is not allowed/"; }
           case "$2" in "adhere: --start=400pm is not allowed"*) true ;; *) false ;; esac &&
           [ "$1" = 2 ] && [ ! -e "$4" ] && [ "$(core "$2")" = "$(core "$3")" ] &&
           case "$3" in *"is not allowed"*"(:set protocol.start)") true ;; *) false ;; esac' \
    _ "$brc" "$out" "$said" "$work/vs-out"
check "... the screen stays up and steps from the automatic start" \
    sh -c "grep -q 'h0     16.95 nm' '$VS/visco-start-step.txt' && grep -q '^t = 0 s: h0 16.95 nm' '$VS/visco-start-step.txt'"
check ":set spacing 16nm on 100 nodes is taken, as --batch -N 100 --spacing=16nm is" \
    grep -q "spacing = 16 nm: .* a new path starts" "$W/limit-spacing/limit-spacing.screen"
E=$W/static-edge
check "--mode=static opens the screen in static mode" grep -q "State  (static equilibrium)" "$E/static-edge.txt"
check "a grid too short for the contact is refused up front, with --batch's reason, and no point is solved" \
    sh -c "grep -q '! grid radius Rmax = .* is too short' '$E/static-edge.txt' && grep -q '^error: grid radius Rmax = .* is too short' '$E/static-edge.txt' && grep -q 'start, not solved yet' '$E/static-edge.txt'"
check "a step after it is refused with the same reason" grep -q "^error: grid radius Rmax = .* is too short" "$E/static-edge.screen"

PL=$W/plots/adhere-plots
for f in force.png profile.png contact.png; do
    check "p wrote $f as a PNG" sh -c "[ \"\$(head -c 8 '$PL/$f' | od -An -tx1 | tr -d ' ')\" = 89504e470d0a1a0a ]"
done
PO=$W/plots-out
check "--out chooses where p writes in the TUI" \
    sh -c "[ \"\$(head -c 8 '$PO/my-plots/force.png' | od -An -tx1 | tr -d ' ')\" = 89504e470d0a1a0a ] && [ ! -e '$PO/adhere-plots' ] && grep -q '^plots: wrote force.png.* in my-plots' '$PO/plots-out.screen'"
check "p says which plots it wrote and where (the status wraps rather than cut the directory)" \
    sh -c "grep -A2 '^plots: ' '$W/plots/plots.screen' | tr '\n' ' ' | grep 'force.png, profile.png, contact.png' | grep -q 'in adhere-plots'"

R=$W/resize
check "after :resize 80x24 the screen is 24 lines of at most 80 columns" \
    sh -c "[ \$(wc -l <'$R/resize.screen') = 24 ] && [ \$(wc -L <'$R/resize.screen') -le 80 ]"
check "at 60x40 the screen is 40 lines of at most 60 columns" \
    sh -c "[ \$(wc -l <'$R/resize-60x40.txt') = 40 ] && [ \$(wc -L <'$R/resize-60x40.txt') -le 60 ]"

check "the help says where p writes the plots and that --out chooses it" \
    sh -c "grep -q 'adhere-plots/' '$W/help/help.screen' && grep -q -- '--out' '$W/help/help.screen'"
check "at 40x12 stepping shows the state" sh -c "grep -q 'h0     16.7 nm' '$W/small/small-state.txt' && ! grep -q 'Parameters' '$W/small/small-state.txt'"
check "and keeps every parameter in view in a compact form" \
    sh -c "grep -q '^E 300 MPa  A 1e-19 J  z0 0.5 nm  R 10 µm' '$W/small/small-state.txt' && grep -q '^turn -5 nm' '$W/small/small-state.txt'"
check "at 40x12 selecting shows the parameters" sh -c "grep -q '^ >A ' '$W/small/small.screen' && [ \$(wc -l <'$W/small/small.screen') = 12 ] && [ \$(wc -L <'$W/small/small.screen') -le 40 ]"

# An ordinary terminal, 100 x 24 (issue 28, item 5)
SH=$W/short
check "at 100x24 the screen is 24 lines of at most 100 columns" \
    sh -c "[ \$(wc -l <'$SH/short.screen') = 24 ] && [ \$(wc -L <'$SH/short.screen') -le 100 ]"
check "at 100x24 the preview keeps its plot, its range in the heading" \
    sh -c "grep -q '^ F against h0  + loading  o unloading  @ now  *h0 2 nm to 17 nm' '$SH/short.screen' && grep -Eq '^ -[0-9.]+ nN\|@' '$SH/short.screen'"
check "the state's words wrap at 100 columns, none cut" \
    sh -c "grep -q 'run to the turning\$' '$SH/short-0.txt' && grep -q 'point, ? for every key' '$SH/short-0.txt'"
check "the turn field shows its list: the ends, shallowest first, and the count" \
    sh -c "grep -q '^  turn  2 … -2 nm    3 turning points' '$SH/short.screen' && grep -q '^turn = 2, 1, -2 nm: r now loads to there' '$SH/short-0.txt'"
check ":set of a key outside the panel reads a bare number in the unit it is shown in (protocol.start 12: 12 nm)" \
    sh -c "grep -q '^protocol.start = 12 nm' '$W/setunit/setunit-start.txt' && grep -q 'start 12 nm' '$W/setunit/setunit-start.txt' && grep -q '^grid.fine_band = 500 nm' '$W/setunit/setunit.screen'"
# A line too long for a narrow screen loses its last clause whole, and a
# wrapped message never puts a number on one line and its unit on the next.
check "at 80 and 40 columns no line ends in a number without its unit" \
    sh -c "cd '$W' && ! grep -E '[0-9]\$' resize/resize.screen resize/resize-60x40.txt small/small.screen small/small-state.txt narrow/narrow.screen short/short.screen short/short-0.txt"
check "at 80 columns the state's rows end at a clause (path ... to redo, not '; start 17 n')" \
    sh -c "grep -Eq 'path   [0-9]+ states, 0 to redo\$' '$W/resize/resize.screen' && grep -Eq ' F +-?[0-9.]+ [pn]N +force\$' '$W/resize/resize.screen'"
check "at 40 columns the preview's axis labels stand apart (its ends whole, the middle shortened)" \
    sh -c "grep -Eq '^ {11}7 nm +h0 +17 nm\$' '$W/narrow/narrow.screen'"
RP=$W/runplot
check "p during r pauses the run and draws the path so far, r going on from there" \
    sh -c "grep -A2 '^paused at h0 = ' '$RP/runplot-paused.txt' | tr '\n' ' ' | grep -q 'plots: wrote force.png.*in adhere-plots.*; r goes on' && [ -s '$RP/adhere-plots/force.png' ] && grep -q '^at the turning point h0 = -5 nm' '$RP/runplot.screen'"
check "... drawn from the 12 states of the path so far" \
    sh -c "grep -q 'path   12 states' '$RP/runplot-paused.txt'"

check "a bad token names FILE:LINE and the token" grep -q "^bad-token.keys:3: unknown key <Foo>" "$W/bad-token/stderr"
check "a bad :set value names FILE:LINE, the value and what is wanted" \
    grep -q "^bad-set.keys:3: E: '5nm' is a length (m, nm, um, ...), but a pressure" "$W/bad-set/stderr"
check "an unknown :set name lists the names" grep -q "^bad-name.keys:1: unknown parameter 'sigma'.*E A z0 R eps d N spacing turn" "$W/bad-name/stderr"

check "a grid too short for the turn is flagged before any solve" \
    sh -c "grep -q '! grid radius Rmax = 150 nm is too short' '$W/grid-warn/grid-warn.screen' && grep -q 'use' '$W/grid-warn/grid-warn.screen' && grep -q 'path   0 states' '$W/grid-warn/grid-warn.screen'"
check "an unwritable :dump names FILE:LINE and the file" \
    grep -q "^bad-dump.keys:2: cannot write the screen to no-such-dir/screen.txt: No such file" "$W/bad-dump/stderr"
PL=$W/prompt-long
check "a 148-character name typed at the ':' prompt is written whole, the header and the path's 4 states in it (not a name cut at 122)" \
    sh -c "[ \$(grep -vc '^#' '$PL/afm-2026-11-27-sample-B-silica-sphere-R10um-on-PDMS-10-to-1-cured-48h-approach-retract-1um-per-s-dwell-0s-run-017-of-120-calibrated-k0.35N-per-m.tsv') = 5 ] && [ \$(ls '$PL' | grep -c '^afm-') = 1 ]"
check "a line longer than the prompt holds writes nothing, under no name" sh -c "! ls '$PL' | grep -q '^xxx'"

# :rows into a pipe no program reads is refused at once: opening it waited
# for a reader for ever, the screen frozen (timeout's 124 if it still does).
mkdir -p "$work/fifo"
mkfifo "$work/fifo/rows.fifo"
printf 'f\n:rows rows.fifo\n' >"$work/fifo/fifo.keys"
(cd "$work/fifo" && timeout 20 "$bin" --replay=fifo.keys --screen=s.txt </dev/null >/dev/null 2>err)
rc=$?
check ":rows into a pipe with no reader: exit 2 at once, saying so (got $rc: $(head -c 200 "$work/fifo/err"))" \
    sh -c "[ $rc = 2 ] && grep -q '^fifo.keys:2: cannot write the rows to rows.fifo: a pipe no program reads' '$work/fifo/err'"

# Determinism, and independence from the caller's terminal settings.
run_case steps "$work/again"
check "the same script gives the same screen" same_file "$S/steps.screen" "$work/again/steps.screen"
mkdir -p "$work/env"
cp "$here/cases/start.keys" "$work/env/"
(cd "$work/env" && TERM=dumb LINES=10 COLUMNS=20 "$bin" --replay=start.keys --screen=start.screen --no-clock </dev/null >/dev/null 2>&1)
check "TERM, LINES and COLUMNS do not change a replay's screen" same_file "$W/start/start.screen" "$work/env/start.screen"

# An elastic sphere in physical time: the screen steps the path the batch
# run writes (adh_rule_path, no integration), row for row, every column but
# the wall time; its state says what the rows so far have seen.
TE=$W/time-elastic
# shellcheck disable=SC2046
"$bin" --batch $(cat "$here/cases/time-elastic.args") --no-plot -o "$work/te-batch" </dev/null >/dev/null 2>"$work/te-batch.err"
trows() { grep -v '^#' "$1" | cut -f1-14; }
check "elastic in time: the screen's rows are --batch --mode=time's, every one ($(trows "$work/te-batch/force.tsv" 2>/dev/null | wc -l) lines)" \
    sh -c "[ -s '$TE/time-elastic-rows.tsv' ] && trows() { grep -v '^#' \"\$1\" | cut -f1-14; }; [ \"\$(trows '$TE/time-elastic-rows.tsv')\" = \"\$(trows '$work/te-batch/force.tsv')\" ]"
TW=$W/time-elastic-walk
check "elastic in time: the jump into contact names the base's position, not its speed (it said 'base at 1 um/s')" \
    sh -c "cat '$TW'/j*.scr | grep -q 'jumped into contact at h0 = [-0-9.]* nm (base at [-0-9.]* nm)' && ! cat '$TW'/j*.scr | grep -q 'base at [0-9.]* [u]m/s)'"
check "elastic in time: walked back from the end, no hysteresis before the path is back at its start" \
    grep -q 'hysteresis not yet' "$TW/time-elastic-walk-b.txt"
check "elastic in time: no jump and no pull-off after three rows, the batch's two jumps and hysteresis at the end" \
    sh -c "grep -q 'jumps  0; in not yet' '$TE/time-elastic-3.txt' && grep -q 'jumps  2; in' '$TE/time-elastic-end.txt' && grep -q 'steps  none in time' '$TE/time-elastic-end.txt'"

# A list typed with an empty element is refused quoting what was typed: it
# quoted the bare numbers as converted to SI, '-1.0000000000000001e-09,,-2...'
# for '-1,,-2', and '9.9999999999999995e-07,,1.9999999999999999e-06' for
# the speeds '1,,2'.
mkdir -p "$work/emptyel"
printf ':set turn -1,,-2\n' >"$work/emptyel/t.keys"
(cd "$work/emptyel" && "$bin" --replay=t.keys --no-clock -N 100 --force </dev/null >/dev/null 2>t.err)
check "a turn list with an empty element is refused quoting it as typed ($(cat "$work/emptyel/t.err"))" \
    grep -qF "t.keys:1: turn: '-1,,-2' has an empty element" "$work/emptyel/t.err"
printf ':set speed 1,\n' >"$work/emptyel/v.keys"
(cd "$work/emptyel" && "$bin" --replay=v.keys --no-clock visco -N 100 --force </dev/null >/dev/null 2>v.err)
check "... and the speeds: '1,' ($(cat "$work/emptyel/v.err"))" \
    grep -qF "v.keys:1: speed: '1,' has an empty element" "$work/emptyel/v.err"

# A cycle run at a time tolerance looser than the default is marked on the
# screen as --batch marks it (it said 'cycle complete' and its numbers as
# though promised); at the default it is not.
mkdir -p "$work/loose"
printf ':set solver.time_tol 1e-2\nr :wait\n' >"$work/loose/l.keys"
printf 'r :wait\n' >"$work/loose/d.keys"
for k in l d; do
    (cd "$work/loose" && "$bin" --replay=$k.keys --screen=$k.screen --no-clock --material=sls --E0=1GPa --Einf=3GPa --tau=1s --mode=time -R 1um \
        -N 150 --spacing=2nm --turn=-1nm --speed=1nm/s </dev/null >/dev/null 2>$k.err)
done
check "a cycle at a loose time tolerance says unconverged and why, one at the default does not ($(grep -h -A1 'cycle complete' "$work/loose/l.screen" | head -c 300))" \
    sh -c "grep -q 'cycle complete' '$work/loose/l.screen' && grep -q 'unconverged: the time tolerance 0.01 is looser than 5e-05' '$work/loose/l.screen' && grep -q 'cycle complete' '$work/loose/d.screen' && ! grep -q unconverged '$work/loose/d.screen'"

# A narrow screen cuts a line of the state at a clause, else before the
# number whose unit would not fit: physical time's base line at 40 columns
# said 'approaching at 1 µ' (the speed 1 µm/s cut in its unit).
mkdir -p "$work/tnarrow"
printf '3f\nb\n' >"$work/tnarrow/n.keys"
(cd "$work/tnarrow" && "$bin" --replay=n.keys --screen=n.screen --no-clock --size=40x24 visco -N 100 --force </dev/null >/dev/null 2>&1)
check "physical time at 40 columns: the base's speed whole or not at all ($(grep '^  base' "$work/tnarrow/n.screen"))" \
    sh -c "grep -q '^  base ' '$work/tnarrow/n.screen' && ! grep '^  base ' '$work/tnarrow/n.screen' | grep -E 'at [0-9.]+' | grep -vqE 'm/s *\$'"

# A signal ends a replay cleanly with 128 + its number. Sent once the first
# step is solved (ADHERE_READY_FILE, see adhere(1)), not after a guessed sleep.
mkdir -p "$work/sig"
printf 'r :wait\n' >"$work/sig/long.keys"
(cd "$work/sig" && ADHERE_READY_FILE=ready exec "$bin" --replay=long.keys --screen=s.txt \
    </dev/null >/dev/null 2>err) &
pid=$!
i=0
while [ ! -e "$work/sig/ready" ] && kill -0 "$pid" 2>/dev/null && [ "$i" -lt 1200 ]; do sleep 0.05; i=$((i + 1)); done
check "a replay's first step creates \$ADHERE_READY_FILE" [ -e "$work/sig/ready" ]
kill -TERM "$pid" 2>/dev/null
wait "$pid"
rc=$?
check "SIGTERM during a solve exits 143 (128 + 15), as --batch (got $rc)" [ "$rc" = 143 ]
check "and says so" grep -q "stopped by signal 15" "$work/sig/err"

echo "1..$n"
[ "$failed" -eq 0 ]
