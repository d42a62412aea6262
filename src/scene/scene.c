#include "scene/scene.h"
#include "scene/datadir.h"

#include <errno.h>
#include <ini.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "adhere/status.h"
#include "adhere/grid.h"
#include "adhere/units.h"

typedef struct scene_parse {
    adh_config *cfg;
    const char *file;
    char why[512];
    int line;                    /* line of the first error, from inih */
    int unload_given;            /* an explicit unload = wins over the one turns implies */
    int kernel_given, grid_given; /* in this scene: together they must fit (adh_config_kernel_fits) */
    char seen[128][64];          /* "section.key" already given: duplicates are errors */
    size_t nseen;
} scene_parse;

typedef enum { K_LEN, K_PRESS, K_ENERGY, K_SPEED, K_COUNT, K_LENLIST, K_KERNEL, K_MODE, K_MIXING, K_FRACTION,
               K_PLOTS, K_BOOL, K_TEXT, K_SWEEP, K_SWEEP_PLOT, K_GRID } key_kind;

typedef struct scene_key {
    const char *section, *key;
    key_kind kind;
} scene_key;

/* Every key a scene may hold; adhere-scene(5) documents the same list. */
static const scene_key keys[] = {
    { "scene", "title", K_TEXT }, { "scene", "mode", K_MODE },
    { "material", "E", K_PRESS }, { "material", "A", K_ENERGY },
    { "material", "z0", K_LEN }, { "material", "R", K_LEN },
    { "grid", "nodes", K_COUNT }, { "grid", "spacing", K_LEN }, { "grid", "kernel", K_KERNEL },
    { "grid", "grid", K_GRID }, { "grid", "fine_band", K_GRID }, { "grid", "growth", K_GRID },
    { "grid", "radius", K_GRID }, { "grid", "operator", K_GRID },
    { "solver", "eps", K_LEN }, { "solver", "max_iter", K_COUNT },
    { "solver", "mixing", K_MIXING }, { "solver", "momentum", K_FRACTION },
    { "protocol", "start", K_LEN }, { "protocol", "step", K_LEN }, { "protocol", "turns", K_LENLIST },
    { "protocol", "dwell", K_COUNT }, { "protocol", "unload", K_BOOL },
    { "output", "plots", K_PLOTS }, { "output", "profiles", K_LENLIST },
    { "output", "drive_speed", K_SPEED },
    { "sweep", "E", K_SWEEP }, { "sweep", "sigma", K_SWEEP }, { "sweep", "eps", K_SWEEP },
    { "sweep", "jobs", K_COUNT }, { "sweep", "plot", K_SWEEP_PLOT },
};

static int fail(scene_parse *sp, const char *fmt, const char *a, const char *b)
{
    /* inih goes on after an error and reports the first line: keep its message. */
    if (!sp->why[0])
        snprintf(sp->why, sizeof sp->why, fmt, a, b);
    return 0; /* inih: 0 = error at this line */
}

/* A comma-separated list of quantities q ("none": empty when allow_none). */
static int parse_qlist(scene_parse *sp, const char *key, const char *value, adh_quantity q, int allow_none,
                       double *out, size_t cap, size_t *count)
{
    char buf[1024], msg[256];
    *count = 0;
    if (allow_none && strcasecmp(value, "none") == 0)
        return 1;
    if (strlen(value) >= sizeof buf)
        return fail(sp, "%s: list longer than 1023 characters%s", key, "");
    /* strtok passes over an empty element ("-1nm,,-2nm"): refuse it */
    for (const char *seg = value;;) {
        const char *comma = strchr(seg, ',');
        size_t len = comma ? (size_t)(comma - seg) : strlen(seg);
        if (strspn(seg, " \t") >= len)
            return fail(sp, "%s: '%.200s' has an empty element: separate values by single commas", key, value);
        if (!comma)
            break;
        seg = comma + 1;
    }
    snprintf(buf, sizeof buf, "%s", value);
    char *save = NULL;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (*count == cap) {
            snprintf(msg, sizeof msg, "%zu", cap);
            return fail(sp, "%s: more than %s values", key, msg);
        }
        while (*t == ' ' || *t == '\t')
            t++;
        if (adh_parse_quantity(t, q, &out[(*count)++], msg, sizeof msg) != 0)
            return fail(sp, "%s: %s", key, msg);
    }
    if (*count)
        return 1;
    return fail(sp, "%s: expected values separated by commas%s", key, allow_none ? ", or none" : "");
}

static int parse_list(scene_parse *sp, const char *key, const char *value, double *out, size_t cap, size_t *count)
{
    return parse_qlist(sp, key, value, ADH_Q_LENGTH, 1, out, cap, count);
}

/* [sweep] E / sigma / eps: one parameter, a list of positive values. */
static int parse_sweep(scene_parse *sp, const char *name, const char *value)
{
    adh_sweep *sw = &sp->cfg->sweep;
    adh_sweep_kind kind = !strcmp(name, "E") ? ADH_SWEEP_E : !strcmp(name, "sigma") ? ADH_SWEEP_SIGMA : ADH_SWEEP_EPS;
    if (sw->kind != ADH_SWEEP_NONE && sw->kind != kind)
        return fail(sp, "sweep: '%s' and '%s' both given: a sweep varies one parameter", adh_sweep_name(sw->kind), name);
    adh_quantity q = kind == ADH_SWEEP_E ? ADH_Q_PRESSURE : kind == ADH_SWEEP_EPS ? ADH_Q_LENGTH : ADH_Q_NONE;
    if (!parse_qlist(sp, name, value, q, 0, sw->values, ADH_MAX_SWEEP, &sw->n))
        return 0;
    for (size_t i = 0; i < sw->n; i++)
        if (!(sw->values[i] > 0)) {
            char msg[64];
            snprintf(msg, sizeof msg, "%g", sw->values[i]);
            return fail(sp, "%s: the swept value %s is not allowed: every value must be above 0", name, msg);
        }
    sw->kind = kind;
    return 1;
}

/* A scene that gives both the kernel and the grid must not pair the
 * paper's kernel with graded rings (as the flags must not); refused at the
 * later of the two keys. */
static int kernel_fits(scene_parse *sp, const char *name, const char *value)
{
    if (!sp->kernel_given || !sp->grid_given || adh_config_kernel_fits(sp->cfg->kernel, sp->cfg->graded))
        return 1;
    return fail(sp, !strcmp(name, "kernel") ? "%s: '%s' is not allowed with grid = graded: the paper's kernel "
                "assumes equal cells; use kernel = ring" : "%s: '%s' is not allowed with kernel = paper: the "
                "paper's kernel assumes equal cells; use kernel = ring", name, value);
}

/* [grid] grid, fine_band, growth, radius, operator: as the flags --grid,
 * --fine-band, --growth, --grid-radius and --operator, by the same
 * functions; auto (fine band, radius) is the default. */
static int grid_key(scene_parse *sp, const char *name, const char *value)
{
    adh_config *c = sp->cfg;
    char msg[256];
    int band = !strcmp(name, "fine_band"), radius = !strcmp(name, "radius");
    int rc = band ? adh_config_set_fine_band(c, value, msg, sizeof msg)
           : radius ? adh_config_set_grid_radius(c, value, msg, sizeof msg)
           : !strcmp(name, "growth") ? adh_config_set_growth(c, value, msg, sizeof msg)
           : !strcmp(name, "operator") ? adh_config_set_operator(c, value, msg, sizeof msg)
           : adh_config_set_grid(c, value, msg, sizeof msg);
    if (rc != 0) {
        char full[300];
        snprintf(full, sizeof full, "%s%s", msg, band || radius ? ", or auto" : "");
        return fail(sp, "%s: %s", name, full);
    }
    if (strcmp(name, "grid") != 0)
        return 1;
    sp->grid_given = 1;
    return kernel_fits(sp, name, value);
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
    scene_parse *sp = user;
    adh_config *c = sp->cfg;
    const scene_key *k = NULL;
    int known_section = 0;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        if (strcmp(keys[i].section, section) != 0)
            continue;
        known_section = 1;
        if (strcmp(keys[i].key, name) == 0)
            k = &keys[i];
    }
    if (!known_section)
        return fail(sp, "unknown section [%s]: sections are scene, material, grid, solver, protocol, output, sweep%s", section, "");
    if (!k)
        return fail(sp, "unknown key '%s' in [%s] (see adhere-scene(5))", name, section);
    char full[64];
    snprintf(full, sizeof full, "%s.%s", section, name);
    for (size_t i = 0; i < sp->nseen; i++)
        if (strcmp(sp->seen[i], full) == 0)
            return fail(sp, "key '%s' given twice in [%s]", name, section);
    if (sp->nseen < sizeof sp->seen / sizeof sp->seen[0])
        snprintf(sp->seen[sp->nseen++], sizeof sp->seen[0], "%s", full);

    char msg[256];
    double v;
    long n;
    int is_auto = strcasecmp(value, "auto") == 0;
    switch (k->kind) {
    case K_LEN: case K_PRESS: case K_ENERGY: case K_SPEED: {
        adh_quantity q = k->kind == K_LEN ? ADH_Q_LENGTH : k->kind == K_PRESS ? ADH_Q_PRESSURE
                       : k->kind == K_ENERGY ? ADH_Q_ENERGY : ADH_Q_SPEED;
        double *dst = NULL;
        if (!strcmp(full, "material.E")) dst = &c->mat.E;
        else if (!strcmp(full, "material.A")) dst = &c->mat.A;
        else if (!strcmp(full, "material.z0")) dst = &c->mat.z0;
        else if (!strcmp(full, "material.R")) dst = &c->mat.R;
        else if (!strcmp(full, "grid.spacing")) dst = &c->spacing;
        else if (!strcmp(full, "solver.eps")) dst = &c->relax.eps;
        else if (!strcmp(full, "protocol.start")) dst = &c->proto.start;
        else if (!strcmp(full, "protocol.step")) dst = &c->proto.step;
        else dst = &c->drive_speed;
        if (is_auto && (dst == &c->spacing || dst == &c->proto.start)) {
            *dst = NAN;
            return 1;
        }
        if (adh_parse_quantity(value, q, &v, msg, sizeof msg) != 0)
            return fail(sp, "%s: %s", name, msg);
        *dst = v;
        return 1;
    }
    case K_COUNT: {
        int nodes = !strcmp(name, "nodes"), jobs = !strcmp(name, "jobs");
        if (nodes && is_auto) { /* the grid follows the physics (adh_config_grid) */
            c->nodes = 1000;
            c->nodes_given = 0;
            return 1;
        }
        /* a whole number here; the run's limits are adh_drive_check's */
        if (adh_parse_count(value, jobs ? 1 : 0, jobs ? 64 : LONG_MAX, &n, msg, sizeof msg) != 0 ||
            (nodes ? adh_grid_nodes_check(n, msg, sizeof msg)
             : !strcmp(name, "dwell") ? adh_protocol_dwell_check(n, msg, sizeof msg)
             : !jobs ? adh_relax_max_iter_check(n, msg, sizeof msg) : ADH_SUCCESS) != ADH_SUCCESS)
            return fail(sp, "%s: %s", name, msg);
        if (nodes) c->nodes = (size_t)n, c->nodes_given = 1;
        else if (jobs) c->sweep.jobs = (int)n;
        else if (!strcmp(name, "dwell")) c->proto.dwell = (size_t)n;
        else c->relax.max_iter = (size_t)n;
        return 1;
    }
    case K_LENLIST:
        if (!strcmp(name, "turns")) {
            if (!parse_list(sp, name, value, c->proto.turns, ADH_MAX_TURNS, &c->proto.nturns))
                return 0;
            if (!sp->unload_given)
                c->proto.unload = c->proto.nturns > 0;
            return 1;
        }
        return parse_list(sp, name, value, c->proto.profiles, ADH_MAX_PROFILES, &c->proto.nprofiles);
    case K_KERNEL:
        if (adh_kernel_parse(value, &c->kernel) != 0)
            return fail(sp, "kernel: '%s' is not a kernel: use paper or ring%s", value, "");
        c->kernel_given = sp->kernel_given = 1;
        return kernel_fits(sp, name, value);
    case K_GRID:
        return grid_key(sp, name, value);
    case K_MIXING:
        if (adh_mix_rule_parse(value, &c->relax.rule) != 0)
            return fail(sp, "mixing: '%s' is not a mixing rule: use paper or momentum%s", value, "");
        return 1;
    case K_FRACTION: {
        double b;
        if (adh_parse_quantity(value, ADH_Q_NONE, &b, msg, sizeof msg) != 0 || !(b >= 0 && b < 1))
            return fail(sp, "momentum: '%s' is not allowed: a number from 0 to below 1%s", value, "");
        c->relax.momentum = b;
        return 1;
    }
    case K_MODE:
        if (!strcmp(value, "relax")) c->mode = ADH_MODE_RELAX;
        else if (!strcmp(value, "static")) c->mode = ADH_MODE_STATIC;
        else if (!strcmp(value, "rigid")) c->mode = ADH_MODE_RIGID;
        else return fail(sp, "mode: '%s' is not a mode: use relax, static or rigid%s", value, "");
        return 1;
    case K_BOOL:
        sp->unload_given = 1;
        if (!strcasecmp(value, "yes") || !strcmp(value, "1") || !strcasecmp(value, "true")) c->proto.unload = 1;
        else if (!strcasecmp(value, "no") || !strcmp(value, "0") || !strcasecmp(value, "false")) c->proto.unload = 0;
        else return fail(sp, "%s: '%s' is not yes or no", name, value);
        return 1;
    case K_PLOTS: {
        unsigned mask = 0;
        int none = 0;
        char buf[256], *save = NULL;
        snprintf(buf, sizeof buf, "%s", value);
        for (char *t = strtok_r(buf, ", ", &save); t; t = strtok_r(NULL, ", ", &save)) {
            if (!strcmp(t, "force")) mask |= ADH_PLOT_FORCE;
            else if (!strcmp(t, "profile")) mask |= ADH_PLOT_PROFILE;
            else if (!strcmp(t, "contact")) mask |= ADH_PLOT_CONTACT;
            else if (!strcmp(t, "precontact")) mask |= ADH_PLOT_PRECONTACT;
            else if (!strcmp(t, "bulge")) mask |= ADH_PLOT_BULGE;
            /* none: no figure of a single run; a sweep's combined figure
             * ([sweep] plot) still follows --no-plot alone */
            else if (!strcmp(t, "none")) none = 1;
            else return fail(sp, "plots: '%s' is not a plot: use force, profile, contact, precontact, bulge or none%s", t, "");
        }
        if (!none && !mask)
            return fail(sp, "plots: name at least one of force, profile, contact, precontact, bulge, or none%s%s", "", "");
        if (none && mask)
            return fail(sp, "plots: 'none' cannot be combined with other plots%s%s", "", "");
        c->plots = mask;
        return 1;
    }
    case K_SWEEP:
        return parse_sweep(sp, name, value);
    case K_SWEEP_PLOT:
        if (!strcmp(value, "jump")) c->sweep.plot = ADH_SWEEP_PLOT_JUMP;
        else if (!strcmp(value, "force")) c->sweep.plot = ADH_SWEEP_PLOT_FORCE;
        else if (!strcmp(value, "none")) c->sweep.plot = ADH_SWEEP_PLOT_NONE;
        else return fail(sp, "plot: '%s' is not a sweep plot: use jump, force or none%s", value, "");
        return 1;
    case K_TEXT:
        /* shown on terminals and in figures: one line of printable text */
        for (const unsigned char *t = (const unsigned char *)value; *t; t++)
            if ((*t < 0x20 && *t != '\t') || *t == 0x7f) {
                snprintf(msg, sizeof msg, "0x%02x", *t);
                return fail(sp, "title: the control character %s is not allowed: a title is one line of "
                            "printable text%s", msg, "");
            }
        snprintf(c->title, sizeof c->title, "%s", value);
        return 1;
    }
    return fail(sp, "internal: key %s has no handler%s", name, "");
}

static void finish_error(scene_parse *sp, int rc, char *why, size_t whylen)
{
    if (rc > 0 && !sp->why[0])
        snprintf(sp->why, sizeof sp->why, "syntax error (expected [section] or key = value)");
    snprintf(why, whylen, "%s:%d: %s", sp->file, rc, sp->why);
}

/* What inih would pass over or misplace, checked line by line first: a
 * section header is checked where it stands (inih reports nothing for an
 * empty unknown section), a key before any section, an indented line (inih
 * would glue it onto the previous value), a line longer than inih's buffer. */
static int prescan(const char *text, scene_parse *sp)
{
    int line = 0, in_section = 0;
    /* inih splits lines at \n only: a file with old Mac line ends (\r
     * alone) would be one long line and every key lost */
    for (const char *p = text; *p; p++) {
        if (*p == '\n')
            line++;
        else if (*p == '\r' && p[1] != '\n') {
            fail(sp, "a carriage return without a line feed (old Mac line ends): save the file with Unix (LF) or DOS (CRLF) line ends%s%s", "", "");
            return line + 1;
        }
    }
    line = 0;
    for (const char *p = text; *p;) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        line++;
        char buf[512];
        if (len >= 199) {
            fail(sp, "line longer than 198 characters%s%s", "", "");
            return line;
        }
        memcpy(buf, p, len);
        buf[len] = '\0';
        p = eol ? eol + 1 : p + len; /* before the \r is dropped: a last line
                                        "x\r" must still move p to its end */
        if (len && buf[len - 1] == '\r')
            buf[--len] = '\0';
        const char *t = buf;
        if (line == 1 && (unsigned char)t[0] == 0xEF && (unsigned char)t[1] == 0xBB && (unsigned char)t[2] == 0xBF)
            t += 3; /* a UTF-8 byte order mark */
        int indented = *t == ' ' || *t == '\t';
        while (*t == ' ' || *t == '\t')
            t++;
        if (!*t || *t == '#' || *t == ';')
            continue;
        if (indented) {
            fail(sp, "indented line: write each key = value at the start of its own line%s%s", "", "");
            return line;
        }
        if (*t == '[') {
            const char *close = strchr(t, ']');
            if (!close) {
                fail(sp, "syntax error: section header without ']'%s%s", "", "");
                return line;
            }
            char name[64];
            size_t nl = (size_t)(close - t - 1) < sizeof name - 1 ? (size_t)(close - t - 1) : sizeof name - 1;
            memcpy(name, t + 1, nl);   /* a longer name is no known section either way */
            name[nl] = '\0';
            int known = 0;
            for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
                known |= strcmp(keys[i].section, name) == 0;
            if (!known) {
                fail(sp, "unknown section [%s]: sections are scene, material, grid, solver, protocol, output, sweep%s", name, "");
                return line;
            }
            /* inih drops whatever follows the ']' on the line */
            const char *rest = close + 1;
            while (*rest == ' ' || *rest == '\t')
                rest++;
            if (*rest && *rest != '#' && *rest != ';') {
                fail(sp, "text after the section header [%s]: '%s' would be ignored; put each key = value on its own line", name, rest);
                return line;
            }
            in_section = 1;
            continue;
        }
        if (!in_section) {
            fail(sp, "'%.200s' comes before any [section]%s", t, "");
            return line;
        }
    }
    return 0;
}

int adh_scene_parse_string(const char *text, const char *name, adh_config *cfg, char *why, size_t whylen)
{
    scene_parse sp;
    memset(&sp, 0, sizeof sp);
    sp.cfg = cfg;
    sp.file = name;
    int rc = prescan(text, &sp);
    if (rc == 0)
        rc = ini_parse_string(text, handler, &sp);
    if (rc != 0) {
        finish_error(&sp, rc, why, whylen);
        return -1;
    }
    return 0;
}

static int is_file(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

int adh_scene_find(const char *arg, char *path, size_t pathlen, char *why, size_t whylen)
{
    if (strchr(arg, '/') || strstr(arg, ".scene") || is_file(arg)) {
        if (!is_file(arg)) {
            snprintf(why, whylen, "scene file %s: %s", arg, errno ? strerror(errno) : "not a regular file");
            return -1;
        }
        snprintf(path, pathlen, "%s", arg);
        return 0;
    }
    char root[3][PATH_MAX];
    int tried[3];
    for (int i = 0; i < 3; i++) {
        tried[i] = adh_data_root(i, root[i], sizeof root[i]) == 0;
        if (!tried[i])
            continue;
        snprintf(path, pathlen, "%s/scenes/%s.scene", root[i], arg);
        if (is_file(path))
            return 0;
    }
    snprintf(why, whylen, "no scene named '%.100s' (looked in %.300s%s%.300s%s%.300s/scenes; $ADHERE_DATADIR "
             "sets where); shipped scenes are default and fig1 ... fig8", arg,
             tried[0] ? root[0] : "", tried[0] ? "/scenes, " : "", tried[1] ? root[1] : "",
             tried[1] ? "/scenes, " : "", root[2]);
    return -1;
}

int adh_scene_load(const char *arg, adh_config *cfg, char *why, size_t whylen)
{
    char path[PATH_MAX];
    if (adh_scene_find(arg, path, sizeof path, why, whylen) != 0)
        return -1;
    /* read whole, so the same checks as for text in memory apply */
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(why, whylen, "%s: cannot read scene: %s", path, strerror(errno));
        return -1;
    }
    char *text = NULL;
    size_t cap = 0, len = 0;
    for (;;) {
        if (len + 4096 + 1 > cap) {
            cap = cap ? 2 * cap : 8192;
            char *grown = cap <= (1u << 20) ? realloc(text, cap) : NULL;
            if (!grown) {
                free(text);
                fclose(f);
                snprintf(why, whylen, "%s: cannot read scene: larger than 1 MiB or out of memory", path);
                return -1;
            }
            text = grown;
        }
        size_t got = fread(text + len, 1, 4096, f);
        len += got;
        if (got < 4096)
            break;
    }
    int bad = ferror(f);
    fclose(f);
    text[len] = '\0';
    const char *nul = bad ? NULL : memchr(text, '\0', len);
    if (bad || nul) {
        int line = 1;
        for (const char *p = text; p < nul; p++)
            line += *p == '\n';
        if (nul)
            snprintf(why, whylen, "%s:%d: a NUL byte: not a text file", path, line);
        else
            snprintf(why, whylen, "%s: cannot read scene: read error", path);
        free(text);
        return -1;
    }
    int rc = adh_scene_parse_string(text, path, cfg, why, whylen);
    free(text);
    if (rc != 0)
        return -1;
    snprintf(cfg->scene, sizeof cfg->scene, "%s", path);
    return 0;
}
