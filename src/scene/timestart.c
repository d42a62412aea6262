/* Whether each run of a configuration in physical time can start where it
 * says (adh_visco_start_check on its own grid and kernel): asked by every
 * driver before a run, the CLI once memory is bounded and the TUI at each
 * edit, so a start is refused alike wherever it is given. */
#include "scene/config.h"

#include <math.h>
#include <stdio.h>

#include "adhere/kernel.h"
#include "adhere/rule_visco.h"
#include "adhere/status.h"
#include "adhere/visco.h"

/* A solid's start on grid g, kernel k (built here when NULL, for the
 * caller to free): ADH_SUCCESS, or why with *fix. */
static int start_check(const adh_run_spec *spec, adh_grid **g, adh_kernel **k, char *why, size_t whylen,
                       unsigned *fix)
{
    int st = ADH_ENOMEM;
    if (!*g)
        *g = adh_config_grid_alloc(spec);
    if (*g && !*k)
        *k = adh_config_kernel_alloc(spec, *g, &st);
    adh_visco_rule_settings vs;
    adh_config_visco(spec, &vs);
    if (*k)
        st = adh_visco_start_check(*g, *k, &spec->mat, &vs.sls, &vs.drive, &spec->proto, why, whylen, fix);
    else
        snprintf(why, whylen, "out of memory building the %zu-node kernel to check the start",
                 *g ? (*g)->n : spec->grid.use.nodes);
    return st;
}

int adh_config_start_check(const adh_config *cfg, char *why, size_t whylen, unsigned *fix)
{
    size_t n = cfg->sweep.naxes ? adh_config_nruns(cfg) : 1;
    adh_run_spec run, built;
    adh_grid *g = NULL;
    adh_kernel *k = NULL;
    int rc = ADH_SUCCESS;
    *fix = 0;
    for (size_t i = 0; i < n && rc == ADH_SUCCESS; i++) {
        adh_config_sweep_run(cfg, i, &run);
        /* the automatic start is one (test_visco_input, E0 from 1 MPa to
         * 1 TPa): a kernel is built here only for a start given, where a
         * large one costs seconds */
        if (run.mode != ADH_MODE_TIME || adh_config_time_rule(&run) != &adh_rule_visco || isnan(run.proto.start))
            continue;
        if (g && !adh_config_same_grid(&built, &run)) {   /* a sweep's runs share a grid where they can */
            adh_kernel_free(k);
            adh_grid_free(g);
            g = NULL, k = NULL;
        }
        built = run;
        char msg[1024], which[256];
        if ((rc = start_check(&run, &g, &k, msg, sizeof msg, fix)) == ADH_SUCCESS)
            continue;
        if (!cfg->sweep.naxes) {
            snprintf(why, whylen, "%s", msg);
            break;
        }
        adh_sweep_describe(&cfg->sweep, i, which, sizeof which);
        snprintf(why, whylen, "sweep run %zu (%s): %s", i + 1, which, msg);
    }
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc;
}
