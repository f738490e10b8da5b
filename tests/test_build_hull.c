/* Tests of hull(), minkowski(), resize() and surface() (build_hull.c,
 * build_surface.c): solids and bounding boxes against hand computations,
 * curved children hulled as OpenSCAD's polyhedra in both modes, unions of
 * convex parts distributed over minkowski, OpenSCAD's resize rules, height
 * maps from .dat text and PNG files, and the exact errors and warnings. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "build/build.h"
#include "build/scene.h"
#include "test_util.h"

static sc_scene *load_opts(const char *name, const char *text, int faithful)
{
    return test_load(name, text, faithful);
}

static sc_scene *load(const char *text)
{
    return load_opts("m.csg", text, 0);
}

static void check_error(const char *name, const char *text, sc_status status,
                        const char *expected)
{
    test_check_error(name, text, status, expected);
}

static void check_warning(const char *text, const char *expected)
{
    sc_scene *s = load(text);
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message, expected);
    assert_int_equal(scene_tree(s)->root, CSG_EMPTY);
    sc_scene_release(s);
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static void check_bounds(const sc_scene *s, vec3 lo, vec3 hi, double tol)
{
    bbox b = scene_tree(s)->bounds;
    for (int k = 0; k < 3; k++) {
        if (!(fabs(v3_get(b.lo, k) - v3_get(lo, k)) <= tol) ||
            !(fabs(v3_get(b.hi, k) - v3_get(hi, k)) <= tol))
            fail_msg("bounds [%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g], expected "
                     "[%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g]",
                     b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z, lo.x, lo.y, lo.z,
                     hi.x, hi.y, hi.z);
    }
}

#define PI 3.14159265358979323846

/* ---- hull ---- */

static void test_hull_boxes(void **state)
{
    (void)state;
    /* two unit cubes 4 apart: the box [0, 5] x [0, 1] x [0, 1] */
    sc_scene *s = load("hull() { cube(1); multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], "
                       "[0, 0, 1, 0], [0, 0, 0, 1]]) { cube(1); } }");
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    assert_int_equal(scene_tree(s)->leaves[0].prim.kind, PRIM_CONVEX);
    assert_int_equal(scene_tree(s)->leaves[0].prim.u.convex.count, 6);
    assert_true(inside(s, 2.5, 0.5, 0.5));
    assert_false(inside(s, 2.5, 1.01, 0.5));
    check_bounds(s, v3(0, 0, 0), v3(5, 1, 1), 0);
    sc_scene_release(s);
    /* a cube and a point-like tip above: a pyramid (the cube's top corners
     * to the apex), under group, colour and a rotation of the whole */
    s = load(
        "multmatrix([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
        "hull() { color(\"red\") { cube(2, center = true); } group() {"
        "polyhedron(points = [[0, 0, 4], [0.001, 0, 4], [0, 0.001, 4], [0, 0, 4.001]], "
        "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]); } %cube(50); } }");
    assert_true(inside(s, 0, 0, 3.9));
    assert_true(inside(s, 0.9, 0.9, 1.01));
    assert_false(inside(s, 0.9, 0.9, 2.5));
    assert_false(inside(s, 10, 10, 10)); /* the '%' cube is left out */
    sc_scene_release(s);
}

/* Spheres are hulled as OpenSCAD's polyhedra, in default mode too: a
 * sphere of 8 fragments has 4 rings, its top is flat at r cos(22.5°). */
static void test_hull_curved(void **state)
{
    (void)state;
    for (int faithful = 0; faithful < 2; faithful++) {
        sc_scene *s = load_opts("m.csg", "hull() { sphere(r = 1, $fn = 8); }", faithful);
        double top = cos(22.5 * PI / 180);
        assert_true(inside(s, 0, 0, top - 1e-9));
        assert_false(inside(s, 0, 0, top + 1e-9));
        check_bounds(s, v3(-sin(67.5 * PI / 180), -sin(67.5 * PI / 180), -top),
                     v3(sin(67.5 * PI / 180), sin(67.5 * PI / 180), top), 1e-12);
        sc_scene_release(s);
    }
    /* a rounded box from eight spheres: a plane set or, with many faces, a
     * mesh; the middle of each face is at the spheres' extent */
    sc_scene *s = load(
        "hull() { "
        "multmatrix([[1,0,0,-5],[0,1,0,-3],[0,0,1,-1],[0,0,0,1]]) { sphere(1, $fn = 30); "
        "}"
        "multmatrix([[1,0,0,5],[0,1,0,-3],[0,0,1,-1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,-5],[0,1,0,3],[0,0,1,-1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,5],[0,1,0,3],[0,0,1,-1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,-5],[0,1,0,-3],[0,0,1,1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,5],[0,1,0,-3],[0,0,1,1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,-5],[0,1,0,3],[0,0,1,1],[0,0,0,1]]) { sphere(1, $fn = 30); }"
        "multmatrix([[1,0,0,5],[0,1,0,3],[0,0,1,1],[0,0,0,1]]) { sphere(1, $fn = 30); "
        "}}");
    double top = 1 + cos(6 * PI / 180); /* 15 rings: the cap ring at 6° */
    assert_true(inside(s, 0, 0, top - 1e-9));
    assert_false(inside(s, 0, 0, top + 1e-9));
    assert_true(inside(s, 5.9, 0, 0));
    assert_false(inside(s, 6.01, 0, 0));
    sc_scene_release(s);
}

/* Extrusions inside a hull give OpenSCAD's polygon vertices in both modes
 * (default mode builds exact extrusion and revolve leaves, which have no
 * vertices of their own): a hexagon prism, and a revolved square ring. */
static void test_hull_extrusions(void **state)
{
    (void)state;
    for (int faithful = 0; faithful < 2; faithful++) {
        sc_scene *s = load_opts(
            "m.csg",
            "hull() { linear_extrude(height = 2) { circle(r = 3, $fn = 6); } "
            "multmatrix([[1,0,0,10],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) { cube(1); } }",
            faithful);
        assert_true(inside(s, -2.9, 0, 1));     /* the hexagon's corner at (-3, 0) */
        assert_false(inside(s, 0, 2.7, 1));     /* past its top edge, y = 2.598 */
        assert_true(inside(s, 10.5, 0.5, 0.5)); /* the cube */
        sc_scene_release(s);
        s = load_opts(
            "m.csg",
            "hull() { rotate_extrude($fn = 4) { "
            "multmatrix([[1,0,0,4],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) { square(1); } "
            "} }",
            faithful);
        /* four rings of points at radius 4 and 5 on the axes, z 0 to 1 */
        assert_true(inside(s, 0, 0, 0.5) && inside(s, 4.9, 0, 0.5) &&
                    inside(s, 0, -4.9, 0.9));
        assert_false(inside(s, 3, 3, 0.5) || inside(s, 0, 0, 1.1));
        sc_scene_release(s);
    }
}

static void test_hull_errors(void **state)
{
    (void)state;
    check_error("m.csg",
                "hull() {\n  difference() { cube(2); torus(r1 = 2, r2 = 1); }\n}",
                SC_ERR_UNSUPPORTED,
                "m.csg:2:27: error: 'torus' inside hull is not supported yet");
    check_error("m.csg",
                "hull() { group() { intersection() { cube(2); implicit(f = "
                "\"x\", bounds = [[0, 0, 0], [1, 1, 1]]); } } }",
                SC_ERR_UNSUPPORTED,
                "m.csg:1:46: error: 'implicit' inside hull is not supported yet");
    /* an open polyhedron in a boolean is no solid for CGAL: left out of
     * it, as OpenSCAD 2021.01 leaves it out, with its message */
    const char *const open[] = {
        "m.csg:2:2: polyhedron is not closed (edge 0-2 is used by 1 face); left out, as "
        "OpenSCAD leaves it out (\"The given mesh is not closed! Unable to convert to "
        "CGAL_Nef_Polyhedron.\")"};
    const test_point whole[] = {{0.05, 0.05, 0.05, 1}}; /* the whole cube's hull */
    test_check_warnings_both(
        "m.csg",
        "hull() { difference() { cube(2);\n polyhedron(points = [[0, 0, 0], [1, "
        "0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 2], [0, 3, 1]]); } }",
        open, 1, whole, 1);
    check_error("m.csg", "hull() { torus(r1 = 2, r2 = 1); }", SC_ERR_UNSUPPORTED,
                "m.csg:1:10: error: 'torus' inside hull is not supported yet");
    /* a radius of the wrong kind is 1, silently, as OpenSCAD takes it */
    sc_scene *one = load("hull() { sphere(r = \"x\"); }");
    assert_int_equal(sc_scene_warning_count(one), 0);
    assert_true(inside(one, 0, 0, 0) && inside(one, 0, 0, 0.8));
    assert_false(inside(one, 1.01, 0, 0) || inside(one, 0, 0, 1.01));
    sc_scene_release(one);
    /* $fa and $fs clamped to 0.01, as OpenSCAD clamps them: 6284, past a
     * sphere's limit */
    check_error("m.csg", "hull() { sphere(r = 10, $fn = 0, $fa = 0, $fs = 0); }",
                SC_ERR_LIMIT,
                "m.csg:1:10: error: hull: $fn, $fa and $fs of radius 10 give too many "
                "fragments (limit is 4096)");
    /* a '%' hull is still checked */
    check_error("m.csg", "cube(); %hull() { difference() { torus(r1 = 2, r2 = 1); } }",
                SC_ERR_UNSUPPORTED,
                "m.csg:1:34: error: 'torus' inside hull is not supported yet");
    /* deep nesting is refused, not followed */
    size_t depth = 1100;
    char *text = malloc(depth * 10 + 64);
    strcpy(text, "hull() { ");
    for (size_t i = 0; i < depth; i++)
        strcat(text, "group() {");
    strcat(text, "cube();");
    for (size_t i = 0; i < depth; i++)
        strcat(text, "}");
    strcat(text, " }");
    check_error("m.csg", text, SC_ERR_LIMIT,
                "m.csg:1:9010: error: too many nested nodes inside hull (limit is 1000)");
    free(text);
}

static void test_hull_booleans(void **state)
{
    (void)state;
    /* a cube cut by OpenSCAD's 32-gon of radius 6: a vertex of the 32-gon at
     * 45 degrees, so the corner column is cut at radius 6 there */
    sc_scene *s = load("hull() { intersection() { cube(10, center = true); "
                       "cylinder(r1 = 6, r2 = 6, h = 20, center = true, $fn = 32); } }");
    check_bounds(s, v3(-5, -5, -5), v3(5, 5, 5), 1e-12);
    assert_true(inside(s, 4.9, 0, 4.9));
    assert_true(inside(s, 4.2, 4.2, 0));  /* radius 5.94 */
    assert_false(inside(s, 4.3, 4.3, 0)); /* radius 6.08 */
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    sc_scene_release(s);
    /* the same in faithful mode */
    s = load_opts("m.csg",
                  "hull() { intersection() { cube(10, center = true); cylinder(r1 = 6, "
                  "r2 = 6, h = 20, center = true, $fn = 32); } }",
                  1);
    assert_false(inside(s, 4.3, 4.3, 0));
    sc_scene_release(s);
    /* a cube with its corner cube cut away: the hull is cut by the plane
     * through (1, 0, 0), (0, 1, 0), (0, 0, 1) */
    s = load("hull() { difference() { cube(2); cube(1); } }");
    check_bounds(s, v3(0, 0, 0), v3(2, 2, 2), 1e-15);
    assert_false(inside(s, 0.3, 0.3, 0.3));
    assert_true(inside(s, 0.4, 0.4, 0.4));
    assert_true(inside(s, 1.9, 1.9, 1.9));
    sc_scene_release(s);
    /* a difference that removes everything: an empty hull */
    check_warning("hull() { difference() { cube(1); cube(2); } }",
                  "hull without volume is empty");
}

/* One difference with a 2D child under two hulls: OpenSCAD 2021.01
 * evaluates it once, and so warns once (its second hull takes the solid
 * from its cache, warnings and all); under one hull, twice, as OpenSCAD
 * caches a child only when its parent has all its children. */
static void test_hull_boolean_once(void **state)
{
    (void)state;
    static const char *const once[] = {
        "m.csg:1:34: Mixing 2D and 3D objects is not supported",
        "m.csg:1:34: Ignoring 2D child object for 3D operation"};
    sc_scene *s = test_check_warnings(
        "m.csg",
        "hull() { difference() { cube(2); square(1); cube(1); } }\n"
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]]) { hull() { "
        "difference() { cube(2); square(1); cube(1); } } }\n"
        "hull() { multmatrix([[1, 0, 0, 0], [0, 1, 0, 10], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ difference() { cube(2); square(1); cube(1); } } }",
        0, once, 2);
    assert_true(inside(s, 1.5, 1.5, 1.5));
    assert_true(inside(s, 1.5, 6.5, 1.5));
    assert_true(inside(s, 1.5, 11.5, 1.5));
    assert_false(inside(s, 0.2, 10.2, 0.2));
    sc_scene_release(s);
    static const char *const twice[] = {
        "m.csg:1:34: Mixing 2D and 3D objects is not supported",
        "m.csg:1:34: Ignoring 2D child object for 3D operation",
        "m.csg:2:96: Mixing 2D and 3D objects is not supported",
        "m.csg:2:96: Ignoring 2D child object for 3D operation"};
    s = test_check_warnings(
        "m.csg",
        "hull() { difference() { cube(2); square(1); cube(1); }\n"
        "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
        "difference() { cube(2); square(1); cube(1); } } }",
        0, twice, 4);
    assert_true(inside(s, 3.5, 1, 1));
    sc_scene_release(s);
}

/* Loads on several threads at once, each with its CGAL boolean under a
 * hull, make the solid a load alone makes. The CGAL plugin is built
 * without CGAL's own thread safety and lets one thread at a time in
 * (guarded.h); a race there need not show in one run, so this checks the
 * outcome, not the lock. */
static const char booleans_text[] =
    "hull() { difference() { sphere(10, $fn = 24); multmatrix([[1, 0, 0, 5], "
    "[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere(8, $fn = 24); } }";

enum { PROBES = 9 };

typedef struct booleans_result {
    bbox bounds;
    int inside[PROBES * PROBES];
    int failed;
} booleans_result;

static void booleans_probe(booleans_result *r)
{
    /* no cmocka check on these threads: a failure is recorded for the
     * main thread to report */
    sc_scene *s = NULL;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    if (sc_scene_load_string("m.csg", booleans_text, strlen(booleans_text), &o, &s, &e) !=
        SC_OK) {
        r->failed = 1;
        return;
    }
    r->bounds = scene_tree(s)->bounds;
    for (int i = 0; i < PROBES; i++)
        for (int j = 0; j < PROBES; j++)
            r->inside[i * PROBES + j] = inside(s, -11 + 22.0 * i / (PROBES - 1), 0.3,
                                               -11 + 22.0 * j / (PROBES - 1));
    sc_scene_release(s);
}

static void *booleans_thread(void *arg)
{
    booleans_result *r = arg;
    for (int k = 0; k < 2; k++)
        booleans_probe(&r[k]);
    return NULL;
}

static void test_hull_booleans_threads(void **state)
{
    (void)state;
    booleans_result alone;
    memset(&alone, 0, sizeof alone);
    booleans_probe(&alone);
    assert_false(alone.failed);
    int in = 0;
    for (int k = 0; k < PROBES * PROBES; k++)
        in += alone.inside[k];
    assert_true(in > 0 && in < PROBES * PROBES); /* the probes see the solid's side */
    enum { THREADS = 4 };
    booleans_result got[THREADS][2];
    memset(got, 0, sizeof got);
    pthread_t thread[THREADS];
    for (int t = 0; t < THREADS; t++)
        assert_int_equal(pthread_create(&thread[t], NULL, booleans_thread, got[t]), 0);
    for (int t = 0; t < THREADS; t++)
        assert_int_equal(pthread_join(thread[t], NULL), 0);
    for (int t = 0; t < THREADS; t++)
        for (int k = 0; k < 2; k++) {
            assert_false(got[t][k].failed);
            assert_memory_equal(&got[t][k].bounds, &alone.bounds, sizeof alone.bounds);
            assert_memory_equal(got[t][k].inside, alone.inside, sizeof alone.inside);
        }
}

static void test_hull_empty(void **state)
{
    (void)state;
    check_warning("hull();", "hull without volume is empty");
    check_warning("hull() { cube([1, 1, 0]); }", "hull without volume is empty");
    /* two squares in one plane */
    check_warning("hull() { polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
                  "faces = [[0, 1, 2], [0, 2, 1]]); polyhedron(points = [[5, 5, 0], "
                  "[6, 5, 0], [5, 6, 0]], faces = [[0, 1, 2], [0, 2, 1]]); }",
                  "hull without volume is empty");
}

/* ---- minkowski ---- */

static void test_minkowski(void **state)
{
    (void)state;
    /* cubes add their sizes */
    sc_scene *s = load("minkowski() { cube(2, center = true); cube([1, 3, 5], center = "
                       "true); }");
    check_bounds(s, v3(-1.5, -2.5, -3.5), v3(1.5, 2.5, 3.5), 1e-15);
    assert_true(inside(s, 1.49, 2.49, 3.49));
    sc_scene_release(s);
    /* a plate and OpenSCAD's sphere of 16 fragments (8 rings): the extent
     * grows by sin(78.75°) across and cos(11.25°) up */
    s = load("minkowski() { cube([10, 6, 2], center = true); sphere(1, $fn = 16); }");
    double across = sin(78.75 * PI / 180), up = cos(11.25 * PI / 180);
    check_bounds(s, v3(-5 - across, -3 - across, -1 - up),
                 v3(5 + across, 3 + across, 1 + up), 1e-12);
    assert_true(inside(s, 5 + across - 1e-9, 0, 0));
    assert_false(inside(s, 5 + across + 1e-9, 0, 0));
    sc_scene_release(s);
    /* a translated child: the sum of the offsets */
    s = load(
        "minkowski() { multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], "
        "[0, 0, 0, 1]]) { cube(1); } multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, "
        "-3], [0, 0, 0, 1]]) { cylinder(h = 1, r = 1, $fn = 4); } }");
    check_bounds(s, v3(9, -1, -3), v3(12, 2, -1), 1e-15);
    sc_scene_release(s);
}

static void test_minkowski_union(void **state)
{
    (void)state;
    /* a union of two cubes distributes: two leaves with the gap kept */
    sc_scene *s = load("minkowski() { union() { cube(1); multmatrix([[1, 0, 0, 3], "
                       "[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(1); } } "
                       "cube(0.5, center = true); }");
    assert_int_equal(scene_tree(s)->leaf_count, 2);
    assert_true(inside(s, 1.2, 0.5, 0.5));
    assert_false(inside(s, 2, 0.5, 0.5));
    assert_true(inside(s, 2.8, 0.5, 0.5));
    check_bounds(s, v3(-0.25, -0.25, -0.25), v3(4.25, 1.25, 1.25), 1e-15);
    sc_scene_release(s);
    /* a nested hull is one convex part; a convex polyhedron is one too */
    s = load("minkowski() { hull() { cube(1); cube([3, 0.5, 0.5]); } "
             "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
             "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]); }");
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    check_bounds(s, v3(0, 0, 0), v3(4, 2, 2), 1e-15);
    sc_scene_release(s);
}

#define NOTCH_POINTS                                                                     \
    "[[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], [2, 0, 2], [2, 2, 2], "     \
    "[0, 2, 2], [1, 1, 1]]"
#define NOTCH_FACES                                                                      \
    "[[0, 1, 2, 3], [4, 5, 1, 0], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [4, 8, 5], " \
    "[5, 8, 6], [6, 8, 7], [7, 8, 4]]"

static void test_minkowski_nonconvex(void **state)
{
    (void)state;
    /* the notch (a cube with a pyramid pressed into its top, apex at (1, 1,
     * 1)) plus the unit cube: convex parts, the dent kept. Above the apex
     * the dent's floor is at 2 - d, d the distance to the nearest side. */
    sc_scene *s = load("minkowski() { cube(1);\n polyhedron(points = " NOTCH_POINTS
                       ", faces = " NOTCH_FACES "); }");
    assert_true(scene_tree(s)->leaf_count > 1);
    check_bounds(s, v3(0, 0, 0), v3(3, 3, 3), 1e-12);
    assert_true(inside(s, 1, 1, 2.6));      /* from (0.1, 0.1, 1.9) */
    assert_false(inside(s, 1.5, 1.5, 2.9)); /* the dent, narrowed */
    assert_true(inside(s, 1.5, 1.5, 2.45)); /* from (0.5, 0.5, 1.45) */
    assert_true(inside(s, 2.9, 2.9, 2.9));
    sc_scene_release(s);
    /* a square tube (a difference) plus a small cube: the hole narrows from
     * 2 to 1.5 */
    s = load("minkowski() { difference() { cube(4, center = true); cube([2, 2, 10], "
             "center = true); } cube(0.5, center = true); }");
    check_bounds(s, v3(-2.25, -2.25, -2.25), v3(2.25, 2.25, 2.25), 1e-12);
    assert_true(inside(s, 0.8, 0, 0));
    assert_false(inside(s, 0.7, 0, 0));
    assert_false(inside(s, 0, 0, 0));
    assert_true(inside(s, 2.2, 2.2, 2.2));
    sc_scene_release(s);
}

static void test_minkowski_errors(void **state)
{
    (void)state;
    check_error("m.csg",
                "minkowski() { cube(1); difference() { cube(2); torus(r1 = 2, "
                "r2 = 1); } }",
                SC_ERR_UNSUPPORTED,
                "m.csg:1:48: error: 'torus' inside minkowski is not supported yet");
    /* the same polyhedron inside a hull is fine: hull takes its points */
    sc_scene *s = load("hull() { polyhedron(points = " NOTCH_POINTS
                       ", faces = " NOTCH_FACES "); }");
    assert_true(inside(s, 1, 1, 1.9));
    sc_scene_release(s);
    check_warning("minkowski() { cube(0); cube(0); }",
                  "minkowski without volume is empty");
    /* of one solid, the solid as it is (OpenSCAD's applyToChildren3D) */
    check_warning("minkowski() { cube(0); }",
                  "cube with a zero, negative or non-finite size is empty");
}

/* ---- resize ---- */

static void test_resize(void **state)
{
    (void)state;
    sc_scene *s = load("resize([10, 0, 4]) { cube([2, 4, 8]); }");
    check_bounds(s, v3(0, 0, 0), v3(10, 4, 4), 1e-14);
    sc_scene_release(s);
    /* auto: zero sizes take the largest asked scale (10 / 2) */
    s = load(
        "resize(newsize = [10, 0, 0], auto = [1, 0, 1], convexity = 0) { cube([2, 4, "
        "8]); }");
    check_bounds(s, v3(0, 0, 0), v3(10, 4, 40), 1e-13);
    sc_scene_release(s);
    s = load("resize([0, 8, 0], true) { cube([2, 4, 8]); }");
    check_bounds(s, v3(0, 0, 0), v3(4, 8, 16), 1e-13);
    sc_scene_release(s);
    /* the exact sphere in default mode: a sphere of diameter 20 */
    s = load("resize([20, 0, 0], auto = true) { sphere(3, $fn = 24); }");
    check_bounds(s, v3(-10, -10, -10), v3(10, 10, 10), 1e-13);
    sc_scene_release(s);
    /* inside a hull, which takes OpenSCAD's polygons in both modes, the
     * scale is from the polygons' box (the octagon's x extent, 2 * 5 sin
     * 67.5), not the exact sphere's (10), in default mode too */
    for (int faithful = 0; faithful < 2; faithful++) {
        s = load_opts("m.csg",
                      "hull() { resize([4, 0, 0], auto = true) { sphere(5, $fn = 8); } }",
                      faithful);
        double k = 2 / (5 * sin(67.5 * PI / 180)); /* 4 over the x extent */
        double top = 5 * cos(22.5 * PI / 180) * k, side = 5 * sin(67.5 * PI / 180) * k;
        check_bounds(s, v3(-side, -side, -top), v3(side, side, top), 1e-12);
        sc_scene_release(s);
    }
    /* OpenSCAD's polyhedron in faithful mode: 5 fragments, 3 rings; the box
     * of its points is scaled to the asked size */
    s = load_opts("m.csg", "resize([20, 10, 6]) { sphere(3, $fn = 5); }", 1);
    check_bounds(s, v3(-20 * cos(36 * PI / 180) / (1 + cos(36 * PI / 180)), -5, -3),
                 v3(20 / (1 + cos(36 * PI / 180)), 5, 3), 1e-12);
    sc_scene_release(s);
    /* a sphere under a shear: its box is r |row|, not the box of a box */
    s = load(
        "resize([10, 0, 0]) { multmatrix([[1, 1, 0, 0], [-1, 1, 0, 0], [0, 0, 1, 0], "
        "[0, 0, 0, 1]]) { sphere(1); } }");
    assert_true(inside(s, 4.999, 0, 0));
    assert_false(inside(s, 5.001, 0, 0));
    assert_true(inside(s, 0, 1.414, 0));
    assert_false(inside(s, 0, 1.415, 0));
    sc_scene_release(s);
    /* a cylinder on its side: x from 0 to its height 4 becomes 0 to 6 */
    s = load("resize([6, 0, 0]) { multmatrix([[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 0], "
             "[0, 0, 0, 1]]) { cylinder(h = 4, r1 = 1, r2 = 0.5); } }");
    check_bounds(s, v3(0, -1, -1), v3(6, 1, 1), 1e-13);
    sc_scene_release(s);
    /* the scale is about the origin, not the box */
    s = load("resize([4, 0, 0]) { multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], "
             "[0, 0, 0, 1]]) { cube(2); } }");
    check_bounds(s, v3(20, 0, 0), v3(24, 2, 2), 1e-13);
    sc_scene_release(s);
}

static void test_resize_boxes(void **state)
{
    (void)state;
    /* a union: both children's box, [0, 4] in x */
    sc_scene *s =
        load("resize([8, 0, 0]) { cube(1); multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], "
             "[0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(2); } }");
    check_bounds(s, v3(0, -2, -2), v3(8, 2, 2), 1e-13);
    sc_scene_release(s);
    /* difference: the box of OpenSCAD's result, x 2..4, becomes 1..2 */
    s = load("resize([1, 0, 0]) { difference() { cube([4, 1, 1]); cube([2, 1, 1]); } }");
    assert_true(inside(s, 1.05, 0.5, 0.5) && inside(s, 1.95, 0.5, 0.5));
    assert_false(inside(s, 0.95, 0.5, 0.5) || inside(s, 2.05, 0.5, 0.5));
    sc_scene_release(s);
    /* intersection: the smallest box in each direction */
    s = load(
        "resize([2, 0, 0]) { intersection() { cube([4, 1, 1]); cube([1, 3, 1]); } }");
    check_bounds(s, v3(0, 0, 0), v3(2, 1, 1), 1e-13);
    sc_scene_release(s);
    /* minkowski: the boxes add; a torus: R + r across */
    s = load(
        "resize([12, 0, 0]) { minkowski() { cube(2, center = true); cube(4, center = "
        "true); } }");
    check_bounds(s, v3(-6, -3, -3), v3(6, 3, 3), 1e-13);
    sc_scene_release(s);
    s = load("resize([6, 0, 0]) { torus(r1 = 2, r2 = 1); }");
    check_bounds(s, v3(-3, -3, -1), v3(3, 3, 1), 1e-13);
    sc_scene_release(s);
    /* nested resize */
    s = load("resize([3, 0, 0]) { resize([100, 0, 0]) { cube(1); } }");
    check_bounds(s, v3(0, 0, 0), v3(3, 1, 1), 1e-13);
    sc_scene_release(s);
    /* 60 nested resizes, alone and in a hull: each is measured once (a
     * walk that measured them again at each level would never finish) */
    char text[4096];
    for (int in_hull = 0; in_hull < 2; in_hull++) {
        strcpy(text, in_hull ? "hull() { " : "");
        for (int i = 0; i < 60; i++)
            strcat(text, "resize([3, 0, 0]) { ");
        strcat(text, "cube(1);");
        for (int i = 0; i < 60; i++)
            strcat(text, " }");
        strcat(text, in_hull ? " }" : "");
        s = load(text);
        check_bounds(s, v3(0, 0, 0), v3(3, 1, 1), 1e-12);
        sc_scene_release(s);
    }
    /* an empty child: nothing to resize */
    s = load("resize([3, 3, 3]) { cube(0); }");
    assert_int_equal(scene_tree(s)->root, CSG_EMPTY);
    sc_scene_release(s);
}

static void test_resize_errors(void **state)
{
    (void)state;
    /* a negative size is as 0, as OpenSCAD resizes a mesh or a 2D shape:
     * that axis keeps its size, or takes the auto scale */
    sc_scene *neg =
        load("resize([-10, 0, 0]) { multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, "
             "1, 3], [0, 0, 0, 1]]) { cube(5); } }");
    check_bounds(neg, v3(1, 2, 3), v3(6, 7, 8), 1e-12);
    sc_scene_release(neg);
    neg = load(
        "resize([10, -20, 0], auto = [false, false, true]) { multmatrix([[1, 0, 0, 1], "
        "[0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]) { cube(5); } }");
    check_bounds(neg, v3(2, 2, 6), v3(12, 7, 16), 1e-12);
    sc_scene_release(neg);
    /* arguments of the wrong kind, as OpenSCAD 2021.01 reads them: a
     * newsize that is no vector is [0, 0, 0], an entry that is no number
     * 0; an auto that is neither true, false nor a vector all false */
    sc_scene *odd = load("resize(newsize = 3) { cube([1, 2, 4]); }");
    check_bounds(odd, v3(0, 0, 0), v3(1, 2, 4), 1e-12);
    sc_scene_release(odd);
    odd = load("resize([2, \"a\", 0], auto = \"yes\") { cube([1, 2, 4]); }");
    check_bounds(odd, v3(0, 0, 0), v3(2, 2, 4), 1e-12);
    sc_scene_release(odd);
    odd = load("resize([2, 0, 0], auto = [0, \"y\", []]) { cube([1, 2, 4]); }");
    check_bounds(odd, v3(0, 0, 0), v3(2, 4, 4), 1e-12);
    sc_scene_release(odd);
    /* an ignored 2D child with an argument of the wrong kind: only
     * OpenSCAD's warnings of the child (openscad -o x.stl prints these) */
    odd = load("resize([2, 0, 0]) { cube(); circle(r = \"x\"); }");
    assert_int_equal(sc_scene_warning_count(odd), 2);
    assert_string_equal(sc_scene_warning(odd, 0)->message,
                        "Mixing 2D and 3D objects is not supported");
    assert_string_equal(sc_scene_warning(odd, 1)->message,
                        "Ignoring 2D child object for 3D operation");
    check_bounds(odd, v3(0, 0, 0), v3(2, 1, 1), 1e-12);
    sc_scene_release(odd);
    /* a revolved square ring (z 0 to 1) stretched to height 2 */
    sc_scene *r =
        load("resize([0, 0, 2]) { rotate_extrude($fn = 4) { "
             "multmatrix([[1,0,0,4],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) { square(1); } "
             "} }");
    assert_true(inside(r, 4.5, 0, 1.9));
    assert_false(inside(r, 4.5, 0, 2.1) || inside(r, 3.9, 0, 1));
    sc_scene_release(r);
    sc_scene *s =
        load("resize([0, 0, 5]) { polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, "
             "1, 0]], faces = [[0, 1, 2], [0, 2, 1]]); }");
    assert_true(sc_scene_warning_count(s) >= 1);
    assert_string_equal(
        sc_scene_warning(s, 0)->message,
        "resize in a direction normal to a flat object is not implemented");
    sc_scene_release(s);
}

/* resize of 2D children is a 2D resize (Polygon2d::resize): the 2D model
 * is the slab of the scaled region, 1 thick about z = 0. */
static void test_resize_2d(void **state)
{
    (void)state;
    sc_scene *s = load("resize([4, 2]) { projection() { cube(1); } }");
    check_bounds(s, v3(0, 0, -0.5), v3(4, 2, 0.5), 1e-12);
    sc_scene_release(s);
    /* auto: y takes x's scale; a negative size is as 0 */
    s = load("resize([6, 0], auto = true) { multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], "
             "[0, 0, 1, 0], [0, 0, 0, 1]]) { square([2, 1]); } }");
    check_bounds(s, v3(3, 3, -0.5), v3(9, 6, 0.5), 1e-12);
    sc_scene_release(s);
    s = load("resize([-6, 3]) { square([2, 1]); }");
    check_bounds(s, v3(0, 0, -0.5), v3(2, 3, 0.5), 1e-12);
    sc_scene_release(s);
    /* y larger than x: y's scale is the auto one */
    s = load("resize([0, 8], auto = [true, false]) { square([1, 2]); }");
    check_bounds(s, v3(0, 0, -0.5), v3(4, 8, 0.5), 1e-12);
    sc_scene_release(s);
    /* hull and minkowski of 2D children in a 2D model */
    s = load("hull() { square(1); multmatrix([[1, 0, 0, 5], [0, 1, 0, 2], [0, 0, 1, "
             "0], [0, 0, 0, 1]]) { square(1); } }");
    check_bounds(s, v3(0, 0, -0.5), v3(6, 3, 0.5), 1e-12);
    assert_false(inside(s, 5.5, 0.5, 0));
    assert_true(inside(s, 3, 1.5, 0));
    sc_scene_release(s);
    s = load("minkowski() { square(1); multmatrix([[1, 0, 0, 5], [0, 1, 0, 2], [0, 0, "
             "1, 0], [0, 0, 0, 1]]) { square(1); } }");
    check_bounds(s, v3(5, 2, -0.5), v3(7, 4, 0.5), 1e-12);
    sc_scene_release(s);
    /* and inside an extrusion */
    s = load("linear_extrude(height = 2) { resize([3, 0], auto = true) { square(1); } }");
    check_bounds(s, v3(0, 0, 0), v3(3, 3, 2), 1e-12);
    sc_scene_release(s);
}

/* A boolean's box is that of OpenSCAD's CGAL result, and a negative size
 * mirrors it (CGAL_Nef_polyhedron::resize); a single solid is a mesh,
 * resized only where the size is > 0. */
static void test_resize_boolean(void **state)
{
    (void)state;
    /* the cut leaves x 0..6 of the cube's 0..10 */
    const char *cut = "difference() { cube([10, 4, 4]); multmatrix([[1, 0, 0, 6], [0, 1, "
                      "0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) { cube([5, 6, 6]); } }";
    char text[256];
    snprintf(text, sizeof text, "resize([12, 0, 0]) { %s }", cut);
    sc_scene *s = load(text);
    assert_true(inside(s, 11.9, 2, 2) && inside(s, 0.1, 3.9, 3.9));
    assert_false(inside(s, 12.1, 2, 2) || inside(s, 1, 4.1, 2));
    sc_scene_release(s);
    /* mirrored along every axis by the auto scale -12 / 6 */
    snprintf(text, sizeof text, "resize([-12, 0, 0], auto = true) { %s }", cut);
    s = load(text);
    assert_true(inside(s, -11.9, -4, -4) && inside(s, -0.1, -7.9, -7.9));
    assert_false(inside(s, -12.1, -4, -4) || inside(s, 0.1, -4, -4) ||
                 inside(s, -1, -8.1, -4));
    sc_scene_release(s);
    /* two solids are a union, a Nef polyhedron too */
    s = load("resize([0, -4, 0]) { cube(1); multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, "
             "0, 1, 0], [0, 0, 0, 1]]) { cube(1); } }");
    check_bounds(s, v3(0, -4, 0), v3(2, 0, 1), 1e-9);
    sc_scene_release(s);
    /* a 2D child of a boolean there is the empty solid, with OpenSCAD's
     * warnings once (measuring is silent; the walk that builds it warns) */
    s = load("resize([0, 0, 4]) { difference() { cube(2); cube(1); square(3); } }");
    assert_true(inside(s, 1.5, 1.5, 3.9));
    assert_false(inside(s, 1.5, 1.5, 4.1) || inside(s, 0.5, 0.5, 0.5));
    assert_int_equal(sc_scene_warning_count(s), 2);
    sc_scene_release(s);
    s = load("hull() { difference() { cube(2); cube(1); square(3); } }");
    check_bounds(s, v3(0, 0, 0), v3(2, 2, 2), 1e-12);
    assert_int_equal(sc_scene_warning_count(s), 2);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "Mixing 2D and 3D objects is not supported");
    assert_string_equal(sc_scene_warning(s, 1)->message,
                        "Ignoring 2D child object for 3D operation");
    sc_scene_release(s);
    /* a difference of one solid is that solid: a mesh */
    s = load("resize([-3, 2, 0]) { difference() { cube(1); } }");
    check_bounds(s, v3(0, 0, 0), v3(1, 2, 1), 1e-12);
    sc_scene_release(s);
}

/* ---- surface ---- */

static const char *work(void)
{
    mkdir(SPANCAST_TEST_WORK, 0777);
    return SPANCAST_TEST_WORK;
}

static void write_file(const char *name, const void *data, size_t size)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", work(), name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, size, f), size);
    fclose(f);
}

static sc_scene *load_file(const char *name, const char *text)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", work(), name);
    return load_opts(path, text, 0);
}

static void test_surface_dat(void **state)
{
    (void)state;
    /* two rows of three values; the second row is short (padded with 0) */
    const char dat[] = "# heights\n\n1 2 3\r\n4\t5\n";
    write_file("h.dat", dat, sizeof dat - 1);
    sc_scene *s = load_file("m.csg", "surface(file = \"h.dat\", center = false, invert = "
                                     "false);");
    assert_int_equal(scene_tree(s)->leaves[0].prim.kind, PRIM_MESH);
    /* x 0..2 (columns), y 0..1 (rows); the floor is min(0, 1 - 1) = 0 from
     * the values read, before the padding */
    check_bounds(s, v3(0, 0, 0), v3(2, 1, 5), 0);
    /* each cell's centre is at its corners' mean: (1 + 2 + 4 + 5) / 4 and
     * (2 + 3 + 5 + 0) / 4 */
    assert_true(inside(s, 0.5, 0.5, 2.99));
    assert_false(inside(s, 0.5, 0.5, 3.01));
    assert_true(inside(s, 1.5, 0.5, 2.49));
    assert_false(inside(s, 1.5, 0.5, 2.51));
    assert_true(inside(s, 1.5, 0.5, 0.01));
    assert_false(inside(s, 1.5, 0.5, -0.01));
    sc_scene_release(s);
    s = load_file("m.csg", "surface(file = \"h.dat\", center = true);");
    check_bounds(s, v3(-1, -0.5, 0), v3(1, 0.5, 5), 0);
    sc_scene_release(s);
}

/* A PNG file, grey, 8 bits, stored without compression. */
static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

static size_t put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
    return 4;
}

static size_t chunk(unsigned char *out, const char *type, const unsigned char *data,
                    uint32_t n)
{
    size_t k = put32(out, n);
    memcpy(out + k, type, 4);
    if (n)
        memcpy(out + k + 4, data, n);
    k += 4 + n;
    return k + put32(out + k, crc32_of(out + 4, 4 + n));
}

static void write_png(const char *name, const unsigned char *grey, uint32_t w, uint32_t h)
{
    unsigned char raw[256], z[300], ihdr[13], file[600];
    uint32_t n = 0;
    for (uint32_t y = 0; y < h; y++) {
        raw[n++] = 0; /* no filter */
        for (uint32_t x = 0; x < w; x++)
            raw[n++] = grey[y * w + x];
    }
    size_t k = 0;
    z[k++] = 0x78;
    z[k++] = 0x01;
    z[k++] = 1; /* final stored block */
    z[k++] = (unsigned char)n;
    z[k++] = (unsigned char)(n >> 8);
    z[k++] = (unsigned char)~n;
    z[k++] = (unsigned char)(~n >> 8);
    memcpy(z + k, raw, n);
    k += n;
    uint32_t a = 1, b = 0;
    for (uint32_t i = 0; i < n; i++) {
        a = (a + raw[i]) % 65521;
        b = (b + a) % 65521;
    }
    k += put32(z + k, b << 16 | a);
    put32(ihdr, w);
    put32(ihdr + 4, h);
    ihdr[8] = 8;  /* bits */
    ihdr[9] = 0;  /* grey */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0;
    ihdr[12] = 0;
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    size_t m = 0;
    memcpy(file, sig, 8);
    m = 8;
    m += chunk(file + m, "IHDR", ihdr, 13);
    m += chunk(file + m, "IDAT", z, (uint32_t)k);
    m += chunk(file + m, "IEND", NULL, 0);
    write_file(name, file, m);
}

static void test_surface_png(void **state)
{
    (void)state;
    /* 3 x 2 pixels; the top image row is the far row (y = 1) */
    const unsigned char grey[6] = {255, 255, 255, 0, 51, 0};
    write_png("h.png", grey, 3, 2);
    sc_scene *s = load_file("m.csg", "surface(file = \"h.png\");");
    /* 255 -> 100 (to rounding of the luma weights), 51 -> 20 */
    bbox b = scene_tree(s)->bounds;
    assert_true(fabs(b.hi.z - 100) <= 1e-9);
    assert_true(b.lo.z == -1);
    /* cell centres: (0 + 20 + 100 + 100) / 4 */
    assert_true(inside(s, 0.5, 0.5, 54.9));
    assert_false(inside(s, 0.5, 0.5, 55.1));
    assert_true(inside(s, 1.5, 0.5, 54.9));
    assert_false(inside(s, 1.5, 0.5, 55.1));
    sc_scene_release(s);
    /* invert: 100 / 255 (1 - L), below zero; the floor is 1 under it */
    s = load_file("m.csg", "surface(file = \"h.png\", invert = true);");
    b = scene_tree(s)->bounds;
    assert_true(fabs(b.lo.z - (100.0 / 255 * (1 - 255.0) - 1)) <= 1e-9);
    assert_true(fabs(b.hi.z - 100.0 / 255) <= 1e-12);
    sc_scene_release(s);
}

/* Loading text as name with --strict fails with status and a message that
 * starts with prefix and ends with suffix. */
static void check_error_strict(const char *name, const char *text, sc_status status,
                               const char *prefix, const char *suffix)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.strict = 1;
    assert_int_equal(sc_scene_load_string(name, text, strlen(text), &o, &s, &e), status);
    assert_null(s);
    char buf[1024];
    const char *got = sc_error_format(&e, buf, sizeof buf);
    size_t n = strlen(got), p = strlen(prefix), q = strlen(suffix);
    if (n < p + q || memcmp(got, prefix, p) || memcmp(got + n - q, suffix, q))
        fail_msg("error '%s', want '%s...%s'", got, prefix, suffix);
}

/* Loads text (a cube and a surface) and checks its one warning, at the
 * file name (column 99), by its start and end, and that the cube is
 * still there. */
static sc_scene *load_surface_warned(const char *text, int faithful, const char *prefix,
                                     const char *suffix)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/m.csg", work());
    sc_scene *s = load_opts(path, text, faithful);
    assert_int_equal(sc_scene_warning_count(s), 1);
    const sc_error *w = sc_scene_warning(s, 0);
    assert_int_equal(w->line, 1);
    assert_int_equal(w->column, 99);
    size_t n = strlen(w->message), p = strlen(prefix), q = strlen(suffix);
    if (n < p + q || memcmp(w->message, prefix, p) ||
        memcmp(w->message + n - q, suffix, q))
        fail_msg("warning '%s', want '%s...%s'", w->message, prefix, suffix);
    assert_true(inside(s, -4.5, 0.5, 0.5));
    return s;
}

/* OpenSCAD 2021.01 renders a model whose surface file cannot be opened or
 * read with a warning, the surface empty; of a .dat file with an illegal
 * value it keeps what it read before the value (the value's line up to
 * it, the rest of the line padded with 0) and ignores the rest. So does
 * spancast, in both modes; --strict makes each warning the error. */
static void test_surface_lenient(void **state)
{
    (void)state;
    char path[1024], prefix[2048];
    snprintf(path, sizeof path, "%s/m.csg", work());
    const char *left_out = "; the surface is empty, as OpenSCAD leaves it out (--strict "
                           "makes it an error)";
    const char *stopped = "; the rest of the file is ignored, as OpenSCAD stops reading "
                          "there (--strict makes it an error)";
    const char bad[] = "1 2 3\n4 x 6\n7 8 9\n";
    write_file("bad.dat", bad, sizeof bad - 1);
    const char not_png[] = "not a png\n";
    write_file("bad.png", not_png, sizeof not_png - 1);
    const unsigned char broken[16] = {0x89, 'P',  'N', 'G', '\r', '\n',
                                      0x1a, '\n', 0,   0,   0};
    write_file("broken.png", broken, sizeof broken);
    for (int faithful = 0; faithful < 2; faithful++) {
        /* a file that cannot be opened: empty */
        snprintf(prefix, sizeof prefix,
                 "surface: the file '%s/nope.png' couldn't be opened: No such file or "
                 "directory",
                 work());
        sc_scene *s = load_surface_warned(
            "multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
            "{ cube(1); } surface(file = \"nope.png\");",
            faithful, prefix, left_out);
        assert_int_equal(scene_tree(s)->leaf_count, 1);
        sc_scene_release(s);
        /* not a PNG (no signature): a .dat file, whose first value is
         * illegal, so nothing is read: empty, with no more warning */
        snprintf(prefix, sizeof prefix,
                 "surface: illegal value in '%s/bad.png' line 1: 'not' is not a number",
                 work());
        s = load_surface_warned(
            "multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
            "{ cube(1); } surface(file = \"bad.png\");",
            faithful, prefix, stopped);
        assert_int_equal(scene_tree(s)->leaf_count, 1);
        sc_scene_release(s);
        /* a PNG signature, then nothing readable: empty */
        snprintf(prefix, sizeof prefix,
                 "surface: can't read PNG image '%s/broken.png': ", work());
        s = load_surface_warned(
            "multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
            "{ cube(1); } surface(file = \"broken.png\");",
            faithful, prefix, left_out);
        assert_int_equal(scene_tree(s)->leaf_count, 1);
        sc_scene_release(s);
        /* an illegal value on line 2: rows 1 2 3 and 4 0 0, the floor at
         * min(0, 1 - 1) from the values read, as OpenSCAD builds it */
        snprintf(prefix, sizeof prefix,
                 "surface: illegal value in '%s/bad.dat' line 2: 'x' is not a number",
                 work());
        s = load_surface_warned(
            "multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
            "{ cube(1); } surface(file = \"bad.dat\");",
            faithful, prefix, stopped);
        assert_int_equal(scene_tree(s)->leaf_count, 2);
        assert_true(inside(s, 0.5, 0.5, 1.74)); /* (1 + 2 + 4 + 0) / 4 */
        assert_false(inside(s, 0.5, 0.5, 1.76));
        assert_true(inside(s, 1.5, 0.5, 1.24)); /* (2 + 3 + 0 + 0) / 4 */
        assert_false(inside(s, 1.5, 0.5, 1.26));
        assert_true(inside(s, 1.5, 0.5, 0.01));
        assert_false(inside(s, 1.5, 0.5, -0.01));
        assert_false(inside(s, 1.5, 1.5, 0.5)); /* no third row */
        assert_false(inside(s, 2.5, 0.5, 0.5)); /* no fourth column */
        sc_scene_release(s);
    }
    /* --strict: the errors */
    snprintf(
        prefix, sizeof prefix,
        "%s:1:16: error: surface: the file '%s/nope.png' couldn't be opened: No such "
        "file or directory",
        path, work());
    check_error_strict(path, "surface(file = \"nope.png\");", SC_ERR_IO, prefix, "");
    snprintf(
        prefix, sizeof prefix,
        "%s:1:16: error: surface: illegal value in '%s/bad.png' line 1: 'not' is not "
        "a number",
        path, work());
    check_error_strict(path, "surface(file = \"bad.png\");", SC_ERR_SEMANTIC, prefix, "");
    snprintf(prefix, sizeof prefix,
             "%s:1:16: error: surface: can't read PNG image '%s/broken.png': ", path,
             work());
    check_error_strict(path, "surface(file = \"broken.png\");", SC_ERR_IO, prefix, "");
    snprintf(
        prefix, sizeof prefix,
        "%s:1:16: error: surface: illegal value in '%s/bad.dat' line 2: 'x' is not a "
        "number",
        path, work());
    check_error_strict(path, "surface(file = \"bad.dat\");", SC_ERR_SEMANTIC, prefix, "");
}

static void test_surface_errors(void **state)
{
    (void)state;
    /* no file: OpenSCAD reads the file "" (its export writes file = "") */
    check_warning("surface();",
                  "surface: the file '' couldn't be opened: No such file or directory; "
                  "the surface is empty, as OpenSCAD leaves it out (--strict makes it an "
                  "error)");
    /* a file name that is not a string is its text, as OpenSCAD 2021.01
     * takes it; center and invert true only when they are true */
    check_warning("surface(file = 3, center = 1, invert = \"yes\");",
                  "surface: the file '3' couldn't be opened: No such file or directory; "
                  "the surface is empty, as OpenSCAD leaves it out (--strict makes it an "
                  "error)");
    /* one row: no area */
    const char one[] = "1 2 3\n";
    write_file("one.dat", one, sizeof one - 1);
    sc_scene *s = load_file("m.csg", "surface(file = \"one.dat\");");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message, "surface without area is empty");
    sc_scene_release(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hull_boxes),
        cmocka_unit_test(test_hull_curved),
        cmocka_unit_test(test_hull_extrusions),
        cmocka_unit_test(test_hull_errors),
        cmocka_unit_test(test_hull_booleans),
        cmocka_unit_test(test_hull_boolean_once),
        cmocka_unit_test(test_hull_booleans_threads),
        cmocka_unit_test(test_hull_empty),
        cmocka_unit_test(test_minkowski),
        cmocka_unit_test(test_minkowski_union),
        cmocka_unit_test(test_minkowski_nonconvex),
        cmocka_unit_test(test_minkowski_errors),
        cmocka_unit_test(test_resize),
        cmocka_unit_test(test_resize_boxes),
        cmocka_unit_test(test_resize_errors),
        cmocka_unit_test(test_resize_2d),
        cmocka_unit_test(test_resize_boolean),
        cmocka_unit_test(test_surface_dat),
        cmocka_unit_test(test_surface_png),
        cmocka_unit_test(test_surface_lenient),
        cmocka_unit_test(test_surface_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
