#include "tui/keysrc.h"

#include <curses.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void tui_keysrc_terminal(tui_keysrc *ks)
{
    memset(ks, 0, sizeof *ks);
}

/* A replay script is a small text file; anything past this is a mistake
 * (a binary given as the script), not a long session. */
#define MAX_SCRIPT (4u << 20)

int tui_keysrc_replay(tui_keysrc *ks, const char *file, char *err, size_t errlen)
{
    memset(ks, 0, sizeof *ks);
    ks->replay = 1;
    ks->file = file;
    /* O_NONBLOCK: a FIFO with no writer must not hang the open; a script
     * is a regular file, and anything else is refused before reading. */
    int fd = open(file, O_RDONLY | O_NONBLOCK);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: cannot read the replay script: %s", file,
                 fd < 0 ? strerror(errno) : "not a regular file (a script is a text file)");
        if (fd >= 0)
            close(fd);
        return -1;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read the replay script: %s", file, strerror(errno));
        close(fd);
        return -1;
    }
    char *text = malloc(MAX_SCRIPT + 1);
    size_t len = text ? fread(text, 1, MAX_SCRIPT + 1, f) : 0;
    int bad = text == NULL || ferror(f);
    fclose(f);
    if (bad || len > MAX_SCRIPT) {
        snprintf(err, errlen, "%s: %s", file, bad ? "cannot read the replay script"
                 : "the replay script is longer than 4 MiB; is it really a script?");
        free(text);
        return -1;
    }
    int line;
    char msg[512];
    int rc = tui_replay_parse(text, len, &ks->script, &line, msg, sizeof msg);
    free(text);
    if (rc != 0) {
        snprintf(err, errlen, "%s:%d: %s", file, line, msg);
        return -1;
    }
    return 0;
}

void tui_keysrc_free(tui_keysrc *ks)
{
    tui_replay_free(&ks->script);
}

/* Terminals disagree on Enter and Backspace; the rest of the TUI sees the
 * replay codes only. */
static int normalize(int c)
{
    switch (c) {
    case '\r': case KEY_ENTER: return '\n';
    case 127: case 8: return KEY_BACKSPACE;
    default: return c;
    }
}

int tui_keysrc_next(tui_keysrc *ks, int wait_ms, tui_replay_item *out)
{
    if (ks->replay) {
        if (ks->pos >= ks->script.n)
            return KEYSRC_END;
        *out = ks->script.items[ks->pos++];
        return KEYSRC_ITEM;
    }
    timeout(wait_ms);
    int c = getch();
    if (c == ERR)
        return KEYSRC_NONE;
    memset(out, 0, sizeof *out);
    out->kind = TUI_REPLAY_KEY;
    out->key = normalize(c);
    return KEYSRC_ITEM;
}
