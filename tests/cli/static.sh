#!/bin/sh
# --mode=static writes the whole equilibrium S-curve with its stable column
# and the fold summary; --reference=static adds it beside a relaxation run.
. "$(dirname "$0")/lib.sh"

out="$TMP/static"
"$ADHERE" --batch -q --no-plot --mode=static -E 1GPa -N 200 --turn=-2nm -o "$out" 2>"$TMP/err"
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
"$ADHERE" --batch -q --no-plot -E 1GPa -N 100 --eps=3pm --turn=-2nm --reference=static -o "$ref" 2>"$TMP/err"
rc=$?
check "relaxation with --reference=static exits 0 (got $rc)" [ "$rc" -eq 0 ]
check "static.tsv is written beside force.tsv" [ -s "$ref/static.tsv" ]
check "summary.tsv has static_pulloff_F" grep -q "^static_pulloff_F	" "$ref/summary.tsv"
rp=$(val pulloff_F "$ref/summary.tsv"); sp=$(val static_pulloff_F "$ref/summary.tsv")
check "the relaxation pull-off $rp is at least as strong as the static one $sp (dynamic hysteresis)" awk "BEGIN {exit !($rp <= $sp * 0.99)}"
done_testing
