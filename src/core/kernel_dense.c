/* The kernel held dense (adhere/kernel.h): N^2 numbers, the oracle. The
 * paper's kernel is symmetric as held (k-matrix times dr, r_j applied in
 * the product), the ring kernel is the full influence matrix. */
#include "adhere/status.h"
#include "core/kernel.h"

#include <gsl/gsl_cblas.h>
#include <stdlib.h>

static void dense_apply(const adh_kernel *k, const double *p, double *out, double *scratch)
{
    int n = (int)k->n;
    const double *w = k->impl;
    if (k->type == ADH_KERNEL_PAPER) {
        for (int i = 0; i < n; i++)
            scratch[i] = k->r[i] * p[i];
        cblas_dsymv(CblasRowMajor, CblasLower, n, 1.0, w, n, scratch, 1, 0.0, out, 1);
    } else {
        cblas_dgemv(CblasRowMajor, CblasNoTrans, n, n, 1.0, w, n, p, 1, 0.0, out, 1);
    }
}

static double dense_entry(const adh_kernel *k, size_t n, size_t j)
{
    double w = ((const double *)k->impl)[n * k->n + j];
    return k->type == ADH_KERNEL_PAPER ? w * k->r[j] : w;
}

static size_t dense_bytes(const adh_kernel *k)
{
    return k->n * k->n * sizeof(double);
}

static const kernel_ops dense_ops = { dense_apply, dense_entry, dense_bytes, free };

/* Symmetric: the lower triangle (dsymv reads only that), mirrored for the
 * entries. */
static int paper_fill(const adh_kernel *k, double *w, const volatile sig_atomic_t *cancel)
{
    size_t n = k->n;
    const double *r = k->r;
    double d = k->dr;
    for (size_t i = 0; i < n; i++) {
        if (cancel && *cancel)
            return ADH_EINTR;
        for (size_t j = 0; j < i; j++) {
            double v = d * adh_kernel_k(r[i], r[j]);
            w[i * n + j] = v;
            w[j * n + i] = v;
        }
        w[i * n + i] = adh_kernel_paper_diagonal(r[i], d);
    }
    return ADH_SUCCESS;
}

/* Column j is D(r, b_j) - D(r, a_j): consecutive columns share an edge. */
static int ring_fill(const adh_kernel *k, double *w, const volatile sig_atomic_t *cancel)
{
    size_t n = k->n;
    const adh_grid *g = k->g;
    double *prev = malloc(n * sizeof *prev);
    if (!prev)
        return ADH_ENOMEM;
    for (size_t i = 0; i < n; i++)
        prev[i] = 0.0; /* D(r, 0) = 0 */
    for (size_t j = 0; j < n; j++) {
        if (cancel && *cancel) {
            free(prev);
            return ADH_EINTR;
        }
        double b = g->graded ? g->edge[j + 1] : (double)(j + 1) * k->dr;
        for (size_t i = 0; i < n; i++) {
            double db = adh_disk_integral(g->r[i], b);
            w[i * n + j] = db - prev[i];
            prev[i] = db;
        }
    }
    free(prev);
    return ADH_SUCCESS;
}

int adh_kernel_dense_build(adh_kernel *k, const volatile sig_atomic_t *cancel)
{
    size_t n = k->n;
    double *w = malloc(n * n * sizeof *w);
    if (!w)
        return ADH_ENOMEM;
    int rc = k->type == ADH_KERNEL_PAPER ? paper_fill(k, w, cancel) : ring_fill(k, w, cancel);
    if (rc != ADH_SUCCESS) {
        free(w);
        return rc;
    }
    k->ops = &dense_ops;
    k->impl = w;
    return ADH_SUCCESS;
}
