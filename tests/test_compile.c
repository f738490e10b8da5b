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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nested_unions_flatten),
        cmocka_unit_test(nested_differences_flatten),
        cmocka_unit_test(subtraction_that_misses_is_dropped),
        cmocka_unit_test(disjoint_intersection_is_empty),
        cmocka_unit_test(wide_union_gets_a_bvh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
