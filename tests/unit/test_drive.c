/* The drive: stepping it by hand gives adh_runner_rule's rows; restoring a
 * snapshot and stepping again gives the same rows bit for bit (the TUI's
 * undo); it says which turn it is on; a raised cancel flag ends it with
 * ADH_EINTR and no row for the step under way. */
#include <math.h>
#include <signal.h>
#include <string.h>

#include "adhere/cycle.h"
#include "adhere/drive.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "tap.h"

static int same_rows(const adh_obs *a, const adh_obs *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i].h0 != b[i].h0 || a[i].F != b[i].F || a[i].a != b[i].a || a[i].iters != b[i].iters ||
            a[i].branch != b[i].branch || a[i].path != b[i].path)
            return 0;
    return 1;
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
    ps.nturns = 2;
    ps.turns[0] = -1e-9;
    ps.turns[1] = -2e-9;

    adh_run ref;
    adh_run_init(&ref);
    int prc = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &ref);
    ok(prc == ADH_SUCCESS && ref.nrows > 50, "the protocol runs (%zu rows)", ref.nrows);

    adh_drive *d = adh_drive_alloc(&adh_rule_relax, g, k);
    adh_run run;
    adh_run_init(&run);
    ok(d && adh_drive_set(d, &m, &rs, &ps, &run) == ADH_SUCCESS, "alloc and set");
    ok(adh_drive_turn(d) == 0 && adh_drive_row(d) == NULL, "at the start: loading, no row yet");
    int rc, saw[3] = { 0 }, order_ok = 1, last_turn = 0;
    adh_drive_snap *snap = NULL;
    size_t snap_rows = 0;
    while ((rc = adh_drive_step(d)) == ADH_CONTINUE) {
        const adh_obs *o = adh_drive_row(d);
        order_ok &= o == &run.rows[run.nrows - 1];
        int t = o->path;
        if (t >= 0 && t < 3)
            saw[t] = 1;
        order_ok &= t >= last_turn;
        last_turn = t;
        /* snapshot in the middle of the first unloading branch */
        if (!snap && o->path == 1 && o->branch < 0 && o->a > 0) {
            snap = adh_drive_snap_alloc(d);
            snap_rows = run.nrows;
        }
    }
    ok(rc == ADH_SUCCESS && adh_drive_turn(d) == -1, "the drive ends with success and says it is done");
    ok(adh_drive_step(d) == ADH_SUCCESS, "a further step says so again");
    ok(order_ok && saw[0] && saw[1] && saw[2], "rows come one per step: loading, then turn 1, then turn 2");
    ok(run.nrows == ref.nrows && same_rows(run.rows, ref.rows, ref.nrows), "stepping by hand gives the protocol's rows");
    ok(run.nturns == 2 && run.turns[1].pulloff_F == ref.turns[1].pulloff_F &&
       run.turns[0].jump_out_h0 == ref.turns[0].jump_out_h0 && run.jump_in_h0 == ref.jump_in_h0,
       "and its turns, pull-offs, jump-out and jump-in");

    adh_turn_result tt[ADH_MAX_TURNS];
    size_t ntt = adh_cycle_turns(run.rows, run.nrows, tt, ADH_MAX_TURNS);
    int same_turns = ntt == run.nturns;
    for (size_t i = 0; same_turns && i < ntt; i++)
        same_turns = tt[i].h0 == run.turns[i].h0 && tt[i].max_load == run.turns[i].max_load &&
                     tt[i].pulloff_F == run.turns[i].pulloff_F && tt[i].path == run.turns[i].path &&
                     tt[i].jump_out_h0 == run.turns[i].jump_out_h0;
    ok(same_turns, "the turns read off the rows (adh_cycle_turns, what the TUI's plots use) are the drive's");

    ok(snap != NULL, "a snapshot on the first unloading branch");
    if (snap) {
        ok(adh_drive_restore(d, snap) == ADH_SUCCESS && run.nrows == snap_rows && adh_drive_turn(d) == 1,
           "restoring it cuts the run back and puts the drive on turn 1 again");
        ok(isnan(run.turns[0].jump_out_h0) || run.turns[0].jump_out_h0 != ref.turns[0].jump_out_h0,
           "the jump-out found after the snapshot is forgotten");
        while ((rc = adh_drive_step(d)) == ADH_CONTINUE)
            ;
        ok(rc == ADH_SUCCESS && run.nrows == ref.nrows && same_rows(run.rows, ref.rows, ref.nrows),
           "stepping on from the snapshot gives the same rows bit for bit");
        ok(run.turns[0].jump_out_h0 == ref.turns[0].jump_out_h0, "and finds the same jump-out");
        adh_drive_snap_free(snap);
    }

    /* in batches: the same rows whatever the batch */
    for (size_t batch = 1; batch <= 64; batch *= 8) {
        adh_run br;
        adh_run_init(&br);
        adh_drive_set(d, &m, &rs, &ps, &br);
        int row, calls = 0;
        size_t rows = 0;
        while ((rc = adh_drive_iterate(d, batch, &row)) == ADH_CONTINUE) {
            calls++;
            rows += row;
        }
        ok(rc == ADH_SUCCESS && rows == ref.nrows && br.nrows == ref.nrows && same_rows(br.rows, ref.rows, ref.nrows) &&
           (size_t)calls > rows, "in batches of %zu iterations: the protocol's rows, one reported per step (%d calls; rc %d, %zu rows reported, %zu kept)",
           batch, calls, rc, rows, br.nrows);
        adh_run_free(&br);
    }

    /* cancel: the flag stops the step under way */
    static volatile sig_atomic_t stop = 0;
    rs.cancel = &stop;
    adh_run cut;
    adh_run_init(&cut);
    adh_drive_set(d, &m, &rs, &ps, &cut);
    adh_drive_step(d);
    adh_drive_step(d);
    stop = 1;
    rc = adh_drive_step(d);
    ok(rc == ADH_EINTR && cut.nrows == 2 && cut.interrupted, "a raised cancel flag: ADH_EINTR, no row for that step");

    /* the grid's edge: a run whose contact outgrows a short grid stops
     * there, and approaching further by hand is refused (it would only add
     * rows past the edge), while retracting goes on */
    {
        adh_grid *gs = adh_grid_alloc(20, 10e-9);
        adh_kernel *ks = adh_kernel_alloc(gs, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
        adh_drive *ds = adh_drive_alloc(&adh_rule_relax, gs, ks);
        adh_protocol_settings pe = adh_protocol_settings_default();
        pe.step = 0.25e-9;
        pe.turns[0] = -3e-9;
        adh_relax_settings re = rs;
        re.cancel = NULL;
        adh_run er;
        adh_run_init(&er);
        int erc = ds ? adh_drive_set(ds, &m, &re, &pe, &er) : ADH_ENOMEM;
        if (erc == ADH_SUCCESS)
            while ((erc = adh_drive_step(ds)) == ADH_CONTINUE)
                ;
        size_t nr = er.nrows;
        ok(erc == ADH_EGRID && nr > 0 && er.rows[nr - 1].a >= 0.9 * 200e-9,
           "a contact past 0.9 Rmax ends the run with ADH_EGRID (rc %d, a = %g m)", erc, nr ? er.rows[nr - 1].a : NAN);
        ok(adh_drive_hand(ds, +1) == ADH_EGRID && er.nrows == nr, "an approach by hand from there is refused, no row added");
        ok(adh_drive_hand(ds, -1) == ADH_SUCCESS && adh_drive_step(ds) != ADH_ENOMEM && er.nrows == nr + 1 &&
           er.rows[nr].branch < 0 && er.rows[nr].h0 > er.rows[nr - 1].h0,
           "a retraction by hand steps out");
        adh_run_free(&er);
        adh_drive_free(ds);
        adh_kernel_free(ks);
        adh_grid_free(gs);
    }

    /* a start inside the neck's reach: unloading goes on past it to the
     * jump-out, and the cycle measures what it measures from the automatic
     * start (the loading force out there is the rigid spheres') */
    {
        adh_relax_settings re = rs;
        re.cancel = NULL;
        adh_protocol_settings pa = adh_protocol_settings_default(), pb;
        pa.step = 0.25e-9;
        pa.turns[0] = -1e-9;
        pb = pa;
        pb.start = 3e-9;
        adh_run ra, rb;
        adh_run_init(&ra);
        adh_run_init(&rb);
        int ca = adh_runner_rule(&adh_rule_relax, g, k, &m, &re, &pa, NULL, NULL, &ra);
        int cb = adh_runner_rule(&adh_rule_relax, g, k, &m, &re, &pb, NULL, NULL, &rb);
        ok(ca == ADH_SUCCESS && cb == ADH_SUCCESS && rb.nturns == 1 && rb.turns[0].jump_out_h0 > 3e-9 &&
           fabs(rb.turns[0].jump_out_h0 - ra.turns[0].jump_out_h0) <= pa.step * 1.001,
           "from a start at 3 nm the unloading goes past it to the jump-out (%g against %g m)",
           rb.turns[0].jump_out_h0, ra.turns[0].jump_out_h0);
        double ha = adh_cycle_hysteresis(ra.rows, ra.nrows, 1), hb = adh_cycle_hysteresis(rb.rows, rb.nrows, 1);
        ok(ha > 0 && fabs(hb - ha) <= 0.02 * ha, "and its hysteresis is the automatic start's within 2 %% (%g against %g J)",
           hb, ha);
        adh_run_free(&ra);
        adh_run_free(&rb);
    }

    /* a step the drive cannot take */
    ps.step = 0;
    ok(adh_drive_set(d, &m, &rs, &ps, &cut) == ADH_EINVAL, "a step of 0 is refused");

    adh_run_free(&cut);
    adh_run_free(&run);
    adh_run_free(&ref);
    adh_drive_free(d);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
