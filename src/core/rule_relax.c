/* The relaxation as a step rule (adhere/rule.h): the paper's dynamics, the
 * drive picking every position. A snapshot is a copy of the relaxed state
 * (its mixing ratio included), so a turn's unloading branch and an undo
 * resume exactly. */
#include "adhere/rule.h"

#include <stdlib.h>

#include "adhere/relax.h"
#include "adhere/state.h"
#include "adhere/status.h"

typedef struct relax_rule {
    const adh_grid *g;
    adh_relax *w;
    adh_material m;
    size_t dwell;   /* the step under way is the dwell at a turn, this many iterations */
} relax_rule;

static void *relax_alloc(const adh_grid *g, const adh_kernel *k)
{
    relax_rule *r = calloc(1, sizeof *r);
    if (!r || !(r->w = adh_relax_alloc(g, k))) {
        free(r);
        return NULL;
    }
    r->g = g;
    return r;
}

static void relax_free(void *vr)
{
    relax_rule *r = vr;
    if (r)
        adh_relax_free(r->w);
    free(r);
}

static int relax_set(void *vr, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                     double start)
{
    relax_rule *r = vr;
    r->m = *m;
    r->dwell = 0;
    return adh_relax_set(r->w, m, settings, start);
}

static void relax_move(void *vr, double h0, size_t dwell)
{
    relax_rule *r = vr;
    r->dwell = dwell;
    if (!dwell)
        adh_relax_move(r->w, h0);
}

static int relax_iterate(void *vr, size_t max_batch)
{
    relax_rule *r = vr;
    return r->dwell ? adh_relax_dwell(r->w, r->dwell) : adh_relax_iterate(r->w, max_batch);
}

static void relax_observe(const void *vr, adh_obs *o)
{
    const relax_rule *r = vr;
    adh_observe(r->g, &r->m, adh_relax_state(r->w), o);
    o->iters = r->dwell ? r->dwell : adh_relax_step_iterations(r->w);
    o->stable = 1;
}

static const adh_state *relax_state(const void *vr)
{
    const relax_rule *r = vr;
    return adh_relax_state(r->w);
}

static size_t relax_progress(const void *vr, double *change)
{
    const relax_rule *r = vr;
    *change = adh_relax_change(r->w);
    return adh_relax_step_iterations(r->w);
}

static void *relax_snap_alloc(const void *vr)
{
    const relax_rule *r = vr;
    return adh_state_alloc(r->g->n);
}

static void relax_snap_free(void *snap)
{
    adh_state_free(snap);
}

static void relax_save(const void *vr, void *snap)
{
    const relax_rule *r = vr;
    adh_state_copy(snap, adh_relax_state(r->w));
}

static void relax_load(void *vr, const void *snap)
{
    relax_rule *r = vr;
    adh_relax_restore(r->w, snap);
}

static const adh_state *relax_snap_state(const void *snap)
{
    return snap;
}

static const char *relax_why(const void *vr, unsigned *fix)
{
    const relax_rule *r = vr;
    *fix = 0;
    return adh_relax_why(r->w);
}

const adh_rule_type adh_rule_relax = {
    .name = "relax",
    .alloc = relax_alloc,
    .free = relax_free,
    .set = relax_set,
    .move = relax_move,
    .iterate = relax_iterate,
    .observe = relax_observe,
    .state = relax_state,
    .why = relax_why,
    .progress = relax_progress,
    .snap_alloc = relax_snap_alloc,
    .snap_free = relax_snap_free,
    .save = relax_save,
    .load = relax_load,
    .snap_state = relax_snap_state,
};
