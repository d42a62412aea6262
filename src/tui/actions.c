#include "tui/actions.h"

#include <curses.h>

#include "tui/replay.h"

/* Several keys per action where terminals differ (arrows vs letters), so a
 * newcomer's first guess works. Order is the order of the help screen. */
const tui_key_binding tui_key_table[] = {
    { 'f', ACT_FORWARD, "step forward: approach by d and relax (a count before it repeats: 10f)" },
    { KEY_RIGHT, ACT_FORWARD, "step forward, as f" },
    { 'b', ACT_BACK, "step back: retract by d and relax (a count repeats: 10b)" },
    { KEY_LEFT, ACT_BACK, "step back, as b" },
    { 'r', ACT_RUN, "run: load to the turning point, or, once unloading, until the surfaces jump apart (the jump-out); any key pauses" },
    { 'u', ACT_UNDO, "undo: back to the previous state on the path (exactly as it was); at its first state, takes back the last edit: the parameters before it and the path they had" },
    { 'U', ACT_REDO, "redo: forward again along the undone states and edits" },
    { 'r' & 0x1f, ACT_REDO, "redo, as U" },
    { 'x', ACT_RESET, "reset: forget the path and go back to the start position" },
    { 'm', ACT_MODE, "mode: switch between relaxation and the static equilibrium curve (in static mode f and r follow the curve, b and u walk back along it)" },
    { KEY_UP, ACT_SELECT_UP, "select the parameter above" },
    { 'k', ACT_SELECT_UP, "select the parameter above, as <Up>" },
    { KEY_DOWN, ACT_SELECT_DOWN, "select the parameter below" },
    { 'j', ACT_SELECT_DOWN, "select the parameter below, as <Down>" },
    { '\n', ACT_EDIT, "edit the selected parameter: a bare number is in the unit shown beside it (10 for R in um), or give a unit (2GPa, 0.4nm); <Enter> sets it, <Esc> cancels" },
    { 'e', ACT_EDIT, "edit the selected parameter, as <Enter>" },
    { '+', ACT_SCALE_UP, "double the selected parameter" },
    { '-', ACT_SCALE_DOWN, "halve the selected parameter" },
    { ':', ACT_COMMAND, "command prompt: set NAME VALUE (a field, or a key of the run: protocol.dwell), dump FILE, rows FILE (as in replay scripts)" },
    { 'p', ACT_PLOTS, "write the plots (force, profile, contact radius) as PNG through gnuplot into ./adhere-plots/, or the directory --out names; the static curve's into static/ there; during r, pause and draw the path so far" },
    { '?', ACT_HELP, "this help; any key returns" },
    { KEY_F(1), ACT_HELP, "help, as ?" },
    { 'l' & 0x1f, ACT_REDRAW, "redraw the screen" },
    { 27, ACT_CANCEL, "cancel a count or pause a run" },
    { ' ', ACT_CANCEL, "pause a run, as <Esc>" },
    { 'q', ACT_QUIT, "quit (the terminal is restored; so it is on SIGINT, SIGTERM and SIGHUP)" },
    { 0, ACT_NONE, NULL },
};

tui_action tui_action_for_key(int key)
{
    for (const tui_key_binding *b = tui_key_table; b->action != ACT_NONE; b++)
        if (b->key == key)
            return b->action;
    return ACT_NONE;
}

void tui_print_keys(FILE *out)
{
    char name[32];
    for (const tui_key_binding *b = tui_key_table; b->action != ACT_NONE; b++) {
        tui_replay_key_name(b->key, name, sizeof name);
        fprintf(out, "%s\t%s\n", name, b->what);
    }
}
