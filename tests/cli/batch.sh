#!/bin/sh
# A batch run writes the tables the core issue names, with their columns and
# keys; without --out the force table streams to standard output (signals: signals.sh).
. "$(dirname "$0")/lib.sh"

out="$TMP/run"
"$ADHERE" --batch -q --no-plot -N 100 --force --eps=3pm --turn=-2nm -o "$out" >"$TMP/stdout" 2>"$TMP/stderr"
rc=$?
check "batch run exits 0 (got $rc: $(head -c 300 "$TMP/stderr"))" [ "$rc" -eq 0 ]
header=$(grep -v '^#' "$out/force.tsv" | head -1)
for col in h0 F delta hc a iters branch F_rigid converged; do
    check "force.tsv has column $col" sh -c "printf '%s\n' '$header' | tr '\t' '\n' | grep -qx '$col'"
done
for key in sigma gamma mu jump_in_h0 max_load pulloff_F jump_out_h0 iterations seconds converged; do
    check "summary.tsv has key $key" grep -q "^$key	" "$out/summary.tsv"
done
check "summary says converged 1" grep -qx "converged	1" "$out/summary.tsv"
check "summary sigma is 7.50 for the default scene" awk -F'\t' '$1=="sigma" && $2>7.49 && $2<7.51 {f=1} END {exit !f}' "$out/summary.tsv"
check "both branches are in force.tsv" sh -c "grep -v '^#' '$out/force.tsv' | cut -f8 | sort -u | tr '\n' ' ' | grep -q -- '+1' && grep -v '^#' '$out/force.tsv' | cut -f8 | grep -q -- '-1'"
check "numbers are written at full precision" awk -F'\t' 'NR>4 && length($1) >= 15 {f=1} END {exit !f}' "$out/force.tsv"
check "no temporary files are left" sh -c "! ls -a '$out' | grep -q tmp"
check "turns.tsv names the turning point" awk -F'\t' '!/^#/ && NR>3 && $1 < -1.99e-9 && $1 > -2.01e-9 {f=1} END {exit !f}' "$out/turns.tsv"

# What a run says on a terminal: a progress line with the plan's total, the
# share done and the time left; one closing line; -q hides both but not a
# warning that changes what the numbers mean.
if command -v script >/dev/null 2>&1; then
    script -qc "'$ADHERE' --batch --no-plot -N 100 -E 3GPa --spacing=10nm --eps=10pm --step=0.25nm --turn=-2nm -o '$TMP/tty'" \
        "$TMP/typescript" >/dev/null 2>&1
    tr '\r' '\n' <"$TMP/typescript" >"$TMP/tty.txt"
    check "in a terminal the progress line gives step, the planned total, percentage and time left" \
        grep -Eq '^  (loading|unloading) +step [0-9]+ of <=[0-9]+ +[0-9]+ %, about [0-9.]+ (s|min).* left' "$TMP/tty.txt"
else
    ok "# SKIP no script(1) to give the run a terminal"
fi
"$ADHERE" --batch -N 100 -E 3GPa --spacing=10nm --eps=10pm --step=0.25nm --turn=-2nm -o "$TMP/close" >"$TMP/stdout" 2>"$TMP/stderr"
check "without -q a run ends with one line: seconds, pull-off, jumps, where the files went" \
    sh -c "[ \$(wc -l <'$TMP/stderr') -eq 1 ] && grep -Eq '^adhere: done in [0-9.]+ s: pull-off -[0-9.]+ nN, jump-in [0-9.]+ nm, jump-out [0-9.]+ nm, hysteresis [0-9.]+ [afpnum]?J; wrote force.tsv, summary.tsv, turns.tsv, force.png.* in $TMP/close' '$TMP/stderr'"
check "and no progress line when stderr is not a terminal" sh -c "! grep -q 'step [0-9]* of' '$TMP/stderr'"
"$ADHERE" --batch -q --no-plot -N 100 -E 3GPa --spacing=10nm --eps=10pm --step=0.25nm --turn=-2nm -o "$TMP/close" >"$TMP/stdout" 2>"$TMP/stderr"
check "-q prints nothing on success" [ ! -s "$TMP/stderr" ]
"$ADHERE" --batch -q --no-plot -N 100 -E 3GPa --spacing=10nm --eps=10pm --step=0.25nm --turn=-2nm --max-iter=50 -o "$TMP/cap" >"$TMP/stdout" 2>"$TMP/stderr"
check "-q still warns when steps hit the iteration cap ($(head -c 120 "$TMP/stderr"))" \
    grep -q "^adhere: warning: [0-9]* of [0-9]* steps reached the iteration cap (50)" "$TMP/stderr"

# Standard output when there is no --out.
"$ADHERE" --batch -q -N 100 --force --eps=3pm --turn=none >"$TMP/stdout" 2>"$TMP/stderr"
rc=$?
check "stdout run exits 0" [ "$rc" -eq 0 ]
check "the force table goes to stdout with its header" grep -q "^h0	F	delta" "$TMP/stdout"
rows=$(grep -cv '^#' "$TMP/stdout")
check "precontact run stops at the jump into contact ($rows lines)" [ "$rows" -gt 100 ]
last_a=$(grep -v '^#' "$TMP/stdout" | tail -1 | cut -f5)
check "its last row is in contact (a = $last_a)" awk "BEGIN {exit !($last_a > 0)}"

# A write that fails (full disk): said, not swallowed.
"$ADHERE" --batch -q -N 100 --force --eps=10pm --turn=none >/dev/full 2>"$TMP/stderr"
rc=$?
check "a force table streamed to a full disk exits 2 and says so ($(cat "$TMP/stderr"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'No space left on device' '$TMP/stderr'"

# Only the plot tables asked for: no contact-line table without the contact plot.
"$ADHERE" --batch -q --no-plot --plots=force -N 100 --force --eps=10pm --turn=-1nm -o "$TMP/only" 2>/dev/null
check "--plots=force writes no contact.tsv and no profiles.tsv" sh -c "[ -s '$TMP/only/force.tsv' ] && [ ! -e '$TMP/only/contact.tsv' ] && [ ! -e '$TMP/only/profiles.tsv' ]"

# Signals (SIGINT halfway, partial tables, exit 130): tests/cli/signals.sh,
# which waits for the phase to begin instead of sleeping.
# The grid's resolution: an explicit grid coarser than the limit is refused
# without --force; with it the run warns (even with -q) and says resolved 0.
"$ADHERE" --batch -q --no-plot -N 100 --eps=3pm --turn=-2nm -o "$TMP/refused" >/dev/null 2>"$TMP/stderr"
rc=$?
check "an unresolved explicit grid is refused with exit 2 ($rc)" sh -c "[ $rc -eq 2 ] && grep -q 'coarser than the resolved limit' '$TMP/stderr' && grep -q -- '--force' '$TMP/stderr' && [ ! -e '$TMP/refused/summary.tsv' ]"
"$ADHERE" --batch -q --no-plot -N 100 --force --eps=3pm --turn=-2nm -o "$TMP/forced" >/dev/null 2>"$TMP/stderr.force"
check "--force: the warning is on stderr even with -q" grep -q "warning: grid spacing .* resolved 0" "$TMP/stderr.force"
check "--force: summary.tsv says resolved 0 and status unresolved" sh -c "grep -qx 'resolved	0' '$TMP/forced/summary.tsv' && grep -qx 'status	unresolved' '$TMP/forced/summary.tsv'"
check "summary.tsv has edge_nodes below the limit's 2.2" awk -F'\t' '$1=="edge_nodes" && $2>0 && $2<2.2 {f=1} END {exit !f}' "$TMP/forced/summary.tsv"
check "summary.tsv has rmax_force_fraction, 1 to 3 % for this grid" awk -F'\t' '$1=="rmax_force_fraction" && $2>0.01 && $2<0.03 {f=1} END {exit !f}' "$TMP/forced/summary.tsv"
# Unloading goes on past the start while the surfaces still touch: a start
# inside the neck's reach (3 nm; the jump-out is near 11 nm here) changes
# neither the pull-off nor the jump-out of the run from the automatic start.
"$ADHERE" --batch -q --no-plot -N 100 --force --eps=3pm --start=3nm --turn=-1nm -o "$TMP/past" >/dev/null 2>"$TMP/stderr"
rc=$?
"$ADHERE" --batch -q --no-plot -N 100 --force --eps=3pm --turn=-1nm -o "$TMP/auto" >/dev/null 2>&1
check "unloading past the start separates: exit 0 ($rc), complete 1, jump-out beyond 3 nm" sh -c "[ $rc -eq 0 ] && grep -qx 'complete	1' '$TMP/past/summary.tsv' && awk -F'\t' '\$1==\"jump_out_h0\" && \$2>3e-9 {f=1} END {exit !f}' '$TMP/past/summary.tsv'"
check "its last row is out of contact and past the start" awk -F'\t' '!/^#/ && $1!="h0" {h=$1; a=$5; b=$8} END {exit !(b==-1 && a==0 && h>3e-9)}' "$TMP/past/force.tsv"
check "jump-out within a step (0.05 nm) and pull-off within 0.1 % of the automatic start's" awk -F'\t' '
    FNR==1 {f++} $1=="jump_out_h0" {j[f]=$2} $1=="pulloff_F" {p[f]=$2}
    END {d=j[1]-j[2]; if (d<0) d=-d; r=(p[1]-p[2])/p[2]; if (r<0) r=-r; exit !(j[1]>0 && d<=0.05e-9+1e-15 && r<1e-3)}' "$TMP/past/summary.tsv" "$TMP/auto/summary.tsv"
# It stops at the model's reach (0.02 R; h0 must stay << R): a small, soft
# sphere (R = 500 nm, sigma = 17), started at 5 nm, still in contact at 10 nm
# never separated:
# complete 0, said on stderr and in summary.tsv.
"$ADHERE" --batch -q --no-plot -R 500nm -E 0.03GPa -N 100 --force --eps=3pm --start=5nm --turn=-1nm -o "$TMP/stuck" >/dev/null 2>"$TMP/stderr"
rc=$?
check "a run that never separates still exits 0 ($rc) and says why on stderr" sh -c "[ $rc -eq 0 ] && grep -q 'incomplete: the surfaces never separated' '$TMP/stderr'"
check "its summary.tsv says complete 0, status not separated, and why" sh -c "grep -qx 'complete	0' '$TMP/stuck/summary.tsv' && grep -qx 'status	not separated' '$TMP/stuck/summary.tsv' && grep -q '^# INCOMPLETE: the surfaces never separated' '$TMP/stuck/summary.tsv'"
check "it unloaded past its start (5 nm) to the reach, 10 nm, and no further" awk -F'\t' '!/^#/ && $1!="h0" && $8==-1 {m=$1} END {exit !(m>9.99e-9 && m<10.01e-9)}' "$TMP/stuck/force.tsv"
done_testing
