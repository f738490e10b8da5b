/* spancast public API.
 *
 * A scene is loaded from a model file (OpenSCAD's .csg grammar plus
 * spancast's own node types), compiled once into an immutable CSG tree, and
 * rendered into a framebuffer (colour and AOVs) that can be written to any
 * image format OpenImageIO supports. It can also be queried: the spans of a
 * line inside the solid, the camera ray of a pixel, point membership.
 * Handles are opaque; options are plain structs filled by an init function.
 * Every call returns a status and, on failure, fills an sc_error with a
 * message and, where the error comes from input, its source position.
 * Nothing here prints or exits.
 */
#ifndef SPANCAST_SPANCAST_H
#define SPANCAST_SPANCAST_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include <spancast/version.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the library this program runs with, "MAJOR.MINOR.PATCH";
 * SPANCAST_VERSION_STRING (spancast/version.h) is the version of the header
 * it was compiled with. The string is static; thread safe. */
const char *sc_version(void);

typedef enum sc_status {
    SC_OK = 0,
    SC_ERR_SYNTAX,      /* malformed input text */
    SC_ERR_SEMANTIC,    /* well-formed text with invalid meaning (bad argument, ...) */
    SC_ERR_UNSUPPORTED, /* a node type spancast cannot render yet */
    SC_ERR_LIMIT,       /* a documented resource limit was exceeded */
    SC_ERR_IO,          /* a file could not be read or written */
    SC_ERR_NOMEM,       /* out of memory */
    SC_ERR_ARGUMENT,    /* invalid API or command-line argument */
    SC_ERR_CANCELLED    /* the caller's cancel flag was set (e.g. by SIGINT) */
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

/* Tree statistics for `spancast info`: the compiled tree, and the tree as
 * the file describes it before simplification. */
#define SC_LEAF_KINDS 16

typedef struct sc_scene_info {
    size_t node_count; /* boolean nodes and leaves of the compiled tree */
    size_t leaf_count;
    size_t depth;
    size_t source_node_count; /* the same before simplification */
    size_t source_leaf_count;
    size_t source_depth;
    size_t bvh_node_count;            /* over wide unions and differences */
    size_t leaf_kinds[SC_LEAF_KINDS]; /* leaves per kind (sc_leaf_kind_name) */
    /* Features the scene uses, which decide the render paths: */
    size_t lights;         /* light() nodes; 0: the default rig */
    size_t mirror_leaves;  /* leaves whose material reflects */
    size_t glass_leaves;   /* leaves whose material transmits */
    size_t checker_leaves; /* leaves with a checkerboard material */
} sc_scene_info;

/* Name of leaf kind index k ("sphere", "box", ...), NULL past the last. */
const char *sc_leaf_kind_name(int k);

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
    int want_id;                                        /* fill the object id buffer */
    double up[3];  /* up hint of SC_CAMERA_VECTOR (default 0, 0, 1) */
    int spp;       /* samples per pixel, stratified and jittered (default 1) */
    int max_depth; /* reflection and refraction bounces (default 5) */
    int region[4]; /* x0, y0, x1, y1 (exclusive): render only this crop of the
                      width x height image; all 0 (default): the whole image */
    /* Called now and then from one rendering thread with the fraction done
     * (0..1), and once with 1 at the end; NULL: not called. */
    void (*progress)(void *user, double fraction);
    void *progress_user;
    /* Cancellation: when not NULL and *cancel becomes non-zero (a signal
     * handler may set it), sc_render stops within a tile and returns
     * SC_ERR_CANCELLED, and the writers of its framebuffer give up without
     * touching their target. NULL by default. */
    const volatile sig_atomic_t *cancel;
} sc_render_options;

void sc_render_options_init(sc_render_options *options);

/* Applies the scene's own settings to options: a camera() node in the file
 * sets camera_mode (SC_CAMERA_VECTOR), camera, up, fov_deg and projection.
 * Call it after sc_render_options_init and before applying the user's own
 * choices, so that those override the file. Returns 1 when the file has a
 * camera, else 0 (options unchanged). */
int sc_render_options_from_scene(sc_render_options *options, const sc_scene *scene);

/* Counters of one render, summed over threads. */
typedef struct sc_render_stats {
    uint64_t camera_rays, shadow_rays, reflection_rays, refraction_rays;
    uint64_t primitive_tests; /* leaf span computations */
    uint64_t span_operations; /* boolean merges of two non-empty span lists */
    uint64_t node_visits;     /* CSG tree nodes whose box a ray was tested against */
    uint64_t bvh_node_visits; /* BVH nodes whose box a ray was tested against */
    uint64_t scratch_mallocs; /* blocks the per-thread scratch arenas took from malloc */
    double setup_seconds;     /* camera, lights, buffers */
    double trace_seconds;     /* the parallel render loop */
    int threads;              /* threads that rendered */
} sc_render_stats;

/* The rendered image: row-major, row 0 at the top. Buffers not asked for are
 * NULL. */
typedef struct sc_framebuffer {
    int width, height;
    float *color;  /* RGB, 3 floats per pixel, scene-linear (sRGB primaries), >= 0 */
    float *depth;  /* distance along the ray to the hit, +inf on a miss */
    uint8_t *mask; /* 255 where the camera ray hits, 0 elsewhere */
    float *normal; /* world normal, 3 floats per pixel, 0 on a miss */
    int32_t *id;   /* index of the leaf the camera ray hit (source order), -1 on a miss */
    int x0, y0;    /* where this image lies in the full image (--region), else 0 */
    char camera_info[256]; /* the camera in words, for the files' metadata */
    sc_render_stats stats;
    const volatile sig_atomic_t *cancel; /* the render options' cancel flag */
} sc_framebuffer;

/* Renders the scene. On success *framebuffer is owned by the caller (release
 * with sc_framebuffer_release). The buffers' size is checked before they are
 * allocated: more than 16 GiB, or more than the machine's memory, is
 * SC_ERR_LIMIT (docs/limits.md). */
sc_status sc_render(const sc_scene *scene, const sc_render_options *options,
                    sc_framebuffer **framebuffer, sc_error *error);

void sc_framebuffer_release(sc_framebuffer *framebuffer);

/* Image output through OpenImageIO; the format follows the file extension.
 * Colour goes to 8-bit formats (PNG, JPEG, ...) sRGB-encoded, to float
 * formats (EXR, float TIFF, ...) as the linear values; every file carries
 * the software name and the camera in its metadata.
 * Each writes a temporary file in the target's folder and renames it into
 * place, so a failure never leaves a partial file or destroys an existing
 * one. When fb->cancel is set before the rename, the temporary is removed,
 * the target is left as it was and the call returns SC_ERR_CANCELLED. */
sc_status sc_framebuffer_write_color(const sc_framebuffer *fb, const char *path,
                                     sc_error *error);
sc_status sc_framebuffer_write_mask(const sc_framebuffer *fb, const char *path,
                                    sc_error *error);
sc_status sc_framebuffer_write_depth(const sc_framebuffer *fb, const char *path,
                                     sc_error *error);
/* World normals as float channels X, Y, Z; object ids as one float channel
 * "id" (-1 on a miss). Both need a float format (.exr or .tif). */
sc_status sc_framebuffer_write_normal(const sc_framebuffer *fb, const char *path,
                                      sc_error *error);
sc_status sc_framebuffer_write_id(const sc_framebuffer *fb, const char *path,
                                  sc_error *error);

/* ---- queries: spans along a ray, point membership -------------------- */

/* A line to query. Points on it are origin + t * direction; direction need
 * not be unit length, and t is in its units (the distance along the ray is
 * t * |direction|, as in the camera contract). */
typedef struct sc_ray_query {
    double origin[3];
    double direction[3]; /* finite, not zero */
    int both_ways;       /* 0 (default): the ray t >= 0; 1: the whole line */
} sc_ray_query;

/* Sets origin and direction to 0 and both_ways to 0. */
void sc_ray_query_init(sc_ray_query *query);

/* One end of a span: where the ray enters (in) or leaves (out) the solid. */
typedef struct sc_span_end {
    double t;        /* ray parameter; -inf or +inf only for an unbounded solid */
    double point[3]; /* origin + t * direction (zeros when t is not finite) */
    /* The leaf whose surface this is, as the id AOV numbers leaves (source
     * order); -1 when the end is not on a surface: the ray starts inside
     * the solid (t = 0), or the solid is unbounded along the line. */
    int leaf;
    const char *leaf_kind; /* "sphere", "box", ... (sc_leaf_kind_name); NULL
                              when leaf is -1; points into static data */
    sc_location location;  /* where the leaf is written; file points into the
                              scene (valid until sc_scene_release) */
    double normal[3];      /* unit world normal pointing out of the resulting
                              solid (so flipped on a subtracted surface); 0
                              when leaf is -1 */
    int subtracted;        /* 1: the surface bounds a subtracted solid (a
                              difference's later operand), its normal flipped */
} sc_span_end;

typedef struct sc_span {
    sc_span_end in, out; /* in.t < out.t */
    double distance;     /* (out.t - in.t) * |direction|: the length inside */
} sc_span;

typedef struct sc_span_list sc_span_list;

/* ALL_SPANS for one line: the sorted, disjoint intervals of the query's
 * ray (t >= 0, or the whole line with both_ways) inside the solid, after
 * the regularisation rule (README: "How a ray meets the solid"). On success
 * *out belongs to the caller (release with sc_span_list_release) and may
 * hold no spans; on failure *out is NULL and error says why:
 * SC_ERR_ARGUMENT for a direction that is zero or a value that is not
 * finite, SC_ERR_NOMEM. The scene is only read: calls on one scene from
 * several threads at once are safe. */
sc_status sc_scene_spans(const sc_scene *scene, const sc_ray_query *query,
                         sc_span_list **out, sc_error *error);

/* The number of spans. */
size_t sc_span_list_count(const sc_span_list *list);

/* Span index (0 = nearest along the direction), or NULL past the last. The
 * pointer is valid until the list is released. */
const sc_span *sc_span_list_get(const sc_span_list *list, size_t index);

/* Frees the list; NULL is ignored. */
void sc_span_list_release(sc_span_list *list);

/* The ray render shoots through the centre of pixel (i, j) (column i from
 * the left, row j from the top) with these options (camera, image size,
 * field of view, projection, viewall, autocenter; the rest is ignored):
 * exactly the ray whose first hit is that pixel's depth. Fills origin and
 * direction (not normalised). Returns SC_ERR_ARGUMENT, with render's
 * message, for a bad camera, and for a pixel outside the image. Thread
 * safe. */
sc_status sc_scene_pixel_ray(const sc_scene *scene, const sc_render_options *options,
                             int i, int j, double origin[3], double direction[3],
                             sc_error *error);

/* Where a point lies relative to the solid. */
typedef enum sc_where { SC_OUTSIDE = 0, SC_INSIDE = 1, SC_ON = 2 } sc_where;

/* Point membership. *where is SC_ON when the surface lies within the
 * scene's tolerance eps of p (the tolerance of the regularisation rule,
 * for unit rays from p: the larger of 1e-9 of the scene's extent and 2^-40
 * of its scale or its distance from p) along one of the three axis lines
 * through p: the lines' spans (as sc_scene_spans gives them) have an end
 * on a surface with |t| <= eps. Along a line the distance to a plane is
 * at least the perpendicular one, and one axis makes an angle of at most
 * acos(1/sqrt(3)) with the normal, so a point on a face or within
 * eps / sqrt(3) of one is SC_ON, and a point farther than eps from every
 * surface never is. Otherwise SC_INSIDE when p lies inside a span of at
 * least two of the three lines (they agree except where a line grazes a
 * surface), else SC_OUTSIDE. Returns SC_ERR_ARGUMENT for a coordinate that
 * is not finite, SC_ERR_NOMEM. Thread safe. */
sc_status sc_scene_inside(const sc_scene *scene, const double p[3], int *where,
                          sc_error *error);

#ifdef __cplusplus
}
#endif

#endif
