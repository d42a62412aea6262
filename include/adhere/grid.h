/* The radial grid r_n = (n - 1/2) dr, n = 1..N (paper section B). */
#ifndef ADHERE_GRID_H
#define ADHERE_GRID_H

#include <stddef.h>
#include "adhere/params.h"

typedef struct adh_grid {
    size_t n;      /* number of nodes N */
    double dr;     /* spacing Delta, m */
    double rmax;   /* N * dr, m */
    double *r;     /* node radii, length n */
    /* A graded grid (adhere/rings.h) has rings of arbitrary edges, node n at
     * the middle of ring [edge[n], edge[n+1]]; dr is then its finest ring
     * width. Zero and NULL here: the uniform grid above, edge[n] = n dr. */
    int graded;
    double *edge;  /* length n + 1 when graded, in the block of r */
} adh_grid;

/* The paper's Delta = 1.5 nm at R = 10 um, z0 = 0.5 nm, scaled with sqrt(R z0)
 * so that the grid resolves the same physics at every R and z0. */
double adh_grid_default_spacing(const adh_material *m);
/* The paper's grid radius, N = 1000 nodes of that spacing (1.5 um at the
 * paper's R and z0). Changing N alone keeps this radius and refines the grid. */
double adh_grid_default_rmax(const adh_material *m);

/* The default spacing for n nodes: the paper's grid radius (above), never
 * past 0.3 R where the paraboloid gap (eq 3) stops describing a sphere,
 * divided by n. Every driver uses this one rule. */
double adh_grid_spacing_for(const adh_material *m, size_t n);

adh_grid *adh_grid_alloc(size_t n, double dr);
void adh_grid_free(adh_grid *g);

#endif
