#include "plot/png.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plot/labels.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* Defaults sent before the style file, so a style may set only what it
 * changes and a missing style still gives the same figures: the installed
 * style itself, compiled in (the Makefile makes style.inc of it). */
static const char *const builtin_style[] = {
#include "style.inc"
};

void adh_png_begin(adh_gnuplot *gp, const char *style, const char *figure, const char *tmp_png)
{
    char q[ADH_GP_PATH_SIZE];
    adh_gnuplot_cmd(gp, "reset");
    for (size_t i = 0; i < sizeof builtin_style / sizeof builtin_style[0]; i++)
        adh_gnuplot_cmd(gp, "%s", builtin_style[i]);
    adh_gnuplot_cmd(gp, "adh_figure = %s", adh_gp_quoted(figure, q, sizeof q));
    if (style && style[0])
        adh_gnuplot_cmd(gp, "load %s", adh_gp_path(style, q, sizeof q));
    adh_gnuplot_cmd(gp, "set output %s", adh_gp_path(tmp_png, q, sizeof q));
}

static unsigned long be32(const unsigned char *b)
{
    return (unsigned long)b[0] << 24 | (unsigned long)b[1] << 16 | (unsigned long)b[2] << 8 | b[3];
}

/* What is wrong with the image f holds, or NULL for a whole PNG. */
static const char *png_fault(FILE *f)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    unsigned char b[8];
    const char *bad = NULL;
    size_t got = fread(b, 1, 8, f);
    /* nothing at all is a disk that took nothing; a start of the signature,
     * one that took a little; anything else is not an image */
    if (got == 0)
        bad = "empty: gnuplot could write nothing into it (a full disk?)";
    else if (got < 8 && memcmp(b, sig, got) == 0)
        bad = "cut short: it ends inside the PNG signature (a full disk?)";
    else if (got < 8 || memcmp(b, sig, 8) != 0)
        bad = "not a PNG (no PNG signature: does a style file set another terminal?)";
    /* chunk by chunk: length, type, data, CRC; IHDR first, IEND last,
     * ending exactly at the end of the file */
    for (long n = 0; !bad; n++) {
        if (fread(b, 1, 8, f) != 8) {
            bad = "cut short: it ends before its IEND chunk (a full disk?)";
            break;
        }
        unsigned long len = be32(b);
        if (len > 0x7fffffffUL) {
            bad = "a chunk length out of range";
            break;
        }
        if (n == 0 && memcmp(b + 4, "IHDR", 4) != 0) {
            bad = "no IHDR chunk first";
            break;
        }
        if (fseek(f, (long)len + 4, SEEK_CUR) != 0) {
            bad = "unreadable";
            break;
        }
        if (memcmp(b + 4, "IEND", 4) == 0) {
            long at = ftell(f);
            long end = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
            if (len != 0)
                bad = "an IEND chunk with data";
            else if (end < at)
                bad = "cut short inside its IEND chunk";
            else if (end > at)
                bad = "data after its IEND chunk";
            break;
        }
    }
    return bad;
}

int adh_png_check(const char *path, char *why, size_t whylen)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    FILE *f = fd >= 0 ? fdopen(fd, "rb") : NULL;
    if (!f) {
        snprintf(why, whylen, "cannot read it: %s", strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    struct stat st;
    const char *bad = fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ? "not a regular file" : png_fault(f);
    fclose(f);
    if (bad) {
        snprintf(why, whylen, "%s", bad);
        return -1;
    }
    return 0;
}

/* adh_outdir_write's writer: the checked image, byte for byte. */
static int copy_png(FILE *out, const void *ctx)
{
    FILE *in = (FILE *)ctx;
    char buf[65536];
    size_t n;
    rewind(in);
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, out) != n)
            return -1;
    return ferror(in) ? -1 : 0;
}

int adh_png_finish(adh_gnuplot *gp, const char *tmp_png, adh_outdir *out, const char *name, char *why,
                   size_t whylen)
{
    adh_gnuplot_cmd(gp, "unset output");
    int rc = adh_gnuplot_sync(gp, ADH_PNG_TIMEOUT_S, why, whylen);
    /* opened once, never through a link: what is checked is what is copied */
    int fd = rc == 0 ? open(tmp_png, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC) : -1;
    FILE *f = fd >= 0 ? fdopen(fd, "rb") : NULL;
    struct stat st;
    if (rc == 0 && !(f && fstat(fd, &st) == 0 && S_ISREG(st.st_mode))) {
        snprintf(why, whylen, "gnuplot wrote no image to %s", tmp_png);
        rc = -1;
    }
    /* a whole PNG or nothing under the final name */
    const char *bad = rc == 0 ? png_fault(f) : NULL;
    if (bad) {
        snprintf(why, whylen, "gnuplot's image is %s; removed", bad);
        rc = -1;
    }
    if (rc == 0 && adh_outdir_write(out, name, copy_png, f, why, whylen) != 0)
        rc = -1;
    if (f)
        fclose(f);
    else if (fd >= 0)
        close(fd);
    unlink(tmp_png);
    return rc;
}
