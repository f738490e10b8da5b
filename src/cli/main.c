/* The spancast command: argument parsing, messages and exit codes.
 *
 * This is the only place that reads argv, prints to the terminal or exits;
 * everything else goes through the public library API. Commands:
 *
 *   spancast render MODEL -o OUT [--mask=FILE] [--depth=FILE] [camera options]
 *   spancast info MODEL
 *   spancast --help | --version
 *
 * Every option that takes a value accepts it as --opt=value or as the next
 * argument. Exit status: 0 on success; 1 when the model cannot be loaded or
 * the image cannot be rendered or written (messages as the library formats
 * them, "file:line:col: error: ..."); 2 for a bad command line
 * ("spancast: error: ..."). Output names are checked before the model is
 * loaded, so a typo in an extension costs no render time.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "render/image_io.h"
#include "render/render.h"
#include "spancast/spancast.h"

#ifndef SPANCAST_VERSION
#define SPANCAST_VERSION "0.1.0"
#endif

enum { EXIT_FAILED = 1, EXIT_USAGE = 2 };

static const char usage_text[] =
    "usage: spancast render MODEL -o OUT.png [options]\n"
    "       spancast info MODEL\n"
    "       spancast --help | --version\n"
    "\n"
    "Renders a CSG model (OpenSCAD's .csg export, plus spancast's own nodes)\n"
    "exactly, by casting rays; 'info' prints the size and bounds of its tree.\n"
    "\n"
    "render options:\n"
    "  -o, --output=FILE      colour image; the format follows the extension\n"
    "                         (.png, .jpg, .tif, .exr, ...)\n"
    "  --mask=FILE            coverage mask: 255 where the model is hit, 0 elsewhere\n"
    "  --depth=FILE           distance from the ray origin to the hit, 32-bit float,\n"
    "                         +inf on a miss (.exr or .tif)\n"
    "  --camera=EX,EY,EZ,CX,CY,CZ\n"
    "                         look from eye E at centre C, z up\n"
    "  --camera=TX,TY,TZ,RX,RY,RZ,D\n"
    "                         OpenSCAD's gimbal camera: translate, rotate (degrees),\n"
    "                         distance\n"
    "  --imgsize=W,H          image size in pixels (default 800,600)\n"
    "  --fov=DEG              vertical field of view in degrees (default 22.5)\n"
    "  --projection=p|o       perspective (default) or orthographic\n"
    "  --viewall              move the camera until the whole model is in view\n"
    "  --autocenter           with --viewall: look at the centre of the model\n"
    "  --threads=N            worker threads (default 0: all cores)\n"
    "  --faithful             spheres and cylinders as the polyhedra OpenSCAD makes\n"
    "                         from $fn, $fa, $fs (default: exact solids)\n"
    "  -q, --quiet            no summary line on stderr\n"
    "\n"
    "Without --camera, spancast looks at the centre of the model from OpenSCAD's\n"
    "default direction (rotate 55,0,25), far enough to show all of it.\n"
    "A value may also follow its option as the next argument: --fov 30.\n"
    "\n"
    "Exit status: 0 success; 1 the model could not be loaded, or an image not\n"
    "rendered or written; 2 a bad command line.\n";

/* ---- messages ---- */

static int usage_error(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("spancast: error: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    return EXIT_USAGE;
}

/* Prints a library error: with its source position when it has one,
 * otherwise as the tool's own message. */
static void print_error(const sc_error *error)
{
    if (error->file[0]) {
        char buf[SC_ERROR_MESSAGE_MAX + SC_ERROR_FILE_MAX + 64];
        fprintf(stderr, "%s\n", sc_error_format(error, buf, sizeof buf));
    } else {
        fprintf(stderr, "spancast: error: %s\n", error->message);
    }
}

static void print_warning(const sc_error *w)
{
    if (w->file[0] && w->line > 0)
        fprintf(stderr, "%s:%d:%d: warning: %s\n", w->file, w->line, w->column,
                w->message);
    else if (w->file[0])
        fprintf(stderr, "%s: warning: %s\n", w->file, w->message);
    else
        fprintf(stderr, "spancast: warning: %s\n", w->message);
}

/* ---- values ---- */

/* A whole string as a finite number. */
static int parse_number(const char *s, double *out)
{
    if (!*s || *s == ' ' || *s == '\t')
        return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || errno == ERANGE || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

/* A whole string as a decimal integer within [lo, hi]. */
static int parse_int(const char *s, long lo, long hi, long *out)
{
    if (!*s || !(*s == '-' || *s == '+' || (*s >= '0' && *s <= '9')))
        return 0;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end || errno == ERANGE || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

/* Splits s at commas into at most max numbers; returns how many there were
 * (max + 1 when there are too many), or -1 when one is not a number. */
static int parse_numbers(const char *s, double *out, int max)
{
    char buf[512];
    size_t len = strlen(s);
    if (len >= sizeof buf)
        return -1;
    memcpy(buf, s, len + 1);
    int count = 0;
    char *field = buf;
    for (;;) {
        char *comma = strchr(field, ',');
        if (comma)
            *comma = '\0';
        if (count == max)
            return max + 1;
        if (!parse_number(field, &out[count]))
            return -1;
        count++;
        if (!comma)
            return count;
        field = comma + 1;
    }
}

/* ---- the command line ---- */

typedef enum opt_id {
    OPT_OUTPUT,
    OPT_MASK,
    OPT_DEPTH,
    OPT_CAMERA,
    OPT_IMGSIZE,
    OPT_FOV,
    OPT_PROJECTION,
    OPT_VIEWALL,
    OPT_AUTOCENTER,
    OPT_THREADS,
    OPT_QUIET,
    OPT_FAITHFUL
} opt_id;

typedef struct opt_spec {
    const char *name;
    opt_id id;
    int takes_value;
    int render_only; /* rejected by 'info' */
} opt_spec;

static const opt_spec options_table[] = {
    {"--output", OPT_OUTPUT, 1, 1},         {"--mask", OPT_MASK, 1, 1},
    {"--depth", OPT_DEPTH, 1, 1},           {"--camera", OPT_CAMERA, 1, 1},
    {"--imgsize", OPT_IMGSIZE, 1, 1},       {"--fov", OPT_FOV, 1, 1},
    {"--projection", OPT_PROJECTION, 1, 1}, {"--viewall", OPT_VIEWALL, 0, 1},
    {"--autocenter", OPT_AUTOCENTER, 0, 1}, {"--threads", OPT_THREADS, 1, 1},
    {"--quiet", OPT_QUIET, 0, 0},           {"--faithful", OPT_FAITHFUL, 0, 0},
};

typedef struct cli_args {
    int render; /* 1: render, 0: info */
    const char *input;
    const char *output, *mask, *depth;
    int quiet;
    int faithful; /* --faithful: OpenSCAD's polyhedra for spheres and cylinders */
    sc_render_options options;
} cli_args;

/* Applies one option with its value (NULL for flags); returns 0 or the exit
 * status of a usage error. */
static int apply_option(cli_args *a, opt_id id, const char *value)
{
    sc_render_options *o = &a->options;
    switch (id) {
    case OPT_OUTPUT:
        a->output = value;
        return 0;
    case OPT_MASK:
        a->mask = value;
        return 0;
    case OPT_DEPTH:
        a->depth = value;
        return 0;
    case OPT_CAMERA: {
        double v[7];
        int n = parse_numbers(value, v, 7);
        if (n != 6 && n != 7)
            return usage_error("--camera expects 6 numbers (eye, centre) or 7 numbers "
                               "(translate, rotate, distance)");
        memcpy(o->camera, v, (size_t)n * sizeof v[0]);
        o->camera_mode = n == 6 ? SC_CAMERA_VECTOR : SC_CAMERA_GIMBAL;
        return 0;
    }
    case OPT_IMGSIZE: {
        const char *comma = strchr(value, ',');
        char w_text[32];
        long w, h;
        if (!comma || (size_t)(comma - value) >= sizeof w_text)
            return usage_error("--imgsize expects W,H with positive integers");
        memcpy(w_text, value, (size_t)(comma - value));
        w_text[comma - value] = '\0';
        if (!parse_int(w_text, 1, 1L << 30, &w) || !parse_int(comma + 1, 1, 1L << 30, &h))
            return usage_error("--imgsize expects W,H with positive integers");
        if (w > RENDER_MAX_SIDE || h > RENDER_MAX_SIDE)
            return usage_error("--imgsize allows at most %d pixels a side",
                               RENDER_MAX_SIDE);
        o->width = (int)w;
        o->height = (int)h;
        return 0;
    }
    case OPT_FOV: {
        double fov;
        if (!parse_number(value, &fov) || !(fov > 0 && fov < 180))
            return usage_error("--fov expects an angle in degrees between 0 and 180");
        o->fov_deg = fov;
        return 0;
    }
    case OPT_PROJECTION:
        if (!strcmp(value, "p") || !strcmp(value, "perspective")) {
            o->projection = SC_PROJECTION_PERSPECTIVE;
        } else if (!strcmp(value, "o") || !strcmp(value, "ortho") ||
                   !strcmp(value, "orthogonal") || !strcmp(value, "orthographic")) {
            o->projection = SC_PROJECTION_ORTHOGRAPHIC;
        } else {
            return usage_error(
                "--projection expects 'p' (perspective) or 'o' (orthographic)");
        }
        return 0;
    case OPT_VIEWALL:
        o->viewall = 1;
        return 0;
    case OPT_AUTOCENTER:
        o->autocenter = 1;
        return 0;
    case OPT_THREADS: {
        long n;
        if (!parse_int(value, 0, 4096, &n))
            return usage_error("--threads expects a non-negative integer (0: all cores)");
        o->threads = (int)n;
        return 0;
    }
    case OPT_QUIET:
        a->quiet = 1;
        return 0;
    case OPT_FAITHFUL:
        a->faithful = 1;
        return 0;
    }
    return 0;
}

static const opt_spec *find_option(const char *arg, size_t name_len)
{
    for (size_t k = 0; k < sizeof options_table / sizeof options_table[0]; k++) {
        const char *name = options_table[k].name;
        if (strlen(name) == name_len && !strncmp(arg, name, name_len))
            return &options_table[k];
    }
    return NULL;
}

/* Parses argv[2..] for the command in a; returns 0 or a usage exit status. */
static int parse_args(cli_args *a, int argc, char **argv)
{
    const char *command = a->render ? "render" : "info";
    int only_files = 0;
    for (int k = 2; k < argc; k++) {
        const char *arg = argv[k];
        const opt_spec *spec = NULL;
        const char *value = NULL;
        int has_value = 0;
        if (!only_files && !strcmp(arg, "--")) {
            only_files = 1;
            continue;
        }
        if (!only_files && arg[0] == '-' && arg[1] == '-') {
            const char *eq = strchr(arg, '=');
            size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
            spec = find_option(arg, len);
            if (!spec)
                return usage_error("unknown option '%.*s'", (int)len, arg);
            if (eq) {
                if (!spec->takes_value)
                    return usage_error("option '%s' takes no value", spec->name);
                value = eq + 1;
                has_value = 1;
            }
        } else if (!only_files && arg[0] == '-' && arg[1] == 'o') {
            spec = find_option("--output", 8);
            if (arg[2]) {
                value = arg + 2;
                has_value = 1;
            }
        } else if (!only_files && !strcmp(arg, "-q")) {
            spec = find_option("--quiet", 7);
        } else if (!only_files && arg[0] == '-' && arg[1]) {
            return usage_error("unknown option '%s'", arg);
        } else {
            if (a->input)
                return usage_error("unexpected argument '%s'", arg);
            a->input = arg;
            continue;
        }
        if (spec->render_only && !a->render)
            return usage_error("option '%s' does not apply to '%s'",
                               arg[1] == '-' ? spec->name : "-o", command);
        if (spec->takes_value && !has_value) {
            if (k + 1 >= argc)
                return usage_error("option '%s' expects a value",
                                   arg[1] == '-' ? spec->name : "-o");
            value = argv[++k];
        }
        if (spec->takes_value && !*value)
            return usage_error("option '%s' expects a value",
                               arg[1] == '-' ? spec->name : "-o");
        int st = apply_option(a, spec->id, value);
        if (st)
            return st;
    }
    if (!a->input)
        return usage_error("missing input file");
    if (a->render && !a->output)
        return usage_error("missing output file (-o)");
    return 0;
}

/* ---- commands ---- */

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static sc_scene *load(const char *path, int faithful)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.faithful = faithful;
    sc_scene *scene = NULL;
    sc_error error;
    if (sc_scene_load(path, &lo, &scene, &error) != SC_OK) {
        print_error(&error);
        return NULL;
    }
    size_t warnings = sc_scene_warning_count(scene);
    for (size_t k = 0; k < warnings; k++)
        print_warning(sc_scene_warning(scene, k));
    return scene;
}

static int run_info(const cli_args *a)
{
    sc_scene *scene = load(a->input, a->faithful);
    if (!scene)
        return EXIT_FAILED;
    sc_scene_info info;
    sc_scene_get_info(scene, &info);
    double lo[3], hi[3];
    printf("model:  %s\n", a->input);
    printf("nodes:  %zu\n", info.node_count);
    printf("leaves: %zu\n", info.leaf_count);
    printf("depth:  %zu\n", info.depth);
    if (sc_scene_bounds(scene, lo, hi))
        printf("bounds: [%g, %g, %g] to [%g, %g, %g]\n", lo[0], lo[1], lo[2], hi[0],
               hi[1], hi[2]);
    else
        printf("bounds: empty\n");
    sc_scene_release(scene);
    return 0;
}

static int run_render(cli_args *a)
{
    /* Reject output names OpenImageIO cannot write before any work. */
    sc_error error;
    if (imgio_check(a->output, IMGIO_COLOR, &error) ||
        (a->mask && imgio_check(a->mask, IMGIO_MASK, &error)) ||
        (a->depth && imgio_check(a->depth, IMGIO_DEPTH, &error)))
        return usage_error("%s", error.message);

    double start = seconds_now();
    sc_scene *scene = load(a->input, a->faithful);
    if (!scene)
        return EXIT_FAILED;
    a->options.want_color = 1;
    a->options.want_mask = a->mask != NULL;
    a->options.want_depth = a->depth != NULL;
    sc_framebuffer *fb = NULL;
    int status = 0;
    sc_status st = sc_render(scene, &a->options, &fb, &error);
    if (st != SC_OK) {
        /* An argument error here comes from the command line's camera. */
        print_error(&error);
        sc_scene_release(scene);
        return st == SC_ERR_ARGUMENT ? EXIT_USAGE : EXIT_FAILED;
    }
    if (sc_framebuffer_write_color(fb, a->output, &error) != SC_OK ||
        (a->mask && sc_framebuffer_write_mask(fb, a->mask, &error) != SC_OK) ||
        (a->depth && sc_framebuffer_write_depth(fb, a->depth, &error) != SC_OK)) {
        print_error(&error);
        status = EXIT_FAILED;
    }
    if (status == 0 && !a->quiet)
        fprintf(stderr, "spancast: wrote %s%s%s%s%s (%dx%d) in %.3f s\n", a->output,
                a->mask ? ", " : "", a->mask ? a->mask : "", a->depth ? ", " : "",
                a->depth ? a->depth : "", fb->width, fb->height, seconds_now() - start);
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    return status;
}

int main(int argc, char **argv)
{
    for (int k = 1; k < argc && strcmp(argv[k], "--"); k++) {
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            fputs(usage_text, stdout);
            return 0;
        }
        if (!strcmp(argv[k], "--version")) {
            printf("spancast %s\n", SPANCAST_VERSION);
            return 0;
        }
    }
    if (argc < 2)
        return usage_error("missing command (try 'spancast --help')");
    const char *command = argv[1];
    cli_args a;
    memset(&a, 0, sizeof a);
    sc_render_options_init(&a.options);
    if (!strcmp(command, "render"))
        a.render = 1;
    else if (!strcmp(command, "info"))
        a.render = 0;
    else if (command[0] == '-')
        return usage_error("missing command before '%s' (try 'spancast --help')",
                           command);
    else
        return usage_error("unknown command '%s' (expected 'render' or 'info')", command);
    int st = parse_args(&a, argc, argv);
    if (st)
        return st;
    return a.render ? run_render(&a) : run_info(&a);
}
