#include "adhere/static.h"
#include "adhere/clock.h"

#include <gsl/gsl_cblas.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/hodlr.h"
#include "adhere/law.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/status.h"

/* Notation. x = (u, h0); the metric is |x|^2 = (theta sum u_n^2 + h0^2) / z0^2
 * (theta = u_weight), so tangents and arclength s are dimensionless / in z0.
 * S = {0 .. m-1} is the active prefix: nodes where p'(h) matters. With
 * U = (2/E) W[:,S] diag(p'_S), the truncated Jacobian is J = I - U E_S^T, and
 * the bordered Newton system
 *     J du + g dh0 = -G,   theta n_u.du + n_h dh0 = rhs      (g = dG/dh0)
 * reduces exactly (unit pivots eliminated) to (m+1) unknowns z = du_S, dh0:
 *     (I - U_S) z + g_S dh0                         = -G_S
 *     theta (U^T n_u).z + (n_h - theta n_u.g) dh0   = rhs + theta n_u.G
 * after which du = -G - g dh0 + U z. Its determinant is that of the full
 * bordered matrix, and by Cramer det J = det B * t_h / rhs for the tangent
 * solve (G = 0): so det J's sign costs nothing beyond the tangent. */

/* LAPACK's LU (OpenBLAS's, as the program is linked; the Makefile's
 * check-fp links Netlib's instead): blocked and tuned, several times faster
 * than gsl_linalg_LU_decomp at these sizes, which is the cost that
 * dominates at large sigma. */
extern void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);

#define ADH_GMRES_MAX 40   /* Krylov dimension before the LU is refreshed */
#ifndef ADH_Q_GROW /* lattice_skip: Newton iterations below which the step grows */
#define ADH_Q_GROW 4
#endif
#ifndef ADH_TAN_RTOL /* GMRES relative residual for tangents */
#define ADH_TAN_RTOL 1e-8
#endif
#ifndef ADH_NEWTON_RTOL /* and for Newton steps (inexact Newton) */
#define ADH_NEWTON_RTOL 1e-4
#endif
#ifndef ADH_GMRES_FRESH /* more iterations than this: refactorize for next time */
#define ADH_GMRES_FRESH 6
#endif
#ifndef ADH_FRONT_GROW /* front mode: Newton iterations up to which the step grows */
#define ADH_FRONT_GROW 3
#endif
#ifndef ADH_FRONT_MAX /* front mode: the longest step, in rings */
#define ADH_FRONT_MAX 64
#endif
#define ADH_FRONT_GAP 1.5 /* z0: the front node's gap is above this */
#define ADH_FRONT_MIN 8   /* rings in contact before front mode starts */
#define ADH_FRONT_REL 10
#ifndef ADH_FRONT_REFRESH /* front steps of this many rings refactorize first */
#define ADH_FRONT_REFRESH 2
#endif
#ifndef ADH_FRONT_WINDOW
#define ADH_FRONT_WINDOW 6 /* rings each side of an extremum stepped in Q */
#endif
#ifndef ADH_HODLR_TOL /* the HODLR preconditioner's blocks (relative, ACA) */
#define ADH_HODLR_TOL 1e-4
#endif
#ifndef ADH_HODLR_LEAF
#define ADH_HODLR_LEAF 64
#endif

static double hodlr_entry(void *ctx, size_t i, size_t j)
{
    return adh_kernel_entry(ctx, i, j);
}

typedef struct lin {
    double *B;       /* LU of the (m+1)^2 bordered matrix */
    int *perm;       /* LAPACK pivots, 1-based */
    int det_sign;    /* sign of det B */
    size_t m;        /* active prefix */
    double *D;       /* p'(h) at the linearization point, all N nodes */
    double *g;       /* dG/dh0 = (2/E) W p', all N nodes */
    double *nu;      /* constraint normal, u part (metric-unit vector with nh) */
    double nh;
    double *Jg;      /* HODLR path: J^-1 g at the linearization point */
    size_t stamp;    /* the step attempt it was factorized in */
    int tangent_border; /* bordered by the current tangent: its det sign is
                           comparable with det_b_sign */
} lin;

struct adh_static {
    const adh_grid *grid;
    const adh_kernel *k;
    size_t n;
    int fast;         /* the kernel's product beats a dense one (any
                         hierarchical storage) */
    int skip;         /* lattice_skip in effect (the setting, or auto's choice) */
    double *W;        /* dense W, row-major N x N (out = W p); NULL with hw */
    adh_hodlr *hw;    /* W as a HODLR matrix, when the kernel is
                         hierarchical: the preconditioner is then the whole
                         Jacobian, factorized in O(N log^2 N) */
    const double *pnu; /* HODLR path, during a solve: the operator's border */
    double pnh, pschur; /* ... and the Schur complement nh - theta nu.x2 */
    double *x2;       /* ... J_L^-1 g of the operator being solved */
    double *colnorm;  /* sum_n |W_nj| */
    double *shape;    /* r^2 / 2R */
    adh_material m;
    adh_static_settings s;
    double c2E;       /* 2/E */

    adh_state *st;    /* the current accepted point */
    adh_state *trial; /* the point being corrected */
    double *tau_u, tau_h;          /* unit tangent at st */
    double *tau_u_new, tau_h_new;  /* tangent at trial */
    lin P;            /* the preconditioner: LU of the truncated bordered
                         system at some recent point, refreshed when GMRES
                         needs more than ADH_GMRES_FRESH iterations with it */
    double *Dst, *gst, *Dtr, *gtr; /* p'(h) and dG/dh0 at st and at trial */
    int det_sign;     /* sign of det J at st */
    int det_b_sign;   /* sign of det B, invariant along the curve */
    size_t attempt;   /* step attempts so far (stamps the factorizations) */

    double *G, *du, *y, *t, *t2, *upred, *scratch, *rG, *bG, *Dc, *gc, *zero, *V, *Z;
    double act;       /* active-set threshold in use (lowered when the
                         preconditioned solve stops contracting) */
    double ds;
    double s_arc;
    int stable;
    double F, dFds;   /* force and its arclength derivative at st */
    double hist_s[3], hist_h0[3], hist_F[3]; /* the last three points (lattice_skip) */
    double q, dq, qslope; /* lattice_skip: Q at st, the step in Q, dQ/ds along tau */
    double *u1, *u2, q1, q2, h1, h2; /* the two points before st, for a quadratic predictor */
    size_t nhist;     /* how many of them there are */
    /* lattice_skip, once the contact has formed: steps of whole rings of
     * the contact line (front mode). Each point holds the gap fH at a fine
     * ring fe[0] (the contact line at the same place in its ring, so the
     * lattice's phase is the same at every point); the predictor moves the
     * last points' gap profiles out by the step, a travelling front. */
    int front;
    size_t fe[3];     /* front node of st and of the two points before */
    size_t fn;        /* consecutive front points (up to 3 used) */
    size_t fk;        /* the step, in rings */
    size_t fend;      /* the front node of the landing on h0_end */
    int fhold;        /* the step was set to approach an extremum: keep it */
    size_t fwin;      /* nonzero: steps in Q until the front passes this
                         node (an extremum's neighbourhood, every phase of
                         the lattice seen) */
    size_t nf;        /* nodes of the uniform fine band */
    double fH;        /* the gap held at the front node, m */
    int front_ok;     /* front mode allowed (it falls back to Q for good
                         when a one-ring step fails) */
    int end_next;     /* the next step lands on h0_end */
    size_t newton_point;
    double residual;
    int done;

    adh_static_fold *folds;
    size_t nfolds_kept;
    adh_static_result res;
};

adh_static_settings adh_static_settings_default(void)
{
    adh_static_settings s = {
        .tol = 1e-9,
        .ds_init = 0.1,
        .ds_min = 1e-7,
        .ds_max = 5.0,
        .u_weight = 1.0,
        .max_angle = 0.4,
        .max_gap_step = 0.25,
        .active_tol = 0.3,
        .h0_start = NAN,
        .h0_end = -5e-9,
        .max_points = 200000,
        .max_newton = 12,
        .lattice_skip = -1,
    };
    return s;
}

int adh_static_settings_validate(const adh_static_settings *s, char *why, size_t whylen)
{
#define BAD(...) do { if (why) snprintf(why, whylen, __VA_ARGS__); return ADH_EINVAL; } while (0)
    if (!(s->tol > 0 && s->tol < 1e-3))
        BAD("static tolerance %g is not allowed: it must be above 0 and below 1e-3 (units of z0)", s->tol);
    if (!(s->ds_min > 0 && s->ds_min <= s->ds_init && s->ds_init <= s->ds_max && s->ds_max < 1e3))
        BAD("arclength steps must satisfy 0 < ds_min (%g) <= ds_init (%g) <= ds_max (%g) < 1000", s->ds_min,
            s->ds_init, s->ds_max);
    if (!(s->u_weight > 0 && isfinite(s->u_weight)))
        BAD("u_weight %g is not allowed: it must be finite and above 0", s->u_weight);
    if (!(s->max_angle > 0 && s->max_angle < 1.5))
        BAD("max_angle %g rad is not allowed: it must be above 0 and below 1.5", s->max_angle);
    if (!(s->max_gap_step >= 0 && s->max_gap_step < 100))
        BAD("max_gap_step %g is not allowed: it must be from 0 (off) to 100 (units of z0)", s->max_gap_step);
    if (!(s->active_tol >= 0 && s->active_tol <= 1))
        BAD("active_tol %g is not allowed: it must be from 0 to 1", s->active_tol);
    if (!isnan(s->h0_start) && !(isfinite(s->h0_start) && s->h0_start > s->h0_end))
        BAD("static start %g m must be finite and above the end %g m", s->h0_start, s->h0_end);
    if (!isfinite(s->h0_end))
        BAD("static end position must be finite");
    if (s->lattice_skip < -1 || s->lattice_skip > 1)
        BAD("lattice_skip %d is not allowed: it must be -1 (auto), 0 or 1", s->lattice_skip);
    if (s->max_points < 2 || s->max_newton < 2)
        BAD("max_points (%zu) and max_newton (%zu) must be at least 2", s->max_points, s->max_newton);
    return ADH_SUCCESS;
#undef BAD
}

static void lin_free(lin *L)
{
    free(L->B);
    free(L->perm);
    free(L->D);
}

/* dense: room for the (n+1)^2 LU; else (HODLR) only the vectors */
static int lin_alloc(lin *L, size_t n, int dense)
{
    if (dense) {
        L->B = malloc((n + 1) * (n + 1) * sizeof *L->B);
        L->perm = malloc((n + 1) * sizeof *L->perm);
    }
    L->D = malloc(4 * n * sizeof *L->D);
    if ((dense && (!L->B || !L->perm)) || !L->D)
        return ADH_ENOMEM;
    L->g = L->D + n;
    L->nu = L->D + 2 * n;
    L->Jg = L->D + 3 * n;
    return ADH_SUCCESS;
}

void adh_static_free(adh_static *w)
{
    if (!w)
        return;
    free(w->W);
    adh_hodlr_free(w->hw);
    free(w->colnorm);
    adh_state_free(w->st);
    adh_state_free(w->trial);
    lin_free(&w->P);
    free(w->G);
    free(w->folds);
    free(w);
}

adh_static *adh_static_alloc(const adh_grid *g, const adh_kernel *k)
{
    adh_static *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    size_t n = g->n;
    w->grid = g;
    w->k = k;
    w->n = n;
    w->fast = adh_kernel_storage_of(k) != ADH_STORAGE_DENSE;
    if (w->fast)
        w->hw = adh_hodlr_alloc(n, hodlr_entry, (void *)k, ADH_HODLR_TOL, ADH_HODLR_LEAF);
    else
        w->W = malloc(n * n * sizeof *w->W);
    w->colnorm = calloc(2 * n, sizeof *w->colnorm);
    w->st = adh_state_alloc(n);
    w->trial = adh_state_alloc(n);
    /* G, du, y, t, t2, upred, scratch, tau_u, tau_u_new, rG, bG, Dc, gc,
     * zero, Dst, gst, Dtr, gtr, u1, u2, x2: n + 1 each; the GMRES basis
     * and its preconditioned vectors */
    w->G = calloc(21 * (n + 1) + (2 * ADH_GMRES_MAX + 1) * (n + 1), sizeof *w->G);
    w->folds = malloc(ADH_STATIC_MAX_FOLDS * sizeof *w->folds);
    int bad = !(w->W || w->hw) || !w->colnorm || !w->st || !w->trial || !w->G || !w->folds;
    if (!bad)
        bad = lin_alloc(&w->P, n, !w->fast) != ADH_SUCCESS;
    if (bad) {
        adh_static_free(w);
        return NULL;
    }
    w->shape = w->colnorm + n;
    double **bufs[] = { &w->G, &w->du, &w->y, &w->t, &w->t2, &w->upred, &w->scratch, &w->tau_u,
                        &w->tau_u_new, &w->rG, &w->bG, &w->Dc, &w->gc, &w->zero,
                        &w->Dst, &w->gst, &w->Dtr, &w->gtr, &w->u1, &w->u2, &w->x2 };
    for (size_t i = 1; i < sizeof bufs / sizeof *bufs; i++)
        *bufs[i] = w->G + i * (n + 1);
    w->V = w->G + 21 * (n + 1);
    w->Z = w->V + (ADH_GMRES_MAX + 1) * (n + 1);
    for (size_t i = 0; i < n && w->W; i++)
        for (size_t j = 0; j < n; j++) {
            double v = adh_kernel_entry(k, i, j);
            w->W[i * n + j] = v;
            w->colnorm[j] += fabs(v);
        }
    return w;
}

/* h and p from u and h0; G = u + (2/E) W p into w->G. Returns max |G| (m),
 * or -1 when a gap closed or a value stopped being finite. */
static double evaluate(adh_static *w, adh_state *x)
{
    size_t n = w->n;
    for (size_t i = 0; i < n; i++) {
        x->h[i] = x->h0 + w->shape[i] - x->u[i];
        if (!(x->h[i] > 0))
            return -1;
        x->p[i] = adh_lj_pressure(x->h[i], w->m.A, w->m.z0);
    }
    adh_kernel_apply(w->k, x->p, w->G, w->scratch);
    double r = 0;
    for (size_t i = 0; i < n; i++) {
        w->G[i] = x->u[i] + w->c2E * w->G[i];
        r = fmax(r, fabs(w->G[i]));
    }
    return isfinite(r) ? r : -1;
}

/* Linearizes at x (h must be current) with constraint normal (nu, nh), and
 * factorizes the reduced bordered matrix. */
static int linearize(adh_static *w, const adh_state *x, const double *nu, double nh, lin *L)
{
    size_t n = w->n, m = 0;
    double c2E = w->c2E, th = w->s.u_weight;
    for (size_t j = 0; j < n; j++) {
        L->D[j] = adh_lj_dpressure(x->h[j], w->m.A, w->m.z0);
        if (w->W && c2E * fabs(L->D[j]) * w->colnorm[j] > w->act)
            m = j + 1;
    }
    adh_kernel_apply(w->k, L->D, L->g, w->scratch);
    double ng = 0;
    for (size_t i = 0; i < n; i++) {
        L->g[i] *= c2E;
        L->nu[i] = nu[i];
        ng += nu[i] * L->g[i];
    }
    L->nh = nh;
    L->m = m;
    L->stamp = w->attempt;
    L->tangent_border = nu == w->tau_u && nh == w->tau_h;
    if (w->hw) {
        /* The whole J = I - (2/E) W diag(D), no truncation; the border by
         * block elimination: det B = det J (nh - theta nu.J^-1 g). */
        int rc = adh_hodlr_factorize(w->hw, -c2E, L->D);
        if (rc < 0)
            return ADH_ENOMEM;
        if (rc > 0)
            return ADH_ESTALL; /* exactly singular: not a simple fold */
        memcpy(L->Jg, L->g, n * sizeof *L->Jg);
        adh_hodlr_solve(w->hw, L->Jg);
        double sc = nh;
        for (size_t i = 0; i < n; i++)
            sc -= th * nu[i] * L->Jg[i];
        if (sc == 0 || !isfinite(sc))
            return ADH_ESTALL;
        L->m = n;
        L->det_sign = adh_hodlr_det_sign(w->hw) * (sc < 0 ? -1 : 1);
        return ADH_SUCCESS;
    }
    size_t ld = m + 1;
    double *B = L->B, *q = w->scratch;
    if (m > 0)
        cblas_dgemv(CblasRowMajor, CblasTrans, (int)n, (int)m, c2E, w->W, (int)n, nu, 1, 0.0, q, 1);
    for (size_t i = 0; i < m; i++) {
        const double *row = w->W + i * n;
        double *Bi = B + i * ld;
        for (size_t j = 0; j < m; j++)
            Bi[j] = -c2E * row[j] * L->D[j];
        Bi[i] += 1.0;
        Bi[m] = L->g[i];
    }
    for (size_t j = 0; j < m; j++)
        B[m * ld + j] = th * q[j] * L->D[j];
    B[m * ld + m] = nh - th * ng;
    /* The row-major B is, to LAPACK, the column-major B^T = P L U: the
     * same determinant, and B x = b is solved as U^T L^T P^T x = b. */
    int nn = (int)ld, info = 0;
    dgetrf_(&nn, &nn, B, &nn, L->perm, &info);
    if (info < 0)
        return ADH_EINVAL;
    int sg = 1;
    for (size_t i = 0; i < ld; i++) {
        if (L->perm[i] != (int)i + 1)
            sg = -sg;
        double d = B[i * ld + i];
        if (d == 0 || !isfinite(d))
            return ADH_ESTALL; /* exactly singular: not a simple fold */
        if (d < 0)
            sg = -sg;
    }
    L->det_sign = sg;
    return ADH_SUCCESS;
}

/* P^-1: solves the truncated bordered system of L,
 *     P [du; dh0] = [bG; bc],   P = [[I - U E_S^T, g], [theta nu^T, nh]],
 * through its (m+1)^2 LU (metres in, metres out). */
static void precond(adh_static *w, const lin *L, const double *bG, double bc, double *du, double *dh0)
{
    size_t n = w->n, m = L->m, ld = m + 1;
    double th = w->s.u_weight;
    if (w->hw) {
        /* J_L^-1 on the u part, the current operator's border eliminated
         * exactly (x2 and the Schur complement set up by solve) */
        memcpy(du, bG, n * sizeof *du);
        adh_hodlr_solve_single(w->hw, du);
        double nd = 0;
        for (size_t i = 0; i < n; i++)
            nd += w->pnu[i] * du[i];
        double dh = (bc - th * nd) / w->pschur;
        for (size_t i = 0; i < n; i++)
            du[i] -= w->x2[i] * dh;
        *dh0 = dh;
        return;
    }
    double *y = w->y;
    double nb = 0;
    for (size_t i = 0; i < n; i++)
        nb += L->nu[i] * bG[i];
    for (size_t i = 0; i < m; i++)
        y[i] = bG[i];
    y[m] = bc - th * nb;
    cblas_dtrsv(CblasColMajor, CblasUpper, CblasTrans, CblasNonUnit, (int)ld, L->B, (int)ld, y, 1);
    cblas_dtrsv(CblasColMajor, CblasLower, CblasTrans, CblasUnit, (int)ld, L->B, (int)ld, y, 1);
    for (size_t i = ld; i-- > 0;) {
        size_t p = (size_t)L->perm[i] - 1;
        double tmp = y[i];
        y[i] = y[p];
        y[p] = tmp;
    }
    double dh = y[m];
    for (size_t j = 0; j < m; j++)
        w->t[j] = L->D[j] * y[j];
    if (m > 0)
        cblas_dgemv(CblasRowMajor, CblasNoTrans, (int)n, (int)m, w->c2E, w->W, (int)n, w->t, 1, 0.0, du, 1);
    else
        memset(du, 0, n * sizeof *du);
    for (size_t i = 0; i < n; i++)
        du[i] += bG[i] - L->g[i] * dh;
    *dh0 = dh;
}

/* The whole bordered operator at one point: J = I - (2/E) W diag(D). */
typedef struct op {
    const double *D, *g, *nu;
    double nh;
} op;

static void op_apply(adh_static *w, const op *A, const double *du, double dh, double *oG, double *oc)
{
    size_t n = w->n;
    double nd = 0;
    for (size_t i = 0; i < n; i++)
        w->t2[i] = A->D[i] * du[i];
    adh_kernel_apply(w->k, w->t2, oG, w->scratch);
    for (size_t i = 0; i < n; i++) {
        oG[i] = du[i] - w->c2E * oG[i] + A->g[i] * dh;
        nd += A->nu[i] * du[i];
    }
    *oc = w->s.u_weight * nd + A->nh * dh;
}

/* A [du; dh] = [bG; bc] by GMRES, right-preconditioned with the LU of L
 * (the truncated system, possibly factorized at a nearby point): each
 * iteration costs one product with W and one triangular solve, against m^3
 * for a new LU. The unknowns and right side are packed as n + 1 numbers
 * (du, dh0). ADH_CONTINUE when ADH_GMRES_MAX iterations do not reach rtol:
 * L is then too far from A. */
static int solve(adh_static *w, const op *A, const lin *L, const double *b, double rtol, double *x, int *its)
{
    size_t n = w->n, n1 = n + 1;
    const int km = ADH_GMRES_MAX;
    double *V = w->V;
    double H[(ADH_GMRES_MAX + 1) * ADH_GMRES_MAX], cs[ADH_GMRES_MAX], sn[ADH_GMRES_MAX];
    double gv[ADH_GMRES_MAX + 1], yv[ADH_GMRES_MAX];
    double beta = cblas_dnrm2((int)n1, b, 1);
    memset(x, 0, n1 * sizeof *x);
    *its = 0;
    if (beta == 0)
        return ADH_SUCCESS;
    if (w->hw) {
        /* the border of A, eliminated exactly around J_L^-1 */
        memcpy(w->x2, A->g, n * sizeof *w->x2);
        adh_hodlr_solve_single(w->hw, w->x2);
        double sc = A->nh;
        for (size_t i = 0; i < n; i++)
            sc -= w->s.u_weight * A->nu[i] * w->x2[i];
        if (sc == 0 || !isfinite(sc))
            return ADH_CONTINUE;
        w->pnu = A->nu, w->pnh = A->nh, w->pschur = sc;
    }
    for (size_t i = 0; i < n1; i++)
        V[i] = b[i] / beta;
    gv[0] = beta;
    int k = 0;
    double resid = beta;
    for (int j = 0; j < km; j++) {
        double *vj = V + (size_t)j * n1, *vn = V + (size_t)(j + 1) * n1, *zj = w->Z + (size_t)j * n1;
        precond(w, L, vj, vj[n], zj, &zj[n]);
        op_apply(w, A, zj, zj[n], vn, &vn[n]);
        /* modified Gram-Schmidt, twice: the Krylov basis must stay orthogonal */
        for (int pass = 0; pass < 2; pass++)
            for (int i = 0; i <= j; i++) {
                double hij = cblas_ddot((int)n1, V + (size_t)i * n1, 1, vn, 1);
                cblas_daxpy((int)n1, -hij, V + (size_t)i * n1, 1, vn, 1);
                H[i * km + j] = pass ? H[i * km + j] + hij : hij;
            }
        double hn = cblas_dnrm2((int)n1, vn, 1);
        if (!isfinite(hn))
            return ADH_CONTINUE;
        H[(j + 1) * km + j] = hn;
        if (hn > 0)
            cblas_dscal((int)n1, 1.0 / hn, vn, 1);
        for (int i = 0; i < j; i++) {
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
        resid = fabs(gv[j + 1]);
        k = j + 1;
        *its = k;
        w->res.krylov_iterations++;
        if (resid <= rtol * beta || hn == 0)
            break;
    }
    for (int i = k - 1; i >= 0; i--) {
        double sum = gv[i];
        for (int l = i + 1; l < k; l++)
            sum -= H[i * km + l] * yv[l];
        if (H[i * km + i] == 0)
            return ADH_CONTINUE;
        yv[i] = sum / H[i * km + i];
    }
    /* x from the preconditioned vectors kept (flexible GMRES): no solve
     * more, and the answer is the combination the residual was measured on */
    for (int i = 0; i < k; i++)
        cblas_daxpy((int)n1, yv[i], w->Z + (size_t)i * n1, 1, x, 1);
    for (size_t i = 0; i < n1; i++)
        if (!isfinite(x[i]))
            return ADH_CONTINUE;
    return resid <= rtol * beta ? ADH_SUCCESS : ADH_CONTINUE;
}

/* p'(h) and g = dG/dh0 = (2/E) W p' at x (h current). */
static void point_jacobian(adh_static *w, const adh_state *x, double *D, double *g)
{
    for (size_t i = 0; i < w->n; i++)
        D[i] = adh_lj_dpressure(x->h[i], w->m.A, w->m.z0);
    adh_kernel_apply(w->k, D, g, w->scratch);
    for (size_t i = 0; i < w->n; i++)
        g[i] *= w->c2E;
}

/* A out = b by GMRES with the preconditioner P; when P has grown stale
 * (slow or failed), it is refactorized at x, with more nodes in if even
 * that fails (the truncation was too coarse). */
static int solve_at(adh_static *w, const op *A, const adh_state *x, const double *b, double rtol, double *out)
{
    int its;
    int rc = solve(w, A, &w->P, b, rtol, out, &its);
    if (rc == ADH_SUCCESS && its <= ADH_GMRES_FRESH)
        return ADH_SUCCESS;
    for (int tries = 0; tries < 3; tries++) {
        int lrc = linearize(w, x, A->nu, A->nh, &w->P);
        w->res.factorizations++;
        if (lrc != ADH_SUCCESS)
            return lrc;
        if (rc == ADH_SUCCESS)
            return ADH_SUCCESS; /* solved, slowly: the new P is for next time */
        rc = solve(w, A, &w->P, b, rtol, out, &its);
        if (rc == ADH_SUCCESS)
            return ADH_SUCCESS;
        if (w->hw)
            break; /* the whole Jacobian was in: nothing more to take in */
        w->act *= 0.1;
    }
    return ADH_EMAXITER;
}

/* Unit tangent at x (D, g there), oriented to continue the current tangent
 * (the bordering row is the current tangent, right side 1). */
static int tangent(adh_static *w, const adh_state *x, const double *D, const double *g, double *tu, double *th_out)
{
    /* P must be factorized at x with the current tangent as its last row:
     * then det J = det B * t_h (Cramer) and GMRES converges at once. */
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight;
    op A = { D, g, w->tau_u, w->tau_h };
    w->zero[n] = z0;
    int rc = solve_at(w, &A, x, w->zero, ADH_TAN_RTOL, w->du);
    w->zero[n] = 0;
    if (rc != ADH_SUCCESS)
        return rc;
    double dh = w->du[n], nrm = dh * dh;
    for (size_t i = 0; i < n; i++)
        nrm += th * w->du[i] * w->du[i];
    nrm = sqrt(nrm); /* in metres: the tangent is (du, dh0) / nrm, dimensionless */
    for (size_t i = 0; i < n; i++)
        tu[i] = w->du[i] / nrm;
    *th_out = dh / nrm;
    return ADH_SUCCESS;
}

static double metric_dot(const adh_static *w, const double *au, double ah, const double *bu, double bh)
{
    double d = 0;
    for (size_t i = 0; i < w->n; i++)
        d += au[i] * bu[i];
    return w->s.u_weight * d + ah * bh;
}

/* The contact measure that parametrizes the curve with lattice_skip:
 * Q = sum_i a_i (z0/h_i)^6 (a_i the ring areas / 2 pi), about the area
 * within the interaction zone. It grows monotonically along the whole
 * curve (the gaps near the axis close on the outer branch, the contact
 * widens after), through every fold in h0, physical or lattice, so a step
 * in Q never has to turn. Its gradient goes into qu (per u_n, divided by
 * theta as the border row expects) and *qh (per h0), both scaled by
 * *scale so that the row has unit metric norm; returns Q. */
static double qmeasure(adh_static *w, const adh_state *x, double *qu, double *qh, double *scale)
{
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight, q = 0, gh = 0, nrm = 0;
    for (size_t i = 0; i < n; i++) {
        double a = adh_rings_weight(w->grid, i), r = z0 / x->h[i], r3 = r * r * r, f = a * r3 * r3;
        q += f;
        double d = -6.0 * f / x->h[i]; /* dQ/dh_i */
        if (qu)
            qu[i] = -d; /* h_i = h0 + r^2/2R - u_i */
        gh += d;
        nrm += d * d / th;
    }
    if (qu) {
        nrm = sqrt(nrm + gh * gh);
        for (size_t i = 0; i < n; i++)
            qu[i] /= th * nrm;
        *qh = gh / nrm;
        *scale = nrm;
    }
    return q;
}

/* The unit secant from st to trial, in the metric (dimensionless). */
static void secant(adh_static *w, double *su, double *sh)
{
    size_t n = w->n;
    double z0 = w->m.z0, dh = (w->trial->h0 - w->st->h0) / z0, s2 = dh * dh;
    for (size_t i = 0; i < n; i++) {
        su[i] = (w->trial->u[i] - w->st->u[i]) / z0;
        s2 += w->s.u_weight * su[i] * su[i];
    }
    double len = sqrt(s2);
    for (size_t i = 0; i < n; i++)
        su[i] /= len;
    *sh = dh / len;
}

/* Newton corrector from the predictor st + ds tau on the hyperplane through
 * it normal to tau (Keller's pseudo-arclength), or on h0 = h0_fix when fix
 * is set. Each Newton step uses the exact Jacobian at the iterate, solved
 * by GMRES with the LU preconditioner. The converged point is left in trial. */
/* Front mode's predictor for the front at node tgt: the gap profiles of
 * the last front points (Lagrange in the front radius), each moved out by
 * its distance to tgt within the fine band (whole rings: exact shifts, the
 * axis's flat gap repeated), u extrapolated in place beyond it. */
static void front_predict(adh_static *w, size_t tgt, adh_state *x)
{
    size_t n = w->n, np = w->fn < 3 ? w->fn : 3;
    const double *r = w->grid->r;
    const double *us[3] = { w->st->u, w->u1, w->u2 };
    double h0s[3] = { w->st->h0, w->h1, w->h2 }, L[3];
    double a = r[tgt];
    for (size_t j = 0; j < np; j++) {
        L[j] = 1;
        for (size_t l = 0; l < np; l++)
            if (l != j)
                L[j] *= (a - r[w->fe[l]]) / (r[w->fe[j]] - r[w->fe[l]]);
    }
    x->h0 = 0;
    for (size_t j = 0; j < np; j++)
        x->h0 += L[j] * h0s[j];
    for (size_t i = 0; i < n; i++) {
        double v = 0;
        if (i < w->nf) {
            for (size_t j = 0; j < np; j++) {
                size_t sh = tgt - w->fe[j], m = i > sh ? i - sh : 0;
                v += L[j] * (h0s[j] + w->shape[m] - us[j][m]);
            }
            x->u[i] = x->h0 + w->shape[i] - v;
        } else {
            for (size_t j = 0; j < np; j++)
                v += L[j] * us[j][i];
            x->u[i] = v;
        }
    }
}

static int correct(adh_static *w, double ds, int fix, double h0_fix, double qtarget, size_t *iters)
{
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight;
    adh_state *x = w->trial;
    for (size_t i = 0; i < n; i++)
        x->u[i] = w->st->u[i] + ds * z0 * w->tau_u[i];
    x->h0 = fix ? h0_fix : w->st->h0 + ds * z0 * w->tau_h;
    memcpy(w->upred, x->u, n * sizeof *x->u);
    double h0pred = x->h0;
    const double *nu = fix ? w->zero : w->tau_u;
    double nh = fix ? 1.0 : w->tau_h;
    int qmode = !fix && !isnan(qtarget) && !w->front;
    int fmode = !fix && w->front;
    size_t tgt = w->fe[0] + w->fk;
    double qscale = 1;
    if (fix && w->front) {
        /* the landing on h0_fix: the front moved to where h0 gets there */
        front_predict(w, w->fend, x);
        x->h0 = h0_fix;
    }
    if (fmode) {
        front_predict(w, tgt, x);
        memset(w->rG, 0, n * sizeof *w->rG);
        w->rG[tgt] = -1.0 / th; /* the row of h_tgt = h0 + r^2/2R - u_tgt */
        nu = w->rG;
        nh = 1.0;
    }
    if (qmode && w->nhist >= 2) {
        /* Q's parabola through the last three points: the curve bends
         * smoothly over many rings, and a better start saves Newton steps */
        double q0 = w->q, q1 = w->q1, q2 = w->q2, dq = qtarget - q0;
        double a = dq / (q0 - q1), b = dq * (qtarget - q1) / (q0 - q2);
        for (size_t i = 0; i < n; i++) {
            double f01 = (w->st->u[i] - w->u1[i]) / (q0 - q1), f12 = (w->u1[i] - w->u2[i]) / (q1 - q2);
            x->u[i] = w->st->u[i] + a * (w->st->u[i] - w->u1[i]) + b * (f01 - f12);
        }
        double f01 = (w->st->h0 - w->h1) / (q0 - q1), f12 = (w->h1 - w->h2) / (q1 - q2);
        x->h0 = w->st->h0 + a * (w->st->h0 - w->h1) + b * (f01 - f12);
    }
    if (qmode)
        nu = w->rG;
    double prev = INFINITY;
    for (size_t it = 0;; it++) {
        double r = evaluate(w, x);
        if (r < 0)
            return ADH_ENAN;
        double cq = 0;
        if (qmode) /* the constraint is nonlinear: it must hold too */
            cq = (qmeasure(w, x, w->rG, &nh, &qscale) - qtarget) / qscale;
        if (fmode)
            cq = x->h[tgt] - w->fH;
        if (r < w->s.tol * z0 && fabs(cq) < w->s.tol * z0) {
            w->residual = r;
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
        point_jacobian(w, x, w->Dc, w->gc);
        /* the constraint's current residual, metres */
        double c;
        if (qmode || fmode) {
            c = cq;
        } else {
            double cu = 0;
            for (size_t i = 0; i < n; i++)
                cu += nu[i] * (x->u[i] - w->upred[i]);
            c = nh * (x->h0 - h0pred) + th * cu;
        }
        for (size_t i = 0; i < n; i++)
            w->bG[i] = -w->G[i];
        w->bG[n] = -c;
        op A = { w->Dc, w->gc, nu, nh };
        if (fmode && w->fk >= ADH_FRONT_REFRESH && it == 0 && w->hw && w->P.stamp != w->attempt) {
            /* the front moved many rings since the factorization: its edge
             * is elsewhere, and a fresh one (a few GMRES iterations' cost)
             * saves ~20 */
            int lrc = linearize(w, x, nu, nh, &w->P);
            w->res.factorizations++;
            if (lrc != ADH_SUCCESS)
                return lrc;
        }
        int rc = solve_at(w, &A, x, w->bG, ADH_NEWTON_RTOL, w->du);
        if (rc != ADH_SUCCESS)
            return rc;
        double dh = w->du[n];
        (*iters)++;
        w->res.newton_iterations++;
        /* damp an update that would close a gap (the law means nothing there) */
        double lam = 1.0;
        for (int tries = 0;; tries++) {
            int closed = 0;
            for (size_t i = 0; i < n && !closed; i++)
                closed = !(x->h0 + lam * dh + w->shape[i] - x->u[i] - lam * w->du[i] > 0);
            if (!closed)
                break;
            if (tries == 6)
                return ADH_ENAN;
            lam *= 0.5;
        }
        for (size_t i = 0; i < n; i++)
            x->u[i] += lam * w->du[i];
        x->h0 += lam * dh;
    }
}

static double force_of(const adh_static *w, const adh_state *x)
{
    return adh_force(w->grid, &w->m, x);
}

/* dF/ds along the unit tangent: F = 2 pi dr sum r p, dh = dh0 - du. */
static double force_slope(const adh_static *w, const double *D, const double *tu, double th)
{
    double s = 0, z0 = w->m.z0;
    if (w->grid->graded) { /* ring areas, as adh_force */
        for (size_t i = 0; i < w->n; i++)
            s += adh_rings_weight(w->grid, i) * D[i] * z0 * (th - tu[i]);
        return 2.0 * M_PI * s;
    }
    for (size_t i = 0; i < w->n; i++)
        s += w->grid->r[i] * D[i] * z0 * (th - tu[i]);
    /* the tail beyond Rmax, 2 pi R W(h0 + Rmax^2/2R), has slope -2 pi R p there
     * per unit h0; s is in units of z0 */
    double edge = w->st->h0 + w->grid->rmax * w->grid->rmax / (2.0 * w->m.R);
    double tail = edge > 0 ? -2.0 * M_PI * w->m.R * adh_lj_pressure(edge, w->m.A, z0) : 0;
    return 2.0 * M_PI * w->grid->dr * s + tail * z0 * th;
}

/* Where the cubic Hermite interpolant on [0,1] (values y0, y1, end slopes
 * m0, m1 per unit t) has its extremum; -1 when none lies inside. */
static double hermite_extremum(double y0, double y1, double m0, double m1)
{
    double a = 6 * y0 + 3 * m0 - 6 * y1 + 3 * m1;
    double b = -6 * y0 - 4 * m0 + 6 * y1 - 2 * m1;
    double c = m0;
    double t = -1;
    if (fabs(a) < 1e-14 * (fabs(b) + fabs(c))) {
        if (b != 0)
            t = -c / b;
    } else {
        double disc = b * b - 4 * a * c;
        if (disc >= 0) {
            double sq = sqrt(disc);
            double qq = -0.5 * (b + (b >= 0 ? sq : -sq));
            double t1 = qq / a, t2 = qq != 0 ? c / qq : -1;
            t = (t1 >= 0 && t1 <= 1) ? t1 : t2;
        }
    }
    if (!(t >= 0 && t <= 1))
        t = m0 / (m0 - m1); /* the slope's linear zero */
    return (t >= 0 && t <= 1) ? t : -1;
}

static double hermite_value(double y0, double y1, double m0, double m1, double t)
{
    double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1;
}

static void fold_add(adh_static *w, const adh_static_fold *f)
{
    if (w->res.folds == 0)
        w->res.jump_in_h0 = f->kind < 0 ? f->h0 : NAN;
    if (f->kind > 0 && (isnan(w->res.jump_out_h0) || f->h0 > w->res.jump_out_h0)) {
        w->res.jump_out_h0 = f->h0;
        w->res.pulloff_F_disp = f->F;
    }
    if (w->nfolds_kept < ADH_STATIC_MAX_FOLDS)
        w->folds[w->nfolds_kept++] = *f;
    w->res.folds++;
}

/* Bookkeeping of a new accepted point against the previous one: folds
 * (the tangent's h0 part changes sign) and the force minimum. */
static void record(adh_static *w, double h0a, double tha, double Fa, double dFa, double len)
{
    double z0 = w->m.z0;
    double h0b = w->st->h0, thb = w->tau_h, Fb = w->F, dFb = w->dFds;
    if (Fb < w->res.pulloff_F) {
        w->res.pulloff_F = Fb;
        w->res.pulloff_h0 = h0b;
    }
    if (dFa < 0 && dFb > 0) {
        double t = hermite_extremum(Fa, Fb, dFa * len, dFb * len);
        if (t >= 0) {
            double Fm = hermite_value(Fa, Fb, dFa * len, dFb * len, t);
            if (Fm < w->res.pulloff_F) {
                w->res.pulloff_F = Fm;
                w->res.pulloff_h0 = hermite_value(h0a, h0b, tha * z0 * len, thb * z0 * len, t);
            }
        }
    }
    if ((tha < 0) != (thb < 0)) {
        double m0 = tha * z0 * len, m1 = thb * z0 * len;
        double t = hermite_extremum(h0a, h0b, m0, m1);
        if (t < 0)
            t = 0.5;
        adh_static_fold f = {
            .h0 = hermite_value(h0a, h0b, m0, m1, t),
            .F = hermite_value(Fa, Fb, dFa * len, dFb * len, t),
            .kind = tha < 0 ? -1 : +1,
        };
        fold_add(w, &f);
    }
}

/* The parabola through (x0,y0), (x1,y1), (x2,y2) as
 * y = y1 + b (x - x1) + c (x - x1)^2. */
static void parabola(const double *x, const double *y, double *b, double *c)
{
    double d1 = (y[1] - y[0]) / (x[1] - x[0]), d2 = (y[2] - y[1]) / (x[2] - x[1]);
    *c = (d2 - d1) / (x[2] - x[0]);
    *b = d1 + *c * (x[1] - x[0]);
}

static double parabola_at(const double *x, const double *y, double t)
{
    double b, c;
    parabola(x, y, &b, &c);
    return y[1] + b * (t - x[1]) + c * (t - x[1]) * (t - x[1]);
}

/* The parabola's extremum, clamped to [x0, x2]: its abscissa in *xm; the
 * value is returned. */
static double parabola_extremum(const double *x, const double *y, double *xm)
{
    double b, c;
    parabola(x, y, &b, &c);
    double t = c != 0 ? x[1] - b / (2 * c) : x[1];
    *xm = fmin(x[2], fmax(x[0], t));
    return parabola_at(x, y, *xm);
}

/* Bookkeeping when the curve steps over the lattice folds (lattice_skip):
 * a fold is where h0 turns between the last three points, the pull-off
 * where F does; both are placed on the parabolas through them (in the
 * arclength s). */
static void record_smooth(adh_static *w)
{
    double *s = w->hist_s, *h = w->hist_h0, *F = w->hist_F;
    s[0] = s[1], h[0] = h[1], F[0] = F[1];
    s[1] = s[2], h[1] = h[2], F[1] = F[2];
    s[2] = w->s_arc, h[2] = w->st->h0, F[2] = w->F;
    if (w->F < w->res.pulloff_F) {
        w->res.pulloff_F = w->F;
        w->res.pulloff_h0 = w->st->h0;
    }
    if (w->res.points < 3)
        return;
    double sm;
    if (F[1] <= F[0] && F[1] <= F[2]) {
        double Fm = parabola_extremum(s, F, &sm);
        if (Fm < w->res.pulloff_F) {
            w->res.pulloff_F = Fm;
            w->res.pulloff_h0 = parabola_at(s, h, sm);
        }
    }
    if ((h[1] - h[0]) * (h[2] - h[1]) < 0) {
        adh_static_fold f = { .kind = h[1] < h[0] ? -1 : +1 };
        f.h0 = parabola_extremum(s, h, &sm);
        f.F = parabola_at(s, F, sm);
        fold_add(w, &f);
    }
}

/* Enters front mode once a contact of a few rings has formed: the front
 * node is the first whose gap exceeds ADH_FRONT_GAP z0, and the gap there
 * is what every later point holds at its front node. */
static size_t front_node_of(const adh_static *w, const adh_state *x)
{
    size_t e = 0;
    while (e < w->n && x->h[e] <= ADH_FRONT_GAP * w->m.z0)
        e++;
    return e;
}

static size_t front_node(const adh_static *w)
{
    return front_node_of(w, w->st);
}

static void front_start(adh_static *w)
{
    size_t e = front_node(w);
    if (e < ADH_FRONT_MIN || e + 2 >= w->nf)
        return;
    w->front = 1;
    w->fe[0] = e;
    w->fH = w->st->h[e];
    w->fn = 1;
    w->fk = 1;
    w->fhold = 0;
}

/* At one lattice phase the jump-out (h0's maximum) and the pull-off (F's
 * minimum) would miss the lattice's own swing, up to ~1e-3 (the exact
 * curve's extremes are its highest lattice folds): when the parabola
 * through the last three front points puts either a few steps ahead, the
 * front steps shorten to land a few rings before it, and from there steps
 * in Q of about a ring (every phase) cross it. kused: the last step in
 * rings, dq: Q's change over it. */
static void front_extremum(adh_static *w, size_t kused, double dq)
{
    if (w->fn < 3)
        return;
    const double *r = w->grid->r;
    double a[3] = { r[w->fe[2]], r[w->fe[1]], r[w->fe[0]] }, hh[3] = { w->h2, w->h1, w->st->h0 };
    double dr = adh_rings_width(w->grid, 0), ahead = INFINITY;
    for (int which = 0; which < 2; which++) {
        const double *y = which ? w->hist_F : hh;
        double b, c;
        parabola(a, y, &b, &c);
        if (which ? !(c > 0) : !(c < 0))
            continue; /* F's minimum, h0's maximum */
        double v = a[1] - b / (2 * c);
        if (v > a[2])
            ahead = fmin(ahead, (v - a[2]) / dr);
    }
    if (!(ahead < 2.0 * (double)w->fk + ADH_FRONT_WINDOW))
        return;
    if (ahead > 2 * ADH_FRONT_WINDOW) {
        /* halfway to the window's start: the next parabola, from closer
         * points, places it better */
        size_t k = (size_t)((ahead - ADH_FRONT_WINDOW) / 2);
        w->fk = k > 1 ? k : 1;
        w->fhold = 1;
        return;
    }
    w->front = 0;
    w->fwin = w->fe[0] + (size_t)ceil(ahead) + ADH_FRONT_WINDOW;
    w->dq = dq / (double)kused;
}

/* Makes trial (tangent in tau_*_new, Jacobian data in Dtr, gtr, det J's
 * sign in det_sign) the current point. */
static void accept(adh_static *w)
{
    size_t n = w->n;
    double z0 = w->m.z0;
    double h0a = w->st->h0, tha = w->tau_h, Fa = w->F, dFa = w->dFds;
    double d2 = (w->trial->h0 - h0a) * (w->trial->h0 - h0a), du2 = 0;
    for (size_t i = 0; i < n; i++)
        du2 += (w->trial->u[i] - w->st->u[i]) * (w->trial->u[i] - w->st->u[i]);
    double len = sqrt(d2 + w->s.u_weight * du2) / z0;
    adh_state *tmp = w->st;
    w->st = w->trial;
    w->trial = tmp;
    double *tt = w->tau_u;
    w->tau_u = w->tau_u_new;
    w->tau_u_new = tt;
    w->tau_h = w->tau_h_new;
    tt = w->Dst;
    w->Dst = w->Dtr;
    w->Dtr = tt;
    tt = w->gst;
    w->gst = w->gtr;
    w->gtr = tt;
    w->stable = w->det_sign > 0;
    w->F = force_of(w, w->st);
    w->s_arc += len;
    w->res.points++;
    if (w->skip) {
        record_smooth(w);
        return;
    }
    w->dFds = force_slope(w, w->Dst, w->tau_u, w->tau_h);
    if (w->res.points > 1)
        record(w, h0a, tha, Fa, dFa, len);
    else {
        w->res.pulloff_F = w->F;
        w->res.pulloff_h0 = w->st->h0;
    }
}

int adh_static_set(adh_static *w, const adh_material *m, const adh_static_settings *s)
{
    if (adh_static_settings_validate(s, NULL, 0) != ADH_SUCCESS || adh_material_validate(m, NULL, 0) != ADH_SUCCESS)
        return ADH_EINVAL;
    double t0 = adh_clock_seconds();
    size_t n = w->n;
    w->m = *m;
    w->s = *s;
    if (isnan(w->s.h0_start))
        w->s.h0_start = adh_protocol_auto_start(m, 0.05e-9);
    if (!(w->s.h0_start > w->s.h0_end))
        return ADH_EINVAL;
    w->c2E = 2.0 / m->E;
    for (size_t i = 0; i < n; i++)
        w->shape[i] = w->grid->r[i] * w->grid->r[i] / (2.0 * m->R);
    memset(&w->res, 0, sizeof w->res);
    w->res.jump_in_h0 = w->res.jump_out_h0 = w->res.pulloff_F_disp = NAN;
    w->res.pulloff_F = INFINITY;
    w->res.pulloff_h0 = NAN;
    w->nfolds_kept = 0;
    w->done = 0;
    w->s_arc = 0;
    w->ds = w->s.ds_init;
    w->act = w->s.active_tol;
    w->det_sign = +1;
    w->skip = s->lattice_skip < 0 ? n > ADH_STATIC_EXACT_MAX_NODES : s->lattice_skip;
    w->nhist = 0;
    w->end_next = 0;
    w->front = 0;
    w->fwin = 0;
    w->front_ok = w->skip;
    w->nf = 1;
    while (w->nf < n && fabs(adh_rings_width(w->grid, w->nf) - adh_rings_width(w->grid, 0)) <
                            1e-6 * adh_rings_width(w->grid, 0))
        w->nf++;

    /* The start: undeformed, going down. */
    memset(w->st->u, 0, n * sizeof *w->st->u);
    w->st->h0 = w->s.h0_start;
    memset(w->tau_u, 0, n * sizeof *w->tau_u);
    w->tau_h = -1.0;
    if (evaluate(w, w->st) < 0)
        return ADH_ENAN;
    int rc = linearize(w, w->st, w->tau_u, w->tau_h, &w->P);
    w->res.factorizations++;
    size_t it = 0;
    if (rc == ADH_SUCCESS)
        rc = correct(w, 0.0, 1, w->s.h0_start, NAN, &it);
    if (rc == ADH_SUCCESS) {
        rc = linearize(w, w->trial, w->tau_u, w->tau_h, &w->P);
        w->res.factorizations++;
    }
    if (rc == ADH_SUCCESS) {
        point_jacobian(w, w->trial, w->Dtr, w->gtr);
        rc = tangent(w, w->trial, w->Dtr, w->gtr, w->tau_u_new, &w->tau_h_new);
    }
    if (rc == ADH_SUCCESS && !(w->tau_h_new < 0))
        rc = ADH_ESTALL; /* the start must lie on the outer branch, going in */
    w->det_b_sign = w->P.det_sign;
    w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->P.det_sign;
    if (rc == ADH_SUCCESS && w->det_sign < 0)
        rc = ADH_ESTALL; /* J = I + small out there: det J > 0 */
    if (rc != ADH_SUCCESS) {
        w->res.seconds += adh_clock_seconds() - t0;
        return rc;
    }
    w->newton_point = it;
    w->F = 0;
    w->dFds = 0;
    accept(w);
    if (w->skip) {
        /* dQ/ds along the start's tangent, from Q's gradient */
        double qh, qs;
        w->q = qmeasure(w, w->st, w->rG, &qh, &qs);
        double d = qh * w->tau_h;
        for (size_t i = 0; i < n; i++)
            d += w->s.u_weight * w->rG[i] * w->tau_u[i];
        w->qslope = d * qs * w->m.z0; /* per unit s, which is in z0 */
        w->dq = w->s.ds_init * w->qslope;
        if (!(w->dq > 0)) {
            w->res.seconds += adh_clock_seconds() - t0;
            return ADH_ESTALL;
        }
    }
    w->res.seconds += adh_clock_seconds() - t0;
    return ADH_SUCCESS;
}

int adh_static_iterate(adh_static *w)
{
    if (w->done)
        return ADH_SUCCESS;
    w->act = w->s.active_tol;
    if (w->res.points >= w->s.max_points)
        return ADH_EMAXITER;
    double t0 = adh_clock_seconds();
    size_t n = w->n;
    double z0 = w->m.z0;
    double cos_max = cos(w->s.max_angle);
    size_t iters = 0;
    int rc;
    for (;;) {
        if (w->ds < w->s.ds_min) {
            rc = ADH_ESTALL;
            break;
        }
        if (w->skip)
            w->ds = w->dq / w->qslope;
        /* The last step lands on h0_end exactly (natural parametrization). */
        int fix = w->tau_h < 0 &&
                  (w->end_next || (!w->front && w->st->h0 + w->ds * z0 * w->tau_h <= w->s.h0_end));
        double ds = fix ? (w->s.h0_end - w->st->h0) / (z0 * w->tau_h) : w->ds;
        w->attempt++;
        rc = correct(w, ds, fix, w->s.h0_end, w->skip && !fix ? w->q + w->dq : NAN, &iters);
        if (rc == ADH_ENOMEM || rc == ADH_EINTR)
            break;
        int ok = rc == ADH_SUCCESS;
        double turn = 0, gap_ratio = 0;
        if (ok) {
            /* No node in the interaction zone may move its gap by more than
             * max_gap_step per step: a node crossing the barrier of the law
             * is what makes a lattice-trapping fold pair, and a step that
             * carried a node across at once could step over the pair. */
            double dg = 0;
            for (size_t i = 0; i < n; i++)
                if (fmin(w->st->h[i], w->trial->h[i]) < 3.0 * z0)
                    dg = fmax(dg, fabs(w->trial->h[i] - w->st->h[i]));
            gap_ratio = w->s.max_gap_step > 0 && !w->skip ? dg / (w->s.max_gap_step * z0) : 0;
            if (gap_ratio > 1) {
                w->res.rejected++;
                w->ds *= fmax(0.1, 0.7 / gap_ratio);
                continue;
            }
            if (w->skip && !fix && w->trial->h0 < w->s.h0_end && w->tau_h < 0) {
                /* a step in Q went past the end: land on it instead (in
                 * front mode from the front node interpolated there) */
                if (w->front && w->fk > 1) {
                    /* a shorter front step to about the end first: the
                     * landing is then within a ring */
                    double f = (w->st->h0 - w->s.h0_end) / (w->st->h0 - w->trial->h0);
                    size_t k = (size_t)floor(f * (double)w->fk);
                    w->fk = k < 1 ? 1 : k < w->fk ? k : w->fk - 1;
                    w->fhold = 1;
                    continue;
                }
                w->end_next = 1;
                w->fend = w->fe[0] + 1;
                continue;
            }
            if (w->front && !fix && front_node_of(w, w->trial) != w->fe[0] + w->fk) {
                /* the gap fH at the target ring, but the contact is not
                 * the disk up to it: not the front that was asked for */
                ok = 0;
                goto failed;
            }
            if (w->skip) {
                /* Q only grows along the curve: there is no leg running
                 * back to land on, and no tangent to solve for. On the curve
                 * smoothed over the lattice the stability follows the
                 * direction of h0 as on the exact one. */
                secant(w, w->tau_u_new, &w->tau_h_new);
                w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->det_b_sign;
                goto decided;
            }
            point_jacobian(w, w->trial, w->Dtr, w->gtr);
            rc = tangent(w, w->trial, w->Dtr, w->gtr, w->tau_u_new, &w->tau_h_new);
            /* A fold in this step: check det B at the new point (below),
             * factorizing there unless GMRES already did. */
            if (rc == ADH_SUCCESS && (w->tau_h_new < 0) != (w->tau_h < 0) &&
                !(w->P.stamp == w->attempt && w->P.tangent_border)) {
                rc = linearize(w, w->trial, w->tau_u, w->tau_h, &w->P);
                w->res.factorizations++;
            }
            ok = rc == ADH_SUCCESS;
        }
        if (ok) {
            double ct = metric_dot(w, w->tau_u, w->tau_h, w->tau_u_new, w->tau_h_new);
            turn = acos(fmin(1.0, fmax(-1.0, ct)));
            /* the secant from the last point must run along the old tangent:
             * a corrector that converged onto another part of the curve
             * fails this or the turn */
            double sh = (w->trial->h0 - w->st->h0) / z0, su = 0, s2 = sh * sh;
            for (size_t i = 0; i < n; i++) {
                double d = (w->trial->u[i] - w->st->u[i]) / z0;
                su += d * w->tau_u[i];
                s2 += w->s.u_weight * d * d;
            }
            double cs = (w->s.u_weight * su + sh * w->tau_h) / sqrt(s2);
            /* det B (bordered by the previous tangent) keeps its sign along
             * one curve traversed one way: a flip means the corrector landed
             * on a part of the curve that runs back against the tangent */
            ok = ct >= cos_max && cs >= cos_max;
            if (w->P.stamp == w->attempt && w->P.tangent_border)
                ok = ok && w->P.det_sign == w->det_b_sign;
            w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->det_b_sign;
        }
    decided:
        if (ok && w->skip) {
            double q = qmeasure(w, w->trial, NULL, NULL, NULL), q0 = w->q;
            double *tu = w->u2;
            w->u2 = w->u1;
            w->u1 = tu;
            memcpy(w->u1, w->st->u, n * sizeof *tu);
            w->q2 = w->q1, w->h2 = w->h1;
            w->q1 = q0, w->h1 = w->st->h0;
            w->nhist++;
            w->newton_point = iters;
            int was_front = w->front && !fix;
            accept(w);
            if (fix)
                w->done = 1;
            w->q = q;
            if (q > q0)
                w->qslope = (q - q0) / (w->s_arc - w->hist_s[1]);
            if (was_front) {
                size_t kused = w->fk;
                w->fe[2] = w->fe[1], w->fe[1] = w->fe[0], w->fe[0] += w->fk;
                w->fn++;
                if (q > q0)
                    w->dq = q - q0; /* should it fall back to steps in Q */
                /* grow while Newton converges at once, shrink when it labours
                 * (not while approaching an extremum) */
                if (w->fhold)
                    w->fhold = 0;
                else if (iters <= ADH_FRONT_GROW)
                    w->fk += w->fk / 2 > 1 ? w->fk / 2 : 1;
                else if (iters >= ADH_FRONT_GROW + 3)
                    w->fk = w->fk * 2 / 3 > 1 ? w->fk * 2 / 3 : 1;
                /* at most 1/ADH_FRONT_REL of the contact radius a step:
                 * the parabolas through three points must see the
                 * extremes coming */
                size_t kmax = w->fe[0] / ADH_FRONT_REL;
                kmax = kmax < 1 ? 1 : kmax > ADH_FRONT_MAX ? ADH_FRONT_MAX : kmax;
                if (w->fk > kmax)
                    w->fk = kmax;
                if (!w->done)
                    front_extremum(w, kused, q - q0);
            } else {
                /* grow while Newton converges at once, shrink when it labours */
                w->dq *= iters <= ADH_Q_GROW ? 1.5 : iters >= ADH_Q_GROW + 3 ? 0.7 : 1.0;
                if (w->fwin && front_node(w) >= w->fwin)
                    w->fwin = 0;
                if (w->front_ok && !w->done && !w->fwin)
                    front_start(w);
            }
            if (w->front && w->fe[0] + w->fk >= w->nf) {
                /* the fine band ends: the grid check below says so */
                w->fk = w->nf - 1 > w->fe[0] ? w->nf - 1 - w->fe[0] : 0;
                if (w->fk == 0)
                    w->front = 0;
            }
            rc = w->done ? ADH_SUCCESS : ADH_CONTINUE;
            double a = adh_contact_radius(w->grid, w->st->h, z0);
            if (a >= 0.9 * w->grid->rmax || !adh_rings_resolves(w->grid, a))
                rc = ADH_EGRID;
            break;
        }
        if (ok) {
            w->newton_point = iters;
            accept(w);
            if (fix)
                w->done = 1;
            /* adapt: aim at half the allowed turn per step (the turn grows
             * about linearly with ds), slow down when Newton labours */
            double f = turn > 1e-12 ? 0.5 * w->s.max_angle / turn : 2.0;
            if (gap_ratio > 0)
                f = fmin(f, 0.7 / gap_ratio);
            f = fmin(2.0, fmax(0.5, f));
            if (iters > 6)
                f = fmin(f, 0.7);
            w->ds = fmin(w->s.ds_max, w->ds * f);
            rc = w->done ? ADH_SUCCESS : ADH_CONTINUE;
            double a = adh_contact_radius(w->grid, w->st->h, z0);
            if (a >= 0.9 * w->grid->rmax || !adh_rings_resolves(w->grid, a))
                rc = ADH_EGRID;
            break;
        }
    failed:
        /* a failed step is usually a fold just ahead: cut hard */
        w->res.rejected++;
        if (w->front && !fix) {
            /* a shorter front step; from one ring, steps in Q across the
             * next few rings (as around an extremum), then front steps
             * again */
            if (w->fk == 1) {
                w->front = 0;
                w->fwin = w->fe[0] + ADH_FRONT_WINDOW;
                w->dq = w->dq > 0 ? w->dq : w->s.ds_init * w->qslope;
            }
            w->fk = w->fk / 2 > 1 ? w->fk / 2 : 1;
            continue;
        }
        if (w->front) {
            /* the landing failed from the front: steps of a ring in Q */
            w->front = 0, w->front_ok = 0;
            w->dq /= (double)w->fk;
        }
        w->ds *= 0.25;
        w->dq *= 0.25;
        w->end_next = 0; /* nearer in Q first: the end from closer by */
    }
    w->res.seconds += adh_clock_seconds() - t0;
    return rc;
}

const adh_state *adh_static_state(const adh_static *w)
{
    return w->st;
}

adh_static_point adh_static_current(const adh_static *w)
{
    adh_static_point p = {
        .s = w->s_arc,
        .tangent_h0 = w->tau_h,
        .direction = w->tau_h < 0 ? +1 : -1,
        .stable = w->stable,
        .newton = w->newton_point,
        .active = w->P.m,
        .residual = w->residual,
    };
    return p;
}

void adh_static_summary(const adh_static *w, adh_static_result *res)
{
    *res = w->res;
}

size_t adh_static_folds(const adh_static *w, const adh_static_fold **folds)
{
    if (folds)
        *folds = w->folds;
    return w->nfolds_kept;
}
