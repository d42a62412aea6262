/* The paper's relaxation solver (section B): after a drive step the
 * deformation is iterated from eq 11 with adaptive mixing until the change
 * falls below eps. The number of iterations is the model's time.
 *
 * Use: alloc, set (material, settings, start position), then per drive step
 * move + iterate until it returns something other than ADH_CONTINUE. */
#ifndef ADHERE_RELAX_H
#define ADHERE_RELAX_H

#include <signal.h>
#include <stddef.h>
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/state.h"

/* How each iteration's change is mixed in (adhere(1), "Mixing rules"). */
typedef enum adh_mix_rule {
    ADH_MIX_PAPER = 0,     /* the paper's: one adaptive ratio, lowered on
                              oscillation or growth of the central change */
    ADH_MIX_MOMENTUM = 1   /* heavy ball: ratio from the measured stiffness,
                              plus a fraction of the previous update */
} adh_mix_rule;

/* The largest iteration cap a step may have (adh_relax_settings_validate). */
#define ADH_RELAX_MAX_ITER_CAP 100000000
/* ADH_SUCCESS, or ADH_EINVAL with a sentence: the one check of the cap,
 * for adh_relax_settings_validate and every parser. */
int adh_relax_max_iter_check(long max_iter, char *why, size_t whylen);

typedef struct adh_relax_settings {
    adh_mix_rule rule;
    double momentum;     /* momentum rule: fraction of the previous update kept
                            up to the reference stiffness (adh_relax_scaled_momentum) */
    double eps;          /* convergence: the change's norm referred to the
                            paper's grid below this (adh_relax_measure), m */
    double rtol;         /* and the central change |u_new(0) - u_old(0)| at most
                            rtol (|u(0)| + |d|) + eps/1000: the step's shift has relaxed */
    double mix_max;      /* largest mixing ratio (paper: 0.2) */
    double mix_min;      /* the ratio never falls below this */
    double mix_down;     /* factor applied on oscillation or growth */
    double mix_up;       /* factor applied otherwise, up to mix_max */
    size_t max_iter;     /* cap per drive step (1 to ADH_RELAX_MAX_ITER_CAP); reaching it is reported */
    /* The caller's cancel flag, or NULL: polled before every iteration, and
     * nonzero stops the solver with ADH_EINTR (a signal handler may set it;
     * the core itself knows nothing of signals). */
    const volatile sig_atomic_t *cancel;
} adh_relax_settings;

adh_relax_settings adh_relax_settings_default(void);
/* "paper" or "momentum": ADH_SUCCESS, or ADH_EINVAL otherwise. */
int adh_mix_rule_parse(const char *name, adh_mix_rule *rule);
/* "paper" or "momentum B": the rule as reports name it. */
void adh_mix_rule_describe(const adh_relax_settings *s, char *buf, size_t len);
int adh_relax_settings_validate(const adh_relax_settings *s, char *why, size_t whylen);
/* What eps bounds. The paper's measure, [sum_n (u_new - u_old)^2]^(1/2) / N
 * with u_new eq 11's deformation before mixing (the residual), on its own
 * grid: uniform, N_ref = 1000 nodes of spacing D_ref (adh_grid_spacing_for
 * at 1000 nodes: 1.5 nm at R = 10 um, z0 = 0.5 nm), out to R_ref = N_ref
 * D_ref. There it is ||du|| / (N_ref sqrt(D_ref)), with ||du||^2 =
 * int_0^R_ref du^2 dr = sum_n w_n du_n^2 (w_n the ring widths): a norm that
 * converges as the grid is refined. Every grid measures that norm over
 * that radius, with that divisor:
 *     change = [sum_n w_n du_n^2 + sum_k w_k du_k^2]^(1/2) / (N_ref sqrt(D_ref)),
 * w_n clipped to r < R_ref, and k over rings beyond a grid short of R_ref
 * (adh_relax_far_rings). The radius must be the paper's because the change
 * out of contact does not fall off: a drive step shifts u by d everywhere,
 * and far out that shift relaxes as one flat mode, at the mixing's pace
 * like the contact line (at the end of a Figure 4 step du is 33 pm from
 * 0.3 to 1.5 um), so a norm over a larger radius ends every step later and
 * one over a smaller radius earlier. The rings beyond a short grid carry
 * what the paper's grid has there: no pressure, eq 11's deformation from
 * the grid's pressure, the drive's shift, and the same mixing. eps then
 * means the same drive on every grid, and on the paper's grid the
 * arithmetic is the paper's, digit for digit. */
#define ADH_RELAX_EPS_NODES 1000
#define ADH_RELAX_FAR_RINGS ADH_STATE_FAR /* 8: far_change sums them in 8 registers */
/* D_ref for material m, m. */
double adh_relax_eps_ref_spacing(const adh_material *m);
/* The measure's weights on grid g for material m: wt[n] (g->n of them) the
 * part of ring n inside R_ref over dr; returns sqrt(dr / D_ref). On the
 * paper's grid 1 and 1 exactly. */
double adh_relax_change_weights(const adh_grid *g, const adh_material *m, double *wt);
/* The rings the measure adds beyond grid g when it ends short of R_ref:
 * ADH_RELAX_FAR_RINGS of them, geometric from Rmax to R_ref, their
 * middles r[] and widths w[] (m); 0 when g reaches R_ref. */
size_t adh_relax_far_rings(const adh_grid *g, const adh_material *m, double *r, double *w);
/* The measure of a change du (length g->n) on grid g and du_far on its far
 * rings (as many as adh_relax_far_rings gives; unread when none); NAN out
 * of memory. */
double adh_relax_measure(const adh_grid *g, const adh_material *m, const double *du, const double *du_far);
/* The smallest eps the measure can reach in double precision when
 * deformations are up to `depth` (m): its rounding floor, 256 DBL_EPSILON
 * depth / sqrt(N_ref), the same on every grid (rounding per node does not
 * shrink with the spacing, and the measure spans R_ref). Below it every
 * step would run to the cap. */
double adh_relax_eps_floor(double depth);

/* The momentum rule's beta for the set one and a stiffness bound s: the
 * set beta up to s = ADH_RELAX_MOMENTUM_REF (the stiffest contact of the
 * paper's Figures 4, 7 and 8, where beta = 0.55 gives its 500-1000
 * iterations per step), and above it the beta that keeps the slow modes'
 * move per iteration, (1 + beta) / ((1 - beta) (1 + s)), at its value
 * there, up to ADH_RELAX_MOMENTUM_MAX (never below the set beta; 0 stays
 * 0). Within a step the beta in use never falls. */
#define ADH_RELAX_MOMENTUM_REF 2500.0
#define ADH_RELAX_MOMENTUM_MAX 0.97
double adh_relax_scaled_momentum(double beta, double stiffness);

typedef struct adh_relax adh_relax;

/* The grid and kernel are borrowed and must outlive the solver. */
adh_relax *adh_relax_alloc(const adh_grid *g, const adh_kernel *k);
void adh_relax_free(adh_relax *w);

/* Undeformed surfaces (u = 0) at position h0. Material may be changed later
 * with this call again without rebuilding anything. */
int adh_relax_set(adh_relax *w, const adh_material *m, const adh_relax_settings *s, double h0);

/* Step the drive to h0_new at constant gap: u shifts by h0_new - h0 (paper:
 * "the deformation was changed to u(r) - d"). Resets the step's iteration count. */
void adh_relax_move(adh_relax *w, double h0_new);

/* Up to max_batch iterations (0: until done). ADH_SUCCESS when converged,
 * ADH_CONTINUE when the batch ended first, ADH_EMAXITER at the cap,
 * ADH_ENAN when the solution stopped being finite, ADH_EINTR when the
 * settings' cancel flag was raised (the step is left unfinished). */
int adh_relax_iterate(adh_relax *w, size_t max_batch);

/* Exactly n more iterations at the current position, converged or not: a
 * pause (dwell) at the turning point. ADH_ENAN if the solution breaks,
 * ADH_EINTR if the cancel flag was raised first. */
int adh_relax_dwell(adh_relax *w, size_t n);

/* The current state (borrowed), and replacing it (for undo / restoring a turn). */
const adh_state *adh_relax_state(const adh_relax *w);
void adh_relax_restore(adh_relax *w, const adh_state *s);

size_t adh_relax_step_iterations(const adh_relax *w);   /* since the last move */
/* Why the last iteration failed (ADH_ENAN: where, after how many
 * iterations, and what was not finite or closed); "" when none has. */
const char *adh_relax_why(const adh_relax *w);
double adh_relax_change(const adh_relax *w);            /* last convergence measure, m */
double adh_relax_mixing(const adh_relax *w);            /* current mixing ratio */
double adh_relax_momentum(const adh_relax *w);          /* momentum rule: the beta in use */
double adh_relax_stiffness(const adh_relax *w);         /* momentum rule: the stiffness bound in use */

/* Recompute h and p from u at the current h0 (after restore or material change). */
void adh_relax_refresh(adh_relax *w);

#endif
