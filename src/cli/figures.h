/* The scene figures the plot module does not draw, made from the rows of a
 * run through the same gnuplot wrapper: Figure 1's inset (precontact.png),
 * Figure 2 (bulge.png), and a sweep's combined figure: Figure 3 (jump.png)
 * or Figure 7 (force.png). */
#ifndef ADH_CLI_FIGURES_H
#define ADH_CLI_FIGURES_H

#include <stddef.h>

#include "adhere/protocol.h"
#include "plot/outdir.h"
#include "scene/config.h"

/* precontact.png and bulge.png of the run of spec (a sweep's run: its own)
 * in out when cfg's plots ask for them. 0 (also when none is asked or
 * there is nothing to draw: msg says so), or -1 with msg when gnuplot is
 * missing or fails; then the names of those asked for and not written are
 * added to the comma-separated list unwritten. */
int cli_figures_run(const adh_config *cfg, const adh_run_spec *spec, const adh_run *run, adh_outdir *out,
                    char *msg, size_t msglen, char *unwritten, size_t ulen);

/* The sweep's combined figure (cfg->sweep.plot) from runs[0..n) in out;
 * an eps sweep's Figure 7 has a panel of hysteresis against eps, with
 * static_hysteresis (the static curve's loop; NAN: none) as its line.
 * 0, or -1 with msg. */
int cli_figures_sweep(const adh_config *cfg, const adh_run *runs, size_t n, double static_hysteresis,
                      adh_outdir *out, char *msg, size_t msglen);

#endif
