#include "adhere/units.h"
#include "scene/measured.h"
#include "scene/text.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_COLS 64
#define MAC_LINE_ENDS "a carriage return without a line feed (old Mac line ends): save the file with Unix (LF) or " \
                      "DOS (CRLF) line ends"

typedef struct unit { const char *sym; double f; } unit;
/* micro as "u", the micro sign U+00B5 and the Greek mu U+03BC */
static const unit lengths[] = { { "pm", 1e-12 }, { "nm", 1e-9 }, { "um", 1e-6 }, { "\xc2\xb5m", 1e-6 },
                                { "\xce\xbcm", 1e-6 }, { "mm", 1e-3 }, { "m", 1 } };
static const unit forces[] = { { "pN", 1e-12 }, { "nN", 1e-9 }, { "uN", 1e-6 }, { "\xc2\xb5N", 1e-6 },
                               { "\xce\xbcN", 1e-6 }, { "mN", 1e-3 }, { "N", 1 } };
#define NUNITS(u) (sizeof u / sizeof u[0])

const char *adh_measured_dir_name(int dir)
{
    return dir > 0 ? "approach" : "retract";
}

/* The unit a header name gives: inside [] or (), or after _ or /
 * ("h0[nm]", "Force (nN)", "force_pN", "h0/nm"). 0 when none of the list. */
static double unit_of(const char *name, const unit *u, size_t nu)
{
    const char *p = strrchr(name, '(');
    if (!p || (strrchr(name, '[') && strrchr(name, '[') > p))
        p = strrchr(name, '[');
    if (!p)
        p = strrchr(name, '_');
    if (!p)
        p = strrchr(name, '/');
    if (!p)
        return 0;
    char sym[16];
    size_t k = 0;
    for (p++; *p == ' '; p++)
        ;
    for (; *p && *p != ']' && *p != ')' && *p != ' ' && k + 1 < sizeof sym; p++)
        sym[k++] = *p;
    sym[k] = '\0';
    for (size_t i = 0; i < nu; i++)
        if (strcmp(sym, u[i].sym) == 0)
            return u[i].f;
    return 0;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r' || s[n - 1] == '\n'))
        s[--n] = '\0';
    return s;
}

/* The separator of a file, from its first line with content: a tab, a
 * comma, a semicolon, else blanks. */
static char separator_of(const char *line)
{
    return strchr(line, '\t') ? '\t' : strchr(line, ',') ? ',' : strchr(line, ';') ? ';' : ' ';
}

/* Splits line in place into fields. Blank-separated, a field that is a unit
 * alone ("(nm)", "[nN]") joins the name before it ("h0 (nm)"). Returns the
 * count, or MAX_COLS + 1 when there are more. */
static int split(char *line, char sep, char **f)
{
    int n = 0;
    if (sep != ' ') {
        for (char *p = line;; n++) {
            char *end = strchr(p, sep);
            if (n == MAX_COLS)
                return MAX_COLS + 1;
            if (end)
                *end = '\0';
            f[n] = trim(p);
            if (!end) {
                n++;
                break;
            }
            p = end + 1;
        }
        return n == 1 && !*f[0] ? 0 : n;
    }
    char *save = NULL;
    for (char *p = strtok_r(line, " \t,;\r\n", &save); p; p = strtok_r(NULL, " \t,;\r\n", &save)) {
        if (n > 0 && (*p == '(' || *p == '[') && !isdigit((unsigned char)p[1]) && p[1] != '-' && p[1] != '.') {
            f[n - 1][strlen(f[n - 1])] = ' ';   /* the blank strtok cut: the unit joins its name */
            continue;
        }
        if (n == MAX_COLS)
            return MAX_COLS + 1;
        f[n++] = p;
    }
    return n;
}

/* A number in field s: 0, or -1 with what it is instead in why ("is not
 * a number", "is too small for a double ..."). */
static int number(const char *s, double *v, char *why, size_t whylen)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    /* strtod reads hex floats (0x10 is 16): no instrument writes one, a
     * garbled field does; and it overflows to inf with ERANGE, which is
     * no gap in the measurement */
    if (end == s || *end || strpbrk(s, "xX"))
        snprintf(why, whylen, "is not a number");
    else if (!isfinite(*v) && errno != ERANGE)
        snprintf(why, whylen, "is not a finite number (a gap in the measurement?)");
    else if (errno == ERANGE || (*v != 0 && fabs(*v) < DBL_MIN))
        snprintf(why, whylen, fabs(*v) < 1 ? "is too small for a double (it underflows: magnitudes below 2.2e-308 "
                                             "are not kept); write 0 for zero"
                                           : "is too large for a double (above 1.8e308)");
    else
        return 0;
    return -1;
}

/* Whether line's numbers are written with decimal commas (a spreadsheet's
 * export in a comma-decimal locale: "1,5 -2,3", "1,5;-2,3"): every field
 * between blanks and semicolons a number once its one comma, between
 * digits, is a point, and one field at least has that comma. Then ex is the
 * hint that says so, quoting the first such field; else "". */
static void decimal_comma(const char *line, char *ex, size_t exlen)
{
    ex[0] = '\0';
    if (!strchr(line, ','))
        return;
    char first[48] = "", dotted[48] = "";
    for (const char *p = line; *p;) {
        size_t n = strcspn(p, " \t;\r\n");
        char buf[48], *end;
        if (n >= sizeof buf)
            return;
        memcpy(buf, p, n);
        buf[n] = '\0';
        char *c = strchr(buf, ',');
        if (c) {
            if (c == buf || !isdigit((unsigned char)c[-1]) || !isdigit((unsigned char)c[1]) || strchr(c + 1, ','))
                return;
            if (!first[0])
                memcpy(first, buf, n + 1);
            *c = '.';
            if (!dotted[0])
                memcpy(dotted, buf, n + 1);
        }
        if (n && (strtod(buf, &end), end == buf || *end || strpbrk(buf, "xX")))
            return;
        p += n;
        p += strspn(p, " \t;\r\n");
    }
    if (first[0])
        snprintf(ex, exlen, "; it looks like a decimal comma ('%s' for %s): write the numbers with a decimal point",
                 first, dotted);
}

/* why, with the hint ex (decimal_comma's) after it: -1. */
static int with_hint(const char *ex, char *why, size_t whylen)
{
    size_t n = strlen(why), k = strlen(ex);
    if (n + 1 >= whylen)
        return -1;
    k = k < whylen - n - 1 ? k : whylen - n - 1;   /* cut, as snprintf would */
    memcpy(why + n, ex, k);
    why[n + k] = '\0';
    return -1;
}

/* The name of a header field without its unit, lower case. */
static void bare_name(const char *field, char *out, size_t len)
{
    size_t k = 0;
    for (const char *p = field; *p && !strchr("[(_/", *p) && k + 1 < len; p++)
        out[k++] = (char)tolower((unsigned char)*p);
    while (k && out[k - 1] == ' ')
        k--;
    out[k] = '\0';
}

static int is_word(const char *name, const char *const *words)
{
    for (; *words; words++)
        if (strcmp(name, *words) == 0)
            return 1;
    return 0;
}

/* One column named by spec: a 1-based number or a header name (a unique
 * prefix will do). -1 with why when it names none or several. */
static int column_of(const char *spec, char **hdr, int nh, int ncols, char *why, size_t whylen)
{
    char *end;
    long k = strtol(spec, &end, 10);
    if (end != spec && !*end) {
        if (k < 1 || k > ncols) {
            snprintf(why, whylen, "column %.40s does not exist: the file has %d", spec, ncols);   /* as written: strtol clamps */
            return -1;
        }
        return (int)k - 1;
    }
    if (!nh) {
        snprintf(why, whylen, "column '%.40s' is named, but the file has no header: give its number", spec);
        return -1;
    }
    int found = -1, exact = -1, nfound = 0;
    char want[64], have[64];
    bare_name(spec, want, sizeof want);
    if (!*want) {   /* '' (--columns=1,) or a unit alone: a prefix of every name, "more than one column" */
        snprintf(why, whylen, "column '%.40s' names no column: give POS,FORCE, each a number from 1 or a header "
                 "name", spec);
        return -1;
    }
    for (int i = 0; i < nh; i++) {
        bare_name(hdr[i], have, sizeof have);
        if (strcmp(have, want) == 0)
            exact = i;
        if (strncmp(have, want, strlen(want)) == 0) {
            found = i;
            nfound++;
        }
    }
    if (exact >= 0)
        return exact;
    if (nfound != 1) {
        snprintf(why, whylen, "column '%.40s' %s", spec, nfound ? "names more than one column: give more of the name or its number"
                                                              : "is not in the header");
        return -1;
    }
    return found;
}

/* The position and force columns: from spec "POS,FORCE", the only two, or
 * the header's names. 0, or -1 with why. */
static int choose_columns(const char *spec, char **hdr, int nh, int ncols, int *cx, int *cy, char *why,
                          size_t whylen)
{
    if (spec && *spec) {
        char buf[256];
        snprintf(buf, sizeof buf, "%s", spec);
        char *comma = strchr(buf, ',');
        if (!comma || strchr(comma + 1, ',')) {
            snprintf(why, whylen, "--columns=%.60s: give two columns, POS,FORCE (numbers from 1 or header names)", spec);
            return -1;
        }
        *comma = '\0';
        if ((*cx = column_of(trim(buf), hdr, nh, ncols, why, whylen)) < 0 ||
            (*cy = column_of(trim(comma + 1), hdr, nh, ncols, why, whylen)) < 0)
            return -1;
        if (*cx == *cy) {
            snprintf(why, whylen, "--columns=%.60s names one column twice", spec);
            return -1;
        }
        return 0;
    }
    if (ncols == 2) {
        *cx = 0;
        *cy = 1;
        return 0;
    }
    static const char *const pos[] = { "h0", "h", "z", "x", "d", "position", "separation", "distance", "height",
                                       "displacement", "piezo", "tip-sample separation", "indentation", NULL };
    static const char *const force[] = { "f", "force", "load", "vdeflection", NULL };
    *cx = *cy = -1;
    int nx = 0, ny = 0;
    char name[64];
    for (int i = 0; i < nh; i++) {
        bare_name(hdr[i], name, sizeof name);
        if (is_word(name, pos)) {
            *cx = i;
            nx++;
        }
        if (is_word(name, force)) {
            *cy = i;
            ny++;
        }
    }
    if (nx == 1 && ny == 1)
        return 0;
    snprintf(why, whylen, "%d columns%s: say which are the position and the force with --columns=POS,FORCE "
             "(numbers from 1 or header names)", ncols, nh ? " and no single position and force name among them" : " and no header");
    return -1;
}

/* Appends a point, growing the arrays. 0 or -1 (out of memory). */
static int push(adh_measured *m, size_t *cap, double x, double y, size_t line)
{
    if (m->n == *cap) {
        size_t nc = *cap ? 2 * *cap : 256;
        double *a = realloc(m->h0, nc * sizeof *a);
        if (!a)
            return -1;
        m->h0 = a;
        double *b = realloc(m->F, nc * sizeof *b);
        if (!b)
            return -1;
        m->F = b;
        size_t *c = realloc(m->line, nc * sizeof *c);
        if (!c)
            return -1;
        m->line = c;
        *cap = nc;
    }
    m->h0[m->n] = x;
    m->F[m->n] = y;
    m->line[m->n] = line;
    m->n++;
    return 0;
}

/* Segments where the position turns. A position that repeats the one
 * before (a turn written twice) continues the segment it is in. A segment
 * of fewer than 3 points between turns is a position going back and
 * forth, not a segment: it is noted (nonmonotonic_line). 0, or -1 with why
 * for a file whose positions never change or turn too often. */
static int segments(adh_measured *m, char *why, size_t whylen)
{
    m->nseg = 0;
    size_t i = 0;
    while (i + 1 < m->n) {
        size_t k = i;
        while (k + 1 < m->n && m->h0[k + 1] == m->h0[i])
            k++;
        if (k + 1 == m->n) {   /* the rest repeats one position */
            if (m->nseg == 0) {
                snprintf(why, whylen, "%s:%zu: the position never changes (%s): a position column must", m->path,
                         m->line[m->n - 1], adh_qtext(m->h0[i], ADH_Q_LENGTH).s);
                return -1;
            }
            m->seg[m->nseg - 1].n = m->n - m->seg[m->nseg - 1].first;
            break;
        }
        int dir = m->h0[k + 1] < m->h0[k] ? 1 : -1;
        size_t j = k + 1;
        while (j + 1 < m->n && (m->h0[j + 1] - m->h0[j]) * (dir > 0 ? -1 : 1) >= 0)
            j++;
        size_t n = j - i + 1;
        if (m->nseg > 0 && n < 3 && j + 1 < m->n && !m->nonmonotonic_line)
            m->nonmonotonic_line = m->line[i + 1];
        if (m->nseg == ADH_MEASURED_MAX_SEGMENTS) {
            snprintf(why, whylen, "%s:%zu: more than %d segments (the position turns too often)", m->path,
                     m->line[i], ADH_MEASURED_MAX_SEGMENTS);
            return -1;
        }
        /* a segment shares its turning point with the next */
        m->seg[m->nseg++] = (adh_measured_segment){ .first = i, .n = n, .dir = dir };
        i = j;
        if (j + 1 == m->n)
            break;
    }
    return 0;
}

/* The header line: the column names, and the units of the chosen two. */
static int header(adh_measured *m, char **f, int nf, const char *columns, int *cx, int *cy, double *fx,
                  double *fy, size_t lineno, char *why, size_t whylen)
{
    char msg[512];
    if (choose_columns(columns, f, nf, nf, cx, cy, msg, sizeof msg) != 0) {
        snprintf(why, whylen, "%s:%zu: %s", m->path, lineno, msg);
        return -1;
    }
    *fx = unit_of(f[*cx], lengths, NUNITS(lengths));
    *fy = unit_of(f[*cy], forces, NUNITS(forces));
    if (*fx == 0 || *fy == 0) {
        snprintf(why, whylen, "%s:%zu: the header's '%.60s' does not name the %s unit: write e.g. 'h0 (nm)' "
                 "and 'F (nN)' (lengths pm nm um mm m, forces pN nN uN mN N; um or \xc2\xb5m)", m->path, lineno,
                 *fx == 0 ? f[*cx] : f[*cy], *fx == 0 ? "position's" : "force's");
        return -1;
    }
    snprintf(m->columns, sizeof m->columns, "%.70s, %.70s", f[*cx], f[*cy]);
    return 0;
}

/* One line: a header before any point, else a point. 0, or -1 with why. */
static int parse_line(adh_measured *m, char *line, size_t len, size_t lineno, const char *columns, char *sep,
                      int *ncols, int *cx, int *cy, double *fx, double *fy, size_t *cap, char *why, size_t whylen)
{
    if (memchr(line, '\0', len)) {
        snprintf(why, whylen, "%s:%zu: a NUL byte: this is not a text table (a binary file?)", m->path, lineno);
        return -1;
    }
    /* other control bytes (an escape sequence) would reach the terminal in
     * the refusals that quote a header word */
    for (size_t i = 0; i < len; i++) {
        unsigned char b = (unsigned char)line[i];
        /* a carriage return ends a line only before its line feed (DOS);
         * alone it is an old Mac line end, or one moving the terminal's
         * cursor back over a refusal that quotes it */
        if (b == '\r' && i + 1 < len && line[i + 1] != '\n') {
            snprintf(why, whylen, "%s:%zu: %s", m->path, lineno, MAC_LINE_ENDS);
            return -1;
        }
        if ((b < 0x20 && b != '\t' && b != '\r' && b != '\n') || b == 0x7f) {
            snprintf(why, whylen, "%s:%zu: the control byte 0x%02x: this is not a text table (a binary file?)",
                     m->path, lineno, b);
            return -1;
        }
    }
    char *hash = strchr(line, '#');
    if (hash)
        *hash = '\0';
    if (!*trim(line))
        return 0;
    /* quoted in a refusal, a Latin-1 byte (0xb5, the micro sign) reached the
     * terminal as it was, and 0x9b is a control (CSI) to some; comments may
     * keep theirs */
    const char *bad = adh_text_not_utf8(line);
    if (bad) {
        snprintf(why, whylen, "%s:%zu: the byte 0x%02x is not UTF-8 text (a Latin-1 or Windows-1252 export? µ is "
                 "0xb5 there): save the file as UTF-8, or write um for µm", m->path, lineno, (unsigned char)*bad);
        return -1;
    }
    if (!*sep)
        *sep = separator_of(line);
    char ex[256];   /* the hint of a decimal comma, for a refusal of this line */
    decimal_comma(line, ex, sizeof ex);
    char *f[MAX_COLS + 1], msg[256];
    int nf = split(line, *sep, f);
    if (nf == 0)
        return 0;
    if (nf > MAX_COLS) {
        snprintf(why, whylen, "%s:%zu: more than %d columns", m->path, lineno, MAX_COLS);
        return -1;
    }
    double v;
    int first_number = number(f[0], &v, msg, sizeof msg) == 0;
    if (!*ncols && !first_number && m->n == 0 && *ex) {   /* numbers, not a header's names */
        snprintf(why, whylen, "%s:%zu: '%.40s' %s", m->path, lineno, f[0], msg);
        return with_hint(ex, why, whylen);
    }
    if (!*ncols && !first_number && m->n == 0) {   /* the header */
        *ncols = nf;
        return header(m, f, nf, columns, cx, cy, fx, fy, lineno, why, whylen);
    }
    if (!*ncols) {   /* the first point, without a header: nm and nN */
        *ncols = nf;
        if (choose_columns(columns, NULL, 0, nf, cx, cy, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "%s:%zu: %s", m->path, lineno, msg);
            return with_hint(ex, why, whylen);
        }
    }
    if (nf != *ncols) {
        snprintf(why, whylen, "%s:%zu: %d column%s where the file has %d", m->path, lineno, nf, nf == 1 ? "" : "s",
                 *ncols);
        return with_hint(ex, why, whylen);
    }
    double x, y;
    for (int c = 0; c < 2; c++) {
        int col = c ? *cy : *cx;
        if (number(f[col], c ? &y : &x, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "%s:%zu: '%.40s' %s (column %d, the %s)", m->path, lineno, f[col], msg, col + 1,
                     c ? "force" : "position");
            return with_hint(ex, why, whylen);
        }
    }
    if (m->n == ADH_MEASURED_MAX_POINTS) {
        snprintf(why, whylen, "%s:%zu: more than a measured curve may hold (%d MiB, %d points): thin it (every k-th "
                 "point) or cut it to the range you compare", m->path, lineno, ADH_MEASURED_MAX_BYTES >> 20,
                 ADH_MEASURED_MAX_POINTS);
        return -1;
    }
    if (push(m, cap, x * *fx, y * *fy, lineno) != 0) {
        snprintf(why, whylen, "%s:%zu: out of memory", m->path, lineno);
        return -1;
    }
    return 0;
}

/* One line of f into buf (at most cap - 1 bytes, its newline kept): its
 * length, 0 at the end, -1 when longer than that (the rest is not read):
 * memory is bounded before a byte is read. A NUL byte is kept, and
 * counted. */
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
    free(m->line);
    m->h0 = m->F = NULL;
    m->line = NULL;
    m->n = m->nseg = 0;
}

/* path opened to read, without waiting: a named pipe no program writes
 * into held the open (and the run) for ever, where a replay script's is
 * refused at once; one with a writer (a shell's <(...)) is read as it
 * comes. NULL with errno, or with *idle set for the writerless pipe. */
static FILE *open_curve(const char *path, int *idle)
{
    *idle = 0;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC), first = EOF, e = 0;
    struct stat st;
    if (fd < 0)
        return NULL;
    if (fstat(fd, &st) == 0 && S_ISFIFO(st.st_mode)) {
        unsigned char b;
        ssize_t r = read(fd, &b, 1);   /* 0: no writer (EOF); -1, EAGAIN: a writer, nothing yet */
        if (r == 0) {
            close(fd);
            *idle = 1;
            return NULL;
        }
        if (r == 1)
            first = b;
    }
    FILE *f = fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) == 0 ? fdopen(fd, "r") : NULL;
    if (!f) {
        e = errno;
        close(fd);
        errno = e;
        return NULL;
    }
    if (first != EOF)
        ungetc(first, f);
    return f;
}

int adh_measured_load(const char *path, const char *columns, adh_measured *m, char *why, size_t whylen)
{
    memset(m, 0, sizeof *m);
    snprintf(m->path, sizeof m->path, "%s", path);
    const char *base = strrchr(path, '/');
    snprintf(m->name, sizeof m->name, "%s", base && base[1] ? base + 1 : path);
    int idle;
    FILE *f = open_curve(path, &idle);
    if (!f) {
        snprintf(why, whylen, "%s: cannot read the measured curve: %s", path,
                 idle ? "a pipe no program writes into" : strerror(errno));
        return -1;
    }
    double fx = 1e-9, fy = 1e-9;   /* nm, nN without a header */
    size_t cap = 0, lineno = 0, bytes = 0;
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > ADH_MEASURED_MAX_BYTES) {
        snprintf(why, whylen, "%s: %lld bytes, more than a measured curve may hold (%d MiB, %d points): thin it "
                 "(every k-th point) or cut it to the range you compare", path, (long long)st.st_size,
                 ADH_MEASURED_MAX_BYTES >> 20, ADH_MEASURED_MAX_POINTS);
        fclose(f);
        return -1;
    }
    int ncols = 0, cx = 0, cy = 1;
    char sep = 0, line[ADH_MEASURED_MAX_LINE + 2];
    long len;
    while ((len = read_line(f, line, sizeof line)) != 0) {
        lineno++;
        bytes += len < 0 ? sizeof line : (size_t)len;
        if (len < 0 && memchr(line, '\r', sizeof line - 1)) {   /* a whole file of them: one line */
            snprintf(why, whylen, "%s:%zu: %s", path, lineno, MAC_LINE_ENDS);
            goto bad;
        }
        if (len < 0 && memchr(line, '\0', sizeof line - 1)) {   /* a file of NULs is binary, not a long line */
            snprintf(why, whylen, "%s:%zu: a NUL byte: this is not a text table (a binary file?)", path, lineno);
            goto bad;
        }
        if (len < 0) {
            snprintf(why, whylen, "%s:%zu: line longer than %d bytes", path, lineno, ADH_MEASURED_MAX_LINE);
            goto bad;
        }
        if (bytes > ADH_MEASURED_MAX_BYTES) {   /* a pipe or a file that grew: fstat could not tell */
            snprintf(why, whylen, "%s:%zu: more than a measured curve may hold (%d MiB, %d points): thin it "
                     "(every k-th point) or cut it to the range you compare", path, lineno,
                     ADH_MEASURED_MAX_BYTES >> 20, ADH_MEASURED_MAX_POINTS);
            goto bad;
        }
        /* a UTF-8 byte-order mark (an editor's or a spreadsheet's export)
         * is no part of the first word */
        char *text = line;
        if (lineno == 1 && len >= 3 && !memcmp(line, "\xef\xbb\xbf", 3))
            text += 3, len -= 3;
        if (parse_line(m, text, (size_t)len, lineno, columns, &sep, &ncols, &cx, &cy, &fx, &fy, &cap, why,
                       whylen) != 0)
            goto bad;
    }
    if (ferror(f)) {
        snprintf(why, whylen, "%s:%zu: read error: %s", path, lineno, strerror(errno));
        goto bad;
    }
    if (m->n < 2 && !lineno) {   /* no line to name: "FILE:0:" named none */
        snprintf(why, whylen, "%s: the file is empty: a measured curve needs at least 2 points", path);
        goto bad;
    }
    if (m->n < 2) {
        snprintf(why, whylen, "%s:%zu: %zu point%s: a measured curve needs at least 2", path, lineno, m->n,
                 m->n == 1 ? "" : "s");
        goto bad;
    }
    if (segments(m, why, whylen) != 0)
        goto bad;
    fclose(f);
    return 0;
bad:
    fclose(f);
    adh_measured_free(m);
    return -1;
}
