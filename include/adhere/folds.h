/* Fold bookkeeping along a force-position curve followed point by point
 * (a continuation: the static curve, or any solver that traces F(h0)
 * through its turning points): where the drive position h0 turns (a fold:
 * under displacement control the contact jumps there), the jump-in and
 * jump-out folds, and the load-controlled pull-off (the force's minimum),
 * each placed between the points rather than at one of them.
 *
 * Two ways to place them, chosen at set:
 *   ADH_FOLDS_HERMITE   consecutive points with their slopes dh0/ds and
 *                       dF/ds (a tangent is known): the extremum of the
 *                       cubic Hermite interpolant between the two points
 *                       where dh0/ds (or dF/ds, for the minimum) changes
 *                       sign. Every fold the points resolve is found.
 *   ADH_FOLDS_PARABOLA  no slopes: a fold where h0 turns between the last
 *                       three points, the force's minimum where F does,
 *                       each at the extremum of the parabola through the
 *                       three (in s). Folds narrower than a step are
 *                       stepped over, by design.
 *
 * No I/O; SI units. Use: alloc, set (mode), add every accepted point in
 * order, read the summary and the folds at any time, free. */
#ifndef ADHERE_FOLDS_H
#define ADHERE_FOLDS_H

#include <stddef.h>

typedef struct adh_fold {
    double h0;           /* where the drive turns, m (interpolated between points) */
    double F;            /* force there, N */
    int kind;            /* -1: h0 has a local minimum (approach jumps in here);
                            +1: a local maximum (retraction jumps here) */
} adh_fold;

/* One accepted point of the curve. */
typedef struct adh_folds_point {
    double s;    /* the curve's parameter (an arclength, increasing) */
    double ds;   /* the step from the previous point, as the caller measured it
                    (s - s_prev up to rounding; the Hermite mode uses this one) */
    double h0;   /* drive position, m */
    double F;    /* force, N */
    double dh0;  /* dh0/ds, m per unit s (Hermite mode only) */
    double dF;   /* dF/ds, N per unit s (Hermite mode only) */
} adh_folds_point;

typedef enum adh_folds_mode {
    ADH_FOLDS_HERMITE = 0,
    ADH_FOLDS_PARABOLA = 1
} adh_folds_mode;

typedef struct adh_folds_summary {
    double jump_in_h0;     /* the first fold if h0 has a minimum there (the outer
                              branch ends); NAN otherwise or if none */
    double jump_out_h0;    /* the h0-maximum fold with the largest h0; NAN if none */
    double pulloff_F;      /* the force's minimum over the curve, N (INFINITY before a point) */
    double pulloff_h0;     /* where, m */
    double pulloff_F_disp; /* force at the jump-out fold, N; NAN if none */
    size_t folds;          /* folds found (all, kept or not) */
    size_t points;         /* points added */
} adh_folds_summary;

typedef struct adh_folds adh_folds;

/* Keeps the first max_kept folds with their position and force (every
 * fold is counted). NULL out of memory. */
adh_folds *adh_folds_alloc(size_t max_kept);
void adh_folds_free(adh_folds *f);

/* Forgets every point and fold; the next point starts a curve. */
void adh_folds_set(adh_folds *f, adh_folds_mode mode);

/* The next accepted point. */
void adh_folds_add(adh_folds *f, const adh_folds_point *p);

adh_folds_summary adh_folds_summary_of(const adh_folds *f);
/* The folds kept: their number, and a borrowed array. */
size_t adh_folds_kept(const adh_folds *f, const adh_fold **folds);
/* The k-th last point added (k = 0: the last; k < 3, and fewer than the
 * points added), for a caller's own extrapolation. */
adh_folds_point adh_folds_recent(const adh_folds *f, size_t k);

#endif
