#include "cli/estimate.h"

#include <math.h>
#include <stdlib.h>

#include "adhere/clock.h"
#include "adhere/kernel.h"
#include "cli/progress.h"

double cli_estimate_cpu_per_call(cli_estimate_fn fn, void *ctx, size_t min_reps, double min_seconds)
{
    size_t reps = 0;
    double t0 = adh_clock_cpu_seconds(), t = t0;
    while (reps < min_reps || t - t0 < min_seconds) {
        fn(ctx);
        reps++;
        t = adh_clock_cpu_seconds();
    }
    return (t - t0) / (double)reps;
}

typedef struct product_job {
    const adh_kernel *k;
    size_t n;
    double *v;
} product_job;

static void product_once(void *ctx)
{
    product_job *j = ctx;
    adh_kernel_apply(j->k, j->v, j->v + j->n, j->v + 2 * j->n);
}

double cli_estimate_product_seconds(const adh_kernel *k, size_t n, double *v, size_t min_reps, double min_seconds)
{
    product_job pj = { k, n, v };
    return cli_estimate_cpu_per_call(product_once, &pj, min_reps, min_seconds);
}

double cli_estimate_iteration(const adh_config *cfg, double *build)
{
    /* CPU seconds, not wall: on a shared machine the wall clock times
     * the other jobs too, and the estimate is of this run's work */
    double t0 = adh_clock_cpu_seconds();
    adh_grid *g = adh_config_grid_alloc(&cfg->spec);
    int st = 0;
    adh_kernel *k = g ? adh_config_kernel_alloc(&cfg->spec, g, &st) : NULL;
    *build = adh_clock_cpu_seconds() - t0;
    double *v = k ? malloc(3 * g->n * sizeof *v) : NULL;
    double per = NAN;
    if (v) {
        for (size_t i = 0; i < g->n; i++)
            v[i] = 1.0 / (1.0 + (double)i);   /* a pressure falling off from the axis */
        per = cli_estimate_product_seconds(k, g->n, v, 5, 0.2);
    }
    free(v);
    adh_kernel_free(k);
    adh_grid_free(g);
    return per;
}

void cli_estimate_print(FILE *f, const adh_config *cfg, const adh_plan *plan)
{
    if (!plan->elastic) {
        fprintf(f, "time: under a second (eq 22 at each position, no elastic solve)\n");
        return;
    }
    if (plan->time_mode) {
        cli_estimate_time_print(f, cfg, plan);
        return;
    }
    if (plan->static_mode) {
        fprintf(f, "time: not estimated: the static curve's Newton steps cost as its folds and grid make them "
                   "(seconds on the paper's grid, up to some 20 s at sigma = 100)\n");
        return;
    }
    double build, per = cli_estimate_iteration(cfg, &build);
    if (!isfinite(per)) {
        fprintf(f, "time: not estimated (the kernel could not be built here)\n");
        return;
    }
    /* the runs, jobs at a time, at one iteration per kernel product */
    /* the runs the plan lists (a study's first ADH_PLAN_MAX_RUNS: its own
     * line, from a pilot, has them all) */
    static adh_plan_progress runs[ADH_PLAN_MAX_RUNS];
    size_t n = plan->nruns < ADH_PLAN_MAX_RUNS ? plan->nruns : ADH_PLAN_MAX_RUNS;
    double iterations = 0;
    for (size_t i = 0; i < n; i++) {
        runs[i] = (adh_plan_progress){ .cost = plan->runs[i].iterations };
        iterations += plan->runs[i].iterations;
    }
    double wall = build + adh_plan_time_left(runs, n, plan->jobs, 0, 1.0 / per);
    char t[32];
    cli_progress_duration(wall, t, sizeof t);
    fprintf(f, "time: about %s (%.2g iterations, each about one kernel product: %.3g ms of CPU on this machine, "
               "timed now%s; the kernel built in %.2g s)%s\n", t, iterations, per * 1e3,
            plan->jobs > 1 ? ", the runs shared out over the jobs" : "", build,
            n < plan->nruns ? "; the first runs alone" : "");
}
