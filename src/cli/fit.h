/* adhere fit: the model fitted to measured curves (--data), by GSL's
 * nonlinear least squares (adhere/fit.h). Reports on standard output; with
 * -o DIR also fit.tsv, fit-points.tsv, best.scene and fit.png. */
#ifndef ADH_CLI_FIT_H
#define ADH_CLI_FIT_H

#include "cli/options.h"

/* The whole subcommand, once the data are read (cli->cfg.measured). Exit
 * status: 0 a fit; 1 no fit (poor, a parameter unidentifiable, not
 * converged, the model failing); 2 bad input; 128 + the signal's number
 * interrupted (130 SIGINT, 143 SIGTERM; the best point so far written,
 * marked PARTIAL). */
int cli_fit_main(cli_options *cli);

#endif
