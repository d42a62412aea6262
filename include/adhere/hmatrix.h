/* A hierarchical matrix for a 1-D kernel (hmat-oss): blocks of well
 * separated node clusters stored low-rank (ACA+ to a tolerance), the near
 * field dense. O(N log N) memory and product where a dense matrix is N^2.
 * The core's kernel uses it as its hmat storage (adhere/kernel.h; its h2
 * storage, adhere/h2.h, holds less and is faster: docs/grids-and-operators.md). */
#ifndef ADHERE_HMATRIX_H
#define ADHERE_HMATRIX_H

#include <stddef.h>

typedef struct adh_hmatrix adh_hmatrix;

/* Entry (i, j) of the matrix; called during assembly only. */
typedef double (*adh_hmatrix_entry_fn)(void *ctx, size_t i, size_t j);

typedef struct adh_hmatrix_settings {
    double tol;     /* ACA+ relative tolerance per block */
    double eta;     /* admissibility: min diameter <= eta x distance */
    int leaf;       /* largest cluster kept dense */
} adh_hmatrix_settings;

adh_hmatrix_settings adh_hmatrix_settings_default(void);

/* Assembles the n x n matrix of entries at nodes x (1-D coordinates, used
 * for clustering only). NULL on failure. */
adh_hmatrix *adh_hmatrix_alloc(size_t n, const double *x, adh_hmatrix_entry_fn entry, void *ctx,
                               const adh_hmatrix_settings *s);
void adh_hmatrix_free(adh_hmatrix *h);

/* y = H v. scratch: n doubles of the caller's (the library permutes its
 * input in place). ADH_SUCCESS, or ADH_ENOMEM when hmat-oss failed.
 * Calls are serialised: the library toggles process-wide threading
 * settings during a product. */
int adh_hmatrix_apply(adh_hmatrix *h, const double *v, double *y, double *scratch);

/* Bytes held by the stored blocks (dense leaves and low-rank factors). */
size_t adh_hmatrix_bytes(const adh_hmatrix *h);
/* Stored numbers over n^2: the compression. */
double adh_hmatrix_ratio(const adh_hmatrix *h);

#endif
