/* The static (equilibrium) curve for a configuration: --mode=static and
 * --reference=static both run it through here. */
#ifndef ADH_CLI_STATIC_H
#define ADH_CLI_STATIC_H

#include <stdio.h>

#include "adhere/runner.h"
#include "adhere/static.h"
#include "scene/config.h"

/* Follows spec's equilibrium curve from the run's start down to its deepest
 * turn (or -5 nm) on grid g with kernel k, appending rows to run. */
int cli_static_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res);

/* The run of relaxation run spec's static reference (mode static): its own
 * automatic grid, resolved for the static curve, where spec's grid follows
 * the material and the static one is within the budget; else spec's grid.
 * 1 when that grid resolves the static curve, else 0 with why. */
int cli_static_reference_spec(const adh_run_spec *spec, adh_run_spec *ss, char *why, size_t whylen);

/* --reference=static: the static curve of relaxation run spec into ref, on
 * the grid above (g and k, the relaxation's, when it is theirs; else built
 * here and freed). *resolved says whether that grid resolves it, and why
 * not. The status of the curve. */
int cli_static_reference(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k, adh_run *ref,
                         adh_static_result *res, int *resolved, char *why, size_t whylen);

/* The plan's line for the reference (--plan --reference=static). */
void cli_static_reference_plan(FILE *f, const adh_run_spec *spec);

#endif
