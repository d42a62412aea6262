#include "plot/fitplot.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "plot/session.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* The data file: index 0 approach points, 1 retract points (x, F, resid),
 * then the model's stretches, each stable or not (x, F). Returns the
 * number of model stretches, or -1. */
static int write_data(const adh_fitplot *p, FILE *f, int *stable_of, int cap)
{
    for (int d = 1; d >= -1; d -= 2) {
        int any = 0;
        for (size_t i = 0; i < p->n; i++)
            if (p->dir[i] == d) {
                fprintf(f, "%.9g\t%.9g\t%.9g\n", p->x[i], p->F[i], p->resid[i]);
                any = 1;
            }
        if (!any)   /* an empty block would shift the indices */
            fprintf(f, "nan\tnan\tnan\n");
        fprintf(f, "\n\n");
    }
    int k = 0;
    for (size_t i = 0; i < p->ncurve && k < cap;) {
        size_t j = i;
        while (j + 1 < p->ncurve && p->stable[j + 1] == p->stable[i])
            j++;
        /* each stretch includes the next point, so the line is unbroken */
        size_t end = j + 1 < p->ncurve ? j + 1 : j;
        for (size_t m = i; m <= end; m++)
            fprintf(f, "%.9g\t%.9g\n", p->cx[m], p->cF[m]);
        fprintf(f, "\n\n");
        stable_of[k++] = p->stable[i];
        i = j + 1;
    }
    return ferror(f) ? -1 : k;
}

/* Whether any point (x, F) lies in the key's box: a fraction fw of the
 * frame's width and fh of its height at corner (right, top) of the frame
 * [x0, x1] x [f0, f1]. */
static int corner_holds(const double *x, const double *F, size_t n, double x0, double x1, double f0, double f1,
                        int right, int top)
{
    const double fw = 0.45, fh = 0.3;
    double xa = right ? x1 - fw * (x1 - x0) : x0, xb = right ? x1 : x0 + fw * (x1 - x0);
    double fa = top ? f1 - fh * (f1 - f0) : f0, fb = top ? f1 : f0 + fh * (f1 - f0);
    for (size_t i = 0; i < n; i++)
        if (x[i] >= xa && x[i] <= xb && F[i] >= fa && F[i] <= fb)
            return 1;
    return 0;
}

/* The key in a corner of the force panel where no point and no stretch of
 * the model lies (a force curve's flat tail leaves the lower right empty,
 * most often); where every corner holds data, at the top right on a white
 * box that hides what it covers. */
static const char *key_place(const adh_fitplot *p, double x0, double x1, double f0, double f1)
{
    static const struct { int right, top; const char *where; } corner[] = {
        { 1, 0, "bottom right" }, { 0, 0, "bottom left" }, { 1, 1, "top right" }, { 0, 1, "top left" },
    };
    for (size_t c = 0; c < sizeof corner / sizeof corner[0]; c++)
        if (!corner_holds(p->x, p->F, p->n, x0, x1, f0, f1, corner[c].right, corner[c].top) &&
            !corner_holds(p->cx, p->cF, p->ncurve, x0, x1, f0, f1, corner[c].right, corner[c].top))
            return corner[c].where;
    return "top right opaque";
}

static void commands(const adh_fitplot *p, adh_gnuplot *gp, const char *dat, const int *stable_of, int nk)
{
    double fbig = 0, xlo = INFINITY, xhi = -INFINITY, flo = INFINITY, fhi = -INFINITY;
    for (size_t i = 0; i < p->n; i++) {
        fbig = fmax(fbig, fabs(p->F[i]));
        xlo = fmin(xlo, p->x[i]);
        xhi = fmax(xhi, p->x[i]);
        flo = fmin(flo, p->F[i]);
        fhi = fmax(fhi, p->F[i]);
    }
    double scale, pad = 0.05 * (fhi - flo), xpad = 0.02 * (xhi - xlo), rbig = 0, rscale;
    const char *unit, *runit;
    adh_force_unit(fbig, &scale, &unit);
    /* the residuals in their own unit: a few nN under a curve in uN */
    for (size_t i = 0; i < p->n; i++)
        rbig = isfinite(p->resid[i]) ? fmax(rbig, fabs(p->resid[i])) : rbig;
    adh_force_unit(rbig > 0 ? rbig : fbig, &rscale, &runit);
    char q[ADH_GP_PATH_SIZE], t[ADH_GP_QUOTED_SIZE(512)];
    adh_gp_path(dat, q, sizeof q);
    adh_gnuplot_cmd(gp, "Fu = %.17g", scale);
    adh_gnuplot_cmd(gp, "set multiplot title %s noenhanced", adh_gp_quoted(p->title, t, sizeof t));
    /* one left margin: the panels' x axes line up whatever their tic labels */
    adh_gnuplot_cmd(gp, "set lmargin 11");
    adh_gnuplot_cmd(gp, "set origin 0,0.3");
    adh_gnuplot_cmd(gp, "set size 1,0.63");
    adh_gnuplot_cmd(gp, "set xrange [%.9g:%.9g]", (xlo - xpad) * 1e9, (xhi + xpad) * 1e9);
    adh_gnuplot_cmd(gp, "set yrange [%.9g:%.9g]", (flo - pad) * scale, (fhi + pad) * scale);
    adh_gnuplot_cmd(gp, "set format x ''");
    adh_gnuplot_cmd(gp, "set ylabel \"force F (%s)\"", unit);
    adh_gnuplot_cmd(gp, "set key %s", key_place(p, xlo - xpad, xhi + xpad, flo - pad, fhi + pad));
    adh_gnuplot_cmd(gp, "plot 0 ls 7 notitle, \\");
    adh_gnuplot_cmd(gp, "  %s index 0 using ($1*1e9):($2*Fu) with points pt 6 ps 0.7 lc rgb adh_loading_color "
                        "title \"measured, approach\", \\", q);
    adh_gnuplot_cmd(gp, "  %s index 1 using ($1*1e9):($2*Fu) with points pt 8 ps 0.7 lc rgb word(adh_unload_colors, 1) "
                        "title \"measured, retract\"%s", q, nk ? ", \\" : "");
    for (int k = 0; k < nk; k++)
        adh_gnuplot_cmd(gp, "  %s index %d using ($1*1e9):($2*Fu) with lines lc rgb \"#000000\" lw %s %s%s", q,
                        2 + k, stable_of[k] ? "1.6" : "1 dt 2",
                        k == 0 ? "title \"best model (dashed: unstable)\"" : "notitle", k + 1 < nk ? ", \\" : "");
    adh_gnuplot_cmd(gp, "set origin 0,0");
    adh_gnuplot_cmd(gp, "set size 1,0.32");
    adh_gnuplot_cmd(gp, "unset title");
    adh_gnuplot_cmd(gp, "unset key");
    adh_gnuplot_cmd(gp, "set format x '%%g'");
    adh_gnuplot_cmd(gp, "set autoscale y");
    adh_gnuplot_cmd(gp, "set xlabel \"drive position (nm, measured)\"");
    adh_gnuplot_cmd(gp, "Ru = %.17g", rscale);
    adh_gnuplot_cmd(gp, "set ylabel \"residual (%s)\"", runit);
    adh_gnuplot_cmd(gp, "plot 0 ls 7 notitle, %s index 0 using ($1*1e9):($3*Ru) with points pt 6 ps 0.5 "
                        "lc rgb adh_loading_color notitle, %s index 1 using ($1*1e9):($3*Ru) with points pt 8 ps 0.5 "
                        "lc rgb word(adh_unload_colors, 1) notitle", q, q);
    adh_gnuplot_cmd(gp, "unset multiplot");
}

int adh_fitplot_write(const adh_fitplot *p, adh_outdir *out, const volatile sig_atomic_t *cancel, char *why,
                      size_t whylen)
{
    adh_session ss;
    if (adh_session_open(&ss, out, "gnuplot.log", p->style, cancel, why, whylen) != 0)
        return -1;
    char dat[PATH_MAX + 64];
    int stable_of[512], rc = -1, nk = -1;
    FILE *f = adh_session_data(&ss, "fit.dat", dat, sizeof dat, why, whylen);
    if (f) {
        nk = write_data(p, f, stable_of, 512);
        if (fclose(f) != 0 || nk < 0) {
            snprintf(why, whylen, "cannot write %.3000s: %s", dat, strerror(errno));
            nk = -1;
        }
    }
    if (nk >= 0) {
        adh_session_begin(&ss, "fit", "fit.png");
        commands(p, ss.gp, dat, stable_of, nk);
        rc = adh_session_end(&ss, "fit.png", why, whylen);
    }
    adh_session_close(&ss);
    return rc;
}
