/* What the viscoelastic tests share: the Figure 1 sphere (E = 1 GPa,
 * sigma = 2.25) on N = 300 nodes of the paper's spacing (1.5 nm: 0.13
 * edge-zone widths, resolved) and kernel, a shallow turn (-1.5 nm), and
 * runs of the static curve and of the viscoelastic solver on it. */
#ifndef ADH_VISCO_FIXTURE_H
#define ADH_VISCO_FIXTURE_H

#include <math.h>
#include <stdlib.h>

#include "adhere/kernel.h"
#include "adhere/law.h"
#include "adhere/runner.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "adhere/visco.h"

#define FIX_TURN (-1.5e-9)
#define FIX_N 300
#define FIX_TAU 1e-3

typedef struct fixture {
    adh_material m;
    adh_grid *g;
    adh_kernel *k;
} fixture;

static inline fixture fix_open(size_t n, double spacing_factor)
{
    fixture f;
    f.m = adh_material_default();
    f.g = adh_grid_alloc(n, spacing_factor * adh_grid_default_spacing(&f.m));
    f.k = f.g ? adh_kernel_alloc(f.g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    if (!f.k) {
        printf("Bail out! out of memory\n");
        exit(1);
    }
    return f;
}

static inline void fix_close(fixture *f)
{
    adh_kernel_free(f->k);
    adh_grid_free(f->g);
}

/* The static curve at modulus E down to the turn (ds_max: its longest
 * step; the default 5 samples the far field coarsely). */
static inline int fix_static(const fixture *f, double E, double ds_max, adh_run *run, adh_static_result *r)
{
    adh_material m = f->m;
    m.E = E;
    adh_static_settings ss = adh_static_settings_default();
    ss.h0_end = FIX_TURN;
    ss.ds_max = ds_max;
    adh_run_init(run);
    return adh_runner_static_curve(f->g, f->k, &m, &ss, NULL, NULL, run, r);
}

typedef struct vrun {
    int rc;
    adh_visco_result r;
    adh_run run;
    const adh_visco_event *ev;
    size_t nev;
    adh_visco *w;
} vrun;

/* One cycle: E0 = the fixture's E, Einf = ratio E0, relaxation time tau,
 * the drive d, tolerance tol, from start (NAN: the automatic one). Free
 * with vrun_free. */
static inline vrun fix_visco_tau(const fixture *f, double ratio, double tau, const adh_visco_drive *d, double tol,
                                 double start)
{
    vrun v;
    adh_sls sls = { f->m.E, ratio * f->m.E, tau };
    adh_visco_settings s = adh_visco_settings_default();
    s.tol = tol;
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    ps.start = start;
    adh_run_init(&v.run);
    v.w = adh_visco_alloc(f->g, f->k);
    char why[256] = "";
    v.rc = v.w ? adh_visco_set(v.w, &f->m, &sls, d, &s, &ps, &v.run, why, sizeof why) : ADH_ENOMEM;
    if (v.rc == ADH_SUCCESS)
        v.rc = adh_visco_run(v.w);
    if (v.rc != ADH_SUCCESS)
        printf("# run stopped: %s %s %s\n", adh_strerror(v.rc), why, v.w ? adh_visco_why(v.w) : "");
    if (v.w) {
        adh_visco_summary(v.w, &v.r);
        v.nev = adh_visco_events(v.w, &v.ev);
    }
    return v;
}

/* A solver set for one cycle to the fixture's turn under sls and the
 * drive d (default settings and protocol otherwise, the IDAS integrator), to be stepped by
 * hand: *rc ADH_CONTINUE, or why it was not set. Free it and run. */
static inline adh_visco *fix_visco_begin(const fixture *f, const adh_sls *sls, const adh_visco_drive *d, adh_run *run,
                                         int *rc)
{
    adh_visco_settings s = adh_visco_settings_default();
    s.integrator = ADH_VISCO_IDAS; /* its callers look into IDAS's jumps */
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    adh_run_init(run);
    adh_visco *w = adh_visco_alloc(f->g, f->k);
    *rc = w ? adh_visco_set(w, &f->m, sls, d, &s, &ps, run, NULL, 0) : ADH_ENOMEM;
    if (*rc == ADH_SUCCESS)
        *rc = ADH_CONTINUE;
    return w;
}

/* The same at tau = FIX_TAU. */
static inline vrun fix_visco_from(const fixture *f, double ratio, const adh_visco_drive *d, double tol, double start)
{
    return fix_visco_tau(f, ratio, FIX_TAU, d, tol, start);
}

static inline vrun fix_visco(const fixture *f, double ratio, const adh_visco_drive *d, double tol)
{
    return fix_visco_from(f, ratio, d, tol, NAN);
}

static inline void vrun_free(vrun *v)
{
    adh_visco_free(v->w);
    adh_run_free(&v->run);
}

static inline adh_visco_drive fix_drive(double v_in, double v_out)
{
    adh_visco_drive d = adh_visco_drive_default();
    d.speed_in = v_in;
    d.speed_out = v_out;
    return d;
}

/* Distance from point (x, y) to the segment (x0, y0)-(x1, y1). */
static inline double seg_dist(double x, double y, double x0, double y0, double x1, double y1)
{
    double dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - x0) * dx + (y - y0) * dy) / l2 : 0;
    t = fmin(1, fmax(0, t));
    return hypot(x - x0 - t * dx, y - y0 - t * dy);
}

/* How far the run's rows lie from the static curve st: each row's
 * distance to the curve's stable segments over its h0 (in the same contact state,
 * unless the curve has no fold and so one branch), h0 in units of z0 and
 * F in units of the curve's pull-off; the largest over the rows, and how
 * many rows had a segment in reach (within 0.1 z0 in h0). Rows within
 * 1 pm of a fold are left out: a slow drive's sphere is on its way from
 * one branch to the other there. */
static inline double static_gap(const adh_run *run, const adh_run *st, const adh_static_result *sr, double z0,
                         size_t *compared)
{
    double worst = 0, Fs = fabs(sr->pulloff_F);
    *compared = 0;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        if (fabs(o->h0 - sr->jump_in_h0) < 1e-12 || fabs(o->h0 - sr->jump_out_h0) < 1e-12)
            continue;
        double best = INFINITY;
        for (size_t j = 0; j + 1 < st->nrows; j++) {
            const adh_obs *a = &st->rows[j], *b = &st->rows[j + 1];
            if (!a->stable || !b->stable || fmin(fabs(o->h0 - a->h0), fabs(o->h0 - b->h0)) > 0.1 * z0)
                continue;
            /* a segment beside the row, not over it, is no measure of its
             * distance: its end's offset in h0 alone */
            if (o->h0 < fmin(a->h0, b->h0) - 1e-3 * z0 || o->h0 > fmax(a->h0, b->h0) + 1e-3 * z0)
                continue;
            if (sr->folds && ((a->a > 0) != (o->a > 0) || (b->a > 0) != (o->a > 0)))
                continue;
            best = fmin(best, seg_dist(o->h0 / z0, o->F / Fs, a->h0 / z0, a->F / Fs, b->h0 / z0, b->F / Fs));
        }
        if (isinf(best))
            continue;
        worst = fmax(worst, best);
        (*compared)++;
    }
    return worst;
}

/* An equilibrium's residual at frozen q, from the kernel's entries and the
 * law (not the solver's products): max_n |u_n + sum_j W_nj (cinf p_j +
 * cdel q_j)|, p at the gaps h = h0 + r^2/2R - u (into h). */
static inline double fix_frozen_residual(const fixture *f, const adh_sls *v, const double *u, const double *q,
                                         double h0, double *h)
{
    size_t n = f->g->n;
    double cinf = 2.0 / v->Einf, cdel = 2.0 * (1.0 / v->E0 - 1.0 / v->Einf), worst = 0;
    double *x = malloc(n * sizeof *x);
    if (!x)
        return INFINITY;
    for (size_t j = 0; j < n; j++) {
        h[j] = h0 + f->g->r[j] * f->g->r[j] / (2.0 * f->m.R) - u[j];
        x[j] = cinf * adh_lj_pressure(h[j], f->m.A, f->m.z0) + cdel * q[j];
    }
    for (size_t i = 0; i < n; i++) {
        double s = u[i];
        for (size_t j = 0; j < n; j++)
            s += adh_kernel_entry(f->k, i, j) * x[j];
        worst = fmax(worst, fabs(s));
    }
    free(x);
    return worst;
}

/* work - (dU + dissipation + jumps), relative to the work (or to the
 * largest of the parts when the work is tiny). */
static inline double energy_gap(const adh_visco_energy *e)
{
    double du = e->stored - e->stored0, rest = du + e->dissipated + e->jumps;
    double scale = fmax(fabs(e->work), fmax(fabs(du), fmax(e->dissipated, e->jumps)));
    return (e->work - rest) / scale;
}

#endif
