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
 * returning. OpenSCAD 2021.01 writes numbers with 6 significant digits.
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
    return scad_load_files(path, options, scene, error, NULL, NULL);
}

/* The conversion, with OpenSCAD's $t set to *time when time is not NULL
 * (a top-level assignment that -D appends to the source, which is how a
 * file's own $t = ... would set it). */
static sc_status convert(const char *path, const sc_load_options *options,
                         const double *time, sc_scene **scene, sc_error *error,
                         void (*depend)(void *user, const char *file), void *user)
{
    *scene = NULL;
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
    char csg[PATH_MAX + 16], log[PATH_MAX + 16], name[PATH_MAX + 16], deps[PATH_MAX + 16];
    snprintf(csg, sizeof csg, "%s/%.*s.csg", dir, (int)(strlen(base) - 5), base);
    snprintf(log, sizeof log, "%s/openscad.log", dir);
    snprintf(deps, sizeof deps, "%s/openscad.d", dir);
    snprintf(name, sizeof name, "%.*s.csg", (int)(strlen(source) - 5), source);

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
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            char last[400];
            last_line(log, last, sizeof last);
            st = fail(error, SC_ERR_IO, "OpenSCAD could not convert '%s': %s", path,
                      last[0] ? last : "it failed without a message");
        }
    }
    if (st == SC_OK && depend)
        read_depends(deps, depend, user);
    if (st == SC_OK) {
        size_t size = 0;
        const char *why;
        char *text = file_read(csg, SIZE_MAX / 2, &size, &why);
        if (!text)
            st = fail(error, SC_ERR_IO, "OpenSCAD wrote no CSG for '%s'%s", path, "");
        else
            st = sc_scene_load_string(name, text, size, options, scene, error);
        free(text);
    }
    unlink(csg);
    unlink(log);
    unlink(deps);
    rmdir(dir);
    return st;
}

sc_status scad_load_files(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user)
{
    return convert(path, options, NULL, scene, error, depend, user);
}

sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error)
{
    return convert(path, options, &t, scene, error, NULL, NULL);
}
