/* The jump into contact, measured on a run's rows: the central gap before
 * it (Figure 3) and whether there was one at all, for a sweep's table and
 * its figure. */
#ifndef ADH_CLI_JUMPS_H
#define ADH_CLI_JUMPS_H

#include "adhere/run.h"

/* The central gap on the last loading row before the jump into contact:
 * the separation at which the surfaces jump (Figure 3). NAN when the
 * loading branch never reached contact or began in it. For a static curve
 * (a run with unstable rows), the gap at the last stable point before its
 * first fold, where the outer branch ends and the surfaces jump. */
double cli_jumps_gap_before(const adh_run *run);

/* Whether the surfaces jumped: 1 when the central gap fell by more than
 * two drive steps on the step into contact (an elastic instability), 0 when
 * the contact came gradually (hard spheres: no jump can be identified, the
 * paper's open symbols in Figure 3), -1 when there was no contact. A
 * static curve with a fold jumped (1). */
int cli_jumps_jumped(const adh_run *run, double step);

#endif
