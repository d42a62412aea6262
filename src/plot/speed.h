/* The contact-line speed da/dt = (da/dh0) x drive speed of a run's rows,
 * which contact.tsv and contact.png share. */
#ifndef ADH_PLOT_SPEED_H
#define ADH_PLOT_SPEED_H

#include <stddef.h>

#include "adhere/run.h"

/* Grid spacings the contact line must cross within a smoothed speed. */
#define ADH_SPEED_CELLS 2.0

/* da/dh0 and the contact-line speed da/dt at every row, for a drive moving
 * at drive_speed (m/s): h0 falls on loading (branch +1) and rises on
 * unloading, so da/dt = -branch * drive_speed * da/dh0 (positive while the
 * contact spreads). Differences are taken along each row's own path, central
 * where both neighbours are in contact, one-sided at the ends of a contact;
 * NAN out of contact and where h0 does not change (a dwell). Rows in
 * physical time (a finite t) give da/dt by differences in t, dwells
 * included. Arrays of run->nrows. */
void adh_speed_stepwise(const adh_run *run, double drive_speed, double *dadh0, double *dadt);

/* The contact-line speed from the least-squares slope da/dh0 over the
 * drive steps in which the contact line crosses at least `cells` grid
 * spacings dr (a symmetric window of rows in contact on the row's path, at
 * most 50 each side). The line sticks at a node and slips to the next, so
 * step-by-step speeds oscillate with the grid; this is the speed the paper
 * reads off (its "steady 20 um/s"). NAN where the row is out of contact.
 * Rows in physical time: the slope of a against t over the window. */
void adh_speed_smoothed(const adh_run *run, double drive_speed, double dr, double cells, double *dadt);

#endif
