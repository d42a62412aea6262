#!/bin/sh
# Studies: a 2-D map of 16 runs (sigma x turn, tiny settings) split into 3
# shards run under GNU parallel and joined by adhere merge equals the study
# run whole (its table but for the timing column, and its map.png); a
# rerun redoes only the run whose result was removed; merge refuses shards
# of different studies or splits, a shard given twice, runs missing, a
# shard still running or cut short (unless --allow-partial, which marks
# the table # PARTIAL); two shards are never written into one directory;
# runs that share a loading branch match the runs stepped alone; ranges
# and the plan's count, time and refusals; an eps study merged has Figure
# 7's static line (# static_hysteresis) as the whole study does; a study
# of another build (its numerics id) is never resumed (--overwrite runs it
# again) nor merged with another build's shards; a resumed study's manifest
# keeps no stale record; a merge whose figure cannot be written commits its
# table and keeps the earlier figure only when it is this table's.
. "$(dirname "$0")/lib.sh"

cp "$(dirname "$0")/map.scene" "$TMP/map.scene"
TINY="--batch -N 100 --force --eps=10pm"
# the table without its timing column (seconds, the 15th) and without the
# scene's path (the same file here)
untimed() { grep -v '^# scene:' "$1" | cut -f1-14,16-; }
rows() { grep -v '^#' "$1" | tail -n +2; }
# reprove DIR NAME: the manifest's record of DIR/NAME made that of the
# file there now, as the adhere that wrote it would have left it: the test
# plays another build (or a killed run) that wrote it
reprove() {
    rec=$(stat --printf '%d\t%i\t%s\t%.9Y\t%.9Z' "$1/$2") &&
        grep -v "^$2	" "$1/.adhere-manifest" >"$TMP/manifest.new" &&
        printf '%s\t%s\n' "$2" "$rec" >>"$TMP/manifest.new" && cat "$TMP/manifest.new" >"$1/.adhere-manifest"
}
# this build's numerics id, as --version prints it
NUMERICS=$("$ADHERE" --version | awk '$1 == "numerics" {print $2}')

# --- the study whole, then in 3 shards under GNU parallel, then merged ---
"$ADHERE" $TINY -q "$TMP/map.scene" -o "$TMP/whole" 2>"$TMP/whole.err"
rc=$?
check "the 16-run map runs whole (exit $rc: $(head -c 300 "$TMP/whole.err"))" [ "$rc" -eq 0 ]
check "its sweep.tsv has 16 rows" [ "$(rows "$TMP/whole/sweep.tsv" | wc -l)" -eq 16 ]
check "and a map.png (2 swept keys: the heat map)" [ -s "$TMP/whole/map.png" ]
if command -v parallel >/dev/null 2>&1; then
    parallel --will-cite "$ADHERE" $TINY -q "$TMP/map.scene" --shard {}/3 -o "$TMP/shard{}" ::: 1 2 3 2>"$TMP/par.err"
    rc=$?
    check "3 shards under GNU parallel (exit $rc: $(head -c 300 "$TMP/par.err"))" [ "$rc" -eq 0 ]
    n1=$(rows "$TMP/shard1/runs.tsv" | wc -l) n2=$(rows "$TMP/shard2/runs.tsv" | wc -l) n3=$(rows "$TMP/shard3/runs.tsv" | wc -l)
    check "each shard stepped its drives: 8 + 4 + 4 runs ($n1 + $n2 + $n3; a drive is a sigma's four turns)" \
        [ "$n1 $n2 $n3" = "8 4 4" ]
    check "a shard writes no sweep.tsv of its own (adhere merge does)" [ ! -e "$TMP/shard1/sweep.tsv" ]
    "$ADHERE" merge -o "$TMP/merged" "$TMP/shard3" "$TMP/shard1" "$TMP/shard2" 2>"$TMP/merge.err"
    rc=$?
    check "adhere merge joins them (exit $rc: $(head -c 300 "$TMP/merge.err"))" [ "$rc" -eq 0 ]
    # without -o, sweep.tsv on a standard output that cannot be written: it
    # exited 2 without a word, the table lost
    "$ADHERE" merge "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" >/dev/full 2>"$TMP/full.err"
    rc=$?
    check "adhere merge to a full standard output: exit 2, saying so ($rc: $(cat "$TMP/full.err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q '^adhere merge: cannot write sweep.tsv to standard output: No space left on device' '$TMP/full.err'"
    check "the merged sweep.tsv is the whole study's but for its timing column" \
        sh -c "untimed() { grep -v '^# scene:' \"\$1\" | cut -f1-14,16-; }; untimed '$TMP/whole/sweep.tsv' >'$TMP/a'; untimed '$TMP/merged/sweep.tsv' >'$TMP/b'; cmp -s '$TMP/a' '$TMP/b'"
    check "the merged map.png is the whole study's, byte for byte" cmp -s "$TMP/whole/map.png" "$TMP/merged/map.png"
    check "and the timing column is really there to differ (16 times, each > 0)" \
        awk -F'\t' '!/^#/ && $1 != "run" {n++; if (!($15 > 0)) bad = 1} END {exit bad || n != 16}' "$TMP/merged/sweep.tsv"
    # the Slurm example's task resubmitted alone (sbatch --array=2, as for a
    # task that failed): with ADHERE_SHARDS (submit.sh sets it) its index is
    # the shard, 2/3 again, and it merges with the others; the array's own
    # numbering made it shard 1/1, refused in shard-1's directory
    mkdir -p "$TMP/slurm" && cp -r "$TMP/shard1" "$TMP/slurm/shard-1" && cp -r "$TMP/shard3" "$TMP/slurm/shard-3"
    SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=2 SLURM_ARRAY_TASK_COUNT=1 ADHERE_SHARDS=3 ADHERE="$ADHERE" \
        ADHERE_SCENE="$TMP/map.scene" ADHERE_OUT="$TMP/slurm" ADHERE_ARGS="$TINY" \
        sh "${ADHERE_SRC:-.}/share/adhere/examples/study.sbatch" 2>"$TMP/sb.err"
    rc=$?
    "$ADHERE" merge -q --no-plot -o "$TMP/slurm/merged" "$TMP"/slurm/shard-* 2>>"$TMP/sb.err"
    check "the Slurm example's task 2 resubmitted alone is shard 2/3 and merges (exit $rc $?: $(head -c 300 "$TMP/sb.err"))" \
        sh -c "grep -q '^shard	2/3\$' '$TMP/slurm/shard-2/study.tsv' && [ \"\$(grep -vc '^#' '$TMP/slurm/merged/sweep.tsv')\" -eq 17 ]"
    # a signal while the merge draws (a gnuplot that never answers, which
    # says when it started): the earlier merge's table and figure stay as
    # they were, no temporary is left, exit 128 + the signal's number
    printf '#!/bin/sh\n: >"$GP_STARTED"\nexec cat 3>&1 >/dev/null\n' >"$TMP/gp-slow"
    chmod +x "$TMP/gp-slow"
    cp "$TMP/merged/sweep.tsv" "$TMP/merged.tsv"
    mkdir -p "$TMP/mtmp"
    for sig in TERM HUP INT; do
        rm -f "$TMP/gp.started"
        GP_STARTED="$TMP/gp.started" ADHERE_GNUPLOT="$TMP/gp-slow" TMPDIR="$TMP/mtmp" \
            "$ADHERE" merge -o "$TMP/merged" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" 2>"$TMP/merge.err" &
        pid=$! i=0
        while [ $i -lt 600 ] && [ ! -e "$TMP/gp.started" ] && kill -0 $pid 2>/dev/null; do sleep 0.1; i=$((i + 1)); done
        kill -$sig $pid
        wait $pid
        rc=$?
        case $sig in TERM) want=143 ;; HUP) want=129 ;; *) want=130 ;; esac
        check "SIG$sig while merge draws: exit $want ($rc: $(head -c 300 "$TMP/merge.err"))" [ "$rc" -eq $want ]
        check "... the earlier merge's sweep.tsv and map.png are as they were" \
            sh -c "cmp -s '$TMP/merged.tsv' '$TMP/merged/sweep.tsv' && cmp -s '$TMP/whole/map.png' '$TMP/merged/map.png'"
        check "... no temporary left, in the directory or in TMPDIR" \
            sh -c "! ls -a '$TMP/merged' | grep -v '^\.adhere-manifest\$' | grep -q '^\.[^.]' && [ -z \"\$(ls -A '$TMP/mtmp')\" ]"
    done
    "$ADHERE" merge -q --no-plot -o "$TMP/merged" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" 2>"$TMP/merge.err"
    rc=$?
    check "a merge without figures into an earlier one's directory (exit $rc): its sweep.tsv, the earlier map.png gone" \
        sh -c "[ $rc -eq 0 ] && cmp -s '$TMP/merged.tsv' '$TMP/merged/sweep.tsv' && [ ! -e '$TMP/merged/map.png' ]"
    # submit.sh with a stand-in for Slurm's sbatch (make check-slurm runs
    # the real one): it runs the array's tasks under GNU parallel, then the
    # merge. A scene, a directory and a flag's value with a space in them
    # (and a quote): ADHERE_ARGS="$*" split --gnuplot-style's path into
    # three words, and every task stopped on a scene path that is not one.
    # The style's directory name ends in two newlines: submit.sh's $(...)
    # dropped them, and every task was refused a directory that is not there
    styled="$TMP/it's styled

"
    mkdir -p "$TMP/fake bin" "$TMP/sub scenes" "$styled"
    : >"$styled/style.gp"
    printf '[scene]\nmode = rigid\n[sweep]\nE = 1GPa, 2GPa, 3GPa, 4GPa\n' >"$TMP/sub scenes/rigid map.scene"
    cat >"$TMP/fake bin/sbatch" <<'EOF'
#!/bin/sh
# sbatch's stand-in: --array=LO-HI runs the script's tasks now under GNU
# parallel, else the script; prints a job id
array= dir=.
while [ $# -gt 1 ]; do
    case $1 in --array=*) array=${1#--array=} ;; --chdir=*) dir=${1#--chdir=} ;; esac
    shift
done
cd "$dir" || exit 1
if [ -n "$array" ]; then
    lo=${array%-*} hi=${array#*-}
    export SLURM_ARRAY_TASK_MIN=$lo SLURM_ARRAY_TASK_COUNT=$((hi - lo + 1))
    parallel --will-cite 'SLURM_ARRAY_TASK_ID={1} sh {2} >adhere-study-{1}.out 2>&1' ::: $(seq "$lo" "$hi") ::: "$1" ||
        exit 1
    echo 41
else
    sh "$1" >adhere-merge.out 2>&1 || exit 1
    echo 42
fi
EOF
    chmod +x "$TMP/fake bin/sbatch"
    # OUT's name ends in a newline too: submit.sh's $(cd OUT && pwd) dropped it
    subout="$TMP/sub out
"
    PATH="$TMP/fake bin:$PATH" ADHERE="$ADHERE" sh "${ADHERE_SRC:-.}/share/adhere/examples/submit.sh" \
        "$TMP/sub scenes/rigid map.scene" "$subout" 2 --gnuplot-style="$styled" -N 100 \
        >"$TMP/sub.out" 2>"$TMP/sub.err"
    rc=$?
    n=$(rows "$subout/merged/sweep.tsv" 2>/dev/null | wc -l)
    check "submit.sh: a scene, -o and --gnuplot-style with spaces, a quote and trailing newlines reach each task whole; 2 shards run and merge, 4 rows (exit $rc, $n rows: $(cat "$TMP/sub.out" "$TMP/sub.err" "$subout"/*.out 2>/dev/null | head -c 400))" \
        sh -c "[ $rc -eq 0 ] && [ $n -eq 4 ] && grep -q 'shards: job 41 (array 1-2), merge: job 42' '$TMP/sub.out'"
else
    not_ok "GNU parallel is not installed (make deps installs it)"
fi
# submit.sh with a shipped scene's name (fig3, whose [sweep] makes a
# study): it was made a path in the working directory, which every task was
# refused; and N checked before anything is made or queued (an sbatch that
# only records what each submission would run)
mkdir -p "$TMP/rec bin"
printf '#!/bin/sh\nprintf "%%s\\n" "${ADHERE_SCENE:-merge}" >>"$SBATCH_LOG"\necho 41\n' >"$TMP/rec bin/sbatch"
chmod +x "$TMP/rec bin/sbatch"
(cd "$TMP" && PATH="$TMP/rec bin:$PATH" SBATCH_LOG="$TMP/sbatch.log" sh "${ADHERE_SRC:-$OLDPWD}/share/adhere/examples/submit.sh" \
    fig3 "$TMP/shipped" 2 >"$TMP/rec.out" 2>&1)
rc=$?
check "submit.sh fig3 OUT 2: the tasks get the shipped scene's name, fig3, not a path to nothing (exit $rc: $(cat "$TMP/sbatch.log" "$TMP/rec.out" | head -c 300))" \
    sh -c "[ $rc -eq 0 ] && [ \"\$(head -n 1 '$TMP/sbatch.log')\" = fig3 ]"
for n in 0 x 1-3; do
    (cd "$TMP" && PATH="$TMP/rec bin:$PATH" SBATCH_LOG="$TMP/sbatch0.log" sh "${ADHERE_SRC:-$OLDPWD}/share/adhere/examples/submit.sh" \
        fig3 "$TMP/zero" "$n" >"$TMP/rec.out" 2>&1)
    rc=$?
    check "submit.sh fig3 OUT $n: exit 2 naming N, nothing made or queued (exit $rc: $(head -c 200 "$TMP/rec.out"))" \
        sh -c "[ $rc -eq 2 ] && grep -q \"N = '$n': give the number of shards\" '$TMP/rec.out' && [ ! -e '$TMP/zero' ] && [ ! -e '$TMP/sbatch0.log' ]"
done

# every run's status is carried: the merged row says what its run-K/summary.tsv says
bad=0
for k in $(seq 1 16); do
    s=$(awk -F'\t' '$1 == "status" {print $2}' "$TMP/whole/run-$k/summary.tsv")
    m=$(awk -F'\t' -v k="$k" '!/^#/ && $1 == k {print $NF}' "$TMP/merged/sweep.tsv")
    [ -n "$s" ] && [ "$s" = "$m" ] || bad=1
done
check "each run's status in the merged table is its summary.tsv's (here: unresolved, --force)" [ "$bad" -eq 0 ]

# --- an eps study's Figure 7: the merge draws the static curve's line too ---
printf '[sweep]\neps = 10pm, 40pm\nplot = force\n' >"$TMP/eps.scene"
EPS="--batch -q -R 1um -d 0.5nm --turn=-1nm"
"$ADHERE" $EPS "$TMP/eps.scene" -o "$TMP/epsw" 2>"$TMP/err" &&
    "$ADHERE" $EPS "$TMP/eps.scene" --shard=1/2 -o "$TMP/eps1" 2>>"$TMP/err" &&
    "$ADHERE" $EPS "$TMP/eps.scene" --shard=2/2 -o "$TMP/eps2" 2>>"$TMP/err" &&
    "$ADHERE" merge -q -o "$TMP/epsm" "$TMP/eps1" "$TMP/eps2" 2>>"$TMP/err"
rc=$?
check "an eps study whole and in 2 shards, merged (exit $rc: $(head -c 300 "$TMP/err"))" [ "$rc" -eq 0 ]
check "... both tables give the static curve's loop (# static_hysteresis) and are the same but for timing" \
    sh -c "grep -q '^# static_hysteresis: [0-9]' '$TMP/epsm/sweep.tsv' && untimed() { grep -v '^# scene:' \"\$1\" | cut -f1-14,16-; }; untimed '$TMP/epsw/sweep.tsv' >'$TMP/ea'; untimed '$TMP/epsm/sweep.tsv' >'$TMP/eb'; cmp -s '$TMP/ea' '$TMP/eb'"
check "... and Figure 7 with its hysteresis panel in each" sh -c "[ -s '$TMP/epsw/force.png' ] && [ -s '$TMP/epsm/force.png' ]"
# the static line is the merge's own arithmetic: shards of another build
# are merged for the table alone
cp -r "$TMP/eps1" "$TMP/eps1b" && cp -r "$TMP/eps2" "$TMP/eps2b"
sed -i 's/^numerics\t.*/numerics\t0123456789abcdef/' "$TMP/eps1b/study.tsv" "$TMP/eps2b/study.tsv"
"$ADHERE" merge -q -o "$TMP/epsb" "$TMP/eps1b" "$TMP/eps2b" 2>"$TMP/err"
rc=$?
check "eps shards of another build: Figure 7's static line refused, exit 2, both ids named ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'numerics ($NUMERICS) are not the shards. (0123456789abcdef)' '$TMP/err' && [ ! -e '$TMP/epsb/sweep.tsv' ]"
"$ADHERE" merge -q --no-plot -o "$TMP/epsb" "$TMP/eps1b" "$TMP/eps2b" 2>"$TMP/err"
rc=$?
check "... merged with --no-plot: the table alone, no # static_hysteresis ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && [ -s '$TMP/epsb/sweep.tsv' ] && ! grep -q static_hysteresis '$TMP/epsb/sweep.tsv'"

# --- a merge whose figure cannot be written (a file size limit between the
# table's size and the figure's): the new table is committed, exit 3; the
# earlier merge's figure stays when it is this table's, said so, and goes
# when it is another table's (an eps study's force.png), said so too ---
"$ADHERE" merge -q -o "$TMP/mfig" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" 2>/dev/null
tsv=$(wc -c <"$TMP/mfig/sweep.tsv") png=$(wc -c <"$TMP/mfig/map.png")
lim=$(( (tsv + png) / 1024 ))   # ulimit -f counts 512-byte blocks here (dash, POSIX)
check "a limit between sweep.tsv ($tsv bytes) and map.png ($png): $lim blocks of 512 bytes" \
    sh -c "[ $tsv -lt $((lim * 512)) ] && [ $((lim * 512)) -lt $png ]"
cp "$TMP/mfig/map.png" "$TMP/mfig.png"
ino=$(stat -c %i "$TMP/mfig/sweep.tsv")
(trap '' XFSZ; ulimit -f "$lim" && exec "$ADHERE" merge -o "$TMP/mfig" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3") 2>"$TMP/err"
rc=$?
check "a merge whose map.png passes ulimit -f: exit 3 ($rc: $(head -c 400 "$TMP/err"))" [ "$rc" -eq 3 ]
check "... its sweep.tsv committed (a new file, 16 rows)" \
    sh -c "[ \$(stat -c %i '$TMP/mfig/sweep.tsv') != $ino ] && [ \$(grep -v '^#' '$TMP/mfig/sweep.tsv' | tail -n +2 | wc -l) -eq 16 ]"
check "... the earlier merge's map.png, this table's, left in place as it was, and said so" \
    sh -c "cmp -s '$TMP/mfig.png' '$TMP/mfig/map.png' && grep -q 'the earlier map.png left in place: drawn from this table' '$TMP/err'"
check "... no temporary left" sh -c "! ls -a '$TMP/mfig' | grep -v '^\.adhere-manifest\$' | grep -q '^\.[^.]'"
# The earlier table is compared as it streams by, never held: an earlier
# sweep.tsv of 104 MB (this table, its seconds column padded with 6.5 MB of
# zeros a row: the column the comparison leaves out) under ulimit -v 225 MB
# (adhere itself takes some 80 MB here), where holding it and its cut copy
# (208 MB and more) cannot fit: the figure is kept; with one other field
# changed in its last row, removed.
awk -F'\t' -v OFS='\t' -v same="$TMP/big-same.tsv" -v other="$TMP/big-other.tsv" '
    BEGIN {z = "0"; while (length(z) < 6500000) z = z z; z = substr(z, 1, 6500000)}
    /^#/ {print >same; print >other; next}
    !col {for (i = 1; i <= NF; i++) if ($i == "seconds") col = i; print >same; print >other; next}
    {$col = $col z; print >same; n++; if (n == 16) $1 = $1 "0"; print >other}' "$TMP/mfig/sweep.tsv"
big=$(wc -c <"$TMP/big-same.tsv")
for what in same other; do
    cp "$TMP/big-$what.tsv" "$TMP/mfig/sweep.tsv" && reprove "$TMP/mfig" sweep.tsv
    (trap '' XFSZ; ulimit -f "$lim" && ulimit -v 230400 && exec "$ADHERE" merge -o "$TMP/mfig" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3") 2>"$TMP/err"
    rc=$?
    if [ $what = same ]; then
        check "an earlier sweep.tsv of $big bytes, this table but for its seconds, under ulimit -v 225 MB: exit 3, map.png kept ($rc: $(tail -n 1 "$TMP/err"))" \
            sh -c "[ $rc -eq 3 ] && [ $big -gt 104000000 ] && cmp -s '$TMP/mfig.png' '$TMP/mfig/map.png' && grep -q 'the earlier map.png left in place: drawn from this table' '$TMP/err'"
    else
        check "... another table's (its last row's run changed): map.png removed, said so ($rc: $(tail -n 1 "$TMP/err"))" \
            sh -c "[ $rc -eq 3 ] && [ ! -e '$TMP/mfig/map.png' ] && grep -q \"the earlier merge's map.png removed: drawn from another table\" '$TMP/err'"
    fi
done
rm -f "$TMP/big-same.tsv" "$TMP/big-other.tsv"
(trap '' XFSZ; ulimit -f "$lim" && exec "$ADHERE" merge -o "$TMP/epsm" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3") 2>"$TMP/err"
rc=$?
check "the same into an eps study's merge: exit 3, its force.png (another table's) removed, said so ($rc: $(head -c 400 "$TMP/err"))" \
    sh -c "[ $rc -eq 3 ] && [ ! -e '$TMP/epsm/force.png' ] && grep -q \"the earlier merge's force.png removed: drawn from another table\" '$TMP/err' && [ \$(grep -v '^#' '$TMP/epsm/sweep.tsv' | tail -n +2 | wc -l) -eq 16 ]"

# --- resumed: one run's result removed, the rerun steps that one alone ---
# (in place: a copy of the directory is not adhere's, its manifest says)
check "study.tsv records the build's numerics id, the one --version prints ($NUMERICS)" \
    sh -c "echo '$NUMERICS' | grep -qx '[0-9a-f]\{16\}' && grep -qx 'numerics	$NUMERICS' '$TMP/whole/study.tsv'"
rm -r "$TMP/whole/run-7"
# beside it: a file of the user's, a temporary a killed run left (in the
# manifest) and a file of the user's under a temporary's name (not in it)
echo mine >"$TMP/whole/notes.txt"
echo cut >"$TMP/whole/.runs.tsv.Kil1ed" && reprove "$TMP/whole" .runs.tsv.Kil1ed
echo mine >"$TMP/whole/.sweep.tsv.Mine12"
# a temporary recorded as adhere records one, before a byte goes into it:
# by identity and birth time; one a killed run left goes, and one the user
# removed and made again under its name (the filesystem giving it the freed
# inode, played by the record's inode: the user's file there now, born a
# second after the temporary) stays: the identity alone removed it
idrec() { printf '%s	%s	-	-	%s
' "$2" "$(stat --printf '%d	%i' "$1/$2")" "$3" >>"$1/.adhere-manifest"; }
echo cut >"$TMP/whole/.runs.tsv.Kil3ed" && idrec "$TMP/whole" .runs.tsv.Kil3ed "$(stat --printf '%.9W' "$TMP/whole/.runs.tsv.Kil3ed")"
echo mine >"$TMP/whole/.map.png.Mine34" &&
    idrec "$TMP/whole" .map.png.Mine34 "$(stat --printf '%.9W' "$TMP/whole/.map.png.Mine34" | awk '{printf "%.9f", $1 - 1}')"
"$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/whole" 2>"$TMP/resume.err"
rc=$?
check "the rerun exits 0 ($rc)" [ "$rc" -eq 0 ]
ran=$(grep -o '^adhere: run [0-9]* of 16' "$TMP/resume.err" | awk '{print $3}' | tr '\n' ' ')
check "it stepped run 7 and no other (ran: $ran)" [ "$ran" = "7 " ]
check "and says 15 were done before" grep -q '(15 done before, kept)' "$TMP/resume.err"
check "run-7 is back, its table the same but for timing" \
    sh -c "[ -s '$TMP/whole/run-7/summary.tsv' ] && grep -v '^# scene:' '$TMP/whole/sweep.tsv' | cut -f1-14,16- | cmp -s - '$TMP/a'"
# the record of the run-7 removed goes with it (it stayed for good before):
# one record of each run-K, each the directory there now
n7=$(grep -c '^run-7/' "$TMP/whole/.adhere-manifest")
stale=0
for k in $(seq 1 16); do
    [ "$(awk -F'\t' -v n="run-$k/" '$1 == n {print $3}' "$TMP/whole/.adhere-manifest")" = "$(stat -c %i "$TMP/whole/run-$k")" ] ||
        stale=$((stale + 1))
done
check "the manifest keeps one record of run-7 ($n7), each run-K's the directory there ($stale not)" \
    [ "$n7/$stale/$(grep -c '^run-' "$TMP/whole/.adhere-manifest")" = "1/0/16" ]
check "... the killed run's temporary is gone with its record" \
    sh -c "[ ! -e '$TMP/whole/.runs.tsv.Kil1ed' ] && ! grep -q Kil1ed '$TMP/whole/.adhere-manifest'"
check "... the user's files stay (notes.txt, .sweep.tsv.Mine12)" \
    sh -c "[ \"\$(cat '$TMP/whole/notes.txt')\" = mine ] && [ \"\$(cat '$TMP/whole/.sweep.tsv.Mine12')\" = mine ]"
check "... a temporary recorded by identity and birth time is gone with its record (.runs.tsv.Kil3ed)" \
    sh -c "[ ! -e '$TMP/whole/.runs.tsv.Kil3ed' ] && ! grep -q Kil3ed '$TMP/whole/.adhere-manifest'"
check "... the user's file made under a temporary's name on its inode, born after it, stays (.map.png.Mine34)" \
    sh -c "[ \"\$(cat '$TMP/whole/.map.png.Mine34' 2>/dev/null)\" = mine ] && ! grep -q Mine34 '$TMP/whole/.adhere-manifest'"

# --- a study of another build: never resumed, its rows never mixed ---
# (the numerics id is the Makefile's hash of the sources that decide the
# numbers: another build is played by study.tsv's id line, edited, and the
# manifest's record of it, as that build's adhere would have left them)
"$ADHERE" $TINY -q "$TMP/map.scene" -o "$TMP/build" 2>/dev/null
echo mine >"$TMP/build/notes.txt" && echo mine >"$TMP/build/run-3/notes.txt"
# another version of one numerics: the same numbers, so it resumes (before,
# a version alone cleared the study and ran it again)
sed -i 's/^version\t.*/version\t0.0.1/' "$TMP/build/study.tsv" && reprove "$TMP/build" study.tsv
"$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/build" 2>"$TMP/err"
rc=$?
check "a study of another version with this numerics id resumes: exit 0, every run kept ($rc: $(head -c 300 "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && ! grep -q '^adhere: run ' '$TMP/err' && grep -q '16 done before, kept' '$TMP/err'"
sed -i 's/^numerics\t.*/numerics\t0123456789abcdef/' "$TMP/build/study.tsv" && reprove "$TMP/build" study.tsv
cp "$TMP/build/runs.tsv" "$TMP/build.runs"
"$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/build" 2>"$TMP/err"
rc=$?
check "a rerun on a study of another numerics id: exit 2, both ids named ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'another build of adhere (numerics there: 0123456789abcdef; this adhere.s: $NUMERICS)' '$TMP/err'"
check "... what to do said: a new -o, or --overwrite to run it again from scratch" \
    sh -c "grep -q 'give a new -o' '$TMP/err' && grep -q -- '--overwrite to run the study again from scratch' '$TMP/err'"
# --overwrite removes more than adhere recorded (every file under its names,
# a killed run's temporaries too): the advice says so, as adhere(1) does
check "... and what --overwrite removes: every file under adhere's names, written by it or not, as adhere(1) says" \
    sh -c "grep -qF \"it removes every file there under adhere's names, whether adhere wrote it or not\" '$TMP/err' &&
           grep -qF \"a killed run's temporaries, as --overwrite in adhere(1) says; other files stay\" '$TMP/err'"
check "... nothing run, nothing changed (runs.tsv, study.tsv's id)" \
    sh -c "! grep -q '^adhere: run ' '$TMP/err' && cmp -s '$TMP/build.runs' '$TMP/build/runs.tsv' && grep -qx 'numerics	0123456789abcdef' '$TMP/build/study.tsv'"
# a study.tsv from before adhere recorded the id: an unknown build
sed -i '/^numerics\t/d' "$TMP/build/study.tsv" && reprove "$TMP/build" study.tsv
"$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/build" 2>"$TMP/err"
rc=$?
check "a study.tsv with no numerics id (before ids): exit 2, said so, the same advice ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'numerics there: none, its study.tsv predates numerics ids' '$TMP/err' && grep -q -- '--overwrite' '$TMP/err' && cmp -s '$TMP/build.runs' '$TMP/build/runs.tsv'"
# an id line this build cannot read (garbled, or another build's form), or
# two of them: this study (its fingerprint) of a build unknown, refused
# alike; it was taken for another study's and cleared, the study run again
# without --overwrite ("line 4 is not adhere's; starting the study afresh")
for what in 'an id in capitals' 'two ids, this build'"'"'s second'; do
    case $what in
    an*) idline='numerics\t0123456789ABCDEF' ;;
    *) idline="numerics\t0123456789abcdef\nnumerics\t$NUMERICS" ;;
    esac
    sed -i '/^numerics\t/d' "$TMP/build/study.tsv" && sed -i "s/^fingerprint\t.*/&\n$idline/" "$TMP/build/study.tsv" &&
        reprove "$TMP/build" study.tsv
    "$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/build" 2>"$TMP/err"
    rc=$?
    check "a study.tsv of this study with $what: exit 2, nothing run or changed ($rc: $(head -c 400 "$TMP/err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q 'numerics there: unreadable' '$TMP/err' && grep -q -- '--overwrite' '$TMP/err' && ! grep -q '^adhere: run ' '$TMP/err' && cmp -s '$TMP/build.runs' '$TMP/build/runs.tsv'"
done
echo theirs >"$TMP/build/.runs.tsv.Ab12Cd"   # a temporary's name, in no manifest
"$ADHERE" $TINY "$TMP/map.scene" --overwrite -o "$TMP/build" 2>"$TMP/err"
rc=$?
check "... --overwrite's note says what it removes, and it did: the unrecorded temporary's name went too" \
    sh -c "grep -qF -- \"--overwrite: it removes every file there under adhere's names, whether adhere wrote it or not\" '$TMP/err' &&
           [ ! -e '$TMP/build/.runs.tsv.Ab12Cd' ]"
ran=$(grep -c '^adhere: run [0-9]* of 16' "$TMP/err")
check "--overwrite: exit $rc, the whole study run again from scratch ($ran runs stepped, none kept)" \
    sh -c "[ $rc -eq 0 ] && [ $ran -eq 16 ] && ! grep -q 'done before' '$TMP/err' && grep -q 'runs again from scratch' '$TMP/err'"
check "... study.tsv now this build's id, sweep.tsv the study's but for timing" \
    sh -c "grep -qx 'numerics	$NUMERICS' '$TMP/build/study.tsv' && grep -v '^# scene:' '$TMP/build/sweep.tsv' | cut -f1-14,16- | cmp -s - '$TMP/a'"
check "... the user's files stay (notes.txt, run-3/notes.txt)" \
    sh -c "[ \"\$(cat '$TMP/build/notes.txt')\" = mine ] && [ \"\$(cat '$TMP/build/run-3/notes.txt')\" = mine ]"
"$ADHERE" $TINY "$TMP/map.scene" -o "$TMP/build" 2>"$TMP/err"
check "... and a rerun of this build resumes it (16 done before, kept)" grep -q '(16 done before, kept)' "$TMP/err"

# --- runs sharing a loading branch against the same runs stepped alone ---
# run 6: sigma = 3, turn -1 nm; its own run loads to -1 nm and unloads
E6=$(awk -F'\t' '!/^#/ && $1 == 6 {print $4}' "$TMP/whole/sweep.tsv")
"$ADHERE" $TINY -q --plots=none -E "$E6" --turn=-1nm -o "$TMP/alone" 2>/dev/null
for key in pulloff_F max_load jump_out_h0 steps iterations; do
    a=$(awk -F'\t' -v k=$key '$1 == k {print $2}' "$TMP/alone/summary.tsv")
    col=$(grep -v '^#' "$TMP/whole/sweep.tsv" | head -1 | tr '\t' '\n' | grep -nx "$key" | cut -d: -f1)
    b=$(awk -F'\t' -v c="$col" '!/^#/ && $1 == 6 {print $c}' "$TMP/whole/sweep.tsv")
    check "run 6 on the shared branch: $key $b, alone $a (within 1e-9)" \
        awk -v a="$a" -v b="$b" 'BEGIN {d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a; exit !(d <= 1e-9 * s)}'
done

# --- merge's refusals ---
M="$ADHERE merge"
$M -o "$TMP/m1" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" "$TMP/shard2" 2>"$TMP/err"
check "a shard given twice: exit 2, its runs listed ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'runs 5-8 are in' '$TMP/err'"
S2=$TMP/shard2
$M -o "$TMP/m1" "$TMP/shard1" $S2 $S2 $S2 $S2 $S2 $S2 "$TMP/shard3" 2>"$TMP/err"
check "a shard given 6 times (more runs twice than the study has): exit 2, each run listed once ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'runs 5-8 are in' '$TMP/err' && ! grep -q 'in all' '$TMP/err'"
# two directories that both say shard 2/3 (one run of it stopped after runs
# 5-6, another after 7-8): together they hold every run, yet are not parts
# to join
mkdir "$TMP/twoA" "$TMP/twoB"
for d in twoA twoB; do cp "$TMP/shard2/study.tsv" "$TMP/$d/"; grep '^#' "$TMP/shard2/runs.tsv" >"$TMP/$d/runs.tsv"; done
grep -v '^#' "$TMP/shard2/runs.tsv" | head -1 | tee -a "$TMP/twoA/runs.tsv" >>"$TMP/twoB/runs.tsv"
awk -F'\t' '$1 == 5 || $1 == 6' "$TMP/shard2/runs.tsv" >>"$TMP/twoA/runs.tsv"
awk -F'\t' '$1 == 7 || $1 == 8' "$TMP/shard2/runs.tsv" >>"$TMP/twoB/runs.tsv"
$M -o "$TMP/m9" "$TMP/shard1" "$TMP/twoA" "$TMP/twoB" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "two directories both holding shard 2/3: exit 2, both and the shard named ($(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'twoA and .*twoB both hold shard 2/3' '$TMP/err' && [ ! -e '$TMP/m9/sweep.tsv' ]"
$M -o "$TMP/m2" "$TMP/shard1" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "a shard missing: exit 2, its runs listed ($(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'runs 5-8 (shards not given: 2/3)' '$TMP/err' && [ ! -e '$TMP/m2/sweep.tsv' ]"
$M --allow-partial -o "$TMP/m3" "$TMP/shard1" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "--allow-partial joins what there is (exit $rc)" [ "$rc" -eq 0 ]
check "... and marks the table # PARTIAL, naming the runs" grep -q '^# PARTIAL: 12 of 16 runs have results.*runs 5-8' "$TMP/m3/sweep.tsv"
check "... the runs without a result say not run" \
    awk -F'\t' '!/^#/ && $1 >= 5 && $1 <= 8 && $NF != "not run" {bad = 1} END {exit bad}' "$TMP/m3/sweep.tsv"
# shards of another build: study.tsv's id edited in a copy (merge reads the
# shards' records, not their manifests)
cp -r "$TMP/shard2" "$TMP/built2"
sed -i 's/^numerics\t.*/numerics\t0123456789abcdef/' "$TMP/built2/study.tsv"
$M -o "$TMP/mb" "$TMP/shard1" "$TMP/built2" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "shards of different numerics ids: exit 2, the shards and ids named, nothing written ($(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'shard1 (numerics $NUMERICS) and .*built2 (numerics 0123456789abcdef) were not computed by one build' '$TMP/err' && [ ! -e '$TMP/mb/sweep.tsv' ]"
sed -i '/^numerics\t/d' "$TMP/built2/study.tsv"
$M -o "$TMP/mb" "$TMP/shard1" "$TMP/built2" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "a shard with no numerics id (before ids): exit 2, said so, nothing written ($(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'built2 (numerics none, its study.tsv predates numerics ids: an unknown build)' '$TMP/err' && [ ! -e '$TMP/mb/sweep.tsv' ]"
"$ADHERE" $TINY -q "$TMP/map.scene" --dwell=5 --shard 2/3 -o "$TMP/other" 2>/dev/null
$M -o "$TMP/m4" "$TMP/shard1" "$TMP/other" "$TMP/shard3" 2>"$TMP/err"
rc=$?
check "shards of different studies: exit 2, what differs named ($(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'different studies.*protocol.dwell = 5' '$TMP/err'"
$M -o "$TMP/m3" "$TMP/shard1" "$TMP/other" 2>/dev/null
rc=$?
check "a refused merge into an earlier merge's directory (exit $rc) leaves its table" \
    sh -c "[ $rc -eq 2 ] && grep -q '^# PARTIAL: 12 of 16' '$TMP/m3/sweep.tsv'"
# --overwrite replaces the user's files under adhere's names with the
# merge's: a merge refused writes nothing, so removes none of them
mkdir "$TMP/mine" && echo mine >"$TMP/mine/map.png"
$M --overwrite -o "$TMP/mine" "$TMP/shard1" "$TMP/shard2" 2>"$TMP/err"
rc=$?
check "a refused merge with --overwrite (exit $rc) leaves the user's map.png in -o" \
    sh -c "[ $rc -eq 2 ] && grep -q 'runs 9-12' '$TMP/err' && [ \"\$(cat '$TMP/mine/map.png')\" = mine ]"
"$ADHERE" $TINY -q "$TMP/map.scene" --shard 2/4 -o "$TMP/split4" 2>/dev/null
$M -o "$TMP/m5" "$TMP/shard1" "$TMP/split4" 2>"$TMP/err"
check "shards of another split: exit 2 ($(cat "$TMP/err"))" sh -c "[ $? -eq 2 ] && grep -q 'shard 1/3.*shard 2/4' '$TMP/err'"
# a line no row of adhere's is (1 GiB, sparse: no disk), refused before it
# is read into memory
mkdir "$TMP/long" && cp "$TMP/shard2/study.tsv" "$TMP/shard2/runs.tsv" "$TMP/long/" && truncate -s +1G "$TMP/long/runs.tsv"
$M -o "$TMP/m7" "$TMP/shard1" "$TMP/long" "$TMP/shard3" 2>"$TMP/err"
check "a runs.tsv with a line of 1 GiB: exit 2 ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'long/runs.tsv is not a record of study' '$TMP/err'"
rm -f "$TMP/long/runs.tsv"
$M -o "$TMP/m6" "$TMP/whole/run-1" 2>"$TMP/err"
check "a directory that holds no shard: exit 2 ($(cat "$TMP/err"))" sh -c "[ $? -eq 2 ] && grep -q 'no study.tsv' '$TMP/err'"
$M -o "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" 2>"$TMP/err"
check "merging into another shard's directory: exit 2 ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'holds a shard' '$TMP/err' && [ ! -e '$TMP/shard1/sweep.tsv' ]"

# --- one directory, one shard ---
"$ADHERE" $TINY -q "$TMP/map.scene" --shard 3/3 -o "$TMP/shard1" 2>"$TMP/err"
check "another shard into a shard's directory: exit 2 ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'holds shard 1/3 of this study, not 3/3' '$TMP/err'"
check "... shard 1's runs untouched" [ "$(rows "$TMP/shard1/runs.tsv" | wc -l)" -eq 8 ]
# a shard that does not end (eps beyond reach) is still running: another
# into its directory is refused by the lock, merge refuses it, and once
# stopped it is a partial shard
cat >"$TMP/slow.scene" <<'S'
[sweep]
sigma = 1.5, 3
eps = 10pm, 1e-22
S
SLOW="--batch -q --no-plot -N 100 --force --max-iter=100000000 --jobs=1 $TMP/slow.scene"
"$ADHERE" $SLOW --shard 1/2 -o "$TMP/fast" 2>/dev/null
rm -f "$TMP/ready"
ADHERE_READY_FILE="$TMP/ready" "$ADHERE" $SLOW --shard 2/2 -o "$TMP/slow" 2>/dev/null &
pid=$!
came=0
wait_phase "$TMP/ready" step "$pid" && came=1
"$ADHERE" $SLOW --shard 2/2 -o "$TMP/slow" 2>"$TMP/err"
rc=$?
check "a second shard into a directory in use: exit 2 (phase came $came; $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'in use' '$TMP/err'"
$M -o "$TMP/m7" "$TMP/fast" "$TMP/slow" 2>"$TMP/err"
check "merge while a shard still runs: exit 2 ($(cat "$TMP/err"))" sh -c "[ $? -eq 2 ] && grep -q 'still writing' '$TMP/err'"
kill -INT "$pid"
wait "$pid"
rc=$?
check "the slow shard stops on SIGINT (exit $rc)" [ "$rc" -eq 130 ]
$M -o "$TMP/m8" "$TMP/fast" "$TMP/slow" 2>"$TMP/err"
check "a shard cut short: exit 2, its runs listed ($(cat "$TMP/err"))" \
    sh -c "[ $? -eq 2 ] && grep -q 'runs 2, 4 (cut short' '$TMP/err'"
$M --allow-partial -o "$TMP/m8" "$TMP/fast" "$TMP/slow" 2>/dev/null
check "... joined with --allow-partial: # PARTIAL, runs 1 and 3 with results" \
    sh -c "grep -q '^# PARTIAL: 2 of 4 runs' '$TMP/m8/sweep.tsv' && awk -F'\t' '!/^#/ && (\$1 == 1 || \$1 == 3) && \$NF != \"not run\" {n++} END {exit n != 2}' '$TMP/m8/sweep.tsv'"

# --- another study's results are not cleared without --overwrite ---
# the fingerprint is the scene's whole text: a comment added to the scene
# cleared a study's results without a word and ran it again from scratch
printf '[scene]\nmode = rigid\n[sweep]\nE = 1GPa, 2GPa\n' >"$TMP/edit.scene"
"$ADHERE" --batch -q "$TMP/edit.scene" -o "$TMP/edit" 2>/dev/null
cp "$TMP/edit/runs.tsv" "$TMP/edit.runs"
printf '# a note\n' >>"$TMP/edit.scene"
"$ADHERE" --batch -q "$TMP/edit.scene" -o "$TMP/edit" 2>"$TMP/err"
rc=$?
check "a study's scene edited (a comment), rerun into its directory: exit 2, said, its rows kept ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'holds another study.s results (2 of its 2 runs; their scenes differ): give a new -o' '$TMP/err' && cmp -s '$TMP/edit.runs' '$TMP/edit/runs.tsv'"
"$ADHERE" --batch -q "$TMP/edit.scene" --overwrite -o "$TMP/edit" 2>"$TMP/err"
rc=$?
check "... --overwrite replaces them with this study's (exit $rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && grep -q '^# runs.tsv: study' '$TMP/edit/runs.tsv' && ! cmp -s '$TMP/edit.runs' '$TMP/edit/runs.tsv'"
"$ADHERE" --batch -q "$TMP/edit.scene" --sweep=E=1GPa,3GPa -o "$TMP/edit" 2>"$TMP/err"
check "... another flag: named ($(cat "$TMP/err"))" grep -q 'their options differ (none against sweep.E = 1GPa,3GPa)' "$TMP/err"
# another study whose runs.tsv cannot be read (a read error: failopen.c
# fails its open with EIO; the manifest refuses a FIFO or a directory put
# under the name, and root reads whatever chmod says) was taken for one
# with nothing to lose, and the directory cleared: refused, naming the file
# and why, nothing removed
printf '[scene]\nmode = rigid\n[sweep]\nE = 1GPa, 2GPa\n' >"$TMP/eio.scene"
"$ADHERE" --batch -q "$TMP/eio.scene" -o "$TMP/eio" 2>/dev/null
(cd "$TMP/eio" && ls -R) >"$TMP/eio.ls"
cp "$TMP/eio/runs.tsv" "$TMP/eio.runs"
printf '# a note\n' >>"$TMP/eio.scene"
if ${CC:-cc} -shared -fPIC -o "$TMP/failopen.so" "${ADHERE_SRC:-.}/tests/cli/failopen.c" -ldl 2>"$TMP/failopen.err"; then
    LD_PRELOAD="$TMP/failopen.so" FAILOPEN_NAME=runs.tsv "$ADHERE" --batch -q "$TMP/eio.scene" -o "$TMP/eio" 2>"$TMP/err"
    rc=$?
    check "another study's runs.tsv unreadable (EIO): exit 2, the file and why named, nothing removed ($rc: $(cat "$TMP/err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q 'could not be read (cannot read .*eio/runs.tsv: Input/output error): nothing there was removed' '$TMP/err' &&
               cmp -s '$TMP/eio.runs' '$TMP/eio/runs.tsv' && (cd '$TMP/eio' && ls -R) | cmp -s - '$TMP/eio.ls'"
else
    not_ok "tests/cli/failopen.c compiles: $(head -c 300 "$TMP/failopen.err")"
fi
# a single run (or a fit, or the TUI's plots) into a study's directory
# removed its results as an earlier run's files
cp "$TMP/edit/runs.tsv" "$TMP/edit.runs"
"$ADHERE" --batch -q --mode=rigid -o "$TMP/edit" 2>"$TMP/err"
rc=$?
check "a single run into a study's directory: exit 2, said, its rows kept ($rc: $(cat "$TMP/err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'edit holds a study.s results (2 runs in runs.tsv), which a run there would remove' '$TMP/err' && cmp -s '$TMP/edit.runs' '$TMP/edit/runs.tsv'"
"$ADHERE" --batch -q --mode=rigid --overwrite -o "$TMP/edit" 2>"$TMP/err"
check "... with --overwrite it runs there ($(cat "$TMP/err"))" sh -c "[ -s '$TMP/edit/summary.tsv' ] && [ ! -e '$TMP/edit/runs.tsv' ]"

# --- values, ranges, the plan ---
"$ADHERE" --batch -q --mode=rigid --sweep='E=10MPa..10GPa,log,13' --run-dirs=no -o "$TMP/log" 2>"$TMP/err"
check "a log range of 13 values runs (rigid spheres: $(head -c 200 "$TMP/err"))" [ "$(rows "$TMP/log/sweep.tsv" | wc -l)" -eq 13 ]
check "... its ends exact and its middle the geometric mean, 10^8.5 Pa" \
    awk -F'\t' '!/^#/ && $1 == 1 && $4 != 10000000 {bad = 1} !/^#/ && $1 == 13 && $4 != 10000000000 {bad = 1}
                !/^#/ && $1 == 7 {r = $4 / 316227766.01683795; if (r < 1 - 1e-15 || r > 1 + 1e-15) bad = 1} END {exit bad}' "$TMP/log/sweep.tsv"
check "... with no run-K directory (--run-dirs=no)" sh -c "! ls -d '$TMP'/log/run-* >/dev/null 2>&1"
"$ADHERE" --batch -q --mode=rigid --sweep='E=1GPa..4GPa,4' --sweep='z0=0.3nm,0.5nm' --sweep=plot=curves -o "$TMP/curves" 2>"$TMP/err"
rc=$?
check "plot = curves draws curves.png (rigid spheres: jump_in_h0 against z0, a curve per E; exit $rc $(head -c 200 "$TMP/err"))" \
    sh -c "[ $rc -eq 0 ] && [ -s '$TMP/curves/curves.png' ] && [ ! -e '$TMP/curves/map.png' ]"
# map.png's tics: labels like 2.73e-20 J, half a dozen across at most (a
# dozen overlapped), a dozen up the side
printf '#!/bin/sh\ntee -a "%s" | "%s" "$@"\n' "$TMP/map.gp" "$(command -v gnuplot)" >"$TMP/logging-gnuplot"
chmod +x "$TMP/logging-gnuplot"
ADHERE_GNUPLOT=$TMP/logging-gnuplot "$ADHERE" --batch -q --mode=rigid --sweep='E=1GPa..4GPa,30' \
    --sweep='A=1e-20J..2e-19J,100' --run-dirs=no -o "$TMP/tics" 2>"$TMP/err"
nx=$(grep '^set xtics (' "$TMP/map.gp" | tail -1 | grep -o "' [0-9]*" | wc -l)
ny=$(grep '^set ytics (' "$TMP/map.gp" | tail -1 | grep -o "' [0-9]*" | wc -l)
check "map.png of 30 x 100 runs: $nx labels across (2 to 6), $ny up the side (7 to 12)" \
    sh -c "[ -s '$TMP/tics/map.png' ] && [ $nx -ge 2 ] && [ $nx -le 6 ] && [ $ny -ge 7 ] && [ $ny -le 12 ]"
# curves.png against a key listed over decades: a log axis (on a linear
# one all but the largest values crowd at the left); over less, linear
: >"$TMP/map.gp"
ADHERE_GNUPLOT=$TMP/logging-gnuplot "$ADHERE" --batch -q --mode=rigid --sweep='z0=0.3nm,0.5nm' \
    --sweep='A=1e-21J,1e-20J,1e-19J' --sweep=plot=curves --run-dirs=no -o "$TMP/clog" 2>"$TMP/err"
check "curves.png against A listed over two decades has a log axis" \
    sh -c "[ -s '$TMP/clog/curves.png' ] && grep -qx 'set logscale x' '$TMP/map.gp'"
: >"$TMP/map.gp"
ADHERE_GNUPLOT=$TMP/logging-gnuplot "$ADHERE" --batch -q --mode=rigid --sweep='z0=0.3nm,0.5nm' \
    --sweep='A=1e-20J,5e-20J,1e-19J' --sweep=plot=curves --run-dirs=no -o "$TMP/clin" 2>"$TMP/err"
check "... over one decade a linear one" sh -c "[ -s '$TMP/clin/curves.png' ] && ! grep -q 'set logscale' '$TMP/map.gp'"
"$ADHERE" --plan -N 100 --force --eps=10pm "$TMP/map.scene" --shard 2/3 -o "$TMP/p" >"$TMP/plan" 2>&1
check "the plan counts the runs" grep -qx 'runs: 16' "$TMP/plan"
check "... the study's product" grep -q '^study: 16 runs, every combination of the 2 keys (4 x 4' "$TMP/plan"
check "... the drives sharing a loading branch" grep -q '^drives: 4 ' "$TMP/plan"
check "... the shard's part, and that the time above it is the whole study's (it said nothing of it)" \
    grep -q "^shard: 2 of 3: .*(4 of the 16 runs; the time above is the whole study's)" "$TMP/plan"
check "... one time line, from the pilot ($(grep -c 'time:' "$TMP/plan") lines with time:)" \
    sh -c "grep -q '^time: about .* on [0-9]* cores*, from a pilot of the study' '$TMP/plan' && [ \$(grep -c 'time:' '$TMP/plan') -eq 1 ]"
check "... and the disk" grep -q '^disk: about .* MB written' "$TMP/plan"
( ulimit -f 1; "$ADHERE" --plan -N 100 --force --eps=10pm "$TMP/map.scene" -o "$TMP/p" >/dev/null 2>"$TMP/err"; echo $? >"$TMP/rc" )
check "a study past the file size limit is refused (exit $(cat "$TMP/rc"): $(cat "$TMP/err"))" \
    sh -c "[ $(cat "$TMP/rc") -eq 2 ] && grep -q 'file size limit' '$TMP/err'"
"$ADHERE" --plan --mode=rigid --sweep=E=1GPa..2GPa,1000 --sweep=A=1e-20J..1e-19J,101 >/dev/null 2>"$TMP/err"
check "more than 100000 runs are refused ($(cat "$TMP/err"))" sh -c "[ $? -eq 2 ] && grep -q 'more than 100000 runs' '$TMP/err'"

# the Slurm examples read their flags (ADHERE_ARGS, ADHERE_MERGE_ARGS) as
# quoted shell words, never as commands: eval ran a $(...) or a backtick in
# them, and a user's ADHERE_ARGS (a task resubmitted by hand) is text
printf '#!/bin/sh\nfor a in "$@"; do printf "[%%s]\\n" "$a"; done >"$ARGS_OUT"\n' >"$TMP/show-args"
chmod +x "$TMP/show-args"
evil="-N 100 --title=\$(touch '$TMP/ran1') '\`touch $TMP/ran2\`' \"a b\" 'it'\\''s' \$HOME"
ARGS_OUT="$TMP/sb.args" SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=1 ADHERE="$TMP/show-args" ADHERE_SCENE=s.scene \
    ADHERE_OUT="$TMP/sbq" ADHERE_ARGS="$evil" sh "${ADHERE_SRC:-.}/share/adhere/examples/study.sbatch" 2>"$TMP/err"
printf '[--batch]\n[-q]\n[--jobs=1]\n[-N]\n[100]\n[--title=$(touch]\n[%s)]\n[`touch %s`]\n[a b]\n[it'"'"'s]\n[$HOME]\n[s.scene]\n[--shard]\n[1/1]\n[-o]\n[%s]\n' \
    "$TMP/ran1" "$TMP/ran2" "$TMP/sbq/shard-1" >"$TMP/sb.want"
check "study.sbatch: ADHERE_ARGS's \$(...) and backticks are text, not run; quotes group words ($(cat "$TMP/err" "$TMP/sb.args" 2>/dev/null | head -c 400))" \
    sh -c "[ ! -e '$TMP/ran1' ] && [ ! -e '$TMP/ran2' ] && cmp -s '$TMP/sb.want' '$TMP/sb.args'"
ARGS_OUT="$TMP/mg.args" ADHERE="$TMP/show-args" ADHERE_OUT="$TMP/sbq" ADHERE_MERGE_ARGS="$evil" \
    sh "${ADHERE_SRC:-.}/share/adhere/examples/merge.sbatch" 2>"$TMP/err"
check "merge.sbatch: ADHERE_MERGE_ARGS likewise ($(cat "$TMP/err" "$TMP/mg.args" 2>/dev/null | head -c 400))" \
    sh -c "[ ! -e '$TMP/ran1' ] && [ ! -e '$TMP/ran2' ] && grep -qx '\[--title=\$(touch\]' '$TMP/mg.args' && grep -qx '\[a b\]' '$TMP/mg.args'"
# a \ that ends the flags is itself, as sh reads it: it was dropped
# (--title=a\ came as --title=a, a lone \ as an empty flag)
ARGS_OUT="$TMP/bs.args" SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=1 ADHERE="$TMP/show-args" ADHERE_SCENE=s.scene \
    ADHERE_OUT="$TMP/sbq" ADHERE_ARGS='--title=a\' sh "${ADHERE_SRC:-.}/share/adhere/examples/study.sbatch" 2>"$TMP/err"
check "study.sbatch: ADHERE_ARGS='--title=a\\' passes --title=a\\ ($(cat "$TMP/err" "$TMP/bs.args" 2>/dev/null | tr '\n' ' ' | head -c 300))" \
    sh -c "[ \"\$(sed -n 4p '$TMP/bs.args')\" = '[--title=a\\]' ]"
ARGS_OUT="$TMP/bs2.args" ADHERE="$TMP/show-args" ADHERE_OUT="$TMP/sbq" ADHERE_MERGE_ARGS='-q \' \
    sh "${ADHERE_SRC:-.}/share/adhere/examples/merge.sbatch" 2>"$TMP/err"
printf '[merge]\n[-q]\n[\\]\n' >"$TMP/bs2.want"
check "merge.sbatch: ADHERE_MERGE_ARGS='-q \\' passes -q and \\ ($(cat "$TMP/err" "$TMP/bs2.args" 2>/dev/null | tr '\n' ' ' | head -c 300))" \
    sh -c "head -n 3 '$TMP/bs2.args' | cmp -s - '$TMP/bs2.want'"
# run by hand as `bash study.sbatch`: an apostrophe in a ${VAR:?...} message
# left bash (not in its POSIX mode) looking for the closing quote
for f in study.sbatch merge.sbatch; do
    check "$f parses under bash too ($(bash -n "${ADHERE_SRC:-.}/share/adhere/examples/$f" 2>&1 | head -c 200))" \
        bash -n "${ADHERE_SRC:-.}/share/adhere/examples/$f"
done
ADHERE="$TMP/show-args" ADHERE_OUT="$TMP/sbq" ADHERE_MERGE_ARGS="'open" ARGS_OUT="$TMP/mg2.args" \
    sh "${ADHERE_SRC:-.}/share/adhere/examples/merge.sbatch" 2>"$TMP/err"
check "an unclosed quote in ADHERE_MERGE_ARGS is refused, nothing run (exit $?: $(cat "$TMP/err"))" \
    sh -c "[ ! -e '$TMP/mg2.args' ] && grep -q 'opened and never closed' '$TMP/err'"
# a FIFO (no file adhere wrote) named runs.tsv in a shard's directory:
# merge says what is wrong with it ("Invalid argument" said nothing),
# exits 2, never opens the pipe's other end, and removes nothing
"$ADHERE" --batch -q --mode=rigid --sweep=E=1GPa,2GPa,3GPa --shard=1/2 -o "$TMP/fifoA" 2>/dev/null
"$ADHERE" --batch -q --mode=rigid --sweep=E=1GPa,2GPa,3GPa --shard=2/2 -o "$TMP/fifoB" 2>/dev/null
rm -f "$TMP/fifoB/runs.tsv"
if mkfifo "$TMP/fifoB/runs.tsv" 2>/dev/null; then
    timeout 60 "$ADHERE" merge -o "$TMP/fifoM" "$TMP/fifoA" "$TMP/fifoB" >/dev/null 2>"$TMP/err"
    rc=$?
    check "a FIFO named runs.tsv in a shard: exit 2, 'not a regular file', the FIFO kept, no merge written ($rc: $(cat "$TMP/err"))" \
        sh -c "[ $rc -eq 2 ] && grep -qF 'cannot read $TMP/fifoB/runs.tsv: not a regular file' '$TMP/err' && ! grep -q 'Invalid argument' '$TMP/err' && [ -p '$TMP/fifoB/runs.tsv' ] && [ ! -e '$TMP/fifoM' ] && [ -d '$TMP/fifoB/run-2' ]"
else
    T=$((T + 1)); echo "ok $T # SKIP mkfifo failed: no FIFO to try"
fi

done_testing
