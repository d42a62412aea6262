/* adh_sayf and adh_say write a message whole, however long (a long path,
 * a long list): one line, "adhere: " and every byte of it, control bytes
 * escaped; past the bound on a message's size, cut with an ellipsis and
 * how much was left out, never in silence. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* say.c compiled here with its malloc counted: the allocation numbered
 * fail_at fails (out of memory on the way) */
static long calls, fail_at = -1;
static void *count_malloc(size_t n)
{
    return ++calls == fail_at ? NULL : malloc(n);
}
#define malloc count_malloc
#include "plot/say.c"   /* in place of libadhere.a's */
#undef malloc

#include "plot/say.h"
#include "tap.h"

/* What fn wrote to stderr, into a malloc'd string (*n its length). */
static char *said(void (*fn)(const char *), const char *arg, size_t *n)
{
    FILE *tmp = tmpfile();
    if (!tmp)
        return NULL;
    fflush(stderr);
    int saved = dup(2);
    dup2(fileno(tmp), 2);
    fn(arg);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    long len = ftell(tmp) >= 0 ? (fseek(tmp, 0, SEEK_END), ftell(tmp)) : -1;
    char *out = len >= 0 ? malloc((size_t)len + 1) : NULL;
    rewind(tmp);
    *n = out ? fread(out, 1, (size_t)len, tmp) : 0;
    if (out)
        out[*n] = '\0';
    fclose(tmp);
    return out;
}

static void sayf(const char *msg)
{
    adh_sayf("%s", msg);
}

static void say(const char *msg)
{
    adh_say(msg);
}

/* n bytes of text: "x" repeated, an ESC every esc bytes (0: none), and
 * "END" last. */
static char *text(size_t n, size_t esc)
{
    char *s = malloc(n + 1);
    if (!s)
        return NULL;
    for (size_t i = 0; i < n; i++)
        s[i] = esc && i % esc == esc - 1 ? '\033' : 'x';
    memcpy(s + n - 3, "END", 3);
    s[n] = '\0';
    return s;
}

/* "adhere: " msg "\n" with each ESC as \x1b. */
static char *expected(const char *msg)
{
    size_t n = strlen(msg);
    char *e = malloc(4 * n + 16), *p = e;
    if (!e)
        return NULL;
    p += sprintf(p, "adhere: ");
    for (const char *c = msg; *c; c++)
        p += *c == '\033' ? sprintf(p, "\\x1b") : sprintf(p, "%c", *c);
    sprintf(p, "\n");
    return e;
}

static void whole(void (*fn)(const char *), const char *name, size_t n, size_t esc)
{
    char *msg = text(n, esc), *want = msg ? expected(msg) : NULL;
    size_t got_n = 0;
    char *got = want ? said(fn, msg, &got_n) : NULL;
    ok(got && strlen(want) == got_n && memcmp(got, want, got_n) == 0,
       "%s of %zu bytes%s is written whole, escaped (%zu bytes said, %zu wanted)", name, n,
       esc ? " with ESC bytes" : "", got_n, want ? strlen(want) : 0);
    free(got);
    free(want);
    free(msg);
}

int main(void)
{
    /* below the old 8 KB cut: as before */
    whole(sayf, "adh_sayf", 100, 0);
    /* past it: adh_sayf cut at 8191 bytes, adh_say's escaping at 16 KB */
    whole(sayf, "adh_sayf", 20000, 0);
    whole(sayf, "adh_sayf", 9000, 7);
    whole(say, "adh_say", 20000, 0);
    whole(say, "adh_say", 20000, 3);
    whole(sayf, "adh_sayf", 300000, 0);

    /* past the bound (ADH_SAY_MAX): cut, with an ellipsis and how much */
    size_t n = ADH_SAY_MAX + 5000;
    char *msg = text(n, 0);
    size_t got_n = 0;
    char *got = msg ? said(sayf, msg, &got_n) : NULL;
    ok(got && !strncmp(got, "adhere: xxx", 11) && !strstr(got, "END") && got_n > ADH_SAY_MAX &&
       got_n < ADH_SAY_MAX + 200, "a message of %zu bytes is cut near ADH_SAY_MAX (%zu bytes said)", n, got_n);
    char tail[128];
    snprintf(tail, sizeof tail, "\xe2\x80\xa6 (message cut: %zu bytes more)\n", n - ADH_SAY_MAX);
    ok(got && got_n > strlen(tail) && !strcmp(got + got_n - strlen(tail), tail),
       "... and ends with the ellipsis and what was left out: '%s'",
       got && got_n > 60 ? got + got_n - 60 : "");
    free(got);
    got = msg ? said(say, msg, &got_n) : NULL;
    ok(got && got_n > strlen(tail) && !strcmp(got + got_n - strlen(tail), tail) && got_n < ADH_SAY_MAX + 200,
       "adh_say cuts it the same way (%zu bytes said)", got_n);
    free(got);

    /* out of memory for the cut's copy: still cut at the bound, never the
     * whole message with a tail that says some of it was left out (it
     * escaped the message whole, 'END' and all, then said 5000 bytes more) */
    calls = 0, fail_at = 1;
    got = msg ? said(say, msg, &got_n) : NULL;
    fail_at = -1;
    const char *cutword = got ? strstr(got, "(message cut: ") : NULL;
    size_t more = 0;
    ok(got && !strstr(got, "END") && got_n < ADH_SAY_MAX + 200 && cutword &&
       sscanf(cutword, "(message cut: %zu bytes more)", &more) == 1 &&
       (size_t)(strstr(got, "\xe2\x80\xa6") - got) - strlen("adhere: ") + more == n,
       "without memory for the cut's copy, a message of %zu bytes is still cut near ADH_SAY_MAX, what was said and "
       "what was left out adding up (%zu bytes said, %zu more)", n, got_n, more);
    free(got);
    free(msg);
    return tap_done();
}
