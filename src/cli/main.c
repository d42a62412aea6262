/* adhere: the command line. Parses options, then hands over to the batch
 * runner, the plan or cost reports, or the TUI. */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "adhere/grid.h"
#include "adhere/status.h"
#include "plot/say.h"
#include "cli/advice.h"
#include "cli/batch.h"
#include "cli/cost.h"
#include "cli/estimate.h"
#include "cli/data.h"
#include "cli/fit.h"
#include "cli/studycost.h"
#include "cli/study.h"
#include "cli/merge.h"
#include "cli/interrupt.h"
#include "cli/options.h"
#include "scene/datadir.h"
#include "scene/budget.h"
#include "cli/static.h"
#include "scene/config.h"
#include "scene/plan.h"
#include "tui/actions.h"
#include "tui/tui.h"

/* OpenBLAS's own; declared here so the GSL CBLAS header stays the only one.
 * Weak: a build against the reference BLAS (make check-fp) has none. */
void openblas_set_num_threads(int num_threads) __attribute__((weak));

/* What was printed must have reached its file: a full disk or a closed
 * pipe is an error, not a success. */
static int stdout_done(void)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        adh_sayf("cannot write to standard output: %s", strerror(errno));
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* A report that went to standard output (a study's sweep.tsv, --cost's,
 * adhere fit's) was lost to a full disk with exit 0: a run that finished
 * says so with exit 2, as --plan does; one that failed keeps its status. */
static int reported(int rc)
{
    return rc == CLI_EXIT_OK ? stdout_done() : rc;
}

/* --plan: the plan, and for a study its shard, expected time, disk; a
 * study that would not fit is refused (exit 2) after its plan. */
static int plan(cli_options *cli)
{
    static adh_plan p;
    char why[1024];
    adh_plan_make(&cli->cfg, &p);
    adh_plan_print(stdout, &cli->cfg, &p);
    if (cli->reference[0])
        cli_static_reference_plan(stdout, &cli->cfg.spec);
    if (!cli->cfg.sweep.naxes) {
        cli_estimate_print(stdout, &cli->cfg, &p);
        return stdout_done();
    }
    /* a study's one time line: its pilot's, which covers every run and
     * grid; the plan's own (rigid spheres, physical time) when the pilot
     * gives none */
    cli_studycost e;
    cli_studycost_time(&cli->cfg, &p, &e);
    if (!p.elastic || cli_studycost_print(stdout, &e) != 0)
        cli_estimate_print(stdout, &cli->cfg, &p);
    if (cli->shard_n) {
        cli_study st;
        cli_study_from_cli(&st, cli);
        /* the time line above counts every run (a shard's job was sized
         * by it with nothing to say so) */
        printf("shard: %u of %u: drives %u, %u, ... (%zu of the %zu runs; the time above is the whole study's); "
               "adhere merge joins the shards\n",
               st.shard_k, st.shard_n, st.shard_k, st.shard_k + st.shard_n, cli_study_shard_runs(&st), st.nruns);
        printf("fingerprint: %s\n", st.fingerprint);
    }
    int fits = cli_studycost_fits(&cli->cfg, &p, stdout, why, sizeof why);
    int rc = stdout_done();
    if (fits != 0) {
        adh_sayf("refused: %s", why);
        return CLI_EXIT_USAGE;
    }
    return rc;
}

/* Before any work, once memory is bounded: adh_config_start_check (each
 * run of cfg that is a standard linear solid in physical time from a start
 * given can start at rest out of contact there). 0, or 2 with why in the
 * CLI's words: the start as it was given (--start=400pm, or start = 400pm
 * (a.scene:6)), a sweep's run named, and the advice in the words cfg's
 * keys were given in. */
static int start_checked(const adh_config *cfg, char *why, size_t whylen)
{
    unsigned fix;
    char keyed[1024];
    if (adh_config_start_check(cfg, 1, keyed, sizeof keyed, &fix) == ADH_SUCCESS)
        return 0;
    cli_options_words(cfg, keyed, why, whylen);
    cli_advice_append_cfg(cfg, CLI_ADVICE_RUN, why, whylen, fix);
    return 2;
}

/* Before any work: the grid (the one the contact's edge needs when none
 * was given, or a refusal), every run valid, the memory for the grid,
 * whichever it is, before anything is allocated (a static curve holds its
 * own solver; a sweep solves one per thread). 0, or the exit status with
 * why in the CLI's words. */
static int checked(adh_config *cfg, const cli_options *cli, char *why, size_t len)
{
    unsigned fix;
    if (adh_config_grid(cfg, why, len, &fix) != 0) {
        cli_advice_append_cfg(cfg, CLI_ADVICE_RUN, why, len, fix);
        return CLI_EXIT_USAGE;
    }
    if ((cli->action == CLI_ACT_TUI ? cli_options_validate_screen : cli_options_validate)(cfg, why, len) != 0)
        return CLI_EXIT_USAGE;
    const adh_run_spec *spec = &cfg->spec;
    unsigned solvers = adh_budget_solvers(spec, (unsigned)adh_plan_jobs(cfg), cli->reference[0] != 0);
    char msg[1200];
    if (adh_budget_check_threads(spec, solvers, (unsigned)adh_plan_jobs(cfg), msg, sizeof msg) != 0) {
        cli_options_words(cfg, msg, why, len);
        return CLI_EXIT_USAGE;
    }
    /* a solid's start, on its kernel: once the memory for it is known */
    return start_checked(cfg, why, len) != 0 ? CLI_EXIT_USAGE : 0;
}

/* adh_config_unit_hint's test of a configuration with a unit put right. */
static int accept(adh_config *copy, void *ctx)
{
    char why[1200];
    return checked(copy, ctx, why, sizeof why);
}

static int run(int argc, char **argv);

/* Under an address-space limit (ulimit -v, -d) OpenBLAS's own threads may
 * be stuck retrying a working buffer that can never be mapped (before
 * 0.3.30 it retries forever), and its exit handler joins them: adhere then
 * never ended, even refusing or printing --version. There, what was
 * written is flushed and the process leaves without the libraries' exit
 * handlers (they only free memory); elsewhere main returns as usual. */
int main(int argc, char **argv)
{
    int status = run(argc, argv);
    struct rlimit as, data;
    if ((getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) ||
        (getrlimit(RLIMIT_DATA, &data) == 0 && data.rlim_cur != RLIM_INFINITY)) {
        if (fflush(NULL) != 0 && status == CLI_EXIT_OK)
            status = CLI_EXIT_USAGE;
        _exit(status);
    }
    return status;
}

static int run(int argc, char **argv)
{
    static cli_options cli;
    /* A file size limit (ulimit -f) is a full disk: the write fails with
     * EFBIG, the temporary goes and summary.tsv says not_written, instead
     * of the signal killing the process with half a file left behind. */
    signal(SIGXFSZ, SIG_IGN);
    /* One thread per run: a product of N = 1000 is too small to share, and
     * idle BLAS threads spinning cost more than they give (a coarse Figure 1
     * run: 14 s with them, 1.6 s without). Sweeps run one process thread
     * per core instead. */
    if (openblas_set_num_threads)
        openblas_set_num_threads(1);
    /* GSL's default error handler aborts the process; the core reads GSL's
     * return values and reports through its own status codes. The handler
     * is process-wide, so the program sets it, once, and the library never
     * does. */
    gsl_set_error_handler_off();
    /* room for a sentence and a path whole (a scene's FILE:LINE: first) */
    char why[PATH_MAX + 1024], envwhy[PATH_MAX + 256];
    /* a set ADHERE_DATADIR naming no directory: refused before anything
     * is read or written (a scene the parse found elsewhere too), but not
     * for --help and --version, which read nothing */
    int envbad = adh_data_env_check(envwhy, sizeof envwhy) != 0;
    if (cli_options_parse(argc, argv, &cli, why, sizeof why) != 0) {
        adh_say(envbad ? envwhy : why);
        return CLI_EXIT_USAGE;
    }
    if (envbad && cli.action != CLI_ACT_HELP && cli.action != CLI_ACT_VERSION) {
        adh_say(envwhy);
        return CLI_EXIT_USAGE;
    }
    switch (cli.action) {
    case CLI_ACT_HELP:
        cli_options_usage(stdout);
        return stdout_done();
    case CLI_ACT_VERSION:
        printf("adhere %s\nnumerics %s\n", ADH_VERSION, cli_study_numerics());
        return stdout_done();
    case CLI_ACT_LIST_KEYS:
        tui_print_keys(stdout);
        return stdout_done();
    case CLI_ACT_MERGE:   /* the study and its grid are the shards' */
        return cli_merge_main(&cli);
    default:
        break;
    }
    /* A measured curve is read before any work: a bad line stops here. */
    if (cli_data_load(&cli, why, sizeof why) != 0) {
        adh_say(why);   /* then FILE:LINE:, as compilers do */
        return CLI_EXIT_USAGE;
    }
    /* A fit chooses its own grid, for the start values and the data */
    if (cli.action == CLI_ACT_FIT) {
        cli.cfg.spec.relax.cancel = cli_interrupt_flag();
        return reported(cli_fit_main(&cli));
    }
    if (cli.action != CLI_ACT_COST) {   /* --cost replaces N and eps and checks each of its runs itself */
        int rc = checked(&cli.cfg, &cli, why, sizeof why);
        if (rc != 0) {
            /* a bare number read in SI may have meant the screen's unit */
            char hint[1024];
            if (adh_config_unit_hint(&cli.cfg, accept, &cli, hint, sizeof hint) == 1)
                adh_sayf("%s (a bare number is in SI units: %s)", hint, why);
            else
                adh_say(why);
            return rc;
        }
    }
    const adh_run_spec *spec = &cli.cfg.spec;
    /* the time: a dense product reads all N^2 numbers every iteration */
    size_t nodes = adh_config_nodes(spec);
    if (cli.action != CLI_ACT_COST && !cli.cfg.output.quiet && spec->mode != ADH_MODE_RIGID &&
        spec->grid.use.storage == ADH_STORAGE_DENSE && nodes > ADH_GRID_MAX_NODES)
        adh_sayf("note: --operator=dense on %zu nodes: every relaxation iteration reads the whole "
                 "%.3g GB kernel, %.3g times the work at the dense budget's %d nodes; --operator=h2 holds it in "
                 "O(N)", nodes, 8e-9 * (double)nodes * (double)nodes,
                 ((double)nodes / ADH_GRID_MAX_NODES) * ((double)nodes / ADH_GRID_MAX_NODES), ADH_GRID_MAX_NODES);
    /* The solvers poll the interrupt flag through their cancel hook: a
     * signal is heard inside a step, not only between steps. */
    cli.cfg.spec.relax.cancel = cli_interrupt_flag();
    switch (cli.action) {
    case CLI_ACT_BATCH:
        return reported(cli_batch_main(&cli));
    case CLI_ACT_PLAN:
        return plan(&cli);
    case CLI_ACT_COST:
        return reported(cli_cost_main(&cli));
    default:
        return tui_main(&cli.cfg);
    }
}
