/* The viscoelastic solver on a grid far too coarse for the contact edge
 * (the Figure 4 sphere, sigma = 7.5, on 3x the paper's spacing: 4.5 nm,
 * 1.3 edge-zone widths), where the contact line snaps ring by ring across
 * a lattice fold of the grid at every ring it crosses: the crossings that
 * get lost and relax, the relaxations that stop in a vanished fold's
 * ghost, the landings next to a fold, the path the integrator cannot turn
 * in. Against the static curve on the same grid (the exact curve, every
 * fold resolved, a number the time solver does not produce): where
 * Einf = E0, and where tau -> 0 (10 ps at 1 um/s), the material is E0's
 * at every instant, and the cycle's pull-off, jump-in and jump-out are the
 * static curve's (0.1 %); one jump event in and one out (those that form
 * and break the contact), one pull-off event, the lattice's snaps
 * counted apart; the energy closes. */
#include <math.h>
#include <stdio.h>

#include "tap.h"
#include "visco_fixture.h"

#define LAT_N 120
#define LAT_SPACING 3.0
#define LAT_E 0.3e9

static size_t count(const vrun *v, int kind, int path)
{
    size_t c = 0;
    for (size_t i = 0; i < v->nev; i++)
        c += v->ev[i].kind == kind && v->ev[i].path == path;
    return c;
}

static void against_static(const fixture *f, const adh_static_result *sr, double ratio, double tau,
                           const char *what)
{
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    vrun v = fix_visco_tau(f, ratio, tau, &d, 1e-4, NAN);
    printf("# %s: %zu steps, %zu jumps, %zu lattice jumps, %zu relaxed, %zu folds resumed\n", what, v.r.steps,
           v.r.jumps, v.r.lattice_jumps, v.r.jumps_relaxed, v.r.folds_resumed);
    ok(v.rc == ADH_SUCCESS, "%s: the cycle runs (%s)", what, adh_strerror(v.rc));
    ok(v.r.lattice_jumps + v.r.jumps_relaxed + v.r.folds_resumed > 0,
       "%s: the lattice folds were met (%zu snaps, %zu relaxed)", what, v.r.lattice_jumps, v.r.jumps_relaxed);
    ok_rel(v.r.pulloff_F, sr->pulloff_F, 1e-3, "pull-off = the static curve's force minimum");
    ok_rel(v.r.jump_in_h0, sr->jump_in_h0, 1e-3, "jump-in at the static curve's first fold");
    ok_rel(v.r.jump_out_h0, sr->jump_out_h0, 1e-3, "jump-out at its retraction fold (the largest h0)");
    size_t in = count(&v, ADH_VISCO_JUMP, 0) + count(&v, ADH_VISCO_CONTACT, 0);
    size_t out = count(&v, ADH_VISCO_JUMP, 1) + count(&v, ADH_VISCO_CONTACT, 1);
    ok(in == 1 && out == 1 && v.r.jumps <= 2, "%s: one contact made and one lost (%zu and %zu events, %zu jumps)",
       what, in, out, v.r.jumps);
    ok(count(&v, ADH_VISCO_PULLOFF, 1) == 1, "%s: one pull-off event (%zu)", what,
       count(&v, ADH_VISCO_PULLOFF, 1));
    double gap = energy_gap(&v.r.cycle);
    ok(fabs(gap) < 1e-2, "%s: the energy closes to %.2g with the snaps' losses (1 %% allowed)", what, gap);
    vrun_free(&v);
}

int main(void)
{
    fixture f = fix_open(LAT_N, LAT_SPACING);
    f.m.E = LAT_E;
    adh_run st;
    adh_static_result sr;
    int rc = fix_static(&f, LAT_E, 5, &st, &sr);
    ok(rc == ADH_SUCCESS && sr.folds > 20, "the static curve at E0 on the coarse grid: %zu folds (the lattice's among them)",
       sr.folds);
    against_static(&f, &sr, 1.0, FIX_TAU, "Einf = E0");
    against_static(&f, &sr, 10.0, 1e-11, "Einf = 10 E0, tau = 10 ps");
    adh_run_free(&st);
    fix_close(&f);
    return tap_done();
}
