/* Tests of the scene builder and the scene API (src/build/build.c,
 * colors.c, scene.c): the meaning of every node OpenSCAD writes, the
 * modifiers, colours, transforms (singular and malformed), convex, open and
 * non-convex polyhedra, empty primitives, deep nesting, file loading, and
 * every builder error and warning message, exactly. Membership is checked
 * with csg_inside, the tree's own point oracle. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "build/build.h"
#include "model/colors.h"
#include "build/scene.h"
#include "test_util.h"

static sc_scene *load(const char *text)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e);
    if (st != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    assert_non_null(s);
    return s;
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e),
                     status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

/* The same with --strict (sc_load_options.strict). */
static void check_error_strict(const char *text, sc_status status, const char *expected)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.strict = 1;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e),
                     status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

/* Loads text and checks that it gives exactly the one warning expected. */
static sc_scene *load_warned(const char *text, const char *expected)
{
    sc_scene *s = load(text);
    assert_int_equal(sc_scene_warning_count(s), 1);
    const sc_error *w = sc_scene_warning(s, 0);
    assert_int_equal(w->status, SC_OK);
    char buf[1024];
    const char *got = sc_error_format(w, buf, sizeof buf);
    /* sc_error_format calls everything an error; warnings are printed by
     * the caller with its own prefix, so compare the rest. */
    const char *tag = strstr(got, "error: ");
    assert_non_null(tag);
    char joined[1024];
    snprintf(joined, sizeof joined, "%.*s%s", (int)(tag - got), got, tag + 7);
    assert_string_equal(joined, expected);
    return s;
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static const csg_leaf *only_leaf(const sc_scene *s)
{
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 1);
    assert_int_not_equal(t->root, CSG_EMPTY);
    assert_int_equal(t->nodes[t->root].op, CSG_LEAF);
    return &t->leaves[t->nodes[t->root].leaf];
}

static int is_empty(const sc_scene *s)
{
    double lo[3], hi[3];
    return scene_tree(s)->root == CSG_EMPTY && !sc_scene_bounds(s, lo, hi);
}

#define assert_near(a, b) assert_true(fabs((double)(a) - (double)(b)) <= 1e-9)
#define assert_near_tol(a, b, tol) assert_true(fabs((double)(a) - (double)(b)) <= (tol))

/* ---- primitives ---- */

static void test_cube(void **state)
{
    (void)state;
    sc_scene *s = load("cube(size = [1, 2, 3], center = false);");
    const csg_leaf *l = only_leaf(s);
    assert_int_equal(l->prim.kind, PRIM_BOX);
    assert_near(l->prim.u.box.lo.x, 0);
    assert_near(l->prim.u.box.hi.z, 3);
    assert_int_equal(l->loc.line, 1);
    assert_int_equal(l->loc.column, 1);
    assert_string_equal(l->loc.file, "m.csg");
    assert_int_equal(l->object_id, 0);
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    assert_near(lo[0], 0);
    assert_near(hi[1], 2);
    assert_near(hi[2], 3);
    sc_scene_release(s);

    s = load("cube(2, true);");
    l = only_leaf(s);
    assert_near(l->prim.u.box.lo.y, -1);
    assert_near(l->prim.u.box.hi.y, 1);
    sc_scene_release(s);

    s = load("cube();");
    l = only_leaf(s);
    assert_near(l->prim.u.box.hi.x, 1);
    sc_scene_release(s);
}

static void test_sphere(void **state)
{
    (void)state;
    sc_scene *s = load("sphere($fn = 0, $fa = 12, $fs = 2, r = 3);");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    assert_near(only_leaf(s)->prim.u.sphere.r, 3);
    sc_scene_release(s);
    s = load("sphere(d = 5);");
    assert_near(only_leaf(s)->prim.u.sphere.r, 2.5);
    sc_scene_release(s);
    s = load("sphere(4, d = 2);"); /* a diameter wins, as in OpenSCAD */
    assert_near(only_leaf(s)->prim.u.sphere.r, 1);
    sc_scene_release(s);
    s = load("sphere();");
    assert_near(only_leaf(s)->prim.u.sphere.r, 1);
    sc_scene_release(s);
}

static void check_cylinder(const char *text, double z0, double z1, double r0, double r1)
{
    sc_scene *s = load(text);
    const csg_leaf *l = only_leaf(s);
    assert_int_equal(l->prim.kind, PRIM_CYLINDER);
    assert_near(l->prim.u.cylinder.z0, z0);
    assert_near(l->prim.u.cylinder.z1, z1);
    assert_near(l->prim.u.cylinder.r0, r0);
    assert_near(l->prim.u.cylinder.r1, r1);
    sc_scene_release(s);
}

static void test_cylinder(void **state)
{
    (void)state;
    check_cylinder("cylinder($fn = 0, $fa = 12, $fs = 2, h = 10, r1 = 2, r2 = 3, "
                   "center = false);",
                   0, 10, 2, 3);
    check_cylinder("cylinder(h = 4, r1 = 2, r2 = 2, center = true);", -2, 2, 2, 2);
    check_cylinder("cylinder(h = 2, r1 = 0, r2 = 3, center = true);", -1, 1, 0, 3);
    check_cylinder("cylinder(h = 2, r1 = 3, r2 = 0);", 0, 2, 3, 0);
    check_cylinder("cylinder(5, 1, 2, true);", -2.5, 2.5, 1, 2);
    check_cylinder("cylinder(h = 1, r = 4);", 0, 1, 4, 4);
    check_cylinder("cylinder(h = 1, d = 4);", 0, 1, 2, 2);
    check_cylinder("cylinder(h = 1, r = 4, r2 = 1);", 0, 1, 4, 1);
    check_cylinder("cylinder(h = 1, d1 = 4, d2 = 6, r1 = 9);", 0, 1, 2, 3);
    check_cylinder("cylinder();", 0, 1, 1, 1);
}

static void test_empty_primitives(void **state)
{
    (void)state;
    static const struct {
        const char *text, *warning;
    } cases[] = {
        {"cube(0);", "m.csg:1:1: cube with a zero, negative or non-finite size is empty"},
        {"cube([1, -1, 1]);",
         "m.csg:1:1: cube with a zero, negative or non-finite size is empty"},
        {"cube([1, inf, 1]);",
         "m.csg:1:1: cube with a zero, negative or non-finite size is empty"},
        {"cube(nan);",
         "m.csg:1:1: cube with a zero, negative or non-finite size is empty"},
        {"sphere(r = 0);",
         "m.csg:1:1: sphere with a zero, negative or non-finite radius is empty"},
        {"sphere(r = -nan);",
         "m.csg:1:1: sphere with a zero, negative or non-finite radius is empty"},
        {"sphere(r = inf);",
         "m.csg:1:1: sphere with a zero, negative or non-finite radius is empty"},
        {"cylinder(h = 0, r1 = 1, r2 = 1);",
         "m.csg:1:1: cylinder with a zero, negative or non-finite height is empty"},
        {"cylinder(h = -1, r1 = 1, r2 = 1);",
         "m.csg:1:1: cylinder with a zero, negative or non-finite height is empty"},
        {"cylinder(h = 1, r1 = 0, r2 = 0);",
         "m.csg:1:1: cylinder with negative, non-finite or two zero radii is empty"},
        {"cylinder(h = 1, r1 = -1, r2 = 1);",
         "m.csg:1:1: cylinder with negative, non-finite or two zero radii is empty"},
        {"cylinder(h = 1, r1 = inf, r2 = 1);",
         "m.csg:1:1: cylinder with negative, non-finite or two zero radii is empty"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sc_scene *s = load_warned(cases[i].text, cases[i].warning);
        assert_true(is_empty(s));
        sc_scene_release(s);
    }
    /* An empty child empties an intersection, as OpenSCAD's does. */
    sc_scene *s = load("intersection() { cube(2); cube(0); }");
    assert_true(is_empty(s));
    sc_scene_release(s);
}

/* The box sc_scene_bounds gives text's model, within 1e-9. */
static void check_box(const char *text, double x0, double y0, double z0, double x1,
                      double y1, double z1)
{
    sc_scene *s = load(text);
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    const double want[6] = {x0, y0, z0, x1, y1, z1};
    for (int k = 0; k < 3; k++) {
        assert_near(lo[k], want[k]);
        assert_near(hi[k], want[k + 3]);
    }
    sc_scene_release(s);
}

/* An argument of the wrong kind is the parameter's default, as OpenSCAD
 * 2021.01 takes it (openscad -o x.csg exports these values): silently,
 * but for a cube's size; a center is true only when it is true. */
static void test_wrong_types(void **state)
{
    (void)state;
    check_box("sphere(r = \"big\");", -1, -1, -1, 1, 1, 1);
    check_box("sphere([1]);", -1, -1, -1, 1, 1, 1);
    check_box("sphere(r = 2, d = true);", -2, -2, -2, 2, 2, 2);
    check_box("cube(1, center = 1);", 0, 0, 0, 1, 1, 1);
    check_box("cylinder(h = [1], r1 = 2, r2 = 2);", -2, -2, 0, 2, 2, 1);
    check_box("cylinder(h = 3, r = 2, r1 = false, center = \"yes\");", -2, -2, 0, 2, 2,
              3);
    sc_scene *c = load_warned("cube(size = [1, 2]);",
                              "m.csg:1:13: Unable to convert cube(size=[1, 2], ...) "
                              "parameter to a number or a vec3 of numbers");
    assert_true(inside(c, 0.5, 0.5, 0.5) && !inside(c, 0.5, 1.5, 0.5));
    sc_scene_release(c);
    c = load_warned("cube(size = [1, 2, \"3\"], center = true);",
                    "m.csg:1:13: Unable to convert cube(size=[1, 2, \"3\"], ...) "
                    "parameter to a number or a vec3 of numbers");
    assert_true(inside(c, -0.4, -0.4, -0.4) && !inside(c, 0.6, 0, 0));
    sc_scene_release(c);
    check_error_strict("cube(size = [1, 2]);", SC_ERR_SEMANTIC,
                       "m.csg:1:13: error: Unable to convert cube(size=[1, 2], ...) "
                       "parameter to a number or a vec3 of numbers");
    /* undef is "not given"; unknown arguments and repeated ones are warned
     * of (OpenSCAD's warnings), and the last wins. */
    sc_scene *s = load("sphere(r = undef, whatever = [1, \"x\"], r = 2, r = 3);");
    assert_near(only_leaf(s)->prim.u.sphere.r, 3);
    assert_int_equal(sc_scene_warning_count(s), 3);
    sc_scene_release(s);
}

/* ---- booleans ---- */

static void test_booleans(void **state)
{
    (void)state;
    sc_scene *s = load("group() { cube(2); sphere(1); }");
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->nodes[t->root].op, CSG_UNION);
    assert_int_equal(t->nodes[t->root].child_count, 2);
    assert_int_equal(t->leaves[0].object_id, 0);
    assert_int_equal(t->leaves[1].object_id, 1);
    assert_int_equal(t->leaves[1].prim.kind, PRIM_SPHERE);
    assert_true(inside(s, 1.5, 1.5, 1.5));
    assert_true(inside(s, -0.5, 0, 0));
    sc_scene_info info;
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(s, &info, NULL), SC_OK);
    assert_int_equal(info.node_count, 3);
    assert_int_equal(info.leaf_count, 2);
    assert_int_equal(info.depth, 2);
    sc_scene_release(s);

    /* Top-level statements, render and union are unions too. */
    s = load("cube(1);\nrender(convexity = 2) { union() { sphere(r = 1); } }");
    t = scene_tree(s);
    assert_int_equal(t->nodes[t->root].op, CSG_UNION);
    assert_true(inside(s, 0.5, 0.5, 0.5) && inside(s, -0.5, 0, 0));
    sc_scene_release(s);

    /* difference: the first minus all the rest. */
    s = load("difference() { cube(4, center = true); sphere(1); cube([3, 3, 0.2]); }");
    t = scene_tree(s);
    assert_int_equal(t->nodes[t->root].op, CSG_DIFFERENCE);
    assert_int_equal(t->nodes[t->root].child_count, 3);
    assert_false(inside(s, 0, 0, 0));
    assert_false(inside(s, 1.5, 1.5, 0.1));
    assert_true(inside(s, 1.5, 1.5, 0.5));
    assert_true(inside(s, -1.5, -1.5, -1.5));
    sc_scene_release(s);

    s = load("intersection() { cube(2, center = true); sphere(1.2); }");
    t = scene_tree(s);
    assert_int_equal(t->nodes[t->root].op, CSG_INTERSECTION);
    assert_true(inside(s, 0.9, 0, 0));
    assert_false(inside(s, 0.9, 0.9, 0.9));
    sc_scene_release(s);

    /* Empty groups and an empty file are the empty solid. */
    s = load("group(); group() { } union() { group(); }");
    assert_true(is_empty(s));
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(s, &info, NULL), SC_OK);
    assert_int_equal(info.node_count, 0);
    sc_scene_release(s);
    s = load("");
    assert_true(is_empty(s));
    sc_scene_release(s);
    s = load("difference() { group(); cube(); }");
    assert_true(is_empty(s));
    sc_scene_release(s);
}

/* ---- transforms ---- */

static void test_multmatrix(void **state)
{
    (void)state;
    sc_scene *s =
        load("multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
             "  multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
             "    cube(1);\n  }\n"
             "}\n");
    const csg_leaf *l = only_leaf(s);
    /* to_world = outer * inner: x' = 2x + 10, z' = z + 5. */
    affine to_world = test_leaf_to_world(l);
    assert_near(to_world.m[0][0], 2);
    assert_near(to_world.m[0][3], 10);
    assert_near(to_world.m[2][3], 5);
    assert_near(l->to_local.m[0][0], 0.5);
    assert_int_equal(l->loc.line, 3);
    assert_int_equal(l->loc.column, 5);
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    assert_near(lo[0], 10);
    assert_near(hi[0], 12);
    assert_near(lo[2], 5);
    assert_true(inside(s, 11.5, 0.5, 5.5));
    assert_false(inside(s, 0.5, 0.5, 0.5));
    sc_scene_release(s);

    /* No matrix is the identity. */
    s = load("multmatrix() { cube(1); }");
    assert_near(test_leaf_to_world(only_leaf(s)).m[0][0], 1);
    sc_scene_release(s);
}

/* Matrices of other shapes render as OpenSCAD 2021.01 reads them, without
 * a word (test_model has the rule): the cube where the identity, filled
 * in, puts it, and scaled down by a bottom right entry other than 1. */
static void test_multmatrix_shapes(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double x, scale;
    } cases[] = {
        {"group() {\n  multmatrix([[1, 0, 0], [0, 1, 0], [0, 0, 1]]) { cube(); }\n}", 0,
         1},
        {"multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0]]) { cube(); }", 4, 1},
        {"multmatrix(m = [[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0]]) { "
         "cube(); }",
         4, 1},
        {"multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, true]]) { "
         "cube(); }",
         4, 1},
        {"multmatrix(m = 1) { cube(); }", 0, 1},
        {"multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [0, 0, 0, "
         "1]]) "
         "{ cube(); }",
         4, 1},
        {"multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0.5, 0, 1]]) { "
         "cube(); }",
         4, 1},
        {"multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 2]]) { cube(); "
         "}",
         2, 0.5},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        sc_scene *s = load(cases[i].text);
        double lo[3], hi[3];
        assert_true(sc_scene_bounds(s, lo, hi));
        assert_near(lo[0], cases[i].x);
        assert_near(hi[0], cases[i].x + cases[i].scale);
        assert_near(lo[1], 0);
        assert_near(hi[2], cases[i].scale);
        assert_int_equal(sc_scene_warning_count(s), 0);
        sc_scene_release(s);
    }
}

/* A nan or inf entry (OpenSCAD 2021.01 exports 0/0 as nan, 1/0 as inf):
 * OpenSCAD removes the subtree with its warning and renders the rest, in
 * the render and the preview; --strict makes it the error. The removed
 * subtree is the empty solid, so it empties an intersection. */
static void test_multmatrix_not_finite(void **state)
{
    (void)state;
    static const char *const matrices[] = {
        "[[1, 0, 0, inf], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "[[1, 0, 0, 0], [0, nan, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "[[-inf, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
        "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, nan]]"};
    for (size_t k = 0; k < sizeof matrices / sizeof *matrices; k++) {
        char text[512];
        snprintf(
            text, sizeof text,
            "cube(size = [1, 1, 1]);\ngroup() {\n  multmatrix(%s) {\n"
            "    multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
            "{ cube(size = [1, 1, 1]); }\n  }\n}\n",
            matrices[k]);
        for (int faithful = 0; faithful < 2; faithful++) {
            sc_scene *s = NULL;
            sc_error e;
            sc_load_options o;
            sc_load_options_init(&o);
            o.faithful = faithful;
            assert_int_equal(
                sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e), SC_OK);
            assert_int_equal(sc_scene_warning_count(s), 1);
            assert_string_equal(sc_scene_warning(s, 0)->message,
                                "Transformation matrix contains Not-a-Number and/or "
                                "Infinity - removing object.");
            assert_int_equal(sc_scene_warning(s, 0)->line, 3);
            assert_int_equal(sc_scene_warning(s, 0)->column, 3);
            assert_true(inside(s, 0.5, 0.5, 0.5));
            assert_false(inside(s, 5.5, 0.5, 0.5));
            sc_scene_release(s);
        }
        check_error_strict(text, SC_ERR_SEMANTIC,
                           "m.csg:3:3: error: multmatrix: matrix entries must be finite");
    }
    sc_scene *s = load_warned(
        "intersection() {\n  cube(5);\n"
        "  multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ cube(1); }\n}\n",
        "m.csg:3:3: Transformation matrix contains Not-a-Number and/or Infinity - "
        "removing object.");
    assert_true(is_empty(s));
    sc_scene_release(s);
    /* errors below it are still errors */
    check_error("multmatrix([[nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
                "{ torus(r1 = \"a\"); }",
                SC_ERR_SEMANTIC,
                "m.csg:1:85: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
}

static void test_singular(void **state)
{
    (void)state;
    /* OpenSCAD writes scale([1, 0, 1]) this way. */
    sc_scene *s = load_warned(
        "group() {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    cube(size = [1, 1, 1], center = false);\n"
        "  }\n"
        "}\n",
        "m.csg:2:3: singular transform: subtree is empty");
    assert_true(is_empty(s));
    sc_scene_release(s);

    /* The rest of the file still counts; an intersection with the flattened
     * subtree is empty. */
    s = load_warned(
        "sphere(1);\n"
        "intersection() {\n"
        "  cube(5);\n"
        "  multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
        "cube(1); }\n"
        "}\n",
        "m.csg:4:3: singular transform: subtree is empty");
    assert_int_equal(scene_tree(s)->nodes[scene_tree(s)->root].op, CSG_LEAF);
    assert_true(inside(s, 0, 0, 0));
    assert_false(inside(s, 3, 3, 3));
    sc_scene_release(s);

    /* The warning is at the matrix that makes the product singular. */
    s = load_warned(
        "multmatrix([[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "  multmatrix([[1, 0, 0, 0], [-1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
        "cube(); } }",
        "m.csg:2:3: singular transform: subtree is empty");
    assert_true(is_empty(s));
    sc_scene_release(s);

    /* OpenSCAD removes a Nef polyhedron (a union of two solids) with its
     * own warning, where it flattens a mesh. */
    s = load_warned(
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n"
        "  union() {\n"
        "    cube(size = [1, 1, 1], center = false);\n"
        "    multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
        "cube(); }\n"
        "  }\n"
        "}\n",
        "m.csg:1:1: Scaling a 3D object with 0 - removing object");
    assert_true(is_empty(s));
    sc_scene_release(s);

    /* Errors under a singular transform are still errors. */
    check_error("multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
                "roof(); }",
                SC_ERR_UNSUPPORTED, "m.csg:1:71: error: 'roof' is not supported yet");
}

/* ---- colours ---- */

static void check_color(const char *text, float r, float g, float b, float a)
{
    sc_scene *s = load(text);
    const csg_leaf *l = only_leaf(s);
    assert_true(fabsf(l->color[0] - r) < 1e-6f);
    assert_true(fabsf(l->color[1] - g) < 1e-6f);
    assert_true(fabsf(l->color[2] - b) < 1e-6f);
    assert_true(fabsf(l->color[3] - a) < 1e-6f);
    sc_scene_release(s);
}

static void test_colors(void **state)
{
    (void)state;
    const float cr = 249 / 255.0f, cg = 215 / 255.0f, cb = 44 / 255.0f; /* Cornfield */
    check_color("cube();", cr, cg, cb, 1);
    check_color("color([1, 0, 0, 1]) { cube(size = [1, 1, 1], center = false); }", 1, 0,
                0, 1);
    check_color("color([0, 0.5, 1]) { cube(); }", 0, 0.5f, 1, 1);
    check_color("color([0.5]) { cube(); }", 0.5f, 1, 1, 1); /* missing components are 1 */
    check_color("color(c = [0.2, 0.4, 0.6, 0.8]) { cube(); }", 0.2f, 0.4f, 0.6f, 0.8f);
    check_color("color(\"red\") { cube(); }", 1, 0, 0, 1);
    check_color("color(\"DarkSlateGray\") { cube(); }", 47 / 255.0f, 79 / 255.0f,
                79 / 255.0f, 1);
    check_color("color(\"transparent\") { cube(); }", 0, 0, 0, 0);
    check_color("color(\"#f00\") { cube(); }", 1, 0, 0, 1);
    check_color("color(\"#12AB34\") { cube(); }", 0x12 / 255.0f, 0xab / 255.0f,
                0x34 / 255.0f, 1);
    check_color("color(\"#ff000080\") { cube(); }", 1, 0, 0, 0x80 / 255.0f);
    check_color("color(\"#f008\") { cube(); }", 1, 0, 0, 0x88 / 255.0f);
    check_color("color(\"blue\", 0.5) { cube(); }", 0, 0, 1, 0.5f);
    check_color("color([1, 0, 0, 0.5], alpha = 0.7) { cube(); }", 1, 0, 0, 0.7f);
    /* Outer wins over inner, as in OpenSCAD 2021.01's preview (a colour is
     * set only where none is); siblings and ancestors keep their own. */
    check_color("color(\"red\") { color(\"blue\") { cube(); } }", 1, 0, 0, 1);
    check_color("color([1, 0, 0, 0.5]) { color(alpha = 1, c = \"yellow\") { cube(); } }",
                1, 0, 0, 0.5f);
    check_color("color([-1, -1, -1, 1]) { color(\"blue\") { cube(); } }", 0, 0, 1, 1);
    check_color("color(\"red\") { multmatrix() { group() { cube(); } } }", 1, 0, 0, 1);
    /* A negative component is OpenSCAD's "none" for it: the colour is not
     * set (a colour inside still applies, the inherited one stays), and
     * where none applies the default fills it in (Renderer::setColor). */
    check_color("color(\"red\") { color([-1, -1, -1, 1]) { cube(); } }", 1, 0, 0, 1);
    check_color("color([-1, -1, -1, 0.3]) { cube(); }", cr, cg, cb, 0.3f);
    check_color("color(alpha = 0.3) { cube(); }", cr, cg, cb, 0.3f);
    check_color("color(alpha = 0.3) { color(\"red\") { cube(); } }", 1, 0, 0, 1);
    check_color("color([1, 0, 0, -1]) { cube(); }", 1, 0, 0, 1);
    check_color("color([1, 0, 0, -1]) { color(\"blue\") { cube(); } }", 0, 0, 1, 1);

    sc_scene *s = load("group() { color(\"lime\") { cube(); } cube(); }");
    assert_true(scene_tree(s)->leaves[0].color[1] == 1.0f);
    assert_true(fabsf(scene_tree(s)->leaves[1].color[0] - cr) < 1e-6f);
    sc_scene_release(s);

    /* OpenSCAD 2021.01's colour warnings; the components clamped, silently
     * for alpha, as OpenSCAD says nothing of it */
    s = load_warned("color(\"nosuch\") { cube(); }",
                    "m.csg:1:7: Unable to parse color \"nosuch\"");
    assert_true(fabsf(only_leaf(s)->color[0] - cr) < 1e-6f);
    sc_scene_release(s);
    s = load_warned(
        "color([2, 0.5, 0]) { cube(); }",
        "m.csg:1:8: color() expects numbers between 0.0 and 1.0. Value of 2.0 is "
        "out of range");
    assert_true(only_leaf(s)->color[0] == 1.0f);
    sc_scene_release(s);
    /* a negative alpha is "none": the default colour's, opaque */
    s = load("color(\"red\", alpha = -0.5) { cube(); }");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(only_leaf(s)->color[3] == 1.0f);
    sc_scene_release(s);
    /* what OpenSCAD reads silently: c of another type sets no colour, a
     * component that is not a number is 0, an alpha that is not one is
     * left out */
    /* OpenSCAD's export of a .scad it converted: the warnings of its
     * arguments were OpenSCAD's to give */
    sc_load_options o;
    sc_load_options_init(&o);
    o.openscad_export = 1;
    sc_error e;
    static const char export[] = "color([1.5, 0, 0, 3]) { cube(1, zz = 1); }";
    assert_int_equal(sc_scene_load_string("m.csg", export, strlen(export), &o, &s, &e),
                     SC_OK);
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_release(s);
    s = load(export);
    assert_int_equal(sc_scene_warning_count(s), 3);
    sc_scene_release(s);
    s = load("color(c = 5) { cube(); }");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(fabsf(only_leaf(s)->color[0] - cr) < 1e-6f);
    sc_scene_release(s);
    s = load("color([1, \"0\", 0.5], alpha = \"half\") { cube(); }");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(only_leaf(s)->color[0] == 1.0f && only_leaf(s)->color[1] == 0.0f &&
                only_leaf(s)->color[2] == 0.5f && only_leaf(s)->color[3] == 1.0f);
    sc_scene_release(s);
}

static void test_color_table(void **state)
{
    (void)state;
    assert_int_equal(colors_count(), 149);
    float rgba[4];
    for (size_t i = 0; i < colors_count(); i++) {
        const char *name = colors_name(i);
        assert_true(colors_lookup(name, strlen(name), rgba));
        if (i > 0)
            assert_true(strcmp(colors_name(i - 1), name) < 0); /* sorted */
        char upper[64];
        size_t n = strlen(name);
        for (size_t k = 0; k <= n; k++)
            upper[k] = (char)(name[k] >= 'a' && name[k] <= 'z' ? name[k] - 32 : name[k]);
        assert_true(colors_lookup(upper, n, rgba));
    }
    assert_null(colors_name(149));
    assert_true(colors_lookup("Grey", 4, rgba) && rgba[0] == 128 / 255.0f);
    assert_true(colors_lookup("rebeccapurple", 13, rgba) && rgba[2] == 153 / 255.0f);
    assert_true(colors_lookup("YellowGreen", 11, rgba) && rgba[0] == 154 / 255.0f);
    assert_false(colors_lookup("", 0, rgba));
    assert_false(colors_lookup("reds", 4, rgba));
    assert_false(colors_lookup("#ff", 3, rgba));
    assert_false(colors_lookup("#ggg", 4, rgba));
    assert_false(colors_lookup("#12345", 6, rgba));
    assert_false(colors_lookup("red\0", 4, rgba));
    assert_false(colors_lookup("aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa", 40, rgba));
}

/* ---- modifiers ---- */

static void test_modifiers(void **state)
{
    (void)state;
    /* '%' is not part of the solid, nor an operand: here the sphere
     * becomes the first child of the difference. */
    sc_scene *s =
        load("difference() { %cube(10, center = true); sphere(1); cube(0.5); }");
    assert_true(inside(s, -0.5, 0, 0));
    assert_false(inside(s, 0.25, 0.25, 0.25));
    assert_false(inside(s, 3, 3, 3));
    assert_int_equal(scene_tree(s)->leaf_count, 2);
    sc_scene_release(s);

    /* '#' is part of it. */
    s = load("#cube(2);");
    assert_true(inside(s, 1, 1, 1));
    sc_scene_release(s);

    /* '*' is dropped, unread: even an unknown node inside is fine. */
    s = load("*cube(2); *group() { frobnicate(); } sphere(1);");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    sc_scene_release(s);

    /* Stacked modifiers: background wins over highlight. */
    s = load("#%cube(); %#sphere();");
    assert_true(is_empty(s));
    sc_scene_release(s);

    /* Children of a background node are checked all the same. */
    check_error("%group() { roof(); }", SC_ERR_UNSUPPORTED,
                "m.csg:1:12: error: 'roof' is not supported yet");
    check_error("%torus(r1 = \"x\");", SC_ERR_SEMANTIC,
                "m.csg:1:13: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
}

/* The tree of the preview's modifier parts of one kind. */
static const csg_tree *part_tree(const sc_scene *s, int kind)
{
    return scene_shading(s)->overlay[kind];
}

static int inside_part(const sc_scene *s, int kind, double x, double y, double z)
{
    const csg_tree *t = part_tree(s, kind);
    return t && csg_inside(t, v3(x, y, z));
}

/* The preview's parts: each '#' and '%' subtree whole, with its
 * ancestors' transform and colour, in a tree of its own; a '%' below a
 * '#' stays out of the highlight; parts outside the '!' subtree are not
 * kept; the solid and its warnings are the same as without them. */
static void test_modifier_parts(void **state)
{
    (void)state;
    sc_scene *s = load("color([0, 1, 0, 0.5]) { multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], "
                       "[0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
                       "  difference() { cube(4, center = true); #sphere(1); }\n"
                       "  %cylinder(h = 1, r1 = 1, r2 = 1);\n"
                       "} }\n"
                       "#group() { cube(1); %sphere(r = 1); }\n"
                       "%group() { #multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
                       "[0, 0, 1, -5], [0, 0, 0, 1]]) { cube(1); } }\n");
    /* The solid: the drilled cube and the '#' group's cube. */
    assert_false(inside(s, 10, 0, 0));
    assert_true(inside(s, 11.5, 0, 0));
    assert_true(inside(s, 0.5, 0.5, 0.5));
    assert_false(inside(s, 0.5, 0.5, 0.2 - 5));
    assert_int_equal(sc_scene_warning_count(s), 0);
    /* Highlighted: the subtracted sphere where it was, the group's cube
     * without its '%' sphere, and the cube under the '%' group. */
    assert_true(inside_part(s, SHADING_OVERLAY_HIGHLIGHT, 10, 0, 0));
    assert_true(inside_part(s, SHADING_OVERLAY_HIGHLIGHT, 0.5, 0.5, 0.5));
    assert_false(inside_part(s, SHADING_OVERLAY_HIGHLIGHT, -0.5, 0, 0));
    assert_true(inside_part(s, SHADING_OVERLAY_HIGHLIGHT, 0.5, 0.5, 0.5 - 5));
    assert_false(inside_part(s, SHADING_OVERLAY_HIGHLIGHT, 11.5, 0, 0));
    const csg_tree *h = part_tree(s, SHADING_OVERLAY_HIGHLIGHT);
    assert_int_equal(h->leaf_count, 3);
    /* Background: the cylinder (with the colour above it), the sphere,
     * and the whole '%' group. */
    assert_true(inside_part(s, SHADING_OVERLAY_BACKGROUND, 10, 0, 0.5));
    assert_true(inside_part(s, SHADING_OVERLAY_BACKGROUND, -0.5, 0, 0));
    assert_true(inside_part(s, SHADING_OVERLAY_BACKGROUND, 0.5, 0.5, 0.5 - 5));
    const csg_tree *g = part_tree(s, SHADING_OVERLAY_BACKGROUND);
    assert_int_equal(g->leaf_count, 3);
    int green = 0;
    for (uint32_t k = 0; k < g->leaf_count; k++)
        green += g->leaves[k].color[1] == 1.0f && g->leaves[k].color[3] == 0.5f;
    assert_int_equal(green, 1);
    sc_scene_release(s);

    /* Without modifiers there are no parts; outside the '!' subtree the
     * parts are not the design's. */
    s = load("cube(1); sphere(2);");
    assert_null(part_tree(s, SHADING_OVERLAY_HIGHLIGHT));
    assert_null(part_tree(s, SHADING_OVERLAY_BACKGROUND));
    sc_scene_release(s);
    s = load("#cube(1); !group() { %sphere(2); cube(3); }");
    assert_null(part_tree(s, SHADING_OVERLAY_HIGHLIGHT));
    assert_true(inside_part(s, SHADING_OVERLAY_BACKGROUND, 1.5, 0, 0));
    sc_scene_release(s);
}

static void test_root_modifier(void **state)
{
    (void)state;
    /* The '!' subtree is the design: its ancestors' transform and colour
     * do not apply, its siblings are gone, its own arguments count. */
    sc_scene *s =
        load("cube(100);\n"
             "color(\"red\") { multmatrix([[1, 0, 0, 50], [0, 1, 0, 0], [0, 0, 1, 0], "
             "[0, 0, 0, 1]]) {\n"
             "  sphere(5);\n"
             "  !multmatrix([[1, 0, 0, 0], [0, 1, 0, 7], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
             "    cube(1);\n"
             "  }\n"
             "} }\n"
             "sphere(20);\n");
    const csg_leaf *l = only_leaf(s);
    assert_int_equal(l->prim.kind, PRIM_BOX);
    affine to_world = test_leaf_to_world(l);
    assert_near(to_world.m[0][3], 0);
    assert_near(to_world.m[1][3], 7);
    assert_true(fabsf(l->color[0] - 249 / 255.0f) < 1e-6f);
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_release(s);

    /* The first '!' wins, with OpenSCAD's warning once, at the second. */
    s = load_warned("!sphere(1);\n!cube(3);\n!cube(4);",
                    "m.csg:2:2: More than one Root Modifier (!)");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    sc_scene_release(s);

    /* Under '*', a '!' is never seen. A root that is also '%' is drawn:
     * the background modifier leaves a node out of its parent, and
     * OpenSCAD's render of the root has none (openscad exports the sphere,
     * written either way round). */
    s = load("*group() { !sphere(1); } cube(2);");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_BOX);
    sc_scene_release(s);
    s = load("!%sphere(1); cube(2);");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    sc_scene_release(s);
    s = load("%!sphere(1); cube(2);");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    sc_scene_release(s);

    /* A root under a singular transform or a background node is built. */
    s = load("%multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
             "!color(\"red\") { sphere(2); } }");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_SPHERE);
    assert_true(only_leaf(s)->color[0] == 1.0f);
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_release(s);

    /* The rest of the file is still checked. */
    check_error("!cube(); torus(r1 = \"a\");", SC_ERR_SEMANTIC,
                "m.csg:1:21: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
}

/* ---- node names ---- */

static void test_unsupported(void **state)
{
    (void)state;
    static const char *names[] = {"roof", "halfspace"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char text[256], expected[256];
        snprintf(text, sizeof text, "group() {\n  cube();\n\n    %s() { cube(); }\n}",
                 names[i]);
        snprintf(expected, sizeof expected, "m.csg:4:5: error: '%s' is not supported yet",
                 names[i]);
        check_error(text, SC_ERR_UNSUPPORTED, expected);
    }
    check_error("group() {\n  cube();\n    %roof() {\n cube(); }\n}", SC_ERR_UNSUPPORTED,
                "m.csg:3:6: error: 'roof' is not supported yet");
    check_error("linear_extrude(height = 10, center = false, convexity = 1, twist = 90, "
                "$fn = 0, $fa = 12, $fs = 2) {\n  roof() { square(); }\n}",
                SC_ERR_UNSUPPORTED,
                "m.csg:2:3: error: 'roof' inside linear_extrude is not supported yet");
    /* A name OpenSCAD does not know is left out with OpenSCAD's warning
     * (an error with --strict), and so are its children. */
    sc_scene *s = load_warned("group() { foo() { sphere(2); } } cube(1);",
                              "m.csg:1:11: Ignoring unknown module 'foo'");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_BOX);
    assert_int_equal(sc_scene_warning_count(s), 1);
    sc_scene_release(s);
    check_error_strict("Cube();", SC_ERR_SEMANTIC,
                       "m.csg:1:1: error: Ignoring unknown module 'Cube'");
    /* polyhedron's old name for its faces, with OpenSCAD's note */
    s = load_warned("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
                    "triangles = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);",
                    "m.csg:1:1: polyhedron(triangles=[]) will be removed in future "
                    "releases. Use polyhedron(faces=[]) instead.");
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    sc_scene_release(s);
}

static void test_leaf_children(void **state)
{
    (void)state;
    sc_scene *s = load_warned("cube(1) { sphere(5); }",
                              "m.csg:1:1: module cube() does not support child modules");
    assert_int_equal(only_leaf(s)->prim.kind, PRIM_BOX);
    sc_scene_release(s);
    s = load("cube(1) { }");
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_release(s);
}

/* The solid's own box (csg/bounds.h), which frames the render: a sphere
 * cut flat (a face square to the axis, and a sphere's equator), and a
 * tetrahedron cut by a slab, whose farthest points in x and y are where
 * the slab's top crosses two edges (a vertex of the result that no leaf
 * has). The tree's box holds the cut-away parts. */
static void check_solid_box(const char *text, const double lo[3], const double hi[3],
                            double tree_hi_z)
{
    sc_scene *s = load(text);
    const shading *look = scene_shading(s);
    assert_true(look->has_solid_box);
    double got[6] = {look->solid_box.lo.x, look->solid_box.lo.y, look->solid_box.lo.z,
                     look->solid_box.hi.x, look->solid_box.hi.y, look->solid_box.hi.z};
    for (int i = 0; i < 3; i++) {
        assert_near_tol(got[i], lo[i], 1e-6);
        assert_near_tol(got[3 + i], hi[i], 1e-6);
    }
    assert_near(s->tree->bounds.hi.z, tree_hi_z);
    sc_scene_release(s);
}

static void test_solid_box(void **state)
{
    (void)state;
    check_solid_box("difference() { sphere(r = 10); "
                    "multmatrix([[1, 0, 0, -20], [0, 1, 0, -20], [0, 0, 1, 5], "
                    "[0, 0, 0, 1]]) cube(size = [40, 40, 40]); }",
                    (double[3]){-10, -10, -10}, (double[3]){10, 10, 5}, 10);
    /* The slab's top (z = 2) is a quarter of the way to the apex (9, 7, 8):
     * the edges from (4, 1, 0) and (1, 4, 0) cross it at (5.25, 2.5, 2) and
     * (3, 4.75, 2). */
    check_solid_box("intersection() { polyhedron(points = [[0, 0, 0], [4, 1, 0], "
                    "[1, 4, 0], [9, 7, 8]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], "
                    "[1, 3, 2]], convexity = 1); "
                    "multmatrix([[1, 0, 0, -5], [0, 1, 0, -5], [0, 0, 1, 0], "
                    "[0, 0, 0, 1]]) cube(size = [20, 20, 2]); }",
                    (double[3]){0, 0, 0}, (double[3]){5.25, 4.75, 2}, 2);
    /* Three cylinders of radius 1, the second and third tilted by 72 and
     * 81 degrees, the first cut by a box: the lowest point is the third's
     * rim, at -sin 81 degrees. Searched as one, the difference's grid found
     * the second's rim (-sin 72) and stopped there; each part is searched
     * over its own box. The highest is the second's far rim, which the box
     * (x up to 20) does not reach. */
    const double pi = 3.14159265358979323846;
    double c72 = cos(72 * pi / 180), s72 = sin(72 * pi / 180);
    double c81 = cos(81 * pi / 180), s81 = sin(81 * pi / 180);
    char text[1024];
    snprintf(text, sizeof text,
             "difference() { union() { cylinder(h = 8, r1 = 1, r2 = 1, center = false); "
             "multmatrix([[%.17g, 0, %.17g, 24], [0, 1, 0, 0], [%.17g, 0, %.17g, 0], "
             "[0, 0, 0, 1]]) cylinder(h = 8, r1 = 1, r2 = 1, center = false); "
             "multmatrix([[%.17g, 0, %.17g, 27], [0, 1, 0, 0], [%.17g, 0, %.17g, 0], "
             "[0, 0, 0, 1]]) cylinder(h = 8, r1 = 1, r2 = 1, center = false); } "
             "multmatrix([[1, 0, 0, -20], [0, 1, 0, -5], [0, 0, 1, 1], [0, 0, 0, 1]]) "
             "cube(size = [40, 10, 10]); }",
             c72, s72, -s72, c72, c81, s81, -s81, c81);
    sc_scene *s = load(text);
    const shading *look = scene_shading(s);
    assert_true(look->has_solid_box);
    assert_near_tol(look->solid_box.lo.z, -s81, 1e-6);
    /* On the round rim of an exact cylinder the search stops within 1e-6
     * of the model's size (36 across; 1.7e-5 off here), as the ridge
     * curves under its steps; a polygonal rim ends at its vertex. */
    assert_near_tol(look->solid_box.hi.z, 8 * c72 + s72, 36e-6);
    sc_scene_release(s);
}

/* ---- polyhedra ---- */

static const char tetrahedron[] =
    "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
    "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);";

/* A cube of side 2 at the origin, quads, listed clockwise from outside as
 * OpenSCAD writes them. */
#define CUBE_POINTS                                                                      \
    "[[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], [2, 0, 2], [2, 2, 2], [0, " \
    "2, "                                                                                \
    "2]]"
#define CUBE_FACES                                                                       \
    "[[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, "  \
    "3]]"

static void test_polyhedron_convex(void **state)
{
    (void)state;
    sc_scene *s = load(tetrahedron);
    const csg_leaf *l = only_leaf(s);
    assert_int_equal(l->prim.kind, PRIM_CONVEX);
    assert_int_equal(l->prim.u.convex.count, 4);
    assert_near(l->prim.u.convex.bounds.hi.x, 1);
    assert_true(inside(s, 0.1, 0.1, 0.1));
    assert_false(inside(s, 0.5, 0.5, 0.5));
    assert_false(inside(s, -0.1, 0.1, 0.1));
    for (uint32_t i = 0; i < 4; i++) {
        const plane *p = &l->prim.u.convex.planes[i];
        assert_true(v3_dot(p->n, v3(0.1, 0.1, 0.1)) < p->d); /* outward */
        assert_near(v3_length(p->n), 1);
    }
    sc_scene_release(s);

    /* Quads, both windings. */
    s = load("polyhedron(points = " CUBE_POINTS ", faces = " CUBE_FACES ");");
    assert_int_equal(only_leaf(s)->prim.u.convex.count, 6);
    assert_true(inside(s, 1, 1, 1));
    assert_true(inside(s, 1.9, 0.1, 1.9));
    assert_false(inside(s, 2.1, 1, 1));
    sc_scene_release(s);
    s = load("polyhedron(" CUBE_POINTS ", [[3, 2, 1, 0], [0, 1, 5, 4], [4, 5, 6, 7], "
             "[1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]);");
    assert_true(inside(s, 1, 1, 1));
    assert_false(inside(s, 1, 1, 2.5));
    sc_scene_release(s);

    /* Triangles: coplanar pairs merge into one plane; the older
     * `triangles` name is read too (with OpenSCAD's note); unused points
     * are fine. */
    s = load_warned(
        "polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], "
        "[2, 0, 2], [2, 2, 2], [0, 2, 2], [50, 50, 50]], triangles = [[0, 1, 2], [0, 2, "
        "3], [4, 5, 1], [4, 1, 0], [7, 6, 5], [7, 5, 4], [5, 6, 2], [5, 2, 1], [6, 7, "
        "3], "
        "[6, 3, 2], [7, 4, 0], [7, 0, 3]]);",
        "m.csg:1:1: polyhedron(triangles=[]) will be removed in future releases. Use "
        "polyhedron(faces=[]) instead.");
    assert_int_equal(only_leaf(s)->prim.u.convex.count, 6);
    assert_true(inside(s, 1, 1, 1));
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    assert_near(hi[0], 2);
    sc_scene_release(s);

    /* 6-digit rounding of a rotated cube stays convex. */
    s = load(
        "polyhedron(points = [[0, 0, 0], [0.707107, 0.707107, 0], [0, 1.41421, 0], "
        "[-0.707107, 0.707107, 0], [0, 0, 1], [0.707107, 0.707107, 1], [0, 1.41421, 1], "
        "[-0.707107, 0.707107, 1]], faces = " CUBE_FACES ");");
    assert_true(inside(s, 0, 0.7, 0.5));
    sc_scene_release(s);

    /* Under a transform. */
    s = load("multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
             "polyhedron(points = " CUBE_POINTS ", faces = " CUBE_FACES "); }");
    assert_true(inside(s, 11, 1, 1));
    assert_false(inside(s, 1, 1, 1));
    sc_scene_release(s);
}

static void test_polyhedron_errors(void **state)
{
    (void)state;
    /* Non-convex polyhedra are meshes now (test_build_mesh.c). */
    /* Open: the cube without its top (an error with --strict, else a
     * warning: test_build_mesh.c). */
    check_error_strict(
        "polyhedron(points = " CUBE_POINTS ", faces = [[0, 1, 2, 3], [4, 5, 1, 0], "
        "[5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);",
        SC_ERR_SEMANTIC,
        "m.csg:1:1: error: polyhedron is not closed (edge 4-5 is used by 1 face)");
    check_error_strict(
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2], [0, 1, 3]]);",
        SC_ERR_SEMANTIC,
        "m.csg:1:1: error: polyhedron is not closed (edge 0-1 is used by 3 faces)");
    /* an index out of range is a warning (test_build_mesh.c), and with
     * --strict the error */
    const char *tetra_bad =
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2.5], [0, 1, 4], [-1, 2], [3]]);";
    check_error_strict(
        tetra_bad, SC_ERR_SEMANTIC,
        "m.csg:1:129: error: polyhedron face 4: point index 4 is out of range "
        "(4 points)");
    /* a face of fewer than 3 points is a warning (test_build_mesh.c), and
     * with --strict the error, at the first such face */
    check_error_strict(
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2], [], [0, 1]]);",
        SC_ERR_SEMANTIC, "m.csg:1:120: error: polyhedron face 4 has fewer than 3 points");
    /* a point OpenSCAD cannot convert is a warning (test_build_mesh.c),
     * and with --strict the error */
    check_error_strict(
        "polyhedron(points = [[0, 0, 0], [1, 0, \"a\"], [0, 1, 0]], faces = [[0, 1, "
        "2]]);",
        SC_ERR_SEMANTIC,
        "m.csg:1:33: error: wrong type for argument 'points' of 'polyhedron' (expected "
        "a vector of [x, y, z] points)");
    /* points that are not a vector are none: every index out of range */
    check_error_strict("polyhedron(points = 3, faces = [[0, 1, 2]]);", SC_ERR_SEMANTIC,
                       "m.csg:1:34: error: polyhedron face 0: point index 0 is out of "
                       "range (0 points)");
    check_error_strict(
        "polyhedron(points = [[0, 0, 0], [1, 0, inf], [0, 1, 0]], faces = [[0, 1, 2]]);",
        SC_ERR_SEMANTIC, "m.csg:1:33: error: polyhedron point 1 is not finite");
    /* an index that is not a number is 0, as OpenSCAD 2021.01 converts it
     * (Value::toDouble): the tetrahedron's last face, [0, 3, 2] */
    sc_scene *s =
        load("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
             "faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [\"x\", 3, 2]]);");
    assert_false(is_empty(s));
    sc_scene_release(s);
    /* a face that is not a vector is an empty one (OpenSCAD warns of it
     * as it tessellates), faces that are not a vector none, as OpenSCAD
     * 2021.01 reads them (Value::toVector) */
    const char *const empty_face[] = {
        "m.csg:1:43: PolySet has degenerate polygons (faces[0] has fewer than 3 points; "
        "left out, as OpenSCAD leaves it out)",
        "m.csg:1:1: polyhedron without faces is empty"};
    s = test_check_warnings("m.csg", "polyhedron(points = [[0, 0, 0]], faces = [0]);", 0,
                            empty_face, 2);
    sc_scene_release(s);
    const char *const old_name[] = {
        "m.csg:1:1: polyhedron(triangles=[]) will be removed in future releases. Use "
        "polyhedron(faces=[]) instead.",
        "m.csg:1:1: polyhedron without faces is empty"};
    s = test_check_warnings("m.csg", "polyhedron(points = [[0, 0, 0]], triangles = 7);",
                            0, old_name, 2);
    sc_scene_release(s);
}

static void test_polyhedron_empty(void **state)
{
    (void)state;
    sc_scene *s = load_warned("polyhedron(points = [], faces = [], convexity = 1);",
                              "m.csg:1:1: polyhedron without faces is empty");
    assert_true(is_empty(s));
    sc_scene_release(s);
    s = load_warned("polyhedron();", "m.csg:1:1: polyhedron without faces is empty");
    sc_scene_release(s);
    /* Flat: two triangles back to back. */
    s = load_warned(
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = [[0, 1, "
        "2], [0, 2, 1]]);",
        "m.csg:1:1: polyhedron without volume is empty");
    assert_true(is_empty(s));
    sc_scene_release(s);
}

/* A file exactly as OpenSCAD 2021.01 wrote it (tests/data/openscad_export.csg,
 * from a model with translate, rotate, scale, mirror, color with alpha, a
 * cone, a for loop, a module, render, if, '%' and '#'). */
static void test_openscad_export(void **state)
{
    (void)state;
    sc_scene *s = NULL;
    sc_error e;
    char buf[1024];
    const char *path = SPANCAST_SOURCE_DIR "/tests/data/openscad_export.csg";
    if (sc_scene_load(path, NULL, &s, &e) != SC_OK)
        fail_msg("%s", sc_error_format(&e, buf, sizeof buf));
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_info info;
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(s, &info, NULL), SC_OK);
    assert_int_equal(info.leaf_count, 14); /* the '%' cube is not built */
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    assert_near(lo[0], -15); /* the cone at x = -10, r1 = 5 */
    assert_near(lo[1], -40); /* the '#' cube */
    assert_near(lo[2], -4);  /* the intersection */
    assert_near(hi[0], 31);  /* the polyhedron at x = 30 */
    assert_near(hi[1], 14);  /* the sphere scaled by 2 in y */
    assert_near(hi[2], 15);  /* the cone's apex */
    assert_true(inside(s, 2.5, -37.5, 2.5));
    assert_false(inside(s, 2.5, 42.5, 2.5));
    assert_true(inside(s, 0, 10, 0));
    assert_false(inside(s, 0, 8, 0)); /* drilled by the for loop */
    assert_true(inside(s, 30.1, 0.1, 0.1));
    const csg_tree *t = scene_tree(s);
    int cones = 0;
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        const csg_leaf *l = &t->leaves[i];
        if (l->prim.kind == PRIM_CYLINDER && l->prim.u.cylinder.r0 == 5) {
            cones++;
            assert_true(fabsf(l->color[2] - 0.705882f) < 1e-6f);
            assert_true(fabsf(l->color[3] - 0.8f) < 1e-6f);
            assert_int_equal(l->loc.line, 13);
            assert_int_equal(l->loc.column, 5);
        }
    }
    assert_int_equal(cones, 1);
    sc_scene_release(s);
}

/* ---- limits and loading ---- */

static char *nested_groups(int n)
{
    const char *open =
        "multmatrix([[1, 0, 0, 0.001], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {";
    size_t lo = strlen(open);
    char *s = malloc((size_t)n * (lo + 1) + 32);
    assert_non_null(s);
    char *p = s;
    for (int i = 0; i < n; i++, p += lo)
        memcpy(p, open, lo);
    p += sprintf(p, "cube();");
    memset(p, '}', (size_t)n);
    p[n] = '\0';
    return s;
}

static void test_deep_nesting(void **state)
{
    (void)state;
    char *text = nested_groups(PARSE_MAX_DEPTH - 1);
    sc_scene *s = load(text);
    const csg_leaf *l = only_leaf(s);
    assert_true(fabs(test_leaf_to_world(l).m[0][3] - 9.999) < 1e-9);
    sc_scene_info info;
    sc_scene_info_init(&info);
    assert_int_equal(sc_scene_get_info(s, &info, NULL), SC_OK);
    assert_int_equal(info.node_count, 1);
    assert_int_equal(info.depth, 1);
    sc_scene_release(s);
    free(text);

    text = nested_groups(PARSE_MAX_DEPTH);
    check_error(text, SC_ERR_LIMIT,
                "m.csg:1:740001: error: too many nested nodes (limit is "
                "10000)");
    free(text);
}

static void test_load_file(void **state)
{
    (void)state;
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    char buf[1024];
    assert_int_equal(sc_scene_load("/nonexistent/x.csg", NULL, &s, &e), SC_ERR_IO);
    assert_null(s);
    assert_string_equal(
        sc_error_format(&e, buf, sizeof buf),
        "error: cannot open '/nonexistent/x.csg': No such file or directory");

    /* ctest runs the test in its build folder. */
    const char path[] = "test_build_tmp.csg";
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs("group() {\n  sphere($fn = 0, $fa = 12, $fs = 2, r = 2);\n}\n", f);
    fclose(f);
    sc_load_options options;
    sc_load_options_init(&options);
    assert_int_equal(options.faithful, 0);
    assert_int_equal(sc_scene_load(path, &options, &s, &e), SC_OK);
    const csg_leaf *l = only_leaf(s);
    assert_string_equal(l->loc.file, path);
    assert_int_equal(l->loc.line, 2);
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(s, lo, hi));
    assert_near(lo[0], -2);
    assert_near(hi[2], 2);
    sc_scene_release(s);

    f = fopen(path, "wb");
    assert_non_null(f);
    fputs("cube();\ncube(\n", f);
    fclose(f);
    assert_int_equal(sc_scene_load(path, NULL, &s, &e), SC_ERR_SYNTAX);
    assert_null(s);
    char expected[256];
    snprintf(expected, sizeof expected,
             "%s:3:1: error: expected a value, found end of file", path);
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
    remove(path);

    assert_int_equal(sc_scene_load("/tmp", NULL, &s, &e), SC_ERR_IO);
    assert_string_equal(sc_error_format(&e, buf, sizeof buf),
                        "error: cannot read '/tmp': Is a directory");
}

static void test_warning_order(void **state)
{
    (void)state;
    sc_scene *s =
        load("cube(0);\ngroup() {\n  sphere(0);\n  color(\"x\") { cube(); }\n}\n"
             "cylinder(h = 0);");
    assert_int_equal(sc_scene_warning_count(s), 4);
    /* the colour's first: OpenSCAD gives it as it instantiates the tree,
     * before any geometry; the empty shapes' then, in file order */
    const int lines[] = {4, 1, 3, 6};
    for (size_t i = 0; i < 4; i++) {
        assert_int_equal(sc_scene_warning(s, i)->line, lines[i]);
        assert_string_equal(sc_scene_warning(s, i)->file, "m.csg");
    }
    assert_null(sc_scene_warning(s, 4));
    sc_scene_release(s);
}

/* The input forms of docs/input.md through the library: a hand-written
 * .csg in OpenSCAD's statement forms builds the tree its braced form
 * builds; OpenSCAD's language beyond the export is an error at its first
 * use (the library runs no OpenSCAD); a .stl path is the model that
 * imports it. */
static void test_input_forms(void **state)
{
    (void)state;
    sc_scene *s = NULL;
    sc_error e;
    char buf[1024];
    const char *path = SPANCAST_SOURCE_DIR "/tests/data/hand_written.csg";
    if (sc_scene_load(path, NULL, &s, &e) != SC_OK)
        fail_msg("%s", sc_error_format(&e, buf, sizeof buf));
    sc_scene *braced = load(
        "difference() {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 0.707107, -0.707107, 0], [0, 0.707107, "
        "0.707107, 0], [0, 0, 0, 1]]) {\n"
        "    color(\"steelblue\", 0.5) { cube(size = [20, 20, 10], center = true); }\n"
        "  }\n"
        "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    cylinder($fn = 0, $fa = 12, $fs = 2, h = 30, r1 = 3, r2 = 3, center = "
        "true);\n"
        "  }\n"
        "  #multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    sphere(r = 4);\n"
        "  }\n"
        "  *sphere(r = 50);\n"
        "}\n"
        "%multmatrix([[1, 0, 0, 30], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "  group() { }\n"
        "}\n");
    sc_scene_info a, b;
    sc_scene_info_init(&a);
    sc_scene_info_init(&b);
    assert_int_equal(sc_scene_get_info(s, &a, NULL), SC_OK);
    assert_int_equal(sc_scene_get_info(braced, &b, NULL), SC_OK);
    assert_int_equal(a.node_count, b.node_count);
    assert_int_equal(a.leaf_count, 3);
    assert_int_equal(a.leaf_count, b.leaf_count);
    assert_int_equal(a.source_node_count, b.source_node_count);
    assert_int_equal(a.depth, b.depth);
    double lo[2][3], hi[2][3];
    assert_true(sc_scene_bounds(s, lo[0], hi[0]));
    assert_true(sc_scene_bounds(braced, lo[1], hi[1]));
    assert_memory_equal(lo[0], lo[1], sizeof lo[0]);
    assert_memory_equal(hi[0], hi[1], sizeof hi[0]);
    sc_scene_release(s);
    sc_scene_release(braced);

    check_error("cube(1);\nsize = 2;\ncube(size);\n", SC_ERR_UNSUPPORTED,
                "m.csg:2:1: error: an assignment ('size = ...') is OpenSCAD's language "
                "beyond its CSG export");
    check_error("translate([1, 0, 0]) cube(1);", SC_ERR_UNSUPPORTED,
                "m.csg:1:1: error: 'translate' is OpenSCAD's language beyond its CSG "
                "export");

    /* A mesh path: the one-line import of it, errors on the whole file. */
    mkdir(SPANCAST_TEST_WORK, 0777);
    const char *stl = SPANCAST_TEST_WORK "/tet.stl";
    const char *bad = SPANCAST_TEST_WORK "/bad.stl";
    FILE *f = fopen(stl, "w");
    assert_non_null(f);
    fputs("solid t\n"
          "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\n"
          "endloop\nendfacet\n"
          "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\n"
          "endloop\nendfacet\n"
          "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\n"
          "endloop\nendfacet\n"
          "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\n"
          "endloop\nendfacet\nendsolid t\n",
          f);
    fclose(f);
    f = fopen(bad, "w");
    assert_non_null(f);
    fputs("solid b\nfacet normal 0 0 1\nouter loop\nvertex 0 0 x\n", f);
    fclose(f);
    s = NULL;
    if (sc_scene_load(stl, NULL, &s, &e) != SC_OK)
        fail_msg("%s", sc_error_format(&e, buf, sizeof buf));
    sc_scene_info_init(&a);
    assert_int_equal(sc_scene_get_info(s, &a, NULL), SC_OK);
    assert_int_equal(a.leaf_count, 1);
    assert_true(sc_scene_bounds(s, lo[0], hi[0]));
    assert_near(hi[0][0], 1);
    sc_scene_release(s);
    s = (sc_scene *)1;
    assert_int_equal(sc_scene_load(bad, NULL, &s, &e), SC_ERR_SEMANTIC);
    assert_null(s);
    /* at the mesh file's own line, which OpenSCAD's reader cannot parse */
    assert_string_equal(e.file, bad);
    assert_int_equal(e.line, 4);
    assert_int_equal(e.column, 1);
    assert_non_null(strstr(e.message, "line 4: can't parse vertex line 'vertex 0 0 x'"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_input_forms),
        cmocka_unit_test(test_cube),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_cylinder),
        cmocka_unit_test(test_empty_primitives),
        cmocka_unit_test(test_wrong_types),
        cmocka_unit_test(test_booleans),
        cmocka_unit_test(test_multmatrix),
        cmocka_unit_test(test_multmatrix_shapes),
        cmocka_unit_test(test_multmatrix_not_finite),
        cmocka_unit_test(test_singular),
        cmocka_unit_test(test_colors),
        cmocka_unit_test(test_color_table),
        cmocka_unit_test(test_modifiers),
        cmocka_unit_test(test_modifier_parts),
        cmocka_unit_test(test_root_modifier),
        cmocka_unit_test(test_unsupported),
        cmocka_unit_test(test_leaf_children),
        cmocka_unit_test(test_polyhedron_convex),
        cmocka_unit_test(test_polyhedron_errors),
        cmocka_unit_test(test_polyhedron_empty),
        cmocka_unit_test(test_openscad_export),
        cmocka_unit_test(test_deep_nesting),
        cmocka_unit_test(test_load_file),
        cmocka_unit_test(test_warning_order),
        cmocka_unit_test(test_solid_box),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
