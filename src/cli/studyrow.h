/* A study's row: one run's numbers as sweep.tsv (and a shard's runs.tsv)
 * hold them: the swept values, every number of the run's summary, its
 * status. One table of columns writes the rows and reads them back, to
 * the last bit (numbers at %.17g), so a table joined from shards is the
 * one the whole study writes. */
#ifndef ADH_CLI_STUDYROW_H
#define ADH_CLI_STUDYROW_H

#include <stdio.h>

#include "adhere/run.h"
#include "adhere/static.h"
#include "cli/timerun.h"
#include "scene/config.h"

/* The numbers of a row, by column. */
enum {
    CLI_ROW_E, CLI_ROW_SIGMA, CLI_ROW_EPS, CLI_ROW_JUMP_IN, CLI_ROW_H_BEFORE, CLI_ROW_H_STAR, CLI_ROW_MAX_LOAD,
    CLI_ROW_PULLOFF, CLI_ROW_JUMP_OUT, CLI_ROW_STEPS, CLI_ROW_ITERATIONS, CLI_ROW_SECONDS, CLI_ROW_JUMPED,
    CLI_ROW_HYSTERESIS, CLI_ROW_PULLOFF_DISP, CLI_ROW_FOLDS,
    CLI_ROW_GAMMA, CLI_ROW_MU, CLI_ROW_ESTAR, CLI_ROW_A, CLI_ROW_Z0, CLI_ROW_R, CLI_ROW_NODES, CLI_ROW_SPACING,
    CLI_ROW_RMAX, CLI_ROW_STEP, CLI_ROW_START, CLI_ROW_DWELL, CLI_ROW_F_JKR, CLI_ROW_F_DMT, CLI_ROW_TURN_H0,
    CLI_ROW_A_TURN, CLI_ROW_PULLOFF_H0, CLI_ROW_UNCONVERGED, CLI_ROW_EDGE_NODES, CLI_ROW_TAIL, CLI_ROW_RESOLVED,
    CLI_ROW_CONVERGED, CLI_ROW_COMPLETE, CLI_ROW_POINTS, CLI_ROW_NEWTON,
    /* physical time (mode time) */
    CLI_ROW_E0, CLI_ROW_EINF, CLI_ROW_TAU, CLI_ROW_SPEED_IN, CLI_ROW_SPEED_OUT, CLI_ROW_DWELL_TIME, CLI_ROW_SPRING,
    CLI_ROW_JUMP_IN_T, CLI_ROW_JUMP_IN_BASE, CLI_ROW_PULLOFF_T, CLI_ROW_PULLOFF_BASE, CLI_ROW_JUMP_OUT_T,
    CLI_ROW_JUMP_OUT_BASE, CLI_ROW_DISSIPATED, CLI_ROW_JUMP_LOSS, CLI_ROW_STORED_CHANGE, CLI_ROW_TIME,
    CLI_ROW_TIME_STEPS, CLI_ROW_JUMPS, CLI_ROW_LATTICE_JUMPS, CLI_ROW_JUMPS_RELAXED, CLI_ROW_FOLDS_RESUMED, CLI_ROW_KRYLOV,
    CLI_ROW_TOLERANCE,
    /* the instrument's spring (mode static or time with one): where the
     * base turns, and rigid spheres' snap-in (eq 22) on the same rows */
    CLI_ROW_SNAP_IN_H0, CLI_ROW_SNAP_IN_BASE, CLI_ROW_SNAP_OUT_H0, CLI_ROW_SNAP_OUT_BASE, CLI_ROW_SNAP_IN_RIGID,
    CLI_ROW_NUMBERS
};

typedef struct cli_studyrow {
    size_t run;                    /* its index in the study, from 0 */
    int done;                      /* 1: filled (by a run or from a table) */
    double v[CLI_ROW_NUMBERS];
    char kernel[8], op[8], mode[8], grid[12];
    char status[64];               /* summary.tsv's word: success, unresolved, interrupted, ... */
    char *reason;                  /* summary.tsv's stop_reason: what stopped a run that ended on an
                                      error, with what may get past it; NULL otherwise (a study of
                                      100000 rows holds no room for the runs that finished). The
                                      status column says "status: reason". Owned by the row: fill
                                      and parse set it without freeing what was there (give them a
                                      new or cleared row); cli_studyrow_clear frees it */
} cli_studyrow;

/* Frees what row owns (its reason) and sets it NULL; the rest is kept. */
void cli_studyrow_clear(cli_studyrow *row);
/* The same for n rows. */
void cli_studyrow_clear_all(cli_studyrow *rows, size_t n);

/* Row i of cfg's study from its run r of specification rc (status: the
 * run's adh status; sres: a static curve's summary, or NULL; tout: a run
 * in physical time's summary and events, or NULL); its reason names what
 * gets past a stop in the words cfg's keys were given in. */
void cli_studyrow_fill(cli_studyrow *row, const adh_config *cfg, size_t i, const adh_run_spec *rc, const adh_run *r,
                       const adh_static_result *sres, const cli_time_out *tout, int status);
/* Row i of a run that did not run: every number NAN, status word. */
void cli_studyrow_empty(cli_studyrow *row, const adh_config *cfg, size_t i, const char *status);

/* The header line and a row of cfg's study (its columns: the mode's, the
 * swept keys'). */
void cli_studyrow_header(FILE *f, const adh_config *cfg);
void cli_studyrow_write(FILE *f, const adh_config *cfg, const cli_studyrow *row);
/* Whether line (without its newline) is cfg's header. */
int cli_studyrow_is_header(const adh_config *cfg, const char *line);
/* A row read back from line (without its newline): 0, or -1 when it is
 * not one of cfg's rows (a column short, a number that does not read, a
 * run out of range, swept values not the run's). */
int cli_studyrow_parse(const adh_config *cfg, const char *line, cli_studyrow *row);
/* What sweep.tsv is made of: cfg's study, rows[i] run i's row, partial
 * (NULL or "": none) why some rows have no result, run_dirs whether run-K/
 * are written, static_hysteresis unless NAN the static curve's loop of an
 * eps sweep's Figure 7 and static_resolved whether its grid resolved it. */
typedef struct cli_studyrow_sweep {
    const adh_config *cfg;
    const cli_studyrow *rows;
    const char *partial;
    int run_dirs;
    double static_hysteresis;
    int static_resolved;
} cli_studyrow_sweep;
/* sweep.tsv from t (a cli_studyrow_sweep): its comment lines, the header
 * and a row for every run; an adh_outdir_write writer. 0. */
int cli_studyrow_table(FILE *f, const void *t);
/* The column name's number index (CLI_ROW_*), or -1 (a word, or none). */
int cli_studyrow_column(const char *name);
/* Whether a row's status says the run has its result: anything but
 * interrupted, not run or output incomplete. */
int cli_studyrow_complete(const cli_studyrow *row);

#endif
