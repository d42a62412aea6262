/* Flexible GMRES (Saad 1993) for A x = b, over callbacks: the caller
 * supplies the product y = A v and a preconditioner z = M^-1 v, and M may
 * change from one iteration to the next (a single-precision solve, an
 * inner iteration): the preconditioned vectors z_j are kept, and x is
 * their combination, so the residual the iteration measured is the
 * residual of the x it returns. Right preconditioning; the Krylov basis is
 * orthogonalized by modified Gram-Schmidt, twice; the small least-squares
 * problem by Givens rotations. No restart: after max_iter iterations it
 * stops (ADH_EMAXITER), and the caller decides (a better preconditioner,
 * usually).
 *
 * Nothing here knows the static mode: any solver with a matrix-free
 * operator and a preconditioner uses it (adhere/precond.h has the two
 * the static mode builds, for the bordered Jacobians of a continuation).
 *
 * Use, GSL style: alloc once for a size, then for each right side set,
 * iterate until it returns something other than ADH_CONTINUE, and
 * solution; or adh_fgmres_solve for the whole loop. Memory: 2 max_iter + 1
 * vectors of n. */
#ifndef ADHERE_FGMRES_H
#define ADHERE_FGMRES_H

#include <stddef.h>

/* y = A x, or z = M^-1 x (x and the output: n numbers, never the same
 * array). ADH_SUCCESS, or a status that stops the solve and is returned. */
typedef int (*adh_fgmres_fn)(void *ctx, const double *x, double *y);

typedef struct adh_fgmres_system {
    adh_fgmres_fn apply;    /* the operator A */
    adh_fgmres_fn precond;  /* M^-1; NULL: none (plain GMRES) */
    void *ctx;
} adh_fgmres_system;

typedef struct adh_fgmres adh_fgmres;

/* A workspace for systems of n unknowns and at most max_iter iterations
 * (1 to ADH_FGMRES_MAX_ITER). NULL on bad sizes or out of memory. */
adh_fgmres *adh_fgmres_alloc(size_t n, size_t max_iter);
void adh_fgmres_free(adh_fgmres *f);

#define ADH_FGMRES_MAX_ITER 200

/* Starts a solve of A x = b from x = 0 until |b - A x| <= rtol |b| (b is
 * read here only). ADH_CONTINUE: iterate; ADH_SUCCESS: b = 0, and the
 * solution is 0. */
int adh_fgmres_set(adh_fgmres *f, const adh_fgmres_system *sys, const double *b, double rtol);

/* One iteration: one preconditioner solve and one product. ADH_CONTINUE:
 * not converged yet; ADH_SUCCESS: converged (or the Krylov space became
 * invariant: the solution is exact); ADH_EMAXITER: max_iter iterations
 * without convergence; ADH_ENAN: a number stopped being finite; or the
 * status a callback returned. */
int adh_fgmres_iterate(adh_fgmres *f);

/* The iterate after the iterations so far into x (n numbers). ADH_SUCCESS,
 * ADH_ESING when the reduced Hessenberg matrix is singular (a breakdown),
 * ADH_ENAN when x is not finite. */
int adh_fgmres_solution(adh_fgmres *f, double *x);

/* Iterations of the current solve; its residual |b - A x| as the
 * iteration measured it (exact arithmetic's, not recomputed). */
size_t adh_fgmres_iterations(const adh_fgmres *f);
double adh_fgmres_residual(const adh_fgmres *f);

/* set, iterate to the end, solution: ADH_SUCCESS when converged with x
 * finite, else the status that stopped it (x is then not an answer).
 * *its (may be NULL): the iterations done. */
int adh_fgmres_solve(adh_fgmres *f, const adh_fgmres_system *sys, const double *b, double rtol, double *x,
                     size_t *its);

#endif
