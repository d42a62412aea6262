#!/bin/sh
# make bench: adhere fit --model=time, what one curve at one speed
# determines. Curves of adhere's own physical-time run (E0 = 1 GPa, Einf =
# 3 GPa, A = 1e-19 J, R = 1 um, N = 150 at 2 nm, 1 nm/s to -1 nm, read every
# 0.05 nm with 0.66 nN of seeded noise: tests/cli/fittime.sh's) at tau from
# 0.01 to 100 s, each fitted from (1.3 E0, 0.8 A, 2.5 GPa, 0.7 tau): the
# values, their errors in standard errors, the flags; then the standard
# errors' honesty over seeds at tau = 1 s (BENCH_FITTIME_SEEDS, default 12).
# Times as ratios to one model evaluation (a --batch run of the curve) in
# the same session.
ADHERE=${ADHERE:-./adhere}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
G="-N 150 --spacing=2nm -R 1um"
# tests/cli/fittime.sh's reading of force.tsv (the rows' base and F, at every
# dx nm of the base, sd nN of seeded noise from tests/cli/drand48.awk)
awk '/^cat >"\$TMP\/sample.awk"/ {f = 1; next} /^EOF$/ {f = 0} f' "$(dirname "$0")/../cli/fittime.sh" >"$T/sample.awk"
DRAND48="$(dirname "$0")/../cli/drand48.awk"
now() { date +%s.%N; }
echo "adhere fit --model=time: one curve at 1 nm/s, 0.66 nN noise (z = (value - truth) / standard error)"
for tau in ${BENCH_FITTIME_TAUS:-0.01 0.1 1 4 10 100}; do
    t0=$(now)
    "$ADHERE" --batch -q --no-plot --material=sls --E0=1GPa --Einf=3GPa --tau=${tau}s --speed=1nm/s $G --turn=-1nm \
        --allow-unconverged -o "$T/gen$tau" 2>/dev/null
    t1=$(now)
    awk -v seed=7 -v sd=0.66 -v dx=0.05 -f "$DRAND48" -f "$T/sample.awk" "$T/gen$tau/force.tsv" >"$T/c$tau.tsv"
    start=$(awk -v t="$tau" 'BEGIN {print 0.7 * t}')
    "$ADHERE" fit -q --model=time --data="$T/c$tau.tsv" --material=sls --E0=1.3GPa --Einf=2.5GPa --tau=${start}s \
        -A 0.8e-19J --speed=1nm/s $G --no-plot -o "$T/f$tau" >"$T/f$tau.out" 2>/dev/null
    t2=$(now)
    awk -F'\t' -v tau="$tau" -v run="$(echo "$t1 - $t0" | bc)" -v fit="$(echo "$t2 - $t1" | bc)" '
        BEGIN {t["E0"] = 1e9; t["A"] = 1e-19; t["Einf"] = 3e9; t["tau"] = tau}
        /^# result:/ {sub(/^# result: /, ""); sub(/ \(.*/, ""); res = $0}
        /^# chi2/ {c = $0; sub(/.*against it /, "", c)}
        /^# model:/ {ev = $0; sub(/.*; /, "", ev); sub(/ model evaluations.*/, "", ev)}
        ($1 in t) {line = line sprintf("  %s %.4g (%+.1f %%, z %+.1f%s)", $1, $2, 100 * ($2 / t[$1] - 1), ($2 - t[$1]) / $3,
                   $6 == "-" ? "" : ", " $6)}
        END {printf "tau %s s:%s; chi2/dof %.3g; %s; %s evaluations, %.1f times one run\n", tau, line, c, res, ev,
             fit / run}' "$T/f$tau/fit.tsv"
    grep '^derived: creep' "$T/f$tau.out" | sed 's/^/    /'
done
echo
echo "the standard errors at tau = 1 s over seeds 1001..: rms and largest |z|"
"$ADHERE" --batch -q --no-plot --material=sls --E0=1GPa --Einf=3GPa --tau=1s --speed=1nm/s $G --turn=-1nm \
    -o "$T/gen" 2>/dev/null
seed=1001
last=$((1000 + ${BENCH_FITTIME_SEEDS:-12}))
while [ $seed -le $last ]; do
    awk -v seed=$seed -v sd=0.66 -v dx=0.05 -f "$DRAND48" -f "$T/sample.awk" "$T/gen/force.tsv" >"$T/s.tsv"
    "$ADHERE" fit -q --model=time --data="$T/s.tsv" --material=sls --E0=1.3GPa --Einf=2.5GPa --tau=0.7s -A 0.8e-19J \
        --speed=1nm/s $G --no-plot -o "$T/s$seed" >/dev/null 2>&1
    awk -F'\t' 'BEGIN {t["E0"] = 1e9; t["A"] = 1e-19; t["Einf"] = 3e9; t["tau"] = 1}
        ($1 in t) {printf "%s %.4f\n", $1, ($2 - t[$1]) / $3}' "$T/s$seed/fit.tsv"
    seed=$((seed + 1))
done | awk '{s[$1] += $2 * $2; n[$1]++; a = $2 < 0 ? -$2 : $2; if (a > m[$1]) m[$1] = a}
    END {for (p in s) printf "  %s: rms z %.2f, largest |z| %.2f over %d curves\n", p, sqrt(s[p] / n[p]), m[p], n[p]}'
