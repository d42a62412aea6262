/* The run plan: what a configuration asks to be simulated, worked out before
 * anything runs (`adhere --plan`). A scene names outputs; the plan derives
 * the least work that produces them: how many runs, which branches, about
 * how many drive steps, what is stored, and what is skipped and why. */
#ifndef ADH_SCENE_PLAN_H
#define ADH_SCENE_PLAN_H

#include <stdio.h>

#include "scene/config.h"

#define ADH_PLAN_MAX_NOTES 32
#define ADH_PLAN_MAX_RUNS 32      /* runs listed one by one; the totals count them all */
#define ADH_PLAN_MAX_KERNELS 64   /* distinct grids told apart (more are counted as new) */
#define ADH_PLAN_ROW_BYTES 800.0  /* a run's row of sweep.tsv, at most (about 550 measured) */

typedef struct adh_plan_note {
    char what[64];
    char why[256];
} adh_plan_note;

/* One independent run (a sweep has several). */
typedef struct adh_plan_run {
    double E, sigma;          /* the run's modulus and eq 17 */
    double start;             /* first drive position, m */
    double end;               /* last loading position, m: the deepest turn, or
                                 the estimated jump into contact (eq 24, eq 23) */
    double eps;
    size_t loading_steps;     /* rows of the loading branch (estimated when it
                                 ends at the jump into contact) */
    size_t unloading_steps;   /* upper bound over all unloading branches: each
                                 ends when the surfaces jump apart */
    double iterations;        /* relaxation iterations expected (adh_plan_iterations);
                                 in static and rigid mode the steps: a cost, not a count */
} adh_plan_run;

typedef struct adh_plan {
    size_t nruns;
    adh_plan_run runs[ADH_PLAN_MAX_RUNS];   /* the first runs */
    double iterations;        /* adh_plan_run's iterations summed over every run */
    size_t drives;            /* drives stepped: runs that differ only in their turn share one */
    int jobs;                 /* runs at once */
    int elastic;              /* 0: rigid spheres only (eq 22), no kernel at all */
    int static_mode;          /* the equilibrium continuation instead of relaxation */
    int time_mode;            /* physical time (mode time): the integrator's own steps */
    int time_path;            /* ... of an elastic material: no integration, the
                                 static curve's path (adhere/rule_path.h) */
    int shared_kernel;        /* one kernel serves every run (same grid) */
    size_t kernels;           /* kernels built in all: one for each distinct grid */
    size_t loading_branches;  /* per run */
    size_t unloading_branches;/* per run */
    size_t snapshots;         /* states kept at the turns, per run */
    int stop_at_contact;      /* loading ends at the jump into contact */
    size_t profiles_asked;    /* positions asked */
    size_t profiles_reached;  /* of them, positions some branch steps to */
    size_t profiles_stored;   /* profiles kept per run, an upper bound (a
                                 position may be passed on several branches) */
    int contact_speeds;       /* contact-line speeds (contact.png) asked */
    size_t loading_steps, unloading_steps;   /* totals over the runs (shared loading counted once) */
    double dwell_iterations;  /* relaxation iterations held at the turns, over every drive */
    int run_dirs;             /* run-K directories written */
    double bytes;             /* about how much the study writes, bytes */
    size_t nstored, nskipped;
    adh_plan_note stored[ADH_PLAN_MAX_NOTES];
    adh_plan_note skipped[ADH_PLAN_MAX_NOTES];
} adh_plan;

/* Works out the plan of cfg (assumed valid: cli_options_validate passed). */
void adh_plan_make(const adh_config *cfg, adh_plan *plan);

/* The steps plan p expects of a drive of rc (loading, and unloading to
 * the start at most). */
size_t adh_plan_steps(const adh_plan *p, const adh_run_spec *rc);

/* Prints it as "key: value" lines, one note per "stored:" / "skip:" line. */
void adh_plan_print(FILE *f, const adh_config *cfg, const adh_plan *plan);

/* The physical-time lines of the plan (plantime.c): the material, the
 * drive, the spring and the time the protocol spans. */
void adh_plan_time_print(FILE *f, const adh_config *cfg);

/* What a run in physical time is expected to take (plantime.c), in the
 * steps of the integrator that will run (adh_visco_rothe_applies, the
 * core's rule). The Rothe steps: the base 0.4 z0 a step out of contact; in
 * contact q's error's step, 0.055 edge zones at E0 (1 + 2y) (y of the
 * contact line's speed, no cap at Einf) over sqrt((1 - E0/Einf)/0.9), at
 * least the base 0.17 z0 a step
 * (rothe_steps, docs/viscoelastic.md). IDAS: about
 * one integrator step per TIME_EDGE_PER_STEP (0.068) edge zones the
 * contact line moves, the edge zone (adh_edge_zone) of an effective modulus
 * E0 (1 + 2y), y = sqrt(10 v tau / l(E0)), up to Einf (past Einf ~ 10 E0
 * the steps do not depend on Einf); the contact line's travel JKR's
 * radius at each turn at that modulus (in on loading, out on each
 * unloading), at least 60 steps a branch in contact; about 60 steps out
 * of contact a branch, 40 a dwell; 15 %
 * more for rejected steps and jumps; near the elastic limit, where the
 * instantaneous problem has a lattice fold at every ring, up to 3.5 times
 * the steps in contact (lattice, 1 + 2.5 / (1 + (Einf/E0 - 1)/0.15)).
 * Measured on resolved grids
 * (docs/viscoelastic.md): a grid that does not resolve the edge zone takes
 * more (2.3 times at 0.35 nodes across it). */
typedef struct adh_plan_time_cost {
    double steps;          /* integrator steps expected */
    double free_steps;     /* of them out of contact, before the 15 % */
    double contact_steps;  /* in contact, before the 15 % (lattice included) */
    double lattice;        /* the elastic limit's factor on them: 1 ... 3.5 */
    double E_ratio;        /* Einf / E0 */
    double a_turn;         /* contact radius at the deepest turn, m */
    double E_in, E_out;    /* effective moduli approaching, retracting, Pa */
    double step_in, step_out;  /* the contact line's travel a step, m */
    double spring;         /* the instrument's k, N/m; NAN: none (its steps are not counted) */
    int rothe;             /* 1: the Rothe steps' model (adh_visco_rothe_applies), 0: IDAS's */
    double work;           /* a step's work against IDAS's step price: 1 for IDAS, 1 + 4.5
                              times the contact line's mean move a step in Einf's edge
                              zones for the Rothe steps (their Newton and GMRES iterations) */
} adh_plan_time_cost;
void adh_plan_time_steps(const adh_run_spec *s, adh_plan_time_cost *c);
/* An elastic sphere in physical time integrates nothing: its cost is its
 * static curve's points on grid g (adh_static_skips' estimate: the exact
 * curve's, or ADH_STATIC_STEP_POINTS over the lattice folds), a point
 * priced about as an integrator step (the default scene: 3.7 against 2.3
 * ms); *exact (may be NULL): 1 for the exact curve. */
double adh_plan_path_points(const adh_run_spec *s, const adh_grid *g, int *exact);

/* Runs at once for a sweep: [sweep] jobs, else one per online core, never
 * more than the runs. */
int adh_plan_jobs(const adh_config *cfg);

/* The relaxation iterations a run of spec is expected to take, from the
 * measured dynamics: about 17 a step out of contact; in contact, at
 * eps = 1 pm, from 109 a step at sigma = 2.25 to 909 at 22.5 (Figures 1,
 * 4, 5, 6 and the bench's cycles), growing as eps^-0.72 for smaller eps
 * (Figure 7: 224 670, 370 010 and 1 185 902 iterations at 1, 0.5 and
 * 0.1 pm). The steps in contact are those below the jump into contact
 * (eq 24, eq 23) on loading, and from each turn up to JKR's fold on
 * unloading. Within a factor of two of a run's own count (tests); it
 * weighs a sweep's runs for its time left, and --plan's time follows. */
double adh_plan_iterations(const adh_run_spec *spec);

/* Runs done a few at a time (a sweep's jobs), each weighed by its expected
 * cost (the plan's iterations: a run at eps = 0.1 pm costs five of one at
 * 1 pm). */
typedef struct adh_plan_progress {
    double cost;       /* expected cost, any unit */
    int state;         /* 0 waiting, 1 under way, 2 done */
    double started;    /* when it started (clock seconds), states 1 and 2 */
    double seconds;    /* how long it took, state 2 */
} adh_plan_progress;

/* The time left until every run is done, jobs at a time: the pace (cost a
 * second, one job's) is that of the runs done so far, over their own
 * seconds, else pace when above 0, else unknown (NAN); a run under way has
 * the rest of its expected time to go (at least a tenth of it); waiting
 * runs take the first job to come free, in order. */
double adh_plan_time_left(const adh_plan_progress *runs, size_t n, int jobs, double now, double pace);

#endif
