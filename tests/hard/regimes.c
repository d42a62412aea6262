/* Hard cases stay numerically stable: the regimes users will try, each run
 * on the default scaled grid (small N), each checked for finite numbers,
 * converged-or-flagged steps, continuity except at reported jumps, and the
 * physics signs. Regimes outside the model are refused before running. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/grid.h"
#include "adhere/protocol.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "scene/config.h"
#include "tap.h"

typedef struct hard_case {
    const char *name;
    adh_run_spec cfg;
} hard_case;

/* Figure 1's material (sigma = 2.25): its contact edge zone (~12 nm) is
 * resolved by the N = 100 grid (15 nm), so lattice trapping does not mask the
 * physics signs checked below; harder materials get finer grids. */
static adh_run_spec base(void)
{
    adh_config d;
    adh_config_default(&d);
    adh_run_spec c = d.spec;
    c.mat.E = 1e9;
    c.grid.use.nodes = 100;
    c.relax.eps = 3e-12;
    c.proto.turns[0] = -2e-9;
    return c;
}

typedef struct outcome {
    int rc;
    adh_run run;
    char why[512];
} outcome;

static int run_config(const adh_run_spec *c, outcome *o)
{
    memset(o, 0, sizeof *o);
    adh_run_init(&o->run);
    adh_grid *g = adh_grid_alloc(c->grid.use.nodes, adh_config_spacing(c));
    o->rc = adh_material_validate(&c->mat, o->why, sizeof o->why);
    if (o->rc == ADH_SUCCESS)
        o->rc = adh_protocol_check(&c->proto, &c->mat, g, o->why, sizeof o->why, NULL);
    if (o->rc != ADH_SUCCESS) {
        adh_grid_free(g);
        return o->rc;
    }
    /* The operator the program itself would hold this grid in (H² on a
     * uniform grid of 256 nodes or more): the regimes users run. */
    adh_kernel *k = adh_kernel_alloc(
        g, &(adh_kernel_settings){ .type = c->grid.use.kernel, .storage = adh_config_storage_for(c, ADH_MODE_RELAX) },
        NULL);
    o->rc = adh_runner_rule(&adh_rule_relax, g, k, &c->mat, &c->relax, &c->proto, NULL, NULL, &o->run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return o->rc;
}

/* The checks every regime must pass; returns the number of failures. */
static void check_run(const char *name, const adh_run_spec *c, outcome *o)
{
    adh_run *r = &o->run;
    ok(o->rc == ADH_SUCCESS && r->nrows > 1, "%s: runs to the end (%s, %zu steps, %zu iterations)", name,
       adh_strerror(o->rc), r->nrows, r->iterations);
    size_t nonfinite = 0, flagged = 0;
    for (size_t i = 0; i < r->nrows; i++) {
        const adh_obs *w = &r->rows[i];
        /* F_rigid is NAN by definition where rigid spheres would overlap. */
        int rigid_ok = w->h0 > 0 ? isfinite(w->F_rigid) : isnan(w->F_rigid);
        if (!(isfinite(w->h0) && isfinite(w->F) && isfinite(w->delta) && isfinite(w->hc) && isfinite(w->a) &&
              isfinite(w->angle) && rigid_ok && w->hc > 0))
            nonfinite++;
        flagged += !w->converged;
    }
    ok(nonfinite == 0, "%s: every number finite, every gap positive (%zu bad rows)", name, nonfinite);
    ok(flagged == r->unconverged, "%s: unconverged steps are flagged and counted (%zu rows, %zu counted)", name, flagged,
       r->unconverged);

    /* Continuity: along a path the force moves by a small part of its range,
     * except where contact is made or lost (the reported jumps). */
    double flo = INFINITY, fhi = -INFINITY;
    for (size_t i = 0; i < r->nrows; i++)
        flo = fmin(flo, r->rows[i].F), fhi = fmax(fhi, r->rows[i].F);
    size_t breaks = 0;
    for (size_t i = 1; i < r->nrows; i++) {
        const adh_obs *p = &r->rows[i - 1], *q = &r->rows[i];
        if (p->path != q->path || (p->a > 0) != (q->a > 0) || !q->converged)
            continue;
        if (fabs(q->F - p->F) > 0.25 * (fhi - flo))
            breaks++;
    }
    ok(breaks == 0, "%s: force continuous except at the jumps (%zu breaks)", name, breaks);

    if (c->proto.nturns == 0)
        return;
    ok(isfinite(r->jump_in_h0) && r->jump_in_h0 > 0, "%s: jump into contact before the surfaces would touch (h0 = %.3g nm)",
       name, r->jump_in_h0 * 1e9);
    /* Unloading force at or below loading force in contact, within the
     * convergence noise: a step stops with an rms residual up to eps sqrt(N),
     * worth about E a eps sqrt(N) of force over a contact a (contact
     * stiffness 2E*a = E a); the error can exceed the residual by 1/(1 - lambda)
     * near the instabilities, and both branches carry it: 4 E a eps sqrt(N). */
    double amax = 0;
    for (size_t i = 0; i < r->nrows; i++)
        amax = fmax(amax, r->rows[i].a);
    double noise = 4.0 * c->mat.E * amax * c->relax.eps * sqrt((double)c->grid.use.nodes);
    size_t pairs = 0, wrong = 0;
    double excess = 0, at = 0;
    for (size_t i = 0; i < r->nrows; i++) {
        const adh_obs *u = &r->rows[i];
        if (u->branch > 0 || u->a == 0)
            continue;
        for (size_t j = 0; j < r->nrows; j++) {
            const adh_obs *l = &r->rows[j];
            if (l->branch < 0 || l->a == 0 || fabs(l->h0 - u->h0) > 1e-3 * c->proto.step)
                continue;
            pairs++;
            if (u->F > l->F + noise) {
                wrong++;
                if (u->F - l->F > excess)
                    excess = u->F - l->F, at = u->h0;
            }
        }
    }
    ok(wrong == 0, "%s: unloading force <= loading force + %.2g N of convergence noise in contact (%zu of %zu pairs wrong, worst %.2g N at %.2f nm)",
       name, noise, wrong, pairs, excess, at * 1e9);
}

#include <time.h>
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void regime(const char *name, adh_run_spec c)
{
    outcome o;
    double t0 = now();
    run_config(&c, &o);
    printf("# %s: %.2f s\n", name, now() - t0);
    check_run(name, &c, &o);
    adh_run_free(&o.run);
}

static void refused(const char *name, adh_run_spec c, const char *mentions)
{
    outcome o;
    int rc = run_config(&c, &o);
    ok(rc != ADH_SUCCESS && strstr(o.why, mentions) && o.run.nrows == 0,
       "%s: refused before running, message mentions '%s': %s", name, mentions, o.why);
    adh_run_free(&o.run);
}

static double sigma_to_E(const adh_run_spec *c, double sigma)
{
    return adh_material_modulus_at_sigma(&c->mat, sigma);
}

int main(void)
{
    adh_run_spec c;
    const double sigmas[] = { 0.01, 0.1, 1, 10, 100 };
    for (size_t i = 0; i < 4; i++) {
        char name[64];
        c = base();
        c.mat.E = sigma_to_E(&c, sigmas[i]);
        if (sigmas[i] >= 10) { /* the edge zone is ~0.04 sqrt(R z0): refine */
            c.grid.use.nodes = 200;
            c.proto.turns[0] = -1e-9;
        }
        snprintf(name, sizeof name, "sigma = %g (N = %zu)", sigmas[i], c.grid.use.nodes);
        /* under ASan sigma = 10 on 200 nodes runs no line or branch of the
         * library that the other regimes and the pass's other tests do not
         * (gcov): the plain build asserts it */
        if (sigmas[i] >= 10 && tap_sanitized_short())
            tap_sanitized_leaves_out("sigma = 10 on N = 200 (the other sigmas' runs, and sigma = 100's approach)");
        else
            regime(name, c);
    }
    /* sigma = 100: the contact edge zone (0.26 nm) is far below the default
     * grids' spacing; the program says so instead of iterating in vain, and
     * the approach to contact, which has no edge zone, still runs. */
    c = base(); c.mat.E = sigma_to_E(&c, 100);
    refused("sigma = 100 on the N = 100 grid", c, "too coarse for this contact");
    c.grid.use.nodes = 1000;
    refused("sigma = 100 on the N = 1000 grid", c, "edge zone is about");
    c.grid.use.nodes = 100; c.proto.nturns = 0; c.proto.unload = 0;
    regime("sigma = 100, approach to contact", c);

    c = base(); c.mat.R = 1.5e-2; c.mat.E = 1e11; c.mat.A = 5e-19;
    regime("R = 1.5 cm (Figure 5 material)", c);
    c = base(); c.mat.R = 0.5e-6; c.mat.E = 1e9;
    regime("R = 0.5 um", c);
    c = base(); c.mat.R = 10e-9;
    refused("R = 10 nm", c, "h0 << R");
    c = base(); c.mat.z0 = 0.1e-9; c.mat.E = sigma_to_E(&c, 2.0); c.proto.turns[0] = -0.5e-9;
    regime("z0 = 0.1 nm (sigma = 2)", c);
    c = base(); c.mat.z0 = 1e-9;
    regime("z0 = 1 nm", c);
    c = base(); c.mat.A = 1e-21;
    regime("A = 1e-21 J", c);
    c = base(); c.mat.A = 1e-18; c.mat.E = 3e9;
    regime("A = 1e-18 J", c);

    /* Turning points: just past the jump-in, deep, and several at once. */
    c = base(); c.proto.nturns = 0; c.proto.unload = 0;
    outcome pre;
    run_config(&c, &pre);
    double jump = pre.run.jump_in_h0;
    adh_run_free(&pre.run);
    c = base(); c.proto.turns[0] = jump - c.proto.step;
    regime("turn one step past the jump-in", c);
    c = base(); c.proto.turns[0] = -20e-9; c.relax.eps = 10e-12;
    regime("turn at -20 nm", c);
    c = base(); c.proto.nturns = 3; c.proto.turns[0] = -3e-9; c.proto.turns[1] = 1e-9; c.proto.turns[2] = -1e-9;
    regime("three turning points", c);
    c = base(); c.proto.dwell = 20000;
    regime("long dwell (20000 iterations)", c);

    c = base(); c.proto.step = 0.005e-9; c.proto.turns[0] = jump - 0.2e-9; c.proto.start = jump + 1.5e-9;
    regime("step d = 0.005 nm", c);
    c = base(); c.proto.step = 0.5e-9;
    regime("step d = 0.5 nm", c);
    c = base(); c.relax.eps = 10e-12;
    regime("eps = 10 pm", c);
    c = base(); c.relax.eps = 0.05e-12; c.proto.turns[0] = jump - 0.3e-9;
    regime("eps = 0.05 pm", c);
    c = base(); c.grid.use.kernel = ADH_KERNEL_RING;
    regime("ring kernel", c);

    /* The largest grid: precontact only, and an iteration cap that the jump
     * step must hit: the cap is reported, never hidden, and nothing breaks. */
    c = base(); c.grid.use.nodes = 4000; c.proto.nturns = 0; c.proto.unload = 0; c.relax.eps = 1e-12; c.relax.max_iter = 20;
    outcome big;
    run_config(&c, &big);
    check_run("N = 4000, capped at 20 iterations", &c, &big);
    ok(big.run.unconverged > 0, "N = 4000: the jump step hit the cap and was counted (%zu)", big.run.unconverged);
    adh_run_free(&big.run);

    c = base(); c.grid.use.spacing = 40e-9;
    refused("spacing 40 nm", c, "too coarse");
    c = base(); c.grid.use.nodes = 20; c.grid.use.spacing = 10e-9;
    refused("a 0.2 um grid", c, "too short");
    c = base(); c.proto.turns[0] = -300e-9;
    refused("turn at -300 nm (R/50 = 200 nm)", c, "too deep");
    return tap_done();
}
