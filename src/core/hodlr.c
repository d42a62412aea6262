#include "adhere/hodlr.h"
#include "adhere/status.h"

#include <gsl/gsl_cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* LAPACK (OpenBLAS's, as the program is linked) through lapacke's _work
 * calls: column-major, no copies, no NaN scan. */

/* Matrices are column-major. A node covers cells lo .. lo+n-1; an inner
 * node's children split them at lo + n0. */
typedef struct node {
    size_t lo, n, n0;
    int c[2];            /* children, -1 at a leaf */
    /* leaf: W's block, A's block's inverse (a GMRES solve is then one
     * matrix-vector product, not two triangular solves of 64), scratch */
    double *Wl, *Al, *lt;
    int *piv;
    /* inner: W[c0,c1] = U01 V01^T, W[c1,c0] = U10 V10^T */
    size_t k01, k10;
    double *U01, *V01, *U10, *V10;
    /* factorization: Y0 = A_c0^-1 U01, Y1 = A_c1^-1 U10, the scaled
     * Vt01 = alpha diag(d_c1) V01, Vt10 = alpha diag(d_c0) V10 (held as V,
     * column-major: products with their transposes read contiguous
     * columns), and the LU of the capacitance matrix
     * S = [[I, Vt01^T Y1], [Vt10^T Y0, I]], then S's inverse (its LU
     * gives the determinant's sign; the inverse is applied in every solve
     * from every ancestor, where small triangular solves cost more) */
    double *Y0, *Y1, *Vt01, *Vt10, *S, *t, *t2;
    int *spiv;
    int sign;
    /* the factorization's solve operands in single precision (Al; Y0, Y1,
     * Vt01, Vt10 and S's inverse in one block), and a scratch of n or 2 K */
    float *Alf, *Yf, *sf;
} node;

struct adh_hodlr {
    size_t n, leaf, nnodes, cap;
    node *nodes;
    adh_hodlr_entry_fn entry;
    void *ctx;
    double tol;
    size_t max_rank;
    size_t bytes_w, bytes_f;
    float *bf; /* the right side of a single-precision solve */
    int single; /* the single-precision copies hold every number (none past FLT_MAX) */
    double *work; /* dgetri's, 64 x the largest capacitance */
    size_t kmax;
};

/* ADH_SUCCESS, ADH_ESING (a pivot exactly zero or not finite) or
 * ADH_EINVAL (LAPACK refused an argument). */
static int lu(double *a, int n, int *piv, int *sign)
{
    if (n == 0) {
        *sign = 1;
        return ADH_SUCCESS;
    }
    if (LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, n, n, a, n, piv) < 0)
        return ADH_EINVAL;
    int s = 1;
    for (int i = 0; i < n; i++) {
        double d = a[i + (size_t)i * n];
        if (d == 0 || !isfinite(d))
            return ADH_ESING;
        if (piv[i] != i + 1)
            s = -s;
        if (d < 0)
            s = -s;
    }
    *sign = s;
    return ADH_SUCCESS;
}

/* The inverse from lu's factors, in place (work: lw numbers). */
static int lu_inverse(double *a, int n, const int *piv, double *work, int lw)
{
    return LAPACKE_dgetri_work(LAPACK_COL_MAJOR, n, a, n, piv, work, lw) == 0 ? ADH_SUCCESS : ADH_ESING;
}

/* Cross approximation with partial pivoting of W's block rows i0.., columns
 * j0..: U (ni x k) V^T (nj x k), stopping when the last cross is below tol
 * of the approximation's Frobenius norm. ADH_SUCCESS or ADH_ENOMEM. */
static int aca(adh_hodlr *h, size_t i0, size_t ni, size_t j0, size_t nj, double **Uo, double **Vo, size_t *ko)
{
    size_t kmax = ni < nj ? ni : nj, cap = 16 < kmax ? 16 : kmax, k = 0;
    double *U = malloc(cap * ni * sizeof *U), *V = malloc(cap * nj * sizeof *V);
    double *row = malloc(nj * sizeof *row), *col = malloc(ni * sizeof *col);
    char *used = calloc(ni, 1);
    if (!U || !V || !row || !col || !used)
        goto oom;
    double norm2 = 0;
    size_t i = ni / 2, zeros = 0;
    while (k < kmax) {
        used[i] = 1;
        for (size_t j = 0; j < nj; j++)
            row[j] = h->entry(h->ctx, i0 + i, j0 + j);
        for (size_t l = 0; l < k; l++)
            cblas_daxpy((int)nj, -U[i + l * ni], V + l * nj, 1, row, 1);
        size_t js = (size_t)cblas_idamax((int)nj, row, 1);
        double piv = row[js];
        if (!(fabs(piv) > 1e-300 * (1 + sqrt(norm2)))) {
            /* a row already matched: try another unused one */
            size_t r = 0;
            while (r < ni && used[r])
                r++;
            if (r == ni || ++zeros > 3)
                break;
            i = r;
            continue;
        }
        for (size_t r = 0; r < ni; r++)
            col[r] = h->entry(h->ctx, i0 + r, j0 + js);
        for (size_t l = 0; l < k; l++)
            cblas_daxpy((int)ni, -V[js + l * nj], U + l * ni, 1, col, 1);
        if (k == cap) {
            cap = 2 * cap < kmax ? 2 * cap : kmax;
            double *nu = realloc(U, cap * ni * sizeof *U);
            if (!nu)
                goto oom;
            U = nu;
            double *nv = realloc(V, cap * nj * sizeof *V);
            if (!nv)
                goto oom;
            V = nv;
        }
        double *u = U + k * ni, *v = V + k * nj;
        memcpy(u, col, ni * sizeof *u);
        for (size_t j = 0; j < nj; j++)
            v[j] = row[j] / piv;
        double uu = cblas_ddot((int)ni, u, 1, u, 1), vv = cblas_ddot((int)nj, v, 1, v, 1), cross = 0;
        for (size_t l = 0; l < k; l++)
            cross += cblas_ddot((int)ni, U + l * ni, 1, u, 1) * cblas_ddot((int)nj, V + l * nj, 1, v, 1);
        norm2 += uu * vv + 2 * cross;
        k++;
        if (uu * vv <= h->tol * h->tol * norm2)
            break;
        /* the next row: the largest of the new column among the unused */
        double best = -1;
        size_t bi = ni;
        for (size_t r = 0; r < ni; r++)
            if (!used[r] && fabs(u[r]) > best)
                best = fabs(u[r]), bi = r;
        if (bi == ni)
            break;
        i = bi;
    }
    free(row), free(col), free(used);
    *Uo = U, *Vo = V, *ko = k;
    h->bytes_w += k * (ni + nj) * sizeof *U;
    if (k > h->max_rank)
        h->max_rank = k;
    return ADH_SUCCESS;
oom:
    free(U), free(V), free(row), free(col), free(used);
    return ADH_ENOMEM;
}

static int build(adh_hodlr *h, size_t lo, size_t n)
{
    if (h->nnodes == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 64;
        node *nn = realloc(h->nodes, cap * sizeof *nn);
        if (!nn)
            return -1;
        h->nodes = nn, h->cap = cap;
    }
    int id = (int)h->nnodes++;
    node *b = &h->nodes[id];
    memset(b, 0, sizeof *b);
    b->lo = lo, b->n = n, b->c[0] = b->c[1] = -1;
    if (n <= h->leaf) {
        double *Wl = malloc(n * n * sizeof *Wl), *Al = malloc(n * n * sizeof *Al);
        double *lt = malloc(64 * n * sizeof *lt);
        int *piv = malloc(n * sizeof *piv);
        float *Alf = malloc(n * n * sizeof *Alf), *sf = malloc(n * sizeof *sf);
        b = &h->nodes[id];
        b->Wl = Wl, b->Al = Al, b->piv = piv, b->lt = lt, b->Alf = Alf, b->sf = sf;
        if (!Wl || !Al || !piv || !lt || !Alf || !sf)
            return -1;
        for (size_t j = 0; j < n; j++)
            for (size_t i = 0; i < n; i++)
                Wl[i + j * n] = h->entry(h->ctx, lo + i, lo + j);
        h->bytes_w += n * n * sizeof *Wl;
        h->bytes_f += n * n * (sizeof *Al + sizeof *Alf);
        return id;
    }
    size_t n0 = n / 2, n1 = n - n0;
    double *U01, *V01, *U10, *V10;
    size_t k01, k10;
    if (aca(h, lo, n0, lo + n0, n1, &U01, &V01, &k01) != ADH_SUCCESS)
        return -1;
    if (aca(h, lo + n0, n1, lo, n0, &U10, &V10, &k10) != ADH_SUCCESS) {
        free(U01), free(V01);
        return -1;
    }
    size_t K = k01 + k10;
    b = &h->nodes[id];
    b->n0 = n0, b->k01 = k01, b->k10 = k10;
    b->U01 = U01, b->V01 = V01, b->U10 = U10, b->V10 = V10;
    b->Y0 = malloc((k01 * n0 + k10 * n1) * sizeof(double));
    b->Vt01 = malloc((k01 * n1 + k10 * n0) * sizeof(double));
    b->S = malloc((K * K + 2 * K) * sizeof(double));
    b->spiv = malloc((K + 1) * sizeof(int));
    b->Yf = malloc(((k01 + k10) * (n0 + n1) + K * K) * sizeof(float));
    b->sf = malloc((2 * K + 1) * sizeof(float));
    if (!b->Y0 || !b->Vt01 || !b->S || !b->spiv || !b->Yf || !b->sf)
        return -1;
    b->Y1 = b->Y0 + k01 * n0;
    b->Vt10 = b->Vt01 + k01 * n1;
    b->t = b->S + K * K;
    b->t2 = b->t + K;
    if (K > h->kmax)
        h->kmax = K;
    h->bytes_f += (2 * (k01 * n0 + k10 * n1) + K * K + 2 * K) * sizeof(double) +
                  ((k01 + k10) * (n0 + n1) + K * K + 2 * K) * sizeof(float);
    int c0 = build(h, lo, n0);
    if (c0 < 0)
        return -1;
    int c1 = build(h, lo + n0, n1);
    if (c1 < 0)
        return -1;
    h->nodes[id].c[0] = c0, h->nodes[id].c[1] = c1;
    return id;
}

void adh_hodlr_free(adh_hodlr *h)
{
    if (!h)
        return;
    for (size_t i = 0; i < h->nnodes; i++) {
        node *b = &h->nodes[i];
        free(b->Wl), free(b->Al), free(b->piv), free(b->lt);
        free(b->U01), free(b->V01), free(b->U10), free(b->V10);
        free(b->Y0), free(b->Vt01), free(b->S), free(b->spiv);
        free(b->Alf), free(b->Yf), free(b->sf);
    }
    free(h->nodes);
    free(h->bf);
    free(h->work);
    free(h);
}

adh_hodlr *adh_hodlr_alloc(size_t n, adh_hodlr_entry_fn entry, void *ctx, double tol, size_t leaf)
{
    if (n == 0 || !entry || !(tol > 0 && tol < 1) || leaf < 2)
        return NULL;
    adh_hodlr *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->n = n, h->leaf = leaf, h->entry = entry, h->ctx = ctx, h->tol = tol;
    h->bf = malloc(n * sizeof *h->bf);
    if (!h->bf || build(h, 0, n) < 0 || !(h->work = malloc(64 * (h->kmax + 1) * sizeof *h->work))) {
        adh_hodlr_free(h);
        return NULL;
    }
    return h;
}

/* Solves A_b X = B in place for node b (B: b->n rows of nrhs columns,
 * leading dimension ldb) with its factorization. ADH_SUCCESS, or
 * ADH_ENOMEM when a multi-column solve (factorize's) could not allocate:
 * one column never allocates. */
static int solve_node(adh_hodlr *h, int id, double *B, size_t ldb, size_t nrhs)
{
    node *b = &h->nodes[id];
    if (b->c[0] < 0) {
        size_t n = b->n;
        if (nrhs == 1) {
            cblas_dgemv(CblasColMajor, CblasNoTrans, (int)n, (int)n, 1.0, b->Al, (int)n, B, 1, 0.0, b->lt, 1);
            memcpy(B, b->lt, n * sizeof *B);
            return ADH_SUCCESS;
        }
        double *T = malloc(n * nrhs * sizeof *T);
        if (!T)
            return ADH_ENOMEM;
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, (int)n, (int)nrhs, (int)n, 1.0, b->Al, (int)n, B,
                    (int)ldb, 0.0, T, (int)n);
        for (size_t c = 0; c < nrhs; c++)
            memcpy(B + c * ldb, T + c * n, n * sizeof *B);
        free(T);
        return ADH_SUCCESS;
    }
    size_t n0 = b->n0, n1 = b->n - n0, K = b->k01 + b->k10;
    int rc = solve_node(h, b->c[0], B, ldb, nrhs);
    if (rc == ADH_SUCCESS)
        rc = solve_node(h, b->c[1], B + n0, ldb, nrhs);
    if (rc != ADH_SUCCESS || K == 0)
        return rc;
    int kk = (int)K, nr = (int)nrhs;
    if (nrhs == 1) {
        /* one column (GMRES): matrix-vector products, not dgemm's blocking */
        double *t = b->t2;
        if (b->k01)
            cblas_dgemv(CblasColMajor, CblasTrans, (int)n1, (int)b->k01, 1.0, b->Vt01, (int)n1, B + n0, 1, 0.0,
                        b->t, 1);
        if (b->k10)
            cblas_dgemv(CblasColMajor, CblasTrans, (int)n0, (int)b->k10, 1.0, b->Vt10, (int)n0, B, 1, 0.0,
                        b->t + b->k01, 1);
        cblas_dgemv(CblasColMajor, CblasNoTrans, kk, kk, 1.0, b->S, kk, b->t, 1, 0.0, t, 1);
        if (b->k01)
            cblas_dgemv(CblasColMajor, CblasNoTrans, (int)n0, (int)b->k01, -1.0, b->Y0, (int)n0, t, 1, 1.0, B, 1);
        if (b->k10)
            cblas_dgemv(CblasColMajor, CblasNoTrans, (int)n1, (int)b->k10, -1.0, b->Y1, (int)n1, t + b->k01, 1, 1.0,
                        B + n0, 1);
        return ADH_SUCCESS;
    }
    double *T0 = malloc(2 * K * nrhs * sizeof *T0), *T = T0 + K * nrhs;
    if (!T0)
        return ADH_ENOMEM;
    if (b->k01)
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)b->k01, (int)nrhs, (int)n1, 1.0, b->Vt01,
                    (int)n1, B + n0, (int)ldb, 0.0, T0, (int)K);
    if (b->k10)
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)b->k10, (int)nrhs, (int)n0, 1.0, b->Vt10,
                    (int)n0, B, (int)ldb, 0.0, T0 + b->k01, (int)K);
    cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, kk, nr, kk, 1.0, b->S, kk, T0, kk, 0.0, T, kk);
    if (b->k01)
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, (int)n0, (int)nrhs, (int)b->k01, -1.0, b->Y0,
                    (int)n0, T, (int)K, 1.0, B, (int)ldb);
    if (b->k10)
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, (int)n1, (int)nrhs, (int)b->k10, -1.0, b->Y1,
                    (int)n1, T + b->k01, (int)K, 1.0, B + n0, (int)ldb);
    free(T0);
    return ADH_SUCCESS;
}

static int factor_node(adh_hodlr *h, int id, double alpha, const double *d)
{
    node *b = &h->nodes[id];
    if (b->c[0] < 0) {
        size_t n = b->n;
        for (size_t j = 0; j < n; j++) {
            double s = alpha * d[b->lo + j];
            for (size_t i = 0; i < n; i++)
                b->Al[i + j * n] = s * b->Wl[i + j * n];
            b->Al[j + j * n] += 1.0;
        }
        int rc = lu(b->Al, (int)n, b->piv, &b->sign);
        return rc != ADH_SUCCESS ? rc : lu_inverse(b->Al, (int)n, b->piv, b->lt, 64 * (int)n);
    }
    int rc = factor_node(h, b->c[0], alpha, d);
    if (rc == ADH_SUCCESS)
        rc = factor_node(h, b->c[1], alpha, d);
    if (rc != ADH_SUCCESS)
        return rc;
    b = &h->nodes[id];
    size_t n0 = b->n0, n1 = b->n - n0, k01 = b->k01, k10 = b->k10, K = k01 + k10;
    const double *d0 = d + b->lo, *d1 = d0 + n0;
    for (size_t l = 0; l < k01; l++)
        for (size_t j = 0; j < n1; j++)
            b->Vt01[j + l * n1] = alpha * b->V01[j + l * n1] * d1[j];
    for (size_t l = 0; l < k10; l++)
        for (size_t j = 0; j < n0; j++)
            b->Vt10[j + l * n0] = alpha * b->V10[j + l * n0] * d0[j];
    if (k01) {
        memcpy(b->Y0, b->U01, k01 * n0 * sizeof *b->Y0);
        rc = solve_node(h, b->c[0], b->Y0, n0, k01);
    }
    if (k10 && rc == ADH_SUCCESS) {
        memcpy(b->Y1, b->U10, k10 * n1 * sizeof *b->Y1);
        rc = solve_node(h, b->c[1], b->Y1, n1, k10);
    }
    if (rc != ADH_SUCCESS)
        return rc;
    double *S = b->S;
    memset(S, 0, K * K * sizeof *S);
    for (size_t i = 0; i < K; i++)
        S[i + i * K] = 1.0;
    if (k01 && k10) {
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)k01, (int)k10, (int)n1, 1.0, b->Vt01, (int)n1,
                    b->Y1, (int)n1, 0.0, S + k01 * K, (int)K);
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, (int)k10, (int)k01, (int)n0, 1.0, b->Vt10, (int)n0,
                    b->Y0, (int)n0, 0.0, S + k01, (int)K);
    }
    int s = 1;
    rc = lu(S, (int)K, b->spiv, &s);
    b->sign = s * h->nodes[b->c[0]].sign * h->nodes[b->c[1]].sign;
    if (rc != ADH_SUCCESS)
        return rc;
    return lu_inverse(S, (int)K, b->spiv, h->work, 64 * (int)(h->kmax + 1));
}

/* 0 when a number does not fit (a factor near singularity can pass FLT_MAX) */
static int to_float(float *f, const double *x, size_t n)
{
    int fits = 1;
    for (size_t i = 0; i < n; i++) {
        f[i] = (float)x[i];
        fits &= isfinite(f[i]) || !isfinite(x[i]);
    }
    return fits;
}

int adh_hodlr_factorize(adh_hodlr *h, double alpha, const double *d)
{
    h->single = 0;
    int rc = factor_node(h, 0, alpha, d);
    if (rc != ADH_SUCCESS)
        return rc;
    int fits = 1;
    for (size_t i = 0; i < h->nnodes; i++) {
        node *b = &h->nodes[i];
        if (b->c[0] < 0) {
            fits &= to_float(b->Alf, b->Al, b->n * b->n);
            continue;
        }
        size_t n0 = b->n0, n1 = b->n - n0, my = b->k01 * n0 + b->k10 * n1, mv = b->k01 * n1 + b->k10 * n0;
        fits &= to_float(b->Yf, b->Y0, my); /* Y0 and Y1 are one block, as Vt01 and Vt10 */
        fits &= to_float(b->Yf + my, b->Vt01, mv);
        fits &= to_float(b->Yf + my + mv, b->S, (b->k01 + b->k10) * (b->k01 + b->k10));
    }
    h->single = fits;
    return ADH_SUCCESS;
}

void adh_hodlr_solve(adh_hodlr *h, double *b)
{
    solve_node(h, 0, b, h->n, 1);
}

/* solve_node's one-column path on the single-precision operands. */
static void solve_node_f(adh_hodlr *h, int id, float *B)
{
    node *b = &h->nodes[id];
    size_t n = b->n;
    if (b->c[0] < 0) {
        cblas_sgemv(CblasColMajor, CblasNoTrans, (int)n, (int)n, 1.0f, b->Alf, (int)n, B, 1, 0.0f, b->sf, 1);
        memcpy(B, b->sf, n * sizeof *B);
        return;
    }
    size_t n0 = b->n0, n1 = n - n0, k01 = b->k01, k10 = b->k10, K = k01 + k10;
    solve_node_f(h, b->c[0], B);
    solve_node_f(h, b->c[1], B + n0);
    if (K == 0)
        return;
    const float *Y0 = b->Yf, *Y1 = Y0 + k01 * n0, *Vt01 = Y1 + k10 * n1, *Vt10 = Vt01 + k01 * n1;
    const float *Si = Vt10 + k10 * n0;
    float *t0 = b->sf, *tf = t0 + K;
    if (k01)
        cblas_sgemv(CblasColMajor, CblasTrans, (int)n1, (int)k01, 1.0f, Vt01, (int)n1, B + n0, 1, 0.0f, t0, 1);
    if (k10)
        cblas_sgemv(CblasColMajor, CblasTrans, (int)n0, (int)k10, 1.0f, Vt10, (int)n0, B, 1, 0.0f, t0 + k01, 1);
    cblas_sgemv(CblasColMajor, CblasNoTrans, (int)K, (int)K, 1.0f, Si, (int)K, t0, 1, 0.0f, tf, 1);
    if (k01)
        cblas_sgemv(CblasColMajor, CblasNoTrans, (int)n0, (int)k01, -1.0f, Y0, (int)n0, tf, 1, 1.0f, B, 1);
    if (k10)
        cblas_sgemv(CblasColMajor, CblasNoTrans, (int)n1, (int)k10, -1.0f, Y1, (int)n1, tf + k01, 1, 1.0f,
                    B + n0, 1);
}

void adh_hodlr_solve_single(adh_hodlr *h, double *b)
{
    if (!h->single || !to_float(h->bf, b, h->n)) {
        solve_node(h, 0, b, h->n, 1);
        return;
    }
    solve_node_f(h, 0, h->bf);
    for (size_t i = 0; i < h->n; i++)
        b[i] = h->bf[i];
}

int adh_hodlr_det_sign(const adh_hodlr *h)
{
    return h->nodes[0].sign;
}

static void apply_node(const adh_hodlr *h, int id, const double *v, double *y)
{
    const node *b = &h->nodes[id];
    if (b->c[0] < 0) {
        cblas_dgemv(CblasColMajor, CblasNoTrans, (int)b->n, (int)b->n, 1.0, b->Wl, (int)b->n, v, 1, 1.0, y, 1);
        return;
    }
    size_t n0 = b->n0, n1 = b->n - n0;
    apply_node(h, b->c[0], v, y);
    apply_node(h, b->c[1], v + n0, y + n0);
    for (size_t l = 0; l < b->k01; l++)
        cblas_daxpy((int)n0, cblas_ddot((int)n1, b->V01 + l * n1, 1, v + n0, 1), b->U01 + l * n0, 1, y, 1);
    for (size_t l = 0; l < b->k10; l++)
        cblas_daxpy((int)n1, cblas_ddot((int)n0, b->V10 + l * n0, 1, v, 1), b->U10 + l * n1, 1, y + n0, 1);
}

void adh_hodlr_apply(const adh_hodlr *h, const double *v, double *y)
{
    memset(y, 0, h->n * sizeof *y);
    apply_node(h, 0, v, y);
}

size_t adh_hodlr_bytes(const adh_hodlr *h)
{
    return h->bytes_w + h->bytes_f + h->cap * sizeof *h->nodes;
}

size_t adh_hodlr_max_rank(const adh_hodlr *h)
{
    return h->max_rank;
}
