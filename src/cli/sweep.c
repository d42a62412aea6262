#include "cli/sweep.h"
#include "plot/say.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/clock.h"
#include "adhere/grid.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "cli/studycost.h"
#include "cli/exit.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "cli/kcache.h"
#include "cli/progress.h"
#include "cli/runout.h"
#include "cli/static.h"
#include "cli/timerun.h"
#include "cli/study.h"
#include "cli/studyrow.h"
#include "cli/tables.h"
#include "scene/budget.h"
#include "scene/plan.h"
#include "util/ready.h"

/* OpenBLAS's own threads would fight the sweep's for the same cores. */
void openblas_set_num_threads(int n) __attribute__((weak));   /* none in the reference BLAS */

#define ETA_MAX_DRIVES 2000

typedef struct study_job {
    const adh_config *cfg;
    const cli_study *st;
    cli_kcache *kc;
    size_t *todo, ntodo, next;     /* the drives to step, in the order taken */
    cli_studyrow *rows;            /* every run's row: those done filled */
    unsigned char *whole;          /* run i ended here, its tables whole (its figures maybe not) */
    adh_outdir *od;                /* NULL: sweep.tsv on standard output alone */
    int run_dirs;
    int rows_fd;                   /* runs.tsv, appended a row at a time; -1 none */
    int shared;                    /* runs that differ only in their turn (or spring, static) share drives */
    size_t done, total;            /* runs finished now, runs to step now */
    int exit_status;
    double t0;
    adh_plan_progress *eta;        /* todo[a]'s expected cost and progress (NULL: by runs alone) */
    int jobs;                      /* drives at once */
    pthread_mutex_t lock;          /* the queue, rows, runs.tsv, messages */
    pthread_mutex_t dirs;          /* od itself: a run-K made (its manifest) */
} study_job;

/* ---- one run's results --------------------------------------------------- */

/* The exit status a finished run calls for. */
static int run_exit(const adh_config *cfg, const adh_run *run, int status)
{
    if (run->interrupted)
        return cli_interrupt_exit();
    if (status != ADH_SUCCESS || (run->unconverged && !cfg->output.allow_unconverged))
        return CLI_EXIT_SOLVER;
    return CLI_EXIT_OK;
}

/* runs.tsv gets the row in one write: a kill leaves it whole or cut, and a
 * cut row does not read back. */
static void append_row(study_job *job, const cli_studyrow *row)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (!m)
        return;
    cli_studyrow_write(m, job->cfg, row);
    fclose(m);
    if (job->rows_fd >= 0 && write(job->rows_fd, text, len) != (ssize_t)len && job->exit_status != CLI_EXIT_USAGE) {
        adh_sayf("cannot write %s/runs.tsv: %s", adh_outdir_path(job->od), strerror(errno));
        job->exit_status = CLI_EXIT_USAGE;
    }
    free(text);
}

/* "67 %, about 5 min left": the drives weighed by their expected
 * iterations (a run at a fifth of the eps takes five times as long), under
 * way and waiting shared out over the jobs; by runs alone past
 * ETA_MAX_DRIVES (job->lock held). */
static void progress_text(const study_job *job, char *buf, size_t len)
{
    if (!job->eta) {
        cli_progress_text(job->done, job->total, adh_clock_seconds() - job->t0, buf, len);
        return;
    }
    double all = 0, done = 0;
    for (size_t a = 0; a < job->ntodo; a++) {
        all += job->eta[a].cost;
        done += job->eta[a].state == 2 ? job->eta[a].cost : 0;
    }
    double left = adh_plan_time_left(job->eta, job->ntodo, job->jobs, adh_clock_seconds(), 0);
    cli_progress_left(all > 0 ? done / all : 1, job->done < job->total ? left : NAN, buf, len);
}

/* Run i (specification spec) ended: its run-K, its row, a line on stderr. */
static void finished(study_job *job, size_t i, const adh_run_spec *spec, const adh_run *run,
                     const adh_static_result *sres, const cli_time_out *tout, int status)
{
    const adh_config *cfg = job->cfg;
    cli_studyrow row;
    cli_studyrow_fill(&row, cfg, i, spec, run, sres, tout, status);
    int out = run_exit(cfg, run, status);
    if (job->od && job->run_dirs) {
        char name[32], why[1024];
        snprintf(name, sizeof name, "run-%zu", i + 1);
        pthread_mutex_lock(&job->dirs);
        adh_outdir *dir = adh_outdir_sub(job->od, name, why, sizeof why);
        pthread_mutex_unlock(&job->dirs);
        if (!dir) {
            adh_say(why);
            out = CLI_EXIT_USAGE;
        } else {
            cli_runout_said said;
            int w = cli_runout_write(cfg, i, spec, run, sres, tout, status, dir, &said);
            /* the row repeats the word its summary.tsv said last (a file not
             * written, figures a signal stopped: no success there) */
            if (said.word[0])
                snprintf(row.status, sizeof row.status, "%s", said.word);
            else if (!strcmp(row.status, "success") && said.lost[0])
                snprintf(row.status, sizeof row.status, "output incomplete");
            out = cli_runout_worse(out, w);
            adh_outdir_close(dir);
        }
    }
    char which[256], pr[64];
    adh_sweep_describe(&cfg->sweep, i, which, sizeof which);
    pthread_mutex_lock(&job->lock);
    cli_studyrow_clear(&job->rows[i]);
    job->rows[i] = row;
    job->whole[i] = !run->interrupted && out != CLI_EXIT_USAGE;
    if (!run->interrupted && job->od)
        append_row(job, &row);
    job->exit_status = cli_runout_worse(job->exit_status, out);
    job->done++;
    if (!cfg->output.quiet) {
        progress_text(job, pr, sizeof pr);
        adh_sayf("run %zu of %zu (%s) %s: %zu steps, %zu iterations, %.3g s; %zu of %zu done, %s",
                 i + 1, job->st->nruns, which, run->interrupted ? "interrupted" : row.status, run->nrows,
                 run->iterations, run->seconds, job->done, job->total, pr);
        if (!run->interrupted && row.reason && !cli_tables_time_marked(run))   /* that one ran through: below */
            adh_sayf("run %zu stopped: %s", i + 1, row.reason);
    }
    /* not hidden by -q: it changes what the run's numbers mean */
    if (cli_tables_time_marked(run))   /* a run in time: its balance open, or its tolerance loose */
        adh_sayf("warning: run %zu (%s): %s", i + 1, which, row.reason ? row.reason : run->why);
    else if (run->unconverged)
        adh_sayf("warning: run %zu (%s): %zu of %zu steps reached the iteration cap (%zu) "
                 "without meeting eps; their rows say converged 0", i + 1, which, run->unconverged, run->nrows,
                 spec->relax.max_iter);
    pthread_mutex_unlock(&job->lock);
}

/* ---- stepping a drive ------------------------------------------------------ */

/* The drive of spec on grid g with kernel k (NULL for rigid spheres); a
 * run in physical time leaves its summary and events in tout. */
static int step(const adh_run_spec *spec, const adh_grid *g, const adh_kernel *k, adh_run *run,
                adh_static_result *sres, cli_time_out *tout)
{
    return spec->mode == ADH_MODE_RIGID
               ? adh_runner_rule(&adh_rule_rigid, NULL, NULL, &spec->mat, NULL, &spec->proto, cli_interrupt_step, NULL, run)
           : spec->mode == ADH_MODE_TIME
               ? cli_time_run(spec, g, k, cli_interrupt_step, NULL, run, tout)
           : spec->mode == ADH_MODE_STATIC
               ? cli_static_run(spec, g, k, cli_interrupt_step, NULL, run, sres)
               : adh_runner_rule(&adh_rule_relax, g, k, &spec->mat, &spec->relax, &spec->proto, cli_interrupt_step,
                                 NULL, run);
}

/* Steps spec with its kernel from the cache: the adh status. */
static int step_cached(study_job *job, const adh_run_spec *spec, adh_run *run, adh_static_result *sres,
                       cli_time_out *tout, size_t *n)
{
    const adh_grid *g = NULL;
    const adh_kernel *k = NULL;
    int st = spec->mode == ADH_MODE_RIGID ? ADH_SUCCESS : cli_kcache_get(job->kc, spec, &g, &k);
    if (st == ADH_EINTR)
        run->interrupted = 1;
    if (st == ADH_SUCCESS)
        st = step(spec, g, k, run, sres, tout);
    *n = g ? g->n : 0;
    cli_kcache_put(job->kc, k);
    return st;
}

/* A run of a shared drive stepped alone: the drive stopped before its turn was done. */
static void step_alone(study_job *job, size_t i, const adh_run_spec *spec)
{
    adh_run run;
    adh_static_result sres;
    cli_time_out tout;
    size_t n;
    adh_run_init(&run);
    memset(&sres, 0, sizeof sres);
    memset(&tout, 0, sizeof tout);
    int st = step_cached(job, spec, &run, &sres, &tout, &n);
    finished(job, i, spec, &run, &sres, &tout, st);
    cli_time_out_free(&tout);
    adh_run_free(&run);
}

/* The runs of a drive that stepped several turns: each one's own run
 * taken from it, or, when the drive stopped before the turn was done
 * (not for a signal), stepped alone. */
static void share_out(study_job *job, const adh_run_spec *ds, const adh_run *run, int status, size_t n,
                      const size_t *members, size_t nodes)
{
    int last_path = run->nrows ? run->rows[run->nrows - 1].path : 0;
    int ended = status == ADH_SUCCESS && !run->interrupted;
    for (size_t j = 0; j < n; j++) {
        if (job->rows[members[j]].done)
            continue;   /* done before (a resumed drive): its row and run-K stay */
        adh_run_spec ms = *ds;
        adh_run_spec own;
        adh_config_sweep_run(job->cfg, members[j], &own);
        ms.proto.turns[0] = own.proto.turns[0];
        ms.proto.nturns = 1;
        size_t t = 0;
        while (t < run->nturns && run->turns[t].h0 != ms.proto.turns[0])
            t++;
        int done = t < run->nturns && (ended || (run->turns[t].path > 0 && run->turns[t].path < last_path));
        adh_run mr;
        if (done && adh_run_turn(run, t, nodes, &mr) == ADH_SUCCESS) {
            finished(job, members[j], &ms, &mr, NULL, NULL, ADH_SUCCESS);
            adh_run_free(&mr);
        } else if (run->interrupted || cli_interrupt_signal()) {
            adh_run_init(&mr);
            mr.interrupted = 1;
            finished(job, members[j], &ms, &mr, NULL, NULL, ADH_SUCCESS);
        } else {
            step_alone(job, members[j], &ms);
        }
    }
}

/* The runs of a static curve shared by their springs: the curve does not
 * depend on k, each run is the curve with its own k (its snap points). */
static void share_springs(study_job *job, const adh_run_spec *ds, const adh_run *run,
                          const adh_static_result *sres, int status, size_t n, const size_t *members)
{
    for (size_t j = 0; j < n; j++) {
        if (job->rows[members[j]].done)
            continue;   /* done before (a resumed drive): its row and run-K stay */
        adh_run_spec own, ms = *ds;
        adh_config_sweep_run(job->cfg, members[j], &own);
        ms.time.spring = own.time.spring;
        ms.proto.start = adh_config_start(ds);   /* the curve's, not this k's own automatic one */
        finished(job, members[j], &ms, run, sres, NULL, status);
    }
}

/* The drive todo[a]. */
static void step_drive(study_job *job, size_t a)
{
    size_t u = job->todo[a], members[ADH_MAX_TURNS], nodes;
    size_t n = adh_sweep_drive_runs(job->cfg, u, members);
    adh_run_spec ds;
    adh_sweep_drive_spec(job->cfg, u, &ds);
    adh_run run;
    adh_static_result sres;
    cli_time_out tout;
    adh_run_init(&run);
    memset(&sres, 0, sizeof sres);
    memset(&tout, 0, sizeof tout);
    if (job->eta) {
        pthread_mutex_lock(&job->lock);
        job->eta[a].state = 1;
        job->eta[a].started = adh_clock_seconds();
        pthread_mutex_unlock(&job->lock);
    }
    int st = step_cached(job, &ds, &run, &sres, &tout, &nodes);
    if (job->eta) {
        pthread_mutex_lock(&job->lock);
        job->eta[a].state = 2;
        job->eta[a].seconds = adh_clock_seconds() - job->eta[a].started;
        pthread_mutex_unlock(&job->lock);
    }
    if (!job->shared)
        finished(job, members[0], &ds, &run, &sres, &tout, st);
    else if (ds.mode == ADH_MODE_STATIC)
        share_springs(job, &ds, &run, &sres, st, n, members);
    else
        share_out(job, &ds, &run, st, n, members, nodes);
    cli_time_out_free(&tout);
    adh_run_free(&run);
}

static void *worker(void *arg)
{
    study_job *job = arg;
    for (;;) {
        pthread_mutex_lock(&job->lock);
        int more = job->next < job->ntodo && !cli_interrupt_signal();
        size_t a = more ? job->next++ : 0;
        pthread_mutex_unlock(&job->lock);
        if (!more)
            return NULL;
        step_drive(job, a);
    }
}

/* ---- the study's directory ------------------------------------------------- */

/* What --overwrite removes (adh_outdir_clear with ADH_OUTDIR_OVERWRITE), in
 * the man page's words under --overwrite: not only what adhere recorded. */
#define OVERWRITE_REMOVES "it removes every file there under adhere's names, whether adhere wrote it or not: a " \
    "user's, an edited table, a link, a killed run's temporaries, as --overwrite in adhere(1) says; other files stay"

/* This study's shard in od, computed by another build (there: its numerics
 * id as shown, not st's, or none recorded, or none this build reads):
 * refused (-1 with why), its rows never mixed with this build's; with
 * --overwrite every file under adhere's names goes and the study runs again from scratch (0). */
static int other_build(const cli_study *st, const char *there, adh_outdir *od, char *why, size_t whylen)
{
    const char *path = adh_outdir_path(od);
    char ids[200];
    snprintf(ids, sizeof ids, "numerics there: %s; this adhere's: %s", there, st->numerics);
    if (!st->cfg->output.overwrite) {
        snprintf(why, whylen, "%.300s holds this study computed by another build of adhere (%s): its rows are not "
                 "mixed with this build's; give a new -o to keep them, or --overwrite to run the study again from "
                 "scratch there (" OVERWRITE_REMOVES ")", path, ids);
        return -1;
    }
    if (!st->cfg->output.quiet)
        adh_sayf("note: %s holds this study computed by another build of adhere (%s): --overwrite: "
                 OVERWRITE_REMOVES "; the study runs again from scratch", path, ids);
    return adh_outdir_clear(od, why, whylen) == 0 ? 0 : -1;
}

/* Another study in od (prev, read with its configuration) whose runs.tsv
 * holds results: refused without --overwrite (-1 with why), naming what
 * differs. Its fingerprint is its scene's whole text: an edited comment
 * cleared a study of hours without a word; -1 too when its runs.tsv
 * cannot be read. 0 when it may be cleared. */
static int other_study(const cli_study *st, const cli_study *prev, adh_outdir *od, char *why, size_t whylen)
{
    if (st->cfg->output.overwrite)
        return 0;
    cli_studyrow *rows = calloc(prev->nruns ? prev->nruns : 1, sizeof *rows);
    size_t cut;
    char msg[1024] = "out of memory for its rows", diff[700];
    long n = rows ? cli_study_read_rows(prev, adh_outdir_fd(od), adh_outdir_path(od), rows, &cut, msg, sizeof msg) : -1;
    if (rows)
        cli_studyrow_clear_all(rows, prev->nruns);
    free(rows);
    if (n < 0) {   /* what it holds cannot be told: it may be results, so nothing is cleared */
        snprintf(why, whylen, "%.300s holds another study whose results could not be read (%.500s): nothing there "
                 "was removed; give a new -o to keep it, or --overwrite to replace it with this study",
                 adh_outdir_path(od), msg);
        return -1;
    }
    if (n == 0)   /* no runs.tsv, or one without a row: nothing of it to lose */
        return 0;
    cli_study_difference(prev, st, diff, sizeof diff);
    snprintf(why, whylen, "%.300s holds another study's results (%ld of its %zu runs; %.300s): give a new -o to keep "
             "them, or --overwrite to replace them with this study's", adh_outdir_path(od), n, prev->nruns, diff);
    return -1;
}

/* An earlier run of this study's shard in od: its rows into rows (1), or
 * nothing (0: od is cleared of another study's files, or of another
 * build's with --overwrite); -1 with why. */
static int resume(const cli_study *st, adh_outdir *od, cli_studyrow *rows, char *why, size_t whylen)
{
    adh_config *old = malloc(sizeof *old);
    if (!old) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    cli_study prev;
    char msg[1024];
    const char *path = adh_outdir_path(od);
    int r = cli_study_read(&prev, old, adh_outdir_fd(od), path, msg, sizeof msg);
    int same = r == 1 && !strcmp(prev.fingerprint, st->fingerprint);
    int other_shard = same && (prev.shard_k != st->shard_k || prev.shard_n != st->shard_n);
    if (other_shard)
        snprintf(why, whylen, "%.800s holds shard %u/%u of this study, not %u/%u: give each shard its own -o "
                 "directory (adhere merge joins them)", path, prev.shard_k, prev.shard_n, st->shard_k, st->shard_n);
    int rebuilt = same && !other_shard && strcmp(prev.numerics, st->numerics) != 0;
    /* this study (its fingerprint line), a line of it unread: a build whose
     * study.tsv this one cannot read (an id of another form, two ids) is
     * another build, not another study to clear */
    int unread = r < 0 && !strcmp(prev.fingerprint, st->fingerprint);
    const char *there = unread ? "unreadable, a line of its study.tsv not of this build's form"
                               : cli_study_numerics_shown(prev.numerics);
    int rc = other_shard ? -1 : rebuilt || unread ? other_build(st, there, od, why, whylen)
           : r == 1 && !same && other_study(st, &prev, od, why, whylen) != 0 ? -1 : 1;
    cli_study_free(&prev);
    free(old);
    if (rc <= 0)
        return rc;
    if (same) {
        size_t cut;
        long n = cli_study_read_rows(st, adh_outdir_fd(od), path, rows, &cut, why, whylen);
        return n < 0 ? -1 : 1;
    }
    if (r < 0 && !st->cfg->output.quiet)
        adh_sayf("note: %s; starting the study afresh", msg);
    return adh_outdir_clear(od, why, whylen) == 0 ? 0 : -1;
}

/* Whether run i's result is complete: its row, and its run-K with its
 * summary where run-K directories are written. */
static int done_before(const study_job *job, size_t i)
{
    if (!cli_studyrow_complete(&job->rows[i]))
        return 0;
    if (!job->run_dirs)
        return 1;
    char name[40];
    struct stat sb;
    snprintf(name, sizeof name, "run-%zu", i + 1);
    if (!adh_outdir_has(job->od, name))
        return 0;
    snprintf(name, sizeof name, "run-%zu/summary.tsv", i + 1);
    return fstatat(adh_outdir_fd(job->od), name, &sb, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(sb.st_mode);
}

/* runs.tsv rewritten with the rows kept (a row cut by a kill goes), then
 * opened for the rows to come. 0, or -1 with why. */
typedef struct kept_rows {
    const cli_study *st;
    const cli_studyrow *rows;
} kept_rows;

static int kept_table(FILE *f, const void *ctx)
{
    const kept_rows *k = ctx;
    cli_study_rows_head(f, k->st);
    for (size_t i = 0; i < k->st->nruns; i++)
        if (k->rows[i].done)
            cli_studyrow_write(f, k->st->cfg, &k->rows[i]);
    return 0;
}

static int open_rows(study_job *job, char *why, size_t whylen)
{
    kept_rows k = { job->st, job->rows };
    if (adh_outdir_write(job->od, "runs.tsv", kept_table, &k, why, whylen) != 0)
        return -1;
    job->rows_fd = adh_outdir_append(job->od, "runs.tsv", why, whylen);
    return job->rows_fd < 0 ? -1 : 0;
}

/* ---- the drives to step ---------------------------------------------------- */

static const unsigned *by_group;   /* qsort's comparison reads it: one study at a time */

static int group_order(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    if (by_group[x] != by_group[y])
        return by_group[x] < by_group[y] ? -1 : 1;
    return (x > y) - (x < y);
}

/* This shard's drives with a run not done, those of one grid together
 * (a kernel serves them in a row); in todo, how many. The distinct grids'
 * specifications (up to max) go into grids, their number into *ngrids. */
static size_t drives_to_step(study_job *job, size_t *todo, adh_run_spec *grids, size_t max, size_t *ngrids)
{
    const cli_study *st = job->st;
    size_t n = 0, members[ADH_MAX_TURNS];
    unsigned *group = malloc(st->ndrives * sizeof *group);
    *ngrids = 0;
    for (size_t u = st->shard_k - 1; u < st->ndrives; u += st->shard_n) {
        size_t m = adh_sweep_drive_runs(job->cfg, u, members), left = 0;
        for (size_t j = 0; j < m; j++)
            left += !job->rows[members[j]].done;
        if (!left)
            continue;
        adh_run_spec ds;
        adh_sweep_drive_spec(job->cfg, u, &ds);
        size_t g = 0;
        while (g < *ngrids && !adh_config_same_grid(&grids[g], &ds))
            g++;
        if (g == *ngrids && g < max)
            grids[(*ngrids)++] = ds;
        if (group)
            group[u] = (unsigned)g;
        todo[n++] = u;
    }
    /* drives of one grid in a row, each grid's in drive order */
    by_group = group;
    if (group)
        qsort(todo, n, sizeof *todo, group_order);
    free(group);
    return n;
}

/* ---- the study ------------------------------------------------------------- */

/* The kernels the runs hold at once fit in memory: each distinct grid's
 * estimate, the largest times the kernels alive at once. 0, or -1 with why. */
static int kernels_fit(const adh_config *cfg, const adh_run_spec *grids, size_t ngrids, int jobs, size_t keep,
                       char *why, size_t whylen)
{
    double most = 0;
    for (size_t g = 0; g < ngrids; g++) {
        /* as a single run counts them: in physical time too */
        unsigned solvers = adh_budget_solvers(&grids[g], (unsigned)jobs, 0);
        if (adh_budget_check(&grids[g], solvers, why, whylen) != 0)
            return -1;
        most = fmax(most, adh_budget_bytes(&grids[g], solvers));
    }
    size_t alive = ngrids < (size_t)jobs + keep ? ngrids : (size_t)jobs + keep;
    double have = adh_budget_machine_bytes();
    if (ngrids > 1 && most * (double)alive > have) {
        snprintf(why, whylen, "the study's runs have %zu grids: %zu kernels at once need about %.3g GB, there is "
                 "%.3g GB; give fewer jobs (--jobs) or shard the study", ngrids, alive, most * (double)alive / 1e9,
                 have / 1e9);
        return -1;
    }
    return 0;
}

/* The runs of this shard that did not end (a signal came first): rows
 * that say interrupted, and their tables where run-K directories are. */
static size_t mark_interrupted(study_job *job)
{
    const cli_study *st = job->st;
    size_t members[ADH_MAX_TURNS], missing = 0;
    for (size_t u = st->shard_k - 1; u < st->ndrives; u += st->shard_n) {
        size_t m = adh_sweep_drive_runs(job->cfg, u, members);
        for (size_t j = 0; j < m; j++) {
            size_t i = members[j];
            if (job->rows[i].done) {   /* ended, or stopped mid-way (its tables say so) */
                /* a run whose figures alone a signal stopped is no missing run */
                missing += !strcmp(job->rows[i].status, "interrupted") && !job->whole[i];
                continue;
            }
            missing++;
            cli_studyrow_empty(&job->rows[i], job->cfg, i, "interrupted");
            if (!job->od || !job->run_dirs)
                continue;
            char name[32], why[1024];
            adh_run none;
            adh_run_spec spec;
            adh_run_init(&none);
            none.interrupted = 1;
            adh_config_sweep_run(job->cfg, i, &spec);
            snprintf(name, sizeof name, "run-%zu", i + 1);
            adh_outdir *dir = adh_outdir_sub(job->od, name, why, sizeof why);
            cli_runout_said said;
            int t = dir ? cli_runout_tables(job->cfg, i, &spec, &none, NULL, NULL, ADH_SUCCESS, dir, &said) : CLI_EXIT_USAGE;
            if (!dir)
                adh_say(why);
            job->exit_status = cli_runout_worse(job->exit_status, t);
            adh_outdir_close(dir);
        }
    }
    return missing;
}

/* The exit status of a row from an earlier run of the study. */
static int row_exit(const adh_config *cfg, const cli_studyrow *row)
{
    static const char *const fine[] = { "success", "no contact", "not separated", "unresolved" };
    if (!strcmp(row->status, "interrupted"))
        return CLI_EXIT_INTERRUPTED;
    if (!strcmp(row->status, "unconverged"))
        return cfg->output.allow_unconverged ? CLI_EXIT_OK : CLI_EXIT_SOLVER;
    for (size_t k = 0; k < sizeof fine / sizeof fine[0]; k++)
        if (!strcmp(row->status, fine[k]))
            return CLI_EXIT_OK;
    return !strcmp(row->status, "output incomplete") ? CLI_EXIT_PLOT : CLI_EXIT_SOLVER;
}

double cli_sweep_static_hysteresis(const adh_config *cfg, cli_kcache *kc, int *resolved)
{
    *resolved = 0;
    if (!adh_sweep_fig7_panel(cfg) || !cfg->output.plot || cli_interrupt_signal())
        return NAN;
    adh_run_spec rs;
    adh_config_sweep_run(cfg, 0, &rs);
    const adh_grid *g;
    const adh_kernel *k;
    int st = cli_kcache_get(kc, &rs, &g, &k);
    adh_run ref;
    adh_run_init(&ref);
    adh_static_result res;
    char why[1024];
    adh_ready_phase("reference");
    if (st == ADH_SUCCESS) {
        st = cli_static_reference(&rs, g, k, &ref, &res, resolved, why, sizeof why);
        cli_kcache_put(kc, k);
        if (!*resolved)
            adh_sayf("warning: Figure 7's equilibrium line comes from a static curve the grid does not "
                     "resolve: %s", why);
    }
    double h = st == ADH_SUCCESS && !ref.interrupted ? cli_tables_static_hysteresis(&ref, &rs.mat) : NAN;
    char stopped[CLI_TABLES_STOPPED_LEN];
    if (st != ADH_SUCCESS && st != ADH_EINTR && !ref.interrupted)
        adh_sayf("the static curve for Figure 7's equilibrium line failed: %s",
                 cli_tables_stopped(cfg, &ref, st, stopped, sizeof stopped));
    adh_run_free(&ref);
    return h;
}

/* The whole study's table and figure (not a shard's: adhere merge writes those). */
static void study_outputs(study_job *job, size_t missing)
{
    const adh_config *cfg = job->cfg;
    size_t n = job->st->nruns;
    char partial[224] = "", why[1024];
    int resolved;
    double hyst = cli_sweep_static_hysteresis(cfg, job->kc, &resolved);
    int sig = cli_interrupt_signal();   /* also one that stopped the static curve */
    if (missing)
        snprintf(partial, sizeof partial, "interrupted by signal %d: %zu of %zu runs finished; the others say interrupted",
                 sig, n - missing, n);
    else if (sig && isnan(hyst) && adh_sweep_fig7_panel(cfg) && cfg->output.plot)
        snprintf(partial, sizeof partial, "interrupted by signal %d: every run finished, its tables whole; not the "
                 "static curve for Figure 7's line", sig);
    else if (sig)
        snprintf(partial, sizeof partial, "interrupted by signal %d while the figures were drawn: every run finished, "
                 "its tables whole; those whose figures were not drawn say interrupted", sig);
    cli_studyrow_sweep t = { cfg, job->rows, partial, job->run_dirs, hyst, resolved };
    if (!job->od) {
        cli_studyrow_table(stdout, &t);
        return;
    }
    if (adh_outdir_write(job->od, "sweep.tsv", cli_studyrow_table, &t, why, sizeof why) != 0) {
        adh_say(why);
        job->exit_status = cli_runout_worse(job->exit_status, CLI_EXIT_USAGE);
        return;
    }
    if (!cfg->output.plot || job->exit_status != CLI_EXIT_OK || sig || adh_sweep_plot_kind(&cfg->sweep) == ADH_SWEEP_PLOT_NONE)
        return;
    int fd = adh_outdir_fd(job->od);
    cli_figures_curves curves = { &fd, 1 };
    if (cli_figures_sweep(cfg, job->rows, n, &curves, hyst, job->od, why, sizeof why) != 0) {
        adh_sayf("sweep plot not written: %s", why);
        job->exit_status = cli_runout_worse(job->exit_status, CLI_EXIT_PLOT);
    }
}

/* The last line: how long, how many, where. */
static void closing(const study_job *job, double t_start, size_t missing)
{
    const adh_config *cfg = job->cfg;
    const cli_study *st = job->st;
    char t[32];
    if (missing || cli_interrupt_signal()) {
        adh_sayf("interrupted by signal %d: %zu of %zu runs finished; %s says which (# PARTIAL)%s",
                 cli_interrupt_signal(), cli_study_shard_runs(st) - missing, cli_study_shard_runs(st),
                 st->shard_n > 1 ? "runs.tsv" : job->od ? "sweep.tsv and each run's summary.tsv" : "sweep.tsv",
                 job->od ? "; run it again to step the rest" : "");
        return;
    }
    if (job->exit_status != CLI_EXIT_OK || cfg->output.quiet)
        return;
    cli_progress_duration(adh_clock_seconds() - t_start, t, sizeof t);
    const char *out = job->od ? adh_outdir_path(job->od) : NULL;
    size_t before = cli_study_shard_runs(st) - job->total;
    char again[96] = "";
    if (before)
        snprintf(again, sizeof again, " (%zu done before, kept)", before);
    if (!out)
        adh_sayf("done in %s: %zu runs; sweep.tsv went to standard output", t, st->nruns);
    else if (st->shard_n > 1)
        adh_sayf("done in %s: shard %u of %u, %zu of the study's %zu runs%s, in %s/runs.tsv; "
                 "adhere merge joins the shards", t, st->shard_k, st->shard_n, cli_study_shard_runs(st), st->nruns,
                 again, out);
    else
        adh_sayf("done in %s: %zu runs%s; sweep.tsv%s in %s/%s", t, st->nruns, again,
                 cfg->output.plot && adh_sweep_plot_kind(&cfg->sweep) != ADH_SWEEP_PLOT_NONE ? " and the sweep's figure" : "",
                 out, job->run_dirs ? ", each run's tables in run-1 ... run-N" : "");
}

/* --force on a grid some runs do not resolve: said even with -q (the
 * first ten). */
static void warn_unresolved(const study_job *job)
{
    size_t members[ADH_MAX_TURNS], said = 0, more = 0;
    for (size_t a = 0; a < job->ntodo; a++) {
        size_t m = adh_sweep_drive_runs(job->cfg, job->todo[a], members);
        for (size_t j = 0; j < m; j++) {
            adh_run_spec rc;
            adh_config_sweep_run(job->cfg, members[j], &rc);
            if (rc.mode == ADH_MODE_RIGID || job->rows[members[j]].done)
                continue;
            adh_grid_report gr;
            adh_config_grid_report(&rc, &gr);
            if (gr.resolved)
                continue;
            if (said++ >= 10) {
                more++;
                continue;
            }
            char msg[512];
            adh_grid_unresolved_sentence(&gr, msg, sizeof msg);
            adh_sayf("warning: run %zu: %s (--force; its summary.tsv: resolved 0)", members[j] + 1, msg);
        }
    }
    if (more)
        adh_sayf("warning: and %zu more runs on grids that do not resolve them (sweep.tsv: resolved 0)", more);
}

/* The first drive's kernel, built before any run starts (a large one takes
 * seconds; a signal then stops the study with nothing computed). 0, or an
 * exit status. */
static int first_kernel(study_job *job)
{
    if (!job->ntodo)
        return 0;
    adh_run_spec ds;
    adh_sweep_drive_spec(job->cfg, job->todo[0], &ds);
    if (ds.mode == ADH_MODE_RIGID)
        return 0;
    const adh_grid *g;
    const adh_kernel *k;
    int st = cli_kcache_get(job->kc, &ds, &g, &k);
    if (st == ADH_SUCCESS) {
        cli_kcache_put(job->kc, k);
        return 0;
    }
    if (st == ADH_EINTR)
        adh_sayf("interrupted by signal %d while building the %zu-node kernel: nothing computed, no "
                 "table written", cli_interrupt_signal(), adh_config_nodes(&ds));
    else
        adh_sayf("out of memory building the %zu-node kernel", adh_config_nodes(&ds));
    return st == ADH_EINTR ? cli_interrupt_exit() : CLI_EXIT_SOLVER;
}

/* A drive's expected cost, in a unit its sweep shares (one mode). */
static double drive_cost(const adh_run_spec *ds)
{
    if (ds->mode == ADH_MODE_RELAX)
        return adh_plan_iterations(ds);
    if (ds->mode == ADH_MODE_TIME && ds->time.sls) {
        adh_plan_time_cost c;
        adh_plan_time_steps(ds, &c);
        /* a step priced as the integrator that runs it (the Rothe steps'
         * against IDAS's: c.work), as --plan prices it (estimatetime.c) */
        if (c.steps > 0 && isfinite(c.steps * c.work))
            return c.steps * c.work;
    }
    /* an elastic sphere in time: its static curve's points, as --plan
     * counts them, so that a sweep of the material weighs it beside the
     * standard linear solid's steps, not as one of them (0 % and 2 h 14 min
     * left after the elastic half of a 2 s study) */
    adh_grid *g = ds->mode == ADH_MODE_TIME ? adh_config_grid_alloc(ds) : NULL;
    double points = g ? adh_plan_path_points(ds, g, NULL) : 1.0;
    adh_grid_free(g);
    return points > 0 && isfinite(points) ? points : 1.0;
}

/* The threads: a run per core. */
static void step_all(study_job *job, int jobs)
{
    pthread_t *threads = calloc((size_t)jobs, sizeof *threads);
    /* each drive's expected cost, for the time left: its iterations in
     * relaxation (adh_plan_iterations), its integrator steps in physical
     * time (adh_plan_time_steps: a sweep of speeds over decades costs
     * 3-10 times more at its fast end), an elastic one its static curve's
     * points (drive_cost), else one each; O(drives) a
     * progress line, so for a few thousand drives at most */
    job->jobs = jobs;
    job->eta = job->ntodo <= ETA_MAX_DRIVES ? calloc(job->ntodo ? job->ntodo : 1, sizeof *job->eta) : NULL;
    for (size_t a = 0; job->eta && a < job->ntodo; a++) {
        adh_run_spec ds;
        adh_sweep_drive_spec(job->cfg, job->todo[a], &ds);
        job->eta[a].cost = drive_cost(&ds);
    }
    int started = 0;
    if (jobs > 1 && openblas_set_num_threads)
        openblas_set_num_threads(1);
    job->t0 = adh_clock_seconds();
    for (int t = 0; threads && t < jobs; t++) {
        if (pthread_create(&threads[t], NULL, worker, job) != 0)
            break;
        started++;
    }
    if (!started)   /* no thread at all: one after another, here */
        worker(job);
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    free(threads);
    free(job->eta);
    job->eta = NULL;
}

/* Rows, the drives to step, runs.tsv: the study ready to step. 0, or an exit status. */
static int prepare(study_job *job, size_t *todo, adh_run_spec *grids, size_t *ngrids, char *why, size_t whylen)
{
    const cli_study *st = job->st;
    if (job->od) {
        if (resume(st, job->od, job->rows, why, whylen) < 0)
            return CLI_EXIT_USAGE;
        for (size_t i = 0; i < st->nruns; i++)
            job->rows[i].done = job->rows[i].done && done_before(job, i);
        if (cli_study_write(st, job->od, why, whylen) != 0 || open_rows(job, why, whylen) != 0)
            return CLI_EXIT_USAGE;
        for (size_t i = 0; i < st->nruns; i++)
            if (job->rows[i].done)
                job->exit_status = cli_runout_worse(job->exit_status, row_exit(job->cfg, &job->rows[i]));
    }
    job->ntodo = drives_to_step(job, todo, grids, ADH_PLAN_MAX_KERNELS, ngrids);
    size_t members[ADH_MAX_TURNS];
    for (size_t a = 0; a < job->ntodo; a++) {
        size_t m = adh_sweep_drive_runs(job->cfg, todo[a], members);
        for (size_t j = 0; j < m; j++)
            job->total += !job->rows[members[j]].done;
    }
    return 0;
}

int cli_sweep_main(cli_options *cli, adh_outdir *od)
{
    const adh_config *cfg = &cli->cfg;
    double t_start = adh_clock_seconds();
    char why[1024];
    if (cfg->spec.mode == ADH_MODE_STATIC && adh_sweep_axis_of(&cfg->sweep, "solver.eps")) {
        /* every run would be the same equilibrium curve */
        adh_sayf("a sweep of eps in mode = static would compute the same curve %zu times: "
                 "eps is the relaxation's convergence parameter; sweep E or sigma, or use mode = relax",
                 adh_config_nruns(cfg));
        return CLI_EXIT_USAGE;
    }
    /* a study that would not fit the disk or the limits runs not at all */
    static adh_plan plan;
    adh_plan_make(cfg, &plan);
    if (cli_studycost_fits(cfg, &plan, NULL, why, sizeof why) != 0) {
        adh_sayf("refused: %s", why);
        return CLI_EXIT_USAGE;
    }
    cli_study st;
    cli_study_from_cli(&st, cli);
    study_job job = { .cfg = cfg, .st = &st, .od = od, .rows_fd = -1, .exit_status = CLI_EXIT_OK,
                      .run_dirs = od && adh_sweep_run_dirs(&cfg->sweep), .shared = st.ndrives < st.nruns };
    job.rows = calloc(st.nruns, sizeof *job.rows);
    job.whole = calloc(st.nruns, sizeof *job.whole);
    job.todo = calloc(st.ndrives, sizeof *job.todo);
    adh_run_spec *grids = malloc(ADH_PLAN_MAX_KERNELS * sizeof *grids);
    size_t ngrids = 0;
    int rc = !job.rows || !job.whole || !job.todo || !grids ? CLI_EXIT_SOLVER : 0;
    if (rc)
        snprintf(why, sizeof why, "out of memory for %zu runs", st.nruns);
    else
        rc = prepare(&job, job.todo, grids, &ngrids, why, sizeof why);
    int jobs = adh_plan_jobs(cfg);
    if ((size_t)jobs > job.ntodo)
        jobs = job.ntodo ? (int)job.ntodo : 1;
    /* one idle kernel kept: the drives of one grid come in a row */
    if (!rc && kernels_fit(cfg, grids, ngrids, jobs, 1, why, sizeof why) != 0)
        rc = CLI_EXIT_USAGE;
    if (!rc && !(job.kc = cli_kcache_new(1))) {
        snprintf(why, sizeof why, "out of memory");
        rc = CLI_EXIT_SOLVER;
    }
    free(grids);
    if (rc) {
        adh_say(why);
        if (job.rows_fd >= 0)
            adh_outdir_log_close(od, "runs.tsv", job.rows_fd);
        cli_studyrow_clear_all(job.rows, st.nruns);
        free(job.rows), free(job.whole), free(job.todo);
        return rc;
    }
    warn_unresolved(&job);
    cli_interrupt_catch();
    if ((rc = first_kernel(&job)) != 0) {
        cli_interrupt_release();
        adh_outdir_log_close(od, "runs.tsv", job.rows_fd);
        cli_kcache_free(job.kc);
        cli_studyrow_clear_all(job.rows, st.nruns);
        free(job.rows), free(job.whole), free(job.todo);
        return rc;
    }
    pthread_mutex_init(&job.lock, NULL);
    pthread_mutex_init(&job.dirs, NULL);
    adh_ready_phase("sweep");
    step_all(&job, jobs);
    size_t missing = cli_interrupt_signal() ? mark_interrupted(&job) : 0;
    if (job.rows_fd >= 0)
        adh_outdir_log_close(od, "runs.tsv", job.rows_fd);
    if (st.shard_n == 1)
        study_outputs(&job, missing);
    if (cli_interrupt_signal())
        job.exit_status = cli_runout_worse(job.exit_status, cli_interrupt_exit());
    cli_interrupt_release();
    closing(&job, t_start, missing);
    pthread_mutex_destroy(&job.lock);
    pthread_mutex_destroy(&job.dirs);
    cli_kcache_free(job.kc);
    cli_studyrow_clear_all(job.rows, st.nruns);
    free(job.rows), free(job.whole), free(job.todo);
    return job.exit_status;
}
