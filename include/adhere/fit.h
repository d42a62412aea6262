/* Fitting the model to a measured force curve: the parameters that make
 * the model's force match measured forces at measured drive positions, in
 * the least-squares sense, by GSL's nonlinear least squares
 * (gsl_multifit_nlinear, Levenberg-Marquardt trust region).
 *
 * The residual of point i is  F_i - baseline - F_model(x_i - offset), the
 * model's branch chosen per point (adhere/fitmodel.h). The free parameters
 * are searched in scaled coordinates: log(p / start) for E, A, z0 and R
 * (positive, and a factor is what matters), offset / z0 and
 * baseline / |F_JKR| at the start; the physical-time model's solid as
 * log(tau / start) and log of Einf/E0 over its start (Einf >= E0 is the
 * search range's end, ratio 1). The Jacobian is forward differences of
 * the model for E, A, z0, R, Einf and tau (one model evaluation each; the
 * physical-time model's step at most ADH_FIT_MODEL_TIME_FD_STEP), and
 * exact for the offset (the branch's slope) and the baseline (-1). Einf's
 * standard error and correlations are Einf's own (its log is E's and the
 * ratio's together), not the ratio's.
 *
 *   adh_fit *f = adh_fit_alloc(g, k, &data, &settings);
 *   adh_fit_run(f, &result);      (progress per evaluation through a callback)
 *   adh_fit_free(f);
 *
 * No I/O. */
#ifndef ADHERE_FIT_H
#define ADHERE_FIT_H

#include <signal.h>
#include <stddef.h>
#include "adhere/fitmodel.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"

typedef enum adh_fit_param {
    ADH_FIT_E = 0, ADH_FIT_A, ADH_FIT_Z0, ADH_FIT_R, ADH_FIT_OFFSET, ADH_FIT_BASELINE,
    ADH_FIT_EINF, ADH_FIT_TAU,   /* the physical-time model's solid (adhere/visco.h); E is its E0 */
    ADH_FIT_NPARAM
} adh_fit_param;

/* "E", "A", "z0", "R", "offset", "baseline", "Einf", "tau". */
const char *adh_fit_param_name(adh_fit_param p);
/* The parameter a name (as above, case-insensitive; "E0" is E) means: 0,
 * or -1. */
int adh_fit_param_parse(const char *name, adh_fit_param *p);

/* Why a parameter's value cannot be trusted (result.flags[p]). */
enum {
    ADH_FIT_AT_LIMIT = 1,     /* it ran to the end of its search range */
    ADH_FIT_UNDETERMINED = 2, /* its standard error is above its value (or J is singular) */
    ADH_FIT_SLOW = 4          /* E0 and tau with tau beyond the data's time in contact
                                 (ADH_FIT_SLOW_RATIO): only the creep rate is determined */
};

/* The physical-time model with E0 and tau free: over a contact much
 * shorter than tau the solid creeps as 1/Einf + (1/E0 - 1/Einf) t/tau, and
 * a curve determines Einf and the rate (1/E0 - 1/Einf)/tau, not E0 and tau
 * apart. Measured (docs/fitting.md) on curves 3.9-4.7 s in contact: tau
 * 4 s recovered within 0.4 to 1.3 standard errors; at 10 s chi2 is flat
 * (within 3) from (E0, tau) = (1.00 GPa, 10.1 s) to (1.17 GPa, 7.6 s),
 * each reported with errors of 1-2 %. Both are flagged when tau exceeds this many times
 * the data's time in contact. */
#define ADH_FIT_SLOW_RATIO 1.0

typedef struct adh_fit_progress {
    size_t evals;            /* model evaluations so far */
    size_t iterations;       /* trust-region iterations so far */
    double value[ADH_FIT_NPARAM];   /* the point just evaluated */
    double chi2;             /* its sum of squared residuals, N^2; INFINITY when the model failed */
    double best_chi2;        /* the best so far */
    int jacobian;            /* 1: an evaluation for a finite difference */
} adh_fit_progress;

/* The fit stops when the trust region's next trial step would move every
 * free parameter by less than this fraction of its standard error (the
 * data cannot tell such points apart; further steps would chase the
 * model's own noise), or an accepted step moved each by less than xtol. */
#define ADH_FIT_STEP_SE 0.1

/* The physical-time model searches again from its best point, at most this
 * many times, until a search lowers chi2 by less than the data's noise^2
 * (adh_fit_run). The restarts are probes: each has its own max_iter, and
 * one that runs out leaves a converged fit converged. */
#define ADH_FIT_RESTARTS 3

typedef struct adh_fit_settings {
    unsigned free;                 /* mask of 1u << adh_fit_param */
    adh_material start;            /* start values (and the fixed ones) */
    double Einf, tau;              /* the physical-time model's start values (its E0 is start.E) */
    double offset, baseline;       /* start values, m and N */
    adh_fit_model_settings model;  /* which model, its solver settings */
    size_t max_iter;               /* trust-region iterations a search (default 50; each restart has its own) */
    double xtol;                   /* stop when a step changes every scaled parameter by less (1e-4) */
    double fd_step;                /* forward-difference step in log(p) (default 1e-2: the model's own noise, the lattice's, must stay small beside the change) */
    double range;                  /* a factor: E, A, z0, R are searched within start / range
                                      .. start * range, clipped to the model's limits (default 100) */
    const volatile sig_atomic_t *cancel;   /* raised: stop with the best so far (ADH_EINTR) */
    /* called after every model evaluation; nonzero stops as cancel does */
    int (*progress)(const adh_fit_progress *p, void *ctx);
    void *ctx;
} adh_fit_settings;

adh_fit_settings adh_fit_settings_default(void);

typedef struct adh_fit_result {
    int status;              /* ADH_SUCCESS; ADH_EINTR (partial: the best so far);
                                ADH_EMAXITER; or the model's error at the start */
    unsigned free;
    double value[ADH_FIT_NPARAM];   /* best values (SI: Pa, J, m, m, m, N, Pa, s) */
    double se[ADH_FIT_NPARAM];      /* standard errors (NAN for fixed ones) */
    double corr[ADH_FIT_NPARAM][ADH_FIT_NPARAM];   /* correlations among the free ones */
    unsigned flags[ADH_FIT_NPARAM]; /* ADH_FIT_AT_LIMIT, ADH_FIT_UNDETERMINED */
    adh_material best;       /* the best material */
    double start, turn;      /* the physical-time model's drive at the best point, as its evaluation
                                runs it (adh_fit_model_drive): where it starts and turns, m; NAN
                                for the other models */
    double creep_rate;       /* the physical-time model's (1/E0 - 1/Einf)/tau at the best point,
                                1/(Pa s): what a curve much shorter than tau determines
                                (ADH_FIT_SLOW); NAN for the other models */
    double contact_time;     /* the physical-time model's: the data's time in contact, s
                                (positions in contact over the drive's speeds, and the
                                dwell); NAN for the other models */
    size_t n, nfree;         /* points, free parameters */
    double chi2;             /* sum of squared residuals, N^2 */
    double rms;              /* sqrt(chi2 / n), N */
    double noise;            /* the data's own scatter (adh_fit_noise), N */
    double chi2_red;         /* chi2 / (noise^2 (n - nfree)): about 1 when the model fits */
    size_t evals, failed;    /* model evaluations, and those that failed */
    int model_status;        /* the last failed evaluation's status (ADH_SUCCESS: none failed) */
    char model_why[400];     /* and why it failed, as a run's adh_run.why says it; "" */
    unsigned model_fix;      /* its ADH_FIX_* bits */
    size_t iterations;
    double seconds;
    int gsl_info;            /* why the search that found the best point stopped: 1 small step
                                (xtol), 2 small gradient, 3 no step lowers chi2, 4 the next step
                                below ADH_FIT_STEP_SE; 0 it ran out of iterations */
} adh_fit_result;

typedef struct adh_fit adh_fit;

/* The grid, kernel and data are borrowed and must outlive the fit. NULL
 * with ADH_EINVAL (no free parameter, fewer points than free parameters)
 * or ADH_ENOMEM in *status. */
adh_fit *adh_fit_alloc(const adh_grid *g, const adh_kernel *k, const adh_fit_data *d, const adh_fit_settings *s,
                       int *status);
void adh_fit_free(adh_fit *f);

/* Runs the fit. res is filled whatever the status (the best point found). */
int adh_fit_run(adh_fit *f, adh_fit_result *res);

/* The model's whole curve at the best point (one more evaluation; in the
 * model's coordinates, without offset and baseline): its length, 0 when it
 * fails; the arrays are borrowed until the next evaluation. */
size_t adh_fit_best_curve(adh_fit *f, const double **h0, const double **F, const int **stable);

/* The residuals of the best point (n of them, N), and its model forces. */
const double *adh_fit_residuals(const adh_fit *f);
const double *adh_fit_model_forces(const adh_fit *f);

/* The data's own scatter, N: per segment the second differences of the
 * force at neighbouring points (the jump's left out), 1.4826 median |d2| /
 * sqrt(6), a robust standard deviation of independent noise on a curve
 * smooth at the points' spacing; at least the rounding's q / sqrt(12), q
 * the smallest step between neighbouring forces. NAN for fewer than 5
 * points. */
double adh_fit_noise(const adh_fit_data *d);

#endif
