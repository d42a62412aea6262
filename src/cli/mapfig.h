/* A study's picture of one sweep.tsv column over its swept keys:
 * map.png, a heat map over the first two keys (each cell a run, the keys'
 * values as tics, gnuplot's image), or curves.png, the column against the
 * last key with a curve for each value of the others. */
#ifndef ADH_CLI_MAPFIG_H
#define ADH_CLI_MAPFIG_H

#include "cli/studyrow.h"
#include "plot/session.h"
#include "scene/config.h"

/* The map (as_map) or the curves of cfg->sweep.map (by default the
 * pull-off, or, where no run has one, the first of max_load, jump_in_h0,
 * h_before some run has) from rows[0..n) through ses. 0, or -1 with why. */
int cli_mapfig_draw(adh_session *ses, const adh_config *cfg, const cli_studyrow *rows, size_t n, int as_map,
                    char *why, size_t whylen);

#endif
