/* IDAS for the viscoelastic solver (adhere/visco.h): its setup, its
 * callbacks, which hand over to the path's system (visco_path.c) or a
 * jump's crossing (visco_cross.c) by mode, the roots and quadratures of
 * the path, and the helpers both systems use. */
#include "visco.h"

#include <idas/idas.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include "adhere/law.h"
#include "adhere/observe.h"
#include "adhere/status.h"

#define VISCO_KRYLOV 30 /* GMRES dimension in the integrator's solves */
#define VISCO_NEWTON_COEF 0.03

double adh_visco_base_of(const adh_visco *w, const double *y)
{
    return w->seg.b0 + w->seg.bdot * y[w->IT];
}

double adh_visco_h0_of(const adh_visco *w, const double *y)
{
    return w->spring ? y[w->IH] : adh_visco_base_of(w, y);
}

int adh_visco_gaps_of(const adh_material *m, size_t n, const double *shape, const double *u, double h0, double *h,
                      double *p)
{
    double A = m->A, z0 = m->z0;
    for (size_t i = 0; i < n; i++) {
        double hi = h0 + shape[i] - u[i];
        if (!(hi > 0))
            return -1;
        h[i] = hi;
        p[i] = adh_lj_pressure(hi, A, z0);
    }
    return 0;
}

int adh_visco_gaps(adh_visco *w, const double *u, double h0)
{
    return adh_visco_gaps_of(&w->m, w->n, w->shape, u, h0, w->h, w->p);
}

void adh_visco_slopes(adh_visco *w)
{
    for (size_t i = 0; i < w->n; i++)
        w->D[i] = adh_lj_dpressure(w->h[i], w->m.A, w->m.z0);
}

/* As adh_force_tail, with its slope. */
double adh_visco_tail(const adh_visco *w, double h0, double *slope)
{
    double s = h0 + w->g->rmax * w->g->rmax / (2.0 * w->m.R);
    if (!(s > 0)) {
        if (slope)
            *slope = 0;
        return 0;
    }
    if (slope)
        *slope = -2.0 * M_PI * w->m.R * adh_lj_pressure(s, w->m.A, w->m.z0);
    return 2.0 * M_PI * w->m.R * adh_lj_energy(s, w->m.A, w->m.z0);
}

double adh_visco_force(const adh_visco *w, double h0)
{
    double F = 0;
    for (size_t i = 0; i < w->n; i++)
        F += w->area[i] * w->p[i];
    return F + adh_visco_tail(w, h0, NULL);
}

double adh_visco_uh_length(const adh_visco *w, const double *d)
{
    double uu = 0;
    for (size_t i = 0; i < w->n; i++)
        uu += d[i] * d[i];
    return sqrt(w->theta * uu + (w->spring ? d[w->IH] * d[w->IH] : 0));
}

void adh_visco_apply(adh_visco *w, const double *x, double *out)
{
    adh_kernel_apply(w->k, x, out, w->scratch);
}

void adh_visco_extra_gap(adh_visco *w, const double *q, double *e)
{
    adh_visco_apply(w, q, e);
    for (size_t i = 0; i < w->n; i++)
        e[i] *= w->cdel;
}

void adh_visco_psolve_q(adh_visco *w, const double *r, double *z)
{
    size_t n = w->n;
    for (size_t i = 0; i < n; i++)
        z[w->IQ + i] = r[w->IQ + i] / w->p_cj;
    if (w->cdel > 0)
        adh_visco_apply(w, z + w->IQ, w->tmp2);
    else
        memset(w->tmp2, 0, n * sizeof *w->tmp2);
}

static int res(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    double *r = N_VGetArrayPointer(rr);
    int rc = w->mode == MODE_CROSS  ? adh_visco_cross_res(w, y, d, r)
             : w->mode == MODE_FLOW ? adh_visco_flow_res(w, y, d, r)
                                    : adh_visco_path_res(w, y, d, r);
    if (rc)
        return rc;
    for (size_t i = 0; i < w->len; i++)
        if (!isfinite(r[i]))
            return 1;
    return 0;
}

static int psetup(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, realtype cj, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    if (adh_visco_gaps(w, y, adh_visco_h0_of(w, y)) < 0)
        return 1;
    adh_visco_slopes(w);
    int rc = w->mode == MODE_CROSS  ? adh_visco_cross_psetup(w, y, d, cj)
             : w->mode == MODE_FLOW ? adh_visco_flow_psetup(w, y, cj)
                                    : adh_visco_path_psetup(w, y, d, cj);
    return rc == ADH_SUCCESS ? 0 : rc == ADH_ENOMEM ? -1 : 1;
}

/* Products with M need D at the Newton iterate: here, once per linear
 * solve (IDAS calls it before each). The preconditioner is set up again
 * here too, not only when IDAS asks: when it was set up for the other
 * system (a jump began or ended), or when the Jacobian has moved (the
 * contact line crossing nodes changes p' there by orders of magnitude
 * within a step, and with the left preconditioning IDAS requires, GMRES
 * then meets its tolerance on a residual that says little, and Newton
 * diverges). */
static int jtsetup(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, realtype cj, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    if (adh_visco_gaps(w, y, adh_visco_h0_of(w, y)) < 0)
        return 1;
    adh_visco_slopes(w);
    double c;
    if (w->mode == MODE_CROSS) {
        c = w->cinf;
    } else if (w->mode == MODE_FLOW) {
        c = w->cinf / (1.0 + cj);
    } else {
        double tp = d[w->IT];
        c = w->cinf + w->cdel * tp / (w->v.tau * (cj + tp / w->v.tau));
    }
    if (w->p_mode != w->mode || adh_visco_pre_stale(w->pre, c, w->D))
        return psetup(s, yy, yp, rr, cj, w);
    return 0;
}

static int jtimes(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, N_Vector vv, N_Vector Jvv, realtype cj,
                  void *data, N_Vector t1, N_Vector t2)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp), *v = N_VGetArrayPointer(vv);
    double *Jv = N_VGetArrayPointer(Jvv);
    if (w->mode == MODE_CROSS)
        adh_visco_cross_jtimes(w, y, d, v, Jv, cj);
    else if (w->mode == MODE_FLOW)
        adh_visco_flow_jtimes(w, y, v, Jv, cj);
    else
        adh_visco_path_jtimes(w, y, d, v, Jv, cj);
    return 0;
}

static int psolve(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, N_Vector rvec, N_Vector zvec, realtype cj,
                  realtype delta, void *data)
{
    adh_visco *w = data;
    const double *r = N_VGetArrayPointer(rvec);
    double *z = N_VGetArrayPointer(zvec);
    if (w->mode == MODE_CROSS)
        adh_visco_cross_psolve(w, r, z);
    else if (w->mode == MODE_FLOW)
        adh_visco_flow_psolve(w, r, z);
    else
        adh_visco_path_psolve(w, r, z);
    return 0;
}

double adh_visco_force_rate(const adh_visco *w, const double *y, const double *d)
{
    double h0 = adh_visco_h0_of(w, y);
    double h0d = w->spring ? d[w->IH] : w->seg.bdot * d[w->IT], ts, s = 0;
    adh_visco_tail(w, h0, &ts);
    for (size_t i = 0; i < w->n; i++) {
        double h = h0 + w->shape[i] - y[i];
        s += w->area[i] * adh_lj_dpressure(h, w->m.A, w->m.z0) * (h0d - d[i]);
    }
    return s + ts * h0d;
}

static int roots(realtype s, N_Vector yy, N_Vector yp, realtype *g, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    const visco_seg *sg = &w->seg;
    for (int i = 0; i < NROOTS; i++)
        g[i] = 1.0;
    if (w->mode == MODE_CROSS) {
        adh_visco_cross_roots(w, y, d, g);
        return 0;
    }
    if (w->mode == MODE_FLOW)
        return 0;
    double h0 = adh_visco_h0_of(w, y), base = adh_visco_base_of(w, y), tl = y[w->IT];
    g[ROOT_FOLD] = d[w->IT];
    if (sg->kind == SEG_LOAD && isfinite(sg->target))
        g[ROOT_END] = h0 - sg->target;
    else if (sg->kind == SEG_DWELL)
        g[ROOT_END] = tl - sg->tl_end;
    else if (sg->kind == SEG_UNLOAD && isfinite(sg->target))
        g[ROOT_END] = base - sg->target;
    if (sg->kind == SEG_UNLOAD)
        g[ROOT_PULLOFF] = adh_visco_force_rate(w, y, d);
    double hmin = INFINITY;
    for (size_t i = 0; i < w->n; i++)
        hmin = fmin(hmin, h0 + w->shape[i] - y[i]);
    g[ROOT_CONTACT] = hmin - ADH_CONTACT_FACTOR * w->m.z0;
    if (!isnan(sg->prof) && sg->kind != SEG_DWELL)
        g[ROOT_PROFILE] = base - sg->prof;
    return 0;
}

/* The base's work -F bdot t' and the dissipation D t' per unit s; none
 * during a jump (no time passes). */
static int quad(realtype s, N_Vector yy, N_Vector yp, N_Vector rQ, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    double *q = N_VGetArrayPointer(rQ), h0 = adh_visco_h0_of(w, y), tp = d[w->IT];
    q[QWORK] = q[QDISS] = 0;
    if (w->mode != MODE_PATH)
        return 0;
    if (adh_visco_gaps(w, y, h0) < 0)
        return 1;
    q[QWORK] = -adh_visco_force(w, h0) * w->seg.bdot * tp;
    if (w->cdel > 0) {
        for (size_t i = 0; i < w->n; i++)
            w->tmp[i] = w->p[i] - y[w->IQ + i];
        q[QDISS] = w->cdel / w->v.tau * adh_visco_energy_norm(w, w->tmp) * tp;
    }
    return 0;
}

static void err_handler(int code, const char *module, const char *function, char *msg, void *data)
{
    adh_visco *w = data;
    snprintf(w->errmsg, sizeof w->errmsg, "%s: %s", function, msg);
}

int adh_visco_dae_create(adh_visco *w)
{
    if (SUNContext_Create(NULL, &w->sun) != 0)
        return ADH_ENOMEM;
    size_t nt = w->n + (size_t)w->spring;
    w->y = N_VNew_Serial((sunindextype)w->len, w->sun);
    w->yp = N_VNew_Serial((sunindextype)w->len, w->sun);
    w->atol = N_VNew_Serial((sunindextype)w->len, w->sun);
    w->yq = N_VNew_Serial(NQUAD, w->sun);
    w->tx = N_VNew_Serial((sunindextype)nt, w->sun);
    w->tb = N_VNew_Serial((sunindextype)nt, w->sun);
    if (!w->y || !w->yp || !w->atol || !w->yq || !w->tx || !w->tb)
        return ADH_ENOMEM;
    w->ls = SUNLinSol_SPGMR(w->y, SUN_PREC_LEFT, VISCO_KRYLOV, w->sun);
    /* classical Gram-Schmidt: fused dot products over the 2N + 1 unknowns
     * (5 % of the sigma = 22.5 cycle's CPU, measured) */
    if (w->ls)
        SUNLinSol_SPGMRSetGSType(w->ls, SUN_CLASSICAL_GS);
    w->tls = SUNLinSol_SPGMR(w->tx, SUN_PREC_RIGHT, 60, w->sun);
    if (!w->ls || !w->tls || adh_visco_tangent_setup(w) != ADH_SUCCESS)
        return ADH_ENOMEM;
    SUNLinSol_SPGMRSetMaxRestarts(w->tls, 5);
    return ADH_SUCCESS;
}

void adh_visco_dae_destroy(adh_visco *w)
{
    if (w->ida)
        IDAFree(&w->ida);
    if (w->ls)
        SUNLinSolFree(w->ls);
    if (w->tls)
        SUNLinSolFree(w->tls);
    w->ls = w->tls = NULL;
    N_Vector *vs[] = { &w->y, &w->yp, &w->atol, &w->yq, &w->tx, &w->tb };
    for (size_t i = 0; i < sizeof vs / sizeof *vs; i++)
        if (*vs[i]) {
            N_VDestroy(*vs[i]);
            *vs[i] = NULL;
        }
    if (w->sun)
        SUNContext_Free(&w->sun);
}

/* The absolute tolerances of this segment (its time scale is z0 / vm). */
static void tolerances(adh_visco *w)
{
    double *a = N_VGetArrayPointer(w->atol), tol = w->s.tol, z0 = w->m.z0;
    for (size_t i = 0; i < w->n; i++) {
        a[i] = tol * z0;
        a[w->IQ + i] = tol * w->pref;
    }
    a[w->IT] = tol * z0 / w->seg.vm;
    if (w->spring)
        a[w->IH] = tol * z0;
}

/* Under a spring h0 = base + F/k follows the force, which the gaps move
 * by F_n' du_n = 2 pi w_n p'(h_n) du_n: u's tolerance passes on to h0
 * multiplied by |2 pi w p'| / k (root sum of squares, as the tolerance
 * is a root mean square), large for a soft spring in contact. h0 is held
 * to that, or to its own tolerance where it is tighter. */
static double spring_gain(const adh_visco *w, const double *y)
{
    double h0 = y[w->IH], s = 0;
    for (size_t i = 0; i < w->n; i++) {
        double g = w->area[i] * adh_lj_dpressure(h0 + w->shape[i] - y[i], w->m.A, w->m.z0);
        s += g * g;
    }
    return fmax(1.0, sqrt(s) / w->dr.spring);
}

/* The error weights: relative and absolute for u and q, absolute only
 * for the clock and h0, whose size is where the run is, not how precise
 * it must be (a relative part would loosen the time of events as a run
 * goes on). The integrator's norm is a root mean square over all 2N + 1
 * (+1) unknowns; the clock and h0 are single numbers that each decide
 * where the path is, so each counts as much as all the nodes together
 * (x sqrt(len)): near a fold an error in t that the mean would have
 * diluted is what the next step's Newton cannot correct. */
static int weights(N_Vector yy, N_Vector ewt, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *a = N_VGetArrayPointer(w->atol);
    double *e = N_VGetArrayPointer(ewt), rt = w->s.tol, sl = sqrt((double)w->len);
    for (size_t i = 0; i < 2 * w->n; i++)
        e[i] = 1.0 / (rt * fabs(y[i]) + a[i]);
    for (size_t i = 2 * w->n; i < w->len; i++)
        e[i] = sl / a[i];
    if (w->spring)
        e[w->IH] /= spring_gain(w, y);
    return 0;
}

static int first_init(adh_visco *w, double s)
{
    w->ida = IDACreate(w->sun);
    if (!w->ida)
        return ADH_ENOMEM;
    /* the energies are reported numbers: their integrals are under the
     * same error control, on the scale of the law's pull-off times z0 */
    double escale = w->m.A / (8.0 * w->m.z0) * w->m.R;
    N_VConst(0.0, w->yq);
    int bad = IDAInit(w->ida, res, s, w->y, w->yp) != IDA_SUCCESS;
    bad = bad || IDASetUserData(w->ida, w) != IDA_SUCCESS;
    bad = bad || IDASetErrHandlerFn(w->ida, err_handler, w) != IDA_SUCCESS;
    bad = bad || IDAWFtolerances(w->ida, weights) != IDA_SUCCESS;
    bad = bad || IDASetLinearSolver(w->ida, w->ls, NULL) != IDA_SUCCESS;
    bad = bad || IDASetPreconditioner(w->ida, psetup, psolve) != IDA_SUCCESS;
    bad = bad || IDASetJacTimes(w->ida, jtsetup, jtimes) != IDA_SUCCESS;
    bad = bad || IDARootInit(w->ida, NROOTS, roots) != IDA_SUCCESS;
    bad = bad || IDASetNoInactiveRootWarn(w->ida) != IDA_SUCCESS;
    bad = bad || IDAQuadInit(w->ida, quad, w->yq) != IDA_SUCCESS;
    bad = bad || IDASetQuadErrCon(w->ida, SUNTRUE) != IDA_SUCCESS;
    bad = bad || IDAQuadSStolerances(w->ida, w->s.tol, w->s.tol * escale) != IDA_SUCCESS;
    bad = bad || IDASetMaxNumSteps(w->ida, 100000) != IDA_SUCCESS;
    /* Newton's corrections to a thirtieth of the tolerance, not a third:
     * the normalisation holds u', and u' = cj du cannot absorb an
     * algebraic residual a step left behind once the next step has to be
     * short (measured: soft springs near their snap-out failed at 0.33
     * and 0.1) */
    bad = bad || IDASetNonlinConvCoef(w->ida, VISCO_NEWTON_COEF) != IDA_SUCCESS;
    return bad ? ADH_ENOMEM : ADH_SUCCESS;
}

int adh_visco_dae_start(adh_visco *w, double s, const double *y, const double *yp)
{
    if (N_VGetArrayPointer(w->y) != y)
        memcpy(N_VGetArrayPointer(w->y), y, w->len * sizeof *y);
    if (N_VGetArrayPointer(w->yp) != yp)
        memcpy(N_VGetArrayPointer(w->yp), yp, w->len * sizeof *yp);
    tolerances(w);
    int rc;
    if (!w->ida) {
        rc = first_init(w, s);
    } else {
        N_VConst(0.0, w->yq);
        rc = IDAReInit(w->ida, s, w->y, w->yp) == IDA_SUCCESS && IDAQuadReInit(w->ida, w->yq) == IDA_SUCCESS
                 ? ADH_SUCCESS
                 : ADH_EINVAL;
    }
    if (rc == ADH_SUCCESS)
        adh_visco_root_directions(w);
    return rc;
}

void adh_visco_root_directions(adh_visco *w)
{
    int dir[NROOTS] = { -1, +1, +1, 0, 0 };
    if (w->seg.kind == SEG_LOAD)
        dir[ROOT_END] = -1;
    if (w->mode == MODE_CROSS) {
        dir[ROOT_FOLD] = w->cross_dir;
        dir[ROOT_END] = w->cross_dir;
    }
    dir[ROOT_PROFILE] = w->seg.kind == SEG_LOAD ? -1 : +1;
    IDASetRootDirection(w->ida, dir);
}

int adh_visco_dae_check(adh_visco *w, double cj, double *fd, double *pre)
{
    N_Vector y = w->y, yp = w->yp, v = N_VClone(y), Mv = N_VClone(y), y2 = N_VClone(y), yp2 = N_VClone(y);
    N_Vector r0 = N_VClone(y), r1 = N_VClone(y), z = N_VClone(y);
    double *vv = N_VGetArrayPointer(v), *a = N_VGetArrayPointer(w->atol), s = w->s_now, eps = 1e-3;
    for (size_t i = 0; i < w->len; i++)
        vv[i] = a[i] * sin(1.0 + 0.37 * (double)i);
    /* a central difference: exact for the normalisation, quadratic in y' */
    N_VLinearSum(1.0, y, eps, v, y2);
    N_VLinearSum(1.0, yp, eps * cj, v, yp2);
    int rc = res(s, y2, yp2, r1, w);
    N_VLinearSum(1.0, y, -eps, v, y2);
    N_VLinearSum(1.0, yp, -eps * cj, v, yp2);
    rc = rc || res(s, y2, yp2, r0, w) || jtsetup(s, y, yp, r0, cj, w) ||
         jtimes(s, y, yp, r0, v, Mv, cj, w, NULL, NULL);
    double *m = N_VGetArrayPointer(Mv), *p0 = N_VGetArrayPointer(r0), *p1 = N_VGetArrayPointer(r1);
    double e = 0, nm = 0;
    for (size_t i = 0; i < w->len; i++) {
        e = fmax(e, fabs((p1[i] - p0[i]) / (2 * eps) - m[i]) / a[i]);
        nm = fmax(nm, fabs(m[i]) / a[i]);
    }
    *fd = e / nm;
    rc = rc || res(s, y, yp, r0, w) || psetup(s, y, yp, r0, cj, w) || psolve(s, y, yp, r0, Mv, z, cj, 0, w);
    double *zz = N_VGetArrayPointer(z);
    e = 0;
    for (size_t i = 0; i < w->len; i++)
        e = fmax(e, fabs(zz[i] - vv[i]) / a[i]);
    *pre = e;
    N_Vector all[] = { v, Mv, y2, yp2, r0, r1, z };
    for (size_t i = 0; i < sizeof all / sizeof *all; i++)
        N_VDestroy(all[i]);
    return rc ? ADH_ESTALL : ADH_SUCCESS;
}
