#include "adhere/models.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>

#include "adhere/status.h"

void adh_material_derive(const adh_material *m, adh_derived *d)
{
    d->gamma = adh_material_gamma(m);
    d->sigma = adh_material_sigma(m);
    d->mu = cbrt(4.0) * pow(d->sigma, 2.0 / 3.0);
    d->Estar = m->E / 2.0;
    d->F_jkr = adh_jkr_pulloff(m);
    d->F_dmt = adh_dmt_pulloff(m);
    d->h_star = adh_jump_separation(m);
}

double adh_rigid_force(const adh_material *m, double h0)
{
    /* Rigid spheres cannot reach h0 <= 0: eq 22 has no value there. */
    if (!(h0 > 0))
        return NAN;
    double s6 = pow(m->z0 / h0, 6.0);
    return m->A * m->R / (6.0 * h0 * h0) * (s6 / 4.0 - 1.0);
}

double adh_bulge(const adh_material *m, double h)
{
    return -m->A * sqrt(2.0 * m->R) / (8.0 * m->E * pow(h, 2.5));
}

double adh_bulge_position(const adh_material *m, double h)
{
    return h - adh_bulge(m, h);
}

double adh_jump_separation(const adh_material *m)
{
    return pow(3.0 * m->A * sqrt(2.0 * m->R) / (8.0 * m->E), 2.0 / 7.0);
}

/* Johnson's reduced modulus is E* = E/2 with the paper's E (eq 12). */
double adh_hertz_force(const adh_material *m, double delta)
{
    if (delta <= 0)
        return 0;
    return 4.0 / 3.0 * (m->E / 2.0) * sqrt(m->R) * pow(delta, 1.5);
}

void adh_jkr(const adh_material *m, double a, double *F, double *overlap)
{
    /* The paper's gamma = -W(z0) is the whole work of adhesion of the LJ law, so
     * it is JKR's w directly, and the pull-off below is -(3/2) pi gamma R (eq 1). */
    double Es = m->E / 2.0, w = adh_material_gamma(m);
    double a3 = a * a * a;
    if (F)
        *F = 4.0 * Es * a3 / (3.0 * m->R) - sqrt(8.0 * M_PI * w * Es * a3);
    if (overlap)
        *overlap = a * a / m->R - sqrt(2.0 * M_PI * w * a / Es);
}

static double jkr_overlap_less(double a, void *ctx)
{
    const double *arg = ctx; /* the material's E, R, gamma and the overlap */
    double Es = arg[0] / 2.0;
    return a * a / arg[1] - sqrt(2.0 * M_PI * arg[2] * a / Es) - arg[3];
}

/* JKR's overlap falls with a up to the fold a_f and rises past it: the
 * stable branch's root is bracketed between a_f and the first doubling of
 * a_f past it, and Brent's method (GSL) finds it to a few roundings. */
double adh_jkr_radius(const adh_material *m, double overlap)
{
    if (isnan(overlap) || overlap == INFINITY)   /* no answer; a contact without bound */
        return overlap;
    double arg[4] = { m->E, m->R, adh_material_gamma(m), overlap };
    double lo = cbrt(M_PI * arg[2] * m->R * m->R / (8.0 * (m->E / 2.0))), hi = lo;
    if (!(jkr_overlap_less(lo, arg) < 0))
        return 0.0;
    for (int i = 0; i < 1100 && jkr_overlap_less(hi, arg) < 0; i++)
        hi *= 2;
    if (!(jkr_overlap_less(hi, arg) >= 0))
        return NAN;
    gsl_function f = { jkr_overlap_less, arg };
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs || gsl_root_fsolver_set(rs, &f, lo, hi) != GSL_SUCCESS) {
        gsl_root_fsolver_free(rs);
        return NAN;
    }
    int rc = GSL_CONTINUE;
    for (int i = 0; i < 200 && rc == GSL_CONTINUE; i++) {
        if (gsl_root_fsolver_iterate(rs) != GSL_SUCCESS)
            break;
        rc = gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs), 0, 4 * DBL_EPSILON);
    }
    double a = gsl_root_fsolver_root(rs);
    gsl_root_fsolver_free(rs);
    return a;
}

double adh_dmt_force(const adh_material *m, double delta)
{
    return adh_hertz_force(m, delta) + adh_dmt_pulloff(m);
}

double adh_jkr_pulloff(const adh_material *m)
{
    return -1.5 * M_PI * adh_material_gamma(m) * m->R;
}

double adh_dmt_pulloff(const adh_material *m)
{
    return -2.0 * M_PI * adh_material_gamma(m) * m->R;
}

double adh_edge_zone(const adh_material *m)
{
    return 243.0 * M_PI * M_PI / 128.0 * m->E * pow(m->z0, 4) / m->A;
}

/* a from a0 to a1 (inclusive) in k >= 2 even steps into c at index i0 */
static int sample_span(const adh_material *m, adh_radius_model fn, const void *ctx, double a0,
                       double a1, size_t k, size_t i0, adh_model_curve *c)
{
    for (size_t j = 0; j < k; j++) {
        double a = a0 + (a1 - a0) * (double)j / (double)(k - 1), F, ov;
        int rc = fn(m, ctx, a, &F, &ov);
        if (rc != ADH_SUCCESS)
            return rc;
        c->h0[i0 + j] = m->z0 - ov;
        c->F[i0 + j] = F;
    }
    return ADH_SUCCESS;
}

int adh_model_sample(const adh_material *m, adh_radius_model fn, const void *ctx, double a_fold,
                     double a_pull, double h0_min, adh_model_curve *c)
{
    const size_t N = ADH_MODEL_POINTS;
    c->n = c->n_load = 0;
    if (!isfinite(h0_min) || !(a_fold >= 0) || !isfinite(a_pull))
        return ADH_EINVAL;
    double target = m->z0 - h0_min, F, ov;
    int rc;
    /* no fold (a_fold = 0): the overlap falls to 0 with a */
    if (a_fold > 0) {
        if ((rc = fn(m, ctx, a_fold, &F, &ov)) != ADH_SUCCESS)
            return rc;
    } else {
        ov = 0;
    }
    if (!(ov < target))
        return ADH_SUCCESS; /* the whole curve is deeper than h0_min */
    /* the deepest radius: overlap(a) = target, bracketed by doubling */
    double lo = a_fold, hi = a_fold > 0 ? a_fold : cbrt(M_PI * adh_material_gamma(m) * m->R * m->R / m->E);
    for (int k = 0;; k++) {
        if ((rc = fn(m, ctx, hi, &F, &ov)) != ADH_SUCCESS)
            return rc;
        if (ov >= target)
            break;
        lo = hi;
        hi *= 2;
        if (k > 200)
            return ADH_EMAXITER;
    }
    for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if ((rc = fn(m, ctx, mid, &F, &ov)) != ADH_SUCCESS)
            return rc;
        if (ov < target)
            lo = mid;
        else
            hi = mid;
    }
    double a_max = lo > 0 ? lo : hi;
    if (!(a_fold > 0))
        a_fold = a_max / (double)N;
    if (a_pull <= a_fold || a_pull >= a_max) {
        /* all on one side of the pull-off */
        if ((rc = sample_span(m, fn, ctx, a_max, a_fold, N, 0, c)) != ADH_SUCCESS)
            return rc;
        c->n = N;
        c->n_load = a_pull >= a_max ? 0 : N;
        return ADH_SUCCESS;
    }
    /* points shared out by radius, each part at least N/8 */
    size_t nd = (size_t)lround((double)(N - 1) * (a_pull - a_fold) / (a_max - a_fold));
    if (nd < N / 8)
        nd = N / 8;
    if (nd > N - N / 8)
        nd = N - N / 8;
    size_t n1 = N - nd;
    if ((rc = sample_span(m, fn, ctx, a_max, a_pull, n1, 0, c)) != ADH_SUCCESS ||
        (rc = sample_span(m, fn, ctx, a_pull, a_fold, nd + 1, n1 - 1, c)) != ADH_SUCCESS)
        return rc;
    c->n = N;
    c->n_load = n1;
    return ADH_SUCCESS;
}

static int jkr_at(const adh_material *m, const void *ctx, double a, double *F, double *overlap)
{
    (void)ctx;
    adh_jkr(m, a, F, overlap);
    return ADH_SUCCESS;
}

int adh_jkr_drive_curve(const adh_material *m, double h0_min, adh_model_curve *c)
{
    double a_fold = cbrt(M_PI * adh_material_gamma(m) * m->R * m->R / (8.0 * (m->E / 2.0)));
    return adh_model_sample(m, jkr_at, NULL, a_fold, cbrt(9.0) * a_fold, h0_min, c);
}

int adh_dmt_drive_curve(const adh_material *m, double h0_min, adh_model_curve *c)
{
    const size_t N = ADH_MODEL_POINTS;
    c->n = c->n_load = 0;
    if (!isfinite(h0_min))
        return ADH_EINVAL;
    double dmax = m->z0 - h0_min;
    if (!(dmax > 0))
        return ADH_SUCCESS;
    for (size_t j = 0; j < N; j++) {
        double delta = dmax * (double)(N - 1 - j) / (double)(N - 1);
        c->h0[j] = m->z0 - delta;
        c->F[j] = adh_dmt_force(m, delta);
    }
    c->n = c->n_load = N;
    return ADH_SUCCESS;
}
