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

int cli_estimate_kernel(const adh_run_spec *s, const adh_grid *g, double *v, size_t min_reps, double min_seconds,
                        cli_estimate_kernel_cost *kc)
{
    /* CPU seconds, not wall: on a shared machine the wall clock times
     * the other jobs too, and the estimate is of this run's work */
    double t0 = adh_clock_cpu_seconds();
    adh_run_spec timed = *s;
    double scale = 1.0;   /* the grid's nodes over the timed kernel's */
    if (s->grid.use.storage == ADH_STORAGE_DENSE && g->n > CLI_ESTIMATE_DENSE_MAX) {
        timed.grid.use.nodes = CLI_ESTIMATE_DENSE_MAX;
        timed.grid.use.graded = 0;
        timed.grid.use.spacing = g->r[g->n - 1] / (double)CLI_ESTIMATE_DENSE_MAX;
        scale = (double)g->n / CLI_ESTIMATE_DENSE_MAX;
    }
    adh_grid *tg = scale > 1.0 ? adh_config_grid_alloc(&timed) : NULL;
    const adh_grid *kg = scale > 1.0 ? tg : g;
    int st = 0;
    adh_kernel *k = kg ? adh_config_kernel_alloc(&timed, kg, &st) : NULL;
    int rc = -1;
    if (k) {
        kc->build = (adh_clock_cpu_seconds() - t0) * scale * scale;
        kc->timed_n = kg->n;
        kc->hierarchical = adh_kernel_storage_of(k) != ADH_STORAGE_DENSE;
        kc->product = cli_estimate_product_seconds(k, kg->n, v, min_reps, min_seconds) * scale * scale;
        rc = 0;
    }
    adh_kernel_free(k);
    adh_grid_free(tg);
    return rc;
}

double cli_estimate_iteration(const adh_config *cfg, double *build, size_t *timed_n)
{
    adh_grid *g = adh_config_grid_alloc(&cfg->spec);
    double *v = g ? malloc(3 * g->n * sizeof *v) : NULL;
    double per = NAN;
    cli_estimate_kernel_cost kc;
    if (v) {
        for (size_t i = 0; i < g->n; i++)
            v[i] = 1.0 / (1.0 + (double)i);   /* a pressure falling off from the axis */
        if (cli_estimate_kernel(&cfg->spec, g, v, 5, 0.2, &kc) == 0) {
            per = kc.product;
            *build = kc.build;
            *timed_n = kc.timed_n;
        }
    }
    free(v);
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
        /* a study's too: a pilot on a coarse grid met folds the real grid
         * has not (studycost.c) */
        fprintf(f, "time: not estimated: the static curve's Newton steps cost as its folds and grid make them "
                   "(seconds on the paper's grid, up to some 20 s at sigma = 100)");
        if (plan->drives > 1)
            fprintf(f, "; the study solves %zu curves, %d at a time", plan->drives, plan->jobs);
        fputc('\n', f);
        return;
    }
    double build;
    size_t timed_n;
    double per = cli_estimate_iteration(cfg, &build, &timed_n);
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
    char t[32], timed[160] = "";
    cli_progress_duration(wall, t, sizeof t);
    size_t nodes = adh_config_nodes(&cfg->spec);
    /* an estimate from a smaller grid says so (cli_estimate_kernel) */
    if (timed_n < nodes)
        snprintf(timed, sizeof timed, " on a smaller grid, %zu nodes, and scaled as N^2 to its %zu", timed_n, nodes);
    fprintf(f, "time: about %s (%.2g iterations, each about one kernel product: %.3g ms of CPU on this machine, "
               "timed now%s%s; the kernel built in %.2g s%s)%s\n", t, iterations, per * 1e3, timed,
            plan->jobs > 1 ? ", the runs shared out over the jobs" : "", build, timed_n < nodes ? ", scaled alike" : "",
            n < plan->nruns ? "; the first runs alone" : "");
}
