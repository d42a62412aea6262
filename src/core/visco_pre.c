/* The viscoelastic solver's preconditioner: the static mode's two (the
 * module adhere/precond.h: a dense LU of the active block, a HODLR of the
 * whole J), for a compliance c given at each factorization and with
 * general borders (the viscoelastic Newton systems carry one or two, and a
 * different compliance each time the integrator's step changes much; the
 * static module's has one border and -2/E). Under a dense kernel this
 * file holds W's entries once for the run: the static solver that lands a
 * jump into contact borrows them (adh_visco_pre_entries,
 * adh_static_alloc_shared, adh_precond_alloc_shared) rather than keeping a
 * copy of its own; it factors its own LU, or builds its own HODLR.
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
/* Woodbury: at most this many nodes updated, and Y columns kept, before
 * a new factorization; a node enters the update when its column moved by
 * more than VISCO_UPDATE_MIN (|cf dd| W_jj); outside [1/2, 2] cf the
 * compliance is factorized anew. */
#define VISCO_RANK 48
#define VISCO_YCACHE 96
#define VISCO_UPDATE_MIN 0.1
/* A new setup is due when a diagonal entry of J moved by more than this
 * (relative; adh_visco_pre_drift): a dense LU is exact and redone at 0.1;
 * HODLR's updates and compliance floor leave more to GMRES, and a setup
 * costs more there. Measured: at 0.3 the dense path lost a soft spring's
 * snap-out (N = 300, k = 1 N/m); HODLR at 0.3 took 5.1 s CPU for the
 * sigma = 22.5 cycle against 7.7 s at 0.1 (and 1.0 lost a jump-out). */
#define VISCO_STALE_DENSE 0.1
#define VISCO_STALE_HODLR 0.3

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
    double *kscr;     /* the kernel's scratch, n */
    size_t nb;        /* borders */
    double *B, *C;    /* nb columns, nb rows of n */
    double *Z;        /* HODLR: J^-1 B, nb columns */
    double Sinv[ADH_VISCO_BORDER_MAX * ADH_VISCO_BORDER_MAX]; /* HODLR: the Schur complement's inverse */
    /* HODLR: the factorization is of J_f = I - cf W diag(df); p'(h)'s
     * changes since (the contact line crossing nodes) ride on it as a
     * Woodbury update at the nodes R, J = J_f - W_{:,R} diag(delta) E_R^T,
     * delta = cf (d - df) there, with Y = J_f^-1 W e_j kept for each node
     * once computed (VISCO_UPDATE_MIN). A compliance other than cf is left to GMRES: with P
     * exact for J(cf), P J(c) has eigenvalues 1 + (c/cf - 1)(1 - mu),
     * mu those of P, in [1, c/cf] for the stable modes (target() below). */
    const adh_kernel *k;
    int have;         /* a factorization exists */
    double cf;        /* its compliance */
    double cbase;     /* the floor it prefers (adh_visco_pre_base) */
    double *df, *deff; /* factorized diag; the one represented (df, updated at R) */
    size_t r, ny;     /* nodes updated; columns of Y computed */
    size_t R[VISCO_RANK];
    double delta[VISCO_RANK];
    size_t ynode[VISCO_YCACHE]; /* Y's columns are J_f^-1 W e_ynode */
    double *Y;        /* VISCO_YCACHE columns of n */
    double K[VISCO_RANK * VISCO_RANK]; /* LU of I - diag(delta) Y_RR */
    int kpiv[VISCO_RANK];
    size_t col[VISCO_RANK];  /* Y's column of R[a] */
    size_t factorizations, updates;
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
    free(p->Y);
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
        p->Y = malloc((VISCO_YCACHE + 2) * n * sizeof *p->Y);
    }
    p->k = k;
    p->colnorm = calloc(n, sizeof *p->colnorm);
    p->wdiag = malloc(n * sizeof *p->wdiag);
    /* d, t, B, C, Z, kscr */
    p->d = malloc((3 + 3 * ADH_VISCO_BORDER_MAX) * nl * sizeof *p->d);
    if ((dense ? !p->W || !p->LU || !p->piv : !p->hw || !p->Y) || !p->colnorm || !p->d || !p->wdiag) {
        adh_visco_pre_free(p);
        return NULL;
    }
    p->t = p->d + nl;
    p->B = p->t + nl;
    p->C = p->B + ADH_VISCO_BORDER_MAX * n;
    p->Z = p->C + ADH_VISCO_BORDER_MAX * n;
    p->kscr = p->Z + ADH_VISCO_BORDER_MAX * n;
    if (p->Y) {
        p->df = p->Y + VISCO_YCACHE * n;
        p->deff = p->df + n;
    }
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

const double *adh_visco_pre_entries(const adh_visco_pre *p)
{
    return p->W;
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

/* HODLR: x <- J^-1 x with the factorization and its Woodbury update;
 * single: the single-precision factor solve (a preconditioner's). */
static void solve_hodlr(adh_visco_pre *p, double *x, int single)
{
    size_t n = p->n, r = p->r;
    if (single)
        adh_hodlr_solve_single(p->hw, x);
    else
        adh_hodlr_solve(p->hw, x);
    if (r == 0)
        return;
    double t[VISCO_RANK];
    for (size_t a = 0; a < r; a++)
        t[a] = p->delta[a] * x[p->R[a]];
    int rr = (int)r, one = 1, info = 0;
    dgetrs_("N", &rr, &one, p->K, &rr, p->kpiv, t, &rr, &info);
    for (size_t a = 0; a < r; a++)
        cblas_daxpy((int)n, t[a], p->Y + p->col[a] * n, 1, x, 1);
}

/* Y's column for node j: J_f^-1 W e_j, computed once per factorization. */
static int ycolumn(adh_visco_pre *p, size_t j, size_t *col)
{
    size_t n = p->n;
    for (size_t c = 0; c < p->ny; c++)
        if (p->ynode[c] == j) {
            *col = c;
            return ADH_SUCCESS;
        }
    if (p->ny == VISCO_YCACHE)
        return ADH_EMAXITER;
    double *y = p->Y + p->ny * n;
    memset(p->t, 0, n * sizeof *p->t);
    p->t[j] = 1;
    adh_kernel_apply(p->k, p->t, y, p->kscr);
    adh_hodlr_solve_single(p->hw, y); /* a preconditioner's column: 1e-6 is plenty */
    p->ynode[p->ny] = j;
    *col = p->ny++;
    return ADH_SUCCESS;
}

/* How much J's diagonal at node j moved, relative: |c W_jj (d - d')| /
 * |1 - c W_jj d'|. Deep in contact J_jj is large and p'(h) changes a
 * little with the load; at the contact line it crosses zero and J_jj ~ 1:
 * those are the columns that move. */
static double moved(const adh_visco_pre *p, double c, double d, double dold, size_t j)
{
    double cw = c * p->wdiag[j];
    return fabs(cw * (d - dold)) / fmax(1.0, fabs(1.0 - cw * dold));
}

/* The Woodbury update for diag d at the factorized compliance:
 * ADH_EMAXITER when it would take too many nodes (factorize anew). */
static int update_hodlr(adh_visco_pre *p, const double *d)
{
    size_t n = p->n, r = 0;
    for (size_t j = 0; j < n; j++) {
        if (!(moved(p, p->cf, d[j], p->df[j], j) > VISCO_UPDATE_MIN))
            continue;
        if (r == VISCO_RANK)
            return ADH_EMAXITER;
        p->R[r] = j;
        p->delta[r] = p->cf * (d[j] - p->df[j]);
        if (ycolumn(p, j, &p->col[r]) != ADH_SUCCESS)
            return ADH_EMAXITER;
        r++;
    }
    memcpy(p->deff, p->df, n * sizeof *d);
    for (size_t a = 0; a < r; a++)
        p->deff[p->R[a]] = d[p->R[a]];
    p->r = r;
    if (r == 0)
        return ADH_SUCCESS;
    for (size_t a = 0; a < r; a++) /* column-major K = I - diag(delta) Y_RR */
        for (size_t b = 0; b < r; b++)
            p->K[a + b * r] = (a == b) - p->delta[a] * p->Y[p->col[b] * n + p->R[a]];
    int rr = (int)r, info = 0;
    dgetrf_(&rr, &rr, p->K, &rr, p->kpiv, &info);
    if (info != 0)
        return ADH_EMAXITER;
    p->updates++;
    return ADH_SUCCESS;
}

/* HODLR: the compliance factorized for c: the floor (just below the
 * instantaneous one, adh_visco_pre_base) while c is within twice it, so
 * that the factorization is regular across the instantaneous problem's
 * folds; else c itself, kept while within 30 %. */
static double target(const adh_visco_pre *p, double c)
{
    if (p->cbase > 0 && c < 2 * p->cbase)
        return p->cbase;
    if (p->have && p->cf != p->cbase && fabs(c / p->cf - 1) < 0.3)
        return p->cf;
    return c;
}

/* HODLR: the whole J (factorized anew, or updated), the border by its
 * Schur complement C0 - C J^-1 B. */
static int factor_hodlr(adh_visco_pre *p, double c, const double *C0)
{
    size_t n = p->n, nb = p->nb;
    c = target(p, c);
    int fresh = !p->have || c != p->cf || update_hodlr(p, p->d) != ADH_SUCCESS;
    if (fresh) {
        p->have = 0;
        int rc = adh_hodlr_factorize(p->hw, -c, p->d);
        if (rc != 0)
            return rc < 0 ? ADH_ENOMEM : ADH_ESTALL;
        p->have = 1;
        p->cf = c;
        memcpy(p->df, p->d, n * sizeof *p->d);
        memcpy(p->deff, p->d, n * sizeof *p->d);
        p->r = p->ny = 0;
        p->factorizations++;
    }
    p->m = n;
    double S[ADH_VISCO_BORDER_MAX * ADH_VISCO_BORDER_MAX];
    for (size_t a = 0; a < nb; a++) {
        memcpy(p->Z + a * n, p->B + a * n, n * sizeof *p->Z);
        solve_hodlr(p, p->Z + a * n, 0);
    }
    for (size_t a = 0; a < nb; a++)
        for (size_t b = 0; b < nb; b++)
            S[a * nb + b] = C0[a * nb + b] - cblas_ddot((int)n, p->C + a * n, 1, p->Z + b * n, 1);
    int rc = small_inverse(nb, S);
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
    p->factorizations++;
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
    return p->hw ? factor_hodlr(p, c, C0) : factor_dense(p, act, C0);
}

void adh_visco_pre_solve(adh_visco_pre *p, const double *r, const double *rxi, double *x, double *xi)
{
    size_t n = p->n, nb = p->nb, m = p->m;
    if (x != r)
        memcpy(x, r, n * sizeof *x);
    if (p->hw) {
        solve_hodlr(p, x, 1);
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
    if (p->hw) {
        /* the compliance is GMRES's (target), p'(h) the update's */
        if (!p->have || target(p, c) != p->cf)
            return INFINITY;
        for (size_t j = 0; j < p->n; j++)
            m = fmax(m, moved(p, p->cf, d[j], p->deff[j], j));
        return m;
    }
    for (size_t j = 0; j < p->n; j++)
        m = fmax(m, fabs(c * d[j] - p->c * p->d[j]) * p->wdiag[j] / fmax(1.0, fabs(1.0 - p->c * p->wdiag[j] * p->d[j])));
    return m;
}

void adh_visco_pre_base(adh_visco_pre *p, double c)
{
    p->cbase = c;
    p->have = 0;
}

int adh_visco_pre_stale(const adh_visco_pre *p, double c, const double *d)
{
    return adh_visco_pre_drift(p, c, d) > (p->hw ? VISCO_STALE_HODLR : VISCO_STALE_DENSE);
}

size_t adh_visco_pre_factorizations(const adh_visco_pre *p)
{
    return p->factorizations;
}

size_t adh_visco_pre_active(const adh_visco_pre *p)
{
    return p->m;
}
