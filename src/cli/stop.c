/* Stopping a command: SIGINT, SIGTERM, --max-time and --max-memory.
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
 *
 * --max-memory=SIZE sets the process's RLIMIT_DATA before the command
 * starts (base/mem.h): the kernel then refuses every allocation past it,
 * which the library turns into a clean error naming the limit, and the
 * library compares its large allocations with what the limit leaves
 * before it makes them. RLIMIT_DATA, not RLIMIT_AS: the address space
 * also counts what is reserved and never used (the shared libraries'
 * mappings, malloc's per-thread arenas of 64 MiB each), so a limit on it
 * would measure the machine's thread count rather than the model. The
 * option is taken out of argv in main, so that it applies to every
 * command alike; child processes (OpenSCAD, the ranks of a batch) inherit
 * the limit.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <unistd.h>

#include "base/mem.h"
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

/* SIZE: a number of bytes, or of KiB, MiB, GiB or TiB with the suffix K,
 * M, G or T (upper or lower case, "iB" or "B" after it allowed): 512M,
 * 1.5G. 0 when it is not one. */
static int parse_size(const char *value, double *bytes)
{
    char *end;
    double v = strtod(value, &end);
    if (end == value || !(v > 0) || !isfinite(v))
        return 0;
    static const char units[] = "KMGT";
    const char *unit = *end ? strchr(units, *end & ~0x20) : NULL;
    if (*end && (!unit || !*unit))
        return 0;
    if (unit) {
        v *= pow(1024, (double)(unit - units + 1));
        end++;
        if (!strcmp(end, "iB") || !strcmp(end, "B"))
            end += strlen(end);
    }
    if (*end)
        return 0;
    *bytes = v;
    return 1;
}

/* Each thread of a render or a measure but the first needs its stack
 * (RLIMIT_STACK, 8 MiB by default) inside the limit, besides the process
 * as it starts and 16 MiB to work in: a limit smaller than that would
 * fail in the OpenMP runtime, which ends the process without the
 * library's error ("libgomp: Thread creation failed"), so it is refused
 * up front. With 2 threads a small render needs 16 MiB in all. */
static uint64_t least_memory(void)
{
    struct rlimit stack;
    uint64_t per_thread = 8u << 20;
    if (getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY &&
        stack.rlim_cur > 0)
        per_thread = (uint64_t)stack.rlim_cur;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    uint64_t threads = cores > 0 ? (uint64_t)cores : 1;
    return mem_in_use() + threads * per_thread + (16u << 20);
}

static int apply_max_memory(const char *value)
{
    double bytes;
    if (!parse_size(value, &bytes) || bytes >= 0x1p62)
        return cli_usage_error(
            "--max-memory expects a size such as 512M or 2G (got '%s')", value);
    uint64_t least = least_memory();
    char text[32];
    if (bytes < (double)least)
        return cli_usage_error("--max-memory=%s is below the %s that spancast needs to "
                               "start its threads on this machine",
                               value, mem_format(least, text, sizeof text));
    struct rlimit limit;
    if (getrlimit(RLIMIT_DATA, &limit) != 0)
        return cli_usage_error("--max-memory: cannot read the memory limit");
    rlim_t want = (rlim_t)bytes;
    if (limit.rlim_max != RLIM_INFINITY && want > limit.rlim_max)
        want = limit.rlim_max; /* a lower hard limit stays the limit */
    limit.rlim_cur = want;
    if (setrlimit(RLIMIT_DATA, &limit) != 0)
        return cli_usage_error("--max-memory: cannot set the memory limit");
    return 0;
}

int cli_take_max_memory(int *argc, char **argv)
{
    static const char name[] = "--max-memory";
    const size_t length = sizeof name - 1;
    for (int k = 1; k < *argc && strcmp(argv[k], "--"); k++) {
        if (strncmp(argv[k], name, length) != 0 ||
            (argv[k][length] != '=' && argv[k][length] != '\0'))
            continue;
        int used = 1;
        const char *value = argv[k] + length + 1;
        if (argv[k][length] == '\0') {
            if (k + 1 >= *argc)
                return cli_usage_error("--max-memory expects a size such as 512M or 2G");
            value = argv[k + 1];
            used = 2;
        }
        int st = apply_max_memory(value);
        if (st)
            return st;
        for (int j = k; j + used <= *argc; j++)
            argv[j] = argv[j + used]; /* argv[argc] is NULL and moves too */
        *argc -= used;
        k--;
    }
    return 0;
}
