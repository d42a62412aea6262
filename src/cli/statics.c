#include "cli/statics.h"

#include <math.h>
#include <stdio.h>

int cli_static_run(const adh_config *cfg, const adh_grid *g, const adh_kernel *k,
                       adh_step_cb cb, void *ctx, adh_run *run, adh_static_result *res)
{
    adh_static_settings s = adh_static_settings_default();
    /* The same start as the relaxation run, so the two curves share an axis. */
    s.h0_start = isnan(cfg->proto.start) ? adh_protocol_auto_start(&cfg->mat, cfg->proto.step)
                                         : cfg->proto.start;
    for (size_t i = 0; i < cfg->proto.nturns; i++)
        s.h0_end = i == 0 ? cfg->proto.turns[0] : fmin(s.h0_end, cfg->proto.turns[i]);
    s.cancel = cfg->relax.cancel;   /* the one cancel flag of the run */
    return adh_static_run(g, k, &cfg->mat, &s, cb, ctx, run, res);
}

size_t cli_static_summary_keys(const adh_static_result *res, const char *prefix,
                               char names[][32], cli_summary_extra *extra)
{
    const struct { const char *key; double value; } v[ADH_STATIC_KEYS] = {
        { "jump_in_h0", res->jump_in_h0 },
        { "jump_out_h0", res->jump_out_h0 },
        { "pulloff_F", res->pulloff_F },
        { "pulloff_h0", res->pulloff_h0 },
        { "pulloff_F_disp", res->pulloff_F_disp },
        { "folds", (double)res->folds },
        { "points", (double)res->points },
        { "newton_iterations", (double)res->newton_iterations },
    };
    for (size_t i = 0; i < ADH_STATIC_KEYS; i++) {
        snprintf(names[i], 32, "%s%s", prefix, v[i].key);
        extra[i].key = names[i];
        extra[i].value = v[i].value;
    }
    return ADH_STATIC_KEYS;
}
