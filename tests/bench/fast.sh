#!/bin/sh
# make bench: what the default costs against the oracle, as ratios of CPU
# seconds measured in this session, interleaved (A B A B ...) so that the
# machine's load falls on both alike; medians over the rounds. One line per
# ratio:
#   - each figure's default run against --operator=dense (Figures 1 to 8 as
#     shipped; BENCH_FIGURES, default "1 2 3 4 5 8", names which: ~11
#     minutes on one core at 3 rounds, most of it Figure 3 dense; "6 7"
#     add most of an hour, Figure 7 dense alone ~10 minutes a round), the
#     printed numbers compared too (every summary value to 10 digits);
#   - the static curve at each sigma of BENCH_SIGMAS (default 1 2 5 7.5 10
#     15 20 50 100; E set for each, defaults otherwise) against sigma = 20,
#     with its grid, points and time a point (docs/performance.md says where
#     sigma = 50 and 100's time goes, and why they stay above 3x: the rings
#     the grid needs).
# BENCH_FIGURES=" " (a blank) runs no figure.
# BENCH_ROUNDS (default 3) rounds. ADHERE: the program (default ./adhere).
# BENCH_ARGS_<figure>: more arguments for that figure's runs, both alike
# (BENCH_FIGURES=7 BENCH_ARGS_7=--turn=0nm: Figure 7 reduced to one turn).
# FAST_SMOKE=1 (make check): Figure 4 a few steps long and two sigmas, one
# round: the ratios mean nothing, but a broken comparison fails the suite.
set -u
ADHERE=${ADHERE:-./adhere}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rounds=${BENCH_ROUNDS:-3}
figures=${BENCH_FIGURES:-1 2 3 4 5 8}
sigmas=${BENCH_SIGMAS:-1 2 5 7.5 10 15 20 50 100}
short=""
if [ "${FAST_SMOKE:-0}" = 1 ]; then
    rounds=1 figures=4 sigmas="2 20" short="--start=6nm --turn=5nm"
fi
failed=0

# cpu NAME ARGS...: one batch run into $tmp/NAME; appends its CPU seconds
# (user + system, threads summed) to $tmp/NAME.cpu
cpu() {
    name=$1; shift
    # a fresh directory each round: a sweep's study resumes from a finished
    # one in place (no work, no time)
    rm -rf "${tmp:?}/$name"
    # shellcheck disable=SC2086 # $short is words
    if ! /usr/bin/time -f '%U %S' -o "$tmp/$name.t" "$ADHERE" -b --no-plot -q --overwrite -o "$tmp/$name" "$@" $short \
        >"$tmp/$name.err" 2>&1; then
        echo "$name: the run failed: $(head -c 300 "$tmp/$name.err")"
        failed=1
        return 1
    fi
    awk '{print $1 + $2}' "$tmp/$name.t" >>"$tmp/$name.cpu"
}
median() { sort -g "$1" | awk '{v[NR] = $1} END {print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# every value of DIR's summary.tsv and sweep.tsv but the operator and the
# times, numbers to 10 digits: what the figure prints
printed() {
    for t in "$1/summary.tsv" "$1/sweep.tsv"; do
        [ -f "$t" ] || continue
        awk -F'\t' '/^#/ {next}
            !h++ {for (i = 1; i <= NF; i++) skip[i] = ($i == "seconds" || $i == "operator")}
            $1 == "seconds" || $1 == "operator" {next}
            {for (i = 1; i <= NF; i++) if (!skip[i]) printf "%s ", ($i + 0 == $i && $i != "") ? sprintf("%.10g", $i) : $i
             print ""}' "$t"
    done
}

machine="$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "machine: $machine, load $(cut -d' ' -f1-3 /proc/loadavg)"
for f in $figures; do
    r=0
    extra=""
    eval "extra=\${BENCH_ARGS_$f:-}"
    while [ "$r" -lt "$rounds" ]; do
        # shellcheck disable=SC2086 # $extra is words
        cpu "fig$f-dense" "fig$f" --operator=dense $extra || break
        # shellcheck disable=SC2086
        cpu "fig$f-default" "fig$f" $extra || break
        r=$((r + 1))
    done
    [ -s "$tmp/fig$f-default.cpu" ] || continue
    d=$(median "$tmp/fig$f-dense.cpu") n=$(median "$tmp/fig$f-default.cpu")
    same=identical
    printed "$tmp/fig$f-dense" >"$tmp/a"
    printed "$tmp/fig$f-default" >"$tmp/b"
    [ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b" || { same=DIFFERENT; failed=1; }
    # a sweep's runs keep theirs in run-K/ (awk stops at a missing file)
    op=$(cat "$tmp/fig$f-default/summary.tsv" "$tmp/fig$f-default"/run-1/summary.tsv 2>/dev/null |
        awk -F'\t' '$1 == "operator" {print $2}' | head -1)
    printf 'ratio: Figure %s%s, dense / default (%s): %.2f (%.2f / %.2f CPU s, median of %d), printed numbers %s; %s\n' \
        "$f" "${extra:+ ($extra)}" "$op" "$(echo "$d $n" | awk '{print $1 / $2}')" "$d" "$n" "$rounds" "$same" "$machine"
done

# the static curve's cost against sigma: E for each sigma, the rest default
e_of() { awk -v s="$1" 'BEGIN {printf "%.6g", 2.25079e9 / s}'; } # sigma = 7.5026 at 0.3 GPa
r=0
while [ "$r" -lt "$rounds" ]; do
    for s in $sigmas; do
        cpu "static-$s" --mode=static -E "$(e_of "$s")" || true
    done
    r=$((r + 1))
done
if [ -s "$tmp/static-20.cpu" ]; then
    t20=$(median "$tmp/static-20.cpu")
    for s in $sigmas; do
        [ -s "$tmp/static-$s.cpu" ] || continue
        t=$(median "$tmp/static-$s.cpu")
        pts=$(awk -F'\t' '$1 == "points" {print $2}' "$tmp/static-$s/summary.tsv")
        printf 'ratio: static curve, sigma = %s / sigma = 20: %.2f (%.2f / %.2f CPU s, median of %d; %s nodes, %s points, %.1f ms a point, %s); %s\n' \
            "$s" "$(echo "$t $t20" | awk '{print $1 / $2}')" "$t" "$t20" "$rounds" \
            "$(awk -F'\t' '$1 == "nodes" {print $2}' "$tmp/static-$s/summary.tsv")" "$pts" \
            "$(echo "$t $pts" | awk '{print ($2 > 0 ? 1000 * $1 / $2 : 0)}')" \
            "$(awk -F'\t' '$1 == "operator" {print $2}' "$tmp/static-$s/summary.tsv")" "$machine"
    done
fi
exit "$failed"
