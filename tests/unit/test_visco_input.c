/* Every way the viscoelastic solver refuses or stops, provoked: bad
 * materials, drives and settings refused with a sentence naming the value,
 * a start in contact, the cancel flag, a callback that stops, the step
 * cap, the grid's edge; and after a final status every call returns it. */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/rule_visco.h"
#include "adhere/runner.h"
#include "tap.h"
#include "visco_fixture.h"

static void refused(const char *what, int rc, const char *why, const char *needle)
{
    ok(rc == ADH_EINVAL && strstr(why, needle) != NULL, "%s refused: \"%s\"", what, why);
}

static int stop_after(const adh_obs *row, const adh_run *run, void *ctx)
{
    return run->nrows >= *(const size_t *)ctx;
}

/* The start's check before a run (adh_visco_start_check) refuses exactly
 * the starts where adh_visco_set cannot begin (ADH_ESTALL: no rest out of
 * contact), a soft and a 0.5 TPa solid, with and without a spring, over
 * starts 20 pm apart from 0.3 to 3.5 nm; the refusal names the start and
 * the contact's gap, 1.1 z0, and its nearest start is one (and a step
 * below it is not). */
static void start_check_agrees(const fixture *f, const adh_visco_drive *d0, const adh_protocol_settings *ps0,
                               adh_run *run)
{
    const adh_sls solids[] = { { 1e9, 1e10, 1e-3 }, { 0.5e12, 1e12, 1e-3 } };
    const double springs[] = { INFINITY, 10 };
    char why[512], msg[512] = "";
    for (size_t si = 0; si < 2; si++)
        for (size_t ki = 0; ki < 2; ki++) {
            adh_visco_drive d = *d0;
            d.spring = springs[ki];
            adh_protocol_settings ps = *ps0;
            adh_visco_settings s = adh_visco_settings_default();
            adh_visco *w = adh_visco_alloc(f->g, f->k);
            size_t agree = 0, refused_n = 0, total = 0;
            for (int j = 15; j <= 175; j++, total++) {
                ps.start = j * 2e-11;
                adh_run_free(run);
                adh_run_init(run);
                int set = adh_visco_set(w, &f->m, &solids[si], &d, &s, &ps, run, NULL, 0);
                unsigned fix = 0;
                int chk = adh_visco_start_check(f->g, f->k, &f->m, &solids[si], &d, &ps, why, sizeof why, &fix);
                agree += (chk == ADH_SUCCESS) == (set == ADH_SUCCESS) && (set == ADH_SUCCESS || set == ADH_ESTALL)
                         && (chk == ADH_SUCCESS || (chk == ADH_EINVAL && fix == ADH_FIX_START));
                if (chk != ADH_SUCCESS && refused_n++ == 0)
                    snprintf(msg, sizeof msg, "%s", why);
            }
            ok(agree == total && refused_n > 0 && refused_n < total,
               "E0 = %g Pa, k = %g N/m: the start's check and the solver agree at %zu of %zu starts (%zu refused)",
               solids[si].E0, springs[ki], agree, total, refused_n);
            ok(strstr(msg, "start = 300 pm is not allowed") && strstr(msg, "1.1 z0 = 550 pm"),
               "... the refusal names the start and the contact's gap: \"%s\"", msg);
            /* the nearest start it names is one, a step below it is not */
            const char *near = strstr(msg, "within the step 50 pm: ");
            char *unit = NULL;
            double at = near ? strtod(near + strlen("within the step 50 pm: "), &unit) : NAN;
            at *= unit && !strncmp(unit, " pm", 3) ? 1e-12 : unit && !strncmp(unit, " nm", 3) ? 1e-9 : NAN;
            ps.start = at;
            int yes = adh_visco_start_check(f->g, f->k, &f->m, &solids[si], &d, &ps, NULL, 0, NULL);
            ps.start = at - ps.step;
            int no = adh_visco_start_check(f->g, f->k, &f->m, &solids[si], &d, &ps, NULL, 0, NULL);
            ok(yes == ADH_SUCCESS && no == ADH_EINVAL,
               "... its nearest start, %.4g m, is one and a step below it is not", at);
            adh_visco_free(w);
        }
    /* the automatic start is one, for every E0 from 1 MPa to 1 TPa (Einf 10
     * E0 up to 1 TPa), with and without a spring: the CLI asks only of a
     * start given */
    size_t fine = 0, tried = 0;
    for (double E0 = 1e6; E0 <= 1.001e12; E0 *= sqrt(10.0))
        for (size_t ki = 0; ki < 2; ki++, tried++) {
            adh_sls v = { E0, fmin(10 * E0, 1e12), 1e-3 };
            adh_visco_drive d = *d0;
            d.spring = springs[ki];
            adh_protocol_settings ps = *ps0;
            ps.start = NAN;
            int chk = adh_visco_start_check(f->g, f->k, &f->m, &v, &d, &ps, why, sizeof why, NULL);
            fine += chk == ADH_SUCCESS;
            if (chk != ADH_SUCCESS)
                printf("# E0 = %g Pa, k = %g N/m: %s\n", E0, springs[ki], why);
        }
    ok(fine == tried, "the automatic start is one at %zu of %zu solids from 1 MPa to 1 TPa, k none and 10 N/m", fine,
       tried);
}

int main(void)
{
    char why[256];
    adh_sls good = { 1e9, 1e10, 1e-3 }, v = good;
    ok(adh_sls_validate(&good, why, sizeof why) == ADH_SUCCESS, "a standard linear solid is accepted");
    v.Einf = 0.5e9;
    refused("Einf < E0", adh_sls_validate(&v, why, sizeof why), why, "below E0");
    v = good, v.tau = 0;
    refused("tau = 0", adh_sls_validate(&v, why, sizeof why), why, "tau = 0");
    v = good, v.tau = NAN;
    refused("tau NaN", adh_sls_validate(&v, why, sizeof why), why, "tau");
    v = good, v.E0 = -1;
    refused("E0 < 0", adh_sls_validate(&v, why, sizeof why), why, "E0 = -1");

    adh_visco_drive d = adh_visco_drive_default(), e = d;
    ok(adh_visco_drive_validate(&d, why, sizeof why) == ADH_SUCCESS && isinf(d.spring),
       "the default drive (1 um/s, no spring) is accepted");
    e.speed_in = 0;
    refused("approach speed 0", adh_visco_drive_validate(&e, why, sizeof why), why, "approach speed 0");
    e = d, e.speed_out = -1e-6;
    refused("retraction speed < 0", adh_visco_drive_validate(&e, why, sizeof why), why, "retraction speed");
    e = d, e.spring = 0;
    refused("k = 0", adh_visco_drive_validate(&e, why, sizeof why), why, "spring k = 0");
    e = d, e.dwell = -1;
    refused("dwell < 0", adh_visco_drive_validate(&e, why, sizeof why), why, "dwell = -1");
    /* a value just outside its range is named with the digits that show it
     * outside: %g's six rounded 0.00099999999 N/m onto the floor, "spring k
     * = 0.001 N/m is not allowed: it must be from 0.001" */
    e = d, e.spring = 0.00099999999;
    refused("k just under the floor", adh_visco_drive_validate(&e, why, sizeof why), why, "spring k = 0.00099999999 N/m");
    e = d, e.spring = 10000.0001;
    refused("k just over the ceiling", adh_visco_drive_validate(&e, why, sizeof why), why, "spring k = 10000.0001 N/m");
    e = d, e.speed_in = 1.0000001;
    refused("approach speed just over 1 m/s", adh_visco_drive_validate(&e, why, sizeof why), why,
            "approach speed 1.0000001 m/s");
    e = d, e.dwell = 1000000.01;
    refused("dwell just over 1e6 s", adh_visco_drive_validate(&e, why, sizeof why), why, "dwell = 1000000.01 s");
    v = good, v.tau = 1000000.1;
    refused("tau just over 1e6 s", adh_sls_validate(&v, why, sizeof why), why, "tau = 1000000.1 s");
    v = good, v.E0 = 999.9999999;
    refused("E0 just under 1 kPa", adh_sls_validate(&v, why, sizeof why), why, "E0 = 999.9999999 Pa");
    adh_visco_settings s = adh_visco_settings_default();
    s.tol = 0;
    refused("tolerance 0", adh_visco_settings_validate(&s, why, sizeof why), why, "time tolerance = 0 is not allowed: it must be from 1e-10 to 1e-2");
    /* named with the digits that put it outside (%g's six read 0.01) */
    s.tol = 0.0100000001;
    refused("tolerance just over 1e-2", adh_visco_settings_validate(&s, why, sizeof why), why,
            "time tolerance = 0.0100000001 is not allowed");

    fixture f = fix_open(100, 1.0);
    adh_visco *w = adh_visco_alloc(f.g, f.k);
    adh_run run;
    adh_run_init(&run);
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    s = adh_visco_settings_default();
    v = good, v.Einf = 1e8;
    refused("a set with Einf < E0", adh_visco_set(w, &f.m, &v, &d, &s, &ps, &run, why, sizeof why), why,
            "below E0");
    ok(adh_visco_iterate(w) == ADH_EINVAL, "a solver never set refuses to step");
    ps.start = 0.6e-9;
    int rc = adh_visco_set(w, &f.m, &good, &d, &s, &ps, &run, why, sizeof why);
    ok(rc == ADH_ESTALL && strstr(why, "start") != NULL, "a start in contact: \"%s\"", why);
    start_check_agrees(&f, &d, &ps, &run);

    /* the cancel flag: stopped on request, the run marked */
    volatile sig_atomic_t cancel = 1;
    ps.start = NAN;
    s.cancel = &cancel;
    ok(adh_visco_set(w, &f.m, &good, &d, &s, &ps, &run, why, sizeof why) == ADH_SUCCESS, "set again");
    ok(adh_visco_iterate(w) == ADH_CONTINUE && run.nrows == 1, "the start's row comes first");
    ok(adh_visco_iterate(w) == ADH_EINTR && run.interrupted, "the cancel flag stops it (interrupted)");
    ok(adh_visco_iterate(w) == ADH_EINTR, "and every later call says so");

    /* as a step rule through the drive and the runner: a callback that
     * stops after 20 rows */
    adh_run_free(&run);
    s.cancel = NULL;
    size_t stop_at = 20;
    adh_visco_rule_settings rs = { good, d, s };
    fixture f3 = fix_open(FIX_N, 1.0);
    rc = adh_runner_rule(&adh_rule_visco, f3.g, f3.k, &f3.m, &rs, &ps, stop_after, &stop_at, &run);
    ok(rc == ADH_SUCCESS && run.interrupted && run.nrows == 20,
       "the rule, through the runner: a callback stops the run after its row 20 (%zu rows)", run.nrows);
    adh_run_free(&run);
    rc = adh_runner_rule(&adh_rule_visco, f3.g, f3.k, &f3.m, &rs, &ps, NULL, NULL, &run);
    ok(rc == ADH_SUCCESS && !isnan(run.jump_in_h0) && run.rows[run.nrows - 1].path == 1 &&
           run.rows[run.nrows - 1].h0 >= run.start,
       "the rule runs the whole cycle: jump-in at %.4g nm, the last row unloading at the start", run.jump_in_h0 * 1e9);
    adh_run_free(&run);
    adh_runner_rule(&adh_rule_visco, f3.g, f3.k, &f3.m, NULL, &ps, NULL, NULL, &run);
    ok(run.status == ADH_SUCCESS && run.nrows > 10, "and with no settings (elastic at E, 1 um/s)");
    fix_close(&f3);

    /* the step cap */
    adh_run_free(&run);
    s.max_steps = 30;
    adh_visco_set(w, &f.m, &good, &d, &s, &ps, &run, why, sizeof why);
    rc = adh_visco_run(w);
    ok(rc == ADH_EMAXITER && run.status == ADH_EMAXITER, "30 steps: ADH_EMAXITER");

    /* the grid's edge: 100 nodes (150 nm) and a turn at -3 nm */
    adh_run_free(&run);
    s = adh_visco_settings_default();
    ps.turns[0] = -3e-9;
    adh_visco_set(w, &f.m, &good, &d, &s, &ps, &run, why, sizeof why);
    rc = adh_visco_run(w);
    ok(rc == ADH_EGRID && run.rows[run.nrows - 1].a >= 0.9 * f.g->rmax,
       "the contact reaches 0.9 Rmax: ADH_EGRID, its row kept (a = %.3g m)", run.rows[run.nrows - 1].a);

    /* a stall in contact on a grid coarser than the one that resolves the
     * contact line (the visco scene's sphere on 120 rings of 5 nm, 1.054 nm
     * resolve it), provoked by a jump's relaxation cut at 10 steps: the
     * reason names the spacing and the one allowed, and asks for more
     * nodes or a finer spacing (before: the relaxation's words alone) */
    adh_run_free(&run);
    adh_material m5 = adh_material_default();
    m5.E = 0.3e9;
    fixture f5 = { m5, adh_grid_alloc(120, 5e-9), NULL };
    f5.k = f5.g ? adh_kernel_alloc(f5.g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL) : NULL;
    adh_visco *w5 = f5.k ? adh_visco_alloc(f5.g, f5.k) : NULL;
    adh_sls el5 = { m5.E, m5.E, 1e-3 };
    s = adh_visco_settings_default();
    s.max_jump_steps = 10;
    ps.turns[0] = 1e-9;
    rc = w5 ? adh_visco_set(w5, &m5, &el5, &d, &s, &ps, &run, why, sizeof why) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_visco_run(w5);
    printf("# %s: %s\n", adh_strerror(rc), w5 ? adh_visco_why(w5) : "");
    ok(rc == ADH_ESTALL && w5 && strstr(adh_visco_why(w5), "lattice folds stopped the integrator at t = ") &&
           strstr(adh_visco_why(w5), "on a grid of spacing 5 nm, coarser than the 1.054 nm that resolves them") &&
           adh_visco_fix(w5) == (ADH_FIX_SPACING | ADH_FIX_NODES),
       "a stall in contact on 5 nm rings names the spacing and the 1.054 nm that resolve the contact line, "
       "and asks for the grid (fix bits %#x)", w5 ? adh_visco_fix(w5) : 0u);
    adh_visco_free(w5);
    adh_kernel_free(f5.k);
    adh_grid_free(f5.g);
    ps.turns[0] = FIX_TURN;
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
    return tap_done();
}
