/* The gnuplot process (handshake, error detection, death, hang, missing
 * program, an image on its output before the handshake, a signal while
 * waiting), the contact-line speed, and adh_plots_write on a synthetic
 * run: valid PNGs of the style's size, tables intact when gnuplot is
 * absent. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "adhere/params.h"
#include "adhere/protocol.h"
#include "plot/gnuplot.h"
#include "plot/outdir.h"
#include "plot/plot.h"
#include "plot/speed.h"
#include "plot/tsv.h"
#include "scene/plan.h"
#include "scene/config.h"
#include "scene/datadir.h"
#include "tap.h"

static char work[256];

/* gnuplot with its log at path (made or appended to); *fd the log's
 * descriptor, for the caller to close after adh_gnuplot_close. */
static adh_gnuplot *open_gp(const char *path, const volatile sig_atomic_t *cancel, int *fd, char *msg,
                            size_t len)
{
    *fd = open(path, O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (*fd < 0) {
        snprintf(msg, len, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    return adh_gnuplot_open(*fd, path, cancel, msg, len);
}

static void close_gp(adh_gnuplot *gp, int fd)
{
    adh_gnuplot_close(gp);
    if (fd >= 0)
        close(fd);
}

static int have_gnuplot(void)
{
    char msg[512];
    int fd;
    adh_gnuplot *gp = open_gp("/dev/null", NULL, &fd, msg, sizeof msg);
    int ok = gp && adh_gnuplot_sync(gp, 20, msg, sizeof msg) == 0;
    close_gp(gp, fd);
    return ok;
}

/* adh_plots_write into dir, opened as an output directory: its status, or
 * 2 when the directory cannot be opened (msg says why). */
static int plots_into(const adh_plot_setup *ps, const adh_run *run, const char *dir, char *msg, size_t len)
{
    adh_outdir *od = adh_outdir_open(dir, 0, msg, len);
    if (!od)
        return 2;
    int rc = adh_plots_write(ps, run, NULL, od, msg, len, NULL, 0);
    adh_outdir_close(od);
    return rc;
}

/* Files in dir whose names start with a dot, but for adhere's manifest:
 * temporaries. */
static int hidden_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return -1;
    struct dirent *e;
    while ((e = readdir(d)))
        n += e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
             strcmp(e->d_name, ADH_OUTDIR_MANIFEST);
    closedir(d);
    return n;
}

static int no_children_left(void)
{
    return waitpid(-1, NULL, WNOHANG) == -1 && errno == ECHILD;
}

static void path_in(char *buf, size_t len, const char *dir, const char *name)
{
    snprintf(buf, len, "%s/%s", dir, name);
}

static int exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

/* PNG signature and IHDR size; 0 when the file is a PNG. */
static int png_size(const char *path, unsigned *w, unsigned *h)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    unsigned char b[24];
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n != sizeof b || memcmp(b, sig, 8) != 0 || memcmp(b + 12, "IHDR", 4) != 0)
        return -1;
    *w = (unsigned)b[16] << 24 | (unsigned)b[17] << 16 | (unsigned)b[18] << 8 | b[19];
    *h = (unsigned)b[20] << 24 | (unsigned)b[21] << 16 | (unsigned)b[22] << 8 | b[23];
    return 0;
}

/* Counts data lines (not comments, not the header) of a table, -1 if absent;
 * *header gets the header line. */
static long table_rows(const char *path, char *header, size_t hlen)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[4096];
    long n = -1;
    header[0] = '\0';
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        if (n < 0) {
            snprintf(header, hlen, "%.500s", line);
            n = 0;
        } else {
            n++;
        }
    }
    fclose(f);
    return n;
}

/* Files in dir whose name contains part. */
static int count_matching(const char *dir, const char *part)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return -1;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strstr(e->d_name, part))
            n++;
    closedir(d);
    return n;
}

/* ------------------------------------------------------- synthetic run */

enum { NODES = 60 };

typedef struct synthetic {
    adh_plot_setup ps;
    char style[300];               /* ps.style */
    adh_run run;
    double store[4][3][NODES];
} synthetic;

static void add_row(adh_run *run, double h0, double F, double a, int branch, int path,
                    const adh_material *m)
{
    adh_obs *o = &run->rows[run->nrows++];
    memset(o, 0, sizeof *o);
    o->h0 = h0;
    o->F = F;
    o->a = a;
    o->branch = branch;
    o->path = path;
    o->converged = 1;
    o->stable = 1;
    o->F_rigid = h0 > 0 ? m->A * m->R / (6 * h0 * h0) * (pow(m->z0 / h0, 6) / 4 - 1) : 0;
}

/* Loading from 10 nm to -5 nm (contact below 2 nm, a growing linearly), an
 * unloading branch back out with a wider contact, two profile positions. */
static void make_synthetic(synthetic *s)
{
    memset(s, 0, sizeof *s);
    s->ps = (adh_plot_setup){ .mat = adh_material_default(), .figures = ADH_PLOT_ALL, .draw = 1,
                              .title = "", .drive_speed = 1e-6, .step = 0.05e-9, .nodes = NODES,
                              .dr = 10e-9, .style = s->style };
    s->ps.mat.E = 3e8;   /* Figure 4's sigma = 7.50 */
    adh_run_init(&s->run);
    s->run.rows = calloc(400, sizeof *s->run.rows);
    s->run.rows_cap = 400;
    const adh_material *m = &s->ps.mat;
    const double d = 0.1e-9;
    for (int k = 0; k <= 150; k++) {
        double h0 = 10e-9 - k * d;
        double a = h0 < 2e-9 ? 0.1e-6 + (2e-9 - h0) * 30 : 0;
        double F = a > 0 ? -2e-7 + (2e-9 - h0) * 40 : -1e-9 / (h0 * 1e9);
        add_row(&s->run, h0, F, a, +1, 0, m);
    }
    for (int k = 0; k <= 120; k++) {
        double h0 = -5e-9 + k * d;
        double a = h0 < 6e-9 ? 0.35e-6 - (h0 + 5e-9) * 20 : 0;
        double F = a > 0 ? 1e-7 - (h0 + 5e-9) * 80 : -1e-9;
        add_row(&s->run, h0, F, a, -1, 1, m);
    }
    s->run.nturns = 1;
    s->run.turns[0] = (adh_turn_result){ .h0 = -5e-9, .max_load = 1e-7, .a_turn = 0.35e-6,
                                         .pulloff_F = -7.8e-7, .pulloff_h0 = 5.9e-9,
                                         .jump_out_h0 = 6e-9, .path = 1 };
    s->run.profiles = calloc(4, sizeof *s->run.profiles);
    s->run.profiles_cap = 4;
    const double pos[2] = { 4e-9, -2e-9 };
    for (int k = 0; k < 4; k++) {
        adh_profile *pr = &s->run.profiles[s->run.nprofiles++];
        pr->h0 = pos[k % 2];
        pr->branch = k < 2 ? 1 : -1;
        pr->path = k < 2 ? 0 : 1;
        pr->u = s->store[k][0];
        pr->h = s->store[k][1];
        pr->p = s->store[k][2];
        for (size_t n = 0; n < NODES; n++) {
            double r = adh_plot_setup_radius(&s->ps, n);
            double h = pr->h0 + r * r / (2 * m->R);
            pr->h[n] = h < m->z0 ? m->z0 : h;
            pr->u[n] = pr->h[n] - h;
            pr->p[n] = 0;
        }
    }
}

static void free_synthetic(synthetic *s)
{
    free(s->run.rows);
    free(s->run.profiles);
}

/* ------------------------------------------------------------- tests */

static double clock_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static volatile sig_atomic_t *raised;
static void raise_flag(int sig)
{
    *raised = sig;
}

static void test_process(void)
{
    char log[300], msg[1024], last[512];
    int fd;
    path_in(log, sizeof log, work, "proc.log");
    adh_gnuplot *gp = open_gp(log, NULL, &fd, msg, sizeof msg);
    ok(gp != NULL, "gnuplot starts (%s)", gp ? "ok" : msg);
    if (!gp)
        return;
    adh_gnuplot_cmd(gp, "x = 1 + 1");
    ok(adh_gnuplot_sync(gp, 20, msg, sizeof msg) == 0, "a clean batch syncs");
    adh_gnuplot_cmd(gp, "plot no_such_function(x)");
    int rc = adh_gnuplot_sync(gp, 20, msg, sizeof msg);
    ok(rc == -1 && strstr(msg, "undefined function"),
       "an error in a batch is reported with gnuplot's words: %s", msg);
    ok(adh_gnuplot_alive(gp), "gnuplot keeps running after an error");
    adh_gnuplot_cmd(gp, "y = 2");
    ok(adh_gnuplot_sync(gp, 20, msg, sizeof msg) == 0,
       "the next clean batch syncs again (errors reset)");
    adh_gnuplot_log_last_line(fd, last, sizeof last);
    ok(strstr(last, "undefined function") != NULL,
       "gnuplot's stderr went to the log: last line \"%s\"", last);
    /* an image on gnuplot's output (no file to put it in) comes before the
     * handshake on the same line: the handshake is found all the same */
    adh_gnuplot_cmd(gp, "set terminal pngcairo size 200,100; unset output; plot x; unset output");
    double t0 = clock_now();
    ok(adh_gnuplot_sync(gp, 20, msg, sizeof msg) == 0 && clock_now() - t0 < 5,
       "a PNG on gnuplot's stdout before the handshake: synced in %.2f s (%s)", clock_now() - t0, msg);
    close_gp(gp, fd);
    ok(no_children_left(), "closing reaps gnuplot");
}

static void test_missing(void)
{
    char log[300], msg[1024];
    int fd, fd2;
    path_in(log, sizeof log, work, "missing.log");
    setenv("ADHERE_GNUPLOT", "/nonexistent/gnuplot", 1);
    adh_gnuplot *gp = open_gp(log, NULL, &fd, msg, sizeof msg);
    ok(gp == NULL && strstr(msg, "/nonexistent/gnuplot"),
       "a missing program is reported at open: %s", msg);
    unsetenv("ADHERE_GNUPLOT");
    char *old = getenv("PATH") ? strdup(getenv("PATH")) : NULL;
    setenv("PATH", "/nonexistent", 1);
    gp = open_gp(log, NULL, &fd2, msg, sizeof msg);
    ok(gp == NULL && strstr(msg, "not found on PATH"), "gnuplot off the PATH: %s", msg);
    close(fd);
    close(fd2);
    if (old) {
        setenv("PATH", old, 1);
        free(old);
    }
    ok(no_children_left(), "the failed child is reaped");
}

static void test_death_and_hang(void)
{
    char log[300], msg[1024], script[300];
    int fd;
    path_in(log, sizeof log, work, "death.log");

    /* a "gnuplot" that complains on stderr and dies */
    path_in(script, sizeof script, work, "dying-gnuplot");
    FILE *f = fopen(script, "w");
    fprintf(f, "#!/bin/sh\necho 'fatal: out of ink' >&2\nexit 7\n");
    fclose(f);
    chmod(script, 0755);
    setenv("ADHERE_GNUPLOT", script, 1);
    adh_gnuplot *gp = open_gp(log, NULL, &fd, msg, sizeof msg);
    ok(gp != NULL, "a dying gnuplot still starts");
    /* SIGPIPE must be ignored only while writing: the caller's handler stays */
    struct sigaction mine, seen;
    memset(&mine, 0, sizeof mine);
    mine.sa_handler = SIG_DFL;
    sigaction(SIGPIPE, &mine, NULL);
    /* let it die first, so the writes meet a closed pipe: wait for its exit
     * (WNOWAIT leaves the status for adh_gnuplot_sync to read) */
    siginfo_t si;
    int died = 0;
    for (int i = 0; i < 1000 && !died; i++) {
        memset(&si, 0, sizeof si);
        died = waitid(P_ALL, 0, &si, WEXITED | WNOHANG | WNOWAIT) == 0 && si.si_pid != 0;
        if (!died)
            nanosleep(&(struct timespec){ 0, 10000000 }, NULL);
    }
    ok(died, "the dying gnuplot has exited before anything is written to it");
    for (int i = 0; i < 2000; i++)
        adh_gnuplot_cmd(gp, "set title \"%d filling the pipe past its buffer\"", i);
    int rc = adh_gnuplot_sync(gp, 5, msg, sizeof msg);
    ok(rc == -1 && strstr(msg, "status 7") && strstr(msg, "out of ink"),
       "death is reported with the exit status and the log's last line: %s", msg);
    sigaction(SIGPIPE, NULL, &seen);
    ok(seen.sa_handler == SIG_DFL, "SIGPIPE disposition restored after writing");
    ok(!adh_gnuplot_alive(gp), "a dead gnuplot is not alive");
    ok(adh_gnuplot_sync(gp, 5, msg, sizeof msg) == -1, "later syncs fail at once");
    close_gp(gp, fd);

    /* a "gnuplot" that never answers */
    path_in(script, sizeof script, work, "hung-gnuplot");
    f = fopen(script, "w");
    fprintf(f, "#!/bin/sh\nexec sleep 30\n");
    fclose(f);
    chmod(script, 0755);
    setenv("ADHERE_GNUPLOT", script, 1);
    gp = open_gp(log, NULL, &fd, msg, sizeof msg);
    rc = adh_gnuplot_sync(gp, 0.5, msg, sizeof msg);
    ok(rc == -1 && strstr(msg, "did not answer"), "a hung gnuplot times out: %s", msg);
    close_gp(gp, fd);
    ok(no_children_left(), "the hung child is killed and reaped");

    /* a signal while waiting for it: the caller's flag ends the wait within
     * 0.1 s of its being raised (SIGALRM raises it here, 0.2 s in), not at
     * the timeout */
    static volatile sig_atomic_t flag;
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = raise_flag;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGALRM, &sa, &old);
    raised = &flag;
    gp = open_gp(log, &flag, &fd, msg, sizeof msg);
    double t0 = clock_now();
    struct itimerval it = { { 0, 0 }, { 0, 200000 } };
    setitimer(ITIMER_REAL, &it, NULL);
    rc = adh_gnuplot_sync(gp, 30, msg, sizeof msg);
    double took = clock_now() - t0;
    ok(rc == -1 && strstr(msg, "interrupted") && took < 1.0,
       "a hung gnuplot, a signal 0.2 s in: the wait ends after %.2f s (below 1 s): %s", took, msg);
    t0 = clock_now();
    close_gp(gp, fd);
    ok(clock_now() - t0 < 1.0 && no_children_left(), "and gnuplot is killed at once (%.2f s)", clock_now() - t0);
    sigaction(SIGALRM, &old, NULL);
    unsetenv("ADHERE_GNUPLOT");
}

static void test_contact_speed(void)
{
    synthetic s;
    make_synthetic(&s);
    size_t n = s.run.nrows;
    double *dadh0 = malloc(n * sizeof *dadh0), *dadt = malloc(n * sizeof *dadt);
    adh_speed_stepwise(&s.run, 1e-6, dadh0, dadt);
    /* loading: a = 0.1 um + 30 (2 nm - h0), so da/dh0 = -30, da/dt = +30 um/s */
    size_t load_mid = 100, unload_mid = 151 + 50, out = 10, turn = 151;
    ok_rel(dadh0[load_mid], -30.0, 1e-6, "loading da/dh0");
    ok_rel(dadt[load_mid], 30e-6, 1e-6, "loading contact line spreads at 30 um/s");
    /* unloading: a = 0.35 um - 20 (h0 + 5 nm): da/dh0 = -20, h0 rising: -20 um/s */
    ok_rel(dadt[unload_mid], -20e-6, 1e-6, "unloading contact line recedes at 20 um/s");
    ok(isnan(dadt[out]), "no speed out of contact");
    ok_rel(dadt[turn], -20e-6, 1e-6, "one-sided at the start of a branch");
    ok_rel(adh_plot_setup_radius(&s.ps, 0), 5e-9, 1e-12, "first node at dr/2");
    /* smoothing a steady spreading changes nothing; on a stick-slip staircase
     * it recovers the mean speed the step-by-step derivative hides */
    double *sm = malloc(n * sizeof *sm);
    adh_speed_smoothed(&s.run, 1e-6, 10e-9, 2.0, sm);
    ok_rel(sm[load_mid], 30e-6, 1e-6, "smoothed loading speed of a steady line");
    ok(isnan(sm[out]), "no smoothed speed out of contact");
    for (size_t i = 0; i < n; i++)
        if (s.run.rows[i].path == 0 && s.run.rows[i].a > 0)   /* hop a node every 5 steps */
            s.run.rows[i].a = 0.1e-6 + 10e-9 * floor((2e-9 - s.run.rows[i].h0) / 0.5e-9 + 1e-9);
    adh_speed_stepwise(&s.run, 1e-6, dadh0, dadt);
    adh_speed_smoothed(&s.run, 1e-6, 10e-9, 2.0, sm);
    ok(dadt[load_mid] == 0 || dadt[load_mid] > 45e-6,
       "the staircase's step-by-step speed is 0 or a spike (%g)", dadt[load_mid]);
    ok_rel(sm[load_mid], 20e-6, 0.15, "its smoothed speed is the mean 20 um/s");
    free(sm);
    free(dadh0);
    free(dadt);
    free_synthetic(&s);
}

static void check_pngs(const char *dir, unsigned w, unsigned h, const char *what)
{
    const char *names[] = { "force.png", "profile.png", "contact.png" };
    for (int i = 0; i < 3; i++) {
        char p[400];
        unsigned pw = 0, ph = 0;
        path_in(p, sizeof p, dir, names[i]);
        int rc = png_size(p, &pw, &ph);
        ok(rc == 0 && pw == w && ph == h, "%s: %s is a %ux%u PNG (got %s %ux%u)", what,
           names[i], w, h, rc == 0 ? "PNG" : "no PNG", pw, ph);
    }
}

static void check_tables(const char *dir, const synthetic *s, const char *what)
{
    char p[400], header[512];
    path_in(p, sizeof p, dir, "profiles.tsv");
    long n = table_rows(p, header, sizeof header);
    ok(n == (long)(s->run.nprofiles * NODES) && strcmp(header, "h0\tbranch\tpath\tr\th\tu\tp\th_sphere\n") == 0,
       "%s: profiles.tsv has its header and %zu rows (got %ld)", what,
       s->run.nprofiles * NODES, n);
    path_in(p, sizeof p, dir, "contact.tsv");
    n = table_rows(p, header, sizeof header);
    ok(n == (long)s->run.nrows && strcmp(header, "h0\tbranch\tpath\ta\tda_dh0\tda_dt\tda_dt_smooth\n") == 0,
       "%s: contact.tsv has its header and one row per step (got %ld)", what, n);
}

static void test_plots(void)
{
    synthetic s;
    make_synthetic(&s);
    char dir[300], msg[2048], p[400];

    path_in(dir, sizeof dir, work, "plots");
    mkdir(dir, 0755);
    int rc = plots_into(&s.ps, &s.run, dir, msg, sizeof msg);
    ok(rc == 0, "plots written: rc %d, %s", rc, msg);
    check_pngs(dir, 900, 600, "installed style");
    check_tables(dir, &s, "with gnuplot");
    ok(hidden_files(dir) == 0, "no temporary files left in the output dir");
    ok(count_matching(work, "adhere-plot-") == 0, "the data temp dir is removed");
    path_in(p, sizeof p, dir, "gnuplot.log");
    ok(!exists(p), "an empty gnuplot.log is not left behind");

    /* profiles.tsv carries full precision */
    path_in(p, sizeof p, dir, "profiles.tsv");
    FILE *f = fopen(p, "r");
    char line[1024] = "";
    while (f && fgets(line, sizeof line, f) && (line[0] == '#' || line[0] == 'h'))
        ;
    if (f)
        fclose(f);
    double h0, r;
    int b, pa;
    ok(sscanf(line, "%lg\t%d\t%d\t%lg", &h0, &b, &pa, &r) == 4 && h0 == s.run.profiles[0].h0 &&
       r == adh_plot_setup_radius(&s.ps, 0), "table numbers round-trip exactly");

    /* a style of another size, given as a file */
    char style[300], dir2[300];
    path_in(style, sizeof style, work, "small.gp");
    f = fopen(style, "w");
    fprintf(f, "set terminal pngcairo size 640,480\n");
    fclose(f);
    snprintf(s.style, sizeof s.style, "%s", style);
    path_in(dir2, sizeof dir2, work, "small");
    mkdir(dir2, 0755);
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 0, "custom style: rc %d, %s", rc, msg);
    check_pngs(dir2, 640, 480, "--gnuplot-style");

    /* a style with an error: reported, nothing half-written */
    f = fopen(style, "w");
    fprintf(f, "set no_such_option 1\n");
    fclose(f);
    path_in(dir2, sizeof dir2, work, "badstyle");
    mkdir(dir2, 0755);
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 3 && strstr(msg, "gnuplot error"), "an error in the style returns 3 and quotes "
       "gnuplot: %s", msg);
    ok(count_matching(dir2, ".png") == 0, "no PNG, not even a temporary one, after an error");
    path_in(p, sizeof p, dir2, "gnuplot.log");
    ok(exists(p), "gnuplot.log is kept when gnuplot complained");
    check_tables(dir2, &s, "bad style");

    /* a style that does not exist */
    snprintf(s.style, sizeof s.style, "%s/nope.gp", work);
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 3 && strstr(msg, "nope.gp"), "a missing style file is named: %s", msg);
    s.style[0] = '\0';

    /* gnuplot missing: exit code 3, tables intact */
    path_in(dir2, sizeof dir2, work, "nognuplot");
    mkdir(dir2, 0755);
    setenv("ADHERE_GNUPLOT", "/nonexistent/gnuplot", 1);
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    unsetenv("ADHERE_GNUPLOT");
    ok(rc == 3 && strstr(msg, "tables written"), "no gnuplot: rc 3 and says so: %s", msg);
    ok(count_matching(dir2, ".png") == 0, "no gnuplot: no PNG");
    check_tables(dir2, &s, "no gnuplot");

    /* plots off: tables only */
    path_in(dir2, sizeof dir2, work, "noplot");
    mkdir(dir2, 0755);
    s.ps.draw = 0;
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 0 && count_matching(dir2, ".png") == 0, "--no-plot: rc 0, no PNG");
    check_tables(dir2, &s, "no plot");

    /* a graded grid: each profile row carries its own node's radius, one
     * row per node of the grid, not of a uniform spacing */
    double radii[NODES];
    for (size_t n = 0; n < NODES; n++)
        radii[n] = 5e-9 * pow(1.05, (double)n) * (double)(n + 1);
    s.ps.r = radii;
    path_in(dir2, sizeof dir2, work, "graded");
    mkdir(dir2, 0755);
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    path_in(p, sizeof p, dir2, "profiles.tsv");
    f = fopen(p, "r");
    size_t rows = 0, same = 0;
    while (f && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == 'h')
            continue;
        if (sscanf(line, "%lg\t%d\t%d\t%lg", &h0, &b, &pa, &r) == 4 && r == radii[rows % NODES])
            same++;
        rows++;
    }
    if (f)
        fclose(f);
    ok(rc == 0 && rows == s.run.nprofiles * NODES && same == rows,
       "graded grid: profiles.tsv has the grid's node radii (%zu of %zu rows)", same, rows);
    s.ps.r = NULL;
    s.ps.draw = 1;

    /* a selection */
    path_in(dir2, sizeof dir2, work, "select");
    mkdir(dir2, 0755);
    s.ps.figures = ADH_PLOT_CONTACT;
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    path_in(p, sizeof p, dir2, "contact.png");
    ok(rc == 0 && exists(p) && count_matching(dir2, ".png") == 1,
       "--plots=contact makes contact.png alone");
    s.ps.figures = ADH_PLOT_ALL;

    /* no profiles stored: profile.png skipped with a note */
    path_in(dir2, sizeof dir2, work, "noprof");
    mkdir(dir2, 0755);
    size_t keep = s.run.nprofiles;
    s.run.nprofiles = 0;
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    path_in(p, sizeof p, dir2, "profile.png");
    ok(rc == 0 && !exists(p) && strstr(msg, "--profiles"),
       "no profiles: profile.png skipped and the message says how: %s", msg);
    s.run.nprofiles = keep;

    /* several turns: the adhesion panel is drawn */
    path_in(dir2, sizeof dir2, work, "turns");
    mkdir(dir2, 0755);
    s.run.nturns = 2;
    s.run.turns[1] = s.run.turns[0];
    s.run.turns[1].h0 = -1e-9;
    s.run.turns[1].max_load = -5e-8;
    s.run.turns[1].pulloff_F = -6e-7;
    s.run.turns[1].path = 2;
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 0, "two turns: force.png with the adhesion panel: %s", msg);
    s.run.nturns = 1;

    /* an output directory that cannot be made (under a file) */
    path_in(p, sizeof p, work, "afile");
    fclose(fopen(p, "w"));
    path_in(dir2, sizeof dir2, work, "afile/dir");
    rc = plots_into(&s.ps, &s.run, dir2, msg, sizeof msg);
    ok(rc == 2 && strstr(msg, "afile"), "a directory that cannot be made is refused: %s", msg);
    ok(no_children_left(), "no gnuplot left running");
    free_synthetic(&s);
}

static void test_data_dir(void)
{
    char buf[512], d[300];
    path_in(d, sizeof d, work, "data");
    mkdir(d, 0755);
    path_in(buf, sizeof buf, d, "gnuplot");
    mkdir(buf, 0755);
    const char *was = getenv("ADHERE_DATADIR");
    char saved[4096] = "";
    if (was)
        snprintf(saved, sizeof saved, "%s", was);
    setenv("ADHERE_DATADIR", d, 1);
    ok(adh_data_dir("gnuplot", buf, sizeof buf) == 0 && strstr(buf, work) == buf,
       "$ADHERE_DATADIR comes first: %s", buf);
    if (was)
        setenv("ADHERE_DATADIR", saved, 1);
    else
        unsetenv("ADHERE_DATADIR");
    ok(adh_data_dir("gnuplot", buf, sizeof buf) == 0, "an installed or source style dir: %s",
       buf);
    char msg[256];
    int rc = adh_plot_style_file("", buf, sizeof buf, msg, sizeof msg);
    ok(rc == 0 && strstr(buf, "style.gp"), "the installed style.gp is found: %s", buf);
}

static void test_default_profiles(void)
{
    adh_config cfg;
    adh_config_default(&cfg);
    double pos[8];
    size_t n = adh_config_default_profiles(&cfg.spec.mat, &cfg.spec.proto, pos, 6);
    double start = adh_protocol_auto_start(&cfg.spec.mat, cfg.spec.proto.step);
    ok(n == 6, "six default profile positions (got %zu)", n);
    ok(n && pos[0] == cfg.spec.proto.turns[0], "the first is the turn itself (%g)", n ? pos[0] : 0);
    ok(n && fabs(pos[n - 1] - 0.5 * start) <= cfg.spec.proto.step,
       "the last is half the start (%g vs %g)", n ? pos[n - 1] : 0, 0.5 * start);
    int on_grid = 1;
    for (size_t i = 1; i < n; i++) {
        double k = round((start - pos[i]) / cfg.spec.proto.step);
        on_grid &= pos[i] == start - k * cfg.spec.proto.step && pos[i] > pos[i - 1];
    }
    ok(on_grid, "each lies exactly on the drive grid start - k d, rising");
    cfg.spec.proto.nturns = 0;
    n = adh_config_default_profiles(&cfg.spec.mat, &cfg.spec.proto, pos, 4);
    ok(n == 4 && pos[0] > 0, "with no turn they start near the jump separation (%g)",
       n ? pos[0] : 0);
}

int main(void)
{
    snprintf(work, sizeof work, "/tmp/adhere-test-gnuplot-XXXXXX");
    if (!mkdtemp(work)) {
        perror("mkdtemp");
        return 1;
    }
    setenv("TMPDIR", work, 1);
    test_contact_speed();
    test_default_profiles();
    test_data_dir();
    test_missing();
    if (!have_gnuplot()) {
        tap_skip("gnuplot is not installed: no process or PNG checks");
        return tap_done();
    }
    test_process();
    test_death_and_hang();
    test_plots();
    tap_remove_dir(work);
    return tap_done();
}
