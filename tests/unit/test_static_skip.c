/* The static curve stepped over lattice folds (lattice_skip = 1, in steps
 * of the contact measure Q) against the exact curve (lattice_skip = 0, the
 * oracle, every fold resolved) on the same resolved grid: the same
 * physical folds (jump-in, jump-out) and pull-off, stability that follows
 * the branches, fewer points. And the automatic choice: exact on small
 * grids. Small grids: a few seconds. */
#include <math.h>
#include <stdlib.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/maugis.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "tap.h"

typedef struct curve {
    adh_run run;
    adh_static_result res;
    int rc;
} curve;

static curve run_curve(const adh_grid *g, const adh_kernel *k, const adh_material *m, int skip)
{
    curve c;
    adh_run_init(&c.run);
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = -2e-9;
    s.lattice_skip = skip;
    c.rc = adh_runner_static_curve(g, k, m, &s, NULL, NULL, &c.run, &c.res);
    return c;
}

static double rel(double a, double b)
{
    return fabs(a - b) / fabs(b);
}

int main(void)
{
    /* sigma = 3.75 on a uniform grid at the static limit, 0.3 edge zones */
    adh_material m = adh_material_default();
    m.E = 0.6e9;
    double dr = adh_grid_edge_spacing(ADH_GRID_STATIC) * adh_edge_zone(&m);
    size_t n = (size_t)ceil(0.55e-6 / dr);
    adh_grid *g = adh_grid_alloc(n, dr);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
    curve ex = run_curve(g, k, &m, 0);
    curve sk = run_curve(g, k, &m, 1);
    ok(ex.rc == ADH_SUCCESS && sk.rc == ADH_SUCCESS, "both curves end at the turn (exact %s, skip %s; N = %zu)",
       adh_strerror(ex.rc), adh_strerror(sk.rc), n);
    ok(ex.res.folds >= 2 && sk.res.folds >= 2, "both find folds (exact %zu, skip %zu)", ex.res.folds,
       sk.res.folds);
    ok(rel(sk.res.jump_in_h0, ex.res.jump_in_h0) < 1e-3, "same jump-in: %.5f against %.5f nm",
       sk.res.jump_in_h0 * 1e9, ex.res.jump_in_h0 * 1e9);
    ok(rel(sk.res.jump_out_h0, ex.res.jump_out_h0) < 1e-3, "same jump-out: %.5f against %.5f nm",
       sk.res.jump_out_h0 * 1e9, ex.res.jump_out_h0 * 1e9);
    ok(rel(sk.res.pulloff_F, ex.res.pulloff_F) < 1e-3, "same pull-off: %.6g against %.6g N (%.1e)",
       sk.res.pulloff_F, ex.res.pulloff_F, rel(sk.res.pulloff_F, ex.res.pulloff_F));
    /* F changes steeply at the fold, and which lattice fold is the highest
     * shifts F by about a ring's worth: a coarser test */
    ok(rel(sk.res.pulloff_F_disp, ex.res.pulloff_F_disp) < 3e-2,
       "same force at the jump-out: %.6g against %.6g N", sk.res.pulloff_F_disp, ex.res.pulloff_F_disp);
    ok(sk.res.points < ex.res.points, "fewer points stepping over the lattice: %zu against %zu", sk.res.points,
       ex.res.points);
    double F_md;
    adh_md_pulloff(&m, adh_md_lambda(&m), &F_md, NULL, NULL, NULL);
    ok(rel(sk.res.pulloff_F, F_md) < 0.03, "pull-off within 3 %% of Maugis-Dugdale: %.4g against %.4g N",
       sk.res.pulloff_F, F_md);

    /* Stability follows the branches: stable before the jump-in and on
     * the contact branch deep down, unstable between the folds. */
    int bad = 0, seen_unstable = 0;
    for (size_t i = 0; i < sk.run.nrows; i++) {
        const adh_obs *o = &sk.run.rows[i];
        if (i == 0 || i + 1 == sk.run.nrows)
            bad += !o->stable;
        seen_unstable |= !o->stable;
        /* the unstable branch runs back up in h0: direction -1 */
        bad += o->stable != (o->branch > 0);
    }
    ok(!bad && seen_unstable, "stable where h0 falls along the curve, unstable where it rises (%d bad rows)", bad);

    /* the automatic choice: exact up to ADH_STATIC_EXACT_MAX_NODES nodes */
    curve au = run_curve(g, k, &m, -1);
    ok(au.rc == ADH_SUCCESS && au.res.points == ex.res.points && au.res.folds == ex.res.folds,
       "lattice_skip = -1 is the exact curve at N = %zu (%zu points, %zu folds)", n, au.res.points, au.res.folds);
    adh_static_settings s = adh_static_settings_default();
    s.lattice_skip = 2;
    char why[200];
    ok(adh_static_settings_validate(&s, why, sizeof why) == ADH_EINVAL, "lattice_skip 2 refused: %s", why);

    adh_run_free(&ex.run);
    adh_run_free(&sk.run);
    adh_run_free(&au.run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
