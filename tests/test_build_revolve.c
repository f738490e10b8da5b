/* Tests of the rotate_extrude builder (src/build/build_revolve.c): the
 * solid each profile makes (tube, torus, cone, partial and negative
 * angles, profiles at x < 0, transforms, holes, several children), the
 * leaf kind in each mode, OpenSCAD's fragment counts and caps in faithful
 * mode, exact and faithful solids agreeing away from the facets, and the
 * exact messages for OpenSCAD's errors and what is not supported.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build/build.h"
#include "build/scene.h"
#include "csg/prim_mesh.h"
#include "csg/prim_revolve.h"
#include "test_util.h"

static sc_scene *load_mode(const char *text, int faithful)
{
    return test_load("m.csg", text, faithful);
}

static sc_scene *load(const char *text)
{
    return load_mode(text, 0);
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    test_check_error("m.csg", text, status, expected);
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static const prim *only_leaf(const sc_scene *s)
{
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 1);
    return &t->leaves[0].prim;
}

#define TRANSLATE(x, y)                                                                  \
    "multmatrix([[1, 0, 0, " #x "], [0, 1, 0, " #y "], [0, 0, 1, 0], [0, 0, 0, 1]])"

/* square([2, 3]) moved to x = 2: a tube r in [2, 4], z in [0, 3] */
#define TUBE "{ " TRANSLATE(2, 0) " { square(size = [2, 3]); } }"

static void test_tube(void **state)
{
    (void)state;
    sc_scene *s = load("rotate_extrude(angle = 360, convexity = 2, $fn = 0, $fa = 12, "
                       "$fs = 2) " TUBE);
    const prim *p = only_leaf(s);
    assert_int_equal(p->kind, PRIM_REVOLVE);
    assert_int_equal(p->u.revolve.rev->edge_count, 4);
    assert_int_equal(p->u.revolve.rev->partial, 0);
    assert_true(inside(s, 3, 0, 1) && inside(s, 0, -3.9, 2.9) && inside(s, -2.1, 0, 0.1));
    assert_false(inside(s, 1.9, 0, 1) || inside(s, 4.1, 0, 1) || inside(s, 0, 3, 3.1) ||
                 inside(s, 0, 0, 1));
    /* the outward normal of the outer wall, through the tree */
    vec3 n = prim_normal(p, v3(4, 0, 1), 1);
    assert_true(n.x > 0 && n.y == 0 && n.z == 0);
    sc_scene_release(s);
}

/* Partial angles: counter-clockwise from +x, negative ones clockwise,
 * beyond the range a full turn, 0 nothing. */
static void test_angles(void **state)
{
    (void)state;
    sc_scene *s = load("rotate_extrude(angle = 90) " TUBE);
    assert_true(inside(s, 2.1, 2.1, 1) && !inside(s, -2.1, 2.1, 1) &&
                !inside(s, 2.1, -2.1, 1));
    assert_int_equal(only_leaf(s)->u.revolve.rev->partial, 1);
    sc_scene_release(s);
    s = load("rotate_extrude(angle = -90) " TUBE);
    assert_true(inside(s, 2.1, -2.1, 1) && !inside(s, 2.1, 2.1, 1) &&
                !inside(s, -2.1, -2.1, 1));
    sc_scene_release(s);
    s = load("rotate_extrude(angle = 270) " TUBE);
    assert_true(inside(s, 2.1, 2.1, 1) && inside(s, -2.1, -2.1, 1) &&
                !inside(s, 2.1, -2.1, 1));
    sc_scene_release(s);
    static const char *const full[] = {"rotate_extrude(angle = 400) " TUBE,
                                       "rotate_extrude(angle = -360) " TUBE,
                                       "rotate_extrude(angle = inf) " TUBE};
    for (size_t i = 0; i < 3; i++) {
        s = load(full[i]);
        assert_int_equal(only_leaf(s)->u.revolve.rev->partial, 0);
        assert_true(inside(s, 2.1, -2.1, 1));
        sc_scene_release(s);
    }
    sc_scene *e = NULL;
    sc_error err;
    const char *zero = "rotate_extrude(angle = 0) " TUBE;
    assert_int_equal(sc_scene_load_string("m.csg", zero, strlen(zero), NULL, &e, &err),
                     SC_OK);
    assert_int_equal(scene_tree(e)->leaf_count, 0);
    assert_int_equal(sc_scene_warning_count(e), 1);
    const sc_error *w = sc_scene_warning(e, 0);
    assert_int_equal(w->status, SC_OK);
    /* sc_error_format calls everything an error; the CLI prints warnings
     * with its own prefix */
    char buf[256];
    assert_string_equal(sc_error_format(w, buf, sizeof buf),
                        "m.csg:1:1: error: rotate_extrude with angle 0 is empty");
    sc_scene_release(e);
}

/* A profile at x <= 0 sweeps from 180 degrees (x goes to x cos a). */
static void test_negative_profile(void **state)
{
    (void)state;
    sc_scene *s =
        load("rotate_extrude(angle = 90) { " TRANSLATE(-4, 0) " { square(size = "
                                                              "[2, 3]); } }");
    assert_true(inside(s, -2.1, -2.1, 1) && !inside(s, 2.1, 2.1, 1) &&
                !inside(s, -2.1, 2.1, 1));
    bbox b = prim_bounds(only_leaf(s));
    assert_true(b.lo.x == -4 && b.lo.y == -4 && b.hi.x == 0 && b.hi.y == 0);
    sc_scene_release(s);
}

/* A circle is a torus (a disc), under a similarity too; under a
 * non-uniform scale its OpenSCAD polygon. */
static void test_circles(void **state)
{
    (void)state;
    sc_scene *s = load("rotate_extrude() { " TRANSLATE(5, 1) " { circle(r = 1); } }");
    const prim_revolve *r = only_leaf(s)->u.revolve.rev;
    assert_int_equal(r->disc_count, 1);
    assert_int_equal(r->edge_count, 0);
    assert_true(r->discs[0].rc == 5 && r->discs[0].zc == 1 && r->discs[0].a == 1);
    assert_true(inside(s, 0, 5.99, 1) && !inside(s, 0, 6.01, 1) && !inside(s, 0, 4, 1.9));
    sc_scene_release(s);
    /* rotated by 90 degrees and scaled by 2: still a circle, radius 2 */
    s = load(
        "rotate_extrude() { multmatrix([[0, -2, 0, 5], [2, 0, 0, 0], [0, 0, 1, 0], [0, "
        "0, 0, 1]]) { circle(r = 1); } }");
    r = only_leaf(s)->u.revolve.rev;
    assert_int_equal(r->disc_count, 1);
    assert_true(r->discs[0].a == 2);
    sc_scene_release(s);
    /* an ellipse: the polygon of circle(r = 1, $fn = 10), scaled */
    s = load(
        "rotate_extrude() { multmatrix([[2, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, "
        "0, 0, 1]]) { circle(r = 1, $fn = 10); } }");
    r = only_leaf(s)->u.revolve.rev;
    assert_int_equal(r->disc_count, 0);
    assert_int_equal(r->edge_count, 10);
    assert_true(inside(s, 6.9, 0, 0) && !inside(s, 5, 0, 0.99));
    sc_scene_release(s);
    /* a circle whose disc would cross the axis though its polygon does not
     * (min x = 0.9 + cos 144 = 0.09): the polygon */
    s = load("rotate_extrude() { " TRANSLATE(0.9, 0) " { circle(r = 1, $fn = 5); } }");
    r = only_leaf(s)->u.revolve.rev;
    assert_int_equal(r->disc_count, 0);
    assert_int_equal(r->edge_count, 5);
    sc_scene_release(s);
}

/* A polygon with a hole (paths, even-odd), and two children united. */
static void test_polygon_paths(void **state)
{
    (void)state;
    sc_scene *s = load("rotate_extrude() { polygon(points = [[1, 0], [5, 0], [5, 4], [1, "
                       "4], [2, 1], [4, 1], [4, 3], [2, 3]], paths = [[0, 1, 2, 3], [4, "
                       "5, 6, 7]]); }");
    assert_true(inside(s, 1.5, 0, 2) && inside(s, 0, 4.5, 0.5) && !inside(s, 3, 0, 2) &&
                !inside(s, 0, 0, 2));
    /* the hole's edges run clockwise, so every edge's normal (dz, -dr)
     * points out of the solid: into the hole at its walls r = 2 and 4 */
    const prim_revolve *r = only_leaf(s)->u.revolve.rev;
    int walls = 0;
    for (uint32_t i = 0; i < r->edge_count; i++) {
        const prim_revolve_edge *e = &r->edges[i];
        if (e->r0 == 2 && e->r1 == 2)
            walls += e->z1 > e->z0; /* normal +r */
        if (e->r0 == 4 && e->r1 == 4)
            walls += e->z1 < e->z0; /* normal -r */
        if (e->r0 == 5 && e->r1 == 5)
            walls += e->z1 > e->z0; /* the outline's outer wall, +r */
    }
    assert_int_equal(walls, 3);
    sc_scene_release(s);
    s = load("rotate_extrude() { square(size = [1, 1]); group() { " TRANSLATE(
        2, 0.5) " { "
                "circle(r = 1); } } }");
    r = only_leaf(s)->u.revolve.rev;
    assert_int_equal(r->region_count, 2);
    assert_true(inside(s, 0.5, 0, 0.5) && inside(s, 2.5, 0, 1.2) &&
                !inside(s, 0.5, 0, 1.2));
    sc_scene_release(s);
}

/* A triangle on the axis: a cone, solid along the axis. */
static void test_cone(void **state)
{
    (void)state;
    sc_scene *s = load("rotate_extrude($fn = 8) { polygon(points = [[0, 0], [3, 0], [0, "
                       "4]]); }");
    assert_true(inside(s, 0, 0, 3.9) && inside(s, 0.5, 0.5, 2) && !inside(s, 0, 0, 4.1) &&
                !inside(s, 1.2, 1.2, 2));
    sc_scene_release(s);
}

/* Faithful mode: OpenSCAD's mesh. Fragments from max |x| = 4 with $fa =
 * 12, $fs = 2: ceil(max(min(30, 2 pi 4 / 2), 5)) = 13; 2 triangles per
 * profile edge and fragment. A quarter with $fn = 12 has 3 fragments and
 * two caps of 2 triangles each. */
static void test_faithful(void **state)
{
    (void)state;
    sc_scene *s = load_mode("rotate_extrude($fn = 0, $fa = 12, $fs = 2) " TUBE, 1);
    const prim *p = only_leaf(s);
    assert_int_equal(p->kind, PRIM_MESH);
    assert_int_equal(p->u.mesh.mesh->tri_count, 2 * 13 * 4);
    assert_true(inside(s, 3, 0, 1) && !inside(s, 1.9, 0, 1));
    sc_scene_release(s);
    s = load_mode("rotate_extrude(angle = 90, $fn = 12) " TUBE, 1);
    p = only_leaf(s);
    assert_int_equal(p->u.mesh.mesh->tri_count, 2 * 3 * 4 + 2 * 2);
    assert_true(inside(s, 2.5, 0.5, 1) && !inside(s, -2.5, 0.5, 1));
    sc_scene_release(s);
    /* a small angle: at least one fragment */
    s = load_mode("rotate_extrude(angle = 5, $fn = 12) " TUBE, 1);
    assert_int_equal(only_leaf(s)->u.mesh.mesh->tri_count, 2 * 1 * 4 + 2 * 2);
    sc_scene_release(s);
}

/* Exact and faithful (with $fn = 256) agree at sampled points farther
 * from the surface than the facets' sagitta. */
static void test_exact_matches_faithful(void **state)
{
    (void)state;
    const char *text = "rotate_extrude(angle = 250, $fn = 256) { polygon(points = [[0, "
                       "0], [3, 0], [4, 2], [2, 2.5], [2.5, 4], [0, 5]]); " TRANSLATE(
                           5, 3) " { circle(r = 1, $fn = 256); } }";
    sc_scene *a = load_mode(text, 0), *b = load_mode(text, 1);
    uint64_t seed = 99;
    int checked = 0;
    for (int i = 0; i < 20000; i++) {
        double u[3];
        for (int k = 0; k < 3; k++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            u[k] = (double)(seed >> 11) * 0x1p-53;
        }
        vec3 q = v3(-7 + 14 * u[0], -7 + 14 * u[1], -1 + 6 * u[2]);
        int ia = inside(a, q.x, q.y, q.z), ib = inside(b, q.x, q.y, q.z);
        if (ia == ib)
            continue;
        /* they may differ only within the sagitta 6 (1 - cos(pi / 256)) of
         * the surface: check that the point is that close to it by moving
         * it a little */
        int near = 0;
        for (int k = 0; k < 6 && !near; k++) {
            vec3 m = q;
            double *c = &m.x;
            c[k / 2] += (k % 2 ? 1e-3 : -1e-3);
            near = inside(a, m.x, m.y, m.z) != ia;
        }
        assert_true(near);
        checked++;
    }
    print_message("exact and faithful differ at %d of 20000 points, all within 1e-3 of "
                  "the surface\n",
                  checked);
    assert_true(checked < 200);
    sc_scene_release(a);
    sc_scene_release(b);
}

/* 2D booleans and offsets in the profile go through the 2D engine: a
 * square ring (a 4 x 4 square less a 2 x 2 one, centred at x = 5) revolves
 * to a tube with a square channel, in both modes. */
static void test_twod_profile(void **state)
{
    (void)state;
    static const char text[] =
        "rotate_extrude($fn = 64) {\n"
        "  difference() {\n"
        "    multmatrix(m = [[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "      square(size = [4, 4], center = true);\n"
        "    }\n"
        "    multmatrix(m = [[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "      square(size = [2, 2], center = true);\n"
        "    }\n"
        "  }\n"
        "}\n";
    for (int faithful = 0; faithful < 2; faithful++) {
        sc_scene *s = load_mode(text, faithful);
        assert_true(inside(s, 3.5, 0, 0) && inside(s, 0, -6.5, 1.5) &&
                    inside(s, -5, 0, 1.5));
        assert_false(inside(s, 5, 0, 0) || inside(s, 0, 5.5, 0.5) ||
                     inside(s, 2.5, 0, 0) || inside(s, 7.5, 0, 0) ||
                     inside(s, 5, 0, 2.5));
        sc_scene_release(s);
    }
    sc_scene *s =
        load("rotate_extrude() { offset(delta = 1) { multmatrix(m = [[1, 0, 0, "
             "5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = 2, "
             "center = true); } } }");
    assert_true(inside(s, 6.9, 0, 1.9) && inside(s, 0, 3.1, -1.9));
    assert_false(inside(s, 7.1, 0, 0) || inside(s, 2.9, 0, 0) || inside(s, 5, 0, 2.1));
    sc_scene_release(s);
}

static void test_errors(void **state)
{
    (void)state;
    /* OpenSCAD's message, with its running range: circle(r = 5) has 16
     * points from angle 0; the 6th (x = -1.91) is the first below 0. It
     * logs it and leaves the extrusion out, the rest rendered; --strict
     * makes it the error. */
    test_check_strict_error("m.csg",
                            "group() {\n  rotate_extrude() { circle(r = 5); }\n}\n", 0,
                            SC_ERR_SEMANTIC,
                            "m.csg:2:3: error: all points for rotate_extrude() must have "
                            "the same X coordinate sign (range is -1.91 -> 5.00)");
    test_check_strict_error(
        "m.csg", "rotate_extrude() { polygon(points = [[-1, 0], [2, 0], [2, 1]]); }", 1,
        SC_ERR_SEMANTIC,
        "m.csg:1:1: error: all points for rotate_extrude() must have the same X "
        "coordinate sign (range is -1.00 -> 2.00)");
    {
        static const char *const crossing[] = {
            "m.csg:1:10: all points for rotate_extrude() must have the same X coordinate "
            "sign (range is -1.00 -> 2.00); the rotate_extrude is empty, as OpenSCAD "
            "leaves "
            "it out"};
        for (int faithful = 0; faithful < 2; faithful++) {
            sc_scene *s =
                test_check_warnings("m.csg",
                                    "cube(1); rotate_extrude() { polygon(points = [[-1, "
                                    "0], [2, 0], [2, 1]]); "
                                    "}",
                                    faithful, crossing, 1);
            assert_true(inside(s, 0.5, 0.5, 0.5));
            assert_false(inside(s, 1.5, 0, 0.5));
            sc_scene_release(s);
        }
    }
    {
        /* a 3D child: ignored with OpenSCAD's warning, the rest revolved */
        static const char *const ignored[] = {
            "m.csg:1:104: Ignoring 3D child object for 2D operation"};
        sc_scene *s = test_check_warnings("m.csg",
                                          "rotate_extrude() { multmatrix([[1, 0, 0, 2], "
                                          "[0, 1, 0, 0], [0, 0, 1, 0], [0, "
                                          "0, 0, 1]]) { square(1); } cube(size = 1); }",
                                          0, ignored, 1);
        assert_true(inside(s, 2.5, 0, 0.5));
        assert_false(inside(s, 0.5, 0.5, 0.5));
        sc_scene_release(s);
    }
    /* an angle that is not a number is 360, as OpenSCAD 2021.01 takes it */
    sc_scene *full = load("rotate_extrude(angle = \"x\", convexity = [2]) { "
                          "multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], "
                          "[0, 0, 0, 1]]) { square(size = 1); } }");
    assert_int_equal(sc_scene_warning_count(full), 0);
    assert_true(inside(full, 1.5, 0, 0.5) && inside(full, -1.5, 0, 0.5) &&
                inside(full, 0, -1.5, 0.5));
    sc_scene_release(full);
    /* a path index that is not a number is 0, as OpenSCAD reads it: the
     * square [1, 2] x [0, 1] revolved */
    sc_scene *ring = load("rotate_extrude($fn = 64) { polygon(points = [[1, 0], [2, 0], "
                          "[2, 1], [1, 1]], paths = [[\"x\", 1, 2, 3]]); }");
    assert_true(inside(ring, 1.5, 0, 0.5));
    assert_false(inside(ring, 0.5, 0, 0.5));
    sc_scene_release(ring);
    /* the file form reads the drawing's arguments as import() does */
    /* an origin that is not [x, y] is [0, 0], with OpenSCAD 2021.01's
     * warning (then the missing file's) */
    static const char *const origin[] = {
        "m.csg:1:41: rotate_extrude(..., origin=3) could not be converted",
        "m.csg:1:1: Can't open DXF file 'a.dxf': No such file or directory; the import "
        "is "
        "empty, as OpenSCAD leaves it out (--strict makes it an error)"};
    sc_scene_release(test_check_warnings(
        "m.csg", "rotate_extrude(file = \"a.dxf\", origin = 3);", 0, origin, 2));
    /* a profile past the edge limit */
    size_t cap = 64 * 1024;
    char *text = malloc(cap);
    assert_non_null(text);
    size_t len = (size_t)snprintf(text, cap, "rotate_extrude() { polygon(points = [");
    for (int i = 0; i < PRIM_REVOLVE_MAX_EDGES + 1; i++)
        len += (size_t)snprintf(text + len, cap - len, "%s[%g, %g]", i ? ", " : "",
                                2 + cos(i * 0.001), (double)i);
    snprintf(text + len, cap - len, "]); }");
    check_error(
        text, SC_ERR_LIMIT,
        "m.csg:1:1: error: rotate_extrude profile has 2049 edges (limit is 2048; a "
        "circle counts 2)");
    free(text);
}

/* Nesting past the guard is an error, not a deep recursion. */
static void test_depth_guard(void **state)
{
    (void)state;
    size_t cap = 32 * 1024;
    char *text = malloc(cap);
    assert_non_null(text);
    size_t len = (size_t)snprintf(text, cap, "rotate_extrude() { ");
    for (int i = 0; i < 1001; i++)
        len += (size_t)snprintf(text + len, cap - len, "group() { ");
    len += (size_t)snprintf(text + len, cap - len, "square(size = 1); ");
    for (int i = 0; i < 1002; i++)
        len += (size_t)snprintf(text + len, cap - len, "} ");
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, len, NULL, &s, &e),
                     SC_ERR_LIMIT);
    char buf[256];
    assert_non_null(strstr(sc_error_format(&e, buf, sizeof buf),
                           "too many nested nodes in rotate_extrude (limit is 1000)"));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tube),
        cmocka_unit_test(test_angles),
        cmocka_unit_test(test_negative_profile),
        cmocka_unit_test(test_circles),
        cmocka_unit_test(test_polygon_paths),
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_faithful),
        cmocka_unit_test(test_exact_matches_faithful),
        cmocka_unit_test(test_twod_profile),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_depth_guard),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
