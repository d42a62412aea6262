#!/bin/sh
# adhere fit --model=time: a standard linear solid in physical time fitted
# to a loading+unloading curve. The curve is adhere's own physical-time run
# at E0 = 1 GPa, Einf = 3 GPa, tau = 1 s, A = 1e-19 J, driven at 1 nm/s to
# -1 nm (R = 1 um on a coarse resolved grid, N = 150, 2 nm), read at every
# 0.05 nm of the base's travel (the turn itself the deepest point) with
# Gaussian noise of 0.66 nN (1 % of its pull-off) from a seeded generator
# written out in the awk script (drand48's, so the same numbers under any
# awk: srand/rand were mawk's own): the truth is what the test chose. The fit starts from (1.3 E0,
# 0.8 A, 2.5 GPa, 0.7 s). Then best.scene reruns the best model, and the
# refusals.
. "$(dirname "$0")/lib.sh"
G="-N 150 --spacing=2nm -R 1um"
SLS="--material=sls --E0=1GPa --Einf=3GPa --tau=1s --speed=1nm/s"
"$ADHERE" --batch -q --no-plot $SLS $G --turn=-1nm -o "$TMP/gen" 2>"$TMP/gen.err"
rc=$?
check "the physical-time run that makes the curve ($rc: $(head -c 300 "$TMP/gen.err"))" [ $rc -eq 0 ]
# force.tsv's base (2) and F (4) by path (11), linear between the
# integrator's rows, at every DX nm of the base from the start down to the
# turn and back (from FROM nm, when given, not the start); SD nN of noise
# (Box-Muller on drand48's generator, seeded as srand48(SEED) seeds it:
# lib.sh's $DRAND48)
cat >"$TMP/sample.awk" <<'EOF'
BEGIN {FS = "\t"; srand48(seed); print "position (nm)\tF (nN)"}
/^#/ || $1 == "t" {next}
{p = $11 + 0; n[p]++; b[p, n[p]] = $2 * 1e9; f[p, n[p]] = $4 * 1e9}
function emit(p, x,   i, a, c) {
    for (i = 1; i < n[p]; i++) {
        a = b[p, i]; c = b[p, i + 1]
        if (a != c && ((x <= a && x >= c) || (x >= a && x <= c))) {
            printf "%.6f\t%.6f\n", x, f[p, i] + (f[p, i + 1] - f[p, i]) * (x - a) / (c - a) + sd * gauss()
            return
        }
    }
}
END {
    top = from != "" ? from : b[0, 1]; lo = b[0, n[0]]
    for (k = 0; top - k * dx > lo + 1e-6; k++) emit(0, top - k * dx)
    printf "%.6f\t%.6f\n", lo, f[0, n[0]] + sd * gauss()
    end = b[1, n[1]] < top ? b[1, n[1]] : top
    for (k = 1; lo + k * dx <= end + 1e-9; k++) emit(1, lo + k * dx)
}
EOF
awk -v seed=7 -v sd=0.66 -v dx=0.05 -f "$DRAND48" -f "$TMP/sample.awk" "$TMP/gen/force.tsv" >"$TMP/curve.tsv"
n=$(($(wc -l <"$TMP/curve.tsv") - 1))
check "the curve: $n points, down to the turn at -1 nm and back" \
    sh -c "[ $n -gt 250 ] && grep -q '^-1.000000	' '$TMP/curve.tsv'"

# (from a scene whose time_tol, looser than the model's 1e-5, the fit
# ignores: it says so, by key and line, as for the scene's other ignored
# keys; it had been dropped in silence)
printf '[solver]\ntime_tol = 1e-3\n' >"$TMP/tol.scene"
"$ADHERE" fit --model=time --data="$TMP/curve.tsv" --material=sls --E0=1.3GPa --Einf=2.5GPa --tau=0.7s -A 0.8e-19J \
    --speed=1nm/s $G --no-plot -o "$TMP/fit" "$TMP/tol.scene" >"$TMP/fit.out" 2>"$TMP/fit.err"
rc=$?
check "adhere fit --model=time exits 0 with a fit ($rc: $(grep '^result' "$TMP/fit.out"); $(tail -1 "$TMP/fit.err"))" \
    sh -c "[ $rc -eq 0 ] && grep -qx 'result: fit' '$TMP/fit.out'"
check "the scene's time_tol = 1e-3 is said to be ignored, by key and line ($(grep 'ignores' "$TMP/fit.err"))" \
    grep -q "^adhere: the fit ignores the scene's time_tol ($TMP/tol.scene:2): .*a tolerance of 1e-05 or tighter" "$TMP/fit.err"
check "the report names the model, E0 (the solid's E), Einf and tau with their standard errors" \
    sh -c "grep -q '^fit: 4 free parameters, physical-time model' '$TMP/fit.out' && grep -q '^E0  .*MPa (' '$TMP/fit.out' && grep -q '^Einf  .*MPa (' '$TMP/fit.out' && grep -q '^tau  .* ms (' '$TMP/fit.out' && grep -q '^  tau  ' '$TMP/fit.out'"
# each recovered within 3 of its standard errors
for p in E0:1e9 A:1e-19 Einf:3e9 tau:1; do
    name=${p%%:*} truth=${p#*:}
    line=$(awk -F'\t' -v p="$name" '$1 == p {print $2, $3, $5}' "$TMP/fit/fit.tsv")
    check "fit.tsv: $name = ${line% *} (free ${line##* }), within 3 standard errors of $truth" \
        awk -v l="$line" -v t="$truth" 'BEGIN {split(l, a, " "); d = a[1] - t; d = d < 0 ? -d : d; exit !(a[3] == 1 && a[2] > 0 && d <= 3 * a[2])}'
done
# best.scene reruns the best model: its force at the curve's positions is
# the fit's model force there (fit-points.tsv), to the interpolation between
# the integrator's rows (0.09 nN measured; the noise is 0.66 nN)
"$ADHERE" --batch -q --no-plot -o "$TMP/rerun" "$TMP/fit/best.scene" 2>"$TMP/rerun.err"
rc=$?
# (the model starts above the curve's first point: its rows from there)
top=$(sed -n 2p "$TMP/curve.tsv" | cut -f1)
awk -v seed=1 -v sd=0 -v dx=0.05 -v from="$top" -f "$DRAND48" -f "$TMP/sample.awk" "$TMP/rerun/force.tsv" | tail -n +2 >"$TMP/rerun.tsv"
awk -F'\t' '!/^#/ && $1 != "file" {printf "%.6f\t%.6f\n", $3 * 1e9, $7 * 1e9}' "$TMP/fit/fit-points.tsv" >"$TMP/model.tsv"
dmax=$(paste "$TMP/rerun.tsv" "$TMP/model.tsv" | awk -F'\t' '$1 != $3 {bad = 1} {d = $2 - $4; d = d < 0 ? -d : d; m = d > m ? d : m}
    END {print bad ? "positions differ" : m}')
check "adhere --batch OUT/best.scene reruns the best model: its force within 0.2 nN of the fit's at every point (exit $rc, largest difference $dmax nN)" \
    sh -c "[ $rc -eq 0 ] && [ \$(wc -l <'$TMP/rerun.tsv') -eq $n ] && awk -v d='$dmax' 'BEGIN {exit !(d + 0 == d && d < 0.2)}'"
check "best.scene holds the solid, the drive and the model's tolerance (mode time, material sls, speed, time_tol 1e-5)" \
    sh -c "grep -qx 'mode = time' '$TMP/fit/best.scene' && grep -qx 'material = sls' '$TMP/fit/best.scene' && grep -q '^speed = 1e-09m/s, 1e-09m/s' '$TMP/fit/best.scene' && grep -qx 'time_tol = 1e-05' '$TMP/fit/best.scene'"

# the refusals: exit 2, the value named as typed, nothing written
refused() { # refused WHAT PATTERN ARGS...: exit 2, stderr matching PATTERN, no output directory
    what=$1 pat=$2
    shift 2
    rm -rf "$TMP/ref"
    "$ADHERE" fit -q --data="$TMP/curve.tsv" "$@" -o "$TMP/ref" >/dev/null 2>"$TMP/ref.err"
    rc=$?
    check "$what: exit 2 ($rc: $(head -c 300 "$TMP/ref.err"))" \
        sh -c "[ $rc -eq 2 ] && grep -q -- \"$pat\" '$TMP/ref.err' && [ ! -e '$TMP/ref' ]"
}
refused "--model=time without --material=sls" "--model=time fits a standard linear solid.*--material=sls" \
    --model=time -E 1GPa $G
refused "--material=sls with the static model" "or --model=time to fit the solid" $SLS $G
refused "--model=relax with --material=sls" "material = sls\|--material=sls" --model=relax $SLS $G
refused "a model that is not one" "--model: 'timed' is not a model: use static, relax or time" --model=timed $SLS $G
refused "--free names a parameter the model has not (Einf with the static model)" \
    "--free: 'Einf' is the standard linear solid's, which only --model=time fits" --free=E,Einf -E 1GPa $G
refused "--free names no parameter (as typed)" "--free: 'tauu' is not a parameter: use E0 (or E), Einf, tau" \
    --model=time --free=E0,tauu $SLS $G
refused "--free names E0 twice (as E0 and E)" "--free: E0 (E) is named twice in 'E0,A,E'" \
    --model=time --free=E0,A,E $SLS $G
refused "--eps with the physical-time model" "--model=time integrates in physical time.*--eps=1pm" \
    --model=time --eps=1pm $SLS $G
# the model integrates at 1e-5 or tighter: a looser --time-tol was dropped in silence
refused "a --time-tol looser than the model's" "--time-tol=1e-3 would be ignored; leave it out, or give one of 1e-05 or less" \
    --model=time --time-tol=1e-3 $SLS $G
refused "an iteration --dwell with the physical-time model" "--dwell=5 would be ignored" --model=time --dwell=5 $SLS $G
refused "--turn with the physical-time model" "takes its turn from the data, at the deepest.*--turn=-2nm" \
    --model=time --turn=-2nm $SLS $G
refused "Einf below E0" "below --E0=1GPa" --model=time $SLS --Einf=0.5GPa $G
refused "--model=time without the data's --speed (the default taken for it in silence)" \
    "--model=time runs its model at the speed the data were measured at.*give --speed" \
    --model=time --material=sls --E0=1.3GPa --Einf=2.5GPa --tau=0.7s $G
# a second cycle (the same curve measured again, its forces moved by 1 pN)
awk -F'\t' 'NR == 1 {print; next} {printf "%s\t%.6f\n", $1, $2 + 0.001}' "$TMP/curve.tsv" >"$TMP/again.tsv"
refused "a second cycle with the physical-time model (compared with the first's branches in silence)" \
    "again.tsv:2: --model=time runs one cycle from rest.*approach again here (segment 3); give one cycle" \
    --model=time --data="$TMP/again.tsv" $SLS $G
# a retraction first, then the approach (the curve's halves swapped): the
# data never approached before, and were told they "approach again"
awk -F'\t' 'NR == 1 {print; next} {x[NR] = $0; v[NR] = $1 + 0} END {d = 2; for (i = 3; i <= NR; i++) if (v[i] < v[d]) d = i
    for (i = d; i <= NR; i++) print x[i]; for (i = 2; i < d; i++) print x[i]}' "$TMP/curve.tsv" >"$TMP/swapped.tsv"
"$ADHERE" fit -q --model=time --data="$TMP/swapped.tsv" $SLS $G -o "$TMP/swapout" >/dev/null 2>"$TMP/swap.err"
rc=$?
check "a retraction before the approach with the physical-time model is said as such, not 'approach again' ($(cat "$TMP/swap.err"))" \
    sh -c "[ $rc -eq 2 ] && grep -q 'swapped.tsv:[0-9]*: --model=time runs one cycle from rest.*the data approach after a retraction here (segment 2); give one cycle, its approach first' '$TMP/swap.err' && [ ! -e '$TMP/swapout' ]"
refused "an empty --model names the time model among the models" "--model: '' is not a model: use static, relax or time" \
    --model= $SLS $G
refused "an empty --free names the solid's parameters among them" "--free: '' names no parameter: .*E0, Einf and tau with --model=time" \
    --model=time --free= $SLS $G
done_testing
