/* A minimal TAP producer for the C tests: one "ok N - what" line per check,
 * the plan at the end, exit status 1 when anything failed. */
#ifndef ADH_TAP_H
#define ADH_TAP_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int tap_n, tap_failed;

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

/* |got - want| <= tol * |want| (relative), reported with both values. */
#define ok_rel(got, want, tol, what) \
    ok(fabs((got) - (want)) <= (tol) * fabs(want), "%s: got %.6g, want %.6g (rel tol %g)", what, \
       (double)(got), (double)(want), (double)(tol))

static inline int tap_done(void)
{
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}

#endif
