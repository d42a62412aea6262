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
#define ADH_FRONT_REL_SWEEP 5 /* ... where the extremes are swept */
#ifndef ADH_FRONT_REFRESH /* front steps of this many rings refactorize first */
#define ADH_FRONT_REFRESH 2
#endif
#ifndef ADH_FRONT_WINDOW
#define ADH_FRONT_WINDOW 6 /* rings each side of an extremum stepped in Q */
#endif
#ifndef ADH_FRONT_PHASES /* steps of a phase sweep across one ring */
#define ADH_FRONT_PHASES 16
#endif
#ifndef ADH_FRONT_SWEEP_MIN /* rings in contact for a phase sweep */
#define ADH_FRONT_SWEEP_MIN 400
#endif
#ifndef ADH_FRONT_SWEEP_BAND /* and rings of the fine band */
#define ADH_FRONT_SWEEP_BAND 4000
#endif

/* Front mode off; allowed when the lattice folds are stepped over; the
 * uniform fine band's extent. */
void static_front_set(adh_static *w)
{
    static_front *fr = &w->fr;
    fr->on = 0;
    fr->fwin = 0;
    fr->pw = 0;
    fr->nosweep[0] = fr->nosweep[1] = 0;
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

/* The Lagrange weights L of the np (at most 3) points at xs for a, and
 * the values ys interpolated there with them: the front predictors' h0. */
static double front_lagrange(const double *xs, size_t np, double a, const double *ys, double *L)
{
    double y = 0;
    for (size_t j = 0; j < np; j++) {
        L[j] = 1;
        for (size_t l = 0; l < np; l++)
            if (l != j)
                L[j] *= (a - xs[l]) / (xs[j] - xs[l]);
    }
    for (size_t j = 0; j < np; j++)
        y += L[j] * ys[j];
    return y;
}

/* static_front_predict in a phase sweep: the front at tgt + phase rings,
 * the last points' at fe[j] + ph[j]; each gap profile moved out by its
 * distance in rings, whole and fractional (linear between rings). */
static void front_predict_phased(adh_static *w, size_t tgt, double phase, adh_state *x)
{
    const static_front *fr = &w->fr;
    size_t n = w->n, np = fr->fn < 3 ? fr->fn : 3;
    const double *us[3] = { w->st->u, w->q.u1, w->q.u2 };
    double h0s[3] = { w->st->h0, w->q.h1, w->q.h2 }, L[3], pj[3];
    double a = (double)tgt + phase;
    for (size_t j = 0; j < np; j++)
        pj[j] = (double)fr->fe[j] + fr->ph[j];
    x->h0 = front_lagrange(pj, np, a, h0s, L);
    for (size_t i = 0; i < n; i++) {
        double v = 0;
        if (i < fr->nf) {
            for (size_t j = 0; j < np; j++) {
                double d = a - pj[j], whole = floor(d), f = d - whole;
                double m0 = (double)i - whole, m1 = m0 - 1;
                size_t k0 = m0 > 0 ? (size_t)m0 : 0, k1 = m1 > 0 ? (size_t)m1 : 0;
                double g0 = h0s[j] + w->shape[k0] - us[j][k0], g1 = h0s[j] + w->shape[k1] - us[j][k1];
                v += L[j] * ((1 - f) * g0 + f * g1);
            }
            x->u[i] = x->h0 + w->shape[i] - v;
        } else {
            for (size_t j = 0; j < np; j++)
                v += L[j] * us[j][i];
            x->u[i] = v;
        }
    }
}

/* Front mode's predictor for the front at node tgt: the gap profiles of
 * the last front points (Lagrange in the front radius), each moved out by
 * its distance to tgt within the fine band (whole rings: exact shifts, the
 * axis's flat gap repeated), u extrapolated in place beyond it. In a phase
 * sweep the front is at tgt + phase and the points at theirs
 * (front_predict_phased). */
void static_front_predict(adh_static *w, size_t tgt, double phase, adh_state *x)
{
    const static_front *fr = &w->fr;
    size_t n = w->n, np = fr->fn < 3 ? fr->fn : 3;
    if (phase != 0 || (fr->ph[0] != 0 && np > 0) || (fr->ph[1] != 0 && np > 1) || (fr->ph[2] != 0 && np > 2)) {
        front_predict_phased(w, tgt, phase, x);
        return;
    }
    const double *r = w->grid->r;
    const double *us[3] = { w->st->u, w->q.u1, w->q.u2 };
    double h0s[3] = { w->st->h0, w->q.h1, w->q.h2 }, L[3], re[3];
    for (size_t j = 0; j < np; j++)
        re[j] = r[fr->fe[j]];
    x->h0 = front_lagrange(re, np, r[tgt], h0s, L);
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
    const static_front *fr = &w->fr;
    size_t tgt = fr->fe[0] + fr->fk;
    double th = w->s.u_weight, gap = fr->pw ? (1 - fr->phn) * fr->fH + fr->phn * fr->hin : fr->fH;
    memset(w->q.rG, 0, w->n * sizeof *w->q.rG);
    w->q.rG[tgt] = -1.0 / th; /* the row of h_tgt = h0 + r^2/2R - u_tgt */
    *row = (static_row){ .kind = STATIC_ROW_GAP, .nu = w->q.rG, .nh = 1.0, .node = tgt, .gap = gap,
                         .refresh = w->fr.fk >= ADH_FRONT_REFRESH &&
                                    !adh_precond_type_of(w->nw.P)->truncates };
}

/* A phase sweep's next step: a 1/ADH_FRONT_PHASES ring on (fk whole rings
 * and the phase phn past them). Front steps otherwise keep theirs. */
void static_front_aim(adh_static *w)
{
    static_front *fr = &w->fr;
    if (!fr->pw)
        return;
    double pos = fr->ph[0] + 1.0 / ADH_FRONT_PHASES;
    size_t whole = (size_t)floor(pos + 1e-9);
    fr->fk = whole;
    fr->phn = whole ? 0 : pos;
}

/* The corrected point's front node is the one asked for: the target ring,
 * or in a sweep past mid-ring (its gap held below 1.5 z0) the next. */
int static_front_is_target(const adh_static *w, size_t node)
{
    const static_front *fr = &w->fr;
    size_t tgt = fr->fe[0] + fr->fk;
    return node == tgt || (fr->pw && node == tgt + 1);
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
    fr->pw = 0;
    fr->ph[0] = fr->ph[1] = fr->ph[2] = fr->phn = 0;
}

static void front_sweep_near(adh_static *w, const double *ahead, const double *behind);

/* The extremes are found by phase sweeps (front_sweep_near) under the
 * HODLR preconditioner (the graded grids) on fine bands of
 * ADH_FRONT_SWEEP_BAND rings or more (sigma above ~40), with the contact
 * ADH_FRONT_SWEEP_MIN rings or more across (the curve at one phase flat
 * over a few rings). At sigma = 20 and 30 (bands of 1 640 and 2 790
 * rings) the sweeps found the lattice's extremes more closely than the
 * steps in Q, and further from the finer grid's: pull-off 9.5e-4 and
 * 1.07e-3 from it, hysteresis 1.0e-3 and 1.6e-3 (docs/static-curve.md),
 * so there the steps in Q stay. */
/* The bands whose extremes are swept (front_sweeps, below) */
static int front_band_swept(const adh_static *w)
{
    return !adh_precond_type_of(w->nw.P)->truncates && w->fr.nf >= ADH_FRONT_SWEEP_BAND;
}

static int front_sweeps(const adh_static *w)
{
    return front_band_swept(w) && w->fr.fe[0] >= ADH_FRONT_SWEEP_MIN;
}

/* At one lattice phase the jump-out (h0's maximum) and the pull-off (F's
 * minimum) would miss the lattice's own swing, up to ~1e-3 (the exact
 * curve's extremes are its highest lattice folds): when the parabola
 * through the last three front points puts either a few steps ahead, the
 * front steps shorten to land a few rings before it, and from there steps
 * in Q of about a ring (every phase) cross it; where front_sweeps, a
 * phase sweep of one ring does (front_sweep_near). kused: the last step
 * in rings, dq: Q's change over it. */
static void front_extremum(adh_static *w, size_t kused, double dq)
{
    static_front *fr = &w->fr;
    if (fr->fn < 3)
        return;
    const double *r = w->grid->r;
    double a[3] = { r[fr->fe[2]], r[fr->fe[1]], r[fr->fe[0]] }, hh[3] = { w->q.h2, w->q.h1, w->st->h0 };
    double FF[3] = { adh_folds_recent(w->folds, 2).F, adh_folds_recent(w->folds, 1).F, w->F };
    double dr = adh_rings_width(w->grid, 0), ahd[2] = { INFINITY, INFINITY }, bhd[2] = { INFINITY, INFINITY };
    for (int which = 0; which < 2; which++) {
        const double *y = which ? FF : hh;
        /* the parabola y = y1 + b (x - x1) + c (x - x1)^2 through the three */
        double d1 = (y[1] - y[0]) / (a[1] - a[0]), d2 = (y[2] - y[1]) / (a[2] - a[1]);
        double c = (d2 - d1) / (a[2] - a[0]), b = d1 + c * (a[1] - a[0]);
        if (which ? !(c > 0) : !(c < 0))
            continue; /* F's minimum, h0's maximum */
        double v = a[1] - b / (2 * c);
        if (v > a[2])
            ahd[which] = (v - a[2]) / dr;
        else
            bhd[which] = (a[2] - v) / dr;
    }
    if (front_sweeps(w)) {
        front_sweep_near(w, ahd, bhd);
        return;
    }
    double ahead = fmin(ahd[0], ahd[1]);
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

/* Where front_sweeps, the lattice's swing at an extremum is found by a
 * phase sweep, not by steps in Q: the curve repeats from ring to ring
 * there (the contact spans thousands of rings: at sigma = 100 h0 at one
 * phase moves by 0.1 pm over a dozen rings, its swing over the phases of
 * one ring is 32 pm, the same in each), so one ring crossed in
 * ADH_FRONT_PHASES steps holds every phase a dozen rings in Q do. A step
 * of a sixteenth of a ring from the last (whose profile moved out by it
 * predicts the next) converges in 2 Newton iterations of ~5 GMRES, ~40 ms
 * at sigma = 100, where a step in Q across the lattice took 5-6 of ~6
 * (~120 ms: its predictor, a parabola in Q over points at other phases,
 * was off by ~0.5 z0). The front steps halve towards the extremum and
 * sweep the ring it is within one of (three past it). */
static void front_sweep_near(adh_static *w, const double *ahead, const double *behind)
{
    static_front *fr = &w->fr;
    double next = INFINITY;
    int now = 0;
    for (int k = 0; k < 2; k++) {
        if (fr->fe[0] < fr->nosweep[k])
            continue; /* swept already */
        now |= ahead[k] <= 1.0 || behind[k] <= 3.0;
        next = fmin(next, ahead[k]);
    }
    if (now && fr->fe[0] > 0) {
        fr->pw = 1;
        fr->pwleft = ADH_FRONT_PHASES;
        fr->hin = w->st->h[fr->fe[0] - 1];
        for (int k = 0; k < 2; k++)
            if (ahead[k] <= 1.0 || behind[k] <= 3.0)
                fr->nosweep[k] = fr->fe[0] + 2 * ADH_FRONT_WINDOW;
        return;
    }
    if (next < 2.0 * (double)fr->fk + ADH_FRONT_WINDOW) {
        size_t k = (size_t)(next / 2);
        fr->fk = k > 1 ? k : 1;
        fr->fhold = 1;
    }
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
 * (a fifth where the extremes are swept: sigma = 100 237 -> 205 points,
 * the extremes the same)
 * (docs/static-curve.md). Up to sigma ~ 25 (a band of 2 048 rings) the
 * cap is 64 as before. q, q0: Q at the new point and the one before. */
void static_front_accepted(adh_static *w, size_t iters, double q, double q0)
{
    static_front *fr = &w->fr;
    size_t kused = fr->fk;
    fr->fe[2] = fr->fe[1], fr->fe[1] = fr->fe[0], fr->fe[0] += fr->fk;
    fr->ph[2] = fr->ph[1], fr->ph[1] = fr->ph[0], fr->ph[0] = fr->pw ? fr->phn : 0;
    fr->fn++;
    if (fr->pw) {
        /* swept: front steps from here, at this point's phase */
        if (--fr->pwleft == 0) {
            fr->pw = 0;
            front_start(w);
        }
        return;
    }
    if (q > q0)
        w->q.dq = q - q0; /* should it fall back to steps in Q */
    if (fr->fhold)
        fr->fhold = 0;
    else if (iters <= ADH_FRONT_GROW)
        fr->fk += fr->fk / 2 > 1 ? fr->fk / 2 : 1;
    else if (iters >= ADH_FRONT_GROW + 3)
        fr->fk = fr->fk * 2 / 3 > 1 ? fr->fk * 2 / 3 : 1;
    size_t rel = front_band_swept(w) ? ADH_FRONT_REL_SWEEP : ADH_FRONT_REL;
    size_t kmax = fr->fe[0] / rel, cap = fr->nf / ADH_FRONT_BAND;
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
    if (fr->on && !fix && fr->pw) {
        /* a sweep's step failed: steps in Q across the extremum instead */
        fr->pw = 0;
        fr->on = 0;
        fr->fwin = fr->fe[0] + 2 * ADH_FRONT_WINDOW;
        w->q.dq = w->q.dq > 0 ? w->q.dq : w->s.ds_init * w->q.qslope;
        return 1;
    }
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
