/* Binned-SAH BVH construction: see bvh.h. */
#include "csg/bvh.h"

#include <omp.h>
#include <stdlib.h>
#include <string.h>

enum { BINS = 16, LEAF_SIZE = 4, SAH_DEPTH = 40 };

/* Box arithmetic inline: building over 10^6 operands spends its time here
 * (the out-of-line bbox_union with its fmin/fmax calls took a quarter of
 * loading a million spheres). Empty boxes (lo > hi) stay empty. */
static inline double min2(double a, double b)
{
    return a < b ? a : b;
}

static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

static inline void box_grow(bbox *acc, const bbox *b)
{
    acc->lo.x = min2(acc->lo.x, b->lo.x);
    acc->lo.y = min2(acc->lo.y, b->lo.y);
    acc->lo.z = min2(acc->lo.z, b->lo.z);
    acc->hi.x = max2(acc->hi.x, b->hi.x);
    acc->hi.y = max2(acc->hi.y, b->hi.y);
    acc->hi.z = max2(acc->hi.z, b->hi.z);
}

static inline void box_add(bbox *acc, vec3 p)
{
    acc->lo.x = min2(acc->lo.x, p.x);
    acc->lo.y = min2(acc->lo.y, p.y);
    acc->lo.z = min2(acc->lo.z, p.z);
    acc->hi.x = max2(acc->hi.x, p.x);
    acc->hi.y = max2(acc->hi.y, p.y);
    acc->hi.z = max2(acc->hi.z, p.z);
}

static inline bbox box_none(void)
{
    bbox b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    return b;
}

static double half_area(const bbox *b)
{
    if (!(b->lo.x <= b->hi.x && b->lo.y <= b->hi.y && b->lo.z <= b->hi.z))
        return 0;
    double x = b->hi.x - b->lo.x, y = b->hi.y - b->lo.y, z = b->hi.z - b->lo.z;
    return x * y + y * z + z * x;
}

/* Makes room for more nodes past out->count, doubling at least. A
 * hierarchy over n operands has at most 2n - 1 nodes; reserving that once
 * keeps the build from growing its array by realloc as it goes, which at a
 * million operands copied the nodes built so far again and again (an
 * eighth of loading a million spheres). Room never written costs no
 * memory: arrays this large are mapped, and their pages come on first
 * touch. Returns 0 when memory ran out. */
static int reserve_nodes(bvh_nodes *out, uint64_t more)
{
    uint64_t need = (uint64_t)out->count + more;
    if (need <= out->cap)
        return 1;
    if (need > UINT32_MAX)
        need = UINT32_MAX;
    uint64_t cap = (uint64_t)out->cap * 2;
    if (cap < need)
        cap = need;
    if (cap > UINT32_MAX)
        cap = UINT32_MAX;
    if (cap <= out->cap)
        return 0;
    csg_bvh_node *v = realloc(out->v, (size_t)cap * sizeof *v);
    if (!v)
        return 0;
    out->v = v;
    out->cap = (uint32_t)cap;
    return 1;
}

static uint32_t push_node(bvh_nodes *out)
{
    if (out->count == out->cap && !reserve_nodes(out, 1))
        return CSG_NO_BVH;
    memset(&out->v[out->count], 0, sizeof out->v[0]);
    return out->count++;
}

static void swap_items(uint32_t *ids, bbox *boxes, uint32_t i, uint32_t j)
{
    uint32_t t = ids[i];
    ids[i] = ids[j];
    ids[j] = t;
    bbox b = boxes[i];
    boxes[i] = boxes[j];
    boxes[j] = b;
}

static double centre_on(const bbox *b, int axis)
{
    return 0.5 * (v3_get(b->lo, axis) + v3_get(b->hi, axis));
}

/* The bin of a box whose centre is c, for bins from lo, scale bins per
 * unit. The product is tested before the cast: centres further apart than
 * a double reaches make width infinite and scale 0, and a centre that is
 * infinite or NaN (a box unbounded both ways) makes the product NaN. Those
 * go to the first or last bin, never through an undefined cast. */
static int bin_of(double c, double lo, double scale)
{
    double t = (c - lo) * scale;
    return t >= BINS ? BINS - 1 : t > 0 ? (int)t : 0;
}

/* Reorders [0, count) so the first half has the smaller centres along axis
 * (quickselect on the middle position). */
static void median_split(uint32_t *ids, bbox *boxes, uint32_t count, int axis)
{
    uint32_t lo = 0, hi = count - 1, k = count / 2;
    while (lo < hi) {
        double pivot = centre_on(&boxes[(lo + hi) / 2], axis);
        uint32_t i = lo, j = hi;
        while (i <= j) {
            while (centre_on(&boxes[i], axis) < pivot)
                i++;
            while (centre_on(&boxes[j], axis) > pivot)
                j--;
            if (i <= j) {
                swap_items(ids, boxes, i, j);
                i++;
                if (j == 0)
                    break;
                j--;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            break;
    }
}

/* The bounds of the operands' boxes and of their centres. */
typedef struct extent {
    bbox bounds, centres;
} extent;

static void extent_of(extent *e, const bbox *boxes, uint32_t count)
{
    e->bounds = box_none();
    e->centres = box_none();
    for (uint32_t i = 0; i < count; i++) {
        box_grow(&e->bounds, &boxes[i]);
        box_add(&e->centres, bbox_center(&boxes[i]));
    }
}

/* How a node splits its operands: at split (0 for a leaf) along axis,
 * with the extents of both sides when measured while partitioning. */
typedef struct plan {
    uint32_t split;
    int axis;
    int measured;
    extent sides[2];
} plan;

/* Fills node's bounds and chooses its split over [0, count), reordering
 * the operands so the first split of them are the left side; known is the
 * extent of those operands when the caller measured it while partitioning
 * (a pass over them saved at every level), NULL otherwise. */
static void plan_node(csg_bvh_node *node, uint32_t *ids, bbox *boxes, uint32_t count,
                      int depth, const extent *known, plan *p)
{
    extent own;
    if (!known) {
        extent_of(&own, boxes, count);
        known = &own;
    }
    bbox bounds = known->bounds, centres = known->centres;
    node->bounds = bounds;
    vec3 ext = bbox_extent(&centres);
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    double lo = v3_get(centres.lo, axis), width = v3_get(ext, axis);

    uint32_t split = 0;
    p->axis = axis;
    p->measured = 0;
    if (count > LEAF_SIZE && width > 0 && depth < SAH_DEPTH) {
        uint32_t bin_count[BINS] = {0};
        bbox bin_box[BINS];
        for (int b = 0; b < BINS; b++)
            bin_box[b] = box_none();
        double scale = BINS / width;
        for (uint32_t i = 0; i < count; i++) {
            int b = bin_of(centre_on(&boxes[i], axis), lo, scale);
            bin_count[b]++;
            box_grow(&bin_box[b], &boxes[i]);
        }
        /* Sweep from the right to get the area and count right of each
         * split, then from the left to price every split. */
        double right_area[BINS];
        uint32_t right_count[BINS];
        bbox acc = box_none();
        uint32_t n = 0;
        for (int b = BINS - 1; b > 0; b--) {
            box_grow(&acc, &bin_box[b]);
            n += bin_count[b];
            right_area[b] = half_area(&acc);
            right_count[b] = n;
        }
        double best = half_area(&bounds) * count; /* cost of a leaf */
        int best_bin = 0;
        acc = box_none();
        n = 0;
        for (int b = 1; b < BINS; b++) {
            box_grow(&acc, &bin_box[b - 1]);
            n += bin_count[b - 1];
            if (n == 0 || right_count[b] == 0)
                continue;
            double cost = half_area(&acc) * n + right_area[b] * right_count[b];
            if (cost < best) {
                best = cost;
                best_bin = b;
            }
        }
        if (best_bin > 0) {
            /* Partition, measuring both sides as each operand is placed. */
            extent_of(&p->sides[0], NULL, 0);
            extent_of(&p->sides[1], NULL, 0);
            uint32_t i = 0, j = count;
            while (i < j) {
                int b = bin_of(centre_on(&boxes[i], axis), lo, scale);
                extent *side = &p->sides[b >= best_bin];
                box_grow(&side->bounds, &boxes[i]);
                box_add(&side->centres, bbox_center(&boxes[i]));
                if (b < best_bin)
                    i++;
                else
                    swap_items(ids, boxes, i, --j);
            }
            split = i;
            p->measured = 1;
        } else if (count > 4 * LEAF_SIZE) {
            /* Even a leaf this large is cheaper by area; split anyway so a
             * ray never tests dozens of operands in one go. */
            median_split(ids, boxes, count, axis);
            split = count / 2;
        }
    } else if (count > LEAF_SIZE) {
        median_split(ids, boxes, count, axis);
        split = count / 2;
    }
    /* At most 4 * LEAF_SIZE operands stay together: larger sets split. */
    p->split = split == count ? 0 : split;
}

/* A right subtree of at least this many operands is built as a task of
 * its own (a million operands: about 30 tasks). */
enum { TASK_MIN = 1u << 15 };

/* Appends the nodes of a subtree built on its own (root at from->v[0]) to
 * out; its interior nodes' indices move with it. Returns the subtree's
 * root in out, or CSG_NO_BVH when memory ran out. */
static uint32_t append_nodes(bvh_nodes *out, const bvh_nodes *from)
{
    uint32_t at = out->count;
    if (from->count == 0 || from->count > UINT32_MAX - at)
        return CSG_NO_BVH;
    uint32_t need = at + from->count;
    if (!reserve_nodes(out, from->count))
        return CSG_NO_BVH;
    for (uint32_t i = 0; i < from->count; i++) {
        csg_bvh_node n = from->v[i];
        if (n.count == 0)
            n.index += at;
        out->v[at + i] = n;
    }
    out->count = need;
    return at;
}

/* Builds the node over [0, count) and its subtree, nodes in depth-first
 * order (a node, its left subtree, its right subtree). With tasks (inside
 * a parallel region), a right subtree of TASK_MIN operands or more is an
 * OpenMP task that builds into nodes of its own, appended once the left
 * one is done: the same nodes in the same order as without. */
static uint32_t build(bvh_nodes *out, uint32_t *ids, bbox *boxes, uint32_t count,
                      uint32_t base, int depth, const extent *known, int tasks)
{
    uint32_t node = push_node(out);
    if (node == CSG_NO_BVH)
        return CSG_NO_BVH;
    plan p;
    plan_node(&out->v[node], ids, boxes, count, depth, known, &p);
    uint32_t split = p.split;
    if (split == 0) {
        out->v[node].index = base;
        out->v[node].count = (uint16_t)count;
        return node;
    }
    out->v[node].axis = (uint8_t)p.axis;
    const extent *left_known = p.measured ? &p.sides[0] : NULL;
    const extent *right_known = p.measured ? &p.sides[1] : NULL;
    uint32_t left, right;
    if (!tasks || count - split < TASK_MIN) {
        left = build(out, ids, boxes, split, base, depth + 1, left_known, tasks);
        right = left == CSG_NO_BVH ? CSG_NO_BVH
                                   : build(out, ids + split, boxes + split, count - split,
                                           base + split, depth + 1, right_known, tasks);
    } else {
        bvh_nodes own = {NULL, 0, 0};
        uint32_t own_root = 0;
#pragma omp task shared(own, own_root)
        own_root = reserve_nodes(&own, 2 * (uint64_t)(count - split))
                       ? build(&own, ids + split, boxes + split, count - split,
                               base + split, depth + 1, right_known, tasks)
                       : CSG_NO_BVH;
        left = build(out, ids, boxes, split, base, depth + 1, left_known, tasks);
#pragma omp taskwait
        right = left == CSG_NO_BVH || own_root == CSG_NO_BVH ? CSG_NO_BVH
                                                             : append_nodes(out, &own);
        free(own.v);
    }
    if (right == CSG_NO_BVH)
        return CSG_NO_BVH;
    out->v[node].index = right;
    out->v[node].count = 0;
    return node;
}

uint32_t bvh_build(bvh_nodes *out, uint32_t *ids, bbox *boxes, uint32_t count,
                   uint32_t items_base)
{
    if (count == 0 || !reserve_nodes(out, 2 * (uint64_t)count))
        return CSG_NO_BVH;
    if (count < 2 * TASK_MIN || omp_in_parallel() || omp_get_max_threads() < 2)
        return build(out, ids, boxes, count, items_base, 0, NULL, 0);
    uint32_t root = CSG_NO_BVH;
#pragma omp parallel
#pragma omp single
    root = build(out, ids, boxes, count, items_base, 0, NULL, 1);
    return root;
}
