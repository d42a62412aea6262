#include "cli/jumps.h"

#include <math.h>

/* The first loading row in contact, and the loading row before it (-1 when
 * the branch began in contact); -1, -1 when it never touched. */
static long first_contact(const adh_run *run, long *before)
{
    long prev = -1;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        if (o->path != 0)
            continue;
        if (o->a > 0) {
            *before = prev;
            return (long)i;
        }
        prev = (long)i;
    }
    *before = -1;
    return -1;
}

/* A static curve (mode = static) jumps into contact at its first fold,
 * where the outer branch ends: the last stable row before the first
 * unstable one. -1 for a relaxation run (every row stable) or a curve
 * without a fold. */
static long first_fold(const adh_run *run)
{
    for (size_t i = 1; i < run->nrows; i++)
        if (!run->rows[i].stable)
            return run->rows[i - 1].stable ? (long)i - 1 : -1;
    return -1;
}

double cli_jumps_gap_before(const adh_run *run)
{
    long fold = first_fold(run);
    if (fold >= 0)
        return run->rows[fold].hc;
    long before, at = first_contact(run, &before);
    return at >= 0 && before >= 0 ? run->rows[before].hc : NAN;
}

int cli_jumps_jumped(const adh_run *run, double step)
{
    if (first_fold(run) >= 0)
        return 1;
    long before, at = first_contact(run, &before);
    if (at < 0)
        return -1;
    return before >= 0 && run->rows[before].hc - run->rows[at].hc > 2.0 * step ? 1 : 0;
}
