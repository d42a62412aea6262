#include "cli/studyrow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/cycle.h"
#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/status.h"
#include "cli/jumps.h"
#include "cli/tables.h"

enum { NUM, SECS, WORD };
enum { ALWAYS, STATIC_ONLY, TIME_ONLY, STATIC_OR_TIME, SNAP };
enum { W_GRID, W_KERNEL, W_OPERATOR, W_MODE };

typedef struct column {
    const char *name;
    int kind;
    int index;     /* CLI_ROW_* for a number, W_* for a word */
    int when;
} column;

/* After run, swept and value; before the swept keys' columns and status.
 * The first ones are the columns sweep.tsv always had, in their places. */
static const column columns[] = {
    { "E", NUM, CLI_ROW_E, ALWAYS }, { "sigma", NUM, CLI_ROW_SIGMA, ALWAYS }, { "eps", NUM, CLI_ROW_EPS, ALWAYS },
    { "jump_in_h0", NUM, CLI_ROW_JUMP_IN, ALWAYS }, { "h_before", NUM, CLI_ROW_H_BEFORE, ALWAYS },
    { "h_star", NUM, CLI_ROW_H_STAR, ALWAYS }, { "max_load", NUM, CLI_ROW_MAX_LOAD, ALWAYS },
    { "pulloff_F", NUM, CLI_ROW_PULLOFF, ALWAYS }, { "jump_out_h0", NUM, CLI_ROW_JUMP_OUT, ALWAYS },
    { "steps", NUM, CLI_ROW_STEPS, ALWAYS }, { "iterations", NUM, CLI_ROW_ITERATIONS, ALWAYS },
    { "seconds", SECS, CLI_ROW_SECONDS, ALWAYS }, { "jumped", NUM, CLI_ROW_JUMPED, ALWAYS },
    { "hysteresis", NUM, CLI_ROW_HYSTERESIS, ALWAYS },
    { "pulloff_F_disp", NUM, CLI_ROW_PULLOFF_DISP, STATIC_ONLY }, { "folds", NUM, CLI_ROW_FOLDS, STATIC_ONLY },
    { "gamma", NUM, CLI_ROW_GAMMA, ALWAYS }, { "mu", NUM, CLI_ROW_MU, ALWAYS }, { "Estar", NUM, CLI_ROW_ESTAR, ALWAYS },
    { "A", NUM, CLI_ROW_A, ALWAYS }, { "z0", NUM, CLI_ROW_Z0, ALWAYS }, { "R", NUM, CLI_ROW_R, ALWAYS },
    { "nodes", NUM, CLI_ROW_NODES, ALWAYS }, { "spacing", NUM, CLI_ROW_SPACING, ALWAYS },
    { "rmax", NUM, CLI_ROW_RMAX, ALWAYS }, { "grid", WORD, W_GRID, ALWAYS }, { "kernel", WORD, W_KERNEL, ALWAYS },
    { "operator", WORD, W_OPERATOR, ALWAYS }, { "mode", WORD, W_MODE, ALWAYS }, { "step", NUM, CLI_ROW_STEP, ALWAYS },
    { "start", NUM, CLI_ROW_START, ALWAYS }, { "dwell", NUM, CLI_ROW_DWELL, ALWAYS },
    { "F_jkr", NUM, CLI_ROW_F_JKR, ALWAYS }, { "F_dmt", NUM, CLI_ROW_F_DMT, ALWAYS },
    { "turn_h0", NUM, CLI_ROW_TURN_H0, ALWAYS }, { "a_turn", NUM, CLI_ROW_A_TURN, ALWAYS },
    { "pulloff_h0", NUM, CLI_ROW_PULLOFF_H0, ALWAYS }, { "unconverged_steps", NUM, CLI_ROW_UNCONVERGED, ALWAYS },
    { "edge_nodes", NUM, CLI_ROW_EDGE_NODES, ALWAYS }, { "rmax_force_fraction", NUM, CLI_ROW_TAIL, ALWAYS },
    { "resolved", NUM, CLI_ROW_RESOLVED, ALWAYS }, { "converged", NUM, CLI_ROW_CONVERGED, ALWAYS },
    { "complete", NUM, CLI_ROW_COMPLETE, ALWAYS },
    { "points", NUM, CLI_ROW_POINTS, STATIC_ONLY }, { "newton_iterations", NUM, CLI_ROW_NEWTON, STATIC_OR_TIME },
    { "E0", NUM, CLI_ROW_E0, TIME_ONLY }, { "Einf", NUM, CLI_ROW_EINF, TIME_ONLY }, { "tau", NUM, CLI_ROW_TAU, TIME_ONLY },
    { "speed_in", NUM, CLI_ROW_SPEED_IN, TIME_ONLY }, { "speed_out", NUM, CLI_ROW_SPEED_OUT, TIME_ONLY },
    { "dwell_time", NUM, CLI_ROW_DWELL_TIME, TIME_ONLY }, { "spring", NUM, CLI_ROW_SPRING, TIME_ONLY },
    { "jump_in_t", NUM, CLI_ROW_JUMP_IN_T, TIME_ONLY }, { "jump_in_base", NUM, CLI_ROW_JUMP_IN_BASE, TIME_ONLY },
    { "pulloff_t", NUM, CLI_ROW_PULLOFF_T, TIME_ONLY }, { "pulloff_base", NUM, CLI_ROW_PULLOFF_BASE, TIME_ONLY },
    { "jump_out_t", NUM, CLI_ROW_JUMP_OUT_T, TIME_ONLY }, { "jump_out_base", NUM, CLI_ROW_JUMP_OUT_BASE, TIME_ONLY },
    { "dissipated", NUM, CLI_ROW_DISSIPATED, TIME_ONLY }, { "jump_loss", NUM, CLI_ROW_JUMP_LOSS, TIME_ONLY },
    { "stored_change", NUM, CLI_ROW_STORED_CHANGE, TIME_ONLY }, { "time", NUM, CLI_ROW_TIME, TIME_ONLY },
    { "time_steps", NUM, CLI_ROW_TIME_STEPS, TIME_ONLY }, { "jumps", NUM, CLI_ROW_JUMPS, TIME_ONLY },
    { "lattice_jumps", NUM, CLI_ROW_LATTICE_JUMPS, TIME_ONLY }, { "jumps_relaxed", NUM, CLI_ROW_JUMPS_RELAXED, TIME_ONLY }, { "folds_resumed", NUM, CLI_ROW_FOLDS_RESUMED, TIME_ONLY },
    { "krylov_iterations", NUM, CLI_ROW_KRYLOV, TIME_ONLY }, { "tolerance", NUM, CLI_ROW_TOLERANCE, TIME_ONLY },
    { "snap_in_h0", NUM, CLI_ROW_SNAP_IN_H0, SNAP }, { "snap_in_base", NUM, CLI_ROW_SNAP_IN_BASE, SNAP },
    { "snap_out_h0", NUM, CLI_ROW_SNAP_OUT_H0, SNAP }, { "snap_out_base", NUM, CLI_ROW_SNAP_OUT_BASE, SNAP },
    { "snap_in_base_rigid", NUM, CLI_ROW_SNAP_IN_RIGID, SNAP },
};
#define NCOLUMNS (sizeof columns / sizeof columns[0])

/* The static curve's columns: a study in mode static, or one sweeping the mode. */
static int static_columns(const adh_config *cfg)
{
    return cfg->spec.mode == ADH_MODE_STATIC || adh_sweep_touches(&cfg->sweep, "scene.mode");
}

/* Physical time's columns: a study in mode time (a mode swept with it
 * takes them too). */
static int time_columns(const adh_config *cfg)
{
    return cfg->spec.mode == ADH_MODE_TIME || (adh_sweep_touches(&cfg->sweep, "scene.mode") &&
                                               cfg->spec.time.sls);
}

/* The spring's snap points: a spring given or swept, in mode static or time. */
static int snap_columns(const adh_config *cfg)
{
    return (cfg->spec.mode == ADH_MODE_STATIC || cfg->spec.mode == ADH_MODE_TIME) &&
           (isfinite(cfg->spec.time.spring) || adh_sweep_axis_of(&cfg->sweep, "protocol.spring"));
}

static int present(const adh_config *cfg, const column *c)
{
    switch (c->when) {
    case STATIC_ONLY: return static_columns(cfg);
    case TIME_ONLY: return time_columns(cfg);
    case STATIC_OR_TIME: return static_columns(cfg) || time_columns(cfg);
    case SNAP: return snap_columns(cfg);
    }
    return 1;
}

static char *word_of(cli_studyrow *row, int w)
{
    return w == W_GRID ? row->grid : w == W_KERNEL ? row->kernel : w == W_OPERATOR ? row->op : row->mode;
}

static size_t word_size(int w)
{
    cli_studyrow r;
    return w == W_GRID ? sizeof r.grid : w == W_KERNEL ? sizeof r.kernel : w == W_OPERATOR ? sizeof r.op : sizeof r.mode;
}

int cli_studyrow_column(const char *name)
{
    for (size_t k = 0; k < NCOLUMNS; k++)
        if (!strcmp(columns[k].name, name))
            return columns[k].kind == WORD ? -1 : columns[k].index;
    return -1;
}

/* What the run's specification says, whatever the run did. */
static void fill_spec(cli_studyrow *row, const adh_run_spec *rc)
{
    double *v = row->v;
    adh_derived d;
    adh_material_derive(&rc->mat, &d);
    int rigid = rc->mode == ADH_MODE_RIGID;
    v[CLI_ROW_E] = rc->mat.E, v[CLI_ROW_SIGMA] = d.sigma, v[CLI_ROW_EPS] = rc->relax.eps;
    v[CLI_ROW_H_STAR] = d.h_star, v[CLI_ROW_GAMMA] = d.gamma, v[CLI_ROW_MU] = d.mu, v[CLI_ROW_ESTAR] = d.Estar;
    v[CLI_ROW_A] = rc->mat.A, v[CLI_ROW_Z0] = rc->mat.z0, v[CLI_ROW_R] = rc->mat.R;
    v[CLI_ROW_STEP] = rc->proto.step, v[CLI_ROW_DWELL] = (double)rc->proto.dwell;
    v[CLI_ROW_F_JKR] = d.F_jkr, v[CLI_ROW_F_DMT] = d.F_dmt;
    double dr = adh_config_spacing(rc);
    v[CLI_ROW_NODES] = (double)adh_config_nodes(rc);
    v[CLI_ROW_SPACING] = dr;
    v[CLI_ROW_RMAX] = rc->grid.use.graded ? adh_config_rings(rc).rmax : (double)rc->grid.use.nodes * dr;
    adh_grid_report gr;
    adh_config_grid_report(rc, &gr);
    v[CLI_ROW_EDGE_NODES] = rigid ? NAN : gr.edge_nodes;
    v[CLI_ROW_RESOLVED] = rigid || gr.resolved ? 1 : 0;
    snprintf(row->grid, sizeof row->grid, "%s", rc->grid.use.graded ? "graded" : "uniform");
    snprintf(row->kernel, sizeof row->kernel, "%s", adh_kernel_name(rc->grid.use.kernel));
    snprintf(row->op, sizeof row->op, "%s", adh_kernel_storage_name(rc->grid.use.storage));
    snprintf(row->mode, sizeof row->mode, "%s", rc->mode == ADH_MODE_STATIC ? "static" : rigid ? "rigid"
             : rc->mode == ADH_MODE_TIME ? "time" : "relax");
}

/* Rigid spheres' snap-in base on r's rows (eq 22's force at the same
 * positions), under spring k; NAN without one. */
static double rigid_snap_in(const adh_run *r, double k)
{
    adh_run rigid;
    adh_run_init(&rigid);
    for (size_t j = 0; j < r->nrows; j++) {
        adh_obs o = r->rows[j];
        o.F = o.F_rigid;
        o.path = 0;
        if (adh_run_push_row(&rigid, &o) != ADH_SUCCESS)
            break;
    }
    double at, base = NAN;
    if (adh_visco_spring_folds(&rigid, k, &at, &base, 1) < 1)
        base = NAN;
    adh_run_free(&rigid);
    return base;
}

/* The spring's snap points of run r: a static curve's where its base
 * turns, a run in time's first jump in and last jump out (its events). */
static void fill_snap(double *v, const adh_run_spec *rc, const adh_run *r, const cli_time_out *tout)
{
    double k = rc->time.spring;
    if (!isfinite(k) || !r->nrows)
        return;
    if (rc->mode == ADH_MODE_STATIC) {
        double store[CLI_TIME_SNAP_KEYS];
        cli_tables_extra x[CLI_TIME_SNAP_KEYS];
        cli_time_snap_keys(r, k, store, x);
        v[CLI_ROW_SNAP_IN_H0] = store[1], v[CLI_ROW_SNAP_IN_BASE] = store[2];
        v[CLI_ROW_SNAP_OUT_H0] = store[3], v[CLI_ROW_SNAP_OUT_BASE] = store[4];
    } else if (tout) {
        for (size_t e = 0; e < tout->nev; e++) {
            const adh_visco_event *ev = &tout->ev[e];
            if (ev->kind != ADH_VISCO_JUMP)
                continue;
            if (ev->path == 0 && isnan(v[CLI_ROW_SNAP_IN_H0]))
                v[CLI_ROW_SNAP_IN_H0] = ev->h0, v[CLI_ROW_SNAP_IN_BASE] = ev->base;
            if (ev->path > 0)
                v[CLI_ROW_SNAP_OUT_H0] = ev->h0, v[CLI_ROW_SNAP_OUT_BASE] = ev->base;
        }
    }
    v[CLI_ROW_SNAP_IN_RIGID] = rigid_snap_in(r, k);
}

/* The jump into contact of a run in physical time, from its events (a
 * drive step means nothing on the integrator's rows): jumped 1 when the
 * first contact on loading came by a jump, 0 when it formed without one,
 * -1 when there was none; h_before the central gap on the last loading
 * row out of contact at or before that event (the row at the fold). */
static void time_jump(double *v, const adh_run *r, const cli_time_out *o)
{
    const adh_visco_event *first = NULL;
    for (size_t e = 0; e < o->nev && !first; e++)
        if (o->ev[e].path == 0 && (o->ev[e].kind == ADH_VISCO_JUMP || o->ev[e].kind == ADH_VISCO_CONTACT))
            first = &o->ev[e];
    v[CLI_ROW_JUMPED] = !first ? -1 : first->kind == ADH_VISCO_JUMP ? 1 : 0;
    v[CLI_ROW_H_BEFORE] = NAN;
    for (size_t i = 0; first && i < r->nrows && r->rows[i].path == 0 && r->rows[i].t <= first->t &&
                       r->rows[i].a == 0; i++)
        v[CLI_ROW_H_BEFORE] = r->rows[i].hc;
}

/* A run in physical time's numbers: its summary's (cli_time_keys) by name,
 * and its pull-off, jumps and hysteresis in the columns every mode has. */
static void fill_time(double *v, const adh_run *r, const cli_time_out *o)
{
    static const struct { const char *key; int col; } map[] = {
        { "E0", CLI_ROW_E0 }, { "Einf", CLI_ROW_EINF }, { "tau", CLI_ROW_TAU }, { "speed_in", CLI_ROW_SPEED_IN },
        { "speed_out", CLI_ROW_SPEED_OUT }, { "dwell_time", CLI_ROW_DWELL_TIME }, { "spring", CLI_ROW_SPRING },
        { "jump_in_t", CLI_ROW_JUMP_IN_T }, { "jump_in_base", CLI_ROW_JUMP_IN_BASE }, { "pulloff_t", CLI_ROW_PULLOFF_T },
        { "pulloff_base", CLI_ROW_PULLOFF_BASE }, { "jump_out_t", CLI_ROW_JUMP_OUT_T },
        { "jump_out_base", CLI_ROW_JUMP_OUT_BASE }, { "hysteresis", CLI_ROW_HYSTERESIS },
        { "dissipated", CLI_ROW_DISSIPATED }, { "jump_loss", CLI_ROW_JUMP_LOSS },
        { "stored_change", CLI_ROW_STORED_CHANGE }, { "time", CLI_ROW_TIME }, { "time_steps", CLI_ROW_TIME_STEPS },
        { "jumps", CLI_ROW_JUMPS }, { "lattice_jumps", CLI_ROW_LATTICE_JUMPS },
        { "jumps_relaxed", CLI_ROW_JUMPS_RELAXED },
        { "folds_resumed", CLI_ROW_FOLDS_RESUMED }, { "newton_iterations", CLI_ROW_NEWTON },
        { "krylov_iterations", CLI_ROW_KRYLOV }, { "tolerance", CLI_ROW_TOLERANCE },
    };
    cli_tables_extra x[CLI_TIME_KEYS];
    size_t n = cli_time_keys(o, x);
    for (size_t k = 0; k < n; k++)
        for (size_t m = 0; m < sizeof map / sizeof map[0]; m++)
            if (!strcmp(x[k].key, map[m].key))
                v[map[m].col] = r->nrows ? x[k].value : NAN;
    const adh_visco_result *res = &o->res;
    int ran = r->nrows > 0;
    v[CLI_ROW_JUMP_IN] = ran ? res->jump_in_h0 : NAN;
    v[CLI_ROW_PULLOFF] = ran ? res->pulloff_F : NAN;
    v[CLI_ROW_PULLOFF_H0] = ran ? res->pulloff_h0 : NAN;
    v[CLI_ROW_JUMP_OUT] = ran ? res->jump_out_h0 : NAN;
    time_jump(v, r, o);
}

void cli_studyrow_fill(cli_studyrow *row, const adh_config *cfg, size_t i, const adh_run_spec *rc, const adh_run *r,
                       const adh_static_result *sres, const cli_time_out *tout, int status)
{
    double *v = row->v;
    for (size_t k = 0; k < CLI_ROW_NUMBERS; k++)
        v[k] = NAN;
    row->run = i;
    row->done = 1;
    fill_spec(row, rc);
    int stat = rc->mode == ADH_MODE_STATIC && sres;
    const adh_turn_result *mt = adh_run_main_turn(r);
    double max_load = mt ? mt->max_load : NAN, pull = mt ? mt->pulloff_F : NAN, out = mt ? mt->jump_out_h0 : NAN;
    int ran = r->nrows > 0;
    if (stat) {
        /* a run that never started has no summary worth the name */
        max_load = ran && status == ADH_SUCCESS && !r->interrupted ? r->rows[r->nrows - 1].F : NAN;
        pull = ran ? sres->pulloff_F : NAN;
        out = ran ? sres->jump_out_h0 : NAN;
        v[CLI_ROW_PULLOFF_DISP] = ran ? sres->pulloff_F_disp : NAN;
        v[CLI_ROW_FOLDS] = ran ? (double)sres->folds : 0;
        v[CLI_ROW_PULLOFF_H0] = ran ? sres->pulloff_h0 : NAN;
        v[CLI_ROW_POINTS] = ran ? (double)sres->points : 0;
        v[CLI_ROW_NEWTON] = ran ? (double)sres->newton_iterations : 0;
        v[CLI_ROW_HYSTERESIS] = ran ? cli_tables_static_hysteresis(r, &rc->mat) : NAN;
    } else {
        v[CLI_ROW_HYSTERESIS] = mt ? adh_cycle_hysteresis(r->rows, r->nrows, mt->path) : NAN;
        v[CLI_ROW_TURN_H0] = mt ? mt->h0 : NAN;
        v[CLI_ROW_A_TURN] = mt ? mt->a_turn : NAN;
        v[CLI_ROW_PULLOFF_H0] = mt ? mt->pulloff_h0 : NAN;
    }
    v[CLI_ROW_JUMP_IN] = r->jump_in_h0;
    v[CLI_ROW_H_BEFORE] = cli_jumps_gap_before(r);
    v[CLI_ROW_MAX_LOAD] = max_load, v[CLI_ROW_PULLOFF] = pull, v[CLI_ROW_JUMP_OUT] = out;
    v[CLI_ROW_STEPS] = (double)r->nrows, v[CLI_ROW_ITERATIONS] = (double)r->iterations;
    v[CLI_ROW_SECONDS] = r->seconds;
    v[CLI_ROW_JUMPED] = cli_jumps_jumped(r, rc->proto.step);
    v[CLI_ROW_START] = r->start;
    v[CLI_ROW_UNCONVERGED] = (double)cli_tables_capped_steps(r);
    v[CLI_ROW_TAIL] = rc->mode == ADH_MODE_RIGID || !ran ? NAN : r->rows[0].F_tail / r->rows[0].F;
    v[CLI_ROW_CONVERGED] = r->unconverged == 0 && status == ADH_SUCCESS && !r->interrupted ? 1 : 0;
    const char *word = status != ADH_SUCCESS && !r->interrupted ? adh_strerror(status) : cli_tables_verdict(rc, r);
    snprintf(row->status, sizeof row->status, "%s", word);
    row->reason = NULL;
    char reason[CLI_TABLES_REASON_LEN];
    if (status != ADH_SUCCESS && !r->interrupted && r->status == status &&
        *cli_tables_stop_reason(cfg, r, reason, sizeof reason))
        row->reason = strdup(reason);   /* NULL when out of memory: the status word alone */
    else if (status == ADH_SUCCESS && *cli_tables_marked_reason(cfg, r, reason, sizeof reason))
        row->reason = strdup(reason);   /* why it ran through unconverged, as summary.tsv's */
    int partial = r->interrupted || status != ADH_SUCCESS;
    v[CLI_ROW_COMPLETE] = !partial && strcmp(word, "no contact") && strcmp(word, "not separated") ? 1 : 0;
    if (rc->mode == ADH_MODE_TIME && tout)
        fill_time(v, r, tout);
    fill_snap(v, rc, r, tout);
}

void cli_studyrow_empty(cli_studyrow *row, const adh_config *cfg, size_t i, const char *status)
{
    adh_run_spec rc;
    adh_run none;
    adh_run_init(&none);
    adh_config_sweep_run(cfg, i, &rc);
    adh_static_result sres;
    memset(&sres, 0, sizeof sres);
    cli_studyrow_fill(row, cfg, i, &rc, &none, rc.mode == ADH_MODE_STATIC ? &sres : NULL, NULL, ADH_SUCCESS);
    snprintf(row->status, sizeof row->status, "%s", status);
    row->v[CLI_ROW_COMPLETE] = 0;
}

void cli_studyrow_clear(cli_studyrow *row)
{
    free(row->reason);
    row->reason = NULL;
}

void cli_studyrow_clear_all(cli_studyrow *rows, size_t n)
{
    for (size_t i = 0; rows && i < n; i++)
        cli_studyrow_clear(&rows[i]);
}

int cli_studyrow_complete(const cli_studyrow *row)
{
    return row->done && strcmp(row->status, "interrupted") && strcmp(row->status, "not run") &&
           strcmp(row->status, "output incomplete");
}

/* ---- the table's text ---------------------------------------------------- */

/* Value j of axis a as the table says it: a number at %.17g, a word as written. */
static void axis_text(const adh_sweep_axis *a, size_t j, char *buf, size_t len)
{
    char text[64];
    double v = adh_sweep_value(a, j, text, sizeof text);
    if (isnan(v))
        snprintf(buf, len, "%s", text);
    else
        snprintf(buf, len, "%.17g", v);
}

/* The swept and value columns: each swept key's name and value, by commas. */
static void swept_value(const adh_config *cfg, size_t i, char *swept, char *value, size_t len)
{
    const adh_sweep *s = &cfg->sweep;
    size_t idx[ADH_SWEEP_MAX_AXES], o = 0, p = 0;
    adh_sweep_index(s, i, idx);
    swept[0] = value[0] = '\0';
    for (size_t k = 0; k < s->naxes; k++) {
        char t[64];
        axis_text(&s->axis[k], idx[k], t, sizeof t);
        o += (size_t)snprintf(swept + o, len - o, "%s%s", k ? "," : "", s->axis[k].name);
        p += (size_t)snprintf(value + p, len - p, "%s%s", k ? "," : "", t);
        if (o >= len || p >= len)
            break;
    }
}

void cli_studyrow_header(FILE *f, const adh_config *cfg)
{
    fputs("run\tswept\tvalue", f);
    for (size_t k = 0; k < NCOLUMNS; k++)
        if (present(cfg, &columns[k]))
            fprintf(f, "\t%s", columns[k].name);
    for (size_t k = 0; k < cfg->sweep.naxes; k++)
        fprintf(f, "\tsweep.%s", cfg->sweep.axis[k].name);
    fputs("\tstatus\n", f);
}

void cli_studyrow_write(FILE *f, const adh_config *cfg, const cli_studyrow *row)
{
    char swept[512], value[512];
    swept_value(cfg, row->run, swept, value, sizeof swept);
    fprintf(f, "%zu\t%s\t%s", row->run + 1, swept, value);
    for (size_t k = 0; k < NCOLUMNS; k++) {
        const column *c = &columns[k];
        if (!present(cfg, c))
            continue;
        if (c->kind == WORD)
            fprintf(f, "\t%s", word_of((cli_studyrow *)row, c->index));
        else
            fprintf(f, c->kind == SECS ? "\t%.6g" : "\t%.17g", row->v[c->index]);
    }
    size_t idx[ADH_SWEEP_MAX_AXES];
    adh_sweep_index(&cfg->sweep, row->run, idx);
    for (size_t k = 0; k < cfg->sweep.naxes; k++) {
        char t[64];
        axis_text(&cfg->sweep.axis[k], idx[k], t, sizeof t);
        fprintf(f, "\t%s", t);
    }
    fprintf(f, "\t%s%s%s\n", row->status, row->reason ? ": " : "", row->reason ? row->reason : "");
}

int cli_studyrow_is_header(const adh_config *cfg, const char *line)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (!m)
        return 0;
    cli_studyrow_header(m, cfg);
    fclose(m);
    int same = text && len && strncmp(text, line, len - 1) == 0 && line[len - 1] == '\0';
    free(text);
    return same;
}

/* The next field of *p (up to a tab or the end) into buf; -1 when there is none. */
static int field(const char **p, char *buf, size_t len)
{
    if (!*p)
        return -1;
    const char *tab = strchr(*p, '\t');
    size_t n = tab ? (size_t)(tab - *p) : strlen(*p);
    if (n >= len)
        return -1;
    memcpy(buf, *p, n);
    buf[n] = '\0';
    *p = tab ? tab + 1 : NULL;
    return 0;
}

static int number(const char *text, double *v)
{
    char *end;
    *v = strtod(text, &end);
    return *text && *end == '\0' ? 0 : -1;
}

int cli_studyrow_parse(const adh_config *cfg, const char *line, cli_studyrow *row)
{
    char f[512], swept[512], value[512], want_s[512], want_v[512];
    const char *p = line;
    double run;
    memset(row, 0, sizeof *row);
    if (field(&p, f, sizeof f) || number(f, &run) || !(run >= 1 && run <= (double)adh_config_nruns(cfg)) ||
        run != floor(run) || field(&p, swept, sizeof swept) || field(&p, value, sizeof value))
        return -1;
    row->run = (size_t)run - 1;
    swept_value(cfg, row->run, want_s, want_v, sizeof want_s);
    if (strcmp(swept, want_s) || strcmp(value, want_v))
        return -1;
    for (size_t k = 0; k < CLI_ROW_NUMBERS; k++)
        row->v[k] = NAN;
    for (size_t k = 0; k < NCOLUMNS; k++) {
        const column *c = &columns[k];
        if (!present(cfg, c))
            continue;
        if (field(&p, f, sizeof f))
            return -1;
        if (c->kind == WORD) {
            if (strlen(f) >= word_size(c->index))
                return -1;
            strcpy(word_of(row, c->index), f);
        } else if (number(f, &row->v[c->index])) {
            return -1;
        }
    }
    size_t idx[ADH_SWEEP_MAX_AXES];
    adh_sweep_index(&cfg->sweep, row->run, idx);
    for (size_t k = 0; k < cfg->sweep.naxes; k++) {
        char t[64];
        axis_text(&cfg->sweep.axis[k], idx[k], t, sizeof t);
        if (field(&p, f, sizeof f) || strcmp(f, t))
            return -1;
    }
    /* "status: reason" for a run that stopped on an error (no status word has ": ") */
    char text[sizeof row->status + 600];
    if (field(&p, text, sizeof text) || p || !text[0])
        return -1;
    char *colon = strstr(text, ": ");
    if (colon)
        *colon = '\0';
    if (strlen(text) >= sizeof row->status || (colon && !(row->reason = strdup(colon + 2))))
        return -1;
    strcpy(row->status, text);
    row->done = 1;
    return 0;
}

int cli_studyrow_table(FILE *f, const void *ctx)
{
    const cli_studyrow_sweep *t = ctx;
    const adh_config *cfg = t->cfg;
    const cli_studyrow *rows = t->rows;
    const char *partial = t->partial;
    double static_hysteresis = t->static_hysteresis;
    int run_dirs = t->run_dirs, static_resolved = t->static_resolved;
    const adh_sweep *s = &cfg->sweep;
    fprintf(f, "# adhere " ADH_VERSION "\n# sweep: one row per run (%s), SI units (m, N, Pa, s%s)\n",
            run_dirs ? "run-K/ holds its tables" : "run_dirs = no: no run-K/",
            time_columns(cfg) || snap_columns(cfg) ? ", J, N/m" : "");
    if (cfg->scene[0])
        cli_tables_comment(f, "scene", cfg->scene);
    if (partial && *partial)
        fprintf(f, "# PARTIAL: %s\n", partial);
    if (time_columns(cfg))
        fprintf(f, "# physical time: pulloff_F the lowest force on the deepest turn's unloading, hysteresis the base's work over "
                   "its cycle, dissipated its viscous part; *_t and *_base the time and the instrument's base there; time the "
                   "run's physical time, time_steps its integrator steps\n");
    if (snap_columns(cfg))
        fprintf(f, "# the spring: snap_in where the base h0 - F/k first turns on approach (dF/dh0 = k; in time the first jump "
                   "in), snap_out where it turns last, on retraction; snap_in_base_rigid rigid spheres' (eq 22), N/m for k\n");
    if (cfg->spec.mode == ADH_MODE_STATIC)
        fprintf(f, "# mode static: each run is the equilibrium curve; jump_in_h0 its first fold, h_before the central gap at the last stable point before it;\n"
                   "# max_load the force at the curve's end (the turn); pulloff_F the load-controlled pull-off (minimum force), pulloff_F_disp the force at the jump-out fold;\n"
                   "# jumped: 1 the curve has a fold, 0 contact came without one, -1 no contact; steps the curve's points, iterations its Newton iterations;\n"
                   "# hysteresis: the equilibrium loop's area (displacement control: the highest and lowest stable force at each h0), J\n");
    else if (cfg->spec.mode == ADH_MODE_TIME)   /* its pull-off and hysteresis: the comment above */
        fprintf(f, "# h_before: central gap on the last loading row out of contact at the first contact event "
                   "(events.tsv); jumped: 1 that event is a jump, 0 contact formed without one, -1 no contact; "
                   "h_star: eq 24; jump_out_h0: where the contact was lost on the deepest turn's unloading\n");
    else
        fprintf(f, "# h_before: central gap on the last loading row before the jump into contact; h_star: eq 24\n"
                   "# jumped: 1 the gap fell by more than 2 steps into contact, 0 contact came gradually (no jump identified), -1 no contact\n"
                   "# pulloff_F: the force minimum on unloading; jump_out_h0: where the surfaces separate; hysteresis: the area between loading and unloading, J\n");
    if (s->naxes == 1) {
        fprintf(f, "# swept: the parameter the sweep varies (%s), value: its value in this run\n", s->axis[0].name);
    } else {
        fprintf(f, "# swept: the parameters the study varies (");
        for (size_t k = 0; k < s->naxes; k++)
            fprintf(f, "%s%s", k ? "," : "", s->axis[k].name);
        fprintf(f, "), value: their values in this run, by commas; sweep.KEY: each one's value\n");
    }
    if (!isnan(static_hysteresis))
        fprintf(f, "# static_hysteresis: %.17g J, the static curve's loop (eps -> 0: the jump instabilities' share of every run's hysteresis)%s\n",
                static_hysteresis, static_resolved ? "" : ", on a grid that does not resolve it");
    cli_studyrow_header(f, cfg);
    size_t n = adh_config_nruns(cfg);
    for (size_t i = 0; i < n; i++)
        cli_studyrow_write(f, cfg, &rows[i]);
    return 0;
}
