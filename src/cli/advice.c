#include "cli/advice.h"

#include <stdio.h>
#include <string.h>

#include "adhere/status.h"

/* In the order a sentence names them. */
static const struct {
    unsigned bit;
    const char *flag;
} flags[] = {
    { ADH_FIX_MODE, "--mode" },
    { ADH_FIX_FINE_BAND, "--fine-band" },
    { ADH_FIX_TURNS, "--turn" },
    { ADH_FIX_RADIUS, "-R" },
    { ADH_FIX_STEP, "-d" },
    { ADH_FIX_START, "--start" },
    { ADH_FIX_NODES, "-N" },
    { ADH_FIX_SPACING, "--spacing" },
    { ADH_FIX_GRID_RADIUS, "--grid-radius" },
    { ADH_FIX_FORCE, "--force" },
};

/* Appends text to list (of len, holding *n bytes), cut at its end. */
static void add(char *list, size_t len, size_t *n, const char *sep, const char *text)
{
    if (*n + 1 < len) {
        int w = snprintf(list + *n, len - *n, "%s%s", *n ? sep : "", text);
        *n += w < 0 ? 0 : (size_t)w < len - *n ? (size_t)w : len - *n - 1;
    }
}

void cli_advice_append_for(cli_advice_for who, char *why, size_t whylen, unsigned fix)
{
    char list[160] = "";
    size_t n = 0;
    /* a fit sets its one turn itself, below the data: --turn would be
     * overwritten, and is no advice */
    unsigned turn = who == CLI_ADVICE_FIT ? fix & ADH_FIX_TURNS : 0;
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
        if ((fix & ~turn) & flags[i].bit)
            add(list, sizeof list, &n, ", ", flags[i].flag);
    if (turn)
        add(list, sizeof list, &n, "; ", "the turn is the fit's, a step below the deepest position in --data");
    size_t len = strlen(why);
    if (n && len + n + 4 <= whylen)
        snprintf(why + len, whylen - len, " (%s)", list);
}

void cli_advice_append(char *why, size_t whylen, unsigned fix)
{
    cli_advice_append_for(CLI_ADVICE_RUN, why, whylen, fix);
}
