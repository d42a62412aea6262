#include "plot/say.h"

#include <stdio.h>
#include <string.h>

#include "plot/outdir.h"

void adh_say(const char *msg)
{
    /* each byte escaped takes four: a why buffer's kilobytes fit whole;
     * on the stack, as a study's threads may say things at once */
    char shown[4 * 4096 + 1];
    adh_outdir_escape_text(msg ? msg : "", shown, sizeof shown, 1);
    fprintf(stderr, "adhere: %s\n", shown);
}
