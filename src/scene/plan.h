/* The run plan: what a configuration asks to be simulated, worked out before
 * anything runs (`adhere --plan`). A scene names outputs; the plan derives
 * the least work that produces them: how many runs, which branches, about
 * how many drive steps, what is stored, and what is skipped and why. */
#ifndef ADH_SCENE_PLAN_H
#define ADH_SCENE_PLAN_H

#include <stdio.h>

#include "scene/config.h"

#define ADH_PLAN_MAX_NOTES 32

typedef struct adh_plan_note {
    char what[64];
    char why[256];
} adh_plan_note;

/* One independent run (a sweep has several). */
typedef struct adh_plan_run {
    double value;             /* the swept value (NAN without a sweep) */
    double E, sigma;          /* the run's modulus and eq 17 */
    double start;             /* first drive position, m */
    double end;               /* last loading position, m: the deepest turn, or
                                 the estimated jump into contact (eq 24, eq 23) */
    double eps;
    size_t loading_steps;     /* rows of the loading branch (estimated when it
                                 ends at the jump into contact) */
    size_t unloading_steps;   /* upper bound over all unloading branches: each
                                 ends when the surfaces jump apart */
} adh_plan_run;

typedef struct adh_plan {
    size_t nruns;
    adh_plan_run runs[ADH_MAX_SWEEP];
    int jobs;                 /* runs at once */
    int elastic;              /* 0: rigid spheres only (eq 22), no kernel at all */
    int static_mode;          /* the equilibrium continuation instead of relaxation */
    int shared_kernel;        /* one kernel serves every run (same grid) */
    size_t kernels;           /* kernels built in all */
    size_t loading_branches;  /* per run */
    size_t unloading_branches;/* per run */
    size_t snapshots;         /* states kept at the turns, per run */
    int stop_at_contact;      /* loading ends at the jump into contact */
    size_t profiles_asked;    /* positions asked */
    size_t profiles_reached;  /* of them, positions some branch steps to */
    size_t profiles_stored;   /* profiles kept per run, an upper bound (a
                                 position may be passed on several branches) */
    int contact_speeds;       /* contact-line speeds (contact.png) asked */
    size_t loading_steps, unloading_steps;   /* totals over the runs */
    size_t nstored, nskipped;
    adh_plan_note stored[ADH_PLAN_MAX_NOTES];
    adh_plan_note skipped[ADH_PLAN_MAX_NOTES];
} adh_plan;

/* Works out the plan of cfg (assumed valid: cli_options_validate passed). */
void adh_plan_make(const adh_config *cfg, adh_plan *plan);

/* Prints it as "key: value" lines, one note per "stored:" / "skip:" line. */
void adh_plan_print(FILE *f, const adh_config *cfg, const adh_plan *plan);

/* Runs at once for a sweep: [sweep] jobs, else one per online core, never
 * more than the runs. */
int adh_plan_jobs(const adh_config *cfg);

#endif
