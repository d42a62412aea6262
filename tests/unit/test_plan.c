/* A sweep's time left and --plan's time (issue 28, item 6): each run
 * weighed by its expected cost, the pace from the runs done, the runs under
 * way and waiting shared out over the jobs. Against schedules worked out
 * by hand. */
#include <math.h>
#include <string.h>

#include "scene/config.h"
#include "scene/plan.h"
#include "tap.h"

static int near(double a, double b)
{
    return fabs(a - b) <= 1e-9 * fmax(1.0, fabs(b));
}

int main(void)
{
    /* Figure 7 as it ran: eps = 1, 0.5, 0.1 pm cost 1 : 1.65 : 5.28
     * (224 670, 370 010, 1 185 507 iterations), two jobs; run 1 took
     * 198 s, run 2 340 s, run 3 started when run 1 ended. At 340 s the pace
     * so far counted runs (2 of 3 done, 340 s: "2 min 50 s left"); the run
     * left is the longest. */
    adh_plan_progress r[3] = {
        { .cost = 224670, .state = 2, .started = 0, .seconds = 198 },
        { .cost = 370010, .state = 2, .started = 0, .seconds = 340 },
        { .cost = 1185507, .state = 1, .started = 198 },
    };
    double pace = (224670.0 + 370010.0) / (198.0 + 340.0);
    double want = 1185507.0 / pace - (340.0 - 198.0);
    double left = adh_plan_time_left(r, 3, 2, 340, 0);
    ok(near(left, want), "Figure 7 at 340 s: the last run's own cost at the pace so far, %.0f s left (got %.0f; "
       "counting runs said 170)", want, left);
    /* a run under way longer than expected still has a tenth of it to go */
    r[2].started = -5000;
    ok(near(adh_plan_time_left(r, 3, 2, 340, 0), 0.1 * 1185507.0 / pace), "an overdue run: a tenth of it left");
    /* nothing done yet: the pace given, the runs shared out over the jobs */
    adh_plan_progress w[4] = { { .cost = 1 }, { .cost = 1 }, { .cost = 1 }, { .cost = 3 } };
    ok(near(adh_plan_time_left(w, 4, 2, 0, 1.0), 4.0), "costs 1, 1, 1, 3 in order on two jobs: 4 (the first two "
       "at once, the third on the first free job, the fourth on the other, 1 + 3; got %g)",
       adh_plan_time_left(w, 4, 2, 0, 1.0));
    ok(near(adh_plan_time_left(w, 4, 1, 0, 2.0), 3.0), "on one job at 2 a second: 6 / 2 = 3");
    ok(isnan(adh_plan_time_left(w, 4, 2, 0, 0)), "no pace and no run done: unknown");
    /* the expected iterations follow eps as eps^-0.72 */
    static adh_config c;
    adh_config_default(&c);
    double i1 = adh_plan_iterations(&c.spec);
    c.spec.relax.eps = 0.1e-12;
    double i01 = adh_plan_iterations(&c.spec);
    ok(i01 / i1 > 4 && i01 / i1 < pow(10, 0.72) * 1.0001, "eps 10 times smaller: %.2f times the iterations "
       "(the steps out of contact do not grow)", i01 / i1);
    return tap_done();
}
