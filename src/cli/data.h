/* The measured curves of --data, read once before any work. */
#ifndef ADH_CLI_DATA_H
#define ADH_CLI_DATA_H

#include <stddef.h>

#include "cli/options.h"

/* Reads every --data file (with --columns) into one chain, set as
 * cli->cfg.measured (NULL without --data). 0, or -1 with "FILE:LINE: why"
 * in why. The curves live until the program ends. */
int cli_data_load(cli_options *cli, char *why, size_t whylen);

#endif
