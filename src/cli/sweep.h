/* A sweep ([sweep] in a scene): several independent runs, one per swept
 * value, run in parallel on the cores, each written to DIR/run-K/ (its own
 * force.tsv, summary.tsv, turns.tsv and plots), with DIR/sweep.tsv holding
 * one row per run and the sweep's combined figure. */
#ifndef ADH_CLI_SWEEP_H
#define ADH_CLI_SWEEP_H

#include <stdio.h>

#include "adhere/static.h"
#include "adhere/protocol.h"
#include "cli/options.h"
#include "cli/timerun.h"
#include "plot/outdir.h"

/* Runs cli->cfg's sweep into out (opened by the caller: run-K/ are made
 * in it); returns the process exit status (batch.h). Without out (NULL),
 * only sweep.tsv is written, to standard output. */
int cli_sweep_main(const cli_options *cli, adh_outdir *out);

/* What a run's summary.tsv said: the files not written (comma-separated,
 * its not_written) and its status word ("" before it was written). */
typedef struct cli_sweep_said {
    char lost[256];
    char word[32];
} cli_sweep_said;

/* sweep.tsv: one row per run. runs[i] is run i of cfg's sweep; in mode =
 * static sres[i] is its curve's summary (pulloff_F_disp and folds columns);
 * in mode = time tout[i] its summary (cli/timerun.h's table).
 * static_hysteresis, unless NAN, is the static curve's loop area (an eps
 * sweep's Figure 7), said in a comment line (and whether its grid
 * resolved it). said[i] (said may be NULL: no run directories) is what its
 * summary.tsv said, whose status word sweep.tsv repeats. */
int cli_sweep_table(FILE *f, const adh_config *cfg, const adh_run *runs, const adh_static_result *sres,
                    const cli_time_out *tout, const int *status, double static_hysteresis, int static_resolved,
                    const cli_sweep_said *said);

#endif
