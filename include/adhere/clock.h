/* Wall time for the cost of a step, a run or a redraw. */
#ifndef ADHERE_CLOCK_H
#define ADHERE_CLOCK_H

/* Seconds on the monotonic clock, from an arbitrary origin. */
double adh_clock_seconds(void);

#endif
