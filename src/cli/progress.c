#include "cli/progress.h"

#include <math.h>
#include <stdio.h>

void cli_progress_duration(double s, char *buf, size_t len)
{
    if (!(s >= 0) || !isfinite(s))
        snprintf(buf, len, "?");
    else if (s < 60)
        snprintf(buf, len, "%.*f s", s < 10 ? 1 : 0, s);
    else if (s < 3600)
        snprintf(buf, len, "%d min %02d s", (int)(s / 60), (int)fmod(s, 60));
    else
        snprintf(buf, len, "%d h %02d min", (int)(s / 3600), (int)fmod(s / 60, 60));
}

void cli_progress_left(double frac, double left, char *buf, size_t len)
{
    if (!isfinite(left) || frac >= 1) {
        snprintf(buf, len, "%3.0f %%", 100 * frac);
        return;
    }
    char t[32];
    cli_progress_duration(left, t, sizeof t);
    snprintf(buf, len, "%3.0f %%, about %s left", 100 * frac, t);
}

void cli_progress_text(size_t done, size_t total, double elapsed, char *buf, size_t len)
{
    if (total == 0) {
        snprintf(buf, len, "%zu done", done);
        return;
    }
    if (done > total)
        done = total;
    double frac = (double)done / (double)total;
    if (done == 0 || done == total || elapsed <= 0) {
        snprintf(buf, len, "%3.0f %%", 100 * frac);
        return;
    }
    char left[32];
    cli_progress_duration(elapsed * (double)(total - done) / (double)done, left, sizeof left);
    snprintf(buf, len, "%3.0f %%, about %s left", 100 * frac, left);
}
