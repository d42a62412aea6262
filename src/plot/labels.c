#include "plot/labels.h"

#include <stdio.h>

const char *adh_gp_quoted(const char *s, char *buf, size_t len)
{
    size_t j = 0;
    if (len < 3)
        return "''";
    buf[j++] = '\'';
    for (; *s && j + 3 < len; s++) {
        if (*s == '\'')
            buf[j++] = '\'';
        buf[j++] = *s;
    }
    buf[j++] = '\'';
    buf[j] = '\0';
    return buf;
}

void adh_force_unit(double fmax, double *scale, const char **name)
{
    if (fmax >= 1e-4) {
        *scale = 1e3; *name = "mN";
    } else if (fmax >= 1e-7) {
        *scale = 1e6; *name = "µN";
    } else if (fmax >= 1e-10) {
        *scale = 1e9; *name = "nN";
    } else {
        *scale = 1e12; *name = "pN";
    }
}

void adh_format_modulus(double v, char *buf, size_t len)
{
    if (v >= 1e9)
        snprintf(buf, len, "%.3g GPa", v * 1e-9);
    else if (v >= 1e6)
        snprintf(buf, len, "%.3g MPa", v * 1e-6);
    else
        snprintf(buf, len, "%.3g kPa", v * 1e-3);
}
