/* Fold bookkeeping (adhere/folds.h) alone, on curves whose folds and
 * minimum are known in closed form. The Hermite mode interpolates cubics
 * exactly, the parabola mode quadratics: there the folds and the pull-off
 * must come out to rounding, wherever the points fall. */
#include <math.h>

#include "adhere/folds.h"
#include "tap.h"

/* h0(s) = s - s^3/3: a minimum at s = -1 (h0 = -2/3), a maximum at s = 1
 * (h0 = 2/3); F(s) = (s - 0.3)^2 - 1: its minimum -1 at s = 0.3. */
static adh_folds_point cubic(double s, double ds)
{
    return (adh_folds_point){ .s = s, .ds = ds, .h0 = s - s * s * s / 3, .F = (s - 0.3) * (s - 0.3) - 1,
                              .dh0 = 1 - s * s, .dF = 2 * (s - 0.3) };
}

/* h0(s) = 1 - (s - 0.37)^2, F(s) = 2 (s - 0.5)^2 - 3 */
static adh_folds_point quad(double s)
{
    return (adh_folds_point){ .s = s, .h0 = 1 - (s - 0.37) * (s - 0.37), .F = 2 * (s - 0.5) * (s - 0.5) - 3 };
}

int main(void)
{
    adh_folds *f = adh_folds_alloc(16);
    ok(f != NULL, "allocated");
    adh_folds_summary r = adh_folds_summary_of(f);
    ok(r.points == 0 && r.folds == 0 && isnan(r.jump_in_h0) && isnan(r.jump_out_h0) && isinf(r.pulloff_F),
       "before any point: no folds, no jumps, pull-off +inf");

    /* uneven steps that never land on a fold or the minimum */
    adh_folds_set(f, ADH_FOLDS_HERMITE);
    double s = -2.0, step = 0.13;
    adh_folds_add(f, &(adh_folds_point){ 0 }); /* a point the next set forgets */
    adh_folds_set(f, ADH_FOLDS_HERMITE);
    adh_folds_add(f, &(adh_folds_point){ .s = s, .h0 = cubic(s, 0).h0, .F = cubic(s, 0).F, .dh0 = cubic(s, 0).dh0,
                                         .dF = cubic(s, 0).dF });
    while (s < 2.0) {
        double ds = step * (1 + 0.3 * sin(7 * s));
        s += ds;
        adh_folds_point p = cubic(s, ds);
        adh_folds_add(f, &p);
    }
    r = adh_folds_summary_of(f);
    const adh_fold *fd;
    size_t nk = adh_folds_kept(f, &fd);
    ok(r.folds == 2 && nk == 2, "Hermite: two folds (%zu)", r.folds);
    ok(nk == 2 && fd[0].kind == -1 && fd[1].kind == +1, "... a minimum of h0, then a maximum");
    ok(nk == 2 && fabs(fd[0].h0 + 2.0 / 3) < 1e-12 && fabs(fd[1].h0 - 2.0 / 3) < 1e-12,
       "... at h0 = -2/3 and 2/3 (%.15g, %.15g)", fd[0].h0, fd[1].h0);
    ok(nk == 2 && fabs(fd[0].F - (1.69 - 1)) < 1e-12 && fabs(fd[1].F - (0.49 - 1)) < 1e-12,
       "... with F(-1) = 0.69 and F(1) = -0.51 (%.15g, %.15g)", fd[0].F, fd[1].F);
    ok(fabs(r.jump_in_h0 + 2.0 / 3) < 1e-12 && fabs(r.jump_out_h0 - 2.0 / 3) < 1e-12 &&
           fabs(r.pulloff_F_disp + 0.51) < 1e-12,
       "jump-in at the first fold, jump-out at the maximum, its force the displacement pull-off");
    ok(fabs(r.pulloff_F + 1) < 1e-12 && fabs(r.pulloff_h0 - (0.3 - 0.009)) < 1e-12,
       "pull-off: F's minimum -1 between the points, at h0(0.3) = 0.291 (%.15g at %.15g)", r.pulloff_F,
       r.pulloff_h0);
    adh_folds_point last = adh_folds_recent(f, 0), before = adh_folds_recent(f, 1);
    ok(last.s == s && fabs(before.s - (s - last.ds)) < 1e-12, "the last points are at hand (s = %g, %g)", last.s, before.s);

    /* parabolas: quadratics exactly, from any three points around */
    adh_folds_set(f, ADH_FOLDS_PARABOLA);
    ok(adh_folds_summary_of(f).points == 0 && adh_folds_kept(f, NULL) == 0, "set forgets the curve");
    double ss[] = { 0.0, 0.2, 0.4, 0.6, 0.75, 0.9 };
    for (int i = 0; i < 6; i++) {
        adh_folds_point p = quad(ss[i]);
        adh_folds_add(f, &p);
    }
    r = adh_folds_summary_of(f);
    nk = adh_folds_kept(f, &fd);
    ok(r.folds == 1 && nk == 1 && fd[0].kind == +1, "parabola: one fold, h0's maximum");
    ok(nk == 1 && fabs(fd[0].h0 - 1) < 1e-13 && fabs(fd[0].F - (2 * 0.0169 - 3)) < 1e-13,
       "... at h0 = 1, F(0.37) = -2.9662 (%.15g, %.15g)", fd[0].h0, fd[0].F);
    ok(isnan(r.jump_in_h0) && fabs(r.jump_out_h0 - 1) < 1e-13, "no jump-in (the first fold is a maximum)");
    ok(fabs(r.pulloff_F + 3) < 1e-13 && fabs(r.pulloff_h0 - (1 - 0.0169)) < 1e-13,
       "pull-off -3 at h0(0.5) = 0.9831 between the points (%.15g at %.15g)", r.pulloff_F, r.pulloff_h0);

    /* only max_kept folds are kept, all are counted */
    adh_folds *one = adh_folds_alloc(1);
    adh_folds_set(one, ADH_FOLDS_PARABOLA);
    double zig[] = { 0, 1, 0, 1, 0 };
    for (int i = 0; i < 5; i++)
        adh_folds_add(one, &(adh_folds_point){ .s = i, .h0 = zig[i], .F = -zig[i] });
    ok(adh_folds_summary_of(one).folds == 3 && adh_folds_kept(one, NULL) == 1,
       "a zigzag: 3 folds counted, 1 kept as asked");
    adh_folds_free(one);
    adh_folds_free(f);
    adh_folds_free(NULL);
    return tap_done();
}
