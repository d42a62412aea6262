#include "adhere/drive.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/clock.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/state.h"
#include "adhere/status.h"
#include "adhere/units.h"

typedef enum phase { PH_START = 0, PH_LOAD, PH_TURN, PH_UNLOAD, PH_DONE } phase;

/* The loading state at a turn (a snapshot of the rule), shared by the
 * drive and every snapshot that saw it (a recorded turn never changes:
 * recording it again makes a new one), so an undo history of snapshots
 * costs no copies of them. */
typedef struct tstate {
    const adh_rule_type *type;
    void *snap;
    int refs;
} tstate;

static tstate *ts_hold(tstate *t)
{
    if (t)
        t->refs++;
    return t;
}

static void ts_drop(tstate *t)
{
    if (t && --t->refs == 0) {
        t->type->snap_free(t->snap);
        free(t);
    }
}

/* A turn's state: a snapshot of rule r of type t. */
static tstate *ts_new(const adh_rule_type *type, const void *r)
{
    tstate *t = calloc(1, sizeof *t);
    if (!t || !(t->snap = type->snap_alloc(r))) {
        free(t);
        return NULL;
    }
    type->save(r, t->snap);
    t->type = type;
    t->refs = 1;
    return t;
}

/* Makes to[] hold what from[] holds. */
static void ts_assign(tstate **to, tstate *const *from)
{
    for (size_t i = 0; i < ADH_MAX_TURNS; i++) {
        tstate *t = ts_hold(from[i]);
        ts_drop(to[i]);
        to[i] = t;
    }
}

/* Where the drive is in the protocol: all a snapshot needs besides the
 * relaxed state and the run's counters. */
typedef struct cursor {
    phase ph;
    long k;          /* the next step's index on its branch */
    size_t ti;       /* loading: the next turn to reach */
    size_t ui;       /* unloading: the turn being unloaded from */
    int in_contact;  /* loading: the surfaces have touched */
    int hand;        /* a step by hand asked for: +1 approach, -1 retract, 0 none */
    unsigned events; /* what the last row meant (ADH_DRIVE_*) */
    int touched;     /* unloading: in contact on this branch so far */
    int status;      /* the final status once ph == PH_DONE */
    long row;        /* index of the last row in the run, -1 none */
    /* the step under way (adh_drive_iterate in batches) */
    int inflight;
    double h0;       /* where it goes */
    int branch, path, at_turn;
    size_t dwell;
    double t0, spent;   /* when its current batch began; seconds so far */
} cursor;

struct adh_drive {
    const adh_grid *g;
    const adh_kernel *k;
    const adh_rule_type *type;   /* the step rule (adhere/rule.h) */
    void *r;                     /* and its workspace */
    adh_material m;
    adh_protocol_settings ps;
    adh_run *run;
    double start;
    double turns[ADH_MAX_TURNS];   /* sorted, shallowest first */
    tstate *ts[ADH_MAX_TURNS];   /* the loading state at each of the run's turns */
    cursor c;
};

struct adh_drive_snap {
    const adh_rule_type *type;
    void *snap;      /* the rule's snapshot */
    cursor c;
    adh_run marks;   /* the run's counts and turns; its arrays stay unused */
    adh_obs last;    /* the run's last row then (redo puts it back) */
    tstate *ts[ADH_MAX_TURNS];
};

/* What a snapshot keeps of a run: its counts and turns, not its arrays
 * (rows past nrows are dropped on restore, never copied). */
static void copy_marks(adh_run *to, const adh_run *from)
{
    to->nrows = from->nrows;
    to->nprofiles = from->nprofiles;
    to->nturns = from->nturns;
    to->iterations = from->iterations;
    to->unconverged = from->unconverged;
    to->seconds = from->seconds;
    to->jump_in_h0 = from->jump_in_h0;
    to->interrupted = from->interrupted;
    memcpy(to->turns, from->turns, sizeof to->turns);
}

/* The rule's present state, NULL for a rule without one. */
static const adh_state *rule_state(const adh_drive *d)
{
    return d->type->state ? d->type->state(d->r) : NULL;
}

adh_drive *adh_drive_alloc(const adh_rule_type *type, const adh_grid *g, const adh_kernel *k)
{
    if (adh_rule_check(type) != ADH_SUCCESS)
        return NULL;
    adh_drive *d = calloc(1, sizeof *d);
    if (!d)
        return NULL;
    d->g = g;
    d->k = k;
    d->type = type;
    d->r = type->alloc(g, k);
    if (!d->r) {
        free(d);
        return NULL;
    }
    d->c.ph = PH_DONE;
    d->c.status = ADH_EINVAL;   /* not set yet */
    d->c.row = -1;
    return d;
}

void adh_drive_free(adh_drive *d)
{
    if (!d)
        return;
    for (size_t i = 0; i < ADH_MAX_TURNS; i++)
        ts_drop(d->ts[i]);
    d->type->free(d->r);
    free(d);
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

int adh_drive_check(const adh_material *m, const adh_relax_settings *rs, const adh_protocol_settings *ps,
                    adh_grid_use use, const adh_grid *g, char *why, size_t whylen, unsigned *fix)
{
    int rc;
    if (fix)
        *fix = 0;
    if ((rc = adh_material_validate(m, why, whylen)) != ADH_SUCCESS ||
        (rc = adh_relax_settings_validate(rs, why, whylen)) != ADH_SUCCESS)
        return rc;
    if (g && use == ADH_GRID_RELAX) {
        /* eps below the measure's rounding floor: every step would run to the cap */
        double deepest = 0;
        for (size_t i = 0; i < ps->nturns && i < ADH_MAX_TURNS; i++)
            deepest = fmin(deepest, ps->turns[i]);
        double floor_eps = adh_relax_eps_floor(m->z0 - deepest);
        if (rs->eps < floor_eps) {
            snprintf(why, whylen, "eps = %s is below what double precision can reach with deformations up to %s: the smallest eps allowed here is %s",
                     adh_qtext(rs->eps, ADH_Q_LENGTH).s, adh_qtext(m->z0 - deepest, ADH_Q_LENGTH).s, adh_qtext(floor_eps, ADH_Q_LENGTH).s);
            return ADH_EINVAL;
        }
    }
    if (g && !(isfinite(g->dr) && g->dr > 0)) {
        snprintf(why, whylen, "spacing = %s is not allowed: it must be above 0", adh_qtext(g->dr, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    /* g NULL: rigid spheres, eq 22 alone, only the drive is checked */
    return adh_protocol_check(ps, m, g, why, whylen, fix);
}

adh_grid adh_drive_uniform_grid(size_t n, double dr)
{
    adh_grid g = { .n = n, .dr = dr, .rmax = (double)n * dr, .r = NULL, .graded = 0, .edge = NULL };
    return g;
}

int adh_drive_set(adh_drive *d, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                  adh_run *run)
{
    if (!(ps->step > 0) || ps->nturns > ADH_MAX_TURNS || ps->nprofiles > ADH_MAX_PROFILES)
        return ADH_EINVAL;
    d->m = *m;
    d->ps = *ps;
    d->run = run;
    d->start = isnan(ps->start) ? adh_protocol_auto_start(m, ps->step) : ps->start;
    run->start = d->start;
    memcpy(d->turns, ps->turns, ps->nturns * sizeof *d->turns);
    qsort(d->turns, ps->nturns, sizeof *d->turns, cmp_desc);
    for (size_t i = 0; i < ADH_MAX_TURNS; i++) {
        ts_drop(d->ts[i]);
        d->ts[i] = NULL;
    }
    memset(&d->c, 0, sizeof d->c);
    d->c.ph = PH_START;
    d->c.row = -1;
    int rc = d->type->set(d->r, &d->m, settings, &d->ps, d->start);
    if (rc != ADH_SUCCESS) {
        d->c.ph = PH_DONE;   /* nothing to step */
        d->c.status = rc;
    }
    return rc;
}

static int wants_profile(const adh_protocol_settings *ps, double h0)
{
    for (size_t i = 0; i < ps->nprofiles; i++)
        if (fabs(ps->profiles[i] - h0) < 1e-6 * ps->step)
            return 1;
    return 0;
}

/* A stepped rule's step, in three parts: begin (move to the next position,
 * or load a turn's snapshot, or dwell there), iterate (in batches), finish
 * (observe, record the row, note jump-in, turns, pull-off and jump-out). */

/* The run's words for a stop on an error: the contact at the grid's edge
 * (the rings' sentence), else the rule's own, else where the drive was. */
static void say_why(adh_drive *d, int status)
{
    adh_run *run = d->run;
    const adh_obs *last = d->c.row >= 0 ? &run->rows[d->c.row] : NULL;
    unsigned fix = 0;
    const char *rule = d->type->why ? d->type->why(d->r, &fix) : NULL;
    run->fix = 0;
    if (status == ADH_EGRID && last && d->g) {
        adh_rings_edge_sentence(d->g, last->a, run->why, sizeof run->why);
        run->fix = adh_rings_edge_fix(d->g, last->a);
    } else if (rule && *rule) {
        snprintf(run->why, sizeof run->why, "%s", rule);
        run->fix = fix;
    } else {
        /* a stepped rule's step had a target; a curve rule's point follows its last */
        double h0 = d->type->next ? (last ? last->h0 : d->start) : d->c.h0;
        snprintf(run->why, sizeof run->why, "%s at %s h0 = %s, after %zu rows",
                 status == ADH_ENAN ? "the force, deformation or contact radius became non-finite"
                                    : adh_strerror(status),
                 d->type->next && last ? "the point after" : "the step to", adh_qtext(h0, ADH_Q_LENGTH).s,
                 run->nrows);
    }
}

static int finish(adh_drive *d, int status)
{
    if (status != ADH_SUCCESS && status != ADH_EINTR)
        say_why(d, status);
    d->c.ph = PH_DONE;
    d->c.status = status;
    d->c.inflight = 0;
    return status;
}

/* The loading branch has reached its end: unload from every turn reached,
 * or stop. */
/* The first turn not unloaded yet (its index), or nturns. */
static size_t first_loaded(const adh_drive *d)
{
    size_t i = 0;
    while (i < d->run->nturns && d->run->turns[i].path != 0)
        i++;
    return i;
}

/* Where the loading lattice goes on from row o: the index of the next
 * position start - k d past it. */
static long load_index_after(const adh_drive *d, const adh_obs *o)
{
    return lround((d->start - o->h0) / d->ps.step) + 1;
}

/* Whether the loading branch has reached its end: every turn (without
 * turns, contact). */
static int loading_done(const adh_drive *d)
{
    size_t nt = d->ps.nturns;
    return (nt == 0 && d->c.in_contact) || (nt > 0 && d->c.ti == nt);
}

/* What follows a branch that has ended: the next turn not unloaded yet (in
 * the order they were reached; a branch begun by hand counts as unloaded;
 * *ui its index), else, when steps by hand left turns of the protocol
 * unreached, loading on to them from where the path is (PH_LOAD), else
 * the end (PH_DONE). */
static phase after_branch(const adh_drive *d, size_t *ui)
{
    *ui = first_loaded(d);
    if (d->ps.unload && *ui < d->run->nturns)
        return PH_TURN;
    if (d->c.ti < d->ps.nturns && d->c.row >= 0)
        return PH_LOAD;
    return PH_DONE;
}

/* A branch has ended: on to what follows it (after_branch). */
static void next_turn(adh_drive *d)
{
    cursor *c = &d->c;
    size_t ui;
    c->status = ADH_SUCCESS;
    c->ph = after_branch(d, &ui);
    if (c->ph == PH_TURN) {
        c->ui = ui;
    } else if (c->ph == PH_LOAD) {
        const adh_obs *o = &d->run->rows[c->row];
        c->k = load_index_after(d, o);
        c->in_contact = o->a > 0;
    }
}

static void start(adh_drive *d, double h0, int branch, int path, size_t dwell, int at_turn)
{
    cursor *c = &d->c;
    c->inflight = 1;
    c->h0 = h0;
    c->branch = branch;
    c->path = path;
    c->dwell = dwell;
    c->at_turn = at_turn;
    c->spent = 0;
    d->type->move(d->r, h0, dwell);
}

/* Where a step by hand in direction dir goes from the last row: loading
 * on the lattice start - k d (each turn not yet reached hit exactly),
 * unloading on turn + k d from the branch's turn; retracting from a
 * loading row turns there (ui: the run's turn it unloads, nturns for a new
 * one). ADH_SUCCESS, ADH_EINVAL for a position out of the model's reach
 * or one turn too many. */
typedef struct hand_plan {
    double h0;
    long k;          /* the step's index on its branch */
    int at_turn;
    size_t ui;       /* retracting: the turn of the branch */
} hand_plan;

/* The contact of row o at the grid's edge, or past a graded grid's fine
 * band: the grid no longer holds it. */
static int at_edge(const adh_drive *d, const adh_obs *o)
{
    return d->g && (o->a >= 0.9 * d->g->rmax || !adh_rings_resolves(d->g, o->a));
}

static int plan_hand(const adh_drive *d, int dir, hand_plan *hp)
{
    const adh_protocol_settings *ps = &d->ps;
    const adh_run *run = d->run;
    double tol = 1e-6 * ps->step;
    /* before the first row: the start, then the step from it */
    adh_obs at_start = { .h0 = d->start, .branch = +1, .path = 0 };
    const adh_obs *last = d->c.row >= 0 ? &run->rows[d->c.row] : &at_start;
    memset(hp, 0, sizeof *hp);
    if (dir > 0) {
        /* deeper in, the contact would only grow further past the grid */
        if (d->c.row >= 0 && at_edge(d, last))
            return ADH_EGRID;
        hp->k = last->branch > 0 && d->c.row >= 0 ? d->c.k : load_index_after(d, last);
        hp->h0 = d->start - (double)hp->k * ps->step;
        size_t ti = d->c.ti;
        while (ti < ps->nturns && d->turns[ti] >= last->h0 - tol)
            ti++;   /* passed already (turns changed since) */
        if (ti < ps->nturns && hp->h0 <= d->turns[ti] + tol) {
            hp->h0 = d->turns[ti];
            hp->at_turn = 1;
            hp->k = (long)floor((d->start - hp->h0) / ps->step + 1e-6);
        }
    } else if (last->branch > 0) {
        /* a turn here: the one the loading branch just recorded, or a new one */
        size_t i = run->nturns;
        while (i-- > 0)
            if (run->turns[i].path == 0 && fabs(run->turns[i].h0 - last->h0) < tol)
                break;
        hp->ui = i < run->nturns ? i : run->nturns;
        if (hp->ui == ADH_MAX_TURNS)
            return ADH_EINVAL;
        hp->k = 1;
        hp->h0 = last->h0 + ps->step;
    } else {
        hp->ui = (size_t)(last->path - 1);
        double turn = run->turns[hp->ui].h0;
        hp->k = lround((last->h0 - turn) / ps->step) + 1;
        hp->h0 = turn + (double)hp->k * ps->step;
    }
    return fabs(hp->h0) > adh_protocol_reach(&d->m) ? ADH_EINVAL : ADH_SUCCESS;
}

/* Records a turn at the present state, as the run's turn ui (the next
 * one). ADH_SUCCESS or ADH_ENOMEM. */
static int record_turn(adh_drive *d, const adh_obs *o)
{
    adh_run *run = d->run;
    size_t ui = run->nturns;
    tstate *t = ts_new(d->type, d->r);
    if (!t)
        return ADH_ENOMEM;
    ts_drop(d->ts[ui]);
    d->ts[ui] = t;
    adh_turn_result *tr = &run->turns[run->nturns++];
    tr->h0 = o->h0;
    tr->max_load = o->F;
    tr->a_turn = o->a;
    tr->pulloff_F = NAN;
    tr->pulloff_h0 = NAN;
    tr->jump_out_h0 = NAN;
    tr->path = 0;
    tr->hysteresis = NAN;
    return ADH_SUCCESS;
}

/* Starts the step by hand asked for. ADH_SUCCESS, or an error (nothing
 * started). */
static int begin_hand(adh_drive *d)
{
    int dir = d->c.hand;
    hand_plan hp;
    int rc = plan_hand(d, dir, &hp);
    d->c.hand = 0;
    if (rc != ADH_SUCCESS)
        return rc;
    cursor *c = &d->c;
    const adh_obs *last = &d->run->rows[c->row];
    if (dir > 0) {
        if (last->branch < 0)
            c->in_contact = last->a > 0;
        c->ph = PH_LOAD;
        c->k = hp.k + 1;
        start(d, hp.h0, +1, 0, 0, hp.at_turn);
        return ADH_SUCCESS;
    }
    if (last->branch > 0) {
        if (hp.ui == d->run->nturns && (rc = record_turn(d, last)) != ADH_SUCCESS)
            return rc;
        d->run->turns[hp.ui].path = (int)hp.ui + 1;
        c->touched = last->a > 0;
    }
    c->ui = hp.ui;
    c->ph = PH_UNLOAD;
    c->k = hp.k + 1;
    start(d, hp.h0, -1, (int)hp.ui + 1, 0, 0);
    return ADH_SUCCESS;
}

/* Whether an unloading branch is over before position h0. It ends at the
 * start, unless the surfaces still touch there: the cycle is asked for its
 * separation, and the start is only where the approach's force is
 * negligible (a soft, sticky contact stretches its neck well past it, the
 * more so when the drive outruns the relaxation). Past the start it goes on
 * while they touch, up to the model's reach. */
static int unload_ended(const adh_drive *d, double h0)
{
    if (h0 <= d->start + 1e-6 * d->ps.step)
        return 0;
    const adh_obs *last = adh_drive_row(d);
    return !(last && last->branch < 0 && last->a > 0) || h0 > adh_protocol_reach(&d->m);
}

/* Picks the next step of the protocol and starts it. ADH_SUCCESS, or the
 * final status when there is none. */
static int begin(adh_drive *d)
{
    const adh_protocol_settings *ps = &d->ps;
    size_t nt = ps->nturns;
    double tol = 1e-6 * ps->step;
    if (d->c.hand && d->c.ph != PH_START)
        return begin_hand(d);
    for (;;) {
        switch (d->c.ph) {
        case PH_START:
            start(d, d->start, +1, 0, 0, 0);
            return ADH_SUCCESS;
        case PH_LOAD: {
            if (loading_done(d)) {
                next_turn(d);
                continue;
            }
            /* Positions are start - k d, computed afresh (never accumulated)
             * so that positions such as -3.5 nm are hit exactly; each turn
             * is hit exactly. */
            long k = d->c.k;
            double h0 = d->start - (double)k * ps->step;
            int at_turn = 0;
            if (nt > 0 && h0 <= d->turns[d->c.ti] + tol) {
                h0 = d->turns[d->c.ti];
                at_turn = 1;
                k = (long)floor((d->start - h0) / ps->step + 1e-6);
            }
            if (nt == 0 && h0 < -adh_protocol_reach(&d->m))
                return finish(d, ADH_SUCCESS);   /* never in contact within the model's reach */
            d->c.k = k + 1;
            start(d, h0, +1, 0, 0, at_turn);
            return ADH_SUCCESS;
        }
        case PH_TURN: {
            adh_turn_result *tr = &d->run->turns[d->c.ui];
            tr->path = (int)d->c.ui + 1;
            d->type->load(d->r, d->ts[d->c.ui]->snap);
            start(d, tr->h0, -1, tr->path, ps->dwell, 0);
            return ADH_SUCCESS;
        }
        case PH_UNLOAD: {
            adh_turn_result *tr = &d->run->turns[d->c.ui];
            double h0 = tr->h0 + (double)d->c.k * ps->step;
            if (unload_ended(d, h0)) {
                next_turn(d);
                continue;
            }
            d->c.k++;
            start(d, h0, -1, tr->path, 0, 0);
            return ADH_SUCCESS;
        }
        case PH_DONE:
        default:
            return d->c.status;
        }
    }
}

/* Appends a solved step's row to the run (either kind of rule): ADH_SUCCESS,
 * ADH_ENAN for a non-finite force, deformation or radius, ADH_ENOMEM. */
static int push_row(adh_drive *d, const adh_obs *o)
{
    if (!(isfinite(o->F) && isfinite(o->delta) && isfinite(o->a)))
        return ADH_ENAN;
    if (adh_run_push_row(d->run, o) != ADH_SUCCESS)
        return ADH_ENOMEM;
    d->c.row = (long)d->run->nrows - 1;
    d->c.events = 0;
    return ADH_SUCCESS;
}

/* Whether the protocol's next step begins another branch (or none is
 * left): the loading branch has reached its last turn (or, without turns,
 * contact), an unloading branch jumped out or its next position is past
 * the start. */
static int branch_ends(const adh_drive *d)
{
    const cursor *c = &d->c;
    switch (c->ph) {
    case PH_LOAD:
        return loading_done(d);
    case PH_UNLOAD:
        return unload_ended(d, d->run->turns[c->ui].h0 + (double)c->k * d->ps.step);
    default:
        return 1;   /* a jump-out moved on to the next turn (PH_TURN) or the end */
    }
}

/* The step under way is solved: observe and record its row (a step that
 * hit the cap is flagged in the row and counted, not fatal), then note
 * what it means for the protocol. ADH_CONTINUE, or the status that ends
 * the run (ADH_EGRID keeps its row). */
static int complete(adh_drive *d, int rc)
{
    adh_run *run = d->run;
    cursor *c = &d->c;
    adh_obs o;
    memset(&o, 0, sizeof o);
    d->type->observe(d->r, &o);
    o.seconds = c->spent;
    o.branch = c->branch;
    o.path = c->path;
    o.converged = (rc == ADH_SUCCESS);
    run->iterations += o.iters;
    run->seconds += c->spent;
    c->inflight = 0;
    if (rc == ADH_EINTR) {
        /* an unfinished step is no result: no row, and the run ends here */
        run->interrupted = 1;
        return finish(d, ADH_EINTR);
    }
    if (rc == ADH_EMAXITER) {
        run->unconverged++;
        rc = ADH_SUCCESS;
    }
    if (rc != ADH_SUCCESS)
        return finish(d, rc);
    if ((rc = push_row(d, &o)) != ADH_SUCCESS)
        return finish(d, rc);
    if (rule_state(d) && wants_profile(&d->ps, c->h0) &&
        adh_run_push_profile(run, rule_state(d), c->branch, c->path) != ADH_SUCCESS)
        return finish(d, ADH_ENOMEM);
    int edge = at_edge(d, &o);
    double tol = 1e-6 * d->ps.step;
    switch (c->ph) {
    case PH_START:
        c->in_contact = o.a > 0;
        c->k = 1;
        c->ti = 0;
        c->ph = PH_LOAD;
        break;
    case PH_LOAD:
        if (edge)
            break;
        if (o.a > 0 && !c->in_contact) {
            c->in_contact = 1;
            c->events |= ADH_DRIVE_JUMP_IN;
            if (isnan(run->jump_in_h0))
                run->jump_in_h0 = o.h0;
        }
        while (c->at_turn && c->ti < d->ps.nturns && fabs(d->turns[c->ti] - c->h0) < tol) {
            if (run->nturns == ADH_MAX_TURNS || record_turn(d, &o) != ADH_SUCCESS)
                return finish(d, ADH_ENOMEM);
            c->events |= ADH_DRIVE_TURN;
            c->ti++;
        }
        break;
    case PH_TURN: {
        if (edge)
            break;
        adh_turn_result *tr = &run->turns[c->ui];
        tr->pulloff_F = o.F;
        tr->pulloff_h0 = o.h0;
        c->touched = o.a > 0;
        c->k = 1;
        c->ph = PH_UNLOAD;
        c->events |= ADH_DRIVE_UNLOAD;
        break;
    }
    case PH_UNLOAD: {
        if (edge)
            break;
        adh_turn_result *tr = &run->turns[c->ui];
        if (!(o.F >= tr->pulloff_F)) {   /* the branch's first row too, begun by hand */
            tr->pulloff_F = o.F;
            tr->pulloff_h0 = o.h0;
        }
        if (o.a > 0)
            c->touched = 1;
        else if (c->touched) {
            tr->jump_out_h0 = o.h0;
            c->events |= ADH_DRIVE_PULLOFF | ADH_DRIVE_END;   /* the branch ends at its jump-out */
            next_turn(d);
        }
        break;
    }
    default:
        break;
    }
    if (edge)
        return finish(d, ADH_EGRID);
    if (branch_ends(d))
        c->events |= ADH_DRIVE_END;
    return ADH_CONTINUE;
}

/* A curve rule's step: the rule's next point (the first: the start)
 * becomes a row, as a stepped rule's solved step does. */
static int curve_step(adh_drive *d, int *row)
{
    adh_run *run = d->run;
    cursor *c = &d->c;
    int rc = d->type->next(d->r), rc2;
    if (rc == ADH_EINTR) {
        run->interrupted = 1;
        return finish(d, ADH_EINTR);
    }
    if (rc != ADH_SUCCESS && rc != ADH_CONTINUE && rc != ADH_EGRID)
        return finish(d, rc);
    adh_obs o;
    memset(&o, 0, sizeof o);
    o.t = NAN;   /* no physical time unless the rule has one */
    d->type->observe(d->r, &o);
    run->iterations += o.iters;
    run->seconds += o.seconds;
    if (d->type->jump_in)
        run->jump_in_h0 = d->type->jump_in(d->r);
    else if (o.a > 0 && isnan(run->jump_in_h0))
        run->jump_in_h0 = o.h0;
    if ((rc2 = push_row(d, &o)) != ADH_SUCCESS)
        return finish(d, rc2);
    *row = 1;
    if (rc == ADH_EGRID)
        return finish(d, ADH_EGRID);
    if (rc == ADH_SUCCESS) {
        /* the path came down to its end: this row is the last */
        c->ph = PH_DONE;
        c->status = ADH_SUCCESS;
        c->events = ADH_DRIVE_END;
    }
    return ADH_CONTINUE;
}

int adh_drive_iterate(adh_drive *d, size_t max_batch, int *row)
{
    *row = 0;
    if (d->type->next) {
        if (d->c.ph == PH_DONE)
            return d->c.status;
        /* a curve rule's work before its next point, in batches (the
         * elastic path's curve): no row yet */
        if (d->type->iterate && d->type->iterate(d->r, max_batch) == ADH_CONTINUE)
            return ADH_CONTINUE;
        return curve_step(d, row);
    }
    if (!d->c.inflight) {
        if (d->c.ph == PH_DONE && !d->c.hand)
            return d->c.status;
        int rc = begin(d);
        if (!d->c.inflight)
            return rc;   /* the protocol is complete (or was ended) */
    }
    cursor *c = &d->c;
    double t0 = adh_clock_seconds();
    int rc = d->type->iterate(d->r, max_batch);
    c->spent += adh_clock_seconds() - t0;
    if (rc == ADH_CONTINUE)
        return ADH_CONTINUE;   /* the step goes on: call again */
    rc = complete(d, rc);
    *row = d->c.row >= 0 && (rc == ADH_CONTINUE || rc == ADH_EGRID);
    return rc;
}

int adh_drive_step(adh_drive *d)
{
    int row, rc;
    while ((rc = adh_drive_iterate(d, 0, &row)) == ADH_CONTINUE && !row)
        ;
    return rc;
}

const adh_obs *adh_drive_row(const adh_drive *d)
{
    if (d->c.row < 0 || !d->run || (size_t)d->c.row >= d->run->nrows)
        return NULL;
    return &d->run->rows[d->c.row];
}

int adh_drive_turn(const adh_drive *d)
{
    switch (d->c.ph) {
    case PH_START: case PH_LOAD: return 0;
    case PH_TURN: case PH_UNLOAD: return (int)d->c.ui + 1;
    default: return -1;
    }
}

double adh_drive_start(const adh_drive *d)
{
    return d->start;
}

const adh_state *adh_drive_state(const adh_drive *d)
{
    return rule_state(d);
}

adh_run *adh_drive_record(const adh_drive *d)
{
    return d->run;
}

void *adh_drive_workspace(const adh_drive *d, const adh_rule_type *type)
{
    return d->type == type ? d->r : NULL;
}

adh_drive_snap *adh_drive_snap_alloc(const adh_drive *d)
{
    if (!d->type->snap_alloc)
        return NULL;   /* a rule without snapshots (the static curve) */
    adh_drive_snap *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->type = d->type;
    s->snap = d->type->snap_alloc(d->r);
    if (!s->snap) {
        free(s);
        return NULL;
    }
    adh_drive_snapshot(d, s);
    return s;
}

void adh_drive_snap_free(adh_drive_snap *s)
{
    if (!s)
        return;
    for (size_t i = 0; i < ADH_MAX_TURNS; i++)
        ts_drop(s->ts[i]);
    s->type->snap_free(s->snap);
    free(s);
}

const adh_state *adh_drive_snap_state(const adh_drive_snap *s)
{
    return s->type->snap_state(s->snap);
}

/* Whether snapshot s fits d: taken of the same rule, on a grid of the
 * same size. */
static int snap_fits(const adh_drive *d, const adh_drive_snap *s)
{
    const adh_state *a = adh_drive_snap_state(s), *b = rule_state(d);
    return s->type == d->type && (a && b ? a->n == b->n : !a && !b);
}

int adh_drive_snapshot(const adh_drive *d, adh_drive_snap *s)
{
    if (!snap_fits(d, s))
        return ADH_EINVAL;
    d->type->save(d->r, s->snap);
    s->c = d->c;
    s->c.hand = 0;   /* a step asked for is not part of the state it was asked from */
    ts_assign(s->ts, d->ts);
    if (d->run) {
        copy_marks(&s->marks, d->run);
        if (d->run->nrows)
            s->last = d->run->rows[d->run->nrows - 1];
    }
    return ADH_SUCCESS;
}

int adh_drive_restore(adh_drive *d, const adh_drive_snap *s)
{
    adh_run *r = d->run;
    int ahead = r && s->marks.nrows == r->nrows + 1;
    if (!snap_fits(d, s) || (r && (s->marks.nrows > r->nrows + 1 || s->marks.nprofiles > r->nprofiles + ahead)))
        return ADH_EINVAL;
    /* one row ahead of the run (a redo): the snapshot's own last row, and
     * its profile when that row stored one (the snapshot's state is it) */
    if (ahead && adh_run_push_row(r, &s->last) != ADH_SUCCESS)
        return ADH_ENOMEM;
    if (ahead && s->marks.nprofiles == r->nprofiles + 1 &&
        adh_run_push_profile(r, adh_drive_snap_state(s), s->last.branch, s->last.path) != ADH_SUCCESS)
        return ADH_ENOMEM;
    d->type->load(d->r, s->snap);
    d->c = s->c;
    ts_assign(d->ts, s->ts);
    if (r) {
        for (size_t i = s->marks.nprofiles; i < r->nprofiles; i++)
            free(r->profiles[i].u);
        copy_marks(r, &s->marks);
    }
    return ADH_SUCCESS;
}

int adh_drive_hand(adh_drive *d, int dir)
{
    if ((dir != 1 && dir != -1) || d->type->next)
        return ADH_EINVAL;   /* a curve rule walks its own path */
    if (d->c.inflight || (d->c.ph == PH_DONE && d->c.status == ADH_EINVAL && d->c.row < 0))
        return ADH_EINVAL;   /* a step under way, or never set */
    hand_plan hp;
    int rc = plan_hand(d, dir, &hp);
    if (rc == ADH_SUCCESS)
        d->c.hand = dir;
    return rc;
}

double adh_drive_hand_position(const adh_drive *d, int dir)
{
    hand_plan hp;
    plan_hand(d, dir, &hp);
    return hp.h0;
}

int adh_drive_pending(const adh_drive *d)
{
    return d->c.hand != 0 || d->c.inflight;
}

unsigned adh_drive_events(const adh_drive *d)
{
    return d->c.row >= 0 ? d->c.events : 0;
}

double adh_drive_step_position(const adh_drive *d)
{
    return d->c.inflight ? d->c.h0 : NAN;
}

size_t adh_drive_progress(const adh_drive *d, double *change)
{
    *change = NAN;
    return d->type->progress ? d->type->progress(d->r, change) : 0;
}

/* Whether the run has a turn recorded at h0. */
static int turn_recorded(const adh_drive *d, double h0)
{
    for (size_t i = 0; d->run && i < d->run->nturns; i++)
        if (fabs(d->run->turns[i].h0 - h0) < 1e-6 * d->ps.step)
            return 1;
    return 0;
}

int adh_drive_retarget(adh_drive *d, const adh_protocol_settings *ps)
{
    if (!(ps->step == d->ps.step) || ps->nturns > ADH_MAX_TURNS || d->c.inflight || d->type->next)
        return ADH_EINVAL;
    d->ps.nturns = ps->nturns;
    memcpy(d->ps.turns, ps->turns, ps->nturns * sizeof *ps->turns);
    memcpy(d->turns, ps->turns, ps->nturns * sizeof *d->turns);
    qsort(d->turns, ps->nturns, sizeof *d->turns, cmp_desc);
    /* the turns the loading branch has passed are behind it */
    double deepest = INFINITY, tol = 1e-6 * ps->step;
    for (size_t i = 0; d->run && i < d->run->nrows; i++)
        if (d->run->rows[i].branch > 0)
            deepest = fmin(deepest, d->run->rows[i].h0);
    size_t ti = 0;
    int unrecorded = 0;
    while (ti < ps->nturns && d->turns[ti] >= deepest - tol) {
        unrecorded |= !turn_recorded(d, d->turns[ti]);
        ti++;
    }
    d->c.ti = ti;
    const adh_obs *last = d->run && d->c.row >= 0 ? &d->run->rows[d->c.row] : NULL;
    if (unrecorded && last && last->branch > 0 && (d->c.ph == PH_LOAD || d->c.ph == PH_DONE)) {
        /* a turn the loading branch passed before it was set: the path
         * turns where it is now, and unloads from here */
        if (!turn_recorded(d, last->h0) && d->run->nturns < ADH_MAX_TURNS && record_turn(d, last) != ADH_SUCCESS)
            return ADH_ENOMEM;
    }
    if (d->c.ph == PH_DONE && d->c.status == ADH_SUCCESS && last) {
        if (last->branch > 0 && ti < ps->nturns) {
            d->c.ph = PH_LOAD;   /* a deeper turn: loading goes on */
        } else {
            next_turn(d);        /* a turn to unload or to reach: the protocol goes on */
        }
    }
    if (d->c.ph == PH_LOAD && last && last->branch > 0 && ti == ps->nturns && unrecorded)
        next_turn(d);            /* the turn just recorded here is unloaded next */
    return ADH_SUCCESS;
}

int adh_drive_next(const adh_drive *d, size_t *turn)
{
    const cursor *c = &d->c;
    size_t nt = d->ps.nturns, u;
    *turn = 0;
    if (c->hand)
        return c->hand;
    switch (c->ph) {
    case PH_START:
    case PH_LOAD:
        if (!loading_done(d)) {
            *turn = c->ti < nt ? c->ti + 1 : 0;
            return +1;
        }
        break;
    case PH_TURN:
        *turn = c->ui + 1;
        return -1;
    case PH_UNLOAD:
        if (!branch_ends(d)) {
            *turn = c->ui + 1;
            return -1;
        }
        break;
    default:
        return 0;
    }
    switch (after_branch(d, &u)) {
    case PH_TURN:
        *turn = u + 1;
        return -1;
    case PH_LOAD:   /* turns steps by hand left unreached */
        *turn = c->ti + 1;
        return +1;
    default:
        return 0;
    }
}

int adh_drive_status(const adh_drive *d)
{
    return d->c.ph == PH_DONE ? d->c.status : ADH_CONTINUE;
}
