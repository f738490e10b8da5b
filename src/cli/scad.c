/* `spancast render model.scad`: OpenSCAD source through OpenSCAD itself.
 *
 * spancast reads OpenSCAD's flattened CSG, not its language; a .scad file is
 * first converted with `openscad -o TMP/NAME.csg /abs/model.scad`, both
 * paths absolute (OpenSCAD writes a relative -o path next to its input), in
 * a private directory made by mkdtemp under $TMPDIR (or /tmp). OpenSCAD's
 * own output goes to a log in that directory; when it fails, its first
 * error is the message (openscad_log), with OpenSCAD's file and line,
 * never the temporary .csg's name. The .csg is loaded under the name
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
 * OpenSCAD 2021.01 writes it only when the conversion succeeds; when it
 * fails, the names come from the source itself (scan_uses): its include
 * <...>, use <...>, import("...") and surface("...") arguments, relative
 * to the file that names them, and those of the .scad files it includes
 * or uses in turn, so that fixing any of them, or creating a missing one,
 * is seen by a watcher.
 */
#define _XOPEN_SOURCE 700 /* realpath, mkdtemp */

#include "cli/scad.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <spawn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "api/mesh_model.h"
#include "cli/cli.h"
#include "formats/file.h"
#include "syntax/parse.h"

extern char **environ;

/* The -D NAME=VALUE settings of the command line, in order
 * (scad_take_defines): written once, before any command runs, as the
 * process's memory limit is, and only read after that. */
#define SCAD_MAX_DEFINES 256
static const char *defines[SCAD_MAX_DEFINES];
static int define_count;

int scad_is_source(const char *path)
{
    size_t n = strlen(path);
    if (n < 5)
        return 0;
    const char *e = path + n - 5;
    return e[0] == '.' && (e[1] | 32) == 's' && (e[2] | 32) == 'c' &&
           (e[3] | 32) == 'a' && (e[4] | 32) == 'd';
}

/* Whether path ends in suffix (a dot and lower-case letters), in any case. */
static int has_suffix(const char *path, const char *suffix)
{
    size_t n = strlen(path), k = strlen(suffix);
    if (n <= k)
        return 0;
    for (size_t i = 0; i < k; i++)
        if ((path[n - k + i] | (suffix[i] == '.' ? 0 : 32)) != suffix[i])
            return 0;
    return 1;
}

int scad_is_mesh(const char *path)
{
    return has_suffix(path, ".stl") || has_suffix(path, ".off") ||
           has_suffix(path, ".amf") || has_suffix(path, ".3mf");
}

int scad_take_defines(int *argc, char **argv)
{
    for (int k = 1; k < *argc && strcmp(argv[k], "--"); k++) {
        if (strncmp(argv[k], "-D", 2) != 0)
            continue;
        int used = 1;
        const char *value = argv[k] + 2;
        if (!*value) {
            if (k + 1 >= *argc)
                return cli_usage_error("-D expects NAME=VALUE, as OpenSCAD's -D");
            value = argv[k + 1];
            used = 2;
        }
        const char *equals = strchr(value, '=');
        if (!equals || equals == value)
            return cli_usage_error("-D expects NAME=VALUE, as OpenSCAD's -D (got '%s')",
                                   value);
        if (define_count == SCAD_MAX_DEFINES)
            return cli_usage_error("too many -D settings (limit is %d)",
                                   SCAD_MAX_DEFINES);
        defines[define_count++] = value;
        for (int j = k; j + used <= *argc; j++)
            argv[j] = argv[j + used]; /* argv[argc] is NULL and moves too */
        *argc -= used;
        k--;
    }
    return 0;
}

int scad_define_count(void)
{
    return define_count;
}

const char *scad_define(int index)
{
    return index >= 0 && index < define_count ? defines[index] : NULL;
}

static sc_status fail(sc_error *error, sc_status status, const char *format,
                      const char *a, const char *b)
{
    memset(error, 0, sizeof *error);
    error->status = status;
    snprintf(error->message, sizeof error->message, format, a, b);
    return status;
}

/* Reads "MESSAGE in file FILE, line N" (OpenSCAD 2021.01's position, the
 * last one on the line) into error as FILE:N:1 (OpenSCAD gives no column)
 * with MESSAGE; 0 when the text has no such position. */
static int openscad_position(const char *text, sc_error *error)
{
    const char *at = NULL;
    for (const char *p = strstr(text, " in file "); p; p = strstr(p + 1, " in file "))
        at = p;
    if (!at)
        return 0;
    const char *file = at + strlen(" in file ");
    const char *comma = NULL;
    for (const char *p = strstr(file, ", line "); p; p = strstr(p + 1, ", line "))
        comma = p;
    if (!comma || comma == file)
        return 0;
    char *end;
    long line = strtol(comma + strlen(", line "), &end, 10);
    if (line < 1 || line > INT_MAX || (*end && *end != ' '))
        return 0;
    snprintf(error->file, sizeof error->file, "%.*s", (int)(comma - file), file);
    error->line = (int)line;
    error->column = 1;
    snprintf(error->message, sizeof error->message, "%.*s", (int)(at - text), text);
    return 1;
}

/* A file's lines as OpenSCAD 2021.01 counts them. Its parser's errors
 * count LFs (flex's yylineno), as spancast's lexer and an editor do where
 * lines end in LF or CRLF; the positions of its other messages count each
 * CR and each LF, so that a CRLF is two lines there, put back on the
 * user's line by user_line. */
typedef struct line_map {
    long lf_newlines, lf_last_line; /* the parser's line breaks, last line */
    long newlines, last_line;       /* the other messages' (last line >= 1) */
    long *crlf; /* the other messages' line of each CR an LF follows, ascending (malloc'd)
                 */
    size_t crlf_count;
} line_map;

/* Where OpenSCAD's messages about the source (source: its real path;
 * path: as the user named it) point. OpenSCAD 2021.01 appends the -D
 * settings to the source's text, after a line of their own, one per line
 * ("\n\x03\n" then "NAME=VALUE;\n" each): the first is on line
 * newlines + 3, where newlines counts the source's line breaks (line_map
 * counts them as OpenSCAD does, CRLF as two). It does so
 * for each use'd library too, whose messages about the settings then
 * point past its end, once for each time it is evaluated. */
typedef struct source_lines {
    const char *source, *path;
    int source_counted; /* 0 until counted; -1 when the source cannot be read */
    line_map lines;     /* the source's */
    /* the settings' messages printed from the libraries, printed once */
    char said[8][SC_ERROR_MESSAGE_MAX];
    int said_count;
    /* the last other file counted (place_other): its name and lines, or
     * counted_ok 0 when it could not be read */
    char counted[SC_ERROR_FILE_MAX];
    line_map counted_lines;
    int counted_ok;
    /* the files the source reaches through include and use, as
     * scan_file names them (malloc'd; libraries_read once) */
    char **libraries;
    int library_count, libraries_read;
    char **reals; /* each library's real path, or NULL (malloc'd) */
} source_lines;

static void libraries_read(source_lines *at);

/* Counts the lines of the file at path into *map (its crlf the caller's to
 * free); 0 when it cannot be read. */
static int count_lines(const char *path, line_map *map)
{
    memset(map, 0, sizeof *map);
    size_t size;
    const char *why;
    char *text = file_read(path, SIZE_MAX / 2, &size, &why);
    if (!text)
        return 0;
    size_t pairs = 0;
    for (size_t i = 0; i + 1 < size; i++)
        pairs += text[i] == '\r' && text[i + 1] == '\n';
    map->crlf = pairs ? malloc(pairs * sizeof *map->crlf) : NULL;
    long n = 0, lf = 0;
    for (size_t i = 0; i < size; i++) {
        if (text[i] == '\r' && i + 1 < size && text[i + 1] == '\n' && map->crlf)
            map->crlf[map->crlf_count++] = n + 1;
        n += text[i] == '\n' || text[i] == '\r';
        lf += text[i] == '\n';
    }
    map->newlines = n;
    map->last_line = n + (size > 0 && text[size - 1] != '\n' && text[size - 1] != '\r');
    if (map->last_line < 1)
        map->last_line = 1;
    map->lf_newlines = lf;
    map->lf_last_line = lf + (size > 0 && text[size - 1] != '\n');
    if (map->lf_last_line < 1)
        map->lf_last_line = 1;
    free(text);
    return 1;
}

/* The user's line of the line `line` of one of OpenSCAD's messages but its
 * parser's, in the file map counts: one less for each CRLF before it.
 * Without the CRLFs' places (no memory for them), the line as given. */
static long user_line(const line_map *map, long line)
{
    size_t lo = 0, hi = map->crlf_count; /* the CRLFs on lines below `line` */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (map->crlf[mid] < line)
            lo = mid + 1;
        else
            hi = mid;
    }
    return line - (long)lo;
}

/* Puts a position past the end of a file whose text OpenSCAD gave the -D
 * settings (map: its lines as OpenSCAD counts them) on the setting there,
 * as a command-line error, or, on the lines OpenSCAD adds before them, at
 * the end of the file; then any position in the file on the user's line. */
static void place_past_end(const line_map *map, sc_error *error)
{
    int parser = !strncmp(error->message, "Parser error", 12);
    long newlines = parser ? map->lf_newlines : map->newlines;
    long last_line = parser ? map->lf_last_line : map->last_line;
    long k = error->line - (newlines + 3);
    if (k >= 0 && k < define_count) {
        char message[SC_ERROR_MESSAGE_MAX];
        snprintf(message, sizeof message, "%s", error->message);
        snprintf(error->message, sizeof error->message, "-D '%.100s': %.400s", defines[k],
                 message);
        snprintf(error->file, sizeof error->file, "<command-line>");
        error->line = 0;
        error->column = 0;
        return;
    }
    if (error->line > last_line) {
        size_t n = strlen(error->message);
        snprintf(error->message + n, sizeof error->message - n,
                 " at the end of the file");
        error->line = (int)last_line;
        error->column = 1;
    }
    if (!parser)
        error->line = (int)user_line(map, error->line);
}

/* Names another file (a use'd or include'd library) at OpenSCAD's position
 * as the working directory reaches it: OpenSCAD 2021.01 names a file
 * relative to the working directory in its parser's errors, but relative to
 * the source's folder in its other messages ("lib/x.scad" for the library
 * beside a source named "models/main.scad", which is "models/lib/x.scad"
 * from here). */
static void place_other(source_lines *at, sc_error *error)
{
    const char *slash = strrchr(at->path, '/');
    if (error->file[0] != '/' && strncmp(error->message, "Parser error", 12)) {
        char name[SC_ERROR_FILE_MAX];
        snprintf(name, sizeof name, "%s", error->file);
        if (slash && (size_t)snprintf(error->file, sizeof error->file, "%.*s/%s",
                                      (int)(slash - at->path), at->path,
                                      name) >= sizeof error->file)
            snprintf(error->file, sizeof error->file, "%s",
                     name); /* too long: as given */
        /* OpenSCAD names a use'd library's lines relative to the library's
         * own folder ("w2.scad" for lib/sub/w2.scad): where the name from
         * the source's folder is no file the source reaches, the one
         * library that ends in it */
        libraries_read(at);
        char real[PATH_MAX];
        int reached = 0, ending = 0, here = realpath(error->file, real) != NULL;
        const char *only = NULL;
        size_t n = strlen(name);
        for (int k = 0; k < at->library_count; k++) {
            const char *lib = at->libraries[k];
            size_t m = strlen(lib);
            reached |= here && at->reals[k] && !strcmp(real, at->reals[k]);
            if (m > n && lib[m - n - 1] == '/' && !strcmp(lib + m - n, name)) {
                ending++;
                only = lib;
            }
        }
        if (!reached && ending == 1)
            snprintf(error->file, sizeof error->file, "%s", only);
    }
    if (strcmp(at->counted, error->file) != 0) { /* a library's warnings come in a row */
        snprintf(at->counted, sizeof at->counted, "%s", error->file);
        free(at->counted_lines.crlf);
        at->counted_ok = count_lines(error->file, &at->counted_lines);
    }
    if (at->counted_ok)
        place_past_end(&at->counted_lines, error);
}

/* Puts a position OpenSCAD gave in the source on it as the user named it
 * (path), or, past the source's end, on the -D setting there, as a
 * command-line error. OpenSCAD names a file relative to the working
 * directory in its parser's errors, but relative to the file's folder in
 * its warnings; other files are named from the working directory too
 * (place_other). */
static void place_position(source_lines *at, sc_error *error)
{
    char real[PATH_MAX], beside[PATH_MAX + SC_ERROR_FILE_MAX];
    const char *slash = strrchr(at->source, '/'); /* realpath is absolute */
    snprintf(beside, sizeof beside, "%.*s/%s", (int)(slash - at->source), at->source,
             error->file);
    int source =
        (realpath(error->file, real) && !strcmp(real, at->source)) ||
        (error->file[0] != '/' && realpath(beside, real) && !strcmp(real, at->source));
    if (!source) {
        place_other(at, error);
        return;
    }
    if (at->source_counted == 0)
        at->source_counted = count_lines(at->source, &at->lines) ? 1 : -1;
    if (at->source_counted > 0)
        place_past_end(&at->lines, error);
    if (strcmp(error->file, "<command-line>") != 0)
        snprintf(error->file, sizeof error->file, "%s", at->path);
}

/* Whether a warning put on the -D settings was printed already (OpenSCAD
 * gives it again for each library and each time it is evaluated); notes
 * it when not. */
static int said_before(source_lines *at, const sc_error *w)
{
    if (strcmp(w->file, "<command-line>") != 0)
        return 0;
    for (int i = 0; i < at->said_count; i++)
        if (!strcmp(at->said[i], w->message))
            return 1;
    if (at->said_count < (int)(sizeof at->said / sizeof at->said[0]))
        snprintf(at->said[at->said_count++], sizeof at->said[0], "%s", w->message);
    return 0;
}

/* OpenSCAD's report on the conversion of path, from its log at log_path.
 * OpenSCAD 2021.01 exits 0 after many errors (a failing assert(), a syntax
 * error in a use <...> file) and leaves the failed part out, so its log
 * decides, not only its exit status (failed: it exited non-zero). It is
 * read a message at a time (next_message: a string's line breaks do not
 * end one). Each "WARNING: " or "DEPRECATED: " line is printed on stderr as a compiler's
 * warning, at OpenSCAD's position when the line has one, else against
 * path (the render goes on, as OpenSCAD's does), and so is an "ERROR: "
 * line of lenient_errors. The first other "ERROR: " line becomes the
 * error (with strict, the first "WARNING: " line too, as OpenSCAD's
 * --hardwarnings makes it one; nothing after it is printed), at its
 * position when it has one, else against path; a failure without an
 * ERROR line is told by OpenSCAD's last non-empty line. File names are as
 * the working directory reaches them (place_other), the source as the
 * user named it, and the -D settings as such (place_position). Returns SC_OK when
 * OpenSCAD reported no error. */
/* OpenSCAD 2021.01's errors that stop nothing: it logs them and goes on
 * evaluating the file, and renders the model. A use <font.ttf> of a file
 * that is not there (FileModule::registerUse) leaves the font unregistered,
 * and text() falls back to fontconfig's match for the font's name. */
static const char *const lenient_errors[] = {"Can't read font with path "};

static int is_lenient_error(const char *text)
{
    for (size_t k = 0; k < sizeof lenient_errors / sizeof lenient_errors[0]; k++)
        if (!strncmp(text, lenient_errors[k], strlen(lenient_errors[k])))
            return 1;
    return 0;
}

/* OpenSCAD's log, read a message at a time (next_message). */
typedef struct log_reader {
    FILE *f;
    char ahead[SC_ERROR_MESSAGE_MAX]; /* a line read ahead, when has_ahead */
    int has_ahead;
} log_reader;

/* Whether a line of OpenSCAD's log starts one of its messages. */
static int is_tagged(const char *line)
{
    static const char *const tags[] = {
        "ECHO: ", "WARNING: ", "ERROR: ", "TRACE: ", "DEPRECATED: "};
    for (size_t k = 0; k < sizeof tags / sizeof tags[0]; k++)
        if (!strncmp(line, tags[k], strlen(tags[k])))
            return 1;
    return 0;
}

/* The next line of f into line (size bytes), without its line break; 0 at
 * the end. */
static int read_line(FILE *f, char *line, size_t size)
{
    if (!fgets(line, (int)size, f))
        return 0;
    size_t n = strlen(line);
    while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
        line[--n] = 0;
    return 1;
}

/* The next line of the log into line (size bytes): the one read ahead
 * first. */
static int next_line(log_reader *r, char *line, size_t size)
{
    if (r->has_ahead) {
        snprintf(line, size, "%s", r->ahead);
        r->has_ahead = 0;
        return 1;
    }
    return read_line(r->f, line, size);
}

/* The next message of the log into message (size bytes, cut to fit); 0 at
 * the end. A message is a line and the lines after it while a string it
 * prints is open (an odd number of '"': OpenSCAD prints a string's line
 * breaks as they are, in echo() and in an assert()'s message, and its
 * position after them) and the next line starts no message of its own. */
static int next_message(log_reader *r, char *message, size_t size)
{
    if (!next_line(r, message, size))
        return 0;
    size_t n = strlen(message), quotes = 0;
    for (size_t i = 0; i < n; i++)
        quotes += message[i] == '"';
    while (quotes % 2 == 1 && read_line(r->f, r->ahead, sizeof r->ahead)) {
        if (is_tagged(r->ahead)) {
            r->has_ahead = 1;
            break;
        }
        for (const char *c = r->ahead; *c; c++)
            quotes += *c == '"';
        snprintf(message + n, size - n, "\n%s", r->ahead);
        n += strlen(message + n);
    }
    return 1;
}

static sc_status openscad_log(const char *log_path, source_lines *at, int failed,
                              int strict, sc_error *error)
{
    const char *path = at->path;
    char first[SC_ERROR_MESSAGE_MAX] = "", last[SC_ERROR_MESSAGE_MAX] = "";
    sc_status status = SC_ERR_SYNTAX; /* of the first: an error, or a warning */
    FILE *f = fopen(log_path, "r");
    if (f) {
        char line[SC_ERROR_MESSAGE_MAX];
        log_reader reader = {.f = f};
        while (next_message(&reader, line, sizeof line)) {
            size_t n = strlen(line);
            int is_error = !strncmp(line, "ERROR: ", 7) && line[7];
            int is_warning = !strncmp(line, "WARNING: ", 9) && line[9];
            size_t skip = is_error ? 7 : 9; /* the text after the tag */
            if (is_error &&
                is_lenient_error(line + 7)) { /* a warning, as its effect is */
                is_error = 0;
                is_warning = 1;
            }
            /* OpenSCAD's notes of a deprecated form are warnings that
             * --hardwarnings leaves alone. */
            int is_deprecated = !strncmp(line, "DEPRECATED: ", 12) && line[12];
            /* echo() output, as OpenSCAD prints it, in order with the
             * warnings; none after the error that stops the conversion */
            if (!strncmp(line, "ECHO: ", 6) && !first[0]) {
                fprintf(stderr, "%s\n", line);
                continue;
            }
            const char *text = line + (is_error || is_warning ? skip : 12);
            if (!first[0] && (is_error || (strict && is_warning))) {
                snprintf(first, sizeof first, "%s", text);
                status = is_error ? SC_ERR_SYNTAX : SC_ERR_SEMANTIC;
            } else if ((is_warning && !strict) || (is_deprecated && !first[0])) {
                sc_error w;
                memset(&w, 0, sizeof w);
                if (openscad_position(text, &w)) {
                    place_position(at, &w);
                    if (said_before(at, &w))
                        continue;
                    if (w.line > 0)
                        fprintf(stderr, "%s:%d:%d: warning: %s\n", w.file, w.line,
                                w.column, w.message);
                    else
                        fprintf(stderr, "%s: warning: %s\n", w.file, w.message);
                } else
                    fprintf(stderr, "%s: warning: %s\n", path, text);
            }
            if (n > 0)
                snprintf(last, sizeof last, "%s", line);
        }
        fclose(f);
    }
    if (first[0]) {
        memset(error, 0, sizeof *error);
        error->status = status;
        if (openscad_position(first, error)) {
            place_position(at, error);
        } else {
            snprintf(error->file, sizeof error->file, "%s", path);
            snprintf(error->message, sizeof error->message, "%s", first);
        }
        return status;
    }
    if (!failed)
        return SC_OK;
    const char *why = last[0] ? last : "it failed without a message";
    return fail(error, SC_ERR_IO, "OpenSCAD could not convert '%s': %s", path, why);
}

#define SCAN_MAX_FILES 256 /* files scan_uses follows, all levels */

/* The files a .scad source names, for a watcher: see the file comment. */
typedef struct scan {
    char *seen[SCAN_MAX_FILES]; /* the .scad files scanned (malloc'd paths) */
    int count;
    void (*depend)(void *user, const char *file);
    void *user;
} scan;

static void scan_file(scan *sc, const char *path, int depth);

/* 1 when path names a file that is there and is no folder. */
static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && !S_ISDIR(st.st_mode);
}

/* Into path (PATH_MAX bytes), the library file name (length bytes) as
 * OpenSCAD 2021.01 finds one that is not beside the file that names it
 * (parsersettings.cc): in each folder of OPENSCADPATH (separated by ':'),
 * then the user's library folder, then OpenSCAD's own; 0 when none holds
 * it. */
static int library_path(const char *name, size_t length, char *path)
{
    const char *list = getenv("OPENSCADPATH");
    const char *data = getenv("XDG_DATA_HOME"), *home = getenv("HOME");
    char user[PATH_MAX];
    if (data && data[0])
        snprintf(user, sizeof user, "%s/OpenSCAD/libraries", data);
    else
        snprintf(user, sizeof user, "%s/.local/share/OpenSCAD/libraries",
                 home ? home : "");
    for (int stage = 0; stage < 3; stage++) {
        const char *p = stage == 0   ? (list ? list : "")
                        : stage == 1 ? user
                                     : "/usr/share/openscad/libraries";
        while (*p) {
            const char *end = stage == 0 ? strchr(p, ':') : NULL;
            size_t n = end ? (size_t)(end - p) : strlen(p);
            if (n &&
                (size_t)snprintf(path, PATH_MAX, "%.*s/%.*s", (int)n, p, (int)length,
                                 name) < PATH_MAX &&
                is_file(path))
                return 1;
            p += n + (end != NULL);
        }
    }
    return 0;
}

/* Reports name, as the source at from names it, and scans it too when it
 * is OpenSCAD source (include and use): beside from, or for a library
 * (follow) that is not there, where OpenSCAD finds it (library_path). */
static void scan_name(scan *sc, const char *from, const char *name, size_t length,
                      int follow, int depth)
{
    char path[PATH_MAX];
    const char *slash = strrchr(from, '/');
    if (length == 0 || length >= sizeof path)
        return;
    if (name[0] == '/' || !slash)
        snprintf(path, sizeof path, "%.*s", (int)length, name);
    else if ((size_t)snprintf(path, sizeof path, "%.*s/%.*s", (int)(slash - from), from,
                              (int)length, name) >= sizeof path)
        return;
    char found[PATH_MAX];
    if (follow && name[0] != '/' && !is_file(path) && library_path(name, length, found))
        memcpy(path, found, sizeof path);
    sc->depend(sc->user, path);
    if (follow)
        scan_file(sc, path, depth + 1);
}

/* Whether word stands on its own at text[i] (of size bytes). */
static int word_at(const char *text, size_t size, size_t i, const char *word)
{
    size_t n = strlen(word);
    if (size - i < n || memcmp(text + i, word, n))
        return 0;
    int before = i > 0 && (isalnum((unsigned char)text[i - 1]) || text[i - 1] == '_' ||
                           text[i - 1] == '$');
    int after =
        i + n < size && (isalnum((unsigned char)text[i + n]) || text[i + n] == '_');
    return !before && !after;
}

static size_t skip_space(const char *text, size_t size, size_t i)
{
    while (i < size && isspace((unsigned char)text[i]))
        i++;
    return i;
}

/* The index of the quote that closes the string opened at text[i], or size
 * when it is not closed. */
static size_t string_end(const char *text, size_t size, size_t i)
{
    for (i++; i < size && text[i] != '"'; i++)
        if (text[i] == '\\')
            i++;
    return i < size ? i : size;
}

/* Scans the OpenSCAD source at path: comments and strings are skipped,
 * include <NAME> and use <NAME> are reported and followed, and the first
 * string argument of import( and surface( (or their file = "...") is
 * reported. Each index below stays within [0, size]. */
static void scan_file(scan *sc, const char *path, int depth)
{
    if (depth > 16 || sc->count == SCAN_MAX_FILES)
        return;
    for (int k = 0; k < sc->count; k++)
        if (!strcmp(sc->seen[k], path))
            return;
    sc->seen[sc->count] = strdup(path);
    if (!sc->seen[sc->count])
        return;
    sc->count++;
    size_t size = 0;
    const char *why;
    char *text = file_read(path, 1 << 24, &size, &why);
    if (!text)
        return;
    size_t i = 0;
    while (i < size) {
        if (i + 1 < size && text[i] == '/' && text[i + 1] == '/') {
            while (i < size && text[i] != '\n')
                i++;
        } else if (i + 1 < size && text[i] == '/' && text[i + 1] == '*') {
            const char *close = strstr(text + i + 2, "*/");
            i = close ? (size_t)(close - text) + 2 : size;
        } else if (text[i] == '"') {
            i = string_end(text, size, i) + 1;
        } else if (word_at(text, size, i, "include") || word_at(text, size, i, "use")) {
            size_t q = skip_space(text, size, i + (text[i] == 'i' ? 7 : 3));
            const char *close =
                q < size && text[q] == '<' ? memchr(text + q, '>', size - q) : NULL;
            if (close) {
                scan_name(sc, path, text + q + 1, (size_t)(close - text) - q - 1, 1,
                          depth);
                i = (size_t)(close - text);
            }
            i++;
        } else if (word_at(text, size, i, "import") ||
                   word_at(text, size, i, "surface")) {
            size_t q = skip_space(text, size, i + (text[i] == 'i' ? 6 : 7));
            if (q < size && text[q] == '(') {
                q = skip_space(text, size, q + 1);
                if (word_at(text, size, q, "file")) {
                    q = skip_space(text, size, q + 4);
                    if (q < size && text[q] == '=')
                        q = skip_space(text, size, q + 1);
                }
                if (q < size && text[q] == '"') {
                    size_t close = string_end(text, size, q);
                    if (close < size)
                        scan_name(sc, path, text + q + 1, close - q - 1, 0, depth);
                    i = close;
                }
            }
            i++;
        } else {
            i++;
        }
    }
    free(text);
}

/* Calls depend for source and every file it names, as scan_file reads
 * them: the watcher's list when OpenSCAD wrote none. */
static void scan_uses(const char *source, void (*depend)(void *user, const char *file),
                      void *user)
{
    scan sc;
    memset(&sc, 0, sizeof sc);
    sc.depend = depend;
    sc.user = user;
    depend(user, source);
    scan_file(&sc, source, 0);
    for (int k = 0; k < sc.count; k++)
        free(sc.seen[k]);
}

static void depend_nothing(void *user, const char *file)
{
    (void)user;
    (void)file;
}

/* The .scad files the source reaches, into at->libraries (once). */
static void libraries_read(source_lines *at)
{
    if (at->libraries_read)
        return;
    at->libraries_read = 1;
    scan sc;
    memset(&sc, 0, sizeof sc);
    sc.depend = depend_nothing;
    scan_file(&sc, at->path, 0);
    size_t room = (size_t)(sc.count ? sc.count : 1) * sizeof(char *);
    at->libraries = malloc(room);
    at->reals = malloc(room);
    for (int k = 0; k < sc.count; k++) {
        if (at->libraries && at->reals) {
            at->reals[at->library_count] = realpath(sc.seen[k], NULL);
            at->libraries[at->library_count++] = sc.seen[k];
        } else {
            free(sc.seen[k]);
        }
    }
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

static sc_status convert(const char *path, const double *time,
                         const sc_load_options *options, char **text, size_t *size,
                         char *name, size_t name_size, sc_error *error,
                         void (*depend)(void *user, const char *file), void *user,
                         const scad_stop *stop);

/* An error at a position in the converted text (named name, a file that
 * does not exist, or an unrelated file of the user's) is put on the source
 * path as the user gave it, with the line of OpenSCAD's export in the
 * message; errors in other files (an imported mesh) keep their position. */
static void blame_source(sc_error *error, const char *name, const char *path)
{
    if (strcmp(error->file, name) != 0)
        return;
    if (error->line > 0) {
        char note[64];
        int n =
            snprintf(note, sizeof note, " (line %d of OpenSCAD's export)", error->line);
        size_t used = strlen(error->message);
        if (n > 0 && used + (size_t)n < sizeof error->message)
            memcpy(error->message + used, note, (size_t)n + 1);
    }
    snprintf(error->file, sizeof error->file, "%s", path);
    error->line = 0;
    error->column = 0;
}

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
    sc_status st = convert(path, time, options, &text, &size, name, sizeof name, error,
                           depend, user, stop);
    if (st == SC_OK) {
        if (stop && stop->loading)
            *stop->loading = 1;
        sc_load_options export;
        if (options)
            export = *options; /* built here: the current size */
        else
            sc_load_options_init(&export);
        export.openscad_export = 1;
        st = sc_scene_load_string(name, text, size, &export, scene, error);
        if (stop && stop->loading)
            *stop->loading = 0;
        if (st != SC_OK)
            blame_source(error, name, path);
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

/* A font the source uses (use <NAME.ttf> or .otf, any case), as scan_file
 * names it: registered when it is a file, as OpenSCAD registers it
 * (FileModule::registerUse), so that text() finds it by its family name.
 * One that is not there is OpenSCAD's error, which openscad_log has told
 * as a warning; one that fontconfig cannot read is OpenSCAD's message. */
static void register_font(void *user, const char *file)
{
    (void)user;
    size_t n = strlen(file);
    if (n < 4 || (strcasecmp(file + n - 4, ".ttf") && strcasecmp(file + n - 4, ".otf")))
        return;
    struct stat st;
    if (stat(file, &st) != 0 || !S_ISREG(st.st_mode))
        return;
    sc_error e;
    if (sc_font_register(file, &e) != SC_OK)
        fprintf(stderr, "%s: warning: %s\n", file, e.message);
}

void scad_register_fonts(const char *path)
{
    scan_uses(path, register_font, NULL);
}

/* Whether the -D setting d (NAME=VALUE) sets $preview. */
static int sets_preview(const char *d)
{
    d += strspn(d, " \t");
    if (strncmp(d, "$preview", 8) != 0)
        return 0;
    d += 8;
    d += strspn(d, " \t");
    return *d == '=';
}

/* The conversion, with OpenSCAD's $t set to *time when time is not NULL
 * (a top-level assignment that -D appends to the source, which is how a
 * file's own $t = ... would set it), and $preview false unless options ask
 * for the preview (not no_preview): OpenSCAD's export to .csg evaluates
 * with $preview true, its render (F6, or an export of a mesh) with false.
 * options->strict: OpenSCAD's first warning is the error. */
static sc_status convert(const char *path, const double *time,
                         const sc_load_options *options, char **text, size_t *size,
                         char *name, size_t name_size, sc_error *error,
                         void (*depend)(void *user, const char *file), void *user,
                         const scad_stop *stop)
{
    int strict = options && options->strict;
    int preview = options && !options->no_preview;
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
    const char *dot = strrchr(base, '.');
    int stem = (int)(dot && dot != base ? (size_t)(dot - base) : strlen(base));
    char csg[PATH_MAX + 16], log[PATH_MAX + 16], deps[PATH_MAX + 16];
    snprintf(csg, sizeof csg, "%s/%.*s.csg", dir, stem, base);
    snprintf(log, sizeof log, "%s/openscad.log", dir);
    snprintf(deps, sizeof deps, "%s/openscad.d", dir);
    snprintf(name, name_size, "%.*s.csg", (int)(base - source) + stem, source);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log, O_WRONLY | O_CREAT | O_TRUNC,
                                     0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    char define[64];
    char *argv[12 + 2 * SCAD_MAX_DEFINES] = {"openscad", "-o", csg};
    int argc = 3;
    for (int k = 0; k < define_count; k++) {
        argv[argc++] = "-D";
        argv[argc++] = (char *)defines[k];   /* posix_spawn does not write argv */
        preview |= sets_preview(defines[k]); /* the user's own wins */
    }
    if (!preview) { /* after the user's, which place_past_end counts */
        argv[argc++] = "-D";
        argv[argc++] = "$preview=false";
    }
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
        } else {
            source_lines at = {.source = source, .path = path};
            st = openscad_log(log, &at, !WIFEXITED(status) || WEXITSTATUS(status) != 0,
                              strict, error);
            for (int k = 0; k < at.library_count; k++) {
                free(at.libraries[k]);
                free(at.reals[k]);
            }
            free(at.libraries);
            free(at.reals);
            free(at.lines.crlf);
            free(at.counted_lines.crlf);
        }
    }
    if (st == SC_OK && depend)
        read_depends(deps, depend, user);
    else if (st != SC_ERR_CANCELLED && depend)
        scan_uses(source, depend, user);
    if (st == SC_OK)
        scad_register_fonts(source);
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

sc_status scad_load_at(const char *path, const sc_load_options *options, double t,
                       sc_scene **scene, sc_error *error, const scad_stop *stop)
{
    return convert_and_load(path, &t, options, scene, error, NULL, NULL, stop);
}

/* ---- MODEL as the commands take it ---- */

/* The note for a .csg that goes on in OpenSCAD's language, at the error
 * that says where (parse_error_is_language). */
static void language_note(const char *path, const sc_error *error)
{
    fprintf(stderr,
            "%s: note: uses OpenSCAD's language beyond its CSG export (line %d); "
            "converting it with openscad\n",
            path, error->line);
}

/* -D given for a file that spancast reads itself. */
static void unused_defines(const char *path)
{
    if (define_count)
        fprintf(stderr,
                "%s: warning: -D is passed to OpenSCAD, which does not convert this "
                "file\n",
                path);
}

/* Whether an error is at the file path (as given). */
static int at_file(const sc_error *error, const char *path)
{
    return strcmp(error->file, path) == 0;
}

sc_status scad_load_model(const char *path, const sc_load_options *options,
                          sc_scene **scene, sc_error *error,
                          void (*depend)(void *user, const char *file), void *user,
                          const scad_stop *stop, int *converted)
{
    *scene = NULL;
    if (converted)
        *converted = 0;
    if (scad_is_source(path)) {
        if (converted)
            *converted = 1;
        return convert_and_load(path, NULL, options, scene, error, depend, user, stop);
    }
    /* The load cannot be stopped from inside: a signal during it ends the
     * process (stop.c), and one that came before it, seen after the flag
     * is set, ends it here. */
    if (stop && stop->loading)
        *stop->loading = 1;
    if (stop && stop->stop && *stop->stop) {
        if (stop->loading)
            *stop->loading = 0;
        memset(error, 0, sizeof *error);
        error->status = SC_ERR_CANCELLED;
        snprintf(error->message, sizeof error->message, "interrupted");
        return SC_ERR_CANCELLED;
    }
    sc_status st = scad_is_mesh(path) ? sc_scene_load_mesh(path, options, scene, error)
                                      : sc_scene_load(path, options, scene, error);
    if (stop && stop->loading)
        *stop->loading = 0;
    if (st != SC_OK && !scad_is_mesh(path) && parse_error_is_language(error) &&
        at_file(error, path)) {
        language_note(path, error);
        if (converted)
            *converted = 1;
        return convert_and_load(path, NULL, options, scene, error, depend, user, stop);
    }
    if (st == SC_OK)
        unused_defines(path);
    return st;
}

sc_status scad_load_objects(const char *path, const sc_load_options *options,
                            sc_objects **objects, sc_error *error, const scad_stop *stop,
                            int *converted)
{
    *objects = NULL;
    *converted = 0;
    sc_status st;
    if (!scad_is_source(path)) {
        if (stop && stop->loading)
            *stop->loading = 1;
        st = sc_objects_load(path, options, objects, error);
        if (stop && stop->loading)
            *stop->loading = 0;
        if (st == SC_OK)
            unused_defines(path);
        if (st == SC_OK || scad_is_mesh(path) || !parse_error_is_language(error) ||
            !at_file(error, path))
            return st;
        language_note(path, error);
    }
    *converted = 1;
    char *text = NULL, name[PATH_MAX + 16];
    size_t size = 0;
    st = convert(path, NULL, options, &text, &size, name, sizeof name, error, NULL, NULL,
                 stop);
    if (st == SC_OK) {
        if (stop && stop->loading)
            *stop->loading = 1;
        st = sc_objects_load_string(name, text, size, options, objects, error);
        if (stop && stop->loading)
            *stop->loading = 0;
        if (st != SC_OK)
            blame_source(error, name, path);
    }
    free(text);
    return st;
}

/* A parse sink that keeps nothing: the check of scad_read_model. */
static sc_status skip_open(void *user, parse_node *node, int *keep, sc_error *error)
{
    (void)user, (void)node, (void)keep, (void)error;
    return SC_OK;
}

static sc_status skip_close(void *user, parse_node *node, sc_error *error)
{
    (void)user, (void)node, (void)error;
    return SC_OK;
}

sc_status scad_read_model(const char *path, const sc_load_options *options, char **text,
                          size_t *size, char *name, size_t name_size, sc_error *error,
                          const scad_stop *stop)
{
    *text = NULL;
    *size = 0;
    if (scad_is_source(path))
        return convert(path, NULL, options, text, size, name, name_size, error, NULL,
                       NULL, stop);
    snprintf(name, name_size, "%s", path);
    if (scad_is_mesh(path))
        return mesh_model_text(path, text, size, error);
    const char *why;
    *text = file_read(path, SIZE_MAX / 2, size, &why);
    if (!*text)
        return fail(error, SC_ERR_IO, "cannot open '%s': %s", path, why);
    /* The syntax alone, streamed (the memory of the open nodes only), to
     * find OpenSCAD's language before the ranks load the text. */
    parse_sink sink = {.open = skip_open, .close = skip_close};
    parse_tree *tree = NULL;
    sc_status st = parse_stream(path, *text, *size, &sink, &tree, error);
    parse_tree_free(tree);
    if (st == SC_OK || !parse_error_is_language(error)) {
        if (st == SC_OK)
            unused_defines(path);
        return SC_OK; /* the ranks' load reports any other error */
    }
    language_note(path, error);
    free(*text);
    *text = NULL;
    *size = 0;
    return convert(path, NULL, options, text, size, name, name_size, error, NULL, NULL,
                   stop);
}

void scad_blame(sc_error *error, const char *name, const char *path)
{
    blame_source(error, name, path);
}

int scad_converted_name(const char *path, char *name, size_t name_size)
{
    char source[PATH_MAX];
    if (!realpath(path, source))
        return 0;
    const char *base = strrchr(source, '/') + 1;
    const char *dot = strrchr(base, '.');
    int stem = (int)(dot && dot != base ? (size_t)(dot - base) : strlen(base));
    return snprintf(name, name_size, "%.*s.csg", (int)(base - source) + stem, source) <
           (int)name_size;
}
