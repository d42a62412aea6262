/* Both kernels against the closed form for a uniform pressure on a disk:
 * u(r) = -(2/E) p D(r, a), D(r,a) = (4a/pi) E(r^2/a^2) inside, and
 * (4r/pi)[E(a^2/r^2) - (1 - a^2/r^2) K(a^2/r^2)] outside, with D(r,a) the
 * integral of the kernel k(r,t) t dt over t from 0 to a (include/adhere/kernel.h). */
#include <math.h>
#include <stdlib.h>

#include "adhere/kernel.h"
#include "tap.h"

/* Largest relative error of W p (p = 1 on nodes inside a) against D(r_n, a),
 * over nodes at least `skip` cells away from the disk edge. */
static double disk_error(const adh_kernel *k, const adh_grid *g, size_t m, size_t skip, double *at)
{
    size_t n = g->n;
    double *p = calloc(n, sizeof *p), *out = calloc(n, sizeof *out), *scr = calloc(n, sizeof *scr);
    for (size_t j = 0; j < m; j++)
        p[j] = 1.0;
    adh_kernel_apply(k, p, out, scr);
    double a = (double)m * g->dr, worst = 0;
    for (size_t i = 0; i < n; i++) {
        if ((i + skip >= m && i < m + skip))
            continue;
        double want = adh_disk_integral(g->r[i], a);
        double e = fabs(out[i] - want) / want;
        if (e > worst) {
            worst = e;
            *at = g->r[i] / a;
        }
    }
    free(p), free(out), free(scr);
    return worst;
}

int main(void)
{
    /* Closed-form checks of D itself: centre 2a (Boussinesq: u(0) = -4pa/E),
     * edge 4a/pi, far field a^2/r (a point load of the same total). */
    ok_rel(adh_disk_integral(0, 3e-7), 6e-7, 1e-14, "D(0,a) = 2a");
    ok_rel(adh_disk_integral(3e-7, 3e-7), 4 * 3e-7 / M_PI, 1e-12, "D(a,a) = 4a/pi");
    ok_rel(adh_disk_integral(1e-3, 1e-7), 1e-14 / 1e-3, 1e-6, "D(r>>a) -> a^2/r");
    ok(fabs(adh_disk_integral(3e-7 * (1 + 1e-12), 3e-7) - adh_disk_integral(3e-7 * (1 - 1e-12), 3e-7)) < 1e-15,
       "D is continuous across r = a");

    adh_grid *g = adh_grid_alloc(400, 1.5e-9);
    adh_kernel *ring = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
    adh_kernel *paper = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    ok(ring && paper, "kernels of 400 nodes allocate");
    double at = 0;
    double er = disk_error(ring, g, 100, 0, &at);
    ok(er < 1e-11, "ring kernel reproduces the disk formula at every node: worst rel error %.2e (tol 1e-11)", er);
    /* The paper's collocation kernel is a quadrature: exact only as r/dr grows.
     * Away from the disk edge (where the pressure jumps) it is within 1 %. */
    double ep = disk_error(paper, g, 100, 3, &at);
    ok(ep < 1e-3, "paper kernel within 0.1%% of the disk formula 3 cells from the edge: worst %.2e at r/a = %.3f", ep, at);
    double ep_all = disk_error(paper, g, 100, 0, &at);
    ok(ep_all < 2e-3, "paper kernel within 0.2%% of the disk formula at every node: worst %.2e at r/a = %.3f", ep_all, at);

    /* Symmetry of k (eq 9) is what lets the paper kernel use dsymv. */
    double asym = 0;
    for (size_t i = 0; i < g->n; i += 37)
        for (size_t j = 0; j < g->n; j += 41)
            if (i != j)
                asym = fmax(asym, fabs(adh_kernel_entry(paper, i, j) / g->r[j] - adh_kernel_entry(paper, j, i) / g->r[i]) /
                                      (adh_kernel_entry(paper, i, j) / g->r[j]));
    ok(asym < 1e-12, "paper kernel k(r,t) is symmetric: worst %.2e", asym);

    /* The kernel scales with the grid: W(dr) = dr W(1), so a material change
     * never needs a rebuild and a grid change always does. */
    adh_grid *g2 = adh_grid_alloc(400, 3e-9);
    adh_kernel *ring2 = adh_kernel_alloc(g2, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
    ok_rel(adh_kernel_entry(ring2, 7, 50), 2 * adh_kernel_entry(ring, 7, 50), 1e-12, "kernel doubles with the spacing");

    adh_kernel_type t;
    ok(adh_kernel_parse("ring", &t) == 0 && t == ADH_KERNEL_RING && adh_kernel_parse("Ring", &t) != 0,
       "kernel names parse: ring yes, Ring no");
    adh_kernel_free(ring2), adh_grid_free(g2);
    adh_kernel_free(ring), adh_kernel_free(paper), adh_grid_free(g);
    return tap_done();
}
