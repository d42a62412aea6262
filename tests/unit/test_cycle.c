/* adh_cycle_measure on rows with known answers: a loading branch and an
 * unloading branch whose forces differ by a constant over a known span, on
 * drive grids that do and do not coincide. adh_cycle_static_hysteresis on
 * a static curve whose area is known in closed form. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/cycle.h"
#include "adhere/run.h"
#include "tap.h"

static size_t add(adh_obs *rows, size_t n, double h0, double F, double a, int path)
{
    memset(&rows[n], 0, sizeof rows[n]);
    rows[n].h0 = h0;
    rows[n].F = F;
    rows[n].a = a;
    rows[n].path = path;
    rows[n].branch = path ? -1 : +1;
    return n + 1;
}

static void push(adh_run *run, double h0, double F, double a, int stable)
{
    adh_obs o = { .h0 = h0, .F = F, .a = a, .stable = stable };
    adh_run_push_row(run, &o);
}

/* A static curve in the solver's order: the outer branch (F = 0, out of
 * contact) from 2.5 down to its fold at 1, two unstable rows back up to
 * the jump-out fold at 2, the contact branch F = -h0^2 down to -0.4,
 * sampled every 0.3 (front steps) and, from 1.4 to 1.1, as the windows
 * around an extremum sample it: stable and unstable rows alternating.
 * The area between the stable branches is that of h0^2 over [1, 2], 7/3.
 * Chords (0.3 wide on a parabola) would give 0.5 % more, and the window's
 * stable rows, with no stable neighbour, would leave [1.1, 1.4] out
 * (0.47 less). */
static void static_area(void)
{
    adh_run run;
    adh_run_init(&run);
    for (int k = 0; k <= 7; k++)
        push(&run, 2.5 - 0.2 * k, 0, 0, 1);
    push(&run, 1.0, 0, 0, 1);
    push(&run, 1.4, -0.98, 1, 0); /* unstable: contact forming */
    push(&run, 1.8, -1.62, 1, 0);
    const double hc[] = { 2.0, 1.7, 1.4, 1.42, 1.3, 1.32, 1.2, 1.22, 1.1, 0.8, 0.5, 0.2, -0.1, -0.4 };
    const int st[] = { 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 1, 1, 1, 1 };
    for (size_t k = 0; k < sizeof hc / sizeof hc[0]; k++)
        push(&run, hc[k], -hc[k] * hc[k], 1, st[k]);
    double area = adh_cycle_static_hysteresis(&run, 1e-5);
    ok(fabs(area / (7.0 / 3.0) - 1) < 1e-4,
       "static hysteresis: stable legs linked across the window's unstable rows, parabolas on the contact branch "
       "(%.8g, want 7/3)", area);
    adh_run_free(&run);
}

int main(void)
{
    static_area();
    adh_obs rows[200];
    memset(rows, 0, sizeof rows);
    size_t n = 0;
    adh_cycle c;
    adh_cycle_measure(rows, 0, &c);
    ok(isnan(c.max_load) && c.unloading == 0 && isnan(c.hysteresis), "no rows: nothing measured");
    /* loading from 10 to -2 (step 1): F = -h0, in contact below 3 */
    for (int k = 0; k <= 12; k++)
        n = add(rows, n, 10.0 - k, -(10.0 - k), 10.0 - k < 3 ? 1.0 + k : 0, 0);
    adh_cycle_measure(rows, n, &c);
    ok(c.max_load == 2.0 && c.h0_turn == -2.0 && c.a_turn == 13.0, "max load and a at the turn (%g, %g)", c.max_load, c.a_turn);
    ok(c.jump_in_h0 == 2.0, "jump-in at the first loading row in contact (%g)", c.jump_in_h0);
    ok(c.unloading == 0 && isnan(c.pulloff_F), "no unloading yet: no pull-off");
    /* unloading from -2 on a shifted grid (step 1, offset 0.5): F = -h0 - 3
     * until 6.5, then out of contact */
    for (int k = 0; k <= 9; k++) {
        double h = -2.0 + 0.5 + k;
        n = add(rows, n, h, h < 6.5 ? -h - 3.0 : -h, h < 6.5 ? 5.0 : 0, 1);
    }
    adh_cycle_measure(rows, n, &c);
    ok(c.unloading == 1, "the unloading branch is measured");
    ok(c.pulloff_F == -5.5 - 3.0 && c.pulloff_h0 == 5.5, "pull-off the most negative force (%g at %g)", c.pulloff_F, c.pulloff_h0);
    ok(c.jump_out_h0 == 6.5, "jump-out at the first row out of contact (%g)", c.jump_out_h0);
    /* gap 3 from -1.5 to 5.5, then trapezoid to 0 at 6.5: 3 * 7 + 1.5 */
    ok(fabs(c.hysteresis - 22.5) < 1e-12, "hysteresis with the loading force interpolated (%g, want 22.5)", c.hysteresis);
    return tap_done();
}
