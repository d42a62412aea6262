#!/bin/sh
# make bench: a 4 x 4 map (sigma x turn, 16 runs in 4 drives) run whole on
# one machine (a run per core) against the same map as 2 shards under GNU
# parallel (each --jobs=1) and merged; the wall times, their ratio, the
# machine. The two tables must agree but for their timing column.
# STUDIES_SMOKE=1 (make check): a coarse grid, the figures meaningless.
# ADHERE: the program (default ./adhere).
set -u
ADHERE=${ADHERE:-./adhere}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ "${STUDIES_SMOKE:-0}" = 1 ]; then
    flags="-N 100 --force --eps=20pm"
else
    flags="-N 400 --force --eps=2pm"
fi
cp "$(dirname "$0")/../cli/map.scene" "$tmp/map.scene"
now() { date +%s.%N; }
echo "studies: a 4 x 4 map (sigma x turn: 16 runs, 4 drives), $flags"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
t0=$(now)
# shellcheck disable=SC2086 # the flags are words
"$ADHERE" --batch -q $flags "$tmp/map.scene" -o "$tmp/whole" 2>/dev/null || { echo "the whole map failed"; exit 1; }
t1=$(now)
# shellcheck disable=SC2086
parallel --will-cite "$ADHERE" --batch -q --jobs=1 $flags "$tmp/map.scene" --shard {}/2 -o "$tmp/shard{}" ::: 1 2 2>/dev/null ||
    { echo "the shards failed"; exit 1; }
"$ADHERE" merge -q -o "$tmp/merged" "$tmp/shard1" "$tmp/shard2" || { echo "the merge failed"; exit 1; }
t2=$(now)
untimed() { grep -v '^# scene:' "$1" | cut -f1-14,16-; }
if ! untimed "$tmp/whole/sweep.tsv" | cmp -s - "$tmp/merged.untimed" 2>/dev/null; then
    untimed "$tmp/merged/sweep.tsv" >"$tmp/merged.untimed"
    untimed "$tmp/whole/sweep.tsv" | cmp -s - "$tmp/merged.untimed" || { echo "the merged table differs"; exit 1; }
fi
awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {
    w = b - a; s = c - b
    printf "whole, a run per core: %.2f s; 2 shards under parallel + merge: %.2f s; ratio shards/whole %.2f\n", w, s, s / w }'
cpu() { awk -F'\t' '!/^#/ && $1 != "run" {s += $15} END {printf "%.2f", s}' "$1"; }
echo "the runs' own seconds (sweep.tsv): whole $(cpu "$tmp/whole/sweep.tsv"), shards $(cpu "$tmp/merged/sweep.tsv"); the tables agree but for timing"
