/* Small pieces every gnuplot figure needs: quoting and natural units. */
#ifndef ADH_PLOT_LABELS_H
#define ADH_PLOT_LABELS_H

#include <stddef.h>

/* Room adh_gp_quote needs for a string of n bytes: a byte takes at most 7
 * characters ( ."\001" ), plus an empty string's '' and the NUL. */
#define ADH_GP_QUOTED_SIZE(n) (7 * (size_t)(n) + 4)
/* ... and for a file name below PATH_MAX with a short suffix and "./". */
#define ADH_GP_PATH_SIZE ADH_GP_QUOTED_SIZE(4096 + 96)

/* The one way user text (a scene title, a file or directory name) enters
 * gnuplot's command stream: as a string expression that evaluates to exactly
 * s and that gnuplot expands nowhere. gnuplot runs `command` in backquotes
 * and expands @name outside single quotes, and its tokenizer cannot read a
 * doubled '' at the start of a string or two in a row; so runs of other bytes
 * go in single quotes (which then hold no quote at all), and each ', newline,
 * carriage return or other control byte is a fixed double-quoted escape
 * ("\047", "\n", "\r", "\ooo") joined on with '.':
 *   it's `x`    ->  'it'."\047".'s `x`'
 * No user byte is ever inside double quotes. Returns the length of the
 * whole expression, as snprintf does; when that is len or more, buf holds
 * adh_text_too_long (an undefined variable: the command fails loudly rather
 * than use a cut string) if it fits, else "". */
size_t adh_gp_quote(const char *s, char *buf, size_t len);

/* adh_gp_quote, returning buf. */
const char *adh_gp_quoted(const char *s, char *buf, size_t len);

/* A file name for gnuplot (set output, load, plot 'file'): adh_gp_quote of
 * path, with "./" put before a relative one, so that gnuplot never takes it
 * for a pipe ('<cmd' in load and plot, '|cmd' in set output), for ~, or for
 * one of its special names ('-', '+', '++', '' = the previous file).
 * Returns buf. */
const char *adh_gp_path(const char *path, char *buf, size_t len);

/* A force unit (mN, µN, nN, pN) that keeps plotted numbers between about
 * 0.1 and 1000 for forces up to fmax newtons. */
void adh_force_unit(double fmax, double *scale, const char **name);

/* A modulus as titles write it, one style for all: "1 GPa", "300 MPa". */
void adh_format_modulus(double v, char *buf, size_t len);

#endif
