/* The spancast command: argument parsing, messages and exit codes.
 *
 * This is the only place that reads argv, prints to the terminal or exits;
 * everything else goes through the public library API. Commands:
 *
 *   spancast render MODEL -o OUT [--mask=FILE] [--depth=FILE] [--normal=FILE]
 *                         [--id=FILE] [camera, sampling and report options]
 *   spancast info MODEL
 *   spancast spans MODEL --ray=... | --rays=FILE | --pixel=I,J [...]   (query.c)
 *   spancast inside MODEL --point=X,Y,Z | --points=FILE [...]       (query.c)
 *   spancast measure MODEL [...]                                     (check.c)
 *   spancast overlaps MODEL [--min-volume=V] [...]                   (check.c)
 *   spancast compare A B [--diff=PREFIX] [...]                       (check.c)
 *   spancast view MODEL [...]        (spancast-view: view.c and its neighbours)
 *   spancast batch JOBS [--json]                                     (batch.c)
 *   spancast --help | --version
 *
 * MODEL is a .csg file, or a .scad file converted by OpenSCAD (scad.c).
 *
 * Every option that takes a value accepts it as --opt=value or as the next
 * argument. Exit status: 0 on success; 1 when the model cannot be loaded or
 * the image cannot be rendered or written (messages as the library formats
 * them, "file:line:col: error: ..."); 2 for a bad command line
 * ("spancast: error: ..."). Output names are checked before the model is
 * loaded, so a typo in an extension costs no render time.
 *
 * Settings come in three layers: the library's defaults, then the model
 * file's own (a camera() node), then the command line. The command line is
 * read once before loading (to fail fast) and applied again on top of the
 * file's settings after loading.
 *
 * Interrupts and --max-time (stop.c): SIGINT, SIGTERM and the time
 * limit's SIGALRM only set a flag, cli_stop. The library polls it through
 * sc_render_options.cancel: the render stops within milliseconds, inside
 * its tile, and a writer removes its temporary and leaves its target as it
 * was. The tool then prints "spancast: interrupted" and dies of the same
 * signal, so its parent sees an interrupted process (status 130 or 143 in
 * a shell), or prints the time limit's error and exits 1. A second
 * interrupt before that kills the process at once.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/dist.h"
#include "cli/frames.h"
#include "cli/scad.h"
#include "cli/tiles.h"
#include "cli/watch.h"
#include "formats/file.h"
#include "formats/image_io.h"
#include "render/render.h"
#include "render/shade.h"
#include "spancast/spancast.h"

enum { EXIT_FAILED = 1, EXIT_USAGE = 2 };

/* What `render` does under mpirun (CMakeLists.txt says). */
#ifndef SPANCAST_MPI_SUPPORT
#define SPANCAST_MPI_SUPPORT "not built"
#endif

/* ---- messages ---- */

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
    OPT_NORMAL,
    OPT_ID,
    OPT_SPP,
    OPT_MAX_DEPTH,
    OPT_REGION,
    OPT_STATS,
    OPT_FAITHFUL,
    OPT_STRICT,
    OPT_COLORSCHEME,
    OPT_LIGHTING,
    OPT_PREVIEW,
    OPT_VIEW,
    OPT_EDGE_ANGLE,
    OPT_EDGE_WIDTH,
    OPT_VIEW_PRESET,
    OPT_SHEET,
    OPT_SECTION,
    OPT_SECTION_STYLE,
    OPT_AO,
    OPT_AO_RADIUS,
    OPT_APERTURE,
    OPT_FOCUS,
    OPT_WATCH,
    OPT_ANIMATE,
    OPT_TURNTABLE,
    OPT_SHUTTER,
    OPT_SUBFRAMES,
    OPT_VIDEO,
    OPT_FPS,
    OPT_MAX_TIME,
    OPT_TILED
} opt_id;

typedef struct opt_spec {
    const char *name;
    opt_id id;
    int takes_value; /* 0 no, 1 yes, 2 optional (only as --opt=value) */
    int render_only; /* rejected by 'info' */
} opt_spec;

static const opt_spec options_table[] = {
    {"--output", OPT_OUTPUT, 1, 1},
    {"--mask", OPT_MASK, 1, 1},
    {"--depth", OPT_DEPTH, 1, 1},
    {"--camera", OPT_CAMERA, 1, 1},
    {"--imgsize", OPT_IMGSIZE, 1, 1},
    {"--fov", OPT_FOV, 1, 1},
    {"--projection", OPT_PROJECTION, 1, 1},
    {"--viewall", OPT_VIEWALL, 0, 1},
    {"--autocenter", OPT_AUTOCENTER, 0, 1},
    {"--threads", OPT_THREADS, 1, 0},
    {"--quiet", OPT_QUIET, 0, 0},
    {"--normal", OPT_NORMAL, 1, 1},
    {"--id", OPT_ID, 1, 1},
    {"--spp", OPT_SPP, 1, 1},
    {"--max-depth", OPT_MAX_DEPTH, 1, 1},
    {"--region", OPT_REGION, 1, 1},
    {"--stats", OPT_STATS, 2, 1},
    {"--faithful", OPT_FAITHFUL, 0, 0},
    {"--strict", OPT_STRICT, 0, 0},
    {"--colorscheme", OPT_COLORSCHEME, 1, 1},
    {"--lighting", OPT_LIGHTING, 1, 1},
    {"--preview", OPT_PREVIEW, 0, 1},
    {"--view", OPT_VIEW, 1, 1},
    {"--edge-angle", OPT_EDGE_ANGLE, 1, 1},
    {"--edge-width", OPT_EDGE_WIDTH, 1, 1},
    {"--view-preset", OPT_VIEW_PRESET, 1, 1},
    {"--sheet", OPT_SHEET, 1, 1},
    {"--section", OPT_SECTION, 1, 1},
    {"--section-style", OPT_SECTION_STYLE, 1, 1},
    {"--ao", OPT_AO, 1, 1},
    {"--ao-radius", OPT_AO_RADIUS, 1, 1},
    {"--aperture", OPT_APERTURE, 1, 1},
    {"--focus", OPT_FOCUS, 1, 1},
    {"--watch", OPT_WATCH, 0, 1},
    {"--max-time", OPT_MAX_TIME, 1, 0},
    {"--tiled", OPT_TILED, 0, 1},
    {"--animate", OPT_ANIMATE, 1, 1},
    {"--turntable", OPT_TURNTABLE, 1, 1},
    {"--shutter", OPT_SHUTTER, 1, 1},
    {"--subframes", OPT_SUBFRAMES, 1, 1},
    {"--video", OPT_VIDEO, 1, 1},
    {"--fps", OPT_FPS, 1, 1},
};

typedef struct cli_args {
    int render; /* 1: render, 0: info */
    const char *input;
    const char *output, *mask, *depth, *normal, *id;
    int quiet;
    int stats;            /* 0 none, 1 text, 2 JSON */
    int faithful;         /* --faithful: OpenSCAD's polyhedra for spheres and cylinders */
    int projection_given; /* --projection: a sheet is orthographic without it */
    int camera_given;     /* --camera */
    sc_view_preset preset; /* --view-preset */

    int tiled;          /* --tiled: stream the outputs tile by tile */
    frames_job frames;  /* --animate, --turntable and what goes with them */
    int frames_given;   /* --subframes, --video or --fps */
    int watch;          /* --watch: render again on every change */
    watch_set *watched; /* with --watch: the files the model was loaded from */
    sc_render_options options;
} cli_args;

/* Applies one option with its value (NULL for flags); returns 0 or the exit
 * status of a usage error. */
static int apply_option(cli_args *a, const opt_spec *spec, const char *value)
{
    sc_render_options *o = &a->options;
    switch (spec->id) {
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
        int n = cli_parse_numbers(value, v, 7);
        if (n != 6 && n != 7)
            return cli_usage_error(
                "--camera expects 6 numbers (eye, centre) or 7 numbers "
                "(translate, rotate, distance)");
        memcpy(o->camera, v, (size_t)n * sizeof v[0]);
        o->camera_mode = n == 6 ? SC_CAMERA_VECTOR : SC_CAMERA_GIMBAL;
        a->camera_given = 1;
        return 0;
    }
    case OPT_IMGSIZE: {
        const char *comma = strchr(value, ',');
        char w_text[32];
        long w, h;
        if (!comma || (size_t)(comma - value) >= sizeof w_text)
            return cli_usage_error("--imgsize expects W,H with positive integers");
        memcpy(w_text, value, (size_t)(comma - value));
        w_text[comma - value] = '\0';
        if (!cli_parse_int(w_text, 1, 1L << 30, &w) ||
            !cli_parse_int(comma + 1, 1, 1L << 30, &h))
            return cli_usage_error("--imgsize expects W,H with positive integers");
        if (w > RENDER_MAX_SIDE || h > RENDER_MAX_SIDE)
            return cli_usage_error("--imgsize allows at most %d pixels a side",
                                   RENDER_MAX_SIDE);
        o->width = (int)w;
        o->height = (int)h;
        return 0;
    }
    case OPT_FOV: {
        double fov;
        if (!cli_parse_number(value, &fov) || !(fov > 0 && fov < 180))
            return cli_usage_error("--fov expects an angle in degrees between 0 and 180");
        o->fov_deg = fov;
        return 0;
    }
    case OPT_PROJECTION:
        a->projection_given = 1;
        if (!strcmp(value, "p") || !strcmp(value, "perspective")) {
            o->projection = SC_PROJECTION_PERSPECTIVE;
        } else if (!strcmp(value, "o") || !strcmp(value, "ortho") ||
                   !strcmp(value, "orthogonal") || !strcmp(value, "orthographic")) {
            o->projection = SC_PROJECTION_ORTHOGRAPHIC;
        } else {
            return cli_usage_error(
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
        if (!cli_parse_int(value, 0, 4096, &n))
            return cli_usage_error(
                "--threads expects a non-negative integer (0: all cores)");
        o->threads = cli_load_threads = (int)n;
        return 0;
    }
    case OPT_QUIET:
        a->quiet = 1;
        return 0;
    case OPT_NORMAL:
        a->normal = value;
        return 0;
    case OPT_ID:
        a->id = value;
        return 0;
    case OPT_SPP: {
        long n;
        if (!cli_parse_int(value, 1, RENDER_MAX_SPP, &n))
            return cli_usage_error("--spp expects an integer from 1 to %d",
                                   RENDER_MAX_SPP);
        o->spp = (int)n;
        return 0;
    }
    case OPT_MAX_DEPTH: {
        long n;
        if (!cli_parse_int(value, 0, SHADE_MAX_DEPTH, &n))
            return cli_usage_error("--max-depth expects an integer from 0 to %d",
                                   SHADE_MAX_DEPTH);
        o->max_depth = (int)n;
        return 0;
    }
    case OPT_REGION: {
        double v[4];
        int ok = cli_parse_numbers(value, v, 4) == 4;
        for (int k = 0; ok && k < 4; k++)
            ok = v[k] == floor(v[k]) && v[k] >= 0 && v[k] <= RENDER_MAX_SIDE;
        if (!ok || !(v[0] < v[2] && v[1] < v[3]))
            return cli_usage_error("--region expects X0,Y0,X1,Y1 with 0 <= X0 < X1 and "
                                   "0 <= Y0 < Y1 (X1, Y1 exclusive)");
        for (int k = 0; k < 4; k++)
            o->region[k] = (int)v[k];
        return 0;
    }
    case OPT_STATS:
        if (!value)
            a->stats = 1;
        else if (!strcmp(value, "json"))
            a->stats = 2;
        else
            return cli_usage_error("--stats takes no value or '=json'");
        return 0;
    case OPT_FAITHFUL:
        a->faithful |= CLI_LOAD_FAITHFUL;
        return 0;
    case OPT_STRICT:
        a->faithful |= CLI_LOAD_STRICT;
        return 0;
    case OPT_COLORSCHEME:
    case OPT_LIGHTING:
    case OPT_PREVIEW:
    case OPT_VIEW:
    case OPT_EDGE_ANGLE:
    case OPT_EDGE_WIDTH:
    case OPT_VIEW_PRESET:
    case OPT_SHEET:
    case OPT_SECTION:
    case OPT_SECTION_STYLE:
    case OPT_AO:
    case OPT_AO_RADIUS:
    case OPT_APERTURE:
    case OPT_FOCUS:
        return cli_apply_preview_option(o, &a->preset, spec->name, strlen(spec->name),
                                        value);
    case OPT_WATCH:
        a->watch = 1;
        return 0;
    case OPT_MAX_TIME:
        return cli_parse_max_time(value);
    case OPT_TILED:
        a->tiled = 1;
        return 0;
    case OPT_ANIMATE:
    case OPT_TURNTABLE: {
        long n;
        if (!cli_parse_int(value, 1, 99999, &n))
            return cli_usage_error("%s expects a number of frames from 1 to 99999",
                                   spec->name);
        *(spec->id == OPT_ANIMATE ? &a->frames.animate : &a->frames.turntable) = (int)n;
        return 0;
    }
    case OPT_SHUTTER: {
        double v[2];
        if (cli_parse_numbers(value, v, 2) != 2 || !(v[0] >= 0 && v[0] <= v[1]) ||
            !(v[1] <= 1))
            return cli_usage_error("--shutter expects OPEN,CLOSE with 0 <= OPEN <= CLOSE "
                                   "<= 1 (fractions of a frame)");
        a->frames.shutter[0] = o->shutter[0] = v[0];
        a->frames.shutter[1] = o->shutter[1] = v[1];
        return 0;
    }
    case OPT_SUBFRAMES: {
        long n;
        if (!cli_parse_int(value, 1, 1024, &n))
            return cli_usage_error("--subframes expects an integer from 1 to 1024");
        a->frames.subframes = (int)n;
        a->frames_given = 1;
        return 0;
    }
    case OPT_VIDEO:
        a->frames.video = value;
        a->frames_given = 1;
        return 0;
    case OPT_FPS: {
        double v;
        if (!cli_parse_number(value, &v) || !(v > 0 && v <= 1000))
            return cli_usage_error("--fps expects frames per second above 0, at most "
                                   "1000");
        a->frames.fps = v;
        a->frames_given = 1;
        return 0;
    }
    }
    return 0;
}

static const opt_spec *find_option(const char *arg, size_t name_len)
{
    return cli_find_option(options_table, sizeof options_table / sizeof options_table[0],
                           sizeof options_table[0], arg, name_len);
}

/* Applies --view-preset and --sheet, which place the camera themselves:
 * a preset is OpenSCAD's view rotation framed like --viewall
 * --autocenter; a sheet is orthographic unless --projection says
 * otherwise. Returns 0 or a usage exit status. */
static int finish_views(cli_args *a)
{
    sc_render_options *o = &a->options;
    if (a->preset && o->sheet_count)
        return cli_usage_error("--view-preset and --sheet exclude each other");
    if ((a->preset || o->sheet_count) && a->camera_given)
        return cli_usage_error("--camera does not combine with --%s",
                               a->preset ? "view-preset" : "sheet");
    if (a->preset) {
        o->camera_mode = SC_CAMERA_GIMBAL;
        memset(o->camera, 0, sizeof o->camera);
        sc_view_preset_rotation(a->preset, o->camera + 3);
        o->camera[6] = 140;
        o->viewall = 1;
        o->autocenter = 1;
    }
    if (o->sheet_count && !a->projection_given)
        o->projection = SC_PROJECTION_ORTHOGRAPHIC;
    return 0;
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
                return cli_usage_error("unknown option '%.*s'", (int)len, arg);
            if (eq) {
                if (!spec->takes_value)
                    return cli_usage_error("option '%s' takes no value", spec->name);
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
            return cli_usage_error("unknown option '%s'", arg);
        } else {
            if (a->input)
                return cli_usage_error("unexpected argument '%s'", arg);
            a->input = arg;
            continue;
        }
        if (spec->render_only && !a->render)
            return cli_usage_error("option '%s' does not apply to '%s'",
                                   arg[1] == '-' ? spec->name : "-o", command);
        if (spec->takes_value == 1 && !has_value) {
            if (k + 1 >= argc)
                return cli_usage_error("option '%s' expects a value",
                                       arg[1] == '-' ? spec->name : "-o");
            value = argv[++k];
        }
        if (spec->takes_value && value && !*value)
            return cli_usage_error("option '%s' expects a value",
                                   arg[1] == '-' ? spec->name : "-o");
        int st = apply_option(a, spec, value);
        if (st)
            return st;
    }
    if (!a->input)
        return cli_usage_error("missing input file");
    if (a->render && !a->output)
        return cli_usage_error("missing output file (-o)");
    int frames = a->frames.animate || a->frames.turntable;
    if (a->frames_given && !frames)
        return cli_usage_error("--subframes, --video and --fps need --animate or "
                               "--turntable");
    if (a->frames.animate && a->frames.turntable &&
        a->frames.animate != a->frames.turntable)
        return cli_usage_error("--animate and --turntable must give the same number of "
                               "frames");
    if (frames && (a->mask || a->depth || a->normal || a->id || a->watch))
        return cli_usage_error("--animate and --turntable write colour frames only (no "
                               "--mask, --depth, --normal, --id or --watch)");
    int st = finish_views(a);
    /* without --preview, the load leaves out what only the preview draws */
    if (!st && a->options.preview)
        a->faithful |= CLI_LOAD_PREVIEW;
    return st;
}

/* ---- commands ---- */

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* watched: NULL, or a set that gets the model's files (render --watch);
 * faithful: CLI_LOAD_* flags. */
static sc_scene *load(const char *path, int faithful, watch_set *watched,
                      int *was_converted)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    cli_load_options(&lo, faithful);
    sc_scene *scene = NULL;
    sc_error error;
    if (watched)
        watch_add_file(watched, path);
    scad_stop stop = {&cli_stop, cli_loading_flag()};
    sc_status st;
    int converted = 0;
    if (dist_size() > 1) {
        st = dist_load(path, &lo, &scene, &error); /* rank 0 reads */
        converted = scad_is_source(path);
    } else {
        st = scad_load_model(path, &lo, &scene, &error, watched ? watch_add_file : NULL,
                             watched, &stop, &converted);
    }
    if (st != SC_OK) {
        if (!cli_stop)
            print_error(&error);
        return NULL;
    }
    /* Warnings at the converted text are put on the source, as its errors
     * are (scad_blame). */
    char name[PATH_MAX + 16] = "";
    if (converted && !scad_converted_name(path, name, sizeof name))
        name[0] = '\0';
    size_t warnings = dist_rank() == 0 ? sc_scene_warning_count(scene) : 0;
    for (size_t k = 0; k < warnings; k++) {
        sc_error w = *sc_scene_warning(scene, k);
        if (name[0])
            scad_blame(&w, name, path);
        print_warning(&w);
    }
    double lo3[3], hi3[3];
    if (dist_rank() == 0 && !sc_scene_bounds(scene, lo3, hi3))
        fprintf(stderr, "%s: warning: the model is empty (nothing to render)\n", path);
    if (was_converted)
        *was_converted = converted;
    return scene;
}

static int run_info(const cli_args *a)
{
    cli_catch_interrupts();
    cli_start_clock();
    sc_scene *scene = load(a->input, a->faithful, NULL, NULL);
    cli_stop_clock();
    if (cli_stop) {
        sc_scene_release(scene);
        return cli_die_stopped();
    }
    if (!scene)
        return EXIT_FAILED;
    sc_scene_info info;
    sc_scene_info_init(&info);
    sc_scene_get_info(scene, &info, NULL);
    double lo[3], hi[3];
    printf("model:  %s\n", a->input);
    printf("nodes:  %zu (%zu as written)\n", info.node_count, info.source_node_count);
    printf("leaves: %zu (%zu as written)\n", info.leaf_count, info.source_leaf_count);
    printf("depth:  %zu (%zu as written)\n", info.depth, info.source_depth);
    printf("bvh:    %zu nodes\n", info.bvh_node_count);
    printf("kinds: ");
    const char *sep = " ";
    for (int k = 0; sc_leaf_kind_name(k); k++) {
        if (!info.leaf_kinds[k])
            continue;
        printf("%s%zu %s", sep, info.leaf_kinds[k], sc_leaf_kind_name(k));
        sep = ", ";
    }
    printf("%s\n", *sep == ' ' ? " none" : "");
    if (info.lights)
        printf("lights: %zu\n", info.lights);
    else
        printf("lights: none (the default rig)\n");
    printf("materials: %zu mirror, %zu glass, %zu checkered leaves\n", info.mirror_leaves,
           info.glass_leaves, info.checker_leaves);
    if (sc_scene_bounds(scene, lo, hi))
        printf("bounds: [%g, %g, %g] to [%g, %g, %g]\n", lo[0], lo[1], lo[2], hi[0],
               hi[1], hi[2]);
    else
        printf("bounds: empty\n");
    if (sc_scene_frame_bounds(scene, NULL, lo, hi))
        printf("frame:  [%g, %g, %g] to [%g, %g, %g] (the solid's own box, which the "
               "render's default camera frames)\n",
               lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    if (info.flat_2d) {
        char slab[160];
        cli_slab_words(scene, slab, sizeof slab);
        printf("2D: drawn flat at z = 0, as OpenSCAD's render draws it; measured as the "
               "slab its preview draws: %s\n",
               slab);
    }
    sc_scene_release(scene);
    return 0;
}

/* Checks that path can be created: its folder exists, is a folder and is
 * writable, and path itself is not a folder. Prints the error the writer
 * would give and returns 0 when not, so a doomed render is never started
 * and an earlier output is not written when a later one cannot be. */
static int output_writable(const char *path)
{
    const char *slash = strrchr(path, '/');
    char folder[4096];
    if (!slash) {
        strcpy(folder, ".");
    } else {
        size_t n = slash == path ? 1 : (size_t)(slash - path);
        if (n >= sizeof folder)
            return 1; /* let the writer judge */
        memcpy(folder, path, n);
        folder[n] = '\0';
    }
    struct stat st;
    int code = 0;
    if (stat(folder, &st) != 0)
        code = errno;
    else if (!S_ISDIR(st.st_mode))
        code = ENOTDIR;
    else if (access(folder, W_OK | X_OK) != 0)
        code = errno;
    else if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        code = EISDIR;
    if (code)
        fprintf(stderr, "spancast: error: cannot write '%s': %s\n", path, strerror(code));
    return code == 0;
}

/* The progress bar: redrawn when the whole percentage changes. */
typedef struct progress_bar {
    int shown; /* last percentage drawn, -1 before the first */
} progress_bar;

static void draw_progress(void *user, double fraction)
{
    progress_bar *bar = user;
    int percent = (int)(fraction * 100);
    if (percent == bar->shown)
        return;
    bar->shown = percent;
    char cells[41];
    int filled = percent * 40 / 100;
    for (int k = 0; k < 40; k++)
        cells[k] = k < filled ? '#' : '.';
    cells[40] = '\0';
    fprintf(stderr, "\rspancast: [%s] %3d%%", cells, percent);
    if (percent == 100)
        fputc('\n', stderr);
    fflush(stderr);
}

typedef struct stage_times {
    double load, write, total;
} stage_times;

static void print_stats(const cli_args *a, const sc_framebuffer *fb, const stage_times *t)
{
    sc_render_stats stats;
    sc_render_stats_init(&stats);
    sc_framebuffer_get_stats(fb, &stats, NULL);
    const sc_render_stats *s = &stats;
    int width = sc_framebuffer_width(fb), height = sc_framebuffer_height(fb);
    uint64_t rays =
        s->camera_rays + s->shadow_rays + s->reflection_rays + s->refraction_rays;
    if (a->stats == 2) {
        printf("{\"image\": {\"width\": %d, \"height\": %d, \"spp\": %d, "
               "\"threads\": %d},\n",
               width, height, a->options.spp, s->threads);
        printf(" \"rays\": {\"camera\": %llu, \"shadow\": %llu, \"reflection\": %llu, "
               "\"refraction\": %llu, \"total\": %llu},\n",
               (unsigned long long)s->camera_rays, (unsigned long long)s->shadow_rays,
               (unsigned long long)s->reflection_rays,
               (unsigned long long)s->refraction_rays, (unsigned long long)rays);
        printf(" \"primitive_tests\": %llu, \"span_operations\": %llu,\n",
               (unsigned long long)s->primitive_tests,
               (unsigned long long)s->span_operations);
        printf(" \"node_visits\": %llu, \"bvh_node_visits\": %llu, "
               "\"scratch_mallocs\": %llu,\n",
               (unsigned long long)s->node_visits, (unsigned long long)s->bvh_node_visits,
               (unsigned long long)s->scratch_mallocs);
        printf(" \"seconds\": {\"load\": %.6f, \"setup\": %.6f, \"trace\": %.6f, "
               "\"write\": %.6f, \"total\": %.6f}}\n",
               t->load, s->setup_seconds, s->trace_seconds, t->write, t->total);
        return;
    }
    printf("image:            %dx%d, %d sample%s per pixel, %d thread%s\n", width, height,
           a->options.spp, a->options.spp == 1 ? "" : "s", s->threads,
           s->threads == 1 ? "" : "s");
    printf("rays:             %llu (camera %llu, shadow %llu, reflection %llu, "
           "refraction %llu)\n",
           (unsigned long long)rays, (unsigned long long)s->camera_rays,
           (unsigned long long)s->shadow_rays, (unsigned long long)s->reflection_rays,
           (unsigned long long)s->refraction_rays);
    printf("primitive tests:  %llu\n", (unsigned long long)s->primitive_tests);
    printf("span operations:  %llu\n", (unsigned long long)s->span_operations);
    printf("node visits:      %llu (BVH %llu)\n", (unsigned long long)s->node_visits,
           (unsigned long long)s->bvh_node_visits);
    printf("scratch mallocs:  %llu\n", (unsigned long long)s->scratch_mallocs);
    printf(
        "seconds:          load %.3f, setup %.3f, trace %.3f, write %.3f, total %.3f\n",
        t->load, s->setup_seconds, s->trace_seconds, t->write, t->total);
}

static int run_render(cli_args *a, int argc, char **argv)
{
    /* Reject output names OpenImageIO cannot write before any work. */
    sc_error error;
    if (imgio_check(a->output, IMGIO_COLOR, &error) ||
        (a->mask && imgio_check(a->mask, IMGIO_MASK, &error)) ||
        (a->depth && imgio_check(a->depth, IMGIO_DEPTH, &error)) ||
        (a->normal && imgio_check(a->normal, IMGIO_NORMAL, &error)) ||
        (a->id && imgio_check(a->id, IMGIO_ID, &error)))
        return cli_usage_error("%s", error.message);
    if (a->mask && imgio_lossy(a->mask) && dist_rank() == 0)
        fprintf(
            stderr,
            "spancast: warning: --mask=%s: JPEG is lossy, so the mask is no longer "
            "exactly 0 and 255 at the model's edges (.png, .tif and .exr are exact)\n",
            a->mask);
    /* OpenSCAD's scale markers belong to its axes (View > Show Scale
     * Markers is greyed out without Show Axes) */
    if ((a->options.view & SC_VIEW_SCALES) && !(a->options.view & SC_VIEW_AXES) &&
        dist_rank() == 0)
        fputs("spancast: warning: --view=scales marks the axes, which are not drawn: "
              "add axes to --view\n",
              stderr);
    int unwritable = /* rank 0 writes the files; every rank learns the outcome */
        dist_rank() == 0 &&
        (!output_writable(a->output) || (a->mask && !output_writable(a->mask)) ||
         (a->depth && !output_writable(a->depth)) ||
         (a->normal && !output_writable(a->normal)) ||
         (a->id && !output_writable(a->id)));
    if (dist_agree(unwritable))
        return EXIT_FAILED;

    double start = seconds_now();
    cli_catch_interrupts();
    cli_start_clock();
    sc_scene *scene = load(a->input, a->faithful, a->watched, NULL);
    if (cli_stop) {
        sc_scene_release(scene);
        return cli_die_stopped();
    }
    if (!scene)
        return EXIT_FAILED;
    stage_times times;
    times.load = seconds_now() - start;
    /* The file's settings, then the command line over them again. */
    cli_args again;
    memset(&again, 0, sizeof again);
    again.render = 1;
    sc_render_options_init(&again.options);
    sc_render_options_from_scene(&again.options, scene);
    (void)parse_args(&again, argc, argv); /* succeeded once already */
    a->options = again.options;
    a->options.cancel = &cli_stop;
    a->options.want_color = 1;
    a->options.want_mask = a->mask != NULL;
    a->options.want_depth = a->depth != NULL;
    a->options.want_normal = a->normal != NULL;
    a->options.want_id = a->id != NULL;
    progress_bar bar = {-1};
    if (!a->quiet && isatty(STDERR_FILENO)) {
        a->options.progress = draw_progress;
        a->options.progress_user = &bar;
    }
    sc_framebuffer *fb = NULL;
    int status = 0;
    /* One sc_render, or tiles across MPI ranks or streamed to the files. */
    tiles_outputs outputs = {a->output, a->mask, a->depth, a->normal, a->id, a->tiled};
    int streamed = 0;
    sc_status st = tiles_render(scene, &a->options, &outputs, &fb, &streamed, &error);
    if (st == SC_ERR_CANCELLED) {
        sc_scene_release(scene);
        return cli_die_stopped();
    }
    if (st != SC_OK) {
        /* An argument error here comes from the command line's camera. */
        print_error(&error);
        sc_scene_release(scene);
        return st == SC_ERR_ARGUMENT ? EXIT_USAGE : EXIT_FAILED;
    }
    if (!fb) { /* an MPI rank other than 0: rank 0 writes and reports */
        sc_scene_release(scene);
        return 0;
    }
    double written = seconds_now();
    if (!streamed && /* else written tile by tile */
        (sc_framebuffer_write_color(fb, a->output, &error) != SC_OK ||
         (a->mask && sc_framebuffer_write_mask(fb, a->mask, &error) != SC_OK) ||
         (a->depth && sc_framebuffer_write_depth(fb, a->depth, &error) != SC_OK) ||
         (a->normal && sc_framebuffer_write_normal(fb, a->normal, &error) != SC_OK) ||
         (a->id && sc_framebuffer_write_id(fb, a->id, &error) != SC_OK))) {
        if (error.status == SC_ERR_CANCELLED) {
            sc_framebuffer_release(fb);
            sc_scene_release(scene);
            return cli_die_stopped();
        }
        print_error(&error);
        status = EXIT_FAILED;
    }
    cli_stop_clock();
    times.write = seconds_now() - written;
    times.total = seconds_now() - start;
    if (status == 0 && !a->quiet)
        fprintf(stderr, "spancast: wrote %s%s%s%s%s%s%s%s%s (%dx%d) in %.3f s\n",
                a->output, a->mask ? ", " : "", a->mask ? a->mask : "",
                a->depth ? ", " : "", a->depth ? a->depth : "", a->normal ? ", " : "",
                a->normal ? a->normal : "", a->id ? ", " : "", a->id ? a->id : "",
                sc_framebuffer_width(fb), sc_framebuffer_height(fb), times.total);
    if (status == 0 && a->stats)
        print_stats(a, fb, &times);
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
    return status;
}

/* The render options for one frame's scene: the file's settings, then the
 * command line over them (frames.c calls it for every evaluation). */
typedef struct frame_context {
    cli_args *args;
    int argc;
    char **argv;
} frame_context;

static int frame_options(void *user, const sc_scene *scene, sc_render_options *out)
{
    frame_context *f = user;
    cli_args again;
    memset(&again, 0, sizeof again);
    again.render = 1;
    frames_job_init(&again.frames);
    sc_render_options_init(&again.options);
    sc_render_options_from_scene(&again.options, scene);
    (void)parse_args(&again, f->argc, f->argv); /* succeeded once already */
    *out = again.options;
    out->cancel = &cli_stop;
    out->want_color = 1;
    return 0;
}

/* `spancast render --animate=N` or `--turntable=N` (frames.c). */
static int run_frames(cli_args *a, int argc, char **argv)
{
    sc_error error;
    if (imgio_check(a->output, IMGIO_COLOR, &error))
        return cli_usage_error("%s", error.message);
    if (!output_writable(a->output) ||
        (a->frames.video && !output_writable(a->frames.video)))
        return EXIT_FAILED;
    cli_catch_interrupts();
    cli_start_clock();
    frame_context context = {a, argc, argv};
    a->frames.input = a->input;
    a->frames.output = a->output;
    a->frames.faithful = a->faithful;
    a->frames.quiet = a->quiet;
    a->frames.options_for = frame_options;
    a->frames.user = &context;
    int status = frames_run(&a->frames);
    cli_stop_clock();
    if (status == FRAMES_INTERRUPTED || cli_stop)
        return cli_die_stopped();
    return status;
}

/* `spancast bench NAME ...`: replaces this process with spancast-bench
 * (bench/main.c), found in the folder of this executable, with the
 * arguments after "bench". The benchmarks link the stability harness and
 * the library's internals, which the tool does not. Returns only on
 * failure, with the exit status. */
static int run_bench(char **argv)
{
    char path[4096];
    if (!file_beside_program("spancast-bench", path, sizeof path)) {
        fprintf(stderr, "spancast: error: cannot find spancast-bench: %s\n",
                strerror(errno));
        return 1;
    }
    argv[1] = path; /* spancast-bench NAME ... */
    execv(path, argv + 1);
    fprintf(stderr, "spancast: error: cannot run '%s': %s\n", path, strerror(errno));
    return 1;
}

/* `spancast render --watch`: renders, then waits for a change to the model
 * or a file it uses (watch.c) and renders again, until interrupted. A model
 * that fails to load or render prints its error and is waited on like any
 * other; the image of the last good model stays as it was. Only a bad
 * command line ends it early. */
static int run_render_watched(cli_args *a, int argc, char **argv)
{
    sc_error error;
    a->watched = watch_open(&error);
    if (!a->watched) {
        print_error(&error);
        return EXIT_FAILED;
    }
    cli_catch_interrupts();
    int status;
    for (;;) {
        status = run_render(a, argc, argv);
        cli_stop_clock();
        if (cli_stop == SIGALRM)
            cli_stop = 0; /* the time limit is per render; keep watching */
        if (status == EXIT_USAGE && !cli_stop)
            break;
        fflush(stdout);
        if (!watch_wait(a->watched, &cli_stop))
            break;
        if (!a->quiet) {
            const char *what = watch_last_change(a->watched);
            fprintf(stderr, "spancast: %s changed, rendering again\n",
                    what ? what : a->input);
        }
    }
    watch_close(a->watched);
    if (cli_stop)
        return cli_die_stopped();
    return status;
}

/* `spancast view ...`: replaces this process with spancast-view, found in
 * the folder of this executable, with the same arguments. The viewer links
 * SDL and the display libraries, which took about 20 ms to load in every
 * run of the tool. Returns only on failure, with the exit status. */
static int run_view(char **argv)
{
    char path[4096];
    if (!file_beside_program("spancast-view", path, sizeof path)) {
        fprintf(stderr, "spancast: error: cannot find spancast-view: %s\n",
                strerror(errno));
        return 1;
    }
    argv[0] = path; /* spancast-view view MODEL ... */
    execv(path, argv);
    fprintf(stderr, "spancast: error: cannot run '%s': %s\n", path, strerror(errno));
    return 1;
}

/* ---- shared with the query commands (cli.h) ---- */

void cli_slab_words(const sc_scene *scene, char *out, size_t size)
{
    double lo[3], hi[3];
    if (!sc_scene_bounds(scene, lo, hi)) {
        snprintf(out, size, "empty");
        return;
    }
    double thick = hi[2] - lo[2];
    if (thick == 1)
        snprintf(out, size, "1 unit thick (z from %g to %g), so its volume is its area",
                 lo[2], hi[2]);
    else
        snprintf(out, size,
                 "%g thick (z from %g to %g, 1e-6 of its size past 1e6 across), so its "
                 "volume is %g times its area",
                 thick, lo[2], hi[2], thick);
}

void cli_print_error(const sc_error *error)
{
    print_error(error);
}

sc_scene *cli_load(const char *path, int faithful)
{
    return load(path, faithful, NULL, NULL);
}

sc_scene *cli_load_converted(const char *path, int faithful, int *converted)
{
    return load(path, faithful, NULL, converted);
}

static int is_camera_option(opt_id id)
{
    return id == OPT_CAMERA || id == OPT_IMGSIZE || id == OPT_FOV ||
           id == OPT_PROJECTION || id == OPT_VIEWALL || id == OPT_AUTOCENTER;
}

int cli_camera_option(const char *name, size_t len)
{
    const opt_spec *spec = find_option(name, len);
    if (!spec || !is_camera_option(spec->id))
        return -1;
    return spec->takes_value != 0;
}

int cli_apply_camera_option(sc_render_options *options, const char *name, size_t len,
                            const char *value)
{
    const opt_spec *spec = find_option(name, len);
    if (!spec || !is_camera_option(spec->id))
        return cli_usage_error("unknown option '%.*s'", (int)len, name);
    cli_args a;
    memset(&a, 0, sizeof a);
    a.options = *options;
    int st = apply_option(&a, spec, value);
    if (!st)
        *options = a.options;
    return st;
}

/* Under mpirun (Open MPI's environment), every rank runs this program with
 * the same arguments: the ranks other than 0 print nothing, so that the
 * command's output and its first error come once, from rank 0, whether the
 * command shares its work (mpi_dist.c) or not, and also for an error found
 * before the ranks join the job. Returns whether this is such a rank. */
static int quiet_other_ranks(void)
{
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    const char *rank = getenv("OMPI_COMM_WORLD_RANK");
    if (!size || atoi(size) <= 1 || !rank || atoi(rank) == 0)
        return 0;
    int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        close(null);
    }
    return 1;
}

static int run(int argc, char **argv);

int main(int argc, char **argv)
{
    int other = quiet_other_ranks();
    int st = run(argc, argv);
    /* An error found before the ranks join the job (a bad command line) is
     * found by every rank, and rank 0 reports it. mpirun aborts the job as
     * soon as a rank exits with a failure, which could stop rank 0 before
     * its message is out; so the other ranks leave quietly with 0, and the
     * job's status is rank 0's. */
    return other && st && dist_size() <= 1 ? 0 : st;
}

static int run(int argc, char **argv)
{
    int limited = cli_take_max_memory(&argc, argv);
    if (limited)
        return limited;
    if (argc > 1 && !strcmp(argv[1], "view"))
        return run_view(argv); /* spancast-view reads its own --help and -D */
    /* spancast-mpi (dist_enter) reads its own -D: it gets argv whole. */
    int whole_argc = argc;
    char **whole = malloc(((size_t)argc + 1) * sizeof *whole);
    if (!whole) {
        fputs("spancast: error: out of memory\n", stderr);
        return EXIT_FAILED;
    }
    memcpy(whole, argv, ((size_t)argc + 1) * sizeof *whole);
    int defined = scad_take_defines(&argc, argv);
    if (defined) {
        free(whole);
        return defined;
    }
    for (int k = 1; k < argc && strcmp(argv[k], "--"); k++) {
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            free(whole);
            cli_print_help(stdout, k > 1 ? argv[1] : NULL);
            return 0;
        }
        if (!strcmp(argv[k], "--version")) {
            free(whole);
            printf("spancast %s\nmpi: %s\n", SPANCAST_VERSION_STRING,
                   SPANCAST_MPI_SUPPORT);
            return 0;
        }
    }
    if (argc < 2) {
        free(whole);
        return cli_usage_error("missing command (try 'spancast --help')");
    }
    const char *command = argv[1];
    if (!strcmp(command, "render") || !strcmp(command, "batch") ||
        !strcmp(command, "measure") || !strcmp(command, "overlaps") ||
        !strcmp(command, "compare")) {
        int st = dist_enter(whole_argc, whole); /* under mpirun: spancast-mpi */
        if (st >= 0) {
            free(whole);
            return st;
        }
    }
    free(whole);
    if (!strcmp(command, "batch"))
        return cli_batch(argc, argv);
    if (!strcmp(command, "bench"))
        return run_bench(argv);
    if (!strcmp(command, "spans"))
        return cli_spans(argc, argv);
    if (!strcmp(command, "inside"))
        return cli_inside(argc, argv);
    if (!strcmp(command, "measure"))
        return cli_measure(argc, argv);
    if (!strcmp(command, "overlaps"))
        return cli_overlaps(argc, argv);
    if (!strcmp(command, "compare"))
        return cli_compare(argc, argv);
    cli_args a;
    memset(&a, 0, sizeof a);
    sc_render_options_init(&a.options);
    frames_job_init(&a.frames);
    if (!strcmp(command, "render"))
        a.render = 1;
    else if (!strcmp(command, "info"))
        a.render = 0;
    else if (command[0] == '-')
        return cli_usage_error("missing command before '%s' (try 'spancast --help')",
                               command);
    else
        return cli_usage_error(
            "unknown command '%s' (expected 'render', 'info', "
            "'spans', 'inside', 'measure', 'overlaps', 'compare', 'view', 'batch' or "
            "'bench')",
            command);
    int st = parse_args(&a, argc, argv);
    if (st)
        return st;
    if (a.render && a.watch && dist_size() > 1)
        return cli_usage_error("--watch does not run under mpirun");
    if (a.render && a.watch)
        return run_render_watched(&a, argc, argv);
    if (a.render && (a.frames.animate || a.frames.turntable))
        return run_frames(&a, argc, argv);
    return a.render ? run_render(&a, argc, argv) : run_info(&a);
}
