/* A study as the command line runs it: its fingerprint (the scene's text,
 * the flags that set keys, the version), the shards it splits into, and
 * the records a shard's directory keeps so that a rerun resumes it and
 * adhere merge joins it with the others: study.tsv (what the study is)
 * and runs.tsv (a row for each run as it ends). */
#ifndef ADH_CLI_STUDY_H
#define ADH_CLI_STUDY_H

#include <stdio.h>

#include "cli/options.h"
#include "cli/studyrow.h"
#include "plot/outdir.h"
#include "scene/config.h"

typedef struct cli_study {
    adh_config *cfg;               /* the study's configuration */
    char scene_path[PATH_MAX];     /* "" = the built-in default */
    char *scene_text;              /* the scene's text, NULL without one */
    cli_set *set;                  /* the flags that set keys (those the study is made of) */
    size_t nset;
    unsigned shard_k, shard_n;     /* this shard; 1/1 for the whole study */
    char fingerprint[17];          /* 16 hex digits */
    char numerics[17];             /* the build that computes its rows (the Makefile's hash of the
                                      sources that decide the numbers); "" a study.tsv from before
                                      adhere recorded one */
    size_t nruns, ndrives;
    int owned;                     /* merge read it: scene_text, set and their values are its own */
} cli_study;

/* This build's numerics id: 16 hex digits, the Makefile's hash of the
 * sources that decide a study's numbers. A study resumes, and merge joins
 * shards, only of one id. */
const char *cli_study_numerics(void);
/* An id as messages show it: the id, or what a study.tsv without one is. */
const char *cli_study_numerics_shown(const char *id);

/* The study cli runs (its shard, or 1/1). */
void cli_study_from_cli(cli_study *st, cli_options *cli);
/* Frees what a study read from a directory owns. */
void cli_study_free(cli_study *st);

/* Whether drive u is this shard's: u = K-1, K-1+N, ... */
int cli_study_mine(const cli_study *st, size_t u);
/* The runs of this shard: how many. */
size_t cli_study_shard_runs(const cli_study *st);

/* study.tsv of st into d. 0, or -1 with why. */
int cli_study_write(const cli_study *st, adh_outdir *d, char *why, size_t whylen);
/* study.tsv read from the directory descriptor dirfd (path names it in
 * messages): the study it records, its configuration rebuilt into cfg
 * (defaults, the scene's text, the flags) and its grid chosen, its
 * fingerprint checked, its numerics id in st->numerics ("" none). 1 read, 0 no study.tsv there, -1 with why
 * (a line that does not read: st->fingerprint its fingerprint line's, "" none). */
int cli_study_read(cli_study *st, adh_config *cfg, int dirfd, const char *path, char *why, size_t whylen);

/* The rows of runs.tsv in dirfd of study st: each row of st's that reads
 * back whole into rows[run] (the last one of a run wins), *partial_lines
 * counting lines that did not (a row cut by a kill). The rows read; -1
 * with why when runs.tsv is another study's. No runs.tsv: 0. */
long cli_study_read_rows(const cli_study *st, int dirfd, const char *path, cli_studyrow *rows,
                         size_t *partial_lines, char *why, size_t whylen);
/* What two studies' recipes differ in (their scenes, or the first flag),
 * for a refusal. */
void cli_study_difference(const cli_study *a, const cli_study *b, char *buf, size_t len);
/* runs.tsv's first lines (a comment and the header). */
void cli_study_rows_head(FILE *f, const cli_study *st);

#endif
