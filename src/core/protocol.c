#include "adhere/protocol.h"
#include "adhere/cycle.h"
#include "adhere/rings.h"
#include "adhere/clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/models.h"
#include "adhere/status.h"

adh_protocol_settings adh_protocol_settings_default(void)
{
    adh_protocol_settings ps;
    memset(&ps, 0, sizeof ps);
    ps.start = NAN;
    ps.step = 0.05e-9;
    ps.nturns = 1;
    ps.turns[0] = -5e-9;
    ps.unload = 1;
    return ps;
}

double adh_protocol_auto_start(const adh_material *m, double step)
{
    /* |delta(h)| = 0.01 z0 from eq 23 */
    double hb = pow(m->A * sqrt(2.0 * m->R) / (8.0 * m->E * 0.01 * m->z0), 0.4);
    double h = fmax(hb, fmax(4.0 * adh_jump_separation(m), 5.0 * m->z0));
    return step * ceil(h / step - 1e-9);
}

static double deepest_turn(const adh_protocol_settings *ps)
{
    double t = INFINITY;
    for (size_t i = 0; i < ps->nturns; i++)
        t = fmin(t, ps->turns[i]);
    return t;
}

int adh_protocol_check(const adh_protocol_settings *ps, const adh_material *m,
                       const adh_grid *g, char *why, size_t whylen)
{
    if (!(isfinite(ps->step) && ps->step >= 1e-14 && ps->step <= 1e-8)) {
        snprintf(why, whylen, "step d = %g m is not allowed: it must be from 1e-14 to 1e-8 m (0.01 pm to 10 nm)", ps->step);
        return ADH_EINVAL;
    }
    if (ps->nturns > ADH_MAX_TURNS) {
        snprintf(why, whylen, "%zu turning points given: at most %d are allowed", ps->nturns, ADH_MAX_TURNS);
        return ADH_EINVAL;
    }
    for (size_t i = 0; i < ps->nturns; i++) {
        double t = ps->turns[i];
        if (!isfinite(t) || t < -0.02 * m->R) {
            int dflt = ps->nturns == 1 && t == adh_protocol_settings_default().turns[0];
            snprintf(why, whylen, "turning point %g m%s is too deep: the model (h0 << R) allows down to -R/50 = %g m%s", t,
                     dflt ? " (the default turn)" : "", -0.02 * m->R, dflt ? "; give a shallower --turn (or turns in the scene), or a larger R" : "");
            return ADH_EINVAL;
        }
    }
    double lowest = ps->nturns ? deepest_turn(ps) : 0.0;
    /* The model needs h0 << R and a grid edge (at most 0.3 R out) where the
     * gap is many z0 wide: r^2/2R there is at most 0.045 R. */
    double need = (10.0 * m->z0 + fabs(lowest)) / 0.045;
    if (m->R < need) {
        snprintf(why, whylen, "R = %g m is too small for this model: h0 << R and a negligible force at the grid edge need R >= %g m here (10 z0 plus the deepest |h0|, over 0.045)",
                 m->R, need);
        return ADH_EINVAL;
    }
    double start = isnan(ps->start) ? adh_protocol_auto_start(m, ps->step) : ps->start;
    if (!isfinite(start) || start <= 0 || start > 0.02 * m->R) {
        if (isnan(ps->start))
            snprintf(why, whylen, "R = %g m is too small for this material: the automatic start (where the force is negligible: the bulge of eq 23 below 0.01 z0 and 4 jump separations out) is %g m, above R/50 = %g m (the model needs h0 << R); use a larger R, or give a start up to %g m",
                     m->R, start, 0.02 * m->R, 0.02 * m->R);
        else
            snprintf(why, whylen, "start = %g m is not allowed: it must be above 0 and at most R/50 = %g m (the model needs h0 << R)",
                     start, 0.02 * m->R);
        return ADH_EINVAL;
    }
    for (size_t i = 0; i < ps->nturns; i++) {
        if (ps->turns[i] >= start) {
            snprintf(why, whylen, "turning point %g m is not allowed: it must lie below the start %g m", ps->turns[i], start);
            return ADH_EINVAL;
        }
    }
    double steps = (start - lowest) / ps->step;
    if (steps > 2e6) {
        snprintf(why, whylen, "%.0f drive steps of %g m from %g to %g m: at most 2e6 are allowed; take a larger step", steps, ps->step, start, lowest);
        return ADH_EINVAL;
    }
    if (!g)
        return ADH_SUCCESS;   /* rigid spheres: no grid to check */
    if (g->n < 10) {
        snprintf(why, whylen, "N = %zu nodes is not allowed: at least 10 are needed", g->n);
        return ADH_EINVAL;
    }
    double lateral = sqrt(m->R * m->z0);
    if (g->dr > 0.25 * lateral) {
        snprintf(why, whylen, "grid spacing %g m is too coarse: the contact edge needs at most 0.25 sqrt(R z0) = %g m; use more nodes", g->dr, 0.25 * lateral);
        return ADH_EGRID;
    }
    if (g->rmax > 0.3 * m->R) {
        snprintf(why, whylen, "grid radius Rmax = N x spacing = %g m is not << R = %g m: at most 0.3 R is allowed", g->rmax, m->R);
        return ADH_EGRID;
    }
    /* The contact at the deepest position: the undeformed overlap radius,
     * enlarged by half again for adhesion (JKR contacts exceed Hertz's). */
    double gap_edge = lowest + g->rmax * g->rmax / (2.0 * m->R);
    double a_est = 1.5 * sqrt(2.0 * m->R * fmax(0.0, m->z0 - lowest));
    if (gap_edge < 10 * m->z0 || a_est > 0.8 * g->rmax) {
        snprintf(why, whylen, "grid radius Rmax = %g m is too short: the contact at h0 = %g m may reach %g m; use more nodes (--nodes) or a larger spacing",
                 g->rmax, lowest, a_est);
        return ADH_EGRID;
    }
    /* Coarser than five edge zones, the contact line moves node by node and
     * the relaxation locks into oscillation between nodes (seen at sigma =
     * 100 on the N = 100 default grid: every step at the iteration cap). */
    double edge = adh_edge_zone(m);
    if (ps->nturns > 0 && g->dr > 5.0 * edge) {
        snprintf(why, whylen, "grid spacing %g m is too coarse for this contact: its edge zone is about %g m wide (sigma = %.3g), and a spacing above 5 times that (%g m) locks the contact line to the nodes; use more nodes or a smaller spacing",
                 g->dr, edge, m->A / (16.0 * M_PI * m->z0 * m->z0) * sqrt(m->R / pow(m->z0, 3)) / m->E, 5.0 * edge);
        return ADH_EGRID;
    }
    if (adh_rings_check(g, m, lowest, why, whylen) != ADH_SUCCESS)
        return ADH_EGRID;
    double tail = fabs(adh_rigid_force(m, gap_edge));
    double scale = fabs(adh_dmt_pulloff(m));
    if (tail > 1e-3 * scale) {
        snprintf(why, whylen, "grid radius Rmax = %g m is too short: the force beyond it (%g N) is not negligible against 2 pi gamma R = %g N",
                 g->rmax, tail, scale);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}

void adh_run_init(adh_run *run)
{
    memset(run, 0, sizeof *run);
    run->jump_in_h0 = NAN;
    run->status = ADH_SUCCESS;
}

void adh_run_free(adh_run *run)
{
    for (size_t i = 0; i < run->nprofiles; i++)
        free(run->profiles[i].u);
    free(run->profiles);
    free(run->rows);
    adh_run_init(run);
}

int adh_run_separated(const adh_run *run, char *why, size_t whylen)
{
    for (size_t i = 0; i < run->nturns; i++) {
        const adh_turn_result *t = &run->turns[i];
        if (t->path <= 0 || isfinite(t->jump_out_h0))
            continue;
        double a_end = NAN, h_end = NAN;
        for (size_t j = run->nrows; j-- > 0;)
            if (run->rows[j].path == t->path) {
                a_end = run->rows[j].a;
                h_end = run->rows[j].h0;
                break;
            }
        snprintf(why, whylen, "the surfaces never separated: unloading from the turn at h0 = %.4g m ended at "
                 "h0 = %.4g m still in contact (contact radius %.4g m), so there is no jump-out and the "
                 "pull-off is only the lowest force seen", t->h0, h_end, a_end);
        return 0;
    }
    return 1;
}

const adh_turn_result *adh_run_main_turn(const adh_run *run)
{
    for (size_t i = run->nturns; i-- > 0;)
        if (run->turns[i].path > 0)
            return &run->turns[i];
    return NULL;
}

int adh_run_push_row(adh_run *run, const adh_obs *o)
{
    if (run->nrows == run->rows_cap) {
        size_t cap = run->rows_cap ? 2 * run->rows_cap : 256;
        adh_obs *p = realloc(run->rows, cap * sizeof *p);
        if (!p)
            return ADH_ENOMEM;
        run->rows = p;
        run->rows_cap = cap;
    }
    run->rows[run->nrows++] = *o;
    return ADH_SUCCESS;
}

static int push_profile(adh_run *run, const adh_state *s, int branch, int path)
{
    if (run->nprofiles == run->profiles_cap) {
        size_t cap = run->profiles_cap ? 2 * run->profiles_cap : 16;
        adh_profile *p = realloc(run->profiles, cap * sizeof *p);
        if (!p)
            return ADH_ENOMEM;
        run->profiles = p;
        run->profiles_cap = cap;
    }
    adh_profile *pr = &run->profiles[run->nprofiles];
    pr->u = malloc(3 * s->n * sizeof(double));
    if (!pr->u)
        return ADH_ENOMEM;
    memcpy(pr->u, s->u, 3 * s->n * sizeof(double));
    pr->h = pr->u + s->n;
    pr->p = pr->u + 2 * s->n;
    pr->h0 = s->h0;
    pr->branch = branch;
    pr->path = path;
    run->nprofiles++;
    return ADH_SUCCESS;
}

typedef struct runner {
    const adh_grid *g;
    const adh_material *m;
    const adh_protocol_settings *ps;
    adh_relax *w;
    adh_run *run;
    adh_step_cb cb;
    void *ctx;
} runner;

static int wants_profile(const adh_protocol_settings *ps, double h0)
{
    for (size_t i = 0; i < ps->nprofiles; i++)
        if (fabs(ps->profiles[i] - h0) < 1e-6 * ps->step)
            return 1;
    return 0;
}

/* Moves to h0 (unless already there), relaxes, observes and records a row.
 * Returns ADH_SUCCESS (also for a step that hit the cap: that is flagged in
 * the row and counted, not fatal), or an error that ends the run. */
static int drive_step(runner *rn, double h0, int branch, int path, size_t dwell, adh_obs *o)
{
    double t0 = adh_clock_seconds();
    int rc;
    if (dwell) {
        rc = adh_relax_dwell(rn->w, dwell);
    } else {
        adh_relax_move(rn->w, h0);
        rc = adh_relax_iterate(rn->w, 0);
    }
    double dt = adh_clock_seconds() - t0;
    const adh_state *s = adh_relax_state(rn->w);
    memset(o, 0, sizeof *o);
    adh_observe(rn->g, rn->m, s, o);
    o->iters = dwell ? dwell : adh_relax_step_iterations(rn->w);
    o->seconds = dt;
    o->branch = branch;
    o->path = path;
    o->converged = (rc == ADH_SUCCESS);
    o->stable = 1;
    rn->run->iterations += o->iters;
    rn->run->seconds += dt;
    if (rc == ADH_EINTR) {
        /* an unfinished step is no result: no row, and the run ends here */
        rn->run->interrupted = 1;
        return ADH_CONTINUE;
    }
    if (rc == ADH_EMAXITER) {
        rn->run->unconverged++;
        rc = ADH_SUCCESS;
    }
    if (rc != ADH_SUCCESS)
        return rc;
    if (!(isfinite(o->F) && isfinite(o->delta) && isfinite(o->a)))
        return ADH_ENAN;
    int prc = adh_run_push_row(rn->run, o);
    if (prc != ADH_SUCCESS)
        return prc;
    if (wants_profile(rn->ps, h0) && push_profile(rn->run, s, branch, path) != ADH_SUCCESS)
        return ADH_ENOMEM;
    if (o->a >= 0.9 * rn->g->rmax || !adh_rings_resolves(rn->g, o->a))
        return ADH_EGRID;
    if (rn->cb && rn->cb(o, rn->run, rn->ctx)) {
        rn->run->interrupted = 1;
        return ADH_CONTINUE;
    }
    return ADH_SUCCESS;
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

static int unload_branch(runner *rn, adh_turn_result *tr, const adh_state *snap, double start)
{
    const adh_protocol_settings *ps = rn->ps;
    adh_obs o;
    adh_relax_restore(rn->w, snap);
    int rc = drive_step(rn, tr->h0, -1, tr->path, ps->dwell, &o);
    if (rc != ADH_SUCCESS)
        return rc;
    tr->pulloff_F = o.F;
    tr->pulloff_h0 = o.h0;
    int touched = o.a > 0;
    for (long k = 1;; k++) {
        double h0 = tr->h0 + (double)k * ps->step;
        if (h0 > start + 1e-6 * ps->step)
            break;
        rc = drive_step(rn, h0, -1, tr->path, 0, &o);
        if (rc != ADH_SUCCESS)
            return rc;
        if (o.F < tr->pulloff_F) {
            tr->pulloff_F = o.F;
            tr->pulloff_h0 = o.h0;
        }
        if (o.a > 0)
            touched = 1;
        else if (touched) {
            tr->jump_out_h0 = o.h0;
            break;
        }
    }
    return ADH_SUCCESS;
}

int adh_protocol_run(const adh_grid *g, const adh_kernel *k, const adh_material *m,
                     const adh_relax_settings *rs, const adh_protocol_settings *ps,
                     adh_step_cb cb, void *ctx, adh_run *run)
{
    adh_relax *w = adh_relax_alloc(g, k);
    adh_state *snaps[ADH_MAX_TURNS] = { 0 };
    double turns[ADH_MAX_TURNS];
    size_t nt = ps->nturns;
    if (!w) {
        run->status = ADH_ENOMEM;
        return run->status;
    }
    runner rn = { g, m, ps, w, run, cb, ctx };
    double start = isnan(ps->start) ? adh_protocol_auto_start(m, ps->step) : ps->start;
    run->start = start;
    memcpy(turns, ps->turns, nt * sizeof *turns);
    qsort(turns, nt, sizeof *turns, cmp_desc);

    adh_relax_set(w, m, rs, start);
    adh_obs o;
    int rc = drive_step(&rn, start, +1, 0, 0, &o);
    size_t ti = 0;
    int in_contact = o.a > 0;
    /* Positions are start - k d, computed afresh (never accumulated) so that
     * positions such as -3.5 nm are hit exactly; each turn is hit exactly. */
    for (long kstep = 1; rc == ADH_SUCCESS; kstep++) {
        if (nt == 0 && in_contact)
            break;
        if (nt > 0 && ti == nt)
            break;
        double h0 = start - (double)kstep * ps->step;
        int at_turn = 0;
        if (nt > 0 && h0 <= turns[ti] + 1e-6 * ps->step) {
            h0 = turns[ti];
            at_turn = 1;
            kstep = (long)floor((start - h0) / ps->step + 1e-6);
        }
        if (nt == 0 && h0 < -0.01 * m->R)
            break;
        rc = drive_step(&rn, h0, +1, 0, 0, &o);
        if (rc != ADH_SUCCESS)
            break;
        if (o.a > 0 && !in_contact) {
            in_contact = 1;
            run->jump_in_h0 = o.h0;
        }
        while (at_turn && ti < nt && fabs(turns[ti] - h0) < 1e-6 * ps->step) {
            adh_turn_result *tr = &run->turns[run->nturns++];
            tr->h0 = h0;
            tr->max_load = o.F;
            tr->a_turn = o.a;
            tr->pulloff_F = NAN;
            tr->pulloff_h0 = NAN;
            tr->jump_out_h0 = NAN;
            tr->path = 0;
            snaps[ti] = adh_state_clone(adh_relax_state(w));
            if (!snaps[ti])
                rc = ADH_ENOMEM;
            ti++;
        }
    }
    if (rc == ADH_SUCCESS && ps->unload) {
        for (size_t i = 0; i < run->nturns && rc == ADH_SUCCESS; i++) {
            run->turns[i].path = (int)i + 1;
            rc = unload_branch(&rn, &run->turns[i], snaps[i], start);
        }
    }
    for (size_t i = 0; i < nt; i++)
        adh_state_free(snaps[i]);
    adh_relax_free(w);
    if (rc == ADH_CONTINUE)
        rc = ADH_SUCCESS; /* interrupted on request: not an error, run->interrupted says so */
    run->status = rc;
    return rc;
}

double adh_hysteresis_area(const adh_run *run, double step)
{
    (void)step;   /* the cycle interpolates: a turn off the drive grid still pairs */
    return adh_cycle_hysteresis(run->rows, run->nrows, (int)run->nturns);
}

/* The hysteresis left when eps -> 0: under displacement control the drive
 * follows stable equilibria only, loading on the highest-force one at each
 * h0 (the outer branch until it ends at the jump-in fold) and unloading on
 * the lowest (the contact until the jump-out fold). Between the folds, and
 * wherever lattice trapping makes stable legs overlap, the two differ: the
 * area between them is the hysteresis no slower drive removes. */
double adh_static_hysteresis_area(const adh_run *curve, double step)
{
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < curve->nrows; i++) {
        lo = fmin(lo, curve->rows[i].h0);
        hi = fmax(hi, curve->rows[i].h0);
    }
    double area = 0;
    for (double x = lo + 0.5 * step; x < hi; x += step) {
        double fmax_ = -INFINITY, fmin_ = INFINITY;
        for (size_t i = 0; i + 1 < curve->nrows; i++) {
            const adh_obs *a = &curve->rows[i], *b = &curve->rows[i + 1];
            if (!a->stable || !b->stable || (x - a->h0) * (x - b->h0) > 0 || a->h0 == b->h0)
                continue;
            double F = a->F + (b->F - a->F) * (x - a->h0) / (b->h0 - a->h0);
            fmax_ = fmax(fmax_, F);
            fmin_ = fmin(fmin_, F);
        }
        if (fmax_ > fmin_)
            area += (fmax_ - fmin_) * step;
    }
    return area;
}
