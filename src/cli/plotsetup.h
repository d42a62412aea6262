/* What a run's plots show, from its configuration and grid: the one place
 * a configuration becomes an adh_plot_setup (batch, sweeps, the TUI). */
#ifndef ADH_CLI_PLOTSETUP_H
#define ADH_CLI_PLOTSETUP_H

#include "adhere/grid.h"
#include "plot/plot.h"
#include "scene/config.h"

/* Fills s from cfg and the run's grid g (NULL for rigid spheres, which have
 * none: the configuration's N and spacing then). s borrows cfg's strings
 * and g's radii: both must outlive its use. */
void cli_plotsetup_fill(const adh_config *cfg, const adh_grid *g, adh_plot_setup *s);

#endif
