#include "scene/text.h"

const char *adh_text_not_utf8(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    while (*p) {
        int n = *p < 0x80 ? 0 : *p >= 0xc2 && *p <= 0xdf ? 1 : *p >= 0xe0 && *p <= 0xef ? 2
              : *p >= 0xf0 && *p <= 0xf4 ? 3 : -1;
        if (n < 0)
            return (const char *)p;
        for (int k = 1; k <= n; k++)
            if ((p[k] & 0xc0) != 0x80)
                return (const char *)p;
        p += n + 1;
    }
    return 0;
}
