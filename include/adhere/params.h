/* Material parameters of the two spheres and the quantities derived from
 * them alone (paper eqs 12, 16, 17): gamma and Tabor's sigma. The closed
 * forms built on them (JKR/DMT pull-off, the jump separation, all of them
 * at once: adh_material_derive) are adhere/models.h's. SI units. */
#ifndef ADHERE_PARAMS_H
#define ADHERE_PARAMS_H

#include <stddef.h>

typedef struct adh_material {
    double E;   /* combined modulus, 2/E = sum (1-nu_i^2)/E_i, Pa (paper eq 12) */
    double A;   /* Hamaker constant, J */
    double z0;  /* Lennard-Jones equilibrium separation, m */
    double R;   /* effective radius, m (eq 4) */
} adh_material;

/* The paper's Figure 1 material: E = 1 GPa, A = 1e-19 J, z0 = 0.5 nm, R = 10 um. */
adh_material adh_material_default(void);

/* ADH_SUCCESS, or ADH_EINVAL with a sentence naming the bad value and the
 * allowed range written to why (if why is not NULL). */
int adh_material_validate(const adh_material *m, char *why, size_t whylen);

/* The work of adhesion of the Lennard-Jones law, gamma = A / (16 pi z0^2)
 * (eq 16), J/m^2, and Tabor's sigma = gamma sqrt(R / z0^3) / E (eq 17):
 * every module takes them from here. */
double adh_material_gamma(const adh_material *m);
double adh_material_sigma(const adh_material *m);
/* Eq 17 solved for E: the modulus at which m has Tabor's sigma, Pa. */
double adh_material_modulus_at_sigma(const adh_material *m, double sigma);

#endif
