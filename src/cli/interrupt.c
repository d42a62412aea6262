#include "cli/interrupt.h"
#include "cli/exit.h"
#include "util/ready.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t received;
static struct sigaction old_int, old_term, old_hup;

static void on_signal(int sig)
{
    received = sig;
}

static int caught;   /* catch twice, release once: the first old handlers stay saved */

void cli_interrupt_catch(void)
{
    if (caught)
        return;
    caught = 1;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    sigaction(SIGHUP, &sa, &old_hup);
}

void cli_interrupt_release(void)
{
    if (!caught)
        return;
    caught = 0;
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    sigaction(SIGHUP, &old_hup, NULL);
}

int cli_interrupt_signal(void)
{
    return received;
}

const volatile sig_atomic_t *cli_interrupt_flag(void)
{
    return &received;
}

/* 128 + the signal's number, as a shell reports a process the signal
 * killed: a caller tells SIGTERM (143) from Ctrl-C (130). */
int cli_interrupt_exit(void)
{
    return received ? 128 + received : CLI_EXIT_INTERRUPTED;
}

int cli_interrupt_step(const adh_obs *row, const adh_run *run, void *ctx)
{
    (void)row, (void)run, (void)ctx;
    adh_ready_mark();   /* a step is done and signals are caught */
    return received != 0;
}
