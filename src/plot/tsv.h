/* The plot module's tables: profiles.tsv (u, h, p at the stored drive
 * positions) and contact.tsv (contact radius and contact-line speed). The
 * run's own tables (force.tsv, turns.tsv, summary.tsv) are cli/tables.c's. */
#ifndef ADH_PLOT_TSV_H
#define ADH_PLOT_TSV_H

#include <stddef.h>
#include <stdio.h>

#include "adhere/run.h"
#include "plot/outdir.h"
#include "plot/setup.h"

/* The comment block each table starts with: material, sigma, gamma, grid. */
void adh_tsv_preamble(FILE *f, const adh_plot_setup *s, const char *what);

/* Write out/profiles.tsv and out/contact.tsv (adh_outdir_write: through a
 * new temporary and a rename). 0, or -1 with msg set. */
int adh_tsv_profiles(const adh_plot_setup *s, const adh_run *run, adh_outdir *out, char *msg, size_t msglen);
int adh_tsv_contact(const adh_plot_setup *s, const adh_run *run, adh_outdir *out, char *msg, size_t msglen);

#endif
