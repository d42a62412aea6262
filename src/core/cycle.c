#include "adhere/cycle.h"

#include <math.h>
#include <stdlib.h>

/* The loading force at h0, linearly interpolated between the two loading
 * rows around it; NAN outside the loading branch. Loading rows go down in
 * h0 (start - k d), so the bracket is found in one pass. */
static double loading_force(const adh_obs *rows, size_t n, double h0)
{
    const adh_obs *prev = NULL;
    for (size_t i = 0; i < n; i++) {
        const adh_obs *r = &rows[i];
        if (r->path != 0)
            continue;
        if (r->h0 == h0)
            return r->F;
        if (prev && (prev->h0 - h0) * (r->h0 - h0) < 0)
            return prev->F + (r->F - prev->F) * (h0 - prev->h0) / (r->h0 - prev->h0);
        prev = r;
    }
    return NAN;
}

double adh_cycle_hysteresis(const adh_obs *rows, size_t n, int path)
{
    double area = 0, prev_h = NAN, prev_gap = NAN, top = -INFINITY;
    int touching = 0;   /* the loading began in contact */
    for (size_t i = 0; i < n; i++)
        if (rows[i].path == 0 && rows[i].h0 > top) {
            top = rows[i].h0;
            touching = rows[i].a > 0;
        }
    for (size_t i = 0; i < n; i++) {
        const adh_obs *u = &rows[i];
        if (u->path != path || path <= 0)
            continue;
        double Fl = loading_force(rows, n, u->h0);
        /* Unloading goes on past the start while the surfaces touch: the
         * approach was never solved out there, but it began where the
         * force is negligible and the deformation below 1 % of z0, so its
         * force is the rigid spheres' (eq 22). Not from a start in
         * contact: no approach of this cycle's came through there (rigid
         * spheres' force below z0 is their overlap's, 3.39 pJ of a 1 TPa
         * sphere's "loop" from 0.1 nm), so the loop is over the positions
         * both branches cover (docs/stop-reasons.md, hysteresis) */
        if (isnan(Fl) && u->h0 > top && !touching)
            Fl = u->F_rigid;
        double gap = Fl - u->F;
        if (!isnan(gap) && !isnan(prev_gap))
            area += 0.5 * (gap + prev_gap) * fabs(u->h0 - prev_h);
        prev_gap = gap;
        prev_h = u->h0;
    }
    return area;
}

void adh_cycle_measure(const adh_obs *rows, size_t n, adh_cycle *c)
{
    c->max_load = c->h0_turn = c->a_turn = c->jump_in_h0 = NAN;
    c->pulloff_F = c->pulloff_h0 = c->jump_out_h0 = c->hysteresis = NAN;
    c->unloading = 0;
    for (size_t i = 0; i < n; i++) {
        const adh_obs *r = &rows[i];
        if (r->path > c->unloading)
            c->unloading = r->path;
        if (r->path != 0)
            continue;
        if (isnan(c->h0_turn) || r->h0 <= c->h0_turn) {
            c->h0_turn = r->h0;
            c->a_turn = r->a;
            c->max_load = r->F;
        }
        if (isnan(c->jump_in_h0) && r->a > 0)
            c->jump_in_h0 = r->h0;
    }
    if (!c->unloading)
        return;
    int touched = 0;
    for (size_t i = 0; i < n; i++) {
        const adh_obs *r = &rows[i];
        if (r->path != c->unloading)
            continue;
        if (isnan(c->pulloff_F) || r->F < c->pulloff_F) {
            c->pulloff_F = r->F;
            c->pulloff_h0 = r->h0;
        }
        if (r->a > 0)
            touched = 1;
        else if (touched && isnan(c->jump_out_h0))
            c->jump_out_h0 = r->h0;
    }
    c->hysteresis = adh_cycle_hysteresis(rows, n, c->unloading);
}

size_t adh_cycle_turns(const adh_obs *rows, size_t n, adh_turn_result *turns, size_t cap)
{
    size_t nt = 0;
    for (size_t i = 0; i < n && nt < cap; i++) {
        int p = rows[i].path;
        if (rows[i].branch > 0 || p <= 0 || (i > 0 && rows[i - 1].branch < 0 && rows[i - 1].path == p))
            continue;
        size_t t = i;   /* the last loading row before the branch */
        while (t > 0 && rows[t].branch < 0)
            t--;
        for (size_t j = 0; j < i; j++)
            if (rows[j].path == 0 && rows[j].h0 == rows[i].h0)
                t = j;   /* the branch began at a turn the loading hit */
        adh_turn_result *tr = &turns[nt++];
        tr->h0 = rows[t].h0;
        tr->max_load = rows[t].F;
        tr->a_turn = rows[t].a;
        tr->path = p;
        tr->pulloff_F = INFINITY;
        tr->pulloff_h0 = NAN;
        tr->jump_out_h0 = NAN;
        tr->hysteresis = NAN;
        int touched = 0;
        for (size_t j = i; j < n && rows[j].branch < 0 && rows[j].path == p; j++) {
            if (rows[j].F < tr->pulloff_F) {
                tr->pulloff_F = rows[j].F;
                tr->pulloff_h0 = rows[j].h0;
            }
            if (rows[j].a > 0)
                touched = 1;
            else if (touched && isnan(tr->jump_out_h0))
                tr->jump_out_h0 = rows[j].h0;
        }
    }
    return nt;
}

double adh_cycle_run_hysteresis(const adh_run *run)
{
    return adh_cycle_hysteresis(run->rows, run->nrows, (int)run->nturns);
}

/* Unstable rows a link between two stable ones may pass: where the steps
 * cross the lattice's folds about a ring at a time (the windows of
 * adhere/static.h around the jump-out and the pull-off), stable and
 * unstable points alternate, each stable leg sampled once; without links
 * those legs covered no h0 and the area lost what lay under them (0.2 to
 * 0.8 % at sigma = 30 to 100, docs/static-curve.md). */
#define CYCLE_LATTICE_LINK 2

/* The stable row a stable leg goes on to from row i, dir +1 (the curve's
 * order) or -1 (back): the neighbour when stable, or past at most
 * CYCLE_LATTICE_LINK unstable rows one on the same side of contact (a link
 * never crosses the jump-in or the jump-out). n when there is none. */
static size_t stable_link(const adh_run *c, size_t i, int dir)
{
    size_t n = c->nrows;
    for (size_t k = 1; k <= CYCLE_LATTICE_LINK + 1; k++) {
        size_t j = dir > 0 ? i + k : i - k;
        if (dir > 0 ? j >= n : k > i)
            return n;
        if (!c->rows[j].stable)
            continue;
        if (c->rows[j].h0 == c->rows[i].h0 || (k > 1 && (c->rows[j].a > 0) != (c->rows[i].a > 0)))
            return n;
        return j;
    }
    return n;
}

/* A stable leg's piece between rows i and j, and the row t (n: none) that
 * makes the chord a parabola: the nearer of the leg's rows before i and
 * after j that carries h0 on in the same direction. The contact branch
 * is sampled in steps of many rings (front steps) where it bends: chords
 * left the area 0.3 to 0.6 % short at sigma = 5 to 20 against the same
 * curve sampled every few rings, the parabolas 0.006 to 0.13 %. */
typedef struct cycle_piece {
    size_t i, j, p, q;
} cycle_piece;

static double piece_force(const adh_run *c, const cycle_piece *s, double x)
{
    size_t n = c->nrows;
    const adh_obs *a = &c->rows[s->i], *b = &c->rows[s->j], *t = NULL;
    if (s->p < n)
        t = &c->rows[s->p];
    if (s->q < n && (!t || fabs(c->rows[s->q].h0 - x) < fabs(t->h0 - x)))
        t = &c->rows[s->q];
    double la = (x - b->h0) / (a->h0 - b->h0), lb = (x - a->h0) / (b->h0 - a->h0);
    if (!t)
        return la * a->F + lb * b->F;
    double lt = (x - a->h0) * (x - b->h0) / ((t->h0 - a->h0) * (t->h0 - b->h0));
    la *= (x - t->h0) / (a->h0 - t->h0);
    lb *= (x - t->h0) / (b->h0 - t->h0);
    return la * a->F + lb * b->F + lt * t->F;
}

/* The hysteresis left when eps -> 0: under displacement control the drive
 * follows stable equilibria only, loading on the highest-force one at each
 * h0 (the outer branch until it ends at the jump-in fold) and unloading on
 * the lowest (the contact until the jump-out fold). Between the folds, and
 * wherever lattice trapping makes stable legs overlap, the two differ: the
 * area between them is the hysteresis no slower drive removes. NAN when
 * memory runs out. */
double adh_cycle_static_hysteresis(const adh_run *curve, double step)
{
    return adh_cycle_static_hysteresis_below(curve, step, INFINITY);
}

double adh_cycle_static_hysteresis_below(const adh_run *curve, double step, double top)
{
    size_t n = curve->nrows, np = 0;
    cycle_piece *pc = n ? malloc(n * sizeof *pc) : NULL;
    if (n && !pc)
        return NAN;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        const adh_obs *a = &curve->rows[i];
        lo = fmin(lo, a->h0);
        hi = fmax(hi, a->h0);
        size_t j = a->stable ? stable_link(curve, i, +1) : n;
        if (j == n)
            continue;
        double dir = curve->rows[j].h0 - a->h0;
        size_t p = stable_link(curve, i, -1), q = stable_link(curve, j, +1);
        pc[np++] = (cycle_piece){ .i = i, .j = j,
                                  .p = p < n && (a->h0 - curve->rows[p].h0) * dir > 0 ? p : n,
                                  .q = q < n && (curve->rows[q].h0 - curve->rows[j].h0) * dir > 0 ? q : n };
    }
    double area = 0;
    hi = fmin(hi, top);
    for (double x = lo + 0.5 * step; x < hi; x += step) {
        double fmax_ = -INFINITY, fmin_ = INFINITY;
        for (size_t k = 0; k < np; k++) {
            if ((x - curve->rows[pc[k].i].h0) * (x - curve->rows[pc[k].j].h0) > 0)
                continue;
            double F = piece_force(curve, &pc[k], x);
            fmax_ = fmax(fmax_, F);
            fmin_ = fmin(fmin_, F);
        }
        if (fmax_ > fmin_)
            area += (fmax_ - fmin_) * step;
    }
    free(pc);
    return area;
}
