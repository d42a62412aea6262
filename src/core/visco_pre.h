/* The viscoelastic solver's preconditioner (adhere/visco.h): an
 * approximate inverse of J = I - c W diag(d), bordered by up to two rows
 * and columns. The static mode's two preconditioners, for any compliance
 * c: under a dense kernel an LU (LAPACK) of J's active block, the nodes
 * where c |d_j| sum_n |W_nj| exceeds a threshold (the columns left out are
 * those of I, nearly); under a hierarchical kernel the whole J as a HODLR
 * matrix (adhere/hodlr.h). Internal to the core. */
#ifndef ADH_VISCO_PRE_H
#define ADH_VISCO_PRE_H

#include <stddef.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"

#define ADH_VISCO_BORDER_MAX 2

typedef struct adh_visco_pre adh_visco_pre;

adh_visco_pre *adh_visco_pre_alloc(const adh_grid *g, const adh_kernel *k);
void adh_visco_pre_free(adh_visco_pre *p);

/* Under a dense kernel, W's entries as it holds them (row-major, those of
 * adh_kernel_entry), for another solver of the same kernel to borrow
 * while p lives (adh_static_alloc_shared); NULL under a hierarchical one. */
const double *adh_visco_pre_entries(const adh_visco_pre *p);

/* Factorizes the bordered system
 *     [J  B ] [x ]   [r  ]
 *     [C  C0] [xi] = [rxi],     J = I - c W diag(d),
 * with nb (0 to 2) borders: B nb columns of n (one after the other), C nb
 * rows of n, C0 nb x nb (row-major); all copied. Dense: an LU of the
 * active block bordered (as static.c's, exact for the truncated J, and
 * regular at a fold of J where the border makes it so); HODLR: the whole
 * J, factorized anew or, when only p'(h) at a few nodes moved, updated
 * (Woodbury), and the border by its Schur complement. act: the active
 * threshold.
 * ADH_SUCCESS, ADH_ENOMEM, or ADH_ESTALL when singular as held. */
int adh_visco_pre_factor(adh_visco_pre *p, double c, const double *d, double act, size_t nb, const double *B,
                         const double *C, const double *C0);

/* Solves it approximately: r (n) and rxi (nb) in, x (n) and xi (nb) out;
 * r and x may be the same. */
void adh_visco_pre_solve(adh_visco_pre *p, const double *r, const double *rxi, double *x, double *xi);

/* How far J = I - c W diag(d) has moved from the one factorized: the
 * largest change of a diagonal entry relative to it, |c d_j - c' d'_j|
 * W_jj / max(1, |1 - c' W_jj d'_j|) (W_jj the self-influence): the
 * contact line's nodes, where p'(h) crosses zero, move most. Under HODLR
 * measured against the factorization with its update, and infinite when
 * c is off the factorized compliance by more than a factor 2. */
double adh_visco_pre_drift(const adh_visco_pre *p, double c, const double *d);
/* Whether that drift calls for a new setup (thresholds in visco_pre.c). */
int adh_visco_pre_stale(const adh_visco_pre *p, double c, const double *d);

/* The compliance a HODLR factorization uses for any c below twice it
 * (just below the instantaneous one): 0 none. Forgets the factorization. */
void adh_visco_pre_base(adh_visco_pre *p, double c);

/* Factorizations so far (the dense LU or HODLR's; Woodbury updates apart). */
size_t adh_visco_pre_factorizations(const adh_visco_pre *p);

/* Nodes in the last factorization (n with HODLR). */
size_t adh_visco_pre_active(const adh_visco_pre *p);

#endif
