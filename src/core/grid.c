#include "adhere/grid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"

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
             "grid spacing %s is coarser than the resolved limit %s at sigma = %.3g (%.2g widths of "
             "the contact's edge zone, %s; this grid has %.2f nodes across it): pull-off, jump-in and "
             "hysteresis may be off by more than 1 %%",
             adh_qtext(r->dr, ADH_Q_LENGTH).s, adh_qtext(r->max_spacing, ADH_Q_LENGTH).s, r->sigma, r->limit, adh_qtext(r->edge, ADH_Q_LENGTH).s, r->edge_nodes);
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
