/* spancast public API.
 *
 * A scene is loaded from a model file (OpenSCAD's .csg grammar plus
 * spancast's own node types), compiled once into an immutable CSG tree, and
 * rendered into a framebuffer (colour and AOVs) that can be written to any
 * image format OpenImageIO supports. It can also be queried: the spans of a
 * line inside the solid, the camera ray of a pixel, point membership, and
 * integrals over the solid (volume, area, inertia, overlaps, comparison).
 * Link with `pkg-config --cflags --libs spancast` or CMake's
 * find_package(spancast) and the target spancast::spancast.
 *
 * Stable API. Programs built against this header keep working with every
 * later libspancast of the same soname (libspancast.so.0); the exported
 * ABI is recorded in abi/libspancast.abi and checked by the tests. Three
 * kinds of type cross the API, each with its own rule:
 *
 * - Opaque handles (sc_scene, sc_framebuffer, sc_span_list, sc_objects,
 *   sc_overlap_list): made by one call, read through functions, freed by
 *   their release call; their layout is private and may change freely.
 *
 * - Sized structs (sc_load_options, sc_render_options, sc_ray_query,
 *   sc_measure_options, and the results sc_scene_info, sc_render_stats,
 *   sc_measure, sc_comparison): plain structs the caller declares and
 *   reads by field, whose first field `size` holds sizeof the struct as
 *   the caller was compiled. Set it up with the struct's init call, a macro
 *   over sc_X_init_size(&x, sizeof x) that also fills the defaults (zeros
 *   for a result): `sc_render_options o; sc_render_options_init(&o);`.
 *   New fields are only ever appended, so a struct may grow in a later
 *   release: the library reads only the first `size` bytes of options (the
 *   fields after them keep their defaults) and writes no further than
 *   `size` into results. A struct that was never set up (a size below any
 *   release's) is SC_ERR_ARGUMENT, and so are options from a newer header
 *   than the library (a size above its own). This is the convention of
 *   SDL3's interfaces and Win32's cbSize: it keeps field access and struct
 *   copies in the caller, where setters and getters for every option
 *   (Embree's rtcSet*, libcurl's easy options) would trade them for a call
 *   per field.
 *
 * - Fixed records (sc_error, sc_location, sc_estimate, sc_color_scheme,
 *   sc_span_end, and the limits SC_ERROR_*_MAX, SC_LEAF_KINDS,
 *   SC_MAX_SECTIONS, SC_MAX_SHEET): small value types embedded in others,
 *   frozen for the life of the soname. sc_span and sc_overlap are only
 *   ever read through pointers the library hands out, so they, too, may
 *   gain fields at their end.
 *
 * Enumerations only gain values at their end. Adding functions, appending
 * fields to sized structs and adding enumerators are compatible changes;
 * anything else (removing or changing a function, reordering fields,
 * changing a fixed record) needs a new soname.
 *
 * Errors: every call that can fail returns an sc_status (SC_OK = 0) and
 * takes `sc_error *error` last; on failure it fills *error (when error is
 * not NULL) with the status, a message and, where the error comes from
 * input, its source position; after success *error holds nothing of use.
 * Nothing here prints, exits, or reads the environment except where a
 * call says so.
 *
 * Ownership: a call that makes a handle gives it to the caller, who
 * releases it with the matching release call (NULL is ignored by every
 * release call). Pointers a getter returns point into the handle and stay
 * valid until it is released. Strings the caller passes are copied or
 * only read during the call.
 *
 * Thread safety: the library has no global mutable state. Handles are
 * immutable once made, so any number of threads may query, render or
 * measure the same scene (or read the same framebuffer, span list,
 * objects or overlap list) at once; a handle must not be released while
 * another thread uses it. Calls that fill a caller's struct touch nothing
 * else. Callbacks (progress) are called from one thread at a time, and a
 * cancel flag may be set from any thread or a signal handler.
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
 * it was compiled with. The string is static; never fails; thread safe. */
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

/* What went wrong (a fixed record: see the opening comment). The caller
 * declares it; the library fills it on failure. Longer file names and
 * messages are cut to fit. */
typedef struct sc_error {
    sc_status status;
    char file[SC_ERROR_FILE_MAX]; /* empty when the error has no source file */
    int line;                     /* 0 when the error has no position */
    int column;
    char message[SC_ERROR_MESSAGE_MAX];
} sc_error;

/* Formats "file:line:col: error: message" (or "error: message" without a
 * position) into buf, cut to size bytes with its terminating NUL (size > 0);
 * returns buf. Never fails; thread safe. */
const char *sc_error_format(const sc_error *error, char *buf, size_t size);

/* ---- scenes ---------------------------------------------------------- */

/* A compiled model: opaque, immutable once loaded. */
typedef struct sc_scene sc_scene;

/* How a model is loaded (a sized struct). */
typedef struct sc_load_options {
    size_t size;  /* sizeof (sc_load_options) as compiled: set by the init call */
    int faithful; /* spheres and cylinders as OpenSCAD's polyhedra for $fn, $fa, $fs */
    int strict;   /* a warning that leaves a part out or renders it otherwise is an
                     error: a polyhedron or imported mesh that is not closed (by
                     default left out with faithful, else rendered by the parity
                     rule), a file that cannot be read, a matrix that is not
                     finite */
    /* the most triangles that the meshes of one load may have, all together:
       polyhedra, imports and surfaces built as meshes, twisted, scaled and
       faithful extrusions, hulls built as meshes. A load past it fails with
       SC_ERR_LIMIT at the mesh that passes it, before that mesh is checked
       or indexed, so that a small file cannot ask for unbounded work. 0
       means the default, 67108864 (2^26); a program that loads untrusted
       models may set less (the fuzzer sets 65536) */
    size_t max_triangles;
    /* the threads that build a large model's hierarchies (65,536 operands
       or triangles and more): 0 (default): all cores, as OpenMP counts
       them; the scene does not depend on it */
    int threads;
    /* the text is OpenSCAD's export of a file it converted (a .scad):
       OpenSCAD gave the warnings of its arguments as it converted it, and
       the export's own (its timestamp, an alpha it folded into the colour)
       are not the user's, so they are not given again (default 0) */
    int openscad_export;
    /* 1: the scene will not be rendered with sc_render_options.preview, so
       what only the preview draws is not built: its '#' and '%' parts, and
       its own solid where that differs from the render's (a '#' operand of
       a union, the 2D objects of a 3D model, every 2D model), which is a
       second walk of the model. A preview of such a scene shows the
       render's solid without parts. 0 (default): both are built */
    int no_preview;
} sc_load_options;

/* Makes the font file at path (.ttf, .otf) one that text() finds by its
 * family name in every later load of this process, as OpenSCAD's
 * use <font.ttf> registers it (fontconfig's application fonts): the spancast
 * tool registers the fonts a .scad uses before it loads the model.
 * SC_ERR_ARGUMENT for a NULL path; SC_ERR_IO when the text plugin does not
 * load or fontconfig cannot read the file. Thread safe. */
sc_status sc_font_register(const char *path, sc_error *error);

/* Sets size and the defaults (faithful 0, strict 0, max_triangles 0,
 * threads 0, openscad_export 0, no_preview 0). Never fails. */
void sc_load_options_init_size(sc_load_options *options, size_t size);
#define sc_load_options_init(options)                                                    \
    sc_load_options_init_size((options), sizeof *(options))

/* Loads and compiles a model file; options may be NULL (the defaults).
 * A path ending in .stl, .off, .amf or .3mf (any case) is a mesh, loaded as
 * sc_scene_load_mesh loads it; any other file is the .csg grammar, in
 * which OpenSCAD's language beyond its CSG export (assignments,
 * expressions, modules, ...) is SC_ERR_UNSUPPORTED at its first use (the
 * library does not run OpenSCAD; the spancast tool converts such a file
 * with it). On success *scene owns everything it needs (release with
 * sc_scene_release); on failure *scene is NULL and error says why:
 * SC_ERR_IO (the file), SC_ERR_SYNTAX, SC_ERR_SEMANTIC, SC_ERR_UNSUPPORTED
 * and SC_ERR_LIMIT with the position in the file, SC_ERR_NOMEM,
 * SC_ERR_ARGUMENT (a NULL path or scene pointer, bad options). Calls
 * loading different scenes may run at once. */
sc_status sc_scene_load(const char *path, const sc_load_options *options,
                        sc_scene **scene, sc_error *error);

/* Same, from length bytes of text in memory (not necessarily
 * NUL-terminated); name is used in error positions and, as the file's
 * folder, to find files the model imports. The text is copied. */
sc_status sc_scene_load_string(const char *name, const char *text, size_t length,
                               const sc_load_options *options, sc_scene **scene,
                               sc_error *error);

/* Frees the scene and everything it owns; NULL is ignored. */
void sc_scene_release(sc_scene *scene);

/* World bounding box of the solid into lo and hi; returns 1, or 0 (lo and
 * hi unset) when the solid is empty. Thread safe. */
int sc_scene_bounds(const sc_scene *scene, double lo[3], double hi[3]);

/* Warnings collected while loading (e.g. a singular transform flattened to an
 * empty solid), in source order: their number, and warning index (NULL
 * past the last; it belongs to the scene). Thread safe. */
size_t sc_scene_warning_count(const sc_scene *scene);
const sc_error *sc_scene_warning(const sc_scene *scene, size_t index);

/* Tree statistics for `spancast info`: the compiled tree, and the tree as
 * the file describes it before simplification. */
#define SC_LEAF_KINDS 16

typedef struct sc_scene_info {
    size_t size;       /* sizeof (sc_scene_info) as compiled: set by the init call */
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
    /* 1 for a 2D model, built as the slab OpenSCAD draws a 2D result: 1
     * unit thick, from z = -0.5 to 0.5 (so its volume is its area) */
    size_t flat_2d;
} sc_scene_info;

/* Name of leaf kind index k ("sphere", "box", ...), NULL past the last or
 * for k < 0. Static strings; thread safe. */
const char *sc_leaf_kind_name(int k);

/* Sets size and zeroes the rest. Never fails. */
void sc_scene_info_init_size(sc_scene_info *info, size_t size);
#define sc_scene_info_init(info) sc_scene_info_init_size((info), sizeof *(info))

/* Fills *info (set up by sc_scene_info_init) with the scene's statistics.
 * SC_ERR_ARGUMENT for a NULL scene or info or one never set up. Thread
 * safe. */
sc_status sc_scene_get_info(const sc_scene *scene, sc_scene_info *info, sc_error *error);

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

/* ---- preview renders: colour schemes, edges, overlays, views, sections */

/* A render colour scheme as OpenSCAD 2021.01 defines one: display values
 * (sRGB-encoded, 0..1), named after the keys of its JSON files. */
#define SC_COLOR_SCHEME_NAME_MAX 64

typedef struct sc_color_scheme {
    char name[SC_COLOR_SCHEME_NAME_MAX];
    float background[3];       /* "background" */
    float axes[3];             /* "axes-color": axes and scale marks */
    float face_front[3];       /* "opencsg-face-front": faces in the preview */
    float face_back[3];        /* "opencsg-face-back": subtracted faces in the preview */
    float render_face[3];      /* "cgal-face-front": faces in the render */
    float render_face_back[3]; /* "cgal-face-back": subtracted faces in the render */
    float edge[3];             /* "cgal-edge-front": edge lines */
    float crosshair[3];        /* "crosshair" */
} sc_color_scheme;

/* The folder OpenSCAD's Debian package installs its render colour schemes
 * in; sc_color_scheme_find reads it when given no other. */
#define SC_COLOR_SCHEME_FOLDER "/usr/share/openscad/color-schemes/render"

/* Fills scheme with OpenSCAD's built-in scheme, Cornfield. Never fails;
 * thread safe. */
void sc_color_scheme_default(sc_color_scheme *scheme);

/* Finds the scheme called name (as OpenSCAD names it: "Cornfield",
 * "Metallic", "Tomorrow Night", ...): Cornfield is built in, the others
 * are read from the *.json files of folder (NULL: SC_COLOR_SCHEME_FOLDER),
 * as OpenSCAD reads them; a file that is not a valid scheme is passed
 * over, as OpenSCAD passes it over. An unknown name is SC_ERR_ARGUMENT
 * with a message listing the names there are; SC_ERR_NOMEM. On failure
 * scheme is left as it was. Reads the folder's files; thread safe. */
sc_status sc_color_scheme_find(const char *name, const char *folder,
                               sc_color_scheme *scheme, sc_error *error);

/* How surfaces are lit. */
typedef enum sc_lighting {
    SC_LIGHTING_DEFAULT = 0, /* the file's light() nodes, else spancast's own rig */
    SC_LIGHTING_OPENSCAD     /* OpenSCAD's: the preview shader's one light with
                                preview set, the render's two fixed lights
                                otherwise; no shadows, no light() nodes */
} sc_lighting;

/* What is drawn over the shaded model (sc_render_options.view, or'ed). */
enum {
    SC_VIEW_EDGES = 1,     /* silhouettes, creases and boolean seams */
    SC_VIEW_AXES = 2,      /* OpenSCAD's axes, and its small axes in the corner */
    SC_VIEW_SCALES = 4,    /* tick marks along the axes (with SC_VIEW_AXES) */
    SC_VIEW_CROSSHAIRS = 8 /* OpenSCAD's crosshairs at the view's centre */
};

/* OpenSCAD's View menu. */
typedef enum sc_view_preset {
    SC_VIEW_PRESET_NONE = 0,
    SC_VIEW_PRESET_TOP,
    SC_VIEW_PRESET_BOTTOM,
    SC_VIEW_PRESET_LEFT,
    SC_VIEW_PRESET_RIGHT,
    SC_VIEW_PRESET_FRONT,
    SC_VIEW_PRESET_BACK,
    SC_VIEW_PRESET_DIAGONAL
} sc_view_preset;

/* The preset's name ("top", ...), NULL for SC_VIEW_PRESET_NONE or an
 * unknown value. Static strings; thread safe. */
const char *sc_view_preset_name(sc_view_preset preset);

/* The preset called name, SC_VIEW_PRESET_NONE when there is none (or name
 * is NULL). Thread safe. */
sc_view_preset sc_view_preset_from_name(const char *name);

/* The preset's rotation as OpenSCAD's $vpr (degrees), for the gimbal
 * camera, into rotation; returns 1, or 0 (rotation unset) for
 * SC_VIEW_PRESET_NONE or an unknown value. Thread safe. */
int sc_view_preset_rotation(sc_view_preset preset, double rotation[3]);

#define SC_MAX_SECTIONS 8 /* --section planes */
#define SC_MAX_SHEET 16   /* views of a contact sheet */

typedef enum sc_section_style {
    SC_SECTION_SOLID = 0, /* caps in one colour */
    SC_SECTION_HATCH      /* caps hatched at 45 degrees */
} sc_section_style;

/* How sc_render renders (a sized struct; fields may be appended). */
typedef struct sc_render_options {
    size_t size;       /* sizeof (sc_render_options) as compiled: set by the init call */
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
     * handler may set it), sc_render stops within milliseconds (it is
     * polled inside tiles, down to the root finders) and returns
     * SC_ERR_CANCELLED, and the writers of its framebuffer give up without
     * touching their target. NULL by default. */
    const volatile sig_atomic_t *cancel;

    /* Preview renders. */
    int use_scheme;         /* 1: colours from scheme: the background (over the
                               file's background()), faces without a colour and
                               subtracted faces; 0 (default): the file's and
                               Cornfield's face colour; edges, axes, crosshairs and
                               caps take scheme's colours either way */
    sc_color_scheme scheme; /* Cornfield by default */
    int preview;            /* 1: OpenSCAD's preview (F5) face colours (face_front,
                               face_back; subtracted faces take face_back even
                               without use_scheme), its '#' and '%' parts and
                               colour alpha (docs/preview.md); 0 (default): its
                               render's (F6: render_face, render_face_back) */
    sc_lighting lighting;   /* default SC_LIGHTING_DEFAULT */
    unsigned view;          /* SC_VIEW_* flags; 0 (default): none */
    double edge_angle_deg;  /* creases: normals further apart than this (default 30) */
    double edge_width;      /* edge lines' width in pixels (default 1) */
    int section_count;      /* half-spaces n.p <= d that keep the solid (default 0) */
    double section[SC_MAX_SECTIONS][4]; /* nx, ny, nz, d; n need not be unit */
    sc_section_style section_style;
    int ao_samples;   /* ambient occlusion rays per sample; 0 (default): none */
    double ao_radius; /* their reach, a fraction of the model's diagonal
                         (default 0.1) */
    /* A contact sheet: sheet_count > 0 renders one tile of width x height per
     * view, in this order, in a grid of ceil(sqrt(n)) columns, each framed
     * like viewall with autocenter and labelled with its name; the image is
     * columns * width by rows * height pixels and region is a crop of it. */
    int sheet_count;
    sc_view_preset sheet[SC_MAX_SHEET];
    /* The first recorded ABI ends here; new fields go below, in release
     * order, and take their defaults for a caller whose struct ends here. */

    /* Distribution ray tracing (docs/distribution.md). */
    double aperture;   /* thin-lens diameter in world units; 0 (default): a pinhole,
                          everything sharp */
    double focus;      /* distance from the eye to the sharp plane; 0 (default): the
                          distance to the view's centre */
    double shutter[2]; /* open, close in [0, 1]: motion() nodes are at their from
                          at 0 and their to at 1, and each sample's rays take a
                          time in [open, close]; both 0 (default): closed at 0 */

    /* Rendering the spp samples of each pixel in passes (a viewer refining a
     * still view): a call renders samples sample_start to sample_start +
     * sample_count - 1 of the spp laid out for the whole image (the same
     * strata, jitter and random streams as one render of spp samples).
     * sample_start is 0 by default, sample_count 0 (default) means up to spp;
     * start + count must not pass spp. sample_sum, when not NULL, holds 3
     * doubles (linear r, g, b) per pixel of the framebuffer (the region's
     * size when there is one, row 0 at the top), owned by the caller: each
     * sample's colour is added to it in sample order, and the colour buffer
     * gets the mean of all samples summed so far, sample_sum / (sample_start
     * + count). Zeroed before the first pass and handed to every pass, it
     * makes the pass that ends at spp write the very colours of one render of
     * spp samples, bit for bit. Without it the colour buffer holds the mean
     * of this call's samples. After SC_ERR_CANCELLED its content is
     * unspecified (some pixels hold more samples than others): start again
     * from zero. */
    int sample_start;
    int sample_count;
    double *sample_sum;

    /* The colour scheme's 2D colours ("cgal-face-2d", "cgal-edge-2d"), in
     * which the render (not the preview) of a 2D model draws its polygons,
     * where the file gives them no colour, and their outlines, as OpenSCAD's
     * render draws a 2D result (docs/extrusions.md); Cornfield's by default
     * (#00bf99, #ff0000). sc_render_options_set_scheme sets them with
     * scheme. */
    float face_2d[3];
    float edge_2d[3];
} sc_render_options;

/* Sets size and the defaults written beside each field. Never fails. */
void sc_render_options_init_size(sc_render_options *options, size_t size);
#define sc_render_options_init(options)                                                  \
    sc_render_options_init_size((options), sizeof *(options))

/* Sets options->scheme and the scheme's 2D colours (options->face_2d and
 * edge_2d, which the fixed record sc_color_scheme has no room for) to the
 * scheme called name, found as sc_color_scheme_find finds it, and sets
 * use_scheme, so that the render is the scheme's, as --colorscheme makes
 * it. Options
 * from a header without edge_2d are SC_ERR_ARGUMENT. On failure options is
 * left as it was. Reads the folder's files; thread safe. */
sc_status sc_render_options_set_scheme(sc_render_options *options, const char *name,
                                       const char *folder, sc_error *error);

/* Applies the scene's own settings to options: a camera() node in the file
 * sets camera_mode (SC_CAMERA_VECTOR), camera, up, fov_deg, projection,
 * aperture and focus.
 * Call it after sc_render_options_init and before applying the user's own
 * choices, so that those override the file. Returns 1 when the file has a
 * camera, else 0 (options unchanged, also for a NULL scene). Writes only
 * those fields; thread safe. */
int sc_render_options_from_scene(sc_render_options *options, const sc_scene *scene);

/* Counters of one render, summed over threads. */
typedef struct sc_render_stats {
    size_t size; /* sizeof (sc_render_stats) as compiled: set by the init call */
    /* camera_rays counts edge lines' neighbour rays too; shadow_rays the
     * ambient occlusion rays */
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

/* Sets size and zeroes the rest. Never fails. */
void sc_render_stats_init_size(sc_render_stats *stats, size_t size);
#define sc_render_stats_init(stats) sc_render_stats_init_size((stats), sizeof *(stats))

/* A rendered image (opaque): its buffers are row-major, row 0 at the top. */
typedef struct sc_framebuffer sc_framebuffer;

/* Renders the scene; options may be NULL (the defaults). On success
 * *framebuffer is owned by the caller (release with
 * sc_framebuffer_release); on failure it is NULL and error says why:
 * SC_ERR_ARGUMENT for bad options (an image size, camera or region out of
 * range, options never set up), SC_ERR_LIMIT when the buffers would take
 * more than 16 GiB or more than the machine's memory (checked before they
 * are allocated; docs/limits.md), SC_ERR_CANCELLED, SC_ERR_NOMEM. It runs
 * on options->threads threads of its own (OpenMP); several renders of one
 * scene may run at once. */
sc_status sc_render(const sc_scene *scene, const sc_render_options *options,
                    sc_framebuffer **framebuffer, sc_error *error);

/* Frees the framebuffer and its buffers; NULL is ignored. */
void sc_framebuffer_release(sc_framebuffer *framebuffer);

/* The image's size in pixels: the region's when the options asked for one,
 * else the whole image's (a contact sheet's: all its tiles). */
int sc_framebuffer_width(const sc_framebuffer *fb);
int sc_framebuffer_height(const sc_framebuffer *fb);

/* Where this image lies in the whole image (the options' region), into
 * *x0 and *y0; 0, 0 without a region. */
void sc_framebuffer_offset(const sc_framebuffer *fb, int *x0, int *y0);

/* The buffers the options asked for (want_color, ...), NULL for the others.
 * They belong to the framebuffer, width * height pixels each. */
/* RGB, 3 floats per pixel, scene-linear (sRGB primaries), >= 0 */
const float *sc_framebuffer_color(const sc_framebuffer *fb);
/* distance along the ray to the hit (t * |direction|), +inf on a miss */
const float *sc_framebuffer_depth(const sc_framebuffer *fb);
/* 255 where the camera ray hits, 0 elsewhere */
const uint8_t *sc_framebuffer_mask(const sc_framebuffer *fb);
/* world normal, 3 floats per pixel, 0 on a miss */
const float *sc_framebuffer_normal(const sc_framebuffer *fb);
/* index of the leaf the camera ray hit (source order), -1 on a miss */
const int32_t *sc_framebuffer_id(const sc_framebuffer *fb);

/* The camera in words, as the image files' metadata carry it; belongs to
 * the framebuffer. */
const char *sc_framebuffer_camera_info(const sc_framebuffer *fb);

/* The render's counters into *stats (set up by sc_render_stats_init).
 * SC_ERR_ARGUMENT for NULL arguments or stats never set up. */
sc_status sc_framebuffer_get_stats(const sc_framebuffer *fb, sc_render_stats *stats,
                                   sc_error *error);

/* Image output through OpenImageIO; the format follows the file extension.
 * Colour goes to 8-bit formats (PNG, JPEG, ...) sRGB-encoded, to float
 * formats (EXR, float TIFF, ...) as the linear values; every file carries
 * the software name and the camera in its metadata.
 * Each writes a temporary file in the target's folder and renames it into
 * place, so a failure never leaves a partial file or destroys an existing
 * one. When fb->cancel is set before the rename, the temporary is removed,
 * the target is left as it was and the call returns SC_ERR_CANCELLED.
 * Errors: SC_ERR_IO (the message names the file and the reason),
 * SC_ERR_UNSUPPORTED for a format that needs the OpenImageIO plugin when
 * it cannot be loaded, SC_ERR_ARGUMENT for a buffer the render did not
 * fill, SC_ERR_NOMEM. Calls writing different files may run at once. */
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
    size_t size; /* sizeof (sc_ray_query) as compiled: set by the init call */
    double origin[3];
    double direction[3]; /* finite, not zero */
    int both_ways;       /* 0 (default): the ray t >= 0; 1: the whole line */
} sc_ray_query;

/* Sets size, origin and direction to 0 and both_ways to 0. Never fails. */
void sc_ray_query_init_size(sc_ray_query *query, size_t size);
#define sc_ray_query_init(query) sc_ray_query_init_size((query), sizeof *(query))

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

/* One span (read through sc_span_list_get; may gain fields at its end). */
typedef struct sc_span {
    sc_span_end in, out; /* in.t < out.t */
    double distance;     /* (out.t - in.t) * |direction|: the length inside */
} sc_span;

/* The spans of one line (opaque). */
typedef struct sc_span_list sc_span_list;

/* ALL_SPANS for one line: the sorted, disjoint intervals of the query's
 * ray (t >= 0, or the whole line with both_ways) inside the solid, after
 * the regularisation rule (README: "How a ray meets the solid"). On success
 * *out belongs to the caller (release with sc_span_list_release) and may
 * hold no spans; on failure *out is NULL and error says why:
 * SC_ERR_ARGUMENT for a direction that is zero or a value that is not
 * finite or a query never set up, SC_ERR_NOMEM, and SC_ERR_LIMIT (at the
 * leaf's position) when an implicit surface needs more than 2^22
 * evaluations to resolve along the line, whose spans past that point
 * would be unsearched: no list is ever cut short silently. The scene is
 * only read: calls on one scene from several threads at once are safe. */
sc_status sc_scene_spans(const sc_scene *scene, const sc_ray_query *query,
                         sc_span_list **out, sc_error *error);

/* The number of spans; 0 for NULL. Thread safe. */
size_t sc_span_list_count(const sc_span_list *list);

/* Span index (0 = nearest along the direction), or NULL past the last. The
 * pointer is valid until the list is released. */
const sc_span *sc_span_list_get(const sc_span_list *list, size_t index);

/* Frees the list; NULL is ignored. */
void sc_span_list_release(sc_span_list *list);

/* The box that the default camera, --viewall and --autocenter frame under
 * options (NULL: the defaults), into lo and hi: for the render, the
 * solid's own box, without what its booleans cut away (OpenSCAD frames
 * the mesh it computed), and a 2D model's polygons; for options->preview,
 * the boxes OpenSCAD's preview frames (its CSG products', with the
 * modifier parts). The render's box is found by searching the solid along
 * lines (docs/camera.md), so it may leave out a spike thinner than its
 * grid; sc_scene_bounds's box holds everything. Returns 1, or 0 (lo and
 * hi 0) when that box is empty or options are not valid. Thread safe. */
int sc_scene_frame_bounds(const sc_scene *scene, const sc_render_options *options,
                          double lo[3], double hi[3]);

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
 * surface never is. Where no axis line finds it so (a point on an edge or a
 * corner of a mesh, where each axis line lies in a face or along the edge
 * and the mesh breaks the tie as a miss), four oblique lines through p,
 * whose directions and their opposites cover the eight octants, are asked
 * the same. Otherwise SC_INSIDE when p lies inside a span of at
 * least two of the three lines (they agree except where a line grazes a
 * surface), else SC_OUTSIDE. Returns SC_ERR_ARGUMENT for a coordinate that
 * is not finite, SC_ERR_NOMEM, and SC_ERR_LIMIT as sc_scene_spans does for
 * one of the lines. Thread safe. */
sc_status sc_scene_inside(const sc_scene *scene, const double p[3], int *where,
                          sc_error *error);

/* ---- queries: measures, overlaps, comparison ------------------------- */

/* Options of the integrating queries (sc_scene_measure, sc_objects_overlaps,
 * sc_scene_compare): they integrate over grids of parallel lines along the
 * three axes, refined where the estimated error is largest until it is
 * within tolerance (docs/measure.md). */
typedef struct sc_measure_options {
    size_t size;      /* sizeof (sc_measure_options) as compiled: set by the init call */
    double tolerance; /* relative error aimed at (default 1e-4) */
    double density;   /* mass per unit volume, for mass and inertia (default 1) */
    int threads;      /* 0 (default): all cores; the result does not depend on it */
    uint64_t max_lines; /* lines per axis before giving up on the tolerance
                           (default 4,000,000) */
    /* Called from the calling thread with the fraction done (0..1), as
     * sc_render_options.progress; NULL: not called. */
    void (*progress)(void *user, double fraction);
    void *progress_user;
    const volatile sig_atomic_t *cancel; /* as sc_render_options.cancel */
    /* The first recorded ABI ends here; new fields go below. */

    /* Several processes sharing one integration (an MPI job: docs/mpi.md),
     * each calling the query with the same scene and options but its own
     * part. The lines of each round, numbered 0 .. count-1, are cut into
     * parts runs in order; run p is lines count*p/parts up to (not
     * including) count*(p+1)/parts, and this process casts run part only.
     * The result is the same, to the last bit, on every process and as
     * with one: every line is cast exactly as alone, and everything that
     * adds lines up runs, in the same order, on every process. */
    int parts; /* 0 or 1 (default): this process casts every line */
    int part;  /* this process's run, 0 .. parts-1 */
    /* Called from the calling thread by every process at once, after each
     * round: records holds count records of size bytes, those of this
     * process's run filled; on return every record must hold what the
     * process owning its run wrote. outcome (3 ints: a status, and for
     * SC_ERR_LIMIT the reason and the leaf) is this process's on the way
     * in and,
     * on the way out, the first one (in part order) whose status is not
     * SC_OK, or this one's when all are. Returns 0 when the exchange
     * failed (the query then fails on every process). */
    int (*share_lines)(void *user, void *records, size_t size, size_t count,
                       int outcome[3]);
    /* Called likewise once at the end with box (lo xyz, hi xyz) of what
     * this process saw; on return the smallest lo and largest hi over all
     * processes. Returns 0 when the exchange failed. */
    int (*share_box)(void *user, double box[6]);
    void *share_user;
} sc_measure_options;

/* Sets size and the defaults written beside each field. Never fails. */
void sc_measure_options_init_size(sc_measure_options *options, size_t size);
#define sc_measure_options_init(options)                                                 \
    sc_measure_options_init_size((options), sizeof *(options))

/* A measured value and a bound on its error: the true value lies within
 * value +- error when the integrand has no feature smaller than the grid
 * resolves (docs/measure.md says how each bound is made). */
typedef struct sc_estimate {
    double value;
    double error;
} sc_estimate;

typedef struct sc_measure {
    size_t size; /* sizeof (sc_measure) as compiled: set by the init call */
    sc_estimate volume;
    sc_estimate area;
    sc_estimate mass;        /* volume * density */
    sc_estimate centroid[3]; /* centre of mass */
    /* Inertia tensor about the centroid (mass units times length squared),
     * I[i][j] = integral of density (|r|^2 delta_ij - r_i r_j) over the solid. */
    sc_estimate inertia[3][3];
    sc_estimate principal[3]; /* principal moments, ascending */
    double axes[3][3];        /* axes[k]: unit axis of principal[k] */
    sc_estimate box_lo[3];    /* tight bounding box: the sampled extremes, with */
    sc_estimate box_hi[3];    /* the distance to the tree's outer box as error */
    double volume_by_axis[3]; /* the volume from the x, y and z lines alone */
    uint64_t lines;           /* lines cast, all axes */
    int converged;            /* 1: volume and area reached the tolerance */
    int threads;              /* threads used */
} sc_measure;

/* Sets size and zeroes the rest. Never fails. */
void sc_measure_init_size(sc_measure *measure, size_t size);
#define sc_measure_init(measure) sc_measure_init_size((measure), sizeof *(measure))

/* Volume, surface area, centroid, inertia and tight box of the solid into
 * *out (set up by sc_measure_init). An empty solid measures 0. Returns
 * SC_ERR_ARGUMENT for an unbounded solid, bad options or structs never set
 * up, SC_ERR_CANCELLED, SC_ERR_NOMEM. Runs on options->threads threads of
 * its own; several measures of one scene may run at once. */
sc_status sc_scene_measure(const sc_scene *scene, const sc_measure_options *options,
                           sc_measure *out, sc_error *error);

/* One pair of top-level objects whose interiors overlap (read through
 * sc_overlap_list_get; may gain fields at its end). */
typedef struct sc_overlap {
    size_t a, b;        /* object indices, a < b (sc_objects_location) */
    sc_estimate volume; /* volume of the intersection */
    double box_lo[3];   /* box of the intersection, as sampled */
    double box_hi[3];
    int converged; /* 1: the volume reached the tolerance (0: the line budget
                      ran out first) */
} sc_overlap;

/* The top-level objects of a model (opaque). */
typedef struct sc_objects sc_objects;

/* The overlapping pairs sc_objects_overlaps finds (opaque). */
typedef struct sc_overlap_list sc_overlap_list;

/* Loads the top-level objects of a model file, each as a scene of its own
 * (keeping the transforms above it): the statements at the top of the
 * file, or, where there is only one, the children of the group, union,
 * render, color or multmatrix node it is, descending while such a node has
 * a single child. options may be NULL (the defaults). On success *out
 * belongs to the caller (sc_objects_release); on failure it is NULL and
 * error says why, as sc_scene_load's. */
sc_status sc_objects_load(const char *path, const sc_load_options *options,
                          sc_objects **out, sc_error *error);

/* Same, from length bytes of text in memory (not necessarily
 * NUL-terminated); name is used in positions and, as the file's folder, to
 * find files the model imports. The text is copied. */
sc_status sc_objects_load_string(const char *name, const char *text, size_t length,
                                 const sc_load_options *options, sc_objects **out,
                                 sc_error *error);

/* The number of objects; 0 for NULL. Thread safe. */
size_t sc_objects_count(const sc_objects *objects);

/* Object index as a scene (it belongs to objects: never release it), NULL
 * past the last. Thread safe. */
const sc_scene *sc_objects_scene(const sc_objects *objects, size_t index);

/* Where object index is written (file points into objects), no position
 * past the last. Thread safe. */
sc_location sc_objects_location(const sc_objects *objects, size_t index);

/* Object index's node name ("cube", "difference", ...; points into
 * objects), NULL past the last. Thread safe. */
const char *sc_objects_name(const sc_objects *objects, size_t index);

/* Frees the objects and their scenes; NULL is ignored. */
void sc_objects_release(sc_objects *objects);

/* The pairs of objects whose common interior has a volume (solids that only
 * touch within the scene tolerance have none), in order of (a, b). On
 * success *out belongs to the caller (sc_overlap_list_release) and may hold
 * no pairs; on failure it is NULL and error says why: SC_ERR_ARGUMENT (bad
 * or uninitialised options), SC_ERR_CANCELLED, SC_ERR_NOMEM. The volume is
 * integrated to options->tolerance relative to itself (or to a millionth
 * of the box the pair shares, when smaller). Runs on options->threads
 * threads of its own; thread safe. */
sc_status sc_objects_overlaps(const sc_objects *objects,
                              const sc_measure_options *options, sc_overlap_list **out,
                              sc_error *error);

/* The number of pairs; 0 for NULL. Thread safe. */
size_t sc_overlap_list_count(const sc_overlap_list *list);

/* Pair index, or NULL past the last; valid until the list is released.
 * Thread safe. */
const sc_overlap *sc_overlap_list_get(const sc_overlap_list *list, size_t index);

/* Frees the list; NULL is ignored. */
void sc_overlap_list_release(sc_overlap_list *list);

/* Loads a closed mesh file (.stl, ASCII or binary, .off, .amf or .3mf) as a scene, as
 * the model import(file = path) would; ownership and errors as
 * sc_scene_load's. */
sc_status sc_scene_load_mesh(const char *path, const sc_load_options *options,
                             sc_scene **scene, sc_error *error);

typedef struct sc_comparison {
    size_t size; /* sizeof (sc_comparison) as compiled: set by the init call */
    sc_estimate volume_a, volume_b;
    sc_estimate only_a, only_b; /* volume of a minus b, of b minus a */
    sc_estimate difference;     /* the symmetric difference: only_a + only_b */
    uint64_t lines;
    int converged; /* 1: the differences reached the tolerance (0: the line
                      budget ran out first) */
} sc_comparison;

/* Sets size and zeroes the rest. Never fails. */
void sc_comparison_init_size(sc_comparison *comparison, size_t size);
#define sc_comparison_init(comparison)                                                   \
    sc_comparison_init_size((comparison), sizeof *(comparison))

/* Volumes of two solids and of their differences into *out (set up by
 * sc_comparison_init), from both span lists along the same lines; the
 * differences are integrated to options->tolerance times the mean of the
 * two volumes. Errors as sc_scene_measure's. Thread safe. */
sc_status sc_scene_compare(const sc_scene *a, const sc_scene *b,
                           const sc_measure_options *options, sc_comparison *out,
                           sc_error *error);

#ifdef __cplusplus
}
#endif

#endif
