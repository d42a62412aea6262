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

/* The central gap on the last loading row before the jump into contact:
 * the separation at which the surfaces jump (Figure 3). NAN when the
 * loading branch never reached contact or began in it. For a static curve
 * (a run with unstable rows), the gap at the last stable point before its
 * first fold, where the outer branch ends and the surfaces jump. */
double cli_sweep_gap_before_jump(const adh_run *run);

/* Whether the surfaces jumped: 1 when the central gap fell by more than
 * two drive steps on the step into contact (an elastic instability), 0 when
 * the contact came gradually (hard spheres: no jump can be identified, the
 * paper's open symbols in Figure 3), -1 when there was no contact. A
 * static curve with a fold jumped (1). */
int cli_sweep_jumped(const adh_run *run, double step);

/* sweep.tsv: one row per run. runs[i] is run i of cfg's sweep; in mode =
 * static sres[i] is its curve's summary (pulloff_F_disp and folds columns). */
int cli_sweep_table(FILE *f, const adh_config *cfg, const adh_run *runs, const adh_static_result *sres,
                          const int *status);

#endif
