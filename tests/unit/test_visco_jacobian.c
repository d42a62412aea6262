/* The viscoelastic solver's linear algebra against differences of its own
 * residual: the Newton matrix's products (one kernel product each) match
 * a difference quotient of the residual, and the preconditioner inverts
 * them, on a state in contact, with and without a spring, dense and H^2.
 * Internal (src/core/visco.h). */
#include <math.h>
#include <stdio.h>

#include "core/visco.h"
#include "adhere/rings.h"
#include "tap.h"
#include "visco_fixture.h"

static void check(const char *what, adh_kernel_storage storage, double spring, double pre_tol)
{
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(FIX_N, adh_grid_default_spacing(&m));
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_RING, .storage = storage }, NULL);
    adh_sls sls = { m.E, 10 * m.E, FIX_TAU };
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = spring;
    adh_visco_settings s = adh_visco_settings_default();
    s.integrator = ADH_VISCO_IDAS; /* its Jacobian and preconditioner are what is checked */
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    adh_run run;
    adh_run_init(&run);
    adh_visco *w = adh_visco_alloc(g, k);
    int rc = adh_visco_set(w, &m, &sls, &d, &s, &ps, &run, NULL, 0);
    while (rc == ADH_SUCCESS || rc == ADH_CONTINUE) {
        rc = adh_visco_iterate(w);
        if (run.nrows && run.rows[run.nrows - 1].a > 20 * adh_rings_width(g, 0) && w->mode == MODE_PATH)
            break;
    }
    ok(rc == ADH_CONTINUE, "%s: in contact (%zu rows)", what, run.nrows);
    double worst_fd = 0, worst_pre = 0;
    for (double cj = 1; cj <= 1e4; cj *= 100) {
        double fd, pre;
        rc = adh_visco_dae_check(w, cj, &fd, &pre);
        worst_fd = fmax(worst_fd, fd);
        worst_pre = fmax(worst_pre, pre);
        printf("# %s, cj %g: products against differences %.3g, preconditioned %.3g\n", what, cj, fd, pre);
    }
    ok(rc == ADH_SUCCESS && worst_fd < 1e-6, "%s: the Newton matrix's products match the residual's differences (%.2g)",
       what, worst_fd);
    ok(worst_pre < pre_tol, "%s: the preconditioner inverts them to %.2g of a tolerance (%.2g allowed)", what,
       worst_pre, pre_tol);
    adh_visco_free(w);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
}

int main(void)
{
    check("dense", ADH_STORAGE_DENSE, INFINITY, 0.05);
    check("dense, 10 N/m spring", ADH_STORAGE_DENSE, 10, 0.05);
    check("H^2", ADH_STORAGE_H2, INFINITY, 0.5);
    check("H^2, 10 N/m spring", ADH_STORAGE_H2, 10, 0.5);
    return tap_done();
}
