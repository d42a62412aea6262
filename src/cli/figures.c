#include "cli/figures.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/cycle.h"
#include "adhere/models.h"
#include "cli/jumps.h"
#include "cli/studyrow.h"
#include "cli/mapfig.h"
#include "cli/tables.h"
#include "plot/axes.h"
#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "plot/outdir.h"
#include "plot/plot.h"
#include "plot/session.h"


typedef struct figure {
    adh_session ses;
    adh_gnuplot *gp;        /* ses.gp */
    unsigned written;       /* ADH_PLOT_* bits of the figures in place */
    char *msg;
    size_t msglen;
} figure;

static int fig_open(figure *fg, const adh_config *cfg, adh_outdir *out, char *msg, size_t msglen)
{
    memset(fg, 0, sizeof *fg);
    fg->msg = msg;
    fg->msglen = msglen;
    if (adh_session_open(&fg->ses, out, "gnuplot-figures.log", cfg->output.gnuplot_style, cfg->spec.relax.cancel,
                         msg, msglen) != 0)
        return -1;
    fg->gp = fg->ses.gp;
    return 0;
}

static void fig_close(figure *fg)
{
    adh_session_close(&fg->ses);
}

static FILE *fig_data(figure *fg, const char *name, char *path, size_t len)
{
    return adh_session_data(&fg->ses, name, path, len, fg->msg, fg->msglen);
}

static void fig_begin(figure *fg, const char *name)
{
    adh_session_begin(&fg->ses, name, name);
}

static int fig_end(figure *fg, const char *name, unsigned bit)
{
    char why[1024];
    int rc = adh_session_end(&fg->ses, name, why, sizeof why);
    if (rc != 0)
        snprintf(fg->msg, fg->msglen, "%s: %s", name, why);
    else
        fg->written |= bit;
    return rc;
}

static int data_done(figure *fg, FILE *f, const char *path)
{
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        snprintf(fg->msg, fg->msglen, "cannot write %.3000s", path);
        return -1;
    }
    return 0;
}

/* Figure 1's inset: the computed force before contact against eq 22 at the
 * nominal position, F(h0), and at the gap eq 23 gives, F(h). */
static int precontact(figure *fg, const adh_run_spec *spec, const adh_run *run)
{
    const adh_material *m = &spec->mat;
    char dat[PATH_MAX + 16], eq[PATH_MAX + 16], q[ADH_GP_PATH_SIZE], q2[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "a.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double xmin = INFINITY, xmax = -INFINITY, fbig = 0, hmin = INFINITY;
    size_t pts = 0;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        if (o->path != 0 || o->a > 0)
            break; /* the loading rows before contact come first */
        fprintf(f, "%.17g\t%.17g\t%.17g\n", o->h0, o->F, adh_rigid_force(m, o->h0));
        xmin = fmin(xmin, o->h0), xmax = fmax(xmax, o->h0);
        hmin = fmin(hmin, o->hc);
        fbig = fmax(fbig, fabs(o->F));
        pts++;
    }
    if (data_done(fg, f, dat) < 0)
        return -1;
    if (pts < 2)
        return 0;
    /* F(h) along eq 23: positions h0 = h - delta(h) for gaps down to the
     * smallest one computed */
    f = fig_data(fg, "b.dat", eq, sizeof eq);
    if (!f)
        return -1;
    for (int k = 0; k <= 400; k++) {
        double h = hmin + (xmax - hmin) * k / 400.0;
        double x = adh_bulge_position(m, h);
        if (x >= xmin && x <= xmax)
            fprintf(f, "%.17g\t%.17g\n", x, adh_rigid_force(m, h));
    }
    if (data_done(fg, f, eq) < 0)
        return -1;
    double fs;
    const char *fu;
    adh_force_unit(fbig, &fs, &fu);
    fig_begin(fg, "precontact.png");
    char es[32];
    adh_format_modulus(m->E, es, sizeof es);
    adh_gnuplot_cmd(fg->gp, "set title \"Force before contact (Figure 1 inset), E = %s\"", es);
    adh_gnuplot_cmd(fg->gp, "set xlabel \"drive position h_0 (nm)\"");
    adh_gnuplot_cmd(fg->gp, "set ylabel \"force F (%s)\"", fu);
    adh_gnuplot_cmd(fg->gp, "set key bottom right");
    adh_gnuplot_cmd(fg->gp, "plot %s using ($1*1e9):($2*%.17g) with points pt 6 lc rgb adh_loading_color title \"computed\", "
                    "'' using ($1*1e9):($3*%.17g) with lines ls 2 lw 2 title \"rigid F(h_0) (eq 22)\", "
                    "%s using ($1*1e9):($2*%.17g) with lines ls 3 title \"F(h), h from eq 23\"",
                    adh_gp_path(dat, q, sizeof q), fs, fs, adh_gp_path(eq, q2, sizeof q2), fs);
    return fig_end(fg, "precontact.png", ADH_PLOT_PRECONTACT);
}

/* Figure 2: the central bulge before contact against the gap, with eq 23. */
static int bulge(figure *fg, const adh_run_spec *spec, const adh_run *run)
{
    const adh_material *m = &spec->mat;
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "c.dat", dat, sizeof dat);
    if (!f)
        return -1;
    size_t pts = 0;
    double hmin = INFINITY, hmax = -INFINITY;
    for (size_t i = 0; i < run->nrows; i++) {
        const adh_obs *o = &run->rows[i];
        if (o->path != 0 || o->a > 0)
            break;
        fprintf(f, "%.17g\t%.17g\n", o->hc, o->delta);
        hmin = fmin(hmin, o->hc), hmax = fmax(hmax, o->hc);
        pts++;
    }
    if (data_done(fg, f, dat) < 0)
        return -1;
    if (pts < 2)
        return 0;
    fig_begin(fg, "bulge.png");
    char es[32];
    adh_format_modulus(m->E, es, sizeof es);
    adh_gnuplot_cmd(fg->gp, "set title \"Bulge before contact (Figure 2), E = %s\"", es);
    adh_gnuplot_cmd(fg->gp, "set xlabel \"central gap h (nm)\"");
    adh_gnuplot_cmd(fg->gp, "set ylabel \"central deformation δ (nm)\"");
    adh_gnuplot_cmd(fg->gp, "set key bottom right");
    adh_gnuplot_cmd(fg->gp, "A = %.17g; R = %.17g; E = %.17g", m->A, m->R, m->E);
    adh_gnuplot_cmd(fg->gp, "set xrange [%.17g:%.17g]", hmin * 1e9 * 0.95, hmax * 1e9);
    adh_gnuplot_cmd(fg->gp, "set samples 400");
    adh_gnuplot_cmd(fg->gp, "plot %s using ($1*1e9):($2*1e9) with points pt 6 lc rgb adh_loading_color title \"computed\", "
                    "-A*sqrt(2*R)/(8*E*(x*1e-9)**2.5)*1e9 with lines ls 2 lw 1.5 title \"eq 23\"",
                    adh_gp_path(dat, q, sizeof q));
    return fig_end(fg, "bulge.png", ADH_PLOT_BULGE);
}

/* The figures cfg asked for and not written (in a directory cleared of
 * earlier runs' files: not there), onto the list. */
static void add_missing(const adh_config *cfg, unsigned written, char *list, size_t len)
{
    static const struct { unsigned bit; const char *name; } figs[] = {
        { ADH_PLOT_PRECONTACT, "precontact.png" }, { ADH_PLOT_BULGE, "bulge.png" } };
    for (size_t i = 0; i < sizeof figs / sizeof figs[0]; i++)
        if ((cfg->output.plots & figs[i].bit) && !(written & figs[i].bit))
            cli_tables_names_add(list, len, figs[i].name);
}

int cli_figures_run(const adh_config *cfg, const adh_run_spec *spec, const adh_run *run, adh_outdir *out,
                    char *msg, size_t msglen, char *unwritten, size_t ulen)
{
    if (msglen)
        msg[0] = '\0';
    if (!cfg->output.plot || !(cfg->output.plots & (ADH_PLOT_PRECONTACT | ADH_PLOT_BULGE)))
        return 0;
    figure fg;
    if (fig_open(&fg, cfg, out, msg, msglen) != 0) {
        add_missing(cfg, 0, unwritten, ulen);
        return -1;
    }
    int rc = 0;
    if ((cfg->output.plots & ADH_PLOT_PRECONTACT) && precontact(&fg, spec, run) != 0)
        rc = -1;
    if ((cfg->output.plots & ADH_PLOT_BULGE) && adh_gnuplot_alive(fg.gp) && bulge(&fg, spec, run) != 0)
        rc = -1;
    fig_close(&fg);
    /* on success, what was written, for the run's closing line */
    if (rc == 0)
        snprintf(msg, msglen, "%s%s%s", cfg->output.plots & ADH_PLOT_PRECONTACT ? "precontact.png" : "",
                 (cfg->output.plots & ADH_PLOT_PRECONTACT) && (cfg->output.plots & ADH_PLOT_BULGE) ? ", " : "",
                 cfg->output.plots & ADH_PLOT_BULGE ? "bulge.png" : "");
    else
        add_missing(cfg, fg.written, unwritten, ulen);
    return rc;
}

/* Figure 3: the gap just before the jump against sigma, with eq 24, from
 * the rows (sigma, h_before, h_star, jumped). */
static int jump(figure *fg, const adh_config *cfg, const cli_studyrow *rows, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "a.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double smin = INFINITY, smax = -INFINITY, hlo = INFINITY, hhi = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        const double *v = rows[i].v;
        double h = v[CLI_ROW_H_BEFORE];
        smin = fmin(smin, v[CLI_ROW_SIGMA]), smax = fmax(smax, v[CLI_ROW_SIGMA]);
        if (isfinite(h)) {
            fprintf(f, "%.17g\t%.17g\t%.17g\t%d\n", v[CLI_ROW_SIGMA], h, v[CLI_ROW_H_STAR], (int)v[CLI_ROW_JUMPED]);
            hlo = fmin(hlo, h), hhi = fmax(hhi, h);
        }
    }
    /* eq 24 as a curve of sigma: h* = (3 A sqrt(2R) / 8E)^(2/7), E from eq 17 */
    fprintf(f, "\n\n");
    const adh_material *m = &cfg->spec.mat;
    for (int k = 0; k <= 200; k++) {
        adh_material at = *m;
        double s = smin * pow(smax / smin, k / 200.0);
        at.E = adh_material_modulus_at_sigma(m, s);
        double h = adh_jump_separation(&at);
        fprintf(f, "%.17g\t%.17g\n", s, h);
        hlo = fmin(hlo, h), hhi = fmax(hhi, h);
    }
    if (data_done(fg, f, dat) < 0)
        return -1;
    fig_begin(fg, "jump.png");
    adh_gnuplot_cmd(fg->gp, "set title \"Jump into contact (Figure 3), z_0 = %.3g nm\"", m->z0 * 1e9);
    adh_gnuplot_cmd(fg->gp, "set logscale xy");
    /* the axes hold the points and eq 24 with a margin, not the decades
     * round them (an empty band below the lowest gap) */
    char tics[256];
    double xlo = smin / 1.5, xhi = smax * 1.5, ylo = hlo * 1e9 / 1.25, yhi = hhi * 1e9 * 1.25;
    adh_gnuplot_cmd(fg->gp, "set xrange [%.17g:%.17g]", xlo, xhi);
    adh_gp_log_tics(xlo, xhi, tics, sizeof tics);
    adh_gnuplot_cmd(fg->gp, "set xtics %s", tics);
    adh_gnuplot_cmd(fg->gp, "set yrange [%.17g:%.17g]", ylo, yhi);
    adh_gp_log_tics(ylo, yhi, tics, sizeof tics);
    adh_gnuplot_cmd(fg->gp, "set ytics %s", tics);
    adh_gnuplot_cmd(fg->gp, "set xlabel \"adhesion–elasticity parameter σ (eq 17)\"");
    adh_gnuplot_cmd(fg->gp, "set ylabel \"gap before the jump h (nm)\"");
    adh_gnuplot_cmd(fg->gp, "set key top left width -6");
    /* filled: a jump; open: contact came gradually, the last gap before it (as the paper) */
    adh_gnuplot_cmd(fg->gp, "plot %s index 0 using 1:($4 == 1 ? $2*1e9 : NaN) with points pt 7 ps 1.2 lc rgb adh_loading_color title \"jump (computed)\", "
                    "'' index 0 using 1:($4 == 1 ? NaN : $2*1e9) with points pt 6 ps 1.2 lc rgb adh_loading_color title \"last gap before contact, no jump\", "
                    "'' index 1 using 1:($2*1e9) with lines lw 2.5 dt 3 lc rgb \"#000000\" title \"eq 24\"",
                    adh_gp_path(dat, q, sizeof q));
    return fig_end(fg, "jump.png", 0);
}

int cli_figures_curve(int dirfd, size_t i, adh_run *run, char *why, size_t whylen)
{
    char name[64];
    snprintf(name, sizeof name, "run-%zu/force.tsv", i + 1);
    adh_run_init(run);
    FILE *f = adh_outdir_read(dirfd, name);
    if (!f) {
        snprintf(why, whylen, "cannot read %s: %s", name, adh_outdir_read_error(errno));
        return -1;
    }
    char line[1024];
    int rc = 0;
    while (rc == 0 && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || !strncmp(line, "h0\t", 3))
            continue;
        adh_obs o;
        memset(&o, 0, sizeof o);
        char *p = line, *end;
        o.h0 = strtod(p, &end);
        int ok = end != p && *end == '\t';
        o.F = ok ? strtod(end + 1, &end) : NAN;
        ok = ok && *end == '\t';
        for (int col = 2; ok && col < 8; col++)   /* to the path, the 9th */
            ok = (end = strchr(end + 1, '\t')) != NULL;
        o.path = ok ? (int)strtol(end + 1, &end, 10) : 0;
        if (!ok || *end != '\t' || adh_run_push_row(run, &o) != 0)
            rc = -1;
    }
    fclose(f);
    if (rc != 0) {
        snprintf(why, whylen, "%s: a row that does not read", name);
        adh_run_free(run);
    }
    return rc;
}

/* "ε = 1 pm" for an eps sweep's run (the paper's labels), else each key's
 * value. */
static void run_label(const adh_config *cfg, size_t i, char *label, size_t len)
{
    const adh_sweep *s = &cfg->sweep;
    size_t idx[ADH_SWEEP_MAX_AXES];
    adh_sweep_index(s, i, idx);
    label[0] = '\0';
    for (size_t k = 0; k < s->naxes; k++) {
        char text[64], piece[128];
        double v = adh_sweep_value(&s->axis[k], idx[k], text, sizeof text);
        if (s->naxes == 1 && !strcmp(s->axis[k].key, "solver.eps"))
            snprintf(piece, sizeof piece, "ε = %g pm", v * 1e12);
        else if (isnan(v))
            snprintf(piece, sizeof piece, "%s%s = %s", k ? ", " : "", s->axis[k].name, text);
        else
            snprintf(piece, sizeof piece, "%s%s = %g", k ? ", " : "", s->axis[k].name, v);
        size_t o = strlen(label), m = strlen(piece);
        if (o + m >= len)
            break;
        memcpy(label + o, piece, m + 1);
    }
}

/* Every run's rows of its force.tsv (h0, F) into f, a blank line between
 * branches and two between runs; the range they span. */
static int overlay_data(figure *fg, FILE *f, const cli_figures_curves *cv, size_t n, double *fbig, double *fmin_,
                        double *fmax_, double *xmin, double *xmax)
{
    for (size_t i = 0; i < n; i++) {
        adh_run r;
        char why[256];
        if (cli_figures_curve(cv->fd[cv->n > 1 ? i : 0], i, &r, why, sizeof why) != 0) {
            snprintf(fg->msg, fg->msglen, "%s", why);
            return -1;
        }
        for (size_t j = 0; j < r.nrows; j++) {
            const adh_obs *o = &r.rows[j];
            if (j > 0 && o->path != r.rows[j - 1].path)
                fputc('\n', f); /* a break between branches */
            fprintf(f, "%.17g\t%.17g\n", o->h0, o->F);
            *fbig = fmax(*fbig, fabs(o->F));
            *fmin_ = fmin(*fmin_, o->F);
            *fmax_ = fmax(*fmax_, o->F);
            *xmin = fmin(*xmin, o->h0);
            *xmax = fmax(*xmax, o->h0);
        }
        fprintf(f, "\n\n");
        adh_run_free(&r);
    }
    return 0;
}

/* The largest h0 where some run's |F| reaches thresh (read again from the
 * runs' force.tsv) into *active, which holds its start. 0, or -1 with msg. */
static int overlay_active(figure *fg, const cli_figures_curves *cv, size_t n, double thresh, double *active)
{
    for (size_t i = 0; i < n; i++) {
        adh_run r;
        char why[256];
        if (cli_figures_curve(cv->fd[cv->n > 1 ? i : 0], i, &r, why, sizeof why) != 0) {
            snprintf(fg->msg, fg->msglen, "%s", why);
            return -1;
        }
        for (size_t j = 0; j < r.nrows; j++)
            if (fabs(r.rows[j].F) >= thresh)
                *active = fmax(*active, r.rows[j].h0);
        adh_run_free(&r);
    }
    return 0;
}

/* Figure 7's second panel: each run's hysteresis (its row's, the area
 * between its branches) against eps, and the static curve's loop as the
 * line eps -> 0 tends to (the paper: the branches "will eventually
 * coalesce" about the equilibrium). Data in c.dat. */
static int hysteresis_panel(figure *fg, const adh_config *cfg, const cli_studyrow *rows, size_t n, double static_hyst)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "c.dat", dat, sizeof dat);
    if (!f)
        return -1;
    const adh_sweep_axis *eps = &cfg->sweep.axis[0];
    double hmax = isnan(static_hyst) ? 0 : static_hyst, emin = INFINITY, emax = 0;
    for (size_t i = 0; i < n; i++) {
        double h = rows[i].v[CLI_ROW_HYSTERESIS], e = adh_sweep_value(eps, i, NULL, 0);
        if (isfinite(h)) {
            fprintf(f, "%.17g\t%.17g\n", e, h);
            hmax = fmax(hmax, h);
            emin = fmin(emin, e);
            emax = fmax(emax, e);
        }
    }
    if (data_done(fg, f, dat) < 0)
        return -1;
    adh_gnuplot_cmd(fg->gp, "unset title");
    adh_gnuplot_cmd(fg->gp, "set origin 0.64,0");
    adh_gnuplot_cmd(fg->gp, "set size 0.36,0.95");
    adh_gnuplot_cmd(fg->gp, "set autoscale");
    adh_gnuplot_cmd(fg->gp, "set logscale x");
    if (emax > 0) /* the points off the frame, a tic at each */
        adh_gnuplot_cmd(fg->gp, "set xrange [%.17g:%.17g]", emin * 1e12 / 1.6, emax * 1e12 * 1.6);
    char *tics = NULL;
    size_t cap = 0;
    FILE *t = open_memstream(&tics, &cap);
    if (!t) {
        snprintf(fg->msg, fg->msglen, "out of memory");
        return -1;
    }
    fprintf(t, "set xtics (");
    for (size_t i = 0; i < n; i++)
        fprintf(t, "%s%.3g", i ? ", " : "", adh_sweep_value(eps, i, NULL, 0) * 1e12);
    fprintf(t, ")");
    fclose(t);
    adh_gnuplot_cmd(fg->gp, "%s", tics);
    free(tics);
    adh_gnuplot_cmd(fg->gp, "set xlabel \"ε (pm)\"");
    adh_gnuplot_cmd(fg->gp, "set ylabel \"hysteresis (fJ)\"");
    adh_gnuplot_cmd(fg->gp, "set yrange [0:%.17g]", 1.15 * hmax * 1e15);
    /* inside, where the hysteresis (growing with eps) leaves room: the
     * force panel's "outside below" would otherwise hold, under the label */
    adh_gnuplot_cmd(fg->gp, "set key inside top left");
    if (isnan(static_hyst))
        adh_gnuplot_cmd(fg->gp, "plot %s using ($1*1e12):($2*1e15) with linespoints lw 2 pt 7 lc rgb \"#1f3f8f\" "
                        "title \"relaxation\"", adh_gp_path(dat, q, sizeof q));
    else
        adh_gnuplot_cmd(fg->gp, "plot %s using ($1*1e12):($2*1e15) with linespoints lw 2 pt 7 lc rgb \"#1f3f8f\" "
                        "title \"relaxation\", %.17g with lines lw 3 lc rgb \"#000000\" dt (5,4) "
                        "title \"static (ε → 0)\"", adh_gp_path(dat, q, sizeof q), static_hyst * 1e15);
    adh_gnuplot_cmd(fg->gp, "unset multiplot");
    return 0;
}

/* Figure 7: every run's loading and unloading curves (read back from its
 * run-K/force.tsv), with the JKR equilibrium curve when the runs share one
 * material; an eps sweep adds the hysteresis panel. */
static int force_overlay(figure *fg, const adh_config *cfg, const cli_figures_curves *cv, const cli_studyrow *rows,
                         size_t n, double static_hyst)
{
    char dat[PATH_MAX + 16], jkr[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "a.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double fbig = 0, fmin_ = 0, fmax_ = 0, xmin = INFINITY, xmax = -INFINITY;
    int same_material = !adh_sweep_touches(&cfg->sweep, "material.") && !adh_sweep_axis_of(&cfg->sweep, "sigma");
    if (overlay_data(fg, f, cv, n, &fbig, &fmin_, &fmax_, &xmin, &xmax) != 0) {
        fclose(f);
        return -1;
    }
    /* the frame ends where every curve has flattened to zero */
    double active = xmin;
    if (overlay_active(fg, cv, n, 0.01 * (fmax_ - fmin_), &active) != 0) {
        fclose(f);
        return -1;
    }
    if (data_done(fg, f, dat) < 0)
        return -1;
    f = fig_data(fg, "b.dat", jkr, sizeof jkr);
    if (!f)
        return -1;
    /* JKR on h0 = z0 - overlap over the runs' positions: index 0 the
     * load-controlled part, index 1 the rest (the paper's break) */
    int jkr_parts = 0;
    if (same_material && isfinite(xmin)) {
        adh_model_curve mc;
        if (adh_jkr_drive_curve(&cfg->spec.mat, xmin, &mc) == 0 && mc.n_load > 1 && mc.n > mc.n_load) {
            for (size_t i = 0; i < mc.n; i++) {
                fprintf(f, "%.17g\t%.17g\n", mc.h0[i], mc.F[i]);
                if (i + 1 == mc.n_load)
                    fprintf(f, "\n\n%.17g\t%.17g\n", mc.h0[i], mc.F[i]);
            }
            jkr_parts = 2;
        }
    }
    if (data_done(fg, f, jkr) < 0)
        return -1;
    double fs;
    const char *fu;
    adh_force_unit(fbig, &fs, &fu);
    fig_begin(fg, "force.png");
    const adh_sweep *sw = &cfg->sweep;
    int panel = adh_sweep_fig7_panel(cfg);
    if (panel) {
        adh_gnuplot_cmd(fg->gp, "set multiplot title \"Force vs position for each %s, and the hysteresis (Figure 7)\"",
                        sw->axis[0].name);
        adh_gnuplot_cmd(fg->gp, "set origin 0,0");
        adh_gnuplot_cmd(fg->gp, "set size 0.64,0.95");
    } else {
        adh_gnuplot_cmd(fg->gp, "set title \"Force vs position for each %s (Figure 7)\"", sw->naxes == 1 ? sw->axis[0].name : "run");
    }
    adh_gnuplot_cmd(fg->gp, "set xlabel \"drive position h_0 (nm)\"");
    adh_gnuplot_cmd(fg->gp, "set ylabel \"force F (%s)\"", fu);
    /* the loops hang below zero and the curves are flat past the jump-out:
     * the range spans the data, to where the curves have flattened; the
     * key sits below the frame */
    adh_gnuplot_cmd(fg->gp, "set key outside below center horizontal");
    double top = fmax(fmax_, 0.0) + 0.04 * (fmax(fmax_, 0.0) - fmin_);
    adh_gnuplot_cmd(fg->gp, "set yrange [%.17g:%.17g]", (fmin_ - 0.04 * (fmax(fmax_, 0.0) - fmin_)) * fs, top * fs);
    adh_gnuplot_cmd(fg->gp, "set xrange [%.17g:%.17g]", xmin * 1e9, adh_plot_active_right(active, xmin, xmax) * 1e9);
    char *cmd = NULL;
    size_t cap = 0;
    FILE *c = open_memstream(&cmd, &cap);
    if (!c) {
        snprintf(fg->msg, fg->msglen, "out of memory");
        return -1;
    }
    fprintf(c, "plot 0 lc rgb \"#888888\" notitle");
    for (size_t i = 0; i < n; i++) {
        char label[256];
        run_label(cfg, i, label, sizeof label);
        /* light to heavy, as the paper's eps = 1, 0.5, 0.1 pm: the style's
         * sweep colours run from light to dark, the widths from thin up */
        fprintf(c, ", %s index %zu using ($1*1e9):($2*%.17g) with lines lw %.2g "
                   "lc rgb word(adh_sweep_colors, 1 + %zu %% words(adh_sweep_colors)) title \"%s\"",
                adh_gp_path(dat, q, sizeof q), i, fs, 1.0 + 2.0 * (double)i / (double)(n > 1 ? n - 1 : 1), i, label);
    }
    if (jkr_parts)
        fprintf(c, ", %s index 0 using ($1*1e9):($2*%.17g) with lines ls 3 lw 2 "
                   "title \"JKR equilibrium (grey: past its pull-off, fixed h_0)\", "
                   "'' index 1 using ($1*1e9):($2*%.17g) with lines ls 3 lw 2 lc rgb adh_model_disp_color "
                   "notitle", adh_gp_path(jkr, q, sizeof q), fs, fs);
    fclose(c);
    adh_gnuplot_cmd(fg->gp, "%s", cmd);
    free(cmd);
    if (panel && hysteresis_panel(fg, cfg, rows, n, static_hyst) != 0)
        return -1;
    return fig_end(fg, "force.png", 0);
}

int cli_figures_sweep(const adh_config *cfg, const cli_studyrow *rows, size_t n, const cli_figures_curves *curves,
                      double static_hysteresis, adh_outdir *out, char *msg, size_t msglen)
{
    if (msglen)
        msg[0] = '\0';
    adh_sweep_plot plot = adh_sweep_plot_kind(&cfg->sweep);
    if (!cfg->output.plot || plot == ADH_SWEEP_PLOT_NONE || n == 0)
        return 0;
    if (plot == ADH_SWEEP_PLOT_SPEED || plot == ADH_SWEEP_PLOT_SNAP)
        return cli_time_sweep_figure(cfg, rows, n, out, msg, msglen);
    figure fg;
    if (fig_open(&fg, cfg, out, msg, msglen) != 0)
        return -1;
    int rc = plot == ADH_SWEEP_PLOT_JUMP ? jump(&fg, cfg, rows, n)
           : plot == ADH_SWEEP_PLOT_FORCE ? force_overlay(&fg, cfg, curves, rows, n, static_hysteresis)
           : cli_mapfig_draw(&fg.ses, cfg, rows, n, plot == ADH_SWEEP_PLOT_MAP, msg, msglen);
    fig_close(&fg);
    return rc;
}
