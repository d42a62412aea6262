/* The standard linear solid as a step rule (adhere/rule_visco.h): a curve
 * rule over the viscoelastic solver (adhere/visco.h), whose own record
 * keeps the turns and profiles; each step hands the drive its row. */
#include "adhere/rule_visco.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"

typedef struct visco_rule {
    adh_visco *w;
    adh_run run;       /* the solver's record */
    int first;         /* the status the first step reports */
    int started;
    char why[320];     /* why the start failed (adh_visco_set) */
} visco_rule;

static void *visco_alloc(const adh_grid *g, const adh_kernel *k)
{
    visco_rule *r = calloc(1, sizeof *r);
    if (!r || !(r->w = adh_visco_alloc(g, k))) {
        free(r);
        return NULL;
    }
    adh_run_init(&r->run);
    return r;
}

static void visco_free(void *vr)
{
    visco_rule *r = vr;
    if (!r)
        return;
    adh_visco_free(r->w);
    adh_run_free(&r->run);
    free(r);
}

static int visco_set(void *vr, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                     double start)
{
    visco_rule *r = vr;
    adh_visco_rule_settings vs = settings ? *(const adh_visco_rule_settings *)settings
                                          : adh_visco_rule_settings_default(m->E);
    adh_protocol_settings p = *ps;
    /* the drive's automatic start is the elastic one; under a spring the
     * solver's own lies outside the snap-in */
    p.start = isnan(ps->start) && isfinite(vs.drive.spring) ? NAN : start;
    adh_run_free(&r->run);
    adh_run_init(&r->run);
    r->started = 0;
    r->why[0] = '\0';
    int rc = adh_visco_set(r->w, m, &vs.sls, &vs.drive, &vs.s, &p, &r->run, r->why, sizeof r->why);
    r->first = rc == ADH_SUCCESS ? ADH_CONTINUE : rc;
    return rc == ADH_EINVAL ? ADH_EINVAL : ADH_SUCCESS;
}

static int visco_next(void *vr)
{
    visco_rule *r = vr;
    if (!r->started) {
        r->started = 1;
        if (r->first != ADH_CONTINUE)
            return r->first;
    }
    int rc = adh_visco_iterate(r->w);
    return rc == ADH_CONTINUE && adh_visco_last(r->w) ? ADH_SUCCESS : rc;
}

static double visco_jump_in(const void *vr)
{
    const visco_rule *r = vr;
    adh_visco_result res;
    adh_visco_summary(r->w, &res);
    return res.jump_in_h0;
}

static void visco_observe(const void *vr, adh_obs *o)
{
    const visco_rule *r = vr;
    *o = r->run.rows[r->run.nrows - 1];
}

static const adh_state *visco_state(const void *vr)
{
    const visco_rule *r = vr;
    return adh_visco_state(r->w);
}

/* The start's failure (it names the start to move), else the solver's. */
static const char *visco_why(const void *vr, unsigned *fix)
{
    const visco_rule *r = vr;
    int own = r->first != ADH_CONTINUE && r->why[0];   /* the rule's own sentence, else the solver's */
    /* the start was no stable point out of contact; or the solver's (a
     * coarse grid's lattice folds: a finer grid) */
    *fix = r->first == ADH_ESTALL ? ADH_FIX_START : own ? 0 : adh_visco_fix(r->w);
    return own ? r->why : adh_visco_why(r->w);
}

const adh_rule_type adh_rule_visco = {
    .name = "visco",
    .alloc = visco_alloc,
    .free = visco_free,
    .set = visco_set,
    .next = visco_next,
    .jump_in = visco_jump_in,
    .observe = visco_observe,
    .state = visco_state,
    .why = visco_why,
};

const adh_visco *adh_rule_visco_solver(const adh_drive *d)
{
    const visco_rule *r = adh_drive_workspace(d, &adh_rule_visco);
    return r ? r->w : NULL;
}

const adh_run *adh_rule_visco_record(const adh_drive *d)
{
    const visco_rule *r = adh_drive_workspace(d, &adh_rule_visco);
    return r ? &r->run : NULL;
}

void adh_rule_visco_take(adh_drive *d, adh_run *run)
{
    visco_rule *r = adh_drive_workspace(d, &adh_rule_visco);
    if (r)
        adh_run_take(run, &r->run);
}
