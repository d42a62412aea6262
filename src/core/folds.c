#include "adhere/folds.h"

#include <math.h>
#include <stdlib.h>

struct adh_folds {
    adh_folds_mode mode;
    adh_fold *kept;
    size_t cap, nkept;
    adh_folds_summary sum;
    adh_folds_point last[3]; /* the last three points, [0] the latest */
};

adh_folds *adh_folds_alloc(size_t max_kept)
{
    adh_folds *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->cap = max_kept;
    f->kept = malloc((max_kept ? max_kept : 1) * sizeof *f->kept);
    if (!f->kept) {
        free(f);
        return NULL;
    }
    adh_folds_set(f, ADH_FOLDS_HERMITE);
    return f;
}

void adh_folds_free(adh_folds *f)
{
    if (!f)
        return;
    free(f->kept);
    free(f);
}

void adh_folds_set(adh_folds *f, adh_folds_mode mode)
{
    f->mode = mode;
    f->nkept = 0;
    f->sum = (adh_folds_summary){ .jump_in_h0 = NAN, .jump_out_h0 = NAN, .pulloff_F = INFINITY,
                                  .pulloff_h0 = NAN, .pulloff_F_disp = NAN };
    for (int i = 0; i < 3; i++)
        f->last[i] = (adh_folds_point){ 0 };
}

/* Where the cubic Hermite interpolant on [0,1] (values y0, y1, end slopes
 * m0, m1 per unit t) has its extremum; -1 when none lies inside. */
static double hermite_extremum(double y0, double y1, double m0, double m1)
{
    double a = 6 * y0 + 3 * m0 - 6 * y1 + 3 * m1;
    double b = -6 * y0 - 4 * m0 + 6 * y1 - 2 * m1;
    double c = m0;
    double t = -1;
    if (fabs(a) < 1e-14 * (fabs(b) + fabs(c))) {
        if (b != 0)
            t = -c / b;
    } else {
        double disc = b * b - 4 * a * c;
        if (disc >= 0) {
            double sq = sqrt(disc);
            double qq = -0.5 * (b + (b >= 0 ? sq : -sq));
            double t1 = qq / a, t2 = qq != 0 ? c / qq : -1;
            t = (t1 >= 0 && t1 <= 1) ? t1 : t2;
        }
    }
    if (!(t >= 0 && t <= 1))
        t = m0 / (m0 - m1); /* the slope's linear zero */
    return (t >= 0 && t <= 1) ? t : -1;
}

static double hermite_value(double y0, double y1, double m0, double m1, double t)
{
    double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1;
}

static void fold_add(adh_folds *f, const adh_fold *fd)
{
    adh_folds_summary *r = &f->sum;
    if (r->folds == 0)
        r->jump_in_h0 = fd->kind < 0 ? fd->h0 : NAN;
    if (fd->kind > 0 && (isnan(r->jump_out_h0) || fd->h0 > r->jump_out_h0)) {
        r->jump_out_h0 = fd->h0;
        r->pulloff_F_disp = fd->F;
    }
    if (f->nkept < f->cap)
        f->kept[f->nkept++] = *fd;
    r->folds++;
}

static void pulloff_at(adh_folds *f, double F, double h0)
{
    if (F < f->sum.pulloff_F) {
        f->sum.pulloff_F = F;
        f->sum.pulloff_h0 = h0;
    }
}

/* The new point b against the previous one a: folds (dh0/ds changes
 * sign) and the force's minimum, on the cubic Hermite interpolants over
 * the step (slopes per unit of the step: times its length). */
static void add_hermite(adh_folds *f, const adh_folds_point *a, const adh_folds_point *b)
{
    double len = b->ds;
    double Fa = a->F, Fb = b->F, dFa = a->dF, dFb = b->dF;
    pulloff_at(f, Fb, b->h0);
    if (dFa < 0 && dFb > 0) {
        double t = hermite_extremum(Fa, Fb, dFa * len, dFb * len);
        if (t >= 0)
            pulloff_at(f, hermite_value(Fa, Fb, dFa * len, dFb * len, t),
                       hermite_value(a->h0, b->h0, a->dh0 * len, b->dh0 * len, t));
    }
    if ((a->dh0 < 0) != (b->dh0 < 0)) {
        double m0 = a->dh0 * len, m1 = b->dh0 * len;
        double t = hermite_extremum(a->h0, b->h0, m0, m1);
        if (t < 0)
            t = 0.5;
        adh_fold fd = {
            .h0 = hermite_value(a->h0, b->h0, m0, m1, t),
            .F = hermite_value(Fa, Fb, dFa * len, dFb * len, t),
            .kind = a->dh0 < 0 ? -1 : +1,
        };
        fold_add(f, &fd);
    }
}

/* The parabola through (x0,y0), (x1,y1), (x2,y2) as
 * y = y1 + b (x - x1) + c (x - x1)^2. */
static void parabola(const double *x, const double *y, double *b, double *c)
{
    double d1 = (y[1] - y[0]) / (x[1] - x[0]), d2 = (y[2] - y[1]) / (x[2] - x[1]);
    *c = (d2 - d1) / (x[2] - x[0]);
    *b = d1 + *c * (x[1] - x[0]);
}

static double parabola_at(const double *x, const double *y, double t)
{
    double b, c;
    parabola(x, y, &b, &c);
    return y[1] + b * (t - x[1]) + c * (t - x[1]) * (t - x[1]);
}

/* The parabola's extremum, clamped to [x0, x2]: its abscissa in *xm; the
 * value is returned. */
static double parabola_extremum(const double *x, const double *y, double *xm)
{
    double b, c;
    parabola(x, y, &b, &c);
    double t = c != 0 ? x[1] - b / (2 * c) : x[1];
    *xm = fmin(x[2], fmax(x[0], t));
    return parabola_at(x, y, *xm);
}

/* A fold where h0 turns between the last three points, the minimum where
 * F does, both on the parabolas through them (in s). */
static void add_parabola(adh_folds *f)
{
    double s[3], h[3], F[3], sm;
    for (int i = 0; i < 3; i++) {
        s[i] = f->last[2 - i].s;
        h[i] = f->last[2 - i].h0;
        F[i] = f->last[2 - i].F;
    }
    pulloff_at(f, F[2], h[2]);
    if (f->sum.points < 3)
        return;
    if (F[1] <= F[0] && F[1] <= F[2]) {
        double Fm = parabola_extremum(s, F, &sm);
        pulloff_at(f, Fm, parabola_at(s, h, sm));
    }
    if ((h[1] - h[0]) * (h[2] - h[1]) < 0) {
        adh_fold fd = { .kind = h[1] < h[0] ? -1 : +1 };
        fd.h0 = parabola_extremum(s, h, &sm);
        fd.F = parabola_at(s, F, sm);
        fold_add(f, &fd);
    }
}

void adh_folds_add(adh_folds *f, const adh_folds_point *p)
{
    f->last[2] = f->last[1];
    f->last[1] = f->last[0];
    f->last[0] = *p;
    f->sum.points++;
    if (f->mode == ADH_FOLDS_PARABOLA) {
        add_parabola(f);
    } else if (f->sum.points > 1) {
        add_hermite(f, &f->last[1], &f->last[0]);
    } else {
        f->sum.pulloff_F = p->F;
        f->sum.pulloff_h0 = p->h0;
    }
}

adh_folds_summary adh_folds_summary_of(const adh_folds *f)
{
    return f->sum;
}

size_t adh_folds_kept(const adh_folds *f, const adh_fold **folds)
{
    if (folds)
        *folds = f->kept;
    return f->nkept;
}

adh_folds_point adh_folds_recent(const adh_folds *f, size_t k)
{
    return f->last[k < 3 ? k : 2];
}
