/* Wall time for the cost of a step, a run or a redraw. */
#ifndef ADHERE_CLOCK_H
#define ADHERE_CLOCK_H

/* Seconds on the monotonic clock, from an arbitrary origin. */
double adh_clock_seconds(void);
/* CPU seconds of the calling thread: what a piece of work costs whatever
 * else the machine is running (a plan's timing on a shared machine). */
double adh_clock_cpu_seconds(void);

#endif
