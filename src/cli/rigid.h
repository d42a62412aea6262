/* A rigid-spheres run: the force of eq 22 at each drive position, for
 * scenes whose outputs need nothing else (mode = rigid). No grid, kernel or
 * relaxation is allocated; the rows look like a loading branch's so the same
 * tables and plots read them. */
#ifndef ADH_CLI_RIGID_H
#define ADH_CLI_RIGID_H

#include "adhere/protocol.h"
#include "scene/config.h"

/* Fills run with one loading row per drive position, start - k d down to
 * adh_plan_rigid_end(cfg). cb (may be NULL) sees every row and may stop the
 * run. ADH_SUCCESS or ADH_ENOMEM. */
int cli_rigid_run(const adh_config *cfg, adh_step_cb cb, void *ctx, adh_run *run);

#endif
