#include "adhere/fitmodel.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/observe.h"
#include "adhere/protocol.h"
#include "adhere/rings.h"
#include "adhere/rule.h"
#include "adhere/rule_visco.h"
#include "adhere/run.h"
#include "adhere/runner.h"
#include "adhere/status.h"

/* One branch, ascending in h0, with its interpolant. */
typedef struct branch {
    size_t n, cap;
    double *h0, *F;
    gsl_interp *interp;
    gsl_interp_accel *acc;
} branch;

struct adh_fit_model {
    const adh_grid *g;
    const adh_kernel *k;
    adh_fit_model_settings s;
    adh_static *w;               /* built on the first static evaluation */
    double time_start;           /* the physical-time model's start, fixed at its first
                                    evaluation (0: none yet) */
    size_t first_points;         /* the first curve's points: later ones are capped at
                                    ADH_FIT_MODEL_POINTS_FACTOR times as many */
    size_t n, cap;               /* the curve */
    double *h0, *F;
    int *stable;
    branch b[2];
    char why[400];               /* why the last evaluation failed, as a run says it; "" */
    unsigned fix;                /* its ADH_FIX_* bits */
};

adh_fit_model_settings adh_fit_model_settings_default(void)
{
    adh_fit_model_settings s;
    memset(&s, 0, sizeof s);
    s.kind = ADH_FIT_MODEL_STATIC;
    s.statics = adh_static_settings_default();
    /* the curve in steps of the contact measure, over the lattice folds
     * (adhere/static.h): measured at Figure 1's material, 3.6 times fewer
     * CPU seconds than the exact curve on N = 1000 (0.32 s, 2.7 on N =
     * 300), within 0.05 nN rms of it (0.09 on N = 300) against a noise of
     * 3.75 nN in the data (docs/fitting.md) */
    s.statics.lattice_skip = 1;
    s.statics.ds_max = 1.0;   /* points every 0.5 nm or closer on the outer branch: the interpolation between them stays below the lattice's noise */
    s.relax = adh_relax_settings_default();
    s.visco = adh_visco_rule_settings_default(adh_material_default().E);
    s.step = 0.05e-9;
    s.margin = 0.25e-9;
    return s;
}

adh_fit_model *adh_fit_model_alloc(const adh_grid *g, const adh_kernel *k, const adh_fit_model_settings *s)
{
    adh_fit_model *fm = calloc(1, sizeof *fm);
    if (!fm)
        return NULL;
    fm->g = g;
    fm->k = k;
    fm->s = *s;
    return fm;
}

static void branch_free(branch *b)
{
    free(b->h0);
    free(b->F);
    if (b->interp)
        gsl_interp_free(b->interp);
    if (b->acc)
        gsl_interp_accel_free(b->acc);
    memset(b, 0, sizeof *b);
}

void adh_fit_model_free(adh_fit_model *fm)
{
    if (!fm)
        return;
    if (fm->w)
        adh_static_free(fm->w);
    free(fm->h0);
    free(fm->F);
    free(fm->stable);
    branch_free(&fm->b[0]);
    branch_free(&fm->b[1]);
    free(fm);
}

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t nc = *cap ? *cap : 256;
    while (nc < need)
        nc *= 2;
    void *q = realloc(*p, nc * size);
    if (!q)
        return -1;
    *p = q;
    *cap = nc;
    return 0;
}

static int curve_push(adh_fit_model *fm, double h0, double F, int stable)
{
    size_t c1 = fm->cap, c2 = fm->cap, c3 = fm->cap;
    if (grow((void **)&fm->h0, &c1, fm->n + 1, sizeof *fm->h0) || grow((void **)&fm->F, &c2, fm->n + 1, sizeof *fm->F) ||
        grow((void **)&fm->stable, &c3, fm->n + 1, sizeof *fm->stable))
        return ADH_ENOMEM;
    fm->cap = c1;
    fm->h0[fm->n] = h0;
    fm->F[fm->n] = F;
    fm->stable[fm->n] = stable;
    fm->n++;
    return ADH_SUCCESS;
}

/* Branch b from the curve's points idx[0..n-1], given in descending h0
 * (ascending when ascending = 1): stored ascending, interpolant built. */
static int branch_set(branch *b, const double *h0, const double *F, const size_t *idx, size_t n, int ascending)
{
    size_t cap = b->cap, cap2 = b->cap;
    if (grow((void **)&b->h0, &cap, n, sizeof *b->h0) || grow((void **)&b->F, &cap2, n, sizeof *b->F))
        return ADH_ENOMEM;
    b->cap = cap;
    for (size_t i = 0; i < n; i++) {
        size_t j = ascending ? idx[i] : idx[n - 1 - i];
        b->h0[i] = h0[j];
        b->F[i] = F[j];
    }
    b->n = n;
    if (b->interp)
        gsl_interp_free(b->interp);
    b->interp = NULL;
    if (n < 2)
        return ADH_SUCCESS;
    b->interp = gsl_interp_alloc(n >= 3 ? gsl_interp_steffen : gsl_interp_linear, n);
    if (!b->acc)
        b->acc = gsl_interp_accel_alloc();
    if (!b->interp || !b->acc)
        return ADH_ENOMEM;
    if (gsl_interp_init(b->interp, b->h0, b->F, n) != GSL_SUCCESS)
        return ADH_ENAN;
    gsl_interp_accel_reset(b->acc);
    return ADH_SUCCESS;
}

/* The force and slope of branch b at h; beyond its ends the end's value
 * with slope 0. */
static void branch_eval(const branch *b, double h, double *F, double *slope)
{
    if (b->n == 0) {
        *F = NAN;
        *slope = 0;
        return;
    }
    if (b->n == 1 || h <= b->h0[0] || h >= b->h0[b->n - 1]) {
        *F = b->n == 1 || h <= b->h0[0] ? b->F[0] : b->F[b->n - 1];
        *slope = 0;
        return;
    }
    *F = gsl_interp_eval(b->interp, b->h0, b->F, h, b->acc);
    *slope = gsl_interp_eval_deriv(b->interp, b->h0, b->F, h, b->acc);
}

/* The static curve's outer and contact branches (see the header). */
static int static_branches(adh_fit_model *fm)
{
    size_t n = fm->n;
    if (n < 2)
        return ADH_ESTALL;   /* a curve of one point: nothing to interpolate */
    size_t *idx = malloc(n * sizeof *idx);
    if (!idx)
        return ADH_ENOMEM;
    size_t kf = 0;
    while (kf + 1 < n && fm->h0[kf + 1] < fm->h0[kf])
        kf++;
    for (size_t i = 0; i <= kf; i++)
        idx[i] = i;
    int rc = branch_set(&fm->b[0], fm->h0, fm->F, idx, kf + 1, 0);
    size_t kmax = kf;
    for (size_t i = kf; i < n; i++)
        if (fm->h0[i] > fm->h0[kmax])
            kmax = i;
    size_t m = 0;
    double low = INFINITY;
    for (size_t i = kmax; i < n; i++)
        if (fm->h0[i] < low) {
            low = fm->h0[i];
            idx[m++] = i;
        }
    if (rc == ADH_SUCCESS)
        rc = branch_set(&fm->b[1], fm->h0, fm->F, idx, m, 0);
    free(idx);
    return rc;
}

static void data_range(const adh_fit_data *d, double offset, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t i = 0; i < d->n; i++) {
        *lo = fmin(*lo, d->x[i] - offset);
        *hi = fmax(*hi, d->x[i] - offset);
    }
}

/* One static curve from start down to end. */
static int trace_static(adh_fit_model *fm, const adh_material *m, const adh_static_settings *ss)
{
    fm->n = 0;
    int rc = adh_static_set(fm->w, m, ss);
    while (rc == ADH_SUCCESS || rc == ADH_CONTINUE) {
        const adh_state *st = adh_static_state(fm->w);
        adh_static_point pt = adh_static_current(fm->w);
        if (curve_push(fm, st->h0, adh_force(fm->g, m, st), pt.stable) != ADH_SUCCESS)
            return ADH_ENOMEM;
        if (rc == ADH_SUCCESS && fm->n > 1)
            return ADH_SUCCESS;
        rc = adh_static_iterate(fm->w);
    }
    return rc;
}

static int eval_static(adh_fit_model *fm, const adh_material *m, double lo, double hi)
{
    if (!fm->w && !(fm->w = adh_static_alloc(fm->g, fm->k)))
        return ADH_ENOMEM;
    adh_static_settings ss = fm->s.statics;
    double step = fm->s.step;
    ss.h0_start = fmax(adh_protocol_auto_start(m, step), step * ceil((hi + fm->s.margin) / step));
    ss.h0_end = fmin(lo - fm->s.margin, -m->z0);
    if (fm->first_points)
        ss.max_points = ADH_FIT_MODEL_POINTS_FACTOR * fm->first_points;
    int rc = trace_static(fm, m, &ss);
    /* The continuation can stall in its last steps towards the end (seen
     * at h0_end = -2.25 nm at Figure 1's material): once the curve is below
     * every point it has all it needs; else it is tried once more to an
     * end a little deeper. */
    if (rc == ADH_ESTALL && fm->n > 1 && fm->h0[fm->n - 1] < lo)
        rc = ADH_SUCCESS;
    if (rc == ADH_ESTALL) {
        ss.h0_end -= 0.37 * step;
        rc = trace_static(fm, m, &ss);
    }
    if (rc == ADH_SUCCESS && !fm->first_points)
        fm->first_points = fm->n;
    if (rc == ADH_EGRID) {   /* the rings word the grid's edge, as in a run */
        const adh_state *st = adh_static_state(fm->w);
        double a = adh_contact_radius(fm->g, st->h, m->z0);
        adh_rings_edge_sentence(fm->g, a, fm->why, sizeof fm->why);
        fm->fix = adh_rings_edge_fix(fm->g, a);
    } else if (rc != ADH_SUCCESS) {
        snprintf(fm->why, sizeof fm->why, "%s", adh_static_why(fm->w, &fm->fix));
    }
    return rc == ADH_SUCCESS ? static_branches(fm) : rc;
}

static int eval_relax(adh_fit_model *fm, const adh_material *m, double lo)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = fm->s.step;
    ps.turns[0] = fm->s.step * floor((lo - fm->s.margin) / fm->s.step);
    adh_run run;
    adh_run_init(&run);
    int rc = adh_runner_rule(&adh_rule_relax, fm->g, fm->k, m, &fm->s.relax, &ps, NULL, NULL, &run);
    if (rc == ADH_SUCCESS && run.interrupted)
        rc = ADH_EINTR;
    if (rc != ADH_SUCCESS && rc != ADH_EINTR && !run.interrupted) {
        snprintf(fm->why, sizeof fm->why, "%s", run.why);
        fm->fix = run.fix;
    }
    size_t *idx = malloc((run.nrows ? run.nrows : 1) * sizeof *idx);
    if (!idx && rc == ADH_SUCCESS)
        rc = ADH_ENOMEM;
    for (size_t i = 0; rc == ADH_SUCCESS && i < run.nrows; i++)
        rc = curve_push(fm, run.rows[i].h0, run.rows[i].F, 1);
    for (int path = 0; rc == ADH_SUCCESS && path < 2; path++) {
        size_t n = 0;
        for (size_t i = 0; i < run.nrows; i++)
            if (run.rows[i].path == path)
                idx[n++] = i;
        rc = branch_set(&fm->b[path], fm->h0, fm->F, idx, n, path == 1);
    }
    free(idx);
    adh_run_free(&run);
    return rc;
}

/* The run's rows of one path, in the base's position, as a branch: the
 * loading path's rows where the base reached below every earlier row, the
 * unloading path's where it rose above every earlier one (the dwell's rows
 * at the turn, and a jump's second row at its base, left out: the branch
 * must be monotone in the base for its interpolant). */
static int time_branch(adh_fit_model *fm, const adh_run *run, int path, size_t *idx)
{
    size_t n = 0;
    double last = path == 0 ? INFINITY : -INFINITY;
    double *base = malloc((run->nrows ? run->nrows : 1) * sizeof *base);
    if (!base)
        return ADH_ENOMEM;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        base[i] = o->base;
        if (o->path != path || !(path == 0 ? o->base < last : o->base > last))
            continue;
        last = o->base;
        idx[n++] = i;
    }
    int rc = branch_set(&fm->b[path], base, fm->F, idx, n, path == 1);
    free(base);
    return rc;
}

/* The physical-time model: one turn at the data's deepest point (the
 * sphere's position there under a spring), the time the data spent in
 * contact being the model's own. */
static int eval_time(adh_fit_model *fm, const adh_material *m, const adh_sls *sls, double offset, double baseline,
                     const adh_fit_data *d)
{
    adh_visco_rule_settings vs = fm->s.visco;
    vs.sls = *sls;
    vs.sls.E0 = m->E;
    vs.s.tol = adh_fit_model_time_tol(vs.s.tol);
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = fm->s.step;
    /* the start is fixed at the first evaluation (adh_fit_model_drive) */
    double lo, hi;
    data_range(d, offset, &lo, &hi);
    if (!fm->time_start)
        fm->time_start = fmax(adh_protocol_auto_start(m, ps.step), ps.step * ceil((hi + fm->s.margin) / ps.step));
    ps.nturns = 1;
    adh_fit_model_drive(fm, m, offset, baseline, d, &ps.start, &ps.turns[0]);
    /* the steps land a row on every point's position: the force there is
     * the integrator's own, not a line between its rows (whose kinks move
     * with the parameters and roughen chi2 on the scale of a step) */
    double *land = malloc(d->n * sizeof *land);
    if (!land)
        return ADH_ENOMEM;
    for (size_t i = 0; i < d->n; i++)
        land[i] = d->x[i] - offset;
    vs.s.land = land;
    vs.s.nland = d->n;
    adh_run run;
    adh_run_init(&run);
    int rc = adh_runner_rule(&adh_rule_visco, fm->g, fm->k, m, &vs, &ps, NULL, NULL, &run);
    free(land);
    if (rc == ADH_SUCCESS && run.interrupted)
        rc = ADH_EINTR;
    if (rc != ADH_SUCCESS && rc != ADH_EINTR && !run.interrupted) {
        snprintf(fm->why, sizeof fm->why, "%s", run.why);
        fm->fix = run.fix;
    }
    for (size_t i = 0; rc == ADH_SUCCESS && i < run.nrows; i++)   /* in the base's position, as the points */
        rc = curve_push(fm, run.rows[i].base, run.rows[i].F, 1);
    size_t *idx = malloc((run.nrows ? run.nrows : 1) * sizeof *idx);
    if (!idx && rc == ADH_SUCCESS)
        rc = ADH_ENOMEM;
    for (int path = 0; rc == ADH_SUCCESS && path < 2; path++)
        rc = time_branch(fm, &run, path, idx);
    free(idx);
    adh_run_free(&run);
    return rc;
}

int adh_fit_model_eval(adh_fit_model *fm, const adh_material *m, double offset, const adh_fit_data *d, double *F,
                       double *slope)
{
    adh_sls sls = fm->s.visco.sls;
    return adh_fit_model_eval_sls(fm, m, &sls, offset, 0.0, d, F, slope);
}

int adh_fit_model_eval_sls(adh_fit_model *fm, const adh_material *m, const adh_sls *sls, double offset,
                           double baseline, const adh_fit_data *d, double *F, double *slope)
{
    double lo, hi;
    data_range(d, offset, &lo, &hi);
    fm->n = 0;
    fm->b[0].n = fm->b[1].n = 0;
    fm->why[0] = '\0';
    fm->fix = 0;
    int relax = fm->s.kind == ADH_FIT_MODEL_RELAX, time = fm->s.kind == ADH_FIT_MODEL_TIME;
    int rc = time ? eval_time(fm, m, sls, offset, baseline, d) : relax ? eval_relax(fm, m, lo)
           : eval_static(fm, m, lo, hi);
    if (rc != ADH_SUCCESS) {
        fm->b[0].n = fm->b[1].n = 0;
        return rc;
    }
    for (size_t i = 0; i < d->n; i++) {
        int which = relax || time ? d->dir[i] < 0 : d->contact[i] != 0;
        double s;
        branch_eval(&fm->b[which], d->x[i] - offset, &F[i], &s);
        if (slope)
            slope[i] = s;
        if (!isfinite(F[i]))
            return ADH_ENAN;
    }
    return ADH_SUCCESS;
}

int adh_fit_model_drive(const adh_fit_model *fm, const adh_material *m, double offset, double baseline,
                        const adh_fit_data *d, double *start, double *turn)
{
    *start = *turn = NAN;
    if (fm->s.kind != ADH_FIT_MODEL_TIME || !fm->time_start || d->n == 0)
        return -1;
    /* one start for every evaluation (the automatic one moves by whole
     * steps with E and A, and with it the time the solid has relaxed
     * before contact: a step in the residuals); a trial whose own is
     * further out (its force not negligible there) starts from its own */
    *start = fmax(fm->time_start, adh_protocol_auto_start(m, fm->s.step));
    size_t deep = 0;
    for (size_t i = 1; i < d->n; i++)
        if (d->x[i] < d->x[deep])
            deep = i;
    double k = fm->s.visco.drive.spring;
    *turn = d->x[deep] - offset + (isfinite(k) ? (d->F[deep] - baseline) / k : 0.0);
    return 0;
}

const char *adh_fit_model_why(const adh_fit_model *fm, unsigned *fix)
{
    if (fix)
        *fix = fm->fix;
    return fm->why;
}

size_t adh_fit_model_branch(const adh_fit_model *fm, int which, const double **h0, const double **F)
{
    const branch *b = &fm->b[which != 0];
    *h0 = b->h0;
    *F = b->F;
    return b->n;
}

size_t adh_fit_model_curve(const adh_fit_model *fm, const double **h0, const double **F, const int **stable)
{
    *h0 = fm->h0;
    *F = fm->F;
    *stable = fm->stable;
    return fm->n;
}

double adh_fit_model_time_tol(double tol)
{
    return fmin(tol, ADH_FIT_MODEL_TIME_TOL);
}
