/* The step-rule interface (adhere/rule.h): every registered rule is whole
 * and steps a protocol through the drive; the rigid rule's rows are eq 22
 * at start - k d down to its end, loading only, with undo; and a rule the
 * core has never heard of -- a ratchet written here, in the test -- plugs
 * into the drive with nothing else changed: loading, each turn unloaded
 * from that turn's own snapshot, the dwell, profiles and undo. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/history.h"
#include "adhere/models.h"
#include "adhere/rule.h"
#include "adhere/rule_rigid.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "tap.h"

/* A ratchet: the state remembers the deepest position reached (u[0]); the
 * force is C (h0 - deepest): 0 while loading, rising on unloading. An
 * unloading branch that started from the wrong turn's state would show it
 * in every row. */
#define C 1e-3
typedef struct ratchet {
    adh_state *st;
    size_t dwell, held;
} ratchet;

static void *ratchet_alloc(const adh_grid *g, const adh_kernel *k)
{
    ratchet *r = calloc(1, sizeof *r);
    if (r && !(r->st = adh_state_alloc(1))) {
        free(r);
        return NULL;
    }
    return r;
}
static void ratchet_free(void *vr)
{
    ratchet *r = vr;
    if (r)
        adh_state_free(r->st);
    free(r);
}
static int ratchet_set(void *vr, const adh_material *m, const void *s, const adh_protocol_settings *ps, double start)
{
    ratchet *r = vr;
    r->st->h0 = start;
    r->st->u[0] = start;
    return ADH_SUCCESS;
}
static void ratchet_move(void *vr, double h0, size_t dwell)
{
    ratchet *r = vr;
    r->dwell = dwell;
    r->held = 0;
    if (!dwell)
        r->st->h0 = h0;
}
static int ratchet_iterate(void *vr, size_t max_batch)
{
    ratchet *r = vr;
    if (r->dwell) {   /* in batches, as a relaxation's dwell would be */
        r->held += max_batch && max_batch < r->dwell - r->held ? max_batch : r->dwell - r->held;
        return r->held < r->dwell ? ADH_CONTINUE : ADH_SUCCESS;
    }
    r->st->u[0] = fmin(r->st->u[0], r->st->h0);
    return ADH_SUCCESS;
}
static void ratchet_observe(const void *vr, adh_obs *o)
{
    const ratchet *r = vr;
    o->h0 = r->st->h0;
    o->F = C * (r->st->h0 - r->st->u[0]);
    o->iters = r->dwell;
    o->stable = 1;
}
static const adh_state *ratchet_state(const void *vr)
{
    return ((const ratchet *)vr)->st;
}
static void *ratchet_snap_alloc(const void *vr)
{
    return adh_state_alloc(1);
}
static void ratchet_snap_free(void *snap)
{
    adh_state_free(snap);
}
static void ratchet_save(const void *vr, void *snap)
{
    adh_state_copy(snap, ((const ratchet *)vr)->st);
}
static void ratchet_load(void *vr, const void *snap)
{
    adh_state_copy(((ratchet *)vr)->st, snap);
}
static const adh_state *ratchet_snap_state(const void *snap)
{
    return snap;
}
static const adh_rule_type ratchet_rule = {
    .name = "ratchet",
    .alloc = ratchet_alloc,
    .free = ratchet_free,
    .set = ratchet_set,
    .move = ratchet_move,
    .iterate = ratchet_iterate,
    .observe = ratchet_observe,
    .state = ratchet_state,
    .snap_alloc = ratchet_snap_alloc,
    .snap_free = ratchet_snap_free,
    .save = ratchet_save,
    .load = ratchet_load,
    .snap_state = ratchet_snap_state,
};

static int same_rows(const adh_run *a, const adh_run *b)
{
    if (a->nrows != b->nrows)
        return 0;
    for (size_t i = 0; i < a->nrows; i++)
        if (a->rows[i].h0 != b->rows[i].h0 || a->rows[i].F != b->rows[i].F || a->rows[i].a != b->rows[i].a ||
            a->rows[i].branch != b->rows[i].branch || a->rows[i].path != b->rows[i].path)
            return 0;
    return 1;
}

static void registered(const adh_material *m, const adh_protocol_settings *ps)
{
    const adh_rule_type *rules[] = {
#define ENTRY(name) &adh_rule_##name,
        ADH_RULES(ENTRY)
#undef ENTRY
    };
    adh_grid *g = adh_grid_alloc(100, 10e-9);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_relax_settings rs = adh_relax_settings_default();
    rs.eps = 10e-12;
    adh_static_settings ss = adh_static_settings_default();
    for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
        const adh_rule_type *t = rules[i];
        const void *settings = !strcmp(t->name, "relax") ? (const void *)&rs
                             : !strcmp(t->name, "static") ? (const void *)&ss : NULL;
        adh_run run;
        adh_run_init(&run);
        int rc = adh_runner_rule(t, g, k, m, settings, ps, NULL, NULL, &run);
        ok(adh_rule_check(t) == ADH_SUCCESS && rc == ADH_SUCCESS && run.nrows > 10 && run.rows[0].h0 == run.start &&
               !isnan(run.jump_in_h0),
           "registered rule %s is whole and steps the protocol to its end through the drive (%zu rows, jump-in at "
           "%.3g nm)", t->name, run.nrows, run.jump_in_h0 * 1e9);
        adh_run_free(&run);
    }
    adh_rule_type broken = adh_rule_relax;
    broken.load = NULL;
    ok(adh_rule_check(&broken) == ADH_EINVAL && !adh_drive_alloc(&broken, g, k),
       "a stepped rule without its snapshots is refused, and no drive is built on it");
    broken = adh_rule_rigid;
    broken.move = adh_rule_relax.move;
    ok(adh_rule_check(&broken) == ADH_EINVAL, "a rule both stepped and a curve is refused");
    adh_kernel_free(k);
    adh_grid_free(g);
}

static void rigid(const adh_material *m, adh_protocol_settings ps)
{
    adh_run run;
    adh_run_init(&run);
    int rc = adh_runner_rule(&adh_rule_rigid, NULL, NULL, m, NULL, &ps, NULL, NULL, &run);
    double end = 0.7 * m->z0, jump = NAN;
    int eq22 = 1;
    for (size_t i = 0; i < run.nrows; i++) {
        const adh_obs *o = &run.rows[i];
        double h0 = run.start - (double)i * ps.step, reach = 1.1 * m->z0 - h0;
        eq22 &= o->h0 == h0 && o->F == adh_rigid_force(m, h0) && o->F_rigid == o->F && o->branch == 1 &&
                o->path == 0 && o->a == (reach > 0 ? sqrt(2 * m->R * reach) : 0);
        if (isnan(jump) && reach > 0)
            jump = h0;
    }
    const adh_obs *last = &run.rows[run.nrows - 1];
    ok(rc == ADH_SUCCESS && eq22 && run.nturns == 0,
       "rigid spheres without a grid: every row is eq 22 at start - k d, loading, no turn recorded (%zu rows)",
       run.nrows);
    ok(last->h0 >= end - 1e-6 * ps.step && last->h0 - ps.step < end && run.jump_in_h0 == jump,
       "the path ends at the last position above 0.7 z0 past a deeper turn (%.4g nm), jump-in where the gap "
       "first falls below 1.1 z0 (%.4g nm)", last->h0 * 1e9, jump * 1e9);
    ok(adh_rule_rigid_end(m, &ps) == end, "its end is 0.7 z0 below a deeper turn");

    /* a curve rule takes no steps by hand; undo by its snapshots */
    adh_drive *d = adh_drive_alloc(&adh_rule_rigid, NULL, NULL);
    adh_run again;
    adh_run_init(&again);
    adh_drive_set(d, m, NULL, &ps, &again);
    for (int i = 0; i < 10; i++)
        adh_drive_step(d);
    adh_drive_snap *s = adh_drive_snap_alloc(d);
    ok(adh_drive_hand(d, +1) == ADH_EINVAL && adh_drive_retarget(d, &ps) == ADH_EINVAL,
       "a curve rule refuses steps by hand and new turns");
    while (adh_drive_step(d) == ADH_CONTINUE)
        ;
    ok(same_rows(&run, &again), "stepped by hand, the drive gives the runner's rows");
    ok(s && adh_drive_restore(d, s) == ADH_SUCCESS && again.nrows == 10 && adh_drive_status(d) == ADH_CONTINUE,
       "a snapshot 10 rows in puts the drive and its run back there");
    while (adh_drive_step(d) == ADH_CONTINUE)
        ;
    ok(same_rows(&run, &again), "stepping on from it gives the same rows again");
    adh_drive_snap_free(s);
    adh_drive_free(d);
    adh_run_free(&again);
    adh_run_free(&run);

    ps.nturns = 1;
    ps.turns[0] = 2e-9;
    adh_run_init(&run);
    adh_runner_rule(&adh_rule_rigid, NULL, NULL, m, NULL, &ps, NULL, NULL, &run);
    last = &run.rows[run.nrows - 1];
    ok(last->h0 >= 2e-9 - 1e-6 * ps.step && last->h0 - ps.step < 2e-9 && run.nturns == 0,
       "a turn above 0.7 z0 ends the path there (%.4g nm), still loading only", last->h0 * 1e9);
    adh_run_free(&run);
}

static void plug_in(const adh_material *m)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = 0.25e-9;
    ps.nturns = 2;
    ps.turns[0] = -1e-9;
    ps.turns[1] = -2e-9;
    ps.dwell = 7;
    ps.nprofiles = 1;
    ps.profiles[0] = 1e-9;
    adh_drive *d = adh_drive_alloc(&ratchet_rule, NULL, NULL);
    adh_history *h = adh_history_alloc();
    adh_run run;
    adh_run_init(&run);
    ok(d && h && adh_drive_set(d, m, NULL, &ps, &run) == ADH_SUCCESS, "a rule defined outside the core: alloc, set");
    int rc, row, own = 1, loads = 1, dwelt = 1;
    size_t undone_at = 0;
    /* small batches: the dwell comes in pieces */
    while ((rc = adh_drive_iterate(d, 3, &row)) == ADH_CONTINUE) {
        if (!row)
            continue;
        const adh_obs *o = adh_drive_row(d);
        if (o->path == 0)
            loads &= o->F == 0 && o->branch == 1;
        else {
            double turn = run.turns[o->path - 1].h0;
            own &= o->F == C * (o->h0 - turn);
            if (adh_drive_events(d) & ADH_DRIVE_UNLOAD)
                dwelt &= o->iters == ps.dwell && o->h0 == turn;
        }
        adh_history_push(h, d);
        if (o->path == 1 && !undone_at && o->h0 > 0)
            undone_at = run.nrows;
    }
    ok(rc == ADH_SUCCESS && run.nturns == 2 && run.turns[0].h0 == -1e-9 && run.turns[1].h0 == -2e-9,
       "the drive's protocol runs it to the end and records both turns (%zu rows)", run.nrows);
    ok(loads && own, "loading rows are the rule's (F = 0) and every unloading row comes from its own turn's "
                     "snapshot: F = C (h0 - turn) on each branch");
    ok(dwelt, "each unloading branch begins with the dwell at its turn, %zu iterations, in batches", ps.dwell);
    ok(run.nprofiles == 3 && fabs(run.profiles[0].h0 - 1e-9) < 1e-6 * ps.step &&
           fabs(run.profiles[2].h0 - 1e-9) < 1e-6 * ps.step,
       "a profile is the rule's state at the position asked for, on each branch that passes it (%zu)", run.nprofiles);
    /* undo back to the first unloading branch, then on again */
    adh_run whole = run;
    adh_obs *rows = malloc(run.nrows * sizeof *rows);
    memcpy(rows, run.rows, run.nrows * sizeof *rows);
    whole.rows = rows;
    while (run.nrows > undone_at && adh_history_undo(h, d) == ADH_SUCCESS)
        ;
    ok(run.nrows == undone_at && adh_drive_state(d)->h0 == run.rows[run.nrows - 1].h0,
       "undo puts the drive and its run back (%zu rows)", run.nrows);
    while (adh_drive_step(d) == ADH_CONTINUE)
        ;
    ok(same_rows(&whole, &run), "stepping on from there gives the same rows");
    free(rows);
    adh_history_free(h);
    adh_drive_free(d);
    adh_run_free(&run);
}

int main(void)
{
    adh_material m = adh_material_default();
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = 0.25e-9;
    ps.turns[0] = -1e-9;
    registered(&m, &ps);
    ps.turns[0] = -5e-9;
    rigid(&m, ps);
    plug_in(&m);
    return tap_done();
}
