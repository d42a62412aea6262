/* --plan's CPU time for physical time: the integrator's steps the plan
 * expects (adh_plan_time_steps: the contact line's travel over a measured
 * step), each priced by what a step does, timed here on the run's grid. */
#include "cli/estimate.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/clock.h"
#include "adhere/kernel.h"
#include "adhere/law.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/units.h"
#include "cli/progress.h"

/* What a step costs, in the operations timed below: fitted (least
 * squares in the log of the ratio) to 15 runs on dense kernels, N = 150
 * ... 1000, sigma 2.25 and 7.5, 1 nm/s ... 10 mm/s, each within 12 % of
 * its CPU seconds a step (docs/viscoelastic.md): 14 kernel products
 * (Newton's residuals, GMRES, the q elimination, the energies), one dense
 * LU of the preconditioner's active nodes (a factorization nearly every
 * step; the active nodes, where p' matters, reach 1.2 to 1.35 times the
 * deepest contact's and average, as an LU's m^3, 0.9 of them), and 70
 * passes over the nodes the size of the law's (IDAS's vector operations,
 * the law at every node). Under a hierarchical kernel HODLR solves and
 * updates replace the LU: 40 products' worth (sigma = 22.5, 1952 rings,
 * H^2). Profiled on the visco sphere (N = 648): LU and its solves 35 %,
 * products 22 %, the rest IDAS and the law. */
#define STEP_PRODUCTS 14.0
#define STEP_LUS 1.0
#define STEP_LU_SHARE 0.9
#define STEP_PASSES 70.0
#define STEP_HODLR_PRODUCTS 40.0

/* CPU seconds a call of fn takes: at least 3 calls and 0.05 s. */
static double cpu_per_call(cli_estimate_fn fn, void *ctx)
{
    return cli_estimate_cpu_per_call(fn, ctx, 3, 0.05);
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

/* Above this many unknowns an LU is timed at it and scaled as m^3: the
 * plan's own time and memory stay bounded (16 MB, well under a second). */
#define LU_TIMED_MAX 1000

/* CPU seconds of a dense LU of m unknowns (a diagonally dominant matrix, as
 * I - c W diag(p') is near its fold), NAN when out of memory. */
static double lu_seconds(size_t m)
{
    if (m < 2)
        return 0.0;
    if (m > LU_TIMED_MAX)
        return lu_seconds(LU_TIMED_MAX) * pow((double)m / LU_TIMED_MAX, 3.0);
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

/* The grid's timings: one product, one pass of the law. */
typedef struct grid_cost {
    adh_run_spec spec;    /* whose grid */
    adh_grid *g;          /* the grid, kept for the runs that share it */
    size_t n;
    size_t timed_n;       /* the nodes its kernel was timed on (n, or CLI_ESTIMATE_DENSE_MAX) */
    int hierarchical;
    double product, pass, build;
    size_t lu_n;          /* the last LU timed for its runs: its size, */
    double lu_t;          /* and its CPU seconds (a sweep's runs share them) */
} grid_cost;

/* lu_seconds(m) for the runs of one grid, timed again only where m is a
 * quarter off the size last timed (scaled as m^3 between): a sweep of 32
 * dwells timed 32 equal LUs, 1.6 s of its plan's 1.75. */
static double lu_for(grid_cost *gc, size_t m)
{
    double r = gc->lu_n ? (double)m / (double)gc->lu_n : 0;
    if (!(r >= 0.8 && r <= 1.25) || !(gc->lu_t >= 0)) {
        gc->lu_t = lu_seconds(m);
        gc->lu_n = m;
        r = 1;
    }
    return gc->lu_t * r * r * r;
}

static int time_grid(const adh_run_spec *s, grid_cost *gc)
{
    adh_grid_free(gc->g);
    gc->n = 0;
    gc->lu_n = 0;
    gc->lu_t = NAN;
    adh_grid *g = gc->g = adh_config_grid_alloc(s);
    double *v = g ? malloc(3 * g->n * sizeof *v) : NULL;
    cli_estimate_kernel_cost kc;
    int rc = -1;
    if (v) {
        for (size_t i = 0; i < g->n; i++)
            v[i] = 1.0 / (1.0 + (double)i);   /* a pressure falling off from the axis */
        rc = cli_estimate_kernel(s, g, v, 3, 0.05, &kc);
    }
    if (rc == 0) {
        law_job lj = { g, &s->mat, v + g->n };
        gc->spec = *s;
        gc->n = g->n;
        gc->timed_n = kc.timed_n;
        gc->hierarchical = kc.hierarchical;
        gc->build = kc.build;
        gc->product = kc.product;
        gc->pass = cpu_per_call(law_once, &lj);
    }
    free(v);
    return rc;
}

/* Nodes of grid g inside radius a. */
static size_t nodes_inside(const adh_grid *g, double a)
{
    size_t m = 0;
    while (m < g->n && g->r[m] < a)
        m++;
    return m;
}

/* One run's estimate and what it rests on. */
typedef struct run_est {
    adh_plan_time_cost c; /* (an elastic path: c.steps the static curve's points) */
    int exact;            /* an elastic path: the exact curve, not its steps */
    grid_cost grid;       /* its grid's timings */
    double build;         /* the kernel's build, when its grid was new */
    double step;          /* a step's CPU seconds */
    size_t lu_nodes;      /* a dense LU's size (0: none) */
    double lu;            /* its CPU seconds */
    double cpu;           /* the run's: build + steps x step */
} run_est;

/* Run s's estimate in *e, timing its grid unless gc holds it already. */
static int run_estimate(const adh_run_spec *s, grid_cost *gc, run_est *e)
{
    adh_plan_time_steps(s, &e->c);
    e->build = 0;
    if (!gc->n || !adh_config_same_grid(&gc->spec, s)) {
        if (time_grid(s, gc) != 0)
            return -1;
        e->build = gc->build;   /* once a grid */
    }
    e->grid = *gc;
    e->grid.g = NULL;   /* gc's, freed with it: the estimate keeps the timings */
    e->step = STEP_PRODUCTS * gc->product + STEP_PASSES * gc->pass;
    e->lu_nodes = 0;
    e->lu = 0;
    if (gc->hierarchical) {
        e->step += STEP_HODLR_PRODUCTS * gc->product;
    } else {
        e->lu_nodes = (size_t)(STEP_LU_SHARE * (double)nodes_inside(gc->g, e->c.a_turn));
        e->lu = lu_for(gc, e->lu_nodes);
        e->step += STEP_LUS * e->lu;
    }
    e->step *= e->c.work;
    e->cpu = e->build + e->c.steps * e->step;
    return isfinite(e->cpu) ? 0 : -1;
}

/* An elastic sphere in time is no integration but its static curve
 * (adh_rule_path): its points, adh_static_skips' estimate (the exact
 * curve's ~1.3 to 3 a fine ring the contact line crosses, or ~150 steps
 * over the lattice folds), each priced as measured on the static curves
 * of the default scene (N = 648 dense: 2.8 ms a point), sigma = 2.25 on
 * 300 nodes of 4 nm (0.46 ms) and sigma = 22.5's graded grid (1952
 * rings, H^2: 5.6 ms; AMD EPYC, 2026-11-27): 90 kernel products and a
 * quarter of a dense LU of 0.9 times the contact's nodes (refreshed when
 * GMRES slows, and at every fold), or 215 products' worth under a
 * hierarchical kernel (HODLR's factorizations and solves). */
#define PATH_PRODUCTS 90.0
#define PATH_LU_SHARE 0.25
#define PATH_HODLR_PRODUCTS 215.0

static int path_estimate(const adh_run_spec *s, grid_cost *gc, run_est *e)
{
    memset(&e->c, 0, sizeof e->c);
    e->build = 0;
    if (!gc->n || !adh_config_same_grid(&gc->spec, s)) {
        if (time_grid(s, gc) != 0)
            return -1;
        e->build = gc->build;
    }
    e->grid = *gc;
    e->grid.g = NULL;
    double deep = s->proto.nturns ? adh_protocol_deepest_turn(&s->proto) : adh_static_settings_default().h0_end;
    e->c.steps = adh_plan_path_points(s, gc->g, &e->exact);
    e->c.a_turn = adh_rings_contact_estimate(&s->mat, fmin(deep, 0.0));
    e->lu_nodes = 0;
    e->lu = 0;
    if (gc->hierarchical) {
        e->step = PATH_HODLR_PRODUCTS * gc->product;
    } else {
        e->lu_nodes = (size_t)(STEP_LU_SHARE * (double)nodes_inside(gc->g, e->c.a_turn));
        e->lu = lu_for(gc, e->lu_nodes);
        e->step = PATH_PRODUCTS * gc->product + PATH_LU_SHARE * e->lu;
    }
    e->cpu = e->build + e->c.steps * e->step;
    return isfinite(e->cpu) ? 0 : -1;
}

/* x to two significant digits (the plan's steps are no better). */
static double two_digits(double x)
{
    if (!(x > 0))
        return x;
    double p = pow(10.0, floor(log10(x)) - 1);
    return nearbyint(x / p) * p;
}

/* "time: [run 1 ]about 1.3 s of CPU (1.33 s: ...)": one run's line. */
static void print_run(FILE *f, const char *label, const run_est *e)
{
    char t[32], a[32], si[32], so[32], ei[32], eo[32];
    cli_progress_duration(e->cpu, t, sizeof t);
    adh_format_quantity(e->c.a_turn, ADH_Q_LENGTH, 3, a, sizeof a);
    adh_format_quantity(e->c.step_in, ADH_Q_LENGTH, 3, si, sizeof si);
    adh_format_quantity(e->c.step_out, ADH_Q_LENGTH, 3, so, sizeof so);
    adh_format_quantity(e->c.E_in, ADH_Q_PRESSURE, 3, ei, sizeof ei);
    adh_format_quantity(e->c.E_out, ADH_Q_PRESSURE, 3, eo, sizeof eo);
    int one = strcmp(ei, eo) == 0;   /* the same both ways: say it once */
    if (e->c.rothe) {
        fprintf(f, "time: %sabout %s of CPU (%.3g s: about %.0f integrator steps (Rothe steps), %.0f out of contact, the "
                   "base 0.4 z0 a step, and %.0f as the contact line moves out to %s and back, %s a step in and %s out "
                   "as q's error allows, measured, at least the base 0.17 z0 a step in contact; a step about %.3g ms: "
                   "%.2g times IDAS's price for its Newton and GMRES iterations, ", label, t, e->cpu,
                two_digits(e->c.steps), two_digits(e->c.free_steps), two_digits(e->c.contact_steps), a, si, so,
                e->step * 1e3, e->c.work);
    } else {
        fprintf(f, "time: %sabout %s of CPU (%.3g s: about %.0f integrator steps, %.0f out of contact and %.0f as the "
                   "contact line moves out to %s and back, %s a step in and %s out: 0.068 edge zones at the effective "
                   "modul%s %s%s%s, measured, at least 60 a branch; ", label, t, e->cpu, two_digits(e->c.steps), two_digits(e->c.free_steps),
                two_digits(e->c.contact_steps), a, si, so, one ? "us" : "i", ei, one ? "" : " and ", one ? "" : eo);
        if (e->c.lattice > 1.05)
            fprintf(f, "%.2g times that for the lattice folds of a solid near elastic (Einf/E0 = %.3g); ", e->c.lattice,
                    e->c.E_ratio);
        fprintf(f, "15 %% more for jumps and rejected steps; a step about %.3g ms: ", e->step * 1e3);
    }
    fprintf(f, "14 kernel products of %.3g ms, ", e->grid.product * 1e3);
    if (e->lu_nodes)
        fprintf(f, "a dense LU of %zu nodes (%.3g ms), ", e->lu_nodes, e->lu * 1e3);
    else if (e->grid.hierarchical)
        fprintf(f, "HODLR solves and updates about 40 products' worth, ");
    char scaled[96] = "";
    if (e->grid.timed_n < e->grid.n)
        snprintf(scaled, sizeof scaled, "; the kernel's product and build timed on %zu nodes and scaled as N^2",
                 e->grid.timed_n);
    fprintf(f, "70 passes of the law over %zu nodes (%.3g us each), timed now; the kernel built in %.2g s%s); ",
            e->grid.n, e->grid.pass * 1e6, e->build, scaled);
    /* a spring's steps are not modelled: measured, its run takes more, the
     * softer the more (docs/viscoelastic.md), beyond the factor of 3 */
    if (isfinite(e->c.spring))
        fprintf(f, "not counted: the steps the spring adds, the softer the more (measured at sigma 2.25 and 7.5, "
                   "1 um/s: 1.4 to 2.2 times the steps at 1 N/m, 4.2 to 5.2 at 1 mN/m, up to 10 times the CPU)\n");
    else
        fprintf(f, "within a factor of about 3 where the grid resolves the contact's edge zone, slower where it does "
                   "not\n");
}

/* "time: about 0.4 s of CPU (...)": an elastic path's line. */
static void print_path(FILE *f, const char *label, const run_est *e)
{
    char t[32];
    cli_progress_duration(e->cpu, t, sizeof t);
    fprintf(f, "time: %sabout %s of CPU (%.3g s: no time integration, an elastic sphere is rate-independent: its "
               "static curve, about %.0f points (%s), a point about %.3g ms: ", label, t, e->cpu, two_digits(e->c.steps),
            e->exact ? "the exact curve, every fold" : "steps over the lattice folds", e->step * 1e3);
    if (e->lu_nodes)
        fprintf(f, "90 kernel products of %.3g ms and a quarter of a dense LU of %zu nodes (%.3g ms), ",
                e->grid.product * 1e3, e->lu_nodes, e->lu * 1e3);
    else
        fprintf(f, "215 kernel products' worth of %.3g ms (HODLR), ", e->grid.product * 1e3);
    fprintf(f, "timed now; the kernel built in %.2g s); within a factor of about 3\n", e->build);
}

void cli_estimate_time_print(FILE *f, const adh_config *cfg, const adh_plan *plan)
{
    static adh_plan_progress runs[ADH_PLAN_MAX_RUNS];
    size_t n = plan->nruns < ADH_PLAN_MAX_RUNS ? plan->nruns : ADH_PLAN_MAX_RUNS;
    grid_cost gc = { .g = NULL, .n = 0 };
    run_est e = { .cpu = 0 }, first = e;
    double cpu = 0, steps = 0, smin = INFINITY, smax = 0;
    int first_sls = 0, sls = 0, paths = 0;   /* a sweep of the material has both kinds */
    for (size_t j = 0; j < n; j++) {
        /* a study past the runs the plan lists: n runs spread over it, the
         * first and the last among them (its first n were taken for all: a
         * sweep of 64 speeds down from 1 m/s counted 64 fast runs) */
        size_t i = n < plan->nruns ? (j * (plan->nruns - 1) + (n - 1) / 2) / (n - 1) : j;
        adh_run_spec s;
        adh_config_sweep_run(cfg, i, &s);
        if ((s.time.sls ? run_estimate(&s, &gc, &e) : path_estimate(&s, &gc, &e)) != 0) {
            adh_grid_free(gc.g);
            fprintf(f, "time: not estimated (the kernel could not be built here)\n");
            return;
        }
        if (j == 0)
            first = e, first_sls = s.time.sls;
        sls |= s.time.sls;
        paths |= !s.time.sls;
        runs[j] = (adh_plan_progress){ .cost = e.cpu };
        cpu += e.cpu;
        steps += e.c.steps;
        smin = fmin(smin, e.c.steps);
        smax = fmax(smax, e.c.steps);
    }
    adh_grid_free(gc.g);
    if (n > 1) {
        /* a study past the runs the plan lists: the rest taken at the
         * mean of the runs estimated, and said so ("in all" summed 32 of 2000) */
        double all = (double)plan->nruns / (double)n;
        char t[32], w[32], rest[128] = "";
        cli_progress_duration(cpu * all, t, sizeof t);
        cli_progress_duration(adh_plan_time_left(runs, n, plan->jobs, 0, 1.0) * all, w, sizeof w);
        if (n < plan->nruns)
            snprintf(rest, sizeof rest, "; the other %zu runs taken at the mean of %zu spread over runs 1 to %zu",
                     plan->nruns - n, n, plan->nruns);
        fprintf(f, "time: about %s of CPU in all, %s on %d core%s (%.3g s: about %.0f %s, %.0f to %.0f "
                   "a run, each run's as run 1's below%s)\n", t, w, plan->jobs, plan->jobs == 1 ? "" : "s", cpu * all,
                two_digits(steps * all),
                sls && paths ? "integrator steps and static curve points" : sls ? "integrator steps"
                                                                         : "static curve points",
                two_digits(smin), two_digits(smax), rest);
    }
    /* run 1's own kind: an elastic first run of a sweep of the material
     * was printed as an integrator's, "0 out of contact ... the effective
     * modulus 0 Pa" */
    (first_sls ? print_run : print_path)(f, n > 1 ? "run 1 " : "", &first);
}
