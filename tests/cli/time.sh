#!/bin/sh
# Physical time from the command line (mode time, issue 29): what a mode
# cannot use is refused with the reason (exit 2, nothing written); a
# viscoelastic cycle writes its tables in seconds (force.tsv with t and
# base, events.tsv, summary's hysteresis and dissipated, which close the
# energy balance), its figures and a plan that says it runs in time; a
# spring on the static curve gives snap points where dF/dh0 = k; sweeps of
# the speed and the spring.
. "$(dirname "$0")/lib.sh"

bad() { # bad "expected text" args...
    want=$1; shift
    out="$TMP/out$T"
    "$ADHERE" --batch -q -o "$out" "$@" >"$TMP/stdout" 2>"$TMP/stderr"
    rc=$?
    msg=$(cat "$TMP/stderr")
    if [ "$rc" -eq 2 ] && grep -q -- "$want" "$TMP/stderr" && [ ! -e "$out" ] && [ "$(wc -l <"$TMP/stderr")" -eq 1 ]; then
        ok "$* -> exit 2: $msg"
    else
        not_ok "$* -> exit $rc (want 2 and '$want', nothing written): $msg"
    fi
}
bad "is below --E0=3e+08 Pa: a standard linear solid is stiffest at first" --material=sls --Einf=0.1GPa
bad "tau = 0 s is not allowed" --material=sls --tau=0
bad "tau = -1e-06 s is not allowed" --material=sls --tau=-1us
bad "approach speed 0 m/s is not allowed" --material=sls --speed=0
bad "retraction speed -1e-06 m/s is not allowed" --material=sls --speed=1um/s,-1um/s
bad "spring k = 0 N/m is not allowed" --mode=static --spring=0
bad "spring k = -1 N/m is not allowed" --mode=static --spring=-1N/m
bad "'2GPa' is a pressure" --material=sls --tau=2GPa
bad "'sticky' is not a material: use elastic or sls" --material=sticky
bad "--Einf is a standard linear solid's: --material=elastic cannot use it" --Einf=3GPa
bad "--tau is a standard linear solid's" --mode=time --tau=1ms
bad "--material=sls runs in physical time: --mode=static cannot use it" --material=sls --mode=static
bad "--material=sls runs in physical time: --mode=rigid cannot use it" --mode=rigid --material=sls
bad "--speed is physical time's: --mode=relax steps the drive in eps-time" --speed=1um/s
bad "--dwell-time is physical time's" --mode=static --dwell-time=1ms
bad "--spring is not allowed with --mode=relax" --spring=1N/m
bad "--spring is not allowed with --mode=rigid" --mode=rigid --spring=1N/m
bad "--dwell=5 counts relaxation iterations: in physical time the hold at a turn is --dwell-time" --material=sls --dwell=5
printf '[scene]\nmode = relax\n[sweep]\nspeed = 1um/s, 2um/s\n' >"$TMP/sw.scene"
bad "sweep.speed varies the drive's speed in m/s: --mode=relax has no physical time" "$TMP/sw.scene"
printf '[material]\nmaterial = sls\n[sweep]\neps = 1pm, 2pm\n' >"$TMP/eps.scene"
bad "physical time has none" "$TMP/eps.scene"
printf '[material]\nmaterial = sls\n[sweep]\nE = 1GPa, 2GPa\nplot = snap\n' >"$TMP/snap.scene"
bad "sweep.plot = snap draws the snap points against the spring: sweep.spring is needed" "$TMP/snap.scene"

# the plan says what runs
"$ADHERE" --plan visco >"$TMP/plan" 2>&1
check "--plan visco: mode time" grep -q '^mode: time (physical time' "$TMP/plan"
check "--plan visco: the solid" grep -qF 'material: standard linear solid: E0 = 300 MPa (relaxed, sigma 7.503), Einf = 3 GPa (instantaneous, sigma 0.7503), tau = 1 ms' "$TMP/plan"
check "--plan visco: the drive and the time it spans" sh -c "grep -qF 'drive: the base at 1 um/s approaching, 1 um/s retracting' '$TMP/plan' && grep -q '^time: about 43.9 ms' '$TMP/plan'"
check "--plan visco stores events.tsv" grep -q '^stored: events.tsv' "$TMP/plan"
check "--plan visco: summary.tsv with the solid, the drive, hysteresis and dissipated" grep -q "^stored: summary.tsv: .*the solid and the drive, hysteresis, dissipated" "$TMP/plan"
"$ADHERE" --plan visco-speed >"$TMP/plans" 2>&1
check "--plan visco-speed: 8 runs in time, speed.png" sh -c "grep -q '^runs: 8$' '$TMP/plans' && grep -q '^mode: time' '$TMP/plans' && grep -q '^stored: speed.png' '$TMP/plans' && grep -q '^sweep: speed_out = 1 nm/s, ' '$TMP/plans'"
"$ADHERE" --plan afm >"$TMP/plana" 2>&1
check "--plan afm: one static curve serves every k, snap.png" sh -c "grep -q '^mode: static' '$TMP/plana' && grep -q '^skip: a curve per k: ' '$TMP/plana' && grep -q '^stored: snap.png' '$TMP/plana' && grep -q '^sweep: spring = 100 mN/m, ' '$TMP/plana'"
"$ADHERE" --plan fig4 >"$TMP/plan4" 2>&1
check "--plan fig4 (elastic) does not run in time" sh -c "grep -q '^mode: relax' '$TMP/plan4' && ! grep -q 'events.tsv\|^material:' '$TMP/plan4'"

# a viscoelastic cycle, coarse
d="$TMP/v"
"$ADHERE" --batch -q visco -N 150 --force -o "$d" >"$TMP/stdout" 2>"$TMP/stderr"
rc=$?
check "adhere --batch visco -N 150 --force exits 0 ($rc: $(head -c 300 "$TMP/stderr"))" [ "$rc" -eq 0 ]
for f in force.tsv summary.tsv turns.tsv events.tsv profiles.tsv force.png profile.png contact.png contact.tsv; do
    check "visco wrote $f" [ -s "$d/$f" ]
done
hdr=$(grep -v '^#' "$d/force.tsv" | head -1 | cut -f1-4)
check "force.tsv begins with t, base, h0, F ($hdr)" [ "$hdr" = "$(printf 't\tbase\th0\tF')" ]
check "the time never goes back over the rows" sh -c "grep -v '^#' '$d/force.tsv' | tail -n +2 | awk -F'\t' 'NR > 1 && \$1 < t - 1e-15 {bad = 1} {t = \$1} END {exit bad}'"
check "without a spring the base is h0 on every row" sh -c "grep -v '^#' '$d/force.tsv' | tail -n +2 | awk -F'\t' '\$2 != \$3 {bad = 1} END {exit bad}'"
sv() { awk -F'\t' -v k="$1" '$1 == k {print $2}' "$d/summary.tsv"; }
check "summary: mode time, material sls" sh -c "[ '$(sv mode)' = time ] && [ '$(sv material)' = sls ]"
for k in E0 Einf tau speed_in speed_out hysteresis dissipated jump_loss time pulloff_F pulloff_t jump_in_t jump_out_t time_steps; do
    check "summary has $k ($(sv $k))" sh -c "[ -n '$(sv $k)' ] && [ '$(sv $k)' != nan ]"
done
check "the cycle's energy closes: hysteresis = dissipated + jump losses + stored change within 1 %" awk \
    "BEGIN {h = $(sv hysteresis); s = $(sv dissipated) + $(sv jump_loss) + $(sv stored_change); exit !(h > 0 && (h - s) / h < 0.01 && (s - h) / h < 0.01)}"
check "the time spans the protocol: start to -5 nm and back at 1 um/s ($(sv time) s)" awk \
    "BEGIN {T = 2 * ($(sv start) + 5e-9) / 1e-6; exit !($(sv time) >= T * (1 - 1e-9) && $(sv time) < 1.1 * T)}"
check "events.tsv: a jump in on loading and out on unloading" sh -c "grep -c '^jump	0	' '$d/events.tsv' | grep -qx 1 && grep -q '^jump	1	' '$d/events.tsv'"
check "the jump out's time is the summary's" sh -c "grep '^jump	1	' '$d/events.tsv' | cut -f3 | grep -qxF '$(sv jump_out_t)'"
check "contact.tsv: speeds from the time (physical time's header)" grep -q '^# physical time: da_dt the central difference in t' "$d/contact.tsv"

# the static curve through a spring: the snap points
d="$TMP/s"
"$ADHERE" --batch -q --mode=static --spring=5N/m -N 150 --force -o "$d" >"$TMP/stdout" 2>"$TMP/stderr"
check "--mode=static --spring=5N/m exits 0 ($(head -c 200 "$TMP/stderr"))" [ $? -eq 0 ]
check "its summary: snap-in outside the jump-in fold, the base further out than the sphere" awk -F'\t' \
    '$1 == "snap_in_h0" {h = $2} $1 == "snap_in_base" {b = $2} $1 == "jump_in_h0" {j = $2} END {exit !(h > j && b > h)}' "$d/summary.tsv"
check "and the snap-out's base lies F/k out, past the pull-off's h0" awk -F'\t' \
    '$1 == "snap_out_base" {b = $2} $1 == "pulloff_h0" {p = $2} END {exit !(b > p)}' "$d/summary.tsv"

# a spring swept over one static curve: the softer, the further out
d="$TMP/afm"
"$ADHERE" --batch -q afm -N 150 --force -o "$d" >"$TMP/stdout" 2>"$TMP/stderr"
check "afm -N 150 --force exits 0 ($(head -c 200 "$TMP/stderr"))" [ $? -eq 0 ]
check "afm wrote snap.png and sweep.tsv" [ -s "$d/snap.png" -a -s "$d/sweep.tsv" ]
check "snap-in's base moves out monotonically as k softens from 40 to 0.1 N/m" sh -c \
    "grep -v '^#' '$d/sweep.tsv' | tail -n +2 | awk -F'\t' 'NR > 1 && \$6 >= b {bad = 1} {b = \$6} END {exit bad || NR != 9}'"
check "every run of the afm sweep shares the one curve" sh -c "[ \$(cat '$d'/run-*/force.tsv | grep -v '^#' | sort -u | wc -l) -eq \$(grep -v '^#' '$d/run-1/force.tsv' | wc -l) ]"

# the speed sweep, two speeds: the faster retraction pulls off harder
printf '[material]\nmaterial = sls\n[protocol]\nturns = -5nm\nspeed = 10nm/s\n[sweep]\nspeed_out = 10nm/s, 1mm/s\nplot = speed\n[output]\nplots = none\n' >"$TMP/speed.scene"
d="$TMP/sp"
"$ADHERE" --batch -q "$TMP/speed.scene" -N 150 --force -o "$d" >"$TMP/stdout" 2>"$TMP/stderr"
check "a speed sweep exits 0 ($(head -c 200 "$TMP/stderr"))" [ $? -eq 0 ]
check "it wrote speed.png" [ -s "$d/speed.png" ]
check "the faster retraction's pull-off is larger and below Einf/E0 times the slow one" sh -c \
    "grep -v '^#' '$d/sweep.tsv' | tail -n +2 | awk -F'\t' '{p[NR] = -\$13} END {exit !(p[2] > 1.5 * p[1] && p[2] < 10 * p[1])}'"
check "each row's status is its run's summary.tsv's ($(grep -v '^#' "$d/sweep.tsv" | tail -n +2 | cut -f23 | tr '\n' ' '))" sh -c \
    "for k in 1 2; do w=\$(awk -F'\t' '\$1 == \"status\" {print \$2}' '$d'/run-\$k/summary.tsv); \
     grep -v '^#' '$d/sweep.tsv' | awk -F'\t' -v k=\$k -v w=\"\$w\" '\$1 == k {f = 1; if (\$NF != w || w == \"\") exit 1} END {exit !f}' || exit 1; done"
done_testing
