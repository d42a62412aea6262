/* An elastic sphere in physical time (adh_rule_path, adhere/rule_path.h):
 * no integration, the static curve's path. Its numbers are the static
 * curve's on the same grid (the same solver and settings: the jump-in,
 * the jump-out and the pull-off to the digit, the hysteresis its loop),
 * and within test_visco_limits' tolerance (0.1 %) of the integrator's
 * standard linear solid at Einf = E0, which is the same elastic sphere
 * integrated in time. Its times are the base's travel over the branch's
 * speed plus the dwell, a closed relation every row must meet; through a
 * spring its jumps sit where the static curve under that spring has its
 * snap points (adh_visco_spring_folds, adh_visco_spring_snap_out); a soft
 * spring's snap-out flies |F|/k and releases F^2/2k. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/cycle.h"
#include "adhere/models.h"
#include "adhere/rule_path.h"
#include "adhere/rule_time.h"
#include "tap.h"
#include "visco_fixture.h"

typedef struct prun {
    int rc;
    adh_run run;
    adh_visco_result r;
    adh_visco_event ev[64];
    size_t nev;
} prun;

/* The elastic path of protocol ps under drive d through the drive and the
 * runner, as every driver steps it. */
static prun path_run(const fixture *f, const adh_visco_drive *d, const adh_protocol_settings *ps)
{
    prun p;
    adh_run_init(&p.run);
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(f->m.E);
    vs.drive = *d;
    adh_drive *dr = adh_drive_alloc(&adh_rule_path, f->g, f->k);
    p.rc = adh_drive_set(dr, &f->m, &vs, ps, &p.run);
    if (p.rc == ADH_SUCCESS)
        p.rc = adh_runner_drive(dr, NULL, NULL);
    adh_rule_time_summary(dr, &p.r);
    const adh_visco_event *ev;
    p.nev = adh_rule_time_events(dr, &ev);
    if (p.nev > 64)
        p.nev = 64;
    memcpy(p.ev, ev, p.nev * sizeof *ev);
    adh_rule_time_take(dr, &p.run);
    adh_drive_free(dr);
    return p;
}

/* The static curve of the same protocol as the static mode runs it
 * (under spring k: from outside its snap-in, close points). */
static int static_run(const fixture *f, double k, const adh_protocol_settings *ps, adh_run *run,
                      adh_static_result *res)
{
    adh_static_settings s = adh_rule_path_static_settings(k, NULL);
    adh_protocol_settings p = *ps;
    if (isfinite(k))
        p.start = adh_visco_auto_start(&f->m, k, ps->step);
    adh_run_init(run);
    return adh_runner_static(f->g, f->k, &f->m, &s, &p, NULL, NULL, run, res);
}

static adh_protocol_settings protocol(void)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.nturns = 1;
    ps.turns[0] = FIX_TURN;
    ps.unload = 1;
    return ps;
}

static size_t count(const prun *p, int kind)
{
    size_t n = 0;
    for (size_t i = 0; i < p->nev; i++)
        n += p->ev[i].kind == kind;
    return n;
}

static void against_static(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    prun p = path_run(f, &d, &ps);
    adh_run st;
    adh_static_result sr;
    int src = static_run(f, INFINITY, &ps, &st, &sr);
    ok(p.rc == ADH_SUCCESS && src == ADH_SUCCESS && count(&p, ADH_VISCO_JUMP) == 2 && p.r.steps == 0,
       "elastic in time: the path runs, two jumps (%zu rows from %zu points of the curve)", p.run.nrows, st.nrows);
    ok(p.r.pulloff_F == sr.pulloff_F && p.r.pulloff_h0 == sr.pulloff_h0,
       "its pull-off is the static curve's on the same grid, to the digit (%.10g N)", p.r.pulloff_F);
    ok(p.r.jump_in_h0 == sr.jump_in_h0 && p.r.jump_out_h0 == sr.jump_out_h0,
       "its jump-in and jump-out are the static curve's folds, to the digit (%.10g, %.10g m)", p.r.jump_in_h0,
       p.r.jump_out_h0);
    double loop = adh_cycle_static_hysteresis(&st, ADH_CYCLE_HYSTERESIS_STEP * f->m.z0);
    ok(p.r.hysteresis == loop, "its hysteresis is the static curve's loop (%.6g J)", p.r.hysteresis);
    ok_rel(p.r.cycle.jumps, loop, 1e-2, "the jumps' losses (events.tsv, by chords along the curve) add up to it");
    ok(p.r.cycle.dissipated == 0 && p.r.cycle.stored == p.r.cycle.stored0,
       "nothing dissipated on the way, nothing left stored back at the start");

    /* the same elastic sphere integrated in time: the standard linear
     * solid at Einf = E0 (test_visco_limits' tolerance, 0.1 %) */
    vrun v = fix_visco(f, 1.0, &d, 1e-4);
    ok(v.rc == ADH_SUCCESS, "Einf = E0 through the integrator at 1 um/s runs (%zu steps)", v.r.steps);
    ok_rel(p.r.pulloff_F, v.r.pulloff_F, 1e-3, "the path's pull-off is the integrator's");
    ok_rel(p.r.jump_in_h0, v.r.jump_in_h0, 1e-3, "the path's jump-in is the integrator's");
    ok_rel(p.r.jump_out_h0, v.r.jump_out_h0, 1e-3, "the path's jump-out is the integrator's");
    ok_rel(p.r.jump_in_t, v.r.jump_in_t, 1e-3, "and so are their times: the jump-in's");
    ok_rel(p.r.jump_out_t, v.r.jump_out_t, 1e-3, "the jump-out's");
    ok_rel(p.r.time, v.r.time, 1e-9, "the cycle's time");
    ok_rel(p.r.hysteresis, v.r.hysteresis, 1e-2, "the hysteresis within 1 % (test_visco_energy's)");
    vrun_free(&v);
    adh_run_free(&st);
    adh_run_free(&p.run);
}

/* t on every row: loading (b_start - base) / v_in; unloading from turn k
 * its time there plus the dwell plus (base - base at the turn) / v_out. */
static void times(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    ps.nturns = 2;
    ps.turns[0] = -1e-9;
    ps.turns[1] = 1e-9;
    adh_visco_drive d = fix_drive(2e-6, 5e-7);
    d.dwell = 3e-3;
    prun p = path_run(f, &d, &ps);
    const adh_obs *r = p.run.rows;
    double b0 = r[0].base, worst = 0;
    double turn_t[3] = { 0 }, turn_b[3] = { 0 };
    int monotone = 1, dwelt = 0;
    for (size_t i = 0; i < p.run.nrows; i++) {
        double want;
        if (r[i].path == 0) {
            want = (b0 - r[i].base) / d.speed_in;
        } else {
            int k = r[i].path;
            if (i == 0 || r[i - 1].path != k) {   /* the branch's first row: the turn, on loading */
                turn_b[k] = r[i].base;
                turn_t[k] = (b0 - r[i].base) / d.speed_in;
                want = turn_t[k];
            } else {
                want = turn_t[k] + d.dwell + (r[i].base - turn_b[k]) / d.speed_out;
                dwelt |= r[i].t == turn_t[k] + d.dwell && r[i].base == turn_b[k];
            }
        }
        worst = fmax(worst, fabs(r[i].t - want) / (fabs(want) + 1e-12));
        if (i && r[i].path == r[i - 1].path && r[i].t < r[i - 1].t)
            monotone = 0;
    }
    ok(p.rc == ADH_SUCCESS && p.run.nturns == 2 && count(&p, ADH_VISCO_UNLOAD) == 2,
       "two turns, two speeds, a 3 ms dwell: both unloaded, each after its dwell");
    ok(worst < 1e-12 && monotone && dwelt,
       "every row's t is the base's travel over the branch's speed, plus the dwell (worst %.2g relative, %zu rows)",
       worst, p.run.nrows);
    ok_rel(p.r.time, turn_t[2] + d.dwell + (r[p.run.nrows - 1].base - turn_b[2]) / d.speed_out, 1e-12,
           "the time is the protocol's: the deepest turn's, its dwell and the retraction back to the start");
    /* a row between the curve's points (a turn, a fold, a landing) has
     * eq 22 at its own h0, not a mixture of its neighbours' */
    double rigid = 0;
    for (size_t i = 0; i < p.run.nrows; i++) {
        double want = adh_rigid_force(&f->m, r[i].h0);
        rigid = fmax(rigid, isnan(want) ? (isnan(r[i].F_rigid) ? 0 : INFINITY)
                                        : fabs(r[i].F_rigid - want) / fabs(want));
    }
    ok(rigid <= 1e-12, "every row's F_rigid is eq 22 at its h0 (worst %.2g relative)", rigid);
    adh_run_free(&p.run);
}

/* A turn short of contact before the deepest: the surfaces never touched
 * on its branch, so it has no jump-out (as the integrator and the static
 * mode say), and its force is the static curve's at that h0 (solved to
 * it: its last point), not a chord across the far field's long steps. */
static void short_turn(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    ps.nturns = 2;
    ps.turns[0] = 5e-9;
    ps.turns[1] = FIX_TURN;
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    prun p = path_run(f, &d, &ps);
    adh_protocol_settings to5 = protocol();
    to5.turns[0] = 5e-9;
    adh_run st;
    adh_static_result sr;
    int src = static_run(f, INFINITY, &to5, &st, &sr);
    const adh_turn_result *tr = p.run.nturns == 2 ? &p.run.turns[0] : NULL;
    ok(p.rc == ADH_SUCCESS && tr && tr->h0 == 5e-9 && tr->a_turn == 0 && isnan(tr->jump_out_h0),
       "a turn at 5 nm, short of contact, before the deepest: no jump-out on its branch (%g)",
       tr ? tr->jump_out_h0 : NAN);
    ok(src == ADH_SUCCESS && st.nrows && tr && fabs(tr->max_load / st.rows[st.nrows - 1].F - 1) < 1e-3,
       "its force is the static curve's at 5 nm (%.6g against %.6g nN)", tr ? tr->max_load * 1e9 : NAN,
       st.nrows ? st.rows[st.nrows - 1].F * 1e9 : NAN);
    /* turns.tsv's hysteresis: the turn short of contact jumped nowhere,
     * so its cycle has none; the deepest's is the summary's */
    ok(tr && tr->hysteresis == 0 && p.run.turns[1].hysteresis == p.r.hysteresis && p.r.hysteresis > 0,
       "the turn short of contact has no hysteresis (%g J), the deepest the summary's (%g, %g J)",
       tr ? tr->hysteresis : NAN, p.run.nturns == 2 ? p.run.turns[1].hysteresis : NAN, p.r.hysteresis);
    /* the turn alone: the lowest force on its branch is the turn's, at
     * its time (the loading's travel over the speed), as the integrator's */
    ps.nturns = 1;
    prun one = path_run(f, &d, &ps);
    const adh_obs *r0 = one.run.nrows ? &one.run.rows[0] : NULL;
    double t5 = r0 ? (r0->base - 5e-9) / d.speed_in : NAN;
    ok(one.rc == ADH_SUCCESS && one.run.nturns == 1 && one.r.pulloff_F == one.run.turns[0].max_load &&
       one.r.pulloff_h0 == 5e-9 && fabs(one.r.pulloff_t - t5) <= 1e-12 * t5,
       "the turn at 5 nm alone: the summary's lowest force is the turn's, at its time %.6g s (%.6g)", t5,
       one.r.pulloff_t);
    adh_run_free(&one.run);
    adh_run_free(&st);
    adh_run_free(&p.run);
}

/* Through a spring: the jumps where the static curve under it puts its
 * snap points. */
static void spring(const fixture *f, double k)
{
    adh_protocol_settings ps = protocol();
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = k;
    prun p = path_run(f, &d, &ps);
    adh_run st;
    adh_static_result sr;
    static_run(f, k, &ps, &st, &sr);
    double at[4], base[4], out_b, out_h0 = adh_visco_spring_snap_out(&st, k, &out_b);
    size_t nf = adh_visco_spring_folds(&st, k, at, base, 4);
    const adh_visco_event *in = NULL, *out = NULL;
    for (size_t i = 0; i < p.nev; i++)
        if (p.ev[i].kind == ADH_VISCO_JUMP)
            *(p.ev[i].path == 0 ? &in : &out) = &p.ev[i];
    ok(p.rc == ADH_SUCCESS && in && out && nf >= 1, "%g N/m: the path runs, a jump in and a jump out", k);
    ok(in && in->h0 == at[0] && in->base == base[0] && in->F == k * (at[0] - base[0]),
       "%g N/m: the snap-in at the static curve's first fold of the base (%.6g nm, base %.6g nm)", k,
       in ? in->h0 * 1e9 : NAN, in ? in->base * 1e9 : NAN);
    ok(out && out->h0 == out_h0 && out->base == out_b,
       "%g N/m: the snap-out at the static curve's (%.6g nm, base %.6g nm)", k, out ? out->h0 * 1e9 : NAN,
       out ? out->base * 1e9 : NAN);
    ok(p.r.pulloff_F <= (out ? out->F : 0) && fabs(p.r.pulloff_F / sr.pulloff_F - 1) < 1e-3,
       "%g N/m: the pull-off before it, the static curve's force minimum (%.6g N)", k, p.r.pulloff_F);
    /* events.tsv in the order they happen: the pull-off (at the snap-out's
     * fold itself under a soft spring, the same instant) before the
     * snap-out and the branch's end */
    size_t i_pull = p.nev, i_out = p.nev, i_end = p.nev;
    for (size_t i = 0; i < p.nev; i++) {
        if (p.ev[i].path != 1)
            continue;
        if (p.ev[i].kind == ADH_VISCO_PULLOFF)
            i_pull = i;
        else if (p.ev[i].kind == ADH_VISCO_JUMP)
            i_out = i;
        else if (p.ev[i].kind == ADH_VISCO_END)
            i_end = i;
    }
    ok(i_pull < i_out && i_out < i_end && i_end < p.nev, "%g N/m: the events in order: pull-off, snap-out, end", k);
    if (k < 1e-2 && out) {
        /* a soft spring: the sphere flies |F|/k, out of the surface force's
         * reach, and the jump releases the spring's energy */
        ok_rel(out->h0_after - out->h0, -out->F / k, 1e-3, "a soft spring: the snap-out flies |F|/k");
        ok_rel(out->loss, out->F * out->F / (2 * k), 1e-3, "a soft spring: it releases F^2/2k");
    }
    adh_run_free(&st);
    adh_run_free(&p.run);
}

/* A soft spring's snap-in thrown past the deepest turn (1 N/m, turn at
 * -2 nm): the sphere lands where the spring's line meets the curve, deeper
 * than the turn, and turns there; on the curve solved deeper by the static
 * mode itself, and k (h0 - base) at its force. (The curve had ended at the
 * turn and the landing was put at its end, off the spring's line, the base
 * 225 nm away in the same instant.) */
static void landing_past_turn(const fixture *f, double k, double h_turn)
{
    adh_protocol_settings ps = protocol();
    ps.turns[0] = h_turn;
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = k;
    prun p = path_run(f, &d, &ps);
    const adh_visco_event *in = NULL, *turn = NULL;
    for (size_t i = 0; i < p.nev; i++)
        if (p.ev[i].kind == ADH_VISCO_JUMP && p.ev[i].path == 0)
            in = &p.ev[i];
        else if (p.ev[i].kind == ADH_VISCO_TURN)
            turn = &p.ev[i];
    ok(p.rc == ADH_SUCCESS && in && turn && in->h0_after < ps.turns[0] && turn->h0 == in->h0_after,
       "%g N/m, turn at %g nm: the snap-in lands past the turn (%.6g nm) and turns there", k, h_turn * 1e9,
       in ? in->h0_after * 1e9 : NAN);
    ok(in && fabs(in->F_after - d.spring * (in->h0_after - in->base)) <= 1e-9 * fabs(in->F_after),
       "its landing is on the spring's line at the jump's base: F = k (h0 - base)");
    /* the static curve to 1 nm past the landing: its force there */
    adh_protocol_settings deep = protocol();
    deep.turns[0] = (in ? in->h0_after : -6e-9) - 1e-9;
    adh_run st;
    adh_static_result sr;
    static_run(f, d.spring, &deep, &st, &sr);
    double Fc = NAN;
    for (size_t i = 1; in && i < st.nrows; i++) {
        const adh_obs *a = &st.rows[i - 1], *b = &st.rows[i];
        if (a->a > 0 && b->a > 0 && (a->h0 - in->h0_after) * (b->h0 - in->h0_after) <= 0) {
            Fc = a->F + (b->F - a->F) * (in->h0_after - a->h0) / (b->h0 - a->h0);
            break;
        }
    }
    ok(in && fabs(Fc - in->F_after) <= 1e-3 * fabs(in->F_after),
       "and on the static curve solved past it (%.6g against %.6g nN)", Fc * 1e9, in ? in->F_after * 1e9 : NAN);
    adh_run_free(&st);
    adh_run_free(&p.run);
}

/* In batches of one point (the TUI, reading keys between): the curve is
 * solved a point a call before the first row (it was solved whole in the
 * first call, deaf to keys), and the rows are the runner's, to the digit. */
static void batches(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    prun whole = path_run(f, &d, &ps);
    adh_run run;
    adh_run_init(&run);
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(f->m.E);
    vs.drive = d;
    adh_drive *dr = adh_drive_alloc(&adh_rule_path, f->g, f->k);
    adh_drive_set(dr, &f->m, &vs, &ps, &run);
    size_t before = 0, calls = 0;
    int row = 0, rc;
    while ((rc = adh_drive_iterate(dr, 1, &row)) == ADH_CONTINUE && calls++ < 1000000)
        before += !row && run.nrows == 0;
    int same = rc == ADH_SUCCESS && run.nrows == whole.run.nrows;
    for (size_t i = 0; same && i < run.nrows; i++)
        same = run.rows[i].t == whole.run.rows[i].t && run.rows[i].h0 == whole.run.rows[i].h0 &&
               run.rows[i].F == whole.run.rows[i].F;
    ok(before > 10 && same, "a point of the curve a call: %zu calls before the first row, then the runner's %zu rows "
       "to the digit", before, whole.run.nrows);
    adh_drive_free(dr);
    adh_run_free(&run);
    adh_run_free(&whole.run);
}

/* Stepped by hand (the TUI's f), the summary says only what the rows so
 * far have seen. */
static void so_far(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    adh_run run;
    adh_run_init(&run);
    adh_drive *dr = adh_drive_alloc(&adh_rule_path, f->g, f->k);
    adh_drive_set(dr, &f->m, NULL, &ps, &run);
    adh_visco_result r;
    int early = 1;
    while (adh_drive_step(dr) == ADH_CONTINUE && !(adh_drive_row(dr)->a > 0)) {
        adh_rule_time_summary(dr, &r);
        early &= isnan(r.jump_in_h0) && isnan(r.pulloff_F) && isnan(r.hysteresis) && r.jumps == 0 &&
                 r.time == adh_drive_row(dr)->t;
    }
    adh_rule_time_summary(dr, &r);
    ok(early && !isnan(r.jump_in_h0) && r.jumps == 1 && isnan(r.hysteresis),
       "stepped by hand: no jump, pull-off or hysteresis before the path reaches them; the jump-in with its "
       "landing");
    adh_drive_free(dr);
    adh_run_free(&run);
}

/* The same drive set again (the TUI's edit, its restart): until the new
 * walk, the summary knows nothing yet, as a fresh drive's says; it was the
 * last walk's (its start, 10.5 nm, beside a new start of 12 nm). */
static void set_again(const fixture *f)
{
    adh_protocol_settings ps = protocol();
    adh_run run, fresh_run;
    adh_run_init(&run);
    adh_run_init(&fresh_run);
    adh_drive *dr = adh_drive_alloc(&adh_rule_path, f->g, f->k), *fresh = adh_drive_alloc(&adh_rule_path, f->g, f->k);
    adh_drive_set(dr, &f->m, NULL, &ps, &run);
    int rc = adh_runner_drive(dr, NULL, NULL);
    adh_visco_result first, again, new;
    adh_rule_time_summary(dr, &first);
    ps.start = 12e-9;
    adh_run_free(&run);
    adh_run_init(&run);
    adh_drive_set(dr, &f->m, NULL, &ps, &run);
    adh_drive_set(fresh, &f->m, NULL, &ps, &fresh_run);
    adh_rule_time_summary(dr, &again);
    adh_rule_time_summary(fresh, &new);
    const adh_visco_event *ev;
    ok(rc == ADH_SUCCESS && first.jumps == 2 && !isnan(first.start_h0) && isnan(again.start_h0) &&
       isnan(again.start_base) && isnan(again.jump_in_h0) && isnan(again.pulloff_F) && isnan(again.hysteresis) &&
       again.jumps == 0 && again.lattice_jumps == 0 && again.time == 0 && again.cycle.work == 0 &&
       adh_rule_time_events(dr, &ev) == 0 && isnan(new.start_h0) && new.jumps == 0 && new.time == 0,
       "set again, before the new walk: the summary knows nothing yet, as a fresh drive's (start %g, was %g m)",
       again.start_h0, first.start_h0);
    adh_drive_free(dr);
    adh_drive_free(fresh);
    adh_run_free(&run);
    adh_run_free(&fresh_run);
}

/* A stiff sphere (1 TPa) started at 0.1 nm, where its surfaces already
 * touch (pressing: F > 0). Its unloading goes on past the start until the
 * surfaces part (the protocol's one rule, as the drive's and the static
 * curve's), so its pull-off and jump-out are those of the same run from
 * the automatic start, an independent run whose loading came from out of
 * contact; and its cycle closes (complete). It ended at the start in
 * contact, `not separated`, with the start's +8.96 uN as its pull-off.
 * Its hysteresis is the loop over the range of h0 both its loading and
 * its unloading cover (below the start): under displacement control the
 * static curve's loop from that start (adh_cycle_static_hysteresis). Under
 * displacement control and through 100 N/m. */
static void start_in_contact(const fixture *f, double k)
{
    fixture stiff = *f;
    stiff.m.E = 1e12;
    adh_protocol_settings ps = protocol();
    ps.start = 0.2 * stiff.m.z0;
    ps.turns[0] = isfinite(k) ? 0 : -1e-9;
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = k;
    prun p = path_run(&stiff, &d, &ps);
    adh_protocol_settings pa = ps;
    pa.start = NAN;
    prun a = path_run(&stiff, &d, &pa);
    size_t same = 0, jumps = 0;
    const adh_obs *r = p.run.rows, *last = p.run.nrows ? &r[p.run.nrows - 1] : NULL;
    for (size_t i = 1; i < p.run.nrows; i++)
        same += r[i].t == r[i - 1].t && r[i].h0 == r[i - 1].h0 && r[i].F == r[i - 1].F && r[i].base == r[i - 1].base &&
                r[i].path == r[i - 1].path;
    for (size_t i = 0; i < p.nev; i++)
        jumps += p.ev[i].kind == ADH_VISCO_JUMP && p.ev[i].path == 0;
    ok(p.rc == ADH_SUCCESS && a.rc == ADH_SUCCESS && p.run.nrows > 2 && r[0].h0 == ps.start && r[0].a > 0 &&
       r[0].t == 0 && jumps == 0 && same == 0 && last->path == 1 && !(last->a > 0) && last->h0 > ps.start,
       "k = %g N/m, a 1 TPa sphere from 0.1 nm (in contact, a = %.3g nm, F = %.3g N): its first row the start, "
       "no jump in; unloading goes on past the start until the surfaces part (its last row at %.4g nm, a = %g), no row "
       "repeated (%zu of %zu)", k, r[0].a * 1e9, r[0].F, last ? last->h0 * 1e9 : NAN, last ? last->a : NAN, same,
       p.run.nrows);
    ok(p.r.cycle.work - p.r.cycle.jumps - p.r.cycle.stored == 0 ||
       fabs(p.r.cycle.work - p.r.cycle.jumps - p.r.cycle.stored) < 1e-6 * fabs(p.r.cycle.work),
       "k = %g N/m: the base's work (%.6g J) is the jumps' losses (%.6g) and the stored change (%.6g)", k,
       p.r.cycle.work, p.r.cycle.jumps, p.r.cycle.stored);
    ok(fabs(p.r.pulloff_F - a.r.pulloff_F) < 1e-3 * fabs(a.r.pulloff_F),
       "k = %g N/m: its pull-off (%.6g N) is the run's from the automatic start (%.6g N)", k, p.r.pulloff_F,
       a.r.pulloff_F);
    ok(fabs(p.r.pulloff_h0 - a.r.pulloff_h0) < 1e-3 * stiff.m.z0 &&
       fabs(p.r.jump_out_h0 - a.r.jump_out_h0) < 1e-3 * stiff.m.z0,
       "k = %g N/m: ... at the same h0 (%.6g, %.6g m), and so is its jump-out (%.6g, %.6g m)", k, p.r.pulloff_h0,
       a.r.pulloff_h0, p.r.jump_out_h0, a.r.jump_out_h0);
    if (!isfinite(k)) {
        adh_run st;
        adh_static_result sr;
        int src = static_run(&stiff, k, &ps, &st, &sr);
        double loop = src == ADH_SUCCESS ? adh_cycle_static_hysteresis(&st, ADH_CYCLE_HYSTERESIS_STEP * stiff.m.z0)
                                         : NAN;
        ok(p.r.hysteresis == loop, "k = inf: its hysteresis is the static curve's loop from that start (%.6g J, %.6g)",
           p.r.hysteresis, loop);
        adh_run_free(&st);
    }
    /* in contact from its first row, it saw no jump in (relaxation and
     * the static curve report none from that start either) */
    ok(isnan(p.r.jump_in_h0) && isnan(p.r.jump_in_t),
       "k = %g N/m, a 1 TPa sphere from 0.1 nm: no jump in claimed (jump_in_h0 %g, t %g)", k, p.r.jump_in_h0,
       p.r.jump_in_t);
    adh_run_free(&p.run);
    adh_run_free(&a.run);
}

/* The walk over a curve that begins in contact with nothing of the curve
 * beyond its start (adh_path_curve.start 0: what the rule hands it where
 * the curve from the automatic start could not be followed): unloading
 * comes back to the start still in contact and can go no further. The
 * branch ends there, not separated, with no pull-off: the lowest force
 * seen (the start's own, +8.96 uN, pressing) is none. */
static void stranded(const fixture *f)
{
    fixture stiff = *f;
    stiff.m.E = 1e12;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_start = 0.2 * stiff.m.z0;
    ss.h0_end = -1e-9;
    adh_run curve, run;
    adh_run_init(&curve);
    adh_run_init(&run);
    adh_static_result sr;
    int src = adh_runner_static_curve(stiff.g, stiff.k, &stiff.m, &ss, NULL, NULL, &curve, &sr);
    adh_path_curve c = { .rows = curve.rows, .n = curve.nrows, .g = stiff.g, .res = &sr, .complete = 1 };
    adh_protocol_settings ps = protocol();
    ps.start = ss.h0_start;
    ps.turns[0] = ss.h0_end;
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    adh_path *p = adh_path_alloc();
    int rc = p ? adh_path_build(p, &c, &stiff.m, &d, &ps, &run) : ADH_ENOMEM;
    adh_visco_result r;
    if (p)
        adh_path_summary(p, adh_path_rows(p), &r);
    const adh_obs *last = run.nrows ? &run.rows[run.nrows - 1] : NULL;
    ok(src == ADH_SUCCESS && rc == ADH_SUCCESS && curve.rows[0].a > 0 && last && last->path == 1 && last->a > 0 &&
       last->h0 == curve.rows[0].h0 && isnan(r.pulloff_F) && isnan(r.pulloff_h0) && isnan(r.jump_out_h0) &&
       run.nturns == 1 && isnan(run.turns[0].pulloff_F),
       "a curve in contact from its first row, nothing beyond it: the unloading ends at the start in contact "
       "(a = %.3g nm), with no pull-off (%g; the start's force %.3g N is none) and no jump out", last ? last->a * 1e9 : NAN,
       p ? r.pulloff_F : NAN, curve.nrows ? curve.rows[0].F : NAN);
    adh_path_free(p);
    adh_run_free(&curve);
    adh_run_free(&run);
}

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    against_static(&f);
    times(&f);
    short_turn(&f);
    spring(&f, 10);
    /* Under ASan, the soft spring's snap points and the 1 N/m landing
     * (1.5 CPU s each) run no line or branch of the library that the
     * cases kept do not (gcov over each case alone): the soft spring's
     * own checks of |F|/k and F^2/2k stay in the plain build. */
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("the 1e-3 N/m spring's snap points and the 1 N/m landing past the turn "
                                 "(the 10 N/m snap points and the 1e-3 N/m landing)");
    } else {
        spring(&f, 1e-3);
        landing_past_turn(&f, 1.0, -2e-9);
    }
    /* a turn short of contact (the curve's end out of it: its slope says
     * nothing of the contact's) under a soft spring that throws the
     * sphere 2 nm into it */
    landing_past_turn(&f, 1e-3, 5e-9);
    so_far(&f);
    batches(&f);
    set_again(&f);
    start_in_contact(&f, INFINITY);
    start_in_contact(&f, 100);
    stranded(&f);
    fix_close(&f);
    return tap_done();
}
