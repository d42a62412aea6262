/* The undo history: undo/redo restore exactly the pushed snapshots and rows,
 * a push after undo drops the redo tail, and the rows stay contiguous. */
#include <string.h>

#include "adhere/history.h"
#include "adhere/status.h"
#include "tap.h"

static void fill(adh_state *s, double h0)
{
    s->h0 = h0;
    for (size_t i = 0; i < s->n; i++) {
        s->u[i] = h0 * (double)(i + 1) / 3.0;   /* not exactly representable */
        s->h[i] = h0 + 1.0 / (double)(i + 7);
        s->p[i] = -h0 * 1e7 / (double)(i + 1);
    }
}

static int same_state(const adh_state *a, const adh_state *b)
{
    return a->n == b->n && a->h0 == b->h0 &&
           memcmp(a->u, b->u, 3 * a->n * sizeof(double)) == 0;
}

int main(void)
{
    const size_t n = 17;
    adh_history *h = adh_history_alloc(n);
    ok(h != NULL, "alloc");
    ok(adh_history_alloc(0) == NULL, "alloc of 0 nodes fails");
    ok(adh_history_length(h) == 0 && adh_history_state(h) == NULL && adh_history_row(h) == NULL,
       "empty history has no current entry");
    ok(adh_history_undo(h) == ADH_EINVAL && adh_history_redo(h) == ADH_EINVAL,
       "undo and redo on an empty history refuse");

    adh_state *s = adh_state_alloc(n), *ref[5];
    adh_obs row;
    for (int k = 0; k < 5; k++) {
        fill(s, 1e-9 * (10 - k));
        memset(&row, 0, sizeof row);
        row.h0 = s->h0;
        row.F = -1e-9 * k;
        row.iters = (size_t)(100 + k);
        ok(adh_history_push(h, s, &row) == ADH_SUCCESS, "push %d", k);
        ref[k] = adh_state_clone(s);
    }
    fill(s, 99);  /* the history must hold copies, not the caller's buffer */
    ok(adh_history_length(h) == 5 && adh_history_redoable(h) == 0, "5 entries, nothing to redo");
    ok(same_state(adh_history_state(h), ref[4]), "current is the last push");

    ok(adh_history_undo(h) == ADH_SUCCESS && adh_history_undo(h) == ADH_SUCCESS, "undo twice");
    ok(adh_history_length(h) == 3 && adh_history_redoable(h) == 2, "3 on the path, 2 to redo");
    ok(same_state(adh_history_state(h), ref[2]), "undo restores the third state bit for bit");
    ok(adh_history_row(h)->iters == 102 && adh_history_row(h)->F == -2e-9, "and its row");

    ok(same_state(adh_history_state_at(h, 0), ref[0]) && same_state(adh_history_state_at(h, 2), ref[2]),
       "state_at gives the states on the path");
    ok(adh_history_state_at(h, 3) == NULL, "state_at past the cursor is NULL (it is redoable, not on the path)");
    ok(adh_history_redo(h) == ADH_SUCCESS, "redo");
    ok(same_state(adh_history_state(h), ref[3]), "redo restores the fourth state bit for bit");
    ok(adh_history_redo(h) == ADH_SUCCESS && adh_history_redo(h) == ADH_EINVAL,
       "redo up to the end, then refuses");

    while (adh_history_undo(h) == ADH_SUCCESS)
        ;
    ok(adh_history_length(h) == 1 && same_state(adh_history_state(h), ref[0]),
       "undo stops at the first entry");

    /* A new step after undo forks the path: the redo tail is gone. */
    adh_history_redo(h);
    fill(s, 42e-9);
    row.h0 = s->h0;
    ok(adh_history_push(h, s, &row) == ADH_SUCCESS, "push after undo");
    ok(adh_history_length(h) == 3 && adh_history_redoable(h) == 0, "the push dropped the redo tail");
    ok(adh_history_state(h)->h0 == 42e-9, "current is the new push");
    const adh_obs *rows = adh_history_rows(h);
    ok(rows[0].h0 == ref[0]->h0 && rows[1].h0 == ref[1]->h0 && rows[2].h0 == 42e-9,
       "rows are the path in order");

    adh_state *wrong = adh_state_alloc(n + 1);
    ok(adh_history_push(h, wrong, &row) == ADH_EINVAL, "a state of the wrong size is refused");

    /* Enough pushes to force the arrays to grow, then check an early entry. */
    for (int k = 0; k < 300; k++) {
        fill(s, (double)k);
        row.h0 = (double)k;
        if (adh_history_push(h, s, &row) != ADH_SUCCESS)
            break;
    }
    ok(adh_history_length(h) == 303, "303 entries after growing");
    rows = adh_history_rows(h);
    ok(rows[1].h0 == ref[1]->h0 && rows[302].h0 == 299.0, "rows survive growth");

    adh_history_clear(h);
    ok(adh_history_length(h) == 0 && adh_history_redoable(h) == 0 && adh_history_state(h) == NULL,
       "clear empties it");

    for (int k = 0; k < 5; k++)
        adh_state_free(ref[k]);
    adh_state_free(s);
    adh_state_free(wrong);
    adh_history_free(h);
    adh_history_free(NULL);
    return tap_done();
}
