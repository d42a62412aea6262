/* One PNG figure through a running gnuplot: the built-in defaults, the
 * style file, output to a temporary image in a private directory, and a
 * copy into the output directory only when gnuplot reports success and the
 * image is whole, so no half-written figure is ever left and gnuplot never
 * opens a file in the output directory. */
#ifndef ADH_PLOT_PNG_H
#define ADH_PLOT_PNG_H

#include <stddef.h>

#include "plot/gnuplot.h"
#include "plot/outdir.h"

#define ADH_PNG_TIMEOUT_S 60.0

/* reset, the built-in defaults, adh_figure = figure, the style file (""
 * for none), and set output to tmp_png. */
void adh_png_begin(adh_gnuplot *gp, const char *style, const char *figure, const char *tmp_png);

/* unset output, wait for gnuplot's verdict, check the image
 * (adh_png_check), and write it into out as name (adh_outdir_write). 0, or
 * -1 with why; tmp_png is removed either way. */
int adh_png_finish(adh_gnuplot *gp, const char *tmp_png, adh_outdir *out, const char *name, char *why,
                   size_t whylen);

/* Whether path is a whole PNG file: the PNG signature, then chunks (IHDR
 * first) each whole, up to an IEND chunk that ends the file. 0, or -1 with
 * why ("empty ...", "not a PNG ...", "cut short ...", ...). CRCs are not
 * checked. */
int adh_png_check(const char *path, char *why, size_t whylen);

#endif
