/* force-base.png: the force against the instrument's base, as an AFM or
 * SFA user reads it off the piezo. Under a spring of stiffness k the
 * sphere sits at h0 = base + F/k; where the force's slope reaches k the
 * sphere jumps while the base stands still, so in these coordinates the
 * snaps are vertical segments of length k times the sphere's flight. */
#include "plot/forcebase.h"

#include <limits.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/visco.h"
#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "plot/plot.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

typedef struct fb_point {
    double base, F, h0;
} fb_point;

/* One curve: the approach (path 0), a retraction (path p), or the whole
 * static curve under the others (path -1). */
typedef struct fb_line {
    fb_point *p;
    size_t n, cap;
    int path;
} fb_line;

enum { FB_OTHER, FB_SNAP_IN, FB_SNAP_OUT };

/* A jump at fixed base; to.F NAN: it lands past the static curve's
 * deepest point, where the curve knows no force (to.h0 that point's: the
 * sphere lands deeper, so its force is below k (to.h0 - base)). */
typedef struct fb_jump {
    fb_point from, to;
    int kind;
} fb_jump;

typedef struct fb_fig {
    fb_line *line;
    size_t nline;
    fb_jump *jump;
    size_t njump, capjump;
    double k;  /* the spring */
    int bad;   /* out of memory */
} fb_fig;

int adh_forcebase_wanted(const adh_plot_setup *s)
{
    return s->sprung && isfinite(s->spring) && s->spring > 0 && (s->equilibrium || s->timed);
}

/* Room for one more of n items of size sz in *a (capacity *cap, first
 * first, doubling); 0, or -1 with fg->bad set and *a kept. */
static int room(fb_fig *fg, void **a, size_t *cap, size_t n, size_t sz, size_t first)
{
    if (n < *cap)
        return 0;
    size_t c = *cap ? 2 * *cap : first;
    void *p = realloc(*a, c * sz);
    if (!p) {
        fg->bad = 1;
        return -1;
    }
    *a = p, *cap = c;
    return 0;
}

static void push(fb_fig *fg, fb_line *l, fb_point pt)
{
    void *a = l->p;
    if (room(fg, &a, &l->cap, l->n, sizeof pt, 64) == 0) {
        l->p = a;
        l->p[l->n++] = pt;
    }
}

static void add_jump(fb_fig *fg, fb_jump j)
{
    void *a = fg->jump;
    if (room(fg, &a, &fg->capjump, fg->njump, sizeof j, 8) == 0) {
        fg->jump = a;
        fg->jump[fg->njump++] = j;
    }
}

static void fig_free(fb_fig *fg)
{
    for (size_t i = 0; i < fg->nline; i++)
        free(fg->line[i].p);
    free(fg->line);
    free(fg->jump);
}

/* ------------------------------------------------------- the static curve */

static double base_of(const adh_obs *o, double k)
{
    return o->h0 - o->F / k;
}

static fb_point row_point(const adh_obs *o, double k)
{
    return (fb_point){ base_of(o, k), o->F, o->h0 };
}

/* fold[i]: the fold of the base at row i (the middle of a turning
 * triple) as the core places it between the rows (adh_visco_spring_folds,
 * the very snap points summary.tsv gives), F = k (h0 - base); F NAN where
 * there is none. NULL out of memory. */
static fb_point *static_folds(const adh_run *run, double k)
{
    size_t n = run->nrows;
    fb_point *fold = malloc(n * sizeof *fold);
    double *at = malloc(n * sizeof *at), *base = malloc(n * sizeof *base);
    if (!fold || !at || !base) {
        free(fold), free(at), free(base);
        return NULL;
    }
    size_t nf = adh_visco_spring_folds(run, k, at, base, n), m = 0;
    for (size_t i = 0; i < n; i++) {
        fold[i] = (fb_point){ NAN, NAN, NAN };
        if (i == 0 || i + 1 >= n)
            continue;
        /* the core's test, row for row: its m-th fold is this one */
        const adh_obs *r = &run->rows[i - 1];
        double b0 = base_of(&r[0], k), b1 = base_of(&r[1], k), b2 = base_of(&r[2], k);
        if (r[0].path == r[1].path && r[1].path == r[2].path && (b1 - b0) * (b2 - b1) < 0 && m < nf) {
            fold[i] = (fb_point){ base[m], k * (at[m] - base[m]), at[m] };
            m++;
        }
    }
    free(at), free(base);
    return fold;
}

/* The first row from `from` on (in direction dir) whose base is back at
 * the fold's b, or -1 when the curve ends first. */
static long landing_row(const adh_run *run, double k, long from, int dir, double b)
{
    for (long j = from; j >= 0 && j < (long)run->nrows; j += dir)
        if (dir > 0 ? base_of(&run->rows[j], k) <= b : base_of(&run->rows[j], k) >= b)
            return j;
    return -1;
}

/* The static curve as the base drives it: in from its start (dir +1, the
 * base falling) or out from its deepest point (dir -1, the base rising).
 * At each fold the sphere jumps, at the fold's base, to the curve's next
 * point with that base (linear between its rows). Out past the curve's
 * start the free sphere's force, below the start's (which adhere chose
 * negligible), is drawn as 0. */
static void static_walk(fb_fig *fg, fb_line *l, const adh_run *run, double k, const fb_point *fold, int dir)
{
    long n = (long)run->nrows, i = dir > 0 ? 0 : n - 1;
    size_t first = fg->njump;
    push(fg, l, row_point(&run->rows[i], k));
    for (long next = i + dir; next >= 0 && next < n; next = i + dir) {
        if (!isfinite(fold[next].F)) {
            push(fg, l, row_point(&run->rows[next], k));
            i = next;
            continue;
        }
        fb_jump jp = { .from = fold[next], .kind = FB_OTHER };
        push(fg, l, jp.from);
        long j = landing_row(run, k, next + dir, dir, jp.from.base);
        if (j < 0) {
            jp.to = dir > 0 ? (fb_point){ jp.from.base, NAN, run->rows[n - 1].h0 }
                            : (fb_point){ jp.from.base, 0, jp.from.base };
            if (dir < 0)
                push(fg, l, jp.to);
            add_jump(fg, jp);
            break;
        }
        const adh_obs *a = &run->rows[j - dir], *b = &run->rows[j];
        double ba = base_of(a, k), t = (jp.from.base - ba) / (base_of(b, k) - ba);
        jp.to = (fb_point){ jp.from.base, a->F + t * (b->F - a->F), a->h0 + t * (b->h0 - a->h0) };
        push(fg, l, jp.to);
        add_jump(fg, jp);
        push(fg, l, row_point(b, k));
        i = j;
    }
    /* the first jump in is the snap-in, the last one out the snap-out;
     * the others are the contact line's hops from ring to ring */
    if (fg->njump > first && !fg->bad)
        fg->jump[dir > 0 ? first : fg->njump - 1].kind = dir > 0 ? FB_SNAP_IN : FB_SNAP_OUT;
}

static int static_fig(fb_fig *fg, const adh_run *run, double k)
{
    fg->line = calloc(3, sizeof *fg->line);
    fb_point *fold = fg->line ? static_folds(run, k) : NULL;
    if (!fold)
        return -1;
    fg->nline = 3;
    fg->line[0].path = -1, fg->line[1].path = 0, fg->line[2].path = 1;
    for (size_t i = 0; i < run->nrows; i++)
        push(fg, &fg->line[0], row_point(&run->rows[i], k));
    static_walk(fg, &fg->line[1], run, k, fold, +1);
    static_walk(fg, &fg->line[2], run, k, fold, -1);
    free(fold);
    return fg->bad ? -1 : 0;
}

/* ------------------------------------------------------ in physical time */

/* The rows as they are, a curve per path; a jump is two rows of a path at
 * one time (and so one base) with the sphere moved. The first on loading
 * is the snap-in, the last of each unloading path its snap-out. An
 * elastic sphere's path (its static curve) puts a landing past the curve's
 * end at that end, the base moved with it: drawn as the static figure
 * draws it, the curve broken and an arrow from the fold. */
static int timed_fig(fb_fig *fg, const adh_run *run)
{
    int np = 0;
    for (size_t i = 0; i < run->nrows; i++)
        np = run->rows[i].path > np ? run->rows[i].path : np;
    fg->line = calloc((size_t)np + 1, sizeof *fg->line);
    long *last = malloc(((size_t)np + 1) * sizeof *last);
    if (!fg->line || !last) {
        free(last);
        return -1;
    }
    fg->nline = (size_t)np + 1;
    for (int p = 0; p <= np; p++)
        fg->line[p].path = p, last[p] = -1;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i], *prev = i ? o - 1 : NULL;
        fb_line *l = &fg->line[o->path];
        if (prev && prev->path == o->path && prev->t == o->t && prev->h0 != o->h0) {
            fb_jump jp = { { prev->base, prev->F, prev->h0 }, { o->base, o->F, o->h0 }, FB_OTHER };
            /* moved by more than rounding (base = h0 - F/k from each row) */
            if (fabs(o->base - prev->base) > 1e-6 * fabs(o->h0 - prev->h0)) {
                jp.to = (fb_point){ prev->base, NAN, o->h0 };
                push(fg, l, (fb_point){ NAN, NAN, NAN });   /* a break in the curve */
            }
            jp.kind = o->path == 0 && last[0] < 0 ? FB_SNAP_IN : FB_OTHER;
            add_jump(fg, jp);
            last[o->path] = (long)fg->njump - 1;
        }
        push(fg, l, (fb_point){ o->base, o->F, o->h0 });
    }
    for (int p = 1; p <= np && !fg->bad; p++)
        if (last[p] >= 0)
            fg->jump[last[p]].kind = FB_SNAP_OUT;
    free(last);
    return fg->bad ? -1 : 0;
}

/* ------------------------------------------------------------ the figure */

/* The base axis's unit: nm up to 10 µm, then µm, then mm (a soft
 * spring's snap-out lands F/k out, a millimetre for 1e-3 N/m). */
static void length_unit(double big, double *scale, const char **name)
{
    *scale = big < 1e-5 ? 1e9 : big < 1e-2 ? 1e6 : 1e3;
    *name = big < 1e-5 ? "nm" : big < 1e-2 ? "µm" : "mm";
}

typedef struct fb_frame {
    double blo, bhi, flo, fhi;
} fb_frame;

static void grow(fb_frame *fr, fb_point p)
{
    if (isfinite(p.base))
        fr->blo = fmin(fr->blo, p.base), fr->bhi = fmax(fr->bhi, p.base);
    if (isfinite(p.F))
        fr->flo = fmin(fr->flo, p.F), fr->fhi = fmax(fr->fhi, p.F);
}

/* forcebase.dat: each curve with points, then the snap-in and the
 * snap-out points; idx[] their datasets (-1: none), curves first. */
static int write_data(const fb_fig *fg, FILE *f, int *idx, fb_frame *fr)
{
    int next = 0;
    for (size_t i = 0; i < fg->nline; i++) {
        idx[i] = -1;
        if (fg->line[i].n < 2)
            continue;
        for (size_t j = 0; j < fg->line[i].n; j++) {
            const fb_point *p = &fg->line[i].p[j];
            if (!isfinite(p->base)) {   /* a break: one blank line */
                fputs("\n", f);
                continue;
            }
            fprintf(f, "%.17g\t%.17g\t%.17g\n", p->base, p->F, p->h0);
            grow(fr, *p);
        }
        fputs("\n\n", f);
        idx[i] = next++;
    }
    for (int kind = FB_SNAP_IN; kind <= FB_SNAP_OUT; kind++) {
        int any = 0;
        for (size_t i = 0; i < fg->njump; i++) {
            const fb_jump *jp = &fg->jump[i];
            if (jp->kind != kind)
                continue;
            if (!isfinite(jp->to.F))   /* the arrow's end, in the frame */
                grow(fr, (fb_point){ jp->from.base, fg->k * (jp->to.h0 - jp->from.base), NAN });
            for (int e = 0; e < 2; e++) {
                const fb_point *p = e ? &jp->to : &jp->from;
                if (!isfinite(p->F))
                    continue;
                fprintf(f, "%.17g\t%.17g\t%.17g\n", p->base, p->F, p->h0);
                grow(fr, *p);
                any = 1;
            }
        }
        if (any)
            fputs("\n\n", f);
        idx[fg->nline + (size_t)kind - FB_SNAP_IN] = any ? next++ : -1;
    }
    return ferror(f) ? -1 : 0;
}

/* The turn an unloading path starts from, for its key entry. */
static double turn_h0(const adh_run *run, int path)
{
    for (size_t t = 0; t < run->nturns; t++)
        if (run->turns[t].path == path)
            return run->turns[t].h0;
    return NAN;
}

/* How many drawn retractions begin where line i's does (i's among them):
 * turns a snap passed together (a soft spring's snap-in landing past
 * both) are one turn, the same rows from the same point; in *first
 * whether i is the first of them. 0 for a line that is no retraction. */
static int same_turn(const fb_fig *fg, const adh_run *run, const int *idx, size_t i, int *first)
{
    int p = fg->line[i].path, n = 0;
    double h = p > 0 ? turn_h0(run, p) : NAN;
    *first = 1;
    if (!(p > 0) || idx[i] < 0)
        return 0;
    for (size_t j = 0; j < fg->nline; j++) {
        int q = fg->line[j].path;
        if (j == i || (q > 0 && idx[j] >= 0 && isfinite(h) && turn_h0(run, q) == h)) {
            n++;
            *first &= j >= i;
        }
    }
    return n;
}

/* The key's entries: each curve drawn, a retraction once per turn point. */
static int key_lines(const fb_fig *fg, const adh_run *run, const int *idx)
{
    int n = 0, first;
    for (size_t i = 0; i < fg->nline; i++)
        n += idx[i] >= 0 && (same_turn(fg, run, idx, i, &first) == 0 || first);
    return n;
}

/* The plot command, clause by clause: the static curve under the run, the
 * approach, the retractions, the snap points over them. */
static void plot_clauses(const fb_fig *fg, const adh_run *run, const int *idx, const char *qdat, FILE *c)
{
    fprintf(c, "plot 0 ls 7 notitle");
    int nunload = 0, first;
    for (size_t i = 0; i < fg->nline; i++)
        nunload += fg->line[i].path > 0 && idx[i] >= 0;
    for (size_t i = 0; i < fg->nline; i++) {
        int p = fg->line[i].path, same = same_turn(fg, run, idx, i, &first);
        if (idx[i] < 0 || !first)   /* a turn passed in one snap with an earlier one: its rows drawn already */
            continue;
        fprintf(c, ", \\\n  %s index %d using ($1*Bu):($2*Fu) with lines ", qdat, idx[i]);
        if (p < 0)
            fprintf(c, "lc rgb \"#999999\" lw 1 dt adh_unstable_dash title \"static curve (unstable between folds)\"");
        else if (p == 0)
            fprintf(c, "ls 1 title \"approach\"");
        else if (nunload > 1 && isfinite(turn_h0(run, p)) && same > 1)
            fprintf(c, "lc rgb adh_ucol(%d) lw adh_unloading_width dt adh_udash(%d) title \"retraction from "
                       "h_0 = %.3g nm (%d turns, one snap)\"", p, p, turn_h0(run, p) * 1e9, same);
        else if (nunload > 1 && isfinite(turn_h0(run, p)))
            fprintf(c, "lc rgb adh_ucol(%d) lw adh_unloading_width dt adh_udash(%d) title \"retraction from "
                       "h_0 = %.3g nm\"", p, p, turn_h0(run, p) * 1e9);
        else
            fprintf(c, "lc rgb adh_ucol(%d) lw adh_unloading_width dt adh_udash(%d) title \"retraction\"", p, p);
    }
    if (idx[fg->nline] >= 0)
        fprintf(c, ", \\\n  %s index %d using ($1*Bu):($2*Fu) with points pt 7 ps 1.1 lc rgb adh_loading_color "
                   "title \"snap-in (base still)\"", qdat, idx[fg->nline]);
    if (idx[fg->nline + 1] >= 0)
        fprintf(c, ", \\\n  %s index %d using ($1*Bu):($2*Fu) with points pt 5 ps 1.1 lc rgb adh_ucol(1) "
                   "title \"snap-out (base still)\"", qdat, idx[fg->nline + 1]);
    for (size_t i = 0; i < fg->njump; i++)
        if (!isfinite(fg->jump[i].to.F)) {
            fprintf(c, ", \\\n  keyentry with vectors dt 2 lw 1.5 lc rgb adh_loading_color "
                       "title \"snap-in, past the curve's end\"");
            break;
        }
}

/* Frame, key and the arrows of snaps that land off the curve. */
static void frame(adh_gnuplot *gp, const fb_fig *fg, const fb_frame *fr, int nkey, double bs, const char *bu,
                  double fs, const char *fu)
{
    double db = fr->bhi - fr->blo, lo = fr->flo, hi = fmax(fr->fhi, 0.0), df = hi - lo;
    db = db > 0 ? db : fmax(fabs(fr->blo), 1e-12);
    df = df > 0 ? df : fmax(fabs(lo), 1e-15);
    adh_gnuplot_cmd(gp, "set xlabel \"base (piezo) position (%s)\"", bu);
    adh_gnuplot_cmd(gp, "set ylabel \"force F (%s)\"", fu);
    adh_gnuplot_cmd(gp, "set xrange [%.17g:%.17g]", (fr->blo - 0.02 * db) * bs, (fr->bhi + 0.02 * db) * bs);
    adh_gnuplot_cmd(gp, "set yrange [%.17g:%.17g]", (lo - 0.04 * df) * fs, (hi + 0.04 * df) * fs);
    int rows = (nkey + 1) / 2;   /* two columns: their titles are long */
    adh_gnuplot_cmd(gp, "set key at screen 0.5, screen 0.01 center bottom vertical maxrows %d width -2", rows);
    adh_gnuplot_cmd(gp, "set bmargin %.3g", 4.2 + 1.05 * rows);
    /* a snap past the curve's end: down to the force at which the sphere
     * would sit at the curve's deepest point, a bound on where it lands */
    for (size_t i = 0; i < fg->njump; i++) {
        const fb_jump *jp = &fg->jump[i];
        if (!isfinite(jp->to.F))
            adh_gnuplot_cmd(gp, "set arrow from first %.17g, first %.17g to first %.17g, first %.17g dt 2 lw 1.5 "
                                "lc rgb adh_loading_color", jp->from.base * bs, jp->from.F * fs, jp->from.base * bs,
                            fg->k * (jp->to.h0 - jp->from.base) * fs);
    }
}

static int draw(adh_session *ses, const fb_fig *fg, const adh_run *run, const char *heading, char *why, size_t whylen)
{
    char dat[PATH_MAX + 32], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(ses, "forcebase.dat", dat, sizeof dat, why, whylen);
    if (!f)
        return -1;
    int *idx = malloc((fg->nline + 2) * sizeof *idx);
    if (!idx) {   /* not "no curve to draw": there is one, and no memory */
        fclose(f);
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    fb_frame fr = { INFINITY, -INFINITY, INFINITY, -INFINITY };
    /* a write that failed is said as one, with its reason, before "no
     * curve to draw" (which hid it) */
    errno = 0;
    int err = write_data(fg, f, idx, &fr) != 0 ? (errno ? errno : EIO) : 0;
    if (fclose(f) != 0 && !err)
        err = errno ? errno : EIO;   /* never 0: a failure is never drawn from */
    if (err || !(fr.bhi >= fr.blo)) {
        if (err)
            snprintf(why, whylen, "cannot write %.3000s: %s", dat, strerror(err));
        else
            snprintf(why, whylen, "no curve to draw");
        free(idx);
        return -1;
    }
    double fs, bs;
    const char *fu, *bu;
    adh_force_unit(fmax(fabs(fr.flo), fabs(fr.fhi)), &fs, &fu);
    length_unit(fmax(fabs(fr.blo), fabs(fr.bhi)), &bs, &bu);
    int nkey = key_lines(fg, run, idx);
    for (size_t i = fg->nline; i < fg->nline + 2; i++)
        nkey += idx[i] >= 0;
    for (size_t i = 0; i < fg->njump; i++)
        if (!isfinite(fg->jump[i].to.F)) {
            nkey++;
            break;
        }
    /* the plot command first: a figure once begun is ended (its image
     * checked and its temporary gone) on every path */
    char *cmd = NULL;
    size_t cap = 0;
    FILE *c = open_memstream(&cmd, &cap);
    if (c)
        plot_clauses(fg, run, idx, adh_gp_path(dat, q, sizeof q), c);
    if (!c || fclose(c) != 0) {
        free(cmd);
        free(idx);
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    adh_session_begin(ses, "forcebase", "force-base.png");
    adh_gnuplot *gp = ses->gp;
    adh_gnuplot_cmd(gp, "Fu = %.17g; Bu = %.17g", fs, bs);
    adh_gnuplot_cmd(gp, "set title %s noenhanced", heading);
    adh_plot_branch_styles(gp);
    frame(gp, fg, &fr, nkey, bs, bu, fs, fu);
    adh_gnuplot_cmd(gp, "%s", cmd);
    free(cmd);
    free(idx);
    return adh_session_end(ses, "force-base.png", why, whylen);
}

int adh_forcebase_figure(adh_session *ses, const adh_plot_setup *s, const adh_run *run, const char *heading,
                         char *why, size_t whylen)
{
    fb_fig fg = { .k = s->spring };
    int rc = s->equilibrium ? static_fig(&fg, run, s->spring) : timed_fig(&fg, run);
    if (rc != 0)
        snprintf(why, whylen, "out of memory");
    else
        rc = draw(ses, &fg, run, heading, why, whylen);
    fig_free(&fg);
    return rc;
}
