#include "tui/replay.h"

#include <curses.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const struct { const char *name; int key; } special[] = {
    { "Left", KEY_LEFT }, { "Right", KEY_RIGHT }, { "Up", KEY_UP }, { "Down", KEY_DOWN },
    { "Enter", '\n' }, { "Esc", 27 }, { "Space", ' ' }, { "Tab", '\t' },
    { "PgUp", KEY_PPAGE }, { "PgDn", KEY_NPAGE }, { "Home", KEY_HOME }, { "End", KEY_END },
    { "BS", KEY_BACKSPACE }, { "Del", KEY_DC }, { "lt", '<' },
};
#define NSPECIAL (sizeof special / sizeof special[0])

int tui_replay_key_code(const char *name)
{
    for (size_t i = 0; i < NSPECIAL; i++)
        if (strcasecmp(name, special[i].name) == 0)
            return special[i].key;
    if ((name[0] == 'F' || name[0] == 'f') && name[1] >= '1' && name[1] <= '9') {
        int n = name[1] - '0';
        if (name[2] >= '0' && name[2] <= '9' && name[3] == '\0')
            n = 10 * n + (name[2] - '0');
        else if (name[2] != '\0')
            return -1;
        return n >= 1 && n <= 12 ? KEY_F(n) : -1;
    }
    /* C-a .. C-z: the control codes 1..26 a terminal sends. */
    if ((name[0] == 'C' || name[0] == 'c') && name[1] == '-' && name[2] != '\0' && name[3] == '\0') {
        int c = name[2] | 0x20;
        return c >= 'a' && c <= 'z' ? c & 0x1f : -1;
    }
    return -1;
}

void tui_replay_key_name(int key, char *buf, size_t len)
{
    for (size_t i = 0; i < NSPECIAL; i++)
        if (special[i].key == key && key != '<') {
            snprintf(buf, len, "<%s>", special[i].name);
            return;
        }
    if (key >= KEY_F(1) && key <= KEY_F(12))
        snprintf(buf, len, "<F%d>", key - KEY_F(0));
    else if (key >= 1 && key <= 26)
        snprintf(buf, len, "<C-%c>", 'a' + key - 1);
    else if (key > ' ' && key < 127)
        snprintf(buf, len, "%c", key);
    else
        snprintf(buf, len, "<key %d>", key);
}

static int push(tui_replay_script *s, const tui_replay_item *it)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 64;
        tui_replay_item *p = realloc(s->items, cap * sizeof *p);
        if (!p)
            return -1;
        s->items = p;
        s->cap = cap;
    }
    s->items[s->n++] = *it;
    return 0;
}

void tui_replay_free(tui_replay_script *s)
{
    for (size_t i = 0; i < s->n; i++) {
        free(s->items[i].name);
        free(s->items[i].value);
    }
    free(s->items);
    memset(s, 0, sizeof *s);
}

/* The words of one line, split at blanks, a word starting with '#' ending
 * the line. w has room for every word: a line of L bytes has at most L/2 + 1. */
typedef struct line_words {
    char **w;
    size_t n;
} line_words;

static void split(char *line, line_words *lw)
{
    lw->n = 0;
    for (char *p = line;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' || *p == '\v')
            p++;
        if (*p == '\0' || *p == '#')
            return;
        lw->w[lw->n++] = p;
        while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\f' && *p != '\v')
            p++;
        if (*p)
            *p++ = '\0';
    }
}

static const char known_commands[] = ":set NAME VALUE, :dump FILE, :rows FILE, :wait, :resize COLSxROWS";

static int parse_size(const char *t, int *cols, int *rows)
{
    char extra;
    if (sscanf(t, "%dx%d%c", cols, rows, &extra) != 2)
        return -1;
    return *cols >= TUI_REPLAY_MIN_COLS && *cols <= TUI_REPLAY_MAX_COLS &&
           *rows >= TUI_REPLAY_MIN_ROWS && *rows <= TUI_REPLAY_MAX_ROWS ? 0 : -1;
}

static int command(tui_replay_script *s, const line_words *lw, size_t first, int line,
                   size_t *used, char *err, size_t errlen)
{
    const char *cmd = lw->w[first];
    size_t nargs = lw->n - first - 1;
    const char *const *arg = (const char *const *)&lw->w[first + 1];
    tui_replay_item it = { .line = line };
    size_t want;
    if (strcmp(cmd, ":set") == 0) {
        it.kind = TUI_REPLAY_SET;
        want = 2;
    } else if (strcmp(cmd, ":dump") == 0) {
        it.kind = TUI_REPLAY_DUMP;
        want = 1;
    } else if (strcmp(cmd, ":rows") == 0) {
        it.kind = TUI_REPLAY_ROWS;
        want = 1;
    } else if (strcmp(cmd, ":wait") == 0) {
        it.kind = TUI_REPLAY_WAIT;
        want = 0;
    } else if (strcmp(cmd, ":resize") == 0) {
        it.kind = TUI_REPLAY_RESIZE;
        want = 1;
    } else {
        snprintf(err, errlen, "unknown command '%s'; the commands are %s", cmd, known_commands);
        return -1;
    }
    /* NAME=VALUE (or NAME = VALUE) as a scene or a flag writes it, for
     * every name: ":set solver.time_tol=1e-3" was refused for its count */
    const char *eq = it.kind == TUI_REPLAY_SET && nargs == 1 ? strchr(arg[0], '=') : NULL;
    const char *value = nargs > 1 ? arg[1] : NULL;
    size_t namelen = nargs ? strlen(arg[0]) : 0;
    if (eq && eq != arg[0] && eq[1]) {
        namelen = (size_t)(eq - arg[0]);
        value = eq + 1;
        nargs = 2;
    } else if (it.kind == TUI_REPLAY_SET && nargs == 3 && strcmp(arg[1], "=") == 0) {
        value = arg[2];
        nargs = 2;
    }
    /* A command owns the rest of its line, so a value can never be taken
     * for keys: ":set E 1 GPa" is an error, not ":set E 1" then "GPa". */
    if (nargs != want) {
        snprintf(err, errlen, "'%s' takes %s, but %zu word%s follow%s%s", cmd,
                 want == 2 ? "NAME VALUE (the value without blanks, e.g. 1GPa)"
                 : want == 1 ? (it.kind == TUI_REPLAY_RESIZE ? "one size COLSxROWS" : "one FILE")
                 : "nothing", nargs, nargs == 1 ? "" : "s", nargs == 1 ? "s" : "",
                 nargs > want && want > 0 ? "; put keys on the next line" : "");
        return -1;
    }
    if (it.kind == TUI_REPLAY_RESIZE && parse_size(arg[0], &it.cols, &it.rows) != 0) {
        snprintf(err, errlen, ":resize '%s' is not allowed: use COLSxROWS with %d-%d columns and %d-%d rows",
                 arg[0], TUI_REPLAY_MIN_COLS, TUI_REPLAY_MAX_COLS, TUI_REPLAY_MIN_ROWS, TUI_REPLAY_MAX_ROWS);
        return -1;
    }
    if (it.kind == TUI_REPLAY_SET) {
        it.name = strndup(arg[0], namelen);
        it.value = strdup(value);
        if (!it.name || !it.value)
            goto nomem;
    } else if (it.kind == TUI_REPLAY_DUMP || it.kind == TUI_REPLAY_ROWS) {
        it.value = strdup(arg[0]);
        if (!it.value)
            goto nomem;
    }
    if (push(s, &it) != 0)
        goto nomem;
    *used = lw->n - first;
    return 0;
nomem:
    free(it.name);
    free(it.value);
    snprintf(err, errlen, "out of memory");
    return -1;
}

static int keys(tui_replay_script *s, const char *word, int line, char *err, size_t errlen)
{
    tui_replay_item it = { .kind = TUI_REPLAY_KEY, .line = line };
    if (strcmp(word, "<") == 0) {   /* a lone '<' can only mean the key */
        it.key = '<';
        return push(s, &it);
    }
    for (const char *p = word; *p;) {
        unsigned char c = (unsigned char)*p;
        if (c == '<') {
            const char *close = strchr(p, '>');
            char name[16];
            size_t nl = close ? (size_t)(close - p - 1) : 0;
            if (!close || nl == 0 || nl >= sizeof name) {
                snprintf(err, errlen, "'%s': '<' opens no key name; write <lt> for the key '<', "
                         "or a name such as <Enter>, <Left>, <F1>, <C-r>", word);
                return -1;
            }
            memcpy(name, p + 1, nl);
            name[nl] = '\0';
            it.key = tui_replay_key_code(name);
            if (it.key < 0) {
                snprintf(err, errlen, "unknown key <%s>; known: <Left> <Right> <Up> <Down> <Enter> "
                         "<Esc> <Space> <Tab> <PgUp> <PgDn> <Home> <End> <BS> <Del> <lt> <F1>..<F12> "
                         "<C-a>..<C-z>", name);
                return -1;
            }
            p = close + 1;
        } else if (c > ' ' && c < 127) {
            it.key = c;
            p++;
        } else {
            snprintf(err, errlen, "'%s' holds the byte 0x%02x, which is not a printable ASCII key "
                     "(write u for micro, <Space> for a blank)", word, c);
            return -1;
        }
        if (push(s, &it) != 0) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
    }
    return 0;
}

int tui_replay_parse(const char *text, size_t len, tui_replay_script *script,
                     int *errline, char *err, size_t errlen)
{
    memset(script, 0, sizeof *script);
    *errline = 0;
    if (memchr(text, '\0', len)) {
        const char *z = memchr(text, '\0', len);
        int line = 1;
        for (const char *p = text; p < z; p++)
            line += *p == '\n';
        *errline = line;
        snprintf(err, errlen, "a NUL byte: a replay script is text");
        return -1;
    }
    char *buf = malloc(len + 1);
    if (!buf) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(buf, text, len);
    buf[len] = '\0';
    line_words lw;
    lw.w = malloc((len / 2 + 2) * sizeof *lw.w);
    if (!lw.w) {
        free(buf);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int line = 0, rc = 0;
    for (char *p = buf, *next; p && *p && rc == 0; p = next) {
        line++;
        next = strchr(p, '\n');
        if (next)
            *next++ = '\0';
        split(p, &lw);
        for (size_t i = 0; i < lw.n && rc == 0;) {
            if (lw.w[i][0] == ':') {
                size_t used = 0;
                rc = command(script, &lw, i, line, &used, err, errlen);
                i += used;
            } else {
                rc = keys(script, lw.w[i], line, err, errlen);
                i++;
            }
        }
    }
    free(lw.w);
    free(buf);
    if (rc != 0) {
        *errline = line;
        tui_replay_free(script);
    }
    return rc;
}
