/* User text through gnuplot itself: every string adh_gp_quote makes, and
 * every file name adh_gp_path makes, comes back from the real gnuplot byte
 * for byte, with backquotes, @macros, $, quotes of both kinds, backslashes,
 * newlines and control bytes in it, and no command in it ever runs (a file
 * the command would create is never created). */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plot/gnuplot.h"
#include "plot/labels.h"
#include "tap.h"

static char work[256], canary[300];

static int exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

/* Whether a command ran: a file whose name starts with PWNED (the canary,
 * or the canary with bytes of the text after it) is in the work directory. */
static int canary_made(void)
{
    DIR *d = opendir(work);
    int found = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL)
        found |= strncmp(e->d_name, "PWNED", 5) == 0;
    if (d)
        closedir(d);
    return found;
}

/* The whole of a file, or NULL. */
static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 16);
    *n = buf ? fread(buf, 1, (1 << 16) - 1, f) : 0;
    fclose(f);
    if (buf)
        buf[*n] = '\0';
    return buf;
}

#define NRANDOM 300
#define MAXLEN 40

static void test_strings(adh_gnuplot *gp)
{
    static const char *const fixed[] = {
        "", "plain", "x`touch CANARY`y", "`touch CANARY`", "@adh_m", "a@adh_m b", "$HOME $(touch CANARY) ${x}",
        "it's", "'", "''", "'''", "'a'", "''`touch CANARY`''", "\"", "\"`touch CANARY`\"", "\\", "a\\",
        "\\'", "line1\nline2", "\n", "cr\rlf", "tab\there", "\001\002\033[31m\177", "# not a comment",
        "a; print 666", "σ = 1, γ = 2 mJ/m²", "<touch CANARY", "|touch CANARY", "{1,2}",
    };
    static const char *const alphabet[] = {
        "`", "@", "@adh_m", "$", "'", "\"", "\\", "\n", "\r", "\t", "#", ";", "|", "<", "~", "a", " ",
        "{", "}", "\001", "\177", "σ", "(", ")", "touch CANARY",
    };
    const size_t nfixed = sizeof fixed / sizeof fixed[0];
    const size_t nalpha = sizeof alphabet / sizeof alphabet[0];
    static char strings[sizeof fixed / sizeof fixed[0] + NRANDOM][MAXLEN * 16];
    size_t n = 0;
    /* CANARY is the canary file's path, so a command that ran would show */
    for (size_t i = 0; i < nfixed + NRANDOM; i++) {
        char raw[MAXLEN * 16] = "";
        if (i < nfixed) {
            snprintf(raw, sizeof raw, "%s", fixed[i]);
        } else {
            int len = 1 + rand() % MAXLEN;
            for (int k = 0; k < len && strlen(raw) + 16 < sizeof raw; k++)
                strcat(raw, alphabet[(size_t)rand() % nalpha]);
        }
        char *o = strings[n], *p = raw;
        char *hit;
        while ((hit = strstr(p, "CANARY")) != NULL) {
            o += sprintf(o, "%.*s%s", (int)(hit - p), p, canary);
            p = hit + 6;
        }
        strcpy(o, p);
        n++;
    }
    /* a macro that would change the text if it were ever expanded */
    adh_gnuplot_cmd(gp, "adh_m = 'EXPANDED'");
    char q[ADH_GP_QUOTED_SIZE(sizeof strings[0])], fq[ADH_GP_PATH_SIZE], file[400];
    for (size_t i = 0; i < n; i++) {
        snprintf(file, sizeof file, "%s/s%zu", work, i);
        adh_gnuplot_cmd(gp, "set print %s", adh_gp_path(file, fq, sizeof fq));
        adh_gnuplot_cmd(gp, "print %s", adh_gp_quoted(strings[i], q, sizeof q));
        adh_gnuplot_cmd(gp, "unset print");
    }
    adh_gnuplot_cmd(gp, "set print \"-\"");
    char msg[1024];
    int rc = adh_gnuplot_sync(gp, 60, msg, sizeof msg);
    ok(rc == 0, "gnuplot reads all %zu quoted strings without an error%s%s", n, rc ? ": " : "", rc ? msg : "");
    size_t same = 0, first_bad = n;
    for (size_t i = 0; i < n; i++) {
        snprintf(file, sizeof file, "%s/s%zu", work, i);
        size_t len;
        char *got = slurp(file, &len);
        /* print ends its line with a newline */
        size_t want = strlen(strings[i]);
        if (got && len == want + 1 && memcmp(got, strings[i], want) == 0 && got[want] == '\n')
            same++;
        else if (first_bad == n)
            first_bad = i;
        free(got);
    }
    ok(same == n, "every string comes back from gnuplot byte for byte (%zu of %zu%s%s)", same, n,
       first_bad < n ? "; first different: " : "", first_bad < n ? adh_gp_quoted(strings[first_bad], q, sizeof q) : "");
    ok(!canary_made(), "no backquoted or piped command ran (no %s* was created)", canary);
}

/* File names gnuplot would take for a pipe, a special file or ~, and names
 * with quotes, backquotes and a newline, relative to gnuplot's directory
 * (this test's): each is written under exactly that name. */
static void test_paths(adh_gnuplot *gp)
{
    char cmdname[400];
    snprintf(cmdname, sizeof cmdname, "|touch %s", canary);
    const char *const names[] = {
        "-", "+", "++", "~", "<touch x", cmdname, "|x", "a'b", "''", "`touch x`", "@adh_m", "new\nline", "$HOME",
        "sp ace", "\"q\"",
    };
    const size_t n = sizeof names / sizeof names[0];
    char fq[ADH_GP_PATH_SIZE];
    for (size_t i = 0; i < n; i++) {
        adh_gnuplot_cmd(gp, "set print %s", adh_gp_path(names[i], fq, sizeof fq));
        adh_gnuplot_cmd(gp, "print 'x'");
        adh_gnuplot_cmd(gp, "unset print");
    }
    adh_gnuplot_cmd(gp, "set print \"-\"");
    char msg[1024];
    int rc = adh_gnuplot_sync(gp, 60, msg, sizeof msg);
    ok(rc == 0, "gnuplot writes every odd file name without an error%s%s", rc ? ": " : "", rc ? msg : "");
    size_t found = 0;
    for (size_t i = 0; i < n; i++) {
        /* cmdname holds a '/': it names a file in a directory that does not
         * exist, so gnuplot cannot write it; the canary shows it never ran */
        if (names[i] == cmdname) {
            found++;
            continue;
        }
        char p[600];
        snprintf(p, sizeof p, "%s/%s", work, names[i]);
        if (exists(p))
            found++;
        else
            ok(0, "file %s was written under its own name", adh_gp_quoted(names[i], fq, sizeof fq));
    }
    ok(found == n, "each odd file name is written as itself, never as a pipe or a special file (%zu of %zu)",
       found, n);
    ok(!canary_made(), "no file name ran a command");
}

static void test_bounds(void)
{
    char small[20], q[64];
    size_t need = adh_gp_quote("a`b'c", small, 5);
    ok(need == strlen(adh_gp_quoted("a`b'c", q, sizeof q)), "the length returned is the whole expression's (%zu)",
       need);
    adh_gp_quote("a`b'c", small, 5);
    ok(strcmp(small, "") == 0, "too small a buffer for the fallback holds \"\", not a cut string");
    adh_gp_quote("a long title that will not fit", small, sizeof small);
    ok(strcmp(small, "adh_text_too_long") == 0,
       "too small a buffer holds an undefined name, so gnuplot fails loudly (%s)", small);
    const char worst[] = "\001a\001a\001a";
    need = adh_gp_quote(worst, q, sizeof q);
    ok(need < ADH_GP_QUOTED_SIZE(strlen(worst)), "ADH_GP_QUOTED_SIZE bounds the worst case (%zu < %zu)", need,
       ADH_GP_QUOTED_SIZE(strlen(worst)));
    ok(strcmp(adh_gp_path("/abs/x", q, sizeof q), "'/abs/x'") == 0, "an absolute path is kept as it is");
    ok(strcmp(adh_gp_path("<x", q, sizeof q), "'./<x'") == 0, "a relative path gets ./ in front: %s", q);
}

int main(void)
{
    snprintf(work, sizeof work, "/tmp/adhere-test-gpquote-XXXXXX");
    if (!mkdtemp(work)) {
        perror("mkdtemp");
        return 1;
    }
    snprintf(canary, sizeof canary, "%s/PWNED", work);
    srand(17);
    test_bounds();
    if (chdir(work) != 0) {
        perror(work);
        return 1;
    }
    char msg[1024];
    int log = open("gnuplot.log", O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    adh_gnuplot *gp = log >= 0 ? adh_gnuplot_open(log, "gnuplot.log", NULL, msg, sizeof msg) : NULL;
    if (!gp || adh_gnuplot_sync(gp, 20, msg, sizeof msg) != 0) {
        printf("ok %d # SKIP gnuplot does not run: %s\n", ++tap_n, msg);
        adh_gnuplot_close(gp);
        return tap_done();
    }
    test_strings(gp);
    test_paths(gp);
    adh_gnuplot_close(gp);
    close(log);
    if (chdir("/") == 0)
        tap_remove_dir(work);
    return tap_done();
}
