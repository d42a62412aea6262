/* A grid and its kernel kept between calls for the run they were built
 * for (scene/config.h, adh_config_kept): a caller that asks again and again
 * for one run's kernel (the screen's start check at every edit) builds it
 * once, and again only when the grid it depends on changes. */
#include "scene/config.h"

#include <string.h>

#include "adhere/status.h"

void adh_config_kept_init(adh_config_kept *kp)
{
    memset(kp, 0, sizeof *kp);
}

void adh_config_kept_drop(adh_config_kept *kp)
{
    if (!kp->lent) {
        adh_kernel_free(kp->k);
        adh_grid_free(kp->g);
    }
    kp->g = NULL;
    kp->k = NULL;
    kp->lent = 0;
}

void adh_config_kept_lend(adh_config_kept *kp, const adh_run_spec *s, adh_grid *g, adh_kernel *k)
{
    adh_config_kept_drop(kp);
    kp->spec = *s;
    kp->g = g;
    kp->k = k;
    kp->lent = 1;
}

int adh_config_kept_take(adh_config_kept *kp, const adh_run_spec *s, adh_grid **g, adh_kernel **k)
{
    if (!kp->k || kp->lent || !adh_config_same_grid(&kp->spec, s))
        return 0;
    *g = kp->g;
    *k = kp->k;
    kp->g = NULL;
    kp->k = NULL;
    return 1;
}

int adh_config_kept_get(adh_config_kept *kp, const adh_run_spec *s)
{
    if (kp->k && adh_config_same_grid(&kp->spec, s))
        return ADH_SUCCESS;
    adh_config_kept_drop(kp);
    int st = ADH_ENOMEM;
    kp->spec = *s;
    kp->g = adh_config_grid_alloc(s);
    kp->k = kp->g ? adh_config_kernel_alloc(s, kp->g, &st) : NULL;
    if (kp->k) {
        kp->built++;
        return ADH_SUCCESS;
    }
    return st;
}
