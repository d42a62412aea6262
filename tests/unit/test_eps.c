/* What eps bounds (adhere/relax.h, adh_relax_measure): on the paper's grid
 * the paper's [sum du^2]^(1/2) / N, digit for digit; on any other grid the
 * same continuum norm of the change over the paper grid's radius, so a
 * change sampled on a finer, a graded, a wider or a narrower grid measures
 * the same, where the paper's own measure moves with N and Rmax. Closed
 * forms and exact identities only. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "adhere/grid.h"
#include "adhere/relax.h"
#include "adhere/rings.h"
#include "tap.h"

/* A change like a relaxation's at the end of a step: smooth over the
 * contact (radius c), then flat, the drive step's shift relaxing out of
 * contact (at Figure 4, 33 pm from 0.3 um to the grid's edge). */
static double change_at(double r, double c)
{
    return 1e-12 * (r < c ? 1.0 - 0.5 * (r / c) * (r / c) : 0.5);
}

static double *sample(const adh_grid *g, double c)
{
    double *du = malloc(g->n * sizeof *du);
    for (size_t i = 0; i < g->n; i++)
        du[i] = change_at(g->r[i], c);
    return du;
}

/* The paper's measure as it reads on grid g, [sum du^2]^(1/2) / N. */
static double paper_measure(const adh_grid *g, const double *du)
{
    double ssq = 0;
    for (size_t i = 0; i < g->n; i++)
        ssq += du[i] * du[i];
    return sqrt(ssq) / (double)g->n;
}

/* the measure of the sampled change on g and its far rings */
static double measure_on(const adh_grid *g, const adh_material *m, double c, double *paper)
{
    double *du = sample(g, c), fr[ADH_RELAX_FAR_RINGS], fw[ADH_RELAX_FAR_RINGS], fdu[ADH_RELAX_FAR_RINGS];
    size_t nf = adh_relax_far_rings(g, m, fr, fw);
    for (size_t k = 0; k < nf; k++)
        fdu[k] = change_at(fr[k], c);
    double v = adh_relax_measure(g, m, du, fdu);
    if (paper)
        *paper = paper_measure(g, du);
    free(du);
    return v;
}

int main(void)
{
    adh_material m = adh_material_default();
    double ref = adh_grid_spacing_for(&m, 1000), c = 0.3e-6;
    ok(adh_relax_eps_ref_spacing(&m) == ref, "the reference spacing is the paper grid's, %.4g m", ref);
    ok(fabs(ref - 1.5e-9) < 1e-20, "1.5 nm at R = 10 um, z0 = 0.5 nm");

    /* the paper's grid, its spacing computed or written down: the paper's
     * arithmetic exactly */
    adh_grid *p = adh_grid_alloc(1000, ref), *p15 = adh_grid_alloc(1000, 1.5e-9);
    double pm, v = measure_on(p, &m, c, &pm);
    ok(v == pm, "paper's grid: the measure is [sum du^2]^(1/2)/N bit for bit (%.17g, %.17g)", v, pm);
    double *wt = malloc(1000 * sizeof *wt), fr[ADH_RELAX_FAR_RINGS], fw[ADH_RELAX_FAR_RINGS];
    int ones = adh_relax_change_weights(p, &m, wt) == 1.0 && adh_relax_change_weights(p15, &m, wt) == 1.0;
    for (size_t i = 0; i < 1000; i++)
        ones &= wt[i] == 1.0;
    ok(ones && adh_relax_far_rings(p, &m, fr, fw) == 0 && adh_relax_far_rings(p15, &m, fr, fw) == 0,
       "its scale and weights are exactly 1, no far rings, the spacing computed or written 1.5nm");
    free(wt);
    double v15 = measure_on(p15, &m, c, &pm);
    ok(v15 == pm, "1.5nm written down: the same digits");

    /* a finer grid over the same radius measures the same change the
     * same (to the sampling's O(dr^2)); the paper's measure falls as
     * 1/sqrt(N) */
    adh_grid *f = adh_grid_alloc(3000, ref / 3.0);
    double fp, vf = measure_on(f, &m, c, &fp);
    ok(fabs(vf / v - 1) < 1e-5, "3x finer, same Rmax: the measure within 1e-5 (%.3g)", vf / v - 1);
    ok(fabs(fp / pm * sqrt(3.0) - 1) < 1e-5, "where the paper's measure is 1/sqrt(3) of itself (%.4f)", fp / pm);
    /* 1.5x finer and 2x wider (Rmax 3 um): the rings past the paper's
     * radius are not counted, though the change is as large there */
    adh_grid *w = adh_grid_alloc(3000, ref / 1.5);
    double wp, vw = measure_on(w, &m, c, &wp);
    ok(fabs(vw / v - 1) < 1e-5, "1.5x finer, 2x Rmax: the measure within 1e-5 (%.3g)", vw / v - 1);
    ok(wp / pm < 0.75, "where the paper's measure falls to %.3f of itself", wp / pm);
    /* a radius that is no whole number of rings: the ring across R_ref counts in part */
    adh_grid *x = adh_grid_alloc(1400, ref * 1.3);
    double vx = measure_on(x, &m, c, NULL);
    ok(fabs(vx / v - 1) < 1e-3, "1.3x coarser, Rmax 1.82 um: the measure within 1e-3 (%.3g)", vx / v - 1);
    /* half the radius, 2x finer: the far rings out to R_ref count the
     * change there */
    adh_grid *h = adh_grid_alloc(1000, ref / 2);
    double hp, vh = measure_on(h, &m, c, &hp), sw = 0;
    size_t nf = adh_relax_far_rings(h, &m, fr, fw);
    for (size_t k = 0; k < nf; k++)
        sw += fw[k];
    ok(nf == ADH_RELAX_FAR_RINGS && fabs(fr[0] - h->rmax) < fw[0] && fabs(sw - (1000 * ref - h->rmax)) < 1e-18,
       "Rmax 0.75 um: %zu far rings span it to R_ref", nf);
    ok(fabs(vh / v - 1) < 1e-5, "2x finer, Rmax 0.75 um: the measure within 1e-5 (%.3g)", vh / v - 1);
    adh_grid *hs = adh_grid_alloc(400, ref / 2);
    double vhs = measure_on(hs, &m, c, NULL);
    ok(fabs(vhs / v - 1) < 1e-5, "2x finer, Rmax 0.3 um: within 1e-5 (%.3g)", vhs / v - 1);
    /* the closed form: ||du||^2 = int_0^c (1 - r^2/2c^2)^2 dr + (R_ref - c)/4, x 1e-24 */
    double rref = 1000 * ref, closed = 1e-12 * sqrt(c * (1 - 1.0 / 3 + 1.0 / 20) + 0.25 * (rref - c)) / (1000 * sqrt(ref));
    ok(fabs(v / closed - 1) < 1e-5, "and the paper grid's measure is the closed form's (%.3g)", v / closed - 1);

    /* a graded grid: the fine band over the contact, rings growing x1.05 */
    adh_rings_spec spec = { .dr = ref / 2, .fine = 0.4e-6, .ratio = 1.05, .rmax = 1.2e-6 };
    adh_grid *gr = adh_rings_alloc(&spec);
    double vg = measure_on(gr, &m, c, NULL);
    ok(gr && fabs(vg / v - 1) < 1e-4, "graded (%zu rings, fine %.3g m, Rmax %.3g m): the measure within 1e-4 (%.2g)",
       gr ? gr->n : 0, spec.dr, gr ? gr->rmax : 0, vg / v - 1);
    spec.rmax = 4e-6;
    adh_grid *gw = adh_rings_alloc(&spec);
    double vgw = measure_on(gw, &m, c, NULL);
    ok(gw && fabs(vgw / v - 1) < 1e-4, "and out to %.3g m: within 1e-4 (%.2g)", gw ? gw->rmax : 0, vgw / v - 1);

    /* the rounding floor: the paper's 256 DBL_EPSILON depth / sqrt(N) on
     * its grid, and the same on a finer one (rounding per node does not
     * shrink with the spacing) */
    double depth = 5e-9;
    ok_rel(adh_relax_eps_floor(depth), 256 * DBL_EPSILON * depth / sqrt(1000.0), 1e-12,
           "the rounding floor is 256 DBL_EPSILON depth / sqrt(1000) on every grid");

    adh_grid_free(p), adh_grid_free(p15), adh_grid_free(f), adh_grid_free(w), adh_grid_free(x), adh_grid_free(h);
    adh_grid_free(hs);
    adh_grid_free(gr), adh_grid_free(gw);
    return tap_done();
}
