/* The solution at one drive position: deformation u, gap h, pressure p.
 * Snapshots are plain copies, so stepping back is restoring a copy. */
#ifndef ADHERE_STATE_H
#define ADHERE_STATE_H

#include <stddef.h>

#define ADH_STATE_FAR 8

typedef struct adh_state {
    size_t n;
    double h0;     /* drive position: closest approach of the undeformed surfaces, m */
    double *u;     /* total deformation u(r_n), m (eq 6); negative is flattening */
    double *h;     /* local gap h(r_n) = h0 + r^2/2R - u, m (eq 5) */
    double *p;     /* pressure p_s(h(r_n)), Pa (eq 10) */
    double mix;    /* the relaxation's mixing ratio: part of the dynamic
                      state, so a restored snapshot resumes exactly */
    double far[ADH_STATE_FAR]; /* the relaxation's deformation on the rings
                      its convergence measure adds beyond a grid short of
                      the paper's radius (adhere/relax.h); 0 otherwise */
} adh_state;

adh_state *adh_state_alloc(size_t n);
void adh_state_free(adh_state *s);
adh_state *adh_state_clone(const adh_state *s);
/* dst and src must have the same n. */
void adh_state_copy(adh_state *dst, const adh_state *src);
/* a and b trade their profiles (u, h, p; not h0, mix or far): each keeps
 * its address, and each block is still freed with one of them. a and b
 * must have the same n. */
void adh_state_swap_profiles(adh_state *a, adh_state *b);

#endif
