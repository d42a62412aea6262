/* Rigid spheres as a step rule (adhere/rule.h): the force of eq 22 at each
 * drive position start - k d (computed afresh, never accumulated) down to
 * the end, loading only. No grid, kernel or relaxation; the rows look like
 * a loading branch's so the same tables and plots read them. A curve rule:
 * below 0.7 z0 the rigid force soon diverges, so its path ends there even
 * when the protocol's turns go deeper. */
#include "adhere/rule_rigid.h"

#include <math.h>
#include <stdlib.h>

#include "adhere/models.h"
#include "adhere/status.h"

typedef struct rigid_rule {
    adh_material m;
    double start, step;
    size_t n;   /* positions on the path */
    size_t k;   /* the next one */
} rigid_rule;

double adh_rule_rigid_end(const adh_material *m, const adh_protocol_settings *ps)
{
    double floor_h = 0.7 * m->z0;
    return ps->nturns ? fmax(adh_protocol_deepest_turn(ps), floor_h) : floor_h;
}

static void *rigid_alloc(const adh_grid *g, const adh_kernel *k)
{
    return calloc(1, sizeof(rigid_rule));
}

static void rigid_free(void *r)
{
    free(r);
}

static int rigid_set(void *vr, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                     double start)
{
    rigid_rule *r = vr;
    double span = (start - adh_rule_rigid_end(m, ps)) / ps->step;
    if (!(span >= 0 && span < 1e9))
        return ADH_EINVAL;
    r->m = *m;
    r->start = start;
    r->step = ps->step;
    r->n = 1 + (size_t)floor(span + 1e-6);
    r->k = 0;
    return ADH_SUCCESS;
}

static int rigid_next(void *vr)
{
    rigid_rule *r = vr;
    if (r->k >= r->n)
        return ADH_EINVAL;
    r->k++;
    return r->k < r->n ? ADH_CONTINUE : ADH_SUCCESS;
}

static void rigid_observe(const void *vr, adh_obs *o)
{
    const rigid_rule *r = vr;
    const adh_material *m = &r->m;
    o->h0 = r->start - (double)(r->k - 1) * r->step;
    o->F = o->F_rigid = adh_rigid_force(m, o->h0);
    o->hc = o->h0;
    /* undeformed spheres: in contact where h0 + r^2/2R < 1.1 z0 */
    double reach = ADH_CONTACT_FACTOR * m->z0 - o->h0;
    o->a = reach > 0 ? sqrt(2.0 * m->R * reach) : 0.0;
    o->branch = +1;
    o->converged = 1;
    o->stable = 1;
}

/* A snapshot is where the path is: the next position's index. */
static void *rigid_snap_alloc(const void *r)
{
    return calloc(1, sizeof(size_t));
}

static void rigid_snap_free(void *snap)
{
    free(snap);
}

static void rigid_save(const void *vr, void *snap)
{
    *(size_t *)snap = ((const rigid_rule *)vr)->k;
}

static void rigid_load(void *vr, const void *snap)
{
    ((rigid_rule *)vr)->k = *(const size_t *)snap;
}

static const adh_state *rigid_snap_state(const void *snap)
{
    return NULL;
}

const adh_rule_type adh_rule_rigid = {
    .name = "rigid",
    .alloc = rigid_alloc,
    .free = rigid_free,
    .set = rigid_set,
    .next = rigid_next,
    .observe = rigid_observe,
    .snap_alloc = rigid_snap_alloc,
    .snap_free = rigid_snap_free,
    .save = rigid_save,
    .load = rigid_load,
    .snap_state = rigid_snap_state,
};
