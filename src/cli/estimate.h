/* --plan's estimated time: the plan's expected iterations, each about one
 * product of the run's kernel, timed here on the grid the run will use. */
#ifndef ADH_CLI_ESTIMATE_H
#define ADH_CLI_ESTIMATE_H

#include <stdio.h>

#include "scene/config.h"
#include "scene/plan.h"

/* Above this many nodes a dense kernel is built and timed on a uniform
 * grid of this many over the same radius, its build and product scaled as
 * N^2 (a matrix of 128 MB, out of every cache as the larger ones are):
 * an estimate allocates no more than that, where the run holds 8 N^2
 * bytes (3.2 GB at N = 20000, a minute to build). */
#define CLI_ESTIMATE_DENSE_MAX 4000

/* A kernel's timings for an estimate, in CPU seconds. */
typedef struct cli_estimate_kernel_cost {
    double build;      /* building it */
    double product;    /* one product */
    size_t timed_n;    /* the nodes it was built and timed on: the grid's, or
                          CLI_ESTIMATE_DENSE_MAX with both scaled as N^2 */
    int hierarchical;  /* its storage is not dense */
} cli_estimate_kernel_cost;

/* The kernel of run spec s on its grid g built (or, dense past
 * CLI_ESTIMATE_DENSE_MAX nodes, a smaller one) and its product applied to
 * v (3 g->n numbers, the input first) as cli_estimate_cpu_per_call; the
 * kernel is freed. 0, or -1 when it cannot be built. */
int cli_estimate_kernel(const adh_run_spec *s, const adh_grid *g, double *v, size_t min_reps, double min_seconds,
                        cli_estimate_kernel_cost *kc);

/* The seconds of one relaxation iteration on cfg's grid: one kernel
 * product (cli_estimate_kernel: applied until 0.2 s have passed, at least
 * 5 times); *build gets the kernel's build, *timed_n the nodes timed on.
 * NAN when the grid or kernel cannot be made. */
double cli_estimate_iteration(const adh_config *cfg, double *build, size_t *timed_n);

/* CPU seconds a call of fn(ctx) takes: called at least min_reps times and
 * until min_seconds have passed. */
typedef void (*cli_estimate_fn)(void *ctx);
double cli_estimate_cpu_per_call(cli_estimate_fn fn, void *ctx, size_t min_reps, double min_seconds);

/* CPU seconds of one product of kernel k (n nodes) applied to v[0, n),
 * v holding 3 n (the product and its workspace after the input), timed
 * as cli_estimate_cpu_per_call. */
double cli_estimate_product_seconds(const adh_kernel *k, size_t n, double *v, size_t min_reps, double min_seconds);

/* "time: about 1 min 50 s (2.1e+05 iterations at 0.5 ms, ...)" for a
 * relaxation; what is not estimated, and why, otherwise. */
void cli_estimate_print(FILE *f, const adh_config *cfg, const adh_plan *plan);

/* The time line of a run (or study) in physical time (estimatetime.c):
 * the integrator's steps the plan expects (adh_plan_time_steps), each
 * priced by the kernel product, dense LU and law pass it takes, timed now
 * on the run's grid, in CPU seconds. */
void cli_estimate_time_print(FILE *f, const adh_config *cfg, const adh_plan *plan);

#endif
