/* The scene figures the plot module does not draw, made from the rows of a
 * run through the same gnuplot wrapper: Figure 1's inset (precontact.png),
 * Figure 2 (bulge.png), and a sweep's combined figure: Figure 3 (jump.png)
 * or Figure 7 (force.png). */
#ifndef ADH_CLI_FIGURES_H
#define ADH_CLI_FIGURES_H

#include <stddef.h>

#include "adhere/protocol.h"
#include "cli/studyrow.h"
#include "plot/outdir.h"
#include "scene/config.h"

/* precontact.png and bulge.png of the run of spec (a sweep's run: its own)
 * in out when cfg's plots ask for them. 0 (also when none is asked or
 * there is nothing to draw: msg says so), or -1 with msg when gnuplot is
 * missing or fails; then the names of those asked for and not written are
 * added to the comma-separated list unwritten. */
int cli_figures_run(const adh_config *cfg, const adh_run_spec *spec, const adh_run *run, adh_outdir *out,
                    char *msg, size_t msglen, char *unwritten, size_t ulen);

/* Where each run's run-K/force.tsv is: fd[0] the directory holding every
 * run-K (n 1), or fd[i] the one holding run i's (a shard's, n the runs). */
typedef struct cli_figures_curves {
    const int *fd;
    size_t n;
} cli_figures_curves;

/* The sweep's combined figure (adh_sweep_plot_kind) from the study's
 * rows[0..n) (and, for Figure 7, the runs' force.tsv) into out: jump.png,
 * force.png, map.png or curves.png. An eps sweep's Figure 7 has a panel
 * of hysteresis against eps, with static_hysteresis (the static curve's
 * loop; NAN: none) as its line. 0, or -1 with msg. */
int cli_figures_sweep(const adh_config *cfg, const cli_studyrow *rows, size_t n, const cli_figures_curves *curves,
                      double static_hysteresis, adh_outdir *out, char *msg, size_t msglen);

/* Run i's force curve read back from dirfd's run-K/force.tsv (its h0, F
 * and path; the numbers as written, to the last bit) into run (initialized
 * here; the caller frees it). 0, or -1 with why. */
int cli_figures_curve(int dirfd, size_t i, adh_run *run, char *why, size_t whylen);

/* A study in physical time's figure (timefigs.c), from its rows: plot =
 * speed, speed.png (pull-off and hysteresis against the one swept speed,
 * log axis, with the static pull-offs at E0 and Einf from two static
 * curves on run 1's grid); plot = snap, snap.png (the snap-in against the
 * swept spring, log axes, with rigid spheres' eq 22). 0, or -1 with msg. */
int cli_time_sweep_figure(const adh_config *cfg, const cli_studyrow *rows, size_t n, adh_outdir *out, char *msg,
                          size_t msglen);

#endif
