/* Energies of the viscoelastic solver's states (adhere/visco.h), and the
 * instrument's jumps on an elastic curve. */
#include "visco.h"

#include <math.h>
#include <string.h>

#include "adhere/law.h"
#include "adhere/observe.h"

/* <a, W a> in the area-weighted inner product (w->tmp2 its scratch): the
 * elastic energies here, the viscous dissipation of the IDAS path and of
 * the Rothe steps. */
double adh_visco_energy_norm(adh_visco *w, const double *a)
{
    adh_visco_apply(w, a, w->tmp2);
    double e = 0;
    for (size_t i = 0; i < w->n; i++)
        e += w->area[i] * a[i] * w->tmp2[i];
    return e;
}

/* The surface energy beyond Rmax, undeformed: 2 pi R int_se^inf w(s) ds
 * with w the law's energy per area (adh_lj_energy), se the edge gap; its
 * h0-derivative is minus adh_force_tail. */
static double tail_energy(const adh_visco *w, double h0)
{
    double se = h0 + w->g->rmax * w->g->rmax / (2.0 * w->m.R);
    if (!(se > 0))
        return 0;
    double AR = w->m.A * w->m.R, z6 = pow(w->m.z0, 6);
    return -AR / (6.0 * se) + AR * z6 / (168.0 * pow(se, 7));
}

double adh_visco_energy_of(adh_visco *w, const double *y, double *el, double *surf, double *spr)
{
    double h0 = adh_visco_h0_of(w, y);
    if (adh_visco_gaps(w, y, h0) < 0)
        return NAN;
    double F = adh_visco_force(w, h0), Us = tail_energy(w, h0);
    for (size_t i = 0; i < w->n; i++)
        Us += w->area[i] * adh_lj_energy(w->h[i], w->m.A, w->m.z0);
    double Ue = 0.5 * w->cinf * adh_visco_energy_norm(w, w->p);
    if (w->cdel > 0)
        Ue += 0.5 * w->cdel * adh_visco_energy_norm(w, y + w->IQ);
    double Uk = w->spring ? F * F / (2.0 * w->dr.spring) : 0;
    if (el)
        *el = Ue;
    if (surf)
        *surf = Us;
    if (spr)
        *spr = Uk;
    return Ue + Us + Uk;
}

double adh_visco_stored(const adh_visco *w, double *elastic, double *surface, double *spring)
{
    adh_visco *mw = (adh_visco *)w; /* scratch buffers only */
    const double *y = N_VGetArrayPointer(w->y);
    return adh_visco_energy_of(mw, y, elastic, surface, spring);
}

/* Where b = h0 - F/k turns along the rows i-1, i, i+1: the parabola
 * through them in the distance along (h0, F/k); h0 there. */
static double turn_of_base(const adh_obs *r, double k, double *base)
{
    double x[3] = { 0 }, b[3], h[3];
    for (int j = 0; j < 3; j++) {
        b[j] = r[j].h0 - r[j].F / k;
        h[j] = r[j].h0;
        if (j)
            x[j] = x[j - 1] + hypot(r[j].h0 - r[j - 1].h0, (r[j].F - r[j - 1].F) / k);
    }
    double d1 = (b[1] - b[0]) / (x[1] - x[0]), d2 = (b[2] - b[1]) / (x[2] - x[1]);
    double c = (d2 - d1) / (x[2] - x[0]), bb = d1 + c * (x[1] - x[0]);
    double t = c != 0 ? x[1] - bb / (2 * c) : x[1];
    t = fmin(x[2], fmax(x[0], t));
    *base = b[1] + bb * (t - x[1]) + c * (t - x[1]) * (t - x[1]);
    double e1 = (h[1] - h[0]) / (x[1] - x[0]), e2 = (h[2] - h[1]) / (x[2] - x[1]);
    double ch = (e2 - e1) / (x[2] - x[0]), bh = e1 + ch * (x[1] - x[0]);
    return h[1] + bh * (t - x[1]) + ch * (t - x[1]) * (t - x[1]);
}

size_t adh_visco_spring_folds(const adh_run *curve, double k, double *at, double *base, size_t max)
{
    size_t found = 0;
    for (size_t i = 1; i + 1 < curve->nrows; i++) {
        const adh_obs *r = &curve->rows[i - 1];
        if (r[0].path != r[1].path || r[1].path != r[2].path)
            continue;
        double b0 = r[0].h0 - r[0].F / k, b1 = r[1].h0 - r[1].F / k, b2 = r[2].h0 - r[2].F / k;
        if (!((b1 - b0) * (b2 - b1) < 0))
            continue;
        double b;
        if (found < max) {
            at[found] = turn_of_base(r, k, &b);
            if (base)
                base[found] = b;
        }
        found++;
    }
    return found;
}

/* The base h0 - F/k of a row. */
static double base_of_row(const adh_obs *r, double k)
{
    return r->h0 - r->F / k;
}

double adh_visco_spring_snap_out(const adh_run *curve, double k, double *base)
{
    double h0 = NAN, b = NAN;
    size_t n = curve->nrows;
    /* the rows of the curve's last path, from the turn outward: i the
     * sphere's row, the base rising as it follows them */
    size_t first = n;
    while (first > 0 && curve->rows[first - 1].path == curve->rows[n - 1].path)
        first--;
    size_t i = n >= 2 ? n - 2 : 0;
    while (i > first && i + 1 < n) {
        const adh_obs *r = &curve->rows[i - 1];
        double b0 = base_of_row(&r[0], k), b1 = base_of_row(&r[1], k), b2 = base_of_row(&r[2], k);
        if (!((b1 - b0) * (b2 - b1) < 0 && b1 > b0)) {
            i--;
            continue;
        }
        /* a fold: the sphere lands on the first row further out whose
         * base is back at the fold's; in contact, the contact line
         * snapped across a lattice fold (a ring) and it goes on from
         * there; out of contact, or beyond the curve's start, it is the
         * snap-out */
        double bf, hf = turn_of_base(r, k, &bf);
        size_t j = i - 1;
        while (j > first && base_of_row(&curve->rows[j], k) < bf)
            j--;
        if (base_of_row(&curve->rows[j], k) < bf || !(curve->rows[j].a > 0)) {
            h0 = hf, b = bf;
            break;
        }
        i = j;
    }
    if (base)
        *base = b;
    return h0;
}

double adh_visco_balance_residual(const adh_visco_result *r)
{
    const adh_visco_energy *c = &r->cycle;
    return r->hysteresis - c->dissipated - c->jumps - (c->stored - c->stored0);
}

double adh_visco_balance_open(const adh_visco_result *r)
{
    if (isnan(r->hysteresis))
        return NAN;
    return adh_visco_balance_residual(r) / fabs(r->hysteresis);
}
