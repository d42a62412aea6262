#include "scene/text.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* RFC 3629's well-formed sequences (its table in section 4): the lead
 * byte fixes how many continuation bytes follow and the range of the
 * first, which is where an overlong form (E0 80 80 for U+0000), a
 * surrogate (ED A0 80, U+D800) and a code point past U+10FFFF (F4 90 80 80)
 * fall out; C0, C1 and F5 to FF lead nothing. */
int adh_text_utf8_len(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    if (*p < 0x80)
        return 1;
    int n = *p >= 0xc2 && *p <= 0xdf ? 1 : *p >= 0xe0 && *p <= 0xef ? 2 : *p >= 0xf0 && *p <= 0xf4 ? 3 : 0;
    unsigned char lo = *p == 0xe0 ? 0xa0 : *p == 0xf0 ? 0x90 : 0x80;
    unsigned char hi = *p == 0xed ? 0x9f : *p == 0xf4 ? 0x8f : 0xbf;
    if (n == 0 || p[1] < lo || p[1] > hi)
        return 0;
    for (int k = 2; k <= n; k++)
        if ((p[k] & 0xc0) != 0x80)
            return 0;
    return n + 1;
}

const char *adh_text_not_utf8(const char *s)
{
    for (int n; *s; s += n)
        if ((n = adh_text_utf8_len(s)) == 0)
            return s;
    return 0;
}

void adh_text_cat(char *buf, size_t len, const char *text)
{
    size_t n = strnlen(buf, len), t = strlen(text);
    if (n + 1 >= len)
        return;
    t = t < len - n - 1 ? t : len - n - 1;
    memcpy(buf + n, text, t);
    buf[n + t] = '\0';
}

void adh_text_catf(char *buf, size_t len, const char *fmt, ...)
{
    size_t n = strnlen(buf, len);
    if (n + 1 >= len)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + n, len - n, fmt, ap);
    va_end(ap);
}
