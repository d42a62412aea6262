#!/bin/sh
# One numeric locale: under a locale with a decimal comma (de_DE.UTF-8,
# built here with localedef when the machine lacks it) the TUI still reads
# :set E 0.5GPa (and refuses 0,5GPa), its p key draws the plots (gnuplot
# reads adhere's numbers) and profiles.tsv, contact.tsv and :rows are
# written with decimal points. Prints TAP.
. "$(dirname "$0")/lib.sh"
need_gnuplot
cd "$TMP" || exit 1
# the locale from its source (the Debian package locales): no root needed
mkdir loc
localedef -i de_DE -f UTF-8 "$TMP/loc/de_DE.UTF-8" >localedef.out 2>&1
export LOCPATH="$TMP/loc"
# (the C library's printf, as adhere's own, through coreutils' printf: not
# awk's, gawk prints 1.5 under any locale, nor dash's builtin, which does too)
comma=$(LC_ALL=de_DE.UTF-8 env printf '%.1f' 1.5)
check "a comma locale is there (localedef: $(head -c 120 localedef.out); 1.5 prints as $comma)" [ "$comma" = "1,5" ]

# (whole numbers in the :set lines: the plots and tables are tested apart
# from reading 0.5GPa)
cat >loc.keys <<'EOF'
:set N 100
:set spacing 10nm
:set eps 10pm
:set d 500pm
:set E 500MPa
33f
p
:rows rows.tsv
EOF
LC_ALL=de_DE.UTF-8 timeout 60 "$ADHERE" --replay=loc.keys --screen=loc.screen --no-clock -o plots </dev/null \
    >loc.out 2>loc.err
rc=$?
check "the TUI under LC_ALL=de_DE.UTF-8: steps, p and :rows run, exit 0 (got $rc: $(head -c 200 loc.err))" \
    [ "$rc" -eq 0 ]
check "... p says it wrote the plots: $(grep -o 'plots[^|]*' loc.screen | head -n 1 | cut -c1-120)" \
    grep -q 'plots: wrote force.png' loc.screen
check "... p drew force.png, profile.png and contact.png" \
    sh -c '[ -s plots/force.png ] && [ -s plots/profile.png ] && [ -s plots/contact.png ]'
# every data row's fields are numbers a C reader takes whole: no 1,5
numbers_ok() { # file: the rows after the header, each field a C number
    awk -F'\t' '/^#/ {next} !h {h = 1; next} {for (i = 1; i <= NF; i++) if ($i !~ /^[-+]?([0-9.]+([eE][-+]?[0-9]+)?|nan|inf)$/) bad = 1; n++}
                END {exit bad || n == 0}' "$1"
}
for t in plots/profiles.tsv plots/contact.tsv rows.tsv; do
    check "... $t is written with decimal points ($(grep -v '^#' "$t" 2>/dev/null | sed -n 2p | cut -c1-60))" numbers_ok "$t"
done
printf ':set E 0.5GPa\n:set d 0.5nm\n' >point.keys
LC_ALL=de_DE.UTF-8 timeout 60 "$ADHERE" --replay=point.keys --no-clock </dev/null >point.out 2>point.err
rc=$?
check "... :set E 0.5GPa and :set d 0.5nm are read there (exit $rc: $(head -c 160 point.err))" [ "$rc" -eq 0 ]
printf ':set E 0,5GPa\n' >comma.keys
LC_ALL=de_DE.UTF-8 timeout 60 "$ADHERE" --replay=comma.keys --no-clock </dev/null >comma.out 2>comma.err
rc=$?
check "... and :set E 0,5GPa is refused there, as everywhere (exit $rc: $(head -c 160 comma.err))" [ "$rc" -eq 2 ]
done_testing
