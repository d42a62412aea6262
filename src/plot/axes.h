/* Axes that hold what a figure shows: no flat tail, no empty decade. */
#ifndef ADH_PLOT_AXES_H
#define ADH_PLOT_AXES_H

#include <stddef.h>

/* The right end of a frame over force curves that flatten to zero as h0
 * grows (the force before contact falls as 1/h0^2): active is the largest
 * h0 at which a curve still reaches 1 % of the force span; the frame ends
 * 15 % of its width past it, never past xmax, so it holds what happens and
 * not a long flat tail (Figure 7's axis ran to 20 nm). */
double adh_plot_active_right(double active, double xmin, double xmax);

/* The tics of a logarithmic axis from lo to hi (both above 0): 1, 2 and 5
 * times each power of ten inside it, as gnuplot's list "(0.5, 1, 2)", so
 * an axis that spans less than a decade still reads; past four decades the
 * powers of ten alone. */
void adh_gp_log_tics(double lo, double hi, char *buf, size_t len);

#endif
