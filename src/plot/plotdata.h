/* The numbers behind the plots: the public tables (profiles.tsv,
 * contact.tsv) and the contact-line speed they and contact.png share. */
#ifndef ADH_PLOT_PLOTDATA_H
#define ADH_PLOT_PLOTDATA_H

#include <stddef.h>
#include <stdio.h>

#include "adhere/protocol.h"
#include "scene/config.h"

/* Grid spacings the contact line must cross within a smoothed speed. */
#define ADH_SPEED_CELLS 2.0

/* da/dh0 and the contact-line speed da/dt at every row, for a drive moving
 * at drive_speed (m/s): h0 falls on loading (branch +1) and rises on
 * unloading, so da/dt = -branch * drive_speed * da/dh0 (positive while the
 * contact spreads). Differences are taken along each row's own path, central
 * where both neighbours are in contact, one-sided at the ends of a contact;
 * NAN out of contact and where h0 does not change (a dwell). Arrays of
 * run->nrows. */
void adh_contact_speed(const adh_run *run, double drive_speed, double *dadh0, double *dadt);

/* The contact-line speed from the least-squares slope da/dh0 over the
 * drive steps in which the contact line crosses at least `cells` grid
 * spacings dr (a symmetric window of rows in contact on the row's path, at
 * most 50 each side). The line sticks at a node and slips to the next, so
 * step-by-step speeds oscillate with the grid; this is the speed the paper
 * reads off (its "steady 20 um/s"). NAN where the row is out of contact. */
void adh_contact_speed_smoothed(const adh_run *run, double drive_speed, double dr,
                                double cells, double *dadt);

/* The row index that follows / precedes row i on the same path, or -1. */
long adh_row_next_on_path(const adh_run *run, size_t i);
long adh_row_prev_on_path(const adh_run *run, size_t i);

/* The comment block every table starts with: material, sigma, gamma, grid. */
void adh_table_preamble(FILE *f, const adh_config *cfg, const char *what);

/* Write DIR/profiles.tsv and DIR/contact.tsv (through a temporary name and
 * a rename). 0, or -1 with msg set. */
int adh_write_profiles_table(const adh_config *cfg, const adh_run *run, const char *path,
                             char *msg, size_t msglen);
int adh_write_contact_table(const adh_config *cfg, const adh_run *run, const char *path,
                            char *msg, size_t msglen);

/* Node radius r_n = (n - 1/2) dr of the run's grid (the profiles do not
 * carry it; it follows from cfg->nodes and the spacing). */
double adh_profile_radius(const adh_config *cfg, size_t n);

#endif
