#include "scene/text.h"

int adh_text_utf8_len(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    int n = *p < 0x80 ? 0 : *p >= 0xc2 && *p <= 0xdf ? 1 : *p >= 0xe0 && *p <= 0xef ? 2
          : *p >= 0xf0 && *p <= 0xf4 ? 3 : -1;
    if (n < 0)
        return 0;
    for (int k = 1; k <= n; k++)
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
