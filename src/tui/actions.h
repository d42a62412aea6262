/* The TUI's action table: every key, what it does, and the sentence the help
 * screen, --list-keys and the man page's KEYS section show for it. Key
 * handling looks keys up here, so a key cannot work without being listed. */
#ifndef ADH_TUI_ACTIONS_H
#define ADH_TUI_ACTIONS_H

#include <stdio.h>

typedef enum tui_action {
    ACT_NONE = 0,
    ACT_FORWARD,      /* approach by d */
    ACT_BACK,         /* retract by d */
    ACT_RUN,          /* continuous: to the turning point, or until pull-off */
    ACT_UNDO,
    ACT_REDO,
    ACT_RESET,
    ACT_MODE,         /* relaxation <-> static equilibrium */
    ACT_SELECT_UP,
    ACT_SELECT_DOWN,
    ACT_EDIT,
    ACT_SCALE_UP,
    ACT_SCALE_DOWN,
    ACT_COMMAND,      /* the ':' prompt, same commands as a replay script */
    ACT_PLOTS,
    ACT_HELP,
    ACT_REDRAW,
    ACT_CANCEL,
    ACT_QUIT
} tui_action;

typedef struct tui_key_binding {
    int key;              /* curses key code, as in tui/replay.h */
    tui_action action;
    const char *what;     /* one line for help, --list-keys and the man page */
} tui_key_binding;

/* The table, terminated by an entry with action ACT_NONE. */
extern const tui_key_binding tui_key_table[];

/* The action bound to key, ACT_NONE when none. Digits are not in the table:
 * they make a count prefix (see the help screen's first line). */
tui_action tui_action_for_key(int key);

/* The key table, one line per key: the key as a replay script writes it
 * (f, <Left>, <C-r>), a TAB, what it does. For --list-keys. */
void tui_print_keys(FILE *out);

#endif
