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
#include <signal.h>
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

/* A signal that comes while the first Jacobian is differenced: raised
 * after the start's evaluation, seen by the next (E's column), which the
 * model then stops (ADH_EINTR) as SIGINT stops it. */
static volatile sig_atomic_t signalled;
static int signal_after_first(const adh_fit_progress *p, void *ctx)
{
    (void)ctx;
    if (p->evals == 1)
        signalled = 1;
    return 0;
}

/* The best point so far, with no standard error or correlation from that
 * Jacobian: its column of E held the refused point's penalty, and the
 * report said 'A 1e-19 J +- 7.3945e-28 J (7.4e-07 %)'. */
static void interrupted_jacobian(const adh_fit_data *d, adh_material start)
{
    adh_fit_settings s = adh_fit_settings_default();
    s.free = 1u << ADH_FIT_E | 1u << ADH_FIT_A;
    s.start = start;
    s.cancel = &signalled;
    s.progress = signal_after_first;
    int st;
    adh_fit *f = adh_fit_alloc(G, K, d, &s, &st);
    adh_fit_result res;
    int rc = f ? adh_fit_run(f, &res) : st;
    ok(rc == ADH_EINTR && res.evals == 2 && isfinite(res.chi2) && isnan(res.se[ADH_FIT_E]) &&
       isnan(res.se[ADH_FIT_A]) && isnan(res.corr[ADH_FIT_E][ADH_FIT_A]) && !res.flags[ADH_FIT_E] && !res.flags[ADH_FIT_A],
       "a signal in the first Jacobian: the start's chi2 kept, no standard error nor correlation from the Jacobian "
       "it cut short (status %d, %zu evaluations, se E %.3g Pa, A %.3g J, corr %.3g)", rc, rc == st ? 0 : res.evals,
       res.se[ADH_FIT_E], res.se[ADH_FIT_A], res.corr[ADH_FIT_E][ADH_FIT_A]);
    adh_fit_free(f);
}

static int recovered(const adh_fit_result *r, int p, double truth, double tol)
{
    double v = r->value[p], se = r->se[p];
    printf("# %s: %.6g against %.6g: %.3g %%, %.2f standard errors\n", adh_fit_param_name((adh_fit_param)p), v,
           truth, 100 * (v - truth) / truth, fabs(v - truth) / se);
    return fabs(v - truth) <= tol * truth && fabs(v - truth) <= 2 * se;
}

/* A file and what its refusal must say. */
static void refused(const char *path, const char *text, const char *columns, size_t nfree, const char *want,
                    const char *what)
{
    FILE *f = fopen(path, "wb");
    fwrite(text, 1, strlen(text) + (strstr(what, "NUL") ? 1 : 0), f);
    if (strstr(what, "NUL"))
        fputs("\n3 4\n", f);
    fclose(f);
    adh_measured m;
    char why[1024] = "";
    adh_material start = adh_material_default();
    int rc = adh_measured_load(path, columns, &m, why, sizeof why);
    if (rc == 0) {
        adh_fitdata fd;
        rc = adh_fitdata_make(&m, nfree, &start, 0, 0, &fd, why, sizeof why);
        if (rc == 0)
            adh_fitdata_free(&fd);
        adh_measured_free(&m);
    }
    ok(rc != 0 && strstr(why, want) && strncmp(why, path, strlen(path)) == 0, "%s: refused with the file, line and "
       "reason (%s)", what, why);
    unlink(path);
}

/* A start without adhesion (A = 0): no JKR pull-off, so no ratio of the
 * curve's attraction to it; said so ("inf times the JKR pull-off" was not). */
static void no_adhesion(const char *path)
{
    FILE *f = fopen(path, "w");
    for (int i = 0; i < 40; i++)   /* an approach in nm and nN, a jump half-way */
        fprintf(f, "%g %g\n", 6.0 - 0.2 * i, i < 20 ? -1.0 : -300.0 + 10 * (i - 20));
    fclose(f);
    adh_measured m;
    adh_fitdata fd;
    char why[1024] = "";
    adh_material start = adh_material_default();
    start.A = 0;
    int rc = adh_measured_load(path, NULL, &m, why, sizeof why);
    ok(rc == 0, "no adhesion: the curve loads (%s)", why);
    if (rc == 0) {
        rc = adh_fitdata_make(&m, 2, &start, 0, 0, &fd, why, sizeof why);
        if (rc == 0)
            adh_fitdata_free(&fd);
        adh_measured_free(&m);
    }
    ok(rc != 0 && strstr(why, ":21: the strongest attraction is -300 nN, but the start values have no adhesion "
                               "(A = 0 J: no JKR pull-off to compare it with): start A above 0") && !strstr(why, "inf"),
       "A = 0 at the start: refused, no ratio to a pull-off there is none of (%s)", why);
    unlink(path);
}

/* A curve with no force below the baseline has no attraction: refused in
 * those words (it was called its 'strongest attraction', and a fit of A
 * from it ran to 'unidentifiable'); the same curve over its baseline, given,
 * is the attraction it holds. */
static void no_attraction(const char *path)
{
    FILE *f = fopen(path, "w");
    for (int i = 0; i < 40; i++)   /* no_adhesion's approach 310 nN up: the least force 10 nN, line 21 */
        fprintf(f, "%g %g\n", 6.0 - 0.2 * i, i < 20 ? 309.0 : 10.0 + 10 * (i - 20));
    fclose(f);
    adh_material start = adh_material_default();   /* JKR pull-off -375 nN */
    for (int given = 0; given < 2; given++) {
        adh_measured m;
        adh_fitdata fd;
        char why[1024] = "";
        int rc = adh_measured_load(path, NULL, &m, why, sizeof why);
        ok(rc == 0, "no attraction: the curve loads (%s)", why);
        if (rc != 0)
            continue;
        rc = adh_fitdata_make(&m, 2, &start, 0, given ? 310e-9 : 0, &fd, why, sizeof why);
        if (rc == 0)
            adh_fitdata_free(&fd);
        adh_measured_free(&m);
        if (given)
            ok(rc == 0, "over a baseline of 310 nN, given: 300 nN of attraction, taken (%s)", why);
        else
            ok(rc != 0 && strstr(why, ":21: no attraction in the data: the least force, 10 nN, is not below the "
                                       "baseline (0 nN)") && !strstr(why, "strongest attraction"),
               "no force below the baseline: refused as no attraction, none called the strongest (%s)", why);
    }
    unlink(path);
}

/* Every refusal of the data path names the file and line and says why. */
static void refusals(const char *path)
{
    refused(path, "h0 (nm)\tF (nN)\n1\t2\n0.5\tnan\n", NULL, 2, ":3: 'nan' is not a finite number (a gap in the measurement?) (column 2, the force)",
            "a NaN");
    refused(path, "1 2\n0.5 1e-320\n", NULL, 2, ":2: '1e-320' is too small for a double (it underflows",
            "1e-320");
    refused(path, "1 2\n0.5 abc\n", NULL, 2, ":2: 'abc' is not a number (column 2, the force)", "a non-number");
    refused(path, "1 2", NULL, 2, ":1: a NUL byte", "a NUL byte");
    refused(path, "z force\n1 2\n", NULL, 2, ":1: the header's 'z' does not name the position's unit",
            "a header without units");
    refused(path, "a (nm),b (nN),c (s)\n1,2,3\n", NULL, 2, ":1: 3 columns", "three columns without names it knows");
    refused(path, "h0 (nm),F (nN),t (s)\n1,2,3\n", "h0,G", 2, "column 'G' is not in the header", "--columns naming no column");
    /* an approach with no jump: the force only grows as the drive comes in */
    char buf[4096];
    int len = 0;
    for (int i = 0; i < 40; i++)
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%g %g\n", 6.0 - 0.2 * i, -1.0 + 0.05 * i);
    refused(path, buf, NULL, 2, ":1-40: no jump in this approach segment", "a curve without a jump");
    /* a jump at the very end: one point in contact */
    len = 0;
    for (int i = 0; i < 40; i++)
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%g %g\n", 6.0 - 0.2 * i, i < 39 ? -1.0 : -300.0);
    refused(path, buf, NULL, 2, "1 point past the jump, in contact", "too few points in contact");
    /* positions going back and forth within a segment */
    len = 0;
    for (int i = 0; i < 40; i++)
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%g %g\n", 6.0 - 0.2 * i + (i == 20 ? 0.5 : 0),
                        i < 30 ? -1.0 : -300.0);
    refused(path, buf, NULL, 2, ":21: the position goes back within a segment", "a non-monotonic position");
    /* nm written where the file meant um: the positions leave the model's reach */
    len = snprintf(buf, sizeof buf, "h0 (um)\tF (nN)\n");
    for (int i = 0; i < 40; i++)
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%g\t%g\n", 6.0 - 0.2 * i, i < 30 ? -1.0 : -300.0);
    refused(path, buf, NULL, 2, ":2: the position 6 um is beyond the model's reach", "positions in the wrong unit");
    /* pN written where the file meant nN: the adhesion is 1000 times too small */
    len = snprintf(buf, sizeof buf, "h0 (nm)\tF (pN)\n");
    for (int i = 0; i < 40; i++)
        len += snprintf(buf + len, sizeof buf - (size_t)len, "%g\t%g\n", 6.0 - 0.2 * i, i < 30 ? -1.0 : -300.0 + i);
    refused(path, buf, NULL, 2, "times the JKR pull-off at the start values", "forces in the wrong unit");
}

int main(void)
{
    adh_material truth = adh_material_default();   /* Figure 1: E = 1 GPa, A = 1e-19 J, z0 = 0.5 nm, R = 10 um */
    adh_grid *g = adh_grid_alloc(300, 2.5e-9);
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
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
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("the start a factor 3 off (the fit of E and A above, from further)");
    } else {
        adh_fit_result b = fit(&s.d, EA, start, 0);
        ok(b.status == ADH_SUCCESS && fabs(b.value[ADH_FIT_E] / a.value[ADH_FIT_E] - 1) < 1e-3 &&
           fabs(b.value[ADH_FIT_A] / a.value[ADH_FIT_A] - 1) < 1e-3,
           "a start a factor 3 off (3E, A/3) converges to the same values (1e-3)");
    }

    start = truth;
    start.E *= 1.3;
    start.A *= 0.8;
    interrupted_jacobian(&s.d, start);

    /* the position offset: the same curve measured 0.7 nm further out, a
     * baseline of 2 nN; offset and baseline free beside E and A */
    static synth so;
    synth_make(&so, g, k, &truth, 6.7e-9, -1.3e-9, 60, 60, 0.01, 7, 0.7e-9, 2e-9);
    start = truth;
    start.E *= 1.3;
    start.A *= 0.8;
    adh_fit_result c = fit(&so.d, EA | 1u << ADH_FIT_OFFSET | 1u << ADH_FIT_BASELINE, start, 0.3e-9);
    printf("# offset %.4f nm (se %.2g), baseline %.3f nN (se %.2g)\n", c.value[ADH_FIT_OFFSET] * 1e9,
           c.se[ADH_FIT_OFFSET] * 1e9, c.value[ADH_FIT_BASELINE] * 1e9, c.se[ADH_FIT_BASELINE] * 1e9);
    ok(c.status == ADH_SUCCESS && fabs(c.value[ADH_FIT_OFFSET] - 0.7e-9) < 0.05e-9,
       "the position offset recovered to 0.05 nm (started 0.4 nm off)");
    ok(recovered(&c, ADH_FIT_E, truth.E, 0.02) && recovered(&c, ADH_FIT_A, truth.A, 0.02),
       "with E and A within 2 %% and two standard errors");

    /* R: the model's force curve is gamma R times a function of h0 / z0 and
     * sigma alone (lengths across the surface scale with sqrt(R z0)), so a
     * curve made with R = 10 um is fitted exactly with R = 7 um held fixed:
     * E and A move to keep gamma R and sigma, which the test checks; R is
     * not identifiable from a force curve beside E and A. With E held at
     * the truth, only A free, the wrong R cannot be made up for: the fit
     * fails honestly, its chi2 far above the data's scatter. */
    start = truth;
    start.R = 7e-6;
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("R = 7 um fixed, E and A free (the fit of E and A above, another R)");
    } else {
        adh_fit_result d = fit(&s.d, EA, start, 0);
        double gR = adh_material_gamma(&d.best) * d.best.R / (adh_material_gamma(&truth) * truth.R);
        double sg = adh_material_sigma(&d.best) / adh_material_sigma(&truth);
        ok(d.chi2_red < 1.6 && fabs(gR - 1) < 0.01 && fabs(sg - 1) < 0.01,
           "R = 7 um fixed, E and A free: gamma R and sigma as made (%.4f, %.4f), chi2/dof %.3g", gR, sg, d.chi2_red);
    }
    adh_fit_result d2 = fit(&s.d, 1u << ADH_FIT_A, start, 0);
    ok(isfinite(d2.chi2_red) && d2.chi2_red > 4, "R = 7 um and E fixed, A free: a poor fit (chi2/dof %.3g against "
       "the data's scatter, above 4)", d2.chi2_red);
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("E, A and R free (the fits of E and A, and of four parameters with the offset)");
    } else {
        adh_fit_result d4 = fit(&s.d, EA | 1u << ADH_FIT_R, truth, 0);
        ok(d4.flags[ADH_FIT_R] || d4.flags[ADH_FIT_E] || d4.flags[ADH_FIT_A] ||
               fabs(d4.corr[ADH_FIT_A][ADH_FIT_R]) > 0.99,
           "E, A and R free: reported unidentifiable or correlated above 0.99 (flags E %u A %u R %u, corr A-R %.4f)",
           d4.flags[ADH_FIT_E], d4.flags[ADH_FIT_A], d4.flags[ADH_FIT_R], d4.corr[ADH_FIT_A][ADH_FIT_R]);
    }

    /* forces written more coarsely than their noise (an export in uN with
     * two decimals: steps of q = 10 nN over noise of 0.5 nN): most second
     * differences are 0, so their median is, and the scatter read 0, chi2
     * per degree of freedom inf, a good fit "poor". The rounding is a noise
     * of its own, uniform over a step: standard deviation q / sqrt(12). */
    if (tap_sanitized_short()) {
        tap_sanitized_leaves_out("forces in steps of 10 nN (the fit of E and A above, on rounded forces)");
    } else {
        static synth sq;
        synth_make(&sq, g, k, &truth, 6e-9, -2e-9, 60, 60, 0.5e-9 / fabs(adh_jkr_pulloff(&truth)), 11, 0, 0);
        const double q = 10e-9;
        for (size_t i = 0; i < sq.n; i++)
            sq.F[i] = q * round(sq.F[i] / q);
        start = truth;
        start.E *= 1.3;
        start.A *= 0.8;
        adh_fit_result qr = fit(&sq.d, EA, start, 0);
        double qsd = q / sqrt(12.0), qall = sqrt(qsd * qsd + 0.25e-18);
        ok(qr.noise >= qsd * (1 - 1e-9) && qr.noise < 1.25 * qall,
           "forces in steps of 10 nN over 0.5 nN of noise: the scatter is at least the rounding's, q/sqrt(12) = %.4g nN "
           "(%.4g nN)", qsd * 1e9, qr.noise * 1e9);
        ok(qr.status == ADH_SUCCESS && qr.chi2_red > 0.6 && qr.chi2_red < 1.6 &&
           recovered(&qr, ADH_FIT_E, truth.E, 0.02),
           "and the fit is a fit: chi2 per degree of freedom %.3g, E within 2 %% and two standard errors", qr.chi2_red);
    }

    /* the measured-file path: a header with spaces and units, three
     * columns, tab-separated, read and labelled as adhere fit reads it */
    char path[64];
    snprintf(path, sizeof path, "/tmp/adhere-test-fit-%ld.tsv", (long)getpid());
    ok(synth_write(&s, path, "synthetic: Figure 1, 1 % noise, seed 42") == 0, "the curve written as an instrument file");
    adh_measured m;
    char why[1024];
    int rc = adh_measured_load(path, NULL, &m, why, sizeof why);
    ok(rc == 0 && m.n == s.n && m.nseg == 2 && m.seg[0].dir == 1 && m.seg[1].dir == -1,
       "read back: %zu points, %zu segments, approach then retract (%s)", m.n, m.nseg, rc ? why : m.columns);
    adh_fitdata fd;
    rc = rc == 0 ? adh_fitdata_make(&m, 2, &truth, 0, 0, &fd, why, sizeof why) : -1;
    ok(rc == 0, "labelled for a fit (%s)", rc ? why : "ok");
    int same = rc == 0 && fd.d.n == s.n;
    for (size_t i = 0; rc == 0 && i < s.n; i++)
        if (fd.d.contact[i] != s.contact[i] || (fd.d.dir[i] != s.dir[i] && i != 59)) {   /* 59: the turn, either's */
            printf("# point %zu (x %.4g nm): data says contact %d dir %d, the model %d %d\n", i, s.x[i] * 1e9,
                   fd.d.contact[i], fd.d.dir[i], s.contact[i], s.dir[i]);
            same = 0;
        }
    ok(same, "each point's branch from the data's own jumps is the model's (%zu in contact)", rc ? 0 : fd.ncontact);
    if (rc == 0 && tap_sanitized_short()) {
        tap_sanitized_leaves_out("the fit of the file's curve (the fit of E and A above, its data read back)");
        adh_fitdata_free(&fd);
    } else if (rc == 0) {
        start = truth;
        start.E *= 1.3;
        start.A *= 0.8;
        adh_fit_result e = fit(&fd.d, EA, start, 0);
        ok(fabs(e.value[ADH_FIT_E] / a.value[ADH_FIT_E] - 1) < 2e-3 && fabs(e.value[ADH_FIT_A] / a.value[ADH_FIT_A] - 1) < 2e-3,
           "and fitted to the same E and A as the curve itself (the file rounds to 1e-6 nm and nN)");
        adh_fitdata_free(&fd);
    }
    adh_measured_free(&m);
    unlink(path);

    refusals(path);
    no_adhesion(path);
    no_attraction(path);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
