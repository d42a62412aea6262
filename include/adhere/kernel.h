/* The discretised elastic half-space kernel, k(r,t) = 4/(pi max) K(min^2/max^2)
 * (K of parameter m): the paper's point collocation (eqs 9, 18-21), or an
 * exact ring-integrated form. For the latter, D(r,a) = int_0^a k(r,t) t dt is
 * (4a/pi) E(r^2/a^2) for r < a and (4r/pi)[E(a^2/r^2) - (1 - a^2/r^2) K(a^2/r^2)]
 * for r > a; a ring [a,b] of unit pressure deflects the surface by
 * D(r,b) - D(r,a), so piecewise-constant pressures need no singular cell.
 * It depends on the grid alone: material changes never rebuild it. */
#ifndef ADHERE_KERNEL_H
#define ADHERE_KERNEL_H

#include <signal.h>

#include "adhere/grid.h"

typedef enum adh_kernel_type {
    ADH_KERNEL_PAPER = 0,   /* point collocation, log singularity per eqs 19-21 */
    ADH_KERNEL_RING = 1     /* exact for piecewise-constant pressure on rings */
} adh_kernel_type;

/* How the influence matrix is held: the dense matrix (N^2 numbers, the
 * oracle), a hierarchical matrix from hmat-oss (adhere/hmatrix.h:
 * O(N log N)), or an H^2 matrix with nested Chebyshev bases (adhere/h2.h:
 * O(N), smaller and faster). The hierarchical products agree with the dense
 * one to ~1e-11; all give the same apply, entry and diagonal. */
typedef enum adh_kernel_storage {
    ADH_STORAGE_DENSE = 0,
    ADH_STORAGE_HMAT = 1,
    ADH_STORAGE_H2 = 2
} adh_kernel_storage;

/* The operator W, one interface over every storage: apply (the product),
 * entry, diagonal, bytes. */
typedef struct adh_kernel adh_kernel;

/* What to build. Zero is the default: the paper's kernel, held dense. */
typedef struct adh_kernel_settings {
    adh_kernel_type type;
    adh_kernel_storage storage;
    const volatile sig_atomic_t *cancel; /* polled once per column while a
                            dense matrix is built (a large ring kernel takes
                            seconds): nonzero stops it with ADH_EINTR; a
                            hierarchical one is assembled in one call. NULL:
                            never */
} adh_kernel_settings;

adh_kernel_settings adh_kernel_settings_default(void);

/* The kernel on grid g (borrowed: it must outlive the kernel). The ring
 * kernel takes any grid, graded too (adhere/rings.h): ring j's influence
 * is D(r, edge[j+1]) - D(r, edge[j]). The paper's kernel takes the uniform
 * grid only. NULL with *status (status may be NULL): ADH_EINVAL for the
 * paper's kernel on a graded grid or an unknown type or storage,
 * ADH_ENOMEM, ADH_EINTR when the cancel flag was raised; else *status is
 * ADH_SUCCESS. */
adh_kernel *adh_kernel_alloc(const adh_grid *g, const adh_kernel_settings *s, int *status);
void adh_kernel_free(adh_kernel *k);
adh_kernel_type adh_kernel_kind(const adh_kernel *k);
adh_kernel_storage adh_kernel_storage_of(const adh_kernel *k);
/* "dense", "hmat" or "h2". */
const char *adh_kernel_storage_name(adh_kernel_storage s);
/* ADH_SUCCESS, or ADH_EINVAL when name is not "dense", "hmat" or "h2". */
int adh_kernel_storage_parse(const char *name, adh_kernel_storage *s);
/* Bytes the stored matrix holds (a memory budget's measure). */
size_t adh_kernel_bytes(const adh_kernel *k);
const char *adh_kernel_name(adh_kernel_type type);
/* ADH_SUCCESS, or ADH_EINVAL when name is neither "paper" nor "ring". */
int adh_kernel_parse(const char *name, adh_kernel_type *type);

/* out_n = integral_0^Rmax p(t) k(r_n, t) t dt, discretised; the deformation
 * is then u = -(2/E) out (eq 11). scratch: N doubles of the caller's, so one
 * kernel can serve several threads. */
void adh_kernel_apply(const adh_kernel *k, const double *p, double *out, double *scratch);

/* The complete disk integral D(r, a) = int_0^a k(r, t) t dt (closed form). */
double adh_disk_integral(double r, double a);

/* Entry (n, j) of the influence matrix W (out = W p), for tests and
 * Jacobians: read from the dense matrix, or from the closed form (the same
 * numbers) under hierarchical storage. */
double adh_kernel_entry(const adh_kernel *k, size_t n, size_t j);
/* W_nn: the self-influence of node n's ring (a Jacobi preconditioner). */
double adh_kernel_diagonal(const adh_kernel *k, size_t n);

#endif
