#include "cli/sweep.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/cycle.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "cli/exit.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "cli/jumps.h"
#include "util/ready.h"
#include "cli/progress.h"
#include "adhere/clock.h"
#include "cli/static.h"
#include "cli/tables.h"
#include "cli/timerun.h"
#include "plot/setup.h"
#include "plot/plot.h"
#include "scene/plan.h"

/* OpenBLAS's own threads would fight the sweep's for the same cores. */
void openblas_set_num_threads(int n) __attribute__((weak));   /* none in the reference BLAS */



typedef struct sweep_job {
    const adh_config *cfg;
    const adh_grid *grid;      /* shared, read-only */
    const adh_kernel *kernel;  /* shared, read-only: apply takes a scratch per call */
    adh_run *runs;
    adh_static_result *sres;   /* mode = static: each run's folds, jumps, pull-offs */
    cli_time_out *tout;        /* mode = time: each run's summary and events */
    int share;                 /* every run is run 0's curve (a spring swept over one static curve) */
    int *status;               /* adh status of each run */
    adh_outdir **out;          /* each run's DIR/run-K, or NULL: nothing but sweep.tsv on stdout */
    int *tables;               /* exit status of writing run i's tables; -1 not yet */
    cli_sweep_said *said;      /* what each run's summary.tsv said */
    size_t next;               /* the next run to start, under lock */
    size_t done;
    int jobs;                  /* runs at once */
    double t0;                 /* when the runs began */
    adh_plan_progress *eta;          /* each run's expected cost, start and time: the time left */
    pthread_mutex_t lock;
} sweep_job;

static int write_tables(const adh_config *cfg, size_t i, const adh_run *run, const adh_static_result *sres,
                        const cli_time_out *tout, int rc, adh_outdir *out, cli_sweep_said *said);

/* "67 %, about 5 min left", weighing each run by its expected iterations:
 * a run at a fifth of the eps takes five times as long, and the last runs
 * of Figure 7 are the longest (job->lock held). */
static void eta_text(const sweep_job *job, char *buf, size_t len)
{
    size_t n = job->cfg->sweep.n;
    double all = 0, done = 0;
    for (size_t i = 0; i < n; i++) {
        all += job->eta[i].cost;
        done += job->eta[i].state == 2 ? job->eta[i].cost : 0;
    }
    double left = adh_plan_time_left(job->eta, n, job->jobs, adh_clock_seconds(), 0);
    cli_progress_left(all > 0 ? done / all : 1, job->done < n ? left : NAN, buf, len);
}

static void *worker(void *arg)
{
    sweep_job *job = arg;
    const adh_config *cfg = job->cfg;
    for (;;) {
        pthread_mutex_lock(&job->lock);
        size_t i = job->next < cfg->sweep.n && !cli_interrupt_signal() ? job->next++ : cfg->sweep.n;
        pthread_mutex_unlock(&job->lock);
        if (i >= cfg->sweep.n)
            break;
        adh_run_spec rc;
        adh_config_sweep_run(cfg, i, &rc);
        adh_run *run = &job->runs[i];
        pthread_mutex_lock(&job->lock);
        job->eta[i].state = 1;
        job->eta[i].started = adh_clock_seconds();
        pthread_mutex_unlock(&job->lock);
        /* each static run allocates its own solver (a dense copy of the
         * shared kernel): nothing of it is shared between threads */
        job->status[i] = job->share && i > 0   /* the same curve: run 0's, done before (one job) */
                       ? cli_time_share(run, &job->runs[0], &job->sres[i], &job->sres[0], job->status[0])
                       : rc.mode == ADH_MODE_RIGID
                       ? adh_runner_rule(&adh_rule_rigid, NULL, NULL, &rc.mat, NULL, &rc.proto, cli_interrupt_step, NULL, run)
                       : rc.mode == ADH_MODE_TIME
                       ? cli_time_run(&rc, job->grid, job->kernel, cli_interrupt_step, NULL, run, &job->tout[i])
                       : rc.mode == ADH_MODE_STATIC
                       ? cli_static_run(&rc, job->grid, job->kernel, cli_interrupt_step, NULL, run, &job->sres[i])
                       : adh_runner_rule(&adh_rule_relax, job->grid, job->kernel, &rc.mat, &rc.relax, &rc.proto,
                                         cli_interrupt_step, NULL, run);
        /* tables as soon as a run ends: a long sweep killed later keeps them */
        if (job->out)
            job->tables[i] = write_tables(cfg, i, run, &job->sres[i], &job->tout[i], job->status[i], job->out[i], &job->said[i]);
        pthread_mutex_lock(&job->lock);
        job->done++;
        job->eta[i].state = 2;
        job->eta[i].seconds = adh_clock_seconds() - job->eta[i].started;
        if (!cfg->output.quiet) {
            char pr[64];
            eta_text(job, pr, sizeof pr);
            fprintf(stderr, "adhere: run %zu of %zu (%s = %s) %s: %zu steps, %zu iterations, %.3g s; %zu of %zu done, %s\n",
                    i + 1, cfg->sweep.n, adh_sweep_name(cfg->sweep.kind), adh_sweep_value_text(cfg->sweep.kind, cfg->sweep.values[i]).s,
                    run->interrupted ? "interrupted" : job->status[i] == ADH_SUCCESS ? "done" : adh_strerror(job->status[i]),
                    run->nrows, run->iterations, run->seconds, job->done, cfg->sweep.n, pr);
        }
        /* not hidden by -q: it changes what the run's numbers mean */
        if (run->unconverged)
            fprintf(stderr, "adhere: warning: run %zu (%s = %s): %zu of %zu steps reached the iteration cap (%zu) "
                    "without meeting eps; their rows say converged 0\n", i + 1, adh_sweep_name(cfg->sweep.kind),
                    adh_sweep_value_text(cfg->sweep.kind, cfg->sweep.values[i]).s, run->unconverged, run->nrows,
                    cfg->spec.relax.max_iter);
        pthread_mutex_unlock(&job->lock);
    }
    return NULL;
}

/* How many runs finished (neither interrupted nor never started). */
static size_t finished(const adh_config *cfg, const adh_run *runs)
{
    size_t k = 0;
    for (size_t i = 0; i < cfg->sweep.n; i++)
        k += !runs[i].interrupted;
    return k;
}

/* The run's summary.tsv's word (a run whose files were not all written,
 * or whose figures a signal stopped, is no success there); its own
 * verdict without one. */
static const char *run_word(const adh_config *cfg, size_t i, const adh_run *runs, const int *status,
                            const cli_sweep_said *said)
{
    adh_run_spec rc;
    adh_config_sweep_run(cfg, i, &rc);
    const adh_run *r = &runs[i];
    const char *word = status[i] != ADH_SUCCESS && !r->interrupted ? adh_strerror(status[i]) : cli_tables_verdict(&rc, r);
    if (said && said[i].word[0])
        word = said[i].word;
    else if (!strcmp(word, "success") && said && said[i].lost[0])
        word = "output incomplete";
    return word;
}

int cli_sweep_table(FILE *f, const adh_config *cfg, const adh_run *runs, const adh_static_result *sres,
                    const cli_time_out *tout, const int *status, double static_hysteresis, int static_resolved,
                    const cli_sweep_said *said)
{
    const char *name = adh_sweep_name(cfg->sweep.kind);
    int stat = cfg->spec.mode == ADH_MODE_STATIC && sres;
    fprintf(f, "# adhere " ADH_VERSION "\n# sweep: one row per run (run-K/ holds its tables), SI units (m, N, Pa, s%s)\n",
            cfg->spec.mode == ADH_MODE_TIME || cfg->sweep.kind == ADH_SWEEP_SPRING ? ", J, N/m" : "");
    if (cfg->scene[0])
        cli_tables_comment(f, "scene", cfg->scene);
    if (finished(cfg, runs) < cfg->sweep.n)
        fprintf(f, "# PARTIAL: interrupted by signal %d: %zu of %zu runs finished; the others say interrupted\n",
                cli_interrupt_signal(), finished(cfg, runs), cfg->sweep.n);
    else if (cli_interrupt_signal())
        fprintf(f, "# PARTIAL: interrupted by signal %d while the figures were drawn: every run finished, its "
                "tables whole; those whose figures were not drawn say interrupted\n", cli_interrupt_signal());
    if (cli_time_sweep_head(f, cfg)) {   /* physical time, or a spring's snap points */
        for (size_t i = 0; i < cfg->sweep.n; i++) {
            cli_time_sweep_row(f, cfg, i, runs, tout);
            fprintf(f, "\t%s\n", run_word(cfg, i, runs, status, said));
        }
        return 0;
    }
    if (stat)
        fprintf(f, "# mode static: each run is the equilibrium curve; jump_in_h0 its first fold, h_before the central gap at the last stable point before it;\n"
                   "# max_load the force at the curve's end (the turn); pulloff_F the load-controlled pull-off (minimum force), pulloff_F_disp the force at the jump-out fold;\n"
                   "# jumped: 1 the curve has a fold, 0 contact came without one, -1 no contact; steps the curve's points, iterations its Newton iterations;\n"
                   "# hysteresis: the equilibrium loop's area (displacement control: the highest and lowest stable force at each h0), J\n");
    else
        fprintf(f, "# h_before: central gap on the last loading row before the jump into contact; h_star: eq 24\n"
                   "# jumped: 1 the gap fell by more than 2 steps into contact, 0 contact came gradually (no jump identified), -1 no contact\n"
                   "# pulloff_F: the force minimum on unloading; jump_out_h0: where the surfaces separate; hysteresis: the area between loading and unloading, J\n");
    fprintf(f, "# swept: the parameter the sweep varies (%s), value: its value in this run\n", name);
    if (!isnan(static_hysteresis))
        fprintf(f, "# static_hysteresis: %.17g J, the static curve's loop (eps -> 0: the jump instabilities' share of every run's hysteresis)%s\n",
                static_hysteresis, static_resolved ? "" : ", on a grid that does not resolve it");
    fprintf(f, "run\tswept\tvalue\tE\tsigma\teps\tjump_in_h0\th_before\th_star\tmax_load\tpulloff_F\tjump_out_h0\tsteps\titerations\tseconds\tjumped\thysteresis\t%sstatus\n",
            stat ? "pulloff_F_disp\tfolds\t" : "");
    for (size_t i = 0; i < cfg->sweep.n; i++) {
        adh_run_spec rc;
        adh_config_sweep_run(cfg, i, &rc);
        adh_derived d;
        adh_material_derive(&rc.mat, &d);
        const adh_run *r = &runs[i];
        const adh_turn_result *mt = adh_run_main_turn(r);
        double max_load = mt ? mt->max_load : NAN, pull = mt ? mt->pulloff_F : NAN, out = mt ? mt->jump_out_h0 : NAN;
        double hyst = mt ? adh_cycle_hysteresis(r->rows, r->nrows, mt->path) : NAN;
        if (stat) {
            /* a run that never started has no summary worth the name */
            int ran = r->nrows > 0;
            max_load = ran && status[i] == ADH_SUCCESS && !r->interrupted ? r->rows[r->nrows - 1].F : NAN;
            pull = ran ? sres[i].pulloff_F : NAN;
            out = ran ? sres[i].jump_out_h0 : NAN;
            hyst = ran ? cli_tables_static_hysteresis(r, &rc.mat) : NAN;
        }
        fprintf(f, "%zu\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%zu\t%.6g\t%d\t%.17g\t",
                i + 1, name, cfg->sweep.values[i], rc.mat.E, d.sigma, rc.relax.eps, r->jump_in_h0,
                cli_jumps_gap_before(r), d.h_star, max_load, pull, out, r->nrows, r->iterations, r->seconds,
                cli_jumps_jumped(r, rc.proto.step), hyst);
        if (stat)
            fprintf(f, "%.17g\t%zu\t", r->nrows ? sres[i].pulloff_F_disp : NAN, r->nrows ? sres[i].folds : (size_t)0);
        fprintf(f, "%s\n", run_word(cfg, i, runs, status, said));
    }
    return 0;
}

typedef struct sweep_tables {
    const adh_config *cfg;
    const adh_run *runs;
    const adh_static_result *sres;
    const cli_time_out *tout;
    const int *status;
    double static_hysteresis;
    int static_resolved;
    const cli_sweep_said *said;
} sweep_tables;

static int write_sweep(FILE *f, const void *ctx)
{
    const sweep_tables *t = ctx;
    return cli_sweep_table(f, t->cfg, t->runs, t->sres, t->tout, t->status, t->static_hysteresis, t->static_resolved, t->said);
}

/* An eps sweep drawn as Figure 7: its runs' hysteresis against eps needs
 * the value eps -> 0 leaves, the static curve's loop (one curve: eps does
 * not enter it). NAN when not asked or when the curve failed; *resolved
 * whether its grid resolves it. */
static double sweep_static_hysteresis(const adh_config *cfg, const adh_grid *g, const adh_kernel *k, int *resolved)
{
    *resolved = 0;
    if (cfg->sweep.kind != ADH_SWEEP_EPS || cfg->spec.mode != ADH_MODE_RELAX || !cfg->output.plot ||
        cfg->sweep.plot != ADH_SWEEP_PLOT_FORCE || cli_interrupt_signal())
        return NAN;
    adh_run_spec rs;
    adh_config_sweep_run(cfg, 0, &rs);
    adh_run ref;
    adh_run_init(&ref);
    adh_static_result res;
    adh_ready_phase("reference");
    char why[1024];
    int st = cli_static_reference(&rs, g, k, &ref, &res, resolved, why, sizeof why);
    if (!*resolved)
        fprintf(stderr, "adhere: warning: Figure 7's equilibrium line comes from a static curve the grid does not "
                "resolve: %s\n", why);
    double h = st == ADH_SUCCESS && !ref.interrupted ? cli_tables_static_hysteresis(&ref, &rs.mat) : NAN;
    if (st != ADH_SUCCESS && !ref.interrupted)
        fprintf(stderr, "adhere: the static curve for Figure 7's equilibrium line failed: %s\n", adh_strerror(st));
    adh_run_free(&ref);
    return h;
}

/* Tables of run i in dir (out/run-K): force.tsv and turns.tsv when data
 * is set, then summary.tsv, last, naming what was not written (those that
 * failed here or before, kept in said, and the list in unwritten); word,
 * when not NULL, is its status, which said keeps. Returns an exit status. */
static int run_tables(const adh_config *cfg, size_t i, const adh_run *run, const adh_static_result *sres,
                      const cli_time_out *tout, int rc, adh_outdir *dir, int data, const char *unwritten,
                      const char *word, cli_sweep_said *said)
{
    char *lost = said->lost;
    char why[1024], note[256] = "";
    adh_run_spec rspec;
    adh_config_sweep_run(cfg, i, &rspec);
    cli_tables_names_add(lost, sizeof said->lost, unwritten ? unwritten : "");
    int partial = run->interrupted || rc != ADH_SUCCESS;
    if (run->interrupted)
        snprintf(note, sizeof note, "interrupted by signal %d after %zu steps", cli_interrupt_signal(), run->nrows);
    else if (rc != ADH_SUCCESS)
        snprintf(note, sizeof note, "the solver stopped after %zu steps: %s", run->nrows, adh_strerror(rc));
    /* a static run's summary.tsv has the batch's static keys */
    char keynames[CLI_TABLES_STATIC_KEYS][32];
    cli_tables_extra extra[CLI_TABLES_STATIC_KEYS + CLI_TIME_KEYS];
    size_t nextra = rspec.mode == ADH_MODE_STATIC && run->nrows
                  ? cli_tables_static_keys(sres, cli_tables_static_hysteresis(run, &rspec.mat), "", keynames, extra) : 0;
    double snap[CLI_TIME_SNAP_KEYS];
    int timed = rspec.mode == ADH_MODE_TIME;
    if (rspec.mode == ADH_MODE_STATIC && run->nrows && isfinite(rspec.time.spring))
        nextra += cli_time_snap_keys(run, rspec.time.spring, snap, extra + nextra);
    if (timed)
        nextra += cli_time_keys(tout, extra + nextra);
    cli_tables t = { cfg, &rspec, run, extra, nextra, partial, note, lost, word };
    int status = CLI_EXIT_OK;
    if (data) {
        const char *names[3] = { "force.tsv", run->nturns ? "turns.tsv" : NULL, timed ? "events.tsv" : NULL };
        adh_outdir_writer writers[3] = { cli_tables_force, cli_tables_turns, cli_time_events };
        const void *ctx[3] = { &t, &t, tout };
        for (int k = 0; k < 3; k++)
            if (names[k] && adh_outdir_write(dir, names[k], writers[k], ctx[k], why, sizeof why) != 0) {
                fprintf(stderr, "adhere: %s\n", why);
                status = CLI_EXIT_USAGE;
                cli_tables_names_add(lost, sizeof said->lost, names[k]);
            }
    }
    if (adh_outdir_write(dir, "summary.tsv", cli_tables_summary, &t, why, sizeof why) != 0) {
        fprintf(stderr, "adhere: %s\n", why);
        status = CLI_EXIT_USAGE;
        cli_tables_names_add(lost, sizeof said->lost, "summary.tsv");   /* sweep.tsv says it */
        said->word[0] = '\0';
    } else {
        snprintf(said->word, sizeof said->word, "%s", cli_tables_summary_word(&t));
    }
    if (status == CLI_EXIT_OK && partial)
        return run->interrupted ? CLI_EXIT_INTERRUPTED : CLI_EXIT_SOLVER;
    if (status == CLI_EXIT_OK && run->unconverged && !cfg->output.allow_unconverged) {
        if (data) /* said once, not again when the figures rewrite the summary */
            fprintf(stderr, "adhere: warning: run %zu: %zu of %zu steps reached the iteration cap without meeting eps (status unconverged; --allow-unconverged accepts them)\n",
                    i + 1, run->unconverged, run->nrows);
        return CLI_EXIT_SOLVER;
    }
    return status;
}

static int write_tables(const adh_config *cfg, size_t i, const adh_run *run, const adh_static_result *sres,
                        const cli_time_out *tout, int rc, adh_outdir *out, cli_sweep_said *said)
{
    return run_tables(cfg, i, run, sres, tout, rc, out, 1, NULL, NULL, said);
}

/* Figures of run i in out/run-K (its tables are there); when one is not
 * written, the run's summary.tsv is written again to say so. An exit
 * status. */
static int write_plots(const adh_config *cfg, const adh_grid *g, size_t i, const adh_run *run,
                       const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir,
                       cli_sweep_said *said)
{
    char msg[1024] = "", missing[256] = "";
    adh_run_spec rspec;
    adh_config_sweep_run(cfg, i, &rspec);
    if (!cfg->output.plot)
        return CLI_EXIT_OK;
    int status = CLI_EXIT_OK;
    /* the plot module's figures only when one is asked: a sweep of many runs
     * should not draw what nobody wants */
    if (cfg->output.plots & ADH_PLOT_ALL) {
        adh_plot_setup ps;
        adh_plot_setup_fill(cfg, &rspec, g, &ps);
        int prc = adh_plots_write(&ps, run, NULL, dir, msg, sizeof msg, missing, sizeof missing);
        if (prc != 0) {
            fprintf(stderr, "adhere: run %zu: plots not written: %s\n", i + 1, msg);
            status = prc == 2 ? CLI_EXIT_USAGE : CLI_EXIT_PLOT;
        }
    }
    if (cli_figures_run(cfg, &rspec, run, dir, msg, sizeof msg, missing, sizeof missing) != 0) {
        fprintf(stderr, "adhere: run %zu: %s\n", i + 1, msg);
        status = status ? status : CLI_EXIT_PLOT;
    }
    if (*missing) {
        int trc = run_tables(cfg, i, run, sres, tout, rc, dir, 0, missing, cli_interrupt_signal() ? "interrupted" : NULL,
                             said);
        if (trc == CLI_EXIT_USAGE)
            status = trc;
    }
    return status;
}

/* Run i's figures not drawn (a signal came first): its summary.tsv names
 * those asked for and says interrupted. An exit status. */
static int plots_skipped(const adh_config *cfg, size_t i, const adh_run *run, const adh_static_result *sres,
                         const cli_time_out *tout, int rc, adh_outdir *dir, cli_sweep_said *said)
{
    static const struct { unsigned bit; const char *name; } figs[] = {
        { ADH_PLOT_FORCE, "force.png" }, { ADH_PLOT_PROFILE, "profile.png" }, { ADH_PLOT_CONTACT, "contact.png" },
        { ADH_PLOT_PRECONTACT, "precontact.png" }, { ADH_PLOT_BULGE, "bulge.png" },
    };
    char missing[256] = "";
    for (size_t k = 0; cfg->output.plot && k < sizeof figs / sizeof figs[0]; k++)
        if (cfg->output.plots & figs[k].bit)
            cli_tables_names_add(missing, sizeof missing, figs[k].name);
    if (!*missing)
        return CLI_EXIT_OK;
    int trc = run_tables(cfg, i, run, sres, tout, rc, dir, 0, missing, "interrupted", said);
    return trc == CLI_EXIT_USAGE ? trc : cli_interrupt_exit();
}

static int worse(int a, int b)
{
    /* usage/output errors first, then interruption, solver failure, plots */
    static const int rank[] = { CLI_EXIT_OK, CLI_EXIT_PLOT, CLI_EXIT_SOLVER, CLI_EXIT_INTERRUPTED, CLI_EXIT_USAGE };
    int ra = 0, rb = 0;
    for (int k = 0; k < 5; k++) {
        if (rank[k] == a) ra = k;
        if (rank[k] == b) rb = k;
    }
    return ra >= rb ? a : b;
}

/* run-1 ... run-n in od, each opened once (no link followed) before any
 * run starts: subs[i], or -1 with why (those made are closed). */
static int open_runs(adh_outdir *od, size_t n, adh_outdir **subs, char *why, size_t whylen)
{
    for (size_t i = 0; i < n; i++) {
        char name[32];
        snprintf(name, sizeof name, "run-%zu", i + 1);
        if (!(subs[i] = adh_outdir_sub(od, name, why, whylen))) {
            while (i-- > 0)
                adh_outdir_close(subs[i]);
            return -1;
        }
    }
    return 0;
}

int cli_sweep_main(const cli_options *cli, adh_outdir *od)
{
    const adh_config *cfg = &cli->cfg;
    const char *out = od ? adh_outdir_path(od) : NULL;
    double t_start = adh_clock_seconds();
    char why[1024];
    size_t n = cfg->sweep.n;
    if (cfg->spec.mode == ADH_MODE_STATIC && cfg->sweep.kind == ADH_SWEEP_EPS) {
        /* every run would be the same equilibrium curve */
        fprintf(stderr, "adhere: a sweep of eps in mode = static would compute the same curve %zu times: "
                "eps is the relaxation's convergence parameter; sweep E or sigma, or use mode = relax\n", n);
        return CLI_EXIT_USAGE;
    }

    /* Every swept parameter (E, sigma, eps) leaves the grid alone, so one
     * kernel serves every run; rigid runs need none. */
    adh_grid *g = NULL;
    adh_kernel *k = NULL;
    if (cfg->spec.mode != ADH_MODE_RIGID) {
        /* --force on a grid some runs do not resolve: said even with -q */
        for (size_t i = 0; i < n; i++) {
            adh_run_spec rc;
            adh_config_sweep_run(cfg, i, &rc);
            adh_grid_report gr;
            adh_grid_check(&rc.mat, adh_config_grid_use(&rc), rc.grid.use.nodes, adh_config_spacing(&rc), &gr);
            if (!gr.resolved) {
                char msg[512];
                adh_grid_unresolved_sentence(&gr, msg, sizeof msg);
                fprintf(stderr, "adhere: warning: run %zu: %s (--force; its summary.tsv: resolved 0)\n", i + 1, msg);
            }
        }
        /* caught from here: a large ring kernel takes seconds to build */
        cli_interrupt_catch();
        int kst = ADH_ENOMEM;
        g = adh_config_grid_alloc(&cfg->spec);
        adh_ready_phase("kernel");
        k = g ? adh_config_kernel_alloc(&cfg->spec, g, &kst) : NULL;
        if (!k) {
            if (kst == ADH_EINTR)
                fprintf(stderr, "adhere: interrupted by signal %d while building the %zu-node kernel: nothing computed, no table written\n",
                        cli_interrupt_signal(), g ? g->n : cfg->spec.grid.use.nodes);
            else
                fprintf(stderr, "adhere: out of memory building the %zu-node kernel\n", g ? g->n : cfg->spec.grid.use.nodes);
            cli_interrupt_release();
            adh_grid_free(g);
            return kst == ADH_EINTR ? cli_interrupt_exit() : CLI_EXIT_SOLVER;
        }
    }
    adh_run *runs = calloc(n, sizeof *runs);
    adh_static_result *sres = calloc(n, sizeof *sres);
    cli_time_out *tout = calloc(n, sizeof *tout);
    int *status = calloc(n, sizeof *status);
    int *tables = calloc(n, sizeof *tables);
    cli_sweep_said *said = calloc(n, sizeof *said);
    adh_outdir **subs = calloc(n, sizeof *subs);
    /* a spring swept over one static curve: the curve once, its snap
     * points for each k */
    int share = cfg->spec.mode == ADH_MODE_STATIC && cfg->sweep.kind == ADH_SWEEP_SPRING;
    int jobs = share ? 1 : adh_plan_jobs(cfg);
    pthread_t *threads = calloc((size_t)jobs, sizeof *threads);
    /* each run's expected cost, for the time left */
    static adh_plan_progress eta[ADH_MAX_SWEEP];
    for (size_t i = 0; i < n && i < ADH_MAX_SWEEP; i++) {
        adh_run_spec rs;
        adh_config_sweep_run(cfg, i, &rs);
        eta[i] = (adh_plan_progress){ .cost = rs.mode == ADH_MODE_RELAX ? adh_plan_iterations(&rs) : 1.0 };
    }
    int failed = !runs || !sres || !tout || !status || !tables || !said || !subs || !threads ? CLI_EXIT_SOLVER : 0;
    if (failed)
        snprintf(why, sizeof why, "out of memory for %zu runs", n);
    else if (od && open_runs(od, n, subs, why, sizeof why) != 0)
        failed = CLI_EXIT_USAGE;
    if (failed) {
        cli_interrupt_release();
        fprintf(stderr, "adhere: %s\n", why);
        free(runs), free(sres), free(tout), free(status), free(tables), free(subs), free(threads), free(said);
        adh_kernel_free(k), adh_grid_free(g);
        return failed;
    }
    for (size_t i = 0; i < n; i++) {
        adh_run_init(&runs[i]);
        status[i] = ADH_SUCCESS;
        tables[i] = -1;
    }
    if (jobs > 1 && openblas_set_num_threads)
        openblas_set_num_threads(1);

    cli_interrupt_catch();
    adh_ready_phase("sweep");

    sweep_job job = { .cfg = cfg, .grid = g, .kernel = k, .runs = runs, .sres = sres, .tout = tout, .share = share, .status = status,
                      .out = od ? subs : NULL, .tables = tables, .said = said, .jobs = jobs, .eta = eta };
    pthread_mutex_init(&job.lock, NULL);
    job.t0 = adh_clock_seconds();
    int started = 0;
    for (int t = 0; t < jobs; t++)
        if (pthread_create(&threads[t], NULL, worker, &job) == 0)
            started++;
        else
            break;
    if (!started) /* no thread at all: run them here, one after another */
        worker(&job);
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    pthread_mutex_destroy(&job.lock);
    int static_resolved;
    double static_hyst = sweep_static_hysteresis(cfg, g, k, &static_resolved);

    int exit_status = CLI_EXIT_OK;
    for (size_t i = 0; i < n; i++) {
        /* a run never started (interrupted before its turn) counts as interrupted */
        if (cli_interrupt_signal() && runs[i].nrows == 0)
            runs[i].interrupted = 1;
        if (runs[i].interrupted)
            exit_status = worse(exit_status, CLI_EXIT_INTERRUPTED);
        else if (status[i] != ADH_SUCCESS)
            exit_status = worse(exit_status, CLI_EXIT_SOLVER);
        else if (runs[i].unconverged && !cfg->output.allow_unconverged)
            exit_status = worse(exit_status, CLI_EXIT_SOLVER);   /* sweep.tsv says unconverged */
    }
    sweep_tables st = { cfg, runs, sres, tout, status, static_hyst, static_resolved, said };
    if (!out) {
        cli_sweep_table(stdout, cfg, runs, sres, tout, status, static_hyst, static_resolved, NULL);
    } else {
        for (size_t i = 0; i < n; i++) {
            if (tables[i] < 0) /* never started: its tables say interrupted */
                tables[i] = write_tables(cfg, i, &runs[i], &sres[i], &tout[i], status[i], subs[i], &said[i]);
            exit_status = worse(exit_status, tables[i]);
            int plot = tables[i] == CLI_EXIT_OK ||
                       (tables[i] == CLI_EXIT_SOLVER && runs[i].unconverged && status[i] == ADH_SUCCESS);
            if (plot && cli_interrupt_signal())
                exit_status = worse(exit_status, plots_skipped(cfg, i, &runs[i], &sres[i], &tout[i], status[i], subs[i], &said[i]));
            else if (plot)
                exit_status = worse(exit_status, write_plots(cfg, g, i, &runs[i], &sres[i], &tout[i], status[i], subs[i], &said[i]));
        }
        if (cli_interrupt_signal())   /* while the tables or plots were written */
            exit_status = worse(exit_status, cli_interrupt_exit());
        if (adh_outdir_write(od, "sweep.tsv", write_sweep, &st, why, sizeof why) != 0) {
            fprintf(stderr, "adhere: %s\n", why);
            exit_status = worse(exit_status, CLI_EXIT_USAGE);
        } else if (cfg->output.plot && exit_status == CLI_EXIT_OK && cfg->sweep.plot != ADH_SWEEP_PLOT_NONE) {
            char msg[1024] = "";
            int frc = cfg->sweep.plot == ADH_SWEEP_PLOT_SPEED || cfg->sweep.plot == ADH_SWEEP_PLOT_SNAP
                    ? cli_time_sweep_figure(cfg, g, k, runs, tout, n, od, msg, sizeof msg)
                    : cli_figures_sweep(cfg, runs, n, static_hyst, od, msg, sizeof msg);
            if (frc != 0) {
                fprintf(stderr, "adhere: sweep plot not written: %s\n", msg);
                exit_status = worse(exit_status, CLI_EXIT_PLOT);
            }
        }
    }
    cli_interrupt_release();
    if (cli_interrupt_signal())
        fprintf(stderr, "adhere: interrupted by signal %d: %zu of %zu runs finished; sweep.tsv%s says which (# PARTIAL)\n",
                cli_interrupt_signal(), finished(cfg, runs), n, out ? " and each run's summary.tsv" : "");
    if (exit_status == CLI_EXIT_OK && !cfg->output.quiet) {
        char t[32];
        cli_progress_duration(adh_clock_seconds() - t_start, t, sizeof t);
        if (out)
            fprintf(stderr, "adhere: done in %s: %zu runs; sweep.tsv%s in %s/, each run's tables%s in "
                    "%s/run-1 ... run-%zu\n", t, n, cfg->output.plot && cfg->sweep.plot != ADH_SWEEP_PLOT_NONE ? " and the sweep's figure" : "",
                    out, cfg->output.plot && cfg->output.plots ? " and plots" : "", out, n);
        else
            fprintf(stderr, "adhere: done in %s: %zu runs; sweep.tsv went to standard output\n", t, n);
    }
    for (size_t i = 0; i < n; i++) {
        adh_run_free(&runs[i]);
        cli_time_out_free(&tout[i]);
        adh_outdir_close(subs[i]);
    }
    free(runs), free(sres), free(tout), free(status), free(tables), free(subs), free(threads), free(said);
    adh_kernel_free(k);
    adh_grid_free(g);
    return exit_status;
}
