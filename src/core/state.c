#include "adhere/state.h"

#include <stdlib.h>
#include <string.h>

adh_state *adh_state_alloc(size_t n)
{
    adh_state *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    /* One block for the three profiles: a snapshot is then a single memcpy. */
    s->u = calloc(3 * n, sizeof(double));
    if (!s->u) {
        free(s);
        return NULL;
    }
    s->h = s->u + n;
    s->p = s->u + 2 * n;
    s->n = n;
    return s;
}

void adh_state_free(adh_state *s)
{
    if (!s)
        return;
    free(s->u);
    free(s);
}

void adh_state_copy(adh_state *dst, const adh_state *src)
{
    dst->h0 = src->h0;
    dst->mix = src->mix;
    memcpy(dst->far, src->far, sizeof dst->far);
    memcpy(dst->u, src->u, 3 * src->n * sizeof(double));
}

void adh_state_swap_profiles(adh_state *a, adh_state *b)
{
    double *u = a->u, *h = a->h, *p = a->p;
    a->u = b->u, a->h = b->h, a->p = b->p;
    b->u = u, b->h = h, b->p = p;
}

adh_state *adh_state_clone(const adh_state *s)
{
    adh_state *c = adh_state_alloc(s->n);
    if (c)
        adh_state_copy(c, s);
    return c;
}
