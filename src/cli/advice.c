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
    { ADH_FIX_TIME_TOL, "--time-tol", "solver.time_tol" },
};
#define NFLAGS (sizeof keys / sizeof keys[0])
#define ELLIPSIS "\xe2\x80\xa6"   /* U+2026, where a name or a list is cut */

/* Appends text to list (of len, holding *n bytes), cut at its end; *n
 * counts what the whole would take, so a caller sees a list that did not fit. */
static void add(char *list, size_t len, size_t *n, const char *sep, const char *text)
{
    const char *s = *n ? sep : "";
    if (*n + 1 < len)
        snprintf(list + *n, len - *n, "%s%s", s, text);
    *n += strlen(s) + strlen(text);
}

void cli_advice_path(const char *path, size_t max, char *buf, size_t len)
{
    size_t n = strlen(path), ell = sizeof ELLIPSIS - 1;
    if (n <= max || max < ell + 2) {
        snprintf(buf, len, "%s", path);
        return;
    }
    /* the file's name at the end is what a reader looks for: a third before, the rest after */
    size_t head = (max - ell) / 3, tail = max - ell - head;
    while (head > 0 && ((unsigned char)path[head] & 0xC0) == 0x80)   /* not inside a UTF-8 character */
        head--;
    const char *end = path + n - tail;
    while (*end && ((unsigned char)*end & 0xC0) == 0x80)
        end++;
    size_t t = strlen(end);
    if (len > head + ell + t) {   /* buf holds max bytes and its end */
        memcpy(buf, path, head);
        memcpy(buf + head, ELLIPSIS, ell);
        memcpy(buf + head + ell, end, t + 1);
    } else if (len) {
        buf[0] = '\0';
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
    if (n >= 0 && (size_t)n + 32 < len && from_scene(origin) && cfg->scene[0]) {
        char place[PATH_MAX], line[32] = "";   /* the name whole, or cut in its middle to the room left */
        cli_advice_path(cfg->scene, len - (size_t)n - 32, place, sizeof place);
        if (origin > 0)
            snprintf(line, sizeof line, ":%d", origin);
        size_t p = strlen(place), l = strlen(line);
        memcpy(buf + n, " (", 2);
        memcpy(buf + n + 2, place, p);
        memcpy(buf + n + 2 + p, line, l);
        memcpy(buf + n + 2 + p + l, ")", 2);
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
 * after "start = 400pm (a.scene:6)": a scene's key is one a line). The
 * scene's name is cut in its middle to max bytes (cli_advice_path). */
static void list_word(const adh_config *cfg, size_t i, int voice, const char *sentence, size_t max, int *file_named,
                      char *buf, size_t len)
{
    int origin;
    const char *word = scene_word(cfg, i, voice, &origin);
    char place[PATH_MAX];
    if (word && cfg->scene[0])
        cli_advice_path(cfg->scene, max, place, sizeof place);
    if (!word)
        flag_word(cfg, i, NULL, buf, len);
    else if (!from_scene(origin) || !cfg->scene[0] || names_place(sentence, cfg->scene, origin > 0 ? origin : 0))
        snprintf(buf, len, "%s", word);
    else if (origin > 0 && *file_named)
        snprintf(buf, len, "%s at line %d", word, origin);
    else if (origin > 0)
        snprintf(buf, len, "%s at %s:%d", word, place, origin);
    else
        snprintf(buf, len, "%s in %s", word, place);
    *file_named |= word && from_scene(origin) && cfg->scene[0];
}

/* The list for fix after why into list (len), the scene's name cut to
 * max bytes; returns the length the whole list takes. */
static size_t advice_list(const adh_config *cfg, cli_advice_for who, const char *why, unsigned fix, size_t max,
                          char *list, size_t len)
{
    char word[PATH_MAX + 64];
    size_t n = 0;
    list[0] = '\0';
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
                list_word(cfg, i, voice, why, max, &file_named, word, sizeof word);
            add(list, len, &n, ", ", word);
        }
    if (turn)
        add(list, len, &n, "; ", "the turn is the fit's, a step below the deepest position in --data");
    return n;
}

void cli_advice_append_cfg(const adh_config *cfg, cli_advice_for who, char *why, size_t whylen, unsigned fix)
{
    char list[CLI_ADVICE_LEN];
    size_t len = strlen(why), max = PATH_MAX, ell = sizeof ELLIPSIS - 1;
    if (len + 4 + ell >= whylen)   /* no room for " (…)": the sentence itself was cut */
        return;
    size_t room = whylen - len - 4 < sizeof list - 1 ? whylen - len - 4 : sizeof list - 1;
    size_t n = advice_list(cfg, who, why, fix, max, list, sizeof list);
    /* too long for why: the scene's name cut in its middle, shorter until the list fits */
    while (n > room && max > 16 && cfg && cfg->scene[0]) {
        max = n - room < max - 16 ? max - (n - room) : 16;
        n = advice_list(cfg, who, why, fix, max, list, sizeof list);
    }
    if (!n)
        return;
    if (n > room) {   /* still too long: its end cut where it is seen, never dropped */
        size_t keep = room - ell;
        while (keep > 0 && ((unsigned char)list[keep] & 0xC0) == 0x80)
            keep--;
        snprintf(list + keep, sizeof list - keep, ELLIPSIS);
    }
    size_t k = strlen(list);   /* k + 4 <= whylen - len: room checked above */
    memcpy(why + len, " (", 2);
    memcpy(why + len + 2, list, k);
    memcpy(why + len + 2 + k, ")", 2);
}
