/* The viscoelastic solver's insides, shared by its files: visco.c (the
 * protocol, one step a call), visco_dae.c (the system IDAS integrates and
 * its linear algebra), visco_energy.c (energies, checks, the spring's
 * folds on a static curve). Internal to the core. */
#ifndef ADH_VISCO_IMPL_H
#define ADH_VISCO_IMPL_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include "adhere/visco.h"
#include "visco_pre.h"

/* Parts of a segment of the path (one IDAS initialisation each). */
enum { SEG_LOAD = 1, SEG_DWELL = 2, SEG_UNLOAD = 3 };

/* The roots watched (IDAS's rootfinding): the fold (t' = 0), the
 * segment's end, a force minimum, contact, a profile position. */
enum { ROOT_FOLD = 0, ROOT_END, ROOT_PULLOFF, ROOT_CONTACT, ROOT_PROFILE, NROOTS };

/* The quadratures: the base's work, the viscous dissipation, and the
 * (virtual) base's work along a jump's crossing. */
enum { QWORK = 0, QDISS, QJUMP, NQUAD };

typedef struct visco_seg {
    int kind;        /* SEG_* */
    int frozen;      /* crossing a jump (q' = 0, the time a path parameter):
                        1 on its way back to the other fold, 2 from there */
    double t0;       /* absolute time where the local time y[IT] is 0, s */
    double b0;       /* base there, m */
    double bdot;     /* base speed, m/s (signed: < 0 approaching) */
    double vm;       /* the metric's speed: time enters s as vm t, m/s */
    double tl_end;   /* dwell: local time it ends */
    double tl_fold;  /* frozen: local time of the fold crossed */
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
    int tls_factored;
    /* the preconditioner's data at its setup */
    double p_cj, p_alpha, p_ceff, p_tp, p_lam;
    /* IDAS's counters restart with each initialisation: what the earlier
     * ones counted (steps, Newton and GMRES iterations, setups, error
     * test failures) */
    long stat0[5];
    int live;            /* IDAS runs: its counters and quadratures count */

    visco_seg seg;
    double s_now;        /* the path parameter now */
    double lam;          /* 1, or 0 while crossing a jump */
    long jump_steps;     /* steps of the crossing under way */
    adh_visco_event pending; /* the jump being crossed: its side before */
    double U_before;

    /* the protocol */
    double b_start, h0_start;
    size_t nturns;
    double turns[ADH_MAX_TURNS];    /* h0, shallowest first */
    visco_snap snap[ADH_MAX_TURNS];
    size_t ti;           /* loading: the next turn to reach */
    size_t ui;           /* unloading: which turn */
    double prof[ADH_MAX_PROFILES];  /* base positions, highest first */
    size_t nprof, pi;    /* profiles; the next one's index on this branch */

    adh_visco_energy acc;   /* the current path's accounts */
    double qbase[NQUAD];    /* quadratures before this initialisation */
    adh_state *st;       /* the physical state now */
    double t_now, base_now;
    double F_now;
    int in_contact;
    adh_run *run;
    adh_visco_event *ev;
    size_t nev, evcap;
    adh_visco_result res;
    int started;         /* the start row is out */
    int first_pending;   /* the next call's row is the state as it is (a
                            branch's first, from its turn's snapshot) */
    int finishing;       /* the next call ends the run */
    int done, status;
    char errmsg[160];    /* IDAS's last error, for the report */
};

/* visco_dae.c */
int adh_visco_dae_create(adh_visco *w);
void adh_visco_dae_destroy(adh_visco *w);
/* h0 of y under the segment, and the base */
double adh_visco_h0_of(const adh_visco *w, const double *y);
double adh_visco_base_of(const adh_visco *w, const double *y);
/* h, p from u and h0 into w->h, w->p; 0, or -1 when a gap closed */
int adh_visco_gaps(adh_visco *w, const double *u, double h0);
/* The force of w->p at h0 (eq 13, tail included) */
double adh_visco_force(const adh_visco *w, double h0);
/* y' consistent with y under the current segment (the tangent, t' > 0),
 * into yp. ADH_SUCCESS, or ADH_ESTALL when the solve fails. */
int adh_visco_tangent(adh_visco *w, const double *y, double *yp);
/* (Re)starts IDAS at s with y, yp under the current segment. */
int adh_visco_dae_start(adh_visco *w, double s, const double *y, const double *yp);
/* The roots' directions for the current segment (and crossing phase). */
void adh_visco_root_directions(adh_visco *w);

/* For the tests: jtimes against a difference of the residual, and the
 * preconditioner against M (adh_visco_dae_check in visco_dae.c). */
int adh_visco_dae_check(adh_visco *w, double cj, double *fd, double *pre);

/* visco_energy.c */
/* U of y (the stored energy), with parts (any may be NULL); uses w->h,
 * w->p, w->tmp, two kernel products */
double adh_visco_energy_of(adh_visco *w, const double *y, double *el, double *surf, double *spr);

#endif
