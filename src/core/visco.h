/* The viscoelastic solver's insides (the public face is adhere/visco.h),
 * shared by its files: visco.c (the protocol, one step a call),
 * visco_dae.c (IDAS, its callbacks, roots, quadratures), visco_path.c (the
 * path's system and its tangent), visco_cross.c (a jump's crossing),
 * visco_flow.c (a jump's relaxation, the crossing's fallback),
 * visco_energy.c (energies, the spring's folds on a static curve),
 * visco_pre.c (the preconditioner), visco_params.c (inputs). Internal to
 * the core. */
#ifndef ADH_CORE_VISCO_H
#define ADH_CORE_VISCO_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include "adhere/visco.h"
#include "visco_pre.h"

/* Parts of a segment of the path (one IDAS initialisation each). */
enum { SEG_LOAD = 1, SEG_DWELL = 2, SEG_UNLOAD = 3 };

/* What IDAS integrates: the path along its arclength s, or a jump's
 * crossing: the equilibria at frozen time and q followed from the fold
 * along their own arclength in (u, h0) to the other branch where the
 * base is back at the fold's position (visco_cross.c); or, where that
 * gets lost (a lattice-fold ladder of an unresolved grid), the jump's
 * overdamped relaxation at frozen time, base and q (visco_flow.c). */
enum { MODE_PATH = 0, MODE_CROSS = 1, MODE_FLOW = 2 };

/* The roots watched along the path (IDAS's rootfinding): the fold
 * (t' = 0), the segment's end, a force minimum, contact, a profile
 * position. */
enum { ROOT_FOLD = 0, ROOT_END, ROOT_PULLOFF, ROOT_CONTACT, ROOT_PROFILE, NROOTS };

/* The quadratures: the base's work, the viscous dissipation. */
enum { QWORK = 0, QDISS, NQUAD };

typedef struct visco_seg {
    int kind;        /* SEG_* */
    double t0;       /* absolute time where the local time y[IT] is 0, s */
    double b0;       /* base there, m */
    double bdot;     /* base speed, m/s (signed: < 0 approaching) */
    double vm;       /* the metric's speed: time enters s as vm t, m/s */
    double tl_end;   /* dwell: local time it ends */
    double target;   /* load: the next turn's h0; unload: the start base */
    double prof;     /* the next profile position of the base (NAN none) */
    int path, branch;
} visco_seg;

/* The state at a turn, to unload from: y (u, q, local time 0, h0) and the
 * accounts up to it. */
typedef struct visco_snap {
    double *y;       /* length len, local time 0 */
    double t;        /* absolute time, s */
    double base;
    double h0;
    adh_visco_energy acc;
    int reached;
} visco_snap;

struct adh_visco {
    const adh_grid *g;
    const adh_kernel *k;
    size_t n, len;       /* nodes; IDAS unknowns: 2n + 1 (+1 with a spring) */
    size_t IQ, IT, IH;   /* where q, the local time and h0 begin in y */
    int spring;          /* 1 with a finite k */
    adh_visco_pre *pre;

    adh_material m;
    adh_sls v;
    adh_visco_drive dr;
    adh_visco_settings s;
    adh_protocol_settings ps;
    double cinf, cdel, theta, pref; /* 2/Einf, 2 (1/E0 - 1/Einf), 1/N, A / 6 pi z0^3 */
    double *shape, *area;           /* r^2 / 2R; 2 pi w_n */
    double *h, *p, *D;              /* gaps, pressures, p'(h) at the last evaluation */
    double *tmp, *tmp2, *scratch;   /* n each */
    /* the preconditioner's own: p'(h) and p - q at its setup, W p'(h),
     * W (p - q), and its borders (2 columns and 2 rows of n) */
    double *pD, *ppq, *WD, *Wpq, *bord;

    /* IDAS */
    SUNContext sun;
    void *ida;
    N_Vector y, yp, atol, yq;
    SUNLinearSolver ls;
    /* the tangent's linear solve (u[, h0]) */
    SUNLinearSolver tls;
    N_Vector tx, tb;
    int tan_row;         /* the tangent's operator has the spring's row */
    /* the preconditioner's data at its setup */
    double p_cj, p_alpha, p_ceff, p_tp;
    int p_mode;
    /* IDAS's counters restart with each initialisation: what the earlier
     * ones counted (steps, Newton and GMRES iterations, setups, error
     * test failures) */
    long stat0[5];
    int live;            /* IDAS runs: its counters and quadratures count */

    visco_seg seg;
    double s_now;        /* the path parameter now */
    int mode;            /* MODE_PATH, or MODE_CROSS during a jump */
    int phase;           /* a crossing: 1 until the base's coordinate turns
                            (the S's other fold), 2 from there */
    int cross_dir;       /* -1 loading (the base's coordinate falls back
                            to the fold's), +1 unloading */
    double b_fold;       /* the base at the fold */
    visco_seg seg_fold;  /* the segment as it was (a dwell's crossing moves
                            h0 through tl at a virtual speed) */
    double s_fold;       /* where on the path the jump under way began */
    /* len each, one block (yfold owns it): the fold's state and y'; a
     * crossing's start y' (or step's secant); its last good point and y';
     * a relaxation's start y' */
    double *yfold, *ypfold, *ywork, *yprev, *ypprev, *ypflow;
    double *ro_last, *ro_dir; /* a Rothe fold's last state and its secant, where the jump relaxes (rothe_relax) */
    long jump_steps;     /* steps of the crossing so far */
    long retries;        /* its retries (visco.c's cross_retry), with the first
                            and the last step that went backwards: what the
                            tests bound by the retries' rule */
    double retry_h1, retry_h;
    int land_try;        /* a jump-in: try the static solver's landing first
                            (visco_land.c) */
    struct adh_static *stat; /* its static solver (allocated at the first; the
                            Rothe steps' too) */
    int rothe;           /* the Rothe steps integrate the path (visco_rothe.c),
                            IDAS only a jump's fold and crossing */
    int rothe_on;        /* they do now (else IDAS took over for a jump) */
    size_t idas_rows;    /* rows IDAS has pushed since it took over */
    size_t rothe_factor; /* the Rothe steps' preconditioner factorizations */
    adh_visco_event rprev[2]; /* the Rothe rows one and two back on this
                            segment (a force minimum between steps) */
    int nrprev;
    struct visco_rothe *ro;
    double *egap;        /* and its extra gap cdel W q, n */
    double nudge;        /* a relaxed jump's push off its fold, per z0 */
    double rest;         /* its rest test: speeds below this (VISCO_REST, less
                            after a rest on no equilibrium) */
    double t_resumed;    /* when the path last went on through a root of t'
                            that was no fold (resume) */
    double t_stuck;      /* when the integrator last could not follow the path
                            on, and the sphere jumped from there */
    double stuck_push;   /* the push of the last relaxation from there (path_stuck) */
    int have_prev;       /* a crossing's last good point is kept (yprev) */
    double s_prev;       /* and where it was */
    adh_visco_event pending; /* the jump being crossed: its side before */
    size_t pull_ev;      /* this path's pull-off event (index + 1 into ev; 0 none) */
    double U_before;

    /* the protocol */
    double b_start, h0_start;
    double stretch, reach;   /* a spring's largest stretch; a crossing's reach, m */
    size_t nturns;
    double turns[ADH_MAX_TURNS];    /* h0, shallowest first */
    visco_snap snap[ADH_MAX_TURNS];
    size_t ti;           /* loading: the next turn to reach */
    size_t ui;           /* unloading: which turn */
    double *prof;        /* base positions, highest first: the profiles' and
                            the settings' landing points (s.land) */
    unsigned char *keep; /* prof[i] stores a profile (else a row lands there) */
    size_t nprof, pi, profcap; /* marks; the next one's index on this branch */

    adh_visco_energy acc;   /* the current path's accounts */
    double qbase[NQUAD];    /* quadratures before this initialisation */
    adh_state *st;       /* the physical state now */
    double t_now, base_now;
    double F_now;
    int in_contact;
    int extended;        /* unloading goes on past the start until apart */
    adh_run *run;
    adh_visco_event *ev;
    size_t nev, evcap;
    adh_visco_result res;
    int started;         /* the start row is out */
    int first_pending;   /* the next call's row is the state as it is (a
                            branch's first, from its turn's snapshot) */
    int finishing;       /* the next call ends the run */
    int done, status;
    unsigned fix;        /* ADH_FIX_* bits of what may get past the stop (adh_visco_fix) */
    char errmsg[400];    /* why the run stopped (IDAS's last words within) */
};

/* visco_dae.c: IDAS, its callbacks (dispatched by mode), the roots and
 * quadratures, and the helpers of both systems */
int adh_visco_dae_create(adh_visco *w);
void adh_visco_dae_destroy(adh_visco *w);
/* (Re)starts IDAS at s with y, yp under the current segment and mode. */
int adh_visco_dae_start(adh_visco *w, double s, const double *y, const double *yp);
/* The roots' directions for the current segment. */
void adh_visco_root_directions(adh_visco *w);
/* For the tests: jtimes against a difference of the residual (*fd,
 * relative), and P^-1 M v against v (*pre, in tolerances), at the
 * integrator's y, y' and the given cj. */
int adh_visco_dae_check(adh_visco *w, double cj, double *fd, double *pre);
/* h0 of y under the segment, and the base */
double adh_visco_h0_of(const adh_visco *w, const double *y);
double adh_visco_base_of(const adh_visco *w, const double *y);
/* The solid relaxed at rest at h0 (q = p, u = -c0 W p by fixed point; c0
 * = 2/E0 as c_inf + c_del), visco_start.c: the buffers, n each (shape
 * r^2/2R read); u, h, p the state. 0 when it settles out of contact, or
 * why not: */
enum { VISCO_REST_TOUCH = 1,      /* a gap closed */
       VISCO_REST_UNSETTLED = 2,  /* the fixed point did not settle */
       VISCO_REST_CONTACT = 3 };  /* a gap below ADH_CONTACT_FACTOR z0 */
typedef struct visco_rest_buf {
    double *u, *h, *p, *tmp, *tmp2, *scratch;
    const double *shape;
} visco_rest_buf;
int adh_visco_rest(const adh_kernel *k, const adh_material *m, double c0, double h0, size_t n,
                   const visco_rest_buf *b);
/* h, p from u and h0 on n nodes of the given shape (r^2/2R, and any
 * extra gap); 0, or -1 when a gap closed; adh_visco_gaps into w->h, w->p */
int adh_visco_gaps_of(const adh_material *m, size_t n, const double *shape, const double *u, double h0, double *h,
                      double *p);
int adh_visco_gaps(adh_visco *w, const double *u, double h0);
/* D = p'(h) at w->h into w->D */
void adh_visco_slopes(adh_visco *w);
/* The force of w->p at h0 (eq 13, tail included) */
double adh_visco_force(const adh_visco *w, double h0);
/* The tail's force beyond Rmax, and its slope dF_tail/dh0 */
double adh_visco_tail(const adh_visco *w, double h0, double *slope);
/* The (u, h0) part of a tangent d in the crossing's metric,
 * sqrt(theta |u'|^2 + h0'^2) (h0 under a spring) */
double adh_visco_uh_length(const adh_visco *w, const double *d);
/* out = W x (the kernel's product) */
void adh_visco_apply(adh_visco *w, const double *x, double *out);
/* e = cdel W q: the gap a frozen (or known) q adds to the elastic problem
 * at Einf (a jump's landing, a Rothe step) */
void adh_visco_extra_gap(adh_visco *w, const double *q, double *e);
/* The preconditioners' q part (cross and flow alike): z_q = r_q / cj, and
 * w->tmp2 = W z_q (zero when c_del is) */
void adh_visco_psolve_q(adh_visco *w, const double *r, double *z);
/* dF/ds at y, y' (h and p' at y computed here, w's buffers untouched) */
double adh_visco_force_rate(const adh_visco *w, const double *y, const double *d);

/* visco_land.c: a jump-in landed by the static solver at Einf with q
 * frozen (from w->yfold): y (len) gets the landing, on the equilibria at
 * the fold's h0, q and time, in contact; ADH_ESTALL (or the static
 * solver's error) where it did not land, y untouched. */
int adh_visco_land_static(adh_visco *w, double *y);

/* visco_rothe.c: the path by Rothe steps (displacement control) */
typedef struct visco_rothe visco_rothe;
#define VISCO_ROTHE_BACK 40   /* IDAS rows without a fold before the Rothe steps take the path back */
#define VISCO_ROTHE_JUMP 1000 /* advance's return: a fold, the path to IDAS */
void adh_visco_rothe_free(adh_visco *w);
/* Starts the steps afresh at y (u, q, local time) under the current
 * segment: no history, a short first step. ADH_SUCCESS, ADH_ENOMEM, or
 * the static solver's error setting it up. */
int adh_visco_rothe_reset(adh_visco *w, const double *y);
/* One accepted step of at most tl_end - y's local time: y, the accounts
 * and the counters updated, *hit 1 when it landed on tl_end. ADH_SUCCESS;
 * VISCO_ROTHE_JUMP where no step down to the shortest converges (y
 * untouched: the last accepted state, before a fold); ADH_EINTR. */
int adh_visco_rothe_advance(adh_visco *w, double *y, double tl_end, int *hit);
/* Back to the state a step before on this segment: y and the accounts
 * there. 1, or 0 when there is none (y untouched). */
int adh_visco_rothe_back(adh_visco *w, double *y);
/* A jump out of contact at y's q, time and h0 (frozen: the static problem
 * at Einf with the extra gap cdel W q), landed by Newton from the
 * surfaces apart: y's u the landing. ADH_SUCCESS out of contact;
 * ADH_ESTALL where it lands in contact, or the corrector's error. */
int adh_visco_rothe_land_out(adh_visco *w, double *y);


/* visco_path.c: the path's residual, Jacobian products, preconditioner,
 * and the tangent that starts each segment */
int adh_visco_path_res(adh_visco *w, const double *y, const double *d, double *r);
void adh_visco_path_jtimes(adh_visco *w, const double *y, const double *d, const double *v, double *Jv,
                           double cj);
int adh_visco_path_psetup(adh_visco *w, const double *y, const double *d, double cj);
void adh_visco_path_psolve(adh_visco *w, const double *r, double *z);
/* y' consistent with y under the current segment (the tangent, t' > 0),
 * into yp. ADH_SUCCESS, or ADH_ESTALL when the solve fails. */
int adh_visco_tangent(adh_visco *w, const double *y, double *yp);
/* Gives the tangent's GMRES its operator and preconditioner. */
int adh_visco_tangent_setup(adh_visco *w);
/* Newton on the equilibrium at y's q and time (u, and h0 by the spring's
 * equation when row is 1; h0 held with 0), to well within the tolerance.
 * ADH_SUCCESS or ADH_ESTALL. */
int adh_visco_polish(adh_visco *w, double *y, int row);

/* visco_cross.c: a jump's crossing, the same four, its start, and its
 * roots (the base's coordinate h0 - F/k: its turn, then its return) */
int adh_visco_cross_res(adh_visco *w, const double *y, const double *d, double *r);
void adh_visco_cross_jtimes(adh_visco *w, const double *y, const double *d, const double *v, double *Jv,
                            double cj);
int adh_visco_cross_psetup(adh_visco *w, const double *y, const double *d, double cj);
void adh_visco_cross_psolve(adh_visco *w, const double *r, double *z);
/* y' at the fold for the crossing, from the path's y' there. */
void adh_visco_cross_start(adh_visco *w, const double *d, double *yp0);
void adh_visco_cross_roots(adh_visco *w, const double *y, const double *d, double *g);
/* The base's coordinate h0 - F/k of y (h0 without a spring). */
double adh_visco_cross_base(const adh_visco *w, const double *y);

/* visco_flow.c: a jump's relaxation, the same four, its start, its speed */
int adh_visco_flow_res(adh_visco *w, const double *y, const double *d, double *r);
void adh_visco_flow_jtimes(adh_visco *w, const double *y, const double *v, double *Jv, double cj);
int adh_visco_flow_psetup(adh_visco *w, const double *y, double cj);
void adh_visco_flow_psolve(adh_visco *w, const double *r, double *z);
/* The relaxation's start from the fold y nudged along the path's tangent
 * d (nudge times it; under a spring at least 1e-3 z0 in its (u, h0)
 * part); y' = -(the residual). */
int adh_visco_flow_start(adh_visco *w, const double *y, const double *d, double nudge, double *y0, double *yp0);
/* How fast it still moves: max over u (and h0) of |y'| / atol, per unit
 * pseudo-time. */
double adh_visco_flow_speed(const adh_visco *w, const double *d);

/* visco.c: a relaxation still moving, checked every VISCO_FLOW_CHECK
 * steps: 1 when Newton on a copy of w->y (at its q and time, h0 by the
 * spring) converges within ten tolerances (z0) of it in u and h0, and w->y
 * is then Newton's state; else 0, w->y untouched. */
int adh_visco_next_to_equilibrium(adh_visco *w);

/* visco_energy.c */
/* <a, W a> in the area-weighted inner product; uses w->tmp2 */
double adh_visco_energy_norm(adh_visco *w, const double *a);
/* U of y (the stored energy), with parts (any may be NULL); uses w->h,
 * w->p, w->tmp, two kernel products */
double adh_visco_energy_of(adh_visco *w, const double *y, double *el, double *surf, double *spr);

#endif
