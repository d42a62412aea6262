#include "adhere/law.h"

#include <math.h>

extern inline double adh_lj_pressure(double h, double A, double z0);
extern inline double adh_lj_dpressure(double h, double A, double z0);

double adh_lj_energy(double h, double A, double z0)
{
    double s = z0 / h, s3 = s * s * s;
    return -A / (12.0 * M_PI * h * h) * (1.0 - s3 * s3 / 4.0);
}
