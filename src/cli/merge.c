#define _GNU_SOURCE   /* fopencookie(3) */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE   /* flock(2) */
#endif
#include "cli/merge.h"
#include "plot/say.h"

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/exit.h"
#include "cli/figures.h"
#include "cli/interrupt.h"
#include "cli/sweep.h"
#include "cli/study.h"
#include "cli/studyrow.h"
#include "plot/outdir.h"

typedef struct shard {
    char path[1024];               /* as messages show it (adh_outdir_escape) */
    int fd;
    cli_study st;
    adh_config *cfg;
} shard;

typedef struct merge {
    cli_options *cli;
    shard *sh;
    size_t n;
    cli_studyrow *rows;            /* the study's rows, those found done */
    size_t nrows;                  /* how many rows has room for */
    int *from;                     /* the shard each run's row came from, -1 none */
    adh_outdir *out;
    struct stat out_st;            /* -o DIR, when it is there */
    int out_known;
    int figure_failed;             /* the figure was not written: the earlier one is looked at */
    int earlier_same;              /* -o's earlier sweep.tsv has this one's rows: its figure is this table's */
} merge;

/* "5, 8, 11-14, 20 and 3 more": runs (from 1) in a short list. */
static void run_list(const size_t *runs, size_t n, char *buf, size_t len)
{
    size_t shown = 0;
    buf[0] = '\0';
    for (size_t a = 0; a < n; shown++) {
        size_t b = a;
        while (b + 1 < n && runs[b + 1] == runs[b] + 1)
            b++;
        char piece[64];
        if (shown == 12) {
            snprintf(piece, sizeof piece, " and more (%zu in all)", n);
            b = n - 1;
        } else if (b > a) {
            snprintf(piece, sizeof piece, "%s%zu-%zu", shown ? ", " : "", runs[a] + 1, runs[b] + 1);
        } else {
            snprintf(piece, sizeof piece, "%s%zu", shown ? ", " : "", runs[a] + 1);
        }
        size_t o = strlen(buf), k = strlen(piece);
        if (o + k >= len)
            return;
        memcpy(buf + o, piece, k + 1);
        a = b + 1;
    }
}

/* Shard k's directory: opened, not in use by a running shard (a shared
 * lock beside its exclusive one), its study read. 0, or 2 with why. */
static int open_shard(merge *m, size_t k, char *why, size_t whylen)
{
    shard *s = &m->sh[k];
    adh_outdir_escape(m->cli->merge[k], s->path, sizeof s->path);
    s->fd = open(m->cli->merge[k], O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (s->fd < 0) {
        snprintf(why, whylen, "cannot open %.1000s: %s", s->path, strerror(errno));
        return 2;
    }
    struct stat st;
    int own = m->out_known && fstat(s->fd, &st) == 0 && st.st_dev == m->out_st.st_dev &&
              st.st_ino == m->out_st.st_ino;
    if (!own && flock(s->fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
        snprintf(why, whylen, "%.1000s is in use: its shard is still writing into it; merge when it has finished",
                 s->path);
        return 2;
    }
    if (!(s->cfg = malloc(sizeof *s->cfg))) {
        snprintf(why, whylen, "out of memory");
        return 2;
    }
    int r = cli_study_read(&s->st, s->cfg, s->fd, s->path, why, whylen);
    if (r == 0)
        snprintf(why, whylen, "%.1000s holds no study.tsv: not the directory of a shard (adhere --shard=K/N -o DIR)",
                 s->path);
    return r == 1 ? 0 : 2;
}

static int one_each(const merge *m, char *why, size_t whylen);

/* Every shard computed by one build (one numerics id): rows of different
 * numerics are never joined, and a shard that records no id (a study.tsv
 * from before adhere recorded one) is joined with no other, as nothing
 * says which build computed it. 0, or 2 with why. */
static int same_numerics(const merge *m, char *why, size_t whylen)
{
    for (size_t k = 1; k < m->n; k++) {
        const cli_study *a = &m->sh[0].st, *b = &m->sh[k].st;
        if (a->numerics[0] && !strcmp(a->numerics, b->numerics))
            continue;
        snprintf(why, whylen, "%.900s (numerics %s) and %.900s (numerics %s) were not computed by one build of "
                 "adhere: rows of different numerics are not joined; rerun %s with one adhere (this one's numerics "
                 "are %s)", m->sh[0].path, cli_study_numerics_shown(a->numerics), m->sh[k].path,
                 cli_study_numerics_shown(b->numerics), m->n > 2 ? "the shards" : "both shards",
                 cli_study_numerics());
        return 2;
    }
    return 0;
}

/* Every shard of one study, one split, each shard once. 0, or 2 with why. */
static int same_study(const merge *m, char *why, size_t whylen)
{
    const cli_study *a = &m->sh[0].st;
    for (size_t k = 1; k < m->n; k++) {
        const cli_study *b = &m->sh[k].st;
        char diff[600];
        if (strcmp(a->fingerprint, b->fingerprint) != 0) {
            cli_study_difference(a, b, diff, sizeof diff);
            snprintf(why, whylen, "%.900s (study %s) and %.900s (study %s) are shards of different studies: %.600s",
                     m->sh[0].path, a->fingerprint, m->sh[k].path, b->fingerprint, diff);
            return 2;
        }
        if (a->shard_n != b->shard_n) {
            snprintf(why, whylen, "%.900s is shard %u/%u, %.900s shard %u/%u: shards of one split are joined "
                     "(every K of one N)", m->sh[0].path, a->shard_k, a->shard_n, m->sh[k].path, b->shard_k,
                     b->shard_n);
            return 2;
        }
    }
    return same_numerics(m, why, whylen) ? 2 : one_each(m, why, whylen);
}

/* Each shard K/N in one directory: two directories that both say they hold
 * one shard are two runs of it (whose runs may differ), not parts to join.
 * A directory named twice is gather's to list. 0, or 2 with why. */
static int one_each(const merge *m, char *why, size_t whylen)
{
    for (size_t k = 1; k < m->n; k++)
        for (size_t j = 0; j < k; j++) {
            const cli_study *a = &m->sh[j].st, *b = &m->sh[k].st;
            struct stat sa, sb;
            if (a->shard_k != b->shard_k || fstat(m->sh[j].fd, &sa) != 0 || fstat(m->sh[k].fd, &sb) != 0 ||
                (sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino))
                continue;
            snprintf(why, whylen, "%.900s and %.900s both hold shard %u/%u of study %s: two runs of one shard, "
                     "not parts to join; name one of them", m->sh[j].path, m->sh[k].path, b->shard_k, b->shard_n,
                     b->fingerprint);
            return 2;
        }
    return 0;
}

/* Each shard's rows into the study's; a run from two shards refuses
 * them (listed). 0, or 2 with why. */
static int gather(merge *m, cli_studyrow *scratch, char *why, size_t whylen)
{
    const cli_study *st = &m->sh[0].st;
    /* a run is listed once however many shards hold it (a directory given
     * five times): the list has room for each run once */
    size_t *dup = malloc(st->nruns * sizeof *dup), ndup = 0;
    unsigned char *twice = calloc(st->nruns, 1);
    const char *dup_a = NULL, *dup_b = NULL;
    if (!dup || !twice) {
        free(dup), free(twice);
        snprintf(why, whylen, "out of memory");
        return 2;
    }
    for (size_t k = 0; k < m->n; k++) {
        size_t cut;
        cli_studyrow_clear_all(scratch, st->nruns);   /* the rows the last shard's left */
        memset(scratch, 0, st->nruns * sizeof *scratch);
        if (cli_study_read_rows(&m->sh[k].st, m->sh[k].fd, m->sh[k].path, scratch, &cut, why, whylen) < 0) {
            free(dup), free(twice);
            return 2;
        }
        for (size_t i = 0; i < st->nruns; i++) {
            if (!cli_studyrow_complete(&scratch[i]))
                continue;
            if (m->from[i] >= 0) {
                if (!dup_a)
                    dup_a = m->sh[m->from[i]].path, dup_b = m->sh[k].path;
                twice[i] = 1;
                continue;
            }
            m->rows[i] = scratch[i];
            scratch[i].reason = NULL;   /* m->rows[i] owns it now */
            m->from[i] = (int)k;
        }
    }
    for (size_t i = 0; i < st->nruns; i++)
        if (twice[i])
            dup[ndup++] = i;
    free(twice);
    if (ndup) {
        char list[400];
        run_list(dup, ndup, list, sizeof list);
        snprintf(why, whylen, "runs %s are in %.900s and in %.900s: each run once (is a shard given twice?)", list,
                 dup_a, dup_b);
    }
    free(dup);
    return ndup ? 2 : 0;
}

/* An eps study's Figure 7 line (the static curve's loop, and sweep.tsv's
 * # static_hysteresis) is computed by the merge itself: by this build,
 * then, only for shards of its own numerics, or its number would sit
 * among another build's. 0, or 2 with why. */
static int own_numerics(const merge *m, const char *partial, char *why, size_t whylen)
{
    const cli_study *st = &m->sh[0].st;
    if (!adh_sweep_fig7_panel(m->sh[0].cfg) || !m->cli->cfg.output.plot || *partial ||
        !strcmp(st->numerics, cli_study_numerics()))
        return 0;
    snprintf(why, whylen, "the shards' eps study draws Figure 7's static line, which the merge computes: this adhere's "
             "numerics (%s) are not the shards' (%s); merge with the adhere that ran them, or --no-plot for the "
             "table alone", cli_study_numerics(), cli_study_numerics_shown(st->numerics));
    return 2;
}

/* Runs without a result: refused (listed) unless --allow-partial, which
 * gives them rows saying not run and a # PARTIAL line. 0, or 2 with why. */
static int missing(merge *m, char *partial, size_t plen, char *why, size_t whylen)
{
    const cli_study *st = &m->sh[0].st;
    size_t *miss = malloc(st->nruns * sizeof *miss), nmiss = 0;
    if (!miss) {
        snprintf(why, whylen, "out of memory");
        return 2;
    }
    for (size_t i = 0; i < st->nruns; i++)
        if (m->from[i] < 0)
            miss[nmiss++] = i;
    int rc = 0;
    if (nmiss) {
        char list[400], shards[200] = "";
        run_list(miss, nmiss, list, sizeof list);
        /* which shards were not given at all */
        size_t o = 0;
        for (unsigned k = 1; k <= st->shard_n && o + 24 < sizeof shards; k++) {
            size_t j = 0;
            while (j < m->n && m->sh[j].st.shard_k != k)
                j++;
            char piece[32];
            if (j < m->n)
                continue;
            snprintf(piece, sizeof piece, "%s%u/%u", o ? ", " : "", k % 1000000u, st->shard_n % 1000000u);
            memcpy(shards + o, piece, strlen(piece) + 1);
            o += strlen(piece);
        }
        if (!m->cli->allow_partial) {
            snprintf(why, whylen, "%zu of the study's %zu runs have no result: runs %s (%s%s); rerun their shards "
                     "to finish them, or --allow-partial to join what there is", nmiss, st->nruns, list,
                     o ? "shards not given: " : "cut short: a shard was stopped before its end", shards);
            rc = 2;
        } else {
            snprintf(partial, plen, "%zu of %zu runs have results (--allow-partial); no result: runs %s",
                     st->nruns - nmiss, st->nruns, list);
            for (size_t j = 0; j < nmiss; j++)
                cli_studyrow_empty(&m->rows[miss[j]], m->sh[0].cfg, miss[j], "not run");
        }
    }
    free(miss);
    return rc;
}

/* -o DIR: a directory of the merge's own (an earlier merge's files
 * replaced, by clear_out), or one of the shards' (an unsharded study's,
 * whose table is written again): opened and locked. 0, or 2 with why.
 * Opened once the shards are found whole: --overwrite's removals there
 * are for a merge that writes, not one refused. */
static int open_out(merge *m, char *why, size_t whylen)
{
    const adh_output_options *o = &m->cli->cfg.output;
    if (!o->dir[0])
        return 0;
    unsigned flags = ADH_OUTDIR_KEEP | (o->overwrite ? ADH_OUTDIR_OVERWRITE : 0);
    if (!(m->out = adh_outdir_open(o->dir, flags, why, whylen)))
        return 2;
    fstat(adh_outdir_fd(m->out), &m->out_st);
    return 0;
}

/* A table's text without its seconds column (the header's column of that
 * name, cut from every line that is not a comment: a run's timing, the
 * one column two merges of one study's shards may differ in), cut as it
 * streams by, a byte at a time: neither table is held. */
typedef struct seconds_cut {
    long col;          /* the seconds column; -2 before the header, -1: none */
    long f;            /* the field of the current row */
    int start, pass;   /* at a line's start; the line is a comment or empty */
    int header;        /* the current row is the header */
    char name[8];      /* the header's current field, until it is known not to be "seconds" */
    size_t nlen;       /* its length so far; > 7: not "seconds", passed on as it comes */
} seconds_cut;

#define SECONDS_CUT_INIT { .col = -2, .start = 1 }

/* The tab that joins field f of a row to the ones before it, kept. */
static size_t cut_tab(const seconds_cut *c, long f, char *out)
{
    return f && f != c->col && !(f == 1 && c->col == 0) ? (out[0] = '\t', 1) : 0;
}

/* The header's field ended (or outgrew "seconds"): dropped if it is the
 * first named seconds, else passed on with its tab. */
static size_t cut_name(seconds_cut *c, char *out)
{
    if (c->col == -2 && c->nlen == 7 && !memcmp(c->name, "seconds", 7)) {
        c->col = c->f;
        return 0;
    }
    size_t n = cut_tab(c, c->f, out), k = c->nlen < 8 ? c->nlen : 0;
    memcpy(out + n, c->name, k);
    return n + k;
}

/* One byte of a table (EOF at its end) through c: what stays of it, in
 * out (16 bytes), and how many. */
static size_t cut_byte(seconds_cut *c, int ch, char *out)
{
    if (ch == EOF && c->start)
        return 0;
    if (c->start) {
        c->start = 0;
        c->pass = ch == '#' || ch == '\n';
        c->header = !c->pass && c->col == -2;
        c->f = 0, c->nlen = 0;
    }
    if (c->pass) {
        c->start = ch == '\n';
        return ch == EOF ? 0 : (out[0] = (char)ch, 1);
    }
    size_t n = 0;
    if (ch == '\t' || ch == '\n' || ch == EOF) {   /* the field ends */
        if (c->header && c->nlen < 8)
            n = cut_name(c, out);
        if (ch == '\t') {
            c->f++, c->nlen = 0;
            if (!c->header && c->f != c->col)
                n += cut_tab(c, c->f, out + n);
            return n;
        }
        if (c->header && c->col == -2)
            c->col = -1;
        c->start = 1;
        return ch == '\n' ? (out[n] = '\n', n + 1) : n;
    }
    if (c->header && c->nlen < 7) {   /* maybe "seconds": held */
        c->name[c->nlen++] = (char)ch;
        return 0;
    }
    if (c->header && c->nlen == 7) {   /* longer: not it */
        n = cut_name(c, out);
        c->nlen = 8;
    }
    if (c->f != c->col || c->header)
        out[n++] = (char)ch;
    return n;
}

/* The earlier table, cut, read as the new one is written to compare. */
typedef struct earlier_cmp {
    FILE *was;
    seconds_cut now_cut, was_cut;
    char q[16];          /* the earlier table's cut bytes not compared yet */
    size_t qn, qi;
    int differ;
} earlier_cmp;

/* The earlier table's next byte once cut, or EOF. */
static int earlier_next(earlier_cmp *e)
{
    while (e->qi == e->qn) {
        int ch = getc(e->was);
        e->qi = 0;
        e->qn = cut_byte(&e->was_cut, ch, e->q);
        if (ch == EOF && e->qn == 0)
            return EOF;
    }
    return (unsigned char)e->q[e->qi++];
}

/* The new table's bytes, as cli_studyrow_table writes them (a cookie
 * stream's write), compared with the earlier table's as they come. */
static ssize_t earlier_write(void *ctx, const char *buf, size_t size)
{
    earlier_cmp *e = ctx;
    char out[16];
    for (size_t i = 0; i < size && !e->differ; i++) {
        size_t n = cut_byte(&e->now_cut, (unsigned char)buf[i], out);
        for (size_t k = 0; k < n && !e->differ; k++)
            e->differ = earlier_next(e) != (unsigned char)out[k];
    }
    return (ssize_t)size;
}

/* The largest earlier sweep.tsv compared: 10^5 rows of some 1 kB, with room. */
#define EARLIER_MAX ((long)256 << 20)

/* Whether -o's sweep.tsv (an earlier merge's, adhere's own) holds the
 * table t writes but for its seconds column: then the earlier figure is
 * this table's. Streamed, both tables a byte at a time through their
 * cuts: a few kB, however long the earlier one (held whole, and cut into
 * copies, it took some four times its size). */
static int earlier_same(const merge *m, const cli_studyrow_sweep *t)
{
    earlier_cmp e = { .now_cut = SECONDS_CUT_INIT, .was_cut = SECONDS_CUT_INIT };
    struct stat st;
    if (!adh_outdir_has(m->out, "sweep.tsv") || !(e.was = adh_outdir_read(adh_outdir_fd(m->out), "sweep.tsv")))
        return 0;
    FILE *f = NULL;
    if (fstat(fileno(e.was), &st) == 0 && st.st_size < EARLIER_MAX)
        f = fopencookie(&e, "w", (cookie_io_functions_t){ .write = earlier_write });
    if (f) {
        cli_studyrow_table(f, t);
        int bad = fflush(f) != 0;
        char out[16];
        size_t n = cut_byte(&e.now_cut, EOF, out);   /* a last line without its newline */
        for (size_t k = 0; k < n && !e.differ; k++)
            e.differ = earlier_next(&e) != (unsigned char)out[k];
        e.differ |= bad || ferror(e.was) || earlier_next(&e) != EOF;   /* nothing more in the earlier one */
        fclose(f);
    }
    fclose(e.was);
    return f && !e.differ;
}

/* A figure not written: what became of the earlier merge's figures
 * (names, listed before the commit), kept when they are this table's,
 * else removed with the rest of it. */
static void earlier_figures(const merge *m, const char *names, int replace)
{
    if (!*names)
        return;
    if (replace)
        adh_sayf_as("adhere merge", "the earlier merge's %s removed: drawn from another table", names);
    else
        adh_sayf_as("adhere merge", "the earlier %s left in place: drawn from this table's rows (%s)", names,
                    m->earlier_same ? "the earlier sweep.tsv differed in its seconds column at most"
                                    : "the study's own, in its directory");
}

/* The new merge's files, written under temporaries, take the earlier
 * one's names only once every one is whole: a refused, failed or
 * interrupted merge leaves the last good one as it was. In a directory of
 * the merge's own the earlier files this merge does not write again go
 * then; a shard's directory (named among them) keeps its records. An exit
 * status. */
static int commit_out(merge *m, int rc)
{
    char why[1024];
    if (cli_interrupt_signal()) {
        if (m->out)
            adh_outdir_abandon(m->out);
        adh_sayf_as("adhere merge", "interrupted by signal %d: nothing written%s%s%s", cli_interrupt_signal(),
                    m->out ? "; " : "", m->out ? adh_outdir_path(m->out) : "", m->out ? " keeps what it held" : "");
        return cli_interrupt_exit();
    }
    if (!m->out)
        return rc;
    if (rc != CLI_EXIT_OK && rc != CLI_EXIT_PLOT) {
        adh_outdir_abandon(m->out);
        return rc;
    }
    int holds_shard = adh_outdir_has(m->out, "study.tsv") || adh_outdir_has(m->out, "runs.tsv");
    /* a figure not written: the earlier one stays when it is this table's */
    int replace = !holds_shard && !(m->figure_failed && m->earlier_same);
    char names[400] = "";
    if (m->figure_failed)
        adh_outdir_earlier(m->out, ".png", names, sizeof names);
    if (adh_outdir_commit(m->out, replace, why, sizeof why) != 0) {
        adh_sayf_as("adhere merge", "%s", why);
        return CLI_EXIT_USAGE;
    }
    earlier_figures(m, names, replace);
    return rc;
}

/* The output directory, when it holds a shard (a study.tsv or runs.tsv,
 * adhere's or not: looked at before it is opened, so that --overwrite
 * removes nothing there for a merge refused), is one of those named. */
static int out_is_named(const merge *m, char *why, size_t whylen)
{
    const char *dir = m->cli->cfg.output.dir;
    int fd = m->out_known ? open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
    struct stat st;
    int held = fd >= 0 && (fstatat(fd, "study.tsv", &st, AT_SYMLINK_NOFOLLOW) == 0 ||
                           fstatat(fd, "runs.tsv", &st, AT_SYMLINK_NOFOLLOW) == 0);
    if (fd >= 0)
        close(fd);
    if (!held)
        return 0;
    for (size_t k = 0; k < m->n; k++)
        if (fstat(m->sh[k].fd, &st) == 0 && st.st_dev == m->out_st.st_dev && st.st_ino == m->out_st.st_ino)
            return 0;
    char shown[1024];
    adh_outdir_escape(dir, shown, sizeof shown);
    snprintf(why, whylen, "-o %.1000s holds a shard of a study: merge into a directory of its own, or name it among "
             "the shards", shown);
    return 2;
}

/* sweep.tsv (standard output without -o) and the study's figure. An exit status. */
static int write_out(merge *m, const char *partial)
{
    adh_config *cfg = m->sh[0].cfg;
    const adh_output_options *mine = &m->cli->cfg.output;
    /* the merge's own outputs, the study's everything else */
    cfg->output.plot = mine->plot;
    cfg->output.quiet = mine->quiet;
    snprintf(cfg->output.gnuplot_style, sizeof cfg->output.gnuplot_style, "%s", mine->gnuplot_style);
    cfg->spec.relax.cancel = cli_interrupt_flag();   /* gnuplot's wait hears a signal */
    const cli_study *st = &m->sh[0].st;
    /* an eps study's Figure 7 line, as the whole study has it (its own curve) */
    int resolved = 0;
    double hyst = NAN;
    cli_kcache *kc = adh_sweep_fig7_panel(cfg) && cfg->output.plot && !*partial ? cli_kcache_new(0) : NULL;
    if (kc) {
        hyst = cli_sweep_static_hysteresis(cfg, kc, &resolved);
        cli_kcache_free(kc);
        if (cli_interrupt_signal())   /* a table without its line would pass for the whole study's */
            return cli_interrupt_exit();
    }
    cli_studyrow_sweep t = { cfg, m->rows, partial, adh_sweep_run_dirs(&cfg->sweep), hyst, resolved };
    char why[1024];
    if (!m->out) {
        errno = 0;   /* so that the reason said is this table's write's */
        cli_studyrow_table(stdout, &t);
        if (fflush(stdout) == 0 && !ferror(stdout))
            return CLI_EXIT_OK;
        /* exit 2 without a word: the table was lost and nothing said so */
        adh_sayf_as("adhere merge", "cannot write sweep.tsv to standard output%s%s", errno ? ": " : "",
                    errno ? strerror(errno) : "");
        return CLI_EXIT_USAGE;
    }
    if (adh_outdir_write(m->out, "sweep.tsv", cli_studyrow_table, &t, why, sizeof why) != 0) {
        adh_say(why);
        return CLI_EXIT_USAGE;
    }
    if (!cfg->output.plot || adh_sweep_plot_kind(&cfg->sweep) == ADH_SWEEP_PLOT_NONE || *partial)
        return CLI_EXIT_OK;
    int *fd = malloc(st->nruns * sizeof *fd);
    if (!fd)
        return CLI_EXIT_SOLVER;
    for (size_t i = 0; i < st->nruns; i++)
        fd[i] = m->from[i] >= 0 ? m->sh[m->from[i]].fd : -1;
    cli_figures_curves curves = { fd, st->nruns };
    int rc = cli_figures_sweep(cfg, m->rows, st->nruns, &curves, hyst, m->out, why, sizeof why);
    free(fd);
    if (rc != 0) {
        adh_sayf("sweep plot not written: %s", why);
        m->figure_failed = 1;
        m->earlier_same = earlier_same(m, &t);
        return CLI_EXIT_PLOT;
    }
    return CLI_EXIT_OK;
}

static void merge_free(merge *m)
{
    for (size_t k = 0; k < m->n; k++) {
        cli_study_free(&m->sh[k].st);
        free(m->sh[k].cfg);
        if (m->sh[k].fd >= 0)
            close(m->sh[k].fd);
    }
    cli_studyrow_clear_all(m->rows, m->nrows);
    free(m->sh), free(m->rows), free(m->from);
    adh_outdir_close(m->out);
}

static int merge_run(cli_options *cli);

/* SIGINT, SIGTERM and SIGHUP are heard through the whole merge (the
 * static curve of Figure 7's line, gnuplot's wait): it stops, removes
 * its temporaries and leaves the earlier merge as it was. */
int cli_merge_main(cli_options *cli)
{
    cli_interrupt_catch();
    int rc = merge_run(cli);
    cli_interrupt_release();
    return rc;
}

static int merge_run(cli_options *cli)
{
    merge m = { .cli = cli, .n = cli->nmerge };
    char why[8192], partial[600] = "";
    int rc = !(m.sh = calloc(m.n, sizeof *m.sh)) ? CLI_EXIT_SOLVER : 0;
    for (size_t k = 0; m.sh && k < m.n; k++)
        m.sh[k].fd = -1;
    /* a shard's directory that is -o too takes no shared lock: open_out locks it */
    m.out_known = cli->cfg.output.dir[0] && stat(cli->cfg.output.dir, &m.out_st) == 0;
    for (size_t k = 0; rc == 0 && k < m.n; k++)
        rc = open_shard(&m, k, why, sizeof why);
    if (rc == 0)
        rc = same_study(&m, why, sizeof why);
    if (rc == 0)
        rc = out_is_named(&m, why, sizeof why);
    size_t nruns = rc == 0 ? m.sh[0].st.nruns : 0;
    cli_studyrow *scratch = NULL;
    if (rc == 0 && (!(m.rows = calloc(nruns, sizeof *m.rows)) || !(m.from = malloc(nruns * sizeof *m.from)) ||
                    !(scratch = calloc(nruns, sizeof *scratch)))) {
        snprintf(why, sizeof why, "out of memory for %zu runs", nruns);
        rc = CLI_EXIT_SOLVER;
    }
    for (size_t i = 0; rc == 0 && i < nruns; i++)
        m.from[i] = -1;
    m.nrows = m.rows ? nruns : 0;
    if (rc == 0)
        rc = gather(&m, scratch, why, sizeof why);
    cli_studyrow_clear_all(scratch, scratch ? nruns : 0);
    free(scratch);
    if (rc == 0)
        rc = missing(&m, partial, sizeof partial, why, sizeof why);
    if (rc == 0)
        rc = own_numerics(&m, partial, why, sizeof why);
    if (rc == 0)
        rc = open_out(&m, why, sizeof why);
    if (rc != 0) {
        adh_sayf_as("adhere merge", "%s", why);
        merge_free(&m);
        return rc;
    }
    if (m.out)
        adh_outdir_stage(m.out);
    rc = commit_out(&m, write_out(&m, partial));
    if (rc == CLI_EXIT_OK && !cli->cfg.output.quiet)
        adh_sayf_as("adhere merge", "%zu shard%s of study %s (%zu runs) joined%s%s%s", m.n, m.n == 1 ? "" : "s",
                    m.sh[0].st.fingerprint, nruns, m.out ? " into " : "; sweep.tsv went to standard output",
                    m.out ? adh_outdir_path(m.out) : "", *partial ? " (# PARTIAL)" : "");
    merge_free(&m);
    return rc;
}
