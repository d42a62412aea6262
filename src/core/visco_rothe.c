/* The viscoelastic path by a Rothe method: time discretised first, each
 * time step a static problem (adhere/static.h's adh_static_solve_at),
 * under displacement control (h0 = base). visco.c steps the protocol;
 * this file advances the state (u, q, local time) by one accepted step.
 *
 * Over a step dt (alpha = dt/tau), with p quadratic in time through the
 * step's ends and the step before, q's equation tau q' = p - q integrates
 * exactly (an exponential integrator, third order):
 *     q1 = a q0 + c0 p0 + c1 p1 - tau^2 k3 c2,
 *     a = e^-alpha, c1 = 1 - (1 - a)/alpha, c0 = (1 - a)/alpha - a,
 * c2 the second divided difference of p (linear in p1), k3 below. So
 * q1 = (known) + c1' p1, and u1 = -W (ceff p1) - e, ceff = cinf + cdel c1',
 * e = cdel W (known): for v = u1 + e the static problem at the compliance
 * ceff with the extra gap e, v + ceff W p(h0 + r^2/2R + e - v) = 0, at the
 * drive's h0, solved by the static solver's corrector from a predictor
 * in the frame of the contact line (the last two gap profiles shifted by
 * the front's predicted move, as the static curve's front steps predict;
 * it halved the Newton iterations against extrapolating u in time).
 *
 * The step's error: the quadratic's part of q against the linear rule's
 * (a conservative estimate of the third-order rule's), in the norm the
 * force sees: sum_n 2 pi w_n |dq_n| over sum_n 2 pi w_n |p_n| plus a floor
 * (a thousandth of the adhesion's force scale), times the delayed part of
 * the compliance cdel / (cinf + cdel), held below
 * ADH_ROTHE_TOL_FACTOR times the tolerance. A node the contact line
 * crosses has a kink in p: its estimate is large, but it weighs only its
 * ring's area.
 *
 * A step whose Newton fails, or that makes or breaks the contact far from
 * its predictor, is halved down to ROTHE_DT_MIN tau: there the sphere is
 * at a fold (a jump), and visco.c hands the path to IDAS from the last
 * accepted state, whose root of t' confirms the fold and whose crossing
 * lands it (visco_land.c, visco_cross.c). Measured against IDAS at
 * sigma = 30 and 75 and on the Figure-4-like sphere (docs/viscoelastic.md). */
#include "visco.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/observe.h"
#include "adhere/params.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/status.h"

#define ROTHE_DT_MIN 1e-4   /* shortest step before a jump: the base moving this
                               far (z0), or in a dwell this long (tau) */
#define ROTHE_MOVE_MAX 0.4  /* longest: the base, or the surface, moving this
                               far (z0; in a dwell the error alone bounds it):
                               rows as dense as a static curve's where q's
                               error allows more */
#define ROTHE_DT_START 1e-3 /* the first step after a (re)start, in tau */
#define ROTHE_JUMP_MOVE 0.5 /* a contact change moving a node this far (z0) from the predictor: a jump */
#define ROTHE_SNAP_MOVE 0.3 /* in contact, a node this far (z0) from the predictor: a snap */
#define ROTHE_LOCATE 1e-4   /* a contact made or lost smoothly placed within this (z0) */
#define ROTHE_FLOOR 1e-3    /* the error norm's floor, in 2 pi R dgamma */
#define ROTHE_ERR_SCALE 2.0 /* the estimate's factor */
#define ROTHE_FRONT_GAP 1.5 /* the front: where the gap passes this, in z0 */
#define ROTHE_NEWTON_TOL 1e-6 /* the step's Newton: max |G| below this, in z0 */
#define ROTHE_FORCE_FLOOR 0.3 /* the force's change a step is relative to at least this, in 2 pi R dgamma */

struct visco_rothe {
    double *u0, *q0, *p0, *pm, *um, *q1, *e, *tmp, *hc, *hp, *r2R, *buf;
    double *yback;              /* y a step before (len) and the accounts there */
    adh_visco_energy acc_back;
    int have_back;
    double dt, dtm, hprev;      /* the next step; the last; h0 a step before */
    double D0, Dm, P0, Pm;      /* the dissipation and the base's power now and a step before */
    double du;                  /* the last step's largest move of u, m */
    double dF;                  /* the last step's change of the force, over its scale */
    int hist;                   /* pm, um hold the step before */
    int contact, next_contact;
    size_t nf;                  /* nodes of the uniform fine band */
    size_t seen[3];             /* the static solver's counters already taken */
};

void adh_visco_rothe_free(adh_visco *w)
{
    if (w->ro) {
        free(w->ro->buf);
        free(w->ro);
        w->ro = NULL;
    }
}

static int rothe_alloc(adh_visco *w)
{
    size_t n = w->n;
    visco_rothe *R = calloc(1, sizeof *R);
    if (!R)
        return ADH_ENOMEM;
    w->ro = R;
    if (!(R->buf = calloc(11 * n + w->len, sizeof *R->buf)))
        return ADH_ENOMEM;
    R->yback = R->buf + 11 * n;
    double **bufs[] = { &R->u0, &R->q0, &R->p0, &R->pm, &R->um, &R->q1, &R->e, &R->tmp, &R->hc, &R->hp, &R->r2R };
    for (size_t i = 0; i < sizeof bufs / sizeof *bufs; i++)
        *bufs[i] = R->buf + i * n;
    double w0 = adh_rings_width(w->g, 0);
    R->nf = 1;
    while (R->nf < n && fabs(adh_rings_width(w->g, R->nf) - w0) < 1e-6 * w0)
        R->nf++;
    for (size_t i = 0; i < n; i++)
        R->r2R[i] = w->shape[i];
    if (!w->stat && !(w->stat = adh_static_alloc_shared(w->g, w->k, adh_visco_pre_entries(w->pre))))
        return ADH_ENOMEM;
    /* the static solver set once (its material and settings); its
     * corrector is then reused with the problem changed at each step */
    adh_material mi = w->m;
    mi.E = w->v.Einf;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_start = w->h0_start;   /* (the cancel flag is the steps', not its start's) */
    int rc = adh_static_set(w->stat, &mi, &ss);
    return rc == ADH_CONTINUE ? ADH_SUCCESS : rc;
}

static double dissipation(adh_visco *w, const double *p, const double *q)
{
    visco_rothe *R = w->ro;
    if (!(w->cdel > 0))
        return 0;
    for (size_t i = 0; i < w->n; i++)
        R->tmp[i] = p[i] - q[i];
    return w->cdel / w->v.tau * adh_visco_energy_norm(w, R->tmp);
}

int adh_visco_rothe_reset(adh_visco *w, const double *y)
{
    int rc;
    if (!w->ro && (rc = rothe_alloc(w)) != ADH_SUCCESS)
        return rc;
    visco_rothe *R = w->ro;
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y);
    if (adh_visco_gaps(w, y, h0) < 0)
        return ADH_ESTALL;
    memcpy(R->u0, y, n * sizeof *R->u0);
    memcpy(R->q0, y + w->IQ, n * sizeof *R->q0);
    memcpy(R->p0, w->p, n * sizeof *R->p0);
    R->contact = R->next_contact = adh_contact_radius(w->g, w->h, w->m.z0) > 0;
    R->hist = 0;
    R->have_back = 0;
    double v = fabs(w->seg.bdot);
    R->dt = ROTHE_DT_START * w->v.tau;
    if (v > 0)
        R->dt = fmin(R->dt, ROTHE_MOVE_MAX * w->m.z0 / v);
    R->D0 = dissipation(w, R->p0, R->q0);
    R->P0 = -adh_visco_force(w, h0) * w->seg.bdot;
    return ADH_SUCCESS;
}

/* q1 = a q0 + c0 p0 + c1 p1 over alpha, and the local error's factor k3:
 * dq = -p'' tau^2 k3 for p's second derivative p''. */
static void coeffs(double al, double *a, double *c0, double *c1, double *k3)
{
    double em = -expm1(-al), phi = em / al;
    *a = 1.0 - em;
    *c1 = 1.0 - phi;
    *c0 = phi - *a;
    if (al < 0.1) {   /* sum_k (-1)^k al^(k+3) / (k! (k+2) (k+3)): no cancellation */
        double s = 0, term = al * al * al, f = 1;
        for (int j = 0; j < 8; j++) {
            s += term / (f * (j + 2) * (j + 3));
            term *= -al;
            f *= j + 1;
        }
        *k3 = s;
    } else {
        double E1 = 1.0 - (*a) * (1.0 + al), E2 = 2.0 - (*a) * (al * al + 2.0 * al + 2.0);
        *k3 = al * E1 - E2;
    }
}

/* The front: where the gap passes ROTHE_FRONT_GAP z0, between nodes; -1 none. */
static double front_of(const adh_visco *w, const double *h)
{
    double G = ROTHE_FRONT_GAP * w->m.z0;
    if (!(h[0] <= G))
        return -1;
    size_t e = 1;
    while (e < w->n && h[e] <= G)
        e++;
    if (e == w->n)
        return -1;
    const double *r = w->g->r;
    return r[e - 1] + (G - h[e - 1]) / (h[e] - h[e - 1]) * (r[e] - r[e - 1]);
}

/* h at radius x (linear between nodes, even in r). */
static double h_at(const adh_visco *w, const double *h, double x)
{
    const double *r = w->g->r;
    size_t n = w->n, nf = w->ro->nf;
    x = fabs(x);
    if (x <= r[0])
        return h[0];
    size_t j = x < r[nf - 1] ? (size_t)((x - r[0]) / (r[1] - r[0])) : nf - 1;
    while (j + 1 < n && r[j + 1] < x)
        j++;
    if (j + 1 >= n)
        return h[n - 1];
    return h[j] + (h[j + 1] - h[j]) * (x - r[j]) / (r[j + 1] - r[j]);
}

/* The predictor's u at h1 into R->tmp: linear in time; in contact, in the
 * fine band, in the frame moving with the front. */
static void predict(adh_visco *w, double dt, double h0, double h1)
{
    visco_rothe *R = w->ro;
    size_t n = w->n;
    double f = R->hist ? dt / R->dtm : 0;
    for (size_t i = 0; i < n; i++)
        R->tmp[i] = R->u0[i] + f * (R->u0[i] - R->um[i]);
    if (!R->hist || !R->contact)
        return;
    for (size_t i = 0; i < n; i++) {
        R->hc[i] = h0 + R->r2R[i] - R->u0[i];
        R->hp[i] = R->hprev + R->r2R[i] - R->um[i];
    }
    double a0 = front_of(w, R->hc), am = front_of(w, R->hp);
    if (a0 < 0 || am < 0)
        return;
    double a1 = a0 + f * (a0 - am);
    for (size_t i = 0; i < R->nf; i++) {
        double x = w->g->r[i];
        double hp = (1 + f) * h_at(w, R->hc, x - (a1 - a0)) - f * h_at(w, R->hp, x - (a1 - am));
        R->tmp[i] = h1 + R->r2R[i] - hp;
    }
}

/* The static solver's counters since the last call into the run's
 * (Newton and GMRES iterations, factorizations; its set clears them: a
 * jump-in's landing). */
static void count(adh_visco *w)
{
    adh_static_result sr;
    adh_static_summary(w->stat, &sr);
    visco_rothe *R = w->ro;
    size_t now[3] = { sr.newton_iterations, sr.krylov_iterations, sr.factorizations };
    for (int i = 0; i < 3; i++) {
        size_t d = now[i] >= R->seen[i] ? now[i] - R->seen[i] : now[i];
        R->seen[i] = now[i];
        if (i < 2)
            w->stat0[1 + i] += (long)d;
        else
            w->rothe_factor += d;
    }
}

/* One attempted step of dt from local time tl: 0 solved and within the
 * tolerance (the answer in *x, q1 in R->q1), 1 rejected by the error, 2
 * failed (Newton, or the contact changed far from the predictor), 3 the
 * contact changed smoothly too far on (*err the fraction of the step to
 * the change). */
static int attempt(adh_visco *w, double tl, double dt, int shortest, double *err, const adh_state **x)
{
    visco_rothe *R = w->ro;
    size_t n = w->n;
    double tau = w->v.tau, al = dt / tau, a, c0, c1, k3;
    coeffs(al, &a, &c0, &c1, &k3);
    double kq = tau * tau * k3, A = R->hist ? 1.0 / (dt * (dt + R->dtm)) : 0;
    for (size_t i = 0; i < n; i++) {
        R->tmp[i] = a * R->q0[i] + c0 * R->p0[i];
        if (R->hist)
            R->tmp[i] += kq * (R->p0[i] / dt + (R->p0[i] - R->pm[i]) / R->dtm) / (dt + R->dtm);
    }
    c1 -= kq * A;
    adh_visco_extra_gap(w, R->tmp, R->e);
    double ceff = w->cinf + w->cdel * c1, h0 = w->seg.b0 + w->seg.bdot * tl;
    double h1 = w->seg.b0 + w->seg.bdot * (tl + dt);
    predict(w, dt, h0, h1);
    for (size_t i = 0; i < n; i++)
        R->tmp[i] += R->e[i];
    int rc = adh_static_solve_at(w->stat, ceff, R->e, R->tmp, h1, ROTHE_NEWTON_TOL, x);
    if (rc != ADH_SUCCESS && shortest) {
        /* no fold for a poor predictor's failure: the state itself, a
         * ten-thousandth of z0 away, predicts once more */
        for (size_t i = 0; i < n; i++)
            R->tmp[i] = R->u0[i] + R->e[i];
        rc = adh_static_solve_at(w->stat, ceff, R->e, R->tmp, h1, ROTHE_NEWTON_TOL, x);
    }
    count(w);
    if (rc != ADH_SUCCESS)
        return 2;
    int now = adh_contact_radius(w->g, (*x)->h, w->m.z0) > 0;
    double moved = 0;
    for (size_t i = 0; i < n; i++)
        moved = fmax(moved, fabs((*x)->u[i] - R->tmp[i]));
    /* the contact made or lost, or (in contact) the contact line snapped
     * a ring across a lattice fold, inside the step: halved, down to the
     * jump that IDAS crosses and counts */
    if (now != R->contact ? moved > ROTHE_JUMP_MOVE * w->m.z0 : R->hist && now && moved > ROTHE_SNAP_MOVE * w->m.z0)
        return 2;
    if (now != R->contact && fabs(h1 - h0) + (w->seg.bdot == 0 ? dt / tau * w->m.z0 : 0) > ROTHE_LOCATE * w->m.z0) {
        /* the contact made or lost smoothly: the step shortened to where
         * the gaps' minimum passes the contact's (secant), until it is
         * placed within ROTHE_LOCATE z0, as IDAS's root */
        double g0 = INFINITY, g1 = INFINITY;
        for (size_t i = 0; i < n; i++) {
            g0 = fmin(g0, h0 + R->r2R[i] - R->u0[i]);
            g1 = fmin(g1, (*x)->h[i]);
        }
        double f = (ADH_CONTACT_FACTOR * w->m.z0 - g0) / (g1 - g0);
        *err = isfinite(f) ? fmin(0.9, fmax(1e-3, f)) : 0.5;
        return 3;
    }
    R->next_contact = now;
    const double *p1 = (*x)->p;
    double num = 0, den = 0;
    for (size_t i = 0; i < n; i++) {
        R->q1[i] = a * R->q0[i] + c0 * R->p0[i] + c1 * p1[i];
        if (R->hist) {
            double pd = (R->p0[i] - R->pm[i]) / R->dtm;
            double c2 = ((p1[i] - R->p0[i]) / dt - pd) / (dt + R->dtm);
            R->q1[i] += kq * (R->p0[i] / dt + pd) / (dt + R->dtm);
            num += w->area[i] * fabs(ROTHE_ERR_SCALE * c2 * kq);
        }
        den += w->area[i] * fabs(p1[i]);
    }
    /* the floor: ROTHE_FLOOR times the adhesion's force scale 2 pi R dgamma */
    den += ROTHE_FLOOR * adh_material_gamma(&w->m) * 2 * M_PI * w->m.R;
    /* q's error moves u by cdel W dq against u's cinf W p + cdel W q:
     * none in an elastic solid (Einf = E0) */
    *err = num / den * w->cdel / (w->cinf + w->cdel);
    return *err > ADH_ROTHE_TOL_FACTOR * w->s.tol ? 1 : 0;
}

/* The accepted step into y (u, q, local time) and the accounts: the
 * base's work and the viscous dissipation, trapezoidal in time. */
/* The integral over the step of f (f0 at its start, f1 at its end, fm a
 * step before): the trapezoid, less the part of the quadratic through the
 * three (third order, as q's rule). A step before shorter than
 * ROTHE_QUAD_SHORT of this one gives the quadratic no slope it can trust
 * (its f differs from f0 by Newton's tolerance, or by nothing): the
 * trapezoid alone. A step of 1.65e-21 s that landed on the turn within
 * rounding had fm = f0, a slope of 0 there, and its quadratic took
 * (f1 - f0) dt / 6 off the next step's work: at 1 mm/s near elastic
 * (Einf = 3 E0, visco's sphere) the hysteresis came out 6.6 % above
 * IDAS's, its energy balance 6.3 % open (now 0.12 % and 0.16 %). */
#define ROTHE_QUAD_SHORT 1e-2

static double quad(const visco_rothe *R, double dt, double fm, double f0, double f1)
{
    double s = 0.5 * (f0 + f1) * dt;
    if (R->hist && R->dtm >= ROTHE_QUAD_SHORT * dt)
        s -= ((f1 - f0) / dt - (f0 - fm) / R->dtm) / (dt + R->dtm) * dt * dt * dt / 6.0;
    return s;
}

/* The force's scale under which its relative change is not asked:
 * ROTHE_FORCE_FLOOR times the adhesion's force 2 pi R dgamma */
static double force_floor(const adh_visco *w)
{
    return ROTHE_FORCE_FLOOR * 2 * M_PI * w->m.R * adh_material_gamma(&w->m);
}

/* The force's change from F0 to F1, relative to the larger or the floor. */
static double force_change(const adh_visco *w, double F0, double F1)
{
    return fabs(F1 - F0) / fmax(fmax(fabs(F0), fabs(F1)), force_floor(w));
}

/* The force's relative change a step is held to: (TOL_FACTOR tol)^(1/3),
 * so that its work's quadrature (third order) errs by TOL_FACTOR tol of it. */
static double force_kappa(const adh_visco *w)
{
    return cbrt(ADH_ROTHE_TOL_FACTOR * w->s.tol);
}

static void accept(adh_visco *w, double *y, double dt, const adh_state *x, int history)
{
    visco_rothe *R = w->ro;
    size_t n = w->n;
    double tl = y[w->IT], h0 = w->seg.b0 + w->seg.bdot * tl;
    memcpy(R->yback, y, w->len * sizeof *y);
    R->acc_back = w->acc;
    R->have_back = 1;
    if (history) {
        memcpy(R->pm, R->p0, n * sizeof *R->pm);
        memcpy(R->um, R->u0, n * sizeof *R->um);
        R->hprev = h0;
    }
    R->du = 0;
    for (size_t i = 0; i < n; i++) {
        R->du = fmax(R->du, fabs(x->u[i] - R->e[i] - R->u0[i]));
        R->u0[i] = x->u[i] - R->e[i];
        R->p0[i] = x->p[i];
    }
    memcpy(R->q0, R->q1, n * sizeof *R->q0);
    memcpy(y, R->u0, n * sizeof *y);
    memcpy(y + w->IQ, R->q0, n * sizeof *y);
    y[w->IT] = tl + dt;
    double h1 = x->h0;
    adh_visco_gaps(w, y, h1);
    double P1 = -adh_visco_force(w, h1) * w->seg.bdot, D1 = dissipation(w, R->p0, R->q0);
    R->dF = 0;
    if (w->seg.bdot != 0)   /* F recovered from the power P = -F bdot: not while the base is held */
        R->dF = force_change(w, -R->P0 / w->seg.bdot, -P1 / w->seg.bdot);
    w->acc.work += quad(R, dt, R->Pm, R->P0, P1);
    w->acc.dissipated += quad(R, dt, R->Dm, R->D0, D1);
    if (history) {
        R->Pm = R->P0, R->Dm = R->D0;
        R->dtm = dt;
        R->hist = 1;
    }
    R->P0 = P1, R->D0 = D1;
    R->contact = R->next_contact;
    w->stat0[0]++;
}

/* The first step after a (re)start has no step before to size it (its
 * length is ROTHE_DT_START tau or MOVE_MAX, whatever the tolerance): its
 * own force change is held to force_kappa, as the later steps' is by the
 * step before's (advance). Where a jump has just landed the force curves
 * hard (on contact, or just apart), and that one trapezoid of the work,
 * MOVE_MAX long at any tolerance, left the energy balance open by a
 * residual that did not fall with it: at 1 mm/s near elastic (Einf = 3 E0,
 * R = 1 um) 6.0e-20 J after the jump-in and 2.1e-20 J after the jump-out,
 * 0.7 % of the hysteresis, at tol 5e-5 to 1e-6 (docs/viscoelastic.md).
 * 1, and *grow the retry's factor, where it changed by more. */
static int first_too_long(adh_visco *w, double dt, double dt_min, const adh_state *x, double *grow)
{
    visco_rothe *R = w->ro;
    if (R->hist || w->seg.bdot == 0 || !(dt > dt_min))
        return 0;
    double F1 = adh_visco_tail(w, x->h0, NULL);
    for (size_t i = 0; i < w->n; i++)
        F1 += w->area[i] * x->p[i];
    double kap = force_kappa(w), dF = force_change(w, -R->P0 / w->seg.bdot, F1);
    if (!(dF > kap))
        return 0;
    *grow = fmax(0.2, 0.9 * kap / dF);
    return 1;
}

/* A step cut to land on a segment's end or a profile that is shorter
 * than ROTHE_QUAD_SHORT of the step it was cut from and of the step
 * before (at a turn, 1.65e-21 s: the end within rounding). */
static int sliver(const visco_rothe *R, double dt, int last)
{
    double ref = R->hist ? fmin(R->dt, R->dtm) : R->dt;
    return last && dt < ROTHE_QUAD_SHORT * ref;
}

int adh_visco_rothe_advance(adh_visco *w, double *y, double tl_end, int *hit)
{
    visco_rothe *R = w->ro;
    double tl = y[w->IT], v = fabs(w->seg.bdot);
    double dt_min = v > 0 ? ROTHE_DT_MIN * w->m.z0 / v : ROTHE_DT_MIN * w->v.tau;
    double dt_max = v > 0 ? ROTHE_MOVE_MAX * w->m.z0 / v : INFINITY;
    *hit = 0;
    for (;;) {
        if (w->s.cancel && *w->s.cancel)
            return ADH_EINTR;
        double left = tl_end - tl, dt = R->dt, err = 0;
        int last = dt >= left * (1 - 1e-9);
        if (last)
            dt = left;
        const adh_state *x = NULL;
        int rc = attempt(w, tl, dt, !(dt > dt_min), &err, &x);
        double grow = err > 0 ? 0.9 * pow(ADH_ROTHE_TOL_FACTOR * w->s.tol / err, 1.0 / 3.0) : 2.0;
        if (rc == 0 && first_too_long(w, dt, dt_min, x, &grow))
            rc = 1;
        if (rc == 0) {
            accept(w, y, dt, x, !sliver(R, dt, last));
            *hit = last;
            /* the next step: by the error's third order, never past DT_MAX;
             * a step cut to land on the segment's end does not shrink it */
            double nd = dt * fmin(2.0, fmax(0.2, grow));
            if (R->du > ROTHE_MOVE_MAX * w->m.z0)   /* the surface moves fast: rows as dense as the base's */
                nd = fmin(nd, dt * fmax(0.2, ROTHE_MOVE_MAX * w->m.z0 / R->du));
            /* the work's quadrature (third order) sees the force: its
             * relative change a step held to (TOL_FACTOR tol)^(1/3), so
             * a step's work to TOL_FACTOR tol of itself. Without it the
             * steps sat at MOVE_MAX where F changed 40 % a step, and at
             * 1 mm/s on sigma0 = 2.25 (10 E0) the hysteresis lay 1.8 %
             * below IDAS's at any tolerance */
            double kap = force_kappa(w);
            if (R->dF > kap)
                nd = fmin(nd, dt * fmax(0.2, kap / R->dF));
            R->dt = fmin(last ? fmax(nd, R->dt) : nd, dt_max);
            return ADH_SUCCESS;
        }
        w->stat0[4]++;
        if (rc == 3) {
            R->dt = dt * err * (1 - 1e-3);
            continue;
        }
        if (rc == 1) {
            R->dt = dt * fmax(0.2, grow);
            continue;
        }
        if (dt > dt_min) {
            R->dt = fmax(0.5 * dt, 0.999 * dt_min);
            continue;
        }
        R->dt = fmin(ROTHE_DT_START * w->v.tau, dt_max);
        return VISCO_ROTHE_JUMP;
    }
}


int adh_visco_rothe_back(adh_visco *w, double *y)
{
    visco_rothe *R = w->ro;
    if (!R || !R->have_back)
        return 0;
    memcpy(y, R->yback, w->len * sizeof *y);
    w->acc = R->acc_back;
    R->have_back = 0;
    return 1;
}

int adh_visco_rothe_land_out(adh_visco *w, double *y)
{
    visco_rothe *R = w->ro;
    size_t n = w->n;
    double h0 = adh_visco_h0_of(w, y);
    adh_visco_extra_gap(w, y + w->IQ, R->e);
    const adh_state *x = NULL;
    int rc = adh_static_solve_at(w->stat, w->cinf, R->e, R->e, h0, ROTHE_NEWTON_TOL, &x);
    count(w);
    if (rc != ADH_SUCCESS)
        return rc;
    if (adh_contact_radius(w->g, x->h, w->m.z0) > 0)
        return ADH_ESTALL;
    for (size_t i = 0; i < n; i++)
        y[i] = x->u[i] - R->e[i];
    return ADH_SUCCESS;
}
