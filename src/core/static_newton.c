/* The static solver's Newton-Krylov corrector (src/core/static.h): G(u, h0)
 * = u + (2/E) W p(h0 + r^2/2R - u) and its Jacobian J = I - (2/E) W
 * diag(p'(h)) at a point, the bordered system [J g; theta nu^T nh] solved
 * by flexible GMRES (adhere/fgmres.h) with a preconditioner
 * (adhere/precond.h) set at a recent point, and Newton's iteration on G = 0
 * plus one constraint. Each Newton step uses the exact Jacobian at the
 * iterate; only the preconditioner lags. */
#include "core/static.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/law.h"
#include "adhere/status.h"

#ifndef ADH_TAN_RTOL /* GMRES relative residual for tangents */
#define ADH_TAN_RTOL 1e-8
#endif
#ifndef ADH_NEWTON_RTOL /* and for Newton steps (inexact Newton) */
#define ADH_NEWTON_RTOL 1e-4
#endif
#ifndef ADH_GMRES_FRESH /* more iterations than this: refactorize for next time */
#define ADH_GMRES_FRESH 6
#endif

static double kernel_entry(void *ctx, size_t i, size_t j)
{
    return adh_kernel_entry(ctx, i, j);
}

/* The preconditioner follows the kernel: under a hierarchical storage W
 * is held as a HODLR matrix and the whole Jacobian factorized in
 * O(N log^2 N), with no dense N x N copy; a dense kernel keeps the dense
 * LU over the active prefix (the oracle). */
int static_newton_alloc(adh_static *w)
{
    const adh_precond_type *T =
        adh_kernel_storage_of(w->k) == ADH_STORAGE_DENSE ? adh_precond_dense : adh_precond_hodlr;
    w->nw.P = adh_precond_alloc_shared(T, w->n, kernel_entry, (void *)w->k, w->entries);
    w->nw.kr = adh_fgmres_alloc(w->n + 1, ADH_GMRES_MAX);
    return w->nw.P && w->nw.kr ? ADH_SUCCESS : ADH_ENOMEM;
}

void static_newton_free(adh_static *w)
{
    adh_precond_free(w->nw.P);
    adh_fgmres_free(w->nw.kr);
}

/* h and p from u and h0; G = u + (2/E) W p. Returns max |G| (m), or -1
 * when a gap closed or a value stopped being finite. */
double static_evaluate(adh_static *w, adh_state *x)
{
    size_t n = w->n;
    double *G = w->nw.G;
    for (size_t i = 0; i < n; i++) {
        x->h[i] = x->h0 + w->shape[i] - x->u[i];
        if (!(x->h[i] > 0))
            return -1;
        x->p[i] = adh_lj_pressure(x->h[i], w->m.A, w->m.z0);
    }
    adh_kernel_apply(w->k, x->p, G, w->nw.scratch);
    double r = 0;
    for (size_t i = 0; i < n; i++) {
        G[i] = x->u[i] + w->c2E * G[i];
        r = fmax(r, fabs(G[i]));
    }
    return isfinite(r) ? r : -1;
}

/* p'(h) and g = dG/dh0 = (2/E) W p' at x (h current). */
void static_jacobian(adh_static *w, const adh_state *x, double *D, double *g)
{
    for (size_t i = 0; i < w->n; i++)
        D[i] = adh_lj_dpressure(x->h[i], w->m.A, w->m.z0);
    adh_kernel_apply(w->k, D, g, w->nw.scratch);
    for (size_t i = 0; i < w->n; i++)
        g[i] *= w->c2E;
}

/* Sets the preconditioner at the point whose p'(h) and dG/dh0 are D and
 * g, bordered by (nu, nh). A singular factorization is not a simple fold:
 * the continuation stalls there. */
int static_refactor(adh_static *w, const double *D, const double *g, const double *nu, double nh)
{
    adh_precond_system sys = { .alpha = -w->c2E, .d = D, .g = g, .nu = nu, .nh = nh,
                               .theta = w->s.u_weight, .active_tol = w->nw.act };
    w->nw.stamp = w->nw.attempt;
    w->nw.tangent_border = nu == w->tau_u && nh == w->tau_h;
    w->res.factorizations++;
    int rc = adh_precond_set(w->nw.P, &sys);
    return rc == ADH_ESING ? ADH_ESTALL : rc;
}

/* The whole bordered operator at one point, J = I - (2/E) W diag(D), as
 * FGMRES's callbacks see it: unknowns and right sides are n + 1 numbers
 * (du, dh0). */
typedef struct static_op {
    adh_static *w;
    const double *D, *g, *nu;
    double nh;
} static_op;

static int op_apply(void *ctx, const double *x, double *y)
{
    const static_op *A = ctx;
    adh_static *w = A->w;
    size_t n = w->n;
    double nd = 0, dh = x[n], *t2 = w->nw.t2;
    for (size_t i = 0; i < n; i++)
        t2[i] = A->D[i] * x[i];
    adh_kernel_apply(w->k, t2, y, w->nw.scratch);
    for (size_t i = 0; i < n; i++) {
        y[i] = x[i] - w->c2E * y[i] + A->g[i] * dh;
        nd += A->nu[i] * x[i];
    }
    y[n] = w->s.u_weight * nd + A->nh * dh;
    return ADH_SUCCESS;
}

static int op_precond(void *ctx, const double *x, double *z)
{
    const static_op *A = ctx;
    adh_precond_apply(A->w->nw.P, x, z);
    return ADH_SUCCESS;
}

/* A x = b by FGMRES, right-preconditioned with P (possibly set at a
 * nearby point): each iteration costs one product with W and one
 * preconditioner solve, against a factorization for a new P. */
static int solve(adh_static *w, const static_op *A, const double *b, double rtol, double *x, size_t *its)
{
    adh_fgmres *kr = w->nw.kr;
    adh_fgmres_system sys = { .apply = op_apply, .precond = op_precond, .ctx = (void *)A };
    *its = 0;
    int rc = adh_fgmres_set(kr, &sys, b, rtol);
    if (rc == ADH_SUCCESS) {
        memset(x, 0, (w->n + 1) * sizeof *x);
        return ADH_SUCCESS;
    }
    rc = adh_precond_border(w->nw.P, A->g, A->nu, A->nh);
    if (rc != ADH_SUCCESS)
        return rc;
    while ((rc = adh_fgmres_iterate(kr)) == ADH_CONTINUE)
        ;
    *its = adh_fgmres_iterations(kr);
    w->res.krylov_iterations += *its;
    return rc == ADH_SUCCESS ? adh_fgmres_solution(kr, x) : rc;
}

/* A out = b; when P has grown stale (slow or failed), it is set again at
 * A's point, with more nodes in if even that fails (the truncation was
 * too coarse). */
static int solve_at(adh_static *w, const static_op *A, const double *b, double rtol, double *out)
{
    size_t its;
    int rc = solve(w, A, b, rtol, out, &its);
    if (rc == ADH_SUCCESS && its <= ADH_GMRES_FRESH)
        return ADH_SUCCESS;
    for (int tries = 0; tries < 3; tries++) {
        int lrc = static_refactor(w, A->D, A->g, A->nu, A->nh);
        if (lrc != ADH_SUCCESS)
            return lrc;
        if (rc == ADH_SUCCESS)
            return ADH_SUCCESS; /* solved, slowly: the new P is for next time */
        rc = solve(w, A, b, rtol, out, &its);
        if (rc == ADH_SUCCESS)
            return ADH_SUCCESS;
        if (!adh_precond_type_of(w->nw.P)->truncates)
            break; /* the whole Jacobian was in: nothing more to take in */
        w->nw.act *= 0.1;
    }
    return ADH_EMAXITER;
}

/* Unit tangent at the point whose p'(h) and dG/dh0 are D and g, oriented
 * to continue the current tangent (the bordering row is the current
 * tangent, right side z0). P set there with that border gives det J =
 * det B * t_h (Cramer), and GMRES converges at once. */
int static_tangent(adh_static *w, const double *D, const double *g, double *tu, double *th_out)
{
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight, *du = w->nw.du;
    static_op A = { w, D, g, w->tau_u, w->tau_h };
    w->nw.zero[n] = z0;
    int rc = solve_at(w, &A, w->nw.zero, ADH_TAN_RTOL, du);
    w->nw.zero[n] = 0;
    if (rc != ADH_SUCCESS)
        return rc;
    double dh = du[n], nrm = dh * dh;
    for (size_t i = 0; i < n; i++)
        nrm += th * du[i] * du[i];
    nrm = sqrt(nrm); /* in metres: the tangent is (du, dh0) / nrm, dimensionless */
    for (size_t i = 0; i < n; i++)
        tu[i] = du[i] / nrm;
    *th_out = dh / nrm;
    return ADH_SUCCESS;
}

/* The predictor st + ds tau into trial (h0 = h0_fix instead when fix is
 * set); a plane constraint passes through it. */
void static_predict(adh_static *w, double ds, int fix, double h0_fix)
{
    size_t n = w->n;
    double z0 = w->m.z0;
    adh_state *x = w->trial;
    for (size_t i = 0; i < n; i++)
        x->u[i] = w->st->u[i] + ds * z0 * w->tau_u[i];
    x->h0 = fix ? h0_fix : w->st->h0 + ds * z0 * w->tau_h;
    memcpy(w->nw.upred, x->u, n * sizeof *x->u);
    w->nw.h0pred = x->h0;
}

/* The constraint's residual at x (metres), and its row (nu, nh) for the
 * next solve. */
static double row_residual(adh_static *w, const static_row *row, const adh_state *x, double *nh)
{
    if (row->kind == STATIC_ROW_Q) {
        double qscale = 1;
        return (static_qmeasure(w, x, w->q.rG, nh, &qscale) - row->target) / qscale;
    }
    if (row->kind == STATIC_ROW_GAP)
        return x->h[row->node] - row->gap;
    double cu = 0;
    for (size_t i = 0; i < w->n; i++)
        cu += row->nu[i] * (x->u[i] - w->nw.upred[i]);
    return *nh * (x->h0 - w->nw.h0pred) + w->s.u_weight * cu;
}

/* Shortens an update (du, dh) that would close a gap (the law means
 * nothing there): the factor, or 0 when halving six times did not do. */
static double damping(const adh_static *w, const adh_state *x, const double *du, double dh)
{
    double lam = 1.0;
    for (int tries = 0;; tries++) {
        int closed = 0;
        for (size_t i = 0; i < w->n && !closed; i++)
            closed = !(x->h0 + lam * dh + w->shape[i] - x->u[i] - lam * du[i] > 0);
        if (!closed)
            return lam;
        if (tries == 6)
            return 0;
        lam *= 0.5;
    }
}

/* Newton from the predictor in trial to G = 0 on the constraint row. A
 * plane's residual is its own business (one solve meets it); Q's and a
 * gap's, nonlinear, must be met too. The converged point is left in
 * trial; *iters counts the iterations. */
int static_correct(adh_static *w, const static_row *row, size_t *iters)
{
    size_t n = w->n;
    double z0 = w->m.z0, *du = w->nw.du, *bG = w->nw.bG;
    adh_state *x = w->trial;
    const double *nu = row->kind == STATIC_ROW_Q ? w->q.rG : row->nu;
    double nh = row->nh, prev = INFINITY;
    for (size_t it = 0;; it++) {
        double r = static_evaluate(w, x);
        if (r < 0)
            return ADH_ENAN;
        double cq = row->kind == STATIC_ROW_PLANE ? 0 : row_residual(w, row, x, &nh);
        if (r < w->s.tol * z0 && fabs(cq) < w->s.tol * z0) {
            w->nw.residual = r;
            return ADH_SUCCESS;
        }
        if (it >= w->s.max_newton)
            return ADH_EMAXITER;
        if (w->s.cancel && *w->s.cancel)
            return ADH_EINTR;
        /* Newton near the curve contracts fast; when it does not, a shorter
         * step is cheaper than more iterations */
        if (it >= 3 && r > 0.5 * prev)
            return ADH_EMAXITER;
        prev = r;
        static_jacobian(w, x, w->nw.Dc, w->nw.gc);
        double c = row->kind == STATIC_ROW_PLANE ? row_residual(w, row, x, &nh) : cq;
        for (size_t i = 0; i < n; i++)
            bG[i] = -w->nw.G[i];
        bG[n] = -c;
        if (row->refresh && it == 0 && w->nw.stamp != w->nw.attempt) {
            int lrc = static_refactor(w, w->nw.Dc, w->nw.gc, nu, nh);
            if (lrc != ADH_SUCCESS)
                return lrc;
        }
        static_op A = { w, w->nw.Dc, w->nw.gc, nu, nh };
        int rc = solve_at(w, &A, bG, ADH_NEWTON_RTOL, du);
        if (rc != ADH_SUCCESS)
            return rc;
        double dh = du[n];
        (*iters)++;
        w->res.newton_iterations++;
        double lam = damping(w, x, du, dh);
        if (lam == 0)
            return ADH_ENAN;
        for (size_t i = 0; i < n; i++)
            x->u[i] += lam * du[i];
        x->h0 += lam * dh;
    }
}
