/* A soft instrument spring (an AFM's softest cantilevers, 1e-3 to 1e-2
 * N/m): the snap-out is the spring's instability at the force minimum,
 * and the sphere's flight is the pull-off force over k, far beyond the
 * surface forces' range (0.4 mm at 1e-3 N/m), where it lands with the
 * surface force all but zero. Closed forms: the landing lies where the
 * spring's force balances a force that has vanished, so the flight is
 * |F| / k and the jump releases the spring's energy F^2 / 2k (the
 * surfaces' and the bulk's are fJ against its nJ); with Einf = E0 the
 * snap-out force is the static curve's pull-off (load control) at any
 * speed; far out, rigid spheres' snap-in, where A R / 6 h^2 rises at k:
 * h = (A R / 3k)^(1/3), the base 3h/2 away. The cycle at 1 m/s through
 * 1e-2 N/m, Einf = 10 E0, stopped at its snap-out ("continuation could
 * not make progress"): the path turns from the base's motion to the
 * sphere's within k / F'' of h0, the integrator stopped short of the
 * fold, and the relaxation's push along the path's tangent (nearly all
 * time there) moved the sphere by nothing. */
#include <math.h>
#include <stdio.h>

#include "tap.h"
#include "visco_fixture.h"

/* The jump of path 0 (snap-in) or 1 (snap-out); NULL if none. */
static const adh_visco_event *jump_of(const vrun *v, int path)
{
    for (size_t i = 0; i < v->nev; i++)
        if (v->ev[i].kind == ADH_VISCO_JUMP && v->ev[i].path == path)
            return &v->ev[i];
    return NULL;
}

/* ok_rel with the case named */
static void rel(const char *what, const char *check, double got, double want, double tol)
{
    char m[200];
    snprintf(m, sizeof m, "%s: %s", what, check);
    ok_rel(got, want, tol, m);
}

/* The snap-out's closed forms; F_want: the force it must jump at (NAN:
 * no reference). */
static void check_snap_out(const char *what, const vrun *v, double k, double F_want)
{
    const adh_visco_event *e = jump_of(v, 1);
    ok(v->rc == ADH_SUCCESS && e && e->a > 0 && e->a_after == 0 && !isnan(v->r.hysteresis),
       "%s: the cycle completes, the snap-out breaks the contact", what);
    if (!e)
        return;
    if (!isnan(F_want))
        rel(what, "the snap-out force is the static pull-off", e->F, F_want, 1e-3);
    ok(fabs(e->F_after) < 1e-9 * fabs(e->F), "%s: it lands where the surface force is gone (%.3g N after %.3g N)", what,
       e->F_after, e->F);
    rel(what, "the flight is |F| / k", e->h0_after - e->h0, fabs(e->F) / k, 1e-3);
    rel(what, "the jump releases the spring's energy F^2 / 2k", e->loss, e->F * e->F / (2 * k), 1e-3);
    double gap = energy_gap(&v->r.cycle);
    ok(fabs(gap) < 0.01, "%s: the energy closes to %.2g (1 %% allowed)", what, gap);
}

/* The static curve's snap-out through a soft spring is load control's:
 * the base where the force is lowest, h0 - F/k at the curve's pull-off
 * (the fold lies k / F'' past it, femtometres). On a grid whose force
 * wiggles ring by ring (the lattice test's, 3x the paper's spacing at
 * sigma = 7.5) every wiggle is a fold of a soft spring; the last fold on
 * the curve is the first one met retracting, where the contact line
 * snaps across a ring and goes on: it was read as the snap-out. */
static void static_snap_out(const fixture *f, const char *what, double E, double k)
{
    adh_run st;
    adh_static_result sr;
    ok(fix_static(f, E, 0.5, &st, &sr) == ADH_SUCCESS, "%s: the static curve", what);
    double at[256], base[256], b;
    size_t nf = adh_visco_spring_folds(&st, k, at, base, 256);
    double h0 = adh_visco_spring_snap_out(&st, k, &b), want = sr.pulloff_h0 - sr.pulloff_F / k;
    rel(what, "the snap-out's base is h0 - F/k at the pull-off", b, want, 1e-4);
    ok(h0 > 0 && fabs(h0 - sr.pulloff_h0) < 0.05 * f->m.z0, "%s: and its h0 the pull-off's, %.5g nm (%.5g nm)",
       what, h0 * 1e9, sr.pulloff_h0 * 1e9);
    printf("# %s: %zu folds of the base on the curve, the last at base %.8g m\n", what, nf,
           nf && nf <= 256 ? base[nf - 1] : NAN);
    adh_run_free(&st);
}

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    adh_run st;
    adh_static_result sr;
    ok(fix_static(&f, f.m.E, 0.5, &st, &sr) == ADH_SUCCESS, "the static curve at E0");

    /* Einf = E0: load control on the static curve, at any speed */
    adh_visco_drive d = fix_drive(1.0, 1.0);
    d.spring = 1e-3;
    vrun v = fix_visco(&f, 1.0, &d, 1e-4);
    check_snap_out("Einf = E0, 1e-3 N/m, 1 m/s", &v, d.spring, sr.pulloff_F);
    const adh_visco_event *in = jump_of(&v, 0);
    double h = cbrt(f.m.A * f.m.R / (3 * d.spring));
    ok(in && fabs(in->h0 / h - 1) < 1e-3 && fabs(in->base / (1.5 * h) - 1) < 1e-3,
       "snap-in at rigid spheres' (A R / 3k)^(1/3) = %.5g nm, base 3/2 of it: got %.5g, %.5g nm", h * 1e9,
       in ? in->h0 * 1e9 : NAN, in ? in->base * 1e9 : NAN);
    vrun_free(&v);

    /* Einf = 10 E0 at 1 m/s, faster than tau over the contact: the
     * pull-off rises above E0's, below Einf / E0 times it */
    double k[2] = { 1e-2, 1e-3 };
    for (int i = 0; i < 2; i++) {
        char what[64];
        snprintf(what, sizeof what, "Einf = 10 E0, %g N/m, 1 m/s", k[i]);
        d.spring = k[i];
        v = fix_visco(&f, 10.0, &d, 1e-4);
        check_snap_out(what, &v, k[i], NAN);
        ok(v.r.pulloff_F < sr.pulloff_F && v.r.pulloff_F > 10 * sr.pulloff_F,
           "%s: pull-off %.4g nN, between E0's %.4g and 10 times it", what, v.r.pulloff_F * 1e9, sr.pulloff_F * 1e9);
        vrun_free(&v);
    }
    static_snap_out(&f, "static, resolved grid, 1e-3 N/m", f.m.E, 1e-3);
    adh_run_free(&st);
    fix_close(&f);
    fixture lat = fix_open(120, 3.0);
    lat.m.E = 0.3e9;
    static_snap_out(&lat, "static, the lattice test's grid, 1e-3 N/m", lat.m.E, 1e-3);
    fix_close(&lat);
    return tap_done();
}
