#include "plot/labels.h"

#include <stdio.h>
#include <string.h>

/* Appends to buf at *j what fits, always counting the whole. */
static void put(char *buf, size_t len, size_t *j, const char *t, size_t n)
{
    if (*j < len)
        memcpy(buf + *j, t, *j + n < len ? n : len - *j);
    *j += n;
}

/* The expression for prefix followed by s (see labels.h). */
static size_t quote2(const char *prefix, const char *s, char *buf, size_t len)
{
    size_t j = 0;
    int pieces = 0, open = 0;   /* open: inside a single-quoted run */
    for (int part = 0; part < 2; part++) {
        for (const unsigned char *c = (const unsigned char *)(part ? s : prefix); *c; c++) {
            int plain = *c >= 0x20 && *c != 0x7f && *c != '\'';
            if (plain) {
                if (!open) {
                    if (pieces++)
                        put(buf, len, &j, ".", 1);
                    put(buf, len, &j, "'", 1);
                    open = 1;
                }
                put(buf, len, &j, (const char *)c, 1);
                continue;
            }
            if (open) {
                put(buf, len, &j, "'", 1);
                open = 0;
            }
            char esc[8];
            if (*c == '\n')
                snprintf(esc, sizeof esc, "\"\\n\"");
            else if (*c == '\r')
                snprintf(esc, sizeof esc, "\"\\r\"");
            else
                snprintf(esc, sizeof esc, "\"\\%03o\"", *c);
            if (pieces++)
                put(buf, len, &j, ".", 1);
            put(buf, len, &j, esc, strlen(esc));
        }
    }
    if (open)
        put(buf, len, &j, "'", 1);
    if (!pieces)
        put(buf, len, &j, "''", 2);
    if (j < len) {
        buf[j] = '\0';
    } else if (len) {
        static const char loud[] = "adh_text_too_long";
        size_t m = len > strlen(loud) ? strlen(loud) : 0;
        memcpy(buf, loud, m);
        buf[m] = '\0';
    }
    return j;
}

size_t adh_gp_quote(const char *s, char *buf, size_t len)
{
    return quote2("", s, buf, len);
}

const char *adh_gp_quoted(const char *s, char *buf, size_t len)
{
    adh_gp_quote(s, buf, len);
    return buf;
}

const char *adh_gp_path(const char *path, char *buf, size_t len)
{
    quote2(path[0] == '/' ? "" : "./", path, buf, len);
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

