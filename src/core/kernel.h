/* The kernel operator's parts, private to it (the public header is
 * adhere/kernel.h), shared by its files and by nothing else: kernel.c (the
 * interface, the closed forms, names), kernel_dense.c (the dense matrix)
 * and kernel_hier.c (hmat-oss and H^2).
 * Each storage supplies its product, entry, bytes and free; the diagonal
 * is the entry's. */
#ifndef ADH_CORE_KERNEL_H
#define ADH_CORE_KERNEL_H

#include "adhere/kernel.h"

typedef struct kernel_ops {
    void (*apply)(const adh_kernel *k, const double *p, double *out, double *scratch);
    double (*entry)(const adh_kernel *k, size_t n, size_t j);
    size_t (*bytes)(const adh_kernel *k);
    void (*free)(void *impl);
} kernel_ops;

struct adh_kernel {
    adh_kernel_type type;
    adh_kernel_storage storage;
    size_t n;
    double dr;
    const double *r;   /* borrowed from the grid */
    const adh_grid *g; /* borrowed */
    const kernel_ops *ops;
    void *impl;        /* the storage's own */
};

/* k(r,t) of eq 9, r != t. */
double adh_kernel_k(double r, double t);
/* The paper's diagonal (eqs 19-21) times dr. */
double adh_kernel_paper_diagonal(double rn, double d);
/* W_nj from the closed forms, as the dense matrix holds it. */
double adh_kernel_formula(const adh_kernel *k, size_t n, size_t j);

/* Builds the storage into k->ops and k->impl: ADH_SUCCESS, ADH_ENOMEM,
 * ADH_EINTR (dense, on cancel). */
int adh_kernel_dense_build(adh_kernel *k, const volatile sig_atomic_t *cancel);
int adh_kernel_hmat_build(adh_kernel *k);
int adh_kernel_h2_build(adh_kernel *k);

#endif
