/* Closed forms the numerics are checked against. SI units throughout. */
#ifndef ADHERE_MODELS_H
#define ADHERE_MODELS_H

#include "adhere/params.h"

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
/* DMT: force at overlap (positive) delta: Hertz - 2 pi gamma R. */
double adh_dmt_force(const adh_material *m, double delta);
double adh_jkr_pulloff(const adh_material *m);
/* Width of the cohesive zone at the contact edge, from a Dugdale zone in the
 * JKR limit with the LJ law's maximum tension A/(9 sqrt(3) pi z0^3) and work
 * gamma: (pi/4) E* gamma / tension^2 = (243 pi^2/128) E z0^4 / A, about
 * 0.37 sqrt(R z0)/sigma. The grid must resolve it to follow the contact line. */
double adh_edge_zone(const adh_material *m);
double adh_dmt_pulloff(const adh_material *m);

#endif
