#!/bin/sh
# Memory is bounded before it is allocated, for every grid: -N 20000 (a
# dense kernel would be 3.2 GB, a static solver 9.6 GB) runs in a bounded
# operator, under 1 GB of peak memory, in relaxation and in static mode; a
# dense operator asked for beyond the memory this process may use (ulimit
# -v stands in for a small machine) is refused with the estimate and what
# to use instead; --data is capped in points and bytes. Prints TAP.
. "$(dirname "$0")/lib.sh"
cd "$TMP" || exit 1
key() { awk -F'\t' -v k="$2" '$1 == k {print $2}' "$1/summary.tsv" 2>/dev/null; }

# peak NAME ARGS...: adhere with ARGS until its first step is solved (its
# readiness file; at most 60 s), then its peak resident memory (VmHWM, kB)
# in hwm and a SIGINT; came 1 when the step came.
peak() {
    name=$1
    shift
    rm -f "$name.ready"
    ADHERE_READY_FILE="$TMP/$name.ready" "$ADHERE" "$@" >/dev/null 2>"$name.err" &
    pid=$!
    came=0
    wait_phase "$name.ready" step "$pid" && came=1
    hwm=$(awk '$1 == "VmHWM:" {print $2}' "/proc/$pid/status" 2>/dev/null)
    kill -INT "$pid" 2>/dev/null
    wait "$pid"
    hwm=${hwm:-0}
}
peak relax --batch -q --no-plot -N 20000 -o relax
check "-N 20000, relaxation: its first step solved under 1 GB (peak $hwm kB, step seen $came)" \
    sh -c "[ $came -eq 1 ] && [ $hwm -gt 0 ] && [ $hwm -lt 1048576 ]"
check "... in the H^2 operator, as summary.tsv says ($(key relax operator))" [ "$(key relax operator)" = h2 ]
peak static --batch -q --no-plot -N 20000 --mode=static -o static
check "-N 20000, --mode=static: its first point solved under 1 GB (peak $hwm kB, point seen $came)" \
    sh -c "[ $came -eq 1 ] && [ $hwm -gt 0 ] && [ $hwm -lt 1048576 ]"

# a dense kernel asked for on a machine too small for it
(ulimit -v 1500000 && exec "$ADHERE" --batch -q -N 20000 --operator=dense -o dense) 2>dense.err
rc=$?
check "--operator=dense -N 20000 with 1.5 GB of address space: refused, exit 2 (got $rc)" [ "$rc" -eq 2 ]
check "... naming the estimate and what to use: $(head -c 300 dense.err)" \
    sh -c "grep -q 'about 3.2[0-9]* GB' dense.err && grep -q -- '--operator=h2' dense.err"
check "... before anything was written" [ ! -e dense/force.tsv ]

# --data: a million points and one more, and a file of 65 MiB
awk 'BEGIN {for (i = 0; i <= 1000000; i++) print i * 1e-3, 1}' >many.dat
"$ADHERE" --batch -q -N 100 --force --data=many.dat -o many 2>many.err
rc=$?
check "--data with 1000001 points: refused, exit 2 (got $rc): $(head -c 200 many.err)" \
    sh -c "[ $rc -eq 2 ] && grep -q '1000000 points' many.err"
dd if=/dev/zero of=big.dat bs=1 count=0 seek=65M 2>/dev/null
"$ADHERE" --batch -q -N 100 --force --data=big.dat -o big 2>big.err
rc=$?
check "--data of 65 MiB: refused before it is read, exit 2 (got $rc): $(head -c 200 big.err)" \
    sh -c "[ $rc -eq 2 ] && grep -q '64 MiB' big.err"
done_testing
