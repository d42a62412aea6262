#include "adhere/grid.h"

#include <math.h>
#include <stdlib.h>

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
