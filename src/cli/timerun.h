/* Physical time for the CLI (mode time): one run through the viscoelastic
 * step rule with its summary keys and events table, and the instrument's
 * snap points on a static curve (mode static with a spring). */
#ifndef ADH_CLI_TIMERUN_H
#define ADH_CLI_TIMERUN_H

#include <stdio.h>

#include "adhere/runner.h"
#include "adhere/visco.h"
#include "cli/tables.h"
#include "plot/outdir.h"
#include "scene/config.h"

/* What a run in physical time leaves beside its rows. */
typedef struct cli_time_out {
    adh_visco_rule_settings vs;    /* the settings it ran with */
    adh_visco_result res;
    adh_visco_event *ev;           /* its events (owned), nev of them */
    size_t nev;
    const char *scene;             /* for events.tsv's comment lines: the scene, NULL none */
    const char *partial;           /* why the run did not finish (# PARTIAL), NULL when it did */
} cli_time_out;

/* Runs spec (mode time) on grid g with kernel k, cb after every row, into
 * run (rows, turns, profiles) and out. The status of adh_runner_drive. */
int cli_time_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k, adh_step_cb cb, void *ctx,
                 adh_run *run, cli_time_out *out);
void cli_time_out_free(cli_time_out *out);

/* The summary keys of a run in physical time (at most CLI_TIME_KEYS):
 * the solid and drive, hysteresis, dissipated, the cycle's energies,
 * the times and bases of the jumps and the pull-off (their h0 and force
 * are the run's turns'), the time, the integrator's counts. */
#define CLI_TIME_KEYS 40
size_t cli_time_keys(const cli_time_out *out, cli_tables_extra *extra);

/* The snap points of a static curve under spring k (finite): snap_in_h0,
 * snap_in_base, snap_out_h0, snap_out_base (NAN where there is none). */
#define CLI_TIME_SNAP_KEYS 5
size_t cli_time_snap_keys(const adh_run *curve, double k, double *store, cli_tables_extra *extra);

/* events.tsv: one row per event of the run (tables: a cli_time_out). */
int cli_time_events(FILE *f, const void *out);

#endif
