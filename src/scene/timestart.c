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

/* A solid's start on the grid and kernel kept in kp (built there when
 * the run's grid is not the one kept): ADH_SUCCESS, or why with *fix. */
static int start_check(const adh_run_spec *spec, adh_config_kept *kp, char *why, size_t whylen, unsigned *fix)
{
    int st = adh_config_kept_get(kp, spec);
    if (st != ADH_SUCCESS) {
        snprintf(why, whylen, "%s building the %zu-node kernel to check the start",
                 st == ADH_EINTR ? "interrupted" : "out of memory", adh_config_nodes(spec));
        return st;
    }
    adh_visco_rule_settings vs;
    adh_config_visco(spec, &vs);
    return adh_visco_start_check(kp->g, kp->k, &spec->mat, &vs.sls, &vs.drive, &spec->proto, why, whylen, fix);
}

/* Each run's start on the grid and kernel kept in kp; keyed: the refusal
 * names the start as a key (adh_config_key_opening). */
static int check(const adh_config *cfg, adh_config_kept *kp, int keyed, char *why, size_t whylen, unsigned *fix)
{
    size_t n = cfg->sweep.naxes ? adh_config_nruns(cfg) : 1;
    adh_run_spec run;
    int rc = ADH_SUCCESS, used = 0;
    *fix = 0;
    for (size_t i = 0; i < n && rc == ADH_SUCCESS; i++) {
        adh_config_sweep_run(cfg, i, &run);
        /* the automatic start is one (test_visco_input, E0 from 1 MPa to
         * 1 TPa): a kernel is built here only for a start given, where a
         * large one costs seconds; a sweep's runs share a grid where they
         * can, and an edit on the screen that leaves it builds none */
        if (run.mode != ADH_MODE_TIME || adh_config_time_rule(&run) != &adh_rule_visco || isnan(run.proto.start))
            continue;
        char msg[1024], which[256];
        used = 1;
        if ((rc = start_check(&run, kp, msg, sizeof msg, fix)) == ADH_SUCCESS)
            continue;
        char said[1024];
        if (!keyed || !adh_config_key_opening(cfg, &run, msg, said, sizeof said))
            snprintf(said, sizeof said, "%s", msg);
        if (!cfg->sweep.naxes) {
            snprintf(why, whylen, "%s", said);
            break;
        }
        adh_sweep_describe(&cfg->sweep, i, which, sizeof which);
        snprintf(why, whylen, "sweep run %zu (%s): %s", i + 1, which, said);
    }
    if (!used)   /* nothing to check now: no kernel held for nothing */
        adh_config_kept_drop(kp);
    return rc;
}

int adh_config_start_check_kept(const adh_config *cfg, adh_config_kept *kp, char *why, size_t whylen,
                                unsigned *fix)
{
    return check(cfg, kp, 0, why, whylen, fix);
}

int adh_config_start_check(const adh_config *cfg, int keyed, char *why, size_t whylen, unsigned *fix)
{
    adh_config_kept kp;
    adh_config_kept_init(&kp);
    int rc = check(cfg, &kp, keyed, why, whylen, fix);
    adh_config_kept_drop(&kp);
    return rc;
}
