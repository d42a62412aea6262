/* The Lennard-Jones surface pressure between parallel planes (paper eq 15). */
#ifndef ADHERE_LAW_H
#define ADHERE_LAW_H

/* pi as <math.h>'s M_PI spells it, which strict ISO C leaves undefined */
#define ADH_LAW_PI 3.14159265358979323846

/* Inline: the relaxation evaluates p at every node of every iteration, and
 * a call per node cost ~7 % of its time (law.c holds the external
 * definitions, C99's inline model). */

/* p(h) = A/(6 pi h^3) [(z0/h)^6 - 1]; positive is repulsive. */
inline double adh_lj_pressure(double h, double A, double z0)
{
    double s = z0 / h, s3 = s * s * s;
    return A / (6.0 * ADH_LAW_PI * h * h * h) * (s3 * s3 - 1.0);
}

/* dp/dh */
inline double adh_lj_dpressure(double h, double A, double z0)
{
    double s = z0 / h, s3 = s * s * s;
    return A / (6.0 * ADH_LAW_PI * h * h * h * h) * (3.0 - 9.0 * s3 * s3);
}

/* Energy per unit area W(h) = -A/(12 pi h^2) [1 - (z0/h)^6 / 4]: p = -dW/dh. */
double adh_lj_energy(double h, double A, double z0);

#endif
