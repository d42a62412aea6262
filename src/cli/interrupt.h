/* SIGINT, SIGTERM and SIGHUP during a batch, sweep or cost run: the handler
 * only raises a flag. The solvers poll it through their settings' cancel
 * pointer (every iteration, Newton step and dwell iteration) and stop; the
 * driver writes what it has, marked partial. */
#ifndef ADH_CLI_INTERRUPT_H
#define ADH_CLI_INTERRUPT_H

#include <signal.h>

#include "adhere/runner.h"

void cli_interrupt_catch(void);     /* install the handlers */
void cli_interrupt_release(void);   /* restore the previous ones */
int cli_interrupt_signal(void);     /* the signal received, 0 if none */
/* The flag for the solvers' cancel hooks (nonzero once a signal came). */
const volatile sig_atomic_t *cli_interrupt_flag(void);
/* The exit status for the signal received, 128 + its number: 130 for
 * SIGINT, 143 for SIGTERM, 129 for SIGHUP (130 if none came). */
int cli_interrupt_exit(void);
/* An adh_step_cb that asks the solver to stop once a signal came. */
int cli_interrupt_step(const adh_obs *row, const adh_run *run, void *ctx);


#endif
