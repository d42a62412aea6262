/* A sweep ([sweep] in a scene, or --sweep): a study of runs, each the
 * configuration with its swept keys set, stepped on the cores (a run per
 * core, kernels shared read-only), the runs that differ only in their turn
 * on one drive. A shard (--shard K/N) steps its drives alone; every run's
 * row goes into DIR/runs.tsv as it ends, so a rerun steps only the runs
 * left, and DIR/study.tsv says which study it is. The whole study writes
 * DIR/sweep.tsv (a row per run) and its figure; a shard leaves them to
 * adhere merge. run-K/ holds a run's own tables and plots where asked. */
#ifndef ADH_CLI_SWEEP_H
#define ADH_CLI_SWEEP_H

#include "cli/kcache.h"
#include "cli/options.h"
#include "plot/outdir.h"

/* Runs cli's study (or its shard) into out (opened by the caller with
 * ADH_OUTDIR_KEEP: an earlier run of the same study is resumed, another's
 * files are cleared); without out (NULL) only sweep.tsv is written, to
 * standard output. The process exit status (exit.h). */
int cli_sweep_main(cli_options *cli, adh_outdir *out);

/* An eps sweep drawn as Figure 7 (adh_sweep_fig7_panel, plots on): its
 * runs' hysteresis against eps needs the value eps -> 0 leaves, the static
 * curve's loop (one curve: eps does not enter it), on a kernel from kc.
 * NAN when not asked, after a signal or when the curve failed; *resolved
 * whether its grid resolves it. */
double cli_sweep_static_hysteresis(const adh_config *cfg, cli_kcache *kc, int *resolved);

#endif
