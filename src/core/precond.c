#include "adhere/precond.h"
#include "adhere/status.h"

#include <stdlib.h>

/* The dispatch of adhere/precond.h; the implementations are
 * precond_dense.c and precond_hodlr.c. */
struct adh_precond {
    const adh_precond_type *type;
    void *state;
    size_t active;
    int det_sign;
};

adh_precond *adh_precond_alloc(const adh_precond_type *T, size_t n, adh_precond_entry_fn entry, void *ctx)
{
    return adh_precond_alloc_shared(T, n, entry, ctx, NULL);
}

adh_precond *adh_precond_alloc_shared(const adh_precond_type *T, size_t n, adh_precond_entry_fn entry, void *ctx,
                                      const double *entries)
{
    adh_precond *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    p->type = T;
    p->det_sign = 1;
    p->state = T->alloc(n, entry, ctx, entries);
    if (!p->state) {
        free(p);
        return NULL;
    }
    return p;
}

void adh_precond_free(adh_precond *p)
{
    if (!p)
        return;
    p->type->free(p->state);
    free(p);
}

int adh_precond_set(adh_precond *p, const adh_precond_system *sys)
{
    return p->type->set(p->state, sys, &p->active, &p->det_sign);
}

int adh_precond_border(adh_precond *p, const double *g, const double *nu, double nh)
{
    return p->type->border ? p->type->border(p->state, g, nu, nh) : ADH_SUCCESS;
}

void adh_precond_apply(adh_precond *p, const double *v, double *z)
{
    p->type->apply(p->state, v, z);
}

int adh_precond_det_sign(const adh_precond *p)
{
    return p->det_sign;
}

size_t adh_precond_active(const adh_precond *p)
{
    return p->active;
}

const adh_precond_type *adh_precond_type_of(const adh_precond *p)
{
    return p->type;
}

size_t adh_precond_bytes(const adh_precond *p)
{
    return p->type->bytes(p->state);
}
