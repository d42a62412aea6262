/* The two mixing rules of the relaxation (adhere(1), "The relaxation and its
 * mixing rules"): they must reach the same equilibrium, the momentum rule
 * must get there in fewer iterations where the contact is stiff, a whole
 * load/unload cycle must give the paper's rule's observables at equal eps,
 * and bad settings are refused. Small grids (N = 100-150) keep it quick. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "tap.h"

/* Relax at one position, in contact, from the undeformed surfaces down to
 * the given eps. Returns the status; copies u out. */
static int relax_at(const adh_grid *g, const adh_kernel *k, const adh_material *m, adh_mix_rule rule,
                    double eps, double h0, double *u, size_t *iters)
{
    adh_relax *w = adh_relax_alloc(g, k);
    adh_relax_settings rs = adh_relax_settings_default();
    rs.rule = rule;
    rs.eps = eps;
    rs.max_iter = 2000000;
    adh_relax_set(w, m, &rs, h0 + 3e-9);
    /* approach in 0.05 nm steps so the contact forms as in a run */
    int rc = ADH_SUCCESS;
    *iters = 0;
    for (double x = h0 + 3e-9 - 0.05e-9; x > h0 - 1e-15 && rc == ADH_SUCCESS; x -= 0.05e-9) {
        adh_relax_move(w, x);
        rc = adh_relax_iterate(w, 0);
        *iters += adh_relax_step_iterations(w);
    }
    memcpy(u, adh_relax_state(w)->u, g->n * sizeof *u);
    adh_relax_free(w);
    return rc;
}

/* Both rules relaxed at -1 nm to eps (n <= 150 nodes): their statuses, the
 * largest difference of the deformations, the momentum rule's central
 * deformation, and each rule's iterations. */
typedef struct both {
    int rp, rm;
    double worst, um0;
    size_t ip, im;
} both;

static both both_rules(const adh_grid *g, const adh_kernel *k, const adh_material *m, double eps)
{
    double up[150], um[150];
    both b;
    b.rp = relax_at(g, k, m, ADH_MIX_PAPER, eps, -1e-9, up, &b.ip);
    b.rm = relax_at(g, k, m, ADH_MIX_MOMENTUM, eps, -1e-9, um, &b.im);
    b.worst = 0;
    for (size_t i = 0; i < g->n; i++)
        b.worst = fmax(b.worst, fabs(up[i] - um[i]));
    b.um0 = um[0];
    return b;
}

static void same_equilibrium(void)
{
    adh_material m = adh_material_default(); /* Figure 4: sigma = 7.5 */
    size_t n = 120;
    adh_grid *g = adh_grid_alloc(n, 1.5e-6 / (double)n / 3.0);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    both b = both_rules(g, k, &m, 1e-15);
    ok(b.rp == ADH_SUCCESS && b.rm == ADH_SUCCESS, "both rules converge in contact at eps 1e-15 m (%d, %d)", b.rp,
       b.rm);
    /* eps 1e-15 m bounds the residual norm by 1e-15 N; the slow modes
     * amplify it (1/mu_min) into the deformation, still far below 1e-12 m */
    ok(b.worst < 1e-12, "paper and momentum reach the same deformation: max |du| = %.2g m < 1e-12 m", b.worst);
    ok(b.um0 < -1e-9, "the state compared is in contact: central flattening %.3g nm", -b.um0 * 1e9);
    ok(b.im * 2 < b.ip, "momentum needs under half the paper's iterations in contact (%zu vs %zu)", b.im, b.ip);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* A whole Figure 4 cycle on a small grid: jump-in, pull-off, jump-out and the
 * contact radius at the turn agree between the rules at equal eps. */
static void same_cycle(void)
{
    adh_material m = adh_material_default();
    size_t n = 150;
    adh_grid *g = adh_grid_alloc(n, 1.5e-6 / (double)n / 2.5);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = -2e-9;
    ps.nturns = 1;
    ps.unload = 1;
    adh_run run[2];
    adh_mix_rule rules[2] = { ADH_MIX_PAPER, ADH_MIX_MOMENTUM };
    int rc[2];
    for (int r = 0; r < 2; r++) {
        adh_relax_settings rs = adh_relax_settings_default();
        rs.rule = rules[r];
        rs.eps = 2e-12;
        adh_run_init(&run[r]);
        rc[r] = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &run[r]);
    }
    ok(rc[0] == ADH_SUCCESS && rc[1] == ADH_SUCCESS && run[0].nturns == 1 && run[1].nturns == 1,
       "a load/unload cycle succeeds with both rules");
    if (rc[0] == ADH_SUCCESS && rc[1] == ADH_SUCCESS && run[0].nturns == 1 && run[1].nturns == 1) {
        const adh_turn_result *a = &run[0].turns[0], *b = &run[1].turns[0];
        ok(fabs(run[0].jump_in_h0 - run[1].jump_in_h0) < 0.051e-9,
           "jump-in within one step: paper %.3f nm, momentum %.3f nm", run[0].jump_in_h0 * 1e9, run[1].jump_in_h0 * 1e9);
        ok(fabs(a->pulloff_F - b->pulloff_F) < 0.01 * fabs(a->pulloff_F),
           "pull-off within 1 %%: paper %.5g N, momentum %.5g N", a->pulloff_F, b->pulloff_F);
        ok(fabs(a->jump_out_h0 - b->jump_out_h0) < 0.11e-9,
           "jump-out within two steps: paper %.3f nm, momentum %.3f nm", a->jump_out_h0 * 1e9, b->jump_out_h0 * 1e9);
        ok(fabs(a->a_turn - b->a_turn) < 0.01 * a->a_turn,
           "contact radius at the turn within 1 %%: %.4g vs %.4g nm", a->a_turn * 1e9, b->a_turn * 1e9);
        ok(run[1].iterations * 3 < run[0].iterations, "momentum takes under a third of the iterations (%zu vs %zu)",
           run[1].iterations, run[0].iterations);
        size_t capped = 0;
        for (size_t i = 0; i < run[1].nrows; i++)
            capped += !run[1].rows[i].converged;
        ok(capped == 0, "every momentum step converged (%zu did not)", capped);
    }
    adh_run_free(&run[0]);
    adh_run_free(&run[1]);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* The momentum rule's beta against the contact's stiffness: the set beta
 * up to the reference, the slow modes' move per iteration held above it. */
static void scaled_rule(void)
{
    double b = 0.55, ref = (1 + b) / ((1 - b) * (1 + ADH_RELAX_MOMENTUM_REF));
    ok(adh_relax_scaled_momentum(b, 0) == b && adh_relax_scaled_momentum(b, 1000) == b &&
           adh_relax_scaled_momentum(b, ADH_RELAX_MOMENTUM_REF) == b,
       "beta is the set 0.55 up to the reference stiffness %g (Figures 4 and 8 unchanged)", ADH_RELAX_MOMENTUM_REF);
    int held = 1, rising = 1;
    double prev = b;
    for (double st = 3000; st <= 40000; st *= 1.3) {
        double x = adh_relax_scaled_momentum(b, st);
        double move = (1 + x) / ((1 - x) * (1 + st));
        held &= fabs(move - ref) < 1e-9 * ref;
        rising &= x > prev;
        prev = x;
    }
    ok(held, "above it the slow modes' move per iteration is held at its reference value");
    ok(rising, "beta rises with the stiffness (%.4f at 40 000)", prev);
    ok(adh_relax_scaled_momentum(b, 1e7) == ADH_RELAX_MOMENTUM_MAX, "beta stops at %.2f",
       ADH_RELAX_MOMENTUM_MAX);
    ok(adh_relax_scaled_momentum(0.99, 1e7) == 0.99 && adh_relax_scaled_momentum(0, 1e5) == 0,
       "a set beta above the cap is kept, and no momentum stays none");
}

/* A soft contact on a coarse grid, stiffer than the reference: the rule
 * raises beta as it says, never lowers it within a step, and still reaches
 * the paper's rule's equilibrium. */
static void stiff_contact(void)
{
    adh_material m = adh_material_default();
    m.E /= 10; /* sigma = 75, on 10 nm nodes */
    size_t n = 60;
    adh_grid *g = adh_grid_alloc(n, 1.5e-6 / (double)n / 2.5);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    both b = both_rules(g, k, &m, 1e-13);
    ok(b.rp == ADH_SUCCESS && b.rm == ADH_SUCCESS && b.worst < 1e-11,
       "stiff contact: both rules reach the same deformation (max |du| = %.2g m < 1e-11 m)", b.worst);
    ok(b.im * 5 < b.ip, "stiff contact: momentum needs under a fifth of the paper's iterations (%zu vs %zu)", b.im,
       b.ip);

    /* one more step, watched iteration by iteration */
    adh_relax *w = adh_relax_alloc(g, k);
    adh_relax_settings rs = adh_relax_settings_default();
    rs.eps = 1e-13;
    adh_relax_set(w, &m, &rs, 2e-9);
    int rc = ADH_SUCCESS;
    for (double x = 2e-9 - 0.05e-9; x > -1e-9 - 1e-15 && rc == ADH_SUCCESS; x -= 0.05e-9) {
        adh_relax_move(w, x);
        rc = adh_relax_iterate(w, 0);
    }
    adh_relax_move(w, -1.05e-9);
    double beta = adh_relax_momentum(w);
    int never_falls = 1, matches = 1;
    do {
        rc = adh_relax_iterate(w, 1);
        double x = adh_relax_momentum(w), st = adh_relax_stiffness(w);
        never_falls &= x >= beta;
        matches &= x >= adh_relax_scaled_momentum(rs.momentum, st);
        beta = x;
    } while (rc == ADH_CONTINUE);
    ok(rc == ADH_SUCCESS && adh_relax_stiffness(w) > ADH_RELAX_MOMENTUM_REF && beta > rs.momentum,
       "stiff contact: stiffness %.0f above the reference, beta in use %.3f above the set %.2f",
       adh_relax_stiffness(w), beta, rs.momentum);
    ok(never_falls && matches, "within the step beta never falls and is at least the stiffness's");
    adh_relax_free(w);
    adh_kernel_free(k);
    adh_grid_free(g);
}

static void settings(void)
{
    char why[256];
    adh_relax_settings s = adh_relax_settings_default();
    ok(s.rule == ADH_MIX_MOMENTUM && s.momentum == 0.55, "the default is momentum 0.55");
    s.momentum = 1.0;
    ok(adh_relax_settings_validate(&s, why, sizeof why) == ADH_EINVAL && strstr(why, "momentum = 1"),
       "momentum 1 is refused: %s", why);
    s.momentum = -0.1;
    ok(adh_relax_settings_validate(&s, why, sizeof why) == ADH_EINVAL, "momentum -0.1 is refused");
    s = adh_relax_settings_default();
    s.rule = (adh_mix_rule)7;
    ok(adh_relax_settings_validate(&s, why, sizeof why) == ADH_EINVAL && strstr(why, "paper or momentum"),
       "an unknown rule is refused: %s", why);
    adh_mix_rule r;
    ok(adh_mix_rule_parse("paper", &r) == 0 && r == ADH_MIX_PAPER && adh_mix_rule_parse("momentum", &r) == 0 &&
       r == ADH_MIX_MOMENTUM && adh_mix_rule_parse("fast", &r) != 0, "rule names parse, others do not");
}

int main(void)
{
    settings();
    scaled_rule();
    stiff_contact();
    /* Under ASan the cycle with both rules runs no line or branch of the
     * library that the stiff contact's relaxations and the pass's other
     * tests do not (gcov): its agreement stays in the plain build. */
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("the rules' equilibrium at eps 1e-15 m (both_rules, as the stiff contact's at 1e-13 m)");
        tap_sanitized_leaves_out("the load/unload cycle with both rules (the stiff contact's relaxations with both)");
    } else {
        same_equilibrium();
        same_cycle();
    }
    return tap_done();
}
