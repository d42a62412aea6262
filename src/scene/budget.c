#include "scene/budget.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "adhere/grid.h"
#include "adhere/protocol.h"
#include "adhere/rings.h"

/* Measured peaks (VmHWM at the first step, N = 2000 to 20000; docs/
 * security.md), rounded up: bytes a node. */
#define PROGRAM_BYTES (16.0 * 1048576)   /* the program, BLAS buffers, tables */
#define H2_NODE 1.5e3                    /* measured 1.0 kB */
#define HMAT_NODE 4.0e3                  /* measured 2.9 kB */
#define HODLR_NODE 6.0e3                 /* static preconditioner, measured 4.4 kB */
#define VECTORS_NODE 400.0               /* the solvers' vectors, ~25 doubles a node */
/* An interactive path keeps every state it passed, for undo: a snapshot of
 * the deformation, gap and pressure, 3 doubles a node (24.4 B measured at
 * N = 5000, 100 steps), and the step's row and its record. */
#define SNAPSHOT_NODE 24.5
#define SNAPSHOT_STEP 512.0
/* Address space a computing thread maps beside that, counted only against
 * ulimit -v and -d: OpenBLAS maps a 128 MiB working buffer for each thread
 * on its first LAPACK or level-2/3 call (blas_memory_alloc) and, before
 * 0.3.30, retries forever when it cannot, deaf to signals; glibc reserves
 * a 64 MiB arena for each thread past the first. Measured: docs/security.md. */
#define BLAS_BUFFER_VM (128.0 * 1048576)
#define ARENA_VM (64.0 * 1048576)

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

/* Bytes of memory there are: the machine's available memory
 * (/proc/meminfo's MemAvailable, else sysconf) and a cgroup's limit. -1
 * when unknown. */
static double memory_room(void)
{
    double m = proc_kb("/proc/meminfo", "MemAvailable");
    if (m < 0) {
        long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
        m = pages > 0 && size > 0 ? (double)pages * (double)size : -1;
    }
    m = least(m, cgroup_limit("/sys/fs/cgroup/memory.max"));
    return least(m, cgroup_limit("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
}

/* The process's VmSize and VmData in bytes, from one read of its status
 * (-1 each when unknown). */
static void vm_sizes(double *size, double *data)
{
    *size = *data = -1;
    FILE *f = fopen("/proc/self/status", "r");
    if (!f)
        return;
    char line[256];
    while (fgets(line, sizeof line, f))
        if (strncmp(line, "VmSize:", 7) == 0)
            *size = 1024.0 * strtod(line + 7, NULL);
        else if (strncmp(line, "VmData:", 7) == 0)
            *data = 1024.0 * strtod(line + 7, NULL);
    fclose(f);
}

/* Whether ulimit -v or -d is set: else nothing below weighs, and the
 * process's status, threads and maps are not read. */
static int address_limited(void)
{
    struct rlimit rl;
    return (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY) ||
           (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY);
}

/* Bytes of address space the limits leave (ulimit -v, and -d, which since
 * Linux 4.7 counts private mappings too), less what is mapped (size,
 * data: vm_sizes); -1 when neither is set. */
static double address_room(double size, double data)
{
    double m = -1;
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        m = least(m, fmax(0.0, (double)rl.rlim_cur - fmax(0.0, size)));
    if (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
        m = least(m, fmax(0.0, (double)rl.rlim_cur - fmax(0.0, data)));
    return m;
}

/* Threads of this process but the calling one: asked before adhere starts
 * any, the BLAS's own, which map their working buffer and an arena as
 * they start, concurrently with main. */
static unsigned other_threads(void)
{
    DIR *dir = opendir("/proc/self/task");
    if (!dir)
        return 0;
    unsigned n = 0;
    struct dirent *de;
    while ((de = readdir(dir)) != NULL)
        n += de->d_name[0] != '.';
    closedir(dir);
    return n > 1 ? n - 1 : 0;
}

/* BLAS working buffers mapped so far: anonymous mappings of their size. */
static unsigned buffers_mapped(void)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f)
        return 0;
    unsigned n = 0;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        unsigned long long a, b, inode;
        int path = 0;
        if (sscanf(line, "%llx-%llx %*s %*s %*s %llu %n", &a, &b, &inode, &path) < 3)
            continue;
        double size = (double)(b - a);
        n += inode == 0 && (path == 0 || line[path] == '\0' || line[path] == '\n') && size >= BLAS_BUFFER_VM &&
             size < BLAS_BUFFER_VM + 1048576;
    }
    fclose(f);
    return n;
}

/* What the address-space limits leave and what the BLAS's own threads have
 * mapped, read as one state. The BLAS's threads map their buffers
 * concurrently with main: a buffer mapped between the read of VmSize and
 * that of the maps would be in neither the address space in use nor the
 * buffers still to come, 128 MiB short, and the run's own buffer then
 * could not be mapped (OpenBLAS retrying forever: a hang, about one run in
 * a hundred at ulimit -v 300000). So the counts are taken between two
 * reads of VmSize and VmData, again until both agree; if they never do,
 * the later sizes with the earlier counts, which count a buffer twice
 * rather than not at all. */
typedef struct {
    double room;       /* address_room; -1 when no limit is set */
    unsigned own;      /* the other threads (other_threads) */
    unsigned mapped;   /* the BLAS buffers mapped (buffers_mapped) */
} address_state;

static void address_read(address_state *st)
{
    double size, data, size2, data2;
    if (!address_limited()) {   /* no room to take a reserve from */
        *st = (address_state){ .room = -1 };
        return;
    }
    vm_sizes(&size, &data);
    for (int tries = 0; tries < 16; tries++) {
        st->own = other_threads();
        st->mapped = buffers_mapped();
        vm_sizes(&size2, &data2);
        int same = size2 == size && data2 == data;
        size = size2, data = data2;
        if (same)
            break;
    }
    st->room = address_room(size, data);
}

/* Address space that `threads` computing threads map beside what the
 * estimate counts, mostly never touched (so it weighs only against an
 * address-space limit): a BLAS working buffer for each of them and of the
 * BLAS's own threads, less those mapped already, an arena for each such
 * thread still to map one, and, when they are more than one (started
 * threads, main only waiting), a stack and an arena for each. */
static double threads_reserve(unsigned threads, const address_state *st)
{
    struct rlimit rl;
    double stack = getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY ? (double)rl.rlim_cur
                                                                                      : 8.0 * 1048576;
    unsigned t = threads ? threads : 1, own = st->own, mapped = st->mapped;
    unsigned unmapped = t + own > mapped ? t + own - mapped : 0;
    unsigned own_unmapped = own > mapped ? own - mapped : 0;
    return unmapped * BLAS_BUFFER_VM + own_unmapped * ARENA_VM + (t > 1 ? t : 0) * (stack + ARENA_VM);
}

double adh_budget_machine_bytes(void)
{
    double size = -1, data = -1;
    if (address_limited())
        vm_sizes(&size, &data);
    double m = least(memory_room(), address_room(size, data));
    return m < 0 ? INFINITY : m;
}

/* adh_budget_fits, with the reserve it counted in *reserve (0 when no
 * address-space limit is set). */
static int fits(double need, unsigned threads, double *have, int *address_bound, double *reserve)
{
    address_state st;
    address_read(&st);
    double mem = memory_room(), as = st.room;
    *reserve = as >= 0 ? threads_reserve(threads, &st) : 0;
    if (as >= 0)
        as = fmax(0.0, as - *reserve);
    double m = least(mem, as);
    *have = m < 0 ? INFINITY : m;
    if (address_bound)
        *address_bound = as >= 0 && (mem < 0 || as < mem);
    return need <= *have;
}

int adh_budget_fits(double need, unsigned threads, double *have, int *address_bound)
{
    double reserve;
    return fits(need, threads, have, address_bound, &reserve);
}

static double kernel_bytes(adh_kernel_storage storage, double n)
{
    return storage == ADH_STORAGE_DENSE ? 8.0 * n * n : storage == ADH_STORAGE_HMAT ? HMAT_NODE * n : H2_NODE * n;
}

double adh_budget_bytes(const adh_run_spec *run, unsigned solvers)
{
    if (run->mode == ADH_MODE_RIGID)
        return PROGRAM_BYTES;
    adh_kernel_storage storage = run->grid.use.storage;
    /* a relaxation's static reference takes the static mode's operator,
     * a kernel of its own where that is not the run's */
    adh_kernel_storage ss = run->mode == ADH_MODE_STATIC ? storage : adh_config_storage_for(run, ADH_MODE_STATIC);
    double n = (double)adh_config_nodes(run);
    /* a static solver copies a dense kernel and factors it (2 n^2 more
     * doubles); over a hierarchical one it builds a HODLR preconditioner */
    double solver = ss == ADH_STORAGE_DENSE ? 16.0 * (n + 1) * (n + 1) : HODLR_NODE * n;
    /* in physical time a viscoelastic sphere's solver holds those two for
     * its path and, from its first jump into contact, the static solver
     * that lands it: that one reads the path's copy of a dense kernel and
     * factors its own (n^2 more), or builds a HODLR of its own: allocated
     * mid-run, past the estimate, where it was not counted */
    if (run->mode == ADH_MODE_TIME && run->time.sls)
        solver += ss == ADH_STORAGE_DENSE ? 8.0 * (n + 1) * (n + 1) : HODLR_NODE * n;
    double own = solvers && ss != storage ? kernel_bytes(ss, n) : 0;
    return PROGRAM_BYTES + kernel_bytes(storage, n) + own + VECTORS_NODE * n + (double)solvers * solver;
}

unsigned adh_budget_solvers(const adh_run_spec *run, unsigned jobs, int reference)
{
    return run->mode == ADH_MODE_STATIC || run->mode == ADH_MODE_TIME ? jobs : reference ? 1 : 0;
}

/* "3.2 GB", "130 MB" */
static void bytes_text(double b, char *buf, size_t len)
{
    if (b >= 1e9)
        snprintf(buf, len, "%.3g GB", b / 1e9);
    else
        snprintf(buf, len, "%.3g MB", b / 1e6);
}

double adh_budget_path_steps(const adh_run_spec *run)
{
    double start = adh_config_start(run), step = run->proto.step;
    double deepest = run->proto.nturns ? adh_protocol_deepest_turn(&run->proto) : 0.0;
    double steps = fmax(0.0, start - deepest) / step + 1;
    for (size_t i = 0; run->proto.unload && i < run->proto.nturns; i++)
        steps += fmax(0.0, start - run->proto.turns[i]) / step + 1;
    return steps;
}

int adh_budget_check_path(const adh_run_spec *run, size_t kept, char *why, size_t whylen)
{
    if (run->mode == ADH_MODE_RIGID)
        return 0;
    double n = (double)adh_config_nodes(run), steps = adh_budget_path_steps(run);
    double per_step = SNAPSHOT_NODE * n + SNAPSHOT_STEP;
    double path = fmax(0.0, steps - (double)kept) * per_step, have, own = adh_budget_bytes(run, 0);
    if (adh_budget_fits(own + path, 1, &have, NULL))
        return 0;
    /* the run alone past the budget: its own refusal (the kernel, its
     * operator), not the path's, which named 432 MB as more than 1.64 GB */
    if (!adh_budget_fits(own, 1, &have, NULL))
        return adh_budget_check(run, 0, why, whylen);
    char a[32], b[32], c[32], d[32];
    bytes_text(steps * per_step, a, sizeof a);
    bytes_text(have, b, sizeof b);
    bytes_text(per_step, c, sizeof c);
    bytes_text(own, d, sizeof d);
    snprintf(why, whylen, "undo would keep %s for this path (%.0f steps to the turn and back, %s a step on %.0f "
             "nodes) beside the %s the run holds, more than the %s this process may use: take a larger "
             "protocol.step, fewer grid.nodes, or a turn nearer the start", a, steps, c, n, d, b);
    return -1;
}

int adh_budget_check_threads(const adh_run_spec *run, unsigned solvers, unsigned threads, char *why,
                             size_t whylen)
{
    if (run->mode == ADH_MODE_RIGID)
        return 0;
    size_t n = adh_config_nodes(run);
    adh_kernel_storage storage = run->grid.use.storage;
    double need = adh_budget_bytes(run, solvers), have, reserve;
    int address;
    if (fits(need, threads, &have, &address, &reserve))
        return 0;
    adh_run_spec h2 = *run;
    h2.grid.use.storage = ADH_STORAGE_H2;
    h2.grid.storage_given = 1;
    char a[32], b[32], c[32], r[32];
    bytes_text(need, a, sizeof a);
    bytes_text(have, b, sizeof b);
    bytes_text(adh_budget_bytes(&h2, solvers), c, sizeof c);
    bytes_text(reserve, r, sizeof r);
    char h2use[80] = "", limit[300] = "";
    if (storage != ADH_STORAGE_H2)
        snprintf(h2use, sizeof h2use, "grid.operator = h2 (about %s), ", c);
    if (address)
        snprintf(limit, sizeof limit, "raise or lift ulimit -v/-d (the address space left, less the %s the BLAS "
                 "and %u computing thread%s map beside the run), ", r, threads ? threads : 1,
                 threads > 1 ? "s" : "");
    /* keys, which each driver says in its words (adh_config_reword) */
    snprintf(why, whylen, "a run on %zu %s with the %s operator%s would hold about %s, more than the %s this "
             "process may use (available memory, ulimit -v/-d, cgroup limit): %suse %sfewer nodes, or the "
             "automatic grid (grid.nodes = auto with grid.spacing = auto; graded where a fine one is needed)",
             n, run->grid.use.graded ? "rings" : "nodes", adh_kernel_storage_name(storage),
             solvers ? " and its static solver" : "", a, b, limit, h2use);
    return -1;
}

int adh_budget_check(const adh_run_spec *run, unsigned solvers, char *why, size_t whylen)
{
    return adh_budget_check_threads(run, solvers, solvers > 1 ? solvers : 1, why, whylen);
}
