/* A jump's relaxation (adhere/visco.h), the crossing's fallback: where
 * following the equilibria from the fold (visco_cross.c) gets lost, as on
 * the ladder of lattice folds of a grid that does not resolve the contact
 * edge, the jump is what it is physically, a motion far faster than tau
 * and the drive, so with time, base and q frozen and no inertia an
 * overdamped one:
 *     r_u = u' + u + W (cinf p + cdel q)      (u' = -G(u))
 *     r_q = q',  r_t = tl'
 *    [r_h = h0' + h0 - base - F / k]
 * in a pseudo-time, from the fold nudged along the path's tangent (the
 * side where no equilibrium is left), until it stops. G's Jacobian
 * J = I - cinf W diag(D) is the static mode's, so the Newton matrix
 * (cj + 1) I - cinf W diag(D) is preconditioned by the same factorization
 * at c = cinf / (1 + cj). Where the crossing lands on the static mode's
 * other branch, this lands on the first stable state downhill, which on a
 * resolved grid is the same branch and on an unresolved one may be a
 * lattice-pinned state near it. */
#include "visco.h"

#include <math.h>
#include <string.h>

#include "adhere/status.h"

int adh_visco_flow_res(adh_visco *w, const double *y, const double *d, double *r)
{
    size_t n = w->n;
    const double *u = y, *q = y + w->IQ;
    double h0 = adh_visco_h0_of(w, y);
    if (adh_visco_gaps(w, u, h0) < 0)
        return 1;
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = w->cinf * w->p[i] + w->cdel * q[i];
    adh_visco_apply(w, w->tmp, r);
    for (size_t i = 0; i < n; i++) {
        r[i] += u[i] + d[i];
        r[w->IQ + i] = d[w->IQ + i];
    }
    r[w->IT] = d[w->IT];
    if (w->spring)
        r[w->IH] = d[w->IH] + h0 - adh_visco_base_of(w, y) - adh_visco_force(w, h0) / w->dr.spring;
    return 0;
}

void adh_visco_flow_jtimes(adh_visco *w, const double *y, const double *v, double *Jv, double cj)
{
    size_t n = w->n;
    const double *vu = v, *vq = v + w->IQ;
    double vt = v[w->IT], bdot = w->seg.bdot, vh = w->spring ? v[w->IH] : bdot * vt, dF = 0;
    for (size_t i = 0; i < n; i++) {
        double dh = vh - vu[i];
        w->tmp[i] = w->cinf * w->D[i] * dh + w->cdel * vq[i];
        dF += w->area[i] * w->D[i] * dh;
    }
    adh_visco_apply(w, w->tmp, Jv);
    for (size_t i = 0; i < n; i++) {
        Jv[i] += (1.0 + cj) * vu[i];
        Jv[w->IQ + i] = cj * vq[i];
    }
    Jv[w->IT] = cj * vt;
    if (w->spring) {
        double ts;
        adh_visco_tail(w, y[w->IH], &ts);
        Jv[w->IH] = (1.0 + cj) * v[w->IH] - bdot * vt - (dF + ts * v[w->IH]) / w->dr.spring;
    }
}

/* With q and tl eliminated (diagonal, cj), the u rows over (1 + cj) are
 * I - c' W diag(D), c' = cinf / (1 + cj), bordered by the spring's h0:
 * column c' W D, row 2 pi w D / k, corner cj + 1 - (sum 2 pi w D + tail')/k.
 * w->p and w->D must hold y's. */
int adh_visco_flow_psetup(adh_visco *w, const double *y, double cj)
{
    size_t n = w->n;
    double c = w->cinf / (1.0 + cj);
    w->p_cj = cj, w->p_ceff = c, w->p_mode = MODE_FLOW;
    memcpy(w->pD, w->D, n * sizeof *w->D);
    adh_visco_apply(w, w->pD, w->WD);
    if (!w->spring)
        return adh_visco_pre_factor(w->pre, c, w->pD, w->s.active_tol, 0, NULL, NULL, NULL);
    double sAD = 0, ts, C0, *B = w->bord, *C = w->bord + 2 * n;
    adh_visco_tail(w, y[w->IH], &ts);
    for (size_t i = 0; i < n; i++) {
        B[i] = c * w->WD[i];
        C[i] = w->area[i] * w->pD[i] / w->dr.spring;
        sAD += w->area[i] * w->pD[i];
    }
    C0 = cj + 1.0 - (sAD + ts) / w->dr.spring;
    return adh_visco_pre_factor(w->pre, c, w->pD, w->s.active_tol, 1, B, C, &C0);
}

void adh_visco_flow_psolve(adh_visco *w, const double *r, double *z)
{
    size_t n = w->n;
    double cj = w->p_cj, dt = r[w->IT] / cj, bdot = w->seg.bdot, xi[1] = { 0 }, rxi[1] = { 0 };
    adh_visco_psolve_q(w, r, z);
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = (r[i] - w->cdel * w->tmp2[i] - (w->spring ? 0 : w->cinf * bdot * dt * w->WD[i])) / (1.0 + cj);
    if (w->spring)
        rxi[0] = r[w->IH] + bdot * dt;
    adh_visco_pre_solve(w->pre, w->tmp, rxi, z, xi);
    z[w->IT] = dt;
    if (w->spring)
        z[w->IH] = xi[0];
}

/* Under a spring, the push along the tangent d is at least this many z0
 * in its (u, h0) part (the crossing's metric, theta |u'|^2 + h0'^2). At a
 * fold (t' = 0) that part is z0 and nothing changes; where the integrator
 * stopped short of one (path_stuck: the crossing from there is tried
 * first, and this is its fallback) d can be nearly all time: a soft
 * spring's path turns from the base's motion to the sphere's within
 * k / F'' of h0 (a femtometre at 1e-3 N/m, at the force minimum), and a
 * push along it moved the sphere by nothing, the relaxation came back
 * and the run stopped. A floor, not a rescaling of every push: a push of
 * a tenth of z0 in h0 throws a soft spring's sphere out of a stable
 * contact (at frozen u its h0 runs away at F_h0 / k), so the larger
 * pushes that test whether a root of t' was a fold stay the tangent's.
 * Without a spring the push is the tangent's, as it was. */
#define VISCO_PUSH_MIN 1e-3

static double push_of(const adh_visco *w, const double *d, double nudge)
{
    if (!w->spring)
        return nudge;
    double len = adh_visco_uh_length(w, d);
    return len > 0 ? fmax(nudge, VISCO_PUSH_MIN * w->m.z0 / len) : nudge;
}

int adh_visco_flow_start(adh_visco *w, const double *y, const double *d, double nudge, double *y0, double *yp0)
{
    memcpy(y0, y, w->len * sizeof *y);
    nudge = push_of(w, d, nudge);
    for (size_t i = 0; i < w->n; i++)
        y0[i] += nudge * d[i];
    if (w->spring)
        y0[w->IH] += nudge * d[w->IH];
    memset(yp0, 0, w->len * sizeof *yp0);
    if (adh_visco_flow_res(w, y0, yp0, w->bord) != 0)
        return ADH_ESTALL;
    for (size_t i = 0; i < w->n; i++)
        yp0[i] = -w->bord[i];
    if (w->spring)
        yp0[w->IH] = -w->bord[w->IH];
    return ADH_SUCCESS;
}

double adh_visco_flow_speed(const adh_visco *w, const double *d)
{
    const double *a = N_VGetArrayPointer(w->atol);
    double v = 0;
    for (size_t i = 0; i < w->n; i++)
        v = fmax(v, fabs(d[i]) / a[i]);
    if (w->spring)
        v = fmax(v, fabs(d[w->IH]) / a[w->IH]);
    return v;
}
