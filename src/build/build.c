/* The scene builder: see build.h for what each node means.
 *
 * The syntax tree is walked in file order with an explicit stack of frames,
 * one per open boolean node (group, union, multmatrix, ...). A frame holds
 * what its children inherit (the accumulated transform, the colour, whether
 * leaves are built at all) and where its children's results start on a
 * stack of CSG node ids. A leaf pushes its id; when a frame's children are
 * done, their ids become one csg_builder_op node, pushed for the parent.
 *
 * Two flags per node keep the modifiers apart:
 *   emit     leaves under the node are built (off under '%', under a
 *            singular transform, and outside the '!' subtree when a file
 *            has one);
 *   counted  the node's result is an operand of its parent's operation (off
 *            under '%' and outside the '!' subtree; a singular transform is
 *            counted as the empty solid, since OpenSCAD gives its subtree
 *            no geometry, which empties an enclosing intersection).
 * Nodes that are not built are still checked, so an error is an error
 * wherever it is written; only '*' subtrees are skipped unread.
 *
 * Polyhedra: OpenSCAD lists each face's points clockwise seen from outside.
 * Rather than trust the winding, each face plane is oriented by the points:
 * a convex polyhedron lies entirely on one side of each of its face planes,
 * and that side is inside. The polyhedron must be closed (every edge shared
 * by exactly two faces); it takes the plane path when convex: no point may
 * lie on the outer side of a face plane by more than 1e-5 of the largest
 * coordinate, which absorbs the 6 significant digits OpenSCAD writes
 * numbers with. (The centroid of the points would orient the planes too,
 * but it can sit on a face of a non-convex mesh; the extremes of the points
 * cannot mislead.) Other polyhedra become triangle meshes (build_mesh.c).
 */
#include "build/build.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_curved.h"
#include "build/build_hull.h"
#include "build/build_mesh.h"
#include "build/build_revolve.h"
#include "build/build_shading.h"
#include "build/build_twod.h"
#include "model/faithful.h"

typedef enum node_kind {
    KIND_UNION, /* group, union, render */
    KIND_DIFFERENCE,
    KIND_INTERSECTION,
    KIND_MULTMATRIX,
    KIND_COLOR,
    KIND_CUBE,
    KIND_SPHERE,
    KIND_CYLINDER,
    KIND_POLYHEDRON,
    KIND_IMPORT,         /* build_mesh.c */
    KIND_LINEAR_EXTRUDE, /* build_extrude.c; its children are its own */
    KIND_ROTATE_EXTRUDE, /* build_revolve.c; its children are its own */
    KIND_TWOD,           /* 2D shapes: checked, then ignored with a warning */
    KIND_HULL,           /* build_hull.c; its children are its own */
    KIND_MINKOWSKI,      /* build_hull.c; its children are its own */
    KIND_SURFACE,        /* build_surface.c */
    KIND_TORUS,          /* torus, quadric, implicit: build_implicit.c */
    KIND_QUADRIC,
    KIND_IMPLICIT, /* the last leaf kind (is_leaf) */
    KIND_MATERIAL, /* spancast's shading nodes: build_shading.c */
    KIND_RESIZE,   /* a scale from the children's box: build_hull.c */
    KIND_LIGHT,
    KIND_CAMERA,
    KIND_BACKGROUND,
    KIND_UNSUPPORTED, /* known, not rendered yet */
    KIND_UNKNOWN
} node_kind;

static const struct {
    const char *name;
    node_kind kind;
} node_names[] = {
    {"group", KIND_UNION},
    {"union", KIND_UNION},
    {"render", KIND_UNION},
    {"difference", KIND_DIFFERENCE},
    {"intersection", KIND_INTERSECTION},
    {"multmatrix", KIND_MULTMATRIX},
    {"color", KIND_COLOR},
    {"cube", KIND_CUBE},
    {"sphere", KIND_SPHERE},
    {"cylinder", KIND_CYLINDER},
    {"polyhedron", KIND_POLYHEDRON},
    /* What else OpenSCAD writes. */
    {"hull", KIND_HULL},
    {"minkowski", KIND_MINKOWSKI},
    {"linear_extrude", KIND_LINEAR_EXTRUDE},
    {"rotate_extrude", KIND_ROTATE_EXTRUDE},
    {"import", KIND_IMPORT},
    {"surface", KIND_SURFACE},
    {"projection", KIND_UNSUPPORTED},
    {"offset", KIND_TWOD},
    {"circle", KIND_TWOD},
    {"square", KIND_TWOD},
    {"polygon", KIND_TWOD},
    {"text", KIND_TWOD},
    {"resize", KIND_RESIZE},
    {"roof", KIND_UNSUPPORTED},
    {"intersection_for", KIND_UNSUPPORTED},
    /* spancast's own extensions. */
    {"torus", KIND_TORUS},
    {"quadric", KIND_QUADRIC},
    {"halfspace", KIND_UNSUPPORTED},
    {"implicit", KIND_IMPLICIT},
    {"material", KIND_MATERIAL},
    {"light", KIND_LIGHT},
    {"camera", KIND_CAMERA},
    {"background", KIND_BACKGROUND},
};

static node_kind kind_of(const char *name)
{
    for (size_t i = 0; i < sizeof node_names / sizeof node_names[0]; i++) {
        if (strcmp(node_names[i].name, name) == 0)
            return node_names[i].kind;
    }
    return KIND_UNKNOWN;
}

static int is_leaf(node_kind kind)
{
    return kind >= KIND_CUBE && kind <= KIND_IMPLICIT;
}

typedef struct frame {
    const parse_node *node; /* NULL for the file itself */
    csg_op op;
    int emit;        /* leaves below are built */
    int counted;     /* the result is an operand of the parent */
    size_t first_id; /* children's results start here on the id stack */
    float color[4];
    uint32_t material; /* index into the shading record's materials */
    affine to_world;
} frame;

typedef struct builder {
    const parse_tree *syntax;
    csg_builder *csg;
    sc_error *error;
    sc_error *warnings;
    size_t warning_count, warning_cap;
    uint32_t *ids; /* results waiting for their parent's operation */
    size_t id_count, id_cap;
    frame *frames;
    size_t frame_count, frame_cap;
    shading *shading;       /* lights, materials, camera, background */
    int faithful;           /* OpenSCAD's polyhedra for spheres and cylinders */
    const parse_node *root; /* the first '!' node, or NULL */
    uint32_t root_id;       /* its result */
    /* the first 2D shape ignored in the 3D model, and the 3D leaves built */
    const parse_node *first_2d;
    size_t solid_leaves;
    /* resize matrices measured so far (build_hull.h) */
    build_resize_cache *resize_cache;
} builder;

static sc_location value_loc(const builder *b, const parse_value *v)
{
    sc_location loc = {b->syntax->file, v->line, v->column};
    return loc;
}

static sc_status warn(builder *b, const sc_location *loc, const char *format, ...)
    SC_PRINTF(3, 4);
static sc_status warn(builder *b, const sc_location *loc, const char *format, ...)
{
    if (!grow_array((void **)&b->warnings, &b->warning_cap, b->warning_count + 1,
                    sizeof *b->warnings))
        return err_nomem(b->error, NULL);
    char message[SC_ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    err_set(&b->warnings[b->warning_count++], SC_OK, loc, "%s", message);
    return SC_OK;
}

static sc_status push_id(builder *b, uint32_t id)
{
    if (!grow_array((void **)&b->ids, &b->id_cap, b->id_count + 1, sizeof *b->ids))
        return err_nomem(b->error, NULL);
    b->ids[b->id_count++] = id;
    return SC_OK;
}

/* Hands a node's result to whoever takes it: the design when the node is
 * the root, else its parent when it is counted. */
static sc_status deliver(builder *b, const parse_node *node, int counted, uint32_t id)
{
    if (node && node == b->root) {
        b->root_id = id;
        return SC_OK;
    }
    return counted ? push_id(b, id) : SC_OK;
}

/* ---- arguments ---- */

/* The value of parameter name (or of the position-th positional argument);
 * NULL when it is not given or undef. */
static const parse_value *arg(const parse_node *n, const char *name, int position)
{
    const parse_arg *a = parse_node_arg(n, name, position);
    return a && a->value.kind != PARSE_UNDEF ? &a->value : NULL;
}

static sc_status wrong_type(builder *b, const parse_node *n, const char *param,
                            const parse_value *v, const char *expected)
{
    sc_location loc = value_loc(b, v);
    return err_set(b->error, SC_ERR_SEMANTIC, &loc,
                   "wrong type for argument '%s' of '%s' (expected %s)", param, n->name,
                   expected);
}

/* Reads a number parameter into *out; *given says whether it was set. */
static sc_status get_number(builder *b, const parse_node *n, const char *name,
                            int position, double *out, int *given)
{
    const parse_value *v = arg(n, name, position);
    *given = 0;
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_NUMBER)
        return wrong_type(b, n, name, v, "a number");
    *out = v->u.number;
    *given = 1;
    return SC_OK;
}

static sc_status get_bool(builder *b, const parse_node *n, const char *name, int position,
                          int *out)
{
    const parse_value *v = arg(n, name, position);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_BOOL)
        return wrong_type(b, n, name, v, "true or false");
    *out = v->u.boolean;
    return SC_OK;
}

/* OpenSCAD's radius lookup: a diameter wins over a radius. */
static sc_status get_radius(builder *b, const parse_node *n, const char *diameter,
                            const char *radius, int radius_position, double *out,
                            int *given)
{
    double d = 0;
    int has_d;
    sc_status st = get_number(b, n, diameter, -1, &d, &has_d);
    if (st == SC_OK)
        st = get_number(b, n, radius, radius_position, out, given);
    if (st == SC_OK && has_d) {
        *out = d / 2;
        *given = 1;
    }
    return st;
}

static int positive_finite(double x)
{
    return x > 0 && isfinite(x);
}

/* ---- leaves ---- */

static sc_status add_leaf(builder *b, const parse_node *n, const prim *p,
                          const frame *state, uint32_t *id)
{
    *id = csg_builder_leaf(b->csg, p, &state->to_world, state->color, n->loc);
    csg_builder_set_material(b->csg, *id, state->material);
    return csg_builder_failed(b->csg) ? err_nomem(b->error, NULL) : SC_OK;
}

/* cube(size = 1, center = false): size is a number or [x, y, z]. */
static sc_status build_cube(builder *b, const parse_node *n, const frame *state,
                            uint32_t *id)
{
    double size[3];
    int center;
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    sc_status st = build_cube_args(&c, n, size, &center);
    if (st != SC_OK || !state->emit)
        return st;
    if (!positive_finite(size[0]) || !positive_finite(size[1]) ||
        !positive_finite(size[2]))
        return warn(b, &n->loc, "cube with a zero, negative or non-finite size is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_BOX;
    vec3 s = v3(size[0], size[1], size[2]);
    p.u.box.lo = center ? v3_scale(s, -0.5) : v3(0, 0, 0);
    p.u.box.hi = center ? v3_scale(s, 0.5) : s;
    return add_leaf(b, n, &p, state, id);
}

/* sphere(r = 1) or sphere(d = 2). */
static sc_status build_sphere(builder *b, const parse_node *n, const frame *state,
                              uint32_t *id)
{
    double r = 1;
    int given;
    sc_status st = get_radius(b, n, "d", "r", 0, &r, &given);
    if (st != SC_OK || !state->emit)
        return st;
    if (!positive_finite(r))
        return warn(b, &n->loc,
                    "sphere with a zero, negative or non-finite radius is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_SPHERE;
    p.u.sphere.r = r;
    if (b->faithful) {
        double fn, fa, fs;
        parse_node_resolution(n, &fn, &fa, &fs);
        if ((st = faithful_sphere(b->csg, r, fn, fa, fs, &n->loc, &p, b->error)) != SC_OK)
            return st;
    }
    return add_leaf(b, n, &p, state, id);
}

/* cylinder(h = 1, r1 = 1, r2 = 1, center = false), also with r, d, d1, d2:
 * r1/d1 and r2/d2 win over r/d, a diameter over a radius. */
static sc_status build_cylinder(builder *b, const parse_node *n, const frame *state,
                                uint32_t *id)
{
    double h = 1, r = 1, r1 = 1, r2 = 1;
    int has_h, has_r, has_r1, has_r2, center = 0;
    sc_status st = get_number(b, n, "h", 0, &h, &has_h);
    if (st == SC_OK)
        st = get_radius(b, n, "d1", "r1", 1, &r1, &has_r1);
    if (st == SC_OK)
        st = get_radius(b, n, "d2", "r2", 2, &r2, &has_r2);
    if (st == SC_OK)
        st = get_radius(b, n, "d", "r", -1, &r, &has_r);
    if (st == SC_OK)
        st = get_bool(b, n, "center", 3, &center);
    if (st != SC_OK || !state->emit)
        return st;
    if (!has_r1)
        r1 = r;
    if (!has_r2)
        r2 = r;
    if (!positive_finite(h))
        return warn(b, &n->loc,
                    "cylinder with a zero, negative or non-finite height is empty");
    if (!(r1 >= 0 && r2 >= 0) || !isfinite(r1) || !isfinite(r2) || (r1 == 0 && r2 == 0))
        return warn(b, &n->loc,
                    "cylinder with negative, non-finite or two zero radii is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_CYLINDER;
    p.u.cylinder.z0 = center ? -h / 2 : 0;
    p.u.cylinder.z1 = center ? h / 2 : h;
    p.u.cylinder.r0 = r1;
    p.u.cylinder.r1 = r2;
    if (b->faithful) {
        double fn, fa, fs;
        parse_node_resolution(n, &fn, &fa, &fs);
        if ((st = faithful_cylinder(b->csg, p.u.cylinder.z0, p.u.cylinder.z1, r1, r2, fn,
                                    fa, fs, &n->loc, &p, b->error)) != SC_OK)
            return st;
    }
    return add_leaf(b, n, &p, state, id);
}

/* ---- polyhedron ---- */

typedef struct mesh {
    vec3 *points;
    uint32_t point_count;
    uint32_t *indices;    /* all faces' point indices, face after face */
    uint32_t *face_start; /* face f is indices[face_start[f] .. face_start[f + 1]) */
    uint32_t face_count;
    uint64_t *edges; /* scratch: undirected edges as (lo << 32 | hi) */
    plane *planes;   /* scratch: one per face */
} mesh;

static void mesh_free(mesh *m)
{
    free(m->points);
    free(m->indices);
    free(m->face_start);
    free(m->edges);
    free(m->planes);
}

static const char points_expected[] = "a vector of [x, y, z] points";
static const char faces_expected[] = "a vector of faces, each a vector of point indices";

static sc_status read_points(builder *b, const parse_node *n, const parse_value *v,
                             mesh *m)
{
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return wrong_type(b, n, "points", v, points_expected);
    uint32_t count = v->u.vector.count;
    if (count && !(m->points = calloc(count, sizeof *m->points)))
        return err_nomem(b->error, NULL);
    for (uint32_t i = 0; i < count; i++) {
        const parse_value *pv = &v->u.vector.items[i];
        if (pv->kind != PARSE_VECTOR || pv->u.vector.count != 3)
            return wrong_type(b, n, "points", pv, points_expected);
        double c[3];
        for (int k = 0; k < 3; k++) {
            const parse_value *cv = &pv->u.vector.items[k];
            if (cv->kind != PARSE_NUMBER)
                return wrong_type(b, n, "points", cv, points_expected);
            c[k] = cv->u.number;
        }
        m->points[i] = v3(c[0], c[1], c[2]);
        if (!v3_is_finite(m->points[i])) {
            sc_location loc = value_loc(b, pv);
            return err_set(b->error, SC_ERR_SEMANTIC, &loc,
                           "polyhedron point %u is not finite", i);
        }
    }
    m->point_count = count;
    return SC_OK;
}

static sc_status read_faces(builder *b, const parse_node *n, const char *param,
                            const parse_value *v, mesh *m)
{
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return wrong_type(b, n, param, v, faces_expected);
    uint32_t count = v->u.vector.count;
    size_t total = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        if (fv->kind != PARSE_VECTOR)
            return wrong_type(b, n, param, fv, faces_expected);
        total += fv->u.vector.count;
    }
    if (total > UINT32_MAX)
        return err_nomem(b->error, NULL);
    m->face_start = calloc((size_t)count + 1, sizeof *m->face_start);
    if (!m->face_start || (total && !(m->indices = calloc(total, sizeof *m->indices))))
        return err_nomem(b->error, NULL);
    uint32_t k = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        m->face_start[f] = k;
        if (fv->u.vector.count < 3) {
            sc_location loc = value_loc(b, fv);
            return err_set(b->error, SC_ERR_SEMANTIC, &loc,
                           "polyhedron face %u has fewer than 3 points", f);
        }
        for (uint32_t i = 0; i < fv->u.vector.count; i++) {
            const parse_value *iv = &fv->u.vector.items[i];
            if (iv->kind != PARSE_NUMBER)
                return wrong_type(b, n, param, iv, faces_expected);
            double x = iv->u.number;
            sc_location loc = value_loc(b, iv);
            if (!(x == floor(x)))
                return err_set(b->error, SC_ERR_SEMANTIC, &loc,
                               "polyhedron face %u: point index %g is not a whole number",
                               f, x);
            if (x < 0 || x >= (double)m->point_count)
                return err_set(
                    b->error, SC_ERR_SEMANTIC, &loc,
                    "polyhedron face %u: point index %g is out of range (%u points)", f,
                    x, m->point_count);
            m->indices[k++] = (uint32_t)x;
        }
    }
    m->face_start[count] = k;
    m->face_count = count;
    return SC_OK;
}

static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* Every undirected edge must belong to exactly two faces. */
static sc_status check_closed(builder *b, const parse_node *n, mesh *m)
{
    uint32_t total = m->face_start[m->face_count];
    if (!(m->edges = calloc(total, sizeof *m->edges)))
        return err_nomem(b->error, NULL);
    size_t count = 0;
    for (uint32_t f = 0; f < m->face_count; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1];
        for (uint32_t i = s; i < e; i++) {
            uint32_t p = m->indices[i], q = m->indices[i + 1 < e ? i + 1 : s];
            if (p == q)
                continue; /* a repeated point adds no edge */
            uint32_t lo = p < q ? p : q, hi = p < q ? q : p;
            m->edges[count++] = (uint64_t)lo << 32 | hi;
        }
    }
    qsort(m->edges, count, sizeof *m->edges, compare_u64);
    for (size_t i = 0; i < count;) {
        size_t j = i;
        while (j < count && m->edges[j] == m->edges[i])
            j++;
        if (j - i != 2)
            return err_set(b->error, SC_ERR_SEMANTIC, &n->loc,
                           "polyhedron is not closed (edge %u-%u is used by %zu face%s)",
                           (unsigned)(m->edges[i] >> 32),
                           (unsigned)(m->edges[i] & 0xffffffffu), j - i,
                           j - i == 1 ? "" : "s");
        i = j;
    }
    return SC_OK;
}

/* Builds the outward face planes (duplicates merged) and checks convexity.
 * Each plane is oriented by the points themselves: all of them must lie on
 * one side, within tol, and inside is that side. A plane with every point
 * on it means the polyhedron is flat. Returns the plane count in *count;
 * 0 means the polyhedron has no volume, UINT32_MAX that it is not convex. */
static sc_status convex_planes(builder *b, mesh *m, uint32_t *count, bbox *bounds)
{
    *count = 0;
    /* The points the faces use: their bounds and scale. */
    uint32_t total = m->face_start[m->face_count];
    unsigned char *used = calloc(m->point_count ? m->point_count : 1, 1);
    if (!used)
        return err_nomem(b->error, NULL);
    double scale = 0;
    *bounds = bbox_empty();
    for (uint32_t i = 0; i < total; i++) {
        uint32_t k = m->indices[i];
        if (used[k])
            continue;
        used[k] = 1;
        scale = fmax(scale, v3_max_abs(m->points[k]));
        *bounds = bbox_add_point(*bounds, m->points[k]);
    }
    if (!(m->planes = calloc(m->face_count, sizeof *m->planes))) {
        free(used);
        return err_nomem(b->error, NULL);
    }
    double tol = 1e-5 * scale; /* convexity, absorbs 6-digit rounding */
    double flat = 1e-12 * scale;
    uint32_t planes = 0;
    sc_status st = SC_OK;
    for (uint32_t f = 0; f < m->face_count; f++) {
        uint32_t s = m->face_start[f], e = m->face_start[f + 1];
        vec3 c = v3(0, 0, 0);
        for (uint32_t i = s; i < e; i++)
            c = v3_add(c, m->points[m->indices[i]]);
        c = v3_scale(c, 1.0 / (e - s));
        /* Newell's normal, about the face centroid for accuracy. */
        vec3 nrm = v3(0, 0, 0);
        for (uint32_t i = s; i < e; i++) {
            vec3 p = v3_sub(m->points[m->indices[i]], c);
            vec3 q = v3_sub(m->points[m->indices[i + 1 < e ? i + 1 : s]], c);
            nrm = v3_add(nrm, v3_cross(p, q));
        }
        double len = v3_length(nrm);
        if (!(len > 1e-24 * scale * scale))
            continue; /* no area, no orientation: the other faces bound it */
        nrm = v3_scale(nrm, 1.0 / len);
        double d = v3_dot(nrm, c);
        double lo = 0, hi = 0; /* extreme signed distances of the points */
        for (uint32_t i = 0; i < m->point_count; i++) {
            if (!used[i])
                continue;
            double dist = v3_dot(nrm, m->points[i]) - d;
            lo = fmin(lo, dist);
            hi = fmax(hi, dist);
        }
        if (hi - lo <= flat) {
            planes = 0; /* every point on one plane: flat */
            break;
        }
        if (hi > -lo) {
            nrm = v3_neg(nrm);
            d = -d;
            double t = hi;
            hi = -lo;
            lo = -t;
        }
        if (hi > tol) {
            *count = UINT32_MAX; /* not convex: the mesh path takes it */
            free(used);
            return SC_OK;
        }
        int duplicate = 0;
        for (uint32_t k = 0; k < planes && !duplicate; k++)
            duplicate = v3_dot(m->planes[k].n, nrm) >= 1 - 1e-14 &&
                        fabs(m->planes[k].d - d) <= flat;
        if (duplicate)
            continue;
        m->planes[planes].n = nrm;
        m->planes[planes].d = d;
        planes++;
    }
    free(used);
    *count = planes < 4 ? 0 : planes;
    return st;
}

/* polyhedron(points, faces, convexity), faces also as the older
 * `triangles`. */
static sc_status build_polyhedron(builder *b, const parse_node *n, const frame *state,
                                  uint32_t *id)
{
    mesh m;
    memset(&m, 0, sizeof m);
    const char *faces_name = "faces";
    const parse_value *faces = arg(n, "faces", 1);
    if (!faces && (faces = arg(n, "triangles", -1)))
        faces_name = "triangles";
    sc_status st = read_points(b, n, arg(n, "points", 0), &m);
    if (st == SC_OK)
        st = read_faces(b, n, faces_name, faces, &m);
    if (st == SC_OK && m.face_count == 0) {
        if (state->emit)
            st = warn(b, &n->loc, "polyhedron without faces is empty");
        mesh_free(&m);
        return st;
    }
    if (st == SC_OK)
        st = check_closed(b, n, &m);
    /* The plane-set path compares every face with every point (and every
     * plane with the others), so larger polyhedra go to the mesh path
     * (build_mesh.c), as do the ones that are not convex. */
    uint32_t count = UINT32_MAX;
    bbox bounds;
    if (st == SC_OK &&
        (uint64_t)m.face_count * m.point_count <= BUILD_MAX_POLYHEDRON_WORK)
        st = convex_planes(b, &m, &count, &bounds);
    if (st == SC_OK && count == UINT32_MAX) {
        build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
        const char *empty = NULL;
        prim p;
        st = build_mesh_prim(&c, &n->loc, "polyhedron", m.points, m.point_count,
                             m.indices, m.face_start, m.face_count, &p, &empty);
        if (st == SC_OK && state->emit)
            st = empty ? warn(b, &n->loc, "%s", empty) : add_leaf(b, n, &p, state, id);
        mesh_free(&m);
        return st;
    }
    if (st == SC_OK && state->emit && count == 0)
        st = warn(b, &n->loc, "polyhedron without volume is empty");
    if (st == SC_OK && state->emit && count > 0) {
        plane *planes = csg_builder_alloc(b->csg, (size_t)count * sizeof *planes);
        if (!planes) {
            st = err_nomem(b->error, NULL);
        } else {
            memcpy(planes, m.planes, (size_t)count * sizeof *planes);
            prim p;
            memset(&p, 0, sizeof p);
            p.kind = PRIM_CONVEX;
            p.u.convex.planes = planes;
            p.u.convex.count = count;
            p.u.convex.bounds = bounds;
            st = add_leaf(b, n, &p, state, id);
        }
    }
    mesh_free(&m);
    return st;
}

/* torus, quadric, implicit (build_implicit.c). */
static sc_status build_curved(builder *b, const parse_node *n, node_kind kind,
                              const frame *state, uint32_t *id)
{
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    const char *empty = NULL;
    prim p;
    memset(&p, 0, sizeof p);
    sc_status st = kind == KIND_TORUS ? build_torus(&c, n, state->emit, &p, &empty)
                   : kind == KIND_QUADRIC
                       ? build_quadric(&c, n, state->emit, &p, &empty)
                       : build_implicit(&c, n, state->emit, &p, &empty);
    if (st != SC_OK || !state->emit)
        return st;
    if (empty)
        return warn(b, &n->loc, "%s", empty);
    return add_leaf(b, n, &p, state, id);
}

/* import(file = "...") (build_mesh.c), linear_extrude (build_extrude.c)
 * or rotate_extrude (build_revolve.c). */
static sc_status build_import_leaf(builder *b, const parse_node *n, node_kind kind,
                                   const frame *state, uint32_t *id)
{
    sc_error note = {SC_OK, "", 0, 0, ""}; /* a warning, e.g. a font fallback */
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, &note};
    const char *empty = NULL;
    prim p;
    sc_status st = kind == KIND_IMPORT ? build_import(&c, n, state->emit, &p, &empty)
                   : kind == KIND_LINEAR_EXTRUDE
                       ? build_linear_extrude(&c, n, state->emit, &p, &empty)
                       : build_rotate_extrude(&c, n, state->emit, &p, &empty);
    if (st != SC_OK || !state->emit)
        return st;
    if (note.message[0]) {
        sc_location at = {b->syntax->file, note.line, note.column};
        if ((st = warn(b, &at, "%s", note.message)) != SC_OK)
            return st;
    }
    if (empty)
        return warn(b, &n->loc, "%s", empty);
    return add_leaf(b, n, &p, state, id);
}

/* A 2D shape (circle, square, polygon, offset) among 3D objects: checked
 * through the 2D engine, then the empty solid with a warning, as OpenSCAD
 * ignores 2D objects in a 3D model. */
static sc_status build_twod_ignored(builder *b, const parse_node *n, const frame *state)
{
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    twod_region r;
    twod_init(&r);
    sc_status st = build_twod_node(&c, n, n->name, &r);
    twod_free(&r);
    if (st != SC_OK || !state->emit)
        return st;
    if (!b->first_2d)
        b->first_2d = n;
    return warn(b, &n->loc, "2D object '%s' in a 3D model is ignored (as in OpenSCAD)",
                n->name);
}

/* hull and minkowski (build_hull.c): one or several convex leaves, united. */
static sc_status build_hull_leaf(builder *b, const parse_node *n, node_kind kind,
                                 const frame *state, uint32_t *id)
{
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    const char *empty = NULL;
    build_prims leaves = {NULL, 0, 0};
    sc_status st =
        kind == KIND_HULL
            ? build_hull(&c, n, state->emit, &b->resize_cache, &leaves, &empty)
            : build_minkowski(&c, n, state->emit, &b->resize_cache, &leaves, &empty);
    uint32_t *ids = leaves.count ? calloc(leaves.count, sizeof *ids) : NULL;
    if (st == SC_OK && leaves.count && !ids)
        st = err_nomem(b->error, NULL);
    if (st == SC_OK && state->emit && empty)
        st = warn(b, &n->loc, "%s", empty);
    for (uint32_t i = 0; st == SC_OK && state->emit && i < leaves.count; i++)
        st = add_leaf(b, n, &leaves.items[i], state, &ids[i]);
    if (st == SC_OK && leaves.count == 1)
        *id = ids[0];
    if (st == SC_OK && leaves.count > 1) {
        *id = csg_builder_op(b->csg, CSG_UNION, ids, leaves.count);
        if (csg_builder_failed(b->csg))
            st = err_nomem(b->error, NULL);
    }
    free(ids);
    free(leaves.items);
    return st;
}

/* surface(file) (build_surface.c). */
static sc_status build_surface_leaf(builder *b, const parse_node *n, const frame *state,
                                    uint32_t *id)
{
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    const char *empty = NULL;
    prim p;
    sc_status st = build_surface(&c, n, state->emit, &p, &empty);
    if (st != SC_OK || !state->emit)
        return st;
    if (empty)
        return warn(b, &n->loc, "%s", empty);
    return add_leaf(b, n, &p, state, id);
}

/* ---- boolean nodes with arguments ---- */

/* multmatrix(m = [[...], [...], [...], [0, 0, 0, 1]]): a row-major 4x4
 * affine matrix of finite numbers; no argument means the identity. */
static sc_status read_matrix(builder *b, const parse_node *n, affine *out)
{
    build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
    double m[4][4];
    sc_status st = build_matrix(&c, n, m);
    if (st != SC_OK)
        return st;
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            out->m[r][k] = m[r][k];
    return SC_OK;
}

/* color(c, alpha): c is [r, g, b, a] (missing components are 1, as in
 * OpenSCAD), a colour name or "#hex"; alpha replaces the alpha. A negative
 * red is OpenSCAD's "no colour" (it writes color([-1, -1, -1, 1]) for a name
 * it did not know): the children keep the colour they inherit. */
static sc_status read_color(builder *b, const parse_node *n, int emit, float color[4])
{
    static const char expected[] = "a vector of numbers or a colour name";
    float rgba[4] = {1, 1, 1, 1};
    int set = 0;
    sc_status st = SC_OK;
    const parse_value *v = arg(n, "c", 0);
    if (v && v->kind == PARSE_VECTOR) {
        double c[4] = {1, 1, 1, 1};
        for (uint32_t i = 0; i < v->u.vector.count; i++) {
            const parse_value *item = &v->u.vector.items[i];
            if (item->kind != PARSE_NUMBER)
                return wrong_type(b, n, "c", item, expected);
            if (i < 4)
                c[i] = item->u.number;
        }
        set = !(c[0] < 0);
        for (int i = 0; set && i < 4; i++) {
            if (!(c[i] >= 0 && c[i] <= 1)) {
                if (emit) {
                    sc_location loc = value_loc(b, &v->u.vector.items[i]);
                    if ((st = warn(b, &loc,
                                   "colour component %g is out of range 0..1 (clamped)",
                                   c[i])) != SC_OK)
                        return st;
                }
                c[i] = c[i] > 1 ? 1 : 0;
            }
            rgba[i] = (float)c[i];
        }
    } else if (v && v->kind == PARSE_STRING) {
        set = colors_lookup(v->u.string.chars, v->u.string.length, rgba);
        if (!set && emit) {
            sc_location loc = value_loc(b, v);
            if ((st = warn(b, &loc, "unknown colour '%s' is ignored",
                           v->u.string.chars)) != SC_OK)
                return st;
        }
    } else if (v) {
        return wrong_type(b, n, "c", v, expected);
    }
    double alpha = 1;
    int has_alpha;
    if ((st = get_number(b, n, "alpha", 1, &alpha, &has_alpha)) != SC_OK)
        return st;
    if (has_alpha && set) {
        if (!(alpha >= 0 && alpha <= 1)) {
            if (emit) {
                sc_location loc = value_loc(b, arg(n, "alpha", 1));
                if ((st = warn(b, &loc,
                               "colour component %g is out of range 0..1 (clamped)",
                               alpha)) != SC_OK)
                    return st;
            }
            alpha = alpha > 1 ? 1 : 0;
        }
        rgba[3] = (float)alpha;
    }
    if (set)
        memcpy(color, rgba, sizeof rgba);
    return SC_OK;
}

/* ---- the walk ---- */

static sc_status push_frame(builder *b, const frame *f)
{
    if (!grow_array((void **)&b->frames, &b->frame_cap, b->frame_count + 1,
                    sizeof *b->frames))
        return err_nomem(b->error, NULL);
    b->frames[b->frame_count++] = *f;
    return SC_OK;
}

/* Ends the innermost frame: its children's results become one node. */
static sc_status pop_frame(builder *b)
{
    frame f = b->frames[--b->frame_count];
    uint32_t id = CSG_EMPTY;
    if (f.emit) {
        size_t count = b->id_count - f.first_id;
        if (count > UINT32_MAX)
            return err_nomem(b->error, NULL);
        /* No id pushed yet means no id array at all: NULL + 0 is undefined. */
        const uint32_t *children = count ? b->ids + f.first_id : NULL;
        id = csg_builder_op(b->csg, f.op, children, (uint32_t)count);
        if (csg_builder_failed(b->csg))
            return err_nomem(b->error, NULL);
    }
    b->id_count = f.first_id;
    return deliver(b, f.node, f.counted, id);
}

/* The first '!' node in file order, outside '*' subtrees and leaves'
 * ignored children, found before the walk so that everything outside it
 * can be checked without being built. */
static const parse_node *find_root(const parse_tree *syntax)
{
    const parse_node *n = syntax->first;
    while (n) {
        if (n->modifiers & PARSE_MOD_DISABLE) {
            n = parse_next_node(n, 1);
            continue;
        }
        if (n->modifiers & PARSE_MOD_ROOT)
            return n;
        n = parse_next_node(n, is_leaf(kind_of(n->name)));
    }
    return NULL;
}

/* $fn, where a node sets it to a number, must be finite and at most
 * BUILD_MAX_FN (zero or negative means "use $fa and $fs", as in OpenSCAD). */
static sc_status check_fn(builder *b, const parse_node *n)
{
    const parse_value *v = arg(n, "$fn", -1);
    if (!v || v->kind != PARSE_NUMBER || v->u.number <= BUILD_MAX_FN)
        return SC_OK;
    sc_location loc = value_loc(b, v);
    if (isnan(v->u.number))
        return err_set(b->error, SC_ERR_SEMANTIC, &loc, "$fn must be a number (got nan)");
    return err_set(b->error, SC_ERR_LIMIT, &loc, "$fn %g is too large (limit is %d)",
                   v->u.number, BUILD_MAX_FN);
}

/* Visits one node: a leaf delivers its result; a boolean node opens a
 * frame for its children. *opened says which. */
static sc_status visit(builder *b, const parse_node *n, int *opened)
{
    *opened = 0;
    sc_status st;
    node_kind kind = kind_of(n->name);
    if (kind == KIND_UNKNOWN)
        return err_set(b->error, SC_ERR_SEMANTIC, &n->loc, "unknown node '%s'", n->name);
    if (kind == KIND_UNSUPPORTED)
        return err_set(b->error, SC_ERR_UNSUPPORTED, &n->loc, "'%s' is not supported yet",
                       n->name);
    if ((st = check_fn(b, n)) != SC_OK)
        return st;
    if ((n->modifiers & PARSE_MOD_ROOT) && n != b->root &&
        (st = warn(b, &n->loc,
                   "root modifier '!' is used more than once; only the first is used")) !=
            SC_OK)
        return st;
    const frame *parent = &b->frames[b->frame_count - 1];
    frame f = *parent;
    f.node = n;
    if (n == b->root) {
        static const float default_color[4] = BUILD_DEFAULT_COLOR;
        f.emit = 1;
        f.to_world = affine_identity();
        memcpy(f.color, default_color, sizeof f.color);
        f.material = 0;
    }
    if (n->modifiers & PARSE_MOD_BACKGROUND)
        f.emit = 0;
    f.counted = f.emit;
    if (kind == KIND_LIGHT)
        return build_light(b->shading, b->syntax, n, &f.to_world, f.emit, b->error);
    if (kind == KIND_CAMERA)
        return build_camera(b->shading, b->syntax, n, f.emit, b->error);
    if (kind == KIND_BACKGROUND)
        return build_background(b->shading, b->syntax, n, f.emit, b->error);
    if (is_leaf(kind)) {
        if (n->child_count > 0 && f.emit && kind != KIND_LINEAR_EXTRUDE &&
            kind != KIND_ROTATE_EXTRUDE && kind != KIND_TWOD && kind != KIND_HULL &&
            kind != KIND_MINKOWSKI &&
            (st = warn(b, &n->loc, "'%s' takes no children; they are ignored",
                       n->name)) != SC_OK)
            return st;
        uint32_t id = CSG_EMPTY;
        b->solid_leaves += f.emit && kind != KIND_TWOD;
        switch (kind) {
        case KIND_CUBE:
            st = build_cube(b, n, &f, &id);
            break;
        case KIND_SPHERE:
            st = build_sphere(b, n, &f, &id);
            break;
        case KIND_CYLINDER:
            st = build_cylinder(b, n, &f, &id);
            break;
        case KIND_TORUS:
        case KIND_QUADRIC:
        case KIND_IMPLICIT:
            st = build_curved(b, n, kind, &f, &id);
            break;
        case KIND_IMPORT:
        case KIND_LINEAR_EXTRUDE:
        case KIND_ROTATE_EXTRUDE:
            st = build_import_leaf(b, n, kind, &f, &id);
            break;
        case KIND_TWOD:
            st = build_twod_ignored(b, n, &f);
            break;
        case KIND_HULL:
        case KIND_MINKOWSKI:
            st = build_hull_leaf(b, n, kind, &f, &id);
            break;
        case KIND_SURFACE:
            st = build_surface_leaf(b, n, &f, &id);
            break;
        default:
            st = build_polyhedron(b, n, &f, &id);
            break;
        }
        return st != SC_OK ? st : deliver(b, n, f.counted, id);
    }
    f.op = kind == KIND_DIFFERENCE     ? CSG_DIFFERENCE
           : kind == KIND_INTERSECTION ? CSG_INTERSECTION
                                       : CSG_UNION;
    f.first_id = b->id_count;
    if (kind == KIND_MULTMATRIX) {
        affine m, inverse;
        if ((st = read_matrix(b, n, &m)) != SC_OK)
            return st;
        f.to_world = affine_mul(&f.to_world, &m);
        if (f.emit && !affine_invert(&f.to_world, &inverse)) {
            if ((st = warn(b, &n->loc, "singular transform: subtree is empty")) != SC_OK)
                return st;
            f.emit = 0; /* still counted: the empty solid */
        }
    } else if (kind == KIND_RESIZE) {
        build_ctx c = {b->syntax->file, b->csg, b->error, b->faithful, NULL};
        const char *warning = NULL;
        affine m;
        if ((st = build_resize(&c, n, &b->resize_cache, &m, &warning)) != SC_OK)
            return st;
        if (warning && f.emit && (st = warn(b, &n->loc, "%s", warning)) != SC_OK)
            return st;
        f.to_world = affine_mul(&f.to_world, &m);
    } else if (kind == KIND_COLOR) {
        if ((st = read_color(b, n, f.emit, f.color)) != SC_OK)
            return st;
    } else if (kind == KIND_MATERIAL) {
        if ((st = build_material(b->shading, b->syntax, n, f.emit, &f.material, f.color,
                                 b->error)) != SC_OK)
            return st;
    }
    *opened = 1;
    return push_frame(b, &f);
}

static sc_status walk(builder *b, uint32_t *root)
{
    static const float default_color[4] = BUILD_DEFAULT_COLOR;
    frame top;
    memset(&top, 0, sizeof top);
    top.op = CSG_UNION;
    top.emit = b->root == NULL;
    top.to_world = affine_identity();
    memcpy(top.color, default_color, sizeof top.color);
    sc_status st = push_frame(b, &top);
    const parse_node *n = b->syntax->first;
    while (st == SC_OK) {
        if (!n) {
            if (b->frame_count == 1)
                break;
            const parse_node *done = b->frames[b->frame_count - 1].node;
            st = pop_frame(b);
            n = done->next;
            continue;
        }
        if (n->modifiers & PARSE_MOD_DISABLE) {
            n = n->next;
            continue;
        }
        int opened;
        st = visit(b, n, &opened);
        n = opened ? n->first_child : n->next;
    }
    if (st != SC_OK)
        return st;
    if (b->root) {
        *root = b->root_id;
        return SC_OK;
    }
    if (b->id_count > UINT32_MAX)
        return err_nomem(b->error, NULL);
    *root = csg_builder_op(b->csg, CSG_UNION, b->ids, (uint32_t)b->id_count);
    return csg_builder_failed(b->csg) ? err_nomem(b->error, NULL) : SC_OK;
}

sc_status build_tree(const parse_tree *syntax, int faithful, csg_tree **out,
                     sc_error **warnings, size_t *warning_count, sc_error *error)
{
    return build_scene(syntax, faithful, out, NULL, warnings, warning_count, error);
}

sc_status build_scene(const parse_tree *syntax, int faithful, csg_tree **out,
                      shading **look, sc_error **warnings, size_t *warning_count,
                      sc_error *error)
{
    *out = NULL;
    if (look)
        *look = NULL;
    *warnings = NULL;
    *warning_count = 0;
    builder b;
    memset(&b, 0, sizeof b);
    b.syntax = syntax;
    b.error = error;
    b.faithful = faithful;
    b.root = find_root(syntax);
    b.root_id = CSG_EMPTY;
    b.csg = csg_builder_new();
    b.shading = shading_new();
    if (!b.csg || !b.shading) {
        csg_builder_free(b.csg);
        shading_free(b.shading);
        return err_nomem(error, NULL);
    }
    uint32_t root = CSG_EMPTY;
    sc_status st = walk(&b, &root);
    free(b.ids);
    free(b.frames);
    if (st == SC_OK && b.first_2d && !b.solid_leaves)
        st = err_set(error, SC_ERR_SEMANTIC, &b.first_2d->loc,
                     "the model has only 2D objects, which have no 3D output (extrude "
                     "them with linear_extrude)");
    build_resize_cache_free(b.resize_cache);
    if (st != SC_OK) {
        csg_builder_free(b.csg);
        shading_free(b.shading);
        free(b.warnings);
        return st;
    }
    st = csg_builder_finish(b.csg, root, out, error);
    if (st != SC_OK) {
        shading_free(b.shading);
        free(b.warnings);
        return st;
    }
    if (look)
        *look = b.shading;
    else
        shading_free(b.shading);
    *warnings = b.warnings;
    *warning_count = b.warning_count;
    return SC_OK;
}
