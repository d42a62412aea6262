#include "scene/budget.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "adhere/grid.h"
#include "adhere/rings.h"

/* Measured peaks (VmHWM at the first step, N = 2000 to 20000; docs/
 * security.md), rounded up: bytes a node. */
#define PROGRAM_BYTES (16.0 * 1048576)   /* the program, BLAS buffers, tables */
#define H2_NODE 1.5e3                    /* measured 1.0 kB */
#define HMAT_NODE 4.0e3                  /* measured 2.9 kB */
#define HODLR_NODE 6.0e3                 /* static preconditioner, measured 4.4 kB */
#define VECTORS_NODE 400.0               /* the solvers' vectors, ~25 doubles a node */

/* A "key: value kB" line of a /proc file, in bytes; -1 when absent. */
static double proc_kb(const char *path, const char *key)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[256];
    double v = -1;
    size_t n = strlen(key);
    while (fgets(line, sizeof line, f))
        if (strncmp(line, key, n) == 0 && line[n] == ':') {
            v = 1024.0 * strtod(line + n + 1, NULL);
            break;
        }
    fclose(f);
    return v;
}

/* A cgroup's limit in bytes (a number, or "max"); -1 when none. */
static double cgroup_limit(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    double v = -1;
    char buf[64];
    if (fgets(buf, sizeof buf, f) && strncmp(buf, "max", 3) != 0)
        v = strtod(buf, NULL);
    fclose(f);
    return v > 0 && v < 1e18 ? v : -1;
}

static double least(double a, double b)
{
    return b >= 0 && (a < 0 || b < a) ? b : a;
}

double adh_budget_machine_bytes(void)
{
    double m = proc_kb("/proc/meminfo", "MemAvailable");
    if (m < 0) {
        long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
        m = pages > 0 && size > 0 ? (double)pages * (double)size : -1;
    }
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        m = least(m, fmax(0.0, (double)rl.rlim_cur - fmax(0.0, proc_kb("/proc/self/status", "VmSize"))));
    if (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        m = least(m, fmax(0.0, (double)rl.rlim_cur - fmax(0.0, proc_kb("/proc/self/status", "VmData"))));
    m = least(m, cgroup_limit("/sys/fs/cgroup/memory.max"));
    m = least(m, cgroup_limit("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    return m < 0 ? INFINITY : m;
}

double adh_budget_bytes(const adh_run_spec *run, unsigned solvers)
{
    if (run->mode == ADH_MODE_RIGID)
        return PROGRAM_BYTES;
    adh_kernel_storage storage = run->grid.use.storage;
    double n = (double)adh_config_nodes(run);
    double kernel = storage == ADH_STORAGE_DENSE ? 8.0 * n * n
                  : storage == ADH_STORAGE_HMAT ? HMAT_NODE * n : H2_NODE * n;
    /* a static solver copies a dense kernel and factors it (2 n^2 more
     * doubles); over a hierarchical one it builds a HODLR preconditioner */
    double solver = storage == ADH_STORAGE_DENSE ? 16.0 * (n + 1) * (n + 1) : HODLR_NODE * n;
    return PROGRAM_BYTES + kernel + VECTORS_NODE * n + (double)solvers * solver;
}

/* "3.2 GB", "130 MB" */
static void bytes_text(double b, char *buf, size_t len)
{
    if (b >= 1e9)
        snprintf(buf, len, "%.3g GB", b / 1e9);
    else
        snprintf(buf, len, "%.3g MB", b / 1e6);
}

int adh_budget_check(const adh_run_spec *run, unsigned solvers, char *why, size_t whylen)
{
    if (run->mode == ADH_MODE_RIGID)
        return 0;
    size_t n = adh_config_nodes(run);
    adh_kernel_storage storage = run->grid.use.storage;
    double need = adh_budget_bytes(run, solvers), have = adh_budget_machine_bytes();
    if (need <= have)
        return 0;
    adh_run_spec h2 = *run;
    h2.grid.use.storage = ADH_STORAGE_H2;
    char a[32], b[32], c[32];
    bytes_text(need, a, sizeof a);
    bytes_text(have, b, sizeof b);
    bytes_text(adh_budget_bytes(&h2, solvers), c, sizeof c);
    char h2use[80] = "";
    if (storage != ADH_STORAGE_H2)
        snprintf(h2use, sizeof h2use, "grid.operator = h2 (about %s), ", c);
    /* keys, which each driver says in its words (adh_config_reword) */
    snprintf(why, whylen, "a run on %zu %s with the %s operator%s would hold about %s, more than the %s this "
             "process may use (available memory, ulimit -v/-d, cgroup limit): use %sfewer nodes, or the "
             "automatic grid (grid.nodes = auto with grid.spacing = auto; graded where a fine one is needed)",
             n, run->grid.use.graded ? "rings" : "nodes", adh_kernel_storage_name(storage),
             solvers ? " and its static solver" : "", a, b, h2use);
    return -1;
}
