#include "adhere/relax.h"
#include "adhere/rings.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/law.h"
#include "adhere/status.h"
#include "adhere/units.h"

/* The per-node passes built for AVX2 and for the baseline, the loader
 * picking the CPU's (GCC's ifunc). Each node's arithmetic is the same in
 * both (no fused multiply-add: AVX2 has none), so they agree digit for
 * digit. */
/* Not under ThreadSanitizer: the ifunc resolver would run instrumented
 * before the sanitizer's runtime is up, and every run crashed at load. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && !defined(__SANITIZE_THREAD__)
#define ADH_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define ADH_SIMD_CLONES
#endif

/* Iterations between stiffness measurements (each one extra kernel
 * product); the restart catches a contact that stiffens in between. */
#define ADH_STIFFNESS_EVERY 32

struct adh_relax {
    const adh_grid *g;
    const adh_kernel *k;
    adh_material m;
    adh_relax_settings s;
    adh_state *st;
    adh_state *next;   /* an update's new u, h and p, written beside the
                          state's, whose place they take unless a gap closes */
    double *kp;        /* the kernel applied to the current pressure */
    int kp_fresh;      /* kp is the current pressure's: a move shifts u and
                          h0 and leaves h and p, so a step's first product
                          is its predecessor's last */
    double *unew;      /* eq 11's deformation less u: the unmixed change */
    double *scratch;
    double *shape;     /* r^2 / 2R, the undeformed sphere (eq 3) */
    double *vel;       /* momentum rule: the previous update u_k - u_(k-1) */
    double *vel_next;  /* and the new one, as next is to st */
    double *perron;    /* momentum rule: power-iteration vector of the stiffness */
    double *work;      /* momentum rule: |p'| x, then (2 N doubles) S x */
    double *ring_w;    /* eps's weight of each node (adh_relax_change_weights) */
    double eps_scale;  /* and its scale, sqrt(dr / D_ref) */
    /* The rings the measure adds beyond a grid short of the paper's radius
     * (adh_relax_far_rings): their weights in fine widths, the kernel rows
     * from the grid's pressure to their middles (node by node: n x
     * ADH_RELAX_FAR_RINGS, so one pass sums all rings at once), their change
     * and the momentum rule's update of them; their deformation is the
     * state's (adh_state.far). */
    size_t nfar;
    double far_w[ADH_RELAX_FAR_RINGS], far_du[ADH_RELAX_FAR_RINGS], far_vel[ADH_RELAX_FAR_RINGS];
    double *far_k;
    double stiffness;  /* upper bound on the largest eigenvalue of (2/E) W |p'| */
    size_t since_estimate;
    double best_change;   /* smallest change since the momentum last restarted */
    double damping;       /* momentum rule: part of the safe ratio in use, (0, 1] */
    double beta;          /* momentum rule: the beta in use (adh_relax_scaled_momentum) */
    double prev_central;  /* previous unmixed central change; 0 = none yet */
    double change;
    int converged;     /* the last pass found the step done */
    int shifted;       /* the last move changed h0 */
    double dscale;     /* |d| of the last move that changed h0: the scale of
                          the central test where u(0) passes through 0 */
    size_t iters;
    char why[240];     /* why the last iteration failed ("" when none did) */
};

adh_relax_settings adh_relax_settings_default(void)
{
    adh_relax_settings s = {
        .rule = ADH_MIX_MOMENTUM, .momentum = 0.55,
        .eps = 1e-12, .rtol = 1e-3, .mix_max = 0.2, .mix_min = 1e-4,
        .mix_down = 0.5, .mix_up = 1.05, .max_iter = 200000,
    };
    return s;
}

int adh_mix_rule_parse(const char *name, adh_mix_rule *rule)
{
    if (strcmp(name, "paper") == 0)
        *rule = ADH_MIX_PAPER;
    else if (strcmp(name, "momentum") == 0)
        *rule = ADH_MIX_MOMENTUM;
    else
        return ADH_EINVAL;
    return ADH_SUCCESS;
}

void adh_mix_rule_describe(const adh_relax_settings *s, char *buf, size_t len)
{
    if (s->rule == ADH_MIX_MOMENTUM)
        snprintf(buf, len, "momentum %g", s->momentum);
    else
        snprintf(buf, len, "paper");
}

int adh_relax_settings_validate(const adh_relax_settings *s, char *why, size_t whylen)
{
    if (!(isfinite(s->eps) && s->eps > 0 && s->eps < 1e-6)) {
        snprintf(why, whylen, "eps = %s is not allowed: it must be above 0 and below 1 um", adh_qtext(s->eps, ADH_Q_LENGTH).s);
        return ADH_EINVAL;
    }
    if (!(isfinite(s->rtol) && s->rtol > 0 && s->rtol < 1)) {
        snprintf(why, whylen, "rtol = %g is not allowed: it must be above 0 and below 1", s->rtol);
        return ADH_EINVAL;
    }
    if (!(s->mix_min > 0 && s->mix_min <= s->mix_max && s->mix_max <= 1)) {
        snprintf(why, whylen, "mixing ratios must satisfy 0 < min (%g) <= max (%g) <= 1", s->mix_min, s->mix_max);
        return ADH_EINVAL;
    }
    if (!(s->mix_down > 0 && s->mix_down < 1 && s->mix_up >= 1)) {
        snprintf(why, whylen, "mixing factors must satisfy 0 < down (%g) < 1 <= up (%g)", s->mix_down, s->mix_up);
        return ADH_EINVAL;
    }
    if (s->rule != ADH_MIX_PAPER && s->rule != ADH_MIX_MOMENTUM) {
        snprintf(why, whylen, "mixing rule %d is not allowed: paper or momentum", (int)s->rule);
        return ADH_EINVAL;
    }
    if (!(s->momentum >= 0 && s->momentum < 1)) {
        snprintf(why, whylen, "momentum = %g is not allowed: it must be at least 0 and below 1",
                 s->momentum);
        return ADH_EINVAL;
    }
    if (adh_relax_max_iter_check(s->max_iter > ADH_RELAX_MAX_ITER_CAP ? LONG_MAX : (long)s->max_iter, why, whylen) != ADH_SUCCESS)
        return ADH_EINVAL;
    return ADH_SUCCESS;
}

double adh_relax_eps_ref_spacing(const adh_material *m)
{
    return adh_grid_spacing_for(m, ADH_RELAX_EPS_NODES);
}

double adh_relax_change_weights(const adh_grid *g, const adh_material *m, double *wt)
{
    double ref = adh_relax_eps_ref_spacing(m), ratio = g->dr / ref;
    /* the paper's grid however its spacing was written down (1.5nm, or
     * scaled from R and z0): the paper's arithmetic, digit for digit */
    if (fabs(ratio - 1.0) < 1e-9 && !g->graded && g->n == ADH_RELAX_EPS_NODES) {
        adh_rings_change_weights(g, INFINITY, wt);
        return 1.0;
    }
    adh_rings_change_weights(g, (double)ADH_RELAX_EPS_NODES * ref, wt);
    return fabs(ratio - 1.0) < 1e-9 ? 1.0 : sqrt(ratio);
}

size_t adh_relax_far_rings(const adh_grid *g, const adh_material *m, double *r, double *w)
{
    double rref = (double)ADH_RELAX_EPS_NODES * adh_relax_eps_ref_spacing(m);
    if (!(g->rmax < rref * (1 - 1e-9)))
        return 0;
    /* geometric, finer near the grid where the change still bends */
    double q = pow(rref / g->rmax, 1.0 / ADH_RELAX_FAR_RINGS), a = g->rmax;
    for (size_t k = 0; k < ADH_RELAX_FAR_RINGS; k++) {
        double b = k + 1 == ADH_RELAX_FAR_RINGS ? rref : a * q;
        r[k] = 0.5 * (a + b);
        w[k] = b - a;
        a = b;
    }
    return ADH_RELAX_FAR_RINGS;
}

double adh_relax_measure(const adh_grid *g, const adh_material *m, const double *du, const double *du_far)
{
    double *wt = malloc(g->n * sizeof *wt), ssq = 0, fr[ADH_RELAX_FAR_RINGS], fw[ADH_RELAX_FAR_RINGS];
    if (!wt)
        return NAN;
    double scale = adh_relax_change_weights(g, m, wt);
    for (size_t i = 0; i < g->n; i++)
        ssq += wt[i] * du[i] * du[i];
    free(wt);
    size_t nfar = adh_relax_far_rings(g, m, fr, fw);
    for (size_t k = 0; k < nfar; k++)
        ssq += fw[k] / g->dr * du_far[k] * du_far[k];
    return sqrt(ssq) * scale / (double)ADH_RELAX_EPS_NODES;
}

double adh_relax_eps_floor(double depth)
{
    /* Rounding leaves du of order DBL_EPSILON |u| per node, times the few
     * dozen terms that matter in each kernel sum (measured: the floor sits
     * near 1e-23 m on the paper's grid with N = 200 and 1.5 nm deep, where
     * steps stop converging). Such a du on every ring has the norm of the
     * paper's radius, whatever the grid. */
    return 256.0 * DBL_EPSILON * fabs(depth) / sqrt((double)ADH_RELAX_EPS_NODES);
}

adh_relax *adh_relax_alloc(const adh_grid *g, const adh_kernel *k)
{
    adh_relax *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->g = g;
    w->k = k;
    w->st = adh_state_alloc(g->n);
    w->next = adh_state_alloc(g->n);
    w->unew = malloc(10 * g->n * sizeof(double));
    if (!w->st || !w->next || !w->unew) {
        adh_relax_free(w);
        return NULL;
    }
    w->scratch = w->unew + g->n;
    w->shape = w->unew + 2 * g->n;
    w->vel = w->unew + 3 * g->n;
    w->perron = w->unew + 4 * g->n;
    w->work = w->unew + 5 * g->n;
    w->ring_w = w->unew + 7 * g->n;
    w->vel_next = w->unew + 8 * g->n;
    w->kp = w->unew + 9 * g->n;
    w->far_k = malloc(ADH_RELAX_FAR_RINGS * g->n * sizeof *w->far_k);
    if (!w->far_k) {
        adh_relax_free(w);
        return NULL;
    }
    return w;
}

void adh_relax_free(adh_relax *w)
{
    if (!w)
        return;
    adh_state_free(w->st);
    adh_state_free(w->next);
    free(w->unew);
    free(w->far_k);
    free(w);
}

void adh_relax_refresh(adh_relax *w)
{
    adh_state *st = w->st;
    w->kp_fresh = 0;
    for (size_t i = 0; i < st->n; i++) {
        st->h[i] = st->h0 + w->shape[i] - st->u[i];
        st->p[i] = adh_lj_pressure(st->h[i], w->m.A, w->m.z0);
    }
}

/* Each drive step starts the momentum rule from rest, with a fresh power
 * vector: the iteration then depends on the state alone, so a restored
 * snapshot resumes exactly. */
static void momentum_reset(adh_relax *w)
{
    for (size_t i = 0; i < w->g->n; i++) {
        w->vel[i] = 0.0;
        w->perron[i] = 1.0;
    }
    for (size_t k = 0; k < ADH_RELAX_FAR_RINGS; k++)
        w->far_vel[k] = 0.0;
    w->stiffness = 0.0;
    w->damping = 1.0;
    w->beta = w->s.momentum;
    w->since_estimate = 0;
    w->best_change = INFINITY;
}

/* One power-iteration step on S = (2/E) W diag|p'(h)|, a matrix with no
 * negative entry: by Collatz-Wielandt max_i (S x)_i / x_i bounds its
 * spectral radius from above for any positive x, and the bound tightens as
 * x approaches the Perron vector. The linearised update's eigenvalues lie
 * within 1 +- that radius, so the bound gives the largest safe ratio. */
ADH_SIMD_CLONES static void stiffness_weights(double *x, const double *h, const double *perron, size_t n, double A,
                                              double z0)
{
#pragma omp simd
    for (size_t i = 0; i < n; i++)
        x[i] = fabs(adh_lj_dpressure(h[i], A, z0)) * perron[i];
}

/* y = scale sx, and the largest y / perron and y (as fmax would find them:
 * a NaN is passed over), in vectors */
ADH_SIMD_CLONES static void stiffness_bound(double *y, const double *sx, const double *perron, size_t n, double scale,
                                            double *bound, double *top)
{
    double b = 0, t = 0;
#pragma omp simd reduction(max : b, t)
    for (size_t i = 0; i < n; i++) {
        double v = scale * sx[i], q = v / perron[i];
        b = q > b ? q : b;
        t = v > t ? v : t;
        y[i] = v;
    }
    *bound = b;
    *top = t;
}

ADH_SIMD_CLONES static void perron_set(double *perron, const double *y, size_t n, double top)
{
#pragma omp simd
    for (size_t i = 0; i < n; i++) {
        double q = y[i] / top;
        perron[i] = q > 1e-300 ? q : 1e-300; /* fmax's, a NaN too */
    }
}

static void estimate_stiffness(adh_relax *w)
{
    size_t n = w->g->n;
    stiffness_weights(w->work, w->st->h, w->perron, n, w->m.A, w->m.z0);
    double *sx = w->work + n, bound, top;
    adh_kernel_apply(w->k, w->work, sx, w->scratch);
    stiffness_bound(w->work, sx, w->perron, n, 2.0 / w->m.E, &bound, &top);
    if (top > 0 && isfinite(top))
        perron_set(w->perron, w->work, n, top);
    w->stiffness = bound;
    w->since_estimate = 0;
}

/* The far rings of the measure (adh_relax_far_rings) for the material
 * set: their weights and kernel rows, the exact ring kernel from the
 * grid's rings (the far rings lie beyond them, where the paper's kernel
 * and the ring kernel agree to (dr/r)^2). */
static void far_set(adh_relax *w)
{
    double r[ADH_RELAX_FAR_RINGS], fw[ADH_RELAX_FAR_RINGS];
    const adh_grid *g = w->g;
    w->nfar = adh_relax_far_rings(g, &w->m, r, fw);
    for (size_t k = 0; k < w->nfar; k++) {
        w->far_w[k] = fw[k] / g->dr;
        double prev = 0;
        for (size_t j = 0; j < g->n; j++) {
            double next = adh_disk_integral(r[k], adh_rings_edge(g, j + 1));
            w->far_k[j * ADH_RELAX_FAR_RINGS + k] = next - prev;
            prev = next;
        }
    }
}

int adh_relax_set(adh_relax *w, const adh_material *m, const adh_relax_settings *s, double h0)
{
    w->m = *m;
    w->s = *s;
    w->eps_scale = adh_relax_change_weights(w->g, m, w->ring_w);
    far_set(w);
    for (size_t i = 0; i < w->g->n; i++) {
        w->shape[i] = w->g->r[i] * w->g->r[i] / (2.0 * m->R);
        w->st->u[i] = 0.0;
    }
    w->st->h0 = h0;
    w->st->mix = s->mix_max;
    for (size_t k = 0; k < ADH_STATE_FAR; k++)
        w->st->far[k] = 0.0;
    w->prev_central = 0;
    w->change = 0;
    w->why[0] = '\0';
    w->iters = 0;
    /* all that a previous run left: a workspace set again is a fresh one,
     * so a reused solver (the drive, the TUI) gives a fresh run's rows */
    w->converged = 0;
    w->shifted = 0;
    w->dscale = 0;
    adh_relax_refresh(w);
    momentum_reset(w);
    return ADH_SUCCESS;
}

void adh_relax_move(adh_relax *w, double h0_new)
{
    double shift = h0_new - w->st->h0;
    for (size_t i = 0; i < w->st->n; i++)
        w->st->u[i] += shift;
    for (size_t k = 0; k < w->nfar; k++)
        w->st->far[k] += shift;
    w->st->h0 = h0_new;
    w->shifted = shift != 0;
    if (shift != 0)
        w->dscale = fabs(shift);
    w->prev_central = 0;
    w->iters = 0;
    momentum_reset(w);
}

/* The slow modes move alpha mu / (1 - beta) = mu (1 + beta) / ((1 - beta)
 * (1 + s)) per iteration. A stiffer contact (a softer material: the bound
 * was 2 450 at Figure 4, 7 900 at sigma = 22.5, 33 000 at sigma = 75)
 * took 4-10x the paper's iterations per step with a fixed beta; holding
 * that move at its reference value keeps a step's iterations on the
 * paper's scale. The cap: past it the stiff modes' decay per iteration,
 * sqrt(beta) = 0.985, starts to be the slower one. */
double adh_relax_scaled_momentum(double beta, double s)
{
    double q = (1.0 + beta) / (1.0 - beta) * (1.0 + s) / (1.0 + ADH_RELAX_MOMENTUM_REF);
    if (beta == 0 || !(q > (1.0 + beta) / (1.0 - beta)))
        return beta;
    return fmax(beta, fmin(ADH_RELAX_MOMENTUM_MAX, (q - 1.0) / (q + 1.0)));
}

/* Heavy-ball mixing: u += v, v = beta v + alpha (u_new - u). For a linear
 * update with eigenvalues mu in (0, mu_max] it is stable while
 * alpha mu_max < 2 (1 + beta), and the slow modes (small mu: the contact
 * line creeping) move alpha / (1 - beta) per iteration instead of alpha;
 * with one ratio and no momentum the stiff contact modes (mu_max ~ 10^3)
 * hold everything to alpha < 2 / mu_max. alpha is half that limit,
 * (1 + beta) / (1 + bound) with the stiffness bound (1 + bound >= mu_max),
 * times a damping factor, and never above mix_max. The gap law is far from
 * linear: when the change grows past twice its smallest value since the
 * last restart, the momentum restarts from rest, the bound is measured
 * again and the damping falls (x mix_down); it recovers (x mix_up) on
 * every other iteration. */
static double momentum_ratio(adh_relax *w)
{
    if (w->stiffness == 0) {
        for (int k = 0; k < 3; k++)
            estimate_stiffness(w);
    } else if (++w->since_estimate >= ADH_STIFFNESS_EVERY) {
        estimate_stiffness(w);
    }
    if (w->change > 2.0 * w->best_change) {
        for (size_t i = 0; i < w->st->n; i++)
            w->vel[i] = 0.0;
        for (size_t k = 0; k < w->nfar; k++)
            w->far_vel[k] = 0.0;
        w->best_change = w->change;
        w->damping = fmax(1e-3, w->damping * w->s.mix_down);
        estimate_stiffness(w);
    } else {
        w->damping = fmin(1.0, w->damping * w->s.mix_up);
    }
    w->best_change = fmin(w->best_change, w->change);
    /* never lower within a step: in a jump the contact, and with it the
     * bound, shrinks while the slow mode (the surfaces springing apart) is
     * still the one to follow */
    w->beta = fmax(w->beta, adh_relax_scaled_momentum(w->s.momentum, w->stiffness));
    return fmin(w->s.mix_max, w->damping * (1.0 + w->beta) / (1.0 + w->stiffness));
}

/* The paper's rule: the ratio falls (x mix_down) when the unmixed change of
 * the central deformation changes sign (oscillation) or grows, and
 * otherwise rises (x mix_up) up to mix_max. */
static double paper_ratio(adh_relax *w)
{
    double c = w->unew[0];
    if (w->prev_central != 0) {
        if (c * w->prev_central < 0 || fabs(c) > fabs(w->prev_central))
            w->st->mix = fmax(w->s.mix_min, w->st->mix * w->s.mix_down);
        else
            w->st->mix = fmin(w->s.mix_max, w->st->mix * w->s.mix_up);
    }
    w->prev_central = c;
    return w->st->mix;
}

/* v = beta v + alpha (u_new - u), u += v, and h and p after them, for
 * every node into vn and next (the nodes are independent: the compiler runs
 * them in vectors, the divisions of p(h) four at a time under AVX2); 1
 * where a new gap closes (h <= 0, where the law has no meaning). One pass
 * that reads each node once: the new state is written beside the old,
 * which an update that closes a gap leaves as it was. */
ADH_SIMD_CLONES static int update_pass(double *restrict vn, adh_state *restrict next, const double *restrict vel,
                                       const adh_state *restrict st, const double *restrict unew,
                                       const double *restrict shape, double alpha, double beta, double A, double z0)
{
    size_t n = st->n;
    const double *restrict u = st->u;
    double *restrict un = next->u, *restrict hn = next->h, *restrict pn = next->p, h0 = st->h0;
    int closes = 0;
#pragma omp simd reduction(| : closes)
    for (size_t i = 0; i < n; i++) {
        double v = beta * vel[i] + alpha * unew[i], ui = u[i] + v, hi = h0 + shape[i] - ui;
        vn[i] = v;
        un[i] = ui;
        hn[i] = hi;
        pn[i] = adh_lj_pressure(hi, A, z0);
        closes |= !(hi > 0);
    }
    return closes;
}

/* the update, or 1 and nothing changed where a gap would close */
static int update(adh_relax *w, double alpha, double beta)
{
    if (update_pass(w->vel_next, w->next, w->vel, w->st, w->unew, w->shape, alpha, beta, w->m.A, w->m.z0))
        return 1;
    adh_state_swap_profiles(w->st, w->next);
    w->kp_fresh = 0;
    double *v = w->vel;
    w->vel = w->vel_next;
    w->vel_next = v;
    return 0;
}

/* The far rings' change, eq 11 at their middles from the grid's pressure
 * (scale = -2/E) less their deformation, into far_du; returns its part of
 * the measure's weighted sum. */
ADH_SIMD_CLONES static double far_change(adh_relax *w, double scale)
{
    size_t n = w->g->n;
    const double *p = w->st->p, *kt = w->far_k;
    /* ring by ring the sums would be chains of dependent additions: node
     * by node all eight rings advance at once, in registers and vectors */
    double t0 = 0, t1 = 0, t2 = 0, t3 = 0, t4 = 0, t5 = 0, t6 = 0, t7 = 0;
    for (size_t j = 0; j < n; j++) {
        const double *kr = kt + j * ADH_RELAX_FAR_RINGS;
        double pj = p[j];
        t0 += kr[0] * pj, t1 += kr[1] * pj, t2 += kr[2] * pj, t3 += kr[3] * pj;
        t4 += kr[4] * pj, t5 += kr[5] * pj, t6 += kr[6] * pj, t7 += kr[7] * pj;
    }
    double t[ADH_RELAX_FAR_RINGS] = { t0, t1, t2, t3, t4, t5, t6, t7 }, sum = 0;
    for (size_t k = 0; k < w->nfar; k++) {
        w->far_du[k] = scale * t[k] - w->st->far[k];
        sum += w->far_w[k] * w->far_du[k] * w->far_du[k];
    }
    return sum;
}

typedef double relax_v4 __attribute__((vector_size(4 * sizeof(double)), aligned(sizeof(double)), may_alias));

/* unew = scale kp - u (eq 11's deformation less u: the unmixed change du),
 * and the sums of du^2 and wt du^2, each in four interleaved parts (lane l
 * adds the nodes l, l + 4, ...; one chain of additions would bound this
 * pass by its latency) added as (0 + 1) + (2 + 3): in vectors, four lanes
 * at a time, the same additions in the same order as one at a time. */
ADH_SIMD_CLONES static void change_sums(double *unew, const double *kp, const double *u, const double *wt, size_t n,
                                        double scale, double *ssq, double *wssq)
{
    relax_v4 s = { 0, 0, 0, 0 }, ws = { 0, 0, 0, 0 };
    size_t k = 0;
    for (; k + 4 <= n; k += 4) {
        relax_v4 du = scale * *(const relax_v4 *)(kp + k) - *(const relax_v4 *)(u + k);
        *(relax_v4 *)(unew + k) = du;
        s += du * du;
        ws += *(const relax_v4 *)(wt + k) * du * du;
    }
    for (; k < n; k++) {
        double du = scale * kp[k] - u[k];
        unew[k] = du;
        s[0] += du * du;
        ws[0] += wt[k] * du * du;
    }
    *ssq = (s[0] + s[1]) + (s[2] + s[3]);
    *wssq = (ws[0] + ws[1]) + (ws[2] + ws[3]);
}

/* One pass of eq 11 with mixing: v = beta v + alpha (u_new - u), u += v,
 * with beta = 0 under the paper's rule. An update that would close the gap
 * somewhere (h <= 0, where the law has no meaning) is undone: the momentum
 * is dropped, then the ratio halved until it fits. */
static int relax_once(adh_relax *w)
{
    adh_state *st = w->st;
    size_t n = st->n;
    double scale = -2.0 / w->m.E;
    if (!w->kp_fresh)
        adh_kernel_apply(w->k, st->p, w->kp, w->scratch);
    w->kp_fresh = 1;
    double ssq, wssq;
    change_sums(w->unew, w->kp, st->u, w->ring_w, n, scale, &ssq, &wssq);
    if (w->nfar)
        wssq += far_change(w, scale);
    if (!isfinite(ssq)) {
        snprintf(w->why, sizeof w->why, "the relaxation at h0 = %s became non-finite after %zu iterations of its step",
                 adh_qtext(st->h0, ADH_Q_LENGTH).s, w->iters);
        return ADH_ENAN;
    }
    /* eps as the paper writes it on the paper's grid, [sum (u_new -
     * u_old)^2]^(1/2) / N with u_new the eq 11 deformation before it is
     * mixed in; on any other grid the same norm of the change over the
     * paper grid's radius (adh_relax_measure: the same product). */
    w->change = sqrt(wssq) * w->eps_scale / (double)ADH_RELAX_EPS_NODES;
    /* Converged: keep the state whose change was measured, not one more
     * mixed update of it. With momentum the state must also be at rest: a
     * small change while the last update was large is the state passing
     * through, as in the middle of a jump. At rest, the slow modes' update
     * is alpha / (1 - beta) times their change; twice that is allowed. */
    w->converged = w->change < w->s.eps;
    /* eps alone passes an unrelaxed shift wherever u is small: the step's
     * shift d counts as d / sqrt(1000) on every grid (1.6 pm at d = 0.05
     * nm: below a larger eps), and a bulge of a few pm is lost in it. The central
     * deformation (eq 14) must also have settled to rtol (1e-3) of itself plus
     * the step (in contact u(0) passes through 0 near h0 = z0). In
     * contact the centre is held by the stiff contact modes and settles long
     * before eps is met (its relative change is ~1e-5 there), so this never
     * binds and eps keeps the paper's meaning: the model's time. */
    if (w->converged) {
        double uc = st->u[0] + w->unew[0];
        w->converged = fabs(w->unew[0]) <= w->s.rtol * (fabs(uc) + w->dscale) + 1e-3 * w->s.eps;
    }
    /* and a shifted state is never its own answer: at least one iteration */
    if (w->converged && w->shifted && w->iters == 0)
        w->converged = 0;
    if (w->converged && w->s.rule == ADH_MIX_MOMENTUM) {
        double vsq = 0;
        for (size_t i = 0; i < n; i++)
            vsq += w->vel[i] * w->vel[i];
        w->converged = sqrt(vsq) <= 2.0 * st->mix * sqrt(ssq) / (1.0 - w->beta);
    }
    if (w->converged)
        return ADH_SUCCESS;

    int momentum = w->s.rule == ADH_MIX_MOMENTUM;
    double alpha = momentum ? momentum_ratio(w) : paper_ratio(w);
    double beta = momentum ? w->beta : 0.0;
    while (update(w, alpha, beta)) {
        if (beta > 0) {
            for (size_t i = 0; i < n; i++)
                w->vel[i] = 0.0;
            for (size_t f = 0; f < w->nfar; f++)
                w->far_vel[f] = 0.0;
            beta = 0;
            continue;
        }
        if (alpha <= w->s.mix_min) {
            st->mix = alpha;
            snprintf(w->why, sizeof w->why, "the relaxation at h0 = %s closed the gap (h <= 0) even at its smallest "
                     "mixing ratio, %g, after %zu iterations of its step", adh_qtext(st->h0, ADH_Q_LENGTH).s,
                     w->s.mix_min, w->iters);
            return ADH_ENAN;
        }
        alpha = fmax(w->s.mix_min, alpha * 0.5);
    }
    /* the far rings move as the grid's far nodes do */
    for (size_t f = 0; f < w->nfar; f++) {
        w->far_vel[f] = beta * w->far_vel[f] + alpha * w->far_du[f];
        st->far[f] += w->far_vel[f];
    }
    st->mix = alpha;
    return ADH_SUCCESS;
}

int adh_relax_iterate(adh_relax *w, size_t max_batch)
{
    for (size_t b = 0; max_batch == 0 || b < max_batch; b++) {
        if (w->iters >= w->s.max_iter)
            return ADH_EMAXITER;
        if (w->s.cancel && *w->s.cancel)
            return ADH_EINTR;
        int rc = relax_once(w);
        if (rc != ADH_SUCCESS)
            return rc;
        if (w->converged)
            return ADH_SUCCESS;
        w->iters++;
    }
    return ADH_CONTINUE;
}

const char *adh_relax_why(const adh_relax *w)
{
    return w->why;
}

int adh_relax_dwell(adh_relax *w, size_t n)
{
    /* A pause goes on relaxing even below eps: the time passes regardless. */
    double eps = w->s.eps;
    w->s.eps = 0;
    int rc = ADH_SUCCESS;
    for (size_t i = 0; i < n && rc == ADH_SUCCESS; i++)
        rc = w->s.cancel && *w->s.cancel ? ADH_EINTR : relax_once(w);
    w->s.eps = eps;
    return rc;
}

const adh_state *adh_relax_state(const adh_relax *w)
{
    return w->st;
}

void adh_relax_restore(adh_relax *w, const adh_state *s)
{
    double mix = w->st->mix;
    adh_state_copy(w->st, s);
    w->shifted = 0;
    if (!(w->st->mix > 0)) /* a state never relaxed carries no ratio */
        w->st->mix = mix;
    w->prev_central = 0;
    w->iters = 0;
    adh_relax_refresh(w);
    momentum_reset(w);
}

size_t adh_relax_step_iterations(const adh_relax *w)
{
    return w->iters;
}

double adh_relax_change(const adh_relax *w)
{
    return w->change;
}

double adh_relax_mixing(const adh_relax *w)
{
    return w->st->mix;
}

double adh_relax_momentum(const adh_relax *w)
{
    return w->beta;
}

double adh_relax_stiffness(const adh_relax *w)
{
    return w->stiffness;
}

int adh_relax_max_iter_check(long max_iter, char *why, size_t whylen)
{
    if (max_iter >= 1 && max_iter <= ADH_RELAX_MAX_ITER_CAP)
        return ADH_SUCCESS;
    snprintf(why, whylen, "max-iter = %ld is not allowed: the iteration cap must be from 1 to %d", max_iter,
             ADH_RELAX_MAX_ITER_CAP);
    return ADH_EINVAL;
}
