/* Stopping a command: SIGINT, SIGTERM and --max-time.
 *
 * The handler only records the signal in cli_stop (a volatile
 * sig_atomic_t: a handler has nowhere else to write), which the library
 * polls through the cancel flag of its options (base/cancel.h: within
 * milliseconds, inside a tile or a line); the command then cleans up and
 * ends by the same signal (cli_die_stopped). --max-time arms a one-shot
 * ITIMER_REAL, whose SIGALRM goes through the same flag, so a time limit
 * stops a command exactly as an interrupt does, and ends it with an error
 * message and exit status 1 instead.
 *
 * Loading a model cannot be interrupted from inside (the parser and the
 * builder take no cancel flag), but while it runs nothing is on disk that
 * would need cleaning up: the caller marks that stretch with
 * cli_loading(1) and cli_loading(0), and a signal inside it ends the
 * process from the handler at once, with only async-signal-safe calls
 * (write, _exit, raise). A .scad conversion is not such a stretch: its
 * OpenSCAD process is killed and its temporary files removed (scad.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "cli/cli.h"

volatile sig_atomic_t cli_stop;
static volatile sig_atomic_t loading; /* in a stretch that cannot be stopped */
static char limit_message[128];       /* written by the handler */
static volatile sig_atomic_t limit_length;
static double limit_seconds;

static void say(const char *text, size_t length)
{
    while (length > 0) {
        ssize_t n = write(STDERR_FILENO, text, length);
        if (n <= 0)
            return;
        text += n;
        length -= (size_t)n;
    }
}

static void on_signal(int sig)
{
    if (cli_stop && sig != SIGALRM) {
        signal(sig, SIG_DFL); /* a second interrupt: stop now */
        raise(sig);
        return;
    }
    if (!cli_stop)
        cli_stop = sig;
    if (!loading)
        return;
    if (sig == SIGALRM) {
        say(limit_message, (size_t)limit_length);
        _exit(CLI_EXIT_FAILED);
    }
    static const char interrupted[] = "spancast: interrupted\n";
    say(interrupted, sizeof interrupted - 1);
    signal(sig, SIG_DFL);
    raise(sig);
}

void cli_catch_interrupts(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    const int signals[3] = {SIGINT, SIGTERM, SIGALRM};
    for (int k = 0; k < 3; k++) {
        struct sigaction old;
        /* A signal the parent set to be ignored (a shell's background job
         * ignores SIGINT) stays ignored. */
        if (signals[k] != SIGALRM && sigaction(signals[k], NULL, &old) == 0 &&
            old.sa_handler == SIG_IGN)
            continue;
        sigaction(signals[k], &sa, NULL);
    }
}

int cli_parse_max_time(const char *value)
{
    double seconds;
    if (!cli_parse_number(value, &seconds) || !(seconds > 0 && seconds <= 1e7))
        return cli_usage_error("--max-time expects seconds above 0 (at most 1e7)");
    limit_seconds = seconds;
    return 0;
}

void cli_start_clock(void)
{
    if (!(limit_seconds > 0))
        return;
    int n = snprintf(limit_message, sizeof limit_message,
                     "spancast: error: time limit of %g s exceeded (--max-time)\n",
                     limit_seconds);
    limit_length = n > 0 && (size_t)n < sizeof limit_message ? n : 0;
    struct itimerval timer;
    memset(&timer, 0, sizeof timer);
    double whole = floor(limit_seconds);
    timer.it_value.tv_sec = (time_t)whole;
    timer.it_value.tv_usec = (suseconds_t)((limit_seconds - whole) * 1e6);
    if (timer.it_value.tv_sec == 0 && timer.it_value.tv_usec == 0)
        timer.it_value.tv_usec = 1;
    setitimer(ITIMER_REAL, &timer, NULL);
}

void cli_stop_clock(void)
{
    struct itimerval timer;
    memset(&timer, 0, sizeof timer);
    setitimer(ITIMER_REAL, &timer, NULL);
}

void cli_loading(int on)
{
    loading = on;
    if (on && cli_stop)
        on_signal(cli_stop); /* a signal that came just before */
}

volatile sig_atomic_t *cli_loading_flag(void)
{
    return &loading;
}

int cli_die_stopped(void)
{
    int sig = cli_stop;
    if (sig == SIGALRM) {
        fputs(limit_message, stderr);
        return CLI_EXIT_FAILED;
    }
    fputs("spancast: interrupted\n", stderr);
    fflush(stderr);
    signal(sig, SIG_DFL);
    raise(sig);
    return 128 + sig; /* not reached */
}
