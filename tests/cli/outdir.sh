#!/bin/sh
# The output directory (-o) as an attacker and a careless user would meet
# it: adhere never writes through a link (a symlinked run-K, a link planted
# at the temporary name an older adhere used, gnuplot's files), never
# deletes or replaces a file it did not write (a user's cost.tsv, sweep.tsv,
# jump.png, run-3/force.tsv in a reused -o), refuses a second run into a
# directory while one is writing, and writes into an -o path of 4 000
# characters without stalling. Prints TAP.
. "$(dirname "$0")/lib.sh"
need_gnuplot
cd "$TMP" || exit 1
mkdir tmp
export TMPDIR="$TMP/tmp"
QUICK="--batch --quiet -N 100 --force --eps=10pm"
key() { awk -F'\t' -v k="$2" '$1 == k {print $2}' "$1/summary.tsv" 2>/dev/null; }
# the files of v, with their contents, one line each
snapshot() { (cd "$1" && for f in $(ls -A | sort); do printf '%s=%s\n' "$f" "$(cat "$f" 2>/dev/null)"; done); }

# --- a sweep whose run-1 is a link to a directory elsewhere ----------------
mkdir v o
echo keep >v/force.tsv
echo keep >v/gnuplot.log
ln -s ../v o/run-1
printf '[sweep]\neps = 10pm, 20pm\n' >sweep.scene
before=$(snapshot v)
"$ADHERE" $QUICK sweep.scene -o o 2>sweep.err
rc=$?
check "a sweep into o with o/run-1 -> ../v: refused, exit 2 (got $rc: $(head -c 300 sweep.err))" [ "$rc" -eq 2 ]
check "... v is untouched: its force.tsv and gnuplot.log kept, nothing added" [ "$(snapshot v)" = "$before" ]
check "... the message names the link" grep -q 'run-1 (a link)' sweep.err
"$ADHERE" $QUICK --overwrite sweep.scene -o o 2>/dev/null
rc=$?
check "with --overwrite: the link itself is replaced by a directory, exit 0 (got $rc)" \
    sh -c "[ $rc -eq 0 ] && [ -d o/run-1 ] && [ ! -L o/run-1 ] && [ -s o/run-1/force.tsv ]"
check "... and v is still untouched" [ "$(snapshot v)" = "$before" ]

# -o a link to a directory that does not exist: said so, not "No such file"
ln -s missing-dir dangling
"$ADHERE" $QUICK --no-plot -o dangling 2>dangling.err
rc=$?
check "-o a dangling link: exit 2, naming the link and its target (got $rc: $(head -c 200 dangling.err))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'symbolic link to missing-dir, which does not exist' dangling.err && [ -L dangling ]"

# --- links planted at the temporary names an older adhere used -------------
# (its pid is visible): the run holds in a long dwell, the links go in, a
# SIGTERM makes it write its tables
rm -f planted.ready
ADHERE_READY_FILE="$TMP/planted.ready" "$ADHERE" $QUICK -d 0.5nm --turn=-1nm --dwell=100000000 -o planted \
    2>planted.err &
pid=$!
came=0
wait_phase planted.ready dwell "$pid" && came=1
for n in force.tsv summary.tsv turns.tsv profiles.tsv contact.tsv; do
    echo keep >"v/$n.target"
    ln -s "$TMP/v/$n.target" "planted/.$n.$pid.tmp"
done
ln -s "$TMP/v/gnuplot.log" "planted/.force.png.tmp$pid"
before=$(snapshot v)
kill -TERM "$pid"
wait "$pid"
rc=$?
check "a run with links at .NAME.PID.tmp: interrupted as asked (phase seen $came, SIGTERM: exit $rc)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 143 ]"
check "... wrote its tables (force.tsv PARTIAL, summary.tsv)" \
    sh -c "grep -q '^# PARTIAL' planted/force.tsv && [ -s planted/summary.tsv ]"
check "... and not through the links: their targets are untouched" [ "$(snapshot v)" = "$before" ]
check "... the links are left as they were" [ -L "planted/.force.tsv.$pid.tmp" ]

# --- a user's files in a reused directory -----------------------------------
mkdir -p user/run-3
echo mine >user/cost.tsv
echo mine >user/sweep.tsv
echo mine >user/jump.png
echo mine >user/run-3/force.tsv
echo mine >user/notes.txt
before=$(snapshot user; snapshot user/run-3)
"$ADHERE" $QUICK --no-plot -o user 2>user.err
rc=$?
check "an unrelated run into a directory holding the user's cost.tsv, sweep.tsv, jump.png, run-3/: refused, exit 2 (got $rc)" \
    [ "$rc" -eq 2 ]
check "... every one of the user's files is kept as it was" [ "$(snapshot user; snapshot user/run-3)" = "$before" ]
check "... the message names them and --overwrite: $(head -c 300 user.err)" \
    sh -c "grep -q 'cost.tsv' user.err && grep -q 'run-3/' user.err && grep -q -- '--overwrite' user.err"

# a user's run-01/ and run-0/ are no names of adhere's (it writes run-1 ...)
mkdir -p lookalike/run-01 lookalike/run-0
"$ADHERE" $QUICK --no-plot -o lookalike 2>lookalike.err
rc=$?
check "a directory holding the user's run-01/ and run-0/: run, exit 0, both kept (got $rc: $(grep -v warning lookalike.err | head -c 160))" \
    sh -c "[ $rc -eq 0 ] && [ -d lookalike/run-01 ] && [ -d lookalike/run-0 ]"

# adhere's own files of an earlier run go; the user's other files stay
"$ADHERE" $QUICK --reference=static -o reuse 2>/dev/null
echo mine >reuse/notes.txt
echo mine >reuse/force.tsv.bak
"$ADHERE" $QUICK --no-plot --turn=none --plots=force -o reuse 2>reuse.err
rc=$?
check "run 2 into run 1's directory: exit 0 (got $rc: $(head -c 200 reuse.err))" [ "$rc" -eq 0 ]
left=$(cd reuse && ls -A | sort | tr '\n' ' ')
check "only run 2's files (its tables: --plots=force writes models.tsv with --no-plot too), the manifest and the user's remain: $left" \
    [ "$left" = ".adhere-manifest force.tsv force.tsv.bak models.tsv notes.txt summary.tsv " ]
check "run 2's summary is run 2's (no turn: turn_h0 nan)" [ "$(key reuse turn_h0)" = nan ]
# a table of adhere's the user edited is the user's now
echo "my edit" >>reuse/force.tsv
"$ADHERE" $QUICK --no-plot -o reuse 2>edit.err
rc=$?
check "a table adhere wrote and the user then edited is not removed: exit 2 (got $rc)" \
    sh -c "[ $rc -eq 2 ] && tail -n 1 reuse/force.tsv | grep -qx 'my edit'"

# a table the user made read-only, and one edited in place and given its
# modification time back (touch -r): the user's now (their change time
# moved); both used to be taken for adhere's and removed
"$ADHERE" $QUICK --no-plot -o kept 2>/dev/null
chmod 444 kept/force.tsv
cp -p kept/turns.tsv turns.orig
printf 'X' | dd of=kept/turns.tsv bs=1 seek=2 conv=notrunc 2>/dev/null
touch -r turns.orig kept/turns.tsv
ino=$(ls -i kept/force.tsv | cut -d' ' -f1)
"$ADHERE" $QUICK --no-plot -o kept 2>kept.err
rc=$?
check "a read-only force.tsv and a turns.tsv edited with its mtime set back: refused, exit 2 (got $rc: $(head -c 200 kept.err))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'force.tsv' kept.err && grep -q 'turns.tsv' kept.err"
check "... both kept as the user left them" \
    sh -c "[ \"\$(ls -i kept/force.tsv | cut -d' ' -f1)\" = $ino ] && [ \"\$(stat -c %a kept/force.tsv)\" = 444 ] && [ \"\$(cut -c3 kept/turns.tsv | head -n 1)\" = X ]"

# --- a directory where adhere writes a file --------------------------------
# --overwrite used to be offered and taken, the run computed, and force.tsv
# then could not be written (exit 2 at the end, its table lost)
mkdir -p dirs/force.tsv dirs2/.adhere-manifest
for ow in "" --overwrite; do
    "$ADHERE" $QUICK --no-plot $ow -o dirs 2>"dirs$ow.err"
    rc=$?
    check "a directory at dirs/force.tsv${ow:+ with $ow}: refused before the run, exit 2 (got $rc: $(head -c 200 "dirs$ow.err"))" \
        sh -c "[ $rc -eq 2 ] && [ ! -e dirs/summary.tsv ] && [ -d dirs/force.tsv ] && grep -q 'force.tsv is a directory' 'dirs$ow.err'"
done
check "... and --overwrite is not offered for it" sh -c "! grep -q 'pass --overwrite' dirs.err"
"$ADHERE" $QUICK --no-plot --overwrite -o dirs2 2>dirs2.err
rc=$?
check "a directory at the manifest's name, --overwrite: refused, exit 2, naming it (got $rc: $(head -c 160 dirs2.err))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'adhere-manifest is a directory' dirs2.err"

# --- two runs into one directory at once -------------------------------------
rm -f first.ready
ADHERE_READY_FILE="$TMP/first.ready" "$ADHERE" $QUICK -d 0.5nm --turn=-1nm --dwell=100000000 -o both 2>first.err &
pid=$!
came=0
wait_phase first.ready dwell "$pid" && came=1
"$ADHERE" $QUICK --no-plot -o both 2>second.err
rc=$?
check "a second run into a directory the first is writing: refused, exit 2 (phase seen $came, got $rc)" \
    sh -c "[ $came -eq 1 ] && [ $rc -eq 2 ]"
check "... saying it is in use: $(head -c 200 second.err)" grep -q 'in use: another adhere' second.err
kill -TERM "$pid"
wait "$pid"
rc=$?
check "... the first finishes its own tables (exit $rc, summary says interrupted)" \
    sh -c "[ $rc -eq 143 ] && grep -qx 'status	interrupted' both/summary.tsv"

# --- a run into an earlier sweep's run-1 while a sweep is started into its parent
# The run (--overwrite: it replaces that study's run-1 on purpose) holds
# run-1's lock while gnuplot draws (a stand-in that never
# answers, and says when it started); the sweep must not empty run-1 under
# it: it used to remove the run's tables and the directory itself.
cat >gp-slow <<EOF
#!/bin/sh
: >"\$GP_STARTED"
exec cat 3>&1 >/dev/null
EOF
chmod +x gp-slow
"$ADHERE" $QUICK --no-plot sweep.scene -o nest 2>/dev/null
rm -f nest.started
GP_STARTED="$TMP/nest.started" ADHERE_GNUPLOT="$TMP/gp-slow" "$ADHERE" $QUICK --plots=force --overwrite -o nest/run-1 \
    2>inner.err &
pid=$!
i=0
while [ ! -e nest.started ] && kill -0 "$pid" 2>/dev/null && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
ino=$(ls -i nest/run-1/force.tsv 2>/dev/null | cut -d' ' -f1)
"$ADHERE" $QUICK --no-plot sweep.scene -o nest 2>outer.err
rc=$?
kept=0
[ -n "$ino" ] && [ "$(ls -i nest/run-1/force.tsv 2>/dev/null | cut -d' ' -f1)" = "$ino" ] && kept=1
kill -INT "$pid"
wait "$pid"
check "a sweep into nest while a run writes into nest/run-1: refused, exit 2 (got $rc: $(head -c 200 outer.err))" \
    sh -c "[ -e nest.started ] && [ $rc -eq 2 ] && grep -q 'run-1 is in use' outer.err"
check "... the run's tables were left where they were (its force.tsv still there: $kept)" [ "$kept" -eq 1 ]
check "... and the run finished into them (summary.tsv names force.png not written)" \
    grep -q '^not_written	force.png' nest/run-1/summary.tsv

# --- an -o path of about 4 080 characters ----------------------------------
long=$TMP/L
while [ ${#long} -lt 3880 ]; do long=$long/dddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddddd; done
long=$long/$(printf '%*s' $((4080 - ${#long} - 1)) '' | tr ' ' e)
t0=$(date +%s)
timeout 120 "$ADHERE" $QUICK --plots=force -o "$long" 2>long.err
rc=$?
took=$(($(date +%s) - t0))
check "an -o path of ${#long} characters: exit 0 in ${took} s (got $rc: $(head -c 160 long.err))" \
    sh -c "[ $rc -eq 0 ] && [ $took -lt 20 ]"
check "... force.png and the tables are there" sh -c '[ -s "$1/force.png" ] && [ -s "$1/force.tsv" ]' sh "$long"
# --- the terminal interface's time/ and static/, links to elsewhere -------
# p in physical time writes into DIR/time, in static mode into DIR/static:
# names adhere gives, which it entered through a link as if the user had
# named them, writing its plots (and removing its earlier ones) in the
# directory the link pointed to.
mkdir tv tv/victim-t tv/victim-s tv/o
ln -s ../victim-t tv/o/time
ln -s ../victim-s tv/o/static
printf 'f\np\n:dump %s\n' "$TMP/tv/t.txt" >tv/t.keys
printf 'm\nf\np\n:dump %s\n' "$TMP/tv/s.txt" >tv/s.keys
"$ADHERE" --replay=tv/t.keys visco -N 100 --force -o tv/o --no-clock >/dev/null 2>&1
check "p in physical time into -o DIR whose time/ is a link: refused, nothing written through it ($(tail -3 tv/t.txt | head -2 | tr -s ' '))" \
    sh -c "[ -z \"\$(ls -A tv/victim-t)\" ] && grep -q 'time is a symbolic link' tv/t.txt"
"$ADHERE" --replay=tv/s.keys -N 100 --force -o tv/o --no-clock >/dev/null 2>&1
check "... and in static mode, DIR/static a link: refused, nothing written through it" \
    sh -c "[ -z \"\$(ls -A tv/victim-s)\" ] && grep -q 'static is a symbolic link' tv/s.txt"
check "... the links themselves left alone" sh -c "[ -L tv/o/time ] && [ -L tv/o/static ]"
# --- -o one run-K of a study -------------------------------------------------
# The study's directory refuses another run while its runs.tsv holds
# results; its run-K did not: a run into DIR/run-2 removed that run's
# tables (sweep.tsv and runs.tsv still describing them) without a word.
"$ADHERE" $QUICK --turn=-1nm --no-plot --sweep=E=1GPa,2GPa -o rk 2>/dev/null
before=$(cat rk/run-2/force.tsv rk/run-2/summary.tsv | cksum)
"$ADHERE" $QUICK --turn=-1nm --no-plot -o rk/run-2 2>rk.err; rc=$?
after=$(cat rk/run-2/force.tsv rk/run-2/summary.tsv 2>/dev/null | cksum)
check "a run into a study's run-2: exit 2, the run's tables kept ($(grep -v warning rk.err | head -c 200))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'run-2 of a study' rk.err && [ '$before' = '$after' ]"
"$ADHERE" $QUICK --turn=-1nm --no-plot --overwrite -o rk/run-2 2>/dev/null; rc=$?
check "... and with --overwrite it runs there (exit $rc)" sh -c "[ $rc -eq 0 ] && [ -s rk/run-2/force.tsv ]"
# --- the terminal interface's ./adhere-plots, a link ------------------------
# p without -o writes into ./adhere-plots, a name adhere gives as it gives
# time/ and static/ there; a link of that name took the plots into the
# directory it pointed to (and lost the files of an earlier p there), in
# relaxation and in static mode.
mkdir tw tw/victim tw/victim-s tw/cwd tw/cwd-s
ln -s ../victim tw/cwd/adhere-plots
ln -s ../victim-s tw/cwd-s/adhere-plots
printf 'f\np\n:dump %s\n' "$TMP/tw/r.txt" >tw/r.keys
printf 'm\nf\np\n:dump %s\n' "$TMP/tw/s.txt" >tw/s.keys
(cd tw/cwd && "$ADHERE" --replay=../r.keys -N 100 --force --no-clock >/dev/null 2>&1)
rc=$?
check "p without -o, ./adhere-plots a link: refused, nothing written through it, exit 0 ($rc: $(grep -A1 'plots not' tw/r.txt | tr -s ' ' | tr '\n' ' '))" \
    sh -c "[ $rc -eq 0 ] && [ -z \"\$(ls -A tw/victim)\" ] && grep -A1 'plots not written' tw/r.txt | tr '\n' ' ' | tr -s ' ' | grep -q 'adhere-plots is a symbolic link: .*give -o DIR to write elsewhere'"
check "... the link left alone" [ -L tw/cwd/adhere-plots ]
(cd tw/cwd-s && "$ADHERE" --replay=../s.keys -N 100 --force --no-clock >/dev/null 2>&1)
check "... and in static mode (adhere-plots/static): refused, nothing written through it" \
    sh -c "[ -z \"\$(ls -A tw/victim-s)\" ] && grep -A1 'plots not written' tw/s.txt | tr '\n' ' ' | tr -s ' ' | grep -q 'adhere-plots is a symbolic link'"
# --- :dump, :rows and --screen over a file the session reads ---------------
# --screen naming the replay script put the screen over it, and :dump
# naming the scene put the screen over the scene: refused, exit 2, the
# file as it was; a link to the script is replaced, not written through
mkdir ti
printf '# my script\nf\n' >ti/s.keys
printf '[material]\nE = 1GPa\n' >ti/a.scene
printf 'f\n:dump a.scene\n' >ti/d.keys
printf 'f\n:rows r.keys\n' >ti/r.keys
ln -s s.keys ti/link.keys
before=$(cat ti/s.keys ti/a.scene ti/r.keys | cksum)
(cd ti && "$ADHERE" --replay=s.keys --screen=s.keys -N 100 --force >/dev/null 2>s.err); rc1=$?
(cd ti && "$ADHERE" --replay=d.keys -N 100 --force a.scene >/dev/null 2>d.err); rc2=$?
(cd ti && "$ADHERE" --replay=r.keys -N 100 --force >/dev/null 2>r.err); rc3=$?
check "--screen=the replay script, :dump the scene, :rows the script: exit 2 each ($rc1 $rc2 $rc3), the files as they were" \
    sh -c "[ $rc1 -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 2 ] && [ '$before' = \"\$(cat ti/s.keys ti/a.scene ti/r.keys | cksum)\" ]"
check "... each naming the file and what it is ($(cat ti/s.err ti/d.err ti/r.err | tr '\n' ' '))" \
    sh -c "grep -q '^adhere: --screen=s.keys is the replay script (--replay) this run reads' ti/s.err && grep -q '^d.keys:2: not writing the screen to a.scene: it is the scene this session reads' ti/d.err && grep -q '^r.keys:2: not writing the rows to r.keys: it is the replay script this session reads' ti/r.err"
(cd ti && "$ADHERE" --replay=s.keys --screen=link.keys -N 100 --force >/dev/null 2>&1); rc=$?
check "... --screen=a link to the script: the link replaced by the screen, the script kept (exit $rc)" \
    sh -c "[ $rc -eq 0 ] && [ ! -L ti/link.keys ] && grep -q 'adhere: two elastic' ti/link.keys && grep -q '^# my script' ti/s.keys"
done_testing
