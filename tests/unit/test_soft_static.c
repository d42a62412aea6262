/* The static curve of soft, strongly adhesive spheres on the grid a run
 * gets by default (graded rings at 0.3 edge-zone widths, H^2 kernel, HODLR
 * preconditioner, steps over the lattice folds): its pull-off within 1 % of
 * the same curve on a grid a third finer (grid-converged to that) and
 * within 3 % of Maugis-Dugdale, its folds reported, at sigma = 15 and 30
 * (lambda 22 and 44). docs/static-curve.md has sigma =
 * 15 ... 100 measured, and bench-static_soft times sigma = 75 and 100. */
#include <math.h>
#include <stdlib.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/maugis.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "tap.h"

/* The static curve to turn -2 nm on graded rings of fine width dr (the
 * automatic grid's band, growth and Rmax); the result, or rc != 0. */
static int curve(const adh_material *m, const adh_rings_choice *gc, double dr, adh_static_result *r, size_t *n)
{
    adh_rings_spec rs = { .dr = dr, .fine = gc->fine, .ratio = gc->ratio, .rmax = gc->rmax };
    adh_grid *g = adh_rings_alloc(&rs);
    adh_kernel_settings ks = { .type = ADH_KERNEL_RING, .storage = ADH_STORAGE_H2 };
    adh_kernel *k = g ? adh_kernel_alloc(g, &ks, NULL) : NULL;
    adh_static *w = k ? adh_static_alloc(g, k) : NULL;
    int rc = ADH_ENOMEM;
    if (w) {
        adh_static_settings s = adh_static_settings_default();
        s.h0_end = -2e-9;
        rc = adh_static_set(w, m, &s);
        while (rc == ADH_SUCCESS || rc == ADH_CONTINUE)
            if ((rc = adh_static_iterate(w)) == ADH_SUCCESS)
                break;
        adh_static_summary(w, r);
        *n = g->n;
    }
    adh_static_free(w);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc;
}

static void one(double sigma)
{
    adh_material m = adh_material_default();
    m.E *= adh_material_sigma(&m) / sigma; /* sigma is proportional to 1/E */
    adh_rings_choice gc;
    char why[1024];
    int rc = adh_rings_choose(&m, ADH_GRID_STATIC, -2e-9, 1, &gc, why, sizeof why, NULL);
    if (!ok(rc == ADH_SUCCESS && gc.graded && gc.hierarchical, "sigma = %g: the automatic static grid is graded and H^2",
            sigma))
        return;
    adh_static_result ra, rf;
    size_t na = 0, nf = 0;
    int ca = curve(&m, &gc, gc.dr, &ra, &na);
    int cf = curve(&m, &gc, gc.dr * 2.0 / 3.0, &rf, &nf);
    if (!ok(ca == ADH_SUCCESS && cf == ADH_SUCCESS, "sigma = %g: both curves reach the turn (%zu and %zu rings)", sigma,
            na, nf))
        return;
    double F_md = NAN;
    adh_md_pulloff(&m, adh_md_lambda(&m), &F_md, NULL, NULL, NULL);
    double e_grid = fabs(ra.pulloff_F / rf.pulloff_F - 1), e_md = fabs(ra.pulloff_F / F_md - 1);
    ok(e_grid < 0.01, "sigma = %g: pull-off %.5g N within 1 %% of the finer grid's %.5g N (%.2f %%)", sigma,
       ra.pulloff_F, rf.pulloff_F, 100 * e_grid);
    ok(e_md < 0.03, "sigma = %g: pull-off within 3 %% of Maugis-Dugdale's %.5g N (%.2f %%)", sigma, F_md, 100 * e_md);
    ok(ra.folds >= 2 && isfinite(ra.jump_in_h0) && isfinite(ra.jump_out_h0) && ra.jump_out_h0 > ra.jump_in_h0,
       "sigma = %g: folds reported (%zu), jump-in %.3f nm before jump-out %.3f nm", sigma, ra.folds,
       ra.jump_in_h0 * 1e9, ra.jump_out_h0 * 1e9);
    ok(fabs(ra.jump_out_h0 / rf.jump_out_h0 - 1) < 0.01, "sigma = %g: jump-out within 1 %% of the finer grid's (%.3f nm)",
       sigma, rf.jump_out_h0 * 1e9);
}

int main(void)
{
    one(15);
    if (tap_sanitized_short())
        tap_sanitized_leaves_out("sigma = 30 (sigma = 15's graded H^2 curves on 2.4x the rings)");
    else
        one(30);
    return tap_done();
}
