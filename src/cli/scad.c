/* `spancast render model.scad`: OpenSCAD source through OpenSCAD itself.
 *
 * spancast reads OpenSCAD's flattened CSG, not its language; a .scad file is
 * first converted with `openscad -o TMP/NAME.csg /abs/model.scad`, both
 * paths absolute (OpenSCAD writes a relative -o path next to its input), in
 * a private directory made by mkdtemp under $TMPDIR (or /tmp). OpenSCAD's
 * own output goes to a log in that directory; when it fails, its last
 * non-empty line is the message. The .csg is loaded under the name
 * DIR/NAME.csg, DIR being the source's directory: OpenSCAD writes import
 * paths as the source gave them, relative to the source, and spancast
 * resolves them relative to the loaded file's name. Error positions in the
 * converted text therefore read DIR/NAME.csg, the file `openscad -o
 * NAME.csg` would have written. Every temporary file is removed before
 * returning, and before the text is loaded. OpenSCAD 2021.01 writes
 * numbers with 6 significant digits.
 *
 * Stopping: the wait for OpenSCAD polls the caller's stop flag every
 * 10 ms (a blocking waitpid could miss a signal that lands just before
 * it); when it is set, OpenSCAD gets SIGTERM, and SIGKILL a second later
 * if it is still running, so an interrupt or a time limit never waits for
 * a conversion.
 *
 * For a watcher (scad_load_files), OpenSCAD also writes a make-style
 * dependency file (-d): "TARGET: FILE FILE ...", continued over lines by a
 * backslash at the end of a line, a space inside a name written as a
 * backslash and a space. Its names are the files the conversion read.
 */
#define _XOPEN_SOURCE 700 /* realpath, mkdtemp */

#include "cli/scad.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <spawn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "formats/file.h"

extern char **environ;

int scad_is_source(const char *path)
{
    size_t n = strlen(path);
    if (n < 5)
        return 0;
    const char *e = path + n - 5;
    return e[0] == '.' && (e[1] | 32) == 's' && (e[2] | 32) == 'c' &&
           (e[3] | 32) == 'a' && (e[4] | 32) == 'd';
}

static sc_status fail(sc_error *error, sc_status status, const char *format,
                      const char *a, const char *b)
{
    memset(error, 0, sizeof *error);
    error->status = status;
    snprintf(error->message, sizeof error->message, format, a, b);
    return status;
}

/* The last non-empty line of the file at path, into buf. */
static void last_line(const char *path, char *buf, size_t size)
{
    buf[0] = 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        size_t n = strlen(line);
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = 0;
        if (n > 0)
            snprintf(buf, size, "%s", line);
    }
    fclose(f);
}

/* Calls depend for each prerequisite in the make-style dependency file at
 * path: the words after the first unescaped ':' (a backslash before a space
 * makes the space part of a name, a backslash before a newline continues the
 * line). */
static void read_depends(const char *path, void (*depend)(void *user, const char *file),
                         void *user)
{
    size_t size = 0;
    const char *why;
    char *text = file_read(path, 1 << 24, &size, &why);
    if (!text)
        return;
    char *colon = NULL;
    for (size_t k = 0; k < size && !colon; k++) {
        if (text[k] == '\\')
            k++;
        else if (text[k] == ':' && k + 1 < size &&
                 (text[k + 1] == ' ' || text[k + 1] == '\n'))
            colon = text + k;
    }
    char word[PATH_MAX];
    size_t len = 0;
    for (const char *p = colon ? colon + 1 : text + size; p <= text + size; p++) {
        int end = p == text + size || *p == ' ' || *p == '\t' || *p == '\n' || *p == '\r';
        if (!end && *p == '\\' && p + 1 < text + size && p[1] == ' ') {
            p++; /* an escaped space belongs to the name */
        } else if (!end && *p == '\\' && p + 1 < text + size &&
                   (p[1] == '\n' || p[1] == '\r')) {
            continue; /* a continuation line */
        } else if (end) {
            if (len > 0 && len < sizeof word) {
                word[len] = '\0';
                depend(user, word);
            }
            len = 0;
            continue;
        }
        if (len < sizeof word)
            word[len] = *p;
        len++;
    }
    free(text);
}

sc_status scad_load(const char *path, const sc_load_options *options, sc_scene **scene,
                    sc_error *error)
{
    return scad_load_files(path, options, scene, error, NULL, NULL, NULL);
}

static void pause_ms(long ms)
{
    struct timespec ts = {0, ms * 1000000L};
    nanosleep(&ts, NULL);
}

/* Waits for the child pid into *status; when *stop is set first, kills
 * it (SIGTERM, then SIGKILL after a second), reaps it and returns 0. */
static int wait_child(pid_t pid, int *status, const volatile sig_atomic_t *stop)
{
    for (;;) {
        pid_t got = waitpid(pid, status, stop ? WNOHANG : 0);
        if (got == pid)
            return 1;
        if (got < 0 && errno != EINTR)
            return 1; /* no such child: nothing to wait for */
        if (stop && *stop)
            break;
        if (stop)
            pause_ms(10);
    }
    kill(pid, SIGTERM);
    for (int k = 0; k < 100; k++) {
        if (waitpid(pid, status, WNOHANG) == pid)
            return 0;
        pause_ms(10);
    }
    kill(pid, SIGKILL);
    while (waitpid(pid, status, 0) < 0 && errno == EINTR)
        ;
    return 0;
}

static sc_status convert(const char *path, const double *time, char **text, size_t *size,
                         char *name, size_t name_size, sc_error *error,
                         void (*depend)(void *user, const char *file), void *user,
                         const scad_stop *stop);

/* The conversion at time (or none), then the load of its text under the
 * name beside the source, with *stop->loading set meanwhile. */
static sc_status convert_and_load(const char *path, const double *time,
                                  const sc_load_options *options, sc_scene **scene,
                                  sc_error *error,
                                  void (*depend)(void *user, const char *file),
                                  void *user, const scad_stop *stop)
{
    *scene = NULL;
    char *text = NULL, name[PATH_MAX + 16];
    size_t size = 0;
    sc_status st =
        convert(path, time, &text, &size, name, sizeof name, error, depend, user, stop);
    if (st == SC_OK) {
        if (stop && stop->loading)
            *stop->loading = 1;
        st = sc_scene_load_string(name, text, size, options, scene, error);
        if (stop && stop->loading)
            *stop->loading = 0;
    }
    free(text);
    return st;
}

sc_status scad_load_files(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user,
                          const scad_stop *stop)
{
    return convert_and_load(path, NULL, options, scene, error, depend, user, stop);
}

/* The conversion, with OpenSCAD's $t set to *time when time is not NULL
 * (a top-level assignment that -D appends to the source, which is how a
 * file's own $t = ... would set it). */
static sc_status convert(const char *path, const double *time, char **text, size_t *size,
                         char *name, size_t name_size, sc_error *error,
                         void (*depend)(void *user, const char *file), void *user,
                         const scad_stop *stop)
{
    *text = NULL;
    *size = 0;
    name[0] = '\0';
    char source[PATH_MAX];
    if (!realpath(path, source))
        return fail(error, SC_ERR_IO, "cannot open '%s': %s", path, strerror(errno));
    const char *tmp = getenv("TMPDIR");
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s/spancast-XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(dir))
        return fail(error, SC_ERR_IO, "cannot make a temporary directory in '%s': %s",
                    tmp && tmp[0] ? tmp : "/tmp", strerror(errno));
    const char *base = strrchr(source, '/') + 1; /* realpath is absolute */
    char csg[PATH_MAX + 16], log[PATH_MAX + 16], deps[PATH_MAX + 16];
    snprintf(csg, sizeof csg, "%s/%.*s.csg", dir, (int)(strlen(base) - 5), base);
    snprintf(log, sizeof log, "%s/openscad.log", dir);
    snprintf(deps, sizeof deps, "%s/openscad.d", dir);
    snprintf(name, name_size, "%.*s.csg", (int)(strlen(source) - 5), source);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log, O_WRONLY | O_CREAT | O_TRUNC,
                                     0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    char define[64];
    char *argv[9] = {"openscad", "-o", csg};
    int argc = 3;
    if (time) {
        snprintf(define, sizeof define, "$t=%.17g", *time);
        argv[argc++] = "-D";
        argv[argc++] = define;
    }
    if (depend) {
        argv[argc++] = "-d";
        argv[argc++] = deps;
    }
    argv[argc++] = source;
    argv[argc] = NULL;
    pid_t pid;
    int spawned = posix_spawnp(&pid, "openscad", &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    sc_status st = SC_OK;
    if (spawned != 0) {
        st = fail(error, SC_ERR_IO,
                  "cannot convert '%s': OpenSCAD is not installed ('openscad' %s)", path,
                  spawned == ENOENT ? "was not found in PATH" : strerror(spawned));
    } else {
        int status = 0;
        if (!wait_child(pid, &status, stop ? stop->stop : NULL)) {
            memset(error, 0, sizeof *error);
            error->status = st = SC_ERR_CANCELLED;
            snprintf(error->message, sizeof error->message, "interrupted");
        } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            char last[400];
            last_line(log, last, sizeof last);
            st = fail(error, SC_ERR_IO, "OpenSCAD could not convert '%s': %s", path,
                      last[0] ? last : "it failed without a message");
        }
    }
    if (st == SC_OK && depend)
        read_depends(deps, depend, user);
    if (st == SC_OK) {
        const char *why;
        *text = file_read(csg, SIZE_MAX / 2, size, &why);
        if (!*text)
            st = fail(error, SC_ERR_IO, "OpenSCAD wrote no CSG for '%s'%s", path, "");
    }
    unlink(csg);
    unlink(log);
    unlink(deps);
    rmdir(dir);
    return st;
}

sc_status scad_convert(const char *path, char **text, size_t *size, char *name,
                       size_t name_size, sc_error *error,
                       void (*depend)(void *user, const char *file), void *user,
                       const scad_stop *stop)
{
    return convert(path, NULL, text, size, name, name_size, error, depend, user, stop);
}

sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error, const scad_stop *stop)
{
    return convert_and_load(path, &t, options, scene, error, NULL, NULL, stop);
}
