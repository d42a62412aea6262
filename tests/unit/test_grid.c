/* The grid's resolution check and the automatic grid (adh_grid_check,
 * adh_rings_choose), and one cheap point of the resolution study in docs/convergence.md:
 * at the limit the pull-off and hysteresis are within 1 % of a grid four
 * times finer, and a grid of one edge-zone width is not. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/static.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/protocol.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "adhere/cycle.h"
#include "tap.h"

static adh_material at_sigma(double sigma)
{
    adh_material m = adh_material_default();
    m.E = adh_material_modulus_at_sigma(&m, sigma);
    return m;
}

static void check_and_choose(void)
{
    adh_material m = adh_material_default();
    m.E = 3e8; /* Figure 4, sigma = 7.5: l = 3.5 nm on the paper's 1.5 nm grid */
    adh_grid_report r;
    adh_grid_check(&m, ADH_GRID_RELAX, 1000, 1.5e-9, &r);
    ok(fabs(r.edge_nodes - 2.34) < 0.02, "Figure 4: l/spacing = %.3f (3.51 nm over 1.5 nm)", r.edge_nodes);
    ok(r.resolved, "Figure 4's paper grid resolves the relaxation (limit %.2f l = %.3g m)", r.limit, r.max_spacing);
    adh_grid_check(&m, ADH_GRID_STATIC, 1000, 1.5e-9, &r);
    ok(!r.resolved, "but not the static curve (limit %.2f l = %.3g m)", r.limit, r.max_spacing);

    size_t n;
    double dr;
    adh_rings_choice gc;
    int rc = adh_rings_choose(&m, ADH_GRID_RELAX, -5e-9, 1, &gc, NULL, 0, NULL);
    ok(rc == ADH_SUCCESS && gc.n == 1000 && isnan(gc.dr) && !gc.graded,
       "Figure 4 relaxation: the automatic grid is the paper's (N = %zu)", gc.n);
    char why[1024];
    unsigned fix;
    int bad = 0, refused = 0, graded = 0;
    for (double sigma = 2.25; sigma <= 200; sigma *= 1.5) {
        adh_material s = at_sigma(sigma);
        for (int use = ADH_GRID_RELAX; use <= ADH_GRID_STATIC; use++) {
            rc = adh_rings_choose(&s, (adh_grid_use)use, -5e-9, 1, &gc, why, sizeof why, &fix);
            /* a refusal names sigma and the memory in quantities (never a
             * flag), and says what to change as bits for the driver's words */
            if (rc == ADH_EGRID && strstr(why, "sigma = ") && strstr(why, "MB") && !strstr(why, "--") &&
                (fix & ADH_FIX_FORCE) && (fix & ADH_FIX_NODES)) {
                refused++;
                continue;
            }
            n = gc.n;
            dr = isnan(gc.dr) ? adh_grid_spacing_for(&s, n) : gc.dr;
            adh_grid *g = NULL;
            if (gc.graded) {
                adh_rings_spec spec = { .dr = gc.dr, .fine = gc.fine, .ratio = gc.ratio, .rmax = gc.rmax };
                g = adh_rings_alloc(&spec);
                graded++;
            } else {
                g = adh_grid_alloc(n, dr);
            }
            adh_grid_check(&s, (adh_grid_use)use, n, g ? g->dr : NAN, &r);
            adh_protocol_settings ps = adh_protocol_settings_default();
            if (rc != ADH_SUCCESS || !g || g->n != n || !r.resolved ||
                n > (gc.hierarchical ? (size_t)ADH_GRID_NODES_MAX : (size_t)ADH_GRID_MAX_NODES) ||
                adh_protocol_check(&ps, &s, g, why, sizeof why, NULL) != ADH_SUCCESS ||
                adh_rings_check(g, &s, -5e-9, why, sizeof why, NULL) != ADH_SUCCESS) {
                bad++;
                printf("# sigma = %.3g use %d: N = %zu, dr = %.3g: %s\n", sigma, use, n, dr, why);
            }
            adh_grid_free(g);
        }
    }
    ok(bad == 0 && refused > 0 && graded > 0,
       "sigma = 2.25 ... 200: the automatic grid is resolved, within the budget and passes the protocol and fine-band "
       "checks, or is refused naming sigma, the memory and what to do (%d not; %d graded, %d refused)", bad, graded, refused);
    /* the uniform grid stays where it resolves with at most the paper's N */
    adh_material mid = at_sigma(15);
    rc = adh_rings_choose(&mid, ADH_GRID_RELAX, -5e-9, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && !gc.graded && gc.n <= ADH_GRID_UNIFORM_MAX_NODES,
       "sigma = 15 relaxation: uniform, N = %zu", gc.n);
    adh_material soft22 = at_sigma(22.5);
    rc = adh_rings_choose(&soft22, ADH_GRID_RELAX, -5e-9, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && gc.graded && gc.dr <= 0.45 * adh_edge_zone(&soft22) * (1 + 1e-9) &&
       gc.fine >= adh_rings_contact_estimate(&soft22, -5e-9),
       "sigma = 22.5 relaxation: graded, %zu rings, fine %.3g m to %.3g m (the contact at the turn %.3g m)", gc.n, gc.dr,
       gc.fine, adh_rings_contact_estimate(&soft22, -5e-9));
    rc = adh_rings_choose(&soft22, ADH_GRID_RELAX, -5e-9, 0, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && !gc.graded, "with the paper's kernel asked for, it stays uniform (N = %zu)", gc.n);
    rc = adh_rings_choose(&mid, ADH_GRID_STATIC, -5e-9, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && gc.graded && gc.n > ADH_STATIC_EXACT_MAX_NODES && gc.n <= ADH_GRID_STATIC_MAX_NODES &&
           gc.dr <= 0.3 * adh_edge_zone(&mid) * (1 + 1e-9),
       "the static curve at sigma = 15 runs on a resolved graded grid of %zu rings (stepping over lattice folds)",
       gc.n);
    adh_material st75 = at_sigma(75);
    rc = adh_rings_choose(&st75, ADH_GRID_STATIC, -5e-9, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && gc.graded && gc.hierarchical && gc.n <= ADH_GRID_STATIC_MAX_NODES,
       "the static curve at sigma = 75 runs on a resolved graded grid of %zu rings", gc.n);
    adh_material st120 = at_sigma(120);
    rc = adh_rings_choose(&st120, ADH_GRID_STATIC, -5e-9, 1, &gc, why, sizeof why, &fix);
    ok(rc == ADH_EGRID && strstr(why, "sigma = 120") && strstr(why, "use the relaxation") && (fix & ADH_FIX_MODE),
       "the static curve at sigma = 120 is refused before it starts (%s)", why);
    /* soft contacts as the H^2 operator allows: sigma = 75 runs resolved on
     * graded rings; a dense (uniform) grid there is beyond its budget */
    adh_material soft = at_sigma(75);
    rc = adh_rings_choose(&soft, ADH_GRID_RELAX, -5e-9, 1, &gc, why, sizeof why, NULL);
    ok(rc == ADH_SUCCESS && gc.graded && gc.hierarchical && gc.n > ADH_GRID_MAX_NODES && gc.n <= ADH_GRID_NODES_MAX &&
           gc.dr <= 0.45 * adh_edge_zone(&soft) * (1 + 1e-9) && gc.fine >= adh_rings_contact_estimate(&soft, -5e-9),
       "sigma = 75 relaxation: graded, resolved, %zu rings held as H^2", gc.n);
    rc = adh_rings_choose(&soft, ADH_GRID_RELAX, -5e-9, 0, &gc, why, sizeof why, &fix);
    ok(rc == ADH_EGRID && strstr(why, "sigma = 75") && strstr(why, "dense kernel") &&
           fix == (ADH_FIX_NODES | ADH_FIX_SPACING | ADH_FIX_FORCE),
       "with the paper's kernel (uniform, dense) sigma = 75 is refused, naming sigma, the memory and what to do (%s)", why);
    adh_material softer = at_sigma(225);
    rc = adh_rings_choose(&softer, ADH_GRID_RELAX, -5e-9, 1, &gc, why, sizeof why, &fix);
    ok(rc == ADH_EGRID && strstr(why, "sigma = 225") && strstr(why, "H^2 kernel") && (fix & ADH_FIX_FORCE),
       "sigma = 225 needs more rings than the grid limit: refused, naming sigma, the memory and what to do (%s)", why);
}

/* pull-off and hysteresis of one cycle at sigma on a grid of x edge-zone
 * widths out to 12 sqrt(R z0), turning at -2 z0 (the study's setting) */
static int cycle(double sigma, double x, int statik, double *pulloff, double *hyst)
{
    adh_material m = at_sigma(sigma);
    double dr = x * adh_edge_zone(&m);
    size_t n = (size_t)ceil(12.0 * sqrt(m.R * m.z0) / dr);
    adh_grid *g = adh_grid_alloc(n, dr);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_run run;
    adh_run_init(&run);
    int rc;
    if (statik) {
        adh_static_settings s = adh_static_settings_default();
        s.h0_start = adh_protocol_auto_start(&m, 0.05e-9);
        s.h0_end = -2 * m.z0;
        adh_static_result res;
        rc = adh_runner_static_curve(g, k, &m, &s, NULL, NULL, &run, &res);
        *pulloff = res.pulloff_F;
        *hyst = adh_cycle_static_hysteresis(&run, 0.001e-9);
    } else {
        adh_relax_settings rs = adh_relax_settings_default();
        /* eps means one drive on every grid (adh_relax_measure) */
        rs.eps = 1e-12;
        adh_protocol_settings ps = adh_protocol_settings_default();
        ps.turns[0] = -2 * m.z0;
        rc = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &run);
        const adh_turn_result *t = adh_run_main_turn(&run);
        *pulloff = t ? t->pulloff_F : NAN;
        *hyst = adh_cycle_run_hysteresis(&run);
    }
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc;
}

static void study_point(const char *name, double sigma, int statik)
{
    double limit = adh_grid_edge_spacing(statik ? ADH_GRID_STATIC : ADH_GRID_RELAX);
    double pf, hf, pl, hl, pc, hc;
    int rc = cycle(sigma, 0.125, statik, &pf, &hf) | cycle(sigma, limit, statik, &pl, &hl) |
             cycle(sigma, 1.0, statik, &pc, &hc);
    double ep = fabs(pl / pf - 1), eh = fabs(hl / hf - 1);
    ok(rc == ADH_SUCCESS && ep < 0.01 && eh < 0.01,
       "%s, sigma = %g: at %.2f l pull-off and hysteresis within 1 %% of 0.125 l (%.2f %%, %.2f %%)", name, sigma,
       limit, 100 * ep, 100 * eh);
    double cp = fabs(pc / pf - 1), ch = fabs(hc / hf - 1);
    ok(cp > 0.01 || ch > 0.01, "%s, sigma = %g: at 1 l they are not (%.1f %%, %.1f %%)", name, sigma, 100 * cp, 100 * ch);
}

int main(void)
{
    check_and_choose();
    study_point("static", 2.25, 1);
    study_point("relaxation", 1, 0);
    return tap_done();
}
