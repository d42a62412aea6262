/* libFuzzer target: a measured curve (--data, adhere fit's input) read as
 * adh_measured_load reads a file, then labelled for a fit. It never
 * crashes; every refusal names the file; a curve it takes has at least 2
 * finite points, segments that cover them, and a refusal quotes no control
 * byte of the file (it reaches the terminal). An input starting with '@'
 * gives its first line as --columns. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "adhere/params.h"
#include "scene/fitdata.h"
#include "scene/measured.h"

static char path[64];

static void check_why(const char *why)
{
    if (strncmp(why, path, strlen(path)) != 0 && strncmp(why, "no measured points", 18) != 0 &&
        strncmp(why, "out of memory", 13) != 0)
        abort();   /* a refusal without the file */
    for (const char *p = why; *p; p++)
        if (((unsigned char)*p < 0x20 && *p != '\t') || *p == 0x7f)
            abort();   /* a control byte of the file quoted to the terminal (a tab moves it on, no harm) */
}

static void remove_file(void)
{
    unlink(path);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!path[0]) {
        snprintf(path, sizeof path, "/tmp/adhere-fuzz-measured-%ld.tsv", (long)getpid());
        atexit(remove_file);
    }
    char columns[64] = "";
    if (size && data[0] == '@') {
        const uint8_t *nl = memchr(data, '\n', size);
        size_t k = nl ? (size_t)(nl - data) : size;   /* the line, its '@' included */
        size_t cl = k - 1 < sizeof columns - 1 ? k - 1 : sizeof columns - 1;
        memcpy(columns, data + 1, cl);
        columns[cl] = '\0';
        for (size_t i = 0; i < cl; i++)   /* a flag the user typed: the file's bytes are what is checked */
            if ((unsigned char)columns[i] < 0x20 || columns[i] == 0x7f)
                columns[i] = '?';
        data += nl ? k + 1 : k;
        size -= nl ? k + 1 : k;
    }
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    adh_measured m;
    char why[1024] = "";
    if (adh_measured_load(path, columns[0] ? columns : NULL, &m, why, sizeof why) != 0) {
        check_why(why);
        return 0;
    }
    if (m.n < 2 || m.nseg < 1)
        abort();
    for (size_t i = 0; i < m.n; i++)
        if (!isfinite(m.h0[i]) || !isfinite(m.F[i]))
            abort();
    for (size_t s = 0; s < m.nseg; s++)
        if (m.seg[s].first + m.seg[s].n > m.n)
            abort();
    adh_material start = adh_material_default();
    adh_fitdata fd;
    why[0] = '\0';
    if (adh_fitdata_make(&m, 2, &start, 0, 0, &fd, why, sizeof why) == 0)
        adh_fitdata_free(&fd);
    else
        check_why(why);
    adh_measured_free(&m);
    return 0;
}
