/* libFuzzer target: whatever bytes a scene title or a file name holds, the
 * quoting function (src/plot/labels.c) gives gnuplot one string expression
 * that evaluates to exactly those bytes and that gnuplot expands nowhere.
 *
 * The output is read here the way gnuplot 5.4 reads a command line:
 *  - its macro pass (command.c, expand_1level_macros) flips "in single
 *    quotes" at every ' and "in double quotes" at every unescaped "; an @
 *    it meets outside both is expanded: every @ must be inside single quotes;
 *  - its tokenizer (scanner.c) runs a backquoted command met outside quotes
 *    or inside double quotes, and ends a single-quoted string at a ' unless a
 *    non-quote byte is followed by '' (taken in as one '): every backquote
 *    must be inside a single-quoted token, every token must be a string or
 *    the '.' joining two;
 *  - the tokens' values, joined, must be the input (behind "./" for a
 *    relative file name), and no command-line byte may be a newline (which
 *    would end the command), a NUL or another control byte.
 * Any failure aborts. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/labels.h"

#define MAXIN 1024

static void fail(const char *why, const char *out)
{
    fprintf(stderr, "fuzz_gpstring: %s\n  output: %s\n", why, out);
    abort();
}

/* The macro pass's quote tracking, as in gnuplot's expand_1level_macros. */
static void check_macros(const char *out)
{
    int in_squote = 0, in_dquote = 0, after_backslash = 0;
    for (const char *c = out; *c; c++) {
        switch (*c) {
        case '@':
            if (!in_squote)
                fail("an @ outside single quotes", out);
            after_backslash = 0;
            break;
        case '"':
            if (!after_backslash)
                in_dquote = !in_dquote;
            after_backslash = 0;
            break;
        case '\'':
            in_squote = !in_squote;
            after_backslash = 0;
            break;
        case '\\':
            if (in_dquote)
                after_backslash = !after_backslash;
            break;
        default:
            after_backslash = 0;
        }
    }
    if (in_squote)
        fail("unbalanced single quotes", out);
}

/* Tokenizes as gnuplot's scanner and evaluates the concatenation into val
 * (at least strlen(out) + 1 bytes). */
static void check_tokens(const char *out, char *val)
{
    size_t v = 0;
    int want_string = 1;
    for (size_t i = 0; out[i];) {
        unsigned char ch = (unsigned char)out[i];
        if (ch < 0x20 || ch == 0x7f)
            fail("a control byte in the command line", out);
        if (ch == ' ') {
            i++;
            continue;
        }
        if (ch == '`')
            fail("a backquote outside quotes", out);
        if (!want_string) {
            if (ch != '.')
                fail("something other than '.' between two strings", out);
            want_string = 1;
            i++;
            continue;
        }
        if (ch == '\'') {
            /* scanner.c: a ' ends the string unless the byte before it is
             * not a quote and it is followed by another ' */
            size_t j = i + 1;
            for (;;) {
                if (!out[j])
                    fail("a single-quoted string without its end", out);
                if (out[j] == '\'')
                    break;
                if (out[j + 1] == '\'' && out[j + 2] == '\'') {
                    val[v++] = out[j];
                    val[v++] = '\'';
                    j += 3;
                    continue;
                }
                val[v++] = out[j++];
            }
            i = j + 1;
        } else if (ch == '"') {
            /* only the escapes the quoting function writes */
            size_t j = i + 1;
            if (out[j] != '\\')
                fail("user text in double quotes", out);
            if (out[j + 1] == 'n' && out[j + 2] == '"') {
                val[v++] = '\n';
                j += 3;
            } else if (out[j + 1] == 'r' && out[j + 2] == '"') {
                val[v++] = '\r';
                j += 3;
            } else if (out[j + 1] >= '0' && out[j + 1] <= '3' && out[j + 2] >= '0' && out[j + 2] <= '7' &&
                       out[j + 3] >= '0' && out[j + 3] <= '7' && out[j + 4] == '"') {
                val[v++] = (char)((out[j + 1] - '0') * 64 + (out[j + 2] - '0') * 8 + (out[j + 3] - '0'));
                j += 5;
            } else {
                fail("a double-quoted string that is not one fixed escape", out);
            }
            i = j;
        } else {
            fail("a token that is neither a string nor '.'", out);
        }
        want_string = 0;
    }
    if (want_string)
        fail("no string, or a trailing '.'", out);
    val[v] = '\0';
}

static void check(const char *in, const char *expect, const char *out)
{
    static char val[ADH_GP_QUOTED_SIZE(MAXIN + 8)];
    check_macros(out);
    check_tokens(out, val);
    if (strcmp(val, expect) != 0)
        fail("the expression does not evaluate to the input", out);
    (void)in;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char in[MAXIN + 1], expect[MAXIN + 8];
    static char out[ADH_GP_QUOTED_SIZE(MAXIN + 8)];
    if (size > MAXIN)
        size = MAXIN;
    memcpy(in, data, size);
    in[size] = '\0';   /* a C string ends at its first NUL, as user text does */

    size_t n = adh_gp_quote(in, out, sizeof out);
    if (n >= sizeof out || n != strlen(out))
        fail("ADH_GP_QUOTED_SIZE is too small, or the length returned is wrong", out);
    check(in, in, out);

    adh_gp_path(in, out, sizeof out);
    snprintf(expect, sizeof expect, "%s%s", in[0] == '/' ? "" : "./", in);
    check(in, expect, out);
    if (expect[0] == '<' || expect[0] == '|' || expect[0] == '~' || !strcmp(expect, "-") ||
        !strcmp(expect, "+") || !strcmp(expect, "++"))
        fail("a file name gnuplot takes for a pipe or a special file", out);

    /* Too small a buffer: a whole expression or the loud undefined name,
     * never a cut string. */
    size_t small = size ? data[0] % 64 : 0;
    char tiny[64];
    n = adh_gp_quote(in, tiny, small);
    if (small && n >= small && strcmp(tiny, "adh_text_too_long") != 0 && tiny[0] != '\0')
        fail("a cut expression in a small buffer", tiny);
    if (small && n < small)
        check(in, in, tiny);
    return 0;
}
