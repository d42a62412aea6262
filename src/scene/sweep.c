/* A study's swept keys: each a list of values or a range, the runs their
 * Cartesian product, a run the configuration with those keys set through
 * adh_config_set, as a scene or a flag sets them. */
#include "scene/config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "adhere/params.h"
#include "adhere/status.h"
#include "adhere/units.h"

/* sigma is no key of the configuration: it sets E by eq 17 */
#define SIGMA "sigma"

/* Copies text without the blanks around it into buf; its length, or
 * (size_t)-1 when it does not fit. */
static size_t trim(const char *text, size_t n, char *buf, size_t len)
{
    while (n && (*text == ' ' || *text == '\t'))
        text++, n--;
    while (n && (text[n - 1] == ' ' || text[n - 1] == '\t'))
        n--;
    if (n >= len)
        return (size_t)-1;
    memcpy(buf, text, n);
    buf[n] = '\0';
    return n;
}

/* The run key `name` names (its name under its section, or the key
 * itself), or NULL with why. */
static const adh_config_key *run_key(const char *name, char *why, size_t whylen)
{
    const adh_config_key *k, *found = NULL;
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        const char *dot = strchr(k->key, '.');
        if (!(k->where & ADH_KEY_RUN) || !(strcmp(k->key, name) == 0 || (dot && strcmp(dot + 1, name) == 0)))
            continue;
        if (found) {
            snprintf(why, whylen, "'%s' names both %s and %s: write the whole key", name, found->key, k->key);
            return NULL;
        }
        found = k;
    }
    if (!found)
        snprintf(why, whylen, "'%.60s' is no key of a run: sweep a key of [material], [grid], [solver] or "
                 "[protocol] (E, A, z0, R, nodes, eps, step, turns, dwell, ...), or sigma", name);
    return found;
}

/* An axis for name: its key, name, quantity and kind. 0, or -1 with why. */
static int axis_for(const char *name, adh_sweep_axis *a, char *why, size_t whylen)
{
    memset(a, 0, sizeof *a);
    if (strcmp(name, SIGMA) == 0 || strcmp(name, "material.sigma") == 0) {
        snprintf(a->name, sizeof a->name, SIGMA);
        snprintf(a->key, sizeof a->key, SIGMA);
        a->quantity = ADH_Q_NONE;
        return 0;
    }
    const adh_config_key *k = run_key(name, why, whylen);
    if (!k)
        return -1;
    const char *dot = strchr(k->key, '.');
    snprintf(a->name, sizeof a->name, "%s", dot ? dot + 1 : k->key);
    snprintf(a->key, sizeof a->key, "%s", k->key);
    a->quantity = (int)k->q;
    a->count = (k->where & ADH_KEY_COUNT) != 0;
    return 0;
}

int adh_sweep_key_of(const char *name, char *key, size_t len)
{
    adh_sweep_axis a;
    char why[300];
    if (axis_for(name, &a, why, sizeof why) != 0)
        return -1;
    snprintf(key, len, "%s", a.key);
    return 0;
}

/* The three parameters a sweep had before any key could be swept are
 * positive quantities; their values say so where they are written. */
static int positive_only(const adh_sweep_axis *a)
{
    return !strcmp(a->key, SIGMA) || !strcmp(a->key, "material.E") || !strcmp(a->key, "solver.eps");
}

/* src into text (of len), cut at its end. */
static void copy_text(const char *src, char *text, size_t len)
{
    size_t n = strlen(src);
    if (!text || !len)
        return;
    if (n >= len)
        n = len - 1;
    memcpy(text, src, n);
    text[n] = '\0';
}

double adh_sweep_value(const adh_sweep_axis *a, size_t j, char *text, size_t len)
{
    double v;
    char buf[40];
    if (a->spacing == ADH_SWEEP_LIST) {
        copy_text(a->text[j], text, len);
        return a->num[j];
    }
    double t = a->n > 1 ? (double)j / (double)(a->n - 1) : 0;
    if (j == 0)
        v = a->lo;
    else if (j + 1 == a->n)
        v = a->hi;
    else if (a->spacing == ADH_SWEEP_LOG)
        v = a->lo * pow(a->hi / a->lo, t);
    else
        v = a->lo + (a->hi - a->lo) * t;
    if (a->count)
        v = (double)llround(v);
    snprintf(buf, sizeof buf, "%.17g", v);
    copy_text(buf, text, len);
    return v;
}

/* Every value of a goes into the key on a scratch configuration: the
 * key's own sentence for one it does not take. */
static int values_fit(const adh_config *c, const adh_sweep_axis *a, char *why, size_t whylen)
{
    adh_config *scratch = malloc(sizeof *scratch);
    if (!scratch) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    *scratch = *c;
    int rc = 0;
    /* a range's values lie between its ends, which the key takes or not
     * as they do (its limits are intervals): the ends are checked */
    for (size_t j = 0; j < a->n && rc == 0; j = a->spacing == ADH_SWEEP_LIST || j + 1 == a->n ? j + 1 : a->n - 1) {
        char text[64], msg[400];
        double v = adh_sweep_value(a, j, text, sizeof text);
        if (strcmp(a->key, SIGMA) != 0 && adh_config_set(scratch, a->key, text, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "%.300s", msg);
            rc = -1;
        } else if (positive_only(a) && !(v > 0)) {
            snprintf(why, whylen, "the swept value %s is not allowed: every value must be above 0", text);
            rc = -1;
        }
    }
    free(scratch);
    return rc;
}

/* "LO .. HI, [lin|log,] N" into a. 0, or -1 with why. */
static int parse_range(const char *text, adh_sweep_axis *a, char *why, size_t whylen)
{
    const char *dots = strstr(text, "..");
    char lo[64], hi[64], mid[16] = "lin", count[32];
    const char *rest = dots + 2, *c1 = strchr(rest, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    const char *c3 = c2 ? strchr(c2 + 1, ',') : NULL;
    int ok = c1 && !c3 && trim(text, (size_t)(dots - text), lo, sizeof lo) != (size_t)-1 &&
             trim(rest, (size_t)(c1 - rest), hi, sizeof hi) != (size_t)-1;
    if (ok && c2)
        ok = trim(c1 + 1, (size_t)(c2 - c1 - 1), mid, sizeof mid) != (size_t)-1 &&
             trim(c2 + 1, strlen(c2 + 1), count, sizeof count) != (size_t)-1;
    else if (ok)
        ok = trim(c1 + 1, strlen(c1 + 1), count, sizeof count) != (size_t)-1;
    if (!ok) {
        snprintf(why, whylen, "'%.100s' is not a range: write LO .. HI, N or LO .. HI, lin|log, N", text);
        return -1;
    }
    long n;
    adh_quantity q = (adh_quantity)a->quantity;
    if (adh_parse_quantity(lo, q, &a->lo, why, whylen) != 0 || adh_parse_quantity(hi, q, &a->hi, why, whylen) != 0)
        return -1;
    if (strcmp(mid, "lin") && strcmp(mid, "log")) {
        snprintf(why, whylen, "'%.20s' is not a spacing: use lin or log", mid);
        return -1;
    }
    if (adh_parse_count(count, 2, ADH_SWEEP_MAX_RUNS, &n, why, whylen) != 0)
        return -1;
    a->spacing = strcmp(mid, "log") ? ADH_SWEEP_LIN : ADH_SWEEP_LOG;
    a->n = (size_t)n;
    if (!(a->lo != a->hi) || !isfinite(a->lo) || !isfinite(a->hi)) {
        snprintf(why, whylen, "the range %s .. %s is empty: give two different ends", lo, hi);
        return -1;
    }
    if (a->spacing == ADH_SWEEP_LOG && !(a->lo / a->hi > 0)) {
        snprintf(why, whylen, "a log range needs ends of one sign, neither 0 (%s .. %s)", lo, hi);
        return -1;
    }
    for (size_t j = 1; a->count && j < a->n; j++)
        if (adh_sweep_value(a, j, NULL, 0) == adh_sweep_value(a, j - 1, NULL, 0)) {
            snprintf(why, whylen, "%zu whole numbers from %s to %s repeat: give fewer values", a->n, lo, hi);
            return -1;
        }
    return 0;
}

/* "V1, V2, ..." into a. 0, or -1 with why. */
static int parse_list(const char *text, adh_sweep_axis *a, char *why, size_t whylen)
{
    a->spacing = ADH_SWEEP_LIST;
    a->n = 0;
    if (adh_list_decimal_comma(text, (adh_quantity)a->quantity, why, whylen) != ADH_SUCCESS)
        return -1;
    for (const char *seg = text;;) {
        const char *comma = strchr(seg, ',');
        size_t len = comma ? (size_t)(comma - seg) : strlen(seg);
        if (a->n == ADH_SWEEP_MAX_LIST) {
            snprintf(why, whylen, "more than %d values: give a range (LO .. HI, N)", ADH_SWEEP_MAX_LIST);
            return -1;
        }
        char *v = a->text[a->n];
        size_t got = trim(seg, len, v, ADH_SWEEP_VALUE_LEN);
        if (got == 0) {
            snprintf(why, whylen, "'%.200s' has an empty element: separate values by single commas", text);
            return -1;
        }
        if (got == (size_t)-1) {
            snprintf(why, whylen, "'%.*s' is longer than %d characters", (int)(len < 80 ? len : 80), seg,
                     ADH_SWEEP_VALUE_LEN - 1);
            return -1;
        }
        if (adh_parse_quantity(v, (adh_quantity)a->quantity, &a->num[a->n], NULL, 0) != 0)
            a->num[a->n] = NAN;
        if (!strcmp(a->key, SIGMA) && adh_parse_quantity(v, ADH_Q_NONE, &a->num[a->n], why, whylen) != 0)
            return -1;
        for (size_t j = 0; j < a->n; j++)
            if (isnan(a->num[a->n]) ? !strcmp(a->text[j], v) : a->num[j] == a->num[a->n]) {
                snprintf(why, whylen, "'%s' is given twice: each value once", v);
                return -1;
            }
        a->n++;
        if (!comma)
            return 0;
        seg = comma + 1;
    }
}

/* The runs with axes a[0..n): their product, or 0 past ADH_SWEEP_MAX_RUNS. */
static size_t product(const adh_sweep_axis *a, size_t n)
{
    size_t runs = 1;
    for (size_t i = 0; i < n; i++) {
        if (a[i].n && runs > ADH_SWEEP_MAX_RUNS / a[i].n)
            return 0;
        runs *= a[i].n;
    }
    return runs <= ADH_SWEEP_MAX_RUNS ? runs : 0;
}

const adh_sweep_axis *adh_sweep_axis_of(const adh_sweep *s, const char *name)
{
    for (size_t i = 0; i < s->naxes; i++)
        if (!strcmp(s->axis[i].name, name) || !strcmp(s->axis[i].key, name))
            return &s->axis[i];
    return NULL;
}

/* Whether a and b set the same value (sigma sets E, E0 is E; speed sets
 * the retraction speed too), so that one of two sweeps would be silently
 * undone: why, or NULL. */
static const char *clash(const char *a, const char *b)
{
    static const char *const pair[][3] = {
        { SIGMA, "material.E", "sigma and E both set the modulus (sigma by eq 17): sweep one of them" },
        { SIGMA, "material.E0", "sigma and E0 both set the modulus (sigma by eq 17): sweep one of them" },
        { "material.E", "material.E0", "E and E0 both set the modulus (E0 is a standard linear solid's E): sweep "
          "one of them" },
        { "protocol.speed", "protocol.speed_out", "speed and speed_out both set the retraction speed (speed sets "
          "both ways): sweep one of them" },
    };
    for (size_t i = 0; i < sizeof pair / sizeof pair[0]; i++)
        if ((!strcmp(a, pair[i][0]) && !strcmp(b, pair[i][1])) || (!strcmp(b, pair[i][0]) && !strcmp(a, pair[i][1])))
            return pair[i][2];
    return NULL;
}

int adh_sweep_set(adh_config *c, const char *name, const char *text, char *why, size_t whylen)
{
    adh_sweep *s = &c->sweep;
    adh_sweep_axis *a = malloc(sizeof *a);
    if (!a) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    int rc = axis_for(name, a, why, whylen);
    size_t at = s->naxes;
    for (size_t i = 0; rc == 0 && i < s->naxes; i++) {
        if (!strcmp(s->axis[i].key, a->key))
            at = i;
        else if (clash(s->axis[i].key, a->key) && strcasecmp(text, "none") != 0) {
            snprintf(why, whylen, "%s", clash(s->axis[i].key, a->key));
            rc = -1;
        }
    }
    if (rc == 0 && strcasecmp(text, "none") == 0) {   /* not swept: the axis goes */
        if (at < s->naxes)
            memmove(&s->axis[at], &s->axis[at + 1], (s->naxes - at - 1) * sizeof *a);
        s->naxes -= at < s->naxes;
        free(a);
        return 0;
    }
    if (rc == 0 && at == ADH_SWEEP_MAX_AXES) {
        snprintf(why, whylen, "more than %d swept keys", ADH_SWEEP_MAX_AXES);
        rc = -1;
    }
    if (rc == 0)
        rc = strstr(text, "..") ? parse_range(text, a, why, whylen) : parse_list(text, a, why, whylen);
    if (rc == 0)
        rc = values_fit(c, a, why, whylen);
    if (rc == 0) {
        size_t n = s->naxes + (at == s->naxes);
        adh_sweep_axis keep = s->axis[at];
        s->axis[at] = *a;
        if (!product(s->axis, n)) {
            s->axis[at] = keep;
            snprintf(why, whylen, "the study would have more than %d runs", ADH_SWEEP_MAX_RUNS);
            rc = -1;
        } else {
            s->naxes = n;
        }
    }
    free(a);
    return rc;
}

void adh_sweep_get(const adh_config *c, const char *name, char *buf, size_t len)
{
    adh_sweep_axis probe;
    char why[200];
    const adh_sweep_axis *a = axis_for(name, &probe, why, sizeof why) == 0 ? adh_sweep_axis_of(&c->sweep, probe.key)
                                                                          : NULL;
    if (!a) {
        snprintf(buf, len, "none");
        return;
    }
    if (a->spacing != ADH_SWEEP_LIST) {
        snprintf(buf, len, "%.17g .. %.17g, %s, %zu", a->lo, a->hi, a->spacing == ADH_SWEEP_LOG ? "log" : "lin", a->n);
        return;
    }
    size_t o = 0;
    buf[0] = '\0';
    for (size_t j = 0; j < a->n && o + 1 < len; j++) {
        int w = snprintf(buf + o, len - o, "%s%s", j ? "," : "", a->text[j]);
        o += w > 0 ? (size_t)w : 0;
    }
}

size_t adh_sweep_runs(const adh_sweep *s)
{
    return s->naxes ? product(s->axis, s->naxes) : 1;
}

void adh_sweep_index(const adh_sweep *s, size_t i, size_t *idx)
{
    for (size_t k = s->naxes; k-- > 0;) {
        idx[k] = s->axis[k].n ? i % s->axis[k].n : 0;
        i = s->axis[k].n ? i / s->axis[k].n : 0;
    }
}

void adh_sweep_describe(const adh_sweep *s, size_t i, char *buf, size_t len)
{
    size_t idx[ADH_SWEEP_MAX_AXES], o = 0;
    adh_sweep_index(s, i, idx);
    if (len)
        buf[0] = '\0';
    for (size_t k = 0; k < s->naxes && o + 1 < len; k++) {
        char v[64];
        double x = adh_sweep_value(&s->axis[k], idx[k], v, sizeof v);
        int w = isnan(x) ? snprintf(buf + o, len - o, "%s%s = %s", k ? ", " : "", s->axis[k].name, v)
                         : snprintf(buf + o, len - o, "%s%s = %g", k ? ", " : "", s->axis[k].name, x);
        o += w > 0 ? (size_t)w : 0;
    }
}

int adh_sweep_touches(const adh_sweep *s, const char *prefix)
{
    for (size_t k = 0; k < s->naxes; k++)
        if (!strncmp(s->axis[k].key, prefix, strlen(prefix)))
            return 1;
    return 0;
}

int adh_sweep_run_dirs(const adh_sweep *s)
{
    if (s->run_dirs >= 0)
        return s->run_dirs;
    return adh_sweep_runs(s) <= 32 || s->plot == ADH_SWEEP_PLOT_FORCE;
}

size_t adh_config_nruns(const adh_config *c)
{
    return adh_sweep_runs(&c->sweep);
}

/* The swept keys of s's run i set on t's spec (a run key sets nothing
 * else), as adh_config_set sets them; base_turns: the configuration's
 * turns before the sweep. */
static void apply(const adh_sweep *s, size_t base_turns, size_t i, adh_config *t)
{
    size_t idx[ADH_SWEEP_MAX_AXES];
    adh_sweep_index(s, i, idx);
    double sigma = NAN;
    for (size_t k = 0; k < s->naxes; k++) {
        char text[64], why[256];
        double v = adh_sweep_value(&s->axis[k], idx[k], text, sizeof text);
        if (!strcmp(s->axis[k].key, SIGMA)) {
            sigma = v;
            continue;
        }
        int unload = t->spec.proto.unload;
        adh_config_set(t, s->axis[k].key, text, why, sizeof why);   /* each value was checked when set */
        /* turns imply unloading, unless the configuration had turns and said otherwise */
        if (!strcmp(s->axis[k].key, "protocol.turns") && base_turns)
            t->spec.proto.unload = unload;
    }
    if (!isnan(sigma))
        t->spec.mat.E = adh_material_modulus_at_sigma(&t->spec.mat, sigma);
}

/* The one rule of a study's modes: its runs share run 1's mode unless
 * scene.mode itself is swept (then each run has its mode, and a grid of
 * its own). */
static int mode_swept(const adh_sweep *s)
{
    return adh_sweep_touches(s, "scene.mode");
}

int adh_config_sweep_mode_check(const adh_config *c, size_t i, const adh_run_spec *run, adh_mode first, char *why,
                                size_t whylen)
{
    if (run->mode == first || mode_swept(&c->sweep))
        return 0;
    char which[256];
    adh_sweep_describe(&c->sweep, i, which, sizeof which);
    snprintf(why, whylen, "sweep run %zu (%s) runs in mode %s, run 1 in mode %s: a study's runs share one mode unless "
             "the mode itself is swept; give the mode (scene.mode = %s) for every run, or sweep it", i + 1, which,
             adh_config_mode_word(run->mode), adh_config_mode_word(first),
             adh_config_mode_word(run->mode == ADH_MODE_TIME ? ADH_MODE_TIME : first));
    return -1;
}

void adh_config_sweep_run(const adh_config *c, size_t i, adh_run_spec *run)
{
    if (!c->sweep.naxes || i >= adh_sweep_runs(&c->sweep)) {
        *run = c->spec;
        run->proto = adh_config_protocol(c);
        return;
    }
    /* only the spec and the plots (for the protocol's profiles) are read */
    adh_config t;
    t.spec = c->spec;
    t.output.plots = c->output.plots;
    apply(&c->sweep, c->spec.proto.nturns, i, &t);
    /* a run whose grid settings or mode differ has a grid of its own */
    if (adh_sweep_touches(&c->sweep, "grid.") || mode_swept(&c->sweep)) {
        char why[512];
        adh_config_choose_grid(&t.spec, NULL, why, sizeof why, NULL);
    }
    *run = t.spec;
    run->proto = adh_config_protocol_for(&t, t.spec.mode);
}

void adh_sweep_materials(const adh_sweep *s, const adh_run_spec *base, adh_sweep_material_cb cb, void *ctx)
{
    adh_sweep *sub = malloc(sizeof *sub);
    adh_config *t = malloc(sizeof *t);
    if (!sub || !t) {   /* the base's alone */
        cb(&base->mat, ctx);
        free(sub), free(t);
        return;
    }
    memset(sub, 0, sizeof *sub);
    for (size_t k = 0; k < s->naxes; k++)
        if (!strncmp(s->axis[k].key, "material.", 9) || !strcmp(s->axis[k].key, SIGMA))
            sub->axis[sub->naxes++] = s->axis[k];
    size_t n = adh_sweep_runs(sub);
    for (size_t i = 0; i < n; i++) {
        t->spec = *base;
        apply(sub, base->proto.nturns, i, t);
        cb(&t->spec.mat, ctx);
    }
    free(sub), free(t);
}

/* ---- drives: runs that differ only in their turn share one ------------- */

/* The axis whose runs share drives, else NULL; *at its position: the
 * turns in relaxation (one loading branch, an unloading branch from each
 * turn), the spring on the static curve (the curve does not depend on k:
 * each k's snap points are read off one curve), the mode not swept. */
static const adh_sweep_axis *shared_turns(const adh_config *c, size_t *at)
{
    const adh_sweep *s = &c->sweep;
    const char *key = c->spec.mode == ADH_MODE_RELAX ? "protocol.turns"
                    : c->spec.mode == ADH_MODE_STATIC ? "protocol.spring" : NULL;
    if (!key || adh_sweep_touches(s, "scene.mode"))
        return NULL;
    for (size_t k = 0; k < s->naxes; k++)
        if (!strcmp(s->axis[k].key, key)) {
            *at = k;
            return &s->axis[k];
        }
    return NULL;
}

static size_t chunks(size_t nt)
{
    return (nt + ADH_MAX_TURNS - 1) / ADH_MAX_TURNS;
}

size_t adh_sweep_drives(const adh_config *c)
{
    size_t at;
    const adh_sweep_axis *t = shared_turns(c, &at);
    size_t runs = adh_config_nruns(c);
    return t ? runs / t->n * chunks(t->n) : runs;
}

size_t adh_sweep_drive_runs(const adh_config *c, size_t u, size_t *runs)
{
    size_t at;
    const adh_sweep *s = &c->sweep;
    const adh_sweep_axis *t = shared_turns(c, &at);
    if (!t) {
        runs[0] = u;
        return 1;
    }
    size_t per = chunks(t->n), g = u / per, first = (u % per) * ADH_MAX_TURNS;
    size_t n = t->n - first < ADH_MAX_TURNS ? t->n - first : ADH_MAX_TURNS;
    /* g: the other axes' combination, the first slowest */
    size_t idx[ADH_SWEEP_MAX_AXES];
    for (size_t k = s->naxes; k-- > 0;) {
        if (k == at)
            continue;
        idx[k] = g % s->axis[k].n;
        g /= s->axis[k].n;
    }
    for (size_t j = 0; j < n; j++) {
        idx[at] = first + j;
        size_t i = 0;
        for (size_t k = 0; k < s->naxes; k++)
            i = i * s->axis[k].n + idx[k];
        runs[j] = i;
    }
    return n;
}

void adh_sweep_drive_spec(const adh_config *c, size_t u, adh_run_spec *run)
{
    size_t at, runs[ADH_MAX_TURNS];
    const adh_sweep_axis *t = shared_turns(c, &at);
    size_t n = adh_sweep_drive_runs(c, u, runs);
    if (!t) {
        adh_config_sweep_run(c, runs[0], run);
        return;
    }
    /* the member with the deepest turn, then every member's turn: the
     * grid and the profiles spread over the path are the deepest's; of
     * springs the softest, whose automatic start lies outside every
     * member's snap-in */
    size_t deepest = 0, idx[ADH_SWEEP_MAX_AXES];
    double turns[ADH_MAX_TURNS];
    for (size_t j = 0; j < n; j++) {
        adh_sweep_index(&c->sweep, runs[j], idx);
        turns[j] = adh_sweep_value(t, idx[at], NULL, 0);
        if (turns[j] < turns[deepest])
            deepest = j;
    }
    adh_config tc;
    tc.spec = c->spec;
    tc.output.plots = c->output.plots;
    apply(&c->sweep, c->spec.proto.nturns, runs[deepest], &tc);
    if (!strcmp(t->key, "protocol.turns")) {
        memcpy(tc.spec.proto.turns, turns, n * sizeof *turns);
        tc.spec.proto.nturns = n;
    }
    if (adh_sweep_touches(&c->sweep, "grid.")) {
        char why[512];
        adh_config_choose_grid(&tc.spec, NULL, why, sizeof why, NULL);
    }
    *run = tc.spec;
    run->proto = adh_config_protocol_for(&tc, tc.spec.mode);
}

adh_sweep_plot adh_sweep_plot_kind(const adh_sweep *s)
{
    if (s->plot != ADH_SWEEP_PLOT_AUTO)
        return s->naxes ? s->plot : ADH_SWEEP_PLOT_NONE;
    return s->naxes >= 2 ? ADH_SWEEP_PLOT_MAP : ADH_SWEEP_PLOT_NONE;
}

int adh_sweep_fig7_panel(const adh_config *c)
{
    const adh_sweep *s = &c->sweep;
    return s->naxes == 1 && !strcmp(s->axis[0].key, "solver.eps") && c->spec.mode == ADH_MODE_RELAX &&
           adh_sweep_plot_kind(s) == ADH_SWEEP_PLOT_FORCE;
}
