/* What an experimenter reads off a state: force (eq 13), central deformation
 * (eq 14), central gap, contact radius (gap < 1.1 z0), contact angle. */
#ifndef ADHERE_OBSERVE_H
#define ADHERE_OBSERVE_H

#include "adhere/grid.h"
#include "adhere/params.h"
#include "adhere/state.h"

#define ADH_CONTACT_FACTOR 1.1   /* in contact where h < 1.1 z0 (paper, Figure 8) */

typedef struct adh_obs {
    double h0;       /* drive position, m */
    double F;        /* total force, N; positive is repulsive (eq 13), tail included */
    double F_tail;   /* the part of F from beyond Rmax (adh_force_tail), N */
    double delta;    /* central deformation h(0) - h0 = -u(0), m (eq 14), at r = 0 */
    double hc;       /* central gap h(0) = h0 + delta, m, at r = 0 */
    double a;        /* contact radius, m; 0 out of contact */
    double angle;    /* exterior contact angle, rad; 0 out of contact */
    double F_rigid;  /* rigid-sphere force at h0 (eq 22), N; NAN for h0 <= 0 */
    double seconds;  /* wall time of the step */
    size_t iters;    /* relaxation iterations of the step */
    int branch;      /* +1 loading, -1 unloading */
    int path;        /* 0 loading, k for the k-th unloading branch */
    int converged;   /* 1 when the step met eps */
    int stable;      /* 1 stable under displacement control (static mode); 1 in relaxation */
    double t;        /* physical time, s (a viscoelastic run, adhere/visco.h); NAN otherwise */
    double base;     /* the instrument's base, m: h0 - F/k under a spring; h0 otherwise */
} adh_obs;

/* Fills the fields computed from the state (F, delta, hc, a, angle, F_rigid,
 * h0; t NAN and base = h0: no clock, no spring). */
void adh_observe(const adh_grid *g, const adh_material *m, const adh_state *s, adh_obs *o);

/* eq 13 over the grid plus the tail beyond Rmax (adh_force_tail). */
double adh_force(const adh_grid *g, const adh_material *m, const adh_state *s);
/* The LJ force from r > Rmax with the surfaces undeformed there: eq 22's
 * closed form at the edge gap h0 + Rmax^2/2R. */
double adh_force_tail(const adh_grid *g, const adh_material *m, double h0);
/* Radius where h first rises through 1.1 z0 going out from the centre,
 * linearly interpolated between nodes; 0 when no node is in contact. */
double adh_contact_radius(const adh_grid *g, const double *h, double z0);
/* Slope angle of h(r) in the near-linear region just outside the contact line
 * (where dh/dr has its first local maximum beyond a); 0 out of contact. */
double adh_contact_angle(const adh_grid *g, const double *h, double a);

#endif
