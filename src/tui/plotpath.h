/* Plots of the TUI's path through the plot writer (src/plot/plot.h). */
#ifndef ADH_TUI_PLOTPATH_H
#define ADH_TUI_PLOTPATH_H

#include <signal.h>
#include <stddef.h>

#include "tui/sim.h"

/* Writes the plots of the path so far into dir, or into dir/sub when sub
 * is not NULL (a name of adhere's own: static, time; never entered through
 * a link), or into sub in the working directory when dir is NULL
 * (adhere-plots, adhere-plots/static: never through a link), created if missing, and cleared of the files adhere wrote there
 * before, as -o is, with the
 * session's configuration as it is now (its plot choices too); cancel is
 * the session's signal flag (a wait for gnuplot ends when it is raised).
 * 0 with the writer's account of what it wrote in msg, or -1 with why. */
int tui_plot_path(const tui_sim *s, const char *dir, const char *sub, const volatile sig_atomic_t *cancel, char *msg,
                  size_t msglen);

#endif
