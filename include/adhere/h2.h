/* An H^2 matrix for a kernel on cells of a line (the rings of a radial
 * grid): a binary tree of cell clusters, each with a Chebyshev interpolation
 * basis on its interval; the children's bases nest in the parent's (transfer
 * matrices), so a far block between well separated clusters is one small
 * matrix of kernel values at their Chebyshev nodes, and the near field is
 * held dense. O(N) numbers and an O(N) product, where adhere/hmatrix.h
 * (hmat-oss: a low-rank basis per block) holds O(N log N) with ranks that
 * grow with the level. The core's kernel uses it as its h2 storage
 * (adhere/kernel.h). */
#ifndef ADHERE_H2_H
#define ADHERE_H2_H

#include <stddef.h>

typedef struct adh_h2 adh_h2;

/* The kernel k(x, t) between a target at x and a source at t, smooth
 * (analytic) away from x = t and symmetric: k(x, t) = k(t, x). */
typedef double (*adh_h2_kernel_fn)(void *ctx, double x, double t);
/* The exact entries of rows i0 .. i0+ni-1 and columns j0 .. j0+nj-1,
 * row-major into out (ni x nj); called for the near field during assembly. */
typedef void (*adh_h2_block_fn)(void *ctx, size_t i0, size_t ni, size_t j0, size_t nj, double *out);

typedef struct adh_h2_problem {
    size_t n;
    const double *edge;      /* n + 1, increasing: cell i is [edge[i], edge[i+1]] */
    const double *x;         /* n targets, x[i] in cell i */
    /* Column j's far-field entries are sum_q w[j nq + q] k(x_i, t[j nq + q]):
     * a quadrature (inside cell j) that must integrate column j's measure
     * exactly against polynomials of degree order - 1 (adh_h2_settings). */
    size_t nq;
    const double *qt, *qw;
    adh_h2_kernel_fn kernel;
    adh_h2_block_fn block;
    void *ctx;
    /* NULL, or the matrix is H diag(cw) with H symmetric (a collocation:
     * column j's source is the point x[j] of weight cw[j]); block then gives
     * H's entries, which are held once for both directions, and nq, qt, qw
     * are not read. Half the near field's bytes. */
    const double *cw;
} adh_h2_problem;

typedef struct adh_h2_settings {
    int order;   /* Chebyshev nodes per cluster */
    double eta;  /* admissible: larger diameter <= eta x distance */
    int leaf;    /* largest cluster kept as a leaf */
    int portable; /* the product's portable copy even where an AVX2 one
                     runs (the same numbers; for tests and timing) */
} adh_h2_settings;

adh_h2_settings adh_h2_settings_default(void);

/* Assembles the matrix. NULL on bad arguments or out of memory. */
adh_h2 *adh_h2_alloc(const adh_h2_problem *pb, const adh_h2_settings *s);
void adh_h2_free(adh_h2 *h);

/* y = H v. Reentrant: concurrent calls work in their own workspace.
 * ADH_SUCCESS, or ADH_ENOMEM when that workspace could not be allocated. */
int adh_h2_apply(adh_h2 *h, const double *v, double *y);

/* Bytes held (near field, couplings, bases and transfers, workspace). */
size_t adh_h2_bytes(const adh_h2 *h);

#endif
