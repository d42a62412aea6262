#include "adhere/params.h"

#include <math.h>
#include <stdio.h>

#include "adhere/status.h"
#include "adhere/units.h"

adh_material adh_material_default(void)
{
    adh_material m = { .E = 1e9, .A = 1e-19, .z0 = 0.5e-9, .R = 10e-6 };
    return m;
}

/* Each quantity must be finite and positive; the upper bounds reject values
 * that are surely a unit slip (a 1 km sphere, a 1e15 Pa modulus) rather than
 * physics, so the message can say so before a solve produces garbage. */
static int check(const char *name, double v, double lo, double hi, adh_quantity q,
                 char *why, size_t n)
{
    /* the limits as the refusal writes them are allowed, within a relative
     * 1e-12, the rounding of values with units: 100nm is 1.0000000000000001e-7 */
    if (isfinite(v) && v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12))
        return 0;
    if (why)
        snprintf(why, n, "%s = %s is out of range: allowed %s to %s", name, adh_qtext(v, q).s,
                 adh_qtext(lo, q).s, adh_qtext(hi, q).s);
    return 1;
}

int adh_material_validate(const adh_material *m, char *why, size_t whylen)
{
    if (check("E (modulus)", m->E, 1e3, 1e13, ADH_Q_PRESSURE, why, whylen) ||
        check("A (Hamaker constant)", m->A, 1e-24, 1e-15, ADH_Q_ENERGY, why, whylen) ||
        check("z0 (equilibrium separation)", m->z0, 1e-12, 1e-7, ADH_Q_LENGTH, why, whylen) ||
        check("R (effective radius)", m->R, 1e-9, 10.0, ADH_Q_LENGTH, why, whylen))
        return ADH_EINVAL;
    return ADH_SUCCESS;
}

double adh_material_gamma(const adh_material *m)
{
    return m->A / (16.0 * M_PI * m->z0 * m->z0);
}

/* gamma sqrt(R / z0^3): sigma times E */
static double sigma_E(const adh_material *m)
{
    return adh_material_gamma(m) * sqrt(m->R / (m->z0 * m->z0 * m->z0));
}

double adh_material_sigma(const adh_material *m)
{
    return sigma_E(m) / m->E;
}

double adh_material_modulus_at_sigma(const adh_material *m, double sigma)
{
    return sigma_E(m) / sigma;
}
