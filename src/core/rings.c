#include "adhere/rings.h"

#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int adh_rings_spec_validate(const adh_rings_spec *s, char *why, size_t whylen)
{
    if (!(isfinite(s->dr) && s->dr > 0)) {
        snprintf(why, whylen, "fine ring width %s is not allowed: it must be above 0", adh_qtext(s->dr, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    if (!(isfinite(s->fine) && s->fine >= s->dr)) {
        snprintf(why, whylen, "fine band radius %s is not allowed: it must be at least one fine ring (%s)", adh_qtext(s->fine, ADH_Q_LENGTH).s, adh_qtext(s->dr, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    if (!(s->ratio >= 1.0 && s->ratio <= ADH_RINGS_MAX_RATIO)) {
        snprintf(why, whylen, "ring growth ratio %g is not allowed: it must be from 1 to %g", s->ratio, ADH_RINGS_MAX_RATIO);
        return ADH_EINVAL;
    }
    if (!(isfinite(s->rmax) && s->rmax >= s->fine)) {
        snprintf(why, whylen, "grid radius %s is not allowed: it must be at least the fine band's %s", adh_qtext(s->rmax, ADH_Q_LENGTH).s, adh_qtext(s->fine, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    /* Bounds the ring count: a ratio of 1 past the band is a uniform grid. */
    if (s->rmax / s->dr > 1e8) {
        snprintf(why, whylen, "grid radius %s over fine width %s is %g rings wide: at most 1e8 is allowed",
                 adh_qtext(s->rmax, ADH_Q_LENGTH).s, adh_qtext(s->dr, ADH_Q_LENGTH).s, s->rmax / s->dr);
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

void adh_rings_change_weights(const adh_grid *g, double rclip, double *wt)
{
    for (size_t i = 0; i < g->n; i++) {
        double a = adh_rings_edge(g, i), b = adh_rings_edge(g, i + 1);
        if (b <= rclip)
            wt[i] = g->graded ? adh_rings_width(g, i) / g->dr : 1.0;
        else
            wt[i] = a < rclip ? (rclip - a) / g->dr : 0.0;
    }
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
    /* JKR's radius (adhesion enlarges it beyond Hertz's), or 1.5 Hertz's
     * where that is larger or JKR has no contact */
    double overlap = m->z0 - h0, est = 1.5 * sqrt(2.0 * m->R * fmax(0.0, overlap));
    return fmax(est, adh_jkr_radius(m, overlap));
}

static void set_fix(unsigned *fix, unsigned bits)
{
    if (fix)
        *fix = bits;
}

int adh_rings_check(const adh_grid *g, const adh_material *m, double lowest, char *why, size_t whylen,
                    unsigned *fix)
{
    set_fix(fix, 0);
    if (!g->graded)
        return ADH_SUCCESS;
    double a_est = adh_rings_contact_estimate(m, lowest), fine = adh_rings_fine_radius(g);
    if (a_est > 0.9 * fine) {
        snprintf(why, whylen, "fine band radius %s is too short: the contact at h0 = %s may reach %s, and its edge must stay inside the band; use a larger fine band",
                 adh_qtext(fine, ADH_Q_LENGTH).s, adh_qtext(lowest, ADH_Q_LENGTH).s, adh_qtext(a_est, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_FINE_BAND);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}

unsigned adh_rings_edge_fix(const adh_grid *g, double a)
{
    if (a >= 0.9 * g->rmax)
        return g->graded ? ADH_FIX_GRID_RADIUS : ADH_FIX_NODES | ADH_FIX_SPACING;
    return adh_rings_resolves(g, a) ? 0 : ADH_FIX_FINE_BAND | ADH_FIX_TURNS;
}

void adh_rings_edge_sentence(const adh_grid *g, double a, char *buf, size_t len)
{
    if (a >= 0.9 * g->rmax)
        snprintf(buf, len, "the contact radius a = %s reached the grid's edge (0.9 Rmax = %s): use %s", adh_qtext(a, ADH_Q_LENGTH).s,
                 adh_qtext(0.9 * g->rmax, ADH_Q_LENGTH).s, g->graded ? "a larger grid radius" : "more nodes or a larger spacing");
    else if (!adh_rings_resolves(g, a))
        snprintf(buf, len, "the contact radius a = %s left the graded grid's fine band (%s), where the rings "
                 "grow too coarse for the contact's edge: widen the fine band or turn shallower", adh_qtext(a, ADH_Q_LENGTH).s,
                 adh_qtext(adh_rings_fine_radius(g), ADH_Q_LENGTH).s);
    else
        snprintf(buf, len, "the contact radius a = %s is within the grid (Rmax = %s)", adh_qtext(a, ADH_Q_LENGTH).s, adh_qtext(g->rmax, ADH_Q_LENGTH).s);
}

/* The contact radius at the deepest position, generously: JKR's a for the
 * overlap z0 - deepest (adhesion enlarges it beyond Hertz's), or the
 * protocol check's Hertz-based estimate, whichever is larger. */
static double contact_estimate(const adh_material *m, double deepest)
{
    double depth = fmax(m->z0 - deepest, m->z0);
    return fmax(adh_jkr_radius(m, depth), 1.5 * sqrt(2.0 * m->R * depth));
}

/* MB a kernel holds: dense N^2 doubles, or as H^2 ~1.3 kB a ring
 * (measured: docs/grids-and-operators.md) */
static double held_mb(int hierarchical, double nodes)
{
    return hierarchical ? 1.3e3 * nodes / 1048576.0 : nodes * nodes * sizeof(double) / 1048576.0;
}

int adh_rings_choose(const adh_material *m, adh_grid_use use, double deepest, int graded_ok, adh_rings_choice *c,
                     char *why, size_t whylen, unsigned *fix)
{
    double paper_rmax = fmin(adh_grid_default_rmax(m), 0.3 * m->R);
    double widths = adh_grid_edge_spacing(use);
    double limit = widths * adh_edge_zone(m);
    adh_derived d;
    adh_material_derive(m, &d);
    set_fix(fix, 0);
    *c = (adh_rings_choice){ .graded = 0, .n = 1000, .dr = NAN, .fine = NAN, .ratio = 1, .rmax = paper_rmax };
    if (paper_rmax / 1000.0 <= limit)
        return ADH_SUCCESS;
    /* the radius the protocol check asks for: the contact within 0.8 Rmax,
     * the gap at the edge 10 z0 wide and the force beyond it below 1e-3 of
     * 2 pi gamma R (gap over 36.5 z0) */
    double a = contact_estimate(m, deepest);
    double gap = 36.6 * m->z0 - fmin(deepest, 0.0);
    double need = fmax(a / 0.8 * 1.05, sqrt(2.0 * m->R * gap));
    /* a finer grid than the paper's costs N^2: only as far out as needed */
    size_t nn = (size_t)ceil(need / limit);
    const char *kind = "uniform";
    if (nn <= ADH_GRID_UNIFORM_MAX_NODES || !graded_ok) {
        c->n = nn < 10 ? 10 : nn;
        c->dr = need / (double)c->n;
        c->rmax = need;
    } else {
        /* Only the band the contact line sweeps needs the fine spacing; the
         * rings grow beyond it as adhere/rings.h allows. */
        kind = "graded";
        adh_rings_spec s = { .dr = limit, .ratio = 1.05 };
        s.fine = 1.25 * adh_rings_contact_estimate(m, fmin(deepest, 0.0));
        s.rmax = fmax(need, 1.1 * s.fine);
        c->graded = 1;
        c->dr = limit;
        c->fine = s.fine;
        c->ratio = s.ratio;
        c->rmax = s.rmax;
        c->hierarchical = 1;
        nn = adh_rings_count(&s);
        c->n = nn;
    }
    /* a dense kernel's memory bounds a uniform grid; graded rings are held
     * as H^2 (~1.3 kB a ring), bounded by the grid limit alone */
    size_t budget = c->hierarchical ? ADH_GRID_NODES_MAX : ADH_GRID_MAX_NODES;
    double held = held_mb(c->hierarchical, (double)nn);
    double held_max = held_mb(c->hierarchical, (double)budget);
    if (need > 0.3 * m->R) {
        /* not the node budget: the paraboloid gap (eq 3) stops describing a
         * sphere past 0.3 R, and the contact or the force's tail needs more */
        snprintf(why, whylen,
                 "sigma = %.3g: the contact at the deepest turn and the force's tail beyond it need the grid out "
                 "to Rmax = %s, beyond 0.3 R = %s where the paraboloid gap (eq 3) stops describing a "
                 "sphere; use a larger R, a shallower turn (the deepest is %s), or a stiffer material",
                 d.sigma, adh_qtext(need, ADH_Q_LENGTH).s, adh_qtext(0.3 * m->R, ADH_Q_LENGTH).s, adh_qtext(deepest, ADH_Q_LENGTH).s);
        set_fix(fix, ADH_FIX_RADIUS | ADH_FIX_TURNS);
        return ADH_EGRID;
    }
    if (nn > budget) {
        snprintf(why, whylen,
                 "sigma = %.3g needs a grid spacing of at most %s (%.2g edge-zone widths of %s) "
                 "out to Rmax = %s: a %s grid of N = %zu nodes (%s of %.0f MB), beyond this program's "
                 "budget of N = %zu (%.0f MB). A grid chosen by hand runs marked resolved 0 where it is "
                 "coarser than the resolved limit; use a stiffer material or a smaller sigma, or choose N or "
                 "the spacing yourself and run it anyway",
                 d.sigma, adh_qtext(limit, ADH_Q_LENGTH).s, widths, adh_qtext(adh_edge_zone(m), ADH_Q_LENGTH).s, adh_qtext(c->rmax, ADH_Q_LENGTH).s, kind, nn,
                 c->hierarchical ? "an H^2 kernel" : "a dense kernel", held, budget, held_max);
        set_fix(fix, ADH_FIX_NODES | ADH_FIX_SPACING | ADH_FIX_FORCE);
        return ADH_EGRID;
    }
    if (use == ADH_GRID_STATIC && nn > ADH_GRID_STATIC_MAX_NODES) {
        snprintf(why, whylen,
                 "sigma = %.3g: a resolved static curve needs a grid spacing of at most %s (%.2g edge-zone "
                 "widths of %s), a %s grid of N = %zu nodes (%.0f MB kernel), and its Newton steps, "
                 "though they step the contact line over many rings at once, cost more with N: beyond N = %d "
                 "(19 s on one core at sigma = 100, 12875 rings) it was not measured. A grid chosen by hand "
                 "runs marked resolved 0 where it is coarser than the limit; use the relaxation (resolved at "
                 "this sigma), a stiffer material, or choose N or the spacing yourself and run it anyway",
                 d.sigma, adh_qtext(limit, ADH_Q_LENGTH).s, widths, adh_qtext(adh_edge_zone(m), ADH_Q_LENGTH).s, kind, nn, held, ADH_GRID_STATIC_MAX_NODES);
        set_fix(fix, ADH_FIX_MODE | ADH_FIX_NODES | ADH_FIX_SPACING | ADH_FIX_FORCE);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}
