#include "cli/studycost.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/statvfs.h>

#include "adhere/clock.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "plot/outdir.h"
#include "cli/progress.h"

#define PILOT_NODES 150
#define PILOT_SECONDS 3.0

/* The pilot stops itself after PILOT_SECONDS. */
static int pilot_clock(const adh_obs *row, const adh_run *run, void *ctx)
{
    return adh_clock_seconds() - *(const double *)ctx > PILOT_SECONDS;
}

/* spec on a coarse uniform grid of the same radius (paper kernel, dense). */
static void coarse(adh_run_spec *spec)
{
    if (spec->mode == ADH_MODE_RIGID || adh_config_nodes(spec) <= PILOT_NODES)
        return;
    double rmax = spec->grid.use.graded ? adh_config_rings(spec).rmax
                                        : (double)spec->grid.use.nodes * adh_config_spacing(spec);
    adh_grid_spec *u = &spec->grid.use;
    u->graded = 0;
    u->nodes = PILOT_NODES;
    u->spacing = rmax / PILOT_NODES;
    u->kernel = ADH_KERNEL_PAPER;
    u->storage = ADH_STORAGE_DENSE;
}

/* CPU seconds a kernel product takes on spec's grid (NAN: not built). */
static double product_seconds(const adh_run_spec *spec)
{
    int st;
    adh_grid *g = adh_config_grid_alloc(spec);
    adh_kernel *k = g ? adh_config_kernel_alloc(spec, g, &st) : NULL;
    double *v = g ? calloc(3 * g->n, sizeof *v) : NULL;
    double t = NAN;
    if (k && v) {
        for (size_t i = 0; i < g->n; i++)
            v[i] = 1.0 / (1.0 + (double)i);
        int reps = 0;
        double t0 = adh_clock_cpu_seconds();
        do
            adh_kernel_apply(k, v, v + g->n, v + 2 * g->n);
        while (++reps < 1000 && adh_clock_cpu_seconds() - t0 < 0.05);
        t = (adh_clock_cpu_seconds() - t0) / reps;
    }
    free(v);
    adh_kernel_free(k);
    adh_grid_free(g);
    return t;
}

typedef struct pilot {
    size_t rows, iterations, planned;
    double seconds;
    int cut;
} pilot;

/* Drive u of cfg on the coarse grid, for at most PILOT_SECONDS. */
static void fly(const adh_config *cfg, const adh_plan *p, size_t u, const adh_run_spec *grid, pilot *out)
{
    adh_run_spec spec;
    adh_sweep_drive_spec(cfg, u, &spec);
    out->planned += adh_plan_steps(p, &spec);
    spec.grid = grid->grid;
    spec.proto.nprofiles = 0;
    /* the steps alone: the dwells are priced apart, by their iterations
     * (a pilot cut in a long dwell counted it as one step of millions of
     * iterations, one cut before its turn not at all) */
    spec.proto.dwell = 0;
    adh_grid *g = spec.mode == ADH_MODE_RIGID ? NULL : adh_config_grid_alloc(&spec);
    int st = ADH_SUCCESS;
    adh_kernel *k = g ? adh_config_kernel_alloc(&spec, g, &st) : NULL;
    adh_run run;
    adh_run_init(&run);
    /* stopped by the wall clock (the plan's own wait), priced in CPU
     * seconds, as --plan's other times: on a shared machine the wall
     * clock times the other jobs too */
    double t0 = adh_clock_seconds(), c0 = adh_clock_cpu_seconds();
    if (spec.mode == ADH_MODE_RIGID)
        adh_runner_rule(&adh_rule_rigid, NULL, NULL, &spec.mat, NULL, &spec.proto, pilot_clock, &t0, &run);
    else if (k)
        adh_runner_rule(&adh_rule_relax, g, k, &spec.mat, &spec.relax, &spec.proto, pilot_clock, &t0, &run);
    out->rows += run.nrows;
    out->iterations += run.iterations;
    out->seconds += adh_clock_cpu_seconds() - c0;
    out->cut |= run.interrupted;
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
}

void cli_studycost_time(const adh_config *cfg, const adh_plan *p, cli_studycost *e)
{
    memset(e, 0, sizeof *e);
    e->seconds = NAN;
    e->jobs = p->jobs;
    adh_run_spec real, small;
    adh_sweep_drive_spec(cfg, 0, &real);
    /* no drive steps to count: in physical time the integrator chooses
     * its own, and the static curve's points and their Newton steps
     * follow its folds, which a coarse pilot grid multiplies (the default
     * scene's study of two A: 15 s planned, 0.7 s run) */
    if (real.mode == ADH_MODE_TIME || real.mode == ADH_MODE_STATIC) {
        e->timed = 1;
        return;
    }
    small = real;
    coarse(&small);
    e->pilot_nodes = real.mode == ADH_MODE_RIGID || adh_config_same_grid(&real, &small) ? 0 : adh_config_nodes(&small);
    pilot pl = { 0 };
    fly(cfg, p, 0, &small, &pl);
    if (p->drives > 1)
        fly(cfg, p, p->drives - 1, &small, &pl);
    e->pilot_cut = pl.cut;
    if (!pl.rows || !pl.planned)
        return;
    /* the pilot's share of its planned steps (unloading ends at the jump
     * out, mostly before the start) carries over to every drive */
    double steps = (double)(p->loading_steps + p->unloading_steps) * (pl.cut ? 1.0 : (double)pl.rows / (double)pl.planned);
    double scale = 1;
    if (real.mode != ADH_MODE_RIGID && !adh_config_same_grid(&real, &small))
        scale = product_seconds(&real) / product_seconds(&small);
    if (!isfinite(scale))
        return;
    double per_row = pl.seconds / (double)pl.rows * scale;
    e->per_step = (double)pl.iterations / (double)pl.rows;
    e->t_iter = pl.iterations ? pl.seconds / (double)pl.iterations * scale : NAN;
    /* each turn's dwell: its iterations, each as the pilot's cost an
     * iteration (a dwell's iteration is a relaxation's, at a fixed h0) */
    e->dwell_iterations = p->dwell_iterations;
    double dwell = e->dwell_iterations > 0 ? e->dwell_iterations * e->t_iter : 0.0;
    double parallel = p->drives < (size_t)p->jobs ? (double)p->drives : (double)p->jobs;
    e->seconds = (steps * per_row + dwell) / (parallel > 0 ? parallel : 1);
}

int cli_studycost_print(FILE *f, const cli_studycost *e)
{
    char t[32];
    if (e->timed || isnan(e->seconds))   /* the plan's own line says why */
        return -1;
    cli_progress_duration(e->seconds, t, sizeof t);
    fprintf(f, "time: about %s on %d core%s, from a pilot of the study's first and last drives%s%s", t, e->jobs,
            e->jobs == 1 ? "" : "s", e->pilot_nodes ? " on a coarse grid" : "", e->pilot_cut ? ", cut at 3 s each" : "");
    if (e->per_step > 0)
        fprintf(f, " (%.0f iterations a step, %.3g ms an iteration here)", e->per_step, e->t_iter * 1e3);
    fprintf(f, " times the plan's steps of every drive");
    if (e->dwell_iterations > 0)
        fprintf(f, ", and the dwells' %.3g iterations at the turns at that cost an iteration", e->dwell_iterations);
    fprintf(f, "; a guide within a factor of about 3\n");
    return 0;
}

/* The file system of dir, or of its nearest parent that exists. */
static int fs_of(const char *dir, struct statvfs *vfs)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s", dir[0] ? dir : ".");
    for (;;) {
        if (statvfs(path, vfs) == 0)
            return 0;
        char *slash = strrchr(path, '/');
        if (errno != ENOENT || !slash)
            return statvfs(".", vfs);
        if (slash == path)
            return statvfs("/", vfs);
        *slash = '\0';
    }
}

int cli_studycost_fits(const adh_config *cfg, const adh_plan *p, FILE *f, char *why, size_t whylen)
{
    double bytes = p->bytes;
    if (p->nruns > ADH_SWEEP_MAX_RUNS) {
        snprintf(why, whylen, "the study has %zu runs: at most %d", p->nruns, ADH_SWEEP_MAX_RUNS);
        return -1;
    }
    if (!cfg->output.dir[0]) {
        if (f)
            fprintf(f, "disk: sweep.tsv to standard output (about %.3g MB)\n", bytes / 2e6);
        return 0;
    }
    struct statvfs vfs;
    if (fs_of(cfg->output.dir, &vfs) != 0)
        return 0;   /* the directory's own error comes when it is opened */
    double free_bytes = (double)vfs.f_bavail * (double)vfs.f_frsize;
    char dir[1024];
    adh_outdir_escape(cfg->output.dir, dir, sizeof dir);
    double inodes = p->run_dirs ? (double)p->nruns * 8 : 8;
    if (f)
        fprintf(f, "disk: about %.3g MB written (%s), %.3g GB free there\n", bytes / 1e6,
                p->run_dirs ? "the tables and a directory of each run" : "the tables", free_bytes / 1e9);
    if (bytes > free_bytes) {
        snprintf(why, whylen, "the study writes about %.3g GB into %.1000s, whose file system has %.3g GB free: "
                 "free space, choose another -o, or write fewer run-K directories (--run-dirs=no)", bytes / 1e9,
                 dir, free_bytes / 1e9);
        return -1;
    }
    if (vfs.f_files && inodes > (double)vfs.f_favail) {
        snprintf(why, whylen, "the study makes about %.0f files in %.1000s, whose file system has %.0f left: "
                 "--run-dirs=no writes a row for each run instead", inodes, dir, (double)vfs.f_favail);
        return -1;
    }
    struct rlimit rl;
    double table = ADH_PLAN_ROW_BYTES * (double)p->nruns;
    if (getrlimit(RLIMIT_FSIZE, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && table > (double)rl.rlim_cur) {
        snprintf(why, whylen, "sweep.tsv would be about %.3g MB, past the file size limit of %.3g MB (ulimit -f)",
                 table / 1e6, (double)rl.rlim_cur / 1e6);
        return -1;
    }
    return 0;
}
