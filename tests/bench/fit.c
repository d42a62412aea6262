/* make bench: adhere fit's cost. A two-parameter (E, A) static fit to the
 * shipped synthetic curve (share/adhere/data/fig1-synthetic.tsv: 200
 * points at Figure 1's parameters, 1 % noise) on Figure 1's automatic grid,
 * from starts off by (1.5, 0.7) and by a factor 3 (3, 1/3): model
 * evaluations, seconds, and the seconds as a ratio to one static curve
 * timed in the same process (the machine is shared: ratios travel, seconds
 * do not). The goal: at most 30 evaluations.
 *
 *   bench-fit              the benchmark
 *   bench-fit N DR         on a uniform grid of N nodes of spacing DR (m), the first start only
 *                          (make check's smoke run: N = 300, 2.5 nm)
 *   bench-fit write PATH   writes the synthetic curve (how the shipped file was made) */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../unit/synth.h"
#include "adhere/fit.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "scene/config.h"
#include "scene/fitdata.h"
#include "scene/measured.h"

void openblas_set_num_threads(int num_threads) __attribute__((weak));

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    if (openblas_set_num_threads)
        openblas_set_num_threads(1);
    gsl_set_error_handler_off(); /* as adhere does at start: the core reports by status */
    adh_material truth = adh_material_default();   /* Figure 1's */
    /* Figure 1's automatic static grid: N = 1000, the paper's 1.5 nm */
    int small = argc == 3 && strcmp(argv[1], "write") != 0;
    size_t nodes = small ? (size_t)atol(argv[1]) : 1000;
    double dr = small ? atof(argv[2]) : adh_grid_spacing_for(&truth, 1000);
    adh_grid *g = nodes >= 10 && dr > 0 ? adh_grid_alloc(nodes, dr) : NULL;
    if (!g) {
        fprintf(stderr, "usage: bench-fit [N DR | write PATH]\n");
        return 2;
    }
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    if (argc == 3 && strcmp(argv[1], "write") == 0) {
        static synth s;
        if (synth_make(&s, g, k, &truth, 8e-9, -2e-9, 100, 100, 0.01, 2026, 0, 0) != 0 ||
            synth_write(&s, argv[2], "adhere's static curve at Figure 1's parameters (E = 1 GPa, A = 1e-19 J, "
                        "z0 = 0.5 nm, R = 10 um; N = 1000, 1.5 nm), 100 points in and 100 out, Gaussian noise of "
                        "1 % of the JKR pull-off (3.75 nN, MT19937 seed 2026)") != 0) {
            fprintf(stderr, "bench-fit: cannot write %s\n", argv[2]);
            return 1;
        }
        return 0;
    }
    adh_measured m;
    adh_fitdata fd;
    char why[1024];
    const char *path = "share/adhere/data/fig1-synthetic.tsv";
    if (adh_measured_load(path, NULL, &m, why, sizeof why) != 0 ||
        adh_fitdata_make(&m, 2, &truth, 0, 0, &fd, why, sizeof why) != 0) {
        fprintf(stderr, "bench-fit: %s\n", why);
        return 1;
    }
    /* the baseline: one static curve at the truth, as a fit evaluates it */
    adh_fit_model_settings ms = adh_fit_model_settings_default();
    adh_fit_model *fm = adh_fit_model_alloc(g, k, &ms);
    double *F = malloc(fd.d.n * sizeof *F), t0 = now();
    adh_fit_model_eval(fm, &truth, 0, &fd.d, F, NULL);
    double t1 = now();
    adh_fit_model_eval(fm, &truth, 0, &fd.d, F, NULL);
    double curve = now() - t1;
    adh_fit_model_free(fm);
    free(F);
    printf("fit: E and A to %zu points at Figure 1's parameters (N = %zu, %.3g nm); one static curve %.2f s "
           "(the first, with the solver's setup, %.2f s)\n", fd.d.n, nodes, dr * 1e9, curve, t1 - t0);
    const double starts[2][2] = { { 1.5, 0.7 }, { 3.0, 1.0 / 3 } };
    for (int i = 0; i < (small ? 1 : 2); i++) {
        adh_fit_settings s = adh_fit_settings_default();
        s.start = truth;
        s.start.E *= starts[i][0];
        s.start.A *= starts[i][1];
        int st;
        adh_fit *f = adh_fit_alloc(g, k, &fd.d, &s, &st);
        adh_fit_result r;
        adh_fit_run(f, &r);
        adh_fit_free(f);
        printf("  start E x %.3g, A x %.3g: %zu evaluations (goal <= 30), %.1f s = %.1f static curves; "
               "E %.5g GPa +- %.2g %%, A %.5g J +- %.2g %%, chi2/dof %.3g, status %d\n", starts[i][0], starts[i][1],
               r.evals, r.seconds, r.seconds / curve, r.value[ADH_FIT_E] * 1e-9, 100 * r.se[ADH_FIT_E] / r.value[ADH_FIT_E],
               r.value[ADH_FIT_A], 100 * r.se[ADH_FIT_A] / r.value[ADH_FIT_A], r.chi2_red, r.status);
    }
    adh_fitdata_free(&fd);
    adh_measured_free(&m);
    adh_kernel_free(k);
    adh_grid_free(g);
    return 0;
}
