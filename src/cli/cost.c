#include "cli/cost.h"
#include "plot/say.h"
#include "adhere/cycle.h"
#include "adhere/clock.h"

#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "adhere/runner.h"
#include "adhere/static.h"
#include "adhere/grid.h"
#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "cli/estimate.h"
#include "cli/exit.h"
#include "scene/text.h"
#include "cli/interrupt.h"
#include "util/ready.h"
#include "cli/progress.h"
#include "cli/static.h"
#include "cli/tables.h"
#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "plot/outdir.h"
#include "plot/plot.h"
#include "plot/session.h"
#include "scene/budget.h"
#include "scene/plan.h"

char *openblas_get_config(void) __attribute__((weak));   /* none in the reference BLAS */
static const char *blas_config(void)
{
    return openblas_get_config ? openblas_get_config() : "reference BLAS";
}

#define MAX_EPS 16
#define MAX_NODES 16

typedef struct cost_run {
    double eps;
    size_t nodes;
    adh_kernel_type kernel;
    int ran;              /* 0: never started (interrupted first) */
    int status;
    double seconds, kernel_seconds;
    size_t iterations, steps, unconverged;
    double pulloff, jump_in, hysteresis, a_turn;
    double err[4];        /* against the most accurate run */
    double err_static[4]; /* pull-off, jump-in, hysteresis and a at the turn against the static curve */
    char reason[CLI_TABLES_REASON_LEN];   /* why a run that stopped on an error stopped (summary.tsv's stop_reason); "" else */
    int fault;            /* a finished run: 1 the surfaces never touched, 2 never separated (summary.tsv's words) */
} cost_run;

/* The static curve every eps should approach, solved on this thread while
 * the workers run: the finest grid with the exact kernel, marked where that
 * grid does not resolve it (its errors are then no verdict). */
typedef struct cost_ref {
    adh_run_spec spec;
    adh_static_result res;
    int status;
    int resolved;
    char why[512];       /* why the grid does not resolve it; "" when it does */
    char stopped[CLI_TABLES_STOPPED_LEN];   /* "STATUS: REASON" of a curve that stopped on an error; "" else */
    double hysteresis;   /* J; NAN when the curve failed */
    double a_turn;       /* m; NAN when the curve failed */
} cost_ref;

typedef struct cost_job {
    const adh_config *cfg;
    cost_run *runs;
    size_t n, next, done;
    size_t base;              /* the smallest N, whose grid a given spacing is (cost_spacing) */
    double t0;                /* when the runs began */
    pthread_mutex_t lock;
    const cost_ref *ref;      /* the static curve, once solved */
    char partial[160];        /* why the report is incomplete; "" when it is not */
} cost_job;



static void measure(cost_run *cr, const adh_run *run)
{
    const adh_turn_result *t = adh_run_main_turn(run);
    cr->seconds = run->seconds;
    cr->iterations = run->iterations;
    cr->steps = run->nrows;
    cr->unconverged = run->unconverged;
    cr->pulloff = t ? t->pulloff_F : NAN;
    cr->a_turn = t ? t->a_turn : NAN;
    cr->jump_in = run->jump_in_h0;
    cr->hysteresis = adh_cycle_run_hysteresis(run);
}

/* The spacing of the grid of n nodes when the coarsest, of base nodes, has
 * the spacing s (--spacing): every N covers its radius, so a larger N
 * refines the same domain and the largest is the reference, a finer grid,
 * not a wider one; each grid as fine as s or finer. Without s (NAN) each
 * N's default grid, which keeps the radius already. */
static double cost_spacing(double s, size_t n, size_t base)
{
    return isnan(s) || n == base ? s : s * (double)base / (double)n;
}

/* Run 0's spec on the uniform grid of n nodes in mode (of the radius of
 * the coarsest, of base nodes), with the operator that mode takes there
 * unless one was given (adh_config_storage_for): the cost of what a run of
 * that N costs by default. */
static adh_run_spec cost_spec(const adh_config *cfg, size_t n, size_t base, adh_mode mode)
{
    adh_run_spec c;
    adh_config_sweep_run(cfg, 0, &c);
    c.mode = mode;
    c.grid.use.nodes = n;
    c.grid.use.spacing = cost_spacing(c.grid.use.spacing, n, base);
    c.grid.use.graded = 0;
    c.grid.chosen = 0;
    c.grid.chosen_h2 = 0;
    c.grid.use.storage = adh_config_storage_for(&c, mode);
    return c;
}

static void *worker(void *arg)
{
    cost_job *job = arg;
    for (;;) {
        pthread_mutex_lock(&job->lock);
        size_t i = job->next < job->n && !cli_interrupt_signal() ? job->next++ : job->n;
        pthread_mutex_unlock(&job->lock);
        if (i >= job->n)
            break;
        cost_run *cr = &job->runs[i];
        cr->ran = 1;
        adh_run_spec c = cost_spec(job->cfg, cr->nodes, job->base, ADH_MODE_RELAX);
        c.relax.eps = cr->eps;
        c.grid.use.kernel = cr->kernel;
        double t0 = adh_clock_seconds();
        adh_grid *g = adh_grid_alloc(c.grid.use.nodes, adh_config_spacing(&c));
        int kst = ADH_ENOMEM;
        adh_kernel *k = g ? adh_config_kernel_alloc(&c, g, &kst) : NULL;
        cr->kernel_seconds = adh_clock_seconds() - t0;
        adh_run run;
        adh_run_init(&run);
        cr->status = k ? adh_runner_rule(&adh_rule_relax, g, k, &c.mat, &c.relax, &c.proto, cli_interrupt_step, NULL, &run) : kst;
        if (kst == ADH_EINTR)
            run.interrupted = 1;
        if (run.interrupted)
            cr->status = ADH_CONTINUE;
        measure(cr, &run);
        if (cr->status == ADH_SUCCESS) {   /* a turn above the jump-in: its numbers are no cycle's */
            adh_derived d;
            char w[8];
            adh_material_derive(&c.mat, &d);
            cr->fault = !adh_run_touched(&run, d.h_star, w, sizeof w) ? 1 : !adh_run_separated(&run, w, sizeof w) ? 2 : 0;
        }
        if (cr->status != ADH_CONTINUE && cr->status == run.status)
            cli_tables_stop_reason_for(job->cfg, CLI_ADVICE_COST, &run, cr->reason, sizeof cr->reason);
        adh_run_free(&run);
        adh_kernel_free(k);
        adh_grid_free(g);
        pthread_mutex_lock(&job->lock);
        job->done++;
        if (!job->cfg->output.quiet) {
            char pr[64];
            cli_progress_text(job->done, job->n, adh_clock_seconds() - job->t0, pr, sizeof pr);
            adh_sayf("cost run %zu of %zu (N = %zu, %s, eps = %g pm): %.3g s, %zu iterations; "
                     "%zu of %zu done, %s", i + 1, job->n, cr->nodes, adh_kernel_name(cr->kernel), cr->eps * 1e12,
                     cr->seconds, cr->iterations, job->done, job->n, pr);
        }
        /* not hidden by -q, as a study's: the row's numbers end where it stopped */
        if (cr->reason[0])
            adh_sayf("cost run %zu (N = %zu, eps = %g pm) stopped: %s", i + 1, cr->nodes, cr->eps * 1e12,
                     cr->reason);
        /* not hidden by -q: the row's error then measures the cap, not eps */
        if (cr->unconverged)
            adh_sayf("warning: cost run %zu (N = %zu, eps = %g pm): %zu of %zu steps reached the "
                     "iteration cap (%zu) without meeting eps", i + 1, cr->nodes, cr->eps * 1e12, cr->unconverged,
                     cr->steps, c.relax.max_iter);
        pthread_mutex_unlock(&job->lock);
    }
    return NULL;
}

static int parse_lists(const cli_options *cli, double *eps, size_t *neps, size_t *nodes, size_t *nnodes, char *why, size_t n)
{
    const char *el = cli->cost_eps[0] ? cli->cost_eps : "2pm,1pm,0.5pm,0.2pm,0.1pm";
    const char *nl = cli->cost_nodes[0] ? cli->cost_nodes : "500,1000,2000";
    char buf[256], msg[256] = "", *save = NULL;
    *neps = *nnodes = 0;
    if (adh_list_decimal_comma(el, ADH_Q_LENGTH, msg, sizeof msg) != ADH_SUCCESS) {   /* 0,5pm: 0 m refused, as 0 */
        snprintf(why, n, "--cost-eps: %s", msg);
        return 2;
    }
    snprintf(buf, sizeof buf, "%s", el);
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (*neps == MAX_EPS || adh_parse_quantity(t, ADH_Q_LENGTH, &eps[*neps], msg, sizeof msg) != 0 ||
            !(eps[*neps] > 0 && eps[*neps] < 1e-6)) {
            snprintf(why, n, "--cost-eps: '%s' is not allowed: %s", t,
                     *neps == MAX_EPS ? "at most 16 values" : msg[0] ? msg : "each eps must be above 0 and below 1 um");
            return 2;
        }
        msg[0] = '\0';
        /* a value twice ran its runs twice, and the reference was which? */
        for (size_t j = 0; j < *neps; j++)
            if (fabs(eps[j] - eps[*neps]) <= 1e-12 * eps[j]) {   /* 1pm and 0.001nm: the rounding of units */
                snprintf(why, n, "--cost-eps: '%s' is given twice (the same eps as value %zu): each eps once", t,
                         j + 1);
                return 2;
            }
        (*neps)++;
    }
    save = NULL;
    snprintf(buf, sizeof buf, "%s", nl);
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        long v = 0;
        int bad = *nnodes == MAX_NODES;
        if (!bad && adh_parse_count(t, 0, LONG_MAX, &v, msg, sizeof msg) != 0) {   /* '1e9': the range too, not only the form */
            snprintf(msg, sizeof msg, "'%.60s' is not allowed: expected a whole number of nodes, %d to %d", t,
                     ADH_GRID_NODES_MIN, ADH_GRID_NODES_MAX);
            bad = 1;
        } else if (!bad) {
            bad = adh_grid_nodes_check(v, msg, sizeof msg) != ADH_SUCCESS;
        }
        if (bad) {
            snprintf(why, n, "--cost-nodes: %s", *nnodes == MAX_NODES ? "at most 16 values" : msg);
            return 2;
        }
        for (size_t j = 0; j < *nnodes; j++)
            if (nodes[j] == (size_t)v) {
                snprintf(why, n, "--cost-nodes: %ld is given twice: each N once", v);
                return 2;
            }
        nodes[(*nnodes)++] = (size_t)v;
    }
    if (!*neps || !*nnodes) {
        snprintf(why, n, "--cost-eps and --cost-nodes need at least one value each");
        return 2;
    }
    return 0;
}

static double rel(double x, double ref)
{
    return fabs(x - ref) / fabs(ref);
}

static const char *cost_status(const cost_run *r)
{
    if (!r->ran)
        return "not_run";
    if (r->status == ADH_CONTINUE)
        return "interrupted";
    if (r->status == ADH_SUCCESS && r->fault)
        return r->fault == 1 ? "no contact" : "not separated";
    return r->status == ADH_SUCCESS && r->unconverged ? "unconverged" : adh_strerror(r->status);
}

static int write_cost(FILE *f, const void *ctx)
{
    const cost_job *job = ctx;
    char rule[64];
    adh_mix_rule_describe(&job->cfg->spec.relax, rule, sizeof rule);
    fprintf(f, "# adhere %s cost report: %ld cores, BLAS %s, mixing %s; errors are relative to the most accurate run (err_*) and the static curve (static_err_*)\n",
            ADH_VERSION, sysconf(_SC_NPROCESSORS_ONLN), blas_config(), rule);
    if (job->partial[0])
        fprintf(f, "# PARTIAL: %s\n", job->partial);
    fprintf(f, "# static curve's hysteresis (eps -> 0, displacement control): %.17g J\n", job->ref->hysteresis);
    fprintf(f, "# static curve's contact radius at the turn: %.17g m\n", job->ref->a_turn);
    if (job->ref->stopped[0])
        fprintf(f, "# static curve stopped: %s\n", job->ref->stopped);
    if (!job->ref->resolved)
        fprintf(f, "# static curve NOT resolved (%s): static_err_* are no verdict\n", job->ref->why);
    fputs("kernel\tnodes\teps\tseconds\tkernel_seconds\titerations\tsteps\tunconverged\tpulloff_F\tjump_in_h0\thysteresis\ta_turn\t"
          "err_pulloff\terr_jump_in\terr_hysteresis\terr_a_turn\tstatic_err_pulloff\tstatic_err_jump_in\tstatic_err_hysteresis\tstatic_err_a_turn\tstatus\n", f);
    for (size_t i = 0; i < job->n; i++) {
        const cost_run *r = &job->runs[i];
        fprintf(f, "%s\t%zu\t%.6g\t%.6g\t%.6g\t%zu\t%zu\t%zu\t%.17g\t%.17g\t%.17g\t%.17g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%s%s%s\n",
                adh_kernel_name(r->kernel), r->nodes, r->eps, r->seconds, r->kernel_seconds, r->iterations, r->steps,
                r->unconverged, r->pulloff, r->jump_in, r->hysteresis, r->a_turn, r->err[0], r->err[1], r->err[2],
                r->err[3], r->err_static[0], r->err_static[1], r->err_static[2], r->err_static[3],
                cost_status(r), r->reason[0] ? ": " : "", r->reason);
    }
    return 0;
}

/* cost.png: error against wall time, log-log, one curve per (N, kernel).
 * 0, or 3 (exit status) with msg. */
static int plot_cost(const cost_job *job, adh_outdir *out, char *msg, size_t len)
{
    adh_session ses;
    if (adh_session_open(&ses, out, "gnuplot.log", job->cfg->output.gnuplot_style, job->cfg->spec.relax.cancel, msg,
                         len) != 0)
        return 3;
    char data[PATH_MAX + 32];
    FILE *f = adh_session_data(&ses, "cost.dat", data, sizeof data, msg, len);
    if (!f) {
        adh_session_close(&ses);
        return 3;
    }
    /* one block per series, blank-line separated, for gnuplot's `index` */
    size_t nseries = 0;
    char titles[64][48];
    for (size_t i = 0; i < job->n; i++) {
        const cost_run *r = &job->runs[i];
        int first = 1;
        for (size_t j = 0; j < i; j++)
            if (job->runs[j].nodes == r->nodes && job->runs[j].kernel == r->kernel)
                first = 0;
        if (!first || nseries == 64)
            continue;
        snprintf(titles[nseries], sizeof titles[0], "N = %zu, %s kernel", r->nodes, adh_kernel_name(r->kernel));
        for (size_t j = 0; j < job->n; j++) {
            const cost_run *s = &job->runs[j];
            if (s->nodes == r->nodes && s->kernel == r->kernel && s->err[0] > 0 && isfinite(s->err[0]))
                fprintf(f, "%.6g %.6g %.6g %.6g\n", s->seconds, s->err[0], s->err[2] > 0 ? s->err[2] : NAN, s->eps * 1e12);
        }
        fprintf(f, "\n\n");
        nseries++;
    }
    int bad = ferror(f);
    if ((fclose(f) != 0) | bad) {
        snprintf(msg, len, "cannot write %.900s", data);
        adh_session_close(&ses);
        return 3;
    }
    char q[ADH_GP_PATH_SIZE];
    adh_gp_path(data, q, sizeof q);
    adh_session_begin(&ses, "cost", "cost.png");
    adh_gnuplot_cmd(ses.gp, "set multiplot layout 1,2 title 'What accuracy costs: error against the most accurate run'");
    adh_gnuplot_cmd(ses.gp, "set logscale xy; set grid; set key bottom left; set xlabel 'wall time (s)'");
    for (int panel = 0; panel < 2; panel++) {
        adh_gnuplot_cmd(ses.gp, "set ylabel '%s'", panel ? "relative error in hysteresis area" : "relative error in pull-off force");
        /* grown as needed: the data file's name, quoted, may be long */
        char *cmd = NULL;
        size_t cmdlen = 0;
        FILE *c = open_memstream(&cmd, &cmdlen);
        if (!c)
            break;
        fputs("plot ", c);
        for (size_t s = 0; s < nseries; s++)
            fprintf(c, "%s%s index %zu using 1:%d with linespoints lw 2 title '%s'", s ? ", " : "", q, s, panel ? 3 : 2, titles[s]);
        fclose(c);
        adh_gnuplot_cmd(ses.gp, "%s", cmd);
        free(cmd);
    }
    adh_gnuplot_cmd(ses.gp, "unset multiplot");
    int rc = adh_session_end(&ses, "cost.png", msg, len);
    adh_session_close(&ses);
    return rc != 0 ? 3 : 0;
}

static int cost_jobs(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return cores > 1 ? (int)(cores < 8 ? cores : 8) : 1;
}

/* Memory before anything is allocated: the runs in parallel hold a kernel
 * each (each run's program share counted too: a margin), beside the static
 * curve's kernel and solver at the finest N, and every thread its BLAS
 * buffer (under ulimit -v). 0, or -1 with why. */
static int cost_budget(const adh_config *cfg, size_t n, size_t base, char *why, size_t whylen)
{
    adh_run_spec sc = cost_spec(cfg, n, base, ADH_MODE_STATIC), rc = cost_spec(cfg, n, base, ADH_MODE_RELAX);
    double jobs = cost_jobs();
    double need = adh_budget_bytes(&sc, 1) + jobs * adh_budget_bytes(&rc, 0), have;
    /* the workers and this thread, which solves the static curve meanwhile */
    if (adh_budget_fits(need, (unsigned)jobs + 1, &have, NULL))
        return 0;
    snprintf(why, whylen, "--cost: its runs at N = %zu would hold about %.3g GB at once (%g in parallel, a %s "
             "kernel each, beside the static curve's solver), more than the %.3g GB this process may use (available "
             "memory, ulimit -v/-d less the BLAS's buffers, cgroup limit): use smaller --cost-nodes", n, need / 1e9,
             jobs, adh_kernel_storage_name(rc.grid.use.storage), have / 1e9);
    return -1;
}

static int by_cost(const void *a, const void *b)
{
    /* the most expensive first, so two workers finish together */
    const cost_run *x = a, *y = b;
    double cx = (double)x->nodes * x->nodes / x->eps, cy = (double)y->nodes * y->nodes / y->eps;
    return (cx < cy) - (cx > cy);
}


static void cost_static_reference(const adh_config *cfg, size_t finest, size_t base, cost_ref *ref)
{
    memset(ref, 0, sizeof *ref);
    ref->spec = cost_spec(cfg, finest, base, ADH_MODE_STATIC);
    ref->spec.grid.use.kernel = ADH_KERNEL_RING;
    adh_grid_report gr;
    adh_grid_check(&ref->spec.mat, ADH_GRID_STATIC, finest, adh_config_spacing(&ref->spec), &gr);
    ref->resolved = gr.resolved;
    if (!gr.resolved)
        adh_grid_unresolved_sentence(&gr, ref->why, sizeof ref->why);
    adh_grid *g = adh_grid_alloc(finest, adh_config_spacing(&ref->spec));
    int kst = ADH_ENOMEM;
    adh_kernel *k = g ? adh_config_kernel_alloc(&ref->spec, g, &kst) : NULL;
    adh_run srun;
    adh_run_init(&srun);
    if (kst == ADH_EINTR)
        srun.interrupted = 1;
    ref->status = k ? cli_static_run(&ref->spec, g, k, cli_interrupt_step, NULL, &srun, &ref->res) : ADH_ENOMEM;
    if (srun.interrupted)
        ref->status = ADH_EINTR;   /* part of a curve is no reference */
    int ok = ref->status == ADH_SUCCESS;
    if (!ok && !srun.interrupted)
        cli_tables_stopped(cfg, &srun, ref->status, ref->stopped, sizeof ref->stopped);
    /* a fine h0 grid: lattice-trapping legs are far shorter than d */
    ref->hysteresis = ok ? cli_tables_static_hysteresis(&srun, &ref->spec.mat) : NAN;
    /* the curve ends at the (deepest) turn: its contact radius there */
    ref->a_turn = ok && srun.nrows ? srun.rows[srun.nrows - 1].a : NAN;
    adh_run_free(&srun);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* The most accurate run: the finest grid, the exact kernel, the smallest
 * eps, among runs that finished (an interrupted one is no reference). */
static const cost_run *cost_best(const cost_run *runs, size_t n)
{
    static const cost_run none = { .pulloff = NAN, .jump_in = NAN, .hysteresis = NAN, .a_turn = NAN, .eps = NAN };
    const cost_run *best = NULL;
    for (size_t i = 0; i < n; i++) {
        const cost_run *r = &runs[i];
        if (!r->ran || r->status != ADH_SUCCESS || r->fault)
            continue;
        if (!best || r->nodes > best->nodes || (r->nodes == best->nodes && r->kernel > best->kernel) ||
            (r->nodes == best->nodes && r->kernel == best->kernel && r->eps < best->eps))
            best = r;
    }
    return best ? best : &none;
}

/* Every run's errors against the best run and the static curve; what was
 * cut short goes into job->partial. */
static void cost_errors(cost_job *job, const cost_run *best, const cost_ref *ref)
{
    int ok = ref->status == ADH_SUCCESS;
    size_t not_run = 0, cut = 0;
    for (size_t i = 0; i < job->n; i++) {
        cost_run *r = &job->runs[i];
        not_run += !r->ran;
        cut += r->ran && r->status == ADH_CONTINUE;
        if (!r->ran || r->status == ADH_CONTINUE) {
            /* nothing measured: no time, no errors */
            r->seconds = r->kernel_seconds = NAN;
            r->pulloff = r->jump_in = r->hysteresis = r->a_turn = NAN;
        }
        r->err[0] = rel(r->pulloff, best->pulloff);
        r->err[1] = rel(r->jump_in, best->jump_in);
        r->err[2] = rel(r->hysteresis, best->hysteresis);
        r->err[3] = rel(r->a_turn, best->a_turn);
        r->err_static[0] = ok ? rel(r->pulloff, ref->res.pulloff_F) : NAN;
        r->err_static[1] = ok ? rel(r->jump_in, ref->res.jump_in_h0) : NAN;
        r->err_static[2] = ok ? rel(r->hysteresis, ref->hysteresis) : NAN;
        r->err_static[3] = ok ? rel(r->a_turn, ref->a_turn) : NAN;
    }
    if (cli_interrupt_signal())
        snprintf(job->partial, sizeof job->partial, "interrupted by signal %d: %zu of %zu runs cut short, %zu never started%s",
                 cli_interrupt_signal(), cut, job->n, not_run, ok ? "" : ", static curve not finished");
    job->ref = ref;
}

static const char *cost_note(const cost_run *r, char *buf, size_t len)
{
    if (!r->ran)
        return "  (not run)";
    if (r->status == ADH_SUCCESS && r->fault)
        return r->fault == 1 ? "  (no contact: the surfaces never touched; put the turn below the jump-in)"
                             : "  (not separated: an unloading branch ended in contact)";
    if (r->status == ADH_SUCCESS)
        return r->unconverged ? "  (some steps at the cap)" : "";
    if (r->status == ADH_CONTINUE)
        return "  (interrupted)";
    snprintf(buf, len, "  (failed%s", r->reason[0] ? ": " : "");
    adh_text_cat(buf, len, r->reason);
    adh_text_cat(buf, len, ")");
    return buf;
}

/* The report on standard output. */
static void cost_print(const cost_job *job, const cost_run *best, const cost_ref *ref, int started)
{
    char rule[64];
    adh_mix_rule_describe(&job->cfg->spec.relax, rule, sizeof rule);
    if (job->partial[0]) {
        printf("# PARTIAL: %s\n", job->partial);
        adh_say(job->partial);
    }
    printf("What accuracy costs: %zu runs of the load/unload cycle, %d at a time on %ld cores, 1 BLAS thread each; mixing %s\n",
           job->n, started ? started : 1, sysconf(_SC_NPROCESSORS_ONLN), rule);
    printf("BLAS: %s\nreference: N = %zu, %s kernel, eps = %g pm; static curve (N = %zu, ring): pull-off %.4g N, jump-in %.4g nm, "
           "hysteresis %s, a at the turn %.4g um%s%s%s\n",
           blas_config(), best->nodes, adh_kernel_name(best->kernel), best->eps * 1e12, ref->spec.grid.use.nodes,
           ref->res.pulloff_F, ref->res.jump_in_h0 * 1e9, adh_qtext(ref->hysteresis, ADH_Q_WORK).s, ref->a_turn * 1e6,
           ref->status == ADH_SUCCESS ? "" : ref->stopped[0] ? " (failed: " : " (failed)", ref->stopped,
           ref->stopped[0] ? ")" : "");
    if (!ref->resolved)
        printf("the static curve is NOT resolved on that grid (%s): its st.* errors are no verdict\n", ref->why);
    printf("\n%-6s %6s %7s %9s %11s %12s %10s %11s %9s | %8s %8s %8s %8s | %8s %8s %8s %8s\n", "kernel", "N", "eps/pm",
           "seconds", "iterations", "pulloff/uN", "jump-in/nm", "hyst/fJ", "a_turn/um", "pulloff", "jump-in", "hyst",
           "a_turn", "st.pull", "st.jump", "st.hyst", "st.a");
    for (size_t i = 0; i < job->n; i++) {
        const cost_run *r = &job->runs[i];
        char note[CLI_TABLES_REASON_LEN + 40];
        printf("%-6s %6zu %7.3g %9.3f %11zu %12.5g %10.4g %11.5g %9.4g | %8.2e %8.2e %8.2e %8.2e | %8.2e %8.2e %8.2e %8.2e%s\n",
               adh_kernel_name(r->kernel), r->nodes, r->eps * 1e12, r->seconds, r->iterations, r->pulloff * 1e6,
               r->jump_in * 1e9, r->hysteresis * 1e15, r->a_turn * 1e6, r->err[0], r->err[1], r->err[2], r->err[3],
               r->err_static[0], r->err_static[1], r->err_static[2], r->err_static[3], cost_note(r, note, sizeof note));
    }
}

/* A flag that sets what --cost sets for each of its runs (N, eps, the
 * kernel, a uniform grid) would be dropped in silence: 0, or -1 with the
 * flag to give instead. */
static int cost_replaced(const cli_options *cli, char *why, size_t whylen)
{
    for (size_t i = 0; i < cli->nset; i++) {
        const cli_set *f = &cli->set[i];
        if (strcmp(f->key, "grid.nodes") == 0 && strcmp(f->value, "auto") != 0)
            snprintf(why, whylen, "--cost runs its grid over --cost-nodes: -N %.40s would be ignored; give "
                     "--cost-nodes=%.40s", f->value, f->value);
        else if (strcmp(f->key, "solver.eps") == 0)
            snprintf(why, whylen, "--cost runs its grid over --cost-eps: --eps=%.40s would be ignored; give "
                     "--cost-eps=%.40s", f->value, f->value);
        else if (strcmp(f->key, "grid.kernel") == 0)
            snprintf(why, whylen, "--cost runs both kernels, paper and ring: --kernel=%.40s would be ignored; "
                     "leave it out", f->value);
        else
            continue;
        return -1;
    }
    if (cli->ndata) {   /* drawn over force.png, which --cost does not draw */
        snprintf(why, whylen, "--cost draws no force curve: --data would be ignored; leave it out (--batch draws "
                 "it over force.png)");
        return -1;
    }
    if (cli->cfg.spec.grid.use.graded) {
        snprintf(why, whylen, "--cost runs uniform grids of --cost-nodes: grid = graded would be ignored; leave "
                 "it out");
        return -1;
    }
    return 0;
}

/* The runs the lists ask for, each checked as a run would be, and the
 * memory they take at once: 0, or the exit status with its message said. */
static int cost_make_runs(const cli_options *cli, cost_run **out, size_t *nout, size_t *finest, size_t *base)
{
    const adh_config *cfg = &cli->cfg;
    char why[1024];
    double eps[MAX_EPS];
    size_t nodes[MAX_NODES], neps, nnodes;
    if (parse_lists(cli, eps, &neps, nodes, &nnodes, why, sizeof why) != 0) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    if (cfg->spec.mode != ADH_MODE_RELAX || cfg->spec.proto.nturns == 0) {
        adh_sayf("--cost measures the relaxation's load/unload cycle: it needs mode relax and a turning point");
        return CLI_EXIT_USAGE;
    }
    /* its runs are the grid's, of one material: a study's others never ran */
    if (cfg->sweep.naxes) {
        fprintf(stderr, "adhere: --cost measures one run's cycle over its grid of eps, N and kernels: a sweep (of %s, "
                "from --sweep or the scene's [sweep]) would be ignored; leave it out, or run --cost for each value\n",
                cfg->sweep.axis[0].name);
        return CLI_EXIT_USAGE;
    }
    if (cost_replaced(cli, why, sizeof why) != 0) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    *finest = 0;
    *base = SIZE_MAX;
    for (size_t a = 0; a < nnodes; a++) {
        *finest = nodes[a] > *finest ? nodes[a] : *finest;
        *base = nodes[a] < *base ? nodes[a] : *base;
    }
    for (size_t a = 0; a < nnodes; a++)
        for (size_t e = 0; e < neps; e++) {
            static adh_config c;   /* large: not on the stack */
            c = *cfg;
            c.spec.grid.use.nodes = nodes[a];
            c.spec.grid.use.spacing = cost_spacing(cfg->spec.grid.use.spacing, nodes[a], *base);
            c.spec.relax.eps = eps[e];
            c.spec.grid.force = 1; /* coarse grids are what the report measures */
            /* its N and eps are the lists', not the keys' (the advice names --cost-nodes) */
            if (cli_options_validate_for(&c, CLI_ADVICE_COST, why, sizeof why) != 0) {
                adh_sayf("--cost: N = %zu, eps = %s: %s", nodes[a], adh_qtext(eps[e], ADH_Q_LENGTH).s, why);
                return CLI_EXIT_USAGE;
            }
        }
    if (cost_budget(cfg, *finest, *base, why, sizeof why) != 0) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    size_t n = neps * nnodes * 2, m = 0;
    cost_run *runs = calloc(n, sizeof *runs);
    if (!runs) {
        adh_sayf("out of memory");
        return CLI_EXIT_SOLVER;
    }
    for (size_t a = 0; a < nnodes; a++) {
        for (int k = 0; k < 2; k++)
            for (size_t e = 0; e < neps; e++)
                runs[m++] = (cost_run){ .eps = eps[e], .nodes = nodes[a], .kernel = (adh_kernel_type)k };
    }
    qsort(runs, n, sizeof *runs, by_cost);
    *out = runs;
    *nout = n;
    return 0;
}

/* cost.tsv and cost.png into od: the exit status. */
static int cost_write(const cost_job *job, adh_outdir *od)
{
    char why[1024];
    /* still caught: a signal while gnuplot draws ends the wait, and the
     * exit says interrupted */
    if (adh_outdir_write(od, "cost.tsv", write_cost, job, why, sizeof why) != 0) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    if (!job->cfg->output.plot || cli_interrupt_signal())
        return CLI_EXIT_OK;
    int prc = plot_cost(job, od, why, sizeof why);
    if (!prc)
        return CLI_EXIT_OK;
    adh_sayf("cost.png not written: %s", why);
    return cli_interrupt_signal() ? cli_interrupt_exit() : prc;
}

static void cost_done(const cost_job *job, const char *out)
{
    char t[32];
    cli_progress_duration(adh_clock_seconds() - job->t0, t, sizeof t);
    if (out)
        adh_sayf("done in %s: %zu cost runs; the table on standard output, cost.tsv%s in %s/", t, job->n,
                 job->cfg->output.plot ? " and cost.png" : "", out);
    else
        adh_sayf("done in %s: %zu cost runs; the table on standard output", t, job->n);
}

/* What the grid of runs will take, said before it starts (the default grid
 * takes hours): each run's expected iterations (adh_plan_iterations) times
 * a kernel product timed now on its N, in CPU seconds as --plan does,
 * shared out over the workers. Negative when a kernel could not be built. */
static double cost_estimate(const adh_config *cfg, const cost_run *runs, size_t n, size_t base, int jobs,
                            size_t *scaled)
{
    static adh_config c;   /* a configuration is large: not on the stack */
    /* one timing for each N (the runs come sorted by cost, not by N) */
    size_t *tn = calloc(n ? n : 1, sizeof *tn), nt = 0;
    double *tp = calloc(n ? n : 1, sizeof *tp), *tb = calloc(n ? n : 1, sizeof *tb), total = 0;
    for (size_t i = 0; tn && tp && tb && i < n && total >= 0; i++) {
        c = *cfg;
        c.spec = cost_spec(cfg, runs[i].nodes, base, ADH_MODE_RELAX);
        c.spec.relax.eps = runs[i].eps;
        c.spec.grid.use.kernel = runs[i].kernel;
        size_t k = 0;
        while (k < nt && tn[k] != runs[i].nodes)
            k++;
        if (k == nt) {
            tn[nt] = runs[i].nodes;
            size_t timed_n = 0;
            tp[nt] = cli_estimate_iteration(&c, &tb[nt], &timed_n);
            *scaled = timed_n && timed_n < tn[nt] ? timed_n : *scaled;
            nt++;
        }
        total = isfinite(tp[k]) ? total + tb[k] + adh_plan_iterations(&c.spec) * tp[k] : -1;
    }
    if (!tn || !tp || !tb)
        total = -1;
    free(tn), free(tp), free(tb);
    return total < 0 ? -1 : total / (jobs > 1 ? jobs : 1);
}

int cli_cost_main(const cli_options *cli)
{
    const adh_config *cfg = &cli->cfg;
    cost_run *runs;
    size_t n, finest, base;
    int status = cost_make_runs(cli, &runs, &n, &finest, &base);
    if (status)
        return status;
    char why[1024];
    const char *out = cfg->output.dir[0] ? cfg->output.dir : NULL;
    adh_outdir *od = out ? adh_outdir_open(out, cfg->output.overwrite ? ADH_OUTDIR_OVERWRITE : 0, why, sizeof why) : NULL;
    if (out && !od) {
        adh_say(why);
        free(runs);
        return CLI_EXIT_USAGE;
    }
    if (!cfg->output.quiet) {
        size_t scaled = 0;   /* the nodes a larger dense kernel was timed on */
        double est = cost_estimate(cfg, runs, n, base, cost_jobs(), &scaled);
        char t[32], on[128] = "";
        cli_progress_duration(est, t, sizeof t);
        if (scaled)
            snprintf(on, sizeof on, ", a dense kernel past %zu nodes timed on a grid of that many and scaled as N^2",
                     scaled);
        if (est >= 0)
            adh_sayf("--cost: %zu runs, expected about %s on %d core%s (the plan's iterations, a kernel "
                     "product timed now%s; the static curve beside them)", n, t, cost_jobs(), cost_jobs() > 1 ? "s" : "",
                     on);
    }
    cli_interrupt_catch();
    adh_ready_phase("cost");
    cost_job job = { .cfg = cfg, .runs = runs, .n = n, .base = base };
    pthread_mutex_init(&job.lock, NULL);
    job.t0 = adh_clock_seconds();
    pthread_t threads[8];
    int started = 0, jobs = cost_jobs();
    for (int t = 0; t < jobs; t++)
        if (pthread_create(&threads[t], NULL, worker, &job) == 0)
            started++;
    if (!started)
        worker(&job);
    static cost_ref ref;   /* holds a run spec: not on the stack */
    cost_static_reference(cfg, finest, base, &ref);
    for (int t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    pthread_mutex_destroy(&job.lock);

    const cost_run *best = cost_best(runs, n);
    cost_errors(&job, best, &ref);
    cost_print(&job, best, &ref, started);
    status = cli_interrupt_signal() ? cli_interrupt_exit() : CLI_EXIT_OK;
    if (od) {
        int wst = cost_write(&job, od);
        status = wst ? wst : status;
    }
    cli_interrupt_release();
    if (status == CLI_EXIT_OK && !cfg->output.quiet)
        cost_done(&job, od ? adh_outdir_path(od) : NULL);
    adh_outdir_close(od);
    free(runs);
    return status;
}
