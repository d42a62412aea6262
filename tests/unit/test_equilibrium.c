/* The equilibrium (static) mode: every point solves the equations, the
 * continuation follows the S-curve through its folds without leaving it, the
 * stability flag agrees with the Jacobian's eigenvalues, and the results go
 * to the right limits: DMT and the rigid curve (eq 22) at small sigma, JKR at
 * large sigma, Maugis-Dugdale (lambda = 1.16 mu) in between, the analytic
 * jump-in (eqs 23-24); the two kernels and a refined grid agree. Small
 * grids: the whole file runs in a few seconds. */
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/static.h"
#include "adhere/kernel.h"
#include "adhere/law.h"
#include "adhere/maugis.h"
#include "adhere/models.h"
#include "adhere/observe.h"
#include "adhere/status.h"
#include "adhere/runner.h"
#include "tap.h"

typedef struct curve {
    adh_run run;
    adh_static_result res;
    int rc;
} curve;

static curve run_curve(const adh_material *m, size_t n, double dr, adh_kernel_type kt, const adh_static_settings *s)
{
    curve c;
    adh_run_init(&c.run);
    adh_grid *g = adh_grid_alloc(n, dr);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = kt }, NULL);
    c.rc = adh_runner_static_curve(g, k, m, s, NULL, NULL, &c.run, &c.res);
    adh_kernel_free(k);
    adh_grid_free(g);
    return c;
}

static double rel(double a, double b)
{
    return fabs(a - b) / fabs(b);
}

/* Smallest real part among the eigenvalues of the full Jacobian
 * I - (2/E) W diag(p'(h)) (real in exact arithmetic: W times a symmetric
 * Hessian). */
static double min_eigen(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_state *st)
{
    size_t n = g->n;
    gsl_matrix *J = gsl_matrix_alloc(n, n);
    gsl_vector_complex *ev = gsl_vector_complex_alloc(n);
    gsl_eigen_nonsymm_workspace *ws = gsl_eigen_nonsymm_alloc(n);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(J, i, j, (i == j) - 2.0 / m->E * adh_kernel_entry(k, i, j) *
                                                   adh_lj_dpressure(st->h[j], m->A, m->z0));
    double lo = NAN;
    if (gsl_eigen_nonsymm(J, ev, ws) == 0) {
        lo = INFINITY;
        for (size_t i = 0; i < n; i++)
            lo = fmin(lo, GSL_REAL(gsl_vector_complex_get(ev, i)));
    }
    gsl_eigen_nonsymm_free(ws);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(J);
    return lo;
}

/* Figure 1's material (sigma = 2.25) point by point through the iterate API. */
static void check_points(void)
{
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(160, adh_grid_default_spacing(&m));
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_static *w = adh_static_alloc(g, k);
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = 1.5e-9; /* past the jump-out fold, inside the grid */
    int rc = adh_static_set(w, &m, &s);
    ok(rc == ADH_SUCCESS, "sigma 2.25: the start point solves (%s)", adh_strerror(rc));
    size_t n = g->n, points = 0, eig_checked = 0, eig_agree = 0;
    double *Wp = malloc(n * sizeof *Wp), *scr = malloc(n * sizeof *scr), *uprev = malloc(n * sizeof *uprev);
    double worst_res = 0, worst_h = 0, worst_jump = 0, h0prev = NAN;
    while (rc == ADH_SUCCESS || rc == ADH_CONTINUE) {
        const adh_state *st = adh_static_state(w);
        adh_static_point pt = adh_static_current(w);
        adh_kernel_apply(k, st->p, Wp, scr);
        for (size_t i = 0; i < n; i++) {
            double h = st->h0 + g->r[i] * g->r[i] / (2 * m.R) - st->u[i];
            worst_res = fmax(worst_res, fabs(st->u[i] + 2.0 / m.E * Wp[i]));
            worst_h = fmax(worst_h, fabs(h - st->h[i]) + fabs(st->p[i] - adh_lj_pressure(h, m.A, m.z0)) * 1e-30);
        }
        if (points > 0) {
            double d2 = (st->h0 - h0prev) * (st->h0 - h0prev);
            for (size_t i = 0; i < n; i++)
                d2 += s.u_weight * (st->u[i] - uprev[i]) * (st->u[i] - uprev[i]);
            worst_jump = fmax(worst_jump, sqrt(d2) / m.z0);
        }
        /* the eigenvalue check away from the folds, where the sign is clear */
        if (points % 7 == 3 && fabs(pt.tangent_h0) > 0.02) {
            double lo = min_eigen(g, k, &m, st);
            eig_checked++;
            eig_agree += (lo > 0) == (pt.stable == 1);
        }
        memcpy(uprev, st->u, n * sizeof *uprev);
        h0prev = st->h0;
        points++;
        if (rc == ADH_SUCCESS && points > 1)
            break;
        rc = adh_static_iterate(w);
    }
    ok(rc == ADH_SUCCESS, "sigma 2.25: the curve reaches its end (%s)", adh_strerror(rc));
    ok(worst_res < 2 * s.tol * m.z0, "every point solves eq 11: max |u + (2/E) W p| = %.3g m < 2 tol z0", worst_res);
    ok(worst_h < 1e-20, "every point's h is h0 + r^2/2R - u and p = p(h) (worst %.3g m)", worst_h);
    ok(worst_jump <= 2 * s.ds_max, "consecutive points are close in (u, h0): worst %.3g z0 <= 2 ds_max", worst_jump);
    ok(eig_checked >= 4 && eig_agree == eig_checked,
       "stable flag == (smallest eigenvalue of I - (2/E) W diag p' > 0) at %zu of %zu points", eig_agree, eig_checked);
    adh_static_result r;
    adh_static_summary(w, &r);
    const adh_static_fold *f;
    size_t nf = adh_static_folds(w, &f);
    ok(nf == r.folds && nf == 2 && f[0].kind == -1 && f[1].kind == +1,
       "sigma 2.25: two folds, approach (h0 minimum) then retraction (h0 maximum): %zu", nf);
    ok(r.points == points, "summary counts every point (%zu)", r.points);
    free(Wp);
    free(scr);
    free(uprev);
    adh_static_free(w);
    adh_kernel_free(k);
    adh_grid_free(g);
}

/* Figure 1's material: the whole run, rows, summary, and the comparisons
 * with the analytic jump-in and Maugis-Dugdale. */
static curve check_fig1(void)
{
    adh_material m = adh_material_default();
    adh_derived d;
    adh_material_derive(&m, &d);
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = -1e-9;
    curve c = run_curve(&m, 300, adh_grid_default_spacing(&m), ADH_KERNEL_PAPER, &s);
    const adh_run *run = &c.run;
    const adh_static_result *r = &c.res;
    ok(c.rc == ADH_SUCCESS && run->status == ADH_SUCCESS, "sigma 2.25, N 300: run succeeds (%s)", adh_strerror(c.rc));
    ok(run->nrows == r->points && run->nrows > 20, "one row per point (%zu)", run->nrows);
    if (run->nrows < 2)
        return c;
    ok(run->rows[0].h0 == adh_protocol_auto_start(&m, 0.05e-9) && run->start == run->rows[0].h0,
       "starts at the automatic start %.4g nm", run->rows[0].h0 * 1e9);
    ok(fabs(run->rows[run->nrows - 1].h0 - s.h0_end) < 1e-6 * m.z0, "ends at h0_end (%.6g nm)",
       run->rows[run->nrows - 1].h0 * 1e9);
    ok(fabs(run->rows[0].delta) < 0.011 * m.z0 && rel(-run->rows[0].delta, -adh_bulge(&m, run->rows[0].hc)) < 0.1,
       "at the start the bulge %.3g m is below 1 %% of z0 and within 10 %% of eq 23", run->rows[0].delta);
    size_t changes = 0, flags_ok = 1;
    double Fmin = INFINITY;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        Fmin = fmin(Fmin, o->F);
        flags_ok &= o->path == 0 && o->converged == 1 && (o->branch == 1 || o->branch == -1) &&
                    o->stable == (o->branch == 1);
        if (i > 0 && o->branch != run->rows[i - 1].branch)
            changes++;
    }
    ok(flags_ok, "rows: path 0, converged, stable exactly where h0 decreases along the curve");
    ok(changes == 2 && r->folds == 2, "branch turns twice, two folds (%zu, %zu)", changes, r->folds);
    ok(r->pulloff_F <= Fmin && r->pulloff_F > Fmin - 0.01 * fabs(Fmin),
       "pulloff_F (%.5g) is the curve's minimum (rows: %.5g) within 1 %%", r->pulloff_F, Fmin);
    ok(r->pulloff_F < r->pulloff_F_disp && r->pulloff_F_disp < 0,
       "load-controlled pull-off %.4g N is below the displacement-controlled %.4g N", r->pulloff_F, r->pulloff_F_disp);
    ok(r->jump_in_h0 > 0 && r->jump_in_h0 < r->jump_out_h0,
       "hysteresis under displacement control: jump-in %.4g nm < jump-out %.4g nm", r->jump_in_h0 * 1e9,
       r->jump_out_h0 * 1e9);
    ok(run->jump_in_h0 == r->jump_in_h0, "run->jump_in_h0 is the summary's");
    double h0_eq24 = adh_bulge_position(&m, adh_jump_separation(&m));
    ok(rel(r->jump_in_h0, h0_eq24) < 0.15, "jump-in %.4g nm within 15 %% of eqs 23-24 (%.4g nm)",
       r->jump_in_h0 * 1e9, h0_eq24 * 1e9);
    double Fl, Fd, od;
    adh_md_pulloff(&m, adh_md_lambda(&m), &Fl, NULL, &Fd, &od);
    ok(rel(r->pulloff_F, Fl) < 0.05, "pull-off %.5g N within 5 %% of Maugis-Dugdale (lambda = 1.16 mu): %.5g N",
       r->pulloff_F, Fl);
    ok(rel(r->jump_out_h0, m.z0 - od) < 0.05, "jump-out %.4g nm within 5 %% of Maugis-Dugdale's z0 - overlap: %.4g nm",
       r->jump_out_h0 * 1e9, (m.z0 - od) * 1e9);
    ok(rel(r->pulloff_F_disp, Fd) < 0.10, "pulloff_F_disp %.4g N within 10 %% of Maugis-Dugdale's %.4g N",
       r->pulloff_F_disp, Fd);
    return c;
}

/* The paper kernel, the ring kernel and a grid twice as fine. */
static void check_kernels_grids(const curve *paper)
{
    adh_material m = adh_material_default();
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = -1e-9;
    double dr = adh_grid_default_spacing(&m);
    curve ring = run_curve(&m, 300, dr, ADH_KERNEL_RING, &s);
    curve fine = run_curve(&m, 600, dr / 2, ADH_KERNEL_PAPER, &s);
    ok(ring.rc == ADH_SUCCESS && fine.rc == ADH_SUCCESS, "ring kernel and refined grid runs succeed");
    const adh_static_result *p = &paper->res, *q = &ring.res, *f = &fine.res;
    ok(q->folds == p->folds && f->folds == p->folds, "same fold count: paper %zu, ring %zu, fine grid %zu", p->folds,
       q->folds, f->folds);
    ok(rel(q->pulloff_F, p->pulloff_F) < 0.01, "ring vs paper kernel: pull-off %.5g vs %.5g N within 1 %%",
       q->pulloff_F, p->pulloff_F);
    ok(rel(f->pulloff_F, p->pulloff_F) < 0.01, "grid dr/2 vs dr: pull-off %.5g vs %.5g N within 1 %%", f->pulloff_F,
       p->pulloff_F);
    ok(rel(q->jump_in_h0, p->jump_in_h0) < 0.02 && rel(f->jump_in_h0, p->jump_in_h0) < 0.02,
       "jump-in within 2 %%: paper %.4g, ring %.4g, fine %.4g nm", p->jump_in_h0 * 1e9, q->jump_in_h0 * 1e9,
       f->jump_in_h0 * 1e9);
    ok(rel(q->jump_out_h0, p->jump_out_h0) < 0.02 && rel(f->jump_out_h0, p->jump_out_h0) < 0.02,
       "jump-out within 2 %%: paper %.4g, ring %.4g, fine %.4g nm", p->jump_out_h0 * 1e9, q->jump_out_h0 * 1e9,
       f->jump_out_h0 * 1e9);
    adh_run_free(&ring.run);
    adh_run_free(&fine.run);
}

/* sigma = 0.01: stiff, weakly adhesive: DMT and the rigid curve. */
static void check_small_sigma(void)
{
    adh_material m = adh_material_default();
    m.E = 2.25e11;
    adh_derived d;
    adh_material_derive(&m, &d);
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = -1e-9;
    curve c = run_curve(&m, 300, adh_grid_default_spacing(&m), ADH_KERNEL_PAPER, &s);
    ok(c.rc == ADH_SUCCESS, "sigma %.3g: run succeeds", d.sigma);
    ok(rel(c.res.pulloff_F, d.F_dmt) < 0.03, "sigma %.3g: pull-off %.5g N within 3 %% of DMT -2 pi gamma R = %.5g N",
       d.sigma, c.res.pulloff_F, d.F_dmt);
    ok(c.res.folds == 0 && isnan(c.res.jump_in_h0) && isnan(c.res.jump_out_h0),
       "sigma %.3g: no folds, no jumps (%zu folds)", d.sigma, c.res.folds);
    double worst = 0;
    size_t compared = 0;
    for (size_t i = 0; i < c.run.nrows; i++)
        if (c.run.rows[i].h0 >= m.z0) {
            worst = fmax(worst, fabs(c.run.rows[i].F - c.run.rows[i].F_rigid));
            compared++;
        }
    ok(compared > 5 && worst < 0.05 * fabs(d.F_dmt),
       "sigma %.3g: for h0 >= z0 the force is eq 22's within 5 %% of 2 pi gamma R (worst %.3g N, %zu rows)", d.sigma,
       worst, compared);
    adh_run_free(&c.run);
}

/* sigma = 5: soft and adhesive: JKR, lattice trapping, robustness. */
static void check_large_sigma(void)
{
    adh_material m = adh_material_default();
    m.E = 4.5e8;
    adh_derived d;
    adh_material_derive(&m, &d);
    adh_static_settings s = adh_static_settings_default();
    s.h0_end = 2e-9;
    double dr = adh_grid_default_spacing(&m);
    curve c = run_curve(&m, 200, dr, ADH_KERNEL_PAPER, &s);
    ok(c.rc == ADH_SUCCESS, "sigma %.3g, N 200: run succeeds (%s)", d.sigma, adh_strerror(c.rc));
    ok(rel(c.res.pulloff_F, d.F_jkr) < 0.10 && rel(c.res.pulloff_F, d.F_jkr) < rel(c.res.pulloff_F, d.F_dmt),
       "sigma %.3g: pull-off %.5g N within 10 %% of JKR -(3/2) pi gamma R = %.5g N (and nearer JKR than DMT)",
       d.sigma, c.res.pulloff_F, d.F_jkr);
    ok(c.res.folds > 2, "sigma %.3g: lattice trapping gives more than two folds (%zu)", d.sigma, c.res.folds);
    ok(c.res.folds % 2 == 0, "an even number of folds: the curve ends on a stable branch (%zu)", c.res.folds);
    int last_stable = c.run.nrows ? c.run.rows[c.run.nrows - 1].stable : 0;
    ok(last_stable, "the last point is stable");
    /* sigma 10 on the default grid: some 400 lattice folds */
    adh_material m10 = adh_material_default();
    m10.E = 2.25e8;
    adh_derived d10;
    adh_material_derive(&m10, &d10);
    adh_static_settings s10 = adh_static_settings_default();
    s10.h0_end = 2.5e-9;
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("sigma 10, N 230 (the coarse grid's lattice folds below, on twice the nodes)");
    } else {
        curve c10 = run_curve(&m10, 230, adh_grid_default_spacing(&m10), ADH_KERNEL_PAPER, &s10);
        ok(c10.rc == ADH_SUCCESS, "sigma %.3g, N 230: run succeeds (%s)", d10.sigma, adh_strerror(c10.rc));
        ok(rel(c10.res.pulloff_F, d10.F_jkr) < 0.10, "sigma %.3g: pull-off %.5g N within 10 %% of JKR %.5g N",
           d10.sigma, c10.res.pulloff_F, d10.F_jkr);
        ok(c10.res.folds > 100, "sigma %.3g: lattice trapping, %zu folds", d10.sigma, c10.res.folds);
        adh_run_free(&c10.run);
    }

    /* Stronger trapping (sigma 10 on a grid twice as coarse: every node
     * crossing is a fold pair of some picometres) and the same curve with
     * half the step, half the turn and half the gap change per step: a
     * continuation that stepped over a fold pair, or turned back onto a leg
     * of the zigzag, would count differently. (At sigma 5 on the default
     * grid the pairs shrink to femtometres near the jump-out fold and their
     * count depends on the resolution: the check there is the pull-off.) */
    s10.h0_end = 3e-9;
    double dr10 = 2 * adh_grid_default_spacing(&m10);
    curve c1 = run_curve(&m10, 110, dr10, ADH_KERNEL_PAPER, &s10);
    /* under ASan the curve at half the steps runs no line or branch of the
     * library that the pass runs without it (gcov): its agreement stays in
     * the plain build */
    if (tap_sanitized_short()) {
        ok(c1.rc == ADH_SUCCESS, "sigma 10, coarse grid: the run succeeds");
        tap_sanitized_leaves_out("sigma 10 on the coarse grid at half the steps (the same curve at the steps set)");
    } else {
        adh_static_settings s2 = s10;
        s2.ds_max *= 0.5;
        s2.max_angle *= 0.5;
        s2.max_gap_step *= 0.5;
        curve c2 = run_curve(&m10, 110, dr10, ADH_KERNEL_PAPER, &s2);
        ok(c1.rc == ADH_SUCCESS && c2.rc == ADH_SUCCESS, "sigma 10, coarse grid: both runs succeed");
        ok(c2.res.folds == c1.res.folds,
           "halving ds_max, max_angle and max_gap_step finds the same folds (%zu vs %zu): none skipped", c2.res.folds,
           c1.res.folds);
        ok(rel(c2.res.pulloff_F, c1.res.pulloff_F) < 1e-3 && rel(c2.res.jump_out_h0, c1.res.jump_out_h0) < 1e-3 &&
               rel(c2.res.jump_in_h0, c1.res.jump_in_h0) < 1e-3,
           "and the same pull-off, jump-in and jump-out within 0.1 %%");
        adh_run_free(&c2.run);
    }
    ok(c1.res.folds > 20, "sigma 10, coarse grid: many lattice-trapping folds (%zu)", c1.res.folds);
    int stable_ok = 1;
    for (size_t i = 0; i < c1.run.nrows; i++)
        stable_ok &= c1.run.rows[i].stable == (c1.run.rows[i].branch == 1);
    ok(stable_ok, "through every lattice fold, stable exactly where h0 decreases along the curve");
    adh_run_free(&c1.run);
    adh_run_free(&c.run);
}

static int stop_after_5(const adh_obs *row, const adh_run *run, void *ctx)
{
    (void)row;
    (void)ctx;
    return run->nrows >= 5;
}

/* A callback stops the run; a grid too short for the depth is reported. */
static void check_stops(void)
{
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(60, adh_grid_default_spacing(&m));
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_static_settings s = adh_static_settings_default();
    adh_run run;
    adh_run_init(&run);
    int rc = adh_runner_static_curve(g, k, &m, &s, stop_after_5, NULL, &run, NULL);
    ok(rc == ADH_SUCCESS && run.interrupted == 1 && run.nrows == 5, "a callback stops the run after 5 rows (%zu)",
       run.nrows);
    adh_run_free(&run);
    adh_run_init(&run);
    adh_static_result r;
    rc = adh_runner_static_curve(g, k, &m, &s, NULL, NULL, &run, &r);
    ok(rc == ADH_EGRID && run.status == ADH_EGRID && run.nrows > 10 &&
           run.rows[run.nrows - 1].a >= 0.9 * g->rmax,
       "N 60 down to -5 nm: ADH_EGRID once the contact reaches 0.9 Rmax, rows kept (%zu)", run.nrows);
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
}

static void check_settings(void)
{
    adh_static_settings s = adh_static_settings_default();
    char why[200];
    ok(adh_static_settings_validate(&s, why, sizeof why) == ADH_SUCCESS, "default settings are valid");
    s.h0_start = -10e-9;
    ok(adh_static_settings_validate(&s, why, sizeof why) == ADH_EINVAL && strstr(why, "start"),
       "a start below the end is refused: %s", why);
    s = adh_static_settings_default();
    s.ds_min = 10;
    ok(adh_static_settings_validate(&s, why, sizeof why) == ADH_EINVAL, "ds_min > ds_init is refused: %s", why);
}

int main(void)
{
    check_settings();
    check_stops();
    check_points();
    curve c = check_fig1();
    check_kernels_grids(&c);
    adh_run_free(&c.run);
    check_small_sigma();
    check_large_sigma();
    return tap_done();
}
