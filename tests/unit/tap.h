/* A minimal TAP producer for the C tests: one "ok N - what" line per check,
 * "ok N # SKIP why" for a check that could not run (tests/run-all.sh counts
 * skips apart; with CI=true a skip fails the run), the plan at the end, exit
 * status 1 when anything failed. */
#ifndef ADH_TAP_H
#define ADH_TAP_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int tap_n, tap_failed;

/* A test program lives in BUILD/tests, where no share/adhere sits beside
 * it: it reads the tree's shipped scenes and styles (the Makefile passes
 * their path) unless $ADHERE_DATADIR already says where. */
#ifdef ADH_TEST_DATADIR
__attribute__((constructor)) static void tap_datadir(void)
{
    setenv("ADHERE_DATADIR", ADH_TEST_DATADIR, 0);
}
#endif

/* The library runs as adhere runs it: one BLAS thread per run (src/cli/
 * main.c says why; idle OpenBLAS threads spin, and two test programs at
 * once on two cores made test_equilibrium five times slower). Set through
 * OpenBLAS's call, weak for the reference BLAS of make check-fp; the
 * environment is left as it is. */
void openblas_set_num_threads(int num_threads) __attribute__((weak));
__attribute__((constructor)) static void tap_one_blas_thread(void)
{
    if (openblas_set_num_threads)
        openblas_set_num_threads(1);
}

/* ... and with GSL's error handler off, as adhere sets it at start (src/
 * cli/main.c): the core reports through its status codes, never abort. */
#include <gsl/gsl_errno.h>
__attribute__((constructor)) static void tap_gsl_handler_off(void)
{
    gsl_set_error_handler_off();
}

/* TAP_SANITIZED: 1 in make check's second build of the C tests, under
 * ASan/UBSan (gcc defines __SANITIZE_ADDRESS__, clang has the feature).
 * There (tap_sanitized_short) the heaviest numerical tests leave out a
 * case that runs the same code as one they keep (on a larger grid, a
 * second time, or another parameter through the same lines and branches,
 * by gcov): make check's plain build runs it and asserts it, and the
 * sanitizers see its paths on the case kept (docs/testing.md lists
 * which); tap_sanitized_leaves_out says so in the TAP stream. TAP_FULL=1
 * in the environment (make check-asan sets it) runs every case. */
#if defined(__SANITIZE_ADDRESS__)
#define TAP_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TAP_SANITIZED 1
#endif
#endif
#ifndef TAP_SANITIZED
#define TAP_SANITIZED 0
#endif
static inline int tap_sanitized_short(void)
{
    return TAP_SANITIZED && !getenv("TAP_FULL");
}
static inline void tap_sanitized_leaves_out(const char *what)
{
    printf("# under ASan: %s left to the plain build (the same code, run here by the cases kept)\n", what);
}

#define ok(cond, ...) tap_ok(!!(cond), __FILE__, __LINE__, __VA_ARGS__)

static inline int tap_ok(int pass, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#include <stdarg.h>
static inline int tap_ok(int pass, const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    printf("%sok %d - ", pass ? "" : "not ", ++tap_n);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    if (!pass) {
        tap_failed++;
        printf("#   failed at %s:%d\n", file, line);
    }
    fflush(stdout);
    return pass;
}

/* A check that cannot run here, and why: never counted as passed. */
static inline void tap_skip(const char *why)
{
    printf("ok %d # SKIP %s\n", ++tap_n, why);
    fflush(stdout);
}

/* |got - want| <= tol * |want| (relative), reported with both values. */
#define ok_rel(got, want, tol, what) \
    ok(fabs((got) - (want)) <= (tol) * fabs(want), "%s: got %.6g, want %.6g (rel tol %g)", what, \
       (double)(got), (double)(want), (double)(tol))

/* max_i |a_i - b_i| over max_i |b_i|: how far a vector is from a
 * reference, relative to the reference's size. */
static inline double tap_maxrel(const double *a, const double *b, size_t n)
{
    double e = 0, s = 0;
    for (size_t i = 0; i < n; i++) {
        e = fmax(e, fabs(a[i] - b[i]));
        s = fmax(s, fabs(b[i]));
    }
    return e / s;
}

/* The test's scratch directory removed when every check passed (kept for
 * a look when one failed). */
static inline void tap_remove_dir(const char *dir)
{
    if (tap_failed)
        return;
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("# could not remove %s\n", dir);
}

static inline int tap_done(void)
{
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}

#endif
