#include "cli/study.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "numerics.h"   /* ADH_NUMERICS: made by the Makefile */
#include "scene/scene.h"

/* The longest line study.tsv or runs.tsv holds: a scene (1 MiB at most,
 * twice that escaped) or a row; anything longer is not adhere's. */
#define STUDY_LINE_MAX ((size_t)4 << 20)

/* getline's, bounded: a line past STUDY_LINE_MAX (a file that is not
 * adhere's, or a tampered one) is -2 before it is held in memory, where
 * getline would take as much as the line. The length, or -1 at the end. */
static ssize_t line_read(char **line, size_t *cap, FILE *f)
{
    size_t len = 0;
    int c = 0;
    while (c != '\n' && (c = getc_unlocked(f)) != EOF) {
        if (len + 2 > *cap) {
            size_t n = *cap ? 2 * *cap : 512;
            char *grown = n <= STUDY_LINE_MAX ? realloc(*line, n) : NULL;
            if (!grown)
                return -2;
            *line = grown, *cap = n;
        }
        (*line)[len++] = (char)c;
    }
    if (!len)
        return -1;
    (*line)[len] = '\0';
    return (ssize_t)len;
}

/* Keys that say where and how a study is written, not what it computes:
 * shards that differ in them are shards of one study. */
static int outside_study(const char *key)
{
    static const char *const keys[] = { "output.dir", "output.overwrite", "output.quiet", "output.plot",
                                        "output.allow_unconverged", "output.gnuplot_style", "sweep.jobs" };
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (!strcmp(key, keys[i]))
            return 1;
    return strncmp(key, "tui.", 4) == 0;
}

/* text with backslash, tab, newline and carriage return escaped. */
static void escaped(FILE *f, const char *text)
{
    for (const char *p = text; *p; p++) {
        if (*p == '\\')
            fputs("\\\\", f);
        else if (*p == '\t')
            fputs("\\t", f);
        else if (*p == '\n')
            fputs("\\n", f);
        else if (*p == '\r')
            fputs("\\r", f);
        else
            fputc(*p, f);
    }
}

/* escaped()'s inverse, in place; -1 for an escape it does not write. */
static int unescape(char *s)
{
    char *o = s;
    for (char *p = s; *p; p++) {
        if (*p != '\\') {
            *o++ = *p;
            continue;
        }
        p++;
        if (*p == '\\')
            *o++ = '\\';
        else if (*p == 't')
            *o++ = '\t';
        else if (*p == 'n')
            *o++ = '\n';
        else if (*p == 'r')
            *o++ = '\r';
        else
            return -1;
    }
    *o = '\0';
    return 0;
}

/* What the study is made of, one line each: the version, the scene's text,
 * the flags that set its keys. */
static void recipe(FILE *f, const cli_study *st)
{
    fprintf(f, "version\t%s\n", ADH_VERSION);
    fputs("scene\t", f);
    escaped(f, st->scene_text ? st->scene_text : "");
    fputc('\n', f);
    for (size_t i = 0; i < st->nset; i++) {
        if (outside_study(st->set[i].key))
            continue;
        fprintf(f, "set\t%s\t", st->set[i].key);
        escaped(f, st->set[i].value);
        fputc('\n', f);
    }
}

/* FNV-1a, 64 bits, over the recipe: tells studies apart (not a
 * cryptographic hash: it guards against mistakes, not forgery). */
static void fingerprint(cli_study *st)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    uint64_t h = 1469598103934665603ULL;
    if (m) {
        recipe(m, st);
        fclose(m);
        for (size_t i = 0; text && i < len; i++) {
            h ^= (unsigned char)text[i];
            h *= 1099511628211ULL;
        }
    }
    free(text);
    snprintf(st->fingerprint, sizeof st->fingerprint, "%016llx", (unsigned long long)h);
}

const char *cli_study_numerics(void)
{
    return ADH_NUMERICS;
}

const char *cli_study_numerics_shown(const char *id)
{
    return id && *id ? id : "none, its study.tsv predates numerics ids: an unknown build";
}

static void counts(cli_study *st)
{
    st->nruns = adh_config_nruns(st->cfg);
    st->ndrives = adh_sweep_drives(st->cfg);
}

void cli_study_from_cli(cli_study *st, cli_options *cli)
{
    memset(st, 0, sizeof *st);
    st->cfg = &cli->cfg;
    snprintf(st->scene_path, sizeof st->scene_path, "%s", cli->cfg.scene);
    st->scene_text = cli->scene_text;
    st->set = cli->set;
    st->nset = cli->nset;
    st->shard_k = cli->shard_n ? cli->shard_k : 1;
    st->shard_n = cli->shard_n ? cli->shard_n : 1;
    snprintf(st->numerics, sizeof st->numerics, "%s", ADH_NUMERICS);
    fingerprint(st);
    counts(st);
}

void cli_study_free(cli_study *st)
{
    if (!st->owned)
        return;
    free(st->scene_text);
    for (size_t i = 0; i < st->nset; i++)
        free((char *)st->set[i].value);
    free(st->set);
    memset(st, 0, sizeof *st);
}

int cli_study_mine(const cli_study *st, size_t u)
{
    return u % st->shard_n == st->shard_k - 1;
}

size_t cli_study_shard_runs(const cli_study *st)
{
    size_t n = 0, runs[ADH_MAX_TURNS];
    for (size_t u = st->shard_k - 1; u < st->ndrives; u += st->shard_n)
        n += adh_sweep_drive_runs(st->cfg, u, runs);
    return n;
}

static int study_table(FILE *f, const void *ctx)
{
    const cli_study *st = ctx;
    fprintf(f, "# adhere " ADH_VERSION "\n# study.tsv: the study this directory holds shard %u of %u of "
            "(adhere merge joins the shards of one fingerprint and numerics; a rerun of the same numerics "
            "resumes it)\n", st->shard_k, st->shard_n);
    fprintf(f, "fingerprint\t%s\nnumerics\t%s\nruns\t%zu\ndrives\t%zu\nshard\t%u/%u\nscene_path\t",
            st->fingerprint, st->numerics, st->nruns, st->ndrives, st->shard_k, st->shard_n);
    escaped(f, st->scene_path);
    fputc('\n', f);
    recipe(f, st);
    return 0;
}

int cli_study_write(const cli_study *st, adh_outdir *d, char *why, size_t whylen)
{
    return adh_outdir_write(d, "study.tsv", study_table, st, why, whylen);
}

/* A line "key\tvalue" of study.tsv into st (the recipe's lines into its
 * scene and flags). 0, or -1. */
static int study_line(cli_study *st, char *line, char *fp, size_t *runs, size_t *drives)
{
    char *tab = strchr(line, '\t');
    if (!tab)
        return -1;
    *tab = '\0';
    char *v = tab + 1;
    /* another version's study is judged as any build's, by its numerics
     * id (resume's refusal, merge's): a version alone changes no number */
    if (!strcmp(line, "version"))
        return 0;
    if (!strcmp(line, "fingerprint"))
        return snprintf(fp, 17, "%s", v) == 16 ? 0 : -1;
    if (!strcmp(line, "numerics")) {   /* the build's: not in the fingerprint, which is what the study is */
        if (strlen(v) != 16 || strspn(v, "0123456789abcdef") != 16 || st->numerics[0])
            return -1;   /* another form, or a second id: which build is unknown */
        memcpy(st->numerics, v, sizeof st->numerics);
        return 0;
    }
    if (!strcmp(line, "runs") || !strcmp(line, "drives")) {
        char *end;
        unsigned long long n = strtoull(v, &end, 10);
        *(!strcmp(line, "runs") ? runs : drives) = (size_t)n;
        return *end ? -1 : 0;
    }
    if (!strcmp(line, "shard")) {
        char extra;
        return sscanf(v, "%u/%u%c", &st->shard_k, &st->shard_n, &extra) == 2 && st->shard_k >= 1 &&
               st->shard_k <= st->shard_n ? 0 : -1;
    }
    if (!strcmp(line, "scene_path"))
        return unescape(v) == 0 && snprintf(st->scene_path, sizeof st->scene_path, "%s", v) < PATH_MAX ? 0 : -1;
    if (!strcmp(line, "scene")) {
        if (unescape(v) != 0 || !(st->scene_text = *v ? strdup(v) : NULL) != !*v)
            return -1;
        return 0;
    }
    if (!strcmp(line, "set")) {
        char *t2 = strchr(v, '\t');
        if (!t2 || (size_t)(t2 - v) >= sizeof st->set[0].key)
            return -1;
        *t2 = '\0';
        cli_set *grown = realloc(st->set, (st->nset + 1) * sizeof *grown);
        if (!grown)
            return -1;
        st->set = grown;
        if (unescape(t2 + 1) != 0 || !(grown[st->nset].value = strdup(t2 + 1)))
            return -1;
        snprintf(grown[st->nset].key, sizeof grown[0].key, "%s", v);
        st->nset++;
        return 0;
    }
    return -1;
}

/* st's configuration from its recipe: the defaults, the scene, the flags,
 * the grid chosen. 0, or -1 with why. */
static int rebuild(cli_study *st, adh_config *cfg, char *why, size_t whylen)
{
    char msg[1024];
    adh_config_default(cfg);
    if (st->scene_text && adh_scene_parse_string(st->scene_text, st->scene_path, cfg, msg, sizeof msg) != 0) {
        snprintf(why, whylen, "its scene does not read: %s", msg);
        return -1;
    }
    snprintf(cfg->scene, sizeof cfg->scene, "%s", st->scene_path);
    for (size_t i = 0; i < st->nset; i++)
        if (adh_config_set(cfg, st->set[i].key, st->set[i].value, msg, sizeof msg) != 0) {
            snprintf(why, whylen, "its %s = %s is refused: %s", st->set[i].key, st->set[i].value, msg);
            return -1;
        }
    if (adh_config_grid(cfg, msg, sizeof msg, NULL) != 0) {
        snprintf(why, whylen, "its grid: %s", msg);
        return -1;
    }
    st->cfg = cfg;
    return 0;
}

int cli_study_read(cli_study *st, adh_config *cfg, int dirfd, const char *path, char *why, size_t whylen)
{
    memset(st, 0, sizeof *st);
    st->owned = 1;
    FILE *f = adh_outdir_read(dirfd, "study.tsv");
    if (!f && errno == ENOENT)
        return 0;
    if (!f) {
        snprintf(why, whylen, "cannot read %.3000s/study.tsv: %s", path, adh_outdir_read_error(errno));
        return -1;
    }
    char *line = NULL, fp[17] = "";
    size_t cap = 0, runs = 0, drives = 0, lineno = 0;
    ssize_t got;
    int rc = 0;
    while (rc == 0 && (got = line_read(&line, &cap, f)) >= 0) {
        lineno++;
        if (got && line[got - 1] == '\n')
            line[--got] = '\0';
        if (line[0] != '#' && line[0])
            rc = study_line(st, line, fp, &runs, &drives);
    }
    if (got == -2)
        rc = -1, lineno++;   /* the line too long for adhere's */
    free(line);
    fclose(f);
    if (rc != 0 || !fp[0] || !st->shard_n) {
        snprintf(why, whylen, "%.3000s/study.tsv: line %zu is not adhere's", path, lineno);
        memcpy(st->fingerprint, fp, sizeof fp);   /* whose study it says it is, if that line read */
        return -1;
    }
    fingerprint(st);
    if (strcmp(fp, st->fingerprint) != 0) {
        snprintf(why, whylen, "%.3000s/study.tsv: its fingerprint %s is not that of what it records (%s): changed "
                 "since adhere wrote it", path, fp, st->fingerprint);
        return -1;
    }
    char msg[1200];
    if (rebuild(st, cfg, msg, sizeof msg) != 0) {
        snprintf(why, whylen, "%.3000s/study.tsv: %s", path, msg);
        return -1;
    }
    counts(st);
    if (st->nruns != runs || st->ndrives != drives) {
        snprintf(why, whylen, "%.3000s/study.tsv says %zu runs in %zu drives, its study has %zu in %zu", path, runs,
                 drives, st->nruns, st->ndrives);
        return -1;
    }
    return 1;
}

void cli_study_rows_head(FILE *f, const cli_study *st)
{
    fprintf(f, "# adhere " ADH_VERSION "\n# runs.tsv: study %s, shard %u of %u: a row for each run as it ends "
            "(sweep.tsv's columns); a rerun skips the runs here\n", st->fingerprint, st->shard_k, st->shard_n);
    cli_studyrow_header(f, st->cfg);
}

long cli_study_read_rows(const cli_study *st, int dirfd, const char *path, cli_studyrow *rows,
                         size_t *partial_lines, char *why, size_t whylen)
{
    *partial_lines = 0;
    FILE *f = adh_outdir_read(dirfd, "runs.tsv");
    if (!f && errno == ENOENT)
        return 0;
    if (!f) {
        snprintf(why, whylen, "cannot read %.3000s/runs.tsv: %s", path, adh_outdir_read_error(errno));
        return -1;
    }
    char *line = NULL, mark[64];
    size_t cap = 0;
    ssize_t got;
    long n = 0;
    int header = 0, study = 0, bad = 0;
    snprintf(mark, sizeof mark, "# runs.tsv: study %s,", st->fingerprint);
    while ((got = line_read(&line, &cap, f)) >= 0) {
        int whole = got && line[got - 1] == '\n';
        if (whole)
            line[--got] = '\0';
        if (line[0] == '#') {
            study |= strncmp(line, mark, strlen(mark)) == 0;
            continue;
        }
        if (!header) {
            header = 1;
            bad = !study || !cli_studyrow_is_header(st->cfg, line);
            if (bad)
                break;
            continue;
        }
        cli_studyrow row;
        if (!whole || cli_studyrow_parse(st->cfg, line, &row) != 0) {
            ++*partial_lines;
            continue;
        }
        cli_studyrow_clear(&rows[row.run]);   /* a later line for the same run replaces it */
        rows[row.run] = row;
        n++;
    }
    bad |= got == -2;   /* a line too long for a row of adhere's */
    free(line);
    fclose(f);
    if (bad || !header) {
        snprintf(why, whylen, "%.3000s/runs.tsv is not a record of study %s", path, st->fingerprint);
        return -1;
    }
    return n;
}

/* The next flag at or after i that makes a study (-q, -o, --jobs ... do
 * not: as its recipe). */
static size_t next_set(const cli_study *st, size_t i)
{
    while (i < st->nset && outside_study(st->set[i].key))
        i++;
    return i;
}

void cli_study_difference(const cli_study *a, const cli_study *b, char *buf, size_t len)
{
    if ((a->scene_text == NULL) != (b->scene_text == NULL) ||
        (a->scene_text && strcmp(a->scene_text, b->scene_text) != 0)) {
        snprintf(buf, len, "their scenes differ");
        return;
    }
    for (size_t i = next_set(a, 0), j = next_set(b, 0); i < a->nset || j < b->nset;
         i = next_set(a, i + 1), j = next_set(b, j + 1))
        if (i >= a->nset || j >= b->nset || strcmp(a->set[i].key, b->set[j].key) ||
            strcmp(a->set[i].value, b->set[j].value)) {
            snprintf(buf, len, "their options differ (%s%s%s against %s%s%s)", i < a->nset ? a->set[i].key : "none",
                     i < a->nset ? " = " : "", i < a->nset ? a->set[i].value : "", j < b->nset ? b->set[j].key : "none",
                     j < b->nset ? " = " : "", j < b->nset ? b->set[j].value : "");
            return;
        }
    snprintf(buf, len, "their options differ in keys that do not change the runs");
}
