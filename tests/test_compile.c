/* Tests of the simplification csg_builder_finish performs when it compiles a
 * tree (src/csg/csg.c): flattening of nested booleans of one kind,
 * subtracted unions split into their operands, subtracted solids whose box
 * misses the first operand dropped, intersections of disjoint boxes made
 * empty, and the BVH over wide nodes. Each case checks the compiled shape and
 * that the solid is unchanged (point membership on a grid compared with the
 * same tree built by hand as it should come out).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "csg/bvh.h"
#include "csg/csg.h"

static const float white[4] = {1, 1, 1, 1};
static const sc_location no_loc = {NULL, 0, 0};

static uint32_t cube_at(csg_builder *b, double x, double y, double z, double size)
{
    prim p = {.kind = PRIM_BOX};
    p.u.box.lo = v3(x, y, z);
    p.u.box.hi = v3(x + size, y + size, z + size);
    affine id = affine_identity();
    return csg_builder_leaf(b, &p, &id, white, no_loc);
}

static uint32_t op2(csg_builder *b, csg_op op, uint32_t a, uint32_t c)
{
    uint32_t kids[2] = {a, c};
    return csg_builder_op(b, op, kids, 2);
}

static csg_tree *finish(csg_builder *b, uint32_t root)
{
    csg_tree *t = NULL;
    sc_error err;
    assert_int_equal(csg_builder_finish(b, root, &t, &err), SC_OK);
    return t;
}

static const csg_node *root_node(const csg_tree *t)
{
    assert_int_not_equal(t->root, CSG_EMPTY);
    return &t->nodes[t->root];
}

/* Membership of both trees agrees on a grid over [-2, 12]^3. */
static void same_solid(const csg_tree *a, const csg_tree *b)
{
    for (int i = 0; i <= 28; i++)
        for (int j = 0; j <= 28; j++)
            for (int k = 0; k <= 28; k++) {
                vec3 p =
                    v3(-2 + 0.5 * i + 0.01, -2 + 0.5 * j + 0.02, -2 + 0.5 * k + 0.03);
                assert_int_equal(csg_inside(a, p), csg_inside(b, p));
            }
}

static void nested_unions_flatten(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t inner = op2(b, CSG_UNION, cube_at(b, 0, 0, 0, 2), cube_at(b, 3, 0, 0, 2));
    uint32_t mid = op2(b, CSG_UNION, inner, cube_at(b, 6, 0, 0, 2));
    csg_tree *t = finish(b, op2(b, CSG_UNION, mid, cube_at(b, 9, 0, 0, 2)));
    assert_int_equal(root_node(t)->op, CSG_UNION);
    assert_int_equal(root_node(t)->child_count, 4);
    assert_int_equal(t->node_count, 5);
    assert_int_equal(t->source_node_count, 7);
    assert_int_equal(t->depth, 2);
    assert_int_equal(t->source_depth, 4);

    csg_builder *h = csg_builder_new();
    uint32_t kids[4] = {cube_at(h, 0, 0, 0, 2), cube_at(h, 3, 0, 0, 2),
                        cube_at(h, 6, 0, 0, 2), cube_at(h, 9, 0, 0, 2)};
    csg_tree *want = finish(h, csg_builder_op(h, CSG_UNION, kids, 4));
    same_solid(t, want);
    csg_tree_free(t);
    csg_tree_free(want);
}

static void nested_differences_flatten(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t d1 = op2(b, CSG_DIFFERENCE, cube_at(b, 0, 0, 0, 10), cube_at(b, 1, 1, 8, 3));
    uint32_t holes = op2(b, CSG_UNION, cube_at(b, 5, 5, 8, 3), cube_at(b, 1, 5, 8, 3));
    csg_tree *t = finish(b, op2(b, CSG_DIFFERENCE, d1, holes));
    /* difference(difference(a, b), union(c, d)) = difference(a, b, c, d) */
    assert_int_equal(root_node(t)->op, CSG_DIFFERENCE);
    assert_int_equal(root_node(t)->child_count, 4);
    assert_int_equal(t->depth, 2);

    csg_builder *h = csg_builder_new();
    uint32_t kids[4] = {cube_at(h, 0, 0, 0, 10), cube_at(h, 1, 1, 8, 3),
                        cube_at(h, 5, 5, 8, 3), cube_at(h, 1, 5, 8, 3)};
    csg_tree *want = finish(h, csg_builder_op(h, CSG_DIFFERENCE, kids, 4));
    same_solid(t, want);
    csg_tree_free(t);
    csg_tree_free(want);
}

static void subtraction_that_misses_is_dropped(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[3] = {cube_at(b, 0, 0, 0, 5), cube_at(b, 20, 0, 0, 5),
                        cube_at(b, 4, 4, 4, 5)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 3));
    assert_int_equal(root_node(t)->child_count, 2);
    assert_int_equal(t->source_leaf_count, 3);
    assert_int_equal(t->leaf_count, 2);

    /* Only one that misses: the first operand alone is left. */
    b = csg_builder_new();
    csg_tree *alone = finish(
        b, op2(b, CSG_DIFFERENCE, cube_at(b, 0, 0, 0, 5), cube_at(b, 20, 0, 0, 5)));
    assert_int_equal(root_node(alone)->op, CSG_LEAF);
    assert_int_equal(alone->node_count, 1);
    csg_tree_free(t);
    csg_tree_free(alone);
}

static void disjoint_intersection_is_empty(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t empty =
        op2(b, CSG_INTERSECTION, cube_at(b, 0, 0, 0, 2), cube_at(b, 5, 5, 5, 2));
    uint32_t kept = cube_at(b, 8, 8, 8, 2);
    csg_tree *t = finish(b, op2(b, CSG_UNION, empty, kept));
    /* The empty intersection vanishes from the union, which is left with
     * one operand: the tree is that leaf. */
    assert_int_equal(root_node(t)->op, CSG_LEAF);
    assert_int_equal(t->node_count, 1);
    assert_int_equal(t->source_node_count, 5);
    csg_tree_free(t);

    b = csg_builder_new();
    t = finish(b,
               op2(b, CSG_INTERSECTION, cube_at(b, 0, 0, 0, 2), cube_at(b, 5, 5, 5, 2)));
    assert_int_equal(t->root, CSG_EMPTY);
    assert_int_equal(t->node_count, 0);
    csg_tree_free(t);
}

/* A wide union gets a BVH whose leaves hold every operand exactly once,
 * each inside the box of every BVH node above it. */
static void wide_union_gets_a_bvh(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[100];
    for (int i = 0; i < 100; i++)
        kids[i] = cube_at(b, (i % 10) * 1.5, (i / 10) * 1.5, (i * 7 % 5) * 0.3, 1);
    csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, 100));
    const csg_node *n = root_node(t);
    assert_int_not_equal(n->bvh, CSG_NO_BVH);
    int seen[100] = {0};
    uint32_t stack[BVH_MAX_DEPTH], sp = 0, leaves = 0;
    stack[sp++] = n->bvh;
    while (sp) {
        const csg_bvh_node *v = &t->bvh_nodes[stack[--sp]];
        if (v->count) {
            for (uint32_t k = 0; k < v->count; k++) {
                uint32_t pos = v->index + k - n->first_child;
                assert_true(pos < 100);
                seen[pos]++;
                bbox child = t->nodes[t->child_ids[v->index + k]].bounds;
                bbox inter = bbox_intersect(child, v->bounds);
                assert_true(inter.lo.x == child.lo.x && inter.hi.z == child.hi.z);
            }
            leaves++;
            continue;
        }
        uint32_t self = (uint32_t)(v - t->bvh_nodes);
        assert_true(sp + 2 <= BVH_MAX_DEPTH);
        stack[sp++] = self + 1;
        stack[sp++] = v->index;
    }
    for (int i = 0; i < 100; i++)
        assert_int_equal(seen[i], 1);
    assert_true(leaves >= 100 / 16);
    csg_tree_free(t);
}

/* The next of xorshift64's numbers in r, as a double in [0, 1). */
static double next_unit(uint64_t *r)
{
    *r ^= *r << 13;
    *r ^= *r >> 7;
    *r ^= *r << 17;
    return (double)(*r >> 11) / 9007199254740992.0;
}

/* The binned SAH split, recomputed the plain way (one set of bins, each
 * box added in turn) at every interior node of a hierarchy built over
 * random boxes: the node's box is the exact union of its operands' boxes,
 * its axis is the widest extent of their centres, and its left child
 * holds exactly the operands whose bin lies left of the cheapest split.
 * bvh_build bins in several interleaved sets; this checks that it still
 * makes the hierarchy the plain algorithm makes. */
enum { CHECK_BINS = 16 };

static bbox union_of(const bbox *boxes, uint32_t count)
{
    bbox u = boxes[0];
    for (uint32_t i = 1; i < count; i++)
        u = bbox_union(u, boxes[i]);
    return u;
}

static double half_area_of(bbox b)
{
    double x = b.hi.x - b.lo.x, y = b.hi.y - b.lo.y, z = b.hi.z - b.lo.z;
    return x * y + y * z + z * x;
}

static double centre_of(const bbox *b, int axis)
{
    return 0.5 * (v3_get(b->lo, axis) + v3_get(b->hi, axis));
}

static void check_split(const bvh_nodes *out, uint32_t node, const bbox *boxes,
                        uint32_t count, int depth, int *checked)
{
    const csg_bvh_node *v = &out->v[node];
    bbox u = union_of(boxes, count);
    assert_memory_equal(&v->bounds, &u, sizeof u);
    if (v->count) {
        assert_int_equal(v->count, count);
        return;
    }
    bbox centres = {bbox_center(&boxes[0]), bbox_center(&boxes[0])};
    for (uint32_t i = 1; i < count; i++)
        centres = bbox_add_point(centres, bbox_center(&boxes[i]));
    vec3 ext = bbox_extent(&centres);
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    assert_int_equal(v->axis, axis);
    /* The left child follows the node; its operands come first. */
    uint32_t left_count = 0, stack[BVH_MAX_DEPTH], sp = 0;
    stack[sp++] = node + 1;
    while (sp) {
        const csg_bvh_node *w = &out->v[stack[--sp]];
        if (w->count) {
            left_count += w->count;
        } else {
            stack[sp++] = (uint32_t)(w - out->v) + 1;
            stack[sp++] = w->index;
        }
    }
    double lo = v3_get(centres.lo, axis), width = v3_get(ext, axis);
    uint32_t bin_count[CHECK_BINS] = {0};
    bbox bin_box[CHECK_BINS];
    for (uint32_t i = 0; i < count; i++) {
        int b = (int)((centre_of(&boxes[i], axis) - lo) * (CHECK_BINS / width));
        b = b < 0 ? 0 : b >= CHECK_BINS ? CHECK_BINS - 1 : b;
        bin_box[b] = bin_count[b]++ ? bbox_union(bin_box[b], boxes[i]) : boxes[i];
    }
    double best = half_area_of(u) * count;
    int best_bin = 0;
    for (int split = 1; split < CHECK_BINS; split++) {
        uint32_t nl = 0, nr = 0;
        bbox l = bbox_empty(), r = bbox_empty();
        for (int b = 0; b < CHECK_BINS; b++) {
            if (!bin_count[b])
                continue;
            if (b < split) {
                l = nl ? bbox_union(l, bin_box[b]) : bin_box[b];
                nl += bin_count[b];
            } else {
                r = nr ? bbox_union(r, bin_box[b]) : bin_box[b];
                nr += bin_count[b];
            }
        }
        if (!nl || !nr)
            continue;
        double cost = half_area_of(l) * nl + half_area_of(r) * nr;
        if (cost < best) {
            best = cost;
            best_bin = split;
        }
    }
    if (best_bin > 0) {
        uint32_t want_left = 0;
        for (uint32_t i = 0; i < count; i++) {
            int b = (int)((centre_of(&boxes[i], axis) - lo) * (CHECK_BINS / width));
            b = b < 0 ? 0 : b >= CHECK_BINS ? CHECK_BINS - 1 : b;
            want_left += b < best_bin;
            if (i < left_count)
                assert_true(b < best_bin);
            else
                assert_true(b >= best_bin);
        }
        assert_int_equal(left_count, want_left);
        (*checked)++;
    }
    check_split(out, node + 1, boxes, left_count, depth + 1, checked);
    check_split(out, v->index, boxes + left_count, count - left_count, depth + 1,
                checked);
}

static void bvh_matches_plain_binning(void **state)
{
    (void)state;
    uint64_t r = 0x853c49e6748fea9bULL;
    for (int round = 0; round < 20; round++) {
        uint32_t count = 50 + (uint32_t)round * 997;
        uint32_t *ids = malloc(count * sizeof *ids);
        bbox *boxes = malloc(count * sizeof *boxes);
        assert_non_null(ids);
        assert_non_null(boxes);
        for (uint32_t i = 0; i < count; i++) {
            double c[4];
            for (int k = 0; k < 4; k++)
                c[k] = next_unit(&r);
            /* Clustered along a row, as a model's leaves come, and random. */
            double x = i % 3 ? (double)i * 0.01 : 100 * c[0];
            vec3 p = v3(x, 10 * c[1], round % 2 ? 10 * c[2] : 0.5);
            double size = 0.05 + c[3];
            boxes[i] = (bbox){p, v3_add(p, v3(size, size, size))};
            ids[i] = i;
        }
        bvh_nodes out = {0};
        uint32_t root = bvh_build(&out, ids, boxes, count, 0);
        assert_int_equal(root, 0);
        int checked = 0;
        check_split(&out, root, boxes, count, 0, &checked);
        assert_true(checked > 0);
        free(out.v);
        free(ids);
        free(boxes);
    }
}

/* A hierarchy over enough operands is built in OpenMP tasks, each large
 * right subtree into nodes of its own, appended when its left sibling is
 * done. It must be the hierarchy one thread builds: the same nodes in the
 * same order, the same operand order, and the indices right when the
 * nodes are appended after others (a tree's second BVH). */
static void bvh_tasks_match_one_thread(void **state)
{
    (void)state;
    enum { COUNT = 150000, BEFORE = 3 };
    uint64_t r = 0x2545f4914f6cdd1dULL;
    uint32_t *ids[2];
    bbox *boxes[2];
    for (int k = 0; k < 2; k++) {
        ids[k] = malloc(COUNT * sizeof *ids[k]);
        boxes[k] = malloc(COUNT * sizeof *boxes[k]);
        assert_non_null(ids[k]);
        assert_non_null(boxes[k]);
    }
    for (uint32_t i = 0; i < COUNT; i++) {
        double c[4];
        for (int k = 0; k < 4; k++)
            c[k] = next_unit(&r);
        /* a grid of spheres, as a large union comes, and scattered boxes */
        vec3 p = i % 5 ? v3(i % 53, (i / 53) % 53, i / 2809)
                       : v3(60 * c[0], 60 * c[1], 60 * c[2]);
        double size = 0.3 + c[3];
        boxes[0][i] = (bbox){p, v3_add(p, v3(size, size, size))};
        ids[0][i] = i;
    }
    memcpy(boxes[1], boxes[0], COUNT * sizeof *boxes[0]);
    memcpy(ids[1], ids[0], COUNT * sizeof *ids[0]);
    bvh_nodes out[2] = {{0}, {0}};
    uint32_t root[2];
    int threads = omp_get_max_threads();
    for (int k = 0; k < 2; k++) {
        omp_set_num_threads(k ? 2 : 1);
        /* nodes of an earlier hierarchy before this one */
        for (int i = 0; i < BEFORE; i++) {
            uint32_t one = 7;
            bbox b = {v3(i, 0, 0), v3(i + 1, 1, 1)};
            assert_int_equal(bvh_build(&out[k], &one, &b, 1, 0), (uint32_t)i);
        }
        root[k] = bvh_build(&out[k], ids[k], boxes[k], COUNT, 10);
    }
    omp_set_num_threads(threads);
    assert_int_equal(root[0], BEFORE);
    assert_int_equal(root[1], BEFORE);
    assert_int_equal(out[1].count, out[0].count);
    assert_true(out[0].count > COUNT / 8);
    for (uint32_t i = 0; i < out[0].count; i++) {
        const csg_bvh_node *a = &out[0].v[i], *b = &out[1].v[i];
        assert_memory_equal(&a->bounds, &b->bounds, sizeof a->bounds);
        assert_int_equal(a->index, b->index);
        assert_int_equal(a->count, b->count);
        if (!a->count)
            assert_int_equal(a->axis, b->axis);
    }
    assert_memory_equal(ids[0], ids[1], COUNT * sizeof *ids[0]);
    assert_memory_equal(boxes[0], boxes[1], COUNT * sizeof *boxes[0]);
    for (int k = 0; k < 2; k++) {
        free(out[k].v);
        free(ids[k]);
        free(boxes[k]);
    }
}

/* Operands whose centres lie further apart than a double reaches (at
 * -1e308 and 1e308), or are not numbers (a box unbounded both ways), still
 * get a hierarchy over all of them: binning them must not turn an infinite
 * or NaN position into a bin number (undefined behaviour, found by the
 * fuzzer; the sanitised suite checks float-to-int casts). */
static void bvh_takes_centres_beyond_double(void **state)
{
    (void)state;
    enum { COUNT = 64 };
    uint32_t ids[COUNT];
    bbox boxes[COUNT];
    for (uint32_t i = 0; i < COUNT; i++) {
        vec3 p = v3(i, i % 7, 0);
        if (i % 4 == 0)
            p.x = i % 8 ? 1e308 : -1e308;
        boxes[i] = (bbox){p, v3_add(p, v3(1, 1, 1))};
        if (i % 4 == 0)
            boxes[i].hi.x = p.x;
        if (i % 16 == 1) {
            boxes[i].lo.x = -INFINITY;
            boxes[i].hi.x = INFINITY;
        }
        ids[i] = i;
    }
    bvh_nodes out = {0};
    uint32_t root = bvh_build(&out, ids, boxes, COUNT, 0);
    assert_int_equal(root, 0);
    /* every operand once, under leaves whose counts add up */
    int seen[COUNT] = {0};
    for (uint32_t i = 0; i < COUNT; i++)
        seen[ids[i]]++;
    for (uint32_t i = 0; i < COUNT; i++)
        assert_int_equal(seen[i], 1);
    uint32_t leaves = 0;
    for (uint32_t i = 0; i < out.count; i++)
        leaves += out.v[i].count;
    assert_int_equal(leaves, COUNT);
    assert_true(out.v[root].bounds.lo.x == -INFINITY);
    assert_true(out.v[root].bounds.hi.x == INFINITY);
    free(out.v);
}

/* A leaf's world box is the box of its local box's eight transformed
 * corners (bbox_transform), bit for bit, for random boxes under random
 * affine maps, including zero and negative entries. */
static void leaf_bounds_are_transformed_corners(void **state)
{
    (void)state;
    uint64_t r = 0xda942042e4dd58b5ULL;
    for (int round = 0; round < 200; round++) {
        csg_builder *b = csg_builder_new();
        uint32_t kids[10];
        affine maps[10];
        prim prims[10];
        uint32_t made = 0;
        for (int i = 0; i < 10; i++) {
            double c[18];
            for (int k = 0; k < 18; k++)
                c[k] = next_unit(&r) * 20 - 10;
            affine m = affine_identity();
            for (int row = 0; row < 3; row++)
                for (int col = 0; col < 4; col++)
                    m.m[row][col] =
                        (r >> (row * 4 + col)) % 7 == 0 ? 0 : c[row * 4 + col];
            if (round % 3 == 0)
                m.m[0][1] = m.m[1][0] = m.m[2][0] = 0; /* sparse, as most are */
            prim p = {.kind = PRIM_BOX};
            p.u.box.lo = v3(c[12], c[13], c[14]);
            p.u.box.hi =
                v3(c[12] + fabs(c[15]), c[13] + fabs(c[16]), c[14] + fabs(c[17]));
            /* A singular map makes no leaf: object ids count the others. */
            maps[made] = m;
            prims[made] = p;
            kids[i] = csg_builder_leaf(b, &p, &m, white, no_loc);
            made += kids[i] != CSG_EMPTY;
        }
        csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, 10));
        uint32_t seen = 0;
        for (uint32_t k = 0; k < t->node_count; k++) {
            const csg_node *n = &t->nodes[k];
            if (n->op != CSG_LEAF)
                continue;
            uint32_t i = t->leaves[n->leaf].object_id;
            bbox want = bbox_transform(&maps[i], prim_bounds(&prims[i]));
            for (int a = 0; a < 3; a++) {
                assert_true(v3_get(n->bounds.lo, a) == v3_get(want.lo, a));
                assert_true(v3_get(n->bounds.hi, a) == v3_get(want.hi, a));
            }
            seen++;
        }
        assert_int_equal(seen, made);
        assert_true(made >= 5);
        csg_tree_free(t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nested_unions_flatten),
        cmocka_unit_test(nested_differences_flatten),
        cmocka_unit_test(subtraction_that_misses_is_dropped),
        cmocka_unit_test(disjoint_intersection_is_empty),
        cmocka_unit_test(wide_union_gets_a_bvh),
        cmocka_unit_test(bvh_matches_plain_binning),
        cmocka_unit_test(bvh_tasks_match_one_thread),
        cmocka_unit_test(bvh_takes_centres_beyond_double),
        cmocka_unit_test(leaf_bounds_are_transformed_corners),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
