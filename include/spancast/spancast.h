/* spancast public API.
 *
 * A scene is loaded from a model file (OpenSCAD's .csg grammar plus
 * spancast's own node types), compiled once into an immutable CSG tree, and
 * rendered into a framebuffer (colour and AOVs) that can be written to any
 * image format OpenImageIO supports. Handles are opaque; options are plain
 * structs filled by an init function. Every call returns a status and, on
 * failure, fills an sc_error with a message and, where the error comes from
 * input, its source position. Nothing here prints or exits.
 */
#ifndef SPANCAST_SPANCAST_H
#define SPANCAST_SPANCAST_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sc_status {
    SC_OK = 0,
    SC_ERR_SYNTAX,      /* malformed input text */
    SC_ERR_SEMANTIC,    /* well-formed text with invalid meaning (bad argument, ...) */
    SC_ERR_UNSUPPORTED, /* a node type spancast cannot render yet */
    SC_ERR_LIMIT,       /* a documented resource limit was exceeded */
    SC_ERR_IO,          /* a file could not be read or written */
    SC_ERR_NOMEM,       /* out of memory */
    SC_ERR_ARGUMENT     /* invalid API or command-line argument */
} sc_status;

/* A source position; line and column count from 1, 0 means "no position". */
typedef struct sc_location {
    const char *file; /* points into the scene or the caller's string; may be NULL */
    int line;
    int column;
} sc_location;

#define SC_ERROR_MESSAGE_MAX 512
#define SC_ERROR_FILE_MAX 1024

typedef struct sc_error {
    sc_status status;
    char file[SC_ERROR_FILE_MAX]; /* empty when the error has no source file */
    int line;                     /* 0 when the error has no position */
    int column;
    char message[SC_ERROR_MESSAGE_MAX];
} sc_error;

/* Formats "file:line:col: error: message" (or "error: message" without a
 * position) into buf; returns buf. */
const char *sc_error_format(const sc_error *error, char *buf, size_t size);

/* ---- scenes ---------------------------------------------------------- */

typedef struct sc_scene sc_scene;

typedef struct sc_load_options {
    int faithful; /* spheres and cylinders as OpenSCAD's polyhedra for $fn, $fa, $fs */
} sc_load_options;

void sc_load_options_init(sc_load_options *options);

/* Loads and compiles a model file. On success *scene owns everything it
 * needs (release with sc_scene_release); on failure *scene is NULL and
 * error is filled. */
sc_status sc_scene_load(const char *path, const sc_load_options *options,
                        sc_scene **scene, sc_error *error);

/* Same, from text in memory; name is used in error positions. */
sc_status sc_scene_load_string(const char *name, const char *text, size_t length,
                               const sc_load_options *options, sc_scene **scene,
                               sc_error *error);

void sc_scene_release(sc_scene *scene);

/* World bounding box of the solid; returns 0 when the solid is empty. */
int sc_scene_bounds(const sc_scene *scene, double lo[3], double hi[3]);

/* Warnings collected while loading (e.g. a singular transform flattened to an
 * empty solid), in source order. */
size_t sc_scene_warning_count(const sc_scene *scene);
const sc_error *sc_scene_warning(const sc_scene *scene, size_t index);

/* Tree statistics for `spancast info`. */
typedef struct sc_scene_info {
    size_t node_count; /* boolean nodes and leaves of the compiled tree */
    size_t leaf_count;
    size_t depth;
} sc_scene_info;

void sc_scene_get_info(const sc_scene *scene, sc_scene_info *info);

/* ---- rendering ------------------------------------------------------- */

typedef enum sc_camera_mode {
    SC_CAMERA_AUTO = 0, /* a default view that shows the whole model */
    SC_CAMERA_VECTOR,   /* eye and centre: camera[0..5] */
    SC_CAMERA_GIMBAL    /* OpenSCAD's translate, rotate, distance: camera[0..6] */
} sc_camera_mode;

typedef enum sc_projection {
    SC_PROJECTION_PERSPECTIVE = 0,
    SC_PROJECTION_ORTHOGRAPHIC
} sc_projection;

typedef struct sc_render_options {
    int width, height; /* image size in pixels (default 800 x 600) */
    sc_camera_mode camera_mode;
    double camera[7]; /* see sc_camera_mode */
    double fov_deg;   /* vertical field of view (default 22.5) */
    sc_projection projection;
    int viewall;    /* OpenSCAD --viewall: move the eye to show the whole model */
    int autocenter; /* OpenSCAD --autocenter: look at the model's centre */
    int threads;    /* 0 = all cores */
    int want_color, want_depth, want_mask, want_normal; /* which buffers to fill */
} sc_render_options;

void sc_render_options_init(sc_render_options *options);

/* The rendered image: row-major, row 0 at the top. Buffers not asked for are
 * NULL. */
typedef struct sc_framebuffer {
    int width, height;
    float *color;  /* RGB, 3 floats per pixel, display (sRGB-encoded) values 0..1 */
    float *depth;  /* distance along the ray to the hit, +inf on a miss */
    uint8_t *mask; /* 255 where the camera ray hits, 0 elsewhere */
    float *normal; /* world normal, 3 floats per pixel, 0 on a miss */
} sc_framebuffer;

/* Renders the scene. On success *framebuffer is owned by the caller (release
 * with sc_framebuffer_release). */
sc_status sc_render(const sc_scene *scene, const sc_render_options *options,
                    sc_framebuffer **framebuffer, sc_error *error);

void sc_framebuffer_release(sc_framebuffer *framebuffer);

/* Image output through OpenImageIO; the format follows the file extension.
 * Each writes a temporary file in the target's folder and renames it into
 * place, so a failure never leaves a partial file or destroys an existing
 * one. */
sc_status sc_framebuffer_write_color(const sc_framebuffer *fb, const char *path,
                                     sc_error *error);
sc_status sc_framebuffer_write_mask(const sc_framebuffer *fb, const char *path,
                                    sc_error *error);
sc_status sc_framebuffer_write_depth(const sc_framebuffer *fb, const char *path,
                                     sc_error *error);

#ifdef __cplusplus
}
#endif

#endif
