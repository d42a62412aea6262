/* LD_PRELOAD shim for tests/cli/studies.sh: opening a file named
 * $FAILOPEN_NAME for reading fails with EIO (a disk's read error, or a
 * file system gone), the one error a test cannot otherwise provoke in a
 * directory adhere wrote itself: its manifest refuses a file put under
 * the name (a FIFO, a directory), and root reads whatever chmod says.
 * Every other open, and every open for writing, goes through. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static int refused(const char *path, int flags)
{
    const char *name = getenv("FAILOPEN_NAME");
    if (!name || !path || (flags & O_ACCMODE) != O_RDONLY)
        return 0;
    const char *base = strrchr(path, '/');
    return strcmp(base ? base + 1 : path, name) == 0;
}

static int next_openat(const char *sym, int dirfd, const char *path, int flags, mode_t mode)
{
    int (*real)(int, const char *, int, ...) = (int (*)(int, const char *, int, ...))dlsym(RTLD_NEXT, sym);
    return real ? real(dirfd, path, flags, mode) : (errno = ENOSYS, -1);
}

#define SHIM(sym)                                                   \
    int sym(int dirfd, const char *path, int flags, ...)            \
    {                                                               \
        mode_t mode = 0;                                            \
        if (flags & (O_CREAT | O_TMPFILE)) {                        \
            va_list ap;                                             \
            va_start(ap, flags);                                    \
            mode = va_arg(ap, mode_t);                              \
            va_end(ap);                                             \
        }                                                           \
        if (refused(path, flags)) {                                 \
            errno = EIO;                                            \
            return -1;                                              \
        }                                                           \
        return next_openat(#sym, dirfd, path, flags, mode);         \
    }
SHIM(openat)
SHIM(openat64)
