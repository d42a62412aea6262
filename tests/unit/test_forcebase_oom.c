/* force-base.png when memory runs out (SQLite style: every allocation of
 * forcebase.c fails once, in turn): each says "out of memory", never "no
 * curve to draw" (the figure's point indices, allocated once the curves
 * are built, said that), and nothing is half-drawn (gnuplot is not reached:
 * this session has none); and when its data file cannot be written or its
 * command's memory stream not opened. forcebase.c is compiled here with
 * its malloc, calloc, realloc, fclose and open_memstream counted. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static long calls, fail_at = -1;

static int fails(void)
{
    return ++calls == fail_at;
}
static void *count_malloc(size_t n)
{
    return fails() ? NULL : malloc(n);
}
static void *count_calloc(size_t n, size_t sz)
{
    return fails() ? NULL : calloc(n, sz);
}
static void *count_realloc(void *p, size_t n)
{
    return fails() ? NULL : realloc(p, n);
}
/* and its files: the fclose_fail_at-th fclose fails with ENOSPC (a full
 * disk, reported at the flush), open_memstream with ENOMEM when asked */
static long fcloses, fclose_fail_at = -1;
static int fclose_errno = ENOSPC;   /* 0: a failure that leaves errno unset */
static int memstream_fails;
static int count_fclose(FILE *f)
{
    int rc = fclose(f);
    if (++fcloses == fclose_fail_at) {
        errno = fclose_errno;
        return EOF;
    }
    return rc;
}
static FILE *count_memstream(char **buf, size_t *len)
{
    if (memstream_fails) {
        errno = ENOMEM;
        return NULL;
    }
    return open_memstream(buf, len);
}
#define malloc count_malloc
#define calloc count_calloc
#define realloc count_realloc
#define fclose count_fclose
#define open_memstream count_memstream
#include "plot/forcebase.c"   /* in place of libadhere-plot.a's */
#undef malloc
#undef calloc
#undef realloc
#undef fclose
#undef open_memstream

#include "tap.h"

/* A run in physical time through k = 10 N/m: an approach with a snap-in
 * (two rows at one time), a retraction with a snap-out. */
static void timed_run(adh_run *run)
{
    adh_run_init(run);
    const double k = 10;
    double h0[] = { 10e-9, 6e-9, 4e-9, 2e-9, 1e-9, 2e-9, 5e-9, 8e-9, 20e-9 };
    double F[] = { -1e-9, -3e-9, -8e-9, -40e-9, 20e-9, -60e-9, -90e-9, -100e-9, -1e-9 };
    int path[] = { 0, 0, 0, 0, 0, 1, 1, 1, 1 };
    double t[] = { 0, 1, 2, 3, 3, 4, 5, 6, 6 };
    for (size_t i = 0; i < sizeof h0 / sizeof h0[0]; i++) {
        adh_obs o;
        memset(&o, 0, sizeof o);
        o.h0 = h0[i], o.F = F[i], o.path = path[i], o.t = t[i];
        o.branch = path[i] ? -1 : 1;
        o.base = h0[i] - F[i] / k;
        adh_run_push_row(run, &o);
    }
    run->turns[0].h0 = 1e-9;
    run->turns[0].path = 1;
    run->nturns = 1;
}

/* A static curve under the same spring: its base h0 - F/k falls, turns
 * back at 6.5 nm (the snap-in's fold), rises to 7.5 nm and falls again. */
static void static_curve(adh_run *run)
{
    adh_run_init(run);
    double h0[] = { 10e-9, 8e-9, 6e-9, 5e-9, 4e-9, 3e-9, 2e-9, 1e-9 };
    double F[] = { -1e-9, -2e-9, -5e-9, -20e-9, -35e-9, -30e-9, -10e-9, 20e-9 };
    for (size_t i = 0; i < sizeof h0 / sizeof h0[0]; i++) {
        adh_obs o;
        memset(&o, 0, sizeof o);
        o.h0 = o.base = h0[i], o.F = F[i], o.branch = 1, o.stable = 1, o.t = NAN;
        adh_run_push_row(run, &o);
    }
}

/* Every allocation of run's figure failing in turn (those before its data
 * file counted first, its directory missing, plus the point indices after
 * it): each says out of memory. */
static void sweep(const char *what, const adh_plot_setup *s, const adh_run *run, const char *dir)
{
    adh_session ses;
    memset(&ses, 0, sizeof ses);
    char why[512];
    snprintf(ses.tmpdir, sizeof ses.tmpdir, "%s/none", dir);
    calls = 0, fail_at = -1;
    int rc = adh_forcebase_figure(&ses, s, run, "t", why, sizeof why);
    long before = calls;
    ok(rc == -1 && strstr(why, "cannot write") && before > 3,
       "%s without a directory for its data: cannot write it (%s), after %ld allocations", what, why, before);
    snprintf(ses.tmpdir, sizeof ses.tmpdir, "%s", dir);
    int all_oom = 1;
    for (long k = 1; k <= before + 1; k++) {
        calls = 0, fail_at = k;
        ses.nmade = 0;
        why[0] = '\0';
        rc = adh_forcebase_figure(&ses, s, run, "t", why, sizeof why);
        if (rc != -1 || strcmp(why, "out of memory") != 0) {
            all_oom = 0;
            printf("# allocation %ld failing: %d, '%s'\n", k, rc, why);
        }
    }
    ok(all_oom && calls == before + 1,
       "%s: each of its %ld allocations failing in turn says out of memory (the last, the figure's point "
       "indices, made last before gnuplot, said there was no curve to draw)", what, before + 1);
}

/* A write that fails (the data file's fclose, ENOSPC) is said with its
 * reason, also where there is no curve to draw (a run of one row: said so
 * without the fault, where the fault was hidden); an open_memstream that
 * fails says out of memory before the figure is begun (it was begun and
 * never ended: gnuplot left with its output open, the image unchecked). */
static void io_faults(const adh_plot_setup *s, const adh_run *run, const char *what, const char *dir)
{
    adh_session ses;
    memset(&ses, 0, sizeof ses);
    snprintf(ses.tmpdir, sizeof ses.tmpdir, "%s", dir);
    char why[512] = "";
    calls = 0, fail_at = -1, fcloses = 0, fclose_fail_at = 1;
    int rc = adh_forcebase_figure(&ses, s, run, "t", why, sizeof why);
    ok(rc == -1 && strstr(why, "cannot write ") && strstr(why, "forcebase.dat: No space left on device"),
       "%s, its data file's fclose failing: \"%s\"", what, why);
    /* a failure with errno unset is still one (EIO), never drawn from */
    fcloses = 0, fclose_fail_at = 1, fclose_errno = 0, errno = 0;
    rc = adh_forcebase_figure(&ses, s, run, "t", why, sizeof why);
    fclose_errno = ENOSPC;
    ok(rc == -1 && strstr(why, "forcebase.dat: Input/output error"),
       "%s, its data file's fclose failing with errno unset: \"%s\"", what, why);
    fclose_fail_at = -1, memstream_fails = 1, ses.nmade = 0;
    why[0] = '\0';
    rc = adh_forcebase_figure(&ses, s, run, "t", why, sizeof why);
    memstream_fails = 0;
    int begun = 0;   /* the session's record of the image a begun figure makes */
    for (size_t i = 0; i < ses.nmade; i++)
        begun |= strcmp(ses.made[i], "force-base.png") == 0;
    ok(rc == -1 && strcmp(why, "out of memory") == 0 && !begun,
       "%s, open_memstream failing: \"%s\", no figure begun (%d)", what, why, begun);
}

static void empty_faults(const adh_plot_setup *s, const char *dir)
{
    adh_run run;
    adh_run_init(&run);
    adh_obs o;
    memset(&o, 0, sizeof o);
    o.h0 = o.base = 10e-9, o.F = -1e-9, o.branch = 1, o.stable = 1, o.t = NAN;
    adh_run_push_row(&run, &o);
    adh_session ses;
    memset(&ses, 0, sizeof ses);
    snprintf(ses.tmpdir, sizeof ses.tmpdir, "%s", dir);
    char why[512] = "";
    calls = 0, fail_at = -1, fcloses = 0, fclose_fail_at = -1;
    int rc = adh_forcebase_figure(&ses, s, &run, "t", why, sizeof why);
    ok(rc == -1 && strcmp(why, "no curve to draw") == 0, "a static curve of one row: \"%s\"", why);
    fcloses = 0, fclose_fail_at = 1;
    rc = adh_forcebase_figure(&ses, s, &run, "t", why, sizeof why);
    fclose_fail_at = -1;
    ok(rc == -1 && strstr(why, "forcebase.dat: No space left on device"),
       "... its data file's fclose failing: the write error, not no curve (\"%s\")", why);
    adh_run_free(&run);
}

int main(void)
{
    char dir[] = "/tmp/adhere-fb-oom-XXXXXX";
    if (!mkdtemp(dir)) {
        printf("Bail out! no temporary directory\n");
        return 1;
    }
    adh_plot_setup s;
    memset(&s, 0, sizeof s);
    s.sprung = 1, s.spring = 10;
    adh_run run;
    s.timed = 1;
    timed_run(&run);
    sweep("physical time", &s, &run, dir);
    io_faults(&s, &run, "physical time", dir);
    adh_run_free(&run);
    s.timed = 0, s.equilibrium = 1;
    static_curve(&run);
    sweep("the static curve", &s, &run, dir);
    io_faults(&s, &run, "the static curve", dir);
    adh_run_free(&run);
    empty_faults(&s, dir);

    char dat[PATH_MAX + 32];
    snprintf(dat, sizeof dat, "%s/forcebase.dat", dir);
    unlink(dat);
    rmdir(dir);
    return tap_done();
}
