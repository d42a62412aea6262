/* Keystroke scripts for --replay: the tokenizer, apart from curses and the
 * session so it can be unit tested and fuzzed. A script is words separated
 * by blanks or newlines:
 *   a word of printable ASCII keys, with <Name> for special keys: f 10f 2GPa<Enter>
 *   :set NAME VALUE   :dump FILE   :wait   :resize COLSxROWS
 *   # a comment, to the end of the line
 * Key codes are those of curses (KEY_LEFT, ...), with Enter as '\n', Esc 27,
 * Tab '\t' and C-x as x & 0x1f, the same codes the terminal key source gives. */
#ifndef ADH_TUI_REPLAY_H
#define ADH_TUI_REPLAY_H

#include <stddef.h>

typedef enum adh_replay_kind {
    ADH_REPLAY_KEY = 0,
    ADH_REPLAY_SET,      /* name, value */
    ADH_REPLAY_DUMP,     /* value: the file */
    ADH_REPLAY_WAIT,
    ADH_REPLAY_RESIZE    /* cols, rows */
} adh_replay_kind;

typedef struct adh_replay_item {
    adh_replay_kind kind;
    int line;            /* 1-based line in the script, for messages */
    int key;             /* ADH_REPLAY_KEY */
    int cols, rows;      /* ADH_REPLAY_RESIZE */
    char *name, *value;  /* ADH_REPLAY_SET / ADH_REPLAY_DUMP (owned) */
} adh_replay_item;

typedef struct adh_replay_script {
    adh_replay_item *items;
    size_t n, cap;
} adh_replay_script;

/* The screen sizes --size and :resize accept. */
#define ADH_REPLAY_MIN_COLS 40
#define ADH_REPLAY_MAX_COLS 1000
#define ADH_REPLAY_MIN_ROWS 12
#define ADH_REPLAY_MAX_ROWS 1000

/* Parses len bytes of text (NUL bytes are an error). Returns 0, or -1 with
 * the offending line in *errline and a sentence naming the token and what is
 * allowed in err. script is emptied first and left empty on error. */
int adh_replay_parse(const char *text, size_t len, adh_replay_script *script,
                     int *errline, char *err, size_t errlen);
void adh_replay_free(adh_replay_script *script);

/* The key code of a special key name without brackets ("Left", "C-r", "F5"),
 * case-insensitive; -1 when unknown. */
int adh_replay_key_code(const char *name);
/* The script spelling of a key code: "f", "<Left>", "<C-r>", "<Enter>". */
void adh_replay_key_name(int key, char *buf, size_t len);

#endif
