/* What the commands of the spancast tool share with main.c: messages,
 * number parsing, loading a model, and render's camera options (so that
 * `spans --pixel` reads --camera, --imgsize, ... exactly as `render` does);
 * and what spancast-view shares with render (render_options.c): messages,
 * number parsing and the preview options.
 */
#ifndef SPANCAST_CLI_CLI_H
#define SPANCAST_CLI_CLI_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "spancast/spancast.h"

enum { CLI_EXIT_FAILED = 1, CLI_EXIT_USAGE = 2 };

/* Prints "spancast: error: ..." on stderr; returns CLI_EXIT_USAGE.
 * (render_options.c, linked into spancast-view too) */
int cli_usage_error(const char *format, ...);

/* Prints the help (help.c): every command's for command NULL (or a name
 * that is no command), else that command's alone. */
void cli_print_help(FILE *out, const char *command);

/* Prints a library error, with its source position when it has one. */
void cli_print_error(const sc_error *error);

/* The thickness of a 2D model's slab in words, from its bounds: "1 unit
 * thick (z from -0.5 to 0.5), so its volume is its area", or, for a model
 * past 1e6 across, drawn thicker so that the rays still find it, the
 * thickness it has and the factor from its area to its volume. */
void cli_slab_words(const sc_scene *scene, char *out, size_t size);

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

/* The entry of an option table named by the len bytes at name, or NULL:
 * table holds count entries of stride bytes, each beginning with its
 * name (const char *), as every command's table does. (render_options.c) */
const void *cli_find_option(const void *table, size_t count, size_t stride,
                            const char *name, size_t len);

/* The next argument of a command's walk over argv after argv[*k]
 * (advancing *k), or NULL at the end. *operand tells a file (anything
 * after the first "--", "-" alone, anything not beginning with '-') from
 * an option; that first "--" itself is skipped and sets *only_files, which
 * starts at 0. (render_options.c) */
const char *cli_next_arg(int argc, char **argv, int *k, int *only_files, int *operand);

/* The length of the name of the option arg (which begins with '-' and is
 * not "-"): up to its '=', if any. Returns 0, or the exit status of a
 * usage error it printed for a short option. (render_options.c) */
int cli_option_name(const char *arg, size_t *len);

/* The value of the option arg (argv[*k], or the long name of a short
 * option there), whose name is its first len bytes: after its '=', else
 * when it takes one the next argument (advancing *k); NULL for a flag.
 * Returns 0, or the exit status of a usage error it printed: a flag given
 * a value, or a value missing or empty. (render_options.c) */
int cli_option_value(int argc, char **argv, int *k, const char *arg, size_t len,
                     int takes_value, const char **value);

/* The output flags of the query commands (spans, inside, measure,
 * overlaps, compare): sets *json for --json, CLI_LOAD_FAITHFUL in *faithful
 * for --faithful and CLI_LOAD_STRICT for --strict and returns 1; 0 for
 * another name. (render_options.c) */
int cli_output_flag(const char *name, int *json, int *faithful);

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

/* The load options the commands keep in one int (their `faithful`
 * field): --faithful, --strict, and --preview (without it the load
 * builds nothing that only the preview draws: sc_load_options.no_preview). */
#define CLI_LOAD_FAITHFUL 1
#define CLI_LOAD_STRICT 2
#define CLI_LOAD_PREVIEW 4

/* The threads a load builds a large model's hierarchies on: the
 * command's --threads (0, the default: all cores). Set while the options
 * are read, before any load (render_options.c). */
extern int cli_load_threads;

/* Sets lo's faithful, strict and no_preview from CLI_LOAD_* flags, and its threads
 * from cli_load_threads. */
static inline void cli_load_options(sc_load_options *lo, int flags)
{
    lo->faithful = (flags & CLI_LOAD_FAITHFUL) != 0;
    lo->strict = (flags & CLI_LOAD_STRICT) != 0;
    lo->no_preview = !(flags & CLI_LOAD_PREVIEW);
    lo->threads = cli_load_threads;
}

/* Loads a .csg or .scad model and prints its warnings; NULL (after printing
 * the error) when it cannot be loaded. flags: CLI_LOAD_*. */
sc_scene *cli_load(const char *path, int faithful);
/* cli_load, and *converted set when the text loaded came from OpenSCAD
 * (positions in the scene then name scad_converted_name). */
sc_scene *cli_load_converted(const char *path, int faithful, int *converted);

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

/* ---- stopping (stop.c): SIGINT, SIGTERM and --max-time ---- */

/* 0, or the signal that asks the command to stop: SIGINT, SIGTERM, or
 * SIGALRM when --max-time has passed. The library's cancel flag. */
extern volatile sig_atomic_t cli_stop;

/* Installs the handler for SIGINT, SIGTERM (unless the parent ignores
 * them) and SIGALRM. */
void cli_catch_interrupts(void);

/* --max-time=SECONDS: records the limit; 0 or a usage exit status. */
int cli_parse_max_time(const char *value);

/* Takes every --max-memory=SIZE (or --max-memory SIZE) out of argv,
 * before the command reads it, and sets the process's memory limit
 * (RLIMIT_DATA) to it: every command obeys it. 0 or a usage exit
 * status. */
int cli_take_max_memory(int *argc, char **argv);

/* Starts and stops the --max-time clock (no-op without the option). */
void cli_start_clock(void);
void cli_stop_clock(void);

/* Marks the stretch of a load, which cannot be stopped from inside: a
 * signal there ends the process from the handler. */
void cli_loading(int on);
volatile sig_atomic_t *cli_loading_flag(void);

/* After cli_stop is set: prints the time limit's error and returns 1, or
 * prints "spancast: interrupted" and ends by the signal. */
int cli_die_stopped(void);
/* `spancast batch JOBS [--json]` (batch.c), with the whole argv; returns
 * the exit status. */
int cli_batch(int argc, char **argv);

#endif
