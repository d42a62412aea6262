/* What may stand under a final name in an output directory: adh_png_check
 * takes a whole PNG and nothing less (every cut of one, a text file, data
 * after IEND), and adh_outdir_owns / adh_outdir_clear know adhere's own
 * files from the user's. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plot/outdir.h"
#include "plot/png.h"
#include "tap.h"

static char work[256];

static void put_file(const char *path, const unsigned char *b, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(b, 1, n, f);
        fclose(f);
    }
}

static size_t chunk(unsigned char *out, const char *type, size_t len)
{
    out[0] = (unsigned char)(len >> 24);
    out[1] = (unsigned char)(len >> 16);
    out[2] = (unsigned char)(len >> 8);
    out[3] = (unsigned char)len;
    memcpy(out + 4, type, 4);
    memset(out + 8, 0x5a, len);
    /* the CRC is not checked; IEND's is the real one */
    static const unsigned char iend_crc[4] = { 0xae, 0x42, 0x60, 0x82 };
    memcpy(out + 8 + len, strcmp(type, "IEND") == 0 ? iend_crc : (const unsigned char *)"\1\2\3\4", 4);
    return 12 + len;
}

static void test_png_check(void)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    unsigned char png[256];
    size_t n = 0;
    memcpy(png, sig, 8);
    n = 8;
    n += chunk(png + n, "IHDR", 13);
    n += chunk(png + n, "IDAT", 40);
    n += chunk(png + n, "IDAT", 7);
    n += chunk(png + n, "IEND", 0);
    char path[300], why[200];
    snprintf(path, sizeof path, "%s/x.png", work);
    put_file(path, png, n);
    ok(adh_png_check(path, why, sizeof why) == 0, "a whole PNG (%zu bytes) passes", n);
    size_t cut_ok = 0;
    for (size_t k = 0; k < n; k++) {
        put_file(path, png, k);
        cut_ok += adh_png_check(path, why, sizeof why) != 0;
    }
    ok(cut_ok == n, "every one of its %zu cuts is refused (%zu were)", n, cut_ok);
    put_file(path, png, n - 5);
    adh_png_check(path, why, sizeof why);
    ok(strstr(why, "cut short") != NULL, "a cut inside IEND says: %s", why);
    put_file(path, png, n - 20);
    adh_png_check(path, why, sizeof why);
    ok(strstr(why, "cut short") != NULL, "a cut before IEND says: %s", why);
    unsigned char more[300];
    memcpy(more, png, n);
    memcpy(more + n, "junk", 4);
    put_file(path, more, n + 4);
    ok(adh_png_check(path, why, sizeof why) != 0 && strstr(why, "after"), "data after IEND is refused: %s", why);
    const char text[] = "    force F (uN)\n  0.2 |-+   ***\n";
    put_file(path, (const unsigned char *)text, sizeof text - 1);
    ok(adh_png_check(path, why, sizeof why) != 0 && strstr(why, "not a PNG"),
       "a text file (a dumb terminal's plot) is refused: %s", why);
    memcpy(more, png, n);
    memcpy(more + 12, "IDAT", 4);
    put_file(path, more, n);
    ok(adh_png_check(path, why, sizeof why) != 0, "a PNG without IHDR first is refused: %s", why);
    snprintf(path, sizeof path, "%s/missing.png", work);
    ok(adh_png_check(path, why, sizeof why) != 0, "a missing file is refused: %s", why);
}

static void test_owns(void)
{
    static const char *const mine[] = {
        "force.tsv", "summary.tsv", "turns.tsv", "static.tsv", "profiles.tsv", "contact.tsv", "sweep.tsv",
        "cost.tsv", "force.png", "profile.png", "contact.png", "precontact.png", "bulge.png", "jump.png",
        "cost.png", "gnuplot.log", "gnuplot-figures.log", ".force.png.tmp123", ".summary.tsv.4242.tmp",
        ".cost.png.77.tmp", ".cost-plot.77.dat",
    };
    static const char *const theirs[] = {
        "notes.txt", "force.tsv.bak", "Force.tsv", "force.tsv~", ".force.png.tmp", ".force.png.tmpX1",
        ".summary.tsv.tmp", ".summary.tsv.12a.tmp", ".cost-plot.dat", "run-1", "my.png", ".force.tsv",
        "gnuplot.log.old",
    };
    size_t a = 0, b = 0;
    for (size_t i = 0; i < sizeof mine / sizeof mine[0]; i++)
        if (adh_outdir_owns(mine[i]))
            a++;
        else
            ok(0, "%s is adhere's", mine[i]);
    for (size_t i = 0; i < sizeof theirs / sizeof theirs[0]; i++)
        if (!adh_outdir_owns(theirs[i]))
            b++;
        else
            ok(0, "%s is the user's", theirs[i]);
    ok(a == sizeof mine / sizeof mine[0], "every name adhere writes, and its temporaries, are adhere's");
    ok(b == sizeof theirs / sizeof theirs[0], "look-alike names are the user's");

    char d[300], p[400];
    snprintf(d, sizeof d, "%s/out", work);
    mkdir(d, 0755);
    const char *files[] = { "force.tsv", "force.png", "notes.txt", "run-2/summary.tsv", "run-5/summary.tsv",
                            "run-5/mine.txt", "keep/force.tsv" };
    snprintf(p, sizeof p, "%s/run-2", d), mkdir(p, 0755);
    snprintf(p, sizeof p, "%s/run-5", d), mkdir(p, 0755);
    snprintf(p, sizeof p, "%s/keep", d), mkdir(p, 0755);
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", d, files[i]);
        put_file(p, (const unsigned char *)"x", 1);
    }
    char why[300];
    ok(adh_outdir_clear(d, why, sizeof why) == 0, "clearing a directory succeeds");
    int gone = 0, kept = 0;
    struct stat st;
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", d, files[i]);
        int there = stat(p, &st) == 0;
        int should = !strcmp(files[i], "notes.txt") || !strcmp(files[i], "run-5/mine.txt") ||
                     !strcmp(files[i], "keep/force.tsv");
        gone += !there && !should;
        kept += there && should;
    }
    ok(gone == 4 && kept == 3, "adhere's files go (%d of 4), the user's stay (%d of 3), also "
       "in a directory not named run-K", gone, kept);
    snprintf(p, sizeof p, "%s/run-2", d);
    ok(stat(p, &st) != 0, "an emptied run-K directory goes");
    snprintf(p, sizeof p, "%s/nonexistent", work);
    ok(adh_outdir_clear(p, why, sizeof why) == 0, "a directory that does not exist is empty");
}

int main(void)
{
    snprintf(work, sizeof work, "/tmp/adhere-test-outfiles-XXXXXX");
    if (!mkdtemp(work)) {
        perror("mkdtemp");
        return 1;
    }
    test_png_check();
    test_owns();
    if (!tap_failed) {
        char cmd[400];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", work);
        if (system(cmd) != 0)
            printf("# could not remove %s\n", work);
    }
    return tap_done();
}
