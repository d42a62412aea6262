#!/bin/sh
# Runs every test of `make check`, prints each test file's TAP stream, then
# one closing line, exactly: "N passed, N failed, N skipped".
# Usage: tests/run-all.sh BUILD
#
# A test is a C program (BUILD/tests: tests/unit, tests/hard) or a script
# (tests/*/NAME.sh) that prints TAP, one line per case:
#     ok N - what was checked
#     not ok N - what was checked        (then "#" lines saying why)
#     ok N # SKIP why it could not run   (counted apart, never as passed)
# and exits non-zero when any case failed (a non-zero exit with no "not ok"
# line counts as one failure). A script without its run bit is run with sh.
# The run fails on any failure; with CI=true (make deps installs everything
# the tests need) it also fails on any skip, and when nothing passed.
BUILD=${1:-build}
export LC_ALL=C.UTF-8 ADHERE_BIN="${ADHERE_BIN:-$PWD/adhere}" ADHERE_SRC="$PWD"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0 skip=0
# ONLY=c: just the C programs (make check-asan). ASAN_TESTS: C tests of a
# second build under the sanitizers (make check: all but those its plain
# build alone runs, the Makefile's ASAN_PLAIN_ONLY), run among the others
# by the two workers below (the tests are single-threaded). FUZZ_BUILD:
# where the fuzzers are.
# TESTS="FILE ...": just those (e.g. TESTS=tests/replay/run.sh).
asan=""
if [ -n "${TESTS:-}" ]; then
    # shellcheck disable=SC2086
    set -- $TESTS
elif [ "${ONLY:-}" = c ]; then
    set -- "$BUILD"/tests/*
else
    set -- "$BUILD"/tests/* tests/cli/*.sh tests/scenes/*.sh tests/replay/*.sh tests/plots/*.sh tests/man/*.sh \
        tests/source/*.sh tests/bench/smoke.sh
    asan=${ASAN_TESTS:-}
    [ -n "${FUZZ_BUILD:-}" ] && set -- "$@" tests/fuzz/run.sh
fi
export BUILD=${FUZZ_BUILD:-$BUILD}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# run_one TEST OUT: runs TEST, writes its TAP and a summary line to OUT and
# "passed failed skipped" to OUT.n.
run_one() {
    t=$1 out=$2
    t0=$(date +%s)
    case "$t" in
    *.sh) if [ -x "$t" ]; then "$t"; else sh "$t"; fi >"$out.log" 2>&1 ;;
    *) if [ -x "$t" ]; then "$t" >"$out.log" 2>&1; else echo "not ok - $t is not executable" >"$out.log"; false; fi ;;
    esac
    rc=$?
    { echo "# $t"; cat "$out.log"; } >"$out"
    s=$(grep -Ec '^ok [0-9]* *# *SKIP' "$out.log")
    p=$(($(grep -c '^ok ' "$out.log") - s))
    f=$(grep -c '^not ok ' "$out.log")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "not ok - $t exited with status $rc" >>"$out"
        f=1
    fi
    echo "# $t: $p passed, $f failed, $s skipped in $(($(date +%s) - t0)) s" >>"$out"
    echo "$p $f $s" >"$out.n"
}
# report OUT: prints it and adds its counts
report() {
    cat "$1"
    read -r p f s <"$1.n"
    pass=$((pass + p)) fail=$((fail + f)) skip=$((skip + s))
}
runnable() { [ -f "$1" ] && case "$1" in *bench-*) false ;; *) true ;; esac; }   # benches: tests/bench/smoke.sh

# Two workers share every test (the ASan build's too): each claims the next
# one not yet taken (mkdir is atomic: one claimant wins) and runs it, so
# the cores stay busy until the list is done; the long tests come first,
# longest first, so no worker starts one at the end. The reports follow in
# the list's order. (Two lanes fixed in advance, the ASan build's and the
# rest, left one core idle for a minute: 171 against 108 s of tests.)
# The long ones, longest first (docs/testing.md has their seconds; the
# fuzz pass is 5 x 3 s of wall clock whatever its CPU), down to 1.5 CPU s:
# the rest, glob order with the ASan build's last, ended on its visco tests
# of 1.5 to 2.6 s, one core idle meanwhile.
longest="*/cli/time.sh */fuzz/run.sh */scenes/plan.sh */replay/run.sh */cli/studies.sh */cli/fit.sh
    */bench/smoke.sh */test_path */test_fit */test_mixing */cli/honest.sh */test_rate_grid */test_equilibrium
    */plots/batch-plots.sh */cli/operator.sh */test_operator */test_soft_static */test_graded_run */test_visco_lattice
    */hard-* */cli/static.sh */test_visco_soft */test_visco_limits */test_visco_rate */cli/budget.sh */scenes/run.sh
    */test_static_skip */test_visco_shared */cli/outdir.sh */cli/signals.sh */test_path_ubound */test_physics"
set -f
long=""
for p in $longest; do
    for t in "$@" $asan; do
        case "$long " in *" $t "*) continue ;; esac
        case "$t" in $p) runnable "$t" && long="$long $t" ;; esac
    done
done
rest=""
for t in "$@" $asan; do
    runnable "$t" || continue
    case "$long " in *" $t "*) ;; *) rest="$rest $t" ;; esac
done
set +f
# shellcheck disable=SC2086
set -- $long $rest
total=$#
worker() {
    i=0
    for t in "$@"; do
        i=$((i + 1))
        mkdir "$work/claim.$i" 2>/dev/null || continue
        run_one "$t" "$work/out.$(printf %04d $i)"
    done
}
worker "$@" &
w1=$!
worker "$@"
wait "$w1"
i=0
while [ "$i" -lt "$total" ]; do
    i=$((i + 1))
    o="$work/out.$(printf %04d $i)"
    [ -f "$o.n" ] && report "$o"
done
status=0
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ] || status=1
if [ "$skip" -gt 0 ] && [ "${CI:-}" = true ]; then
    echo "# CI=true: a skip fails the run (make deps installs what the tests need)"
    status=1
fi
echo "$pass passed, $fail failed, $skip skipped"
exit "$status"
