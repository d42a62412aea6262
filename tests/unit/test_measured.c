/* --data as instruments write it (scene/measured.h): separators, headers
 * with spaces and units, columns by name or number, the segments. Each
 * file is written here and read back; the values are the file's numbers
 * times the units' factors, exactly as typed. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene/measured.h"
#include "tap.h"

static char path[64];

static int load(const char *text, const char *columns, adh_measured *m, char *why, size_t whylen)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return adh_measured_load(path, columns, m, why, whylen);
}

/* 0 when m holds n points, the first (x0, F0) and the last (x1, F1), in SI. */
static int holds(const adh_measured *m, size_t n, double x0, double F0, double x1, double F1)
{
    return m->n == n && fabs(m->h0[0] - x0) <= 1e-12 * fabs(x0) && fabs(m->F[0] - F0) <= 1e-12 * fabs(F0) &&
           fabs(m->h0[n - 1] - x1) <= 1e-12 * fabs(x1) && fabs(m->F[n - 1] - F1) <= 1e-12 * fabs(F1);
}

static void reads(const char *what, const char *text, const char *columns, size_t n, double x0, double F0, double x1,
                  double F1)
{
    adh_measured m;
    char why[512] = "";
    int rc = load(text, columns, &m, why, sizeof why);
    ok(rc == 0 && holds(&m, n, x0, F0, x1, F1), "%s (%s)", what, rc ? why : m.columns);
    if (rc == 0)
        adh_measured_free(&m);
}

int main(void)
{
    snprintf(path, sizeof path, "/tmp/adhere-test-measured-%ld.txt", (long)getpid());
    reads("no header: nm and nN", "3 -1\n2 -2\n", NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    reads("CSV with 'z (nm),F (nN)'", "z (nm),F (nN)\n3,-1\n2,-2\n", NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    reads("TSV with 'Separation (nm)<TAB>Force (nN)'", "Separation (nm)\tForce (nN)\n3\t-1\n2\t-2\n", NULL, 2, 3e-9,
          -1e-9, 2e-9, -2e-9);
    reads("blank-separated with the unit a word of its own: 'h0 (um)  F (pN)'", "h0 (um)  F (pN)\n0.003 -1000\n0.002 -2000\n",
          NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    reads("the micro sign: 'h0 (\xc2\xb5m)', 'F (\xc2\xb5N)'", "h0 (\xc2\xb5m),F (\xc2\xb5N)\n0.003,-0.001\n0.002,-0.002\n",
          NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    reads("the Greek mu: 'h0 (\xce\xbcm)'", "h0 (\xce\xbcm);F (nN)\n0.003;-1\n0.002;-2\n", NULL, 2, 3e-9, -1e-9, 2e-9,
          -2e-9);
    reads("metres and newtons: 'h0[m] F[N]'", "h0[m] F[N]\n3e-9 -1e-9\n2e-9 -2e-9\n", NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    /* a UTF-8 byte-order mark (a spreadsheet's export) before the header,
     * or before the first number: skipped, the file read as without it */
    reads("a byte-order mark before the header", "\xef\xbb\xbfh0 (um)\tF (pN)\n0.003\t-1000\n0.002\t-2000\n", NULL, 2,
          3e-9, -1e-9, 2e-9, -2e-9);
    reads("a byte-order mark before the first number", "\xef\xbb\xbf" "3 -1\n2 -2\n", NULL, 2, 3e-9, -1e-9, 2e-9, -2e-9);
    reads("a byte-order mark before the header, a column chosen by name", "\xef\xbb\xbf" "Force (nN),Separation (nm)\n-1,3\n-2,2\n",
          "Separation,Force", 2, 3e-9, -1e-9, 2e-9, -2e-9);
    const char *three = "# exported\nTime (s)\tForce (nN)\tSeparation (nm)\n0\t-1\t3\n0.1\t-2\t2\n0.2\t-3\t1\n";
    reads("three columns: the position and force found by name", three, NULL, 3, 3e-9, -1e-9, 1e-9, -3e-9);
    reads("three columns chosen by number (--columns=3,2)", three, "3,2", 3, 3e-9, -1e-9, 1e-9, -3e-9);
    reads("three columns chosen by name (--columns=Separation,Force)", three, "Separation,Force", 3, 3e-9, -1e-9, 1e-9,
          -3e-9);
    reads("three columns chosen by a prefix of the name (--columns=sep,for)", three, "sep,for", 3, 3e-9, -1e-9, 1e-9,
          -3e-9);

    adh_measured m;
    char why[512];
    int rc = load("h0 (nm)\tF (nN)\n3\t0\n2\t-1\n1\t-5\n2\t-6\n3\t-1\n4\t0\n3.5\t0\n3\t0\n2.5\t-0.5\n", NULL, &m, why,
                  sizeof why);
    ok(rc == 0 && m.nseg == 3 && m.seg[0].dir == 1 && m.seg[0].n == 3 && m.seg[1].dir == -1 && m.seg[1].n == 4 &&
       m.seg[2].dir == 1 && m.seg[2].n == 4 && !m.nonmonotonic_line,
       "approach, retract, approach: three segments by the position's direction, each turn shared");
    if (rc == 0)
        adh_measured_free(&m);
    rc = load("h0 (nm)\tF (nN)\n5\t0\n4\t0\n4.5\t0\n3\t0\n2\t0\n1\t0\n", NULL, &m, why, sizeof why);
    ok(rc == 0 && m.nonmonotonic_line == 4, "a position going back for two points is noted, line %zu", rc ? 0 : m.nonmonotonic_line);
    if (rc == 0)
        adh_measured_free(&m);
    rc = load("h0 (nm)\tF (nN)\n5\t0\n4\t0\n3\t1\n3\t2\n4\t0\n5\t0\n", NULL, &m, why, sizeof why);
    ok(rc == 0 && m.nseg == 2 && m.seg[0].n == 4 && m.seg[1].first == 3 && m.seg[1].n == 3 && !m.nonmonotonic_line,
       "a turn written twice: two segments, the second writing the retract's first point (%s)", rc ? why : "ok");
    if (rc == 0)
        adh_measured_free(&m);
    rc = load("h0 (nm)\tF (nN)\n5\t0\n5\t1\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":3: the position never changes"), "a position that never changes: refused (%s)", why);
    rc = load("1\t2\t3\n4\t5\n", "1,2", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":2: 2 columns where the file has 3"), "a short line: refused (%s)", why);
    rc = load("h0 (nm),F (nN),t (s)\n1,2,3\n", "4,2", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "column 4 does not exist: the file has 3"), "a column beyond the file: refused (%s)", why);
    /* past a long's range: it named strtol's clamp, 9223372036854775807, a number never written */
    rc = load("h0 (nm),F (nN),t (s)\n1,2,3\n", "99999999999999999999,2", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "column 99999999999999999999 does not exist: the file has 3"),
       "a column number past a long's range: refused, quoted as written (%s)", why);
    rc = load("1,2,3\n2,3,4\n", "h0,F", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "the file has no header: give its number"), "a name without a header: refused (%s)", why);
    rc = load("Separation (nm),Sep2 (nm),F (nN)\n1,2,3\n", "sep,F", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "names more than one column"), "an ambiguous prefix: refused (%s)", why);
    /* a Latin-1 header (0xb5, the micro sign) was quoted byte for byte in
     * the refusal, as was a C1 control (0x9b, CSI to some terminals) in a
     * number; a comment may keep its Latin-1 */
    rc = load("h0 (\xb5m)\tF (nN)\n5\t-1\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":1: the byte 0xb5 is not UTF-8 text") && !strstr(why, "(\xb5m"),
       "a Latin-1 micro sign in the header: refused as not UTF-8, the byte not quoted (%s)", why);
    rc = load("h0 (nm)\tF (nN)\n5\t-1\x9b\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":2: the byte 0x9b is not UTF-8 text") && !strchr(why, '\x9b'),
       "a C1 control in a number: refused, the byte not quoted (%s)", why);
    rc = load("# 25 \xb0" "C\nh0 (\xc2\xb5m)\tF (nN)\n0.005\t-1\n0.004\t-2\n", NULL, &m, why, sizeof why);
    ok(rc == 0, "a Latin-1 comment and a UTF-8 micro sign: read (%s)", rc ? why : "ok");
    if (rc == 0)
        adh_measured_free(&m);
    /* an empty name (--columns=1,) or a unit alone is a prefix of every
     * name: it was refused as naming "more than one column" */
    rc = load("Separation (nm),F (nN)\n1,2\n", "1,", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "column '' names no column"), "an empty column name: refused as naming none (%s)", why);
    rc = load("Separation (nm),F (nN)\n1,2\n", "1,(nN)", &m, why, sizeof why);
    ok(rc != 0 && strstr(why, "column '(nN)' names no column"), "a unit alone: refused as naming none (%s)", why);
    /* old Mac line ends (a carriage return alone): the file is one line,
     * refused as a comment of 0 points or a line over 4096 bytes; and a
     * carriage return inside a line, quoted, moved the terminal's cursor
     * back over the message */
    rc = load("# a comment\rh0 (nm)\tF (nN)\r5\t-1\r4\t-2\r", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":1: a carriage return without a line feed (old Mac line ends)") && !strchr(why, '\r'),
       "old Mac line ends: refused as such (%s)", why);
    char big[8192];
    size_t bl = 0;
    bl += (size_t)snprintf(big, sizeof big, "h0 (nm)\tF (nN)\r");
    for (int i = 0; i < 600; i++)
        bl += (size_t)snprintf(big + bl, sizeof big - bl, "%d\t-1\r", 600 - i);
    rc = load(big, NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":1: a carriage return without a line feed (old Mac line ends)"),
       "old Mac line ends past 4096 bytes: refused as such, not as a long line (%s)", why);
    rc = load("h0 \r(nm)\tF (nN)\r\n5\t-1\r\n4\t-2\r\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":1: a carriage return without a line feed") && !strchr(why, '\r'),
       "a carriage return inside a line: refused, not quoted (%s)", why);
    /* a value too large for a double is an overflow, not a gap (strtod
     * gives inf and ERANGE, and the test for a gap came first); a hex
     * float (strtod reads 0x10 as 16) is no instrument's number, refused
     * as the units' parser refuses it */
    rc = load("h0 (nm)\tF (nN)\n5\t1e400\n4\t-2\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":2: '1e400' is too large for a double") && !strstr(why, "gap"),
       "1e400: refused as too large, not as a gap (%s)", why);
    rc = load("h0 (nm)\tF (nN)\n5\t0x10\n4\t-2\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":2: '0x10' is not a number"), "a hex float, 0x10: refused, not read as 16 (%s)", why);
    rc = load("h0 (nm)\tF (nN)\n0X1p2\t1\n4\t-2\n", NULL, &m, why, sizeof why);
    ok(rc != 0 && strstr(why, ":2: '0X1p2' is not a number"), "a hex float, 0X1p2: refused, not read as 4 (%s)", why);
    rc = load("h0 (nm)\tF (nN)\r\n5\t-1\r\n4\t-2\r", NULL, &m, why, sizeof why);
    ok(rc == 0 && m.n == 2, "DOS line ends, the last line's without its line feed: read (%s)", rc ? why : "ok");
    if (rc == 0)
        adh_measured_free(&m);
    /* a named pipe no program writes into: refused at once, not waited on
     * (the open held the run for ever); alarm: a hang fails the test */
    char fifo[80];
    snprintf(fifo, sizeof fifo, "/tmp/adhere-test-measured-fifo-%ld", (long)getpid());
    if (mkfifo(fifo, 0600) == 0) {
        alarm(20);
        rc = adh_measured_load(fifo, NULL, &m, why, sizeof why);
        alarm(0);
        ok(rc != 0 && strstr(why, "a pipe no program writes into"), "a pipe no program writes into: refused at once (%s)",
           why);
        unlink(fifo);
    } else {
        ok(0, "mkfifo %s", fifo);
    }
    unlink(path);
    return tap_done();
}
