/* The checking commands: `spancast measure`, `spancast overlaps` and
 * `spancast compare`.
 *
 *   spancast measure MODEL [--tolerance=REL] [--density=D] [common options]
 *   spancast overlaps MODEL [--min-volume=V] [--tolerance=REL] [common options]
 *   spancast compare A B [--tolerance=REL] [--max-pixels=N] [--diff=PREFIX]
 *                        [--imgsize=W,H] [common options]
 *   common options: --threads=N --json --faithful -q/--quiet
 *
 * `measure` prints the mass properties of sc_scene_measure, each value
 * with its error bound. `overlaps` prints every pair of top-level objects
 * whose interiors overlap (sc_objects_overlaps). `compare` integrates the
 * symmetric difference of two solids (sc_scene_compare) and renders masks
 * and depths of both from seven views, the six along the axes and one along
 * the diagonal, all orthographic on one camera per view that frames both
 * models, and counts the pixels where they disagree away from silhouette
 * edges (a pixel whose neighbours differ in either mask is an edge pixel:
 * there a sub-pixel shift of an edge changes the mask). B may be a mesh
 * (.stl, .off, .amf or .3mf), loaded as an import.
 *
 * Under `mpirun -np N` every rank loads the models (a model's text comes
 * from rank 0, dist.h; a mesh or the objects of overlaps each rank reads
 * itself) and casts its share of the lines (dist_share_lines); rank 0
 * prints the results, which are those of one process to the last digit,
 * and renders compare's views alone.
 *
 * Exit status: measure as render (0, 1 when the model does not load, 2 for
 * a bad command line); overlaps and compare as diff: 0 no overlap above
 * --min-volume / the same within the tolerances, 1 an overlap / different,
 * 2 any error.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "build/build_mesh.h" /* a mesh file's rounding */
#include "cli/cli.h"
#include "cli/dist.h"
#include "cli/scad.h"
#include "formats/framebuffer.h" /* the difference image is a framebuffer of its own */
#include "spancast/spancast.h"

enum { MEASURE = 1, OVERLAPS = 2, COMPARE = 4, ALL = 7 };

typedef struct check_args {
    int command;
    const char *inputs[2];
    int input_count;
    int json, faithful, quiet;
    sc_measure_options options;
    double min_volume;
    long max_pixels;
    const char *diff;
    int width, height;
} check_args;

typedef struct check_option {
    const char *name;
    int takes_value;
    int commands;
} check_option;

static const check_option check_options[] = {
    {"--tolerance", 1, ALL},      {"--threads", 1, ALL},
    {"--json", 0, ALL},           {"--faithful", 0, ALL},
    {"--strict", 0, ALL},         {"--quiet", 0, ALL},
    {"--density", 1, MEASURE},    {"--min-volume", 1, OVERLAPS},
    {"--max-pixels", 1, COMPARE}, {"--diff", 1, COMPARE},
    {"--imgsize", 1, COMPARE},    {"--max-time", 1, ALL},
};

static const char *command_name(int command)
{
    return command == MEASURE ? "measure" : command == OVERLAPS ? "overlaps" : "compare";
}

/* A library call failed: the interrupt or time limit that stopped it, or
 * its error and status. */
static int call_failed(const sc_error *error, int status)
{
    if (cli_stop)
        return cli_die_stopped();
    cli_print_error(error);
    return status;
}

static int apply_check_option(check_args *a, const char *name, const char *value)
{
    double v;
    if (cli_output_flag(name, &a->json, &a->faithful))
        return 0;
    if (!strcmp(name, "--quiet")) {
        a->quiet = 1;
    } else if (!strcmp(name, "--tolerance")) {
        if (!cli_parse_number(value, &v) || !(v > 0 && v < 1))
            return cli_usage_error(
                "--tolerance expects a relative error between 0 and 1");
        a->options.tolerance = v;
    } else if (!strcmp(name, "--threads")) {
        if (!cli_parse_number(value, &v) || v != floor(v) || v < 0 || v > 4096)
            return cli_usage_error("--threads expects a non-negative integer (0: all "
                                   "cores)");
        a->options.threads = cli_load_threads = (int)v;
    } else if (!strcmp(name, "--density")) {
        if (!cli_parse_number(value, &v) || !(v > 0))
            return cli_usage_error("--density expects a positive number");
        a->options.density = v;
    } else if (!strcmp(name, "--min-volume")) {
        if (!cli_parse_number(value, &v) || v < 0)
            return cli_usage_error("--min-volume expects a non-negative volume");
        a->min_volume = v;
    } else if (!strcmp(name, "--max-pixels")) {
        if (!cli_parse_number(value, &v) || v != floor(v) || v < 0 || v > 1e12)
            return cli_usage_error("--max-pixels expects a non-negative integer");
        a->max_pixels = (long)v;
    } else if (!strcmp(name, "--diff")) {
        a->diff = value;
    } else if (!strcmp(name, "--max-time")) {
        return cli_parse_max_time(value);
    } else if (!strcmp(name, "--imgsize")) {
        double wh[2];
        if (cli_parse_numbers(value, wh, 2) != 2 || wh[0] != floor(wh[0]) ||
            wh[1] != floor(wh[1]) || wh[0] < 1 || wh[1] < 1 || wh[0] > 8192 ||
            wh[1] > 8192)
            return cli_usage_error("--imgsize expects W,H with integers from 1 to 8192");
        a->width = (int)wh[0];
        a->height = (int)wh[1];
    }
    return 0;
}

static int parse_check_args(check_args *a, int argc, char **argv)
{
    int wanted = a->command == COMPARE ? 2 : 1;
    int k = 1, only_files = 0, operand;
    const char *arg;
    while ((arg = cli_next_arg(argc, argv, &k, &only_files, &operand))) {
        if (operand) {
            if (a->input_count == wanted)
                return cli_usage_error("unexpected argument '%s'", arg);
            a->inputs[a->input_count++] = arg;
            continue;
        }
        if (!strcmp(arg, "-q"))
            arg = "--quiet";
        size_t len;
        int st = cli_option_name(arg, &len);
        if (st)
            return st;
        const check_option *spec =
            cli_find_option(check_options, sizeof check_options / sizeof check_options[0],
                            sizeof check_options[0], arg, len);
        if (!spec)
            return cli_usage_error("unknown option '%.*s'", (int)len, arg);
        if (!(spec->commands & a->command))
            return cli_usage_error("option '%.*s' does not apply to '%s'", (int)len, arg,
                                   command_name(a->command));
        const char *value;
        st = cli_option_value(argc, argv, &k, arg, len, spec->takes_value, &value);
        if (st)
            return st;
        st = apply_check_option(a, spec->name, value);
        if (st)
            return st;
    }
    if (a->input_count < wanted)
        return cli_usage_error(wanted == 2 ? "compare expects two models: A B"
                                           : "missing input file");
    return 0;
}

/* ---- progress ---- */

typedef struct progress_line {
    int shown; /* last percentage drawn, -1 before the first */
    const char *what;
} progress_line;

static void draw_progress(void *user, double fraction)
{
    progress_line *p = user;
    int percent = (int)(fraction * 100);
    if (percent == p->shown)
        return;
    p->shown = percent;
    fprintf(stderr, "\rspancast: %s %3d%%", p->what, percent);
    if (percent >= 100)
        fputc('\n', stderr);
    fflush(stderr);
}

static void start_progress(check_args *a, progress_line *line, const char *what)
{
    line->shown = -1;
    line->what = what;
    if (!a->quiet && isatty(STDERR_FILENO)) {
        a->options.progress = draw_progress;
        a->options.progress_user = line;
    }
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* ---- output ---- */

static void json_estimate(const char *name, sc_estimate e)
{
    printf("\"%s\": {\"value\": %.17g, \"error\": %.17g}", name, e.value, e.error);
}

/* "name": [...] of n estimates; without the name when name is NULL. */
static void json_estimates(const char *name, const sc_estimate *e, int n)
{
    if (name)
        printf("\"%s\": ", name);
    putchar('[');
    for (int k = 0; k < n; k++)
        printf("%s{\"value\": %.17g, \"error\": %.17g}", k ? ", " : "", e[k].value,
               e[k].error);
    putchar(']');
}

static void text_estimate(const char *label, sc_estimate e)
{
    printf("%-18s %.10g +- %.2g\n", label, e.value, e.error);
}

static void text_estimates(const char *label, const sc_estimate *e)
{
    printf("%-18s (%.10g, %.10g, %.10g) +- (%.2g, %.2g, %.2g)\n", label, e[0].value + 0.0,
           e[1].value + 0.0, e[2].value + 0.0, e[0].error, e[1].error, e[2].error);
}

static void print_measure(const check_args *a, const sc_measure *m)
{
    if (a->json) {
        putchar('{');
        json_estimate("volume", m->volume);
        fputs(", ", stdout);
        json_estimate("area", m->area);
        fputs(", ", stdout);
        json_estimate("mass", m->mass);
        printf(", \"density\": %.17g, ", a->options.density);
        json_estimates("centroid", m->centroid, 3);
        fputs(",\n \"inertia\": [", stdout);
        for (int i = 0; i < 3; i++) {
            fputs(i ? ", " : "", stdout);
            json_estimates(NULL, m->inertia[i], 3);
        }
        fputs("],\n ", stdout);
        json_estimates("principal_moments", m->principal, 3);
        fputs(", \"principal_axes\": [", stdout);
        for (int i = 0; i < 3; i++)
            printf("%s[%.17g, %.17g, %.17g]", i ? ", " : "", m->axes[i][0], m->axes[i][1],
                   m->axes[i][2]);
        fputs("],\n ", stdout);
        json_estimates("box_min", m->box_lo, 3);
        fputs(", ", stdout);
        json_estimates("box_max", m->box_hi, 3);
        printf(",\n \"volume_by_axis\": [%.17g, %.17g, %.17g], \"lines\": %llu, "
               "\"converged\": %s, \"tolerance\": %.17g}\n",
               m->volume_by_axis[0], m->volume_by_axis[1], m->volume_by_axis[2],
               (unsigned long long)m->lines, m->converged ? "true" : "false",
               a->options.tolerance);
        return;
    }
    text_estimate("volume", m->volume);
    text_estimate("area", m->area);
    if (a->options.density != 1) {
        char label[64];
        snprintf(label, sizeof label, "mass (density %g)", a->options.density);
        text_estimate(label, m->mass);
    }
    text_estimates("centroid", m->centroid);
    printf("inertia about the centroid%s:\n",
           a->options.density != 1 ? "" : " (unit density)");
    for (int i = 0; i < 3; i++)
        text_estimates("", m->inertia[i]);
    printf("%-18s %.10g, %.10g, %.10g +- %.2g\n", "principal moments",
           m->principal[0].value, m->principal[1].value, m->principal[2].value,
           m->principal[0].error);
    printf("%-18s (%.6f, %.6f, %.6f) (%.6f, %.6f, %.6f) (%.6f, %.6f, %.6f)\n",
           "principal axes", m->axes[0][0], m->axes[0][1], m->axes[0][2], m->axes[1][0],
           m->axes[1][1], m->axes[1][2], m->axes[2][0], m->axes[2][1], m->axes[2][2]);
    text_estimates("box min", m->box_lo);
    text_estimates("box max", m->box_hi);
    printf("volume by axis     x %.10g, y %.10g, z %.10g\n", m->volume_by_axis[0],
           m->volume_by_axis[1], m->volume_by_axis[2]);
    printf("lines              %llu, tolerance %g%s\n", (unsigned long long)m->lines,
           a->options.tolerance,
           m->converged ? "" : " (not reached: the line budget ran out)");
}

/* ---- measure ---- */

static int run_measure(check_args *a)
{
    sc_scene *scene = cli_load(a->inputs[0], a->faithful);
    if (!scene)
        return cli_stop ? cli_die_stopped() : CLI_EXIT_FAILED;
    progress_line line;
    start_progress(a, &line, "measuring");
    double t0 = seconds_now();
    sc_measure m;
    sc_measure_init(&m);
    sc_error error;
    sc_status st = sc_scene_measure(scene, &a->options, &m, &error);
    sc_scene_info info;
    sc_scene_info_init(&info);
    sc_scene_get_info(scene, &info, NULL);
    char slab[160] = "";
    if (info.flat_2d)
        cli_slab_words(scene, slab, sizeof slab);
    sc_scene_release(scene);
    /* the numbers below are the slab's: say so, quiet or not */
    if (st == SC_OK && info.flat_2d)
        fprintf(
            stderr,
            "spancast: note: %s is a 2D model, measured as the slab OpenSCAD's preview "
            "draws it: %s\n",
            a->inputs[0], slab);
    if (st)
        return call_failed(&error,
                           st == SC_ERR_ARGUMENT ? CLI_EXIT_USAGE : CLI_EXIT_FAILED);
    print_measure(a, &m);
    if (!a->quiet)
        fprintf(stderr, "spancast: measured %s in %.2f s (%d threads)\n", a->inputs[0],
                seconds_now() - t0, m.threads);
    return 0;
}

/* ---- overlaps ---- */

/* Under mpirun, whether every rank loaded path (a file each rank reads
 * itself), ok saying whether this one did; the same answer on every rank.
 * Rank 0 says so when only another rank failed. */
static int loaded_everywhere(int ok, const char *path)
{
    int failed = dist_agree(!ok);
    if (failed && ok)
        fprintf(stderr,
                "spancast: error: cannot load '%s' on every rank of the MPI job (a "
                "rank reads it itself: is it where every rank can see it?)\n",
                path);
    return !failed;
}

/* Where an object is written, as overlaps prints it: file:line:col, or,
 * for a model OpenSCAD converted (source: the file the user named), the
 * source with the line of OpenSCAD's export the object is on (scad_blame's
 * form: the export is not the user's text). */
static void object_place(char *out, size_t size, sc_location at, const char *source)
{
    if (source)
        snprintf(out, size, "%s (line %d of OpenSCAD's export)", source, at.line);
    else
        snprintf(out, size, "%s:%d:%d", at.file, at.line, at.column);
}

static int run_overlaps(check_args *a)
{
    const char *path = a->inputs[0];
    sc_load_options lo;
    sc_load_options_init(&lo);
    cli_load_options(&lo, a->faithful);
    sc_objects *objects = NULL;
    sc_error error;
    /* A .scad (or a .csg in OpenSCAD's language) is converted by each rank
     * under mpirun; the load itself cannot be stopped from inside
     * (stop.c). */
    scad_stop stop = {&cli_stop, cli_loading_flag()};
    int converted = 0;
    sc_status loaded = scad_load_objects(path, &lo, &objects, &error, &stop, &converted);
    int everywhere = loaded_everywhere(loaded == SC_OK, path);
    if (loaded != SC_OK)
        return call_failed(&error, CLI_EXIT_USAGE);
    if (!everywhere) {
        sc_objects_release(objects);
        return CLI_EXIT_USAGE;
    }
    progress_line line;
    start_progress(a, &line, "checking pairs");
    double t0 = seconds_now();
    sc_overlap_list *pairs = NULL;
    if (sc_objects_overlaps(objects, &a->options, &pairs, &error) != SC_OK) {
        sc_objects_release(objects);
        return call_failed(&error, CLI_EXIT_USAGE);
    }
    size_t objects_count = sc_objects_count(objects), above = 0;
    size_t count = sc_overlap_list_count(pairs);
    if (a->json)
        printf("{\"objects\": %zu, \"overlaps\": [", objects_count);
    else
        printf("%zu top-level objects\n", objects_count);
    for (size_t k = 0; k < count; k++) {
        const sc_overlap *p = sc_overlap_list_get(pairs, k);
        sc_location la = sc_objects_location(objects, p->a);
        sc_location lb = sc_objects_location(objects, p->b);
        const char *na = sc_objects_name(objects, p->a),
                   *nb = sc_objects_name(objects, p->b);
        above += p->volume.value > a->min_volume;
        if (a->json) {
            printf("%s\n  {\"a\": {\"index\": %zu, \"node\": \"%s\", \"line\": %d, "
                   "\"column\": %d}, \"b\": {\"index\": %zu, \"node\": \"%s\", \"line\": "
                   "%d, \"column\": %d}, ",
                   k ? "," : "", p->a + 1, na, la.line, la.column, p->b + 1, nb, lb.line,
                   lb.column);
            json_estimate("volume", p->volume);
            printf(", \"box_min\": [%.17g, %.17g, %.17g], \"box_max\": [%.17g, %.17g, "
                   "%.17g], \"converged\": %s}",
                   p->box_lo[0], p->box_lo[1], p->box_lo[2], p->box_hi[0], p->box_hi[1],
                   p->box_hi[2], p->converged ? "true" : "false");
        } else {
            char wa[PATH_MAX + 64], wb[PATH_MAX + 64];
            object_place(wa, sizeof wa, la, converted ? path : NULL);
            object_place(wb, sizeof wb, lb, converted ? path : NULL);
            printf(
                "overlap: %s (%s, object %zu) and %s (%s, object %zu): "
                "volume %.8g +- %.2g%s, box (%.6g, %.6g, %.6g) to (%.6g, %.6g, %.6g)\n",
                wa, na, p->a + 1, wb, nb, p->b + 1, p->volume.value, p->volume.error,
                p->converged ? "" : " (tolerance not reached: the line budget ran out)",
                p->box_lo[0], p->box_lo[1], p->box_lo[2], p->box_hi[0], p->box_hi[1],
                p->box_hi[2]);
        }
    }
    if (a->json)
        printf("%s], \"above_min_volume\": %zu}\n", count ? "\n" : "", above);
    else if (!count)
        puts("no overlaps");
    if (!a->quiet)
        fprintf(stderr, "spancast: checked %zu pairs in %.2f s\n",
                objects_count * (objects_count - (objects_count > 0)) / 2,
                seconds_now() - t0);
    sc_overlap_list_release(pairs);
    sc_objects_release(objects);
    return above ? 1 : 0;
}

/* ---- compare ---- */

static sc_scene *load_any(const char *path, int faithful)
{
    if (!scad_is_mesh(path))
        return cli_load(path, faithful);
    sc_load_options lo;
    sc_load_options_init(&lo);
    cli_load_options(&lo, faithful);
    sc_scene *scene = NULL;
    sc_error error;
    cli_loading(1); /* cannot be stopped from inside: stop.c */
    sc_status st = sc_scene_load_mesh(path, &lo, &scene, &error);
    cli_loading(0);
    if (st != SC_OK && !cli_stop)
        cli_print_error(&error);
    if (!loaded_everywhere(st == SC_OK, path)) {
        sc_scene_release(scene);
        return NULL;
    }
    return scene;
}

/* One view of the comparison: a direction the camera looks along. */
typedef struct view {
    const char *name; /* where the eye is */
    const char *file; /* the diff image's suffix */
    double dir[3];    /* the direction it looks along */
} view;

static const view views[] = {
    {"+x", "px", {-1, 0, 0}},
    {"-x", "nx", {1, 0, 0}},
    {"+y", "py", {0, -1, 0}},
    {"-y", "ny", {0, 1, 0}},
    {"+z", "pz", {0, 0, -1}},
    {"-z", "nz", {0, 0, 1}},
    {"diagonal", "diagonal", {-1, -1, -1}},
};

typedef struct view_result {
    long mask_mismatch; /* away from silhouette edges */
    long depth_mismatch;
    long edge_mismatch; /* at edges, reported only */
} view_result;

/* 1 when pixel (x, y) or one of its 8 neighbours differs from it in mask m. */
static int at_edge(const uint8_t *m, int w, int h, int x, int y)
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                continue;
            if (m[(size_t)ny * (size_t)w + (size_t)nx] !=
                m[(size_t)y * (size_t)w + (size_t)x])
                return 1;
        }
    return 0;
}

/* Renders both scenes from view v and counts the mismatches; writes the
 * diff image when a->diff is set. Returns 0 or an exit status. */
static int compare_view(const check_args *a, const sc_scene *sa, const sc_scene *sb,
                        const double lo[3], const double hi[3], const view *v,
                        view_result *out)
{
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = a->width;
    o.height = a->height;
    o.threads = a->options.threads;
    o.want_color = 0;
    o.want_mask = o.want_depth = o.want_normal = 1;
    o.projection = SC_PROJECTION_ORTHOGRAPHIC;
    o.camera_mode = SC_CAMERA_VECTOR;
    double centre[3], radius = 0, len = 0;
    for (int i = 0; i < 3; i++) {
        centre[i] = (lo[i] + hi[i]) / 2;
        radius += (hi[i] - lo[i]) * (hi[i] - lo[i]) / 4;
        len += v->dir[i] * v->dir[i];
    }
    radius = sqrt(radius);
    len = sqrt(len);
    /* The orthographic image is a tan(fov / 2) * distance high (half); the
     * eye stands far enough for the whole sphere around both boxes. */
    double aspect = (double)a->width / a->height;
    double distance =
        1.05 * radius /
        (tan(o.fov_deg / 2 * (3.14159265358979323846 / 180)) * fmin(1, aspect));
    for (int i = 0; i < 3; i++) {
        o.camera[i] = centre[i] - v->dir[i] / len * distance;
        o.camera[3 + i] = centre[i];
    }
    sc_framebuffer *fa = NULL, *fb = NULL;
    sc_error error;
    o.cancel = &cli_stop;
    if (sc_render(sa, &o, &fa, &error) != SC_OK ||
        sc_render(sb, &o, &fb, &error) != SC_OK) {
        sc_framebuffer_release(fa);
        return call_failed(&error, CLI_EXIT_USAGE);
    }
    int w = a->width, h = a->height;
    /* A uniform shift d of the surface changes the volume by d times the
     * area, about d / size of it: the volume's relative tolerance read as
     * a distance is that tolerance times the size. */
    double depth_tolerance = a->options.tolerance * 2 * radius;
    float *diff = a->diff ? calloc((size_t)w * (size_t)h * 3, sizeof *diff) : NULL;
    memset(out, 0, sizeof *out);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t p = (size_t)y * (size_t)w + (size_t)x;
            int ha = fa->mask[p] != 0, hb = fb->mask[p] != 0;
            int edge = at_edge(fa->mask, w, h, x, y) || at_edge(fb->mask, w, h, x, y);
            /* The distance between the surfaces along A's normal: a wall
             * seen at a grazing angle moves far in depth for a small shift. */
            const float *n = fa->normal + p * 3;
            double facing =
                fabs(n[0] * v->dir[0] + n[1] * v->dir[1] + n[2] * v->dir[2]) / len;
            int depth_off =
                ha && hb &&
                fabs((double)fa->depth[p] - fb->depth[p]) * facing > depth_tolerance;
            if (ha != hb)
                *(edge ? &out->edge_mismatch : &out->mask_mismatch) += 1;
            else if (depth_off && !edge)
                out->depth_mismatch++;
            if (diff) {
                float *c = diff + p * 3;
                /* white: neither; grey: both; red: only A; blue: only B;
                 * magenta: both, at different depths. */
                float r = 1, g = 1, b = 1;
                if (ha && hb && !depth_off)
                    r = g = b = 0.5f;
                else if (ha && hb)
                    r = 1, g = 0, b = 1;
                else if (ha)
                    r = 1, g = 0, b = 0;
                else if (hb)
                    r = 0, g = 0, b = 1;
                c[0] = r, c[1] = g, c[2] = b;
            }
        }
    int status = 0;
    if (a->diff) {
        char path[4096];
        snprintf(path, sizeof path, "%s%s.png", a->diff, v->file);
        sc_framebuffer image = *fa;
        image.color = diff;
        image.depth = NULL;
        image.normal = NULL;
        image.id = NULL;
        if (!diff || sc_framebuffer_write_color(&image, path, &error) != SC_OK) {
            if (diff)
                cli_print_error(&error);
            else
                fputs("spancast: error: out of memory\n", stderr);
            status = CLI_EXIT_USAGE;
        }
    }
    free(diff);
    sc_framebuffer_release(fa);
    sc_framebuffer_release(fb);
    return status;
}

static int run_compare(check_args *a)
{
    sc_scene *sa = load_any(a->inputs[0], a->faithful);
    if (!sa)
        return cli_stop ? cli_die_stopped() : CLI_EXIT_USAGE;
    sc_scene *sb = load_any(a->inputs[1], a->faithful);
    if (!sb) {
        sc_scene_release(sa);
        return cli_stop ? cli_die_stopped() : CLI_EXIT_USAGE;
    }
    progress_line line;
    start_progress(a, &line, "comparing volumes");
    double t0 = seconds_now();
    sc_comparison c;
    sc_comparison_init(&c);
    sc_error error;
    if (sc_scene_compare(sa, sb, &a->options, &c, &error) != SC_OK) {
        sc_scene_release(sa);
        sc_scene_release(sb);
        return call_failed(&error, CLI_EXIT_USAGE);
    }
    double lo[3], hi[3], lo2[3], hi2[3];
    int has_a = sc_scene_bounds(sa, lo, hi), has_b = sc_scene_bounds(sb, lo2, hi2);
    for (int i = 0; i < 3; i++)
        if (!has_a || (has_b && lo2[i] < lo[i]))
            lo[i] = lo2[i];
    for (int i = 0; i < 3; i++)
        if (!has_a || (has_b && hi2[i] > hi[i]))
            hi[i] = hi2[i];
    double larger = fmax(fabs(c.volume_a.value), fabs(c.volume_b.value));
    int different = c.difference.value > a->options.tolerance * larger;
    /* Where the volumes alone differ, how much of it a mesh file's
     * rounding can account for (OpenSCAD's ASCII STL writes 6
     * significant digits): said when it can account for all of it. */
    build_mesh_rounding_info rounding[2];
    int rounded[2] = {0, 0};
    double rounding_volume = 0;
    for (int k = 0; k < 2 && different; k++) {
        rounded[k] =
            scad_is_mesh(a->inputs[k]) && build_mesh_rounding(a->inputs[k], &rounding[k]);
        rounding_volume += rounded[k] ? rounding[k].volume : 0;
    }
    int explained = different && rounding_volume >= c.difference.value;
    view_result results[sizeof views / sizeof views[0]];
    int status = 0;
    /* the views: rank 0's alone (under mpirun), which prints them */
    size_t view_count =
        (has_a || has_b) && dist_rank() == 0 ? sizeof views / sizeof views[0] : 0;
    for (size_t k = 0; k < view_count && !status; k++) {
        status = compare_view(a, sa, sb, lo, hi, &views[k], &results[k]);
        different |= results[k].mask_mismatch > a->max_pixels ||
                     results[k].depth_mismatch > a->max_pixels;
    }
    sc_scene_release(sa);
    sc_scene_release(sb);
    if (status)
        return status;
    if (a->json) {
        putchar('{');
        json_estimate("volume_a", c.volume_a);
        fputs(", ", stdout);
        json_estimate("volume_b", c.volume_b);
        fputs(",\n ", stdout);
        json_estimate("only_a", c.only_a);
        fputs(", ", stdout);
        json_estimate("only_b", c.only_b);
        fputs(", ", stdout);
        json_estimate("symmetric_difference", c.difference);
        printf(",\n \"relative_difference\": %.17g, \"tolerance\": %.17g, \"converged\": "
               "%s, \"lines\": %llu, \"views\": [",
               larger > 0 ? c.difference.value / larger : 0, a->options.tolerance,
               c.converged ? "true" : "false", (unsigned long long)c.lines);
        for (size_t k = 0; k < view_count; k++)
            printf("%s\n  {\"view\": \"%s\", \"mask_mismatch\": %ld, \"depth_mismatch\": "
                   "%ld, \"edge_mismatch\": %ld}",
                   k ? "," : "", views[k].name, results[k].mask_mismatch,
                   results[k].depth_mismatch, results[k].edge_mismatch);
        printf("], \"rounding\": %.17g, \"same\": %s}\n", rounding_volume,
               different ? "false" : "true");
    } else {
        text_estimate("volume A", c.volume_a);
        text_estimate("volume B", c.volume_b);
        text_estimate("A not B", c.only_a);
        text_estimate("B not A", c.only_b);
        printf("%-18s %.10g +- %.2g (%.3g of the larger volume, tolerance %g%s)\n",
               "symmetric diff", c.difference.value, c.difference.error,
               larger > 0 ? c.difference.value / larger : 0, a->options.tolerance,
               c.converged ? "" : "; not reached: the line budget ran out");
        printf("views %dx%d, pixels that differ (mask away from edges, depth away from "
               "edges, mask at edges):\n",
               a->width, a->height);
        for (size_t k = 0; k < view_count; k++)
            printf("  %-9s %ld %ld %ld\n", views[k].name, results[k].mask_mismatch,
                   results[k].depth_mismatch, results[k].edge_mismatch);
        puts(different ? "different" : "same");
    }
    for (int k = 0; k < 2 && explained; k++) {
        if (!rounded[k])
            continue;
        char written[64];
        if (rounding[k].digits)
            snprintf(written, sizeof written, "to %d significant digits",
                     rounding[k].digits);
        else
            snprintf(written, sizeof written, "as floats (binary STL)");
        fprintf(
            stderr,
            "spancast: note: '%s' gives its coordinates %s: its surface may lie up to "
            "%.2g from the one it was written from, which can account for a "
            "difference of up to %.3g (%.3g of the larger volume)\n",
            a->inputs[k], written, rounding[k].offset, rounding[k].volume,
            larger > 0 ? rounding[k].volume / larger : 0);
    }
    if (!a->quiet)
        fprintf(stderr, "spancast: compared in %.2f s (%llu lines)\n", seconds_now() - t0,
                (unsigned long long)c.lines);
    return different ? 1 : 0;
}

static int run_check(int command, int argc, char **argv)
{
    check_args a;
    memset(&a, 0, sizeof a);
    a.command = command;
    sc_measure_options_init(&a.options);
    /* An overlap is a thin sliver more often than not, whose volume to 1e-4
     * of itself costs a minute; a thousandth says how much interferes. */
    if (command == OVERLAPS)
        a.options.tolerance = 1e-3;
    if (command == COMPARE)
        a.options.tolerance = 1e-6;
    a.width = a.height = 256;
    int status = parse_check_args(&a, argc, argv);
    if (status)
        return status;
    cli_catch_interrupts();
    cli_start_clock();
    a.options.cancel = &cli_stop;
    dist_share_lines(&a.options);
    status = command == MEASURE    ? run_measure(&a)
             : command == OVERLAPS ? run_overlaps(&a)
                                   : run_compare(&a);
    status = dist_agree(status); /* rank 0's verdict on compare's views */
    if (fflush(stdout) != 0 && !status) {
        fprintf(stderr, "spancast: error: cannot write the output: %s\n",
                strerror(errno));
        status = command == MEASURE ? CLI_EXIT_FAILED : CLI_EXIT_USAGE;
    }
    return status;
}

int cli_measure(int argc, char **argv)
{
    return run_check(MEASURE, argc, argv);
}

int cli_overlaps(int argc, char **argv)
{
    return run_check(OVERLAPS, argc, argv);
}

int cli_compare(int argc, char **argv)
{
    return run_check(COMPARE, argc, argv);
}
