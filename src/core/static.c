/* The static solver's facade (adhere/static.h): settings, alloc, set (the
 * start point), iterate (one accepted point by the step strategy in
 * effect: static_arclength.c, or static_qstep.c with static_front.c), and
 * the accepted point's bookkeeping. The parts are listed in
 * src/core/static.h. */
#include "adhere/units.h"
#include "adhere/static.h"
#include "adhere/clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/law.h"
#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "core/static.h"

adh_static_settings adh_static_settings_default(void)
{
    adh_static_settings s = {
        .tol = 1e-9,
        .ds_init = 0.1,
        .ds_min = 1e-7,
        .ds_max = 5.0,
        .u_weight = 1.0,
        .max_angle = 0.4,
        .max_gap_step = 0.25,
        .active_tol = 0.3,
        .h0_start = NAN,
        .h0_end = -5e-9,
        .max_points = 200000,
        .max_newton = 12,
        .lattice_skip = -1,
    };
    return s;
}

int adh_static_settings_validate(const adh_static_settings *s, char *why, size_t whylen)
{
#define BAD(...) do { if (why) snprintf(why, whylen, __VA_ARGS__); return ADH_EINVAL; } while (0)
    if (!(s->tol > 0 && s->tol < 1e-3))
        BAD("static tolerance %g is not allowed: it must be above 0 and below 1e-3 (units of z0)", s->tol);
    if (!(s->ds_min > 0 && s->ds_min <= s->ds_init && s->ds_init <= s->ds_max && s->ds_max < 1e3))
        BAD("arclength steps must satisfy 0 < ds_min (%g) <= ds_init (%g) <= ds_max (%g) < 1000", s->ds_min,
            s->ds_init, s->ds_max);
    if (!(s->u_weight > 0 && isfinite(s->u_weight)))
        BAD("u_weight %g is not allowed: it must be finite and above 0", s->u_weight);
    if (!(s->max_angle > 0 && s->max_angle < 1.5))
        BAD("max_angle %g rad is not allowed: it must be above 0 and below 1.5", s->max_angle);
    if (!(s->max_gap_step >= 0 && s->max_gap_step < 100))
        BAD("max_gap_step %g is not allowed: it must be from 0 (off) to 100 (units of z0)", s->max_gap_step);
    if (!(s->active_tol >= 0 && s->active_tol <= 1))
        BAD("active_tol %g is not allowed: it must be from 0 to 1", s->active_tol);
    if (!isnan(s->h0_start) && !(isfinite(s->h0_start) && s->h0_start > s->h0_end))
        BAD("static start %s must be finite and above the end %s", adh_qtext(s->h0_start, ADH_Q_LENGTH).s,
            adh_qtext(s->h0_end, ADH_Q_LENGTH).s);
    if (!isfinite(s->h0_end))
        BAD("static end position must be finite");
    if (s->lattice_skip < -1 || s->lattice_skip > 1)
        BAD("lattice_skip %d is not allowed: it must be -1 (auto), 0 or 1", s->lattice_skip);
    if (s->max_points < 2 || s->max_newton < 2)
        BAD("max_points (%zu) and max_newton (%zu) must be at least 2", s->max_points, s->max_newton);
    return ADH_SUCCESS;
#undef BAD
}

void adh_static_free(adh_static *w)
{
    if (!w)
        return;
    static_newton_free(w);
    adh_state_free(w->st);
    adh_state_free(w->trial);
    adh_state_free(w->past_least);
    adh_folds_free(w->folds);
    free(w->extra);
    free(w->buf);
    free(w);
}

adh_static *adh_static_alloc(const adh_grid *g, const adh_kernel *k)
{
    return adh_static_alloc_shared(g, k, NULL);
}

adh_static *adh_static_alloc_shared(const adh_grid *g, const adh_kernel *k, const double *entries)
{
    adh_static *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    size_t n = g->n;
    w->grid = g;
    w->k = k;
    w->entries = entries;
    w->n = n;
    w->st = adh_state_alloc(n);
    w->trial = adh_state_alloc(n);
    w->folds = adh_folds_alloc(ADH_STATIC_MAX_FOLDS);
    /* n + 1 numbers each (the zeros stay zero) */
    double **bufs[] = { &w->nw.G, &w->nw.du, &w->nw.bG, &w->nw.Dc, &w->nw.gc, &w->nw.zero,
                        &w->nw.upred, &w->nw.scratch, &w->nw.t2, &w->tau_u, &w->tau_u_new,
                        &w->Dst, &w->gst, &w->Dtr, &w->gtr, &w->q.rG, &w->q.u1, &w->q.u2, &w->shape };
    size_t nb = sizeof bufs / sizeof *bufs;
    w->buf = calloc(nb * (n + 1), sizeof *w->buf);
    if (!w->st || !w->trial || !w->folds || !w->buf || static_newton_alloc(w) != ADH_SUCCESS) {
        adh_static_free(w);
        return NULL;
    }
    for (size_t i = 0; i < nb; i++)
        *bufs[i] = w->buf + i * (n + 1);
    return w;
}

int adh_static_set_gap(adh_static *w, const double *e)
{
    if (!e) {
        free(w->extra);
        w->extra = NULL;
        return ADH_SUCCESS;
    }
    if (!w->extra && !(w->extra = malloc(w->n * sizeof *w->extra)))
        return ADH_ENOMEM;
    memcpy(w->extra, e, w->n * sizeof *e);
    return ADH_SUCCESS;
}

/* The undeformed gap less h0 at each node, r^2/2R and the extra gap e
 * (NULL: none), for the material set in w->m. */
void static_shape(adh_static *w, const double *e)
{
    const double *r = w->grid->r;
    for (size_t i = 0; i < w->n; i++)
        w->shape[i] = r[i] * r[i] / (2.0 * w->m.R) + (e ? e[i] : 0.0);
}

double static_metric_dot(const adh_static *w, const double *au, double ah, const double *bu, double bh)
{
    double d = 0;
    for (size_t i = 0; i < w->n; i++)
        d += au[i] * bu[i];
    return w->s.u_weight * d + ah * bh;
}

/* The unit secant from st to trial, in the metric (dimensionless). */
void static_secant(adh_static *w, double *su, double *sh)
{
    size_t n = w->n;
    double z0 = w->m.z0, dh = (w->trial->h0 - w->st->h0) / z0, s2 = dh * dh;
    for (size_t i = 0; i < n; i++) {
        su[i] = (w->trial->u[i] - w->st->u[i]) / z0;
        s2 += w->s.u_weight * su[i] * su[i];
    }
    double len = sqrt(s2);
    for (size_t i = 0; i < n; i++)
        su[i] /= len;
    *sh = dh / len;
}

/* dF/ds along the unit tangent: F = 2 pi dr sum r p, dh = dh0 - du. */
static double force_slope(const adh_static *w, const double *D, const double *tu, double th)
{
    double s = 0, z0 = w->m.z0;
    if (w->grid->graded) { /* ring areas, as adh_force */
        for (size_t i = 0; i < w->n; i++)
            s += adh_rings_weight(w->grid, i) * D[i] * z0 * (th - tu[i]);
        return 2.0 * M_PI * s;
    }
    for (size_t i = 0; i < w->n; i++)
        s += w->grid->r[i] * D[i] * z0 * (th - tu[i]);
    /* the tail beyond Rmax, 2 pi R W(h0 + Rmax^2/2R), has slope -2 pi R p there
     * per unit h0; s is in units of z0 */
    double edge = w->st->h0 + w->grid->rmax * w->grid->rmax / (2.0 * w->m.R);
    double tail = edge > 0 ? -2.0 * M_PI * w->m.R * adh_lj_pressure(edge, w->m.A, z0) : 0;
    return 2.0 * M_PI * w->grid->dr * s + tail * z0 * th;
}

static void swap(double **a, double **b)
{
    double *t = *a;
    *a = *b;
    *b = t;
}

/* Makes trial (tangent in tau_*_new, Jacobian data in Dtr, gtr, det J's
 * sign in det_sign) the current point, and hands it to the fold
 * bookkeeping: with its tangent and force slope on the exact curve, by
 * the last three points when the lattice folds are stepped over. */
void static_accept(adh_static *w)
{
    size_t n = w->n;
    double z0 = w->m.z0;
    double d2 = (w->trial->h0 - w->st->h0) * (w->trial->h0 - w->st->h0), du2 = 0;
    for (size_t i = 0; i < n; i++)
        du2 += (w->trial->u[i] - w->st->u[i]) * (w->trial->u[i] - w->st->u[i]);
    double len = sqrt(d2 + w->s.u_weight * du2) / z0;
    adh_state *tmp = w->st;
    w->st = w->trial;
    w->trial = tmp;
    swap(&w->tau_u, &w->tau_u_new);
    w->tau_h = w->tau_h_new;
    swap(&w->Dst, &w->Dtr);
    swap(&w->gst, &w->gtr);
    w->stable = w->det_sign > 0;
    w->F = adh_force(w->grid, &w->m, w->st);
    w->s_arc += len;
    w->res.points++;
    if (!w->skip)
        w->dFds = force_slope(w, w->Dst, w->tau_u, w->tau_h);
    adh_folds_point p = { .s = w->s_arc, .ds = len, .h0 = w->st->h0, .F = w->F, .dh0 = w->tau_h * z0,
                          .dF = w->dFds };
    adh_folds_add(w->folds, &p);
}

/* The status after an accepted point: the end, more to come, or the
 * contact has reached the grid's edge or left its resolved part. */
int static_accepted(adh_static *w)
{
    int rc = w->done ? ADH_SUCCESS : ADH_CONTINUE;
    double a = adh_contact_radius(w->grid, w->st->h, w->m.z0);
    if (a >= 0.9 * w->grid->rmax || !adh_rings_resolves(w->grid, a))
        rc = ADH_EGRID;
    return rc;
}

/* Whether the next step lands on h0_end (natural parametrization: then
 * *ds is the step there along the tangent), else *ds = w->ds. Front steps
 * land only when asked (end_next). */
int static_landing(const adh_static *w, int front, double *ds)
{
    double z0 = w->m.z0;
    int fix = w->tau_h < 0 &&
              (w->end_next || (!front && w->st->h0 + w->ds * z0 * w->tau_h <= w->s.h0_end));
    *ds = fix ? (w->s.h0_end - w->st->h0) / (z0 * w->tau_h) : w->ds;
    return fix;
}

/* What a rejected step attempt met, for the stop's sentence: the
 * corrector's status (ADH_SUCCESS: it converged, but off the curve). */
const char *static_reject(int rc)
{
    switch (rc) {
    case ADH_SUCCESS: return "the corrected point left the curve (it turned past the largest angle or ran back)";
    case ADH_EMAXITER: return "Newton's corrector did not converge";
    case ADH_ENAN: return "Newton's corrector met a closed gap or a non-finite value";
    default: return adh_strerror(rc);
    }
}

/* The step fell below ds_min: the stop's sentence (how: the kind of
 * step), and the relaxation named as what goes on there (it steps the
 * drive without following the curve). ADH_ESTALL. */
int static_stalled(adh_static *w, const char *how)
{
    snprintf(w->why, sizeof w->why,
             "the static curve stalled at h0 = %s (F = %s, %zu point%s, %zu attempt%s rejected): the %s fell below "
             "its floor, %g z0; the last attempt: %s; the relaxation steps the drive without following the curve",
             adh_qtext(w->st->h0, ADH_Q_LENGTH).s, adh_qtext(w->F, ADH_Q_FORCE).s, w->res.points, w->res.points == 1 ? "" : "s", w->res.rejected,
             w->res.rejected == 1 ? "" : "s",
             how, w->s.ds_min, w->last_reject ? w->last_reject : "none");
    w->fix = ADH_FIX_MODE;
    return ADH_ESTALL;
}

/* The start point: from guess (NULL: undeformed), going down, corrected
 * at h0 = h0_start, its tangent and det J's sign (the start must lie on a
 * stable branch going in: out there J = I + small, det J > 0). */
static int start(adh_static *w, const double *guess)
{
    size_t n = w->n;
    if (guess)
        memcpy(w->st->u, guess, n * sizeof *w->st->u);
    else
        memset(w->st->u, 0, n * sizeof *w->st->u);
    w->st->h0 = w->s.h0_start;
    memset(w->tau_u, 0, n * sizeof *w->tau_u);
    w->tau_h = -1.0;
    if (static_evaluate(w, w->st) < 0) {
        snprintf(w->why, sizeof w->why, "the static curve's start h0 = %s: the surface pressure is not finite there "
                 "(the surfaces overlap): start further out", adh_qtext(w->s.h0_start, ADH_Q_LENGTH).s);
        w->fix = ADH_FIX_START;
        return ADH_ENAN;
    }
    static_jacobian(w, w->st, w->nw.Dc, w->nw.gc);
    int rc = static_refactor(w, w->nw.Dc, w->nw.gc, w->tau_u, w->tau_h);
    size_t it = 0;
    if (rc == ADH_SUCCESS) {
        static_predict(w, 0.0, 1, w->s.h0_start);
        static_row row = { .kind = STATIC_ROW_PLANE, .nu = w->nw.zero, .nh = 1.0 };
        rc = static_correct(w, &row, &it);
    }
    if (rc == ADH_SUCCESS) {
        static_jacobian(w, w->trial, w->Dtr, w->gtr);
        rc = static_refactor(w, w->Dtr, w->gtr, w->tau_u, w->tau_h);
    }
    if (rc == ADH_SUCCESS)
        rc = static_tangent(w, w->Dtr, w->gtr, w->tau_u_new, &w->tau_h_new);
    if (rc == ADH_SUCCESS && !(w->tau_h_new < 0))
        rc = ADH_ESTALL;
    w->det_b_sign = adh_precond_det_sign(w->nw.P);
    w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->det_b_sign;
    if (rc == ADH_SUCCESS && w->det_sign < 0)
        rc = ADH_ESTALL;
    if (rc != ADH_SUCCESS) {
        /* out there the surfaces barely feel each other: the start is solved at once */
        snprintf(w->why, sizeof w->why, "the static curve's start h0 = %s %s%s: start further out",
                 adh_qtext(w->s.h0_start, ADH_Q_LENGTH).s,
                 rc == ADH_ESTALL ? "is not on the outer branch going in (a stable point out of contact)"
                                  : "could not be solved: ",
                 rc == ADH_ESTALL ? "" : static_reject(rc));
        w->fix = ADH_FIX_START;
        return rc;
    }
    w->newton_point = it;
    w->F = 0;
    w->dFds = 0;
    static_accept(w);
    return w->skip ? static_qstep_start(w) : ADH_SUCCESS;
}

static void reset(adh_static *w);
static int traced(adh_static *w, double *guess, char *how, size_t howlen, unsigned *fix);

/* Whether the surfaces touch at the present point (a row's a > 0). */
static int in_contact(const adh_static *w)
{
    return adh_contact_radius(w->grid, w->st->h, w->m.z0) > 0;
}

int adh_static_set(adh_static *w, const adh_material *m, const adh_static_settings *s)
{
    if (adh_static_settings_validate(s, NULL, 0) != ADH_SUCCESS || adh_material_validate(m, NULL, 0) != ADH_SUCCESS)
        return ADH_EINVAL;
    double t0 = adh_clock_seconds();
    size_t n = w->n;
    w->m = *m;
    w->s = *s;
    if (isnan(w->s.h0_start))
        w->s.h0_start = adh_protocol_auto_start(m, 0.05e-9);
    if (!(w->s.h0_start > w->s.h0_end))
        return ADH_EINVAL;
    w->c2E = 2.0 / m->E;
    static_shape(w, w->extra);
    reset(w);
    w->past_on = w->past_lost = 0;
    int rc = start(w, NULL);
    /* A start in contact: the unloading goes on past it until the surfaces
     * separate (the protocol's rule, adhere/drive.h, one for every mode):
     * on the static curve that is the curve from further out, traced from
     * the automatic start down to the start; its pull-off and jump-out are
     * the curve's (docs/static-curve.md). The start itself is solved again
     * as it was, from the undeformed surfaces. */
    int past = rc == ADH_SUCCESS && in_contact(w);
    if (rc == ADH_EMAXITER || rc == ADH_ENAN || past) {
        /* Newton from the undeformed surfaces did not reach the state
         * there: a contact (a stiff sphere already pressing, or past the
         * snap-in, the inner branch) too far from them. The curve from
         * further out reaches it; from there the start is solved at once. */
        adh_static_settings want = w->s;
        double *guess = malloc(n * sizeof *guess);
        char how[sizeof w->why];   /* the way's stop whole: its remedy is at its end */
        unsigned fix = 0;
        int trc = guess ? traced(w, guess, how, sizeof how, &fix) : ADH_ENOMEM;
        w->s = want;
        reset(w);
        /* (stopped on the way: no curve) */
        rc = trc == ADH_ENOMEM || trc == ADH_EINTR ? trc : start(w, trc == ADH_SUCCESS && !past ? guess : NULL);
        free(guess);
        if (rc == ADH_SUCCESS && in_contact(w)) {
            w->past_on = trc == ADH_SUCCESS;
            w->past_lost = trc != ADH_SUCCESS;
        }
        if (rc == ADH_ENOMEM) {   /* said so, not as the start's Newton failure */
            snprintf(w->why, sizeof w->why, "out of memory on the way to the static curve's start h0 = %s",
                     adh_qtext(w->s.h0_start, ADH_Q_LENGTH).s);
            w->fix = 0;
        } else if (rc != ADH_SUCCESS && trc != ADH_SUCCESS) {
            /* the start's own failure, and what stopped the way to it */
            snprintf(w->why, sizeof w->why, "the static curve from further out did not reach its start h0 = %s: ",
                     adh_qtext(w->s.h0_start, ADH_Q_LENGTH).s);
            size_t k = strlen(w->why), len = strlen(how);   /* how whole where it fits (its remedy last) */
            len = len < sizeof w->why - 1 - k ? len : sizeof w->why - 1 - k;
            memcpy(w->why + k, how, len);
            w->why[k + len] = '\0';
            w->fix = fix;
            rc = trc;
        }
    }
    w->res.seconds += adh_clock_seconds() - t0;
    return rc;
}

/* A new curve under w->s (its start resolved) from no points. */
static void reset(adh_static *w)
{
    memset(&w->res, 0, sizeof w->res);
    w->done = 0;
    w->s_arc = 0;
    w->ds = w->s.ds_init;
    w->nw.act = w->s.active_tol;
    w->det_sign = +1;
    w->skip = w->s.lattice_skip < 0 ? adh_static_skips(w->grid, &w->m, w->s.h0_end) : w->s.lattice_skip;
    adh_folds_set(w->folds, w->skip ? ADH_FOLDS_PARABOLA : ADH_FOLDS_HERMITE);
    w->q.nhist = 0;
    w->end_next = 0;
    w->why[0] = '\0';
    w->fix = 0;
    w->last_reject = NULL;
    static_front_set(w);
}

/* The curve from the automatic start (where the undeformed surfaces are
 * solved at once) down to w->s.h0_start, through every fold: its last
 * point's u into guess; or why not, in how (with the settings that get
 * past it in *fix). w->s is left changed. */
static int traced(adh_static *w, double *guess, char *how, size_t howlen, unsigned *fix)
{
    double to = w->s.h0_start, from = adh_protocol_auto_start(&w->m, 0.05e-9);
    *fix = ADH_FIX_START;
    snprintf(how, howlen, "the automatic start, %s, is not further out", adh_qtext(from, ADH_Q_LENGTH).s);
    if (!(from > to))
        return ADH_EINVAL;
    w->s.h0_start = from;
    w->s.h0_end = to;
    reset(w);
    if (!w->past_least && !(w->past_least = adh_state_alloc(w->n)))
        return ADH_ENOMEM;
    w->past_least_F = INFINITY;
    int rc = start(w, NULL);
    while (rc == ADH_SUCCESS && !w->done) {
        if (w->F < w->past_least_F) {   /* where the pull-off profile is */
            adh_state_copy(w->past_least, w->st);
            w->past_least_F = w->F;
        }
        if ((rc = adh_static_iterate(w)) == ADH_CONTINUE)
            rc = ADH_SUCCESS;
    }
    if (rc == ADH_SUCCESS && w->F < w->past_least_F) {
        adh_state_copy(w->past_least, w->st);
        w->past_least_F = w->F;
    }
    if (rc == ADH_SUCCESS) {
        memcpy(guess, w->st->u, w->n * sizeof *guess);
        w->past = adh_folds_summary_of(w->folds);
        return rc;
    }
    double a = adh_contact_radius(w->grid, w->st->h, w->m.z0);
    if (rc == ADH_EGRID) {   /* as a run's stop at the grid's edge says it */
        adh_rings_edge_sentence(w->grid, a, how, howlen);
        *fix = adh_rings_edge_fix(w->grid, a);
    } else {
        snprintf(how, howlen, "%s", w->why[0] ? w->why : adh_strerror(rc));
        *fix = w->fix;
    }
    return rc;
}

double adh_static_exact_points(const adh_grid *g, const adh_material *m, double h0_end)
{
    double l = adh_edge_zone(m), crossings = adh_rings_contact_estimate(m, fmin(h0_end, 0.0)) / g->dr;
    return crossings * (l >= 4.0 * g->dr ? 1.3 : 3.0);
}

int adh_static_skips(const adh_grid *g, const adh_material *m, double h0_end)
{
    /* resolved as adh_grid_check says, with its margin */
    int resolved = g->dr <= ADH_GRID_EDGE_SPACING_STATIC * adh_edge_zone(m) * (1 + 1e-9);
    return g->n > ADH_STATIC_EXACT_MAX_NODES ||
           (resolved && adh_static_exact_points(g, m, h0_end) > 3.0 * ADH_STATIC_STEP_POINTS);
}

int adh_static_iterate(adh_static *w)
{
    if (w->done)
        return ADH_SUCCESS;
    w->nw.act = w->s.active_tol;
    if (w->res.points >= w->s.max_points) {
        snprintf(w->why, sizeof w->why, "the static curve reached its cap of %zu points at h0 = %s, before its end "
                 "h0 = %s", w->s.max_points, adh_qtext(w->st->h0, ADH_Q_LENGTH).s,
                 adh_qtext(w->s.h0_end, ADH_Q_LENGTH).s);
        w->fix = 0;
        return ADH_EMAXITER;
    }
    double t0 = adh_clock_seconds();
    int rc = w->skip ? static_qstep_iterate(w) : static_arclength_iterate(w);
    w->res.seconds += adh_clock_seconds() - t0;
    return rc;
}

const adh_state *adh_static_state(const adh_static *w)
{
    return w->st;
}

adh_static_point adh_static_current(const adh_static *w)
{
    adh_static_point p = {
        .s = w->s_arc,
        .tangent_h0 = w->tau_h,
        .direction = w->tau_h < 0 ? +1 : -1,
        .stable = w->stable,
        .newton = w->newton_point,
        .active = adh_precond_active(w->nw.P),
        .residual = w->nw.residual,
    };
    return p;
}

const char *adh_static_why(const adh_static *w, unsigned *fix)
{
    if (fix)
        *fix = w->fix;
    return w->why;
}

void adh_static_summary(const adh_static *w, adh_static_result *res)
{
    adh_folds_summary f = adh_folds_summary_of(w->folds);
    *res = w->res;
    res->jump_in_h0 = f.jump_in_h0;
    res->jump_out_h0 = f.jump_out_h0;
    res->pulloff_F = f.pulloff_F;
    res->pulloff_h0 = f.pulloff_h0;
    res->pulloff_F_disp = f.pulloff_F_disp;
    res->folds = f.folds;
    if (w->past_lost) {   /* the unloading past the start is not known */
        res->pulloff_F = res->pulloff_h0 = NAN;
    } else if (w->past_on) {   /* the curve past the start, as from further out */
        if (w->past.pulloff_F < res->pulloff_F) {
            res->pulloff_F = w->past.pulloff_F;
            res->pulloff_h0 = w->past.pulloff_h0;
        }
        if (!isnan(w->past.jump_out_h0) && !(w->past.jump_out_h0 <= res->jump_out_h0)) {
            res->jump_out_h0 = w->past.jump_out_h0;
            res->pulloff_F_disp = w->past.pulloff_F_disp;
        }
    }
    if (isinf(res->pulloff_F))   /* no point at all: the least force of none is no pull-off */
        res->pulloff_F = res->pulloff_h0 = NAN;
}

size_t adh_static_folds(const adh_static *w, const adh_static_fold **folds)
{
    return adh_folds_kept(w->folds, folds);
}

const adh_state *adh_static_past_least(const adh_static *w, double *F)
{
    if (!w->past_on || !w->past_least)
        return NULL;
    *F = w->past_least_F;
    return w->past_least;
}
