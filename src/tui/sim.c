#include "tui/sim.h"
#include "adhere/clock.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/drive.h"
#include "adhere/maugis.h"
#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/protocol.h"
#include "adhere/rings.h"
#include "adhere/rule_static.h"
#include "adhere/status.h"
#include "scene/budget.h"

static tui_params_set params_get(const tui_sim *s);
static int params_check(const tui_sim *s, const tui_params_set *p, adh_mode mode, char *why, size_t whylen);
static void params_config(const tui_sim *s, const tui_params_set *p, adh_config *c);
static adh_protocol_settings params_protocol(const tui_params_set *p);
static void drive_attach(tui_sim *s);
static void sync_turn(tui_sim *s);

/* Turning points deepest last: the order --batch reaches them in. */
static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

const tui_param_info tui_params[P_COUNT] = {
    [P_E] = { "E", "E", "E", "combined modulus", ADH_Q_PRESSURE },
    [P_A] = { "A", "A", "A", "Hamaker constant", ADH_Q_ENERGY },
    [P_Z0] = { "z0", "z0", "z0", "equilibrium gap", ADH_Q_LENGTH },
    [P_R] = { "R", "R", "R", "sphere radius", ADH_Q_LENGTH },
    [P_EPS] = { "eps", "\xce\xb5", "eps", "convergence (eps)", ADH_Q_LENGTH },
    [P_D] = { "d", "d", "d", "drive step", ADH_Q_LENGTH },
    [P_N] = { "N", "N", "N", "grid nodes", ADH_Q_NONE },
    [P_SPACING] = { "spacing", "\xce\x94", "dr", "grid spacing", ADH_Q_LENGTH },
    [P_TURN] = { "turn", "turn", "turn", "turning point", ADH_Q_LENGTH },
};

double tui_sim_spacing(const tui_sim *s)
{
    return isnan(s->spacing) ? adh_grid_spacing_for(&s->mat, s->nodes) : s->spacing;
}

/* The configuration of the grid for parameters p: the one the screen
 * started from, with p's material, protocol and grid. */
static void params_config(const tui_sim *s, const tui_params_set *p, adh_config *c)
{
    *c = s->base;
    c->mat = p->mat;
    c->relax = p->relax;
    c->mode = s->mode;
    c->proto.step = p->step;
    c->proto.start = p->start_opt;
    c->proto.nturns = p->nturns;
    memcpy(c->proto.turns, p->turns, p->nturns * sizeof *p->turns);
    c->nodes = p->nodes;
    c->spacing = p->spacing;
    c->graded = p->grid.graded;
    c->fine_band = p->grid.fine_band;
    c->growth = p->grid.growth;
    c->grid_radius = p->grid.grid_radius;
    c->kernel = p->grid.kernel;
    c->storage = p->grid.storage;
    c->grid_chosen = p->grid_auto;
}

/* The grid as it stands in c: N and the spacing resolved, and a graded
 * grid's automatic band and radius (they follow the material and turns). */
static adh_grid_asked grid_of(const adh_config *c)
{
    adh_grid_asked g = { c->nodes, adh_config_spacing(c), c->fine_band, c->growth, c->grid_radius,
                         c->kernel, c->storage, c->graded };
    if (c->graded) {
        adh_rings_spec rs = adh_config_rings(c);
        g.fine_band = rs.fine;
        g.grid_radius = rs.rmax;
        g.growth = rs.ratio;
    }
    return g;
}

static int same_grid(const adh_grid_asked *a, const adh_grid_asked *b)
{
    /* NAN fields (automatic band, radius) are equal when both are NAN */
    #define SAME(x) (a->x == b->x || (isnan((double)a->x) && isnan((double)b->x)))
    return a->nodes == b->nodes && SAME(spacing) && SAME(fine_band) && SAME(growth) && SAME(grid_radius) &&
           a->kernel == b->kernel && a->storage == b->storage && a->graded == b->graded;
    #undef SAME
}

/* The configuration of the parameters on screen for a mode: an automatic
 * grid is chosen per mode, as --batch --mode would (the static curve needs
 * finer rings), so the other mode's grid is chosen again; a grid given
 * stays as given. */
static void mode_config(const tui_sim *s, const tui_params_set *p, adh_mode mode, adh_config *c)
{
    params_config(s, p, c);
    c->mode = mode;
    if (mode != s->mode && p->grid_auto) {
        char why[512];
        adh_config_grid_again(c, why, sizeof why);   /* a refusal keeps the grid as it is (solves say why) */
    }
    adh_budget_operator(c);   /* the operator --batch would hold this grid in */
}

static adh_grid_asked mode_grid(const tui_sim *s, const tui_params_set *p, adh_mode mode)
{
    adh_config c;
    mode_config(s, p, mode, &c);
    return grid_of(&c);
}

/* Whether the relaxation's grid for the parameters on screen is another
 * than the one its kernel was built for. */
static int grid_changed(const tui_sim *s)
{
    tui_params_set p = params_get(s);
    adh_grid_asked now = mode_grid(s, &p, ADH_MODE_RELAX);
    return !same_grid(&s->built, &now);
}

/* A grid that follows the material chooses again for p, as --batch would
 * for these parameters; a refusal keeps the grid asked for and says why
 * (solves are then refused). */
static void params_regrid(const tui_sim *s, tui_params_set *p, char *why, size_t whylen)
{
    why[0] = '\0';
    if (!p->grid_auto)
        return;
    adh_config c;
    params_config(s, p, &c);
    if (adh_config_grid_again(&c, why, whylen) == 0)
        why[0] = '\0';
    p->nodes = c.nodes;
    p->spacing = c.spacing;
    p->grid = (adh_grid_asked){ c.nodes, c.spacing, c.fine_band, c.growth, c.grid_radius, c.kernel, c.storage,
                                c.graded };
}

/* An automatic grid on screen is the mode's: chosen again (N, spacing and
 * the rest shown) when the mode changed or parameters came back by undo;
 * gridchoice says why none could be chosen. */
static void grid_follow_mode(tui_sim *s)
{
    tui_params_set q = params_get(s);
    params_regrid(s, &q, s->gridchoice, sizeof s->gridchoice);
    if (!s->grid_auto)
        return;
    s->nodes = q.nodes;
    s->spacing = q.spacing;
    s->grid = q.grid;
}

enum { PROF_CONTACT = 0, PROF_PULLOFF = 1 };
#define NO_POINT SIZE_MAX

/* Forgets the static curve (its points, summary, profiles); the solver
 * itself stays allocated for the next curve on the same grid. */
static void curve_drop(tui_sim *s)
{
    s->curve.nrows = 0;
    s->ccur = 0;
    s->walk = 0;
    s->cstatus = ADH_CONTINUE;
    memset(&s->sres, 0, sizeof s->sres);
    s->sres.jump_in_h0 = s->sres.jump_out_h0 = s->sres.pulloff_F_disp = NAN;
    s->sres.pulloff_F = s->sres.pulloff_h0 = NAN;
    s->cprof_at[PROF_CONTACT] = s->cprof_at[PROF_PULLOFF] = NO_POINT;
}

double tui_sim_curve_end(const tui_sim *s)
{
    tui_params_set q = params_get(s);
    adh_protocol_settings ps = params_protocol(&q);
    return adh_rule_static_end(&ps);
}

static int curve_started(const tui_sim *s)
{
    return s->curve.nrows > 0 || s->cstatus != ADH_CONTINUE;
}

/* A curve belongs to the material, grid, start and end it was computed
 * for: when one of them changed, it is dropped (eps and d alone do not
 * touch it, unless d moved an automatic start). */
static void curve_check(tui_sim *s)
{
    if (!curve_started(s))
        return;
    const adh_material *a = &s->ckey.mat, *b = &s->mat;
    tui_params_set p = params_get(s);
    adh_grid_asked g = mode_grid(s, &p, ADH_MODE_STATIC);
    if (a->E != b->E || a->A != b->A || a->z0 != b->z0 || a->R != b->R || !same_grid(&s->ckey.grid, &g) ||
        s->ckey.start != s->start || s->ckey.end != tui_sim_curve_end(s))
        curve_drop(s);
}

/* The static curve's solver, grid and kernel, and the curve on them. */
static void free_static(tui_sim *s)
{
    adh_drive_free(s->sdrv);
    s->sdrv = NULL;
    for (int i = 0; i < 2; i++) {
        adh_state_free(s->cprof[i]);
        s->cprof[i] = NULL;
    }
    curve_drop(s);
    adh_kernel_free(s->sk);
    adh_grid_free(s->sg);
    s->sk = NULL;
    s->sg = NULL;
}

/* The relaxation's solver, grid and kernel (the path's states stay in its
 * history). */
static void free_solver(tui_sim *s)
{
    adh_drive_free(s->drv);
    adh_kernel_free(s->k);
    adh_grid_free(s->g);
    s->drv = NULL;
    s->k = NULL;
    s->g = NULL;
}

static void path_free(tui_path *p)
{
    adh_history_free(p->hist);
    p->hist = NULL;
    adh_run_free(&p->run);
    adh_run_init(&p->run);
}

/* Moves the path on screen out (the screen's becomes empty). */
static tui_path path_take(tui_sim *s)
{
    tui_path p = s->path;
    s->path.hist = NULL;
    adh_run_init(&s->path.run);
    return p;
}

static size_t path_length(const tui_sim *s)
{
    return s->path.hist ? adh_history_length(s->path.hist) : 0;
}

static void edits_clear(tui_edit *e, size_t *n)
{
    for (size_t i = 0; i < *n; i++)
        path_free(&e[i].path);
    *n = 0;
}

/* The batch run's own check of grid and protocol, before any solve: a
 * newcomer who sets N = 100 learns the contact will not fit before
 * stepping into it, and a solve is refused, as --batch refuses the run. */

static void check_grid(tui_sim *s)
{
    adh_grid_check(&s->mat, s->mode == ADH_MODE_STATIC ? ADH_GRID_STATIC : ADH_GRID_RELAX, s->nodes,
                   tui_sim_spacing(s), &s->gridres);
    /* the resolution itself is shown on the Derived panel's E* line */
    tui_params_set p = params_get(s);
    if (s->gridchoice[0])   /* no grid resolves this material within the budget */
        snprintf(s->gridwarn, sizeof s->gridwarn, "%s", s->gridchoice);
    else if (params_check(s, &p, s->mode, s->gridwarn, sizeof s->gridwarn) == ADH_SUCCESS)
        s->gridwarn[0] = '\0';
}

/* The closed forms for the material on screen: recomputed with it. */
static void derive(tui_sim *s)
{
    adh_material_derive(&s->mat, &s->der);
    tui_models *m = &s->models;
    m->md_lambda = adh_md_lambda(&s->mat);
    double ov = NAN;
    if (adh_md_pulloff(&s->mat, m->md_lambda, &m->md_pulloff, NULL, NULL, &ov) != ADH_SUCCESS)
        m->md_pulloff = ov = NAN;
    m->md_jump_out = s->mat.z0 - ov;
    m->jump_in = adh_bulge_position(&s->mat, adh_jump_separation(&s->mat));
}

/* A change to the physics: the old path no longer belongs to these
 * parameters, so it is dropped and the next step starts at the start. */
static void new_path(tui_sim *s)
{
    s->start = isnan(s->start_opt) ? adh_protocol_auto_start(&s->mat, s->step) : s->start_opt;
    s->busy = 0;
    s->warn[0] = '\0';
    if (s->path.hist)
        adh_history_clear(s->path.hist);
    adh_run_free(&s->path.run);
    adh_run_init(&s->path.run);
    if (s->drv && !grid_changed(s))
        drive_attach(s);
    /* An automatic spacing follows sqrt(R z0): when R or z0 moved it, the
     * grid is a different grid and the kernel must follow. E and A never
     * get here with a changed spacing, so they never rebuild it. */
    if (s->g && grid_changed(s))
        s->grid_stale = 1;
    check_grid(s);
    curve_check(s);
}

int tui_sim_init(tui_sim *s, const adh_config *cfg, char *why, size_t whylen)
{
    memset(s, 0, sizeof *s);
    adh_run_init(&s->curve);
    adh_run_init(&s->path.run);
    s->mat = cfg->mat;
    s->nodes = cfg->nodes;
    s->spacing = cfg->spacing;
    s->base = *cfg;
    s->grid_auto = cfg->grid_chosen;
    s->grid = (adh_grid_asked){ cfg->nodes, cfg->spacing, cfg->fine_band, cfg->growth, cfg->grid_radius,
                                cfg->kernel, cfg->storage, cfg->graded };
    s->relax = cfg->relax;
    s->step = cfg->proto.step;
    s->start_opt = cfg->proto.start;
    s->nturns = cfg->proto.nturns < ADH_MAX_TURNS ? cfg->proto.nturns : ADH_MAX_TURNS;
    memcpy(s->turns, cfg->proto.turns, s->nturns * sizeof *s->turns);
    qsort(s->turns, s->nturns, sizeof *s->turns, cmp_desc);
    s->tcur = 0;
    s->turn = s->nturns ? s->turns[0] : NAN;
    tui_params_set p = params_get(s);
    if (params_check(s, &p, cfg->mode, why, whylen) == ADH_EINVAL)
        return -1;
    derive(s);
    s->grid_stale = 1;
    s->edit_moved = -1;
    s->mode = cfg->mode == ADH_MODE_STATIC ? ADH_MODE_STATIC : ADH_MODE_RELAX;
    curve_drop(s);
    new_path(s);
    return 0;
}

void tui_sim_free(tui_sim *s)
{
    free_static(s);
    free_solver(s);
    path_free(&s->path);
    edits_clear(s->undo_edits, &s->nundo_edits);
    edits_clear(s->redo_edits, &s->nredo_edits);
    adh_run_free(&s->curve);
}

/* Puts the drive on the path on screen: set for the parameters on screen,
 * then restored where the path is (a path given back by undo goes on from
 * where it was). */
static void drive_attach(tui_sim *s)
{
    tui_params_set p = params_get(s);
    adh_protocol_settings ps = params_protocol(&p);
    adh_drive_set(s->drv, &s->mat, &s->relax, &ps, &s->path.run);
    if (path_length(s) && adh_history_restore(s->path.hist, s->drv) != ADH_SUCCESS) {
        adh_history_clear(s->path.hist);   /* states of another grid: not this path's any more */
        adh_run_free(&s->path.run);
        adh_run_init(&s->path.run);
        adh_drive_set(s->drv, &s->mat, &s->relax, &ps, &s->path.run);
    } else if (path_length(s)) {
        adh_drive_retarget(s->drv, &ps);   /* the snapshot counted its turns against the turns of its time */
    }
}

static int ensure_solver(tui_sim *s, char *why, size_t whylen)
{
    if (!s->path.hist && !(s->path.hist = adh_history_alloc())) {
        snprintf(why, whylen, "out of memory for the path");
        return -1;
    }
    if (s->drv && !s->grid_stale)
        return 0;
    free_solver(s);
    /* the grid, kernel and operator --batch builds for these parameters */
    adh_config c;
    tui_params_set p = params_get(s);
    mode_config(s, &p, ADH_MODE_RELAX, &c);
    if (adh_budget_check(&c, 0, why, whylen) != 0)
        return -1;
    int st;
    s->g = adh_config_grid_alloc(&c);
    s->k = s->g ? adh_config_kernel_alloc(&c, s->g, &st) : NULL;
    s->drv = s->k ? adh_drive_alloc(&adh_rule_relax, s->g, s->k) : NULL;
    s->built = grid_of(&c);
    if (!s->drv) {
        free_solver(s);
        snprintf(why, whylen, "out of memory for a grid of N = %zu nodes: try fewer", c.nodes);
        return -1;
    }
    s->grid_stale = 0;
    drive_attach(s);
    return 0;
}

/* The static curve's grid, kernel and drive for the parameters on screen:
 * built on its first point, and again (the curve dropped) when that grid
 * changed. */
static int ensure_static(tui_sim *s, char *why, size_t whylen)
{
    adh_config c;
    tui_params_set p = params_get(s);
    mode_config(s, &p, ADH_MODE_STATIC, &c);
    adh_grid_asked now = grid_of(&c);
    if (s->sdrv && same_grid(&s->sbuilt, &now))
        return 0;
    free_static(s);
    if (adh_budget_check(&c, 1, why, whylen) != 0)
        return -1;
    int st;
    s->sg = adh_config_grid_alloc(&c);
    s->sk = s->sg ? adh_config_kernel_alloc(&c, s->sg, &st) : NULL;
    s->sdrv = s->sk ? adh_drive_alloc(&adh_rule_static, s->sg, s->sk) : NULL;
    s->sbuilt = now;
    if (!s->sdrv) {
        free_static(s);
        snprintf(why, whylen, "out of memory for the static solver on a grid of N = %zu nodes: try fewer", c.nodes);
        return -1;
    }
    return 0;
}

static tui_params_set params_get(const tui_sim *s)
{
    tui_params_set p = { s->mat, s->nodes, s->spacing, s->step, s->start_opt, s->turn, s->start, s->grid_auto,
                         s->grid, s->relax, { 0 }, s->nturns, s->tcur };
    memcpy(p.turns, s->turns, s->nturns * sizeof *s->turns);
    return p;
}

/* Pushes e on a stack of at most TUI_MAX_EDITS, forgetting the oldest. */
static void edits_push(tui_edit *st, size_t *n, const tui_edit *e)
{
    if (*n == TUI_MAX_EDITS) {
        path_free(&st[0].path);
        memmove(st, st + 1, (TUI_MAX_EDITS - 1) * sizeof *st);
        (*n)--;
    }
    st[(*n)++] = *e;
}

/* Swaps the parameters and path on screen with those of edit e (popped
 * from one stack), pushing what was on screen on the other. */
static void edit_swap(tui_sim *s, tui_edit *from, size_t *nfrom, tui_edit *to, size_t *nto)
{
    tui_edit e = from[--(*nfrom)], back = { params_get(s), e.param, e.keeps_path, { .hist = NULL } };
    adh_run_init(&back.path.run);
    tui_sim_cancel(s);
    if (!e.keeps_path) {
        back.path = path_take(s);
        s->path = e.path;
    }
    edits_push(to, nto, &back);
    s->mat = e.par.mat;
    s->nodes = e.par.nodes;
    s->spacing = e.par.spacing;
    s->grid_auto = e.par.grid_auto;
    s->grid = e.par.grid;
    s->step = e.par.step;
    s->start_opt = e.par.start_opt;
    s->turn = e.par.turn;
    memcpy(s->turns, e.par.turns, e.par.nturns * sizeof *s->turns);
    s->nturns = e.par.nturns;
    s->tcur = e.par.tcur;
    s->start = e.par.start;
    s->relax = e.par.relax;
    grid_follow_mode(s);   /* they may have been set in the other mode */
    derive(s);
    s->warn[0] = '\0';
    if (s->g)
        s->grid_stale = grid_changed(s);
    if (s->drv && !s->grid_stale) {
        drive_attach(s);
    } else if (path_length(s)) {
        /* the path's states are on their own grid: build it now, so plots
         * and the next step find grid and states agreeing */
        char why[256];
        if (ensure_solver(s, why, sizeof why) != 0)
            path_free(&s->path);
    }
    sync_turn(s);
    check_grid(s);
    curve_check(s);
    s->edit_moved = e.param;
}

/* The value of parameter p in SI (NAN: not set). */
static double param_value(const tui_sim *s, tui_param p)
{
    switch (p) {
    case P_E: return s->mat.E;
    case P_A: return s->mat.A;
    case P_Z0: return s->mat.z0;
    case P_R: return s->mat.R;
    case P_EPS: return s->relax.eps;
    case P_D: return s->step;
    case P_N: return (double)s->nodes;
    case P_SPACING: return tui_sim_spacing(s);
    case P_TURN: return s->turn;
    default: return NAN;
    }
}

const char *tui_sim_param_unit(const tui_sim *s, tui_param p, int utf8, double *factor)
{
    const char *um = utf8 ? "\xc2\xb5m" : "um";
    double v = param_value(s, p);
    *factor = 1;
    switch (p) {
    /* moduli in the units of the literature: GPa for glasses and metals,
     * MPa for polymers and gels, kPa below */
    case P_E:
        if (v >= 0.9995e9) { *factor = 1e9; return "GPa"; }
        if (v >= 0.9995e6) { *factor = 1e6; return "MPa"; }
        *factor = 1e3;
        return "kPa";
    case P_A: return "J";
    /* gaps, steps and positions in nm, as an AFM reads them */
    case P_Z0: case P_D: case P_SPACING: case P_TURN: *factor = 1e-9; return "nm";
    case P_R:
        if (v >= 0.9995e-3) { *factor = 1e-3; return "mm"; }
        *factor = 1e-6;
        return um;
    case P_EPS: *factor = 1e-12; return "pm";
    default: return "";
    }
}

void tui_sim_param_text(const tui_sim *s, tui_param p, int utf8, char *buf, size_t len)
{
    double f, v = param_value(s, p);
    const char *unit = tui_sim_param_unit(s, p, utf8, &f);
    if (p == P_N)
        snprintf(buf, len, "%zu", s->nodes);
    else if (p == P_TURN && isnan(v))
        snprintf(buf, len, "none");
    else if (p == P_A)
        snprintf(buf, len, "%.4g J", v);
    else
        snprintf(buf, len, "%.4g %s", v / f, unit);
}

int tui_sim_param_lookup(const char *name)
{
    for (int p = 0; p < P_COUNT; p++)
        if (strcmp(name, tui_params[p].name) == 0)
            return p;
    return -1;
}

/* Every parameter change goes through here, from typed text or a scale key. */
static int set_value_(tui_sim *s, tui_param p, double v, char *why, size_t whylen);

/* The turns an edit of the turn gives: the list typed (staged by
 * tui_sim_set) or the one value v (NAN: none), shallowest first. */
static void params_turns(const tui_sim *s, tui_params_set *np, double v)
{
    if (s->nstage) {
        memcpy(np->turns, s->stage_turns, s->nstage * sizeof *np->turns);
        np->nturns = s->nstage;
    } else {
        np->turns[0] = v;
        np->nturns = isnan(v) ? 0 : 1;
    }
    qsort(np->turns, np->nturns, sizeof *np->turns, cmp_desc);
    np->tcur = 0;
    np->turn = np->nturns ? np->turns[0] : NAN;
}

/* Whether an edit of the turn to v changes a grid that follows the
 * material (a deeper turn needs a larger one): the path cannot stay. */
static int turn_regrids(const tui_sim *s, double v)
{
    if (!s->g)
        return 0;   /* no grid built yet: nothing to keep */
    tui_params_set np = params_get(s), now = np;
    params_turns(s, &np, v);
    char why[512];
    params_regrid(s, &np, why, sizeof why);
    /* the path is the relaxation's: its grid decides, in either mode */
    adh_grid_asked ga = mode_grid(s, &np, ADH_MODE_RELAX), gb = mode_grid(s, &now, ADH_MODE_RELAX);
    return !same_grid(&ga, &gb);
}

/* An edit that took is put on the undo stack with the parameters before it
 * and (unless it kept the path) the path they had; the path on screen
 * starts afresh. */
static int set_value(tui_sim *s, tui_param p, double v, char *why, size_t whylen)
{
    tui_edit e = { params_get(s), (int)p, p == P_TURN && !turn_regrids(s, v), { .hist = NULL } };
    adh_run_init(&e.path.run);
    if (!e.keeps_path)
        e.path = path_take(s);   /* the next step starts a new one */
    if (set_value_(s, p, v, why, whylen) != 0) {
        if (!e.keeps_path) {
            path_free(&s->path);
            s->path = e.path;
        }
        return -1;
    }
    edits_push(s->undo_edits, &s->nundo_edits, &e);
    edits_clear(s->redo_edits, &s->nredo_edits);
    s->edit_kept_path = e.keeps_path;
    return 0;
}

/* The protocol the parameters p describe, as --batch would run it. */
static adh_protocol_settings params_protocol(const tui_params_set *p)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.start = p->start_opt;
    ps.step = p->step;
    ps.nturns = p->nturns;
    memcpy(ps.turns, p->turns, p->nturns * sizeof *p->turns);
    return ps;
}

static double params_spacing(const tui_params_set *p)
{
    return isnan(p->spacing) ? adh_grid_spacing_for(&p->mat, p->nodes) : p->spacing;
}

/* The core's one check of every limit, the one --batch and scene files
 * meet: ADH_EINVAL refuses an edit; ADH_EGRID (a grid that cannot hold
 * the run) lets it through, shown, and a solve is refused until mended. */
static int params_check(const tui_sim *s, const tui_params_set *p, adh_mode mode, char *why, size_t whylen)
{
    adh_protocol_settings ps = params_protocol(p);
    adh_grid_use use = mode == ADH_MODE_STATIC ? ADH_GRID_STATIC : ADH_GRID_RELAX;
    if (!p->grid.graded) {
        adh_grid g = adh_drive_uniform_grid(p->nodes, params_spacing(p));
        return adh_drive_check(&p->mat, &p->relax, &ps, use, &g, why, whylen, NULL);
    }
    /* rings: the check reads their edges (cheap to lay out; no kernel) */
    adh_config c;
    params_config(s, p, &c);
    int rc = ADH_EGRID;
    if (adh_config_grid_check(&c, why, whylen) != 0)
        return ADH_EINVAL;
    adh_grid *g = adh_config_grid_alloc(&c);
    if (!g)
        snprintf(why, whylen, "out of memory for a graded grid of %zu rings", p->nodes);
    else
        rc = adh_drive_check(&p->mat, &p->relax, &ps, use, g, why, whylen, NULL);
    adh_grid_free(g);
    return rc;
}

static int set_value_(tui_sim *s, tui_param p, double v, char *why, size_t whylen)
{
    char choice[512];
    const char *name = tui_params[p].name;
    tui_params_set np = params_get(s);
    switch (p) {
    case P_E: np.mat.E = v; break;
    case P_A: np.mat.A = v; break;
    case P_Z0: np.mat.z0 = v; break;
    case P_R: np.mat.R = v; break;
    case P_EPS: np.relax.eps = v; break;
    case P_D: np.step = v; break;
    case P_N:
        /* the limits are the core's (adh_drive_check); a count beyond any
         * grid is held at 1e18 so that it converts, and is refused there */
        np.nodes = v >= 0 ? (size_t)llround(fmin(v, 1e18)) : 0;
        break;
    case P_SPACING: np.spacing = v; break;
    case P_TURN:
        params_turns(s, &np, v);
        s->nstage = 0;
        break;
    default:
        snprintf(why, whylen, "%s cannot be set", name);
        return -1;
    }
    if (p == P_N || p == P_SPACING) {
        /* a grid given: uniform, with the kernel and operator asked for, as
         * --batch -N/--spacing builds it */
        const adh_config *b = &s->base;
        np.grid_auto = 0;
        np.grid.graded = b->grid_chosen ? b->asked.graded : b->graded;
        np.grid.kernel = b->grid_chosen ? b->asked.kernel : b->kernel;
        np.grid.storage = b->grid_chosen ? b->asked.storage : b->storage;
        if (p == P_N && (s->grid_auto || (s->grid.graded && !np.grid.graded)))
            np.spacing = NAN;   /* N uniform nodes at the scaled spacing, as -N alone gives: not the
                                   automatic grid's spacing, nor N rings' fine width */
        choice[0] = '\0';
    } else if (p <= P_R || p == P_TURN) {
        /* the grid follows the material and the deepest turn, as --batch's would */
        params_regrid(s, &np, choice, sizeof choice);
    }
    char msg[512];
    if (params_check(s, &np, s->mode, msg, sizeof msg) == ADH_EINVAL) {
        snprintf(why, whylen, "%s", msg);
        return -1;
    }
    s->mat = np.mat;
    s->relax = np.relax;
    s->step = np.step;
    s->nodes = np.nodes;
    s->spacing = np.spacing;
    s->grid_auto = np.grid_auto;
    s->grid = np.grid;
    if (p == P_N || p == P_SPACING || p <= P_R || p == P_TURN)
        snprintf(s->gridchoice, sizeof s->gridchoice, "%s", choice);
    s->turn = np.turn;
    memcpy(s->turns, np.turns, np.nturns * sizeof *s->turns);
    s->nturns = np.nturns;
    s->tcur = np.tcur;
    if (p <= P_R)
        derive(s);
    if (p == P_TURN && !(s->g && grid_changed(s))) {
        /* where a run turns is not physics: the path stays, and the drive
         * turns where it is told from here on (unless the grid had to grow
         * for a deeper turn: then set_value took the path, as for E) */
        if (s->drv && !s->grid_stale) {
            tui_params_set q = params_get(s);
            adh_protocol_settings ps = params_protocol(&q);
            adh_drive_retarget(s->drv, &ps);
        }
        sync_turn(s);
        check_grid(s);
        curve_check(s);   /* but it is where the static curve ends */
        return 0;
    }
    new_path(s);
    return 0;
}

int tui_sim_set(tui_sim *s, tui_param p, const char *text, char *why, size_t whylen)
{
    const tui_param_info *pi = &tui_params[p];
    char msg[256];
    double v;
    if (p == P_N) {
        long n;
        if (adh_parse_count(text, 0, LONG_MAX, &n, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "%s: %s", pi->name, msg);
            return -1;
        }
        v = (double)n;
    } else if (p == P_SPACING && strcmp(text, "auto") == 0) {
        v = NAN;
    } else if (p == P_TURN && strchr(text, ',')) {
        /* a list of turning points, as a scene's turn = ... */
        char buf[1024];
        snprintf(buf, sizeof buf, "%s", text);
        size_t n = 0;
        for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
            while (*tok == ' ')
                tok++;
            if (n == ADH_MAX_TURNS) {
                snprintf(why, whylen, "turn: more than %d turning points in '%s'", ADH_MAX_TURNS, text);
                return -1;
            }
            double x;
            if (adh_parse_quantity(tok, ADH_Q_NONE, &x, NULL, 0) == 0) {
                double f;
                tui_sim_param_unit(s, p, 0, &f);
                x *= f;
            } else if (adh_parse_quantity(tok, pi->q, &x, msg, sizeof msg) != 0) {
                snprintf(why, whylen, "%s: %s", pi->name, msg);
                return -1;
            }
            s->stage_turns[n++] = x;
        }
        if (n == 0) {
            snprintf(why, whylen, "turn: '%s' holds no turning point: give lengths separated by commas", text);
            return -1;
        }
        s->nstage = n;
        v = s->stage_turns[0];
    } else if (adh_parse_quantity(text, ADH_Q_NONE, &v, NULL, 0) == 0) {
        /* a bare number is in the unit the panel shows beside the value */
        double f;
        tui_sim_param_unit(s, p, 0, &f);
        v *= f;
    } else if (adh_parse_quantity(text, pi->q, &v, msg, sizeof msg) != 0) {
        snprintf(why, whylen, "%s: %s", pi->name, msg);
        return -1;
    }
    return set_value(s, p, v, why, whylen);
}

int tui_sim_scale(tui_sim *s, tui_param p, double factor, char *why, size_t whylen)
{
    double v;
    switch (p) {
    case P_E: v = s->mat.E; break;
    case P_A: v = s->mat.A; break;
    case P_Z0: v = s->mat.z0; break;
    case P_R: v = s->mat.R; break;
    case P_EPS: v = s->relax.eps; break;
    case P_D: v = s->step; break;
    case P_N: v = (double)s->nodes; break;
    case P_SPACING: v = tui_sim_spacing(s); break;
    case P_TURN: v = s->turn; break;
    default: return -1;
    }
    if (isnan(v)) {
        snprintf(why, whylen, "%s is not set: type a value first", tui_params[p].name);
        return -1;
    }
    if (p == P_TURN && s->nturns > 1) {
        /* every turning point of the list, not the one on screen alone */
        for (size_t i = 0; i < s->nturns; i++)
            s->stage_turns[i] = s->turns[i] * factor;
        s->nstage = s->nturns;
        int rc = set_value(s, p, s->stage_turns[0], why, whylen);
        s->nstage = 0;
        return rc;
    }
    return set_value(s, p, p == P_N ? round(v * factor) : v * factor, why, whylen);
}

/* The index of the turning point on screen at h0 (within the drive's
 * tolerance of a millionth of a step), or nturns: a turn made by hand. */
static size_t turn_index(const tui_sim *s, double h0)
{
    size_t k = 0;
    while (k < s->nturns && !(fabs(s->turns[k] - h0) < 1e-6 * s->step))
        k++;
    return k;
}

/* The turn of the row on screen, for the panel: its branch's turn while
 * unloading, the turn it reached, else the next one loading will reach
 * (the deepest when none is left). */
static void sync_turn(tui_sim *s)
{
    s->tcur = s->nturns ? s->nturns - 1 : 0;
    s->turn = s->nturns ? s->turns[s->tcur] : NAN;
    if (!s->nturns || !s->drv || s->grid_stale)
        return;
    const adh_run *run = &s->path.run;
    const adh_obs *o = run->nrows ? &run->rows[run->nrows - 1] : NULL;
    double t = NAN;
    size_t k;
    if (o && o->branch < 0 && o->path > 0)
        t = run->turns[o->path - 1].h0;
    else if (o && (adh_drive_events(s->drv) & ADH_DRIVE_TURN))
        t = run->turns[run->nturns - 1].h0;
    else if (adh_drive_next(s->drv, &k) > 0 && k > 0)
        t = s->turns[k - 1];
    size_t i = isnan(t) ? s->nturns : turn_index(s, t);
    if (i < s->nturns) {
        s->tcur = i;
        s->turn = s->turns[i];
    }
}

/* After a restore: the drive takes the turns on screen (a turn edit since
 * the snapshot was taken keeps the path). */
static void drive_restored(tui_sim *s)
{
    tui_params_set q = params_get(s);
    adh_protocol_settings ps = params_protocol(&q);
    adh_drive_retarget(s->drv, &ps);
    sync_turn(s);
}

/* A solve on a grid the core's check refuses is refused, as --batch
 * refuses the run: with the check's sentence. */
static int grid_refuses(const tui_sim *s, char *why, size_t whylen)
{
    if (!s->gridwarn[0])
        return 0;
    snprintf(why, whylen, "%s", s->gridwarn);
    return 1;
}

/* ---- static mode: the equilibrium curve ---------------------------------- */

static int curve_begin(tui_sim *s, int dir, char *why, size_t whylen)
{
    char h0[64];
    if (dir < 0) {
        if (s->curve.nrows == 0) {
            snprintf(why, whylen, "no point of the equilibrium curve yet: f solves the first one, at the start");
            return -1;
        }
        if (s->ccur == 0) {
            snprintf(why, whylen, "this is the first point of the curve (the start): there is nothing to walk back to");
            return -1;
        }
        s->walk = -1;
    } else if (s->curve.nrows && s->ccur + 1 < s->curve.nrows) {
        s->walk = +1;   /* computed before: shown again, not solved again */
    } else if (s->cstatus == ADH_SUCCESS) {
        adh_format_quantity(s->curve.rows[s->curve.nrows - 1].h0, ADH_Q_LENGTH, 4, h0, sizeof h0);
        snprintf(why, whylen, "the curve is complete (it ends at h0 = %s): b or u walks back along it", h0);
        return -1;
    } else if (s->cstatus != ADH_CONTINUE) {
        if (s->cstatus == ADH_EGRID && s->sg && s->curve.nrows) {
            char edge[400];
            adh_rings_edge_sentence(s->sg, s->curve.rows[s->curve.nrows - 1].a, edge, sizeof edge);
            snprintf(why, whylen, "the curve stopped after %zu points: %s", s->curve.nrows, edge);
        }
        else
            snprintf(why, whylen, "the curve stopped after %zu point%s: %s; x starts it again", s->curve.nrows,
                     s->curve.nrows == 1 ? "" : "s", adh_strerror(s->cstatus));
        return -1;
    } else {
        if (grid_refuses(s, why, whylen) || ensure_static(s, why, whylen) != 0)
            return -1;
        s->walk = 0;
        s->t0 = adh_clock_seconds();
    }
    s->dir = dir;
    s->target = s->curve.nrows ? s->curve.rows[s->ccur].h0 : s->start;
    s->busy = 1;
    return 0;
}

/* Keeps the state of point i as profile which (allocated once per grid). */
static void keep_profile(tui_sim *s, int which, size_t i, const adh_state *st)
{
    if (!s->cprof[which] || s->cprof[which]->n != st->n) {
        adh_state_free(s->cprof[which]);
        s->cprof[which] = adh_state_alloc(st->n);
    }
    if (!s->cprof[which])
        return;   /* a profile less in the plots, nothing worse */
    adh_state_copy(s->cprof[which], st);
    s->cprof_at[which] = i;
}

/* The point the drive just added: shown, and kept as a profile when it is
 * the first in contact or the lowest force so far. */
static void curve_pushed(tui_sim *s, const adh_state *st)
{
    size_t i = s->curve.nrows - 1;
    const adh_obs *o = &s->curve.rows[i];
    s->ccur = i;
    if (o->a > 0 && s->cprof_at[PROF_CONTACT] == NO_POINT)
        keep_profile(s, PROF_CONTACT, i, st);
    if (s->cprof_at[PROF_PULLOFF] == NO_POINT || o->F < s->curve.rows[s->cprof_at[PROF_PULLOFF]].F)
        keep_profile(s, PROF_PULLOFF, i, st);
}

/* One accepted point of the continuation (the start point first), from
 * the drive's static step rule, or one move of the cursor over points
 * computed before. */
static int curve_work(tui_sim *s, char *why, size_t whylen)
{
    s->busy = 0;
    s->walked = s->walk != 0;
    if (s->walk) {
        s->ccur = s->walk > 0 ? s->ccur + 1 : s->ccur - 1;
        s->walk = 0;
        return ADH_SUCCESS;
    }
    if (s->curve.nrows == 0) {
        /* the relaxation's start and deepest turn: the two share an axis,
         * as in --batch */
        tui_params_set q = params_get(s);
        adh_protocol_settings ps = params_protocol(&q);
        adh_static_settings ss = adh_static_settings_default();
        s->ckey.mat = s->mat;
        s->ckey.grid = s->sbuilt;
        s->ckey.start = s->start;
        s->ckey.end = tui_sim_curve_end(s);
        adh_run_free(&s->curve);
        adh_run_init(&s->curve);
        int rc = adh_drive_set(s->sdrv, &s->mat, &ss, &ps, &s->curve);
        if (rc != ADH_SUCCESS) {
            s->cstatus = rc;
            snprintf(why, whylen, "the curve cannot start: %s", adh_strerror(rc));
            return rc;
        }
    }
    char h0[64];
    adh_format_quantity(s->curve.nrows ? s->curve.rows[s->curve.nrows - 1].h0 : s->start, ADH_Q_LENGTH, 4, h0, sizeof h0);
    int row, rc = adh_drive_iterate(s->sdrv, 0, &row);
    const adh_static *sw = adh_rule_static_solver(s->sdrv);
    adh_static_summary(sw, &s->sres);
    if (row) {
        curve_pushed(s, adh_static_state(sw));
        if (rc == ADH_CONTINUE && (adh_drive_events(s->sdrv) & ADH_DRIVE_END))
            rc = ADH_SUCCESS;   /* the curve came down to its end */
    }
    s->cstatus = rc;
    if (rc == ADH_CONTINUE || rc == ADH_SUCCESS)
        return ADH_SUCCESS;
    if (rc == ADH_EGRID) {
        adh_rings_edge_sentence(s->sg, s->curve.rows[s->curve.nrows - 1].a, why, whylen);
        return ADH_EGRID;
    }
    if (rc == ADH_ENAN)
        snprintf(why, whylen, "the curve stopped after h0 = %s: a non-finite force; its %zu points are kept",
                 h0, s->curve.nrows);
    else
        snprintf(why, whylen, "the curve stopped %s h0 = %s: %s; its %zu point%s kept",
                 s->curve.nrows ? "after" : "at its start,", h0, adh_strerror(rc), s->curve.nrows,
                 s->curve.nrows == 1 ? " is" : "s are");
    return rc;
}

void tui_sim_set_mode(tui_sim *s, adh_mode mode)
{
    tui_sim_cancel(s);
    s->mode = mode == ADH_MODE_STATIC ? ADH_MODE_STATIC : ADH_MODE_RELAX;
    /* the static curve has its own resolution limit: an automatic grid is
     * this mode's (each mode keeps its solver, path or curve, on its own) */
    grid_follow_mode(s);
    if (s->g && grid_changed(s))
        s->grid_stale = 1;
    check_grid(s);
    curve_check(s);
}

const adh_obs *tui_sim_curve(const tui_sim *s, size_t *n)
{
    *n = s->curve.nrows;
    return s->curve.nrows ? s->curve.rows : NULL;
}

const adh_state *tui_sim_curve_profile(const tui_sim *s, int which, size_t *at)
{
    if (which == 2) {
        /* the solver holds the last point, unless a failed step left it elsewhere */
        if (!s->sdrv || !adh_rule_static_solver(s->sdrv) || !s->curve.nrows ||
            !(s->cstatus == ADH_CONTINUE || s->cstatus == ADH_SUCCESS || s->cstatus == ADH_EGRID))
            return NULL;
        *at = s->curve.nrows - 1;
        return adh_static_state(adh_rule_static_solver(s->sdrv));
    }
    if (which < 0 || which > 1 || s->cprof_at[which] == NO_POINT || s->cprof_at[which] >= s->curve.nrows)
        return NULL;
    *at = s->cprof_at[which];
    return s->cprof[which];
}

size_t tui_sim_curve_fold(const tui_sim *s, adh_static_fold *last)
{
    const adh_static_fold *f;
    size_t n = s->sdrv && adh_rule_static_solver(s->sdrv) && s->curve.nrows ? adh_static_folds(adh_rule_static_solver(s->sdrv), &f) : 0;
    if (n)
        *last = f[n - 1];
    return n;
}

int tui_sim_begin(tui_sim *s, int dir, char *why, size_t whylen)
{
    if (s->busy) {
        snprintf(why, whylen, "a step is already being solved");
        return -1;
    }
    if (s->mode == ADH_MODE_STATIC)
        return curve_begin(s, dir, why, whylen);
    if (grid_refuses(s, why, whylen) || ensure_solver(s, why, whylen) != 0)
        return -1;
    int hrc = dir != 0 ? adh_drive_hand(s->drv, dir) : ADH_SUCCESS;
    if (hrc != ADH_SUCCESS) {
        double h0 = adh_drive_hand_position(s->drv, dir);
        if (hrc == ADH_EGRID) {
            /* the edge or the graded grid's fine band: the drive's own sentence says which */
            char edge[400];
            adh_rings_edge_sentence(s->g, adh_drive_row(s->drv)->a, edge, sizeof edge);
            snprintf(why, whylen, "no approach from here: %s; b retracts", edge);
        }
        else if (fabs(h0) > adh_protocol_reach(&s->mat))
            snprintf(why, whylen, "h0 = %g m is out of reach: the model (h0 << R) allows |h0| up to R/50 = %g m",
                     h0, adh_protocol_reach(&s->mat));
        else
            snprintf(why, whylen, "at most %d turning points on one path: x starts a new one", ADH_MAX_TURNS);
        return -1;
    }
    size_t k;
    if (dir == 0 && adh_drive_next(s->drv, &k) == 0) {
        tui_sim_why_done(s, why, whylen);
        return -1;
    }
    s->t0 = adh_clock_seconds();
    s->busy = 1;
    return 0;
}

void tui_sim_cancel(tui_sim *s)
{
    if (!s->busy)
        return;
    s->busy = 0;
    if (s->mode == ADH_MODE_STATIC) {
        s->walk = 0;   /* a point is solved within one tui_sim_work: nothing half done */
        return;
    }
    if (path_length(s)) {
        adh_history_restore(s->path.hist, s->drv);
        drive_restored(s);
    } else {
        drive_attach(s);
    }
}

int tui_sim_work(tui_sim *s, size_t batch, char *why, size_t whylen)
{
    if (!s->busy)
        return ADH_SUCCESS;
    if (s->mode == ADH_MODE_STATIC)
        return curve_work(s, why, whylen);
    int row, rc = adh_drive_iterate(s->drv, batch, &row);
    if (rc == ADH_CONTINUE && !row)
        return rc;
    if (row) {
        if (adh_history_push(s->path.hist, s->drv) != ADH_SUCCESS) {
            snprintf(why, whylen, "out of memory for the history");
            tui_sim_cancel(s);
            return ADH_ENOMEM;
        }
        edits_clear(s->redo_edits, &s->nredo_edits);   /* a new step, as a new edit, ends what could be redone */
        const adh_obs *o = adh_drive_row(s->drv);
        s->warn[0] = '\0';
        if (!o->converged)
            snprintf(s->warn, sizeof s->warn, "not converged: the cap of %zu iterations was hit", o->iters);
        sync_turn(s);
    }
    if (rc == ADH_CONTINUE) {
        if (adh_drive_pending(s->drv))
            return ADH_CONTINUE;   /* the start came first: the step asked for goes on */
        s->busy = 0;
        return ADH_SUCCESS;
    }
    s->busy = 0;
    if (rc == ADH_SUCCESS)
        return TUI_SIM_DONE;
    if (rc == ADH_EGRID) {
        adh_rings_edge_sentence(s->g, adh_drive_row(s->drv)->a, why, whylen);
        return ADH_EGRID;
    }
    snprintf(why, whylen, "the step failed: %s; back to the previous state (try a smaller d or a larger eps)",
             adh_strerror(rc));
    s->busy = 1;
    tui_sim_cancel(s);
    return rc;
}

unsigned tui_sim_events(const tui_sim *s)
{
    return s->mode == ADH_MODE_RELAX && s->drv && path_length(s) ? adh_drive_events(s->drv) : 0;
}

int tui_sim_next(const tui_sim *s, size_t *turn)
{
    *turn = s->nturns ? 1 : 0;
    return s->drv && !s->grid_stale ? adh_drive_next(s->drv, turn) : +1;
}

void tui_sim_why_done(const tui_sim *s, char *buf, size_t len)
{
    int st = s->drv && !s->grid_stale ? adh_drive_status(s->drv) : ADH_SUCCESS;
    if (st == ADH_SUCCESS || st == ADH_CONTINUE)
        snprintf(buf, len, "the protocol is complete: every turn was unloaded (f and b still step by hand, x starts again)");
    else
        snprintf(buf, len, "the protocol stopped: %s (f and b still step by hand, x starts again)", adh_strerror(st));
}

void tui_sim_turn_name(const tui_sim *s, size_t i, char *buf, size_t len)
{
    const adh_run *run = &s->path.run;
    if (i >= run->nturns) {
        snprintf(buf, len, "a turn");
        return;
    }
    double h0 = run->turns[i].h0;
    size_t k = turn_index(s, h0);
    if (k < s->nturns) {
        if (s->nturns > 1)
            snprintf(buf, len, "turn %zu of %zu", k + 1, s->nturns);
        else
            snprintf(buf, len, "the turn");
        return;
    }
    char q[64];
    adh_format_quantity(h0, ADH_Q_LENGTH, 4, q, sizeof q);
    snprintf(buf, len, "the turn at h0 = %s", q);
}

const adh_run *tui_sim_run(const tui_sim *s)
{
    return &s->path.run;
}

/* Takes back the last edit (redo: puts it back), when there is one. */
static int edit_undo(tui_sim *s, int redo)
{
    if (redo ? !s->nredo_edits : !s->nundo_edits)
        return ADH_EINVAL;
    if (redo)
        edit_swap(s, s->redo_edits, &s->nredo_edits, s->undo_edits, &s->nundo_edits);
    else
        edit_swap(s, s->undo_edits, &s->nundo_edits, s->redo_edits, &s->nredo_edits);
    return ADH_SUCCESS;
}

int tui_sim_undo(tui_sim *s)
{
    tui_sim_cancel(s);
    s->edit_moved = -1;
    if (s->mode == ADH_MODE_STATIC) {
        if (s->curve.nrows == 0 || s->ccur == 0)
            return edit_undo(s, 0);
        s->ccur--;
        return ADH_SUCCESS;
    }
    if (!s->drv || s->grid_stale || !s->path.hist || adh_history_undo(s->path.hist, s->drv) != ADH_SUCCESS)
        return edit_undo(s, 0);
    drive_restored(s);
    s->warn[0] = '\0';
    return ADH_SUCCESS;
}

int tui_sim_redo(tui_sim *s)
{
    tui_sim_cancel(s);
    s->edit_moved = -1;
    if (s->mode == ADH_MODE_STATIC) {
        if (s->curve.nrows == 0 || s->ccur + 1 >= s->curve.nrows)
            return edit_undo(s, 1);
        s->ccur++;
        return ADH_SUCCESS;
    }
    if (!s->drv || s->grid_stale || !s->path.hist || adh_history_redo(s->path.hist, s->drv) != ADH_SUCCESS)
        return edit_undo(s, 1);
    drive_restored(s);
    s->warn[0] = '\0';
    return ADH_SUCCESS;
}

void tui_sim_reset(tui_sim *s)
{
    if (s->mode == ADH_MODE_STATIC) {
        tui_sim_cancel(s);
        curve_drop(s);   /* the relaxation path is the other mode's: kept */
        return;
    }
    new_path(s);
    sync_turn(s);
}

const adh_obs *tui_sim_row(const tui_sim *s)
{
    if (s->mode == ADH_MODE_STATIC)
        return s->curve.nrows ? &s->curve.rows[s->ccur] : NULL;
    return s->path.run.nrows ? &s->path.run.rows[s->path.run.nrows - 1] : NULL;
}

const adh_obs *tui_sim_rows(const tui_sim *s, size_t *n)
{
    if (s->mode == ADH_MODE_STATIC) {
        *n = s->curve.nrows ? s->ccur + 1 : 0;
        return s->curve.nrows ? s->curve.rows : NULL;
    }
    *n = s->path.run.nrows;
    return s->path.run.nrows ? s->path.run.rows : NULL;
}

size_t tui_sim_redoable(const tui_sim *s)
{
    if (s->mode == ADH_MODE_STATIC)
        return s->curve.nrows ? s->curve.nrows - 1 - s->ccur : 0;
    return s->path.hist ? adh_history_redoable(s->path.hist) : 0;
}

void tui_sim_cycle(const tui_sim *s, adh_cycle *c)
{
    adh_cycle_measure(s->path.run.nrows ? s->path.run.rows : NULL, s->path.run.nrows, c);
}

double tui_sim_target(const tui_sim *s)
{
    if (s->mode == ADH_MODE_STATIC || !s->drv)
        return s->target;
    return adh_drive_step_position(s->drv);
}

size_t tui_sim_progress(const tui_sim *s, double *change)
{
    if (s->mode == ADH_MODE_STATIC) {
        *change = 0;
        return s->curve.nrows;
    }
    *change = 0;
    return s->drv ? adh_drive_progress(s->drv, change) : 0;
}

int tui_sim_will_build(const tui_sim *s)
{
    if (s->mode == ADH_MODE_STATIC) {
        tui_params_set p = params_get(s);
        adh_grid_asked g = mode_grid(s, &p, ADH_MODE_STATIC);
        return !s->sdrv || !same_grid(&s->sbuilt, &g);
    }
    return !s->g || s->grid_stale;
}
