/* The Lennard-Jones surface pressure between parallel planes (paper eq 15). */
#ifndef ADHERE_LAW_H
#define ADHERE_LAW_H

/* p(h) = A/(6 pi h^3) [(z0/h)^6 - 1]; positive is repulsive. */
double adh_lj_pressure(double h, double A, double z0);
/* dp/dh */
double adh_lj_dpressure(double h, double A, double z0);
/* Energy per unit area W(h) = -A/(12 pi h^2) [1 - (z0/h)^6 / 4]: p = -dW/dh. */
double adh_lj_energy(double h, double A, double z0);

#endif
