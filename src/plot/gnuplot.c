#include "plot/gnuplot.h"
#include "adhere/clock.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

struct adh_gnuplot {
    pid_t pid;          /* 0 once reaped */
    int to_child;       /* gnuplot's stdin; -1 once closed */
    int from_child;     /* gnuplot's stdout, where `set print "-"` sends sync lines */
    int broken;         /* died, timed out, or a write failed */
    int write_errno;    /* why a queued write failed, 0 if none */
    unsigned seq;       /* number of the last sync sent */
    char *out; size_t outlen, outcap;   /* commands not yet sent */
    char in[4096]; size_t inlen;        /* partial line read back */
    int log_fd;                         /* the caller's; read for messages */
    const volatile sig_atomic_t *cancel;
    char logname[4096];
};

const char *adh_gnuplot_program(void)
{
    const char *p = getenv("ADHERE_GNUPLOT");
    return p && *p ? p : "gnuplot";
}

static void set_cloexec(int fd)
{
    int fl = fcntl(fd, F_GETFD);
    if (fl >= 0)
        fcntl(fd, F_SETFD, fl | FD_CLOEXEC);
}

static void close_fd(int *fd)
{
    if (*fd >= 0)
        close(*fd);
    *fd = -1;
}

static void sleep_ms(long ms)
{
    struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
    while (nanosleep(&ts, &ts) < 0 && errno == EINTR)
        ;
}

/* In the child between fork and exec: only async-signal-safe calls. */
static void exec_child(const char *prog, int in_fd, int out_fd, int log_fd, int err_fd)
{
    /* The parent may ignore SIGPIPE or block signals (the TUI does); gnuplot
     * must start with ordinary dispositions or it could not be stopped. */
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(SIGPIPE, &dfl, NULL);
    sigaction(SIGINT, &dfl, NULL);
    sigaction(SIGTERM, &dfl, NULL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);

    if (dup2(in_fd, 0) < 0 || dup2(out_fd, 1) < 0 || dup2(log_fd, 2) < 0) {
        int e = errno;
        (void)!write(err_fd, &e, sizeof e);
        _exit(127);
    }
    char *const argv[] = { (char *)prog, (char *)"-d", NULL };
    execvp(prog, argv);
    int e = errno;
    (void)!write(err_fd, &e, sizeof e);
    _exit(127);
}

adh_gnuplot *adh_gnuplot_open(int log_fd, const char *logname, const volatile sig_atomic_t *cancel, char *msg,
                              size_t msglen)
{
    const char *prog = adh_gnuplot_program();
    int in_pipe[2] = { -1, -1 }, out_pipe[2] = { -1, -1 }, err_pipe[2] = { -1, -1 };
    adh_gnuplot *gp = calloc(1, sizeof *gp);
    if (!gp || pipe(in_pipe) < 0 || pipe(out_pipe) < 0 || pipe(err_pipe) < 0) {
        snprintf(msg, msglen, "cannot start gnuplot: %s", strerror(errno ? errno : ENOMEM));
        goto fail;
    }
    for (int i = 0; i < 2; i++) {
        set_cloexec(in_pipe[i]);
        set_cloexec(out_pipe[i]);
        set_cloexec(err_pipe[i]);
    }
    snprintf(gp->logname, sizeof gp->logname, "%s", logname);
    gp->log_fd = log_fd;
    gp->cancel = cancel;
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(msg, msglen, "cannot start gnuplot: fork: %s", strerror(errno));
        goto fail;
    }
    if (pid == 0)
        exec_child(prog, in_pipe[0], out_pipe[1], log_fd, err_pipe[1]);
    gp->pid = pid;
    close_fd(&in_pipe[0]);
    close_fd(&out_pipe[1]);
    close_fd(&err_pipe[1]);
    gp->to_child = in_pipe[1];
    gp->from_child = out_pipe[0];

    /* The exec-error pipe closes unread when exec succeeds (close-on-exec);
     * otherwise the child wrote its errno there before exiting. */
    int child_errno = 0;
    ssize_t n;
    while ((n = read(err_pipe[0], &child_errno, sizeof child_errno)) < 0 && errno == EINTR)
        ;
    close_fd(&err_pipe[0]);
    if (n > 0) {
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            ;
        gp->pid = 0;
        if (child_errno == ENOENT && !strchr(prog, '/'))
            snprintf(msg, msglen, "gnuplot not found on PATH (install gnuplot, e.g. the "
                     "Debian package gnuplot-nox)");
        else
            snprintf(msg, msglen, "cannot run %s: %s", prog, strerror(child_errno));
        adh_gnuplot_close(gp);
        return NULL;
    }
    /* Sync lines come back on stdout; the pngcairo terminal never writes there. */
    adh_gnuplot_cmd(gp, "set print \"-\"");
    return gp;

fail:
    close_fd(&in_pipe[0]); close_fd(&in_pipe[1]);
    close_fd(&out_pipe[0]); close_fd(&out_pipe[1]);
    close_fd(&err_pipe[0]); close_fd(&err_pipe[1]);
    free(gp);
    return NULL;
}

void adh_gnuplot_cmd(adh_gnuplot *gp, const char *fmt, ...)
{
    if (!gp || gp->broken)
        return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        size_t room = gp->outcap - gp->outlen;
        int n = vsnprintf(gp->out ? gp->out + gp->outlen : NULL, room, fmt, ap);
        va_end(ap);
        if (n < 0) {
            gp->write_errno = EINVAL;
            return;
        }
        if ((size_t)n + 2 <= room) {
            gp->out[gp->outlen + (size_t)n] = '\n';
            gp->outlen += (size_t)n + 1;
            return;
        }
        size_t cap = gp->outcap ? gp->outcap : 4096;
        while (cap < gp->outlen + (size_t)n + 2)
            cap *= 2;
        char *p = realloc(gp->out, cap);
        if (!p) {
            gp->write_errno = ENOMEM;
            return;
        }
        gp->out = p;
        gp->outcap = cap;
    }
}

/* Writes everything queued. SIGPIPE is ignored for the duration so that a
 * dead gnuplot shows up as EPIPE here rather than killing the program;
 * the caller's disposition is restored afterwards. */
static int flush_out(adh_gnuplot *gp)
{
    struct sigaction ign, old;
    memset(&ign, 0, sizeof ign);
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGPIPE, &ign, &old);
    size_t off = 0;
    int rc = 0;
    while (off < gp->outlen) {
        ssize_t n = write(gp->to_child, gp->out + off, gp->outlen - off);
        if (n < 0) {
            if (errno == EINTR && !(gp->cancel && *gp->cancel))
                continue;
            gp->write_errno = errno;
            rc = -1;
            break;
        }
        off += (size_t)n;
    }
    sigaction(SIGPIPE, &old, NULL);
    gp->outlen = 0;
    return rc;
}

static void reap(adh_gnuplot *gp, int *status)
{
    *status = -1;
    if (gp->pid <= 0)
        return;
    /* gnuplot has closed its stdout, so it is exiting or gone; a short wait
     * collects its status without ever blocking on a hung child. */
    for (int i = 0; i < 100; i++) {
        pid_t r = waitpid(gp->pid, status, WNOHANG);
        if (r == gp->pid || (r < 0 && errno != EINTR)) {
            gp->pid = 0;
            return;
        }
        sleep_ms(10);
    }
    kill(gp->pid, SIGKILL);
    while (waitpid(gp->pid, status, 0) < 0 && errno == EINTR)
        ;
    gp->pid = 0;
}

static void describe_death(adh_gnuplot *gp, int status, char *msg, size_t msglen)
{
    char last[512];
    adh_gnuplot_log_last_line(gp->log_fd, last, sizeof last);
    char how[64];
    if (status >= 0 && WIFSIGNALED(status))
        snprintf(how, sizeof how, "killed by signal %d", WTERMSIG(status));
    else if (status >= 0 && WIFEXITED(status))
        snprintf(how, sizeof how, "exited with status %d", WEXITSTATUS(status));
    else
        snprintf(how, sizeof how, "stopped");
    if (*last)
        snprintf(msg, msglen, "gnuplot %s: %s (log: %s)", how, last, gp->logname);
    else
        snprintf(msg, msglen, "gnuplot %s (log: %s)", how, gp->logname);
}

/* Parses "ADH_SYNC seq errno message" wherever it starts in the n bytes of
 * line (an image gnuplot wrote to its output may come before it on the
 * same line). Returns 1 when it is the sync for seq (filling *err and
 * errmsg), 0 for any other line. */
static int parse_sync(const char *line, size_t n, unsigned seq, int *err, char *errmsg, size_t len)
{
    static const char tag[] = "ADH_SYNC ";
    const char *at = NULL;
    for (size_t i = 0; i + sizeof tag - 1 <= n && !at; i++)
        if (memcmp(line + i, tag, sizeof tag - 1) == 0)
            at = line + i;
    unsigned s;
    int e, off = 0;
    if (!at || sscanf(at, "ADH_SYNC %u %d %n", &s, &e, &off) < 2 || s != seq)
        return 0;
    line = at;
    *err = e;
    snprintf(errmsg, len, "%s", line + off);
    return 1;
}

int adh_gnuplot_sync(adh_gnuplot *gp, double timeout_s, char *msg, size_t msglen)
{
    if (!gp || gp->broken) {
        snprintf(msg, msglen, "gnuplot is not running");
        return -1;
    }
    gp->seq++;
    /* `reset errors` clears GPVAL_ERRNO so each sync reports only its batch. */
    adh_gnuplot_cmd(gp, "print sprintf(\"ADH_SYNC %u %%d %%s\", GPVAL_ERRNO, GPVAL_ERRMSG)",
                    gp->seq);
    adh_gnuplot_cmd(gp, "reset errors");
    if (gp->write_errno == ENOMEM || gp->write_errno == EINVAL) {
        snprintf(msg, msglen, "cannot queue gnuplot commands: %s", strerror(gp->write_errno));
        gp->broken = 1;
        return -1;
    }
    /* EINTR: the cancel flag, which the wait below answers */
    if (flush_out(gp) < 0 && gp->write_errno != EPIPE && gp->write_errno != EINTR) {
        snprintf(msg, msglen, "cannot write to gnuplot: %s", strerror(gp->write_errno));
        gp->broken = 1;
        return -1;
    }
    /* On EPIPE gnuplot is dead: reading to EOF below reports how it died. */
    double deadline = adh_clock_seconds() + timeout_s;
    for (;;) {
        char *nl;
        while ((nl = memchr(gp->in, '\n', gp->inlen)) != NULL) {
            *nl = '\0';
            int err = 0;
            char errmsg[512];
            int found = parse_sync(gp->in, (size_t)(nl - gp->in), gp->seq, &err, errmsg, sizeof errmsg);
            size_t used = (size_t)(nl - gp->in) + 1;
            memmove(gp->in, nl + 1, gp->inlen - used);
            gp->inlen -= used;
            if (found) {
                if (err == 0)
                    return 0;
                /* the log's line also names the file and line (a style file) */
                char last[512];
                adh_gnuplot_log_last_line(gp->log_fd, last, sizeof last);
                snprintf(msg, msglen, "gnuplot error: %s (log: %s)",
                         *errmsg && strstr(last, errmsg) ? last : errmsg, gp->logname);
                return -1;
            }
        }
        /* a line longer than the buffer (an image on gnuplot's output): its
         * tail is kept, where a sync line could be starting */
        if (gp->inlen == sizeof gp->in) {
            memmove(gp->in, gp->in + gp->inlen - 64, 64);
            gp->inlen = 64;
        }
        double left = deadline - adh_clock_seconds();
        int cancelled = gp->cancel && *gp->cancel;
        if (left <= 0 || cancelled) {
            if (cancelled)
                snprintf(msg, msglen, "interrupted by signal %d; stopped gnuplot", (int)*gp->cancel);
            else
                snprintf(msg, msglen, "gnuplot did not answer within %.3g s; stopped it (log: %s)",
                         timeout_s, gp->logname);
            gp->broken = 1;
            if (gp->pid > 0)
                kill(gp->pid, SIGKILL);
            int st;
            reap(gp, &st);
            return -1;
        }
        /* in slices, so that a raised cancel flag is seen within 0.1 s even
         * when its signal came just before the poll */
        struct pollfd pfd = { gp->from_child, POLLIN, 0 };
        int pr = poll(&pfd, 1, left > 0.1 ? 100 : (int)(left * 1000) + 1);
        if (pr < 0 && errno != EINTR) {
            snprintf(msg, msglen, "cannot read from gnuplot: %s", strerror(errno));
            gp->broken = 1;
            return -1;
        }
        if (pr <= 0)
            continue;
        ssize_t n = read(gp->from_child, gp->in + gp->inlen, sizeof gp->in - gp->inlen);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int st;
            gp->broken = 1;
            reap(gp, &st);
            describe_death(gp, st, msg, msglen);
            return -1;
        }
        gp->inlen += (size_t)n;
    }
}

int adh_gnuplot_alive(const adh_gnuplot *gp)
{
    return gp && !gp->broken && gp->pid > 0;
}

void adh_gnuplot_close(adh_gnuplot *gp)
{
    if (!gp)
        return;
    if (gp->pid > 0 && gp->cancel && *gp->cancel)
        kill(gp->pid, SIGKILL);   /* interrupted: the figure is abandoned, no grace */
    if (gp->pid > 0 && !gp->broken && gp->to_child >= 0) {
        gp->outlen = 0;
        adh_gnuplot_cmd(gp, "quit");
        flush_out(gp);
    }
    close_fd(&gp->to_child);   /* EOF on stdin also makes gnuplot exit */
    if (gp->pid > 0) {
        int st;
        pid_t r = 0;
        /* Give it 2 s to finish a PNG, then ask, then insist. */
        for (int i = 0; i < 200 && (r = waitpid(gp->pid, &st, WNOHANG)) == 0; i++)
            sleep_ms(10);
        if (r == 0) {
            kill(gp->pid, SIGTERM);
            for (int i = 0; i < 50 && (r = waitpid(gp->pid, &st, WNOHANG)) == 0; i++)
                sleep_ms(10);
        }
        if (r == 0) {
            kill(gp->pid, SIGKILL);
            while (waitpid(gp->pid, &st, 0) < 0 && errno == EINTR)
                ;
        }
        gp->pid = 0;
    }
    close_fd(&gp->from_child);
    free(gp->out);
    free(gp);
}

void adh_gnuplot_log_last_line(int log_fd, char *buf, size_t len)
{
    if (len)
        buf[0] = '\0';
    struct stat st;
    if (log_fd < 0 || fstat(log_fd, &st) != 0)
        return;
    char tail[4096];
    off_t from = st.st_size > (off_t)sizeof tail - 1 ? st.st_size - (off_t)sizeof tail + 1 : 0;
    ssize_t got = pread(log_fd, tail, sizeof tail - 1, from);
    size_t n = got > 0 ? (size_t)got : 0;
    tail[n] = '\0';
    /* gnuplot follows an error with a line holding only a caret under the
     * offending column; the message is the line before, so skip those. */
    char *end = tail + n;
    while (end > tail) {
        char *start = end;
        while (start > tail && start[-1] != '\n')
            start--;
        char *a = start, *b = end;
        while (a < b && (*a == ' ' || *a == '\t' || *a == '^' || *a == '\r' || *a == '\n'))
            a++;
        while (b > a && (b[-1] == ' ' || b[-1] == '\t' || b[-1] == '\r' || b[-1] == '\n'))
            b--;
        if (b > a) {
            snprintf(buf, len, "%.*s", (int)(b - a), a);
            return;
        }
        end = start > tail ? start - 1 : tail;
    }
}
