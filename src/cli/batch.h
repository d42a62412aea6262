/* The batch driver: runs the configured protocol with no TUI, streams or
 * writes the tables, then the plots. Returns the process exit status. */
#ifndef ADH_CLI_BATCH_H
#define ADH_CLI_BATCH_H

#include "cli/options.h"

/* Exit statuses shared by every driver. */
enum {
    CLI_EXIT_OK = 0,
    CLI_EXIT_SOLVER = 1,     /* the solver failed (NaN, grid overflow): partial tables */
    CLI_EXIT_USAGE = 2,      /* bad input: nothing was run or written */
    CLI_EXIT_PLOT = 3,       /* tables written, plots not */
    CLI_EXIT_INTERRUPTED = 130
};

int cli_batch_main(const cli_options *cli);

#endif
