/* The instrument's spring: an elastic sphere (Einf = E0) pulled through a
 * spring of stiffness k jumps where the base h0 - F/k turns along the
 * static curve, i.e. where dF/dh0 = k (adh_visco_spring_folds on the
 * static curve: no new solver), AFM's snap-in on approach and snap-out on
 * retraction; the softer the spring the further out it snaps in, and a
 * soft one measures the load-controlled pull-off, the static curve's force
 * minimum. */
#include <math.h>
#include <stdio.h>

#include "tap.h"
#include "visco_fixture.h"

/* The first jump on path 0 (loading) and the last on path 1. */
static void jumps_of(const vrun *v, double *in, double *out)
{
    *in = *out = NAN;
    for (size_t i = 0; i < v->nev; i++) {
        if (v->ev[i].kind != ADH_VISCO_JUMP)
            continue;
        if (v->ev[i].path == 0 && isnan(*in))
            *in = v->ev[i].h0;
        if (v->ev[i].path == 1)
            *out = v->ev[i].h0;
    }
}

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    adh_run st;
    adh_static_result sr;
    ok(fix_static(&f, f.m.E, 0.5, &st, &sr) == ADH_SUCCESS, "the static curve at E0, sampled finely");
    double k[3] = { 40, 10, 1 }, snap_in[3];
    for (int i = 0; i < 3; i++) {
        double at[16];
        size_t nf = adh_visco_spring_folds(&st, k[i], at, NULL, 16);
        adh_visco_drive d = fix_drive(1e-6, 1e-6);
        d.spring = k[i];
        vrun v = fix_visco(&f, 1.0, &d, 1e-4);
        double in, out;
        jumps_of(&v, &in, &out);
        snap_in[i] = in;
        ok(v.rc == ADH_SUCCESS && nf >= 2, "k = %g N/m: the cycle runs; the static curve turns the base %zu times",
           k[i], nf);
        ok_rel(in, at[0], 1e-3, "snap-in where dF/dh0 = k first");
        if (k[i] >= 10)
            ok_rel(out, at[nf < 16 ? nf - 1 : 15], 1e-3, "snap-out where dF/dh0 = k last");
        else
            ok_rel(v.r.pulloff_F, sr.pulloff_F, 1e-3, "soft: the pull-off is the load-controlled one");
        vrun_free(&v);
    }
    ok(snap_in[2] > snap_in[1] && snap_in[1] > snap_in[0], "softer springs snap in from further out: %.4g > %.4g > %.4g nm",
       snap_in[2] * 1e9, snap_in[1] * 1e9, snap_in[0] * 1e9);
    adh_run_free(&st);
    fix_close(&f);
    return tap_done();
}
