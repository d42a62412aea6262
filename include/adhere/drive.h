/* One run of the loading/unloading protocol as a stepping object (GSL
 * style): every driver (batch, sweeps, --cost, the TUI) steps the same
 * drive, so they produce the same rows by construction.
 *
 *   d = adh_drive_alloc(grid, kernel);
 *   adh_drive_set(d, material, relax settings, protocol, run);
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
 * per-step checks (grid edge, NaN, the cancel flag of the relax settings).
 * The relaxation is its step rule; the static curve (adh_static_*) is a
 * whole-curve continuation and stays behind its own object. No I/O. */
#ifndef ADHERE_DRIVE_H
#define ADHERE_DRIVE_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"

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
 * value and what is allowed. Whether the grid resolves the contact is
 * adh_grid_check's question (a driver may run it anyway, marked). */
int adh_drive_check(const adh_material *m, const adh_relax_settings *rs, const adh_protocol_settings *ps,
                    adh_grid_use use, const adh_grid *g, char *why, size_t whylen);
/* The description of a uniform grid of n nodes of spacing dr, without its
 * nodes (r = NULL): enough for adh_drive_check and adh_protocol_check. */
adh_grid adh_drive_uniform_grid(size_t n, double dr);

/* The grid and kernel are borrowed and must outlive the drive. NULL when
 * out of memory. */
adh_drive *adh_drive_alloc(const adh_grid *g, const adh_kernel *k);
void adh_drive_free(adh_drive *d);

/* Puts the drive at the start of the protocol ps (the material, relax and
 * protocol settings are copied; run is borrowed and must outlive the drive,
 * it is filled with rows, turns, profiles and the summary as the drive
 * steps; it should be freshly initialised).
 * ADH_SUCCESS, or ADH_EINVAL for a step <= 0 or too many turns (the full
 * check of a run is adh_protocol_check). */
int adh_drive_set(adh_drive *d, const adh_material *m, const adh_relax_settings *rs,
                  const adh_protocol_settings *ps, adh_run *run);

/* One drive step: relaxes the next position, observes it and appends its
 * row to the run. ADH_CONTINUE with the row (adh_drive_row), ADH_SUCCESS
 * once the protocol is complete (no row), ADH_EINTR when the relax
 * settings' cancel flag was raised (the step under way is dropped, no row,
 * run->interrupted = 1), else the error that ends the run (ADH_EGRID: the
 * contact reached the grid edge, its row kept; ADH_ENAN, ADH_ENOMEM: no
 * row). After a final status every further call returns it again. */
int adh_drive_step(adh_drive *d);

/* The same in batches, for a driver that must stay responsive (the TUI
 * polls keys between them): at most max_batch relaxation iterations of the
 * step under way (0: until it is done; a dwell is done whole), starting
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
/* The relaxed state of the last step (borrowed). */
const adh_state *adh_drive_state(const adh_drive *d);

/* A snapshot of a drive: the relaxed state, where it is in the protocol
 * and how much of the run it has written. Restoring it puts the drive back
 * there and cuts the run back to what it held then (vis-style undo). */
typedef struct adh_drive_snap adh_drive_snap;
/* A snapshot sized for d (NULL when out of memory), filled with its present state. */
adh_drive_snap *adh_drive_snap_alloc(const adh_drive *d);
void adh_drive_snap_free(adh_drive_snap *s);
/* Overwrites s with d's present state. ADH_SUCCESS or ADH_EINVAL (sizes differ). */
int adh_drive_snapshot(const adh_drive *d, adh_drive_snap *s);
/* ADH_SUCCESS, or ADH_EINVAL when s was taken on another grid or holds
 * more rows than the run now has (a snapshot never invents rows). */
int adh_drive_restore(adh_drive *d, const adh_drive_snap *s);

#endif
