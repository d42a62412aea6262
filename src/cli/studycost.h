/* What a study will cost before it runs: the expected time from a cheap
 * pilot (the study's first and last drives stepped on a coarse grid of
 * the same radius, their iterations a step; the time of a kernel product
 * on the real grid against the coarse one), and the disk and limits it
 * needs, which refuse a study that would not fit. */
#ifndef ADH_CLI_STUDYCOST_H
#define ADH_CLI_STUDYCOST_H

#include <stdio.h>

#include "scene/config.h"
#include "scene/plan.h"

typedef struct cli_studycost {
    double seconds;          /* expected wall time of the runs to do, s (NAN: no estimate) */
    double per_step;         /* iterations a step, from the pilot (relaxation) */
    double t_iter;           /* seconds an iteration takes on the real grid */
    double dwell_iterations; /* held at the turns, every drive's (the plan's), priced at t_iter */
    size_t pilot_nodes;      /* the pilot's grid */
    int pilot_cut;           /* the pilot was stopped before its end (it took too long) */
    int timed;               /* physical time or the static curve: no pilot (their steps follow the
                                integrator's tolerance, the curve's folds) */
    int jobs;
} cli_studycost;

/* The expected time of plan p of cfg (steps over jobs cores), from the
 * pilot: it runs for at most a few seconds. */
void cli_studycost_time(const adh_config *cfg, const adh_plan *p, cli_studycost *e);
/* The study's one "time:" line, saying what it is built from: 0, or -1
 * with nothing printed when the pilot gives no estimate (physical time,
 * the static curve; a pilot that computed nothing): the plan's own line
 * then says why. */
int cli_studycost_print(FILE *f, const cli_studycost *e);

/* Whether the study fits: at most ADH_SWEEP_MAX_RUNS runs, what it writes
 * on the free space and inodes of its directory's file system, its largest
 * file under the file size limit (ulimit -f). 0, or -1 with why; when f is
 * not NULL the figures go there as plan lines. */
int cli_studycost_fits(const adh_config *cfg, const adh_plan *p, FILE *f, char *why, size_t whylen);

#endif
