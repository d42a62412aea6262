#include "scene/measured.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct { const char *sym; double f; } unit;
static const unit lengths[] = { { "pm", 1e-12 }, { "nm", 1e-9 }, { "um", 1e-6 }, { "\xc2\xb5m", 1e-6 },
                                { "mm", 1e-3 }, { "m", 1 } };
static const unit forces[] = { { "pN", 1e-12 }, { "nN", 1e-9 }, { "uN", 1e-6 }, { "\xc2\xb5N", 1e-6 },
                               { "mN", 1e-3 }, { "N", 1 } };

/* The unit a header token names: inside [] or (), or after _ or /
 * ("h0[nm]", "F(nN)", "force_pN", "h0/nm"). 0 when none of the list. */
static double unit_of(const char *tok, const unit *u, size_t nu)
{
    const char *p = tok + strcspn(tok, "[(_/");
    if (!*p)
        return 0;
    char sym[16];
    size_t k = 0;
    for (p++; *p && *p != ']' && *p != ')' && k + 1 < sizeof sym; p++)
        sym[k++] = *p;
    sym[k] = '\0';
    for (size_t i = 0; i < nu; i++)
        if (strcmp(sym, u[i].sym) == 0)
            return u[i].f;
    return 0;
}

/* Splits line into at most 3 tokens at blanks, tabs and commas. */
static int split(char *line, char **tok)
{
    int n = 0;
    for (char *p = strtok(line, " \t,\r\n"); p; p = strtok(NULL, " \t,\r\n"))
        if (n < 3)
            tok[n++] = p;
        else
            return 4;
    return n;
}

static int number(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return end != s && !*end && errno != ERANGE && isfinite(*v);
}

/* Why a token that reads as a number whole is still refused: out of a
 * double's range or not finite; NULL when it is no number at all. */
static const char *out_of_range(const char *s)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end)
        return NULL;
    if (errno == ERANGE)
        return fabs(v) < 1 ? "is too small for a double (it underflows: magnitudes below 2.2e-308 are not kept); "
                             "write 0 for zero"
                           : "is too large for a double (above 1.8e308)";
    return isfinite(v) ? NULL : "is not a finite number";
}

/* One line of f into buf (at most cap - 1 bytes, its newline kept): its
 * length, 0 at the end, -1 when longer than that (buf then holds its first
 * cap - 1 bytes; the rest is not read). A NUL byte is kept, and counted. */
static long read_line(FILE *f, char *buf, size_t cap)
{
    size_t n = 0;
    int c;
    while ((c = getc(f)) != EOF) {
        if (n + 1 >= cap) {
            buf[n] = '\0';
            return -1;
        }
        buf[n++] = (char)c;
        if (c == '\n')
            break;
    }
    buf[n] = '\0';
    return (long)n;
}

void adh_measured_free(adh_measured *m)
{
    free(m->h0);
    free(m->F);
    m->h0 = m->F = NULL;
    m->n = 0;
}

int adh_measured_load(const char *path, adh_measured *m, char *why, size_t whylen)
{
    memset(m, 0, sizeof *m);
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(why, whylen, "%s: cannot read the measured curve: %s", path, strerror(errno));
        return -1;
    }
    double fx = 1e-9, fy = 1e-9;   /* nm, nN */
    size_t cap = 0, lineno = 0, bytes = 0;
    int header_seen = 0;
    char line[4096];
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > ADH_MEASURED_MAX_BYTES) {
        snprintf(why, whylen, "%s: %lld bytes, more than a measured curve may hold (%d MiB, %d points): thin it "
                 "(every k-th point) or cut it to the range you compare", path, (long long)st.st_size,
                 ADH_MEASURED_MAX_BYTES >> 20, ADH_MEASURED_MAX_POINTS);
        goto bad;
    }
    long len;
    while ((len = read_line(f, line, sizeof line)) != 0) {
        lineno++;
        if (len < 0 && !memchr(line, '\0', sizeof line - 1)) {
            snprintf(why, whylen, "%s:%zu: line longer than %zu characters", path, lineno, sizeof line - 2);
            goto bad;
        }
        if (memchr(line, '\0', len < 0 ? sizeof line - 1 : (size_t)len)) {
            snprintf(why, whylen, "%s:%zu: a NUL byte: not a text file (a measured curve is text, a drive position "
                     "and a force a line)", path, lineno);
            goto bad;
        }
        bytes += (size_t)len;
        if (bytes > ADH_MEASURED_MAX_BYTES || m->n == ADH_MEASURED_MAX_POINTS) {
            snprintf(why, whylen, "%s:%zu: more than a measured curve may hold (%d MiB, %d points): thin it "
                     "(every k-th point) or cut it to the range you compare", path, lineno,
                     ADH_MEASURED_MAX_BYTES >> 20, ADH_MEASURED_MAX_POINTS);
            goto bad;
        }
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        char copy[4096], *tok[3];
        snprintf(copy, sizeof copy, "%s", line);
        int nt = split(copy, tok);
        if (nt == 0)
            continue;
        double x, y;
        if (nt == 2 && number(tok[0], &x) && number(tok[1], &y)) {
            if (m->n == cap) {
                size_t nc = cap ? 2 * cap : 256;
                double *a = realloc(m->h0, nc * sizeof *a);
                if (a)
                    m->h0 = a;
                double *b = a ? realloc(m->F, nc * sizeof *b) : NULL;
                if (!b) {
                    snprintf(why, whylen, "%s:%zu: out of memory", path, lineno);
                    goto bad;
                }
                m->F = b;
                cap = nc;
            }
            m->h0[m->n] = x * fx;
            m->F[m->n] = y * fy;
            m->n++;
            continue;
        }
        /* a header, before any number: it must name both units */
        if (nt == 2 && m->n == 0 && !header_seen && !isdigit((unsigned char)tok[0][0]) && tok[0][0] != '-' &&
            tok[0][0] != '+' && tok[0][0] != '.') {
            fx = unit_of(tok[0], lengths, sizeof lengths / sizeof lengths[0]);
            fy = unit_of(tok[1], forces, sizeof forces / sizeof forces[0]);
            if (fx == 0 || fy == 0) {
                snprintf(why, whylen, "%s:%zu: the header '%s %s' does not name the %s unit: write e.g. "
                         "'h0[nm] F[nN]' (lengths pm nm um mm m, forces pN nN uN mN N)", path, lineno, tok[0],
                         tok[1], fx == 0 ? "position's" : "force's");
                goto bad;
            }
            header_seen = 1;
            continue;
        }
        const char *range = nt == 2 ? out_of_range(tok[0]) : NULL;
        int which = range ? 0 : 1;
        if (!range && nt == 2)
            range = out_of_range(tok[1]);
        if (range) {
            snprintf(why, whylen, "%s:%zu: '%.60s' %s", path, lineno, tok[which], range);
            goto bad;
        }
        char *nl = strpbrk(line, "\r\n");
        if (nl)
            *nl = '\0';
        snprintf(why, whylen, "%s:%zu: '%.60s' is not two numbers: each line is a drive position and a force "
                 "(nm and nN, or the units a header names, e.g. 'h0[nm] F[nN]')", path, lineno, line);
        goto bad;
    }
    if (ferror(f)) {
        snprintf(why, whylen, "%s:%zu: read error: %s", path, lineno, strerror(errno));
        goto bad;
    }
    if (m->n < 2) {
        snprintf(why, whylen, "%s:%zu: %zu point%s: a measured curve needs at least 2", path, lineno, m->n,
                 m->n == 1 ? "" : "s");
        goto bad;
    }
    fclose(f);
    return 0;
bad:
    fclose(f);
    adh_measured_free(m);
    return -1;
}
