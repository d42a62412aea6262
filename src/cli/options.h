/* The command line: one table drives getopt_long, --help and the checks. */
#ifndef ADH_CLI_OPTIONS_H
#define ADH_CLI_OPTIONS_H

#include <stdio.h>

#include "cli/advice.h"
#include "scene/config.h"

typedef enum cli_action {
    CLI_ACT_TUI = 0, CLI_ACT_BATCH, CLI_ACT_HELP, CLI_ACT_VERSION, CLI_ACT_LIST_KEYS,
    CLI_ACT_PLAN, CLI_ACT_COST, CLI_ACT_FIT, CLI_ACT_MERGE
} cli_action;

#define CLI_MAX_DATA 8   /* --data files (ADH_MEASURED_MAX_FILES) */

/* adhere fit's own options, as typed (src/cli/fit.c reads them). */
typedef struct cli_fit_options {
    char free[128];          /* --free list, "" = E,A */
    char model[16];          /* --model: "" = static, relax */
    double offset, baseline; /* --offset, --baseline start values (m, N) */
    int given;               /* one of them was given (refused without fit) */
} cli_fit_options;

#define CLI_MAX_SET 512      /* flags that set a key */
#define CLI_MAX_MERGE 4096   /* shard directories adhere merge joins */

/* A flag's key and its text, as given (a study's fingerprint is made of
 * them and the scene's text). */
typedef struct cli_set {
    char key[64];
    const char *value;
} cli_set;

typedef struct cli_options {
    adh_config cfg;
    cli_action action;
    const char *scene_arg;   /* positional SCENE, or NULL */
    char reference[16];      /* --reference: "" or "static" */
    char cost_eps[256];      /* --cost-eps list, "" = default */
    char cost_nodes[256];    /* --cost-nodes list, "" = default */
    const char *data[CLI_MAX_DATA];   /* every --data FILE, in order (the first is also output.data) */
    size_t ndata;
    char columns[256];       /* --columns POS,FORCE, "" = automatic */
    cli_fit_options fit;
    char *scene_text;        /* the scene file's text, or NULL (the built-in default) */
    cli_set set[CLI_MAX_SET];   /* every flag that set a key, in order */
    size_t nset;
    unsigned shard_k, shard_n;  /* --shard K/N; 0/0: the whole study */
    int allow_partial;       /* adhere merge --allow-partial */
    const char *merge[CLI_MAX_MERGE];   /* adhere merge's shard directories */
    size_t nmerge;
} cli_options;

/* Fills cli from argv (defaults, then the scene if one is named, then the
 * flags). `adhere fit ...` (the first argument) is the fit subcommand,
 * `adhere merge [OPTIONS] DIR...` joins a study's shards. Returns 0, or 2
 * with a message in why. */
int cli_options_parse(int argc, char **argv, cli_options *cli, char *why, size_t whylen);
void cli_options_usage(FILE *out);

/* A sentence of the configuration's (naming keys: grid.kernel = paper) in
 * the words the user wrote each key in: a flag's (--kernel=paper), or the
 * scene's key with its file and line (kernel = paper (a.scene:3)); a key
 * nobody set in the scene's words when the sentence's keys came from the
 * scene alone, else as a flag. */
void cli_options_words(const adh_config *cfg, const char *sentence, char *out, size_t len);
/* A core check's sentence about run of cfg in those words: its opening
 * setting as it was given (adh_config_key_opening: --start=400pm, or
 * start = 400pm (a.scene:6), where the core wrote start = 400 pm), and any
 * key it names. For who CLI_ADVICE_COST N and eps keep the core's words:
 * --cost takes them from --cost-nodes and --cost-eps, not the keys. */
void cli_options_core_words(const adh_config *cfg, const adh_run_spec *run, cli_advice_for who, const char *sentence,
                            char *out, size_t len);

/* Checks the whole configuration before anything runs. 0 or 2 with why. */
int cli_options_validate(const adh_config *cfg, char *why, size_t whylen);
/* The same, with the advice in who's words (adhere fit's: its turn is its
 * data's). */
int cli_options_validate_for(const adh_config *cfg, cli_advice_for who, char *why, size_t whylen);
/* The same for the screen, which runs one run of a sweep (the values at
 * the left): a sweep whose runs move between modes (a material swept
 * between elastic and sls) is a study's concern, --batch's refusal. */
int cli_options_validate_screen(const adh_config *cfg, char *why, size_t whylen);

#endif
