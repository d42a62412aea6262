/* A readiness signal for tests: with $ADHERE_READY_FILE set, the first
 * solve step of a run (batch, sweep, cost, or in the TUI) creates that
 * (empty) file. SIGINT and SIGTERM are caught by then, so a test waits for
 * the file instead of sleeping before it signals. */
#ifndef ADH_CLI_READY_H
#define ADH_CLI_READY_H

/* Creates $ADHERE_READY_FILE once per process; later calls, or an unset
 * variable, do nothing. Async-safe enough for solver threads: a second
 * creation from a racing thread is harmless. */
void adh_ready_mark(void);

#endif
