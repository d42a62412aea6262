/* Physical time: a standard linear solid driven at a real speed, through an
 * instrument's spring.
 *
 * The material. With the creep compliance
 *     J(t) = 1/Einf + (1/E0 - 1/Einf)(1 - exp(-t/tau))
 * (E0 relaxed, Einf instantaneous, both in adh_material's combined-modulus
 * convention) the surface deformation is
 *     u = -W [cinf p + cdel q],   tau dq/dt = p - q,
 * cinf = 2/Einf, cdel = 2(1/E0 - 1/Einf), W the kernel (adhere/kernel.h;
 * elastic spheres are u = -(2/E) W p) and q the pressure low-passed over
 * tau. At each instant the sphere is elastic at Einf with the extra,
 * known, deformation -cdel W q.
 *
 * The drive. The instrument's base moves at a speed in m/s (one for each
 * branch), holds at each turn for a dwell in seconds, and pulls the sphere
 * through a spring of stiffness k: h0 = base + F/k (F > 0 repulsive;
 * k = INFINITY is the paper's displacement control, h0 = base). There is
 * no inertia: the sphere's position follows quasi-statically.
 *
 * The integration (settings.integrator). Under displacement control, by
 * default, Rothe steps: each time step the static problem at an effective
 * compliance with a known extra gap (q's equation integrated exactly over
 * the step), solved by the static solver's corrector, the step held by
 * q's local error; a fold where no step converges, landed by the static
 * curve (in), Newton from apart (out) or the IDAS path below from the last
 * step. Through a spring (or asked for), IDAS: the state (u, q, t[, h0]) is a differential-algebraic
 * system solved by SUNDIALS' IDAS (variable-order BDF with error control)
 * along an arclength s of the path in (u, base speed x t): the residual
 *     u + W (cinf p + cdel q) = 0
 *     tau q' - (p - q) t' = 0
 *     theta |u'|^2 [+ h0'^2] + (v t')^2 = z0^2   (' = d/ds, theta = 1/N)
 *    [h0 - base(t) - F/k = 0]
 * Its Newton systems, with q eliminated (its block is diagonal), are the
 * elastic Jacobian I - c W diag(p'(h)) at an effective compliance between
 * cinf and cinf + cdel, bordered: preconditioned as the static mode's
 * (a dense LU over the active nodes, or the whole Jacobian as a HODLR
 * matrix under a hierarchical kernel). Along s the path goes smoothly
 * through a fold of the instantaneous problem, where t turns back
 * (t' = 0): that root of t' is where the sphere jumps (under a spring, its
 * instability). The jump itself is fast against tau: it relaxes at frozen
 * time, base and q, overdamped (u' = -G(u) in a pseudo-time, by the same
 * integrator and preconditioner), from the fold nudged along the path to
 * the stable state it lands on. Energies are integrated alongside (IDAS
 * quadratures): the drive's work, the viscous dissipation
 *     D = (cdel / tau) <p - q, W (p - q)>
 * (<a, b> = sum_n 2 pi w_n a_n b_n, w_n the ring weights), and the stored
 * energy is
 *     U = cinf/2 <p, W p> + cdel/2 <q, W q> + sum_n 2 pi w_n w(h_n)
 *         + U_tail(h0) + F^2 / 2k
 * so that work = dU + dissipation + the energy each jump releases.
 *
 * Use: alloc, set (solves the start), iterate until it returns something
 * other than ADH_CONTINUE (one row a call); or adh_visco_run. No I/O. */
#ifndef ADHERE_VISCO_H
#define ADHERE_VISCO_H

#include <signal.h>
#include <stddef.h>

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "adhere/protocol.h"
#include "adhere/run.h"
#include "adhere/state.h"

/* A standard linear solid. */
typedef struct adh_sls {
    double E0;    /* relaxed (long-time) modulus, Pa, combined as adh_material's E */
    double Einf;  /* instantaneous modulus, Pa, at least E0 */
    double tau;   /* relaxation time of the creep form, s */
} adh_sls;

/* ADH_SUCCESS, or ADH_EINVAL with a sentence naming the value and what is
 * allowed: E0 and Einf from 1 kPa to 1 TPa, Einf >= E0, tau above 0 and at
 * most 1e6 s. */
int adh_sls_validate(const adh_sls *v, char *why, size_t whylen);

/* The instrument. */
typedef struct adh_visco_drive {
    double speed_in;   /* base speed while approaching, m/s */
    double speed_out;  /* while retracting, m/s */
    double dwell;      /* held at each turn, s */
    double spring;     /* stiffness k, N/m; INFINITY: displacement control */
} adh_visco_drive;

/* 1 um/s both ways, no dwell, no spring. */
adh_visco_drive adh_visco_drive_default(void);
/* The instrument springs a drive may hold, N/m: from the softest AFM
 * cantilevers to a stiff surface-force apparatus (INFINITY beyond). */
#define ADH_SPRING_MIN 1e-3
#define ADH_SPRING_MAX 1e4
/* ADH_SUCCESS, or ADH_EINVAL with a sentence: speeds above 0 and at most
 * 1 m/s, dwell from 0 to 1e6 s, k from ADH_SPRING_MIN to ADH_SPRING_MAX
 * (INFINITY allowed). */
int adh_visco_drive_validate(const adh_visco_drive *d, char *why, size_t whylen);

/* The integrator (adh_visco_settings.integrator). */
enum {
    ADH_VISCO_AUTO = 0,   /* Rothe where it applies and was measured to (adh_visco_rothe_applies), else IDAS */
    ADH_VISCO_IDAS = 1,   /* IDAS along the arclength, everywhere */
    ADH_VISCO_ROTHE = 2   /* the Rothe steps; refused under a spring */
};

typedef struct adh_visco_settings {
    int integrator;      /* ADH_VISCO_AUTO, _IDAS or _ROTHE */
    double tol;          /* the integrator's relative tolerance; absolute ones are
                            tol z0 (u, h0), tol A / (6 pi z0^3) (q) and the time
                            to move z0 (t); the Rothe steps' local error in q,
                            in the force's area-weighted norm, is held below
                            ADH_ROTHE_TOL_FACTOR tol */
    double active_tol;   /* the preconditioner's dense LU takes node j where
                            c |p'(h_j)| sum_n |W_nj| exceeds this (as static) */
    size_t max_steps;    /* integrator steps of the whole run (ADH_EMAXITER beyond) */
    size_t max_jump_steps; /* steps of one jump's relaxation, where following the
                            equilibria got lost (ADH_ESTALL beyond) */
    const volatile sig_atomic_t *cancel; /* polled every step: nonzero stops
                            with ADH_EINTR; NULL = never */
    const double *land;  /* base positions, m, where the steps land a row
                            (as on a profile's, none stored); NULL none */
    size_t nland;
} adh_visco_settings;

#define ADH_ROTHE_TOL_FACTOR 5.0
/* tol's range (adh_visco_settings_validate): relative, as its name says */
#define ADH_VISCO_TOL_MIN 1e-10
#define ADH_VISCO_TOL_MAX 1e-2
/* The default tol, and the loosest at which halving it was measured to
 * move the pull-off, the jumps and the hysteresis by under 0.5 % (at 1e-4
 * the sigma = 75 cycle's hysteresis moved 0.59 %; at 5e-4 an Einf = 100 E0
 * cycle's lay 2 % off the converged one, its energy balance closed to
 * 0.3 %: the balance does not see that error): numbers at a looser tol
 * are not promised, and a driver says so. */
#define ADH_VISCO_TOL_DEFAULT 5e-5
/* 1 when tol is looser than ADH_VISCO_TOL_DEFAULT: its numbers are not
 * promised to 0.5 % (to rounding: the default's own text reads back as it). */
int adh_visco_tol_loose(double tol);
/* auto takes the Rothe steps up to this Einf/E0: measured beyond (100 and
 * 1000 E0) their error estimate took 2.3 and 8.6 times IDAS's steps and
 * their pull-off lay 0.35 and 1.1 % (dissipation 0.55 and 11 %) off the
 * converged values, which IDAS's default matches within 0.01 %: q's error
 * estimate does not hold the force there (docs/viscoelastic.md) */
#define ADH_ROTHE_RATIO_MAX 10.0
adh_visco_settings adh_visco_settings_default(void);
/* 1 when the Rothe steps integrate the path of solid v under drive d with
 * settings s: asked for, or auto without a spring and Einf at most
 * ADH_ROTHE_RATIO_MAX E0; else 0 (IDAS). */
int adh_visco_rothe_applies(const adh_sls *v, const adh_visco_drive *d, const adh_visco_settings *s);
int adh_visco_settings_validate(const adh_visco_settings *s, char *why, size_t whylen);

/* What happened where. */
enum {
    ADH_VISCO_JUMP = 1,     /* across a fold, forming or breaking the contact:
                               h0, F, a before and after */
    ADH_VISCO_CONTACT = 2,  /* contact formed (loading) or lost without a jump */
    ADH_VISCO_PULLOFF = 3,  /* the force's lowest local minimum on an unloading
                               path (one per path, not one per lattice wiggle) */
    ADH_VISCO_TURN = 4,     /* a turn reached (loading) */
    ADH_VISCO_UNLOAD = 5,   /* retraction begins (after the dwell) */
    ADH_VISCO_END = 6       /* the base is back at the start */
};

typedef struct adh_visco_event {
    int kind;
    int path;               /* 0 loading, k the k-th unloading branch */
    double t;               /* time, s */
    double base;            /* base position, m */
    double h0, F, a;        /* sphere position, force, contact radius (before a jump) */
    double h0_after, F_after, a_after; /* after a jump (else the same) */
    double loss;            /* energy the jump released, J (else 0): stored energy
                               before - after */
} adh_visco_event;

/* Energy accounts of a path, J. */
typedef struct adh_visco_energy {
    double work;        /* done by the base on the sphere (and spring) */
    double dissipated;  /* viscous, the integral of D */
    double jumps;       /* released by jumps (stored energy before - after) */
    double stored;      /* U at the end of the account */
    double stored0;     /* U at its beginning */
} adh_visco_energy;

typedef struct adh_visco_result {
    double start_base;     /* where the base starts and comes back to, m */
    double start_h0;
    double jump_in_h0;     /* first contact on loading (a jump's landing side, or
                              where the contact formed), m; NAN if none */
    double jump_in_t;
    double jump_in_base;
    double pulloff_F;      /* most negative force on the deepest turn's unloading, N */
    double pulloff_h0, pulloff_t, pulloff_base;
    double jump_out_h0;    /* where the contact was lost on that unloading; NAN if never */
    double jump_out_t, jump_out_base;
    double hysteresis;     /* NAN until that cycle closes; then the base's net work over it (loading to the
                              turn, dwell, unloading back to the start), J */
    adh_visco_energy cycle; /* that cycle's accounts */
    double time;           /* physical time at the end (or now), s */
    size_t steps;          /* integrator steps (jumps' relaxations included) */
    size_t jumps;          /* jumps that formed or broke the contact (each an event) */
    size_t lattice_jumps;  /* jumps that did neither: the contact line snapping
                              across a lattice fold of the grid, a ring (in the
                              accounts' jump losses, no events) */
    size_t jumps_relaxed;  /* jumps of either kind that landed by relaxing, where
                              following the equilibria got lost (lattice folds of
                              a grid that does not resolve the contact edge) */
    size_t folds_resumed;  /* roots of t' that were no fold (the relaxation
                              came back to them): the path went on, no jump */
    size_t newton;         /* Newton iterations */
    size_t krylov;         /* GMRES iterations */
    size_t setups;         /* preconditioner factorizations (a dense LU, or HODLR's;
                              its low-rank updates apart) */
    size_t error_fails;    /* steps the error test rejected */
    double seconds;        /* wall time */
} adh_visco_result;

typedef struct adh_visco adh_visco;

/* The grid and kernel are borrowed and must outlive the solver. Copies a
 * dense W (N^2 doubles) once, or assembles a hierarchical one as HODLR.
 * NULL when out of memory. */
adh_visco *adh_visco_alloc(const adh_grid *g, const adh_kernel *k);
void adh_visco_free(adh_visco *w);

/* Puts the solver at the protocol's start, solved (m's A, z0 and R; its E
 * is not read: the moduli are v's). The protocol ps gives the start (NAN:
 * automatic, where the force is negligible and, under a spring, well
 * outside the snap-in), the turns (reached by h0, the sphere's position),
 * whether to unload, and the profile positions (of the base). run (borrowed,
 * freshly initialised) gets one row per step (t and base filled), the
 * turns' summaries and the profiles. ADH_SUCCESS; ADH_EINVAL for bad
 * values (why says which, if not NULL); ADH_ESTALL when the start is not
 * a stable point out of contact. */
int adh_visco_set(adh_visco *w, const adh_material *m, const adh_sls *v, const adh_visco_drive *d,
                  const adh_visco_settings *s, const adh_protocol_settings *ps, adh_run *run, char *why,
                  size_t whylen);

/* One step: appends its row to the run. ADH_CONTINUE with a row;
 * ADH_SUCCESS when the protocol is complete (no row); ADH_EINTR on the
 * cancel flag; otherwise the error that stopped it (ADH_EGRID: the
 * contact reached 0.9 Rmax or left a graded grid's fine band; ADH_ESTALL:
 * the integrator or a jump's relaxation failed; ADH_EMAXITER: max_steps).
 * After a final status every call returns it again. */
int adh_visco_iterate(adh_visco *w);

/* The whole protocol, without a callback (a driver steps the rule,
 * adhere/rule_visco.h, through the drive and the runner). Returns
 * ADH_SUCCESS or the error. */
int adh_visco_run(adh_visco *w);

/* 1 when the row the last iterate returned is the protocol's last (the
 * next call returns ADH_SUCCESS). */
int adh_visco_last(const adh_visco *w);

/* Why the run stopped, when it stopped on an error (the integrator's own
 * words for ADH_ESTALL); "" otherwise. */
const char *adh_visco_why(const adh_visco *w);
/* The ADH_FIX_* bits (adhere/status.h) of what may get past that stop:
 * ADH_FIX_SPACING | ADH_FIX_NODES where the contact line's lattice folds
 * stopped it on a grid coarser than the one that resolves them; else 0. */
unsigned adh_visco_fix(const adh_visco *w);

/* The current state (borrowed), time and base. */
const adh_state *adh_visco_state(const adh_visco *w);
double adh_visco_time(const adh_visco *w);
double adh_visco_base(const adh_visco *w);
/* The summary so far. */
void adh_visco_summary(const adh_visco *w, adh_visco_result *res);

/* How far the closed cycle's energy balance is open: (hysteresis -
 * dissipated - jumps - stored change) / |hysteresis|; NAN before the
 * cycle closes. Past ADH_VISCO_BALANCE_MAX the integration did not
 * converge: a converged run closes to 1e-4 - 4e-3 of the work
 * (docs/viscoelastic.md), a step too long for its work's quadrature (the
 * Rothe steps before their force bound: 1.9 % at 1 mm/s on sigma0 = 2.25)
 * or a loose tolerance leaves it open further. */
#define ADH_VISCO_BALANCE_MAX 5e-3
double adh_visco_balance_open(const adh_visco_result *r);
/* What the balance leaves, J: the work (hysteresis) less the dissipated
 * energy, the jumps' losses and the stored energy's change over the
 * cycle (summary.tsv's energy_residual). */
double adh_visco_balance_residual(const adh_visco_result *r);
/* The events so far (borrowed). */
size_t adh_visco_events(const adh_visco *w, const adh_visco_event **ev);
/* The stored energy U of the current state, J, and its parts. */
double adh_visco_stored(const adh_visco *w, double *elastic, double *surface, double *spring);

/* The automatic start for material m (its E the relaxed modulus) and
 * step: the elastic one (force negligible, deformation below 1 % of z0),
 * and under a spring k (INFINITY: none) where rigid spheres' force rises
 * at most a quarter of k per metre (F' = A R / 3 h^3), well outside the
 * snap-in. On the step's lattice. */
double adh_visco_auto_start(const adh_material *m, double spring, double step);

/* Whether the solid can start where ps says (its start, or NAN: the
 * automatic one adh_visco_set takes) on grid g with kernel k: relaxed, at
 * rest, out of contact, the state adh_visco_set solves first by the same
 * arithmetic (where it fails, the run stops before its first step with
 * ADH_ESTALL). ADH_SUCCESS; ADH_EINVAL with why naming the start, what a
 * start must be and what it is there, and the least start above it that
 * is (to within the step), *fix (may be NULL) ADH_FIX_START; ADH_ENOMEM.
 * No I/O: a driver asks it before the run. */
int adh_visco_start_check(const adh_grid *g, const adh_kernel *k, const adh_material *m, const adh_sls *v,
                          const adh_visco_drive *d, const adh_protocol_settings *ps, char *why, size_t whylen,
                          unsigned *fix);

/* The settings of the viscoelastic step rule (adhere/rule_visco.h): the
 * material beyond adh_material (whose E is E0), the instrument and the
 * integrator. */
typedef struct adh_visco_rule_settings {
    adh_sls sls;
    adh_visco_drive drive;
    adh_visco_settings s;
} adh_visco_rule_settings;

/* Einf = E0 = E (elastic), tau = 1 ms, the default drive and integrator. */
adh_visco_rule_settings adh_visco_rule_settings_default(double E);

/* The instrument's jumps on an elastic (static) curve: where the base
 * h0 - F/k turns, i.e. dF/dh0 = k, located on the stable rows of curve
 * (in the order of the rows, interpolated between them). Fills up to max
 * positions (h0, m) into at and the base's there into base (may be NULL);
 * returns how many there are. */
size_t adh_visco_spring_folds(const adh_run *curve, double k, double *at, double *base, size_t max);

/* The instrument's snap-out on an elastic (static) curve: the base's
 * position and h0 (returned) where the sphere, retracted from the curve's
 * end through the spring k, jumps out of contact. It follows the rows
 * outward while the base rises; at a fold (a turn of the base) it lands
 * on the first row further out whose base is back at the fold's: a row in
 * contact is the contact line snapping across a lattice fold of the grid,
 * and it goes on from there (a soft spring's force wiggles make one fold
 * per ring near the pull-off); out of contact, or beyond the curve's
 * start, the fold is the snap-out. NAN (both) when there is none. */
double adh_visco_spring_snap_out(const adh_run *curve, double k, double *base);

#endif
