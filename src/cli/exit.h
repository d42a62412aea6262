/* The process's exit statuses, shared by every driver (batch, sweeps,
 * --cost); adhere(1)'s EXIT STATUS gives them. */
#ifndef ADH_CLI_EXIT_H
#define ADH_CLI_EXIT_H

enum {
    CLI_EXIT_OK = 0,
    CLI_EXIT_SOLVER = 1,     /* the solver failed (NaN, grid overflow): partial tables */
    CLI_EXIT_USAGE = 2,      /* bad input: nothing was run or written */
    CLI_EXIT_PLOT = 3,       /* tables written, plots not */
    /* stopped by a signal: 128 + its number (cli_interrupt_exit); this is
     * SIGINT's, for a run an earlier session's signal stopped */
    CLI_EXIT_INTERRUPTED = 130
};

#endif
