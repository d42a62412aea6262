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
#include "plot/outdir.h"

/* Runs cli->cfg's sweep into out (opened by the caller: run-K/ are made
 * in it); returns the process exit status (batch.h). Without out (NULL),
 * only sweep.tsv is written, to standard output. */
int cli_sweep_main(const cli_options *cli, adh_outdir *out);

/* A run's files not written, comma-separated (its summary.tsv's not_written). */
#define CLI_SWEEP_LOST 256

/* sweep.tsv: one row per run. runs[i] is run i of cfg's sweep; in mode =
 * static sres[i] is its curve's summary (pulloff_F_disp and folds columns);
 * lost[i] (lost may be NULL) the files of run i not written, whose status
 * is then not success, as its summary.tsv's is not. */
int cli_sweep_table(FILE *f, const adh_config *cfg, const adh_run *runs, const adh_static_result *sres,
                    const int *status, const char (*lost)[CLI_SWEEP_LOST]);

#endif
