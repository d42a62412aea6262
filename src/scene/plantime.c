/* The plan of a run in physical time (mode time): what `adhere --plan`
 * says of the material, the instrument and the time the protocol spans. */
#include "scene/plan.h"

#include <math.h>
#include <stdio.h>

#include "adhere/models.h"
#include "adhere/units.h"
#include "adhere/visco.h"

void adh_plan_time_print(FILE *f, const adh_config *cfg)
{
    adh_run_spec s;
    adh_config_sweep_run(cfg, 0, &s);
    adh_visco_rule_settings v;
    adh_config_visco(&s, &v);
    char a[64], b[64], c[64];
    fprintf(f, "mode: time (physical time: the path integrated with error control, relative tolerance %g; each "
               "fold or spring instability crossed as a jump)\n", v.s.tol);
    adh_format_quantity(v.sls.E0, ADH_Q_PRESSURE, 4, a, sizeof a);
    if (s.time.sls) {
        adh_material inf = s.mat;
        inf.E = v.sls.Einf;
        adh_derived d0, di;
        adh_material_derive(&s.mat, &d0);
        adh_material_derive(&inf, &di);
        adh_format_quantity(v.sls.Einf, ADH_Q_PRESSURE, 4, b, sizeof b);
        adh_format_quantity(v.sls.tau, ADH_Q_TIME, 4, c, sizeof c);
        fprintf(f, "material: standard linear solid: E0 = %s (relaxed, sigma %.4g), Einf = %s%s (instantaneous, "
                   "sigma %.4g), tau = %s\n", a, d0.sigma, b, isnan(s.time.Einf) ? " (auto: 10 E0)" : "",
                di.sigma, c);
    } else {
        fprintf(f, "material: elastic, E = %s (time only moves the drive: the curve is the static one)\n", a);
    }
    adh_format_quantity(v.drive.speed_in, ADH_Q_SPEED, 4, a, sizeof a);
    adh_format_quantity(v.drive.speed_out, ADH_Q_SPEED, 4, b, sizeof b);
    adh_format_quantity(v.drive.dwell, ADH_Q_TIME, 4, c, sizeof c);
    fprintf(f, "drive: the base at %s approaching, %s retracting; held %s at each turn\n", a, b, c);
    if (isfinite(v.drive.spring)) {
        adh_format_quantity(v.drive.spring, ADH_Q_STIFFNESS, 4, a, sizeof a);
        fprintf(f, "spring: k = %s between the base and the sphere (h0 = base + F/k; it snaps where dF/dh0 = k)\n", a);
    } else {
        fprintf(f, "spring: none (displacement control: h0 is the base)\n");
    }
    /* from the start to the deepest turn and back to the start (a spring's
     * run starts further out; a contact still held goes on past it) */
    double start = adh_config_start(&s), deep = adh_protocol_deepest_turn(&s.proto);
    if (s.proto.nturns && s.proto.unload) {
        double T = (start - deep) / v.drive.speed_in + (double)s.proto.nturns * v.drive.dwell +
                   (start - deep) / v.drive.speed_out;
        adh_format_quantity(T, ADH_Q_TIME, 4, a, sizeof a);
        fprintf(f, "span: about %s of physical time from the start to the deepest turn and back (%.3g tau)%s\n", a, T / v.sls.tau,
                isfinite(v.drive.spring) ? ", more from a spring's start" : "");
    }
}
