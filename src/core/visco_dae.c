/* The system IDAS integrates along the path parameter s (adhere/visco.h),
 * its Jacobian's products and its preconditioner, its roots and
 * quadratures, and the tangent that starts each segment. Unknowns
 * y = (u, q, tl[, h0]), tl the segment's local time. Each residual row is
 * in its unknown's units (u and h0 in m, q in Pa, tl in s), so that the
 * integrator's error weights also weigh the linear solves sensibly:
 *     r_u = u + W (cinf p + cdel q)
 *     r_q = q' - lam (p - q) tl' / tau
 *     r_t = sig ((theta |u'|^2 + (vm tl')^2) / z0^2 - 1),  sig = z0 / 2 vm
 *     r_h = h0 - base(tl) - F / k
 * with h = h0 + r^2/2R - u, p = p(h), D = p'(h), lam = 0 while crossing a
 * jump (q frozen). */
#include "visco_impl.h"

#include <gsl/gsl_cblas.h>
#include <idas/idas.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include "adhere/law.h"
#include "adhere/observe.h"
#include "adhere/status.h"

#define VISCO_KRYLOV 30       /* GMRES dimension in the integrator's solves */
#define VISCO_TANGENT_RTOL 1e-10
#ifndef VISCO_REFRESH
#define VISCO_REFRESH 0.1     /* adh_visco_pre_drift beyond which it is set up again */
#endif

double adh_visco_base_of(const adh_visco *w, const double *y)
{
    return w->seg.b0 + w->seg.bdot * y[w->IT];
}

double adh_visco_h0_of(const adh_visco *w, const double *y)
{
    return w->spring ? y[w->IH] : adh_visco_base_of(w, y);
}

int adh_visco_gaps(adh_visco *w, const double *u, double h0)
{
    double A = w->m.A, z0 = w->m.z0;
    for (size_t i = 0; i < w->n; i++) {
        double h = h0 + w->shape[i] - u[i];
        if (!(h > 0))
            return -1;
        w->h[i] = h;
        w->p[i] = adh_lj_pressure(h, A, z0);
    }
    return 0;
}

/* The tail beyond Rmax, as adh_force_tail, and its slope dF_tail/dh0. */
static double tail(const adh_visco *w, double h0, double *slope)
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
    return F + tail(w, h0, NULL);
}

/* D = p'(h) at w->h */
static void slopes(adh_visco *w)
{
    for (size_t i = 0; i < w->n; i++)
        w->D[i] = adh_lj_dpressure(w->h[i], w->m.A, w->m.z0);
}

static void kernel_apply(adh_visco *w, const double *x, double *out)
{
    adh_kernel_apply(w->k, x, out, w->scratch);
}

static int res(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    double *r = N_VGetArrayPointer(rr);
    size_t n = w->n;
    const double *u = y, *q = y + w->IQ, *ud = d, *qd = d + w->IQ;
    double h0 = adh_visco_h0_of(w, y), tp = d[w->IT], z0 = w->m.z0;
    if (adh_visco_gaps(w, u, h0) < 0)
        return 1; /* a gap closed: a shorter step */
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = w->cinf * w->p[i] + w->cdel * q[i];
    kernel_apply(w, w->tmp, r);
    double lt = w->lam * tp / w->v.tau, uu = 0;
    for (size_t i = 0; i < n; i++) {
        r[i] += u[i];
        r[w->IQ + i] = qd[i] - lt * (w->p[i] - q[i]);
        uu += ud[i] * ud[i];
    }
    double vm = w->seg.vm;
    r[w->IT] = z0 / (2 * vm) * ((w->theta * uu + vm * vm * tp * tp) / (z0 * z0) - 1.0);
    if (w->spring)
        r[w->IH] = h0 - adh_visco_base_of(w, y) - adh_visco_force(w, h0) / w->dr.spring;
    for (size_t i = 0; i < w->len; i++)
        if (!isfinite(r[i]))
            return 1;
    return 0;
}

/* Products with the Newton matrix M = dF/dy + cj dF/dy' need D at y. */
static int psetup(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, realtype cj, void *data);

/* Products with the Newton matrix M = dF/dy + cj dF/dy' need D at y. */
static int jtsetup(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, realtype cj, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy);
    if (adh_visco_gaps(w, y, adh_visco_h0_of(w, y)) < 0)
        return 1;
    slopes(w);
    /* The preconditioner is set up again here, not only when IDAS asks:
     * when it was set up for the other side of a fold's switch (lam: its
     * q elimination would be wrong), or when the Jacobian has moved
     * (the contact line crossing nodes changes p' there by orders of
     * magnitude within a step, and with the left preconditioning IDAS
     * requires, GMRES then meets its tolerance on a residual that says
     * little, and Newton diverges). */
    double tp = N_VGetArrayPointer(yp)[w->IT], alpha = cj + w->lam * tp / w->v.tau;
    double ceff = w->cinf + w->cdel * w->lam * tp / (w->v.tau * alpha);
    if ((w->p_lam != w->lam || adh_visco_pre_drift(w->pre, ceff, w->D) > VISCO_REFRESH) &&
        psetup(s, yy, yp, rr, cj, w) != 0)
        return 1;
    return 0;
}

/* M v: one kernel product. dh = dh0 - du, the change of the gaps. */
static int jtimes(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, N_Vector vv, N_Vector Jvv, realtype cj,
                  void *data, N_Vector t1, N_Vector t2)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp), *v = N_VGetArrayPointer(vv);
    double *Jv = N_VGetArrayPointer(Jvv), *dh = w->tmp2;
    size_t n = w->n;
    const double *vu = v, *vq = v + w->IQ, *q = y + w->IQ;
    double tp = d[w->IT], vt = v[w->IT], bdot = w->seg.bdot, z0 = w->m.z0, vm = w->seg.vm;
    double vh = w->spring ? v[w->IH] : bdot * vt;
    for (size_t i = 0; i < n; i++) {
        dh[i] = vh - vu[i];
        w->tmp[i] = w->cinf * w->D[i] * dh[i] + w->cdel * vq[i];
    }
    kernel_apply(w, w->tmp, Jv);
    double lt = w->lam / w->v.tau, ud = 0, dF = 0;
    for (size_t i = 0; i < n; i++) {
        Jv[i] += vu[i];
        Jv[w->IQ + i] = cj * vq[i] - lt * (tp * (w->D[i] * dh[i] - vq[i]) + (w->p[i] - q[i]) * cj * vt);
        ud += d[i] * vu[i];
        dF += w->area[i] * w->D[i] * dh[i];
    }
    Jv[w->IT] = cj * (w->theta * ud + vm * vm * tp * vt) / (vm * z0);
    if (w->spring) {
        double ts;
        tail(w, y[w->IH], &ts);
        Jv[w->IH] = v[w->IH] - bdot * vt - (dF + ts * v[w->IH]) / w->dr.spring;
    }
    return 0;
}

/* The preconditioner: M with q eliminated (its block is diagonal,
 * alpha = cj + lam tl'/tau) is J_eff = I - ceff W diag(D), ceff = cinf +
 * cdel lam tl' / (tau alpha), bordered by the tl (and h0) columns
 *     B_t = bdot ceff W D + a W (p - q)          [no spring]
 *     B_t = a W (p - q),  B_h = ceff W D         [spring]
 * (a = cdel lam cj / (tau alpha)) and the rows of r_t (cj theta u' /
 * (vm z0), corner cj vm tl' / z0) and r_h (2 pi w D / k, corners -bdot
 * and 1 - (sum 2 pi w D + tail') / k). */
static int psetup(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, realtype cj, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y), tp = d[w->IT], z0 = w->m.z0, vm = w->seg.vm, k = w->dr.spring;
    if (adh_visco_gaps(w, y, h0) < 0)
        return 1;
    slopes(w);
    double alpha = cj + w->lam * tp / w->v.tau;
    double ceff = w->cinf + w->cdel * w->lam * tp / (w->v.tau * alpha);
    w->p_cj = cj, w->p_alpha = alpha, w->p_ceff = ceff, w->p_tp = tp, w->p_lam = w->lam;
    memcpy(w->pD, w->D, n * sizeof *w->D);
    kernel_apply(w, w->pD, w->WD);
    for (size_t i = 0; i < n; i++)
        w->ppq[i] = w->p[i] - y[w->IQ + i];
    kernel_apply(w, w->ppq, w->Wpq);
    double a = w->cdel * w->lam * cj / (alpha * w->v.tau);
    double *B = w->bord, *C = w->bord + 2 * n, C0[4];
    for (size_t i = 0; i < n; i++) {
        B[i] = (w->spring ? 0 : w->seg.bdot * ceff * w->WD[i]) + a * w->Wpq[i];
        C[i] = cj * w->theta * d[i] / (vm * z0);
    }
    C0[0] = cj * vm * tp / z0;
    size_t nb = 1;
    if (w->spring) {
        double sAD = 0, ts;
        tail(w, h0, &ts);
        for (size_t i = 0; i < n; i++) {
            B[n + i] = ceff * w->WD[i];
            C[n + i] = w->area[i] * w->D[i] / k;
            sAD += w->area[i] * w->D[i];
        }
        nb = 2;
        C0[1] = 0;
        C0[2] = -w->seg.bdot;
        C0[3] = 1.0 - (sAD + ts) / k;
    }
    int rc = adh_visco_pre_factor(w->pre, ceff, w->pD, w->s.active_tol, nb, B, C, C0);
    return rc == ADH_SUCCESS ? 0 : rc == ADH_ENOMEM ? -1 : 1;
}

/* M^-1 r with the setup's factorization: q eliminated exactly, then the
 * bordered J_eff, then q back. One kernel product (W r_q). */
static int psolve(realtype s, N_Vector yy, N_Vector yp, N_Vector rr, N_Vector rvec, N_Vector zvec, realtype cj,
                  realtype delta, void *data)
{
    adh_visco *w = data;
    const double *r = N_VGetArrayPointer(rvec);
    double *z = N_VGetArrayPointer(zvec);
    size_t n = w->n;
    double alpha = w->p_alpha, a = w->cdel / alpha, rxi[2], xi[2] = { 0, 0 };
    memcpy(w->tmp, r + w->IQ, n * sizeof *r);
    kernel_apply(w, w->tmp, w->tmp2);
    for (size_t i = 0; i < n; i++)
        w->tmp2[i] = r[i] - a * w->tmp2[i];
    rxi[0] = r[w->IT];
    if (w->spring)
        rxi[1] = r[w->IH];
    adh_visco_pre_solve(w->pre, w->tmp2, rxi, z, xi);
    double lt = w->lam * w->p_tp / w->v.tau, lc = w->lam * w->p_cj / w->v.tau;
    double dh0 = w->spring ? xi[1] : w->seg.bdot * xi[0];
    for (size_t i = 0; i < n; i++)
        z[w->IQ + i] = (w->tmp[i] + lt * w->pD[i] * (dh0 - z[i]) + lc * w->ppq[i] * xi[0]) / alpha;
    z[w->IT] = xi[0];
    if (w->spring)
        z[w->IH] = xi[1];
    return 0;
}

/* dF/ds at y, y' (h, D at y computed here). */
static double force_rate(adh_visco *w, const double *y, const double *d)
{
    double h0 = adh_visco_h0_of(w, y);
    double h0d = w->spring ? d[w->IH] : w->seg.bdot * d[w->IT], ts, s = 0;
    tail(w, h0, &ts);
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
    double h0 = adh_visco_h0_of(w, y), base = adh_visco_base_of(w, y), tl = y[w->IT];
    for (int i = 0; i < NROOTS; i++)
        g[i] = 1.0;
    if (sg->frozen == 1) {
        g[ROOT_FOLD] = d[w->IT]; /* the crossing's other fold: t turns up */
        return 0;
    }
    if (sg->frozen == 2) {
        g[ROOT_END] = tl - sg->tl_fold;
        return 0;
    }
    g[ROOT_FOLD] = d[w->IT];
    if (sg->kind == SEG_LOAD && isfinite(sg->target))
        g[ROOT_END] = h0 - sg->target;
    else if (sg->kind == SEG_DWELL)
        g[ROOT_END] = tl - sg->tl_end;
    else if (sg->kind == SEG_UNLOAD)
        g[ROOT_END] = base - sg->target;
    if (sg->kind == SEG_UNLOAD)
        g[ROOT_PULLOFF] = force_rate(w, y, d);
    double hmin = INFINITY;
    for (size_t i = 0; i < w->n; i++)
        hmin = fmin(hmin, h0 + w->shape[i] - y[i]);
    g[ROOT_CONTACT] = hmin - ADH_CONTACT_FACTOR * w->m.z0;
    if (!isnan(sg->prof) && sg->kind != SEG_DWELL)
        g[ROOT_PROFILE] = base - sg->prof;
    return 0;
}

/* <a, W a> in the area-weighted inner product. */
static double energy_norm(adh_visco *w, const double *a)
{
    kernel_apply(w, a, w->tmp2);
    double e = 0;
    for (size_t i = 0; i < w->n; i++)
        e += w->area[i] * a[i] * w->tmp2[i];
    return e;
}

static int quad(realtype s, N_Vector yy, N_Vector yp, N_Vector rQ, void *data)
{
    adh_visco *w = data;
    const double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp);
    double *q = N_VGetArrayPointer(rQ);
    double h0 = adh_visco_h0_of(w, y), tp = d[w->IT];
    if (adh_visco_gaps(w, y, h0) < 0)
        return 1;
    double P = -adh_visco_force(w, h0) * w->seg.bdot * tp;
    q[QWORK] = w->seg.frozen ? 0 : P;
    q[QJUMP] = w->seg.frozen ? P : 0;
    q[QDISS] = 0;
    if (!w->seg.frozen && w->cdel > 0) {
        for (size_t i = 0; i < w->n; i++)
            w->tmp[i] = w->p[i] - y[w->IQ + i];
        q[QDISS] = w->cdel / w->v.tau * energy_norm(w, w->tmp) * tp;
    }
    return 0;
}

/* The tangent's operator: [J_u, cinf W D; 2 pi w D / k, 1 - (..)/k] on
 * (u'[, h0']), with D at the point (w->D). */
static int tan_atimes(void *data, N_Vector vv, N_Vector zz)
{
    adh_visco *w = data;
    const double *v = N_VGetArrayPointer(vv);
    double *z = N_VGetArrayPointer(zz);
    size_t n = w->n;
    double vh = w->spring ? v[n] : 0, dF = 0;
    for (size_t i = 0; i < n; i++) {
        w->tmp[i] = w->cinf * w->D[i] * (vh - v[i]);
        dF += w->area[i] * w->D[i] * (vh - v[i]);
    }
    kernel_apply(w, w->tmp, z);
    for (size_t i = 0; i < n; i++)
        z[i] += v[i];
    if (w->spring) {
        double ts;
        tail(w, w->st->h0, &ts);
        z[n] = vh - (dF + ts * vh) / w->dr.spring;
    }
    return 0;
}

static int tan_psolve(void *data, N_Vector rv, N_Vector zv, realtype tol, int lr)
{
    adh_visco *w = data;
    const double *r = N_VGetArrayPointer(rv);
    double *z = N_VGetArrayPointer(zv), xi[2] = { 0, 0 }, rxi[2] = { 0, 0 };
    if (w->spring)
        rxi[0] = r[w->n];
    adh_visco_pre_solve(w->pre, r, rxi, z, xi);
    if (w->spring)
        z[w->n] = xi[0];
    return 0;
}

/* y' along the path at y: with tl' = 1 first, the u (and h0) rows
 * differentiated give
 *     J_u a [+ cinf W D a_h] = -cdel lam W (p - q) / tau [- cinf bdot W D]
 *    [2 pi w D / k . a + (1 - (sum 2 pi w D + tail') / k) a_h = bdot]
 * then the normalisation scales it: tl' = z0 / sqrt(theta |a|^2 + vm^2). */
int adh_visco_tangent(adh_visco *w, const double *y, double *yp)
{
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y), k = w->dr.spring, bdot = w->seg.bdot;
    if (adh_visco_gaps(w, y, h0) < 0)
        return ADH_ESTALL;
    slopes(w);
    w->st->h0 = h0;
    kernel_apply(w, w->D, w->WD);
    for (size_t i = 0; i < n; i++)
        w->ppq[i] = w->p[i] - y[w->IQ + i];
    kernel_apply(w, w->ppq, w->Wpq);
    double *b = N_VGetArrayPointer(w->tb), *x = N_VGetArrayPointer(w->tx), lt = w->lam / w->v.tau;
    for (size_t i = 0; i < n; i++)
        b[i] = -w->cdel * lt * w->Wpq[i] - (w->spring ? 0 : w->cinf * bdot * w->WD[i]);
    if (w->spring) {
        double sAD = 0, ts, C0;
        tail(w, h0, &ts);
        for (size_t i = 0; i < n; i++) {
            w->bord[i] = w->cinf * w->WD[i];
            w->bord[2 * n + i] = w->area[i] * w->D[i] / k;
            sAD += w->area[i] * w->D[i];
        }
        C0 = 1.0 - (sAD + ts) / k;
        b[n] = bdot;
        if (adh_visco_pre_factor(w->pre, w->cinf, w->D, w->s.active_tol, 1, w->bord, w->bord + 2 * n, &C0) !=
            ADH_SUCCESS)
            return ADH_ESTALL;
    } else if (adh_visco_pre_factor(w->pre, w->cinf, w->D, w->s.active_tol, 0, NULL, NULL, NULL) != ADH_SUCCESS) {
        return ADH_ESTALL;
    }
    double bn = sqrt(N_VDotProd(w->tb, w->tb));
    N_VConst(0.0, w->tx);
    if (bn > 0) {
        if (SUNLinSolSetup(w->tls, NULL) != 0)
            return ADH_ESTALL;
        int rc = SUNLinSolSolve(w->tls, NULL, w->tx, w->tb, VISCO_TANGENT_RTOL * bn);
        if (rc != SUNLS_SUCCESS)
            return ADH_ESTALL;
    }
    double z0 = w->m.z0, vm = w->seg.vm, aa = 0;
    for (size_t i = 0; i < n; i++)
        aa += x[i] * x[i];
    double tp = z0 / sqrt(w->theta * aa + vm * vm);
    for (size_t i = 0; i < n; i++) {
        yp[i] = x[i] * tp;
        yp[w->IQ + i] = lt * w->ppq[i] * tp;
    }
    yp[w->IT] = tp;
    if (w->spring)
        yp[w->IH] = x[n] * tp;
    for (size_t i = 0; i < w->len; i++)
        if (!isfinite(yp[i]))
            return ADH_ESTALL;
    return ADH_SUCCESS;
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
    w->tls = SUNLinSol_SPGMR(w->tx, SUN_PREC_RIGHT, 60, w->sun);
    if (!w->ls || !w->tls)
        return ADH_ENOMEM;
    if (SUNLinSolSetATimes(w->tls, w, tan_atimes) != 0 ||
        SUNLinSolSetPreconditioner(w->tls, w, NULL, tan_psolve) != 0 || SUNLinSolInitialize(w->tls) != 0)
        return ADH_ENOMEM;
    SUNLinSol_SPGMRSetMaxRestarts(w->tls, 5);
    SUNLinSol_SPGMRSetGSType(w->tls, SUN_CLASSICAL_GS);
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

static int first_init(adh_visco *w, double s)
{
    w->ida = IDACreate(w->sun);
    if (!w->ida)
        return ADH_ENOMEM;
    int bad = IDAInit(w->ida, res, s, w->y, w->yp) != IDA_SUCCESS;
    bad = bad || IDASetUserData(w->ida, w) != IDA_SUCCESS;
    bad = bad || IDASetErrHandlerFn(w->ida, err_handler, w) != IDA_SUCCESS;
    bad = bad || IDASVtolerances(w->ida, w->s.tol, w->atol) != IDA_SUCCESS;
    bad = bad || IDASetLinearSolver(w->ida, w->ls, NULL) != IDA_SUCCESS;
    bad = bad || IDASetPreconditioner(w->ida, psetup, psolve) != IDA_SUCCESS;
    bad = bad || IDASetJacTimes(w->ida, jtsetup, jtimes) != IDA_SUCCESS;
    bad = bad || IDARootInit(w->ida, NROOTS, roots) != IDA_SUCCESS;
    bad = bad || IDASetNoInactiveRootWarn(w->ida) != IDA_SUCCESS;
    N_VConst(0.0, w->yq);
    bad = bad || IDAQuadInit(w->ida, quad, w->yq) != IDA_SUCCESS;
    /* the energies are reported numbers: their integrals are under the
     * same error control, on the scale of the law's pull-off times z0 */
    double escale = 2.0 * M_PI * w->m.A / (16.0 * M_PI * w->m.z0 * w->m.z0) * w->m.R * w->m.z0;
    bad = bad || IDASetQuadErrCon(w->ida, SUNTRUE) != IDA_SUCCESS;
    bad = bad || IDAQuadSStolerances(w->ida, w->s.tol, w->s.tol * escale) != IDA_SUCCESS;
    bad = bad || IDASetMaxNumSteps(w->ida, 100000) != IDA_SUCCESS;
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
        rc = IDAReInit(w->ida, s, w->y, w->yp) == IDA_SUCCESS && IDAQuadReInit(w->ida, w->yq) == IDA_SUCCESS &&
                     IDASVtolerances(w->ida, w->s.tol, w->atol) == IDA_SUCCESS
                 ? ADH_SUCCESS
                 : ADH_EINVAL;
    }
    if (rc != ADH_SUCCESS)
        return rc;
    adh_visco_root_directions(w);
    return ADH_SUCCESS;
}

void adh_visco_root_directions(adh_visco *w)
{
    const visco_seg *sg = &w->seg;
    int dir[NROOTS] = { -1, +1, +1, 0, 0 };
    if (sg->frozen == 1)
        dir[ROOT_FOLD] = +1;
    if (!sg->frozen && sg->kind == SEG_LOAD)
        dir[ROOT_END] = -1;
    dir[ROOT_PROFILE] = sg->kind == SEG_LOAD ? -1 : +1;
    IDASetRootDirection(w->ida, dir);
}

/* Checks, for the tests: at y, y' (the integrator's now) and cj, the
 * largest difference, relative to the vector, between M v by jtimes and
 * by a difference of the residual (*fd), and between P^-1 M v and v
 * (*pre), for v a smooth pseudo-random vector scaled as the error
 * weights. ADH_SUCCESS or the first failing call's status. */
int adh_visco_dae_check(adh_visco *w, double cj, double *fd, double *pre)
{
    N_Vector y = w->y, yp = w->yp, v = N_VClone(y), Mv = N_VClone(y), y2 = N_VClone(y), yp2 = N_VClone(y);
    N_Vector r0 = N_VClone(y), r1 = N_VClone(y), z = N_VClone(y);
    double *vv = N_VGetArrayPointer(v), *a = N_VGetArrayPointer(w->atol), s = w->s_now;
    for (size_t i = 0; i < w->len; i++)
        vv[i] = a[i] * sin(1.0 + 0.37 * (double)i);
    int rc = res(s, y, yp, r0, w) || jtsetup(s, y, yp, r0, cj, w) || jtimes(s, y, yp, r0, v, Mv, cj, w, NULL, NULL);
    double eps = 1e-3;
    N_VLinearSum(1.0, y, eps, v, y2);
    N_VLinearSum(1.0, yp, eps * cj, v, yp2);
    rc = rc || res(s, y2, yp2, r1, w);
    double *m = N_VGetArrayPointer(Mv), *p0 = N_VGetArrayPointer(r0), *p1 = N_VGetArrayPointer(r1);
    double e = 0, nm = 0;
    for (size_t i = 0; i < w->len; i++) {
        double d = (p1[i] - p0[i]) / eps;
        e = fmax(e, fabs(d - m[i]) / a[i]);
        nm = fmax(nm, fabs(m[i]) / a[i]);
    }
    *fd = e / nm;
    rc = rc || psetup(s, y, yp, r0, cj, w) || jtsetup(s, y, yp, r0, cj, w) ||
         jtimes(s, y, yp, r0, v, Mv, cj, w, NULL, NULL) || psolve(s, y, yp, r0, Mv, z, cj, 0, w);
    double *zz = N_VGetArrayPointer(z);
    e = 0;
    for (size_t i = 0; i < w->len; i++)
        e = fmax(e, fabs(zz[i] - vv[i]) / a[i]);
    *pre = e;
    N_Vector all[] = { v, Mv, y2, yp2, r0, r1, z };
    for (size_t i = 0; i < 7; i++)
        N_VDestroy(all[i]);
    return rc ? ADH_ESTALL : ADH_SUCCESS;
}
