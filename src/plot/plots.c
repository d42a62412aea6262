/* The three figures (force.png, profile.png, contact.png) as gnuplot
 * commands over temporary data files, and adh_plots_write tying tables,
 * style and gnuplot process together. */
#include "plot/plot.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/maugis.h"
#include "adhere/models.h"
#include "adhere/params.h"
#include "plot/axes.h"
#include "plot/forcebase.h"
#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "plot/models.h"
#include "plot/outdir.h"
#include "scene/text.h"
#include "plot/png.h"
#include "plot/session.h"
#include "plot/speed.h"
#include "adhere/units.h"
#include "plot/tsv.h"
#include "scene/measured.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#define MAX_LABELLED_UNLOADS 8

typedef struct plotter {
    const adh_plot_setup *s;
    const adh_run *run;
    const adh_run *ref;       /* the static equilibrium beside a relaxation run, or NULL */
    adh_outdir *out;
    adh_session ses;          /* gnuplot, its style, data files and images */
    adh_gnuplot *gp;          /* ses.gp */
    adh_derived d;
    char done[512];           /* files written, for msg */
    char notes[512];          /* figures skipped for lack of data */
    unsigned written;         /* ADH_PLOT_* bits of the figures in place */
    unsigned skipped;         /* ... and of those skipped for lack of data */
    int base_done;            /* force-base.png in place, or skipped with force.png */
    char error[1024];         /* the first gnuplot failure */
} plotter;

/* A scene title makes a two-line heading, which needs more room above. */
static int has_title(const plotter *pl)
{
    return pl->s->title && pl->s->title[0];
}

/* 1, 2 or 5 times a power of ten, at least x */
static double nice_step(double x)
{
    double p = pow(10.0, floor(log10(x)));
    return x <= p ? p : x <= 2 * p ? 2 * p : x <= 5 * p ? 5 * p : 10 * p;
}

/* The nice step (1, 2, 5 times a power of ten) just below step. */
static double nice_below(double step)
{
    double p = pow(10.0, floor(log10(step) + 1e-9)), m = step / p;
    return m > 4.5 ? 2 * p : m > 1.5 ? p : 0.5 * p;
}

/* A length with a prefix chosen for it, e.g. "10 µm", "1.5 cm". */
static void format_length(double v, char *buf, size_t len)
{
    double a = fabs(v);
    if (a >= 1e-2)
        snprintf(buf, len, "%.3g cm", v * 1e2);
    else if (a >= 1e-3)
        snprintf(buf, len, "%.3g mm", v * 1e3);
    else if (a >= 1e-6)
        snprintf(buf, len, "%.3g µm", v * 1e6);
    else
        snprintf(buf, len, "%.3g nm", v * 1e9);
}

/* A speed as the headings write it: adh_qtext's with µ, not its ASCII u
 * ("1 µm/s"). */
static void speed_text(double v, char *buf, size_t len)
{
    adh_qtext_buf q = adh_qtext(v, ADH_Q_SPEED);
    const char *u = strstr(q.s, "um/s");
    if (u)
        snprintf(buf, len, "%.*sµm/s%s", (int)(u - q.s), q.s, u + 4);
    else
        snprintf(buf, len, "%s", q.s);
}

/* A figure title as a gnuplot string expression (adh_gp_quote: the scene
 * title is user text), drawn noenhanced so its _ ^ { } @ & ~ print as
 * themselves: the scene title (if any) on its own line, then what the
 * figure is with sigma, gamma, R, E. */
#define HEADING_SIZE ADH_GP_QUOTED_SIZE(1024)
static void title_string(const plotter *pl, const char *what, char *buf, size_t len)
{
    char r[32], e[32], text[1024], scene[300];
    format_length(pl->s->mat.R, r, sizeof r);
    adh_format_modulus(pl->s->mat.E, e, sizeof e);
    /* The scene title names the scene's own figure (Figure 4's profiles);
     * its other PNGs carry only its label ("Figure 4 scene"), or force.png
     * would be titled "profiles on approach and retraction". The scene's
     * figure is the most specific plot it asks for. */
    unsigned want = pl->s->figures;
    int own = !strcmp(what, "Surface profiles") ? 1
            : !strncmp(what, "Contact", 7) ? !(want & ADH_PLOT_PROFILE)
            : !(want & (ADH_PLOT_PROFILE | ADH_PLOT_CONTACT));
    char title[256];   /* a scene title's length, as scene files allow */
    snprintf(title, sizeof title, "%s", has_title(pl) ? pl->s->title : "");
    const char *colon = strchr(title, ':');
    if (own || !colon)
        snprintf(scene, sizeof scene, "%s", title);
    else
        snprintf(scene, sizeof scene, "%.*s scene", (int)(colon - title), title);
    if (isfinite(pl->s->Einf)) {   /* a standard linear solid: sigma is E0's */
        char ei[32], tau[32];
        adh_format_modulus(pl->s->Einf, ei, sizeof ei);
        adh_format_quantity(pl->s->tau, ADH_Q_TIME, 3, tau, sizeof tau);
        snprintf(text, sizeof text, "%s%s%s: σ0 = %.3g, R = %s, E0 = %s, E∞ = %s, τ = %s",
                 scene, scene[0] ? "\n" : "", what, pl->d.sigma, r, e, ei, tau);
    } else {
        snprintf(text, sizeof text, "%s%s%s: σ = %.3g, γ = %.3g mJ/m², R = %s, E = %s",
                 scene, scene[0] ? "\n" : "", what, pl->d.sigma, pl->d.gamma * 1e3, r, e);
    }
    adh_gp_quote(text, buf, len);
}

static const adh_turn_result *turn_of_path(const adh_run *run, int path)
{
    for (size_t t = 0; t < run->nturns; t++)
        if (run->turns[t].path == path)
            return &run->turns[t];
    return NULL;
}

static int max_path(const adh_run *run)
{
    int m = 0;
    for (size_t i = 0; i < run->nrows; i++)
        if (run->rows[i].path > m)
            m = run->rows[i].path;
    return m;
}

static FILE *data_file(plotter *pl, const char *name, char *path, size_t len)
{
    char why[PATH_MAX + 128];
    FILE *f = adh_session_data(&pl->ses, name, path, len, why, sizeof why);
    if (!f)
        adh_text_catf(pl->error, sizeof pl->error, "%s%s", *pl->error ? "; " : "", why);
    return f;
}

static int data_close(plotter *pl, FILE *f, const char *path)
{
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        adh_text_catf(pl->error, sizeof pl->error, "%scannot write %s", *pl->error ? "; " : "", path);
        return -1;
    }
    return 0;
}

/* gnuplot merges runs of blank lines, so an empty dataset would shift every
 * later `index`: each set is collected apart and only non-empty ones are
 * written, each getting the next index. */
typedef struct datafile {
    FILE *f;          /* the file gnuplot reads */
    FILE *cur;        /* the set being collected */
    char *buf;
    size_t buflen, points;
    int nsets, broken, bad;
} datafile;

static int set_begin(datafile *df)
{
    df->buf = NULL;
    df->buflen = 0;
    df->points = 0;
    df->broken = 1;
    df->cur = open_memstream(&df->buf, &df->buflen);
    if (!df->cur)
        df->bad = 1;
    return df->cur ? 0 : -1;
}

static void set_point(datafile *df, double x, double y)
{
    if (!df->cur)
        return;
    fprintf(df->cur, "%.17g\t%.17g\n", x, y);
    df->points++;
    df->broken = 0;
}

/* A single blank line: the curve is broken here but the set goes on. */
static void set_break(datafile *df)
{
    if (df->cur && !df->broken)
        fputs("\n", df->cur);
    df->broken = 1;
}

/* The set's index, or -1 when it had no points (and was not written). */
static int set_end(datafile *df)
{
    if (!df->cur)
        return -1;
    fclose(df->cur);
    df->cur = NULL;
    int idx = -1;
    if (df->points > 0) {
        if (fwrite(df->buf, 1, df->buflen, df->f) != df->buflen)
            df->bad = 1;
        fputs("\n\n", df->f);
        idx = df->nsets++;
    }
    free(df->buf);
    df->buf = NULL;
    return idx;
}

/* The key entry of an unloading branch: its turn, or one entry for them all
 * when there are too many to label one by one. */
static void unload_title(const adh_turn_result *tr, int nunload, int *labelled, char *title, size_t len)
{
    if (nunload > MAX_LABELLED_UNLOADS)
        snprintf(title, len, (*labelled)++ ? "notitle" : "title \"unloading (%d branches)\"", nunload);
    else if (tr)
        snprintf(title, len, "title \"unloading from %.3g nm\"", tr->h0 * 1e9);
    else
        snprintf(title, len, "title \"unloading\"");
}

static void begin_figure(plotter *pl, const char *figure, const char *name)
{
    adh_session_begin(&pl->ses, figure, name);
}

/* The figure into place, or its failure remembered for msg. */
static int finish_figure(plotter *pl, const char *name)
{
    char why[1024];
    if (adh_session_end(&pl->ses, name, why, sizeof why) != 0) {
        if (!*pl->error)
            snprintf(pl->error, sizeof pl->error, "%s: %.960s", name, why);
        return -1;
    }
    adh_text_catf(pl->done, sizeof pl->done, "%s%s", *pl->done ? ", " : "", name);
    pl->written |= !strcmp(name, "force.png") ? ADH_PLOT_FORCE
                 : !strcmp(name, "profile.png") ? ADH_PLOT_PROFILE : ADH_PLOT_CONTACT;
    return 0;
}

/* ---------------------------------------------------------------- force */

/* One dataset: h0 and the force (radius: the contact radius) of the rows
 * of path whose stability is `stable`, plus the row after each such
 * stretch so dashed and solid stretches meet; a blank line breaks the
 * curve between stretches. Returns its index or -1 if empty. */
static int write_stability_set(datafile *df, const adh_run *run, int path, int stable, int radius)
{
    int prev_stable = -1;
    if (set_begin(df) < 0)
        return -1;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        if (o->path != path)
            continue;
        if (o->stable == stable || prev_stable == stable)
            set_point(df, o->h0, radius ? o->a : o->F);
        else
            set_break(df);
        prev_stable = o->stable;
    }
    return set_end(df);
}

/* A model curve as two datasets: its load-controlled part, and the part
 * past the pull-off that only displacement control reaches (they share the
 * pull-off point, so the change of dash marks the break). */
typedef struct model_sets {
    int load, disp;     /* dataset indices, -1 when empty */
} model_sets;

static model_sets write_model_sets(datafile *df, const adh_model_curve *c)
{
    model_sets ms = { -1, -1 };
    set_begin(df);
    for (size_t i = 0; i < c->n_load; i++)
        set_point(df, c->h0[i], c->F[i]);
    ms.load = df->points > 1 ? set_end(df) : (set_end(df), -1);
    set_begin(df);
    for (size_t i = c->n_load ? c->n_load - 1 : 0; i < c->n; i++)
        set_point(df, c->h0[i], c->F[i]);
    ms.disp = df->points > 1 ? set_end(df) : (set_end(df), -1);
    return ms;
}

static void unload_color(int path, char *buf, size_t len)
{
    snprintf(buf, len, "lc rgb adh_ucol(%d)", path);
}

/* What force.png is drawn from, gathered step by step. */
typedef struct force_fig {
    char dat[PATH_MAX + 32];       /* force.dat: every curve, one dataset each */
    char adh[PATH_MAX + 32];       /* adhesion.dat: adhesion against maximum load */
    int np;                        /* the highest path */
    int *set;                      /* set[2k + (1 - stable)]: path k's stable / unstable rows */
    int rigid_set, ref_set[2];
    int meas_set[2 * ADH_MEASURED_MAX_FILES];   /* --data: file f's approach [2f], retract [2f + 1] */
    const adh_measured *meas_file[ADH_MEASURED_MAX_FILES];
    int nmeas;
    const adh_run *ref;            /* --reference=static, NULL */
    model_sets jkr, dmt, md;
    double md_lambda;
    int models, any_disp;          /* a model curve was written; one has a part past its pull-off */
    double flo, fhi, xmin, xmax, xpad;
    size_t nadh, order[ADH_MAX_TURNS];   /* turns with an adhesion, in load order */
    double fscale;
    const char *funit;
    int nunload;                   /* unloading branches drawn */
    double lo, hi;                 /* the force axis */
    double xright;                 /* the position axis's right end, m */
    int panel;                     /* the adhesion panel beside it (two turns or more) */
    int keyrows;                   /* the key's rows, three entries a row, under both panels */
    double bmargin;                /* both panels' bottom margin, character heights: the key's room */
} force_fig;

static void force_grow(force_fig *ff, double h0, double F)
{
    ff->flo = fmin(ff->flo, F);
    ff->fhi = fmax(ff->fhi, F);
    ff->xmin = fmin(ff->xmin, h0);
    ff->xmax = fmax(ff->xmax, h0);
}

/* The computed curves: the run's paths, eq 22 before contact, the static
 * reference, the measured points; the frame grows round them. */
static void force_curves(plotter *pl, force_fig *ff, datafile *df)
{
    const adh_run *run = pl->run;
    for (int p = 0; p <= ff->np; p++)
        for (int s = 1; s >= 0; s--)
            ff->set[2 * p + (1 - s)] = write_stability_set(df, run, p, s, 0);
    set_begin(df);
    double last = INFINITY;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        force_grow(ff, o->h0, o->F);
        if (adh_plot_rigid_point(o, &last))
            set_point(df, o->h0, o->F_rigid);
    }
    ff->rigid_set = df->points > 1 ? set_end(df) : (set_end(df), -1);
    /* --reference=static: the equilibrium curve (its path 0), stable and
     * unstable stretches, a computed curve like the run's own */
    ff->ref = pl->ref && pl->ref->nrows >= 2 ? pl->ref : NULL;
    ff->ref_set[0] = ff->ref_set[1] = -1;
    if (ff->ref) {
        for (int s = 1; s >= 0; s--)
            ff->ref_set[1 - s] = write_stability_set(df, ff->ref, 0, s, 0);
        for (size_t i = 0; i < ff->ref->nrows; i++)
            force_grow(ff, ff->ref->rows[i].h0, ff->ref->rows[i].F);
    }
    /* --data: the user's measurements, points over the model, in the
     * frame: each file's approach and retract apart */
    ff->nmeas = 0;
    for (const adh_measured *m = pl->s->measured; m && ff->nmeas < ADH_MEASURED_MAX_FILES; m = m->next) {
        ff->meas_file[ff->nmeas] = m;
        for (int r = 0; r < 2; r++) {
            set_begin(df);
            for (size_t sg = 0; sg < m->nseg; sg++) {
                const adh_measured_segment *seg = &m->seg[sg];
                if ((seg->dir < 0) != r)
                    continue;
                for (size_t i = seg->first; i < seg->first + seg->n; i++) {
                    set_point(df, m->h0[i], m->F[i]);
                    force_grow(ff, m->h0[i], m->F[i]);
                }
            }
            ff->meas_set[2 * ff->nmeas + r] = df->points ? set_end(df) : (set_end(df), -1);
        }
        ff->nmeas++;
    }
}

/* The models for comparison (not for rigid spheres, where E means
 * nothing), each over the whole width of the frame. -1 out of memory. */
static int force_models(plotter *pl, force_fig *ff, datafile *df)
{
    adh_plot_models *m = malloc(sizeof *m);
    if (!m)
        return -1;
    /* the curves of models.tsv: they start where force.png's frame does */
    adh_plot_models_make(pl->s, ff->xmin - ff->xpad, m);
    ff->jkr = write_model_sets(df, &m->curve[ADH_PLOT_JKR]);
    ff->md = write_model_sets(df, &m->curve[ADH_PLOT_MD]);
    ff->dmt = write_model_sets(df, &m->curve[ADH_PLOT_DMT]);
    ff->md_lambda = m->lambda;
    free(m);
    ff->models = ff->jkr.load >= 0 || ff->jkr.disp >= 0 || ff->md.load >= 0 || ff->md.disp >= 0 ||
                 ff->dmt.load >= 0 || ff->dmt.disp >= 0;
    ff->any_disp = ff->jkr.disp >= 0 || ff->md.disp >= 0 || ff->dmt.disp >= 0;
    return 0;
}

static double force_active_right(const plotter *pl, const force_fig *ff, double span, double xmax);

/* The position axis's label: through a spring h0 is where the sphere is,
 * not where the instrument drives (the base, in force.tsv beside it). */
static void position_label(plotter *pl)
{
    adh_gnuplot_cmd(pl->gp, "set xlabel \"%s position h_0 (nm)\"", pl->s->sprung ? "sphere" : "drive");
}

/* The force axis before its margins: the curves and the deepest model
 * pull-off (the rigid spheres' alone: their own). */
static void force_span(const plotter *pl, const force_fig *ff, double *lo, double *hi)
{
    *lo = fmin(ff->flo, pl->s->rigid ? ff->flo : pl->d.F_dmt);
    *hi = fmax(ff->fhi, 0.0);
}

/* force.dat: every curve of the figure. The position axis's margin is a
 * fiftieth of the rows' span, or of the part where the force acts when
 * that is under a tenth of it: a soft spring's snap-out lands where the
 * base is, a millimetre out, and its margin alone hid the contact. */
static int force_data(plotter *pl, force_fig *ff)
{
    FILE *f = data_file(pl, "force.dat", ff->dat, sizeof ff->dat);
    if (!f)
        return -1;
    datafile df = { .f = f };
    ff->flo = ff->xmin = INFINITY;
    ff->fhi = ff->xmax = -INFINITY;
    force_curves(pl, ff, &df);
    ff->xpad = 0.02 * (ff->xmax - ff->xmin);
    double lo, hi;
    force_span(pl, ff, &lo, &hi);
    double right = force_active_right(pl, ff, hi - lo, ff->xmax + ff->xpad);
    if (right - ff->xmin < 0.1 * (ff->xmax - ff->xmin))
        ff->xpad = 0.02 * (right - ff->xmin);
    if (force_models(pl, ff, &df) != 0) {
        fclose(f);
        return -1;
    }
    return data_close(pl, f, ff->dat) < 0 || df.bad ? -1 : 0;
}

/* adhesion.dat: adhesion against maximum load, one point per turn, in
 * load order. */
static int adhesion_data(plotter *pl, force_fig *ff)
{
    const adh_run *run = pl->run;
    FILE *f = data_file(pl, "adhesion.dat", ff->adh, sizeof ff->adh);
    if (!f)
        return -1;
    size_t *order = ff->order, n = 0;
    for (size_t t = 0; t < run->nturns; t++)
        if (isfinite(run->turns[t].pulloff_F) && isfinite(run->turns[t].max_load))
            order[n++] = t;
    for (size_t a = 1; a < n; a++)
        for (size_t b = a; b > 0 && run->turns[order[b]].max_load <
                                    run->turns[order[b - 1]].max_load; b--) {
            size_t x = order[b];
            order[b] = order[b - 1];
            order[b - 1] = x;
        }
    for (size_t k = 0; k < n; k++)
        fprintf(f, "%.17g\t%.17g\n", run->turns[order[k]].max_load, -run->turns[order[k]].pulloff_F);
    ff->nadh = n;
    return data_close(pl, f, ff->adh) < 0 ? -1 : 0;
}


/* The largest h0 of run's rows, or active, at which |F| reaches 1 % of
 * span: where its curves have not yet flattened to zero. */
static double rows_active(const adh_run *run, double span, double active)
{
    for (size_t i = 0; run && i < run->nrows; i++)
        if (fabs(run->rows[i].F) >= 0.01 * span && run->rows[i].h0 > active)
            active = run->rows[i].h0;
    return active;
}

/* The position axis's right end: past the last h0 where the run's or the
 * reference's force reaches 1 % of span, or a measured point, by a
 * margin, and never past xmax. */
static double force_active_right(const plotter *pl, const force_fig *ff, double span, double xmax)
{
    /* the measured points are data too: the frame keeps them whole */
    double active = rows_active(ff->ref, span, rows_active(pl->run, span, ff->xmin));
    for (const adh_measured *m = pl->s->measured; m; m = m->next)
        for (size_t i = 0; i < m->n; i++)
            active = fmax(active, m->h0[i]);
    return adh_plot_active_right(active, ff->xmin, xmax);
}

/* The force axis: its unit and a range round the computed curves and the
 * deepest model pull-off (the key sits below the frame: no room is kept
 * for it); the position axis to where the curves have flattened. The rigid
 * force, which shoots up near h0 = z0, runs off the top: it is only a
 * reference. */
static void force_frame(plotter *pl, force_fig *ff)
{
    const adh_derived *d = &pl->d;
    double big = fmax(fabs(ff->flo), fmax(fabs(ff->fhi), fabs(d->F_dmt)));
    adh_force_unit(big, &ff->fscale, &ff->funit);
    ff->nunload = 0;
    for (int p = 1; p <= ff->np; p++)
        ff->nunload += ff->set[2 * p] >= 0 || ff->set[2 * p + 1] >= 0;
    double lo, hi;
    force_span(pl, ff, &lo, &hi);
    double span = hi - lo;
    lo -= 0.04 * span;
    hi += 0.04 * span;
    ff->lo = lo;
    ff->hi = hi;
    ff->xright = force_active_right(pl, ff, span, ff->xmax + ff->xpad);
    /* the key below, in up to three columns: the tics, the label and its rows */
    int nmodel = ff->models ? (ff->jkr.load >= 0 || ff->jkr.disp >= 0) + (ff->md.load >= 0 || ff->md.disp >= 0) +
                              (ff->dmt.load >= 0 || ff->dmt.disp >= 0) + ff->any_disp
                            : 2;
    int nmeas_sets = 0;
    for (int i = 0; i < 2 * ff->nmeas; i++)
        nmeas_sets += ff->meas_set[i] >= 0;
    int nkey = (ff->set[0] >= 0) + (ff->set[1] >= 0) + (ff->rigid_set >= 0) + nmodel + nmeas_sets +
               (ff->ref_set[0] >= 0 || ff->ref_set[1] >= 0) + ff->panel +
               (ff->nunload > MAX_LABELLED_UNLOADS ? 1 : ff->nunload);
    ff->keyrows = (nkey + 2) / 3;
    ff->bmargin = 4.2 + 1.05 * ff->keyrows;
}

/* The style and key title of path p's stretch (stable or not). */
static void run_clause_style(plotter *pl, const force_fig *ff, int p, int stable, int *labelled, char *style,
                             size_t slen, char *title, size_t tlen)
{
    if (p == 0) {
        snprintf(style, slen, "ls 1%s", stable ? "" : " lw 1.2 dt adh_unstable_dash");
        /* the static mode's path 0 is the whole equilibrium curve */
        if (pl->s->equilibrium)
            snprintf(title, tlen, "title \"%s\"", stable ? "static equilibrium" : "unstable (displacement control)");
        else
            snprintf(title, tlen, "title \"loading%s\"", stable ? "" : " (unstable)");
        return;
    }
    char lc[128];
    unload_color(p, lc, sizeof lc);
    if (stable)
        snprintf(style, slen, "%s lw adh_unloading_width dt adh_udash(%d)", lc, p);
    else
        snprintf(style, slen, "%s lw 1 dt adh_unstable_dash", lc);
    if (!stable)
        snprintf(title, tlen, "notitle");
    else
        unload_title(turn_of_path(pl->run, p), ff->nunload, labelled, title, tlen);
}

/* The plot command's curves: the static reference underneath (its
 * unstable stretches dashed), then the run's paths. */
static void force_run_clauses(plotter *pl, const force_fig *ff, FILE *c, const char *qdat)
{
    for (int s = 1; s >= 0; s--)
        if (ff->ref_set[1 - s] >= 0)
            fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with lines ls 9%s notitle", qdat,
                    ff->ref_set[1 - s], s ? "" : " lw 0.8 dt adh_unstable_dash");
    int labelled = 0;
    for (int p = 0; p <= ff->np; p++) {
        for (int s = 1; s >= 0; s--) {
            int idx = ff->set[2 * p + (1 - s)];
            if (idx < 0)
                continue;
            char style[200], title[160];   /* style: a colour, its width and dash: never cut */
            run_clause_style(pl, ff, p, s, &labelled, style, sizeof style, title, sizeof title);
            fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with lines %s %s", qdat,
                    idx, style, title);
        }
    }
}

/* The model curves, the load-controlled part in the model's line and the
 * part past the pull-off in the same dash, thin and grey. Maugis-Dugdale
 * is a grey band under the others: where it and JKR agree (lambda above
 * 3) JKR's dashes show on it. */
static const struct { int ls; const char *name; } model_line[3] = { { 8, "md" }, { 3, "jkr" }, { 4, "dmt" } };

static const model_sets *model_of(const force_fig *ff, int k)
{
    return k == 0 ? &ff->md : k == 1 ? &ff->jkr : &ff->dmt;
}

static void force_model_clauses(const force_fig *ff, FILE *c, const char *qdat, int band)
{
    for (int k = 0; k < 3; k++) {
        const model_sets *ms = model_of(ff, k);
        if ((k == 0) != band)
            continue;
        if (ms->load >= 0)
            fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with lines ls %d notitle", qdat, ms->load,
                    model_line[k].ls);
        if (ms->disp >= 0)
            fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with lines ls %d lc rgb adh_model_disp_color "
                       "lw %s notitle", qdat, ms->disp, model_line[k].ls, k == 0 ? "2" : "1");
    }
}

/* The references over the run and the key's entries for them: eq 22, the
 * measured points, the models. Their key entries come after the run's. */
static void force_reference_clauses(plotter *pl, const force_fig *ff, FILE *c, const char *qdat)
{
    const adh_derived *d = &pl->d;
    force_model_clauses(ff, c, qdat, 0);
    if (ff->rigid_set >= 0)
        fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with lines ls 2 "
                   "title \"rigid spheres (eq 22)\"", qdat, ff->rigid_set);
    /* each file in the key by its name: the user's text, quoted so that
     * gnuplot expands nothing in it (adh_gp_quote); approach points open
     * circles, retract points open triangles; the files in black and
     * greys, apart from the run's colours */
    for (int i = 0; i < 2 * ff->nmeas; i++) {
        if (ff->meas_set[i] < 0)
            continue;
        static const char *const colors[] = { "#000000", "#555555", "#888888", "#aaaaaa" };
        char name[ADH_GP_QUOTED_SIZE(128)];
        adh_gp_quoted(ff->meas_file[i / 2]->name, name, sizeof name);
        fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Fu) with points pt %d ps 0.8 lc rgb \"%s\" "
                   "title %s.' %s' noenhanced", qdat, ff->meas_set[i], i % 2 ? 8 : 6, colors[(i / 2) % 4], name,
                i % 2 ? "retract" : "approach");
    }
    if (ff->ref_set[0] >= 0 || ff->ref_set[1] >= 0)
        fprintf(c, ", \\\n  keyentry with lines ls 9 title \"static equilibrium\"");
    if (!ff->models) {
        fprintf(c, ", \\\n  Fjkr*Fu with lines ls 3 title sprintf(\"JKR −(3/2)πγR = %%.3g %s\", "
                   "Fjkr*Fu)", ff->funit);
        fprintf(c, ", \\\n  Fdmt*Fu with lines ls 4 title sprintf(\"DMT −2πγR = %%.3g %s\", "
                   "Fdmt*Fu)", ff->funit);
        return;
    }
    for (int k = 1; k < 4; k++) {
        int m = k % 3;   /* JKR, DMT, then Maugis-Dugdale: the key in the paper's order */
        const model_sets *ms = model_of(ff, m);
        if (ms->load < 0 && ms->disp < 0)
            continue;
        char title[128];   /* short: the man page says what the pull-offs are */
        if (m == 1)
            snprintf(title, sizeof title, "JKR, pull-off %.3g %s", d->F_jkr * ff->fscale, ff->funit);
        else if (m == 0)
            snprintf(title, sizeof title, "Maugis–Dugdale, λ = %.3g", ff->md_lambda);
        else
            snprintf(title, sizeof title, "DMT, pull-off %.3g %s", d->F_dmt * ff->fscale, ff->funit);
        fprintf(c, ", \\\n  keyentry with lines ls %d%s title \"%s\"", model_line[m].ls,
                ms->load >= 0 ? "" : " lc rgb adh_model_disp_color", title);
    }
    if (ff->any_disp)
        fprintf(c, ", \\\n  keyentry with lines ls 3 lc rgb adh_model_disp_color lw 1 "
                   "title \"models past pull-off (grey)\"");
    if (ff->panel)
        fprintf(c, ", \\\n  keyentry with linespoints ls 6 title \"adhesion vs max load (right)\"");
}

/* The force panel: frame, the key below it, then one plot command built
 * clause by clause: the Maugis-Dugdale band under everything, the run's
 * curves, the references over them. -1 out of memory. */
static int force_panel(plotter *pl, const force_fig *ff)
{
    position_label(pl);
    adh_gnuplot_cmd(pl->gp, "set ylabel \"force F (%s)\"", ff->funit);
    adh_gnuplot_cmd(pl->gp, "set xrange [%.17g:%.17g]", (ff->xmin - ff->xpad) * 1e9, ff->xright * 1e9);
    adh_gnuplot_cmd(pl->gp, "set yrange [%.17g:%.17g]", ff->lo * ff->fscale, ff->hi * ff->fscale);
    adh_gnuplot_cmd(pl->gp, "set key at screen 0.5, screen 0.01 center bottom vertical maxrows %d width -2", ff->keyrows);
    adh_gnuplot_cmd(pl->gp, "set bmargin %.3g", ff->bmargin);
    adh_plot_branch_styles(pl->gp);
    char *cmd = NULL, q[ADH_GP_PATH_SIZE];
    size_t cmdcap = 0;
    FILE *c = open_memstream(&cmd, &cmdcap);
    if (!c)
        return -1;
    const char *qdat = adh_gp_path(ff->dat, q, sizeof q);
    fprintf(c, "plot 0 ls 7 notitle");
    force_model_clauses(ff, c, qdat, 1);
    force_run_clauses(pl, ff, c, qdat);
    force_reference_clauses(pl, ff, c, qdat);
    fclose(c);
    adh_gnuplot_cmd(pl->gp, "%s", cmd);
    free(cmd);
    return 0;
}

/* The characters of the labels of the tics every step from lo to hi, a
 * space between each. */
static int tic_chars(double lo, double hi, double step)
{
    int n = 0;
    for (double k = ceil(lo / step); k * step <= hi * (1 + 1e-12) && n < 1000; k++) {
        char t[32];
        double v = fabs(k) < 1e-9 ? 0 : k * step;   /* no "-0", no 1e-17 */
        n += snprintf(t, sizeof t, "%g", v) + 2;
    }
    return n;
}

/* The adhesion panel at the right (two turns or more): adhesion against
 * the maximum load, with JKR's and DMT's. */
static void adhesion_panel(plotter *pl, const force_fig *ff, double top)
{
    const adh_run *run = pl->run;
    const adh_derived *d = &pl->d;
    const size_t *order = ff->order;
    double fscale = ff->fscale;
    char q[ADH_GP_PATH_SIZE];
    adh_gnuplot_cmd(pl->gp, "set origin 0.64,0");
    adh_gnuplot_cmd(pl->gp, "set size 0.36,%g", top);
    adh_gnuplot_cmd(pl->gp, "unset title");
    adh_gnuplot_cmd(pl->gp, "set autoscale");
    adh_gnuplot_cmd(pl->gp, "set xlabel \"maximum load (%s)\"", ff->funit);
    /* a narrow panel: three or four ticks, or their labels collide;
     * never fewer than two, whatever the span of the loads */
    double lmin = INFINITY, lmax = -INFINITY, amin = INFINITY, amax = -INFINITY;
    for (size_t k = 0; k < ff->nadh; k++) {
        lmin = fmin(lmin, run->turns[order[k]].max_load * fscale);
        lmax = fmax(lmax, run->turns[order[k]].max_load * fscale);
        amin = fmin(amin, -run->turns[order[k]].pulloff_F * fscale);
        amax = fmax(amax, -run->turns[order[k]].pulloff_F * fscale);
    }
    if (lmax > lmin) {
        double span = lmax - lmin, lo_ = lmin - 0.12 * span, hi_ = lmax + 0.12 * span;
        double step = nice_step((hi_ - lo_) / 3.0);
        for (int k = 0; k < 6 && floor(hi_ / step) - ceil(lo_ / step) + 1 < 3; k++)
            step = nice_below(step);
        /* their labels must not touch: some 30 characters fit the panel */
        while (tic_chars(lo_, hi_, step) > 30)
            step = nice_step(1.01 * step * 1.5);
        adh_gnuplot_cmd(pl->gp, "set xtics %.17g", step);
        /* an explicit range, so the JKR and DMT lines span the panel */
        adh_gnuplot_cmd(pl->gp, "set xrange [%.17g:%.17g]", lo_, hi_);
    }
    /* the adhesion and the two models, not zero: a pull-off that rises
     * then saturates with the load (Figure 5) must not be flattened */
    amin = fmin(amin, -d->F_jkr * fscale);
    amax = fmax(amax, -d->F_dmt * fscale);
    if (amax > amin) {
        double span = amax - amin, lo_ = amin - 0.1 * span, hi_ = amax + 0.1 * span;
        double step = nice_step((hi_ - lo_) / 6.0);
        adh_gnuplot_cmd(pl->gp, "set ytics %.17g", step);
        adh_gnuplot_cmd(pl->gp, "set yrange [%.17g:%.17g]", lo_, hi_);
    }
    adh_gnuplot_cmd(pl->gp, "set ylabel \"adhesion −F_{min} (%s)\"", ff->funit);
    /* its entries are in the force panel's key, whose room below it keeps */
    adh_gnuplot_cmd(pl->gp, "unset key");
    adh_gnuplot_cmd(pl->gp, "set bmargin %.3g", ff->bmargin);
    adh_gnuplot_cmd(pl->gp,
                    "plot %s using ($1*Fu):($2*Fu) with linespoints ls 6 notitle, "
                    "-Fjkr*Fu with lines ls 3 notitle, "
                    "-Fdmt*Fu with lines ls 4 notitle",
                    adh_gp_path(ff->adh, q, sizeof q));
    adh_gnuplot_cmd(pl->gp, "unset multiplot");
}

static int plot_force(plotter *pl)
{
    const adh_run *run = pl->run;
    const adh_derived *d = &pl->d;
    if (run->nrows < 2) {
        pl->skipped |= ADH_PLOT_FORCE;
        adh_text_catf(pl->notes, sizeof pl->notes, "%sforce.png skipped: fewer than 2 rows",
               *pl->notes ? "; " : "");
        return 0;
    }
    /* large (two paths, the turn order): not on the stack; one per thread,
     * as a study's threads draw their runs' figures at once */
    static _Thread_local force_fig ff;
    memset(&ff, 0, sizeof ff);
    ff.np = max_path(run);
    ff.set = malloc(2 * ((size_t)ff.np + 1) * sizeof *ff.set);
    if (!ff.set || force_data(pl, &ff) != 0 || adhesion_data(pl, &ff) != 0) {
        free(ff.set);
        return -1;
    }
    ff.panel = ff.nadh >= 2;
    force_frame(pl, &ff);
    char heading[HEADING_SIZE];
    char what[96], speed[64];
    speed_text(pl->s->drive_speed, speed, sizeof speed);
    snprintf(what, sizeof what, pl->s->timed ? "Force vs position at %s" : "Force vs position", speed);
    title_string(pl, what, heading, sizeof heading);

    begin_figure(pl, "force", "force.png");
    adh_gnuplot_cmd(pl->gp, "Fu = %.17g", ff.fscale);
    adh_gnuplot_cmd(pl->gp, "Fjkr = %.17g", d->F_jkr);
    adh_gnuplot_cmd(pl->gp, "Fdmt = %.17g", d->F_dmt);
    int panel = ff.panel;
    /* a two-line heading (scene title) needs more room above the panels,
     * or it runs into the adhesion panel's top */
    double top = has_title(pl) ? 0.90 : 0.95;
    if (panel) {
        adh_gnuplot_cmd(pl->gp, "set multiplot title %s noenhanced", heading);
        adh_gnuplot_cmd(pl->gp, "set origin 0,0");
        adh_gnuplot_cmd(pl->gp, "set size 0.64,%g", top);
    } else {
        adh_gnuplot_cmd(pl->gp, "set title %s noenhanced", heading);
    }
    int rc = force_panel(pl, &ff);
    free(ff.set);
    if (rc != 0)
        return -1;
    if (panel)
        adhesion_panel(pl, &ff, top);
    return finish_figure(pl, "force.png");
}

/* The force against the instrument's base beside force.png, when a
 * spring sets the base apart from h0 (plot/forcebase.h). */
static int plot_force_base(plotter *pl)
{
    if (pl->run->nrows < 2) {
        pl->base_done = 1;   /* force.png's note says why */
        return 0;
    }
    char heading[HEADING_SIZE], what[160], speed[64] = "";
    if (pl->s->timed)
        speed_text(pl->s->drive_speed, speed, sizeof speed);
    snprintf(what, sizeof what, "Force vs base position%s%s, spring k = %s", *speed ? " at " : "", speed,
             adh_qtext(pl->s->spring, ADH_Q_STIFFNESS).s);
    title_string(pl, what, heading, sizeof heading);
    char why[1024];
    if (adh_forcebase_figure(&pl->ses, pl->s, pl->run, heading, why, sizeof why) != 0) {
        if (!*pl->error)
            snprintf(pl->error, sizeof pl->error, "force-base.png: %.960s", why);
        return -1;
    }
    adh_text_catf(pl->done, sizeof pl->done, "%sforce-base.png", *pl->done ? ", " : "");
    pl->base_done = 1;
    return 0;
}

/* -------------------------------------------------------------- profile */

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* Which stored profiles profile.png draws: loading and the unloading
 * branch of the deepest turn (with several turns the other branches would
 * bury the comparison Figure 4B makes), and their distinct positions, top
 * of the figure first, each with one colour. */
typedef struct profile_fig {
    const adh_turn_result *main_turn;
    size_t nsel, *sel;             /* indices into run->profiles */
    size_t npos;
    double *pos;
    char dat[PATH_MAX + 32];
    double amax;                   /* the largest radius in contact */
} profile_fig;

static int profile_select(const adh_run *run, profile_fig *pf)
{
    pf->main_turn = adh_run_main_turn(run);
    int unload_path = pf->main_turn ? pf->main_turn->path : -1;
    pf->sel = malloc((run->nprofiles + 1) * sizeof *pf->sel);
    pf->pos = malloc((run->nprofiles + 1) * sizeof *pf->pos);
    if (!pf->sel || !pf->pos)
        return -1;
    for (size_t k = 0; k < run->nprofiles; k++)
        if (run->profiles[k].path == 0 || run->profiles[k].path == unload_path)
            pf->sel[pf->nsel++] = k;
    for (size_t k = 0; k < pf->nsel; k++) {
        double h0 = run->profiles[pf->sel[k]].h0;
        size_t j = 0;
        while (j < pf->npos && fabs(pf->pos[j] - h0) > 1e-15)
            j++;
        if (j == pf->npos)
            pf->pos[pf->npos++] = h0;
    }
    qsort(pf->pos, pf->npos, sizeof *pf->pos, cmp_desc);
    return 0;
}

/* profile.dat: h(r) of each selected profile. */
static int profile_data(plotter *pl, profile_fig *pf)
{
    const adh_run *run = pl->run;
    const adh_plot_setup *s = pl->s;
    FILE *f = data_file(pl, "profile.dat", pf->dat, sizeof pf->dat);
    if (!f)
        return -1;
    pf->amax = 0;
    for (size_t k = 0; k < pf->nsel; k++) {
        const adh_profile *pr = &run->profiles[pf->sel[k]];
        for (size_t n = 0; n < s->nodes; n++) {
            double r = adh_plot_setup_radius(s, n);
            fprintf(f, "%.17g\t%.17g\n", r, pr->h[n]);
            if (pr->h[n] < ADH_CONTACT_FACTOR * s->mat.z0 && r > pf->amax)
                pf->amax = r;
        }
        fprintf(f, "\n\n");
    }
    return data_close(pl, f, pf->dat) < 0 ? -1 : 0;
}

/* The plot command: the undeformed sphere, then each profile, loading
 * first so each position's key entry is its solid curve. */
static void profile_clauses(plotter *pl, const profile_fig *pf, FILE *c, const char *qdat)
{
    const adh_run *run = pl->run;
    fprintf(c, "plot (htop + (x*1e-6)**2/(2*R))*1e9 with lines ls 5 "
               "title \"undeformed, %.3g nm\"", pf->pos[0] * 1e9);
    int titled[ADH_MAX_PROFILES * 2] = { 0 };
    int any_unload = 0, any_load = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t k = 0; k < pf->nsel; k++) {
            const adh_profile *pr = &run->profiles[pf->sel[k]];
            int loading = pr->path == 0;
            if (loading != (pass == 0))
                continue;
            size_t j = 0;
            while (j + 1 < pf->npos && fabs(pf->pos[j] - pr->h0) > 1e-15)
                j++;
            char title[96] = "notitle";
            /* a key taller than the frame helps nobody: with many positions
             * only the top and bottom ones are named */
            int named = pf->npos <= 16 || j == 0 || j + 1 == pf->npos;
            if (named && j < sizeof titled / sizeof titled[0] && !titled[j]) {
                snprintf(title, sizeof title, "title \"%.3g nm\"", pr->h0 * 1e9);
                titled[j] = 1;
            }
            any_unload |= !loading;
            any_load |= loading;
            fprintf(c, ", \\\n  %s index %zu using ($1*1e6):($2*1e9) with lines "
                       "lc rgb adh_pcol(%zu) "
                       "lw %s dt %d %s", qdat, k, j, loading ? "2" : "1.6", loading ? 1 : 2,
                    title);
        }
    }
    if (any_load)
        fprintf(c, ", \\\n  keyentry with lines lc rgb \"#888888\" lw 2 dt 1 "
                   "title \"loading\"");
    if (any_unload)
        fprintf(c, ", \\\n  keyentry with lines lc rgb \"#888888\" lw 1.6 dt 2 "
                   "title \"unloading from %.3g nm\"", pf->main_turn->h0 * 1e9);
}

/* The frame: wide enough to show the contact and the flank beyond it,
 * high enough that every position's parabola enters from the top; then
 * the curves. -1 out of memory. */
static int profile_figure(plotter *pl, const profile_fig *pf)
{
    const adh_plot_setup *s = pl->s;
    double rgrid = adh_plot_setup_radius(s, s->nodes - 1);
    double R = s->mat.R, top = pf->pos[0], bottom = pf->pos[pf->npos - 1];
    double rise = fmax(top - bottom, 10.0 * s->mat.z0);
    double xmax = sqrt(2.0 * R * rise);
    if (xmax < 1.6 * pf->amax)
        xmax = 1.6 * pf->amax;
    if (xmax > rgrid)
        xmax = rgrid;
    double ymax = top + xmax * xmax / (2.0 * R);
    char heading[HEADING_SIZE], q[ADH_GP_PATH_SIZE];
    title_string(pl, "Surface profiles", heading, sizeof heading);
    adh_gnuplot_cmd(pl->gp, "set title %s noenhanced", heading);
    adh_gnuplot_cmd(pl->gp, "set xlabel \"radial distance r (µm)\"");
    adh_gnuplot_cmd(pl->gp, "set ylabel \"local separation h(r) (nm)\"");
    adh_gnuplot_cmd(pl->gp, "set xrange [0:%.17g]", xmax * 1e6);
    adh_gnuplot_cmd(pl->gp, "set yrange [0:%.17g]", ymax * 1e9);
    adh_gnuplot_cmd(pl->gp, "set key outside right top vertical title \"h_0\" noautotitle");
    adh_gnuplot_cmd(pl->gp, "set samples 400");
    adh_gnuplot_cmd(pl->gp, "R = %.17g", R);
    adh_gnuplot_cmd(pl->gp, "htop = %.17g", top);
    /* each position its own colour (a qualitative list: loading and
     * unloading at one position are told apart by their dash alone);
     * more positions than colours cycle */
    adh_gnuplot_cmd(pl->gp, "adh_pcol(j) = word(adh_profile_colors, 1 + j %% words(adh_profile_colors))");
    char *cmd = NULL;
    size_t cmdcap = 0;
    FILE *c = open_memstream(&cmd, &cmdcap);
    if (!c)
        return -1;
    profile_clauses(pl, pf, c, adh_gp_path(pf->dat, q, sizeof q));
    fclose(c);
    adh_gnuplot_cmd(pl->gp, "%s", cmd);
    free(cmd);
    return 0;
}

static int plot_profile(plotter *pl)
{
    profile_fig pf = { 0 };
    int rc = -1;
    if (profile_select(pl->run, &pf) != 0)
        goto out;
    if (pf.nsel == 0) {
        pl->skipped |= ADH_PLOT_PROFILE;
        adh_text_catf(pl->notes, sizeof pl->notes, "%sprofile.png skipped: no profiles stored "
               "(ask with --profiles=M[,M...])", *pl->notes ? "; " : "");
        rc = 0;
        goto out;
    }
    if (profile_data(pl, &pf) != 0)
        goto out;
    begin_figure(pl, "profile", "profile.png");
    if (profile_figure(pl, &pf) == 0)
        rc = finish_figure(pl, "profile.png");
out:
    free(pf.sel);
    free(pf.pos);
    return rc;
}

/* -------------------------------------------------------------- contact */

/* contact.dat: per path, the step-by-step speed, the smoothed speed and the
 * radius (in contact, plus the row either side so the jumps show), at
 * set[3p], set[3p + 1], set[3p + 2]. */
static int contact_data(plotter *pl, const double *dadt, const double *smooth, int np, int *set,
                        char *dat, size_t datlen)
{
    const adh_run *run = pl->run;
    size_t n = run->nrows;
    FILE *f = data_file(pl, "contact.dat", dat, datlen);
    if (!f)
        return -1;
    datafile df = { .f = f };
    for (int p = 0; p <= np; p++) {
        for (int k = 0; k < 2; k++) {
            const double *v = k == 0 ? dadt : smooth;
            set_begin(&df);
            for (size_t i = 0; i < n; i++) {
                if (run->rows[i].path != p)
                    continue;
                if (isfinite(v[i]))
                    set_point(&df, run->rows[i].h0, v[i]);
                else
                    set_break(&df);
            }
            set[3 * p + k] = set_end(&df);
        }
        set_begin(&df);
        for (size_t i = 0; i < n; i++) {
            if (run->rows[i].path != p)
                continue;
            long a = adh_run_prev_on_path(run, i), b = adh_run_next_on_path(run, i);
            if (run->rows[i].a > 0 || (a >= 0 && run->rows[a].a > 0) ||
                (b >= 0 && run->rows[b].a > 0))
                set_point(&df, run->rows[i].h0, run->rows[i].a);
            else
                set_break(&df);
        }
        set[3 * p + 2] = set_end(&df);
    }
    return data_close(pl, f, dat) < 0 || df.bad ? -1 : 0;
}

/* The frame of one panel: 0 the contact-line speed above, 1 the contact
 * radius below, sharing the x axis. */
static void contact_frame(plotter *pl, int panel, double top, int in_mm, int keyrows, double amax)
{
    if (panel == 0) {
        adh_gnuplot_cmd(pl->gp, "set origin 0,0.42");
        adh_gnuplot_cmd(pl->gp, "set size 1,%.3f", top - 0.42);
        adh_gnuplot_cmd(pl->gp, "set format x \"\"");
        adh_gnuplot_cmd(pl->gp, "unset xlabel");
        adh_gnuplot_cmd(pl->gp, "set bmargin 1");
        adh_gnuplot_cmd(pl->gp, "set tmargin 0.5");
        adh_gnuplot_cmd(pl->gp, "set ylabel \"contact-line speed da/dt (%s)\"",
                        in_mm ? "mm/s" : "µm/s");
        adh_gnuplot_cmd(pl->gp, "Vu = %g", in_mm ? 1e3 : 1e6);
        /* one key for both panels, below them: out of the data */
        adh_gnuplot_cmd(pl->gp, "set key at screen 0.5, screen 0.01 center bottom vertical maxrows %d", keyrows);
    } else {
        adh_gnuplot_cmd(pl->gp, "set origin 0,0");
        adh_gnuplot_cmd(pl->gp, "set size 1,0.44");
        adh_gnuplot_cmd(pl->gp, "set format x \"%% g\"");
        position_label(pl);
        adh_gnuplot_cmd(pl->gp, "set tmargin 1");
        adh_gnuplot_cmd(pl->gp, "set bmargin %.3g", 4.2 + 1.05 * keyrows);
        adh_gnuplot_cmd(pl->gp, "set yrange [0:*]");
        /* a low panel: four or five tics, not nine */
        if (amax > 0)
            adh_gnuplot_cmd(pl->gp, "set ytics %.17g", nice_step(amax * 1e6 / 4.5));
        adh_gnuplot_cmd(pl->gp, "set ylabel \"contact radius a (µm)\"");
        adh_gnuplot_cmd(pl->gp, "unset key");
    }
    /* both panels share the left margin so their x axes line up */
    adh_gnuplot_cmd(pl->gp, "set lmargin 11");
}

/* Unloading branches with a smoothed speed: the key's entries. */
static int contact_unloads(const int *set, int np)
{
    int n = 0;
    for (int p = 1; p <= np; p++)
        n += set[3 * p + 1] >= 0;
    return n;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The 5th and 95th percentiles of v's finite values (0, and 0 between
 * them), in lo and hi; -1 when there are fewer than 20 or no memory. */
static int speed_bulk(const double *v, size_t n, double *lo, double *hi)
{
    double *s = n ? malloc(n * sizeof *s) : NULL;
    size_t m = 0;
    for (size_t i = 0; s && i < n; i++)
        if (isfinite(v[i]))
            s[m++] = v[i];
    if (m < 20) {
        free(s);
        return -1;
    }
    qsort(s, m, sizeof *s, cmp_double);
    *lo = fmin(0, s[m / 20]);
    *hi = fmax(0, s[m - 1 - m / 20]);
    free(s);
    return 0;
}

/* One panel's plot command: each path's curves, loading first. -1 out of
 * memory. */
static int contact_panel(plotter *pl, int panel, const int *set, int np, const char *qdat)
{
    char *cmd = NULL;
    size_t cmdcap = 0;
    FILE *c = open_memstream(&cmd, &cmdcap);
    if (!c)
        return -1;
    fprintf(c, "plot %s", panel == 0 ? "0 ls 7 notitle" : "NaN notitle");
    int nunload = contact_unloads(set, np), labelled = 0;
    for (int p = 0; p <= np; p++) {
        char lc[128], title[128];
        const adh_turn_result *tr = turn_of_path(pl->run, p);
        if (p == 0) {
            snprintf(lc, sizeof lc, "lc rgb adh_loading_color");
            snprintf(title, sizeof title, "title \"loading\"");
        } else {
            unload_color(p, lc, sizeof lc);
            unload_title(tr, nunload, &labelled, title, sizeof title);
        }
        /* the key is the speed panel's: the radius panel's curves go untitled */
        if (panel == 1)
            snprintf(title, sizeof title, "notitle");
        char smooth[160];   /* the branch's colour and dash */
        if (p == 0)
            snprintf(smooth, sizeof smooth, "%s dt 1", lc);
        else
            snprintf(smooth, sizeof smooth, "%s dt adh_udash(%d)", lc, p);
        const char *width = p == 0 ? "adh_loading_width" : "adh_unloading_width";
        if (panel == 0) {
            /* step by step, thin and pale; the smoothed speed on top */
            if (set[3 * p] >= 0)
                fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Vu) with lines %s "
                           "lw 0.6 notitle", qdat, set[3 * p], p == 0 ? "lc rgb adh_hop_color" : lc);
            if (set[3 * p + 1] >= 0)
                fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*Vu) with lines %s "
                           "lw %s %s", qdat, set[3 * p + 1], smooth, width, title);
        } else if (set[3 * p + 2] >= 0) {
            fprintf(c, ", \\\n  %s index %d using ($1*1e9):($2*1e6) with lines %s lw %s "
                       "%s", qdat, set[3 * p + 2], smooth, width, title);
        }
    }
    if (panel == 0)
        fprintf(c, ", \\\n  keyentry with lines lc rgb adh_hop_color lw 0.6 "
                   "title \"step by step (node hops)\"");
    fclose(c);
    adh_gnuplot_cmd(pl->gp, "%s", cmd);
    free(cmd);
    return 0;
}

/* The h0 range of the rows in contact, padded; 0 when never in contact. */
static int contact_range(plotter *pl, double *lo, double *hi)
{
    const adh_run *run = pl->run;
    double xmin = INFINITY, xmax = -INFINITY;
    for (size_t i = 0; i < run->nrows; i++)
        if (run->rows[i].a > 0) {
            xmin = fmin(xmin, run->rows[i].h0);
            xmax = fmax(xmax, run->rows[i].h0);
        }
    if (!(xmax >= xmin)) {
        pl->skipped |= ADH_PLOT_CONTACT;
        adh_text_catf(pl->notes, sizeof pl->notes, "%scontact.png skipped: never in contact", *pl->notes ? "; " : "");
        return 0;
    }
    double xpad = fmax(0.03 * (xmax - xmin), 2 * fabs(pl->s->step));
    *lo = xmin - xpad;
    *hi = xmax + xpad;
    return 1;
}

/* Static mode: a curve of equilibria has no speed (nothing moves along it
 * in time), so contact.png is the contact radius a(h0) alone, its stable
 * stretches solid and the unstable ones dashed, through the folds. */
static int plot_contact_static(plotter *pl)
{
    double lo, hi;
    if (!contact_range(pl, &lo, &hi))
        return 0;
    char dat[PATH_MAX + 32], q[ADH_GP_PATH_SIZE], heading[HEADING_SIZE];
    FILE *f = data_file(pl, "contact.dat", dat, sizeof dat);
    if (!f)
        return -1;
    datafile df = { .f = f };
    int set[2];
    for (int s = 1; s >= 0; s--)
        set[1 - s] = write_stability_set(&df, pl->run, 0, s, 1);
    if (data_close(pl, f, dat) < 0 || df.bad)
        return -1;
    title_string(pl, "Contact radius along the static equilibrium curve", heading, sizeof heading);
    begin_figure(pl, "contact", "contact.png");
    adh_gnuplot_cmd(pl->gp, "set title %s noenhanced", heading);
    adh_gnuplot_cmd(pl->gp, "set xrange [%.17g:%.17g]", lo * 1e9, hi * 1e9);
    adh_gnuplot_cmd(pl->gp, "set yrange [0:*]");
    position_label(pl);
    adh_gnuplot_cmd(pl->gp, "set ylabel \"contact radius a (µm)\"");
    adh_gnuplot_cmd(pl->gp, "set key outside below center horizontal width -6");
    const char *qdat = adh_gp_path(dat, q, sizeof q);
    char stable[ADH_GP_PATH_SIZE + 128] = "", unstable[ADH_GP_PATH_SIZE + 160] = "";
    if (set[0] >= 0)
        snprintf(stable, sizeof stable, ", \\\n  %s index %d using ($1*1e9):($2*1e6) with lines ls 1 title \"stable\"",
                 qdat, set[0]);
    if (set[1] >= 0)
        snprintf(unstable, sizeof unstable, ", \\\n  %s index %d using ($1*1e9):($2*1e6) with lines ls 1 lw 1.2 "
                 "dt adh_unstable_dash title \"unstable (displacement control)\"", qdat, set[1]);
    adh_gnuplot_cmd(pl->gp, "plot NaN notitle%s%s", stable, unstable);
    return finish_figure(pl, "contact.png");
}

static int plot_contact(plotter *pl)
{
    if (pl->s->equilibrium)
        return plot_contact_static(pl);
    const adh_run *run = pl->run;
    size_t n = run->nrows;
    double *dadh0 = n ? malloc(n * sizeof *dadh0) : NULL;
    double *dadt = n ? malloc(n * sizeof *dadt) : NULL;
    double *smooth = n ? malloc(n * sizeof *smooth) : NULL;
    int np = max_path(run);
    int *set = malloc(3 * ((size_t)np + 1) * sizeof *set);
    char dat[PATH_MAX + 32], q[ADH_GP_PATH_SIZE];
    int rc = -1;
    if ((n && (!dadh0 || !dadt || !smooth)) || !set)
        goto out;
    adh_speed_stepwise(run, pl->s->drive_speed, dadh0, dadt);
    adh_speed_smoothed(run, pl->s->drive_speed, pl->s->dr, ADH_SPEED_CELLS, smooth);
    double xlo, xhi;
    if (!contact_range(pl, &xlo, &xhi)) {
        rc = 0;
        goto out;
    }
    if (contact_data(pl, dadt, smooth, np, set, dat, sizeof dat) != 0)
        goto out;

    /* µm/s as in Figure 8, mm/s when a large sphere makes that unwieldy */
    double vmax = 0, vlo = 0, vhi = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(smooth[i]))
            vmax = fmax(vmax, fabs(smooth[i]));
    /* in physical time the speed diverges at each jump (as the drive's
     * times da/dh0): the scale is the bulk's, the 5th to 95th percentile */
    if (pl->s->timed && speed_bulk(smooth, n, &vlo, &vhi) == 0)
        vmax = fmax(fabs(vlo), fabs(vhi));
    int in_mm = vmax >= 2e-3;
    char heading[HEADING_SIZE], what[128], speed[64];
    speed_text(pl->s->drive_speed, speed, sizeof speed);
    snprintf(what, sizeof what, pl->s->timed ? "Contact line in time, base at %s" : "Contact line at drive speed %s",
             speed);
    title_string(pl, what, heading, sizeof heading);
    /* a two-line heading (scene title) needs more room above the panels */
    double top = has_title(pl) ? 0.90 : 0.94;
    begin_figure(pl, "contact", "contact.png");
    adh_gnuplot_cmd(pl->gp, "set multiplot title %s noenhanced", heading);
    adh_gnuplot_cmd(pl->gp, "set xrange [%.17g:%.17g]", xlo * 1e9, xhi * 1e9);
    adh_plot_branch_styles(pl->gp);
    int nunload = contact_unloads(set, np);
    int keyrows = (2 + (nunload > MAX_LABELLED_UNLOADS ? 1 : nunload) + 2) / 3;
    double amax = 0;
    for (size_t i = 0; i < n; i++)
        amax = fmax(amax, run->rows[i].a);
    for (int panel = 0; panel < 2; panel++) {
        contact_frame(pl, panel, top, in_mm, keyrows, amax);
        /* adaptive time steps: a node hop within a short step is a spike
         * of the step-by-step speed; the scale is the smoothed bulk's, and
         * the label says what goes off it */
        if (panel == 0 && pl->s->timed && vhi > vlo) {
            adh_gnuplot_cmd(pl->gp, "set yrange [%.17g:%.17g]", (vlo - 0.3 * (vhi - vlo)) * (in_mm ? 1e3 : 1e6),
                            (vhi + 0.3 * (vhi - vlo)) * (in_mm ? 1e3 : 1e6));
            adh_gnuplot_cmd(pl->gp, "set ylabel \"contact-line speed da/dt (%s)\\n(off the scale at the jumps)\"",
                            in_mm ? "mm/s" : "µm/s");
        }
        if (contact_panel(pl, panel, set, np, adh_gp_path(dat, q, sizeof q)) != 0)
            goto out;
    }
    adh_gnuplot_cmd(pl->gp, "unset multiplot");
    rc = finish_figure(pl, "contact.png");
out:
    free(dadh0);
    free(dadt);
    free(smooth);
    free(set);
    return rc;
}

/* ------------------------------------------------------------- the lot */

/* name appended to the comma-separated list in buf (may be NULL). */
static void add_name(char *buf, size_t len, const char *name)
{
    if (buf && len)
        adh_text_catf(buf, len, "%s%s", *buf ? "," : "", name);
}

/* The figures asked for that are neither in place nor skipped for lack of
 * data, onto the list. */
static void add_unwritten_figures(char *buf, size_t len, unsigned want, unsigned done)
{
    static const struct { unsigned bit; const char *name; } figs[] = {
        { ADH_PLOT_FORCE, "force.png" }, { ADH_PLOT_PROFILE, "profile.png" }, { ADH_PLOT_CONTACT, "contact.png" },
    };
    for (size_t i = 0; i < sizeof figs / sizeof figs[0]; i++)
        if ((want & figs[i].bit) && !(done & figs[i].bit))
            add_name(buf, len, figs[i].name);
}

int adh_plots_write(const adh_plot_setup *s, const adh_run *run, const adh_run *reference, adh_outdir *out,
                    char *msg, size_t msglen, char *unwritten, size_t ulen)
{
    char why[1024], table_error[1024] = "";
    if (msglen)
        msg[0] = '\0';
    if (unwritten && ulen)
        unwritten[0] = '\0';
    const char *dir = adh_outdir_path(out);
    unsigned want = s->draw ? s->figures & ADH_PLOT_ALL : 0;
    /* Only the tables that were asked for: profiles where profiles were
     * stored, contact-line tracking when the contact plot is wanted. A
     * table that cannot be written (a full disk) does not stop the others. */
    char tables[96] = "";   /* profiles.tsv, contact.tsv, models.tsv */
    if (run->nprofiles > 0) {
        if (adh_tsv_profiles(s, run, out, why, sizeof why) != 0) {
            snprintf(table_error, sizeof table_error, "%s", why);
            add_name(unwritten, ulen, "profiles.tsv");
        } else {
            strcat(tables, "profiles.tsv");
        }
    }
    if (s->figures & ADH_PLOT_CONTACT) {
        if (adh_tsv_contact(s, run, out, why, sizeof why) != 0) {
            if (!*table_error)
                snprintf(table_error, sizeof table_error, "%s", why);
            add_name(unwritten, ulen, "contact.tsv");
        } else {
            strcat(tables, *tables ? ", contact.tsv" : "contact.tsv");
        }
    }
    /* the model curves force.png draws, so it can be drawn again */
    if ((s->figures & ADH_PLOT_FORCE) && !s->rigid && run->nrows) {
        if (adh_tsv_models(s, run, reference, out, why, sizeof why) != 0) {
            if (!*table_error)
                snprintf(table_error, sizeof table_error, "%s", why);
            add_name(unwritten, ulen, "models.tsv");
        } else {
            strcat(tables, *tables ? ", models.tsv" : "models.tsv");
        }
    }
    if (!want) {
        if (*table_error) {
            snprintf(msg, msglen, "%s", table_error);
            return 2;
        }
        snprintf(msg, msglen, "wrote %s in %s (plots off)", *tables ? tables : "no plot tables", dir);
        return 0;
    }

    plotter pl;
    memset(&pl, 0, sizeof pl);
    pl.s = s;
    pl.run = run;
    pl.ref = reference;
    pl.out = out;
    adh_material_derive(&s->mat, &pl.d);
    int rc = 0;
    if (adh_session_open(&pl.ses, out, "gnuplot.log", s->style, s->cancel, why, sizeof why) != 0)
        snprintf(pl.error, sizeof pl.error, "%.990s; no plots made", why);
    pl.gp = pl.ses.gp;
    if (pl.gp) {
        /* Figures are independent: a failure in one does not stop the others
         * while gnuplot lives. */
        if ((want & ADH_PLOT_FORCE) && adh_gnuplot_alive(pl.gp))
            plot_force(&pl);
        if ((want & ADH_PLOT_FORCE) && adh_forcebase_wanted(s) && adh_gnuplot_alive(pl.gp))
            plot_force_base(&pl);
        if ((want & ADH_PLOT_PROFILE) && adh_gnuplot_alive(pl.gp))
            plot_profile(&pl);
        if ((want & ADH_PLOT_CONTACT) && adh_gnuplot_alive(pl.gp))
            plot_contact(&pl);
        if (!*pl.error && !adh_gnuplot_alive(pl.gp))
            snprintf(pl.error, sizeof pl.error, "gnuplot stopped");
        adh_session_close(&pl.ses);
    }
    add_unwritten_figures(unwritten, ulen, want, pl.written | pl.skipped);
    if ((want & ADH_PLOT_FORCE) && adh_forcebase_wanted(s) && !pl.base_done)
        add_name(unwritten, ulen, "force-base.png");

    if (*table_error) {
        snprintf(msg, msglen, "%s%s%s", table_error, *pl.error ? "; plotting failed too: " : "", pl.error);
        rc = 2;
    } else if (*pl.error) {
        snprintf(msg, msglen, "plotting failed: %s; %s%stables written in %s", pl.error,
                 *pl.done ? pl.done : "", *pl.done ? " written, " : "", dir);
        rc = 3;
    } else {
        snprintf(msg, msglen, "wrote %s%s%s in %s%s%s", pl.done, *pl.done && *tables ? ", " : "", tables, dir,
                 *pl.notes ? "; " : "", pl.notes);
    }
    return rc;
}
