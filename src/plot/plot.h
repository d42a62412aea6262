/* PNG plots of a run through one gnuplot process (force.png, profile.png,
 * contact.png) with their data tables (profiles.tsv, contact.tsv). */
#ifndef ADH_PLOT_H
#define ADH_PLOT_H

#include <stddef.h>

#include "adhere/protocol.h"
#include "scene/config.h"

/* Writes the plots cfg->plots asks for into dir. Returns 0, or 3 when gnuplot
 * is missing, dies or reports an error (msg says what; the tables are still
 * written), or 2 when dir cannot be written. */
int adh_plots_write(const adh_config *cfg, const adh_run *run, const char *dir,
                    char *msg, size_t msglen);

#endif
