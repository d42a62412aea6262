/* What may stand under a final name in an output directory: adh_png_check
 * takes a whole PNG and nothing less (every cut of one, a text file, data
 * after IEND, an empty file said as such); an output directory removes
 * only what adhere wrote there (its manifest), refuses a user's file under
 * an adhere name, a second run at once and a link, and writes through no
 * link; adh_outfile_write replaces a link at the path. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "plot/outdir.h"
#include "plot/png.h"
#include "tap.h"

static char work[256];

static void put_file(const char *path, const unsigned char *b, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(b, 1, n, f);
        fclose(f);
    }
}

static size_t chunk(unsigned char *out, const char *type, size_t len)
{
    out[0] = (unsigned char)(len >> 24);
    out[1] = (unsigned char)(len >> 16);
    out[2] = (unsigned char)(len >> 8);
    out[3] = (unsigned char)len;
    memcpy(out + 4, type, 4);
    memset(out + 8, 0x5a, len);
    /* the CRC is not checked; IEND's is the real one */
    static const unsigned char iend_crc[4] = { 0xae, 0x42, 0x60, 0x82 };
    memcpy(out + 8 + len, strcmp(type, "IEND") == 0 ? iend_crc : (const unsigned char *)"\1\2\3\4", 4);
    return 12 + len;
}

static void test_png_check(void)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    unsigned char png[256];
    size_t n = 0;
    memcpy(png, sig, 8);
    n = 8;
    n += chunk(png + n, "IHDR", 13);
    n += chunk(png + n, "IDAT", 40);
    n += chunk(png + n, "IDAT", 7);
    n += chunk(png + n, "IEND", 0);
    char path[300], why[200];
    snprintf(path, sizeof path, "%s/x.png", work);
    put_file(path, png, n);
    ok(adh_png_check(path, why, sizeof why) == 0, "a whole PNG (%zu bytes) passes", n);
    size_t cut_ok = 0;
    for (size_t k = 0; k < n; k++) {
        put_file(path, png, k);
        cut_ok += adh_png_check(path, why, sizeof why) != 0;
    }
    ok(cut_ok == n, "every one of its %zu cuts is refused (%zu were)", n, cut_ok);
    put_file(path, png, n - 5);
    adh_png_check(path, why, sizeof why);
    ok(strstr(why, "cut short") != NULL, "a cut inside IEND says: %s", why);
    put_file(path, png, n - 20);
    adh_png_check(path, why, sizeof why);
    ok(strstr(why, "cut short") != NULL, "a cut before IEND says: %s", why);
    unsigned char more[300];
    memcpy(more, png, n);
    memcpy(more + n, "junk", 4);
    put_file(path, more, n + 4);
    ok(adh_png_check(path, why, sizeof why) != 0 && strstr(why, "after"), "data after IEND is refused: %s", why);
    const char text[] = "    force F (uN)\n  0.2 |-+   ***\n";
    put_file(path, (const unsigned char *)text, sizeof text - 1);
    ok(adh_png_check(path, why, sizeof why) != 0 && strstr(why, "not a PNG"),
       "a text file (a dumb terminal's plot) is refused: %s", why);
    memcpy(more, png, n);
    memcpy(more + 12, "IDAT", 4);
    put_file(path, more, n);
    ok(adh_png_check(path, why, sizeof why) != 0, "a PNG without IHDR first is refused: %s", why);
    put_file(path, png, 0);
    ok(adh_png_check(path, why, sizeof why) != 0 && strstr(why, "empty") && !strstr(why, "style"),
       "an empty image (a full disk) is said to be empty, not blamed on a style: %s", why);
    snprintf(path, sizeof path, "%s/missing.png", work);
    ok(adh_png_check(path, why, sizeof why) != 0, "a missing file is refused: %s", why);
}

static int write_text(FILE *f, const void *ctx)
{
    fputs((const char *)ctx, f);
    return 0;
}

static int fail_writer(FILE *f, const void *ctx)
{
    (void)ctx;
    fputs("half a table", f);
    return -1;
}

/* The file's text ("" when it cannot be read). */
static const char *text_of(const char *path)
{
    static char buf[256];
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (f) {
        size_t n = fread(buf, 1, sizeof buf - 1, f);
        buf[n] = '\0';
        fclose(f);
    }
    return buf;
}

static int is_link(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && S_ISLNK(st.st_mode);
}

/* Names in dir starting with a dot, but for the manifest. */
static int hidden(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
             strcmp(e->d_name, ADH_OUTDIR_MANIFEST);
    if (d)
        closedir(d);
    return n;
}

static void put_text(const char *dir, const char *name, const char *text)
{
    char p[400];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    put_file(p, (const unsigned char *)text, strlen(text));
}

static void test_owns(void)
{
    static const char *const mine[] = {
        "force.tsv", "summary.tsv", "turns.tsv", "static.tsv", "profiles.tsv", "contact.tsv", "sweep.tsv",
        "cost.tsv", "force.png", "profile.png", "contact.png", "precontact.png", "bulge.png", "jump.png",
        "cost.png", "gnuplot.log", "gnuplot-figures.log", ADH_OUTDIR_MANIFEST,
    };
    static const char *const theirs[] = {
        "notes.txt", "force.tsv.bak", "Force.tsv", "force.tsv~", ".force.png.tmp123", ".summary.tsv.4242.tmp",
        "run-1", "my.png", ".force.tsv", "gnuplot.log.old",
    };
    size_t a = 0, b = 0;
    for (size_t i = 0; i < sizeof mine / sizeof mine[0]; i++)
        a += adh_outdir_owns(mine[i]) != 0;
    for (size_t i = 0; i < sizeof theirs / sizeof theirs[0]; i++)
        b += !adh_outdir_owns(theirs[i]);
    ok(a == sizeof mine / sizeof mine[0], "every name adhere writes is adhere's (%zu)", a);
    ok(b == sizeof theirs / sizeof theirs[0], "look-alikes and temporaries are not names it writes (%zu)", b);
}

/* What adhere wrote goes with the next run; nothing else does, and nothing
 * is written through a link. */
static void test_outdir(void)
{
    char d[300], p[400], q[400], why[1200];
    snprintf(d, sizeof d, "%s/out", work);
    adh_outdir *od = adh_outdir_open(d, 0, why, sizeof why);
    ok(od != NULL, "a new directory opens (%s)", od ? "made" : why);
    if (!od)
        return;
    ok(adh_outdir_write(od, "force.tsv", write_text, "run 1\n", why, sizeof why) == 0 &&
       adh_outdir_write(od, "force.png", write_text, "png 1\n", why, sizeof why) == 0, "two files written");
    ok(adh_outdir_write(od, "summary.tsv", fail_writer, NULL, why, sizeof why) != 0 && strstr(why, "summary.tsv"),
       "a writer that fails: refused, named (%s)", why);
    snprintf(p, sizeof p, "%s/summary.tsv", d);
    ok(access(p, F_OK) != 0 && hidden(d) == 0, "... no file under its name and no temporary left");
    adh_outdir *two = adh_outdir_open(d, 0, why, sizeof why);
    ok(!two && strstr(why, "in use"), "a second run into it while the first writes is refused: %s", why);
    adh_outdir_close(two);
    adh_outdir_close(od);

    /* the user's files beside adhere's, and one of adhere's the user rewrote */
    put_text(d, "notes.txt", "mine");
    od = adh_outdir_open(d, 0, why, sizeof why);
    snprintf(p, sizeof p, "%s/force.tsv", d);
    snprintf(q, sizeof q, "%s/notes.txt", d);
    ok(od && access(p, F_OK) != 0 && !strcmp(text_of(q), "mine"),
       "the next run removes run 1's files and keeps the user's (%s)", od ? "opened" : why);
    ok(adh_outdir_write(od, "force.tsv", write_text, "run 2\n", why, sizeof why) == 0, "run 2 writes force.tsv");
    adh_outdir_close(od);
    put_text(d, "force.tsv", "edited by the user\n");   /* in place: same inode, new size */
    od = adh_outdir_open(d, 0, why, sizeof why);
    ok(!od && strstr(why, "force.tsv") && strstr(why, "--overwrite") &&
       !strcmp(text_of(p), "edited by the user\n"),
       "a file of adhere's the user changed is no longer adhere's: refused, kept: %s", why);
    adh_outdir_close(od);

    /* a user's file under one of adhere's names, in a directory adhere never wrote */
    char u[300];
    snprintf(u, sizeof u, "%s/user", work);
    mkdir(u, 0755);
    put_text(u, "cost.tsv", "my costs");
    od = adh_outdir_open(u, 0, why, sizeof why);
    snprintf(q, sizeof q, "%s/cost.tsv", u);
    ok(!od && strstr(why, "cost.tsv") && !strcmp(text_of(q), "my costs"),
       "a user's cost.tsv in a reused directory: refused, kept: %s", why);
    od = adh_outdir_open(u, ADH_OUTDIR_OVERWRITE, why, sizeof why);
    ok(od && access(q, F_OK) != 0, "--overwrite: removed as if adhere had written it");
    adh_outdir_close(od);

    /* links: at a final name, and a run-K that points elsewhere */
    char v[300];
    snprintf(v, sizeof v, "%s/victim", work);
    mkdir(v, 0755);
    put_text(v, "force.tsv", "keep");
    char l[300];
    snprintf(l, sizeof l, "%s/links", work);
    mkdir(l, 0755);
    snprintf(p, sizeof p, "%s/force.tsv", l);
    snprintf(q, sizeof q, "%s/force.tsv", v);
    symlink(q, p);
    od = adh_outdir_open(l, 0, why, sizeof why);
    ok(!od && strstr(why, "force.tsv (a link)"), "a link under an adhere name refuses the directory: %s", why);
    od = adh_outdir_open(l, ADH_OUTDIR_OVERWRITE, why, sizeof why);
    ok(od && adh_outdir_write(od, "force.tsv", write_text, "new", why, sizeof why) == 0 && !is_link(p) &&
       !strcmp(text_of(p), "new") && !strcmp(text_of(q), "keep"),
       "--overwrite replaces the link itself; its target keeps its text");
    snprintf(p, sizeof p, "%s/run-1", l);
    symlink(v, p);
    adh_outdir *sub = od ? adh_outdir_sub(od, "run-1", why, sizeof why) : NULL;
    ok(!sub && strstr(why, "symbolic link") && !strcmp(text_of(q), "keep"),
       "a run-K that is a link is not entered: %s", why);
    adh_outdir_close(sub);
    adh_outdir_close(od);
    unlink(p);

    /* run-K: made, recorded, emptied by the next run and removed when empty,
     * kept with the user's file in it */
    od = adh_outdir_open(l, 0, why, sizeof why);
    adh_outdir *r1 = od ? adh_outdir_sub(od, "run-1", why, sizeof why) : NULL;
    adh_outdir *r2 = od ? adh_outdir_sub(od, "run-2", why, sizeof why) : NULL;
    ok(r1 && r2 && adh_outdir_write(r1, "summary.tsv", write_text, "1", why, sizeof why) == 0 &&
       adh_outdir_write(r2, "summary.tsv", write_text, "2", why, sizeof why) == 0, "a sweep's run-1, run-2 written");
    adh_outdir_close(r1), adh_outdir_close(r2), adh_outdir_close(od);
    snprintf(p, sizeof p, "%s/run-2", l);
    put_text(p, "mine.txt", "mine");
    od = adh_outdir_open(l, 0, why, sizeof why);
    snprintf(p, sizeof p, "%s/run-1", l);
    snprintf(q, sizeof q, "%s/run-2/mine.txt", l);
    struct stat st;
    ok(od && stat(p, &st) != 0 && !strcmp(text_of(q), "mine"),
       "the next run removes run-1 and keeps run-2 with the user's file (%s)", od ? "opened" : why);
    snprintf(q, sizeof q, "%s/run-2/summary.tsv", l);
    ok(access(q, F_OK) != 0, "... from which adhere's summary.tsv went");
    adh_outdir_close(od);

    /* a log: kept when it holds something, removed when empty */
    od = adh_outdir_open(l, 0, why, sizeof why);
    int fd = od ? adh_outdir_log_open(od, "gnuplot.log", why, sizeof why) : -1;
    adh_outdir_log_close(od, "gnuplot.log", fd);
    snprintf(p, sizeof p, "%s/gnuplot.log", l);
    ok(fd >= 0 && access(p, F_OK) != 0, "an empty log is removed");
    fd = od ? adh_outdir_log_open(od, "gnuplot.log", why, sizeof why) : -1;
    ok(fd >= 0 && write(fd, "warning\n", 8) == 8, "a log written to");
    adh_outdir_log_close(od, "gnuplot.log", fd);
    adh_outdir_close(od);
    od = adh_outdir_open(l, 0, why, sizeof why);
    ok(od && access(p, F_OK) != 0, "... is kept, and is adhere's: the next run removes it");
    adh_outdir_close(od);
}

/* A writer that says it has begun (a byte on the pipe ctx names) and then
 * waits for ever: the process is killed inside it. */
static int stuck_writer(FILE *f, const void *ctx)
{
    const int *fds = ctx;
    fputs("half a table", f);
    fflush(f);
    (void)!write(fds[1], "w", 1);
    for (;;)
        pause();
    return 0;
}

/* A run killed (SIGKILL) while it writes a file leaves its temporary; the
 * next run into the directory removes it: the manifest recorded it first. */
static void test_killed_writer(void)
{
    char d[300], why[1200];
    snprintf(d, sizeof d, "%s/killed", work);
    int fds[2];
    if (pipe(fds) != 0)
        return;
    pid_t pid = fork();
    if (pid == 0) {
        adh_outdir *od = adh_outdir_open(d, 0, why, sizeof why);
        if (od)
            adh_outdir_write(od, "force.tsv", stuck_writer, fds, why, sizeof why);
        _exit(1);
    }
    char c = 0;
    ssize_t got = read(fds[0], &c, 1);   /* the writer has begun */
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
    close(fds[0]);
    close(fds[1]);
    ok(got == 1 && hidden(d) == 1, "a run killed while writing force.tsv leaves one temporary (%d)", hidden(d));
    adh_outdir *od = adh_outdir_open(d, 0, why, sizeof why);
    ok(od && hidden(d) == 0, "the next run into the directory removes it (%s, %d left)", od ? "opened" : why,
       hidden(d));
    adh_outdir_close(od);
}

/* Staged files (adhere merge) take their names only all at once: a commit
 * that fails part way (a name that cannot be renamed over, here a
 * directory put there while the merge wrote) keeps the earlier run's files
 * it would have removed, and leaves no temporary. */
static void test_staged_commit(void)
{
    char d[300], p[400], why[1200];
    snprintf(d, sizeof d, "%s/staged", work);
    adh_outdir *od = adh_outdir_open(d, ADH_OUTDIR_KEEP, why, sizeof why);
    if (od) {
        adh_outdir_stage(od);
        adh_outdir_write(od, "sweep.tsv", write_text, "one\n", why, sizeof why);
        adh_outdir_write(od, "map.png", write_text, "one\n", why, sizeof why);
    }
    int rc = od ? adh_outdir_commit(od, 1, why, sizeof why) : -1;
    adh_outdir_close(od);
    snprintf(p, sizeof p, "%s/map.png", d);
    ok(rc == 0 && !strcmp(text_of(p), "one\n"), "a staged run committed: its files under their names (%s)",
       rc ? why : "yes");
    od = adh_outdir_open(d, ADH_OUTDIR_KEEP, why, sizeof why);
    if (od) {
        adh_outdir_stage(od);
        adh_outdir_write(od, "sweep.tsv", write_text, "two\n", why, sizeof why);
    }
    snprintf(p, sizeof p, "%s/sweep.tsv", d);
    unlink(p);
    mkdir(p, 0777);   /* nothing is renamed over a directory */
    rc = od ? adh_outdir_commit(od, 1, why, sizeof why) : 0;
    adh_outdir_close(od);
    snprintf(p, sizeof p, "%s/map.png", d);
    ok(rc != 0 && !strcmp(text_of(p), "one\n") && hidden(d) == 0,
       "a commit that fails keeps the earlier run's map.png it would have removed, no temporary (%s; %d hidden)",
       rc ? why : "committed", hidden(d));
}

/* A manifest line longer than any adhere writes is not read, its tail
 * neither: a user's force.tsv whose record ends a long comment line is not
 * taken for adhere's (and removed). */
static void test_long_line(void)
{
    char d[300], p[400], why[1200];
    snprintf(d, sizeof d, "%s/longline", work);
    mkdir(d, 0777);
    put_text(d, "force.tsv", "mine\n");
    snprintf(p, sizeof p, "%s/force.tsv", d);
    struct stat st;
    stat(p, &st);
    char rec[200];
    snprintf(rec, sizeof rec, "force.tsv\t%llu\t%llu\t%lld\t%lld.%09ld\t%lld.%09ld\n", (unsigned long long)st.st_dev,
             (unsigned long long)st.st_ino, (long long)st.st_size, (long long)st.st_mtim.tv_sec, st.st_mtim.tv_nsec,
             (long long)st.st_ctim.tv_sec, st.st_ctim.tv_nsec);
    char text[1000];   /* the record from byte 255 on: the line's tail as fgets reads 255 bytes at a time */
    memset(text, '.', 255);
    text[0] = '#';
    snprintf(text + 255, sizeof text - 255, "%s", rec);
    put_text(d, ADH_OUTDIR_MANIFEST, text);
    adh_outdir *od = adh_outdir_open(d, 0, why, sizeof why);
    ok(!od && !strcmp(text_of(p), "mine\n"), "a record at the end of a %zu-byte line is not read: the user's force.tsv "
       "stays (%s)", strlen(text), od ? "opened" : why);
    adh_outdir_close(od);
}

/* A file at a path the user names (:rows, :dump): a link there is
 * replaced, never written through. */
static void test_outfile(void)
{
    char target[300], link[300];
    snprintf(target, sizeof target, "%s/victim/rows-target", work);
    snprintf(link, sizeof link, "%s/rows.tsv", work);
    put_file(target, (const unsigned char *)"keep", 4);
    symlink(target, link);
    ok(adh_outfile_write(link, write_text, "rows\n") == 0 && !is_link(link) && !strcmp(text_of(link), "rows\n") &&
       !strcmp(text_of(target), "keep"), "a link at the path is replaced; its target keeps its text");
    ok(adh_outfile_write(link, fail_writer, NULL) != 0 && !strcmp(text_of(link), "rows\n") && hidden(work) == 0,
       "a failed write leaves the old file and no temporary");
    ok(adh_outfile_write("/dev/null", write_text, "x") == 0, "a device is written in place");
    /* a file its owner made read-only is not replaced, as a shell's > would
     * not replace it: the new file was renamed over it (the outdir's
     * manifest already holds such a file the user's) */
    char ro[300];
    snprintf(ro, sizeof ro, "%s/kept.tsv", work);
    put_file(ro, (const unsigned char *)"mine", 4);
    chmod(ro, 0444);
    ok(adh_outfile_write(ro, write_text, "rows\n") == EACCES && !strcmp(text_of(ro), "mine") && hidden(work) == 0,
       "a read-only file at the path is not replaced (EACCES), and no temporary is left");
    unlink(ro);
    /* a pipe no program reads: opening it to write waits for a reader for
     * ever (the screen froze on :rows FIFO until SIGINT ended the session);
     * refused at once, ENXIO (an alarm fails the test where it would wait) */
    char fifo[300];
    snprintf(fifo, sizeof fifo, "%s/rows.fifo", work);
    mkfifo(fifo, 0600);
    alarm(10);
    ok(adh_outfile_write(fifo, write_text, "rows\n") == ENXIO, "a pipe with no reader is refused at once (ENXIO), "
       "not waited on");
    /* with a reader it is written in place, as a shell's > would */
    int rd = open(fifo, O_RDONLY | O_NONBLOCK);
    char got[16] = "";
    int wr = adh_outfile_write(fifo, write_text, "rows\n");
    ssize_t n = rd >= 0 ? read(rd, got, sizeof got - 1) : -1;
    alarm(0);
    ok(wr == 0 && n == 5 && !strcmp(got, "rows\n"), "a pipe with a reader is written in place (%zd bytes)", n);
    if (rd >= 0)
        close(rd);
    unlink(fifo);
}

int main(void)
{
    snprintf(work, sizeof work, "/tmp/adhere-test-outfiles-XXXXXX");
    if (!mkdtemp(work)) {
        perror("mkdtemp");
        return 1;
    }
    test_png_check();
    test_owns();
    test_outdir();
    test_killed_writer();
    test_staged_commit();
    test_long_line();
    test_outfile();
    tap_remove_dir(work);
    return tap_done();
}
