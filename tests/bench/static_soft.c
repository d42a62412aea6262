/* Benchmark of the static curve at large sigma on the grid a run gets by
 * default (adh_rings_choose for the static curve: the spacing at the
 * resolved limit 0.3 l, graded and hierarchical past 1000 nodes), with the
 * pull-off against Maugis-Dugdale. Issue 14's targets, one core: sigma =
 * 22.5 under 5 s, sigma = 75 under 15 s.
 * Arguments: sigma values (default 15 22.5 75); the material is the default
 * one with E set for each sigma. ADH_TURN (m, default -5e-9) is the curve's
 * end, as --turn. A sigma whose grid the budget refuses is reported so. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/maugis.h"
#include "adhere/rings.h"
#include "adhere/static.h"
#include "adhere/status.h"

static double cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void openblas_set_num_threads(int);

static int one(double sigma, double turn)
{
    adh_material m = adh_material_default();
    m.E *= adh_material_sigma(&m) / sigma; /* sigma is proportional to 1/E */
    adh_rings_choice gc;
    char why[1024];
    if (adh_rings_choose(&m, ADH_GRID_STATIC, turn, 1, &gc, why, sizeof why, NULL) != ADH_SUCCESS) {
        printf("static sigma=%.4g: refused: %s\n", sigma, why);
        return 0;
    }
    double c0 = cpu();
    adh_grid *g;
    if (gc.graded) {
        adh_rings_spec rs = { .dr = gc.dr, .fine = gc.fine, .ratio = gc.ratio, .rmax = gc.rmax };
        g = adh_rings_alloc(&rs);
    } else {
        g = adh_grid_alloc(gc.n, isnan(gc.dr) ? adh_grid_spacing_for(&m, gc.n) : gc.dr);
    }
    adh_kernel_type kt = gc.graded ? ADH_KERNEL_RING : ADH_KERNEL_PAPER;
    adh_kernel_settings ks = { .type = kt, .storage = gc.hierarchical ? ADH_STORAGE_H2 : ADH_STORAGE_DENSE };
    adh_kernel *k = g ? adh_kernel_alloc(g, &ks, NULL) : NULL;
    if (!k) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    double c_kernel = cpu() - c0;
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = turn;
    /* tuning knobs, not part of the benchmark's contract */
    if (getenv("ADH_GAP"))
        s.max_gap_step = atof(getenv("ADH_GAP"));
    if (getenv("ADH_DS_MAX"))
        s.ds_max = atof(getenv("ADH_DS_MAX"));
    if (getenv("ADH_UW"))
        s.u_weight = atof(getenv("ADH_UW"));
    if (getenv("ADH_SKIP"))
        s.lattice_skip = atoi(getenv("ADH_SKIP"));
    if (getenv("ADH_ANGLE"))
        s.max_angle = atof(getenv("ADH_ANGLE"));
    adh_static_result r;
    c0 = cpu();
    adh_static *w = adh_static_alloc(g, k);
    if (!w) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    int rc = adh_static_set(w, &m, &s);
    while (rc == ADH_CONTINUE || rc == ADH_SUCCESS) {
        rc = adh_static_iterate(w);
        if (rc == ADH_SUCCESS)
            break;
    }
    double c_run = cpu() - c0;
    adh_static_summary(w, &r);
    if (getenv("ADH_FOLDS")) {
        const adh_static_fold *f;
        size_t nf = adh_static_folds(w, &f);
        for (size_t i = 0; i < nf; i++)
            printf("  fold %zu: h0 %.6f nm, F %.6g N, kind %+d\n", i, f[i].h0 * 1e9, f[i].F, f[i].kind);
    }
    adh_static_free(w);
    double F_md = NAN;
    adh_md_pulloff(&m, adh_md_lambda(&m), &F_md, NULL, NULL, NULL);
    printf("static sigma=%.4g E=%.4g Pa: %s grid, N=%zu, spacing %.3g m, %s kernel (%s), status %s\n", sigma, m.E,
           gc.graded ? "graded" : "uniform", g->n, gc.dr, adh_kernel_name(kt), gc.hierarchical ? "h2" : "dense",
           adh_strerror(rc));
    printf("  kernel %.2f s CPU, curve %.2f s CPU\n", c_kernel, c_run);
    printf("  points %zu, rejected %zu, Newton %zu, GMRES %zu, LU factorizations %zu, folds %zu\n", r.points,
           r.rejected, r.newton_iterations, r.krylov_iterations, r.factorizations, r.folds);
    printf("  jump-in %.6f nm, jump-out %.6f nm, pull-off %.9g N\n", r.jump_in_h0 * 1e9, r.jump_out_h0 * 1e9, r.pulloff_F);
    printf("  jump-in %.4f nm, jump-out %.4f nm, pull-off %.5g N, Maugis-Dugdale %.5g N, ratio %.4f\n",
           r.jump_in_h0 * 1e9, r.jump_out_h0 * 1e9, r.pulloff_F, F_md, r.pulloff_F / F_md);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc == ADH_SUCCESS ? 0 : 1;
}

int main(int argc, char **argv)
{
    openblas_set_num_threads(1); /* the targets are for one core */
    double turn = getenv("ADH_TURN") ? atof(getenv("ADH_TURN")) : -5e-9;
    int bad = 0;
    if (argc < 2) {
        bad |= one(15, turn);
        bad |= one(22.5, turn);
        bad |= one(75, turn);
    }
    for (int i = 1; i < argc; i++)
        bad |= one(atof(argv[i]), turn);
    return bad;
}
