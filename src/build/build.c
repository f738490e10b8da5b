/* The scene builder: see build.h for what each node means.
 *
 * The typed model is walked in file order with an explicit stack of frames,
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
 *            no geometry, which empties an enclosing intersection);
 *   warns    the nodes under it give their warnings: where they are built,
 *            and also under '%', under a singular transform and under a
 *            transform removed for a nan or inf entry, whose subtrees
 *            OpenSCAD 2021.01's render evaluates (with their warnings)
 *            before it leaves them out; off outside the '!' subtree. A
 *            '%' child is no operand of its parent there, so its parent
 *            does not warn that it mixes 2D and 3D or ignores it; a
 *            removed transform warns of neither for its own children,
 *            and says that it is removed after their warnings.
 * Nodes that are not built are still checked, so an error is an error
 * wherever it is written; only '*' subtrees are skipped unread. What
 * warns without being built is only checked, as any node that is not
 * built: its leaves are not added, and a leaf whose warnings would need
 * its geometry (a curved leaf, a surface, a hull or minkowski's CGAL
 * result) says nothing.
 *
 * The preview's modifier parts: the walk notes every '#' and '%' node it
 * meets inside the design (not outside the '!' subtree), with the state its
 * parent hands it. Once the solid is built, each noted subtree is walked
 * again on its own (walk_part), from that state, into one of two more
 * trees, the highlighted parts and the background parts, which the
 * shading record carries (shading.overlay). The part's own '%' does not
 * keep it out there, while a '%' below it does, as in OpenSCAD, whose
 * preview draws a '#' subtree without its '%' children. These walks read
 * the model again with a shading record and warnings of their own, so the
 * solid's lights, materials and warnings are the same with modifiers or
 * without; what they could not build is a warning at the node.
 *
 * Polyhedra: OpenSCAD lists each face's points clockwise seen from outside.
 * Rather than trust the winding, each face plane is oriented by the points:
 * a convex polyhedron lies entirely on one side of each of its face planes,
 * and that side is inside. The polyhedron must be closed (every edge shared
 * by exactly two faces); it takes the plane path when convex: no point may
 * lie on the outer side of a face plane by more than 1e-5 of the largest
 * coordinate, which absorbs the 6 significant digits OpenSCAD writes
 * numbers with, or of the solid's size where that is smaller (a small
 * dented solid far out is not convex). (The centroid of the points would
 * orient the planes too, but it can sit on a face of a non-convex mesh;
 * the extremes of the points cannot mislead.) Other polyhedra become
 * triangle meshes (build_mesh.c).
 */
#include "build/build.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "build/build_ctx.h"
#include "build/build_extrude_faithful.h"
#include "build/build_hull.h"
#include "build/build_nef_cache.h"
#include "build/build_mesh.h"
#include "build/build_motion.h"
#include "build/build_revolve.h"
#include "build/build_shading.h"
#include "build/build_twod.h"
#include "csg/bounds.h"
#include "implicit/solve.h"
#include "model/faithful.h"

typedef struct frame {
    const model_node *node; /* NULL for the file itself */
    csg_op op;
    int emit;        /* leaves below are built */
    int warns;       /* the nodes below give their warnings (see above) */
    int counted;     /* the result is an operand of the parent */
    size_t first_id; /* children's results start here on the id stack */
    float color[4];
    int color_set;     /* a color() or material(color) above has set it: OpenSCAD
                          2021.01's preview keeps the outermost colour */
    uint32_t material; /* index into the shading record's materials */
    affine to_world;
    int moving;            /* inside a motion node: leaves carry motion */
    csg_motion motion;     /* its motion (build_motion.h) */
    int shown;             /* inside the design: not outside the '!' subtree */
    size_t first_ignored;  /* its ignored 2D children start here on that stack */
    int highlighted;       /* a '#' node or inside one */
    int negative;          /* subtracted in OpenSCAD's normal form: below an odd
                              number of differences' later operands */
    int in_render;         /* the preview's walk, inside a render() */
    int render_negative;   /* then the render()'s own negative */
    uint32_t render_first; /* then the object id of its first leaf */
    /* a '#' or '%' term of a child is lost: it reaches a render() without
     * meeting another operand (OpenSCAD's RenderNode collects none) */
    int children_lost;
    /* its result reaches a CGAL operation in OpenSCAD's render: an
     * operation of two or more operands, or a render() (to_cgal) */
    int cgal;
    /* OpenSCAD 2021.01 moves a mesh's points (PolySet::transform) until a
     * CGAL operation, or the render's end, takes the mesh and tessellates
     * and checks it there: the transforms since the innermost such
     * operation (or the root), and to_world at it (to_world is
     * cgal_world * since_cgal) */
    affine since_cgal;
    affine cgal_world;
    /* faithful mode: a CGAL operation above takes no mesh that passes
     * through itself (build_cgal_crossing), so none below needs looking at */
    int crossing_clean;
} frame;

/* A '#' or '%' node and the state its parent hands it. */
typedef struct part_mark {
    const model_node *node;
    int kind; /* SHADING_OVERLAY_* */
    frame parent;
} part_mark;

/* A 2D child a 3D operation ignores (build_twod_ignored). */
typedef struct ignored_child {
    const model_node *node;
    int empty; /* no outline: OpenSCAD does not say that it mixes 2D and 3D */
} ignored_child;

typedef struct builder {
    const model *model;
    const char *file; /* for positions */
    csg_builder *csg;
    sc_error *error;
    build_notes warnings; /* every warning of the build, in order */
    uint32_t *ids;        /* results waiting for their parent's operation */
    size_t id_count, id_cap;
    /* one per id, grown with ids (id_cap): ID_* flags, and the node whose
     * result it is */
    unsigned char *id_flags;
    const model_node **id_nodes;
    /* the preview's solid (build_preview_solid): a union leaves out its
     * highlighted operands unless all are, as OpenSCAD's preview does */
    int drop_highlighted;
    size_t drops; /* unions that have such operands to leave out */
    /* the walk notes the preview's parts (mark_part, highlight_operands):
     * the main walk, or the preview's of a 2D model (whose main walk does
     * not visit nodes) */
    int notes_parts;
    /* a walk for the preview (its solid, its parts): 2D objects in a 3D
     * model are the slabs OpenSCAD's preview draws (build_preview_slab) */
    int preview;
    size_t flat_parts;   /* 2D objects the main walk left out of a 3D model, or
                            1 for a 2D model, which the preview draws as slabs */
    size_t renders;      /* render() nodes the main walk met, which the preview
                            draws each as one mesh (enter_render) */
    int root_warned;     /* a second '!' was warned of */
    int background_root; /* the root ('!') carries '%': the main walk draws
                            it, as OpenSCAD's render does, the preview as a
                            background part only */
    size_t cgal_drops;   /* meshes that are not closed (polyhedra, imports,
                            extrusions), which the main walk left out of a
                            CGAL operation in faithful mode and OpenSCAD's
                            preview draws as they are */
    size_t cgal_built;   /* leaves the main walk built as OpenSCAD's CGAL
                            takes them (a mesh in a CGAL operation: moved,
                            snapped, split on libtess2's diagonals; a shape
                            snapped), which its preview draws as written */
    uint32_t leaves;     /* leaves added so far: the next one's object_id */
    /* the preview's walk: the object ids of the leaves subtracted inside a
       render() (shading.preview_swapped) */
    uint32_t *swapped;
    size_t swapped_count, swapped_cap;
    /* the preview's walk: the leaves of each outermost render(), by object
     * id (shading.preview_renders) */
    shading_ids *lone;
    size_t lone_count, lone_cap;
    /* the preview's walk: its slabs (shading.preview_slabs) */
    shading_slab *slabs;
    size_t slab_count, slab_cap;
    int flat_model; /* the main walk was a 2D model's */
    frame *frames;
    size_t frame_count, frame_cap;
    shading *shading; /* lights, materials, camera, background */
    int faithful;     /* OpenSCAD's polyhedra for spheres and cylinders */
    int strict;       /* a mesh OpenSCAD would leave out is an error */
    int mesh_model;   /* BUILD_MESH_MODEL */
    size_t max_triangles, triangles_left; /* the meshes' budget, what is left of it */
    uint32_t root_id;                     /* the result of the first '!' node */
    /* resize matrices measured so far (build_hull.h) */
    build_resize_cache *resize_cache;
    build_imports imports; /* the files the imports read so far */
    build_nef_cache *nefs; /* CGAL's solids so far (build_nef_cache.h) */
    /* 2D children ignored in 3D operations, warned of when their parent
     * ends (flush_ignored) */
    ignored_child *ignored;
    size_t ignored_count, ignored_cap;
    part_mark *marks; /* the modifier parts met, in file order */
    size_t mark_count, mark_cap;
    const model_node *part; /* the subtree walk_part builds: its '%' is ignored */
} builder;

static sc_status warn(builder *b, const sc_location *loc, const char *format, ...)
    SC_PRINTF(3, 4);
static sc_status warn(builder *b, const sc_location *loc, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    sc_status st = build_notes_add(&b->warnings, b->error, loc, format, args);
    va_end(args);
    return st;
}

/* The build context of node n's builder: its warnings go to b's where
 * the node is built, nowhere where it is only checked. */
static build_ctx context(builder *b, int emit, sc_error *note)
{
    build_ctx c = {.file = b->file,
                   .csg = b->csg,
                   .error = b->error,
                   .faithful = b->faithful,
                   .note = note,
                   .notes = emit ? &b->warnings : NULL,
                   .strict = b->strict,
                   .mesh_model = b->mesh_model,
                   .triangles_left = &b->triangles_left,
                   .max_triangles = b->max_triangles,
                   .imports = &b->imports,
                   .nefs = b->nefs};
    return c;
}

/* What push_id records of a result besides its id. */
enum {
    ID_HIGHLIGHTED = 1, /* a highlighted term (highlight_operands) */
    ID_SLAB = 2         /* a 2D object left out of a 3D model, which the preview draws */
};

static sc_status push_id(builder *b, uint32_t id, int flags, const model_node *node)
{
    size_t cap = b->id_cap;
    if (!grow_array((void **)&b->ids, &b->id_cap, b->id_count + 1, sizeof *b->ids))
        return err_nomem(b->error, NULL);
    if (b->id_cap != cap || !b->id_flags || !b->id_nodes) {
        unsigned char *flags = realloc(b->id_flags, b->id_cap);
        if (flags)
            b->id_flags = flags;
        const model_node **nodes = realloc(b->id_nodes, b->id_cap * sizeof *nodes);
        if (nodes)
            b->id_nodes = nodes;
        if (!flags || !nodes)
            return err_nomem(b->error, NULL);
    }
    b->id_flags[b->id_count] = (unsigned char)flags;
    b->id_nodes[b->id_count] = node;
    b->ids[b->id_count++] = id;
    return SC_OK;
}

/* Notes the subtree of n, with the state its parent hands it, as a part of
 * the preview of kind (SHADING_OVERLAY_*): walk_part builds it. */
static sc_status add_mark(builder *b, const model_node *n, int kind, const frame *parent)
{
    if (!grow_array((void **)&b->marks, &b->mark_cap, b->mark_count + 1,
                    sizeof *b->marks))
        return err_nomem(b->error, NULL);
    part_mark *m = &b->marks[b->mark_count++];
    m->node = n;
    m->kind = kind;
    m->parent = *parent;
    return SC_OK;
}

/* Hands a node's result to whoever takes it: the design when the node is
 * the root, else its parent when it is counted. highlighted: the result is
 * a highlighted term (highlight_operands); a root that is one is a part of
 * the preview too, as OpenSCAD's buildCSGTree makes it (unless its own '#'
 * made it one already: mark_part). */
static sc_status deliver(builder *b, const model_node *node, int counted, uint32_t id,
                         int flags)
{
    if (node && node->is_root) {
        b->root_id = id;
        if ((flags & ID_HIGHLIGHTED) && !(node->modifiers & MODEL_MOD_HIGHLIGHT) &&
            b->notes_parts && id != CSG_EMPTY)
            return add_mark(b, node, SHADING_OVERLAY_HIGHLIGHT,
                            &b->frames[b->frame_count - 1]);
        return SC_OK;
    }
    return counted ? push_id(b, id, flags, node) : SC_OK;
}

/* Whether n is a render(), a union by another name. */
static int is_render(const model_node *n)
{
    return n->kind == MODEL_UNION && n->name && !strcmp(n->name, "render");
}

/* Whether the result at k on the id stack is an operand in OpenSCAD's
 * preview: not the empty solid, or a 2D object there drawn as a slab. */
static int operand(const builder *b, size_t k)
{
    return b->ids[k] != CSG_EMPTY || (b->id_flags[k] & ID_SLAB);
}

/* Sets *highlighted to whether the result of f's operation over its
 * children (on the id stack from f->first_id) is a highlighted term, as
 * OpenSCAD 2021.01's CSGTreeEvaluator::applyToChildren marks it: a '#'
 * node or one inside '#'; a union all of whose operands are; a difference
 * whose first operand is; an intersection all of whose operands are. The
 * empty solid is no operand. Where the highlight stops, OpenSCAD's preview
 * draws the highlighted operands as parts (its highlightNodes): a union's
 * or an intersection's with operands of both kinds, a difference's
 * subtrahends unless its first operand is highlighted, and (top, for the
 * file's own list) the whole when it is highlighted. Those are noted as
 * parts (add_mark, the main walk only, inside the design); and a union
 * with operands of both kinds leaves its highlighted ones out of
 * OpenSCAD's preview solid: counted in drops, and done in the preview's
 * solid (drop_highlighted). An intersection of several highlighted
 * operands and others is noted operand by operand, where OpenSCAD draws
 * the intersection of the highlighted ones. */
static sc_status highlight_operands(builder *b, const frame *f, int top, int *highlighted)
{
    if (f->node && is_render(f->node)) {
        /* OpenSCAD's RenderNode is one leaf of its own geometry, which
         * ignores the modifiers inside, and collects no operand's term:
         * nothing is noted, and only a '#' on it or above highlights it */
        *highlighted = f->highlighted;
        return SC_OK;
    }
    size_t marked = 0, plain = 0;
    for (size_t k = f->first_id; k < b->id_count; k++) {
        if (!operand(b, k))
            continue;
        if (b->id_flags[k] & ID_HIGHLIGHTED)
            marked++;
        else
            plain++;
    }
    int first = f->first_id < b->id_count && (b->id_flags[f->first_id] & ID_HIGHLIGHTED);
    int whole = f->op == CSG_DIFFERENCE ? first : !plain && marked > 0;
    *highlighted = f->highlighted || whole;
    int noting = b->notes_parts && f->shown && f->emit;
    /* which operands become parts: a union's or intersection's mixed
     * ones, a difference's subtrahends, or all at the top */
    int parts = (top && whole) || (f->op == CSG_DIFFERENCE ? !first : plain && marked);
    for (size_t k = f->first_id; noting && parts && k < b->id_count; k++) {
        if (!operand(b, k) || !(b->id_flags[k] & ID_HIGHLIGHTED))
            continue;
        sc_status st = add_mark(b, b->id_nodes[k], SHADING_OVERLAY_HIGHLIGHT, f);
        if (st != SC_OK)
            return st;
    }
    /* not inside a render(), whose mesh OpenSCAD builds of all its
     * children (the main walk does not know it is inside one: the
     * preview's walk is done, and keeps them) */
    if (f->op == CSG_UNION && plain && marked) {
        b->drops++;
        if (b->drop_highlighted && !f->in_render) {
            size_t kept = f->first_id;
            for (size_t k = f->first_id; k < b->id_count; k++)
                if (!(b->id_flags[k] & ID_HIGHLIGHTED)) {
                    b->ids[kept] = b->ids[k];
                    b->id_flags[kept] = b->id_flags[k];
                    b->id_nodes[kept++] = b->id_nodes[k];
                }
            b->id_count = kept;
        }
    }
    return SC_OK;
}

static int positive_finite(double x)
{
    return x > 0 && isfinite(x);
}

/* ---- leaves ---- */

/* Whether shape n is empty whatever its context, as OpenSCAD 2021.01
 * makes it (its builder warns): a cube, sphere or cylinder of a zero,
 * negative or non-finite size, a cylinder of two zero radii, a
 * polyhedron without faces. */
static int empty_shape(const model_node *n)
{
    if (n->pending)
        return 0;
    switch (n->kind) {
    case MODEL_CUBE:
        return !positive_finite(n->u.cube.size[0]) ||
               !positive_finite(n->u.cube.size[1]) || !positive_finite(n->u.cube.size[2]);
    case MODEL_SPHERE:
        return !positive_finite(n->u.sphere.r);
    case MODEL_CYLINDER: {
        double r1 = n->u.cylinder.r1, r2 = n->u.cylinder.r2;
        return !positive_finite(n->u.cylinder.h) || !(r1 >= 0 && r2 >= 0) ||
               !isfinite(r1) || !isfinite(r2) || (r1 == 0 && r2 == 0);
    }
    case MODEL_POLYHEDRON:
        return n->u.polyhedron.face_count == 0;
    default:
        return 0;
    }
}

static sc_status add_leaf(builder *b, const model_node *n, const prim *p,
                          const frame *state, uint32_t *id)
{
    *id = csg_builder_leaf(b->csg, p, &state->to_world, state->color, n->loc);
    if (*id == CSG_EMPTY)
        return csg_builder_failed(b->csg) ? err_nomem(b->error, NULL) : SC_OK;
    uint32_t object = b->leaves++;
    if (state->in_render && state->negative != state->render_negative) {
        if (!grow_array((void **)&b->swapped, &b->swapped_cap, b->swapped_count + 1,
                        sizeof *b->swapped))
            return err_nomem(b->error, NULL);
        b->swapped[b->swapped_count++] = object;
    }
    csg_builder_set_material(b->csg, *id, state->material);
    if (state->moving && *id != CSG_EMPTY)
        return build_motion_leaf(b->csg, *id, &state->motion, &state->to_world, n,
                                 b->error);
    return csg_builder_failed(b->csg) ? err_nomem(b->error, NULL) : SC_OK;
}

/* The transforms since the CGAL operation that takes a leaf in state,
 * returned, with *rest the state that places it from there. */
static const affine *at_cgal(const frame *state, frame *rest)
{
    *rest = *state;
    rest->to_world = state->cgal_world;
    return &state->since_cgal;
}

/* A mesh's leaf (a polyhedron's, an import's) in the render, as OpenSCAD
 * 2021.01 holds its points where a CGAL operation or the render's end
 * takes them: moved by the transforms since (state's since_cgal,
 * returned; build_mesh_merge_moved), where its points are snapped, a
 * face that is not planar is split and the mesh judged, and placed by the
 * rest (*rest: state with to_world its cgal_world). NULL where nothing
 * moved it, in the preview (OpenCSG draws the points as written) and in a
 * motion (its leaf keeps its own). */
static const affine *moved_leaf(const builder *b, const frame *state, frame *rest)
{
    if (b->preview || state->moving || affine_is_identity(&state->since_cgal))
        return NULL;
    return at_cgal(state, rest);
}

/* In faithful mode where a CGAL operation takes a shape (state->cgal),
 * OpenSCAD 2021.01 snaps the points of its mesh to its grid of 2^-20
 * where the transforms since that operation have moved them
 * (build_mesh_merge_moved) and CGAL hulls them: those transforms, and in
 * *rest the state that places the result; NULL elsewhere (the preview, a
 * motion, a shape drawn as it is). */
static const affine *snapped_shape(builder *b, const frame *state, frame *rest)
{
    if (!b->faithful || !state->cgal || b->preview || state->moving)
        return NULL;
    b->cgal_built += state->emit && state->shown;
    return at_cgal(state, rest);
}

/* A cube's box (lo, hi) snapped so (snapped_shape) where the transforms
 * since do not turn it: its snapped corners' box. 0 where they turn it
 * or a corner lies past the grid (2^40): the cube is then a mesh's
 * (faithful_hull_leaf). *lo >= *hi on an axis: empty, as OpenSCAD's hull
 * of flat corners. */
static int snapped_box(const affine *m, vec3 *lo, vec3 *hi)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (i != j && m->m[i][j] != 0)
                return 0;
    vec3 p = affine_point(m, *lo), q = affine_point(m, *hi);
    double v[6] = {fmin(p.x, q.x), fmin(p.y, q.y), fmin(p.z, q.z),
                   fmax(p.x, q.x), fmax(p.y, q.y), fmax(p.z, q.z)};
    for (int k = 0; k < 6; k++)
        if (!build_mesh_snap(v[k], &v[k]))
            return 0;
    *lo = v3(v[0], v[1], v[2]);
    *hi = v3(v[3], v[4], v[5]);
    return 1;
}

/* Shape n's faithful mesh (faces, freed here) snapped where it has moved
 * to (since, snapped_shape) and hulled, as CGAL takes it: one convex leaf
 * placed by rest, or nothing when the snapped points span no volume. */
static sc_status faithful_hull_leaf(builder *b, const model_node *n,
                                    faithful_faces *faces, const affine *since,
                                    const frame *rest, uint32_t *id)
{
    build_ctx c = context(b, rest->emit, NULL);
    c.drawn_as_is = 0;
    build_mesh_faces f;
    sc_status st =
        build_mesh_merge_moved(&c, &n->loc, 0, since, faces->points, faces->point_count,
                               faces->indices, faces->face_start, faces->face_count, &f);
    faithful_faces_free(faces);
    build_prims leaf = {NULL, 0, 0};
    if (st == SC_OK)
        st = build_hull_points(&c, n, f.points, f.point_count, &leaf);
    build_mesh_faces_free(&f);
    if (st == SC_OK && leaf.count)
        st = add_leaf(b, n, &leaf.items[0], rest, id);
    free(leaf.items);
    return st;
}

/* cube(size, center): a box, or the empty solid for no size. */
static sc_status build_cube(builder *b, const model_node *n, const frame *state,
                            uint32_t *id)
{
    const double *size = n->u.cube.size;
    int center = n->u.cube.center;
    if (!state->emit)
        return SC_OK;
    if (empty_shape(n))
        return warn(b, &n->loc, "cube with a zero, negative or non-finite size is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_BOX;
    vec3 s = v3(size[0], size[1], size[2]);
    p.u.box.lo = center ? v3_scale(s, -0.5) : v3(0, 0, 0);
    p.u.box.hi = center ? v3_scale(s, 0.5) : s;
    frame rest;
    const affine *since = snapped_shape(b, state, &rest);
    if (since && snapped_box(since, &p.u.box.lo, &p.u.box.hi)) {
        if (!(p.u.box.lo.x < p.u.box.hi.x && p.u.box.lo.y < p.u.box.hi.y &&
              p.u.box.lo.z < p.u.box.hi.z))
            return SC_OK;
        state = &rest;
    } else if (since) {
        /* its 8 corners and 6 faces, outward */
        static const uint32_t quads[24] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                           2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
        static const uint32_t starts[7] = {0, 4, 8, 12, 16, 20, 24};
        vec3 corners[8];
        for (int k = 0; k < 8; k++)
            corners[k] = v3(k & 1 ? p.u.box.hi.x : p.u.box.lo.x,
                            k & 2 ? p.u.box.hi.y : p.u.box.lo.y,
                            k & 4 ? p.u.box.hi.z : p.u.box.lo.z);
        faithful_faces box = {NULL, 8, NULL, NULL, 6};
        box.points = malloc(sizeof corners);
        box.indices = malloc(sizeof quads);
        box.face_start = malloc(sizeof starts);
        if (!box.points || !box.indices || !box.face_start) {
            faithful_faces_free(&box);
            return err_nomem(b->error, &n->loc);
        }
        memcpy(box.points, corners, sizeof corners);
        memcpy(box.indices, quads, sizeof quads);
        memcpy(box.face_start, starts, sizeof starts);
        return faithful_hull_leaf(b, n, &box, since, &rest, id);
    }
    return add_leaf(b, n, &p, state, id);
}

/* A faithful sphere or cylinder of more than PRIM_CONVEX_MAX_PLANES
 * faces, as a mesh leaf of its faces (freed here). */
static sc_status faithful_mesh_leaf(builder *b, const model_node *n,
                                    faithful_faces *faces, const frame *state,
                                    uint32_t *id)
{
    build_ctx c = context(b, state->emit, NULL);
    c.drawn_as_is = 1; /* convex: OpenSCAD hulls it for CGAL, unchecked */
    prim p;
    const char *empty = NULL;
    sc_status st =
        build_mesh_prim(&c, &n->loc, n->name, 0, faces->points, faces->point_count,
                        faces->indices, faces->face_start, faces->face_count, &p, &empty);
    faithful_faces_free(faces);
    if (st != SC_OK || empty)
        return st;
    return add_leaf(b, n, &p, state, id);
}

/* sphere(r): exact, or OpenSCAD's polyhedron in faithful mode (a mesh
 * leaf past PRIM_CONVEX_MAX_PLANES). */
static sc_status build_sphere(builder *b, const model_node *n, const frame *state,
                              uint32_t *id)
{
    double r = n->u.sphere.r;
    if (!state->emit)
        return SC_OK;
    if (empty_shape(n))
        return warn(b, &n->loc,
                    "sphere with a zero, negative or non-finite radius is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_SPHERE;
    p.u.sphere.r = r;
    const model_resolution *res = &n->u.sphere.res;
    sc_status st = SC_OK;
    frame rest;
    const affine *since = snapped_shape(b, state, &rest);
    if (since) {
        faithful_faces faces;
        st = faithful_sphere_faces(r, res->fn, res->fa, res->fs, &n->loc, &faces,
                                   b->error);
        return st == SC_OK ? faithful_hull_leaf(b, n, &faces, since, &rest, id) : st;
    }
    if (b->faithful) {
        long f = faithful_sphere_fragments(r, res->fn, res->fs, res->fa);
        if (f > 0 && faithful_sphere_face_count(f) > PRIM_CONVEX_MAX_PLANES) {
            faithful_faces faces;
            st = faithful_sphere_faces(r, res->fn, res->fa, res->fs, &n->loc, &faces,
                                       b->error);
            return st == SC_OK ? faithful_mesh_leaf(b, n, &faces, state, id) : st;
        }
        st = faithful_sphere(b->csg, r, res->fn, res->fa, res->fs, &n->loc, &p, b->error);
    }
    return st == SC_OK ? add_leaf(b, n, &p, state, id) : st;
}

/* cylinder(h, r1, r2, center): a frustum, or OpenSCAD's polyhedron in
 * faithful mode. */
static sc_status build_cylinder(builder *b, const model_node *n, const frame *state,
                                uint32_t *id)
{
    double h = n->u.cylinder.h, r1 = n->u.cylinder.r1, r2 = n->u.cylinder.r2;
    int center = n->u.cylinder.center;
    if (!state->emit)
        return SC_OK;
    if (empty_shape(n))
        return warn(b, &n->loc,
                    positive_finite(h)
                        ? "cylinder with negative, non-finite or two zero radii is empty"
                        : "cylinder with a zero, negative or non-finite height is empty");
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_CYLINDER;
    p.u.cylinder.z0 = center ? -h / 2 : 0;
    p.u.cylinder.z1 = center ? h / 2 : h;
    p.u.cylinder.r0 = r1;
    p.u.cylinder.r1 = r2;
    const model_resolution *res = &n->u.cylinder.res;
    sc_status st = SC_OK;
    double z0 = p.u.cylinder.z0, z1 = p.u.cylinder.z1;
    frame rest;
    const affine *since = snapped_shape(b, state, &rest);
    if (since) {
        faithful_faces faces;
        st = faithful_cylinder_faces(z0, z1, r1, r2, res->fn, res->fa, res->fs, &n->loc,
                                     &faces, b->error);
        return st == SC_OK ? faithful_hull_leaf(b, n, &faces, since, &rest, id) : st;
    }
    if (b->faithful) {
        long f = faithful_fragments(fmax(r1, r2), res->fn, res->fs, res->fa);
        if (f > 0 && (size_t)f + 2 > PRIM_CONVEX_MAX_PLANES) {
            faithful_faces faces;
            st = faithful_cylinder_faces(z0, z1, r1, r2, res->fn, res->fa, res->fs,
                                         &n->loc, &faces, b->error);
            return st == SC_OK ? faithful_mesh_leaf(b, n, &faces, state, id) : st;
        }
        st = faithful_cylinder(b->csg, z0, z1, r1, r2, res->fn, res->fa, res->fs, &n->loc,
                               &p, b->error);
    }
    return st == SC_OK ? add_leaf(b, n, &p, state, id) : st;
}

/* ---- polyhedron ---- */

/* A polyhedron's faces (the model's) and the builder's scratch. */
typedef struct mesh {
    const vec3 *points;
    uint32_t point_count;
    const uint32_t *indices; /* all faces' point indices, face after face */
    const uint32_t
        *face_start; /* face f is indices[face_start[f] .. face_start[f + 1]) */
    uint32_t face_count;
    uint64_t *edges; /* scratch: undirected edges as (lo << 32 | hi) */
    plane *planes;   /* scratch: one per face */
} mesh;

static void mesh_free(mesh *m)
{
    free(m->edges);
    free(m->planes);
}

/* Builds the outward face planes (duplicates merged) and checks convexity.
 * Each plane is oriented by the points themselves: all of them must lie on
 * one side, within tol (1e-5 of the largest coordinate or of the solid's
 * size, whichever is smaller), and inside is that side. A plane with every point
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
    /* convexity: absorbs 6-digit rounding, but no more than 1e-5 of the
     * solid's own size, or a small dented solid far out passes as convex */
    vec3 ext = v3_sub(bounds->hi, bounds->lo);
    double tol = 1e-5 * fmin(scale, fmax(ext.x, fmax(ext.y, ext.z)));
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

/* Whether m's faces are one piece, joined by their edges: a convex
 * polyhedron is, where the plane test's tolerance (1e-5 of the solid's
 * size) can pass two small solids far apart. 1, 0, or -1 when
 * memory runs out. */
static int faces_joined(const mesh *m)
{
    uint32_t *parent = malloc((m->face_count ? m->face_count : 1) * sizeof *parent);
    int joined = -1;
    if (parent && build_mesh_pieces(m->indices, m->face_start, m->face_count, parent)) {
        joined = 1;
        for (uint32_t f = 1; f < m->face_count && joined; f++)
            joined = build_mesh_piece(parent, f) == build_mesh_piece(parent, 0);
    }
    free(parent);
    return joined;
}

/* A mesh builder's warning (c.note), at its own position. */
static sc_status warn_note(builder *b, const sc_error *note)
{
    if (!note->message[0])
        return SC_OK;
    sc_location at = {b->file, note->line, note->column};
    return warn(b, &at, "%s", note->message);
}

/* polyhedron(points, faces): its points merged as OpenSCAD merges them
 * (build_mesh_merge) where they have moved to (moved_leaf), then convex
 * planes when it is closed and convex, else a mesh (build_mesh_solid,
 * which also takes the meshes that are not closed). */
static sc_status build_polyhedron(builder *b, const model_node *n, const frame *state,
                                  uint32_t *id)
{
    frame rest;
    const affine *since = moved_leaf(b, state, &rest);
    b->cgal_built += !b->preview && state->cgal && state->emit && state->shown;
    if (since)
        state = &rest;
    sc_error note = {SC_OK, "", 0, 0, ""};
    build_ctx c = context(b, state->warns, &note);
    c.drawn_as_is = !state->cgal || b->preview; /* OpenCSG takes any mesh */
    size_t left_out = b->warnings.left_out;
    sc_status st = build_bad_indices(&c, n);
    if (st != SC_OK)
        return st;
    if (n->u.polyhedron.face_count == 0) {
        /* not again after a warning that left its faces out, as OpenSCAD
         * prints only that */
        if (state->warns && b->warnings.left_out == left_out)
            st = warn(b, &n->loc, "polyhedron without faces is empty");
        return st;
    }
    build_mesh_faces f;
    st = build_mesh_merge_moved(&c, &n->loc, 1, since, n->u.polyhedron.points,
                                n->u.polyhedron.point_count, n->u.polyhedron.indices,
                                n->u.polyhedron.face_start, n->u.polyhedron.face_count,
                                &f);
    if (st != SC_OK)
        return st;
    mesh m;
    memset(&m, 0, sizeof m);
    m.points = f.points;
    m.point_count = f.point_count;
    m.indices = f.indices;
    m.face_start = f.face_start;
    m.face_count = f.face_count;
    /* The plane-set path compares every face with every point (and every
     * plane with the others), so larger polyhedra go to the mesh path
     * (build_mesh.c), as do the ones that are not convex or not closed, and
     * convex ones of more than PRIM_CONVEX_MAX_PLANES planes, each of which
     * a ray would test. Only a polyhedron the plane-set path would take
     * is judged closed here: build_mesh_solid judges the others. */
    int planes_path = (uint64_t)m.face_count * m.point_count <= BUILD_MAX_POLYHEDRON_WORK;
    uint32_t count = UINT32_MAX;
    bbox bounds;
    if (planes_path)
        st = convex_planes(b, &m, &count, &bounds);
    if (count != UINT32_MAX && count > PRIM_CONVEX_MAX_PLANES)
        count = UINT32_MAX;
    if (st == SC_OK && count != UINT32_MAX && count > 0) {
        int joined = faces_joined(&m);
        if (joined < 0)
            st = err_nomem(b->error, &n->loc);
        else if (!joined)
            count = UINT32_MAX; /* several pieces: the mesh path */
    }
    if (st == SC_OK && count != UINT32_MAX && f.face_count) {
        char why[8];
        int sound = build_mesh_cgal_closed(&c, &f, "polyhedron", 1, why, sizeof why);
        if (sound < 0)
            st = err_nomem(b->error, &n->loc);
        else if (!sound)
            count = UINT32_MAX;
    }
    if (st == SC_OK && count == UINT32_MAX) {
        const char *empty = NULL;
        prim p;
        st = build_mesh_solid(&c, &n->loc, "polyhedron", 1, b->strict, &f, &p, &empty);
        /* "": left out where CGAL leaves it out, with its warning */
        b->cgal_drops += st == SC_OK && empty && !empty[0] && b->faithful &&
                         !c.drawn_as_is && state->emit && state->shown;
        if (st == SC_OK && state->warns)
            st = warn_note(b, &note);
        if (st == SC_OK && state->warns && empty)
            st = empty[0] ? warn(b, &n->loc, "%s", empty) : SC_OK;
        else if (st == SC_OK && state->emit && !empty)
            st = add_leaf(b, n, &p, state, id);
        mesh_free(&m);
        build_mesh_faces_free(&f);
        return st;
    }
    if (st == SC_OK && state->warns && count == 0)
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
    build_mesh_faces_free(&f);
    return st;
}

/* torus, quadric, implicit (model/lower_curved.c read them). */
static sc_status build_curved(builder *b, const model_node *n, const frame *state,
                              uint32_t *id)
{
    if (!state->emit)
        return SC_OK;
    const char *empty = n->kind == MODEL_TORUS     ? n->u.torus->empty
                        : n->kind == MODEL_QUADRIC ? n->u.quadric->empty
                                                   : n->u.implicit->empty;
    if (empty)
        return warn(b, &n->loc, "%s", empty);
    prim p;
    memset(&p, 0, sizeof p);
    if (n->kind == MODEL_TORUS) {
        p.kind = PRIM_TORUS;
        p.u.torus.major = n->u.torus->r1;
        p.u.torus.minor = n->u.torus->r2;
    } else if (n->kind == MODEL_QUADRIC) {
        /* The coefficients live with the tree. */
        prim_quadric *q = csg_builder_alloc(b->csg, sizeof *q);
        if (!q)
            return err_nomem(b->error, NULL);
        memcpy(q->a, n->u.quadric->a, sizeof q->a);
        q->box = n->u.quadric->box;
        p.kind = PRIM_QUADRIC;
        p.u.quadric.q = q;
    } else {
        /* The bytecode lives with the tree. */
        const model_implicit *f = n->u.implicit;
        expr_program *program = csg_builder_alloc(b->csg, sizeof *program);
        if (!program)
            return err_nomem(b->error, NULL);
        *program = f->program;
        p.kind = PRIM_IMPLICIT;
        p.u.implicit.program = program;
        p.u.implicit.box = f->box;
        p.u.implicit.tolerance = f->tolerance;
        p.u.implicit.lipschitz = f->method == SOLVE_LIPSCHITZ && f->lipschitz == 0
                                     ? solve_estimate_lipschitz(program, f->box)
                                     : f->lipschitz;
        p.u.implicit.method = f->method;
    }
    return add_leaf(b, n, &p, state, id);
}

/* The leaves of node n united: none is the empty solid, one is itself. */
static sc_status add_leaves(builder *b, const model_node *n, const build_prims *leaves,
                            const frame *state, uint32_t *id)
{
    uint32_t *ids = leaves->count > 1 ? calloc(leaves->count, sizeof *ids) : id;
    if (!ids)
        return err_nomem(b->error, NULL);
    sc_status st = SC_OK;
    for (uint32_t i = 0; st == SC_OK && i < leaves->count; i++)
        st = add_leaf(b, n, &leaves->items[i], state, &ids[i]);
    if (st == SC_OK && leaves->count > 1) {
        *id = csg_builder_op(b->csg, CSG_UNION, ids, leaves->count);
        if (csg_builder_failed(b->csg))
            st = err_nomem(b->error, NULL);
    }
    if (ids != id)
        free(ids);
    return st;
}

/* import(file = "...") (build_mesh.c: one leaf, or one per object of an
 * AMF or 3MF file, united as OpenSCAD unites them, where their points have
 * moved to: moved_leaf), linear_extrude (build_extrude.c) or
 * rotate_extrude (build_revolve.c). */
static sc_status build_import_leaf(builder *b, const model_node *n, const frame *state,
                                   uint32_t *id)
{
    frame rest;
    const affine *since = n->kind == MODEL_IMPORT ? moved_leaf(b, state, &rest) : NULL;
    b->cgal_built += n->kind == MODEL_IMPORT && !b->preview && state->cgal &&
                     state->emit && state->shown;
    if (since)
        state = &rest;
    sc_error note = {SC_OK, "", 0, 0, ""}; /* a warning, e.g. a font fallback */
    build_ctx c = context(b, state->warns, &note);
    c.moved = since;
    c.drawn_as_is = !state->cgal || b->preview; /* OpenCSG takes any mesh */
    const char *empty = NULL;
    prim p;
    build_prims leaves = {NULL, 0, 0};
    size_t left_out = b->warnings.left_out;
    sc_status st = SC_OK;
    /* an import of a file that does not open is empty, with OpenSCAD's
     * warning at the file's name (build_file_not_opened); read for its
     * warnings where it is not built */
    if (n->kind == MODEL_IMPORT && state->warns)
        st = build_import_parts(&c, n->u.import, b->strict, &leaves, &empty);
    else if (n->kind == MODEL_LINEAR_EXTRUDE)
        st = build_linear_extrude(&c, n, state->emit, &p, &empty);
    else if (n->kind == MODEL_ROTATE_EXTRUDE)
        st = build_rotate_extrude(&c, n, state->emit, &p, &empty);
    if (st == SC_OK && state->warns && note.message[0]) {
        sc_location at = {b->file, note.line, note.column};
        st = warn(b, &at, "%s", note.message);
    }
    /* left out of a CGAL operation (or not read): the preview draws it */
    b->cgal_drops += st == SC_OK && empty && !empty[0] && b->faithful && !c.drawn_as_is &&
                     state->emit && state->shown;
    if (st != SC_OK || !state->warns)
        ;
    else if (!state->emit) /* only warned of */
        st = empty && empty[0] && n->kind == MODEL_IMPORT &&
                     b->warnings.left_out == left_out
                 ? warn(b, &n->loc, "%s", empty)
                 : SC_OK;
    else if (empty) /* "": left out, the warning was the note; nor is an
                     * extrusion of an import left out (build_notes) */
        st = empty[0] && b->warnings.left_out == left_out ? warn(b, &n->loc, "%s", empty)
                                                          : SC_OK;
    else if (n->kind == MODEL_IMPORT)
        st = add_leaves(b, n, &leaves, state, id);
    else
        st = add_leaf(b, n, &p, state, id);
    free(leaves.items);
    return st;
}

/* A 2D object among 3D objects (a 2D shape, or an operation whose first
 * child with a dimension is 2D: build_dim): checked through the 2D engine,
 * then the empty solid, with OpenSCAD 2021.01's warnings (isValidDim and
 * collectChildren3D in its GeometryEvaluator.cc) when its parent ends. */
static sc_status build_twod_ignored(builder *b, const model_node *n, const frame *state)
{
    build_ctx c = context(b, state->warns, NULL);
    int empty;
    sc_status st = build_twod_check(&c, n, &empty);
    /* a '%' child is no operand of its parent's, which says nothing of it */
    if (st != SC_OK || !state->warns ||
        ((n->modifiers & MODEL_MOD_BACKGROUND) && n != b->part))
        return st;
    if (!grow_array((void **)&b->ignored, &b->ignored_cap, b->ignored_count + 1,
                    sizeof *b->ignored))
        return err_nomem(b->error, NULL);
    b->ignored[b->ignored_count++] = (ignored_child){n, empty};
    return SC_OK;
}

/* The warnings for the 2D children that frame f ignored, once all its
 * children are built, as OpenSCAD checks dimensions after evaluating the
 * children: first that f mixes them, at the first that is not empty (an
 * empty one, such as a polygon emptied by a bad point, mixes nothing for
 * OpenSCAD 2021.01's isValidDim), then each ignored; with --strict the
 * first of them is the error. */
static sc_status flush_ignored(builder *b, const frame *f)
{
    build_ctx c = context(b, 1, NULL); /* only children that warn are kept */
    sc_status st = SC_OK;
    for (size_t k = f->first_ignored; k < b->ignored_count; k++) {
        if (!b->ignored[k].empty) {
            st = build_mixing(&c, &b->ignored[k].node->loc, 0);
            break;
        }
    }
    for (size_t k = f->first_ignored; st == SC_OK && k < b->ignored_count; k++)
        st = build_ignoring(&c, &b->ignored[k].node->loc, 0);
    b->ignored_count = f->first_ignored;
    return st;
}

/* A 2D model: the '!' node n when its subtree is 2D, or else (n NULL) the
 * file's top level when its first node with a dimension is 2D, as
 * OpenSCAD's top-level group takes its dimension. Its region (3D objects
 * in it ignored with a warning) becomes the slab OpenSCAD draws a 2D
 * result as (build_flat_slab), with state's colour; the shading record
 * says that the model is flat, so that the render draws it as OpenSCAD's
 * render draws 2D (shading.h). */
/* Records where OpenSCAD's render draws the 2D model of region r, in
 * state's frame: the plane z = 0, the region's box in it and its outlines,
 * all in the world (shading.h). */
static sc_status note_flat(builder *b, const twod_region *r, const frame *state)
{
    shading *s = b->shading;
    const affine *m = &state->to_world;
    vec3 origin = affine_point(m, v3(0, 0, 0));
    vec3 n = v3_cross(affine_vector(m, v3(1, 0, 0)), affine_vector(m, v3(0, 1, 0)));
    double len = v3_length(n);
    /* a flattened frame leaves n zero: no ray meets the plane */
    n = len > 0 ? v3_scale(n, 1 / len) : v3(0, 0, 0);
    s->flat_plane[0] = n.x;
    s->flat_plane[1] = n.y;
    s->flat_plane[2] = n.z;
    s->flat_plane[3] = v3_dot(n, origin);
    free(s->flat_points);
    free(s->flat_start);
    s->flat_points = NULL;
    s->flat_start = NULL;
    s->flat_outlines = 0;
    s->flat_box = bbox_empty();
    if (r->contour_count == 0)
        return SC_OK;
    s->flat_points = malloc((size_t)r->point_count * 3 * sizeof *s->flat_points);
    s->flat_start = malloc(((size_t)r->contour_count + 1) * sizeof *s->flat_start);
    if (!s->flat_points || !s->flat_start)
        return err_nomem(b->error, NULL);
    for (uint32_t i = 0; i < r->point_count; i++) {
        vec3 p = affine_point(m, v3(r->xy[2 * i], r->xy[2 * i + 1], 0));
        s->flat_points[3 * i] = p.x;
        s->flat_points[3 * i + 1] = p.y;
        s->flat_points[3 * i + 2] = p.z;
        s->flat_box = bbox_add_point(s->flat_box, p);
    }
    memcpy(s->flat_start, r->start,
           ((size_t)r->contour_count + 1) * sizeof *s->flat_start);
    s->flat_outlines = r->contour_count;
    return SC_OK;
}

static sc_status build_flat(builder *b, const model_node *n, const frame *state,
                            uint32_t *id)
{
    *id = CSG_EMPTY;
    const model_node *at = n ? n : twod_walk_next(b->model->first);
    build_ctx c = context(b, 1, NULL);
    twod_region r;
    twod_init(&r);
    size_t left_out = b->warnings.left_out;
    sc_status st = n ? build_twod_main(&c, n, &r) : build_twod_top(&c, at, &r);
    prim p;
    const char *empty = NULL;
    if (st == SC_OK)
        st = build_flat_slab(&c, &at->loc, &r, 1, &p, &empty);
    if (st == SC_OK && !empty)
        st = note_flat(b, &r, state);
    twod_free(&r);
    if (st != SC_OK)
        return st;
    b->shading->flat_2d = 1;
    if (empty) /* not warned of after an import left out (build_notes) */
        return b->warnings.left_out > left_out ? SC_OK : warn(b, &at->loc, "%s", empty);
    return add_leaf(b, at, &p, state, id);
}

/* A 2D leaf of the preview's walk (a shape, or an operation OpenSCAD
 * evaluates to a polygon: offset, hull, minkowski, projection, resize, an
 * import, text) as OpenSCAD's preview draws it (Renderer::render_surface):
 * the slab of its region 1 thick, or 1.1 where it is subtracted, in its
 * own coordinates, with f's transform and colour. Nothing where its region
 * has no area. */
static sc_status build_preview_slab(builder *b, const model_node *n, const frame *f,
                                    uint32_t *id)
{
    *id = CSG_EMPTY;
    if (!f->emit)
        return SC_OK;
    build_ctx c = context(b, 1, NULL);
    twod_region r;
    twod_init(&r);
    sc_status st = build_twod_main(&c, n, &r);
    prim p;
    const char *empty = NULL;
    if (st == SC_OK)
        st = build_flat_slab(&c, &n->loc, &r, f->negative ? 1.1 : 1, &p, &empty);
    twod_free(&r);
    if (st != SC_OK || empty)
        return st;
    st = add_leaf(b, n, &p, f, id);
    if (st != SC_OK || *id == CSG_EMPTY)
        return st;
    /* framed by its polygons' box, not the slab's (OpenSCAD's
     * PolySet::getBoundingBox of the flat polygons) */
    bbox flat = prim_bounds(&p);
    flat.lo.z = flat.hi.z = 0;
    if (!grow_array((void **)&b->slabs, &b->slab_cap, b->slab_count + 1,
                    sizeof *b->slabs))
        return err_nomem(b->error, NULL);
    b->slabs[b->slab_count++] =
        (shading_slab){b->leaves - 1, bbox_transform(&f->to_world, flat)};
    return SC_OK;
}

/* hull and minkowski (build_hull.c): one or several convex leaves, united
 * (add_leaves). Without emit, build_hull and build_minkowski give no
 * leaves, so nothing is added. An empty result is not warned of after an
 * import left out (build_notes), as for an extrusion. */
static sc_status build_hull_leaf(builder *b, const model_node *n, const frame *state,
                                 uint32_t *id)
{
    build_ctx c = context(b, state->emit, NULL);
    const char *empty = NULL;
    build_prims leaves = {NULL, 0, 0};
    size_t left_out = b->warnings.left_out;
    sc_status st =
        n->kind == MODEL_HULL
            ? build_hull(&c, n, state->emit, &b->resize_cache, &leaves, &empty)
            : build_minkowski(&c, n, state->emit, &b->resize_cache, &leaves, &empty);
    if (st == SC_OK && state->emit && empty && b->warnings.left_out == left_out)
        st = warn(b, &n->loc, "%s", empty);
    if (st == SC_OK && state->emit)
        st = add_leaves(b, n, &leaves, state, id);
    free(leaves.items);
    return st;
}

/* Faithful mode: n, which OpenSCAD 2021.01 makes a Nef polyhedron of and
 * which takes a mesh that passes through itself, as CGAL's solid
 * (build_cgal_crossing): its boundary as a mesh leaf, drawn as it is. */
static sc_status build_cgal_leaf(builder *b, const model_node *n, const frame *state,
                                 uint32_t *id)
{
    build_ctx c = context(b, state->emit, NULL);
    vec3 *tris = NULL;
    uint32_t count = 0;
    sc_status st =
        build_nef_triangles(&c, n, n->name, &b->resize_cache, 0, &tris, &count);
    const char *empty = NULL;
    prim p;
    if (st == SC_OK && count)
        st = build_mesh_soup(&c, &n->loc, n->name, tris, count, &p, &empty);
    free(tris);
    if (st == SC_OK && count && !empty)
        st = add_leaf(b, n, &p, state, id);
    return st;
}

/* Faithful mode: if n, which OpenSCAD 2021.01 makes a Nef polyhedron of,
 * takes a mesh that passes through itself (build_cgal_crossing), n drawn
 * in state as CGAL's solid and delivered, and *crossing set. OpenSCAD's
 * preview draws it as written (OpenCSG). */
static sc_status cgal_crossing(builder *b, const model_node *n, const frame *state,
                               int *crossing)
{
    build_ctx c = context(b, 0, NULL);
    sc_status st = build_cgal_crossing(&c, n, crossing);
    if (st != SC_OK || !*crossing)
        return st;
    b->cgal_built += state->emit && state->shown;
    uint32_t id = CSG_EMPTY;
    st = build_cgal_leaf(b, n, state, &id);
    return st != SC_OK ? st
                       : deliver(b, n, state->counted, id,
                                 state->highlighted ? ID_HIGHLIGHTED : 0);
}

/* surface(file) (build_surface.c). */
static sc_status build_surface_leaf(builder *b, const model_node *n, const frame *state,
                                    uint32_t *id)
{
    build_ctx c = context(b, state->emit, NULL);
    const char *empty = NULL;
    prim p;
    if (!state->emit)
        return SC_OK;
    sc_status st = build_surface(&c, n->u.surface, &p, &empty);
    if (st != SC_OK)
        return st;
    if (empty)
        return warn(b, &n->loc, "%s", empty);
    return add_leaf(b, n, &p, state, id);
}

/* ---- boolean nodes with arguments ---- */

/* color(c, alpha) (model.h): the colour its children get, each component
 * clamped to 0..1 (its warnings are the model's), unless a colour above it
 * is set: OpenSCAD 2021.01's preview sets a colour only where none is
 * (CSGTreeEvaluator, visit(ColorNode)), so the outermost wins and a
 * library part is recoloured from outside. A colour with a negative
 * component (OpenSCAD's "none", [-1, -1, -1, 1], for a name it does not
 * know; [-1, -1, -1, a] for color(alpha = a)) is not set (Color4f's
 * isValid), so a colour inside it still applies; where none does, its
 * negative components are the default colour's and the others its own,
 * as OpenSCAD's Renderer::setColor fills them in: color(alpha = 0.5) is
 * the face colour at half opacity. */
static void apply_color(const model_node *n, frame *f)
{
    static const float def[4] = BUILD_DEFAULT_COLOR;
    const model_color *mc = n->u.color;
    if (f->color_set)
        return;
    int valid = 1;
    float *color = f->color;
    for (int i = 0; i < 4; i++) {
        double c = i == 3 && mc->has_alpha ? mc->alpha : mc->c[i];
        valid &= !(c < 0);
        color[i] = c < 0 ? def[i] : c <= 1 ? (float)c : c > 1 ? 1.0f : 0.0f;
    }
    f->color_set = valid;
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
    /* Read in place, not copied (a frame is over 600 bytes): nothing
     * below pushes a frame, so the slot stays as it is. */
    const frame *f = &b->frames[--b->frame_count];
    uint32_t id = CSG_EMPTY;
    sc_status st;
    if (f->node && f->node->kind == MODEL_XFORM && f->node->not_finite) {
        /* removed after its children's warnings, without checking their
         * dimensions */
        build_ctx c = context(b, f->warns, NULL);
        b->ignored_count = f->first_ignored;
        st = build_xform_not_finite(&c, f->node);
    } else {
        st = flush_ignored(b, f);
    }
    if (st != SC_OK)
        return st;
    int highlighted;
    if ((st = highlight_operands(b, f, 0, &highlighted)) != SC_OK)
        return st;
    if (f->emit) {
        size_t count = b->id_count - f->first_id;
        if (count > UINT32_MAX)
            return err_nomem(b->error, NULL);
        /* No id pushed yet means no id array at all: NULL + 0 is undefined. */
        const uint32_t *children = count ? b->ids + f->first_id : NULL;
        id = csg_builder_op(b->csg, f->op, children, (uint32_t)count);
        if (csg_builder_failed(b->csg))
            return err_nomem(b->error, NULL);
    }
    b->id_count = f->first_id;
    int outermost = b->frame_count == 0 || !b->frames[b->frame_count - 1].in_render;
    if (f->in_render && outermost && b->leaves > f->render_first) {
        if (!grow_array((void **)&b->lone, &b->lone_cap, b->lone_count + 1,
                        sizeof *b->lone))
            return err_nomem(b->error, NULL);
        b->lone[b->lone_count++] = (shading_ids){f->render_first, b->leaves};
    }
    return deliver(b, f->node, f->counted, id, highlighted ? ID_HIGHLIGHTED : 0);
}

/* Notes n for the preview when it carries '#' or '%' inside the design
 * (the main walk only: walk_part builds what was noted). */
static sc_status mark_part(builder *b, const model_node *n, const frame *parent)
{
    if (!b->notes_parts || !(parent->shown || n->is_root) ||
        (parent->children_lost && !n->is_root))
        return SC_OK;
    sc_status st = SC_OK;
    if (n->modifiers & MODEL_MOD_BACKGROUND)
        st = add_mark(b, n, SHADING_OVERLAY_BACKGROUND, parent);
    /* a '#' where nothing is built (below a '%', or with one), or on the
     * root; others where the highlight stops (highlight_operands) */
    if (st == SC_OK && (n->modifiers & MODEL_MOD_HIGHLIGHT) &&
        (!parent->emit || n->is_root || (n->modifiers & MODEL_MOD_BACKGROUND)))
        st = add_mark(b, n, SHADING_OVERLAY_HIGHLIGHT, parent);
    return st;
}

/* Notes the '#' and '%' children of hull or minkowski n (state f) as
 * parts: OpenSCAD's CSGTreeEvaluator draws them
 * (applyBackgroundAndHighlight), though the builder reads them as the
 * operation's operands and does not walk them. */
static sc_status mark_operands(builder *b, const model_node *n, const frame *f)
{
    sc_status st = SC_OK;
    if (!b->notes_parts || !f->shown)
        return st;
    for (const model_node *k = n->first_child; st == SC_OK && k; k = k->next) {
        if (k->modifiers & MODEL_MOD_DISABLE)
            continue;
        if (k->modifiers & MODEL_MOD_BACKGROUND)
            st = add_mark(b, k, SHADING_OVERLAY_BACKGROUND, f);
        if (st == SC_OK && (k->modifiers & MODEL_MOD_HIGHLIGHT))
            st = add_mark(b, k, SHADING_OVERLAY_HIGHLIGHT, f);
    }
    return st;
}

/* A minkowski() of one solid, which OpenSCAD 2021.01 passes through as it
 * is (applyToChildren3D: no sum, no CGAL): built as a group of it. */
static int lone_minkowski(const model_node *n)
{
    return n->kind == MODEL_MINKOWSKI && build_operands(n->kind, n->first_child) == 1;
}

/* Whether OpenSCAD 2021.01's render hands the results of the nodes first
 * (a list of siblings, the children of an operation of this kind) to
 * CGAL: where two or more of them are operands (build_operands). A
 * render() unites its children so too, and takes one child's mesh as it
 * is. A mesh that is not closed is left out where its result meets CGAL,
 * and drawn as it is where nothing hands it to CGAL. */
static int to_cgal(model_kind kind, const model_node *first)
{
    return build_operands(kind, first) > 1;
}

/* The state node n hands its children (or, for a leaf, builds with),
 * from its parent's: written into *f, which may be the next free slot of
 * b->frames. */
static void inherit(const builder *b, const model_node *n, const frame *parent, frame *f)
{
    *f = *parent;
    f->node = n;
    if (n->is_root) {
        static const float default_color[4] = BUILD_DEFAULT_COLOR;
        f->emit = 1;
        f->warns = 1;
        f->shown = 1;
        f->to_world = affine_identity();
        memcpy(f->color, default_color, sizeof f->color);
        f->color_set = 0;
        f->material = 0;
        f->highlighted = 0;
    }
    if (n->modifiers & MODEL_MOD_HIGHLIGHT)
        f->highlighted = 1;
    if (parent->node && parent->op == CSG_DIFFERENCE && parent->node->first_child != n)
        f->negative = !parent->negative;
    /* '%' leaves n out of its parent's result; the root ('!') has no
     * parent in OpenSCAD's render, which draws it all the same (its
     * preview draws it as a background part) */
    if ((n->modifiers & MODEL_MOD_BACKGROUND) && n != b->part &&
        !(n->is_root && !b->preview))
        f->emit = 0;
    f->counted = f->emit;
    f->children_lost = parent->children_lost && n->child_count == 1 && !n->is_root;
    /* a leaf's children (an extrusion's 2D ones) are united by Clipper */
    int operation = (!model_is_leaf(n->kind) || lone_minkowski(n)) &&
                    to_cgal(n->kind, n->first_child);
    f->cgal = (!n->is_root && parent->cgal) || operation;
    if (n->is_root || operation) {
        f->since_cgal = affine_identity();
        f->cgal_world = f->to_world;
    }
}

/* f's node n transforms its children by m: for a CGAL operation of
 * its children (a multmatrix of several), after their union (inherit). */
static void transform_frame(const model_node *n, frame *f, const affine *m)
{
    f->to_world = affine_mul(&f->to_world, m);
    if (!model_is_leaf(n->kind) && to_cgal(n->kind, n->first_child))
        f->cgal_world = f->to_world;
    else
        f->since_cgal = affine_mul(&f->since_cgal, m);
}

/* Whether leaf n builds with its parent's state as it is (inherit would
 * change nothing it reads), and its builder pushes no frame, so that the
 * parent's frame serves it in place: a frame is over 600 bytes, and
 * copying one per leaf was a large part of the walk of a million. */
static int plain_leaf(const builder *b, const model_node *n, const frame *parent)
{
    model_kind kind = n->kind;
    return (kind == MODEL_SPHERE || kind == MODEL_CUBE || kind == MODEL_CYLINDER) &&
           !n->is_root && parent->counted == parent->emit &&
           !(parent->in_render && parent->op == CSG_DIFFERENCE) && /* negative */
           !((n->modifiers & MODEL_MOD_BACKGROUND) && n != b->part);
}

/* Builds leaf n with state f and delivers its result. */
static sc_status visit_leaf(builder *b, const model_node *n, const frame *f)
{
    sc_status st;
    model_kind kind = n->kind;
    /* OpenSCAD's primitives warn of their children as OpenSCAD words it,
     * with the arguments' warnings (model.h), and its import and surface
     * ignore them silently; spancast's own leaves warn here. */
    if (n->child_count > 0 && f->emit &&
        (kind == MODEL_TORUS || kind == MODEL_QUADRIC || kind == MODEL_IMPLICIT) &&
        (st = warn(b, &n->loc, "'%s' takes no children; they are ignored", n->name)) !=
            SC_OK)
        return st;
    uint32_t id = CSG_EMPTY;
    switch (kind) {
    case MODEL_CUBE:
        st = build_cube(b, n, f, &id);
        break;
    case MODEL_SPHERE:
        st = build_sphere(b, n, f, &id);
        break;
    case MODEL_CYLINDER:
        st = build_cylinder(b, n, f, &id);
        break;
    case MODEL_TORUS:
    case MODEL_QUADRIC:
    case MODEL_IMPLICIT:
        st = build_curved(b, n, f, &id);
        break;
    case MODEL_IMPORT:
    case MODEL_LINEAR_EXTRUDE:
    case MODEL_ROTATE_EXTRUDE:
        st = build_import_leaf(b, n, f, &id);
        break;
    case MODEL_HULL:
    case MODEL_MINKOWSKI:
        st = build_hull_leaf(b, n, f, &id);
        break;
    case MODEL_SURFACE:
        st = build_surface_leaf(b, n, f, &id);
        break;
    case MODEL_POLYHEDRON:
        st = build_polyhedron(b, n, f, &id);
        break;
    case MODEL_PROJECTION: {
        /* without a 3D child (build_projects): no geometry, as in OpenSCAD,
         * so neither 2D nor ignored; its children still give their
         * warnings */
        build_ctx c = context(b, f->emit, NULL);
        st = build_twod_check(&c, n, NULL);
        break;
    }
    default: /* the 2D shapes, taken before */
        st = SC_OK;
        break;
    }
    return st != SC_OK ? st
                       : deliver(b, n, f->counted, id,
                                 f->highlighted || (n->modifiers & MODEL_MOD_HIGHLIGHT)
                                     ? ID_HIGHLIGHTED
                                     : 0);
}

/* render(): OpenSCAD 2021.01's preview draws it as one mesh
 * (CSGTreeEvaluator evaluates its geometry into one leaf), in the colour its
 * ancestors give it, or the face colours where none do; the walls of holes
 * cut inside it are that mesh's own faces, in the front colour. The main
 * walk counts it, so that the preview's solid is walked; the preview's
 * walk keeps the colour from above (the colours inside are not applied)
 * and notes where the render()'s own subtraction starts. */
static void enter_render(builder *b, frame *f)
{
    f->children_lost = 1;
    if (!b->preview) {
        b->renders += f->emit && f->shown;
    } else if (!f->in_render) {
        f->in_render = 1;
        f->render_negative = f->negative;
        f->render_first = b->leaves;
        f->color_set = 1;
    }
}

/* Visits one node: a leaf delivers its result; a boolean node opens a
 * frame for its children. *opened says which. */
static sc_status visit(builder *b, const model_node *n, int *opened)
{
    *opened = 0;
    sc_status st;
    model_kind kind = n->kind;
    if (kind == MODEL_ERROR) {
        *b->error = *n->u.error;
        return n->u.error->status;
    }
    /* OpenSCAD's warning, once, at the second '!' (find_root_tag) */
    if ((n->modifiers & MODEL_MOD_ROOT) && !n->is_root && !b->root_warned) {
        b->root_warned = 1;
        if ((st = warn(b, &n->loc, "More than one Root Modifier (!)")) != SC_OK)
            return st;
    }
    const frame *parent = &b->frames[b->frame_count - 1];
    if ((st = mark_part(b, n, parent)) != SC_OK)
        return st;
    b->background_root |= n->is_root && (n->modifiers & MODEL_MOD_BACKGROUND);
    if (plain_leaf(b, n, parent))
        return visit_leaf(b, n, parent);
    /* faithful mode: the outermost operation OpenSCAD makes a Nef
     * polyhedron of, if it takes a mesh that passes through itself, is
     * CGAL's solid (build_cgal_leaf); else nothing below it is */
    int checked = 0;
    if (b->faithful && !b->preview && !parent->moving && !parent->crossing_clean &&
        !model_is_leaf(kind) && kind != MODEL_HULL && kind != MODEL_MINKOWSKI &&
        kind != MODEL_PROJECTION && build_dim(n, 0) == 3 &&
        to_cgal(kind, n->first_child)) {
        /* the state n gets: a '!' node is drawn though its parent is not */
        frame f;
        inherit(b, n, parent, &f);
        int crossing = 0;
        if (f.emit && (st = cgal_crossing(b, n, &f, &crossing)) != SC_OK)
            return st;
        if (crossing)
            return SC_OK;
        checked = f.emit;
    }
    int flat = build_dim(n, 0) == 2 && (kind != MODEL_PROJECTION || build_projects(n));
    /* OpenSCAD's preview draws 2D booleans, transforms and colours as CSG
     * of its 2D leaves' slabs */
    if (flat && b->preview &&
        (kind == MODEL_UNION || kind == MODEL_DIFFERENCE || kind == MODEL_INTERSECTION ||
         kind == MODEL_XFORM || kind == MODEL_COLOR || kind == MODEL_MATERIAL))
        flat = 0;
    if ((model_is_leaf(kind) && !lone_minkowski(n)) || kind == MODEL_LIGHT ||
        kind == MODEL_CAMERA || kind == MODEL_BACKGROUND || flat) {
        frame f;
        inherit(b, n, parent, &f);
        if (kind == MODEL_LIGHT)
            return build_light(b->shading, n, &f.to_world, f.emit, b->error);
        if (kind == MODEL_CAMERA) {
            build_camera(b->shading, n, f.emit);
            return SC_OK;
        }
        if (kind == MODEL_BACKGROUND) {
            build_background(b->shading, n, f.emit);
            return SC_OK;
        }
        if (flat) {
            /* ignored, it is the empty solid, which empties an intersection
             * as in OpenSCAD */
            uint32_t id = CSG_EMPTY;
            int flags = f.highlighted ? ID_HIGHLIGHTED : 0;
            if (b->preview) {
                st = build_preview_slab(b, n, &f, &id);
            } else if (n->is_root) {
                st = build_flat(b, n, &f, &id);
            } else {
                b->flat_parts += f.emit && f.shown;
                flags |= ID_SLAB;
                st = build_twod_ignored(b, n, &f);
            }
            return st != SC_OK ? st : deliver(b, n, f.counted, id, flags);
        }
        if ((kind == MODEL_HULL || kind == MODEL_MINKOWSKI) &&
            (st = mark_operands(b, n, &f)) != SC_OK)
            return st;
        return visit_leaf(b, n, &f);
    }
    /* A boolean node: its frame is made in place, in the next slot, and
     * counted once complete. */
    if (!grow_array((void **)&b->frames, &b->frame_cap, b->frame_count + 1,
                    sizeof *b->frames))
        return err_nomem(b->error, NULL);
    frame *f = &b->frames[b->frame_count];
    inherit(b, n, &b->frames[b->frame_count - 1], f);
    f->crossing_clean |= checked;
    f->op = kind == MODEL_DIFFERENCE     ? CSG_DIFFERENCE
            : kind == MODEL_INTERSECTION ? CSG_INTERSECTION
                                         : CSG_UNION;
    f->first_id = b->id_count;
    f->first_ignored = b->ignored_count;
    if (is_render(n))
        enter_render(b, f);
    if (kind == MODEL_XFORM) {
        affine inverse;
        transform_frame(n, f, n->u.xform);
        if (n->not_finite) {
            /* OpenSCAD 2021.01 removes the subtree, in the render and the
             * preview alike, once its children are evaluated: the warning
             * comes when it ends (pop_frame) */
            f->emit = 0; /* still counted: the empty solid */
        } else if (f->emit && !affine_invert(&f->to_world, &inverse)) {
            /* OpenSCAD 2021.01 flattens a mesh (PolySet::transform), a
             * sheet this engine does not draw, and removes a Nef
             * polyhedron that is not empty with its own warning
             * (CGAL_Nef_polyhedron::transform) */
            const char *removal;
            if (!build_singular_removes(n, &removal))
                removal = "singular transform: subtree is empty";
            if (removal && (st = warn(b, &n->loc, "%s", removal)) != SC_OK)
                return st;
            f->emit = 0; /* still counted: the empty solid */
        }
    } else if (kind == MODEL_RESIZE) {
        build_ctx c = context(b, f->emit, NULL);
        const char *warning = NULL;
        affine m;
        if ((st = build_resize(&c, n, &b->resize_cache, &m, &warning)) != SC_OK)
            return st;
        if (warning && f->warns && (st = warn(b, &n->loc, "%s", warning)) != SC_OK)
            return st;
        transform_frame(n, f, &m);
    } else if (kind == MODEL_MOTION) {
        if ((st = build_motion_open(n, f->moving, &f->to_world, &f->motion, b->error)))
            return st;
        f->moving = 1;
    } else if (kind == MODEL_COLOR) {
        apply_color(n, f);
    } else if (kind == MODEL_MATERIAL) {
        if ((st = build_material(b->shading, n, f->emit, &f->material,
                                 f->color_set ? NULL : f->color, b->error)) != SC_OK)
            return st;
        f->color_set |= n->u.material->has_color;
    }
    *opened = 1;
    b->frame_count++;
    return SC_OK;
}

/* The last node of the model in file order: where the lowering stopped
 * when a node had an argument error (model.h). */
static const model_node *last_node(const model *m)
{
    const model_node *n = m->first;
    while (n) {
        while (n->next)
            n = n->next;
        if (!n->first_child)
            break;
        n = n->first_child;
    }
    return n;
}

/* The shading nodes at the top level (light, camera, background). */
static sc_status walk_shading(builder *b, const frame *top)
{
    sc_status st = SC_OK;
    for (const model_node *n = b->model->first; st == SC_OK && n; n = n->next) {
        if (n->modifiers & (MODEL_MOD_DISABLE | MODEL_MOD_BACKGROUND))
            continue;
        if (n->kind == MODEL_LIGHT)
            st = build_light(b->shading, n, &top->to_world, 1, b->error);
        else if (n->kind == MODEL_CAMERA)
            build_camera(b->shading, n, 1);
        else if (n->kind == MODEL_BACKGROUND)
            build_background(b->shading, n, 1);
    }
    return st;
}

/* The walk of a 2D model's top level (build_flat): the shading nodes at
 * the top level are read, the rest is the 2D engine's; an argument error
 * that ended the lowering is reported as the main walk would. */
static sc_status walk_flat(builder *b, const frame *top, uint32_t *root)
{
    sc_status st = build_flat(b, NULL, top, root);
    const model_node *last = last_node(b->model);
    if (st == SC_OK && last && last->kind == MODEL_ERROR) {
        *b->error = *last->u.error;
        return last->u.error->status;
    }
    return st == SC_OK ? walk_shading(b, top) : st;
}

/* Faithful mode: where OpenSCAD 2021.01's render unites the file's
 * objects with CGAL (its root group, a union of several) and one of them
 * takes a mesh that passes through itself, the model is CGAL's solid of
 * that union (cgal_crossing), as a union() of them would be; *whole says
 * so, and the shading nodes at the top level are read. all: the union,
 * which the id stack names until the walk ends. */
static sc_status walk_cgal(builder *b, const frame *top, model_node *all, int *whole)
{
    *whole = 0;
    if (!b->faithful || b->preview || b->model->has_root || !top->cgal ||
        build_list_dim(b->model->first, 0) != 3)
        return SC_OK;
    memset(all, 0, sizeof *all);
    all->kind = MODEL_UNION;
    all->name = "top level";
    all->loc = b->model->first->loc;
    all->first_child = b->model->first;
    for (const model_node *n = b->model->first; n; n = n->next)
        all->child_count++;
    frame state = *top;
    state.node = all;
    state.counted = 1;
    sc_status st = cgal_crossing(b, all, &state, whole);
    return st == SC_OK && *whole ? walk_shading(b, top) : st;
}

static sc_status walk(builder *b, uint32_t *root)
{
    static const float default_color[4] = BUILD_DEFAULT_COLOR;
    frame top;
    memset(&top, 0, sizeof top);
    top.op = CSG_UNION;
    top.emit = !b->model->has_root;
    top.warns = top.emit;
    top.shown = top.emit;
    top.to_world = affine_identity();
    top.since_cgal = top.to_world;
    top.cgal_world = top.to_world;
    top.cgal = to_cgal(MODEL_UNION, b->model->first);
    memcpy(top.color, default_color, sizeof top.color);
    sc_status st = push_frame(b, &top);
    if (st == SC_OK && !b->preview && !b->model->has_root &&
        build_list_dim(b->model->first, 0) == 2) {
        /* the preview draws the 2D model as it draws a 3D one: the CSG of
         * its leaves' slabs, each in its colour, with what the render
         * leaves out, and notes its parts then */
        b->flat_parts++;
        b->notes_parts = 0;
        b->flat_model = 1;
        return walk_flat(b, &top, root);
    }
    model_node all;
    int whole = 0;
    if (st == SC_OK)
        st = walk_cgal(b, &top, &all, &whole);
    const model_node *n = whole ? NULL : b->model->first;
    while (st == SC_OK) {
        if (!n) {
            if (b->frame_count == 1)
                break;
            const model_node *done = b->frames[b->frame_count - 1].node;
            st = pop_frame(b);
            n = done->next;
            continue;
        }
        if (n->modifiers & MODEL_MOD_DISABLE) {
            n = n->next; /* '*' set on the typed model (api/overlap.c) */
            continue;
        }
        int opened;
        st = visit(b, n, &opened);
        n = opened ? n->first_child : n->next;
    }
    if (st == SC_OK)
        st = flush_ignored(b, &b->frames[0]);
    if (st != SC_OK)
        return st;
    if (b->model->has_root) {
        *root = b->root_id;
        return SC_OK;
    }
    int highlighted;
    if ((st = highlight_operands(b, &b->frames[0], 1, &highlighted)) != SC_OK)
        return st;
    if (b->id_count > UINT32_MAX)
        return err_nomem(b->error, NULL);
    *root = csg_builder_op(b->csg, CSG_UNION, b->ids, (uint32_t)b->id_count);
    return csg_builder_failed(b->csg) ? err_nomem(b->error, NULL) : SC_OK;
}

/* Walks the subtree of mark into sub, a builder of its own (build_parts),
 * from the state its parent handed it, its own '%' ignored. *id is its
 * result in sub's CSG builder. */
static sc_status walk_part(builder *sub, const part_mark *mark, uint32_t *id)
{
    *id = CSG_EMPTY;
    frame top = mark->parent;
    top.node = NULL;
    top.op = CSG_UNION;
    top.emit = top.warns = top.counted = top.shown = 1;
    top.first_id = top.first_ignored = 0;
    top.negative = 0; /* a part is a product of its own */
    sub->part = mark->node;
    sub->root_id = CSG_EMPTY;
    sub->frame_count = sub->id_count = sub->ignored_count = 0;
    int opened = 0;
    sc_status st = push_frame(sub, &top);
    if (st == SC_OK)
        st = visit(sub, mark->node, &opened);
    const model_node *n = opened ? mark->node->first_child : NULL;
    /* Down to the part's own frame: popping it ends the walk. */
    while (st == SC_OK && sub->frame_count > 1) {
        if (!n) {
            const model_node *done = sub->frames[sub->frame_count - 1].node;
            st = pop_frame(sub);
            n = done->next;
            continue;
        }
        st = visit(sub, n, &opened);
        n = opened ? n->first_child : n->next;
    }
    if (st != SC_OK)
        return st;
    if (mark->node->is_root)
        *id = sub->root_id;
    else if (sub->id_count == 1)
        *id = sub->ids[0];
    return SC_OK;
}

/* Sets up sub, a builder of the preview's (its parts, its solid) for b's
 * model, with b's caches, its errors into error. */
static void preview_builder(const builder *b, builder *sub, sc_error *error)
{
    memset(sub, 0, sizeof *sub);
    sub->model = b->model;
    sub->file = b->file;
    sub->error = error;
    sub->faithful = b->faithful;
    sub->mesh_model = b->mesh_model;
    sub->max_triangles = b->max_triangles;
    sub->resize_cache = b->resize_cache;
    sub->imports = b->imports;
    sub->nefs = b->nefs;
    sub->preview = 1;
}

/* Builds the preview's modifier parts of each kind that b noted into a
 * tree (shading.overlay). A part that cannot be built is left out with a
 * warning at its node; only running out of memory fails. */
static sc_status build_parts(builder *b)
{
    static const char modifier[SHADING_OVERLAYS] = {'#', '%'};
    sc_status st = SC_OK;
    for (int kind = 0; st == SC_OK && kind < SHADING_OVERLAYS; kind++) {
        size_t count = 0;
        for (size_t k = 0; k < b->mark_count; k++)
            count += b->marks[k].kind == kind;
        if (!count)
            continue;
        sc_error error;
        builder sub;
        preview_builder(b, &sub, &error);
        /* the parts' meshes have what is left of the model's budget */
        sub.triangles_left = b->triangles_left;
        /* a '%' part is the term OpenSCAD's evaluator makes of its node, from
         * which a union with operands of both kinds has taken its
         * highlighted ones (drawn as '#' parts only): `%union() { a();
         * #b(); }` draws b red, not grey under red */
        sub.drop_highlighted = kind == SHADING_OVERLAY_BACKGROUND;
        sub.csg = csg_builder_new();
        sub.shading = shading_new();
        uint32_t *results = calloc(count, sizeof *results);
        if (!sub.csg || !sub.shading || !results)
            st = err_nomem(b->error, NULL);
        uint32_t done = 0;
        for (size_t k = 0; st == SC_OK && k < b->mark_count; k++) {
            const part_mark *m = &b->marks[k];
            if (m->kind != kind)
                continue;
            sc_status part = walk_part(&sub, m, &results[done]);
            if (part == SC_ERR_NOMEM)
                st = err_nomem(b->error, NULL);
            else if (part != SC_OK)
                st = warn(b, &m->node->loc, "'%c' subtree is left out of the preview: %s",
                          modifier[kind], error.message);
            else
                done++;
        }
        b->resize_cache = sub.resize_cache;
        b->imports = sub.imports;
        b->triangles_left = sub.triangles_left;
        free(sub.ids);
        free(sub.id_flags);
        free(sub.id_nodes);
        free(sub.frames);
        free(sub.ignored);
        free(sub.swapped);
        free(sub.warnings.items);
        shading_free(sub.shading);
        shading_slabs slabs = {sub.slabs, sub.slab_count};
        shading_renders renders = {sub.lone, sub.lone_count};
        uint32_t root = CSG_EMPTY;
        if (st == SC_OK) {
            root = csg_builder_op(sub.csg, CSG_UNION, results, done);
            if (csg_builder_failed(sub.csg))
                st = err_nomem(b->error, NULL);
        }
        free(results);
        if (st != SC_OK) {
            free(slabs.items);
            free(renders.items);
            csg_builder_free(sub.csg);
            break;
        }
        b->shading->overlay_slabs[kind] = slabs;
        b->shading->overlay_renders[kind] = renders;
        /* The builder is freed here whatever happens. */
        st = csg_builder_finish(sub.csg, root, &b->shading->overlay[kind], &error);
        if (st == SC_ERR_NOMEM)
            st = err_nomem(b->error, NULL);
        else if (st != SC_OK)
            st = warn(b, NULL, "the '%c' parts are left out of the preview: %s",
                      modifier[kind], error.message);
    }
    return st;
}

/* Builds the preview's solid (shading.preview_solid) where it differs
 * from the solid. Where a union has highlighted operands and others
 * (b->drops), OpenSCAD 2021.01's preview leaves the highlighted ones out
 * of its solid and draws them as parts only (CSGTreeEvaluator), so that
 * `cube(10); #sphere(3);` shows the sphere translucent red, not the solid
 * sphere through red. And where the render leaves out 2D objects of a 3D
 * model, or 3D objects of a 2D one (b->flat_parts), the preview draws
 * both, each 2D object as a slab (build_preview_slab). And where the
 * render's meshes and shapes are built as OpenSCAD's CGAL takes them
 * (b->cgal_built), the preview's are drawn as they are written, as
 * OpenCSG draws them (a quad out of its plane split on its own fan). The model is walked
 * again into a tree of its own, so (highlight_operands, b->preview); the
 * walk's warnings are the main walk's, and are not given again. When it
 * cannot be built, a warning says so and the preview shows the solid. */
static sc_status build_preview_solid(builder *b)
{
    if (!b->drops && !b->flat_parts && !b->renders && !b->cgal_drops &&
        !b->background_root && !b->cgal_built)
        return SC_OK;
    sc_error error;
    builder sub;
    preview_builder(b, &sub, &error);
    sub.strict = b->strict;
    sub.triangles_left = b->max_triangles; /* the same meshes as the solid's */
    sub.root_id = CSG_EMPTY;
    sub.drop_highlighted = 1;
    sub.notes_parts = b->flat_model; /* the main walk noted none */
    sub.csg = csg_builder_new();
    sub.shading = shading_new();
    uint32_t root = CSG_EMPTY;
    sc_status st = sub.csg && sub.shading ? walk(&sub, &root) : SC_ERR_NOMEM;
    b->resize_cache = sub.resize_cache;
    b->imports = sub.imports;
    if (b->flat_model) { /* its parts: none were noted */
        free(b->marks);
        b->marks = sub.marks;
        b->mark_count = sub.mark_count;
        b->mark_cap = sub.mark_cap;
        sub.marks = NULL;
    }
    free(sub.ids);
    free(sub.id_flags);
    free(sub.id_nodes);
    free(sub.frames);
    free(sub.ignored);
    free(sub.marks);
    free(sub.warnings.items);
    shading_free(sub.shading);
    if (st == SC_OK) {
        b->shading->preview_swapped = sub.swapped;
        b->shading->preview_swapped_count = sub.swapped_count;
        b->shading->preview_slabs = (shading_slabs){sub.slabs, sub.slab_count};
        b->shading->preview_renders = (shading_renders){sub.lone, sub.lone_count};
        sub.swapped = NULL;
        sub.slabs = NULL;
        sub.lone = NULL;
    }
    free(sub.swapped);
    free(sub.slabs);
    free(sub.lone);
    if (st != SC_OK || !sub.csg) {
        csg_builder_free(sub.csg);
        if (st == SC_ERR_NOMEM)
            return err_nomem(b->error, NULL);
        return warn(b, NULL, "the preview shows the render's solid: %s", error.message);
    }
    /* The builder is freed here whatever happens. */
    st = csg_builder_finish(sub.csg, root, &b->shading->preview_solid, &error);
    if (st == SC_ERR_NOMEM)
        return err_nomem(b->error, NULL);
    if (st != SC_OK)
        return warn(b, NULL, "the preview shows the render's solid: %s", error.message);
    return SC_OK;
}

/* The model's warnings of arguments (model.h), first, as OpenSCAD gives
 * them when it instantiates the tree; with --strict the first is the
 * error (an argument that is not a parameter is most often a misspelt one,
 * which leaves the part as it would be without it). */
static sc_status argument_notes(builder *b)
{
    const model_notes *notes = &b->model->notes;
    for (size_t i = 0; i < notes->count; i++) {
        const sc_error *note = &notes->items[i];
        if (b->strict) {
            *b->error = *note;
            b->error->status = SC_ERR_SEMANTIC;
            return SC_ERR_SEMANTIC;
        }
        sc_status st = warn_note(b, note);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

/* SC_ERR_LIMIT where the tree t reaches past BUILD_MAX_EXTENT from the
 * origin (or its bounds are not finite): "FILE: error: the model reaches
 * 2e+30 from the origin (limit is 1e+30)". */
static sc_status check_extent(const csg_tree *t, const char *file, sc_error *error)
{
    if (t->root == CSG_EMPTY || bbox_is_empty(&t->bounds))
        return SC_OK;
    const double c[6] = {t->bounds.lo.x, t->bounds.lo.y, t->bounds.lo.z,
                         t->bounds.hi.x, t->bounds.hi.y, t->bounds.hi.z};
    double reach = 0;
    for (int i = 0; i < 6; i++)
        if (!(fabs(c[i]) <= reach))
            reach = fabs(c[i]); /* nan too */
    if (reach <= BUILD_MAX_EXTENT)
        return SC_OK;
    sc_location loc = {file, 0, 0};
    return err_set(error, SC_ERR_LIMIT, &loc,
                   "the model reaches %g from the origin (limit is %g)", reach,
                   BUILD_MAX_EXTENT);
}

/* build_scene and build_scene_take: owned, when not NULL, is m, freed as
 * soon as the walk is done; spare (or NULL) is freed or given to the
 * builder. */
static sc_status build_scene_of(const model *m, model *owned, void *spare,
                                size_t spare_size, int flags, size_t max_triangles,
                                csg_tree **out, shading **look, sc_error **warnings,
                                size_t *warning_count, sc_error *error)
{
    *out = NULL;
    if (look)
        *look = NULL;
    *warnings = NULL;
    *warning_count = 0;
    builder b;
    memset(&b, 0, sizeof b);
    b.model = m;
    b.file = m->file;
    b.error = error;
    b.faithful = (flags & BUILD_FAITHFUL) != 0;
    b.strict = (flags & BUILD_STRICT) != 0;
    b.mesh_model = (flags & BUILD_MESH_MODEL) != 0;
    b.max_triangles = max_triangles ? max_triangles : BUILD_MAX_TRIANGLES;
    b.triangles_left = b.max_triangles;
    b.root_id = CSG_EMPTY;
    b.notes_parts = 1;
    b.csg = csg_builder_new();
    b.shading = shading_new();
    b.nefs = build_nef_cache_new();
    if (!b.csg || !b.shading || !b.nefs) {
        build_nef_cache_free(b.nefs);
        csg_builder_free(b.csg);
        shading_free(b.shading);
        model_free(owned);
        free(spare);
        return err_nomem(error, NULL);
    }
    /* Room for the model's leaves up front, in the spare buffer where it
     * serves; running out of memory here fails the builder, which the
     * walk reports as any other failure. */
    if (m->leaf_count && m->leaf_count < UINT32_MAX / 2) {
        csg_builder_give(b.csg, spare, spare_size);
        (void)csg_builder_reserve(b.csg, (uint32_t)m->leaf_count);
    } else {
        free(spare);
    }
    uint32_t root = CSG_EMPTY;
    sc_status st = argument_notes(&b);
    if (st == SC_OK)
        st = walk(&b, &root);
    free(b.ids);
    free(b.id_flags);
    free(b.id_nodes);
    free(b.frames);
    free(b.ignored);
    b.ids = NULL;
    b.id_flags = NULL;
    b.id_nodes = NULL;
    b.frames = NULL;
    b.ignored = NULL;
    /* what only the preview draws, unless the scene is not for one */
    int preview = look && !(flags & BUILD_NO_PREVIEW);
    if (st == SC_OK && preview)
        st = build_preview_solid(&b);
    if (st == SC_OK && preview)
        st = build_parts(&b);
    free(b.marks);
    free(b.swapped);
    free(b.lone);
    free(b.slabs);
    build_resize_cache_free(b.resize_cache);
    build_nef_cache_free(b.nefs);
    build_imports_free(&b.imports);
    /* Nothing below reads the model: the builder, the shading record and
     * the warnings hold copies of what they need, and the extent's error
     * the file's name. */
    char file[SC_ERROR_FILE_MAX];
    const char *named = m->file ? file : NULL;
    snprintf(file, sizeof file, "%s", m->file ? m->file : "");
    model_free(owned);
    if (st != SC_OK) {
        csg_builder_free(b.csg);
        shading_free(b.shading);
        free(b.warnings.items);
        return st;
    }
    st = csg_builder_finish(b.csg, root, out, error);
    if (st == SC_OK)
        st = check_extent(*out, named, error);
    if (st == SC_OK && look && !b.shading->flat_2d) {
        int met = 1;
        if (!csg_solid_bounds(*out, &b.shading->solid_box, &met))
            st = err_nomem(error, NULL);
        b.shading->has_solid_box = 1;
        /* OpenSCAD: "Current top level object is empty." */
        sc_location model = {b.file, 0, 0};
        if (st == SC_OK && !met && (*out)->root != CSG_EMPTY)
            st = warn(&b, &model,
                      "no ray of a search across the model's box meets the solid: its "
                      "operations leave it empty, or nearly");
    }
    if (st != SC_OK) {
        if (*out)
            csg_tree_free(*out);
        *out = NULL;
        shading_free(b.shading);
        free(b.warnings.items);
        return st;
    }
    if (look)
        *look = b.shading;
    else
        shading_free(b.shading);
    *warnings = b.warnings.items;
    *warning_count = b.warnings.count;
    return SC_OK;
}

sc_status build_scene(const model *m, int flags, size_t max_triangles, csg_tree **out,
                      shading **look, sc_error **warnings, size_t *warning_count,
                      sc_error *error)
{
    return build_scene_of(m, NULL, NULL, 0, flags, max_triangles, out, look, warnings,
                          warning_count, error);
}

sc_status build_scene_take(model *m, void *spare, size_t spare_size, int flags,
                           size_t max_triangles, csg_tree **out, shading **look,
                           sc_error **warnings, size_t *warning_count, sc_error *error)
{
    return build_scene_of(m, m, spare, spare_size, flags, max_triangles, out, look,
                          warnings, warning_count, error);
}
