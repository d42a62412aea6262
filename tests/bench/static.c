/* Benchmark of the equilibrium (static) mode: the whole S-curve for the
 * paper's Figure 1 material (E = 1 GPa, A = 1e-19 J, z0 = 0.5 nm, R = 10 um,
 * N = 1000, spacing 1.5 nm, paper kernel) from the automatic start down to
 * -5 nm. Target (issue 6): under 2 s on one core (OPENBLAS_NUM_THREADS=1).
 * Optional arguments: N, E (Pa), kernel ("paper" | "ring"). */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "adhere/static.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/status.h"
#include "adhere/runner.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of this process: on a loaded machine the wall time overstates
 * what one core needs. */
static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void openblas_set_num_threads(int);

int main(int argc, char **argv)
{
    openblas_set_num_threads(1); /* the target is for one core */
    adh_material m = adh_material_default();
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 1000;
    if (argc > 2)
        m.E = atof(argv[2]);
    adh_kernel_type kt = ADH_KERNEL_PAPER;
    if (argc > 3 && adh_kernel_parse(argv[3], &kt) != 0) {
        fprintf(stderr, "kernel must be paper or ring\n");
        return 2;
    }
    adh_derived d;
    adh_material_derive(&m, &d);
    double t0 = now();
    adh_grid *g = adh_grid_alloc(n, 1.5e-9);
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = kt }, NULL) : NULL;
    if (!k) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    double t_kernel = now() - t0;
    adh_static_settings s = adh_static_settings_default();
    /* tuning knobs, not part of the benchmark's contract */
    if (getenv("ADH_DS_MAX")) s.ds_max = atof(getenv("ADH_DS_MAX"));
    if (getenv("ADH_ANGLE")) s.max_angle = atof(getenv("ADH_ANGLE"));
    if (getenv("ADH_ACTIVE")) s.active_tol = atof(getenv("ADH_ACTIVE"));
    if (getenv("ADH_TOL")) s.tol = atof(getenv("ADH_TOL"));
    if (getenv("ADH_UW")) s.u_weight = atof(getenv("ADH_UW"));
    if (getenv("ADH_GAP")) s.max_gap_step = atof(getenv("ADH_GAP"));
    adh_run run;
    adh_run_init(&run);
    adh_static_result r;
    t0 = now();
    double c0 = cpu();
    int rc = adh_runner_static_curve(g, k, &m, &s, NULL, NULL, &run, &r);
    double t_run = now() - t0, c_run = cpu() - c0;
    printf("static: N=%zu kernel=%s E=%g sigma=%.3f status=%s\n", n, adh_kernel_name(kt), m.E, d.sigma,
           adh_strerror(rc));
    printf("  kernel build      %.3f s\n", t_kernel);
    printf("  whole curve       %.3f s CPU, %.3f s wall (target < 2 s on one core)\n", c_run, t_run);
    printf("  points %zu, rejected %zu, Newton iterations %zu, GMRES iterations %zu, LU factorizations %zu\n",
           r.points, r.rejected, r.newton_iterations, r.krylov_iterations, r.factorizations);
    printf("  folds %zu  jump_in_h0 %.4g nm  jump_out_h0 %.4g nm\n", r.folds, r.jump_in_h0 * 1e9,
           r.jump_out_h0 * 1e9);
    printf("  pulloff_F %.5g N (JKR %.5g, DMT %.5g)  pulloff_F_disp %.5g N\n", r.pulloff_F, d.F_jkr, d.F_dmt,
           r.pulloff_F_disp);
    if (getenv("ADH_BENCH_ROWS"))
        for (size_t i = 0; i < run.nrows; i++)
            printf("%zu %.6g %.6g %.6g %d %d %zu\n", i, run.rows[i].h0 * 1e9, run.rows[i].F, run.rows[i].a * 1e9,
                   run.rows[i].branch, run.rows[i].stable, run.rows[i].iters);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc == ADH_SUCCESS ? 0 : 1;
}
