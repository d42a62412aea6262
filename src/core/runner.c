#include "adhere/runner.h"

#include <string.h>

#include "adhere/rule_static.h"
#include "adhere/status.h"

int adh_runner_drive(adh_drive *d, adh_step_cb cb, void *ctx)
{
    adh_run *run = adh_drive_record(d);
    int rc;
    while ((rc = adh_drive_step(d)) == ADH_CONTINUE)
        if (cb && cb(adh_drive_row(d), run, ctx)) {
            run->interrupted = 1;
            return ADH_SUCCESS;
        }
    if (rc == ADH_EINTR) {
        run->interrupted = 1;   /* stopped on request: not an error, the run says so */
        rc = ADH_SUCCESS;
    }
    return rc;
}

/* A drive of rule type set to ps, stepped to the end; its workspace is
 * left to summary (may be NULL) before the drive goes. */
static int run_rule(const adh_rule_type *type, const adh_grid *g, const adh_kernel *k, const adh_material *m,
                    const void *settings, const adh_protocol_settings *ps, adh_step_cb cb, void *ctx,
                    adh_run *run, adh_static_result *res)
{
    adh_drive *d = adh_drive_alloc(type, g, k);
    if (!d) {
        run->status = ADH_ENOMEM;
        return run->status;
    }
    int rc = adh_drive_set(d, m, settings, ps, run);
    if (rc == ADH_SUCCESS)
        rc = adh_runner_drive(d, cb, ctx);
    if (res) {
        const adh_static *w = adh_rule_static_solver(d);
        memset(res, 0, sizeof *res);
        if (w)
            adh_static_summary(w, res);
    }
    adh_drive_free(d);
    run->status = rc;
    return rc;
}

int adh_runner_rule(const adh_rule_type *type, const adh_grid *g, const adh_kernel *k, const adh_material *m,
                    const void *settings, const adh_protocol_settings *ps, adh_step_cb cb, void *ctx,
                    adh_run *run)
{
    return run_rule(type, g, k, m, settings, ps, cb, ctx, run, NULL);
}

int adh_runner_static(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_static_settings *s,
                      const adh_protocol_settings *ps, adh_step_cb cb, void *ctx, adh_run *run,
                      adh_static_result *res)
{
    return run_rule(&adh_rule_static, g, k, m, s, ps, cb, ctx, run, res);
}

int adh_runner_static_curve(const adh_grid *g, const adh_kernel *k, const adh_material *m,
                            const adh_static_settings *s, adh_step_cb cb, void *ctx, adh_run *run,
                            adh_static_result *res)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.nturns = 0;   /* the settings' own end */
    ps.start = s->h0_start;
    return adh_runner_static(g, k, m, s, &ps, cb, ctx, run, res);
}
