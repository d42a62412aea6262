/* The elastic path's bound on the deformations it keeps (rule_path.c's
 * PATH_U_BYTES), made small here so that a 300-node curve (through a
 * spring: close points) crosses it: the first 256 rows fit, the next doubling does not, and the path goes on
 * without profiles. The same drive set again (the TUI's restart after an
 * edit) keeps its rows' deformations again from the first row: it must
 * allocate them anew, not write through the array the bound let go. */
#define PATH_U_BYTES ((size_t)(256 * 300 * sizeof(float) + 1))   /* FIX_N nodes */
#include "core/rule_path.c"   /* with the bound above, in place of libadhere.a's */

#include "adhere/runner.h"
#include "tap.h"
#include "visco_fixture.h"

static int one_run(adh_drive *dr, const fixture *f, size_t *curve_rows)
{
    adh_protocol_settings ps = adh_protocol_settings_default();
    ps.turns[0] = FIX_TURN;
    ps.nturns = 1;
    adh_run run;
    adh_run_init(&run);
    /* through a spring: points at most z0 / 4 apart, past 256 of them */
    adh_visco_rule_settings vs = adh_visco_rule_settings_default(f->m.E);
    vs.drive.spring = 10;
    int rc = adh_drive_set(dr, &f->m, &vs, &ps, &run);
    if (rc == ADH_SUCCESS)
        rc = adh_runner_drive(dr, NULL, NULL);
    const adh_run *c = adh_rule_path_curve(dr, NULL);
    *curve_rows = c ? c->nrows : 0;
    adh_rule_path_take(dr, &run);
    adh_run_free(&run);
    return rc;
}

int main(void)
{
    fixture f = fix_open(FIX_N, 1.0);
    adh_drive *dr = adh_drive_alloc(&adh_rule_path, f.g, f.k);
    size_t rows1 = 0, rows2 = 0;
    int rc1 = one_run(dr, &f, &rows1);
    ok(rc1 == ADH_SUCCESS && rows1 > 256, "the curve crosses the bound: %zu rows past 256 kept", rows1);
    int rc2 = one_run(dr, &f, &rows2);
    ok(rc2 == ADH_SUCCESS && rows2 == rows1, "the drive set again runs the same curve (%zu rows), its deformations "
       "kept anew", rows2);
    adh_drive_free(dr);
    fix_close(&f);
    return tap_done();
}
