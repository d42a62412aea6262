/* The columns of a force table, one row per drive step: force.tsv and
 * static.tsv of a batch run, a sweep's runs, the TUI's :rows. One place,
 * so every writer's rows read alike. */
#ifndef ADH_PLOT_ROWS_H
#define ADH_PLOT_ROWS_H

#include <stdio.h>

#include "adhere/observe.h"

/* The header line: h0 F delta hc a angle iters branch path converged
 * stable F_rigid seconds. */
void adh_rows_header(FILE *f);
/* One row, every number to round-trip precision (seconds to 6 digits). */
void adh_rows_write(FILE *f, const adh_obs *o);
/* The same in physical time (mode time): two columns first, the time t
 * and the instrument's base position, then the others. */
void adh_rows_header_timed(FILE *f);
void adh_rows_write_timed(FILE *f, const adh_obs *o);

#endif
