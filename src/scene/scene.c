#include "scene/scene.h"
#include "scene/datadir.h"
#include "scene/text.h"

#include <errno.h>
#include <ini.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>


typedef struct scene_parse {
    adh_config *cfg;
    const char *file;
    char why[512];
    int line;                    /* line of the first error, from inih */
    int unload_given;            /* an explicit unload = wins over the one turns implies */
    int kernel_given, grid_given; /* in this scene: together they must fit (adh_config_kernel_fits) */
    char seen[128][64];          /* "section.key" already given: duplicates are errors */
    size_t nseen;
    int keyline[256];            /* the lines inih hands the handler, in order (prescan's) */
    size_t nkeyline, ncall;      /* how many; the handler's calls so far */
} scene_parse;

__attribute__((format(printf, 2, 3))) static int fail(scene_parse *sp, const char *fmt, ...)
{
    /* inih goes on after an error and reports the first line: keep its message. */
    if (!sp->why[0]) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(sp->why, sizeof sp->why, fmt, ap);
        va_end(ap);
    }
    return 0; /* inih: 0 = error at this line */
}

/* Whether name is a section some key a scene may hold is in. */
static int known_section(const char *name)
{
    const adh_config_key *k;
    size_t len = strlen(name);
    for (size_t i = 0; (k = adh_config_key_at(i)); i++)
        if ((k->where & ADH_KEY_SCENE) && strncmp(k->key, name, len) == 0 && k->key[len] == '.')
            return 1;
    return 0;
}

/* A scene that gives both the kernel and the grid must not pair the
 * paper's kernel with graded rings (as the flags must not); refused at the
 * later of the two keys. */
static int kernel_fits(scene_parse *sp, const char *name, const char *value)
{
    const adh_grid_spec *g = &sp->cfg->spec.grid.asked;
    if (!sp->kernel_given || !sp->grid_given || adh_config_kernel_fits(g->kernel, g->graded))
        return 1;
    return fail(sp, !strcmp(name, "kernel") ? "%s: '%s' is not allowed with grid = graded: the paper's kernel "
                "assumes equal cells; use kernel = ring" : "%s: '%s' is not allowed with kernel = paper: the "
                "paper's kernel assumes equal cells; use kernel = ring", name, value);
}

/* The configuration's words in a scene's: a key is the name under its
 * section ("kernel", "kernel = ring"). */
static void say_key(const char *key, const char *value, char *buf, size_t len, void *ctx)
{
    const char *dot = strchr(key, '.');
    snprintf(buf, len, "%s%s%s", dot ? dot + 1 : key, value ? " = " : "", value ? value : "");
}

/* adh_config_reword with say_key, as an adh_config_words */
static void key_words(const char *in, void *ctx, char *out, size_t len)
{
    adh_config_reword(in, say_key, ctx, out, len);
}

/* [sweep] E after [sweep] material.E (or sigma after material.sigma):
 * one key under two spellings, the second's values would silently replace
 * the first's. 0, or the failure reported. */
static int swept_twice(scene_parse *sp, const char *section, const char *name)
{
    char mine[64], theirs[64];
    if (strcmp(section, "sweep") != 0 || adh_sweep_key_of(name, mine, sizeof mine) != 0)
        return 0;
    for (size_t i = 0; i < sp->nseen; i++)
        if (!strncmp(sp->seen[i], "sweep.", 6) && adh_sweep_key_of(sp->seen[i] + 6, theirs, sizeof theirs) == 0 &&
            !strcmp(mine, theirs)) {
            char msg[300];
            snprintf(msg, sizeof msg, "%s swept twice in [sweep], as '%s' and as '%s': give its values once", mine,
                     sp->seen[i] + 6, name);
            fail(sp, "%s", msg);
            return -1;
        }
    return 0;
}

/* Each key = value through adh_config_set, as the flags and the TUI set
 * them; the scene adds what is about a file: sections, duplicates, an
 * explicit unload over the one turns imply, kernel and grid given together. */
static int handler(void *user, const char *section, const char *name, const char *value)
{
    scene_parse *sp = user;
    adh_config *c = sp->cfg;
    /* inih (built without INI_HANDLER_LINENO) does not say the line: the
     * prescan counted the key lines, the handler is called once for each */
    int line = sp->ncall < sp->nkeyline ? sp->keyline[sp->ncall] : -1;
    sp->ncall++;
    if (!known_section(section))
        return fail(sp, "unknown section [%s]: sections are scene, material, grid, solver, protocol, output, sweep", section);
    char full[64], msg[400];
    snprintf(full, sizeof full, "%s.%s", section, name);
    const adh_config_key *k = adh_config_key_find(full);
    if (!k || !(k->where & ADH_KEY_SCENE)) {
        const adh_config_key *near = adh_config_key_suggest(section, name);
        if (!near)
            return fail(sp, "unknown key '%s' in [%s] (see adhere-scene(5))", name, section);
        char sec[32];   /* the key's section: a table's name, short */
        const char *dot = strchr(near->key, '.');
        size_t sl = (size_t)(dot - near->key) < sizeof sec ? (size_t)(dot - near->key) : sizeof sec - 1;
        memcpy(sec, near->key, sl);
        sec[sl] = '\0';
        if (strcmp(sec, section) == 0)
            return fail(sp, "unknown key '%s': did you mean '%s'? (see adhere-scene(5))", name, dot + 1);
        snprintf(msg, sizeof msg, "unknown key '%s' in [%s]: did you mean '%s' in [%s]? (see adhere-scene(5))", name,
                 section, dot + 1, sec);
        return fail(sp, "%s", msg);
    }
    for (size_t i = 0; i < sp->nseen; i++)
        if (strcmp(sp->seen[i], full) == 0)
            return fail(sp, "key '%s' given twice in [%s]", name, section);
    if (swept_twice(sp, section, name) != 0)
        return 0;
    if (sp->nseen < sizeof sp->seen / sizeof sp->seen[0])
        snprintf(sp->seen[sp->nseen++], sizeof sp->seen[0], "%s", full);

    int unload = c->spec.proto.unload;
    if (adh_config_set(c, full, value, msg, sizeof msg) != 0) {
        char words[700], setting[300];
        /* "nodes = 5 is not allowed", not "nodes: N = 5 nodes is ..." */
        snprintf(setting, sizeof setting, "%s = %s", name, value);
        adh_config_refusal(full, setting, name, msg, key_words, NULL, words, sizeof words);
        /* '#' comments a line only at its start: "E = 1GPa # stiff" read
         * 'GPa # stiff' as the unit */
        const char *hash = strstr(value, " #");
        return fail(sp, "%s%s", words, hash ? " (a comment after a value starts with ' ;', not '#')" : "");
    }
    adh_config_note_given(c, full, value, sp->file);
    adh_config_note_origin(c, full, line);
    if (!strcmp(full, "protocol.turns") && sp->unload_given)
        c->spec.proto.unload = unload;
    sp->unload_given |= !strcmp(full, "protocol.unload");
    if (!strcmp(full, "grid.kernel") || !strcmp(full, "grid.grid")) {
        sp->kernel_given |= !strcmp(name, "kernel");
        sp->grid_given |= !strcmp(name, "grid");
        return kernel_fits(sp, name, value);
    }
    return 1;
}

static void finish_error(scene_parse *sp, int rc, char *why, size_t whylen)
{
    if (rc > 0 && !sp->why[0])
        snprintf(sp->why, sizeof sp->why, "syntax error (expected [section] or key = value)");
    snprintf(why, whylen, "%s:%d: %s", sp->file, rc, sp->why);
}

/* A control byte other than a tab on a line (an escape sequence): the
 * refusals quote values and keys, and it would reach the terminal (a
 * title's was refused alone). Named with the key when it is in the value. */
static int control_byte(const char *buf, scene_parse *sp)
{
    const char *p = buf;
    while (*p && ((unsigned char)*p >= 0x20 || *p == '\t') && *p != 0x7f)
        p++;
    const char *eq = strpbrk(buf, "=:"), *k = buf;
    while (*k == ' ' || *k == '\t')
        k++;
    /* Latin-1 text, or a C1 control (0x9b, CSI to some terminals), was
     * quoted as it was in a value's refusal; a comment line may keep it */
    const char *bad = *k == '#' || *k == ';' ? NULL : adh_text_not_utf8(buf);
    if (bad && bad < p)
        p = bad;
    if (!*p)
        return 0;
    char key[64] = "", msg[300];
    if (eq && eq < p && *k != '[' && *k != '#' && *k != ';') {   /* the key is text: name it */
        size_t kl = (size_t)(eq - k);
        while (kl && (k[kl - 1] == ' ' || k[kl - 1] == '\t'))
            kl--;
        snprintf(key, sizeof key, "%.*s: ", (int)(kl < 40 ? kl : 40), k);
    }
    if (p == bad)
        snprintf(msg, sizeof msg, "%sthe byte 0x%02x is not UTF-8 text: save the scene as UTF-8 (a Latin-1 byte, or a "
                 "control to some terminals, would reach the terminal in a message)", key, (unsigned char)*p);
    else
        snprintf(msg, sizeof msg, "%sthe control character 0x%02x is not allowed: a scene is printable text (an escape "
                 "sequence would reach the terminal in a message)", key, (unsigned char)*p);
    fail(sp, "%s", msg);
    return 1;
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
            fail(sp, "a carriage return without a line feed (old Mac line ends): save the file with Unix (LF) or DOS (CRLF) line ends");
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
            /* a binary file is one long line: its control byte named, not
             * the length (as a short line's is) */
            size_t c = 0;
            while (c < len && ((unsigned char)p[c] >= 0x20 || p[c] == '\t' || p[c] == '\r') && p[c] != 0x7f)
                c++;
            if (c < len) {
                char msg[200];
                snprintf(msg, sizeof msg, "the control character 0x%02x is not allowed: a scene is printable text (an "
                         "escape sequence would reach the terminal in a message)", (unsigned char)p[c]);
                fail(sp, "%s", msg);
                return line;
            }
            fail(sp, "line longer than 198 characters");
            return line;
        }
        memcpy(buf, p, len);
        buf[len] = '\0';
        p = eol ? eol + 1 : p + len; /* before the \r is dropped: a last line
                                        "x\r" must still move p to its end */
        if (len && buf[len - 1] == '\r')
            buf[--len] = '\0';
        if (control_byte(buf, sp))
            return line;
        const char *t = buf;
        if (line == 1 && (unsigned char)t[0] == 0xEF && (unsigned char)t[1] == 0xBB && (unsigned char)t[2] == 0xBF)
            t += 3; /* a UTF-8 byte order mark */
        int indented = *t == ' ' || *t == '\t';
        while (*t == ' ' || *t == '\t')
            t++;
        if (!*t || *t == '#' || *t == ';')
            continue;
        if (indented) {
            fail(sp, "indented line: write each key = value at the start of its own line");
            return line;
        }
        if (*t == '[') {
            const char *close = strchr(t, ']');
            if (!close) {
                fail(sp, "syntax error: section header without ']'");
                return line;
            }
            char name[64];
            size_t nl = (size_t)(close - t - 1) < sizeof name - 1 ? (size_t)(close - t - 1) : sizeof name - 1;
            memcpy(name, t + 1, nl);   /* a longer name is no known section either way */
            name[nl] = '\0';
            if (!known_section(name)) {
                fail(sp, "unknown section [%s]: sections are scene, material, grid, solver, protocol, output, sweep", name);
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
            fail(sp, "'%.200s' comes before any [section]", t);
            return line;
        }
        /* a line with no '=' or ':' inih refuses, with no call */
        if (strpbrk(t, "=:") && sp->nkeyline < sizeof sp->keyline / sizeof sp->keyline[0])
            sp->keyline[sp->nkeyline++] = line;
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
             "sets where); shipped scenes are default, fig1 ... fig8, visco, visco-speed and afm", arg,
             tried[0] ? root[0] : "", tried[0] ? "/scenes, " : "", tried[1] ? root[1] : "",
             tried[1] ? "/scenes, " : "", root[2]);
    return -1;
}

int adh_scene_read(const char *arg, char *path, size_t pathlen, char **text_out, char *why, size_t whylen)
{
    *text_out = NULL;
    if (adh_scene_find(arg, path, pathlen, why, whylen) != 0)
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
    *text_out = text;
    return 0;
}

int adh_scene_load(const char *arg, adh_config *cfg, char *why, size_t whylen)
{
    char path[PATH_MAX], *text;
    if (adh_scene_read(arg, path, sizeof path, &text, why, whylen) != 0)
        return -1;
    int rc = adh_scene_parse_string(text, path, cfg, why, whylen);
    free(text);
    if (rc != 0)
        return -1;
    snprintf(cfg->scene, sizeof cfg->scene, "%s", path);
    return 0;
}
