/* The kernel held hierarchically (adhere/kernel.h): by hmat-oss
 * (adhere/hmatrix.h, O(N log N)) or as an H^2 matrix (adhere/h2.h, O(N)).
 * Entries come from the closed forms, the same numbers the dense matrix
 * holds; a failed product is NaN, never a deformation. */
#include "adhere/h2.h"
#include "adhere/hmatrix.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "core/kernel.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdlib.h>

static double formula_entry(const adh_kernel *k, size_t n, size_t j)
{
    return adh_kernel_formula(k, n, j);
}

static void fail(const adh_kernel *k, double *out)
{
    for (size_t i = 0; i < k->n; i++)
        out[i] = NAN;
}

static void hmat_apply(const adh_kernel *k, const double *p, double *out, double *scratch)
{
    if (adh_hmatrix_apply(k->impl, p, out, scratch) != ADH_SUCCESS)
        fail(k, out);
}

static size_t hmat_bytes(const adh_kernel *k)
{
    return adh_hmatrix_bytes(k->impl);
}

static void hmat_free(void *impl)
{
    adh_hmatrix_free(impl);
}

static const kernel_ops hmat_ops = { hmat_apply, formula_entry, hmat_bytes, hmat_free };

static double hmat_entry(void *ctx, size_t n, size_t j)
{
    return adh_kernel_formula(ctx, n, j);
}

int adh_kernel_hmat_build(adh_kernel *k)
{
    adh_hmatrix_settings hs = adh_hmatrix_settings_default();
    k->impl = adh_hmatrix_alloc(k->n, k->r, hmat_entry, k, &hs);
    k->ops = &hmat_ops;
    return k->impl ? ADH_SUCCESS : ADH_ENOMEM;
}

static void h2_apply(const adh_kernel *k, const double *p, double *out, double *scratch)
{
    if (adh_h2_apply(k->impl, p, out) != ADH_SUCCESS)
        fail(k, out);
}

static size_t h2_bytes(const adh_kernel *k)
{
    return adh_h2_bytes(k->impl);
}

static void h2_free(void *impl)
{
    adh_h2_free(impl);
}

static const kernel_ops h2_ops = { h2_apply, formula_entry, h2_bytes, h2_free };

/* The ring kernel's near field, a block at a time: consecutive columns
 * share their edges, so a row of nj entries takes nj + 1 disk integrals. */
static void h2_block(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out)
{
    const adh_kernel *k = ctx;
    for (size_t i = 0; i < ni; i++) {
        double r = k->r[i0 + i], prev = adh_disk_integral(r, adh_rings_edge(k->g, j0));
        for (size_t j = 0; j < nj; j++) {
            double next = adh_disk_integral(r, adh_rings_edge(k->g, j0 + j + 1));
            out[i * nj + j] = next - prev;
            prev = next;
        }
    }
}

static double h2_kernel(void *ctx, double r, double t)
{
    return adh_kernel_k(r, t);
}

/* The paper's kernel is held as the dense matrix holds it: the symmetric
 * dr k(r_n, r_j) (the paper's diagonal on it), r_j applied in the product
 * (adh_h2_problem.cw), so that its near field is held once for both
 * directions. */
static void h2_paper_block(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out)
{
    const adh_kernel *k = ctx;
    for (size_t i = 0; i < ni; i++)
        for (size_t j = 0; j < nj; j++)
            out[i * nj + j] = i0 + i == j0 + j ? adh_kernel_paper_diagonal(k->r[i0 + i], k->dr)
                                               : k->dr * adh_kernel_k(k->r[i0 + i], k->r[j0 + j]);
}

static double h2_paper_kernel(void *ctx, double r, double t)
{
    const adh_kernel *k = ctx;
    return k->dr * adh_kernel_k(r, t);
}

/* The H^2 operator: the far field of column j is the kernel against
 * column j's measure, t dt over ring j (Gauss-Legendre, exact for the
 * interpolating polynomials), or for the paper's collocation the point r_j
 * of weight r_j (dr in the kernel: h2_paper_kernel). */
int adh_kernel_h2_build(adh_kernel *k)
{
    const adh_grid *g = k->g;
    size_t n = g->n;
    adh_h2_settings hs = adh_h2_settings_default();
    int paper = k->type == ADH_KERNEL_PAPER;
    size_t nq = paper ? 0 : (size_t)hs.order / 2 + 1;
    double *edge = malloc((n + 1) * sizeof *edge), *qt = malloc((2 * n * nq + 1) * sizeof *qt), *qw = qt + n * nq;
    gsl_integration_glfixed_table *gl = paper ? NULL : gsl_integration_glfixed_table_alloc(nq);
    adh_h2 *h = NULL;
    if (!edge || !qt || (!paper && !gl))
        goto done;
    for (size_t j = 0; j <= n; j++)
        edge[j] = adh_rings_edge(g, j);
    for (size_t j = 0; j < n; j++)
        for (size_t q = 0; q < nq; q++) {
            double t, w;
            gsl_integration_glfixed_point(edge[j], edge[j + 1], q, &t, &w, gl);
            qt[j * nq + q] = t;
            qw[j * nq + q] = w * t;
        }
    adh_h2_problem pb = { .n = n, .edge = edge, .x = g->r, .nq = nq, .qt = qt, .qw = qw,
                          .kernel = paper ? h2_paper_kernel : h2_kernel, .block = paper ? h2_paper_block : h2_block,
                          .ctx = k, .cw = paper ? g->r : NULL };
    h = adh_h2_alloc(&pb, &hs);
done:
    if (gl)
        gsl_integration_glfixed_table_free(gl);
    free(edge), free(qt);
    k->impl = h;
    k->ops = &h2_ops;
    return h ? ADH_SUCCESS : ADH_ENOMEM;
}
