/* The ncurses front end. Runs on a terminal, or headless from a replay
 * script (cfg->replay) with no tty at all. Returns the process exit status. */
#ifndef ADH_TUI_H
#define ADH_TUI_H

#include <stdio.h>

#include "scene/config.h"

int tui_main(const adh_config *cfg);

/* The key table, one line per key: the key as a replay script writes it
 * (f, <Left>, <C-r>), a TAB, what it does. For --list-keys. */
void tui_print_keys(FILE *out);

#endif
