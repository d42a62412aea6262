#include "adhere/run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"

void adh_run_init(adh_run *run)
{
    memset(run, 0, sizeof *run);
    run->jump_in_h0 = NAN;
    run->status = ADH_SUCCESS;
}

void adh_run_free(adh_run *run)
{
    for (size_t i = 0; i < run->nprofiles; i++)
        free(run->profiles[i].u);
    free(run->profiles);
    free(run->rows);
    adh_run_init(run);
}

int adh_run_separated(const adh_run *run, char *why, size_t whylen)
{
    for (size_t i = 0; i < run->nturns; i++) {
        const adh_turn_result *t = &run->turns[i];
        if (t->path <= 0 || isfinite(t->jump_out_h0))
            continue;
        double a_end = NAN, h_end = NAN;
        for (size_t j = run->nrows; j-- > 0;)
            if (run->rows[j].path == t->path) {
                a_end = run->rows[j].a;
                h_end = run->rows[j].h0;
                break;
            }
        snprintf(why, whylen, "the surfaces never separated: unloading from the turn at h0 = %.4g m ended at "
                 "h0 = %.4g m still in contact (contact radius %.4g m), so there is no jump-out and the "
                 "pull-off is only the lowest force seen", t->h0, h_end, a_end);
        return 0;
    }
    return 1;
}

const adh_turn_result *adh_run_main_turn(const adh_run *run)
{
    for (size_t i = run->nturns; i-- > 0;)
        if (run->turns[i].path > 0)
            return &run->turns[i];
    return NULL;
}

int adh_run_push_row(adh_run *run, const adh_obs *o)
{
    if (run->nrows == run->rows_cap) {
        size_t cap = run->rows_cap ? 2 * run->rows_cap : 256;
        adh_obs *p = realloc(run->rows, cap * sizeof *p);
        if (!p)
            return ADH_ENOMEM;
        run->rows = p;
        run->rows_cap = cap;
    }
    run->rows[run->nrows++] = *o;
    return ADH_SUCCESS;
}

int adh_run_push_profile(adh_run *run, const adh_state *s, int branch, int path)
{
    if (run->nprofiles == run->profiles_cap) {
        size_t cap = run->profiles_cap ? 2 * run->profiles_cap : 16;
        adh_profile *p = realloc(run->profiles, cap * sizeof *p);
        if (!p)
            return ADH_ENOMEM;
        run->profiles = p;
        run->profiles_cap = cap;
    }
    adh_profile *pr = &run->profiles[run->nprofiles];
    pr->u = malloc(3 * s->n * sizeof(double));
    if (!pr->u)
        return ADH_ENOMEM;
    memcpy(pr->u, s->u, 3 * s->n * sizeof(double));
    pr->h = pr->u + s->n;
    pr->p = pr->u + 2 * s->n;
    pr->h0 = s->h0;
    pr->branch = branch;
    pr->path = path;
    run->nprofiles++;
    return ADH_SUCCESS;
}
