#include "adhere/models.h"

#include <math.h>

static double gamma_of(const adh_material *m)
{
    return m->A / (16.0 * M_PI * m->z0 * m->z0);
}

double adh_rigid_force(const adh_material *m, double h0)
{
    /* Rigid spheres cannot reach h0 <= 0: eq 22 has no value there. */
    if (!(h0 > 0))
        return NAN;
    double s6 = pow(m->z0 / h0, 6.0);
    return m->A * m->R / (6.0 * h0 * h0) * (s6 / 4.0 - 1.0);
}

double adh_bulge(const adh_material *m, double h)
{
    return -m->A * sqrt(2.0 * m->R) / (8.0 * m->E * pow(h, 2.5));
}

double adh_bulge_position(const adh_material *m, double h)
{
    return h - adh_bulge(m, h);
}

double adh_jump_separation(const adh_material *m)
{
    return pow(3.0 * m->A * sqrt(2.0 * m->R) / (8.0 * m->E), 2.0 / 7.0);
}

/* Johnson's reduced modulus is E* = E/2 with the paper's E (eq 12). */
double adh_hertz_force(const adh_material *m, double delta)
{
    if (delta <= 0)
        return 0;
    return 4.0 / 3.0 * (m->E / 2.0) * sqrt(m->R) * pow(delta, 1.5);
}

void adh_jkr(const adh_material *m, double a, double *F, double *overlap)
{
    /* The paper's gamma = -W(z0) is the whole work of adhesion of the LJ law, so
     * it is JKR's w directly, and the pull-off below is -(3/2) pi gamma R (eq 1). */
    double Es = m->E / 2.0, w = gamma_of(m);
    double a3 = a * a * a;
    if (F)
        *F = 4.0 * Es * a3 / (3.0 * m->R) - sqrt(8.0 * M_PI * w * Es * a3);
    if (overlap)
        *overlap = a * a / m->R - sqrt(2.0 * M_PI * w * a / Es);
}

double adh_dmt_force(const adh_material *m, double delta)
{
    return adh_hertz_force(m, delta) + adh_dmt_pulloff(m);
}

double adh_jkr_pulloff(const adh_material *m)
{
    return -1.5 * M_PI * gamma_of(m) * m->R;
}

double adh_dmt_pulloff(const adh_material *m)
{
    return -2.0 * M_PI * gamma_of(m) * m->R;
}

double adh_edge_zone(const adh_material *m)
{
    return 243.0 * M_PI * M_PI / 128.0 * m->E * pow(m->z0, 4) / m->A;
}
