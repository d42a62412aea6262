/* Flexible GMRES (adhere/fgmres.h) alone, against LAPACK's LU solves
 * (lapacke) of the same systems: unpreconditioned, with a preconditioner
 * that changes every iteration (what "flexible" is for), with an exact one
 * (one iteration), and every way a solve stops short: the iteration cap,
 * a callback's error, a product that is not finite, b = 0, bad sizes. */
#include <gsl/gsl_cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/fgmres.h"
#include "adhere/status.h"
#include "tap.h"

#define N 60

typedef struct sys {
    const double *A;   /* row-major N x N */
    const double *LU;  /* LAPACK's factors of A (column-major A^T's), for the exact preconditioner */
    const lapack_int *piv;
    int calls, fail_at, fail_with, nan_at;
} sys;

static int apply(void *ctx, const double *x, double *y)
{
    sys *s = ctx;
    if (++s->calls == s->fail_at)
        return s->fail_with;
    for (int i = 0; i < N; i++) {
        y[i] = 0;
        for (int j = 0; j < N; j++)
            y[i] += s->A[i * N + j] * x[j];
    }
    if (s->calls == s->nan_at)
        y[3] = NAN;
    return ADH_SUCCESS;
}

/* Jacobi with a weight that changes every call: a different M each
 * iteration, which plain GMRES cannot take and flexible GMRES can. */
static int jacobi_varying(void *ctx, const double *x, double *z)
{
    sys *s = ctx;
    static int k;
    double wgt = 1.0 + 0.4 * sin(1.3 * k++);
    for (int i = 0; i < N; i++)
        z[i] = wgt * x[i] / s->A[i * N + i];
    return ADH_SUCCESS;
}

static int exact(void *ctx, const double *x, double *z)
{
    sys *s = ctx;
    memcpy(z, x, N * sizeof *z);
    /* A = (A^T)^T: LAPACK factored A^T (the row-major array read
     * column-major), so A z = x is its transposed solve */
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'T', N, 1, s->LU, N, s->piv, z, N);
    return ADH_SUCCESS;
}

/* |b - A x| / |b| computed here, not as the iteration measured it */
static double true_residual(const double *A, const double *x, const double *b)
{
    double r2 = 0, b2 = 0;
    for (int i = 0; i < N; i++) {
        double r = b[i];
        for (int j = 0; j < N; j++)
            r -= A[i * N + j] * x[j];
        r2 += r * r;
        b2 += b[i] * b[i];
    }
    return sqrt(r2 / b2);
}

int main(void)
{
    /* a nonsymmetric matrix with a spread spectrum (a convection-diffusion
     * stencil plus a smooth dense part), and a right side */
    static double A[N * N], LU[N * N], Aref[N * N], b[N], xref[N], x[N];
    lapack_int piv[N], pref[N];
    for (int i = 0; i < N; i++) {
        for (int j = 0; j < N; j++)
            A[i * N + j] = 0.3 / (1.0 + fabs((double)(i - j))) * cos(0.7 * i - 0.2 * j);
        A[i * N + i] += 2.0 + 0.05 * i;
        if (i > 0)
            A[i * N + i - 1] -= 1.3;
        if (i + 1 < N)
            A[i * N + i + 1] -= 0.6;
        b[i] = sin(0.37 * i) + 0.5;
    }
    /* the reference: LAPACK's dgesv on the same system */
    memcpy(Aref, A, sizeof A);
    memcpy(xref, b, sizeof b);
    ok(LAPACKE_dgesv(LAPACK_ROW_MAJOR, N, 1, Aref, N, pref, xref, 1) == 0, "LAPACK solves the reference system");
    memcpy(LU, A, sizeof A);
    LAPACKE_dgetrf(LAPACK_COL_MAJOR, N, N, LU, N, piv);

    adh_fgmres *f = adh_fgmres_alloc(N, N);
    ok(f != NULL, "allocated for %d unknowns, %d iterations", N, N);
    sys s = { .A = A, .LU = LU, .piv = piv };
    size_t its = 0;

    adh_fgmres_system plain = { .apply = apply, .ctx = &s };
    int rc = adh_fgmres_solve(f, &plain, b, 1e-12, x, &its);
    ok(rc == ADH_SUCCESS && tap_maxrel(x, xref, N) < 1e-10,
       "unpreconditioned: converged in %zu iterations, within 1e-10 of LAPACK (%.1e)", its, tap_maxrel(x, xref, N));
    ok(true_residual(A, x, b) < 2e-12 && adh_fgmres_residual(f) <= 1e-12 * cblas_dnrm2(N, b, 1),
       "the residual it claims holds: |b - Ax|/|b| = %.1e", true_residual(A, x, b));
    size_t its_plain = its;

    adh_fgmres_system flex = { .apply = apply, .precond = jacobi_varying, .ctx = &s };
    rc = adh_fgmres_solve(f, &flex, b, 1e-12, x, &its);
    ok(rc == ADH_SUCCESS && tap_maxrel(x, xref, N) < 1e-10,
       "a preconditioner changing every iteration: converged in %zu, within 1e-10 of LAPACK (%.1e)", its,
       tap_maxrel(x, xref, N));
    ok(true_residual(A, x, b) < 2e-12, "... and its x has the residual measured (%.1e): the kept z_j",
       true_residual(A, x, b));

    adh_fgmres_system lu = { .apply = apply, .precond = exact, .ctx = &s };
    rc = adh_fgmres_solve(f, &lu, b, 1e-12, x, &its);
    ok(rc == ADH_SUCCESS && its == 1 && tap_maxrel(x, xref, N) < 1e-12,
       "the exact inverse as preconditioner: one iteration (%zu), within 1e-12 (%.1e)", its, tap_maxrel(x, xref, N));

    /* step by step, GSL style: the residual falls monotonically */
    rc = adh_fgmres_set(f, &plain, b, 1e-12);
    double prev = INFINITY;
    int mono = 1;
    while (rc == ADH_CONTINUE) {
        rc = adh_fgmres_iterate(f);
        mono &= adh_fgmres_residual(f) <= prev;
        prev = adh_fgmres_residual(f);
    }
    ok(rc == ADH_SUCCESS && mono && adh_fgmres_iterations(f) == its_plain,
       "set/iterate: the residual never rises, the same %zu iterations as solve", adh_fgmres_iterations(f));
    ok(adh_fgmres_solution(f, x) == ADH_SUCCESS && tap_maxrel(x, xref, N) < 1e-10, "solution after iterate");

    adh_fgmres *small = adh_fgmres_alloc(N, 3);
    rc = adh_fgmres_solve(small, &plain, b, 1e-12, x, &its);
    ok(rc == ADH_EMAXITER && its == 3, "three iterations allowed: ADH_EMAXITER after %zu", its);

    s.calls = 0, s.fail_at = 2, s.fail_with = ADH_ENOMEM;
    rc = adh_fgmres_solve(f, &plain, b, 1e-12, x, &its);
    ok(rc == ADH_ENOMEM && its == 1, "a product that fails: its status (%d), after %zu iteration", rc, its);
    s.calls = 0, s.fail_at = 0, s.nan_at = 3;
    rc = adh_fgmres_solve(f, &plain, b, 1e-12, x, &its);
    ok(rc == ADH_ENAN, "a product that is not finite: ADH_ENAN (%d)", rc);
    s.nan_at = 0;

    double zero[N] = { 0 };
    x[0] = 7;
    rc = adh_fgmres_solve(f, &plain, zero, 1e-12, x, &its);
    ok(rc == ADH_SUCCESS && its == 0 && x[0] == 0, "b = 0: x = 0 with no iteration");

    ok(adh_fgmres_alloc(0, 10) == NULL && adh_fgmres_alloc(N, 0) == NULL &&
           adh_fgmres_alloc(N, ADH_FGMRES_MAX_ITER + 1) == NULL,
       "no workspace for 0 unknowns, 0 iterations or past ADH_FGMRES_MAX_ITER");
    adh_fgmres_free(small);
    adh_fgmres_free(f);
    adh_fgmres_free(NULL);
    return tap_done();
}
