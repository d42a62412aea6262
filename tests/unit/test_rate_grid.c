/* The relaxation's rate-dependent numbers are the spheres', not the grid's
 * (adhere/relax.h, adh_relax_measure: eps bounds the change's norm over the
 * paper grid's radius). At sigma = 15 a load/unload cycle on the automatic
 * grid's spacing and radius, on a grid 1.5x finer over the same radius, and
 * on one of twice that radius at that fine spacing give the same pull-off,
 * hysteresis (within 1 %), jump-in and jump-out (within one drive step).
 * Cheaper settings than a figure's that still resolve the contact: turn at
 * 0 nm, d = 0.2 nm, eps = 20 pm, the ring kernel held as H^2; the grid
 * of twice the radius grows its rings x1.05 past the automatic radius. The
 * paper's own measure, sqrt(sum du^2)/N, applied on each grid as it stood,
 * moved the pull-off by 1.2 % and 4.5 %, the hysteresis by 1.2 % and 13 %
 * and the jump-out by 3 and 14 steps between these grids
 * (docs/convergence.md); tests/bench/rategrid.sh runs the
 * figures' settings at sigma = 7.5 and 22.5. */
#include <math.h>
#include <stdio.h>

#include "adhere/cycle.h"
#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/status.h"
#include "adhere/rings.h"
#include "adhere/runner.h"
#include "tap.h"

#define STEP 0.2e-9   /* drive step, m */

typedef struct result {
    double pulloff, hyst, jump_in, jump_out;
    size_t n;
    int rc;
} result;

/* A cycle on g (freed here). */
static result cycle(const adh_material *m, adh_grid *g)
{
    result r = { NAN, NAN, NAN, NAN, g ? g->n : 0, ADH_ENOMEM };
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING, .storage = ADH_STORAGE_H2 }, NULL) : NULL;
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = 0;
    ps.nturns = 1;
    ps.step = STEP;
    adh_relax_settings rs = adh_relax_settings_default();
    rs.eps = 20e-12;
    adh_run run;
    adh_run_init(&run);
    char why[512];
    if (k && (r.rc = adh_protocol_check(&ps, m, g, why, sizeof why, NULL)) == ADH_SUCCESS)
        r.rc = adh_runner_rule(&adh_rule_relax, g, k, m, &rs, &ps, NULL, NULL, &run);
    else if (k)
        printf("# %s\n", why);
    adh_cycle c;
    adh_cycle_measure(run.rows, run.nrows, &c);
    r.pulloff = c.pulloff_F;
    r.hyst = c.hysteresis;
    r.jump_in = c.jump_in_h0;
    r.jump_out = c.jump_out_h0;
    if (run.unconverged)
        r.rc = ADH_EMAXITER;
    printf("# %s N = %zu, dr = %.4g nm, Rmax = %.4g um: pull-off %.6g uN, hysteresis %.6g fJ, jump-in %.4g nm, "
           "jump-out %.4g nm, %zu iterations, %.1f s\n", g && g->graded ? "graded" : "uniform", r.n,
           g ? g->dr * 1e9 : NAN, g ? g->rmax * 1e6 : NAN, r.pulloff * 1e6, r.hyst * 1e15, r.jump_in * 1e9,
           r.jump_out * 1e9, run.iterations, run.seconds);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return r;
}

static void agree(const char *what, const result *a, const result *b)
{
    double ep = fabs(b->pulloff / a->pulloff - 1), eh = fabs(b->hyst / a->hyst - 1);
    ok(a->rc == ADH_SUCCESS && b->rc == ADH_SUCCESS && ep < 0.01 && eh < 0.01,
       "%s: pull-off within 1 %% (%.2f %%), hysteresis within 1 %% (%.2f %%)", what, 100 * ep, 100 * eh);
    double step = STEP * (1 + 1e-9);
    ok(fabs(b->jump_in - a->jump_in) <= step && fabs(b->jump_out - a->jump_out) <= step,
       "%s: jump-in and jump-out within a drive step (%.3g, %.3g nm apart)", what,
       (b->jump_in - a->jump_in) * 1e9, (b->jump_out - a->jump_out) * 1e9);
}

int main(void)
{
    adh_material m = adh_material_default();
    m.E = adh_material_modulus_at_sigma(&m, 15);
    adh_rings_choice gc;
    char why[1024];
    int rc = adh_rings_choose(&m, ADH_GRID_RELAX, 0, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && !gc.graded, "sigma = 15, turn 0: the automatic grid is uniform, N = %zu, dr = %.4g m",
       gc.n, gc.dr);
    if (rc != ADH_SUCCESS)
        return tap_done();
    size_t fine = (size_t)ceil(1.5 * (double)gc.n);
    double fdr = gc.rmax / (double)fine;
    /* twice the radius in rings growing past the automatic grid's */
    adh_rings_spec wide = { .dr = fdr, .fine = gc.rmax, .ratio = 1.05, .rmax = 2 * gc.rmax };
    result a = cycle(&m, adh_grid_alloc(gc.n, gc.dr));
    result w = cycle(&m, adh_rings_alloc(&wide));
    ok(a.hyst > 0 && a.pulloff < 0 && a.jump_out > a.jump_in, "the cycle has a loop: %.4g fJ", a.hyst * 1e15);
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("the uniform grid 1.5x finer (the automatic grid's cycle on 1.5x the nodes)");
    } else {
        result f = cycle(&m, adh_grid_alloc(fine, fdr));
        agree("1.5x finer, same Rmax", &a, &f);
    }
    agree("1.5x finer, 2x Rmax (graded past the automatic radius)", &a, &w);
    return tap_done();
}
