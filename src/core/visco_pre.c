/* The viscoelastic solver's preconditioner: the static mode's two
 * (src/core/static.c: linearize, precond), for a compliance c given at
 * each factorization and with general borders (the viscoelastic Newton
 * systems carry one or two, and a different compliance each time the
 * integrator's step changes much). static.c keeps its own copies inside
 * its continuation; when its preconditioner becomes a module of its own,
 * this file should become a user of it.
 *
 * Dense: J = I - U E_S^T with U = c W[:,S] diag(d_S) (the columns outside
 * the active prefix S are those of I), so J x = x - U x_S and, with the
 * border, x = r - B xi + U x_S where the (m + nb) unknowns (x_S, xi) solve
 *     [I - U_S   B_S   ] [x_S]   [r_S         ]
 *     [C U       C0 - C B] [xi ] = [rxi - C r ]
 * exactly: one LU of that block. */
#include "visco_pre.h"

#include <gsl/gsl_cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/hodlr.h"
#include "adhere/status.h"

/* LAPACK (OpenBLAS's, as the program is linked; Netlib's under make check-fp). */
extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
extern void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a, const int *lda,
                    const int *ipiv, double *b, const int *ldb, int *info);

/* As the static mode's HODLR preconditioner (static.c). */
#define VISCO_HODLR_TOL 1e-4
#define VISCO_HODLR_LEAF 64

struct adh_visco_pre {
    size_t n;
    double *W;        /* dense W, row-major (out = W p); NULL with hw */
    double *colnorm;  /* sum_n |W_nj| */
    adh_hodlr *hw;    /* W as HODLR under a hierarchical kernel */
    double *LU;       /* dense: the bordered block's LU, (m + nb)^2 (the
                         column-major LU of its row-major transpose) */
    int *piv;
    size_t m;         /* active nodes */
    double c;         /* the compliance factorized */
    double *d;        /* its diag, n */
    double *wdiag;    /* W_jj */
    double *t;        /* scratch, n + nb */
    size_t nb;        /* borders */
    double *B, *C;    /* nb columns, nb rows of n */
    double *Z;        /* HODLR: J^-1 B, nb columns */
    double Sinv[ADH_VISCO_BORDER_MAX * ADH_VISCO_BORDER_MAX]; /* HODLR: the Schur complement's inverse */
};

static double hodlr_entry(void *ctx, size_t i, size_t j)
{
    return adh_kernel_entry(ctx, i, j);
}

void adh_visco_pre_free(adh_visco_pre *p)
{
    if (!p)
        return;
    free(p->W);
    free(p->colnorm);
    adh_hodlr_free(p->hw);
    free(p->LU);
    free(p->piv);
    free(p->d);
    free(p->wdiag);
    free(p);
}

adh_visco_pre *adh_visco_pre_alloc(const adh_grid *g, const adh_kernel *k)
{
    adh_visco_pre *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    size_t n = g->n, nl = n + ADH_VISCO_BORDER_MAX;
    p->n = n;
    int dense = adh_kernel_storage_of(k) == ADH_STORAGE_DENSE;
    if (dense) {
        p->W = malloc(n * n * sizeof *p->W);
        p->LU = malloc(nl * nl * sizeof *p->LU);
        p->piv = malloc(nl * sizeof *p->piv);
    } else {
        p->hw = adh_hodlr_alloc(n, hodlr_entry, (void *)k, VISCO_HODLR_TOL, VISCO_HODLR_LEAF);
    }
    p->colnorm = calloc(n, sizeof *p->colnorm);
    p->wdiag = malloc(n * sizeof *p->wdiag);
    /* d, t, B, C, Z */
    p->d = malloc((2 + 3 * ADH_VISCO_BORDER_MAX) * nl * sizeof *p->d);
    if ((dense ? !p->W || !p->LU || !p->piv : !p->hw) || !p->colnorm || !p->d || !p->wdiag) {
        adh_visco_pre_free(p);
        return NULL;
    }
    p->t = p->d + nl;
    p->B = p->t + nl;
    p->C = p->B + ADH_VISCO_BORDER_MAX * n;
    p->Z = p->C + ADH_VISCO_BORDER_MAX * n;
    for (size_t j = 0; j < n; j++)
        p->wdiag[j] = adh_kernel_diagonal(k, j);
    for (size_t i = 0; i < n && dense; i++)
        for (size_t j = 0; j < n; j++) {
            double v = adh_kernel_entry(k, i, j);
            p->W[i * n + j] = v;
            p->colnorm[j] += fabs(v);
        }
    return p;
}

/* The inverse of the nb x nb matrix S (row-major), in place; ADH_ESTALL
 * when singular. */
static int small_inverse(size_t nb, double *S)
{
    if (nb == 0)
        return ADH_SUCCESS;
    if (nb == 1) {
        if (!(S[0] != 0 && isfinite(S[0])))
            return ADH_ESTALL;
        S[0] = 1.0 / S[0];
        return ADH_SUCCESS;
    }
    double det = S[0] * S[3] - S[1] * S[2];
    if (!(det != 0 && isfinite(det)))
        return ADH_ESTALL;
    double a = S[0];
    S[0] = S[3] / det;
    S[3] = a / det;
    S[1] = -S[1] / det;
    S[2] = -S[2] / det;
    return ADH_SUCCESS;
}

/* HODLR: the whole J, the border by its Schur complement C0 - C J^-1 B. */
static int factor_hodlr(adh_visco_pre *p, const double *C0)
{
    size_t n = p->n, nb = p->nb;
    int rc = adh_hodlr_factorize(p->hw, -p->c, p->d);
    p->m = n;
    if (rc != 0)
        return rc < 0 ? ADH_ENOMEM : ADH_ESTALL;
    double S[ADH_VISCO_BORDER_MAX * ADH_VISCO_BORDER_MAX];
    for (size_t a = 0; a < nb; a++) {
        memcpy(p->Z + a * n, p->B + a * n, n * sizeof *p->Z);
        adh_hodlr_solve(p->hw, p->Z + a * n);
    }
    for (size_t a = 0; a < nb; a++)
        for (size_t b = 0; b < nb; b++)
            S[a * nb + b] = C0[a * nb + b] - cblas_ddot((int)n, p->C + a * n, 1, p->Z + b * n, 1);
    rc = small_inverse(nb, S);
    memcpy(p->Sinv, S, nb * nb * sizeof *S);
    return rc;
}

static int factor_dense(adh_visco_pre *p, double act, const double *C0)
{
    size_t n = p->n, nb = p->nb, m = 0;
    double c = p->c;
    for (size_t j = 0; j < n; j++)
        if (c * fabs(p->d[j]) * p->colnorm[j] > act)
            m = j + 1;
    p->m = m;
    size_t ld = m + nb;
    if (ld == 0)
        return ADH_SUCCESS;
    double *L = p->LU;
    for (size_t i = 0; i < m; i++) {
        const double *row = p->W + i * n;
        double *Li = L + i * ld;
        for (size_t j = 0; j < m; j++)
            Li[j] = -c * row[j] * p->d[j];
        Li[i] += 1.0;
        for (size_t a = 0; a < nb; a++)
            Li[m + a] = p->B[a * n + i];
    }
    for (size_t a = 0; a < nb; a++) {
        double *La = L + (m + a) * ld;
        const double *Ca = p->C + a * n;
        if (m > 0)
            cblas_dgemv(CblasRowMajor, CblasTrans, (int)n, (int)m, c, p->W, (int)n, Ca, 1, 0.0, La, 1);
        for (size_t j = 0; j < m; j++)
            La[j] *= p->d[j];
        for (size_t b = 0; b < nb; b++)
            La[m + b] = C0[a * nb + b] - cblas_ddot((int)n, Ca, 1, p->B + b * n, 1);
    }
    int nn = (int)ld, info = 0;
    dgetrf_(&nn, &nn, L, &nn, p->piv, &info);
    return info == 0 ? ADH_SUCCESS : ADH_ESTALL;
}

int adh_visco_pre_factor(adh_visco_pre *p, double c, const double *d, double act, size_t nb, const double *B,
                         const double *C, const double *C0)
{
    size_t n = p->n;
    if (nb > ADH_VISCO_BORDER_MAX)
        return ADH_EINVAL;
    memcpy(p->d, d, n * sizeof *d);
    p->c = c;
    p->nb = nb;
    if (nb) {
        memcpy(p->B, B, nb * n * sizeof *B);
        memcpy(p->C, C, nb * n * sizeof *C);
    }
    return p->hw ? factor_hodlr(p, C0) : factor_dense(p, act, C0);
}

void adh_visco_pre_solve(adh_visco_pre *p, const double *r, const double *rxi, double *x, double *xi)
{
    size_t n = p->n, nb = p->nb, m = p->m;
    if (x != r)
        memcpy(x, r, n * sizeof *x);
    if (p->hw) {
        adh_hodlr_solve_single(p->hw, x);
        double e[ADH_VISCO_BORDER_MAX];
        for (size_t a = 0; a < nb; a++)
            e[a] = rxi[a] - cblas_ddot((int)n, p->C + a * n, 1, x, 1);
        for (size_t a = 0; a < nb; a++) {
            xi[a] = 0;
            for (size_t b = 0; b < nb; b++)
                xi[a] += p->Sinv[a * nb + b] * e[b];
            cblas_daxpy((int)n, -xi[a], p->Z + a * n, 1, x, 1);
        }
        return;
    }
    size_t ld = m + nb;
    if (ld == 0)
        return;
    double *t = p->t;
    memcpy(t, x, m * sizeof *t);
    for (size_t a = 0; a < nb; a++)
        t[m + a] = rxi[a] - cblas_ddot((int)n, p->C + a * n, 1, x, 1);
    int nn = (int)ld, one = 1, info = 0;
    dgetrs_("T", &nn, &one, p->LU, &nn, p->piv, t, &nn, &info);
    for (size_t a = 0; a < nb; a++) {
        xi[a] = t[m + a];
        cblas_daxpy((int)n, -xi[a], p->B + a * n, 1, x, 1);
    }
    for (size_t j = 0; j < m; j++)
        t[j] *= p->d[j];
    if (m > 0)
        cblas_dgemv(CblasRowMajor, CblasNoTrans, (int)n, (int)m, p->c, p->W, (int)n, t, 1, 1.0, x, 1);
}

double adh_visco_pre_drift(const adh_visco_pre *p, double c, const double *d)
{
    double m = 0;
    for (size_t j = 0; j < p->n; j++)
        m = fmax(m, fabs(c * d[j] - p->c * p->d[j]) * p->wdiag[j]);
    return m;
}

size_t adh_visco_pre_active(const adh_visco_pre *p)
{
    return p->m;
}
