/* Benchmark of the relaxation: milliseconds per iteration at several N,
 * beside the time to stream the kernel matrix once (the memory bound every
 * iteration pays), and optionally the whole Figure 4 load/unload cycle.
 * Prints medians of REPEAT runs. Usage: bench-relax [REPEAT] [cycle N]
 * BENCH_N=n measures that one size instead of 500 ... 4000 (make check runs
 * every bench once at a tiny size, so a broken bench fails the build). Exits
 * 1 when a cycle run fails. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_cblas.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/protocol.h"
#include "adhere/relax.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "scene/config.h"

void openblas_set_num_threads(int);

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Reading N*N doubles once, as a general matrix-vector product must, with
 * OpenBLAS's vectorised dasum: the memory floor of one iteration. (The
 * symmetric paper kernel needs only half of it through dsymv.) */
static double stream_seconds(size_t n)
{
    double *m = malloc(n * n * sizeof *m);
    for (size_t i = 0; i < n * n; i++)
        m[i] = 1.0 / (double)(i + 1);
    volatile double sink = 0;
    double best = INFINITY;
    for (int rep = 0; rep < 20; rep++) {
        double t0 = now();
        sink = cblas_dasum((int)(n * n), m, 1);
        best = fmin(best, now() - t0);
    }
    (void)sink;
    free(m);
    return best;
}

int main(int argc, char **argv)
{
    int repeat = argc > 1 ? atoi(argv[1]) : 5;
    size_t cycle_n = argc > 2 ? (size_t)atol(argv[2]) : 1000;
    if (repeat < 1)
        repeat = 1;
    openblas_set_num_threads(1);
    adh_config cfg;
    adh_config_default(&cfg);
    printf("relaxation: one iteration (eq 11 product, mixing, pressures) against streaming the kernel once\n");
    printf("%6s %10s %14s %14s %8s\n", "N", "kernel", "ms/iteration", "ms/stream", "ratio");
    size_t ns[] = { 500, 1000, 2000, 4000 }, nsizes = 4;
    if (getenv("BENCH_N") && atol(getenv("BENCH_N")) > 0) {
        ns[0] = (size_t)atol(getenv("BENCH_N"));
        nsizes = 1;
    }
    int failed = 0;
    for (size_t a = 0; a < nsizes; a++) {
        for (int kind = 0; kind < 2; kind++) {
            cfg.spec.grid.use.nodes = ns[a];
            adh_grid *g = adh_grid_alloc(cfg.spec.grid.use.nodes, adh_config_spacing(&cfg.spec));
            adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = (adh_kernel_type)kind }, NULL);
            adh_relax *w = adh_relax_alloc(g, k);
            adh_relax_settings rs = adh_relax_settings_default();
            rs.eps = 1e-30; /* never converged: every call is full iterations */
            adh_relax_set(w, &cfg.spec.mat, &rs, 0.3e-9); /* in contact: the costly regime */
            int iters = ns[a] >= 4000 ? 20 : 200;
            double t[15];
            for (int r = 0; r < repeat && r < 15; r++) {
                double t0 = now();
                adh_relax_iterate(w, (size_t)iters);
                t[r] = (now() - t0) / iters;
            }
            double it = median(t, repeat < 15 ? repeat : 15);
            double st = stream_seconds(ns[a]);
            printf("%6zu %10s %14.4f %14.4f %8.2f\n", ns[a], adh_kernel_name((adh_kernel_type)kind), it * 1e3, st * 1e3, it / st);
            adh_relax_free(w);
            adh_kernel_free(k);
            adh_grid_free(g);
        }
    }
    if (cycle_n) {
        cfg.spec.grid.use.nodes = cycle_n;
        adh_grid *g = adh_grid_alloc(cfg.spec.grid.use.nodes, adh_config_spacing(&cfg.spec));
        adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
        printf("\nFigure 4 cycle (N = %zu, eps = 1 pm, d = 0.05 nm, turn -5 nm), one core:\n", cycle_n);
        printf("%-14s %10s %7s %11s %10s %12s %14s\n", "mixing", "seconds", "steps", "iterations",
               "per step", "in contact", "pull-off (N)");
        /* The default first (median of up to 3); the others once each. The
         * paper's rule takes minutes: only with BENCH_PAPER=1. */
        const struct { adh_mix_rule rule; double beta; int runs; } rules[] = {
            { ADH_MIX_MOMENTUM, cfg.spec.relax.momentum, repeat < 3 ? repeat : 3 },
            { ADH_MIX_MOMENTUM, 0.8, 1 },
            { ADH_MIX_PAPER, 0, getenv("BENCH_PAPER") && atoi(getenv("BENCH_PAPER")) ? 1 : 0 },
        };
        for (size_t q = 0; q < sizeof rules / sizeof rules[0]; q++) {
            adh_relax_settings rs = cfg.spec.relax;
            rs.rule = rules[q].rule;
            rs.momentum = rules[q].beta;
            char name[32];
            adh_mix_rule_describe(&rs, name, sizeof name);
            if (rules[q].runs == 0) {
                printf("%-14s (BENCH_PAPER=1 runs it: about 5 minutes at N = 1000)\n", name);
                continue;
            }
            double t[3], pulloff = NAN;
            size_t iters = 0, steps = 0, contact_iters = 0, contact_steps = 0;
            for (int r = 0; r < rules[q].runs; r++) {
                adh_run run;
                adh_run_init(&run);
                double t0 = now();
                int rc = adh_runner_rule(&adh_rule_relax, g, k, &cfg.spec.mat, &rs, &cfg.spec.proto, NULL, NULL, &run);
                t[r] = now() - t0;
                if (rc != ADH_SUCCESS) {
                    fprintf(stderr, "bench-relax: the cycle with %s failed: %s\n", name, adh_strerror(rc));
                    failed = 1;
                }
                iters = run.iterations;
                steps = run.nrows;
                contact_iters = contact_steps = 0;
                for (size_t i = 0; i < run.nrows; i++)
                    if (run.rows[i].a > 0) {
                        contact_iters += run.rows[i].iters;
                        contact_steps++;
                    }
                pulloff = run.nturns ? run.turns[0].pulloff_F : NAN;
                adh_run_free(&run);
            }
            printf("%-14s %10.2f %7zu %11zu %10.0f %12.0f %14.5g\n", name, median(t, rules[q].runs), steps,
                   iters, (double)iters / (double)steps,
                   contact_steps ? (double)contact_iters / (double)contact_steps : NAN, pulloff);
        }
        printf("(seconds: median of %d for the first row; per step: all steps, and steps in contact)\n",
               repeat < 3 ? repeat : 3);
        adh_kernel_free(k);
        adh_grid_free(g);
    }
    return failed;
}
