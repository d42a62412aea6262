#include "adhere/history.h"

#include <stdlib.h>

#include "adhere/status.h"

struct adh_history {
    adh_drive_snap **snaps;   /* kept allocated past the cursor for reuse */
    size_t used;              /* entries that hold data (path + redoable) */
    size_t alloced;           /* snapshots allocated (>= used) */
    size_t cap;
    size_t len;               /* entries on the path: cursor + 1, 0 when empty */
};

adh_history *adh_history_alloc(void)
{
    return calloc(1, sizeof(adh_history));
}

void adh_history_free(adh_history *h)
{
    if (!h)
        return;
    for (size_t i = 0; i < h->alloced; i++)
        adh_drive_snap_free(h->snaps[i]);
    free(h->snaps);
    free(h);
}

int adh_history_push(adh_history *h, const adh_drive *d)
{
    size_t at = h->len;
    if (at == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 64;
        adh_drive_snap **s = realloc(h->snaps, cap * sizeof *s);
        if (!s)
            return ADH_ENOMEM;
        h->snaps = s;
        h->cap = cap;
    }
    /* Snapshots past the path are overwritten in place rather than freed:
     * undo a few steps and step again, and no allocation happens (unless
     * the grid changed under them). */
    if (at < h->alloced && adh_drive_snapshot(d, h->snaps[at]) == ADH_SUCCESS) {
        h->len = h->used = at + 1;
        return ADH_SUCCESS;
    }
    adh_drive_snap *s = adh_drive_snap_alloc(d);
    if (!s)
        return ADH_ENOMEM;
    if (at < h->alloced)
        adh_drive_snap_free(h->snaps[at]);
    else
        h->alloced++;
    h->snaps[at] = s;
    h->len = h->used = at + 1;
    return ADH_SUCCESS;
}

int adh_history_undo(adh_history *h, adh_drive *d)
{
    if (h->len <= 1 || adh_drive_restore(d, h->snaps[h->len - 2]) != ADH_SUCCESS)
        return ADH_EINVAL;
    h->len--;
    return ADH_SUCCESS;
}

int adh_history_redo(adh_history *h, adh_drive *d)
{
    if (h->len >= h->used || adh_drive_restore(d, h->snaps[h->len]) != ADH_SUCCESS)
        return ADH_EINVAL;
    h->len++;
    return ADH_SUCCESS;
}

int adh_history_restore(const adh_history *h, adh_drive *d)
{
    return h->len ? adh_drive_restore(d, h->snaps[h->len - 1]) : ADH_EINVAL;
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

const adh_state *adh_history_state_at(const adh_history *h, size_t i)
{
    return i < h->len ? adh_drive_snap_state(h->snaps[i]) : NULL;
}
