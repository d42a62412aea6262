#!/bin/sh
# Batch runs with --out make valid PNGs of the style's size beside their
# tables; --no-plot, --plots and --gnuplot-style are obeyed; with gnuplot off
# the PATH (or dying) the run exits 3 with every table intact and gnuplot's
# own stderr never printed raw. Prints TAP.
BIN=${ADHERE_BIN:-./adhere}
SRC=${ADHERE_SRC:-.}
export LC_ALL=C.UTF-8
T=$(mktemp -d "${TMPDIR:-/tmp}/adhere-plots-XXXXXX") || exit 1
trap 'rm -rf "$T"' EXIT
n=0 failed=0
ok() { n=$((n + 1)); echo "ok $n - $1"; }
no() { n=$((n + 1)); failed=$((failed + 1)); echo "not ok $n - $1"; }
check() { if eval "$1"; then ok "$2"; else no "$2"; fi; }

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "ok 1 # SKIP gnuplot is not installed (make deps installs it)"
    echo "1..1"
    exit 0
fi

# --force: a coarse grid (unresolved, and warned about) keeps the plots fast
RUN="--batch --quiet --nodes=100 --force --eps=1e-11"

# "W H" of a PNG, or "bad" when the file is not a PNG.
png_size() {
    [ -f "$1" ] || { echo missing; return; }
    sig=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
    ihdr=$(od -An -c -j12 -N4 "$1" | tr -d ' \n')
    if [ "$sig" != 89504e470d0a1a0a ] || [ "$ihdr" != IHDR ]; then echo bad; return; fi
    set -- $(od -An -tu1 -j16 -N8 "$1")
    echo "$(( ($1 << 24) + ($2 << 16) + ($3 << 8) + $4 )) $(( ($5 << 24) + ($6 << 16) + ($7 << 8) + $8 ))"
}

# data rows of a table: lines that are neither comments nor the header
rows() { grep -v '^#' "$1" 2>/dev/null | tail -n +2 | wc -l; }

# The size the installed style asks for.
size=$(sed -n 's/^set terminal pngcairo size \([0-9]*\),\([0-9]*\).*/\1 \2/p' \
       "$SRC/share/adhere/gnuplot/style.gp" | head -1)
check '[ -n "$size" ]' "the installed style sets a PNG size ($size)"

# --- a full run ---------------------------------------------------------
D=$T/full
"$BIN" $RUN --profiles=-5nm,-2nm,1nm,4nm -o "$D" 2>"$T/full.err"
rc=$?
check '[ $rc -eq 0 ]' "batch with plots exits 0 (got $rc)"
for p in force profile contact; do
    s=$(png_size "$D/$p.png")
    check '[ "$s" = "$size" ]' "$p.png is a valid PNG of $size (got $s)"
done
check '[ "$(grep -v "^#" "$D/profiles.tsv" | head -1)" = "$(printf "h0\tbranch\tpath\tr\th\tu\tp\th_sphere")" ]' \
    "profiles.tsv starts with its header"
check '[ "$(rows "$D/profiles.tsv")" -eq $((100 * 8)) ]' \
    "profiles.tsv holds 4 positions x 2 branches x 100 nodes ($(rows "$D/profiles.tsv") rows)"
check '[ "$(rows "$D/contact.tsv")" -eq "$(rows "$D/force.tsv")" ]' \
    "contact.tsv has a row for every force.tsv row"
check '! ls -a "$D" | grep -q "tmp"' "no temporary file left in the output dir"
check '! grep -v "warning: grid spacing .* (--force; summary.tsv: resolved 0)" "$T/full.err"' "nothing on stderr but the unresolved grid's warning"
# the contact line spreads while loading and recedes while unloading
check 'awk -F"\t" "!/^#/ && \$2 == 1 && \$6 != \"nan\" && \$6 < 0 {bad++} END {exit bad > 3}" "$D/contact.tsv"' \
    "loading contact-line speeds are positive (bar lattice hops)"
check 'awk -F"\t" "!/^#/ && \$2 == -1 && \$6 != \"nan\" && \$6 + 0 < 0 {neg++} END {exit !(neg > 10)}" "$D/contact.tsv"' \
    "unloading has receding (negative) speeds"

# --- several turns: the adhesion panel -----------------------------------
D=$T/turns
"$BIN" $RUN --turn=-3nm,0 --plots=force -o "$D" 2>"$T/turns.err"
rc=$?
s=$(png_size "$D/force.png")
check '[ $rc -eq 0 ] && [ "$s" = "$size" ]' "two turns: force.png with its adhesion panel ($rc, $s)"
check '[ ! -e "$D/profile.png" ] && [ ! -e "$D/contact.png" ]' "--plots=force makes force.png alone"

# --- force.png's references: the static curve and the models -------------
# A gnuplot that logs its commands and keeps the figures' data files
# (GPLOG.force.dat, GPLOG.contact.dat, ...) before adhere removes them, then
# passes everything to the real gnuplot.
GP=$(command -v gnuplot)
cat >"$T/logging-gnuplot" <<EOF
#!/bin/sh
tee -a "\$GPLOG" | "$GP" "\$@"
rc=\$?
for f in \$(sed -n "s/.*'\\([^']*\\/[a-z]*\\.dat\\)'.*/\\1/p" "\$GPLOG" | sort -u); do
    cp "\$f" "\$GPLOG.\$(basename "\$f")" 2>/dev/null
done
exit \$rc
EOF
chmod +x "$T/logging-gnuplot"
# dataset k (gnuplot's index: two blank lines apart) of a data file
dataset() { awk -v k="$1" 'NF == 0 {b++; next} {if (b >= 2) i++; b = 0} i == k' "$2"; }
# the index of the first plot clause whose style matches the ERE $1
index_of() { grep -E "index [0-9]+ using .* $1" "$2" | head -1 | sed 's/.* index \([0-9]*\) using.*/\1/'; }
val() { awk -F'\t' -v k="$1" '$1 == k {print $2}' "$2"; }

D=$T/ref
L=$T/ref.gp
GPLOG=$L ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --eps=3pm \
    --reference=static --plots=force -o "$D" 2>"$T/ref.err"
rc=$?
s=$(png_size "$D/force.png")
check '[ $rc -eq 0 ] && [ "$s" = "$size" ]' "--reference=static: force.png made ($rc, $s: $(head -c 200 "$T/ref.err"))"
check 'grep -q "keyentry with lines ls 9 title \"static equilibrium" "$L"' "the key names the static equilibrium"
for m in "JKR, pull-off" "Maugis–Dugdale, λ = " "DMT, pull-off" "models past pull-off"; do
    check 'grep -q "keyentry .*title \"$m" "$L"' "the key names \"$m\""
done
check '[ -s "$L.force.dat" ]' "force.png's data kept by the logging gnuplot"
# every stable point of static.tsv is in the dataset drawn solid with ls 9
i=$(index_of 'ls 9 notitle' "$L")
grep -v '^#' "$D/static.tsv" | awk -F'\t' 'NR > 1 && $11 == 1 {printf "%.9g %.9g\n", $1, $2}' | sort -u >"$T/static.want"
dataset "$i" "$L.force.dat" | awk '{printf "%.9g %.9g\n", $1, $2}' | sort -u >"$T/static.got"
nwant=$(wc -l <"$T/static.want")
check '[ -n "$i" ] && [ "$nwant" -gt 10 ] && [ -z "$(comm -23 "$T/static.want" "$T/static.got")" ]' \
    "the solid static curve (index $i) holds all $nwant stable points of static.tsv"
j=$(index_of 'ls 9 lw [0-9.]+ dt adh_unstable_dash' "$L")
nun=$(grep -v '^#' "$D/static.tsv" | awk -F'\t' 'NR > 1 && $11 == 0' | wc -l)
check '[ "$nun" -eq 0 ] || [ -n "$j" ]' "its $nun unstable points are drawn dashed (index $j)"
# the models on h0 = z0 - overlap: JKR's load part ends at -(3/2) pi gamma R,
# its dashed part at the fold, -(5/6) pi gamma R; DMT ends at h0 = z0, -2 pi gamma R
jkr=$(val F_jkr "$D/summary.tsv"); dmt=$(val F_dmt "$D/summary.tsv"); z0=$(val z0 "$D/summary.tsv")
i=$(index_of 'ls 3 notitle' "$L"); k=$(index_of 'ls 3 lc rgb adh_model_disp_color' "$L")
check '[ -n "$i" ] && dataset "$i" "$L.force.dat" | awk -v f="$jkr" "{m = NR == 1 || \$2 < m ? \$2 : m; last = \$2} END {exit !(NR > 10 && m == last && (m - f) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "JKR's load-controlled part (index $i) ends at its minimum, -(3/2) pi gamma R = $jkr N"
check '[ -n "$k" ] && dataset "$k" "$L.force.dat" | awk -v f="$jkr" "{last = \$2} END {exit !(NR > 10 && (last - f * 5 / 9) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "JKR's displacement-controlled part (index $k) ends at the fold, -(5/6) pi gamma R"
i=$(index_of 'ls 4 notitle' "$L")
check '[ -n "$i" ] && dataset "$i" "$L.force.dat" | awk -v f="$dmt" -v z="$z0" "{h = \$1; last = \$2} END {exit !(NR > 10 && (h - z) ^ 2 < (1e-9 * z) ^ 2 && (last - f) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "DMT (index $i) ends at contact, h0 = z0, with -2 pi gamma R = $dmt N"
i=$(index_of 'ls 8 notitle' "$L")
check '[ -n "$i" ] && dataset "$i" "$L.force.dat" | awk -v j="$jkr" -v d="$dmt" "{m = NR == 1 || \$2 < m ? \$2 : m} END {exit !(NR > 10 && m < j && m > d)}"' \
    "Maugis-Dugdale (index $i) pulls off between JKR and DMT"

# without --reference a relaxation run's force.png has no static curve
D=$T/noref
GPLOG=$T/noref.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --eps=3pm \
    --plots=force -o "$D" 2>/dev/null
check 'grep -q "keyentry .*JKR, pull-off" "$T/noref.gp" && ! grep -q "ls 9" "$T/noref.gp"' \
    "without --reference: the models, no static curve"

# --mode=static: the models beside the equilibrium curve
D=$T/static
GPLOG=$T/static.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --mode=static \
    --plots=force -o "$D" 2>"$T/static.err"
rc=$?
s=$(png_size "$D/force.png")
check '[ $rc -eq 0 ] && [ "$s" = "$size" ]' "--mode=static: force.png made ($rc, $s)"
check 'grep -q "title \"static equilibrium\"" "$T/static.gp" && grep -q "keyentry .*JKR, pull-off" "$T/static.gp" && grep -q "keyentry .*Maugis" "$T/static.gp" && grep -q "keyentry .*DMT, pull-off" "$T/static.gp"' \
    "--mode=static: the equilibrium curve with JKR, Maugis-Dugdale and DMT"

# --- a paper's figure: headings, the adhesion panel, units, eq 24 ----------
cat >"$T/two.scene" <<'SCENE'
[scene]
title = Figure 9: profiles somewhere else (E = 1 GPa)
[material]
E = 1GPa
[protocol]
turns = -3nm, 0nm
[output]
plots = force, profile
SCENE
D=$T/two
GPLOG=$T/two.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN "$T/two.scene" -o "$D" 2>"$T/two.err"
rc=$?
check '[ $rc -eq 0 ] && [ "$(png_size "$D/force.png")" = "$size" ]' "a titled two-turn scene: force.png ($rc: $(head -c 200 "$T/two.err"))"
head1="set multiplot title 'Figure 9 scene'.\"\\n\".'Force vs position"   # single-quoted runs, a fixed "\n"
check 'grep -qF "$head1" "$T/two.gp"' \
    "force.png is headed by the scene's label, not by the profiles' title"
head2="set title 'Figure 9: profiles somewhere else (E = 1 GPa)'.\"\\n\".'Surface profiles"
check 'grep -qF "$head2" "$T/two.gp"' \
    "the profiles, the scene's own figure, carry its title"
check 'grep -q "set size 0.64,0.9$" "$T/two.gp" && grep -q "set size 0.36,0.9$" "$T/two.gp"' \
    "under a two-line heading both panels stop at 90 % of the height, clear of it"
# the panel's load ticks: at least three inside its x range
sed -n '/^set xlabel "maximum load/,/^unset multiplot/p' "$T/two.gp" >"$T/panel.gp"
xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/panel.gp" | tail -1)
xt=$(sed -n 's/^set xtics \(.*\)$/\1/p' "$T/panel.gp" | tail -1)
check 'echo "$xr $xt" | awk "{lo = \$1; hi = \$2; st = \$3; n = 0; for (k = int(lo / st) - 1; k <= int(hi / st) + 1; k++) if (k * st >= lo && k * st <= hi) n++; exit !(st > 0 && n >= 3)}"' \
    "the adhesion panel has at least three load ticks with two turns (range $xr, step $xt)"
check 'echo "$xr $xt" | awk "{lo = \$1; hi = \$2; st = \$3; n = 0; for (k = int(lo / st) - 1; k <= int(hi / st) + 1; k++) if (k * st >= lo && k * st <= hi) n += length(sprintf(\"%g\", k * st)) + 2; exit !(n <= 30)}"' \
    "its tick labels fit the narrow panel without touching (at most 30 characters in all)"
yr=$(sed -n 's/^set yrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/panel.gp" | tail -1)
check 'echo "$yr" | awk "{exit !(NF == 2 && \$1 > 0 && \$2 > \$1)}"' "its adhesion axis does not start at 0 ($yr), so a rise then saturation shows"
cat >"$T/units.scene" <<'SCENE'
[scene]
title = Figure 1 again
[material]
E = 1GPa
[protocol]
turns = -2nm
unload = no
[output]
plots = precontact
SCENE
GPLOG=$T/units.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN "$T/units.scene" -o "$T/units" 2>/dev/null
check 'grep -q "set title \"Force before contact (Figure 1 inset), E = 1 GPa\"" "$T/units.gp" && ! grep -q "e+0[0-9] Pa" "$T/units.gp"' \
    "titles write moduli in one style (1 GPa, never 1e+09 Pa)"
cat >"$T/jump.scene" <<'SCENE'
[scene]
title = Figure 3, small
[protocol]
turns = none
[output]
plots = none
[sweep]
sigma = 1, 3
plot = jump
SCENE
GPLOG=$T/jump.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN "$T/jump.scene" -o "$T/jump" 2>"$T/jump.err"
check '[ "$(png_size "$T/jump/jump.png")" = "$size" ] && grep -q "with lines lw [0-9.]* dt 3 .*title \"eq 24\"" "$T/jump.gp"' \
    "Figure 3's eq 24 curve is dotted, as in the paper ($(head -c 100 "$T/jump.err"))"

# --- --data: a measured curve over force.png --------------------------------
q="$T/it's \"measured\".txt"
printf '# an AFM retraction, comma or blank separated\nh0[um] F[pN]\n0.002, -150000\n0.004  -120000\n0.006\t-50000\n' >"$q"
D=$T/data
GPLOG=$T/data.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --eps=3pm \
    --plots=force --data="$q" -o "$D" 2>"$T/data.err"
rc=$?
check '[ $rc -eq 0 ] && [ "$(png_size "$D/force.png")" = "$size" ]' "--data: force.png made ($rc: $(head -c 200 "$T/data.err"))"
i=$(index_of "with points .*title 'it'.+txt'[.]' retract'" "$T/data.gp")
check '[ -n "$i" ] && [ "$(dataset "$i" "$T/data.gp.force.dat" | awk "{printf \"%.6g %.6g\\n\", \$1, \$2}" | tr "\n" " ")" = "2e-09 -1.5e-07 4e-09 -1.2e-07 6e-09 -5e-08 " ]' \
    "the measured points are drawn (index $i), in the units the header names (um, pN), named in the key"
printf '%s' "it's" >"$T/rawname"
cat >"$T/quotedname" <<'QUOTED'
title 'it'."\047".'s "measured".txt'.' retract'
QUOTED
check '! grep -qFf "$T/rawname" "$T/data.gp" && grep -qFf "$T/quotedname" "$T/data.gp"' \
    "the file's name reaches gnuplot's commands only as adh_gp_quote writes it, in the key"
printf '1 -2\n3 -4\n5 oops\n' >"$T/bad.txt"
"$BIN" $RUN --turn=-2nm --data="$T/bad.txt" -o "$T/baddata" 2>"$T/bad.err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "^adhere: $T/bad.txt:3: .oops. is not a number (column 2, the force)" "$T/bad.err" && [ ! -e "$T/baddata/force.tsv" ]' \
    "a malformed --data file is refused with FILE:LINE and exit 2 before the run ($rc: $(cat "$T/bad.err"))"
printf 'z force\n1 2\n3 4\n' >"$T/nounit.txt"
"$BIN" $RUN --turn=-2nm --data="$T/nounit.txt" -o "$T/nounit" 2>"$T/nounit.err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "^adhere: .*nounit.txt:1: the header.s .z. does not name the position.s unit" "$T/nounit.err"' \
    "a header without units is refused, naming what to write ($(cat "$T/nounit.err"))"

# --- plots fit for a paper (issue 28, item 4) -----------------------------
# The palette: every colour the style gives the run differs from every other
# and from the loading colour; the references (models, rigid spheres) are
# black or grey, each with its own dash or width, so none shares a hue with
# a branch; JKR and Maugis-Dugdale never draw the same line.
ST="$SRC/share/adhere/gnuplot/style.gp"
word_list() { sed -n "s/^$1 = \"\\(.*\\)\"/\\1/p" "$ST" | tr ' ' '\n'; }
loadc=$(word_list adh_loading_color)
nun=$(word_list adh_unload_colors | wc -l)
check '[ "$nun" -ge 6 ] && [ "$(word_list adh_unload_colors | tr a-f A-F | sort -u | wc -l)" -eq "$nun" ] && ! word_list adh_unload_colors | grep -qix "$loadc"' \
    "the style's $nun unloading colours are all different, and none is the loading colour $loadc"
npc=$(word_list adh_profile_colors | wc -l)
check '[ "$npc" -ge 10 ] && [ "$(word_list adh_profile_colors | tr a-f A-F | sort -u | wc -l)" -eq "$npc" ]' \
    "each of the $npc profile positions of Figure 4 takes its own colour"
lsdef() { sed -n "s/^set style line $1 \\(.*\\) *# .*/\\1/p" "$ST" | sed 's/ *$//'; }
grey() { echo "$1" | grep -qE 'lc rgb "#([0-9a-fA-F]{2})\1\1"'; }
check 'grey "$(lsdef 2)" && grey "$(lsdef 3)" && grey "$(lsdef 4)" && grey "$(lsdef 8)"' \
    "rigid spheres, JKR, DMT and Maugis-Dugdale are drawn in black or grey: $(lsdef 3); $(lsdef 8); $(lsdef 4)"
check '[ "$(lsdef 3)" != "$(lsdef 8)" ] && [ "$(lsdef 3)" != "$(lsdef 4)" ] && [ "$(lsdef 4)" != "$(lsdef 8)" ] && ! word_list adh_unload_colors | grep -qi "^#000000$"' \
    "JKR, DMT and Maugis-Dugdale each have their own line, and no branch is black"
# force.png of a two-turn run: each branch its own colour and dash, the
# key below the frame, no x range past where the curves flatten
D=$T/paper
GPLOG=$T/paper.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm,0 --eps=3pm --plots=force \
    -o "$D" 2>"$T/paper.err"
rc=$?
check '[ $rc -eq 0 ] && [ -s "$D/force.png" ]' "a two-turn run's force.png ($rc: $(head -c 200 "$T/paper.err"))"
check 'grep -q "lc rgb adh_ucol(1) lw adh_unloading_width dt adh_udash(1)" "$T/paper.gp" && grep -q "lc rgb adh_ucol(2) lw adh_unloading_width dt adh_udash(2)" "$T/paper.gp"' \
    "each unloading branch is drawn in its own colour and dash"
# the style's colour and dash of each of nine branches, by gnuplot itself
cat >"$T/udash.gp" <<GPEOF
load "$ST"
$(grep -E '^adh_(nc|ucol|udash)' "$T/paper.gp" | sed 's/^/ /')
do for [p=1:9] { print adh_ucol(p), adh_udash(p) }
GPEOF
sed -i 's/^ //' "$T/udash.gp"
gnuplot "$T/udash.gp" 2>"$T/udash.txt"
check '[ "$(wc -l <"$T/udash.txt")" -eq 9 ] && [ "$(sort -u "$T/udash.txt" | wc -l)" -eq 9 ]' \
    "nine branches (Figure 6) never repeat a colour with the same dash: $(tr '\n' ';' <"$T/udash.txt")"
check 'grep -q "^set key at screen 0.5, screen 0.01 center bottom" "$T/paper.gp" && ! grep -q "^set key \\(top\\|bottom\\|right\\|left\\)" "$T/paper.gp"' \
    "force.png's key sits below the frames, never over the data"
xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/paper.gp" | head -1)
start=$(awk -F'\t' '!/^#/ && $1 != "h0" {print $1; exit}' "$D/force.tsv")
last=$(awk -F'\t' '!/^#/ && $1 != "h0" && $9 > 0 && $5 > 0 {if ($1 > m) m = $1} END {print m}' "$D/force.tsv")
check 'echo "$xr $start $last" | awk "{exit !(\$2 < \$3 * 1e9 && \$2 > \$4 * 1e9)}"' \
    "the position axis ($xr nm) stops short of the start ($start m), past the last contact ($last m)"
check '[ "$(grep -c "^set yrange" "$T/paper.gp")" -ge 1 ]' "the force axis is set from the data"
# models.tsv: the curves force.png draws, against their closed forms
M=$D/models.tsv
mval() { awk -F'\t' -v m="$1" -v p="$2" '$1 == m && $2 == p {print $'"$3"'}' "$M"; }
summ() { awk -F'\t' -v k="$1" '$1 == k {print $2}' "$D/summary.tsv"; }
jkr=$(summ F_jkr); dmt=$(summ F_dmt); z0=$(summ z0)
check '[ -s "$M" ] && head -20 "$M" | grep -qx "$(printf "model\tpart\th0\tF")"' "models.tsv is written beside force.tsv, with its header"
check 'mval jkr load 4 | awk -v f="$jkr" "{m = NR == 1 || \$1 < m ? \$1 : m; last = \$1} END {exit !(NR > 10 && m == last && (m - f) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "models.tsv: JKR's load part ends at its minimum, -(3/2) pi gamma R = $jkr N"
check 'mval jkr displacement 4 | awk -v f="$jkr" "{last = \$1} END {exit !(NR > 10 && (last - f * 5 / 9) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "models.tsv: JKR's displacement part ends at the fold, -(5/6) pi gamma R"
check 'mval dmt load 3 | tail -1 | awk -v z="$z0" "{exit !((\$1 - z) ^ 2 < (1e-9 * z) ^ 2)}" && mval dmt load 4 | tail -1 | awk -v f="$dmt" "{exit !((\$1 - f) ^ 2 < (1e-9 * f) ^ 2)}"' \
    "models.tsv: DMT ends at contact, h0 = z0, with -2 pi gamma R = $dmt N"
check 'mval maugis_dugdale load 4 | awk -v j="$jkr" -v d="$dmt" "{m = NR == 1 || \$1 < m ? \$1 : m} END {exit !(NR > 10 && m < j && m > d)}"' \
    "models.tsv: Maugis-Dugdale pulls off between JKR and DMT"
awk -F'\t' '!/^#/ && $1 != "h0" && $9 == 0 && $1 > 0 {printf "%.12g %.12g\n", $1, $12}' "$D/force.tsv" | sort >"$T/rigid.want"
awk -F'\t' '$1 == "rigid" {printf "%.12g %.12g\n", $3, $4}' "$M" | sort >"$T/rigid.got"
check '[ "$(wc -l <"$T/rigid.got")" -gt 10 ] && cmp -s "$T/rigid.want" "$T/rigid.got"' \
    "models.tsv: eq 22 at every approach position before contact, as force.tsv's F_rigid ($(wc -l <"$T/rigid.got") rows)"
# --- force-base.png: the force against the instrument's base ---------------
# Written exactly when a finite spring sets the base apart from h0 (the
# static curve, physical time); without one base = h0: no such file.
check '[ -s "$T/static/force.png" ] && [ -s "$T/ref/force.png" ] && [ ! -e "$T/static/force-base.png" ] && [ ! -e "$T/ref/force-base.png" ] && ! grep -q forcebase "$T/static.gp" "$T/ref.gp"' \
    "no spring: no force-base.png (the static curve, a relaxation)"
# n-th point (from 1) of dataset k of a data file, column c
pt() { dataset "$1" "$2" | awk -v n="$3" -v c="$4" 'NR == n {print $c}'; }
# |a - b| <= tol * |s|: a relation within the printed digits, not a number
near() { awk "BEGIN {d = ($1) - ($2); s = $3; t = $4; exit !(d * d <= t * t * s * s)}"; }
k=10
D=$T/sk
GPLOG=$T/sk.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --mode=static --spring=$k \
    --plots=force -o "$D" 2>"$T/sk.err"
rc=$?
check '[ $rc -eq 0 ] && [ "$(png_size "$D/force-base.png")" = "$size" ] && grep -q "^force-base.png	" "$D/.adhere-manifest"' \
    "--mode=static --spring: force-base.png made and in the manifest ($rc: $(head -c 200 "$T/sk.err"))"
check 'grep -q "^set xlabel \"base (piezo) position (nm)\"" "$T/sk.gp" && grep -q "^set key at screen 0.5, screen 0.01 center bottom" "$T/sk.gp"' \
    "force-base.png: the base (piezo) position in nm, the key below the frame"
F=$T/sk.gp.forcebase.dat
i=$(index_of 'title "snap-in' "$T/sk.gp"); o=$(index_of 'title "snap-out' "$T/sk.gp")
a=$(index_of 'title "approach"' "$T/sk.gp"); r=$(index_of 'title "retraction"' "$T/sk.gp")
b1=$(pt "$i" "$F" 1 1) f1=$(pt "$i" "$F" 1 2) h1=$(pt "$i" "$F" 1 3) b2=$(pt "$i" "$F" 2 1) f2=$(pt "$i" "$F" 2 2) h2=$(pt "$i" "$F" 2 3)
sb=$(val snap_in_base "$D/summary.tsv"); sh=$(val snap_in_h0 "$D/summary.tsv")
check '[ -n "$i" ] && [ "$b1" = "$b2" ] && [ "$b1" = "$(printf %.17g "$sb")" ] && near "$f1" "$k * ($sh - $sb)" "$f1" 1e-9 && near "$h1" "$sh" "$sh" 1e-12' \
    "the snap-in at one base, summary.tsv's snap_in_base ($b1 = $sb m), from F = k (snap_in_h0 - base)"
check 'near "$f2 - $f1" "$k * ($h2 - $h1)" "$f2 - $f1" 1e-9 && [ "$(echo "$h2 $h1" | awk "{print (\$1 < \$2)}")" = 1 ]' \
    "the snap-in's force change ($f1 to $f2 N) is k times the sphere's flight in ($h1 to $h2 m)"
# where it lands is on the curve of force.tsv: between two rows, linearly
check 'grep -v "^#" "$D/force.tsv" | awk -F"\t" -v k=$k -v b="$b2" -v f="$f2" "NR > 1 {c = \$1 - \$2 / k; if (NR > 2 && (c - b) * (p - b) <= 0 && c != p) {g = q + (\$2 - q) * (b - p) / (c - p); if ((g - f) ^ 2 < (1e-9 * f) ^ 2) ok = 1} p = c; q = \$2} END {exit !ok}"' \
    "the snap-in lands on force.tsv's curve at that base"
ob=$(pt "$o" "$F" 1 1) of1=$(pt "$o" "$F" 1 2) oh1=$(pt "$o" "$F" 1 3) ob2=$(pt "$o" "$F" 2 1) of2=$(pt "$o" "$F" 2 2) oh2=$(pt "$o" "$F" 2 3)
check '[ -n "$o" ] && [ "$ob" = "$ob2" ] && [ "$ob" = "$(printf %.17g "$(val snap_out_base "$D/summary.tsv")")" ] && near "$of2 - $of1" "$k * ($oh2 - $oh1)" "$of1" 1e-9' \
    "the snap-out at summary.tsv's snap_out_base ($ob m), its force change k times the sphere's flight"
# a stiff spring's snap-out lands beyond the curve's start: force.tsv has
# no base out there, and the free sphere's force is drawn as 0
check 'grep -v "^#" "$D/force.tsv" | awk -F"\t" -v k=$k -v b="$ob" "NR > 1 && \$1 - \$2 / k >= b {n++} END {exit n > 0}" && [ "$of2" = 0 ] && [ "$oh2" = "$ob" ]' \
    "past force.tsv's start the snap-out lands at F = 0, h0 = base"
# the piezo moves one way on each: in the approach's base falls, in the
# retraction's it rises (a snap: the same base twice); each from force.tsv's end
first=$(grep -v '^#' "$D/force.tsv" | awk -F'\t' -v k=$k 'NR == 2 {printf "%.9g", $1 - $2 / k}')
last=$(grep -v '^#' "$D/force.tsv" | awk -F'\t' -v k=$k 'NR > 1 {v = $1 - $2 / k} END {printf "%.9g", v}')
check '[ -n "$a" ] && dataset "$a" "$F" | awk -v s="$first" "NR == 1 && sprintf(\"%.9g\", \$1) != s {bad++} NR > 1 && \$1 > p {bad++} {p = \$1} END {exit bad || NR < 10}"' \
    "the approach starts at force.tsv's first row's base ($first m) and its base never rises"
check '[ -n "$r" ] && dataset "$r" "$F" | awk -v s="$last" "NR == 1 && sprintf(\"%.9g\", \$1) != s {bad++} NR > 1 && \$1 < p {bad++} {p = \$1} END {exit bad || NR < 10}"' \
    "the retraction starts at the curve's deepest point ($last m) and its base never falls"
# a soft spring's snap-in lands past the curve's deepest point: an arrow
# down to k (h0 there - base), where the sphere would sit at that point;
# physical time's landing (the same grid and spring) is below it
k=1
D=$T/sk1
GPLOG=$T/sk1.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-1.5nm --mode=static --spring=$k \
    --plots=force -o "$D" 2>/dev/null
set -- $(sed -n 's/^set arrow from first \([^,]*\), first \([^ ]*\) to first \([^,]*\), first \([^ ]*\) .*/\1 \2 \3 \4/p' "$T/sk1.gp")
narrow=$# arrow_at=$1 arrow_from=$2 arrow_at2=$3 arrow_to=$4
hl=$(grep -v '^#' "$D/force.tsv" | awk -F'\t' 'NR > 1 {v = $1} END {print v}')
sb=$(val snap_in_base "$D/summary.tsv"); sh=$(val snap_in_h0 "$D/summary.tsv")
check '[ "$narrow" -eq 4 ] && [ "$arrow_at" = "$arrow_at2" ] && near "$arrow_at" "$sb * 1e9" "$arrow_at" 1e-9 && near "$arrow_to / $arrow_from" "($hl - $sb) / ($sh - $sb)" 1 1e-9 && grep -q "keyentry .*past the curve" "$T/sk1.gp"' \
    "k = 1 N/m: the snap-in's arrow at snap_in_base ($arrow_at nm) ends at k (h0 at the curve's end - base)"
# physical time through the integrator: a standard linear solid with
# Einf = E0 (an elastic sphere in time walks its static curve instead)
D=$T/tk
GPLOG=$T/tk.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN --material=sls --E0=1GPa --Einf=1GPa --turn=-1.5nm \
    --mode=time --spring=$k --plots=force -o "$D" 2>/dev/null
rc=$?
F=$T/tk.gp.forcebase.dat
check '[ $rc -eq 0 ] && [ "$(png_size "$D/force-base.png")" = "$size" ] && grep -q "^set xlabel \"base (piezo) position (nm)\"" "$T/tk.gp"' \
    "--mode=time --spring: force-base.png made ($rc)"
# its snap points are the rows of events.tsv's jumps, at one base each
ev() { awk -F'\t' -v w="$1" -v c="$2" '$1 == "jump" {n++; v[n] = $c} END {print v[w == "first" ? 1 : n]}' "$D/events.tsv"; }
i=$(index_of 'title "snap-in' "$T/tk.gp"); o=$(index_of 'title "snap-out' "$T/tk.gp")
check '[ -n "$i" ] && [ "$(pt "$i" "$F" 1 1)" = "$(ev first 4)" ] && [ "$(pt "$i" "$F" 2 1)" = "$(ev first 4)" ] && [ "$(pt "$i" "$F" 1 3)" = "$(ev first 5)" ] && [ "$(pt "$i" "$F" 2 3)" = "$(ev first 8)" ] && near "$(pt "$i" "$F" 1 2)" "$(ev first 6)" "$(ev first 6)" 1e-9 && near "$(pt "$i" "$F" 2 2)" "$(ev first 9)" "$(ev first 9)" 1e-9' \
    "physical time: the snap-in's points are events.tsv's first jump, before and after at its base ($(ev first 4) m)"
check '[ -n "$o" ] && [ "$(pt "$o" "$F" 1 1)" = "$(ev last 4)" ] && [ "$(pt "$o" "$F" 2 1)" = "$(ev last 4)" ] && near "$(pt "$o" "$F" 2 2) - $(pt "$o" "$F" 1 2)" "$k * ($(pt "$o" "$F" 2 3) - $(pt "$o" "$F" 1 3))" "$(pt "$o" "$F" 1 2)" 1e-6' \
    "physical time: the snap-out is events.tsv's last jump, its force change k times the sphere's flight (to 1e-6: the integrator's fold holds the spring's equation to its tolerance, 6e-8 here)"
# the static figure's arrow bounds where the sphere lands: F scaled alike in both
check 'awk -v t="$(ev first 9)" -v f="$(ev first 6)" -v a="$arrow_to" -v b="$arrow_from" "BEGIN {exit !(t / f >= a / b)}"' \
    "physical time's snap-in lands ($(ev first 9) N) at or past the static arrow's end"
# an elastic sphere in time walks its static curve, solved past the turn
# where the snap-in lands beyond it: the approach unbroken, no arrow, the
# landing on the spring's line at the snap's base
D=$T/te
GPLOG=$T/te.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-1.5nm --mode=time --spring=$k \
    --plots=force -o "$D" 2>/dev/null
a=$(index_of 'title "approach"' "$T/te.gp")
eb=$(awk -F'\t' '$1 == "jump" {print $4; exit}' "$D/events.tsv")
land=$(awk -F'\t' -v k="$k" '$1 == "jump" {d = $9 - k * ($8 - $4); print (d < 0 ? -d : d) <= 1e-9 * ($9 < 0 ? -$9 : $9) && $8 < -1.5e-9; exit}' "$D/events.tsv")
# (a single blank line breaks a dataset's curve: no segment across it; the
# landing's base is h0 - F/k again, equal to the snap's to rounding)
check '[ -n "$a" ] && awk -v k="$a" "!NF {b++; brk = 1; next} {if (b >= 2) i++; b = 0} i == k {if (!brk && n && \$1 > p + 1e-12 * (p < 0 ? -p : p)) bad++; p = \$1; n++; brk = 0} END {exit bad || n < 10}" "$T/te.gp.forcebase.dat" && [ "$(grep -c "^set arrow" "$T/te.gp")" -eq 0 ] && [ "$land" = 1 ]' \
    "elastic physical time: the approach's base never rises, the snap-in from base $eb m lands past the turn on the spring's line, no arrow"
# turns a snap-in passes together (through 10 N/m the landing at -2.79 nm
# passes -1 and -2 nm) unload from one point, the same rows: the key named
# that retraction twice; now once, saying so, and the turn at -3 nm apart
D=$T/tt
GPLOG=$T/tt.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN --turns=-1nm,-2nm,-3nm --mode=time --spring=10N/m \
    --plots=force -o "$D" 2>/dev/null
same=$(grep -v '^#' "$D/turns.tsv" | awk -F'\t' 'NR > 1 {n[$1]++} END {for (h in n) if (n[h] == 2) print h}')
check '[ -n "$same" ] && [ "$(grep -o "title \"retraction[^\"]*\"" "$T/tt.gp" | sort | uniq -d)" = "" ] && [ "$(grep -c "title \"retraction from h_0 = " "$T/tt.gp")" -eq 2 ] && grep -q "title \"retraction from h_0 = $(awk "BEGIN {printf \"%.3g\", $same * 1e9}") nm (2 turns, one snap)\"" "$T/tt.gp" && grep -q "title \"retraction from h_0 = -3 nm\"" "$T/tt.gp"' \
    "turns at -1 and -2 nm both passed in the snap-in (at $same m): one retraction in force-base.png's key, said so, and -3 nm's"
# the same directory run again without a spring: the earlier figure goes
"$BIN" $RUN -E 1GPa --turn=-2nm --mode=static --plots=force -o "$T/sk" 2>/dev/null
check '[ -s "$T/sk/force.png" ] && [ ! -e "$T/sk/force-base.png" ]' \
    "a run without a spring into the same directory removes the earlier force-base.png"

# one spelling of units and no title that repeats the heading's numbers
check '! grep -h "^set .*title\|^set .*label\|title \"" "$T"/*.gp | grep -q "um/s\|sigma = [0-9]"' \
    "no figure writes um/s or repeats sigma in words (µm/s, σ in the heading)"
check '! grep -h "^title" "$SRC"/share/adhere/scenes/*.scene | grep -qi "sigma = \|E = [0-9]\|R = [0-9]\|um/s"' \
    "the shipped scenes' titles leave sigma, E, R and speeds to the headings"

# The static curve's contact.png: the contact radius alone (a curve of
# equilibria has no speed), stable and unstable stretches apart; its
# contact.tsv says the speeds are nan
D=$T/staticc
GPLOG=$T/staticc.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN -E 1GPa --turn=-2nm --mode=static \
    --plots=contact -o "$D" 2>"$T/staticc.err"
rc=$?
check '[ $rc -eq 0 ] && [ "$(png_size "$D/contact.png")" = "$size" ]' "--mode=static: contact.png made ($rc: $(head -c 200 "$T/staticc.err"))"
check '! grep -q "speed" "$T/staticc.gp" && grep -q "set ylabel \"contact radius a (µm)\"" "$T/staticc.gp"' \
    "--mode=static: no speed panel, the contact radius labelled"
check 'grep -q "with lines ls 1 title \"stable\"" "$T/staticc.gp" && grep -q "dt adh_unstable_dash title \"unstable (displacement control)\"" "$T/staticc.gp"' \
    "--mode=static: stable and unstable stretches styled apart in the key"
i=$(index_of 'ls 1 title "stable"' "$T/staticc.gp")
grep -v '^#' "$D/force.tsv" | awk -F'\t' 'NR > 1 && $11 == 1 {printf "%.9g %.9g\n", $1, $5}' | sort -u >"$T/sa.want"
dataset "$i" "$T/staticc.gp.contact.dat" | awk '{printf "%.9g %.9g\n", $1, $2}' | sort -u >"$T/sa.got"
check '[ -n "$i" ] && [ "$(wc -l <"$T/sa.want")" -gt 10 ] && [ -z "$(comm -23 "$T/sa.want" "$T/sa.got")" ]' \
    "--mode=static: the solid curve holds every stable row's contact radius ($(wc -l <"$T/sa.want") rows)"
check 'awk -F"\t" "!/^#/ && \$1 != \"h0\" && (\$6 != \"nan\" || \$7 != \"nan\") {bad++} END {exit bad > 0}" "$D/contact.tsv" && grep -q "^# the static equilibrium curve: nothing moves along it" "$D/contact.tsv"' \
    "--mode=static: contact.tsv's speeds are nan, and it says why"

# Figure 3's axes hold the points, not the decades round them
yr=$(sed -n 's/^set yrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/jump.gp" | tail -1)
hmin=$(awk -F'\t' '!/^#/ && $1 != "run" {print $8}' "$T/jump/sweep.tsv" | sort -g | head -1)
check 'echo "$yr $hmin" | awk "{exit !(\$1 > 0 && \$1 >= \$3 * 1e9 / 1.5 && \$2 < 10)}" && grep -q "^set ytics (" "$T/jump.gp"' \
    "Figure 3's gap axis ($yr nm) starts within a factor 1.5 of the smallest gap ($hmin m), with its own tics"

# Figure 7's frame: the runs' curves to where they flatten, not the start;
# the key below it; each run's colour from the style
cat >"$T/f7.scene" <<'SCENE'
[scene]
title = Figure 7, small
[material]
E = 1GPa
[protocol]
turns = -2nm
[output]
plots = none
[sweep]
eps = 3pm, 2pm
plot = force
SCENE
GPLOG=$T/f7.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" $RUN "$T/f7.scene" -o "$T/f7" 2>"$T/f7.err"
# (the force panel's range is the first; the hysteresis panel's follows)
xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/f7.gp" | head -1)
hmax=$(awk -F'\t' '!/^#/ && $1 != "h0" {if ($1 > m) m = $1} END {print m}' "$T/f7/run-1/force.tsv")
jout=$(awk -F'\t' '$1 == "jump_out_h0" {print $2}' "$T/f7/run-1/summary.tsv")
check '[ -s "$T/f7/force.png" ] && echo "$xr $hmax $jout" | awk "{exit !(\$2 < 0.8 * \$3 * 1e9 && \$2 > \$4 * 1e9)}"' \
    "Figure 7's position axis ($xr nm) ends short of the start ($hmax m), past the jump-out ($jout m)"
check 'grep -q "^set key outside below" "$T/f7.gp" && grep -q "lc rgb word(adh_sweep_colors, 1 + 1 % words(adh_sweep_colors)) title \"ε = 2 pm\"" "$T/f7.gp"' \
    "Figure 7's key below the frame, each run in the style's sweep colours"
# the hysteresis panel's key inside its frame: the force panel's "outside
# below" would hold otherwise and put it over the panel's eps label
check 'sed -n "/^set origin 0.64,0/,\$p" "$T/f7.gp" | grep -q "^set key inside "' \
    "Figure 7's hysteresis panel keeps its key inside its frame, off its x label"

# --- --no-plot ------------------------------------------------------------
D=$T/noplot
"$BIN" $RUN --no-plot -o "$D" 2>/dev/null
rc=$?
check '[ $rc -eq 0 ] && ! ls "$D" | grep -q "\.png$"' "--no-plot: exit 0 and no PNG"

# --- --gnuplot-style --------------------------------------------------------
printf 'set terminal pngcairo size 640,400\n' >"$T/small.gp"
D=$T/style
"$BIN" $RUN --plots=contact --gnuplot-style="$T/small.gp" -o "$D" 2>/dev/null
rc=$?
s=$(png_size "$D/contact.png")
check '[ $rc -eq 0 ] && [ "$s" = "640 400" ]' "--gnuplot-style sets the size (got $rc, $s)"

# --- gnuplot off the PATH ---------------------------------------------------
D=$T/nognuplot
PATH=/nonexistent "$BIN" $RUN -o "$D" 2>"$T/nognuplot.err"
rc=$?
check '[ $rc -eq 3 ]' "gnuplot off the PATH: exit 3 (got $rc)"
check 'grep -q "gnuplot not found" "$T/nognuplot.err"' \
    "and says so: $(head -1 "$T/nognuplot.err")"
for t in force.tsv summary.tsv profiles.tsv contact.tsv; do
    check '[ "$(rows "$D/$t")" -gt 0 ] || [ $t = profiles.tsv -a -s "$D/$t" ]' "$t still written"
done
check '! ls "$D" | grep -q "png"' "no PNG, not even a partial one"

# --- a soft spring in physical time: its snap-out lands a millimetre out -
# (F / k: 1.7 uN / 1e-3 N/m); the position axis is the contact's, not the
# flight's (its margin alone was 35 um and hid the curve), and the heading
# says the speed in its own unit (it said 1e+06 um/s)
D=$T/soft
GPLOG=$T/soft.gp ADHERE_GNUPLOT=$T/logging-gnuplot "$BIN" --batch --quiet --nodes=400 --force --material=sls \
    --spring=1e-3N/m --speed=1m/s -o "$D" 2>"$T/soft.err"
rc=$?
sed -n '/Force vs position/,/^unset multiplot/p' "$T/soft.gp" >"$T/softforce.gp"
xr=$(sed -n 's/^set xrange \[\(.*\):\(.*\)\]$/\1 \2/p' "$T/softforce.gp" | head -1)
far=$(awk -F'\t' '!/^#/ && $1 != "t" && $3 > m {m = $3} END {print m * 1e9}' "$D/force.tsv")
check 'echo "$xr $far" | awk "{exit !(NF == 3 && \$1 < -5 && \$1 > -7 && \$2 > 7 && \$2 < 100 && \$3 > 1e5)}"' \
    "a soft spring's force.png spans the contact (-5 nm turn, 7.2 nm jump-out), not its landing at $far nm ($rc; x range $xr)"
check 'grep -q "Force vs position at 1 m/s" "$T/softforce.gp" && grep -q "Contact line in time, base at 1 m/s" "$T/soft.gp"' \
    "its headings say 1 m/s"
check 'grep -q "set xlabel \"sphere position h_0 (nm)\"" "$T/softforce.gp" && ! grep -q "drive position" "$T/soft.gp" && grep -q "set xlabel \"drive position h_0 (nm)\"" "$T/two.gp"' \
    "through a spring the position axis is the sphere's (h0 = base + F/k), without one the drive's"

# --- a gnuplot that dies, shouting on stderr -----------------------------
printf '#!/bin/sh\necho "fatal: out of ink" >&2\nexit 7\n' >"$T/dying-gnuplot"
chmod +x "$T/dying-gnuplot"
D=$T/dying
ADHERE_GNUPLOT=$T/dying-gnuplot "$BIN" $RUN -o "$D" 2>"$T/dying.err"
rc=$?
check '[ $rc -eq 3 ]' "a dying gnuplot: exit 3 (got $rc)"
check 'grep -q "status 7.*out of ink" "$T/dying.err"' "its death and last words are quoted once"
check '! grep -qx "fatal: out of ink" "$T/dying.err"' "its raw stderr never reaches the terminal"
check '[ -s "$D/gnuplot.log" ]' "its stderr is kept in gnuplot.log"
check '[ "$(rows "$D/force.tsv")" -gt 0 ] && [ -s "$D/contact.tsv" ]' "tables intact"

echo "1..$n"
[ $failed -eq 0 ]
