/* The static curve's start in contact when memory runs out on the way
 * there (static.c compiled here with its malloc and calloc counted: the
 * allocation after the solver's own fails): adh_static_set says out of
 * memory, ADH_ENOMEM, not the start's Newton failure with its advice to
 * start further out (what it said before). */
#include <stdlib.h>
#include <string.h>

static long calls, fail_at = -1;

static void *count_malloc(size_t n)
{
    return ++calls == fail_at ? NULL : malloc(n);
}
static void *count_calloc(size_t n, size_t sz)
{
    return ++calls == fail_at ? NULL : calloc(n, sz);
}
#define malloc count_malloc
#define calloc count_calloc
#include "core/static.c"   /* in place of libadhere.a's */
#undef malloc
#undef calloc

#include "adhere/grid.h"
#include "adhere/kernel.h"
#include "adhere/params.h"
#include "tap.h"

int main(void)
{
    /* 0.3 nm on the default material: inside the snap-in, Newton from
     * u = 0 fails (test_stop_reasons), the way from the automatic start
     * reaches it */
    adh_material m = adh_material_default();
    adh_grid *g = adh_grid_alloc(300, adh_grid_default_spacing(&m));
    adh_kernel *k = adh_kernel_alloc(g, &(adh_kernel_settings){ .type = ADH_KERNEL_PAPER }, NULL);
    adh_static *w = adh_static_alloc(g, k);
    adh_static_settings s = adh_static_settings_default();
    s.h0_start = 0.3e-9;
    s.h0_end = -1e-9;
    fail_at = calls + 1;
    unsigned fix = 1;
    int rc = w ? adh_static_set(w, &m, &s) : ADH_ENOMEM;
    const char *why = w ? adh_static_why(w, &fix) : "";
    ok(w && calls >= fail_at && rc == ADH_ENOMEM && strstr(why, "out of memory") && strstr(why, "300 pm") &&
       !strstr(why, "further out") && fix == 0,
       "memory out on the way to a start in contact: ADH_ENOMEM, said so (%s: %s)", adh_strerror(rc), why);
    fail_at = -1;
    rc = w ? adh_static_set(w, &m, &s) : ADH_ENOMEM;
    ok(rc == ADH_SUCCESS, "... and with memory, the same start is solved (%s)", adh_strerror(rc));
    adh_static_free(w);
    adh_kernel_free(k);
    adh_grid_free(g);
    return tap_done();
}
