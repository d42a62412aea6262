/* The figures of a sweep in physical time or of the instrument's spring:
 * speed.png (pull-off and hysteresis against the speed, the static
 * pull-offs at E0 and Einf as lines) and snap.png (snap-in and snap-out
 * against the spring's stiffness). */
#include "cli/timerun.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"
#include "cli/static.h"
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

/* The static pull-off of spec's material at modulus E (NAN if the curve
 * fails). */
static double static_pulloff(const adh_run_spec *spec, double E, const adh_grid *g, const adh_kernel *k)
{
    adh_run_spec s = *spec;
    s.mat.E = E;
    s.mode = ADH_MODE_STATIC;
    adh_run run;
    adh_run_init(&run);
    adh_static_result res;
    int rc = cli_static_run(&s, g, k, NULL, NULL, &run, &res);
    adh_run_free(&run);
    return rc == ADH_SUCCESS ? res.pulloff_F : NAN;
}

/* An energy's unit: fJ or aJ, whichever keeps the numbers above 1. */
static void energy_unit(double emax, double *scale, const char **name)
{
    *scale = emax >= 1e-15 ? 1e15 : 1e18;
    *name = emax >= 1e-15 ? "fJ" : "aJ";
}

static int speed_figure(tfig *fg, const adh_config *cfg, const adh_grid *g, const adh_kernel *k,
                        const cli_time_out *tout, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(&fg->ses, "speed.dat", dat, sizeof dat, fg->msg, fg->msglen);
    if (!f)
        return -1;
    double fbig = 0, ebig = 0;
    for (size_t i = 0; i < n; i++) {
        const adh_visco_result *r = &tout[i].res;
        fprintf(f, "%.17g\t%.17g\t%.17g\n", cfg->sweep.values[i], -r->pulloff_F, r->hysteresis);
        if (isfinite(r->pulloff_F))
            fbig = fmax(fbig, fabs(r->pulloff_F));
        if (isfinite(r->hysteresis))
            ebig = fmax(ebig, fabs(r->hysteresis));
    }
    if (data_close(fg, f, dat) < 0)
        return -1;
    adh_run_spec s;
    adh_config_sweep_run(cfg, 0, &s);
    double p0 = static_pulloff(&s, s.mat.E, g, k), pinf = static_pulloff(&s, adh_config_einf(&s), g, k);
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
    adh_session_begin(&fg->ses, "speed", "speed.png");
    adh_gnuplot *gp = fg->ses.gp;
    adh_gnuplot_cmd(gp, "set title \"Pull-off and hysteresis against the %s speed (E0 = %s, E∞ = %s, τ = %s)\"",
                    cfg->sweep.kind == ADH_SWEEP_SPEED_OUT ? "retraction" : "drive", e0, ei, tau);
    adh_gnuplot_cmd(gp, "set logscale x");
    adh_gnuplot_cmd(gp, "set format x \"10^{%%L}\"");
    adh_gnuplot_cmd(gp, "set xlabel \"%s speed (m/s)\"", cfg->sweep.kind == ADH_SWEEP_SPEED_OUT
                    ? "retraction (base)" : "base");
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
    adh_gnuplot_cmd(gp, "plot %s using 1:($2*%.17g) with linespoints pt 7 lw 2 lc rgb \"#c0392b\" title \"pull-off\", "
                        "'' using 1:($3*%.17g) axes x1y2 with linespoints pt 5 lw 2 lc rgb \"#1f3f8f\" title \"hysteresis\", "
                        "%.17g with lines dt 2 lw 2 lc rgb \"#27ae60\" title \"static pull-off at E0\", "
                        "%.17g with lines dt 4 lw 2 lc rgb \"#8e44ad\" title \"static pull-off at E∞\", "
                        "%.17g with lines dt 3 lw 2 lc rgb \"#e67e22\" title \"E∞/E0 × the one at E0 (crack theory's bound)\"",
                    adh_gp_path(dat, q, sizeof q), fs, es, -p0 * fs, -pinf * fs, -ratio * p0 * fs);
    char why[1024];
    if (adh_session_end(&fg->ses, "speed.png", why, sizeof why) != 0) {
        snprintf(fg->msg, fg->msglen, "speed.png: %s", why);
        return -1;
    }
    return 0;
}

/* Run i's snap points: from its events (physical time) or its static
 * curve's base turns; rigid spheres' from eq 22 on the same positions. */
static void snap_points(const adh_config *cfg, size_t i, const adh_run *r, const cli_time_out *o, double *v)
{
    double kk = cfg->sweep.values[i];
    for (int j = 0; j < 5; j++)
        v[j] = NAN;
    if (cfg->spec.mode == ADH_MODE_TIME) {
        for (size_t e = 0; e < o->nev; e++) {
            const adh_visco_event *ev = &o->ev[e];
            if (ev->kind != ADH_VISCO_JUMP)
                continue;
            if (ev->path == 0 && isnan(v[0]))
                v[0] = ev->h0, v[1] = ev->base;
            if (ev->path > 0)
                v[2] = ev->h0, v[3] = ev->base;
        }
    } else {
        double store[CLI_TIME_SNAP_KEYS];
        cli_tables_extra x[CLI_TIME_SNAP_KEYS];
        cli_time_snap_keys(r, kk, store, x);
        v[0] = store[1], v[1] = store[2], v[2] = store[3], v[3] = store[4];
    }
    /* rigid spheres: the same rows with eq 22's force */
    adh_run rigid;
    adh_run_init(&rigid);
    for (size_t j = 0; j < r->nrows; j++) {
        adh_obs row = r->rows[j];
        row.F = row.F_rigid;
        row.path = 0;
        if (adh_run_push_row(&rigid, &row) != ADH_SUCCESS)
            break;
    }
    double at, base;
    if (adh_visco_spring_folds(&rigid, kk, &at, &base, 1) >= 1)
        v[4] = base;
    adh_run_free(&rigid);
}

static int snap_figure(tfig *fg, const adh_config *cfg, const adh_run *runs, const cli_time_out *tout, size_t n)
{
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(&fg->ses, "snap.dat", dat, sizeof dat, fg->msg, fg->msglen);
    if (!f)
        return -1;
    for (size_t i = 0; i < n; i++) {
        double v[5];
        snap_points(cfg, i, &runs[i], &tout[i], v);
        fprintf(f, "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", cfg->sweep.values[i], v[0], v[1], v[2], v[3], v[4]);
    }
    if (data_close(fg, f, dat) < 0)
        return -1;
    adh_session_begin(&fg->ses, "snap", "snap.png");
    adh_gnuplot *gp = fg->ses.gp;
    char e[32];
    adh_format_modulus(cfg->spec.mat.E, e, sizeof e);
    double kmin = INFINITY, kmax = 0;
    for (size_t i = 0; i < n; i++)
        kmin = fmin(kmin, cfg->sweep.values[i]), kmax = fmax(kmax, cfg->sweep.values[i]);
    adh_gnuplot_cmd(gp, "set title \"Snap-in against the spring (E = %s, R = %.3g µm)%s\"", e, cfg->spec.mat.R * 1e6,
                    cfg->spec.mode == ADH_MODE_TIME ? ", in physical time" : "");
    adh_gnuplot_cmd(gp, "set logscale xy");
    adh_gnuplot_cmd(gp, "set xrange [%.17g:%.17g]", kmin / 1.3, kmax * 1.3);
    adh_gnuplot_cmd(gp, "set xlabel \"spring stiffness k (N/m)\"");
    adh_gnuplot_cmd(gp, "set ylabel \"snap-in distance (nm)\"");
    adh_gnuplot_cmd(gp, "set key top right");
    /* the snap-out's base lies F/k out, microns for a soft spring: sweep.tsv has it */
    adh_gnuplot_cmd(gp, "plot %s using 1:($3*1e9) with linespoints pt 7 lw 2 lc rgb \"#1f3f8f\" title \"base (cantilever's support)\", "
                        "'' using 1:($2*1e9) with linespoints pt 6 lw 2 lc rgb \"#c0392b\" title \"sphere h_0 (tip)\", "
                        "'' using 1:($6*1e9) with lines dt 2 lw 2 lc rgb \"#000000\" title \"base, rigid spheres (eq 22)\"",
                    adh_gp_path(dat, q, sizeof q));
    char why[1024];
    if (adh_session_end(&fg->ses, "snap.png", why, sizeof why) != 0) {
        snprintf(fg->msg, fg->msglen, "snap.png: %s", why);
        return -1;
    }
    return 0;
}

int cli_time_sweep_figure(const adh_config *cfg, const adh_grid *g, const adh_kernel *k, const adh_run *runs,
                          const cli_time_out *tout, size_t n, adh_outdir *out, char *msg, size_t msglen)
{
    tfig fg = { .msg = msg, .msglen = msglen };
    if (adh_session_open(&fg.ses, out, "gnuplot-figures.log", cfg->output.gnuplot_style, cfg->spec.relax.cancel,
                         msg, msglen) != 0)
        return -1;
    int rc = cfg->sweep.plot == ADH_SWEEP_PLOT_SPEED ? speed_figure(&fg, cfg, g, k, tout, n)
                                                     : snap_figure(&fg, cfg, runs, tout, n);
    adh_session_close(&fg.ses);
    return rc;
}
