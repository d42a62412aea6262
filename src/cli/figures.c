#include "cli/figures.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adhere/cycle.h"
#include "adhere/models.h"
#include "cli/jumps.h"
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

/* Figure 3: the gap just before the jump against sigma, with eq 24. */
static int jump(figure *fg, const adh_config *cfg, const adh_run *runs, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "a.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double smin = INFINITY, smax = -INFINITY, hlo = INFINITY, hhi = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        adh_run_spec rc;
        adh_config_sweep_run(cfg, i, &rc);
        adh_derived d;
        adh_material_derive(&rc.mat, &d);
        double h = cli_jumps_gap_before(&runs[i]);
        smin = fmin(smin, d.sigma), smax = fmax(smax, d.sigma);
        if (isfinite(h)) {
            fprintf(f, "%.17g\t%.17g\t%.17g\t%d\n", d.sigma, h, d.h_star, cli_jumps_jumped(&runs[i], rc.proto.step));
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
    adh_gnuplot_cmd(fg->gp, "set key top left");
    /* filled: a jump; open: contact came gradually, the last gap before it (as the paper) */
    adh_gnuplot_cmd(fg->gp, "plot %s index 0 using 1:($4 == 1 ? $2*1e9 : NaN) with points pt 7 ps 1.2 lc rgb adh_loading_color title \"jump (computed)\", "
                    "'' index 0 using 1:($4 == 1 ? NaN : $2*1e9) with points pt 6 ps 1.2 lc rgb adh_loading_color title \"last gap before contact, no jump\", "
                    "'' index 1 using 1:($2*1e9) with lines lw 2.5 dt 3 lc rgb \"#000000\" title \"eq 24\"",
                    adh_gp_path(dat, q, sizeof q));
    return fig_end(fg, "jump.png", 0);
}

/* Figure 7's second panel: each run's hysteresis (the area between its
 * branches, adh_cycle_hysteresis) against eps, and the static curve's
 * loop as the line eps -> 0 tends to (the paper: the branches "will
 * eventually coalesce" about the equilibrium). Data in c.dat. */
static int hysteresis_panel(figure *fg, const adh_config *cfg, const adh_run *runs, size_t n, double static_hyst)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "c.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double hmax = isnan(static_hyst) ? 0 : static_hyst, emin = INFINITY, emax = 0;
    for (size_t i = 0; i < n; i++) {
        const adh_turn_result *mt = adh_run_main_turn(&runs[i]);
        double h = mt ? adh_cycle_hysteresis(runs[i].rows, runs[i].nrows, mt->path) : NAN;
        if (isfinite(h)) {
            fprintf(f, "%.17g\t%.17g\n", cfg->sweep.values[i], h);
            hmax = fmax(hmax, h);
            emin = fmin(emin, cfg->sweep.values[i]);
            emax = fmax(emax, cfg->sweep.values[i]);
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
    char tics[ADH_MAX_SWEEP * 32 + 16] = "set xtics (", one[32];
    for (size_t i = 0; i < n && i < ADH_MAX_SWEEP; i++) {
        int w = snprintf(one, sizeof one, "%s%.3g", i ? ", " : "", cfg->sweep.values[i] * 1e12);
        if (w > 0 && strlen(tics) + (size_t)w + 2 < sizeof tics)
            strcat(tics, one);
    }
    adh_gnuplot_cmd(fg->gp, "%s)", tics);
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

/* Figure 7: every run's loading and unloading curves, with the JKR
 * equilibrium curve when the runs share one material; an eps sweep adds
 * the hysteresis panel. */
static int force_overlay(figure *fg, const adh_config *cfg, const adh_run *runs, size_t n, double static_hyst)
{
    char dat[PATH_MAX + 16], jkr[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = fig_data(fg, "a.dat", dat, sizeof dat);
    if (!f)
        return -1;
    double fbig = 0, fmin_ = 0, fmax_ = 0, xmin = INFINITY, xmax = -INFINITY;
    int same_material = cfg->sweep.kind == ADH_SWEEP_EPS;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < runs[i].nrows; j++) {
            const adh_obs *o = &runs[i].rows[j];
            if (j > 0 && o->path != runs[i].rows[j - 1].path)
                fputc('\n', f); /* a break between branches */
            fprintf(f, "%.17g\t%.17g\n", o->h0, o->F);
            fbig = fmax(fbig, fabs(o->F));
            fmin_ = fmin(fmin_, o->F);
            fmax_ = fmax(fmax_, o->F);
            xmin = fmin(xmin, o->h0);
            xmax = fmax(xmax, o->h0);
        }
        fprintf(f, "\n\n");
    }
    /* the frame ends where every curve has flattened to zero */
    double active = xmin;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < runs[i].nrows; j++)
            if (fabs(runs[i].rows[j].F) >= 0.01 * (fmax_ - fmin_))
                active = fmax(active, runs[i].rows[j].h0);
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
    if (same_material) {
        adh_gnuplot_cmd(fg->gp, "set multiplot title \"Force vs position for each %s, and the hysteresis (Figure 7)\"",
                        adh_sweep_name(cfg->sweep.kind));
        adh_gnuplot_cmd(fg->gp, "set origin 0,0");
        adh_gnuplot_cmd(fg->gp, "set size 0.64,0.95");
    } else {
        adh_gnuplot_cmd(fg->gp, "set title \"Force vs position for each %s (Figure 7)\"", adh_sweep_name(cfg->sweep.kind));
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
        char label[64];
        if (cfg->sweep.kind == ADH_SWEEP_EPS)
            snprintf(label, sizeof label, "ε = %g pm", cfg->sweep.values[i] * 1e12);
        else
            snprintf(label, sizeof label, "%s = %g", adh_sweep_name(cfg->sweep.kind), cfg->sweep.values[i]);
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
    if (same_material && hysteresis_panel(fg, cfg, runs, n, static_hyst) != 0)
        return -1;
    return fig_end(fg, "force.png", 0);
}

int cli_figures_sweep(const adh_config *cfg, const adh_run *runs, size_t n, double static_hysteresis,
                      adh_outdir *out, char *msg, size_t msglen)
{
    if (msglen)
        msg[0] = '\0';
    if (!cfg->output.plot || cfg->sweep.plot == ADH_SWEEP_PLOT_NONE || n == 0)
        return 0;
    figure fg;
    if (fig_open(&fg, cfg, out, msg, msglen) != 0)
        return -1;
    int rc = cfg->sweep.plot == ADH_SWEEP_PLOT_JUMP ? jump(&fg, cfg, runs, n) : force_overlay(&fg, cfg, runs, n, static_hysteresis);
    fig_close(&fg);
    return rc;
}
