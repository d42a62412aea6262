#include "plot/plotdata.h"
#include "plot/outdir.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "adhere/params.h"
#include "plot/plot.h"

long adh_row_next_on_path(const adh_run *run, size_t i)
{
    for (size_t j = i + 1; j < run->nrows; j++)
        if (run->rows[j].path == run->rows[i].path)
            return (long)j;
    return -1;
}

long adh_row_prev_on_path(const adh_run *run, size_t i)
{
    for (size_t j = i; j-- > 0;)
        if (run->rows[j].path == run->rows[i].path)
            return (long)j;
    return -1;
}

/* Slope between two rows, NAN when either is out of contact or h0 did not
 * move (a dwell leaves h0 fixed: no drive, no defined da/dh0). */
static double slope(const adh_obs *x, const adh_obs *y)
{
    double dh = y->h0 - x->h0;
    if (!(x->a > 0) || !(y->a > 0) || fabs(dh) < 1e-18)
        return NAN;
    return (y->a - x->a) / dh;
}

void adh_contact_speed(const adh_run *run, double drive_speed, double *dadh0, double *dadt)
{
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        long p = adh_row_prev_on_path(run, i), n = adh_row_next_on_path(run, i);
        double d = NAN;
        if (o->a > 0) {
            double back = p >= 0 ? slope(&run->rows[p], o) : NAN;
            double fwd = n >= 0 ? slope(o, &run->rows[n]) : NAN;
            if (!isnan(back) && !isnan(fwd) && p >= 0 && n >= 0) {
                /* the central difference over both neighbours, second order
                 * on a uniform drive and still exact on a non-uniform one */
                d = slope(&run->rows[p], &run->rows[n]);
                if (isnan(d))
                    d = 0.5 * (back + fwd);
            } else {
                d = !isnan(fwd) ? fwd : back;
            }
        }
        dadh0[i] = d;
        /* loading drives h0 down (dh0/dt = -v), unloading up (+v) */
        double dh0dt = (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = d * dh0dt;
    }
}

void adh_contact_speed_smoothed(const adh_run *run, double drive_speed, double dr,
                                double cells, double *dadt)
{
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        dadt[i] = NAN;
        if (!(o->a > 0))
            continue;
        long lo = (long)i, hi = (long)i;
        for (int k = 0; k < 50; k++) {
            long p = adh_row_prev_on_path(run, (size_t)lo);
            long n = adh_row_next_on_path(run, (size_t)hi);
            if (p < 0 || n < 0 || !(run->rows[p].a > 0) || !(run->rows[n].a > 0))
                break;
            lo = p;
            hi = n;
            if (fabs(run->rows[hi].a - run->rows[lo].a) >= cells * dr)
                break;
        }
        if (lo == hi) {
            /* the first or last row of a contact: one step to a neighbour */
            long n = adh_row_next_on_path(run, i), p = adh_row_prev_on_path(run, i);
            if (n >= 0 && run->rows[n].a > 0)
                hi = n;
            else if (p >= 0 && run->rows[p].a > 0)
                lo = p;
            else
                continue;
        }
        /* least-squares slope over the window: its end points sit on hops,
         * so their difference alone would overstate the mean */
        double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
        for (long j = lo; j >= 0; j = (j == hi) ? -1 : adh_row_next_on_path(run, (size_t)j)) {
            double x = run->rows[j].h0 - o->h0, y = run->rows[j].a;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            m += 1;
        }
        double den = m * sxx - sx * sx;
        if (!(fabs(den) > 0))
            continue;
        double dh0dt = (o->branch > 0 ? -1.0 : 1.0) * drive_speed;
        dadt[i] = (m * sxy - sx * sy) / den * dh0dt;
    }
}

double adh_profile_radius(const adh_config *cfg, size_t n)
{
    return ((double)n + 0.5) * adh_config_spacing(cfg);
}

void adh_table_preamble(FILE *f, const adh_config *cfg, const char *what)
{
    adh_derived d;
    adh_material_derive(&cfg->mat, &d);
    fprintf(f, "# adhere: %s\n", what);
    fprintf(f, "# E = %.17g Pa, A = %.17g J, z0 = %.17g m, R = %.17g m\n", cfg->mat.E,
            cfg->mat.A, cfg->mat.z0, cfg->mat.R);
    fprintf(f, "# sigma = %.6g, gamma = %.6g J/m^2, N = %zu, spacing = %.17g m\n", d.sigma,
            d.gamma, cfg->nodes, adh_config_spacing(cfg));
}

typedef struct table_ctx {
    const adh_config *cfg;
    const adh_run *run;
    const double *dadh0, *dadt, *smooth;
} table_ctx;

static int profiles_table(FILE *f, const void *vctx)
{
    const table_ctx *c = vctx;
    const adh_config *cfg = c->cfg;
    const adh_run *run = c->run;
    adh_table_preamble(f, cfg, "surface profiles at the stored drive positions");
    fprintf(f, "# branch +1 loading, -1 unloading; path 0 loading, k the k-th unloading "
               "branch\n");
    for (size_t t = 0; t < run->nturns; t++)
        fprintf(f, "# path %d unloads from the turn at h0 = %.17g m\n", run->turns[t].path,
                run->turns[t].h0);
    fprintf(f, "# h gap, u deformation, p pressure (positive repulsive), "
               "h_sphere = h0 + r^2/(2R) the undeformed gap\n");
    if (run->nprofiles == 0)
        fprintf(f, "# no profiles stored: ask for positions with --profiles=M[,M...]\n");
    fprintf(f, "# SI units: h0, r, h, u, h_sphere in m, p in Pa\n");
    fprintf(f, "h0\tbranch\tpath\tr\th\tu\tp\th_sphere\n");
    for (size_t k = 0; k < run->nprofiles; k++) {
        const adh_profile *pr = &run->profiles[k];
        for (size_t n = 0; n < cfg->nodes; n++) {
            double r = adh_profile_radius(cfg, n);
            fprintf(f, "%.17g\t%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", pr->h0,
                    pr->branch, pr->path, r, pr->h[n], pr->u[n], pr->p[n],
                    pr->h0 + r * r / (2.0 * cfg->mat.R));
        }
    }
    return 0;
}

int adh_write_profiles_table(const adh_config *cfg, const adh_run *run, const char *path,
                             char *msg, size_t msglen)
{
    table_ctx c = { cfg, run, NULL, NULL, NULL };
    return adh_outdir_write(path, profiles_table, &c, msg, msglen);
}

static int contact_table(FILE *f, const void *vctx)
{
    const table_ctx *c = vctx;
    const adh_config *cfg = c->cfg;
    const adh_run *run = c->run;
    adh_table_preamble(f, cfg, "contact radius and contact-line speed");
    fprintf(f, "# in contact where the gap is below %.2g z0; a = 0 out of contact\n",
            ADH_CONTACT_FACTOR);
    fprintf(f, "# drive speed |dh0/dt| = %.17g m/s (h0 falls on loading, rises on "
               "unloading); da_dt = da/dh0 * dh0/dt, positive while the contact spreads, "
               "nan out of contact\n", cfg->drive_speed);
    fprintf(f, "# da_dt_smooth: least-squares slope over the steps in which the contact line crosses "
               "%g grid spacings (it sticks and slips node by node)\n", ADH_SPEED_CELLS);
    fprintf(f, "# SI units: h0, a in m, da_dh0 dimensionless, da_dt and da_dt_smooth in "
               "m/s\n");
    fprintf(f, "h0\tbranch\tpath\ta\tda_dh0\tda_dt\tda_dt_smooth\n");
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        fprintf(f, "%.17g\t%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\n", o->h0, o->branch,
                o->path, o->a, c->dadh0[i], c->dadt[i], c->smooth[i]);
    }
    return 0;
}

int adh_write_contact_table(const adh_config *cfg, const adh_run *run, const char *path,
                            char *msg, size_t msglen)
{
    double *dadh0 = NULL, *dadt = NULL, *smooth = NULL;
    if (run->nrows) {
        dadh0 = malloc(run->nrows * sizeof *dadh0);
        dadt = malloc(run->nrows * sizeof *dadt);
        smooth = malloc(run->nrows * sizeof *smooth);
        if (!dadh0 || !dadt || !smooth) {
            free(dadh0);
            free(dadt);
            free(smooth);
            snprintf(msg, msglen, "cannot write %s: out of memory", path);
            return -1;
        }
        adh_contact_speed(run, cfg->drive_speed, dadh0, dadt);
        adh_contact_speed_smoothed(run, cfg->drive_speed, adh_config_spacing(cfg),
                                   ADH_SPEED_CELLS, smooth);
    }
    table_ctx c = { cfg, run, dadh0, dadt, smooth };
    int rc = adh_outdir_write(path, contact_table, &c, msg, msglen);
    free(dadh0);
    free(dadt);
    free(smooth);
    return rc;
}

size_t adh_plot_default_profiles(const adh_config *cfg, double *out, size_t max)
{
    const adh_protocol_settings *ps = &cfg->proto;
    double step = ps->step;
    if (!(step > 0) || max == 0)
        return 0;
    double start = isnan(ps->start) ? adh_protocol_auto_start(&cfg->mat, step) : ps->start;
    adh_derived d;
    adh_material_derive(&cfg->mat, &d);
    double lo = d.h_star;
    for (size_t i = 0; i < ps->nturns; i++)
        lo = i == 0 || ps->turns[i] < lo ? ps->turns[i] : lo;
    double hi = 0.5 * start;
    if (!(hi > lo))
        hi = start;
    if (!(hi > lo))
        return 0;
    size_t n = 0;
    for (size_t j = 0; j < max; j++) {
        double x = max == 1 ? lo : lo + (hi - lo) * (double)j / (double)(max - 1);
        double k = round((start - x) / step);
        if (k < 0)
            k = 0;
        double h = start - k * step;     /* exactly as the protocol computes it */
        if (j == 0 && ps->nturns)
            h = lo;                       /* turns are hit exactly, on their own */
        if (n == 0 || fabs(out[n - 1] - h) > 0.5 * step)
            out[n++] = h;
    }
    return n;
}
