/* The manifest at a study's scale: an output directory whose manifest lists
 * 10^5 run-K directories opens (its manifest is adhere's, not a foreign
 * file for being large), and a name is found in it in the time it takes
 * among 10^3: the lookups (adh_outdir_has, and every run-K a study adds)
 * go through an index, not along the list, and a manifest naming one
 * run-K 10^5 times opens as fast. Timed as a ratio against the small
 * directory in this process (best of 5 each), never in seconds. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "plot/outdir.h"
#include "tap.h"

#define REAL 100         /* run-K directories made on disk in each */
#define LISTED 100000    /* run-K the large manifest lists (a study's most) */

static char work[256];

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* dir with run-1..run-REAL (made the first time) and a manifest listing
 * them and, up to listed, run-K that are not there (their records as a
 * study leaves them: device, inode, "-" for a directory). 0, or -1. */
static int make_dir(const char *dir, size_t listed, int one_name)
{
    char path[512];
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return -1;
    snprintf(path, sizeof path, "%s/" ADH_OUTDIR_MANIFEST, dir);
    FILE *m = fopen(path, "w");
    if (!m)
        return -1;
    fputs("# adhere: the files it wrote in this directory\n", m);
    struct stat st;
    if (stat(dir, &st) != 0)
        return -1;
    /* the others first: a walk along the list passes them all */
    for (size_t k = REAL + 1; k <= listed; k++)
        fprintf(m, "run-%zu/\t%llu\t%llu\t-\t-\t-\n", one_name ? 1 : k, (unsigned long long)st.st_dev,
                1000000000000ULL + k);
    for (size_t k = 1; k <= REAL; k++) {
        snprintf(path, sizeof path, "%s/run-%zu", dir, k);
        if ((mkdir(path, 0777) != 0 && errno != EEXIST) || stat(path, &st) != 0)
            break;
        fprintf(m, "run-%zu/\t%llu\t%llu\t-\t-\t-\n", k, (unsigned long long)st.st_dev, (unsigned long long)st.st_ino);
    }
    return fclose(m) == 0 ? 0 : -1;
}

/* Seconds to look up every real run-K in d ten times (the best of 5);
 * *found how many were found in a pass. */
static double lookups(const adh_outdir *d, size_t *found)
{
    double best = 1e30;
    for (int rep = 0; rep < 5; rep++) {
        size_t n = 0;
        double t0 = now();
        for (size_t k = 1; k <= 10 * REAL; k++) {
            char name[32];
            snprintf(name, sizeof name, "run-%zu", (k - 1) % REAL + 1);
            n += adh_outdir_has(d, name) != 0;
        }
        double t = now() - t0;
        best = t < best ? t : best;
        *found = n / 10;
    }
    return best;
}

int main(void)
{
    snprintf(work, sizeof work, "/tmp/adhere-test-manifest-XXXXXX");
    if (!mkdtemp(work)) {
        perror("mkdtemp");
        return 1;
    }
    char dir[300], why[1024] = "";
    snprintf(dir, sizeof dir, "%s/study", work);
    /* the same run-K directories, listed first alone, then among LISTED */
    ok(make_dir(dir, REAL, 0) == 0, "%d run-K directories, a manifest of them", REAL);
    double t0 = now();
    adh_outdir *d = adh_outdir_open(dir, ADH_OUTDIR_KEEP, why, sizeof why);
    double t_small_open = now() - t0;
    size_t fs = 0, fb = 0;
    double ts = d ? lookups(d, &fs) : NAN;
    ok(d != NULL && fs == REAL, "it opens, every run-K found (%zu of %d; %s)", fs, REAL, d ? "kept" : why);
    adh_outdir_close(d);
    ok(make_dir(dir, LISTED, 0) == 0, "the manifest made to list %d run-K", LISTED);
    t0 = now();
    d = adh_outdir_open(dir, ADH_OUTDIR_KEEP, why, sizeof why);
    double t_big_open = now() - t0;
    ok(d != NULL, "it opens, its own (%s; %.3f s against %.3f s)", d ? "kept" : why, t_big_open, t_small_open);
    if (d) {
        double tb = lookups(d, &fb);
        ok(fb == REAL, "every run-K is found among them (%zu of %d)", fb, REAL);
        /* along the list the large one costs some 1000 times the small one */
        ok(tb < 4 * ts, "%d lookups among %d entries take %.2f times those among %d (%.5f s, %.5f s): an index, "
           "not a walk along the list", 10 * REAL, LISTED, tb / ts, REAL, tb, ts);
        adh_outdir *s = adh_outdir_sub(d, "run-100001", why, sizeof why);
        ok(s != NULL && adh_outdir_has(d, "run-100001"), "a run-K added to it is found in it (%s)", s ? "yes" : why);
        adh_outdir_close(s);
    }
    adh_outdir_close(d);
    /* a manifest whose lines (corrupted, or another's making) all name
     * run-1: its entries chained under the one name, not probed past one
     * another (their square: seconds at 10^5) */
    char added[400];   /* the run-K added above goes */
    snprintf(added, sizeof added, "%s/run-100001/" ADH_OUTDIR_MANIFEST, dir);
    unlink(added);
    *strrchr(added, '/') = '\0';
    rmdir(added);
    ok(make_dir(dir, LISTED, 1) == 0, "the manifest made to list run-1 %d times", LISTED);
    double t_dup_open = 1e30;   /* the best of 3: a loaded machine's pause is not the index's */
    d = NULL;
    for (int rep = 0; rep < 3; rep++) {
        adh_outdir_close(d);
        t0 = now();
        d = adh_outdir_open(dir, ADH_OUTDIR_KEEP, why, sizeof why);
        t_dup_open = fmin(t_dup_open, now() - t0);
    }
    ok(d != NULL && adh_outdir_has(d, "run-1") && adh_outdir_has(d, "run-100"), "it opens, run-1 and run-100 found (%s)",
       d ? "kept" : why);
    ok(t_dup_open < 4 * t_big_open, "it opens in %.2f times the time of %d names once each (%.3f s, %.3f s)",
       t_dup_open / t_big_open, LISTED, t_dup_open, t_big_open);
    adh_outdir_close(d);
    tap_remove_dir(work);
    return tap_done();
}
