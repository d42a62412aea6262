#include "adhere/maugis.h"

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

static double lhs_eq1(double lambda, double Ab, double s)
{
    double X, Y;
    xy_of(s, &X, &Y);
    return 0.5 * lambda * Ab * Ab * X + 4.0 / 3.0 * lambda * lambda * Ab * Y - 1.0;
}

int adh_md_at_radius(const adh_material *m, double lambda, double a, adh_md_point *pt)
{
    if (!(a > 0) || !(lambda > 0) || !isfinite(a) || !isfinite(lambda))
        return ADH_EINVAL;
    md_scale sc = scale_of(m);
    double Ab = a / sc.a;
    /* eq 1 rises monotonically in s from -1 at s = 0 */
    double lo = 0, hi = 1;
    int k = 0;
    while (lhs_eq1(lambda, Ab, hi) < 0) {
        lo = hi;
        hi *= 4;
        if (++k > 60)
            return ADH_EMAXITER;
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if (lhs_eq1(lambda, Ab, mid) < 0)
            lo = mid;
        else
            hi = mid;
    }
    double s = 0.5 * (lo + hi), A, P, D;
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

/* Minimum over log s of P (which = 0) or D (which = 1): a scan, then golden
 * section in the bracket. Returns the s of the minimum, or -1 when the
 * minimum is at the end of the scan (none inside: the DMT-like limit). */
static double md_min(double lambda, int which)
{
    const double l0 = -6.0, l1 = 7.0;
    const int nscan = 521;
    double best = INFINITY;
    int ib = 0;
    for (int i = 0; i < nscan; i++) {
        double s = pow(10.0, l0 + (l1 - l0) * i / (nscan - 1)), A, P, D;
        md_of_s(lambda, s, &A, &P, &D);
        double v = which ? D : P;
        if (v < best) {
            best = v;
            ib = i;
        }
    }
    if (ib == nscan - 1)
        return -1;
    double step = (l1 - l0) / (nscan - 1);
    double x0 = l0 + (ib - 1) * step, x1 = l0 + (ib + 1) * step;
    const double gr = 0.5 * (sqrt(5.0) - 1.0);
    double xa = x1 - gr * (x1 - x0), xb = x0 + gr * (x1 - x0), fa, fb, A, P, D;
    md_of_s(lambda, pow(10.0, xa), &A, &P, &D);
    fa = which ? D : P;
    md_of_s(lambda, pow(10.0, xb), &A, &P, &D);
    fb = which ? D : P;
    for (int it = 0; it < 100 && x1 - x0 > 1e-13; it++) {
        if (fa < fb) {
            x1 = xb;
            xb = xa;
            fb = fa;
            xa = x1 - gr * (x1 - x0);
            md_of_s(lambda, pow(10.0, xa), &A, &P, &D);
            fa = which ? D : P;
        } else {
            x0 = xa;
            xa = xb;
            fa = fb;
            xb = x0 + gr * (x1 - x0);
            md_of_s(lambda, pow(10.0, xb), &A, &P, &D);
            fb = which ? D : P;
        }
    }
    return pow(10.0, 0.5 * (x0 + x1));
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
