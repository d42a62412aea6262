/* Which gnuplot style file a run uses, and the branches' styles of it. */
#include "plot/plot.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plot/gnuplot.h"
#include "scene/datadir.h"

static int is_dir(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

int adh_plot_style_file(const char *style, char *buf, size_t len, char *msg, size_t msglen)
{
    if (style[0]) {
        if (is_dir(style))
            snprintf(buf, len, "%s/style.gp", style);
        else
            snprintf(buf, len, "%s", style);
        if (access(buf, R_OK) != 0) {
            snprintf(msg, msglen, "gnuplot style %s: %s", buf, strerror(errno));
            return -1;
        }
        return 0;
    }
    char dir[4096];
    if (adh_data_dir("gnuplot", dir, sizeof dir) == 0) {
        snprintf(buf, len, "%s/style.gp", dir);
        if (access(buf, R_OK) == 0)
            return 0;
    }
    if (len)
        buf[0] = '\0';
    return 1;
}

/* Unloading branch k (path k) takes the k-th colour of the style and the
 * k-th dash, cycling; when the colours and dashes would start over
 * together, the dashes move on by one, so no two of the first colours x
 * dashes branches look alike. */
void adh_plot_branch_styles(adh_gnuplot *gp)
{
    adh_gnuplot_cmd(gp, "adh_nc = words(adh_unload_colors); adh_nd = words(adh_unload_dashes)");
    adh_gnuplot_cmd(gp, "adh_ucol(p) = word(adh_unload_colors, 1 + (p - 1) %% adh_nc)");
    adh_gnuplot_cmd(gp, "adh_udash(p) = int(word(adh_unload_dashes, 1 + ((p - 1) + (p - 1) / adh_nc * "
                    "(adh_nc %% adh_nd == 0)) %% adh_nd))");
}
