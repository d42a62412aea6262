/* The tab-separated tables a batch run writes: force.tsv (one row per drive
 * step), summary.tsv (key<TAB>value), turns.tsv (one row per turning point).
 * Files are written under a temporary name and renamed into place, so a
 * reader never sees half a table. */
#ifndef ADH_CLI_TABLES_H
#define ADH_CLI_TABLES_H

#include <stdio.h>

#include "adhere/cycle.h"
#include "adhere/protocol.h"
#include "adhere/static.h"
#include "cli/advice.h"
#include "scene/config.h"

typedef struct cli_tables_extra {
    const char *key;
    double value;
} cli_tables_extra;


typedef struct cli_tables {
    const adh_config *cfg;
    const adh_run_spec *spec;        /* the run's (a sweep's run K: its own) */
    const adh_run *run;
    const cli_tables_extra *extra;  /* more summary keys (static mode...), may be NULL */
    size_t nextra;
    int partial;                     /* the run was interrupted or failed */
    const char *note;                /* why, for the comment lines */
    const char *unwritten;           /* files of the run not written (a full disk), comma-separated;
                                        NULL or "" when none: summary.tsv says so */
    const char *status;              /* summary status word; NULL = from the run */
} cli_tables;

/* Whether r is a run in time marked unconverged though it ran through
 * (its energy balance open, or its tolerance looser than promised:
 * cli_time_run): unconverged (r->unconverged) with its sentence in
 * r->why, having stopped on no error (a run that stopped has its stop's
 * sentence there). */
int cli_tables_time_marked(const adh_run *r);
/* That sentence, with the setting that may close it as it was given
 * (" (--time-tol)"), into buf (CLI_TABLES_REASON_LEN), which is
 * returned; "" for any other run. */
const char *cli_tables_marked_reason(const adh_config *cfg, const adh_run *r, char *buf, size_t len);
/* The steps of r that reached the iteration cap (summary.tsv's and
 * sweep.tsv's unconverged_steps): none where a run in time is marked. */
size_t cli_tables_capped_steps(const adh_run *r);
/* The summary's status word: interrupted, unconverged (steps at the
 * iteration cap), success, or the solver's error. */
const char *cli_tables_status_word(const adh_run *r);
/* The status word of a run of c (its specification), as summary.tsv and sweep.tsv say it:
 * cli_tables_status_word's, and for a finished run "no contact" (the
 * surfaces never touched), "not separated" (an unloading branch ended in
 * contact) or "unresolved" (a grid coarser than the limit) where that holds. */
const char *cli_tables_verdict(const adh_run_spec *c, const adh_run *r);
/* summary.tsv's status word for t: t->status when set, else the run's
 * verdict, and "output incomplete" for a success some file of which was
 * not written. */
const char *cli_tables_summary_word(const cli_tables *t);
/* A reason's room: the core's sentence (400 bytes) and the advice after
 * it (a scene's keys with its file and line) whole; and a "STATUS: REASON". */
#define CLI_TABLES_REASON_LEN (PATH_MAX + 1700)
#define CLI_TABLES_STOPPED_LEN (CLI_TABLES_REASON_LEN + 100)
/* Why run r stopped on an error, as summary.tsv's stop_reason, sweep.tsv's
 * status column and the stderr line say it: the core's sentence and what
 * gets past it (its ADH_FIX_* bits) in the words cfg's keys were given in
 * (cli_advice_append_cfg: "(-N, --spacing)" from flags, "(nodes at
 * a.scene:3, spacing at line 4)" from a scene; cfg NULL: the flags),
 * control bytes as spaces; "" for a run that finished or was interrupted.
 * Written to buf (CLI_TABLES_REASON_LEN holds it whole), which is returned. */
const char *cli_tables_stop_reason(const adh_config *cfg, const adh_run *r, char *buf, size_t len);
/* The same with the advice for who (cli_advice_for: a --cost run's N is
 * --cost-nodes'). */
const char *cli_tables_stop_reason_for(const adh_config *cfg, cli_advice_for who, const adh_run *r, char *buf,
                                       size_t len);
/* "STATUS: REASON" for run r that stopped with status (adh_strerror's
 * word, then cli_tables_stop_reason's, when it has one), in buf
 * (CLI_TABLES_STOPPED_LEN holds both whole), which is returned. */
const char *cli_tables_stopped(const adh_config *cfg, const adh_run *r, int status, char *buf, size_t len);
/* A core's reason (why, fix: adh_run.why and .fix, or the like) in those
 * words: what fix names in cfg's words added, control bytes as spaces;
 * "" for "". */
const char *cli_tables_reason(const adh_config *cfg, const char *why, unsigned fix, char *buf, size_t len);
/* Appends name (or a comma-separated list) to the comma-separated list in
 * buf; what does not fit is left off whole names at a time. */
void cli_tables_names_add(char *buf, size_t len, const char *name);
/* A comment line "# key: value" with value's backslashes, newlines, tabs
 * and other control bytes escaped (\\, \n, \t, \xHH): a file name with
 * a newline in it cannot start a row. */
void cli_tables_comment(FILE *f, const char *key, const char *value);
int cli_tables_force(FILE *f, const void *tables);
int cli_tables_summary(FILE *f, const void *tables);
int cli_tables_turns(FILE *f, const void *tables);

/* The equilibrium loop's area of a static curve (adh_cycle_static_hysteresis
 * sampled every CLI_TABLES_HYSTERESIS_STEP z0): the hysteresis no slower
 * drive removes, the jump instabilities'. NAN for an empty curve. */
#define CLI_TABLES_HYSTERESIS_STEP ADH_CYCLE_HYSTERESIS_STEP
double cli_tables_static_hysteresis(const adh_run *curve, const adh_material *m);

/* The summary keys of a static result and its loop's area (above),
 * prefixed ("" or "static_"), into extra[] (at most CLI_TABLES_STATIC_KEYS
 * entries); returns how many. */
#define CLI_TABLES_STATIC_KEYS 9
size_t cli_tables_static_keys(const adh_static_result *res, double hysteresis, const char *prefix,
                              char names[][32], cli_tables_extra *extra);

#endif
