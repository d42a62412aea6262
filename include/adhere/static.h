/* The static limit (eps -> 0) the paper says could not be computed:
 * equilibrium at every drive position, G(u, h0) = u + (2/E) W p(h0 + r^2/2R - u) = 0,
 * solved by Newton's method and followed along the whole S-shaped curve
 * F(h0) by pseudo-arclength continuation in (u, h0) through its folds,
 * unstable parts included.
 *
 * The Jacobian is J = I - (2/E) W diag(p'(h)). p'(h) falls off as h^-4, so
 * only the nodes in and near the interaction zone (an index prefix S) enter
 * a dense LU (LAPACK dgetrf from OpenBLAS) of the bordered, truncated system;
 * that LU preconditions GMRES on the whole bordered system (every Newton
 * step is exact up to the GMRES tolerance; the part of J left out of the LU
 * is what GMRES corrects, a few iterations), and is reused from point to
 * point until GMRES needs more than a few iterations with it (on a
 * hierarchical kernel GMRES's products and the preconditioner's use the
 * kernel's own fast product). J has real eigenvalues (W times a symmetric
 * Hessian), det J changes sign at each fold, and a point is stable under
 * displacement control when det J > 0 (no negative eigen-direction; one
 * contact line gives at most one). By Cramer's rule det J = det B * t_h for
 * the tangent t bordered by the previous one, and det B keeps its sign
 * along the curve: det J's sign is that of t_h times det B's, and det B's
 * is checked wherever the LU is refreshed at a new point and at every fold.
 *
 * Step control: the arclength step adapts to the turn of the tangent
 * (max_angle), to Newton's progress, and to the largest change of a gap in
 * the interaction zone (max_gap_step), so that every node crossing the
 * law's barrier is resolved: at large sigma each crossing is a pair of
 * lattice-trapping folds. A step is rejected when Newton fails, the tangent
 * turns too far, the secant leaves the tangent, or det B (bordered by the
 * previous tangent) changes sign: the corrector then landed on a leg of the
 * curve that runs back. Fold pairs far smaller than a picometre in h0 (where
 * trapping fades out) may still be stepped over: their count depends on the
 * resolution, the jumps and pull-offs do not.
 *
 * Large grids (lattice_skip): on a resolved grid a lattice fold pair spans
 * well under a picometre to a few pm in h0, yet the exact curve needs
 * several points for each, so its cost is the number of fine rings times
 * that. There the curve is followed in steps of a contact measure Q (about
 * the area where the gap is near z0), which grows monotonically along the
 * whole curve: each step solves G = 0 with Q fixed (no tangent, no turn to
 * watch, no leg running back to land on), from the parabola through the
 * last three points, and its size follows Newton's effort. The folds of h0
 * and the force's minimum are placed on the parabola through three points,
 * so lattice folds a step spans are stepped over, and physical ones
 * (jump-in, jump-out) are found as on the exact curve (within 1e-3 in h0
 * and in pull-off, tests/unit/test_static_skip.c).
 *
 * Once a few rings are in contact the steps are whole rings of the contact
 * line (front steps): every point holds the same gap at its front ring, so
 * all see the lattice at one phase and the curve they sample is smooth; the
 * predictor moves the gap profiles out as a travelling front, and within a
 * few rings of the jump-out and the pull-off the steps in Q (every phase)
 * take over again, so that the lattice's extremes are found as before.
 *
 * Under a hierarchical kernel W is also held as a HODLR matrix
 * (adhere/hodlr.h) and the preconditioner is the whole Jacobian factorized
 * in O(N log^2 N), with no dense N x N copy; a dense kernel keeps the dense
 * LU over the active prefix (the oracle).
 *
 * The parts, each usable alone: flexible GMRES (adhere/fgmres.h), the
 * preconditioners (adhere/precond.h), the fold bookkeeping
 * (adhere/folds.h); the step strategies are src/core/static_*.c
 * (docs/static-solver.md).
 *
 * Use: alloc, set (solves the start point), then iterate until it returns
 * something other than ADH_CONTINUE; or a drive stepping adh_rule_static
 * (adhere/rule_static.h) for the rows of a protocol, adh_runner_static
 * (adhere/runner.h) for the whole curve. */
#ifndef ADHERE_STATIC_H
#define ADHERE_STATIC_H

#include <signal.h>
#include <stddef.h>
#include "adhere/folds.h"
#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/state.h"

typedef struct adh_static_settings {
    double tol;          /* Newton: max_n |u_n + (2/E)(W p)_n| < tol * z0 */
    double ds_init;      /* first arclength step, in units of z0 */
    double ds_min;       /* below this the continuation stalls (ADH_ESTALL) */
    double ds_max;       /* largest arclength step */
    double u_weight;     /* weight of every u_n against h0 in the arclength metric */
    double max_angle;    /* largest turn of the tangent per step, rad */
    double max_gap_step; /* largest change of any gap below 3 z0 per step, in z0
                            (resolves every node crossing: lattice folds); 0 = off */
    double active_tol;   /* node j enters the preconditioner's dense LU when
                            (2/E) |p'(h_j)| sum_n |W_nj| exceeds this */
    double h0_start;     /* first position, m; NAN = adh_protocol_auto_start(m, 0.05 nm) */
    double h0_end;       /* turning depth, m: the curve ends the first time it
                            comes down to it, so it must lie below the jump-in
                            for the whole S (the default -5 nm does) */
    size_t max_points;   /* cap on accepted points (ADH_EMAXITER beyond) */
    size_t max_newton;   /* Newton iterations per attempted step */
    int lattice_skip;    /* 0: the exact curve, every fold resolved (the
                            oracle). 1: steps in a contact measure Q (the
                            area where the gap is about z0, which only grows
                            along the curve) from a secant predictor, stepping
                            over the lattice folds a step spans; folds and
                            pull-off from the parabola through the last three
                            points; max_angle, max_gap_step and ds_max do not
                            apply. -1 (default): adh_static_skips, 1 where
                            the exact curve is estimated to cost more than
                            3x the steps, or past ADH_STATIC_EXACT_MAX_NODES
                            nodes */
    const volatile sig_atomic_t *cancel; /* polled before every Newton iteration:
                            nonzero stops with ADH_EINTR; NULL = never */
} adh_static_settings;

adh_static_settings adh_static_settings_default(void);
/* ADH_SUCCESS, or ADH_EINVAL with a sentence naming the bad value. */
int adh_static_settings_validate(const adh_static_settings *s, char *why, size_t whylen);

/* Above this many nodes (the paper's N) lattice_skip = -1 steps over
 * lattice folds: the exact curve traces the contact line across every fine
 * ring, several points a ring (74 CPU s at sigma = 15, 1219 rings). */
#define ADH_STATIC_EXACT_MAX_NODES 1000
/* The automatic choice between the exact curve and the steps, by their
 * cost in points (a point costs about the same on either path, on the
 * same grid and preconditioner). The exact curve resolves the contact
 * line's crossing of every fine ring up to the deepest turn: about
 * a/dr crossings (a the contact radius expected there,
 * adh_rings_contact_estimate), each ~1.3 points or fewer with at least 4
 * nodes across the edge zone l, ~3 below (there the line snaps ring by
 * ring, a lattice fold pair at most crossings). Measured, points per
 * crossing: 0.4 (sigma = 1, 17.6 nodes across l), 0.7 (2, 8.8), 1.0 (3,
 * 5.9), 1.3 (4, 4.4) on the paper's grid at turn -5 nm, 1.1 (3.75, 6.5
 * and 7); 3.1 (5, 3.5), 8.1 (7.5, 3.3), 4.4 (3.75, 3.3), 2.3 (2.25, 3.45).
 * The steps take ~ADH_STATIC_STEP_POINTS points (measured 85 to 154 from
 * sigma = 1 to 7.5) whatever the grid. The exact curve, the oracle, is
 * kept where it is estimated within 3x the steps' cost; past
 * ADH_STATIC_EXACT_MAX_NODES the steps always (docs/static-curve.md). A
 * grid coarser than the static limit (run by hand) keeps the exact curve:
 * the steps' accuracy was measured on resolved grids only. */
#define ADH_STATIC_STEP_POINTS 150
/* The exact curve's points as estimated above, for grid g, material m and
 * the curve's end (deepest position) h0_end. */
double adh_static_exact_points(const adh_grid *g, const adh_material *m, double h0_end);
/* 1 when lattice_skip = -1 steps over the lattice folds: the one rule of
 * every driver. */
int adh_static_skips(const adh_grid *g, const adh_material *m, double h0_end);

/* Up to this many folds are kept with their position and force. */
#define ADH_STATIC_MAX_FOLDS 4096

/* A fold: where the drive turns (adhere/folds.h). */
typedef adh_fold adh_static_fold;

typedef struct adh_static_result {
    double jump_in_h0;     /* first fold, where the outer branch ends; NAN if none */
    double jump_out_h0;    /* the retraction fold with the largest h0; NAN if none */
    double pulloff_F;      /* load-controlled pull-off: minimum force of the curve, N */
    double pulloff_h0;     /* where that minimum is, m */
    double pulloff_F_disp; /* force at the jump-out fold, N; NAN if none */
    size_t folds;          /* folds traversed (lattice-trapping folds included) */
    size_t points;         /* accepted points (rows) */
    size_t rejected;       /* rejected step attempts */
    size_t newton_iterations;
    size_t factorizations; /* dense LU factorizations */
    size_t krylov_iterations; /* GMRES iterations (one product with W each) */
    double seconds;        /* wall time of the solves */
} adh_static_result;

/* One accepted point of the curve. */
typedef struct adh_static_point {
    double s;            /* arclength from the start in the solver's metric, units of z0 */
    double tangent_h0;   /* d h0 / ds, dimensionless (|.| <= 1) */
    int direction;       /* +1 when h0 decreases along the curve here, -1 otherwise */
    int stable;          /* 1: det J > 0, stable under displacement control */
    size_t newton;       /* Newton iterations spent reaching it (rejected attempts too) */
    size_t active;       /* nodes in the preconditioner (its dense LU, or all N with HODLR) */
    double residual;     /* max_n |u_n + (2/E)(W p)_n|, m */
} adh_static_point;

typedef struct adh_static adh_static;

/* The grid and kernel are borrowed and must outlive the solver. Copies a
 * dense W (N^2 doubles) once, or assembles a hierarchical one as HODLR
 * (O(N log N)); material changes do not rebuild it. */
adh_static *adh_static_alloc(const adh_grid *g, const adh_kernel *k);
/* As adh_static_alloc, borrowing W's entries where another solver of the
 * same kernel holds them already, row-major and bit for bit those of
 * adh_kernel_entry (adhere/precond.h's adh_precond_alloc_shared): a dense
 * kernel is then not copied again. entries must outlive the solver; NULL:
 * adh_static_alloc. */
adh_static *adh_static_alloc_shared(const adh_grid *g, const adh_kernel *k, const double *entries);
void adh_static_free(adh_static *w);

/* Solves the start point (u = 0 as the first guess; where Newton fails
 * from there, the curve traced down to it from the automatic start) and
 * resets the curve. ADH_EINVAL on bad settings, ADH_EMAXITER / ADH_ENAN
 * (or the way's stop) when it fails, ADH_ENOMEM. */
int adh_static_set(adh_static *w, const adh_material *m, const adh_static_settings *s);

/* An extra undeformed gap e_n at every node, added to r^2/2R from the
 * next adh_static_set on (NULL: none; copied, kept until changed): the
 * curve of a sphere with a known extra deformation -e. A viscoelastic
 * sphere at one instant is elastic at its instantaneous modulus with its
 * delayed deformation frozen (adhere/visco.h lands its jumps into
 * contact so).
 * ADH_ENOMEM when the copy cannot be made. */
int adh_static_set_gap(adh_static *w, const double *e);

/* One equilibrium at h0 by the curve's corrector alone (Newton-Krylov
 * with its preconditioner, h0 held), for a caller whose every solve is a
 * new static problem (a viscoelastic time step, adhere/visco.h): the
 * compliance c = 2/E in place of the material's, the extra gap e (n;
 * NULL none) in place of adh_static_set_gap's, from the predictor v (n, u
 * at h0), to tol (in z0; 0: the settings'). Needs an adh_static_set first
 * (the material's other values, the settings); the problem stays changed
 * until the next adh_static_set, which also starts a curve afresh. The
 * answer (u, h, p, h0; borrowed until the next call) in *x (may be NULL).
 * ADH_SUCCESS, ADH_EINVAL for c <= 0 or tol < 0, or the corrector's
 * error (ADH_EMAXITER when it does not converge, ADH_ENAN). */
int adh_static_solve_at(adh_static *w, double c, const double *e, const double *v, double h0, double tol,
                        const adh_state **x);

/* Advances by one accepted point. ADH_CONTINUE: more to come; ADH_SUCCESS:
 * this point is the end (h0 = h0_end); otherwise an error (ADH_ESTALL when
 * the step fell below ds_min, ADH_EMAXITER past max_points, ADH_ENAN,
 * ADH_EGRID when the contact reaches 0.9 Rmax, ADH_EINTR when the cancel
 * flag was raised: the current point is then the last accepted one). */
int adh_static_iterate(adh_static *w);

/* The current point (borrowed; u, h, p, h0) and its continuation data. */
const adh_state *adh_static_state(const adh_static *w);
adh_static_point adh_static_current(const adh_static *w);
/* Why the curve stopped on an error (adh_static_set or _iterate): what
 * failed and where, in quantities; in *fix (may be NULL) the ADH_FIX_*
 * bits of what may get past it. "" otherwise (the grid's edge is the
 * caller's to word: adh_rings_edge_sentence). */
const char *adh_static_why(const adh_static *w, unsigned *fix);
/* The summary so far (folds, jumps, pull-off, counts). */
void adh_static_summary(const adh_static *w, adh_static_result *res);
/* The folds found so far: their number, and a borrowed array. */
size_t adh_static_folds(const adh_static *w, const adh_static_fold **folds);
/* From a start in contact, the point of least force on the curve past the
 * start (traced from the automatic start down to it: the unloading goes on
 * there, adh_static_set): its state (borrowed) and force in *F; NULL when
 * the start is out of contact, or that curve was not followed. */
const adh_state *adh_static_past_least(const adh_static *w, double *F);

#endif
