/* Steps in a contact measure Q (lattice_skip 1). On a resolved large grid
 * a lattice fold pair spans well under a picometre to a few pm in h0, yet
 * the exact curve needs several points for each. Q (about the area where
 * the gap is near z0) grows monotonically along the whole curve, so each
 * step solves G = 0 with Q fixed: no tangent, no turn to watch, no leg
 * running back to land on. The predictor is the parabola in Q through the
 * last three points, the step follows Newton's effort, and the folds and
 * the force's minimum are placed on the parabolas through three points
 * (adhere/folds.h): lattice folds a step spans are stepped over, physical
 * ones (jump-in, jump-out) are found as on the exact curve. Once a contact
 * of a few rings has formed, front steps (static_front.c) take over. */
#include "core/static.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/rings.h"
#include "adhere/status.h"
#include "adhere/units.h"

#ifndef ADH_Q_GROW /* Newton iterations below which the step grows */
#define ADH_Q_GROW 4
#endif

/* Q = sum_i a_i (z0/h_i)^6 (a_i the ring areas / 2 pi), about the area
 * within the interaction zone. It grows monotonically along the whole
 * curve (the gaps near the axis close on the outer branch, the contact
 * widens after), through every fold in h0, physical or lattice, so a step
 * in Q never has to turn. Its gradient goes into qu (per u_n, divided by
 * theta as the border row expects) and *qh (per h0), both scaled by
 * *scale so that the row has unit metric norm; returns Q. */
double static_qmeasure(adh_static *w, const adh_state *x, double *qu, double *qh, double *scale)
{
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight, q = 0, gh = 0, nrm = 0;
    for (size_t i = 0; i < n; i++) {
        double a = adh_rings_weight(w->grid, i), r = z0 / x->h[i], r3 = r * r * r, f = a * r3 * r3;
        q += f;
        double d = -6.0 * f / x->h[i]; /* dQ/dh_i */
        if (qu)
            qu[i] = -d; /* h_i = h0 + r^2/2R - u_i */
        gh += d;
        nrm += d * d / th;
    }
    if (qu) {
        nrm = sqrt(nrm + gh * gh);
        for (size_t i = 0; i < n; i++)
            qu[i] /= th * nrm;
        *qh = gh / nrm;
        *scale = nrm;
    }
    return q;
}

/* After the start point: Q there, and dQ/ds along the start's tangent
 * from Q's gradient, which sets the first step in Q. */
int static_qstep_start(adh_static *w)
{
    static_qstep *q = &w->q;
    double qh, qs;
    q->q = static_qmeasure(w, w->st, q->rG, &qh, &qs);
    double d = qh * w->tau_h;
    for (size_t i = 0; i < w->n; i++)
        d += w->s.u_weight * q->rG[i] * w->tau_u[i];
    q->qslope = d * qs * w->m.z0; /* per unit s, which is in z0 */
    q->dq = w->s.ds_init * q->qslope;
    if (q->dq > 0)
        return ADH_SUCCESS;
    snprintf(w->why, sizeof w->why, "the static curve's start h0 = %s: the contact measure Q does not grow along "
             "its tangent (steps in Q cannot begin): start further out", adh_qtext(w->st->h0, ADH_Q_LENGTH).s);
    w->fix = ADH_FIX_START;
    return ADH_ESTALL;
}

/* Q's parabola through the last three points at qtarget: the curve bends
 * smoothly over many rings, and a better start saves Newton steps. */
static void parabola_predict(adh_static *w, double qtarget)
{
    const static_qstep *Q = &w->q;
    adh_state *x = w->trial;
    const double *u0 = w->st->u;
    double q0 = Q->q, q1 = Q->q1, q2 = Q->q2, dq = qtarget - q0;
    double a = dq / (q0 - q1), b = dq * (qtarget - q1) / (q0 - q2);
    for (size_t i = 0; i < w->n; i++) {
        double f01 = (u0[i] - Q->u1[i]) / (q0 - q1), f12 = (Q->u1[i] - Q->u2[i]) / (q1 - q2);
        x->u[i] = u0[i] + a * (u0[i] - Q->u1[i]) + b * (f01 - f12);
    }
    double f01 = (w->st->h0 - Q->h1) / (q0 - q1), f12 = (Q->h1 - Q->h2) / (q1 - q2);
    x->h0 = w->st->h0 + a * (w->st->h0 - Q->h1) + b * (f01 - f12);
}

/* Predicts and corrects one step: a landing on h0_end (from the front
 * moved there in front mode), a front step, or a step in Q. */
static int correct(adh_static *w, double ds, int fix, size_t *iters)
{
    adh_state *x = w->trial;
    double h0_end = w->s.h0_end;
    static_predict(w, ds, fix, h0_end);
    static_row row = { .kind = STATIC_ROW_PLANE, .nu = w->nw.zero, .nh = 1.0 };
    if (fix) {
        if (w->fr.on) {
            static_front_predict(w, w->fr.fend, 0, x);
            x->h0 = h0_end;
        }
    } else if (w->fr.on) {
        static_front_aim(w);
        static_front_predict(w, w->fr.fe[0] + w->fr.fk, w->fr.pw ? w->fr.phn : 0, x);
        static_front_row(w, &row);
    } else {
        double qtarget = w->q.q + w->q.dq;
        if (w->q.nhist >= 2)
            parabola_predict(w, qtarget);
        row = (static_row){ .kind = STATIC_ROW_Q, .target = qtarget };
    }
    return static_correct(w, &row, iters);
}

/* The accepted step: the history the predictors use, Q's slope, and the
 * next step (in Q: grow while Newton converges at once, shrink when it
 * labours; front steps by their own rules). */
static int accepted(adh_static *w, int fix, size_t iters)
{
    static_qstep *Q = &w->q;
    /* Q only grows along the curve; on the curve smoothed over the lattice
     * the stability follows the direction of h0 as on the exact one */
    static_secant(w, w->tau_u_new, &w->tau_h_new);
    w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->det_b_sign;
    double q = static_qmeasure(w, w->trial, NULL, NULL, NULL), q0 = Q->q;
    double *tu = Q->u2;
    Q->u2 = Q->u1;
    Q->u1 = tu;
    memcpy(Q->u1, w->st->u, w->n * sizeof *tu);
    Q->q2 = Q->q1, Q->h2 = Q->h1;
    Q->q1 = q0, Q->h1 = w->st->h0;
    Q->nhist++;
    w->newton_point = iters;
    int was_front = w->fr.on && !fix;
    static_accept(w);
    if (fix)
        w->done = 1;
    Q->q = q;
    if (q > q0)
        Q->qslope = (q - q0) / (w->s_arc - adh_folds_recent(w->folds, 1).s);
    if (was_front) {
        static_front_accepted(w, iters, q, q0);
    } else {
        Q->dq *= iters <= ADH_Q_GROW ? 1.5 : iters >= ADH_Q_GROW + 3 ? 0.7 : 1.0;
        static_front_qstep_accepted(w);
    }
    static_front_clamp(w);
    return static_accepted(w);
}

int static_qstep_iterate(adh_static *w)
{
    size_t iters = 0;
    for (;;) {
        if (w->ds < w->s.ds_min)
            return static_stalled(w, w->fr.on ? "step (in rings of the contact line)" : "step (in the contact measure Q)");
        w->ds = w->q.dq / w->q.qslope;
        double ds;
        int fix = static_landing(w, w->fr.on, &ds);
        w->nw.attempt++;
        int rc = correct(w, ds, fix, &iters);
        if (rc == ADH_ENOMEM || rc == ADH_EINTR)
            return rc;
        int ok = rc == ADH_SUCCESS;
        if (ok && !fix && w->trial->h0 < w->s.h0_end && w->tau_h < 0) {
            /* a step in Q went past the end: land on it instead (in front
             * mode from the front node interpolated there) */
            if (!static_front_past_end(w)) {
                w->end_next = 1;
                w->fr.fend = w->fr.fe[0] + 1;
            }
            continue;
        }
        /* the gap fH at the target ring, but the contact is not the disk
         * up to it: not the front that was asked for */
        if (ok && w->fr.on && !fix && !static_front_is_target(w, static_front_node_of(w, w->trial)))
            ok = 0;
        if (ok)
            return accepted(w, fix, iters);
        /* a failed step is usually a fold just ahead: cut hard */
        w->res.rejected++;
        w->last_reject = rc == ADH_SUCCESS && w->fr.on ? "the corrected contact was not the front asked for"
                                                        : static_reject(rc);
        if (static_front_failed(w, fix))
            continue;
        w->ds *= 0.25;
        w->q.dq *= 0.25;
        w->end_next = 0; /* nearer in Q first: the end from closer by */
    }
}
