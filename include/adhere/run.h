/* The record of a run, whatever filled it (the drive's relaxation, the
 * static continuation, rigid spheres): its rows, the turns with their
 * pull-offs and jump-outs, stored surface profiles and a summary. All that
 * writers and plots read. No I/O. */
#ifndef ADHERE_RUN_H
#define ADHERE_RUN_H

#include <stddef.h>
#include "adhere/observe.h"
#include "adhere/state.h"

#define ADH_MAX_TURNS 64
#define ADH_MAX_PROFILES 64

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
    double hysteresis;   /* physical time's, J: the base's net work over this turn's cycle (loading to it,
                            the dwell, unloading back to the start), as its step rule accounted it, the
                            deepest turn's its summary's; NAN until that cycle closes, and in the other
                            modes (their rows' area between the branches, adh_cycle_hysteresis) */
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
    char why[400];          /* when it stopped on an error: the step rule's (or the
                               drive's) sentence, what failed and where (h0, t, the
                               step size...); "" otherwise. Names quantities, never a
                               flag: a driver adds its words for fix. A run in time
                               whose energy balance is open (unconverged 1, status
                               ADH_SUCCESS) says that here */
    unsigned fix;           /* ADH_FIX_* bits (adhere/status.h) of what may get past
                               the stop; 0: nothing known to */
    int interrupted;        /* 1 when a callback or the cancel flag asked to stop */
} adh_run;

void adh_run_init(adh_run *run);
void adh_run_free(adh_run *run);
/* Appends a row (growing the array). ADH_SUCCESS or ADH_ENOMEM. */
int adh_run_push_row(adh_run *run, const adh_obs *row);
/* Stores a copy of state s as a profile of the given branch and path.
 * ADH_SUCCESS or ADH_ENOMEM. */
int adh_run_push_profile(adh_run *run, const adh_state *s, int branch, int path);
/* Moves from's turns and profiles into to (its own freed), leaving from
 * without profiles, and its start once it has rows: a curve rule's own
 * record handed to its drive's. */
void adh_run_take(adh_run *to, adh_run *from);
/* The last unloading branch's summary (the deepest turn), or NULL. */
const adh_turn_result *adh_run_main_turn(const adh_run *run);

/* Whether every unloading branch ended with the surfaces apart: 1, or 0
 * with a sentence in why (a branch that reached the start still in
 * contact, as a pinned contact line does on an unresolved grid). A run
 * without unloading branches is not asked to separate: 1. */
int adh_run_separated(const adh_run *run, char *why, size_t whylen);

/* Whether the surfaces came into contact (a row with a contact radius): 1,
 * or 0 with a sentence in why naming where the drive turned and that jump-in,
 * pull-off and jump-out are then not measured, with what to change (a turn
 * below h_star, eq 24's gap at the jump). An empty run is not asked: 1. */
int adh_run_touched(const adh_run *run, double h_star, char *why, size_t whylen);

/* The run a drive of turn t alone would have recorded, from src, whose
 * drive stepped several turns (one loading branch, an unloading branch
 * from each): its loading rows down to the turn, the turn's unloading
 * branch as path 1, the profiles on them (n values each, the grid's
 * nodes), the jump-in when it came before the turn, and its counts summed
 * over those rows. Status and interruption are the caller's to set. The
 * same numbers as the turn's own run when the drive stepped to the same
 * positions (shallower turns on the lattice start - k d), else within the
 * solver's tolerance. ADH_SUCCESS or ADH_ENOMEM (out then empty). */
int adh_run_turn(const adh_run *src, size_t t, size_t n, adh_run *out);

/* The row index that follows / precedes row i on the same path, or -1. */
long adh_run_next_on_path(const adh_run *run, size_t i);
long adh_run_prev_on_path(const adh_run *run, size_t i);

#endif
