/* A bare number teaches: flags and scenes read one in SI, a screen shows
 * the same quantity in nm or GPa, and "-R 10" (10 m) is a slip for 10 um
 * far more often than a wish. The quantities given bare are remembered;
 * after a refusal each is tried in the units a screen shows it in, and the
 * ones that would run are named. */
#include "scene/config.h"
#include "scene/text.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

size_t adh_config_name_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 40 || lb > 40)
        return 99;
    size_t d[41][41];
    for (size_t i = 0; i <= la; i++)
        d[i][0] = i;
    for (size_t j = 0; j <= lb; j++)
        d[0][j] = j;
    for (size_t i = 1; i <= la; i++)
        for (size_t j = 1; j <= lb; j++) {
            size_t sub = d[i - 1][j - 1] + (tolower((unsigned char)a[i - 1]) != tolower((unsigned char)b[j - 1]));
            size_t del = d[i - 1][j] + 1, ins = d[i][j - 1] + 1;
            d[i][j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
            /* two letters swapped count as one slip: --trun is --turn, not --tau */
            if (i > 1 && j > 1 && tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 2]) &&
                tolower((unsigned char)a[i - 2]) == tolower((unsigned char)b[j - 1]) && d[i - 2][j - 2] + 1 < d[i][j])
                d[i][j] = d[i - 2][j - 2] + 1;
        }
    return d[la][lb];
}

/* How far a name may be from the one meant: a letter in a short name, two
 * in a longer one (a one-letter name must match but for case). */
static size_t near_enough(const char *name)
{
    size_t n = strlen(name);
    return n >= 4 ? 2 : n >= 2 ? 1 : 0;
}

const adh_config_key *adh_config_key_suggest(const char *section, const char *name)
{
    const adh_config_key *k, *best = NULL;
    size_t bd = near_enough(name) + 1, sl = strlen(section);
    for (size_t i = 0; (k = adh_config_key_at(i)); i++) {
        if (!(k->where & ADH_KEY_SCENE))
            continue;
        const char *dot = strchr(k->key, '.');
        int here = (size_t)(dot - k->key) == sl && strncmp(k->key, section, sl) == 0;
        /* in its own section a near name; elsewhere the same name */
        size_t d = adh_config_name_distance(name, dot + 1);
        if (!here && d > 0)
            continue;
        if (d < bd || (d == bd && here && best && strncmp(best->key, section, sl) != 0)) {
            bd = d;
            best = k;
        }
    }
    return best;
}

void adh_config_note_given(adh_config *c, const char *key, const char *text, const char *where)
{
    const adh_config_key *k = adh_config_key_find(key);
    size_t i = 0;
    while (i < c->ngiven && strcmp(c->given[i].key, key) != 0)
        i++;
    if (i < c->ngiven) {   /* given again: the last word counts */
        memmove(&c->given[i], &c->given[i + 1], (c->ngiven - i - 1) * sizeof c->given[0]);
        c->ngiven--;
    }
    if (!k || !k->units || !adh_quantity_is_bare(text) || strlen(text) >= sizeof c->given[0].text ||
        c->ngiven == ADH_MAX_GIVEN)
        return;
    adh_given *g = &c->given[c->ngiven++];
    snprintf(g->key, sizeof g->key, "%s", key);
    snprintf(g->text, sizeof g->text, "%s", text);
    snprintf(g->where, sizeof g->where, "%s", where);
}

/* text with unit after each element ("-5,-2" and "nm": "-5nm,-2nm"); its
 * values as given (in SI) into si, *n of them. 0, or -1 when it does not
 * fit. */
static int with_unit(const char *text, const char *unit, char *out, size_t len, double *si, size_t cap, size_t *n)
{
    size_t o = 0;
    *n = 0;
    for (const char *p = text; *p;) {
        size_t k = strcspn(p, ",");
        char *end;
        double v = strtod(p, &end);
        if (*n == cap)
            return -1;
        si[(*n)++] = v;
        while (k > 0 && (p[k - 1] == ' ' || p[k - 1] == '\t'))
            k--;
        int w = snprintf(out + o, len - o, "%s%.*s%s", o ? "," : "", (int)k, p, unit);
        if (w < 0 || (size_t)w >= len - o)
            return -1;
        o += (size_t)w;
        p += strcspn(p, ",");
        if (*p == ',')
            p++;
        while (*p == ' ' || *p == '\t')
            p++;
    }
    return 0;
}

/* "R = 10 m" ("turns = -5 m, -2 m"): the key's name and what it was read as. */
static void read_as(const adh_given *g, const adh_config_key *k, const double *si, size_t n, char *out, size_t len)
{
    const char *dot = strchr(g->key, '.');
    out[0] = '\0';
    adh_text_catf(out, len, "%s = ", dot ? dot + 1 : g->key);
    for (size_t i = 0; i < n; i++)
        adh_text_catf(out, len, "%s%s", i ? ", " : "", adh_qtext(si[i], k->q).s);
}

/* The units of g's key that make c run, as the one who gave it would write
 * them ("--radius=10um", "R = 10um"), joined by " or " into out. */
static int rescues(const adh_config *c, const adh_given *g, const adh_config_key *k,
                   int (*accept)(adh_config *, void *), void *ctx, adh_config *copy, char *out, size_t len)
{
    int found = 0;
    const char *dot = strchr(g->key, '.');
    int flag = g->where[0] == '-';
    out[0] = '\0';
    for (const char *u = k->units; *u;) {
        char unit[16], text[256], why[512];
        double si[ADH_MAX_TURNS > ADH_SWEEP_MAX_LIST ? ADH_MAX_TURNS : ADH_SWEEP_MAX_LIST];
        size_t n, ul = strcspn(u, " ");
        snprintf(unit, sizeof unit, "%.*s", (int)(ul < sizeof unit ? ul : sizeof unit - 1), u);
        u += ul;
        while (*u == ' ')
            u++;
        if (with_unit(g->text, unit, text, sizeof text, si, sizeof si / sizeof si[0], &n) != 0)
            continue;
        *copy = *c;
        if (adh_config_set(copy, g->key, text, why, sizeof why) != 0 || accept(copy, ctx) != 0)
            continue;
        adh_text_catf(out, len, "%s%s%s%s", found ? " or " : "", flag ? g->where : dot ? dot + 1 : g->key, flag ? "=" : " = ",
            text);
        found = 1;
    }
    return found;
}

int adh_config_unit_hint(const adh_config *c, int (*accept)(adh_config *copy, void *ctx), void *ctx, char *out,
                         size_t len)
{
    if (len)
        out[0] = '\0';
    adh_config *copy = malloc(sizeof *copy);
    if (!copy)
        return -1;
    int rc = 0;
    for (size_t i = 0; i < c->ngiven && !rc; i++) {
        const adh_given *g = &c->given[i];
        const adh_config_key *k = adh_config_key_find(g->key);
        char text[256], was[256], alt[600];
        double si[ADH_MAX_TURNS > ADH_SWEEP_MAX_LIST ? ADH_MAX_TURNS : ADH_SWEEP_MAX_LIST];
        size_t n;
        if (!k || !k->units || with_unit(g->text, "", text, sizeof text, si, sizeof si / sizeof si[0], &n) != 0)
            continue;
        int zero = 1;
        for (size_t j = 0; j < n; j++)
            zero &= si[j] == 0;
        if (zero || !rescues(c, g, k, accept, ctx, copy, alt, sizeof alt))
            continue;
        read_as(g, k, si, n, was, sizeof was);
        if (g->where[0] == '-')
            snprintf(out, len, "%s is out of range; did you mean %s?", was, alt);
        else
            snprintf(out, len, "%s is out of range; did you mean %s in %s?", was, alt, g->where);
        rc = 1;
    }
    free(copy);
    return rc;
}
