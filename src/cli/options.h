/* The command line: one table drives getopt_long, --help and the checks. */
#ifndef ADH_CLI_OPTIONS_H
#define ADH_CLI_OPTIONS_H

#include <stdio.h>

#include "scene/config.h"

typedef enum adh_action {
    ADH_ACT_TUI = 0, ADH_ACT_BATCH, ADH_ACT_HELP, ADH_ACT_VERSION, ADH_ACT_LIST_KEYS,
    ADH_ACT_PLAN, ADH_ACT_COST
} adh_action;

typedef struct adh_cli {
    adh_config cfg;
    adh_action action;
    const char *scene_arg;   /* positional SCENE, or NULL */
    char reference[16];      /* --reference: "" or "static" */
    char cost_eps[256];      /* --cost-eps list, "" = default */
    char cost_nodes[256];    /* --cost-nodes list, "" = default */
} adh_cli;

/* Fills cli from argv (defaults, then the scene if one is named, then the
 * flags). Returns 0, or 2 with a message in why. */
int adh_cli_parse(int argc, char **argv, adh_cli *cli, char *why, size_t whylen);
void adh_cli_usage(FILE *out);

/* Checks the whole configuration before anything runs. 0 or 2 with why. */
int adh_cli_validate(const adh_config *cfg, char *why, size_t whylen);

#endif
