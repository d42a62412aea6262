#include "plot/axes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double adh_plot_active_right(double active, double xmin, double xmax)
{
    return fmin(active + fmax(0.15 * (active - xmin), 1e-9), xmax);
}

void adh_gp_log_tics(double lo, double hi, char *buf, size_t len)
{
    static const double mant[3] = { 1, 2, 5 };
    int d0 = (int)floor(log10(lo)), d1 = (int)floor(log10(hi));
    int all = d1 - d0 < 4;
    size_t j = 0;
    buf[0] = '\0';
    if (len < 3)
        return;
    j += (size_t)snprintf(buf, len, "(");
    for (int d = d0; d <= d1; d++)
        for (int k = 0; k < (all ? 3 : 1); k++) {
            double t = mant[k] * pow(10.0, d);
            if (t < lo * (1 - 1e-9) || t > hi * (1 + 1e-9))
                continue;
            char one[32];
            int w = snprintf(one, sizeof one, "%s%g", j > 1 ? ", " : "", t);
            if (j + (size_t)w + 2 > len)
                break;
            memcpy(buf + j, one, (size_t)w + 1);
            j += (size_t)w;
        }
    snprintf(buf + j, len - j, ")");
}
