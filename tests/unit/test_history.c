/* The undo history of a drive: undo and redo put the drive and its run back
 * exactly (rows, turns, state), a step after an undo gives the row it gave
 * before, a push after undo drops the redo tail, the first entry is never
 * undone; and steps by hand (the TUI's f and b) turn, unload and load again
 * on the protocol's lattices. */
#include <math.h>
#include <string.h>

#include "adhere/history.h"
#include "adhere/status.h"
#include "tap.h"

static int same_row(const adh_obs *a, const adh_obs *b)
{
    return a->h0 == b->h0 && a->F == b->F && a->a == b->a && a->iters == b->iters && a->branch == b->branch &&
           a->path == b->path;
}

static int step_hand(adh_drive *d, int dir)
{
    if (adh_drive_hand(d, dir) != ADH_SUCCESS)
        return ADH_EINVAL;
    int rc, row;
    while ((rc = adh_drive_iterate(d, 0, &row)) == ADH_CONTINUE && adh_drive_pending(d))
        ;
    return rc;
}

int main(void)
{
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(100, 10e-9);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_relax_settings rs = adh_relax_settings_default();
    rs.eps = 10e-12;
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.step = 0.25e-9;
    ps.nturns = 1;
    ps.turns[0] = -1e-9;
    adh_drive *d = adh_drive_alloc(&adh_rule_relax, g, k);
    adh_run run;
    adh_run_init(&run);
    adh_history *h = adh_history_alloc();
    ok(h && d && adh_drive_set(d, &m, &rs, &ps, &run) == ADH_SUCCESS, "alloc and set");
    ok(adh_history_length(h) == 0 && adh_history_undo(h, d) == ADH_EINVAL && adh_history_redo(h, d) == ADH_EINVAL,
       "an empty history has nothing to undo or redo");

    /* the first f: the start, then one step in */
    ok(step_hand(d, +1) == ADH_CONTINUE && run.nrows == 2 && run.rows[1].h0 == run.start - ps.step,
       "the first step by hand solves the start, then approaches by d");
    double start = run.start;
    /* one entry per row, as the TUI keeps them */
    adh_history_push(h, d);
    int rc = ADH_CONTINUE;
    while (rc == ADH_CONTINUE && !(adh_drive_events(d) & ADH_DRIVE_TURN)) {
        rc = step_hand(d, +1);
        adh_history_push(h, d);
    }
    ok(rc == ADH_CONTINUE && run.rows[run.nrows - 1].h0 == -1e-9 && run.nturns == 1,
       "approaching by hand hits the turn exactly and records it (%zu rows)", run.nrows);
    size_t nturn = run.nrows;
    for (int i = 0; i < 6; i++) {
        rc = step_hand(d, -1);
        adh_history_push(h, d);
    }
    const adh_obs *o = &run.rows[run.nrows - 1];
    ok(rc == ADH_CONTINUE && o->branch < 0 && o->path == 1 && fabs(o->h0 - (-1e-9 + 6 * ps.step)) < 1e-18 &&
       run.turns[0].path == 1 && run.nturns == 1,
       "retracting from the turn unloads that turn, by d from it (h0 %g)", o->h0);
    ok(!isnan(run.turns[0].pulloff_F) && run.turns[0].pulloff_F <= run.rows[nturn].F,
       "the branch's pull-off is tracked from its first row");

    adh_obs last = *o;
    size_t n = run.nrows;
    size_t t;
    ok(adh_drive_next(d, &t) == -1 && t == 1, "the drive says its next step unloads turn 1");
    ok(adh_history_undo(h, d) == ADH_SUCCESS && adh_history_undo(h, d) == ADH_SUCCESS && run.nrows == n - 2,
       "two undos cut the run back two rows");
    ok(adh_history_redoable(h) == 2 && adh_history_redo(h, d) == ADH_SUCCESS && run.nrows == n - 1,
       "redo puts a row back");
    ok(adh_history_redo(h, d) == ADH_SUCCESS && run.nrows == n && same_row(&run.rows[n - 1], &last) &&
       adh_history_redo(h, d) == ADH_EINVAL, "and the last, as it was; nothing more to redo");
    adh_history_undo(h, d);
    ok(step_hand(d, -1) == ADH_CONTINUE && same_row(&run.rows[n - 1], &last),
       "undo, then the same step again: the same row, bit for bit");
    adh_history_push(h, d);
    ok(adh_history_redoable(h) == 0, "a push drops what could be redone");

    /* approach again from the unloading branch, then retract: a new turn */
    ok(step_hand(d, +1) == ADH_CONTINUE && run.rows[run.nrows - 1].branch > 0 && run.rows[run.nrows - 1].path == 0 &&
       fabs(run.rows[run.nrows - 1].h0 - (last.h0 - ps.step)) < 1e-18,
       "approaching from the unloading branch loads again on the lattice");
    adh_history_push(h, d);
    ok(step_hand(d, -1) == ADH_CONTINUE && run.nturns == 2 && run.rows[run.nrows - 1].path == 2 &&
       fabs(run.turns[1].h0 - (last.h0 - ps.step)) < 1e-18, "retracting from there records a second turn, path 2 (%zu turns, path %d)",
       run.nturns, run.rows[run.nrows - 1].path);
    adh_history_push(h, d);

    while (adh_history_undo(h, d) == ADH_SUCCESS)
        ;
    ok(adh_history_length(h) == 1 && run.nrows == 2 && run.nturns == 0 && run.rows[0].h0 == start,
       "undo stops at the first entry, with the run back to its two rows and no turn");
    ok(adh_history_state_at(h, 0) && adh_history_state_at(h, 0)->h0 == run.rows[1].h0 && adh_history_state_at(h, 1) == NULL,
       "the states on the path are the snapshots' (%g, row %g)", adh_history_state_at(h, 0)->h0, run.rows[1].h0);
    adh_history_clear(h);
    ok(adh_history_length(h) == 0, "clear forgets every entry");
    adh_material small = m;
    small.R = 1e-6;   /* reach R/50 = 20 nm */
    ps.start = 19.9e-9;
    adh_run_free(&run);
    adh_run_init(&run);
    adh_drive_set(d, &small, &rs, &ps, &run);
    ok(adh_drive_hand(d, -1) == ADH_EINVAL && adh_drive_hand(d, +1) == ADH_SUCCESS,
       "a step beyond the model's reach (19.9 + 0.25 nm > R/50) is refused before it starts; one in is not");

    /* after steps by hand the protocol goes on from the path: two turns,
     * turn 1 unloaded by hand then to its pull-off, and loading goes on to
     * turn 2, never reached (a stored profile comes back with its row on
     * redo) */
    ps.start = NAN;
    ps.nturns = 2;
    ps.turns[0] = -1e-9;
    ps.turns[1] = -2e-9;
    ps.nprofiles = 1;
    ps.profiles[0] = -0.5e-9;
    adh_run_free(&run);
    adh_run_init(&run);
    adh_drive_set(d, &m, &rs, &ps, &run);
    adh_history *h2 = adh_history_alloc();
    int row, ok_steps = 1;
    while (!(adh_drive_events(d) & ADH_DRIVE_TURN) && ok_steps) {
        ok_steps = adh_drive_iterate(d, 0, &row) == ADH_CONTINUE;
        if (row)
            adh_history_push(h2, d);
    }
    size_t np = run.nprofiles, nr = run.nrows;
    ok(ok_steps && np == 1 && run.rows[nr - 1].h0 == -1e-9, "loading reaches turn 1, storing the profile at -0.5 nm");
    adh_history_undo(h2, d), adh_history_undo(h2, d), adh_history_undo(h2, d);
    ok(run.nprofiles == 0, "undo past the profile's row drops it");
    int r1 = adh_history_redo(h2, d), r2 = adh_history_redo(h2, d), r3 = adh_history_redo(h2, d);
    ok(r1 == ADH_SUCCESS && r2 == ADH_SUCCESS && r3 == ADH_SUCCESS && run.nprofiles == 1 && run.nrows == nr &&
       fabs(run.profiles[0].h0 - -0.5e-9) < 1e-18, "redo puts the row and its profile back (%d %d %d, %zu profiles, %zu of %zu rows, h0 %g)",
       r1, r2, r3, run.nprofiles, run.nrows, nr, run.nprofiles ? run.profiles[0].h0 : NAN);
    ok(step_hand(d, -1) == ADH_CONTINUE && adh_drive_next(d, &t) == -1 && t == 1, "b at turn 1: its branch goes on");
    int rc2;
    while ((rc2 = adh_drive_step(d)) == ADH_CONTINUE && !(adh_drive_events(d) & ADH_DRIVE_PULLOFF))
        ;
    ok(rc2 == ADH_CONTINUE && (adh_drive_events(d) & ADH_DRIVE_END), "turn 1 pulls off, and its branch ends there");
    ok(adh_drive_next(d, &t) == +1 && t == 2, "then the protocol loads on to turn 2, never reached by hand");
    while ((rc2 = adh_drive_step(d)) == ADH_CONTINUE)
        ;
    ok(rc2 == ADH_SUCCESS && run.nturns == 2 && run.turns[1].h0 == -2e-9 && !isnan(run.turns[1].pulloff_F) &&
       adh_drive_status(d) == ADH_SUCCESS, "and unloads it: both turns pulled off, the protocol complete");
    adh_history_free(h2);

    adh_history_free(h);
    adh_drive_free(d);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
