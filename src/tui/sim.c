#include "tui/sim.h"
#include "adhere/clock.h"

#include <limits.h>
#include <float.h>
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
#include "adhere/rule_time.h"
#include "adhere/status.h"
#include "scene/budget.h"
#include "scene/text.h"

static void drive_attach(tui_sim *s);
static void sync_turn(tui_sim *s);
static void edge_words(const adh_grid *g, double a, char *why, size_t whylen);

/* Turning points deepest last: the order --batch reaches them in. */
static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

const tui_param_info tui_params[P_COUNT] = {
    [P_E] = { "E", "material.E", "E", "E", "combined modulus", ADH_Q_PRESSURE },
    [P_A] = { "A", "material.A", "A", "A", "Hamaker constant", ADH_Q_ENERGY },
    [P_Z0] = { "z0", "material.z0", "z0", "z0", "equilibrium gap", ADH_Q_LENGTH },
    [P_R] = { "R", "material.R", "R", "R", "sphere radius", ADH_Q_LENGTH },
    [P_EPS] = { "eps", "solver.eps", "\xce\xb5", "eps", "convergence (eps)", ADH_Q_LENGTH },
    [P_D] = { "d", "protocol.step", "d", "d", "drive step", ADH_Q_LENGTH },
    [P_N] = { "N", "grid.nodes", "N", "N", "grid nodes", ADH_Q_NONE },
    [P_SPACING] = { "spacing", "grid.spacing", "\xce\x94", "dr", "grid spacing", ADH_Q_LENGTH },
    [P_TURN] = { "turn", "protocol.turns", "turn", "turn", "turning point", ADH_Q_LENGTH },
    [P_EINF] = { "Einf", "material.Einf", "E\xe2\x88\x9e", "Einf", "instantaneous modulus", ADH_Q_PRESSURE },
    [P_TAU] = { "tau", "material.tau", "\xcf\x84", "tau", "relaxation time", ADH_Q_TIME },
    [P_SPEED] = { "speed", "protocol.speed", "v", "v", "base speed", ADH_Q_SPEED },
};

static const adh_run_spec *spec(const tui_sim *s)
{
    return &s->cfg.spec;
}

double tui_sim_spacing(const tui_sim *s)
{
    return adh_config_spacing(spec(s));
}

const adh_grid_spec *tui_sim_grid(const tui_sim *s)
{
    return &spec(s)->grid.use;
}

adh_mode tui_sim_mode(const tui_sim *s)
{
    return spec(s)->mode;
}

int tui_sim_curve_mode(const tui_sim *s)
{
    return spec(s)->mode == ADH_MODE_STATIC || spec(s)->mode == ADH_MODE_TIME;
}

int tui_sim_param_shown(const tui_sim *s, tui_param p)
{
    int timed = spec(s)->mode == ADH_MODE_TIME;
    switch (p) {
    case P_EPS: case P_D: return !timed;   /* the relaxation's and its drive's */
    case P_EINF: case P_TAU: return timed && spec(s)->time.sls;
    case P_SPEED: return timed;
    default: return p < P_COUNT;
    }
}

/* The mode of the curve on screen (static when the screen relaxes). */
static adh_mode curve_mode_of(const tui_sim *s)
{
    return spec(s)->mode == ADH_MODE_TIME ? ADH_MODE_TIME : ADH_MODE_STATIC;
}

/* The rule of the curve on screen. */
static const adh_rule_type *curve_rule(const tui_sim *s)
{
    return spec(s)->mode == ADH_MODE_TIME ? adh_config_time_rule(spec(s)) : &adh_rule_static;
}

const double *tui_sim_turns(const tui_sim *s, size_t *n)
{
    *n = spec(s)->proto.nturns;
    return spec(s)->proto.turns;
}

/* ---- the TUI's words ------------------------------------------------------ */

/* The field that edits key, or P_COUNT. */
static tui_param field_of(const char *key)
{
    int p = 0;
    while (p < P_COUNT && strcmp(tui_params[p].key, key) != 0)
        p++;
    return (tui_param)p;
}

/* A key in the TUI's words: its field ("N", "turn = -2nm"), or the key
 * itself, which :set takes. */
static void say_field(const char *key, const char *value, char *buf, size_t len, void *ctx)
{
    tui_param p = field_of(key);
    const char *name = p < P_COUNT ? tui_params[p].name : key;
    snprintf(buf, len, "%s%s%s", name, value ? " = " : "", value ? value : "");
}

/* What a refusal asks to change (the core's ADH_FIX_* bits), in the order
 * a sentence names them: the fields, or the keys :set takes. The screen
 * runs any grid, marked UNRESOLVED where it is coarser than the limit, so
 * "run it anyway" needs nothing here. */
static const struct { unsigned bit; const char *here; } fix_words[] = {
    { ADH_FIX_MODE, "m" },
    { ADH_FIX_FINE_BAND, ":set grid.fine_band" },
    { ADH_FIX_TURNS, "turn" },
    { ADH_FIX_RADIUS, "R" },
    { ADH_FIX_STEP, "d" },
    { ADH_FIX_START, ":set protocol.start" },
    { ADH_FIX_NODES, "N" },
    { ADH_FIX_SPACING, "spacing" },
    { ADH_FIX_GRID_RADIUS, ":set grid.radius" },
    { ADH_FIX_TIME_TOL, ":set solver.time_tol" },
};

/* The core's sentence in why with the screen's words for fix after it, as
 * " (N, spacing)"; nothing for 0 or when they do not fit. */
static void advice(char *why, size_t whylen, unsigned fix)
{
    char list[160] = "";
    size_t n = 0;
    for (size_t i = 0; i < sizeof fix_words / sizeof fix_words[0]; i++)
        if ((fix & fix_words[i].bit) && n + strlen(fix_words[i].here) + 3 < sizeof list)
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", fix_words[i].here);
    size_t len = strlen(why);
    if (n && len + n + 4 <= whylen)
        snprintf(why + len, whylen - len, " (%s)", list);
}

/* Why run stopped on an error: the core's sentence (what failed and where)
 * with the screen's words for what may get past it; "" when it has none. */
static void stop_words(const adh_run *run, char *buf, size_t len)
{
    snprintf(buf, len, "%s", run->why);
    if (*buf)
        advice(buf, len, run->fix);
}

const char *tui_sim_stop_reason(const tui_sim *s, char *buf, size_t len)
{
    int stopped = s->cstatus != ADH_CONTINUE && s->cstatus != ADH_SUCCESS;
    buf[0] = '\0';
    if (stopped)
        stop_words(&s->curve, buf, len);
    return buf;
}

void tui_sim_words(const char *sentence, char *out, size_t len)
{
    adh_config_reword(sentence, say_field, NULL, out, len);
}

/* tui_sim_words as an adh_config_words */
static void field_words(const char *in, void *ctx, char *out, size_t len)
{
    tui_sim_words(in, out, len);
}

/* ---- the grid of each mode ------------------------------------------------ */

/* The grid of run r as it stands: N and the spacing resolved, and a graded
 * grid's automatic band and radius (they follow the material and turns). */
static adh_grid_spec grid_of(const adh_run_spec *r)
{
    adh_grid_spec g = r->grid.use;
    g.spacing = adh_config_spacing(r);
    if (g.graded) {
        adh_rings_spec rs = adh_config_rings(r);
        g.fine_band = rs.fine;
        g.radius = rs.rmax;
        g.growth = rs.ratio;
    }
    return g;
}

static int same_grid(const adh_grid_spec *a, const adh_grid_spec *b)
{
    /* NAN fields (automatic band, radius) are equal when both are NAN */
    #define SAME(x) (a->x == b->x || (isnan((double)a->x) && isnan((double)b->x)))
    return a->nodes == b->nodes && SAME(spacing) && SAME(fine_band) && SAME(growth) && SAME(radius) &&
           a->kernel == b->kernel && a->storage == b->storage && a->graded == b->graded;
    #undef SAME
}

/* Run r in mode: an automatic grid is chosen per mode, as --batch --mode
 * would (the static curve needs finer rings), so the other mode's grid is
 * chosen again; a grid given stays as given. */
static adh_run_spec mode_spec(const tui_sim *s, const adh_run_spec *r, adh_mode mode)
{
    adh_run_spec m = *r;
    m.mode = mode;
    if (mode != r->mode) {
        char why[512];   /* a refusal keeps the grid asked for (solves say why) */
        adh_config_choose_grid(&m, &s->cfg, why, sizeof why, NULL);
    }
    return m;
}

static adh_grid_spec mode_grid(const tui_sim *s, const adh_run_spec *r, adh_mode mode)
{
    adh_run_spec m = mode_spec(s, r, mode);
    return grid_of(&m);
}

/* Whether the relaxation's grid for the configuration is another than the
 * one its kernel was built for. */
static int grid_changed(const tui_sim *s)
{
    adh_grid_spec now = mode_grid(s, spec(s), ADH_MODE_RELAX);
    return !same_grid(&s->built, &now);
}

/* The grid on screen is the mode's: chosen again for the material, as
 * --batch would, while it follows the material; why says why none could
 * be chosen ("" when one was, or the grid is given). */
static void regrid(tui_sim *s, char *why, size_t whylen)
{
    unsigned fix;
    if (adh_config_choose_grid(&s->cfg.spec, &s->cfg, why, whylen, &fix) == 0)
        why[0] = '\0';
    else
        advice(why, whylen, fix);
}

enum { PROF_CONTACT = 0, PROF_PULLOFF = 1 };
#define NO_POINT SIZE_MAX

/* Forgets the static curve (its points, summary, profiles); the solver
 * itself stays allocated for the next curve on the same grid. */
static void curve_drop(tui_sim *s)
{
    s->curve.nrows = 0;
    s->cset = 0;
    s->ccur = 0;
    s->walk = 0;
    s->cstatus = ADH_CONTINUE;
    memset(&s->sres, 0, sizeof s->sres);
    s->sres.jump_in_h0 = s->sres.jump_out_h0 = s->sres.pulloff_F_disp = NAN;
    s->sres.pulloff_F = s->sres.pulloff_h0 = NAN;
    memset(&s->vres, 0, sizeof s->vres);
    s->vres.jump_in_h0 = s->vres.jump_out_h0 = s->vres.pulloff_F = s->vres.pulloff_h0 = NAN;
    s->cprof_at[PROF_CONTACT] = s->cprof_at[PROF_PULLOFF] = NO_POINT;
}

double tui_sim_curve_end(const tui_sim *s)
{
    adh_protocol_settings ps = adh_config_protocol_for(&s->cfg, spec(s)->mode);
    if (spec(s)->mode == ADH_MODE_TIME)   /* back where the base started */
        return ps.nturns && ps.unload ? s->start : adh_protocol_deepest_turn(&ps);
    return adh_rule_static_end(&ps);
}

static int curve_started(const tui_sim *s)
{
    return s->curve.nrows > 0 || s->cstatus != ADH_CONTINUE || s->cset;
}

/* A curve belongs to the material, grid, start and end it was computed
 * for: when one of them changed, it is dropped (eps and d alone do not
 * touch it, unless d moved an automatic start). */
static void curve_check(tui_sim *s)
{
    if (!curve_started(s))
        return;
    const adh_material *a = &s->ckey.mat, *b = &spec(s)->mat;
    adh_grid_spec g = mode_grid(s, spec(s), curve_mode_of(s));
    const adh_time_settings *ta = &s->ckey.time, *tb = &spec(s)->time;
    int time_same = ta->sls == tb->sls && (ta->Einf == tb->Einf || (isnan(ta->Einf) && isnan(tb->Einf))) &&
                    ta->tau == tb->tau && ta->speed_in == tb->speed_in && ta->speed_out == tb->speed_out &&
                    ta->dwell == tb->dwell && ta->spring == tb->spring && ta->tol == tb->tol;
    if (a->E != b->E || a->A != b->A || a->z0 != b->z0 || a->R != b->R || !same_grid(&s->ckey.grid, &g) ||
        s->ckey.start != s->start || s->ckey.end != tui_sim_curve_end(s) || s->ckey.rule != curve_rule(s) ||
        (s->ckey.rule != &adh_rule_static && !time_same))
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

/* The core's one check of every limit, the one --batch and scene files
 * meet, on the configuration as it stands: ADH_EINVAL refuses an edit;
 * ADH_EGRID (a grid that cannot hold the run) lets it through, shown, and
 * a solve is refused until mended, as --batch refuses the run. why is in
 * the screen's words. */
static int check_words(const tui_sim *s, char *why, size_t whylen, unsigned *fix);

/* A solid's start, as a run from the command line is refused: on the
 * kernel kept from the last check, or the curve's when it is built on the
 * same grid (lent for the check), so that an edit that leaves the grid
 * builds none (1.8 s, twice an edit, at N = 3000 before). */
static int start_check(tui_sim *s, char *why, size_t whylen, unsigned *fix)
{
    adh_run_spec m = mode_spec(s, spec(s), curve_mode_of(s));
    if (s->sk && !(s->startk.k && adh_config_same_grid(&s->startk.spec, &m))) {
        adh_grid_spec now = grid_of(&m);
        if (same_grid(&s->sbuilt, &now))
            adh_config_kept_lend(&s->startk, &m, s->sg, s->sk);
    }
    int rc = adh_config_start_check_kept(&s->cfg, &s->startk, why, whylen, fix);
    if (s->startk.lent)
        adh_config_kept_drop(&s->startk);   /* the curve's: freed with it */
    return rc;
}

static int params_check(tui_sim *s, char *why, size_t whylen)
{
    char msg[TUI_SIM_WHY_LEN];   /* a sweep's run (256) before a start's sentence (1024), whole */
    unsigned fix = 0;
    int rc = check_words(s, msg, sizeof msg, &fix);
    if (rc == ADH_SUCCESS && adh_config_time_check(&s->cfg, spec(s), msg, sizeof msg) != 0)
        rc = ADH_EINVAL;   /* the material, drive and mode do not fit */
    if (rc == ADH_SUCCESS)
        rc = start_check(s, msg, sizeof msg, &fix);
    if (rc != ADH_SUCCESS) {
        tui_sim_words(msg, why, whylen);   /* a sentence of the configuration's names keys */
        advice(why, whylen, fix);
    }
    return rc;
}

static int check_words(const tui_sim *s, char *why, size_t whylen, unsigned *fix)
{
    const adh_run_spec *r = spec(s);
    adh_protocol_settings ps = adh_config_protocol(&s->cfg);
    adh_grid_use use = adh_config_grid_use(r);
    if (!r->grid.use.graded) {
        adh_grid g = adh_drive_uniform_grid(r->grid.use.nodes, adh_config_spacing(r));
        return adh_drive_check(&r->mat, &r->relax, &ps, use, &g, why, whylen, fix);
    }
    /* rings: the check reads their edges (cheap to lay out; no kernel) */
    if (adh_config_grid_check(r, why, whylen) != 0)
        return ADH_EINVAL;
    int rc = ADH_EGRID;
    adh_grid *g = adh_config_grid_alloc(r);
    if (!g)
        snprintf(why, whylen, "out of memory for a graded grid of %zu rings", r->grid.use.nodes);
    else
        rc = adh_drive_check(&r->mat, &r->relax, &ps, use, g, why, whylen, fix);
    adh_grid_free(g);
    return rc;
}

/* The check, and the resolution the Derived panel shows: a newcomer who
 * sets N = 100 learns the contact will not fit before stepping into it. */
static void check_grid(tui_sim *s)
{
    const adh_run_spec *r = spec(s);
    adh_grid_check(&r->mat, adh_config_grid_use(r), r->grid.use.nodes, tui_sim_spacing(s), &s->gridres);
    if (s->gridchoice[0])   /* no grid resolves this material within the budget */
        snprintf(s->gridwarn, sizeof s->gridwarn, "%s", s->gridchoice);
    else if (params_check(s, s->gridwarn, sizeof s->gridwarn) == ADH_SUCCESS)
        s->gridwarn[0] = '\0';
}

/* The closed forms for the material on screen: recomputed with it. */
static void derive(tui_sim *s)
{
    const adh_material *mat = &spec(s)->mat;
    adh_material_derive(mat, &s->der);
    tui_models *m = &s->models;
    m->md_lambda = adh_md_lambda(mat);
    double ov = NAN;
    if (adh_md_pulloff(mat, m->md_lambda, &m->md_pulloff, NULL, NULL, &ov) != ADH_SUCCESS)
        m->md_pulloff = ov = NAN;
    m->md_jump_out = mat->z0 - ov;
    m->jump_in = adh_bulge_position(mat, adh_jump_separation(mat));
}

/* A change to the physics: the old path no longer belongs to these
 * parameters, so it is dropped and the next step starts at the start. */
static void new_path(tui_sim *s)
{
    s->start = adh_config_start(spec(s));
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

/* The turns shallowest first: the order the drive reaches them in, and
 * the one the panel and "turn 3 of 8" count in. */
static void sort_turns(tui_sim *s)
{
    adh_protocol_settings *p = &s->cfg.spec.proto;
    qsort(p->turns, p->nturns, sizeof *p->turns, cmp_desc);
}

int tui_sim_init(tui_sim *s, const adh_config *cfg, char *why, size_t whylen)
{
    memset(s, 0, sizeof *s);
    adh_run_init(&s->curve);
    adh_run_init(&s->path.run);
    s->cfg = *cfg;
    /* the screen relaxes or follows the static curve: rigid spheres are --batch's */
    s->cfg.spec.mode = cfg->spec.mode == ADH_MODE_RIGID ? ADH_MODE_RELAX : cfg->spec.mode;
    sort_turns(s);
    s->tcur = 0;
    s->turn = spec(s)->proto.nturns ? spec(s)->proto.turns[0] : NAN;
    regrid(s, s->gridchoice, sizeof s->gridchoice);
    if (params_check(s, why, whylen) == ADH_EINVAL)
        return -1;
    derive(s);
    s->grid_stale = 1;
    s->edit_moved = NULL;
    curve_drop(s);
    new_path(s);
    return 0;
}

void tui_sim_free(tui_sim *s)
{
    free_static(s);
    adh_config_kept_drop(&s->startk);
    free_solver(s);
    path_free(&s->path);
    edits_clear(s->undo_edits, &s->nundo_edits);
    edits_clear(s->redo_edits, &s->nredo_edits);
    adh_run_free(&s->curve);
}

/* Puts the drive on the path on screen: set for the configuration's
 * relaxation protocol (turns, unload, dwell and profiles, as --batch's),
 * then restored where the path is (a path given back by undo goes on from
 * where it was). */
static void drive_attach(tui_sim *s)
{
    const adh_run_spec *r = spec(s);
    adh_protocol_settings ps = adh_config_protocol_for(&s->cfg, ADH_MODE_RELAX);
    adh_drive_set(s->drv, &r->mat, &r->relax, &ps, &s->path.run);
    if (path_length(s) && adh_history_restore(s->path.hist, s->drv) != ADH_SUCCESS) {
        adh_history_clear(s->path.hist);   /* states of another grid: not this path's any more */
        adh_run_free(&s->path.run);
        adh_run_init(&s->path.run);
        adh_drive_set(s->drv, &r->mat, &r->relax, &ps, &s->path.run);
    } else if (path_length(s)) {
        adh_drive_retarget(s->drv, &ps);   /* the snapshot counted its turns against the turns of its time */
    }
}

/* The memory the run of m needs, against what there is (scene/budget.h),
 * the refusal in the screen's words. */
static int budget(const adh_run_spec *m, unsigned solvers, char *why, size_t whylen)
{
    char msg[1024];
    if (adh_budget_check(m, solvers, msg, sizeof msg) == 0)
        return 0;
    tui_sim_words(msg, why, whylen);
    return -1;
}

/* The path to the turn and back keeps a state a step for undo: its memory
 * too, before a step is taken (scene/budget.h). */
static int path_budget(const tui_sim *s, char *why, size_t whylen)
{
    char msg[1024];
    adh_run_spec m = mode_spec(s, spec(s), ADH_MODE_RELAX);
    if (adh_budget_check_path(&m, path_length(s), msg, sizeof msg) == 0)
        return 0;
    tui_sim_words(msg, why, whylen);
    return -1;
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
    /* the grid, kernel and operator --batch builds for this configuration,
     * within the memory this process may use */
    adh_run_spec m = mode_spec(s, spec(s), ADH_MODE_RELAX);
    if (budget(&m, 0, why, whylen) != 0)
        return -1;
    int st;
    s->g = adh_config_grid_alloc(&m);
    s->k = s->g ? adh_config_kernel_alloc(&m, s->g, &st) : NULL;
    s->kernels_built += s->k != NULL;
    s->drv = s->k ? adh_drive_alloc(&adh_rule_relax, s->g, s->k) : NULL;
    s->built = grid_of(&m);
    if (!s->drv) {
        free_solver(s);
        snprintf(why, whylen, "out of memory for a grid of N = %zu nodes: try fewer", m.grid.use.nodes);
        return -1;
    }
    s->grid_stale = 0;
    drive_attach(s);
    return 0;
}

/* The static curve's grid, kernel and drive for the configuration: built
 * on its first point, and again (the curve dropped) when that grid
 * changed. */
static int ensure_static(tui_sim *s, char *why, size_t whylen)
{
    adh_run_spec m = mode_spec(s, spec(s), curve_mode_of(s));
    adh_grid_spec now = grid_of(&m);
    if (s->sdrv && same_grid(&s->sbuilt, &now) && s->srule == curve_rule(s))
        return 0;
    free_static(s);
    if (budget(&m, 1, why, whylen) != 0)
        return -1;
    int st;
    /* the start check's, when it checked this grid: not built twice */
    if (!adh_config_kept_take(&s->startk, &m, &s->sg, &s->sk)) {
        s->sg = adh_config_grid_alloc(&m);
        s->sk = s->sg ? adh_config_kernel_alloc(&m, s->sg, &st) : NULL;
        s->kernels_built += s->sk != NULL;
    }
    s->srule = curve_rule(s);
    s->sdrv = s->sk ? adh_drive_alloc(s->srule, s->sg, s->sk) : NULL;
    s->sbuilt = now;
    if (!s->sdrv) {
        free_static(s);
        snprintf(why, whylen, "out of memory for the static solver on a grid of N = %zu nodes: try fewer", m.grid.use.nodes);
        return -1;
    }
    return 0;
}

/* ---- edits: by key, undone by snapshots ------------------------------------ */

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

/* The key's name as the table holds it (it outlives any edit). */
static const char *key_name(const char *key)
{
    const adh_config_key *k = adh_config_key_find(key);
    return k ? k->key : NULL;
}

/* After the run specification on screen changed (an edit, undo, redo, a
 * mode): the closed forms, the drive and the checks follow it. */
static void spec_changed(tui_sim *s, const adh_material *before)
{
    const adh_material *m = &spec(s)->mat;
    if (m->E != before->E || m->A != before->A || m->z0 != before->z0 || m->R != before->R)
        derive(s);
}

/* Swaps the run specification and path on screen with those of edit e
 * (popped from one stack), pushing what was on screen on the other. */
static void edit_swap(tui_sim *s, tui_edit *from, size_t *nfrom, tui_edit *to, size_t *nto)
{
    tui_edit e = from[--(*nfrom)], back = { s->cfg.spec, "", e.keeps_path, { .hist = NULL } };
    snprintf(back.key, sizeof back.key, "%s", e.key);
    adh_run_init(&back.path.run);
    tui_sim_cancel(s);
    if (!e.keeps_path) {
        back.path = path_take(s);
        s->path = e.path;
    }
    edits_push(to, nto, &back);
    adh_material was = spec(s)->mat;
    adh_mode mode = spec(s)->mode;
    s->cfg.spec = e.spec;
    s->cfg.spec.mode = mode;   /* the edit may have been made in the other mode */
    regrid(s, s->gridchoice, sizeof s->gridchoice);
    s->start = adh_config_start(spec(s));
    spec_changed(s, &was);
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
    s->edit_moved = key_name(e.key);
}

/* Whether the relaxation's grid differs between run specifications a and
 * b (a deeper turn needs a larger one that follows the material). */
static int relax_grid_differs(const tui_sim *s, const adh_run_spec *a, const adh_run_spec *b)
{
    adh_grid_spec ga = mode_grid(s, a, ADH_MODE_RELAX), gb = mode_grid(s, b, ADH_MODE_RELAX);
    return !same_grid(&ga, &gb);
}

/* The edit of key that made the configuration on screen from `before`:
 * the grid chosen again, the core's check (a refusal puts `before` back),
 * then on the undo stack with the path `before` had, unless it keeps it
 * (a new turn the built grid need not follow: where a run turns is not
 * physics). */
static int edit_apply(tui_sim *s, const adh_run_spec *before, const char *key, char *why, size_t whylen)
{
    int turns = strcmp(key, "protocol.turns") == 0;
    char choice[512];
    if (turns)
        sort_turns(s);
    regrid(s, choice, sizeof choice);
    if (params_check(s, why, whylen) == ADH_EINVAL) {
        s->cfg.spec = *before;
        return -1;
    }
    tui_edit e = { *before, "", turns && !(s->g && relax_grid_differs(s, before, spec(s))), { .hist = NULL } };
    snprintf(e.key, sizeof e.key, "%s", key);
    adh_run_init(&e.path.run);
    if (!e.keeps_path)
        e.path = path_take(s);   /* the next step starts a new one */
    edits_push(s->undo_edits, &s->nundo_edits, &e);
    edits_clear(s->redo_edits, &s->nredo_edits);
    s->edit_kept_path = e.keeps_path;
    snprintf(s->gridchoice, sizeof s->gridchoice, "%s", choice);
    spec_changed(s, &before->mat);
    if (turns) {
        s->tcur = 0;
        s->turn = spec(s)->proto.nturns ? spec(s)->proto.turns[0] : NAN;
    }
    if (turns && !(s->g && grid_changed(s))) {
        /* the path stays, and the drive turns where it is told from here
         * on (unless the grid had to grow for a deeper turn: then the
         * path went, as for E) */
        if (s->drv && !s->grid_stale) {
            adh_protocol_settings ps = adh_config_protocol_for(&s->cfg, ADH_MODE_RELAX);
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

/* A :set key's text in the configuration's words: on the screen a bare
 * number is in the unit shown, here the unit its key is shown in for its
 * present value (protocol.start in nm, grid.fine_band in um or nm), each
 * element of a list; given on in SI, exactly. Anything else as typed.
 * unit (ulen bytes) receives the unit a bare number was read in ("" when
 * none was). */
static void key_value_in_unit(const tui_sim *s, const adh_config_key *k, const char *text, char *out, size_t len,
                              char *unit, size_t ulen)
{
    char cur[1024];
    double now = NAN, f = 1;
    snprintf(out, len, "%s", text);
    unit[0] = '\0';
    if (!k->units || !adh_quantity_is_bare(text) || adh_config_get(&s->cfg, k->key, cur, sizeof cur) != 0)
        return;
    now = strtod(cur, NULL);   /* "auto", "none": 0, the smallest unit */
    const char *u = adh_config_key_unit(k, now, &f);
    if (!u)
        return;
    snprintf(unit, ulen, "%s", u);
    size_t o = 0;
    out[0] = '\0';
    for (const char *p = text; *p;) {
        char *end, one[40];
        double v = strtod(p, &end);
        int w = snprintf(one, sizeof one, "%s%.17g", o ? "," : "", v * f);
        if (w < 0 || o + (size_t)w >= len)
            break;   /* a list longer than the buffer: the setter refuses it */
        memcpy(out + o, one, (size_t)w + 1);
        o += (size_t)w;
        p = strchr(end, ',') ? strchr(end, ',') + 1 : end + strlen(end);
    }
}

/* n bytes of s without the blanks around them: *s moved, the length left. */
static size_t trimmed(const char **s, size_t n)
{
    while (n && (**s == ' ' || **s == '\t'))
        (*s)++, n--;
    while (n && ((*s)[n - 1] == ' ' || (*s)[n - 1] == '\t'))
        n--;
    return n;
}

/* msg, a setter's refusal of value (the text typed, its bare numbers read
 * in unit and given on in SI), with each element of value it quotes
 * ('1.0000000000000019e-309') put back as typed ('1e-300' nm): the
 * refusal names what the user typed, never the conversion. value and
 * text are lists alike, element for element. */
static void as_typed(const char *msg, const char *value, const char *text, const char *unit, char *out, size_t len)
{
    snprintf(out, len, "%s", msg);
    char whole[600], *all;   /* a list quoted whole ("has more than 2 values") */
    if (unit[0] && strchr(value, ',') && strlen(value) < 500 && (snprintf(whole, sizeof whole, "'%s'", value),
                                                                 all = strstr(out, whole))) {
        char rest[1024];
        snprintf(rest, sizeof rest, "'%.200s' %s%s", text, unit, all + strlen(whole));
        *all = '\0';
        adh_text_cat(out, len, rest);
        return;
    }
    for (const char *v = value, *t = text; unit[0] && *v && *t;) {
        size_t nv = strcspn(v, ","), nt = strcspn(t, ",");
        const char *ts = t;
        size_t tn = trimmed(&ts, nt);
        char quoted[64], rest[1024];
        char *at = nv + 3 <= sizeof quoted && (nv != tn || strncmp(v, ts, nv))
                 ? (snprintf(quoted, sizeof quoted, "'%.*s'", (int)nv, v), strstr(out, quoted)) : NULL;
        if (at) {   /* out up to the quote kept in place, the rest put after it */
            snprintf(rest, sizeof rest, "'%.*s' %s%s", (int)(tn < 100 ? tn : 100), ts, unit, at + strlen(quoted));
            *at = '\0';
            adh_text_cat(out, len, rest);
        }
        v += nv + (v[nv] == ',');
        t += nt + (t[nt] == ',');
    }
}

/* A setter's refusal of text typed for key (value: as the setter was
 * given it, bare numbers read in unit, "" for none), shown as name: "N =
 * 5 is not allowed: ...", not "N: N = 5 nodes is not allowed" (the core
 * names its quantity), else "name: sentence", a value it quotes as typed. */
static void refused(const char *name, const char *key, const char *text, const char *value, const char *unit,
                    const char *msg, char *why, size_t whylen)
{
    char setting[512], typed[512];
    as_typed(msg, value, text, unit, typed, sizeof typed);
    snprintf(setting, sizeof setting, "%s = %s", name, text);
    adh_config_refusal(key, setting, name, typed, field_words, NULL, why, whylen);
}

int tui_sim_set_key(tui_sim *s, const char *key, const char *text, char *why, size_t whylen)
{
    const adh_config_key *k = adh_config_key_find(key);
    char msg[512];
    if (!k || !(k->where & ADH_KEY_RUN) || strcmp(key, "scene.mode") == 0) {
        snprintf(why, whylen, "%s is not set here: %s", key, k && !strcmp(key, "scene.mode")
                 ? "m switches between relaxation and the static curve (a scene in physical time stays in it)"
                 : "the screen sets the keys of the run "
                 "(material, grid, solver, protocol, profiles)");
        return -1;
    }
    adh_run_spec before = s->cfg.spec;
    char value[1024], unit[16];
    key_value_in_unit(s, k, text, value, sizeof value, unit, sizeof unit);
    if (adh_config_set(&s->cfg, key, value, msg, sizeof msg) != 0) {
        refused(key, key, text, value, unit, msg, why, whylen);
        return -1;
    }
    return edit_apply(s, &before, key, why, whylen);
}

/* ---- the panel's fields ------------------------------------------------- */

/* The value of field p in SI (NAN: not set). */
static double param_value(const tui_sim *s, tui_param p)
{
    const adh_run_spec *r = spec(s);
    switch (p) {
    case P_E: return r->mat.E;
    case P_A: return r->mat.A;
    case P_Z0: return r->mat.z0;
    case P_R: return r->mat.R;
    case P_EPS: return r->relax.eps;
    case P_D: return r->proto.step;
    case P_N: return (double)r->grid.use.nodes;
    case P_SPACING: return tui_sim_spacing(s);
    case P_TURN: return s->turn;
    case P_EINF: return adh_config_einf(r);
    case P_TAU: return r->time.tau;
    case P_SPEED: return r->time.speed_in;
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
    case P_E: case P_EINF:
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
    /* times and speeds in the units an experiment states them in */
    case P_TAU:
        if (v >= 0.9995) return "s";
        if (v >= 0.9995e-3) { *factor = 1e-3; return "ms"; }
        *factor = 1e-6;
        return utf8 ? "\xc2\xb5s" : "us";
    case P_SPEED:
        if (v >= 0.9995e-3) { *factor = 1e-3; return "mm/s"; }
        if (v >= 0.9995e-6) { *factor = 1e-6; return utf8 ? "\xc2\xb5m/s" : "um/s"; }
        *factor = 1e-9;
        return "nm/s";
    default: return "";
    }
}

void tui_sim_param_text(const tui_sim *s, tui_param p, int utf8, char *buf, size_t len)
{
    double f, v = param_value(s, p);
    const char *unit = tui_sim_param_unit(s, p, utf8, &f);
    if (p == P_N)
        snprintf(buf, len, "%zu", spec(s)->grid.use.nodes);
    else if (p == P_TURN && isnan(v))
        snprintf(buf, len, "none");
    else if (p == P_TURN && spec(s)->proto.nturns > 1)   /* a list: its ends, shallowest first */
        snprintf(buf, len, "%.4g %s %.4g %s", spec(s)->proto.turns[0] / f, utf8 ? "\xe2\x80\xa6" : "...",
                 spec(s)->proto.turns[spec(s)->proto.nturns - 1] / f, unit);
    else if (p == P_A)
        snprintf(buf, len, "%.4g J", v);
    else if (p == P_SPEED && spec(s)->time.speed_out != v)   /* approach, retraction */
        snprintf(buf, len, "%.4g,%.4g %s", v / f, spec(s)->time.speed_out / f, unit);
    else
        snprintf(buf, len, "%.4g %s", v / f, unit);
}

void tui_sim_turns_text(const tui_sim *s, char *buf, size_t len)
{
    const adh_protocol_settings *p = &spec(s)->proto;
    size_t o = 0;
    buf[0] = '\0';
    if (!p->nturns) {
        snprintf(buf, len, "none");
        return;
    }
    for (size_t i = 0; i < p->nturns && o + 1 < len; i++) {
        int w = snprintf(buf + o, len - o, "%s%.4g", i ? ", " : "", p->turns[i] * 1e9);
        o += w > 0 ? (size_t)w : 0;
    }
    if (o + 1 < len)
        snprintf(buf + o, len - o, " nm");
}

int tui_sim_field(const char *key)
{
    tui_param p = field_of(key);
    return p < P_COUNT ? (int)p : -1;
}

int tui_sim_param_lookup(const char *name)
{
    for (int p = 0; p < P_COUNT; p++)
        if (strcmp(name, tui_params[p].name) == 0)
            return p;
    return -1;
}

/* One value typed into field p in the configuration's words: a bare number
 * is in the panel's unit, given on in SI, exactly (%.17g reads back to the
 * same double); a value with a unit, a count, auto or none as typed. */
static void field_value(const tui_sim *s, tui_param p, const char *text, char *out, size_t len)
{
    double x, f;
    while (*text == ' ')
        text++;
    if (p != P_N && adh_parse_quantity(text, ADH_Q_NONE, &x, NULL, 0) == 0) {
        tui_sim_param_unit(s, p, 0, &f);
        snprintf(out, len, "%.17g", x * f);
    } else {
        snprintf(out, len, "%s", text);
    }
}

/* The text typed into field p in the configuration's words (a list of
 * turns value by value). -1 with why when it does not fit. */
static int field_text(const tui_sim *s, tui_param p, const char *text, char *out, size_t len, char *why, size_t whylen)
{
    if ((p != P_TURN && p != P_SPEED) || !strchr(text, ',')) {
        field_value(s, p, text, out, len);
        return 0;
    }
    /* a list of turning points, as a scene's turns = ... (or the two speeds);
     * "-1,5nm" (a decimal comma) said of the text typed, before its bare
     * numbers become SI */
    char msg[400];
    if (adh_list_decimal_comma(text, p == P_TURN ? ADH_Q_LENGTH : ADH_Q_SPEED, msg, sizeof msg) != ADH_SUCCESS) {
        snprintf(why, whylen, "%s: %s", tui_params[p].name, msg);
        return -1;
    }
    size_t o = 0;
    for (const char *seg = text;;) {
        const char *comma = strchr(seg, ',');
        char one[128], si[64];
        size_t n = comma ? (size_t)(comma - seg) : strlen(seg);
        if (n >= sizeof one) {
            snprintf(why, whylen, "%s: '%.100s...' is too long a value", tui_params[p].name, seg);
            return -1;
        }
        memcpy(one, seg, n);
        one[n] = '\0';
        if (strspn(one, " \t") == n) {   /* said of the text typed, not of its values in SI */
            snprintf(why, whylen, "%s: '%.100s' has an empty element: separate values by single commas",
                     tui_params[p].name, text);
            return -1;
        }
        field_value(s, p, one, si, sizeof si);
        o += (size_t)snprintf(out + o, o < len ? len - o : 0, "%s%s", seg == text ? "" : ",", si);
        if (!comma)
            break;
        seg = comma + 1;
    }
    if (o >= len) {
        snprintf(why, whylen, "%s: '%.100s' is too long a list", tui_params[p].name, text);
        return -1;
    }
    return 0;
}

int tui_sim_set(tui_sim *s, tui_param p, const char *text, char *why, size_t whylen)
{
    const tui_param_info *pi = &tui_params[p];
    char value[1024], msg[512];
    if (field_text(s, p, text, value, sizeof value, why, whylen) != 0)
        return -1;
    adh_run_spec before = s->cfg.spec;
    /* the spacing set on a grid that followed the material keeps the N on
     * screen: the grid becomes yours as it is shown */
    if (p == P_SPACING && adh_config_grid_auto(&before) && strcmp(value, "auto") != 0) {
        char n[32];
        snprintf(n, sizeof n, "%zu", before.grid.use.nodes);
        adh_config_set(&s->cfg, "grid.nodes", n, msg, sizeof msg);
    }
    if (adh_config_set(&s->cfg, pi->key, value, msg, sizeof msg) != 0) {
        double f;
        const char *unit = p == P_N ? "" : tui_sim_param_unit(s, p, 0, &f);   /* field_value's */
        s->cfg.spec = before;
        refused(pi->name, pi->key, text, value, unit, msg, why, whylen);
        return -1;
    }
    return edit_apply(s, &before, pi->key, why, whylen);
}

int tui_sim_scale(tui_sim *s, tui_param p, double factor, char *why, size_t whylen)
{
    const adh_protocol_settings *ps = &spec(s)->proto;
    double v = param_value(s, p);
    char text[1100];
    if (isnan(v)) {
        snprintf(why, whylen, "%s is not set: type a value first", tui_params[p].name);
        return -1;
    }
    if (!isfinite(v * factor)) {   /* 99999+: it was refused as "'infs' is not a number" */
        snprintf(why, whylen, "%s doubled that many times is past the largest number a double holds (%.3g)",
                 tui_params[p].name, DBL_MAX);
        return -1;
    }
    if (p == P_TURN && ps->nturns > 1) {
        /* every turning point of the list, not the one on screen alone */
        size_t o = 0;
        for (size_t i = 0; i < ps->nturns; i++)
            o += (size_t)snprintf(text + o, sizeof text - o, "%s%.17gm", i ? "," : "", ps->turns[i] * factor);
    } else if (p == P_N) {
        snprintf(text, sizeof text, "%.0f", round(v * factor));
    } else if (p == P_SPEED) {   /* both ways, each by the factor */
        snprintf(text, sizeof text, "%.17gm/s,%.17gm/s", v * factor, spec(s)->time.speed_out * factor);
    } else {
        snprintf(text, sizeof text, "%.17g%s", v * factor, adh_quantity_unit(tui_params[p].q));
    }
    return tui_sim_set(s, p, text, why, whylen);
}

/* The index of the turning point on screen at h0 (within the drive's
 * tolerance of a millionth of a step), or nturns: a turn made by hand. */
static size_t turn_index(const tui_sim *s, double h0)
{
    const adh_protocol_settings *ps = &spec(s)->proto;
    size_t k = 0;
    while (k < ps->nturns && !(fabs(ps->turns[k] - h0) < 1e-6 * ps->step))
        k++;
    return k;
}

/* The turn of the row on screen, for the panel: its branch's turn while
 * unloading, the turn it reached, else the next one loading will reach
 * (the deepest when none is left). */
static void sync_turn(tui_sim *s)
{
    const double *turns = spec(s)->proto.turns;
    size_t nturns = spec(s)->proto.nturns;
    s->tcur = nturns ? nturns - 1 : 0;
    s->turn = nturns ? turns[s->tcur] : NAN;
    if (!nturns || !s->drv || s->grid_stale)
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
        t = turns[k - 1];
    size_t i = isnan(t) ? nturns : turn_index(s, t);
    if (i < nturns) {
        s->tcur = i;
        s->turn = turns[i];
    }
}

/* After a restore: the drive takes the turns on screen (a turn edit since
 * the snapshot was taken keeps the path). */
static void drive_restored(tui_sim *s)
{
    adh_protocol_settings ps = adh_config_protocol_for(&s->cfg, ADH_MODE_RELAX);
    adh_drive_retarget(s->drv, &ps);
    sync_turn(s);
}

/* A solve on a grid the core's check refuses is refused, as --batch
 * refuses the run: with the check's sentence. */
static int grid_refuses(const tui_sim *s, char *why, size_t whylen)
{
    if (!s->gridwarn[0])
        return 0;
    snprintf(why, whylen, "%s", s->gridwarn);   /* already in the TUI's words */
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
            char edge[512];
            edge_words(s->sg, s->curve.rows[s->curve.nrows - 1].a, edge, sizeof edge);
            snprintf(why, whylen, "the curve stopped after %zu points: %s", s->curve.nrows, edge);
        }
        else {
            char reason[600];
            stop_words(&s->curve, reason, sizeof reason);
            snprintf(why, whylen, "the curve stopped after %zu point%s: %s%s%s; x starts it again", s->curve.nrows,
                     s->curve.nrows == 1 ? "" : "s", adh_strerror(s->cstatus), *reason ? ": " : "", reason);
        }
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
static int curve_work(tui_sim *s, char *why, size_t whylen, int *busy)
{
    *busy = 0;
    s->busy = 0;
    s->walked = s->walk != 0;
    if (s->walk) {
        s->ccur = s->walk > 0 ? s->ccur + 1 : s->ccur - 1;
        s->walk = 0;
        /* physical time's summary as at the point shown: walked back
         * before the path's end it showed the whole cycle's hysteresis */
        adh_rule_time_summary_at(s->sdrv, s->ccur + 1, &s->vres);
        return ADH_SUCCESS;
    }
    if (!s->cset) {
        /* the relaxation's start and deepest turn: the two share an axis,
         * as in --batch */
        adh_protocol_settings ps = adh_config_protocol_for(&s->cfg, curve_mode_of(s));
        adh_static_settings ss = adh_config_static_settings(spec(s));
        adh_visco_rule_settings vs;
        adh_config_visco(spec(s), &vs);
        s->ckey.mat = spec(s)->mat;
        s->ckey.grid = s->sbuilt;
        s->ckey.start = s->start;
        s->ckey.end = tui_sim_curve_end(s);
        s->ckey.rule = s->srule;
        s->ckey.time = spec(s)->time;
        adh_run_free(&s->curve);
        adh_run_init(&s->curve);
        int rc = adh_drive_set(s->sdrv, &spec(s)->mat, s->srule != &adh_rule_static ? (const void *)&vs
                               : (const void *)&ss, &ps, &s->curve);
        if (rc != ADH_SUCCESS) {
            s->cstatus = rc;
            snprintf(why, whylen, "the curve cannot start: %s", adh_strerror(rc));
            return rc;
        }
        s->cset = 1;
    }
    char h0[64];
    adh_format_quantity(s->curve.nrows ? s->curve.rows[s->curve.nrows - 1].h0 : s->start, ADH_Q_LENGTH, 4, h0, sizeof h0);
    /* a point of the elastic path's static curve a call: keys are read
     * between (it was solved whole inside one call: 8 s deaf to 'q' at
     * N = 2000, under "any key stops") */
    int row, rc = adh_drive_iterate(s->sdrv, 1, &row);
    if (rc == ADH_CONTINUE && !row) {
        *busy = s->busy = 1;   /* no point yet: the work goes on */
        return ADH_SUCCESS;
    }
    const adh_static *sw = adh_rule_static_solver(s->sdrv);
    if (sw)
        adh_static_summary(sw, &s->sres);
    adh_rule_time_summary(s->sdrv, &s->vres);   /* physical time's, either rule */
    if (row) {
        curve_pushed(s, adh_drive_state(s->sdrv));
        if (rc == ADH_CONTINUE && (adh_drive_events(s->sdrv) & ADH_DRIVE_END))
            rc = ADH_SUCCESS;   /* the curve came down to its end */
    }
    s->cstatus = rc;
    if (rc == ADH_CONTINUE || rc == ADH_SUCCESS)
        return ADH_SUCCESS;
    if (rc == ADH_EGRID) {
        edge_words(s->sg, s->curve.rows[s->curve.nrows - 1].a, why, whylen);
        return ADH_EGRID;
    }
    char reason[600];
    stop_words(&s->curve, reason, sizeof reason);
    snprintf(why, whylen, "the curve stopped %s h0 = %s: %s%s%s; its %zu point%s kept",
             s->curve.nrows ? "after" : "at its start,", h0, rc == ADH_ENAN ? "a non-finite force" : adh_strerror(rc),
             *reason ? ": " : "", reason, s->curve.nrows, s->curve.nrows == 1 ? " is" : "s are");
    return rc;
}

void tui_sim_set_mode(tui_sim *s, adh_mode mode)
{
    tui_sim_cancel(s);
    s->cfg.spec.mode = mode == ADH_MODE_RIGID ? ADH_MODE_RELAX : mode;
    /* the static curve has its own resolution limit: an automatic grid is
     * this mode's (each mode keeps its solver, path or curve, on its own) */
    regrid(s, s->gridchoice, sizeof s->gridchoice);
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
        if (!s->sdrv || !s->curve.nrows ||
            !(s->cstatus == ADH_CONTINUE || s->cstatus == ADH_SUCCESS || s->cstatus == ADH_EGRID))
            return NULL;
        *at = s->curve.nrows - 1;
        return adh_drive_state(s->sdrv);
    }
    /* From a start in contact the unloading goes on past the start
     * (adh_static_set): the pull-off is on the curve past it where it lies
     * below every point from the start inward (1 TPa from 0.1 nm: there
     * the start's own force, +9 uN, was the least of the rows'); the
     * profile is the solver's, at the start's row (no row of the curve's) */
    const adh_static *sw = which == PROF_PULLOFF && s->sdrv && s->curve.nrows ? adh_rule_static_solver(s->sdrv) : NULL;
    double F;
    const adh_state *past = sw ? adh_static_past_least(sw, &F) : NULL;
    if (past && (s->cprof_at[which] == NO_POINT || s->cprof_at[which] >= s->curve.nrows ||
                 F < s->curve.rows[s->cprof_at[which]].F)) {
        *at = 0;
        return past;
    }
    if (which < 0 || which > 1 || s->cprof_at[which] == NO_POINT || s->cprof_at[which] >= s->curve.nrows)
        return NULL;
    *at = s->cprof_at[which];
    return s->cprof[which];
}

size_t tui_sim_curve_fold(const tui_sim *s, adh_static_fold *last)
{
    const adh_static_fold *f;
    const adh_static *sw = s->sdrv ? adh_rule_static_solver(s->sdrv) : NULL;
    size_t n = sw && s->curve.nrows ? adh_static_folds(sw, &f) : 0;
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
    if (tui_sim_curve_mode(s))
        return curve_begin(s, dir, why, whylen);
    if (grid_refuses(s, why, whylen) || path_budget(s, why, whylen) != 0 || ensure_solver(s, why, whylen) != 0)
        return -1;
    int hrc = dir != 0 ? adh_drive_hand(s->drv, dir) : ADH_SUCCESS;
    if (hrc != ADH_SUCCESS) {
        double h0 = adh_drive_hand_position(s->drv, dir);
        if (hrc == ADH_EGRID) {
            /* the edge or the graded grid's fine band: the drive's own sentence says which */
            char edge[512];
            edge_words(s->g, adh_drive_row(s->drv)->a, edge, sizeof edge);
            snprintf(why, whylen, "no approach from here: %s; b retracts", edge);
        }
        else if (fabs(h0) > adh_protocol_reach(&spec(s)->mat))
            snprintf(why, whylen, "h0 = %s is out of reach: the model (h0 << R) allows |h0| up to R/50 = %s",
                     adh_qtext(h0, ADH_Q_LENGTH).s, adh_qtext(adh_protocol_reach(&spec(s)->mat), ADH_Q_LENGTH).s);
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
    if (tui_sim_curve_mode(s)) {
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

/* The edge sentences of the core in the TUI's words. */
static void edge_words(const adh_grid *g, double a, char *why, size_t whylen)
{
    adh_rings_edge_sentence(g, a, why, whylen);
    advice(why, whylen, adh_rings_edge_fix(g, a));
}

tui_work tui_sim_work(tui_sim *s, size_t batch, char *why, size_t whylen)
{
    if (!s->busy)
        return TUI_WORK_STEPPED;
    if (tui_sim_curve_mode(s)) {
        int busy, rc = curve_work(s, why, whylen, &busy);
        return busy ? TUI_WORK_BUSY : rc == ADH_SUCCESS ? TUI_WORK_STEPPED : TUI_WORK_FAILED;
    }
    int row, rc = adh_drive_iterate(s->drv, batch, &row);
    if (rc == ADH_CONTINUE && !row)
        return TUI_WORK_BUSY;
    if (row) {
        if (adh_history_push(s->path.hist, s->drv) != ADH_SUCCESS) {
            snprintf(why, whylen, "out of memory for the history");
            tui_sim_cancel(s);
            return TUI_WORK_FAILED;
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
            return TUI_WORK_BUSY;   /* the start came first: the step asked for goes on */
        s->busy = 0;
        return TUI_WORK_STEPPED;
    }
    s->busy = 0;
    if (rc == ADH_SUCCESS)
        return TUI_WORK_COMPLETE;
    if (rc == ADH_EGRID) {
        edge_words(s->g, adh_drive_row(s->drv)->a, why, whylen);
        return TUI_WORK_FAILED;
    }
    char reason[600];
    stop_words(adh_drive_record(s->drv), reason, sizeof reason);
    snprintf(why, whylen, "the step failed: %s%s%s; back to the previous state (try a smaller d or a larger eps)",
             adh_strerror(rc), *reason ? ": " : "", reason);
    s->busy = 1;
    tui_sim_cancel(s);
    return TUI_WORK_FAILED;
}

unsigned tui_sim_events(const tui_sim *s)
{
    return spec(s)->mode == ADH_MODE_RELAX && s->drv && path_length(s) ? adh_drive_events(s->drv) : 0;
}

int tui_sim_next(const tui_sim *s, size_t *turn)
{
    *turn = spec(s)->proto.nturns ? 1 : 0;
    return s->drv && !s->grid_stale ? adh_drive_next(s->drv, turn) : +1;
}

void tui_sim_why_done(const tui_sim *s, char *buf, size_t len)
{
    int st = s->drv && !s->grid_stale ? adh_drive_status(s->drv) : ADH_SUCCESS;
    if ((st == ADH_SUCCESS || st == ADH_CONTINUE) && !spec(s)->proto.unload && spec(s)->proto.nturns)
        snprintf(buf, len, "the protocol is complete: it loads only (protocol.unload = no); f and b step by hand, "
                 "x starts again");
    else if (st == ADH_SUCCESS || st == ADH_CONTINUE)
        snprintf(buf, len, "the protocol is complete: every turn was unloaded (f and b still step by hand, x starts again)");
    else {
        char reason[600];
        stop_words(adh_drive_record(s->drv), reason, sizeof reason);
        snprintf(buf, len, "the protocol stopped: %s%s%s (f and b still step by hand, x starts again)",
                 adh_strerror(st), *reason ? ": " : "", reason);
    }
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
    size_t nturns = spec(s)->proto.nturns;
    if (k < nturns) {
        if (nturns > 1)
            snprintf(buf, len, "turn %zu of %zu", k + 1, nturns);
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
    s->edit_moved = NULL;
    if (tui_sim_curve_mode(s)) {
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
    s->edit_moved = NULL;
    if (tui_sim_curve_mode(s)) {
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
    if (tui_sim_curve_mode(s)) {
        tui_sim_cancel(s);
        curve_drop(s);   /* the relaxation path is the other mode's: kept */
        return;
    }
    new_path(s);
    sync_turn(s);
}

const adh_obs *tui_sim_row(const tui_sim *s)
{
    if (tui_sim_curve_mode(s))
        return s->curve.nrows ? &s->curve.rows[s->ccur] : NULL;
    return s->path.run.nrows ? &s->path.run.rows[s->path.run.nrows - 1] : NULL;
}

const adh_obs *tui_sim_rows(const tui_sim *s, size_t *n)
{
    if (tui_sim_curve_mode(s)) {
        *n = s->curve.nrows ? s->ccur + 1 : 0;
        return s->curve.nrows ? s->curve.rows : NULL;
    }
    *n = s->path.run.nrows;
    return s->path.run.nrows ? s->path.run.rows : NULL;
}

size_t tui_sim_redoable(const tui_sim *s)
{
    if (tui_sim_curve_mode(s))
        return s->curve.nrows ? s->curve.nrows - 1 - s->ccur : 0;
    return s->path.hist ? adh_history_redoable(s->path.hist) : 0;
}

void tui_sim_cycle(const tui_sim *s, adh_cycle *c)
{
    adh_cycle_measure(s->path.run.nrows ? s->path.run.rows : NULL, s->path.run.nrows, c);
}

double tui_sim_target(const tui_sim *s)
{
    if (tui_sim_curve_mode(s) || !s->drv)
        return s->target;
    return adh_drive_step_position(s->drv);
}

size_t tui_sim_progress(const tui_sim *s, double *change)
{
    if (tui_sim_curve_mode(s)) {
        *change = 0;
        return s->curve.nrows;
    }
    *change = 0;
    return s->drv ? adh_drive_progress(s->drv, change) : 0;
}

size_t tui_sim_kernels_built(const tui_sim *s)
{
    return s->kernels_built + s->startk.built;
}

int tui_sim_will_build(const tui_sim *s)
{
    if (tui_sim_curve_mode(s)) {
        adh_grid_spec g = mode_grid(s, spec(s), curve_mode_of(s));
        return !s->sdrv || !same_grid(&s->sbuilt, &g) || s->srule != curve_rule(s);
    }
    return !s->g || s->grid_stale;
}
