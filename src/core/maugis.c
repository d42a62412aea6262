#include "adhere/maugis.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>
#include <math.h>

#include "adhere/status.h"

/* Scales between the nondimensional and SI forms (see the header). */
typedef struct md_scale {
    double w, K, R;
    double a;   /* m per unit A */
    double F;   /* N per unit P */
    double d;   /* m per unit D */
} md_scale;

static md_scale scale_of(const adh_material *m)
{
    md_scale s;
    s.w = adh_material_gamma(m);
    s.K = 2.0 * m->E / 3.0; /* (4/3) E*, E* = E/2 */
    s.R = m->R;
    s.a = cbrt(M_PI * s.w * s.R * s.R / s.K);
    s.F = M_PI * s.w * s.R;
    s.d = cbrt(M_PI * M_PI * s.w * s.w * s.R / (s.K * s.K));
    return s;
}

double adh_md_lambda(const adh_material *m)
{
    double sigma = adh_material_sigma(m);
    return 1.16 * cbrt(4.0) * pow(sigma, 2.0 / 3.0);
}

double adh_md_stress(const adh_material *m, double lambda)
{
    md_scale s = scale_of(m);
    return 0.5 * lambda * cbrt(M_PI * s.w * s.K * s.K / s.R);
}

/* X = s + (m^2 - 2) atan s and Y = s atan s - m + 1 with m^2 = 1 + s^2; both
 * cancel to O(s^3), O(s^2) for small s, where their series take over. */
static void xy_of(double s, double *X, double *Y)
{
    if (s < 1e-3) {
        double s2 = s * s;
        *X = s * s2 * (4.0 / 3.0 - 8.0 / 15.0 * s2);
        *Y = s2 * (0.5 - 5.0 / 24.0 * s2);
        return;
    }
    double m = sqrt(1.0 + s * s), at = atan(s);
    *X = s + (s * s - 1.0) * at;
    *Y = s * at - (m - 1.0);
}

/* The nondimensional point for Dugdale-zone parameter s = sqrt(m^2 - 1):
 * eq 1 is a quadratic in A with positive coefficients, one positive root. */
static void md_of_s(double lambda, double s, double *A, double *P, double *D)
{
    double X, Y;
    xy_of(s, &X, &Y);
    double a2 = 0.5 * lambda * X, a1 = 4.0 / 3.0 * lambda * lambda * Y;
    double Ab = 2.0 / (a1 + sqrt(a1 * a1 + 4.0 * a2));
    double m2 = 1.0 + s * s;
    *A = Ab;
    *P = Ab * Ab * Ab - lambda * Ab * Ab * (s + m2 * atan(s));
    *D = Ab * Ab - 4.0 / 3.0 * Ab * lambda * s;
}

typedef struct eq1_ctx {
    double lambda, Ab;
} eq1_ctx;

/* eq 1, left side minus right, as a function of s */
static double lhs_eq1(double s, void *ctx)
{
    const eq1_ctx *c = ctx;
    double X, Y;
    xy_of(s, &X, &Y);
    return 0.5 * c->lambda * c->Ab * c->Ab * X + 4.0 / 3.0 * c->lambda * c->lambda * c->Ab * Y - 1.0;
}

/* Brent's method (GSL) on f's sign change in [lo, hi]: f(lo) < 0 <= f(hi)
 * (checked by the caller: GSL's error handler never hears of a bad
 * bracket). The root to a few units of rounding, in *x. */
static int root_in(gsl_function *f, double lo, double hi, double *x)
{
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs)
        return ADH_ENOMEM;
    int rc = gsl_root_fsolver_set(rs, f, lo, hi) == GSL_SUCCESS ? GSL_CONTINUE : GSL_EFAILED;
    for (int i = 0; i < 200 && rc == GSL_CONTINUE; i++) {
        if (gsl_root_fsolver_iterate(rs) != GSL_SUCCESS)
            break;
        rc = gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs), 0,
                                    4 * DBL_EPSILON);
    }
    *x = gsl_root_fsolver_root(rs);
    gsl_root_fsolver_free(rs);
    return rc == GSL_SUCCESS ? ADH_SUCCESS : ADH_EMAXITER;
}

int adh_md_at_radius(const adh_material *m, double lambda, double a, adh_md_point *pt)
{
    if (!(a > 0) || !(lambda > 0) || !isfinite(a) || !isfinite(lambda))
        return ADH_EINVAL;
    md_scale sc = scale_of(m);
    double Ab = a / sc.a;
    eq1_ctx ctx = { lambda, Ab };
    gsl_function f = { lhs_eq1, &ctx };
    /* eq 1 rises monotonically in s from -1 at s = 0: bracket the root */
    double lo = 0, hi = 1;
    int k = 0;
    while (lhs_eq1(hi, &ctx) < 0) {
        lo = hi;
        hi *= 4;
        if (++k > 60)
            return ADH_EMAXITER;
    }
    double s = hi, A, P, D;
    if (lhs_eq1(hi, &ctx) > 0) {
        int rc = root_in(&f, lo, hi, &s);
        if (rc != ADH_SUCCESS)
            return rc;
    }
    md_of_s(lambda, s, &A, &P, &D);
    /* P and D from the given A (the root's A differs by rounding only) */
    double m2 = 1.0 + s * s;
    P = Ab * Ab * Ab - lambda * Ab * Ab * (s + m2 * atan(s));
    D = Ab * Ab - 4.0 / 3.0 * Ab * lambda * s;
    pt->a = a;
    pt->c = a * sqrt(m2);
    pt->F = P * sc.F;
    pt->overlap = D * sc.d;
    return ADH_SUCCESS;
}

int adh_md_curve(const adh_material *m, double lambda, double a_max, size_t n, adh_md_point *pts)
{
    if (n < 2 || !(a_max > 0))
        return ADH_EINVAL;
    for (size_t i = 0; i < n; i++) {
        int rc = adh_md_at_radius(m, lambda, a_max * (double)(i + 1) / (double)n, &pts[i]);
        if (rc != ADH_SUCCESS)
            return rc;
    }
    return ADH_SUCCESS;
}

typedef struct pd_ctx {
    double lambda;
    int which;
} pd_ctx;

/* P (which = 0) or D (which = 1) at s = 10^x */
static double pd_of(double x, void *ctx)
{
    const pd_ctx *c = ctx;
    double A, P, D;
    md_of_s(c->lambda, pow(10.0, x), &A, &P, &D);
    return c->which ? D : P;
}

/* Minimum over log s of P (which = 0) or D (which = 1): a scan brackets
 * it, then Brent's minimization (GSL) places it. Returns the s of the
 * minimum, or -1 when the minimum is at the end of the scan (none inside:
 * the DMT-like limit). A minimum flat to rounding over the bracket is the
 * scan's point. */
static double md_min(double lambda, int which)
{
    const double l0 = -6.0, l1 = 7.0;
    const int nscan = 521;
    pd_ctx ctx = { lambda, which };
    double best = INFINITY;
    int ib = 0;
    for (int i = 0; i < nscan; i++) {
        double v = pd_of(l0 + (l1 - l0) * i / (nscan - 1), &ctx);
        if (v < best) {
            best = v;
            ib = i;
        }
    }
    if (ib == nscan - 1)
        return -1;
    double step = (l1 - l0) / (nscan - 1);
    double xm = l0 + ib * step, x0 = xm - step, x1 = xm + step;
    double f0 = pd_of(x0, &ctx), f1 = pd_of(x1, &ctx);
    if (!(best < f0 && best < f1)) /* GSL's condition for a bracket */
        return pow(10.0, xm);
    gsl_function f = { pd_of, &ctx };
    gsl_min_fminimizer *ms = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!ms)
        return pow(10.0, xm);
    /* The bracket shrinks until P or D is flat to rounding over it (about
     * 3e-8 decades: a minimum's place is fixed to the square root of the
     * rounding only), then stays: the cap of iterations ends it there. */
    int rc = gsl_min_fminimizer_set_with_values(ms, &f, xm, best, x0, f0, x1, f1);
    for (int it = 0; it < 100 && rc == GSL_SUCCESS; it++) {
        if (gsl_min_fminimizer_iterate(ms) != GSL_SUCCESS)
            break;
        if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(ms), gsl_min_fminimizer_x_upper(ms), 1e-12, 0) ==
            GSL_SUCCESS)
            break;
    }
    double x = gsl_min_fminimizer_x_minimum(ms);
    gsl_min_fminimizer_free(ms);
    return pow(10.0, x);
}

int adh_md_pulloff(const adh_material *m, double lambda, double *F_load, double *a_load,
                   double *F_disp, double *overlap_disp)
{
    if (!(lambda > 0) || !isfinite(lambda))
        return ADH_EINVAL;
    md_scale sc = scale_of(m);
    double A, P, D;
    double s = md_min(lambda, 0);
    if (s < 0) {
        /* the force falls all the way to the DMT tail: its limit is -2 */
        A = 0;
        P = -2.0;
    } else {
        md_of_s(lambda, s, &A, &P, &D);
    }
    if (F_load)
        *F_load = P * sc.F;
    if (a_load)
        *a_load = A * sc.a;
    s = md_min(lambda, 1);
    if (s < 0) {
        if (F_disp)
            *F_disp = NAN;
        if (overlap_disp)
            *overlap_disp = NAN;
    } else {
        md_of_s(lambda, s, &A, &P, &D);
        if (F_disp)
            *F_disp = P * sc.F;
        if (overlap_disp)
            *overlap_disp = D * sc.d;
    }
    return ADH_SUCCESS;
}

static int md_at(const adh_material *m, const void *ctx, double a, double *F, double *overlap)
{
    adh_md_point pt;
    int rc = adh_md_at_radius(m, *(const double *)ctx, a, &pt);
    if (rc != ADH_SUCCESS)
        return rc;
    *F = pt.F;
    *overlap = pt.overlap;
    return ADH_SUCCESS;
}

int adh_md_drive_curve(const adh_material *m, double lambda, double h0_min, adh_model_curve *c)
{
    c->n = c->n_load = 0;
    if (!(lambda > 0) || !isfinite(lambda))
        return ADH_EINVAL;
    md_scale sc = scale_of(m);
    double A, P, D, a_fold = 0, a_pull = 0;
    double s = md_min(lambda, 1);
    if (s >= 0) {
        md_of_s(lambda, s, &A, &P, &D);
        a_fold = A * sc.a;
    }
    s = md_min(lambda, 0);
    if (s >= 0) {
        md_of_s(lambda, s, &A, &P, &D);
        a_pull = A * sc.a;
    }
    return adh_model_sample(m, md_at, &lambda, a_fold, a_pull, h0_min, c);
}
