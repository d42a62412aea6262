#include "cli/static.h"

int cli_static_run(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k,
                   adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res)
{
    adh_static_settings s = adh_static_settings_default();
    s.cancel = spec->relax.cancel;   /* the one cancel flag of the run */
    /* The same start as the relaxation run, so the two curves share an
     * axis; the drive ends the curve at the protocol's deepest turn. */
    adh_protocol_settings ps = spec->proto;
    ps.start = adh_config_start(spec);
    return adh_runner_static(g, k, &spec->mat, &s, &ps, cb, ctx, run, res);
}
