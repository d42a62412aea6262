#include "cli/data.h"

#include "scene/measured.h"

int cli_data_load(cli_options *cli, char *why, size_t whylen)
{
    static adh_measured measured[CLI_MAX_DATA];
    cli->cfg.output.measured = NULL;
    /* a curve the configuration names without --data (output.data) */
    if (cli->ndata == 0 && cli->cfg.output.data[0])
        cli->data[cli->ndata++] = cli->cfg.output.data;
    for (size_t i = 0; i < cli->ndata; i++) {
        if (adh_measured_load(cli->data[i], cli->columns, &measured[i], why, whylen) != 0)
            return -1;
        if (i > 0)
            measured[i - 1].next = &measured[i];
    }
    if (cli->ndata)
        cli->cfg.output.measured = &measured[0];
    return 0;
}
