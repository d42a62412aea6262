/* One point of the grid-resolution study (docs/convergence.md, "Resolution"): a load and
 * unload cycle at a given sigma on a uniform grid of spacing x edge-zone
 * widths, in the relaxation or the static mode. With normal lengths in z0
 * and lateral ones in sqrt(R z0) the problem depends on sigma alone, so R,
 * z0 and A stay the paper's and E sets sigma.
 *
 * Usage: bench-gridstudy MODE SIGMA X [TURN_Z0 [RMAX]]
 *   MODE relax | static; X = spacing / l, l = (243 pi^2/128) E z0^4 / A;
 *   TURN_Z0 the turning point in z0 (default -2); RMAX the grid radius in
 *   sqrt(R z0) (default 12). In relax mode eps = 1 pm, which means one
 *   drive on every grid (adh_relax_measure: the change's norm over the
 *   paper grid's radius), so refining the grid does not also change the
 *   drive.
 * Prints one tab-separated line: mode sigma x N spacing pulloff_F jump_in_h0
 * hysteresis seconds status. Not part of make bench (minutes per point). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/static.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/protocol.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "adhere/cycle.h"

void openblas_set_num_threads(int);

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: %s relax|static SIGMA X [TURN_Z0 [RMAX]]\n", argv[0]);
        return 2;
    }
    openblas_set_num_threads(1);
    int statik = strcmp(argv[1], "static") == 0;
    double sigma = atof(argv[2]), x = atof(argv[3]);
    double turn_z0 = argc > 4 ? atof(argv[4]) : -2.0;
    double rmax_l = argc > 5 ? atof(argv[5]) : 12.0;
    adh_material m = adh_material_default();
    m.E = adh_material_modulus_at_sigma(&m, sigma);
    double lat = sqrt(m.R * m.z0);
    double dr = x * adh_edge_zone(&m);
    size_t n = (size_t)ceil(rmax_l * lat / dr);
    adh_grid *g = adh_grid_alloc(n, dr);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    if (!k)
        return 1;
    adh_run run;
    adh_run_init(&run);
    double step = 0.05e-9, pulloff, jump_in, hyst;
    int rc;
    if (statik) {
        adh_static_settings s = adh_static_settings_default();
        s.h0_start = adh_protocol_auto_start(&m, step);
        s.h0_end = turn_z0 * m.z0;
        adh_static_result res;
        rc = adh_runner_static_curve(g, k, &m, &s, NULL, NULL, &run, &res);
        pulloff = res.pulloff_F;
        jump_in = res.jump_in_h0;
        hyst = adh_cycle_static_hysteresis(&run, 0.001e-9);
    } else {
        adh_relax_settings rs = adh_relax_settings_default();
        rs.eps = 1e-12;
        adh_protocol_settings ps = adh_protocol_settings_default();
        ps.turns[0] = turn_z0 * m.z0;
        rc = adh_runner_rule(&adh_rule_relax, g, k, &m, &rs, &ps, NULL, NULL, &run);
        const adh_turn_result *t = adh_run_main_turn(&run);
        pulloff = t ? t->pulloff_F : NAN;
        jump_in = run.jump_in_h0;
        hyst = adh_cycle_run_hysteresis(&run);
    }
    printf("%s\t%g\t%g\t%zu\t%.6g\t%.8g\t%.8g\t%.8g\t%.1f\t%s\n", argv[1], sigma, x, n, dr, pulloff,
           jump_in, hyst, run.seconds, adh_strerror(rc));
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc == ADH_SUCCESS ? 0 : 1;
}
