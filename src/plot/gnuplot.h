/* One gnuplot child process driven over a pipe:
 * fork/exec of `gnuplot -d` with no shell, its stderr in a log file (never on
 * the terminal, which may be a curses screen), and a sync handshake after
 * every batch of commands that is both flow control and error detection. */
#ifndef ADH_PLOT_GNUPLOT_H
#define ADH_PLOT_GNUPLOT_H

#include <signal.h>
#include <stddef.h>

typedef struct adh_gnuplot adh_gnuplot;

/* The program run: $ADHERE_GNUPLOT if set (tests use it to inject a broken
 * gnuplot), else "gnuplot" looked up on PATH. */
const char *adh_gnuplot_program(void);

/* Starts gnuplot with its stderr on log_fd (the caller's, opened for
 * reading and appending; logname names it in messages). cancel (may be
 * NULL) is the caller's interrupt flag: once it is raised a wait for
 * gnuplot stops within 0.1 s and gnuplot is killed. NULL when it cannot be
 * started (not on PATH, no fork): msg says why. */
adh_gnuplot *adh_gnuplot_open(int log_fd, const char *logname, const volatile sig_atomic_t *cancel, char *msg,
                              size_t msglen);

/* Queues one command line (a newline is added). Nothing is checked until
 * the next sync; a write failure is remembered and reported there. */
void adh_gnuplot_cmd(adh_gnuplot *gp, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Sends the queued commands and a sync line, then waits (at most timeout_s
 * seconds) for gnuplot to echo it back, wherever in its output it comes
 * (after an image gnuplot could not put in a file, say). Returns 0 when
 * gnuplot reported no error since the previous sync; -1 with msg set when
 * it reported one, died, timed out or the cancel flag was raised
 * (gnuplot's own message is quoted from its log when it has one).
 * gnuplot keeps running after a reported error; after a death or timeout
 * every later call fails at once. */
int adh_gnuplot_sync(adh_gnuplot *gp, double timeout_s, char *msg, size_t msglen);

/* Whether the process is still usable (not dead, not timed out). */
int adh_gnuplot_alive(const adh_gnuplot *gp);

/* Asks gnuplot to quit, waits briefly, then terminates and reaps it.
 * Safe with NULL. */
void adh_gnuplot_close(adh_gnuplot *gp);

/* The last non-empty line of the log (a descriptor open for reading),
 * stripped of gnuplot's caret markers and surrounding blanks; "" when there
 * is none. */
void adh_gnuplot_log_last_line(int log_fd, char *buf, size_t len);

#endif
