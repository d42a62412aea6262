/* A sweep's time left and --plan's time (issue 28, item 6): each run
 * weighed by its expected cost, the pace from the runs done, the runs under
 * way and waiting shared out over the jobs. Against schedules worked out
 * by hand. */
#include <math.h>
#include <string.h>

#include "adhere/models.h"
#include "adhere/protocol.h"
#include "scene/config.h"
#include "scene/plan.h"
#include "scene/scene.h"
#include "tap.h"

static int near(double a, double b)
{
    return fabs(a - b) <= 1e-9 * fmax(1.0, fabs(b));
}

/* A run in physical time at Einf = einf_ratio E0, one speed both ways. */
static adh_run_spec *time_spec(adh_config *c, double einf_ratio, double speed, double spring)
{
    adh_config_default(c);
    adh_run_spec *s = &c->spec;
    s->mode = ADH_MODE_TIME;
    s->time.sls = 1;
    s->time.Einf = einf_ratio * s->mat.E;
    s->time.tau = 1e-3;
    s->time.speed_in = s->time.speed_out = speed;
    s->time.dwell = 0;
    s->time.spring = spring;
    return s;
}

/* Physical time's steps (adh_plan_time_steps) as IDAS takes them (it
 * integrates through a spring, whose own steps the plan does not count):
 * the contact line's travel
 * is JKR's radius at the turn (its overlap there is z0 - turn), a step's
 * travel 0.068 edge zones of E0 when slow and of Einf when fast, and an
 * elastic sphere (Einf = E0) does not depend on the speed and takes 3.5
 * times the steps in contact (a lattice fold at every ring). */
static void time_steps(adh_config *c)
{
    adh_run_spec *s = time_spec(c, 10, 1e-15, 1.0);
    adh_plan_time_cost slow, fast, slow_el, fast_el;
    adh_plan_time_steps(s, &slow);
    ok(!slow.rothe, "through a spring: IDAS's steps (its rule, adh_visco_rothe_applies)");
    double ov;
    adh_material m = s->mat;
    m.E = slow.E_in;
    adh_jkr(&m, slow.a_turn, NULL, &ov);
    double turn = adh_protocol_deepest_turn(&s->proto);
    ok(fabs(ov - (m.z0 - turn)) < 1e-9 * m.z0, "the contact radius %.4g nm is JKR's at the deepest turn (overlap "
       "%.6g nm, z0 - turn %.6g nm)", slow.a_turn * 1e9, ov * 1e9, (m.z0 - turn) * 1e9);
    m.E = s->mat.E;
    ok(fabs(slow.E_in / s->mat.E - 1) < 1e-3 && fabs(slow.step_in / (0.068 * adh_edge_zone(&m)) - 1) < 1e-3,
       "slow (1 fm/s): the relaxed modulus (%.4g of E0), 0.068 of its edge zone a step", slow.E_in / s->mat.E);
    s->time.speed_in = s->time.speed_out = 1.0;
    adh_plan_time_steps(s, &fast);
    ok(fabs(fast.E_in / s->time.Einf - 1) < 0.01 && fast.steps < slow.steps,
       "fast (1 m/s): Einf's (%.4g of it), fewer steps (%.0f against %.0f)", fast.E_in / s->time.Einf,
       fast.steps, slow.steps);
    /* far from elastic the steps do not depend on Einf (measured: 1530
     * and 1547 steps at 100 and 1000 E0, 100 nm/s; the former effective
     * modulus, E0^(1-f) Einf^f, planned 760 and 390), and a branch in
     * contact takes some 60 steps at least (50-74 measured, the sphere
     * then DMT-stiff) */
    adh_plan_time_cost e100, e1000;
    s->time.speed_in = s->time.speed_out = 1e-7;
    s->time.Einf = 100 * s->mat.E;
    adh_plan_time_steps(s, &e100);
    s->time.Einf = 1000 * s->mat.E;
    adh_plan_time_steps(s, &e1000);
    ok(fabs(e100.steps / e1000.steps - 1) < 0.01 && e100.E_in < 10 * s->mat.E,
       "100 nm/s, Einf = 100 and 1000 E0: the same steps within 1 %% (%.0f, %.0f), at an effective modulus below "
       "10 E0 (%.3g E0)",
       e100.steps, e1000.steps, e100.E_in / s->mat.E);
    s->time.speed_in = s->time.speed_out = 1.0;
    adh_plan_time_steps(s, &e1000);
    ok(e1000.contact_steps >= 2 * 60.0 - 1e-9, "1 m/s, Einf = 1000 E0: at least 60 steps a branch in contact "
       "(%.0f in two)", e1000.contact_steps);
    s->time.Einf = 10 * s->mat.E;
    s->time.sls = 0;
    adh_plan_time_steps(s, &fast_el);
    s->time.speed_in = s->time.speed_out = 1e-15;
    adh_plan_time_steps(s, &slow_el);
    ok(near(fast_el.steps, slow_el.steps) && near(slow_el.lattice, 3.5) &&
           fabs(slow_el.contact_steps / slow_el.lattice / (slow.contact_steps / slow.lattice) - 1) < 1e-3,
       "an elastic sphere: the same steps at every speed (%.0f), in contact the relaxed solid's times 3.5 for "
       "its lattice folds", slow_el.steps);
}

/* Without a spring, up to Einf = 10 E0, the Rothe steps run (the core's
 * rule) and the plan counts theirs: no lattice factor near elastic, and
 * fast (1 m/s) the base's travel in contact, z0 - turn in and twice that
 * out, at 0.17 z0 a step; past 10 E0 IDAS's again. */
static void rothe_steps(adh_config *c)
{
    adh_run_spec *s = time_spec(c, 1.5, 1.0, INFINITY);
    adh_plan_time_cost r, idas, far;
    adh_plan_time_steps(s, &r);
    double h = s->mat.z0 - adh_protocol_deepest_turn(&s->proto);
    ok(r.rothe && r.lattice == 1.0 && near(r.contact_steps, 3.0 * h / (0.17 * s->mat.z0)),
       "no spring, Einf = 1.5 E0, 1 m/s: the Rothe steps', no lattice factor, in contact the base's %.3g nm at "
       "0.17 z0 a step (%.1f)", 3e9 * h, r.contact_steps);
    s->time.spring = 1.0;
    adh_plan_time_steps(s, &idas);
    ok(!idas.rothe && idas.lattice > 1.5 && idas.steps > 2 * r.steps,
       "through a spring IDAS's, with its lattice folds (%.2g): %.0f steps against the Rothe steps' %.0f",
       idas.lattice, idas.steps, r.steps);
    s->time.spring = INFINITY;
    s->time.Einf = 11 * s->mat.E;
    adh_plan_time_steps(s, &far);
    ok(!far.rothe, "no spring, Einf = 11 E0: IDAS's");
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
    time_steps(&c);
    rothe_steps(&c);

    /* a sweep of more runs than the plan lists one by one (32): the
     * iterations' total summed runs[i] over every run, reading past the
     * list (garbage in the total; at 50000 runs --plan crashed) */
    static adh_config big;
    static adh_plan plan;
    char why[512] = "";
    adh_config_default(&big);
    int parsed = adh_scene_parse_string("[sweep]\nE = 1GPa .. 2GPa, 50000\n", "big.scene", &big, why, sizeof why);
    ok(parsed == 0, "a sweep of 50000 runs parses (%s)", why);
    adh_plan_make(&big, &plan);
    double sum = 0;
    for (size_t i = 0; i < adh_config_nruns(&big); i++) {
        adh_run_spec rc;
        adh_config_sweep_run(&big, i, &rc);
        sum += adh_plan_iterations(&rc);
    }
    ok(plan.nruns == 50000 && near(plan.iterations, sum), "the plan's iterations are every run's, %.6g (got %.6g)",
       sum, plan.iterations);
    char text[1 << 14] = "", want_line[64];
    FILE *f = fmemopen(text, sizeof text - 1, "w");
    adh_plan_print(f, &big, &plan);
    fclose(f);
    snprintf(want_line, sizeof want_line, "iterations: about %.2g ", sum);
    ok(strstr(text, want_line) != NULL, "and --plan prints that total: '%s'", want_line);
    return tap_done();
}
