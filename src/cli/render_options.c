/* What `spancast render` and `spancast view` (spancast-view, a program of
 * its own) read alike: the tool's usage errors, number parsing, and
 * render's preview options (--colorscheme, --preview, --lighting, --view,
 * --edge-angle, --edge-width, --view-preset, --sheet, --section,
 * --section-style, --ao, --ao-radius) and its lens (--aperture, --focus).
 *
 * One parser for both, so that the viewer takes each option with render's
 * checks and refuses it with render's message, byte for byte
 * (tests/cli_view.sh compares them). Linked into both programs.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "render/render.h"
#include "spancast/spancast.h"

int cli_load_threads;

/* ---- messages and values ---- */

/* The message is written in one piece: under mpirun, a line written in
 * parts can be cut by another process's output (mpirun's own notice of
 * the failed rank). */
int cli_usage_error(const char *format, ...)
{
    char message[2048];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    fprintf(stderr, "spancast: error: %s\n", message);
    return CLI_EXIT_USAGE;
}

int cli_parse_number(const char *s, double *out)
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

int cli_parse_int(const char *s, long lo, long hi, long *out)
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

int cli_parse_numbers(const char *s, double *out, int max)
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
        if (!cli_parse_number(field, &out[count]))
            return -1;
        count++;
        if (!comma)
            return count;
        field = comma + 1;
    }
}

/* ---- the preview options ---- */

typedef enum preview_id {
    PREVIEW_COLORSCHEME,
    PREVIEW_PREVIEW,
    PREVIEW_LIGHTING,
    PREVIEW_VIEW,
    PREVIEW_EDGE_ANGLE,
    PREVIEW_EDGE_WIDTH,
    PREVIEW_VIEW_PRESET,
    PREVIEW_SHEET,
    PREVIEW_SECTION,
    PREVIEW_SECTION_STYLE,
    PREVIEW_AO,
    PREVIEW_AO_RADIUS,
    PREVIEW_APERTURE,
    PREVIEW_FOCUS
} preview_id;

typedef struct preview_spec {
    const char *name;
    preview_id id;
    int takes_value; /* 0: a flag */
} preview_spec;

static const preview_spec preview_table[] = {
    {"--colorscheme", PREVIEW_COLORSCHEME, 1},
    {"--preview", PREVIEW_PREVIEW, 0},
    {"--lighting", PREVIEW_LIGHTING, 1},
    {"--view", PREVIEW_VIEW, 1},
    {"--edge-angle", PREVIEW_EDGE_ANGLE, 1},
    {"--edge-width", PREVIEW_EDGE_WIDTH, 1},
    {"--view-preset", PREVIEW_VIEW_PRESET, 1},
    {"--sheet", PREVIEW_SHEET, 1},
    {"--section", PREVIEW_SECTION, 1},
    {"--section-style", PREVIEW_SECTION_STYLE, 1},
    {"--ao", PREVIEW_AO, 1},
    {"--ao-radius", PREVIEW_AO_RADIUS, 1},
    {"--aperture", PREVIEW_APERTURE, 1},
    {"--focus", PREVIEW_FOCUS, 1},
};

static const preview_spec *find_preview_option(const char *name, size_t len)
{
    for (size_t k = 0; k < sizeof preview_table / sizeof preview_table[0]; k++)
        if (strlen(preview_table[k].name) == len &&
            !strncmp(preview_table[k].name, name, len))
            return &preview_table[k];
    return NULL;
}

int cli_preview_option(const char *name, size_t len)
{
    const preview_spec *spec = find_preview_option(name, len);
    return spec ? spec->takes_value : -1;
}

/* The names of a comma-separated list, each looked up in names[]; sets the
 * bit of each in *flags, or appends its index to out[*count] (max of them).
 * Returns 0, or a usage error naming option and the bad name. */
static int parse_name_list(const char *option, const char *value,
                           const char *const *names, int name_count, unsigned *flags,
                           int *out, int *count, int max)
{
    const char *p = value;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        int found = -1;
        for (int k = 0; k < name_count; k++)
            if (names[k] && strlen(names[k]) == len && !strncmp(names[k], p, len))
                found = k;
        if (found < 0) {
            char list[256] = "";
            for (int k = 0; k < name_count; k++) {
                if (!names[k])
                    continue;
                if (list[0])
                    strcat(list, ", ");
                strcat(list, names[k]);
            }
            return cli_usage_error("%s: unknown name '%.*s' (expected %s)", option,
                                   (int)len, p, list);
        }
        if (flags)
            *flags |= 1u << found;
        if (out) {
            if (*count >= max)
                return cli_usage_error("%s takes at most %d names", option, max);
            out[(*count)++] = found;
        }
        if (!comma)
            return 0;
        p = comma + 1;
    }
}

const char *const cli_view_names[CLI_VIEW_NAME_COUNT] = {"edges", "axes", "scales",
                                                         "crosshairs"};
static const char *const preset_names[] = {NULL,    "top",   "bottom", "left",
                                           "right", "front", "back",   "diagonal"};

int cli_apply_preview_option(sc_render_options *o, sc_view_preset *preset,
                             const char *name, size_t len, const char *value)
{
    const preview_spec *spec = find_preview_option(name, len);
    if (!spec)
        return cli_usage_error("unknown option '%.*s'", (int)len, name);
    switch (spec->id) {
    case PREVIEW_COLORSCHEME: {
        sc_error error;
        if (sc_render_options_set_scheme(o, value, NULL, &error) != SC_OK)
            return cli_usage_error("--colorscheme: %s", error.message);
        o->use_scheme = 1;
        return 0;
    }
    case PREVIEW_LIGHTING:
        if (!strcmp(value, "default"))
            o->lighting = SC_LIGHTING_DEFAULT;
        else if (!strcmp(value, "openscad"))
            o->lighting = SC_LIGHTING_OPENSCAD;
        else
            return cli_usage_error("--lighting expects 'default' or 'openscad'");
        return 0;
    case PREVIEW_PREVIEW:
        o->preview = 1;
        return 0;
    case PREVIEW_VIEW: {
        unsigned flags = 0;
        int st = parse_name_list("--view", value, cli_view_names, CLI_VIEW_NAME_COUNT,
                                 &flags, NULL, NULL, 0);
        if (st)
            return st;
        o->view |= flags; /* bit k of cli_view_names is SC_VIEW_* 1 << k */
        return 0;
    }
    case PREVIEW_EDGE_ANGLE: {
        double v;
        if (!cli_parse_number(value, &v) || !(v > 0 && v < 180))
            return cli_usage_error("--edge-angle expects an angle in degrees between 0 "
                                   "and 180");
        o->edge_angle_deg = v;
        return 0;
    }
    case PREVIEW_EDGE_WIDTH: {
        double v;
        if (!cli_parse_number(value, &v) || !(v > 0 && v <= RENDER_MAX_EDGE_WIDTH))
            return cli_usage_error("--edge-width expects a width in pixels above 0 and "
                                   "at most %d",
                                   RENDER_MAX_EDGE_WIDTH);
        o->edge_width = v;
        return 0;
    }
    case PREVIEW_VIEW_PRESET: {
        int index[1], count = 0;
        int st = parse_name_list("--view-preset", value, preset_names, 8, NULL, index,
                                 &count, 1);
        if (st)
            return st;
        *preset = (sc_view_preset)index[0];
        return 0;
    }
    case PREVIEW_SHEET: {
        int index[SC_MAX_SHEET], count = 0;
        int st = parse_name_list("--sheet", value, preset_names, 8, NULL, index, &count,
                                 SC_MAX_SHEET);
        if (st)
            return st;
        o->sheet_count = count;
        for (int k = 0; k < count; k++)
            o->sheet[k] = (sc_view_preset)index[k];
        return 0;
    }
    case PREVIEW_SECTION: {
        double v[4];
        if (cli_parse_numbers(value, v, 4) != 4 || (v[0] == 0 && v[1] == 0 && v[2] == 0))
            return cli_usage_error("--section expects NX,NY,NZ,D with a non-zero normal "
                                   "(keeps the half-space n.p <= D)");
        if (o->section_count >= SC_MAX_SECTIONS)
            return cli_usage_error("at most %d --section options", SC_MAX_SECTIONS);
        memcpy(o->section[o->section_count++], v, sizeof v);
        return 0;
    }
    case PREVIEW_SECTION_STYLE:
        if (!strcmp(value, "solid"))
            o->section_style = SC_SECTION_SOLID;
        else if (!strcmp(value, "hatch"))
            o->section_style = SC_SECTION_HATCH;
        else
            return cli_usage_error("--section-style expects 'solid' or 'hatch'");
        return 0;
    case PREVIEW_AO: {
        long n;
        if (!cli_parse_int(value, 0, RENDER_MAX_AO, &n))
            return cli_usage_error("--ao expects a number of rays from 0 to %d",
                                   RENDER_MAX_AO);
        o->ao_samples = (int)n;
        return 0;
    }
    case PREVIEW_AO_RADIUS: {
        double v;
        if (!cli_parse_number(value, &v) || !(v > 0))
            return cli_usage_error("--ao-radius expects a positive fraction of the "
                                   "model's diagonal");
        o->ao_radius = v;
        return 0;
    }
    case PREVIEW_APERTURE: {
        double v;
        if (!cli_parse_number(value, &v) || !(v >= 0))
            return cli_usage_error("--aperture expects the lens's diameter in model "
                                   "units (0: a pinhole)");
        o->aperture = v;
        return 0;
    }
    case PREVIEW_FOCUS: {
        double v;
        if (!cli_parse_number(value, &v) || !(v > 0))
            return cli_usage_error("--focus expects a positive distance from the eye");
        o->focus = v;
        return 0;
    }
    }
    return 0;
}

const void *cli_find_option(const void *table, size_t count, size_t stride,
                            const char *name, size_t len)
{
    for (size_t k = 0; k < count; k++) {
        const char *entry = (const char *)table + k * stride;
        const char *entry_name;
        memcpy(&entry_name, entry, sizeof entry_name); /* the entry's first member */
        if (strlen(entry_name) == len && !strncmp(name, entry_name, len))
            return entry;
    }
    return NULL;
}

const char *cli_next_arg(int argc, char **argv, int *k, int *only_files, int *operand)
{
    while (++*k < argc) {
        const char *arg = argv[*k];
        if (!*only_files && !strcmp(arg, "--")) {
            *only_files = 1;
            continue;
        }
        *operand = *only_files || arg[0] != '-' || !arg[1];
        return arg;
    }
    return NULL;
}

int cli_option_name(const char *arg, size_t *len)
{
    if (arg[1] != '-')
        return cli_usage_error("unknown option '%s'", arg);
    const char *eq = strchr(arg, '=');
    *len = eq ? (size_t)(eq - arg) : strlen(arg);
    return 0;
}

int cli_option_value(int argc, char **argv, int *k, const char *arg, size_t len,
                     int takes_value, const char **value)
{
    *value = NULL;
    if (arg[len] == '=') {
        if (!takes_value)
            return cli_usage_error("option '%.*s' takes no value", (int)len, arg);
        *value = arg + len + 1;
    } else if (takes_value) {
        if (*k + 1 >= argc)
            return cli_usage_error("option '%s' expects a value", arg);
        *value = argv[++*k];
    }
    if (takes_value && !**value)
        return cli_usage_error("option '%.*s' expects a value", (int)len, arg);
    return 0;
}

int cli_output_flag(const char *name, int *json, int *faithful)
{
    if (!strcmp(name, "--json"))
        *json = 1;
    else if (!strcmp(name, "--faithful"))
        *faithful |= CLI_LOAD_FAITHFUL;
    else if (!strcmp(name, "--strict"))
        *faithful |= CLI_LOAD_STRICT;
    else
        return 0;
    return 1;
}
