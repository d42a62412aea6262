#!/bin/sh
# A file under its final name is whole: a style that makes gnuplot write
# text, or a full disk (a file size limit stands in for it) cutting a PNG
# short, leaves no force.png and exits 3; a disk that takes nothing at all
# is said to be full, not blamed on a style; a table the disk refuses
# leaves a summary.tsv that says what is missing and never "success" (exit
# 2), also when the limit's signal is left at its default; no temporary
# stays behind when gnuplot dies. (A reused -o: tests/cli/outdir.sh.)
# Prints TAP.
. "$(dirname "$0")/lib.sh"
need_gnuplot
RUN="--batch --quiet --nodes=100 -E 20GPa --eps=1e-10 --step=1nm"
cd "$TMP" || exit 1
mkdir tmp
export TMPDIR="$TMP/tmp"
key() { awk -F'\t' -v k="$2" '$1 == k {print $2}' "$1/summary.tsv" 2>/dev/null; }
no_temporaries() { # dir what: any hidden file but adhere's manifest is one
    left=$(ls -A "$1" | grep '^\.' | grep -v '^\.adhere-manifest$' | tr '\n' ' ')
    if [ -z "$left" ] && [ -z "$(ls -A "$TMPDIR")" ]; then ok "$2: no temporary file left"
    else not_ok "$2: temporaries left: $left $(ls -A "$TMPDIR" | tr '\n' ' ')"; fi
}

# --- a style that sets another terminal ------------------------------------
printf 'set terminal dumb\n' >dumb.gp
"$ADHERE" $RUN --plots=force --gnuplot-style=dumb.gp -o dumb 2>dumb.err
rc=$?
check "a style with 'set terminal dumb': exit 3 (got $rc)" [ "$rc" -eq 3 ]
check "... no force.png (a text file is not a PNG)" [ ! -e dumb/force.png ]
check "... and the message says so: $(head -c 300 dumb.err)" grep -q 'force.png: .*not a PNG' dumb.err
check "... summary.tsv: not_written force.png, status not success ($(key dumb status)), complete 0" \
    [ "$(key dumb not_written)/$(key dumb status)/$(key dumb complete)" = "force.png/output incomplete/0" ]
no_temporaries dumb "a text image"
# the same in a sweep: each run's summary, written before its figures, is
# written again to say so
printf '[sweep]\nE = 10GPa, 20GPa\n' >sweep.scene
"$ADHERE" $RUN --plots=force --gnuplot-style=dumb.gp sweep.scene -o sweep 2>/dev/null
rc=$?
check "a sweep with that style: exit 3 (got $rc)" [ "$rc" -eq 3 ]
check "... run-2/summary.tsv: not_written force.png, status $(key sweep/run-2 status)" \
    [ "$(key sweep/run-2 not_written)/$(key sweep/run-2 status)" = "force.png/output incomplete" ]

# --- a full disk: RLIMIT_FSIZE refuses writes past a size, as a full disk does
# (SIGXFSZ ignored, so a write fails with EFBIG instead of killing)
"$ADHERE" $RUN -o full 2>/dev/null
rc=$?
check "an unlimited run writes everything (exit $rc)" [ "$rc" -eq 0 ]
size() { wc -c <"$1" 2>/dev/null || echo 0; }
rows() { grep -vc '^#' "$1"; }
png=$(size full/force.png) tsv=$(size full/force.tsv) prof=$(size full/profiles.tsv)
echo "# sizes: force.png $png, force.tsv $tsv, profiles.tsv $prof bytes"

# the PNG cut short: the limit on gnuplot alone, below force.png's size
lim=$(( (png / 2 + 1023) / 1024 ))
cat >gp-limited <<EOF
#!/bin/sh
trap '' XFSZ
ulimit -f $lim && exec gnuplot "\$@"
EOF
chmod +x gp-limited
ADHERE_GNUPLOT="$TMP/gp-limited" "$ADHERE" $RUN --plots=force -o cut 2>cut.err
rc=$?
check "force.png cut short at $lim KiB: exit 3 (got $rc)" [ "$rc" -eq 3 ]
check "... no force.png under its final name" [ ! -e cut/force.png ]
check "... the message says it was cut short: $(head -c 300 cut.err)" grep -q 'force.png: .*cut short' cut.err
check "... summary.tsv names it and does not say success ($(key cut not_written), $(key cut status))" \
    [ "$(key cut not_written)/$(key cut status)" = "force.png/output incomplete" ]
no_temporaries cut "a PNG cut short"

# a disk that takes nothing at all: an empty image, said to be so
cat >gp-full <<EOF
#!/bin/sh
trap '' XFSZ
ulimit -f 0 && exec gnuplot "\$@"
EOF
chmod +x gp-full
ADHERE_GNUPLOT="$TMP/gp-full" "$ADHERE" $RUN --plots=force -o full0 2>full0.err
rc=$?
check "a full disk under gnuplot: exit 3 (got $rc)" [ "$rc" -eq 3 ]
check "... the image is said to be empty (a full disk), not blamed on a style file: $(head -c 300 full0.err)" \
    sh -c 'grep -q "force.png: .*empty.*full disk" full0.err && ! grep -q "style file" full0.err'

# profiles.tsv refused: a limit between force.tsv and profiles.tsv
lim=$(( (tsv * 3 + 1023) / 1024 ))
if [ $((lim * 1024)) -lt "$prof" ]; then
    (trap '' XFSZ; ulimit -f "$lim" && exec "$ADHERE" $RUN -o disk) 2>disk.err
    rc=$?
    check "profiles.tsv refused by a full disk: exit 2 (got $rc)" [ "$rc" -eq 2 ]
    check "... the message names it: $(head -c 300 disk.err)" grep -q 'profiles.tsv' disk.err
    check "... no profiles.tsv, not even cut" [ ! -e disk/profiles.tsv ]
    check "... summary.tsv is written and lists it under not_written ($(key disk not_written))" \
        sh -c 'printf "%s\n" "$1" | tr , "\n" | grep -qx profiles.tsv' sh "$(key disk not_written)"
    check "... status is not success ($(key disk status)) and complete is 0" \
        [ "$(key disk status)/$(key disk complete)" = "output incomplete/0" ]
    check "... force.tsv is whole (as many rows as unlimited)" [ "$(rows disk/force.tsv)" -eq "$(rows full/force.tsv)" ]
    no_temporaries disk "a full disk"
else
    echo "ok $((T + 1)) # SKIP profiles.tsv ($prof bytes) not larger than 3 x force.tsv ($tsv)"
    T=$((T + 1))
fi

# --- a file size limit with its signal left as the shell sets it ---------
# (ulimit -f without trap: SIGXFSZ would kill the process): the limit is a
# full disk, the run says so and leaves no temporary
(ulimit -f 8 && exec "$ADHERE" $RUN --step=0.1nm -o fsize) 2>fsize.err
rc=$?
check "ulimit -f 8, force.tsv about 28 kB (SIGXFSZ not ignored by the caller): exit 2, not killed (got $rc: $(head -c 200 fsize.err))" \
    [ "$rc" -eq 2 ]
check "... summary.tsv is written: complete 0, status output incomplete" \
    [ "$(key fsize complete)/$(key fsize status)" = "0/output incomplete" ]
check "... and names force.tsv under not_written ($(key fsize not_written))" \
    sh -c 'printf "%s\n" "$1" | tr , "\n" | grep -qx force.tsv' sh "$(key fsize not_written)"
check "... no force.tsv under its final name" [ ! -e fsize/force.tsv ]
check "... the message names the file and the limit: $(head -c 200 fsize.err)" grep -q 'force.tsv: File too large' fsize.err
no_temporaries fsize "a file size limit"

# --- gnuplot dying with an image open ----------------------------------------
cat >gp-dies <<EOF
#!/bin/sh
# passes commands on until the first 'set output', then stops: gnuplot has
# opened the temporary image and never finishes it
sed -u '/^set output/q' | gnuplot "\$@"
EOF
chmod +x gp-dies
ADHERE_GNUPLOT="$TMP/gp-dies" "$ADHERE" $RUN -o dies 2>dies.err
rc=$?
check "gnuplot dying mid-figure: exit 3 (got $rc: $(head -c 200 dies.err))" [ "$rc" -eq 3 ]
check "... no PNG under a final name" sh -c '! ls dies | grep -q "\.png$"'
no_temporaries dies "gnuplot dying"
check "... summary.tsv lists every figure as not written ($(key dies not_written))" \
    [ "$(key dies not_written)" = "force.png,profile.png,contact.png" ]
done_testing
