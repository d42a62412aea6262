#include "scene/scene.h"

#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "adhere/units.h"

typedef struct scene_parse {
    adh_config *cfg;
    const char *file;
    char why[512];
    int line;                    /* line of the first error, from inih */
    char seen[128][64];          /* "section.key" already given: duplicates are errors */
    size_t nseen;
} scene_parse;

typedef enum { K_LEN, K_PRESS, K_ENERGY, K_SPEED, K_COUNT, K_LENLIST, K_KERNEL, K_MODE,
               K_PLOTS, K_BOOL, K_TEXT } key_kind;

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
    { "solver", "eps", K_LEN }, { "solver", "max_iter", K_COUNT },
    { "protocol", "start", K_LEN }, { "protocol", "step", K_LEN }, { "protocol", "turns", K_LENLIST },
    { "protocol", "dwell", K_COUNT }, { "protocol", "unload", K_BOOL },
    { "output", "plots", K_PLOTS }, { "output", "profiles", K_LENLIST },
    { "output", "drive_speed", K_SPEED },
};

static int fail(scene_parse *sp, const char *fmt, const char *a, const char *b)
{
    /* inih goes on after an error and reports the first line: keep its message. */
    if (!sp->why[0])
        snprintf(sp->why, sizeof sp->why, fmt, a, b);
    return 0; /* inih: 0 = error at this line */
}

static int parse_list(scene_parse *sp, const char *key, const char *value, double *out, size_t cap, size_t *count)
{
    char buf[1024], msg[256];
    *count = 0;
    if (strcasecmp(value, "none") == 0)
        return 1;
    snprintf(buf, sizeof buf, "%s", value);
    char *save = NULL;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (*count == cap)
            return fail(sp, "%s: too many values%s", key, "");
        if (adh_parse_quantity(t, ADH_Q_LENGTH, &out[(*count)++], msg, sizeof msg) != 0)
            return fail(sp, "%s: %s", key, msg);
    }
    return *count ? 1 : fail(sp, "%s: expected lengths separated by commas, or none%s", key, "");
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
        return fail(sp, "unknown section [%s]: sections are scene, material, grid, solver, protocol, output%s", section, "");
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
        int nodes = !strcmp(name, "nodes");
        if (adh_parse_count(value, nodes ? 10 : !strcmp(name, "dwell") ? 0 : 1, nodes ? 20000 : 100000000, &n, msg, sizeof msg) != 0)
            return fail(sp, "%s: %s", name, msg);
        if (nodes) c->nodes = (size_t)n;
        else if (!strcmp(name, "dwell")) c->proto.dwell = (size_t)n;
        else c->relax.max_iter = (size_t)n;
        return 1;
    }
    case K_LENLIST:
        if (!strcmp(name, "turns")) {
            if (!parse_list(sp, name, value, c->proto.turns, ADH_MAX_TURNS, &c->proto.nturns))
                return 0;
            c->proto.unload = c->proto.nturns > 0;
            return 1;
        }
        return parse_list(sp, name, value, c->proto.profiles, ADH_MAX_PROFILES, &c->proto.nprofiles);
    case K_KERNEL:
        if (adh_kernel_parse(value, &c->kernel) != 0)
            return fail(sp, "kernel: '%s' is not a kernel: use paper or ring%s", value, "");
        return 1;
    case K_MODE:
        if (!strcmp(value, "relax")) c->mode = ADH_MODE_RELAX;
        else if (!strcmp(value, "static")) c->mode = ADH_MODE_STATIC;
        else return fail(sp, "mode: '%s' is not a mode: use relax or static%s", value, "");
        return 1;
    case K_BOOL:
        if (!strcasecmp(value, "yes") || !strcmp(value, "1") || !strcasecmp(value, "true")) c->proto.unload = 1;
        else if (!strcasecmp(value, "no") || !strcmp(value, "0") || !strcasecmp(value, "false")) c->proto.unload = 0;
        else return fail(sp, "%s: '%s' is not yes or no", name, value);
        return 1;
    case K_PLOTS: {
        unsigned mask = 0;
        char buf[256], *save = NULL;
        snprintf(buf, sizeof buf, "%s", value);
        for (char *t = strtok_r(buf, ", ", &save); t; t = strtok_r(NULL, ", ", &save)) {
            if (!strcmp(t, "force")) mask |= ADH_PLOT_FORCE;
            else if (!strcmp(t, "profile")) mask |= ADH_PLOT_PROFILE;
            else if (!strcmp(t, "contact")) mask |= ADH_PLOT_CONTACT;
            else if (!strcmp(t, "none")) c->plot = 0;
            else return fail(sp, "plots: '%s' is not a plot: use force, profile, contact or none%s", t, "");
        }
        if (mask)
            c->plots = mask;
        return 1;
    }
    case K_TEXT:
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

int adh_scene_parse_string(const char *text, const char *name, adh_config *cfg, char *why, size_t whylen)
{
    scene_parse sp;
    memset(&sp, 0, sizeof sp);
    sp.cfg = cfg;
    sp.file = name;
    int rc = ini_parse_string(text, handler, &sp);
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
    const char *env = getenv("ADHERE_DATADIR");
    const char *dirs[] = { env, ADH_DATADIR, ADH_SRCDATA };
    for (size_t i = 0; i < 3; i++) {
        if (!dirs[i] || !*dirs[i])
            continue;
        snprintf(path, pathlen, "%s/scenes/%s.scene", dirs[i], arg);
        if (is_file(path))
            return 0;
    }
    snprintf(why, whylen, "no scene named '%s' (looked in $ADHERE_DATADIR/scenes, %s/scenes, %s/scenes); "
             "shipped scenes are default and fig1 ... fig8", arg, ADH_DATADIR, ADH_SRCDATA);
    return -1;
}

int adh_scene_load(const char *arg, adh_config *cfg, char *why, size_t whylen)
{
    char path[PATH_MAX];
    if (adh_scene_find(arg, path, sizeof path, why, whylen) != 0)
        return -1;
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(why, whylen, "cannot read scene %s: %s", path, strerror(errno));
        return -1;
    }
    scene_parse sp;
    memset(&sp, 0, sizeof sp);
    sp.cfg = cfg;
    sp.file = path;
    int rc = ini_parse_file(f, handler, &sp);
    fclose(f);
    if (rc != 0) {
        if (rc < 0)
            snprintf(why, whylen, "cannot read scene %s", path);
        else
            finish_error(&sp, rc, why, whylen);
        return -1;
    }
    snprintf(cfg->scene, sizeof cfg->scene, "%s", path);
    return 0;
}
