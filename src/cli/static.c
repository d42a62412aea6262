#include "cli/static.h"

#include "scene/plan.h"

int cli_static_run(const adh_config *cfg, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res)
{
    adh_static_settings s = adh_static_settings_default();
    /* The same start as the relaxation run, so the two curves share an axis. */
    s.h0_start = adh_plan_start(cfg);
    if (cfg->proto.nturns)
        s.h0_end = adh_protocol_deepest_turn(&cfg->proto);
    s.cancel = cfg->relax.cancel;   /* the one cancel flag of the run */
    return adh_static_run(g, k, &cfg->mat, &s, cb, ctx, run, res);
}
