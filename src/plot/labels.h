/* Small pieces every gnuplot figure needs: quoting and natural units. */
#ifndef ADH_PLOT_LABELS_H
#define ADH_PLOT_LABELS_H

#include <stddef.h>

/* A gnuplot single-quoted string: nothing is special inside but the quote
 * itself, which is doubled, so any path survives. Returns buf. */
const char *adh_gp_quoted(const char *s, char *buf, size_t len);

/* A force unit (mN, µN, nN, pN) that keeps plotted numbers between about
 * 0.1 and 1000 for forces up to fmax newtons. */
void adh_force_unit(double fmax, double *scale, const char **name);

/* A modulus as titles write it, one style for all: "1 GPa", "300 MPa". */
void adh_format_modulus(double v, char *buf, size_t len);

#endif
