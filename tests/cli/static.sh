#!/bin/sh
# --mode=static writes the whole equilibrium S-curve with its stable column
# and the fold summary; --reference=static adds it beside a relaxation run.
. "$(dirname "$0")/lib.sh"

out="$TMP/static"
"$ADHERE" --batch -q --no-plot --mode=static -E 1GPa -N 200 --force --turn=-2nm -o "$out" 2>"$TMP/err"
rc=$?
check "static run exits 0 (got $rc: $(head -c 200 "$TMP/err"))" [ "$rc" -eq 0 ]
for key in jump_in_h0 jump_out_h0 pulloff_F pulloff_F_disp folds; do
    check "summary.tsv has $key" grep -q "^$key	" "$out/summary.tsv"
done
val() { awk -F'\t' -v k="$1" '$1 == k {print $2}' "$2"; }
jin=$(val jump_in_h0 "$out/summary.tsv"); jout=$(val jump_out_h0 "$out/summary.tsv")
pull=$(val pulloff_F "$out/summary.tsv"); disp=$(val pulloff_F_disp "$out/summary.tsv")
folds=$(val folds "$out/summary.tsv"); jkr=$(val F_jkr "$out/summary.tsv"); dmt=$(val F_dmt "$out/summary.tsv")
check "the surfaces jump out ($jout) further than they jump in ($jin): equilibrium hysteresis" awk "BEGIN {exit !($jout > $jin && $jin > 0)}"
check "at least the two folds of jump-in and jump-out ($folds)" [ "$folds" -ge 2 ]
check "load-controlled pull-off $pull N lies between JKR $jkr and 1.1 x DMT $dmt (sigma = 2.25)" \
    awk "BEGIN {exit !($pull < 0.95 * $jkr && $pull > 1.1 * $dmt)}"
check "the displacement-controlled pull-off $disp is weaker than the load-controlled one $pull" awk "BEGIN {exit !($disp > $pull)}"
check "force.tsv marks stable and unstable points" sh -c "grep -v '^#' '$out/force.tsv' | awk -F'\t' 'NR>1 {s[\$11]++} END {exit !(s[0] > 0 && s[1] > 0)}'"
check "the minimum force in force.tsv is the pull-off" sh -c "grep -v '^#' '$out/force.tsv' | awk -F'\t' -v p=$pull 'NR>1 && \$2 < m {m = \$2} END {exit !(m >= p * 1.0001 && m <= p * 0.98)}'"

ref="$TMP/ref"
"$ADHERE" --batch -q --no-plot -E 1GPa -N 100 --force --eps=3pm --turn=-2nm --reference=static -o "$ref" 2>"$TMP/err"
rc=$?
check "relaxation with --reference=static exits 0 (got $rc)" [ "$rc" -eq 0 ]
check "static.tsv is written beside force.tsv" [ -s "$ref/static.tsv" ]
check "summary.tsv has static_pulloff_F" grep -q "^static_pulloff_F	" "$ref/summary.tsv"
rp=$(val pulloff_F "$ref/summary.tsv"); sp=$(val static_pulloff_F "$ref/summary.tsv")
check "the relaxation pull-off $rp is at least as strong as the static one $sp (dynamic hysteresis)" awk "BEGIN {exit !($rp <= $sp * 0.99)}"
rh=$(val hysteresis "$ref/summary.tsv"); sh=$(val static_hysteresis "$ref/summary.tsv")
check "summary.tsv has the relaxation's hysteresis $rh J and the static curve's $sh J, smaller (no slower drive removes it)" \
    awk "BEGIN {exit !($rh > 0 && $sh > 0 && $sh < $rh)}"
check "on the -N 100 grid the static reference is not resolved: static_resolved 0, and said on stderr" \
    sh -c "[ '$(val static_resolved "$ref/summary.tsv")' = 0 ] && grep -q 'static reference curve is not resolved' '$TMP/err'"
check "static mode's summary.tsv has the equilibrium loop's hysteresis" \
    awk "BEGIN {exit !($(val hysteresis "$out/summary.tsv") > 0)}"
# With the grid chosen for the relaxation, the reference gets the static
# curve's own resolved grid (0.3 l, not the relaxation's 0.45 l); --plan says which.
"$ADHERE" --plan --reference=static >"$TMP/plan" 2>"$TMP/err"
check "--plan --reference=static names the reference's own resolved grid" \
    grep -q "^reference: the static curve on its own uniform grid of [0-9]* nodes .*: resolved" "$TMP/plan"
"$ADHERE" --plan --reference=static -N 1000 >"$TMP/plan" 2>"$TMP/err"
check "and with -N 1000 (the relaxation's grid, 0.43 l) says it is not resolved" \
    grep -q "^reference: the static curve on the relaxation's uniform grid of 1000 nodes .*: NOT resolved" "$TMP/plan"
# A sweep in mode = static: each run is the whole curve, in parallel; the
# runs' summaries and sweep.tsv carry the static keys.
cat >"$TMP/static-sweep.scene" <<'SCENE'
[scene]
title = three moduli, equilibrium curves
mode = static
[protocol]
turns = -2nm
[output]
plots = none
[sweep]
E = 1GPa, 2GPa, 4GPa
jobs = 2
SCENE
sw="$TMP/static-sweep"
"$ADHERE" --batch "$TMP/static-sweep.scene" -N 200 --force -o "$sw" >"$TMP/stdout" 2>"$TMP/err"
rc=$?
nruns=$(grep -c '^adhere: run [0-9]* of ' "$TMP/err")
check "each sweep run says how many are done, the share and the time left ($nruns runs)" \
    sh -c "[ $nruns -ge 2 ] && grep -q '; $nruns of $nruns done, 100 %' '$TMP/err' && grep -q 'done, *[0-9]* %, about .* left' '$TMP/err'"
check "and a closing line says where sweep.tsv and the runs went" grep -q "^adhere: done in .*: $nruns runs; sweep.tsv.* in $sw/" "$TMP/err"
check "a static sweep exits 0 (got $rc: $(head -c 300 "$TMP/err"))" [ "$rc" -eq 0 ]
# scol NAME: the column of sweep.tsv named NAME
scol() { grep -v '^#' "$sw/sweep.tsv" | head -1 | tr '\t' '\n' | grep -nx "$1" | cut -d: -f1; }
srow() { grep -v '^#' "$sw/sweep.tsv" | awk -F'\t' -v r="$1" -v c="$(scol "$2")" '$1 == r {print $c}'; }
check "static sweep: three rows in sweep.tsv" [ "$(grep -v '^#' "$sw/sweep.tsv" | tail -n +2 | wc -l)" -eq 3 ]
for key in jump_in_h0 jump_out_h0 pulloff_F pulloff_F_disp folds; do
    check "static sweep: sweep.tsv has column $key" [ -n "$(scol $key)" ]
done
jkr=$(val F_jkr "$sw/run-1/summary.tsv"); dmt=$(val F_dmt "$sw/run-1/summary.tsv")
for r in 1 2 3; do
    s="$sw/run-$r/summary.tsv"
    check "static sweep run-$r wrote force.tsv and summary.tsv in mode static" \
        sh -c "[ -s '$sw/run-$r/force.tsv' ] && grep -qx 'mode	static' '$s'"
    for key in jump_in_h0 jump_out_h0 pulloff_F pulloff_F_disp folds; do
        check "static sweep run-$r: summary.tsv has $key, as sweep.tsv ($(val $key "$s"))" \
            awk -v a="$(val $key "$s")" -v b="$(srow $r $key)" 'BEGIN {exit !(a != "" && a == b)}'
    done
    pull=$(srow $r pulloff_F) disp=$(srow $r pulloff_F_disp) jin=$(srow $r jump_in_h0) jout=$(srow $r jump_out_h0)
    # the coarse grid (N = 200, 7.5 nm) moves pull-off by a few per cent
    check "static sweep run-$r: pull-off $pull N lies between 0.98 x JKR $jkr and 1.05 x DMT $dmt" \
        awk "BEGIN {exit !($pull < 0.98 * $jkr && $pull > 1.05 * $dmt)}"
    check "static sweep run-$r: finite jumps, out ($jout) beyond in ($jin), displacement pull-off $disp weaker" \
        awk "BEGIN {exit !($jin > 0 && $jout > $jin && $disp < 0 && $disp > $pull)}"
    # sweep.tsv's status is the run's summary.tsv's: success, or unresolved
    # where -N 200 is coarser than the limit (resolved 0)
    want=success
    [ "$(val resolved "$s")" = 0 ] && want=unresolved
    check "static sweep run-$r: at least two folds ($(srow $r folds)), status $want, as its summary.tsv's" \
        sh -c "[ '$(srow $r folds)' -ge 2 ] && [ '$(srow $r status)' = $want ] && [ '$(val status "$s")' = $want ]"
done
check "static sweep: each run's sigma is its E's (sigma halves as E doubles)" \
    awk -v a="$(srow 1 sigma)" -v b="$(srow 2 sigma)" -v c="$(srow 3 sigma)" \
    'BEGIN {exit !(a / b > 1.999999 && a / b < 2.000001 && b / c > 1.999999 && b / c < 2.000001)}'
"$ADHERE" --batch -q "$TMP/static-sweep.scene" -N 200 --force >"$TMP/stdout" 2>"$TMP/err"
check "a static sweep without --out prints sweep.tsv with the static columns" \
    sh -c "grep -v '^#' '$TMP/stdout' | head -1 | tr '\t' '\n' | grep -qx pulloff_F_disp"
sed 's/^E = .*/eps = 1pm, 2pm/' "$TMP/static-sweep.scene" >"$TMP/eps-static.scene"
"$ADHERE" --batch -q "$TMP/eps-static.scene" -N 200 --force -o "$TMP/eps-static" >/dev/null 2>"$TMP/err"
rc=$?
check "an eps sweep in mode = static is refused with exit 2, saying why (got $rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'same curve 2 times' '$TMP/err'"
# The command that stopped with "continuation could not make progress" (a
# corrector step past the turn, tests/unit/test_static_skip.c): it ends at
# the turn, with the jumps and pull-off of a finished curve.
"$ADHERE" --batch -q --mode=static fig1 -N 200 --spacing=3.4nm --turn=-2.25nm -o "$TMP/land" >/dev/null 2>"$TMP/err"
rc=$?
last=$(grep -v '^#' "$TMP/land/force.tsv" | tail -1 | cut -f1)
check "fig1 static at N = 200, 3.4 nm, turn -2.25 nm: exit 0, ends at the turn ($rc, last h0 $last: $(head -c 200 "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && awk 'BEGIN {exit !($last > -2.2501e-9 && $last < -2.2499e-9)}' && grep -qx 'status	success' '$TMP/land/summary.tsv'"
# From inside the snap-in (0.3 nm, the jump-in is at $jin m) the
# equilibrium is a contact on the curve's inner branch: the curve starts
# there (it stopped after 0 steps, exit 1: Newton from the undeformed
# surfaces did not converge). Its first row is at the start, in contact,
# with the force of the curve from the automatic start through that h0
# (its last crossing going in, linear between rows).
S="--batch -q --no-plot --mode=static -E 1GPa --force --turn=-2nm"
# shellcheck disable=SC2086
"$ADHERE" $S -N 400 -o "$TMP/far" 2>"$TMP/err"
# shellcheck disable=SC2086
"$ADHERE" $S -N 400 --start=0.3nm -o "$TMP/inner" 2>"$TMP/err"
rc=$?
first=$(grep -v '^#' "$TMP/inner/force.tsv" | sed -n 2p | cut -f1,2,4)
Fc=$(grep -v '^#' "$TMP/far/force.tsv" | awk -F'\t' 'NR > 2 && p > 3e-10 && $1 <= 3e-10 {F = pF + ($2 - pF) * (3e-10 - p) / ($1 - p)}
                                                     NR > 1 {p = $1; pF = $2} END {print F}')
check "static from 0.3 nm: exit 0, the first row at 0.3 nm in contact, its force the curve's there, $Fc N ($rc: $first: $(head -c 300 "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && echo '$first' | awk -v Fc='$Fc' '{exit !(\$1 > 2.9999e-10 && \$1 < 3.0001e-10 && \$3 < 1.1 * 5e-10 &&
                                                               (\$2 / Fc - 1)^2 < 0.005^2)}'"
# A curve that stops says why, not only the status words: the static
# curve's cap on points (solver.max_points = 10, a scene's key), the one
# stop every CPU reaches alike (the stall this provoked before depended on
# rounding: the reference BLAS completed the curve). stderr and
# summary.tsv's # PARTIAL line name where it was and where it was going;
# summary.tsv keeps its status line and adds stop_reason after it; a
# study's status column says "status: reason", and a rerun reads its rows
# back.
# the cap's own range: 2 points to the solver's 200000, refused by the value
for v in 1 200001; do
    printf '[solver]\nmax_points = %s\n' "$v" >"$TMP/capbad.scene"
    "$ADHERE" --batch -q --no-plot --mode=static "$TMP/capbad.scene" -o "$TMP/capbad" 2>"$TMP/err"
    rc=$?
    check "max_points = $v: exit 2, the range named, nothing written ($rc: $(head -c 200 "$TMP/err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q ': max_points: $v points is not allowed: from 2 to 200000\$' '$TMP/err' && [ ! -e '$TMP/capbad' ]"
done
printf '[solver]\nmax_points = 10\n' >"$TMP/cap.scene"
# shellcheck disable=SC2086
"$ADHERE" $S -N 200 "$TMP/cap.scene" -o "$TMP/stop" 2>"$TMP/err"
rc=$?
why="the static curve reached its cap of 10 points at h0 = [^ ]* nm, before its end h0 = -2 nm"
check "static capped at 10 points on 200 nodes: exit 1, stderr says why ($rc: $(tail -n 1 "$TMP/err"))" \
    sh -c "[ $rc -eq 1 ] && grep -qx \"adhere: the solver stopped after 10 steps: iteration cap reached before convergence: $why\" '$TMP/err'"
check "... summary.tsv: # PARTIAL says it, status unchanged, then stop_reason, last" \
    sh -c "grep -q \"^# PARTIAL: the solver stopped after 10 steps: iteration cap reached before convergence: $why\" '$TMP/stop/summary.tsv' &&
           tail -n 2 '$TMP/stop/summary.tsv' | head -n 1 | grep -qx 'status	iteration cap reached before convergence' &&
           tail -n 1 '$TMP/stop/summary.tsv' | grep -qx \"stop_reason	$why\""
check "a finished run has no stop_reason line" sh -c "! grep -q '^stop_reason' '$out/summary.tsv' '$TMP/inner/summary.tsv'"
# shellcheck disable=SC2086
"$ADHERE" $S -N 200 "$TMP/cap.scene" --sweep=start=10nm,12nm --run-dirs=no -o "$TMP/stops" 2>"$TMP/err"
rc=$?
check "a study of such starts: exit 1, the row that stopped says why ($rc: $(grep -v '^#' "$TMP/stops/sweep.tsv" | sed -n 2p | awk -F'\t' '{print $NF}'))" \
    sh -c "[ $rc -eq 1 ] && grep -v '^#' '$TMP/stops/sweep.tsv' | sed -n 2p | awk -F'\t' '{print \$NF}' |
           grep -qx \"iteration cap reached before convergence: $why\""
# with run-K directories (the default up to 32 runs) the row takes the
# word its run's summary.tsv said: that word was held in 32 bytes, and the
# status column said 'iteration cap reached before co: ...'
# shellcheck disable=SC2086
"$ADHERE" $S -N 200 "$TMP/cap.scene" --sweep=start=10nm,12nm --run-dirs=yes -o "$TMP/stopsd" 2>"$TMP/err"
rc=$?
check "... with run-K directories: the status word whole, as in run-K's summary.tsv ($rc: $(grep -v '^#' "$TMP/stopsd/sweep.tsv" | sed -n 2p | awk -F'\t' '{print $NF}' | cut -c1-60))" \
    sh -c "[ $rc -eq 1 ] && grep -v '^#' '$TMP/stopsd/sweep.tsv' | sed -n 2p | awk -F'\t' '{print \$NF}' |
           grep -qx \"iteration cap reached before convergence: $why\" &&
           grep -qx 'status	iteration cap reached before convergence' '$TMP/stopsd/run-1/summary.tsv'"
cp "$TMP/stops/sweep.tsv" "$TMP/stops.before"
# shellcheck disable=SC2086
"$ADHERE" $S -N 200 "$TMP/cap.scene" --sweep=start=10nm,12nm --run-dirs=no -o "$TMP/stops" 2>"$TMP/err"
rc=$?
check "... a rerun reads those rows back: the same sweep.tsv, exit 1 ($rc: $(head -c 300 "$TMP/err"))" \
    sh -c "[ $rc -eq 1 ] && cmp -s '$TMP/stops.before' '$TMP/stops/sweep.tsv'"
"$ADHERE" merge -q "$TMP/stops" -o "$TMP/stops-merged" 2>"$TMP/err"
rc=$?
check "... adhere merge keeps the reasons: the same rows ($rc: $(head -c 300 "$TMP/err"))" \
    sh -c "[ $rc -le 1 ] && grep -v '^#' '$TMP/stops.before' >'$TMP/m1' && grep -v '^#' '$TMP/stops-merged/sweep.tsv' >'$TMP/m2' &&
           cmp -s '$TMP/m1' '$TMP/m2'"
# A curve with no point at all (the way to its start stopped by the cap
# on points) has no pull-off: nan in summary.tsv, not the least force of
# no rows, inf
printf '[solver]\nmax_points = 8\n' >"$TMP/cap8.scene"
"$ADHERE" --batch --mode=static -E 10GPa --start=0.6nm -N 200 --force --no-plot -q -o "$TMP/nopoint" "$TMP/cap8.scene" 2>"$TMP/err"
rc=$?
check "a static curve stopped before its first point: exit 1, points 0 and pulloff_F nan ($rc: $(grep -E '^(points|pulloff_F)	' "$TMP/nopoint/summary.tsv" | tr '\n\t' '  '))" \
    sh -c "[ $rc -eq 1 ] && grep -qx 'points	0' '$TMP/nopoint/summary.tsv' && grep -qx 'pulloff_F	nan' '$TMP/nopoint/summary.tsv'"
done_testing
