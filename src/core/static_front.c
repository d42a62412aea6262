/* Front steps, within the steps in Q (static_qstep.c): once a few rings
 * are in contact the steps are whole rings of the contact line. Every
 * point holds the same gap at its front ring, so all see the lattice at
 * one phase and the curve they sample is smooth; the predictor moves the
 * gap profiles out as a travelling front, and within a few rings of the
 * jump-out and the pull-off the steps in Q (every phase) take over again,
 * so that the lattice's extremes are found as before. */
#include "core/static.h"

#include <math.h>
#include <string.h>

#include "adhere/rings.h"

#ifndef ADH_FRONT_GROW /* Newton iterations up to which the step grows */
#define ADH_FRONT_GROW 3
#endif
#ifndef ADH_FRONT_MAX /* the longest step, in rings, on a fine band of up */
#define ADH_FRONT_MAX 64 /* to ADH_FRONT_BAND times this */
#endif
#ifndef ADH_FRONT_BAND /* beyond: the longest step is the band's 1/this */
#define ADH_FRONT_BAND 32
#endif
#define ADH_FRONT_GAP 1.5 /* z0: the front node's gap is above this */
#define ADH_FRONT_MIN 8   /* rings in contact before front mode starts */
#define ADH_FRONT_REL 10
#ifndef ADH_FRONT_REFRESH /* front steps of this many rings refactorize first */
#define ADH_FRONT_REFRESH 2
#endif
#ifndef ADH_FRONT_WINDOW
#define ADH_FRONT_WINDOW 6 /* rings each side of an extremum stepped in Q */
#endif

/* Front mode off; allowed when the lattice folds are stepped over; the
 * uniform fine band's extent. */
void static_front_set(adh_static *w)
{
    static_front *fr = &w->fr;
    fr->on = 0;
    fr->fwin = 0;
    fr->ok = w->skip;
    fr->nf = 1;
    double w0 = adh_rings_width(w->grid, 0);
    while (fr->nf < w->n && fabs(adh_rings_width(w->grid, fr->nf) - w0) < 1e-6 * w0)
        fr->nf++;
}

/* The front node: the first whose gap exceeds ADH_FRONT_GAP z0. */
size_t static_front_node_of(const adh_static *w, const adh_state *x)
{
    size_t e = 0;
    while (e < w->n && x->h[e] <= ADH_FRONT_GAP * w->m.z0)
        e++;
    return e;
}

/* Front mode's predictor for the front at node tgt: the gap profiles of
 * the last front points (Lagrange in the front radius), each moved out by
 * its distance to tgt within the fine band (whole rings: exact shifts, the
 * axis's flat gap repeated), u extrapolated in place beyond it. */
void static_front_predict(adh_static *w, size_t tgt, adh_state *x)
{
    const static_front *fr = &w->fr;
    size_t n = w->n, np = fr->fn < 3 ? fr->fn : 3;
    const double *r = w->grid->r;
    const double *us[3] = { w->st->u, w->q.u1, w->q.u2 };
    double h0s[3] = { w->st->h0, w->q.h1, w->q.h2 }, L[3];
    double a = r[tgt];
    for (size_t j = 0; j < np; j++) {
        L[j] = 1;
        for (size_t l = 0; l < np; l++)
            if (l != j)
                L[j] *= (a - r[fr->fe[l]]) / (r[fr->fe[j]] - r[fr->fe[l]]);
    }
    x->h0 = 0;
    for (size_t j = 0; j < np; j++)
        x->h0 += L[j] * h0s[j];
    for (size_t i = 0; i < n; i++) {
        double v = 0;
        if (i < fr->nf) {
            for (size_t j = 0; j < np; j++) {
                size_t sh = tgt - fr->fe[j], m = i > sh ? i - sh : 0;
                v += L[j] * (h0s[j] + w->shape[m] - us[j][m]);
            }
            x->u[i] = x->h0 + w->shape[i] - v;
        } else {
            for (size_t j = 0; j < np; j++)
                v += L[j] * us[j][i];
            x->u[i] = v;
        }
    }
}

/* The constraint of a front step: the gap fH at the target ring. A step
 * of many rings moved the contact's edge since the factorization: a fresh
 * one (a few GMRES iterations' cost) saves ~20 when it is the whole
 * Jacobian's. */
void static_front_row(adh_static *w, static_row *row)
{
    size_t tgt = w->fr.fe[0] + w->fr.fk;
    double th = w->s.u_weight;
    memset(w->q.rG, 0, w->n * sizeof *w->q.rG);
    w->q.rG[tgt] = -1.0 / th; /* the row of h_tgt = h0 + r^2/2R - u_tgt */
    *row = (static_row){ .kind = STATIC_ROW_GAP, .nu = w->q.rG, .nh = 1.0, .node = tgt, .gap = w->fr.fH,
                         .refresh = w->fr.fk >= ADH_FRONT_REFRESH &&
                                    !adh_precond_type_of(w->nw.P)->truncates };
}

/* A front step went past h0_end: a shorter one to about the end first
 * (the landing is then within a ring). 0 when that is not for front mode
 * to do. */
int static_front_past_end(adh_static *w)
{
    static_front *fr = &w->fr;
    if (!(fr->on && fr->fk > 1))
        return 0;
    double f = (w->st->h0 - w->s.h0_end) / (w->st->h0 - w->trial->h0);
    size_t k = (size_t)floor(f * (double)fr->fk);
    fr->fk = k < 1 ? 1 : k < fr->fk ? k : fr->fk - 1;
    fr->fhold = 1;
    return 1;
}

static void front_start(adh_static *w)
{
    static_front *fr = &w->fr;
    size_t e = static_front_node_of(w, w->st);
    if (e < ADH_FRONT_MIN || e + 2 >= fr->nf)
        return;
    fr->on = 1;
    fr->fe[0] = e;
    fr->fH = w->st->h[e];
    fr->fn = 1;
    fr->fk = 1;
    fr->fhold = 0;
}

/* At one lattice phase the jump-out (h0's maximum) and the pull-off (F's
 * minimum) would miss the lattice's own swing, up to ~1e-3 (the exact
 * curve's extremes are its highest lattice folds): when the parabola
 * through the last three front points puts either a few steps ahead, the
 * front steps shorten to land a few rings before it, and from there steps
 * in Q of about a ring (every phase) cross it. kused: the last step in
 * rings, dq: Q's change over it. */
static void front_extremum(adh_static *w, size_t kused, double dq)
{
    static_front *fr = &w->fr;
    if (fr->fn < 3)
        return;
    const double *r = w->grid->r;
    double a[3] = { r[fr->fe[2]], r[fr->fe[1]], r[fr->fe[0]] }, hh[3] = { w->q.h2, w->q.h1, w->st->h0 };
    double FF[3] = { adh_folds_recent(w->folds, 2).F, adh_folds_recent(w->folds, 1).F, w->F };
    double dr = adh_rings_width(w->grid, 0), ahead = INFINITY;
    for (int which = 0; which < 2; which++) {
        const double *y = which ? FF : hh;
        /* the parabola y = y1 + b (x - x1) + c (x - x1)^2 through the three */
        double d1 = (y[1] - y[0]) / (a[1] - a[0]), d2 = (y[2] - y[1]) / (a[2] - a[1]);
        double c = (d2 - d1) / (a[2] - a[0]), b = d1 + c * (a[1] - a[0]);
        if (which ? !(c > 0) : !(c < 0))
            continue; /* F's minimum, h0's maximum */
        double v = a[1] - b / (2 * c);
        if (v > a[2])
            ahead = fmin(ahead, (v - a[2]) / dr);
    }
    if (!(ahead < 2.0 * (double)fr->fk + ADH_FRONT_WINDOW))
        return;
    if (ahead > 2 * ADH_FRONT_WINDOW) {
        /* halfway to the window's start: the next parabola, from closer
         * points, places it better */
        size_t k = (size_t)((ahead - ADH_FRONT_WINDOW) / 2);
        fr->fk = k > 1 ? k : 1;
        fr->fhold = 1;
        return;
    }
    fr->on = 0;
    fr->fwin = fr->fe[0] + (size_t)ceil(ahead) + ADH_FRONT_WINDOW;
    w->q.dq = dq / (double)kused;
}

/* An accepted front step: the front moves on, and the next step grows
 * while Newton converges at once, shrinks when it labours (not while
 * approaching an extremum), and stays under 1/ADH_FRONT_REL of the contact
 * radius (the parabolas through three points must see the extremes
 * coming) and under ADH_FRONT_MAX rings or 1/ADH_FRONT_BAND of the fine
 * band, whichever is longer. A cap of 64 rings alone made the front steps
 * as many as the band is long (the band is ~1.25 contact radii at the
 * turn, 0.3 edge widths a ring: ~1 640 rings at sigma = 20, ~12 800 at
 * 100): 210 front steps at sigma = 100 against 66 at 20; with the cap a
 * share of the band 110, where the tenth of the contact radius binds
 * (docs/static-curve.md). Up to sigma ~ 25 (a band of 2 048 rings) the
 * cap is 64 as before. q, q0: Q at the new point and the one before. */
void static_front_accepted(adh_static *w, size_t iters, double q, double q0)
{
    static_front *fr = &w->fr;
    size_t kused = fr->fk;
    fr->fe[2] = fr->fe[1], fr->fe[1] = fr->fe[0], fr->fe[0] += fr->fk;
    fr->fn++;
    if (q > q0)
        w->q.dq = q - q0; /* should it fall back to steps in Q */
    if (fr->fhold)
        fr->fhold = 0;
    else if (iters <= ADH_FRONT_GROW)
        fr->fk += fr->fk / 2 > 1 ? fr->fk / 2 : 1;
    else if (iters >= ADH_FRONT_GROW + 3)
        fr->fk = fr->fk * 2 / 3 > 1 ? fr->fk * 2 / 3 : 1;
    size_t kmax = fr->fe[0] / ADH_FRONT_REL, cap = fr->nf / ADH_FRONT_BAND;
    cap = cap > ADH_FRONT_MAX ? cap : ADH_FRONT_MAX;
    kmax = kmax < 1 ? 1 : kmax > cap ? cap : kmax;
    if (fr->fk > kmax)
        fr->fk = kmax;
    if (!w->done)
        front_extremum(w, kused, q - q0);
}

/* An accepted step in Q: past an extremum's window, front steps (again)
 * once the contact has formed. */
void static_front_qstep_accepted(adh_static *w)
{
    static_front *fr = &w->fr;
    if (fr->fwin && static_front_node_of(w, w->st) >= fr->fwin)
        fr->fwin = 0;
    if (fr->ok && !w->done && !fr->fwin)
        front_start(w);
}

/* The fine band ends: front steps stop short of it (the grid check says
 * the rest). */
void static_front_clamp(adh_static *w)
{
    static_front *fr = &w->fr;
    if (fr->on && fr->fe[0] + fr->fk >= fr->nf) {
        fr->fk = fr->nf - 1 > fr->fe[0] ? fr->nf - 1 - fr->fe[0] : 0;
        if (fr->fk == 0)
            fr->on = 0;
    }
}

/* A failed step in front mode: a shorter front step; from one ring, steps
 * in Q across the next few rings (as around an extremum), then front steps
 * again (returns 1: try again). A failed landing from the front: steps of
 * a ring in Q from here on (returns 0: the caller cuts the step). */
int static_front_failed(adh_static *w, int fix)
{
    static_front *fr = &w->fr;
    if (fr->on && !fix) {
        if (fr->fk == 1) {
            fr->on = 0;
            fr->fwin = fr->fe[0] + ADH_FRONT_WINDOW;
            w->q.dq = w->q.dq > 0 ? w->q.dq : w->s.ds_init * w->q.qslope;
        }
        fr->fk = fr->fk / 2 > 1 ? fr->fk / 2 : 1;
        return 1;
    }
    if (fr->on) {
        fr->on = 0, fr->ok = 0;
        w->q.dq /= (double)fr->fk;
    }
    return 0;
}
