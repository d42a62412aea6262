/* A relaxation that has not come to rest is checked every 100 steps for an
 * equilibrium next to it (src/core/visco.c, adh_visco_next_to_equilibrium):
 * it lands only where Newton's equilibrium lies within ten tolerances (z0)
 * of the state, and then on Newton's state.
 *
 * Next to an equilibrium: a state in contact moved off its equilibrium by
 * 3 tolerances is landed on it (the residual of the frozen problem from
 * the kernel's entries and the law, below the tolerance; within ten
 * tolerances of where it was); moved by 30 it is left alone.
 *
 * In flight: a soft spring's snap-out on a coarse grid (1 N/m, 15 nm
 * nodes; its crossing is lost on the lattice and the jump relaxes for
 * hundreds of steps, half a micrometre out) was checked mid-flight,
 * where Newton's equilibrium is the landing hundreds of nm on, and landed
 * where the flight was (457 of 522 nm out, the force off the spring's
 * line). The landing must be on the spring's line, F = k (h0 - base),
 * with F from the law at the landed state's gaps. Internal
 * (src/core/visco.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/observe.h"
#include "core/visco.h"
#include "tap.h"
#include "visco_fixture.h"

/* A state moved off the equilibrium ye by a smooth shift of u, shift z0
 * at the centre, and checked. */
static int moved_and_checked(adh_visco *w, const double *ye, double shift, double *moved)
{
    double *y = N_VGetArrayPointer(w->y);
    memcpy(y, ye, w->len * sizeof *y);
    for (size_t i = 0; i < w->n; i++)
        y[i] += shift * exp(-(double)i / 50.0);
    memcpy(moved, y, w->len * sizeof *y);
    return adh_visco_next_to_equilibrium(w);
}

static void next_to(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    size_t n = f.g->n;
    double z0 = f.m.z0;
    adh_sls sls = { f.m.E, 2 * f.m.E, FIX_TAU };
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    adh_visco_settings s = adh_visco_settings_default();
    adh_run run;
    int rc;
    adh_visco *w = fix_visco_begin(&f, &sls, &d, &run, &rc);
    /* loading, in contact, on the path */
    while (rc == ADH_CONTINUE && !(w->mode == MODE_PATH && w->st->h0 < 0))
        rc = adh_visco_iterate(w);
    ok(rc == ADH_CONTINUE && w->mode == MODE_PATH, "loading in contact: h0 = %.4g nm", w->st->h0 * 1e9);
    double *ye = malloc(w->len * sizeof *ye), *y0 = malloc(w->len * sizeof *y0), *h = malloc(n * sizeof *h);
    memcpy(ye, N_VGetArrayPointer(w->y), w->len * sizeof *ye);
    rc = adh_visco_polish(w, ye, 0);
    double h0 = adh_visco_h0_of(w, ye), tol = s.tol;
    double r = fix_frozen_residual(&f, &sls, ye, ye + w->IQ, h0, h);
    ok(rc == ADH_SUCCESS && r < tol * z0 && h[0] < 1.1 * z0, "an equilibrium in contact (residual %.3g z0)",
       r / z0);

    int landed = moved_and_checked(w, ye, 3 * tol * z0, y0);
    const double *y = N_VGetArrayPointer(w->y);
    double from = 0, off = 0;
    for (size_t i = 0; i < n; i++) {
        from = fmax(from, fabs(y[i] - y0[i]));
        off = fmax(off, fabs(y[i] - ye[i]));
    }
    r = fix_frozen_residual(&f, &sls, y, y + w->IQ, adh_visco_h0_of(w, y), h);
    ok(landed && r < tol * z0 && from <= 10 * tol * z0 && off < tol * z0,
       "3 tolerances off, it lands on the equilibrium: residual %.3g z0, %.3g tolerances from where it was, %.3g "
       "from the equilibrium",
       r / z0, from / (tol * z0), off / (tol * z0));
    ok(memcmp(y + w->IQ, ye + w->IQ, (n + 1) * sizeof *y) == 0, "its q and time are the state's, bit for bit");

    landed = moved_and_checked(w, ye, 30 * tol * z0, y0);
    ok(!landed && memcmp(N_VGetArrayPointer(w->y), y0, w->len * sizeof *y0) == 0,
       "30 tolerances off, no landing, the state untouched");
    /* though Newton from there finds the equilibrium */
    rc = adh_visco_polish(w, y0, 0);
    off = 0;
    for (size_t i = 0; i < n; i++)
        off = fmax(off, fabs(y0[i] - ye[i]));
    ok(rc == ADH_SUCCESS && off < tol * z0, "though Newton from there finds it (%.3g tolerances off)",
       off / (tol * z0));
    free(ye), free(y0), free(h);
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
}

#define SOFT_K 1.0

static void in_flight(void)
{
    fixture f = fix_open(100, 10.0); /* the paper's radius on 100 nodes of 15 nm */
    double z0 = f.m.z0;
    adh_sls sls = { f.m.E, f.m.E, FIX_TAU };
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = SOFT_K;
    adh_visco_settings s = adh_visco_settings_default();
    adh_run run;
    int rc;
    adh_visco *w = fix_visco_begin(&f, &sls, &d, &run, &rc);
    const adh_visco_event *ev = NULL;
    size_t nev = 0, relaxed = 0;
    /* to the snap-out: the unloading's jump event */
    while (rc == ADH_CONTINUE) {
        adh_visco_result r0;
        adh_visco_summary(w, &r0);
        rc = adh_visco_iterate(w);
        nev = adh_visco_events(w, &ev);
        if (nev && ev[nev - 1].kind == ADH_VISCO_JUMP && ev[nev - 1].path == 1) {
            adh_visco_result r1;
            adh_visco_summary(w, &r1);
            relaxed = r1.jumps_relaxed - r0.jumps_relaxed;
            break;
        }
    }
    ok(rc == ADH_CONTINUE && nev, "the snap-out through %g N/m (%s)", SOFT_K, adh_strerror(rc));
    if (!(rc == ADH_CONTINUE && nev)) {
        printf("# %s\n", adh_visco_why(w));
        adh_visco_free(w);
        adh_run_free(&run);
        fix_close(&f);
        return;
    }
    const adh_visco_event *e = &ev[nev - 1];
    printf("# from h0 %.4g nm to %.6g nm, base %.6g nm; the relaxation's steps %ld\n", e->h0 * 1e9,
           e->h0_after * 1e9, e->base * 1e9, w->jump_steps);
    ok(relaxed == 1 && w->jump_steps >= 100 && e->h0_after - e->h0 > 100e-9,
       "it relaxed, %.0f nm out, over %ld steps: checked for an equilibrium mid-flight", (e->h0_after - e->h0) * 1e9,
       w->jump_steps);
    const adh_state *st = adh_visco_state(w);
    double F = adh_force(f.g, &f.m, st), base = adh_visco_base(w);
    double off = F / SOFT_K - (st->h0 - base), off_ev = e->F_after / SOFT_K - (e->h0_after - e->base);
    ok(fabs(off) < s.tol * z0 && fabs(off_ev) < s.tol * z0 && fabs(e->h0_after - st->h0) < s.tol * z0 &&
           base == e->base,
       "it lands on the spring's line: F/k - (h0 - base) = %.3g z0 at the landed state (the law's force), %.3g in "
       "its event (%.3g allowed)",
       off / z0, off_ev / z0, s.tol);
    ok(!(e->a_after > 0), "out of contact");
    while (rc == ADH_CONTINUE)
        rc = adh_visco_iterate(w);
    ok(rc == ADH_SUCCESS, "the cycle completes (%s)", adh_strerror(rc));
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
}

int main(void)
{
    next_to();
    in_flight();
    return tap_done();
}
