/* Graded radial grids (adhere/rings.h): their geometry, the exact ring
 * kernel on arbitrary edges against the disk formula, the uniform grid as
 * the special case, and the convergence measure's weights. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "tap.h"

/* Largest relative error of W p against D(r_n, a) for p = 1 on rings [0, a = edge m]. */
static double disk_error(const adh_kernel *k, const adh_grid *g, size_t m)
{
    size_t n = g->n;
    double *p = calloc(3 * n, sizeof *p), *out = p + n, *scr = p + 2 * n;
    for (size_t j = 0; j < m; j++)
        p[j] = 1.0;
    adh_kernel_apply(k, p, out, scr);
    double a = adh_rings_edge(g, m), worst = 0;
    for (size_t i = 0; i < n; i++)
        worst = fmax(worst, fabs(out[i] - adh_disk_integral(g->r[i], a)) / adh_disk_integral(g->r[i], a));
    free(p);
    return worst;
}

int main(void)
{
    adh_rings_spec spec = { .dr = 1.5e-9, .fine = 300e-9, .ratio = 1.05, .rmax = 3e-6 };
    char why[256];
    ok(adh_rings_spec_validate(&spec, why, sizeof why) == 0, "a fine band then growth 1.05 is a valid spec");
    adh_grid *g = adh_rings_alloc(&spec);
    ok(g && g->graded && g->n == adh_rings_count(&spec), "graded grid allocates with the counted rings");
    size_t nf = 200;
    double worst_fine = 0, worst_ratio = 0, worst_mid = 0;
    int monotone = 1;
    for (size_t i = 0; i < g->n; i++) {
        double w = adh_rings_width(g, i);
        if (!(w > 0))
            monotone = 0;
        if (i < nf)
            worst_fine = fmax(worst_fine, fabs(w - spec.dr) / spec.dr);
        else
            worst_ratio = fmax(worst_ratio, w / adh_rings_width(g, i - 1));
        worst_mid = fmax(worst_mid, fabs(g->r[i] - 0.5 * (g->edge[i] + g->edge[i + 1])));
    }
    ok(monotone && worst_fine < 1e-9, "the first %zu rings are the fine width (worst rel %.1e)", nf, worst_fine);
    ok(worst_ratio <= spec.ratio * (1 + 1e-12) && worst_ratio > 1.0, "beyond the band each ring grows by the ratio (largest %.6f)", worst_ratio);
    ok(worst_mid == 0, "nodes at ring middles");
    ok(g->rmax >= spec.rmax && g->rmax < spec.rmax * spec.ratio + 1e-6, "last edge %.4g m reaches rmax %.4g m", g->rmax, spec.rmax);
    ok(g->n < 300, "far fewer rings than a uniform grid (%zu vs %.0f)", g->n, spec.rmax / spec.dr);
    ok_rel(g->dr, spec.dr, 1e-12, "dr is the finest width");

    double area = 0;
    for (size_t i = 0; i < g->n; i++)
        area += adh_rings_weight(g, i);
    ok_rel(area, 0.5 * g->rmax * g->rmax, 1e-12, "ring weights sum to rmax^2/2 (force is exact for uniform p)");
    ok(adh_rings_locate(g, 0.5 * (g->edge[250] + g->edge[251])) == 250 && adh_rings_locate(g, g->edge[250]) == 250 &&
           adh_rings_locate(g, 10 * g->rmax) == g->n - 1,
       "locate finds the ring holding a radius");

    /* The exact ring kernel on graded edges: a uniform pressure on [0, a]
     * gives D(r, a) at every node, a inside the band or out in the growth. */
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
    ok(k != NULL, "ring kernel on a graded grid allocates");
    double e1 = disk_error(k, g, 120), e2 = disk_error(k, g, 240);
    ok(e1 < 1e-11, "disk in the fine band: u = -(2/E) p D(r,a) at every node, worst rel %.1e", e1);
    ok(e2 < 1e-11, "disk edge in the growing rings: worst rel %.1e", e2);
    int st = ADH_SUCCESS;
    ok(adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, &st) == NULL && st == ADH_EINVAL,
       "the paper's kernel refuses a graded grid (ADH_EINVAL)");
    adh_kernel_free(k);

    /* Uniform edges through the graded path reproduce today's ring kernel. */
    size_t n = 300;
    adh_grid *u = adh_grid_alloc(n, 1.5e-9);
    double *edge = malloc((n + 1) * sizeof *edge);
    for (size_t j = 0; j <= n; j++)
        edge[j] = (double)j * 1.5e-9;
    adh_grid *ge = adh_rings_alloc_edges(n, edge);
    ok(ge && ge->graded, "grid from explicit uniform edges");
    adh_kernel_settings ring = { .type = ADH_KERNEL_RING };
    adh_kernel *ku = adh_kernel_alloc(u, &ring, NULL), *ke = adh_kernel_alloc(ge, &ring, NULL);
    double diff = 0, big = 0, dr_diff = 0;
    for (size_t i = 0; i < n; i++) {
        dr_diff = fmax(dr_diff, fabs(ge->r[i] - u->r[i]));
        for (size_t j = 0; j < n; j++) {
            diff = fmax(diff, fabs(adh_kernel_entry(ku, i, j) - adh_kernel_entry(ke, i, j)));
            big = fmax(big, fabs(adh_kernel_entry(ku, i, j)));
        }
    }
    ok(dr_diff <= 1e-14 * u->rmax, "same nodes to rounding (worst %.1e m)", dr_diff);
    ok(diff <= 1e-12 * big, "graded kernel on uniform edges = uniform ring kernel to rounding (max diff %.1e of %.1e)", diff, big);

    /* The convergence measure's weights (adh_relax_measure, tested in
     * test_eps): 1 on a uniform grid, a ring's width in fine widths. */
    double e2w[4] = { 0, 1e-9, 2e-9, 4e-9 }, wt[300];
    adh_grid *a3 = adh_rings_alloc_edges(3, e2w);
    adh_rings_change_weights(a3, INFINITY, wt);
    ok(wt[0] == 1 && wt[1] == 1 && fabs(wt[2] - 2) < 1e-12, "a wide ring weighs as the fine rings it spans");
    adh_rings_change_weights(u, INFINITY, wt);
    int ones = 1;
    for (size_t i = 0; i < n; i++)
        ones &= wt[i] == 1.0;
    ok(ones, "uniform grid: every weight exactly 1");
    ok(adh_rings_alloc_edges(3, (double[]){ 0, 2e-9, 1e-9, 3e-9 }) == NULL, "edges that do not increase are refused");

    adh_rings_spec bad = spec;
    bad.ratio = 1.2;
    ok(adh_rings_spec_validate(&bad, why, sizeof why) != 0 && strstr(why, "1.2") && strstr(why, "1.1"),
       "ratio 1.2 refused naming the value and the limit: %s", why);
    bad = spec;
    bad.rmax = 1e-7;
    ok(adh_rings_spec_validate(&bad, why, sizeof why) != 0 && adh_rings_alloc(&bad) == NULL, "rmax inside the fine band refused");

    /* The fine band's contact estimate: JKR's radius where it exceeds the
     * overlap estimate (soft, adhesive), never below either. */
    adh_material m = adh_material_default();
    m.E = 1e8; /* sigma = 22.5 */
    double h0 = -2e-9, est = adh_rings_contact_estimate(&m, h0), F, ov;
    double hertz = 1.5 * sqrt(2.0 * m.R * (m.z0 - h0));
    adh_jkr(&m, est, &F, &ov);
    ok(est > hertz && fabs(ov - (m.z0 - h0)) < 1e-3 * (m.z0 - h0),
       "sigma 22.5: estimate %.1f nm is JKR's at overlap z0 - h0 (%.3f nm), above the overlap rule's %.1f nm", est * 1e9, ov * 1e9, hertz * 1e9);
    m.E = 1e11; /* sigma = 0.02: stiff, the overlap rule is the larger */
    ok_rel(adh_rings_contact_estimate(&m, h0), hertz, 1e-12, "stiff spheres: the overlap rule's estimate");

    /* why a run stopped at the grid: the fine band's end, the grid's edge */
    char msg[400];
    double fr = adh_rings_fine_radius(g);
    adh_rings_edge_sentence(g, 1.01 * fr, msg, sizeof msg);
    ok(strstr(msg, "left the graded grid's fine band") && strstr(msg, "widen the fine band") && !strstr(msg, "--") &&
           adh_rings_edge_fix(g, 1.01 * fr) == (ADH_FIX_FINE_BAND | ADH_FIX_TURNS),
       "a contact past the fine band is named so, with what to change (in quantities, and as the fine band's and "
       "the turns' bits): %s", msg);
    adh_rings_edge_sentence(g, 0.95 * g->rmax, msg, sizeof msg);
    ok(strstr(msg, "reached the grid's edge") && strstr(msg, "0.9 Rmax") && strstr(msg, "a larger grid radius") &&
           adh_rings_edge_fix(g, 0.95 * g->rmax) == ADH_FIX_GRID_RADIUS,
       "a contact at 0.95 Rmax of a graded grid asks for a larger grid radius: %s", msg);
    adh_rings_edge_sentence(u, 0.95 * u->rmax, msg, sizeof msg);
    ok(strstr(msg, "more nodes or a larger spacing") &&
           adh_rings_edge_fix(u, 0.95 * u->rmax) == (ADH_FIX_NODES | ADH_FIX_SPACING),
       "a uniform grid's edge asks for more nodes or a larger spacing: %s", msg);
    adh_rings_edge_sentence(u, 0.5 * u->rmax, msg, sizeof msg);
    ok(strstr(msg, "within the grid") != NULL && adh_rings_edge_fix(u, 0.5 * u->rmax) == 0,
       "a uniform grid has no band to leave: %s", msg);

    adh_grid_free(a3);
    free(edge);
    adh_kernel_free(ku), adh_kernel_free(ke);
    adh_grid_free(ge), adh_grid_free(u), adh_grid_free(g);
    return tap_done();
}
