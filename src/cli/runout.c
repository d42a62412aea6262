#include "cli/runout.h"
#include "plot/say.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/status.h"
#include "cli/exit.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "cli/tables.h"
#include "plot/forcebase.h"
#include "plot/plot.h"
#include "plot/setup.h"

/* Tables of run i in dir (out/run-K): force.tsv and turns.tsv when data
 * is set, then summary.tsv, last, naming what was not written (those that
 * failed here, and the list in unwritten); word, when not NULL, is its
 * status. Returns an exit status. */
static int run_tables(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                      const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, int data, const char *unwritten,
                      const char *word, cli_runout_said *said)
{
    char *lost = said->lost;
    char why[1024], note[CLI_TABLES_STOPPED_LEN + 100] = "", stopped[CLI_TABLES_STOPPED_LEN];
    const adh_run_spec *rs = spec;
    cli_tables_names_add(lost, sizeof said->lost, unwritten ? unwritten : "");
    int partial = run->interrupted || rc != ADH_SUCCESS;
    if (run->interrupted)
        snprintf(note, sizeof note, "interrupted by signal %d after %zu steps", cli_interrupt_signal(), run->nrows);
    else if (rc != ADH_SUCCESS)
        snprintf(note, sizeof note, "the solver stopped after %zu steps: %s", run->nrows,
                 cli_tables_stopped(cfg, run, rc, stopped, sizeof stopped));
    /* a static run's summary.tsv has the batch's static keys */
    char keynames[CLI_TABLES_STATIC_KEYS][32];
    cli_tables_extra extra[CLI_TABLES_STATIC_KEYS + CLI_TIME_SNAP_KEYS + CLI_TIME_KEYS];
    size_t nextra = rs->mode == ADH_MODE_STATIC && sres && run->nrows
                  ? cli_tables_static_keys(sres, cli_tables_static_hysteresis(run, &rs->mat), "", keynames, extra) : 0;
    /* physical time's keys: a static curve's snap points under a spring,
     * a run in time its summary */
    double snap[CLI_TIME_SNAP_KEYS];
    int timed = rs->mode == ADH_MODE_TIME && tout;
    if (rs->mode == ADH_MODE_STATIC && run->nrows && isfinite(rs->time.spring))
        nextra += cli_time_snap_keys(run, rs->time.spring, snap, extra + nextra);
    if (timed)
        nextra += cli_time_keys(tout, extra + nextra);
    cli_tables t = { cfg, rs, run, extra, nextra, partial, note, lost, word };
    int status = CLI_EXIT_OK;
    if (data) {
        const char *names[3] = { "force.tsv", run->nturns ? "turns.tsv" : NULL, timed ? "events.tsv" : NULL };
        adh_outdir_writer writers[3] = { cli_tables_force, cli_tables_turns, cli_time_events };
        cli_time_out to = timed ? *tout : (cli_time_out){ 0 };   /* events.tsv says the scene and a stop too */
        to.scene = cfg->scene;
        to.partial = partial ? note : NULL;
        const void *ctx[3] = { &t, &t, &to };
        for (int k = 0; k < 3; k++)
            if (names[k] && adh_outdir_write(dir, names[k], writers[k], ctx[k], why, sizeof why) != 0) {
                adh_say(why);
                status = CLI_EXIT_USAGE;
                cli_tables_names_add(lost, sizeof said->lost, names[k]);
            }
    }
    if (adh_outdir_write(dir, "summary.tsv", cli_tables_summary, &t, why, sizeof why) != 0) {
        adh_say(why);
        status = CLI_EXIT_USAGE;
        cli_tables_names_add(lost, sizeof said->lost, "summary.tsv");   /* sweep.tsv says it */
        said->word[0] = '\0';
    } else {
        snprintf(said->word, sizeof said->word, "%s", cli_tables_summary_word(&t));
    }
    if (status == CLI_EXIT_OK && partial)
        return run->interrupted ? cli_interrupt_exit() : CLI_EXIT_SOLVER;
    if (status == CLI_EXIT_OK && run->unconverged && !cfg->output.allow_unconverged) {
        char marked[CLI_TABLES_REASON_LEN];   /* a run in time: its balance open, or its tolerance loose */
        if (data && *cli_tables_marked_reason(cfg, run, marked, sizeof marked))
            adh_sayf("warning: run %zu: %s (status unconverged; --allow-unconverged accepts it)", i + 1, marked);
        else if (data) /* said once, not again when the figures rewrite the summary */
            adh_sayf("warning: run %zu: %zu of %zu steps reached the iteration cap without meeting eps (status unconverged; --allow-unconverged accepts them)",
                     i + 1, run->unconverged, run->nrows);
        return CLI_EXIT_SOLVER;
    }
    return status;
}

/* Figures of run i in out/run-K (its tables are there); when one is not
 * written, the run's summary.tsv is written again to say so. An exit
 * status. */
static int write_plots(const adh_config *cfg, size_t i, const adh_run_spec *rspec, const adh_run *run,
                       const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said)
{
    char msg[1024] = "", missing[256] = "";
    if (!cfg->output.plot)
        return CLI_EXIT_OK;
    int status = CLI_EXIT_OK;
    /* the plot module's figures only when one is asked: a sweep of many runs
     * should not draw what nobody wants */
    if (cfg->output.plots & ADH_PLOT_ALL) {
        /* the figures draw the rows and profiles: the grid only gives the profiles' radii */
        adh_grid *g = rspec->mode == ADH_MODE_RIGID ? NULL : adh_config_grid_alloc(rspec);
        adh_plot_setup ps;
        adh_plot_setup_fill(cfg, rspec, g, &ps);
        int prc = adh_plots_write(&ps, run, NULL, dir, msg, sizeof msg, missing, sizeof missing);
        adh_grid_free(g);
        if (prc != 0) {
            adh_sayf("run %zu: plots not written: %s", i + 1, msg);
            status = prc == 2 ? CLI_EXIT_USAGE : CLI_EXIT_PLOT;
        }
    }
    if (cli_figures_run(cfg, rspec, run, dir, msg, sizeof msg, missing, sizeof missing) != 0) {
        adh_sayf("run %zu: %s", i + 1, msg);
        status = status ? status : CLI_EXIT_PLOT;
    }
    if (*missing) {
        int trc = run_tables(cfg, i, rspec, run, sres, tout, rc, dir, 0, missing, cli_interrupt_signal() ? "interrupted" : NULL,
                             said);
        if (trc == CLI_EXIT_USAGE)
            status = trc;
    }
    return status;
}

/* Run i's figures not drawn (a signal came first): its summary.tsv names
 * those asked for and says interrupted. An exit status. */
static int plots_skipped(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                         const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said)
{
    static const struct { unsigned bit; const char *name; } figs[] = {
        { ADH_PLOT_FORCE, "force.png" }, { ADH_PLOT_PROFILE, "profile.png" }, { ADH_PLOT_CONTACT, "contact.png" },
        { ADH_PLOT_PRECONTACT, "precontact.png" }, { ADH_PLOT_BULGE, "bulge.png" },
    };
    char missing[256] = "";
    for (size_t k = 0; cfg->output.plot && k < sizeof figs / sizeof figs[0]; k++)
        if (cfg->output.plots & figs[k].bit)
            cli_tables_names_add(missing, sizeof missing, figs[k].name);
    adh_plot_setup ps;
    adh_plot_setup_fill(cfg, spec, NULL, &ps);
    if (cfg->output.plot && (cfg->output.plots & ADH_PLOT_FORCE) && adh_forcebase_wanted(&ps))
        cli_tables_names_add(missing, sizeof missing, "force-base.png");
    if (!*missing)
        return CLI_EXIT_OK;
    int trc = run_tables(cfg, i, spec, run, sres, tout, rc, dir, 0, missing, "interrupted", said);
    return trc == CLI_EXIT_USAGE ? trc : cli_interrupt_exit();
}

int cli_runout_worse(int a, int b)
{
    /* usage/output errors first, then interruption (128 + any signal's
     * number), solver failure, plots */
    static const int rank[] = { CLI_EXIT_OK, CLI_EXIT_PLOT, CLI_EXIT_SOLVER, CLI_EXIT_INTERRUPTED, CLI_EXIT_USAGE };
    int ra = a > 128 ? 3 : 0, rb = b > 128 ? 3 : 0;
    for (int k = 0; k < 5; k++) {
        if (rank[k] == a) ra = k;
        if (rank[k] == b) rb = k;
    }
    return ra >= rb ? a : b;
}

int cli_runout_tables(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                      const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said)
{
    memset(said, 0, sizeof *said);
    return run_tables(cfg, i, spec, run, sres, tout, rc, dir, 1, NULL, NULL, said);
}

int cli_runout_write(const adh_config *cfg, size_t i, const adh_run_spec *spec, const adh_run *run,
                     const adh_static_result *sres, const cli_time_out *tout, int rc, adh_outdir *dir, cli_runout_said *said)
{
    int t = cli_runout_tables(cfg, i, spec, run, sres, tout, rc, dir, said);
    /* figures of a run that finished (one with steps at the cap too) */
    int plot = t == CLI_EXIT_OK || (t == CLI_EXIT_SOLVER && run->unconverged && rc == ADH_SUCCESS && !run->interrupted);
    if (!plot)
        return t;
    int p = cli_interrupt_signal() ? plots_skipped(cfg, i, spec, run, sres, tout, rc, dir, said)
                                   : write_plots(cfg, i, spec, run, sres, tout, rc, dir, said);
    return cli_runout_worse(t, p);
}
