/* The physics session behind the TUI: the parameters on screen, the grid,
 * kernel and relaxation solver built from them, and the history of relaxed
 * states. Only core API calls; no curses, so the loop decides when to draw.
 *
 * A drive step is solved in batches (tui_sim_work) so the loop can poll keys
 * and draw progress between them. The grid and kernel are built on the first
 * step after N or the spacing changed, never for a material change. */
#ifndef ADH_TUI_SIM_H
#define ADH_TUI_SIM_H

#include <stddef.h>

#include "adhere/grid.h"
#include "adhere/history.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/relax.h"
#include "adhere/units.h"
#include "scene/config.h"

/* The editable parameters, in panel order. */
typedef enum tui_param {
    P_E = 0, P_A, P_Z0, P_R, P_EPS, P_D, P_N, P_SPACING, P_TURN, P_COUNT
} tui_param;

typedef struct tui_param_info {
    const char *name;      /* the :set name */
    const char *label;     /* on screen (UTF-8) */
    const char *ascii;     /* on screen without UTF-8 */
    const char *what;
    adh_quantity q;        /* ADH_Q_NONE: a count */
} tui_param_info;

extern const tui_param_info tui_params[P_COUNT];

typedef struct tui_sim {
    adh_material mat;
    adh_derived der;
    size_t nodes;
    double spacing;            /* NAN: scaled with sqrt(R z0) */
    adh_kernel_type kernel;
    adh_relax_settings relax;
    double step;               /* d */
    double start_opt;          /* the configured start, NAN = automatic */
    double turn;               /* where r stops loading */
    double start;              /* the start in use */

    adh_grid *g;
    adh_kernel *k;
    adh_relax *w;
    adh_history *hist;
    int grid_stale;            /* N or spacing changed since the kernel was built */

    /* the step being solved */
    int busy;
    int solving_start;         /* the first state, at the start position */
    int then_dir;              /* the step asked for once the start is solved */
    int dir;                   /* +1 approach (loading), -1 retract */
    double target;
    double t0;
    char warn[256];            /* about the last step; "" when fine */
    char gridwarn[512];        /* why the grid may not hold the run to the turn; "" */
} tui_sim;

int tui_sim_init(tui_sim *s, const adh_config *cfg, char *why, size_t whylen);
void tui_sim_free(tui_sim *s);

/* The text of a parameter's value as the panel shows it. */
void tui_sim_param_text(const tui_sim *s, tui_param p, char *buf, size_t len);
/* Looks up a :set name; -1 when unknown. */
int tui_sim_param_lookup(const char *name);

/* Sets parameter p from text with units. 0 when set (a change to the physics
 * starts a new path from the start); -1 with a sentence naming the value and
 * what is allowed in why, nothing changed. */
int tui_sim_set(tui_sim *s, tui_param p, const char *text, char *why, size_t whylen);
/* Multiplies parameter p by factor, same rules. */
int tui_sim_scale(tui_sim *s, tui_param p, double factor, char *why, size_t whylen);

/* Starts a drive step in direction dir (+1 approach, -1 retract). Builds the
 * grid and kernel first if needed (which can take a second at large N).
 * With stay, the drive does not move: the state is relaxed again where it
 * is, as the first row of a new branch (how --batch begins unloading at a
 * turn). 0, or -1 with why. */
int tui_sim_begin(tui_sim *s, int dir, int stay, char *why, size_t whylen);
/* Up to batch iterations of the step in progress. ADH_CONTINUE while not
 * done; ADH_SUCCESS when the step is done and on the history (a step that
 * hit the iteration cap is done too, with s->warn saying so); an error code
 * with why when the step failed (the state is back where it was). */
int tui_sim_work(tui_sim *s, size_t batch, char *why, size_t whylen);
/* Abandons the step in progress: back to the last state on the history. */
void tui_sim_cancel(tui_sim *s);

int tui_sim_undo(tui_sim *s);   /* ADH_SUCCESS or ADH_EINVAL: nothing to undo */
int tui_sim_redo(tui_sim *s);
/* Forgets the path: the next step starts from the start position. */
void tui_sim_reset(tui_sim *s);

/* The current row (NULL before the first step), and the path's rows. */
const adh_obs *tui_sim_row(const tui_sim *s);
const adh_obs *tui_sim_rows(const tui_sim *s, size_t *n);
size_t tui_sim_redoable(const tui_sim *s);
/* Iterations so far of the step in progress, and its convergence measure. */
size_t tui_sim_progress(const tui_sim *s, double *change);
double tui_sim_spacing(const tui_sim *s);

#endif
