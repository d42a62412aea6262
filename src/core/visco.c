/* The viscoelastic protocol (adhere/visco.h): load from the start to the
 * deepest turn at the approach speed (snapshotting every turn), then from
 * each turn's snapshot dwell and retract at the retraction speed until the
 * base is back at the start. One integrator step a call; events (a fold,
 * contact, a force minimum, a turn, a profile position, a segment's end)
 * are IDAS's roots. */
#include "visco.h"

#include <idas/idas.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/clock.h"
#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "adhere/units.h"

/* A crossing that has not landed in this many steps is lost (a resolved
 * grid's crossings take tens to a few hundred): the jump relaxes instead. */
#define VISCO_CROSS_STEPS 1000
/* ... and one whose retries (each a quarter of the step that went
 * backwards) have come down to steps this many tolerances long (in z0 of
 * the crossing's arclength) is lost too: a step that moves u by a
 * thousandth of its tolerance resolves nothing more of a hairpin, and
 * before this floor the retries went on to steps of 1e-250 (measured at
 * sigma = 75 next to the jump-out: twice 480 retries, 60 CPU s, before
 * the step count gave up). */
#define VISCO_RETRY_MIN 1e-3
/* A relaxation has landed when nothing moves faster than this many
 * tolerances per unit pseudo-time (its rates are 1 and more). */
#define VISCO_REST 1e-3
/* ... and a rest on no equilibrium (the ghost of a vanished fold) makes
 * it ten times stricter, down to this */
#define VISCO_REST_MIN 1e-9
/* A relaxed jump's push off its fold along the path's tangent (per z0):
 * first a thousandth, ten times more each time the relaxation comes back
 * to the fold (the root put the fold on its stable side, further from it
 * than the push), up to a tenth. */
#define VISCO_NUDGE 1e-3
#define VISCO_NUDGE_MAX 0.1

/* A push that came to nothing (a relaxation back at its fold, or the
 * integrator stuck again at the instant it was pushed off): ten times
 * harder, while below VISCO_NUDGE_MAX. 1 with *push raised, 0 when it
 * may grow no more. */
static int push_harder(double *push)
{
    if (!(*push < VISCO_NUDGE_MAX))
        return 0;
    *push *= 10;
    return 1;
}
/* A relaxation that has not come to rest is checked every this many steps
 * for an equilibrium next to it (Newton on a copy): next to a lattice fold
 * of the contact line one crawled on at steps of 1e-5 with an error-test
 * failure every other step, moving the contact line by a thousandth of a
 * ring, faster than its rest test all the same (measured at sigma = 75
 * loading, 2300 steps before it was stopped by hand; it would have gone
 * on to max_jump_steps and stopped the run). */
#define VISCO_FLOW_CHECK 100


static void snaps_free(adh_visco *w)
{
    for (size_t i = 0; i < ADH_MAX_TURNS; i++) {
        free(w->snap[i].y);
        w->snap[i].y = NULL;
    }
    free(w->yfold);
    w->yfold = NULL;
}

void adh_visco_free(adh_visco *w)
{
    if (!w)
        return;
    adh_visco_dae_destroy(w);
    adh_visco_pre_free(w->pre);
    snaps_free(w);
    adh_state_free(w->st);
    adh_static_free(w->stat);
    adh_visco_rothe_free(w);
    free(w->egap);
    free(w->shape);
    free(w->ev);
    free(w->prof);
    free(w->keep);
    free(w);
}

adh_visco *adh_visco_alloc(const adh_grid *g, const adh_kernel *k)
{
    adh_visco *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    size_t n = g->n;
    w->g = g;
    w->k = k;
    w->n = n;
    w->pre = adh_visco_pre_alloc(g, k);
    w->st = adh_state_alloc(n);
    /* shape, area, h, p, D, tmp, tmp2, scratch, pD, ppq, WD, Wpq: n each;
     * bord: 4 n */
    w->shape = malloc(16 * n * sizeof *w->shape);
    if (!w->pre || !w->st || !w->shape) {
        adh_visco_free(w);
        return NULL;
    }
    double **bufs[] = { &w->shape, &w->area, &w->h, &w->p, &w->D, &w->tmp, &w->tmp2, &w->scratch,
                        &w->pD, &w->ppq, &w->WD, &w->Wpq, &w->bord };
    for (size_t i = 1; i < sizeof bufs / sizeof *bufs; i++)
        *bufs[i] = w->shape + i * n;
    for (size_t i = 0; i < n; i++)
        w->area[i] = 2.0 * M_PI * adh_rings_weight(g, i);
    w->status = ADH_EINVAL; /* not set yet */
    w->done = 1;
    return w;
}

/* The physical state of y under the current segment: st, time, base, F. */
static void load_state(adh_visco *w, const double *y)
{
    double h0 = adh_visco_h0_of(w, y);
    adh_visco_gaps(w, y, h0);
    memcpy(w->st->u, y, w->n * sizeof *y);
    memcpy(w->st->h, w->h, w->n * sizeof *y);
    memcpy(w->st->p, w->p, w->n * sizeof *y);
    w->st->h0 = h0;
    w->t_now = w->seg.t0 + y[w->IT];
    w->base_now = adh_visco_base_of(w, y);
    w->F_now = adh_visco_force(w, h0);
}

static double contact_radius(const adh_visco *w)
{
    return adh_contact_radius(w->g, w->st->h, w->m.z0);
}

static void fill_event(adh_visco *w, adh_visco_event *e, int kind)
{
    memset(e, 0, sizeof *e);
    e->kind = kind;
    e->path = w->seg.path;
    e->t = w->t_now;
    e->base = w->base_now;
    e->h0 = e->h0_after = w->st->h0;
    e->F = e->F_after = w->F_now;
    e->a = e->a_after = contact_radius(w);
}

static int add_event(adh_visco *w, int kind)
{
    if (w->nev == w->evcap) {
        size_t cap = w->evcap ? 2 * w->evcap : 64;
        adh_visco_event *e = realloc(w->ev, cap * sizeof *e);
        if (!e)
            return ADH_ENOMEM;
        w->ev = e;
        w->evcap = cap;
    }
    fill_event(w, &w->ev[w->nev++], kind);
    return ADH_SUCCESS;
}

/* A force minimum on unloading. The force's lattice wiggles (the contact
 * line snapping ring by ring: on a coarse grid each snap raises the force
 * by a few per cent) make a minimum at each ring; an unloading path has
 * one pull-off, its lowest minimum: a lower one replaces the last, which
 * moves to the end of the events (those between came before it). */
static int pulloff_event_at(adh_visco *w, const adh_visco_event *at)
{
    adh_visco_event *last = w->pull_ev ? &w->ev[w->pull_ev - 1] : NULL;
    double F = at ? at->F : w->F_now;
    if (last && !(F < last->F))
        return ADH_SUCCESS;
    if (last) {
        memmove(last, last + 1, (w->nev - w->pull_ev) * sizeof *last);
        w->nev--;
    }
    int rc = add_event(w, ADH_VISCO_PULLOFF);
    if (rc == ADH_SUCCESS && at)
        w->ev[w->nev - 1] = *at;
    w->pull_ev = rc == ADH_SUCCESS ? w->nev : 0;
    return rc;
}

static int pulloff_event(adh_visco *w)
{
    return pulloff_event_at(w, NULL);
}

/* IDAS's counters so far: steps, Newton and GMRES iterations,
 * preconditioner setups, error-test failures. */
static void counters(const adh_visco *w, long *c)
{
    memset(c, 0, 5 * sizeof *c);
    if (!w->ida || !w->live)
        return;
    IDAGetNumSteps(w->ida, &c[0]);
    IDAGetNumNonlinSolvIters(w->ida, &c[1]);
    IDAGetNumLinIters(w->ida, &c[2]);
    IDAGetNumPrecEvals(w->ida, &c[3]);
    IDAGetNumErrTestFails(w->ida, &c[4]);
}

/* The accounts now: those folded in at the last initialisation plus the
 * quadratures since. */
static adh_visco_energy accounts_now(adh_visco *w)
{
    adh_visco_energy e = w->acc;
    double s;
    if (w->ida && w->live && IDAGetQuad(w->ida, &s, w->yq) == IDA_SUCCESS) {
        const double *q = N_VGetArrayPointer(w->yq);
        e.work += q[QWORK];
        e.dissipated += q[QDISS];
    }
    return e;
}

/* Before IDAS starts again: fold its counters and quadratures in (once:
 * until it starts, there is nothing live to add). */
static void fold_in(adh_visco *w)
{
    long c[5];
    counters(w, c);
    for (int i = 0; i < 5; i++)
        w->stat0[i] += c[i];
    w->acc = accounts_now(w);
    w->live = 0;
}

/* Starts the integrator at s and y under the current segment and mode
 * (y' the path's tangent, or given). */
static int restart_idas(adh_visco *w, double s, double *y, const double *yp_given)
{
    double *ypv = malloc(w->len * sizeof *ypv);
    if (!ypv)
        return ADH_ENOMEM;
    /* on the path (or, for a crossing, on the equilibria at its h0)
     * within a thousandth of the tolerance first; a relaxation starts
     * off them on purpose */
    int rc = w->mode == MODE_FLOW ? ADH_SUCCESS : adh_visco_polish(w, y, w->mode == MODE_PATH);
    if (rc == ADH_SUCCESS && yp_given)
        memcpy(ypv, yp_given, w->len * sizeof *ypv);
    else if (rc == ADH_SUCCESS)
        rc = adh_visco_tangent(w, y, ypv);
    if (rc != ADH_SUCCESS)
        snprintf(w->errmsg, sizeof w->errmsg, "at t = %.6g s, h0 = %.6g m, %s could not be %s", w->t_now,
                 adh_visco_h0_of(w, y), w->mode == MODE_CROSS ? "a jump's crossing" : "the path",
                 yp_given ? "put back on its equilibria (Newton)" : "restarted (Newton or its tangent)");
    if (rc == ADH_SUCCESS && (rc = adh_visco_dae_start(w, s, y, ypv)) != ADH_SUCCESS) {
        char ida[200];
        snprintf(ida, sizeof ida, "%.199s", w->errmsg);
        snprintf(w->errmsg, sizeof w->errmsg, "at t = %.6g s, h0 = %.6g m, the integrator could not be restarted%s%s%s",
                 w->t_now, adh_visco_h0_of(w, y), *ida ? " (" : "", ida, *ida ? ")" : "");
    }
    w->live = rc == ADH_SUCCESS;
    free(ypv);
    return rc;
}

/* Starts the path's integration at y: the Rothe steps where they
 * integrate it (the path, not a jump), else IDAS. */
static int restart(adh_visco *w, double s, double *y, const double *yp_given)
{
    fold_in(w);
    w->nrprev = 0;
    if (w->rothe && w->mode == MODE_PATH) {
        w->rothe_on = 1;
        int rc = adh_visco_rothe_reset(w, y);
        if (rc != ADH_SUCCESS)
            snprintf(w->errmsg, sizeof w->errmsg, "at t = %.6g s, h0 = %.6g m, the Rothe steps could not start: %s",
                     w->t_now, adh_visco_h0_of(w, y), adh_strerror(rc));
        return rc;
    }
    w->rothe_on = 0;
    return restart_idas(w, s, y, yp_given);
}

static int push_row(adh_visco *w, double t0)
{
    adh_obs o;
    memset(&o, 0, sizeof o);
    adh_observe(w->g, &w->m, w->st, &o);
    o.t = w->t_now;
    o.base = w->base_now;
    o.branch = w->seg.branch;
    o.path = w->seg.path;
    o.converged = 1;
    o.stable = 1;
    o.seconds = adh_clock_seconds() - t0;
    long c[5];
    counters(w, c);
    o.iters = (size_t)(w->stat0[1] + c[1]) - w->res.newton;
    w->res.newton = (size_t)(w->stat0[1] + c[1]);
    if (adh_run_push_row(w->run, &o) != ADH_SUCCESS)
        return ADH_ENOMEM;
    w->run->seconds += o.seconds;
    if (o.a >= 0.9 * w->g->rmax || !adh_rings_resolves(w->g, o.a))
        return ADH_EGRID;
    return ADH_CONTINUE;
}

/* A stall in contact on a grid coarser than the one that resolves the
 * contact line (the static curve's limit, 0.3 edge zones): there the
 * contact line snaps ring by ring across the lattice's folds, and a
 * pair of them too tight for either integrator stops the run (measured:
 * E0 = Einf = 0.3 GPa at 1 nm/s on 5 nm rings, 1.05 nm resolving them,
 * stopped in contact on loading; 10 and 15 nm rings ran). The sentence
 * says so, names the spacing and the one that is allowed, and asks for
 * a finer grid; IDAS's words follow where there is room. */
static void stall_unresolved(adh_visco *w)
{
    double lim = ADH_GRID_EDGE_SPACING_STATIC * adh_edge_zone(&w->m);
    if (!w->in_contact || !(w->g->dr > lim))
        return;
    /* the integrator's own words, within the parentheses of what it said */
    char said[sizeof w->errmsg];
    const char *in = strstr(w->errmsg, " (");
    snprintf(said, sizeof said, "%s", in ? in + 2 : w->errmsg);
    size_t k = strlen(said);
    if (in && k && said[k - 1] == ')')
        said[--k] = '\0';
    int n = snprintf(w->errmsg, sizeof w->errmsg,
                     "the contact line's lattice folds stopped the integrator at t = %.6g s, h0 = %s on a grid of "
                     "spacing %s, coarser than the %s that resolves them (%g of the contact's edge zone, %s): use a "
                     "finer grid",
                     w->t_now, adh_qtext(adh_visco_h0_of(w, N_VGetArrayPointer(w->y)), ADH_Q_LENGTH).s,
                     adh_qtext(w->g->dr, ADH_Q_LENGTH).s, adh_qtext(lim, ADH_Q_LENGTH).s, ADH_GRID_EDGE_SPACING_STATIC,
                     adh_qtext(adh_edge_zone(&w->m), ADH_Q_LENGTH).s);
    size_t at = n > 0 ? (size_t)n : 0;
    if (k && at + 8 < sizeof w->errmsg) {   /* as much of them as fits, in parentheses */
        size_t take = k < sizeof w->errmsg - at - 4 ? k : sizeof w->errmsg - at - 4;
        memcpy(w->errmsg + at, " (", 2);
        memcpy(w->errmsg + at + 2, said, take);
        memcpy(w->errmsg + at + 2 + take, ")", 2);
    }
    w->fix = ADH_FIX_SPACING | ADH_FIX_NODES;
}

static int stop(adh_visco *w, int rc)
{
    if (rc == ADH_ESTALL)
        stall_unresolved(w);
    if (rc == ADH_EMAXITER)
        snprintf(w->errmsg, sizeof w->errmsg, "the integrator took its cap of %zu steps by t = %.6g s, h0 = %.6g m",
                 w->s.max_steps, w->t_now, adh_visco_h0_of(w, N_VGetArrayPointer(w->y)));
    else if (rc != ADH_SUCCESS && rc != ADH_EINTR && !w->errmsg[0])
        snprintf(w->errmsg, sizeof w->errmsg, "at t = %.6g s, h0 = %.6g m: %s", w->t_now,
                 adh_visco_h0_of(w, N_VGetArrayPointer(w->y)), adh_strerror(rc));
    w->done = 1;
    w->status = rc;
    w->run->status = rc == ADH_EINTR ? ADH_SUCCESS : rc;
    if (rc == ADH_EINTR)
        w->run->interrupted = 1;
    return rc;
}

static adh_turn_result *turn_now(adh_visco *w)
{
    return w->seg.path > 0 ? &w->run->turns[w->seg.path - 1] : NULL;
}

/* After a row: the unloading's lowest force so far, the grid's check. */
static int finish_row(adh_visco *w, int rc)
{
    adh_turn_result *tr = turn_now(w);
    if (tr && w->F_now < tr->pulloff_F) {
        tr->pulloff_F = w->F_now;
        tr->pulloff_h0 = w->st->h0;
    }
    if (tr && (size_t)w->seg.path == w->nturns && !(w->F_now >= w->res.pulloff_F)) {
        w->res.pulloff_F = w->F_now, w->res.pulloff_h0 = w->st->h0;
        w->res.pulloff_t = w->t_now, w->res.pulloff_base = w->base_now;
    }
    if (rc == ADH_EGRID || rc == ADH_ENOMEM)
        return stop(w, rc);
    return ADH_CONTINUE;
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

static double auto_start(const adh_visco *w)
{
    adh_material m0 = w->m;
    m0.E = w->v.E0;
    return adh_visco_auto_start(&m0, w->spring ? w->dr.spring : INFINITY, w->ps.step > 0 ? w->ps.step : 0.05e-9);
}

double adh_visco_auto_start(const adh_material *m, double spring, double step)
{
    double h = adh_protocol_auto_start(m, step);
    if (spring < INFINITY) {
        double hs = cbrt(4.0 * m->A * m->R / (3.0 * spring));
        if (hs > h)
            h = step * ceil(hs / step);
    }
    return h;
}

/* The start at sphere position h0, at rest: the material has relaxed
 * there (q = p), so u = -(2/E0) W p, by fixed point (a contraction this
 * far out; adh_visco_rest). y gets u, q, tl = 0[, h0]; *base the base
 * that holds it. */
static int solve_start(adh_visco *w, double h0, double *y, double *base)
{
    size_t n = w->n;
    memset(y, 0, w->len * sizeof *y);
    visco_rest_buf b = { y, w->h, w->p, w->tmp, w->tmp2, w->scratch, w->shape };
    if (adh_visco_rest(w->k, &w->m, w->cinf + w->cdel, h0, n, &b) != 0)
        return ADH_ESTALL;
    memcpy(y + w->IQ, w->p, n * sizeof *y);
    double F = adh_visco_force(w, h0);
    *base = w->spring ? h0 - F / w->dr.spring : h0;
    if (w->spring)
        y[w->IH] = h0;
    return ADH_SUCCESS;
}

static int check_all(const adh_material *m, const adh_sls *v, const adh_visco_drive *d,
                     const adh_visco_settings *s, const adh_protocol_settings *ps, char *why, size_t whylen)
{
    int rc;
    adh_material m0 = *m;
    m0.E = v->E0;
    if ((rc = adh_sls_validate(v, why, whylen)) != ADH_SUCCESS ||
        (rc = adh_visco_drive_validate(d, why, whylen)) != ADH_SUCCESS ||
        (rc = adh_visco_settings_validate(s, why, whylen)) != ADH_SUCCESS ||
        (rc = adh_material_validate(&m0, why, whylen)) != ADH_SUCCESS)
        return rc;
    if (ps->nturns > ADH_MAX_TURNS || ps->nprofiles > ADH_MAX_PROFILES) {
        if (why)
            snprintf(why, whylen, "%zu turns and %zu profiles given: at most %d of each are allowed", ps->nturns,
                     ps->nprofiles, ADH_MAX_TURNS);
        return ADH_EINVAL;
    }
    return ADH_SUCCESS;
}

/* A landing point this close (in z0) to a mark before it, or to a turn,
 * is dropped: a row lands there already, and a step of next to nothing
 * between the two would be all it added. */
#define LAND_MERGE 1e-3

typedef struct { double b; unsigned char keep; } visco_mark;

static int cmp_mark_desc(const void *a, const void *b)
{
    double x = ((const visco_mark *)a)->b, y = ((const visco_mark *)b)->b;
    return x > y ? -1 : x < y;
}

static int near_turn(const adh_visco *w, double b)
{
    for (size_t k = 0; k < w->nturns; k++)
        if (fabs(b - w->turns[k]) < LAND_MERGE * w->m.z0)
            return 1;
    return 0;
}

/* The profiles (kept) and the landing points (a row only), highest first. */
static int set_marks(adh_visco *w, const adh_visco_settings *s)
{
    size_t n = w->ps.nprofiles + (s->land ? s->nland : 0);
    visco_mark *mk = malloc((n ? n : 1) * sizeof *mk);
    if (!mk)
        return ADH_ENOMEM;
    for (size_t i = 0; i < n; i++) {
        int kept = i < w->ps.nprofiles;
        mk[i].b = kept ? w->ps.profiles[i] : s->land[i - w->ps.nprofiles];
        mk[i].keep = (unsigned char)kept;
    }
    qsort(mk, n, sizeof *mk, cmp_mark_desc);
    if (n > w->profcap) {
        double *p = realloc(w->prof, n * sizeof *p);
        if (p)
            w->prof = p;
        unsigned char *k = p ? realloc(w->keep, n) : NULL;
        if (k)
            w->keep = k;
        if (!p || !k) {
            free(mk);
            return ADH_ENOMEM;
        }
        w->profcap = n;
    }
    w->nprof = 0;
    for (size_t i = 0; i < n; i++) {
        int close = w->nprof > 0 && w->prof[w->nprof - 1] - mk[i].b < LAND_MERGE * w->m.z0;
        if (!mk[i].keep && (close || near_turn(w, mk[i].b) || !isfinite(mk[i].b)))
            continue;
        w->prof[w->nprof] = mk[i].b;
        w->keep[w->nprof++] = mk[i].keep;
    }
    free(mk);
    return ADH_SUCCESS;
}

static int set_protocol(adh_visco *w, const adh_visco_settings *s)
{
    w->nturns = w->ps.nturns;
    memcpy(w->turns, w->ps.turns, w->nturns * sizeof *w->turns);
    qsort(w->turns, w->nturns, sizeof *w->turns, cmp_desc);
    int rc = set_marks(w, s);
    w->ti = w->ui = w->pi = 0;
    while (w->pi < w->nprof && w->prof[w->pi] > w->b_start)
        w->pi++;
    return rc;
}

/* The next profile position on the current branch (NAN: none left). */
static double next_profile(const adh_visco *w)
{
    if (w->seg.branch > 0)
        return w->pi < w->nprof ? w->prof[w->pi] : NAN;
    return w->pi > 0 ? w->prof[w->pi - 1] : NAN;
}

/* The mark the base has reached is a profile's (else a landing point's). */
static int profile_here(const adh_visco *w)
{
    size_t i = w->seg.branch > 0 ? w->pi : w->pi - 1;
    return i < w->nprof && w->keep[i];
}

static void seg_set(adh_visco *w, int kind, double t0, double b0)
{
    visco_seg *sg = &w->seg;
    sg->kind = kind;
    sg->t0 = t0;
    sg->b0 = b0;
    sg->bdot = kind == SEG_LOAD ? -w->dr.speed_in : kind == SEG_UNLOAD ? w->dr.speed_out : 0;
    /* the metric's speed: the base's, but at least z0 per tau, so that
     * time counts while q relaxes at a standing (or crawling) base: the
     * path there must not look vertical (t' ~ 0, a fold to the rootfinder).
     * An elastic solid (cdel = 0) has no q to relax: a moving base's own
     * speed, so that its path is the same at every speed (rate-independent,
     * as it is); with the floor 500 times the base's at 1 nm/s, IDAS's
     * corrector failed at a lattice fold on 5 nm rings where 1 um/s ran */
    double vt = w->cdel > 0 || kind == SEG_DWELL ? w->m.z0 / w->v.tau : 0;
    sg->vm = fmax(kind == SEG_LOAD ? w->dr.speed_in : kind == SEG_UNLOAD ? w->dr.speed_out : 0, vt);
    sg->tl_end = w->dr.dwell;
    sg->branch = kind == SEG_LOAD ? +1 : -1;
    sg->target = kind == SEG_LOAD ? (w->ti < w->nturns ? w->turns[w->ti] : NAN) : w->b_start;
    w->mode = MODE_PATH;
    sg->prof = next_profile(w);
}

int adh_visco_set(adh_visco *w, const adh_material *m, const adh_sls *v, const adh_visco_drive *d,
                  const adh_visco_settings *s, const adh_protocol_settings *ps, adh_run *run, char *why,
                  size_t whylen)
{
    int rc = check_all(m, v, d, s, ps, why, whylen);
    if (rc != ADH_SUCCESS)
        return rc;
    size_t n = w->n;
    adh_visco_dae_destroy(w);
    snaps_free(w);
    w->m = *m;
    w->m.E = v->E0;
    w->v = *v, w->dr = *d, w->s = *s, w->ps = *ps, w->run = run;
    w->errmsg[0] = '\0';
    w->fix = 0;
    w->spring = isfinite(d->spring);
    if (s->integrator == ADH_VISCO_ROTHE && w->spring) {
        if (why)
            snprintf(why, whylen, "the Rothe integrator under a spring of %g N/m is not allowed: it steps under "
                     "displacement control only (the IDAS integrator, or auto, takes the spring)", d->spring);
        return ADH_EINVAL;
    }
    w->rothe = adh_visco_rothe_applies(v, d, s);
    w->rothe_on = 0;
    w->rothe_factor = 0;
    adh_visco_rothe_free(w);
    w->IQ = n, w->IT = 2 * n, w->IH = 2 * n + 1;
    w->len = 2 * n + 1 + (size_t)w->spring;
    w->cinf = 2.0 / v->Einf;
    w->cdel = fmax(0.0, 2.0 * (1.0 / v->E0 - 1.0 / v->Einf));
    /* a HODLR factorization at nine tenths of the instantaneous compliance:
     * at a fold of the instantaneous problem J is singular, and a bordered
     * solve through the Schur complement of a factorization singular there
     * too would be all cancellation; at 0.9 cinf the fold's mode has
     * eigenvalue 0.1 and the mismatch is GMRES's (visco_pre.c) */
    adh_visco_pre_base(w->pre, 0.9 * w->cinf);
    w->theta = 1.0 / (double)n;
    w->pref = m->A / (6.0 * M_PI * pow(m->z0, 3));
    /* how far a spring can stretch: twice the adhesive force Einf/E0
     * times the law's DMT pull-off, over k; and how far from its fold a
     * jump's crossing may take the sphere: the model's reach, R/50, and
     * that */
    adh_derived dv;
    adh_material_derive(&w->m, &dv);
    w->stretch = w->spring ? 2.0 * v->Einf / v->E0 * fabs(dv.F_dmt) / d->spring : 0;
    w->reach = 0.02 * m->R + w->stretch;
    for (size_t i = 0; i < n; i++)
        w->shape[i] = w->g->r[i] * w->g->r[i] / (2.0 * m->R);
    w->nev = w->pull_ev = 0;
    memset(&w->acc, 0, sizeof w->acc);
    memset(w->stat0, 0, sizeof w->stat0);
    memset(&w->res, 0, sizeof w->res);
    w->t_resumed = w->t_stuck = NAN;
    w->stuck_push = VISCO_NUDGE;
    w->res.jump_in_h0 = w->res.jump_out_h0 = w->res.pulloff_F = NAN;
    w->res.jump_in_t = w->res.jump_in_base = w->res.jump_out_t = w->res.jump_out_base = NAN;
    w->res.pulloff_h0 = w->res.pulloff_t = w->res.pulloff_base = NAN;
    w->res.hysteresis = NAN;   /* until the deepest turn's cycle closes (close_cycle) */
    w->started = w->first_pending = w->finishing = 0;
    w->done = 1;
    w->s_now = 0;
    w->land_try = 0;
    for (size_t i = 0; i < ps->nturns; i++)
        if (!(w->snap[i].y = malloc(w->len * sizeof *w->snap[i].y)))
            return ADH_ENOMEM;
    if (!(w->yfold = malloc(8 * w->len * sizeof *w->yfold)))
        return ADH_ENOMEM;
    w->ypfold = w->yfold + w->len, w->ywork = w->ypfold + w->len;
    w->yprev = w->ywork + w->len, w->ypprev = w->yprev + w->len, w->ypflow = w->ypprev + w->len;
    w->ro_last = w->ypflow + w->len, w->ro_dir = w->ro_last + w->len;
    if ((rc = adh_visco_dae_create(w)) != ADH_SUCCESS)
        return rc;
    double h0 = isnan(ps->start) ? auto_start(w) : ps->start;
    double *y = N_VGetArrayPointer(w->y);
    w->seg.t0 = 0, w->seg.bdot = 0, w->seg.b0 = h0;
    if (solve_start(w, h0, y, &w->b_start) != ADH_SUCCESS) {
        if (why)
            snprintf(why, whylen, "the start h0 = %s is not a stable point out of contact%s: start further out",
                     adh_qtext(h0, ADH_Q_LENGTH).s, w->spring ? " under the spring" : "");
        return ADH_ESTALL;
    }
    w->h0_start = h0;
    w->res.start_base = w->b_start, w->res.start_h0 = h0;
    if ((rc = set_protocol(w, s)) != ADH_SUCCESS)
        return rc;
    seg_set(w, SEG_LOAD, 0.0, w->b_start);
    w->seg.path = 0;
    run->start = h0;
    run->jump_in_h0 = NAN;
    load_state(w, y);
    w->in_contact = 0;
    w->acc.stored0 = w->acc.stored = adh_visco_energy_of(w, y, NULL, NULL, NULL);
    rc = restart(w, w->s_now, y, NULL);
    if (rc != ADH_SUCCESS)
        return rc;
    load_state(w, y);
    w->done = 0;
    w->status = ADH_CONTINUE;
    return ADH_SUCCESS;
}

/* Loading reached turn k: its snapshot. */
static void take_snapshot(adh_visco *w, size_t k)
{
    visco_snap *sn = &w->snap[k];
    memcpy(sn->y, N_VGetArrayPointer(w->y), w->len * sizeof *sn->y);
    sn->y[w->IT] = 0;
    sn->t = w->t_now;
    sn->base = w->base_now;
    sn->h0 = w->st->h0;
    sn->acc = accounts_now(w);
    sn->reached = 1;
}

/* Unloading from turn k: its snapshot, then a dwell or the retraction;
 * the next call's row is the turn's state. */
static int begin_turn(adh_visco *w, size_t k)
{
    visco_snap *sn = &w->snap[k];
    double *y = N_VGetArrayPointer(w->y);
    memcpy(y, sn->y, w->len * sizeof *y);
    w->ui = k;
    w->extended = 0;
    w->pull_ev = 0;
    /* profiles: the unloading ones are those above the turn */
    w->pi = 0;
    while (w->pi < w->nprof && w->prof[w->pi] > sn->base)
        w->pi++;
    w->seg.branch = -1;
    seg_set(w, w->dr.dwell > 0 ? SEG_DWELL : SEG_UNLOAD, sn->t, sn->base);
    w->seg.path = (int)k + 1;
    fold_in(w);
    w->acc = sn->acc;
    load_state(w, y);
    adh_turn_result *tr = &w->run->turns[k];
    memset(tr, 0, sizeof *tr);
    tr->h0 = sn->h0;
    tr->max_load = w->F_now;
    tr->a_turn = contact_radius(w);
    tr->pulloff_F = w->F_now;
    tr->pulloff_h0 = sn->h0;
    tr->jump_out_h0 = NAN;
    tr->hysteresis = NAN;   /* until its cycle closes (close_cycle) */
    tr->path = (int)k + 1;
    w->run->nturns = k + 1;
    w->in_contact = tr->a_turn > 0;
    int rc = restart(w, w->s_now, y, NULL);
    if (rc != ADH_SUCCESS)
        return rc;
    w->first_pending = 1;
    return ADH_SUCCESS;
}

/* A turn's cycle is over: its hysteresis (turns.tsv); the deepest's
 * accounts are the run's, and its summary. */
static void close_cycle(adh_visco *w)
{
    w->acc = accounts_now(w);
    w->acc.stored = adh_visco_energy_of(w, N_VGetArrayPointer(w->y), NULL, NULL, NULL);
    /* every turn's cycle began at the start (its accounts the loading's to
     * its snapshot), so its work is its hysteresis: turns.tsv's */
    adh_turn_result *tr = turn_now(w);
    if (tr)
        tr->hysteresis = w->acc.work;
    if ((size_t)w->seg.path != w->nturns)
        return;
    w->res.cycle = w->acc;
    w->res.hysteresis = w->acc.work;
}

/* The root ending a segment: a turn (loading), the dwell's end, or the
 * base back at the start. The row is pushed first. */
static int segment_end(adh_visco *w, double t0)
{
    double *y = N_VGetArrayPointer(w->y);
    int rc = push_row(w, t0);
    if (w->seg.kind == SEG_LOAD) {
        take_snapshot(w, w->ti);
        add_event(w, ADH_VISCO_TURN);
        if (++w->ti < w->nturns) {
            w->seg.target = w->turns[w->ti];
        } else if (w->ps.unload && rc == ADH_CONTINUE) {
            int brc = begin_turn(w, 0);
            if (brc != ADH_SUCCESS)
                return stop(w, brc);
        } else {
            w->finishing = 1;
        }
        return finish_row(w, rc);
    }
    if (w->seg.kind == SEG_DWELL) {
        seg_set(w, SEG_UNLOAD, w->t_now, w->base_now);
        w->seg.path = (int)w->ui + 1;
        y[w->IT] = 0;
        add_event(w, ADH_VISCO_UNLOAD);
        int brc = restart(w, w->s_now, y, NULL);
        if (brc != ADH_SUCCESS)
            return stop(w, brc);
        return finish_row(w, rc);
    }
    if (w->in_contact && !w->extended && rc == ADH_CONTINUE) {
        /* still in contact where the base started (a spring's pull, or a
         * slow peel, reaches this far): retraction goes on until the
         * surfaces are apart (contact_changed ends it a z0 after), at most
         * as far as the model reaches, R/50, and the spring stretches */
        w->extended = 1;
        w->seg.target = w->b_start + w->reach;
        return finish_row(w, rc);
    }
    add_event(w, ADH_VISCO_END);
    rc = finish_row(w, rc);
    close_cycle(w);
    if (rc == ADH_CONTINUE && w->ui + 1 < w->nturns) {
        int brc = begin_turn(w, w->ui + 1);
        if (brc != ADH_SUCCESS)
            return stop(w, brc);
    } else {
        w->finishing = 1;
    }
    return rc;
}

/* A fold of the path (t' = 0): the row of its last stable point, then
 * the jump's crossing from there (visco_cross.c). Without a spring the
 * crossing's system is the path's with q' = 0, which at t' = 0 is the
 * same residual: the integrator goes on without a new start (a new start
 * on a point a root's interpolation placed within the tolerance of the
 * path would have to correct its residual along the fold's null
 * direction through t, with t' ~ cj dt unbounded as the first step
 * shrinks). Under a spring the fold is the spring's, where J_u is
 * regular, and the crossing starts anew there. */
static void jump_begin(adh_visco *w);

static int fold(adh_visco *w, double t0)
{
    double *y = N_VGetArrayPointer(w->y), *yp = N_VGetArrayPointer(w->yp);
    int rc = push_row(w, t0);
    jump_begin(w);
    memcpy(w->ypfold, N_VGetArrayPointer(w->yp), w->len * sizeof *y);
    adh_visco_event *e = &w->pending;
    if (!w->spring && w->seg.bdot == 0) {
        /* a dwell: h0 moves through tl at a virtual speed, z0 per tau */
        w->seg.bdot = w->m.z0 / w->v.tau;
        w->seg.b0 = w->b_fold - w->seg.bdot * y[w->IT];
    }
    if (!w->spring) {
        /* a jump-in: the static solver lands it (visco_land.c) */
        w->land_try = w->seg.kind == SEG_LOAD && !(e->a > 0);
        adh_visco_root_directions(w);
        return finish_row(w, rc);
    }
    double *yp0 = w->ywork;
    adh_visco_cross_start(w, yp, yp0);
    int brc = restart(w, w->s_now, y, yp0);
    if (brc != ADH_SUCCESS)
        return stop(w, brc);
    return finish_row(w, rc);
}

/* A jump begins at the state now: its side before (pending), the fold's
 * state and segment, the crossing's set-up. */
static void jump_begin(adh_visco *w)
{
    double *y = N_VGetArrayPointer(w->y);
    adh_visco_event *e = &w->pending;
    memset(e, 0, sizeof *e);
    e->kind = ADH_VISCO_JUMP;
    e->path = w->seg.path;
    e->t = w->t_now, e->base = w->base_now, e->h0 = w->st->h0, e->F = w->F_now, e->a = contact_radius(w);
    w->U_before = adh_visco_energy_of(w, y, NULL, NULL, NULL);
    memcpy(w->yfold, y, w->len * sizeof *y);
    w->s_fold = w->s_now;
    w->b_fold = w->base_now;
    w->seg_fold = w->seg;
    w->jump_steps = 0;
    w->retries = 0;
    w->nudge = VISCO_NUDGE;
    w->mode = MODE_CROSS;
    w->have_prev = 0;
    w->phase = 1;
    w->cross_dir = w->seg.bdot > 0 ? +1 : w->seg.bdot < 0 ? -1 : w->spring ? 0 : +1;
}

/* Contact formed or lost at an event (a jump's landing or a root). */
static void contact_changed(adh_visco *w, int now, double h0, double t, double base)
{
    w->in_contact = now;
    if (now && w->seg.kind == SEG_LOAD && isnan(w->res.jump_in_h0)) {
        w->res.jump_in_h0 = h0, w->res.jump_in_t = t, w->res.jump_in_base = base;
        w->run->jump_in_h0 = h0;
        if (w->nturns == 0)
            w->finishing = 1;
    }
    if (!now && w->extended && w->seg.kind == SEG_UNLOAD)
        w->seg.target = fmin(w->seg.target, base + w->m.z0);
    adh_turn_result *tr = turn_now(w);
    if (!now && tr && isnan(tr->jump_out_h0)) {
        tr->jump_out_h0 = h0;
        if ((size_t)w->seg.path == w->nturns)
            w->res.jump_out_h0 = h0, w->res.jump_out_t = t, w->res.jump_out_base = base;
    }
}

/* Whether y's u is within the tolerance of the fold's: a jump that came
 * back to where it began. */
static int came_back(const adh_visco *w)
{
    const double *y = N_VGetArrayPointer(w->y);
    double moved = 0;
    for (size_t i = 0; i < w->n; i++)
        moved = fmax(moved, fabs(y[i] - w->yfold[i]));
    return !(moved > w->s.tol * w->m.z0);
}

/* The relaxation came back to the fold from every push (up to a tenth
 * of z0): the state is stable there, and t' touched zero without a fold
 * (where the contact line crosses a ring fast, the path's u' is large
 * and t' small). No jump: the path goes on from the fold's state. A
 * second time at the same instant it is stuck. */
static int resume(adh_visco *w, double t0)
{
    double *y = N_VGetArrayPointer(w->y);
    if (w->t_now == w->t_resumed) {
        snprintf(w->errmsg, sizeof w->errmsg, "a jump at t = %g s came back to its fold", w->t_now);
        return stop(w, ADH_ESTALL);
    }
    w->t_resumed = w->t_now;
    w->res.jumps_relaxed--;
    w->res.folds_resumed++;
    memcpy(y, w->yfold, w->len * sizeof *y);
    int rc = restart(w, w->s_fold, y, NULL);
    if (rc != ADH_SUCCESS)
        return stop(w, rc);
    load_state(w, y);
    return finish_row(w, push_row(w, t0));
}

static int start_flow(adh_visco *w);
static int fold(adh_visco *w, double t0);

/* The integrator could not follow the path on from y (a pair of lattice
 * folds tighter than its corrector can turn in, which its root finding
 * did not see): the sphere jumps from there, relaxing (visco_flow.c). A
 * second time at the same instant it is stuck. */
static int path_stuck(adh_visco *w, double t0)
{
    /* stuck anew: the first push; stuck again at the same instant, after
     * a relaxation that came to rest next to where it began, the caller
     * has pushed harder (push_harder, as a relaxation that comes back) */
    if (w->t_now != w->t_stuck)
        w->stuck_push = VISCO_NUDGE;
    w->t_stuck = w->t_now;
    load_state(w, N_VGetArrayPointer(w->y));
    int rc = fold(w, t0);
    if (w->done || w->spring)
        return rc;
    w->nudge = w->stuck_push;
    int brc = start_flow(w);
    return brc == ADH_SUCCESS ? rc : stop(w, brc);
}

/* Whether y is an equilibrium (at its q, time and base): Newton polishes
 * a copy of it onto one. Where a fold has just vanished (a lattice
 * fold's, say) a relaxation crawls past its ghost, slower than its rest
 * test, with no equilibrium there; and a crossing whose S is all but
 * gone (a lattice fold pair) can land next to the fold, where Newton
 * cycles. */
static int on_equilibrium(adh_visco *w)
{
    memcpy(w->ywork, N_VGetArrayPointer(w->y), w->len * sizeof *w->ywork);
    int rc = adh_visco_polish(w, w->ywork, 1);
    w->p_mode = -1; /* the polish factorized the preconditioner for itself */
    return rc == ADH_SUCCESS;
}

/* A relaxation still moving is on an equilibrium only where Newton's
 * (on a copy) is next to it: u and h0 within ten tolerances (z0), and the
 * state then moves there. Else a soft spring's flight, checked mid-way
 * (Newton finds where it lands, hundreds of nm on), landed where it was:
 * 457 of 522 nm out at 1 N/m, the force off the spring's line. */
int adh_visco_next_to_equilibrium(adh_visco *w)
{
    if (!on_equilibrium(w))
        return 0;
    double *y = N_VGetArrayPointer(w->y), d = 0;
    for (size_t i = 0; i < w->n; i++)
        d = fmax(d, fabs(w->ywork[i] - y[i]));
    if (w->spring)
        d = fmax(d, fabs(w->ywork[w->IH] - y[w->IH]));
    if (!(d <= 10 * w->s.tol * w->m.z0))
        return 0;
    memcpy(y, w->ywork, w->len * sizeof *y);
    return 1;
}

/* Under a spring, a relaxation from where the integrator stopped (no
 * root of t' there) that left the contact only when pushed harder than
 * the first push, after coming back from it: the state was stable, and
 * the push threw it out (at frozen u a soft spring's h0 runs away at
 * F_h0 / k, faster than u follows: measured, an elastic sphere through
 * 1e-3 N/m on the shipped grid "snapped out" at 178 nN against the static
 * pull-off's 380). Not a snap-out: the run stops and says so rather than
 * report it. From a root of t' the harder pushes are the designed test
 * (E0 = 1 GPa through 2e-3 N/m at 0.1 m/s snaps out so, at the force
 * minimum). */
static int soft_throw(adh_visco *w, int crossed, const adh_visco_event *e)
{
    if (crossed || !w->spring || !(w->nudge > VISCO_NUDGE) || !(e->a > 0) || e->a_after > 0 ||
        e->t != w->t_stuck)
        return 0;
    snprintf(w->errmsg, sizeof w->errmsg,
             "a jump at t = %.6g s left the contact only when pushed %g z0 off a state it came back to: "
             "a stable contact thrown out through the spring, not a snap-out", w->t_now, w->nudge);
    return 1;
}

/* The crossing is back at the fold's base on the other branch: the
 * path goes on from there (time and q as at the fold). With crossed 0 it
 * relaxed there instead. A crossing that landed on no equilibrium
 * relaxes from the fold (the mode is then MODE_FLOW, no row). */
static int land(adh_visco *w, double t0, int crossed)
{
    double *y = N_VGetArrayPointer(w->y), moved = 0;
    size_t n = w->n;
    memcpy(y + w->IQ, w->yfold + w->IQ, (n + 1) * sizeof *y);
    w->seg = w->seg_fold;
    w->mode = MODE_PATH;
    if (w->ida)
        IDASetMaxStep(w->ida, 0); /* the crossing's limit, if it set one, is off */
    for (size_t i = 0; i < n; i++)
        moved = fmax(moved, fabs(y[i] - w->yfold[i]));
    if (!crossed && !(moved > w->s.tol * w->m.z0))
        return resume(w, t0);
    if (crossed && !on_equilibrium(w)) {   /* the jump relaxes instead */
        int brc = start_flow(w);
        return brc == ADH_SUCCESS ? ADH_CONTINUE : stop(w, brc);
    }
    load_state(w, y);
    adh_visco_event e = w->pending;
    double U = adh_visco_energy_of(w, y, NULL, NULL, NULL);
    e.h0_after = w->st->h0, e.F_after = w->F_now, e.a_after = contact_radius(w);
    if (soft_throw(w, crossed, &e))
        return stop(w, ADH_ESTALL);
    e.loss = w->U_before - U;
    w->acc.jumps += e.loss;
    /* a jump that neither forms nor breaks the contact is the contact line
     * snapping across a lattice fold of the grid (a ring): counted and in
     * the accounts, no event of its own */
    if ((e.a_after > 0) == (e.a > 0)) {
        w->res.lattice_jumps++;
    } else {
        w->res.jumps++;
        if (add_event(w, ADH_VISCO_JUMP) == ADH_SUCCESS)
            w->ev[w->nev - 1] = e;
    }
    if ((e.a_after > 0) != (e.a > 0))
        contact_changed(w, e.a_after > 0, e.h0, e.t, e.base);
    int rc = restart(w, w->s_now, y, NULL);
    if (rc != ADH_SUCCESS)
        return stop(w, rc);
    load_state(w, y);
    /* under a spring the landing may lie past the next turn: it turns there */
    if (w->seg.kind == SEG_LOAD && w->ti < w->nturns && w->st->h0 <= w->turns[w->ti])
        return segment_end(w, t0);
    return finish_row(w, push_row(w, t0));
}

/* The crossing got lost: the jump relaxes instead, from the fold. */
static int start_flow(adh_visco *w)
{
    double *y0 = N_VGetArrayPointer(w->y);
    w->seg = w->seg_fold;
    if (w->ida)
        IDASetMaxStep(w->ida, 0);
    w->mode = MODE_FLOW;
    w->jump_steps = 0;
    w->rest = VISCO_REST;
    w->res.jumps_relaxed++;
    int rc = adh_visco_flow_start(w, w->yfold, w->ypfold, w->nudge, y0, w->ypflow);
    if (rc != ADH_SUCCESS)
        snprintf(w->errmsg, sizeof w->errmsg, "a jump at t = %.6g s could not start relaxing from its fold", w->t_now);
    return rc == ADH_SUCCESS ? restart(w, 0.0, y0, w->ypflow) : rc;
}

/* The crossing's metric product of a and b (u, and the parameter: tl
 * without a spring, h0 with one), per z0^2. */
static double cross_dot(const adh_visco *w, const double *a, const double *b)
{
    double d = 0;
    for (size_t i = 0; i < w->n; i++)
        d += a[i] * b[i];
    d *= w->theta;
    if (w->spring)
        d += a[w->IH] * b[w->IH];
    else
        d += w->seg.vm * w->seg.vm * a[w->IT] * b[w->IT];
    return d;
}

/* Whether the crossing's last step went backwards: its secant against
 * the tangent of the step before. At a lattice fold's hairpin a step can
 * land on the leg that comes back, and the crossing would retrace the
 * way it came (to the outer branch and out to infinity). */
static int cross_reversed(adh_visco *w)
{
    if (!w->have_prev)
        return 0;
    const double *y = N_VGetArrayPointer(w->y), *prev = w->yprev, *tp = w->ypprev;
    double *sec = w->ywork; /* the crossing's start is long used */
    for (size_t i = 0; i < w->len; i++)
        sec[i] = y[i] - prev[i];
    return cross_dot(w, sec, tp) < 0;
}

static void cross_keep(adh_visco *w)
{
    memcpy(w->yprev, N_VGetArrayPointer(w->y), w->len * sizeof(double));
    memcpy(w->ypprev, N_VGetArrayPointer(w->yp), w->len * sizeof(double));
    w->s_prev = w->s_now;
    w->have_prev = 1;
}

/* Whether the crossing has lost its way: too many steps (a ladder of
 * lattice folds), or the sphere beyond the model's reach (|h0 - h0_fold|
 * over R/50) or the contact beyond the grid. */
static int cross_lost(adh_visco *w)
{
    const double *y = N_VGetArrayPointer(w->y);
    double h0 = adh_visco_h0_of(w, y), a;
    if (w->jump_steps > VISCO_CROSS_STEPS || fabs(h0 - adh_visco_h0_of(w, w->yfold)) > w->reach)
        return 1;
    if (adh_visco_gaps(w, y, h0) < 0)
        return 1;
    a = adh_contact_radius(w->g, w->h, w->m.z0);
    return a >= 0.9 * w->g->rmax;
}

/* Back to the crossing's last good point, with steps at most a quarter of
 * the one that went backwards, until the crossing lands; where Newton
 * cannot put that point back on the equilibria (next to a lattice fold),
 * the crossing is lost and the jump relaxes. */
static int cross_retry(adh_visco *w)
{
    double h;
    IDAGetLastStep(w->ida, &h);
    if (w->retries++ == 0)
        w->retry_h1 = fabs(h);
    w->retry_h = fabs(h);
    if (++w->jump_steps > VISCO_CROSS_STEPS || fabs(h) < VISCO_RETRY_MIN * w->s.tol)
        return start_flow(w);
    double *y = N_VGetArrayPointer(w->y);
    memcpy(y, w->yprev, w->len * sizeof *y);
    w->s_now = w->s_prev;
    int rc = restart(w, w->s_now, y, w->ypprev);
    if (rc == ADH_SUCCESS)
        IDASetMaxStep(w->ida, 0.25 * fabs(h));
    else if (rc != ADH_ENOMEM)
        rc = start_flow(w);   /* its last good point is not one (Newton): lost, it relaxes */
    return rc;
}

/* A root during a crossing: its phase 1 ends where the base's coordinate
 * b turns back (the S's other fold), phase 2 where it is back at the
 * fold's: the first branch that holds at the same base, however small
 * the S (a lattice fold's). Along the path b moves as the drive,
 * sign(bdot), until the fold; beyond it the other way: it turns back the
 * drive's way, and crosses the fold's base the drive's way. A dwell
 * under a spring has no such sign: there the turn is the first one ten
 * tolerances off the fold's base (closer, it is the fold's own). */
static int cross_root(adh_visco *w, const int *rf, double t0)
{
    const double *y = N_VGetArrayPointer(w->y);
    double db = adh_visco_cross_base(w, y) - w->b_fold;
    if (w->phase == 1 && rf[ROOT_FOLD] && (w->cross_dir != 0 || fabs(db) > 10 * w->s.tol * w->m.z0)) {
        w->phase = 2;
        if (w->cross_dir == 0)
            w->cross_dir = db > 0 ? -1 : +1;
        adh_visco_root_directions(w);
    } else if (w->phase == 2 && rf[ROOT_END]) {
        return land(w, t0, 1);
    }
    return ADH_CONTINUE;
}

static int on_roots(adh_visco *w, const int *rf, double t0)
{
    if (rf[ROOT_CONTACT])
        contact_changed(w, rf[ROOT_CONTACT] < 0, w->st->h0, w->t_now, w->base_now);
    if (rf[ROOT_CONTACT])
        add_event(w, ADH_VISCO_CONTACT);
    if (rf[ROOT_PULLOFF] && pulloff_event(w) != ADH_SUCCESS)
        return stop(w, ADH_ENOMEM);
    if (rf[ROOT_PROFILE]) {
        if (profile_here(w) && adh_run_push_profile(w->run, w->st, w->seg.branch, w->seg.path) != ADH_SUCCESS)
            return stop(w, ADH_ENOMEM);
        w->pi += w->seg.branch > 0 ? 1 : -1;
        w->seg.prof = next_profile(w);
    }
    if (rf[ROOT_FOLD])
        return fold(w, t0);
    if (rf[ROOT_END])
        return segment_end(w, t0);
    return finish_row(w, push_row(w, t0));
}

/* After a step of a jump's relaxation: 1 with what iterate returns in
 * *out (a landing's row, or the error), 0 to go on relaxing. At rest on
 * the fold it came from, it starts again pushed harder; at rest on no
 * equilibrium (a ghost), it goes on with a rest test ten times stricter. */
static int flow_step(adh_visco *w, double t0, int *out)
{
    double v = adh_visco_flow_speed(w, N_VGetArrayPointer(w->yp));
    if (v < w->rest && came_back(w) && push_harder(&w->nudge)) {   /* relaxed back to the fold */
        w->res.jumps_relaxed--;   /* the same jump, counted again as it starts */
        int brc = start_flow(w);
        *out = brc == ADH_SUCCESS ? ADH_CONTINUE : stop(w, brc);
        return brc != ADH_SUCCESS;
    }
    if (v < w->rest && on_equilibrium(w)) {
        *out = land(w, t0, 0);
        return 1;
    }
    if (v < w->rest && (w->rest *= 0.1) < VISCO_REST_MIN) {
        snprintf(w->errmsg, sizeof w->errmsg, "a jump at t = %g s came to rest on no equilibrium", w->t_now);
        *out = stop(w, ADH_ESTALL);
        return 1;
    }
    if ((w->jump_steps + 1) % VISCO_FLOW_CHECK == 0 && adh_visco_next_to_equilibrium(w)) {
        *out = land(w, t0, 0);
        return 1;
    }
    if (++w->jump_steps > (long)w->s.max_jump_steps) {
        snprintf(w->errmsg, sizeof w->errmsg, "a jump at t = %g s did not come to rest", w->t_now);
        *out = stop(w, ADH_ESTALL);
        return 1;
    }
    return 0;
}

/* The local time where the segment ends (its target reached, its dwell
 * over) and where the base passes the next profile position. */
static double seg_end_tl(const adh_visco *w, double *tl_prof)
{
    const visco_seg *sg = &w->seg;
    *tl_prof = INFINITY;
    if (sg->kind == SEG_DWELL)
        return sg->tl_end;
    double tl = N_VGetArrayPointer(w->y)[w->IT], e;
    if (!isnan(sg->prof) && (e = (sg->prof - sg->b0) / sg->bdot) > tl)
        *tl_prof = e;
    e = isnan(sg->target) ? INFINITY : (sg->target - sg->b0) / sg->bdot;
    return e > tl ? e : INFINITY;
}

/* The gaps' minimum now. */
static double min_gap(const adh_visco *w)
{
    double g = INFINITY;
    for (size_t i = 0; i < w->n; i++)
        g = fmin(g, w->st->h[i]);
    return g;
}

/* A force minimum on unloading between Rothe rows: at the row before,
 * refined to the parabola's vertex through it and its neighbours. */
static int rothe_pulloff(adh_visco *w)
{
    adh_visco_event *a = &w->rprev[1], *b = &w->rprev[0];
    if (w->seg.kind != SEG_UNLOAD || w->nrprev < 2 || !(b->F < a->F) || !(w->F_now > b->F))
        return ADH_SUCCESS;
    adh_visco_event e = *b;
    double x0 = a->h0, x1 = b->h0, x2 = w->st->h0, f0 = a->F, f1 = b->F, f2 = w->F_now;
    double num = (x1 - x0) * (x1 - x0) * (f1 - f2) - (x1 - x2) * (x1 - x2) * (f1 - f0);
    double den = (x1 - x0) * (f1 - f2) - (x1 - x2) * (f1 - f0);
    if (den != 0) {
        double x = x1 - 0.5 * num / den;
        if (x > fmin(x0, x2) && x < fmax(x0, x2)) {
            double l0 = (x - x1) * (x - x2) / ((x0 - x1) * (x0 - x2)), l1 = (x - x0) * (x - x2) / ((x1 - x0) * (x1 - x2)),
                   l2 = (x - x0) * (x - x1) / ((x2 - x0) * (x2 - x1));
            double F = l0 * f0 + l1 * f1 + l2 * f2;
            if (F < e.F) {
                e.F = e.F_after = F;
                e.h0 = e.h0_after = e.base = x;
            }
        }
    }
    adh_turn_result *tr = turn_now(w);
    if (tr && e.F < tr->pulloff_F)
        tr->pulloff_F = e.F, tr->pulloff_h0 = e.h0;
    if (tr && (size_t)w->seg.path == w->nturns && !(e.F >= w->res.pulloff_F))
        w->res.pulloff_F = e.F, w->res.pulloff_h0 = e.h0, w->res.pulloff_t = e.t, w->res.pulloff_base = e.base;
    return pulloff_event_at(w, &e);
}

/* A Rothe step found no convergent step down to its shortest (the state
 * itself predicting too): a fold ahead. A jump-in lands by the static
 * curve at frozen q (visco_land.c), which confirms the fold; on unloading,
 * on a grid that resolves the edge zone, the jump out by Newton from the
 * surfaces apart. Any other (a lattice fold's snap in contact on a coarse
 * grid: to the nearest branch, not the surfaces apart) and a landing that
 * fails go to IDAS from the last accepted state: its root of t' confirms
 * the fold and its crossing lands the jump, and the Rothe steps resume
 * where it lands (restart), or after VISCO_ROTHE_BACK rows without a
 * fold. */
static int land(adh_visco *w, double t0, int crossed);

/* Neither IDAS's tangent at the Rothe steps' last state nor at the one
 * before: on a coarse grid, next to a pair of the contact line's lattice
 * folds, Newton's polish there fails. The jump relaxes instead, from the
 * last state (ylast, its accounts and rows), pushed along the Rothe
 * steps' own last secant (yb to ylast, scaled to the path's metric: a
 * tangent's length z0), as a lost crossing relaxes from its fold (pushed
 * harder where it comes back; a state it comes back to from every push
 * is stable, and the path goes on from it). */
static int rothe_relax(adh_visco *w, double *yb, const double *ylast, adh_visco_energy acc_last, size_t rows_last)
{
    double *y = N_VGetArrayPointer(w->y), *d = w->ro_dir;
    for (size_t i = 0; i < w->len; i++)
        d[i] = ylast[i] - yb[i];
    double len = cross_dot(w, d, d);   /* the path's metric (no spring here) */
    if (!(len > 0))
        return ADH_ESTALL;
    len = sqrt(len) / w->m.z0;
    for (size_t i = 0; i < w->len; i++)
        d[i] /= len;
    memcpy(y, ylast, w->len * sizeof *y);
    w->acc = acc_last;
    if (w->run->nrows < rows_last)   /* the last state's row, taken back above, is its row again */
        w->run->nrows = rows_last;
    load_state(w, y);
    w->in_contact = contact_radius(w) > 0;
    w->errmsg[0] = '\0';
    jump_begin(w);
    memcpy(w->ypfold, d, w->len * sizeof *d);
    return start_flow(w);
}

static int rothe_jump(adh_visco *w, double t0, int *landed)
{
    double *y = N_VGetArrayPointer(w->y);
    *landed = 0;
    /* on a grid that resolves the contact's edge zone (the static
     * curve's limit) the contact line has no lattice folds to snap
     * across: a fold on unloading is the jump out */
    int resolved = w->g->dr <= ADH_GRID_EDGE_SPACING_STATIC * adh_edge_zone(&w->m);
    if ((!w->in_contact && w->seg.kind == SEG_LOAD) || (w->in_contact && w->seg.kind == SEG_UNLOAD && resolved)) {
        /* a jump-in by the static curve at frozen q, which confirms its
         * fold (the curve passes one); a jump-out by Newton from the
         * surfaces apart */
        jump_begin(w);
        int lrc = w->in_contact ? adh_visco_rothe_land_out(w, y) : adh_visco_land_static(w, y);
        if (lrc == ADH_SUCCESS) {
            *landed = 1;
            return land(w, t0, 1);
        }
        if (lrc == ADH_ENOMEM || lrc == ADH_EINTR)
            return lrc;
        memcpy(y, w->yfold, w->len * sizeof *y);
        w->seg = w->seg_fold;
        w->mode = MODE_PATH;
    }
    fold_in(w);
    w->rothe_on = 0;
    w->idas_rows = 0;
    double *ylast = w->ro_last;
    memcpy(ylast, y, w->len * sizeof *y);
    adh_visco_energy acc_last = w->acc;
    size_t rows_last = w->run->nrows;
    int rc = restart_idas(w, w->s_now, y, NULL);
    if (rc != ADH_SUCCESS && rc != ADH_ENOMEM && adh_visco_rothe_back(w, y)) {
        /* too close to the fold for IDAS's tangent: from the step before
         * (its row is the table's last but one: the last goes) */
        if (w->run->nrows && w->run->rows[w->run->nrows - 1].t == w->t_now)
            w->run->nrows--;
        load_state(w, y);
        w->in_contact = contact_radius(w) > 0;
        w->errmsg[0] = '\0';
        rc = restart_idas(w, w->s_now, y, NULL);
        if (rc != ADH_SUCCESS && rc != ADH_ENOMEM && w->in_contact)
            rc = rothe_relax(w, y, ylast, acc_last, rows_last);
    }
    return rc;
}

/* One Rothe step and its row: a profile, a contact formed or lost, a
 * force minimum, a segment's end on the way. VISCO_ROTHE_JUMP: IDAS has
 * the path now. */
static int rothe_iterate(adh_visco *w, double t0)
{
    double *y = N_VGetArrayPointer(w->y), tl_prof;
    if (w->stat0[0] >= (long)w->s.max_steps)
        return stop(w, ADH_EMAXITER);
    double tl_end = seg_end_tl(w, &tl_prof);
    int hit, rc;
    adh_visco_event before;
    fill_event(w, &before, ADH_VISCO_PULLOFF);
    double g0 = min_gap(w);
    rc = adh_visco_rothe_advance(w, y, fmin(tl_end, tl_prof), &hit);
    if (rc == VISCO_ROTHE_JUMP) {
        int landed;
        rc = rothe_jump(w, t0, &landed);
        if (landed)
            return rc;
        return rc == ADH_SUCCESS ? VISCO_ROTHE_JUMP : stop(w, rc);
    }
    if (rc != ADH_SUCCESS)
        return stop(w, rc);
    load_state(w, y);
    w->rprev[1] = w->rprev[0];
    w->rprev[0] = before;
    w->nrprev++;
    int now = contact_radius(w) > 0;
    if (now != w->in_contact) {
        /* where the gap's minimum passed the contact's, between the steps
         * (linear in it): as IDAS's root places it */
        double g1 = min_gap(w), f = (ADH_CONTACT_FACTOR * w->m.z0 - g0) / (g1 - g0);
        f = isfinite(f) ? fmin(1, fmax(0, f)) : 1;
        double h0 = before.h0 + f * (w->st->h0 - before.h0), t = before.t + f * (w->t_now - before.t);
        double base = before.base + f * (w->base_now - before.base);
        contact_changed(w, now, h0, t, base);
        if (add_event(w, ADH_VISCO_CONTACT) == ADH_SUCCESS) {
            adh_visco_event *e = &w->ev[w->nev - 1];
            e->h0 = e->h0_after = h0, e->t = t, e->base = base;
        }
        tl_end = seg_end_tl(w, &tl_prof); /* an extended unloading ends a z0 on */
    }
    if (rothe_pulloff(w) != ADH_SUCCESS)
        return stop(w, ADH_ENOMEM);
    if (hit && !(tl_prof > y[w->IT] * (1 + 1e-12))) {
        if (profile_here(w) && adh_run_push_profile(w->run, w->st, w->seg.branch, w->seg.path) != ADH_SUCCESS)
            return stop(w, ADH_ENOMEM);
        w->pi += w->seg.branch > 0 ? 1 : -1;
        w->seg.prof = next_profile(w);
    }
    if (hit && !(tl_end > y[w->IT] * (1 + 1e-12)))
        return segment_end(w, t0);
    return finish_row(w, push_row(w, t0));
}

int adh_visco_iterate(adh_visco *w)
{
    if (w->done)
        return w->status;
    double t0 = adh_clock_seconds();
    if (!w->started || w->first_pending) {
        w->started = 1;
        w->first_pending = 0;
        return finish_row(w, push_row(w, t0));
    }
    if (w->finishing)
        return stop(w, ADH_SUCCESS);
    if (w->rothe_on) {
        int rrc = rothe_iterate(w, t0);
        if (rrc != VISCO_ROTHE_JUMP)
            return rrc;
    }
    if (w->mode == MODE_CROSS && w->land_try) {
        w->land_try = 0;
        int lrc = adh_visco_land_static(w, N_VGetArrayPointer(w->y));
        if (lrc == ADH_SUCCESS)
            return land(w, t0, 1);
        if (lrc == ADH_ENOMEM || lrc == ADH_EINTR)
            return stop(w, lrc);
    }
    for (;;) {
        if (w->s.cancel && *w->s.cancel)
            return stop(w, ADH_EINTR);
        long c[5];
        counters(w, c);
        if ((size_t)(w->stat0[0] + c[0]) >= w->s.max_steps)
            return stop(w, ADH_EMAXITER);
        double s;
        int flag = IDASolve(w->ida, w->s_now + 1.0, &s, w->y, w->yp, IDA_ONE_STEP);
        if (flag < 0 && w->mode == MODE_CROSS) {
            int brc = start_flow(w);
            if (brc != ADH_SUCCESS)
                return stop(w, brc);
            continue;
        }
        /* stuck on the path: a relaxation from there; stuck again at the
         * same instant, pushed harder while it may be */
        if (flag < 0 && w->mode == MODE_PATH &&
            (w->t_now != w->t_stuck || (!w->spring && push_harder(&w->stuck_push)))) {
            w->s_now = s;
            return path_stuck(w, t0);
        }
        if (flag < 0) {
            char ida[200];
            snprintf(ida, sizeof ida, "%.199s", w->errmsg);
            const double *y = N_VGetArrayPointer(w->y);
            snprintf(w->errmsg, sizeof w->errmsg, "the integrator stopped %s at t = %.6g s, h0 = %.6g m (%s)",
                     w->mode == MODE_CROSS ? "crossing a jump" : "on the path", w->t_now, adh_visco_h0_of(w, y),
                     ida);
            return stop(w, ADH_ESTALL);
        }
        if (w->mode == MODE_FLOW) {
            int out;
            if (flow_step(w, t0, &out))
                return out;
            continue;
        }
        w->s_now = s;
        if (w->mode == MODE_CROSS && cross_lost(w)) {
            int brc = start_flow(w);
            if (brc != ADH_SUCCESS)
                return stop(w, brc);
            continue;
        }
        if (w->mode == MODE_CROSS && cross_reversed(w)) {
            int brc = cross_retry(w);
            if (brc != ADH_SUCCESS)
                return stop(w, brc);
            continue;
        }
        if (w->mode == MODE_CROSS) {
            cross_keep(w);
            int rf[NROOTS] = { 0 };
            if (flag == IDA_ROOT_RETURN) {
                IDAGetRootInfo(w->ida, rf);
                int rc = cross_root(w, rf, t0);
                if (rc != ADH_CONTINUE || w->mode == MODE_PATH)
                    return rc;
            }
            ++w->jump_steps;
            continue;
        }
        load_state(w, N_VGetArrayPointer(w->y));
        if (flag != IDA_ROOT_RETURN && w->rothe && ++w->idas_rows >= VISCO_ROTHE_BACK) {
            /* no fold came: the Rothe steps' failure was no jump's; they
             * take the path back */
            int rc = push_row(w, t0);
            int brc = restart(w, w->s_now, N_VGetArrayPointer(w->y), NULL);
            return brc == ADH_SUCCESS ? finish_row(w, rc) : stop(w, brc);
        }
        if (flag != IDA_ROOT_RETURN)
            return finish_row(w, push_row(w, t0));
        int rf[NROOTS];
        IDAGetRootInfo(w->ida, rf);
        return on_roots(w, rf, t0);
    }
}

int adh_visco_run(adh_visco *w)
{
    int rc;
    while ((rc = adh_visco_iterate(w)) == ADH_CONTINUE)
        ;
    return rc == ADH_EINTR ? ADH_SUCCESS : rc;
}

int adh_visco_last(const adh_visco *w)
{
    return w->finishing && !w->done;
}

const char *adh_visco_why(const adh_visco *w)
{
    return w->errmsg;
}

unsigned adh_visco_fix(const adh_visco *w)
{
    return w->fix;
}

const adh_state *adh_visco_state(const adh_visco *w)
{
    return w->st;
}

double adh_visco_time(const adh_visco *w)
{
    return w->t_now;
}

double adh_visco_base(const adh_visco *w)
{
    return w->base_now;
}

void adh_visco_summary(const adh_visco *w, adh_visco_result *res)
{
    *res = w->res;
    long c[5];
    counters(w, c);
    res->steps = (size_t)(w->stat0[0] + c[0]);
    res->newton = (size_t)(w->stat0[1] + c[1]);
    res->krylov = (size_t)(w->stat0[2] + c[2]);
    res->setups = adh_visco_pre_factorizations(w->pre) + w->rothe_factor;
    res->error_fails = (size_t)(w->stat0[4] + c[4]);
    res->time = w->t_now;
    res->seconds = w->run ? w->run->seconds : 0;
}

size_t adh_visco_events(const adh_visco *w, const adh_visco_event **ev)
{
    if (ev)
        *ev = w->ev;
    return w->nev;
}
