#!/bin/sh
# make check runs every benchmark once at a tiny size: the figures mean
# nothing there, but a bench that no longer builds or runs fails the suite
# (make bench gives the real figures). Prints TAP. BUILD: the build dir.
set -u
BUILD=${BUILD:-build}

n=0 failed=0
ok() { n=$((n + 1)); echo "ok $n - $*"; }
no() { n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - $*"; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
# bench NAME ARGS...: runs BUILD/tests/bench-NAME, passes when it exits 0.
bench() {
    name=$1; shift
    b=$BUILD/tests/bench-$name
    if [ ! -x "$b" ]; then no "bench-$name is built ($b)"; return; fi
    if "$b" "$@" >"$out" 2>&1; then
        ok "bench-$name $* runs ($(wc -l <"$out") lines)"
    else
        no "bench-$name $* runs"
        sed 's/^/#   /' "$out"
    fi
}
# one repeat at N = 100, its Figure 4 cycle at N = 100
BENCH_N=100 bench relax 1 100
# the automatic static grid at sigma = 2.25 (the paper's)
bench static_soft 2.25
# the whole static curve at N = 300 (shorter grids do not hold the contact)
bench static 300
# the viscoelastic cycle against the relaxation's (N = 100) and the static
# curve's (sigma = 2.25)
bench visco 100 2.25
# the kernel storages at N = 200 and 400 (dense and hmat-oss at 200 only)
bench operator 200 200 200 400
# adhere fit on the shipped curve, one start, on a coarse grid
bench fit 300 2.5e-9
# the soft-contact relaxation goals through the CLI, each run a few steps
if SOFT_SMOKE=1 ADHERE="${ADHERE_BIN:-./adhere}" tests/bench/soft.sh >"$out" 2>&1; then
    ok "soft.sh runs ($(wc -l <"$out") lines)"
else
    no "soft.sh runs"
    sed 's/^/#   /' "$out"
fi
# the grid and mixing comparisons of the rate-dependent numbers, a few steps each
if RATE_SMOKE=1 ADHERE="${ADHERE_BIN:-./adhere}" tests/bench/rategrid.sh >"$out" 2>&1; then
    ok "rategrid.sh runs ($(wc -l <"$out") lines)"
else
    no "rategrid.sh runs"
    sed 's/^/#   /' "$out"
fi
# the default against the dense oracle and the static curve against sigma,
# each a few steps long
if FAST_SMOKE=1 ADHERE="${ADHERE_BIN:-./adhere}" tests/bench/fast.sh >"$out" 2>&1; then
    ok "fast.sh runs ($(wc -l <"$out") lines)"
else
    no "fast.sh runs"
    sed 's/^/#   /' "$out"
fi
# the 4 x 4 map whole and in 2 shards under GNU parallel, on a coarse grid
if STUDIES_SMOKE=1 ADHERE="${ADHERE_BIN:-./adhere}" tests/bench/studies.sh >"$out" 2>&1; then
    ok "studies.sh runs ($(wc -l <"$out") lines)"
else
    no "studies.sh runs"
    sed 's/^/#   /' "$out"
fi
echo "1..$n"
[ "$failed" -eq 0 ]
