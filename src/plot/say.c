#include "plot/say.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/outdir.h"

/* A message of up to 4 KB is escaped on the stack (each byte escaped takes
 * four): a study's threads may say things at once, and a why buffer's
 * kilobytes need no allocation; a longer one (a long path, a long list)
 * on the heap, up to ADH_SAY_MAX bytes. */
#define SAY_STACK 4096

/* "WHO: MSG\n" with msg's first n bytes escaped, and, when some were left
 * out (more of them past n, or what the escaped text could not hold), an
 * ellipsis and how many. */
static void say_text(const char *who, const char *msg, size_t n, size_t more)
{
    char small[4 * SAY_STACK + 1], *cut = NULL, *big = NULL;
    if (msg[n] != '\0' && (cut = malloc(n + 1)) != NULL) {   /* a prefix: NUL-terminated, on its own */
        memcpy(cut, msg, n);
        cut[n] = '\0';
    }
    const char *text = cut ? cut : msg;
    if (n > SAY_STACK)
        big = malloc(4 * n + 1);
    /* out of memory: as much as the stack holds, and what was left out said;
     * without the prefix's copy, room for n bytes at most, which escape no
     * more than n of msg's (not all of it, past the bound) */
    size_t room = big ? 4 * n + 1 : sizeof small;
    if (text == msg && msg[n] != '\0' && room > n + 1)
        room = n + 1;
    size_t done = adh_outdir_escape_prefix(text, big ? big : small, room, 1);
    more += n - (done < n ? done : n);
    char tail[80] = "";
    if (more)
        snprintf(tail, sizeof tail, "\xe2\x80\xa6 (message cut: %zu bytes more)", more);
    if (who)
        fprintf(stderr, "%s: %s%s\n", who, big ? big : small, tail);
    else
        fprintf(stderr, "%s%s\n", big ? big : small, tail);
    free(big);
    free(cut);
}

void adh_say_as(const char *who, const char *msg)
{
    msg = msg ? msg : "";
    size_t n = strlen(msg);
    say_text(who, msg, n < ADH_SAY_MAX ? n : ADH_SAY_MAX, n > ADH_SAY_MAX ? n - ADH_SAY_MAX : 0);
}

void adh_say(const char *msg)
{
    adh_say_as("adhere", msg);
}

/* fmt's text formatted whole first (on the heap when longer than the
 * stack's 8 KB, up to ADH_SAY_MAX bytes), then escaped: a file name or a
 * why in it is shown as adh_say shows it. */
static void vsay(const char *who, const char *fmt, va_list ap)
{
    char small[8192], *big = NULL;
    va_list again;
    va_copy(again, ap);
    int w = vsnprintf(small, sizeof small, fmt, ap);
    size_t n = w < 0 ? 0 : (size_t)w, room = sizeof small - 1;
    if (w < 0)
        small[0] = '\0';
    if (n > room) {
        size_t len = (n < ADH_SAY_MAX ? n : ADH_SAY_MAX) + 1;
        if ((big = malloc(len)) != NULL) {
            vsnprintf(big, len, fmt, again);
            room = len - 1;
        }
    }
    va_end(again);
    size_t said = n < room ? n : room;
    say_text(who, big ? big : small, said, n - said);
    free(big);
}

void adh_sayf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsay("adhere", fmt, ap);
    va_end(ap);
}

void adh_sayf_as(const char *who, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsay(who, fmt, ap);
    va_end(ap);
}
