#!/bin/sh
# adhere --plan's time against the runs it plans: a standard linear solid
# far from elastic (Einf = 1000 E0) in physical time, whose steps the plan
# counts within the factor adhere(1) promises; a study's pilot, which
# prices each turn's dwell; the static curve, whose time is not estimated.
. "$(dirname "$0")/lib.sh"

# within WHAT PLANNED ACTUAL FACTOR: both above 0, each within FACTOR of the other
within() {
    check "$1: the plan's $2 within a factor $4 of the run's $3" \
        awk -v p="$2" -v r="$3" -v k="$4" 'BEGIN {exit !(p > 0 && r > 0 && p / r < k && r / p < k)}'
}
# cpu_of DIR ARGS...: the CPU seconds of adhere --batch ARGS -o DIR (sh's
# times: the child's user and system, as --plan prices its work in CPU
# seconds, so that other jobs on the machine do not count)
cpu_of() {
    d=$1; shift
    ( "$ADHERE" --batch -q --no-plot "$@" -o "$d" >/dev/null 2>&1; times ) |
        awk 'NR == 2 {split($1, u, /[ms]/); split($2, s, /[ms]/); print u[1] * 60 + u[2] + s[1] * 60 + s[2]}'
}

# Physical time far from elastic: Einf = 1000 E0, the worst the plan's
# steps met in a sweep of Einf/E0 = 1 ... 1000 and 1 nm/s ... 1 mm/s
# (docs/viscoelastic.md). Its steps do not depend on Einf past about
# 10 E0 (the creep's delayed part, at tau's pace, is then all of it); an
# effective modulus interpolated between E0 and Einf made the contact
# line's step 1000^f times the edge zone and planned a quarter of the
# steps (210 for 836 here, 170 for 680 on the visco scene's own sphere).
# A small sphere (R = 1 um) on a resolved grid of 300 nodes: 0.2 s.
W="visco --Einf=300GPa -R 1um -N 300 --spacing=1nm --speed=100nm/s"
# shellcheck disable=SC2086
"$ADHERE" --plan $W >"$TMP/pw" 2>&1
psteps=$(sed -n 's/^time: about [^(]* ([0-9.e+-]* s: about \([0-9]*\) integrator steps.*/\1/p' "$TMP/pw")
# shellcheck disable=SC2086
"$ADHERE" --batch -q --no-plot $W -o "$TMP/rw" >/dev/null 2>&1
rsteps=$(awk -F'\t' '$1 == "time_steps" {print $2}' "$TMP/rw/summary.tsv")
check "Einf = 1000 E0 ($W): resolved, as the plan's promise asks" grep -qx 'resolved	1' "$TMP/rw/summary.tsv"
within "Einf = 1000 E0" "$psteps" "$rsteps" 3

# A study's pilot flies its first and last drives and prices every drive's
# turns' dwells by their iterations. The middle drive of dwell = 0, D, 1
# is not flown: its dwell was not counted at all (the same plan as
# dwell = 0, 1, 2), and one the pilot did fly counted as whatever part of
# it the pilot's 3 s reached.
B="-N 100 --force --step=0.2nm --jobs=1"
secs() { # secs FILE: a study plan's seconds, from "time: about 1 min 05 s on 1 core, from a pilot"
    awk '/^time: about .* from a pilot/ {
        s = $0; sub(/^time: about /, "", s); sub(/ on 1 core.*/, "", s)
        n = split(s, w, " "); t = 0
        for (i = 1; i < n; i += 2) t += w[i] * (w[i + 1] == "h" ? 3600 : w[i + 1] == "min" ? 60 : 1)
        print t }' "$1"
}
for dw in 0,1,2 0,1000000,1 0,500000,1; do
    # shellcheck disable=SC2086
    "$ADHERE" --plan $B --sweep=dwell=$dw >"$TMP/plan$dw" 2>&1
done
short=$(secs "$TMP/plan0,1,2") long=$(secs "$TMP/plan0,1000000,1")
check "a study whose middle drive dwells a million iterations plans more ($long s) than one without the dwell ($short s): half as much again at least" \
    awk -v a="$long" -v b="$short" 'BEGIN {exit !(a > 0 && b > 0 && a > 1.5 * b)}'
check "... and its line says so: $(grep '^time:' "$TMP/plan0,1000000,1" | head -c 300)" \
    grep -q "^time: about .*, and the dwells' 1e+06 iterations at the turns" "$TMP/plan0,1000000,1"
# shellcheck disable=SC2086
within "a study with a dwell (dwell = 0, 500000, 1)" "$(secs "$TMP/plan0,500000,1")" "$(cpu_of "$TMP/rdw" $B --sweep=dwell=0,500000,1)" 3

# The static curve's time is not estimated, a study's either: its pilot on
# a coarse grid met lattice folds the real grid has not (15 s planned for
# the default scene's study of two A, 0.7 s run)
"$ADHERE" --plan --mode=static >"$TMP/pst" 2>&1
check "--plan --mode=static: its time not estimated, and why" \
    sh -c "[ \$(grep -c '^time:' '$TMP/pst') -eq 1 ] && grep -q '^time: not estimated: the static curve' '$TMP/pst'"
"$ADHERE" --plan --mode=static --sweep=A=5e-20J,1e-19J >"$TMP/psts" 2>&1
check "--plan --mode=static of a study: not estimated either, no pilot ($(grep '^time:' "$TMP/psts"))" \
    sh -c "[ \$(grep -c '^time:' '$TMP/psts') -eq 1 ] && grep -q '^time: not estimated: the static curve.*; the study solves 2 curves' '$TMP/psts'"

done_testing
