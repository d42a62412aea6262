/* The numbers converge: halving the integrator's tolerance, and refining
 * the grid 1.5x at the same radius, move the pull-off, the jump-in and
 * jump-out positions and the hysteresis by less than 0.5 %, at 1e-6 m/s
 * (no jump: contact forms and is lost smoothly) and 1e-5 m/s (the surfaces
 * jump apart across a fold of the instantaneous problem). */
#include <math.h>
#include <stdio.h>

#include "tap.h"
#include "visco_fixture.h"

typedef struct nums {
    int rc;
    double pull, in, out, hyst;
} nums;

static nums cycle(size_t n, double spacing_factor, double tol, double V)
{
    fixture f = fix_open(n, spacing_factor);
    adh_visco_drive d = fix_drive(V, V);
    vrun v = fix_visco(&f, 10.0, &d, tol);
    nums x = { v.rc, v.r.pulloff_F, v.r.jump_in_h0, v.r.jump_out_h0, v.r.hysteresis };
    vrun_free(&v);
    fix_close(&f);
    return x;
}

static void moved(const char *what, double V, const nums *a, const nums *b)
{
    double d[4] = { fabs(b->pull / a->pull - 1), fabs(b->in / a->in - 1), fabs(b->out / a->out - 1),
                    fabs(b->hyst / a->hyst - 1) };
    ok(a->rc == ADH_SUCCESS && b->rc == ADH_SUCCESS && d[0] < 5e-3 && d[1] < 5e-3 && d[2] < 5e-3 && d[3] < 5e-3,
       "%g m/s, %s: pull-off %.2g, jump-in %.2g, jump-out %.2g, hysteresis %.2g (relative moves; 0.5 %% allowed)", V,
       what, d[0], d[1], d[2], d[3]);
}

int main(void)
{
    double V[2] = { 1e-6, 1e-5 };
    for (int i = 0; i < 2; i++) {
        nums base = cycle(FIX_N, 1.0, 1e-4, V[i]);
        nums tight = cycle(FIX_N, 1.0, 5e-5, V[i]);
        nums fine = cycle(FIX_N * 3 / 2, 1.0 / 1.5, 1e-4, V[i]);
        moved("tolerance halved", V[i], &base, &tight);
        moved("grid 1.5x finer", V[i], &base, &fine);
    }
    return tap_done();
}
