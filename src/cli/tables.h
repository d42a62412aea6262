/* The tab-separated tables a batch run writes: force.tsv (one row per drive
 * step), summary.tsv (key<TAB>value), turns.tsv (one row per turning point).
 * Files are written under a temporary name and renamed into place, so a
 * reader never sees half a table. */
#ifndef ADH_CLI_TABLES_H
#define ADH_CLI_TABLES_H

#include <stdio.h>

#include "adhere/protocol.h"
#include "scene/config.h"

typedef struct cli_summary_extra {
    const char *key;
    double value;
} cli_summary_extra;

/* Writes dir/name atomically through writer(f, ctx). 0, or -1 with why. */
typedef int (*cli_table_writer)(FILE *f, const void *ctx);
int cli_write_atomic(const char *dir, const char *name, cli_table_writer writer, const void *ctx,
                     char *why, size_t whylen);

typedef struct cli_tables {
    const adh_config *cfg;
    const adh_run *run;
    const cli_summary_extra *extra;  /* more summary keys (static mode...), may be NULL */
    size_t nextra;
    int partial;                     /* the run was interrupted or failed */
    const char *note;                /* why, for the comment lines */
    const char *unwritten;           /* files of the run not written (a full disk), comma-separated;
                                        NULL or "" when none: summary.tsv says so */
    const char *status;              /* summary status word; NULL = from the run */
} cli_tables;

/* The summary's status word: interrupted, unconverged (steps at the
 * iteration cap), success, or the solver's error. */
const char *cli_run_status_word(const adh_run *r);
/* Appends name (or a comma-separated list) to the comma-separated list in
 * buf; what does not fit is left off whole names at a time. */
void cli_names_add(char *buf, size_t len, const char *name);
int cli_write_force(FILE *f, const void *tables);
int cli_write_summary(FILE *f, const void *tables);
int cli_write_turns(FILE *f, const void *tables);

#endif
