/* A readiness signal for tests: with $ADHERE_READY_FILE set, adhere appends
 * a line to that file naming each phase of a run as it begins, and the line
 * "step" once the first drive step is solved. Signals are caught by then,
 * so a test waits for a line instead of sleeping before it sends one.
 * Without the variable nothing is written. */
#ifndef ADH_UTIL_READY_H
#define ADH_UTIL_READY_H

/* Appends "PHASE\n" (kernel, relax, static, rigid, reference, dwell, plot,
 * cost, sweep) in one write, so a reader sees the line whole or not at all. */
void adh_ready_phase(const char *phase);
/* Appends "step" once per process: the first solved step. */
void adh_ready_mark(void);

#endif
