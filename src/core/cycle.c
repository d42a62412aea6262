#include "adhere/cycle.h"

#include <math.h>

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
    for (size_t i = 0; i < n; i++)
        if (rows[i].path == 0)
            top = fmax(top, rows[i].h0);
    for (size_t i = 0; i < n; i++) {
        const adh_obs *u = &rows[i];
        if (u->path != path || path <= 0)
            continue;
        double Fl = loading_force(rows, n, u->h0);
        /* Unloading goes on past the start while the surfaces touch: the
         * approach was never solved out there, but it began where the
         * force is negligible and the deformation below 1 % of z0, so its
         * force is the rigid spheres' (eq 22) */
        if (isnan(Fl) && u->h0 > top)
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

/* The hysteresis left when eps -> 0: under displacement control the drive
 * follows stable equilibria only, loading on the highest-force one at each
 * h0 (the outer branch until it ends at the jump-in fold) and unloading on
 * the lowest (the contact until the jump-out fold). Between the folds, and
 * wherever lattice trapping makes stable legs overlap, the two differ: the
 * area between them is the hysteresis no slower drive removes. */
double adh_cycle_static_hysteresis(const adh_run *curve, double step)
{
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < curve->nrows; i++) {
        lo = fmin(lo, curve->rows[i].h0);
        hi = fmax(hi, curve->rows[i].h0);
    }
    double area = 0;
    for (double x = lo + 0.5 * step; x < hi; x += step) {
        double fmax_ = -INFINITY, fmin_ = INFINITY;
        for (size_t i = 0; i + 1 < curve->nrows; i++) {
            const adh_obs *a = &curve->rows[i], *b = &curve->rows[i + 1];
            if (!a->stable || !b->stable || (x - a->h0) * (x - b->h0) > 0 || a->h0 == b->h0)
                continue;
            double F = a->F + (b->F - a->F) * (x - a->h0) / (b->h0 - a->h0);
            fmax_ = fmax(fmax_, F);
            fmin_ = fmin(fmin_, F);
        }
        if (fmax_ > fmin_)
            area += (fmax_ - fmin_) * step;
    }
    return area;
}
