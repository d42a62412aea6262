/* PNG plots of a run through one gnuplot process (force.png, profile.png,
 * contact.png) with their data tables (profiles.tsv, contact.tsv). The
 * plotter reads the run and a small description of what to draw, never the
 * whole configuration. */
#ifndef ADH_PLOT_H
#define ADH_PLOT_H

#include <signal.h>
#include <stddef.h>

#include "adhere/params.h"
#include "adhere/run.h"
#include "plot/outdir.h"
#include "scene/figures.h"
#include "scene/measured.h"

/* What the plots of one run show, beside the run itself. Strings and
 * arrays are borrowed: they must outlive the call they are passed to. */
typedef struct adh_plot_setup {
    adh_material mat;              /* headings, model curves, the tables' preamble */
    unsigned figures;              /* adh_plot_kind bits asked for: ADH_PLOT_CONTACT
                                      also asks for contact.tsv */
    int draw;                      /* 0: the tables only, no PNG (--no-plot) */
    const char *title;             /* the scene's title, "" for none */
    int rigid;                     /* rigid spheres: no JKR, DMT, MD curves (E means nothing) */
    int equilibrium;               /* path 0 is the static equilibrium curve (--mode=static) */
    double drive_speed;            /* |dh0/dt|, m/s: contact-line speeds */
    double step;                   /* drive step d, m */
    size_t nodes;                  /* the run's grid: N nodes (each profile's length), */
    double dr;                     /* its (finest) spacing, m, */
    const double *r;               /* and its node radii; NULL: uniform, (n + 1/2) dr */
    const char *style;             /* gnuplot style file or directory, "" = the installed one */
    const adh_measured *measured;  /* --data: drawn over force.png, NULL = none */
    const volatile sig_atomic_t *cancel; /* the caller's interrupt flag: a wait for gnuplot
                                            stops once it is raised (NULL: none) */
} adh_plot_setup;

/* Node n's radius on the setup's grid. */
double adh_plot_radius(const adh_plot_setup *s, size_t n);

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

#endif
