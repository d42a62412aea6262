#include "plot/say.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "plot/outdir.h"

void adh_say_as(const char *who, const char *msg)
{
    /* each byte escaped takes four: a why buffer's kilobytes fit whole;
     * on the stack, as a study's threads may say things at once */
    char shown[4 * 4096 + 1];
    adh_outdir_escape_text(msg ? msg : "", shown, sizeof shown, 1);
    if (who)
        fprintf(stderr, "%s: %s\n", who, shown);
    else
        fprintf(stderr, "%s\n", shown);
}

void adh_say(const char *msg)
{
    adh_say_as("adhere", msg);
}

/* fmt's text formatted whole first, then escaped: a file name or a why
 * in it is shown as adh_say shows it. */
static void vsay(const char *who, const char *fmt, va_list ap)
{
    char msg[8192];
    vsnprintf(msg, sizeof msg, fmt, ap);
    adh_say_as(who, msg);
}

void adh_sayf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsay("adhere", fmt, ap);
    va_end(ap);
}

void adh_sayf_as(const char *who, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsay(who, fmt, ap);
    va_end(ap);
}
