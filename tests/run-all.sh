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
for t in "$BUILD"/tests/* tests/cli/*.sh tests/scenes/*.sh tests/replay/*.sh tests/plots/*.sh tests/man/*.sh tests/asan/*.sh; do
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
