/* One run of the loading/unloading protocol as a stepping object (GSL
 * style): every driver (batch, sweeps, --cost, the TUI) steps the same
 * drive, so they produce the same rows by construction.
 *
 *   d = adh_drive_alloc(&adh_rule_relax, grid, kernel);
 *   adh_drive_set(d, material, &relax_settings, protocol, run);
 *   while ((rc = adh_drive_step(d)) == ADH_CONTINUE)
 *       use adh_drive_row(d);                 (also appended to run)
 *   rc: ADH_SUCCESS (done), ADH_EINTR (cancel flag: no row for the step
 *   under way), or the error that ended the run (ADH_EGRID keeps its row).
 *   adh_drive_free(d);
 *
 * The drive owns the protocol: drive positions (start - k d while loading,
 * turn + k d while unloading, never accumulated, each turn hit exactly),
 * the turns (one loading branch snapshotted at every turn, then each turn's
 * unloading branch from its snapshot), the dwell, the detection of jump-in,
 * pull-off and jump-out (filled into the run's summary as it goes), and the
 * per-step checks (grid edge, NaN, the rule's cancel flag). What a step
 * does is its step rule's (adhere/rule.h), chosen at alloc: the relaxation
 * (adh_rule_relax: a step moves the drive and relaxes, the paper's
 * dynamics), the static equilibrium curve (adh_rule_static: a step is the
 * next accepted point of the continuation, adhere/static.h, from the
 * protocol's start down to its deepest turn, through every fold) or rigid
 * spheres (adh_rule_rigid: eq 22). The last two walk their own path: the
 * protocol's turns, steps by hand and retargeting are a stepped rule's.
 * No I/O.
 *
 * A driver may also step by hand (the TUI's f and b): adh_drive_hand asks
 * for one step approaching or retracting by d from the last row, on the
 * same lattices (start - k d loading, each turn not yet reached hit
 * exactly; turn + k d unloading). Retracting from the loading branch turns
 * there: the turn is recorded in the run (the one the loading branch just
 * reached, or a new one) and its unloading branch begins, without a dwell.
 * Approaching from an unloading branch loads again. Stepping on without a
 * hand step follows the protocol from wherever the drive is: loading to
 * the next turn not yet reached, then unloading every turn not yet
 * unloaded, in the order reached, from its snapshot. */
#ifndef ADHERE_DRIVE_H
#define ADHERE_DRIVE_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/rule.h"
#include "adhere/run.h"

typedef struct adh_drive adh_drive;

/* Every limit of a run, in one place, for every driver (flags, scene files,
 * the TUI's fields and :set): the material, the relax settings (and eps
 * above its rounding floor on the grid's nodes, relaxation only), the
 * protocol (step, turns, start, R; adh_protocol_check) and the grid g (N,
 * spacing, a radius and a graded grid's fine band that hold the contact;
 * only n, dr, rmax and a graded grid's edges are read, so a uniform grid
 * need not be built: adh_drive_uniform_grid). g = NULL: rigid spheres, no
 * grid. ADH_SUCCESS; ADH_EINVAL for a value outside its limits, ADH_EGRID
 * for a grid that cannot hold the run, each with a sentence naming the
 * value and what is allowed, and in *fix (may be NULL) the ADH_FIX_* bits of
 * the settings it asks to change, for the driver's own words (adhere/status.h).
 * Whether the grid resolves the contact is adh_grid_check's question (a
 * driver may run it anyway, marked). */
int adh_drive_check(const adh_material *m, const adh_relax_settings *rs, const adh_protocol_settings *ps,
                    adh_grid_use use, const adh_grid *g, char *why, size_t whylen, unsigned *fix);
/* The description of a uniform grid of n nodes of spacing dr, without its
 * nodes (r = NULL): enough for adh_drive_check and adh_protocol_check. */
adh_grid adh_drive_uniform_grid(size_t n, double dr);

/* A drive stepping rule type on grid g with kernel k (borrowed: they must
 * outlive the drive; NULL for a rule that needs none, such as rigid). Builds
 * the rule's workspace (the static curve's: a dense copy of W). NULL when
 * out of memory, or for a type adh_rule_check refuses. */
adh_drive *adh_drive_alloc(const adh_rule_type *type, const adh_grid *g, const adh_kernel *k);
void adh_drive_free(adh_drive *d);

/* Puts the drive at the start of the protocol ps (the material, the rule's
 * settings and the protocol settings are copied; settings is the rule's
 * own type: adh_relax_settings for relax, adh_static_settings for static,
 * NULL for rigid; run is borrowed and must outlive the drive, it is filled
 * with rows, turns, profiles and the summary as the drive steps; it should
 * be freshly initialised). The start is ps->start, or with NAN the
 * automatic one for ps->step.
 * ADH_SUCCESS, or ADH_EINVAL for a step <= 0, too many turns or bad
 * settings (the full check of a run is adh_protocol_check). A curve rule's
 * failure at its start (the static curve's first point) is its first
 * step's status. */
int adh_drive_set(adh_drive *d, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                  adh_run *run);

/* The run d fills (borrowed from adh_drive_set), NULL before it is set. */
adh_run *adh_drive_record(const adh_drive *d);

/* The rule's workspace when d steps rule type, else NULL: for the rule's
 * own accessors (adhere/rule_static.h). */
void *adh_drive_workspace(const adh_drive *d, const adh_rule_type *type);

/* One drive step: solves the next position (a curve rule: its next
 * point), observes it and appends its row to the run. ADH_CONTINUE with
 * the row (adh_drive_row), ADH_SUCCESS once the protocol is complete (no
 * row; a curve rule's last row is flagged ADH_DRIVE_END), ADH_EINTR when
 * the rule's cancel flag was raised (the step under way is dropped, no
 * row, run->interrupted = 1), else the error that ends the run (ADH_EGRID:
 * the contact reached the grid edge, its row kept; ADH_ENAN, ADH_ENOMEM: no
 * row). After a final status every further call returns it again. A whole
 * run with a callback per row: adh_runner_drive (adhere/runner.h). */
int adh_drive_step(adh_drive *d);

/* The same in batches, for a driver that must stay responsive (the TUI
 * polls keys between them): at most max_batch units of the rule's work on
 * the step under way (relaxation iterations; 0: until it is done; a dwell
 * is done whole; a curve rule's point is one unit), starting
 * the next step when none is. ADH_CONTINUE with *row = 0 while the step
 * goes on, ADH_CONTINUE with *row = 1 when it produced its row, else as
 * adh_drive_step (*row = 1 for ADH_EGRID's kept row). The rows do not
 * depend on the batch size. Snapshots are taken between steps. */
int adh_drive_iterate(adh_drive *d, size_t max_batch, int *row);

/* The row of the last step that returned ADH_CONTINUE (or ADH_EGRID);
 * NULL before the first. Borrowed from the run. */
const adh_obs *adh_drive_row(const adh_drive *d);

/* Which part of the protocol the next step belongs to: 0 the loading
 * branch, k (1..nturns) the unloading branch of the k-th turn reached
 * (deepest last), -1 when the protocol is complete. */
int adh_drive_turn(const adh_drive *d);
/* The start in use (the automatic one when ps->start is NAN). */
double adh_drive_start(const adh_drive *d);
/* The state of the last step (borrowed), NULL for a rule without one. */
const adh_state *adh_drive_state(const adh_drive *d);

/* What the last row meant, for a driver that pauses on events (or 0). */
enum {
    ADH_DRIVE_JUMP_IN = 1,    /* loading: first row in contact */
    ADH_DRIVE_TURN = 2,       /* loading: a turn of the protocol reached (snapshotted) */
    ADH_DRIVE_UNLOAD = 4,     /* the first row of a turn's unloading branch (from its snapshot) */
    ADH_DRIVE_PULLOFF = 8,    /* unloading: out of contact after contact: the branch ended */
    ADH_DRIVE_END = 16        /* the protocol's next step begins another branch, or none is left */
};
unsigned adh_drive_events(const adh_drive *d);

/* Asks for the next step to go by hand: dir +1 approaches by d, -1
 * retracts by d (before the first row, the start is solved first, then
 * that step). ADH_SUCCESS; ADH_EINVAL for a dir other than +-1, a curve
 * rule, a step under way, a drive never set, a position beyond the model's reach
 * (|h0| > R/50, adh_protocol_reach) or a 65th turn; ADH_EGRID for an
 * approach from a row whose contact the grid no longer holds (at 0.9 Rmax
 * or past a graded grid's fine band): deeper in it would only grow. */
int adh_drive_hand(adh_drive *d, int dir);
/* Where a step by hand in direction dir would go (for a message). */
double adh_drive_hand_position(const adh_drive *d, int dir);
/* 1 while a step is under way or asked for by hand: the driver iterates
 * on; 0 once the last row asked for is in. */
int adh_drive_pending(const adh_drive *d);

/* Which way the next step goes (a step by hand asked for, else the
 * protocol's): +1 loading (*turn: the protocol's next turn to reach, 1..,
 * 0 none), -1 unloading (*turn: the run's turn k whose branch it is on or
 * begins), 0 when the protocol is complete or was stopped
 * (adh_drive_status says which). After steps by hand the protocol goes on
 * from where the path is: the turns recorded and not yet unloaded first,
 * then loading on to the turns not yet reached. */
int adh_drive_next(const adh_drive *d, size_t *turn);
/* ADH_CONTINUE while the protocol goes on, else the status that ended it
 * (ADH_SUCCESS: complete; ADH_EGRID, ADH_ENAN...: stopped there). */
int adh_drive_status(const adh_drive *d);
/* Where the step under way goes (h0, m); NAN between steps. */
double adh_drive_step_position(const adh_drive *d);
/* Iterations so far of the step under way (or the last), and its change. */
size_t adh_drive_progress(const adh_drive *d, double *change);
/* Replaces the protocol's turning points, keeping the path: turns the
 * loading branch has passed are behind it, and when one of them was never
 * reached as a turn (it was set after the path passed it) the path turns
 * where its loading branch is now, as the next branch to unload.
 * ADH_SUCCESS, or ADH_EINVAL for a different step, too many turns, a step
 * under way, a curve rule; ADH_ENOMEM. */
int adh_drive_retarget(adh_drive *d, const adh_protocol_settings *ps);

/* A snapshot of a drive: the relaxed state, where it is in the protocol
 * and how much of the run it has written. Restoring it puts the drive back
 * there and cuts the run back to what it held then (vis-style undo). */
typedef struct adh_drive_snap adh_drive_snap;
/* A snapshot sized for d (NULL when out of memory, or when d's rule has no
 * snapshots: the static curve), filled with its present state. */
adh_drive_snap *adh_drive_snap_alloc(const adh_drive *d);
void adh_drive_snap_free(adh_drive_snap *s);
/* Overwrites s with d's present state. ADH_SUCCESS or ADH_EINVAL (another
 * rule, or sizes differ). */
int adh_drive_snapshot(const adh_drive *d, adh_drive_snap *s);
/* ADH_SUCCESS, or ADH_EINVAL when s was taken of another rule or on another grid or holds
 * more than one row beyond what the run now has. A snapshot one row ahead
 * (a redo after an undo) puts its own last row back; a snapshot never
 * invents rows. The turn states it saw are shared, not copied. */
int adh_drive_restore(adh_drive *d, const adh_drive_snap *s);
/* The state a snapshot holds (borrowed), NULL for a rule without one. */
const adh_state *adh_drive_snap_state(const adh_drive_snap *s);

#endif
