#include "adhere/precond.h"
#include "adhere/hodlr.h"
#include "adhere/status.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The HODLR preconditioner (adhere/precond.h): J = I + alpha W diag(d)
 * whole, no truncation, factorized by adhere/hodlr.h; the border by block
 * elimination, det B = det J (nh - theta nu.J^-1 g). Applied, the u part
 * goes through J^-1 in single precision (half the memory traffic; its
 * error is far below the blocks' tolerance) and the border of the operator
 * being solved is eliminated exactly around it. */
#ifndef ADH_HODLR_TOL /* the blocks' relative tolerance (ACA) */
#define ADH_HODLR_TOL 1e-4
#endif
#ifndef ADH_HODLR_LEAF
#define ADH_HODLR_LEAF 64
#endif

typedef struct hodlr {
    size_t n;
    adh_hodlr *h;
    double *Jg;        /* J^-1 g at the point set */
    double *x2;        /* J^-1 g of the operator's border */
    const double *nu;  /* the operator's border row (borrowed, or nu0) */
    double *nu0;       /* the border row at the point set */
    double schur;      /* ... and its Schur complement nh - theta nu.x2 */
    double theta;
} hodlr;

static void hodlr_free(void *state)
{
    hodlr *P = state;
    if (!P)
        return;
    adh_hodlr_free(P->h);
    free(P->Jg);
    free(P);
}

static void *hodlr_alloc(size_t n, adh_precond_entry_fn entry, void *ctx, const double *entries)
{
    hodlr *P = calloc(1, sizeof *P);
    if (!P)
        return NULL;
    P->n = n;
    P->h = adh_hodlr_alloc(n, entry, ctx, ADH_HODLR_TOL, ADH_HODLR_LEAF);
    P->Jg = malloc(3 * n * sizeof *P->Jg);
    if (!P->h || !P->Jg) {
        hodlr_free(P);
        return NULL;
    }
    P->x2 = P->Jg + n;
    P->nu0 = P->x2 + n;
    return P;
}

static int hodlr_set(void *state, const adh_precond_system *sys, size_t *active, int *det_sign)
{
    hodlr *P = state;
    size_t n = P->n;
    double th = sys->theta;
    P->theta = th;
    *active = 0;
    int rc = adh_hodlr_factorize(P->h, sys->alpha, sys->d);
    if (rc != ADH_SUCCESS)
        return rc;
    memcpy(P->Jg, sys->g, n * sizeof *P->Jg);
    adh_hodlr_solve(P->h, P->Jg);
    double sc = sys->nh;
    for (size_t i = 0; i < n; i++)
        sc -= th * sys->nu[i] * P->Jg[i];
    if (sc == 0 || !isfinite(sc))
        return ADH_ESING;
    *active = n;
    *det_sign = adh_hodlr_det_sign(P->h) * (sc < 0 ? -1 : 1);
    /* until a border says otherwise, the operator's is the one set */
    memcpy(P->nu0, sys->nu, n * sizeof *P->nu0);
    memcpy(P->x2, P->Jg, n * sizeof *P->x2);
    P->nu = P->nu0;
    P->schur = sc;
    return ADH_SUCCESS;
}

static int hodlr_border(void *state, const double *g, const double *nu, double nh)
{
    hodlr *P = state;
    size_t n = P->n;
    memcpy(P->x2, g, n * sizeof *P->x2);
    adh_hodlr_solve_single(P->h, P->x2);
    double sc = nh;
    for (size_t i = 0; i < n; i++)
        sc -= P->theta * nu[i] * P->x2[i];
    if (sc == 0 || !isfinite(sc))
        return ADH_ESING;
    P->nu = nu;
    P->schur = sc;
    return ADH_SUCCESS;
}

static void hodlr_apply(void *state, const double *v, double *z)
{
    hodlr *P = state;
    size_t n = P->n;
    memcpy(z, v, n * sizeof *z);
    adh_hodlr_solve_single(P->h, z);
    double nd = 0;
    for (size_t i = 0; i < n; i++)
        nd += P->nu[i] * z[i];
    double dh = (v[n] - P->theta * nd) / P->schur;
    for (size_t i = 0; i < n; i++)
        z[i] -= P->x2[i] * dh;
    z[n] = dh;
}

static size_t hodlr_bytes(const void *state)
{
    const hodlr *P = state;
    return adh_hodlr_bytes(P->h) + 3 * P->n * sizeof *P->Jg;
}

static const adh_precond_type hodlr_type = {
    .name = "hodlr",
    .truncates = 0,
    .alloc = hodlr_alloc,
    .free = hodlr_free,
    .set = hodlr_set,
    .border = hodlr_border,
    .apply = hodlr_apply,
    .bytes = hodlr_bytes,
};

const adh_precond_type *adh_precond_hodlr = &hodlr_type;
