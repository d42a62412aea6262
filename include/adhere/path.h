/* The path an elastic sphere takes in physical time, read off its static
 * curve. An elastic solid without inertia is rate-independent: driven at
 * any speed, through a spring or not, it follows the equilibria the base
 * can reach continuously (the base h0 - F/k monotone along them: k =
 * INFINITY, displacement control, h0 itself) and jumps where that branch
 * ends, a fold of the base (dF/dh0 = k), landing on the first equilibrium
 * further along the curve at the same base. Time only labels the base's
 * position: t = the base's travel over the branch's speed, plus the dwell
 * at each turn. So the physical path is a walk over the curve's rows, no
 * integration: loading down the curve (the base falling below every
 * earlier one), each turn's unloading back up it (rising above every
 * later one) until the base is back at its start with the surfaces apart.
 *
 * Folds are the parabola's through the three rows around a turn of the
 * base (adh_visco_spring_folds, as the static curve's snap points are);
 * under displacement control the jump into contact and the jump out are
 * the static solver's own folds (jump_in_h0, jump_out_h0). A jump's loss
 * is the base's work along the curve from the fold to the landing,
 * integral of F d(base), the stored energy before minus after; the cycle's
 * work, the hysteresis, is what the jumps released (no dissipation on the
 * way: an elastic solid stores it). A soft spring's snap-out whose landing
 * lies beyond the curve's start lands on the rigid spheres' force (eq 22:
 * the deformation is long gone there). Rows and events are those of
 * adhere/visco.h (t, base, h0, F, a before and after a jump), so every
 * writer of physical time reads them unchanged. No I/O. */
#ifndef ADHERE_PATH_H
#define ADHERE_PATH_H

#include <stddef.h>

#include "adhere/folds.h"
#include "adhere/grid.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/run.h"
#include "adhere/static.h"
#include "adhere/visco.h"

/* What the path is read off. */
typedef struct adh_path_curve {
    const adh_obs *rows;          /* the static curve from the start to its end (the
                                     deepest turn), in order */
    size_t n;
    const float *u;               /* each row's deformation (n x grid nodes), or NULL:
                                     no profiles */
    const adh_grid *g;            /* the grid of u */
    const adh_static_result *res; /* the static solver's summary: its jump-in, jump-out
                                     and pull-off, under displacement control */
    const adh_fold *folds;        /* its folds, in order (the jump-in's force) */
    size_t nfolds;
    int complete;                 /* 1: the curve reached its end; 0: it stopped (the
                                     path then loads as far as it goes) */
    size_t start;                 /* the protocol's start among rows: 0, or, for a start
                                     where the surfaces already touch, after the curve
                                     beyond it (from where they do not), which the
                                     unloading follows on past the start until they
                                     part; a start in contact at rows[0] (no curve beyond
                                     it) ends its unloading there, with no pull-off */
} adh_path_curve;

typedef struct adh_path adh_path;

adh_path *adh_path_alloc(void);
void adh_path_free(adh_path *p);
/* Forgets the last walk: no rows, no events, nothing measured (its
 * summary NAN where nothing is known, zero counts). A driver that solves
 * its curve again calls it, so that the summary asked before the next
 * walk is no earlier walk's. */
void adh_path_clear(adh_path *p);

/* Walks curve c for material m under drive d (speeds, dwell, spring) and
 * protocol ps (turns reached by h0, profiles at positions of the base),
 * appending every row (t, base filled) to run with its turns and profiles;
 * the events and the summary are p's. ADH_SUCCESS or ADH_ENOMEM. */
int adh_path_build(adh_path *p, const adh_path_curve *c, const adh_material *m, const adh_visco_drive *d,
                   const adh_protocol_settings *ps, adh_run *run);

/* Where the curve must end for the walk (a snap-in through a soft spring
 * that lands past the curve's deepest point: solve it deeper and walk
 * again), or NAN when the curve was deep enough. */
double adh_path_deeper(const adh_path *p);
/* The rows the walk appended. */
size_t adh_path_rows(const adh_path *p);
/* The summary as the walk's first rows (all of them: adh_path_rows) have
 * seen it (adh_visco_result's fields: the times and bases of the jumps and
 * the pull-off, the cycle's accounts once its branch ended, time; no
 * integrator steps), and the events among those rows (borrowed; a jump's
 * from its landing's row): a driver that hands the rows out one by one
 * shows what happened so far. */
void adh_path_summary(const adh_path *p, size_t rows, adh_visco_result *res);
size_t adh_path_events(const adh_path *p, size_t rows, const adh_visco_event **ev);
/* The state at the path's row (counted from the walk's first), its
 * deformation linear between the curve's rows around it (p's own, valid
 * until the next call); NULL without the rows' deformations. The curve
 * must still be there. */
const adh_state *adh_path_state(adh_path *p, size_t row);

#endif
