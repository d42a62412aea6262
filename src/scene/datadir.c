#include "scene/datadir.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef ADH_DATADIR
#define ADH_DATADIR "/usr/local/share/adhere"
#endif

int adh_data_root(int i, char *buf, size_t len)
{
    if (i == 0) {
        const char *env = getenv("ADHERE_DATADIR");
        if (!env || !*env)
            return -1;
        snprintf(buf, len, "%s", env);
        return 0;
    }
    if (i == 1) {
        /* the executable's own path, not argv[0] nor the build's source
         * path: a copied tree then reads its own scenes */
        char exe[PATH_MAX];
        ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n <= 0)
            return -1;
        exe[n] = '\0';
        char *slash = strrchr(exe, '/');
        if (!slash)
            return -1;
        *slash = '\0';
        snprintf(buf, len, "%s/share/adhere", exe);
        return 0;
    }
    if (i == 2) {
        snprintf(buf, len, "%s", ADH_DATADIR);
        return 0;
    }
    return -1;
}

int adh_data_dir(const char *sub, char *buf, size_t len)
{
    char root[PATH_MAX];
    for (int i = 0; i < 3; i++) {
        if (adh_data_root(i, root, sizeof root) != 0)
            continue;
        struct stat st;
        snprintf(buf, len, "%s/%s", root, sub);
        if (stat(buf, &st) == 0 && S_ISDIR(st.st_mode))
            return 0;
    }
    return -1;
}

int adh_data_env_check(char *why, size_t whylen)
{
    const char *env = getenv("ADHERE_DATADIR");
    struct stat st;
    if (!env || !*env || (stat(env, &st) == 0 && S_ISDIR(st.st_mode)))
        return 0;
    snprintf(why, whylen, "ADHERE_DATADIR=%s is not a directory: set it to the one holding scenes/ and gnuplot/, or "
             "unset it (adhere then looks beside its executable and in %s)", env, ADH_DATADIR);
    return -1;
}
