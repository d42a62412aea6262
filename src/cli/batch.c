#include "cli/batch.h"
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
#include "adhere/protocol.h"
#include "adhere/status.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "cli/rigid.h"
#include "cli/statics.h"
#include "cli/sweep.h"
#include "cli/tables.h"
#include "plot/plot.h"


typedef struct batch_ctx {
    const adh_config *cfg;
    FILE *stream;           /* force rows as they come (no --out), or NULL */
    int progress;           /* draw a progress bar on stderr */
    double last_draw;
} batch_ctx;

static int on_step(const adh_obs *o, const adh_run *run, void *vctx)
{
    batch_ctx *ctx = vctx;
    if (ctx->stream) {
        adh_force_row(ctx->stream, o);
        fflush(ctx->stream);
    }
    if (ctx->progress) {
        double t = adh_clock_seconds();
        if (t - ctx->last_draw > 0.1) {
            ctx->last_draw = t;
            fprintf(stderr, "\r  %s step %5zu  h0 %+8.3f nm  F %+10.4g uN  iters %7zu  total %9zu ",
                    o->branch > 0 ? "loading  " : "unloading", run->nrows, o->h0 * 1e9, o->F * 1e6,
                    o->iters, run->iterations);
        }
    }
    return adh_interrupt_step(o, run, NULL);
}

static int make_dir(const char *dir, char *why, size_t n)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", dir);
    /* mkdir -p: each parent in turn, tolerating ones that exist. */
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            snprintf(why, n, "cannot create directory %s: %s", buf, strerror(errno));
            return -1;
        }
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
        snprintf(why, n, "cannot create directory %s: %s", buf, strerror(errno));
        return -1;
    }
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode) || access(buf, W_OK) != 0) {
        snprintf(why, n, "cannot write into %s: not a writable directory", buf);
        return -1;
    }
    return 0;
}

int adh_batch_main(const adh_cli *cli)
{
    const adh_config *cfg = &cli->cfg;
    char why[1024];
    const char *out = cfg->out_dir[0] ? cfg->out_dir : NULL;
    if (out && make_dir(out, why, sizeof why) != 0) {
        fprintf(stderr, "adhere: %s\n", why);
        return ADH_EXIT_USAGE;
    }
    if (cfg->sweep.kind != ADH_SWEEP_NONE)
        return adh_sweep_main(cli);
    /* Rigid spheres need eq 22 alone: no grid, no kernel. */
    int rigid = cfg->mode == ADH_MODE_RIGID;
    adh_grid *g = rigid ? NULL : adh_config_grid_alloc(cfg);
    adh_kernel *k = g ? adh_config_kernel_alloc(cfg, g) : NULL;
    if (!rigid && !k) {
        fprintf(stderr, "adhere: out of memory building the %zu-node kernel\n", g ? g->n : cfg->nodes);
        adh_grid_free(g);
        return ADH_EXIT_SOLVER;
    }

    adh_interrupt_catch();

    batch_ctx ctx = { cfg, out ? NULL : stdout, !cfg->quiet && isatty(2), 0 };
    if (ctx.stream) {
        fprintf(ctx.stream, "# adhere %s force table, SI units\n", ADH_VERSION);
        adh_force_header(ctx.stream);
    }
    adh_run run;
    adh_run_init(&run);
    adh_static_result sres;
    int rc = rigid ? adh_rigid_run(cfg, on_step, &ctx, &run)
           : cfg->mode == ADH_MODE_STATIC ? adh_cli_static_run(cfg, g, k, on_step, &ctx, &run, &sres)
           : adh_protocol_run(g, k, &cfg->mat, &cfg->relax, &cfg->proto, on_step, &ctx, &run);
    /* --reference=static: the equilibrium curve beside the relaxation run. */
    adh_run ref;
    adh_run_init(&ref);
    adh_static_result rres;
    int want_ref = cli->reference[0] && cfg->mode == ADH_MODE_RELAX && rc == ADH_SUCCESS && !run.interrupted;
    if (want_ref && adh_cli_static_run(cfg, g, k, NULL, NULL, &ref, &rres) != ADH_SUCCESS) {
        fprintf(stderr, "adhere: the static reference curve failed: %s\n", adh_strerror(ref.status));
        want_ref = 0;
    }
    if (ctx.progress)
        fprintf(stderr, "\r%*s\r", 100, "");
    adh_interrupt_release();

    int status = ADH_EXIT_OK;
    char note[512] = "";
    if (run.interrupted) {
        snprintf(note, sizeof note, "interrupted by signal %d after %zu steps", adh_interrupt_signal(), run.nrows);
        status = ADH_EXIT_INTERRUPTED;
    } else if (rc != ADH_SUCCESS) {
        snprintf(note, sizeof note, "the solver stopped after %zu steps: %s", run.nrows, adh_strerror(rc));
        status = ADH_EXIT_SOLVER;
    }
    if (note[0])
        fprintf(stderr, "adhere: %s\n", note);
    if (run.unconverged && !cfg->quiet)
        fprintf(stderr, "adhere: warning: %zu of %zu steps reached the iteration cap (%zu) without meeting eps = %g m; their rows say converged 0\n",
                run.unconverged, run.nrows, cfg->relax.max_iter, cfg->relax.eps);

    char keynames[2 * ADH_STATIC_KEYS][32];
    adh_summary_extra extra[2 * ADH_STATIC_KEYS];
    size_t nextra = 0;
    if (cfg->mode == ADH_MODE_STATIC)
        nextra += adh_static_summary_keys(&sres, "", keynames, extra);
    if (want_ref)
        nextra += adh_static_summary_keys(&rres, "static_", keynames + nextra, extra + nextra);
    /* A force table streamed to a full disk or a closed pipe is lost: say so. */
    if (ctx.stream && (fflush(ctx.stream) != 0 || ferror(ctx.stream))) {
        fprintf(stderr, "adhere: cannot write the force table to standard output: %s\n", strerror(errno));
        status = ADH_EXIT_USAGE;
    }
    adh_tables tables = { cfg, &run, extra, nextra, status != ADH_EXIT_OK, note };
    adh_tables ref_tables = { cfg, &ref, NULL, 0, 0, NULL };
    if (ctx.stream && tables.partial)
        fprintf(ctx.stream, "# PARTIAL: %s\n", note);
    if (out) {
        if (adh_write_atomic(out, "force.tsv", adh_write_force, &tables, why, sizeof why) != 0 ||
            adh_write_atomic(out, "summary.tsv", adh_write_summary, &tables, why, sizeof why) != 0 ||
            (run.nturns && adh_write_atomic(out, "turns.tsv", adh_write_turns, &tables, why, sizeof why) != 0) ||
            (want_ref && adh_write_atomic(out, "static.tsv", adh_write_force, &ref_tables, why, sizeof why) != 0)) {
            fprintf(stderr, "adhere: %s\n", why);
            status = ADH_EXIT_USAGE;
        } else if (status == ADH_EXIT_OK) {
            /* With --no-plot this writes the plots' tables only. */
            char msg[1024] = "";
            int prc = adh_plots_write(cfg, &run, want_ref ? &ref : NULL, out, msg, sizeof msg);
            if (prc != 0) {
                fprintf(stderr, "adhere: plots not written: %s\n", msg);
                status = prc == 2 ? ADH_EXIT_USAGE : ADH_EXIT_PLOT;
            }
            /* the scene figures (Figure 1 inset, Figure 2) when asked */
            if (adh_figures_run(cfg, &run, out, msg, sizeof msg) != 0) {
                fprintf(stderr, "adhere: plots not written: %s\n", msg);
                if (status == ADH_EXIT_OK)
                    status = ADH_EXIT_PLOT;
            }
        }
    }
    adh_run_free(&run);
    adh_run_free(&ref);
    adh_kernel_free(k);
    adh_grid_free(g);
    return status;
}
