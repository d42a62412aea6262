/* Every stop a run can come to says why (SQLite style: each error path
 * provoked): the run's record (adh_run.why, .fix) holds the step rule's
 * sentence of what failed and where, not the status code's generic words,
 * with the ADH_FIX_* bits of what may get past it only where that is
 * known. The static curve (its start, a stalled step of either kind, the
 * point cap), physical time (its start, the step cap), the relaxation's
 * grid edge, and a run that finishes says nothing. Small grids: about a
 * second. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/drive.h"
#include "adhere/fit.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/rule_visco.h"
#include "adhere/runner.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "tap.h"

/* The static curve with settings s from start (NAN: automatic) down to -1 nm. */
static int static_run(const adh_grid *g, const adh_kernel *k, const adh_material *m, adh_static_settings s,
                      double start, adh_run *run)
{
    adh_run_init(run);
    s.h0_end = -1e-9;
    s.h0_start = start;
    return adh_runner_static_curve(g, k, m, &s, NULL, NULL, run, NULL);
}

/* Whether the record's sentence has every one of the (NULL-ended) parts,
 * and names no flag (the core never does). */
static int says(const adh_run *run, const char *const *parts)
{
    for (; *parts; parts++)
        if (!strstr(run->why, *parts))
            return 0;
    return run->why[0] && !strstr(run->why, "--");
}

static void static_stops(const adh_grid *g, const adh_kernel *k, const adh_material *m)
{
    adh_run run;
    adh_static_settings s = adh_static_settings_default();

    /* 0.3 nm: inside the snap-in, the start cannot be solved from u = 0;
     * it is taken from the curve traced from further out, here cut short
     * by a cap of 5 points: the start and what stopped the way there */
    s.max_points = 5;
    int rc = static_run(g, k, m, s, 0.3e-9, &run);
    ok(rc == ADH_EMAXITER && run.status == rc && run.nrows == 0 &&
       says(&run, (const char *[]){ "the static curve from further out did not reach its start h0 = 300 pm: the "
                                    "static curve reached its cap of 5 points",
                                    "before its end h0 = 300 pm", NULL }),
       "a static curve whose start fails says where and what stopped the way there (%s: %s; fix %#x)",
       adh_strerror(rc), run.why, run.fix);
    adh_run_free(&run);
    s = adh_static_settings_default();
    rc = static_run(g, k, m, s, 0.3e-9, &run);
    ok(rc == ADH_SUCCESS && run.nrows > 0 && run.rows[0].h0 == 0.3e-9 && run.rows[0].hc < ADH_CONTACT_FACTOR * m->z0,
       "... without the cap it starts there, in contact (%s: %s)", adh_strerror(rc), run.why);
    adh_run_free(&run);

    /* every step judged off the curve (a turn of at most 1e-6 rad per step)
     * and a floor just under the first step: the exact curve stalls at once */
    s.lattice_skip = 0;
    s.max_angle = 1e-6;
    s.ds_min = 0.9 * s.ds_init;
    rc = static_run(g, k, m, s, NAN, &run);
    ok(rc == ADH_ESTALL && run.nrows == 1 &&
       says(&run, (const char *[]){ "stalled at h0 = ", "arclength step fell below its floor",
                                    "the last attempt: the corrected point left the curve", NULL }) &&
       run.fix == ADH_FIX_MODE,
       "an arclength step below ds_min: the curve stalled, where, the last rejection, the relaxation named (%s)",
       run.why);
    ok(!strstr(run.why, adh_strerror(ADH_ESTALL)), "... in its own words, not the status code's");
    adh_run_free(&run);
    /* the same stall on the way to a start in contact (0.3 nm): the
     * start, then the stall's sentence whole, to its last words */
    rc = static_run(g, k, m, s, 0.3e-9, &run);
    ok(rc == ADH_ESTALL && run.nrows == 0 &&
       says(&run, (const char *[]){ "start h0 = 300 pm", "arclength step fell below its floor",
                                    "the last attempt: the corrected point left the curve",
                                    "the relaxation steps the drive without following the curve", NULL }) &&
       run.fix == ADH_FIX_MODE,
       "a stall on the way to the start: the start, and the stall's sentence whole (%zu bytes: %s)",
       strlen(run.why), run.why);
    adh_run_free(&run);

    /* the same in steps of Q (lattice_skip): Newton's corrector given two
     * iterations, a step cut below the floor */
    s = adh_static_settings_default();
    s.lattice_skip = 1;
    s.max_newton = 2;
    s.ds_min = 0.9 * s.ds_init;
    rc = static_run(g, k, m, s, NAN, &run);
    ok(rc == ADH_ESTALL && says(&run, (const char *[]){ "stalled at h0 = ", "step (in the contact measure Q)", NULL }),
       "a step in Q below ds_min says it was a step in Q (%s)", run.why);
    adh_run_free(&run);

    /* the point cap */
    s = adh_static_settings_default();
    s.max_points = 3;
    rc = static_run(g, k, m, s, NAN, &run);
    ok(rc == ADH_EMAXITER && run.nrows == 3 &&
       says(&run, (const char *[]){ "cap of 3 points", "before its end h0 = -1 nm", NULL }) && run.fix == 0,
       "the point cap: where the curve was and where it was going (%s)", run.why);
    adh_run_free(&run);

    /* a curve that comes down to its end has nothing to say */
    rc = static_run(g, k, m, adh_static_settings_default(), NAN, &run);
    ok(rc == ADH_SUCCESS && run.why[0] == '\0' && run.fix == 0, "a finished curve: no reason (%s)",
       adh_strerror(rc));
    adh_run_free(&run);
}

/* Physical time through the drive, as the CLI and the TUI step it. */
static int visco_run(const adh_grid *g, const adh_kernel *k, const adh_material *m, size_t max_steps, double start,
                     adh_run *run)
{
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(m->E);
    vs.sls.Einf = 2.0 * m->E;
    vs.s.max_steps = max_steps;
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = -1e-9;
    ps.start = start;
    adh_run_init(run);
    return adh_runner_rule(&adh_rule_visco, g, k, m, &vs, &ps, NULL, NULL, run);
}

static void visco_stops(const adh_grid *g, const adh_kernel *k, const adh_material *m)
{
    adh_run run;
    int rc = visco_run(g, k, m, 200000, 0.3e-9, &run);
    ok(rc == ADH_ESTALL && run.nrows == 0 &&
       says(&run, (const char *[]){ "the start h0 = 300 pm is not a stable point out of contact", "start further out",
                                    NULL }) && run.fix == ADH_FIX_START,
       "physical time from inside the snap-in: the start named, start further out (%s: %s)", adh_strerror(rc), run.why);
    adh_run_free(&run);

    rc = visco_run(g, k, m, 10, NAN, &run);
    ok(rc == ADH_EMAXITER && says(&run, (const char *[]){ "the integrator took its cap of 10 steps by t = ", " h0 = ",
                                                          NULL }) && run.fix == 0,
       "the integrator's step cap: when and where (%s: %s)", adh_strerror(rc), run.why);
    adh_run_free(&run);
}

/* The relaxation on a grid its contact outgrows: the rings' sentence, and
 * what to change (the grid's radius: more nodes or a larger spacing). */
static void relax_edge(const adh_material *m)
{
    adh_grid *g = adh_grid_alloc(20, 10e-9);
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    if (!k) {
        printf("Bail out! out of memory\n");
        exit(1);
    }
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = 0.25e-9;
    ps.turns[0] = -3e-9;
    adh_relax_settings rs = adh_relax_settings_default();
    adh_run run;
    adh_run_init(&run);
    int rc = adh_runner_rule(&adh_rule_relax, g, k, m, &rs, &ps, NULL, NULL, &run);
    char edge[400];
    adh_rings_edge_sentence(g, run.nrows ? run.rows[run.nrows - 1].a : 0, edge, sizeof edge);
    ok(rc == ADH_EGRID && run.nrows > 0 && !strcmp(run.why, edge) &&
       run.fix == adh_rings_edge_fix(g, run.rows[run.nrows - 1].a) && run.fix != 0u,
       "the relaxation at the grid's edge: the rings' sentence and what to change (%s; fix %#x)", run.why, run.fix);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* adhere fit's model on the same grid: its first evaluation stops at the
 * grid's edge, and the result says why as a run does (the rings' sentence,
 * what to change), for the relaxation model and the static one; the fit's
 * status is the model's error at the start. */
static void fit_stops(const adh_material *m)
{
    enum { N = 24 };
    static double x[N], F[N];
    static int dir[N], contact[N], seg[N];
    for (int i = 0; i < N; i++) {   /* 3 nm down to -2.5 nm and back up */
        int back = i >= N / 2;
        x[i] = back ? -2.5e-9 + (i - N / 2) * 0.5e-9 : 3e-9 - i * 0.5e-9;
        dir[i] = back ? -1 : 1, seg[i] = back, contact[i] = x[i] < 0;
        F[i] = 0;
    }
    adh_fit_data d = { N, x, F, dir, contact, seg };
    adh_grid *g = adh_grid_alloc(20, 10e-9);
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    if (!k) {
        printf("Bail out! out of memory\n");
        exit(1);
    }
    for (int kind = ADH_FIT_MODEL_STATIC; kind <= ADH_FIT_MODEL_RELAX; kind++) {
        adh_fit_settings s = adh_fit_settings_default();
        s.free = 1u << ADH_FIT_E;
        s.start = *m;
        s.model.kind = (adh_fit_model_kind)kind;
        int st;
        adh_fit *f = adh_fit_alloc(g, k, &d, &s, &st);
        adh_fit_result res;
        int rc = f ? adh_fit_run(f, &res) : st;
        ok(f && rc == ADH_EGRID && res.model_status == ADH_EGRID && res.failed > 0 && !isfinite(res.chi2) &&
           strstr(res.model_why, "reached the grid's edge (0.9 Rmax = 180 nm): use more nodes or a larger spacing") &&
           res.model_fix != 0u,
           "a fit whose %s model stops at the grid's edge: the status, the rings' sentence, what to change (%s: %s; fix %#x)",
           kind == ADH_FIT_MODEL_RELAX ? "relaxation" : "static", adh_strerror(rc), f ? res.model_why : "",
           f ? res.model_fix : 0u);
        adh_fit_free(f);
    }
    adh_kernel_free(k);
    adh_grid_free(g);
}

int main(void)
{
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(300, adh_grid_default_spacing(&m));
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    if (!k) {
        printf("Bail out! out of memory\n");
        return 1;
    }
    static_stops(g, k, &m);
    visco_stops(g, k, &m);
    relax_edge(&m);
    fit_stops(&m);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
