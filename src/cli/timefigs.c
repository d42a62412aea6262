/* The figures of a sweep in physical time or of the instrument's spring:
 * speed.png (pull-off and hysteresis against the speed, the static
 * pull-offs at E0 and Einf as lines) and snap.png (snap-in and snap-out
 * against the spring's stiffness). */
#include "cli/figures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"
#include "cli/interrupt.h"
#include "cli/static.h"
#include "cli/studyrow.h"
#include "plot/labels.h"
#include "plot/session.h"

typedef struct tfig {
    adh_session ses;
    char *msg;
    size_t msglen;
} tfig;

static int data_close(tfig *fg, FILE *f, const char *path)
{
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        snprintf(fg->msg, fg->msglen, "cannot write %.3000s", path);
        return -1;
    }
    return 0;
}

/* The static pull-off of spec's material at modulus E on spec's grid
 * (NAN if the curve fails). */
static double static_pulloff(const adh_run_spec *spec, double E)
{
    adh_run_spec s = *spec;
    s.mat.E = E;
    s.mode = ADH_MODE_STATIC;
    adh_grid *g = adh_config_grid_alloc(&s);
    int st = ADH_ENOMEM;
    adh_kernel *k = g ? adh_config_kernel_alloc(&s, g, &st) : NULL;
    adh_run run;
    adh_run_init(&run);
    adh_static_result res;
    int rc = k ? cli_static_run(&s, g, k, cli_interrupt_step, NULL, &run, &res) : st;
    adh_run_free(&run);
    adh_kernel_free(k);
    adh_grid_free(g);
    return rc == ADH_SUCCESS ? res.pulloff_F : NAN;
}

/* Row i's swept value (the study's one key). */
static double swept(const adh_config *cfg, const cli_studyrow *row)
{
    char text[64];
    return adh_sweep_value(&cfg->sweep.axis[0], row->run, text, sizeof text);
}

/* An energy's unit: fJ or aJ, whichever keeps the numbers above 1. */
static void energy_unit(double emax, double *scale, const char **name)
{
    *scale = emax >= 1e-15 ? 1e15 : 1e18;
    *name = emax >= 1e-15 ? "fJ" : "aJ";
}

static int speed_figure(tfig *fg, const adh_config *cfg, const cli_studyrow *rows, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(&fg->ses, "speed.dat", dat, sizeof dat, fg->msg, fg->msglen);
    if (!f)
        return -1;
    double fbig = 0, ebig = 0, vmin = INFINITY, vmax = 0;
    for (size_t i = 0; i < n; i++) {
        double pull = rows[i].v[CLI_ROW_PULLOFF], hyst = rows[i].v[CLI_ROW_HYSTERESIS], v = swept(cfg, &rows[i]);
        fprintf(f, "%.17g\t%.17g\t%.17g\n", v, -pull, hyst);
        vmin = fmin(vmin, v), vmax = fmax(vmax, v);
        if (isfinite(pull))
            fbig = fmax(fbig, fabs(pull));
        if (isfinite(hyst))
            ebig = fmax(ebig, fabs(hyst));
    }
    if (data_close(fg, f, dat) < 0)
        return -1;
    adh_run_spec s;
    adh_config_sweep_run(cfg, 0, &s);
    double p0 = static_pulloff(&s, s.mat.E), pinf = static_pulloff(&s, adh_config_einf(&s));
    double ratio = adh_config_einf(&s) / s.mat.E;   /* crack theory's bound on the enhancement */
    fbig = fmax(fbig, fmax(isfinite(p0) ? ratio * fabs(p0) : 0, isfinite(pinf) ? fabs(pinf) : 0));
    double fs, es;
    const char *fu, *eu;
    adh_force_unit(fbig, &fs, &fu);
    energy_unit(ebig, &es, &eu);
    char e0[32], ei[32], tau[32];
    adh_format_modulus(s.mat.E, e0, sizeof e0);
    adh_format_modulus(adh_config_einf(&s), ei, sizeof ei);
    adh_format_quantity(s.time.tau, ADH_Q_TIME, 3, tau, sizeof tau);
    int out = !strcmp(cfg->sweep.axis[0].key, "protocol.speed_out");
    adh_session_begin(&fg->ses, "speed", "speed.png");
    adh_gnuplot *gp = fg->ses.gp;
    adh_gnuplot_cmd(gp, "set title \"Pull-off and hysteresis against the %s speed (E0 = %s, E∞ = %s, τ = %s)\"",
                    out ? "retraction" : "drive", e0, ei, tau);
    adh_gnuplot_cmd(gp, "set logscale x");
    if (vmin == vmax)   /* one speed: a decade either side (autoscale found an empty range) */
        adh_gnuplot_cmd(gp, "set xrange [%.17g:%.17g]", vmin / 10, vmax * 10);
    adh_gnuplot_cmd(gp, "set format x \"10^{%%L}\"");
    adh_gnuplot_cmd(gp, "set xlabel \"%s speed (m/s)\"", out ? "retraction (base)" : "base");
    adh_gnuplot_cmd(gp, "set ylabel \"adhesion -F_{pull-off} (%s)\"", fu);
    adh_gnuplot_cmd(gp, "set y2label \"hysteresis (%s)\"", eu);
    adh_gnuplot_cmd(gp, "set ytics nomirror");
    adh_gnuplot_cmd(gp, "set y2tics");
    /* the data in the lower two thirds, the key above them */
    adh_gnuplot_cmd(gp, "set yrange [0:%.17g]", 1.5 * fbig * fs);
    adh_gnuplot_cmd(gp, "set y2range [0:%.17g]", 1.5 * ebig * es);
    adh_gnuplot_cmd(gp, "set key top left Left reverse maxrows 3 width -4");
    /* where the drive moves z0 in tau: below it the solid relaxes as it goes */
    adh_gnuplot_cmd(gp, "set arrow from %.17g, graph 0 to %.17g, graph 1 nohead dt 3 lc rgb \"#888888\"",
                    s.mat.z0 / s.time.tau, s.mat.z0 / s.time.tau);
    adh_gnuplot_cmd(gp, "set label \"V τ = z_0\" at %.17g, graph 0.72 offset 0.5,0 tc rgb \"#666666\"",
                    s.mat.z0 / s.time.tau);
    /* the palette's (share/adhere/gnuplot/style.gp): the measured pair in
     * the run's colours, the static references in the static curve's, the
     * bound black, as the force plots draw their models */
    adh_gnuplot_cmd(gp, "plot %s using 1:($2*%.17g) with linespoints pt 7 lw 2 lc rgb adh_loading_color title \"pull-off\", "
                        "'' using 1:($3*%.17g) axes x1y2 with linespoints pt 5 lw 2 lc rgb word(adh_unload_colors, 1) title \"hysteresis\", "
                        "%.17g with lines dt 2 lw 2 lc rgb adh_static_color title \"static pull-off at E0\", "
                        "%.17g with lines dt 4 lw 2 lc rgb adh_static_color title \"static pull-off at E∞\", "
                        "%.17g with lines dt 3 lw 1.5 lc rgb \"#000000\" title \"E∞/E0 × the one at E0 (crack theory's bound)\"",
                    adh_gp_path(dat, q, sizeof q), fs, es, -p0 * fs, -pinf * fs, -ratio * p0 * fs);
    char why[1024];
    if (adh_session_end(&fg->ses, "speed.png", why, sizeof why) != 0) {
        snprintf(fg->msg, fg->msglen, "speed.png: %s", why);
        return -1;
    }
    return 0;
}

static int snap_figure(tfig *fg, const adh_config *cfg, const cli_studyrow *rows, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(&fg->ses, "snap.dat", dat, sizeof dat, fg->msg, fg->msglen);
    if (!f)
        return -1;
    double kmin = INFINITY, kmax = 0;
    for (size_t i = 0; i < n; i++) {
        const double *v = rows[i].v;
        double k = swept(cfg, &rows[i]);
        kmin = fmin(kmin, k), kmax = fmax(kmax, k);
        fprintf(f, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", k, v[CLI_ROW_SNAP_IN_H0], v[CLI_ROW_SNAP_IN_BASE],
                v[CLI_ROW_SNAP_OUT_H0], v[CLI_ROW_SNAP_OUT_BASE], v[CLI_ROW_SNAP_IN_RIGID]);
    }
    if (data_close(fg, f, dat) < 0)
        return -1;
    adh_session_begin(&fg->ses, "snap", "snap.png");
    adh_gnuplot *gp = fg->ses.gp;
    char e[32];
    adh_format_modulus(cfg->spec.mat.E, e, sizeof e);
    adh_gnuplot_cmd(gp, "set title \"Snap-in against the spring (E = %s, R = %.3g µm)%s\"", e, cfg->spec.mat.R * 1e6,
                    cfg->spec.mode == ADH_MODE_TIME ? ", in physical time" : "");
    adh_gnuplot_cmd(gp, "set logscale xy");
    adh_gnuplot_cmd(gp, "set xrange [%.17g:%.17g]", kmin / 1.3, kmax * 1.3);
    adh_gnuplot_cmd(gp, "set xlabel \"spring stiffness k (N/m)\"");
    adh_gnuplot_cmd(gp, "set ylabel \"snap-in distance (nm)\"");
    adh_gnuplot_cmd(gp, "set key top right");
    /* the snap-out's base lies F/k out, microns for a soft spring: sweep.tsv has it */
    adh_gnuplot_cmd(gp, "plot %s using 1:($3*1e9) with linespoints pt 7 lw 2 lc rgb adh_loading_color title \"base (cantilever's support)\", "
                        "'' using 1:($2*1e9) with linespoints pt 6 lw 2 lc rgb word(adh_unload_colors, 1) title \"sphere h_0 (tip)\", "
                        "'' using 1:($6*1e9) with lines dt 2 lw 2 lc rgb \"#000000\" title \"base, rigid spheres (eq 22)\"",
                    adh_gp_path(dat, q, sizeof q));
    char why[1024];
    if (adh_session_end(&fg->ses, "snap.png", why, sizeof why) != 0) {
        snprintf(fg->msg, fg->msglen, "snap.png: %s", why);
        return -1;
    }
    return 0;
}

int cli_time_sweep_figure(const adh_config *cfg, const cli_studyrow *rows, size_t n, adh_outdir *out, char *msg,
                          size_t msglen)
{
    tfig fg = { .msg = msg, .msglen = msglen };
    if (adh_session_open(&fg.ses, out, "gnuplot-figures.log", cfg->output.gnuplot_style, cfg->spec.relax.cancel,
                         msg, msglen) != 0)
        return -1;
    int rc = adh_sweep_plot_kind(&cfg->sweep) == ADH_SWEEP_PLOT_SPEED ? speed_figure(&fg, cfg, rows, n)
                                                                      : snap_figure(&fg, cfg, rows, n);
    adh_session_close(&fg.ses);
    return rc;
}
