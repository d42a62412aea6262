#include "adhere/history.h"

#include <stdlib.h>

#include "adhere/status.h"

struct adh_history {
    size_t n;           /* nodes per state */
    adh_state **snaps;  /* snapshots kept allocated past the cursor for reuse */
    adh_obs *rows;      /* parallel to snaps, contiguous for adh_history_rows */
    size_t used;        /* entries that hold data (path + redoable) */
    size_t alloced;     /* snapshots allocated (>= used) */
    size_t cap;         /* capacity of the two arrays */
    size_t len;         /* entries on the path: cursor + 1, 0 when empty */
};

adh_history *adh_history_alloc(size_t n)
{
    if (n == 0)
        return NULL;
    adh_history *h = calloc(1, sizeof *h);
    if (h)
        h->n = n;
    return h;
}

void adh_history_free(adh_history *h)
{
    if (!h)
        return;
    for (size_t i = 0; i < h->alloced; i++)
        adh_state_free(h->snaps[i]);
    free(h->snaps);
    free(h->rows);
    free(h);
}

static int grow(adh_history *h)
{
    size_t cap = h->cap ? 2 * h->cap : 64;
    adh_state **s = realloc(h->snaps, cap * sizeof *s);
    if (!s)
        return ADH_ENOMEM;
    h->snaps = s;
    adh_obs *r = realloc(h->rows, cap * sizeof *r);
    if (!r)
        return ADH_ENOMEM;
    h->rows = r;
    h->cap = cap;
    return ADH_SUCCESS;
}

int adh_history_push(adh_history *h, const adh_state *s, const adh_obs *row)
{
    if (s->n != h->n)
        return ADH_EINVAL;
    size_t at = h->len;
    if (at == h->cap && grow(h) != ADH_SUCCESS)
        return ADH_ENOMEM;
    /* Snapshots past the path are overwritten in place rather than freed:
     * undo a few steps and step again, and no allocation happens. */
    if (at == h->alloced) {
        h->snaps[at] = adh_state_alloc(h->n);
        if (!h->snaps[at])
            return ADH_ENOMEM;
        h->alloced++;
    }
    adh_state_copy(h->snaps[at], s);
    h->rows[at] = *row;
    h->len = at + 1;
    h->used = h->len;
    return ADH_SUCCESS;
}

int adh_history_undo(adh_history *h)
{
    if (h->len <= 1)
        return ADH_EINVAL;
    h->len--;
    return ADH_SUCCESS;
}

int adh_history_redo(adh_history *h)
{
    if (h->len >= h->used)
        return ADH_EINVAL;
    h->len++;
    return ADH_SUCCESS;
}

void adh_history_clear(adh_history *h)
{
    h->len = 0;
    h->used = 0;
}

size_t adh_history_length(const adh_history *h)
{
    return h->len;
}

size_t adh_history_redoable(const adh_history *h)
{
    return h->used - h->len;
}

const adh_state *adh_history_state(const adh_history *h)
{
    return h->len ? h->snaps[h->len - 1] : NULL;
}

const adh_state *adh_history_state_at(const adh_history *h, size_t i)
{
    return i < h->len ? h->snaps[i] : NULL;
}

const adh_obs *adh_history_row(const adh_history *h)
{
    return h->len ? &h->rows[h->len - 1] : NULL;
}

const adh_obs *adh_history_rows(const adh_history *h)
{
    return h->rows;
}
