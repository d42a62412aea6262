#include "cli/tables.h"
#include "plot/outdir.h"
#include "plot/rows.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "adhere/cycle.h"
#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/status.h"
#include "cli/advice.h"
#include "scene/text.h"

#define VERSION_LINE "# adhere " ADH_VERSION "\n"

void cli_tables_comment(FILE *f, const char *key, const char *value)
{
    fprintf(f, "# %s: ", key);
    for (const unsigned char *p = (const unsigned char *)value; *p; p++) {
        if (*p == '\\')
            fputs("\\\\", f);
        else if (*p == '\n')
            fputs("\\n", f);
        else if (*p == '\r')
            fputs("\\r", f);
        else if (*p == '\t')
            fputs("\\t", f);
        else if (*p < 0x20 || *p == 0x7f)
            fprintf(f, "\\x%02x", *p);
        else
            fputc(*p, f);
    }
    fputc('\n', f);
}

static void comment_head(FILE *f, const cli_tables *t, const char *what)
{
    fprintf(f, VERSION_LINE "# %s, SI units (m, N, Pa, J, s, rad)\n", what);
    if (t->cfg->scene[0])
        cli_tables_comment(f, "scene", t->cfg->scene);
    if (t->partial)
        fprintf(f, "# PARTIAL: %s\n", t->note ? t->note : "the run did not finish");
}

int cli_tables_force(FILE *f, const void *ctx)
{
    const cli_tables *t = ctx;
    int timed = t->spec->mode == ADH_MODE_TIME;
    comment_head(f, t, timed ? "force table in physical time: one row per integrator step; t the time, base the "
                 "instrument's base (h0 = base + F/k), h0 the sphere's position; branch +1 loading, -1 unloading; "
                 "path 0 loading, k the k-th unloading branch; iters Newton iterations"
                 : "force table: one row per drive step; branch +1 loading, -1 unloading; path 0 loading, k the k-th unloading branch");
    (timed ? adh_rows_header_timed : adh_rows_header)(f);
    for (size_t i = 0; i < t->run->nrows; i++)
        (timed ? adh_rows_write_timed : adh_rows_write)(f, &t->run->rows[i]);
    return 0;
}

void cli_tables_names_add(char *buf, size_t len, const char *name)
{
    size_t n = strlen(buf), m = strlen(name), sep = n ? 1 : 0;
    if (!m || n + sep + m >= len)
        return;
    if (sep)
        buf[n++] = ',';
    memcpy(buf + n, name, m + 1);
}

const char *cli_tables_status_word(const adh_run *r)
{
    if (r->interrupted)
        return "interrupted";
    if (r->status != ADH_SUCCESS)
        return adh_strerror(r->status);
    return r->unconverged ? "unconverged" : "success";
}

/* 0 when the surfaces touched and every unloading branch separated; 1 no
 * contact, 2 not separated, with why. A rigid run is not asked. */
static int contact_fault(const adh_run_spec *c, const adh_run *r, char *why, size_t whylen)
{
    if (c->mode == ADH_MODE_RIGID)
        return 0;
    adh_derived d;
    adh_material_derive(&c->mat, &d);
    if (!adh_run_touched(r, d.h_star, why, whylen))
        return 1;
    return adh_run_separated(r, why, whylen) ? 0 : 2;
}

static int grid_resolved(const adh_run_spec *c)
{
    adh_grid_report gr;
    adh_config_grid_report(c, &gr);
    return c->mode == ADH_MODE_RIGID || gr.resolved;
}

const char *cli_tables_verdict(const adh_run_spec *c, const adh_run *r)
{
    const char *word = cli_tables_status_word(r);
    if (strcmp(word, "success") != 0)
        return word;
    char why[512];
    int fault = contact_fault(c, r, why, sizeof why);
    return fault == 1 ? "no contact" : fault == 2 ? "not separated" : !grid_resolved(c) ? "unresolved" : word;
}

const char *cli_tables_summary_word(const cli_tables *t)
{
    const char *word = t->status ? t->status : cli_tables_verdict(t->spec, t->run);
    return !strcmp(word, "success") && t->unwritten && *t->unwritten ? "output incomplete" : word;
}

static const char *reason_for(const adh_config *cfg, cli_advice_for who, const char *why, unsigned fix, char *buf,
                              size_t len)
{
    snprintf(buf, len, "%s", why);
    if (buf[0])   /* in the words each key was given in: a scene's by its key and line */
        cli_advice_append_cfg(cfg, who, buf, len, fix);
    /* after the advice: a scene's name may hold a tab or a newline too */
    for (char *p = buf; *p; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f)
            *p = ' ';
    return buf;
}

const char *cli_tables_reason(const adh_config *cfg, const char *why, unsigned fix, char *buf, size_t len)
{
    return reason_for(cfg, CLI_ADVICE_RUN, why, fix, buf, len);
}

const char *cli_tables_stop_reason_for(const adh_config *cfg, cli_advice_for who, const adh_run *r, char *buf,
                                       size_t len)
{
    buf[0] = '\0';
    if (r->interrupted || r->status == ADH_SUCCESS || !r->why[0])
        return buf;
    return reason_for(cfg, who, r->why, r->fix, buf, len);
}

const char *cli_tables_stop_reason(const adh_config *cfg, const adh_run *r, char *buf, size_t len)
{
    return cli_tables_stop_reason_for(cfg, CLI_ADVICE_RUN, r, buf, len);
}

const char *cli_tables_stopped(const adh_config *cfg, const adh_run *r, int status, char *buf, size_t len)
{
    char reason[CLI_TABLES_REASON_LEN];
    snprintf(buf, len, "%s%s", adh_strerror(status), *cli_tables_stop_reason(cfg, r, reason, sizeof reason) ? ": " : "");
    adh_text_cat(buf, len, reason);
    return buf;
}

static void kv(FILE *f, const char *k, double v)
{
    fprintf(f, "%s\t%.17g\n", k, v);
}

int cli_tables_summary(FILE *f, const void *ctx)
{
    const cli_tables *t = ctx;
    const adh_run_spec *c = t->spec;
    const adh_run *r = t->run;
    adh_derived d;
    adh_material_derive(&c->mat, &d);
    comment_head(f, t, "run summary: key<TAB>value");
    fputs("key\tvalue\n", f);
    kv(f, "sigma", d.sigma);
    kv(f, "gamma", d.gamma);
    kv(f, "mu", d.mu);
    kv(f, "Estar", d.Estar);
    kv(f, "E", c->mat.E);
    kv(f, "A", c->mat.A);
    kv(f, "z0", c->mat.z0);
    kv(f, "R", c->mat.R);
    if (c->grid.use.graded) {
        /* the rings actually built: N and Rmax follow from the spec */
        adh_rings_spec rs = adh_config_rings(c);
        adh_grid *g = adh_rings_alloc(&rs);
        kv(f, "nodes", g ? (double)g->n : NAN);
        kv(f, "spacing", rs.dr);
        kv(f, "rmax", g ? g->rmax : NAN);
        fprintf(f, "grid\tgraded\n");
        kv(f, "fine_band", rs.fine);
        kv(f, "growth", rs.ratio);
        adh_grid_free(g);
    } else {
        kv(f, "nodes", (double)c->grid.use.nodes);
        kv(f, "spacing", adh_config_spacing(c));
        kv(f, "rmax", (double)c->grid.use.nodes * adh_config_spacing(c));
    }
    fprintf(f, "kernel\t%s\n", adh_kernel_name(c->grid.use.kernel));
    fprintf(f, "operator\t%s\n", adh_kernel_storage_name(c->grid.use.storage));
    fprintf(f, "mode\t%s\n", c->mode == ADH_MODE_STATIC ? "static" : c->mode == ADH_MODE_TIME ? "time" : "relax");
    if (c->mode == ADH_MODE_TIME)
        fprintf(f, "material\t%s\n", c->time.sls ? "sls" : "elastic");
    kv(f, "eps", c->relax.eps);
    kv(f, "step", c->proto.step);
    kv(f, "start", r->start);
    kv(f, "dwell", (double)c->proto.dwell);
    kv(f, "F_jkr", d.F_jkr);
    kv(f, "F_dmt", d.F_dmt);
    kv(f, "h_star", d.h_star);
    /* In static mode the jumps and pull-off come from the curve's folds and
     * minimum (the extra keys), not from unloading branches. */
    if (c->mode != ADH_MODE_STATIC) {
        kv(f, "jump_in_h0", r->jump_in_h0);
        const adh_turn_result *mt = adh_run_main_turn(r);
        kv(f, "turn_h0", mt ? mt->h0 : NAN);
        kv(f, "max_load", mt ? mt->max_load : NAN);
        kv(f, "a_turn", mt ? mt->a_turn : NAN);
        kv(f, "pulloff_F", mt ? mt->pulloff_F : NAN);
        kv(f, "pulloff_h0", mt ? mt->pulloff_h0 : NAN);
        kv(f, "jump_out_h0", mt ? mt->jump_out_h0 : NAN);
        if (c->mode != ADH_MODE_TIME)   /* physical time's is the base's work, integrated (an extra key) */
            kv(f, "hysteresis", mt ? adh_cycle_hysteresis(r->rows, r->nrows, mt->path) : NAN);
    }
    for (size_t i = 0; i < t->nextra; i++)
        kv(f, t->extra[i].key, t->extra[i].value);
    kv(f, "steps", (double)r->nrows);
    kv(f, "iterations", (double)r->iterations);
    kv(f, "unconverged_steps", (double)cli_tables_capped_steps(r));
    kv(f, "seconds", r->seconds);
    /* the grid's resolution of the contact edge (adh_grid_check) and the
     * share of the starting force from beyond Rmax (the analytic tail) */
    int rigid = c->mode == ADH_MODE_RIGID;
    adh_grid_report gr;
    adh_config_grid_report(c, &gr);
    kv(f, "edge_nodes", rigid ? NAN : gr.edge_nodes);
    kv(f, "rmax_force_fraction", rigid || r->nrows == 0 ? NAN : r->rows[0].F_tail / r->rows[0].F);
    kv(f, "resolved", rigid || gr.resolved ? 1 : 0);
    /* an interrupted run stopped mid-way: its last step may be anywhere */
    kv(f, "converged", (r->unconverged == 0 && r->status == ADH_SUCCESS && !r->interrupted) ? 1 : 0);
    char why[512];
    int fault = contact_fault(c, r, why, sizeof why);
    int lost = t->unwritten && *t->unwritten;
    kv(f, "complete", t->partial || fault || lost ? 0 : 1);
    if (fault && !t->partial)
        fprintf(f, "# INCOMPLETE: %s\n", why);
    if (lost)
        fprintf(f, "not_written\t%s\n", t->unwritten);
    /* success only for a finished, converged run on a resolved grid that
     * touched and separated, every file of which was written */
    fprintf(f, "status\t%s\n", cli_tables_summary_word(t));
    /* what stopped a run that ended on an error, and what may get past it */
    char reason[CLI_TABLES_REASON_LEN];
    if (*cli_tables_stop_reason(t->cfg, r, reason, sizeof reason))
        fprintf(f, "stop_reason\t%s\n", reason);
    /* and why a run that ran through is marked unconverged: it did not
     * stop, so not stop_reason */
    if (*cli_tables_marked_reason(t->cfg, r, reason, sizeof reason))
        fprintf(f, "unconverged_reason\t%s\n", reason);
    return 0;
}

int cli_tables_turns(FILE *f, const void *ctx)
{
    const cli_tables *t = ctx;
    comment_head(f, t, "turning points: the adhesion (-pulloff_F) against the maximum load (Figures 5, 6 insets)");
    fputs("turn_h0\tmax_load\ta_turn\tpulloff_F\tpulloff_h0\tjump_out_h0\tpath\thysteresis\n", f);
    const adh_run *r = t->run;
    /* physical time's is the base's work over each turn's cycle, as its
     * step rule accounted it (summary.tsv's for the deepest): the area
     * between the rows' branches, linear between their unequal steps, was
     * 0.3 % off it beside the cycle's energy balance */
    int timed = t->spec->mode == ADH_MODE_TIME;
    for (size_t i = 0; i < r->nturns; i++) {
        const adh_turn_result *tr = &r->turns[i];
        fprintf(f, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%d\t%.17g\n", tr->h0, tr->max_load, tr->a_turn,
                tr->pulloff_F, tr->pulloff_h0, tr->jump_out_h0, tr->path,
                tr->path <= 0 ? NAN : timed ? tr->hysteresis : adh_cycle_hysteresis(r->rows, r->nrows, tr->path));
    }
    return 0;
}

double cli_tables_static_hysteresis(const adh_run *curve, const adh_material *m)
{
    return curve->nrows ? adh_cycle_static_hysteresis(curve, CLI_TABLES_HYSTERESIS_STEP * m->z0) : NAN;
}

size_t cli_tables_static_keys(const adh_static_result *res, double hysteresis, const char *prefix,
                              char names[][32], cli_tables_extra *extra)
{
    const struct { const char *key; double value; } v[CLI_TABLES_STATIC_KEYS] = {
        { "jump_in_h0", res->jump_in_h0 },
        { "jump_out_h0", res->jump_out_h0 },
        { "pulloff_F", res->pulloff_F },
        { "pulloff_h0", res->pulloff_h0 },
        { "pulloff_F_disp", res->pulloff_F_disp },
        { "folds", (double)res->folds },
        { "points", (double)res->points },
        { "newton_iterations", (double)res->newton_iterations },
        { "hysteresis", hysteresis },
    };
    for (size_t i = 0; i < CLI_TABLES_STATIC_KEYS; i++) {
        snprintf(names[i], 32, "%s%s", prefix, v[i].key);
        extra[i].key = names[i];
        extra[i].value = v[i].value;
    }
    return CLI_TABLES_STATIC_KEYS;
}

int cli_tables_time_marked(const adh_run *r)
{
    return r->status == ADH_SUCCESS && r->unconverged && r->why[0];
}

const char *cli_tables_marked_reason(const adh_config *cfg, const adh_run *r, char *buf, size_t len)
{
    buf[0] = '\0';
    return cli_tables_time_marked(r) ? reason_for(cfg, CLI_ADVICE_RUN, r->why, r->fix, buf, len) : buf;
}

size_t cli_tables_capped_steps(const adh_run *r)
{
    return cli_tables_time_marked(r) ? 0 : r->unconverged;
}
