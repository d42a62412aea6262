#include "adhere/rings.h"

#include "adhere/models.h"
#include "adhere/status.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int adh_rings_spec_validate(const adh_rings_spec *s, char *why, size_t whylen)
{
    if (!(isfinite(s->dr) && s->dr > 0)) {
        snprintf(why, whylen, "fine ring width %g m is not allowed: it must be above 0", s->dr);
        return ADH_EINVAL;
    }
    if (!(isfinite(s->fine) && s->fine >= s->dr)) {
        snprintf(why, whylen, "fine band radius %g m is not allowed: it must be at least one fine ring (%g m)", s->fine, s->dr);
        return ADH_EINVAL;
    }
    if (!(s->ratio >= 1.0 && s->ratio <= ADH_RINGS_MAX_RATIO)) {
        snprintf(why, whylen, "ring growth ratio %g is not allowed: it must be from 1 to %g", s->ratio, ADH_RINGS_MAX_RATIO);
        return ADH_EINVAL;
    }
    if (!(isfinite(s->rmax) && s->rmax >= s->fine)) {
        snprintf(why, whylen, "grid radius %g m is not allowed: it must be at least the fine band's %g m", s->rmax, s->fine);
        return ADH_EINVAL;
    }
    /* Bounds the ring count: a ratio of 1 past the band is a uniform grid. */
    if (s->rmax / s->dr > 1e8) {
        snprintf(why, whylen, "grid radius %g m over fine width %g m is %g rings wide: at most 1e8 is allowed",
                 s->rmax, s->dr, s->rmax / s->dr);
        return ADH_EINVAL;
    }
    return ADH_SUCCESS;
}

/* Walks the edges; fills edge[] when it is not NULL. */
static size_t walk(const adh_rings_spec *s, double *edge)
{
    size_t nf = (size_t)ceil(s->fine / s->dr - 1e-9), n = 0;
    double e = 0, w = s->dr;
    if (edge)
        edge[0] = 0;
    for (; n < nf; n++) {
        e = (double)(n + 1) * s->dr;
        if (edge)
            edge[n + 1] = e;
    }
    while (e < s->rmax * (1 - 1e-12)) {
        w *= s->ratio;
        e += w;
        n++;
        if (edge)
            edge[n] = e;
    }
    return n;
}

size_t adh_rings_count(const adh_rings_spec *s)
{
    char why[8];
    return adh_rings_spec_validate(s, why, sizeof why) == 0 ? walk(s, NULL) : 0;
}

static adh_grid *grid_of(size_t n)
{
    adh_grid *g = calloc(1, sizeof *g);
    if (!g)
        return NULL;
    /* One block, as adh_grid_free frees r alone. */
    g->r = malloc((2 * n + 1) * sizeof *g->r);
    if (!g->r) {
        free(g);
        return NULL;
    }
    g->edge = g->r + n;
    g->n = n;
    g->graded = 1;
    return g;
}

/* Nodes at ring middles; dr the finest ring. */
static void finish(adh_grid *g)
{
    double dmin = INFINITY;
    for (size_t i = 0; i < g->n; i++) {
        g->r[i] = 0.5 * (g->edge[i] + g->edge[i + 1]);
        dmin = fmin(dmin, g->edge[i + 1] - g->edge[i]);
    }
    g->dr = dmin;
    g->rmax = g->edge[g->n];
}

adh_grid *adh_rings_alloc(const adh_rings_spec *s)
{
    size_t n = adh_rings_count(s);
    adh_grid *g = n ? grid_of(n) : NULL;
    if (!g)
        return NULL;
    walk(s, g->edge);
    finish(g);
    return g;
}

adh_grid *adh_rings_alloc_edges(size_t n, const double *edge)
{
    if (n == 0 || edge[0] != 0)
        return NULL;
    for (size_t i = 0; i < n; i++)
        if (!(edge[i + 1] > edge[i]) || !isfinite(edge[i + 1]))
            return NULL;
    adh_grid *g = grid_of(n);
    if (!g)
        return NULL;
    for (size_t i = 0; i <= n; i++)
        g->edge[i] = edge[i];
    finish(g);
    return g;
}

double adh_rings_edge(const adh_grid *g, size_t j)
{
    return g->graded ? g->edge[j] : (double)j * g->dr;
}

double adh_rings_width(const adh_grid *g, size_t i)
{
    return g->graded ? g->edge[i + 1] - g->edge[i] : g->dr;
}

double adh_rings_weight(const adh_grid *g, size_t i)
{
    return g->r[i] * adh_rings_width(g, i);
}

size_t adh_rings_locate(const adh_grid *g, double r)
{
    if (!(r > 0))
        return ADH_SUCCESS;
    if (!g->graded) {
        double i = floor(r / g->dr);
        return i >= (double)g->n ? g->n - 1 : (size_t)i;
    }
    size_t lo = 0, hi = g->n; /* edge[lo] <= r < edge[hi] */
    if (r >= g->edge[g->n])
        return g->n - 1;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (g->edge[mid] <= r)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

void adh_rings_change_weights(const adh_grid *g, double *wt)
{
    for (size_t i = 0; i < g->n; i++)
        wt[i] = g->graded ? adh_rings_width(g, i) / g->dr : 1.0;
}

double adh_rings_change_of(const adh_grid *g, double weighted_ssq)
{
    return sqrt(weighted_ssq) / (g->graded ? g->rmax / g->dr : (double)g->n);
}

double adh_rings_change(const adh_grid *g, const double *du)
{
    double ssq = 0;
    if (!g->graded) {
        for (size_t i = 0; i < g->n; i++)
            ssq += du[i] * du[i];
    } else {
        for (size_t i = 0; i < g->n; i++)
            ssq += adh_rings_width(g, i) / g->dr * du[i] * du[i];
    }
    return adh_rings_change_of(g, ssq);
}

double adh_rings_fine_radius(const adh_grid *g)
{
    if (!g->graded)
        return g->rmax;
    size_t i = 0;
    while (i < g->n && g->edge[i + 1] - g->edge[i] <= g->dr * (1 + 1e-9))
        i++;
    return g->edge[i];
}

int adh_rings_resolves(const adh_grid *g, double a)
{
    return !g->graded || a < adh_rings_fine_radius(g);
}

double adh_rings_contact_estimate(const adh_material *m, double h0)
{
    double overlap = m->z0 - h0, est = 1.5 * sqrt(2.0 * m->R * fmax(0.0, overlap));
    /* JKR's overlap rises with a past its fold a_f: bisect on [a_f, hi]. */
    double Es = 0.5 * m->E, gamma = adh_material_gamma(m), F, ov;
    double lo = cbrt(M_PI * gamma * m->R * m->R / (8.0 * Es)), hi = lo;
    for (int i = 0; i < 200; i++) {
        adh_jkr(m, hi, &F, &ov);
        if (!(ov < overlap))
            break;
        hi *= 2;
    }
    adh_jkr(m, lo, &F, &ov);
    if (!(ov < overlap)) /* the contact is out past JKR's fold */
        return est;
    for (int i = 0; i < 100; i++) {
        double mid = 0.5 * (lo + hi);
        adh_jkr(m, mid, &F, &ov);
        if (ov < overlap)
            lo = mid;
        else
            hi = mid;
    }
    return fmax(est, hi);
}

int adh_rings_check(const adh_grid *g, const adh_material *m, double lowest, char *why, size_t whylen)
{
    if (!g->graded)
        return ADH_SUCCESS;
    double a_est = adh_rings_contact_estimate(m, lowest), fine = adh_rings_fine_radius(g);
    if (a_est > 0.9 * fine) {
        snprintf(why, whylen, "fine band radius %g m is too short: the contact at h0 = %g m may reach %g m, and its edge must stay inside the band; use a larger --fine-band",
                 fine, lowest, a_est);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}

void adh_rings_edge_sentence(const adh_grid *g, double a, char *buf, size_t len)
{
    if (a >= 0.9 * g->rmax)
        snprintf(buf, len, "the contact radius a = %.4g m reached the grid's edge (0.9 Rmax = %.4g m): use more "
                 "nodes or a larger spacing (-N, --spacing; a graded grid: --grid-radius)", a, 0.9 * g->rmax);
    else if (!adh_rings_resolves(g, a))
        snprintf(buf, len, "the contact radius a = %.4g m left the graded grid's fine band (%.4g m), where the rings "
                 "grow too coarse for the contact's edge: widen it (--fine-band) or turn shallower", a,
                 adh_rings_fine_radius(g));
    else
        snprintf(buf, len, "the contact radius a = %.4g m is within the grid (Rmax = %.4g m)", a, g->rmax);
}
