#!/bin/sh
# A scene, an output directory name, a style path or $TMPDIR can hold any
# text; none of it may ever run as a command through gnuplot (backquotes,
# @macros, '<cmd' and '|cmd' file names), and what it says reaches the figure
# as itself: the commands gnuplot was sent (logged by a wrapper) carry the
# title literally. Text no figure can show (control bytes, NUL) is refused
# with file:line. Every command tried would create a file named PWNED...; the
# test fails if any such file appears. Prints TAP.
. "$(dirname "$0")/lib.sh"
SRC=${ADHERE_SRC:-$PWD}
need_gnuplot
RUN="--batch --quiet --nodes=100 --force --eps=1e-10 --plots=force"
cd "$TMP" || exit 1
nothing_ran() { # what: no PWNED* anywhere under $TMP (those found are removed)
    p=$(find "$TMP" -name 'PWNED*' | sed "s|^$TMP/||" | tr '\n' ' ')
    if [ -z "$p" ]; then ok "$1: no command ran"; else not_ok "$1: a command ran and made $p"; fi
    find "$TMP" -name 'PWNED*' -exec rm -rf {} + 2>/dev/null
}
is_png() { [ "$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')" = 89504e470d0a1a0a ]; }

# gnuplot behind a wrapper that keeps a copy of every command it is sent
cat >"$TMP/gp-log" <<EOF
#!/bin/sh
tee -a "$TMP/commands.gp" | exec gnuplot "\$@"
EOF
chmod +x "$TMP/gp-log"

# --- the scene title ----------------------------------------------------
# every form gnuplot expands, in single and double quotes, and quotes at the
# start, in pairs and at the end
title='x`touch PWNED1`y "`touch PWNED2`" '"'"'`touch PWNED3`'"'"' @adh_figure $(touch PWNED4) ${HOME} \ '"''"' end'"'"
printf '[scene]\ntitle = %s\n' "$title" >inject.scene
rm -f commands.gp
ADHERE_GNUPLOT="$TMP/gp-log" "$ADHERE" $RUN inject.scene -o out1 2>err1
rc=$?
check "a title with backquotes, @, \$ and quotes: exit 0 (got $rc)" [ "$rc" -eq 0 ]
check "... and force.png is written" is_png out1/force.png
nothing_ran "the title"
# the commands sent carry the title as single-quoted runs, with ' as a fixed escape
want=$(cat <<'EOF'
'x`touch PWNED1`y "`touch PWNED2`" '."\047".'`touch PWNED3`'."\047".' @adh_figure $(touch PWNED4) ${HOME} \ '."\047"."\047".' end'."\047"."\n".'Force vs position
EOF
)
check "the title reaches gnuplot literally, as single-quoted runs with fixed escapes for ' and newline" \
    grep -qF "set title $want" commands.gp

# text a figure cannot show is refused with file:line
printf '[scene]\ntitle = a\001b\n' >ctl.scene
"$ADHERE" $RUN ctl.scene -o out2 2>err2
rc=$?
check "a control byte in the title: exit 2 (got $rc)" [ "$rc" -eq 2 ]
check "... named with file:line: $(head -c 200 err2)" grep -q 'ctl.scene:2: title: the control character 0x01' err2
check "... and nothing written" [ ! -e out2/force.tsv ]
printf '[scene]\ntitle = a\000`touch PWNED5`\n' >nul.scene
"$ADHERE" $RUN nul.scene -o out3 2>err3
rc=$?
check "a NUL byte in a scene: exit 2 with file:line (got $rc: $(head -c 200 err3))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'nul.scene:2: a NUL byte' err3"
printf '[scene]\ntitle = a\n`touch PWNED6`\n' >nl.scene
"$ADHERE" $RUN nl.scene -o out4 2>err4
rc=$?
check "a title broken by a newline: the next line is an error at file:3 (got $rc: $(head -c 200 err4))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'nl.scene:3:' err4"
nothing_ran "refused scenes"

# --- output directory names ---------------------------------------------
# relative names gnuplot would take for a pipe, names with quotes, a
# backquote, a macro, $( ) and a newline
nl='
'
i=0
for dir in '|touch PWNED7;x' '<touch PWNED8;x' "a'b''" 'o`touch PWNED9`' '@adh_figure' '$(touch PWNED10)' \
           "new${nl}line" "$TMP/abs'\`touch PWNED11\`"; do
    i=$((i + 1))
    "$ADHERE" $RUN -o "$dir" 2>"err-dir$i"
    rc=$?
    check "-o $(printf '%s' "$dir" | tr '\n' '^'): exit 0 and force.png in that very directory (got $rc)" \
        sh -c "[ $rc -eq 0 ] && [ -d \"\$1\" ] && od -An -tx1 -N8 \"\$1/force.png\" | grep -q '89 50 4e 47'" sh "$dir"
    check "... and no temporary left in it" sh -c '! ls -A "$1" | grep -q tmp' sh "$dir"
done
nothing_ran "odd -o names"

# --- style file paths -----------------------------------------------------
# a style file is code by design; its path is only a name
for dir in '<touch PWNED12;x' "st'y\`touch PWNED13\`le"; do
    mkdir -p "$dir"
    cp "$SRC/share/adhere/gnuplot/style.gp" "$dir/style.gp"
    "$ADHERE" $RUN --gnuplot-style="$dir/style.gp" -o out-style 2>err-style
    rc=$?
    check "--gnuplot-style=$dir/style.gp: exit 0 (got $rc: $(head -c 200 err-style))" [ "$rc" -eq 0 ]
done
nothing_ran "odd style paths"

# --- $TMPDIR, where gnuplot's data files go --------------------------------
mkdir -p '<touch PWNED14;x'
TMPDIR='<touch PWNED14;x' "$ADHERE" $RUN -o out-tmpdir 2>err-tmpdir
rc=$?
check "TMPDIR='<touch PWNED14;x': exit 0 (got $rc: $(head -c 200 err-tmpdir))" [ "$rc" -eq 0 ]
check "... and its temporary directory removed" sh -c '[ -z "$(ls -A "<touch PWNED14;x")" ]'
nothing_ran "an odd TMPDIR"

# --- the TUI's plot key, with the same scene and an odd directory ----------
cat >plot.keys <<'EOF'
:set N 100
:set eps 100pm
:set d 0.5nm
4f
p
EOF
rm -f commands.gp
# an earlier run's table (an earlier adhere wrote it) and the user's own
# file in that directory
"$ADHERE" $RUN --no-plot --reference=static -o '|touch PWNED15;y' 2>/dev/null
earlier=no
[ -s '|touch PWNED15;y/static.tsv' ] && earlier=yes
: >'|touch PWNED15;y/notes.txt'
ADHERE_GNUPLOT="$TMP/gp-log" timeout 60 "$ADHERE" --replay=plot.keys --screen=plot.screen --no-clock --plots=force \
    -o '|touch PWNED15;y' inject.scene </dev/null >tui.out 2>tui.err
rc=$?
check "the TUI's p key with the title and -o '|touch PWNED15;y': exit 0 (got $rc: $(head -c 200 tui.err))" [ "$rc" -eq 0 ]
check "... writes force.png there" is_png '|touch PWNED15;y/force.png'
check "... sending the title literally" grep -qF "set title $want" commands.gp
check "... after removing the earlier run's static.tsv, keeping the user's notes.txt" \
    sh -c '[ ! -e "|touch PWNED15;y/static.tsv" ] && [ -e "|touch PWNED15;y/notes.txt" ]'
check "... (the earlier run had written static.tsv)" [ "$earlier" = yes ]
nothing_ran "the TUI's plot key"
done_testing
