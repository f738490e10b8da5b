/* The lowering pass: syntax tree in, typed model out (model.h).
 *
 * One table gives every node name its kind and its lowering function,
 * which reads the node's arguments into the model node and checks them.
 * The walk is the builder's: file order with an explicit stack (nodes nest
 * PARSE_MAX_DEPTH deep), into the children of the kinds the builder walks
 * into, past '*' subtrees and leaves' children. Before a node's own
 * arguments, its $fn is checked (at most MODEL_MAX_FN), as for every node
 * the builder visits.
 *
 * The root ('!') is found first, as the builder needs it before its walk:
 * the first '!' node in file order outside '*' subtrees and leaves'
 * children (a '!' under a light counts, though nothing under a light is
 * built). A scan of the modifiers alone skips this when no node has a '!'.
 */
#include "model/model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "model/args.h"
#include "model/colors.h"
#include "model/lower_curved.h"
#include "model/lower_shading.h"
#include "model/lower_motion.h"

typedef struct lowerer {
    model *m;
    model_reader r; /* its error is the node error being made */
} lowerer;

typedef sc_status (*lower_fn)(lowerer *l, const parse_node *n, model_node *out);

/* ---- arguments ---- */

static sc_status get_number(lowerer *l, const parse_node *n, const char *name,
                            int position, double *out, int *given)
{
    const parse_value *v = model_arg(n, name, position);
    *given = 0;
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_NUMBER)
        return model_wrong_type(&l->r, n, name, v, "a number");
    *out = v->u.number;
    *given = 1;
    return SC_OK;
}

/* OpenSCAD's radius lookup: a diameter wins over a radius. */
static sc_status get_radius(lowerer *l, const parse_node *n, const char *diameter,
                            const char *radius, int radius_position, double *out,
                            int *given)
{
    double d = 0;
    int has_d;
    sc_status st = get_number(l, n, diameter, -1, &d, &has_d);
    if (st == SC_OK)
        st = get_number(l, n, radius, radius_position, out, given);
    if (st == SC_OK && has_d) {
        *out = d / 2;
        *given = 1;
    }
    return st;
}

static model_resolution resolution(const parse_node *n)
{
    model_resolution res;
    parse_node_resolution(n, &res.fn, &res.fa, &res.fs);
    return res;
}

/* ---- leaves ---- */

/* cube(size = 1, center = false): size is a number or [x, y, z]. */
static sc_status lower_cube(lowerer *l, const parse_node *n, model_node *out)
{
    return model_cube(&l->r, n, out->u.cube.size, &out->u.cube.center);
}

/* sphere(r = 1) or sphere(d = 2). */
static sc_status lower_sphere(lowerer *l, const parse_node *n, model_node *out)
{
    int given;
    out->u.sphere.r = 1;
    out->u.sphere.res = resolution(n);
    return get_radius(l, n, "d", "r", 0, &out->u.sphere.r, &given);
}

/* cylinder(h = 1, r1 = 1, r2 = 1, center = false), also with r, d, d1, d2:
 * r1/d1 and r2/d2 win over r/d, a diameter over a radius. */
static sc_status lower_cylinder(lowerer *l, const parse_node *n, model_node *out)
{
    double h = 1, r = 1, r1 = 1, r2 = 1;
    int has_h, has_r, has_r1, has_r2, center = 0;
    sc_status st = get_number(l, n, "h", 0, &h, &has_h);
    if (st == SC_OK)
        st = get_radius(l, n, "d1", "r1", 1, &r1, &has_r1);
    if (st == SC_OK)
        st = get_radius(l, n, "d2", "r2", 2, &r2, &has_r2);
    if (st == SC_OK)
        st = get_radius(l, n, "d", "r", -1, &r, &has_r);
    if (st == SC_OK)
        st = model_bool(&l->r, n, "center", 3, &center);
    out->u.cylinder.h = h;
    out->u.cylinder.r1 = has_r1 ? r1 : r;
    out->u.cylinder.r2 = has_r2 ? r2 : r;
    out->u.cylinder.center = center;
    out->u.cylinder.res = resolution(n);
    return st;
}

static const char points_expected[] = "a vector of [x, y, z] points";
static const char faces_expected[] = "a vector of faces, each a vector of point indices";

static sc_status read_points(lowerer *l, const parse_node *n, const parse_value *v,
                             model_node *out)
{
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return model_wrong_type(&l->r, n, "points", v, points_expected);
    uint32_t count = v->u.vector.count;
    vec3 *points = NULL;
    if (count && !(points = arena_alloc(&l->m->mem, (size_t)count * sizeof *points)))
        return err_nomem(l->r.error, NULL);
    for (uint32_t i = 0; i < count; i++) {
        const parse_value *pv = &v->u.vector.items[i];
        if (pv->kind != PARSE_VECTOR || pv->u.vector.count != 3)
            return model_wrong_type(&l->r, n, "points", pv, points_expected);
        double c[3];
        for (int k = 0; k < 3; k++) {
            const parse_value *cv = &pv->u.vector.items[k];
            if (cv->kind != PARSE_NUMBER)
                return model_wrong_type(&l->r, n, "points", cv, points_expected);
            c[k] = cv->u.number;
        }
        points[i] = v3(c[0], c[1], c[2]);
        if (!v3_is_finite(points[i])) {
            sc_location loc = model_loc(&l->r, pv);
            return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                           "polyhedron point %u is not finite", i);
        }
    }
    out->u.polyhedron.points = points;
    out->u.polyhedron.point_count = count;
    return SC_OK;
}

/* One face's point indices into indices: whole numbers below count. */
static sc_status read_face(lowerer *l, const parse_node *n, const char *param,
                           const parse_value *fv, uint32_t f, uint32_t count,
                           uint32_t *indices)
{
    if (fv->u.vector.count < 3) {
        sc_location loc = model_loc(&l->r, fv);
        return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                       "polyhedron face %u has fewer than 3 points", f);
    }
    for (uint32_t i = 0; i < fv->u.vector.count; i++) {
        const parse_value *iv = &fv->u.vector.items[i];
        if (iv->kind != PARSE_NUMBER)
            return model_wrong_type(&l->r, n, param, iv, faces_expected);
        double x = iv->u.number;
        sc_location loc = model_loc(&l->r, iv);
        if (!(x == floor(x)))
            return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                           "polyhedron face %u: point index %g is not a whole number", f,
                           x);
        if (x < 0 || x >= (double)count)
            return err_set(
                l->r.error, SC_ERR_SEMANTIC, &loc,
                "polyhedron face %u: point index %g is out of range (%u points)", f, x,
                count);
        indices[i] = (uint32_t)x;
    }
    return SC_OK;
}

static sc_status read_faces(lowerer *l, const parse_node *n, const char *param,
                            const parse_value *v, model_node *out)
{
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return model_wrong_type(&l->r, n, param, v, faces_expected);
    uint32_t count = v->u.vector.count;
    size_t total = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        if (fv->kind != PARSE_VECTOR)
            return model_wrong_type(&l->r, n, param, fv, faces_expected);
        total += fv->u.vector.count;
    }
    if (total > UINT32_MAX)
        return err_nomem(l->r.error, NULL);
    uint32_t *start = arena_calloc(&l->m->mem, (size_t)count + 1, sizeof *start);
    uint32_t *indices = total ? arena_calloc(&l->m->mem, total, sizeof *indices) : NULL;
    if (!start || (total && !indices))
        return err_nomem(l->r.error, NULL);
    uint32_t k = 0;
    for (uint32_t f = 0; f < count; f++) {
        const parse_value *fv = &v->u.vector.items[f];
        start[f] = k;
        sc_status st =
            read_face(l, n, param, fv, f, out->u.polyhedron.point_count, indices + k);
        if (st != SC_OK)
            return st;
        k += fv->u.vector.count;
    }
    start[count] = k;
    out->u.polyhedron.indices = indices;
    out->u.polyhedron.face_start = start;
    out->u.polyhedron.face_count = count;
    return SC_OK;
}

/* polyhedron(points, faces, convexity), faces also as the older
 * `triangles`. */
static sc_status lower_polyhedron(lowerer *l, const parse_node *n, model_node *out)
{
    const char *faces_name = "faces";
    const parse_value *faces = model_arg(n, "faces", 1);
    if (!faces && (faces = model_arg(n, "triangles", -1)))
        faces_name = "triangles";
    sc_status st = read_points(l, n, model_arg(n, "points", 0), out);
    return st != SC_OK ? st : read_faces(l, n, faces_name, faces, out);
}

/* import(file = "x.stl" | "x.off") in a 3D model. */
static sc_status lower_import(lowerer *l, const parse_node *n, model_node *out)
{
    model_import *import = arena_alloc(&l->m->mem, sizeof *import);
    if (!import)
        return err_nomem(l->r.error, NULL);
    out->u.import = import;
    return model_read_import(&l->r, n, import);
}

/* surface(file, center, invert). */
static sc_status lower_surface(lowerer *l, const parse_node *n, model_node *out)
{
    model_surface *surface = arena_alloc(&l->m->mem, sizeof *surface);
    if (!surface)
        return err_nomem(l->r.error, NULL);
    out->u.surface = surface;
    return model_read_surface(&l->r, n, surface);
}

/* ---- boolean nodes with arguments ---- */

/* multmatrix(m = [[...], [...], [...], [0, 0, 0, 1]]): a row-major 4x4
 * affine matrix of finite numbers; no argument means the identity. */
static sc_status lower_xform(lowerer *l, const parse_node *n, model_node *out)
{
    double m[4][4];
    sc_status st = model_matrix(&l->r, n, m);
    if (st != SC_OK)
        return st;
    affine *a = arena_alloc(&l->m->mem, sizeof *a);
    if (!a)
        return err_nomem(l->r.error, NULL);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            a->m[r][k] = m[r][k];
    out->u.xform = a;
    return SC_OK;
}

/* color(c, alpha): c is [r, g, b, a] (missing components are 1, as in
 * OpenSCAD), a colour name or "#hex"; alpha replaces the alpha. A negative
 * red is OpenSCAD's "no colour" (it writes color([-1, -1, -1, 1]) for a name
 * it did not know): the children keep the colour they inherit. */
static sc_status lower_color(lowerer *l, const parse_node *n, model_node *out)
{
    static const char expected[] = "a vector of numbers or a colour name";
    float rgba[4] = {1, 1, 1, 1};
    model_color *color = arena_calloc(&l->m->mem, 1, sizeof *color);
    if (!color)
        return err_nomem(l->r.error, NULL);
    out->u.color = color;
    double *c = color->c;
    c[0] = c[1] = c[2] = c[3] = 1;
    const parse_value *v = model_arg(n, "c", 0);
    if (v && v->kind == PARSE_VECTOR) {
        for (uint32_t i = 0; i < v->u.vector.count; i++) {
            const parse_value *item = &v->u.vector.items[i];
            if (item->kind != PARSE_NUMBER)
                return model_wrong_type(&l->r, n, "c", item, expected);
            if (i < 4) {
                c[i] = item->u.number;
                color->c_loc[i] = model_loc(&l->r, item);
            }
        }
        color->set = !(c[0] < 0);
    } else if (v && v->kind == PARSE_STRING) {
        color->set = colors_lookup(v->u.string.chars, v->u.string.length, rgba);
        for (int i = 0; i < 4; i++)
            c[i] = rgba[i];
        if (!color->set) {
            color->unknown = v->u.string.chars;
            color->unknown_loc = model_loc(&l->r, v);
        }
    } else if (v) {
        return model_wrong_type(&l->r, n, "c", v, expected);
    }
    sc_status st = get_number(l, n, "alpha", 1, &color->alpha, &color->has_alpha);
    if (st == SC_OK && color->has_alpha)
        color->alpha_loc = model_loc(&l->r, model_arg(n, "alpha", 1));
    return st;
}

/* ---- spancast's curved leaves (lower_curved.c) ---- */

static sc_status lower_torus(lowerer *l, const parse_node *n, model_node *out)
{
    model_torus *t = arena_calloc(&l->m->mem, 1, sizeof *t);
    if (!t)
        return err_nomem(l->r.error, NULL);
    out->u.torus = t;
    return model_read_torus(&l->r, n, t);
}

static sc_status lower_quadric(lowerer *l, const parse_node *n, model_node *out)
{
    model_quadric *q = arena_calloc(&l->m->mem, 1, sizeof *q);
    if (!q)
        return err_nomem(l->r.error, NULL);
    out->u.quadric = q;
    return model_read_quadric(&l->r, n, q);
}

static sc_status lower_implicit(lowerer *l, const parse_node *n, model_node *out)
{
    model_implicit *f = arena_calloc(&l->m->mem, 1, sizeof *f);
    if (!f)
        return err_nomem(l->r.error, NULL);
    out->u.implicit = f;
    return model_read_implicit(&l->r, n, f);
}

/* ---- shading nodes (lower_shading.c) ---- */

static sc_status lower_motion(lowerer *l, const parse_node *n, model_node *out)
{
    model_motion *motion = arena_alloc(&l->m->mem, sizeof *motion);
    if (!motion)
        return err_nomem(l->r.error, NULL);
    out->u.motion = motion;
    return model_read_motion(&l->r, n, motion);
}

static sc_status lower_light(lowerer *l, const parse_node *n, model_node *out)
{
    shading_light *light = arena_alloc(&l->m->mem, sizeof *light);
    if (!light)
        return err_nomem(l->r.error, NULL);
    out->u.light = light;
    return model_read_light(&l->r, n, light);
}

static sc_status lower_camera(lowerer *l, const parse_node *n, model_node *out)
{
    shading_camera *camera = arena_alloc(&l->m->mem, sizeof *camera);
    if (!camera)
        return err_nomem(l->r.error, NULL);
    out->u.camera = camera;
    return model_read_camera(&l->r, n, camera);
}

static sc_status lower_background(lowerer *l, const parse_node *n, model_node *out)
{
    float *c = arena_alloc(&l->m->mem, 3 * sizeof *c);
    if (!c)
        return err_nomem(l->r.error, NULL);
    out->u.background = c;
    return model_read_background(&l->r, n, c);
}

static sc_status lower_material(lowerer *l, const parse_node *n, model_node *out)
{
    model_material *m = arena_calloc(&l->m->mem, 1, sizeof *m);
    if (!m)
        return err_nomem(l->r.error, NULL);
    out->u.material = m;
    return model_read_material(&l->r, n, m);
}

/* The kinds whose builders still read their own syntax node. */
static sc_status keep_syntax(lowerer *l, const parse_node *n, model_node *out)
{
    (void)l;
    out->syntax = n;
    return SC_OK;
}

static sc_status unsupported(lowerer *l, const parse_node *n, model_node *out)
{
    (void)out;
    return err_set(l->r.error, SC_ERR_UNSUPPORTED, &n->loc, "'%s' is not supported yet",
                   n->name);
}

/* ---- the table of node kinds ---- */

static const struct {
    const char *name;
    model_kind kind;
    lower_fn lower; /* NULL: no arguments read */
} kinds[] = {
    {"group", MODEL_UNION, NULL},
    {"union", MODEL_UNION, NULL},
    {"render", MODEL_UNION, NULL},
    {"difference", MODEL_DIFFERENCE, NULL},
    {"intersection", MODEL_INTERSECTION, NULL},
    {"multmatrix", MODEL_XFORM, lower_xform},
    {"color", MODEL_COLOR, lower_color},
    {"cube", MODEL_CUBE, lower_cube},
    {"sphere", MODEL_SPHERE, lower_sphere},
    {"cylinder", MODEL_CYLINDER, lower_cylinder},
    {"polyhedron", MODEL_POLYHEDRON, lower_polyhedron},
    /* What else OpenSCAD writes. */
    {"hull", MODEL_HULL, keep_syntax},
    {"minkowski", MODEL_MINKOWSKI, keep_syntax},
    {"linear_extrude", MODEL_LINEAR_EXTRUDE, keep_syntax},
    {"rotate_extrude", MODEL_ROTATE_EXTRUDE, keep_syntax},
    {"import", MODEL_IMPORT, lower_import},
    {"surface", MODEL_SURFACE, lower_surface},
    {"projection", MODEL_UNSUPPORTED, unsupported},
    {"offset", MODEL_OFFSET, keep_syntax},
    {"circle", MODEL_CIRCLE, keep_syntax},
    {"square", MODEL_SQUARE, keep_syntax},
    {"polygon", MODEL_POLYGON, keep_syntax},
    {"text", MODEL_TEXT, keep_syntax},
    {"resize", MODEL_RESIZE, keep_syntax},
    {"roof", MODEL_UNSUPPORTED, unsupported},
    {"intersection_for", MODEL_UNSUPPORTED, unsupported},
    /* spancast's own extensions. */
    {"torus", MODEL_TORUS, lower_torus},
    {"quadric", MODEL_QUADRIC, lower_quadric},
    {"halfspace", MODEL_HALFSPACE, unsupported},
    {"implicit", MODEL_IMPLICIT, lower_implicit},
    {"material", MODEL_MATERIAL, lower_material},
    {"light", MODEL_LIGHT, lower_light},
    {"motion", MODEL_MOTION, lower_motion},
    {"camera", MODEL_CAMERA, lower_camera},
    {"background", MODEL_BACKGROUND, lower_background},
};

#define KIND_COUNT (sizeof kinds / sizeof kinds[0])
#define KIND_UNKNOWN KIND_COUNT

/* The table entry of name, KIND_UNKNOWN when it has none. */
static size_t kind_index(const char *name)
{
    for (size_t i = 0; i < KIND_COUNT; i++) {
        if (kinds[i].name[0] == name[0] && strcmp(kinds[i].name, name) == 0)
            return i;
    }
    return KIND_UNKNOWN;
}

model_kind model_kind_of(const char *name)
{
    size_t i = kind_index(name);
    return i == KIND_UNKNOWN ? MODEL_UNKNOWN : kinds[i].kind;
}

/* Whether the builder walks into the children of the node named name: the
 * root search does, except under leaves (under an unknown node too: the
 * error there comes later, in file order). */
static int root_search_enters(const char *name)
{
    size_t i = kind_index(name);
    return i == KIND_UNKNOWN || !model_is_leaf(kinds[i].kind);
}

static const parse_node *find_root(const parse_tree *syntax)
{
    const parse_node *n = syntax->first;
    int any = 0;
    for (; n && !any; n = parse_next_node(n, 0))
        any = (n->modifiers & PARSE_MOD_ROOT) != 0;
    if (!any)
        return NULL;
    n = syntax->first;
    while (n) {
        if (n->modifiers & PARSE_MOD_DISABLE) {
            n = parse_next_node(n, 1);
            continue;
        }
        if (n->modifiers & PARSE_MOD_ROOT)
            return n;
        n = parse_next_node(n, !root_search_enters(n->name));
    }
    return NULL;
}

/* $fn, where a node sets it to a number, must be finite and at most
 * MODEL_MAX_FN (zero or negative means "use $fa and $fs", as in OpenSCAD). */
static sc_status check_fn(lowerer *l, const parse_node *n)
{
    const parse_value *v = model_arg(n, "$fn", -1);
    if (!v || v->kind != PARSE_NUMBER || v->u.number <= MODEL_MAX_FN)
        return SC_OK;
    sc_location loc = model_loc(&l->r, v);
    if (isnan(v->u.number))
        return err_set(l->r.error, SC_ERR_SEMANTIC, &loc,
                       "$fn must be a number (got nan)");
    return err_set(l->r.error, SC_ERR_LIMIT, &loc, "$fn %g is too large (limit is %d)",
                   v->u.number, MODEL_MAX_FN);
}

/* Lowers one node into out: its kind and arguments. */
static sc_status lower_node(lowerer *l, const parse_node *n, model_node *out)
{
    size_t i = kind_index(n->name);
    if (i == KIND_UNKNOWN)
        return err_set(l->r.error, SC_ERR_SEMANTIC, &n->loc, "unknown node '%s'",
                       n->name);
    out->kind = kinds[i].kind;
    if (kinds[i].lower == unsupported)
        return unsupported(l, n, out);
    sc_status st = check_fn(l, n);
    if (st == SC_OK && kinds[i].lower)
        st = kinds[i].lower(l, n, out);
    return st;
}

/* An open node whose children are being lowered. */
typedef struct open_node {
    const parse_node *syntax;
    model_node *node;
} open_node;

static sc_status walk(lowerer *l, const parse_tree *syntax, sc_error *error)
{
    const parse_node *root = find_root(syntax);
    l->m->has_root = root != NULL;
    open_node *stack = NULL;
    size_t depth = 0, cap = 0;
    model_node **link = &l->m->first; /* where the next node goes */
    const parse_node *n = syntax->first;
    sc_status st = SC_OK;
    for (;;) {
        if (!n) {
            if (depth == 0)
                break;
            open_node done = stack[--depth];
            link = &done.node->next;
            n = done.syntax->next;
            continue;
        }
        if (n->modifiers & PARSE_MOD_DISABLE) {
            n = n->next;
            continue;
        }
        model_node *node = arena_calloc(&l->m->mem, 1, sizeof *node);
        if (!node) {
            st = err_nomem(error, NULL);
            break;
        }
        node->name = n->name;
        node->loc = n->loc;
        node->modifiers = n->modifiers;
        node->is_root = n == root;
        node->child_count = n->child_count;
        *link = node;
        link = &node->next;
        sc_error node_error; /* filled only on an error */
        l->r.error = &node_error;
        st = lower_node(l, n, node);
        if (st == SC_ERR_NOMEM) {
            *error = node_error;
            break;
        }
        if (st != SC_OK) {
            sc_error *copy = arena_alloc(&l->m->mem, sizeof *copy);
            if (!copy) {
                st = err_nomem(error, NULL);
                break;
            }
            *copy = node_error;
            node->kind = MODEL_ERROR;
            node->u.error = copy;
            st = SC_OK;
            break;
        }
        if (model_is_leaf(node->kind) || node->kind >= MODEL_LIGHT || !n->first_child) {
            n = n->next;
            continue;
        }
        if (!grow_array((void **)&stack, &cap, depth + 1, sizeof *stack)) {
            st = err_nomem(error, NULL);
            break;
        }
        stack[depth++] = (open_node){n, node};
        link = &node->first_child;
        n = n->first_child;
    }
    free(stack);
    return st;
}

sc_status model_lower(const parse_tree *syntax, model **out, sc_error *error)
{
    *out = NULL;
    model *m = calloc(1, sizeof *m);
    if (!m)
        return err_nomem(error, NULL);
    arena_init(&m->mem, 64 * 1024);
    m->file = syntax->file;
    lowerer l = {m, {syntax->file, NULL}};
    sc_status st = walk(&l, syntax, error);
    if (st != SC_OK) {
        model_free(m);
        return st;
    }
    *out = m;
    return SC_OK;
}

void model_free(model *m)
{
    if (!m)
        return;
    arena_free(&m->mem);
    free(m);
}
