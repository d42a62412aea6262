#!/bin/sh
# The status tells the truth and no input is silently dropped: steps at the
# iteration cap make a run `unconverged` (exit 1, said under -q) unless
# --allow-unconverged; an unreachable eps, text after a section header, old
# Mac line ends, empty list elements, flags that cannot go together, a FIFO
# as replay script, a missing style file and an unwritable standard output
# are each refused with a message (exit 2); mistakes get a hint; a turn the
# surfaces never reach is said as such, never success; a file name with a
# newline breaks no table; --gnuplot-style takes a directory.
. "$(dirname "$0")/lib.sh"

# --- item 4: unconverged steps ------------------------------------------
quick="-N 200 -E 10GPa --eps=10pm -d 0.5nm --turn=-1nm --no-plot"
"$ADHERE" --batch -q $quick --max-iter=3 -o "$TMP/cap" >/dev/null 2>"$TMP/cap.err"
rc=$?
check "--max-iter=3: exit 1, as for a solver failure (got $rc)" [ "$rc" -eq 1 ]
check "summary.tsv says status unconverged, not success" grep -qx 'status	unconverged' "$TMP/cap/summary.tsv"
check "-q does not hide the warning ($(head -c 160 "$TMP/cap.err"))" grep -q 'warning: .* reached the iteration cap' "$TMP/cap.err"
"$ADHERE" --batch -q $quick --max-iter=3 --allow-unconverged -o "$TMP/allow" >/dev/null 2>"$TMP/allow.err"
rc=$?
check "--allow-unconverged: exit 0 (got $rc)" [ "$rc" -eq 0 ]
check "and the summary still says unconverged" grep -qx 'status	unconverged' "$TMP/allow/summary.tsv"
"$ADHERE" --batch -q $quick -o "$TMP/fine" >/dev/null 2>&1
check "a converged run still says success" grep -qx 'status	success' "$TMP/fine/summary.tsv"

refused() { # refused "expected text" args...: exit 2, one message with the text
    want=$1; shift
    "$@" >"$TMP/out" 2>"$TMP/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -q -- "$want" "$TMP/err"; then
        ok "$* -> exit 2: $(head -c 200 "$TMP/err")"
    else
        not_ok "$* -> exit $rc (want 2 and '$want'): $(head -c 300 "$TMP/err")"
    fi
}
refused "^adhere: --eps=1e-30m is below what double precision can reach.*smallest eps allowed here is [0-9.e-]* m" \
    "$ADHERE" --batch -q --eps=1e-30 -o "$TMP/e30"
check "and nothing was written" [ ! -e "$TMP/e30/force.tsv" ]

# --- item 5: nothing dropped in silence ---------------------------------
printf '[material] E = 1GPa' >"$TMP/oneline.scene"
refused "oneline.scene:1: text after the section header \[material\]" "$ADHERE" --plan "$TMP/oneline.scene"
printf '[material]\rE = 1GPa\rA = 2e-19J\r' >"$TMP/mac.scene"
refused "mac.scene:1: a carriage return without a line feed" "$ADHERE" --plan "$TMP/mac.scene"
printf '[material]\r\nE = 1GPa\r\n' >"$TMP/dos.scene"
"$ADHERE" --plan "$TMP/dos.scene" 2>&1 | grep '^loading' >"$TMP/dos.plan"
"$ADHERE" --plan 2>&1 | grep '^loading' >"$TMP/default.plan"
"$ADHERE" --plan -E 1GPa 2>&1 | grep '^loading' >"$TMP/e1.plan"
check "DOS (CRLF) line ends still read: E = 1GPa moves the start as -E 1GPa does ($(cat "$TMP/dos.plan"))" \
    sh -c "! cmp -s '$TMP/dos.plan' '$TMP/default.plan' && cmp -s '$TMP/dos.plan' '$TMP/e1.plan'"
printf '[protocol]\nturns = -1nm,,-2nm\n' >"$TMP/empty.scene"
refused "turns: '-1nm,,-2nm' has an empty element" "$ADHERE" --plan "$TMP/empty.scene"
refused "--turn: '-1nm,,-2nm' has an empty element" "$ADHERE" --plan --turn=-1nm,,-2nm
refused "--profiles: '-1nm,' has an empty element" "$ADHERE" --plan --profiles=-1nm,
# a turn given twice unloaded the same branch twice (twice the work) and
# listed it twice in turns.tsv; -1nm and -0.001um are the same turn
refused "--turn: the turn -1 nm is given twice" "$ADHERE" --plan --turn=-1nm,-2nm,-0.001um
printf '[protocol]\nturns = -1nm, -1nm\n' >"$TMP/twice.scene"
refused "twice.scene:2: turns: the turn -1 nm is given twice" "$ADHERE" --plan "$TMP/twice.scene"
refused "--plan and --cost do not go together" "$ADHERE" --plan --cost
refused "--replay drives the TUI .* --batch" "$ADHERE" --batch --replay="$TMP/x.keys"
refused "--reference=static is for --mode=relax" "$ADHERE" --batch --mode=static --reference=static
refused "--reference=static is for --mode=relax" "$ADHERE" --batch --mode=rigid --reference=static
# physical time was told "rigid spheres have no elastic curve to compare"
refused "--reference=static is for --mode=relax: in physical time" "$ADHERE" --batch --material=sls --reference=static
refused "--reference=static is for --mode=relax: in physical time" "$ADHERE" --batch --mode=time --reference=static
refused "--screen writes the final screen of a --replay run" "$ADHERE" --screen="$TMP/s.txt"
# a --screen that cannot be written was found after the whole replay ran
printf 'f\n' >"$TMP/f.keys"
refused "^adhere: --screen=$TMP/nodir/s.txt: cannot write the screen there: No such file or directory$" \
    "$ADHERE" --replay="$TMP/f.keys" --screen="$TMP/nodir/s.txt" -N 100 --force
# a --screen naming no file (a trailing /) is said for what stands there:
# "nodir/" was called a directory
refused "^adhere: --screen=$TMP/nodir/: cannot write the screen there: No such file or directory$" \
    "$ADHERE" --replay="$TMP/f.keys" --screen="$TMP/nodir/" -N 100 --force
refused "^adhere: --screen=$TMP/f.keys/: cannot write the screen there: Not a directory$" \
    "$ADHERE" --replay="$TMP/f.keys" --screen="$TMP/f.keys/" -N 100 --force
refused "^adhere: --screen=$TMP/: cannot write the screen there: it is a directory$" \
    "$ADHERE" --replay="$TMP/f.keys" --screen="$TMP/" -N 100 --force
# --size sets a replay's screen: without --replay it was dropped in silence
refused "^adhere: --size sets the screen of a --replay run (a terminal keeps its own size): give --replay=FILE too" \
    "$ADHERE" --batch -q --size=100x32 -o "$TMP/size"
check "and nothing was written" [ ! -e "$TMP/size" ]
refused "^adhere: --size sets the screen of a --replay run" "$ADHERE" --size=100x32
# ... as were --columns without --data and --run-dirs without a study
refused "^adhere: --columns=3,2 picks the columns of a measured curve: give --data=FILE too" "$ADHERE" --batch -q --columns=3,2 --plan
refused "^adhere: --run-dirs=yes sets a study's run-K directories: give a scene with a \[sweep\] section" \
    "$ADHERE" --batch -q --run-dirs=yes --plan
# a study's figure with no key swept (a scene's [sweep] plot = map, or
# --sweep=plot=map): dropped in silence, the scene run once
refused "^adhere: --sweep=plot=map is a study's, and no key is swept: sweep one" "$ADHERE" --batch -q --plan --sweep=plot=map
printf '[sweep]\nmap = pulloff_F\n' >"$TMP/nokey.scene"
refused "^adhere: map = pulloff_F ($TMP/nokey.scene:2) is a study's, and no key is swept" "$ADHERE" --batch -q --plan "$TMP/nokey.scene"
mkfifo "$TMP/fifo" 2>/dev/null
if [ -p "$TMP/fifo" ]; then
    refused "cannot read the replay script: not a regular file" timeout 10 "$ADHERE" --replay="$TMP/fifo"
else
    T=$((T + 1)); echo "ok $T # SKIP mkfifo failed: no FIFO to try"
fi
"$ADHERE" --batch -q --mode=rigid -N 10 --turn=-1nm -o "$TMP/rigid" >/dev/null 2>"$TMP/rigid.err"
rc=$?
check "--mode=rigid builds no grid, so a coarse N is no error (exit $rc: $(head -c 120 "$TMP/rigid.err"))" [ "$rc" -eq 0 ]
refused "too small for this material: the automatic start .* is 7.35 nm.* give a start" \
    "$ADHERE" --plan -R 150nm --turn=none
refused "turning point -5 nm (the default turn) is too deep.*give a shallower turn or a larger R (--turn, -R)" "$ADHERE" --plan -R 150nm
refused "--gnuplot-style=$TMP/none.gp: No such file" "$ADHERE" --batch -q --gnuplot-style="$TMP/none.gp" -o "$TMP/st"
check "a missing style file is found before the run: no table written" [ ! -e "$TMP/st/force.tsv" ]
for a in --plan --help --list-keys --version; do
    "$ADHERE" $a >/dev/full 2>"$TMP/err"
    rc=$?
    check "$a to a full disk: exit 2 with a message (got $rc: $(cat "$TMP/err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q 'cannot write to standard output' '$TMP/err'"
done
# a study's sweep.tsv, --cost's report and adhere fit's, on standard output
# to a full disk, were lost with exit 0 and not a word
D1=$(cd "$(dirname "$0")/../../share/adhere/data" && pwd)/fig1-synthetic.tsv
for a in "--batch -N 100 --force --eps=10pm --turn=-1nm --no-plot --sweep=E=1GPa,2GPa" \
         "--cost -E 1GPa --turn=-1nm --spacing=15nm --cost-nodes=60 --cost-eps=20pm --no-plot" \
         "fit --data=$D1 fig1"; do
    # shellcheck disable=SC2086
    "$ADHERE" $a -q >/dev/full 2>"$TMP/err"
    rc=$?
    check "${a%% *} ... to a full disk: exit 2 with a message (got $rc: $(grep -v warning "$TMP/err" | head -c 200))" \
        sh -c "[ $rc -eq 2 ] && grep -q 'cannot write to standard output' '$TMP/err'"
done

# --- issue 24, item 6: a turn the surfaces never reach --------------------
"$ADHERE" --batch -q --mode=static --turn=3nm --no-plot -o "$TMP/st3" 2>"$TMP/st3.err"
check "--mode=static --turn=3nm (before the jump-in): not success ($(awk -F'\t' '$1 == "status"' "$TMP/st3/summary.tsv"))" \
    sh -c "grep -qx 'status	no contact' '$TMP/st3/summary.tsv' && grep -qx 'complete	0' '$TMP/st3/summary.tsv'"
check "... saying the surfaces never touched and what to change: $(head -c 200 "$TMP/st3.err")" \
    sh -c "grep -q 'never came into contact' '$TMP/st3.err' && grep -q 'put the turn below' '$TMP/st3.err'"
"$ADHERE" --batch -q --turn=3nm -N 100 --force --no-plot -o "$TMP/rx3" 2>"$TMP/rx3.err"
check "relaxation --turn=3nm: never came into contact, not 'still in contact' ($(grep -v warning "$TMP/rx3.err" | head -c 160))" \
    sh -c "grep -q 'never came into contact' '$TMP/rx3.err' && ! grep -q 'still in contact' '$TMP/rx3.err' && grep -qx 'status	no contact' '$TMP/rx3/summary.tsv'"
# A shallow turn the surfaces never reach beside a deep one (a Figure 5 set
# of turns reaching above the jump-in): its unloading branch is never in
# contact, so it has nothing to separate; the run said 'the surfaces never
# separated: ... still in contact (contact radius 0 nm)', status not
# separated and complete 0 of a run whose deep turn separated.
"$ADHERE" --batch -q --turn=5nm,-2nm -N 100 --force --eps=10pm --no-plot -o "$TMP/rx52" 2>"$TMP/rx52.err"
check "relaxation --turn=5nm,-2nm: no 'never separated' of the 5 nm turn ($(grep -v warning "$TMP/rx52.err" | head -c 160))" \
    sh -c "! grep -q 'never separated' '$TMP/rx52.err' && ! grep -qx 'status	not separated' '$TMP/rx52/summary.tsv' && grep -qx 'complete	1' '$TMP/rx52/summary.tsv'"
check "... its turns.tsv row of 5 nm says no jump-out (nan), the -2 nm row its own" \
    awk -F'\t' '$1 + 0 == 5e-9 {s = ($6 == "nan")} $1 + 0 == -2e-9 {d = ($6 + 0 > 0)} END {exit !(s && d)}' "$TMP/rx52/turns.tsv"
"$ADHERE" --batch -q --material=sls --turn=5nm,-2nm -N 100 --force --no-plot -o "$TMP/tm52" 2>"$TMP/tm52.err"
check "... and so in physical time ($(grep -v warning "$TMP/tm52.err" | head -c 160))" \
    sh -c "! grep -q 'never separated' '$TMP/tm52.err' && grep -qx 'complete	1' '$TMP/tm52/summary.tsv'"

# --- issue 24, item 7: a file name with a newline breaks no table ---------
nl='
'
evil="$TMP/evil${nl}1	2	3"
mkdir -p "$evil"
printf '[material]\nE = 20GPa\n' >"$evil/x.scene"
"$ADHERE" --batch -q -N 100 --force --eps=10pm --no-plot "$evil/x.scene" -o "$TMP/nl" 2>/dev/null
header_first() { # file header: every line before the header is a comment
    awk -v h="$2" '$0 == h {exit !ok} /^#/ {next} {exit 1} BEGIN {ok = 1}' "$1"
}
check "a scene path with a newline: force.tsv's first line that is not a comment is its header" \
    header_first "$TMP/nl/force.tsv" "$(printf 'h0\tF\tdelta\thc\ta\tangle\titers\tbranch\tpath\tconverged\tstable\tF_rigid\tseconds')"
check "... summary.tsv's too" header_first "$TMP/nl/summary.tsv" "$(printf 'key\tvalue')"
check "... turns.tsv's too" header_first "$TMP/nl/turns.tsv" "$(printf 'turn_h0\tmax_load\ta_turn\tpulloff_F\tpulloff_h0\tjump_out_h0\tpath\thysteresis')"
check "... the path is there, escaped: $(grep '^# scene' "$TMP/nl/force.tsv")" grep -q '^# scene: .*evil\\n1\\t2\\t3/x.scene$' "$TMP/nl/force.tsv"

# --- issue 24, item 7: --gnuplot-style=DIR, as the plot code reads it ----
if command -v gnuplot >/dev/null 2>&1; then
    mkdir -p "$TMP/styledir"
    printf 'set terminal pngcairo size 640,480\n' >"$TMP/styledir/style.gp"
    "$ADHERE" --batch -q -N 100 --force --eps=10pm --plots=force --gnuplot-style="$TMP/styledir" -o "$TMP/sd" 2>"$TMP/sd.err"
    rc=$?
    w=$(od -An -tu1 -j16 -N4 "$TMP/sd/force.png" 2>/dev/null | awk '{print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4}')
    check "--gnuplot-style=DIR (DIR/style.gp) is accepted and used: exit $rc, force.png $w px wide ($(head -c 120 "$TMP/sd.err"))" \
        sh -c "[ $rc -eq 0 ] && [ '$w' = 640 ]"
    mkdir -p "$TMP/emptydir"
    "$ADHERE" --batch -q -N 100 --force --gnuplot-style="$TMP/emptydir" -o "$TMP/ed" 2>"$TMP/ed.err"
    rc=$?
    check "... a directory without style.gp is refused, naming it (exit $rc: $(head -c 160 "$TMP/ed.err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q 'emptydir/style.gp' '$TMP/ed.err'"
else
    T=$((T + 1)); echo "ok $T # SKIP gnuplot is not installed"
fi

# --- a sweep's table says each run's status as its summary.tsv does --------
# gnuplot missing: every run's figures are not written, its summary says
# output incomplete; sweep.tsv used to say success for each
printf '[sweep]\neps = 10pm, 20pm\n' >"$TMP/nogp.scene"
ADHERE_GNUPLOT="$TMP/no-such-gnuplot" "$ADHERE" --batch -q -R 1um -d 0.5nm --turn=-1nm --plots=force \
    "$TMP/nogp.scene" -o "$TMP/nogp" 2>/dev/null
rc=$?
sweep_word() { awk -F'\t' -v r="$1" '$1 == r {print $NF}' "$TMP/nogp/sweep.tsv"; }
summary_word() { awk -F'\t' '$1 == "status" {print $2}' "$TMP/nogp/run-$1/summary.tsv"; }
check "a sweep without gnuplot: exit 3 (got $rc), each run's summary says output incomplete" \
    sh -c "[ $rc -eq 3 ] && [ '$(summary_word 1)' = 'output incomplete' ] && [ '$(summary_word 2)' = 'output incomplete' ]"
check "... and so does sweep.tsv (run 1: '$(sweep_word 1)', run 2: '$(sweep_word 2)')" \
    sh -c "[ '$(sweep_word 1)' = 'output incomplete' ] && [ '$(sweep_word 2)' = 'output incomplete' ]"

# --- errors that teach --------------------------------------------------
refused "'GPa' looks like the unit of '-E 1': write the number and its unit together, -E 1GPa" "$ADHERE" -E 1 GPa
refused "unknown unit 'GPA' (units are case-sensitive: did you mean 'GPa'?)" "$ADHERE" -E 1GPA
refused "unknown unit 'Gpa' (units are case-sensitive: did you mean 'GPa'?)" "$ADHERE" -E 1Gpa
refused "unknown option '--bach': did you mean --batch?" "$ADHERE" --bach
refused "'extra': --help, --version and --list-keys take no scene" "$ADHERE" --version extra
check "and --version alone still prints the version" sh -c "'$ADHERE' --version | grep -q '^adhere '"

# --- soft contacts: the automatic grid follows sigma, or the run is refused
"$ADHERE" --plan -E 0.1GPa >"$TMP/soft.plan" 2>&1
check "sigma = 22.5: the automatic grid is graded, ring kernel, resolved ($(grep '^kernel' "$TMP/soft.plan"))" \
    sh -c "grep -q '^kernel: ring, .*graded grid of' '$TMP/soft.plan' && grep -q '^resolution: .* resolved' '$TMP/soft.plan'"
"$ADHERE" --plan -E 0.1GPa --kernel=paper >"$TMP/softp.plan" 2>&1
check "with --kernel=paper it stays uniform ($(grep '^kernel' "$TMP/softp.plan"))" \
    sh -c "grep -q '^kernel: paper, N = ' '$TMP/softp.plan' && grep -q '^resolution: .* resolved' '$TMP/softp.plan'"
refused "sigma = 120: a resolved static curve .*N = [0-9]* nodes .*MB.*use the relaxation.*(--mode, -N, --spacing, --force)" "$ADHERE" --batch --mode=static -E 18.75MPa -o "$TMP/st120"
check "and nothing was written" [ ! -e "$TMP/st120" ]
"$ADHERE" --plan -E 30MPa >"$TMP/soft75.plan" 2>&1
check "sigma = 75: graded rings held as H^2, resolved ($(grep '^kernel' "$TMP/soft75.plan"))" \
    sh -c "grep -q '^kernel: ring, h2, graded grid of' '$TMP/soft75.plan' && grep -q '^resolution: .* resolved' '$TMP/soft75.plan'"
refused "sigma = 225 needs a grid spacing .*graded grid of N = .*H^2 kernel of .*MB.*--force" "$ADHERE" --plan -E 10MPa
# A negative hysteresis of the relaxation is its eps's, not noise to round
# to zero: a 1 TPa sphere's curve has no fold (sigma 0.0023), its static
# hysteresis is 0, and the relaxation's loop, each step ended at eps short
# of its equilibrium, is -5.75e-16 J at 1 pm, -4.19e-17 at 0.1 pm and
# -2.66e-18 at 0.01 pm: it goes to the static 0 as eps does. Kept signed
# (the relaxation has no tolerance on the force to call it zero within);
# a tenth of eps must shrink it at least five times.
"$ADHERE" --batch -q --no-plot -E 1TPa -o "$TMP/tpa1" 2>/dev/null
"$ADHERE" --batch -q --no-plot -E 1TPa --eps=0.1pm -o "$TMP/tpa01" 2>/dev/null
h1=$(awk -F'\t' '$1 == "hysteresis" { print $2 }' "$TMP/tpa1/summary.tsv")
h01=$(awk -F'\t' '$1 == "hysteresis" { print $2 }' "$TMP/tpa01/summary.tsv")
check "a 1 TPa sphere's relaxation (no fold): its negative hysteresis is eps's, a fifth of it or less at a tenth of eps ($h1 J at 1 pm, $h01 J at 0.1 pm)" \
    awk -v a="$h1" -v b="$h01" 'BEGIN { exit !(a < 0 && b < 0 && b > a / 5) }'
done_testing
