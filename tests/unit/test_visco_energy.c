/* Energy over a cycle: the base's work equals the change of the stored
 * energy (elastic, with q's part, the surface's and the spring's) plus
 * the viscous dissipation plus what the jumps released, each computed on
 * its own (work and dissipation integrated along the path, stored energy
 * from the states, a jump's loss as the stored energy before minus after);
 * within 1 %. With Einf = E0 there is no dissipation, and the work over a
 * cycle is the static curve's hysteresis, the area between its stable
 * branches (adh_cycle_static_hysteresis). Far from elastic on a coarse
 * grid (Einf = 1000 E0, 5 nm rings, no jump): the hysteresis is not the
 * dissipated energy alone (0.45 % apart) but closes with the energy still
 * stored when the base is back (stored_change), to the integration's
 * tolerance. */
#include <math.h>
#include <stdio.h>
#include <string.h>

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

/* A cycle far from elastic on a coarse grid: the visco scene's sphere (E0 = 0.3 GPa, R = 10 um,
 * sigma 7.5) far from elastic, Einf = 1000 E0, on 300 rings of 5 nm (0.7
 * nodes across its edge zone) at 1 um/s to -5 nm and back, at the
 * default tolerance and integrator (IDAS, past 10 E0). No jump of either
 * kind: the work is the dissipated energy plus the stored energy's change,
 * which the material, retracted within two tau of losing contact, still
 * holds (0.47 % of the work). Measured: residual 1.8e-4 of the work at
 * 5e-5, 1.6e-6 at 1.25e-5 (integration, not a missing term). */
static void far_from_elastic(void)
{
    adh_material m = adh_material_default();
    m.E = 0.3e9;
    adh_grid *g = adh_grid_alloc(300, 5e-9);
    adh_kernel *k = g ? adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    adh_sls sls = { m.E, 1000 * m.E, 1e-3 };
    adh_visco_drive d = adh_visco_drive_default();
    adh_visco_settings s = adh_visco_settings_default();
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = -5e-9;
    adh_run run;
    adh_run_init(&run);
    adh_visco *w = k ? adh_visco_alloc(g, k) : NULL;
    int rc = w ? adh_visco_set(w, &m, &sls, &d, &s, &ps, &run, NULL, 0) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_visco_run(w);
    adh_visco_result r;
    memset(&r, 0, sizeof r);
    if (w)
        adh_visco_summary(w, &r);
    const adh_visco_energy *e = &r.cycle;
    double du = e->stored - e->stored0, res = (e->work - e->dissipated - e->jumps - du) / e->work;
    printf("# Einf = 1000 E0, 5 nm rings: hysteresis %.6g J, dissipated %.6g, stored change %.4g (%.2g of it), "
           "jumps %zu + %zu lattice, residual %.2g of the work\n",
           r.hysteresis, e->dissipated, du, du / e->work, r.jumps, r.lattice_jumps, res);
    ok(rc == ADH_SUCCESS && r.jumps == 0 && r.lattice_jumps == 0 && e->jumps == 0,
       "Einf = 1000 E0 on 5 nm rings: the cycle runs, no jump (%s, %zu, %zu)", adh_strerror(rc), r.jumps,
       r.lattice_jumps);
    ok(fabs(res) < 1e-3, "... the work is the dissipated energy and the stored energy's change within 1e-3 (%.2g)", res);
    ok(du / e->work > 2e-3 && fabs(r.hysteresis - e->dissipated) / e->work > 2e-3,
       "... which differ from the dissipated energy alone by the energy still stored (%.2g, %.2g of the work)",
       du / e->work, (r.hysteresis - e->dissipated) / e->work);
    adh_visco_free(w);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* The Rothe steps' work quadrature at 1 mm/s on the Figure 1 sphere
 * (sigma0 = 2.25) at Einf = 10 E0, N = 400 of 3 nm, turn -3 nm: the force
 * changes 40 % a step at the base's 0.4 z0 cap, and before the steps were
 * bounded by the force's change their hysteresis lay 1.8 % below the
 * converged one (IDAS at a sixteenth of its tolerance) at any tolerance,
 * the balance as open. Now within 0.5 % of it, the balance closed within
 * ADH_VISCO_BALANCE_MAX; at a loose tolerance (3e-3: steps of 0.25 of the
 * force) the balance is open past it (1.7 % measured), which the CLI marks
 * unconverged. */
static adh_visco_result fast_cycle(const fixture *f, int integrator, double tol)
{
    adh_sls sls = { f->m.E, 10 * f->m.E, 1e-3 };
    adh_visco_drive d = fix_drive(1e-3, 1e-3);
    adh_visco_settings s = adh_visco_settings_default();
    s.integrator = integrator;
    s.tol = tol;
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = -3e-9;
    adh_run run;
    adh_run_init(&run);
    adh_visco *w = adh_visco_alloc(f->g, f->k);
    int rc = w ? adh_visco_set(w, &f->m, &sls, &d, &s, &ps, &run, NULL, 0) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_visco_run(w);
    adh_visco_result r;
    memset(&r, 0, sizeof r);
    r.hysteresis = NAN;
    if (w && rc == ADH_SUCCESS)
        adh_visco_summary(w, &r);
    adh_visco_free(w);
    adh_run_free(&run);
    return r;
}

static void fast_near_elastic(void)
{
    fixture f = fix_open(400, 2.0);   /* 3 nm: twice the paper's spacing */
    adh_visco_result ref = fast_cycle(&f, ADH_VISCO_IDAS, 5e-5 / 16);
    adh_visco_result ro = fast_cycle(&f, ADH_VISCO_ROTHE, 5e-5);
    adh_visco_result loose = fast_cycle(&f, ADH_VISCO_ROTHE, 3e-3);
    double open = adh_visco_balance_open(&ro), lopen = adh_visco_balance_open(&loose);
    printf("# 1 mm/s, 10 E0, sigma0 = 2.25: IDAS at tol/16 %.6g J; Rothe %.6g J (%zu steps, balance open %.2g), "
           "at 3e-3 %.6g J (%zu steps, open %.2g)\n",
           ref.hysteresis, ro.hysteresis, ro.steps, open, loose.hysteresis, loose.steps, lopen);
    ok(fabs(adh_visco_balance_open(&ref)) < ADH_VISCO_BALANCE_MAX, "1 mm/s at 10 E0: IDAS's balance closes (%.2g)",
       adh_visco_balance_open(&ref));
    ok_rel(ro.hysteresis, ref.hysteresis, 5e-3, "... the Rothe steps' hysteresis within 0.5 % of IDAS's at tol/16");
    ok(fabs(open) < ADH_VISCO_BALANCE_MAX, "... and their balance closes within %g (%.2g)", ADH_VISCO_BALANCE_MAX, open);
    ok(fabs(lopen) > ADH_VISCO_BALANCE_MAX, "... at a loose tolerance (3e-3) the balance is open past %g (%.2g): marked",
       ADH_VISCO_BALANCE_MAX, lopen);
    fix_close(&f);
}

int main(void)
{
    far_from_elastic();
    fast_near_elastic();
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
