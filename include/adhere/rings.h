/* Graded radial grids: rings of arbitrary edges. A band of uniform fine
 * rings where the contact line sweeps, then ring widths growing
 * geometrically out to a radius that holds the force. The uniform grid of
 * adhere/grid.h is the special case edge[n] = n dr, and every function here
 * accepts it too. */
#ifndef ADHERE_RINGS_H
#define ADHERE_RINGS_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/params.h"

#define ADH_RINGS_MAX_RATIO 1.1 /* widest growth allowed between neighbours */

typedef struct adh_rings_spec {
    double dr;      /* width of the fine rings, m */
    double fine;    /* the fine band [0, fine]: whole fine rings, rounded up */
    double ratio;   /* each ring beyond is this much wider, 1 <= ratio <= 1.1 */
    double rmax;    /* the last ring ends at or just beyond this radius */
} adh_rings_spec;

/* ADH_SUCCESS when the spec is usable, ADH_EINVAL with a message naming
 * the value otherwise. */
int adh_rings_spec_validate(const adh_rings_spec *s, char *why, size_t whylen);
/* Rings the spec gives (0 if invalid), without building them. */
size_t adh_rings_count(const adh_rings_spec *s);
/* The graded grid of a spec; NULL if invalid or out of memory. */
adh_grid *adh_rings_alloc(const adh_rings_spec *s);
/* A grid of the given n + 1 ring edges (edge[0] = 0, strictly increasing);
 * copied. NULL if the edges are not that. Freed with adh_grid_free. */
adh_grid *adh_rings_alloc_edges(size_t n, const double *edge);

/* Edge j (0..n) of grid g, graded or uniform. */
double adh_rings_edge(const adh_grid *g, size_t j);
/* Width of ring i. */
double adh_rings_width(const adh_grid *g, size_t i);
/* (b^2 - a^2) / 2 = r_i (b - a) of ring i = [a, b]: the force is
 * 2 pi sum p_i times these (exact for piecewise-constant pressure). */
double adh_rings_weight(const adh_grid *g, size_t i);
/* The ring holding radius r: i with edge[i] <= r < edge[i+1] (n - 1 past the end). */
size_t adh_rings_locate(const adh_grid *g, double r);

/* Outer edge of the fine band: the leading rings of the finest width (rmax
 * on a uniform grid). A contact line past it is no longer resolved. */
double adh_rings_fine_radius(const adh_grid *g);
/* Whether a contact of radius a (m) lies inside the fine band. */
int adh_rings_resolves(const adh_grid *g, double a);
/* Why a run whose contact radius reached a stopped on g (the drive's grid
 * check, ADH_EGRID): the grid's edge (0.9 Rmax) or the end of a graded
 * grid's fine band, with the numbers and what to change, as a sentence;
 * and what to change as ADH_FIX_* bits (adhere/status.h). */
void adh_rings_edge_sentence(const adh_grid *g, double a, char *buf, size_t len);
unsigned adh_rings_edge_fix(const adh_grid *g, double a);

/* The weights of the relaxation's convergence measure (adhere/relax.h,
 * adh_relax_measure): the part of each ring within [0, rclip] over the
 * finest width, so that dr sum_n wt_n du_n^2 is the integral of du^2 over
 * r < rclip with du constant on each ring; exactly 1 for every ring of a
 * uniform grid inside rclip (INFINITY: no clip). */
void adh_rings_change_weights(const adh_grid *g, double rclip, double *wt);

/* The contact radius expected at drive position h0 (m): the larger of the
 * estimate adh_protocol_check uses for the grid radius (the undeformed
 * overlap radius, half again for adhesion) and JKR's at overlap z0 - h0,
 * which is the larger one for soft, strongly adhesive spheres. */
double adh_rings_contact_estimate(const adh_material *m, double h0);
/* Before a run: the contact expected at the deepest position lowest (m)
 * must lie inside the fine band.
 * ADH_SUCCESS, or ADH_EGRID with a sentence in why (*fix:
 * ADH_FIX_FINE_BAND). Uniform grids pass. */
int adh_rings_check(const adh_grid *g, const adh_material *m, double lowest, char *why, size_t whylen,
                    unsigned *fix);

/* The grid a run gets when neither N nor the spacing is given. */
typedef struct adh_rings_choice {
    int graded;     /* 0: n uniform nodes of spacing dr; 1: rings (adhere/rings.h) */
    size_t n;       /* nodes, or rings */
    double dr;      /* spacing or fine ring width, m; NAN: the paper's spacing
                       scaled with sqrt(R z0) (it then follows R and z0) */
    double fine;    /* graded: radius of the fine band, m */
    double ratio;   /* graded: growth of the rings past it */
    double rmax;    /* m */
    int hierarchical; /* hold the kernel as an H^2 matrix (adhere/h2.h): set
                       for graded grids, whose N is past the dense product's
                       cache cliff: a product takes 0.3-0.9 ms dense, 0.06 ms
                       H^2 at N = 1310; an operator asked for keeps its own) */
} adh_rings_choice;

/* The paper's grid (N = 1000 at its scaled spacing) where that resolves the
 * edge zone; else the resolved spacing out to the radius the run needs (the
 * contact at the deepest turn within 0.8 Rmax and a negligible force at the
 * edge): uniform while that takes at most ADH_GRID_UNIFORM_MAX_NODES nodes,
 * otherwise (when `graded_ok`, i.e. the ring kernel may be used) a graded
 * grid, fine over the band the contact line sweeps (1.25 x the contact
 * expected at the deepest turn) and growing x1.05 beyond. Fills *c and
 * returns ADH_SUCCESS, or ADH_EGRID with a sentence naming sigma, the grid
 * needed, its memory and what to do (*fix: ADH_FIX_NODES, _SPACING, _FORCE,
 * and for the static curve _MODE): beyond ADH_GRID_MAX_NODES nodes, or for
 * the static curve beyond ADH_GRID_STATIC_MAX_NODES; or a grid past 0.3 R
 * (*fix: ADH_FIX_RADIUS, _TURNS). Uniform and graded
 * grids alike: it sits here, above both. */
int adh_rings_choose(const adh_material *m, adh_grid_use use, double deepest, int graded_ok, adh_rings_choice *c,
                     char *why, size_t whylen, unsigned *fix);

#endif
