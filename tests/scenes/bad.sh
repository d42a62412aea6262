#!/bin/sh
# Bad scene files: exit 2, one message "FILE:LINE: what", nothing written,
# both for a batch run and for --plan.
. "$(dirname "$0")/../cli/lib.sh"

bad() { # bad LINE "expected text" <<scene on stdin
    line=$1 want=$2
    T2=$((T + 1))
    f="$TMP/bad$T2.scene"
    cat >"$f"
    out="$TMP/out$T2"
    "$ADHERE" --batch -q -o "$out" "$f" >"$TMP/stdout" 2>"$TMP/stderr"
    rc=$?
    msg=$(cat "$TMP/stderr")
    if [ "$rc" -eq 2 ] && grep -qF -- "adhere: $f:$line: " "$TMP/stderr" && grep -qF -- "$want" "$TMP/stderr" \
        && [ ! -e "$out" ] && [ "$(wc -l <"$TMP/stderr")" -eq 1 ]; then
        ok "bad scene -> exit 2 at line $line: $msg"
    else
        not_ok "bad scene -> exit $rc (want 2, '$f:$line:' and '$want', nothing written): $msg"
    fi
    "$ADHERE" --plan "$f" >"$TMP/stdout" 2>"$TMP/stderr"
    rc=$?
    check "--plan of the same bad scene exits 2 ($rc) with $f:$line" sh -c "[ $rc -eq 2 ] && grep -qF -- '$f:$line: ' '$TMP/stderr' && [ ! -s '$TMP/stdout' ]"
}

bad 3 "unknown section [materials]" <<'S'
[scene]
title = typo in a section
[materials]
E = 1GPa
S
bad 4 "unknown key 'Young'" <<'S'
# a comment
[material]
E = 1GPa
Young = 2
S
bad 3 "'1,5': unknown unit ',5'" <<'S'
[material]
E = 1GPa
A = 1,5
S
bad 2 "unknown unit 'parsecs'" <<'S'
[material]
R = 10parsecs
S
bad 2 "is a length (m, nm, um, ...), but a pressure" <<'S'
[material]
E = 3nm
S
bad 4 "key 'E' given twice in [material]" <<'S'
[material]
E = 1GPa
A = 1e-19J
E = 2GPa
S
bad 3 "sigma and E both set the modulus" <<'S'
[sweep]
sigma = 1, 2
E = 1GPa
S
bad 2 "the swept value -1 is not allowed" <<'S'
[sweep]
sigma = 1, -1
S
bad 3 "indented line" <<'S'
[protocol]
turns = -1nm,
   -2nm
S
bad 1 "comes before any [section]" <<'S'
E = 1GPa
S
bad 2 "section header without ']'" <<'S'
# comment
[protocol
S
bad 2 "'fast' is not a mode" <<'S'
[scene]
mode = fast
S
bad 2 "use 10 to 20000 nodes" <<'S'
[grid]
nodes = 9
S
bad 2 "eps" <<'S'
[solver]
eps = 1GPa
S
bad 3 "growth: '1.2' is not allowed: use a ratio from 1 to 1.1" <<'S'
[grid]
kernel = ring
growth = 1.2
S
bad 2 "operator: 'fmm' is not an operator: use dense, hmat or h2" <<'S'
[grid]
operator = fmm
S
bad 4 "grid: 'graded' is not allowed with kernel = paper" <<'S'
[grid]
kernel = paper
# the paper's kernel assumes equal cells
grid = graded
S

# A scene that parses but cannot run names what is wrong, before running.
cat >"$TMP/deep.scene" <<'S'
[sweep]
sigma = 1, 1e9
S
"$ADHERE" --batch -q -o "$TMP/deep" "$TMP/deep.scene" >/dev/null 2>"$TMP/stderr"
rc=$?
check "a sweep with an impossible run exits 2 naming the run ($(cat "$TMP/stderr"))" sh -c "[ $rc -eq 2 ] && grep -q 'sweep run 2 (sigma = 1e+09)' '$TMP/stderr' && [ ! -e '$TMP/deep' ]"

# Missing files.
"$ADHERE" --batch -q -o "$TMP/m" "$TMP/nonexistent.scene" >/dev/null 2>"$TMP/stderr"
rc=$?
check "a missing scene file exits 2 naming it ($(cat "$TMP/stderr"))" sh -c "[ $rc -eq 2 ] && grep -qF '$TMP/nonexistent.scene' '$TMP/stderr' && [ ! -e '$TMP/m' ]"
"$ADHERE" --plan fig9 >/dev/null 2>"$TMP/stderr"
rc=$?
check "an unknown shipped scene exits 2 ($(cat "$TMP/stderr"))" sh -c "[ $rc -eq 2 ] && grep -q \"no scene named 'fig9'\" '$TMP/stderr'"

bad 3 "mixing: 'fast' is not a mixing rule: use paper or momentum" <<'S'
[solver]
eps = 1pm
mixing = fast
S
# a core check's refusal names the key as written, once: "nodes = 5 is not
# allowed", not "nodes: N = 5 nodes is not allowed"
bad 2 ":2: nodes = 5 is not allowed: use 10 to 20000 nodes" <<'S'
[grid]
nodes = 5
S
bad 3 ":3: tau = -1 s is not allowed: the relaxation time must be above 0" <<'S'
[material]
material = sls
tau = -1 s
S
bad 2 "momentum: '1' is not allowed: a number from 0 to below 1" <<'S'
[solver]
momentum = 1
S
done_testing
