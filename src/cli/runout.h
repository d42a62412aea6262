/* A study's run in its own directory (run-K): force.tsv, turns.tsv and
 * summary.tsv as a batch run writes them, then the run's figures; a
 * summary that names what was not written and why. */
#ifndef ADH_CLI_RUNOUT_H
#define ADH_CLI_RUNOUT_H

#include "adhere/run.h"
#include "adhere/static.h"
#include "cli/timerun.h"
#include "plot/outdir.h"
#include "scene/config.h"

/* What a run's summary.tsv said: the files not written (comma-separated,
 * its not_written) and its status word ("" when it was not written); a
 * study's row repeats the word. */
typedef struct cli_runout_said {
    char lost[256];
    char word[64];      /* a study row's status holds as much: "iteration cap reached before convergence" is 40 */
} cli_runout_said;

/* The worse of two exit statuses: usage and output errors first, then
 * interruption, solver failure, plots. */
int cli_runout_worse(int a, int b);

/* Run i of cfg's study (specification spec, adh status rc; sres a static
 * curve's summary or NULL; tout a run in physical time's or NULL) into dir: its tables, then, unless a signal
 * came (then its summary says which figures were not drawn), its
 * figures; said: what its summary.tsv said last. The exit status its
 * outputs call for. */
int cli_runout_write(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                     const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said);

/* The tables alone (a run that never started: they say interrupted). */
int cli_runout_tables(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                      const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said);

#endif
