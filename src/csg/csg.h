/* The compiled CSG tree and its ray queries.
 *
 * The scene builder (src/build/) describes the solid through csg_builder:
 * leaves (a primitive with its transform and colour) and boolean nodes over
 * node ids. csg_builder_finish freezes it into an immutable csg_tree: flat
 * node and leaf arrays, world bounds per node, the scene scale for
 * tolerances. The renderer only ever sees a const csg_tree.
 *
 * Queries (all reentrant; per-call memory comes from a caller-owned scratch
 * arena, which the caller resets after each pixel sample):
 *   csg_spans      ALL_SPANS: the full span list within [tmin, tmax];
 *   csg_first_hit  FIRST_HIT: the first surface crossing within [tmin, tmax];
 *   csg_any_hit    ANY_HIT: whether any surface lies within [tmin, tmax].
 * Difference and intersection evaluate their first child first and clip the
 * others to what is left; a node whose box the ray misses is skipped; a
 * union asked for the first hit narrows the rest of the ray to its first
 * entry as it goes, and one asked for any hit stops at its first blocker.
 */
#ifndef SPANCAST_CSG_CSG_H
#define SPANCAST_CSG_CSG_H

#include <stdint.h>

#include "base/arena.h"
#include "csg/prim.h"
#include "csg/span.h"
#include "math/motion.h"
#include "math/vec.h"
#include "spancast/spancast.h"

#define CSG_EMPTY UINT32_MAX /* node id of the empty solid */

typedef enum csg_op { CSG_LEAF, CSG_UNION, CSG_INTERSECTION, CSG_DIFFERENCE } csg_op;

/* A moving leaf: its world transform at ray time s in [0, 1] is
 * before . path(s) . after (a motion() node's from and to, with the
 * transforms above the node before it and those below it after it). */
typedef struct csg_motion {
    affine before, after;
    motion path;
} csg_motion;

typedef struct csg_leaf {
    prim prim;
    /* world to local: the inverse of the leaf's transform (at time 0 for a
     * moving leaf). The transform itself is not kept: the builder takes
     * the leaf's world bounds from it when the leaf is added, and nothing
     * after reads it (a leaf fewer 96 bytes, at 10^6 leaves 96 MB). */
    affine to_local;
    const csg_motion *motion; /* NULL for a leaf that stands still */
    float color[4];           /* RGBA, 0..1 */
    uint32_t object_id;       /* index of the leaf in source order, for the id AOV */
    uint32_t material;        /* index into the scene's material table; 0: the default */
    sc_location loc;          /* where the leaf was written */
} csg_leaf;

typedef struct csg_node {
    csg_op op;
    uint32_t leaf;        /* CSG_LEAF: index into leaves */
    uint32_t first_child; /* others: children are child_ids[first_child ..] */
    uint32_t child_count;
    uint32_t bvh; /* root in bvh_nodes over the union's children or the
                     difference's subtrahends; CSG_NO_BVH when none */
    bbox bounds;  /* world bounds */
    int flat;     /* CSG_UNION, CSG_INTERSECTION: takes the queries' flat path (csg.c) */
} csg_node;

#define CSG_NO_BVH UINT32_MAX

/* A node of a bounding volume hierarchy over the children of a wide union
 * (or the subtrahends of a wide difference). Depth-first layout: an
 * interior node's left child follows it, its right child is at index. */
typedef struct csg_bvh_node {
    bbox bounds;
    uint32_t index; /* interior: right child; leaf: first operand's position in
                       child_ids (a BVH reorders its node's operands) */
    uint16_t count; /* leaf: number of items; 0 for an interior node */
    uint8_t axis;   /* interior: the split axis, for near-first traversal */
} csg_bvh_node;

/* Per-thread query counters; a query adds to them when given one. */
typedef struct csg_counters {
    uint64_t queries;    /* csg_spans / csg_first_hit / csg_any_hit calls */
    uint64_t nodes;      /* tree nodes whose box was tested */
    uint64_t bvh_nodes;  /* BVH nodes whose box was tested */
    uint64_t prim_tests; /* primitive span computations */
    uint64_t span_ops;   /* boolean merges of two non-empty span lists */
} csg_counters;

typedef struct csg_tree {
    arena mem;              /* owns every array below but the owned ones */
    csg_leaf *owned_leaves; /* leaves when taken over from the builder, else NULL */
    /* nodes, child_ids and bvh_nodes when taken over from the compiler
     * (malloc'd), else NULL */
    csg_node *owned_nodes;
    uint32_t *owned_child_ids;
    csg_bvh_node *owned_bvh_nodes;
    csg_node *nodes; /* only nodes reachable from the root; children
                        before parents */
    uint32_t node_count;
    uint32_t *child_ids;
    csg_leaf *leaves;
    uint32_t leaf_count;
    csg_bvh_node *bvh_nodes;
    uint32_t bvh_node_count;
    uint32_t root;  /* CSG_EMPTY when the solid is empty */
    uint32_t depth; /* levels of boolean nodes above the deepest leaf, + 1 */
    bbox bounds;    /* world bounds of the root */
    double scale;   /* characteristic length: max of extent and |coordinates| */
    /* csg_eps's parts that depend on the tree alone, computed once: */
    vec3 eps_center;   /* the centre of bounds (the origin when empty) */
    double eps_extent; /* 1e-9 of the extent (of the scale when none) */
    double eps_near;   /* fmax(eps_extent, 2^-40 scale): csg_eps's length for
                          an origin within sqrt(eps_near2) of eps_center */
    double eps_near2;  /* squared distance below which the distance term
                          cannot win, so csg_eps needs no square root for it */
    int has_motion;    /* some leaf moves (its transform depends on the ray's time) */
    /* The tree as described, before simplification (reachable part). */
    uint32_t source_node_count, source_leaf_count, source_depth;
    /* The leaves per primitive kind and per material index
     * (material_leaves[m] for m < material_slots, in mem), counted as they
     * were made, so that statistics need not read every leaf; leaf_counts
     * is 0 where they were not kept (a tree made otherwise, a material
     * index too large to count): read the leaves then. */
    int leaf_counts;
    uint32_t kind_leaves[PRIM_KIND_COUNT];
    uint32_t *material_leaves;
    uint32_t material_slots;
} csg_tree;

/* ---- building ---- */

typedef struct csg_builder csg_builder;

csg_builder *csg_builder_new(void);
void csg_builder_free(csg_builder *b);

/* Memory that will belong to the finished tree (polyhedron planes, names).
 * Returns NULL on allocation failure. */
void *csg_builder_alloc(csg_builder *b, size_t size);

/* Makes room for leaves more leaves and their nodes at once, so that a
 * large tree's arrays are allocated once rather than grown by doubling
 * (each doubling a copy into fresh memory). Returns 1, or 0 when memory
 * ran out, which fails the builder as any allocation of it does
 * (csg_builder_failed). */
int csg_builder_reserve(csg_builder *b, uint32_t leaves);

/* Gives the builder buffer, size bytes from malloc that its caller is done
 * with (the file's text, once parsed); the builder frees it, at the latest
 * in the next csg_builder_reserve. Unless the builder has its leaves' array
 * already, csg_builder_reserve makes the array of the buffer with realloc
 * when both are at least MEM_HUGE_MIN bytes: the C
 * library keeps so large a block in a mapping of its own and moves it by
 * remapping, so the pages the buffer has touched serve the leaves instead
 * of being faulted in and cleared once more (at 10^6 leaves, 140 MB of
 * text for 330 MB of leaves). */
void csg_builder_give(csg_builder *b, void *buffer, size_t size);

/* Adds a leaf; to_world must be invertible (the builder of the scene checks
 * and flattens singular transforms itself). Returns its node id, or
 * CSG_EMPTY when the allocation failed (see csg_builder_failed). */
uint32_t csg_builder_leaf(csg_builder *b, const prim *p, const affine *to_world,
                          const float color[4], sc_location loc);

/* Sets the material index of the leaf that node id (from csg_builder_leaf)
 * names; ignores CSG_EMPTY and ids of boolean nodes. */
void csg_builder_set_material(csg_builder *b, uint32_t id, uint32_t material);

/* Adds a boolean node over children (node ids, CSG_EMPTY allowed) and
 * returns its id. Empty operands are simplified away: a union drops them, an
 * intersection with one is empty, a difference with an empty first operand
 * is empty and drops empty subtrahends; a node left with one child is that
 * child; a node with none is CSG_EMPTY. */
uint32_t csg_builder_op(csg_builder *b, csg_op op, const uint32_t *children,
                        uint32_t count);

/* Makes the leaf that node id names move (see csg_motion; to_world as
 * given to csg_builder_leaf must be its transform at time 0). Its bounds
 * then cover the whole motion. Returns 0 when m's transform is singular
 * at some sampled time. */
int csg_builder_set_motion(csg_builder *b, uint32_t id, const csg_motion *m);

/* 1 when an allocation failed since the builder was made. */
int csg_builder_failed(const csg_builder *b);

/* Compiles the tree with the given root (CSG_EMPTY for an empty solid) and
 * frees the builder in every case. Compiling simplifies: nested unions and
 * intersections are flattened into their parent, a difference whose first
 * operand is a difference takes over its operands, a union subtracted is
 * subtracted child by child, subtracted solids whose box misses the first
 * operand's box are dropped, an intersection whose boxes do not overlap is
 * empty, and empties propagate. Wide unions and differences (8 or more
 * operands) get a BVH (binned SAH) over their operands' boxes. On success *out owns the
 * tree (free with csg_tree_free). */
sc_status csg_builder_finish(csg_builder *b, uint32_t root, csg_tree **out,
                             sc_error *error);

void csg_tree_free(csg_tree *t);

/* ---- queries ---- */

typedef struct csg_ray {
    vec3 o, d; /* d need not be unit length */
    double tmin, tmax;
} csg_ray;

typedef struct csg_hit {
    double t;
    uint32_t leaf;
    uint16_t part;
    uint8_t flip;    /* the surface normal is flipped (subtracted surface) */
    uint8_t exiting; /* the ray leaves the solid here (its origin was inside) */
} csg_hit;

/* The scene-relative tolerance, in units of the ray parameter, for rays
 * from o along d: the larger of 1e-9 of the scene's extent and 2^-40 of the
 * larger of its scale and the distance from o to the scene, divided by |d|. */
double csg_eps(const csg_tree *t, vec3 o, vec3 d);

/* ALL_SPANS: the spans of the solid along the ray, clipped to [tmin, tmax]
 * (a clipped end has leaf SPAN_NO_LEAF). Memory from scratch. Returns 0 on
 * allocation failure, 1 otherwise. */
int csg_spans(const csg_tree *t, const csg_ray *r, arena *scratch, span_list *out);

/* The whole line along axis a (0, 1, 2) through the point whose a-th
 * coordinate is at and whose next two (cyclically) are u and v: the lines
 * of the measures (src/api/lines.h) and of the solid's box (bounds.h). */
csg_ray csg_axis_line(int a, double at, double u, double v);

/* csg_spans of the subtree under node id alone (at time 0). */
int csg_spans_node(const csg_tree *t, uint32_t id, const csg_ray *r, arena *scratch,
                   span_list *out);

/* FIRST_HIT: 1 and *hit when a surface crosses the ray within [tmin, tmax]. */
int csg_first_hit(const csg_tree *t, const csg_ray *r, arena *scratch, csg_hit *hit);

/* ANY_HIT: 1 when a surface crosses the ray within [tmin, tmax], the same
 * answer as csg_first_hit's (for shadow rays: something lies between the
 * point and the light). A union stops at its first operand that meets the
 * segment; only a segment that starts inside the solid needs more. */
int csg_any_hit(const csg_tree *t, const csg_ray *r, arena *scratch);

/* The same three queries, adding to *counters (which may be NULL). */
int csg_spans_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                      csg_counters *counters, span_list *out);
int csg_first_hit_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                          csg_counters *counters, csg_hit *hit);
int csg_any_hit_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                        csg_counters *counters);

/* Unit world normal at a hit, outward from the solid (flip applied). */
vec3 csg_hit_normal(const csg_tree *t, const csg_ray *r, const csg_hit *hit);

/* The queries and the normal at a time in [0, 1], which places moving
 * leaves (csg_motion); the others are these at time 0. */
int csg_spans_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                 csg_counters *counters, span_list *out);
int csg_first_hit_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                     csg_counters *counters, csg_hit *hit);
int csg_any_hit_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                   csg_counters *counters);
vec3 csg_hit_normal_at(const csg_tree *t, const csg_ray *r, double time,
                       const csg_hit *hit);

/* Point membership of the whole tree (the oracle for tests). */
int csg_inside(const csg_tree *t, vec3 p);

#endif
