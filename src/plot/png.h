/* One PNG figure through a running gnuplot: the built-in defaults, the
 * style file, output to a temporary name, and the move into place only when
 * gnuplot reports success, so no half-written figure is ever left. */
#ifndef ADH_PLOT_PNG_H
#define ADH_PLOT_PNG_H

#include <stddef.h>

#include "plot/gnuplot.h"

#define ADH_PNG_TIMEOUT_S 60.0

/* reset, the built-in defaults, adh_figure = figure, the style file (""
 * for none), and set output to tmp_png. */
void adh_png_begin(adh_gnuplot *gp, const char *style, const char *figure, const char *tmp_png);

/* unset output, wait for gnuplot's verdict, check the image
 * (adh_png_check), rename tmp_png to final. 0, or -1 with why (tmp_png
 * removed). */
int adh_png_finish(adh_gnuplot *gp, const char *tmp_png, const char *final, char *why, size_t whylen);

/* Whether path is a whole PNG file: the PNG signature, then chunks (IHDR
 * first) each whole, up to an IEND chunk that ends the file. 0, or -1 with
 * why ("not a PNG ...", "cut short ...", ...). CRCs are not checked. */
int adh_png_check(const char *path, char *why, size_t whylen);

#endif
