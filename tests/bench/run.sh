#!/bin/sh
# make bench: figures, not pass/fail. Times depend on the machine, so the
# machine is printed with them. BENCH_REPEAT (default 5) runs per median;
# BENCH_CYCLE_N (default 1000; 0 skips) sets the Figure 4 cycle's grid.
BUILD=${1:-build}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "threads: one per run (OpenBLAS set to 1 thread)"
echo
"$BUILD/tests/bench-relax" "${BENCH_REPEAT:-5}" "${BENCH_CYCLE_N:-1000}"
echo
"$BUILD/tests/bench-static"
