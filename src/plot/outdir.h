/* The files adhere owns in an output directory (-o DIR): a run first
 * removes every one an earlier run left, so a directory never mixes the
 * tables and figures of two runs. Other files are never touched. */
#ifndef ADH_PLOT_OUTDIR_H
#define ADH_PLOT_OUTDIR_H

#include <stddef.h>
#include <stdio.h>

/* Whether name (a bare file name) is one adhere writes: a table, a figure,
 * a gnuplot log, or a temporary of one (.NAME.PID.tmp, .NAME.tmpPID) left
 * by a run that was killed. */
int adh_outdir_owns(const char *name);

/* mkdir -p dir, and that it is a writable directory: 0, or -1 with a
 * sentence naming the directory in why. Every output directory (-o, a
 * sweep's run-K, the TUI's plots) is made here. */
int adh_outdir_make(const char *dir, char *why, size_t whylen);

/* A new private directory $TMPDIR/NAME-XXXXXX (/tmp without TMPDIR) for
 * gnuplot's data files, its path in buf: 0, or -1 with "cannot make a
 * temporary directory PATH: reason" in why (buf then ""). The caller
 * removes it. */
int adh_outdir_temp(const char *name, char *buf, size_t len, char *why, size_t whylen);

/* Writes dir/name atomically: writer fills a temporary beside it
 * (DIR/.NAME.PID.tmp), which is renamed to dir/name only when every byte
 * got out, so a reader never sees half a table and a full disk leaves no
 * file under the final name. writer returns 0, or nonzero on failure. 0, or
 * -1 with "cannot write DIR/NAME: reason" in why. Every table is written
 * here. */
typedef int (*adh_outdir_writer)(FILE *f, const void *ctx);
int adh_outdir_write(const char *dir, const char *name, adh_outdir_writer writer, const void *ctx,
                     char *why, size_t whylen);

/* Removes from dir every file adh_outdir_owns, and each sweep directory
 * run-K holding nothing else once its own files are gone. 0, or -1 with why
 * (a file that cannot be removed); a dir that does not exist is empty. */
int adh_outdir_clear(const char *dir, char *why, size_t whylen);

#endif
