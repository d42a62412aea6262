/* The parts of the static solver, private to it (the public header is
 * adhere/static.h), shared by its files and by nothing else:
 *
 *   static.c            the facade: alloc, set (the start point), iterate
 *                       (one accepted point, by the strategy in effect),
 *                       the accepted point's bookkeeping
 *   static_newton.c     the Newton-Krylov corrector: G and its Jacobian at
 *                       a point, bordered solves by flexible GMRES
 *                       (adhere/fgmres.h) with a preconditioner
 *                       (adhere/precond.h) refreshed when it goes stale,
 *                       the tangent, Newton's iteration on one constraint
 *   static_arclength.c  the exact curve: pseudo-arclength steps along the
 *                       tangent, every fold resolved (lattice_skip 0)
 *   static_qstep.c      steps in the contact measure Q (lattice_skip 1)
 *   static_front.c      steps of whole rings of the contact line, within
 *                       the Q steps once a contact has formed
 *
 * Folds and pull-off are adhere/folds.h's. Notation: x = (u, h0); the
 * metric is |x|^2 = (theta sum u_n^2 + h0^2) / z0^2 (theta = u_weight), so
 * tangents and arclength s are dimensionless / in z0. */
#ifndef ADH_CORE_STATIC_H
#define ADH_CORE_STATIC_H

#include "adhere/fgmres.h"
#include "adhere/folds.h"
#include "adhere/precond.h"
#include "adhere/static.h"

#define ADH_GMRES_MAX 40   /* Krylov dimension before the preconditioner is refreshed */

/* The corrector's linear algebra and workspace. */
typedef struct static_newton {
    adh_precond *P;     /* set at some recent point, refreshed when FGMRES
                           needs more than ADH_GMRES_FRESH iterations with it */
    adh_fgmres *kr;
    size_t stamp;       /* the step attempt P was set in */
    int tangent_border; /* P bordered by the current tangent: its det sign
                           is comparable with det_b_sign */
    size_t attempt;     /* step attempts so far (stamps the factorizations) */
    double act;         /* active-set threshold in use (lowered when the
                           preconditioned solve stops contracting) */
    double *G;          /* G at the last evaluation */
    double *du;         /* the last bordered solve's answer, n + 1 */
    double *bG;         /* its right side, n + 1 */
    double *Dc, *gc;    /* p'(h) and dG/dh0 at the iterate */
    double *zero;       /* n + 1 zeros (a tangent's right side borrows the last) */
    double *upred;      /* the predictor's u (a plane constraint passes through it) */
    double h0pred;      /* ... and its h0 */
    double *scratch, *t2;
    double residual;    /* max_n |G_n| at the last converged point, m */
} static_newton;

/* The constraint a Newton correction holds: the bordered system's last row. */
typedef enum static_row_kind {
    STATIC_ROW_PLANE,  /* nu.(u - upred) theta + nh (h0 - h0pred) = 0 */
    STATIC_ROW_Q,      /* Q(u, h0) = target (nonlinear) */
    STATIC_ROW_GAP     /* h at node = gap (front steps) */
} static_row_kind;

typedef struct static_row {
    static_row_kind kind;
    const double *nu;   /* PLANE: the normal's u part; GAP: the row of h at node */
    double nh;          /* ... its h0 part */
    double target;      /* Q */
    size_t node;        /* GAP */
    double gap;         /* GAP, m */
    int refresh;        /* set the preconditioner at the first iterate when
                           it was set in an earlier attempt */
} static_row;

/* Steps in Q, and the history of accepted points their predictors use. */
typedef struct static_qstep {
    double q, dq, qslope; /* Q at the current point, the step in Q, dQ/ds along the tangent */
    double *rG;           /* the constraint row: Q's gradient, or the front's */
    double *u1, *u2, q1, q2, h1, h2; /* the two points before the current one */
    size_t nhist;         /* how many of them there are */
} static_qstep;

/* Front steps (lattice_skip, once the contact has formed): whole rings of
 * the contact line. Each point holds the gap fH at a fine ring fe[0] (the
 * contact line at the same place in its ring, so the lattice's phase is
 * the same at every point); the predictor moves the last points' gap
 * profiles out by the step, a travelling front. */
typedef struct static_front {
    int on;
    size_t fe[3];     /* front node of the current point and of the two before */
    size_t fn;        /* consecutive front points (up to 3 used) */
    size_t fk;        /* the step, in rings */
    size_t fend;      /* the front node of the landing on h0_end */
    int fhold;        /* the step was set to approach an extremum: keep it */
    size_t fwin;      /* nonzero: steps in Q until the front passes this
                         node (an extremum's neighbourhood, every phase of
                         the lattice seen) */
    size_t nf;        /* nodes of the uniform fine band */
    double fH;        /* the gap held at the front node, m */
    /* A phase sweep (HODLR preconditioner, fine bands of 4000 rings or
     * more: static_front.c): at an extremum the front crosses one ring in
     * ADH_FRONT_PHASES steps, each holding the gap at fe[0] at a value
     * between fH (phase 0) and hin (phase 1), instead of ~20 steps in Q
     * over a dozen rings */
    int pw;           /* sweeping */
    size_t pwleft;    /* steps left in the sweep */
    size_t nosweep[2]; /* no new sweep for h0's maximum, F's minimum before
                          the front passes this node */
    double ph[3];     /* the phases of fe[0..2] (fractions of a ring) */
    double phn;       /* the phase of the step being taken */
    double hin;       /* the gap a ring inside the front at phase 0, m */
    int ok;           /* front mode allowed (it falls back to Q for good
                         when a one-ring step fails) */
} static_front;

struct adh_static {
    const adh_grid *grid;
    const adh_kernel *k;
    const double *entries; /* W's, borrowed for a dense preconditioner; NULL: it copies them */
    size_t n;
    int skip;         /* lattice_skip in effect (the setting, or auto's choice) */
    double *shape;    /* r^2 / 2R, plus the extra gap if one is set */
    double *extra;    /* the extra gap (adh_static_set_gap), n; NULL none */
    adh_material m;
    adh_static_settings s;
    double c2E;       /* 2/E */
    static_newton nw;

    adh_state *st;    /* the current accepted point */
    adh_state *trial; /* the point being corrected */
    double *tau_u, tau_h;          /* unit tangent at st */
    double *tau_u_new, tau_h_new;  /* tangent at trial */
    double *Dst, *gst, *Dtr, *gtr; /* p'(h) and dG/dh0 at st and at trial */
    int det_sign;     /* sign of det J at st */
    int det_b_sign;   /* sign of det B, invariant along the curve */
    double ds;        /* the arclength step */
    double s_arc;
    int stable;
    double F, dFds;   /* force and its arclength derivative at st */
    int end_next;     /* the next step lands on h0_end */
    size_t newton_point;
    int done;
    static_qstep q;
    static_front fr;
    adh_folds *folds;
    adh_static_result res;
    /* A start in contact: the curve past it, from the automatic start down
     * to it (the unloading goes on past the start until the surfaces
     * separate, as the drive's does): its summary, merged into the
     * curve's (past_on), or unknown (past_lost: no pull-off then). */
    adh_folds_summary past;
    int past_on, past_lost;
    adh_state *past_least; /* its point of least force (allocated on the first trace) */
    double past_least_F;
    double *buf;      /* the vectors above, one allocation */
    const char *last_reject; /* why the last step attempt was rejected (static_reject) */
    char why[400];    /* why the curve stopped ("" while it goes on; as long as a run's) */
    unsigned fix;     /* ADH_FIX_* bits beside it */
};

/* static_newton.c */
int static_newton_alloc(adh_static *w);
void static_newton_free(adh_static *w);
double static_evaluate(adh_static *w, adh_state *x);
void static_jacobian(adh_static *w, const adh_state *x, double *D, double *g);
int static_refactor(adh_static *w, const double *D, const double *g, const double *nu, double nh);
int static_tangent(adh_static *w, const double *D, const double *g, double *tu, double *th_out);
void static_predict(adh_static *w, double ds, int fix, double h0_fix);
int static_correct(adh_static *w, const static_row *row, size_t *iters);

/* static.c */
void static_shape(adh_static *w, const double *e);
double static_metric_dot(const adh_static *w, const double *au, double ah, const double *bu, double bh);
void static_secant(adh_static *w, double *su, double *sh);
void static_accept(adh_static *w);
int static_accepted(adh_static *w);
int static_landing(const adh_static *w, int front, double *ds);
const char *static_reject(int rc);
int static_stalled(adh_static *w, const char *how);

/* static_arclength.c */
int static_arclength_iterate(adh_static *w);

/* static_qstep.c */
double static_qmeasure(adh_static *w, const adh_state *x, double *qu, double *qh, double *scale);
int static_qstep_start(adh_static *w);
int static_qstep_iterate(adh_static *w);

/* static_front.c */
void static_front_set(adh_static *w);
size_t static_front_node_of(const adh_static *w, const adh_state *x);
void static_front_aim(adh_static *w);
void static_front_predict(adh_static *w, size_t tgt, double phase, adh_state *x);
int static_front_is_target(const adh_static *w, size_t node);
void static_front_row(adh_static *w, static_row *row);
int static_front_past_end(adh_static *w);
void static_front_accepted(adh_static *w, size_t iters, double q, double q0);
void static_front_qstep_accepted(adh_static *w);
void static_front_clamp(adh_static *w);
int static_front_failed(adh_static *w, int fix);

#endif
