/* flock(2) is BSD's: the lock goes with the open directory, so it ends
 * with the descriptor (a killed run leaves no stale lock behind). */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
/* statx(2)'s birth time: a temporary's record tells it from a file the
 * user made later under its name on the inode it freed */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "plot/outdir.h"
#include "scene/text.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif
/* The largest manifest read: a study's 10^5 run-K lines (some 45 bytes
 * each) and its files, with room; a larger one is not adhere's. */
#define MANIFEST_MAX (16 << 20)
/* A path as messages show it: every byte of PATH_MAX a control byte, \xNN. */
#define SHOWN_MAX (4 * PATH_MAX + 64)

/* One file or directory adhere wrote, as the manifest records it. */
typedef struct entry {
    char name[32];          /* "force.tsv", or "run-3/" for a directory */
    unsigned long long dev, ino;
    long long size;         /* -1: a directory, or a log that grows */
    long long mt_sec;
    long mt_nsec;
    long long ct_sec;       /* the change time: a chmod, a link, an edit */
    long ct_nsec;           /* whose mtime was set back all move it */
    long long bt_sec;       /* a file recorded by identity (a temporary, a log): */
    long bt_nsec;           /* its birth time, when bt_known */
    int bt_known;
} entry;

/* A file written under its temporary name, waiting for adh_outdir_commit. */
typedef struct staged {
    char tmp[64], name[32];
} staged;

/* The entries by name: open addressing over their indices (+1; 0 empty),
 * a study's 10^5 run-K directories each found at once instead of among
 * all the others; the entries of one name (a manifest's repeated lines)
 * chained from its slot, so that they cost no probes. Rebuilt when an
 * entry is dropped (entries move). */
typedef struct name_index {
    size_t *slot;       /* nslot slots, then nslot / 2 links: an entry's next of its name (+1; 0 none) */
    size_t nslot;       /* a power of 2, at least twice the entries */
    int stale;
} name_index;

struct adh_outdir {
    int fd;
    unsigned flags;
    int foreign_manifest;   /* a manifest there that adhere cannot trust */
    entry *e;
    size_t n, cap;
    name_index *ix;         /* a cache of e's names (find): changed through a const adh_outdir too */
    int staging;            /* adh_outdir_stage: new files wait under their temporaries */
    staged *st;
    size_t nst, capst;
    char path[SHOWN_MAX];   /* for messages: DIR, or DIR/run-K, escaped (adh_outdir_escape) */
};

/* Every name any mode writes (batch, sweep, cost, the TUI's plot key);
 * adhere(1) lists the same under FILES. */
static const char *const owned[] = {
    "force.tsv", "summary.tsv", "turns.tsv", "static.tsv", "profiles.tsv", "contact.tsv", "models.tsv",
    "sweep.tsv", "cost.tsv", "fit.tsv", "fit-points.tsv", "best.scene", "fit.png", "study.tsv", "runs.tsv",
    "force.png", "force-base.png", "profile.png", "contact.png", "precontact.png", "bulge.png", "jump.png", "cost.png",
    "map.png", "curves.png", "events.tsv", "speed.png", "snap.png",
    "gnuplot.log", "gnuplot-figures.log", ADH_OUTDIR_MANIFEST,
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

int adh_outdir_owns(const char *name)
{
    for (size_t i = 0; i < sizeof owned / sizeof owned[0]; i++)
        if (strcmp(name, owned[i]) == 0)
            return 1;
    return 0;
}

/* run-K as a sweep names it: K from 1, no leading zero (a user's run-01
 * or run-0 is no name of adhere's) */
static int is_run_dir(const char *name)
{
    return strncmp(name, "run-", 4) == 0 && name[4] >= '1' && name[4] <= '9' &&
           all_digits(name + 4, strlen(name + 4)) && strlen(name) < 24;
}

/* A temporary of an owned name: .NAME.XXXXXX (this version), or an older
 * adhere's .NAME.PID.tmp, .NAME.tmpPID, .cost-plot.PID.dat. Only
 * --overwrite removes them: adhere cannot prove a killed run's are its own. */
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
        const char *o = owned[i][0] == '.' ? owned[i] + 1 : owned[i];
        size_t len = strlen(o);
        if (strncmp(rest, o, len) != 0 || rest[len] != '.')
            continue;
        const char *t = rest + len + 1;
        size_t n = strlen(t);
        if (n == 6 && strspn(t, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789") == 6)
            return 1;
        if (strncmp(t, "tmp", 3) == 0 && all_digits(t + 3, n - 3))
            return 1;
        if (n > 4 && strcmp(t + n - 4, ".tmp") == 0 && all_digits(t, n - 4))
            return 1;
    }
    return 0;
}

/* ------------------------------------------------------- new files */

/* Six letters or digits no other call of this process repeats soon. */
static void random6(char *out)
{
    static const char set[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    static _Atomic unsigned long long counter;   /* a sweep's threads write at once */
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    unsigned long long x = (unsigned long long)ts.tv_nsec ^ ((unsigned long long)ts.tv_sec << 30) ^
                           ((unsigned long long)getpid() << 16) ^ (uintptr_t)out ^
                           ((atomic_fetch_add(&counter, 1) + 1) * 0x9E3779B97F4A7C15ULL);
    for (int i = 0; i < 6; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        out[i] = set[x % 62];
    }
    out[6] = '\0';
}

/* A new file .NAME.XXXXXX in dirfd: O_EXCL and O_NOFOLLOW, so nothing
 * planted under that name (a link) is ever opened. Its descriptor, or -1
 * with errno. */
static int temp_open(int dirfd, const char *name, int mode, char *tmp, size_t len);
static int temp_create(int dirfd, const char *name, char *tmp, size_t len)
{
    return temp_open(dirfd, name, O_WRONLY, tmp, len);
}

/* temp_create's, opened with mode (O_WRONLY, or O_RDWR | O_APPEND for a log). */
static int temp_open(int dirfd, const char *name, int mode, char *tmp, size_t len)
{
    for (int tries = 0; tries < 100; tries++) {
        char r[8];
        random6(r);
        if (snprintf(tmp, len, ".%s.%s", name[0] == '.' ? name + 1 : name, r) >= (int)len) {
            errno = ENAMETOOLONG;
            return -1;
        }
        int fd = openat(dirfd, tmp, mode | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    return -1;
}

/* writer into fd, every byte out (a full disk or a file size limit shows
 * up here), st the file as written; fd is closed. 0, or an errno. */
static int fill(int fd, adh_outdir_writer writer, const void *ctx, struct stat *st)
{
    FILE *f = fdopen(fd, "w");
    if (!f) {
        int e = errno;
        close(fd);
        return e;
    }
    errno = 0;
    int rc = writer(f, ctx);
    int saved = rc ? (errno ? errno : EIO) : 0;
    if (fflush(f) != 0 || ferror(f)) {
        saved = saved ? saved : errno ? errno : EIO;
    }
    if (!saved && st && fstat(fileno(f), st) != 0)
        saved = errno;
    if (fclose(f) != 0 && !saved)
        saved = errno ? errno : EIO;
    return saved;
}

/* --------------------------------------------------------- manifest */

static int entry_name_ok(const char *name)
{
    size_t n = strlen(name);
    if (n && name[n - 1] == '/') {
        char base[64];
        snprintf(base, sizeof base, "%.*s", (int)(n - 1), name);
        return is_run_dir(base);
    }
    return (adh_outdir_owns(name) || owned_temporary(name)) && strcmp(name, ADH_OUTDIR_MANIFEST) != 0;
}

/* FNV-1a of name without a trailing '/': "run-3" and "run-3/" in one chain. */
static size_t name_hash(const char *name)
{
    size_t n = strlen(name);
    if (n && name[n - 1] == '/')
        n--;
    uint64_t h = 1469598103934665603ULL;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)name[i]) * 1099511628211ULL;
    return (size_t)h;
}

/* Whether a and b are one name but for a trailing '/'. */
static int same_base(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    na -= na && a[na - 1] == '/';
    nb -= nb && b[nb - 1] == '/';
    return na == nb && !memcmp(a, b, na);
}

/* The slot whose chain holds name's entries, or an empty one. */
static size_t index_slot(const name_index *ix, const entry *e, const char *name)
{
    size_t k = name_hash(name) & (ix->nslot - 1);
    while (ix->slot[k] && !same_base(e[ix->slot[k] - 1].name, name))
        k = (k + 1) & (ix->nslot - 1);
    return k;
}

static void index_put(name_index *ix, const entry *e, size_t i)
{
    size_t *next = ix->slot + ix->nslot;
    size_t k = index_slot(ix, e, e[i].name), head = ix->slot[k];
    next[i] = head ? next[head - 1] : 0;
    if (head)
        next[head - 1] = i + 1;
    else
        ix->slot[k] = i + 1;
}

/* d's index made anew for its entries: 0, or -1 (no memory: find searches
 * linearly). */
static int index_build(const adh_outdir *d)
{
    name_index *ix = d->ix;
    size_t want = 64;
    while (want < 2 * d->n + 2)
        want *= 2;
    if (want != ix->nslot) {
        size_t *slot = realloc(ix->slot, (want + want / 2) * sizeof *slot);
        if (!slot)
            return -1;
        ix->slot = slot, ix->nslot = want;
    }
    memset(ix->slot, 0, ix->nslot * sizeof *ix->slot);
    for (size_t i = 0; i < d->n; i++)
        index_put(ix, d->e, i);
    ix->stale = 0;
    return 0;
}

/* Entry d->n - 1, just added: indexed when the index is current and has room. */
static void index_added(adh_outdir *d)
{
    name_index *ix = d->ix;
    if (!ix)
        return;
    if (ix->stale || 2 * d->n + 2 > ix->nslot)
        ix->stale = 1;   /* built again, larger, when next looked in */
    else
        index_put(ix, d->e, d->n - 1);
}

static void index_stale(adh_outdir *d)
{
    if (d->ix)
        d->ix->stale = 1;
}

/* The birth time of name in dirfd (never through a link): 1, or 0 where
 * the filesystem keeps none. */
static int birth(int dirfd, const char *name, struct timespec *bt)
{
    struct statx sx;
    if (statx(dirfd, name, AT_SYMLINK_NOFOLLOW, STATX_BTIME, &sx) != 0 || !(sx.stx_mask & STATX_BTIME))
        return 0;
    bt->tv_sec = (time_t)sx.stx_btime.tv_sec;
    bt->tv_nsec = (long)sx.stx_btime.tv_nsec;
    return 1;
}

static int add_raw(adh_outdir *d, const char *name, unsigned long long dev, unsigned long long ino,
                   long long size, const struct timespec *mt, const struct timespec *ct, const struct timespec *bt)
{
    if (d->n == d->cap) {
        size_t cap = d->cap ? 2 * d->cap : 16;
        entry *e = realloc(d->e, cap * sizeof *e);
        if (!e)
            return -1;
        d->e = e;
        d->cap = cap;
    }
    d->e[d->n++] = (entry){ .dev = dev, .ino = ino, .size = size, .mt_sec = (long long)mt->tv_sec,
                            .mt_nsec = mt->tv_nsec, .ct_sec = (long long)ct->tv_sec, .ct_nsec = ct->tv_nsec,
                            .bt_sec = bt ? (long long)bt->tv_sec : 0, .bt_nsec = bt ? bt->tv_nsec : 0,
                            .bt_known = bt != NULL };
    snprintf(d->e[d->n - 1].name, sizeof d->e[0].name, "%s", name);
    index_added(d);
    return 0;
}

/* name as st is now; a log that grows, and a directory, by identity alone
 * (a file's with its birth time, where the filesystem keeps one) */
static int add_entry(adh_outdir *d, const char *name, const struct stat *st, int grows)
{
    struct timespec bt;
    int by_birth = grows && S_ISREG(st->st_mode) && birth(d->fd, name, &bt);
    return add_raw(d, name, (unsigned long long)st->st_dev, (unsigned long long)st->st_ino,
                   grows || S_ISDIR(st->st_mode) ? -1 : (long long)st->st_size, &st->st_mtim, &st->st_ctim,
                   by_birth ? &bt : NULL);
}

static void drop_entry(adh_outdir *d, size_t i)
{
    d->e[i] = d->e[--d->n];
    index_stale(d);
}

/* Whether st, name in d now, is still the file or directory e recorded.
 * A file recorded by identity is born when it was: a user's file made
 * under its name may be given the inode it freed. */
static int same(const adh_outdir *d, const entry *e, const char *name, const struct stat *st)
{
    size_t n = strlen(e->name);
    int dir = n && e->name[n - 1] == '/';
    if (dir ? !S_ISDIR(st->st_mode) : !S_ISREG(st->st_mode))
        return 0;
    if (e->dev != (unsigned long long)st->st_dev || e->ino != (unsigned long long)st->st_ino)
        return 0;
    struct timespec bt;
    if (e->size < 0 && e->bt_known)
        return birth(d->fd, name, &bt) && (long long)bt.tv_sec == e->bt_sec && bt.tv_nsec == e->bt_nsec;
    return e->size < 0 || (e->size == (long long)st->st_size && e->mt_sec == (long long)st->st_mtim.tv_sec &&
                           e->mt_nsec == st->st_mtim.tv_nsec && e->ct_sec == (long long)st->st_ctim.tv_sec &&
                           e->ct_nsec == st->st_ctim.tv_nsec);
}

/* The entry of d that name (a file, or "run-K" for the directory) is
 * still, or -1. */
static long find(const adh_outdir *d, const char *name, const struct stat *st)
{
    char dirname[40];
    snprintf(dirname, sizeof dirname, "%s/", name);
    name_index *ix = d->ix;
    if (!ix || ((ix->stale || !ix->nslot) && index_build(d) != 0)) {
        for (size_t i = 0; i < d->n; i++)
            if ((!strcmp(d->e[i].name, name) || !strcmp(d->e[i].name, dirname)) && same(d, &d->e[i], name, st))
                return (long)i;
        return -1;
    }
    const size_t *next = ix->slot + ix->nslot;
    for (size_t c = ix->slot[index_slot(ix, d->e, name)]; c; c = next[c - 1]) {
        size_t i = c - 1;
        if ((!strcmp(d->e[i].name, name) || !strcmp(d->e[i].name, dirname)) && same(d, &d->e[i], name, st))
            return (long)i;
    }
    return -1;
}

static int manifest_table(FILE *f, const void *ctx)
{
    const adh_outdir *d = ctx;
    fputs("# adhere: the files it wrote in this directory (name, device, inode, size, modification time,\n"
          "# change time); a later run removes only those that are still the same, and writes nothing through\n"
          "# a link\n", f);
    for (size_t i = 0; i < d->n; i++) {
        const entry *e = &d->e[i];
        if (e->size < 0 && e->bt_known)   /* the birth time where the change time goes */
            fprintf(f, "%s\t%llu\t%llu\t-\t-\t%lld.%09ld\n", e->name, e->dev, e->ino, e->bt_sec, e->bt_nsec);
        else if (e->size < 0)
            fprintf(f, "%s\t%llu\t%llu\t-\t-\t-\n", e->name, e->dev, e->ino);
        else
            fprintf(f, "%s\t%llu\t%llu\t%lld\t%lld.%09ld\t%lld.%09ld\n", e->name, e->dev, e->ino, e->size,
                    e->mt_sec, e->mt_nsec, e->ct_sec, e->ct_nsec);
    }
    return 0;
}

/* The manifest rewritten from d's entries (a new file renamed over it):
 * 0, or the errno of the call that failed (*made, when not NULL, says
 * whether that was after the new file was made: else the create's). */
static int save_e(adh_outdir *d, int *made)
{
    char tmp[64];
    int fd = temp_create(d->fd, ADH_OUTDIR_MANIFEST, tmp, sizeof tmp);
    if (made)
        *made = fd >= 0;
    if (fd < 0)
        return errno;
    int e = fill(fd, manifest_table, d, NULL);
    if (!e && renameat(d->fd, tmp, d->fd, ADH_OUTDIR_MANIFEST) != 0)
        e = errno;
    if (e)
        unlinkat(d->fd, tmp, 0);
    return e;
}

/* save_e's, as -1 with errno (that failing call's, not the clean-up's). */
static int save(adh_outdir *d)
{
    int e = save_e(d, NULL);
    errno = e;
    return e ? -1 : 0;
}

/* The words for e, the errno of creating a file or directory in a
 * directory that exists (what: "the directory", or one the user can find
 * by it): ENOENT there is a file system that makes its own files only
 * (/proc), which the system's words alone ("No such file or directory")
 * hide. */
static const char *create_reason(const char *what, int e, char *buf, size_t len)
{
    if (e != ENOENT)
        return strerror(e);
    snprintf(buf, len, "%.3000s exists, but its file system lets nothing new be made in it (%s)", what, strerror(e));
    return buf;
}

/* d's manifest saved, or why not in words naming the call that failed:
 * a file not created in d, or the new manifest not written. 0, or -1. */
static int save_why(adh_outdir *d, char *why, size_t whylen)
{
    int made;
    int e = save_e(d, &made);
    char reason[200];
    if (e && !made)
        snprintf(why, whylen, "cannot create a file in %.3000s: %s", d->path,
                 create_reason("the directory", e, reason, sizeof reason));
    else if (e)
        snprintf(why, whylen, "cannot write %.3000s/%s: %s", d->path, ADH_OUTDIR_MANIFEST, strerror(e));
    return e ? -1 : 0;
}

/* The last entry added, appended to the manifest (a study adds a run-K
 * directory at a time: rewriting a manifest of thousands for each would
 * cost their square); the whole manifest rewritten when that fails. */
static int save_added(adh_outdir *d)
{
    int fd = openat(d->fd, ADH_OUTDIR_MANIFEST, O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != geteuid()) {
        if (fd >= 0)
            close(fd);
        return save(d);
    }
    adh_outdir one = *d;
    one.e = &d->e[d->n - 1];
    one.n = 1;
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    int rc = m ? 0 : -1;
    if (m) {
        manifest_table(m, &one);
        fclose(m);
        /* the entry's line alone, after the comment lines */
        const char *line = text;
        while (*line == '#' && strchr(line, '\n'))
            line = strchr(line, '\n') + 1;
        size_t n = strlen(line);
        rc = write(fd, line, n) == (ssize_t)n ? 0 : -1;
    }
    free(text);
    close(fd);
    return rc == 0 ? 0 : save(d);
}

/* "SEC.NSEC" into t: 1, or 0. */
static int parse_time(const char *text, struct timespec *t)
{
    long long sec;
    long nsec;
    if (sscanf(text, "%lld.%ld", &sec, &nsec) != 2 || nsec < 0 || nsec > 999999999)
        return 0;
    t->tv_sec = (time_t)sec;
    t->tv_nsec = nsec;
    return 1;
}

/* One line of the manifest. A file's line without its change time (an
 * adhere before it recorded one) proves nothing: the file is then refused,
 * unless --overwrite. */
static void parse_line(adh_outdir *d, const char *line)
{
    char name[64], size[32], mtime[48], ctime[48];
    unsigned long long dev, ino;
    int got = line[0] == '#' ? 0 : sscanf(line, "%63[^\t]\t%llu\t%llu\t%31s\t%47s\t%47s", name, &dev, &ino, size,
                                          mtime, ctime);
    if (got < 5 || !entry_name_ok(name))
        return;
    long long bytes = -1;
    struct timespec mt = { 0, 0 }, ct = { 0, 0 }, bt;
    int identity = strcmp(size, "-") == 0;
    if (!identity && (got < 6 || sscanf(size, "%lld", &bytes) != 1 || bytes < 0 || !parse_time(mtime, &mt) ||
                      !parse_time(ctime, &ct)))
        return;
    /* a record by identity: its birth time in the last column, or '-' (a
     * directory, a filesystem that keeps none, an adhere before it) */
    add_raw(d, name, dev, ino, bytes, &mt, &ct, identity && got == 6 && parse_time(ctime, &bt) ? &bt : NULL);
}

/* d's manifest into its entries. One that is not a regular file of this
 * user's (a link, a pipe, another's) is not trusted: d->foreign_manifest. */
static void load(adh_outdir *d)
{
    int fd = openat(d->fd, ADH_OUTDIR_MANIFEST, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        d->foreign_manifest = errno != ENOENT;
        return;
    }
    struct stat st;
    FILE *f = NULL;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != geteuid() || st.st_size > MANIFEST_MAX ||
        !(f = fdopen(fd, "r"))) {
        d->foreign_manifest = 1;
        close(fd);
        return;
    }
    char line[256];
    while (fgets(line, sizeof line, f)) {
        if (!strchr(line, '\n') && !feof(f)) {   /* longer than any of adhere's: none of its tail is read */
            int c;
            while ((c = getc(f)) != EOF && c != '\n')
                ;
            continue;
        }
        parse_line(d, line);
    }
    fclose(f);
}

/* ------------------------------------------------- opening, clearing */

void adh_outdir_escape(const char *in, char *out, size_t len)
{
    adh_outdir_escape_text(in, out, len, 0);
}

void adh_outdir_escape_text(const char *in, char *out, size_t len, int keep_lines)
{
    adh_outdir_escape_prefix(in, out, len, keep_lines);
}

size_t adh_outdir_escape_prefix(const char *in, char *out, size_t len, int keep_lines)
{
    const char *in0 = in;
    size_t o = 0;
    for (; *in && o + 1 < len; in++) {
        unsigned char b = (unsigned char)*in;
        /* a byte that begins no UTF-8 character too: 0x9b alone is CSI to
         * some terminals, as ESC [ is to all */
        int n = adh_text_utf8_len(in);
        int layout = keep_lines && (b == '\n' || b == '\t');
        if (!layout && (b < 0x20 || b == 0x7f || n == 0)) {
            if (o + 5 > len)
                break;
            snprintf(out + o, len - o, "\\x%02x", b);
            o += 4;
        } else if (o + (size_t)n < len) {   /* a character whole, or none */
            memcpy(out + o, in, (size_t)n);
            o += (size_t)n;
            in += n - 1;
        } else {
            break;
        }
    }
    if (len)
        out[o < len ? o : len - 1] = '\0';
    return (size_t)(in - in0);
}

static adh_outdir *outdir_new(int fd, unsigned flags, const char *path)
{
    adh_outdir *d = calloc(1, sizeof *d);
    if (!d) {
        close(fd);
        return NULL;
    }
    d->fd = fd;
    d->flags = flags;
    d->ix = calloc(1, sizeof *d->ix);   /* none (no memory): find searches linearly */
    adh_outdir_escape(path, d->path, sizeof d->path);   /* messages quote it: no escape sequence reaches a terminal */
    return d;
}

static int clear(adh_outdir *d, int depth, char *why, size_t whylen);
static int foreign(adh_outdir *d, int depth, char *why, size_t whylen);

/* d locked for this run (held until it is closed): 0, or -1 with why when
 * another adhere holds it. */
static int lock(adh_outdir *d, char *why, size_t whylen)
{
    if (flock(d->fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
        snprintf(why, whylen, "%.3000s is in use: another adhere is writing into it (it holds the directory's "
                 "lock); wait for it to finish, or choose another -o", d->path);
        return -1;
    }
    return 0;
}

/* The directory name in dirfd opened without following a link: its
 * descriptor, or -1 with why (path is name as the user reads it, hint what
 * to do when it is a link). */
static int open_nofollow(int dirfd, const char *name, const char *path, const char *hint, char *why, size_t whylen)
{
    int fd = openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        struct stat st;
        int link = e == ELOOP || (fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode));
        if (link)
            snprintf(why, whylen, "%.3000s is a symbolic link: adhere writes through no link; remove it, or %s",
                     path, hint);
        else
            snprintf(why, whylen, "cannot open directory %.3000s: %s", path, strerror(e));
    }
    return fd;
}

/* The directory name in dirfd, never through a link: d with no entries
 * yet, or NULL with why. */
static adh_outdir *open_at(int dirfd, const char *name, const char *path, const char *hint, unsigned flags,
                           char *why, size_t whylen)
{
    int fd = open_nofollow(dirfd, name, path, hint, why, whylen);
    if (fd < 0)
        return NULL;
    adh_outdir *d = outdir_new(fd, flags, path);
    if (!d)
        snprintf(why, whylen, "out of memory");
    return d;
}

/* The run-K directory `name` of d emptied of adhere's files (its own
 * manifest's, or with OVERWRITE every one under adhere's names), then
 * removed when nothing else is in it: 1 removed, 0 kept (the user's files
 * are in it; it then keeps an empty manifest), -1 with why. */
static int empty_subdir(adh_outdir *d, const char *name, unsigned flags, char *why, size_t whylen)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%.4000s/%.40s", d->path, name);
    adh_outdir *s = open_at(d->fd, name, path, "choose another -o", flags, why, whylen);
    if (!s)
        return -1;
    /* a run writing into DIR/run-K itself (-o DIR/run-K) holds its lock */
    if (lock(s, why, whylen) != 0) {
        adh_outdir_close(s);
        return -1;
    }
    load(s);
    int rc = clear(s, 1, why, whylen);
    if (rc == 0 && (flags & ADH_OUTDIR_OVERWRITE))
        rc = foreign(s, 1, why, whylen);
    if (rc == 0 && s->n == 0 && !s->foreign_manifest) {
        unlinkat(s->fd, ADH_OUTDIR_MANIFEST, 0);
        rc = unlinkat(d->fd, name, AT_REMOVEDIR) == 0;
        if (!rc)
            save(s);
    }
    adh_outdir_close(s);
    return rc;
}

/* Every file of d's manifest that is still the one adhere wrote goes; the
 * others leave the manifest (they are no longer adhere's). A run-K is
 * emptied of its own and goes when nothing else is in it. */
static int clear(adh_outdir *d, int depth, char *why, size_t whylen)
{
    for (size_t i = d->n; i-- > 0;) {
        const entry *e = &d->e[i];
        size_t len = strlen(e->name);
        int dir = e->name[len - 1] == '/';
        char base[32];
        snprintf(base, sizeof base, "%.*s", (int)(dir ? len - 1 : len), e->name);
        struct stat st;
        if (fstatat(d->fd, base, &st, AT_SYMLINK_NOFOLLOW) != 0 || !same(d, e, base, &st) || (dir && depth > 0)) {
            drop_entry(d, i);
            continue;
        }
        if (dir) {
            int rc = empty_subdir(d, base, d->flags & ~(unsigned)ADH_OUTDIR_OVERWRITE, why, whylen);
            if (rc < 0)
                return -1;
            if (rc > 0)
                drop_entry(d, i);
            continue;
        }
        if (unlinkat(d->fd, base, 0) != 0 && errno != ENOENT) {
            snprintf(why, whylen, "cannot remove %.3000s/%s, written by an earlier run: %s", d->path, base,
                     strerror(errno));
            return -1;
        }
        drop_entry(d, i);
    }
    return 0;
}

/* --overwrite: a file under one of adhere's names (or a link) removed as
 * if adhere had written it; a directory run-K (never a link to one)
 * emptied of them. */
static int overwrite(adh_outdir *d, const char *name, const struct stat *st, int depth, char *why, size_t whylen)
{
    if (S_ISDIR(st->st_mode))
        return depth == 0 && is_run_dir(name) && empty_subdir(d, name, d->flags, why, whylen) < 0 ? -1 : 0;
    if (unlinkat(d->fd, name, 0) != 0 && errno != ENOENT) {
        snprintf(why, whylen, "cannot remove %.3000s/%s (--overwrite): %s", d->path, name, strerror(errno));
        return -1;
    }
    return 0;
}

/* Files under adhere's names that its manifest does not prove its own:
 * refused by name, or with OVERWRITE removed. */
/* d's entries, from the first; NULL with why. */
static DIR *listing(adh_outdir *d, char *why, size_t whylen)
{
    int dup_fd = dup(d->fd);
    DIR *dir = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
    if (!dir) {
        if (dup_fd >= 0)
            close(dup_fd);
        snprintf(why, whylen, "cannot read %.3000s: %s", d->path, strerror(errno));
    } else {
        rewinddir(dir);   /* a dup shares the offset an earlier listing left at the end */
    }
    return dir;
}

/* A directory where adhere writes a file (force.tsv/, its manifest) is
 * refused even with OVERWRITE: adhere removes no directory of the user's,
 * and nothing can be renamed over one. 0, or -1 with why. */
static int dir_at_file(adh_outdir *d, char *why, size_t whylen)
{
    DIR *dir = listing(d, why, whylen);
    if (!dir)
        return -1;
    int rc = 0;
    struct dirent *de;
    while (rc == 0 && (de = readdir(dir)) != NULL) {
        struct stat st;
        if (adh_outdir_owns(de->d_name) && fstatat(d->fd, de->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 &&
            S_ISDIR(st.st_mode)) {
            snprintf(why, whylen, "%.3000s/%.40s is a directory, where adhere writes a file: refused, not "
                     "replaced (adhere removes no directory of yours, --overwrite neither); move it away, or "
                     "choose another -o", d->path, de->d_name);
            rc = -1;
        }
    }
    closedir(dir);
    return rc;
}

static int foreign(adh_outdir *d, int depth, char *why, size_t whylen)
{
    if (dir_at_file(d, why, whylen) != 0)
        return -1;
    DIR *dir = listing(d, why, whylen);
    if (!dir)
        return -1;
    char list[600] = "";
    size_t count = 0;
    int rc = 0;
    struct dirent *de;
    while (rc == 0 && (de = readdir(dir)) != NULL) {
        const char *name = de->d_name;
        int manifest = strcmp(name, ADH_OUTDIR_MANIFEST) == 0;
        /* a run-K is adhere's only at the top: it makes none inside one */
        int mine = adh_outdir_owns(name) || (depth == 0 && is_run_dir(name));
        struct stat st;
        if ((!mine && !owned_temporary(name)) || fstatat(d->fd, name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (manifest ? !d->foreign_manifest : mine && find(d, name, &st) >= 0)
            continue;
        if (d->flags & ADH_OUTDIR_OVERWRITE)
            rc = overwrite(d, name, &st, depth, why, whylen);
        else if (mine && count++ < 6) {
            char item[64];
            snprintf(item, sizeof item, "%s%.40s%s", *list ? ", " : "", name,
                     S_ISLNK(st.st_mode) ? " (a link)" : S_ISDIR(st.st_mode) ? "/" : "");
            strncat(list, item, sizeof list - strlen(list) - 1);
        }
    }
    closedir(dir);
    if (rc == 0 && count) {
        snprintf(why, whylen, "%.2000s holds %s%s, under names adhere writes but not written by it (or changed "
                 "since it wrote them): refused, so that nothing of yours is removed or replaced; move %s away, "
                 "choose another -o, or pass --overwrite to replace %s", d->path, list, count > 6 ? " and more" : "",
                 count > 1 ? "them" : "it", count > 1 ? "them" : "it");
        return -1;
    }
    return rc;
}

/* KEEP: the earlier run's files stay, their records with them; a record
 * whose file is gone or no longer the one adhere wrote (a run-K the user
 * removed) goes, or it would stay for good, and a temporary a killed run
 * left (never a result) goes with its record. Only the manifest's own
 * records are looked at: nothing else in d is touched. */
static void prune(adh_outdir *d)
{
    for (size_t i = d->n; i-- > 0;) {
        const entry *e = &d->e[i];
        size_t len = strlen(e->name);
        char base[32];
        snprintf(base, sizeof base, "%.*s", (int)(e->name[len - 1] == '/' ? len - 1 : len), e->name);
        struct stat st;
        int here = fstatat(d->fd, base, &st, AT_SYMLINK_NOFOLLOW) == 0 && same(d, e, base, &st);
        if (here && owned_temporary(base) && unlinkat(d->fd, base, 0) == 0)
            here = 0;
        if (!here)
            drop_entry(d, i);
    }
}

/* The rows of a study's runs.tsv in d that adhere wrote (its manifest
 * proves it), 0 without one: each a run's result, perhaps hours of them. */
static long study_rows(const adh_outdir *d)
{
    struct stat st;
    if (fstatat(d->fd, "runs.tsv", &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode) ||
        find(d, "runs.tsv", &st) < 0)
        return 0;
    FILE *f = adh_outdir_read(d->fd, "runs.tsv");
    if (!f)
        return 0;
    long n = 0;
    for (int c, bol = 1; (c = getc(f)) != EOF; bol = c == '\n')
        n += bol && c != '#';
    fclose(f);
    return n > 0 ? n - 1 : 0;   /* its header */
}

/* The results d holds as a study's run-K: its parent's manifest lists d
 * (a run-K of d's device and inode) and the parent's runs.tsv holds that
 * many rows adhere wrote; 0 otherwise. name gets the run-K. */
static long study_run_rows(const adh_outdir *d, char *name, size_t len)
{
    struct stat me;
    if (fstat(d->fd, &me) != 0)
        return 0;
    int pfd = openat(d->fd, "..", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    adh_outdir *p = pfd >= 0 ? outdir_new(pfd, 0, "..") : NULL;
    if (!p)
        return 0;
    load(p);
    long rows = 0;
    for (size_t i = 0; i < p->n && !rows; i++) {
        const entry *e = &p->e[i];
        size_t l = strlen(e->name);
        char run[32];
        struct stat st;
        if (l < 2 || e->name[l - 1] != '/' || e->dev != (unsigned long long)me.st_dev ||
            e->ino != (unsigned long long)me.st_ino)
            continue;
        memcpy(run, e->name, l - 1);   /* name is shorter than run: entry's is 32 too */
        run[l - 1] = '\0';
        if (!is_run_dir(run) || fstatat(p->fd, run, &st, AT_SYMLINK_NOFOLLOW) != 0 || st.st_dev != me.st_dev ||
            st.st_ino != me.st_ino)
            continue;
        rows = study_rows(p);
        snprintf(name, len, "%s", run);
    }
    adh_outdir_close(p);
    return rows;
}

/* The session's inputs by identity (adh_outdir_inputs), each with what
 * it is to the run and the option that named it. */
static struct {
    dev_t dev;
    ino_t ino;
    char path[256];
    const char *what, *option;
} session_input[16];
static size_t ninputs;

void adh_outdir_inputs(const adh_outdir_input *in, size_t n)
{
    struct stat st;
    ninputs = 0;
    for (size_t i = 0; i < n && ninputs < sizeof session_input / sizeof session_input[0]; i++)
        if (in[i].path && *in[i].path && stat(in[i].path, &st) == 0 && S_ISREG(st.st_mode)) {
            session_input[ninputs].dev = st.st_dev, session_input[ninputs].ino = st.st_ino;
            adh_outdir_escape(in[i].path, session_input[ninputs].path, sizeof session_input[ninputs].path);
            session_input[ninputs].what = in[i].what;
            session_input[ninputs].option = in[i].option;
            ninputs++;
        }
}

int adh_outdir_input_named(const char *path, const char **what, const char **option)
{
    struct stat out;
    if (lstat(path, &out) != 0 || !S_ISREG(out.st_mode))
        return 0;
    for (size_t i = 0; i < ninputs; i++)
        if (session_input[i].dev == out.st_dev && session_input[i].ino == out.st_ino) {
            *what = session_input[i].what;
            *option = session_input[i].option;
            return 1;
        }
    return 0;
}

/* A file under one of adhere's names in d that is an input of this
 * session: clearing d (as an earlier run's, or --overwrite) would remove
 * it. 0, or -1 with why. */
static int removes_input(const adh_outdir *d, char *why, size_t whylen)
{
    for (size_t k = 0; k < sizeof owned / sizeof owned[0] && ninputs; k++) {
        struct stat st;
        if (fstatat(d->fd, owned[k], &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode))
            continue;
        for (size_t i = 0; i < ninputs; i++)
            if (st.st_dev == session_input[i].dev && st.st_ino == session_input[i].ino) {
                snprintf(why, whylen, "%.3000s/%s is read by this run (as %s), and a run into %.3000s would remove "
                         "or replace it: copy it elsewhere first, or give another -o", d->path, owned[k],
                         session_input[i].path, d->path);
                return -1;
            }
    }
    return 0;
}

/* Locked, the earlier run's files cleared (KEEP: their stale records),
 * foreign files refused, the manifest written: d is ready for this run's
 * files. */
static int prepare(adh_outdir *d, int depth, char *why, size_t whylen)
{
    if (lock(d, why, whylen) != 0)
        return -1;
    if (faccessat(d->fd, ".", W_OK | X_OK, AT_EACCESS) != 0) {
        snprintf(why, whylen, "cannot write into %.3000s: %s", d->path, strerror(errno));
        return -1;
    }
    load(d);
    /* a run, a fit or the TUI's plots into a study's directory removed its
     * results without a word: only --overwrite does (a study opens with
     * KEEP and decides itself) */
    long rows = depth || (d->flags & (ADH_OUTDIR_KEEP | ADH_OUTDIR_OVERWRITE)) ? 0 : study_rows(d);
    if (rows > 0) {
        snprintf(why, whylen, "%.3000s holds a study's results (%ld run%s in runs.tsv), which a run there would "
                 "remove: give another -o, or --overwrite to replace them", d->path, rows, rows == 1 ? "" : "s");
        return -1;
    }
    /* nor a run-K of one, whose tables sweep.tsv and runs.tsv still describe */
    char run[32];
    rows = depth || (d->flags & (ADH_OUTDIR_KEEP | ADH_OUTDIR_OVERWRITE)) ? 0 : study_run_rows(d, run, sizeof run);
    if (rows > 0) {
        snprintf(why, whylen, "%.3000s is %s of a study (%ld run%s in its runs.tsv), whose tables a run there would "
                 "replace: give another -o, or --overwrite to replace them", d->path, run, rows, rows == 1 ? "" : "s");
        return -1;
    }
    /* refused before anything is removed; KEEP: an earlier study's files stay */
    if ((!(d->flags & ADH_OUTDIR_KEEP) && removes_input(d, why, whylen) != 0) || foreign(d, depth, why, whylen) != 0 || (!(d->flags & ADH_OUTDIR_KEEP) && clear(d, depth, why, whylen) != 0))
        return -1;
    if (d->flags & ADH_OUTDIR_KEEP)
        prune(d);
    d->foreign_manifest = 0;
    return save_why(d, why, whylen);
}

/* mkdir -p: each missing component of path made. */
static int make_path(const char *path, char *why, size_t whylen)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1;; p++) {
        if (*p && *p != '/')
            continue;
        char c = *p;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            int e = errno;
            char shown[SHOWN_MAX], reason[200];
            adh_outdir_escape(buf, shown, sizeof shown);
            /* the one before it is there (a dangling link is not): the
             * refusal is this mkdir's, in a directory that exists */
            char *up = strrchr(buf, '/');
            struct stat st;
            if (up)
                *up = '\0';
            int in_dir = stat(!up ? "." : up == buf ? "/" : buf, &st) == 0 && S_ISDIR(st.st_mode);
            snprintf(why, whylen, "cannot create directory %.3000s: %s", shown,
                     in_dir ? create_reason("the directory it goes in", e, reason, sizeof reason) : strerror(e));
            return -1;
        }
        *p = c;
        if (!c)
            return 0;
    }
}

/* Why the directory path did not open (e), in words that say what is there. */
static void open_failed(const char *raw, int e, char *why, size_t whylen)
{
    struct stat st;
    char target[512], shown_target[4 * sizeof target];
    char path[SHOWN_MAX];
    adh_outdir_escape(raw, path, sizeof path);
    ssize_t n = e == ENOENT ? readlink(raw, target, sizeof target - 1) : -1;
    if (n >= 0) {
        target[n] = '\0';
        adh_outdir_escape(target, shown_target, sizeof shown_target);
        snprintf(why, whylen, "cannot write into %.3000s: it is a symbolic link to %.400s, which does not exist; "
                 "make that directory, or choose another -o", path, shown_target);
    } else if (e == EACCES && stat(raw, &st) == 0 && S_ISDIR(st.st_mode) && access(raw, W_OK | X_OK) == 0) {
        snprintf(why, whylen, "cannot read directory %.3000s: %s (adhere reads a directory before it writes "
                 "into it, to remove only its own files)", path, strerror(e));
    } else {
        snprintf(why, whylen, "cannot write into %.3000s: %s", path, strerror(e));
    }
}

adh_outdir *adh_outdir_open(const char *path, unsigned flags, char *why, size_t whylen)
{
    if (!path[0] || strlen(path) >= PATH_MAX) {
        char shown[1024];
        adh_outdir_escape(path, shown, sizeof shown);
        snprintf(why, whylen, "cannot write into %.200s...: %s", shown, strerror(path[0] ? ENAMETOOLONG : ENOENT));
        return NULL;
    }
    if (make_path(path, why, whylen) != 0)
        return NULL;
    /* the directory the user named, through any link in that name: the
     * names inside it are the ones no link may redirect */
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        open_failed(path, errno, why, whylen);
        return NULL;
    }
    adh_outdir *d = outdir_new(fd, flags, path);
    if (!d) {
        snprintf(why, whylen, "out of memory");
        return NULL;
    }
    if (prepare(d, 0, why, whylen) != 0) {
        adh_outdir_close(d);
        return NULL;
    }
    return d;
}

/* name's components below dirfd (which is closed), each made if missing
 * and entered without following a link: the last one's d, or NULL with why. */
static adh_outdir *walk_in(int dirfd, const char *path, const char *name, unsigned flags, char *why, size_t whylen)
{
    const char *hint = path ? "choose another -o" : "give -o DIR to write elsewhere";
    char shown_raw[PATH_MAX + 64], comp[PATH_MAX];
    size_t at = path ? (size_t)snprintf(shown_raw, sizeof shown_raw, "%s/", path) : 0;
    for (const char *c = name;;) {
        size_t n = strcspn(c, "/");   /* name is shorter than PATH_MAX */
        memcpy(comp, c, n < sizeof comp ? n : sizeof comp - 1);
        comp[n < sizeof comp ? n : sizeof comp - 1] = '\0';
        at += (size_t)snprintf(shown_raw + at, sizeof shown_raw - at, "%s%s", at && shown_raw[at - 1] != '/' ? "/" : "",
                               comp);
        char shown[SHOWN_MAX];
        adh_outdir_escape(shown_raw, shown, sizeof shown);
        if (mkdirat(dirfd, comp, 0777) != 0 && errno != EEXIST) {
            char reason[200];
            snprintf(why, whylen, "cannot create directory %.3000s: %s", shown,
                     create_reason("the directory it goes in", errno, reason, sizeof reason));
            close(dirfd);
            return NULL;
        }
        if (!c[n]) {   /* a link there is refused, not followed */
            adh_outdir *d = open_at(dirfd, comp, shown, hint, flags, why, whylen);
            close(dirfd);
            return d;
        }
        int fd = open_nofollow(dirfd, comp, shown, hint, why, whylen);
        close(dirfd);
        if (fd < 0)
            return NULL;
        dirfd = fd;
        c += n + 1;
    }
}

adh_outdir *adh_outdir_open_in(const char *path, const char *name, unsigned flags, char *why, size_t whylen)
{
    char sub[PATH_MAX + 64];
    int n = path ? snprintf(sub, sizeof sub, "%s/%s", path, name) : snprintf(sub, sizeof sub, "%s", name);
    if ((path && !path[0]) || n >= PATH_MAX) {
        char shown[1024];
        adh_outdir_escape(path ? path : name, shown, sizeof shown);
        snprintf(why, whylen, "cannot write into %.200s...: %s", shown, strerror(n >= PATH_MAX ? ENAMETOOLONG : ENOENT));
        return NULL;
    }
    if (path && make_path(path, why, whylen) != 0)
        return NULL;
    int fd = open(path ? path : ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        open_failed(path ? path : ".", errno, why, whylen);
        return NULL;
    }
    adh_outdir *d = walk_in(fd, path, name, flags, why, whylen);
    if (d && prepare(d, 0, why, whylen) != 0) {
        adh_outdir_close(d);
        return NULL;
    }
    return d;
}

adh_outdir *adh_outdir_sub(adh_outdir *d, const char *name, char *why, size_t whylen)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%.4000s/%.40s", d->path, name);
    if (mkdirat(d->fd, name, 0777) != 0 && errno != EEXIST) {
        char reason[200];
        snprintf(why, whylen, "cannot create directory %.3000s: %s", path,
                 create_reason("the directory it goes in", errno, reason, sizeof reason));
        return NULL;
    }
    struct stat st;
    if (fstatat(d->fd, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode) && find(d, name, &st) < 0) {
        char dir[40];
        snprintf(dir, sizeof dir, "%s/", name);
        if (add_entry(d, dir, &st, 0) != 0 || save_added(d) != 0) {
            snprintf(why, whylen, "cannot write into %.3000s: %s", d->path, strerror(errno ? errno : ENOMEM));
            return NULL;
        }
    }
    adh_outdir *s = open_at(d->fd, name, path, "choose another -o", d->flags & ~(unsigned)ADH_OUTDIR_KEEP, why,
                            whylen);
    if (s && prepare(s, 1, why, whylen) != 0) {
        adh_outdir_close(s);
        return NULL;
    }
    return s;
}

int adh_outdir_clear(adh_outdir *d, char *why, size_t whylen)
{
    if (removes_input(d, why, whylen) != 0 || clear(d, 0, why, whylen) != 0)
        return -1;
    return save_why(d, why, whylen);
}

int adh_outdir_fd(const adh_outdir *d)
{
    return d->fd;
}

FILE *adh_outdir_read(int dirfd, const char *name)
{
    int fd = openat(dirfd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    if (fd >= 0 && (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
        close(fd);
        errno = EINVAL;   /* a pipe or device under the name: not adhere's */
        return NULL;
    }
    FILE *f = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!f && fd >= 0) {
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

const char *adh_outdir_read_error(int err)
{
    if (err == EINVAL)
        return "not a regular file (a pipe, device or directory under the name; adhere reads only the files it wrote)";
    if (err == ELOOP)
        return "a symbolic link (adhere reads no file through a link)";
    return strerror(err);
}

int adh_outdir_has(const adh_outdir *d, const char *name)
{
    struct stat st;
    return fstatat(d->fd, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && find(d, name, &st) >= 0;
}

void adh_outdir_close(adh_outdir *d)
{
    if (!d)
        return;
    adh_outdir_abandon(d);   /* never committed: nothing half-done stays */
    close(d->fd);
    free(d->st);
    if (d->ix)
        free(d->ix->slot);
    free(d->ix);
    free(d->e);
    free(d);
}

const char *adh_outdir_path(const adh_outdir *d)
{
    return d->path;
}

/* ------------------------------------------------------------ files */

/* Whether name may be made or replaced in d: absent, adhere's own, or
 * --overwrite. */
static int may_replace(const adh_outdir *d, const char *name)
{
    struct stat st;
    if (fstatat(d->fd, name, &st, AT_SYMLINK_NOFOLLOW) != 0)
        return errno == ENOENT;
    return (d->flags & ADH_OUTDIR_OVERWRITE) || find(d, name, &st) >= 0;
}

static void not_replaced(const adh_outdir *d, const char *name, char *why, size_t whylen)
{
    snprintf(why, whylen, "cannot write %.3000s/%s: a file adhere did not write is there (left alone; "
             "--overwrite replaces it)", d->path, name);
}

/* The newest record of name kept, every older one and tmp's dropped. */
static void keep_newest(adh_outdir *d, const char *name, const char *tmp)
{
    long newest = -1;
    for (size_t i = 0; i < d->n; i++)
        if (!strcmp(d->e[i].name, name))
            newest = (long)i;
    entry keep = newest >= 0 ? d->e[newest] : (entry){ .size = 0 };
    for (size_t i = d->n; i-- > 0;)
        if (!strcmp(d->e[i].name, name) || !strcmp(d->e[i].name, tmp))
            drop_entry(d, i);
    if (newest >= 0)
        d->e[d->n++] = keep;   /* room: at least that one was dropped */
    index_stale(d);
}

/* ------------------------------------------------- staged files */

/* The staged temporary of name, or -1. */
static long stage_find(const adh_outdir *d, const char *name)
{
    for (size_t i = 0; i < d->nst; i++)
        if (!strcmp(d->st[i].name, name))
            return (long)i;
    return -1;
}

/* The record of the file (a temporary) called name dropped. */
static void drop_named(adh_outdir *d, const char *name)
{
    for (size_t i = d->n; i-- > 0;)
        if (!strcmp(d->e[i].name, name))
            drop_entry(d, i);
}

/* Staged entry i's temporary removed with its record. */
static void stage_drop(adh_outdir *d, size_t i)
{
    unlinkat(d->fd, d->st[i].tmp, 0);
    drop_named(d, d->st[i].tmp);
    d->st[i] = d->st[--d->nst];
}

/* tmp, now whole, waits to become name; an earlier staged name's goes. 0, or -1. */
static int stage_push(adh_outdir *d, const char *name, const char *tmp)
{
    long old = stage_find(d, name);
    if (old >= 0)
        stage_drop(d, (size_t)old);
    if (d->nst == d->capst) {
        size_t cap = d->capst ? 2 * d->capst : 8;
        staged *t = realloc(d->st, cap * sizeof *t);
        if (!t)
            return -1;
        d->st = t, d->capst = cap;
    }
    snprintf(d->st[d->nst].tmp, sizeof d->st[0].tmp, "%s", tmp);
    snprintf(d->st[d->nst].name, sizeof d->st[0].name, "%s", name);
    d->nst++;
    return 0;
}

void adh_outdir_stage(adh_outdir *d)
{
    d->staging = 1;
}

void adh_outdir_abandon(adh_outdir *d)
{
    if (!d->nst && !d->staging)
        return;
    while (d->nst)
        stage_drop(d, d->nst - 1);
    d->staging = 0;
    save(d);
}

/* Whether name is staged now: a name a staged file will take, or its temporary. */
static int staged_now(const adh_outdir *d, const char *name)
{
    for (size_t k = 0; k < d->nst; k++)
        if (!strcmp(name, d->st[k].name) || !strcmp(name, d->st[k].tmp))
            return 1;
    return 0;
}

/* The files of d's manifest not staged now, and still as an earlier run
 * wrote them, removed (run-K directories stay). */
static void clear_unstaged(adh_outdir *d)
{
    for (size_t i = d->n; i-- > 0;) {
        const entry *e = &d->e[i];
        size_t len = strlen(e->name);
        struct stat st;
        if (staged_now(d, e->name) || (len && e->name[len - 1] == '/'))
            continue;
        if (fstatat(d->fd, e->name, &st, AT_SYMLINK_NOFOLLOW) == 0 && same(d, e, e->name, &st))
            unlinkat(d->fd, e->name, 0);
        drop_entry(d, i);
    }
}

size_t adh_outdir_earlier(const adh_outdir *d, const char *suffix, char *buf, size_t len)
{
    size_t count = 0, o = 0;
    if (len)
        buf[0] = '\0';
    size_t ns = suffix ? strlen(suffix) : 0;
    for (size_t i = 0; i < d->n; i++) {
        const entry *e = &d->e[i];
        size_t n = strlen(e->name);
        struct stat st;
        if (staged_now(d, e->name) || e->name[n - 1] == '/' || owned_temporary(e->name) || n < ns ||
            (suffix && strcmp(e->name + n - ns, suffix)) || fstatat(d->fd, e->name, &st, AT_SYMLINK_NOFOLLOW) != 0 ||
            !same(d, e, e->name, &st))
            continue;
        if (o + n + 3 <= len) {   /* room for ", " and the name: else cut there */
            if (count)
                memcpy(buf + o, ", ", 2), o += 2;
            memcpy(buf + o, e->name, n + 1);
            o += n;
        }
        count++;
    }
    return count;
}

int adh_outdir_commit(adh_outdir *d, int replace, char *why, size_t whylen)
{
    int e = 0;
    size_t done = 0;
    for (; done < d->nst; done++) {
        staged *s = &d->st[done];
        struct stat st, now;
        /* as adh_outdir_write records it: before the rename and after */
        if (fstatat(d->fd, s->tmp, &st, AT_SYMLINK_NOFOLLOW) != 0 || add_entry(d, s->name, &st, 0) != 0 ||
            save(d) != 0 || renameat(d->fd, s->tmp, d->fd, s->name) != 0) {
            e = errno ? errno : ENOMEM;
            snprintf(why, whylen, "cannot write %.3000s/%s: %s", d->path, s->name, strerror(e));
            break;
        }
        if (fstatat(d->fd, s->name, &now, AT_SYMLINK_NOFOLLOW) == 0 && now.st_ino == st.st_ino)
            add_entry(d, s->name, &now, 0);
        keep_newest(d, s->name, s->tmp);
    }
    /* the earlier files go only once every new one is in place: a commit
     * that fails part way removes none of them */
    if (!e && replace)
        clear_unstaged(d);
    if (done) {   /* the committed leave the staged list */
        memmove(d->st, d->st + done, (d->nst - done) * sizeof *d->st);
        d->nst -= done;
    }
    adh_outdir_abandon(d);   /* what a failure left, and the mode */
    save(d);
    return e ? -1 : 0;
}

int adh_outdir_write(adh_outdir *d, const char *name, adh_outdir_writer writer, const void *ctx, char *why,
                     size_t whylen)
{
    if (!may_replace(d, name)) {
        not_replaced(d, name, why, whylen);
        return -1;
    }
    char tmp[64];
    struct stat st;
    size_t before = d->n;
    int fd = temp_create(d->fd, name, tmp, sizeof tmp);
    int e = fd < 0 ? errno : 0;
    /* the temporary is recorded (by identity) before a byte goes into it:
     * one a kill leaves is the next run's to remove */
    if (!e && (fstat(fd, &st) != 0 || add_entry(d, tmp, &st, 1) != 0 || save(d) != 0)) {
        e = errno ? errno : ENOMEM;
        close(fd);
    } else if (!e) {
        e = fill(fd, writer, ctx, &st);
    }
    /* recorded before the rename (a manifest that cannot be written stops
     * it), and again after it, which moves the change time: a kill between
     * the two leaves the new file unproven, so a later run refuses it (never
     * takes it for the user's), and the older record keeps the older file
     * proven until it is replaced */
    if (!e && d->staging) {
        if (stage_push(d, name, tmp) == 0)
            return 0;
        e = ENOMEM;
    }
    if (!e && (add_entry(d, name, &st, 0) != 0 || save(d) != 0))
        e = errno ? errno : ENOMEM;
    if (!e && renameat(d->fd, tmp, d->fd, name) != 0)
        e = errno;
    if (e) {
        if (fd >= 0)
            unlinkat(d->fd, tmp, 0);
        d->n = before < d->n ? before : d->n;
        index_stale(d);
        snprintf(why, whylen, "cannot write %.3000s/%s: %s", d->path, name, strerror(e));
        return -1;
    }
    struct stat now;
    if (fstatat(d->fd, name, &now, AT_SYMLINK_NOFOLLOW) == 0 && now.st_dev == st.st_dev && now.st_ino == st.st_ino)
        add_entry(d, name, &now, 0);
    keep_newest(d, name, tmp);
    save(d);
    return 0;
}

/* A log staged: made under a temporary, renamed by adh_outdir_commit. */
static int log_stage(adh_outdir *d, const char *name, char *why, size_t whylen)
{
    char tmp[64];
    struct stat st;
    int fd = temp_open(d->fd, name, O_RDWR | O_APPEND, tmp, sizeof tmp);
    if (fd < 0 || fstat(fd, &st) != 0 || add_entry(d, tmp, &st, 1) != 0 || save(d) != 0 ||
        stage_push(d, name, tmp) != 0) {
        snprintf(why, whylen, "cannot open gnuplot's log %.3000s/%s: %s", d->path, name, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlinkat(d->fd, tmp, 0);
            drop_named(d, tmp);
        }
        return -1;
    }
    return fd;
}

int adh_outdir_log_open(adh_outdir *d, const char *name, char *why, size_t whylen)
{
    if (!may_replace(d, name)) {
        not_replaced(d, name, why, whylen);
        return -1;
    }
    if (d->staging)
        return log_stage(d, name, why, whylen);
    /* an earlier log of this run's goes (each holds one session's
     * complaints), and with it its record */
    unlinkat(d->fd, name, 0);
    for (size_t i = d->n; i-- > 0;)
        if (!strcmp(d->e[i].name, name))
            drop_entry(d, i);
    int fd = openat(d->fd, name, O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_APPEND | O_CLOEXEC, 0666);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || add_entry(d, name, &st, 1) != 0 || save(d) != 0) {
        snprintf(why, whylen, "cannot open gnuplot's log %.3000s/%s: %s", d->path, name, strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    return fd;
}

int adh_outdir_append(adh_outdir *d, const char *name, char *why, size_t whylen)
{
    if (!may_replace(d, name)) {
        not_replaced(d, name, why, whylen);
        return -1;
    }
    int fd = openat(d->fd, name, O_WRONLY | O_CREAT | O_APPEND | O_NOFOLLOW | O_CLOEXEC, 0666);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(why, whylen, "cannot open %.3000s/%s: %s", d->path, name, fd < 0 ? strerror(errno) : "not a regular file");
        if (fd >= 0)
            close(fd);
        return -1;
    }
    for (size_t i = d->n; i-- > 0;)
        if (!strcmp(d->e[i].name, name))
            drop_entry(d, i);
    if (add_entry(d, name, &st, 1) != 0 || save(d) != 0) {
        snprintf(why, whylen, "cannot write into %.3000s: %s", d->path, strerror(errno ? errno : ENOMEM));
        close(fd);
        return -1;
    }
    return fd;
}

void adh_outdir_log_close(adh_outdir *d, const char *name, int fd)
{
    struct stat st, now;
    if (fd < 0)
        return;
    long i = -1, k = stage_find(d, name);
    if (k >= 0) {   /* staged: an empty log is not kept, a full one waits */
        if (fstat(fd, &st) == 0 && st.st_size == 0)
            stage_drop(d, (size_t)k);
        save(d);
        close(fd);
        return;
    }
    if (fstat(fd, &st) == 0 && fstatat(d->fd, name, &now, AT_SYMLINK_NOFOLLOW) == 0 &&
        now.st_dev == st.st_dev && now.st_ino == st.st_ino)
        i = find(d, name, &now);
    if (i >= 0) {
        /* empty: removed; else recorded as it ends, size and time too */
        drop_entry(d, (size_t)i);
        if (st.st_size > 0 || unlinkat(d->fd, name, 0) != 0)
            add_entry(d, name, &now, 0);
        save(d);
    }
    close(fd);
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

/* path's directory part into dir (PATH_MAX bytes; path is shorter):
 * its last component, or NULL when path names no file (too long, or
 * "", ".", ".." there: *e the errno to say, EISDIR only where a directory
 * stands: "nodir/" is no such directory, "afile/" not a directory). */
static const char *outfile_dir(const char *path, char *dir, int *e)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    struct stat st;
    if (strlen(path) >= PATH_MAX - 16) {
        *e = ENAMETOOLONG;
        return NULL;
    }
    if (!*base || !strcmp(base, ".") || !strcmp(base, "..")) {
        *e = !*path ? ENOENT : stat(path, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : ENOTDIR;
        return NULL;
    }
    /* shorter than path (checked above): copied, not printed, so that no
     * compiler sees a truncation to warn about */
    size_t dl = slash ? (slash == path ? 1 : (size_t)(slash - path)) : 1;
    memcpy(dir, slash ? path : ".", dl);
    dir[dl] = '\0';
    return base;
}

const char *adh_outfile_reason(const char *path, int e, char *buf, size_t len)
{
    char dir[PATH_MAX], shown[SHOWN_MAX];
    struct stat st;
    int bad;
    if (e == ENXIO)
        return "a pipe no program reads";
    /* ENOENT with the directory there: the create's, in it (the open of a
     * missing directory gives ENOENT too, and the system's words then) */
    if (e != ENOENT || !outfile_dir(path, dir, &bad) || stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        return strerror(e);
    char what[SHOWN_MAX + 16];
    adh_outdir_escape(dir, shown, sizeof shown);
    snprintf(what, sizeof what, "the directory %.3000s", shown);
    return create_reason(what, e, buf, len);
}

/* path's directory opened into *dfd (-1 when it is not) and its last
 * component in *base, what stands there in *st (*there 0 when nothing
 * does): 0, or the errno that refuses path before anything is made there
 * (a name too long, no file name, no such directory, a directory at path). */
static int outfile_at(const char *path, int *dfd, const char **base, struct stat *st, int *there)
{
    char dir[PATH_MAX];
    int e;
    *dfd = -1;
    *there = 0;
    if (!(*base = outfile_dir(path, dir, &e)))
        return e;
    *dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (*dfd < 0)
        return errno;
    *there = fstatat(*dfd, *base, st, AT_SYMLINK_NOFOLLOW) == 0;
    /* a rename cannot put a file over a directory */
    return *there && S_ISDIR(st->st_mode) ? EISDIR : 0;
}

int adh_outfile_check(const char *path)
{
    const char *base;
    struct stat st;
    int dfd, there, e = outfile_at(path, &dfd, &base, &st, &there);
    if (dfd >= 0)
        close(dfd);
    return e;
}

int adh_outfile_write(const char *path, adh_outdir_writer writer, const void *ctx)
{
    char tmp[PATH_MAX];
    const char *base;
    struct stat st;
    int dfd, there, e = outfile_at(path, &dfd, &base, &st, &there);
    if (!e && there && !S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode) && !S_ISDIR(st.st_mode)) {
        /* a terminal, pipe or /dev/null: written in place, nothing to
         * replace. Opened without waiting: a pipe no program reads would
         * hold the open for ever (the screen frozen), and is ENXIO */
        int fd = openat(dfd, base, O_WRONLY | O_NOFOLLOW | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
        if (fd >= 0 && fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) != 0) {
            close(fd);
            fd = -1;
        }
        e = fd < 0 ? errno : fill(fd, writer, ctx, NULL);
    } else if (there && S_ISREG(st.st_mode) && !(st.st_mode & 0222)) {
        /* made read-only by its owner: kept, as a shell's > keeps it (the
         * rename below would replace it, root or not) */
        e = EACCES;
    } else if (!e) {
        int fd = temp_create(dfd, base, tmp, sizeof tmp);
        e = fd < 0 ? errno : fill(fd, writer, ctx, NULL);
        if (!e && renameat(dfd, tmp, dfd, base) != 0)
            e = errno;
        if (e && fd >= 0)
            unlinkat(dfd, tmp, 0);
    }
    if (dfd >= 0)
        close(dfd);
    return e;
}
