/* A jump's crossing (adhere/visco.h). At a fold of the path the stable
 * state is gone; the sphere reaches another one far faster than tau and
 * the drive, so q and the base are frozen while it does. As in the static
 * mode, the jump lands on the other branch of the equilibria: they are
 * followed from the fold along their own arclength in (u, h0),
 *     r_u = u + W (cinf p + cdel q(frozen))
 *     theta |u'|^2 + h0'^2 = z0^2,
 * to where the base's coordinate b = h0 - F/k (h0 without a spring) is
 * back at the fold's, after it has turned once (the S's other fold).
 * Under a spring h0 is its own unknown and the clock stands (tl' = 0);
 * without one h0 = b(tl) and tl is the parameter: in a dwell, where the
 * base stands, h0 is moved through tl at a virtual speed for the
 * crossing. Measured in (u, h0) the path is as smooth as the static
 * curve; measured with the base (h0 - F/k, which the force's small
 * wiggles move by F'/k) a soft spring would fold it into hairpins.
 *     no spring: y = (u, q, tl),     r_q = q',  r_t = the path's normalisation
 *     spring:    y = (u, q, tl, h0), r_q = q',  r_t = tl', r_h = the normalisation
 * The Newton matrix, q (and tl) eliminated, is J_u = I - cinf W diag(D)
 * bordered by the parameter's column and the normalisation's row. */
#include "visco.h"

#include <math.h>
#include <string.h>

#include "adhere/law.h"
#include "adhere/status.h"

/* The parameter's slot, dh0/dP, and the normalisation's row scale and
 * weight: P = h0 (spring) or tl. */
static size_t param(const adh_visco *w, double *gP, double *sc, double *wP)
{
    double vm = w->seg.vm, z0 = w->m.z0;
    if (w->spring) {
        *gP = 1, *sc = 1.0 / z0, *wP = 1;
        return w->IH;
    }
    /* the path's own normalisation, so that the switch at the fold (where
     * t' = 0) changes nothing but q' = 0 */
    *gP = w->seg.bdot, *sc = 1.0 / (vm * z0), *wP = vm * vm;
    return w->IT;
}

int adh_visco_cross_res(adh_visco *w, const double *y, const double *d, double *r)
{
    size_t n = w->n;
    const double *u = y, *q = y + w->IQ;
    double h0 = adh_visco_h0_of(w, y), gP, sc, wP, z0 = w->m.z0;
    size_t P = param(w, &gP, &sc, &wP);
    if (adh_visco_gaps(w, u, h0) < 0)
        return 1;
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = w->cinf * w->p[i] + w->cdel * q[i];
    adh_visco_apply(w, w->tmp, r);
    double uu = 0;
    for (size_t i = 0; i < n; i++) {
        r[i] += u[i];
        r[w->IQ + i] = d[w->IQ + i];
        uu += d[i] * d[i];
    }
    r[w->IT] = d[w->IT];
    /* (sc z0^2 / 2) (theta |u'|^2 + wP P'^2 - z0^2) / z0^2: the path's r_t without a spring */
    r[P] = 0.5 * sc * (w->theta * uu + wP * d[P] * d[P] - z0 * z0);
    return 0;
}

void adh_visco_cross_jtimes(adh_visco *w, const double *y, const double *d, const double *v, double *Jv,
                            double cj)
{
    size_t n = w->n;
    const double *vu = v, *vq = v + w->IQ;
    double gP, sc, wP, ud = 0;
    size_t P = param(w, &gP, &sc, &wP);
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = w->cinf * w->D[i] * (gP * v[P] - vu[i]) + w->cdel * vq[i];
    adh_visco_apply(w, w->tmp, Jv);
    for (size_t i = 0; i < n; i++) {
        Jv[i] += vu[i];
        Jv[w->IQ + i] = cj * vq[i];
        ud += d[i] * vu[i];
    }
    Jv[w->IT] = cj * v[w->IT];
    Jv[P] = cj * sc * (w->theta * ud + wP * d[P] * v[P]);
}

/* q (and tl) eliminated: J_u at cinf, bordered by cinf gP W D and the
 * normalisation's row cj sc theta u' (corner cj sc wP P'). w->p and w->D
 * must hold y's. */
int adh_visco_cross_psetup(adh_visco *w, const double *y, const double *d, double cj)
{
    size_t n = w->n;
    double gP, sc, wP, C0, *B = w->bord, *C = w->bord + 2 * n;
    size_t P = param(w, &gP, &sc, &wP);
    w->p_cj = cj, w->p_ceff = w->cinf, w->p_mode = MODE_CROSS;
    memcpy(w->pD, w->D, n * sizeof *w->D);
    adh_visco_apply(w, w->pD, w->WD);
    for (size_t i = 0; i < n; i++) {
        B[i] = w->cinf * gP * w->WD[i];
        C[i] = cj * sc * w->theta * d[i];
    }
    C0 = cj * sc * wP * d[P];
    return adh_visco_pre_factor(w->pre, w->cinf, w->pD, w->s.active_tol, 1, B, C, &C0);
}

void adh_visco_cross_psolve(adh_visco *w, const double *r, double *z)
{
    size_t n = w->n;
    double cj = w->p_cj, gP, sc, wP, xi[1] = { 0 }, rxi[1];
    size_t P = param(w, &gP, &sc, &wP);
    adh_visco_psolve_q(w, r, z);
    for (size_t i = 0; i < n; i++)
        w->tmp[i] = r[i] - w->cdel * w->tmp2[i];
    if (w->spring)
        z[w->IT] = r[w->IT] / cj;
    rxi[0] = r[P];
    adh_visco_pre_solve(w->pre, w->tmp, rxi, z, xi);
    z[P] = xi[0];
}

void adh_visco_cross_start(adh_visco *w, const double *d, double *yp0)
{
    memcpy(yp0, d, w->len * sizeof *d);
    memset(yp0 + w->IQ, 0, w->n * sizeof *yp0);
    if (!w->spring)
        return;
    yp0[w->IT] = 0;
    /* at a fold (t' = 0) the (u, h0) part is z0 long, the crossing's
     * normalisation, and h0 moves the drive's way (through a spring's fold
     * h0 goes on as it went: the fold is the base's, where dF/dh0 = k);
     * from short of one (the integrator stopped in a soft spring's turn,
     * its tangent nearly all time, or past the fold) it is scaled to z0
     * and turned the drive's way */
    double len = adh_visco_uh_length(w, d), z0 = w->m.z0;
    double sc = len > 0 && len < 0.5 * z0 ? z0 / len : 1.0;
    if (d[w->IH] * w->cross_dir < 0)
        sc = -sc;
    if (sc != 1.0) {
        for (size_t i = 0; i < w->n; i++)
            yp0[i] *= sc;
        yp0[w->IH] *= sc;
    }
}

double adh_visco_cross_base(const adh_visco *w, const double *y)
{
    double h0 = adh_visco_h0_of(w, y);
    if (!w->spring)
        return h0;
    double F = adh_visco_tail(w, h0, NULL);
    for (size_t i = 0; i < w->n; i++)
        F += w->area[i] * adh_lj_pressure(h0 + w->shape[i] - y[i], w->m.A, w->m.z0);
    return h0 - F / w->dr.spring;
}

/* Phase 1: the turn of b = h0 - F/k along the crossing (db/ds = 0);
 * phase 2: b back at the fold's. */
void adh_visco_cross_roots(adh_visco *w, const double *y, const double *d, double *g)
{
    if (w->phase == 1) {
        double h0s = w->spring ? d[w->IH] : w->seg.bdot * d[w->IT];
        g[ROOT_FOLD] = h0s - (w->spring ? adh_visco_force_rate(w, y, d) / w->dr.spring : 0);
    } else {
        g[ROOT_END] = adh_visco_cross_base(w, y) - w->b_fold;
    }
}
