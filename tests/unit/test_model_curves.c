/* The model curves force.png draws, F against the drive position: JKR, DMT
 * and Maugis-Dugdale on h0 = z0 - overlap, checked against their closed
 * forms (pull-offs, fold, contact point) and against each other's limits. */
#include <math.h>

#include "adhere/maugis.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/status.h"
#include "tap.h"

static int rising(const adh_model_curve *c)
{
    for (size_t i = 1; i < c->n; i++)
        if (!(c->h0[i] > c->h0[i - 1]))
            return 0;
    return 1;
}

static size_t argmin_F(const adh_model_curve *c)
{
    size_t k = 0;
    for (size_t i = 1; i < c->n; i++)
        if (c->F[i] < c->F[k])
            k = i;
    return k;
}

int main(void)
{
    /* Figure 4's material (sigma 7.5), the default scene's */
    adh_material m = adh_material_default();
    m.E = 0.3e9;
    adh_derived d;
    adh_material_derive(&m, &d);
    double piwR = M_PI * d.gamma * m.R, Es = m.E / 2.0;
    double h0_min = -5e-9;
    static adh_model_curve c, c2;

    /* ---- JKR */
    ok(adh_jkr_drive_curve(&m, h0_min, &c) == ADH_SUCCESS, "JKR curve solves");
    ok(c.n == ADH_MODEL_POINTS && c.n_load > 1 && c.n_load < c.n,
       "JKR: %zu points, %zu of them load-controlled, the rest past the pull-off", c.n, c.n_load);
    ok(fabs(c.h0[0] - h0_min) < 1e-6 * m.z0, "JKR starts at h0_min (%.6g nm)", c.h0[0] * 1e9);
    ok(rising(&c), "JKR: h0 rises along the curve from the deepest contact to the fold");
    size_t k = argmin_F(&c);
    ok(k == c.n_load - 1, "JKR: the minimum force is the last load-controlled point (%zu, %zu)", k, c.n_load - 1);
    ok_rel(c.F[c.n_load - 1], -1.5 * piwR, 1e-12, "JKR load-controlled pull-off -(3/2) pi gamma R");
    /* the pull-off radius a^3 = 9 pi gamma R^2 / (8 E*), and h0 = z0 - overlap there */
    double ap = cbrt(9.0 * M_PI * d.gamma * m.R * m.R / (8.0 * Es));
    double ovp = ap * ap / m.R - sqrt(2.0 * M_PI * d.gamma * ap / Es);
    ok(fabs(c.h0[c.n_load - 1] - (m.z0 - ovp)) < 1e-9 * m.z0,
       "JKR pull-off at h0 = z0 - overlap(a_p) = %.6g nm (got %.6g nm)", (m.z0 - ovp) * 1e9,
       c.h0[c.n_load - 1] * 1e9);
    double af = ap / cbrt(9.0);
    double ovf = af * af / m.R - sqrt(2.0 * M_PI * d.gamma * af / Es);
    ok_rel(c.F[c.n - 1], -5.0 / 6.0 * piwR, 1e-12, "JKR fold (last point): -(5/6) pi gamma R");
    ok(fabs(c.h0[c.n - 1] - (m.z0 - ovf)) < 1e-9 * m.z0, "JKR fold at h0 = z0 - minimum overlap = %.6g nm",
       (m.z0 - ovf) * 1e9);
    ok(c.h0[c.n - 1] > m.z0, "JKR: the fold lies beyond contact, at negative overlap");
    /* every point on the closed form: F from the overlap's radius */
    int on_jkr = 1;
    for (size_t i = 0; i < c.n; i += 17) {
        /* the radius back from the force: bisect F(a) on the branch's side */
        double lo = i < c.n_load ? ap : af, hi = i < c.n_load ? 1e3 * ap : ap;
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (lo + hi), F;
            adh_jkr(&m, mid, &F, NULL);
            if ((F < c.F[i]) == (i < c.n_load))
                lo = mid;
            else
                hi = mid;
        }
        double ov;
        adh_jkr(&m, 0.5 * (lo + hi), NULL, &ov);
        if (fabs(c.h0[i] - (m.z0 - ov)) > 1e-6 * m.z0)
            on_jkr = 0;
    }
    ok(on_jkr, "JKR: every 17th point is on F(a), h0 = z0 - overlap(a)");

    /* h0_min between the pull-off and the fold: only the displacement part */
    int rc = adh_jkr_drive_curve(&m, 0.5 * (c.h0[c.n_load - 1] + c.h0[c.n - 1]), &c2);
    ok(rc == ADH_SUCCESS && c2.n == ADH_MODEL_POINTS && c2.n_load == 0,
       "JKR above its pull-off: all past the pull-off (n_load %zu)", c2.n_load);
    ok(adh_jkr_drive_curve(&m, c.h0[c.n - 1] + 1e-9, &c2) == ADH_SUCCESS && c2.n == 0,
       "JKR: nothing when h0_min is beyond the fold");
    ok(adh_jkr_drive_curve(&m, NAN, &c2) == ADH_EINVAL, "JKR: NaN h0_min refused");

    /* ---- DMT */
    rc = adh_dmt_drive_curve(&m, h0_min, &c2);
    ok(rc == ADH_SUCCESS && c2.n == ADH_MODEL_POINTS && c2.n_load == c2.n,
       "DMT curve: %zu points, all load-controlled", c2.n);
    ok(fabs(c2.h0[c2.n - 1] - m.z0) < 1e-15 && fabs(c2.F[c2.n - 1] + 2.0 * piwR) < 1e-12 * piwR,
       "DMT at contact: h0 = z0, F = -2 pi gamma R (%.6g uN)", c2.F[c2.n - 1] * 1e6);
    ok_rel(c2.F[0], adh_hertz_force(&m, m.z0 - h0_min) - 2.0 * piwR, 1e-12,
           "DMT at h0_min: Hertz(z0 - h0_min) - 2 pi gamma R");
    ok(rising(&c2), "DMT: h0 rises to contact");
    ok(adh_dmt_drive_curve(&m, 2.0 * m.z0, &c2) == ADH_SUCCESS && c2.n == 0, "DMT: nothing beyond contact");

    /* ---- Maugis-Dugdale at lambda from mu */
    double lam = adh_md_lambda(&m), Fl, al, Fd, od;
    adh_md_pulloff(&m, lam, &Fl, &al, &Fd, &od);
    ok(adh_md_drive_curve(&m, lam, h0_min, &c2) == ADH_SUCCESS, "MD curve at lambda = %.3g solves", lam);
    ok(c2.n == ADH_MODEL_POINTS && c2.n_load > 1 && c2.n_load < c2.n, "MD: %zu points, %zu load-controlled",
       c2.n, c2.n_load);
    ok(rising(&c2), "MD: h0 rises along the curve");
    ok(argmin_F(&c2) == c2.n_load - 1, "MD: the minimum force ends the load-controlled part");
    ok_rel(c2.F[c2.n_load - 1], Fl, 1e-6, "MD load-controlled pull-off = adh_md_pulloff's");
    ok(c2.F[c2.n_load - 1] > -2.0 * piwR && c2.F[c2.n_load - 1] < -1.5 * piwR,
       "MD pull-off between DMT and JKR (%.4g pi gamma R)", c2.F[c2.n_load - 1] / piwR);
    ok_rel(c2.F[c2.n - 1], Fd, 1e-6, "MD fold force = adh_md_pulloff's displacement-controlled pull-off");
    ok(fabs(c2.h0[c2.n - 1] - (m.z0 - od)) < 1e-6 * m.z0, "MD fold at h0 = z0 - its minimum overlap");
    ok(fabs(c2.h0[0] - h0_min) < 1e-6 * m.z0, "MD starts at h0_min");

    /* lambda large: JKR's curve; lambda small: DMT's, with no fold */
    ok(adh_md_drive_curve(&m, 1000.0, h0_min, &c2) == ADH_SUCCESS, "MD at lambda = 1000 solves");
    ok_rel(c2.F[c2.n_load - 1], -1.5 * piwR, 0.01, "lambda = 1000: pull-off -> JKR");
    ok(fabs(c2.h0[c2.n - 1] - c.h0[c.n - 1]) < 0.05 * m.z0, "lambda = 1000: fold at JKR's (%.4g vs %.4g nm)",
       c2.h0[c2.n - 1] * 1e9, c.h0[c.n - 1] * 1e9);
    ok(adh_md_drive_curve(&m, 1e-4, h0_min, &c2) == ADH_SUCCESS && c2.n == ADH_MODEL_POINTS,
       "MD at lambda = 1e-4 solves");
    ok(c2.n_load == c2.n, "lambda = 1e-4: stable all the way (DMT-like, no break)");
    double worst = 0;
    for (size_t i = 0; i < c2.n; i++)
        worst = fmax(worst, fabs(c2.F[i] - adh_dmt_force(&m, m.z0 - c2.h0[i])) / (2.0 * piwR));
    ok(worst < 0.05, "lambda = 1e-4: on DMT's F(h0) within 5 %% of 2 pi gamma R (worst %.3g)", worst);
    ok(adh_md_drive_curve(&m, 0.0, h0_min, &c2) == ADH_EINVAL, "MD: lambda 0 refused");
    /* ---- JKR's radius at an overlap: the overlap it gives back (closed
     * form, eq of adh_jkr), on the stable branch past the fold, none below
     * the fold's overlap */
    {
        double a_f = cbrt(M_PI * d.gamma * m.R * m.R / (8.0 * Es)), ov_f;
        adh_jkr(&m, a_f, NULL, &ov_f);
        const double want[] = { ov_f * 0.5, 0.0, 1e-9, 5e-9, 1e-6 };
        for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
            double a = adh_jkr_radius(&m, want[i]), ov;
            adh_jkr(&m, a, NULL, &ov);
            ok(a > a_f && fabs(ov - want[i]) <= 1e-12 * (fabs(want[i]) + a * a / m.R),
               "JKR radius at overlap %g m: %g m past the fold %g m, overlap back %g", want[i], a, a_f, ov);
        }
        ok(adh_jkr_radius(&m, ov_f * 1.5) == 0.0 && adh_jkr_radius(&m, ov_f) == 0.0,
           "JKR radius: no contact at or below the fold's overlap %g m", ov_f);
        ok(isnan(adh_jkr_radius(&m, NAN)) && adh_jkr_radius(&m, INFINITY) == INFINITY,
           "JKR radius: a NaN overlap gives NaN (it said 0, no contact), an infinite one an infinite radius (it "
           "said NaN)");
        /* at the materials' limits (params.c) and overlaps up to 1e300 m */
        double worst_back = 0;
        for (int lim = 0; lim < 16; lim++) {
            adh_material x = m;
            x.E = lim & 1 ? 1e13 : 1e3, x.A = lim & 2 ? 1e-15 : 1e-24, x.z0 = lim & 4 ? 1e-7 : 1e-12;
            x.R = lim & 8 ? 10.0 : 1e-9;
            const double ovs[] = { 1e-12, 1e-9, 1.0, 1e300 };
            for (size_t i = 0; i < sizeof ovs / sizeof *ovs; i++) {
                double a = adh_jkr_radius(&x, ovs[i]), ov = NAN;
                adh_jkr(&x, a, NULL, &ov);
                worst_back = fmax(worst_back, a > 0 ? fabs(ov - ovs[i]) / (ovs[i] + a * a / x.R) : INFINITY);
            }
        }
        ok(worst_back <= 1e-12, "JKR radius at the materials' limits, overlaps 1 pm to 1e300 m: the overlap back "
           "(worst %.2g of a^2/R)", worst_back);
    }
    return tap_done();
}
