#!/bin/sh
# Runs every test of `make check` and prints one TAP stream per test file,
# then the closing line "N passed, N failed". Usage: tests/run-all.sh BUILD
# Each test is a C program (tests/unit, tests/hard) or an executable script
# (tests/cli, tests/replay, tests/plots, tests/man) that prints TAP lines.
BUILD=${1:-build}
export LC_ALL=C.UTF-8 ADHERE_BIN="$PWD/adhere" ADHERE_SRC="$PWD" OPENBLAS_NUM_THREADS=1
log=$(mktemp)
trap 'rm -f "$log"' EXIT
pass=0 fail=0
# ONLY=c: just the C programs (make check-asan). ASAN_BUILD: a second build
# of the C tests under the sanitizers. FUZZ_BUILD: where the fuzzers are.
if [ "${ONLY:-}" = c ]; then
    set -- "$BUILD"/tests/*
else
    set -- "$BUILD"/tests/* tests/cli/*.sh tests/scenes/*.sh tests/replay/*.sh tests/plots/*.sh tests/man/*.sh
    [ -n "${ASAN_BUILD:-}" ] && set -- "$@" "$ASAN_BUILD"/tests/*
    [ -n "${FUZZ_BUILD:-}" ] && set -- "$@" tests/fuzz/run.sh
fi
export BUILD=${FUZZ_BUILD:-$BUILD}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
for t in "$@"; do
    [ -f "$t" ] && [ -x "$t" ] || continue
    case "$t" in *bench-*) continue ;; esac
    echo "# $t"
    "$t" >"$log" 2>&1
    rc=$?
    cat "$log"
    p=$(grep -c '^ok ' "$log")
    f=$(grep -c '^not ok ' "$log")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "not ok - $t exited with status $rc"
        f=1
    fi
    pass=$((pass + p)) fail=$((fail + f))
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
