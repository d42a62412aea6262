/* The static (equilibrium) curve for a configuration: --mode=static and
 * --reference=static both run it through here. */
#ifndef ADH_CLI_STATICS_H
#define ADH_CLI_STATICS_H

#include "adhere/static.h"
#include "adhere/protocol.h"
#include "cli/tables.h"
#include "scene/config.h"

/* Follows the equilibrium curve from the run's start down to its deepest
 * turn (or -5 nm) on grid g with kernel k, appending rows to run. */
int cli_static_run(const adh_config *cfg, const adh_grid *g, const adh_kernel *k,
                       adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res);

/* The summary keys of a static result, prefixed ("" or "static_"), into
 * extra[] (at most ADH_STATIC_KEYS entries); returns how many. */
#define ADH_STATIC_KEYS 8
size_t cli_static_summary_keys(const adh_static_result *res, const char *prefix,
                               char names[][32], cli_summary_extra *extra);

#endif
