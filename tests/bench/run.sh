#!/bin/sh
# make bench: figures, not pass/fail. Times depend on the machine, so the
# machine is printed with them. BENCH_REPEAT (default 5) runs per median;
# BENCH_CYCLE_N (default 1000; 0 skips) sets the Figure 4 cycle's grid.
# BENCH_DENSE_MAX (default 10000) is the largest N whose kernel is built
# dense in the storage benchmark (N^2 x 8 bytes: 0.8 GB at 10^4, 3.2 GB at
# 2 x 10^4); BENCH_HMAT_MAX (default 100000) the largest assembled by
# hmat-oss (70 s at 10^5); BENCH_OPERATOR_N (default "1000 3000 10000 30000
# 100000"); BENCH_FIG6=1 adds Figure 6 to the soft-contact relaxation goals;
# BENCH_FIGURES (default "1 2 3 4 5 8") the figures whose default run is timed against
# --operator=dense (tests/bench/fast.sh).
BUILD=${1:-build}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "threads: one per run (OpenBLAS set to 1 thread)"
echo
"$BUILD/tests/bench-relax" "${BENCH_REPEAT:-5}" "${BENCH_CYCLE_N:-1000}"
echo
"$BUILD/tests/bench-static"
echo
# the static curve on the automatic resolved grid at sigma = 15, 22.5 and 75
"$BUILD/tests/bench-static_soft"
echo
# the viscoelastic cycle against the relaxation's Figure 4 cycle (N = 1000,
# dense and H^2) and against the static curve at sigma = 75 (issue 29's
# goals: ratios of at most 1 and 6); BENCH_VISCO_SIGMA sets sigma
"$BUILD/tests/bench-visco" "${BENCH_CYCLE_N:-1000}" "${BENCH_VISCO_SIGMA:-75}"
echo
# the relaxation goals of soft contacts through the CLI (BENCH_FIG6=1 adds
# Figure 6: ~12 minutes)
ADHERE=./adhere tests/bench/soft.sh
echo
# the rate-dependent numbers against the grid and the mixing rule at sigma
# = 7.5 and 22.5 (docs/convergence.md; ~15 minutes, most of it the paper's
# mixing rule)
ADHERE=./adhere tests/bench/rategrid.sh
echo
# the default operator against --operator=dense per figure, and the static
# curve's cost against sigma (BENCH_FIGURES, BENCH_SIGMAS, BENCH_ROUNDS)
ADHERE=./adhere tests/bench/fast.sh
echo
# a 4 x 4 map whole against 2 shards under GNU parallel
ADHERE=./adhere tests/bench/studies.sh
echo
# shellcheck disable=SC2086 # the sizes are words
"$BUILD/tests/bench-operator" "${BENCH_DENSE_MAX:-10000}" "${BENCH_HMAT_MAX:-100000}" ${BENCH_OPERATOR_N:-1000 3000 10000 30000 100000}
echo
# adhere fit: E and A to the shipped 200-point Figure 1 curve, evaluations and seconds
"$BUILD/tests/bench-fit"
echo
# adhere fit --model=time: what one curve at one speed determines (tau from
# 0.01 to 100 s) and the standard errors over seeds (docs/fitting.md)
ADHERE=./adhere tests/bench/fittime.sh
