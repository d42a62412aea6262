/* The physics session behind the TUI: the session's one configuration (a
 * field's Enter, + and -, :set all set it by key through adh_config_set;
 * undo keeps snapshots of its run specification), the grid, kernel and
 * relaxation solver built from it, and the history of relaxed states. The
 * drive steps the configuration's own protocol, as --batch's does (its
 * turns, unload, dwell and profiles). Only core API calls; no curses, so
 * the loop decides when to draw.
 *
 * A drive step is solved in batches (tui_sim_work) so the loop can poll keys
 * and draw progress between them. The grid and kernel are built on the first
 * step after N or the spacing changed, never for a material change.
 *
 * Two modes share the parameters, grid and kernel. Relaxation (the paper's)
 * steps the core's drive (adhere/drive.h), the object --batch steps: by
 * hand (f, b) or along the protocol (r), so its rows are --batch's rows; the
 * path is the drive's run, with undo by the drive's snapshots
 * (adhere/history.h). Nothing here knows where a step goes. Static mode follows
 * the equilibrium curve by continuation (adh_static_*), one accepted point
 * per step; the points computed so far are kept as rows, and a cursor says
 * which is shown: stepping back (b, u) and forward again (f, U) over points
 * already computed moves the cursor and computes nothing, and only a step
 * past the last point asks the solver for more. Each mode keeps its own
 * path or curve across a toggle; a change of what a curve depends on (E, A,
 * z0, R, N, spacing, start, turn) drops the curve, and the next step starts
 * it again from the start.
 *
 * Physical time (a scene with material = sls, or mode = time) is a curve
 * mode as the static one is: the viscoelastic step rule's drive, one
 * integrator step a point (an elastic material: the static curve's path,
 * adh_rule_path, solved at the first step, one row of the batch run's a
 * point), the same keys walking back and forth over the points computed;
 * the panel shows E0, Einf, tau and the speed, the state the time, the
 * base and the speed. */
#ifndef ADH_TUI_SIM_H
#define ADH_TUI_SIM_H

#include <stddef.h>

#include "adhere/cycle.h"
#include "adhere/drive.h"
#include "adhere/static.h"
#include "adhere/grid.h"
#include "adhere/history.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/relax.h"
#include "adhere/run.h"
#include "adhere/units.h"
#include "adhere/visco.h"
#include "scene/config.h"

/* A check's sentence on the screen whole: "sweep run N (its values): "
 * (up to 256 bytes of values) before the core's sentence (up to 1024). */
#define TUI_SIM_WHY_LEN 1536

/* The panel's fields, in panel order: each edits one key of the
 * configuration (adh_config_set). */
typedef enum tui_param {
    P_E = 0, P_A, P_Z0, P_R, P_EPS, P_D, P_N, P_SPACING, P_TURN,
    P_EINF, P_TAU, P_SPEED,   /* physical time's: on screen only when the scene runs in time */
    P_COUNT
} tui_param;

typedef struct tui_param_info {
    const char *name;      /* the field's name, as :set takes it */
    const char *key;       /* the configuration key it edits */
    const char *label;     /* on screen (UTF-8) */
    const char *ascii;     /* on screen without UTF-8 */
    const char *what;
    adh_quantity q;        /* ADH_Q_NONE: a count */
} tui_param_info;

extern const tui_param_info tui_params[P_COUNT];

/* What the closed forms predict for the parameters on screen, to hold the
 * computed cycle against (all from core functions). */
typedef struct tui_models {
    double md_lambda;      /* Maugis-Dugdale parameter, 1.16 mu */
    double md_pulloff;     /* its pull-off at fixed load, N; NAN if it failed */
    double md_jump_out;    /* its jump out at fixed h0 (the fold), drive position h0 = z0 - overlap */
    double jump_in;        /* drive position of the jump into contact (eq 24 through eq 23) */
} tui_models;

/* A relaxation path: the drive's run and its undo history (hist NULL:
 * none yet). */
typedef struct tui_path {
    adh_run run;
    adh_history *hist;
} tui_path;

/* One edit on the undo (or redo) stack: a snapshot of the run
 * specification on the other side of it, and its path. */
typedef struct tui_edit {
    adh_run_spec spec;
    char key[40];           /* the key the edit set */
    int keeps_path;         /* a new turn: the path is the same on both sides */
    tui_path path;
} tui_edit;

#define TUI_MAX_EDITS 32

/* What tui_sim_work says of the step in progress, htop style: what the
 * loop does next. */
typedef enum tui_work {
    TUI_WORK_BUSY = 0,     /* not done: call again */
    TUI_WORK_STEPPED,      /* done and on the history (s->warn says when it hit the cap) */
    TUI_WORK_COMPLETE,     /* the protocol was already complete: no row */
    TUI_WORK_FAILED        /* failed, with why: back where it was (a grid edge keeps its row) */
} tui_work;

typedef struct tui_sim {
    /* The session's one configuration: flags and scene first, then every
     * edit, each through adh_config_set. Its mode is the screen's
     * (relaxation or static), its grid's `use` the mode's. */
    adh_config cfg;
    adh_derived der;
    tui_models models;
    char gridchoice[512];      /* why no grid could be chosen for the material on screen; "" */
    double turn;               /* the turn the drive is on: the config's turns[tcur] (NAN: none) */
    size_t tcur;               /* (the config's turns are kept shallowest first) */
    double start;              /* the start in use */

    adh_grid *g;
    adh_kernel *k;
    adh_drive *drv;            /* on g and k; steps the path */
    adh_grid_spec built;       /* the grid the relaxation's kernel was built for (N, spacing resolved) */
    tui_path path;             /* the path on screen: the drive's run and its history */
    tui_edit undo_edits[TUI_MAX_EDITS], redo_edits[TUI_MAX_EDITS];
    size_t nundo_edits, nredo_edits;
    const char *edit_moved;    /* the key of the edit the last undo/redo took back, else NULL */
    int edit_kept_path;        /* the last edit kept the path (a turn the grid did not have to follow) */
    int grid_stale;            /* the grid changed since the kernel was built */

    /* the step being solved */
    int busy;
    int dir;                   /* static mode: +1 the next point, -1 the previous */
    double target;             /* static mode: the point's h0 */
    double t0;
    char warn[256];            /* about the last step; "" when fine */
    char gridwarn[TUI_SIM_WHY_LEN]; /* why the grid may not hold the run to the turn; "" */
    adh_grid_report gridres;   /* the core's resolution check of the grid (Derived panel) */

    /* static mode: the equilibrium curve */
    adh_drive *sdrv;           /* the static step rule's drive, built on the first static step (a dense copy of W) */
    adh_grid *sg;              /* its own grid and kernel: an automatic grid is chosen per mode, */
    adh_kernel *sk;            /* the static curve's finer (0.3 edge widths against 0.45) */
    adh_grid_spec sbuilt;      /* the grid sg was built for */
    adh_config_kept startk;    /* a solid's start check: its grid and kernel (sg, sk lent while they
                                  are the same grid), kept from edit to edit, and handed to the curve */
    size_t kernels_built;      /* kernels this session built for the path and the curve (the start
                                  check's: startk.built) */
    adh_run curve;             /* rows: every point computed so far, in curve order */
    size_t ccur;               /* the point shown (when curve.nrows > 0) */
    int walk;                  /* the step in progress only moves the cursor: +1, -1 */
    int walked;                /* the last step moved the cursor over kept points */
    int cset;                  /* the curve's drive is set (its first point may be under way) */
    int cstatus;               /* ADH_CONTINUE while the curve can go on, ADH_SUCCESS
                                  once it came down to its end, else the error that
                                  stopped it (shown, never hidden) */
    adh_static_result sres;    /* summary of the points computed so far */
    adh_visco_result vres;     /* in physical time: the run's summary so far */
    const adh_rule_type *srule; /* the curve's rule: static, or in physical time visco or path */
    struct {                   /* what the curve was computed for */
        adh_material mat;
        adh_grid_spec grid;
        double start, end;
        const adh_rule_type *rule;
        adh_time_settings time;
    } ckey;
    adh_state *cprof[2];       /* profiles kept: first point in contact, pull-off */
    size_t cprof_at[2];        /* their points */
} tui_sim;

/* The screen's state for cfg (copied: the session's one configuration).
 * 0, or -1 with why when a value is outside its limits. */
int tui_sim_init(tui_sim *s, const adh_config *cfg, char *why, size_t whylen);
void tui_sim_free(tui_sim *s);

/* The text of a parameter's value as the panel shows it ("10 µm"; "um"
 * without utf8): in the unit the panel reads a bare number in. */
void tui_sim_param_text(const tui_sim *s, tui_param p, int utf8, char *buf, size_t len);
/* The turns as a sentence says them: all of them, shallowest first
 * ("2, 1.5, 1, 0 nm"), or "none". */
void tui_sim_turns_text(const tui_sim *s, char *buf, size_t len);
/* That unit for p's present value ("nm", "GPa"; "" for N), and its factor
 * to SI. */
const char *tui_sim_param_unit(const tui_sim *s, tui_param p, int utf8, double *factor);
/* Looks up a :set name; -1 when unknown. */
int tui_sim_param_lookup(const char *name);
/* The field that edits a configuration key; -1 when none does. */
int tui_sim_field(const char *key);

/* Sets field p from text with units; a bare number is in the unit the
 * panel shows beside it (tui_sim_param_unit). 0 when set (a change to the physics
 * starts a new path from the start); -1 with a sentence naming the value and
 * what is allowed in why, nothing changed. */
int tui_sim_set(tui_sim *s, tui_param p, const char *text, char *why, size_t whylen);
/* Multiplies field p by factor, same rules. */
int tui_sim_scale(tui_sim *s, tui_param p, double factor, char *why, size_t whylen);
/* Sets a key of the run specification (adh_config_set: "protocol.dwell",
 * "grid.fine_band"), as an edit of the screen: the same checks, the same
 * undo. */
int tui_sim_set_key(tui_sim *s, const char *key, const char *text, char *why, size_t whylen);
/* A sentence of the configuration's or the core's in the TUI's words: a
 * key or flag it names becomes the field or the :set that changes it. */
void tui_sim_words(const char *sentence, char *out, size_t len);
/* The turning points (the config's, shallowest first), and how many. */
const double *tui_sim_turns(const tui_sim *s, size_t *n);
/* The mode on screen: ADH_MODE_RELAX, ADH_MODE_STATIC or ADH_MODE_TIME. */
adh_mode tui_sim_mode(const tui_sim *s);
/* Whether the screen steps a curve (static mode, physical time): points
 * computed once, walked back and forth. */
int tui_sim_curve_mode(const tui_sim *s);
/* Whether field p is on the panel: physical time's only in physical time
 * (Einf and tau for a solid), eps and d only outside it. */
int tui_sim_param_shown(const tui_sim *s, tui_param p);

/* Switches between relaxation and static mode. Nothing is computed: each
 * mode finds its path or curve as it left it (unless the parameters it
 * depends on changed meanwhile). A step in progress is dropped. */
void tui_sim_set_mode(tui_sim *s, adh_mode mode);
/* The curve's end (the turn, or -5 nm without one). */
double tui_sim_curve_end(const tui_sim *s);
/* Static mode: the points computed so far (all of them, past the cursor
 * too), and the states kept for profiles (which 0: first point in contact,
 * 1: pull-off, 2: the last point computed; NULL when none), with the point
 * each belongs to (a pull-off past a start in contact, on the curve beyond
 * the start, is no point's: the start's, 0). */
const adh_obs *tui_sim_curve(const tui_sim *s, size_t *n);
const adh_state *tui_sim_curve_profile(const tui_sim *s, int which, size_t *at);
/* The last fold the curve passed (0 when none yet, else the fold count). */
size_t tui_sim_curve_fold(const tui_sim *s, adh_static_fold *last);

/* Starts a drive step: dir +1 approaches by d, -1 retracts by d (by hand;
 * the first step also solves the start), 0 takes the protocol's next step
 * (r). Builds the grid and kernel first if needed (which can take a second
 * at large N). 0, or -1 with why (out of the model's reach; the protocol
 * complete).
 * In static mode +1 is the next point of the curve (computed when past the
 * last one) and -1 the previous point (computed before: nothing is solved,
 * the equilibrium curve being the same whichever way the drive moves); -1
 * with why at the start, at the curve's end or after the solver stopped. */
int tui_sim_begin(tui_sim *s, int dir, char *why, size_t whylen);
/* Up to batch iterations of the step in progress (tui_work: busy, a step
 * done, the protocol complete, or a failure with why). */
tui_work tui_sim_work(tui_sim *s, size_t batch, char *why, size_t whylen);
/* Abandons the step in progress: back to the last state on the history. */
void tui_sim_cancel(tui_sim *s);

/* What the last row meant (adh_drive_events: ADH_DRIVE_*), 0 in static
 * mode or before a row. */
unsigned tui_sim_events(const tui_sim *s);
/* Which way the protocol's next step goes (adh_drive_next): +1 loading
 * (*turn its next turn, 0 none), -1 unloading turn *turn, 0 complete. */
int tui_sim_next(const tui_sim *s, size_t *turn);
/* Why the protocol has no next step (tui_sim_next 0): a sentence, "the
 * protocol is complete ..." or the status that stopped it. */
void tui_sim_why_done(const tui_sim *s, char *buf, size_t len);
/* Why the curve (static mode, physical time) stopped on an error: the
 * core's sentence with the screen's words for what may get past it,
 * written to buf and returned; "" when it goes on, finished or has none. */
const char *tui_sim_stop_reason(const tui_sim *s, char *buf, size_t len);
/* The run's turn i (0-based, in the order reached) in words: "turn 3 of 8"
 * for a turn of the protocol, "the turn at h0 = 1.5 nm" for one made by
 * hand (b on the loading branch). */
void tui_sim_turn_name(const tui_sim *s, size_t i, char *buf, size_t len);
/* The relaxation path's record (rows, turns, pull-offs), as --batch's. */
const adh_run *tui_sim_run(const tui_sim *s);

/* Undo walks back along the path (static mode: the curve); at its first
 * state it takes back the last edit, restoring the run specification before
 * it and the path it had (edit_moved names the key). Redo the other way.
 * ADH_SUCCESS or ADH_EINVAL: nothing to undo (redo). */
int tui_sim_undo(tui_sim *s);
int tui_sim_redo(tui_sim *s);
/* Forgets the path (static mode: the curve): the next step starts from the
 * start position. */
void tui_sim_reset(tui_sim *s);

/* The current row (NULL before the first step), and the path's rows (in
 * static mode the curve's points up to the one shown). */
const adh_obs *tui_sim_row(const tui_sim *s);
const adh_obs *tui_sim_rows(const tui_sim *s, size_t *n);
size_t tui_sim_redoable(const tui_sim *s);
/* The relaxation path measured as a cycle (max load, pull-off, jumps,
 * hysteresis): adh_cycle_measure() of its rows. */
void tui_sim_cycle(const tui_sim *s, adh_cycle *c);
/* Where the step in progress goes (static mode: the point's start). */
double tui_sim_target(const tui_sim *s);
/* Iterations so far of the step in progress, and its convergence measure. */
size_t tui_sim_progress(const tui_sim *s, double *change);
double tui_sim_spacing(const tui_sim *s);
/* The grid on screen (the mode's: asked for, or chosen for the material). */
const adh_grid_spec *tui_sim_grid(const tui_sim *s);
/* Whether the next step of the mode on screen first builds its grid and
 * kernel (the first step, or the grid changed): a moment at large N. */
int tui_sim_will_build(const tui_sim *s);
/* Kernels this session has built: the path's, the curve's and the start
 * check's (an edit that leaves the grid builds none). */
size_t tui_sim_kernels_built(const tui_sim *s);

#endif
