/* adhere --cost: what accuracy costs in time. Runs the configured protocol
 * over a grid of eps, N and kernels, in parallel on the cores, and reports
 * each run's wall time and iterations beside its error against the most
 * accurate run (and the static curve) in pull-off force, jump-in position,
 * hysteresis area and contact radius at the turn. */
#ifndef ADH_CLI_COST_H
#define ADH_CLI_COST_H

#include "cli/options.h"

int cli_cost_main(const cli_options *cli);

#endif
