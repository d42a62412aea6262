/* A jump-in landed by the static solver (src/core/visco_land.c): at the
 * loading's fold, q frozen, the sphere elastic at Einf with the extra gap
 * cdel W q. Its landing, checked against what the solver does not compute
 * itself: the residual u + W (cinf p + cdel q) of the frozen problem,
 * evaluated here from the kernel's entries and the law (below the
 * tolerance); the contact (the central gap at z0's scale); the fold's h0
 * that of the frozen problem's own fold (the static curve with that gap,
 * solved here); and with q = 0 the static curve at Einf's contact branch
 * at the same h0 (the static mode, solved here). On the fixture's grid at
 * Einf = 2 E0, 1 um/s (at 10 E0 its contact forms without a jump).
 * Internal (src/core/visco.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/visco.h"
#include "tap.h"
#include "visco_fixture.h"

/* The static curve at Einf with the extra gap e (NULL: none) down to
 * h0_end, exactly (every fold resolved); its end state's u into u (may be
 * NULL), its summary into sr. */
static int static_at(const fixture *f, double E, const double *e, double h0_end, double *u, adh_static_result *sr)
{
    adh_material m = f->m;
    m.E = E;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_end = h0_end;
    ss.lattice_skip = 0;
    ss.ds_max = 0.1;
    adh_static *st = adh_static_alloc(f->g, f->k);
    int rc = st ? adh_static_set_gap(st, e) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_static_set(st, &m, &ss);
    if (rc == ADH_SUCCESS || rc == ADH_CONTINUE)
        while ((rc = adh_static_iterate(st)) == ADH_CONTINUE)
            ;
    if (rc == ADH_SUCCESS) {
        adh_static_summary(st, sr);
        if (u)
            memcpy(u, adh_static_state(st)->u, f->g->n * sizeof *u);
    }
    adh_static_free(st);
    return rc;
}

int main(void)
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
    /* to the loading's fold: the jump-in waiting for its landing */
    while (rc == ADH_CONTINUE) {
        rc = adh_visco_iterate(w);
        if (w->mode == MODE_CROSS && w->land_try)
            break;
    }
    ok(rc == ADH_CONTINUE && w->mode == MODE_CROSS && w->land_try, "the loading's fold is reached (%zu rows)",
       run.nrows);
    if (rc != ADH_CONTINUE) {
        printf("Bail out! no fold: %s\n", adh_visco_why(w));
        return 1;
    }
    double tol = s.tol, h0f = adh_visco_h0_of(w, w->yfold);
    double *y = malloc(w->len * sizeof *y), *h = malloc(n * sizeof *h), *e = malloc(n * sizeof *e);
    double *qf = malloc(n * sizeof *qf), *us = malloc(n * sizeof *us);
    memcpy(qf, w->yfold + w->IQ, n * sizeof *qf);

    /* the landing with the fold's q */
    rc = adh_visco_land_static(w, y);
    ok(rc == ADH_SUCCESS, "the static solver lands the jump-in (%s)", adh_strerror(rc));
    double h0 = adh_visco_h0_of(w, y);
    double r = fix_frozen_residual(&f, &sls, y, qf, h0, h);
    ok(r < tol * z0, "the landing is an equilibrium of the frozen problem: residual %.3g z0 (%.3g allowed)", r / z0,
       tol);
    ok(memcmp(y + w->IQ, qf, n * sizeof *qf) == 0, "q is the fold's, bit for bit");
    ok(h[0] < 1.1 * z0, "it is in contact: the central gap %.4g z0 (contact below 1.1)", h[0] / z0);
    ok(h0 == h0f, "its h0 is the fold's (%.9g nm)", h0 * 1e9);
    printf("# fold h0 %.9g nm, landed: central gap %.5g z0, u(0) %.5g z0\n", h0f * 1e9, h[0] / z0, y[0] / z0);

    /* the fold is the frozen problem's: the static curve at Einf with the
     * extra gap cdel W q, the product taken here from the kernel's entries */
    double cdel = 2.0 * (1.0 / sls.E0 - 1.0 / sls.Einf);
    for (size_t i = 0; i < n; i++) {
        double x = 0;
        for (size_t j = 0; j < n; j++)
            x += adh_kernel_entry(f.k, i, j) * qf[j];
        e[i] = cdel * x;
    }
    adh_static_result sr;
    rc = static_at(&f, sls.Einf, e, h0f - 0.5 * z0, NULL, &sr);
    ok(rc == ADH_SUCCESS && fabs(sr.jump_in_h0 - h0f) < tol * z0,
       "the fold is the frozen problem's: the static curve with the gap folds at %.9g nm (%.2g z0 off, %.2g "
       "allowed)",
       sr.jump_in_h0 * 1e9, (sr.jump_in_h0 - h0f) / z0, tol);

    /* q = 0: the static curve at Einf itself. Its fold lies below the
     * path's (Einf is the stiffer), so the frozen fold is put there: the
     * curve's fold less 0.1 z0, on its contact branch */
    rc = static_at(&f, sls.Einf, NULL, FIX_TURN, NULL, &sr);
    double hq = sr.jump_in_h0 - 0.1 * z0;
    ok(rc == ADH_SUCCESS && hq < h0f, "the static curve at Einf folds at %.6g nm, below the path's fold",
       sr.jump_in_h0 * 1e9);
    rc = static_at(&f, sls.Einf, NULL, hq, us, &sr);
    memset(w->yfold + w->IQ, 0, n * sizeof *w->yfold);
    w->yfold[w->IT] = (hq - w->seg.b0) / w->seg.bdot;
    int lrc = adh_visco_land_static(w, y);
    ok(rc == ADH_SUCCESS && lrc == ADH_SUCCESS, "with q = 0 at h0 = %.6g nm both land (%s, %s)", hq * 1e9,
       adh_strerror(rc), adh_strerror(lrc));
    double du = 0;
    for (size_t i = 0; i < n; i++)
        du = fmax(du, fabs(y[i] - us[i]));
    memset(qf, 0, n * sizeof *qf);
    r = fix_frozen_residual(&f, &sls, y, qf, adh_visco_h0_of(w, y), h);
    ok(lrc == ADH_SUCCESS && du < tol * z0 && r < tol * z0 && h[0] < 1.1 * z0,
       "with q = 0 the landing is the static curve's contact branch: |u - u_static| %.3g z0, residual %.3g z0 (%.3g "
       "allowed), central gap %.4g z0",
       du / z0, r / z0, tol, h[0] / z0);

    free(y), free(h), free(e), free(qf), free(us);
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
    return tap_done();
}
