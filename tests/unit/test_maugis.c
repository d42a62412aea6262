/* Maugis-Dugdale: the JKR and DMT limits, the monotone transition between
 * them, and lambda = 1.16 mu. */
#include <math.h>

#include "adhere/maugis.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/status.h"
#include "tap.h"

int main(void)
{
    adh_material m = adh_material_default();
    adh_derived d;
    adh_material_derive(&m, &d);
    double piwR = M_PI * d.gamma * m.R;

    ok_rel(adh_md_lambda(&m), 1.16 * d.mu, 1e-12, "lambda = 1.16 mu");

    double Fl, al, Fd, od;
    ok(adh_md_pulloff(&m, 300.0, &Fl, &al, &Fd, &od) == ADH_SUCCESS, "pull-off at lambda = 300 solves");
    ok_rel(Fl, d.F_jkr, 0.01, "lambda = 300: load-controlled pull-off -> JKR -(3/2) pi gamma R");
    ok_rel(Fd, -5.0 / 6.0 * piwR, 0.02, "lambda = 300: displacement-controlled pull-off -> JKR -(5/6) pi gamma R");
    ok(od < 0, "lambda = 300: the displacement pull-off is at negative overlap (%g m)", od);

    ok(adh_md_pulloff(&m, 0.01, &Fl, &al, &Fd, &od) == ADH_SUCCESS, "pull-off at lambda = 0.01 solves");
    ok_rel(Fl, d.F_dmt, 0.02, "lambda = 0.01: load-controlled pull-off -> DMT -2 pi gamma R");

    /* |F_pulloff| / (pi gamma R) falls from 2 to 1.5 as lambda grows */
    double lams[] = { 0.05, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0 };
    double prev = -2.0 * piwR * 1.0001;
    int mono = 1, inside = 1;
    for (size_t i = 0; i < sizeof lams / sizeof *lams; i++) {
        adh_md_pulloff(&m, lams[i], &Fl, NULL, NULL, NULL);
        if (!(Fl > prev))
            mono = 0;
        if (!(Fl >= -2.0 * piwR * 1.001 && Fl <= -1.5 * piwR * 0.999))
            inside = 0;
        prev = Fl;
    }
    ok(mono, "pull-off rises monotonically from DMT towards JKR as lambda grows (0.05 .. 100)");
    ok(inside, "pull-off stays between -2 and -1.5 pi gamma R (0.1 %% slack)");

    /* The curve: JKR at large lambda, at three contact radii */
    adh_md_point pts[3];
    double amax = 3.0 * cbrt(M_PI * d.gamma * m.R * m.R / (2.0 * m.E / 3.0));
    ok(adh_md_curve(&m, 1000.0, amax, 3, pts) == ADH_SUCCESS, "curve at lambda = 1000 solves");
    int jkr_ok = 1;
    for (int i = 0; i < 3; i++) {
        double F, ov;
        adh_jkr(&m, pts[i].a, &F, &ov);
        if (fabs(pts[i].F - F) > 0.01 * piwR || fabs(pts[i].overlap - ov) > 0.01 * fabs(ov) + 1e-3 * m.z0)
            jkr_ok = 0;
        if (!(pts[i].c > pts[i].a))
            jkr_ok = 0;
    }
    ok(jkr_ok, "lambda = 1000: F(a) within 0.01 pi gamma R and overlap(a) within 1 %% of JKR, c > a");

    /* DMT at small lambda: F = Hertz(overlap) - 2 pi gamma R; MD approaches
     * it only as sqrt(lambda), so check the level and the trend */
    double err[2] = { 0, 0 }, lam2[2] = { 1e-2, 1e-4 };
    for (int j = 0; j < 2; j++) {
        ok(adh_md_curve(&m, lam2[j], amax, 3, pts) == ADH_SUCCESS, "curve at lambda = %g solves", lam2[j]);
        for (int i = 0; i < 3; i++)
            err[j] = fmax(err[j], fabs(pts[i].F - adh_dmt_force(&m, pts[i].overlap)) / (2.0 * piwR));
    }
    ok(err[1] < 0.05, "lambda = 1e-4: F(overlap) within 5 %% of 2 pi gamma R of DMT (worst %.3g)", err[1]);
    ok(err[1] < 0.5 * err[0], "the distance to DMT shrinks as lambda falls (%.3g at 1e-2, %.3g at 1e-4)", err[0], err[1]);

    ok(adh_md_at_radius(&m, 1.0, -1.0, pts) == ADH_EINVAL, "a <= 0 is refused");
    ok(adh_md_pulloff(&m, 0.0, &Fl, NULL, NULL, NULL) == ADH_EINVAL, "lambda <= 0 is refused");
    /* the Dugdale range w / sigma0 at lambda = 1.16 mu is about the LJ range:
     * Johnson and Greenwood's match makes it 0.97 z0 */
    double hD = d.gamma / adh_md_stress(&m, adh_md_lambda(&m));
    ok(hD > 0.9 * m.z0 && hD < 1.05 * m.z0, "Dugdale range w/sigma0 = %.3g z0 (0.9 .. 1.05 z0)", hD / m.z0);
    return tap_done();
}
