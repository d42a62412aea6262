/* PNG plots of a run through one gnuplot process (force.png, profile.png,
 * contact.png) with their data tables (profiles.tsv, contact.tsv). The
 * plotter reads the run and a small description of what to draw, never the
 * whole configuration. */
#ifndef ADH_PLOT_H
#define ADH_PLOT_H

#include <stddef.h>

#include "adhere/run.h"
#include "plot/gnuplot.h"
#include "plot/outdir.h"
#include "plot/setup.h"
#include "scene/figures.h"

/* Writes the figures s asks for into out, beside profiles.tsv (when the
 * run stored profiles) and contact.tsv (when the contact figure is asked),
 * which are written also with s->draw == 0 or no gnuplot.
 * reference, when not NULL, is a second run drawn on force.png for
 * comparison: the static equilibrium curve of --reference=static (its
 * path 0, stable stretches solid, unstable ones dashed).
 * Returns 0 (msg names the files written and any figure skipped for lack of
 * data), or 3 when gnuplot is missing, dies, reports an error or makes no
 * whole PNG (msg says what, quoting gnuplot; the tables are still written),
 * or 2 when a table cannot be written (a full disk: the other files are
 * still tried). unwritten (may be NULL) receives the comma-separated names
 * of the files asked for and not written ("" when none). No temporary file
 * or directory stays behind on any path. gnuplot's stderr goes to
 * out/gnuplot.log, kept only when it holds something. */
int adh_plots_write(const adh_plot_setup *s, const adh_run *run, const adh_run *reference, adh_outdir *out,
                    char *msg, size_t msglen, char *unwritten, size_t ulen);

/* The gnuplot style file in use: style (a file, or a directory holding
 * style.gp) if not "", else style.gp in adh_data_dir("gnuplot").
 * 0; 1 when no style is set and none is installed (buf = "", the built-in
 * defaults serve); -1 when style names nothing readable (msg). */
int adh_plot_style_file(const char *style, char *buf, size_t len, char *msg, size_t msglen);

/* The gnuplot functions adh_ucol(p) and adh_udash(p): unloading path p's
 * colour and dash from the style's lists (force.png, force-base.png). */
void adh_plot_branch_styles(adh_gnuplot *gp);

#endif
