/* A core refusal that opens with a setting's quantity and value, opened
 * with the setting's key: the core names quantities ("start = 400 pm is
 * not allowed", "E (modulus) = 0 Pa is out of range") and never a flag,
 * while a driver names the setting as its user gave it (the flag, or the
 * scene's key and line): the key is what adh_config_reword turns into
 * those words. One table for every such opening of the core's checks. */
#include "scene/config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/status.h"
#include "adhere/units.h"

/* The core's opening (its words before the value), the key whose value
 * it names, the key that sets the same value under another name (E and
 * E0), and the words after the value that are not the key's ("5 nodes").
 * Of two openings that begin alike the longer comes first; of one opening
 * on two keys (a dwell in iterations or in seconds) the value says which. */
static const struct {
    const char *head, *key, *alt, *tail;
} openings[] = {
    /* adh_material_validate */
    { "E (modulus) = ", "material.E", "material.E0", "" },
    { "A (Hamaker constant) = ", "material.A", NULL, "" },
    { "z0 (equilibrium separation) = ", "material.z0", NULL, "" },
    { "R (effective radius) = ", "material.R", NULL, "" },
    /* adh_protocol_check, adh_protocol_dwell_check, adh_visco_start_check */
    { "R = ", "material.R", NULL, "" },
    { "start = ", "protocol.start", NULL, "" },
    { "step d = ", "protocol.step", NULL, "" },
    { "dwell = ", "protocol.dwell", NULL, " iterations" },
    { "grid spacing ", "grid.spacing", NULL, "" },
    { "grid radius Rmax = ", "grid.radius", NULL, "" },
    /* adh_grid_nodes_check, adh_drive_check's grid and eps */
    { "N = ", "grid.nodes", NULL, " nodes" },
    { "spacing = ", "grid.spacing", NULL, "" },
    { "eps = ", "solver.eps", NULL, "" },
    /* adh_relax_settings_validate, adh_relax_max_iter_check */
    { "momentum = ", "solver.momentum", NULL, "" },
    { "max-iter = ", "solver.max_iter", NULL, "" },
    /* adh_rings_spec_validate, adh_rings_check */
    { "fine band radius ", "grid.fine_band", NULL, "" },
    { "ring growth ratio ", "grid.growth", NULL, "" },
    { "grid radius ", "grid.radius", NULL, "" },
    { "fine ring width ", "grid.spacing", NULL, "" },
    /* adh_sls_validate, adh_visco_drive_validate */
    { "E0 = ", "material.E0", "material.E", "" },
    { "Einf = ", "material.Einf", NULL, "" },
    { "tau = ", "material.tau", NULL, "" },
    { "spring k = ", "protocol.spring", NULL, "" },
    { "dwell = ", "protocol.dwell_time", NULL, "" },
    /* adh_visco_settings_validate */
    { "time tolerance = ", "solver.time_tol", NULL, "" },
};
#define NOPENINGS (sizeof openings / sizeof openings[0])

/* The value text as typed, the space between number and unit taken out
 * ("400 pm" -> "400pm", as adh_qtext_arg writes it). */
static void typed(const char *v, size_t n, char *out, size_t len)
{
    size_t o = 0;
    for (size_t i = 0; i < n && o + 1 < len; i++)
        if (v[i] != ' ')
            out[o++] = v[i];
    out[o] = '\0';
}

/* Whether text (the sentence's value, as typed) is key's value in run:
 * the sentence's four digits against the key's own value, so a value the
 * core derived from others (a uniform grid's radius, N x spacing) is not
 * put down to a key that holds another. */
static int holds(const adh_config *c, const adh_run_spec *run, const char *key, const char *text)
{
    const adh_config_key *k = adh_config_key_find(key);
    adh_config *copy = k ? malloc(sizeof *copy) : NULL;
    if (!copy)
        return 0;
    *copy = *c;
    copy->spec = *run;   /* a run's keys are its spec's (ADH_KEY_RUN) */
    char own[256], *end;
    int got = adh_config_get(copy, key, own, sizeof own);
    free(copy);
    double want = strtod(own, &end), said;
    if (got != 0 || end == own || !isfinite(want))
        return 0;   /* auto, none: not the value named */
    if (k->q == ADH_Q_NONE) {
        said = strtod(text, &end);
        if (end == text || *end)
            return 0;
    } else if (adh_parse_quantity(text, k->q, &said, NULL, 0) != ADH_SUCCESS) {
        return 0;
    }
    return fabs(said - want) <= 1e-3 * fmax(fabs(said), fabs(want));
}

const char *adh_config_key_opening(const adh_config *c, const adh_run_spec *run, const char *in, char *out,
                                   size_t len)
{
    for (size_t i = 0; i < NOPENINGS; i++) {
        size_t h = strlen(openings[i].head), t = strlen(openings[i].tail);
        const char *v = in + h, *is = strncmp(in, openings[i].head, h) == 0 ? strstr(v, " is ") : NULL;
        if (!is || (size_t)(is - v) <= t || strncmp(is - t, openings[i].tail, t) != 0)
            continue;
        const char *key = openings[i].alt ? adh_config_origin_last(c, openings[i].key, openings[i].alt)
                                          : openings[i].key;
        char text[128];
        typed(v, (size_t)(is - v) - t, text, sizeof text);
        /* nobody set it: the core's quantity is no setting the user gave */
        if (adh_config_origin(c, key) == -2 || !holds(c, run, key, text))
            continue;
        snprintf(out, len, "%s = %s%s", key, text, is);
        return key;
    }
    snprintf(out, len, "%s", in);
    return NULL;
}

/* The words after the value of a refusal that opens with key's quantity
 * and value ("N = 5 nodes is not allowed: ...": " is not allowed: ..."),
 * NULL when it opens otherwise. */
static const char *opening_after(const char *key, const char *in)
{
    for (size_t i = 0; i < NOPENINGS; i++) {
        size_t h = strlen(openings[i].head), t = strlen(openings[i].tail);
        const char *v = in + h, *is = strncmp(in, openings[i].head, h) == 0 ? strstr(v, " is ") : NULL;
        int named = !strcmp(key, openings[i].key) || (openings[i].alt && !strcmp(key, openings[i].alt));
        if (named && is && (size_t)(is - v) > t && strncmp(is - t, openings[i].tail, t) == 0)
            return is;
    }
    return NULL;
}

void adh_config_refusal(const char *key, const char *setting, const char *name, const char *msg,
                        adh_config_words words, void *ctx, char *out, size_t len)
{
    char w[1024];
    const char *after = opening_after(key, msg);
    words(after ? after : msg, ctx, w, sizeof w);
    snprintf(out, len, after ? "%s%s" : "%s: %s", after ? setting : name, w);
}
