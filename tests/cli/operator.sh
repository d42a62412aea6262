#!/bin/sh
# The default operator against the dense oracle on the figures' uniform
# grids (issue "fast by default"): a short run of each distinct grid
# (Figures 1 and 2 share one, Figures 4, 7 and 8 another, Figure 5 its own)
# by default (H^2) and with --operator=dense prints the same numbers: the
# closing line, every summary value to 10 digits, the same iterations at
# every step; and the static reference beside it is the dense curve, digit
# for digit. tests/unit/test_operator.c compares the products.
. "$(dirname "$0")/lib.sh"

key() { awk -F'\t' -v k="$2" '$1 == k {print $2}' "$1/summary.tsv"; }
# every summary value but the operator and the time, numbers to 10 digits
digits() {
    awk -F'\t' '!/^#/ && $1 != "operator" && $1 != "seconds" && $1 != "key" {
        if ($2 + 0 == $2 && $2 != "") printf "%s %.10g\n", $1, $2; else print $1, $2 }' "$1/summary.tsv"
}
table() { grep -v '^#' "$1/$2" | cut -f"$3"; } # FILE COLUMNS: a table's columns

for f in fig1 fig4 fig5; do
    for op in default dense; do
        flag=""
        [ "$op" = dense ] && flag=--operator=dense
        # shellcheck disable=SC2086 # flag is one word or none
        "$ADHERE" --batch "$f" --turn=1nm --step=0.2nm --eps=5pm --no-plot $flag -o "$TMP/$f-$op" \
            >/dev/null 2>"$TMP/$f-$op.err"
        echo "rc $?" >>"$TMP/$f-$op.err"
    done
    d="$TMP/$f-default" o="$TMP/$f-dense"
    check "$f: both runs exit 0 ($(tail -1 "$d.err"), $(tail -1 "$o.err"))" \
        sh -c "tail -1 '$d.err' | grep -qx 'rc 0' && tail -1 '$o.err' | grep -qx 'rc 0'"
    check "$f: the default operator is h2 ($(key "$d" operator)), the oracle's dense ($(key "$o" operator))" \
        sh -c "[ '$(key "$d" operator)' = h2 ] && [ '$(key "$o" operator)' = dense ]"
    closing() { sed -n "s/done in [0-9.]* s//; s|$TMP/$f-[a-z]*|DIR|p" "$1"; }
    check "$f: the same closing line ($(closing "$d.err" | head -c 120))" \
        sh -c "[ -n \"$(closing "$d.err" | grep pull-off)\" ] && [ \"$(closing "$d.err")\" = \"$(closing "$o.err")\" ]"
    digits "$d" >"$TMP/$f-d.sum"
    digits "$o" >"$TMP/$f-o.sum"
    check "$f: every summary value the same to 10 digits ($(diff "$TMP/$f-d.sum" "$TMP/$f-o.sum" | head -3 | tr '\n' ' '))" \
        cmp -s "$TMP/$f-d.sum" "$TMP/$f-o.sum"
    table "$d" force.tsv 1,7-11 >"$TMP/$f-d.it"
    table "$o" force.tsv 1,7-11 >"$TMP/$f-o.it"
    check "$f: the same steps, iterations, branches and convergence at every step ($(wc -l <"$TMP/$f-d.it") rows)" \
        cmp -s "$TMP/$f-d.it" "$TMP/$f-o.it"
done

# --reference=static takes the static mode's operator (dense on a uniform
# grid): its curve is the dense run's, every column but the time.
for op in default dense; do
    flag=""
    [ "$op" = dense ] && flag=--operator=dense
    # shellcheck disable=SC2086
    "$ADHERE" --batch -q fig1 --turn=1nm --step=0.2nm --eps=5pm --no-plot --reference=static $flag \
        -o "$TMP/ref-$op" >/dev/null 2>&1
done
check "--reference=static: the same static curve by default as with --operator=dense" \
    sh -c "[ -s '$TMP/ref-default/static.tsv' ] && [ \"\$(grep -v '^#' '$TMP/ref-default/static.tsv' | cut -f1-12)\" = \"\$(grep -v '^#' '$TMP/ref-dense/static.tsv' | cut -f1-12)\" ]"
done_testing
