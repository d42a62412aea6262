/* The static equilibrium curve as a step rule (adhere/rule.h): a curve
 * rule, each step the next accepted point of the continuation
 * (adhere/static.h), from the protocol's start down to its deepest turn
 * (none: the settings' own end), through every fold. */
#include "adhere/rule_static.h"

#include <math.h>
#include <stdlib.h>

#include "adhere/status.h"

typedef struct static_rule {
    const adh_grid *g;
    adh_static *sw;
    adh_material m;
    int first;        /* the status the first step reports: the start point's */
    int started;      /* the first step is taken */
    double seconds;   /* the solver's wall time up to the last point */
    double spent;     /* and on the last point */
} static_rule;

static void *static_alloc(const adh_grid *g, const adh_kernel *k)
{
    static_rule *r = calloc(1, sizeof *r);
    if (!r || !(r->sw = adh_static_alloc(g, k))) {
        free(r);
        return NULL;
    }
    r->g = g;
    return r;
}

static void static_free(void *vr)
{
    static_rule *r = vr;
    if (r)
        adh_static_free(r->sw);
    free(r);
}

static int static_set(void *vr, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                      double start)
{
    static_rule *r = vr;
    adh_static_settings s = *(const adh_static_settings *)settings;
    s.h0_start = start;
    if (ps->nturns)
        s.h0_end = adh_protocol_deepest_turn(ps);
    r->m = *m;
    r->started = 0;
    r->seconds = 0;
    int rc = adh_static_set(r->sw, m, &s);
    /* the start point solved: more points follow (ADH_SUCCESS from
     * adh_static_iterate means the end) */
    r->first = rc == ADH_SUCCESS ? ADH_CONTINUE : rc;
    return rc == ADH_EINVAL ? ADH_EINVAL : ADH_SUCCESS;
}

static int static_next(void *vr)
{
    static_rule *r = vr;
    int rc = r->started ? adh_static_iterate(r->sw) : r->first;
    r->started = 1;
    adh_static_result res;
    adh_static_summary(r->sw, &res);
    r->spent = res.seconds - r->seconds;
    r->seconds = res.seconds;
    return rc;
}

static double static_jump_in(const void *vr)
{
    const static_rule *r = vr;
    adh_static_result res;
    adh_static_summary(r->sw, &res);
    return res.jump_in_h0;
}

static void static_observe(const void *vr, adh_obs *o)
{
    const static_rule *r = vr;
    adh_observe(r->g, &r->m, adh_static_state(r->sw), o);
    adh_static_point pt = adh_static_current(r->sw);
    o->seconds = r->spent;
    o->iters = pt.newton;
    o->branch = pt.direction;
    o->path = 0;
    o->converged = 1;
    o->stable = pt.stable;
}

static const adh_state *static_state(const void *vr)
{
    const static_rule *r = vr;
    return adh_static_state(r->sw);
}

static const char *static_why(const void *vr, unsigned *fix)
{
    const static_rule *r = vr;
    return adh_static_why(r->sw, fix);
}

const adh_rule_type adh_rule_static = {
    .name = "static",
    .alloc = static_alloc,
    .free = static_free,
    .set = static_set,
    .next = static_next,
    .jump_in = static_jump_in,
    .observe = static_observe,
    .state = static_state,
    .why = static_why,
};

const adh_static *adh_rule_static_solver(const adh_drive *d)
{
    const static_rule *r = adh_drive_workspace(d, &adh_rule_static);
    return r ? r->sw : NULL;
}

double adh_rule_static_end(const adh_protocol_settings *ps)
{
    return ps->nturns ? adh_protocol_deepest_turn(ps) : adh_static_settings_default().h0_end;
}
