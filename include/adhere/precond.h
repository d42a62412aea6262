/* Preconditioners for the bordered Jacobians of a continuation in
 * (u, h0) on a kernel W (n nodes): the (n+1) x (n+1) system
 *
 *     B = [ I + alpha W diag(d)   g  ]
 *         [ theta nu^T            nh ]
 *
 * (the static mode's G(u, h0) = u + (2/E) W p(h0 + r^2/2R - u) has
 * alpha = -2/E, d = p'(h), g = dG/dh0; the last row is the continuation's
 * constraint, weighted by theta). One interface, GSL style, two
 * implementations:
 *
 *   adh_precond_dense  the LU (LAPACK, through lapacke) of B truncated to
 *                      the index prefix of nodes where alpha d_j W's column
 *                      j is large; the nodes beyond are left to the Krylov
 *                      solver. Holds W dense: n^2 numbers (its own copy,
 *                      or borrowed where W's entries are held already:
 *                      adh_precond_alloc_shared), (m+1)^3 / 3 a
 *                      factorization. The oracle, for dense kernels.
 *   adh_precond_hodlr  the whole I + alpha W diag(d), W held as a HODLR
 *                      matrix (adhere/hodlr.h, O(n log n) numbers), its
 *                      factorization O(n log^2 n); the border eliminated
 *                      by a Schur complement; applied in single precision.
 *                      For hierarchical kernels.
 *
 * Either is applied as z = M^-1 v to vectors of n + 1 numbers (the u part,
 * then the border's), as adhere/fgmres.h's preconditioner callback wants.
 * M is B at the point of the last adh_precond_set: a preconditioner set a
 * few points back still serves (flexible GMRES corrects the difference),
 * so a caller refactorizes only when the Krylov solver slows down. det B's
 * sign comes with the factorization (a fold of the continuation flips it).
 *
 * Use: alloc once for a kernel (its entries through a callback), then set
 * at a point, border for each operator solved with it, apply as often as
 * the Krylov solver asks, free. */
#ifndef ADHERE_PRECOND_H
#define ADHERE_PRECOND_H

#include <stddef.h>

/* Entry (i, j) of W. */
typedef double (*adh_precond_entry_fn)(void *ctx, size_t i, size_t j);

/* The point a preconditioner is set at. The arrays are read during
 * adh_precond_set only. */
typedef struct adh_precond_system {
    double alpha;       /* J = I + alpha W diag(d) */
    const double *d;    /* n numbers */
    const double *g;    /* the border column, n numbers */
    const double *nu;   /* the border row's node part, n numbers (times theta) */
    double nh;          /* the corner */
    double theta;       /* the border row's weight on the node part */
    double active_tol;  /* dense: node j enters the LU when
                           |alpha d_j| sum_i |W_ij| exceeds it, and so does
                           every node before it; hodlr: unused */
} adh_precond_system;

typedef struct adh_precond adh_precond;

typedef struct adh_precond_type {
    const char *name;   /* "dense" or "hodlr" */
    int truncates;      /* 1: set takes a prefix of the nodes, and a lower
                           active_tol takes more (dense); 0: all of them */
    void *(*alloc)(size_t n, adh_precond_entry_fn entry, void *ctx, const double *entries);
    void (*free)(void *state);
    int (*set)(void *state, const adh_precond_system *sys, size_t *active, int *det_sign);
    int (*border)(void *state, const double *g, const double *nu, double nh);
    void (*apply)(void *state, const double *v, double *z);
    size_t (*bytes)(const void *state);
} adh_precond_type;

extern const adh_precond_type *adh_precond_dense;
extern const adh_precond_type *adh_precond_hodlr;

/* Reads W (n x n) through entry: the dense one copies it (n^2 calls), the
 * HODLR one assembles it by cross approximation (O(n log n) calls). NULL
 * out of memory. */
adh_precond *adh_precond_alloc(const adh_precond_type *T, size_t n, adh_precond_entry_fn entry, void *ctx);
/* As adh_precond_alloc, where W's entries are held already, row-major
 * (entries[i n + j] = entry(ctx, i, j), bit for bit), by whoever outlives
 * this preconditioner and leaves them unchanged: the dense one reads them
 * there instead of copying them (n^2 numbers fewer, the same arithmetic);
 * the HODLR one assembles its own as before. entries NULL: a copy. */
adh_precond *adh_precond_alloc_shared(const adh_precond_type *T, size_t n, adh_precond_entry_fn entry, void *ctx,
                                      const double *entries);
void adh_precond_free(adh_precond *p);

/* Factorizes B at the point sys describes; its border is the operator's
 * until adh_precond_border names another. ADH_SUCCESS; ADH_ESING when B is
 * singular as held (a pivot exactly zero or not finite: not a simple
 * fold); ADH_ENOMEM. */
int adh_precond_set(adh_precond *p, const adh_precond_system *sys);

/* The border (g, nu, nh; theta as set) of the operator the next applies
 * precondition, which may differ from the factorized one (another
 * constraint, a later point): the HODLR preconditioner eliminates it
 * exactly (a solve with g, O(n log n)); the dense one keeps its own. nu is
 * borrowed until the next border. ADH_SUCCESS, or ADH_ESING when the
 * border's Schur complement vanishes. */
int adh_precond_border(adh_precond *p, const double *g, const double *nu, double nh);

/* z = M^-1 v, n + 1 numbers each (never the same array). */
void adh_precond_apply(adh_precond *p, const double *v, double *z);

/* Sign of det B at the last set (+1 or -1); nodes it factorized (the
 * dense one's prefix, or n); its type; bytes it holds. */
int adh_precond_det_sign(const adh_precond *p);
size_t adh_precond_active(const adh_precond *p);
const adh_precond_type *adh_precond_type_of(const adh_precond *p);
size_t adh_precond_bytes(const adh_precond *p);

#endif
