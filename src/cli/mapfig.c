#include "cli/mapfig.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/labels.h"

/* How a column is drawn: its label, and the scale to its unit. */
static void unit_of(const char *col, const cli_studyrow *rows, size_t n, int c, double *scale, char *label, size_t len)
{
    static const char *const forces[] = { "pulloff_F", "max_load", "F_jkr", "F_dmt", "pulloff_F_disp" };
    static const char *const lengths[] = { "jump_in_h0", "jump_out_h0", "h_before", "h_star", "turn_h0", "pulloff_h0",
                                           "a_turn", "start", "step", "spacing", "rmax", "z0" };
    *scale = 1;
    for (size_t k = 0; k < sizeof forces / sizeof forces[0]; k++)
        if (!strcmp(col, forces[k])) {
            double big = 0;
            const char *u;
            for (size_t i = 0; i < n; i++)
                if (isfinite(rows[i].v[c]))
                    big = fmax(big, fabs(rows[i].v[c]));
            adh_force_unit(big, scale, &u);
            snprintf(label, len, "%s (%s)", col, u);
            return;
        }
    for (size_t k = 0; k < sizeof lengths / sizeof lengths[0]; k++)
        if (!strcmp(col, lengths[k])) {
            *scale = 1e9;
            snprintf(label, len, "%s (nm)", col);
            return;
        }
    snprintf(label, len, "%s", col);
}

/* set xtics/ytics with the axis's values at their indices, at most about
 * a dozen labelled up the side, half that across (labels like 2.73e-20 J
 * side by side: a dozen overlapped on the 900-pixel figure). */
static void index_tics(adh_gnuplot *gp, const char *which, const adh_sweep_axis *a)
{
    size_t most = which[0] == 'x' ? 6 : 12;
    char *cmd = NULL;
    size_t cap = 0;
    FILE *c = open_memstream(&cmd, &cap);
    if (!c)
        return;
    size_t every = (a->n + most - 1) / most;
    fprintf(c, "set %s (", which);
    for (size_t j = 0; j < a->n; j += every) {
        char text[64], label[64], q[ADH_GP_QUOTED_SIZE(64)];
        double v = adh_sweep_value(a, j, text, sizeof text);
        if (isnan(v))
            snprintf(label, sizeof label, "%s", text);
        else
            adh_format_quantity(v, (adh_quantity)a->quantity, 3, label, sizeof label);
        fprintf(c, "%s%s %zu", j ? ", " : "", adh_gp_quoted(label, q, sizeof q), j);
    }
    fprintf(c, ")");
    fclose(c);
    adh_gnuplot_cmd(gp, "%s", cmd);
    free(cmd);
}

/* The map: the first key down (rows of the image), the second across;
 * other keys at their first value. */
static int map(adh_session *ses, const adh_config *cfg, const cli_studyrow *rows, int c, const char *col, double scale,
               const char *label, char *why, size_t whylen)
{
    const adh_sweep *s = &cfg->sweep;
    const adh_sweep_axis *y = &s->axis[0], *x = &s->axis[1];
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(ses, "m.dat", dat, sizeof dat, why, whylen);
    if (!f)
        return -1;
    size_t stride = 1;
    for (size_t k = 2; k < s->naxes; k++)
        stride *= s->axis[k].n;
    for (size_t a = 0; a < y->n; a++) {
        for (size_t b = 0; b < x->n; b++)
            fprintf(f, "%zu\t%zu\t%.17g\n", b, a, rows[(a * x->n + b) * stride].v[c] * scale);
        fputc('\n', f);
    }
    if (fclose(f) != 0) {
        snprintf(why, whylen, "cannot write %.3000s", dat);
        return -1;
    }
    adh_session_begin(ses, "map.png", "map.png");
    adh_gnuplot *gp = ses->gp;
    adh_gnuplot_cmd(gp, "set title \"%s over %s and %s%s\" noenhanced", col, y->name, x->name,
                    s->naxes > 2 ? " (the other keys at their first value)" : "");
    adh_gnuplot_cmd(gp, "set xlabel \"%s\"", x->name);
    adh_gnuplot_cmd(gp, "set ylabel \"%s\"", y->name);
    adh_gnuplot_cmd(gp, "set cblabel \"%s\" noenhanced", label);
    adh_gnuplot_cmd(gp, "set xrange [-0.5:%.17g]", (double)x->n - 0.5);
    adh_gnuplot_cmd(gp, "set yrange [-0.5:%.17g]", (double)y->n - 0.5);
    adh_gnuplot_cmd(gp, "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21908d', 3 '#5dc963', 4 '#fde725')");
    adh_gnuplot_cmd(gp, "unset key");
    index_tics(gp, "xtics", x);
    index_tics(gp, "ytics", y);
    adh_gnuplot_cmd(gp, "plot %s using 1:2:3 with image", adh_gp_path(dat, q, sizeof q));
    return adh_session_end(ses, "map.png", why, whylen);
}

/* An axis's values in a unit people read: lengths in nm, pressures in
 * MPa or GPa, the rest in SI. */
static double axis_scale(const adh_sweep_axis *x, const char **unit)
{
    double big = 0;
    for (size_t j = 0; j < x->n; j++)
        big = fmax(big, fabs(adh_sweep_value(x, j, NULL, 0)));
    *unit = adh_quantity_unit((adh_quantity)x->quantity)[0] ? adh_quantity_unit((adh_quantity)x->quantity) : "1";
    if (x->quantity == ADH_Q_LENGTH) {
        *unit = "nm";
        return 1e9;
    }
    if (x->quantity == ADH_Q_PRESSURE) {
        *unit = big >= 1e9 ? "GPa" : "MPa";
        return big >= 1e9 ? 1e-9 : 1e-6;
    }
    return 1;
}

/* The column against the last key: a curve for each value of the others
 * (their combination in the key). */
static int curves(adh_session *ses, const adh_config *cfg, const cli_studyrow *rows, size_t n, int c,
                  const char *col, double scale, const char *label, char *why, size_t whylen)
{
    const adh_sweep *s = &cfg->sweep;
    const adh_sweep_axis *x = &s->axis[s->naxes - 1];
    size_t ncurves = n / x->n;
    char dat[PATH_MAX + 16], q[ADH_GP_PATH_SIZE];
    FILE *f = adh_session_data(ses, "c.dat", dat, sizeof dat, why, whylen);
    if (!f)
        return -1;
    int words = 0, positive = 1;
    double lo = INFINITY, hi = 0;
    for (size_t j = 0; j < x->n; j++) {
        double v = adh_sweep_value(x, j, NULL, 0);
        words |= isnan(v);
        positive &= v > 0;
        lo = fmin(lo, v), hi = fmax(hi, v);
    }
    const char *unit;
    double xs = axis_scale(x, &unit);
    for (size_t g = 0; g < ncurves; g++) {
        for (size_t j = 0; j < x->n; j++)
            fprintf(f, "%.17g\t%.17g\n", words ? (double)j : adh_sweep_value(x, j, NULL, 0) * xs,
                    rows[g * x->n + j].v[c] * scale);
        fprintf(f, "\n\n");
    }
    if (fclose(f) != 0) {
        snprintf(why, whylen, "cannot write %.3000s", dat);
        return -1;
    }
    adh_session_begin(ses, "curves.png", "curves.png");
    adh_gnuplot *gp = ses->gp;
    adh_gnuplot_cmd(gp, "set title \"%s against %s\" noenhanced", col, x->name);
    adh_gnuplot_cmd(gp, "set xlabel \"%s (%s)\" noenhanced", x->name, unit);
    adh_gnuplot_cmd(gp, "set ylabel \"%s\" noenhanced", label);
    if (words)
        index_tics(gp, "xtics", x);
    else if (positive && (x->spacing == ADH_SWEEP_LOG || hi >= 100 * lo))
        /* a log range, or a list over two decades or more (speeds, springs):
         * on a linear axis all but the largest values crowd at its left */
        adh_gnuplot_cmd(gp, "set logscale x");
    adh_gnuplot_cmd(gp, ncurves > 12 ? "unset key" : "set key outside right");
    char *cmd = NULL;
    size_t cap = 0;
    FILE *m = open_memstream(&cmd, &cap);
    if (!m) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    fprintf(m, "plot");
    for (size_t g = 0; g < ncurves; g++) {
        char title[256] = "", tq[ADH_GP_QUOTED_SIZE(256)];
        if (s->naxes > 1) {
            adh_sweep_describe(s, g * x->n, title, sizeof title);
            char *last = strrchr(title, ',');   /* the last key's value is the abscissa */
            if (last)
                *last = '\0';
            else
                title[0] = '\0';
        }
        fprintf(m, "%s %s index %zu using 1:2 with linespoints lw 2 pt 7 title %s", g ? "," : "",
                adh_gp_path(dat, q, sizeof q), g, adh_gp_quoted(title[0] ? title : col, tq, sizeof tq));
    }
    fclose(m);
    adh_gnuplot_cmd(gp, "%s", cmd);
    free(cmd);
    return adh_session_end(ses, "curves.png", why, whylen);
}

/* Without map = COLUMN: the pull-off, or where no run has one (rigid
 * spheres do not unload, an approach stops at contact) the first of these
 * that some run has. */
static const char *auto_column(const cli_studyrow *rows, size_t n)
{
    static const char *const cols[] = { "pulloff_F", "max_load", "jump_in_h0", "h_before" };
    for (size_t k = 0; k < sizeof cols / sizeof cols[0]; k++) {
        int c = cli_studyrow_column(cols[k]);
        for (size_t i = 0; i < n; i++)
            if (isfinite(rows[i].v[c]))
                return cols[k];
    }
    return cols[0];
}

int cli_mapfig_draw(adh_session *ses, const adh_config *cfg, const cli_studyrow *rows, size_t n, int as_map,
                    char *why, size_t whylen)
{
    const char *col = cfg->sweep.map[0] ? cfg->sweep.map : auto_column(rows, n);
    int c = cli_studyrow_column(col);
    if (c < 0 || !cfg->sweep.naxes || (as_map && cfg->sweep.naxes < 2)) {
        snprintf(why, whylen, "no %s of %s to draw", as_map ? "map" : "curves", col);
        return -1;
    }
    size_t finite = 0;
    for (size_t i = 0; i < n; i++)
        finite += isfinite(rows[i].v[c]) != 0;
    if (!finite) {
        snprintf(why, whylen, "no run has a %s to draw (every one is nan: see sweep.tsv's status)", col);
        return -1;
    }
    double scale;
    char label[96];
    unit_of(col, rows, n, c, &scale, label, sizeof label);
    return as_map ? map(ses, cfg, rows, c, col, scale, label, why, whylen)
                  : curves(ses, cfg, rows, n, c, col, scale, label, why, whylen);
}
