/* SIGINT and SIGTERM during a batch, sweep or cost run: the handler only
 * records the signal; the solvers' step callbacks see it and stop, and the
 * driver writes what it has, marked partial. */
#ifndef ADH_CLI_INTERRUPT_H
#define ADH_CLI_INTERRUPT_H

#include "adhere/protocol.h"

void adh_interrupt_catch(void);     /* install the handlers */
void adh_interrupt_release(void);   /* restore the previous ones */
int adh_interrupt_signal(void);     /* the signal received, 0 if none */
/* An adh_step_cb that asks the solver to stop once a signal came. */
int adh_interrupt_step(const adh_obs *row, const adh_run *run, void *ctx);

#endif
