/* LD_PRELOAD shim for tests/cli/budget.sh: makes the BLAS's own thread map
 * its 128 MiB working buffer at the worst moment for adhere's memory
 * check, every time instead of about one run in a hundred: after the main
 * thread has read /proc/self/status (its VmSize) and before it opens
 * /proc/self/maps (where it counts the buffers mapped). A check that read
 * the two apart counted that buffer nowhere, let the run start, and the
 * run's own buffer could not be mapped (OpenBLAS 0.3.21 retries forever).
 * Condition variables order the two threads; a wait gives up after 10 s
 * only so that a program reading in another order cannot deadlock. It
 * appends to $BLASRACE_LOG "ordered" once it has ordered them, or "alone"
 * when there was no other thread to order (one core, or
 * OPENBLAS_NUM_THREADS=1: no BLAS thread of its own). */
#define _GNU_SOURCE
#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#define BUFFER (128UL * 1048576)

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t changed = PTHREAD_COND_INITIALIZER;
static int status_read, buffer_mapped, buffer_waiting, logged;
static FILE *status_file;
static FILE *(*real_fopen)(const char *, const char *);
static int (*real_fclose)(FILE *);

static void find_real(void)
{
    if (!real_fopen) {
        real_fopen = (FILE * (*)(const char *, const char *)) dlsym(RTLD_NEXT, "fopen");
        real_fclose = (int (*)(FILE *))dlsym(RTLD_NEXT, "fclose");
    }
}

/* Waits, lock held, until *flag is set or 10 s have passed. */
static void wait_for(int *flag)
{
    struct timespec until;
    clock_gettime(CLOCK_REALTIME, &until);
    until.tv_sec += 10;
    while (!*flag)
        if (pthread_cond_timedwait(&changed, &lock, &until) == ETIMEDOUT)
            break;
}

static void set(int *flag)
{
    *flag = 1;
    pthread_cond_broadcast(&changed);
}

static void *real_mmap(void *addr, size_t len, int prot, int flags, int fd, off_t off)
{
    return (void *)syscall(SYS_mmap, addr, len, prot, flags, fd, off);
}

/* Another thread's first buffer waits for main's read of its status. */
void *mmap(void *addr, size_t len, int prot, int flags, int fd, off_t off)
{
    if (len != BUFFER || getpid() == (pid_t)syscall(SYS_gettid))
        return real_mmap(addr, len, prot, flags, fd, off);
    pthread_mutex_lock(&lock);
    int first = !buffer_mapped && !buffer_waiting;
    if (first) {
        set(&buffer_waiting);
        wait_for(&status_read);
    }
    pthread_mutex_unlock(&lock);
    void *p = real_mmap(addr, len, prot, flags, fd, off);
    if (first) {
        pthread_mutex_lock(&lock);
        set(&buffer_mapped);
        pthread_mutex_unlock(&lock);
    }
    return p;
}

void *mmap64(void *addr, size_t len, int prot, int flags, int fd, off_t off)
{
    return mmap(addr, len, prot, flags, fd, off);
}

static void note(const char *what)
{
    const char *log = getenv("BLASRACE_LOG");
    FILE *f = log && !logged ? real_fopen(log, "a") : NULL;
    if (f) {
        fprintf(f, "%s\n", what);
        real_fclose(f);
    }
    logged = 1;
}

/* Whether the process has a thread besides the caller (the BLAS's own:
 * none on one core or with OPENBLAS_NUM_THREADS=1). */
static int other_thread(void)
{
    DIR *d = opendir("/proc/self/task");
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) != NULL;)
        n += e->d_name[0] != '.';
    if (d)
        closedir(d);
    return n > 1;
}

/* main's reads of its status and maps, in adhere's memory check */
FILE *fopen(const char *path, const char *mode)
{
    find_real();
    pthread_mutex_lock(&lock);
    if (strcmp(path, "/proc/self/maps") == 0 && status_read && buffer_waiting && !logged) {
        wait_for(&buffer_mapped);
        note(buffer_mapped ? "ordered" : "not ordered");
    }
    pthread_mutex_unlock(&lock);
    FILE *f = real_fopen(path, mode);
    if (strcmp(path, "/proc/self/status") == 0)
        status_file = f;
    return f;
}

FILE *fopen64(const char *path, const char *mode)
{
    return fopen(path, mode);
}

int fclose(FILE *f)
{
    find_real();
    pthread_mutex_lock(&lock);
    if (f && f == status_file && !status_read) {
        /* the other thread at its buffer first, held there (or none) */
        status_file = NULL;
        if (other_thread())
            wait_for(&buffer_waiting);
        else
            note("alone");
        set(&status_read);
    }
    pthread_mutex_unlock(&lock);
    return real_fclose(f);
}
