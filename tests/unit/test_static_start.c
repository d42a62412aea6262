/* The static curve from a start where the equilibrium is already a
 * contact: a stiff sphere pressing (sigma 0.23, a curve without folds) and
 * a softer one past its snap-in (sigma 0.5, the inner branch). Newton from
 * the undeformed surfaces does not reach these states; the start is the
 * curve's own state there all the same: it solves u = -(2/E) W p (checked
 * here by the kernel's own product), it is stable and goes in, and its
 * force is the curve's through that h0 traced from far out (the last of
 * its crossings going in: past the snap-in, the inner branch). Its
 * unloading goes on past the start until the surfaces part: the curve's
 * pull-off and jump-out are those of the curve from far out (a 1 TPa
 * sphere from 0.1 nm reported +9 uN, its start's force, as a pull-off). */
#include <math.h>
#include <stdlib.h>

#include "adhere/cycle.h"
#include "adhere/kernel.h"
#include "adhere/law.h"
#include "adhere/observe.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/runner.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "tap.h"

/* max_n |u_n + (2/E) (W p)_n| over z0 */
static double residual(const adh_kernel *k, const adh_material *m, const adh_state *st, size_t n)
{
    double *out = malloc(n * sizeof *out), *scratch = malloc(n * sizeof *scratch), r = 0;
    adh_kernel_apply(k, st->p, out, scratch);
    for (size_t i = 0; i < n; i++)
        r = fmax(r, fabs(st->u[i] + 2.0 / m->E * out[i]));
    free(out);
    free(scratch);
    return r / m->z0;
}

/* The force of the curve traced from far out at h0, on its last crossing
 * of h0 going in (linear between the rows around it); NAN: none. */
static double curve_force_at(const adh_run *run, double h0)
{
    double F = NAN;
    for (size_t i = 1; i < run->nrows; i++) {
        const adh_obs *a = &run->rows[i - 1], *b = &run->rows[i];
        if (a->h0 >= h0 && b->h0 <= h0 && a->h0 > b->h0)
            F = a->F + (b->F - a->F) * (h0 - a->h0) / (b->h0 - a->h0);
    }
    return F;
}

/* folded: the curve from far out has a snap-in, and the start lies past it
 * (its inner branch); else it has no fold at all */
static void one(double E, double start, size_t n, double dr, int folded, const char *what)
{
    adh_material m = { .E = E, .A = 1e-19, .z0 = 0.5e-9, .R = 10e-6 };
    adh_grid *g = adh_grid_alloc(n, dr);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_static *w = adh_static_alloc(g, k);
    adh_static_settings s = adh_static_settings_default();
    s.h0_start = start;
    s.h0_end = -1e-9;
    int rc = adh_static_set(w, &m, &s);
    ok(rc == ADH_SUCCESS, "%s: the static curve starts at h0 = %g nm (%s)", what, start * 1e9,
       adh_static_why(w, NULL));
    if (rc == ADH_SUCCESS) {
        adh_obs o;
        adh_observe(g, &m, adh_static_state(w), &o);
        adh_static_point pt = adh_static_current(w);
        double r = residual(k, &m, adh_static_state(w), n);
        ok(r < 1e-6, "%s: the start solves the equations (residual %.2g z0)", what, r);
        ok(o.hc < ADH_CONTACT_FACTOR * m.z0 && pt.stable && pt.direction == +1,
           "%s: a stable contact going in (central gap %.3g z0)", what, o.hc / m.z0);
    }
    if (rc == ADH_SUCCESS) {
        adh_obs o;
        adh_observe(g, &m, adh_static_state(w), &o);
        adh_run run;
        adh_run_init(&run);
        adh_static_settings far = adh_static_settings_default();
        far.h0_end = s.h0_end;
        adh_static_result res;
        int frc = adh_runner_static_curve(g, k, &m, &far, NULL, NULL, &run, &res);
        double Fc = curve_force_at(&run, start);
        ok(frc == ADH_SUCCESS && fabs(o.F / Fc - 1) < 0.005,
           "%s: its force %.5g N is the curve's from far out there, %.5g N (%.2g %%)", what, o.F, Fc,
           100 * fabs(o.F / Fc - 1));
        /* the unloading goes on past the start until the surfaces part
         * (the protocol's rule): the pull-off and jump-out are the curve's
         * from far out, not the lowest force from the start inward (that
         * of the start itself where the force only rises inward) */
        int irc;
        while ((irc = adh_static_iterate(w)) == ADH_CONTINUE)
            ;
        adh_static_result mine;
        adh_static_summary(w, &mine);
        ok(irc == ADH_SUCCESS && res.pulloff_F < 0 && fabs(mine.pulloff_F / res.pulloff_F - 1) < 1e-3 &&
           fabs(mine.pulloff_h0 - res.pulloff_h0) < 1e-3 * m.z0 && mine.pulloff_h0 > start,
           "%s: its pull-off %.6g N at %.4g nm, past the start, is the curve's from far out, %.6g N at %.4g nm",
           what, mine.pulloff_F, mine.pulloff_h0 * 1e9, res.pulloff_F, res.pulloff_h0 * 1e9);
        ok(isnan(res.jump_out_h0) ? isnan(mine.jump_out_h0)
                                  : fabs(mine.jump_out_h0 - res.jump_out_h0) < 1e-3 * m.z0 &&
                                    fabs(mine.pulloff_F_disp / res.pulloff_F_disp - 1) < 1e-3,
           "%s: and its jump-out %.4g nm (F %.4g N) the curve's, %.4g nm (F %.4g N)", what,
           mine.jump_out_h0 * 1e9, mine.pulloff_F_disp, res.jump_out_h0 * 1e9, res.pulloff_F_disp);
        /* its hysteresis: the loop over the positions both its loading and
         * its unloading cover, below the start (the unloading past it has
         * no loading of this cycle beside it): the curve's from far out
         * over the same positions, the same samples */
        adh_run mine_rows;
        adh_run_init(&mine_rows);
        adh_static_result mres;
        int mrc = adh_runner_static_curve(g, k, &m, &s, NULL, NULL, &mine_rows, &mres);
        double step = ADH_CYCLE_HYSTERESIS_STEP * m.z0;
        double hm = adh_cycle_static_hysteresis(&mine_rows, step), hf = adh_cycle_static_hysteresis_below(&run, step, start);
        double scale = fabs(res.pulloff_F) * m.z0;   /* the adhesion's work, a pull-off over z0 */
        ok(mrc == ADH_SUCCESS && fabs(hm - hf) <= 1e-3 * fmax(fabs(hf), 1e-3 * scale),
           "%s: its hysteresis %.6g J is the loop of the curve from far out below the start, %.6g J "
           "(the whole curve's %.6g J)", what, hm, hf, adh_cycle_static_hysteresis(&run, step));
        adh_run_free(&mine_rows);
        if (folded)
            ok(res.folds && res.jump_in_h0 > start,
               "%s: the start is past the curve's snap-in at %.4g nm: its inner branch (%zu folds)", what,
               res.jump_in_h0 * 1e9, res.folds);
        else
            ok(res.folds == 0, "%s: the curve from far out has no fold (%zu)", what, res.folds);
        adh_run_free(&run);
    }
    adh_static_free(w);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* The loop of a relaxation run below h0 = top: the run's rows with h0 <=
 * top only (a start there, whose loading is the run's from further out),
 * measured as a run's (adh_cycle_hysteresis); and the work of its
 * loading there, the integral of |F| dh0, the scale of the loop (a
 * difference of two such works). */
static double loop_below(const adh_run *run, double top, double *work)
{
    adh_obs *rows = malloc((run->nrows ? run->nrows : 1) * sizeof *rows);
    size_t n = 0;
    int path = 0;
    *work = 0;
    for (size_t i = 0; rows && i < run->nrows; i++) {
        if (run->rows[i].h0 > top + 1e-15)
            continue;
        if (n && rows[n - 1].path == 0 && run->rows[i].path == 0)
            *work += 0.5 * fabs(rows[n - 1].F + run->rows[i].F) * fabs(rows[n - 1].h0 - run->rows[i].h0);
        path = run->rows[i].path > path ? run->rows[i].path : path;
        rows[n++] = run->rows[i];
    }
    double h = rows ? adh_cycle_hysteresis(rows, n, path) : NAN;
    free(rows);
    return h;
}

/* Relaxation from a start in contact: its unloading goes on past the
 * start, and its hysteresis is the loop below the start (the positions
 * both branches cover), as the same relaxation's from the automatic start
 * over the same positions: it stood rigid spheres' force in for an
 * approach past the start that no such approach made (below z0 their
 * overlap's: 3.39 pJ at N = 500 from 0.1 nm, a loop of -1.5e-17 J from
 * the automatic start). */
static void relax_loop(void)
{
    adh_material m = { .E = 1e12, .A = 1e-19, .z0 = 0.5e-9, .R = 10e-6 };
    adh_grid *g = adh_grid_alloc(200, 1.5e-9);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_relax_settings rs = adh_relax_settings_default();
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.nturns = 1;
    ps.turns[0] = -1e-9;
    adh_run from, far;
    adh_run_init(&from);
    adh_run_init(&far);
    adh_protocol_settings pf = ps;
    ps.start = 0.1e-9;
    int a = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &from);
    int b = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &pf, NULL, NULL, &far);
    double work, mine = adh_cycle_run_hysteresis(&from), ref = loop_below(&far, ps.start, &work);
    double beyond = from.nrows ? from.rows[from.nrows - 1].h0 : NAN;
    ok(a == ADH_SUCCESS && b == ADH_SUCCESS && beyond > ps.start && fabs(mine - ref) <= 1e-3 * work,
       "relaxation of a 1 TPa sphere from 0.1 nm (its unloading to %.4g nm, past the start): its hysteresis %.4g J "
       "is the loop below the start of the run from the automatic start, %.4g J, within 1e-3 of the loading's work "
       "there, %.4g J", beyond * 1e9, mine, ref, work);
    adh_run_free(&from);
    adh_run_free(&far);
    adh_kernel_free(k);
    adh_grid_free(g);
}

int main(void)
{
    one(10e9, 0.4e-9, 200, 1.5e-9, 0, "E = 10 GPa (no folds)");
    one(3e9, 1.0e-9, 200, 1.5e-9, 1, "E = 3 GPa");
    /* Newton from the undeformed surfaces solves this start (pressing,
     * +9 uN); the pull-off past it, DMT's -2 pi gamma R nearly */
    one(1e12, 0.1e-9, 200, 1.5e-9, 0, "E = 1 TPa (no folds)");
    /* a coarse grid (6 nm, 0.5 edge-zone widths: unresolved on purpose),
     * whose contact line steps over the nodes in lattice folds, loading
     * and unloading alike: a loop below the start, where the others have
     * none */
    one(1e9, 1.0e-9, 200, 6e-9, 1, "E = 1 GPa on 6 nm (lattice folds)");
    relax_loop();
    return tap_done();
}
