/* Building the CSG tree and answering ray queries on it.
 *
 * The builder collects nodes in growable arrays (children are always built
 * before their parent, so node ids increase towards the root) and, when
 * finished, copies them into flat arrays in the tree's arena and computes
 * world bounds bottom-up: a leaf's box is its local box transformed; a union
 * bounds its children's union, an intersection their intersection, a
 * difference its first child.
 *
 * A query walks the tree recursively (its depth is bounded by the scene
 * builder's nesting limit). Each node first tests its box against the part
 * of the ray that can still matter; a leaf carries the ray into its local
 * frame without renormalising and asks its primitive for spans; boolean
 * nodes fold their children's span lists with span_combine. Intersection and
 * difference evaluate their first child first: an empty result ends the
 * node, and the other children are only tested against the stretch of ray
 * the first child occupies.
 */
#include "csg/csg.h"

#include <stdlib.h>
#include <string.h>

#include "base/error.h"

struct csg_builder {
    arena mem; /* becomes the tree's arena */
    csg_node *nodes;
    uint32_t node_count, node_cap;
    uint32_t *child_ids;
    uint32_t child_count, child_cap;
    csg_leaf *leaves;
    uint32_t leaf_count, leaf_cap;
    int failed;
};

/* Grows *array (of elem-size items, capacity *cap) to hold need items.
 * Returns 0 on overflow or allocation failure, leaving the array as it was. */
static int grow(void **array, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap)
        return 1;
    uint64_t n = *cap ? (uint64_t)*cap * 2 : 64;
    while (n < need)
        n *= 2;
    if (n > UINT32_MAX - 1 || n > SIZE_MAX / elem)
        return 0;
    void *p = realloc(*array, (size_t)n * elem);
    if (!p)
        return 0;
    *array = p;
    *cap = (uint32_t)n;
    return 1;
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
    arena_free(&b->mem);
    free(b->nodes);
    free(b->child_ids);
    free(b->leaves);
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

static uint32_t add_node(csg_builder *b, const csg_node *n)
{
    if (!grow((void **)&b->nodes, &b->node_cap, b->node_count + 1, sizeof *b->nodes)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    b->nodes[b->node_count] = *n;
    return b->node_count++;
}

uint32_t csg_builder_leaf(csg_builder *b, const prim *p, const affine *to_world,
                          const float color[4], sc_location loc)
{
    affine to_local;
    if (b->failed || !affine_invert(to_world, &to_local))
        return CSG_EMPTY;
    if (!grow((void **)&b->leaves, &b->leaf_cap, b->leaf_count + 1, sizeof *b->leaves)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    csg_leaf *l = &b->leaves[b->leaf_count];
    memset(l, 0, sizeof *l);
    l->prim = *p;
    l->to_world = *to_world;
    l->to_local = to_local;
    memcpy(l->color, color, sizeof l->color);
    l->object_id = b->leaf_count;
    l->loc = loc;
    csg_node n = {CSG_LEAF, b->leaf_count, 0, 0, bbox_empty()};
    uint32_t id = add_node(b, &n);
    if (id != CSG_EMPTY)
        b->leaf_count++;
    return id;
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
    if (!grow((void **)&b->child_ids, &b->child_cap, b->child_count + kept,
              sizeof *b->child_ids)) {
        b->failed = 1;
        return CSG_EMPTY;
    }
    uint32_t first = b->child_count;
    for (uint32_t i = 0; i < count; i++) {
        if (children[i] != CSG_EMPTY)
            b->child_ids[b->child_count++] = children[i];
    }
    csg_node n = {op, 0, first, kept, bbox_empty()};
    return add_node(b, &n);
}

/* Copies count items of size elem into the arena; NULL on failure (or when
 * count is 0, which the caller treats as "nothing to copy"). */
static void *arena_copy(arena *a, const void *src, size_t count, size_t elem)
{
    if (count == 0)
        return NULL;
    void *p = arena_calloc(a, count, elem);
    if (p)
        memcpy(p, src, count * elem);
    return p;
}

sc_status csg_builder_finish(csg_builder *b, uint32_t root, csg_tree **out,
                             sc_error *error)
{
    *out = NULL;
    if (!b)
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory");
    if (b->failed) {
        csg_builder_free(b);
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory");
    }
    csg_tree *t = calloc(1, sizeof *t);
    uint32_t *depth = calloc(b->node_count ? b->node_count : 1, sizeof *depth);
    if (!t || !depth) {
        free(t);
        free(depth);
        csg_builder_free(b);
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory");
    }
    /* Bounds and depth bottom-up: children have smaller ids. */
    for (uint32_t i = 0; i < b->node_count; i++) {
        csg_node *n = &b->nodes[i];
        if (n->op == CSG_LEAF) {
            const csg_leaf *l = &b->leaves[n->leaf];
            bbox local = prim_bounds(&l->prim);
            n->bounds = bbox_transform(&l->to_world, local);
            depth[i] = 1;
            continue;
        }
        const uint32_t *kids = &b->child_ids[n->first_child];
        bbox box = b->nodes[kids[0]].bounds;
        uint32_t d = depth[kids[0]];
        for (uint32_t k = 1; k < n->child_count; k++) {
            const csg_node *c = &b->nodes[kids[k]];
            if (n->op == CSG_UNION)
                box = bbox_union(box, c->bounds);
            else if (n->op == CSG_INTERSECTION)
                box = bbox_intersect(box, c->bounds);
            if (depth[kids[k]] > d)
                d = depth[kids[k]];
        }
        n->bounds = box;
        depth[i] = d + 1;
    }
    t->mem = b->mem;
    memset(&b->mem, 0, sizeof b->mem);
    t->node_count = b->node_count;
    t->leaf_count = b->leaf_count;
    t->nodes = arena_copy(&t->mem, b->nodes, b->node_count, sizeof *b->nodes);
    t->child_ids =
        arena_copy(&t->mem, b->child_ids, b->child_count, sizeof *b->child_ids);
    t->leaves = arena_copy(&t->mem, b->leaves, b->leaf_count, sizeof *b->leaves);
    int failed = (b->node_count && !t->nodes) || (b->child_count && !t->child_ids) ||
                 (b->leaf_count && !t->leaves);
    if (failed) { /* before anything reads the arrays that are missing */
        free(depth);
        csg_builder_free(b);
        csg_tree_free(t);
        return err_set(error, SC_ERR_NOMEM, NULL, "out of memory");
    }
    t->root = root;
    t->bounds = root == CSG_EMPTY ? bbox_empty() : t->nodes[root].bounds;
    t->depth = root == CSG_EMPTY ? 0 : depth[root];
    t->scale = 1.0;
    if (!bbox_is_empty(&t->bounds)) {
        vec3 ext = bbox_extent(&t->bounds);
        double s = fmax(v3_max_abs(ext),
                        fmax(v3_max_abs(t->bounds.lo), v3_max_abs(t->bounds.hi)));
        if (s > 0 && isfinite(s))
            t->scale = s;
    }
    free(depth);
    csg_builder_free(b);
    *out = t;
    return SC_OK;
}

void csg_tree_free(csg_tree *t)
{
    if (!t)
        return;
    arena_free(&t->mem);
    free(t);
}

/* ---- queries ---- */

typedef struct eval_ctx {
    const csg_tree *tree;
    vec3 o, d, inv_d;
    double eps;
    arena *scratch;
    int oom;
} eval_ctx;

static const span_list no_spans = {NULL, 0};

static span_list eval_leaf(eval_ctx *c, const csg_node *n)
{
    const csg_leaf *l = &c->tree->leaves[n->leaf];
    uint32_t cap = prim_max_spans(&l->prim);
    span_list r = {arena_alloc(c->scratch, (size_t)cap * sizeof(span)), 0};
    if (!r.v) {
        c->oom = 1;
        return no_spans;
    }
    vec3 o = affine_point(&l->to_local, c->o);
    vec3 d = affine_vector(&l->to_local, c->d);
    r.n = prim_spans(&l->prim, n->leaf, o, d, r.v, cap);
    r.n = span_regularize(r.v, r.n, c->eps);
    return r;
}

/* The spans of node id that matter within [tmin, tmax]; spans may extend
 * beyond that range (primitives report whole spans), callers clip. */
static span_list eval(eval_ctx *c, uint32_t id, double tmin, double tmax)
{
    const csg_node *n = &c->tree->nodes[id];
    double t0 = tmin - c->eps, t1 = tmax + c->eps;
    if (!bbox_ray(&n->bounds, c->o, c->inv_d, &t0, &t1))
        return no_spans;
    if (n->op == CSG_LEAF)
        return eval_leaf(c, n);

    const uint32_t *kids = &c->tree->child_ids[n->first_child];
    span_list acc = eval(c, kids[0], tmin, tmax);
    for (uint32_t k = 1; k < n->child_count && !c->oom; k++) {
        if (n->op == CSG_UNION) {
            acc = span_combine(SPAN_UNION, acc, eval(c, kids[k], tmin, tmax), c->eps,
                               c->scratch, &c->oom);
            continue;
        }
        if (acc.n == 0)
            break;
        /* Only where the first operand's solid lies can the others matter. */
        double lo = fmax(tmin, acc.v[0].in.t), hi = fmin(tmax, acc.v[acc.n - 1].out.t);
        span_list other = eval(c, kids[k], lo, hi);
        acc =
            span_combine(n->op == CSG_INTERSECTION ? SPAN_INTERSECTION : SPAN_DIFFERENCE,
                         acc, other, c->eps, c->scratch, &c->oom);
    }
    return c->oom ? no_spans : acc;
}

double csg_eps(const csg_tree *t, vec3 o, vec3 d)
{
    double dist = 0;
    if (!bbox_is_empty(&t->bounds)) {
        vec3 center = bbox_center(&t->bounds);
        dist = v3_length(v3_sub(o, center));
    }
    double len = v3_length(d);
    if (!(len > 0))
        len = 1;
    return 1e-9 * fmax(t->scale, dist) / len;
}

static void init_ctx(eval_ctx *c, const csg_tree *t, const csg_ray *r, arena *scratch)
{
    c->tree = t;
    c->o = r->o;
    c->d = r->d;
    c->inv_d = v3(1.0 / r->d.x, 1.0 / r->d.y, 1.0 / r->d.z);
    c->eps = csg_eps(t, r->o, r->d);
    c->scratch = scratch;
    c->oom = 0;
}

int csg_spans(const csg_tree *t, const csg_ray *r, arena *scratch, span_list *out)
{
    *out = no_spans;
    if (t->root == CSG_EMPTY || !(r->tmin <= r->tmax))
        return 1;
    eval_ctx c;
    init_ctx(&c, t, r, scratch);
    span_list all = eval(&c, t->root, r->tmin, r->tmax);
    if (c.oom)
        return 0;
    /* Clip to [tmin, tmax]; a clipped end refers to no surface. The list
     * may be shared with a leaf or child result, so write a copy. */
    uint32_t first = 0, last = all.n;
    while (first < all.n && all.v[first].out.t <= r->tmin)
        first++;
    while (last > first && all.v[last - 1].in.t >= r->tmax)
        last--;
    if (first == last)
        return 1;
    span *v = arena_alloc(scratch, (size_t)(last - first) * sizeof(span));
    if (!v)
        return 0;
    memcpy(v, all.v + first, (size_t)(last - first) * sizeof(span));
    uint32_t n = last - first;
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

int csg_first_hit(const csg_tree *t, const csg_ray *r, arena *scratch, csg_hit *hit)
{
    span_list s;
    if (!csg_spans(t, r, scratch, &s) || s.n == 0)
        return 0;
    const span_end *e = &s.v[0].in;
    int exiting = 0;
    if (e->leaf == SPAN_NO_LEAF) {
        /* The ray starts inside the solid: the first crossing is the exit. */
        e = &s.v[0].out;
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

int csg_any_hit(const csg_tree *t, const csg_ray *r, arena *scratch)
{
    csg_hit hit;
    return csg_first_hit(t, r, scratch, &hit);
}

vec3 csg_hit_normal(const csg_tree *t, const csg_ray *r, const csg_hit *hit)
{
    const csg_leaf *l = &t->leaves[hit->leaf];
    vec3 o = affine_point(&l->to_local, r->o);
    vec3 d = affine_vector(&l->to_local, r->d);
    vec3 local_n = prim_normal(&l->prim, v3_madd(o, d, hit->t), hit->part);
    vec3 n = v3_normalize(affine_vector_transposed(&l->to_local, local_n));
    return hit->flip ? v3_neg(n) : n;
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
