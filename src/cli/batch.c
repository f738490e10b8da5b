/* `spancast batch JOBS [--json] [--strict]`: many spancast commands from one file, as a
 * model library is checked in CI.
 *
 * JOBS holds one job a line: the arguments of one spancast command without
 * the program's name (`render part.csg -o part.png --imgsize=400,300`).
 * Words are split as the shell splits them: blanks separate words, '...'
 * keeps everything literally, "..." keeps everything but \" \\ \$ and \`,
 * which stand for the character after the backslash, and a backslash
 * outside quotes escapes the next character; '#' at the start of a word
 * starts a comment to the end of the line. There are no variables, globs
 * or continuation lines. Each job runs in the jobs file's folder, so
 * relative paths are relative to it.
 *
 * Every job runs once, as a process of its own (this program, by its own
 * path, with the MPI variables of the environment left out, so that a job
 * is an ordinary run even when the batch runs under mpirun), its output
 * (stdout and stderr) captured; a job that fails does not stop the
 * others. Under mpirun the jobs are the pieces of dist.h's queue, spread
 * over the ranks, and rank 0 prints the summary. At the end: a table of
 * every job (its line, exit status, time, command, for a failure the last
 * line it printed, its message, and for every job the whole of what it
 * printed, stdout and stderr as they came, bounded by BATCH_OUTPUT: the
 * first BATCH_OUTPUT_HEAD bytes and the last ones, with what was left out
 * counted between), or with --json the same as JSON. What jobs that
 * succeeded printed (a measure's report, a query's answers) is kept up to
 * BATCH_KEPT bytes in all; a failed job's always.
 * Exit status: 0 when every job succeeded, 1 when one failed or the jobs
 * file cannot be read, 2 for a bad command line or a malformed jobs file
 * (file:line:col: error: ...).
 */
#define _GNU_SOURCE /* posix_spawn_file_actions_addchdir_np */

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <spawn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/scad.h"
#include "cli/dist.h"
#include "formats/file.h"

extern char **environ;

#define BATCH_MAX_FILE ((size_t)64 << 20) /* bytes of a jobs file */
#define BATCH_MAX_JOBS 1000000
#define BATCH_MESSAGE 512
#define BATCH_OUTPUT ((size_t)16 << 10)     /* bytes of a failed job's output kept */
#define BATCH_OUTPUT_HEAD ((size_t)4 << 10) /* of them, from its beginning */
#define BATCH_KEPT ((size_t)64 << 20)       /* of succeeded jobs' output, in all */

typedef struct batch_job {
    int line;
    int argc;
    char **argv; /* argc words and a NULL */
} batch_job;

/* What became of one job; travels between ranks as it is. */
typedef struct batch_result {
    int32_t exit_status;         /* the job's exit status, or 128 + its signal */
    int32_t signal;              /* the signal that ended it, or 0 */
    double seconds;              /* wall time */
    char message[BATCH_MESSAGE]; /* the last line it printed */
    /* the job's output (NUL-terminated, malloc'd), or NULL; travels after
     * the struct (pack_result) */
    char *output;
    int32_t dropped; /* rank 0: output left out past BATCH_KEPT */
} batch_result;

typedef struct batch {
    const char *path;
    char folder[PATH_MAX];
    char program[PATH_MAX];
    batch_job *jobs;
    int count;
    batch_result *results; /* rank 0: one per job */
    char **env;            /* environ without the MPI variables */
    int strict;            /* --strict: passed on to every job but bench */
    size_t kept;           /* rank 0: bytes of succeeded jobs' output kept */
} batch;

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void free_jobs(batch *b)
{
    for (int k = 0; k < b->count; k++) {
        for (int w = 0; w < b->jobs[k].argc; w++)
            free(b->jobs[k].argv[w]);
        free(b->jobs[k].argv);
    }
    free(b->jobs);
    for (int k = 0; b->results && k < b->count; k++)
        free(b->results[k].output);
    free(b->results);
    free(b->env);
}

/* Prints a jobs-file error at line:col; returns CLI_EXIT_USAGE. */
static int syntax_error(const char *path, int line, int col, const char *what)
{
    fprintf(stderr, "%s:%d:%d: error: %s\n", path, line, col, what);
    return CLI_EXIT_USAGE;
}

/* Splits the line [p, end) of the jobs file into words, appended to job
 * (argv malloc'd). Returns 0, or an exit status after printing the
 * error. */
static int split_line(const char *path, int line, const char *p, const char *end,
                      batch_job *job)
{
    const char *start = p;
    size_t cap = 0;
    for (;;) {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\r'))
            p++;
        if (p == end || *p == '#')
            return 0;
        char *word = malloc((size_t)(end - p) + 1);
        if (!word) {
            fprintf(stderr, "spancast: error: out of memory\n");
            return CLI_EXIT_FAILED;
        }
        size_t n = 0;
        while (p < end && *p != ' ' && *p != '\t' && *p != '\r') {
            if (*p == '\'' || *p == '"') {
                char quote = *p;
                int col = (int)(p - start) + 1;
                p++;
                while (p < end && *p != quote) {
                    if (quote == '"' && *p == '\\' && p + 1 < end &&
                        strchr("\"\\$`", p[1]))
                        p++;
                    word[n++] = *p++;
                }
                if (p == end) {
                    free(word);
                    return syntax_error(path, line, col,
                                        quote == '"' ? "unterminated double quote"
                                                     : "unterminated single quote");
                }
                p++;
            } else if (*p == '\\') {
                if (p + 1 == end) {
                    free(word);
                    return syntax_error(path, line, (int)(p - start) + 1,
                                        "backslash at the end of the line");
                }
                word[n++] = p[1];
                p += 2;
            } else {
                word[n++] = *p++;
            }
        }
        word[n] = '\0';
        if ((size_t)job->argc + 2 > cap) {
            cap = cap ? 2 * cap : 8;
            char **grown = realloc(job->argv, cap * sizeof *grown);
            if (!grown) {
                free(word);
                fprintf(stderr, "spancast: error: out of memory\n");
                return CLI_EXIT_FAILED;
            }
            job->argv = grown;
        }
        job->argv[job->argc++] = word;
        job->argv[job->argc] = NULL;
    }
}

/* Reads and splits the jobs file. Returns 0 or an exit status. */
static int read_jobs(batch *b)
{
    size_t size = 0;
    const char *why = NULL;
    char *text = file_read(b->path, BATCH_MAX_FILE, &size, &why);
    if (!text) {
        fprintf(stderr, "spancast: error: cannot read '%s': %s\n", b->path, why);
        return CLI_EXIT_FAILED;
    }
    int cap = 0, line = 0, status = 0;
    for (const char *p = text; p < text + size && !status;) {
        const char *end = memchr(p, '\n', (size_t)(text + size - p));
        if (!end)
            end = text + size;
        line++;
        batch_job job = {line, 0, NULL};
        status = split_line(b->path, line, p, end, &job);
        if (!status && job.argc > 0) {
            if (!strcmp(job.argv[0], "batch") || !strcmp(job.argv[0], "view"))
                status = syntax_error(b->path, line, 1,
                                      !strcmp(job.argv[0], "batch")
                                          ? "a job cannot be a batch"
                                          : "a job cannot open a window ('view')");
            else if (b->count == BATCH_MAX_JOBS)
                status =
                    syntax_error(b->path, line, 1, "too many jobs (limit is 1000000)");
        }
        if (!status && job.argc > 0 && b->count == cap) {
            cap = cap ? 2 * cap : 64;
            batch_job *grown = realloc(b->jobs, (size_t)cap * sizeof *grown);
            if (!grown) {
                fprintf(stderr, "spancast: error: out of memory\n");
                status = CLI_EXIT_FAILED;
            } else {
                b->jobs = grown;
            }
        }
        if (!status && job.argc > 0) {
            b->jobs[b->count++] = job;
        } else {
            for (int w = 0; w < job.argc; w++)
                free(job.argv[w]);
            free(job.argv);
        }
        p = end + 1;
    }
    free(text);
    return status;
}

/* The last non-empty line of the file open at fd, into out. */
static void last_line(int fd, char *out, size_t size)
{
    out[0] = '\0';
    off_t length = lseek(fd, 0, SEEK_END);
    if (length <= 0)
        return;
    char tail[4096];
    off_t from = length > (off_t)sizeof tail ? length - (off_t)sizeof tail : 0;
    ssize_t got = pread(fd, tail, (size_t)(length - from), from);
    if (got <= 0)
        return;
    size_t n = (size_t)got;
    while (n > 0 && (tail[n - 1] == '\n' || tail[n - 1] == '\r' || tail[n - 1] == ' '))
        n--;
    size_t begin = n;
    while (begin > 0 && tail[begin - 1] != '\n' && tail[begin - 1] != '\r')
        begin--;
    snprintf(out, size, "%.*s", (int)(n - begin), tail + begin);
}

/* What the file open at fd holds, at most BATCH_OUTPUT bytes of it: its
 * beginning and its end, with a line saying how much was left out between
 * (malloc'd, NUL-terminated; NULL when empty or out of memory). */
static char *bounded_output(int fd)
{
    off_t length = lseek(fd, 0, SEEK_END);
    if (length <= 0)
        return NULL;
    size_t total = (size_t)length;
    size_t head = total > BATCH_OUTPUT ? BATCH_OUTPUT_HEAD : total;
    size_t tail = total > BATCH_OUTPUT ? BATCH_OUTPUT - BATCH_OUTPUT_HEAD : 0;
    char gap[96] = "";
    if (tail)
        snprintf(gap, sizeof gap, "\n[... %zu bytes left out ...]\n",
                 total - head - tail);
    size_t gap_size = strlen(gap);
    char *out = malloc(head + gap_size + tail + 1);
    if (!out)
        return NULL;
    ssize_t got = pread(fd, out, head, 0);
    size_t n = got > 0 ? (size_t)got : 0;
    if (tail) {
        memcpy(out + n, gap, gap_size);
        n += gap_size;
        got = pread(fd, out + n, tail, (off_t)(total - tail));
        n += got > 0 ? (size_t)got : 0;
    }
    out[n] = '\0';
    return out;
}

/* Runs job k as a process of its own. */
static sc_status run_job(void *user, int k, void **result, sc_error *error)
{
    const batch *b = user;
    const batch_job *job = &b->jobs[k];
    batch_result *r = calloc(1, sizeof *r);
    if (!r) {
        snprintf(error->message, sizeof error->message, "out of memory");
        error->status = SC_ERR_NOMEM;
        return SC_ERR_NOMEM;
    }
    /* The job's output, captured in an unnamed temporary file. */
    const char *tmp = getenv("TMPDIR");
    char log[PATH_MAX];
    snprintf(log, sizeof log, "%s/spancast-batch-XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    int fd = mkstemp(log);
    if (fd >= 0)
        unlink(log);
    /* The batch's own -D settings go to every job, after its command. */
    int defines = scad_define_count();
    char **argv = calloc((size_t)job->argc + 3 + 2 * (size_t)defines, sizeof *argv);
    double start = seconds_now();
    int spawned = ENOMEM;
    pid_t pid = 0;
    if (argv) {
        argv[0] = (char *)b->program;
        int n = 1;
        if (job->argc)
            argv[n++] = job->argv[0];
        for (int d = 0; d < defines; d++) {
            argv[n++] = "-D";
            argv[n++] = (char *)scad_define(d);
        }
        if (job->argc > 1) {
            memcpy(argv + n, job->argv + 1, (size_t)(job->argc - 1) * sizeof *argv);
            n += job->argc - 1;
        }
        if (b->strict && job->argc > 0 && strcmp(job->argv[0], "bench") != 0)
            argv[n] = (char *)"--strict";
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        if (fd >= 0) {
            posix_spawn_file_actions_adddup2(&actions, fd, 1);
            posix_spawn_file_actions_adddup2(&actions, fd, 2);
        }
        posix_spawn_file_actions_addchdir_np(&actions, b->folder);
        spawned = posix_spawn(&pid, b->program, &actions, NULL, argv, b->env);
        posix_spawn_file_actions_destroy(&actions);
    }
    if (spawned != 0) {
        r->exit_status = 127;
        snprintf(r->message, sizeof r->message,
                 "spancast: error: cannot run '%.300s': %s", b->program,
                 strerror(spawned));
    } else {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
        if (WIFSIGNALED(status)) {
            r->signal = WTERMSIG(status);
            r->exit_status = 128 + r->signal;
        } else {
            r->exit_status = WEXITSTATUS(status);
        }
        if (fd >= 0)
            last_line(fd, r->message, sizeof r->message);
        if (fd >= 0)
            r->output = bounded_output(fd);
        if (r->signal && !r->message[0])
            snprintf(r->message, sizeof r->message, "killed by signal %d (%s)", r->signal,
                     strsignal(r->signal));
    }
    r->seconds = seconds_now() - start;
    free(argv);
    if (fd >= 0)
        close(fd);
    *result = r;
    return SC_OK;
}

/* The struct (its output pointer meaningless), then the output's bytes. */
static void *pack_result(void *user, const void *result, size_t *size)
{
    (void)user;
    const batch_result *r = result;
    size_t extra = r->output ? strlen(r->output) : 0;
    char *bytes = malloc(sizeof *r + extra);
    if (bytes) {
        memcpy(bytes, r, sizeof *r);
        memcpy(bytes + sizeof *r, r->output ? r->output : "", extra);
    }
    *size = sizeof *r + extra;
    return bytes;
}

static void *unpack_result(void *user, const void *bytes, size_t size)
{
    (void)user;
    if (size < sizeof(batch_result) || size - sizeof(batch_result) > BATCH_OUTPUT + 96)
        return NULL;
    batch_result *r = malloc(sizeof *r);
    if (!r)
        return NULL;
    memcpy(r, bytes, sizeof *r);
    r->message[sizeof r->message - 1] = '\0';
    r->output = NULL;
    size_t extra = size - sizeof *r;
    if (extra) {
        r->output = malloc(extra + 1);
        if (!r->output) {
            free(r);
            return NULL;
        }
        memcpy(r->output, (const char *)bytes + sizeof *r, extra);
        r->output[extra] = '\0';
    }
    return r;
}

/* Takes the result's output (the result is released after); a succeeded
 * job's past BATCH_KEPT bytes of such output in all is left out. */
static sc_status deliver_result(void *user, int k, const void *result, sc_error *error)
{
    (void)error;
    batch *b = user;
    batch_result *r = &b->results[k];
    *r = *(const batch_result *)result;
    ((batch_result *)result)->output = NULL;
    r->dropped = 0;
    if (r->exit_status == 0 && r->output) {
        size_t n = strlen(r->output);
        if (n > BATCH_KEPT - b->kept) {
            free(r->output);
            r->output = NULL;
            r->dropped = 1;
        } else {
            b->kept += n;
        }
    }
    return SC_OK;
}

static void release_result(void *user, void *result)
{
    (void)user;
    if (result)
        free(((batch_result *)result)->output);
    free(result);
}

/* The job's words as one line, quoted for the shell where needed. */
static void print_command(FILE *out, const batch_job *job)
{
    for (int w = 0; w < job->argc; w++) {
        const char *word = job->argv[w];
        int plain = word[0] != '\0';
        for (const char *c = word; *c && plain; c++)
            plain = strchr(" \t'\"\\#$`*?[]{}()<>|&;~!", *c) == NULL;
        fputs(w ? " " : "", out);
        if (plain) {
            fputs(word, out);
            continue;
        }
        fputc('\'', out);
        for (const char *c = word; *c; c++)
            fputs(*c == '\'' ? "'\\''" : (char[2]){*c, 0}, out);
        fputc('\'', out);
    }
}

static void print_json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\')
            fprintf(out, "\\%c", *c);
        else if (*c == '\n')
            fputs("\\n", out);
        else if (*c < 0x20)
            fprintf(out, "\\u%04x", *c);
        else
            fputc(*c, out);
    }
    fputc('"', out);
}

/* A job's output under its line in the table, each line marked; for a
 * failed job only when it is more than the one line of its message. */
static void print_output(const char *output, int failed)
{
    if (!output)
        return;
    size_t n = strlen(output);
    while (n > 0 &&
           (output[n - 1] == '\n' || output[n - 1] == '\r' || output[n - 1] == ' '))
        n--;
    if (failed && !memchr(output, '\n', n))
        return; /* the message alone */
    for (size_t at = 0; at < n;) {
        const char *end = memchr(output + at, '\n', n - at);
        size_t len = end ? (size_t)(end - (output + at)) : n - at;
        printf("%-30s| %.*s\n", "", (int)len, output + at);
        at += len + 1;
    }
}

static void print_table(const batch *b, int failed, double seconds)
{
    printf("%-5s %-6s %-6s %9s  %s\n", "job", "line", "exit", "seconds", "command");
    for (int k = 0; k < b->count; k++) {
        const batch_result *r = &b->results[k];
        printf("%-5d %-6d %-6d %9.3f  ", k + 1, b->jobs[k].line, r->exit_status,
               r->seconds);
        print_command(stdout, &b->jobs[k]);
        putchar('\n');
        if (r->exit_status != 0)
            printf("%-30s%s\n", "", r->message[0] ? r->message : "(no message)");
        print_output(r->output, r->exit_status != 0);
        if (r->dropped)
            printf("%-30s| [... output left out: the batch keeps %zu MiB of it ...]\n",
                   "", BATCH_KEPT >> 20);
    }
    printf("%d job%s: %d succeeded, %d failed, in %.3f s\n", b->count,
           b->count == 1 ? "" : "s", b->count - failed, failed, seconds);
}

static void print_json(const batch *b, int failed, double seconds)
{
    printf("{\"jobs\": [");
    for (int k = 0; k < b->count; k++) {
        const batch_result *r = &b->results[k];
        printf("%s\n  {\"line\": %d, \"args\": [", k ? "," : "", b->jobs[k].line);
        for (int w = 0; w < b->jobs[k].argc; w++) {
            fputs(w ? ", " : "", stdout);
            print_json_string(stdout, b->jobs[k].argv[w]);
        }
        printf("], \"exit\": %d, \"ok\": %s, \"seconds\": %.6f, \"message\": ",
               r->exit_status, r->exit_status == 0 ? "true" : "false", r->seconds);
        print_json_string(stdout, r->exit_status ? r->message : "");
        fputs(", \"output\": ", stdout);
        print_json_string(stdout, r->output ? r->output : "");
        putchar('}');
    }
    printf("],\n \"succeeded\": %d, \"failed\": %d, \"seconds\": %.6f}\n",
           b->count - failed, failed, seconds);
}

/* environ without OMPI_* and PMIX_*: a job is not a rank. (malloc'd array
 * of pointers into environ) */
static char **job_environment(void)
{
    size_t n = 0;
    while (environ[n])
        n++;
    char **env = malloc((n + 1) * sizeof *env);
    if (!env)
        return NULL;
    size_t kept = 0;
    for (size_t k = 0; k < n; k++)
        if (strncmp(environ[k], "OMPI_", 5) && strncmp(environ[k], "PMIX_", 5))
            env[kept++] = environ[k];
    env[kept] = NULL;
    return env;
}

int cli_batch(int argc, char **argv)
{
    const char *path = NULL;
    int json = 0, strict = 0;
    for (int k = 2; k < argc; k++) {
        if (!strcmp(argv[k], "--json"))
            json = 1;
        else if (!strcmp(argv[k], "--strict"))
            strict = 1;
        else if (argv[k][0] == '-' && argv[k][1])
            return cli_usage_error("unknown option '%s'", argv[k]);
        else if (path)
            return cli_usage_error("unexpected argument '%s'", argv[k]);
        else
            path = argv[k];
    }
    if (!path)
        return cli_usage_error("missing jobs file");
    batch b;
    memset(&b, 0, sizeof b);
    b.path = path;
    b.strict = strict;
    int status = read_jobs(&b);
    char resolved[PATH_MAX];
    if (!status && !realpath(path, resolved)) {
        fprintf(stderr, "spancast: error: cannot read '%s': %s\n", path, strerror(errno));
        status = CLI_EXIT_FAILED;
    }
    ssize_t len =
        status ? -1 : readlink("/proc/self/exe", b.program, sizeof b.program - 1);
    if (!status && len <= 0) {
        fprintf(stderr, "spancast: error: cannot find this program: %s\n",
                strerror(errno));
        status = CLI_EXIT_FAILED;
    }
    status = dist_agree(status); /* under mpirun: stop together */
    if (status) {
        free_jobs(&b);
        return status;
    }
    b.program[len] = '\0';
    snprintf(b.folder, sizeof b.folder, "%s", resolved);
    *strrchr(b.folder, '/') = '\0'; /* realpath is absolute */
    if (!b.folder[0])
        strcpy(b.folder, "/");
    b.env = job_environment();
    b.results = calloc(b.count > 0 ? (size_t)b.count : 1, sizeof *b.results);
    if (dist_agree(!b.env || !b.results)) {
        fprintf(stderr, "spancast: error: out of memory\n");
        free_jobs(&b);
        return CLI_EXIT_FAILED;
    }
    dist_work work;
    memset(&work, 0, sizeof work);
    work.count = b.count;
    work.run = run_job;
    work.pack = pack_result;
    work.unpack = unpack_result;
    work.deliver = deliver_result;
    work.release = release_result;
    work.user = &b;
    work.window = b.count > 0 ? b.count : 1; /* results are small: no bound */
    double start = seconds_now();
    sc_error error;
    memset(&error, 0, sizeof error);
    sc_status st = dist_run(&work, &error);
    double seconds = seconds_now() - start;
    if (st != SC_OK) {
        cli_print_error(&error);
        free_jobs(&b);
        return CLI_EXIT_FAILED;
    }
    if (dist_rank() != 0) {
        free_jobs(&b);
        return 0;
    }
    int failed = 0;
    for (int k = 0; k < b.count; k++)
        failed += b.results[k].exit_status != 0;
    if (json)
        print_json(&b, failed, seconds);
    else
        print_table(&b, failed, seconds);
    free_jobs(&b);
    return failed ? CLI_EXIT_FAILED : 0;
}
