#include "cli/batch.h"
#include "plot/say.h"

#include "adhere/cycle.h"
#include "adhere/clock.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/protocol.h"
#include "adhere/rings.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "cli/advice.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "util/ready.h"
#include "cli/progress.h"
#include "cli/static.h"
#include "cli/sweep.h"
#include "cli/tables.h"
#include "cli/timerun.h"
#include "plot/rows.h"
#include "plot/outdir.h"
#include "adhere/units.h"
#include "plot/setup.h"
#include "plot/plot.h"
#include "scene/plan.h"


typedef struct batch_ctx {
    const adh_run_spec *spec;
    FILE *stream;           /* force rows as they come (no --out), or NULL */
    int progress;           /* draw a progress line on stderr */
    size_t total;           /* the plan's steps back to the start (unloading ends
                               at the jump out, before or past it); 0 when
                               unknown (static mode) */
    double t0, last_draw;
} batch_ctx;

static int on_step(const adh_obs *o, const adh_run *run, void *vctx)
{
    batch_ctx *ctx = vctx;
    if (ctx->stream) {
        (ctx->spec->mode == ADH_MODE_TIME ? adh_rows_write_timed : adh_rows_write)(ctx->stream, o);
        fflush(ctx->stream);
    }
    if (ctx->progress) {
        double t = adh_clock_seconds();
        if (t - ctx->last_draw > 0.1) {
            char pr[64];
            ctx->last_draw = t;
            cli_progress_text(run->nrows, ctx->total, t - ctx->t0, pr, sizeof pr);
            if (ctx->total && o->branch < 0 && o->h0 > run->start + 1e-6 * ctx->spec->proto.step)
                /* unloading on past the start, still in contact: the plan's total does not count it */
                fprintf(stderr, "\r  unloading step %zu, past the start%s  h0 %+8.3f nm  F %+10.4g uN ", run->nrows,
                        o->a > 0 ? ", still in contact" : "", o->h0 * 1e9, o->F * 1e6);
            else if (ctx->total)
                fprintf(stderr, "\r  %s step %zu of <=%zu  %-26s h0 %+8.3f nm  F %+10.4g uN ",
                        o->branch > 0 ? "loading  " : "unloading", run->nrows, ctx->total, pr, o->h0 * 1e9, o->F * 1e6);
            else if (isfinite(o->t))   /* physical time */
                fprintf(stderr, "\r  %s step %zu  t %-10.4g s  h0 %+8.3f nm  F %+10.4g uN ", o->branch > 0 ? "loading  "
                        : "unloading", run->nrows, o->t, o->h0 * 1e9, o->F * 1e6);
            else
                fprintf(stderr, "\r  point %zu  h0 %+8.3f nm  F %+10.4g uN ", run->nrows, o->h0 * 1e9, o->F * 1e6);
        }
    }
    /* the loading row at the deepest turn: the dwell comes next */
    const adh_run_spec *spec = ctx->spec;
    if (spec->proto.dwell && o->path == 0 && o->branch > 0 && spec->mode == ADH_MODE_RELAX) {
        double deepest = adh_protocol_deepest_turn(&spec->proto);
        if (fabs(o->h0 - deepest) < 1e-6 * spec->proto.step)
            adh_ready_phase("dwell");
    }
    return cli_interrupt_step(o, run, NULL);
}

/* The closing line: how long, what the cycle measured (with the static
 * reference's loop, static_hyst, when there is one: the share of the
 * hysteresis no slower drive removes), where it went. */
static void closing_line(const adh_run_spec *spec, const adh_run *run, const adh_static_result *sres,
                         const adh_visco_result *tres, double static_hyst, double seconds, const char *out,
                         const char *tables, const char *plots)
{
    char t[32], F[64] = "", in[64] = "", jo[64] = "", hy[160] = "", why[512];
    double pull = NAN, jin = run->jump_in_h0, jout = NAN, hyst = NAN;
    adh_derived d;
    adh_material_derive(&spec->mat, &d);
    if (spec->mode != ADH_MODE_RIGID && !adh_run_touched(run, d.h_star, why, sizeof why)) {
        /* no contact: the lowest force is only the force at the turn */
    } else if (spec->mode == ADH_MODE_STATIC) {
        pull = sres->pulloff_F;
        jin = sres->jump_in_h0;
        jout = sres->jump_out_h0;
        hyst = cli_tables_static_hysteresis(run, &spec->mat);
    } else {
        const adh_turn_result *tr = adh_run_main_turn(run);
        if (tr) {
            pull = tr->pulloff_F;
            jout = tr->jump_out_h0;
            /* physical time's: the base's work over the cycle, as summary.tsv says it */
            hyst = tres ? tres->hysteresis : adh_cycle_hysteresis(run->rows, run->nrows, tr->path);
        }
    }
    if (!isnan(hyst) && !isnan(static_hyst))
        snprintf(hy, sizeof hy, ", hysteresis %s (static %s)", adh_qtext(hyst, ADH_Q_WORK).s,
                 adh_qtext(static_hyst, ADH_Q_WORK).s);
    else if (!isnan(hyst))
        snprintf(hy, sizeof hy, ", hysteresis %s", adh_qtext(hyst, ADH_Q_WORK).s);
    cli_progress_duration(seconds, t, sizeof t);
    adh_format_quantity(pull, ADH_Q_FORCE, 4, F, sizeof F);
    adh_format_quantity(jin, ADH_Q_LENGTH, 4, in, sizeof in);
    adh_format_quantity(jout, ADH_Q_LENGTH, 4, jo, sizeof jo);
    char where[PATH_MAX + 2400];   /* the directory's name escaped with the rest: one line, one writer */
    if (out && strncmp(plots, "wrote ", 6) == 0)
        snprintf(where, sizeof where, "wrote %s, %s", tables, plots + 6);
    else if (out)
        snprintf(where, sizeof where, "wrote %s in %s%s%s", tables, out, plots[0] ? "; " : "", plots);
    else
        snprintf(where, sizeof where, "the force table went to standard output");
    adh_sayf("done in %s: pull-off %s, jump-in %s, jump-out %s%s; %s", t, isnan(pull) ? "none" : F,
             isnan(jin) ? "none" : in, isnan(jout) ? "none" : jo, hy, where);
}

/* One run's state across its phases: build, step, judge, write. */
typedef struct batch_job {
    const cli_options *cli;
    const adh_config *cfg;
    adh_run_spec spec;        /* the configuration's one run */
    adh_outdir *od;           /* NULL: the force table on standard output */
    const char *out;
    double t_start;
    int rigid, timed;
    adh_grid *g;
    adh_kernel *k;
    batch_ctx ctx;
    adh_run run, ref;         /* the run and its static reference */
    adh_static_result sres, rres;
    cli_time_out tout;
    int rc, want_ref, ref_resolved;
    int status;               /* the exit status so far */
    char note[1024];          /* why the tables are partial; "" when they are not */
} batch_job;

/* The grid and kernel (rigid spheres need eq 22 alone: neither): 0, or
 * the exit status with its message said. */
static int batch_build(batch_job *j)
{
    const adh_run_spec *spec = &j->spec;
    j->g = j->rigid ? NULL : adh_config_grid_alloc(spec);
    /* --force on a grid coarser than the resolved limit: said even with -q */
    if (!j->rigid) {
        char why[1024];
        adh_grid_report gr;
        adh_config_grid_report(spec, &gr);
        if (!gr.resolved) {
            adh_grid_unresolved_sentence(&gr, why, sizeof why);
            adh_sayf("warning: %s (--force; summary.tsv: resolved 0)", why);
        }
    }
    /* caught from here: a large ring kernel takes seconds to build */
    cli_interrupt_catch();
    int kst = ADH_ENOMEM;
    if (j->g)
        adh_ready_phase("kernel");
    j->k = j->g ? adh_config_kernel_alloc(spec, j->g, &kst) : NULL;
    if (j->rigid || j->k)
        return 0;
    if (kst == ADH_EINTR)
        adh_sayf("interrupted by signal %d while building the %zu-node kernel: nothing computed, no table written",
                 cli_interrupt_signal(), spec->grid.use.nodes);
    else
        adh_sayf("out of memory building the %zu-node kernel", j->g ? j->g->n : spec->grid.use.nodes);
    cli_interrupt_release();
    adh_grid_free(j->g);
    return kst == ADH_EINTR ? cli_interrupt_exit() : CLI_EXIT_SOLVER;
}

/* The run by its mode's rule, rows streamed when there is no -o, then
 * --reference=static's equilibrium curve beside a relaxation run. */
static void batch_step(batch_job *j)
{
    const adh_run_spec *spec = &j->spec;
    adh_plan plan;
    adh_plan_make(j->cfg, &plan);
    j->ctx = (batch_ctx){ spec, j->out ? NULL : stdout, !j->cfg->output.quiet && isatty(2),
                          plan.static_mode || plan.time_mode ? 0 : plan.loading_steps + plan.unloading_steps,
                          j->t_start, 0 };
    if (j->ctx.stream) {
        fprintf(j->ctx.stream, "# adhere %s force table, SI units\n", ADH_VERSION);
        (j->timed ? adh_rows_header_timed : adh_rows_header)(j->ctx.stream);
    }
    adh_ready_phase(j->rigid ? "rigid" : spec->mode == ADH_MODE_STATIC ? "static" : j->timed ? "time" : "relax");
    adh_run *run = &j->run;
    j->rc = j->rigid ? adh_runner_rule(&adh_rule_rigid, NULL, NULL, &spec->mat, NULL, &spec->proto, on_step, &j->ctx, run)
          : spec->mode == ADH_MODE_STATIC ? cli_static_run(spec, j->g, j->k, on_step, &j->ctx, run, &j->sres)
          : j->timed ? cli_time_run(spec, j->g, j->k, on_step, &j->ctx, run, &j->tout)
          : adh_runner_rule(&adh_rule_relax, j->g, j->k, &spec->mat, &spec->relax, &spec->proto, on_step, &j->ctx, run);
    j->want_ref = j->cli->reference[0] && spec->mode == ADH_MODE_RELAX && j->rc == ADH_SUCCESS && !run->interrupted;
    if (j->want_ref) {
        adh_ready_phase("reference");
        char rwhy[1024];
        int rrc = cli_static_reference(spec, j->g, j->k, &j->ref, &j->rres, &j->ref_resolved, rwhy, sizeof rwhy);
        if (!j->ref_resolved)
            adh_sayf("warning: the static reference curve is not resolved: %s (summary.tsv: "
                     "static_resolved 0)", rwhy);
        if (rrc != ADH_SUCCESS && !j->ref.interrupted) {
            char stopped[CLI_TABLES_STOPPED_LEN];
            adh_sayf("the static reference curve failed: %s",
                     cli_tables_stopped(j->cfg, &j->ref, j->ref.status, stopped, sizeof stopped));
            j->want_ref = 0;
        }
    }
    if (j->ctx.progress)
        fprintf(stderr, "\r%*s\r", 100, "");
}

/* What the run's end says: interrupted, stopped at the grid's edge, a
 * solver failure, no contact or no separation, steps at the cap. */
static void batch_judge(batch_job *j)
{
    const adh_run_spec *spec = &j->spec;
    const adh_run *run = &j->run;
    if (run->interrupted || j->ref.interrupted) {
        if (j->ref.interrupted)
            snprintf(j->note, sizeof j->note, "interrupted by signal %d during the static reference curve (%zu of its points)",
                     cli_interrupt_signal(), j->ref.nrows);
        else
            snprintf(j->note, sizeof j->note, "interrupted by signal %d after %zu steps", cli_interrupt_signal(), run->nrows);
        j->status = cli_interrupt_exit();
    } else if (j->rc == ADH_EGRID && run->nrows) {
        char edge[900];
        double a = run->rows[run->nrows - 1].a;
        adh_rings_edge_sentence(j->g, a, edge, sizeof edge);
        cli_advice_append_cfg(j->cfg, CLI_ADVICE_RUN, edge, sizeof edge, adh_rings_edge_fix(j->g, a));
        snprintf(j->note, sizeof j->note, "the run stopped after %zu steps at h0 = %s: %s", run->nrows,
                 adh_qtext(run->rows[run->nrows - 1].h0, ADH_Q_LENGTH).s, edge);
        j->status = CLI_EXIT_SOLVER;
    } else if (j->rc != ADH_SUCCESS) {
        char stopped[CLI_TABLES_STOPPED_LEN];
        snprintf(j->note, sizeof j->note, "the solver stopped after %zu steps: %s", run->nrows,
                 cli_tables_stopped(j->cfg, run, j->rc, stopped, sizeof stopped));
        j->status = CLI_EXIT_SOLVER;
    }
    if (j->note[0])
        adh_say(j->note);
    char sep[512];
    adh_derived der;
    adh_material_derive(&spec->mat, &der);
    int touched = j->rigid || adh_run_touched(run, der.h_star, sep, sizeof sep);
    if (j->status == CLI_EXIT_OK && (!touched || !adh_run_separated(run, sep, sizeof sep)))
        adh_sayf("incomplete: %s (summary.tsv: complete 0)", sep);
    /* Steps at the cap change what the numbers mean: said even under -q, and
     * the run's status, unless --allow-unconverged asked for them. */
    const adh_output_options *o = &j->cfg->output;
    int unconverged = run->unconverged && j->status == CLI_EXIT_OK;
    char marked[CLI_TABLES_REASON_LEN];   /* a run in time: its balance open, or its tolerance loose */
    if (*cli_tables_marked_reason(j->cfg, run, marked, sizeof marked) && (!o->allow_unconverged || !o->quiet))
        adh_sayf("warning: %s%s", marked,
                 o->allow_unconverged ? "" : " (status unconverged, exit 1; --allow-unconverged accepts it)");
    else if (run->unconverged && (!o->allow_unconverged || !o->quiet))
        adh_sayf("warning: %zu of %zu steps reached the iteration cap (%zu) without meeting eps = %s; their rows say converged 0%s",
                 run->unconverged, run->nrows, spec->relax.max_iter, adh_qtext(spec->relax.eps, ADH_Q_LENGTH).s,
                 o->allow_unconverged ? "" : " (status unconverged, exit 1; --allow-unconverged accepts them)");
    if (unconverged && !o->allow_unconverged)
        j->status = CLI_EXIT_SOLVER;
}

/* The mode's own summary keys: the static curve's, the spring's snap
 * points, physical time's, the static reference's. How many. */
static size_t batch_extra(const batch_job *j, double ref_hyst, char (*keynames)[32], cli_tables_extra *extra,
                          double *snap)
{
    const adh_run_spec *spec = &j->spec;
    size_t n = 0;
    if (spec->mode == ADH_MODE_STATIC)
        n += cli_tables_static_keys(&j->sres, cli_tables_static_hysteresis(&j->run, &spec->mat), "", keynames, extra);
    if (spec->mode == ADH_MODE_STATIC && isfinite(spec->time.spring))   /* the instrument's snap points */
        n += cli_time_snap_keys(&j->run, spec->time.spring, snap, extra + n);
    if (j->timed)
        n += cli_time_keys(&j->tout, extra + n);
    if (j->want_ref) {
        n += cli_tables_static_keys(&j->rres, ref_hyst, "static_", keynames + n, extra + n);
        extra[n++] = (cli_tables_extra){ "static_resolved", j->ref_resolved };
    }
    return n;
}

/* The plots and the scene's figures of a whole run into od, and the
 * closing line; what was not written is added to unwritten. */
static void batch_plots(batch_job *j, double ref_hyst, char *unwritten, size_t ulen)
{
    /* With --no-plot this writes the plots' tables only. A signal here is
     * still caught: gnuplot finishes its file, the temporaries go, and the
     * exit says interrupted. */
    const adh_run_spec *spec = &j->spec;
    char msg[1024] = "", missing[256] = "", fig[1024] = "", plots[2100] = "";
    adh_ready_phase("plot");
    adh_plot_setup ps;
    adh_plot_setup_fill(j->cfg, spec, j->g, &ps);
    int prc = adh_plots_write(&ps, &j->run, j->want_ref ? &j->ref : NULL, j->od, msg, sizeof msg, missing,
                              sizeof missing);
    if (prc != 0) {
        adh_sayf("plots not written: %s", msg);
        j->status = prc == 2 ? CLI_EXIT_USAGE : j->status == CLI_EXIT_OK ? CLI_EXIT_PLOT : j->status;
    }
    cli_tables_names_add(unwritten, ulen, missing);
    /* the scene figures (Figure 1 inset, Figure 2) when asked */
    if (!cli_interrupt_signal() && cli_figures_run(j->cfg, spec, &j->run, j->od, fig, sizeof fig, unwritten, ulen) != 0) {
        adh_sayf("plots not written: %s", fig);
        if (j->status == CLI_EXIT_OK)
            j->status = CLI_EXIT_PLOT;
    }
    if (j->status != CLI_EXIT_OK || j->cfg->output.quiet)
        return;
    char tables_[128];
    snprintf(tables_, sizeof tables_, "force.tsv, summary.tsv%s%s%s", j->run.nturns ? ", turns.tsv" : "",
             j->want_ref ? ", static.tsv" : "", j->timed ? ", events.tsv" : "");
    /* "wrote A, B in DIR; notes" from the plots, the scene figures' names after A, B */
    const char *in = strstr(msg, " in ");
    if (strncmp(msg, "wrote ", 6) == 0 && in && !strstr(msg, "no plot tables"))
        snprintf(plots, sizeof plots, "wrote %.*s%s%s%s", (int)(in - msg - 6), msg + 6, fig[0] ? ", " : "", fig, in);
    else if (fig[0])
        snprintf(plots, sizeof plots, "wrote %s in %.1000s", fig, j->out);
    closing_line(spec, &j->run, &j->sres, j->timed ? &j->tout.res : NULL, ref_hyst, adh_clock_seconds() - j->t_start,
                 j->out, tables_, plots);
}

/* The tables into od: every file is tried even when one fails (a full
 * disk), and summary.tsv comes last, naming what was not written: a
 * summary that says success speaks for the whole directory. */
static void batch_write(batch_job *j, cli_tables *tables, const cli_tables *ref_tables, double ref_hyst)
{
    char why[1024], unwritten[512] = "";
    struct { const char *name; int want; adh_outdir_writer w; const void *t; } tab[] = {
        { "force.tsv", 1, cli_tables_force, tables },
        { "turns.tsv", j->run.nturns > 0, cli_tables_turns, tables },
        { "static.tsv", j->want_ref, cli_tables_force, ref_tables },
        { "events.tsv", j->timed, cli_time_events, &j->tout },
    };
    j->tout.scene = j->cfg->scene;
    j->tout.partial = tables->partial ? (tables->note ? tables->note : "the run did not finish") : NULL;
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        if (!tab[i].want)
            continue;
        if (adh_outdir_write(j->od, tab[i].name, tab[i].w, tab[i].t, why, sizeof why) != 0) {
            adh_say(why);
            j->status = CLI_EXIT_USAGE;
            cli_tables_names_add(unwritten, sizeof unwritten, tab[i].name);
        }
    }
    if (!tables->partial)
        batch_plots(j, ref_hyst, unwritten, sizeof unwritten);
    tables->unwritten = unwritten;
    if (cli_interrupt_signal() && !tables->partial)
        tables->status = "interrupted";   /* while plotting: the figures not written are named */
    if (adh_outdir_write(j->od, "summary.tsv", cli_tables_summary, tables, why, sizeof why) != 0) {
        adh_say(why);
        j->status = CLI_EXIT_USAGE;
    }
    tables->unwritten = NULL;   /* unwritten ends here */
}

/* One run (no sweep) into od (NULL: the force table on standard output). */
static int run_batch(const cli_options *cli, adh_outdir *od, double t_start)
{
    static batch_job job;   /* large: not on the stack */
    batch_job *j = &job;
    memset(j, 0, sizeof *j);
    j->cli = cli;
    j->cfg = &cli->cfg;
    /* the one run: the configuration's, with the protocol every driver steps */
    adh_config_sweep_run(j->cfg, 0, &j->spec);
    j->od = od;
    j->out = od ? adh_outdir_path(od) : NULL;
    j->t_start = t_start;
    j->rigid = j->spec.mode == ADH_MODE_RIGID;
    j->timed = j->spec.mode == ADH_MODE_TIME;
    int st = batch_build(j);
    if (st)
        return st;
    adh_run_init(&j->run);
    adh_run_init(&j->ref);
    batch_step(j);
    j->status = CLI_EXIT_OK;
    batch_judge(j);
    double ref_hyst = j->want_ref ? cli_tables_static_hysteresis(&j->ref, &j->spec.mat) : NAN;
    char keynames[2 * CLI_TABLES_STATIC_KEYS][32];
    cli_tables_extra extra[2 * CLI_TABLES_STATIC_KEYS + 1 + CLI_TIME_KEYS];
    double snap[CLI_TIME_SNAP_KEYS];
    size_t nextra = batch_extra(j, ref_hyst, keynames, extra, snap);
    /* A force table streamed to a full disk or a closed pipe is lost: say so. */
    if (j->ctx.stream && (fflush(j->ctx.stream) != 0 || ferror(j->ctx.stream))) {
        adh_sayf("cannot write the force table to standard output: %s", strerror(errno));
        j->status = CLI_EXIT_USAGE;
    }
    int partial = j->note[0] != '\0';
    cli_tables tables = { j->cfg, &j->spec, &j->run, extra, nextra, partial, j->note, NULL,
                          j->ref.interrupted ? "interrupted" : NULL };
    cli_tables ref_tables = { j->cfg, &j->spec, &j->ref, NULL, 0, j->ref.interrupted, j->note, NULL, NULL };
    if (j->ctx.stream && partial)
        fprintf(j->ctx.stream, "# PARTIAL: %s\n", j->note);
    if (j->out)
        batch_write(j, &tables, &ref_tables, ref_hyst);
    else if (j->status == CLI_EXIT_OK && !j->cfg->output.quiet)
        closing_line(&j->spec, &j->run, &j->sres, j->timed ? &j->tout.res : NULL, ref_hyst,
                     adh_clock_seconds() - t_start, NULL, "", "");
    cli_interrupt_release();
    if (cli_interrupt_signal() && !partial) {
        adh_sayf("interrupted by signal %d while plotting; the tables are complete", cli_interrupt_signal());
        j->status = cli_interrupt_exit();
    }
    cli_time_out_free(&j->tout);
    adh_run_free(&j->run);
    adh_run_free(&j->ref);
    adh_kernel_free(j->k);
    adh_grid_free(j->g);
    return j->status;
}

int cli_batch_main(cli_options *cli)
{
    const adh_config *cfg = &cli->cfg;
    double t_start = adh_clock_seconds();
    char why[1024];
    adh_outdir *od = NULL;
    /* a directory never mixes two runs: the earlier run's files go first
     * (a study keeps them until it knows they are not its own: it resumes
     * itself), and another's files under adhere's names refuse it */
    unsigned flags = (cfg->output.overwrite ? ADH_OUTDIR_OVERWRITE : 0) | (cfg->sweep.naxes ? ADH_OUTDIR_KEEP : 0);
    if (cfg->output.dir[0] && !(od = adh_outdir_open(cfg->output.dir, flags, why, sizeof why))) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    int rc = cfg->sweep.naxes ? cli_sweep_main(cli, od) : run_batch(cli, od, t_start);
    adh_outdir_close(od);
    return rc;
}
