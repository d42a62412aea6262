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
export LC_ALL=C.UTF-8 ADHERE_BIN="$PWD/adhere" ADHERE_SRC="$PWD" OPENBLAS_NUM_THREADS=1
log=$(mktemp)
trap 'rm -f "$log"' EXIT
pass=0 fail=0 skip=0
# ONLY=c: just the C programs (make check-asan). ASAN_BUILD: a second build
# of the C tests under the sanitizers. FUZZ_BUILD: where the fuzzers are.
# TESTS="FILE ...": just those (e.g. TESTS=tests/replay/run.sh).
if [ -n "${TESTS:-}" ]; then
    # shellcheck disable=SC2086
    set -- $TESTS
elif [ "${ONLY:-}" = c ]; then
    set -- "$BUILD"/tests/*
else
    set -- "$BUILD"/tests/* tests/cli/*.sh tests/scenes/*.sh tests/replay/*.sh tests/plots/*.sh tests/man/*.sh \
        tests/bench/smoke.sh
    [ -n "${ASAN_BUILD:-}" ] && set -- "$@" "$ASAN_BUILD"/tests/*
    [ -n "${FUZZ_BUILD:-}" ] && set -- "$@" tests/fuzz/run.sh
fi
export BUILD=${FUZZ_BUILD:-$BUILD}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
for t in "$@"; do
    [ -f "$t" ] || continue
    case "$t" in *bench-*) continue ;; esac   # run by tests/bench/smoke.sh
    echo "# $t"
    t0=$(date +%s)
    case "$t" in
    *.sh) if [ -x "$t" ]; then "$t"; else sh "$t"; fi >"$log" 2>&1 ;;
    *) if [ -x "$t" ]; then "$t" >"$log" 2>&1; else echo "not ok - $t is not executable" >"$log"; false; fi ;;
    esac
    rc=$?
    cat "$log"
    s=$(grep -Ec '^ok [0-9]* *# *SKIP' "$log")
    p=$(($(grep -c '^ok ' "$log") - s))
    f=$(grep -c '^not ok ' "$log")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "not ok - $t exited with status $rc"
        f=1
    fi
    echo "# $t: $p passed, $f failed, $s skipped in $(($(date +%s) - t0)) s"
    pass=$((pass + p)) fail=$((fail + f)) skip=$((skip + s))
done
status=0
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ] || status=1
if [ "$skip" -gt 0 ] && [ "${CI:-}" = true ]; then
    echo "# CI=true: a skip fails the run (make deps installs what the tests need)"
    status=1
fi
echo "$pass passed, $fail failed, $skip skipped"
exit "$status"
