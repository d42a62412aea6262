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

/* What the grid serves: the relaxation (dynamic, the paper's) or the static
 * equilibrium curve, whose exact folds feel the lattice more. */
typedef enum adh_grid_use { ADH_GRID_RELAX = 0, ADH_GRID_STATIC = 1 } adh_grid_use;

/* The resolution limits, from the measured study in docs/convergence.md ("Resolution"):
 * pull-off, jump-in and hysteresis within 1 % of their grid-converged
 * values need a spacing of at most this many edge-zone widths
 * l = (243 pi^2/128) E z0^4 / A ~ 0.37 sqrt(R z0) / sigma. */
#define ADH_GRID_EDGE_SPACING_RELAX 0.45
#define ADH_GRID_EDGE_SPACING_STATIC 0.3
double adh_grid_edge_spacing(adh_grid_use use);
/* The budget of an automatic uniform grid: a dense N x N kernel of at most
 * this many nodes (4000: 128 MB, ~4 ms per relaxation iteration, a Figure 4
 * cycle of ~15 min on one core). An automatic graded grid is held as an H^2
 * operator (~1.3 kB a ring): its budget is the grid limit itself,
 * ADH_GRID_NODES_MAX rings (~24 MB; sigma = 75 takes ~6 000). */
#define ADH_GRID_MAX_NODES 4000
/* The nodes a grid may have at all (flags, scene files, the TUI's N). */
#define ADH_GRID_NODES_MIN 10
#define ADH_GRID_NODES_MAX 20000
/* ADH_SUCCESS, or ADH_EINVAL with "N = 5 nodes is not allowed: use 10 to
 * 20000 nodes": the one check of N, for the run's check and every parser. */
int adh_grid_nodes_check(long n, char *why, size_t whylen);

typedef struct adh_grid_report {
    size_t n;             /* nodes */
    double dr;            /* spacing, m */
    double rmax;          /* N dr, m */
    double sigma;         /* eq 17 */
    double edge;          /* edge-zone width l, m */
    double edge_nodes;    /* l / dr: nodes across the edge zone */
    double limit;         /* the limit in edge-zone widths (adh_grid_edge_spacing) */
    double max_spacing;   /* the resolved limit, limit x l, m */
    int resolved;         /* 1 when dr <= max_spacing */
    double kernel_bytes;  /* memory of the dense kernel, bytes */
} adh_grid_report;

/* The resolution check of a uniform grid of n nodes of spacing dr: every
 * driver (batch, TUI) reports this one. */
void adh_grid_check(const adh_material *m, adh_grid_use use, size_t n, double dr, adh_grid_report *r);

/* The sentence a driver shows for an unresolved grid (the same everywhere). */
void adh_grid_unresolved_sentence(const adh_grid_report *r, char *buf, size_t len);

/* Past this many nodes at the limit a uniform automatic grid gives way to a
 * graded one (the paper's N: below it the uniform grid is as cheap). */
#define ADH_GRID_UNIFORM_MAX_NODES 1000
/* The budget of an automatic static curve: past 1000 nodes it steps over
 * the lattice folds (adhere/static.h, lattice_skip), many rings a step,
 * each Newton step solved with a HODLR preconditioner (adhere/hodlr.h):
 * measured about 2 CPU s at sigma = 22.5 (1952 rings), 8-11 s at sigma =
 * 75 (8893 rings, 58 MB) and 19 s at sigma = 100 (12875 rings, 84 MB): up
 * to sigma ~ 110 at the default turn, as far as it was measured
 * (docs/static-curve.md). */
#define ADH_GRID_STATIC_MAX_NODES 14000

adh_grid *adh_grid_alloc(size_t n, double dr);
void adh_grid_free(adh_grid *g);

#endif
