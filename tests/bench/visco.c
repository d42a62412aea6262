/* Benchmark of the viscoelastic solver (adhere/visco.h) against the
 * baselines of issue 29, each in this process on the same operator:
 *  1. the Figure-4-like cycle (E0 = 0.3 GPa, Einf = 3 GPa, tau = 1 ms,
 *     1 um/s, turn -5 nm) at N nodes against the relaxation's Figure 4
 *     cycle (E = 0.3 GPa, its default eps and mixing), on the dense and on
 *     the H^2 operator: the goal is a ratio of at most 1;
 *  2. the cycle at Tabor's sigma (default 75, E0 there, Einf = 10 E0,
 *     1 um/s, turn -5 nm) on the static curve's automatic grid, against
 *     the static curve itself: the goal is a ratio of at most 6.
 * Times are CPU seconds of this process (one thread: the run's time, less
 * the machine's other load), wall seconds beside them.
 * Usage: bench-visco [N [sigma [tol [refine]]]]  (make check's smoke: 100
 * and 2.25; N = 0 leaves the first out, sigma = 0 the second; tol: the
 * integrator's tolerance,
 * default the solver's, 5e-5; refine: the grids' spacing divided by this,
 * over the same radius and band, default 1: the convergence promise's
 * grid is 1.5; with either, the Figure-4-like rows leave the relaxation
 * out). BENCH_INTEGRATOR=idas in the environment: the IDAS path
 * (adh_visco_settings.integrator) instead of the default, for the record. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "adhere/kernel.h"
#include "adhere/relax.h"
#include "adhere/rings.h"
#include "adhere/rule_visco.h"
#include "adhere/runner.h"
#include "adhere/status.h"
#include "adhere/visco.h"

void openblas_set_num_threads(int);

typedef struct clock2 {
    double cpu, wall;
} clock2;

static clock2 now(void)
{
    struct timespec c, w;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
    clock_gettime(CLOCK_MONOTONIC, &w);
    clock2 t = { (double)c.tv_sec + 1e-9 * (double)c.tv_nsec, (double)w.tv_sec + 1e-9 * (double)w.tv_nsec };
    return t;
}

static clock2 since(clock2 t0)
{
    clock2 t = now();
    t.cpu -= t0.cpu;
    t.wall -= t0.wall;
    return t;
}

/* The viscoelastic cycle of material m (E = E0) with Einf = ratio E0. */
static double bench_tol; /* 0: the solver's default */
static double bench_refine = 1; /* the grids' spacing over this */
static int bench_integrator = ADH_VISCO_AUTO; /* BENCH_INTEGRATOR=idas: the IDAS path for the record */

/* The machine, as /proc/cpuinfo names it. */
static void machine(void)
{
    char line[256];
    FILE *f = fopen("/proc/cpuinfo", "r");
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
            printf("machine: %s", strchr(line, ':') + 2);
            break;
        }
    if (f)
        fclose(f);
}

static int visco_cycle(const adh_grid *g, const adh_kernel *k, const adh_material *m, double ratio, clock2 *t,
                       adh_visco_result *res)
{
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(m->E);
    vs.sls.Einf = ratio * m->E;
    if (bench_tol > 0)
        vs.s.tol = bench_tol;
    vs.s.integrator = bench_integrator;
    adh_protocol_settings ps = adh_protocol_settings_default();
    adh_run run;
    adh_run_init(&run);
    clock2 t0 = now();
    adh_drive *d = adh_drive_alloc(&adh_rule_visco, g, k);
    int rc = d ? adh_drive_set(d, m, &vs, &ps, &run) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_runner_drive(d, NULL, NULL);
    *t = since(t0);
    if (d) {
        adh_visco_summary(adh_rule_visco_solver(d), res);
        if (rc != ADH_SUCCESS)   /* where and why, beside the bench's numbers */
            printf("  the viscoelastic cycle stopped at t = %.6g s, base %.6g m: %s\n",
                   adh_visco_time(adh_rule_visco_solver(d)), adh_visco_base(adh_rule_visco_solver(d)),
                   adh_visco_why(adh_rule_visco_solver(d)));
    }
    adh_drive_free(d);
    adh_run_free(&run);
    return rc;
}

/* The rest of the cycle's energy balance beside its hysteresis and
 * dissipated energy, which differ by these (no pair read alone): the
 * jumps' losses, the energy still stored when the base is back, and what
 * the balance leaves (the integration's error), as a fraction of the work. */
static void energy_line(const char *indent, const adh_visco_result *res)
{
    const adh_visco_energy *c = &res->cycle;
    double du = c->stored - c->stored0;
    printf("%sjump loss %.6g J, stored change %.6g J, energy residual %.2g of the work\n", indent, c->jumps, du,
           (res->hysteresis - c->dissipated - c->jumps - du) / res->hysteresis);
}

static int figure4(size_t n)
{
    adh_material m = adh_material_default();
    m.E = 0.3e9;
    adh_grid *g = adh_grid_alloc((size_t)lround((double)n * bench_refine), adh_grid_spacing_for(&m, n) / bench_refine);
    int bad = 0;
    printf("Figure-4-like viscoelastic cycle against the relaxation's Figure 4 cycle, N = %zu (spacing %.4g nm):\n", g->n,
           g->dr * 1e9);
    printf("%-7s %14s %14s %8s %6s %6s %s\n", "kernel", "relax CPU s", "visco CPU s", "ratio", "steps", "jumps",
           "(wall s: relax, visco)");
    adh_kernel_storage st[2] = { ADH_STORAGE_DENSE, ADH_STORAGE_H2 };
    for (int i = 0; i < 2; i++) {
        adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER, .storage = st[i] }, NULL);
        adh_relax_settings rs = adh_relax_settings_default();
        adh_protocol_settings ps = adh_protocol_settings_default();
        adh_run run;
        adh_run_init(&run);
        clock2 t0 = now();
        /* a convergence run (another tolerance or grid) wants the cycle's
         * numbers alone */
        int conv = bench_tol > 0 || bench_refine != 1;
        int rc = conv ? ADH_SUCCESS : adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &run);
        clock2 tr = since(t0), tv;
        adh_run_free(&run);
        adh_visco_result res;
        int rv = visco_cycle(g, k, &m, 10.0, &tv, &res);
        if (conv)   /* no baseline, no ratio */
            printf("%-7s %14s %14.2f %8s %6zu %6zu (-, %.2f)%s\n", adh_kernel_storage_name(st[i]), "-", tv.cpu, "-",
                   res.steps, res.jumps, tv.wall, rv ? "  FAILED" : "");
        else
            printf("%-7s %14.2f %14.2f %8.3f %6zu %6zu (%.2f, %.2f)%s\n", adh_kernel_storage_name(st[i]), tr.cpu,
                   tv.cpu, tv.cpu / tr.cpu, res.steps, res.jumps, tr.wall, tv.wall, rc || rv ? "  FAILED" : "");
        printf("        pull-off %.6g N, jump-in %.6g m, jump-out %.6g m, hysteresis %.6g J, dissipated %.6g J\n",
               res.pulloff_F, res.jump_in_h0, res.jump_out_h0, res.hysteresis, res.cycle.dissipated);
        energy_line("        ", &res);
        bad |= rc != ADH_SUCCESS || rv != ADH_SUCCESS;
        adh_kernel_free(k);
    }
    adh_grid_free(g);
    return bad;
}

static int soft(double sigma)
{
    adh_material m = adh_material_default();
    m.E *= adh_material_sigma(&m) / sigma;
    double turn = adh_protocol_settings_default().turns[0];
    adh_rings_choice gc;
    char why[1024];
    if (adh_rings_choose(&m, ADH_GRID_STATIC, turn, 1, &gc, why, sizeof why, NULL) != ADH_SUCCESS) {
        printf("sigma = %g: refused: %s\n", sigma, why);
        return 1;
    }
    adh_grid *g;
    if (gc.graded) {
        adh_rings_spec rs = { .dr = gc.dr / bench_refine, .fine = gc.fine, .ratio = gc.ratio, .rmax = gc.rmax };
        g = adh_rings_alloc(&rs);
    } else {
        double dr = isnan(gc.dr) ? adh_grid_spacing_for(&m, gc.n) : gc.dr;
        g = adh_grid_alloc((size_t)lround((double)gc.n * bench_refine), dr / bench_refine);
    }
    adh_kernel_settings ks = { .type = gc.graded ? ADH_KERNEL_RING : ADH_KERNEL_PAPER,
                               .storage = gc.hierarchical ? ADH_STORAGE_H2 : ADH_STORAGE_DENSE };
    adh_kernel *k = adh_kernel_alloc(g, &ks, NULL);
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_end = turn;
    adh_run run;
    adh_run_init(&run);
    adh_static_result sr;
    clock2 t0 = now();
    int rc = adh_runner_static_curve(g, k, &m, &ss, NULL, NULL, &run, &sr);
    clock2 ts = since(t0), tv;
    adh_run_free(&run);
    adh_visco_result res;
    int rv = visco_cycle(g, k, &m, 10.0, &tv, &res);
    printf("\nsigma = %g (E0 = %.3g Pa, Einf = 10 E0, tau = 1 ms, 1 um/s, tolerance %g), %s grid of %zu nodes "
           "(spacing %.4g nm), %s:\n",
           sigma, m.E, bench_tol > 0 ? bench_tol : adh_visco_settings_default().tol, gc.graded ? "graded" : "uniform",
           g->n, g->dr * 1e9, gc.hierarchical ? "H^2" : "dense");
    printf("  static curve %.2f CPU s, viscoelastic cycle %.2f CPU s: ratio %.2f (goal 6)\n", ts.cpu, tv.cpu,
           tv.cpu / ts.cpu);
    if (rc || rv)
        printf("  FAILED: the static curve %s, the viscoelastic cycle %s\n", adh_strerror(rc), adh_strerror(rv));
    printf("  (wall %.2f and %.2f s; %zu steps, %zu jumps, %zu lattice jumps, %zu relaxed, %zu folds resumed, %zu "
           "factorizations, %zu Newton and %zu GMRES iterations)\n",
           ts.wall, tv.wall, res.steps, res.jumps, res.lattice_jumps, res.jumps_relaxed, res.folds_resumed, res.setups,
           res.newton, res.krylov);
    printf("  pull-off %.6g N, jump-in %.6g m, jump-out %.6g m, hysteresis %.6g J, dissipated %.6g J\n", res.pulloff_F,
           res.jump_in_h0, res.jump_out_h0, res.hysteresis, res.cycle.dissipated);
    energy_line("  ", &res);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc != ADH_SUCCESS || rv != ADH_SUCCESS;
}

int main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 1000;
    double sigma = argc > 2 ? atof(argv[2]) : 75;
    bench_tol = argc > 3 ? atof(argv[3]) : 0;
    bench_refine = argc > 4 ? atof(argv[4]) : 1;
    if (!(bench_refine >= 1 && bench_refine <= 4)) {
        fprintf(stderr, "bench-visco: refine %s is not allowed: from 1 to 4\n", argv[4]);
        return 2;
    }
    const char *in = getenv("BENCH_INTEGRATOR");
    if (in && strcmp(in, "idas") && strcmp(in, "rothe") && strcmp(in, "auto")) {
        fprintf(stderr, "bench-visco: BENCH_INTEGRATOR=%s is not allowed: idas, rothe or auto\n", in);
        return 2;
    }
    bench_integrator = !in || !strcmp(in, "auto") ? ADH_VISCO_AUTO : !strcmp(in, "idas") ? ADH_VISCO_IDAS : ADH_VISCO_ROTHE;
    openblas_set_num_threads(1);
    machine();
    printf("integrator: %s\n", bench_integrator == ADH_VISCO_IDAS     ? "IDAS"
                              : bench_integrator == ADH_VISCO_ROTHE ? "Rothe"
                                                                    : "auto (Rothe without a spring, Einf <= 10 E0)");
    int bad = n ? figure4(n) : 0;   /* N = 0: sigma's cycle alone */
    bad |= sigma > 0 ? soft(sigma) : 0;   /* sigma = 0: the N cycle alone */
    return bad;
}
