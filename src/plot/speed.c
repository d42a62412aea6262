/* The contact-line speed da/dt of a run's rows, step by step and smoothed
 * over the grid's stick-slip. */
#include "plot/speed.h"

#include <math.h>

/* Slope between two rows, NAN when either is out of contact or h0 did not
 * move (a dwell leaves h0 fixed: no drive, no defined da/dh0). */
static double slope(const adh_obs *x, const adh_obs *y)
{
    double dh = y->h0 - x->h0;
    if (!(x->a > 0) || !(y->a > 0) || fabs(dh) < 1e-18)
        return NAN;
    return (y->a - x->a) / dh;
}

void adh_speed_stepwise(const adh_run *run, double drive_speed, double *dadh0, double *dadt)
{
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        long p = adh_run_prev_on_path(run, i), n = adh_run_next_on_path(run, i);
        double d = NAN;
        if (o->a > 0) {
            double back = p >= 0 ? slope(&run->rows[p], o) : NAN;
            double fwd = n >= 0 ? slope(o, &run->rows[n]) : NAN;
            if (!isnan(back) && !isnan(fwd) && p >= 0 && n >= 0) {
                /* the central difference over both neighbours, second order
                 * on a uniform drive and still exact on a non-uniform one */
                d = slope(&run->rows[p], &run->rows[n]);
                if (isnan(d))
                    d = 0.5 * (back + fwd);
            } else {
                d = !isnan(fwd) ? fwd : back;
            }
        }
        dadh0[i] = d;
        /* loading drives h0 down (dh0/dt = -v), unloading up (+v) */
        double dh0dt = (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = d * dh0dt;
    }
}

void adh_speed_smoothed(const adh_run *run, double drive_speed, double dr, double cells, double *dadt)
{
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        dadt[i] = NAN;
        if (!(o->a > 0))
            continue;
        long lo = (long)i, hi = (long)i;
        for (int k = 0; k < 50; k++) {
            long p = adh_run_prev_on_path(run, (size_t)lo);
            long n = adh_run_next_on_path(run, (size_t)hi);
            if (p < 0 || n < 0 || !(run->rows[p].a > 0) || !(run->rows[n].a > 0))
                break;
            lo = p;
            hi = n;
            if (fabs(run->rows[hi].a - run->rows[lo].a) >= cells * dr)
                break;
        }
        if (lo == hi) {
            /* the first or last row of a contact: one step to a neighbour */
            long n = adh_run_next_on_path(run, i), p = adh_run_prev_on_path(run, i);
            if (n >= 0 && run->rows[n].a > 0)
                hi = n;
            else if (p >= 0 && run->rows[p].a > 0)
                lo = p;
            else
                continue;
        }
        /* least-squares slope over the window: its end points sit on hops,
         * so their difference alone would overstate the mean */
        double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
        for (long j = lo; j >= 0; j = (j == hi) ? -1 : adh_run_next_on_path(run, (size_t)j)) {
            double x = run->rows[j].h0 - o->h0, y = run->rows[j].a;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            m += 1;
        }
        double den = m * sxx - sx * sx;
        if (!(fabs(den) > 0))
            continue;
        double dh0dt = (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = (m * sxy - sx * sy) / den * dh0dt;
    }
}
