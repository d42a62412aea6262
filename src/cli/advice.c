#include "cli/advice.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "adhere/status.h"

/* In the order a sentence names them: the flag, and the key a scene sets. */
static const struct {
    unsigned bit;
    const char *flag;
    const char *key;
} keys[] = {
    { ADH_FIX_MODE, "--mode", "scene.mode" },
    { ADH_FIX_FINE_BAND, "--fine-band", "grid.fine_band" },
    { ADH_FIX_TURNS, "--turn", "protocol.turns" },
    { ADH_FIX_RADIUS, "-R", "material.R" },
    { ADH_FIX_STEP, "-d", "protocol.step" },
    { ADH_FIX_START, "--start", "protocol.start" },
    { ADH_FIX_NODES, "-N", "grid.nodes" },
    { ADH_FIX_SPACING, "--spacing", "grid.spacing" },
    { ADH_FIX_GRID_RADIUS, "--grid-radius", "grid.radius" },
    { ADH_FIX_FORCE, "--force", "grid.force" },
};
#define NFLAGS (sizeof keys / sizeof keys[0])

/* Appends text to list (of len, holding *n bytes), cut at its end. */
static void add(char *list, size_t len, size_t *n, const char *sep, const char *text)
{
    if (*n + 1 < len) {
        int w = snprintf(list + *n, len - *n, "%s%s", *n ? sep : "", text);
        *n += w < 0 ? 0 : (size_t)w < len - *n ? (size_t)w : len - *n - 1;
    }
}

static int from_scene(int origin)
{
    return origin == -1 || origin > 0;
}

/* Whether the keys of bits that were set were set by the scene alone
 * (some were, no flag did); when none was, placed: whether the sentence
 * the list follows placed a key in the scene (spacing = 2m (a.scene:3)). */
static int scene_voice(const adh_config *cfg, unsigned bits, int placed)
{
    int scene = 0, flag = 0;
    for (size_t i = 0; cfg && i < NFLAGS; i++)
        if (bits & keys[i].bit) {
            int from = adh_config_origin(cfg, keys[i].key);
            scene |= from_scene(from);
            flag |= from == 0;
        }
    return scene ? !flag : !flag && placed;
}

/* The i-th key as the scene says it (its name in its section), when the
 * scene set it, or nobody did and voice is the scene's; NULL: the flag. */
static const char *scene_word(const adh_config *cfg, size_t i, int voice, int *origin)
{
    *origin = cfg ? adh_config_origin(cfg, keys[i].key) : -2;
    const adh_config_key *k = adh_config_key_find(keys[i].key);
    if (!k || !(k->where & ADH_KEY_SCENE) || !(from_scene(*origin) || (*origin == -2 && voice)))
        return NULL;
    return strchr(keys[i].key, '.') + 1;
}

/* The i-th key as a flag, with value (NULL: none): "-R=500nm", or a run's
 * value of a sweep the line gave ("--sweep=R=500nm"; "--sweep=R"). */
static void flag_word(const adh_config *cfg, size_t i, const char *value, char *buf, size_t len)
{
    const char *swept = cfg && adh_config_origin(cfg, keys[i].key) == 0 ? adh_config_swept_as(cfg, keys[i].key) : NULL;
    if (swept)
        snprintf(buf, len, "--sweep=%s%s%s", swept, value ? "=" : "", value ? value : "");
    else
        snprintf(buf, len, "%s%s%s", keys[i].flag, value ? "=" : "", value ? value : "");
}

void cli_advice_key(const adh_config *cfg, unsigned voice_bits, unsigned bit, const char *value, char *buf, size_t len)
{
    size_t i = 0;
    while (i < NFLAGS && keys[i].bit != bit)
        i++;
    if (i == NFLAGS) {
        snprintf(buf, len, "%s", value ? value : "");
        return;
    }
    int origin;
    const char *word = scene_word(cfg, i, scene_voice(cfg, voice_bits, 0), &origin);
    if (!word) {
        flag_word(cfg, i, value, buf, len);
        return;
    }
    int n = snprintf(buf, len, "%s%s%s", word, value ? " = " : "", value ? value : "");
    if (n >= 0 && (size_t)n < len && from_scene(origin) && cfg->scene[0]) {
        if (origin > 0)
            snprintf(buf + n, len - (size_t)n, " (%.1000s:%d)", cfg->scene, origin);
        else
            snprintf(buf + n, len - (size_t)n, " (%.1000s)", cfg->scene);
    }
}

/* Whether sentence names where the scene's line (0: the scene itself) is,
 * as cli_options_words writes it: "(a.scene:6)", "(line 6)", "(a.scene)". */
static int names_place(const char *sentence, const char *scene, int line)
{
    char place[PATH_MAX + 32];
    if (line > 0) {
        snprintf(place, sizeof place, "(line %d)", line);
        if (strstr(sentence, place))
            return 1;
        snprintf(place, sizeof place, "(%s:%d)", scene, line);
    } else {
        snprintf(place, sizeof place, "(%s)", scene);
    }
    return strstr(sentence, place) != NULL;
}

/* Whether sentence names the scene's file, at any line. */
static int names_file(const char *sentence, const char *scene)
{
    char place[PATH_MAX + 8];
    snprintf(place, sizeof place, "(%s:", scene);
    return strstr(sentence, place) != NULL || names_place(sentence, scene, 0);
}

/* The list's word for the i-th key after sentence: the flag, or the
 * scene's key with where it was written ("nodes at a.scene:3", "spacing
 * at line 4"), or its name alone where the sentence says where ("start",
 * after "start = 400pm (a.scene:6)": a scene's key is one a line). */
static void list_word(const adh_config *cfg, size_t i, int voice, const char *sentence, int *file_named, char *buf,
                      size_t len)
{
    int origin;
    const char *word = scene_word(cfg, i, voice, &origin);
    if (!word)
        flag_word(cfg, i, NULL, buf, len);
    else if (!from_scene(origin) || !cfg->scene[0] || names_place(sentence, cfg->scene, origin > 0 ? origin : 0))
        snprintf(buf, len, "%s", word);
    else if (origin > 0 && *file_named)
        snprintf(buf, len, "%s at line %d", word, origin);
    else if (origin > 0)
        snprintf(buf, len, "%s at %.1000s:%d", word, cfg->scene, origin);
    else
        snprintf(buf, len, "%s in %.1000s", word, cfg->scene);
    *file_named |= word && from_scene(origin) && cfg->scene[0];
}

void cli_advice_append_cfg(const adh_config *cfg, cli_advice_for who, char *why, size_t whylen, unsigned fix)
{
    char list[1200] = "", word[1100];
    size_t n = 0;
    /* a fit sets its one turn itself, below the data: --turn would be
     * overwritten, and is no advice */
    unsigned turn = who == CLI_ADVICE_FIT ? fix & ADH_FIX_TURNS : 0;
    /* --cost's N is each of --cost-nodes (-N is refused beside it) */
    unsigned nodes = who == CLI_ADVICE_COST ? fix & ADH_FIX_NODES : 0;
    int file_named = cfg && cfg->scene[0] && names_file(why, cfg->scene);
    int voice = scene_voice(cfg, fix & ~turn & ~nodes, file_named);
    for (size_t i = 0; i < NFLAGS; i++)
        if ((fix & ~turn) & keys[i].bit) {
            if (keys[i].bit & nodes)
                snprintf(word, sizeof word, "--cost-nodes");
            else
                list_word(cfg, i, voice, why, &file_named, word, sizeof word);
            add(list, sizeof list, &n, ", ", word);
        }
    if (turn)
        add(list, sizeof list, &n, "; ", "the turn is the fit's, a step below the deepest position in --data");
    size_t len = strlen(why);
    if (n && len + n + 4 <= whylen)
        snprintf(why + len, whylen - len, " (%s)", list);
}
