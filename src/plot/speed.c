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

/* Rows in physical time (mode time) carry their time, which a run in time
 * advances: the speed is then da/dt itself, dwells included. (Rows made
 * without it, zeroed, have t = 0 throughout.) */
static int timed(const adh_run *run)
{
    return run->nrows > 1 && isfinite(run->rows[0].t) && run->rows[run->nrows - 1].t > run->rows[0].t;
}

/* da/dt between two rows of a timed run, NAN out of contact. */
static double rate(const adh_obs *x, const adh_obs *y)
{
    double dt = y->t - x->t;
    if (!(x->a > 0) || !(y->a > 0) || !(fabs(dt) > 0))
        return NAN;
    return (y->a - x->a) / dt;
}

/* The central difference at row i over its neighbours on the path, one-sided
 * at the ends of a contact. */
static double difference(const adh_run *run, size_t i, double (*d)(const adh_obs *, const adh_obs *))
{
    const adh_obs *o = &run->rows[i];
    long p = adh_run_prev_on_path(run, i), n = adh_run_next_on_path(run, i);
    if (!(o->a > 0))
        return NAN;
    double back = p >= 0 ? d(&run->rows[p], o) : NAN;
    double fwd = n >= 0 ? d(o, &run->rows[n]) : NAN;
    if (!isnan(back) && !isnan(fwd)) {
        /* the central difference over both neighbours, second order
         * on a uniform drive and still exact on a non-uniform one */
        double c = d(&run->rows[p], &run->rows[n]);
        return isnan(c) ? 0.5 * (back + fwd) : c;
    }
    return !isnan(fwd) ? fwd : back;
}

void adh_speed_stepwise(const adh_run *run, double drive_speed, double *dadh0, double *dadt)
{
    int t = timed(run);
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        dadh0[i] = difference(run, i, slope);
        /* loading drives h0 down (dh0/dt = -v), unloading up (+v) */
        double dh0dt = (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = t ? difference(run, i, rate) : dadh0[i] * dh0dt;
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
        int t = timed(run);
        for (int k = 0; k < 50; k++) {
            long p = adh_run_prev_on_path(run, (size_t)lo);
            long n = adh_run_next_on_path(run, (size_t)hi);
            int pin = p >= 0 && run->rows[p].a > 0, nin = n >= 0 && run->rows[n].a > 0;
            /* in physical time the steps shrink to nothing at events: a
             * window at the end of a contact grows on its one side */
            if (!(pin && nin) && !(t && (pin || nin)))
                break;
            lo = pin ? p : lo;
            hi = nin ? n : hi;
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
            double x = t ? run->rows[j].t - o->t : run->rows[j].h0 - o->h0, y = run->rows[j].a;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            m += 1;
        }
        double den = m * sxx - sx * sx;
        if (!(fabs(den) > 0))
            continue;
        double dh0dt = t ? 1.0 : (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = (m * sxy - sx * sy) / den * dh0dt;
    }
}
