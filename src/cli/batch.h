/* The batch driver: runs the configured protocol with no TUI, streams or
 * writes the tables, then the plots. Returns the process exit status. */
#ifndef ADH_CLI_BATCH_H
#define ADH_CLI_BATCH_H

#include "cli/exit.h"
#include "cli/options.h"

int cli_batch_main(cli_options *cli);

#endif
