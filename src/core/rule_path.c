/* An elastic sphere in physical time as a step rule (adhere/rule_path.h):
 * the static curve solved whole at the first step, then the path read off
 * it (adhere/path.h), one row a step. */
#include "adhere/rule_path.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/observe.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "adhere/visco.h"

/* The rows' deformations are kept (as floats: profiles and the state
 * shown) up to this many bytes; past it the path has no profiles. */
#ifndef PATH_U_BYTES   /* (a test sets its own) */
#define PATH_U_BYTES ((size_t)1 << 28)
#endif

typedef struct path_rule {
    const adh_grid *g;
    adh_static *sw;
    adh_path *path;
    adh_material m;
    adh_visco_drive drive;
    adh_protocol_settings ps;
    adh_static_settings ss; /* the curve's settings (its end moves deeper for a landing) */
    adh_run curve;          /* the static curve */
    adh_static_result sres;
    float *u;               /* its rows' deformations, ucap rows; NULL: not kept */
    size_t ucap;
    int keep_u;
    adh_path_curve pc;
    adh_run run;            /* the path's record */
    size_t next;            /* the next row of run to hand out */
    int first;              /* the status of the curve's start */
    int kept_first;         /* the curve's start is among its rows */
    size_t start_row;       /* the start's row: after the curve past a start in
                               contact (past_rows), else 0 */
    int deeper;             /* the solves deeper so far */
    int built, status;      /* the path read off; the curve's final status */
    int brc;                /* the walk's own status once built (ADH_ENOMEM, ADH_EINTR, ...) */
    char why[256];          /* a stop of the path's own (else the curve's) */
} path_rule;

adh_static_settings adh_rule_path_static_settings(double k, const volatile sig_atomic_t *cancel)
{
    adh_static_settings s = adh_static_settings_default();
    s.cancel = cancel;
    if (isfinite(k))
        s.ds_max = fmin(s.ds_max, 0.25);
    return s;
}

static void *path_alloc(const adh_grid *g, const adh_kernel *k)
{
    path_rule *r = calloc(1, sizeof *r);
    if (!r || !(r->sw = adh_static_alloc(g, k)) || !(r->path = adh_path_alloc())) {
        if (r)
            adh_static_free(r->sw);
        free(r);
        return NULL;
    }
    r->g = g;
    adh_run_init(&r->curve);
    adh_run_init(&r->run);
    return r;
}

static void path_free(void *vr)
{
    path_rule *r = vr;
    if (!r)
        return;
    adh_static_free(r->sw);
    adh_path_free(r->path);
    adh_run_free(&r->curve);
    adh_run_free(&r->run);
    free(r->u);
    free(r);
}

static int keep_point(path_rule *r);

/* Whether the surfaces touch at the static curve's present point. */
static int in_contact(const path_rule *r)
{
    return adh_contact_radius(r->g, adh_static_state(r->sw)->h, r->m.z0) > 0;
}

/* A start in contact: the unloading goes on past it until the surfaces
 * part (the protocol's one rule, adhere/drive.h), so the path needs the
 * curve beyond the start too: the curve from the automatic start (out of
 * contact, where the undeformed surfaces are solved at once) down to the
 * start, its rows kept before the start's (its last, the start itself,
 * dropped: the start's own row follows). The walk begins at the start's
 * row (adh_path_curve.start). Where that curve stops short, no rows past
 * the start: the walk ends there, with no pull-off (adhere/path.h). The
 * curve from the start is set again afterwards. ADH_SUCCESS, or
 * ADH_ENOMEM / ADH_EINTR. */
static int past_rows(path_rule *r)
{
    adh_static_settings past = r->ss;
    past.h0_start = adh_protocol_auto_start(&r->m, 0.05e-9);
    past.h0_end = r->ss.h0_start;
    int rc = past.h0_start > past.h0_end ? adh_static_set(r->sw, &r->m, &past) : ADH_EINVAL;
    if (rc == ADH_SUCCESS && (rc = keep_point(r)) == ADH_SUCCESS)
        for (;;) {
            int irc = adh_static_iterate(r->sw);
            if (irc != ADH_CONTINUE && irc != ADH_SUCCESS) {
                rc = irc;
                break;
            }
            if ((rc = keep_point(r)) != ADH_SUCCESS || irc == ADH_SUCCESS)
                break;
        }
    if (rc == ADH_ENOMEM || rc == ADH_EINTR)
        return rc;
    r->start_row = rc == ADH_SUCCESS && r->curve.nrows > 1 ? r->curve.nrows - 1 : 0;
    r->curve.nrows = r->start_row;   /* (the start's own row comes next) */
    return adh_static_set(r->sw, &r->m, &r->ss);
}

/* The curve from its start again, under r->ss: no rows yet. */
static int restart(path_rule *r)
{
    adh_run_free(&r->curve);
    adh_run_init(&r->curve);
    adh_run_free(&r->run);
    adh_run_init(&r->run);
    r->next = 0;
    r->built = 0;
    adh_path_clear(r->path);   /* the summary until the walk: nothing yet, not the last walk's */
    r->kept_first = 0;
    r->brc = ADH_SUCCESS;
    r->start_row = 0;
    int rc = adh_static_set(r->sw, &r->m, &r->ss);
    if (rc == ADH_SUCCESS && in_contact(r))
        rc = past_rows(r);
    r->first = rc == ADH_SUCCESS ? ADH_CONTINUE : rc;
    return rc;
}

static int path_set(void *vr, const adh_material *m, const void *settings, const adh_protocol_settings *ps,
                    double start)
{
    path_rule *r = vr;
    adh_visco_rule_settings vs = settings ? *(const adh_visco_rule_settings *)settings
                                          : adh_visco_rule_settings_default(m->E);
    if (adh_visco_drive_validate(&vs.drive, NULL, 0) != ADH_SUCCESS)
        return ADH_EINVAL;
    adh_static_settings s = adh_rule_path_static_settings(vs.drive.spring, vs.s.cancel);
    /* the drive's automatic start is the elastic one; under a spring the
     * curve starts outside the snap-in, as the static mode's does */
    s.h0_start = isnan(ps->start) && isfinite(vs.drive.spring)
               ? adh_visco_auto_start(m, vs.drive.spring, ps->step) : start;
    if (ps->nturns)
        s.h0_end = adh_protocol_deepest_turn(ps);
    r->m = *m;
    r->drive = vs.drive;
    r->ps = *ps;
    r->ss = s;
    r->keep_u = 1;
    r->deeper = 0;
    int rc = restart(r);
    return rc == ADH_EINVAL ? ADH_EINVAL : ADH_SUCCESS;
}

/* The static curve's present point as a row of the curve, and its
 * deformation. */
static int keep_point(path_rule *r)
{
    const adh_state *st = adh_static_state(r->sw);
    adh_obs o;
    memset(&o, 0, sizeof o);
    adh_observe(r->g, &r->m, st, &o);
    adh_static_point pt = adh_static_current(r->sw);
    o.t = NAN;
    o.iters = pt.newton;
    o.branch = pt.direction;
    o.converged = 1;
    o.stable = pt.stable;
    size_t i = r->curve.nrows, n = r->g->n;
    if (adh_run_push_row(&r->curve, &o) != ADH_SUCCESS)
        return ADH_ENOMEM;
    if (r->keep_u && i >= r->ucap) {
        size_t cap = r->ucap ? 2 * r->ucap : 256;
        float *u = cap * n * sizeof *u <= PATH_U_BYTES ? realloc(r->u, cap * n * sizeof *u) : NULL;
        if (!u) {   /* past the bound (or out of memory): no profiles */
            free(r->u);
            r->u = NULL;
            r->ucap = 0;   /* the next set keeps them again, from a new array */
            r->keep_u = 0;
        } else {
            r->u = u;
            r->ucap = cap;
        }
    }
    for (size_t j = 0; r->keep_u && j < n; j++)
        r->u[i * n + j] = (float)st->u[j];
    return ADH_SUCCESS;
}

/* One point more of the static curve (the first call: its start):
 * ADH_CONTINUE while it goes on, else its final status (ADH_SUCCESS at its
 * end). */
static int curve_point(path_rule *r)
{
    if (!r->kept_first) {
        if (r->first != ADH_CONTINUE)
            return r->first;
        r->kept_first = 1;
        int krc = keep_point(r);
        return krc != ADH_SUCCESS ? krc : ADH_CONTINUE;
    }
    int rc = adh_static_iterate(r->sw);
    if (rc == ADH_CONTINUE || rc == ADH_SUCCESS || rc == ADH_EGRID) {
        int krc = keep_point(r);
        if (krc != ADH_SUCCESS)
            return krc;
    }
    return rc;
}

/* The path read off the curve solved (its final status st). */
static int walk(path_rule *r, int st)
{
    r->status = st;
    if (r->status == ADH_EINTR || r->status == ADH_ENOMEM)
        return r->status;
    const adh_fold *f;
    size_t nf = adh_static_folds(r->sw, &f);
    adh_static_summary(r->sw, &r->sres);
    r->pc = (adh_path_curve){ .rows = r->curve.rows, .n = r->curve.nrows, .u = r->keep_u ? r->u : NULL, .g = r->g,
                              .res = &r->sres, .folds = f, .nfolds = nf, .complete = r->status == ADH_SUCCESS,
                              .start = r->start_row };
    r->built = 1;
    int rc = adh_path_build(r->path, &r->pc, &r->m, &r->drive, &r->ps, &r->run);
    if (rc == ADH_SUCCESS && r->run.nrows)
        r->run.rows[0].seconds = r->sres.seconds;   /* the curve's, solved before the first row */
    return rc;
}


/* The path read off the curve (as far as it went); solved deeper, at
 * most PATH_DEEPER times, where a snap-in lands past its end (a turn short
 * of contact: once into contact, then by the chord there). 1 once the
 * path is built (r->brc its status), 0 when the curve is solved again. */
#define PATH_DEEPER 4
static int walked(path_rule *r, int st)
{
    int rc = walk(r, st);
    double need = adh_path_deeper(r->path);
    if (rc == ADH_SUCCESS && r->status == ADH_SUCCESS && isfinite(need) && r->deeper < PATH_DEEPER) {
        r->deeper++;
        r->ss.h0_end = need;
        if ((rc = restart(r)) == ADH_SUCCESS)
            return 0;
    }
    r->why[0] = '\0';
    if (rc == ADH_SUCCESS && r->status == ADH_SUCCESS && isfinite(adh_path_deeper(r->path))) {
        r->status = ADH_ESTALL;   /* the landing still past the curve: not a finished path */
        snprintf(r->why, sizeof r->why, "the snap-in through the spring lands deeper than h0 = %s, where the static "
                 "curve was solved to", adh_qtext(r->ss.h0_end, ADH_Q_LENGTH).s);
    }
    r->built = 1;
    r->brc = rc;
    return 1;
}

/* The work before the path's first row, max_batch points of the curve at
 * a time (0: all): a driver that reads keys between calls (the TUI) stays
 * responsive while a large grid's curve is solved. ADH_CONTINUE: call
 * again; ADH_SUCCESS: built (next hands out its rows, or its failure). */
static int path_iterate(void *vr, size_t max_batch)
{
    path_rule *r = vr;
    for (size_t n = 0; !r->built && (max_batch == 0 || n < max_batch); n++) {
        int rc = curve_point(r);
        if (rc != ADH_CONTINUE)
            walked(r, rc);
    }
    return r->built ? ADH_SUCCESS : ADH_CONTINUE;
}

static int path_next(void *vr)
{
    path_rule *r = vr;
    path_iterate(r, 0);
    if (r->brc != ADH_SUCCESS)
        return r->brc;
    if (r->next >= r->run.nrows)
        return r->status == ADH_SUCCESS || r->status == ADH_EGRID ? ADH_ESTALL : r->status;
    r->next++;
    if (r->next < r->run.nrows)
        return ADH_CONTINUE;
    /* the last row: the path's end, the grid's edge, or the failure next */
    return r->status == ADH_SUCCESS || r->status == ADH_EGRID ? r->status : ADH_CONTINUE;
}

static double path_jump_in(const void *vr)
{
    const path_rule *r = vr;
    adh_visco_result res;
    adh_path_summary(r->path, r->next, &res);
    return res.jump_in_h0;
}

static void path_observe(const void *vr, adh_obs *o)
{
    const path_rule *r = vr;
    *o = r->run.rows[r->next - 1];
}

static const adh_state *path_state(const void *vr)
{
    const path_rule *r = vr;
    const adh_state *s = r->built && r->next ? adh_path_state(r->path, r->next - 1) : NULL;
    return s ? s : adh_static_state(r->sw);
}

static const char *path_why(const void *vr, unsigned *fix)
{
    const path_rule *r = vr;
    if (r->why[0]) {
        if (fix)
            *fix = 0;
        return r->why;
    }
    return adh_static_why(r->sw, fix);
}

const adh_rule_type adh_rule_path = {
    .name = "path",
    .alloc = path_alloc,
    .free = path_free,
    .set = path_set,
    .iterate = path_iterate,
    .next = path_next,
    .jump_in = path_jump_in,
    .observe = path_observe,
    .state = path_state,
    .why = path_why,
};

const adh_run *adh_rule_path_curve(const adh_drive *d, adh_static_result *res)
{
    const path_rule *r = adh_drive_workspace(d, &adh_rule_path);
    if (!r || !r->built)
        return NULL;
    if (res)
        *res = r->sres;
    return &r->curve;
}

const adh_path *adh_rule_path_walk(const adh_drive *d, size_t *rows)
{
    const path_rule *r = adh_drive_workspace(d, &adh_rule_path);
    if (r && rows)
        *rows = r->next;
    return r ? r->path : NULL;
}

void adh_rule_path_take(adh_drive *d, adh_run *run)
{
    path_rule *r = adh_drive_workspace(d, &adh_rule_path);
    if (r)
        adh_run_take(run, &r->run);
}
