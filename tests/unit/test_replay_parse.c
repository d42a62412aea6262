/* The replay-script tokenizer: keys, special key names, commands, comments,
 * and errors that name the line and the token. */
#include <curses.h>
#include <string.h>

#include "tap.h"
#include "tui/replay.c"   /* the TUI is not in libadhere.a */

static int parse(const char *text, tui_replay_script *s, int *line, char *err, size_t n)
{
    return tui_replay_parse(text, strlen(text), s, line, err, n);
}

static int fails_on(const char *text, int want_line, const char *want_in_msg)
{
    tui_replay_script s;
    char err[512] = "";
    int line = -1;
    int rc = parse(text, &s, &line, err, sizeof err);
    int good = rc == -1 && line == want_line && strstr(err, want_in_msg) != NULL && s.n == 0;
    if (!good)
        printf("#   rc %d line %d err '%s'\n", rc, line, err);
    return good;
}

int main(void)
{
    tui_replay_script s;
    char err[512];
    int line;

    ok(parse("f 10f\n<Left><Right> <C-r>  <Enter>\tq", &s, &line, err, sizeof err) == 0, "keys parse");
    int want[] = { 'f', '1', '0', 'f', KEY_LEFT, KEY_RIGHT, 'r' & 0x1f, '\n', 'q' };
    int same = s.n == sizeof want / sizeof want[0];
    for (size_t i = 0; same && i < s.n; i++)
        same = s.items[i].kind == TUI_REPLAY_KEY && s.items[i].key == want[i];
    ok(same, "9 keys in order, words split into their characters");
    ok(s.n == 9 && s.items[0].line == 1 && s.items[4].line == 2 && s.items[8].line == 2,
       "each key knows its line");
    tui_replay_free(&s);

    ok(parse("# a comment f f\n:set E 1GPa # why\n:dump out/a.txt\n:wait\n:resize 80x24\n<lt> < <Esc><Space><Tab><PgUp><PgDn><F1><F12><BS>",
             &s, &line, err, sizeof err) == 0, "commands and comments parse");
    ok(s.n == 14, "4 commands and 10 keys (got %zu)", s.n);
    if (s.n == 14) {
        ok(s.items[0].kind == TUI_REPLAY_SET && strcmp(s.items[0].name, "E") == 0 &&
           strcmp(s.items[0].value, "1GPa") == 0 && s.items[0].line == 2, ":set E 1GPa on line 2");
        ok(s.items[1].kind == TUI_REPLAY_DUMP && strcmp(s.items[1].value, "out/a.txt") == 0, ":dump FILE");
        ok(s.items[2].kind == TUI_REPLAY_WAIT, ":wait");
        ok(s.items[3].kind == TUI_REPLAY_RESIZE && s.items[3].cols == 80 && s.items[3].rows == 24, ":resize 80x24");
        ok(s.items[4].key == '<' && s.items[5].key == '<' && s.items[6].key == 27 && s.items[7].key == ' ' &&
           s.items[8].key == '\t' && s.items[9].key == KEY_PPAGE && s.items[10].key == KEY_NPAGE &&
           s.items[11].key == KEY_F(1) && s.items[12].key == KEY_F(12) && s.items[13].key == KEY_BACKSPACE,
           "special keys map to curses codes");
    }
    tui_replay_free(&s);

    ok(parse("", &s, &line, err, sizeof err) == 0 && s.n == 0, "an empty script is fine");
    ok(parse("\n\n  \n# only comments\n", &s, &line, err, sizeof err) == 0 && s.n == 0, "blank lines and comments only");
    ok(parse("f\r\nq\r\n", &s, &line, err, sizeof err) == 0 && s.n == 2, "CRLF line ends");
    tui_replay_free(&s);
    ok(parse("<enter><c-R><f5>", &s, &line, err, sizeof err) == 0 && s.n == 3 && s.items[1].key == 18 &&
       s.items[2].key == KEY_F(5), "key names are case-insensitive");
    tui_replay_free(&s);

    ok(fails_on("f\nf <Foo> q", 2, "unknown key <Foo>"), "unknown key name names line 2 and the name");
    ok(fails_on("f\n\n\n:frob 1", 4, "unknown command ':frob'"), "unknown command names line 4");
    ok(fails_on(":set E", 1, "takes NAME VALUE"), ":set with one word");
    ok(fails_on(":set E 1 GPa", 1, "3 words follow"), ":set with a blank in the value");
    ok(fails_on(":wait f", 1, "takes nothing"), ":wait with keys after it");
    ok(fails_on(":dump", 1, "one FILE"), ":dump without a file");
    ok(fails_on("f\n:resize 10x10", 2, "'10x10' is not allowed"), ":resize too small");
    ok(fails_on(":resize 80by24", 1, "'80by24'"), ":resize malformed");
    ok(fails_on("a<Enter", 1, "'<' opens no key name"), "unclosed <");
    ok(fails_on("<>", 1, "'<' opens no key name"), "empty <>");
    ok(fails_on("<F13>", 1, "unknown key <F13>"), "F13");
    ok(fails_on("<C-1>", 1, "unknown key <C-1>"), "C-1");
    ok(fails_on("2\xc2\xb5m", 1, "0xc2"), "a non-ASCII byte");
    ok(fails_on("f\nq\x01", 2, "0x01"), "a control byte");
    ok(tui_replay_parse("f\n\0q", 4, &s, &line, err, sizeof err) == -1 && line == 2, "a NUL byte on line 2");

    char name[32];
    tui_replay_key_name(KEY_LEFT, name, sizeof name);
    ok(strcmp(name, "<Left>") == 0, "name of KEY_LEFT is <Left>");
    tui_replay_key_name(18, name, sizeof name);
    ok(strcmp(name, "<C-r>") == 0, "name of 18 is <C-r>");
    tui_replay_key_name('\n', name, sizeof name);
    ok(strcmp(name, "<Enter>") == 0, "name of newline is <Enter>");
    tui_replay_key_name('?', name, sizeof name);
    ok(strcmp(name, "?") == 0, "name of ? is ?");
    tui_replay_key_name(KEY_F(10), name, sizeof name);
    ok(strcmp(name, "<F10>") == 0, "name of F10");
    /* Every named key round-trips through its name. */
    int keys_ok = 1;
    int codes[] = { KEY_UP, KEY_DOWN, 27, ' ', '\t', KEY_PPAGE, KEY_NPAGE, KEY_F(1), KEY_F(12), 1, 26, 'x', '<' };
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        tui_replay_key_name(codes[i], name, sizeof name);
        if (parse(name, &s, &line, err, sizeof err) != 0 || s.n != 1 || s.items[0].key != codes[i]) {
            printf("#   %d -> '%s' does not round-trip\n", codes[i], name);
            keys_ok = 0;
        }
        tui_replay_free(&s);
    }
    ok(keys_ok, "key names round-trip through the parser");

    /* Random scripts from the tokens' alphabet: every parse must either
     * succeed with keys on real lines or fail naming a line that exists. */
    static const char alphabet[] = "fbru:<>#\n \tset E1GPa:dump :wait :resize 80x24 <Enter><C-r><F1>\x01\xc3";
    unsigned seed = 12345;
    int fuzz_ok = 1;
    char buf[200];
    for (int round = 0; round < 20000 && fuzz_ok; round++) {
        size_t len = (size_t)(round % 199);
        int lines = 1;
        for (size_t i = 0; i < len; i++) {
            seed = seed * 1103515245u + 12345u;
            buf[i] = alphabet[(seed >> 16) % (sizeof alphabet - 1)];
            lines += buf[i] == '\n';
        }
        int rc = tui_replay_parse(buf, len, &s, &line, err, sizeof err);
        if (rc == 0) {
            for (size_t i = 0; i < s.n; i++)
                if (s.items[i].line < 1 || s.items[i].line > lines)
                    fuzz_ok = 0;
        } else if (rc != -1 || line < 1 || line > lines || err[0] == '\0' || s.n != 0) {
            fuzz_ok = 0;
        }
        if (!fuzz_ok)
            printf("#   round %d: rc %d line %d of %d: %s\n", round, rc, line, lines, err);
        tui_replay_free(&s);
    }
    ok(fuzz_ok, "20000 random scripts parse or fail on a real line, never crash");
    return tap_done();
}
