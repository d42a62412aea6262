/* The ncurses front end. Runs on a terminal, or headless from a replay
 * script (cfg->replay) with no tty at all. Returns the process exit status. */
#ifndef ADH_TUI_H
#define ADH_TUI_H

#include "scene/config.h"

int tui_main(const adh_config *cfg);

#endif
