/* --plan's CPU time for physical time: the integrator's steps the plan
 * expects (adh_plan_time_steps: the contact line's travel over a measured
 * step), each priced by what a step does, timed here on the run's grid. */
#include "cli/estimate.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>

#include "adhere/clock.h"
#include "adhere/kernel.h"
#include "adhere/law.h"
#include "cli/progress.h"

/* What a step costs, in the operations timed below, measured (profiled
 * on the visco sphere, N = 648: LU and its solves 35 %, products 22 %,
 * the rest IDAS's vector operations and the law at every node; fitted on
 * N = 150 ... 1000 dense and the sigma = 22.5 cycle's 1952 rings, H^2,
 * docs/viscoelastic.md): about 10 kernel products a step (Newton's
 * residuals, GMRES, the q elimination and the energies), 1.4 dense LUs of
 * the active nodes' matrix (a factorization nearly every step, and its
 * solves) at 0.63 of the deepest contact's nodes (an LU's n^3 averaged
 * over a contact growing from nothing), and about 90 passes over the nodes
 * the size of the law's; under a hierarchical kernel, HODLR solves and
 * updates in place of the LU, about 40 products' worth. */
#define STEP_PRODUCTS 10.0
#define STEP_LUS 1.4
#define STEP_LU_SHARE 0.63
#define STEP_PASSES 90.0
#define STEP_HODLR_PRODUCTS 40.0

/* CPU seconds a call of fn takes: at least 3 calls and 0.05 s. */
typedef void (*timed_fn)(void *ctx);
static double cpu_per_call(timed_fn fn, void *ctx)
{
    size_t reps = 0;
    double t0 = adh_clock_cpu_seconds(), t = t0;
    while (reps < 3 || t - t0 < 0.05) {
        fn(ctx);
        reps++;
        t = adh_clock_cpu_seconds();
    }
    return (t - t0) / (double)reps;
}

typedef struct lu_job {
    int m;
    double *a, *work;
    int *piv;
} lu_job;

static void lu_once(void *ctx)
{
    lu_job *j = ctx;
    for (int i = 0; i < j->m * j->m; i++)
        j->work[i] = j->a[i];
    LAPACKE_dgetrf(LAPACK_ROW_MAJOR, j->m, j->m, j->work, j->m, j->piv);
}

/* CPU seconds of a dense LU of m unknowns (a diagonally dominant matrix, as
 * I - c W diag(p') is near its fold), NAN when out of memory. */
static double lu_seconds(size_t m)
{
    if (m < 2)
        return 0.0;
    lu_job j = { .m = (int)m };
    j.a = malloc(2 * m * m * sizeof *j.a);
    j.piv = malloc(m * sizeof *j.piv);
    double t = NAN;
    if (j.a && j.piv) {
        j.work = j.a + m * m;
        for (size_t r = 0; r < m; r++)
            for (size_t c = 0; c < m; c++)
                j.a[r * m + c] = (r == c ? (double)m : 0.0) + 1.0 / (1.0 + fabs((double)r - (double)c));
        t = cpu_per_call(lu_once, &j);
    }
    free(j.a);
    free(j.piv);
    return t;
}

typedef struct law_job {
    const adh_grid *g;
    const adh_material *m;
    double *out;
} law_job;

/* The law's pressure and slope at every node of the sphere's gap. */
static void law_once(void *ctx)
{
    law_job *j = ctx;
    for (size_t i = 0; i < j->g->n; i++) {
        double r = j->g->r[i], h = j->m->z0 + r * r / (2.0 * j->m->R);
        j->out[i] = adh_lj_pressure(h, j->m->A, j->m->z0) + adh_lj_dpressure(h, j->m->A, j->m->z0);
    }
}

typedef struct product_job {
    const adh_kernel *k;
    size_t n;
    double *v;
} product_job;

static void product_once(void *ctx)
{
    product_job *j = ctx;
    adh_kernel_apply(j->k, j->v, j->v + j->n, j->v + 2 * j->n);
}

/* The grid's timings: one product, one pass of the law. */
typedef struct grid_cost {
    adh_run_spec spec;    /* whose grid */
    size_t n;
    int hierarchical;
    double product, pass, build;
} grid_cost;

static int time_grid(const adh_run_spec *s, grid_cost *gc)
{
    double t0 = adh_clock_cpu_seconds();
    adh_grid *g = adh_config_grid_alloc(s);
    int st = 0;
    adh_kernel *k = g ? adh_config_kernel_alloc(s, g, &st) : NULL;
    gc->build = adh_clock_cpu_seconds() - t0;
    double *v = k ? malloc(3 * g->n * sizeof *v) : NULL;
    int rc = -1;
    if (v) {
        for (size_t i = 0; i < g->n; i++)
            v[i] = 1.0 / (1.0 + (double)i);   /* a pressure falling off from the axis */
        product_job pj = { k, g->n, v };
        law_job lj = { g, &s->mat, v + g->n };
        gc->spec = *s;
        gc->n = g->n;
        gc->hierarchical = adh_kernel_storage_of(k) != ADH_STORAGE_DENSE;
        gc->product = cpu_per_call(product_once, &pj);
        gc->pass = cpu_per_call(law_once, &lj);
        rc = 0;
    }
    free(v);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc;
}

/* Nodes of spec's grid inside radius a. */
static size_t nodes_inside(const adh_run_spec *s, double a)
{
    adh_grid *g = adh_config_grid_alloc(s);
    size_t m = 0;
    while (g && m < g->n && g->r[m] < a)
        m++;
    adh_grid_free(g);
    return m;
}

/* One run's CPU seconds, its steps in *c and a step's seconds in *step. */
static double run_seconds(const adh_run_spec *s, grid_cost *gc, adh_plan_time_cost *c, double *step,
                          size_t *lu_nodes, double *lu)
{
    adh_plan_time_steps(s, c);
    double build = 0;
    if (!gc->n || !adh_config_same_grid(&gc->spec, s)) {
        if (time_grid(s, gc) != 0)
            return NAN;
        build = gc->build;   /* once a grid */
    }
    *step = STEP_PRODUCTS * gc->product + STEP_PASSES * gc->pass;
    *lu_nodes = 0;
    *lu = 0;
    if (gc->hierarchical) {
        *step += STEP_HODLR_PRODUCTS * gc->product;
    } else {
        *lu_nodes = (size_t)(STEP_LU_SHARE * (double)nodes_inside(s, c->a_turn));
        *lu = lu_seconds(*lu_nodes);
        *step += STEP_LUS * *lu;
    }
    return build + c->steps * *step;
}

void cli_estimate_time_print(FILE *f, const adh_config *cfg, const adh_plan *plan)
{
    static adh_plan_progress runs[ADH_PLAN_MAX_RUNS];
    size_t n = plan->nruns < ADH_PLAN_MAX_RUNS ? plan->nruns : ADH_PLAN_MAX_RUNS;
    grid_cost gc = { .n = 0 }, gc0 = { .n = 0 };
    adh_plan_time_cost c, c0 = { 0 };
    double cpu = 0, steps = 0, step = NAN, step0 = NAN, lu0 = 0, build = 0, smin = INFINITY, smax = 0;
    size_t lu_nodes0 = 0;
    for (size_t i = 0; i < n; i++) {
        adh_run_spec s;
        adh_config_sweep_run(cfg, i, &s);
        size_t lu_nodes;
        double lu, t = run_seconds(&s, &gc, &c, &step, &lu_nodes, &lu);
        if (!isfinite(t)) {
            fprintf(f, "time: not estimated (the kernel could not be built here)\n");
            return;
        }
        if (i == 0) {
            c0 = c;
            step0 = step;
            lu0 = lu;
            lu_nodes0 = lu_nodes;
            build = gc.build;
            gc0 = gc;
        }
        runs[i] = (adh_plan_progress){ .cost = t };
        cpu += t;
        steps += c.steps;
        smin = fmin(smin, c.steps);
        smax = fmax(smax, c.steps);
    }
    char t[32], w[32];
    cli_progress_duration(cpu, t, sizeof t);
    if (n > 1) {
        cli_progress_duration(adh_plan_time_left(runs, n, plan->jobs, 0, 1.0), w, sizeof w);
        fprintf(f, "time: about %s of CPU in all, %s on %d core%s (%.3g s of CPU: %.2g integrator steps, %.2g to %.2g "
                   "a run%s; run 1's as below)\n", t, w, plan->jobs, plan->jobs == 1 ? "" : "s", cpu, steps, smin, smax,
                n < plan->nruns ? "; the first runs alone" : "");
    }
    double cpu0 = build + c0.steps * step0;
    cli_progress_duration(cpu0, t, sizeof t);
    fprintf(f, "time: %sabout %s (%.3g s of CPU: about %.2g integrator steps, %.0f out of contact and %.0f as the "
               "contact line moves %.3g um in and out, %.3g nm a step approaching and %.3g nm retracting (0.068 edge "
               "zones at the effective moduli %.2g and %.2g GPa, measured), 15 %% more for jumps and rejected steps; "
               "each step about %.3g ms of CPU here: 10 kernel products of %.3g ms, ",
            n > 1 ? "run 1 " : "", t, cpu0, c0.steps, c0.free_steps, c0.contact_steps,
            c0.a_turn * 1e6, c0.step_in * 1e9, c0.step_out * 1e9, c0.E_in / 1e9, c0.E_out / 1e9, step0 * 1e3,
            gc0.product * 1e3);
    if (lu_nodes0)
        fprintf(f, "a dense LU of %zu nodes (%.3g ms) 1.4 times, ", lu_nodes0, lu0 * 1e3);
    else if (gc0.hierarchical)
        fprintf(f, "HODLR solves and updates about 40 products' worth, ");
    fprintf(f, "90 passes of the law over the %zu nodes, timed now; the kernel built in %.2g s); "
               "a guide within a factor of about 3 where the grid resolves the contact's edge zone, "
               "slower where it does not\n", gc0.n, build);
}
