/* The run specification's physical time (mode time): the standard linear
 * solid and the instrument's drive as the configuration holds them, the
 * viscoelastic rule's settings made from them, and what a mode cannot use. */
#include "scene/config.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "adhere/status.h"
#include "adhere/units.h"
#include "adhere/rule.h"
#include "adhere/visco.h"

adh_time_settings adh_time_settings_default(void)
{
    adh_visco_drive d = adh_visco_drive_default();
    adh_time_settings t = { .sls = 0, .Einf = NAN, .tau = 1e-3, .speed_in = d.speed_in, .speed_out = d.speed_out,
                            .dwell = d.dwell, .spring = d.spring, .tol = adh_visco_settings_default().tol,
                            .given = 0 };
    return t;
}

double adh_config_einf(const adh_run_spec *s)
{
    if (!s->time.sls)
        return s->mat.E;
    return isnan(s->time.Einf) ? 10 * s->mat.E : s->time.Einf;
}

void adh_config_visco(const adh_run_spec *s, adh_visco_rule_settings *out)
{
    *out = adh_visco_rule_settings_default(s->mat.E);
    out->sls.Einf = adh_config_einf(s);
    out->sls.tau = s->time.tau;
    out->drive = (adh_visco_drive){ .speed_in = s->time.speed_in, .speed_out = s->time.speed_out,
                                    .dwell = s->time.dwell, .spring = s->time.spring };
    out->s.tol = s->time.tol;
    out->s.cancel = s->relax.cancel;
}

const adh_rule_type *adh_config_time_rule(const adh_run_spec *s)
{
    return s->time.sls ? &adh_rule_visco : &adh_rule_path;
}

const char *adh_config_mode_word(adh_mode m)
{
    return m == ADH_MODE_STATIC ? "static" : m == ADH_MODE_RIGID ? "rigid" : m == ADH_MODE_TIME ? "time" : "relax";
}

/* The first key of bits, by its name. */
static const char *key_of(unsigned bits)
{
    return bits & ADH_TIME_E0 ? "material.E0" : bits & ADH_TIME_EINF ? "material.Einf" : bits & ADH_TIME_TAU
         ? "material.tau" : bits & ADH_TIME_SPEED ? "protocol.speed" : bits & ADH_TIME_DWELL ? "protocol.dwell_time"
         : "protocol.spring";
}

/* A modulus as a value a flag or a scene takes back, to six digits
 * ("100MPa": one word, the unit with it). */
static adh_qtext_buf arg_text(double pa)
{
    adh_qtext_buf t;
    adh_format_quantity(pa, ADH_Q_PRESSURE, 6, t.s, sizeof t.s);
    char *sp = strchr(t.s, ' ');
    if (sp)
        memmove(sp, sp + 1, strlen(sp));
    return t;
}

#define BAD(...)                                  \
    do {                                          \
        snprintf(why, whylen, __VA_ARGS__);       \
        return -1;                                \
    } while (0)

/* What a study of physical time's keys needs beyond each run's own check:
 * its figures' keys, and no eps (physical time has none). */
int adh_config_time_sweep_check(const adh_config *c, char *why, size_t whylen)
{
    adh_mode mode = c->spec.mode;
    const adh_sweep *sw = &c->sweep;
    int timed = adh_sweep_axis_of(sw, "protocol.speed") || adh_sweep_axis_of(sw, "protocol.speed_out");
    adh_sweep_plot plot = sw->plot;
    if (plot == ADH_SWEEP_PLOT_SPEED && (!timed || mode != ADH_MODE_TIME))
        BAD("sweep.plot = speed draws the pull-off against the swept speed: a sweep of speed or speed_out in "
            "physical time is needed (scene.mode = time)");
    if (plot == ADH_SWEEP_PLOT_SNAP && (!adh_sweep_axis_of(sw, "protocol.spring") ||
                                        (mode != ADH_MODE_TIME && mode != ADH_MODE_STATIC)))
        BAD("sweep.plot = snap draws the snap points against the spring: a sweep of spring in scene.mode = static "
            "or time is needed");
    if ((plot == ADH_SWEEP_PLOT_SPEED || plot == ADH_SWEEP_PLOT_SNAP) && sw->naxes != 1)
        BAD("sweep.plot = %s draws one swept key: the study varies %zu (plot = curves or map for more)",
            plot == ADH_SWEEP_PLOT_SPEED ? "speed" : "snap", sw->naxes);
    if (adh_sweep_axis_of(sw, "solver.eps") && mode == ADH_MODE_TIME)
        BAD("sweep.eps varies the relaxation's convergence parameter: physical time has none (its steps follow a "
            "tolerance on the solution)");
    return 0;
}

int adh_config_time_check(const adh_config *c, const adh_run_spec *s, char *why, size_t whylen)
{
    const adh_time_settings *t = &s->time;
    adh_mode mode = s->mode;
    if (t->sls && mode != ADH_MODE_TIME)
        BAD("material.material = sls runs in physical time: scene.mode = %s cannot use it (leave the mode out, or "
            "scene.mode = time)", adh_config_mode_word(mode));
    unsigned solid = t->given & (ADH_TIME_E0 | ADH_TIME_EINF | ADH_TIME_TAU);
    if (solid && !t->sls)
        BAD("%s is a standard linear solid's: material.material = elastic cannot use it (material.material = sls, "
            "or leave %s out)", key_of(solid), key_of(solid));
    /* an elastic sphere in time follows its static curve: no integration
     * whose tolerance this could be (the curve's own is the static one's) */
    if ((t->given & ADH_TIME_TOL) && !t->sls)
        BAD("solver.time_tol is the time integration's tolerance, a standard linear solid's: material.material = "
            "elastic integrates nothing in time (material.material = sls, or leave solver.time_tol out)");
    unsigned drive = t->given & (ADH_TIME_SPEED | ADH_TIME_DWELL);
    if (drive && mode != ADH_MODE_TIME)
        BAD("%s is physical time's: scene.mode = %s steps the drive in eps-time (material.material = sls, or "
            "scene.mode = time)", key_of(drive), adh_config_mode_word(mode));
    if ((t->given & ADH_TIME_SPRING) && isfinite(t->spring) && (mode == ADH_MODE_RELAX || mode == ADH_MODE_RIGID))
        BAD("protocol.spring is not allowed with scene.mode = %s: %s (scene.mode = static for the snap points of "
            "the static curve, or physical time)", adh_config_mode_word(mode), mode == ADH_MODE_RIGID
            ? "rigid spheres are followed at fixed positions only" : "the relaxation has no physical time for the "
            "sphere to follow the spring in");
    if (mode == ADH_MODE_TIME && s->proto.dwell)
        BAD("protocol.dwell = %zu counts relaxation iterations: in physical time the hold at a turn is "
            "protocol.dwell_time, in seconds", s->proto.dwell);
    if (mode == ADH_MODE_TIME) {
        adh_visco_rule_settings v;
        adh_config_visco(s, &v);
        /* E0 is the modulus as the user gave it: E, or E0 (the same value
         * under the solid's name), or neither (the default) */
        const char *e0 = adh_config_origin_last(c, "material.E", "material.E0");
        if (!(v.sls.Einf >= v.sls.E0))
            BAD("material.Einf = %s is below %s = %s%s: a standard linear solid is stiffest at first (Einf >= E0)",
                arg_text(v.sls.Einf).s, e0, arg_text(v.sls.E0).s,
                adh_config_origin(c, e0) == -2 ? " (the default)" : "");
        /* auto is 10 E0: past E0 = 100 GPa it is past Einf's own limit, and
         * the core's refusal named a value no one gave ("Einf = 2e+12 Pa") */
        if (isnan(t->Einf) && !(v.sls.Einf <= 1e12)) {
            adh_qtext_buf e0v = arg_text(v.sls.E0);
            char give[64];
            snprintf(give, sizeof give, v.sls.E0 < 1e12 ? "from %s to 1TPa" : "= %s", e0v.s);
            BAD("material.Einf = auto (10 times %s = %s) is %s, above 1TPa, the instantaneous modulus's limit: "
                "give material.Einf %s, or %s up to 100GPa", e0, e0v.s, arg_text(v.sls.Einf).s, give, e0);
        }
        char msg[256];
        if (adh_sls_validate(&v.sls, msg, sizeof msg) != ADH_SUCCESS ||
            adh_visco_drive_validate(&v.drive, msg, sizeof msg) != ADH_SUCCESS)
            BAD("%s", msg);
        /* below 1e-18 m the integrator stopped (1e-20 m did: tau = 10 fs at
         * 1 um/s), and the answer is the relaxed limit long before */
        double travel = v.sls.tau * fmin(v.drive.speed_in, v.drive.speed_out);
        /* at the limit to the product's rounding (1 ps x 1 um/s) is at it, not below */
        if (t->sls && travel < 1e-18 * (1 - 4 * DBL_EPSILON))
            BAD("material.tau x speed = %g m is below 1e-18 m: the solid relaxes before the drive moves a billionth "
                "of z0; material.material = elastic at E = E0 is that limit", travel);
    }
    return 0;
}
