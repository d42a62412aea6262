#!/bin/sh
# Shipped scenes end to end at reduced N and looser eps (seconds each):
# Figures 1 and 4 (the issue's two), Figure 2, Figure 3's sigma sweep, a
# small eps sweep like Figure 7's, and a rigid-only run.
. "$(dirname "$0")/../cli/lib.sh"

run() { # run NAME DIR [flags...]
    name=$1 dir=$2; shift 2
    "$ADHERE" --batch -q "$name" -N 100 --force --eps=3pm -o "$dir" "$@" >"$TMP/stdout" 2>"$TMP/stderr"
    rc=$?
    check "adhere --batch $name -N 100 --force --eps=3pm $* exits 0 (got $rc: $(head -c 300 "$TMP/stderr"))" [ "$rc" -eq 0 ]
}
rows() { grep -v '^#' "$1" | tail -n +2; }          # the data rows of a table
summary() { awk -F'\t' -v k="$2" '$1 == k {print $2}' "$1/summary.tsv"; }

# Figure 4: profiles at the ten positions on both branches, force and profile plots.
d="$TMP/fig4"
run fig4 "$d"
for f in force.tsv summary.tsv turns.tsv profiles.tsv force.png profile.png; do
    check "fig4 wrote $f" [ -s "$d/$f" ]
done
check "fig4 drew no contact figure (not asked)" [ ! -e "$d/contact.png" ]
check "fig4 summary: converged 1" grep -qx "converged	1" "$d/summary.tsv"
check "fig4 summary: total iterations and seconds" awk -F'\t' '$1=="iterations" && $2>0 {i=1} $1=="seconds" && $2>0 {s=1} END {exit !(i && s)}' "$d/summary.tsv"
for h in -5 -3.5 -2 -0.5 1 2.5 4 5.5 7 8.5; do
    check "fig4 profile at h0 = $h nm on loading and unloading" awk -F'\t' -v h="$h" \
        '!/^#/ && $1+0 == $1 && ($1*1e9 - h)^2 < 1e-6 {b[$2]=1} END {exit !(b[1] && b[-1])}' "$d/profiles.tsv"
done
n=$(rows "$d/profiles.tsv" | cut -f1,2 | awk -F'\t' '{printf "%.4f %s\n", $1*1e9, $2}' | sort -u | wc -l)
check "fig4 stored profiles only at the positions asked ($n position-branch pairs, want 20)" [ "$n" -eq 20 ]
planned=$("$ADHERE" --plan fig4 -N 100 --force --eps=3pm | sed -n 's/^loading branches: 1 (from .* to -5 nm, \([0-9]*\) steps)$/\1/p')
loaded=$(rows "$d/force.tsv" | awk -F'\t' '$9 == 0' | wc -l)
check "fig4: the plan's loading steps are the run's ($planned planned, $loaded run)" [ "$planned" = "$loaded" ]
bound=$("$ADHERE" --plan fig4 -N 100 --force | sed -n 's/^steps: .* + at most \([0-9]*\) unloading to the start (more if the surfaces still touch there)$/\1/p')
unloaded=$(rows "$d/force.tsv" | awk -F'\t' '$9 != 0' | wc -l)
check "fig4 separates before the start: the unloading stays within the plan's steps to it ($unloaded <= $bound)" [ "$unloaded" -le "$bound" ]
check "fig4 turns at -5 nm" awk -F'\t' '!/^#/ && $1+0 == $1 && $1 < -4.99e-9 && $1 > -5.01e-9 {f=1} END {exit !f}' "$d/turns.tsv"

# Figure 1: approach into contact to -2 nm, no unloading, the eq 23 inset.
d="$TMP/fig1"
run fig1 "$d"
for f in force.tsv summary.tsv force.png precontact.png; do
    check "fig1 wrote $f" [ -s "$d/$f" ]
done
check "fig1 has no unloading row" sh -c "! grep -v '^#' '$d/force.tsv' | cut -f8 | grep -q -- '-1'"
last=$(rows "$d/force.tsv" | tail -1 | cut -f1)
check "fig1 loads to h0 = -2 nm (last row $last)" awk "BEGIN {exit !($last < -1.99e-9 && $last > -2.01e-9)}"
check "fig1 jumped into contact on the way" awk -F'\t' '$1=="jump_in_h0" && $2 > 0 && $2 < 5e-9 {f=1} END {exit !f}' "$d/summary.tsv"
check "fig1: attraction before contact exceeds the rigid one (bulge)" awk -F'\t' \
    '!/^#/ && $1+0 == $1 && $5 == 0 && $1 < 4e-9 && $1 > 2.5e-9 && $2 < $12 {f=1} END {exit !f}' "$d/force.tsv"

# Figure 2: stops at the jump into contact; the bulge figure.
d="$TMP/fig2"
run fig2 "$d"
check "fig2 wrote bulge.png" [ -s "$d/bulge.png" ]
incontact=$(rows "$d/force.tsv" | awk -F'\t' '$5 > 0' | wc -l)
check "fig2 stops at the jump: one row in contact ($incontact)" [ "$incontact" -eq 1 ]
est=$("$ADHERE" --plan fig2 -N 100 --force | sed -n 's/.*ends at the jump into contact, about \([0-9]*\) steps)$/\1/p')
got=$(rows "$d/force.tsv" | wc -l)
check "fig2: the plan's estimate of the steps to the jump is within 10% ($est planned, $got run)" awk "BEGIN {exit !($est > 0.9 * $got && $est < 1.1 * $got)}"
check "fig2 has no turns.tsv" [ ! -e "$d/turns.tsv" ]

# Figure 3: the sigma sweep, in parallel, one row per run.
d="$TMP/fig3"
run fig3 "$d"
n=$(rows "$d/sweep.tsv" | wc -l)
check "fig3 sweep.tsv has 13 rows ($n)" [ "$n" -eq 13 ]
for k in 1 7 13; do
    check "fig3 run-$k has its own force.tsv and summary.tsv" [ -s "$d/run-$k/force.tsv" -a -s "$d/run-$k/summary.tsv" ]
done
check "fig3 runs draw no figure of their own (plots = none)" sh -c "! ls '$d'/run-*/*.png >/dev/null 2>&1"
check "fig3 wrote jump.png" [ -s "$d/jump.png" ]
header=$(grep -v '^#' "$d/sweep.tsv" | head -1)
for col in value sigma jump_in_h0 h_before h_star pulloff_F iterations seconds jumped; do
    check "sweep.tsv has column $col" sh -c "printf '%s\n' '$header' | tr '\t' '\n' | grep -qx '$col'"
done
check "fig3: for sigma >= 1 the jump gap is within 25% of eq 24" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 && \$5 >= 1 {n++; r = \$8 / \$9; if (r < 0.75 || r > 1.25) bad = 1} END {exit bad || n < 5}'"
check "fig3: soft spheres jump, the hardest come into contact gradually" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 && \$5 >= 1 && \$16 != 1 {bad = 1} NR == 2 && \$16 != 0 {bad = 1} END {exit bad}'"
# The gap before the jump is sampled one drive step before the fold, where
# the gap falls steeply with h0, so it can dip between neighbouring sigmas;
# the jump position itself, and the gap over each factor of 3 in sigma, grow.
check "fig3: the jump position grows with sigma" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 && \$5 >= 0.3 {if (\$7 <= prev) bad = 1; prev = \$7} END {exit bad}'"
check "fig3: the jump gap grows with sigma (1, 3, 10, 30)" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 && (\$5 == 1 || \$5 == 3 || \$5 == 10 || \$5 == 30) {n++; if (\$8 <= prev) bad = 1; prev = \$8} END {exit bad || n != 4}'"
check "fig3: each run's sigma is the one it names" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 {r = \$5 / \$3; if (r < 0.999999 || r > 1.000001) bad = 1} END {exit bad}'"

# An eps sweep like Figure 7's, small enough for a test.
cat >"$TMP/eps.scene" <<'SCENE'
[scene]
title = two eps, one kernel
[protocol]
turns = 0nm
[output]
plots = none
[sweep]
eps = 8pm, 4pm
jobs = 2
plot = force
SCENE
d="$TMP/eps"
"$ADHERE" --batch -q "$TMP/eps.scene" -N 100 --force -o "$d" >"$TMP/stdout" 2>"$TMP/stderr"
rc=$?
check "an eps sweep runs (exit $rc: $(head -c 300 "$TMP/stderr"))" [ "$rc" -eq 0 ]
check "eps sweep: two rows in sweep.tsv" [ "$(rows "$d/sweep.tsv" | wc -l)" -eq 2 ]
check "eps sweep: each run unloads and has a pull-off" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR > 1 && \$11 < 0 {n++} END {exit n != 2}'"
check "eps sweep: the smaller eps takes more iterations" sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR == 2 {a = \$14} NR == 3 {b = \$14} END {exit !(b > a)}'"
e1=$(summary "$d/run-1" eps) e2=$(summary "$d/run-2" eps)
check "eps sweep: the runs' eps are 8 and 4 pm ($e1, $e2)" awk "BEGIN {exit !($e1 > 7.99e-12 && $e1 < 8.01e-12 && $e2 > 3.99e-12 && $e2 < 4.01e-12)}"
check "eps sweep: combined force.png" [ -s "$d/force.png" ]
check "eps sweep: every run's hysteresis in sweep.tsv (column 17), positive" \
    sh -c "grep -v '^#' '$d/sweep.tsv' | awk -F'\t' 'NR == 1 && \$17 != \"hysteresis\" {bad = 1} NR > 1 && !(\$17 > 0) {bad = 1} END {exit bad}'"
h1=$(grep -v '^#' "$d/sweep.tsv" | awk -F'\t' 'NR == 2 {print $17}') s1=$(summary "$d/run-1" hysteresis)
t1=$(awk -F'\t' '$1 + 0 == $1 && $7 == 1 {print $8}' "$d/run-1/turns.tsv")
check "eps sweep: run-1's summary.tsv and turns.tsv carry sweep.tsv's hysteresis ($h1, $s1, $t1)" \
    sh -c "[ -n '$h1' ] && [ '$s1' = '$h1' ] && [ '$t1' = '$h1' ]"
check "eps sweep drawn as Figure 7: sweep.tsv gives the static curve's loop for its equilibrium line" \
    grep -q "^# static_hysteresis: [0-9.e+-]* J" "$d/sweep.tsv"
"$ADHERE" --batch -q "$TMP/eps.scene" -N 100 --force >"$TMP/stdout" 2>"$TMP/stderr"
check "a sweep without --out prints sweep.tsv on stdout" sh -c "grep -v '^#' '$TMP/stdout' | head -1 | grep -q '^run	swept	value'"

# SIGINT during a sweep: every run stops, tables are written and say so.
# Sent once a first step is solved (ADHERE_READY_FILE, see adhere(1)); the
# paper's mixing rule keeps the runs going for minutes.
ADHERE_READY_FILE="$TMP/ready" "$ADHERE" --batch -q fig7 -N 100 --force --mixing=paper --no-plot -o "$TMP/int" \
    >/dev/null 2>"$TMP/stderr" &
pid=$!
check "a sweep's first step is announced in \$ADHERE_READY_FILE" wait_phase "$TMP/ready" step "$pid"
kill -INT $pid
wait $pid
rc=$?
check "SIGINT ends a sweep with status 130 (got $rc)" [ "$rc" -eq 130 ]
check "the interrupted sweep's sweep.tsv says interrupted" sh -c "grep -v '^#' '$TMP/int/sweep.tsv' | awk -F'\t' 'NR > 1 && \$NF != \"interrupted\" {bad = 1} NR > 1 {n++} END {exit bad || n != 3}'"
check "run-1/force.tsv is marked partial" grep -q "^# PARTIAL: interrupted" "$TMP/int/run-1/force.tsv"

# Rigid spheres: eq 22 at each position, no iteration at all.
d="$TMP/rigid"
run default "$d" --mode=rigid --turn=none --no-plot
check "rigid: zero iterations" grep -qx "iterations	0" "$d/summary.tsv"
check "rigid: every force is eq 22's" awk -F'\t' '!/^#/ && $1+0 == $1 {n++; if ($2 != $12) bad = 1} END {exit bad || n < 10}' "$d/force.tsv"
check "rigid: stops above h0 = 0" sh -c "grep -v '^#' '$d/force.tsv' | tail -1 | awk -F'\t' '{exit !(\$1 > 0)}'"

done_testing
