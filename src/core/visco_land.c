/* A jump-in's landing by the static solver (adhere/static.h). At a fold
 * the sphere jumps far faster than tau and the drive: q, the time and the
 * base are frozen, and with q frozen the sphere is elastic at Einf with
 * the known extra deformation -cdel W q,
 *     u + W (cinf p(h0 + r^2/2R - u) + cdel q) = 0,
 * which for v = u + cdel W q is the static problem at Einf with the extra
 * gap e = cdel W q: v + cinf W p(h0 + r^2/2R + e - v) = 0. Its curve, from
 * the static mode's start outside the contact down to the fold's h0, goes
 * through the fold (the same one: the path's fold is where t' = 0 and q'
 * with it, the frozen problem's) and the S and lands on the branch that
 * holds there, as the crossing (visco_cross.c) does, but in the static
 * mode's steps: in a contact measure and whole rings of the contact line
 * on a large grid, stepping over the ladder of lattice folds the crossing
 * climbs ring by ring (measured at sigma = 75, 8893 rings: two crossings
 * of 1000 steps lost on it, then a relaxation of 1100 steps, 100 CPU s).
 * The curve ends a little below the fold's h0 (a curve that stopped on
 * the outer branch above its own fold has not jumped), and Newton puts
 * the landing on the equilibria at the fold's h0. Where any of it fails,
 * the crossing does the jump as before. */
#include "visco.h"

#include <math.h>
#include <string.h>

#include "adhere/observe.h"
#include "adhere/static.h"
#include "adhere/status.h"

/* The curve ends this many tolerances (of z0) below the fold's h0, ten
 * times more at each retry: the path's fold is placed within about the
 * tolerance, and above the static curve's own fold the curve would end on
 * the outer branch. */
#define LAND_BELOW 10.0
#define LAND_TRIES 3

/* The static curve at Einf with the extra gap w->egap, down to h0_end;
 * its last state's u (the static unknown v) into v. ADH_SUCCESS when it
 * passed a fold and ended in contact. */
static int land_curve(adh_visco *w, double h0_end, double *v)
{
    adh_material m = w->m;
    m.E = w->v.Einf;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_end = h0_end;
    ss.cancel = w->s.cancel;
    int rc = adh_static_set(w->stat, &m, &ss);
    if (rc == ADH_SUCCESS || rc == ADH_CONTINUE)
        while ((rc = adh_static_iterate(w->stat)) == ADH_CONTINUE)
            ;
    if (rc != ADH_SUCCESS)
        return rc;
    adh_static_result sr;
    adh_static_summary(w->stat, &sr);
    const adh_state *st = adh_static_state(w->stat);
    if (isnan(sr.jump_in_h0) || !(adh_contact_radius(w->g, st->h, w->m.z0) > 0))
        return ADH_ESTALL;
    memcpy(v, st->u, w->n * sizeof *v);
    return ADH_SUCCESS;
}

int adh_visco_land_static(adh_visco *w, double *y)
{
    size_t n = w->n;
    /* its preconditioner reads W where the path's holds it: a dense
     * kernel's N^2 entries are not copied a second time */
    if (!w->stat && !(w->stat = adh_static_alloc_shared(w->g, w->k, adh_visco_pre_entries(w->pre))))
        return ADH_ENOMEM;
    if (!w->egap && !(w->egap = malloc(n * sizeof *w->egap)))
        return ADH_ENOMEM;
    adh_visco_extra_gap(w, w->yfold + w->IQ, w->egap);
    if (adh_static_set_gap(w->stat, w->egap) != ADH_SUCCESS)
        return ADH_ENOMEM;
    double h0f = adh_visco_h0_of(w, w->yfold), below = LAND_BELOW * w->s.tol * w->m.z0;
    double *x = w->ywork;
    memcpy(x, w->yfold, w->len * sizeof *x);
    int rc = ADH_ESTALL;
    for (int k = 0; k < LAND_TRIES && rc != ADH_SUCCESS && rc != ADH_ENOMEM && rc != ADH_EINTR; k++, below *= 10)
        rc = land_curve(w, h0f - below, x);
    if (rc != ADH_SUCCESS)
        return rc;
    for (size_t i = 0; i < n; i++)
        x[i] -= w->egap[i];
    /* on the equilibria at the fold's h0, q and time */
    rc = adh_visco_polish(w, x, 1);
    w->p_mode = -1; /* the polish factorized the preconditioner for itself */
    if (rc != ADH_SUCCESS)
        return rc;
    double h0 = adh_visco_h0_of(w, x);
    if (adh_visco_gaps(w, x, h0) < 0 || !(adh_contact_radius(w->g, w->h, w->m.z0) > 0))
        return ADH_ESTALL;
    memcpy(y, x, w->len * sizeof *y);
    return ADH_SUCCESS;
}
