/* Building the CSG tree, compiling it, and answering ray queries on it.
 *
 * The builder collects nodes in growable arrays (children are always built
 * before their parent, so node ids increase towards the root). Compiling
 * (csg_builder_finish) walks the nodes reachable from the root in that
 * order, so every node sees its children already compiled, and rewrites
 * them into a simpler tree (see csg.h): world bounds bottom-up (a leaf's box
 * is its local box transformed; a union bounds its children's union, an
 * intersection their intersection, a difference its first child), nested
 * booleans of one kind flattened, empties and subtracted solids that cannot
 * touch dropped. A last pass keeps only what the new root reaches, in flat
 * arrays in the tree's arena, and builds a BVH over the operands of wide
 * nodes. Nothing here recurses on the input's nesting.
 *
 * A query walks the compiled tree recursively (its depth is what is left
 * after flattening, bounded by the scene builder's nesting limit). Each node
 * first tests its box against the part of the ray that can still matter; a
 * leaf carries the ray into its local frame without renormalising and asks
 * its primitive for spans; boolean nodes fold their children's span lists
 * with span_combine. Intersection and difference evaluate their first child
 * first: an empty result ends the node, and the other children are only
 * tested against the stretch of ray the first child occupies. Unions (and
 * the subtrahends of a difference) are visited through their BVH when they
 * have one, near side first.
 */
#include "csg/csg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "base/mem.h"
#include "csg/bvh.h"

struct csg_builder {
    arena mem; /* becomes the tree's arena */
    csg_node *nodes;
    uint32_t node_count, node_cap;
    uint32_t *child_ids;
    uint32_t child_count, child_cap;
    csg_leaf *leaves;
    uint32_t leaf_count, leaf_cap;
    void *spare; /* csg_builder_give's buffer, until the leaves take it */
    size_t spare_size;
    /* the fresh pages of the leaves' and nodes' arrays (reserved), faulted
     * in on another core while the builder fills them (mem_prefault) */
    mem_prefault *prefault[2];
    uint32_t moving; /* leaves given a motion */
    /* the leaves per kind and per material index (the tree's leaf_counts);
     * counts_lost once an index was too large to count */
    uint32_t kind_leaves[PRIM_KIND_COUNT];
    uint32_t *material_leaves; /* malloc'd, material_slots of them */
    uint32_t material_slots;
    int counts_lost;
    int failed;
};

/* Material indices counted per leaf at most (the counts of a file with more
 * materials are not kept). */
#define MATERIAL_SLOTS_MAX (1u << 20)

/* Adds delta to the leaves of material index m. */
static void count_material(csg_builder *b, uint32_t m, int delta)
{
    if (b->counts_lost)
        return;
    if (m >= b->material_slots) {
        uint32_t old = b->material_slots, cap = old;
        if (delta < 0 || m >= MATERIAL_SLOTS_MAX) {
            b->counts_lost = 1;
            return;
        }
        if (!grow_array32((void **)&b->material_leaves, &cap, m + 1,
                          sizeof *b->material_leaves)) {
            b->failed = 1; /* as for any of the builder's arrays */
            return;
        }
        memset(b->material_leaves + old, 0,
               (size_t)(cap - old) * sizeof *b->material_leaves);
        b->material_slots = cap;
    }
    b->material_leaves[m] += (uint32_t)delta;
}

/* Waits for the faulting-in of the arrays' pages: before they may move,
 * or are read. */
static void prefault_end(csg_builder *b)
{
    for (int i = 0; i < 2; i++) {
        mem_prefault_end(b->prefault[i]);
        b->prefault[i] = NULL;
    }
}

csg_builder *csg_builder_new(void)
{
    csg_builder *b = calloc(1, sizeof *b);
    if (b)
        arena_init(&b->mem, 64 * 1024);
    return b;
}

void csg_builder_free(csg_builder *b)
{
    if (!b)
        return;
    prefault_end(b);
    arena_free(&b->mem);
    free(b->nodes);
    free(b->child_ids);
    free(b->leaves);
    free(b->spare);
    free(b->material_leaves);
    free(b);
}

void *csg_builder_alloc(csg_builder *b, size_t size)
{
    void *p = arena_alloc(&b->mem, size);
    if (!p)
        b->failed = 1;
    return p;
}

int csg_builder_failed(const csg_builder *b)
{
    return b->failed;
}

int csg_builder_reserve(csg_builder *b, uint32_t leaves)
{
    /* The nodes: one per leaf, and the operations above them, which are
     * few in a large model (a sixteenth more, as room). */
    uint64_t nodes = (uint64_t)b->node_count + leaves + leaves / 16 + 16;
    uint64_t all_leaves = (uint64_t)b->leaf_count + leaves;
    size_t bytes = (size_t)all_leaves * sizeof *b->leaves; /* < 2^32 * 328 */
    prefault_end(b);
    if (!b->failed && b->spare && !b->leaves && b->spare_size >= MEM_HUGE_MIN &&
        bytes >= MEM_HUGE_MIN && all_leaves < UINT32_MAX) {
        /* The given buffer becomes the leaves' array; its bytes are
         * garbage to the leaves, each written whole when added. */
        void *p = realloc(b->spare, bytes);
        if (!p) {
            b->failed = 1;
            return 0;
        }
        b->spare = NULL;
        mem_advise_huge(p, bytes);
        b->leaves = p;
        b->leaf_cap = (uint32_t)all_leaves;
        /* the pages past the buffer's are new: faulted in on another core
         * while the builder fills the leaves from the front */
        if (bytes > b->spare_size)
            b->prefault[0] =
                mem_prefault_start((char *)p + b->spare_size, bytes - b->spare_size);
    }
    free(b->spare); /* too small to be worth keeping, or not needed */
    b->spare = NULL;
    if (b->failed || nodes >= UINT32_MAX ||
        !grow_array32((void **)&b->leaves, &b->leaf_cap, (uint32_t)all_leaves,
                      sizeof *b->leaves) ||
        !grow_array32((void **)&b->nodes, &b->node_cap, (uint32_t)nodes,
                      sizeof *b->nodes)) {
        b->failed = 1;
        return 0;
    }
    /* the room reserved, not the array's whole capacity */
    b->prefault[1] = mem_prefault_start(
        b->nodes + b->node_count, (size_t)(nodes - b->node_count) * sizeof *b->nodes);
    return 1;
}

void csg_builder_give(csg_builder *b, void *buffer, size_t size)
{
    free(b->spare);
    b->spare = buffer;
    b->spare_size = size;
}

static uint32_t add_node(csg_builder *b, const csg_node *n)
{
    if (b->node_count + 1 > b->node_cap)
        prefault_end(b); /* before the array moves */
    if (!grow_array32((void **)&b->nodes, &b->node_cap, b->node_count + 1,
                      sizeof *b->nodes)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    b->nodes[b->node_count] = *n;
    return b->node_count++;
}

static bbox world_box(const affine *w, bbox local);
static bbox motion_bounds(const csg_leaf *l);

uint32_t csg_builder_leaf(csg_builder *b, const prim *p, const affine *to_world,
                          const float color[4], sc_location loc)
{
    affine to_local;
    if (b->failed || !affine_invert(to_world, &to_local))
        return CSG_EMPTY;
    if (b->leaf_count + 1 > b->leaf_cap)
        prefault_end(b); /* before the array moves */
    if (!grow_array32((void **)&b->leaves, &b->leaf_cap, b->leaf_count + 1,
                      sizeof *b->leaves)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    csg_leaf *l = &b->leaves[b->leaf_count];
    memset(l, 0, sizeof *l);
    l->prim = *p;
    l->to_local = to_local;
    memcpy(l->color, color, sizeof l->color);
    l->object_id = b->leaf_count;
    l->loc = loc;
    csg_node n = {.op = CSG_LEAF,
                  .leaf = b->leaf_count,
                  .bvh = CSG_NO_BVH,
                  .bounds = world_box(to_world, prim_bounds(p))};
    uint32_t id = add_node(b, &n);
    if (id != CSG_EMPTY) {
        b->leaf_count++;
        if ((unsigned)p->kind < PRIM_KIND_COUNT)
            b->kind_leaves[p->kind]++;
        else
            b->counts_lost = 1;
        count_material(b, 0, 1);
    }
    return id;
}

void csg_builder_set_material(csg_builder *b, uint32_t id, uint32_t material)
{
    if (id < b->node_count && b->nodes[id].op == CSG_LEAF) {
        csg_leaf *l = &b->leaves[b->nodes[id].leaf];
        count_material(b, l->material, -1);
        count_material(b, material, 1);
        l->material = material;
    }
}

/* Samples of a motion's time taken for its bounds, and steps between two
 * of them over which a corner's path length is summed. */
#define MOTION_SAMPLES 64
#define MOTION_STEPS 4

/* The world transform of a moving leaf at time s. */
static affine motion_world(const csg_motion *m, double s)
{
    affine at = motion_at(&m->path, s);
    affine w = affine_mul(&m->before, &at);
    return affine_mul(&w, &m->after);
}

int csg_builder_set_motion(csg_builder *b, uint32_t id, const csg_motion *m)
{
    if (b->failed || id >= b->node_count || b->nodes[id].op != CSG_LEAF)
        return 1;
    for (int k = 0; k <= MOTION_SAMPLES; k++) {
        affine w = motion_world(m, (double)k / MOTION_SAMPLES), inverse;
        if (!affine_invert(&w, &inverse))
            return 0;
    }
    csg_motion *copy = csg_builder_alloc(b, sizeof *copy);
    if (!copy) {
        b->failed = 1;
        return 1;
    }
    *copy = *m;
    csg_leaf *l = &b->leaves[b->nodes[id].leaf];
    l->motion = copy;
    b->moving++;
    b->nodes[id].bounds = motion_bounds(l);
    return 1;
}

/* World bounds of a moving leaf over its whole motion: the union of its
 * boxes at MOTION_SAMPLES + 1 times, each grown by half the longest path a
 * corner of its local box takes to the next sample (summed over
 * MOTION_STEPS steps). An affine image of a box is the hull of its
 * corners' images, and a point whose path from a to b is at most L long
 * lies within L / 2 of a or of b, so every intermediate box lies inside. */
static bbox motion_bounds(const csg_leaf *l)
{
    bbox local = prim_bounds(&l->prim), out = bbox_empty();
    if (bbox_is_empty(&local))
        return local;
    for (int k = 0; k <= MOTION_SAMPLES; k++) {
        double s = (double)k / MOTION_SAMPLES;
        affine w = motion_world(l->motion, s);
        bbox box = bbox_transform(&w, local);
        double longest = 0;
        for (int c = 0; k < MOTION_SAMPLES && c < 8; c++) {
            vec3 p = v3(c & 1 ? local.hi.x : local.lo.x, c & 2 ? local.hi.y : local.lo.y,
                        c & 4 ? local.hi.z : local.lo.z);
            vec3 prev = affine_point(&w, p);
            double length = 0;
            for (int j = 1; j <= MOTION_STEPS; j++) {
                affine wj = motion_world(l->motion,
                                         s + (double)j / (MOTION_SAMPLES * MOTION_STEPS));
                vec3 next = affine_point(&wj, p);
                length += v3_length(v3_sub(next, prev));
                prev = next;
            }
            longest = fmax(longest, length);
        }
        /* 1.01: the polyline's length falls short of the arc's by a
         * relative (angle step)^2 / 24, far below 1 %. */
        vec3 pad = v3(1, 1, 1);
        box.lo = v3_sub(box.lo, v3_scale(pad, 0.505 * longest));
        box.hi = v3_add(box.hi, v3_scale(pad, 0.505 * longest));
        out = bbox_union(out, box);
    }
    return out;
}

uint32_t csg_builder_op(csg_builder *b, csg_op op, const uint32_t *children,
                        uint32_t count)
{
    if (b->failed || op == CSG_LEAF)
        return CSG_EMPTY;
    if (op == CSG_DIFFERENCE && (count == 0 || children[0] == CSG_EMPTY))
        return CSG_EMPTY;
    uint32_t kept = 0, last = CSG_EMPTY;
    for (uint32_t i = 0; i < count; i++) {
        if (children[i] == CSG_EMPTY) {
            if (op == CSG_INTERSECTION)
                return CSG_EMPTY;
            continue;
        }
        kept++;
        last = children[i];
    }
    if (kept == 0)
        return CSG_EMPTY;
    if (kept == 1)
        return last; /* for a difference, the only one kept is the first */
    if (!grow_array32((void **)&b->child_ids, &b->child_cap, b->child_count + kept,
                      sizeof *b->child_ids)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    uint32_t first = b->child_count;
    for (uint32_t i = 0; i < count; i++) {
        if (children[i] != CSG_EMPTY)
            b->child_ids[b->child_count++] = children[i];
    }
    csg_node n = {op, 0, first, kept, CSG_NO_BVH, bbox_empty(), 0};
    return add_node(b, &n);
}

/* ---- compiling ---- */

typedef struct id_vec {
    uint32_t *v;
    uint32_t n, cap;
} id_vec;

static int id_push(id_vec *a, uint32_t x)
{
    if (!grow_array32((void **)&a->v, &a->cap, a->n + 1, sizeof *a->v))
        return 0;
    a->v[a->n++] = x;
    return 1;
}

static int boxes_overlap(const bbox *a, const bbox *b)
{
    bbox i = bbox_intersect(*a, *b);
    return !bbox_is_empty(&i);
}

/* The compiled nodes before the final compaction; child lists index kids. */
typedef struct compiler {
    const csg_builder *src;
    csg_node *nodes;
    uint32_t count, cap;
    id_vec kids;
    id_vec operands; /* of the node being compiled */
    int failed;
} compiler;

static uint32_t emit(compiler *c, const csg_node *n)
{
    if (!grow_array32((void **)&c->nodes, &c->cap, c->count + 1, sizeof *c->nodes)) {
        c->failed = 1;
        return CSG_EMPTY;
    }
    c->nodes[c->count] = *n;
    return c->count++;
}

static void add_operand(compiler *c, uint32_t id)
{
    if (!id_push(&c->operands, id))
        c->failed = 1;
}

/* Adds node m as an operand, or its children when it is a node of the same
 * kind (flattening). */
static void add_flattened(compiler *c, uint32_t m, csg_op op)
{
    const csg_node *n = &c->nodes[m];
    if (n->op != op) {
        add_operand(c, m);
        return;
    }
    for (uint32_t k = 0; k < n->child_count; k++)
        add_operand(c, c->kids.v[n->first_child + k]);
}

/* Compiles boolean source node n, whose children map already gives. Returns
 * the compiled id, or CSG_EMPTY. */
static uint32_t compile_op(compiler *c, const csg_node *n, const uint32_t *map)
{
    const uint32_t *src_kids = &c->src->child_ids[n->first_child];
    c->operands.n = 0;
    bbox bounds = bbox_empty();
    if (n->op == CSG_DIFFERENCE) {
        uint32_t first = map[src_kids[0]];
        if (first == CSG_EMPTY)
            return CSG_EMPTY;
        bounds = c->nodes[first].bounds;
        add_flattened(c, first, CSG_DIFFERENCE);
        for (uint32_t k = 1; k < n->child_count; k++) {
            uint32_t m = map[src_kids[k]];
            if (m == CSG_EMPTY)
                continue;
            /* A union subtracted is its children subtracted one by one. */
            const csg_node *sub = &c->nodes[m];
            uint32_t count = sub->op == CSG_UNION ? sub->child_count : 1;
            for (uint32_t g = 0; g < count; g++) {
                uint32_t id = sub->op == CSG_UNION ? c->kids.v[sub->first_child + g] : m;
                if (boxes_overlap(&c->nodes[id].bounds, &bounds))
                    add_operand(c, id);
            }
        }
    } else {
        for (uint32_t k = 0; k < n->child_count; k++) {
            uint32_t m = map[src_kids[k]];
            if (m == CSG_EMPTY) {
                if (n->op == CSG_INTERSECTION)
                    return CSG_EMPTY;
                continue;
            }
            add_flattened(c, m, n->op);
        }
        for (uint32_t k = 0; k < c->operands.n; k++) {
            const bbox *b = &c->nodes[c->operands.v[k]].bounds;
            if (n->op == CSG_UNION)
                bounds = bbox_union(bounds, *b);
            else
                bounds = k == 0 ? *b : bbox_intersect(bounds, *b);
        }
        if (n->op == CSG_INTERSECTION && bbox_is_empty(&bounds))
            return CSG_EMPTY;
    }
    if (c->failed || c->operands.n == 0)
        return CSG_EMPTY;
    if (c->operands.n == 1)
        return c->operands.v[0];
    csg_node out = {n->op, 0, c->kids.n, c->operands.n, CSG_NO_BVH, bounds, 0};
    for (uint32_t k = 0; k < c->operands.n; k++) {
        if (!id_push(&c->kids, c->operands.v[k])) {
            c->failed = 1;
            return CSG_EMPTY;
        }
    }
    return emit(c, &out);
}

/* Marks the nodes that root reaches among count nodes whose children have
 * smaller ids than their parents; returns the number marked, or 0 on
 * allocation failure (*marks then NULL). */
static uint32_t mark_reachable(const csg_node *nodes, const uint32_t *kids,
                               uint32_t count, uint32_t root, unsigned char **marks)
{
    *marks = calloc(count ? count : 1, 1);
    if (!*marks || root == CSG_EMPTY)
        return 0;
    uint32_t reached = 0;
    (*marks)[root] = 1;
    for (uint32_t i = root + 1; i-- > 0;) {
        if (!(*marks)[i])
            continue;
        reached++;
        const csg_node *n = &nodes[i];
        if (n->op != CSG_LEAF)
            for (uint32_t k = 0; k < n->child_count; k++)
                (*marks)[kids[n->first_child + k]] = 1;
    }
    return reached;
}

/* Depth of every marked node (children first); returns the root's. */
static uint32_t depths(const csg_node *nodes, const uint32_t *kids, uint32_t count,
                       const unsigned char *marks, uint32_t *depth, uint32_t root)
{
    for (uint32_t i = 0; i < count; i++) {
        if (!marks[i])
            continue;
        const csg_node *n = &nodes[i];
        uint32_t d = 0;
        if (n->op != CSG_LEAF)
            for (uint32_t k = 0; k < n->child_count; k++)
                if (depth[kids[n->first_child + k]] > d)
                    d = depth[kids[n->first_child + k]];
        depth[i] = d + 1;
    }
    return root == CSG_EMPTY ? 0 : depth[root];
}

/* Builds the BVHs of the tree's wide nodes; returns 0 when memory ran out. */
static int build_bvhs(csg_tree *t, bvh_nodes *out)
{
    bbox *boxes = NULL;
    uint32_t boxes_cap = 0;
    for (uint32_t i = 0; i < t->node_count; i++) {
        csg_node *n = &t->nodes[i];
        uint32_t skip = n->op == CSG_DIFFERENCE ? 1 : 0;
        if ((n->op != CSG_UNION && n->op != CSG_DIFFERENCE) || n->child_count - skip < 8)
            continue;
        uint32_t count = n->child_count - skip, first = n->first_child + skip;
        if (!grow_array32((void **)&boxes, &boxes_cap, count, sizeof *boxes)) {
            free(boxes);
            return 0;
        }
        for (uint32_t k = 0; k < count; k++)
            boxes[k] = t->nodes[t->child_ids[first + k]].bounds;
        n->bvh = bvh_build(out, &t->child_ids[first], boxes, count, first);
        if (n->bvh == CSG_NO_BVH) {
            free(boxes);
            return 0;
        }
    }
    free(boxes);
    return 1;
}

/* A flat union: one without a BVH whose operands are leaves of at most
 * FLAT_LEAF_SPANS spans each, FLAT_SPANS in all (the root of a small
 * scene, a handful of bosses or ribs), or booleans of leaves alone (a
 * chamfered plate: a box cut by boxes). eval's union path for it, step for
 * step (the same box tests, merges, regularisations and narrowing, so the
 * same spans), with the leaves' and the running result's spans in local
 * arrays: no call through for_operands, and one allocation from scratch,
 * for the result, instead of three per operand. A boolean operand is
 * evaluated by eval; the recursion below stays one level deep, so the
 * local arrays sit once on the stack of a deep tree's query. Should the
 * running result outgrow FLAT_SPANS, the union starts again by the general
 * path. */
#define FLAT_LEAF_SPANS 2
#define FLAT_SPANS 16

static int is_flat_union(const csg_tree *t, const csg_node *n)
{
    if (n->bvh != CSG_NO_BVH)
        return 0;
    const uint32_t *ids = &t->child_ids[n->first_child];
    uint32_t total = 0;
    for (uint32_t k = 0; k < n->child_count; k++) {
        const csg_node *child = &t->nodes[ids[k]];
        if (child->op != CSG_LEAF) {
            const uint32_t *below = &t->child_ids[child->first_child];
            for (uint32_t j = 0; j < child->child_count; j++)
                if (t->nodes[below[j]].op != CSG_LEAF)
                    return 0;
            continue;
        }
        uint32_t cap = prim_max_spans(&t->leaves[child->leaf].prim);
        if (cap > FLAT_LEAF_SPANS)
            return 0;
        total += cap;
    }
    return total <= FLAT_SPANS;
}

/* Whether a leaf's spans depend on the ray alone: the convex kinds, whose
 * prim_spans ignores the range and the mode (only a mesh's walk uses
 * them), spends no budget and gives at most one span. */
static int memo_kind(prim_kind kind)
{
    return kind == PRIM_SPHERE || kind == PRIM_BOX || kind == PRIM_CYLINDER ||
           kind == PRIM_CONVEX;
}

/* A flat intersection: one without a BVH whose operands are all convex
 * leaves (a chamfered plate: a box cut by rotated boxes; a rounded boss:
 * a sphere cut by a box). Its result is at most one span, which the
 * queries compute in place (eval_convex_cut). */
static int is_flat_intersection(const csg_tree *t, const csg_node *n)
{
    if (n->bvh != CSG_NO_BVH)
        return 0;
    const uint32_t *ids = &t->child_ids[n->first_child];
    for (uint32_t k = 0; k < n->child_count; k++) {
        const csg_node *child = &t->nodes[ids[k]];
        if (child->op != CSG_LEAF || !memo_kind(t->leaves[child->leaf].prim.kind))
            return 0;
    }
    return 1;
}

/* Marks the unions and intersections that take the flat paths, once: the
 * queries test the mark instead of walking the operands of every node
 * they meet. Runs after build_bvhs, since a node with a BVH is never
 * flat. */
static void mark_flat_unions(csg_tree *t)
{
    for (uint32_t i = 0; i < t->node_count; i++) {
        csg_node *n = &t->nodes[i];
        n->flat = n->op == CSG_UNION          ? is_flat_union(t, n)
                  : n->op == CSG_INTERSECTION ? is_flat_intersection(t, n)
                                              : 0;
    }
}

/* Takes a malloc'd array, shrunk to count elements of size elem; NULL
 * when shrinking fails (an allocation failure like any other:
 * tests/fault_alloc.c), and then *v is freed. */
static void *take_array(void **v, size_t count, size_t elem)
{
    void *p = realloc(*v, count * elem);
    if (!p)
        free(*v);
    *v = NULL;
    return p;
}

/* Counts leaf l, copied into tree t, in t's kinds and in materials (the
 * tree's material counts, the builder's size; NULL when it has none). */
static void count_copied(csg_tree *t, uint32_t *materials, const csg_builder *b,
                         const csg_leaf *l)
{
    if ((unsigned)l->prim.kind < PRIM_KIND_COUNT)
        t->kind_leaves[l->prim.kind]++;
    if (materials && l->material < b->material_slots)
        materials[l->material]++;
}

/* Freezes the compiled nodes that root reaches into t, taking the
 * builder's leaves; returns 0 when memory ran out. Every array is written
 * once, in its final place: a million leaves of 368 bytes copied through
 * two temporaries made loading a million spheres touch three times their
 * size. When the tree keeps every leaf in source order (the usual case: a
 * leaf is dropped only when simplification removes it), the builder's own
 * array becomes the tree's, shrunk to size, and nothing is copied. In the
 * same way, when root reaches every compiled node (nothing was left
 * behind by flattening), the compiled nodes and child lists keep their
 * places and become the tree's, and so does the BVH's array: at 10^6
 * leaves, 150 MB neither copied nor touched for the first time. */
static int freeze(csg_tree *t, compiler *c, csg_builder *b, uint32_t root)
{
    unsigned char *marks;
    uint32_t reached = mark_reachable(c->nodes, c->kids.v, c->count, root, &marks);
    uint32_t *renumber = calloc(c->count ? c->count : 1, sizeof *renumber);
    int ok = marks && renumber;
    /* Sizes first, so that each array is allocated once. */
    size_t kid_total = 0;
    uint32_t leaf_total = 0;
    int in_order = 1;
    for (uint32_t i = 0; ok && i < c->count; i++) {
        if (!marks[i])
            continue;
        const csg_node *n = &c->nodes[i];
        if (n->op == CSG_LEAF)
            in_order &= n->leaf == leaf_total++;
        else
            kid_total += n->child_count;
    }
    in_order &= leaf_total == b->leaf_count;
    /* Every compiled node kept, each at its own index. */
    int whole = ok && reached == c->count && kid_total == c->kids.n;
    csg_node *nodes = NULL;
    uint32_t *kids = NULL;
    csg_leaf *leaves = NULL;
    if (ok && reached && whole) {
        ok = (nodes = take_array((void **)&c->nodes, reached, sizeof *nodes)) != NULL;
        t->owned_nodes = nodes;
    } else if (ok && reached) {
        ok = (nodes = arena_alloc(&t->mem, (size_t)reached * sizeof *nodes)) != NULL;
    }
    if (ok && kid_total && whole) {
        ok = (kids = take_array((void **)&c->kids.v, kid_total, sizeof *kids)) != NULL;
        t->owned_child_ids = kids;
    } else if (ok && kid_total) {
        ok = kid_total <= UINT32_MAX &&
             (kids = arena_calloc(&t->mem, kid_total, sizeof *kids)) != NULL;
    }
    if (ok && leaf_total) {
        if (in_order) {
            /* Shrinking can fail too; an allocation failure is one, whatever
             * it was for (tests/fault_alloc.c). */
            leaves = realloc(b->leaves, (size_t)leaf_total * sizeof *leaves);
            ok = leaves != NULL;
            if (ok)
                b->leaves = NULL;
            t->owned_leaves = leaves;
        } else {
            ok = (leaves = arena_calloc(&t->mem, leaf_total, sizeof *leaves)) != NULL;
        }
    }
    /* The leaves' counts: the builder's when every leaf is kept in order,
     * else those of the leaves copied. */
    uint32_t *materials = NULL;
    int counted = ok && !b->counts_lost;
    if (counted && b->material_slots)
        ok = counted = (materials = arena_calloc(&t->mem, b->material_slots,
                                                 sizeof *materials)) != NULL;
    if (counted && in_order) {
        memcpy(t->kind_leaves, b->kind_leaves, sizeof t->kind_leaves);
        if (b->material_slots)
            memcpy(materials, b->material_leaves, b->material_slots * sizeof *materials);
    }
    uint32_t count = 0, leaf_count = 0, kid_count = 0;
    for (uint32_t i = 0; ok && whole && i < reached; i++) {
        /* In place: the numbering and the child lists stay as they are. */
        csg_node *n = &nodes[i];
        if (n->op == CSG_LEAF) {
            if (!in_order) {
                leaves[leaf_count] = b->leaves[n->leaf];
                count_copied(t, materials, b, &leaves[leaf_count]);
            }
            n->leaf = leaf_count++;
        }
        renumber[i] = count++;
    }
    for (uint32_t i = 0; ok && !whole && i < c->count; i++) {
        if (!marks[i])
            continue;
        csg_node n = c->nodes[i];
        if (n.op == CSG_LEAF) {
            if (!in_order) {
                leaves[leaf_count] = b->leaves[n.leaf];
                count_copied(t, materials, b, &leaves[leaf_count]);
            }
            n.leaf = leaf_count++;
        } else {
            uint32_t first = kid_count;
            for (uint32_t k = 0; k < n.child_count; k++)
                kids[kid_count++] = renumber[c->kids.v[n.first_child + k]];
            n.first_child = first;
        }
        renumber[i] = count;
        nodes[count++] = n;
    }
    /* The builder's leaves are no longer needed (those kept are copied or
     * taken), nor are the compiled nodes: free them before the BVHs. */
    free(b->leaves);
    b->leaves = NULL;
    free(c->nodes);
    c->nodes = NULL;
    free(c->kids.v);
    c->kids.v = NULL;
    free(marks);
    bvh_nodes bvh = {NULL, 0, 0};
    if (ok) {
        t->root = root == CSG_EMPTY ? CSG_EMPTY : renumber[root];
        t->node_count = count;
        t->leaf_count = leaf_count;
        t->nodes = nodes;
        t->child_ids = kids;
        t->leaves = leaves;
        t->leaf_counts = counted;
        t->material_leaves = counted ? materials : NULL;
        t->material_slots = counted ? b->material_slots : 0;
    }
    free(renumber);
    if (ok)
        ok = build_bvhs(t, &bvh);
    if (ok)
        mark_flat_unions(t);
    if (ok) {
        uint32_t *depth = calloc(count ? count : 1, sizeof *depth);
        unsigned char *all = malloc(count ? count : 1);
        ok = depth && all;
        if (ok) {
            memset(all, 1, count ? count : 1);
            t->depth = depths(nodes, kids, count, all, depth, t->root);
        }
        free(depth);
        free(all);
    }
    if (ok && bvh.count) {
        t->bvh_nodes = t->owned_bvh_nodes =
            take_array((void **)&bvh.v, bvh.count, sizeof *bvh.v);
        t->bvh_node_count = bvh.count;
        ok = t->bvh_nodes != NULL;
    }
    free(bvh.v);
    return ok;
}

/* The world box of a finite local box under w: on each axis, the sum of
 * each column's smaller (larger) product with the box's two extents, plus
 * the translation (Arvo, Graphics Gems 1990). This is the box of the
 * eight transformed corners bit for bit: every term depends on one
 * coordinate only, rounded products and sums are monotonic, so the corner
 * that takes each term's minimum also takes the minimum of the rounded
 * sum, added in the same order as affine_point. A box that is empty or
 * not finite goes the corners' way, whose 0 * inf terms it keeps. */
static bbox world_box(const affine *w, bbox local)
{
    double ext[6] = {local.lo.x, local.lo.y, local.lo.z,
                     local.hi.x, local.hi.y, local.hi.z};
    for (int k = 0; k < 6; k++) {
        if (!isfinite(ext[k]))
            return bbox_transform(w, local);
    }
    if (bbox_is_empty(&local))
        return local;
    double lo[3], hi[3];
    for (int i = 0; i < 3; i++) {
        double sum_lo = 0, sum_hi = 0;
        for (int j = 0; j < 3; j++) {
            double a = w->m[i][j] * ext[j], b = w->m[i][j] * ext[j + 3];
            double small = a < b ? a : b, large = a < b ? b : a;
            sum_lo = j ? sum_lo + small : small;
            sum_hi = j ? sum_hi + large : large;
        }
        lo[i] = sum_lo + w->m[i][3];
        hi[i] = sum_hi + w->m[i][3];
    }
    bbox r = {v3(lo[0], lo[1], lo[2]), v3(hi[0], hi[1], hi[2])};
    return r;
}

/* Source statistics of the builder's nodes (a leaf's world bounds were set
 * when it was added). */
static int measure_source(csg_builder *b, uint32_t root, csg_tree *t)
{
    unsigned char *marks;
    t->source_node_count =
        mark_reachable(b->nodes, b->child_ids, b->node_count, root, &marks);
    uint32_t *depth = calloc(b->node_count ? b->node_count : 1, sizeof *depth);
    int ok = marks && depth;
    if (ok) {
        t->source_depth =
            depths(b->nodes, b->child_ids, b->node_count, marks, depth, root);
        for (uint32_t i = 0; i < b->node_count; i++)
            t->source_leaf_count += marks[i] && b->nodes[i].op == CSG_LEAF;
    }
    free(marks);
    free(depth);
    return ok;
}

static int compile(csg_builder *b, uint32_t root, csg_tree *t)
{
    if (!measure_source(b, root, t))
        return 0;
    /* The compiled nodes are written over the source ones, in place: node
     * i is read before the compiled node it makes is written, at an index
     * no greater than i (a source node makes one compiled node at most),
     * and a boolean node reads only its operands' compiled nodes, written
     * before it. The source's child lists stay apart. */
    compiler c = {b, b->nodes, 0, b->node_cap, {NULL, 0, 0}, {NULL, 0, 0}, 0};
    b->nodes = NULL;
    uint32_t *map = malloc((b->node_count ? b->node_count : 1) * sizeof *map);
    unsigned char *marks;
    mark_reachable(c.nodes, b->child_ids, b->node_count, root, &marks);
    int ok = map && marks;
    uint32_t new_root = CSG_EMPTY;
    for (uint32_t i = 0; ok && i < b->node_count; i++) {
        map[i] = CSG_EMPTY;
        if (!marks[i])
            continue;
        csg_node n = c.nodes[i];
        map[i] = n.op == CSG_LEAF ? emit(&c, &n) : compile_op(&c, &n, map);
        ok = !c.failed;
    }
    if (ok && root != CSG_EMPTY)
        new_root = map[root];
    free(map);
    free(marks);
    /* The source child lists are compiled: free them before the tree is
     * frozen. */
    free(b->child_ids);
    b->child_ids = NULL;
    ok = ok && freeze(t, &c, b, new_root);
    free(c.nodes);
    free(c.kids.v);
    free(c.operands.v);
    return ok;
}

/* The parts of csg_eps (below) that depend on the tree alone. With
 * near = fmax(eps_extent, 2^-40 scale), the distance term 2^-40 dist wins
 * over near only where dist > 2^40 near (the product by a power of two is
 * exact). sqrt is correctly rounded and monotonic, and sqrt(fl(D * D)) is
 * D for every D whose square is a finite normal number, so
 * dist2 <= fl(D * D) gives sqrt(dist2) <= D: then csg_eps's value is near
 * bit for bit, whatever its square root would have been. Any other D
 * turns the test off (-1); an empty tree's distance is 0 and its value is
 * near everywhere. */
static void eps_prepare(csg_tree *t)
{
    double extent = t->scale;
    t->eps_center = v3(0, 0, 0);
    if (!bbox_is_empty(&t->bounds)) {
        t->eps_center = bbox_center(&t->bounds);
        double e = v3_max_abs(bbox_extent(&t->bounds));
        if (e > 0 && isfinite(e))
            extent = e;
    }
    t->eps_extent = 1e-9 * extent;
    t->eps_near = fmax(t->eps_extent, 0x1p-40 * t->scale);
    double reach = 0x1p40 * t->eps_near, reach2 = reach * reach;
    int normal = isfinite(reach2) && reach2 >= 0x1p-1022;
    t->eps_near2 = bbox_is_empty(&t->bounds) ? INFINITY : normal ? reach2 : -1;
}

sc_status csg_builder_finish(csg_builder *b, uint32_t root, csg_tree **out,
                             sc_error *error)
{
    *out = NULL;
    if (!b)
        return err_nomem(error, NULL);
    csg_tree *t = b->failed ? NULL : calloc(1, sizeof *t);
    if (!t) {
        csg_builder_free(b);
        return err_nomem(error, NULL);
    }
    prefault_end(b); /* its threads are done by now */
    uint32_t moving = b->moving;
    t->mem = b->mem;
    memset(&b->mem, 0, sizeof b->mem);
    int ok = compile(b, root, t);
    csg_builder_free(b);
    if (!ok) {
        csg_tree_free(t);
        return err_nomem(error, NULL);
    }
    t->bounds = t->root == CSG_EMPTY ? bbox_empty() : t->nodes[t->root].bounds;
    /* a pass over every leaf only when some leaf moves (10^6 leaves: 232 MB) */
    for (uint32_t i = 0; moving && i < t->leaf_count; i++)
        t->has_motion |= t->leaves[i].motion != NULL;
    t->scale = 1.0;
    if (!bbox_is_empty(&t->bounds)) {
        vec3 ext = bbox_extent(&t->bounds);
        double s = fmax(v3_max_abs(ext),
                        fmax(v3_max_abs(t->bounds.lo), v3_max_abs(t->bounds.hi)));
        if (s > 0 && isfinite(s))
            t->scale = s;
    }
    eps_prepare(t);
    *out = t;
    return SC_OK;
}

void csg_tree_free(csg_tree *t)
{
    if (!t)
        return;
    arena_free(&t->mem);
    free(t->owned_leaves);
    free(t->owned_nodes);
    free(t->owned_child_ids);
    free(t->owned_bvh_nodes);
    free(t);
}

/* ---- queries ---- */

typedef enum eval_mode {
    EVAL_ALL,   /* the node's spans, complete within the range */
    EVAL_FIRST, /* correct up to the first crossing after the range start */
    EVAL_ANY    /* stop as soon as the solid is seen inside the range */
} eval_mode;

/* A leaf's regularised spans, kept for the rest of a query (see
 * leaf_spans). */
#define LEAF_MEMO 16 /* entries, a power of two; leaf l goes to l % LEAF_MEMO */

typedef struct leaf_memo {
    uint32_t leaf;
    uint32_t n;
    span v[1];
} leaf_memo;

typedef struct eval_ctx {
    const csg_tree *tree;
    vec3 o, d, inv_d;
    double time; /* the ray's, for moving leaves */
    double eps;
    arena *scratch;
    csg_counters *counters; /* never NULL inside a query */
    int oom;
    int blocked;        /* EVAL_ANY found the solid in the range: BLOCKED_AT or _START */
    uint32_t memo_full; /* bit k: memo[k] holds a leaf's spans */
    leaf_memo memo[LEAF_MEMO];
} eval_ctx;

static const span_list no_spans = {NULL, 0};

/* The query recursion goes as deep as the tree (10000 levels on a render
 * thread's stack), so the rarer paths below stay out of the frames of
 * eval and eval_cut: the compiler would otherwise inline them there and
 * every level would pay for their locals. */
#if defined(__GNUC__)
#define COLD_PATH __attribute__((noinline))
#define INLINE_PATH inline __attribute__((always_inline))
#else
#define COLD_PATH
#define INLINE_PATH inline
#endif

/* A leaf's world-to-local transform at time: its own, or for a moving leaf
 * the inverse of its transform then, in *scratch. csg_builder_set_motion
 * checked that it is invertible at every sampled time; a time between
 * samples where it were not leaves the ray in world coordinates, which
 * the leaf's bounds already contain. */
static const affine *leaf_to_local(const csg_leaf *l, double time, affine *scratch)
{
    if (!l->motion)
        return &l->to_local;
    affine w = motion_world(l->motion, fmin(1.0, fmax(0.0, time)));
    if (!affine_invert(&w, scratch))
        return &l->to_local;
    return scratch;
}

static span_list eval(eval_ctx *c, uint32_t id, double lo, double hi, eval_mode mode);

/* The ray o + t d in the local frame of moving leaf l at time: out of
 * eval's frame (COLD_PATH), since the transform it builds would cost every
 * level of the recursion its size. */
static COLD_PATH void moving_leaf_ray(const csg_leaf *l, double time, vec3 o, vec3 d,
                                      vec3 *lo, vec3 *ld)
{
    affine moved;
    const affine *to_local = leaf_to_local(l, time, &moved);
    *lo = affine_point(to_local, o);
    *ld = affine_vector(to_local, d);
}

/* The regularised spans of leaf n's primitive over [lo, hi] into out, which
 * has room for its prim_max_spans; returns their count. A query may ask
 * for one leaf several times (a difference asked for its first crossing
 * evaluates its first operand once to find where to look, then again in
 * a window there); a convex leaf's spans are a function of the query's
 * ray, time and eps, so the first answer is kept in c->memo and copied on
 * the next request, the same spans without the primitive test. */
static uint32_t leaf_spans(eval_ctx *c, const csg_node *n, double lo, double hi,
                           eval_mode mode, span *out, uint32_t cap)
{
    const csg_leaf *l = &c->tree->leaves[n->leaf];
    uint32_t slot = n->leaf & (LEAF_MEMO - 1);
    leaf_memo *m = &c->memo[slot];
    int memo = memo_kind(l->prim.kind);
    if (memo && (c->memo_full >> slot & 1) && m->leaf == n->leaf) {
        if (m->n)
            out[0] = m->v[0];
        return m->n;
    }
    vec3 o, d;
    if (l->motion) {
        moving_leaf_ray(l, c->time, c->o, c->d, &o, &d);
    } else {
        o = affine_point(&l->to_local, c->o);
        d = affine_vector(&l->to_local, c->d);
    }
    c->counters->prim_tests++;
    uint32_t count = prim_spans_range(&l->prim, n->leaf, o, d, lo, hi, c->eps,
                                      mode != EVAL_ALL, out, cap);
    /* One span (every convex leaf's) regularises to itself or to nothing. */
    if (count == 1)
        count = out[0].out.t - out[0].in.t > c->eps;
    else
        count = span_regularize(out, count, c->eps);
    if (memo && count <= 1) {
        c->memo_full |= 1u << slot;
        m->leaf = n->leaf;
        m->n = count;
        if (count)
            m->v[0] = out[0];
    }
    return count;
}

static span_list eval_leaf(eval_ctx *c, const csg_node *n, double lo, double hi,
                           eval_mode mode)
{
    uint32_t cap = prim_max_spans(&c->tree->leaves[n->leaf].prim);
    span_list r = {arena_alloc(c->scratch, (size_t)cap * sizeof(span)), 0};
    if (!r.v) {
        c->oom = 1;
        return no_spans;
    }
    r.n = leaf_spans(c, n, lo, hi, mode, r.v, cap);
    return r;
}

/* What EVAL_ANY found: an operand of a union (of the root, or of a union
 * below it: the mode passes through unions alone) with solid in the range,
 * and whether that solid holds the range start. Then so does the root: a
 * union holds what its operands hold, and its regularisation drops only
 * spans no longer than eps, which an operand's regularised span is not. */
enum { BLOCKED_AT = 1, BLOCKED_START = 2 };

static int blocker(span_list s, double lo, double hi)
{
    for (uint32_t k = 0; k < s.n; k++)
        if (s.v[k].out.t > lo && s.v[k].in.t < hi)
            return s.v[k].in.t <= lo ? BLOCKED_START : BLOCKED_AT;
    return 0;
}

/* Frees everything allocated in scratch since mark except the list r,
 * which moves to mark. A boolean's inputs die once it has combined them,
 * but a bump arena keeps them: a ray through n nested shells made every
 * level keep its own copy of the list below it, n^2 spans in all (1.6 GB
 * at 10000 levels). Moving the result down keeps one live list per level
 * of recursion, linear in the tree. Correct because r (the only survivor)
 * was allocated after mark or is not in scratch at all, so the copy's
 * destination lies at or before its source, or elsewhere: memmove. */
static span_list keep(eval_ctx *c, arena_mark mark, span_list r)
{
    arena_restore(c->scratch, mark);
    if (r.n == 0)
        return no_spans;
    span *v = arena_alloc(c->scratch, (size_t)r.n * sizeof(span));
    if (!v) {
        c->oom = 1;
        return no_spans;
    }
    memmove(v, r.v, (size_t)r.n * sizeof(span));
    r.v = v;
    return r;
}

static span_list combine(eval_ctx *c, span_op op, span_list a, span_list b)
{
    c->counters->span_ops += a.n && b.n;
    return span_combine(op, a, b, c->eps, c->scratch, &c->oom);
}

typedef struct union_state {
    span_list acc;
    eval_mode mode;
    int narrowed;     /* EVAL_FIRST moved hi to the running first entry */
    arena_mark start; /* scratch before the first operand (see keep) */
} union_state;

/* The first span of s that reaches past lo, or NULL. */
static const span *first_after(span_list s, double lo)
{
    for (uint32_t k = 0; k < s.n; k++)
        if (s.v[k].out.t > lo)
            return &s.v[k];
    return NULL;
}

/* Adds operand id to a union's running result. In EVAL_ANY mode a blocker
 * ends the query. In EVAL_FIRST mode, while the range start lies outside
 * the union, *hi narrows to the union's first entry: later operands can
 * only move that entry closer. (If a later operand puts the range start
 * inside, the first crossing is an exit, which operands beyond the narrowed
 * range can move; eval then evaluates the union again in full.) */
static int visit_union(eval_ctx *c, void *state, uint32_t id, double *lo, double *hi)
{
    union_state *u = state;
    span_list s = eval(c, id, *lo, *hi, u->mode == EVAL_ANY ? EVAL_ANY : EVAL_ALL);
    if (c->blocked || c->oom)
        return 0;
    if (u->mode == EVAL_ANY && (c->blocked = blocker(s, *lo, *hi)))
        return 0;
    u->acc = keep(c, u->start, combine(c, SPAN_UNION, u->acc, s));
    if (c->oom)
        return 0;
    const span *first = u->mode == EVAL_FIRST ? first_after(u->acc, *lo) : NULL;
    if (first && first->in.t >= *lo && first->in.t < *hi) {
        *hi = first->in.t;
        u->narrowed = 1;
    }
    return 1;
}

/* The regularised union of acc's count spans and s into acc (room for
 * FLAT_SPANS), merged as scratch; returns the new count. Both lists are
 * regularised already (leaf_spans and every boolean regularise, and a
 * regularised list is its own regularisation), so when s lies wholly
 * after or wholly before acc with a gap longer than eps, the merge would
 * only lay them end to end and the regularisation would change nothing:
 * the two are joined without either. */
static uint32_t union_into(span *acc, uint32_t count, span_list s, double eps,
                           span *merged)
{
    if (s.v[0].in.t - acc[count - 1].out.t > eps) {
        memcpy(acc + count, s.v, s.n * sizeof(span));
        return count + s.n;
    }
    if (acc[0].in.t - s.v[s.n - 1].out.t > eps) {
        memmove(acc + s.n, acc, count * sizeof(span));
        memcpy(acc, s.v, s.n * sizeof(span));
        return count + s.n;
    }
    count = span_merge(SPAN_UNION, (span_list){acc, count}, s, merged);
    count = span_regularize(merged, count, eps);
    memcpy(acc, merged, count * sizeof(span));
    return count;
}

/* One pass of the flat union over [lo, hi] in mode (EVAL_ALL, EVAL_FIRST
 * or EVAL_ANY, as visit_union), its result in acc (room for FLAT_SPANS);
 * returns its count, 0 with c->blocked set when EVAL_ANY met a blocker,
 * or with c->oom set, or with *overflow set when the result would not fit.
 * *narrowed as union_state's. */
static uint32_t flat_union_pass(eval_ctx *c, const csg_node *n, double lo, double hi,
                                eval_mode mode, span *acc, int *narrowed, int *overflow)
{
    const uint32_t *ids = &c->tree->child_ids[n->first_child];
    eval_mode operand_mode = mode == EVAL_ANY ? EVAL_ANY : EVAL_ALL;
    span leaf[FLAT_LEAF_SPANS], merged[FLAT_SPANS];
    uint32_t count = 0;
    *narrowed = 0;
    for (uint32_t k = 0; k < n->child_count; k++) {
        const csg_node *child = &c->tree->nodes[ids[k]];
        arena_mark mark = arena_save(c->scratch);
        span_list s = {leaf, 0};
        if (child->op == CSG_LEAF) {
            c->counters->nodes++;
            double t0 = lo - c->eps, t1 = hi + c->eps;
            if (!bbox_ray(&child->bounds, c->o, c->inv_d, &t0, &t1))
                continue;
            /* The first operand with spans writes them in place. */
            s.v = count == 0 ? acc : leaf;
            s.n = leaf_spans(c, child, lo, hi, operand_mode, s.v, FLAT_LEAF_SPANS);
        } else {
            s = eval(c, ids[k], lo, hi, operand_mode);
            if (c->oom || c->blocked)
                return 0;
        }
        if (mode == EVAL_ANY && (c->blocked = blocker(s, lo, hi)))
            return 0;
        if (s.n == 0) {
            arena_restore(c->scratch, mark);
            continue;
        }
        if (count + s.n > FLAT_SPANS) {
            arena_restore(c->scratch, mark);
            *overflow = 1;
            return 0;
        }
        if (count == 0) {
            if (s.v != acc)
                memcpy(acc, s.v, s.n * sizeof(span));
            count = s.n;
        } else {
            c->counters->span_ops++;
            count = union_into(acc, count, s, c->eps, merged);
        }
        arena_restore(c->scratch, mark); /* s, if eval's, is copied */
        const span *first =
            mode == EVAL_FIRST ? first_after((span_list){acc, count}, lo) : NULL;
        if (first && first->in.t >= lo && first->in.t < hi) {
            hi = first->in.t;
            *narrowed = 1;
        }
    }
    return count;
}

/* Sets *out to the flat union's spans and returns 1, or returns 0 when
 * they outgrew FLAT_SPANS (the caller takes the general path). Kept out of
 * eval's frame (COLD_PATH): inlined there, its arrays would cost every
 * level of a deep tree's recursion (test_limits' 10000 levels overflowed
 * the stack). */
static COLD_PATH int eval_flat_union(eval_ctx *c, const csg_node *n, double lo, double hi,
                                     eval_mode mode, span_list *out)
{
    span acc[FLAT_SPANS];
    int narrowed, overflow = 0;
    *out = no_spans;
    uint32_t count = flat_union_pass(c, n, lo, hi, mode, acc, &narrowed, &overflow);
    const span *first = narrowed ? first_after((span_list){acc, count}, lo) : NULL;
    if (first && first->in.t < lo)
        count = flat_union_pass(c, n, lo, hi, EVAL_ALL, acc, &narrowed, &overflow);
    if (overflow)
        return 0;
    if (count == 0)
        return 1;
    span_list r = {arena_alloc(c->scratch, count * sizeof(span)), count};
    if (!r.v) {
        c->oom = 1;
        return 1;
    }
    memcpy(r.v, acc, count * sizeof(span));
    *out = r;
    return 1;
}

/* Visits the operands of n held by its BVH (or, without one, the listed
 * operands from index skip on) that the ray's [lo, hi] can meet, near side
 * first, calling visit until it returns 0. */
typedef int (*operand_visit)(eval_ctx *c, void *state, uint32_t id, double *lo,
                             double *hi);

/* for_operands through n's BVH. */
static INLINE_PATH void walk_operands(eval_ctx *c, const csg_node *n, double lo,
                                      double hi, operand_visit visit, void *state)
{
    const uint32_t *ids = c->tree->child_ids;
    uint32_t stack[BVH_MAX_DEPTH];
    uint32_t sp = 0;
    stack[sp++] = n->bvh;
    const double *dir = &c->d.x;
    while (sp > 0) {
        const csg_bvh_node *b = &c->tree->bvh_nodes[stack[--sp]];
        c->counters->bvh_nodes++;
        double t0 = lo - c->eps, t1 = hi + c->eps;
        if (!bbox_ray(&b->bounds, c->o, c->inv_d, &t0, &t1))
            continue;
        if (b->count) {
            for (uint32_t k = 0; k < b->count; k++)
                if (!visit(c, state, ids[b->index + k], &lo, &hi))
                    return;
            continue;
        }
        uint32_t near = (uint32_t)(b - c->tree->bvh_nodes) + 1, far = b->index;
        if (dir[b->axis] < 0) {
            uint32_t swap = near;
            near = far;
            far = swap;
        }
        stack[sp++] = far;
        stack[sp++] = near;
    }
}

static int visit_cut(eval_ctx *c, void *state, uint32_t id, double *lo, double *hi);

/* The BVH walks, one per visitor, which each inlines. Each has its own
 * frame (COLD_PATH, though they are not rare): the walk's stack of
 * BVH_MAX_DEPTH entries then sits in the query recursion only at the
 * nodes that have a BVH, not in the frames of eval and eval_cut at every
 * level of a deep tree. */
static COLD_PATH void walk_union_operands(eval_ctx *c, const csg_node *n, double lo,
                                          double hi, void *state)
{
    walk_operands(c, n, lo, hi, visit_union, state);
}

static COLD_PATH void walk_cut_operands(eval_ctx *c, const csg_node *n, double lo,
                                        double hi, void *state)
{
    walk_operands(c, n, lo, hi, visit_cut, state);
}

static INLINE_PATH void for_operands(eval_ctx *c, const csg_node *n, uint32_t skip,
                                     double lo, double hi, operand_visit visit,
                                     void *state)
{
    if (n->bvh != CSG_NO_BVH) {
        if (visit == visit_union)
            walk_union_operands(c, n, lo, hi, state);
        else
            walk_cut_operands(c, n, lo, hi, state);
        return;
    }
    const uint32_t *ids = c->tree->child_ids;
    for (uint32_t k = skip; k < n->child_count; k++)
        if (!visit(c, state, ids[n->first_child + k], &lo, &hi))
            return;
}

typedef struct cut_state {
    span_list acc;
    span_op op;
    arena_mark start; /* scratch before the first operand (see keep) */
} cut_state;

/* Whether the spans of b lie wholly before or after those of a, apart by
 * a gap: subtracting b then gives a itself (a regularised list is its own
 * regularisation). A tie is not apart: the sweep would take b's exit as
 * the result's entry. */
static int apart(span_list a, span_list b)
{
    return b.v[b.n - 1].out.t < a.v[0].in.t || b.v[0].in.t > a.v[a.n - 1].out.t;
}

/* Subtracts convex leaf n (a hole, a slot) from acc over [lo, hi], tested
 * into a local span first: when it misses, or lies beside acc, acc stands
 * as it is, without the copy that combining and keeping it would cost.
 * Out of the recursion's frames (COLD_PATH), as eval's rarer paths. */
static COLD_PATH span_list subtract_leaf(eval_ctx *c, const csg_node *n, span_list acc,
                                         arena_mark start, double lo, double hi)
{
    c->counters->nodes++;
    double t0 = lo - c->eps, t1 = hi + c->eps;
    if (!bbox_ray(&n->bounds, c->o, c->inv_d, &t0, &t1))
        return acc;
    span one[1];
    span_list b = {one, leaf_spans(c, n, lo, hi, EVAL_ALL, one, 1)};
    if (b.n == 0 || apart(acc, b))
        return acc;
    return keep(c, start, combine(c, SPAN_DIFFERENCE, acc, b));
}

/* Intersects or subtracts operand id; narrows [lo, hi] to what is left. */
static int visit_cut(eval_ctx *c, void *state, uint32_t id, double *lo, double *hi)
{
    cut_state *s = state;
    const csg_node *n = &c->tree->nodes[id];
    if (s->op == SPAN_DIFFERENCE && n->op == CSG_LEAF &&
        memo_kind(c->tree->leaves[n->leaf].prim.kind))
        s->acc = subtract_leaf(c, n, s->acc, s->start, *lo, *hi);
    else
        s->acc =
            keep(c, s->start, combine(c, s->op, s->acc, eval(c, id, *lo, *hi, EVAL_ALL)));
    if (c->oom || s->acc.n == 0)
        return 0;
    *lo = fmax(*lo, s->acc.v[0].in.t);
    *hi = fmin(*hi, s->acc.v[s->acc.n - 1].out.t);
    return 1;
}

/* A difference of a few subtrahends from a wide union (one with a BVH)
 * evaluates its subtrahends first: where they lie, the union's operands
 * need not be visited at all. A ray through a cut-away corner of a block
 * of n^3 spheres otherwise walks every sphere in the corner. */
static int cuts_first(const eval_ctx *c, const csg_node *n)
{
    if (n->op != CSG_DIFFERENCE || n->bvh != CSG_NO_BVH || n->child_count > 5)
        return 0;
    const csg_node *a = &c->tree->nodes[c->tree->child_ids[n->first_child]];
    return a->op == CSG_UNION && a->bvh != CSG_NO_BVH;
}

/* The union of n's subtrahends within [lo, hi], clipped to where the first
 * operand's box lies along the ray. */
COLD_PATH static span_list subtrahends(eval_ctx *c, const csg_node *n, double lo,
                                       double hi)
{
    const uint32_t *ids = &c->tree->child_ids[n->first_child];
    double a0 = lo - c->eps, a1 = hi + c->eps;
    if (!bbox_ray(&c->tree->nodes[ids[0]].bounds, c->o, c->inv_d, &a0, &a1))
        return no_spans;
    lo = fmax(lo, a0);
    hi = fmin(hi, a1);
    arena_mark start = arena_save(c->scratch);
    span_list cut = no_spans;
    for (uint32_t k = 1; k < n->child_count && !c->oom; k++)
        cut = keep(c, start,
                   combine(c, SPAN_UNION, cut, eval(c, ids[k], lo, hi, EVAL_ALL)));
    return c->oom ? no_spans : cut;
}

/* The next free stretch of [lo, hi] outside the spans of cut (sorted,
 * disjoint), from stretch *k on: 1 and its ends, or 0 when there is none.
 * Stretches of no length are skipped, except for a range of no length (a
 * membership query at one point). */
static int free_stretch(span_list cut, double lo, double hi, uint32_t *k, double *f0,
                        double *f1)
{
    while (*k <= cut.n) {
        double a = *k == 0 ? lo : fmax(lo, cut.v[*k - 1].out.t);
        double b = *k == cut.n ? hi : fmin(hi, cut.v[*k].in.t);
        (*k)++;
        if (a < b || (a == b && lo == hi)) {
            *f0 = a;
            *f1 = b;
            return 1;
        }
    }
    return 0;
}

/* The part of s within [a, b], in new scratch memory when an end moves; a
 * moved end refers to no surface (it lies inside a subtrahend). */
static span_list clip_list(eval_ctx *c, span_list s, double a, double b)
{
    uint32_t first = 0, last = s.n;
    while (first < s.n && s.v[first].out.t <= a)
        first++;
    while (last > first && s.v[last - 1].in.t >= b)
        last--;
    if (first == last)
        return no_spans;
    span_list out = {s.v + first, last - first};
    if (out.v[0].in.t >= a && out.v[out.n - 1].out.t <= b)
        return out;
    span *v = arena_alloc(c->scratch, (size_t)out.n * sizeof(span));
    if (!v) {
        c->oom = 1;
        return no_spans;
    }
    memcpy(v, out.v, (size_t)out.n * sizeof(span));
    span_end none = {0, SPAN_NO_LEAF, 0, 0};
    if (v[0].in.t < a) {
        v[0].in = none;
        v[0].in.t = a;
    }
    if (v[out.n - 1].out.t > b) {
        v[out.n - 1].out = none;
        v[out.n - 1].out.t = b;
    }
    out.v = v;
    return out;
}

/* Difference n over [lo, hi] by cuts_first: the subtrahends in full, the
 * first operand only on the stretches they leave free (its spans there are
 * those of the whole; inside the subtrahends nothing of it survives). */
COLD_PATH static span_list eval_cut_free(eval_ctx *c, const csg_node *n, double lo,
                                         double hi)
{
    arena_mark start = arena_save(c->scratch);
    span_list cut = subtrahends(c, n, lo, hi);
    uint32_t first = c->tree->child_ids[n->first_child];
    span_list acc = no_spans;
    uint32_t k = 0;
    double f0, f1;
    while (!c->oom && free_stretch(cut, lo, hi, &k, &f0, &f1)) {
        /* Evaluated over its stretch only, the first operand may show solid
         * beyond it that is not there (its own subtrahends were not asked
         * there). Inside the cut that is harmless, but a later stretch
         * would take it up: cut each result half an eps into the cut. */
        double a = f0 > lo ? f0 - 0.5 * c->eps : -INFINITY;
        double b = f1 < hi ? f1 + 0.5 * c->eps : INFINITY;
        span_list part = clip_list(c, eval(c, first, f0, f1, EVAL_ALL), a, b);
        acc = combine(c, SPAN_UNION, acc, part);
    }
    if (c->oom)
        return no_spans;
    return keep(c, start, combine(c, SPAN_DIFFERENCE, acc, cut));
}

/* Intersection or difference n over [lo, hi], given its first operand's
 * spans there (from scratch mark start on, or before it): the others only
 * where the first lies. */
static span_list cut_operands(eval_ctx *c, const csg_node *n, span_list first,
                              arena_mark start, double lo, double hi)
{
    cut_state s = {first, n->op == CSG_INTERSECTION ? SPAN_INTERSECTION : SPAN_DIFFERENCE,
                   start};
    if (c->oom || s.acc.n == 0)
        return no_spans;
    /* Only where the first operand's solid lies can the others matter. */
    double first_lo = fmax(lo, s.acc.v[0].in.t);
    double first_hi = fmin(hi, s.acc.v[s.acc.n - 1].out.t);
    for_operands(c, n, 1, first_lo, first_hi, visit_cut, &s);
    return c->oom ? no_spans : s.acc;
}

/* A flat intersection n over [lo, hi] (is_flat_intersection): eval_cut's
 * steps, box test for box test and leaf for leaf, with the running span in
 * place of a list in scratch. Each step is span_combine's intersection of
 * two single spans (span_intersect_pair); then the range narrows to it, as
 * visit_cut's does. */
static COLD_PATH span_list eval_convex_cut(eval_ctx *c, const csg_node *n, double lo,
                                           double hi)
{
    const uint32_t *ids = &c->tree->child_ids[n->first_child];
    span acc, b;
    for (uint32_t k = 0; k < n->child_count; k++) {
        const csg_node *child = &c->tree->nodes[ids[k]];
        c->counters->nodes++;
        double t0 = lo - c->eps, t1 = hi + c->eps;
        if (!bbox_ray(&child->bounds, c->o, c->inv_d, &t0, &t1))
            return no_spans;
        if (!leaf_spans(c, child, lo, hi, EVAL_ALL, k ? &b : &acc, 1))
            return no_spans;
        if (k > 0) {
            c->counters->span_ops++;
            const span_end *in, *out;
            if (!span_intersect_pair(&acc, &b, c->eps, &in, &out))
                return no_spans;
            acc = (span){*in, *out};
        }
        lo = fmax(lo, acc.in.t);
        hi = fmin(hi, acc.out.t);
    }
    span_list r = {arena_alloc(c->scratch, sizeof(span)), 1};
    if (!r.v) {
        c->oom = 1;
        return no_spans;
    }
    r.v[0] = acc;
    return r;
}

/* Intersection or difference n over [lo, hi]: the first operand in full,
 * the others only where it lies. */
static span_list eval_cut(eval_ctx *c, const csg_node *n, double lo, double hi)
{
    if (n->flat)
        return eval_convex_cut(c, n, lo, hi);
    if (cuts_first(c, n))
        return eval_cut_free(c, n, lo, hi);
    arena_mark start = arena_save(c->scratch);
    span_list first = eval(c, c->tree->child_ids[n->first_child], lo, hi, EVAL_ALL);
    return cut_operands(c, n, first, start, lo, hi);
}

/* The first crossing after lo of a span list, or INFINITY. */
static double first_crossing(span_list s, double lo)
{
    const span *f = first_after(s, lo);
    return !f ? INFINITY : f->in.t >= lo ? f->in.t : f->out.t;
}

/* The part of a window's result from the first operand's first entry on.
 * Before that entry the result is empty, but a window's evaluation may show
 * solid there (operands cut only within the window); a span reaching over
 * the entry starts at it, on the first operand's surface. */
static span_list from_entry(eval_ctx *c, span_list r, const span_end *entry)
{
    uint32_t k = 0;
    while (k < r.n && r.v[k].out.t <= entry->t)
        k++;
    if (k == r.n)
        return no_spans;
    if (k == 0 && r.v[0].in.t >= entry->t)
        return r;
    span_list out = {arena_alloc(c->scratch, (size_t)(r.n - k) * sizeof(span)), r.n - k};
    if (!out.v) {
        c->oom = 1;
        return no_spans;
    }
    memcpy(out.v, r.v + k, (size_t)out.n * sizeof(span));
    if (out.v[0].in.t < entry->t)
        out.v[0].in = *entry;
    return out;
}

/* Intersection or difference n asked for its first crossing: rather than
 * its whole first operand along the ray, it evaluates growing windows
 * [start, start + step], doubling step, until the window holds a crossing.
 * The result is exact within a window, so a crossing found inside it is
 * the first one. The first window starts where the first operand (asked for
 * its own first crossing, which a union finds cheaply) begins: before that
 * the result is empty. With a BVH below, the cost follows the solids near
 * the first hit instead of every solid along the ray. */
static span_list eval_cut_first_free(eval_ctx *c, const csg_node *n, double lo,
                                     double hi);

static COLD_PATH span_list eval_cut_first(eval_ctx *c, const csg_node *n, double lo,
                                          double hi, int plain)
{
    if (!plain && cuts_first(c, n))
        return eval_cut_first_free(c, n, lo, hi);
    /* A first operand that is one leaf, or a flat union or intersection,
     * costs about as much in full as asked for its first crossing: it is
     * evaluated once, in full, and each window cuts its spans there,
     * rather than evaluating it again per window. */
    const csg_node *first = &c->tree->nodes[c->tree->child_ids[n->first_child]];
    int whole = first->op == CSG_LEAF || first->flat;
    span_list a = eval(c, c->tree->child_ids[n->first_child], lo, hi,
                       whole ? EVAL_ALL : EVAL_FIRST);
    const span *f = first_after(a, lo);
    if (c->oom || !f)
        return no_spans;
    span_end entry = f->in;
    int outside = entry.t > lo; /* the ray starts outside the first operand */
    double start = outside ? entry.t : lo;
    double step = fmax(f->out.t - start, 16 * c->eps);
    arena_mark mark = arena_save(c->scratch);
    for (;;) {
        double end = fmin(hi, start + step);
        span_list r =
            whole ? cut_operands(c, n, a, mark, start, end) : eval_cut(c, n, start, end);
        if (outside)
            r = from_entry(c, r, &entry);
        if (c->oom || end >= hi || first_crossing(r, lo) < end - c->eps)
            return r;
        step *= 2;
    }
}

/* eval_cut_first for a difference by cuts_first: every crossing of the
 * result lies on a free stretch (or at its ends), so the first stretch
 * that holds one holds the first. */
COLD_PATH static span_list eval_cut_first_free(eval_ctx *c, const csg_node *n, double lo,
                                               double hi)
{
    arena_mark start = arena_save(c->scratch);
    span_list cut = subtrahends(c, n, lo, hi);
    uint32_t k = 0;
    double f0, f1;
    while (!c->oom && free_stretch(cut, lo, hi, &k, &f0, &f1)) {
        /* A stretch that starts where a subtrahend ends, with the first
         * operand solid there, has its first crossing right at the start:
         * a ray onto a cut face. eval_cut_first would find it only after
         * asking the first operand for its first crossing from inside,
         * which is its exit (every solid along the ray, to the far side of
         * a block of n^3 spheres), and a first window as long as that. A
         * short window, exact within itself as eval_cut_first's are, finds
         * it at the cost of the solids near the start. */
        if (f0 > lo) {
            double end = fmin(f1, f0 + 64 * c->eps);
            arena_mark probe = arena_save(c->scratch);
            span_list r = eval_cut(c, n, f0, end);
            if (c->oom)
                return no_spans;
            if (first_crossing(r, f0) < end - c->eps)
                return keep(c, start, r);
            arena_restore(c->scratch, probe);
        }
        span_list r = eval_cut_first(c, n, f0, f1, 1);
        if (c->oom)
            return no_spans;
        if (first_crossing(r, f0) <= f1)
            return keep(c, start, r);
    }
    arena_restore(c->scratch, start);
    return no_spans;
}

/* The spans of node id that matter within [lo, hi]; spans may extend beyond
 * that range (primitives report whole spans), callers clip. */
static span_list eval(eval_ctx *c, uint32_t id, double lo, double hi, eval_mode mode)
{
    const csg_node *n = &c->tree->nodes[id];
    c->counters->nodes++;
    double t0 = lo - c->eps, t1 = hi + c->eps;
    if (!bbox_ray(&n->bounds, c->o, c->inv_d, &t0, &t1))
        return no_spans;
    if (n->op == CSG_LEAF)
        return eval_leaf(c, n, lo, hi, mode);
    if (n->op == CSG_UNION) {
        span_list flat;
        if (n->flat && eval_flat_union(c, n, lo, hi, mode, &flat))
            return flat;
        union_state u = {no_spans, mode, 0, arena_save(c->scratch)};
        for_operands(c, n, 0, lo, hi, visit_union, &u);
        const span *first = u.narrowed ? first_after(u.acc, lo) : NULL;
        if (first && first->in.t < lo) {
            u.acc = keep(c, u.start, no_spans);
            u.mode = EVAL_ALL;
            for_operands(c, n, 0, lo, hi, visit_union, &u);
        }
        return c->oom ? no_spans : u.acc;
    }
    /* Beyond its box the node is empty: no window need reach further. */
    if (mode != EVAL_FIRST)
        return eval_cut(c, n, lo, hi);
    arena_mark start = arena_save(c->scratch);
    return keep(c, start, eval_cut_first(c, n, lo, fmin(hi, t1), 0));
}

/* Two parts, in length units. The resolution: 1e-9 of the solid's extent,
 * the size below which coincident faces fuse and slivers vanish. The
 * rounding: a coordinate of magnitude X (the scene far from the origin, or
 * the ray's origin far from the scene) carries errors of a few ulps of X,
 * which tied surfaces must also absorb; 2^-40 of X is 8192 ulps, room for a
 * chain of roundings and a ray at a shallow angle. Both terms used to be
 * 1e-9 (9e6 ulps): a part of size 1 moved to 1e8, or seen from 1e9 away,
 * then lost every feature below 0.1 or 1 unit, which double precision
 * resolves down to 1e-8 (tests/test_stability.c, translation and far
 * camera). The extent falls back to the scale for a solid of no extent. */
double csg_eps(const csg_tree *t, vec3 o, vec3 d)
{
    double len = v3_length(d);
    if (!(len > 0))
        len = 1;
    /* Within eps_near2 of the centre (every shadow and secondary ray of a
     * scene seen from nearby) the distance term loses to the others and
     * needs no square root; eps_prepare says why the test is exact. */
    double dist2 = v3_dot(v3_sub(o, t->eps_center), v3_sub(o, t->eps_center));
    if (dist2 <= t->eps_near2)
        return t->eps_near / len;
    double dist = bbox_is_empty(&t->bounds) ? 0 : sqrt(dist2);
    return fmax(t->eps_extent, 0x1p-40 * fmax(t->scale, dist)) / len;
}

/* Runs a query from the root; returns 0 on allocation failure. */
static int run_node(const csg_tree *t, uint32_t id, const csg_ray *r, double time,
                    arena *scratch, csg_counters *counters, eval_mode mode,
                    span_list *out, int *blocked)
{
    csg_counters unused = {0, 0, 0, 0, 0};
    eval_ctx c;
    c.tree = t;
    c.o = r->o;
    c.d = r->d;
    c.time = time;
    c.inv_d = v3(1.0 / r->d.x, 1.0 / r->d.y, 1.0 / r->d.z);
    c.eps = csg_eps(t, r->o, r->d);
    c.scratch = scratch;
    c.counters = counters ? counters : &unused;
    c.oom = 0;
    c.blocked = 0;
    c.memo_full = 0;
    c.counters->queries++;
    *out = no_spans;
    *blocked = 0;
    if (id == CSG_EMPTY || !(r->tmin <= r->tmax))
        return 1;
    *out = eval(&c, id, r->tmin, r->tmax, mode);
    *blocked = c.blocked;
    return !c.oom;
}

static int run(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
               csg_counters *counters, eval_mode mode, span_list *out, int *blocked)
{
    return run_node(t, t->root, r, time, scratch, counters, mode, out, blocked);
}

/* Clips a root span list to [tmin, tmax] into new scratch memory (the list
 * may be shared with a leaf or child result); a clipped end refers to no
 * surface. Returns 0 on allocation failure. */
static int clip(span_list all, const csg_ray *r, arena *scratch, span_list *out)
{
    *out = no_spans;
    uint32_t first = 0, last = all.n;
    while (first < all.n && all.v[first].out.t <= r->tmin)
        first++;
    while (last > first && all.v[last - 1].in.t >= r->tmax)
        last--;
    if (first == last)
        return 1;
    uint32_t n = last - first;
    span *v = arena_alloc(scratch, (size_t)n * sizeof(span));
    if (!v)
        return 0;
    memcpy(v, all.v + first, (size_t)n * sizeof(span));
    if (v[0].in.t < r->tmin) {
        v[0].in.t = r->tmin;
        v[0].in.leaf = SPAN_NO_LEAF;
        v[0].in.part = 0;
        v[0].in.flip = 0;
    }
    if (v[n - 1].out.t > r->tmax) {
        v[n - 1].out.t = r->tmax;
        v[n - 1].out.leaf = SPAN_NO_LEAF;
        v[n - 1].out.part = 0;
        v[n - 1].out.flip = 0;
    }
    out->v = v;
    out->n = n;
    return 1;
}

int csg_spans_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                 csg_counters *counters, span_list *out)
{
    span_list all;
    int blocked;
    *out = no_spans;
    return run(t, r, time, scratch, counters, EVAL_ALL, &all, &blocked) &&
           clip(all, r, scratch, out);
}

int csg_spans_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                      csg_counters *counters, span_list *out)
{
    return csg_spans_at(t, r, 0, scratch, counters, out);
}

csg_ray csg_axis_line(int a, double at, double u, double v)
{
    double o[3];
    o[a] = at;
    o[(a + 1) % 3] = u;
    o[(a + 2) % 3] = v;
    csg_ray r;
    r.o = v3(o[0], o[1], o[2]);
    r.d = v3(a == 0, a == 1, a == 2);
    r.tmin = -INFINITY;
    r.tmax = INFINITY;
    return r;
}

int csg_spans(const csg_tree *t, const csg_ray *r, arena *scratch, span_list *out)
{
    return csg_spans_counted(t, r, scratch, NULL, out);
}

int csg_spans_node(const csg_tree *t, uint32_t id, const csg_ray *r, arena *scratch,
                   span_list *out)
{
    span_list all;
    int blocked;
    *out = no_spans;
    return run_node(t, id, r, 0, scratch, NULL, EVAL_ALL, &all, &blocked) &&
           clip(all, r, scratch, out);
}

/* The first span of clip(all, r), without the copy: 1 and *out, or 0
 * when the clipped list is empty. Only the last span of the clipped list
 * can reach past tmax, and a span before another ends before that one's
 * entry (below tmax), so the first span's exit is clipped exactly when it
 * lies beyond tmax. */
static int first_clipped(span_list all, const csg_ray *r, span *out)
{
    uint32_t first = 0;
    while (first < all.n && all.v[first].out.t <= r->tmin)
        first++;
    if (first == all.n || all.v[first].in.t >= r->tmax)
        return 0;
    *out = all.v[first];
    span_end none = {0, SPAN_NO_LEAF, 0, 0};
    if (out->in.t < r->tmin) {
        out->in = none;
        out->in.t = r->tmin;
    }
    if (out->out.t > r->tmax) {
        out->out = none;
        out->out.t = r->tmax;
    }
    return 1;
}

int csg_first_hit_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                     csg_counters *counters, csg_hit *hit)
{
    span_list all;
    span s;
    int blocked;
    if (!run(t, r, time, scratch, counters, EVAL_FIRST, &all, &blocked) ||
        !first_clipped(all, r, &s))
        return 0;
    const span_end *e = &s.in;
    int exiting = 0;
    if (e->leaf == SPAN_NO_LEAF) {
        /* The ray starts inside the solid: the first crossing is the exit. */
        e = &s.out;
        exiting = 1;
        if (e->leaf == SPAN_NO_LEAF)
            return 0;
    }
    hit->t = e->t;
    hit->leaf = e->leaf;
    hit->part = e->part;
    hit->flip = e->flip;
    hit->exiting = (uint8_t)exiting;
    return 1;
}

int csg_first_hit_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                          csg_counters *counters, csg_hit *hit)
{
    return csg_first_hit_at(t, r, 0, scratch, counters, hit);
}

int csg_first_hit(const csg_tree *t, const csg_ray *r, arena *scratch, csg_hit *hit)
{
    return csg_first_hit_counted(t, r, scratch, NULL, hit);
}

int csg_any_hit_at(const csg_tree *t, const csg_ray *r, double time, arena *scratch,
                   csg_counters *counters)
{
    span_list all;
    int blocked;
    if (!run(t, r, time, scratch, counters, EVAL_ANY, &all, &blocked))
        return 0;
    if (!blocked)
        blocked = blocker(all, r->tmin, r->tmax);
    if (!blocked)
        return 0;
    /* The solid meets the segment. From a start outside it, that means a
     * surface lies in between; from a start inside (a shadow ray from the
     * inner face of a glass solid, on the side the ray came from), only if
     * the segment gets out. Membership at the start needs only the
     * operands around it, unless the blocker already holds the start. */
    int inside = blocked == BLOCKED_START;
    if (!inside) {
        csg_ray start = *r;
        start.tmax = r->tmin;
        if (!run(t, &start, time, scratch, counters, EVAL_ALL, &all, &blocked))
            return 0;
        for (uint32_t k = 0; k < all.n && !inside; k++)
            inside = all.v[k].in.t <= r->tmin && all.v[k].out.t > r->tmin;
        if (!inside)
            return 1;
    }
    csg_hit hit;
    return csg_first_hit_at(t, r, time, scratch, counters, &hit);
}

int csg_any_hit_counted(const csg_tree *t, const csg_ray *r, arena *scratch,
                        csg_counters *counters)
{
    return csg_any_hit_at(t, r, 0, scratch, counters);
}

int csg_any_hit(const csg_tree *t, const csg_ray *r, arena *scratch)
{
    return csg_any_hit_counted(t, r, scratch, NULL);
}

vec3 csg_hit_normal_at(const csg_tree *t, const csg_ray *r, double time,
                       const csg_hit *hit)
{
    const csg_leaf *l = &t->leaves[hit->leaf];
    affine moved;
    const affine *to_local = leaf_to_local(l, time, &moved);
    vec3 o = affine_point(to_local, r->o);
    vec3 d = affine_vector(to_local, r->d);
    vec3 local_n = prim_normal(&l->prim, v3_madd(o, d, hit->t), hit->part);
    vec3 n = v3_normalize(affine_vector_transposed(to_local, local_n));
    return hit->flip ? v3_neg(n) : n;
}

vec3 csg_hit_normal(const csg_tree *t, const csg_ray *r, const csg_hit *hit)
{
    return csg_hit_normal_at(t, r, 0, hit);
}

static int inside_node(const csg_tree *t, uint32_t id, vec3 p)
{
    const csg_node *n = &t->nodes[id];
    if (n->op == CSG_LEAF) {
        const csg_leaf *l = &t->leaves[n->leaf];
        return prim_inside(&l->prim, affine_point(&l->to_local, p));
    }
    const uint32_t *kids = &t->child_ids[n->first_child];
    int first = inside_node(t, kids[0], p);
    for (uint32_t k = 1; k < n->child_count; k++) {
        switch (n->op) {
        case CSG_UNION:
            if (first)
                return 1;
            first = inside_node(t, kids[k], p);
            break;
        case CSG_INTERSECTION:
            if (!first)
                return 0;
            first = inside_node(t, kids[k], p);
            break;
        default: /* difference */
            if (!first)
                return 0;
            if (inside_node(t, kids[k], p))
                return 0;
            break;
        }
    }
    return first;
}

int csg_inside(const csg_tree *t, vec3 p)
{
    return t->root != CSG_EMPTY && inside_node(t, t->root, p);
}
