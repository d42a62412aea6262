#!/bin/sh
# Memory is bounded before it is allocated, for every grid: -N 20000 (a
# dense kernel would be 3.2 GB, a static solver 9.6 GB) runs in a bounded
# operator, under 1 GB of peak memory, in relaxation and in static mode; a
# dense operator asked for beyond the memory this process may use (ulimit
# -v stands in for a small machine) is refused with the estimate and what
# to use instead; --data is capped in points and bytes. Prints TAP.
. "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
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

# A study in physical time counts each run's solvers as a single run does
# (a viscoelastic path's preconditioner, n^2 on a dense kernel, and the
# landing's LU, n^2 more): over nodes = 100, 4000 on the dense operator
# under 600 MB of address space its largest run (a 128 MB kernel, about
# 531 MB with its solvers) is refused alone, and the study with it, before
# its first run. It counted the kernels only and started (killed here
# after 20 s).
for a in "-N 4000" "--sweep=nodes=100,4000"; do
    (ulimit -v 600000 && exec timeout -s KILL 20 "$ADHERE" --batch -q --no-plot --mode=time --material=sls $a \
        --operator=dense --force --jobs=1 -o visco) 2>visco.err
    rc=$?
    check "physical time, sls, $a, dense, under ulimit -v 600000: refused up front, exit 2 (got $rc): $(grep -v warning visco.err | head -c 300)" \
        sh -c "[ $rc -eq 2 ] && grep -q 'a run on 4000 nodes with the dense operator and its static solver would hold about 5[0-9][0-9] MB, more than the [0-9.]* MB this process may use' visco.err"
    check "... before a run was written" sh -c "[ ! -e visco/sweep.tsv ] && [ ! -e visco/force.tsv ] && [ ! -e visco/run-1 ]"
done

# Under an address-space limit the BLAS's working buffers (OpenBLAS maps
# 128 MiB a thread and, before 0.3.30, retries forever when it cannot,
# deaf to signals) are counted: a run either fits or is refused, and
# adhere ends either way. It used to hang below about 340 MB, even for
# --version (the library's exit handler joins its thread, stuck retrying).
# guarded LIMIT_KB ARGS...: adhere under ulimit -v, killed after 20 s; rc
guarded() {
    lim=$1
    shift
    (ulimit -v "$lim" && exec timeout -s KILL 20 "$ADHERE" "$@") >guarded.out 2>guarded.err
    rc=$?
}
guarded 150000 --version
check "adhere --version under ulimit -v 150000 ends, exit 0 (got $rc)" [ "$rc" -eq 0 ]
hung="" refused=0 ran=0 other=""
for lim in 200000 300000 400000 500000 700000; do
    for mode in relax static; do
        guarded "$lim" --batch -q --no-plot -N 200 --force -R 1um -d 0.5nm --turn=-1nm --eps=10pm --mode=$mode -o lim
        case $rc in
        0) ran=$((ran + 1)) ;;
        2) grep -q 'ulimit -v' guarded.err && refused=$((refused + 1)) || other="$other $lim/$mode: $(head -c 200 guarded.err)" ;;
        137) hung="$hung $lim/$mode" ;;
        *) other="$other $lim/$mode: exit $rc" ;;
        esac
    done
done
check "a small run under ulimit -v 200 MB ... 700 MB: never hung (hung at:${hung:- none})" [ -z "$hung" ]
check "... each refused naming ulimit -v ($refused) or run to its end ($ran)${other:+; otherwise:$other}" \
    sh -c "[ -z '$other' ] && [ $refused -gt 0 ] && [ $ran -gt 0 ]"
# The BLAS's own thread maps its buffer as the library loads, concurrently
# with the check: one that came between the check's read of VmSize and its
# count of the buffers mapped was counted nowhere, the run went ahead and
# hung at its first product (about one run in a hundred at 300 MB, more
# under load). blasrace.c holds that thread until the check has read
# VmSize and the check until the buffer is mapped: that order every time.
if ${CC:-cc} -shared -fPIC -o blasrace.so "$HERE/blasrace.c" -ldl -lpthread 2>blasrace.err; then
    (ulimit -v 300000 && exec timeout -s KILL 20 env LD_PRELOAD="$TMP/blasrace.so" BLASRACE_LOG="$TMP/race.log" \
        "$ADHERE" --batch -q --no-plot -N 200 --force -R 1um -d 0.5nm --turn=-1nm --eps=10pm -o race) \
        >race.out 2>race.err
    rc=$?
    if grep -qx alone race.log 2>/dev/null; then
        ok "# SKIP the BLAS has no thread of its own here (one core, or OPENBLAS_NUM_THREADS=1): no race to provoke"
    else
        check "the BLAS's thread mapping its buffer inside the check (ulimit -v 300000, $(cat race.log 2>/dev/null)): refused naming ulimit -v, not hung (exit $rc)" \
            sh -c "grep -qx ordered race.log && [ $rc -eq 2 ] && grep -q 'ulimit -v' race.err"
    fi
else
    not_ok "tests/cli/blasrace.c compiles: $(head -c 300 blasrace.err)"
fi

# The TUI keeps every state of its path for undo (3 doubles a node a
# step): at N = 20000 and d = 0.1 pm the path to the turn and back (438 506
# steps) would keep 215 GB. It is refused before a step, on the screen; it
# used to step on until the machine ran out.
printf ':set N 20000\n:set d 0.1pm\nf\n' >path.keys
"$ADHERE" --replay=path.keys --screen=path.screen --size=200x32 --no-clock </dev/null >path.out 2>&1
rc=$?
check "the TUI at N = 20000, d = 0.1 pm: its first step refused, naming the undo states (exit $rc: $(grep -o 'error: .*' path.screen | cut -c1-160))" \
    sh -c "[ $rc -eq 0 ] && grep -q 'undo would keep [0-9.]* GB for this path' path.screen && grep -q 'path   0 states' path.screen"
# the run alone past the budget (a dense kernel of 20000 nodes, 3.2 GB,
# under 2 GB of address space): refused for the kernel and its operator,
# not as the path's 432 MB of undo "more than the 1.64 GB this process may
# use"
printf ':set N 20000\n:set grid.operator dense\nf\n' >dense.keys
(ulimit -v 2000000 && exec "$ADHERE" --replay=dense.keys --screen=dense.screen --size=200x32 --no-clock </dev/null >dense.out 2>&1)
rc=$?
check "the TUI at N = 20000 on the dense operator under ulimit -v 2000000: refused for the run's kernel, not the path (exit $rc: $(grep -o 'error: .*' dense.screen | cut -c1-160))" \
    sh -c "[ $rc -eq 0 ] && grep -q 'error: a run on 20000 nodes with the dense operator would hold about 3.2[0-9]* GB' dense.screen &&
           ! grep -q 'undo would keep' dense.screen && grep -q 'path   0 states' dense.screen"

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
