#!/bin/sh
# A signal is heard in every phase: inside one long relaxation step, in a
# long dwell, in --reference=static, in --mode=static, in --cost, and
# while gnuplot draws (batch and the TUI's p). Each
# run is signalled once adhere says (through ADHERE_READY_FILE) that the
# phase has begun -- no sleep decides when -- and must stop promptly, keep
# what it has marked PARTIAL with status interrupted, leave no temporary
# file and exit 128 + the signal's number (SIGINT 130, SIGTERM 143, SIGHUP
# 129), as a shell reports a process the signal killed.
. "$(dirname "$0")/lib.sh"

now() { date +%s.%N; }
# signal_run NAME PHASE SIG ARGS...: starts adhere with ARGS, waits for PHASE,
# sends SIG, waits. Sets rc (exit status), took (seconds from the signal to
# the exit), came (1 when the phase was announced).
signal_run() {
    name=$1 phase=$2 sig=$3
    shift 3
    rm -f "$TMP/$name.ready"
    ADHERE_READY_FILE="$TMP/$name.ready" "$ADHERE" "$@" >"$TMP/$name.stdout" 2>"$TMP/$name.stderr" &
    pid=$!
    came=0
    wait_phase "$TMP/$name.ready" "$phase" "$pid" && came=1
    t0=$(now)
    kill -"$sig" "$pid" 2>/dev/null
    # a program that does not hear the signal is stopped after 60 s
    ( i=0; while kill -0 "$pid" 2>/dev/null && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
      kill -KILL "$pid" 2>/dev/null ) &
    guard=$!
    wait "$pid"
    rc=$?
    took=$(awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.2f", b - a}')
    kill "$guard" 2>/dev/null
    wait "$guard" 2>/dev/null
}
# Within 1 s of CPU work; the bound leaves room for a machine shared with
# other jobs, and for writing the tables.
prompt() { awk -v t="$took" 'BEGIN {exit !(t < 5)}'; }
# hidden files but adhere's manifest (.adhere-manifest) are temporaries
no_temporaries() { ! ls -a "$1" | grep -v '^\.adhere-manifest$' | grep -q '^\.'"[^.]"; }

# 1. One long step: eps tight and the start close in, so the first step
# alone runs for minutes; the flag is polled inside the step.
signal_run step relax INT --batch -q -N 1000 --eps=1e-22 --max-iter=100000000 --start=0.5nm --turn=-1nm
check "inside one long step: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "inside one long step: stopped within 5 s (${took} s)" prompt
check "the streamed table ends marked PARTIAL" grep -q '^# PARTIAL: interrupted' "$TMP/step.stdout"

# 2. A long dwell at the turn: every dwell iteration polls the flag.
signal_run dwell dwell TERM --batch -q --no-plot -N 200 --force --eps=10pm -d 0.5nm --turn=-1nm --dwell=100000000 -o "$TMP/dwell"
check "in a long dwell: SIGTERM heard, exit 143 (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 143 ]"
check "in a long dwell: stopped within 5 s (${took} s)" prompt
check "force.tsv says it is partial" grep -q "^# PARTIAL: interrupted" "$TMP/dwell/force.tsv"
check "summary.tsv says complete 0 and status interrupted" \
    sh -c "grep -qx 'complete	0' '$TMP/dwell/summary.tsv' && grep -qx 'status	interrupted' '$TMP/dwell/summary.tsv'"
n=$(grep -cv '^#' "$TMP/dwell/force.tsv")
check "the loading rows computed before the dwell are kept ($n lines)" [ "$n" -gt 10 ]
check "every kept row has all 13 columns" awk -F'\t' '!/^#/ && NF != 13 {bad=1} END {exit bad}' "$TMP/dwell/force.tsv"
check "no temporary file is left in the output directory" no_temporaries "$TMP/dwell"

# 3. --reference=static: the equilibrium curve after the relaxation run.
signal_run ref reference INT --batch -q --no-plot --eps=10pm -d 0.5nm --reference=static -o "$TMP/ref"
check "in --reference=static: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "in --reference=static: stopped within 5 s (${took} s)" prompt
check "static.tsv is kept, marked PARTIAL" grep -q "^# PARTIAL: interrupted by signal 2 during the static reference" "$TMP/ref/static.tsv"
check "summary.tsv says status interrupted, not success" grep -qx 'status	interrupted' "$TMP/ref/summary.tsv"
check "no plot is drawn from an interrupted run" sh -c "! ls '$TMP/ref' | grep -q png"

# 4. --mode=static: the continuation polls the flag at every Newton step.
signal_run static static INT --batch -q --no-plot --mode=static -o "$TMP/static"
check "in --mode=static: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "in --mode=static: stopped within 5 s (${took} s)" prompt
check "force.tsv is marked PARTIAL, status interrupted" \
    sh -c "grep -q '^# PARTIAL: interrupted' '$TMP/static/force.tsv' && grep -qx 'status	interrupted' '$TMP/static/summary.tsv'"

# 5. --cost: runs under way stop, runs not started say so; nothing says
# success with 0 s.
signal_run cost cost INT --cost -q --cost-nodes=500,1000 --cost-eps=1pm,0.5pm -o "$TMP/cost"
check "in --cost: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "in --cost: stopped within 5 s (${took} s)" prompt
check "cost.tsv and the report are marked PARTIAL" \
    sh -c "grep -q '^# PARTIAL: interrupted' '$TMP/cost/cost.tsv' && grep -q '^# PARTIAL: interrupted' '$TMP/cost.stdout'"
check "no run is listed as success" sh -c "! awk -F'\t' '\$NF == \"success\"' '$TMP/cost/cost.tsv' | grep -q ."
nr=$(awk -F'\t' '$NF == "not_run"' "$TMP/cost/cost.tsv" | wc -l)
check "runs never started say not_run ($nr of 8)" [ "$nr" -ge 1 ]
check "and have no time (nan, not 0 s)" awk -F'\t' '$NF == "not_run" && $4 != "nan" {bad=1} END {exit bad}' "$TMP/cost/cost.tsv"
signal_run costhup cost HUP --cost -q --cost-nodes=500,1000 --cost-eps=1pm,0.5pm -o "$TMP/costhup"
check "in --cost: SIGHUP heard, exit 129 (phase announced $came, exit $rc after ${took} s), cost.tsv PARTIAL" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 129 ] && grep -q '^# PARTIAL: interrupted by signal 1' '$TMP/costhup/cost.tsv'"
# 6. Ctrl-C while plotting reaches gnuplot too (the whole process group):
# the tables stay complete, no temporary PNG, data file or directory is
# left, the exit says interrupted.
if command -v setsid >/dev/null 2>&1 && command -v gnuplot >/dev/null 2>&1; then
    mkdir -p "$TMP/tmpdir"
    rm -f "$TMP/plot.ready"
    TMPDIR="$TMP/tmpdir" ADHERE_READY_FILE="$TMP/plot.ready" setsid "$ADHERE" --batch -q -N 200 --force --eps=10pm -d 0.5nm --turn=-1nm \
        -o "$TMP/plot" >/dev/null 2>"$TMP/plot.stderr" &
    pid=$!
    came=0
    wait_phase "$TMP/plot.ready" plot "$pid" && came=1
    kill -INT -- "-$pid" 2>/dev/null || kill -INT "$pid"
    wait "$pid"
    rc=$?
    check "Ctrl-C while plotting: exit 130 (phase announced $came, got $rc: $(head -c 200 "$TMP/plot.stderr"))" \
        sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
    check "no temporary file in the output directory" no_temporaries "$TMP/plot"
    check "no plot data directory left in TMPDIR" sh -c "[ -z \"\$(ls -A '$TMP/tmpdir')\" ]"
    check "the tables are complete (force.tsv not PARTIAL)" sh -c "! grep -q '^# PARTIAL' '$TMP/plot/force.tsv'"
    check "summary.tsv says interrupted and names the figures not drawn" \
        sh -c "grep -qx 'status	interrupted' '$TMP/plot/summary.tsv' && grep -q '^not_written	.*png' '$TMP/plot/summary.tsv'"
else
    T=$((T + 1)); echo "ok $T # SKIP setsid or gnuplot missing: no process group to interrupt"
fi

# 7. A sweep: every run polls the same flag; none is listed as done.
printf '[sweep]\nE = 0.3GPa, 0.5GPa, 1GPa, 2GPa\n' >"$TMP/sweep.scene"
signal_run sweep sweep INT --batch -q --no-plot -N 1000 --eps=1e-22 --max-iter=100000000 --start=0.5nm --turn=-1nm -o "$TMP/sweep" "$TMP/sweep.scene"
check "in a sweep: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "in a sweep: stopped within 5 s (${took} s)" prompt
check "sweep.tsv lists every run as interrupted" \
    awk -F'\t' '!/^#/ && $1 != "run" {n++; if ($NF != "interrupted") bad=1} END {exit bad || n != 4}' "$TMP/sweep/sweep.tsv"
check "sweep.tsv says # PARTIAL: $(grep '^# PARTIAL' "$TMP/sweep/sweep.tsv")" \
    grep -q '^# PARTIAL: interrupted by signal 2: 0 of 4 runs finished' "$TMP/sweep/sweep.tsv"
check "and the run closes saying interrupted: $(tail -n 1 "$TMP/sweep.stderr")" \
    grep -q '^adhere: interrupted by signal 2: 0 of 4 runs finished' "$TMP/sweep.stderr"
# SIGTERM (a job scheduler's) and SIGHUP (the terminal closed) stop a
# study the same way; the exit says which (128 + its number).
for sig in TERM HUP; do
    case $sig in TERM) want=143 num=15 ;; *) want=129 num=1 ;; esac
    signal_run "sweep$sig" sweep $sig --batch -q --no-plot -N 1000 --eps=1e-22 --max-iter=100000000 --start=0.5nm \
        --turn=-1nm -o "$TMP/sweep$sig" "$TMP/sweep.scene"
    check "in a sweep: SIG$sig heard, exit $want (phase announced $came, exit $rc after ${took} s)" \
        sh -c "[ $came -eq 1 ] && [ $rc -eq $want ]"
    check "... sweep.tsv says # PARTIAL: interrupted by signal $num" \
        grep -q "^# PARTIAL: interrupted by signal $num: 0 of 4 runs finished" "$TMP/sweep$sig/sweep.tsv"
    check "... no temporary file is left" no_temporaries "$TMP/sweep$sig"
done

# 8. A sweep's shared kernel: a large dense ring kernel takes seconds to
# build, and the build polls the flag (before any run, so nothing is
# written). Past 4000 nodes only --operator=dense asks for it.
signal_run kernel kernel INT --batch -q --no-plot -N 6000 --spacing=0.25nm --kernel=ring --operator=dense -o "$TMP/kernel" "$TMP/sweep.scene"
check "building a sweep's kernel: SIGINT heard (phase announced $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ]"
check "building a sweep's kernel: stopped within 5 s (${took} s)" prompt
check "and says nothing was computed" grep -q "while building the .*kernel: nothing computed" "$TMP/kernel.stderr"
# 9. gnuplot slow to answer (a figure of millions of points): the wait for
# it hears SIGINT (batch) and SIGTERM (the TUI's p) within 1 s, kills it,
# and the run says which figures it did not draw. The stand-in takes every
# command and never answers; it says when it started (its readiness file).
cat >"$TMP/gp-slow" <<EOF
#!/bin/sh
: >"\$GP_STARTED"
# its output kept open (fd 3), as a gnuplot still drawing keeps it
exec cat 3>&1 >/dev/null
EOF
chmod +x "$TMP/gp-slow"
# gnuplot_wait NAME SIG ARGS...: adhere with ARGS and the slow gnuplot; SIG
# once gnuplot has started; sets rc, took, came as signal_run does.
gnuplot_wait() {
    name=$1 sig=$2
    shift 2
    rm -f "$TMP/$name.started"
    GP_STARTED="$TMP/$name.started" ADHERE_GNUPLOT="$TMP/gp-slow" "$ADHERE" "$@" >"$TMP/$name.stdout" 2>"$TMP/$name.stderr" &
    pid=$!
    came=0 i=0
    while [ $i -lt 600 ] && kill -0 "$pid" 2>/dev/null; do
        [ -e "$TMP/$name.started" ] && { came=1; break; }
        sleep 0.1
        i=$((i + 1))
    done
    t0=$(now)
    kill -"$sig" "$pid" 2>/dev/null
    ( i=0; while kill -0 "$pid" 2>/dev/null && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
      kill -KILL "$pid" 2>/dev/null ) &
    guard=$!
    wait "$pid"
    rc=$?
    took=$(awk -v a="$t0" -v b="$(now)" 'BEGIN {printf "%.2f", b - a}')
    kill "$guard" 2>/dev/null
    wait "$guard" 2>/dev/null
}
within1() { awk -v t="$took" 'BEGIN {exit !(t < 1)}'; }
mkdir -p "$TMP/gptmp"
TMPDIR="$TMP/gptmp" gnuplot_wait gpwait INT --batch -q -N 100 --force --eps=10pm -o "$TMP/gpwait"
check "SIGINT while gnuplot draws: exit 130 within 1 s (gnuplot started $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ] && awk -v t=$took 'BEGIN {exit !(t < 1)}'"
check "... summary.tsv says interrupted and names the figures not drawn" \
    sh -c "grep -qx 'status	interrupted' '$TMP/gpwait/summary.tsv' && grep -q '^not_written	force.png' '$TMP/gpwait/summary.tsv'"
check "... no temporary left, in the directory or in TMPDIR" \
    sh -c "no_tmp() { ! ls -a \"\$1\" | grep -v '^\\.adhere-manifest\$' | grep -q '^\\.'\"[^.]\"; }; no_tmp '$TMP/gpwait' && [ -z \"\$(ls -A '$TMP/gptmp')\" ]"
# a sweep: its runs finished, their figures stopped; sweep.tsv says what
# each run's summary.tsv says (it used to say success, with no # PARTIAL
# line though the closing line pointed at one)
printf '[sweep]\neps = 10pm, 20pm\n' >"$TMP/gpsweep.scene"
TMPDIR="$TMP/gptmp" gnuplot_wait gpsweep INT --batch -q -R 1um -d 0.5nm --turn=-1nm --plots=force "$TMP/gpsweep.scene" \
    -o "$TMP/gpsweep"
sweep_word() { awk -F'\t' -v r="$1" '$1 == r {print $NF}' "$TMP/gpsweep/sweep.tsv"; }
check "SIGINT while gnuplot draws a sweep's figures: exit 130 within 1 s (gnuplot started $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 130 ] && awk -v t=$took 'BEGIN {exit !(t < 1)}'"
check "... each run's summary.tsv and sweep.tsv say interrupted (sweep.tsv: $(sweep_word 1), $(sweep_word 2))" \
    sh -c "grep -qx 'status	interrupted' '$TMP/gpsweep/run-1/summary.tsv' && grep -qx 'status	interrupted' '$TMP/gpsweep/run-2/summary.tsv' && [ '$(sweep_word 1)' = interrupted ] && [ '$(sweep_word 2)' = interrupted ]"
# a study draws a run's figures as it ends: the other run may still be
# stepping when the signal comes (then it is the one not finished)
check "... and sweep.tsv has its # PARTIAL line ($(grep '^# PARTIAL' "$TMP/gpsweep/sweep.tsv"))" \
    grep -Eq '^# PARTIAL: interrupted by signal 2( while the figures were drawn|: 1 of 2 runs finished)' "$TMP/gpsweep/sweep.tsv"
# one run: it ends, then its figures are stopped; its row keeps its numbers
printf '[sweep]\neps = 10pm\n' >"$TMP/gpone.scene"
TMPDIR="$TMP/gptmp" gnuplot_wait gpone INT --batch -q -R 1um -d 0.5nm --turn=-1nm --plots=force "$TMP/gpone.scene" \
    -o "$TMP/gpone"
check "a one-run sweep's figures stopped: sweep.tsv says every run finished, the row keeps its pull-off" \
    sh -c "grep -q '^# PARTIAL: interrupted by signal 2 while the figures were drawn' '$TMP/gpone/sweep.tsv' && awk -F'\t' '\$1 == 1 && \$11 + 0 < 0 && \$NF == \"interrupted\" {k++} END {exit !k}' '$TMP/gpone/sweep.tsv'"
printf ':set N 100\n:set spacing 10nm\n:set eps 10pm\n3f\np\n' >"$TMP/gpwait.keys"
# (not in a subshell: rc, came and took are the caller's)
gnuplot_wait tuiwait TERM --replay="$TMP/gpwait.keys" --screen="$TMP/gpwait.screen" --no-clock -o "$TMP/tuiwait" </dev/null
check "SIGTERM during the TUI's p while gnuplot draws: exit 143 within 1 s (gnuplot started $came, exit $rc after ${took} s)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 143 ] && awk -v t=$took 'BEGIN {exit !(t < 1)}'"
done_testing
