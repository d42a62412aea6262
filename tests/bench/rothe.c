/* A measured experiment, not a mode of adhere: the viscoelastic cycle of
 * issue 29 by a Rothe method (time discretised first, each time step a
 * static problem), against the static curve's time in this process and
 * against IDAS's cycle (adhere/visco.h) on the same grid and kernel.
 *
 * The solid: u = -W (cinf p + cdel q), tau q' = p - q. Over a step dt
 * (alpha = dt/tau) with p linear in time between its ends, q's equation
 * integrates exactly (an exponential integrator, second order):
 *     q1 = a q0 + c0 p0 + c1 p1,
 *     a = e^-alpha, c1 = 1 - (1 - a)/alpha, c0 = (1 - a)/alpha - a;
 * with p quadratic through the step before too (ORDER 3, the default) q1
 * gains -tau^2 k3 c2 (c2 the second divided difference of p, linear in p1;
 * k3 below), third order. Either way q1 = (known) + c1' p1, so
 * u1 = -W (ceff p1) - e, ceff = cinf + cdel c1', e = cdel W (known):
 * for v = u1 + e the static problem at the modulus 2/ceff with the extra
 * gap e, v + ceff W p(h0 + r^2/2R + e - v) = 0, at the drive's h0. It is
 * solved by the static solver's Newton-Krylov corrector (src/core/static.h,
 * its HODLR preconditioner, h0 held by the bordering row) from a predictor
 * extrapolating u linearly in time.
 *
 * The step's error: the linear rule's local error from p's curvature (the
 * quadratic through the last three p's against the linear one; with
 * ORDER 3 the step keeps the quadratic's q, a conservative estimate), in the norm the
 * force sees: sum_n 2 pi w_n |dq_n| over sum_n 2 pi w_n |p_n| (plus a
 * floor, the adhesion's force scale). A node the contact line crosses has
 * a kink in p: its estimate is large, but it weighs only its ring's area.
 *
 * Jumps: a step whose Newton fails, or that gains or loses the contact, is
 * halved, down to DT_MIN tau; there the sphere jumps at frozen q: a
 * jump-in lands by the static curve at Einf with the extra gap cdel W q
 * (as visco_land.c), a jump-out by Newton at Einf from v = 0.
 *
 * Usage: bench-rothe SIGMA TOL [IDAS_TOLS...]   (SIGMA 0: the Figure-4-like
 * cycle at N = 1000; each IDAS tolerance runs IDAS's cycle once; TOL the
 * Rothe step's tolerance, run at TOL and TOL/2; ROTHE_REFINE=1.5 in the
 * environment: the grid 1.5 times finer, the same radius and band). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/kernel.h"
#include "adhere/law.h"
#include "adhere/observe.h"
#include "adhere/rings.h"
#include "adhere/rule_visco.h"
#include "adhere/runner.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "adhere/visco.h"
#include "core/static.h"

void openblas_set_num_threads(int);

#define DT_MIN 1e-4   /* shortest step before a jump, in tau */
#define DT_MAX 2.0    /* longest, in tau */
#define JUMP_MOVE 0.5 /* a contact change moving a node this far (z0) from the predictor is a jump */
#ifndef FLOOR
#define FLOOR 1e-3 /* the error norm's floor, in 2 pi R dgamma (out of contact sum |p| is small) */
#endif
#ifndef ORDER
#define ORDER 3 /* 3: p quadratic through three steps; 2: linear over the step;
                   1: backward Euler on q (for the record) */
#endif
#define ORDER3 (ORDER == 3)
#ifndef ERR_SCALE
#define ERR_SCALE 2.0 /* the estimate's factor (its first runs: 2) */
#endif
#ifndef SHIFT
#define SHIFT 1 /* the predictor in the front's frame (0: linear in time) */
#endif
#define FRONT_GAP 1.5 /* the front: where the gap passes this, in z0 */
#ifndef NEWTON_TOL
#define NEWTON_TOL 1e-6 /* the step's Newton: max |G| below this, in z0 */
#endif

static double cpu_now(void)
{
    struct timespec c;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
    return (double)c.tv_sec + 1e-9 * (double)c.tv_nsec;
}

/* The cycle's phases: approach, loading in contact, unloading in
 * contact, apart after the jump-out. */
enum { PH_APPROACH, PH_LOAD, PH_UNLOAD, PH_APART, NPH };

typedef struct rothe_result {
    double pulloff, jump_in, jump_out, hyst, diss, cpu;
    size_t ph_steps[NPH];
    double ph_cpu[NPH];
    size_t steps, rejected, halved, newton, krylov, factor;
    int rc;
} rothe_result;

typedef struct rothe {
    const adh_grid *g;
    const adh_kernel *k;
    adh_static *S;
    adh_material m;     /* E = E0 */
    adh_sls v;
    size_t n;
    double cinf, cdel, tau, V, tol;
    double *area, *r2R, *scratch, *e, *tmp;
    double *u0, *q0, *p0, *pm, *um; /* now; p and u a step before */
    double *q1;
    double t, h0, F, dtm;           /* time, position, force; the last step */
    double hprev;                   /* h0 a step before */
    double *hc, *hp;                /* gap profiles now and a step before (the predictor's) */
    size_t nf;                      /* nodes of the uniform fine band */
    int hist;                       /* pm, um hold the step before */
    double h_start, h_turn, t_turn, t_end;
    int contact, unloading, next_contact;
    double Fm, hm, F2, h2;          /* the unloading's force two points back */
    int nun;                        /* unloading points so far */
    size_t newton, krylov, factor;  /* the static solver's counters before its last set */
} rothe;

static double h0_at(const rothe *R, double t)
{
    return t <= R->t_turn ? R->h_start - R->V * t : R->h_turn + R->V * (t - R->t_turn);
}

/* The static solver's problem: compliance c, extra gap e. */
static void set_problem(rothe *R, double c, const double *e)
{
    adh_static *S = R->S;
    S->c2E = c;
    S->m.E = 2.0 / c;
    for (size_t i = 0; i < R->n; i++)
        S->shape[i] = R->r2R[i] + (e ? e[i] : 0.0);
}

/* Newton at h0 from the predictor v (n) on the problem set; trial holds
 * the answer. */
static int newton_at(rothe *R, const double *v, double h0)
{
    adh_static *S = R->S;
    memcpy(S->trial->u, v, R->n * sizeof *v);
    S->trial->h0 = h0;
    memcpy(S->nw.upred, v, R->n * sizeof *v);
    S->nw.h0pred = h0;
    S->nw.attempt++;
    static_row row = { .kind = STATIC_ROW_PLANE, .nu = S->nw.zero, .nh = 1.0 };
    size_t its = 0;
    return static_correct(S, &row, &its);
}

/* The coefficients of q1 = a q0 + c0 p0 + c1 p1 over alpha, and the local
 * error's factor k3: dq = -p'' tau^2 k3 for p's second derivative p''
 * (twice the quadratic's leading coefficient: the quadratic's part
 * c2 s (s - dt) against the linear interpolation, c2 = p''/2). */
static void coeffs(double al, double *a, double *c0, double *c1, double *k3)
{
    double em = -expm1(-al), phi = em / al;
    *a = 1.0 - em;
    *c1 = 1.0 - phi;
    *c0 = phi - *a;
    if (al < 0.1) {   /* sum_k (-1)^k al^(k+3) / (k! (k+2) (k+3)) */
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

static double force_of(rothe *R, const adh_state *x)
{
    return adh_force(R->g, &R->m, x);
}

static double dissipation(rothe *R, const double *p, const double *q)
{
    for (size_t i = 0; i < R->n; i++)
        R->tmp[i] = p[i] - q[i];
    adh_kernel_apply(R->k, R->tmp, R->e, R->scratch);
    double s = 0;
    for (size_t i = 0; i < R->n; i++)
        s += R->area[i] * R->tmp[i] * R->e[i];
    return R->cdel / R->tau * s;
}

/* The frozen-q problem (compliance cinf, extra gap cdel W q0) into R->e. */
static void frozen(rothe *R)
{
    adh_kernel_apply(R->k, R->q0, R->e, R->scratch);
    for (size_t i = 0; i < R->n; i++)
        R->e[i] *= R->cdel;
}

/* The static solver's counters so far into R's (before a set clears them). */
static void count(rothe *R)
{
    adh_static_result sr;
    adh_static_summary(R->S, &sr);
    R->newton += sr.newton_iterations;
    R->krylov += sr.krylov_iterations;
    R->factor += sr.factorizations;
}

/* A jump at frozen q from the state now: ADH_SUCCESS with u0, p0 the
 * landing's. */
static int jump(rothe *R)
{
    adh_static *S = R->S;
    size_t n = R->n;
    frozen(R);
    int rc;
    if (!R->contact) {   /* in: the static curve at Einf with the extra gap, as visco_land.c */
        adh_material mi = R->m;
        mi.E = R->v.Einf;
        adh_static_settings ss = adh_static_settings_default();
        double below = 1e-4 * R->m.z0;
        rc = ADH_ESTALL;
        for (int k = 0; k < 3 && rc != ADH_SUCCESS; k++, below *= 10) {
            ss.h0_end = R->h0 - below;
            count(R);   /* set clears the solver's counters */
            adh_static_set_gap(S, R->e);
            rc = adh_static_set(S, &mi, &ss);
            if (rc == ADH_SUCCESS || rc == ADH_CONTINUE)
                while ((rc = adh_static_iterate(S)) == ADH_CONTINUE)
                    ;
            /* Rothe's last step (alpha = DT_MIN) was a little softer than
             * Einf: its fold lies a little above the frozen problem's, and
             * a curve ending between them has not jumped */
            if (rc == ADH_SUCCESS && !(adh_contact_radius(R->g, S->st->h, R->m.z0) > 0))
                rc = ADH_ESTALL;
        }
        adh_static_set_gap(S, NULL);
        S->s.tol = NEWTON_TOL;
        if (rc != ADH_SUCCESS) {
            fprintf(stderr, "jump-in landing's curve: %s %s\n", adh_strerror(rc), adh_static_why(S, NULL));
            return rc;
        }
        memcpy(R->tmp, S->st->u, n * sizeof *R->tmp);
    } else {
        memset(R->tmp, 0, n * sizeof *R->tmp);
    }
    set_problem(R, R->cinf, R->e);
    rc = newton_at(R, R->tmp, R->h0);
    if (rc != ADH_SUCCESS) {
        fprintf(stderr, "jump's Newton at h0 %g: %s\n", R->h0, adh_strerror(rc));
        return rc;
    }
    int now = adh_contact_radius(R->g, S->trial->h, R->m.z0) > 0;
    if (now == R->contact) {
        fprintf(stderr, "jump at h0 %g landed with contact %d\n", R->h0, now);
        return ADH_ESTALL;
    }
    for (size_t i = 0; i < n; i++) {
        R->u0[i] = S->trial->u[i] - R->e[i];
        R->p0[i] = S->trial->p[i];
    }
    R->contact = R->next_contact = now;
    R->F = force_of(R, S->trial);
    R->hist = 0;
    return ADH_SUCCESS;
}

/* The front: where the gap passes FRONT_GAP z0, between nodes (m); -1 none. */
static double front_of(const rothe *R, const double *h)
{
    double G = FRONT_GAP * R->m.z0;
    if (!(h[0] <= G))
        return -1;
    size_t e = 1;
    while (e < R->n && h[e] <= G)
        e++;
    if (e == R->n)
        return -1;
    const double *r = R->g->r;
    return r[e - 1] + (G - h[e - 1]) / (h[e] - h[e - 1]) * (r[e] - r[e - 1]);
}

/* h at radius x (linear between nodes; even in r). */
static double h_at(const rothe *R, const double *h, double x)
{
    const double *r = R->g->r;
    x = fabs(x);
    if (x <= r[0])
        return h[0];
    /* the fine band is uniform: the node below x at once there */
    size_t j = x < r[R->nf - 1] ? (size_t)((x - r[0]) / (r[1] - r[0])) : R->nf - 1;
    while (j + 1 < R->n && r[j + 1] < x)
        j++;
    if (j + 1 >= R->n)
        return h[R->n - 1];
    return h[j] + (h[j + 1] - h[j]) * (x - r[j]) / (r[j + 1] - r[j]);
}

/* The predictor's u at h1 into R->tmp: linear in time; in contact, in the
 * fine band, in the frame moving with the front (the last two gap
 * profiles shifted by the front's predicted move: a travelling front, as
 * the static curve's front steps predict). */
static void predict(rothe *R, double dt, double h1)
{
    size_t n = R->n;
    double f = R->hist ? dt / R->dtm : 0;
    for (size_t i = 0; i < n; i++)
        R->tmp[i] = R->u0[i] + f * (R->u0[i] - R->um[i]);
    if (!R->hist || !R->contact || !SHIFT)
        return;
    for (size_t i = 0; i < n; i++) {
        R->hc[i] = R->h0 + R->r2R[i] - R->u0[i];
        R->hp[i] = R->hprev + R->r2R[i] - R->um[i];
    }
    double a0 = front_of(R, R->hc), am = front_of(R, R->hp);
    if (a0 < 0 || am < 0)
        return;
    double a1 = a0 + f * (a0 - am);
    for (size_t i = 0; i < R->nf; i++) {
        double x = R->g->r[i];
        double hp = (1 + f) * h_at(R, R->hc, x - (a1 - a0)) - f * h_at(R, R->hp, x - (a1 - am));
        R->tmp[i] = h1 + R->r2R[i] - hp;
    }
}

/* One attempted step of dt: 0 accepted, 1 rejected by the error (dt
 * proposed in *dtn), 2 failed (Newton, or the contact changed). */
static int attempt(rothe *R, double dt, double *err)
{
    adh_static *S = R->S;
    size_t n = R->n;
    double al = dt / R->tau, a, c0, c1, k3, l[3] = { 0, 0, 0 };
    coeffs(al, &a, &c0, &c1, &k3);
    if (ORDER == 1) {   /* q1 = (q0 + alpha p1) / (1 + alpha); its error against the linear rule */
        l[0] = a, l[1] = c0, l[2] = c1;
        a = 1.0 / (1.0 + al), c0 = 0, c1 = al / (1.0 + al);
    }
    for (size_t i = 0; i < n; i++)
        R->tmp[i] = a * R->q0[i] + c0 * R->p0[i];
    /* third order: p quadratic through the step before too (q's part of
     * the quadratic, -tau^2 k3 c2 with c2 = A p1 + B_n the second divided
     * difference), the difference to the linear rule the error estimate */
    double A = 0, kq = R->tau * R->tau * k3;
    if (ORDER3 && R->hist) {
        A = 1.0 / (dt * (dt + R->dtm));
        for (size_t i = 0; i < n; i++)
            R->tmp[i] += kq * (R->p0[i] / dt + (R->p0[i] - R->pm[i]) / R->dtm) / (dt + R->dtm);
        c1 -= kq * A;
    }
    adh_kernel_apply(R->k, R->tmp, R->e, R->scratch);
    for (size_t i = 0; i < n; i++)
        R->e[i] *= R->cdel;
    double ceff = R->cinf + R->cdel * c1, h1 = h0_at(R, R->t + dt);
    set_problem(R, ceff, R->e);
    predict(R, dt, h1);
    for (size_t i = 0; i < n; i++)
        R->tmp[i] += R->e[i];
    if (newton_at(R, R->tmp, h1) != ADH_SUCCESS)
        return 2;
    /* a contact formed or lost far from the predictor is a jump (a
     * contact that forms smoothly, or a gap passing 1.1 z0 on the outer
     * branch, is none) */
    int now = adh_contact_radius(R->g, S->trial->h, R->m.z0) > 0;
    if (now != R->contact) {
        double moved = 0;
        for (size_t i = 0; i < n; i++)
            moved = fmax(moved, fabs(S->trial->u[i] - R->tmp[i]));
        if (moved > JUMP_MOVE * R->m.z0)
            return 2;
    }
    R->next_contact = now;
    const double *p1 = S->trial->p;
    double num = 0, den = 0;
    for (size_t i = 0; i < n; i++) {
        R->q1[i] = a * R->q0[i] + c0 * R->p0[i] + c1 * p1[i];
        if (R->hist) {
            double c2 = ((p1[i] - R->p0[i]) / dt - (R->p0[i] - R->pm[i]) / R->dtm) / (dt + R->dtm);
            if (ORDER3)
                R->q1[i] += kq * (R->p0[i] / dt + (R->p0[i] - R->pm[i]) / R->dtm) / (dt + R->dtm);
            if (ORDER > 1)
                num += R->area[i] * fabs(ERR_SCALE * c2 * kq);
        }
        if (ORDER == 1)
            num += R->area[i] * fabs(R->q1[i] - (l[0] * R->q0[i] + l[1] * R->p0[i] + l[2] * p1[i]));
        den += R->area[i] * fabs(p1[i]);
    }
    /* the floor: FLOOR times the adhesion's force scale 2 pi R dgamma, A R / 8 z0^2 */
    den += FLOOR * R->m.A / (16.0 * M_PI * R->m.z0 * R->m.z0) * 2 * M_PI * R->m.R;
    *err = num / den;
    return *err > R->tol ? 1 : 0;
}

/* The unloading's force minimum: the least point, or the parabola's
 * vertex through the three points around it. */
static void pulloff(rothe *R, rothe_result *res)
{
    double F1 = R->F, h1 = R->h0;
    if (F1 < res->pulloff)
        res->pulloff = F1;
    if (R->nun >= 2 && R->Fm < F1 && R->Fm < R->F2) {
        double a = R->h2, b = R->hm, c = h1, fa = R->F2, fb = R->Fm, fc = F1;
        double num = (b - a) * (b - a) * (fb - fc) - (b - c) * (b - c) * (fb - fa);
        double den = (b - a) * (fb - fc) - (b - c) * (fb - fa);
        if (den != 0) {
            double x = b - 0.5 * num / den;
            if (x > a && x < c) {
                double l0 = (x - b) * (x - c) / ((a - b) * (a - c)), l1 = (x - a) * (x - c) / ((b - a) * (b - c)),
                       l2 = (x - a) * (x - b) / ((c - a) * (c - b));
                double fx = l0 * fa + l1 * fb + l2 * fc;
                if (fx < res->pulloff)
                    res->pulloff = fx;
            }
        }
    }
    R->F2 = R->Fm, R->h2 = R->hm;
    R->Fm = F1, R->hm = h1;
    R->nun++;
}

static void accept(rothe *R, double dt, rothe_result *res, double *Dnow)
{
    adh_static *S = R->S;
    size_t n = R->n;
    double h1 = S->trial->h0, F1 = force_of(R, S->trial);
    res->hyst += -0.5 * (R->F + F1) * (h1 - R->h0);
    memcpy(R->pm, R->p0, n * sizeof *R->pm);
    memcpy(R->um, R->u0, n * sizeof *R->um);
    R->hprev = R->h0;
    for (size_t i = 0; i < n; i++) {
        R->u0[i] = S->trial->u[i] - R->e[i];
        R->p0[i] = S->trial->p[i];
    }
    memcpy(R->q0, R->q1, n * sizeof *R->q0);
    double D1 = dissipation(R, R->p0, R->q0);
    res->diss += 0.5 * (*Dnow + D1) * dt;
    *Dnow = D1;
    R->dtm = dt;
    R->hist = 1;
    R->t += dt;
    R->h0 = h1;
    R->F = F1;
    /* a contact formed or lost without a jump (a low sigma): where, as IDAS
     * records it */
    if (!R->contact && R->next_contact && isnan(res->jump_in))
        res->jump_in = h1;
    if (R->contact && !R->next_contact && R->unloading && isnan(res->jump_out)) {
        res->jump_out = h1;
        if (R->t + R->m.z0 / R->V > R->t_turn + (R->h_start - R->h_turn) / R->V)
            R->t_end = R->t + R->m.z0 / R->V;
    }
    R->contact = R->next_contact;
    if (R->unloading)
        pulloff(R, res);
    res->steps++;
}

static int cycle(rothe *R, rothe_result *res)
{
    size_t n = R->n;
    double Dnow = 0, dt = 1e-3 * R->tau;
    R->t = 0;
    R->h0 = R->h_start;
    R->contact = R->next_contact = 0;
    R->unloading = 0;
    R->nun = 0;
    R->hist = 0;
    /* the start: relaxed (q = p) at h_start, the static problem at E0 */
    set_problem(R, R->cinf + R->cdel, NULL);
    memset(R->tmp, 0, n * sizeof *R->tmp);
    if (newton_at(R, R->tmp, R->h0) != ADH_SUCCESS)
        return ADH_ESTALL;
    memcpy(R->u0, R->S->trial->u, n * sizeof *R->u0);
    memcpy(R->p0, R->S->trial->p, n * sizeof *R->p0);
    memcpy(R->q0, R->p0, n * sizeof *R->q0);
    R->F = force_of(R, R->S->trial);
    Dnow = 0;
    for (;;) {
        if (!(R->t < R->t_end * (1 - 1e-12))) {
            if (!R->contact || R->t_end > R->t_turn + (R->h_start - R->h_turn) / R->V)
                break;
            /* still in contact where the base started: on until apart, as
             * IDAS's cycle (at most R/50 further) */
            R->t_end += R->m.R / 50 / R->V;
        }
        double lim = R->t < R->t_turn ? R->t_turn : R->t_end;
        int last = dt >= lim - R->t;
        double step = last ? lim - R->t : dt, err = 0;
        int ph = !R->contact ? (R->unloading ? PH_APART : PH_APPROACH) : (R->unloading ? PH_UNLOAD : PH_LOAD);
        double c0 = cpu_now();
        int rc = attempt(R, step, &err);
        res->ph_cpu[ph] += cpu_now() - c0;
        res->ph_steps[ph]++;
        if (rc == 0) {
            accept(R, step, res, &Dnow);
            if (R->t >= R->t_turn * (1 - 1e-12))
                R->unloading = 1;
            double grow = err > 0 ? 0.9 * pow(R->tol / err, 1.0 / (ORDER == 1 ? 2 : 3)) : 2.0;
            dt = step * fmin(2.0, fmax(0.2, grow));
            dt = fmin(dt, DT_MAX * R->tau);
            continue;
        }
        if (rc == 1) {
            res->rejected++;
            dt = step * fmax(0.2, 0.9 * pow(R->tol / err, 1.0 / (ORDER == 1 ? 2 : 3)));
            continue;
        }
        res->halved++;
        if (step > DT_MIN * R->tau) {
            dt = 0.5 * step;
            continue;
        }
        /* a jump at frozen q */
        double hj = R->h0;
        int was = R->contact;
        if (jump(R) != ADH_SUCCESS)
            return ADH_ESTALL;
        if (!was)
            res->jump_in = hj;
        else if (R->unloading && isnan(res->jump_out)) {
            res->jump_out = hj;
            double te = R->t + R->m.z0 / R->V; /* as IDAS's cycle: a z0 past the contact's end */
            if (te > R->t_turn + (R->h_start - R->h_turn) / R->V)
                R->t_end = te;
        }
        Dnow = dissipation(R, R->p0, R->q0);
        R->nun = 0;
        dt = 1e-3 * R->tau;
    }
    return ADH_SUCCESS;
}

static int rothe_run(const adh_grid *g, const adh_kernel *k, const adh_material *m, double ratio, double tol,
                     rothe_result *res)
{
    memset(res, 0, sizeof *res);
    res->pulloff = INFINITY;
    res->jump_in = res->jump_out = NAN;
    double c0 = cpu_now();
    rothe R = { .g = g, .k = k, .m = *m, .n = g->n, .tol = tol };
    R.v.E0 = m->E;
    R.v.Einf = ratio * m->E;
    R.v.tau = 1e-3;
    R.tau = R.v.tau;
    R.V = 1e-6;
    R.cinf = 2.0 / R.v.Einf;
    R.cdel = 2.0 * (1.0 / R.v.E0 - 1.0 / R.v.Einf);
    adh_protocol_settings ps = adh_protocol_settings_default();
    R.h_start = adh_visco_auto_start(m, INFINITY, ps.step > 0 ? ps.step : 0.05e-9);
    R.h_turn = ps.turns[0];
    R.t_turn = (R.h_start - R.h_turn) / R.V;
    R.t_end = R.t_turn + (R.h_start - R.h_turn) / R.V;
    size_t n = R.n;
    double *buf = calloc(14 * n, sizeof *buf);
    R.S = adh_static_alloc(g, k);
    if (!buf || !R.S)
        return ADH_ENOMEM;
    double **bufs[] = { &R.area, &R.r2R, &R.scratch, &R.e, &R.tmp, &R.u0, &R.q0, &R.p0, &R.pm, &R.um, &R.q1, &R.hc, &R.hp };
    for (size_t i = 0; i < sizeof bufs / sizeof *bufs; i++)
        *bufs[i] = buf + i * n;
    double w0 = adh_rings_width(g, 0);
    R.nf = 1;
    while (R.nf < n && fabs(adh_rings_width(g, R.nf) - w0) < 1e-6 * w0)
        R.nf++;
    for (size_t i = 0; i < n; i++) {
        R.area[i] = 2.0 * M_PI * adh_rings_weight(g, i);
        R.r2R[i] = g->r[i] * g->r[i] / (2.0 * m->R);
    }
    /* the static solver, set once (its start point); then its corrector
     * is reused with the problem changed under it */
    adh_material mi = *m;
    mi.E = R.v.Einf;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_start = R.h_start;
    int rc = adh_static_set(R.S, &mi, &ss);
    R.S->s.tol = NEWTON_TOL;
    if (rc == ADH_SUCCESS || rc == ADH_CONTINUE)
        rc = cycle(&R, res);
    count(&R);
    res->newton = R.newton;
    res->krylov = R.krylov;
    res->factor = R.factor;
    res->cpu = cpu_now() - c0;
    res->rc = rc;
    if (rc != ADH_SUCCESS)
        printf("  Rothe stopped at t = %.6g s, h0 = %.6g m: %s\n", R.t, R.h0, adh_strerror(rc));
    adh_static_free(R.S);
    free(buf);
    return rc;
}

static double idas_run(const adh_grid *g, const adh_kernel *k, const adh_material *m, double ratio, double tol,
                       adh_visco_result *res)
{
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(m->E);
    vs.sls.Einf = ratio * m->E;
    vs.s.tol = tol;
    adh_protocol_settings ps = adh_protocol_settings_default();
    adh_run run;
    adh_run_init(&run);
    double c0 = cpu_now();
    adh_drive *d = adh_drive_alloc(&adh_rule_visco, g, k);
    int rc = d ? adh_drive_set(d, m, &vs, &ps, &run) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_runner_drive(d, NULL, NULL);
    double t = cpu_now() - c0;
    if (d)
        adh_visco_summary(adh_rule_visco_solver(d), res);
    if (rc != ADH_SUCCESS)
        printf("  IDAS failed: %s\n", adh_strerror(rc));
    adh_drive_free(d);
    adh_run_free(&run);
    return t;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bench-rothe SIGMA TOL [IDAS_TOL...]\n");
        return 2;
    }
    double sigma = atof(argv[1]), tol = atof(argv[2]);
    /* ROTHE_REFINE: the grid's spacing over this (the same radius and band) */
    const char *rf = getenv("ROTHE_REFINE");
    double refine = rf ? atof(rf) : 1;
    if (!(refine >= 1 && refine <= 4)) {
        fprintf(stderr, "bench-rothe: ROTHE_REFINE %s is not allowed: from 1 to 4\n", rf);
        return 2;
    }
    openblas_set_num_threads(1);
    adh_material m = adh_material_default();
    adh_grid *g;
    adh_kernel *k;
    double turn = adh_protocol_settings_default().turns[0];
    if (sigma > 0) {
        m.E *= adh_material_sigma(&m) / sigma;
        adh_rings_choice gc;
        char why[1024];
        if (adh_rings_choose(&m, ADH_GRID_STATIC, turn, 1, &gc, why, sizeof why, NULL) != ADH_SUCCESS) {
            printf("refused: %s\n", why);
            return 1;
        }
        if (gc.graded) {
            adh_rings_spec rs = { .dr = gc.dr / refine, .fine = gc.fine, .ratio = gc.ratio, .rmax = gc.rmax };
            g = adh_rings_alloc(&rs);
        } else {
            g = adh_grid_alloc((size_t)lround(gc.n * refine),
                               (isnan(gc.dr) ? adh_grid_spacing_for(&m, gc.n) : gc.dr) / refine);
        }
        adh_kernel_settings ks = { .type = gc.graded ? ADH_KERNEL_RING : ADH_KERNEL_PAPER,
                                   .storage = gc.hierarchical ? ADH_STORAGE_H2 : ADH_STORAGE_DENSE };
        k = adh_kernel_alloc(g, &ks, NULL);
    } else {   /* the Figure-4-like cycle, N = 1000, H^2 */
        m.E = 0.3e9;
        g = adh_grid_alloc((size_t)lround(1000 * refine), adh_grid_spacing_for(&m, 1000) / refine);
        k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER, .storage = ADH_STORAGE_H2 }, NULL);
    }
    double ratio = 10.0;
    printf("sigma = %g (E0 = %.3g Pa, Einf = %g E0, tau = 1 ms, 1 um/s), %zu nodes, spacing %.4g nm\n", sigma, m.E,
           ratio, g->n, g->dr * 1e9);
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_end = turn;
    adh_run run;
    adh_run_init(&run);
    adh_static_result sr;
    double c0 = cpu_now();
    int rc = adh_runner_static_curve(g, k, &m, &ss, NULL, NULL, &run, &sr);
    double ts = cpu_now() - c0;
    adh_run_free(&run);
    printf("static curve: %.2f CPU s (%zu points)%s\n", ts, sr.points, rc ? " FAILED" : "");
    fflush(stdout);
    for (int a = 3; a < argc; a++) {
        adh_visco_result vr;
        double t = idas_run(g, k, &m, ratio, atof(argv[a]), &vr);
        printf("IDAS tol %-8g %8.2f CPU s ratio %6.2f steps %5zu | pull-off %.6g N jump-in %.6g m jump-out %.6g m "
               "hysteresis %.6g J dissipated %.6g J\n",
               atof(argv[a]), t, t / ts, vr.steps, vr.pulloff_F, vr.jump_in_h0, vr.jump_out_h0, vr.hysteresis,
               vr.cycle.dissipated);
        fflush(stdout);
    }
    for (int j = 0; j < 2; j++, tol *= 0.5) {
        rothe_result r;
        rothe_run(g, k, &m, ratio, tol, &r);
        printf("Rothe tol %-7g %8.2f CPU s ratio %6.2f steps %5zu (rejected %zu, halved %zu; %zu Newton, %zu GMRES, "
               "%zu factorizations) | pull-off %.6g N jump-in %.6g m jump-out %.6g m hysteresis %.6g J "
               "dissipated %.6g J\n",
               tol, r.cpu, r.cpu / ts, r.steps, r.rejected, r.halved, r.newton, r.krylov, r.factor, r.pulloff,
               r.jump_in, r.jump_out, r.hyst, r.diss);
        printf("  attempts (CPU s): approach %zu (%.2f), loading in contact %zu (%.2f), unloading in contact %zu "
               "(%.2f), apart %zu (%.2f)\n",
               r.ph_steps[0], r.ph_cpu[0], r.ph_steps[1], r.ph_cpu[1], r.ph_steps[2], r.ph_cpu[2], r.ph_steps[3],
               r.ph_cpu[3]);
        fflush(stdout);
    }
    adh_kernel_free(k);
    adh_grid_free(g);
    return 0;
}
