/* Where keys come from: the terminal, or a replay script read whole before
 * the screen opens (so a bad script fails before any terminal change). Both
 * give tui_replay_items; the terminal gives only keys. */
#ifndef ADH_TUI_KEYSRC_H
#define ADH_TUI_KEYSRC_H

#include <stddef.h>

#include "tui/replay.h"

typedef struct tui_keysrc {
    int replay;                 /* 1: items from the script */
    const char *file;           /* the script's name, for FILE:LINE messages */
    tui_replay_script script;
    size_t pos;
} tui_keysrc;

enum { KEYSRC_NONE = 0, KEYSRC_ITEM = 1, KEYSRC_END = -1 };

void tui_keysrc_terminal(tui_keysrc *ks);
/* Reads and parses the script. 0, or -1 with "FILE:LINE: what" or
 * "FILE: why" in err. */
int tui_keysrc_replay(tui_keysrc *ks, const char *file, char *err, size_t errlen);
void tui_keysrc_free(tui_keysrc *ks);

/* The next input. Terminal: waits up to wait_ms (-1: forever; curses must be
 * up) and returns KEYSRC_NONE when nothing came. Script: the next item, or
 * KEYSRC_END after the last. */
int tui_keysrc_next(tui_keysrc *ks, int wait_ms, tui_replay_item *out);

#endif
