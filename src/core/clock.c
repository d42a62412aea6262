#include "adhere/clock.h"

#include <time.h>

double adh_clock_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double adh_clock_cpu_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return adh_clock_seconds();
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
