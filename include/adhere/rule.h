/* A step rule: what one step of the drive (adhere/drive.h) does. The drive
 * owns the protocol (where each step goes, the turns and their snapshots,
 * the dwell, steps by hand, the events, undo); the rule owns the physics of
 * a step. GSL style: a rule is a constant type object, a table of
 * functions over the rule's own workspace (void *r), and the drive is
 * allocated with one:
 *
 *   d = adh_drive_alloc(&adh_rule_relax, grid, kernel);
 *   adh_drive_set(d, material, &relax_settings, protocol, run);
 *
 * The rules:
 *   relax   the paper's relaxation (rule_relax.c): the drive picks each
 *           position, the rule iterates eq 11 there until the change is
 *           below eps; settings: adh_relax_settings.
 *   static  the static equilibrium curve (rule_static.c): the rule follows
 *           the curve by continuation through its folds, from the start down
 *           to the deepest turn, and picks its own positions; settings:
 *           adh_static_settings.
 *   rigid   rigid spheres, eq 22 alone (rule_rigid.c): the force at start -
 *           k d down to the deepest turn but not below 0.7 z0, loading
 *           only, no grid or kernel; settings: none (NULL).
 *   visco   a standard linear solid in physical time (rule_visco.c): the
 *           integrator walks the whole cycle at the drive's speeds, through
 *           its spring; settings: adh_visco_rule_settings.
 *   path    an elastic sphere in physical time (rule_path.c): the static
 *           curve solved, then the path the base drives along it (its
 *           jumps at the base's folds, time from the base's travel), no
 *           integration; settings: adh_visco_rule_settings.
 *
 * Two kinds of rule, told apart by which functions they fill:
 *   stepped (move, iterate and the snapshots; next NULL): the drive's
 *     protocol picks every position (loading, each turn's unloading branch
 *     from its snapshot, the dwell) and the rule solves there. Steps by
 *     hand and adh_drive_retarget work. relax.
 *   curve (next; move NULL): the rule walks its own path from the
 *     protocol's start to its end, one point a step; the drive records
 *     the rows. static, rigid, visco; path also fills iterate, its work
 *     before a point in batches (a driver reading keys stays responsive).
 *
 * A new rule (a time-dependent material, say) needs nothing else changed:
 *   1. a file src/core/rule_NAME.c defining
 *        const adh_rule_type adh_rule_NAME = { .name = "NAME", ... };
 *      with its settings struct where its solver declares it;
 *   2. one registration: NAME added to ADH_RULES below.
 * The drive, its snapshots and undo history, and the runner
 * (adhere/runner.h) step it as they step the others; a driver chooses it by
 * passing &adh_rule_NAME and its settings. No I/O. */
#ifndef ADHERE_RULE_H
#define ADHERE_RULE_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/observe.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/state.h"

typedef struct adh_rule_type {
    const char *name;

    /* The workspace on grid g with kernel k (both borrowed; NULL for a rule
     * that needs none, such as rigid), or NULL when out of memory. */
    void *(*alloc)(const adh_grid *g, const adh_kernel *k);
    void (*free)(void *r);
    /* Puts the rule at the protocol's start: the material, the rule's own
     * settings (copied), the protocol and its start (resolved: never NAN).
     * ADH_SUCCESS, or ADH_EINVAL for bad settings (the drive then does not
     * step); any other failure is reported by the first step. */
    int (*set)(void *r, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
               double start);

    /* A stepped rule: begins the step to position h0; dwell > 0 asks for
     * the protocol's dwell at a turn instead (held where the rule is:
     * the turn's snapshot was just loaded). */
    void (*move)(void *r, double h0, size_t dwell);
    /* Works on the step begun by move, at most max_batch units of work (0:
     * until it is done). ADH_CONTINUE: call again; ADH_SUCCESS: solved;
     * ADH_EMAXITER: at the cap (a row, flagged unconverged); else the error
     * that ends the run (ADH_EINTR when the settings' cancel flag was
     * raised). The rows do not depend on max_batch. A curve rule may fill
     * it too, for work before its next point (path: the static curve, a
     * point a unit): ADH_CONTINUE, no point yet; ADH_SUCCESS, next has its
     * point (or its failure). */
    int (*iterate)(void *r, size_t max_batch);

    /* A curve rule: the next point of its path (the first call: the start).
     * ADH_CONTINUE: a point, more follow; ADH_SUCCESS: a point, the path's
     * last; ADH_EGRID: a point, and the grid ends the run there; else the
     * error that ends the run, no point. */
    int (*next)(void *r);
    /* A curve rule may locate the jump into contact itself (the static
     * curve, at its fold): its position so far, NAN for none. NULL: the
     * drive takes the first row in contact. */
    double (*jump_in)(const void *r);

    /* The row of the step just solved: what the state shows (adh_observe),
     * iters, stable; a curve rule also branch and seconds. The drive fills
     * a stepped rule's branch, path, converged and seconds. */
    void (*observe)(const void *r, adh_obs *o);
    /* The present state (borrowed; a stored profile is a copy of it). NULL
     * (the function) for a rule without one: rigid. */
    const adh_state *(*state)(const void *r);
    /* The work done on the step under way (or the last) and its latest
     * change, for a driver's progress line; NULL when it has no measure. */
    size_t (*progress)(const void *r, double *change);
    /* After a step or point that ended the run on an error: the rule's
     * sentence saying what failed and where ("" or NULL when it has none;
     * the drive then says where), and in *fix the ADH_FIX_* bits of what
     * may get past it (adhere/status.h). NULL (the function): no words. */
    const char *(*why)(const void *r, unsigned *fix);

    /* Snapshots of the rule's dynamic state: at every turn a stepped rule
     * unloads from, and in a drive's undo history (adh_drive_snap). The
     * state of a snapshot (snap_state) says which grid it was taken on; a
     * snapshot is only loaded into a rule of its own type whose state has
     * the same size. A stepped rule must have them; a curve rule without
     * them (static) cannot be snapshotted (adh_drive_snap_alloc: NULL). */
    void *(*snap_alloc)(const void *r);
    void (*snap_free)(void *snap);
    void (*save)(const void *r, void *snap);
    void (*load)(void *r, const void *snap);
    const adh_state *(*snap_state)(const void *snap);
} adh_rule_type;

/* The registration: one X(NAME) per rule, each defined as adh_rule_NAME in
 * src/core/rule_NAME.c (a test steps every rule listed here). */
#define ADH_RULES(X) X(relax) X(static) X(rigid) X(visco) X(path)

#define ADH_RULE_DECLARE(name) extern const adh_rule_type adh_rule_##name;
ADH_RULES(ADH_RULE_DECLARE)
#undef ADH_RULE_DECLARE

/* Whether t is a whole rule: a name, alloc, free, set and observe; either
 * move, iterate and the five snapshot functions (stepped) or next (curve),
 * not both. ADH_SUCCESS or ADH_EINVAL (adh_drive_alloc refuses it). */
int adh_rule_check(const adh_rule_type *t);

#endif
