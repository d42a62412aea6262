/* The loading/unloading protocol of the paper (section B), run as a sequence
 * of drive steps: load from a start where the force is negligible down to the
 * deepest turning point (snapshotting the state at every turn on the way),
 * then for every turn restore its snapshot, optionally dwell, and unload
 * until the surfaces jump apart. One loading branch serves every turn. */
#ifndef ADHERE_PROTOCOL_H
#define ADHERE_PROTOCOL_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/observe.h"
#include "adhere/params.h"
#include "adhere/relax.h"

#define ADH_MAX_TURNS 64
#define ADH_MAX_PROFILES 64

typedef struct adh_protocol_settings {
    double start;                 /* first position, m; NAN = automatic */
    double step;                  /* drive step d > 0, m */
    size_t nturns;                /* 0: load until contact, no unloading */
    double turns[ADH_MAX_TURNS];  /* turning points, m (any order) */
    int unload;                   /* 1: unload from every turn */
    size_t dwell;                 /* iterations held at a turn before unloading */
    size_t nprofiles;             /* positions where h, u, p are stored */
    double profiles[ADH_MAX_PROFILES];
} adh_protocol_settings;

adh_protocol_settings adh_protocol_settings_default(void);

/* The automatic start: where the bulge (eq 23) is below 1 % of z0 and at
 * least 4 jump separations (eq 24) out, rounded up to a whole number of steps. */
double adh_protocol_auto_start(const adh_material *m, double step);

/* How far the drive may go either side of contact: |h0| up to R/50 (the
 * model needs h0 << R). Every start, turn and position meets this one limit. */
double adh_protocol_reach(const adh_material *m);

/* Checks the settings and that the grid can hold the run: the pressure at
 * Rmax negligible and the contact expected well inside Rmax at the deepest
 * turn. ADH_EINVAL / ADH_EGRID with a sentence in why. g may be NULL (rigid
 * spheres, no elastic solve): then only the drive settings are checked. */
int adh_protocol_check(const adh_protocol_settings *ps, const adh_material *m,
                       const adh_grid *g, char *why, size_t whylen);

typedef struct adh_profile {
    double h0;
    int branch, path;
    double *u, *h, *p;            /* length N each */
} adh_profile;

typedef struct adh_turn_result {
    double h0;           /* the turning point */
    double max_load;     /* force at the turn, N */
    double a_turn;       /* contact radius at the turn, m */
    double pulloff_F;    /* most negative force on its unloading branch, N */
    double pulloff_h0;   /* where that minimum is */
    double jump_out_h0;  /* first position out of contact on unloading; NAN if none */
    int path;            /* its path number in the rows */
} adh_turn_result;

typedef struct adh_run {
    adh_obs *rows;  size_t nrows, rows_cap;
    adh_profile *profiles; size_t nprofiles, profiles_cap;
    adh_turn_result turns[ADH_MAX_TURNS]; size_t nturns;
    double jump_in_h0;      /* first loading position in contact; NAN if none */
    double start;           /* the start actually used */
    size_t iterations;      /* total relaxation iterations */
    double seconds;         /* total wall time of the solves */
    size_t unconverged;     /* steps that hit the iteration cap */
    int status;             /* ADH_SUCCESS or the error that stopped the run */
    int interrupted;        /* 1 when a callback or the cancel flag asked to stop */
} adh_run;

void adh_run_init(adh_run *run);
void adh_run_free(adh_run *run);
/* Appends a row (growing the array). ADH_SUCCESS or ADH_ENOMEM. */
int adh_run_push_row(adh_run *run, const adh_obs *row);
/* The last unloading branch's summary (the deepest turn), or NULL. */
const adh_turn_result *adh_run_main_turn(const adh_run *run);

/* Whether every unloading branch ended with the surfaces apart: 1, or 0
 * with a sentence in why (a branch that reached the start still in
 * contact, as a pinned contact line does on an unresolved grid). A run
 * without unloading branches is not asked to separate: 1. */
int adh_run_separated(const adh_run *run, char *why, size_t whylen);

/* Called after every drive step with the row just added; return nonzero to stop. */
typedef int (*adh_step_cb)(const adh_obs *row, const adh_run *run, void *ctx);

/* Runs the whole protocol. Returns ADH_SUCCESS, or the first error (the run
 * keeps every row computed so far, run->status says why it stopped). A
 * raised rs->cancel flag or a callback asking to stop ends it with
 * ADH_SUCCESS and run->interrupted = 1; the step under way is dropped. */
int adh_protocol_run(const adh_grid *g, const adh_kernel *k, const adh_material *m,
                     const adh_relax_settings *rs, const adh_protocol_settings *ps,
                     adh_step_cb cb, void *ctx, adh_run *run);

/* The area between the loading and unloading force curves over the positions
 * both visit (N m): the energy one cycle dissipates. 0 without unloading. */
double adh_hysteresis_area(const adh_run *run, double step);
/* The same for a static curve (one path, stable flags): the area between the
 * highest and lowest stable force at each h0, sampled every step. */
double adh_static_hysteresis_area(const adh_run *curve, double step);

#endif
