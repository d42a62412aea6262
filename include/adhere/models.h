/* Closed forms the numerics are checked against, and every derived
 * quantity of a material. SI units throughout. */
#ifndef ADHERE_MODELS_H
#define ADHERE_MODELS_H

#include <stddef.h>
#include "adhere/params.h"

typedef struct adh_derived {
    double gamma;   /* surface energy A/(16 pi z0^2), J/m^2 (eq 16) */
    double sigma;   /* gamma sqrt(R/z0^3)/E (eq 17) */
    double mu;      /* Tabor parameter 4^(1/3) sigma^(2/3) */
    double Estar;   /* Johnson's reduced modulus E/2 */
    double F_jkr;   /* JKR pull-off -(3/2) pi gamma R, N (eq 1) */
    double F_dmt;   /* DMT pull-off -2 pi gamma R, N (eq 2) */
    double h_star;  /* analytic jump separation (eq 24), m */
} adh_derived;

/* Every derived quantity of m at once: gamma, sigma, Tabor's mu, E*, the
 * JKR and DMT pull-offs and the jump separation. */
void adh_material_derive(const adh_material *m, adh_derived *d);

/* Rigid spheres, Derjaguin approximation (eq 22); NAN for h0 <= 0, where
 * rigid surfaces would overlap. */
double adh_rigid_force(const adh_material *m, double h0);
/* Precontact bulge delta(h) at central gap h (eq 23); negative. */
double adh_bulge(const adh_material *m, double h);
/* Drive position h0 = h - delta(h) that gives central gap h (eq 23 inverted). */
double adh_bulge_position(const adh_material *m, double h);
/* Jump-into-contact separation (eq 24). */
double adh_jump_separation(const adh_material *m);
/* Hertz force for indentation delta > 0: F = (2/3) E sqrt(R) delta^(3/2). */
double adh_hertz_force(const adh_material *m, double delta);
/* JKR: force and approach (overlap, positive = interpenetration) at contact radius a. */
void adh_jkr(const adh_material *m, double a, double *F, double *overlap);
/* JKR's contact radius at an overlap on its stable branch (past the fold,
 * where the overlap rises with a); 0 where the overlap is at or below the
 * fold's (JKR has no stable contact there); NAN for a NaN overlap,
 * INFINITY for an infinite one. */
double adh_jkr_radius(const adh_material *m, double overlap);
/* DMT: force at overlap (positive) delta: Hertz - 2 pi gamma R. */
double adh_dmt_force(const adh_material *m, double delta);
double adh_jkr_pulloff(const adh_material *m);
/* Width of the cohesive zone at the contact edge, from a Dugdale zone in the
 * JKR limit with the LJ law's maximum tension A/(9 sqrt(3) pi z0^3) and work
 * gamma: (pi/4) E* gamma / tension^2 = (243 pi^2/128) E z0^4 / A, about
 * 0.37 sqrt(R z0)/sigma. The grid must resolve it to follow the contact line. */
double adh_edge_zone(const adh_material *m);
double adh_dmt_pulloff(const adh_material *m);

/* A model's force against the drive position, to draw beside a computed
 * F(h0): h0 = z0 - overlap (the surfaces touch at z0, as in eq 22), over the
 * drive positions h0 >= h0_min (the deepest position of the figure), from the
 * deepest contact out to where a displacement-driven contact jumps apart (the
 * fold: the minimum overlap). Points 0 .. n_load-1 are stable under load
 * control and end at the load-controlled pull-off (the minimum force); that
 * point also begins the rest, n_load-1 .. n-1, which only displacement
 * control reaches (Figure 7's "break"). n_load = n when no point is past the
 * pull-off, 0 when h0_min stops the curve before it reaches the pull-off;
 * n = 0 when no part of the curve lies at h0 >= h0_min. */
#define ADH_MODEL_POINTS 240
typedef struct adh_model_curve {
    size_t n, n_load;
    double h0[ADH_MODEL_POINTS];   /* m, decreasing overlap: h0 rises along the curve */
    double F[ADH_MODEL_POINTS];    /* N */
} adh_model_curve;

/* JKR down to its fold at a_f = (pi gamma R^2 / (8 E*))^(1/3), where the
 * force is -(5/6) pi gamma R; its load-controlled pull-off is at 9^(1/3) a_f,
 * -(3/2) pi gamma R. ADH_SUCCESS, or ADH_EINVAL for a non-finite h0_min. */
int adh_jkr_drive_curve(const adh_material *m, double h0_min, adh_model_curve *c);
/* DMT from contact (overlap 0, h0 = z0, F = -2 pi gamma R) inwards: stable
 * throughout (n_load = n). ADH_SUCCESS, or ADH_EINVAL as above. */
int adh_dmt_drive_curve(const adh_material *m, double h0_min, adh_model_curve *c);

/* For the core's own model curves (JKR here, Maugis-Dugdale in maugis.c):
 * samples a model given as F(a), overlap(a) into an adh_model_curve. */
/* The model at contact radius a; ADH_SUCCESS or an error to pass on. */
typedef int (*adh_radius_model)(const adh_material *m, const void *ctx, double a, double *F,
                                 double *overlap);

/* Contact radii from the one where h0 = z0 - overlap comes down to h0_min
 * (found by bisection: the overlap must rise with a above a_fold) down to
 * a_fold, with a_pull (a_fold <= a_pull) sampled exactly: the pull-off that
 * ends the load-controlled part. */
int adh_model_sample(const adh_material *m, adh_radius_model fn, const void *ctx, double a_fold,
                     double a_pull, double h0_min, adh_model_curve *c);

#endif
