/* Who set each key, a flag or a scene's line: a refusal of the run is
 * about keys, and names them in the words the user wrote them in (the
 * flag, or the scene's key with its file and line). */
#include "scene/config.h"

#include <stdio.h>
#include <string.h>

void adh_config_note_origin(adh_config *c, const char *key, int line)
{
    size_t i = 0;
    while (i < c->norigin && strcmp(c->origin[i].key, key) != 0)
        i++;
    if (i == c->norigin) {
        /* a longer key is no key of the table: nothing to name it by */
        if (c->norigin == ADH_MAX_ORIGINS || strlen(key) >= sizeof c->origin[0].key)
            return;
        c->norigin++;
    } else {
        /* the table in the order the keys were last set: of two keys that
         * set one value (E and E0), the later is the one that holds */
        memmove(&c->origin[i], &c->origin[i + 1], (c->norigin - 1 - i) * sizeof c->origin[0]);
        i = c->norigin - 1;
    }
    snprintf(c->origin[i].key, sizeof c->origin[i].key, "%s", key);
    c->origin[i].line = line;
}

/* The origin table's entry of a sweep of key (sweep.NAME, NAME any of
 * the key's names), or -1. */
static long swept_at(const adh_config *c, const char *key)
{
    char swept[64];
    for (size_t i = 0; i < c->norigin; i++)
        if (!strncmp(c->origin[i].key, "sweep.", 6) && adh_sweep_key_of(c->origin[i].key + 6, swept, sizeof swept) == 0 &&
            !strcmp(swept, key))
            return (long)i;
    return -1;
}

/* Where key stands in the order of setting: a swept key after every other
 * (each run sets it last); -1 when nobody set it. */
static long rank(const adh_config *c, const char *key)
{
    long s = swept_at(c, key);
    if (s >= 0)
        return (long)c->norigin + s;
    for (size_t i = 0; i < c->norigin; i++)
        if (!strcmp(c->origin[i].key, key))
            return (long)i;
    return -1;
}

const char *adh_config_origin_last(const adh_config *c, const char *a, const char *b)
{
    return rank(c, b) > rank(c, a) ? b : a;
}

const char *adh_config_swept_as(const adh_config *c, const char *key)
{
    long s = swept_at(c, key);
    return s >= 0 ? c->origin[s].key + 6 : NULL;
}

int adh_config_origin(const adh_config *c, const char *key)
{
    /* each run of a study takes the swept key's values, over the key's
     * own setting (as rank orders them): a scene's 'E = 0.05GPa' beside
     * '[sweep] E = 1GPa, 2GPa' is not where a run's 1GPa was written */
    long s = swept_at(c, key);
    if (s >= 0)
        return c->origin[s].line;
    for (size_t i = 0; i < c->norigin; i++)
        if (!strcmp(c->origin[i].key, key))
            return c->origin[i].line;
    return -2;
}
