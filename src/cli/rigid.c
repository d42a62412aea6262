#include "cli/rigid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/status.h"
#include "scene/plan.h"

int cli_rigid_run(const adh_config *cfg, adh_step_cb cb, void *ctx, adh_run *run)
{
    const adh_material *m = &cfg->mat;
    double step = cfg->proto.step;
    double start = adh_plan_start(cfg), end = adh_plan_rigid_end(cfg);
    size_t n = 1 + (size_t)floor((start - end) / step + 1e-6);
    run->start = start;
    run->rows = calloc(n, sizeof *run->rows);
    if (!run->rows) {
        run->status = ADH_ENOMEM;
        return run->status;
    }
    run->rows_cap = n;
    for (size_t k = 0; k < n; k++) {
        adh_obs *o = &run->rows[run->nrows++];
        o->h0 = start - (double)k * step; /* afresh, never accumulated: as the core does */
        o->F = o->F_rigid = adh_rigid_force(m, o->h0);
        o->hc = o->h0;
        /* undeformed spheres: in contact where h0 + r^2/2R < 1.1 z0 */
        double reach = ADH_CONTACT_FACTOR * m->z0 - o->h0;
        o->a = reach > 0 ? sqrt(2.0 * m->R * reach) : 0.0;
        o->branch = +1;
        o->converged = 1;
        o->stable = 1;
        if (o->a > 0 && isnan(run->jump_in_h0))
            run->jump_in_h0 = o->h0;
        if (cb && cb(o, run, ctx)) {
            run->interrupted = 1;
            break;
        }
    }
    run->status = ADH_SUCCESS;
    return run->status;
}
