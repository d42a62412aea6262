/* The model a fit holds against measured points (adhere/fit.h): the force
 * at each point's drive position, from the branch that point is on.
 *
 * The static model (default) follows the equilibrium curve (adhere/static.h)
 * from above the highest point down past the deepest: its outer branch runs
 * from the start to the first fold (the jump-in), its contact branch from
 * the fold with the largest h0 after it (the jump-out) to the end, with the
 * lattice folds' few picometres of back-and-forth left out (only points
 * below every earlier one are kept). Which of the two a point is compared
 * with is the data's own word: a point past the data's jump (contact = 1)
 * against the contact branch, the others against the outer branch. So the
 * residuals are continuous in the parameters (a model jump moving past a
 * point does not switch its branch); a point where its branch does not
 * reach (past the model's fold) takes the branch's end value, and the
 * misfit grows with the distance to it.
 *
 * The relaxation model (on request) runs the paper's protocol with one turn
 * below the deepest point: approach points against its loading branch,
 * retract points against its unloading branch, as the drive ran them.
 *
 * The physical-time model (on request) runs the same protocol through the
 * viscoelastic rule (adhere/rule_visco.h: a standard linear solid at the
 * drive's speeds, through its spring), turned at the data's deepest point
 * (the time spent in contact is the model's: a turn a step deeper would
 * add to it): approach points against its loading branch, retract points
 * against its unloading branch, both in the base's position (the drive's:
 * h0 - F/k under a spring, h0 without one).
 *
 * Between the curve's points a monotone cubic (GSL's Steffen interpolation)
 * gives the force and its slope. The solver is allocated once and reused by
 * every evaluation (a dense copy of the kernel, or its HODLR form); each
 * evaluation traces the whole curve for its material. No I/O. */
#ifndef ADHERE_FITMODEL_H
#define ADHERE_FITMODEL_H

#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/relax.h"
#include "adhere/static.h"
#include "adhere/visco.h"

/* Measured points, in the model's units and sign (x: drive position, m,
 * larger further apart; F: N, positive repulsive). */
typedef struct adh_fit_data {
    size_t n;
    const double *x;
    const double *F;
    const int *dir;        /* +1 approach (x falls), -1 retract */
    const int *contact;    /* 1: past the segment's jump (in contact), 0: before it */
    const int *seg;        /* the segment of each point */
} adh_fit_data;

typedef enum adh_fit_model_kind {
    ADH_FIT_MODEL_STATIC = 0, ADH_FIT_MODEL_RELAX = 1, ADH_FIT_MODEL_TIME = 2
} adh_fit_model_kind;

typedef struct adh_fit_model_settings {
    adh_fit_model_kind kind;
    adh_static_settings statics;   /* h0_start and h0_end are set per evaluation */
    adh_relax_settings relax;      /* the relaxation model's */
    adh_visco_rule_settings visco; /* the physical-time model's: the drive and the integrator
                                      (the solid is set per evaluation) */
    double step;                   /* drive step of the relaxation, and the start's rounding, m */
    double margin;                 /* the curve runs this far past the data's ends, m */
} adh_fit_model_settings;

adh_fit_model_settings adh_fit_model_settings_default(void);

typedef struct adh_fit_model adh_fit_model;

/* A trial far from the start can cost far more than the start (a large
 * sigma on a grid chosen for a small one: every lattice fold resolved). Its
 * curve is capped at this many times the first evaluation's points, and
 * refused past them (ADH_EMAXITER): the fit steps back. */
#define ADH_FIT_MODEL_POINTS_FACTOR 8

/* The physical-time model's integrator tolerance, at most (a run's is
 * 5e-5): the fit's forward differences must stand above the model's
 * own noise. Measured at tau 10 s on a curve of 4.7 s in contact
 * (docs/fitting.md): at 5e-5 the differences of E0 and tau over a step
 * 10 times shorter were as large as over 1 % (noise, 0.06 nN against
 * 0.08), at 1e-5 a tenth of them (0.008 and 0.005 nN), for 1.2 times
 * the CPU time an evaluation. */
#define ADH_FIT_MODEL_TIME_TOL 1e-5
/* The tolerance the physical-time model integrates to when the setting
 * is tol: tol, or ADH_FIT_MODEL_TIME_TOL where tol is looser (the one rule
 * for the model, its best.scene and the refusal of a setting it drops). */
double adh_fit_model_time_tol(double tol);

/* The physical-time model's forward-difference step in log(p), at most
 * (adh_fit_settings.fd_step's 1e-2 otherwise): its rows land on the data's
 * positions, so chi2 is smooth below 1 %, and over 12 seeded curves at
 * tau = 1 s (docs/fitting.md) 1 % differences left the standard errors too
 * small by about 2 (rms z 1.9-2.2), 0.1 % by 1.2-1.5; 0.01 % met the
 * model's own noise (1.3-1.6). */
#define ADH_FIT_MODEL_TIME_FD_STEP 1e-3

/* g and k are borrowed. NULL when out of memory. */
adh_fit_model *adh_fit_model_alloc(const adh_grid *g, const adh_kernel *k, const adh_fit_model_settings *s);
void adh_fit_model_free(adh_fit_model *fm);

/* The model's force at every point's position x_i - offset (F, N) and its
 * slope dF/dh0 there (slope, N/m; may be NULL). ADH_SUCCESS, ADH_EINTR
 * (the settings' cancel flag), or the solver's error (ADH_ESTALL,
 * ADH_EGRID, ...: no value then). */
int adh_fit_model_eval(adh_fit_model *fm, const adh_material *m, double offset, const adh_fit_data *d, double *F,
                       double *slope);

/* The same for the physical-time model, with the solid (its E0 is m->E)
 * and the baseline: under a spring the model's turn is the sphere's
 * position at the data's deepest point, x - offset + (F - baseline) / k. */
int adh_fit_model_eval_sls(adh_fit_model *fm, const adh_material *m, const adh_sls *sls, double offset,
                           double baseline, const adh_fit_data *d, double *F, double *slope);

/* The physical-time model's drive for material m at offset and baseline,
 * as its evaluation runs it: *start, m, fixed at the model's first
 * evaluation (the automatic start there, or above the data's highest
 * point), or further out where m's own automatic start is; *turn, m, the
 * data's deepest position in the model's coordinates (the sphere's there
 * under a spring: x - offset + (F - baseline) / k). 0; -1 with both NAN
 * for the other models (each curve starts at its own) or before the first
 * evaluation. */
int adh_fit_model_drive(const adh_fit_model *fm, const adh_material *m, double offset, double baseline,
                        const adh_fit_data *d, double *start, double *turn);

/* Why the last evaluation failed, as a run's adh_run.why says it (what
 * stopped the curve, where), and in *fix (may be NULL) its ADH_FIX_* bits;
 * "" when it succeeded or nothing more than its status is known. */
const char *adh_fit_model_why(const adh_fit_model *fm, unsigned *fix);

/* The branches of the last successful evaluation, ascending in h0: 0 the
 * outer (static) or loading (relaxation) branch, 1 the contact or
 * unloading branch. Their length; *h0 and *F borrowed. */
size_t adh_fit_model_branch(const adh_fit_model *fm, int which, const double **h0, const double **F);

/* The last evaluation's curve (every point, in the order solved; borrowed;
 * the physical-time model's in the base's position, as its points are
 * compared). */
size_t adh_fit_model_curve(const adh_fit_model *fm, const double **h0, const double **F, const int **stable);

#endif
