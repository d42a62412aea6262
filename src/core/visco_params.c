/* The viscoelastic solver's inputs (adhere/visco.h): defaults and the one
 * check of each, for every driver. */
#include "adhere/visco.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/status.h"

#define BAD(...)                                   \
    do {                                           \
        if (why)                                   \
            snprintf(why, whylen, __VA_ARGS__);    \
        return ADH_EINVAL;                         \
    } while (0)

/* v, refused for lying outside [lo, hi], as %g shows it, with more digits
 * where %g's six would round it into the range: 0.00099999999 N/m read
 * "spring k = 0.001 N/m is not allowed: it must be from 0.001", a message
 * that named no value outside. */
typedef struct shown {
    char s[32];
} shown;

static shown outside(double v, double lo, double hi)
{
    shown t;
    for (int digits = 6; digits <= 17; digits++) {
        snprintf(t.s, sizeof t.s, "%.*g", digits, v);
        double back = strtod(t.s, NULL);
        if (!(back >= lo && back <= hi))
            break;
    }
    return t;
}

int adh_sls_validate(const adh_sls *v, char *why, size_t whylen)
{
    if (!(v->E0 >= 1e3 && v->E0 <= 1e12))
        BAD("E0 = %s Pa is not allowed: the relaxed modulus must be from 1 kPa to 1 TPa", outside(v->E0, 1e3, 1e12).s);
    if (!(v->Einf >= 1e3 && v->Einf <= 1e12))
        BAD("Einf = %s Pa is not allowed: the instantaneous modulus must be from 1 kPa to 1 TPa",
            outside(v->Einf, 1e3, 1e12).s);
    if (!(v->Einf >= v->E0))
        BAD("Einf = %g Pa is below E0 = %g Pa: a standard linear solid is stiffest at first (Einf >= E0)",
            v->Einf, v->E0);
    if (!(v->tau > 0 && v->tau <= 1e6))
        BAD("tau = %s s is not allowed: the relaxation time must be above 0 and at most 1e6 s",
            outside(v->tau, DBL_TRUE_MIN, 1e6).s);
    return ADH_SUCCESS;
}

adh_visco_drive adh_visco_drive_default(void)
{
    adh_visco_drive d = { .speed_in = 1e-6, .speed_out = 1e-6, .dwell = 0, .spring = INFINITY };
    return d;
}

int adh_visco_drive_validate(const adh_visco_drive *d, char *why, size_t whylen)
{
    if (!(d->speed_in > 0 && d->speed_in <= 1))
        BAD("approach speed %s m/s is not allowed: it must be above 0 and at most 1 m/s",
            outside(d->speed_in, DBL_TRUE_MIN, 1).s);
    if (!(d->speed_out > 0 && d->speed_out <= 1))
        BAD("retraction speed %s m/s is not allowed: it must be above 0 and at most 1 m/s",
            outside(d->speed_out, DBL_TRUE_MIN, 1).s);
    if (!(d->dwell >= 0 && d->dwell <= 1e6))
        BAD("dwell = %s s is not allowed: it must be from 0 to 1e6 s", outside(d->dwell, 0, 1e6).s);
    /* Softer than 1 mN/m the snap-in runs out to where the static curve's
     * hysteresis quadrature alone took minutes and ignored signals; stiffer
     * than 10 kN/m the spring holds like the base itself and physical time's
     * continuation could not step it (measured on the visco scene: 1e-4 and
     * 1e5 N/m stopped, 1e-3 to 1e4 ran). In physical time, too, softer
     * holds the sphere's position h0 = base + F/k only to the force's
     * tolerance over k: at 3e-4 and 1e-4 N/m four of six runs of the visco
     * sphere stopped, while 1e-3 to 1e-2 N/m ran at 1e-6 to 1 m/s.
     * Infinity is displacement control. */
    if (!(isinf(d->spring) && d->spring > 0) && !(d->spring >= ADH_SPRING_MIN && d->spring <= ADH_SPRING_MAX))
        BAD("spring k = %s N/m is not allowed: it must be from %g to %g N/m, or none (displacement control, "
            "what a stiffer spring approaches); a softer one would hold the sphere's position only to the "
            "force's tolerance over k", outside(d->spring, ADH_SPRING_MIN, ADH_SPRING_MAX).s, ADH_SPRING_MIN,
            ADH_SPRING_MAX);
    return ADH_SUCCESS;
}

adh_visco_settings adh_visco_settings_default(void)
{
    /* 5e-5: at 1e-4 the sigma = 75 cycle's hysteresis moved 0.59 % with the
     * tolerance halved (which lattice folds the path meets moves it ~0.2 %),
     * past the 0.5 % physical time promises; from 5e-5 on 0.26 %. The
     * Figure-4-like cycle costs 12 % more steps (docs/viscoelastic.md). */
    adh_visco_settings s = {
        .integrator = ADH_VISCO_AUTO,
        .tol = ADH_VISCO_TOL_DEFAULT,
        .active_tol = 0.1,
        .max_steps = 200000,
        .max_jump_steps = 20000,
        .cancel = NULL,
    };
    return s;
}

int adh_visco_settings_validate(const adh_visco_settings *s, char *why, size_t whylen)
{
    if (s->integrator < ADH_VISCO_AUTO || s->integrator > ADH_VISCO_ROTHE)
        BAD("integrator %d is not allowed: it must be 0 (auto), 1 (IDAS) or 2 (Rothe)", s->integrator);
    if (!(s->tol >= ADH_VISCO_TOL_MIN && s->tol <= ADH_VISCO_TOL_MAX))
        BAD("time tolerance = %s is not allowed: it must be from 1e-10 to 1e-2 (relative)",
            outside(s->tol, ADH_VISCO_TOL_MIN, ADH_VISCO_TOL_MAX).s);
    if (!(s->active_tol >= 0 && s->active_tol <= 1))
        BAD("active_tol %g is not allowed: it must be from 0 to 1", s->active_tol);
    if (s->max_steps < 10 || s->max_jump_steps < 10)
        BAD("max_steps (%zu) and max_jump_steps (%zu) must be at least 10", s->max_steps, s->max_jump_steps);
    return ADH_SUCCESS;
}

int adh_visco_tol_loose(double tol)
{
    return tol > ADH_VISCO_TOL_DEFAULT * (1 + 1e-12);
}

int adh_visco_rothe_applies(const adh_sls *v, const adh_visco_drive *d, const adh_visco_settings *s)
{
    if (s->integrator == ADH_VISCO_IDAS || isfinite(d->spring))
        return 0;
    return s->integrator == ADH_VISCO_ROTHE || v->Einf <= ADH_ROTHE_RATIO_MAX * v->E0 * (1 + 1e-12);
}

adh_visco_rule_settings adh_visco_rule_settings_default(double E)
{
    adh_visco_rule_settings r = {
        .sls = { .E0 = E, .Einf = E, .tau = 1e-3 },
        .drive = adh_visco_drive_default(),
        .s = adh_visco_settings_default(),
    };
    return r;
}
