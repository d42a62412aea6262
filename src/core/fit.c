#include "adhere/fit.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/visco.h"

static const char *const names[ADH_FIT_NPARAM] = { "E", "A", "z0", "R", "offset", "baseline", "Einf", "tau" };

/* The model's own limits on E, A, z0, R (adh_material_validate's). */
static const double lim_lo[4] = { 1e3, 1e-24, 1e-12, 1e-9 }, lim_hi[4] = { 1e13, 1e-15, 1e-7, 10.0 };

/* Searched in log(p / start): E, A, z0, R and the solid's Einf (as Einf/E0)
 * and tau; offset and baseline linearly. */
static int is_log(int k)
{
    return k <= ADH_FIT_R || k >= ADH_FIT_EINF;
}

/* A residual that no trial point can beat: the point is refused (outside
 * the search range, or the model failed there). In units of the force
 * scale, per point. */
#define PENALTY 1e3

const char *adh_fit_param_name(adh_fit_param p)
{
    return p < ADH_FIT_NPARAM ? names[p] : "?";
}

int adh_fit_param_parse(const char *name, adh_fit_param *p)
{
    if (strcasecmp(name, "E0") == 0) {   /* the solid's name for the material's E */
        *p = ADH_FIT_E;
        return 0;
    }
    for (int i = 0; i < ADH_FIT_NPARAM; i++)
        if (strcasecmp(name, names[i]) == 0) {
            *p = (adh_fit_param)i;
            return 0;
        }
    return -1;
}

adh_fit_settings adh_fit_settings_default(void)
{
    adh_fit_settings s;
    memset(&s, 0, sizeof s);
    s.free = 1u << ADH_FIT_E | 1u << ADH_FIT_A;
    s.start = adh_material_default();
    s.model = adh_fit_model_settings_default();
    s.Einf = s.model.visco.sls.Einf;
    s.tau = s.model.visco.sls.tau;
    s.max_iter = 50;
    s.xtol = 1e-4;
    s.fd_step = 1e-2;
    s.range = 100;
    return s;
}

struct adh_fit {
    const adh_fit_data *d;
    adh_fit_settings s;
    adh_fit_model *fm;
    size_t p;                       /* free parameters */
    int idx[ADH_FIT_NPARAM];        /* which, in order */
    double lo[ADH_FIT_NPARAM], hi[ADH_FIT_NPARAM];   /* the scaled search range */
    double fscale;                  /* |F_JKR| at the start, N */
    double *Fm, *slope;             /* the model at the last evaluation */
    double *cache_r, *cache_slope, cache_theta[ADH_FIT_NPARAM];
    int cache_ok;
    double *best_r, *best_F, best_chi2, best_theta[ADH_FIT_NPARAM];
    size_t evals, failed, iters;
    int stop, model_status;
    char model_why[400];            /* the last failed evaluation's reason (adh_fit_model_why) */
    unsigned model_fix;
    double xcur[ADH_FIT_NPARAM], se[ADH_FIT_NPARAM];   /* the accepted point, its standard errors */
    int have_se, converged;
    int jac_whole;                  /* the workspace's J has every column: no stop cut it short */
    struct timespec t0;
};

/* Every parameter's value (SI) at scaled point theta of the free ones. */
static void values_of(const adh_fit *f, const double *theta, double *v)
{
    const adh_material *m = &f->s.start;
    v[ADH_FIT_E] = m->E;
    v[ADH_FIT_A] = m->A;
    v[ADH_FIT_Z0] = m->z0;
    v[ADH_FIT_R] = m->R;
    v[ADH_FIT_OFFSET] = f->s.offset;
    v[ADH_FIT_BASELINE] = f->s.baseline;
    v[ADH_FIT_EINF] = f->s.Einf;
    v[ADH_FIT_TAU] = f->s.tau;
    for (size_t j = 0; j < f->p; j++) {
        int k = f->idx[j];
        if (k == ADH_FIT_EINF)   /* E (before it in idx) is set: the ratio Einf/E0 is searched */
            v[k] = v[ADH_FIT_E] * (f->s.Einf / m->E) * exp(theta[j]);
        else if (is_log(k))
            v[k] *= exp(theta[j]);
        else if (k == ADH_FIT_OFFSET)
            v[k] += theta[j] * m->z0;
        else
            v[k] += theta[j] * f->fscale;
    }
}

static double elapsed(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0->tv_sec) + 1e-9 * (double)(t.tv_nsec - t0->tv_nsec);
}

static void report(adh_fit *f, const double *theta, double chi2, int jac)
{
    adh_fit_progress pr = { .evals = f->evals, .iterations = f->iters, .chi2 = chi2,
                            .best_chi2 = f->best_chi2, .jacobian = jac };
    values_of(f, theta, pr.value);
    int stop = f->s.cancel && *f->s.cancel;
    if (f->s.progress && f->s.progress(&pr, f->s.ctx))
        stop = 1;
    if (stop)
        f->stop = 1;
}

/* The scaled residuals r at theta (and the model's slopes). 0; -1 when the
 * point is refused (out of range, or the model failed: r = PENALTY). */
static int residuals(adh_fit *f, const double *theta, double *r, double *slope, int jac)
{
    const adh_fit_data *d = f->d;
    int refused = 0;
    for (size_t j = 0; j < f->p; j++)
        refused |= !(theta[j] >= f->lo[j] && theta[j] <= f->hi[j]);
    double v[ADH_FIT_NPARAM], chi2 = INFINITY;
    values_of(f, theta, v);
    adh_sls sls = { v[ADH_FIT_E], v[ADH_FIT_EINF], v[ADH_FIT_TAU] };
    char msg[200];
    /* a solid outside its limits (E0 or Einf past 1 TPa, Einf below a
     * fixed Einf's E0): outside the search range */
    if (f->s.model.kind == ADH_FIT_MODEL_TIME && adh_sls_validate(&sls, msg, sizeof msg) != ADH_SUCCESS)
        refused = 1;
    if (!refused) {
        adh_material m = { v[ADH_FIT_E], v[ADH_FIT_A], v[ADH_FIT_Z0], v[ADH_FIT_R] };
        f->evals++;
        int rc = adh_fit_model_eval_sls(f->fm, &m, &sls, v[ADH_FIT_OFFSET], v[ADH_FIT_BASELINE], d, f->Fm, slope);
        if (rc != ADH_SUCCESS) {
            f->failed++;
            refused = 1;
            if (rc == ADH_EINTR) {
                f->stop = 1;
            } else {
                f->model_status = rc;
                snprintf(f->model_why, sizeof f->model_why, "%s", adh_fit_model_why(f->fm, &f->model_fix));
            }
        }
    }
    if (!refused) {
        chi2 = 0;
        for (size_t i = 0; i < d->n; i++) {
            double res = d->F[i] - v[ADH_FIT_BASELINE] - f->Fm[i];
            r[i] = res / f->fscale;
            chi2 += res * res;
        }
        if (!jac && chi2 < f->best_chi2) {   /* accepted or trial points: J is held at them */
            f->best_chi2 = chi2;
            memcpy(f->best_theta, theta, f->p * sizeof *theta);
            memcpy(f->best_F, f->Fm, d->n * sizeof *f->Fm);
            for (size_t i = 0; i < d->n; i++)
                f->best_r[i] = r[i] * f->fscale;
        }
    } else {
        for (size_t i = 0; i < d->n; i++)
            r[i] = PENALTY;
        if (slope)
            memset(slope, 0, d->n * sizeof *slope);
    }
    if (!refused || f->evals)
        report(f, theta, chi2, jac);
    return refused ? -1 : 0;
}

static int gsl_f(const gsl_vector *x, void *params, gsl_vector *fv)
{
    adh_fit *f = params;
    if (f->stop)
        return GSL_EBADFUNC;
    /* a trial step shorter than ADH_FIT_STEP_SE standard errors in every
     * parameter: the optimum is as near as the data can tell (no model
     * evaluation is spent on it) */
    int near = f->have_se;
    for (size_t j = 0; near && j < f->p; j++)
        near = fabs(x->data[j] - f->xcur[j]) < ADH_FIT_STEP_SE * f->se[j];
    if (near) {
        f->converged = 1;
        return GSL_EBADFUNC;
    }
    int rc = residuals(f, x->data, f->cache_r, f->cache_slope, 0);
    memcpy(f->cache_theta, x->data, f->p * sizeof *x->data);
    f->cache_ok = rc == 0;
    memcpy(fv->data, f->cache_r, f->d->n * sizeof *fv->data);
    return f->stop ? GSL_EBADFUNC : GSL_SUCCESS;
}

/* The Jacobian: forward differences for E, A, z0, R, Einf, tau (backward where the
 * forward point is refused), exact for the offset and the baseline. */
static int gsl_df(const gsl_vector *x, void *params, gsl_matrix *J)
{
    adh_fit *f = params;
    size_t n = f->d->n;
    if (!f->cache_ok || memcmp(f->cache_theta, x->data, f->p * sizeof *x->data) != 0) {
        memcpy(f->cache_theta, x->data, f->p * sizeof *x->data);
        f->cache_ok = residuals(f, x->data, f->cache_r, f->cache_slope, 0) == 0;
    }
    double *rh = malloc(n * sizeof *rh), theta[ADH_FIT_NPARAM];
    f->jac_whole = 0;
    if (!rh)
        return GSL_ENOMEM;
    for (size_t j = 0; j < f->p && !f->stop; j++) {
        int k = f->idx[j];
        for (size_t i = 0; i < n; i++) {
            if (k == ADH_FIT_OFFSET)
                gsl_matrix_set(J, i, j, f->cache_slope[i] * f->s.start.z0 / f->fscale);
            else if (k == ADH_FIT_BASELINE)
                gsl_matrix_set(J, i, j, -1.0);
        }
        if (!is_log(k))
            continue;
        double h = f->s.model.kind == ADH_FIT_MODEL_TIME ? fmin(f->s.fd_step, ADH_FIT_MODEL_TIME_FD_STEP)
                                                         : f->s.fd_step;
        memcpy(theta, x->data, f->p * sizeof *theta);
        theta[j] += h;
        if (residuals(f, theta, rh, NULL, 1) != 0 && !f->stop) {
            h = -h;
            theta[j] = x->data[j] + h;
            if (residuals(f, theta, rh, NULL, 1) != 0)
                h = 0;
        }
        for (size_t i = 0; i < n; i++)
            gsl_matrix_set(J, i, j, h != 0 && f->cache_ok ? (rh[i] - f->cache_r[i]) / h : 0.0);
    }
    free(rh);
    f->jac_whole = !f->stop;
    return f->stop ? GSL_EBADFUNC : GSL_SUCCESS;
}

static void search_range(adh_fit *f)
{
    const adh_material *m = &f->s.start;
    double start[4] = { m->E, m->A, m->z0, m->R };
    for (size_t j = 0; j < f->p; j++) {
        int k = f->idx[j];
        if (k <= ADH_FIT_R) {
            f->lo[j] = fmax(-log(f->s.range), log(lim_lo[k] / start[k]));
            f->hi[j] = fmin(log(f->s.range), log(lim_hi[k] / start[k]));
        } else if (k == ADH_FIT_EINF) {   /* Einf >= E0: the ratio from 1; its 1 TPa as E0's (refused beyond) */
            f->lo[j] = fmin(0.0, -log(f->s.Einf / m->E));
            f->hi[j] = log(f->s.range);
        } else if (k == ADH_FIT_TAU) {   /* tau > 0, at most 1e6 s (adh_sls_validate's) */
            f->lo[j] = -log(f->s.range);
            f->hi[j] = fmin(log(f->s.range), log(1e6 / f->s.tau));
        } else {   /* 10 z0 either way; the baseline as large as the pull-off */
            f->lo[j] = -(k == ADH_FIT_OFFSET ? 10.0 : 1.0);
            f->hi[j] = -f->lo[j];
        }
    }
}

adh_fit *adh_fit_alloc(const adh_grid *g, const adh_kernel *k, const adh_fit_data *d, const adh_fit_settings *s,
                       int *status)
{
    *status = ADH_EINVAL;
    adh_fit *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->d = d;
    f->s = *s;
    for (int i = 0; i < ADH_FIT_NPARAM; i++)
        if (s->free & 1u << i)
            f->idx[f->p++] = i;
    if (f->p == 0 || d->n <= f->p) {
        free(f);
        return NULL;
    }
    *status = ADH_ENOMEM;
    f->fscale = fabs(adh_jkr_pulloff(&s->start));
    f->s.model.statics.cancel = s->cancel;
    f->s.model.relax.cancel = s->cancel;
    f->s.model.visco.s.cancel = s->cancel;
    f->fm = adh_fit_model_alloc(g, k, &f->s.model);
    f->Fm = malloc(d->n * sizeof *f->Fm);
    f->slope = malloc(d->n * sizeof *f->slope);
    f->cache_r = malloc(d->n * sizeof *f->cache_r);
    f->cache_slope = malloc(d->n * sizeof *f->cache_slope);
    f->best_r = malloc(d->n * sizeof *f->best_r);
    f->best_F = malloc(d->n * sizeof *f->best_F);
    if (!f->fm || !f->Fm || !f->slope || !f->cache_r || !f->cache_slope || !f->best_r || !f->best_F) {
        adh_fit_free(f);
        return NULL;
    }
    search_range(f);
    *status = ADH_SUCCESS;
    return f;
}

void adh_fit_free(adh_fit *f)
{
    if (!f)
        return;
    adh_fit_model_free(f->fm);
    free(f->Fm);
    free(f->slope);
    free(f->cache_r);
    free(f->cache_slope);
    free(f->best_r);
    free(f->best_F);
    free(f);
}

size_t adh_fit_best_curve(adh_fit *f, const double **h0, const double **F, const int **stable)
{
    double v[ADH_FIT_NPARAM];
    values_of(f, f->best_theta, v);
    adh_material m = { v[ADH_FIT_E], v[ADH_FIT_A], v[ADH_FIT_Z0], v[ADH_FIT_R] };
    adh_sls sls = { v[ADH_FIT_E], v[ADH_FIT_EINF], v[ADH_FIT_TAU] };
    if (adh_fit_model_eval_sls(f->fm, &m, &sls, v[ADH_FIT_OFFSET], v[ADH_FIT_BASELINE], f->d, f->Fm, NULL) !=
        ADH_SUCCESS)
        return 0;
    return adh_fit_model_curve(f->fm, h0, F, stable);
}

const double *adh_fit_residuals(const adh_fit *f)
{
    return f->best_r;
}

const double *adh_fit_model_forces(const adh_fit *f)
{
    return f->best_F;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The force's resolution: the smallest nonzero step between neighbours
 * (the quantum of forces written to a few decimals; on unrounded data a
 * step far below the noise). 0 when every force is the same. */
static double resolution(const adh_fit_data *d)
{
    double q = INFINITY;
    for (size_t i = 1; i < d->n; i++) {
        double step = fabs(d->F[i] - d->F[i - 1]);
        if (step > 0)
            q = fmin(q, step);
    }
    return isfinite(q) ? q : 0;
}

double adh_fit_noise(const adh_fit_data *d)
{
    double *a = malloc((d->n ? d->n : 1) * sizeof *a);
    size_t m = 0;
    if (!a)
        return NAN;
    for (size_t i = 1; i + 1 < d->n; i++) {
        int same = d->seg[i - 1] == d->seg[i] && d->seg[i] == d->seg[i + 1] &&
                   d->contact[i - 1] == d->contact[i] && d->contact[i] == d->contact[i + 1];
        if (same)
            a[m++] = fabs(d->F[i + 1] - 2 * d->F[i] + d->F[i - 1]);
    }
    double s = NAN;
    if (m >= 3) {
        qsort(a, m, sizeof *a, cmp_double);
        double med = m % 2 ? a[m / 2] : 0.5 * (a[m / 2 - 1] + a[m / 2]);
        s = 1.4826 * med / sqrt(6.0);
        /* forces written more coarsely than their noise (uN with two
         * decimals) mostly repeat: the median second difference is 0, yet
         * the rounding is a noise of its own, uniform over the step */
        s = fmax(s, resolution(d) / sqrt(12.0));
    }
    free(a);
    return s;
}

/* The covariance of log Einf, not of the ratio searched: log Einf is
 * log E0 + log(Einf/E0), so with E free its row and column gain E's
 * (cov' = T cov T^T, T the identity with a 1 at (Einf, E)). */
static void einf_covariance(const adh_fit *f, gsl_matrix *cov)
{
    int je = -1, jr = -1;
    for (size_t j = 0; j < f->p; j++) {
        je = f->idx[j] == ADH_FIT_E ? (int)j : je;
        jr = f->idx[j] == ADH_FIT_EINF ? (int)j : jr;
    }
    if (je < 0 || jr < 0)
        return;
    double cee = gsl_matrix_get(cov, je, je), cer = gsl_matrix_get(cov, je, jr);
    for (size_t b = 0; b < f->p; b++) {   /* the row (and column) of Einf: cov(r, b) + cov(E, b) */
        if ((int)b == jr)
            continue;
        double c = gsl_matrix_get(cov, jr, b) + gsl_matrix_get(cov, je, b);
        gsl_matrix_set(cov, jr, b, c);
        gsl_matrix_set(cov, b, jr, c);
    }
    gsl_matrix_set(cov, jr, jr, gsl_matrix_get(cov, jr, jr) + 2 * cer + cee);
}

/* The data's time in contact at the drive's speeds: the travel between
 * neighbouring points of a segment both past its jump, and the dwell. */
static double contact_time(const adh_fit *f)
{
    const adh_fit_data *d = f->d;
    const adh_visco_drive *dr = &f->s.model.visco.drive;
    double t = dr->dwell;
    for (size_t i = 0; i + 1 < d->n; i++)
        if (d->seg[i] == d->seg[i + 1] && d->contact[i] && d->contact[i + 1])
            t += fabs(d->x[i + 1] - d->x[i]) / (d->dir[i] > 0 ? dr->speed_in : dr->speed_out);
    /* the turn: the approach's deepest point and the retraction's first */
    for (size_t i = 0; i + 1 < d->n; i++)
        if (d->seg[i] != d->seg[i + 1] && d->contact[i] && d->contact[i + 1])
            t += fabs(d->x[i + 1] - d->x[i]) / dr->speed_out;
    return t;
}

/* Standard errors and correlations from J at the best point, scaled by the
 * residual variance; the flags. */
static void statistics(adh_fit *f, gsl_multifit_nlinear_workspace *w, adh_fit_result *res)
{
    size_t p = f->p, n = f->d->n;
    /* a J that a signal cut short holds a column of the refused point's
     * penalty (or none): its errors were garbage, A +- 7e-28 J (7e-7 %)
     * from a fit stopped in its first Jacobian; they stay nan */
    if (!f->jac_whole)
        return;
    gsl_matrix *cov = gsl_matrix_alloc(p, p);
    double s2 = res->chi2 / (f->fscale * f->fscale) / (double)(n - p);
    if (cov) {
        gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cov);
        einf_covariance(f, cov);
    }
    for (size_t a = 0; a < p; a++) {
        int ka = f->idx[a];
        double va = cov ? gsl_matrix_get(cov, a, a) * s2 : NAN;
        double st = sqrt(va);   /* in scaled units */
        double scale = is_log(ka) ? res->value[ka] : ka == ADH_FIT_OFFSET ? f->s.start.z0 : f->fscale;
        res->se[ka] = isfinite(st) ? st * scale : NAN;
        if (!(isfinite(st) && st < 1.0))
            res->flags[ka] |= ADH_FIT_UNDETERMINED;
        double span = f->hi[a] - f->lo[a], th = f->best_theta[a];
        if (th - f->lo[a] < 1e-3 * span || f->hi[a] - th < 1e-3 * span)
            res->flags[ka] |= ADH_FIT_AT_LIMIT;
        for (size_t b = 0; b < p; b++) {
            int kb = f->idx[b];
            double c = cov ? gsl_matrix_get(cov, a, b) /
                             sqrt(gsl_matrix_get(cov, a, a) * gsl_matrix_get(cov, b, b)) : NAN;
            res->corr[ka][kb] = c;
        }
    }
    gsl_matrix_free(cov);
    unsigned slow = 1u << ADH_FIT_E | 1u << ADH_FIT_TAU;
    if (f->s.model.kind == ADH_FIT_MODEL_TIME && (f->s.free & slow) == slow &&
        res->value[ADH_FIT_TAU] > ADH_FIT_SLOW_RATIO * res->contact_time) {
        res->flags[ADH_FIT_E] |= ADH_FIT_SLOW;
        res->flags[ADH_FIT_TAU] |= ADH_FIT_SLOW;
    }
}

static void fill_result(adh_fit *f, adh_fit_result *res)
{
    memset(res, 0, sizeof *res);
    res->free = f->s.free;
    res->n = f->d->n;
    res->nfree = f->p;
    for (int i = 0; i < ADH_FIT_NPARAM; i++) {
        res->se[i] = NAN;
        for (int j = 0; j < ADH_FIT_NPARAM; j++)
            res->corr[i][j] = NAN;
    }
    values_of(f, f->best_theta, res->value);
    res->best = (adh_material){ res->value[ADH_FIT_E], res->value[ADH_FIT_A], res->value[ADH_FIT_Z0],
                                res->value[ADH_FIT_R] };
    res->chi2 = f->best_chi2;
    adh_fit_model_drive(f->fm, &res->best, res->value[ADH_FIT_OFFSET], res->value[ADH_FIT_BASELINE], f->d,
                        &res->start, &res->turn);
    res->creep_rate = f->s.model.kind == ADH_FIT_MODEL_TIME
                    ? (1 / res->value[ADH_FIT_E] - 1 / res->value[ADH_FIT_EINF]) / res->value[ADH_FIT_TAU] : NAN;
    res->contact_time = f->s.model.kind == ADH_FIT_MODEL_TIME ? contact_time(f) : NAN;
    res->rms = sqrt(f->best_chi2 / (double)f->d->n);
    res->noise = adh_fit_noise(f->d);
    res->chi2_red = f->best_chi2 / (res->noise * res->noise * (double)(f->d->n - f->p));
    res->evals = f->evals;
    res->failed = f->failed;
    res->model_status = f->model_status;
    snprintf(res->model_why, sizeof res->model_why, "%s", f->model_why);
    res->model_fix = f->model_fix;
    res->iterations = f->iters;
    res->seconds = elapsed(&f->t0);
}

/* The accepted point and the standard errors the data's own scatter
 * gives there (from J, and the noise, not the residuals: far from the
 * optimum they would be inflated by the misfit), for the test of the next
 * trial step. The test is armed only once an accepted step was itself
 * shorter than one standard error in every parameter: near the optimum,
 * not where the trust region shrank around a model failure. */
static void accept(adh_fit *f, gsl_multifit_nlinear_workspace *w, const gsl_vector *xold)
{
    size_t p = f->p;
    const gsl_vector *x = gsl_multifit_nlinear_position(w);
    f->have_se = 0;
    gsl_matrix *cov = gsl_matrix_alloc(p, p);
    double noise = adh_fit_noise(f->d) / f->fscale;
    int ok = cov && xold && isfinite(noise) &&
             gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cov) == GSL_SUCCESS;
    for (size_t j = 0; ok && j < p; j++) {
        f->se[j] = sqrt(gsl_matrix_get(cov, j, j)) * noise;
        ok = isfinite(f->se[j]) && fabs(gsl_vector_get(x, j) - gsl_vector_get(xold, j)) < f->se[j];
    }
    for (size_t j = 0; j < p; j++)
        f->xcur[j] = gsl_vector_get(x, j);
    f->have_se = ok;
    gsl_matrix_free(cov);
}

/* One Levenberg-Marquardt search from theta0 (scaled): the status, why it
 * stopped in *ginfo, and its workspace (its J at the last accepted point)
 * in *wout, or NULL when out of memory. */
static int lm_search(adh_fit *f, const double *theta0, gsl_multifit_nlinear_workspace **wout, int *ginfo)
{
    size_t n = f->d->n, p = f->p, iters0 = f->iters;   /* each search its own max_iter */
    f->stop = f->converged = f->have_se = f->jac_whole = 0;
    f->cache_ok = 0;
    *ginfo = 0;
    gsl_multifit_nlinear_fdf fdf = { .f = gsl_f, .df = gsl_df, .fvv = NULL, .n = n, .p = p, .params = f };
    gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
    /* Levenberg-Marquardt; the parameters are already scaled (log of a
     * factor, z0, the pull-off), so the trust region is a ball in them
     * (Levenberg's D = I): measured on Figure 1's curve from a start a
     * factor 3 off, 24 evaluations against 50 with More's scaling, and the
     * dogleg methods with More's stopped at a false point (docs/fitting.md) */
    par.trs = gsl_multifit_nlinear_trs_lm;
    par.scale = gsl_multifit_nlinear_scale_levenberg;
    gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, n, p);
    gsl_vector *x = gsl_vector_calloc(p), *xold = gsl_vector_alloc(p);
    *wout = w;
    if (!w || !x || !xold) {
        gsl_vector_free(x);
        gsl_vector_free(xold);
        return ADH_ENOMEM;
    }
    for (size_t j = 0; j < p; j++)
        gsl_vector_set(x, j, theta0[j]);
    int status = ADH_CONTINUE, gs = gsl_multifit_nlinear_init(x, &fdf, w);
    if (gs != GSL_SUCCESS || !isfinite(f->best_chi2))
        status = f->stop ? ADH_EINTR : f->model_status != ADH_SUCCESS ? f->model_status : ADH_EINVAL;
    else
        accept(f, w, NULL);
    while (status == ADH_CONTINUE) {
        if (f->iters - iters0 == f->s.max_iter) {
            status = ADH_EMAXITER;
            break;
        }
        gsl_vector_memcpy(xold, gsl_multifit_nlinear_position(w));
        gs = gsl_multifit_nlinear_iterate(w);
        f->iters++;
        if (f->converged) {   /* the next step would be below the data's resolution */
            *ginfo = 4;
            status = ADH_SUCCESS;
            break;
        }
        if (f->stop) {
            status = ADH_EINTR;
            break;
        }
        if (gs == GSL_ENOPROG) {   /* no step lowers chi2 any more: a minimum, or a limit */
            *ginfo = 3;
            status = ADH_SUCCESS;
            break;
        }
        if (gs != GSL_SUCCESS) {
            status = ADH_EINVAL;
            break;
        }
        double dmax = 0;
        const gsl_vector *xn = gsl_multifit_nlinear_position(w);
        for (size_t j = 0; j < p; j++)
            dmax = fmax(dmax, fabs(gsl_vector_get(xn, j) - gsl_vector_get(xold, j)));
        int info = 0;
        gsl_multifit_nlinear_test(1e-300, 1e-8, 0, &info, w);
        accept(f, w, xold);
        if (dmax < f->s.xtol || info == 2) {
            *ginfo = info == 2 ? 2 : 1;
            status = ADH_SUCCESS;
        }
    }
    gsl_vector_free(x);
    gsl_vector_free(xold);
    return status;
}

int adh_fit_run(adh_fit *f, adh_fit_result *res)
{
    clock_gettime(CLOCK_MONOTONIC, &f->t0);
    f->best_chi2 = INFINITY;
    f->evals = f->failed = f->iters = 0;
    f->model_status = ADH_SUCCESS;
    f->model_why[0] = '\0';
    f->model_fix = 0;
    memset(f->best_theta, 0, sizeof f->best_theta);
    double theta0[ADH_FIT_NPARAM] = { 0 };
    int ginfo = 0;
    gsl_multifit_nlinear_workspace *w = NULL;
    int status = lm_search(f, theta0, &w, &ginfo);
    /* The physical-time model's chi2 is rough on the scale of its steps
     * (a jump crossing a point moves that point's force by the jump), and
     * the search stops in a pocket of it: on a curve of the round trip's
     * kind (docs/fitting.md) from (1.3 E0, 0.8 A, 0.83 Einf, 0.7 tau) at
     * chi2 2.4 noise^2 above the optimum found from the truth, E0 3.2
     * standard errors off. A new search from the best point (a new trust
     * region, a new J) until one lowers chi2 by less than the noise^2 */
    /* The restarts are probes of a converged fit: one that runs out of its
     * iterations (or fails) leaves the fit converged at a point at least
     * as good; the fit says why the search that found its best point
     * stopped. Only an interrupt (or no memory) is the fit's. */
    double noise = adh_fit_noise(f->d);
    for (int again = 0; f->s.model.kind == ADH_FIT_MODEL_TIME && again < ADH_FIT_RESTARTS && status == ADH_SUCCESS &&
                        isfinite(noise); again++) {
        double before = f->best_chi2;
        memcpy(theta0, f->best_theta, sizeof theta0);
        gsl_multifit_nlinear_free(w);
        int info, st = lm_search(f, theta0, &w, &info);
        if (f->best_chi2 < before)
            ginfo = info;
        if (st == ADH_EINTR || st == ADH_ENOMEM)
            status = st;
        if (st != ADH_SUCCESS || before - f->best_chi2 < noise * noise)
            break;
    }
    fill_result(f, res);
    res->gsl_info = ginfo;
    if (w && isfinite(f->best_chi2))
        statistics(f, w, res);
    res->status = w ? status : ADH_ENOMEM;
    gsl_multifit_nlinear_free(w);
    return res->status;
}
