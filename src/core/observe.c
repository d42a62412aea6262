#include "adhere/observe.h"

#include <math.h>

#include "adhere/law.h"
#include "adhere/models.h"
#include "adhere/rings.h"

/* From node i to node i + 1: dr on the uniform grid, kept exact there. */
static double node_gap(const adh_grid *g, size_t i)
{
    return g->graded ? g->r[i + 1] - g->r[i] : g->dr;
}

/* Beyond Rmax the surfaces are taken undeformed (u = 0): the gap is
 * s = h0 + r^2/2R, r dr = R ds, and the integral is eq 22's,
 * 2 pi R W(s) at the edge gap. The far-field deformation there is that of a
 * point force, u(r) = -2F/(pi E r), at most |u(Rmax)|; it changes the tail
 * by about 2|u(Rmax)| / s of itself, below 1e-5 in every shipped scene
 * (tested), while the tail itself is up to 2 % of the force before contact. */
double adh_force_tail(const adh_grid *g, const adh_material *m, double h0)
{
    double s = h0 + g->rmax * g->rmax / (2.0 * m->R);
    if (!(s > 0))
        return 0;
    return 2.0 * M_PI * m->R * adh_lj_energy(s, m->A, m->z0);
}

double adh_force(const adh_grid *g, const adh_material *m, const adh_state *s)
{
    /* eq 13 by the midpoint rule, which is also exact for the ring kernel's
     * piecewise-constant pressure: ring area pi(b^2 - a^2) = 2 pi r_n dr. */
    double sum = 0;
    if (g->graded) { /* the same: ring area pi(b^2 - a^2) = 2 pi r_n (b - a) */
        for (size_t i = 0; i < g->n; i++)
            sum += s->p[i] * adh_rings_weight(g, i);
        return 2.0 * M_PI * sum + adh_force_tail(g, m, s->h0);
    }
    for (size_t i = 0; i < g->n; i++)
        sum += s->p[i] * g->r[i];
    return 2.0 * M_PI * g->dr * sum + adh_force_tail(g, m, s->h0);
}

/* The outermost node in contact, so a contact that has lifted at the centre
 * under tension still reports its true edge. */
static long last_contact_node(const adh_grid *g, const double *h, double thr)
{
    for (long i = (long)g->n - 1; i >= 0; i--)
        if (h[i] < thr)
            return i;
    return -1;
}

double adh_contact_radius(const adh_grid *g, const double *h, double z0)
{
    double thr = ADH_CONTACT_FACTOR * z0;
    long i = last_contact_node(g, h, thr);
    if (i < 0)
        return 0;
    if ((size_t)i + 1 >= g->n)
        return g->rmax;
    double t = (thr - h[i]) / (h[i + 1] - h[i]);
    return g->r[i] + t * node_gap(g, (size_t)i);
}

double adh_contact_angle(const adh_grid *g, const double *h, double a)
{
    if (a <= 0)
        return 0;
    /* the first node past a: on the uniform grid round(a / dr) */
    size_t i = adh_rings_locate(g, a);
    if (i + 1 < g->n && a >= 0.5 * (g->r[i] + g->r[i + 1]))
        i++;
    /* Out from the edge the slope rises steeply, peaks, and falls to a
     * shallow minimum before the sphere's own curvature takes over: that
     * stationary slope is the "apparently linear" flank the paper measures. */
    double prev = 0;
    int past_peak = 0;
    for (; i + 1 < g->n; i++) {
        double s = (h[i + 1] - h[i]) / node_gap(g, i);
        if (!past_peak && s < prev && prev > 0)
            past_peak = 1;
        else if (past_peak && s > prev)
            return atan(prev);
        prev = s;
    }
    return atan(prev);
}

void adh_observe(const adh_grid *g, const adh_material *m, const adh_state *s, adh_obs *o)
{
    o->h0 = s->h0;
    o->F = adh_force(g, m, s);
    o->F_tail = adh_force_tail(g, m, s->h0);
    /* The first node sits at r = dr/2; u is even in r, so u(r) = u0 + c r^2
     * through the first two nodes gives u at the axis (eq 14 is at r = 0). */
    double u0 = g->n > 1 ? (9.0 * s->u[0] - s->u[1]) / 8.0 : s->u[0];
    o->delta = -u0;
    o->hc = s->h0 - u0;
    o->a = adh_contact_radius(g, s->h, m->z0);
    o->angle = adh_contact_angle(g, s->h, o->a);
    o->F_rigid = adh_rigid_force(m, s->h0);
    o->t = NAN;
    o->base = s->h0;
}
