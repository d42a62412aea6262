/* What a load/unload cycle measures, read off its rows (any driver's: the
 * batch run's, the TUI's path): the maximum load and the contact radius at
 * the turn, the jump into contact, the pull-off and the jump out of contact,
 * and the hysteresis (the area between loading and unloading). SI units, no
 * I/O. */
#ifndef ADHERE_CYCLE_H
#define ADHERE_CYCLE_H

#include <stddef.h>
#include "adhere/observe.h"
#include "adhere/run.h"

typedef struct adh_cycle {
    double max_load;     /* force at the deepest loading position (the turn), N; NAN before any row */
    double h0_turn;      /* deepest loading position, m */
    double a_turn;       /* contact radius there, m */
    double jump_in_h0;   /* first loading position in contact; NAN if none */
    int unloading;       /* the unloading branch measured (its path number), 0 if none */
    double pulloff_F;    /* most negative force on that branch, N; NAN if none */
    double pulloff_h0;
    double jump_out_h0;  /* first position out of contact on it after contact; NAN if none yet */
    double hysteresis;   /* area between loading and that branch, J; NAN without one */
} adh_cycle;

/* Measures rows (path 0 loading, path k > 0 the k-th unloading branch) on
 * the last unloading branch, the deepest turn's in a batch run. */
void adh_cycle_measure(const adh_obs *rows, size_t n, adh_cycle *c);

/* The turns of rows, as a run reports them: for each unloading branch
 * (path k > 0, in row order), the loading state it turned from (the
 * loading row at the branch's first position, else the last loading row
 * before the branch: a path that turned where it stood), its pull-off (the
 * force minimum) and where it left contact. Returns how many (at most cap). */
size_t adh_cycle_turns(const adh_obs *rows, size_t n, adh_turn_result *turns, size_t cap);

/* The area between loading (path 0) and the unloading branch path: the
 * force gap, the loading force linearly interpolated at each unloading
 * position, integrated by the trapezoid rule over the positions both
 * branches cover; past the loading branch's start (unloading goes on
 * there while the surfaces touch) the loading force is the rigid
 * spheres', F_rigid, where the loading began out of contact; from a
 * start in contact (the loading's first row a > 0) the area is over the
 * positions both branches cover only, up to the start. 0 when they share
 * fewer than two positions. */
double adh_cycle_hysteresis(const adh_obs *rows, size_t n, int path);

/* The area between the loading and unloading force curves over the positions
 * both visit (N m): the energy one cycle dissipates, for the deepest turn
 * (adh_cycle_hysteresis interpolates, so a turn off the drive grid still
 * pairs). 0 without unloading. */
double adh_cycle_run_hysteresis(const adh_run *run);
/* The same for a static curve (one path, stable flags): the area between the
 * highest and lowest stable force at each h0, sampled every step, each
 * stable leg interpolated by parabolas through its rows (rows of one leg
 * may have up to two unstable rows between them where the steps cross the
 * lattice's folds, never across the jump-in or jump-out). NAN when memory
 * runs out. */
double adh_cycle_static_hysteresis(const adh_run *curve, double step);
/* The same over the positions h0 < top only (the same samples below it):
 * the loop of a cycle whose start, top, lies on the curve. */
double adh_cycle_static_hysteresis_below(const adh_run *curve, double step, double top);
/* The step, in z0, every driver samples a static curve's loop at. */
#define ADH_CYCLE_HYSTERESIS_STEP 0.002

#endif
