/* The exact static curve (lattice_skip 0): Keller's pseudo-arclength
 * continuation in (u, h0). Each step predicts along the unit tangent,
 * corrects by Newton on the hyperplane through the prediction normal to
 * it, and is judged: rejected when Newton fails, a gap in the interaction
 * zone moved by more than max_gap_step, the tangent turned by more than
 * max_angle, the secant left the old tangent, or det B (bordered by the
 * previous tangent) changed sign (the corrector then landed on a leg of
 * the curve that runs back). The step adapts to the tangent's turn, to
 * Newton's effort and to the gaps' change, so that every node crossing
 * the law's barrier (a lattice-trapping fold pair) is resolved. */
#include "core/static.h"

#include <math.h>

#include "adhere/status.h"

/* The largest change of a gap below 3 z0 from st to trial, over what
 * max_gap_step allows (0 when it is off): a node crossing the barrier of
 * the law is what makes a lattice-trapping fold pair, and a step that
 * carried a node across at once could step over the pair. */
static double gap_ratio(const adh_static *w)
{
    double z0 = w->m.z0, dg = 0;
    for (size_t i = 0; i < w->n; i++)
        if (fmin(w->st->h[i], w->trial->h[i]) < 3.0 * z0)
            dg = fmax(dg, fabs(w->trial->h[i] - w->st->h[i]));
    return w->s.max_gap_step > 0 ? dg / (w->s.max_gap_step * z0) : 0;
}

/* The tangent at the corrected point, and whether the step stays on the
 * curve it came along; *turn: the tangent's turn, rad. */
static int judge(adh_static *w, double *turn)
{
    size_t n = w->n;
    double z0 = w->m.z0, th = w->s.u_weight, cos_max = cos(w->s.max_angle);
    static_jacobian(w, w->trial, w->Dtr, w->gtr);
    int rc = static_tangent(w, w->Dtr, w->gtr, w->tau_u_new, &w->tau_h_new);
    /* A fold in this step: check det B at the new point (below),
     * factorizing there unless GMRES already did. */
    if (rc == ADH_SUCCESS && (w->tau_h_new < 0) != (w->tau_h < 0) &&
        !(w->nw.stamp == w->nw.attempt && w->nw.tangent_border))
        rc = static_refactor(w, w->Dtr, w->gtr, w->tau_u, w->tau_h);
    if (rc != ADH_SUCCESS)
        return 0;
    double ct = static_metric_dot(w, w->tau_u, w->tau_h, w->tau_u_new, w->tau_h_new);
    *turn = acos(fmin(1.0, fmax(-1.0, ct)));
    /* the secant from the last point must run along the old tangent: a
     * corrector that converged onto another part of the curve fails this
     * or the turn */
    double sh = (w->trial->h0 - w->st->h0) / z0, su = 0, s2 = sh * sh;
    for (size_t i = 0; i < n; i++) {
        double d = (w->trial->u[i] - w->st->u[i]) / z0;
        su += d * w->tau_u[i];
        s2 += th * d * d;
    }
    double cs = (th * su + sh * w->tau_h) / sqrt(s2);
    /* det B (bordered by the previous tangent) keeps its sign along one
     * curve traversed one way: a flip means the corrector landed on a part
     * of the curve that runs back against the tangent */
    int ok = ct >= cos_max && cs >= cos_max;
    if (w->nw.stamp == w->nw.attempt && w->nw.tangent_border)
        ok = ok && adh_precond_det_sign(w->nw.P) == w->det_b_sign;
    w->det_sign = (w->tau_h_new > 0 ? 1 : -1) * w->det_b_sign;
    return ok;
}

int static_arclength_iterate(adh_static *w)
{
    size_t iters = 0;
    for (;;) {
        if (w->ds < w->s.ds_min)
            return static_stalled(w, "arclength step");
        double ds;
        int fix = static_landing(w, 0, &ds);
        w->nw.attempt++;
        static_predict(w, ds, fix, w->s.h0_end);
        static_row row = { .kind = STATIC_ROW_PLANE, .nu = fix ? w->nw.zero : w->tau_u, .nh = fix ? 1.0 : w->tau_h };
        int rc = static_correct(w, &row, &iters);
        if (rc == ADH_ENOMEM || rc == ADH_EINTR)
            return rc;
        double turn = 0, gr = 0;
        int ok = rc == ADH_SUCCESS;
        if (ok && !fix && w->trial->h0 < w->s.h0_end && w->tau_h < 0) {
            /* the corrector (held on the plane normal to the tangent, not
             * at a given h0) went past the end: land on it instead, from
             * here. Accepted, the point past the end would have no way on:
             * the landing from there runs back against the tangent and
             * every cut step is judged so again (the curve stalled). */
            w->end_next = 1;
            continue;
        }
        if (ok) {
            gr = gap_ratio(w);
            if (gr > 1) {
                w->res.rejected++;
                w->last_reject = "the step closed the gap too far at once";
                w->ds *= fmax(0.1, 0.7 / gr);
                continue;
            }
            ok = judge(w, &turn);
        }
        if (ok) {
            w->newton_point = iters;
            static_accept(w);
            if (fix)
                w->done = 1;
            /* adapt: aim at half the allowed turn per step (the turn grows
             * about linearly with ds), slow down when Newton labours */
            double f = turn > 1e-12 ? 0.5 * w->s.max_angle / turn : 2.0;
            if (gr > 0)
                f = fmin(f, 0.7 / gr);
            f = fmin(2.0, fmax(0.5, f));
            if (iters > 6)
                f = fmin(f, 0.7);
            w->ds = fmin(w->s.ds_max, w->ds * f);
            return static_accepted(w);
        }
        /* a failed step is usually a fold just ahead: cut hard */
        w->res.rejected++;
        w->last_reject = static_reject(rc);
        w->ds *= 0.25;
        w->end_next = 0; /* nearer first: the end from closer by */
    }
}
