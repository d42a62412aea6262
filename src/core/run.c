#include "adhere/run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"
#include "adhere/units.h"

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
        int touched = t->a_turn > 0;
        for (size_t j = run->nrows; j-- > 0;)
            if (run->rows[j].path == t->path) {
                if (isnan(a_end)) {
                    a_end = run->rows[j].a;
                    h_end = run->rows[j].h0;
                }
                touched |= run->rows[j].a > 0;
            }
        /* a turn above the jump-in (beside deeper ones): its branch was
         * never in contact, so there was nothing to separate */
        if (!touched)
            continue;
        snprintf(why, whylen, "the surfaces never separated: unloading from the turn at h0 = %s ended at "
                 "h0 = %s still in contact (contact radius %s), so there is no jump-out and %s",
                 adh_qtext(t->h0, ADH_Q_LENGTH).s, adh_qtext(h_end, ADH_Q_LENGTH).s, adh_qtext(a_end, ADH_Q_LENGTH).s,
                 /* (none where the unloading could not go on: physical time past a start in contact) */
                 isnan(t->pulloff_F) ? "no pull-off" : "the pull-off is only the lowest force seen");
        return 0;
    }
    return 1;
}

int adh_run_touched(const adh_run *run, double h_star, char *why, size_t whylen)
{
    double turn = INFINITY;
    for (size_t i = 0; i < run->nrows; i++) {
        if (run->rows[i].a > 0)
            return 1;
        if (run->rows[i].path == 0)
            turn = fmin(turn, run->rows[i].h0);
    }
    if (run->nrows == 0)
        return 1;
    snprintf(why, whylen, "the surfaces never came into contact: the drive turned at h0 = %s with the contact "
             "radius still 0, so there is no jump-in, pull-off or jump-out, and the lowest force is only the force "
             "at the turn; put the turn below the jump into contact, at h0 = 0 for one (eq 24's gap there is "
             "h* = %s)", adh_qtext(turn, ADH_Q_LENGTH).s, adh_qtext(h_star, ADH_Q_LENGTH).s);
    return 0;
}

const adh_turn_result *adh_run_main_turn(const adh_run *run)
{
    for (size_t i = run->nturns; i-- > 0;)
        if (run->turns[i].path > 0)
            return &run->turns[i];
    return NULL;
}

/* items with room for one more element (the array doubles, from first);
 * NULL when memory ran out, the old array still the caller's. */
static void *grow(void *items, size_t *cap, size_t n, size_t size, size_t first)
{
    if (n < *cap)
        return items;
    size_t c = *cap ? 2 * *cap : first;
    void *p = realloc(items, c * size);
    if (p)
        *cap = c;
    return p;
}

int adh_run_push_row(adh_run *run, const adh_obs *o)
{
    adh_obs *rows = grow(run->rows, &run->rows_cap, run->nrows, sizeof *rows, 256);
    if (!rows)
        return ADH_ENOMEM;
    run->rows = rows;
    run->rows[run->nrows++] = *o;
    return ADH_SUCCESS;
}

int adh_run_push_profile(adh_run *run, const adh_state *s, int branch, int path)
{
    adh_profile *profiles = grow(run->profiles, &run->profiles_cap, run->nprofiles, sizeof *profiles, 16);
    if (!profiles)
        return ADH_ENOMEM;
    run->profiles = profiles;
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

long adh_run_next_on_path(const adh_run *run, size_t i)
{
    for (size_t j = i + 1; j < run->nrows; j++)
        if (run->rows[j].path == run->rows[i].path)
            return (long)j;
    return -1;
}

long adh_run_prev_on_path(const adh_run *run, size_t i)
{
    for (size_t j = i; j-- > 0;)
        if (run->rows[j].path == run->rows[i].path)
            return (long)j;
    return -1;
}

/* The copy of profile p in out, as path (the state's n values each). */
static int copy_profile(adh_run *out, const adh_profile *p, size_t n, int path)
{
    adh_profile *profiles = grow(out->profiles, &out->profiles_cap, out->nprofiles, sizeof *profiles, 16);
    if (!profiles)
        return ADH_ENOMEM;
    out->profiles = profiles;
    adh_profile *q = &out->profiles[out->nprofiles];
    *q = *p;
    q->path = path;
    if (!(q->u = malloc(3 * n * sizeof(double))))
        return ADH_ENOMEM;
    memcpy(q->u, p->u, 3 * n * sizeof(double));
    q->h = q->u + n;
    q->p = q->u + 2 * n;
    out->nprofiles++;
    return ADH_SUCCESS;
}

int adh_run_turn(const adh_run *src, size_t t, size_t n, adh_run *out)
{
    adh_run_init(out);
    const adh_turn_result *tr = &src->turns[t];
    int rc = ADH_SUCCESS;
    out->start = src->start;
    /* the loading branch down to the turn's row, then the turn's unloading branch as path 1 */
    int reached = 0;
    for (size_t i = 0; i < src->nrows && rc == ADH_SUCCESS && !reached; i++)
        if (src->rows[i].path == 0) {
            rc = adh_run_push_row(out, &src->rows[i]);
            reached = src->rows[i].h0 == tr->h0;
        }
    for (size_t i = 0; i < src->nrows && rc == ADH_SUCCESS && tr->path > 0; i++)
        if (src->rows[i].path == tr->path) {
            adh_obs o = src->rows[i];
            o.path = 1;
            rc = adh_run_push_row(out, &o);
        }
    for (size_t i = 0; i < src->nprofiles && rc == ADH_SUCCESS; i++) {
        const adh_profile *p = &src->profiles[i];
        if ((p->path == 0 && p->h0 >= tr->h0) || (tr->path > 0 && p->path == tr->path))
            rc = copy_profile(out, p, n, p->path ? 1 : 0);
    }
    if (rc != ADH_SUCCESS) {
        adh_run_free(out);
        return rc;
    }
    out->turns[0] = *tr;
    out->turns[0].path = tr->path > 0 ? 1 : 0;
    out->nturns = 1;
    out->jump_in_h0 = src->jump_in_h0 >= tr->h0 ? src->jump_in_h0 : NAN;
    for (size_t i = 0; i < out->nrows; i++) {
        out->iterations += out->rows[i].iters;
        out->seconds += out->rows[i].seconds;
        out->unconverged += !out->rows[i].converged;
    }
    return ADH_SUCCESS;
}

void adh_run_take(adh_run *to, adh_run *from)
{
    /* the rule's own start (under a spring, outside the snap-in), not the
     * drive's automatic elastic one, which no row of it has */
    if (from->nrows)
        to->start = from->start;
    memcpy(to->turns, from->turns, sizeof to->turns);
    to->nturns = from->nturns;
    for (size_t i = 0; i < to->nprofiles; i++)
        free(to->profiles[i].u);   /* h and p share its block (adh_run_push_profile) */
    free(to->profiles);
    to->profiles = from->profiles;
    to->nprofiles = from->nprofiles;
    to->profiles_cap = from->profiles_cap;
    from->profiles = NULL;
    from->nprofiles = from->profiles_cap = 0;
}
