/* The path an elastic sphere takes in physical time, walked over its
 * static curve (adhere/path.h). */
#include "adhere/path.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/cycle.h"
#include "adhere/law.h"
#include "adhere/models.h"
#include "adhere/status.h"

/* A point of the path: where on the curve (x = row i + fraction) and its
 * row. */
typedef struct path_pt {
    double x;
    adh_obs o;
} path_pt;

struct adh_path {
    adh_visco_event *ev;
    size_t *ev_row;             /* the row (of the walk's) each event shows from */
    size_t nev, evcap;
    size_t *lat_row;            /* the landing row of each lattice jump */
    size_t nlat, latcap;
    adh_visco_result res;
    size_t jump_in_row;
    double *xs;                 /* where on the curve each row of run is (-1: a
                                   landing beyond it, rigid) */
    size_t nxs, xcap;
    size_t row0;                /* run's rows before the walk */

    /* the walk under way */
    const adh_path_curve *c;
    adh_material m;
    adh_visco_drive d;
    adh_protocol_settings ps;   /* turns and profiles sorted, deepest last */
    adh_run *run;
    adh_state *st;              /* a profile's state */
    double k, b_start;
    int rc;                     /* ADH_ENOMEM once a push failed */
    /* the branch: t = t0 + |base - b0| / speed; its path and direction */
    double t0, b0, speed;
    int path, branch;
    path_pt last;               /* the last row emitted */
    int have_last, in_contact;
    double work, losses;        /* the base's work and the jumps' losses so far */
    double work_in;             /* the branch's work until its base came back to the
                                   start's (NAN before: a start in contact's loop) */
    int stranded;               /* the branch ended in contact at the curve's first row */
    size_t branch_ev;           /* the branch's first event */
    long pull_row;              /* the branch's lowest force: its row, -1 none */
    /* the turns reached on loading: where on the curve, when, the base, and
     * the loading's accounts there */
    double turn_x[ADH_MAX_TURNS], turn_work[ADH_MAX_TURNS], turn_loss[ADH_MAX_TURNS];
    adh_obs turn_o[ADH_MAX_TURNS];
    size_t reached;
    double deeper;              /* the curve's end a snap-in's landing needs (NAN: none) */
};

/* Nothing measured yet: no jump, no pull-off, no cycle. */
static void result_reset(adh_visco_result *r)
{
    memset(r, 0, sizeof *r);
    r->jump_in_h0 = r->jump_out_h0 = r->pulloff_F = r->pulloff_h0 = r->hysteresis = NAN;
    r->jump_in_t = r->jump_in_base = r->jump_out_t = r->jump_out_base = r->pulloff_t = r->pulloff_base = NAN;
    r->start_h0 = r->start_base = NAN;
}

adh_path *adh_path_alloc(void)
{
    adh_path *p = calloc(1, sizeof *p);
    if (p)
        adh_path_clear(p);
    return p;
}

void adh_path_clear(adh_path *p)
{
    p->nev = p->nxs = p->nlat = 0;
    p->jump_in_row = (size_t)-1;
    result_reset(&p->res);
}

void adh_path_free(adh_path *p)
{
    if (!p)
        return;
    free(p->ev);
    free(p->ev_row);
    free(p->lat_row);
    free(p->xs);
    adh_state_free(p->st);
    free(p);
}

size_t adh_path_events(const adh_path *p, size_t rows, const adh_visco_event **ev)
{
    size_t n = 0;
    while (n < p->nev && p->ev_row[n] < rows)
        n++;
    *ev = p->ev;
    return n;
}

void adh_path_summary(const adh_path *p, size_t rows, adh_visco_result *res)
{
    *res = p->res;
    if (rows >= p->nxs)
        return;
    /* what the walk's first rows have seen: the events among them */
    const adh_visco_event *ev;
    size_t n = adh_path_events(p, rows, &ev), deepest = p->ps.nturns, ended = 0, out = 0, pull = 0;
    res->jumps = res->lattice_jumps = 0;
    for (size_t i = 0; i < n; i++) {
        res->jumps += ev[i].kind == ADH_VISCO_JUMP;
        if ((size_t)ev[i].path != deepest || deepest == 0)
            continue;
        ended |= ev[i].kind == ADH_VISCO_END;
        pull |= ev[i].kind == ADH_VISCO_PULLOFF;
        out |= (ev[i].kind == ADH_VISCO_JUMP || ev[i].kind == ADH_VISCO_CONTACT) && !(ev[i].a_after > 0);
    }
    for (size_t i = 0; i < p->nlat; i++)
        res->lattice_jumps += p->lat_row[i] < rows;
    if (p->jump_in_row == (size_t)-1 || p->jump_in_row - p->row0 >= rows)
        res->jump_in_h0 = res->jump_in_t = res->jump_in_base = NAN;
    if (!pull)
        res->pulloff_F = res->pulloff_h0 = res->pulloff_t = res->pulloff_base = NAN;
    if (!out)
        res->jump_out_h0 = res->jump_out_t = res->jump_out_base = NAN;
    if (!ended) {
        res->hysteresis = NAN;
        memset(&res->cycle, 0, sizeof res->cycle);
    }
    res->time = rows ? p->run->rows[p->row0 + rows - 1].t : 0;
}

size_t adh_path_rows(const adh_path *p)
{
    return p->nxs;
}

static double base_of(const adh_path *p, const adh_obs *o)
{
    return o->h0 - o->F / p->k;
}

static double row_base(const adh_path *p, size_t i)
{
    return base_of(p, &p->c->rows[i]);
}

/* The row at x, every field linear between the rows around it. */
static path_pt at(const adh_path *p, double x)
{
    size_t n = p->c->n;
    path_pt q = { .x = x };
    size_t i = x <= 0 || n < 2 ? 0 : x >= (double)(n - 1) ? n - 2 : (size_t)x;
    double f = n < 2 ? 0 : x - (double)i;
    const adh_obs *a = &p->c->rows[i], *b = &p->c->rows[n < 2 ? 0 : i + 1];
#define LERP(field) q.o.field = a->field + f * (b->field - a->field)
    LERP(h0); LERP(F); LERP(F_tail); LERP(delta); LERP(hc); LERP(a); LERP(angle); LERP(F_rigid);
#undef LERP
    if (!(q.o.a > 0))
        q.o.a = 0;
    q.o.iters = f == 0 ? a->iters : f == 1 ? b->iters : 0;
    return q;
}

/* The deformation at x on the state st (h0, h, p with it). 0, or -1
 * without the rows' deformations. */
static int state_at(adh_path *p, double x)
{
    const adh_path_curve *c = p->c;
    size_t n = c->n, N = c->g ? c->g->n : 0;
    if (!c->u || !N)
        return -1;
    if (!p->st && !(p->st = adh_state_alloc(N)))
        return -1;
    size_t i = x <= 0 || n < 2 ? 0 : x >= (double)(n - 1) ? n - 2 : (size_t)x;
    double f = n < 2 ? 0 : x - (double)i;
    const float *u0 = c->u + i * N, *u1 = c->u + (n < 2 ? i : i + 1) * N;
    adh_state *s = p->st;
    s->h0 = at(p, x).o.h0;
    for (size_t j = 0; j < N; j++) {
        double r = c->g->r[j];
        s->u[j] = (double)u0[j] + f * ((double)u1[j] - (double)u0[j]);
        s->h[j] = s->h0 + r * r / (2.0 * p->m.R) - s->u[j];
        s->p[j] = adh_lj_pressure(s->h[j], p->m.A, p->m.z0);
    }
    return 0;
}

/* Room for one more in a growing array (*a of *cap elements of size sz). */
static int room(adh_path *p, void **a, size_t *cap, size_t n, size_t sz)
{
    if (n < *cap)
        return 0;
    size_t c = *cap ? 2 * *cap : 32;
    void *b = realloc(*a, c * sz);
    if (!b) {
        p->rc = ADH_ENOMEM;
        return -1;
    }
    *a = b;
    *cap = c;
    return 0;
}

/* The last row emitted, counted from the walk's first. */
static size_t last_row(const adh_path *p)
{
    return p->run->nrows - 1 - p->row0;
}

static adh_visco_event *add_event(adh_path *p, int kind, const path_pt *q)
{
    size_t cap = p->evcap;
    if (room(p, (void **)&p->ev, &cap, p->nev, sizeof *p->ev) || room(p, (void **)&p->ev_row, &p->evcap, p->nev,
                                                                       sizeof *p->ev_row))
        return NULL;
    p->ev_row[p->nev] = last_row(p);
    adh_visco_event *e = &p->ev[p->nev++];
    memset(e, 0, sizeof *e);
    e->kind = kind;
    e->path = p->path;
    e->t = q->o.t;
    e->base = q->o.base;
    e->h0 = e->h0_after = q->o.h0;
    e->F = e->F_after = q->o.F;
    e->a = e->a_after = q->o.a;
    return e;
}

/* The profiles the base passed from the last row to q (on one leg of the
 * curve: no jump between). */
static void profiles_between(adh_path *p, const path_pt *q)
{
    double ba = p->last.o.base, bb = q->o.base;
    for (size_t j = 0; j < p->ps.nprofiles && p->rc == ADH_SUCCESS; j++) {
        double pos = p->ps.profiles[j];
        int hit = p->branch > 0 ? (bb <= pos && pos < ba) : (ba < pos && pos <= bb);
        if (!hit || state_at(p, p->last.x + (q->x - p->last.x) * (pos - ba) / (bb - ba)) != 0)
            continue;
        if (adh_run_push_profile(p->run, p->st, p->branch, p->path) != ADH_SUCCESS)
            p->rc = ADH_ENOMEM;
    }
}

/* Appends q as the path's next row, at time t; leg: 1 when q follows the
 * last row along the curve (profiles between), 0 across a jump. */
static void emit(adh_path *p, path_pt *q, double t, int leg)
{
    q->o.t = t;
    q->o.base = base_of(p, &q->o);
    /* eq 22 at the row's own h0: a row between the curve's points (a turn,
     * a fold, a landing) is no mixture of its neighbours' closed forms */
    q->o.F_rigid = adh_rigid_force(&p->m, q->o.h0);
    q->o.branch = p->branch;
    q->o.path = p->path;
    q->o.converged = 1;
    q->o.stable = 1;
    if (p->have_last) {
        double b0 = p->last.o.base, b1 = q->o.base;
        if (p->branch < 0 && isnan(p->work_in) && b0 < p->b_start && b1 >= p->b_start) {
            /* the base back at the start's: the loop of a cycle from a start in contact */
            double Fs = p->last.o.F + (q->o.F - p->last.o.F) * (p->b_start - b0) / (b1 - b0);
            p->work_in = p->work - 0.5 * (p->last.o.F + Fs) * (p->b_start - b0);
        }
        p->work -= 0.5 * (p->last.o.F + q->o.F) * (q->o.base - p->last.o.base);
        if (leg)
            profiles_between(p, q);
    }
    if (p->nxs == p->xcap) {
        size_t cap = p->xcap ? 2 * p->xcap : 256;
        double *xs = realloc(p->xs, cap * sizeof *xs);
        if (!xs)
            p->rc = ADH_ENOMEM;
        else
            p->xs = xs, p->xcap = cap;
    }
    if (p->nxs < p->xcap)
        p->xs[p->nxs++] = q->x;
    if (adh_run_push_row(p->run, &q->o) != ADH_SUCCESS)
        p->rc = ADH_ENOMEM;
    if (p->path > 0) {
        adh_turn_result *tr = &p->run->turns[p->path - 1];
        if (q->o.F < tr->pulloff_F) {
            tr->pulloff_F = q->o.F;
            tr->pulloff_h0 = q->o.h0;
            p->pull_row = (long)p->run->nrows - 1;
        }
    }
    p->last = *q;
    p->have_last = 1;
}

/* The time the base reaches b on the branch under way. */
static double time_at(const adh_path *p, double b)
{
    return p->t0 + fabs(b - p->b0) / p->speed;
}

/* Contact formed or lost at row q (by a jump or not). */
static void contact_now(adh_path *p, int now, const path_pt *q)
{
    p->in_contact = now;
    /* in contact at the walk's first row (a start where the surfaces
     * already touch) is no jump in: none was seen, as in relaxation and
     * the static curve (it said jump_in_h0 = the start, t = 0) */
    int first = p->run->nrows - 1 == p->row0;
    if (now && p->branch > 0 && !first && isnan(p->res.jump_in_h0)) {
        p->res.jump_in_h0 = q->o.h0, p->res.jump_in_t = q->o.t, p->res.jump_in_base = q->o.base;
        p->jump_in_row = p->run->nrows - 1;
    }
    adh_turn_result *tr = p->path > 0 ? &p->run->turns[p->path - 1] : NULL;
    if (!now && tr && isnan(tr->jump_out_h0)) {
        tr->jump_out_h0 = q->o.h0;
        if ((size_t)p->path == p->ps.nturns)
            p->res.jump_out_h0 = q->o.h0, p->res.jump_out_t = q->o.t, p->res.jump_out_base = q->o.base;
    }
}

/* A point of the curve followed without a jump. */
static void step_pt(adh_path *p, path_pt q)
{
    emit(p, &q, time_at(p, base_of(p, &q.o)), 1);
    if ((q.o.a > 0) != p->in_contact) {
        add_event(p, ADH_VISCO_CONTACT, &q);
        contact_now(p, q.o.a > 0, &q);
    }
}

/* A row of the curve followed without a jump. */
static void step_to(adh_path *p, double x)
{
    step_pt(p, at(p, x));
}

/* The fold of the base at row i (the rows i - 1, i, i + 1 turn it): every
 * field at the parabola's extremum through the three, its h0 and base the
 * static curve's snap point's (adh_visco_spring_folds). */
static path_pt fold_at(const adh_path *p, size_t i)
{
    const adh_path_curve *c = p->c;
    if (i == 0 || i + 1 >= c->n)
        return at(p, (double)i);
    double b0 = row_base(p, i - 1), b1 = row_base(p, i), b2 = row_base(p, i + 1);
    double curv = b0 - 2 * b1 + b2, s = curv != 0 ? (b0 - b2) / (2 * curv) : 0;
    s = fmin(1.0, fmax(-1.0, s));
    path_pt q = at(p, (double)i + s);
    const adh_obs *r = &c->rows[i - 1];
#define PARA(field) q.o.field = r[1].field + 0.5 * s * (r[2].field - r[0].field) + \
                                0.5 * s * s * (r[0].field - 2 * r[1].field + r[2].field)
    PARA(h0); PARA(F); PARA(F_tail); PARA(delta); PARA(hc); PARA(a); PARA(angle); PARA(F_rigid);
#undef PARA
    if (!(q.o.a > 0))
        q.o.a = r[1].a > 0 ? r[1].a : 0;
    adh_run view = { .rows = (adh_obs *)r, .nrows = 3 };
    double h0, b;
    if (adh_visco_spring_folds(&view, p->k, &h0, &b, 1) == 1) {
        q.o.h0 = h0;
        if (isfinite(p->k))
            q.o.F = p->k * (h0 - b);
    }
    return q;
}

/* Under displacement control the static solver placed the jump into
 * contact (its first fold) and the jump out (its retraction fold of the
 * largest h0) itself: a fold of the walk that is one of them (within the
 * rows around it) takes its place and force. */
static void static_fold(const adh_path *p, size_t i, int into, path_pt *q)
{
    const adh_path_curve *c = p->c;
    if (isfinite(p->k) || !c->res || i == 0 || i + 1 >= c->n)
        return;
    double h0 = into ? c->res->jump_in_h0 : c->res->jump_out_h0;
    double F = !into ? c->res->pulloff_F_disp : c->nfolds && c->folds[0].kind < 0 && c->folds[0].h0 == h0
             ? c->folds[0].F : NAN;
    double lo = fmin(c->rows[i - 1].h0, c->rows[i + 1].h0), hi = fmax(c->rows[i - 1].h0, c->rows[i + 1].h0);
    double w = fmax(hi, c->rows[i].h0) - fmin(lo, c->rows[i].h0);
    if (!(h0 >= lo - w && h0 <= hi + w) || !isfinite(F))
        return;
    q->o.h0 = h0;
    q->o.F = F;
}

/* The integral of F d(base) along the curve from xa to xb (either order),
 * each quantity linear between rows (the trapezoid: independent of how
 * the curve is parametrised, where a parabola in the row index was not:
 * 1.2 % off on the tests' lattice grid). */
static double curve_work(const adh_path *p, double xa, double xb)
{
    if (xb < xa)
        return -curve_work(p, xb, xa);
    size_t n = p->c->n;
    double sum = 0, x = xa;
    while (x < xb && n >= 2) {
        double i = floor(x), xe = i + 1 < xb ? i + 1 : xb;
        if (i >= (double)(n - 1))
            break;
        path_pt u = at(p, x), v = at(p, xe);
        sum += 0.5 * (u.o.F + v.o.F) * (base_of(p, &v.o) - base_of(p, &u.o));
        x = xe;
    }
    return sum;
}

/* A jump's loss, the stored energy before less after: the integral of
 * F d(base) along the curve from the fold f on to row i (the first the
 * path left behind), then along the curve to the landing at x = xl. */
static double jump_loss(const adh_path *p, const path_pt *f, size_t i, double xl)
{
    const adh_obs *r = &p->c->rows[i];
    return 0.5 * (f->o.F + r->F) * (base_of(p, r) - base_of(p, &f->o)) + curve_work(p, (double)i, xl);
}

/* Rigid spheres' interaction energy at h (eq 22's potential). */
static double rigid_energy(const adh_material *m, double h)
{
    double AR = m->A * m->R;
    return -AR / (6.0 * h) + AR * pow(m->z0, 6) / (168.0 * pow(h, 7));
}

/* Where a soft spring's snap-out lands beyond the curve's start: the
 * sphere where h0 - F/k is the fold's base b, F rigid spheres' (eq 22;
 * the deformation is long gone there); its loss from the curve's start
 * (x = 0) on in *loss. */
static path_pt land_rigid(const adh_path *p, double b, double *loss)
{
    path_pt q = { .x = -1 };
    double h = b;
    for (int it = 0; it < 100 && isfinite(p->k); it++)
        h = b + adh_rigid_force(&p->m, h) / p->k;
    double F = adh_rigid_force(&p->m, h);
    q.o.h0 = q.o.hc = h;
    q.o.F = q.o.F_rigid = F;
    const adh_obs *s = &p->c->rows[0];
    double spring = isfinite(p->k) ? (F * F - s->F * s->F) / (2.0 * p->k) : 0;
    *loss = rigid_energy(&p->m, s->h0) - rigid_energy(&p->m, h) - spring;
    return q;
}

/* A jump from the fold f to the landing l (the same base, the same
 * time): both rows, and its event or its count. */
static void jump(adh_path *p, path_pt *f, path_pt *l, double loss)
{
    double t = time_at(p, base_of(p, &f->o));
    emit(p, f, t, 1);
    emit(p, l, t, 0);
    p->losses += loss;
    int before = f->o.a > 0, after = l->o.a > 0;
    if (before == after) {
        p->res.lattice_jumps++;
        if (room(p, (void **)&p->lat_row, &p->latcap, p->nlat, sizeof *p->lat_row) == 0)
            p->lat_row[p->nlat++] = last_row(p);
        return;
    }
    adh_visco_event *e = add_event(p, ADH_VISCO_JUMP, f);
    if (e) {
        e->h0_after = l->o.h0, e->F_after = l->o.F, e->a_after = l->o.a;
        e->loss = loss;
    }
    p->res.jumps++;
    contact_now(p, after, f);   /* a jump-in's row is its landing's */
}

/* Loading reached the next turn at the last row: its snapshot. */
static void reach_turn(adh_path *p)
{
    size_t k = p->reached++;
    p->turn_x[k] = p->last.x;
    p->turn_o[k] = p->last.o;
    p->turn_work[k] = p->work;
    p->turn_loss[k] = p->losses;
    add_event(p, ADH_VISCO_TURN, &p->last);
}

/* Every turn the last row reached (h0 at or past it; all of them at a
 * complete curve's end, the deepest turn). */
static void reach_turns(adh_path *p, int end)
{
    while (p->reached < p->ps.nturns && (end || p->last.o.h0 <= p->ps.turns[p->reached]))
        reach_turn(p);
}

/* The landing of a fold at base bf on loading: from row i on, the first
 * point whose base is below it (x; the curve's end when none). */
static double landing_in(const adh_path *p, size_t i, double bf)
{
    size_t n = p->c->n, j = i;
    while (j < n && !(row_base(p, j) < bf))
        j++;
    if (j >= n)
        return (double)(n - 1);
    return (double)(j - 1) + (bf - row_base(p, j - 1)) / (row_base(p, j) - row_base(p, j - 1));
}

/* A snap-in from base bf that found no landing on the curve (xl at its
 * end, the base there still above bf): a soft spring throws the sphere
 * past the deepest turn. The landing is where F(h0) = k (h0 - bf); past
 * the end the force rises with depth at least as fast as it did over the
 * curve's last stretch in contact (a contact stiffens as it grows), so
 * the chord over that stretch, at least 2 z0 of h0 long (the lattice's
 * steps, steep between its folds, average out over it: the last two
 * rows' slope put the end short of the landing twice on 200 nodes of
 * 7.5 nm), meets k (h0 - bf) beyond the landing: a curve to there, and a
 * fifth more, holds it (adh_path_deeper asks for it). An end out of
 * contact says nothing of the contact's force: 2 z0 into contact first,
 * and from there the chord (the solve again asks again). Where the force
 * still falls with depth, F >= F_end bounds it: bf + F_end / k. 1 when
 * the landing lies past the curve's end. */
static int note_deeper(adh_path *p, double xl, double bf)
{
    size_t n = p->c->n;
    const adh_obs *e = &p->c->rows[n - 1];
    if (xl < (double)(n - 1) || row_base(p, n - 1) < bf || !isfinite(p->k) || !(e->F < 0))
        return 0;
    double z0 = p->m.z0, need;
    if (!(e->a > 0)) {
        need = fmin(e->h0, 0) - 2 * z0;
    } else {
        size_t j = n - 1;
        while (j > 0 && p->c->rows[j - 1].a > 0 && p->c->rows[j].h0 - e->h0 < 2 * z0)
            j--;
        const adh_obs *d = &p->c->rows[j];
        double s = d->h0 != e->h0 ? (e->F - d->F) / (e->h0 - d->h0) : 0;   /* dF/dh0 < 0: rising with depth */
        double gap = e->F - p->k * (e->h0 - bf);                           /* < 0: no landing yet */
        need = s < 0 ? e->h0 + 1.2 * gap / (p->k - s) : bf + 1.1 * e->F / p->k;
    }
    if (need < e->h0 && !(need >= p->deeper))
        p->deeper = need;
    return 1;
}

/* The turn at h0 = T (exactly: the protocol's), at x between rows a and
 * b. Out of contact the curve's far-field steps are long (1.2 nm around
 * 5 nm) and F ~ h0^-2 bends across them: a chord put F 2.6 % off the
 * curve solved to T; the ratio to eq 22, F / F_rigid (1 + the sphere's
 * small bulge), is what is linear there. */
static path_pt turn_point(const adh_path *p, double x, double T, const adh_obs *a, const adh_obs *b)
{
    path_pt q = at(p, x);
    q.o.h0 = T;
    double ra = a->F / adh_rigid_force(&p->m, a->h0), rb = b->F / adh_rigid_force(&p->m, b->h0);
    if (!(a->a > 0) && !(b->a > 0) && isfinite(ra) && isfinite(rb))
        q.o.F = adh_rigid_force(&p->m, T) * (ra + (rb - ra) * (T - a->h0) / (b->h0 - a->h0));
    return q;
}

/* Loading, from the curve's start down to the deepest turn (without
 * turns: to the first contact). */
static void load(adh_path *p)
{
    const adh_path_curve *c = p->c;
    size_t n = c->n, nt = p->ps.nturns;
    p->path = 0, p->branch = +1, p->t0 = 0, p->b0 = p->b_start, p->speed = p->d.speed_in;
    p->have_last = 0;
    step_to(p, (double)c->start);
    double bmin = p->b_start;
    for (size_t i = c->start + 1; i < n && p->rc == ADH_SUCCESS && (nt ? p->reached < nt : !p->in_contact);) {
        double T = nt ? p->ps.turns[p->reached] : -INFINITY;
        if (row_base(p, i) < bmin) {
            const adh_obs *a = &c->rows[i - 1], *b = &c->rows[i];
            double x = (double)(i - 1) + (T - a->h0) / (b->h0 - a->h0);
            if (b->h0 < T && a->h0 > T && x > p->last.x) {   /* the turn, between the rows */
                step_pt(p, turn_point(p, x, T, a, b));
                reach_turn(p);
                continue;
            }
            step_to(p, (double)i);
            bmin = row_base(p, i);
            reach_turns(p, i + 1 == n && c->complete);
            i++;
            continue;
        }
        /* the base turned at row i - 1: a fold, and its landing further
         * on; into contact under displacement control, the static
         * solver's fold */
        path_pt f = fold_at(p, i - 1);
        double xl = landing_in(p, i, base_of(p, &f.o));
        if (!p->in_contact && at(p, xl).o.a > 0) {
            static_fold(p, i - 1, 1, &f);
            xl = landing_in(p, i, base_of(p, &f.o));
        }
        if (note_deeper(p, xl, base_of(p, &f.o))) {
            /* no landing on this curve: the path stops at the fold (the
             * curve solved deeper walks again), never lands off the
             * spring's line with the base moved in an instant */
            emit(p, &f, time_at(p, base_of(p, &f.o)), 1);
            break;
        }
        path_pt l = at(p, xl);
        jump(p, &f, &l, jump_loss(p, &f, i, xl));
        bmin = base_of(p, &f.o);
        reach_turns(p, xl >= (double)(n - 1) && c->complete);
        i = (size_t)ceil(xl);
        if ((double)i == xl)
            i++;
    }
}

/* The branch's pull-off event, among its events in time order; under
 * displacement control at the static curve's minimum where the branch
 * reached it (its rows around it). */
static void pulloff(adh_path *p, adh_turn_result *tr)
{
    /* no event where the force only rose from the turn (a turn short of
     * contact): no minimum; the summary's lowest force is the turn's, with
     * its time and base (as the integrator's; they were NaN beside it) */
    if (p->pull_row < 0)
        return;
    if (p->run->rows[p->pull_row - (p->pull_row > 0)].path != p->path) {
        const adh_obs *o = &p->run->rows[p->pull_row];
        if ((size_t)p->path == p->ps.nturns)
            p->res.pulloff_F = o->F, p->res.pulloff_h0 = o->h0, p->res.pulloff_t = o->t, p->res.pulloff_base = o->base;
        return;
    }
    path_pt q = { .o = p->run->rows[p->pull_row] };
    const adh_static_result *sr = p->c->res;
    const adh_obs *r = p->run->rows;
    size_t pr = (size_t)p->pull_row, nr = p->run->nrows;
    if (!isfinite(p->k) && sr && pr > 0 && pr + 1 < nr && r[pr - 1].path == p->path && r[pr + 1].path == p->path &&
        sr->pulloff_F <= q.o.F && sr->pulloff_h0 >= fmin(r[pr - 1].h0, r[pr + 1].h0) &&
        sr->pulloff_h0 <= fmax(r[pr - 1].h0, r[pr + 1].h0)) {
        q.o.F = tr->pulloff_F = sr->pulloff_F;
        q.o.h0 = q.o.base = tr->pulloff_h0 = sr->pulloff_h0;
        q.o.t = time_at(p, q.o.base);
    }
    /* before every event of its instant too: under a soft spring the
     * force minimum is the snap-out's fold, and the jump and the branch's
     * end (from the landing's row) follow it */
    size_t at_ev = p->nev;
    size_t pull_at = (size_t)p->pull_row - p->row0;
    while (at_ev > p->branch_ev && p->ev[at_ev - 1].t >= q.o.t && p->ev_row[at_ev - 1] >= pull_at)
        at_ev--;
    adh_visco_event *e = add_event(p, ADH_VISCO_PULLOFF, &q);
    if (!e)
        return;
    adh_visco_event keep = *e;
    memmove(&p->ev[at_ev + 1], &p->ev[at_ev], (p->nev - 1 - at_ev) * sizeof *e);
    memmove(&p->ev_row[at_ev + 1], &p->ev_row[at_ev], (p->nev - 1 - at_ev) * sizeof *p->ev_row);
    p->ev[at_ev] = keep;
    p->ev_row[at_ev] = (size_t)p->pull_row - p->row0;
    if ((size_t)p->path == p->ps.nturns)
        p->res.pulloff_F = q.o.F, p->res.pulloff_h0 = q.o.h0, p->res.pulloff_t = q.o.t, p->res.pulloff_base = q.o.base;
}

/* The base back at its start (or beyond it, a soft spring's landing; or
 * past a start in contact, where the surfaces part): the branch ends.
 * stored_change: the stored energy there less the start's. */
static void end_branch(adh_path *p, double stored_change)
{
    add_event(p, ADH_VISCO_END, &p->last);
    size_t k = (size_t)p->path - 1;
    adh_turn_result *tr = &p->run->turns[k];
    if (p->stranded)   /* the unloading past the start is not known: no pull-off */
        tr->pulloff_F = tr->pulloff_h0 = NAN;
    else
        pulloff(p, tr);
    p->res.time = p->last.o.t;
    /* the turn's cycle: the loading to it, then this branch */
    double jumps = p->turn_loss[k] + p->losses;
    /* A start in contact: the cycle's loop is over the range of the base
     * both its loading and its unloading cover, the base below the start's
     * (docs/stop-reasons.md, hysteresis): the unloading past the start has
     * no loading beside it. Under displacement control the curve's loop
     * from the start's row on; through a spring the base's work from the
     * start to the turn and back to the start's base. */
    size_t s0 = p->c->start;
    double in_range = p->turn_work[k] + (isnan(p->work_in) ? p->work : p->work_in);
    /* no dissipation on the way: the base's work is what the jumps
     * released and what stays stored (nothing, back at the start); under
     * displacement control the static curve's loop, the area between its
     * highest and lowest stable force at each h0 (the loading and the
     * unloading of this path), by parabolas through each stable leg
     * (adh_cycle_static_hysteresis): the sum of the losses, by chords
     * along the curve, is within 0.3 % of it on the default scene. A
     * shallower turn's loop is that of the curve down to its turn: its
     * cycle meets no lattice fold deeper (the whole curve's loop, 21 %
     * above its own at -1 nm beside a turn at -3 nm on a coarse grid); one
     * short of contact jumped nowhere and has none */
    if (isfinite(p->k) || !p->c->complete || (jumps == 0 && k + 1 != p->ps.nturns)) {
        tr->hysteresis = s0 ? in_range : jumps + stored_change;
    } else {
        size_t rows = k + 1 == p->ps.nturns ? p->c->n : (size_t)floor(p->turn_x[k]) + 1;
        rows = rows < p->c->n ? rows : p->c->n;
        adh_run view = { .rows = (adh_obs *)p->c->rows + s0, .nrows = rows > s0 ? rows - s0 : 0 };
        tr->hysteresis = adh_cycle_static_hysteresis(&view, ADH_CYCLE_HYSTERESIS_STEP * p->m.z0);
    }
    if (k + 1 != p->ps.nturns)
        return;
    adh_visco_energy *cy = &p->res.cycle;
    cy->work = p->turn_work[k] + p->work;
    cy->jumps = jumps;
    cy->dissipated = 0;
    cy->stored0 = 0;
    cy->stored = stored_change;
    p->res.hysteresis = tr->hysteresis;
}

/* The landing of a fold at base bf on unloading: from row j back, the
 * first point whose base is above it (x), or -1 beyond the curve's start. */
static double landing_out(const adh_path *p, long j, double bf)
{
    while (j >= 0 && !(row_base(p, (size_t)j) > bf))
        j--;
    if (j < 0)
        return -1;
    double bl = row_base(p, (size_t)j), bu = row_base(p, (size_t)j + 1);
    return (double)j + (bf - bl) / (bu - bl);
}

/* The stored energy at a landing l beyond the curve's start less the
 * start's, both rigid spheres' with the spring's. */
static double stored_beyond(const adh_path *p, const path_pt *l)
{
    const adh_obs *s = &p->c->rows[0];
    double sk = isfinite(p->k) ? (l->o.F * l->o.F - s->F * s->F) / (2 * p->k) : 0;
    return rigid_energy(&p->m, l->o.h0) - rigid_energy(&p->m, s->h0) + sk;
}

/* The stored energy at the last row, on the curve, less the start's:
 * nothing back at the start; past a start in contact, the base's work
 * along the curve from there to the start. */
static double stored_here(const adh_path *p)
{
    return p->last.x < (double)p->c->start ? curve_work(p, p->last.x, (double)p->c->start) : 0;
}

/* Turn k's unloading branch: from its point on the loading path back up
 * the curve, the base rising, until it is back at the start with the
 * surfaces apart. */
static void unload(adh_path *p, size_t k)
{
    path_pt q = { .x = p->turn_x[k], .o = p->turn_o[k] };
    p->path = (int)k + 1, p->branch = -1, p->have_last = 0;
    p->work = p->losses = 0;
    p->work_in = NAN;
    p->stranded = 0;
    p->branch_ev = p->nev;
    p->pull_row = -1;
    adh_turn_result *tr = &p->run->turns[k];
    memset(tr, 0, sizeof *tr);
    tr->h0 = q.o.h0;
    tr->max_load = q.o.F;
    tr->a_turn = q.o.a;
    tr->pulloff_F = INFINITY;
    tr->jump_out_h0 = NAN;
    tr->hysteresis = NAN;   /* until the branch ends (end_branch) */
    tr->path = (int)k + 1;
    p->run->nturns = k + 1;
    p->in_contact = q.o.a > 0;
    double bt = base_of(p, &q.o);
    p->t0 = q.o.t, p->b0 = bt, p->speed = p->d.speed_out;
    emit(p, &q, p->t0, 0);
    if (p->d.dwell > 0) {   /* nothing moves in an elastic solid held still */
        p->t0 += p->d.dwell;
        emit(p, &q, p->t0, 0);
        add_event(p, ADH_VISCO_UNLOAD, &p->last);
    }
    double bmax = bt, x = p->turn_x[k];
    long j = x == floor(x) ? (long)x - 1 : (long)floor(x);
    while (p->rc == ADH_SUCCESS) {
        if (!p->in_contact && bmax >= p->b_start && p->last.o.base >= p->b_start) {
            end_branch(p, stored_here(p));
            return;
        }
        if (j < 0) {
            /* the curve's first row, in contact still: a start where the
             * surfaces touch whose curve beyond it (from where they do
             * not, adh_path_curve.start) was not had. The unloading would
             * go on past it until they part; the branch ends here, in
             * contact (the run says so: not separated), with no jump out
             * and no pull-off: the lowest force seen is not one (a 1 TPa
             * sphere from 0.1 nm reported its start's +8.96 uN) */
            p->stranded = 1;
            end_branch(p, 0);
            return;
        }
        double bj = row_base(p, (size_t)j);
        if (bj > bmax) {
            if (!p->in_contact && bj > p->b_start && p->last.o.base < p->b_start) {
                /* the base back at its start between the rows: the end there */
                double xs = (double)j + (p->b_start - bj) / (base_of(p, &p->last.o) - bj) * (p->last.x - (double)j);
                step_to(p, xs);
                end_branch(p, stored_here(p));
                return;
            }
            step_to(p, (double)j);
            bmax = bj;
            j--;
            continue;
        }
        /* the base turned at row j + 1: a fold, landing further out; out
         * of contact under displacement control, the static solver's */
        path_pt f = fold_at(p, (size_t)j + 1);
        double xl = landing_out(p, j, base_of(p, &f.o));
        if (p->in_contact && (xl < 0 || !(at(p, xl).o.a > 0))) {
            static_fold(p, (size_t)j + 1, 0, &f);
            xl = landing_out(p, j, base_of(p, &f.o));
        }
        if (xl < 0) {   /* beyond the curve's start: a soft spring's flight */
            double loss;
            path_pt l = land_rigid(p, base_of(p, &f.o), &loss);
            jump(p, &f, &l, loss + jump_loss(p, &f, (size_t)j, 0));
            end_branch(p, stored_beyond(p, &l) + curve_work(p, 0, (double)p->c->start));
            return;
        }
        path_pt l = at(p, xl);
        jump(p, &f, &l, jump_loss(p, &f, (size_t)j, xl));
        bmax = base_of(p, &f.o);
        j = (long)floor(xl);
        if ((double)j == xl)
            j--;
    }
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

int adh_path_build(adh_path *p, const adh_path_curve *c, const adh_material *m, const adh_visco_drive *d,
                   const adh_protocol_settings *ps, adh_run *run)
{
    adh_path_clear(p);
    p->row0 = run->nrows;
    p->c = c, p->m = *m, p->d = *d, p->ps = *ps, p->run = run;
    p->rc = ADH_SUCCESS;
    p->k = d->spring;
    p->reached = 0;
    p->work = p->losses = 0;
    p->work_in = NAN;
    p->stranded = 0;
    p->in_contact = 0;
    p->branch_ev = 0;
    p->pull_row = -1;
    p->deeper = NAN;
    qsort(p->ps.turns, p->ps.nturns, sizeof *p->ps.turns, cmp_desc);
    qsort(p->ps.profiles, p->ps.nprofiles, sizeof *p->ps.profiles, cmp_desc);
    adh_visco_result *r = &p->res;
    if (c->n == 0 || c->start >= c->n)
        return ADH_SUCCESS;
    p->b_start = row_base(p, c->start);
    r->start_h0 = c->rows[c->start].h0;
    r->start_base = p->b_start;
    run->start = c->rows[c->start].h0;
    load(p);
    r->time = p->have_last ? p->last.o.t : 0;
    if (c->complete && ps->unload && p->reached == p->ps.nturns)
        for (size_t k = 0; k < p->reached && p->rc == ADH_SUCCESS; k++)
            unload(p, k);
    return p->rc;
}

double adh_path_deeper(const adh_path *p)
{
    return p->deeper;
}

const adh_state *adh_path_state(adh_path *p, size_t row)
{
    if (row >= p->nxs)
        return NULL;
    double x = p->xs[row];
    if (x >= 0)
        return state_at(p, x) == 0 ? p->st : NULL;
    /* a landing beyond the curve: undeformed */
    if (state_at(p, 0) != 0)
        return NULL;
    adh_state *s = p->st;
    s->h0 = p->run->rows[p->row0 + row].h0;
    for (size_t j = 0; j < s->n; j++) {
        double r = p->c->g->r[j];
        s->u[j] = 0;
        s->h[j] = s->h0 + r * r / (2.0 * p->m.R);
        s->p[j] = adh_lj_pressure(s->h[j], p->m.A, p->m.z0);
    }
    return s;
}
