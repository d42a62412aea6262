#include "adhere/precond.h"
#include "adhere/status.h"

#include <gsl/gsl_cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The dense preconditioner (adhere/precond.h). With U = alpha W[:,S]
 * diag(d_S) on the active prefix S = {0 .. m-1}, the truncated Jacobian is
 * J = I + U E_S^T, and the bordered system
 *     J x + g y = b,   theta nu.x + nh y = c
 * reduces exactly (the unit pivots outside S eliminated) to m + 1 unknowns
 * z = x_S, y:
 *     (I + U_S) z + g_S y                          = b_S
 *     theta (U^T nu).z + (nh - theta nu.g) y       = c - theta nu.b
 * after which x = b - g y - U z. Its determinant is that of the truncated
 * bordered matrix. The (m+1)^2 LU is LAPACK's (OpenBLAS's, as the program
 * is linked; make check-fp links Netlib's): blocked and tuned, several
 * times faster than gsl_linalg_LU_decomp at these sizes, the cost that
 * dominates a static curve at large sigma on a dense kernel. */
typedef struct dense {
    size_t n, m;
    const double *W;  /* row-major n x n: own, or borrowed (adh_precond_alloc_shared) */
    double *own;      /* W when copied, and colnorm, one block */
    double *colnorm;  /* sum_i |W_ij| */
    double *B;        /* LU of the (m+1)^2 reduced matrix */
    int *perm;        /* LAPACK pivots, 1-based */
    double *D, *g, *nu, *y, *t; /* d, g, nu at the point; scratch of n + 1 */
    double c, theta;  /* -alpha, theta */
} dense;

static void dense_free(void *state)
{
    dense *P = state;
    if (!P)
        return;
    free(P->own);
    free(P->B);
    free(P->perm);
    free(P->D);
    free(P);
}

/* W's entries copied into own, or read where they are (entries), and
 * their column sums in the same order either way. */
static void *dense_alloc(size_t n, adh_precond_entry_fn entry, void *ctx, const double *entries)
{
    dense *P = calloc(1, sizeof *P);
    if (!P)
        return NULL;
    P->n = n;
    P->own = malloc(((entries ? 0 : n * n) + n) * sizeof *P->own);
    P->B = malloc((n + 1) * (n + 1) * sizeof *P->B);
    P->perm = malloc((n + 1) * sizeof *P->perm);
    P->D = malloc((5 * n + 2) * sizeof *P->D);
    if (!P->own || !P->B || !P->perm || !P->D) {
        dense_free(P);
        return NULL;
    }
    double *W = entries ? NULL : P->own;
    P->W = entries ? entries : W;
    P->colnorm = P->own + (entries ? 0 : n * n);
    P->g = P->D + n;
    P->nu = P->g + n;
    P->y = P->nu + n;
    P->t = P->y + n + 1;
    memset(P->colnorm, 0, n * sizeof *P->colnorm);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double v = W ? (W[i * n + j] = entry(ctx, i, j)) : entries[i * n + j];
            P->colnorm[j] += fabs(v);
        }
    return P;
}

/* The sign of det from the LU's pivots and diagonal; ADH_ESING when a
 * pivot is exactly zero or not finite. */
static int lu_sign(const double *B, const int *perm, size_t ld, int *sign)
{
    int sg = 1;
    for (size_t i = 0; i < ld; i++) {
        if (perm[i] != (int)i + 1)
            sg = -sg;
        double d = B[i * ld + i];
        if (d == 0 || !isfinite(d))
            return ADH_ESING;
        if (d < 0)
            sg = -sg;
    }
    *sign = sg;
    return ADH_SUCCESS;
}

static int dense_set(void *state, const adh_precond_system *sys, size_t *active, int *det_sign)
{
    dense *P = state;
    size_t n = P->n, m = 0;
    double c = -sys->alpha, th = sys->theta, ng = 0;
    P->c = c;
    P->theta = th;
    for (size_t j = 0; j < n; j++) {
        P->D[j] = sys->d[j];
        if (c * fabs(P->D[j]) * P->colnorm[j] > sys->active_tol)
            m = j + 1;
    }
    for (size_t i = 0; i < n; i++) {
        P->g[i] = sys->g[i];
        P->nu[i] = sys->nu[i];
        ng += P->nu[i] * P->g[i];
    }
    P->m = m;
    *active = m;
    size_t ld = m + 1;
    double *B = P->B, *q = P->y;
    if (m > 0)
        cblas_dgemv(CblasRowMajor, CblasTrans, (int)n, (int)m, c, P->W, (int)n, P->nu, 1, 0.0, q, 1);
    for (size_t i = 0; i < m; i++) {
        const double *row = P->W + i * n;
        double *Bi = B + i * ld;
        for (size_t j = 0; j < m; j++)
            Bi[j] = -c * row[j] * P->D[j];
        Bi[i] += 1.0;
        Bi[m] = P->g[i];
    }
    for (size_t j = 0; j < m; j++)
        B[m * ld + j] = th * q[j] * P->D[j];
    B[m * ld + m] = sys->nh - th * ng;
    /* The row-major B is, to LAPACK, the column-major B^T = P L U: the
     * same determinant, and B x = b is solved as U^T L^T P^T x = b. */
    lapack_int info = LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, (lapack_int)ld, (lapack_int)ld, B, (lapack_int)ld,
                                          P->perm);
    if (info < 0)
        return ADH_EINVAL;
    return lu_sign(B, P->perm, ld, det_sign);
}

static void dense_apply(void *state, const double *v, double *z)
{
    dense *P = state;
    size_t n = P->n, m = P->m, ld = m + 1;
    double th = P->theta, *y = P->y, nb = 0;
    for (size_t i = 0; i < n; i++)
        nb += P->nu[i] * v[i];
    for (size_t i = 0; i < m; i++)
        y[i] = v[i];
    y[m] = v[n] - th * nb;
    cblas_dtrsv(CblasColMajor, CblasUpper, CblasTrans, CblasNonUnit, (int)ld, P->B, (int)ld, y, 1);
    cblas_dtrsv(CblasColMajor, CblasLower, CblasTrans, CblasUnit, (int)ld, P->B, (int)ld, y, 1);
    for (size_t i = ld; i-- > 0;) {
        size_t p = (size_t)P->perm[i] - 1;
        double tmp = y[i];
        y[i] = y[p];
        y[p] = tmp;
    }
    double dh = y[m];
    for (size_t j = 0; j < m; j++)
        P->t[j] = P->D[j] * y[j];
    if (m > 0)
        cblas_dgemv(CblasRowMajor, CblasNoTrans, (int)n, (int)m, P->c, P->W, (int)n, P->t, 1, 0.0, z, 1);
    else
        memset(z, 0, n * sizeof *z);
    for (size_t i = 0; i < n; i++)
        z[i] += v[i] - P->g[i] * dh;
    z[n] = dh;
}

static size_t dense_bytes(const void *state)
{
    const dense *P = state;
    size_t n = P->n, w = P->W == P->own ? n * n : 0;   /* a borrowed W is its owner's */
    return (w + n + (n + 1) * (n + 1) + 5 * n + 2) * sizeof(double) + (n + 1) * sizeof(int);
}

static const adh_precond_type dense_type = {
    .name = "dense",
    .truncates = 1,
    .alloc = dense_alloc,
    .free = dense_free,
    .set = dense_set,
    .border = NULL, /* its own border, factorized */
    .apply = dense_apply,
    .bytes = dense_bytes,
};

const adh_precond_type *adh_precond_dense = &dense_type;
