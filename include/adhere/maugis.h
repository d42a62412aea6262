/* The Maugis-Dugdale contact (Maugis 1992, in the form of Johnson and
 * Greenwood 1997): a Dugdale stress sigma0 acting over the annulus a < r < c
 * bridges JKR (lambda -> infinity) and DMT (lambda -> 0). Its parameter is
 * taken from Tabor's as lambda = 1.16 mu, Johnson and Greenwood's match of
 * the Dugdale law to the Lennard-Jones law (same work of adhesion, same
 * range). Closed form, SI units, no I/O.
 *
 * Nondimensional form: K = (4/3) E* = (2/3) E (the paper's E), w = gamma,
 *   A = a (K / (pi w R^2))^(1/3),  P = F / (pi w R),
 *   D = overlap (K^2 / (pi^2 w^2 R))^(1/3),  m = c / a > 1,
 *   (lambda A^2/2)[s + (m^2-2) atan s] + (4 lambda^2 A/3)[s atan s - m + 1] = 1,
 *   P = A^3 - lambda A^2 [s + m^2 atan s],   D = A^2 - (4/3) A lambda s,
 * with s = sqrt(m^2 - 1). The overlap is positive for interpenetration of the
 * undeformed spheres; compared with the drive position of the Lennard-Jones
 * model, h0 = z0 - overlap (the surfaces touch at z0, as in eq 22). */
#ifndef ADHERE_MAUGIS_H
#define ADHERE_MAUGIS_H

#include <stddef.h>
#include "adhere/models.h"
#include "adhere/params.h"

typedef struct adh_md_point {
    double a;        /* contact radius, m */
    double c;        /* outer radius of the Dugdale zone, m */
    double F;        /* force, N; positive is repulsive */
    double overlap;  /* approach of the undeformed surfaces, m */
} adh_md_point;

/* lambda = 1.16 mu, mu = 4^(1/3) sigma^(2/3). */
double adh_md_lambda(const adh_material *m);
/* The Dugdale stress sigma0 (Pa) that goes with lambda. */
double adh_md_stress(const adh_material *m, double lambda);

/* The point at contact radius a > 0. ADH_EINVAL for a <= 0 or lambda <= 0,
 * ADH_EMAXITER if the root for c could not be bracketed or GSL's root
 * solver did not converge, ADH_ENOMEM. */
int adh_md_at_radius(const adh_material *m, double lambda, double a, adh_md_point *pt);

/* The curve on n >= 2 contact radii spaced evenly from a_max/n to a_max. */
int adh_md_curve(const adh_material *m, double lambda, double a_max, size_t n, adh_md_point *pts);

/* Pull-off under load control (minimum force, F_load, at contact radius
 * a_load) and under displacement control (force at the minimum overlap:
 * the fold where a displacement-driven contact jumps out). Any output may
 * be NULL. */
int adh_md_pulloff(const adh_material *m, double lambda, double *F_load, double *a_load,
                   double *F_disp, double *overlap_disp);

/* The curve against the drive position (adh_model_curve, models.h): down to
 * the fold, or, in the DMT-like limit where the overlap has no minimum,
 * down to a contact radius 1/ADH_MODEL_POINTS of the deepest. ADH_SUCCESS,
 * ADH_EINVAL for lambda <= 0 or a non-finite h0_min, ADH_EMAXITER as above. */
int adh_md_drive_curve(const adh_material *m, double lambda, double h0_min, adh_model_curve *c);

#endif
