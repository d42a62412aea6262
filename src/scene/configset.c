/* Setting the configuration by key: one table of every key, each with the
 * one function that reads its text. Scene files, the flags, the TUI's
 * fields and :set all come here, so a value means the same and is refused
 * with the same sentence whichever way it is given. */
#include "scene/config.h"
#include "scene/text.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "adhere/grid.h"
#include "adhere/static.h"
#include "adhere/status.h"
#include "adhere/units.h"
#include "adhere/visco.h"

typedef struct key_def key_def;
typedef int (*key_setter)(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen);
typedef void (*key_getter)(const adh_config *c, const key_def *k, char *buf, size_t len);

struct key_def {
    adh_config_key pub;
    key_setter set;
    size_t off;                    /* the field in adh_config, for the setters that share a shape */
    key_getter get;                /* its value as text the setter reads back to the same value */
};

#define F(field) offsetof(adh_config, field)

static double *dbl(adh_config *c, const key_def *k)
{
    return (double *)(void *)((char *)c + k->off);
}

static int *flag(adh_config *c, const key_def *k)
{
    return (int *)(void *)((char *)c + k->off);
}

static const void *field(const adh_config *c, const key_def *k)
{
    return (const char *)c + k->off;
}

static const char *name_of(const key_def *k)
{
    const char *dot = strchr(k->pub.key, '.');
    return dot ? dot + 1 : k->pub.key;
}

/* ---- the shapes ---------------------------------------------------------- */

static int set_quantity(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    double v;
    if (adh_parse_quantity(text, k->pub.q, &v, why, whylen) != 0)
        return -1;
    *dbl(c, k) = v;
    return 0;
}

/* A quantity, or auto: the automatic value (NAN). A refusal says auto is
 * allowed too. */
static int set_quantity_auto(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (strcasecmp(text, "auto") == 0) {
        *dbl(c, k) = NAN;
        return 0;
    }
    if (set_quantity(c, k, text, why, whylen) != 0) {
        adh_text_cat(why, whylen, ", or auto");
        return -1;
    }
    return 0;
}

/* A length above 0, or auto: a graded grid's band and radius (how they fit
 * the spacing and each other is adh_config_grid_check's). */
static int set_radius(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    double v;
    if (strcasecmp(text, "auto") == 0) {
        *dbl(c, k) = NAN;
        return 0;
    }
    int number = adh_parse_quantity(text, ADH_Q_LENGTH, &v, why, whylen) == 0;
    if (!number || !(v > 0)) {
        if (number)
            snprintf(why, whylen, "'%s' is not allowed: use a length above 0", text);
        size_t n = strlen(why);
        snprintf(why + n, whylen - n, ", or auto");
        return -1;
    }
    *dbl(c, k) = v;
    return 0;
}

static int parse_bool(const char *text, int *out)
{
    if (!strcasecmp(text, "yes") || !strcmp(text, "1") || !strcasecmp(text, "true"))
        *out = 1;
    else if (!strcasecmp(text, "no") || !strcmp(text, "0") || !strcasecmp(text, "false"))
        *out = 0;
    else
        return -1;
    return 0;
}

static int set_bool(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (parse_bool(text, flag(c, k)) != 0) {
        snprintf(why, whylen, "'%s' is not yes or no", text);
        return -1;
    }
    return 0;
}

static int set_path(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (!*text || strlen(text) >= PATH_MAX) {
        snprintf(why, whylen, "a path of 1 to %d characters is needed", PATH_MAX - 1);
        return -1;
    }
    /* "-" is standard input or output to most programs; adhere's paths
     * name files and directories (-o - made a directory called "-") */
    if (!strcmp(text, "-")) {
        snprintf(why, whylen, "'-' is not allowed: adhere reads and writes named files and directories, not standard "
                 "input or output; write ./- for one named '-'");
        return -1;
    }
    snprintf((char *)c + k->off, PATH_MAX, "%s", text);
    return 0;
}

/* A comma-separated list of quantities q into out[] ("none": empty, when
 * allow_none). */
static int parse_list(const char *text, adh_quantity q, int allow_none, double *out, size_t cap, size_t *count,
                      char *why, size_t whylen)
{
    char buf[1024];
    size_t n = 0;
    if (allow_none && strcasecmp(text, "none") == 0) {
        *count = 0;
        return 0;
    }
    if (strlen(text) >= sizeof buf) {
        snprintf(why, whylen, "list longer than %zu characters", sizeof buf - 1);
        return -1;
    }
    /* strtok passes over an empty element ("-1nm,,-2nm"): refuse it */
    for (const char *seg = text;;) {
        const char *comma = strchr(seg, ',');
        size_t len = comma ? (size_t)(comma - seg) : strlen(seg);
        if (strspn(seg, " \t") >= len) {
            snprintf(why, whylen, "'%.200s' has an empty element: separate values by single commas", text);
            return -1;
        }
        if (!comma)
            break;
        seg = comma + 1;
    }
    /* "-0,5nm" was two turns, 0 m and 5 nm, taken without a word */
    if (adh_list_decimal_comma(text, q, why, whylen) != ADH_SUCCESS)
        return -1;
    double vals[ADH_MAX_TURNS > ADH_MAX_PROFILES ? ADH_MAX_TURNS : ADH_MAX_PROFILES];
    snprintf(buf, sizeof buf, "%s", text);
    char *save = NULL;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (n == cap || n == sizeof vals / sizeof vals[0]) {
            snprintf(why, whylen, "'%.200s' has more than %zu values: give at most %zu, separated by commas", text, cap,
                     cap);
            return -1;
        }
        if (adh_parse_quantity(t, q, &vals[n++], why, whylen) != 0)
            return -1;
    }
    memcpy(out, vals, n * sizeof *vals);
    *count = n;
    return 0;
}

/* Appends text to buf (holding o characters of len), whole or cut at the
 * end; the new length. */
static size_t append(char *buf, size_t len, size_t o, const char *text)
{
    size_t n = strlen(text);
    if (o + n >= len)
        n = o + 1 < len ? len - 1 - o : 0;
    memcpy(buf + o, text, n);
    buf[o + n] = '\0';
    return o + n;
}

/* A word of a short list, each naming a value. */
typedef struct word {
    const char *name;
    int value;
} word;

static const word modes[] = { { "relax", ADH_MODE_RELAX }, { "static", ADH_MODE_STATIC }, { "rigid", ADH_MODE_RIGID },
                              { "time", ADH_MODE_TIME }, { NULL, 0 } };
static const word materials[] = { { "elastic", 0 }, { "sls", 1 }, { NULL, 0 } };
static const word grids[] = { { "uniform", 0 }, { "graded", 1 }, { NULL, 0 } };
static const word sweep_plots[] = { { "jump", ADH_SWEEP_PLOT_JUMP }, { "force", ADH_SWEEP_PLOT_FORCE },
                                    { "map", ADH_SWEEP_PLOT_MAP }, { "curves", ADH_SWEEP_PLOT_CURVES },
                                    { "speed", ADH_SWEEP_PLOT_SPEED }, { "snap", ADH_SWEEP_PLOT_SNAP },
                                    { "none", ADH_SWEEP_PLOT_NONE }, { "auto", ADH_SWEEP_PLOT_AUTO }, { NULL, 0 } };
static const word run_dirs[] = { { "yes", 1 }, { "no", 0 }, { "auto", -1 }, { NULL, 0 } };

/* The value text names in list, or -1 with "'text' is not a WHAT: use A, B
 * or C". */
static int parse_word(const word *list, const char *what, const char *text, int *value, char *why, size_t whylen)
{
    size_t n = 0;
    for (; list[n].name; n++)
        if (strcmp(text, list[n].name) == 0) {
            *value = list[n].value;
            return 0;
        }
    snprintf(why, whylen, "'%.100s' is not a %s: use", text, what);
    size_t o = strlen(why);
    for (size_t i = 0; i < n; i++) {
        o = append(why, whylen, o, i == 0 ? " " : i + 1 == n ? " or " : ", ");
        o = append(why, whylen, o, list[i].name);
    }
    return -1;
}

static const char *word_name(const word *list, int value)
{
    for (; list->name; list++)
        if (list->value == value)
            return list->name;
    return "";
}

/* A whole number; its limits are the run's check's (adh_drive_check). */
static int parse_count(const char *text, long lo, long hi, long *n, char *why, size_t whylen)
{
    return adh_parse_count(text, lo, hi, n, why, whylen) == 0 ? 0 : -1;
}

/* A count whose range its own check names (adh_grid_nodes_check, ...):
 * text that is no whole number ('1e9', '12.5', '-3') is refused naming the
 * range too, not only the form, of what (nodes, iterations). */
static int parse_count_of(const char *text, const char *what, long lo, long hi, long *n, char *why, size_t whylen)
{
    if (parse_count(text, 0, LONG_MAX, n, why, whylen) == 0)
        return 0;
    snprintf(why, whylen, "'%.60s' is not allowed: expected a whole number of %s, %ld to %ld", text, what, lo, hi);
    return -1;
}

/* ---- each key's own ------------------------------------------------------ */

static int set_title(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    /* shown on terminals and in figures: one line of printable text */
    for (const unsigned char *t = (const unsigned char *)text; *t; t++)
        if ((*t < 0x20 && *t != '\t') || *t == 0x7f) {
            snprintf(why, whylen, "the control character 0x%02x is not allowed: a title is one line of printable text", *t);
            return -1;
        }
    snprintf(c->output.title, sizeof c->output.title, "%s", text);
    return 0;
}

static int set_mode(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    int v;
    if (parse_word(modes, "mode", text, &v, why, whylen) != 0)
        return -1;
    c->spec.mode = (adh_mode)v;
    c->spec.time.given |= ADH_TIME_MODE;   /* kept whatever the material: adh_config_time_check refuses a mismatch */
    return 0;
}

static int set_nodes(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    long n;
    adh_grid_settings *g = &c->spec.grid;
    if (strcasecmp(text, "auto") == 0) {   /* the grid follows the physics (adh_config_grid) */
        g->asked.nodes = 1000;
        g->nodes_given = 0;
        return 0;
    }
    if (parse_count_of(text, "nodes", ADH_GRID_NODES_MIN, ADH_GRID_NODES_MAX, &n, why, whylen) != 0 ||
        adh_grid_nodes_check(n, why, whylen) != ADH_SUCCESS)
        return -1;
    g->asked.nodes = (size_t)n;
    g->nodes_given = 1;
    return 0;
}

static int set_max_iter(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    long n;
    if (parse_count_of(text, "iterations", 1, ADH_RELAX_MAX_ITER_CAP, &n, why, whylen) != 0 ||
        adh_relax_max_iter_check(n, why, whylen) != ADH_SUCCESS)
        return -1;
    c->spec.relax.max_iter = (size_t)n;
    return 0;
}

/* The static curve's cap on points: a bound on its work, and the one stop
 * a test can provoke on every CPU alike (a stall depends on rounding) */
static int set_max_points(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    long n, hi = (long)adh_static_settings_default().max_points;
    if (parse_count_of(text, "points", 2, hi, &n, why, whylen) != 0)
        return -1;
    if (n < 2 || n > hi) {
        snprintf(why, whylen, "%ld points is not allowed: from 2 to %ld", n, hi);
        return -1;
    }
    c->spec.max_points = (size_t)n;
    return 0;
}

static int set_dwell(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    long n;
    if (parse_count_of(text, "iterations", 0, ADH_PROTOCOL_MAX_DWELL, &n, why, whylen) != 0 ||
        adh_protocol_dwell_check(n, why, whylen) != ADH_SUCCESS)
        return -1;
    c->spec.proto.dwell = (size_t)n;
    return 0;
}

static int set_jobs(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    long n = 0;
    if (strcasecmp(text, "auto") != 0 && parse_count(text, 1, 64, &n, why, whylen) != 0)   /* auto: one per core */
        return -1;
    c->sweep.jobs = (int)n;
    return 0;
}

static int set_kernel(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (adh_kernel_parse(text, &c->spec.grid.asked.kernel) != 0) {
        snprintf(why, whylen, "'%s' is not a kernel: use paper or ring", text);
        return -1;
    }
    c->spec.grid.kernel_given = 1;
    return 0;
}

static int set_grid_kind(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    return parse_word(grids, "grid", text, &c->spec.grid.asked.graded, why, whylen);
}

static int set_growth(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    double g = NAN;
    /* the ratio's limits are the rings spec's: asked of a spec that is
     * valid but for its ratio */
    int number = adh_parse_quantity(text, ADH_Q_NONE, &g, NULL, 0) == 0;
    adh_rings_spec s = { .dr = 1, .fine = 1, .ratio = g, .rmax = 1 };
    if (!number || adh_rings_spec_validate(&s, NULL, 0) != ADH_SUCCESS) {
        snprintf(why, whylen, "'%s' is not allowed: use a ratio from 1 to %g", text, ADH_RINGS_MAX_RATIO);
        return -1;
    }
    c->spec.grid.asked.growth = g;
    return 0;
}

static int set_operator(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (adh_kernel_storage_parse(text, &c->spec.grid.asked.storage) != 0) {
        snprintf(why, whylen, "'%s' is not an operator: use dense, hmat or h2", text);
        return -1;
    }
    c->spec.grid.storage_given = 1;
    return 0;
}

static int set_mixing(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    if (adh_mix_rule_parse(text, &c->spec.relax.rule) != 0) {
        snprintf(why, whylen, "'%s' is not a mixing rule: use paper or momentum", text);
        return -1;
    }
    return 0;
}

static int set_momentum(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    double b;
    if (adh_parse_quantity(text, ADH_Q_NONE, &b, NULL, 0) != 0 || !(b >= 0 && b < 1)) {
        snprintf(why, whylen, "'%s' is not allowed: a number from 0 to below 1", text);
        return -1;
    }
    c->spec.relax.momentum = b;
    return 0;
}

/* Turns also say whether to unload: from every turn, when there is one. */
static int set_turns(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    adh_protocol_settings *p = &c->spec.proto;
    double t[ADH_MAX_TURNS];
    size_t n;
    if (parse_list(text, ADH_Q_LENGTH, 1, t, ADH_MAX_TURNS, &n, why, whylen) != 0)
        return -1;
    /* a turn given twice unloaded the same branch twice, listed twice in turns.tsv */
    for (size_t i = 1; i < n; i++)
        for (size_t j = 0; j < i; j++)
            if (t[i] == t[j]) {
                snprintf(why, whylen, "the turn %s is given twice: give each turning point once",
                         adh_qtext(t[i], ADH_Q_LENGTH).s);
                return -1;
            }
    memcpy(p->turns, t, n * sizeof *t);
    p->nturns = n;
    p->unload = p->nturns > 0;
    return 0;
}

static int set_profiles(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    adh_protocol_settings *p = &c->spec.proto;
    return parse_list(text, ADH_Q_LENGTH, 1, p->profiles, ADH_MAX_PROFILES, &p->nprofiles, why, whylen);
}

static int set_plots(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    static const struct { const char *name; unsigned bit; } plots[] = {
        { "force", ADH_PLOT_FORCE }, { "profile", ADH_PLOT_PROFILE }, { "contact", ADH_PLOT_CONTACT },
        { "precontact", ADH_PLOT_PRECONTACT }, { "bulge", ADH_PLOT_BULGE }, { "none", 0 },
    };
    unsigned mask = 0;
    int none = 0;
    char buf[256], *save = NULL;
    if (strlen(text) >= sizeof buf || strstr(text, ",,") || text[0] == ',' || (*text && text[strlen(text) - 1] == ',')) {
        snprintf(why, whylen, "'%.200s' has an empty element: separate values by single commas", text);
        return -1;
    }
    snprintf(buf, sizeof buf, "%s", text);
    for (char *t = strtok_r(buf, ", ", &save); t; t = strtok_r(NULL, ", ", &save)) {
        size_t i = 0;
        while (i < sizeof plots / sizeof plots[0] && strcmp(t, plots[i].name) != 0)
            i++;
        if (i == sizeof plots / sizeof plots[0]) {
            snprintf(why, whylen, "'%s' is not a plot: use force, profile, contact, precontact, bulge or none", t);
            return -1;
        }
        /* none: no figure of a single run; a sweep's combined figure
         * follows output.plot alone */
        none |= plots[i].bit == 0;
        mask |= plots[i].bit;
    }
    if (!none && !mask) {
        snprintf(why, whylen, "name at least one of force, profile, contact, precontact, bulge, or none");
        return -1;
    }
    if (none && mask) {
        snprintf(why, whylen, "'none' cannot be combined with other plots");
        return -1;
    }
    c->output.plots = mask;
    return 0;
}

/* [sweep] KEY: a swept key (sweep.c), sweep.E, sweep.sigma and
 * sweep.eps as much as any other. */
static int set_sweep(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    return adh_sweep_set(c, name_of(k), text, why, whylen);
}

static int set_run_dirs(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    return parse_word(run_dirs, "run_dirs value", text, &c->sweep.run_dirs, why, whylen);
}

/* The column a map shows: any name of a sweep.tsv column (checked when
 * the table is drawn, where the columns are known). */
static int set_map(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    size_t n = strlen(text);
    if (n == 0 || n >= sizeof c->sweep.map || strspn(text, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.") != n) {
        snprintf(why, whylen, "'%.60s' is not a column name: use one of sweep.tsv's (pulloff_F, hysteresis, ...)", text);
        return -1;
    }
    snprintf(c->sweep.map, sizeof c->sweep.map, "%s", text);
    return 0;
}

static int set_sweep_plot(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    int v;
    if (parse_word(sweep_plots, "sweep plot", text, &v, why, whylen) != 0)
        return -1;
    c->sweep.plot = (adh_sweep_plot)v;
    return 0;
}

static int set_size(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    int cols, rows;
    char extra;
    if (sscanf(text, "%dx%d%c", &cols, &rows, &extra) != 2 || cols < 40 || cols > 1000 || rows < 12 || rows > 1000) {
        snprintf(why, whylen, "'%s' is not allowed: use COLSxROWS with 40-1000 columns and 12-1000 rows", text);
        return -1;
    }
    c->tui.cols = cols;
    c->tui.rows = rows;
    return 0;
}

/* ---- physical time (mode time) ------------------------------------------ */

/* The material: a standard linear solid runs in physical time, unless the
 * mode was given (adh_config_time_check then says whether they fit). */
static int set_material_kind(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    int v;
    if (parse_word(materials, "material", text, &v, why, whylen) != 0)
        return -1;
    c->spec.time.sls = v;
    if (!v)   /* elastic over a solid (a flag over a scene's): its keys go with it */
        c->spec.time.given &= ~(unsigned)(ADH_TIME_E0 | ADH_TIME_EINF | ADH_TIME_TAU | ADH_TIME_TOL);
    /* elastic leaves physical time unless its drive was given (a speed,
     * a dwell in seconds, a spring): then it is an elastic sphere in time */
    unsigned drive = c->spec.time.given & (ADH_TIME_SPEED | ADH_TIME_DWELL | ADH_TIME_SPRING);
    if (!(c->spec.time.given & ADH_TIME_MODE))
        c->spec.mode = v || (drive && c->spec.mode == ADH_MODE_TIME) ? ADH_MODE_TIME
                     : c->spec.mode == ADH_MODE_TIME ? ADH_MODE_RELAX : c->spec.mode;
    return 0;
}

/* One value of the solid or the drive, checked by the core's own limits
 * (adh_sls_validate, adh_visco_drive_validate) with the others at values
 * they allow; how it fits the others is adh_config_time_check's. */
static int time_value_ok(const char *name, double v, char *why, size_t whylen)
{
    adh_sls m = { 1e9, 1e9, 1 };
    adh_visco_drive d = adh_visco_drive_default();
    if (!strcmp(name, "E0"))
        m.E0 = m.Einf = v;
    else if (!strcmp(name, "Einf"))
        m.E0 = 1e3, m.Einf = v;   /* E0 at its least: the refusal is Einf's own */
    else if (!strcmp(name, "tau"))
        m.tau = v;
    else if (!strcmp(name, "dwell_time"))
        d.dwell = v;
    else if (!strcmp(name, "spring"))
        d.spring = v;
    else if (!strcmp(name, "speed_out"))
        d.speed_out = v;
    else
        d.speed_in = v;
    return adh_sls_validate(&m, why, whylen) == ADH_SUCCESS && adh_visco_drive_validate(&d, why, whylen) == ADH_SUCCESS;
}

static unsigned time_bit(const char *name)
{
    return !strcmp(name, "E0") ? ADH_TIME_E0 : !strcmp(name, "Einf") ? ADH_TIME_EINF : !strcmp(name, "tau") ? ADH_TIME_TAU
         : !strcmp(name, "dwell_time") ? ADH_TIME_DWELL : !strcmp(name, "spring") ? ADH_TIME_SPRING : ADH_TIME_SPEED;
}

/* E0 (the material's E under its solid's name), Einf (or auto), tau,
 * dwell_time and spring (or none). */
static int set_time_quantity(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    const char *name = name_of(k);
    double v;
    if (!strcmp(name, "Einf") && strcasecmp(text, "auto") == 0)
        v = NAN;
    else if (!strcmp(name, "spring") && strcasecmp(text, "none") == 0)
        v = INFINITY;
    else if (adh_parse_quantity(text, k->pub.q, &v, why, whylen) != 0 || !time_value_ok(name, v, why, whylen)) {
        if (!strcmp(name, "Einf"))
            adh_text_cat(why, whylen, ", or auto (10 E0)");
        return -1;
    }
    *dbl(c, k) = v;
    c->spec.time.given |= time_bit(name);
    return 0;
}

/* The time integration's relative tolerance: a plain number, checked by
 * the core's own limits (adh_visco_settings_validate); that it needs a
 * solid is adh_config_time_check's. */
static int set_time_tol(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    adh_visco_settings s = adh_visco_settings_default();
    if (adh_parse_quantity(text, ADH_Q_NONE, &s.tol, why, whylen) != 0 ||
        adh_visco_settings_validate(&s, why, whylen) != ADH_SUCCESS)
        return -1;
    c->spec.time.tol = s.tol;
    c->spec.time.given |= ADH_TIME_TOL;
    return 0;
}

/* speed = V (both ways) or Vin, Vout. */
static int set_speed(adh_config *c, const key_def *k, const char *text, char *why, size_t whylen)
{
    double v[2];
    size_t n;
    if (parse_list(text, ADH_Q_SPEED, 0, v, 2, &n, why, whylen) != 0)
        return -1;
    for (size_t i = 0; i < n; i++)
        if (!time_value_ok(i ? "speed_out" : "speed_in", v[i], why, whylen))
            return -1;
    c->spec.time.speed_in = v[0];
    c->spec.time.speed_out = v[n - 1];
    c->spec.time.given |= ADH_TIME_SPEED;
    return 0;
}


/* ---- the values as text --------------------------------------------------- */


/* Exact: %.17g reads back to the same double. */
static void get_number(double v, char *buf, size_t len)
{
    snprintf(buf, len, "%.17g", v);
}

static void get_quantity(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    double v = *(const double *)field(c, k);
    if (isnan(v))
        snprintf(buf, len, "auto");
    else
        get_number(v, buf, len);
}

static void get_bool(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", *(const int *)field(c, k) ? "yes" : "no");
}

static void get_path(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", (const char *)field(c, k));
}

static void get_list(const double *v, size_t n, char *buf, size_t len)
{
    size_t o = append(buf, len, 0, n ? "" : "none");
    for (size_t i = 0; i < n; i++) {
        char one[40];
        snprintf(one, sizeof one, "%s%.17g", i ? "," : "", v[i]);
        o = append(buf, len, o, one);
    }
}

static void get_title(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", c->output.title);
}

static void get_mode(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", word_name(modes, (int)c->spec.mode));
}

static void get_nodes(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    if (c->spec.grid.nodes_given)
        snprintf(buf, len, "%zu", c->spec.grid.asked.nodes);
    else
        snprintf(buf, len, "auto");
}

static void get_max_iter(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%zu", c->spec.relax.max_iter);
}

static void get_max_points(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%zu", c->spec.max_points ? c->spec.max_points : adh_static_settings_default().max_points);
}

static void get_dwell(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%zu", c->spec.proto.dwell);
}

static void get_jobs(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    if (c->sweep.jobs)
        snprintf(buf, len, "%d", c->sweep.jobs);
    else
        snprintf(buf, len, "auto");
}

static void get_kernel(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", adh_kernel_name(c->spec.grid.asked.kernel));
}

static void get_grid_kind(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", word_name(grids, c->spec.grid.asked.graded));
}

static void get_growth(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    get_number(c->spec.grid.asked.growth, buf, len);
}

static void get_operator(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", adh_kernel_storage_name(c->spec.grid.asked.storage));
}

static void get_mixing(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", c->spec.relax.rule == ADH_MIX_PAPER ? "paper" : "momentum");
}

static void get_momentum(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    get_number(c->spec.relax.momentum, buf, len);
}

static void get_turns(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    get_list(c->spec.proto.turns, c->spec.proto.nturns, buf, len);
}

static void get_profiles(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    get_list(c->spec.proto.profiles, c->spec.proto.nprofiles, buf, len);
}

static void get_plots(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    static const char *const names[] = { "force", "profile", "contact", "precontact", "bulge" };
    static const unsigned bits[] = { ADH_PLOT_FORCE, ADH_PLOT_PROFILE, ADH_PLOT_CONTACT, ADH_PLOT_PRECONTACT, ADH_PLOT_BULGE };
    size_t o = append(buf, len, 0, c->output.plots ? "" : "none");
    for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++)
        if (c->output.plots & bits[i]) {
            o = append(buf, len, o, o ? "," : "");
            o = append(buf, len, o, names[i]);
        }
}

static void get_sweep(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    adh_sweep_get(c, name_of(k), buf, len);
}

static void get_run_dirs(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", word_name(run_dirs, c->sweep.run_dirs));
}

static void get_map(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", c->sweep.map[0] ? c->sweep.map : "pulloff_F");
}

static void get_sweep_plot(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", word_name(sweep_plots, (int)c->sweep.plot));
}

static void get_size(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%dx%d", c->tui.cols, c->tui.rows);
}


static void get_material_kind(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    snprintf(buf, len, "%s", word_name(materials, c->spec.time.sls));
}

static void get_time_quantity(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    double v = *(const double *)field(c, k);
    if (isinf(v))
        snprintf(buf, len, "none");
    else
        get_quantity(c, k, buf, len);
}

static void get_speed(const adh_config *c, const key_def *k, char *buf, size_t len)
{
    const adh_time_settings *t = &c->spec.time;
    double v[2] = { t->speed_in, t->speed_out };
    get_list(v, t->speed_in == t->speed_out ? 1 : 2, buf, len);
}

/* ---- the table ------------------------------------------------------------ */

enum { S = ADH_KEY_SCENE, R = ADH_KEY_RUN, C = ADH_KEY_COUNT };

/* Every key; adhere-scene(5) documents those a scene may hold (where S),
 * adhere(1) the flags that set the others. */
static const key_def keys[] = {
    { { "scene.title", S, ADH_Q_NONE, NULL }, set_title, 0, get_title },
    { { "scene.mode", S | R, ADH_Q_NONE, NULL }, set_mode, 0, get_mode },
    { { "material.E", S | R, ADH_Q_PRESSURE, "GPa MPa kPa" }, set_quantity, F(spec.mat.E), get_quantity },
    { { "material.A", S | R, ADH_Q_ENERGY, NULL }, set_quantity, F(spec.mat.A), get_quantity },
    { { "material.z0", S | R, ADH_Q_LENGTH, "nm" }, set_quantity, F(spec.mat.z0), get_quantity },
    { { "material.R", S | R, ADH_Q_LENGTH, "mm um" }, set_quantity, F(spec.mat.R), get_quantity },
    { { "material.material", S | R, ADH_Q_NONE, NULL }, set_material_kind, 0, get_material_kind },
    { { "material.E0", S | R, ADH_Q_PRESSURE, "GPa MPa kPa" }, set_time_quantity, F(spec.mat.E), get_quantity },
    { { "material.Einf", S | R, ADH_Q_PRESSURE, "GPa MPa kPa" }, set_time_quantity, F(spec.time.Einf), get_quantity },
    { { "material.tau", S | R, ADH_Q_TIME, NULL }, set_time_quantity, F(spec.time.tau), get_quantity },
        { { "grid.nodes", S | R | C, ADH_Q_NONE, NULL }, set_nodes, 0, get_nodes },
    { { "grid.spacing", S | R, ADH_Q_LENGTH, "nm" }, set_quantity_auto, F(spec.grid.asked.spacing), get_quantity },
    { { "grid.kernel", S | R, ADH_Q_NONE, NULL }, set_kernel, 0, get_kernel },
    { { "grid.grid", S | R, ADH_Q_NONE, NULL }, set_grid_kind, 0, get_grid_kind },
    { { "grid.fine_band", S | R, ADH_Q_LENGTH, "um nm" }, set_radius, F(spec.grid.asked.fine_band), get_quantity },
    { { "grid.growth", S | R, ADH_Q_NONE, NULL }, set_growth, 0, get_growth },
    { { "grid.radius", S | R, ADH_Q_LENGTH, "um nm" }, set_radius, F(spec.grid.asked.radius), get_quantity },
    { { "grid.operator", S | R, ADH_Q_NONE, NULL }, set_operator, 0, get_operator },
    { { "grid.force", R, ADH_Q_NONE, NULL }, set_bool, F(spec.grid.force), get_bool },
    { { "solver.eps", S | R, ADH_Q_LENGTH, "pm" }, set_quantity, F(spec.relax.eps), get_quantity },
    { { "solver.max_iter", S | R | C, ADH_Q_NONE, NULL }, set_max_iter, 0, get_max_iter },
    { { "solver.max_points", S | R | C, ADH_Q_NONE, NULL }, set_max_points, 0, get_max_points },
    { { "solver.mixing", S | R, ADH_Q_NONE, NULL }, set_mixing, 0, get_mixing },
    { { "solver.momentum", S | R, ADH_Q_NONE, NULL }, set_momentum, 0, get_momentum },
    { { "solver.time_tol", S | R, ADH_Q_NONE, NULL }, set_time_tol, F(spec.time.tol), get_quantity },
    { { "protocol.start", S | R, ADH_Q_LENGTH, "nm" }, set_quantity_auto, F(spec.proto.start), get_quantity },
    { { "protocol.step", S | R, ADH_Q_LENGTH, "nm" }, set_quantity, F(spec.proto.step), get_quantity },
    { { "protocol.turns", S | R, ADH_Q_LENGTH, "nm" }, set_turns, 0, get_turns },
    { { "protocol.dwell", S | R | C, ADH_Q_NONE, NULL }, set_dwell, 0, get_dwell },
    { { "protocol.unload", S | R, ADH_Q_NONE, NULL }, set_bool, F(spec.proto.unload), get_bool },
    { { "protocol.speed", S | R, ADH_Q_SPEED, NULL }, set_speed, 0, get_speed },
    { { "protocol.speed_out", S | R, ADH_Q_SPEED, NULL }, set_time_quantity, F(spec.time.speed_out), get_quantity },
    { { "protocol.dwell_time", S | R, ADH_Q_TIME, NULL }, set_time_quantity, F(spec.time.dwell), get_quantity },
    { { "protocol.spring", S | R, ADH_Q_STIFFNESS, NULL }, set_time_quantity, F(spec.time.spring), get_time_quantity },
    { { "output.plots", S, ADH_Q_NONE, NULL }, set_plots, 0, get_plots },
    { { "output.profiles", S | R, ADH_Q_LENGTH, "nm" }, set_profiles, 0, get_profiles },
    { { "output.drive_speed", S, ADH_Q_SPEED, "um/s" }, set_quantity, F(output.drive_speed), get_quantity },
    { { "output.dir", 0, ADH_Q_NONE, NULL }, set_path, F(output.dir), get_path },
    { { "output.overwrite", 0, ADH_Q_NONE, NULL }, set_bool, F(output.overwrite), get_bool },
    { { "output.plot", 0, ADH_Q_NONE, NULL }, set_bool, F(output.plot), get_bool },
    { { "output.quiet", 0, ADH_Q_NONE, NULL }, set_bool, F(output.quiet), get_bool },
    { { "output.allow_unconverged", 0, ADH_Q_NONE, NULL }, set_bool, F(output.allow_unconverged), get_bool },
    { { "output.gnuplot_style", 0, ADH_Q_NONE, NULL }, set_path, F(output.gnuplot_style), get_path },
    { { "output.data", 0, ADH_Q_NONE, NULL }, set_path, F(output.data), get_path },
    { { "sweep.E", S, ADH_Q_PRESSURE, "GPa MPa kPa" }, set_sweep, 0, get_sweep },
    { { "sweep.sigma", S, ADH_Q_NONE, NULL }, set_sweep, 0, get_sweep },
    { { "sweep.eps", S, ADH_Q_LENGTH, "pm" }, set_sweep, 0, get_sweep },
    { { "sweep.jobs", S | C, ADH_Q_NONE, NULL }, set_jobs, 0, get_jobs },
    { { "sweep.plot", S, ADH_Q_NONE, NULL }, set_sweep_plot, 0, get_sweep_plot },
    { { "sweep.run_dirs", S, ADH_Q_NONE, NULL }, set_run_dirs, 0, get_run_dirs },
    { { "sweep.map", S, ADH_Q_NONE, NULL }, set_map, 0, get_map },
    { { "tui.replay", 0, ADH_Q_NONE, NULL }, set_path, F(tui.replay), get_path },
    { { "tui.screen", 0, ADH_Q_NONE, NULL }, set_path, F(tui.screen), get_path },
    { { "tui.size", 0, ADH_Q_NONE, NULL }, set_size, 0, get_size },
    { { "tui.no_clock", 0, ADH_Q_NONE, NULL }, set_bool, F(tui.no_clock), get_bool },
};
#define NKEYS (sizeof keys / sizeof keys[0])

/* Any other key in [sweep] sweeps the key it names (sweep.c): one entry
 * stands for them all. */
static const key_def any_swept = { { "sweep.KEY", S, ADH_Q_NONE, NULL }, NULL, 0, NULL };

static const key_def *find(const char *key)
{
    for (size_t i = 0; i < NKEYS; i++)
        if (strcmp(keys[i].pub.key, key) == 0)
            return &keys[i];
    return strncmp(key, "sweep.", 6) == 0 && key[6] ? &any_swept : NULL;
}

const adh_config_key *adh_config_key_find(const char *key)
{
    const key_def *k = find(key);
    return k ? &k->pub : NULL;
}

const adh_config_key *adh_config_key_at(size_t i)
{
    return i < NKEYS ? &keys[i].pub : NULL;
}

/* The size of one unit of q ("um" for a length: 1e-6). */
static double unit_size(const char *unit, adh_quantity q)
{
    char text[32];
    double v = NAN;
    snprintf(text, sizeof text, "1%s", unit);
    return adh_parse_quantity(text, q, &v, NULL, 0) == 0 ? v : NAN;
}

const char *adh_config_key_unit(const adh_config_key *k, double value, double *factor)
{
    static char unit[16];   /* the table's text, one key's unit at a time */
    if (!k || !k->units)
        return NULL;
    /* largest first: the first unit not above the value, else the last */
    for (const char *p = k->units; *p;) {
        size_t n = strcspn(p, " "), m = n < sizeof unit ? n : sizeof unit - 1;
        memcpy(unit, p, m);
        unit[m] = '\0';
        *factor = unit_size(unit, k->q);
        p += n;
        while (*p == ' ')
            p++;
        if (!*p || fabs(value) >= 0.9995 * *factor)
            break;
    }
    return unit;
}

int adh_config_get(const adh_config *c, const char *key, char *buf, size_t len)
{
    const key_def *k = find(key);
    if (!k || len == 0)
        return -1;
    if (k == &any_swept)
        adh_sweep_get(c, key + 6, buf, len);
    else
        k->get(c, k, buf, len);
    return 0;
}

int adh_config_set(adh_config *c, const char *key, const char *text, char *why, size_t whylen)
{
    const key_def *k = find(key);
    if (!k) {
        snprintf(why, whylen, "'%s' is not a key of the configuration", key);
        return -1;
    }
    if (k == &any_swept)
        return adh_sweep_set(c, key + 6, text, why, whylen);
    /* every setter changes nothing when it refuses: it writes last */
    if (k->set(c, k, text, why, whylen) != 0)
        return -1;
    if (strncmp(key, "grid.", 5) == 0 && strcmp(key, "grid.force") != 0) {
        /* the grid asked for changed: a run builds it until adh_config_grid
         * chooses again */
        c->spec.grid.use = c->spec.grid.asked;
        c->spec.grid.chosen = 0;
    }
    return 0;
}

/* ---- a sentence in a driver's words ------------------------------------- */

static int keychar(char ch)
{
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_';
}

/* The longest key at p (p starts no word inside another), or NULL. */
static const key_def *key_at(const char *p, size_t *len)
{
    const key_def *best = NULL;
    *len = 0;
    for (size_t i = 0; i < NKEYS; i++) {
        size_t n = strlen(keys[i].pub.key);
        if (n <= *len || strncmp(p, keys[i].pub.key, n) != 0)
            continue;
        /* "grid.radius" is not inside "grid.radiusx", nor "grid.grid" inside "grid.grid.x" */
        if (keychar(p[n]) || (p[n] == '.' && keychar(p[n + 1])))
            continue;
        best = &keys[i];
        *len = n;
    }
    return best;
}

void adh_config_reword(const char *in, adh_config_say say, void *ctx, char *out, size_t len)
{
    size_t o = 0;
    if (len == 0)
        return;
    for (const char *p = in; *p && o + 1 < len;) {
        size_t klen;
        const key_def *k = (p == in || !(keychar(p[-1]) || p[-1] == '.')) ? key_at(p, &klen) : NULL;
        if (!k) {
            out[o++] = *p++;
            continue;
        }
        /* said: a scene's key is said with its file's path and line, whole */
        char value[128] = "", said[PATH_MAX + 256];
        const char *q = p + klen;
        int assigned = strncmp(q, " = ", 3) == 0;
        if (assigned) {
            const char *v = q + 3;
            size_t n = strcspn(v, " ,;:)");
            if (n && v[n - 1] == '.' && (v[n] == '\0' || v[n] == ' '))
                n--;   /* the sentence's full stop */
            if (n >= sizeof value)
                n = sizeof value - 1;
            memcpy(value, v, n);
            value[n] = '\0';
            q = v + n;
            assigned = n > 0;
            if (!assigned)
                q = p + klen;
        }
        say(k->pub.key, assigned ? value : NULL, said, sizeof said, ctx);
        o = append(out, len, o, said);
        p = q;
    }
    out[o] = '\0';
}
