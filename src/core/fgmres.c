#include "adhere/fgmres.h"
#include "adhere/status.h"

#include <gsl/gsl_cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct adh_fgmres {
    size_t n, km;
    double *V;        /* the Krylov basis, km + 1 vectors of n */
    double *Z;        /* the preconditioned vectors, km of n (flexible) */
    double *H;        /* Hessenberg matrix, (km + 1) x km, row stride km,
                         reduced to triangular by the rotations */
    double *cs, *sn;  /* Givens rotations */
    double *gv;       /* the rotated right side |b| e_1 */
    double *yv;       /* the least-squares solution */
    adh_fgmres_system sys;
    double beta, rtol, resid;
    size_t k;         /* iterations done */
    int status;       /* of the last iteration: ADH_CONTINUE while it goes on */
};

adh_fgmres *adh_fgmres_alloc(size_t n, size_t max_iter)
{
    if (n == 0 || max_iter == 0 || max_iter > ADH_FGMRES_MAX_ITER)
        return NULL;
    adh_fgmres *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    size_t km = max_iter;
    f->n = n;
    f->km = km;
    f->V = malloc((2 * km + 1) * n * sizeof *f->V);
    f->H = malloc(((km + 1) * km + 5 * km + 1) * sizeof *f->H);
    if (!f->V || !f->H) {
        adh_fgmres_free(f);
        return NULL;
    }
    f->Z = f->V + (km + 1) * n;
    f->cs = f->H + (km + 1) * km;
    f->sn = f->cs + km;
    f->yv = f->sn + km;
    f->gv = f->yv + km; /* km + 1 */
    return f;
}

void adh_fgmres_free(adh_fgmres *f)
{
    if (!f)
        return;
    free(f->V);
    free(f->H);
    free(f);
}

int adh_fgmres_set(adh_fgmres *f, const adh_fgmres_system *sys, const double *b, double rtol)
{
    size_t n = f->n;
    f->sys = *sys;
    f->rtol = rtol;
    f->k = 0;
    f->beta = cblas_dnrm2((int)n, b, 1);
    f->resid = f->beta;
    if (f->beta == 0) {
        f->status = ADH_SUCCESS;
        return ADH_SUCCESS;
    }
    for (size_t i = 0; i < n; i++)
        f->V[i] = b[i] / f->beta;
    f->gv[0] = f->beta;
    f->status = ADH_CONTINUE;
    return ADH_CONTINUE;
}

/* Applies the previous rotations to the new column j of H, then makes and
 * applies the one that zeroes H[j+1][j]. */
static void rotate(adh_fgmres *f, size_t j)
{
    size_t km = f->km;
    double *H = f->H, *cs = f->cs, *sn = f->sn, *gv = f->gv;
    for (size_t i = 0; i < j; i++) {
        double a = H[i * km + j], c = H[(i + 1) * km + j];
        H[i * km + j] = cs[i] * a + sn[i] * c;
        H[(i + 1) * km + j] = -sn[i] * a + cs[i] * c;
    }
    double a = H[j * km + j], c = H[(j + 1) * km + j], rr = hypot(a, c);
    cs[j] = rr > 0 ? a / rr : 1.0;
    sn[j] = rr > 0 ? c / rr : 0.0;
    H[j * km + j] = rr;
    H[(j + 1) * km + j] = 0;
    gv[j + 1] = -sn[j] * gv[j];
    gv[j] = cs[j] * gv[j];
}

int adh_fgmres_iterate(adh_fgmres *f)
{
    if (f->status != ADH_CONTINUE)
        return f->status;
    size_t n = f->n, km = f->km, j = f->k;
    double *vj = f->V + j * n, *vn = f->V + (j + 1) * n, *zj = f->Z + j * n, *H = f->H;
    int rc = ADH_SUCCESS;
    if (f->sys.precond)
        rc = f->sys.precond(f->sys.ctx, vj, zj);
    else
        memcpy(zj, vj, n * sizeof *zj);
    if (rc == ADH_SUCCESS)
        rc = f->sys.apply(f->sys.ctx, zj, vn);
    if (rc != ADH_SUCCESS)
        return f->status = rc;
    /* modified Gram-Schmidt, twice: the Krylov basis must stay orthogonal */
    for (int pass = 0; pass < 2; pass++)
        for (size_t i = 0; i <= j; i++) {
            double hij = cblas_ddot((int)n, f->V + i * n, 1, vn, 1);
            cblas_daxpy((int)n, -hij, f->V + i * n, 1, vn, 1);
            H[i * km + j] = pass ? H[i * km + j] + hij : hij;
        }
    double hn = cblas_dnrm2((int)n, vn, 1);
    if (!isfinite(hn))
        return f->status = ADH_ENAN;
    H[(j + 1) * km + j] = hn;
    if (hn > 0)
        cblas_dscal((int)n, 1.0 / hn, vn, 1);
    rotate(f, j);
    f->resid = fabs(f->gv[j + 1]);
    f->k = j + 1;
    if (f->resid <= f->rtol * f->beta)
        f->status = ADH_SUCCESS;
    else if (hn == 0)
        f->status = ADH_ESING; /* an invariant space, yet a residual: breakdown */
    else if (f->k == km)
        f->status = ADH_EMAXITER;
    return f->status;
}

int adh_fgmres_solution(adh_fgmres *f, double *x)
{
    size_t n = f->n, km = f->km, k = f->k;
    const double *H = f->H, *gv = f->gv;
    double *yv = f->yv;
    memset(x, 0, n * sizeof *x);
    for (size_t i = k; i-- > 0;) {
        double sum = gv[i];
        for (size_t l = i + 1; l < k; l++)
            sum -= H[i * km + l] * yv[l];
        if (H[i * km + i] == 0)
            return ADH_ESING;
        yv[i] = sum / H[i * km + i];
    }
    /* x from the preconditioned vectors kept (flexible GMRES): no solve
     * more, and the answer is the combination the residual was measured on */
    for (size_t i = 0; i < k; i++)
        cblas_daxpy((int)n, yv[i], f->Z + i * n, 1, x, 1);
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return ADH_ENAN;
    return ADH_SUCCESS;
}

size_t adh_fgmres_iterations(const adh_fgmres *f)
{
    return f->k;
}

double adh_fgmres_residual(const adh_fgmres *f)
{
    return f->resid;
}

int adh_fgmres_solve(adh_fgmres *f, const adh_fgmres_system *sys, const double *b, double rtol, double *x,
                     size_t *its)
{
    int rc = adh_fgmres_set(f, sys, b, rtol);
    while (rc == ADH_CONTINUE)
        rc = adh_fgmres_iterate(f);
    if (its)
        *its = f->k;
    if (f->k == 0 && rc == ADH_SUCCESS) {
        memset(x, 0, f->n * sizeof *x);
        return ADH_SUCCESS;
    }
    int xrc = adh_fgmres_solution(f, x);
    return rc != ADH_SUCCESS ? rc : xrc;
}
