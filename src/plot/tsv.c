/* The plot module's tables, profiles.tsv and contact.tsv. */
#include "plot/tsv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/models.h"
#include "adhere/params.h"
#include "plot/outdir.h"
#include "plot/speed.h"

/* The comment block each table starts with: material, sigma, gamma, grid. */
void adh_tsv_preamble(FILE *f, const adh_plot_setup *s, const char *what)
{
    adh_derived d;
    adh_material_derive(&s->mat, &d);
    fprintf(f, "# adhere: %s\n", what);
    fprintf(f, "# E = %.17g Pa, A = %.17g J, z0 = %.17g m, R = %.17g m\n", s->mat.E,
            s->mat.A, s->mat.z0, s->mat.R);
    fprintf(f, "# sigma = %.6g, gamma = %.6g J/m^2, N = %zu, spacing = %.17g m\n", d.sigma,
            d.gamma, s->nodes, s->dr);
}

typedef struct table_ctx {
    const adh_plot_setup *s;
    const adh_run *run;
    const double *dadh0, *dadt, *smooth;
} table_ctx;

static int profiles_table(FILE *f, const void *vctx)
{
    const table_ctx *c = vctx;
    const adh_plot_setup *s = c->s;
    const adh_run *run = c->run;
    adh_tsv_preamble(f, s, "surface profiles at the stored drive positions");
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
        for (size_t n = 0; n < s->nodes; n++) {
            double r = adh_plot_setup_radius(s, n);
            fprintf(f, "%.17g\t%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", pr->h0,
                    pr->branch, pr->path, r, pr->h[n], pr->u[n], pr->p[n],
                    pr->h0 + r * r / (2.0 * s->mat.R));
        }
    }
    return 0;
}

int adh_tsv_profiles(const adh_plot_setup *s, const adh_run *run, adh_outdir *out, char *msg, size_t msglen)
{
    table_ctx c = { s, run, NULL, NULL, NULL };
    return adh_outdir_write(out, "profiles.tsv", profiles_table, &c, msg, msglen);
}

static int contact_table(FILE *f, const void *vctx)
{
    const table_ctx *c = vctx;
    const adh_plot_setup *s = c->s;
    const adh_run *run = c->run;
    adh_tsv_preamble(f, s, "contact radius and contact-line speed");
    fprintf(f, "# in contact where the gap is below %.2g z0; a = 0 out of contact\n",
            ADH_CONTACT_FACTOR);
    if (s->timed)
        fprintf(f, "# physical time: da_dt the central difference in t, positive while the contact spreads, "
                   "nan out of contact (the base moves at %.17g m/s when retracting)\n", s->drive_speed);
    else
        fprintf(f, "# drive speed |dh0/dt| = %.17g m/s (h0 falls on loading, rises on "
                   "unloading); da_dt = da/dh0 * dh0/dt, positive while the contact spreads, "
                   "nan out of contact\n", s->drive_speed);
    fprintf(f, "# da_dt_smooth: least-squares slope over the steps in which the contact line crosses "
               "%g grid spacings (it sticks and slips node by node)\n", ADH_SPEED_CELLS);
    if (s->equilibrium)
        fprintf(f, "# the static equilibrium curve: nothing moves along it in time, so da_dt and da_dt_smooth "
                   "are nan; da_dh0 is its slope (infinite at its folds)\n");
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

int adh_tsv_contact(const adh_plot_setup *s, const adh_run *run, adh_outdir *out, char *msg, size_t msglen)
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
            snprintf(msg, msglen, "cannot write %s/contact.tsv: out of memory", adh_outdir_path(out));
            return -1;
        }
        adh_speed_stepwise(run, s->drive_speed, dadh0, dadt);
        adh_speed_smoothed(run, s->drive_speed, s->dr, ADH_SPEED_CELLS, smooth);
        for (size_t i = 0; s->equilibrium && i < run->nrows; i++)
            dadt[i] = smooth[i] = NAN;
    }
    table_ctx c = { s, run, dadh0, dadt, smooth };
    int rc = adh_outdir_write(out, "contact.tsv", contact_table, &c, msg, msglen);
    free(dadh0);
    free(dadt);
    free(smooth);
    return rc;
}
