/* The preconditioners (adhere/precond.h) alone, against LAPACK's LU
 * (lapacke) of the whole bordered matrix
 *     B = [ I + alpha W diag(d)   g ;  theta nu^T   nh ]
 * on the ring kernel of a graded grid, d shaped like the static mode's
 * p'(h) (large over a contact, a bump of the other sign at its edge,
 * decaying outside): the dense one untruncated is B^-1 to rounding, and
 * truncated takes the prefix its rule names; both make flexible GMRES
 * converge to LAPACK's solution in a few iterations, with another border
 * too; det B's sign is LAPACK's, through a sign change; a singular B is
 * reported. */
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/fgmres.h"
#include "adhere/kernel.h"
#include "adhere/precond.h"
#include "adhere/rings.h"
#include "adhere/status.h"
#include "tap.h"

typedef struct problem {
    size_t n;
    const double *W;         /* row-major */
    double alpha, theta, nh;
    const double *d, *g, *nu;
    adh_precond *P;
} problem;

static double entry(void *ctx, size_t i, size_t j)
{
    return adh_kernel_entry(ctx, i, j);
}

/* y = B x */
static int apply_B(void *ctx, const double *x, double *y)
{
    const problem *p = ctx;
    size_t n = p->n;
    double nd = 0;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (size_t j = 0; j < n; j++)
            s += p->W[i * n + j] * p->d[j] * x[j];
        y[i] = x[i] + p->alpha * s + p->g[i] * x[n];
        nd += p->nu[i] * x[i];
    }
    y[n] = p->theta * nd + p->nh * x[n];
    return ADH_SUCCESS;
}

static int apply_M(void *ctx, const double *x, double *z)
{
    adh_precond_apply(((const problem *)ctx)->P, x, z);
    return ADH_SUCCESS;
}

/* B (row-major, n + 1 square) solved for x in place by LAPACK; det B's sign */
static int lapack_solve(const problem *p, double *x)
{
    size_t n = p->n, m = n + 1;
    double *B = malloc(m * m * sizeof *B);
    lapack_int *piv = malloc(m * sizeof *piv);
    /* B column-major, as apply_B applies it */
    for (size_t j = 0; j < n; j++) {
        for (size_t i = 0; i < n; i++)
            B[i + j * m] = (i == j) + p->alpha * p->W[i * n + j] * p->d[j];
        B[n + j * m] = p->theta * p->nu[j];
    }
    for (size_t i = 0; i < n; i++)
        B[i + n * m] = p->g[i];
    B[n + n * m] = p->nh;
    int sign = LAPACKE_dgetrf(LAPACK_COL_MAJOR, (lapack_int)m, (lapack_int)m, B, (lapack_int)m, piv) == 0;
    for (size_t i = 0; i < m && sign; i++)
        sign *= (piv[i] != (lapack_int)i + 1 ? -1 : 1) * (B[i + i * m] < 0 ? -1 : 1);
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', (lapack_int)m, 1, B, (lapack_int)m, piv, x, (lapack_int)m);
    free(B), free(piv);
    return sign;
}

static int set(problem *p, double active_tol)
{
    adh_precond_system sys = { .alpha = p->alpha, .d = p->d, .g = p->g, .nu = p->nu, .nh = p->nh,
                               .theta = p->theta, .active_tol = active_tol };
    return adh_precond_set(p->P, &sys);
}

/* FGMRES on B with P to 1e-10: iterations, or -1 when it failed */
static int krylov(problem *p, const double *b, double *x)
{
    adh_fgmres *f = adh_fgmres_alloc(p->n + 1, 60);
    adh_fgmres_system sys = { .apply = apply_B, .precond = apply_M, .ctx = p };
    size_t its;
    int rc = adh_fgmres_solve(f, &sys, b, 1e-10, x, &its);
    adh_fgmres_free(f);
    return rc == ADH_SUCCESS ? (int)its : -1;
}

/* The test's data: the grid's kernel W and the vectors, in one block */
typedef struct fixture {
    adh_grid *gr;
    adh_kernel *k;
    size_t n;
    double *W, *v, *d, *g, *nu, *x, *xr, *g2, *nu2;
    problem p;
} fixture;

static void fixture_alloc(fixture *f)
{
    /* rings of 1 nm to 400 nm, then x1.05 to 1.5 um */
    adh_rings_spec rs = { .dr = 1e-9, .fine = 400e-9, .ratio = 1.05, .rmax = 1.5e-6 };
    f->gr = adh_rings_alloc(&rs);
    f->k = adh_kernel_alloc(f->gr, &(adh_kernel_settings){ .type = ADH_KERNEL_RING }, NULL);
    size_t n = f->n = f->gr->n;
    f->W = malloc(n * n * sizeof *f->W), f->v = malloc(8 * (n + 1) * sizeof *f->v);
    f->d = f->v + (n + 1), f->g = f->d + (n + 1), f->nu = f->g + (n + 1), f->x = f->nu + (n + 1);
    f->xr = f->x + (n + 1), f->g2 = f->xr + (n + 1), f->nu2 = f->g2 + (n + 1);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            f->W[i * n + j] = adh_kernel_entry(f->k, i, j);
    for (size_t i = 0; i <= n; i++)
        f->v[i] = cos(0.05 * (double)i) + 0.3 * sin(1.7 * (double)i);
    f->p = (problem){ .n = n, .W = f->W, .alpha = -1.0, .theta = 0.7, .nh = 0.3, .d = f->d, .g = f->g, .nu = f->nu };
    for (size_t i = 0; i < n; i++) {
        f->g[i] = 0.01 * exp(-f->gr->r[i] / 300e-9);
        f->nu[i] = 0.05 * cos(0.01 * (double)i);
        f->g2[i] = 0.02 * exp(-f->gr->r[i] / 100e-9);
        f->nu2[i] = -0.03;
    }
}

static void fixture_free(fixture *f)
{
    free(f->W), free(f->v);
    adh_kernel_free(f->k);
    adh_grid_free(f->gr);
}

/* -alpha d W ~ 4 per ring over a contact of 250 nm, the edge's bump
 * `scale` (40: one eigenvalue changes sign) */
static void contact_shape(fixture *f, double scale)
{
    for (size_t i = 0; i < f->n; i++) {
        double r = f->gr->r[i] * 1e9;
        f->d[i] = -(r < 250 ? 4.0 / 1e-9 : 0);
        f->d[i] += scale / 1e-9 * (r > 250 && r < 251);
        f->d[i] -= 4.0 / 1e-9 / pow(1 + fmax(0, r - 250.0), 4) * (r >= 250);
    }
}

/* untruncated, through a sign change of det B: against LAPACK */
static void check_untruncated(fixture *f, int t, const char *name)
{
    size_t n = f->n;
    problem *p = &f->p;
    for (int sgn = 0; sgn < 2; sgn++) {
        double scale = sgn ? 40.0 : 1.0;
        contact_shape(f, scale);
        memcpy(f->xr, f->v, (n + 1) * sizeof *f->xr);
        int ds = lapack_solve(p, f->xr);
        int rc = set(p, 0.0);
        ok(rc == ADH_SUCCESS && adh_precond_det_sign(p->P) == ds, "%s, edge bump %g: det B's sign %+d, LAPACK's %+d",
           name, scale, adh_precond_det_sign(p->P), ds);
        ok(adh_precond_active(p->P) == n, "%s: active_tol 0 takes every node", name);
        adh_precond_apply(p->P, f->v, f->x);
        double e = tap_maxrel(f->x, f->xr, n + 1);
        ok(t == 0 ? e < 1e-10 : e < 1e-3, "%s: M^-1 v within %g of LAPACK's B^-1 v (%.1e)", name,
           t == 0 ? 1e-10 : 1e-3, e);
        int its = krylov(p, f->v, f->x);
        ok(its > 0 && its <= (t == 0 ? 2 : 6) && tap_maxrel(f->x, f->xr, n + 1) < 1e-8,
           "%s: FGMRES with it converges in %d iterations to LAPACK's solution (%.1e)", name, its,
           tap_maxrel(f->x, f->xr, n + 1));
    }
}

/* another border on the same Jacobian: the HODLR one eliminates it
 * exactly, the dense one leaves it to the Krylov iterations */
static void check_border(fixture *f, int t, const char *name)
{
    size_t n = f->n;
    ok(adh_precond_border(f->p.P, f->g2, f->nu2, -0.2) == ADH_SUCCESS, "%s: another border", name);
    problem p2 = f->p;
    p2.g = f->g2, p2.nu = f->nu2, p2.nh = -0.2;
    memcpy(f->xr, f->v, (n + 1) * sizeof *f->xr);
    lapack_solve(&p2, f->xr);
    int its = krylov(&p2, f->v, f->x);
    ok(its > 0 && its <= (t == 0 ? 10 : 6) && tap_maxrel(f->x, f->xr, n + 1) < 1e-8,
       "%s: with another border FGMRES converges in %d iterations (%.1e)", name, its,
       tap_maxrel(f->x, f->xr, n + 1));
}

/* truncated (dense only): the prefix up to the last node whose column
 * (times |alpha d_j|) sums past active_tol */
static void check_truncated(fixture *f)
{
    size_t n = f->n, m = 0;
    problem *p = &f->p;
    for (size_t j = 0; j < n; j++) {
        double cs = 0;
        for (size_t i = 0; i < n; i++)
            cs += fabs(f->W[i * n + j]);
        if (fabs(p->alpha * f->d[j]) * cs > 0.3)
            m = j + 1;
    }
    int rc = set(p, 0.3);
    ok(rc == ADH_SUCCESS && adh_precond_active(p->P) == m && m < n,
       "dense, active_tol 0.3: the first %zu of %zu nodes (%zu named by the rule)", adh_precond_active(p->P), n, m);
    memcpy(f->xr, f->v, (n + 1) * sizeof *f->xr);
    lapack_solve(p, f->xr);
    int its = krylov(p, f->v, f->x);
    ok(its > 0 && its <= 20 && tap_maxrel(f->x, f->xr, n + 1) < 1e-8,
       "dense, truncated: FGMRES converges in %d iterations (%.1e)", its, tap_maxrel(f->x, f->xr, n + 1));
}

static void check_type(fixture *f, int t, const adh_precond_type *type)
{
    size_t n = f->n;
    f->p.P = adh_precond_alloc(type, n, entry, f->k);
    const char *name = type->name;
    ok(f->p.P != NULL && adh_precond_type_of(f->p.P) == type, "%s: assembled (N = %zu, %.2f MB)", name, n,
       f->p.P ? adh_precond_bytes(f->p.P) / 1048576.0 : 0);
    check_untruncated(f, t, name);
    check_border(f, t, name);
    if (t == 0)
        check_truncated(f);
    /* J = I and a zero border: B singular, its last pivot exactly 0 */
    problem z = f->p;
    memset(f->x, 0, (n + 1) * sizeof *f->x);
    z.d = z.g = z.nu = f->x, z.nh = 0;
    ok(set(&z, 0.0) == ADH_ESING, "%s: a singular B is ADH_ESING", name);
    adh_precond_free(f->p.P);
}

/* W's entries held already (as the viscoelastic path's preconditioner
 * holds them when its jump is landed by the static solver): borrowed, n^2
 * numbers fewer, and the same factorization and solve to the bit */
static void check_shared(fixture *f)
{
    size_t n = f->n;
    adh_precond *pd = adh_precond_alloc(adh_precond_dense, n, entry, f->k);
    adh_precond *ph = adh_precond_alloc(adh_precond_hodlr, n, entry, f->k);
    adh_precond *pb = adh_precond_alloc_shared(adh_precond_dense, n, entry, f->k, f->W);
    problem pc = f->p, pw = f->p;
    pc.P = pd, pw.P = pb;
    int rcc = set(&pc, 0.3), rcw = set(&pw, 0.3);
    adh_precond_apply(pd, f->v, f->x);
    adh_precond_apply(pb, f->v, f->xr);
    ok(rcc == ADH_SUCCESS && rcw == ADH_SUCCESS && adh_precond_active(pb) == adh_precond_active(pd) &&
           adh_precond_det_sign(pb) == adh_precond_det_sign(pd) && memcmp(f->x, f->xr, (n + 1) * sizeof *f->x) == 0,
       "dense on W's entries borrowed: the same prefix (%zu), det sign and M^-1 v to the bit as on its copy",
       adh_precond_active(pb));
    ok(adh_precond_bytes(pd) - adh_precond_bytes(pb) == n * n * sizeof(double),
       "... holding n^2 numbers fewer (%.2f MB against %.2f MB)", adh_precond_bytes(pb) / 1048576.0,
       adh_precond_bytes(pd) / 1048576.0);
    adh_precond_free(pb);
    ok(adh_precond_bytes(pd) >= n * n * sizeof(double) && adh_precond_bytes(ph) < adh_precond_bytes(pd),
       "dense holds W (%.2f MB), HODLR less (%.2f MB)", adh_precond_bytes(pd) / 1048576.0,
       adh_precond_bytes(ph) / 1048576.0);
    ok(adh_precond_dense->truncates && !adh_precond_hodlr->truncates, "the dense one truncates, HODLR not");
    adh_precond_free(pd);
    adh_precond_free(ph);
    adh_precond_free(NULL);
}

int main(void)
{
    fixture f;
    fixture_alloc(&f);
    check_type(&f, 0, adh_precond_dense);
    check_type(&f, 1, adh_precond_hodlr);
    check_shared(&f);
    fixture_free(&f);
    return tap_done();
}
