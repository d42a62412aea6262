#include "plot/outdir.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* Every name any mode writes (batch, sweep, cost, the TUI's plot key);
 * adhere(1) lists the same under FILES. */
static const char *const owned[] = {
    "force.tsv", "summary.tsv", "turns.tsv", "static.tsv", "profiles.tsv", "contact.tsv",
    "sweep.tsv", "cost.tsv",
    "force.png", "profile.png", "contact.png", "precontact.png", "bulge.png", "jump.png", "cost.png",
    "gnuplot.log", "gnuplot-figures.log",
};

static int all_digits(const char *s, size_t n)
{
    if (n == 0)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9')
            return 0;
    return 1;
}

/* The temporaries: .NAME.PID.tmp (tables, cost.png), .NAME.tmpPID
 * (figures), .cost-plot.PID.dat (cost.png's data). */
static int owned_temporary(const char *name)
{
    if (name[0] != '.')
        return 0;
    const char *rest = name + 1;
    if (strncmp(rest, "cost-plot.", 10) == 0) {
        size_t n = strlen(rest + 10);
        return n > 4 && strcmp(rest + 10 + n - 4, ".dat") == 0 && all_digits(rest + 10, n - 4);
    }
    for (size_t i = 0; i < sizeof owned / sizeof owned[0]; i++) {
        size_t len = strlen(owned[i]);
        if (strncmp(rest, owned[i], len) != 0 || rest[len] != '.')
            continue;
        const char *t = rest + len + 1;
        size_t n = strlen(t);
        if (strncmp(t, "tmp", 3) == 0 && all_digits(t + 3, n - 3))
            return 1;
        if (n > 4 && strcmp(t + n - 4, ".tmp") == 0 && all_digits(t, n - 4))
            return 1;
    }
    return 0;
}

int adh_outdir_owns(const char *name)
{
    for (size_t i = 0; i < sizeof owned / sizeof owned[0]; i++)
        if (strcmp(name, owned[i]) == 0)
            return 1;
    return owned_temporary(name);
}

static int is_run_dir(const char *name)
{
    return strncmp(name, "run-", 4) == 0 && all_digits(name + 4, strlen(name + 4));
}

static int clear(const char *dir, int depth, char *why, size_t whylen)
{
    DIR *d = opendir(dir);
    if (!d) {
        if (errno == ENOENT)
            return 0;
        snprintf(why, whylen, "cannot read %s to clear an earlier run's files: %s", dir, strerror(errno));
        return -1;
    }
    int rc = 0;
    struct dirent *e;
    char p[PATH_MAX + 300];
    while (rc == 0 && (e = readdir(d)) != NULL) {
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(p, &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode) && depth == 0 && is_run_dir(e->d_name)) {
            rc = clear(p, 1, why, whylen);
            rmdir(p);   /* only when nothing else is in it */
        } else if (!S_ISDIR(st.st_mode) && adh_outdir_owns(e->d_name) && unlink(p) != 0 && errno != ENOENT) {
            snprintf(why, whylen, "cannot remove %.3000s, left by an earlier run: %s", p, strerror(errno));
            rc = -1;
        }
    }
    closedir(d);
    return rc;
}

int adh_outdir_clear(const char *dir, char *why, size_t whylen)
{
    return clear(dir, 0, why, whylen);
}

int adh_outdir_make(const char *dir, char *why, size_t n)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1;; p++) {
        if (*p && *p != '/')
            continue;
        char c = *p;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            snprintf(why, n, "cannot create directory %.900s: %s", buf, strerror(errno));
            return -1;
        }
        *p = c;
        if (!c)
            break;
    }
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode) || access(buf, W_OK) != 0) {
        snprintf(why, n, "cannot write into %.900s: not a writable directory", buf);
        return -1;
    }
    return 0;
}

int adh_outdir_temp(const char *name, char *buf, size_t len, char *why, size_t whylen)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(buf, len, "%s/%s-XXXXXX", tmp && *tmp ? tmp : "/tmp", name);
    if (mkdtemp(buf))
        return 0;
    snprintf(why, whylen, "cannot make a temporary directory %.900s: %s", buf, strerror(errno));
    if (len)
        buf[0] = '\0';
    return -1;
}

int adh_outdir_write(const char *dir, const char *name, adh_outdir_writer writer, const void *ctx,
                     char *why, size_t whylen)
{
    char path[PATH_MAX + 64], tmp[PATH_MAX + 80];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (strlen(path) >= PATH_MAX) {
        snprintf(why, whylen, "cannot write %.3000s: %s", path, strerror(ENAMETOOLONG));
        return -1;
    }
    /* the temporary beside it, DIR/.NAME.PID.tmp (adh_outdir_owns knows it) */
    snprintf(tmp, sizeof tmp, "%s/.%s.%ld.tmp", dir, name, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(why, whylen, "cannot write %.3000s: %s", path, strerror(errno));
        return -1;
    }
    errno = 0;
    int rc = writer(f, ctx);
    int saved = errno;
    /* fflush + fsync-free close: a full disk shows up here, before the rename. */
    if (fflush(f) != 0 || ferror(f)) {
        rc = -1;
        saved = errno;
    }
    if (fclose(f) != 0 && rc == 0) {
        rc = -1;
        saved = errno;
    }
    if (rc != 0) {
        unlink(tmp);
        snprintf(why, whylen, "cannot write %.3000s: %s", path, strerror(saved ? saved : EIO));
        return -1;
    }
    if (rename(tmp, path) != 0) {
        saved = errno;
        unlink(tmp);
        snprintf(why, whylen, "cannot write %.3000s: %s", path, strerror(saved));
        return -1;
    }
    return 0;
}
