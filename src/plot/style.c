/* Which gnuplot style file a run uses. */
#include "plot/plot.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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
