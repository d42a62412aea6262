/* Whole runs: a drive (adhere/drive.h) stepped to the end of its protocol,
 * a callback after every row. The loop every driver's batch run uses (the
 * CLI's batch, sweeps and --cost, the tests); the TUI steps the drive
 * itself. Sits above the drive and the solvers: nothing below includes it.
 * No I/O. */
#ifndef ADHERE_RUNNER_H
#define ADHERE_RUNNER_H

#include "adhere/drive.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/observe.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/rule.h"
#include "adhere/run.h"
#include "adhere/static.h"

/* Called after every drive step with the row just added; return nonzero to stop. */
typedef int (*adh_step_cb)(const adh_obs *row, const adh_run *run, void *ctx);

/* Steps d (set) to the end of its protocol, calling cb (may be NULL) after
 * every row; a nonzero return stops it. ADH_SUCCESS when the protocol is
 * complete or was stopped on request (cb, or the cancel flag:
 * run->interrupted = 1), else the error that ended the run. */
int adh_runner_drive(adh_drive *d, adh_step_cb cb, void *ctx);

/* Runs the whole protocol ps with step rule type (settings: the rule's,
 * adhere/rule.h) on grid g with kernel k (NULL for rigid spheres).
 * Returns ADH_SUCCESS, or the first error (the run keeps every row
 * computed so far, run->status says why it stopped). A raised cancel flag
 * or a callback asking to stop ends it with ADH_SUCCESS and
 * run->interrupted = 1; the step under way is dropped. */
int adh_runner_rule(const adh_rule_type *type, const adh_grid *g, const adh_kernel *k, const adh_material *m,
                    const void *settings, const adh_protocol_settings *ps, adh_step_cb cb, void *ctx,
                    adh_run *run);

/* The static curve of protocol ps: from its start (NAN: automatic for its
 * step) down to its deepest turn (none: s->h0_end), as every driver's
 * static mode runs it. As adh_runner_rule with adh_rule_static, and fills
 * res (may be NULL) with the curve's summary: one row per accepted point
 * (adh_observe plus branch = direction, path 0, converged 1, stable,
 * iters = Newton iterations), run->start and run->jump_in_h0 set,
 * run->turns left empty (one curve, no unloading branches). */
int adh_runner_static(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_static_settings *s,
                      const adh_protocol_settings *ps, adh_step_cb cb, void *ctx, adh_run *run,
                      adh_static_result *res);
/* The same from s->h0_start down to s->h0_end, with no protocol. */
int adh_runner_static_curve(const adh_grid *g, const adh_kernel *k, const adh_material *m,
                            const adh_static_settings *s, adh_step_cb cb, void *ctx, adh_run *run,
                            adh_static_result *res);

#endif
