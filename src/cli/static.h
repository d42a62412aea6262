/* The static (equilibrium) curve for a configuration: --mode=static and
 * --reference=static both run it through here. */
#ifndef ADH_CLI_STATIC_H
#define ADH_CLI_STATIC_H

#include "adhere/runner.h"
#include "adhere/static.h"
#include "scene/config.h"

/* Follows spec's equilibrium curve from the run's start down to its deepest
 * turn (or -5 nm) on grid g with kernel k, appending rows to run. */
int cli_static_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res);

#endif
