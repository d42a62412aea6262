/* Keystroke scripts for --replay: the tokenizer, apart from curses and the
 * session so it can be unit tested and fuzzed. A script is words separated
 * by blanks or newlines:
 *   a word of printable ASCII keys, with <Name> for special keys: f 10f 2GPa<Enter>
 *   :set NAME VALUE   :dump FILE   :rows FILE   :wait   :resize COLSxROWS
 *   # a comment, to the end of the line
 * Key codes are those of curses (KEY_LEFT, ...), with Enter as '\n', Esc 27,
 * Tab '\t' and C-x as x & 0x1f, the same codes the terminal key source gives. */
#ifndef ADH_TUI_REPLAY_H
#define ADH_TUI_REPLAY_H

#include <stddef.h>

typedef enum tui_replay_kind {
    TUI_REPLAY_KEY = 0,
    TUI_REPLAY_SET,      /* name, value */
    TUI_REPLAY_DUMP,     /* value: the file */
    TUI_REPLAY_WAIT,
    TUI_REPLAY_RESIZE,   /* cols, rows */
    TUI_REPLAY_ROWS      /* value: the file */
} tui_replay_kind;

typedef struct tui_replay_item {
    tui_replay_kind kind;
    int line;            /* 1-based line in the script, for messages */
    int key;             /* TUI_REPLAY_KEY */
    int cols, rows;      /* TUI_REPLAY_RESIZE */
    char *name, *value;  /* TUI_REPLAY_SET / _DUMP / _ROWS (owned) */
} tui_replay_item;

typedef struct tui_replay_script {
    tui_replay_item *items;
    size_t n, cap;
} tui_replay_script;

/* The screen sizes --size and :resize accept. */
#define TUI_REPLAY_MIN_COLS 40
#define TUI_REPLAY_MAX_COLS 1000
#define TUI_REPLAY_MIN_ROWS 12
#define TUI_REPLAY_MAX_ROWS 1000

/* Parses len bytes of text (NUL bytes are an error). Returns 0, or -1 with
 * the offending line in *errline and a sentence naming the token and what is
 * allowed in err. script is emptied first and left empty on error. */
int tui_replay_parse(const char *text, size_t len, tui_replay_script *script,
                     int *errline, char *err, size_t errlen);
void tui_replay_free(tui_replay_script *script);

/* The key code of a special key name without brackets ("Left", "C-r", "F5"),
 * case-insensitive; -1 when unknown. */
int tui_replay_key_code(const char *name);
/* The script spelling of a key code: "f", "<Left>", "<C-r>", "<Enter>". */
void tui_replay_key_name(int key, char *buf, size_t len);

#endif
