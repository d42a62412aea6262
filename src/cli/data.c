#include "cli/data.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "scene/measured.h"

/* Whether --data k names a file an earlier one does (a link, or the same
 * path twice): a fit would count its points twice, claiming errors
 * sqrt(2) smaller than the data give. -1 with why, else 0. */
static int named_before(const cli_options *cli, size_t k, char *why, size_t whylen)
{
    struct stat a, b;
    if (stat(cli->data[k], &a) != 0 || !S_ISREG(a.st_mode))
        return 0;   /* the reader says what is wrong with it */
    for (size_t i = 0; i < k; i++)
        if (stat(cli->data[i], &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
            snprintf(why, whylen, "--data: %s is %s again: give each measured curve once (a fit would count its "
                     "points twice)", cli->data[k], cli->data[i]);
            return -1;
        }
    return 0;
}

/* Whether curve k holds the points an earlier one does, bit for bit: a
 * copy of one file under another name (two measurements never agree to
 * the last digit of every point), which named_before cannot see. */
static int copied_before(const cli_options *cli, const adh_measured *m, size_t k, char *why, size_t whylen)
{
    for (size_t i = 0; i < k; i++)
        if (m[i].n == m[k].n && memcmp(m[i].h0, m[k].h0, m[k].n * sizeof *m[k].h0) == 0 &&
            memcmp(m[i].F, m[k].F, m[k].n * sizeof *m[k].F) == 0) {
            snprintf(why, whylen, "--data: %s holds the same %zu points as %s (a copy?): give each measured curve "
                     "once (a fit would count its points twice)", cli->data[k], m[k].n, cli->data[i]);
            return -1;
        }
    return 0;
}

/* Whether a segment of m repeats an earlier one of the same direction
 * point for point: the curve written twice in one file (appended again),
 * which a fit would count twice as it would a copy of the file. */
static int repeated_within(const adh_measured *m, char *why, size_t whylen)
{
    for (size_t k = 1; k < m->nseg; k++)
        for (size_t j = 0; j < k; j++) {
            const adh_measured_segment *a = &m->seg[j], *b = &m->seg[k];
            if (a->dir != b->dir || a->n != b->n || a->n < 2 ||
                memcmp(m->h0 + a->first, m->h0 + b->first, b->n * sizeof *m->h0) != 0 ||
                memcmp(m->F + a->first, m->F + b->first, b->n * sizeof *m->F) != 0)
                continue;
            snprintf(why, whylen, "%s:%zu: lines %zu to %zu repeat lines %zu to %zu point for point (the curve "
                     "written twice?): give each measured segment once (a fit would count its points twice)",
                     m->path, m->line[b->first], m->line[b->first], m->line[b->first + b->n - 1], m->line[a->first],
                     m->line[a->first + a->n - 1]);
            return -1;
        }
    return 0;
}

int cli_data_load(cli_options *cli, char *why, size_t whylen)
{
    static adh_measured measured[CLI_MAX_DATA];
    cli->cfg.output.measured = NULL;
    /* a curve the configuration names without --data (output.data) */
    if (cli->ndata == 0 && cli->cfg.output.data[0])
        cli->data[cli->ndata++] = cli->cfg.output.data;
    for (size_t i = 0; i < cli->ndata; i++) {
        if (named_before(cli, i, why, whylen) != 0 ||
            adh_measured_load(cli->data[i], cli->columns, &measured[i], why, whylen) != 0 ||
            copied_before(cli, measured, i, why, whylen) != 0 || repeated_within(&measured[i], why, whylen) != 0)
            return -1;
        if (i > 0)
            measured[i - 1].next = &measured[i];
    }
    if (cli->ndata)
        cli->cfg.output.measured = &measured[0];
    return 0;
}
