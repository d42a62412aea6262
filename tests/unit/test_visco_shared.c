/* A viscoelastic run holds its dense kernel's entries once for its
 * solvers: the path's preconditioner copies W (N^2 numbers) when the
 * solver is allocated, and the static solver that lands the first jump
 * into contact (src/core/visco_land.c), allocated there, reads them where
 * the path's preconditioner holds them. It used to copy them again, one
 * more N^2 matrix from the first jump on. Measured as the process's peak
 * resident memory (getrusage) from the solver's allocation to the turn
 * past the jump (Einf = 2 E0: the instantaneous problem folds), on N =
 * 1500 nodes: one copy is 18 MB, and the run grew 22 MB with it, 4 MB now
 * (the two preconditioners' LUs of the contact's nodes, the integrator's
 * vectors, the rows). */
#include <math.h>
#include <stdio.h>
#include <sys/resource.h>

#include "tap.h"
#include "visco_fixture.h"

static double peak_bytes(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? 1024.0 * (double)ru.ru_maxrss : NAN;
}

int main(void)
{
    const size_t n = 1500;
    fixture f = fix_open(n, 1.0);
    adh_sls sls = { f.m.E, 2 * f.m.E, FIX_TAU };
    adh_visco_drive d = fix_drive(1e-6, 1e-6);
    adh_visco_settings s = adh_visco_settings_default();
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    ps.unload = 0;   /* the loading alone: its jump into contact is the landing */
    adh_run run;
    adh_run_init(&run);
    adh_visco *w = adh_visco_alloc(f.g, f.k);
    double before = peak_bytes();
    char why[256] = "";
    int rc = w ? adh_visco_set(w, &f.m, &sls, &d, &s, &ps, &run, why, sizeof why) : ADH_ENOMEM;
    if (rc == ADH_SUCCESS)
        rc = adh_visco_run(w);
    double grown = peak_bytes() - before, copy = 8.0 * (double)n * (double)n;
    adh_visco_result r = { 0 };
    if (w)
        adh_visco_summary(w, &r);
    ok(rc == ADH_SUCCESS && isfinite(r.jump_in_h0) && r.jumps == 1 && r.jumps_relaxed == 0,
       "loading on %zu dense nodes (Einf = 2 E0) runs, its jump into contact landed at %.4g nm (%zu jumps, %zu relaxed; %s %s)", n, r.jump_in_h0 * 1e9, r.jumps, r.jumps_relaxed,
       adh_strerror(rc), why);
    ok(isfinite(grown) && grown < 0.5 * copy,
       "from the solver's allocation on, the peak memory grew %.2f MB, less than half a copy of W (%.1f MB)",
       grown / 1e6, copy / 1e6);
    adh_visco_free(w);
    adh_run_free(&run);
    fix_close(&f);
    return tap_done();
}
