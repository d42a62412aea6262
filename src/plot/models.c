#include "plot/models.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adhere/maugis.h"
#include "plot/tsv.h"

const char *adh_plot_model_name(int k)
{
    static const char *const names[ADH_PLOT_NMODELS] = { "maugis_dugdale", "jkr", "dmt" };
    return k >= 0 && k < ADH_PLOT_NMODELS ? names[k] : "";
}

static void extent(const adh_run *run, double *lo, double *hi)
{
    for (size_t i = 0; run && i < run->nrows; i++) {
        *lo = fmin(*lo, run->rows[i].h0);
        *hi = fmax(*hi, run->rows[i].h0);
    }
}

double adh_plot_models_start(const adh_plot_setup *s, const adh_run *run, const adh_run *ref)
{
    double lo = INFINITY, hi = -INFINITY;
    extent(run, &lo, &hi);
    if (ref && ref->nrows >= 2)   /* as force.png takes a reference */
        extent(ref, &lo, &hi);
    /* the measured points force.png draws: each file's segments */
    for (const adh_measured *m = s->measured; m; m = m->next)
        for (size_t sg = 0; sg < m->nseg; sg++)
            for (size_t i = m->seg[sg].first; i < m->seg[sg].first + m->seg[sg].n; i++) {
                lo = fmin(lo, m->h0[i]);
                hi = fmax(hi, m->h0[i]);
            }
    return hi >= lo ? lo - 0.02 * (hi - lo) : NAN;
}

void adh_plot_models_make(const adh_plot_setup *s, double h0_min, adh_plot_models *m)
{
    for (int k = 0; k < ADH_PLOT_NMODELS; k++)
        m->curve[k].n = m->curve[k].n_load = 0;
    m->lambda = NAN;
    if (s->rigid || !isfinite(h0_min))
        return;
    m->lambda = adh_md_lambda(&s->mat);
    if (adh_md_drive_curve(&s->mat, m->lambda, h0_min, &m->curve[ADH_PLOT_MD]) != 0)
        m->curve[ADH_PLOT_MD].n = 0;
    if (adh_jkr_drive_curve(&s->mat, h0_min, &m->curve[ADH_PLOT_JKR]) != 0)
        m->curve[ADH_PLOT_JKR].n = 0;
    if (adh_dmt_drive_curve(&s->mat, h0_min, &m->curve[ADH_PLOT_DMT]) != 0)
        m->curve[ADH_PLOT_DMT].n = 0;
}

int adh_plot_rigid_point(const adh_obs *o, double *last)
{
    int drawn = o->path == 0 && o->h0 > 0 && isfinite(o->F_rigid) && o->h0 < *last;
    if (o->path == 0)
        *last = o->h0 < *last ? o->h0 : -INFINITY;
    return drawn;
}

typedef struct table {
    const adh_plot_setup *s;
    const adh_run *run;
    const adh_plot_models *m;
} table;

static int models_table(FILE *f, const void *ctx)
{
    const table *t = ctx;
    adh_tsv_preamble(f, t->s, "the model curves beside the run, as force.png draws them");
    fprintf(f, "# h0 = z0 - overlap: the surfaces touch at z0, as in eq 22\n");
    fprintf(f, "# model: jkr; maugis_dugdale (lambda = %.6g); dmt; rigid, eq 22 between rigid spheres at the "
               "run's approach positions before contact\n", t->m->lambda);
    fprintf(f, "# part: load, what a load-controlled contact follows down to its pull-off (the minimum force); "
               "displacement, the rest, which only a displacement-controlled drive reaches (its last point is "
               "the fold); the point between them is in both\n");
    fprintf(f, "# SI units: h0 in m, F in N\n");
    fprintf(f, "model\tpart\th0\tF\n");
    static const int order[ADH_PLOT_NMODELS] = { ADH_PLOT_JKR, ADH_PLOT_MD, ADH_PLOT_DMT };
    for (int j = 0; j < ADH_PLOT_NMODELS; j++) {
        const adh_model_curve *c = &t->m->curve[order[j]];
        for (size_t i = 0; i < c->n; i++) {
            /* the pull-off ends one part and begins the other */
            if (i < c->n_load)
                fprintf(f, "%s\tload\t%.17g\t%.17g\n", adh_plot_model_name(order[j]), c->h0[i], c->F[i]);
            if (i + 1 >= c->n_load && c->n_load < c->n)
                fprintf(f, "%s\tdisplacement\t%.17g\t%.17g\n", adh_plot_model_name(order[j]), c->h0[i], c->F[i]);
        }
    }
    double last = INFINITY;
    for (size_t i = 0; i < t->run->nrows; i++)
        if (adh_plot_rigid_point(&t->run->rows[i], &last))
            fprintf(f, "rigid\t-\t%.17g\t%.17g\n", t->run->rows[i].h0, t->run->rows[i].F_rigid);
    return 0;
}

int adh_tsv_models(const adh_plot_setup *s, const adh_run *run, const adh_run *ref, adh_outdir *out, char *msg,
                   size_t msglen)
{
    adh_plot_models *m = malloc(sizeof *m);
    if (!m) {
        snprintf(msg, msglen, "cannot write %s/models.tsv: out of memory", adh_outdir_path(out));
        return -1;
    }
    adh_plot_models_make(s, adh_plot_models_start(s, run, ref), m);
    table t = { s, run, m };
    int rc = adh_outdir_write(out, "models.tsv", models_table, &t, msg, msglen);
    free(m);
    return rc;
}
