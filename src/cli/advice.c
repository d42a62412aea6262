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

void cli_advice_append(char *why, size_t whylen, unsigned fix)
{
    char list[128] = "";
    size_t n = 0;
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
        if (fix & flags[i].bit)
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", flags[i].flag);
    size_t len = strlen(why);
    if (n && len + n + 4 <= whylen)
        snprintf(why + len, whylen - len, " (%s)", list);
}
