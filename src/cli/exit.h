/* The process's exit statuses, shared by every driver (batch, sweeps,
 * --cost); adhere(1)'s EXIT STATUS gives them. */
#ifndef ADH_CLI_EXIT_H
#define ADH_CLI_EXIT_H

enum {
    CLI_EXIT_OK = 0,
    CLI_EXIT_SOLVER = 1,     /* the solver failed (NaN, grid overflow): partial tables */
    CLI_EXIT_USAGE = 2,      /* bad input: nothing was run or written */
    CLI_EXIT_PLOT = 3,       /* tables written, plots not */
    CLI_EXIT_INTERRUPTED = 130
};

#endif
