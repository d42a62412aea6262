#include "cli/batch.h"

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
                         double static_hyst, double seconds, const char *out, const char *tables, const char *plots)
{
    char t[32], F[64] = "", in[64] = "", jo[64] = "", hy[96] = "", why[512];
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
            hyst = adh_cycle_hysteresis(run->rows, run->nrows, tr->path);
        }
    }
    if (!isnan(hyst) && !isnan(static_hyst))
        snprintf(hy, sizeof hy, ", hysteresis %.4g fJ (static %.4g fJ)", hyst * 1e15, static_hyst * 1e15);
    else if (!isnan(hyst))
        snprintf(hy, sizeof hy, ", hysteresis %.4g fJ", hyst * 1e15);
    cli_progress_duration(seconds, t, sizeof t);
    adh_format_quantity(pull, ADH_Q_FORCE, 4, F, sizeof F);
    adh_format_quantity(jin, ADH_Q_LENGTH, 4, in, sizeof in);
    adh_format_quantity(jout, ADH_Q_LENGTH, 4, jo, sizeof jo);
    fprintf(stderr, "adhere: done in %s: pull-off %s, jump-in %s, jump-out %s%s; ", t, isnan(pull) ? "none" : F,
            isnan(jin) ? "none" : in, isnan(jout) ? "none" : jo, hy);
    if (out && strncmp(plots, "wrote ", 6) == 0)
        fprintf(stderr, "wrote %s, %s\n", tables, plots + 6);
    else if (out)
        fprintf(stderr, "wrote %s in %s%s%s\n", tables, out, plots[0] ? "; " : "", plots);
    else
        fprintf(stderr, "the force table went to standard output\n");
}

/* One run (no sweep) into od (NULL: the force table on standard output). */
static int run_batch(const cli_options *cli, adh_outdir *od, double t_start)
{
    const adh_config *cfg = &cli->cfg;
    /* the one run: the configuration's, with the protocol every driver steps */
    adh_run_spec spec_;
    adh_config_sweep_run(cfg, 0, &spec_);
    const adh_run_spec *spec = &spec_;
    char why[1024];
    const char *out = od ? adh_outdir_path(od) : NULL;
    /* Rigid spheres need eq 22 alone: no grid, no kernel. */
    int rigid = spec->mode == ADH_MODE_RIGID;
    adh_grid *g = rigid ? NULL : adh_config_grid_alloc(spec);
    /* --force on a grid coarser than the resolved limit: said even with -q */
    if (!rigid) {
        adh_grid_report gr;
        adh_grid_check(&spec->mat, adh_config_grid_use(spec), spec->grid.use.nodes, adh_config_spacing(spec), &gr);
        if (!gr.resolved) {
            adh_grid_unresolved_sentence(&gr, why, sizeof why);
            fprintf(stderr, "adhere: warning: %s (--force; summary.tsv: resolved 0)\n", why);
        }
    }
    /* caught from here: a large ring kernel takes seconds to build */
    cli_interrupt_catch();
    int kst = ADH_ENOMEM;
    if (g)
        adh_ready_phase("kernel");
    adh_kernel *k = g ? adh_config_kernel_alloc(spec, g, &kst) : NULL;
    if (!rigid && !k) {
        if (kst == ADH_EINTR)
            fprintf(stderr, "adhere: interrupted by signal %d while building the %zu-node kernel: nothing computed, no table written\n",
                    cli_interrupt_signal(), spec->grid.use.nodes);
        else
            fprintf(stderr, "adhere: out of memory building the %zu-node kernel\n", g ? g->n : spec->grid.use.nodes);
        cli_interrupt_release();
        adh_grid_free(g);
        return kst == ADH_EINTR ? cli_interrupt_exit() : CLI_EXIT_SOLVER;
    }

    adh_plan plan;
    adh_plan_make(cfg, &plan);
    batch_ctx ctx = { spec, out ? NULL : stdout, !cfg->output.quiet && isatty(2),
                      plan.static_mode || plan.time_mode ? 0 : plan.loading_steps + plan.unloading_steps, t_start, 0 };
    int timed = spec->mode == ADH_MODE_TIME;
    if (ctx.stream) {
        fprintf(ctx.stream, "# adhere %s force table, SI units\n", ADH_VERSION);
        (timed ? adh_rows_header_timed : adh_rows_header)(ctx.stream);
    }
    adh_run run;
    adh_run_init(&run);
    adh_static_result sres;
    cli_time_out tout = { 0 };
    adh_ready_phase(rigid ? "rigid" : spec->mode == ADH_MODE_STATIC ? "static" : timed ? "time" : "relax");
    int rc = rigid ? adh_runner_rule(&adh_rule_rigid, NULL, NULL, &spec->mat, NULL, &spec->proto, on_step, &ctx, &run)
           : spec->mode == ADH_MODE_STATIC ? cli_static_run(spec, g, k, on_step, &ctx, &run, &sres)
           : timed ? cli_time_run(spec, g, k, on_step, &ctx, &run, &tout)
           : adh_runner_rule(&adh_rule_relax, g, k, &spec->mat, &spec->relax, &spec->proto, on_step, &ctx, &run);
    /* --reference=static: the equilibrium curve beside the relaxation run. */
    adh_run ref;
    adh_run_init(&ref);
    adh_static_result rres;
    int ref_resolved = 0;
    int want_ref = cli->reference[0] && spec->mode == ADH_MODE_RELAX && rc == ADH_SUCCESS && !run.interrupted;
    if (want_ref) {
        adh_ready_phase("reference");
        char rwhy[1024];
        int rrc = cli_static_reference(spec, g, k, &ref, &rres, &ref_resolved, rwhy, sizeof rwhy);
        if (!ref_resolved)
            fprintf(stderr, "adhere: warning: the static reference curve is not resolved: %s (summary.tsv: "
                    "static_resolved 0)\n", rwhy);
        if (rrc != ADH_SUCCESS && !ref.interrupted) {
            fprintf(stderr, "adhere: the static reference curve failed: %s\n", adh_strerror(ref.status));
            want_ref = 0;
        }
    }
    if (ctx.progress)
        fprintf(stderr, "\r%*s\r", 100, "");

    int status = CLI_EXIT_OK;
    char note[512] = "";
    if (run.interrupted || ref.interrupted) {
        if (ref.interrupted)
            snprintf(note, sizeof note, "interrupted by signal %d during the static reference curve (%zu of its points)",
                     cli_interrupt_signal(), ref.nrows);
        else
            snprintf(note, sizeof note, "interrupted by signal %d after %zu steps", cli_interrupt_signal(), run.nrows);
        status = cli_interrupt_exit();
    } else if (rc == ADH_EGRID && run.nrows) {
        char edge[400];
        adh_rings_edge_sentence(g, run.rows[run.nrows - 1].a, edge, sizeof edge);
        cli_advice_append(edge, sizeof edge, adh_rings_edge_fix(g, run.rows[run.nrows - 1].a));
        snprintf(note, sizeof note, "the run stopped after %zu steps at h0 = %s: %s", run.nrows,
                 adh_qtext(run.rows[run.nrows - 1].h0, ADH_Q_LENGTH).s, edge);
        status = CLI_EXIT_SOLVER;
    } else if (rc != ADH_SUCCESS) {
        snprintf(note, sizeof note, "the solver stopped after %zu steps: %s", run.nrows, adh_strerror(rc));
        status = CLI_EXIT_SOLVER;
    }
    if (note[0])
        fprintf(stderr, "adhere: %s\n", note);
    char sep[512];
    adh_derived der;
    adh_material_derive(&spec->mat, &der);
    int touched = rigid || adh_run_touched(&run, der.h_star, sep, sizeof sep);
    if (status == CLI_EXIT_OK && (!touched || !adh_run_separated(&run, sep, sizeof sep)))
        fprintf(stderr, "adhere: incomplete: %s (summary.tsv: complete 0)\n", sep);
    /* Steps at the cap change what the numbers mean: said even under -q, and
     * the run's status, unless --allow-unconverged asked for them. */
    int unconverged = run.unconverged && status == CLI_EXIT_OK;
    if (run.unconverged && (!cfg->output.allow_unconverged || !cfg->output.quiet))
        fprintf(stderr, "adhere: warning: %zu of %zu steps reached the iteration cap (%zu) without meeting eps = %s; their rows say converged 0%s\n",
                run.unconverged, run.nrows, spec->relax.max_iter, adh_qtext(spec->relax.eps, ADH_Q_LENGTH).s,
                cfg->output.allow_unconverged ? "" : " (status unconverged, exit 1; --allow-unconverged accepts them)");
    if (unconverged && !cfg->output.allow_unconverged)
        status = CLI_EXIT_SOLVER;

    double ref_hyst = want_ref ? cli_tables_static_hysteresis(&ref, &spec->mat) : NAN;
    char keynames[2 * CLI_TABLES_STATIC_KEYS][32];
    cli_tables_extra extra[2 * CLI_TABLES_STATIC_KEYS + 1 + CLI_TIME_KEYS];
    double snap[CLI_TIME_SNAP_KEYS];
    size_t nextra = 0;
    if (spec->mode == ADH_MODE_STATIC)
        nextra += cli_tables_static_keys(&sres, cli_tables_static_hysteresis(&run, &spec->mat), "", keynames, extra);
    if (spec->mode == ADH_MODE_STATIC && isfinite(spec->time.spring))   /* the instrument's snap points */
        nextra += cli_time_snap_keys(&run, spec->time.spring, snap, extra + nextra);
    if (timed)
        nextra += cli_time_keys(&tout, extra + nextra);
    if (want_ref)
        nextra += cli_tables_static_keys(&rres, ref_hyst, "static_", keynames + nextra, extra + nextra);
    if (want_ref)
        extra[nextra++] = (cli_tables_extra){ "static_resolved", ref_resolved };
    /* A force table streamed to a full disk or a closed pipe is lost: say so. */
    if (ctx.stream && (fflush(ctx.stream) != 0 || ferror(ctx.stream))) {
        fprintf(stderr, "adhere: cannot write the force table to standard output: %s\n", strerror(errno));
        status = CLI_EXIT_USAGE;
    }
    int partial = note[0] != '\0';
    cli_tables tables = { cfg, spec, &run, extra, nextra, partial, note, NULL, ref.interrupted ? "interrupted" : NULL };
    cli_tables ref_tables = { cfg, spec, &ref, NULL, 0, ref.interrupted, note, NULL, NULL };
    if (ctx.stream && tables.partial)
        fprintf(ctx.stream, "# PARTIAL: %s\n", note);
    if (out) {
        /* Every file is tried even when one fails (a full disk), and
         * summary.tsv comes last, naming what was not written: a summary
         * that says success speaks for the whole directory. */
        char unwritten[512] = "";
        struct { const char *name; int want; adh_outdir_writer w; const void *t; } tab[] = {
            { "force.tsv", 1, cli_tables_force, &tables },
            { "turns.tsv", run.nturns > 0, cli_tables_turns, &tables },
            { "static.tsv", want_ref, cli_tables_force, &ref_tables },
            { "events.tsv", timed, cli_time_events, &tout },
        };
        for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
            if (!tab[i].want)
                continue;
            if (adh_outdir_write(od, tab[i].name, tab[i].w, tab[i].t, why, sizeof why) != 0) {
                fprintf(stderr, "adhere: %s\n", why);
                status = CLI_EXIT_USAGE;
                cli_tables_names_add(unwritten, sizeof unwritten, tab[i].name);
            }
        }
        if (!partial) {
            /* With --no-plot this writes the plots' tables only. A signal
             * here is still caught: gnuplot finishes its file, the
             * temporaries go, and the exit says interrupted. */
            char msg[1024] = "", missing[256] = "", fig[1024] = "", plots[2100] = "";
            adh_ready_phase("plot");
            adh_plot_setup ps;
            adh_plot_setup_fill(cfg, spec, g, &ps);
            int prc = adh_plots_write(&ps, &run, want_ref ? &ref : NULL, od, msg, sizeof msg, missing,
                                      sizeof missing);
            if (prc != 0) {
                fprintf(stderr, "adhere: plots not written: %s\n", msg);
                status = prc == 2 ? CLI_EXIT_USAGE : status == CLI_EXIT_OK ? CLI_EXIT_PLOT : status;
            }
            cli_tables_names_add(unwritten, sizeof unwritten, missing);
            /* the scene figures (Figure 1 inset, Figure 2) when asked */
            if (!cli_interrupt_signal() &&
                cli_figures_run(cfg, spec, &run, od, fig, sizeof fig, unwritten, sizeof unwritten) != 0) {
                fprintf(stderr, "adhere: plots not written: %s\n", fig);
                if (status == CLI_EXIT_OK)
                    status = CLI_EXIT_PLOT;
            }
            if (status == CLI_EXIT_OK && !cfg->output.quiet) {
                char tables_[128];
                snprintf(tables_, sizeof tables_, "force.tsv, summary.tsv%s%s%s", run.nturns ? ", turns.tsv" : "",
                         want_ref ? ", static.tsv" : "", timed ? ", events.tsv" : "");
                /* "wrote A, B in DIR; notes" from the plots, the scene figures' names after A, B */
                const char *in = strstr(msg, " in ");
                if (strncmp(msg, "wrote ", 6) == 0 && in && !strstr(msg, "no plot tables"))
                    snprintf(plots, sizeof plots, "wrote %.*s%s%s%s", (int)(in - msg - 6), msg + 6, fig[0] ? ", " : "",
                             fig, in);
                else if (fig[0])
                    snprintf(plots, sizeof plots, "wrote %s in %.1000s", fig, out);
                closing_line(spec, &run, &sres, ref_hyst, adh_clock_seconds() - t_start, out, tables_, plots);
            }
        }
        tables.unwritten = unwritten;
        if (cli_interrupt_signal() && !partial)
            tables.status = "interrupted";   /* while plotting: the figures not written are named */
        if (adh_outdir_write(od, "summary.tsv", cli_tables_summary, &tables, why, sizeof why) != 0) {
            fprintf(stderr, "adhere: %s\n", why);
            status = CLI_EXIT_USAGE;
        }
    } else if (status == CLI_EXIT_OK && !cfg->output.quiet) {
        closing_line(spec, &run, &sres, ref_hyst, adh_clock_seconds() - t_start, NULL, "", "");
    }
    cli_interrupt_release();
    if (cli_interrupt_signal() && !partial) {
        fprintf(stderr, "adhere: interrupted by signal %d while plotting; the tables are complete\n", cli_interrupt_signal());
        status = cli_interrupt_exit();
    }
    cli_time_out_free(&tout);
    adh_run_free(&run);
    adh_run_free(&ref);
    adh_kernel_free(k);
    adh_grid_free(g);
    return status;
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
        fprintf(stderr, "adhere: %s\n", why);
        return CLI_EXIT_USAGE;
    }
    int rc = cfg->sweep.naxes ? cli_sweep_main(cli, od) : run_batch(cli, od, t_start);
    adh_outdir_close(od);
    return rc;
}
