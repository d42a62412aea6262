/* Drawing: the main screen (parameters, derived values, state, the
 * force-position preview, status) and the help screen, from the session and
 * what the loop tells. Also the text dump of the screen for replays. */
#ifndef ADH_TUI_SCREEN_H
#define ADH_TUI_SCREEN_H

#include <stddef.h>

#include "tui/sim.h"

typedef struct tui_view {
    int sel;               /* selected parameter */
    int utf8;              /* the locale can show sigma, gamma... */
    int no_clock;          /* timings masked */
    const char *status;    /* the status line, plain words */
    int status_error;
    const char *prompt;    /* the edit or command prompt being typed, or NULL */
    long count;            /* count prefix being typed, 0 none */
    const char *activity;  /* "idle", "running to the turning point"... */
    int help_top;          /* first help line shown */
    const struct adh_measured *measured;   /* --data: drawn 'x' under the path, or NULL */
    int params_first;      /* the parameters are being worked on: on a small
                              screen they come before the state */
} tui_view;

void tui_draw(const tui_sim *s, const tui_view *v);
/* Draws the help screen; returns how many lines the help has. */
int tui_draw_help(const tui_view *v);

/* Writes what the terminal shows (curscr) as UTF-8 text, trailing blanks
 * trimmed. 0, or -1 with why. */
int tui_dump_screen(const char *path, char *why, size_t whylen);

#endif
