/* --plan's estimated time: the plan's expected iterations, each about one
 * product of the run's kernel, timed here on the grid the run will use. */
#ifndef ADH_CLI_ESTIMATE_H
#define ADH_CLI_ESTIMATE_H

#include <stdio.h>

#include "scene/config.h"
#include "scene/plan.h"

/* The seconds of one relaxation iteration on cfg's grid: the kernel built
 * (*build gets how long that took) and applied until 0.2 s have passed (at
 * least 5 times). NAN when the grid or kernel cannot be made. */
double cli_estimate_iteration(const adh_config *cfg, double *build);

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
