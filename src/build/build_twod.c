/* Evaluation of OpenSCAD's 2D nodes into a region, as OpenSCAD 2021.01's
 * GeometryEvaluator does it (twod.h).
 *
 * Leaves:
 *   square(size, center)   4 points (0,0) (x,0) (x,y) (0,y), moved by -size/2
 *                          when centred; empty unless both sides are > 0
 *                          and finite. Not passed through the clipper.
 *   circle(r | d)          OpenSCAD's polygon of f fragments (faithful.c's
 *                          rule from $fn, $fa, $fs): point k at 360 k / f
 *                          degrees. Empty unless 0 < r < inf. Not clipped.
 *   polygon(points, paths) one contour of all points (empty with fewer than
 *                          3), or one per path; then sanitized: the even-odd
 *                          union through the clipper, so a path inside an
 *                          odd number of others is a hole.
 * Operations over the children's regions (an empty or '%' child is
 * nothing; one child is taken as it is, without the clipper; more go
 * through twod_clip_apply):
 *   group, union, render, color   union
 *   difference, intersection      the boolean of the children
 *   multmatrix(m)                 union, then the points moved by the
 *                                 matrix's xy part; a zero determinant
 *                                 empties the region, a negative one (a
 *                                 mirror) sanitizes it again
 *   offset(r | delta, chamfer)    union, then Clipper's offset: round
 *                                 joins for r, miter for delta, square for
 *                                 delta with chamfer; the arc tolerance of
 *                                 round joins is |r| (1 - cos(180° / f)),
 *                                 f fragments of a circle of radius |r|
 *   hull()                        convex hull of every child's points
 *   minkowski()                   Clipper's Minkowski sum (twod_clip.cpp)
 *   resize(newsize, auto)         union, then scaled to the new size
 *                                 (Polygon2d::resize: resize_scale)
 * hull, minkowski and resize are 2D wherever their first child with a
 * dimension is: in a 2D model, inside an extrusion, and in a 3D model
 * (ignored there with a warning, build.c).
 *   import(file = "x.dxf", layer, origin, scale, $fn, $fa, $fs)
 *                          the drawing's contours as OpenSCAD's DxfData
 *                          joins them (dxf.c), then sanitized; the file is
 *                          found from the directory of the model. Other
 *                          files are errors: .svg is not supported yet,
 *                          .stl, .off and the like are 3D.
 * A 3D child of a 2D operation (its dimension is OpenSCAD's: a shape's
 * own, an operation's that of its first child that has one) is the empty
 * region, as in OpenSCAD (an intersection with it is empty), with
 * OpenSCAD's warnings, "Mixing 2D and 3D objects is not supported"
 * (once per operation, at the first 3D child whose geometry is not empty,
 * not from offset and the extrusions) and "Ignoring 3D child object for
 * 2D operation" (not for a child with no geometry at all:
 * warn_3d). The recursion over the children is the one 2D walk
 * (twod_walk, below), with its depth guard (TWOD_WALK_MAX_DEPTH).
 */
#include "build/build_twod.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "build/build_hull.h"
#include "build/build_mesh.h"
#include "build/build_projection.h"
#include "build/build_text.h"
#include "formats/dxf.h"
#include "formats/svg.h"
#include "model/args.h"
#include "model/faithful.h"

/* Offsets and Minkowski sums grow the point count by a product; these
 * bound it before the clipper starts. */
#define TWOD_MAX_PRODUCT 20000000.0

/* ---- the one 2D walk ---- */

const model_node *twod_walk_next(const model_node *k)
{
    while (k && (k->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND)))
        k = k->next;
    return k;
}

const model_node *twod_walk_first(const model_node *n)
{
    return twod_walk_next(n->first_child);
}

sc_status twod_walk(twod_walker *w, const model_node *n, const affine2 *m, int depth,
                    void *out)
{
    if (depth > TWOD_WALK_MAX_DEPTH)
        return err_set(w->c->error, SC_ERR_LIMIT, &n->loc,
                       "too many nested %s in %s (limit is %d)", w->nested, w->outer,
                       TWOD_WALK_MAX_DEPTH);
    return w->visit(w, n, m, depth, out);
}

sc_status twod_walk_children(twod_walker *w, const model_node *n, const affine2 *m,
                             int depth)
{
    sc_status st = SC_OK;
    for (const model_node *k = n->first_child; st == SC_OK && k; k = k->next) {
        if (k->modifiers & MODEL_MOD_BACKGROUND)
            st = build_twod_background(w->c, k, w->outer);
        else if (!(k->modifiers & MODEL_MOD_DISABLE))
            st = twod_walk(w, k, m, depth + 1, NULL);
    }
    /* A multmatrix removed for a nan or inf entry: OpenSCAD 2021.01 says so
     * once its children are evaluated, with their warnings. */
    return st == SC_OK ? build_xform_not_finite(w->c, n) : st;
}

sc_status twod_walk_fold(const twod_walker *w, const model_node *n, const affine2 *m,
                         affine2 *inner)
{
    if (n->pending)
        return build_pending(w->c, n);
    build_matrix_xy(n->u.xform, m->m, inner->m);
    return SC_OK;
}

/* ---- dimensions ---- */

/* The drawing of the import n, NULL for a mesh: lowered in the 2D context
 * (in_2d) the node holds a drawing, unless its file is not one; elsewhere
 * its import does when the file is a .dxf or .svg (model.h). */
static const model_drawing *drawing_of(const model_node *n, int in_2d)
{
    if (in_2d)
        return n->u.drawing->not_2d ? NULL : n->u.drawing;
    return n->u.import->drawing;
}

/* The dimension of n's own kind: 2 or 3 for a shape, -1 for an operation
 * that takes its children's, 0 for a node without geometry. in_2d: n was
 * lowered in the 2D context (where hull and minkowski are 2D operations and
 * an import is a drawing). */
static int kind_dim(const model_node *n, int in_2d)
{
    switch (n->kind) {
    case MODEL_CIRCLE:
    case MODEL_SQUARE:
    case MODEL_POLYGON:
    case MODEL_TEXT:
    case MODEL_OFFSET:
    case MODEL_PROJECTION: /* without a 3D child, it decides none (list_dim) */
        return 2;
    case MODEL_IMPORT:
        return drawing_of(n, in_2d) ? 2 : 3;
    case MODEL_XFORM: /* removed for a nan or inf entry: no geometry (model.h) */
        return n->not_finite ? 0 : -1;
    case MODEL_UNION:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
    case MODEL_RESIZE:
    case MODEL_MOTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        return -1;
    case MODEL_CUBE:
    case MODEL_SPHERE:
    case MODEL_CYLINDER:
    case MODEL_POLYHEDRON:
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE:
    case MODEL_SURFACE:
    case MODEL_TORUS:
    case MODEL_QUADRIC:
    case MODEL_IMPLICIT:
    case MODEL_HALFSPACE:
        return 3;
    default:
        return 0;
    }
}

static int list_dim(const model_node *first, int in_2d, int depth);
static int node_dim(const model_node *n, int in_2d, int depth);

/* Whether projection n has a child that is 3D (its children are lowered
 * in the points context, model.h): without one OpenSCAD 2021.01 makes no
 * geometry of it, so it decides no dimension. */
static int projects(const model_node *n, int depth)
{
    if (depth > TWOD_WALK_MAX_DEPTH)
        return 1;
    for (const model_node *k = twod_walk_first(n); k; k = twod_walk_next(k->next)) {
        if (node_dim(k, 0, depth + 1) == 3)
            return 1;
    }
    return 0;
}

static int node_dim(const model_node *n, int in_2d, int depth)
{
    int d = kind_dim(n, in_2d);
    return d >= 0 ? d : list_dim(twod_walk_first(n), in_2d, depth + 1);
}

/* The first dimension among the nodes from first on that count. Past the
 * 2D walk's depth limit it answers 0: the walk reports that depth. */
static int list_dim(const model_node *first, int in_2d, int depth)
{
    if (depth > TWOD_WALK_MAX_DEPTH)
        return 0;
    for (const model_node *k = first; k; k = twod_walk_next(k->next)) {
        int d = k->kind == MODEL_PROJECTION && !projects(k, depth)
                    ? 0
                    : node_dim(k, in_2d, depth);
        if (d)
            return d;
    }
    return 0;
}

int build_dim(const model_node *n, int in_2d)
{
    return node_dim(n, in_2d, 0);
}

int build_list_dim(const model_node *first, int in_2d)
{
    return list_dim(twod_walk_next(first), in_2d, 0);
}

int build_projects(const model_node *n)
{
    return projects(n, 0);
}

static int positive_finite(double x)
{
    return x > 0 && isfinite(x);
}

/* What OpenSCAD 2021.01's geometry of the 3D node n is, which decides its
 * warnings in a 2D operation: some (or not known to be empty), empty (a
 * solid of no size: "Ignoring" it, but no "Mixing"), or none (nothing
 * below it, or a 3D operation that CGAL ends with nothing: no warning at
 * all). Its rules are those of OpenSCAD's 3D operations on empty and
 * missing children (GeometryEvaluator.cc: applyToChildren3D, CGALUtils'
 * applyOperator3D and applyHull), seen on OpenSCAD 2021.01 runs: the
 * static rules (presence), and CGAL's solid where OpenSCAD evaluates a
 * boolean or minkowski with it (warn_3d), which also reads an import's
 * file (import_3d) and evaluates an extrusion's children (extrusion). */
typedef enum build_presence { BUILD_SOME, BUILD_EMPTY, BUILD_NONE } build_presence;

/* What OpenSCAD 2021.01's extrusion n of count children that count (not
 * '*' nor '%') is, all of them empty or not (empty): its visits of
 * LinearExtrudeNode and RotateExtrudeNode take the children's union
 * (applyToChildren2D), which is no polygon without children or with one
 * that is empty (or 3D), and an empty polygon of two or more; no polygon,
 * or a rotation by 0, is none; a polygon is extruded, empty when it is,
 * or when the height is not positive (extrudePolygon). */
static build_presence extrusion(const model_node *n, uint32_t count, int empty)
{
    if (n->pending)
        return BUILD_SOME;
    if (count == 0 || (count == 1 && empty))
        return BUILD_NONE;
    if (n->kind == MODEL_ROTATE_EXTRUDE) {
        double a = n->u.rotate_extrude->angle; /* as build_revolve.c reads it */
        if (a == 0)
            return BUILD_NONE;
    } else if (n->u.linear_extrude->height <= 0) {
        return BUILD_EMPTY;
    }
    return empty ? BUILD_EMPTY : BUILD_SOME;
}

static build_presence presence(const model_node *n, int in_2d, int depth);

static int counted(const model_node *k)
{
    return !(k->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND));
}

/* Whether OpenSCAD 2021.01's polygon of 2D node n is known from its
 * arguments alone to be empty (primitives.cc): a square of a size that is
 * not positive and finite, a circle of a radius that is not, a polygon
 * of two points or fewer without paths or with one it cannot read, text
 * without characters, a multmatrix removed for a nan or inf entry; a
 * group, union, colour, transform, offset or hull whose children all are
 * (none counted included), a difference whose first child is, an
 * intersection with one that is. Anything else is not known to be. */
static int twod_empty(const model_node *n, int depth)
{
    if (n->pending || depth > TWOD_WALK_MAX_DEPTH)
        return 0;
    switch (n->kind) {
    case MODEL_SQUARE:
        return !(n->u.square->sx > 0 && n->u.square->sy > 0 && !isinf(n->u.square->sx) &&
                 !isinf(n->u.square->sy));
    case MODEL_CIRCLE: {
        double r = n->u.circle->has_d ? n->u.circle->d / 2 : n->u.circle->r;
        return !(r > 0 && !isinf(r));
    }
    case MODEL_POLYGON: /* with no paths, a polygon of two points or fewer */
        return n->u.polygon->bad_point ||
               (n->u.polygon->path_count == 0 && n->u.polygon->point_count < 3);
    case MODEL_TEXT:
        return n->u.text->length == 0;
    case MODEL_XFORM:
        if (n->not_finite) /* removed (model.h) */
            return 1;
        /* fall through */
    case MODEL_UNION:
    case MODEL_COLOR:
    case MODEL_OFFSET:
    case MODEL_HULL:
        for (const model_node *k = n->first_child; k; k = k->next)
            if (counted(k) && !twod_empty(k, depth + 1))
                return 0;
        return 1;
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
        for (const model_node *k = n->first_child; k; k = k->next) {
            if (!counted(k))
                continue;
            if (twod_empty(k, depth + 1))
                return 1;
            if (n->kind == MODEL_DIFFERENCE)
                return 0;
        }
        return 1;
    default:
        return 0;
    }
}

/* A 3D operation's children that count (neither '%' nor '*', nor 2D,
 * which it ignores, nor shading nodes), folded one by one. */
typedef struct presence_fold {
    uint32_t count;
    build_presence first;
    int some, later_missing;
} presence_fold;

static int counts_3d(const model_node *k, int in_2d)
{
    return k->kind != MODEL_LIGHT && k->kind != MODEL_CAMERA &&
           k->kind != MODEL_BACKGROUND && build_dim(k, in_2d) != 2;
}

static void fold_add(presence_fold *f, build_presence p)
{
    if (f->count++ == 0)
        f->first = p;
    else
        f->later_missing |= p != BUILD_SOME;
    f->some |= p == BUILD_SOME;
}

/* None without any; a hull is none unless a child is some; one child is
 * itself; then union-like operations are some when a child is, else none;
 * a difference is its first child; an intersection is its first child
 * unless a later one is empty or none, which makes it none (CGALUtils'
 * applyOperator3D). A minkowski is taken as a union. */
static build_presence fold_result(const presence_fold *f, model_kind kind)
{
    if (f->count == 0)
        return BUILD_NONE;
    if (kind == MODEL_HULL)
        return f->some ? BUILD_SOME : BUILD_NONE;
    if (f->count == 1 || kind == MODEL_DIFFERENCE)
        return f->first;
    if (kind == MODEL_INTERSECTION)
        return f->later_missing ? BUILD_NONE : f->first;
    return f->some ? BUILD_SOME : BUILD_NONE;
}

static build_presence operation(const model_node *n, int in_2d, int depth)
{
    presence_fold f = {0, BUILD_NONE, 0, 0};
    for (const model_node *k = twod_walk_first(n); k; k = twod_walk_next(k->next))
        if (counts_3d(k, in_2d))
            fold_add(&f, presence(k, in_2d, depth + 1));
    return fold_result(&f, n->kind);
}

/* Past the walk's depth limit some: the walks report that depth. */
static build_presence presence(const model_node *n, int in_2d, int depth)
{
    if (depth > TWOD_WALK_MAX_DEPTH || n->unsized)
        return BUILD_SOME;
    switch (n->kind) {
    case MODEL_CUBE: {
        const double *size = n->u.cube.size;
        return positive_finite(size[0]) && positive_finite(size[1]) &&
                       positive_finite(size[2])
                   ? BUILD_SOME
                   : BUILD_EMPTY;
    }
    case MODEL_SPHERE:
        return positive_finite(n->u.sphere.r) ? BUILD_SOME : BUILD_EMPTY;
    case MODEL_CYLINDER: {
        double r1 = n->u.cylinder.r1, r2 = n->u.cylinder.r2;
        int radii = r1 >= 0 && r2 >= 0 && isfinite(r1) && isfinite(r2) && (r1 || r2);
        return positive_finite(n->u.cylinder.h) && radii ? BUILD_SOME : BUILD_EMPTY;
    }
    case MODEL_POLYHEDRON:
        return n->u.polyhedron.face_count ? BUILD_SOME : BUILD_EMPTY;
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE: {
        uint32_t count = 0, empty = 0; /* its children, and those known empty */
        for (const model_node *k = n->first_child; k; k = k->next) {
            count += counted(k);
            empty += counted(k) && twod_empty(k, depth + 1);
        }
        return extrusion(n, count, count && empty == count);
    }
    case MODEL_XFORM:
        if (n->not_finite) /* removed: no geometry (model.h) */
            return BUILD_NONE;
        return operation(n, in_2d, depth);
    case MODEL_UNION:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
    case MODEL_RESIZE:
    case MODEL_MOTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        return operation(n, in_2d, depth);
    default:
        return BUILD_SOME;
    }
}

int build_node_empty(const model_node *n)
{
    return !n->pending && presence(n, 0, 0) != BUILD_SOME;
}

int build_operands(model_kind kind, const model_node *first)
{
    int count = 0, some = 0;
    if (kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION) {
        for (const model_node *k = twod_walk_next(first); count < 2 && k;
             k = twod_walk_next(k->next))
            count += k->kind != MODEL_LIGHT && k->kind != MODEL_CAMERA &&
                     k->kind != MODEL_BACKGROUND;
        return count;
    }
    /* the solids counted first, and their subtrees scanned (presence)
     * only where two or more may count, so that a chain of transforms is
     * not scanned once per level */
    for (const model_node *k = twod_walk_next(first); count < 2 && k;
         k = twod_walk_next(k->next))
        count += build_dim(k, 0) == 3;
    if (count < 2)
        return count;
    for (const model_node *k = twod_walk_next(first); some < 2 && k;
         k = twod_walk_next(k->next))
        some += build_dim(k, 0) == 3 && !build_node_empty(k);
    return some;
}

/* ---- OpenSCAD's evaluation ---- */

typedef struct eval {
    twod_walker walk; /* first: the visitor is the walker */
    const build_ctx *c;
    const char *outer; /* the node that asked for 2D, for messages */
    int in_2d;         /* the nodes visited now were lowered in the 2D context */
} eval;

static const affine2 unmoved = {{{1, 0, 0}, {0, 1, 0}}};

static eval evaluator(const build_ctx *c, const char *outer);

static sc_status clip_status(const eval *e, const model_node *n, int code)
{
    if (code == TWOD_CLIP_OK)
        return SC_OK;
    if (code == TWOD_CLIP_NOMEM)
        return err_nomem(e->c->error, &n->loc);
    if (code == TWOD_CLIP_TOO_MANY)
        return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                       "%s: too many points in a 2D shape (limit is %u)", n->name,
                       TWOD_MAX_POINTS);
    return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                   "%s: coordinates out of range (limit is %g)", n->name, TWOD_MAX_COORD);
}

/* The outlines of a region that OpenSCAD's sanitize takes
 * (twod_clipper_admit): from the first one with a point past Clipper's
 * range on, none, with OpenSCAD's warning. */
static sc_status admit_outlines(const eval *e, const model_node *n, twod_region *out)
{
    long refused = twod_clipper_admit(out);
    if (refused < 0)
        return err_nomem(e->c->error, &n->loc);
    if (!refused)
        return SC_OK;
    if (e->c->strict)
        return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                       "%s: outline %ld has coordinates out of the clipper's range",
                       n->name, refused);
    return build_note_left_out(e->c, &n->loc,
                               "Range check failed for polygon. skipping (outline %ld of "
                               "%s and those after it, as OpenSCAD leaves them out; "
                               "--strict makes it an error)",
                               refused,
                               n->kind == MODEL_IMPORT ? "the drawing" : "the shape");
}

/* The node's argument error, kept by the lowering (model.h). */
static sc_status pending(const eval *e, const model_node *n)
{
    return build_pending(e->c, n);
}

static sc_status read_square(const eval *e, const model_node *n, twod_region *out)
{
    if (n->pending)
        return pending(e, n);
    double sx = n->u.square->sx, sy = n->u.square->sy;
    int center = n->u.square->center;
    /* past the clipper's range it is drawn while no clipper takes it, as
     * OpenSCAD's square is born sanitized (transform, below) */
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return SC_OK;
    double x0 = 0, y0 = 0, x1 = sx, y1 = sy;
    if (center) {
        x0 -= sx / 2;
        y0 -= sy / 2;
        x1 -= sx / 2;
        y1 -= sy / 2;
    }
    if (!twod_begin_contour(out) || !twod_add_point(out, x0, y0) ||
        !twod_add_point(out, x1, y0) || !twod_add_point(out, x1, y1) ||
        !twod_add_point(out, x0, y1))
        return err_nomem(e->c->error, &n->loc);
    out->sanitized = 1;
    return SC_OK;
}

static sc_status read_circle(const eval *e, const model_node *n, twod_region *out)
{
    if (n->pending)
        return pending(e, n);
    const model_circle *args = n->u.circle;
    /* a d of nan is given: it empties the circle */
    double r = args->has_d ? args->d / 2 : args->r, fn = args->res.fn, fa = args->res.fa,
           fs = args->res.fs;
    out->sanitized = 1;
    if (!(r > 0 && isfinite(r))) /* past the range, as a square */
        return SC_OK;
    long f = faithful_fragments(r, fn, fs, fa);
    if (f < 0)
        return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                       "circle has too many fragments (limit is %d)",
                       FAITHFUL_MAX_FRAGMENTS);
    if (!twod_begin_contour(out))
        return err_nomem(e->c->error, &n->loc);
    for (long k = 0; k < f; k++) {
        double a = 360.0 * (double)k / (double)f;
        if (!twod_add_point(out, r * faithful_cos_deg(a), r * faithful_sin_deg(a)))
            return err_nomem(e->c->error, &n->loc);
    }
    return SC_OK;
}

/* text: OpenSCAD's glyph polygons (build_text.c), outlines counter-clockwise
 * and holes clockwise, united with the non-zero rule as its text renderer
 * unites them. A font fallback is the caller's warning (c->note), or,
 * where the caller takes none (a 2D model), one of c->notes. */
static sc_status read_text(const eval *e, const model_node *n, twod_region *out)
{
    twod_region glyphs;
    twod_init(&glyphs);
    sc_error fallback = {SC_OK, "", 0, 0, ""};
    sc_status st =
        text_faithful_polygons(e->c, n, &glyphs, e->c->note ? e->c->note : &fallback);
    if (st == SC_OK && fallback.message[0])
        st = build_note(e->c, &n->loc, "%s", fallback.message);
    if (st == SC_OK) {
        glyphs.sanitized = 1; /* already oriented: the union keeps holes */
        twod_region *one = &glyphs;
        st = clip_status(e, n, twod_clip_apply(&one, 1, TWOD_UNION, out));
    }
    twod_free(&glyphs);
    return st;
}

sc_status build_twod_polygon(const build_ctx *c, const model_node *n, const affine2 *m,
                             int empty_is_all, twod_region *out)
{
    if (n->pending)
        return build_pending(c, n);
    const model_polygon *p = n->u.polygon;
    if (!p->has_points)
        return SC_OK;
    int paths = p->has_paths && (p->path_count > 0 || !empty_is_all);
    uint32_t count = paths ? p->path_count : 1;
    for (uint32_t k = 0; k < count; k++) {
        if (p->range_bad && k + 1 >= p->range_bad) /* OpenSCAD's clipper refuses it */
            break;
        uint32_t first = paths ? p->path_start[k] : 0;
        uint32_t len = paths ? p->path_start[k + 1] - first : p->point_count;
        if (!twod_begin_contour(out))
            return err_nomem(c->error, &n->loc);
        for (uint32_t i = 0; i < len; i++) {
            uint32_t index = paths ? p->index[first + i] : i;
            double x = p->xy[2 * index], y = p->xy[2 * index + 1];
            if (!twod_add_moved(out, m, x, y))
                return build_twod_add_error(c, n, out);
        }
    }
    return SC_OK;
}

static sc_status read_polygon(const eval *e, const model_node *n, twod_region *out)
{
    if (n->pending)
        return pending(e, n);
    const model_polygon *p = n->u.polygon;
    sc_status st = build_bad_indices(e->c, n);
    /* OpenSCAD: an empty paths list means all points; fewer than 3 are
     * nothing */
    if (st != SC_OK || !p->has_points ||
        (!(p->has_paths && p->path_count > 0) && p->point_count < 3))
        return st;
    st = build_twod_polygon(e->c, n, &unmoved, 1, out);
    if (st != SC_OK)
        return st;
    out->sanitized = 0;
    /* the outline the clipper refuses is left out already (range_bad, with
     * its warning); before it, those it skips (fewer than 3 points) that
     * reach past its range add nothing, and it could not take them */
    if (twod_clipper_admit(out) < 0)
        return err_nomem(e->c->error, &n->loc);
    return out->contour_count ? clip_status(e, n, twod_clip_sanitize(out)) : SC_OK;
}

/* A 3D child k of a 2D operation: nothing, with OpenSCAD 2021.01's
 * warnings (GeometryEvaluator.cc: isValidDim, collectChildren2D), the
 * first also saying that the operation mixes when mixing is set. */
/* OpenSCAD's message for an import k of a file no reader takes, which it
 * gives as it evaluates the import, before any dimension check; nothing
 * for other nodes. */
static sc_status unsupported_import(const eval *e, const model_node *k)
{
    if (k->kind != MODEL_IMPORT || k->pending)
        return SC_OK;
    const char *file = e->in_2d ? k->u.drawing->file : k->u.import->file;
    const sc_location *at = e->in_2d ? &k->u.drawing->file_loc : &k->u.import->file_loc;
    return model_mesh_format_of(file) == MODEL_MESH_UNSUPPORTED
               ? build_import_unsupported(e->c, at, file, 0)
               : SC_OK;
}

static sc_status ignore_3d(const eval *e, const model_node *k, int mixing)
{
    sc_status st = SC_OK;
    if (mixing)
        st = build_mixing(e->c, &k->loc, 1);
    if (st == SC_OK)
        st = build_ignoring(e->c, &k->loc, 1);
    return st;
}

/* The warnings for the 3D children among the nodes from first on, once
 * they are all evaluated: that the operation mixes (when mixing is set),
 * at the first 3D child whose geometry is not empty, then each ignored,
 * but those with no geometry. states[i] is what OpenSCAD's geometry of
 * the i-th child that counts (not '*' or '%') is (warn_3d). */
static sc_status ignore_3d_children(const eval *e, const model_node *first, int mixing,
                                    const build_presence *states)
{
    sc_status st = SC_OK;
    uint32_t i = 0;
    for (const model_node *k = twod_walk_next(first); mixing && k;
         k = twod_walk_next(k->next), i++) {
        if (build_dim(k, e->in_2d) == 3 && states[i] == BUILD_SOME) {
            st = build_mixing(e->c, &k->loc, 1);
            break;
        }
    }
    i = 0;
    for (const model_node *k = twod_walk_next(first); st == SC_OK && k;
         k = twod_walk_next(k->next), i++) {
        if (build_dim(k, e->in_2d) == 3 && states[i] != BUILD_NONE)
            st = ignore_3d(e, k, 0);
    }
    return st;
}

static sc_status eval_children(eval *e, const model_node *n, twod_region **regions,
                               uint32_t *count, int depth);
static void free_children(twod_region *regions, uint32_t count);

/* n's region, evaluated for its warnings (and errors) only, as OpenSCAD
 * evaluates what it then leaves out; *empty (when empty is not NULL)
 * says whether it has no outline. */
static sc_status eval_only(eval *e, const model_node *n, int depth, int *empty)
{
    twod_region r;
    twod_init(&r);
    sc_status st = twod_walk(&e->walk, n, &unmoved, depth, &r);
    if (empty)
        *empty = r.contour_count == 0;
    twod_free(&r);
    return st;
}

/* The import n of a mesh (not a drawing), left out: OpenSCAD 2021.01
 * reads its file first (ImportNode::createGeometry), with the warnings of
 * a file it cannot open or parse or whose format it does not take, which
 * make it empty, as a file without faces is; it takes the mesh as it
 * comes, closed or not, as no CGAL operation follows. In the 2D context
 * the node holds the file as a drawing that is not one, read as the same
 * import (build_import_left_out finds the file by name and position). */
static sc_status import_3d(const eval *e, const model_node *n, build_presence *state)
{
    if (n->pending || !e->c->notes)
        return unsupported_import(e, n);
    model_import here;
    const model_import *import = n->u.import;
    if (e->in_2d) {
        const model_drawing *d = n->u.drawing;
        here = (model_import){d->file, d->file_loc, model_mesh_format_of(d->file), NULL};
        import = &here;
    }
    const char *empty = NULL;
    sc_status st = build_import_left_out(e->c, import, &empty);
    if (st == SC_OK && empty)
        *state = BUILD_EMPTY;
    return st;
}

/* Whether OpenSCAD 2021.01 ignores n as a 2D child of a 3D operation: 2D
 * (build_dim), and not a projection without a 3D child, which is no
 * geometry (build_projects). */
static int flat_child(const eval *e, const model_node *n)
{
    return build_dim(n, e->in_2d) == 2 &&
           (n->kind != MODEL_PROJECTION || build_projects(n));
}

/* Whether 3D subtree n has a polyhedron or a mesh import, which CGAL may
 * find is not closed. */
static int has_mesh(const model_node *n, int in_2d, int depth)
{
    if (depth > TWOD_WALK_MAX_DEPTH || build_dim(n, in_2d) == 2)
        return 0;
    if (n->kind == MODEL_POLYHEDRON || n->kind == MODEL_IMPORT)
        return 1;
    for (const model_node *k = n->first_child; k; k = k->next)
        if (!(k->modifiers & MODEL_MOD_DISABLE) && has_mesh(k, in_2d, depth + 1))
            return 1;
    return 0;
}

/* Whether OpenSCAD 2021.01 evaluates 3D operation n with CGAL (as Nef
 * polyhedra): a difference or intersection of two or more children (2D
 * ones among them, which are empty operands), a minkowski or union of two
 * or more that are not empty. A union is taken there only with a mesh
 * below it, the one thing CGAL can find wrong in it. */
static int cgal_operation(const eval *e, const model_node *n)
{
    int boolean = n->kind == MODEL_DIFFERENCE || n->kind == MODEL_INTERSECTION;
    int sum = n->kind == MODEL_MINKOWSKI;
    int unites = n->kind == MODEL_UNION || n->kind == MODEL_COLOR ||
                 n->kind == MODEL_MATERIAL || n->kind == MODEL_XFORM ||
                 n->kind == MODEL_RESIZE;
    if (!boolean && !sum && !unites)
        return 0;
    /* the children counted first, and the subtrees scanned (presence,
     * has_mesh) only where two or more may count, so that a chain of
     * transforms is not scanned once per level */
    uint32_t count = 0, some = 0;
    for (const model_node *k = twod_walk_first(n); k; k = twod_walk_next(k->next))
        count += boolean ? k->kind != MODEL_LIGHT && k->kind != MODEL_CAMERA &&
                               k->kind != MODEL_BACKGROUND
                         : counts_3d(k, e->in_2d);
    if (count < 2 || boolean)
        return count >= 2;
    for (const model_node *k = twod_walk_first(n); some < 2 && k;
         k = twod_walk_next(k->next))
        some += counts_3d(k, e->in_2d) && presence(k, e->in_2d, 0) == BUILD_SOME;
    return some >= 2 && (sum || has_mesh(n, e->in_2d, 0));
}

/* What OpenSCAD's geometry of n is after CGAL evaluated it (s): a boolean
 * whose first operand has no geometry at all (2D, or none) has none; an
 * intersection with a later operand that is empty has none
 * (applyOperator3D); otherwise empty or some as the solid is. */
static build_presence cgal_presence(const eval *e, const model_node *n,
                                    const build_nef_state *s)
{
    if (n->kind == MODEL_DIFFERENCE || n->kind == MODEL_INTERSECTION) {
        const model_node *first = twod_walk_first(n);
        while (first && (first->kind == MODEL_LIGHT || first->kind == MODEL_CAMERA ||
                         first->kind == MODEL_BACKGROUND))
            first = twod_walk_next(first->next);
        if (s->first_empty && first &&
            (build_dim(first, e->in_2d) == 2 ||
             presence(first, e->in_2d, 0) == BUILD_NONE))
            return BUILD_NONE;
        if (n->kind == MODEL_INTERSECTION && s->later_empty)
            return BUILD_NONE;
    }
    return s->empty ? BUILD_EMPTY : BUILD_SOME;
}

/* The warnings of a 3D subtree n that is left out here (a child of a 2D
 * operation, or a '%' one), as OpenSCAD 2021.01 evaluates it before it
 * leaves it out, and in *state (when not NULL) what its geometry is, which
 * decides its parent's warnings: its 2D parts through this engine (a
 * polygon's point), a 3D operation's own check of its children's
 * dimensions once they are evaluated (build_mixing, build_ignoring, as
 * build.c's flush_ignored: not under a multmatrix removed for a nan or inf
 * entry, which is said instead), an extrusion's 2D children, a
 * polyhedron's indices and points, an import of a file no reader takes.
 * '%' children below give their warnings too, and are not operands. A
 * boolean or minkowski that OpenSCAD evaluates with CGAL is evaluated so
 * (build_nef_evaluate): the warnings of its subtree, a mesh in it that is
 * not closed among them, and whether it comes out empty. */
static sc_status warn_3d(eval *e, const model_node *n, int depth, build_presence *state)
{
    build_presence unused;
    if (!state)
        state = &unused;
    *state = BUILD_SOME;
    if (depth > TWOD_WALK_MAX_DEPTH)
        return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                       "too many nested %s in %s (limit is %d)", e->walk.nested,
                       e->walk.outer, TWOD_WALK_MAX_DEPTH);
    switch (n->kind) {
    case MODEL_POLYHEDRON:
        *state = presence(n, e->in_2d, depth);
        return build_bad_indices(e->c, n);
    case MODEL_IMPORT:
        return import_3d(e, n, state);
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE: {
        twod_region *regions;
        uint32_t count;
        sc_status st = eval_children(e, n, &regions, &count, depth);
        int empty = 1;
        for (uint32_t i = 0; i < count; i++)
            empty &= regions[i].contour_count == 0;
        if (st == SC_OK)
            *state = extrusion(n, count, empty);
        free_children(regions, count);
        return st;
    }
    case MODEL_UNION:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
    case MODEL_XFORM:
    case MODEL_RESIZE:
    case MODEL_MOTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        break;
    default:
        *state = presence(n, e->in_2d, depth);
        return SC_OK;
    }
    if (e->c->notes && cgal_operation(e, n)) {
        build_nef_state cgal;
        sc_status st = build_nef_evaluate(e->c, n, &cgal);
        if (st != SC_OK || cgal.walked) {
            *state = cgal_presence(e, n, &cgal);
            return st;
        }
    }
    const model_node *mixing = NULL; /* the first 2D child that is not empty */
    presence_fold fold = {0, BUILD_NONE, 0, 0};
    for (const model_node *k = n->first_child; k; k = k->next) {
        if (k->modifiers & MODEL_MOD_DISABLE)
            continue;
        int empty = 1, operand = !(k->modifiers & MODEL_MOD_BACKGROUND);
        build_presence p = BUILD_NONE;
        sc_status st = build_dim(k, e->in_2d) == 2 ? eval_only(e, k, depth + 1, &empty)
                                                   : warn_3d(e, k, depth + 1, &p);
        if (st != SC_OK)
            return st;
        if (operand && counts_3d(k, e->in_2d))
            fold_add(&fold, p);
        if (!mixing && !empty && operand && flat_child(e, k))
            mixing = k;
    }
    if (!n->unsized)
        *state = fold_result(&fold, n->kind);
    if (n->kind == MODEL_XFORM && n->not_finite) {
        *state = BUILD_NONE;
        return build_xform_not_finite(e->c, n);
    }
    sc_status st = mixing ? build_mixing(e->c, &mixing->loc, 0) : SC_OK;
    for (const model_node *k = twod_walk_first(n); st == SC_OK && k;
         k = twod_walk_next(k->next)) {
        if (flat_child(e, k))
            st = build_ignoring(e->c, &k->loc, 0);
    }
    return st;
}

/* A '%' child k (build_twod_background). */
static sc_status background(eval *e, const model_node *k, int depth)
{
    return build_dim(k, e->in_2d) == 2 ? eval_only(e, k, depth, NULL)
                                       : warn_3d(e, k, depth, NULL);
}

/* The regions of the nodes from first on, the children of an operation of
 * this kind ('*' left out, '%' evaluated for its warnings only; 3D ones
 * ignored with a warning, as
 * OpenSCAD ignores them, unless removed: the operation is a multmatrix
 * removed for a nan or inf entry). *regions holds *count initialised
 * regions, to be freed by free_children. */
static sc_status eval_list(eval *e, const model_node *first, model_kind kind, int removed,
                           twod_region **regions, uint32_t *count, int depth)
{
    *regions = NULL;
    *count = 0;
    uint32_t total = 0;
    for (const model_node *k = first; k; k = k->next)
        total++;
    if (total == 0)
        return SC_OK;
    twod_region *r = calloc(total, sizeof *r);
    build_presence *states = malloc(total * sizeof *states);
    if (!r || !states) {
        free(r);
        free(states);
        return err_nomem(e->c->error, &first->loc);
    }
    *regions = r;
    /* OpenSCAD's operations on children (applyToChildren: the booleans,
     * multmatrix, color, hull, minkowski, a file's top level) say once
     * that they mix; offset and the extrusions take 2D children without
     * that check. */
    int mixing = kind != MODEL_OFFSET && kind != MODEL_LINEAR_EXTRUDE &&
                 kind != MODEL_ROTATE_EXTRUDE;
    sc_status st = SC_OK;
    for (const model_node *k = first; st == SC_OK && k; k = k->next) {
        if (k->modifiers & MODEL_MOD_DISABLE)
            continue;
        if (k->modifiers & MODEL_MOD_BACKGROUND) {
            /* its parent says nothing of it (ignore_3d_children) */
            st = background(e, k, depth + 1);
            continue;
        }
        twod_init(&r[*count]);
        (*count)++;
        /* a 3D child is an empty operand, as in OpenSCAD: it empties an
         * intersection; OpenSCAD evaluates it first, with the warnings of
         * its subtree */
        states[*count - 1] = BUILD_NONE;
        if (build_dim(k, e->in_2d) != 3)
            st = twod_walk(&e->walk, k, &unmoved, depth + 1, &r[*count - 1]);
        else
            st = warn_3d(e, k, depth + 1, &states[*count - 1]);
    }
    /* After the children's own warnings, as OpenSCAD checks the
     * dimensions once its children are evaluated; not those of a
     * multmatrix it removes for a nan or inf entry. */
    if (st == SC_OK && !removed)
        st = ignore_3d_children(e, first, mixing, states);
    free(states);
    return st;
}

static sc_status eval_children(eval *e, const model_node *n, twod_region **regions,
                               uint32_t *count, int depth)
{
    /* The children of a 2D shape, and everything below an extrusion, were
     * lowered in the 2D context; those of a main-model operation in the
     * main model. */
    int outer_2d = e->in_2d;
    e->in_2d = outer_2d || model_is_2d(n->kind) || n->kind == MODEL_LINEAR_EXTRUDE ||
               n->kind == MODEL_ROTATE_EXTRUDE;
    sc_status st =
        eval_list(e, n->first_child, n->kind, n->kind == MODEL_XFORM && n->not_finite,
                  regions, count, depth);
    e->in_2d = outer_2d;
    return st;
}

static void free_children(twod_region *regions, uint32_t count)
{
    for (uint32_t i = 0; i < count; i++)
        twod_free(&regions[i]);
    free(regions);
}

/* OpenSCAD's applyToChildren2D: no child is nothing, one child is itself.
 * Returns 1 when that settles *out. */
static int trivial(twod_region *regions, uint32_t count, twod_region *out)
{
    twod_clear(out);
    if (count == 1)
        twod_move(out, &regions[0]);
    return count <= 1;
}

/* The clipper's operands: the children, NULL for the empty ones; malloc'd,
 * NULL when memory runs out. */
static twod_region **operands(twod_region *regions, uint32_t count)
{
    twod_region **list = malloc((size_t)count * sizeof *list);
    for (uint32_t i = 0; list && i < count; i++)
        list[i] = regions[i].contour_count ? &regions[i] : NULL;
    return list;
}

/* union, difference and intersection: more than one child goes through
 * the clipper. */
static sc_status combine(const eval *e, const model_node *n, twod_region *regions,
                         uint32_t count, twod_op op, twod_region *out)
{
    if (trivial(regions, count, out))
        return SC_OK;
    twod_region **list = operands(regions, count);
    if (!list)
        return err_nomem(e->c->error, &n->loc);
    int code = twod_clip_apply(list, count, op, out);
    free(list);
    return clip_status(e, n, code);
}

static sc_status read_matrix(const eval *e, const model_node *n, double m[2][3])
{
    static const double id[2][3] = {{1, 0, 0}, {0, 1, 0}};
    if (n->pending)
        return pending(e, n);
    build_matrix_xy(n->u.xform, id, m);
    return SC_OK;
}

/* r, the union of a transform's (or resize's) count children, through m. */
static sc_status transform(const eval *e, const model_node *n, double m[2][3],
                           uint32_t count, twod_region *r)
{
    double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if (det == 0) {
        twod_clear(r);
        return count ? build_xform_flat_2d(e->c, n) : SC_OK;
    }
    for (uint32_t i = 0; i < r->point_count; i++) {
        double x = r->xy[2 * i], y = r->xy[2 * i + 1];
        r->xy[2 * i] = m[0][0] * x + m[0][1] * y + m[0][2];
        r->xy[2 * i + 1] = m[1][0] * x + m[1][1] * y + m[1][2];
        if (!(isfinite(r->xy[2 * i]) && isfinite(r->xy[2 * i + 1])))
            return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                           "%s: coordinates are not finite", n->name);
    }
    /* OpenSCAD sanitizes a sanitized region turned over; outside the
     * clipper's range it moves it as it is, and so does the next node
     * unless that is a clipper's (which refuses it: clip_status) */
    if (!(r->sanitized && det <= 0 && r->contour_count))
        return SC_OK;
    sc_status st = admit_outlines(e, n, r);
    return st != SC_OK || !r->contour_count ? st
                                            : clip_status(e, n, twod_clip_sanitize(r));
}

static sc_status offset(const eval *e, const model_node *n, twod_region *r)
{
    if (n->pending)
        return pending(e, n);
    const model_offset *o = n->u.offset;
    double delta = o->delta, fn = o->res.fn, fa = o->res.fa, fs = o->res.fs;
    twod_join join = TWOD_JOIN_ROUND;
    if (!o->has_r && o->has_delta)
        join = o->chamfer ? TWOD_JOIN_SQUARE : TWOD_JOIN_MITER;
    if (!r->contour_count)
        return SC_OK;
    if (!isfinite(delta)) {
        /* OpenSCAD 2021.01 draws nothing for an offset of inf or nan (a
         * .scad's 1/0, which its export writes as inf) */
        twod_clear(r);
        return SC_OK;
    }
    double arc_tolerance = 0;
    if (join == TWOD_JOIN_ROUND) {
        long f = faithful_fragments(fabs(delta), fn, fs, fa);
        if (f < 0)
            return err_set(
                e->c->error, SC_ERR_LIMIT, &n->loc,
                "offset: $fn, $fa and $fs of radius %g give too many fragments "
                "(limit is %d)",
                fabs(delta), FAITHFUL_MAX_FRAGMENTS);
        if ((double)f * r->point_count > TWOD_MAX_PRODUCT)
            return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                           "offset: %u points with round joins of %ld fragments are too "
                           "many (limit is %.0f points times fragments)",
                           r->point_count, f, TWOD_MAX_PRODUCT);
        arc_tolerance = fabs(delta) * (1 - faithful_cos_deg(180.0 / (double)f));
    }
    twod_region result;
    twod_init(&result);
    int code = twod_clip_offset(r, delta, join, arc_tolerance, &result);
    if (code == TWOD_CLIP_OK)
        twod_move(r, &result);
    twod_free(&result);
    return clip_status(e, n, code);
}

static sc_status hull(const eval *e, const model_node *n, twod_region *regions,
                      uint32_t count, twod_region *out)
{
    size_t total = 0;
    for (uint32_t i = 0; i < count; i++)
        total += regions[i].point_count;
    if (total > TWOD_MAX_POINTS)
        return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                       "hull of %zu points is too large (limit is %u)", total,
                       TWOD_MAX_POINTS);
    double *xy = malloc((total ? total : 1) * 2 * sizeof *xy);
    if (!xy)
        return err_nomem(e->c->error, &n->loc);
    size_t k = 0;
    for (uint32_t i = 0; i < count; i++) {
        if (!regions[i].point_count) /* an empty child (a 3D one left out) */
            continue;
        memcpy(xy + 2 * k, regions[i].xy,
               (size_t)regions[i].point_count * 2 * sizeof *xy);
        k += regions[i].point_count;
    }
    int ok = twod_hull(xy, (uint32_t)total, out);
    free(xy);
    out->sanitized = 0; /* OpenSCAD's hull is not passed through the clipper */
    return ok ? SC_OK : err_nomem(e->c->error, &n->loc);
}

static sc_status minkowski(const eval *e, const model_node *n, twod_region *regions,
                           uint32_t count, twod_region *out)
{
    if (trivial(regions, count, out))
        return SC_OK;
    double product = regions[0].point_count;
    for (uint32_t i = 1; i < count; i++) {
        if (!regions[i].contour_count)
            continue;
        if (product * regions[i].point_count > TWOD_MAX_PRODUCT)
            return err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                           "minkowski: the sum of %.0f and %u points is too large (limit "
                           "is %.0f pairs of points)",
                           product, regions[i].point_count, TWOD_MAX_PRODUCT);
        /* the sum can have as many points as the pairs: a bound for the
         * next step */
        product = product * regions[i].point_count;
    }
    twod_region **list = operands(regions, count);
    if (!list)
        return err_nomem(e->c->error, &n->loc);
    int code = twod_clip_minkowski(list, count, out);
    free(list);
    return clip_status(e, n, code);
}

/* resize(newsize, auto) of region r, as OpenSCAD 2021.01's
 * Polygon2d::resize scales it: by newsize / extent of r's points along
 * each axis whose new size is > 0 (a negative one is as 0), else 1, or
 * where auto is set the scale of the larger new size (y when it is given
 * and larger than x). Sets the scale into m and returns 1; returns 0 when
 * r stays as it is: without points, or when a size asks to stretch a
 * region that is flat along it (OpenSCAD's infinite scale; the region has
 * no area either way, so it is emptied). */
static int resize_scale(const model_resize *args, twod_region *r, double m[2][3])
{
    if (!r->point_count)
        return 0;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < r->point_count; i++) {
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], r->xy[2 * i + k]);
            hi[k] = fmax(hi[k], r->xy[2 * i + k]);
        }
    }
    const double *size = args->size;
    int largest = size[1] != 0 && size[1] > size[0];
    double scale[2], extent[2] = {hi[0] - lo[0], hi[1] - lo[1]};
    double autoscale = size[largest] > 0 ? size[largest] / extent[largest] : 1;
    for (int k = 0; k < 2; k++) {
        scale[k] = size[k] > 0 ? size[k] / extent[k] : 1;
        if (args->autosize[k] != 0 && !(size[k] > 0))
            scale[k] = autoscale;
        if (!isfinite(scale[k])) {
            twod_clear(r);
            return 0;
        }
    }
    m[0][0] = scale[0];
    m[0][1] = m[0][2] = m[1][0] = m[1][2] = 0;
    m[1][1] = scale[1];
    return 1;
}

/* import of an SVG drawing (svg.c): OpenSCAD's region of the page, already
 * through the clipper. A file that cannot be opened is a warning and
 * nothing, as OpenSCAD makes it. */
static sc_status read_svg(const eval *e, const model_node *n, twod_region *out)
{
    const model_drawing *d = drawing_of(n, e->in_2d);
    char *path = build_file_path(e->c, d->file);
    if (!path)
        return err_nomem(e->c->error, &n->loc);
    sc_status st;
    FILE *f = fopen(path, "rb");
    if (!f) {
        st = build_file_not_opened(e->c, &n->loc, "SVG", path, strerror(errno));
    } else {
        fclose(f);
        svg_options o = {d->dpi, d->center};
        svg_refused refused;
        st = svg_read_file(path, d->file, &d->file_loc, &o, out, &refused, e->c->error);
        if (st == SC_OK && refused.shapes && e->c->strict)
            st = err_set(e->c->error, SC_ERR_LIMIT, &n->loc,
                         "import: shape %u of '%s' has coordinates out of the clipper's "
                         "range",
                         refused.first, d->file);
        else if (st == SC_OK && refused.shapes)
            st = build_note_left_out(
                e->c, &n->loc,
                "Range check failed for polygon. skipping (%u shape%s of '%s', the first "
                "shape %u: the outline past the clipper's range and those after it in "
                "the shape, as OpenSCAD leaves them out; --strict makes it an error)",
                refused.shapes, refused.shapes == 1 ? "" : "s", d->file, refused.first);
        /* OpenSCAD 2021.01 logs a drawing it cannot parse as an error and
         * renders the rest: a warning with the file's own line, and the
         * import empty, unless --strict */
        if (st == SC_ERR_SYNTAX && !e->c->strict) {
            sc_error why = *e->c->error;
            err_clear(e->c->error);
            twod_clear(out);
            st = build_note_left_out(e->c, &d->file_loc,
                                     "%s; the import is empty, as OpenSCAD leaves it out "
                                     "(--strict makes it an error)",
                                     why.message);
        }
    }
    free(path);
    return st;
}

/* A warning of the DXF reader (dxf_options.warn): OpenSCAD 2021.01 warns
 * and reads on; --strict makes one that changes the drawing an error. */
static sc_status dxf_warning(void *ctx, const sc_location *at, int changes,
                             const char *message)
{
    const build_ctx *c = ctx;
    if (changes && c->strict)
        return err_set(c->error, SC_ERR_SEMANTIC, at, "%s", message);
    return build_note(c, at, "%s%s", message,
                      changes ? " (--strict makes it an error)" : "");
}

/* import of a DXF drawing (dxf.c), sanitized as OpenSCAD sanitizes a leaf's
 * polygons. */
static sc_status read_import(const eval *e, const model_node *n, twod_region *out)
{
    if (n->pending)
        return pending(e, n);
    const model_drawing *d = drawing_of(n, e->in_2d);
    if (!d) { /* a 3D file, or one of no format OpenSCAD's import() reads:
               * read, then ignored */
        build_presence state = BUILD_SOME;
        sc_status st = import_3d(e, n, &state);
        return st != SC_OK ? st : ignore_3d(e, n, 0);
    }
    const char *name = d->file;
    sc_location loc = d->file_loc;
    if (d->format == MODEL_DRAWING_SVG)
        return read_svg(e, n, out);
    /* a drawing at no finite place is read where it is, then dropped */
    dxf_options o = {d->res.fn, d->res.fa, d->res.fs, d->layer, 0, 0, 1, NULL, NULL};
    o.warn = dxf_warning;
    o.warn_ctx = (void *)e->c;
    if (!d->far) {
        o.origin_x = d->origin[0];
        o.origin_y = d->origin[1];
        o.scale = d->scale;
    }
    sc_status st;
    char *path = build_file_path(e->c, name);
    if (!path)
        return err_nomem(e->c->error, &n->loc);
    /* OpenSCAD 2021.01 (import.cc, DxfData) reads a drawing it cannot
     * open as nothing, with a warning. */
    FILE *f = fopen(path, "rb");
    if (!f) {
        st = build_file_not_opened(e->c, &n->loc, "DXF", path, strerror(errno));
        free(path);
        return st;
    }
    fclose(f);
    char unsupported[32];
    st = dxf_read_file(path, &loc, &o, out, unsupported, e->c->error);
    if (st == SC_OK && unsupported[0] && e->c->note && !e->c->note->message[0])
        err_set(e->c->note, SC_OK, &loc,
                "import: DXF entities '%s' in '%s' are ignored, as OpenSCAD ignores them",
                unsupported, path);
    free(path);
    /* every point at no finite place (model_drawing.far): OpenSCAD 2021.01
     * draws nothing (whether its clipper also says "Range check failed for
     * polygon" depends on how its DXF reader joined the outlines there) */
    if (st == SC_OK && d->far)
        twod_clear(out);
    if (st == SC_OK && out->contour_count)
        st = admit_outlines(e, n, out);
    if (st == SC_OK && out->contour_count)
        st = clip_status(e, n, twod_clip_sanitize(out));
    return st;
}

/* The walk's visitor: n's region into out (a twod_region); m is the
 * identity, as OpenSCAD moves a multmatrix's region after evaluating it. */
static sc_status eval_node(twod_walker *w, const model_node *n, const affine2 *unused,
                           int depth, void *result)
{
    (void)unused;
    eval *e = (eval *)w;
    twod_region *out = result;
    const char *name = n->name;
    model_kind kind = n->kind;
    twod_clear(out);
    switch (kind) {
    case MODEL_ERROR: /* a main-model node's argument error */
        *e->c->error = *n->u.error;
        return n->u.error->status;
    case MODEL_SQUARE:
        return read_square(e, n, out);
    case MODEL_CIRCLE:
        return read_circle(e, n, out);
    case MODEL_POLYGON:
        return read_polygon(e, n, out);
    case MODEL_TEXT:
        return read_text(e, n, out);
    case MODEL_IMPORT:
        return read_import(e, n, out);
    case MODEL_PROJECTION:
        return build_projection(e->c, n, out);
    default:
        break;
    }
    if (build_dim(n, e->in_2d) == 3) { /* evaluated, then ignored */
        build_presence state;
        sc_status st = warn_3d(e, n, depth, &state);
        return st == SC_OK && state != BUILD_NONE ? ignore_3d(e, n, 0) : st;
    }
    twod_op op = kind == MODEL_DIFFERENCE     ? TWOD_DIFFERENCE
                 : kind == MODEL_INTERSECTION ? TWOD_INTERSECTION
                                              : TWOD_UNION;
    if (kind != MODEL_UNION && kind != MODEL_COLOR && kind != MODEL_XFORM &&
        kind != MODEL_OFFSET && kind != MODEL_DIFFERENCE && kind != MODEL_INTERSECTION &&
        kind != MODEL_HULL && kind != MODEL_MINKOWSKI && kind != MODEL_RESIZE)
        return err_set(e->c->error, SC_ERR_UNSUPPORTED, &n->loc,
                       "'%s' inside %s is not supported yet", name, e->outer);
    double m[2][3] = {{1, 0, 0}, {0, 1, 0}};
    sc_status st;
    if (kind == MODEL_XFORM && (st = read_matrix(e, n, m)) != SC_OK)
        return st;
    if (kind == MODEL_RESIZE && n->pending)
        return pending(e, n);
    twod_region *regions;
    uint32_t count;
    st = eval_children(e, n, &regions, &count, depth);
    if (st == SC_OK && kind == MODEL_XFORM && n->not_finite) {
        /* removed for a nan or inf entry: OpenSCAD 2021.01 evaluates the
         * children (their warnings, not its check of their dimensions,
         * eval_list), then says so */
        free_children(regions, count);
        twod_clear(out);
        return build_xform_not_finite(e->c, n);
    }
    if (st == SC_OK) {
        if (kind == MODEL_HULL)
            st = hull(e, n, regions, count, out);
        else if (kind == MODEL_MINKOWSKI)
            st = minkowski(e, n, regions, count, out);
        else
            st = combine(e, n, regions, count, op, out);
    }
    free_children(regions, count);
    if (st == SC_OK && kind == MODEL_XFORM)
        st = transform(e, n, m, count, out);
    if (st == SC_OK && kind == MODEL_OFFSET)
        st = offset(e, n, out);
    if (st == SC_OK && kind == MODEL_RESIZE && resize_scale(n->u.resize, out, m))
        st = transform(e, n, m, count, out);
    return st;
}

static eval evaluator(const build_ctx *c, const char *outer)
{
    eval e = {{c, outer, "2D nodes", eval_node}, c, outer, 1};
    return e;
}

sc_status build_twod_add_error(const build_ctx *c, const model_node *n,
                               const twod_region *r)
{
    eval e = evaluator(c, n->name);
    return clip_status(
        &e, n, r->point_count >= TWOD_MAX_POINTS ? TWOD_CLIP_TOO_MANY : TWOD_CLIP_NOMEM);
}

sc_status build_twod_children(const build_ctx *c, const model_node *parent,
                              twod_region *out)
{
    eval e = evaluator(c, parent->name);
    twod_region *regions;
    uint32_t count;
    sc_status st = eval_children(&e, parent, &regions, &count, 1);
    if (st == SC_OK)
        st = combine(&e, parent, regions, count, TWOD_UNION, out);
    free_children(regions, count);
    return st;
}

sc_status build_twod_node(const build_ctx *c, const model_node *n, const char *outer,
                          twod_region *out)
{
    eval e = evaluator(c, outer);
    return twod_walk(&e.walk, n, &unmoved, 1, out);
}

sc_status build_twod_main(const build_ctx *c, const model_node *n, twod_region *out)
{
    eval e = evaluator(c, n->name);
    e.in_2d = 0;
    return twod_walk(&e.walk, n, &unmoved, 1, out);
}

sc_status build_twod_check(const build_ctx *c, const model_node *n, int *empty)
{
    twod_region r;
    twod_init(&r);
    sc_status st = build_twod_main(c, n, &r);
    if (empty)
        *empty = r.contour_count == 0;
    twod_free(&r);
    return st;
}

sc_status build_twod_background(const build_ctx *c, const model_node *k,
                                const char *outer)
{
    eval e = evaluator(c, outer);
    return background(&e, k, 1);
}

sc_status build_twod_top(const build_ctx *c, const model_node *first, twod_region *out)
{
    eval e = evaluator(c, "the 2D model");
    e.in_2d = 0;
    twod_region *regions;
    uint32_t count;
    sc_status st = eval_list(&e, first, MODEL_UNION, 0, &regions, &count, 0);
    if (st == SC_OK && count)
        st = combine(&e, first, regions, count, TWOD_UNION, out);
    free_children(regions, count);
    return st;
}
