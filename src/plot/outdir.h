/* An output directory (-o DIR, a sweep's run-K, the TUI's plots) and the
 * files adhere writes in it. The directory is opened once and every file is
 * made relative to that descriptor, never through a name that could be a
 * link: temporaries are created new (O_EXCL, O_NOFOLLOW) and renamed into
 * place, a sweep's run-K is opened with O_NOFOLLOW. adhere keeps a manifest
 * (.adhere-manifest) of what it wrote, each file with its device, inode,
 * size, modification and change time, and removes from an earlier run only the
 * files the manifest proves are still the ones it wrote: a file of the user's
 * is never deleted or replaced, unless --overwrite says so. A lock on the
 * directory refuses a second run into it while one is writing. */
#ifndef ADH_PLOT_OUTDIR_H
#define ADH_PLOT_OUTDIR_H

#include <stddef.h>
#include <stdio.h>

/* The manifest's name in each directory adhere writes. */
#define ADH_OUTDIR_MANIFEST ".adhere-manifest"

typedef struct adh_outdir adh_outdir;

/* adh_outdir_open's flags. OVERWRITE (--overwrite): files under the names
 * adhere writes that it cannot prove are its own (a directory written by an
 * older adhere, or the user's) are removed or replaced as if they were. */
enum { ADH_OUTDIR_OVERWRITE = 1,
       ADH_OUTDIR_KEEP = 2 };   /* the files an earlier run wrote stay (a study resumed): adh_outdir_clear
                                   removes them when they turn out to be another's */

/* mkdir -p path and open it: locked against a second adhere, cleared of
 * the files an earlier run wrote (per its manifest), and checked for files
 * under adhere's names that it did not write, which refuse it unless
 * OVERWRITE. NULL with a sentence naming the directory and what to do in
 * why. */
adh_outdir *adh_outdir_open(const char *path, unsigned flags, char *why, size_t whylen);

/* The files this session reads (its scene, replay script, gnuplot style,
 * measured curves; a path "" or NULL skipped), by identity, each with what
 * it is ("the scene") and the option that named it ("--replay"; NULL for
 * none), both kept as pointers (string constants): an output directory
 * whose clearing would remove one (adhere DIR/best.scene -o DIR: the scene
 * a fit wrote, an earlier run's file) is refused, naming it, --overwrite
 * or not; a file the user names for output (--screen, the TUI's :dump and
 * :rows) is looked up by adh_outdir_input_named. Up to 16; later calls
 * replace the list. */
typedef struct adh_outdir_input {
    const char *path, *what, *option;
} adh_outdir_input;
void adh_outdir_inputs(const adh_outdir_input *in, size_t n);
/* Whether path names one of the session's inputs (the same file, not a
 * link to it, which adh_outfile_write replaces rather than writes
 * through): 1 with what it is and its option (adh_outdir_inputs), or 0.
 * --screen naming the replay script put the screen over it. */
int adh_outdir_input_named(const char *path, const char **what, const char **option);

/* path/name, a directory adhere names inside the one the user named (the
 * terminal interface's static/ and time/), or name in the working
 * directory when path is NULL (its adhere-plots, adhere-plots/static):
 * path is followed as adh_outdir_open follows it, each component of name
 * is made there and never entered through a link; then opened as
 * adh_outdir_open does, path itself left as it is. NULL with why. */
adh_outdir *adh_outdir_open_in(const char *path, const char *name, unsigned flags, char *why, size_t whylen);

/* The subdirectory name (a sweep's run-K) of d: made with mkdirat, opened
 * without following a link, recorded in d's manifest, and opened as
 * adh_outdir_open does. NULL with why. */
adh_outdir *adh_outdir_sub(adh_outdir *d, const char *name, char *why, size_t whylen);

/* The files an earlier run wrote removed, as adh_outdir_open does without
 * KEEP. 0, or -1 with why. */
int adh_outdir_clear(adh_outdir *d, char *why, size_t whylen);

/* The directory's descriptor, for reading what adhere wrote in it
 * (openat with O_NOFOLLOW); writes go through adh_outdir_write. */
int adh_outdir_fd(const adh_outdir *d);

/* name in the directory dirfd (a path below it: "run-3/force.tsv"), a
 * regular file opened for reading without following a link at its last
 * component; NULL with errno (ENOENT: none there). */
FILE *adh_outdir_read(int dirfd, const char *name);
/* Why adh_outdir_read failed with err (its errno), in words: "not a
 * regular file ..." for a pipe, device or directory under the name (EINVAL,
 * whose strerror, "Invalid argument", said nothing of it), "a symbolic
 * link ..." for a link (ELOOP), else strerror(err). */
const char *adh_outdir_read_error(int err);

/* Whether name in d is a file or directory the manifest proves adhere
 * wrote (and is still as it wrote it). */
int adh_outdir_has(const adh_outdir *d, const char *name);

/* Unlocks and frees d (NULL is fine). */
void adh_outdir_close(adh_outdir *d);

/* in as a message shows it, into out: each control byte (below 0x20, and
 * 0x7f) as \xNN, so that a name holding an escape sequence cannot clear or
 * recolour the terminal that reads the message. */
void adh_outdir_escape(const char *in, char *out, size_t len);

/* The same for a message's text: with keep_lines its newlines and tabs
 * stay as they are (they lay the message out; they move no cursor a
 * terminal does not expect). */
void adh_outdir_escape_text(const char *in, char *out, size_t len, int keep_lines);
/* The same, returning how many bytes of in were written (escaped): all of
 * them (strlen(in)) when out held the text whole; out holds 4 strlen(in) + 1. */
size_t adh_outdir_escape_prefix(const char *in, char *out, size_t len, int keep_lines);

/* The path d was opened as, for messages ("DIR/run-2"), escaped as
 * adh_outdir_escape does. */
const char *adh_outdir_path(const adh_outdir *d);

/* Writes d/name atomically: writer fills a new temporary .NAME.XXXXXX in
 * d, which is renamed to name only when every byte got out (a full disk,
 * or a file size limit, leaves no file under the final name and no
 * temporary), then recorded in the manifest. writer returns 0, or nonzero
 * on failure. 0, or -1 with "cannot write DIR/NAME: reason" in why. A file
 * under name that adhere did not write is not replaced (unless OVERWRITE).
 * Every table and figure is written here. Threads may write into different
 * directories at once, not into one. */
typedef int (*adh_outdir_writer)(FILE *f, const void *ctx);
int adh_outdir_write(adh_outdir *d, const char *name, adh_outdir_writer writer, const void *ctx, char *why,
                     size_t whylen);

/* Staging (adhere merge: the earlier merge stays whole until the new one
 * is): after adh_outdir_stage, adh_outdir_write and adh_outdir_log_open
 * leave each new file under its temporary (recorded in the manifest, so a
 * kill leaves nothing the next run cannot remove). adh_outdir_commit
 * renames them all into place at once and, with replace, removes the
 * files an earlier run wrote that this one did not write again (run-K
 * directories stay): 0, or -1 with why (what was not renamed is removed).
 * adh_outdir_abandon removes them, leaving the earlier files as they were;
 * adh_outdir_close abandons what was not committed. */
void adh_outdir_stage(adh_outdir *d);
/* The files an earlier run wrote that this one has not staged again (of
 * the manifest, still as written; not run-K directories, not
 * temporaries), those commit with replace would remove, whose names end
 * in suffix (NULL: any): their names by commas into buf (cut at len); how
 * many. */
size_t adh_outdir_earlier(const adh_outdir *d, const char *suffix, char *buf, size_t len);
int adh_outdir_commit(adh_outdir *d, int replace, char *why, size_t whylen);
void adh_outdir_abandon(adh_outdir *d);

/* A log (gnuplot.log) made new in d for appending, readable too, recorded
 * in the manifest as a file that grows: its descriptor (close-on-exec), or
 * -1 with why. adh_outdir_log_close closes it and removes it when it stayed
 * empty. */
int adh_outdir_log_open(adh_outdir *d, const char *name, char *why, size_t whylen);
void adh_outdir_log_close(adh_outdir *d, const char *name, int fd);

/* A table that grows by whole rows (a study's runs.tsv): name, adhere's
 * own or new, opened for appending (O_APPEND: each row one write),
 * recorded in the manifest as a file that grows; its descriptor, or -1
 * with why. adh_outdir_log_close records it as it ends. */
int adh_outdir_append(adh_outdir *d, const char *name, char *why, size_t whylen);

/* Whether name (a bare file name) is one adhere writes in an output
 * directory: a table, a figure, a gnuplot log, the manifest. */
int adh_outdir_owns(const char *name);

/* A new private directory $TMPDIR/NAME-XXXXXX (/tmp without TMPDIR) for
 * gnuplot's data files and images, its path in buf: 0, or -1 with "cannot
 * make a temporary directory PATH: reason" in why (buf then ""). The caller
 * removes it. */
int adh_outdir_temp(const char *name, char *buf, size_t len, char *why, size_t whylen);

/* One file at a path the user named (the TUI's :rows and :dump, --screen):
 * a new temporary beside it renamed over it, so a link there is replaced,
 * never written through, a read-only file kept (EACCES, as a shell's >
 * keeps it); a device or pipe there is written in place (a
 * pipe no program reads: ENXIO at once, not waited on). 0, or the errno
 * that stopped it (nothing left under a temporary name). */
int adh_outfile_write(const char *path, adh_outdir_writer writer, const void *ctx);
/* What adh_outfile_write refuses path for before it makes anything there
 * (its directory missing or not one, a directory at path, no file name, a
 * name too long; not a read-only file, which it finds as it writes): 0,
 * or that errno. For a path checked before the work that fills it
 * (--screen, before the replay). */
int adh_outfile_check(const char *path);

/* The words for e, adh_outfile_write's errno for path: a pipe no program
 * reads (ENXIO), a directory whose file system lets no file be created in
 * it (ENOENT with the directory there: /proc), else the system's. buf
 * (len bytes) may hold them. */
const char *adh_outfile_reason(const char *path, int e, char *buf, size_t len);

#endif
