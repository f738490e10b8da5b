/* The typed model: the syntax tree lowered once into one tagged node per
 * kind, with every argument read and checked. After it no stage sees the
 * syntax tree or compares node names.
 *
 * model_lower (lower.c) gives each node name its kind through one table,
 * reads its arguments into the node's typed fields (cube{size, center},
 * sphere{r, resolution}, multmatrix's affine map, ...) and checks their
 * types and values, with the messages and positions the file's reader
 * expects. The builders (src/build/) switch on model_kind.
 *
 * The model mirrors the walks the builders make over the file. In the
 * main model: the children of a group, union, render, difference,
 * intersection, multmatrix, color, material and resize; '*' subtrees are
 * left out (they are never read), and so are the children of a 3D leaf,
 * which the builder ignores with a warning. Nested subtrees, which their
 * builders read each in their own way, are lowered in their context:
 *   2D context       the children of the extrusions and of a 2D shape
 *                    (lower_twod.c)
 *   points context   the children of hull and minkowski, the 3D children
 *                    of projection (in whichever context it stands), and
 *                    each resize's subtree once more for its measuring
 *                    (lower_points.c)
 * In a nested context a node's argument error is kept in the node
 * (pending) and lowering goes on; the builder reports it where it reads
 * the node, so the first error in its walk is the one reported.
 *
 * An argument error in the main model is not a failure of the lowering:
 * the node that has it becomes a MODEL_ERROR node holding the error, the
 * last node of the model in file order, and lowering stops there. The
 * builder reports it when its walk reaches it, so an error the builder
 * finds earlier in the file (an open polyhedron, a missing import, a
 * nested node's pending error) is still the one reported, as when the two
 * stages were one.
 *
 * Every node is allocated from the model's arena (loading a million leaves
 * makes no million mallocs), the larger payloads (matrices, colours,
 * errors) apart from the node so that it stays small (128 bytes). The
 * model points into the syntax tree (names, strings), which must outlive
 * it.
 */
#ifndef SPANCAST_MODEL_MODEL_H
#define SPANCAST_MODEL_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "base/arena.h"
#include "implicit/expr.h"
#include "math/vec.h"
#include "model/params.h"
#include "model/shading.h"
#include "spancast/spancast.h"
#include "syntax/parse.h"

/* The largest $fn a node may set: it is the number of polygon sides that
 * OpenSCAD-faithful rendering builds, so an absurd value must not reach it.
 * A larger or non-finite $fn is an error at the value (docs/limits.md).
 * The same as FAITHFUL_MAX_FRAGMENTS, the most fragments of a circle. */
#define MODEL_MAX_FN 65536

typedef enum model_kind {
    MODEL_UNION, /* group, union, render */
    MODEL_DIFFERENCE,
    MODEL_INTERSECTION,
    MODEL_XFORM, /* multmatrix */
    MODEL_COLOR,
    MODEL_MATERIAL,
    MODEL_RESIZE,
    MODEL_MOTION, /* motion(from, to): its subtree moves during the shutter */
    /* Leaves: the builder does not walk their children (the extrusions,
     * hull and minkowski build from them themselves). */
    MODEL_CUBE,
    MODEL_SPHERE,
    MODEL_CYLINDER,
    MODEL_POLYHEDRON,
    MODEL_IMPORT,
    MODEL_LINEAR_EXTRUDE,
    MODEL_ROTATE_EXTRUDE,
    MODEL_CIRCLE, /* 2D shapes: in a 3D model checked, then ignored */
    MODEL_SQUARE,
    MODEL_POLYGON,
    MODEL_TEXT,
    MODEL_OFFSET,
    MODEL_PROJECTION, /* 2D from 3D children (lowered in the points context) */
    MODEL_HULL,
    MODEL_MINKOWSKI,
    MODEL_SURFACE,
    MODEL_TORUS,
    MODEL_QUADRIC,
    MODEL_IMPLICIT, /* the last leaf kind */
    /* Shading nodes: no geometry, and no children walked. */
    MODEL_LIGHT,
    MODEL_CAMERA,
    MODEL_BACKGROUND,
    /* An argument error found while lowering (see above). */
    MODEL_ERROR,
    /* Kinds model_kind_of gives and a lowered model never holds (lowering
     * makes them errors): spancast's halfspace, other names OpenSCAD
     * writes that are not supported yet, and unknown names. */
    MODEL_HALFSPACE,
    MODEL_UNSUPPORTED,
    MODEL_UNKNOWN
} model_kind;

/* Modifier flags (the parser's, PARSE_MOD_*). */
enum {
    MODEL_MOD_DISABLE = PARSE_MOD_DISABLE,
    MODEL_MOD_ROOT = PARSE_MOD_ROOT,
    MODEL_MOD_HIGHLIGHT = PARSE_MOD_HIGHLIGHT,
    MODEL_MOD_BACKGROUND = PARSE_MOD_BACKGROUND
};

/* $fn, $fa, $fs of a curved leaf: its own numbers, else those an ancestor
 * passes down (model_special_args), else OpenSCAD's defaults (0, 12, 2). */
typedef struct model_resolution {
    double fn, fa, fs;
} model_resolution;

/* color(c, alpha) as OpenSCAD 2021.01 reads it (color.cc): c = [r, g, b,
 * a] (a component that is not a number 0, a missing one 1) unless c[0] <
 * 0, or a known colour name, sets the colour (set), with the components
 * as written (the builder clamps them to 0..1 silently, as OpenGL does
 * OpenSCAD's); an unknown name, and a c of another type, leave it unset; a
 * number alpha replaces c[3], any other is ignored. Its warnings are the
 * instantiation's (params.h). */
typedef struct model_color {
    int set; /* c was read: a vector, or a name or "#hex" it knows */
    double c[4];
    int has_alpha; /* alpha given: it replaces c[3] when set */
    double alpha;
} model_color;

/* material(): the material its children get, and the base colour it sets
 * (when has_color), as color() does. */
typedef struct model_material {
    shading_material material;
    float color[3];
    int has_color;
} model_material;

/* circle(r = 1 | d, $fn, $fa, $fs): what a d of nan means is the
 * builder's (has_d says it was given). */
typedef struct model_circle {
    double r, d; /* d: nan when not given */
    int has_d;
    model_resolution res;
} model_circle;

/* motion(from = M0, to = M1): the subtree under M0 when the shutter
 * opens and under M1 when it closes (lower_motion.c). */
typedef struct model_motion {
    affine from, to;
} model_motion;

/* torus(r1, r2): major radius r1 in the xy plane, minor radius r2 < r1. */
typedef struct model_torus {
    double r1, r2;
    const char *empty; /* why it is empty (a warning where built), or NULL */
} model_torus;

/* quadric(a, bounds): A x^2 + B y^2 + C z^2 + D xy + E yz + F xz + G x + H y
 * + I z + J <= 0 inside the box. */
typedef struct model_quadric {
    double a[10]; /* finite */
    bbox box;
    const char *empty;
} model_quadric;

/* implicit(f, bounds, method, tolerance, params, lipschitz): f(x, y, z) < 0
 * inside the box, f compiled. */
typedef struct model_implicit {
    expr_program program;
    bbox box;
    double tolerance; /* > 0 */
    double lipschitz; /* > 0 when given, else 0 */
    int method;       /* solve_method */
    const char *empty;
} model_implicit;

/* import(file) of a mesh, in a 3D model. */
typedef enum model_mesh_format {
    MODEL_MESH_STL,
    MODEL_MESH_OFF,
    MODEL_MESH_AMF,
    MODEL_MESH_3MF,
    /* any other extension: OpenSCAD 2021.01's "Unsupported file format", an
     * empty import (build_mesh.h) */
    MODEL_MESH_UNSUPPORTED
} model_mesh_format;
/* import(file) outside the 2D context: a mesh, or a .dxf or .svg drawing
 * (drawing set), whose dimension is 2 wherever it stands, as in OpenSCAD,
 * where the file's extension decides what import() makes. The drawing's
 * arguments are read as in the 2D context, their error pending. */
typedef struct model_import {
    const char *file; /* as written */
    sc_location file_loc;
    model_mesh_format format;            /* a mesh (drawing NULL) */
    const struct model_drawing *drawing; /* or NULL */
} model_import;

/* surface(file, center, invert): a height map (.dat or PNG). */
typedef struct model_surface {
    const char *file; /* as written */
    sc_location file_loc;
    int center, invert;
} model_surface;

typedef struct model_node model_node;

/* A polyhedron's point index out of range: its value as written, its
 * face and place in the face as written, and its position. */
typedef struct model_bad_index {
    double value;
    uint32_t face, place;
    sc_location loc;
} model_bad_index;

/* A point that OpenSCAD 2021.01 cannot convert where a polyhedron's face
 * or a polygon reads it: not a vector of 3 numbers (or 2: z is then 0) for
 * a polyhedron, of 2 numbers for a polygon, or a number in it not finite
 * (for a polygon: infinite; spancast takes no nan there either). OpenSCAD
 * logs "Unable to convert points[3] = [0, 0, "a"] to a vec3 of numbers"
 * and stops reading there: a polyhedron keeps the faces before it, a
 * polygon is empty. The builders give the message as a warning. */
typedef struct model_bad_point {
    uint32_t index;   /* its place in points */
    int not_finite;   /* numbers, one of them nan or inf */
    sc_location loc;  /* the point's */
    const char *text; /* the point as OpenSCAD echoes it (model_echo_value) */
} model_bad_point;

/* The 2D nodes below an extrusion, and a 2D shape in a 3D model, are
 * lowered in the 2D context: every builder of 2D subtrees (the 2D engine,
 * the exact region and revolve profiles, text) reads them, each at its own
 * point of its walk, so an argument error does not end the lowering there.
 * It is kept in the node (pending) for the builder to report where it
 * reads the arguments, which keeps the first error in the builder's order
 * the one reported. '*' subtrees are left out; '%' ones are lowered (text
 * detection looks into them). 2D nodes lower no argument they do not use:
 * color, 2D hull and minkowski take none. */

/* square(size, center) */
typedef struct model_square {
    double sx, sy;
    int center;
} model_square;

/* polygon(points, paths): the paths' point indices in file order. An index
 * is read as OpenSCAD 2021.01 reads it (model_index_value: truncated toward
 * zero, 0 when it is not a number), and one out of range is left out of
 * its path and listed in bad, as OpenSCAD leaves it out with a warning,
 * which the builder gives. */
typedef struct model_polygon {
    const double *xy; /* points, 2 per point, finite */
    uint32_t point_count;
    int has_points;             /* points given */
    int has_paths;              /* paths given (maybe an empty vector) */
    uint32_t path_count;        /* paths */
    const uint32_t *path_start; /* path k: index[path_start[k] .. [k + 1]) */
    const uint32_t *index;
    const model_bad_index *bad;
    uint32_t bad_count;
    const model_bad_point *bad_point; /* the polygon is then empty; or NULL */
    /* 1 + the first contour (path k, or 0: all the points) that OpenSCAD
     * 2021.01's clipper refuses (lower_twod.c: a coordinate past about
     * 7.04e13 in magnitude): it and those after it are left out with
     * "Range check failed for polygon. skipping"; 0: none */
    uint32_t range_bad;
} model_polygon;

/* offset(r | delta, chamfer, $fn, $fa, $fs) */
typedef struct model_offset {
    double delta; /* r when has_r, else delta, 1 when neither */
    int has_r, has_delta, chamfer;
    model_resolution res;
} model_offset;

/* The formats of a 2D import. */
typedef enum model_drawing_format {
    MODEL_DRAWING_DXF,
    MODEL_DRAWING_SVG
} model_drawing_format;

/* OpenSCAD's default dpi of an SVG import: 72 user units to the inch, so
 * that a unit is a typographic point (import.cc, SVG_DEFAULT_DPI). */
#define MODEL_SVG_DPI 72.0

/* import(file = "x.dxf", layer, origin, scale, $fn, $fa, $fs) and
 * import(file = "x.svg", center, dpi) in 2D; also the drawing of an
 * extrusion's file form (lower_twod.c), lowered as its only child. */
typedef struct model_drawing {
    const char *file; /* as written */
    sc_location file_loc;
    model_drawing_format format;
    int not_2d;              /* not a .dxf nor .svg: the builder names its context */
    const char *layer;       /* or NULL (DXF) */
    double origin[2], scale; /* DXF: scale > 0, or not finite */
    /* DXF: 1 when the origin or the scale is not finite, which puts every
     * point at no finite place, so the drawing is empty, as OpenSCAD
     * 2021.01 draws it */
    int far;
    int center; /* SVG: centre the drawing's bounds on the origin */
    double dpi; /* SVG: user units to the inch, >= 0.001 */
    model_resolution res;
} model_drawing;

/* linear_extrude(height = 100, center, twist, slices, scale, $fn, $fa,
 * $fs). Its builders read different arguments: the exact ones height and
 * center only (their error is exact_error), the faithful one all (its
 * error is the node's pending one). */
typedef struct model_linear_extrude {
    double height;
    int center;
    double twist;  /* finite */
    double slices; /* a given count >= 1, truncated; else 0 */
    double sx, sy; /* scale, finite, a negative one 0 */
    model_resolution res;
    int plain; /* twist absent or 0, scale absent, 1 or [1, 1] (not checked) */
    const sc_error *exact_error; /* or NULL */
} model_linear_extrude;

/* rotate_extrude(angle = 360, convexity, $fn, $fa, $fs) */
typedef struct model_rotate_extrude {
    double angle; /* as given */
    model_resolution res;
} model_rotate_extrude;

/* resize(newsize, auto): the sizes (0: keep) and which directions scale
 * with the largest given one. In the main model the builder measures the
 * resize node lowered in the points context (measured), whose children
 * are that context's; in the points context measured is NULL (the node
 * itself is measured). */
typedef struct model_resize {
    double size[3];     /* finite, as given (the builder reads a negative one) */
    double autosize[3]; /* 0 or 1 */
    const model_node *measured;
} model_resize;

/* The most slices of one linear_extrude. */
#define MODEL_MAX_SLICES 1000000.0

/* The most bytes text() lays out. */
#define MODEL_MAX_TEXT_BYTES 10000

/* text(text, size, font, direction, language, script, halign, valign,
 * spacing, $fn, $fa, $fs) */
typedef struct model_text {
    const char *text;
    size_t length;
    double size, spacing; /* finite */
    model_resolution res;
    const char *font, *direction, *language, *script, *halign, *valign;
} model_text;

struct model_node {
    model_kind kind;
    unsigned modifiers;   /* MODEL_MOD_* */
    int is_root;          /* the first '!' node: its subtree is the design */
    int not_finite;       /* multmatrix with a nan or inf entry (xform) */
    int unsized;          /* a solid in the 2D context whose size could not be read */
    const char *name;     /* as the file writes it, for messages */
    sc_location loc;      /* of the name */
    uint32_t child_count; /* children written in the file (lowered or not) */
    model_node *first_child, *next; /* lowered children, in file order */
    /* 2D context (above): the node's argument error, for its builder to
     * report where it reads the arguments; NULL when they are good. */
    const sc_error *pending;
    union {
        struct {
            double size[3];
            int center;
        } cube;
        struct {
            double r;
            model_resolution res;
        } sphere;
        struct {
            double h, r1, r2; /* r1 at the bottom (z = 0 or -h/2) */
            int center;
            model_resolution res;
        } cylinder;
        struct {
            const vec3 *points; /* finite */
            uint32_t point_count;
            const uint32_t *indices;    /* every face's point indices, in range */
            const uint32_t *face_start; /* face f: indices[face_start[f] .. [f + 1]) */
            uint32_t face_count;        /* each face has 3 points or more (not
                                           below hull, minkowski and resize) */
            /* the indices out of range, left out of their faces as
             * OpenSCAD 2021.01 leaves them out with a warning, which the
             * builders give where they build the node */
            const model_bad_index *bad;
            uint32_t bad_count;
            /* the point the faces ended at, or NULL */
            const model_bad_point *bad_point;
            /* the faces of fewer than 3 points (after the indices out of
             * range), left out (kept where face_count's note says):
             * OpenSCAD 2021.01 warns of them once, as it tessellates the
             * polyhedron ("PolySet has degenerate polygons"); the first
             * is faces[degenerate_face], at degenerate_loc */
            uint32_t degenerate, degenerate_face;
            sc_location degenerate_loc;
        } polyhedron;
        /* multmatrix: rows of the 3x4 affine part; the zero map when an
         * entry is nan or inf (not_finite), which OpenSCAD 2021.01 removes
         * with a warning: every walk takes it as a singular transform (no
         * geometry), and the builders warn of it */
        const affine *xform;
        const model_color *color; /* color */
        const model_import *import;
        const model_surface *surface;
        const model_torus *torus;
        const model_quadric *quadric;
        const model_implicit *implicit;
        const model_material *material; /* material */
        const model_motion *motion;     /* motion */
        const shading_light *light;     /* light: position or direction local */
        const shading_camera *camera;   /* camera: world coordinates */
        const float *background;        /* background: 3 colour components */
        const sc_error *error;          /* MODEL_ERROR */
        /* 2D context (read after pending) */
        const model_circle *circle;
        const model_square *square;
        const model_polygon *polygon;
        const model_offset *offset;
        const model_drawing *drawing; /* MODEL_IMPORT in 2D */
        const model_text *text;
        const model_linear_extrude *linear_extrude;
        const model_rotate_extrude *rotate_extrude;
        const model_resize *resize;
        /* projection(cut): its children are lowered in the points context */
        struct {
            int cut;
        } projection;
    } u;
};

typedef struct model {
    arena mem;         /* owns every node and array */
    const char *file;  /* as the syntax tree names it; not owned */
    model_node *first; /* top-level nodes, linked by next */
    int has_root;      /* some node (maybe after an error) has the '!' */
    size_t leaf_count; /* leaf nodes of the main model: what the builder
                          reserves room for (csg_builder_reserve) */
    /* OpenSCAD's warnings of the arguments of every node it instantiates
     * (params.h): outside '*' subtrees and the children of its primitives,
     * in file order. The builder gives them before its own, as OpenSCAD
     * gives them before it evaluates any geometry. */
    model_notes notes;
} model;

/* Lowers syntax into *out (free with model_free). Returns SC_OK with a
 * model whose last node may be a MODEL_ERROR (see above); a failure to
 * allocate is SC_ERR_NOMEM in error, with *out NULL. */
sc_status model_lower(const parse_tree *syntax, model **out, sc_error *error);

/* Lowers the node n alone, and its subtree, in the 2D context into *out
 * (free with model_free; its first node is n's): a 2D subtree or an
 * extrusion for the 2D builders on their own (their tests). Fails only
 * for memory. */
sc_status model_lower_twod(const char *file, const parse_node *n, model **out,
                           sc_error *error);

void model_free(model *m);

/* The lowering of a streamed parse: model_stream_sink's calls, made by
 * parse_stream in file order, lower each node as soon as its arguments
 * are read, so that its syntax can go when it closes; a subtree whose
 * lowering reads its children (the main model's resize and light, camera
 * and background) is kept and lowered when it closes. The model is the
 * one model_lower makes from the whole tree, node for node and error for
 * error. */
typedef struct model_stream model_stream;

/* A new lowering into a model naming file (which must outlive it). */
sc_status model_stream_new(const char *file, model_stream **out, sc_error *error);

/* The sink to pass to parse_stream; s must outlive the parse. */
parse_sink model_stream_sink(model_stream *s);

/* After parse_stream succeeded with s's sink: the model into *out (free
 * with model_free). Frees s either way. */
sc_status model_stream_finish(model_stream *s, model **out);

/* Frees s and its model (after a failed parse). */
void model_stream_free(model_stream *s);

/* The kind of a node name, through the lowering pass's one table. */
model_kind model_kind_of(const char *name);

/* Whether kind is a leaf (the builder does not walk its children). */
static inline int model_is_leaf(model_kind kind)
{
    return kind >= MODEL_CUBE && kind <= MODEL_IMPLICIT;
}

/* Whether kind is a 2D shape. */
static inline int model_is_2d(model_kind kind)
{
    return kind >= MODEL_CIRCLE && kind <= MODEL_PROJECTION;
}

#endif
