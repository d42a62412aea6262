/* The solid at rest at its start (adhere/visco.h): the state the run
 * begins from (visco.c's solve_start) and, before any run, whether a start
 * admits one (adh_visco_start_check), by the same arithmetic. */
#include "visco.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/observe.h"
#include "adhere/status.h"
#include "adhere/units.h"

#define VISCO_START_ITERS 400   /* the start's fixed-point iterations */

int adh_visco_rest(const adh_kernel *k, const adh_material *m, double c0, double h0, size_t n,
                   const visco_rest_buf *b)
{
    double du = INFINITY;
    memset(b->u, 0, n * sizeof *b->u);
    for (int it = 0; it < VISCO_START_ITERS && !(du < 1e-13 * m->z0); it++) {
        if (adh_visco_gaps_of(m, n, b->shape, b->u, h0, b->h, b->p) < 0)
            return VISCO_REST_TOUCH;
        for (size_t i = 0; i < n; i++)
            b->tmp[i] = c0 * b->p[i];
        adh_kernel_apply(k, b->tmp, b->tmp2, b->scratch);
        du = 0;
        for (size_t i = 0; i < n; i++) {
            du = fmax(du, fabs(-b->tmp2[i] - b->u[i]));
            b->u[i] = -b->tmp2[i];
        }
    }
    if (!(du < 1e-13 * m->z0))
        return VISCO_REST_UNSETTLED;
    if (adh_visco_gaps_of(m, n, b->shape, b->u, h0, b->h, b->p) < 0)
        return VISCO_REST_TOUCH;
    for (size_t i = 0; i < n; i++)
        if (b->h[i] < ADH_CONTACT_FACTOR * m->z0)
            return VISCO_REST_CONTACT;
    return 0;
}

/* The nearest start above h0, on its lattice h0 + j step, whose rest is
 * out of contact, by bisection over j up to the first at or above hi:
 * NAN when that one is not either. */
static double nearest_start(const adh_kernel *k, const adh_material *m, double c0, double h0, double hi,
                            double step, size_t n, const visco_rest_buf *b)
{
    double jlo = 0, jhi = ceil((hi - h0) / step);
    if (adh_visco_rest(k, m, c0, h0 + jhi * step, n, b) != 0)
        return NAN;
    while (jhi - jlo > 1) {   /* h0 + jlo step is not, h0 + jhi step is */
        double j = floor((jlo + jhi) / 2);
        if (adh_visco_rest(k, m, c0, h0 + j * step, n, b) == 0)
            jhi = j;
        else
            jlo = j;
    }
    return h0 + jhi * step;
}

int adh_visco_start_check(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_sls *v,
                          const adh_visco_drive *d, const adh_protocol_settings *ps, char *why, size_t whylen,
                          unsigned *fix)
{
    if (fix)
        *fix = 0;
    size_t n = g->n;
    adh_material m0 = *m;
    m0.E = v->E0;
    double step = ps->step > 0 ? ps->step : 0.05e-9;
    int spring = isfinite(d->spring);
    double automatic = adh_visco_auto_start(&m0, spring ? d->spring : INFINITY, step);
    double h0 = isnan(ps->start) ? automatic : ps->start;
    /* as adh_visco_set: c0 = c_inf + c_del, 2/E0 in its own rounding */
    double c0 = 2.0 / v->Einf + fmax(0.0, 2.0 * (1.0 / v->E0 - 1.0 / v->Einf));
    double *buf = malloc(7 * n * sizeof *buf);
    if (!buf) {
        if (why)
            snprintf(why, whylen, "out of memory for the start's rest state on %zu nodes", n);
        return ADH_ENOMEM;
    }
    double *shape = buf + 6 * n;   /* as adh_visco_set's */
    for (size_t i = 0; i < n; i++)
        shape[i] = g->r[i] * g->r[i] / (2.0 * m->R);
    visco_rest_buf b = { buf, buf + n, buf + 2 * n, buf + 3 * n, buf + 4 * n, buf + 5 * n, shape };
    int r = adh_visco_rest(k, &m0, c0, h0, n, &b);
    if (r == 0) {
        free(buf);
        return ADH_SUCCESS;
    }
    double hmin = INFINITY;
    for (size_t i = 0; r == VISCO_REST_CONTACT && i < n; i++)
        hmin = fmin(hmin, b.h[i]);
    double near = nearest_start(k, &m0, c0, h0, fmax(automatic, h0 + step), step, n, &b);
    free(buf);
    if (fix)
        *fix = ADH_FIX_START;
    if (!why)
        return ADH_EINVAL;
    char there[200], allowed[160] = "";
    if (r == VISCO_REST_CONTACT)
        snprintf(there, sizeof there, "there at rest its smallest gap is %s",
                 adh_qtext(hmin, ADH_Q_LENGTH).s);
    else if (r == VISCO_REST_TOUCH)
        snprintf(there, sizeof there, "there at rest the surfaces meet");
    else
        snprintf(there, sizeof there, "there no rest state settles (the surfaces are pulled into contact)");
    if (!isnan(near))
        snprintf(allowed, sizeof allowed, "; the nearest start that is, to within the step %s: %s",
                 adh_qtext(step, ADH_Q_LENGTH).s, adh_qtext(near, ADH_Q_LENGTH).s);
    snprintf(why, whylen, "start = %s is not allowed%s: a standard linear solid starts relaxed, at rest out of "
             "contact (every gap at least %.2g z0 = %s), and %s%s",
             adh_qtext(h0, ADH_Q_LENGTH).s, isnan(ps->start) ? " (the automatic one)" : "", ADH_CONTACT_FACTOR,
             adh_qtext(ADH_CONTACT_FACTOR * m->z0, ADH_Q_LENGTH).s, there, allowed);
    return ADH_EINVAL;
}
