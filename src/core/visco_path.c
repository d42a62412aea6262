/* The path's system (adhere/visco.h), integrated along its arclength s.
 * Unknowns y = (u, q, tl[, h0]), tl the segment's local time; each
 * residual row in its unknown's units (u and h0 in m, q in Pa, tl in s),
 * so that the integrator's error weights also weigh the linear solves:
 *     r_u = u + W (cinf p + cdel q)
 *     r_q = q' - (p - q) tl' / tau
 *     r_t = sig ((theta |u'|^2 [+ h0'^2] + (vm tl')^2) / z0^2 - 1),  sig = z0 / 2 vm
 *    [r_h = h0 - base(tl) - F / k]
 * with h = h0 + r^2/2R - u, p = p(h), D = p'(h). */
#include "visco.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "adhere/status.h"

#define VISCO_TANGENT_RTOL 1e-10

int adh_visco_path_res(adh_visco *w, const double *y, const double *d, double *r)
{
    size_t n = w->n;
    const double *u = y, *q = y + w->IQ, *ud = d, *qd = d + w->IQ;
    double h0 = adh_visco_h0_of(w, y), tp = d[w->IT], z0 = w->m.z0;
    if (adh_visco_gaps(w, u, h0) < 0)
        return 1; /* a gap closed: a shorter step */
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = w->cinf * w->p[i] + w->cdel * q[i];
    adh_visco_apply(w, w->tmp, r);
    double lt = tp / w->v.tau, uu = 0;
    for (size_t i = 0; i < n; i++) {
        r[i] += u[i];
        r[w->IQ + i] = qd[i] - lt * (w->p[i] - q[i]);
        uu += ud[i] * ud[i];
    }
    double vm = w->seg.vm, hp = w->spring ? d[w->IH] : 0;
    r[w->IT] = z0 / (2 * vm) * ((w->theta * uu + hp * hp + vm * vm * tp * tp) / (z0 * z0) - 1.0);
    if (w->spring)
        r[w->IH] = h0 - adh_visco_base_of(w, y) - adh_visco_force(w, h0) / w->dr.spring;
    return 0;
}

/* M v, M = dF/dy + cj dF/dy' (D and p at y already in w): one kernel
 * product. dh = dh0 - du, the change of the gaps. */
void adh_visco_path_jtimes(adh_visco *w, const double *y, const double *d, const double *v, double *Jv, double cj)
{
    size_t n = w->n;
    const double *vu = v, *vq = v + w->IQ, *q = y + w->IQ;
    double *dh = w->tmp2, tp = d[w->IT], vt = v[w->IT], bdot = w->seg.bdot, z0 = w->m.z0, vm = w->seg.vm;
    double vh = w->spring ? v[w->IH] : bdot * vt;
    for (size_t i = 0; i < n; i++) {
        dh[i] = vh - vu[i];
        w->tmp[i] = w->cinf * w->D[i] * dh[i] + w->cdel * vq[i];
    }
    adh_visco_apply(w, w->tmp, Jv);
    double lt = 1.0 / w->v.tau, ud = 0, dF = 0;
    for (size_t i = 0; i < n; i++) {
        Jv[i] += vu[i];
        Jv[w->IQ + i] = cj * vq[i] - lt * (tp * (w->D[i] * dh[i] - vq[i]) + (w->p[i] - q[i]) * cj * vt);
        ud += d[i] * vu[i];
        dF += w->area[i] * w->D[i] * dh[i];
    }
    Jv[w->IT] = cj * (w->theta * ud + vm * vm * tp * vt) / (vm * z0);
    if (w->spring) {
        double ts;
        adh_visco_tail(w, y[w->IH], &ts);
        Jv[w->IT] += cj * d[w->IH] * v[w->IH] / (vm * z0);
        Jv[w->IH] = v[w->IH] - bdot * vt - (dF + ts * v[w->IH]) / w->dr.spring;
    }
}

/* The preconditioner: M with q eliminated (its block is diagonal,
 * alpha = cj + tl'/tau) is J_eff = I - ceff W diag(D), ceff = cinf +
 * cdel tl' / (tau alpha), bordered by the tl (and h0) columns
 *     B_t = bdot ceff W D + a W (p - q)          [no spring]
 *     B_t = a W (p - q),  B_h = ceff W D         [spring]
 * (a = cdel cj / (tau alpha)) and the rows of r_t (cj theta u' /
 * (vm z0), corners cj vm tl' / z0 and cj h0' / (vm z0)) and r_h
 * (2 pi w D / k, corners -bdot and 1 - (sum 2 pi w D + tail') / k).
 * w->p and w->D must hold y's. */
int adh_visco_path_psetup(adh_visco *w, const double *y, const double *d, double cj)
{
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y), tp = d[w->IT], z0 = w->m.z0, vm = w->seg.vm, k = w->dr.spring;
    double alpha = cj + tp / w->v.tau;
    double ceff = w->cinf + w->cdel * tp / (w->v.tau * alpha);
    w->p_cj = cj, w->p_alpha = alpha, w->p_ceff = ceff, w->p_tp = tp, w->p_mode = MODE_PATH;
    memcpy(w->pD, w->D, n * sizeof *w->D);
    for (size_t i = 0; i < n; i++)
        w->ppq[i] = w->p[i] - y[w->IQ + i];
    adh_visco_apply(w, w->pD, w->WD);
    adh_visco_apply(w, w->ppq, w->Wpq);
    double a = w->cdel * cj / (alpha * w->v.tau);
    double *B = w->bord, *C = w->bord + 2 * n, C0[4];
    for (size_t i = 0; i < n; i++) {
        B[i] = (w->spring ? 0 : w->seg.bdot * ceff * w->WD[i]) + a * w->Wpq[i];
        C[i] = cj * w->theta * d[i] / (vm * z0);
    }
    C0[0] = cj * vm * tp / z0;
    size_t nb = 1;
    if (w->spring) {
        double sAD = 0, ts;
        adh_visco_tail(w, h0, &ts);
        for (size_t i = 0; i < n; i++) {
            B[n + i] = ceff * w->WD[i];
            C[n + i] = w->area[i] * w->pD[i] / k;
            sAD += w->area[i] * w->pD[i];
        }
        nb = 2;
        C0[1] = cj * d[w->IH] / (vm * z0);
        C0[2] = -w->seg.bdot;
        C0[3] = 1.0 - (sAD + ts) / k;
    }
    return adh_visco_pre_factor(w->pre, ceff, w->pD, w->s.active_tol, nb, B, C, C0);
}

/* M^-1 r with the setup's factorization: q eliminated exactly, then the
 * bordered J_eff, then q back. One kernel product (W r_q). */
void adh_visco_path_psolve(adh_visco *w, const double *r, double *z)
{
    size_t n = w->n;
    double alpha = w->p_alpha, a = w->cdel / alpha, rxi[2] = { r[w->IT], 0 }, xi[2] = { 0, 0 };
    memcpy(w->tmp, r + w->IQ, n * sizeof *r);
    adh_visco_apply(w, w->tmp, w->tmp2);
    for (size_t i = 0; i < n; i++)
        w->tmp2[i] = r[i] - a * w->tmp2[i];
    if (w->spring)
        rxi[1] = r[w->IH];
    adh_visco_pre_solve(w->pre, w->tmp2, rxi, z, xi);
    double lt = w->p_tp / w->v.tau, lc = w->p_cj / w->v.tau;
    double dh0 = w->spring ? xi[1] : w->seg.bdot * xi[0];
    for (size_t i = 0; i < n; i++)
        z[w->IQ + i] = (w->tmp[i] + lt * w->pD[i] * (dh0 - z[i]) + lc * w->ppq[i] * xi[0]) / alpha;
    z[w->IT] = xi[0];
    if (w->spring)
        z[w->IH] = xi[1];
}

/* The tangent's operator: [J_u, cinf W D; 2 pi w D / k, 1 - (..)/k] on
 * (u'[, h0']), with D at the point (w->D); without the spring's row
 * (tan_row 0) h0 stays (the identity on its slot). */
static int tan_atimes(void *data, N_Vector vv, N_Vector zz)
{
    adh_visco *w = data;
    const double *v = N_VGetArrayPointer(vv);
    double *z = N_VGetArrayPointer(zz);
    size_t n = w->n;
    double vh = w->spring && w->tan_row ? v[n] : 0, dF = 0;
    for (size_t i = 0; i < n; i++) {
        w->tmp[i] = w->cinf * w->D[i] * (vh - v[i]);
        dF += w->area[i] * w->D[i] * (vh - v[i]);
    }
    adh_visco_apply(w, w->tmp, z);
    for (size_t i = 0; i < n; i++)
        z[i] += v[i];
    if (w->spring && !w->tan_row)
        z[n] = v[n];
    if (w->spring && w->tan_row) {
        double ts;
        adh_visco_tail(w, w->st->h0, &ts);
        z[n] = vh - (dF + ts * vh) / w->dr.spring;
    }
    return 0;
}

static int tan_psolve(void *data, N_Vector rv, N_Vector zv, realtype tol, int lr)
{
    adh_visco *w = data;
    const double *r = N_VGetArrayPointer(rv);
    double *z = N_VGetArrayPointer(zv), xi[2] = { 0, 0 }, rxi[2] = { 0, 0 };
    if (w->spring && w->tan_row)
        rxi[0] = r[w->n];
    adh_visco_pre_solve(w->pre, r, rxi, z, xi);
    if (w->spring)
        z[w->n] = w->tan_row ? xi[0] : r[w->n];
    return 0;
}

int adh_visco_tangent_setup(adh_visco *w)
{
    if (SUNLinSolSetATimes(w->tls, w, tan_atimes) != 0 ||
        SUNLinSolSetPreconditioner(w->tls, w, NULL, tan_psolve) != 0 || SUNLinSolInitialize(w->tls) != 0)
        return ADH_ENOMEM;
    return ADH_SUCCESS;
}

/* The tangent's preconditioner: J_u at cinf (the instantaneous one),
 * bordered by the spring's row. */
static int tangent_factor(adh_visco *w, double h0)
{
    size_t n = w->n;
    if (!w->spring || !w->tan_row)
        return adh_visco_pre_factor(w->pre, w->cinf, w->D, w->s.active_tol, 0, NULL, NULL, NULL);
    double sAD = 0, ts, C0;
    adh_visco_tail(w, h0, &ts);
    for (size_t i = 0; i < n; i++) {
        w->bord[i] = w->cinf * w->WD[i];
        w->bord[2 * n + i] = w->area[i] * w->D[i] / w->dr.spring;
        sAD += w->area[i] * w->D[i];
    }
    C0 = 1.0 - (sAD + ts) / w->dr.spring;
    return adh_visco_pre_factor(w->pre, w->cinf, w->D, w->s.active_tol, 1, w->bord, w->bord + 2 * n, &C0);
}

/* y' along the path at y: with tl' = 1 first, the u (and h0) rows
 * differentiated give
 *     J_u a [+ cinf W D a_h] = -cdel W (p - q) / tau [- cinf bdot W D]
 *    [2 pi w D / k . a + (1 - (sum 2 pi w D + tail') / k) a_h = bdot]
 * then the normalisation scales it: tl' = z0 / sqrt(theta |a|^2 + a_h^2 + vm^2). */
int adh_visco_tangent(adh_visco *w, const double *y, double *yp)
{
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y), bdot = w->seg.bdot;
    if (adh_visco_gaps(w, y, h0) < 0)
        return ADH_ESTALL;
    adh_visco_slopes(w);
    w->st->h0 = h0;
    w->tan_row = 1;
    adh_visco_apply(w, w->D, w->WD);
    for (size_t i = 0; i < n; i++)
        w->ppq[i] = w->p[i] - y[w->IQ + i];
    adh_visco_apply(w, w->ppq, w->Wpq);
    double *b = N_VGetArrayPointer(w->tb), *x = N_VGetArrayPointer(w->tx), lt = 1.0 / w->v.tau;
    for (size_t i = 0; i < n; i++)
        b[i] = -w->cdel * lt * w->Wpq[i] - (w->spring ? 0 : w->cinf * bdot * w->WD[i]);
    if (w->spring)
        b[n] = bdot;
    if (tangent_factor(w, h0) != ADH_SUCCESS)
        return ADH_ESTALL;
    w->p_mode = -1; /* the integrator's preconditioner is set up again */
    double bn = sqrt(N_VDotProd(w->tb, w->tb));
    N_VConst(0.0, w->tx);
    if (bn > 0) {
        if (SUNLinSolSetup(w->tls, NULL) != 0)
            return ADH_ESTALL;
        if (SUNLinSolSolve(w->tls, NULL, w->tx, w->tb, VISCO_TANGENT_RTOL * bn) != SUNLS_SUCCESS)
            return ADH_ESTALL;
    }
    double z0 = w->m.z0, vm = w->seg.vm, aa = 0, ah = w->spring ? x[n] : 0;
    for (size_t i = 0; i < n; i++)
        aa += x[i] * x[i];
    double tp = z0 / sqrt(w->theta * aa + ah * ah + vm * vm);
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

/* The spring's equation h0 = base + F/k holds to F's rounding over k
 * only: F sums pressures that cancel (in contact ~200 times F), and a soft
 * spring magnifies its last digits. Through 1 mN/m on a 200-node grid the
 * residual stalled at 7e-17 m while a thousandth of the tolerance asked
 * 2.5e-17 (5e-5 z0), and the path could not restart at its turn. */
static double spring_rounding(const adh_visco *w, double h0)
{
    double fa = fabs(adh_visco_tail(w, h0, NULL));
    for (size_t i = 0; i < w->n; i++)
        fa += fabs(w->area[i] * w->p[i]);
    return 16 * DBL_EPSILON * (sqrt((double)w->n) * fa / w->dr.spring + fabs(h0));
}

/* Newton on the equilibrium at y's q and time: u (and, with row, h0 from
 * the spring's equation) until the residual is a thousandth of the
 * tolerance. A point the integrator's rootfinding interpolated is on the
 * path only within the tolerance, and a new start there would have to
 * correct that in its first step, where u' = cj du is then unbounded. */
int adh_visco_polish(adh_visco *w, double *y, int row)
{
    size_t n = w->n;
    double lim = 1e-3 * w->s.tol * w->m.z0, *b = N_VGetArrayPointer(w->tb), *x = N_VGetArrayPointer(w->tx);
    w->tan_row = row;
    for (int it = 0; it < 8; it++) {
        double h0 = adh_visco_h0_of(w, y), big = 0;
        if (adh_visco_gaps(w, y, h0) < 0)
            return ADH_ESTALL;
        for (size_t i = 0; i < n; i++)
            w->tmp[i] = w->cinf * w->p[i] + w->cdel * y[w->IQ + i];
        adh_visco_apply(w, w->tmp, w->tmp2);
        for (size_t i = 0; i < n; i++) {
            b[i] = -(y[i] + w->tmp2[i]);
            big = fmax(big, fabs(b[i]));
        }
        int held = 1;   /* the spring's equation, where there is one */
        if (w->spring) {
            b[n] = row ? -(h0 - adh_visco_base_of(w, y) - adh_visco_force(w, h0) / w->dr.spring) : 0;
            held = fabs(b[n]) < fmax(lim, spring_rounding(w, h0));
        }
        if (big < lim && held)
            return ADH_SUCCESS;
        adh_visco_slopes(w);
        w->st->h0 = h0;
        adh_visco_apply(w, w->D, w->WD);
        if (tangent_factor(w, h0) != ADH_SUCCESS || SUNLinSolSetup(w->tls, NULL) != 0)
            return ADH_ESTALL;
        N_VConst(0.0, w->tx);
        if (SUNLinSolSolve(w->tls, NULL, w->tx, w->tb, 1e-3 * lim) != SUNLS_SUCCESS &&
            SUNLinSolResNorm(w->tls) > lim)
            return ADH_ESTALL;
        for (size_t i = 0; i < n; i++)
            y[i] += x[i];
        if (w->spring && row)
            y[w->IH] += x[n];
    }
    return ADH_ESTALL;
}
