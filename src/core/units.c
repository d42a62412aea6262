#include "adhere/units.h"
#include "adhere/status.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const struct { const char *sym; double factor; } prefixes[] = {
    /* micro as u, the micro sign U+00B5 and the Greek mu U+03BC (the man
     * pages' \(*m renders as the latter) */
    { "f", 1e-15 }, { "p", 1e-12 }, { "n", 1e-9 }, { "u", 1e-6 }, { "\xc2\xb5", 1e-6 }, { "\xce\xbc", 1e-6 },
    { "m", 1e-3 }, { "c", 1e-2 }, { "k", 1e3 }, { "M", 1e6 }, { "G", 1e9 }, { "T", 1e12 },
    { "z", 1e-21 }, { "a", 1e-18 }, { "", 1.0 },
};

static const char *const unit_sym[] = {
    [ADH_Q_NONE] = "", [ADH_Q_LENGTH] = "m", [ADH_Q_PRESSURE] = "Pa",
    [ADH_Q_ENERGY] = "J", [ADH_Q_SPEED] = "m/s", [ADH_Q_FORCE] = "N",
    [ADH_Q_TIME] = "s", [ADH_Q_STIFFNESS] = "N/m", [ADH_Q_WORK] = "J",
};

static const char *const quantity_name[] = {
    [ADH_Q_NONE] = "a plain number", [ADH_Q_LENGTH] = "a length (m, nm, um, ...)",
    [ADH_Q_PRESSURE] = "a pressure (Pa, MPa, GPa, ...)", [ADH_Q_ENERGY] = "an energy (J, zJ, ...)",
    [ADH_Q_SPEED] = "a speed (m/s, um/s, ...)", [ADH_Q_FORCE] = "a force (N, uN, nN, ...)",
    [ADH_Q_TIME] = "a time (s, ms, us, ...)", [ADH_Q_STIFFNESS] = "a stiffness (N/m, mN/m, ...)",
    [ADH_Q_WORK] = "an energy (J, fJ, ...)",
};

const char *adh_quantity_unit(adh_quantity q)
{
    return unit_sym[q];
}

/* Which quantity a bare unit symbol names, so "5nm" given for a modulus can be
 * reported as "a length where a pressure is wanted" rather than as garbage. */
static int unit_of(const char *suffix, adh_quantity *q, double *factor)
{
    for (int k = ADH_Q_LENGTH; k <= ADH_Q_LAST; k++) {
        if (k == ADH_Q_WORK) /* an energy's unit: found as ADH_Q_ENERGY */
            continue;
        size_t ul = strlen(unit_sym[k]), sl = strlen(suffix);
        if (sl < ul || strcmp(suffix + sl - ul, unit_sym[k]) != 0)
            continue;
        size_t pl = sl - ul;
        for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++) {
            if (strlen(prefixes[i].sym) == pl && strncmp(suffix, prefixes[i].sym, pl) == 0) {
                /* "m" alone is metres, not a milli-prefix on nothing. */
                *q = (adh_quantity)k;
                *factor = prefixes[i].factor;
                return 0;
            }
        }
    }
    return -1;
}

/* Units are case-sensitive (m is milli, M mega): a unit that matches one
 * of the wanted quantity's spellings but for case gets those spellings. */
static void spelling_hint(const char *suffix, adh_quantity q, char *hint, size_t len)
{
    hint[0] = '\0';
    if (q == ADH_Q_NONE)
        return;
    size_t off = 0;
    int found = 0;
    for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++) {
        char cand[16];
        snprintf(cand, sizeof cand, "%s%s", prefixes[i].sym, unit_sym[q]);
        if (strcasecmp(cand, suffix) != 0)
            continue;
        char piece[64];
        snprintf(piece, sizeof piece, "%s'%s'", found ? " or " : " (units are case-sensitive: did you mean ", cand);
        if (off + strlen(piece) + 3 > len)
            break;   /* the hint ends with whole candidates and "?)" */
        memcpy(hint + off, piece, strlen(piece) + 1);
        off += strlen(piece);
        found++;
    }
    if (found)
        memcpy(hint + off, "?)", 3);
}

static void trim(const char *text, char *buf, size_t len)
{
    while (*text == ' ' || *text == '\t')
        text++;
    snprintf(buf, len, "%s", text);
    size_t n = strlen(buf);
    while (n > 0 && (buf[n - 1] == ' ' || buf[n - 1] == '\t' || buf[n - 1] == '\n' || buf[n - 1] == '\r'))
        buf[--n] = '\0';
}

int adh_parse_quantity(const char *text, adh_quantity q, double *value, char *why, size_t whylen)
{
    if (q == ADH_Q_WORK)
        q = ADH_Q_ENERGY;
    char buf[128];
    if (!text || strlen(text) >= sizeof buf - 1) {
        if (why)
            snprintf(why, whylen, "value is missing or longer than %zu characters; expected %s",
                     sizeof buf - 2, quantity_name[q]);
        return ADH_EINVAL;
    }
    trim(text, buf, sizeof buf);
    /* strtod accepts "nan", "inf" and hex floats; none is a physical value here. */
    const char *c = buf;
    if (*c == '+' || *c == '-')
        c++;
    if (!((*c >= '0' && *c <= '9') || *c == '.') || strpbrk(buf, "xX")) {
        if (why)
            snprintf(why, whylen, "'%s' is not a number; expected %s", buf, quantity_name[q]);
        return ADH_EINVAL;
    }
    errno = 0;
    char *end;
    double v = strtod(buf, &end);
    if (end == buf) {
        if (why)
            snprintf(why, whylen, "'%s' is not a number; expected %s", buf, quantity_name[q]);
        return ADH_EINVAL;
    }
    while (*end == ' ')
        end++;
    double factor = 1.0;
    if (*end) {
        adh_quantity got;
        if (unit_of(end, &got, &factor) != 0) {
            if (why) {
                char hint[96];
                spelling_hint(end, q, hint, sizeof hint);
                snprintf(why, whylen, "'%s': unknown unit '%s'%s; expected %s", buf, end, hint, quantity_name[q]);
            }
            return ADH_EINVAL;
        }
        if (got != q) {
            if (why)
                snprintf(why, whylen, "'%s' is %s, but %s is wanted here", buf,
                         quantity_name[got], q == ADH_Q_NONE ? "a plain number" : quantity_name[q]);
            return ADH_EINVAL;
        }
    }
    /* a number past a double's range as written that its unit brings back
     * ('1e-310GPa' is 1e-301 Pa): read again wider and taken in SI, so that
     * the key's own range judges it (E: 1 kPa to 10 TPa), not the double's
     * least magnitude, which 1e-301 Pa is far above. Only there: every
     * other number is read as before, to the same digit. */
    if (errno == ERANGE && factor != 1.0) {
        long double wide = strtold(buf, NULL) * (long double)factor;
        if (fabsl(wide) >= DBL_MIN && fabsl(wide) <= DBL_MAX) {
            v = (double)wide;
            factor = 1.0;
            errno = 0;
        }
    }
    /* below a double's normal range (strtod's ERANGE for a tiny number, or
     * the unit's factor taking it there): it underflows, to 0 or to a
     * number that has lost its digits, which is no out-of-range overflow */
    int under = (errno == ERANGE && fabs(v) < 1) || (v != 0 && fabs(v * factor) < DBL_MIN);
    v *= factor;
    if (under) {
        if (why)
            /* the least magnitude offered is one that is accepted:
             * DBL_MIN to 3 digits rounds up (2.23e-308), to 2 it rounds
             * down to a number refused here (2.2e-308) */
            snprintf(why, whylen, "'%s' underflows%s (a double keeps no magnitude below %.2g%s%s): write 0 "
                     "for zero, or a magnitude of at least %.3g%s%s", buf, v == 0 ? " to zero" : "", DBL_MIN,
                     *unit_sym[q] ? " " : "", unit_sym[q], DBL_MIN, *unit_sym[q] ? " " : "", unit_sym[q]);
        return ADH_EINVAL;
    }
    if (!isfinite(v) || errno == ERANGE) {
        if (why)
            snprintf(why, whylen, "'%s' is out of the range of finite numbers", buf);
        return ADH_EINVAL;
    }
    *value = v;
    return ADH_SUCCESS;
}

int adh_parse_count(const char *text, long lo, long hi, long *value, char *why, size_t whylen)
{
    char buf[64];
    char range[96];
    if (hi == LONG_MAX)
        snprintf(range, sizeof range, "a whole number%s", lo > 0 ? " above 0" : "");
    else
        snprintf(range, sizeof range, "a whole number from %ld to %ld", lo, hi);
    if (!text || strlen(text) >= sizeof buf - 1) {
        if (why)
            snprintf(why, whylen, "expected %s", range);
        return ADH_EINVAL;
    }
    trim(text, buf, sizeof buf);
    errno = 0;
    char *end;
    long v = strtol(buf, &end, 10);
    if (end == buf || *end || errno == ERANGE || v < lo || v > hi) {
        if (why)
            snprintf(why, whylen, "'%s' is not allowed: expected %s", buf, range);
        return ADH_EINVAL;
    }
    *value = v;
    return ADH_SUCCESS;
}

void adh_format_quantity(double value, adh_quantity q, int digits, char *buf, size_t len)
{
    static const struct { const char *sym; double f; } pick[] = {
        { "T", 1e12 }, { "G", 1e9 }, { "M", 1e6 }, { "k", 1e3 }, { "", 1 },
        { "m", 1e-3 }, { "u", 1e-6 }, { "n", 1e-9 }, { "p", 1e-12 }, { "f", 1e-15 }, { "a", 1e-18 },
    };
    /* zero in the prefix its quantity is read in: "0 nm" beside "2.85 nm" */
    static const char *const zero_prefix[] = {
        [ADH_Q_NONE] = "", [ADH_Q_LENGTH] = "n", [ADH_Q_PRESSURE] = "", [ADH_Q_ENERGY] = "",
        [ADH_Q_SPEED] = "u", [ADH_Q_FORCE] = "n", [ADH_Q_TIME] = "", [ADH_Q_STIFFNESS] = "",
        [ADH_Q_WORK] = "f",
    };
    if (value == 0) {
        snprintf(buf, len, "0%s%s%s", q == ADH_Q_NONE ? "" : " ", zero_prefix[q], unit_sym[q]);
        return;
    }
    if (q == ADH_Q_NONE || !isfinite(value)) {
        snprintf(buf, len, "%.*g%s%s", digits, value, q == ADH_Q_NONE ? "" : " ", unit_sym[q]);
        return;
    }
    double a = fabs(value);
    size_t i = 0, n = sizeof pick / sizeof pick[0];
    while (i + 1 < n && a < pick[i].f * 0.9995)
        i++;
    /* past the prefixes' reach (1e-30 m, 1e15 Pa): SI with its exponent */
    if (a < pick[n - 1].f * 0.9995 || a >= pick[0].f * 999.5) {
        snprintf(buf, len, "%.*g %s", digits, value, unit_sym[q]);
        return;
    }
    /* Energies read better in plain J with an exponent (1e-19 J, not 100 zJ). */
    if (q == ADH_Q_ENERGY) {
        snprintf(buf, len, "%.*g J", digits, value);
        return;
    }
    snprintf(buf, len, "%.*g %s%s", digits, value / pick[i].f, pick[i].sym, unit_sym[q]);
}

const char *adh_format_shortest(double value, char *buf, size_t len)
{
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, len, "%.*g", digits, value);
        if (!isfinite(value) || strtod(buf, NULL) == value)
            break;
    }
    return buf;
}

adh_qtext_buf adh_qtext(double value, adh_quantity q)
{
    adh_qtext_buf t;
    adh_format_quantity(value, q, 4, t.s, sizeof t.s);
    return t;
}

adh_qtext_buf adh_qtext_arg(double value, adh_quantity q)
{
    adh_qtext_buf t = adh_qtext(value, q);
    char *sp = strchr(t.s, ' ');
    if (sp)
        memmove(sp, sp + 1, strlen(sp));
    return t;
}

int adh_quantity_is_bare(const char *text)
{
    for (const char *p = text; p && *p;) {
        char *end;
        strtod(p, &end);
        if (end == p)
            return 0;
        while (*end == ' ' || *end == '\t')
            end++;
        if (*end && *end != ',')
            return 0;
        p = *end == ',' ? end + 1 : end;
    }
    return 1;
}

/* One element of a list, blanks trimmed, into buf (cut at len). */
static void element(const char *seg, size_t n, char *buf, size_t len)
{
    while (n && (*seg == ' ' || *seg == '\t'))
        seg++, n--;
    while (n && (seg[n - 1] == ' ' || seg[n - 1] == '\t'))
        n--;
    if (n >= len)
        n = len - 1;
    memcpy(buf, seg, n);
    buf[n] = '\0';
}

int adh_list_decimal_comma(const char *text, adh_quantity q, char *why, size_t whylen)
{
    char a[64], b[64], joined[130];
    for (const char *seg = text, *comma; (comma = strchr(seg, ',')) != NULL; seg = comma + 1) {
        const char *next = strchr(comma + 1, ',');
        element(seg, (size_t)(comma - seg), a, sizeof a);
        element(comma + 1, next ? (size_t)(next - comma - 1) : strlen(comma + 1), b, sizeof b);
        const char *d = a + (*a == '+' || *a == '-');
        size_t digits = strspn(b, "0123456789");
        double v;
        /* a: a sign and digits alone (bare: SI); b: digits, then a unit */
        if (!*d || d[strspn(d, "0123456789")] || !digits || !b[digits] || b[digits] == '.' || b[digits] == 'e' ||
            b[digits] == 'E')
            continue;
        snprintf(joined, sizeof joined, "%s.%s", a, b);
        if (adh_parse_quantity(joined, q, &v, NULL, 0) != ADH_SUCCESS)
            continue;
        if (why)
            snprintf(why, whylen, "'%.200s' reads as two values, %s and %s: a decimal comma? write %s for one "
                     "value, or give each value its unit", text, a, b, joined);
        return ADH_EINVAL;
    }
    return ADH_SUCCESS;
}
