/* The HODLR solver (adhere/hodlr.h) against dense LAPACK on the ring
 * kernel of a graded grid: the held W's product, and A = I + alpha W
 * diag(d) solved and its determinant's sign, for a d shaped like the
 * static mode's p'(h) (large and negative over a contact, positive at its
 * edge, nothing outside), with the sign flipped by a negative eigenvalue. */
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/hodlr.h"
#include "adhere/kernel.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "tap.h"


static double entry(void *ctx, size_t i, size_t j)
{
    return adh_kernel_entry(ctx, i, j);
}

/* Solves the dense A x = b and returns det A's sign (0: singular). */
static int dense_solve(const double *W, size_t n, double alpha, const double *d, double *b)
{
    double *A = malloc(n * n * sizeof *A);
    lapack_int *piv = malloc(n * sizeof *piv), nn = (lapack_int)n;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++)
            A[i + j * n] = (i == j) + alpha * W[i * n + j] * d[j];
    int s = LAPACKE_dgetrf(LAPACK_COL_MAJOR, nn, nn, A, nn, piv) == 0;
    for (size_t i = 0; i < n && s; i++)
        s *= (piv[i] != (lapack_int)i + 1 ? -1 : 1) * (A[i + i * n] < 0 ? -1 : 1);
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', nn, 1, A, nn, piv, b, nn);
    free(A), free(piv);
    return s;
}

int main(void)
{
    /* rings of 1 nm to 400 nm, then x1.05 to 1.5 um */
    adh_rings_spec rs = { .dr = 1e-9, .fine = 400e-9, .ratio = 1.05, .rmax = 1.5e-6 };
    adh_grid *g = adh_rings_alloc(&rs);
    adh_kernel_settings ks = { .type = ADH_KERNEL_RING, .storage = ADH_STORAGE_H2 };
    adh_kernel *k = adh_kernel_alloc(g, &ks, NULL);
    size_t n = g->n;
    adh_hodlr *h = adh_hodlr_alloc(n, entry, k, 1e-9, 32);
    ok(h != NULL, "assembled (N = %zu, largest rank %zu, %.2f MB)", n, h ? adh_hodlr_max_rank(h) : 0,
       h ? adh_hodlr_bytes(h) / 1048576.0 : 0);
    double *W = malloc(n * n * sizeof *W), *v = malloc(4 * n * sizeof *v), *y = v + n, *yd = y + n, *d = yd + n;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            W[i * n + j] = adh_kernel_entry(k, i, j);
    for (size_t i = 0; i < n; i++)
        v[i] = cos(0.05 * (double)i) + 0.3 * sin(1.7 * (double)i);
    adh_hodlr_apply(h, v, y);
    for (size_t i = 0; i < n; i++) {
        yd[i] = 0;
        for (size_t j = 0; j < n; j++)
            yd[i] += W[i * n + j] * v[j];
    }
    ok(tap_maxrel(y, yd, n) < 1e-7, "product within 1e-7 of dense (%.1e)", tap_maxrel(y, yd, n));

    /* d as -(2/E) p'(h) on a contact of radius 250 nm: large and positive
     * inside (alpha d W ~ 4 per ring, as at the resolved static limit), a
     * negative bump at the edge (p' > 0 past the pressure's minimum),
     * decaying as h^-4 outside */
    double alpha = 1.0;
    for (int sgn = 0; sgn < 2; sgn++) {
        double scale = sgn ? 40.0 : 1.0; /* the larger bump makes one eigenvalue negative */
        for (size_t i = 0; i < n; i++) {
            double r = g->r[i] * 1e9;
            d[i] = r < 250 ? 4.0 / 1e-9 : 0;
            d[i] -= scale / 1e-9 * (r > 250 && r < 251); /* one ring: one eigenvalue */
            d[i] += 4.0 / 1e-9 / pow(1 + fmax(0, r - 250.0), 4) * (r >= 250);
        }
        int rc = adh_hodlr_factorize(h, alpha, d);
        for (size_t i = 0; i < n; i++)
            y[i] = yd[i] = v[i];
        adh_hodlr_solve(h, y);
        int ds = dense_solve(W, n, alpha, d, yd);
        ok(rc == ADH_SUCCESS && tap_maxrel(y, yd, n) < 1e-5, "solve (edge bump %g) within 1e-5 of dense LU (%.1e)", scale,
           tap_maxrel(y, yd, n));
        ok(ds != 0 && adh_hodlr_det_sign(h) == ds, "det sign %+d as dense LU's %+d", adh_hodlr_det_sign(h), ds);
        /* the single-precision copy: float rounding (6e-8) grown by the
         * conditioning, still far inside the preconditioner's 1e-4 */
        for (size_t i = 0; i < n; i++)
            yd[i] = v[i];
        adh_hodlr_solve_single(h, yd);
        ok(tap_maxrel(yd, y, n) < 1e-4 && tap_maxrel(yd, y, n) > 0,
           "single-precision solve (edge bump %g) within 1e-4 of the double one (%.1e)", scale, tap_maxrel(yd, y, n));
        /* a right side single precision cannot hold: the double solve */
        for (size_t i = 0; i < n; i++)
            y[i] = yd[i] = 1e300 * v[i];
        adh_hodlr_solve(h, y);
        adh_hodlr_solve_single(h, yd);
        ok(memcmp(y, yd, n * sizeof *y) == 0, "single-precision solve of a right side past FLT_MAX: the double one");
    }
    free(W), free(v);
    adh_hodlr_free(h);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
