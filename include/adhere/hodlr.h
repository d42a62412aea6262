/* A hierarchically off-diagonal low-rank (HODLR) matrix W on the cells of
 * a line, and a direct solver for A = I + alpha W diag(d) built on it.
 *
 * The cells are split by index into a binary tree (leaves of at most
 * `leaf` cells held dense); each pair of siblings' two off-diagonal blocks
 * of W is held as U V^T, assembled by adaptive cross approximation (ACA,
 * partial pivoting) from the entries to a relative tolerance. W depends on
 * the grid alone, so it is assembled once; A's off-diagonal blocks are
 * then U (alpha diag(d) V)^T with no new approximation, and A is
 * factorized for any d by the recursive Sherman-Morrison-Woodbury scheme
 * (Ambikasaran and Darve): at each node, A = diag(A_0, A_1) + low rank,
 * the children's factorizations solve for the low-rank columns, and a
 * small capacitance matrix of twice the rank is LU-factorized. Factorizing
 * costs O(N k^2 log^2 N), a solve O(N k log N), the memory O(N k log N),
 * where a dense LU costs N^3 / 3 and N^2 numbers. det A = product of the
 * leaves' and capacitance matrices' determinants, so its sign comes free.
 *
 * adhere/precond.h's HODLR preconditioner is built on it (the static
 * mode's Jacobian I - (2/E) W diag(p'(h)), whole). */
#ifndef ADHERE_HODLR_H
#define ADHERE_HODLR_H

#include <stddef.h>

/* Entry (i, j) of W. */
typedef double (*adh_hodlr_entry_fn)(void *ctx, size_t i, size_t j);

typedef struct adh_hodlr adh_hodlr;

/* Assembles W (n cells, leaves of at most `leaf` cells, ACA to relative
 * tolerance tol per block). NULL on bad arguments or out of memory. */
adh_hodlr *adh_hodlr_alloc(size_t n, adh_hodlr_entry_fn entry, void *ctx, double tol, size_t leaf);
void adh_hodlr_free(adh_hodlr *h);

/* Factorizes A = I + alpha W diag(d) (d: n numbers, copied). ADH_SUCCESS;
 * ADH_ESING when a pivot is exactly zero or not finite (A singular as
 * held); ADH_ENOMEM. */
int adh_hodlr_factorize(adh_hodlr *h, double alpha, const double *d);

/* Solves A x = b in place (b: n numbers) with the last factorization. */
void adh_hodlr_solve(adh_hodlr *h, double *b);

/* The same solve on single-precision copies of the factorization (made by
 * adh_hodlr_factorize): relative error ~1e-6, for a preconditioner, whose
 * own error (the blocks' tolerance) is larger; half the memory traffic of
 * adh_hodlr_solve, which is bound by it. Where a factor or b does not fit
 * in single precision, the double solve. */
void adh_hodlr_solve_single(adh_hodlr *h, double *b);

/* Sign of det A at the last factorization (+1 or -1). */
int adh_hodlr_det_sign(const adh_hodlr *h);

/* y = W v with the held approximation (tests). */
void adh_hodlr_apply(const adh_hodlr *h, const double *v, double *y);

/* Bytes held (W's blocks and the factorization); the largest rank. */
size_t adh_hodlr_bytes(const adh_hodlr *h);
size_t adh_hodlr_max_rank(const adh_hodlr *h);

#endif
