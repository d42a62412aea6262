#include "adhere/grid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/models.h"
#include "adhere/rings.h"
#include "adhere/status.h"

/* The paper's grid, 1.5 nm at R = 10 um and z0 = 0.5 nm, is 0.0212 sqrt(R z0):
 * lateral lengths scale with sqrt(R z0), so this keeps the same nodes per
 * contact zone at every size (a fixed 1.5 nm would be useless at R = 1.5 cm). */
double adh_grid_default_spacing(const adh_material *m)
{
    const double ref = 1.5e-9 / sqrt(10e-6 * 0.5e-9);
    return ref * sqrt(m->R * m->z0);
}

double adh_grid_default_rmax(const adh_material *m)
{
    return 1000.0 * adh_grid_default_spacing(m);
}

double adh_grid_spacing_for(const adh_material *m, size_t n)
{
    return fmin(adh_grid_default_rmax(m), 0.3 * m->R) / (double)n;
}

double adh_grid_edge_spacing(adh_grid_use use)
{
    return use == ADH_GRID_STATIC ? ADH_GRID_EDGE_SPACING_STATIC : ADH_GRID_EDGE_SPACING_RELAX;
}

void adh_grid_check(const adh_material *m, adh_grid_use use, size_t n, double dr, adh_grid_report *r)
{
    adh_derived d;
    adh_material_derive(m, &d);
    r->n = n;
    r->dr = dr;
    r->rmax = (double)n * dr;
    r->sigma = d.sigma;
    r->edge = adh_edge_zone(m);
    r->edge_nodes = r->edge / dr;
    r->limit = adh_grid_edge_spacing(use);
    r->max_spacing = r->limit * r->edge;
    /* a relative margin so the limit's own rounding never flips the flag */
    r->resolved = dr <= r->max_spacing * (1 + 1e-9);
    r->kernel_bytes = (double)n * (double)n * sizeof(double);
}

void adh_grid_unresolved_sentence(const adh_grid_report *r, char *buf, size_t len)
{
    snprintf(buf, len,
             "grid spacing %.3g m is coarser than the resolved limit %.3g m at sigma = %.3g (%.2g widths of "
             "the contact's edge zone, %.3g m; this grid has %.2f nodes across it): pull-off, jump-in and "
             "hysteresis may be off by more than 1 %%",
             r->dr, r->max_spacing, r->sigma, r->limit, r->edge, r->edge_nodes);
}

/* The contact radius at the deepest position, generously: JKR's a for the
 * overlap z0 - deepest (adhesion enlarges it beyond Hertz's), or the
 * protocol check's Hertz-based estimate, whichever is larger. */
static double contact_estimate(const adh_material *m, double deepest)
{
    double depth = fmax(m->z0 - deepest, m->z0);
    double lo = 0, hi = 10 * sqrt(2 * m->R * depth) + 10 * sqrt(m->R * m->z0);
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi), ov;
        adh_jkr(m, mid, NULL, &ov);
        if (ov < depth)
            lo = mid;
        else
            hi = mid;
    }
    return fmax(hi, 1.5 * sqrt(2.0 * m->R * depth));
}

/* MB a kernel holds: dense N^2 doubles, or as H^2 ~1.3 kB a ring
 * (measured: docs/grids-and-operators.md) */
static double held_mb(int hierarchical, double nodes)
{
    return hierarchical ? 1.3e3 * nodes / 1048576.0 : nodes * nodes * sizeof(double) / 1048576.0;
}

int adh_grid_choose(const adh_material *m, adh_grid_use use, double deepest, int graded_ok, adh_grid_choice *c,
                    char *why, size_t whylen)
{
    double paper_rmax = fmin(adh_grid_default_rmax(m), 0.3 * m->R);
    double widths = adh_grid_edge_spacing(use);
    double limit = widths * adh_edge_zone(m);
    adh_derived d;
    adh_material_derive(m, &d);
    *c = (adh_grid_choice){ .graded = 0, .n = 1000, .dr = NAN, .fine = NAN, .ratio = 1, .rmax = paper_rmax };
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
                 "to Rmax = %.3g m, beyond 0.3 R = %.3g m where the paraboloid gap (eq 3) stops describing a "
                 "sphere; use a larger R, a shallower turn (the deepest is %.3g m), or a stiffer material",
                 d.sigma, need, 0.3 * m->R, deepest);
        return ADH_EGRID;
    }
    if (nn > budget) {
        snprintf(why, whylen,
                 "sigma = %.3g needs a grid spacing of at most %.3g m (%.2g edge-zone widths of %.3g m) "
                 "out to Rmax = %.3g m: a %s grid of N = %zu nodes (%s of %.0f MB), beyond this program's "
                 "budget of N = %zu (%.0f MB); use a stiffer material or a smaller sigma, or give -N/--spacing "
                 "yourself with --force (the run is then marked resolved 0)",
                 d.sigma, limit, widths, adh_edge_zone(m), c->rmax, kind, nn,
                 c->hierarchical ? "an H^2 kernel" : "a dense kernel", held, budget, held_max);
        return ADH_EGRID;
    }
    if (use == ADH_GRID_STATIC && nn > ADH_GRID_STATIC_MAX_NODES) {
        snprintf(why, whylen,
                 "sigma = %.3g: a resolved static curve needs a grid spacing of at most %.3g m (%.2g edge-zone "
                 "widths of %.3g m), a %s grid of N = %zu nodes (%.0f MB kernel), and its Newton steps, "
                 "though they step the contact line over many rings at once, cost more with N: beyond N = %d "
                 "(19 s on one core at sigma = 100, 12875 rings) it was not measured; use --mode=relax "
                 "(resolved at this sigma), a stiffer material, or give -N/--spacing yourself with --force (the "
                 "run is then marked resolved 0 if the grid is coarser than the limit)",
                 d.sigma, limit, widths, adh_edge_zone(m), kind, nn, held, ADH_GRID_STATIC_MAX_NODES);
        return ADH_EGRID;
    }
    return ADH_SUCCESS;
}

adh_grid *adh_grid_alloc(size_t n, double dr)
{
    if (n == 0 || !(dr > 0))
        return NULL;
    adh_grid *g = calloc(1, sizeof *g); /* graded = 0, edge = NULL: uniform */
    if (!g)
        return NULL;
    g->r = malloc(n * sizeof *g->r);
    if (!g->r) {
        free(g);
        return NULL;
    }
    g->n = n;
    g->dr = dr;
    g->rmax = (double)n * dr;
    for (size_t i = 0; i < n; i++)
        g->r[i] = ((double)i + 0.5) * dr;
    return g;
}

void adh_grid_free(adh_grid *g)
{
    if (!g)
        return;
    free(g->r);
    free(g);
}

int adh_grid_nodes_check(long n, char *why, size_t whylen)
{
    if (n >= ADH_GRID_NODES_MIN && n <= ADH_GRID_NODES_MAX)
        return ADH_SUCCESS;
    snprintf(why, whylen, "N = %ld nodes is not allowed: use %d to %d nodes", n, ADH_GRID_NODES_MIN, ADH_GRID_NODES_MAX);
    return ADH_EINVAL;
}
