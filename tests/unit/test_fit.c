/* adhere fit's engine (adhere/fit.h) on synthetic curves made by the
 * program's own static curve at parameters the test chose, with seeded
 * noise (tests/unit/synth.h): Figure 1's material on a coarse resolved
 * grid (N = 200, spacing 3.4 nm, 0.29 edge zones), 60 points down from
 * 6 nm to -2 nm and 60 back up; the noise's standard deviation is 1 % of
 * the JKR pull-off (3.75 nN). Each fit takes ~20 evaluations of ~0.07 s.
 * And the measured-file path: a header with spaces and units, three
 * columns, through adh_measured_load and adh_fitdata_make, and each of
 * their refusals. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "adhere/fit.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/status.h"
#include "scene/fitdata.h"
#include "scene/measured.h"
#include "synth.h"
#include "tap.h"

static const adh_grid *G;
static const adh_kernel *K;

static adh_fit_result fit(const adh_fit_data *d, unsigned free, adh_material start, double offset)
{
    adh_fit_settings s = adh_fit_settings_default();
    s.free = free;
    s.start = start;
    s.offset = offset;
    int st;
    adh_fit_result res;
    memset(&res, 0, sizeof res);
    adh_fit *f = adh_fit_alloc(G, K, d, &s, &st);
    if (!f) {
        res.status = st;
        return res;
    }
    adh_fit_run(f, &res);
    adh_fit_free(f);
    printf("# fit: status %d, E %.6g (se %.3g), A %.6g (se %.3g), offset %.4g nm (se %.2g), chi2_red %.3g, "
           "%zu evals, %zu iters, %.2f s, flags %u %u\n", res.status, res.value[ADH_FIT_E], res.se[ADH_FIT_E],
           res.value[ADH_FIT_A], res.se[ADH_FIT_A], res.value[ADH_FIT_OFFSET] * 1e9, res.se[ADH_FIT_OFFSET] * 1e9,
           res.chi2_red, res.evals, res.iterations, res.seconds, res.flags[ADH_FIT_E], res.flags[ADH_FIT_A]);
    return res;
}

static int recovered(const adh_fit_result *r, int p, double truth, double tol)
{
    double v = r->value[p], se = r->se[p];
    printf("# %s: %.6g against %.6g: %.3g %%, %.2f standard errors\n", adh_fit_param_name((adh_fit_param)p), v,
           truth, 100 * (v - truth) / truth, fabs(v - truth) / se);
    return fabs(v - truth) <= tol * truth && fabs(v - truth) <= 2 * se;
}

int main(void)
{
    adh_material truth = adh_material_default();   /* Figure 1: E = 1 GPa, A = 1e-19 J, z0 = 0.5 nm, R = 10 um */
    adh_grid *g = adh_grid_alloc(300, 2.5e-9);
    adh_kernel *k = adh_kernel_alloc(g, ADH_KERNEL_PAPER);
    G = g;
    K = k;
    static synth s;
    ok(synth_make(&s, g, k, &truth, 6e-9, -2e-9, 60, 60, 0.01, 42, 0, 0) == 0,
       "the synthetic curve: jump-in %.4g nm, jump-out %.4g nm", s.jump_in * 1e9, s.jump_out * 1e9);
    unsigned EA = 1u << ADH_FIT_E | 1u << ADH_FIT_A;

    adh_material start = truth;
    start.E *= 1.3;
    start.A *= 0.8;
    adh_fit_result a = fit(&s.d, EA, start, 0);
    ok(a.status == ADH_SUCCESS && !a.flags[ADH_FIT_E] && !a.flags[ADH_FIT_A], "E, A at 1 %% noise: a fit");
    ok(recovered(&a, ADH_FIT_E, truth.E, 0.02), "E within 2 %% and two standard errors of the truth");
    ok(recovered(&a, ADH_FIT_A, truth.A, 0.02), "A within 2 %% and two standard errors of the truth");
    ok(a.chi2_red > 0.6 && a.chi2_red < 1.6, "chi2 per degree of freedom against the data's scatter is about 1: %.3g",
       a.chi2_red);
    ok(fabs(a.noise / (0.01 * fabs(adh_jkr_pulloff(&truth))) - 1) < 0.25,
       "the scatter the data show is the noise put in, within 25 %%: %.3g nN", a.noise * 1e9);

    start = truth;
    start.E *= 3;
    start.A /= 3;
    adh_fit_result b = fit(&s.d, EA, start, 0);
    ok(b.status == ADH_SUCCESS && fabs(b.value[ADH_FIT_E] / a.value[ADH_FIT_E] - 1) < 1e-3 &&
       fabs(b.value[ADH_FIT_A] / a.value[ADH_FIT_A] - 1) < 1e-3,
       "a start a factor 3 off (3E, A/3) converges to the same values (1e-3)");

    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
