#include "plot/session.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "plot/plot.h"
#include "plot/png.h"

/* name remembered for the end, once */
static void made(adh_session *s, const char *name)
{
    for (size_t i = 0; i < s->nmade; i++)
        if (!strcmp(s->made[i], name))
            return;
    if (s->nmade < ADH_SESSION_FILES)
        snprintf(s->made[s->nmade++], sizeof s->made[0], "%s", name);
}

int adh_session_open(adh_session *s, adh_outdir *out, const char *logname, const char *style,
                     const volatile sig_atomic_t *cancel, char *why, size_t whylen)
{
    memset(s, 0, sizeof *s);
    s->out = out;
    s->logname = logname;
    s->log_fd = -1;
    snprintf(s->logpath, sizeof s->logpath, "%s/%s", adh_outdir_path(out), logname);
    if (adh_plot_style_file(style, s->style, sizeof s->style, why, whylen) < 0)
        return -1;
    if (adh_outdir_temp("adhere-plot", s->tmpdir, sizeof s->tmpdir, why, whylen) != 0)
        return -1;
    s->log_fd = adh_outdir_log_open(out, logname, why, whylen);
    if (s->log_fd >= 0)
        s->gp = adh_gnuplot_open(s->log_fd, s->logpath, cancel, why, whylen);
    if (!s->gp) {
        adh_session_close(s);
        return -1;
    }
    return 0;
}

FILE *adh_session_data(adh_session *s, const char *name, char *path, size_t len, char *why, size_t whylen)
{
    snprintf(path, len, "%s/%s", s->tmpdir, name);
    made(s, name);
    unlink(path);   /* an earlier figure's */
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        snprintf(why, whylen, "cannot write %s: %s", path, strerror(errno));
        if (fd >= 0)
            close(fd);
    }
    return f;
}

static void image_path(const adh_session *s, const char *name, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s", s->tmpdir, name);
}

void adh_session_begin(adh_session *s, const char *figure, const char *name)
{
    char tmp[PATH_MAX + 64];
    image_path(s, name, tmp, sizeof tmp);
    made(s, name);
    adh_png_begin(s->gp, s->style, figure, tmp);
}

int adh_session_end(adh_session *s, const char *name, char *why, size_t whylen)
{
    char tmp[PATH_MAX + 64];
    image_path(s, name, tmp, sizeof tmp);
    return adh_png_finish(s->gp, tmp, s->out, name, why, whylen);
}

void adh_session_close(adh_session *s)
{
    adh_gnuplot_close(s->gp);
    s->gp = NULL;
    if (s->tmpdir[0]) {
        char p[PATH_MAX + 64];
        for (size_t i = 0; i < s->nmade; i++) {
            image_path(s, s->made[i], p, sizeof p);
            unlink(p);
        }
        rmdir(s->tmpdir);
        s->tmpdir[0] = '\0';
    }
    adh_outdir_log_close(s->out, s->logname, s->log_fd);
    s->log_fd = -1;
}
