/* The query commands: `spancast spans` and `spancast inside`.
 *
 *   spancast spans MODEL (--ray=OX,OY,OZ,DX,DY,DZ | --rays=FILE | --pixel=I,J)...
 *                  [--both-ways] [--json] [--faithful] [render's camera options]
 *   spancast inside MODEL (--point=X,Y,Z | --points=FILE)... [--json] [--faithful]
 *
 * `spans` prints, for each ray in command-line order, every interval of it
 * inside the solid (sc_scene_spans), like BRL-CAD's nirt: for both ends the
 * ray parameter t (in units of the direction given, not normalised), the
 * point, the leaf with its source position, the outward normal of the
 * solid and whether the surface is a subtracted one; then the distance
 * inside, (t_out - t_in) |d|. --pixel=I,J asks the library for the ray
 * `render` shoots through that pixel's centre with the same camera options
 * (sc_scene_pixel_ray), so its first span's t |d| is the pixel's depth.
 * `inside` prints in, out or on for each point (sc_scene_inside).
 *
 * A FILE holds one ray (6 numbers) or one point (3 numbers) a line,
 * separated by spaces, tabs or commas; blank lines and lines starting with
 * '#' are skipped. The command line and those files are read before the
 * model is loaded, so a typo costs no load time: a bad option is
 * "spancast: error: ...", a bad line "FILE:LINE: error: ...", both exit 2;
 * a model that does not load exits 1.
 *
 * JSON is written by the small writer below rather than a library: the
 * documents are flat, their only strings are file and kind names (escaped
 * per RFC 8259: quote, backslash and control characters), and numbers must
 * be printed with %.17g so that they read back as the same doubles, which
 * is exactly what a writer of a few lines does. Non-finite numbers (an end
 * of an unbounded solid) are null.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/scad.h"
#include "spancast/spancast.h"

/* ---- what to query ---- */

typedef struct query_item {
    double v[6]; /* ray: origin, direction; point: x, y, z */
    int pixel;   /* 1: a --pixel; v is filled after loading */
    int i, j;    /* the pixel */
} query_item;

typedef struct query_args {
    int spans; /* 1: spans, 0: inside */
    const char *input;
    int json, both_ways, faithful;
    query_item *items;
    size_t count, cap;
    const char *camera_args[64]; /* render's camera options, as given (argv) */
    const char *camera_values[64];
    int camera_count;
    /* a model OpenSCAD converted: its positions name export (the name of
     * its export, scad_converted_name), which is not the user's text, so
     * they are put on the input as scad_blame puts messages; "" otherwise */
    char export[PATH_MAX + 16];
} query_args;

/* Whether a span end is at a position in OpenSCAD's export of the input. */
static int in_export(const query_args *a, const sc_span_end *e)
{
    return a->export[0] && e->location.file && strcmp(e->location.file, a->export) == 0;
}

/* Whether e's leaf is the mesh file given as the model, whose position is
 * in the one-line model that imports it: no place in the file. */
static int in_mesh_model(const query_args *a, const sc_span_end *e)
{
    return scad_is_mesh(a->input) && e->location.file &&
           strcmp(e->location.file, a->input) == 0;
}

static int add_item(query_args *a, const query_item *item)
{
    if (a->count == a->cap) {
        size_t cap = a->cap ? a->cap * 2 : 16;
        query_item *p = cap > a->cap && cap < SIZE_MAX / sizeof *p
                            ? realloc(a->items, cap * sizeof *p)
                            : NULL;
        if (!p) {
            fputs("spancast: error: out of memory\n", stderr);
            return CLI_EXIT_FAILED;
        }
        a->items = p;
        a->cap = cap;
    }
    a->items[a->count++] = *item;
    return 0;
}

static int direction_zero(const double *d)
{
    return d[0] == 0 && d[1] == 0 && d[2] == 0;
}

/* Reads FILE: `want` numbers a line. Returns 0 or an exit status. */
static int read_items(query_args *a, const char *path, int want)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return cli_usage_error("cannot open '%s': %s", path, strerror(errno));
    char *line = NULL;
    size_t line_cap = 0;
    long number = 0;
    int status = 0;
    while (!status && getline(&line, &line_cap, f) >= 0) {
        number++;
        query_item item;
        memset(&item, 0, sizeof item);
        int n = 0;
        char *save = NULL;
        for (char *field = strtok_r(line, " \t,\r\n", &save); field;
             field = strtok_r(NULL, " \t,\r\n", &save)) {
            if (n == 0 && field[0] == '#')
                break;
            double v;
            if (!cli_parse_number(field, &v)) {
                fprintf(stderr, "%s:%ld: error: '%s' is not a finite number\n", path,
                        number, field);
                status = CLI_EXIT_USAGE;
                break;
            }
            if (n < 6)
                item.v[n] = v;
            n++;
        }
        if (status || n == 0)
            continue;
        if (n != want) {
            fprintf(stderr, "%s:%ld: error: expected %d numbers (%s), got %d\n", path,
                    number, want, want == 6 ? "origin, direction" : "x, y, z", n);
            status = CLI_EXIT_USAGE;
        } else if (want == 6 && direction_zero(item.v + 3)) {
            fprintf(stderr, "%s:%ld: error: ray direction must not be zero\n", path,
                    number);
            status = CLI_EXIT_USAGE;
        } else {
            status = add_item(a, &item);
        }
    }
    if (!status && ferror(f))
        status = cli_usage_error("cannot read '%s': %s", path, strerror(errno));
    free(line);
    fclose(f);
    return status;
}

/* One option of a query command with its value (NULL for a flag). */
static int apply_query_option(query_args *a, const char *name, const char *value)
{
    query_item item;
    memset(&item, 0, sizeof item);
    if (cli_output_flag(name, &a->json, &a->faithful))
        return 0;
    if (!strcmp(name, "--both-ways")) {
        a->both_ways = 1;
    } else if (!strcmp(name, "--ray")) {
        if (cli_parse_numbers(value, item.v, 6) != 6)
            return cli_usage_error("--ray expects 6 numbers: OX,OY,OZ,DX,DY,DZ");
        if (direction_zero(item.v + 3))
            return cli_usage_error("--ray direction must not be zero");
        return add_item(a, &item);
    } else if (!strcmp(name, "--pixel")) {
        double v[2];
        if (cli_parse_numbers(value, v, 2) != 2 || v[0] != floor(v[0]) ||
            v[1] != floor(v[1]) || v[0] < 0 || v[1] < 0 || v[0] > 1e9 || v[1] > 1e9)
            return cli_usage_error("--pixel expects I,J: a column and a row, integers "
                                   ">= 0");
        item.pixel = 1;
        item.i = (int)v[0];
        item.j = (int)v[1];
        return add_item(a, &item);
    } else if (!strcmp(name, "--point")) {
        if (cli_parse_numbers(value, item.v, 3) != 3)
            return cli_usage_error("--point expects 3 numbers: X,Y,Z");
        return add_item(a, &item);
    } else if (!strcmp(name, "--rays")) {
        return read_items(a, value, 6);
    } else if (!strcmp(name, "--points")) {
        return read_items(a, value, 3);
    }
    return 0;
}

/* Options of each command: name, takes a value. */
typedef struct query_option {
    const char *name;
    int takes_value;
    int spans; /* 1: spans only, 0: inside only, 2: both */
} query_option;

static const query_option query_options[] = {
    {"--ray", 1, 1},       {"--rays", 1, 1},     {"--pixel", 1, 1},
    {"--both-ways", 0, 1}, {"--point", 1, 0},    {"--points", 1, 0},
    {"--json", 0, 2},      {"--faithful", 0, 2}, {"--strict", 0, 2},
};

static int parse_query_args(query_args *a, int argc, char **argv)
{
    const char *command = a->spans ? "spans" : "inside";
    sc_render_options scratch; /* checks the camera options before loading */
    sc_render_options_init(&scratch);
    int k = 1, only_files = 0, operand;
    const char *arg;
    while ((arg = cli_next_arg(argc, argv, &k, &only_files, &operand))) {
        if (operand) {
            if (a->input)
                return cli_usage_error("unexpected argument '%s'", arg);
            a->input = arg;
            continue;
        }
        size_t len;
        int st = cli_option_name(arg, &len);
        if (st)
            return st;
        const query_option *spec =
            cli_find_option(query_options, sizeof query_options / sizeof query_options[0],
                            sizeof query_options[0], arg, len);
        int camera = cli_camera_option(arg, len);
        if (!spec && camera < 0)
            return cli_usage_error("unknown option '%.*s'", (int)len, arg);
        if ((spec && spec->spans != 2 && spec->spans != a->spans) ||
            (camera >= 0 && !a->spans))
            return cli_usage_error("option '%.*s' does not apply to '%s'", (int)len, arg,
                                   command);
        int takes_value = spec ? spec->takes_value : camera;
        const char *value;
        st = cli_option_value(argc, argv, &k, arg, len, takes_value, &value);
        if (st)
            return st;
        if (spec) {
            char name[32];
            snprintf(name, sizeof name, "%.*s", (int)len, arg);
            st = apply_query_option(a, name, value);
        } else {
            if (a->camera_count ==
                (int)(sizeof a->camera_args / sizeof a->camera_args[0]))
                return cli_usage_error("too many camera options");
            a->camera_args[a->camera_count] = arg;
            a->camera_values[a->camera_count++] = value;
            st = cli_apply_camera_option(&scratch, arg, len, value);
        }
        if (st)
            return st;
    }
    if (!a->input)
        return cli_usage_error("missing input file");
    if (!a->count)
        return cli_usage_error(a->spans
                                   ? "no ray to query (give --ray, --rays or --pixel)"
                                   : "no point to query (give --point or --points)");
    return 0;
}

/* ---- output ---- */

static void json_number(double v)
{
    if (isfinite(v))
        printf("%.17g", v);
    else
        fputs("null", stdout);
}

static void json_vector(const double *v)
{
    putchar('[');
    for (int k = 0; k < 3; k++) {
        if (k)
            fputs(", ", stdout);
        json_number(v[k]);
    }
    putchar(']');
}

/* A string per RFC 8259: quote, backslash and control characters escaped;
 * every other byte as it is (file names are passed through as bytes). */
static void json_string(const char *s)
{
    if (!s) {
        fputs("null", stdout);
        return;
    }
    putchar('"');
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            printf("\\%c", *p);
        else if (*p == '\n')
            fputs("\\n", stdout);
        else if (*p == '\t')
            fputs("\\t", stdout);
        else if (*p < 0x20 || *p == 0x7f)
            printf("\\u%04x", *p);
        else
            putchar(*p);
    }
    putchar('"');
}

static void json_end(const query_args *a, const sc_span_end *e)
{
    fputs("{\"t\": ", stdout);
    json_number(e->t);
    fputs(", \"point\": ", stdout);
    json_vector(e->point);
    if (e->leaf < 0) {
        fputs(", \"leaf\": null}", stdout);
        return;
    }
    printf(", \"leaf\": %d, \"kind\": ", e->leaf);
    json_string(e->leaf_kind);
    fputs(", \"file\": ", stdout);
    if (in_export(a, e))
        json_string(a->input);
    else
        json_string(e->location.file);
    if (in_export(a, e))
        printf(", \"line\": null, \"column\": null, \"export_line\": %d, \"normal\": ",
               e->location.line);
    else if (in_mesh_model(a, e))
        fputs(", \"line\": null, \"column\": null, \"normal\": ", stdout);
    else
        printf(", \"line\": %d, \"column\": %d, \"normal\": ", e->location.line,
               e->location.column);
    json_vector(e->normal);
    printf(", \"subtracted\": %s}", e->subtracted ? "true" : "false");
}

static void text_vector(const double *v)
{
    printf("(%.10g, %.10g, %.10g)", v[0], v[1], v[2]);
}

static void text_end(const query_args *a, const char *label, const sc_span_end *e)
{
    printf("%s t=%.10g ", label, e->t);
    text_vector(e->point);
    if (e->leaf < 0) {
        fputs(isfinite(e->t) ? " (ray start)" : " (unbounded)", stdout);
        return;
    }
    if (in_export(a, e))
        printf(" %s#%d@%s (line %d of OpenSCAD's export) normal ",
               e->leaf_kind ? e->leaf_kind : "leaf", e->leaf, a->input, e->location.line);
    else if (in_mesh_model(a, e))
        printf(" %s#%d@%s normal ", e->leaf_kind ? e->leaf_kind : "leaf", e->leaf,
               a->input);
    else
        printf(" %s#%d@%s:%d:%d normal ", e->leaf_kind ? e->leaf_kind : "leaf", e->leaf,
               e->location.file ? e->location.file : "?", e->location.line,
               e->location.column);
    text_vector(e->normal);
    if (e->subtracted)
        fputs(" subtracted", stdout);
}

static void print_spans(const query_args *a, const query_item *item, size_t index,
                        const sc_span_list *list)
{
    size_t n = sc_span_list_count(list);
    if (a->json) {
        printf("%s\n  {", index ? "," : "");
        if (item->pixel)
            printf("\"pixel\": [%d, %d], ", item->i, item->j);
        fputs("\"origin\": ", stdout);
        json_vector(item->v);
        fputs(", \"direction\": ", stdout);
        json_vector(item->v + 3);
        printf(", \"both_ways\": %s, \"spans\": [", a->both_ways ? "true" : "false");
        for (size_t k = 0; k < n; k++) {
            const sc_span *s = sc_span_list_get(list, k);
            fputs(k ? ",\n    {\"in\": " : "\n    {\"in\": ", stdout);
            json_end(a, &s->in);
            fputs(", \"out\": ", stdout);
            json_end(a, &s->out);
            fputs(", \"distance\": ", stdout);
            json_number(s->distance);
            putchar('}');
        }
        fputs("]}", stdout);
        return;
    }
    if (item->pixel)
        printf("pixel %d,%d: ", item->i, item->j);
    else
        printf("ray %zu: ", index + 1);
    fputs("origin ", stdout);
    text_vector(item->v);
    fputs(" direction ", stdout);
    text_vector(item->v + 3);
    printf(", %s: %zu span%s\n", a->both_ways ? "whole line" : "t >= 0", n,
           n == 1 ? "" : "s");
    for (size_t k = 0; k < n; k++) {
        const sc_span *s = sc_span_list_get(list, k);
        fputs("  ", stdout);
        text_end(a, "in", &s->in);
        fputs("; ", stdout);
        text_end(a, "out", &s->out);
        printf("; distance %.10g\n", s->distance);
    }
}

/* ---- the commands ---- */

static int run_spans(query_args *a, sc_scene *scene)
{
    sc_render_options options;
    sc_render_options_init(&options);
    sc_render_options_from_scene(&options, scene);
    for (int k = 0; k < a->camera_count; k++) {
        const char *arg = a->camera_args[k], *eq = strchr(arg, '=');
        cli_apply_camera_option(&options, arg, eq ? (size_t)(eq - arg) : strlen(arg),
                                a->camera_values[k]); /* succeeded once already */
    }
    sc_error error;
    for (size_t k = 0; k < a->count; k++) {
        query_item *item = &a->items[k];
        if (item->pixel && sc_scene_pixel_ray(scene, &options, item->i, item->j, item->v,
                                              item->v + 3, &error) != SC_OK) {
            cli_print_error(&error); /* a camera or pixel the image does not have */
            return CLI_EXIT_USAGE;
        }
    }
    if (a->json)
        fputs("{\"rays\": [", stdout);
    for (size_t k = 0; k < a->count; k++) {
        sc_ray_query q;
        sc_ray_query_init(&q);
        memcpy(q.origin, a->items[k].v, sizeof q.origin);
        memcpy(q.direction, a->items[k].v + 3, sizeof q.direction);
        q.both_ways = a->both_ways;
        sc_span_list *list = NULL;
        if (sc_scene_spans(scene, &q, &list, &error) != SC_OK) {
            fflush(stdout);
            cli_print_error(&error);
            return CLI_EXIT_FAILED;
        }
        print_spans(a, &a->items[k], k, list);
        sc_span_list_release(list);
    }
    if (a->json)
        fputs("\n]}\n", stdout);
    return 0;
}

static int run_inside(query_args *a, sc_scene *scene)
{
    static const char *const names[] = {"out", "in", "on"};
    sc_error error;
    if (a->json)
        fputs("{\"points\": [", stdout);
    for (size_t k = 0; k < a->count; k++) {
        int where;
        if (sc_scene_inside(scene, a->items[k].v, &where, &error) != SC_OK) {
            fflush(stdout);
            cli_print_error(&error);
            return CLI_EXIT_FAILED;
        }
        if (a->json) {
            fputs(k ? ",\n  {\"point\": " : "\n  {\"point\": ", stdout);
            json_vector(a->items[k].v);
            printf(", \"where\": \"%s\"}", names[where]);
        } else {
            printf("%s\n", names[where]);
        }
    }
    if (a->json)
        fputs("\n]}\n", stdout);
    return 0;
}

static int run_query(int spans, int argc, char **argv)
{
    query_args a;
    memset(&a, 0, sizeof a);
    a.spans = spans;
    int status = parse_query_args(&a, argc, argv);
    if (!status) {
        int converted = 0;
        sc_scene *scene = cli_load_converted(a.input, a.faithful, &converted);
        if (converted && !scad_converted_name(a.input, a.export, sizeof a.export))
            a.export[0] = '\0';
        if (!scene) {
            status = CLI_EXIT_FAILED;
        } else {
            status = spans ? run_spans(&a, scene) : run_inside(&a, scene);
            sc_scene_release(scene);
        }
    }
    free(a.items);
    if (fflush(stdout) != 0 && !status) {
        fprintf(stderr, "spancast: error: cannot write the output: %s\n",
                strerror(errno));
        status = CLI_EXIT_FAILED;
    }
    return status;
}

int cli_spans(int argc, char **argv)
{
    return run_query(1, argc, argv);
}

int cli_inside(int argc, char **argv)
{
    return run_query(0, argc, argv);
}
