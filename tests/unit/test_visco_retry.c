/* A crossing's retries stop at their floor (src/core/visco.c, cross_retry).
 * A crossing step that goes backwards against the last tangent (at a
 * lattice fold's hairpin) is taken again from the last good point with at
 * most a quarter of the step, until the step is VISCO_RETRY_MIN = 1e-3
 * tolerances (in z0 of the crossing's arclength); below that the crossing
 * is lost and the jump relaxes. So a crossing whose first step backwards
 * was h1 retries at most 2 + floor(log4(h1 / floor)) times (the step of
 * the k-th is at most h1 / 4^(k-1), and every one but the last is at
 * least the floor): the bound is the rule's, not a run's.
 *
 * The hairpin is provoked where it was met (a lattice grid's snap-in at a
 * loose tolerance): there the restart's Newton polish put the last good
 * point back on the equilibria a little behind where it had been kept, and
 * every step shorter than that shift read as going backwards. Here the last
 * good point is planted ahead of the crossing's start by a fixed shift of u
 * (the polish, holding h0, takes it back): every step shorter than the
 * shift goes backwards, the retries come down to the floor, and the jump
 * relaxes (jumps_relaxed) onto the spring's line instead of spinning.
 * Internal (src/core/visco.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/observe.h"
#include "core/visco.h"
#include "tap.h"
#include "visco_fixture.h"

#define SPRING 10.0

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    size_t n = f.g->n;
    double z0 = f.m.z0;
    adh_sls sls = { f.m.E, 2 * f.m.E, FIX_TAU };
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    d.spring = SPRING;
    adh_visco_settings s = adh_visco_settings_default();
    adh_run run;
    int rc;
    adh_visco *w = fix_visco_begin(&f, &sls, &d, &run, &rc);
    while (rc == ADH_CONTINUE && w->mode != MODE_CROSS)
        rc = adh_visco_iterate(w);
    ok(rc == ADH_CONTINUE && w->mode == MODE_CROSS, "the snap-in's crossing starts (%zu rows)", run.nrows);
    if (rc != ADH_CONTINUE) {
        printf("Bail out! no crossing: %s\n", adh_visco_why(w));
        return 1;
    }
    /* the last good point: the crossing's start with u moved along its
     * tangent d by delta, so that a step h along d goes backwards against
     * it while h z0^2 < delta theta |d_u|^2: for steps under a thousandth of z0
     * of the crossing's arclength */
    const double *y = N_VGetArrayPointer(w->y), *t = N_VGetArrayPointer(w->yp);
    double du2 = 0;
    for (size_t i = 0; i < n; i++)
        du2 += t[i] * t[i];
    double delta = 1e-3 * z0 * z0 / (w->theta * du2);
    memcpy(w->yprev, y, w->len * sizeof *y);
    memcpy(w->ypprev, t, w->len * sizeof *t);
    for (size_t i = 0; i < n; i++)
        w->yprev[i] += delta * t[i];
    w->s_prev = w->s_now;
    w->have_prev = 1;
    printf("# planted: u moved by %.3g z0 (rms), the tangent's u part %.3g of its length\n",
           delta * sqrt(du2 / (double)n) / z0, sqrt(w->theta * du2) / z0);

    /* the jump: one call (the crossing, its retries, the relaxation) */
    size_t relaxed0 = w->res.jumps_relaxed, nev0 = w->nev;
    rc = adh_visco_iterate(w);
    double floor_h = 1e-3 * s.tol;
    long bound = 2 + (long)floor(log(w->retry_h1 / floor_h) / log(4.0));
    printf("# %ld retries, the first from a step of %.3g, the last %.3g; floor %.3g, bound %ld\n", w->retries,
           w->retry_h1, w->retry_h, floor_h, bound);
    ok(w->retries >= 2 && w->retry_h1 >= floor_h, "the crossing went backwards and was retried (%ld times)",
       w->retries);
    /* a quarter to rounding: IDA holds the step to 1/hmax_inv, not to hmax
     * itself, an ulp either side (under valgrind the last step was 1 ulp
     * above h1 / 4^5 and this failed) */
    double quarter = w->retry_h1 * pow(0.25, (double)(w->retries - 1));
    ok(w->retry_h < floor_h && w->retry_h <= quarter * (1 + 1e-12),
       "each retry a quarter of the step or less, down to the floor: the last %.17g <= %.17g (to rounding), < %.3g",
       w->retry_h, quarter, floor_h);
    ok(w->retries <= bound, "the retries stop at the floor: %ld, at most 2 + log4(%.3g / %.3g) = %ld", w->retries,
       w->retry_h1, floor_h, bound);
    adh_visco_result r;
    adh_visco_summary(w, &r);
    ok(rc == ADH_CONTINUE && r.jumps_relaxed == relaxed0 + 1 && w->mode == MODE_PATH,
       "the jump relaxed instead (jumps_relaxed %zu, %s)", r.jumps_relaxed, adh_strerror(rc));
    /* where it landed: on the spring's line, in contact (the snap-in's
     * event), the force from the law at the landed state's gaps */
    const adh_visco_event *ev;
    size_t nev = adh_visco_events(w, &ev);
    const adh_state *st = adh_visco_state(w);
    double F = adh_force(f.g, &f.m, st), off = F / SPRING - (st->h0 - adh_visco_base(w));
    ok(nev == nev0 + 1 && ev[nev - 1].kind == ADH_VISCO_JUMP && ev[nev - 1].a_after > 0 && fabs(off) < s.tol * z0,
       "it landed in contact on the spring's line: F/k - (h0 - base) = %.3g z0 (%.3g allowed)", off / z0, s.tol);
    while (rc == ADH_CONTINUE)
        rc = adh_visco_iterate(w);
    adh_visco_summary(w, &r);
    ok(rc == ADH_SUCCESS, "the cycle completes (%s, %zu steps)", adh_strerror(rc), r.steps);
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
    return tap_done();
}
