#include "cli/static.h"

#include "scene/plan.h"

int cli_static_run(const adh_config *cfg, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res)
{
    adh_static_settings s = adh_static_settings_default();
    s.cancel = cfg->relax.cancel;   /* the one cancel flag of the run */
    /* The same start as the relaxation run, so the two curves share an
     * axis; the drive ends the curve at the protocol's deepest turn. */
    adh_protocol_settings ps = cfg->proto;
    ps.start = adh_plan_start(cfg);
    return adh_runner_static(g, k, &cfg->mat, &s, &ps, cb, ctx, run, res);
}
