/* Energy over a cycle: the base's work equals the change of the stored
 * energy (elastic, with q's part, the surface's and the spring's) plus
 * the viscous dissipation plus what the jumps released, each computed on
 * its own (work and dissipation integrated along the path, stored energy
 * from the states, a jump's loss as the stored energy before minus after);
 * within 1 %. With Einf = E0 there is no dissipation, and the work over a
 * cycle is the static curve's hysteresis, the area between its stable
 * branches (adh_cycle_static_hysteresis). */
#include <math.h>
#include <stdio.h>

#include "adhere/cycle.h"
#include "tap.h"
#include "visco_fixture.h"

static void closes(const fixture *f, double ratio, adh_visco_drive d, const char *what)
{
    vrun v = fix_visco(f, ratio, &d, 1e-4);
    const adh_visco_energy *e = &v.r.cycle;
    double gap = energy_gap(e);
    printf("# %s: work %.5g J = dU %.5g + dissipated %.5g + jumps %.5g (%zu), gap %.2g\n", what, e->work,
           e->stored - e->stored0, e->dissipated, e->jumps, v.r.jumps, gap);
    ok(v.rc == ADH_SUCCESS && fabs(gap) < 1e-2, "%s: the energy closes to %.2g (1 %% allowed)", what, gap);
    int pos = e->dissipated >= 0;
    for (size_t i = 0; i < v.nev; i++)
        if (v.ev[i].kind == ADH_VISCO_JUMP)
            pos &= v.ev[i].loss > 0;
    ok(pos, "%s: dissipation and every jump's loss are positive", what);
    vrun_free(&v);
}

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    adh_visco_drive d = fix_drive(1e-5, 1e-5);
    closes(&f, 10.0, d, "Einf = 10 E0 at 1e-5 m/s (a jump out)");
    d = fix_drive(1e-7, 1e-6);
    d.dwell = 5 * FIX_TAU;
    closes(&f, 10.0, d, "in at 1e-7 m/s, 5 tau held, out at 1e-6 m/s");
    d = fix_drive(1e-6, 1e-6);
    d.spring = 10;
    closes(&f, 10.0, d, "through a 10 N/m spring at 1e-6 m/s (snap-in and snap-out)");

    adh_run st;
    adh_static_result sr;
    ok(fix_static(&f, f.m.E, 0.5, &st, &sr) == ADH_SUCCESS, "the static curve at E0");
    double area = adh_cycle_static_hysteresis(&st, 1e-13);
    d = fix_drive(1e-6, 1e-6);
    vrun v = fix_visco(&f, 1.0, &d, 1e-4);
    ok(v.rc == ADH_SUCCESS && v.r.cycle.dissipated == 0, "Einf = E0: no dissipation");
    ok_rel(v.r.hysteresis, area, 1e-2, "Einf = E0: the work over the cycle is the static hysteresis area");
    ok_rel(v.r.cycle.jumps, area, 1e-2, "Einf = E0: ... and what the two jumps released");
    vrun_free(&v);
    adh_run_free(&st);
    fix_close(&f);
    return tap_done();
}
