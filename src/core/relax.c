#include "adhere/relax.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/law.h"
#include "adhere/status.h"

struct adh_relax {
    const adh_grid *g;
    const adh_kernel *k;
    adh_material m;
    adh_relax_settings s;
    adh_state *st;
    double *unew;      /* eq 11 applied to the current pressure */
    double *scratch;
    double *shape;     /* r^2 / 2R, the undeformed sphere (eq 3) */
    double prev_central;  /* previous unmixed central change; 0 = none yet */
    double change;
    size_t iters;
};

adh_relax_settings adh_relax_settings_default(void)
{
    adh_relax_settings s = {
        .eps = 1e-12, .mix_max = 0.2, .mix_min = 1e-4,
        .mix_down = 0.5, .mix_up = 1.05, .max_iter = 200000,
    };
    return s;
}

int adh_relax_settings_validate(const adh_relax_settings *s, char *why, size_t whylen)
{
    if (!(isfinite(s->eps) && s->eps > 0 && s->eps < 1e-6)) {
        snprintf(why, whylen, "eps = %g m is not allowed: it must be above 0 and below 1e-6 m (1 um)", s->eps);
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
    if (s->max_iter < 1) {
        snprintf(why, whylen, "the iteration cap must be at least 1");
        return ADH_EINVAL;
    }
    return ADH_SUCCESS;
}

adh_relax *adh_relax_alloc(const adh_grid *g, const adh_kernel *k)
{
    adh_relax *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->g = g;
    w->k = k;
    w->st = adh_state_alloc(g->n);
    w->unew = malloc(3 * g->n * sizeof(double));
    if (!w->st || !w->unew) {
        adh_relax_free(w);
        return NULL;
    }
    w->scratch = w->unew + g->n;
    w->shape = w->unew + 2 * g->n;
    return w;
}

void adh_relax_free(adh_relax *w)
{
    if (!w)
        return;
    adh_state_free(w->st);
    free(w->unew);
    free(w);
}

void adh_relax_refresh(adh_relax *w)
{
    adh_state *st = w->st;
    for (size_t i = 0; i < st->n; i++) {
        st->h[i] = st->h0 + w->shape[i] - st->u[i];
        st->p[i] = adh_lj_pressure(st->h[i], w->m.A, w->m.z0);
    }
}

int adh_relax_set(adh_relax *w, const adh_material *m, const adh_relax_settings *s, double h0)
{
    w->m = *m;
    w->s = *s;
    for (size_t i = 0; i < w->g->n; i++) {
        w->shape[i] = w->g->r[i] * w->g->r[i] / (2.0 * m->R);
        w->st->u[i] = 0.0;
    }
    w->st->h0 = h0;
    w->st->mix = s->mix_max;
    w->prev_central = 0;
    w->change = 0;
    w->iters = 0;
    adh_relax_refresh(w);
    return ADH_SUCCESS;
}

void adh_relax_move(adh_relax *w, double h0_new)
{
    double shift = h0_new - w->st->h0;
    for (size_t i = 0; i < w->st->n; i++)
        w->st->u[i] += shift;
    w->st->h0 = h0_new;
    w->prev_central = 0;
    w->iters = 0;
}

/* One pass of eq 11 with mixing. The mixing rule is the paper's: the ratio
 * falls (x mix_down) when the unmixed change of the central deformation
 * changes sign (oscillation) or grows, and otherwise rises (x mix_up) up to
 * mix_max. A mixed update that would close the gap somewhere (h <= 0, where
 * the law has no meaning) is undone and retried with half the ratio. */
static int relax_once(adh_relax *w)
{
    adh_state *st = w->st;
    size_t n = st->n;
    double scale = -2.0 / w->m.E;
    adh_kernel_apply(w->k, st->p, w->unew, w->scratch);
    double ssq = 0;
    for (size_t i = 0; i < n; i++) {
        w->unew[i] = scale * w->unew[i] - st->u[i]; /* now the unmixed change */
        ssq += w->unew[i] * w->unew[i];
    }
    if (!isfinite(ssq))
        return ADH_ENAN;
    /* eps as the paper writes it: [sum (u_new - u_old)^2]^(1/2) / N, with
     * u_new the eq 11 deformation before it is mixed in. */
    w->change = sqrt(ssq) / (double)n;
    /* Converged: keep the state whose change was measured, not one more
     * mixed update of it. */
    if (w->change < w->s.eps)
        return ADH_SUCCESS;

    double c = w->unew[0];
    if (w->prev_central != 0) {
        if (c * w->prev_central < 0 || fabs(c) > fabs(w->prev_central))
            w->st->mix = fmax(w->s.mix_min, w->st->mix * w->s.mix_down);
        else
            w->st->mix = fmin(w->s.mix_max, w->st->mix * w->s.mix_up);
    }
    w->prev_central = c;

    for (;;) {
        int closed = 0;
        for (size_t i = 0; i < n; i++) {
            double u = st->u[i] + w->st->mix * w->unew[i];
            double h = st->h0 + w->shape[i] - u;
            if (!(h > 0)) {
                closed = 1;
                break;
            }
        }
        if (!closed)
            break;
        if (w->st->mix <= w->s.mix_min)
            return ADH_ENAN;
        w->st->mix = fmax(w->s.mix_min, w->st->mix * 0.5);
    }
    for (size_t i = 0; i < n; i++) {
        st->u[i] += w->st->mix * w->unew[i];
        st->h[i] = st->h0 + w->shape[i] - st->u[i];
        st->p[i] = adh_lj_pressure(st->h[i], w->m.A, w->m.z0);
    }
    return ADH_SUCCESS;
}

int adh_relax_iterate(adh_relax *w, size_t max_batch)
{
    for (size_t b = 0; max_batch == 0 || b < max_batch; b++) {
        if (w->iters >= w->s.max_iter)
            return ADH_EMAXITER;
        int rc = relax_once(w);
        if (rc != ADH_SUCCESS)
            return rc;
        if (w->change < w->s.eps)
            return ADH_SUCCESS;
        w->iters++;
    }
    return ADH_CONTINUE;
}

int adh_relax_dwell(adh_relax *w, size_t n)
{
    /* A pause goes on relaxing even below eps: the time passes regardless. */
    double eps = w->s.eps;
    w->s.eps = 0;
    int rc = ADH_SUCCESS;
    for (size_t i = 0; i < n && rc == ADH_SUCCESS; i++)
        rc = relax_once(w);
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
    if (!(w->st->mix > 0)) /* a state never relaxed carries no ratio */
        w->st->mix = mix;
    w->prev_central = 0;
    w->iters = 0;
    adh_relax_refresh(w);
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
