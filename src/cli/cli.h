/* What the commands of the spancast tool share with main.c: messages,
 * number parsing, loading a model, and render's camera options (so that
 * `spans --pixel` reads --camera, --imgsize, ... exactly as `render` does);
 * and what spancast-view shares with render (render_options.c): messages,
 * number parsing and the preview options.
 */
#ifndef SPANCAST_CLI_CLI_H
#define SPANCAST_CLI_CLI_H

#include <stddef.h>

#include "spancast/spancast.h"

enum { CLI_EXIT_FAILED = 1, CLI_EXIT_USAGE = 2 };

/* Prints "spancast: error: ..." on stderr; returns CLI_EXIT_USAGE.
 * (render_options.c, linked into spancast-view too) */
int cli_usage_error(const char *format, ...);

/* Prints a library error, with its source position when it has one. */
void cli_print_error(const sc_error *error);

/* A whole string as a finite number: 1, or 0 when it is not one.
 * (render_options.c) */
int cli_parse_number(const char *s, double *out);

/* A whole string as a decimal integer within [lo, hi]: 1, or 0 when it is
 * not one. (render_options.c) */
int cli_parse_int(const char *s, long lo, long hi, long *out);

/* Splits s at commas into at most max numbers; returns how many there were
 * (max + 1 when there are too many), or -1 when one is not a number. (render_options.c)
 */
int cli_parse_numbers(const char *s, double *out, int max);

/* The names of --view in the order of their SC_VIEW_* bits: bit k is
 * 1 << k. (render_options.c) */
#define CLI_VIEW_NAME_COUNT 4
extern const char *const cli_view_names[CLI_VIEW_NAME_COUNT];

/* Whether the option named by the len bytes at name is one of render's
 * preview options (--colorscheme, --preview, --lighting, --view,
 * --edge-angle, --edge-width, --view-preset, --sheet, --section,
 * --section-style, --ao, --ao-radius): -1 when not, else 1 when it takes a
 * value, 0 when not. (render_options.c, for render and spancast-view) */
int cli_preview_option(const char *name, size_t len);

/* Applies such an option to options as `render` does: value is the
 * option's value, non-NULL when it takes one (the caller checks that);
 * --view-preset sets *preset, which the caller turns into a camera.
 * Returns 0 or the exit status of a usage error it printed, with render's
 * message. */
int cli_apply_preview_option(sc_render_options *options, sc_view_preset *preset,
                             const char *name, size_t len, const char *value);

/* Loads a .csg or .scad model and prints its warnings; NULL (after printing
 * the error) when it cannot be loaded. */
sc_scene *cli_load(const char *path, int faithful);

/* Whether the option named by the len bytes at name is one of render's
 * camera options (--camera, --imgsize, --fov, --projection, --viewall,
 * --autocenter): -1 when not, else 1 when it takes a value, 0 when not. */
int cli_camera_option(const char *name, size_t len);

/* Applies such an option (value NULL for a flag) to options as `render`
 * does; returns 0 or the exit status of a usage error it printed. */
int cli_apply_camera_option(sc_render_options *options, const char *name, size_t len,
                            const char *value);

/* The commands of query.c: `spancast spans ...` and `spancast inside ...`
 * with the whole argv; return the exit status. */
int cli_spans(int argc, char **argv);
int cli_inside(int argc, char **argv);

/* The commands of check.c: `spancast measure`, `spancast overlaps` and
 * `spancast compare`, with the whole argv; return the exit status. */
int cli_measure(int argc, char **argv);
int cli_overlaps(int argc, char **argv);
int cli_compare(int argc, char **argv);

/* `spancast batch JOBS [--json]` (batch.c), with the whole argv; returns
 * the exit status. */
int cli_batch(int argc, char **argv);

#endif
