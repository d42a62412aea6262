/* The loading/unloading protocol of the paper (section B), run as a sequence
 * of drive steps: load from a start where the force is negligible down to the
 * deepest turning point (snapshotting the state at every turn on the way),
 * then for every turn restore its snapshot, optionally dwell, and unload
 * until the surfaces jump apart. One loading branch serves every turn. */
#ifndef ADHERE_PROTOCOL_H
#define ADHERE_PROTOCOL_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/params.h"
#include "adhere/run.h"

/* The longest dwell at a turn, in iterations (adh_protocol_check). */
#define ADH_PROTOCOL_MAX_DWELL 100000000
/* ADH_SUCCESS, or ADH_EINVAL with a sentence: the one check of a dwell,
 * for the run's check and every parser. */
int adh_protocol_dwell_check(long dwell, char *why, size_t whylen);

typedef struct adh_protocol_settings {
    double start;                 /* first position, m; NAN = automatic */
    double step;                  /* drive step d > 0, m */
    size_t nturns;                /* 0: load until contact, no unloading */
    double turns[ADH_MAX_TURNS];  /* turning points, m (any order) */
    int unload;                   /* 1: unload from every turn */
    size_t dwell;                 /* iterations held at a turn before unloading (up to ADH_PROTOCOL_MAX_DWELL) */
    size_t nprofiles;             /* positions where h, u, p are stored */
    double profiles[ADH_MAX_PROFILES];
} adh_protocol_settings;

adh_protocol_settings adh_protocol_settings_default(void);

/* The lowest of the turns, m; INFINITY when there is none. */
double adh_protocol_deepest_turn(const adh_protocol_settings *ps);

/* The automatic start: where the bulge (eq 23) is below 1 % of z0 and at
 * least 4 jump separations (eq 24) out, rounded up to a whole number of steps. */
double adh_protocol_auto_start(const adh_material *m, double step);

/* How far the drive may go either side of contact: |h0| up to R/50 (the
 * model needs h0 << R). Every start, turn and position meets this one limit. */
double adh_protocol_reach(const adh_material *m);

/* Checks the settings and that the grid can hold the run: the pressure at
 * Rmax negligible and the contact expected well inside Rmax at the deepest
 * turn. ADH_EINVAL / ADH_EGRID with a sentence in why, and in *fix (may be
 * NULL) the ADH_FIX_* bits of what it asks to change (adhere/status.h).
 * g may be NULL (rigid spheres, no elastic solve): then only the drive
 * settings are checked. */
int adh_protocol_check(const adh_protocol_settings *ps, const adh_material *m, const adh_grid *g, char *why,
                       size_t whylen, unsigned *fix);

#endif
