#!/bin/sh
# Every bad input named in the core issue: exit status 2, one message naming
# the value and what is allowed (the real limit: issue 24, item 7), and no
# output file left behind.
. "$(dirname "$0")/lib.sh"

bad() { # bad "expected text" args...
    want=$1; shift
    out="$TMP/out$T"
    "$ADHERE" --batch -q -o "$out" "$@" >"$TMP/stdout" 2>"$TMP/stderr"
    rc=$?
    msg=$(cat "$TMP/stderr")
    if [ "$rc" -eq 2 ] && grep -q -- "$want" "$TMP/stderr" && [ ! -e "$out/force.tsv" ] && [ ! -e "$out/summary.tsv" ] \
        && [ "$(wc -l <"$TMP/stderr")" -eq 1 ]; then
        ok "$* -> exit 2: $msg"
    else
        not_ok "$* -> exit $rc (want 2 and '$want', no tables): $msg"
    fi
}

# the core's sentence names a quantity ("E (modulus) = 0 Pa"): the CLI opens
# it with the setting as it was given, a flag by the flag with its value
bad "^adhere: --modulus=0Pa is out of range: allowed 1 kPa to 10 TPa$" -E 0
bad "^adhere: --modulus=-1GPa is out of range: allowed 1 kPa to 10 TPa$" -E -1GPa
bad "^adhere: --hamaker=0J is out of range" -A 0
bad "^adhere: --z0=-500pm is out of range: allowed 1 pm to 100 nm$" --z0=-0.5nm
bad "^adhere: --radius=0nm is out of range" -R 0
# the limits themselves are allowed as the refusal writes them: -z 100nm
# (100 x 1e-9 rounds to 1.0000000000000001e-7) was refused with 'allowed 1
# pm to 100 nm'; it now gets as far as R's own check
bad "R = 10 um is too small for this model" -z 100nm
bad "^adhere: --nodes=5 is not allowed: use 10 to 20000 nodes$" -N 5
# a decimal comma in a list: '-0,5nm' ran two turns, 0 m and 5 nm, without a
# word; a scene's, a sweep's and the screen's list alike
bad "^adhere: --turn: '-0,5nm' reads as two values, -0 and 5nm: a decimal comma? write -0.5nm for one value, or give each value its unit$" --turns=-0,5nm
printf '[protocol]\nturns = -1,5nm\n' >"$TMP/comma.scene"
bad "^adhere: $TMP/comma.scene:2: turns: '-1,5nm' reads as two values, -1 and 5nm: a decimal comma? write -1.5nm" "$TMP/comma.scene"
bad "^adhere: --sweep: E: '1,5GPa' reads as two values, 1 and 5GPa: a decimal comma? write 1.5GPa" --sweep=E=1,5GPa
printf ':set turn -1,5nm\n' >"$TMP/comma.keys"
"$ADHERE" --replay="$TMP/comma.keys" -N 100 --force >/dev/null 2>"$TMP/comma.err"
rc=$?
check "... and the screen's :set turn -1,5nm (a bare -1 is nm there): exit $rc, $(cat "$TMP/comma.err")" \
    sh -c "[ $rc -eq 2 ] && grep -q \"comma.keys:1: turn: '-1,5nm' reads as two values, -1 and 5nm: a decimal comma?\" '$TMP/comma.err'"
bad "'1e3' is not allowed: expected a whole number of nodes, 10 to 20000$" --nodes=1e3
# every count names its range, not only the form ('expected a whole number'
# said nothing of how many): the iteration cap, the dwell, a scene's key and
# --cost-nodes' list
bad "^adhere: --max-iter: '1e9' is not allowed: expected a whole number of iterations, 1 to 100000000$" --max-iter=1e9
bad "^adhere: --max-iter: '-3' is not allowed: expected a whole number of iterations, 1 to 100000000$" --max-iter=-3
bad "^adhere: --dwell: '12.5' is not allowed: expected a whole number of iterations, 0 to 100000000$" --dwell=12.5
printf '[protocol]\ndwell = 1e9\n' >"$TMP/dwell.scene"
bad "^adhere: $TMP/dwell.scene:2: dwell: '1e9' is not allowed: expected a whole number of iterations, 0 to 100000000$" "$TMP/dwell.scene"
bad "^adhere: --cost-nodes: '1e9' is not allowed: expected a whole number of nodes, 10 to 20000$" --cost --cost-nodes=500,1e9
# a cost value twice ran its runs twice (--cost-nodes=100,100: 20 runs for 10)
bad "^adhere: --cost-nodes: 100 is given twice: each N once$" --cost --cost-nodes=100,100
bad "^adhere: --cost-eps: '0.001nm' is given twice (the same eps as value 1): each eps once$" --cost --cost-eps=1pm,0.001nm
bad "too coarse" -N 20
bad "too short.*; use more nodes or a larger spacing (-N, --spacing)$" --spacing=0.5nm
# the grid's advice in the words the grid was given in: a scene's N by its
# key, file and line (it said '(-N)', a flag the scene's user never wrote),
# a key nobody set in the scene's words beside it, a flag's by the flag
printf '[grid]\n# coarse\nnodes = 20\n' >"$TMP/n20.scene"
bad "^adhere: grid spacing 75 nm is too coarse: .*; use more nodes (nodes at $TMP/n20.scene:3)$" "$TMP/n20.scene"
printf '[grid]\nnodes = 100\nspacing = 2nm\n' >"$TMP/ns.scene"
bad "too short.*; use more nodes or a larger spacing (nodes at $TMP/ns.scene:2, spacing at line 3)$" "$TMP/ns.scene"
printf '[grid]\nnodes = 10\n' >"$TMP/n10.scene"
bad "too short.*; use more nodes or a larger spacing (nodes at $TMP/n10.scene:2, --spacing)$" "$TMP/n10.scene" --spacing=2nm
printf '[grid]\nnodes = 100\nspacing = 10nm\n' >"$TMP/unres.scene"
bad "coarser than the resolved limit .*; use spacing = 1.581nm ($TMP/unres.scene:3) or more nodes over the same radius, or --force to run it anyway (marked resolved 0)$" "$TMP/unres.scene"
bad "coarser than the resolved limit .*; use --spacing=1.581nm or more nodes over the same radius, or --force" -N 100 --spacing=10nm
bad "unknown option '--frobnicate'" --frobnicate
bad "unknown option '-x'" -x
bad "needs a value" --modulus
bad "'abc' is not a number" -E abc
bad "'nan' is not a number" -E nan
bad "'inf' is not a number" -R inf
bad "unknown unit 'parsecs'" -R 5parsecs
bad "is a length (m, nm, um, ...), but a pressure" -E 5nm
bad "is a pressure (Pa, MPa, GPa, ...), but a length" --eps=1GPa
bad "must lie below the start" --turn=50nm
bad "must lie below the start" --start=5nm --turn=-1nm,6nm
# Rmax at its limit, 0.3 R exactly (1000 x 3 nm at R = 10 um, which the
# units make a few ulps more), is allowed; just beyond it is not
"$ADHERE" --plan --force -R 10um -N 1000 --spacing=3nm >/dev/null 2>"$TMP/stderr"
rc=$?
check "Rmax = 1000 x 3 nm = 0.3 R exactly is allowed (exit $rc: $(cat "$TMP/stderr"))" [ "$rc" -eq 0 ]
bad "grid radius Rmax = 3.001 um is not << R = 10 um: at most 0.3 R = 3 um is allowed (N x spacing)" -R 10um -N 1000 --spacing=3.001nm
# a graded grid's last ring ends past the radius asked: the refusal says so
bad "grid radius Rmax = 3.013 um is not << R = 10 um: at most 0.3 R = 3 um is allowed (the graded rings' outer edge" \
    -R 10um --grid=graded --kernel=ring --grid-radius=3um
bad "material.E swept twice (--sweep=E=... and --sweep=material.E=...): give its values once" --sweep=E=1GPa,2GPa --sweep=material.E=3GPa
bad "sigma swept twice (--sweep=sigma=... and --sweep=sigma=...)" --sweep=sigma=1,2 --sweep=sigma=3
bad "^adhere: --eps=0nm is not allowed" --eps=0
bad "--mixing: 'fast' is not a mixing rule: use paper or momentum" --mixing=fast
bad "--momentum: '1' is not allowed: a number from 0 to below 1" --momentum=1
bad "--momentum: 'x' is not allowed" --momentum=x
bad "^adhere: --eps=-1pm is not allowed" --eps=-1pm
bad "'paperish' is not a kernel" --kernel=paperish
bad "--grid: 'graded2' is not a grid: use uniform or graded" --grid=graded2
bad "--grid=graded is not allowed with --kernel=paper" --grid=graded
bad "--growth: '1.2' is not allowed: use a ratio from 1 to 1.1" --grid=graded --kernel=ring --growth=1.2
bad "--growth: 'x' is not allowed" --growth=x
bad "fine band radius .* too short.*; use a larger fine band (--fine-band)$" --grid=graded --kernel=ring --fine-band=100nm
# a graded grid's radius is its own setting: it was told 'use more nodes or
# a larger spacing (-N, --spacing)', neither of which moves a radius given
bad "grid radius Rmax = .* is too short: .*; use a larger grid radius (--grid-radius)$" --grid=graded --kernel=ring --grid-radius=200nm
bad "^adhere: --grid-radius=600nm is not allowed: it must be at least the fine band" --grid=graded --kernel=ring --fine-band=800nm --grid-radius=600nm
bad "--growth: '0.9' is not allowed: use a ratio from 1 to 1.1" --growth=0.9
bad "--fine-band: '-1nm' is not allowed: use a length above 0" --fine-band=-1nm
bad "--grid-radius: '0' is not allowed: use a length above 0" --grid-radius=0
bad "--operator: 'sparse' is not an operator: use dense, hmat or h2" --operator=sparse
bad "out of the range of finite numbers" -E 1e999
# below a double's range: an underflow, not out of range; a unit's factor too
bad "'1e-400m' underflows to zero (a double keeps no magnitude below 2.2e-308 m): write 0 for zero, or a magnitude of at least 2.23e-308 m, or auto$" --start=1e-400m
bad "'1e-300pm' underflows (a double keeps no magnitude below 2.2e-308 m)" --start=1e-300pm
# a number below a double's range before its unit but not after: the
# modulus's own range, not the double's least magnitude (1e-301 Pa is far
# above 2.2e-308 Pa, the limit the refusal named)
bad "^adhere: --modulus=1e-301Pa is out of range: allowed 1 kPa to 10 TPa$" -E 1e-310GPa
bad "^adhere: --step=0nm is not allowed" --step=0
bad "more than one scene" fig1 fig2
# the core names quantities, the CLI adds its flags
bad "(the default turn) is too deep.*; give a shallower turn or a larger R (--turn, -R)$" -R 100nm
bad "beyond this program's budget.*; use a stiffer material.*run it anyway (-N, --spacing, --force)$" -E 1MPa
bad "a resolved static curve.*; use the relaxation.*run it anyway (--mode, -N, --spacing, --force)$" -E 20MPa --mode=static
bad "at most 2e6 are allowed; take a larger step (-d)$" -d 0.01pm
bad "no scene named 'nosuchscene'" nosuchscene
# Every core sentence that opens with a setting's quantity and value (the
# material's, the protocol's, the solver's, the grid's) opens with the
# setting as it was given: a scene's key with its file and line, a swept
# one by its sweep; they said 'E (modulus) = 1e+20 Pa', 'step d = 100 nm',
# 'grid radius 600 nm' to users who never wrote those words
printf '# hard\n[material]\nE = 1e20\n' >"$TMP/e20.scene"
bad "^adhere: E = 1e+20Pa ($TMP/e20.scene:3) is out of range: allowed 1 kPa to 10 TPa$" "$TMP/e20.scene"
printf '[protocol]\nstep = 100nm\n' >"$TMP/step.scene"
bad "^adhere: step = 100nm ($TMP/step.scene:2) is not allowed: it must be from 0.01 pm to 10 nm$" "$TMP/step.scene"
bad "^adhere: --step=100nm is not allowed: it must be from 0.01 pm to 10 nm$" -d 100nm
printf '[solver]\neps = 2um\n' >"$TMP/eps.scene"
bad "^adhere: eps = 2um ($TMP/eps.scene:2) is not allowed" "$TMP/eps.scene"
bad "^adhere: --eps=1e-30m is below what double precision can reach" --eps=1e-30
printf '[grid]\ngrid = graded\nkernel = ring\nfine_band = 800nm\nradius = 600nm\n' >"$TMP/rings.scene"
bad "^adhere: radius = 600nm ($TMP/rings.scene:5) is not allowed: it must be at least the fine band's 800 nm$" "$TMP/rings.scene"
bad "^adhere: sweep run 2 (step = 1e-07): --sweep=step=100nm is not allowed" --sweep=step=1nm,100nm
printf '[sweep]\nstep = 1nm, 100nm\n' >"$TMP/sweepstep.scene"
bad "^adhere: sweep run 2 (step = 1e-07): step = 100nm ($TMP/sweepstep.scene:2) is not allowed" "$TMP/sweepstep.scene"
# ... the advice after it says the file once: a key the sentence placed
# by its name alone ('(R at r.scene:3)' repeated what it had just said)
printf '[material]\nz0 = 100nm\nR = 10um\n' >"$TMP/r10.scene"
bad "^adhere: R = 10um ($TMP/r10.scene:3) is too small for this model: .* over 0.045 (R)$" "$TMP/r10.scene"
bad "^adhere: --radius=10um is too small for this model: .* over 0.045 (-R)$" -z 100nm -R 10um
# ... a key nobody set in the scene's words after a sentence that placed
# one in the scene (it said '(-N)' to a user of the scene alone)
printf '# coarse\n[grid]\nspacing = 2\n' >"$TMP/sp2.scene"
bad "^adhere: spacing = 2m ($TMP/sp2.scene:3) is too coarse: .*; use more nodes (nodes)$" "$TMP/sp2.scene"
# ... and what nobody set stays the core's quantity (no flag to name)
bad "^adhere: R = 10 um is too small for this model: .* (-R)$" -z 100nm
# --cost's N is each of --cost-nodes: its advice names that, not -N (which
# --cost refuses) nor a scene's nodes; the spacing it scales is --spacing's
bad "^adhere: --cost: N = 20, eps = 1 pm: grid spacing 75 nm is too coarse: .*; use more nodes (--cost-nodes)$" \
    --cost --cost-nodes=20 --cost-eps=1pm
bad "^adhere: --cost: N = 20, eps = 1 pm: grid radius Rmax = 100 nm is too short: .* (--cost-nodes, --spacing)$" \
    --cost --cost-nodes=20 --cost-eps=1pm --spacing=5nm
printf '[grid]\nspacing = 5nm\n' >"$TMP/costsp.scene"
bad "^adhere: --cost: N = 20, eps = 1 pm: grid radius Rmax = 100 nm is too short: .* (--cost-nodes, spacing at $TMP/costsp.scene:2)$" \
    --cost --cost-nodes=20 --cost-eps=1pm "$TMP/costsp.scene"
# ... and its eps is --cost-eps', not the scene's eps beside it
bad "^adhere: --cost: N = 100, eps = 1e-30 m: eps = 1e-30 m is below what double precision can reach" \
    --cost --cost-nodes=100 --cost-eps=1e-30 "$TMP/eps.scene"

# Messages that name the real limit (issue 24, item 7): a radius past 0.3 R
# is not the node budget; a NUL byte and a number below a double's range in
# --data are said to be what they are.
bad "beyond 0.3 R = 60 nm where the paraboloid gap" -R 0.2um -E 10MPa --turn=-1nm
check "... and does not blame the node budget" sh -c "! grep -q 'budget of N' '$TMP/stderr'"
printf '1 2\n3\0004 5\n' >"$TMP/nul.dat"
bad "nul.dat:2: a NUL byte" --data="$TMP/nul.dat"
# a file of NULs (no newline in its first 4096 bytes) was 'line longer than
# 4096 bytes', which sent the user to the line length of a binary file
head -c 10000 /dev/zero >"$TMP/zeros.dat"
bad "zeros.dat:1: a NUL byte: this is not a text table" --data="$TMP/zeros.dat"
# an escape sequence in a header word would reach the terminal in the
# refusal that quotes it
printf 'h0 (\033[2Jnm)\tF (nN)\n1\t2\n' >"$TMP/esc.dat"
bad "esc.dat:1: the control byte 0x1b: this is not a text table" --data="$TMP/esc.dat"
check "... and the refusal holds no escape byte" sh -c "! grep -q \"\$(printf '\033')\" '$TMP/stderr'"
# escaped RC WANT TEXT: the run exited WANT and its stderr says TEXT (a
# name shown escaped, read as fixed text) with no ESC byte in it
escaped() {
    [ "$1" -eq "$2" ] && grep -qF -- "$3" "$TMP/stderr" && ! grep -q "$(printf '\033')" "$TMP/stderr"
}
# -o DIR with an escape sequence in its name: the messages show it escaped
# (\x1b), its bytes never reach the terminal
ESCDIR=$TMP/$(printf 'o\033[2Jdir')
: >"$ESCDIR"
"$ADHERE" --batch -q --mode=rigid -o "$ESCDIR/x" >/dev/null 2>"$TMP/stderr"
check "-o DIR/x under a file named with ESC: exit 2, the name escaped ($(cat "$TMP/stderr"))" escaped $? 2 'o\x1b[2Jdir/x'
rm -f "$ESCDIR"
"$ADHERE" --batch --mode=rigid -o "$ESCDIR" >/dev/null 2>"$TMP/stderr"
check "... a run into it: its closing line names it escaped ($(cat "$TMP/stderr"))" escaped $? 0 'o\x1b[2Jdir'
"$ADHERE" merge "$ESCDIR" >/dev/null 2>"$TMP/stderr"
check "... merge of it (no shard there): exit 2, escaped ($(cat "$TMP/stderr"))" escaped $? 2 'o\x1b[2Jdir holds no study.tsv'
# a scene or --data file named with an escape sequence: the refusal names
# it escaped, as a directory's (every "adhere: ..." message goes through
# one writer; it printed the name's bytes as they were)
"$ADHERE" --batch -q "$TMP/$(printf 'x\033[2J').scene" >/dev/null 2>"$TMP/stderr"
check "a scene file named with ESC: exit 2, the name escaped ($(cat "$TMP/stderr"))" escaped $? 2 'x\x1b[2J.scene'
"$ADHERE" --batch -q --mode=rigid --data="$TMP/$(printf 'd\033[2J').tsv" -o "$TMP/escdata" >/dev/null 2>"$TMP/stderr"
check "a --data file named with ESC: exit 2, the name escaped ($(cat "$TMP/stderr"))" escaped $? 2 'd\x1b[2J.tsv'
# ... and the bare number's hint naming that scene (it was printed past
# the one writer, the ESC as it was)
printf '[material]\nE = 300\n' >"$TMP/$(printf 'h\033[2J').scene"
"$ADHERE" --batch -q "$TMP/$(printf 'h\033[2J').scene" >/dev/null 2>"$TMP/stderr"
check "a bare-number hint naming a scene named with ESC: exit 2, the name escaped ($(cat "$TMP/stderr"))" escaped $? 2 "did you mean E = 300GPa or E = 300MPa in $TMP/h\\x1b[2J.scene?"
# a byte that begins no UTF-8 character (0x9b, CSI to some terminals) in
# the name is escaped too: it was quoted as it was; a UTF-8 name is not
C1DIR=$TMP/$(printf 'o\2332J\302\265dir')
: >"$C1DIR"
"$ADHERE" --batch -q --mode=rigid -o "$C1DIR/x" >/dev/null 2>"$TMP/stderr"
check "-o DIR/x under a file named with the byte 0x9b: escaped, its micro sign kept ($(cat "$TMP/stderr"))" \
    sh -c "grep -qF 'o\\x9b2Jµdir/x' '$TMP/stderr' && ! grep -q \"\$(printf '\233')\" '$TMP/stderr'"
rm -f "$C1DIR"
printf '1 2\n3 1e-320\n' >"$TMP/tiny.dat"
bad "tiny.dat:2: '1e-320' is too small for a double (it underflows" --data="$TMP/tiny.dat"

# A bare number is SI (issue 28, item 2): where the same number in the unit
# the screen shows would run, the refusal says so, by the flag or the
# scene's key; where no unit rescues it, the refusal stands alone.
bad "^adhere: R = 10 m is out of range; did you mean --radius=10um? (a bare number is in SI units: sigma = 7.5e+03 needs" -R 10
bad "^adhere: turns = -5 m is out of range; did you mean --turn=-5nm? (a bare number is in SI units: turning point -5 m is too deep" --turn=-5
bad "turns = -5 m, -2 m is out of range; did you mean --turn=-5nm,-2nm?" --turn=-5,-2
bad "eps = 1 m is out of range; did you mean --eps=1pm?" --eps=1
bad "z0 = 500 mm is out of range; did you mean --z0=0.5nm?" -z 0.5
bad "E = 1 Pa is out of range; did you mean --modulus=1GPa? (a bare number is in SI units: --modulus=1Pa is out of range: allowed 1 kPa to 10 TPa)" -E 1
printf '[material]\nE = 300\n' >"$TMP/e300.scene"
bad "E = 300 Pa is out of range; did you mean E = 300GPa or E = 300MPa in $TMP/e300.scene?" "$TMP/e300.scene"
bad "^adhere: --spacing=2m is too coarse" --spacing=2
check "... and a bare number no unit rescues gets no hint" sh -c "! grep -q 'did you mean' '$TMP/stderr'"
bad "^adhere: --modulus=300Pa is out of range" -E 300Pa
check "... nor one given with its unit" sh -c "! grep -q 'did you mean' '$TMP/stderr'"
# Names (issue 28, item 6): the scene key's name is a flag too; a mistyped
# one gets the flag, by a short option's letter or a key's name
bad "unknown option '--E=1GPa': did you mean -E 1GPa (--modulus=1GPa)?" --E=1GPa
bad "unknown option '--max_iter=9': did you mean --max-iter=9?" --max_iter=9
bad "unknown option '--trun=-1nm': did you mean --turn=-1nm?" --trun=-1nm
bad "unknown option '--xyzzy' (see adhere --help)" --xyzzy
"$ADHERE" --plan --turns=-1nm,-2nm >"$TMP/plan" 2>&1
check "--turns sets the turns as --turn does" grep -q "turning points: 2 (-1, -2 nm)" "$TMP/plan"
printf '[protocol]\nturn = -2nm\n' >"$TMP/turn.scene"
bad "turn.scene:2: unknown key 'turn': did you mean 'turns'? (see adhere-scene(5))" "$TMP/turn.scene"
printf '[protocol]\nR = 2um\n' >"$TMP/r.scene"
bad "r.scene:2: unknown key 'R' in \\[protocol\\]: did you mean 'R' in \\[material\\]?" "$TMP/r.scene"
# ... whole from a scene deep in directories (a path of 1.3 KB): the
# message was cut at 1023 bytes, in the path, and the error itself lost
deep="$TMP/$(printf 'k%.0s' $(seq 1 250))/$(printf 'l%.0s' $(seq 1 250))/$(printf 'm%.0s' $(seq 1 250))"
deep="$deep/$(printf 'n%.0s' $(seq 1 250))/$(printf 'o%.0s' $(seq 1 250))"
mkdir -p "$deep" && cp "$TMP/r.scene" "$deep/r.scene"
bad "^adhere: $deep/r.scene:2: unknown key 'R' in \\[protocol\\]: did you mean 'R' in \\[material\\]?" "$deep/r.scene"
# ... and a refusal's advice names the deep scene's key with its file whole
# (the advice cut the path at 1000 bytes: its file's name and line lost)
printf '[material]\nR = 100nm\n' >"$deep/d.scene"
bad "^adhere: turning point .* is too deep: .*; give a shallower turn or a larger R (turns, R at $deep/d.scene:2)\$" "$deep/d.scene"

# An output path that cannot be a directory.
touch "$TMP/afile"
"$ADHERE" --batch -q -N 100 --force --turn=none -o "$TMP/afile/sub" >/dev/null 2>"$TMP/stderr"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "cannot create directory" "$TMP/stderr"; then ok "unwritable --out -> exit 2: $(cat "$TMP/stderr")"; else not_ok "unwritable --out -> exit $rc"; fi

# A directory whose file system makes its own files only (/proc): creating
# a file or directory there fails with "No such file or directory", which
# alone read as if /proc were missing. The failing call is named, and that
# the directory is there (not root: the access check's own refusal).
nonew="the directory.* exists, but its file system lets nothing new be made in it \(No such file or directory\)\$"
for o in /proc /proc/adhere-new; do
    "$ADHERE" --batch -q -N 100 --force -o "$o" >/dev/null 2>"$TMP/stderr"
    rc=$?
    check "-o $o: exit 2, the create named, not a missing directory (got $rc: $(cat "$TMP/stderr"))" \
        sh -c "[ $rc -eq 2 ] && grep -Eq '^adhere: cannot (create a file in $o: |create directory $o: )$nonew|: Permission denied\$' '$TMP/stderr'"
done
printf 'q\n' >"$TMP/quit.keys"
"$ADHERE" --replay="$TMP/quit.keys" --screen=/proc/adhere-screen.txt >/dev/null 2>"$TMP/stderr"
rc=$?
check "--screen=/proc/FILE: exit 2, naming /proc as there (got $rc: $(cat "$TMP/stderr"))" \
    sh -c "[ $rc -eq 2 ] && grep -Eq '^adhere: cannot write the screen to /proc/adhere-screen.txt: ($nonew|Permission denied\$)' '$TMP/stderr'"

# "-" names no file here (standard output to most programs): -o - made a
# directory called "-", --data=- looked for a file called "-"
bad "^adhere: --out: '-' is not allowed: adhere reads and writes named files and directories, not standard input or output; write ./- for one named '-'$" -o -
check "-o - leaves no directory called '-'" test ! -e ./-
bad "^adhere: --data: '-' is not allowed" --data=-

# a misspelt ADHERE_DATADIR was passed over in silence (the built-in places
# used instead): refused, naming it, before anything is read or written
ADHERE_DATADIR="$TMP/no-such-dir" "$ADHERE" --batch -q -o "$TMP/dd" fig1 >/dev/null 2>"$TMP/stderr"
rc=$?
check "ADHERE_DATADIR=missing -> exit 2 naming it, nothing written ($rc: $(cat "$TMP/stderr"))" \
    sh -c "[ $rc -eq 2 ] && grep -qF 'adhere: ADHERE_DATADIR=$TMP/no-such-dir is not a directory' '$TMP/stderr' && [ ! -e '$TMP/dd' ]"
ADHERE_DATADIR="$TMP/no-such-dir" "$ADHERE" --help >"$TMP/stdout" 2>"$TMP/stderr"
check "... but --help reads nothing and answers (exit $?)" sh -c "[ $? -eq 0 ] && grep -q '^usage: adhere' '$TMP/stdout'"
ADHERE_DATADIR="$ADHERE_SRC/share/adhere" "$ADHERE" --plan fig1 >/dev/null 2>"$TMP/stderr"
check "ADHERE_DATADIR naming the shipped data is read (exit $?)" [ $? -eq 0 ]

done_testing
