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
 *
 * A streamed lowering (model_stream, at the end) makes the same walk one
 * node at a time as the parser reads them: the same visit of each node,
 * the same root search made alongside, in file order, and the subtrees
 * whose lowering reads the children kept whole and walked when they close.
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
#include "model/lower_points.h"
#include "model/lower_twod.h"

/* A resize node lowered in the points context, by its syntax node. */
typedef struct resize_entry {
    const parse_node *syntax;
    model_node *node;
} resize_entry;

/* The kinds of the node names met lately, by the name's address: a parse
 * tree stores each distinct name once (parse.h), so within one tree an
 * address stands for its text, and the table of kinds is not searched
 * again for each of a million nodes. Direct-mapped; an empty slot has no
 * name. */
enum { KIND_CACHE = 8 };

typedef struct kind_cache {
    const char *name[KIND_CACHE];
    size_t index[KIND_CACHE];               /* into kinds, or KIND_UNKNOWN */
    const model_params *params[KIND_CACHE]; /* model_params_of the name */
    model_params_memo memo[KIND_CACHE];     /* of the name's calls */
} kind_cache;

typedef struct lowerer {
    model *m;
    model_reader r; /* its error is the node error being made */
    /* the points context's resize nodes: open addressing on the syntax
     * node's address, cap a power of two */
    resize_entry *resizes;
    size_t resize_count, resize_cap;
    int stopped; /* a main-model node has an argument error: lowering ends */
    kind_cache seen;
} lowerer;

static size_t resize_slot(const resize_entry *table, size_t cap, const parse_node *n)
{
    size_t h = (size_t)(uintptr_t)n;
    h ^= h >> 17;
    h *= (size_t)0x9e3779b97f4a7c15ull;
    size_t i = (h ^ (h >> 29)) & (cap - 1);
    while (table[i].syntax && table[i].syntax != n)
        i = (i + 1) & (cap - 1);
    return i;
}

static sc_status lower_resize(lowerer *l, const parse_node *n, model_node *out);

typedef sc_status (*lower_fn)(lowerer *l, const parse_node *n, model_node *out);

/* ---- leaves ---- */

/* cube(size = 1, center = false): size is a number or [x, y, z]. */
static sc_status lower_cube(lowerer *l, const parse_node *n, model_node *out)
{
    return model_cube(&l->r, n, out->u.cube.size, &out->u.cube.center);
}

/* sphere(r = 1) or sphere(d = 2). */
static sc_status lower_sphere(lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_sphere(&l->r, n, &out->u.sphere.r, &out->u.sphere.res);
}

/* cylinder(h = 1, r1 = 1, r2 = 1, center = false), also with r, d, d1, d2. */
static sc_status lower_cylinder(lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_cylinder(&l->r, n, &out->u.cylinder.h, &out->u.cylinder.r1,
                               &out->u.cylinder.r2, &out->u.cylinder.center,
                               &out->u.cylinder.res);
}

/* polyhedron(points, faces, convexity), faces also as the older
 * `triangles`, read as OpenSCAD 2021.01 reads them (model_read_polyhedron):
 * a face of fewer than 3 points is left out. */
static sc_status lower_polyhedron(lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_polyhedron(&l->r, &l->m->mem, n, 3, out);
}

/* import(file = "x.stl" | "x.off" | "x.amf" | "x.3mf") of a mesh, or of a
 * .dxf or .svg drawing, which is 2D wherever it stands (its argument error
 * kept in the node, as for the other 2D shapes: lower_kept). */
static sc_status lower_import(lowerer *l, const parse_node *n, model_node *out)
{
    if (model_import_is_drawing(n)) {
        sc_error nomem;
        sc_status st = model_import_drawing(&l->m->mem, l->r.file, n, out, &nomem);
        if (st != SC_OK)
            *l->r.error = nomem;
        return st;
    }
    model_import *import = arena_alloc(&l->m->mem, sizeof *import);
    if (!import)
        return err_nomem(l->r.error, NULL);
    out->u.import = import;
    return model_read_import(&l->r, &l->m->mem, n, import);
}

/* surface(file, center, invert). */
static sc_status lower_surface(lowerer *l, const parse_node *n, model_node *out)
{
    model_surface *surface = arena_alloc(&l->m->mem, sizeof *surface);
    if (!surface)
        return err_nomem(l->r.error, NULL);
    out->u.surface = surface;
    return model_read_surface(&l->r, &l->m->mem, n, surface);
}

/* ---- boolean nodes with arguments ---- */

/* multmatrix(m = [[...], [...], [...], [0, 0, 0, 1]]): a row-major 4x4
 * affine matrix; no argument means the identity. One with a nan or inf
 * entry is kept as the zero map, marked not_finite (model.h). */
static sc_status lower_xform(lowerer *l, const parse_node *n, model_node *out)
{
    return model_read_xform(&l->r, &l->m->mem, n, &out->u.xform, &out->not_finite);
}

/* color(c, alpha): c is [r, g, b, a] (missing components are 1, as in
 * OpenSCAD), a colour name or "#hex"; alpha replaces the alpha. Without
 * c, or with a name OpenSCAD does not know, c is its ColorNode's
 * [-1, -1, -1, 1] (build.c's apply_color reads negative components). */
static sc_status lower_color(lowerer *l, const parse_node *n, model_node *out)
{
    float rgba[4] = {1, 1, 1, 1};
    model_color *color = arena_calloc(&l->m->mem, 1, sizeof *color);
    if (!color)
        return err_nomem(l->r.error, NULL);
    out->u.color = color;
    double *c = color->c;
    c[0] = c[1] = c[2] = -1;
    c[3] = 1;
    const parse_value *v = model_arg(n, "c", 0);
    if (v && v->kind == PARSE_VECTOR) {
        for (uint32_t i = 0; i < 4; i++) {
            const parse_value *item =
                i < v->u.vector.count ? &v->u.vector.items[i] : NULL;
            c[i] = !item ? 1 : item->kind == PARSE_NUMBER ? item->u.number : 0;
        }
        color->set = 1;
    } else if (v && v->kind == PARSE_STRING) {
        color->set = colors_lookup(v->u.string.chars, v->u.string.length, rgba);
        for (int i = 0; color->set && i < 4; i++)
            c[i] = rgba[i];
    }
    const parse_value *alpha = model_arg(n, "alpha", 1);
    color->has_alpha = alpha && alpha->kind == PARSE_NUMBER;
    color->alpha = color->has_alpha ? alpha->u.number : 1;
    return SC_OK;
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

/* The extrusions, and a 2D shape in a 3D model: read as in the 2D
 * context (the builders check a shape through the 2D engine, and each
 * extrusion builder reads the arguments it takes), the error kept in the
 * node (pending). */
static sc_status lower_kept(lowerer *l, const parse_node *n, model_node *out)
{
    sc_error nomem;
    sc_status st = model_twod_args(&l->m->mem, l->r.file, n, out, &nomem);
    if (st != SC_OK)
        *l->r.error = nomem;
    return st;
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
    {"hull", MODEL_HULL, NULL},
    {"minkowski", MODEL_MINKOWSKI, NULL},
    {"linear_extrude", MODEL_LINEAR_EXTRUDE, lower_kept},
    {"rotate_extrude", MODEL_ROTATE_EXTRUDE, lower_kept},
    {"import", MODEL_IMPORT, lower_import},
    {"surface", MODEL_SURFACE, lower_surface},
    {"projection", MODEL_PROJECTION, lower_kept},
    {"offset", MODEL_OFFSET, lower_kept},
    {"circle", MODEL_CIRCLE, lower_kept},
    {"square", MODEL_SQUARE, lower_kept},
    {"polygon", MODEL_POLYGON, lower_kept},
    {"text", MODEL_TEXT, lower_kept},
    {"resize", MODEL_RESIZE, lower_resize},
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

/* Whether the root search walks into the children of the node named
 * name: it does, except under leaves and unknown nodes (OpenSCAD looks for
 * '!' among the nodes it instantiated, and it instantiates neither's
 * children). */
static int root_search_enters_kind(size_t i)
{
    return i != KIND_UNKNOWN && !model_is_leaf(kinds[i].kind);
}

static int root_search_enters(const char *name)
{
    return root_search_enters_kind(kind_index(name));
}

/* The cache slot of a name of the tree l lowers, filled. */
static size_t lowerer_slot(lowerer *l, const char *name)
{
    size_t slot = ((uintptr_t)name >> 3) & (KIND_CACHE - 1);
    if (l->seen.name[slot] != name) {
        l->seen.name[slot] = name;
        l->seen.index[slot] = kind_index(name);
        l->seen.params[slot] = model_params_of(name);
        l->seen.memo[slot].p = NULL;
    }
    return slot;
}

/* kind_index of a name of the tree l lowers, through l's cache. */
static size_t lowerer_kind(lowerer *l, const char *name)
{
    return l->seen.index[lowerer_slot(l, name)];
}

/* Whether OpenSCAD instantiates the children of a node of this kind: not
 * those of its primitives (nor of spancast's leaves and shading nodes,
 * which take none, nor of a name it does not know). */
static int instantiates_children(size_t kind)
{
    if (kind == KIND_UNKNOWN)
        return 0;
    switch (kinds[kind].kind) {
    case MODEL_UNION:
    case MODEL_DIFFERENCE:
    case MODEL_INTERSECTION:
    case MODEL_XFORM:
    case MODEL_COLOR:
    case MODEL_MATERIAL:
    case MODEL_RESIZE:
    case MODEL_MOTION:
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE:
    case MODEL_OFFSET:
    case MODEL_PROJECTION:
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        return 1;
    default:
        return 0;
    }
}

/* Adds OpenSCAD's warnings of n's arguments to the model's notes, when n
 * is a builtin module of OpenSCAD's (params.h); *instantiates is then
 * whether n's children are instantiated in turn, *primitive whether n is
 * one of OpenSCAD's primitives (which warn of children). */
static sc_status check_params(lowerer *l, const parse_node *n, int *instantiates,
                              int *primitive, sc_error *error)
{
    size_t slot = lowerer_slot(l, n->name);
    *instantiates = instantiates_children(l->seen.index[slot]);
    const model_params *p = l->seen.params[slot];
    *primitive = p && p->primitive;
    if (l->seen.index[slot] == KIND_UNKNOWN)
        return model_note_unknown(l->r.file, n, &l->m->notes, error);
    return p ? model_check_params(l->r.file, n, p, &l->seen.memo[slot], &l->m->notes,
                                  error)
             : SC_OK;
}

/* Whether n has a child that is not '*' (OpenSCAD never reads those). */
static int has_live_child(const parse_node *n)
{
    for (const parse_node *c = n->first_child; c; c = c->next)
        if (!(c->modifiers & PARSE_MOD_DISABLE))
            return 1;
    return 0;
}

/* The warnings of the arguments of every node OpenSCAD instantiates, in
 * file order: outside '*' subtrees and the children of primitives. */
static sc_status check_tree(lowerer *l, const parse_tree *syntax, sc_error *error)
{
    const parse_node *n = syntax->first;
    while (n) {
        int instantiates = 0, primitive;
        if (!(n->modifiers & PARSE_MOD_DISABLE)) {
            size_t at = l->m->notes.count;
            sc_status st = check_params(l, n, &instantiates, &primitive, error);
            if (st == SC_OK && primitive && has_live_child(n))
                st = model_note_children(l->r.file, n, &l->m->notes, at, error);
            if (st != SC_OK)
                return st;
        }
        n = parse_next_node(n, !instantiates);
    }
    return SC_OK;
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
        if ((n->modifiers & PARSE_MOD_DISABLE) || kind_index(n->name) == KIND_UNKNOWN) {
            n = parse_next_node(n, 1);
            continue;
        }
        if (n->modifiers & PARSE_MOD_ROOT)
            return n;
        n = parse_next_node(n, !root_search_enters(n->name));
    }
    return NULL;
}

/* $fn, where a node sets it to a finite number, must be at most
 * MODEL_MAX_FN (zero or negative means "use $fa and $fs", as in OpenSCAD).
 * An infinite or nan $fn is OpenSCAD 2021.01's 3 fragments
 * (get_fragments_from_r; faithful_fragments). */
static sc_status check_fn(lowerer *l, const parse_node *n)
{
    const parse_value *v = model_arg(n, "$fn", -1);
    if (!v || v->kind != PARSE_NUMBER || !isfinite(v->u.number) ||
        v->u.number <= MODEL_MAX_FN)
        return SC_OK;
    sc_location loc = model_loc(&l->r, v);
    return err_set(l->r.error, SC_ERR_LIMIT, &loc, "$fn %g is too large (limit is %d)",
                   v->u.number, MODEL_MAX_FN);
}

/* Lowers one node into out: its kind and arguments. */
static sc_status lower_node(lowerer *l, const parse_node *n, model_node *out)
{
    size_t i = lowerer_kind(l, n->name);
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

/* Where a node is lowered (model.h): the main model, where the first
 * argument error ends the lowering; a 2D subtree; the points context
 * below hull, minkowski and resize. */
typedef enum context { IN_MAIN, IN_2D, IN_POINTS } context;

/* An open node whose children are being lowered. */
typedef struct open_node {
    const parse_node *syntax;
    model_node *node;
    context ctx; /* of the node's own list */
} open_node;

/* The context of the children of a node of this kind in ctx; IN_MAIN for a
 * main-model leaf means its children are not lowered. */
static context children_context(context ctx, model_kind kind)
{
    if (kind == MODEL_PROJECTION)
        return IN_POINTS; /* 3D children, in every context */
    if (kind == MODEL_LINEAR_EXTRUDE || kind == MODEL_ROTATE_EXTRUDE)
        return IN_2D;
    if (ctx != IN_MAIN)
        return ctx;
    if (model_is_2d(kind))
        return IN_2D;
    if (kind == MODEL_HULL || kind == MODEL_MINKOWSKI)
        return IN_POINTS;
    return IN_MAIN;
}

/* Remembers the resize node n lowered in the points context as node, so
 * that the main model's resize of n is measured from it. */
static sc_status remember_resize(lowerer *l, const parse_node *n, model_node *node,
                                 sc_error *error)
{
    if (2 * (l->resize_count + 1) > l->resize_cap) {
        size_t cap = l->resize_cap ? 2 * l->resize_cap : 64;
        resize_entry *grown = calloc(cap, sizeof *grown);
        if (!grown)
            return err_nomem(error, NULL);
        for (size_t i = 0; i < l->resize_cap; i++) {
            if (!l->resizes[i].syntax)
                continue;
            size_t j = resize_slot(grown, cap, l->resizes[i].syntax);
            grown[j] = l->resizes[i];
        }
        free(l->resizes);
        l->resizes = grown;
        l->resize_cap = cap;
    }
    size_t i = resize_slot(l->resizes, l->resize_cap, n);
    if (!l->resizes[i].syntax)
        l->resize_count++;
    l->resizes[i] = (resize_entry){n, node};
    return SC_OK;
}

static model_node *remembered_resize(const lowerer *l, const parse_node *n)
{
    if (!l->resize_cap)
        return NULL;
    return l->resizes[resize_slot(l->resizes, l->resize_cap, n)].node;
}

/* Lowers n in the 2D or points context: its kind from the table, then
 * its arguments, an error kept in the node. */
static sc_status lower_nested(lowerer *l, const parse_node *n, context ctx,
                              model_node *out, sc_error *error)
{
    out->kind = model_kind_of(n->name);
    sc_status st = ctx == IN_2D ? model_twod_args(&l->m->mem, l->r.file, n, out, error)
                                : model_points_args(&l->m->mem, l->r.file, n, out, error);
    if (st == SC_OK && ctx == IN_POINTS && out->kind == MODEL_RESIZE)
        st = remember_resize(l, n, out, error);
    return st;
}

/* Lowers n (not disabled) in ctx as the next node of its list: a new
 * model node stored at **link, *link then its next. In the main model an
 * argument error makes it a MODEL_ERROR node and sets l->stopped, which
 * ends the lowering; a failure (memory) is returned. */
static sc_status visit(lowerer *l, const parse_node *n, context ctx,
                       const parse_node *root, model_node ***link, model_node **out,
                       sc_error *error)
{
    model_node *node = arena_calloc(&l->m->mem, 1, sizeof *node);
    if (!node)
        return err_nomem(error, NULL);
    node->name = n->name;
    node->loc = n->loc;
    node->modifiers = n->modifiers;
    node->is_root = ctx == IN_MAIN && n == root;
    node->child_count = n->child_count;
    **link = node;
    *link = &node->next;
    *out = node;
    if (ctx != IN_MAIN)
        return lower_nested(l, n, ctx, node, error);
    sc_error node_error; /* filled only on an error */
    l->r.error = &node_error;
    sc_status st = lower_node(l, n, node);
    if (st == SC_ERR_NOMEM) {
        *error = node_error;
        return st;
    }
    if (st != SC_OK) {
        sc_error *copy = arena_alloc(&l->m->mem, sizeof *copy);
        if (!copy)
            return err_nomem(error, NULL);
        *copy = node_error;
        node->kind = MODEL_ERROR;
        node->u.error = copy;
        l->stopped = 1;
    } else if (model_is_leaf(node->kind)) {
        l->m->leaf_count++;
    }
    return SC_OK;
}

/* Whether the walk lowers the children of node, lowered in ctx, in the
 * context *inner. */
static int enters(context ctx, const model_node *node, context *inner)
{
    *inner = children_context(ctx, node->kind);
    return !(*inner == IN_MAIN &&
             (model_is_leaf(node->kind) || node->kind >= MODEL_LIGHT));
}

/* Lowers the nodes from first up to end (their subtrees included) in ctx,
 * linking them from *link; *tail, when given, is then where the next
 * node would be linked. */
static sc_status walk(lowerer *l, const parse_node *first, const parse_node *end,
                      context ctx, const parse_node *root, model_node **link,
                      model_node ***tail, sc_error *error)
{
    open_node *stack = NULL;
    size_t depth = 0, cap = 0;
    const parse_node *n = first;
    sc_status st = SC_OK;
    for (;;) {
        if (depth == 0 ? n == end : !n) {
            if (depth == 0)
                break;
            open_node done = stack[--depth];
            link = &done.node->next;
            n = done.syntax->next;
            ctx = done.ctx;
            continue;
        }
        if ((n->modifiers & PARSE_MOD_DISABLE) ||
            lowerer_kind(l, n->name) == KIND_UNKNOWN) {
            n = n->next; /* OpenSCAD leaves both out, and an unknown node with a note */
            continue;
        }
        model_node *node;
        if ((st = visit(l, n, ctx, root, &link, &node, error)) != SC_OK || l->stopped)
            break;
        context inner;
        /* an extrusion's file form has made its child (lower_twod.c), and
         * OpenSCAD leaves out the written ones */
        if (!n->first_child || node->first_child || !enters(ctx, node, &inner)) {
            n = n->next;
            continue;
        }
        if (!grow_array((void **)&stack, &cap, depth + 1, sizeof *stack)) {
            st = err_nomem(error, NULL);
            break;
        }
        stack[depth++] = (open_node){n, node, ctx};
        link = &node->first_child;
        n = n->first_child;
        ctx = inner;
    }
    free(stack);
    if (tail)
        *tail = link;
    return st;
}

/* resize in the main model: its arguments and subtree lowered in the
 * points context (once: a resize inside another one's subtree has been),
 * for the builder to measure. */
static sc_status lower_resize(lowerer *l, const parse_node *n, model_node *out)
{
    model_node *measured = remembered_resize(l, n);
    model_node *detached = NULL;
    if (!measured) {
        sc_status st = walk(l, n, n->next, IN_POINTS, NULL, &detached, NULL, l->r.error);
        if (st != SC_OK)
            return st;
        measured = detached;
    }
    model_resize *r = arena_calloc(&l->m->mem, 1, sizeof *r);
    if (!r)
        return err_nomem(l->r.error, NULL);
    *r = *measured->u.resize;
    r->measured = measured;
    out->u.resize = r;
    return SC_OK;
}

sc_status model_lower(const parse_tree *syntax, model **out, sc_error *error)
{
    *out = NULL;
    model *m = calloc(1, sizeof *m);
    if (!m)
        return err_nomem(error, NULL);
    arena_init(&m->mem, 64 * 1024);
    m->file = syntax->file;
    lowerer l = {.m = m, .r = {syntax->file, NULL}};
    const parse_node *root = find_root(syntax);
    m->has_root = root != NULL;
    sc_status st = check_tree(&l, syntax, error);
    if (st == SC_OK)
        st = walk(&l, syntax->first, NULL, IN_MAIN, root, &m->first, NULL, error);
    free(l.resizes);
    if (st != SC_OK) {
        model_free(m);
        return st;
    }
    *out = m;
    return SC_OK;
}

sc_status model_lower_twod(const char *file, const parse_node *n, model **out,
                           sc_error *error)
{
    *out = NULL;
    model *m = calloc(1, sizeof *m);
    if (!m)
        return err_nomem(error, NULL);
    arena_init(&m->mem, 4096);
    m->file = file;
    lowerer l = {.m = m, .r = {file, NULL}};
    sc_status st = walk(&l, n, n->next, IN_2D, NULL, &m->first, NULL, error);
    free(l.resizes);
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
    free(m->notes.items);
    free(m);
}

/* ---- the streamed lowering ---- */

/* What the stream knows of an open syntax node, by its depth. */
typedef struct stream_frame {
    model_node *node;     /* its model node; NULL when not lowered */
    uint8_t descend;      /* its children are lowered, in ctx */
    uint8_t ctx;          /* context of its children */
    uint8_t searched;     /* the root search enters its children */
    uint8_t deferred;     /* its subtree is kept and walked when it closes */
    uint8_t instantiates; /* OpenSCAD instantiates its children (check_tree) */
    uint8_t primitive;    /* an instantiated primitive of OpenSCAD's */
    uint8_t live_child;   /* it has a child that is not '*' (so far) */
    size_t notes_from;    /* where its warnings start in the notes */
} stream_frame;

struct model_stream {
    lowerer l;
    uint32_t fork_depth;    /* a second part's (model_stream_sink's fork): the
                               depth of its list's node, 0 at the top level */
    model_node **link;      /* where the next lowered node goes */
    const parse_node *root; /* the root ('!') while its syntax lives */
    int has_root;           /* the root search found it */
    uint32_t kept_depth;    /* depth of the deferred node; 0 if none */
    stream_frame *frames;   /* by depth - 1 */
    size_t frame_cap;
};

/* Whether a node of this kind, in the main model, reads its subtree
 * while it is lowered: resize measures it (lower_resize); light, camera
 * and background check that they have no children (lower_shading.c). */
static int reads_subtree(size_t kind)
{
    if (kind == KIND_UNKNOWN)
        return 0;
    model_kind k = kinds[kind].kind;
    return k == MODEL_RESIZE || k == MODEL_LIGHT || k == MODEL_CAMERA ||
           k == MODEL_BACKGROUND;
}

static sc_status stream_open(void *user, parse_node *n, int *keep, sc_error *error)
{
    model_stream *s = user;
    uint32_t depth = n->depth;
    if (!grow_array((void **)&s->frames, &s->frame_cap, depth, sizeof *s->frames))
        return err_nomem(error, NULL);
    const stream_frame *parent = depth > 1 ? &s->frames[depth - 2] : NULL;
    stream_frame *f = &s->frames[depth - 1];
    memset(f, 0, sizeof *f);
    int disabled = (n->modifiers & PARSE_MOD_DISABLE) != 0;
    size_t kind = lowerer_kind(&s->l, n->name);
    /* The root search of find_root, in the same order. */
    int searched = (!parent || parent->searched) && !disabled && kind != KIND_UNKNOWN;
    if (searched && !s->has_root && (n->modifiers & PARSE_MOD_ROOT)) {
        s->has_root = 1;
        s->root = n;
    }
    f->searched = searched && root_search_enters_kind(kind);
    /* The argument warnings of check_tree, in the same order. */
    if (parent && parent->primitive && !disabled)
        s->frames[depth - 2].live_child = 1;
    if ((!parent || parent->instantiates) && !disabled) {
        int instantiates, primitive;
        f->notes_from = s->l.m->notes.count;
        sc_status st = check_params(&s->l, n, &instantiates, &primitive, error);
        if (st != SC_OK)
            return st;
        f->instantiates = (uint8_t)instantiates;
        f->primitive = (uint8_t)primitive;
    }
    if (s->kept_depth)
        return SC_OK; /* inside a kept subtree: walked when it closes */
    int visited = !s->l.stopped && (!parent || parent->descend) && !disabled &&
                  kind != KIND_UNKNOWN;
    if (!visited)
        return SC_OK;
    context ctx = parent ? (context)parent->ctx : IN_MAIN;
    if (ctx == IN_MAIN && reads_subtree(kind)) {
        *keep = 1;
        s->kept_depth = depth;
        f->deferred = 1;
        f->ctx = (uint8_t)ctx;
        return SC_OK;
    }
    model_node *node;
    sc_status st = visit(&s->l, n, ctx, s->root, &s->link, &node, error);
    if (st != SC_OK)
        return st;
    f->node = node; /* its child count comes at its close */
    if (s->l.stopped)
        return SC_OK;
    context inner;
    f->descend = (uint8_t)enters(ctx, node, &inner);
    f->ctx = (uint8_t)inner;
    if (f->descend)
        s->link = &node->first_child;
    return SC_OK;
}

static sc_status stream_close(void *user, parse_node *n, sc_error *error)
{
    model_stream *s = user;
    uint32_t depth = n->depth;
    const stream_frame *f = &s->frames[depth - 1];
    sc_status st = SC_OK;
    /* its children are known now: the warning goes before its others */
    if (f->live_child && (st = model_note_children(s->l.r.file, n, &s->l.m->notes,
                                                   f->notes_from, error)) != SC_OK)
        return st;
    if (s->kept_depth && depth > s->kept_depth)
        return SC_OK;
    if (f->deferred) {
        /* n is not linked to a sibling: the walk ends after its subtree. */
        s->kept_depth = 0;
        st = walk(&s->l, n, NULL, (context)f->ctx, s->root, s->link, &s->link, error);
    } else if (f->node) {
        f->node->child_count = n->child_count;
        if (f->descend)
            s->link = &f->node->next;
    }
    /* n's syntax is freed now: forget pointers into it. The root, if it
     * was there, is lowered; a resize remembered in the points context is
     * looked up only within the walk of a kept subtree. */
    s->root = NULL;
    if (s->l.resize_count) {
        memset(s->l.resizes, 0, s->l.resize_cap * sizeof *s->l.resizes);
        s->l.resize_count = 0;
    }
    return st;
}

sc_status model_stream_new(const char *file, model_stream **out, sc_error *error)
{
    *out = NULL;
    model_stream *s = calloc(1, sizeof *s);
    model *m = s ? calloc(1, sizeof *m) : NULL;
    if (!m) {
        free(s);
        return err_nomem(error, NULL);
    }
    arena_init(&m->mem, 64 * 1024);
    m->file = file;
    s->l = (lowerer){.m = m, .r = {file, NULL}};
    s->link = &m->first;
    *out = s;
    return SC_OK;
}

/* A split parse's second part (parse_sink's fork): a stream of its own,
 * lowering into a model of its own, that starts with the open frames of
 * the first part's (copies: what it sets in them, live_child, is joined).
 * None while a subtree is kept whole or the lowering has stopped. */
static void *stream_fork(void *user, uint32_t depth)
{
    model_stream *s = user, *t;
    if (s->kept_depth || s->l.stopped || model_stream_new(s->l.r.file, &t, NULL) != SC_OK)
        return NULL;
    if (depth &&
        !grow_array((void **)&t->frames, &t->frame_cap, depth, sizeof *t->frames)) {
        model_stream_free(t);
        return NULL;
    }
    if (depth)
        memcpy(t->frames, s->frames, depth * sizeof *t->frames);
    t->fork_depth = depth;
    return t;
}

/* Appends the second part t to s, as one stream would have lowered both:
 * its nodes after s's last, its warnings after s's, its memory s's.
 * Parts that one stream would have lowered otherwise are not joined: a
 * root ('!') in t (s's search may have found one first), a lowering
 * stopped by an argument error in either (s's would not lower t's nodes,
 * and t's warnings would come after its error). */
static int stream_join(void *user, void *forked)
{
    model_stream *s = user, *t = forked;
    model *m = s->l.m, *part = t->l.m;
    if (s->kept_depth || s->l.stopped || t->l.stopped || t->has_root || t->kept_depth)
        return 0;
    if (part->notes.count) {
        if (!grow_array((void **)&m->notes.items, &m->notes.cap,
                        m->notes.count + part->notes.count, sizeof *m->notes.items))
            return 0;
        memcpy(m->notes.items + m->notes.count, part->notes.items,
               part->notes.count * sizeof *m->notes.items);
        m->notes.count += part->notes.count;
    }
    if (part->first) {
        *s->link = part->first;
        s->link = t->link;
    }
    m->leaf_count += part->leaf_count;
    if (t->fork_depth)
        s->frames[t->fork_depth - 1].live_child |=
            t->frames[t->fork_depth - 1].live_child;
    arena_adopt(&m->mem, &part->mem);
    model_stream_free(t);
    return 1;
}

static void stream_drop(void *forked)
{
    model_stream_free(forked);
}

parse_sink model_stream_sink(model_stream *s)
{
    parse_sink sink = {.user = s,
                       .open = stream_open,
                       .close = stream_close,
                       .fork = stream_fork,
                       .join = stream_join,
                       .drop = stream_drop};
    return sink;
}

sc_status model_stream_finish(model_stream *s, model **out)
{
    *out = s->l.m;
    (*out)->has_root = s->has_root;
    s->l.m = NULL;
    model_stream_free(s);
    return SC_OK;
}

void model_stream_free(model_stream *s)
{
    if (!s)
        return;
    model_free(s->l.m);
    free(s->l.resizes);
    free(s->frames);
    free(s);
}
