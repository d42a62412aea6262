/* The physical-time fit's restarts (adh_fit_run) are probes of a fit
 * that converged: each has its own iteration budget, and one that runs
 * out leaves the fit converged. They shared one budget, so a fit whose
 * first search converged in its last allowed iteration was reported
 * ADH_EMAXITER, its gsl_info the restart's (0).
 *
 * The curve is the model's own at E0 = 1 GPa, Einf = 3 GPa, tau = 1 s,
 * A = 1e-19 J, R = 1 um (N = 150, 2 nm: fittime.sh's), driven at 1 nm/s
 * from 3 nm to -1 nm and back, 30 points each way, with seeded noise of
 * 1 % of the pull-off (GSL's MT19937). The fit starts at the truth; a
 * first fit finds how many iterations its first search takes (the
 * restart's first evaluation is the best point again, its chi2 the same
 * to the bit), and the second gives it exactly that many: under one
 * shared budget the restart had none left. */
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/fit.h"
#include "adhere/fitmodel.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "adhere/status.h"
#include "tap.h"

#define NAPP 30
#define NRET 30
#define N (NAPP + NRET)

static double x[N], F[N];
static int dir[N], contact[N], seg[N];

/* The model's curve at the truth on the points, and each point's side of
 * its segment's jump (the largest step of the force along the drive). */
static int make(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_fit_model_settings *ms)
{
    for (int i = 0; i < N; i++) {
        int a = i < NAPP;
        x[i] = a ? 3e-9 - 4e-9 * i / (NAPP - 1) : -1e-9 + 4e-9 * (i - NAPP + 1) / NRET;
        dir[i] = a ? 1 : -1;
        seg[i] = !a;
    }
    adh_fit_data d = { .n = N, .x = x, .F = F, .dir = dir, .contact = contact, .seg = seg };
    adh_fit_model *fm = adh_fit_model_alloc(g, k, ms);
    int rc = fm ? adh_fit_model_eval_sls(fm, m, &ms->visco.sls, 0, 0, &d, F, NULL) : ADH_ENOMEM;
    adh_fit_model_free(fm);
    if (rc != ADH_SUCCESS)
        return -1;
    int jin = 1, jout = NAPP + 1;   /* the first point past each jump */
    for (int i = 1; i < NAPP; i++)
        if (fabs(F[i] - F[i - 1]) > fabs(F[jin] - F[jin - 1]))
            jin = i;
    for (int i = NAPP + 1; i < N; i++)
        if (fabs(F[i] - F[i - 1]) > fabs(F[jout] - F[jout - 1]))
            jout = i;
    for (int i = 0; i < N; i++)
        contact[i] = i < NAPP ? i >= jin : i < jout;
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 5);
    double sd = 0.01 * fabs(adh_jkr_pulloff(m));
    for (int i = 0; i < N; i++)
        F[i] += gsl_ran_gaussian(r, sd);
    gsl_rng_free(r);
    return 0;
}

/* The iterations before the first restart: those at the first
 * evaluation (not a Jacobian's) that repeats an earlier one's chi2. */
typedef struct watch {
    double chi2[512];
    size_t n, first;
} watch;

static int watch_restart(const adh_fit_progress *p, void *ctx)
{
    watch *w = ctx;
    if (p->jacobian || w->first)
        return 0;
    for (size_t i = 0; i < w->n; i++)
        if (w->chi2[i] == p->chi2)
            w->first = p->iterations;
    if (w->n < sizeof w->chi2 / sizeof w->chi2[0])
        w->chi2[w->n++] = p->chi2;
    return 0;
}

static adh_fit_result run(const adh_grid *g, const adh_kernel *k, const adh_fit_data *d, const adh_fit_settings *s)
{
    int st;
    adh_fit *f = adh_fit_alloc(g, k, d, s, &st);
    adh_fit_result res;
    memset(&res, 0, sizeof res);
    res.status = st;
    if (f)
        adh_fit_run(f, &res);
    adh_fit_free(f);
    printf("# max_iter %zu: status %d, gsl_info %d, %zu iterations, %zu evaluations\n", s->max_iter, res.status,
           res.gsl_info, res.iterations, res.evals);
    return res;
}

int main(void)
{
    adh_grid *g = adh_grid_alloc(150, 2e-9);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_material truth = adh_material_default();
    truth.R = 1e-6;
    adh_fit_settings s = adh_fit_settings_default();
    s.model.kind = ADH_FIT_MODEL_TIME;
    s.model.visco = adh_visco_rule_settings_default(truth.E);
    s.model.visco.sls = (adh_sls){ .E0 = truth.E, .Einf = 3 * truth.E, .tau = 1.0 };
    s.model.visco.drive.speed_in = s.model.visco.drive.speed_out = 1e-9;
    ok(make(g, k, &truth, &s.model) == 0, "the physical-time model's curve at the truth, %d points, with noise", N);
    adh_fit_data d = { .n = N, .x = x, .F = F, .dir = dir, .contact = contact, .seg = seg };

    s.free = 1u << ADH_FIT_E | 1u << ADH_FIT_A | 1u << ADH_FIT_EINF | 1u << ADH_FIT_TAU;
    s.start = truth;
    s.Einf = s.model.visco.sls.Einf;
    s.tau = s.model.visco.sls.tau;
    watch w = { .n = 0, .first = 0 };
    s.progress = watch_restart;
    s.ctx = &w;
    adh_fit_result first = run(g, k, &d, &s);
    ok(first.status == ADH_SUCCESS && w.first > 0 && first.iterations > w.first,
       "from the truth the first search converges in %zu iterations, and a restart goes on to %zu", w.first,
       first.iterations);
    s.progress = NULL;
    s.max_iter = w.first ? w.first : 1;
    adh_fit_result res = run(g, k, &d, &s);
    ok(res.iterations > s.max_iter, "with max_iter = %zu the restart has iterations of its own (%zu in all)", s.max_iter,
       res.iterations);
    ok(res.status == ADH_SUCCESS, "the fit is converged (status %d: %s)", res.status, adh_strerror(res.status));
    ok(res.gsl_info >= 1 && res.gsl_info <= 4, "its gsl_info is a converged search's (%d)", res.gsl_info);
    /* the same point to well within the model's noise (1e-9 of chi2), not
     * bit for bit: the cap is not to move the best point, rounding may */
    ok(fabs(res.chi2 - first.chi2) <= 1e-9 * first.chi2,
       "and its best point the one the fit without the cap found (chi2 %.6g, %.6g N^2)", res.chi2, first.chi2);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
