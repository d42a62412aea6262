/* fit.png: a fit's measured points, the best model over them, and the
 * residuals below, through one gnuplot process. */
#ifndef ADH_PLOT_FITPLOT_H
#define ADH_PLOT_FITPLOT_H

#include <signal.h>
#include <stddef.h>

#include "plot/outdir.h"

/* Everything in the measured coordinates (m, N); arrays borrowed. */
typedef struct adh_fitplot {
    size_t n;
    const double *x, *F, *resid;   /* the points and their residuals */
    const int *dir;                /* +1 approach, -1 retract */
    size_t ncurve;                 /* the best model's curve, in the order solved */
    const double *cx, *cF;
    const int *stable;             /* drawn solid where 1, dashed where 0 */
    const char *title;             /* the heading (user text: quoted) */
    const char *style;             /* gnuplot style file or directory, "" = the installed one */
} adh_fitplot;

/* Writes fit.png into out (through a plot session: gnuplot opens nothing
 * there). cancel: the interrupt flag gnuplot's waits poll. 0, or -1 with
 * why (gnuplot missing or failing); no temporary stays behind. */
int adh_fitplot_write(const adh_fitplot *p, adh_outdir *out, const volatile sig_atomic_t *cancel, char *why,
                      size_t whylen);

#endif
