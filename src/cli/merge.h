/* adhere merge DIR...: the shards of one study joined into the table and
 * figure the whole study writes (sweep.tsv, jump.png, force.png, map.png,
 * curves.png; its timing column aside, the same to the last digit).
 * Refused: directories that are no shard's, shards of different studies
 * (their fingerprints), of different splits, a run given twice, runs
 * missing (they are listed) and a shard still running or cut short,
 * unless --allow-partial, which writes what there is and marks the table
 * # PARTIAL. Nothing is written into a shard's directory but the merge's
 * own files, and only when it is named among the shards. */
#ifndef ADH_CLI_MERGE_H
#define ADH_CLI_MERGE_H

#include "cli/options.h"

/* The process exit status (exit.h). */
int cli_merge_main(cli_options *cli);

#endif
