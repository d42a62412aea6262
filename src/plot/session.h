/* Figures through one gnuplot into an output directory: the style file,
 * a private temporary directory for gnuplot's data files and images (it
 * opens nothing in the output directory, whose names could be links), its
 * log there (adh_outdir_log_open), each image checked and copied into place
 * (adh_png_finish), and every temporary removed whatever path a figure
 * took. plots.c, the CLI's scene figures and --cost's figure share it. */
#ifndef ADH_PLOT_SESSION_H
#define ADH_PLOT_SESSION_H

#include <limits.h>
#include <signal.h>
#include <stdio.h>

#include "plot/gnuplot.h"
#include "plot/outdir.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#define ADH_SESSION_FILES 16

typedef struct adh_session {
    adh_gnuplot *gp;
    adh_outdir *out;
    const char *logname;      /* in out, e.g. "gnuplot.log" */
    int log_fd;
    char logpath[PATH_MAX + 64];
    char style[PATH_MAX];     /* "" = the built-in defaults only */
    char tmpdir[PATH_MAX];    /* private (mkdtemp): nobody else's names */
    char made[ADH_SESSION_FILES][32];
    size_t nmade;             /* files made in tmpdir, removed at the end */
} adh_session;

/* The style (adh_plot_style_file of style), the temporary directory
 * ($TMPDIR/adhere-plot-XXXXXX), the log out/logname and gnuplot started
 * with cancel as its interrupt flag. 0, or -1 with why (nothing left
 * behind). */
int adh_session_open(adh_session *s, adh_outdir *out, const char *logname, const char *style,
                     const volatile sig_atomic_t *cancel, char *why, size_t whylen);

/* A new data file name in the temporary directory, for writing; its path
 * (for gnuplot) in path. NULL with why. */
FILE *adh_session_data(adh_session *s, const char *name, char *path, size_t len, char *why, size_t whylen);

/* A figure begins (adh_png_begin: defaults, style, adh_figure = figure),
 * gnuplot's image going to the temporary directory. */
void adh_session_begin(adh_session *s, const char *figure, const char *name);

/* The figure into out as name (adh_png_finish). 0, or -1 with why. */
int adh_session_end(adh_session *s, const char *name, char *why, size_t whylen);

/* gnuplot stopped, the temporaries and their directory removed, the log
 * closed (removed when empty). */
void adh_session_close(adh_session *s);

#endif
