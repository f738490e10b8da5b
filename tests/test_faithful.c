/* Tests of faithful mode (src/model/faithful.c and its use by the builder):
 * OpenSCAD 2021.01's fragment-count rule on a table of cases worked out by
 * hand from the rule, its degree trigonometry, and the plane sets of
 * spheres and cylinders checked against vertices computed here from the
 * documented layout: every vertex lies inside every plane, and every plane
 * holds at least three vertices, so the plane set is the polyhedron whose
 * vertices they are. Then rays through loaded scenes, and the errors.
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

#include "build/scene.h"
#include "model/faithful.h"

static const double pi = 3.14159265358979323846;

static void test_fragments(void **state)
{
    (void)state;
    static const struct {
        double r, fn, fs, fa;
        long expected;
    } cases[] = {
        {10, 0, 2, 12, 30},            /* defaults: min(360 / 12, 31.4) = 30 */
        {4, 0, 2, 12, 13},             /* 2 pi 4 / 2 = 12.57 -> 13 */
        {3, 0, 0.5, 1, 38},            /* 37.7 -> 38 */
        {20, 0, 0.1, 20, 18},          /* 360 / 20 */
        {0.2, 0, 2, 12, 5},            /* at least 5 */
        {8, 0, 1, 5, 51},              /* min(72, 50.27) -> 51 */
        {10, 5.7, 2, 12, 5},           /* $fn truncates */
        {10, 1, 2, 12, 3},             /* at least 3 */
        {10, 2.9, 2, 12, 3},           /* at least 3 */
        {10, -4, 2, 12, 30},           /* $fn <= 0 is off */
        {1e-7, 0, 2, 12, 3},           /* below OpenSCAD's grid */
        {1e-7, 64, 2, 12, 3},          /* ... even with $fn */
        {10, INFINITY, 2, 12, 3},      /* non-finite $fn */
        {10, NAN, 2, 12, 3},           /* non-finite $fn */
        {10, 0, 0, 0, -1},             /* no finite count */
        {10, 1e9, 2, 12, -1},          /* over the limit */
        {10, 65536, 2, 12, 65536},     /* at the limit */
        {10, 65537, 2, 12, -1},        /* past it */
        {10, 0, 0.001, 0.01, 36000},   /* 360 / 0.01 */
        {1000, 0, 0.5, 1e-300, 12567}, /* 2 pi 1000 / 0.5 = 12566.4 */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        long got = faithful_fragments(cases[k].r, cases[k].fn, cases[k].fs, cases[k].fa);
        if (got != cases[k].expected)
            fail_msg("case %zu: %ld fragments, expected %ld", k, got, cases[k].expected);
        /* a sphere's limit is lower: its faces grow as the square */
        long sphere =
            faithful_sphere_fragments(cases[k].r, cases[k].fn, cases[k].fs, cases[k].fa);
        long expected = cases[k].expected > 4096 ? -1 : cases[k].expected;
        if (sphere != expected)
            fail_msg("case %zu: %ld sphere fragments, expected %ld", k, sphere, expected);
    }
    assert_int_equal(faithful_sphere_fragments(10, 4096, 2, 12), 4096);
    assert_int_equal(faithful_sphere_fragments(10, 4097, 2, 12), -1);
}

static void test_degrees(void **state)
{
    (void)state;
    assert_true(faithful_sin_deg(0) == 0);
    assert_true(faithful_sin_deg(30) == 0.5);
    assert_true(faithful_sin_deg(150) == 0.5);
    assert_true(faithful_sin_deg(180) == 0);
    assert_true(faithful_sin_deg(270) == -1);
    assert_true(faithful_sin_deg(360) == 0);
    assert_true(faithful_sin_deg(-90) == -1);
    assert_true(faithful_cos_deg(90) == 0);
    assert_true(faithful_cos_deg(60) == 0.5);
    assert_true(faithful_cos_deg(120) == -0.5);
    assert_true(faithful_cos_deg(180) == -1);
    assert_true(faithful_cos_deg(270) == 0);
    assert_true(faithful_cos_deg(45) == faithful_sin_deg(45));
    for (int k = 0; k < 720; k++) {
        double x = -360 + k * 1.37;
        assert_true(fabs(faithful_sin_deg(x) - sin(x * pi / 180)) < 1e-14);
        assert_true(fabs(faithful_cos_deg(x) - cos(x * pi / 180)) < 1e-14);
    }
}

/* Checks that planes are exactly the faces of the hull of points: all
 * points inside all planes, at least three points on each plane. */
static void check_hull(const prim *p, const vec3 *points, size_t count, double scale)
{
    double tol = 1e-12 * scale;
    assert_int_equal(p->kind, PRIM_CONVEX);
    for (uint32_t k = 0; k < p->u.convex.count; k++) {
        const plane *pl = &p->u.convex.planes[k];
        assert_true(fabs(v3_length(pl->n) - 1) < 1e-12);
        int on = 0;
        for (size_t i = 0; i < count; i++) {
            double s = v3_dot(pl->n, points[i]) - pl->d;
            if (s > tol)
                fail_msg("point %zu is outside plane %u by %g", i, k, s);
            on += s > -tol;
        }
        if (on < 3)
            fail_msg("plane %u holds %d points", k, on);
    }
    for (size_t i = 0; i < count; i++) {
        assert_true(points[i].x >= p->u.convex.bounds.lo.x - tol);
        assert_true(points[i].z <= p->u.convex.bounds.hi.z + tol);
    }
}

static void test_sphere_planes(void **state)
{
    (void)state;
    static const double fns[] = {3, 4, 5, 6, 7, 12, 31, 64};
    for (size_t c = 0; c < sizeof fns / sizeof fns[0]; c++) {
        long f = (long)fns[c], rings = (f + 1) / 2;
        double r = 2.5;
        csg_builder *csg = csg_builder_new();
        prim p;
        sc_error e;
        assert_int_equal(faithful_sphere(csg, r, fns[c], 12, 2, NULL, &p, &e), SC_OK);
        assert_int_equal(p.u.convex.count, (uint32_t)((rings - 1) * f + 2));
        vec3 *points = malloc((size_t)(rings * f) * sizeof *points);
        for (long i = 0; i < rings; i++) {
            double phi = pi * (i + 0.5) / rings;
            for (long k = 0; k < f; k++) {
                double theta = 2 * pi * k / f;
                points[i * f + k] = v3(r * sin(phi) * cos(theta),
                                       r * sin(phi) * sin(theta), r * cos(phi));
            }
        }
        check_hull(&p, points, (size_t)(rings * f), r);
        free(points);
        csg_builder_free(csg);
    }
}

static void test_cylinder_planes(void **state)
{
    (void)state;
    static const struct {
        double r0, r1, fn;
        uint32_t planes;
    } cases[] = {
        {3, 3, 6, 8},   /* prism: 2 caps + 6 sides */
        {3, 1, 9, 11},  /* frustum */
        {1, 3, 5, 7},   /* frustum widening upwards */
        {3, 0, 12, 13}, /* cone, apex up: one cap */
        {0, 2, 3, 4},   /* cone, apex down */
        {5, 5, 0, 18},  /* defaults: 2 pi 5 / 2 = 15.7 -> 16 */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double z0 = -1.5, z1 = 4;
        long f = faithful_fragments(fmax(cases[c].r0, cases[c].r1), cases[c].fn, 2, 12);
        csg_builder *csg = csg_builder_new();
        prim p;
        sc_error e;
        assert_int_equal(faithful_cylinder(csg, z0, z1, cases[c].r0, cases[c].r1,
                                           cases[c].fn, 12, 2, NULL, &p, &e),
                         SC_OK);
        assert_int_equal(p.u.convex.count, cases[c].planes);
        vec3 *points = malloc((size_t)(2 * f) * sizeof *points);
        for (long k = 0; k < f; k++) {
            double theta = 2 * pi * k / f;
            points[k] = v3(cases[c].r0 * cos(theta), cases[c].r0 * sin(theta), z0);
            points[f + k] = v3(cases[c].r1 * cos(theta), cases[c].r1 * sin(theta), z1);
        }
        check_hull(&p, points, (size_t)(2 * f), 5);
        free(points);
        csg_builder_free(csg);
    }
}

static sc_scene *load(const char *text, int faithful)
{
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    sc_scene *s = NULL;
    sc_error e;
    if (sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e) != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    return s;
}

/* The first hit of the ray o + t d, or -1 when it misses. */
static double first_hit(const sc_scene *s, vec3 o, vec3 d)
{
    arena scratch;
    arena_init(&scratch, 4096);
    csg_ray ray = {o, d, 0, INFINITY};
    csg_hit hit;
    double t = csg_first_hit(scene_tree(s), &ray, &scratch, &hit) ? hit.t : -1;
    arena_free(&scratch);
    return t;
}

static void test_scene(void **state)
{
    (void)state;
    /* $fn = 4: the sphere's rings are squares at z = +-r cos 45 with
     * corners on the axes; the cylinder is a square prism, corners on the
     * axes, so its face in the +x+y quadrant is x + y = r. */
    const char *text = "sphere($fn = 4, $fa = 12, $fs = 2, r = 2);\n"
                       "multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], "
                       "[0, 0, 0, 1]]) { cylinder($fn = 4, $fa = 12, $fs = 2, h = 3, "
                       "r1 = 2, r2 = 2, center = true); }\n";
    sc_scene *exact = load(text, 0), *faithful = load(text, 1);
    const csg_tree *t = scene_tree(faithful);
    assert_int_equal(t->leaf_count, 2);
    assert_int_equal(t->leaves[0].prim.kind, PRIM_CONVEX);
    assert_int_equal(t->leaves[0].prim.u.convex.count, 6);
    assert_int_equal(t->leaves[1].prim.kind, PRIM_CONVEX);
    assert_int_equal(t->leaves[1].prim.u.convex.count, 6);
    assert_int_equal(scene_tree(exact)->leaves[0].prim.kind, PRIM_SPHERE);
    assert_int_equal(scene_tree(exact)->leaves[1].prim.kind, PRIM_CYLINDER);

    /* Down the axis onto the sphere's top cap, and onto the exact sphere.
     * The two are united, so OpenSCAD hands the sphere to CGAL with its
     * points on its grid of 2^-20: the cap at 2 cos 45, truncated to the
     * grid, in float. */
    double c45 = sqrt(0.5);
    double cap = (float)(trunc(2 * c45 * 1048576.0) / 1048576.0);
    assert_true(cap != 2 * c45);
    assert_true(fabs(first_hit(faithful, v3(0, 0, 10), v3(0, 0, -1)) - (10 - cap)) <
                1e-12);
    assert_true(fabs(first_hit(exact, v3(0, 0, 10), v3(0, 0, -1)) - 8) < 1e-12);
    /* Along -x at y = 0.5, z = 0 into the prism's face x + y = 2 (x from 10). */
    assert_true(fabs(first_hit(faithful, v3(20, 0.5, 0), v3(-1, 0, 0)) - 8.5) < 1e-12);
    assert_true(fabs(first_hit(exact, v3(20, 0.5, 0), v3(-1, 0, 0)) -
                     (10 - sqrt(4 - 0.25))) < 1e-12);
    /* Just outside the square ring at its corner direction: misses the
     * faithful sphere, hits the exact one. */
    assert_true(first_hit(faithful, v3(1.95 * c45, 1.95 * c45, 10), v3(0, 0, -1)) < 0);
    assert_true(first_hit(exact, v3(1.95 * c45, 1.95 * c45, 10), v3(0, 0, -1)) > 0);
    sc_scene_release(exact);
    sc_scene_release(faithful);
}

/* An infinite or nan $fn is OpenSCAD 2021.01's 3 fragments (its
 * primitive-inf-tests, which it renders): the same solids as $fn = 3. */
static void test_infinite_fn(void **state)
{
    (void)state;
    static const char format[] =
        "sphere($fn = %s, $fa = 12, $fs = 2, r = 2);\n"
        "multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "  cylinder($fn = %s, $fa = 12, $fs = 2, h = 3, r1 = 2, r2 = 1, center = true);\n"
        "}\n";
    char three[512], text[512];
    snprintf(three, sizeof three, format, "3", "3");
    sc_scene *expected = load(three, 1);
    const csg_tree *e = scene_tree(expected);
    assert_int_equal(e->leaf_count, 2);
    static const char *const values[] = {"inf", "-inf", "nan"};
    for (size_t k = 0; k < 3; k++) {
        snprintf(text, sizeof text, format, values[k], values[k]);
        sc_scene *got = load(text, 1);
        const csg_tree *t = scene_tree(got);
        assert_int_equal(t->leaf_count, 2);
        for (uint32_t i = 0; i < 2; i++) {
            assert_int_equal(t->leaves[i].prim.kind, PRIM_CONVEX);
            assert_int_equal(t->leaves[i].prim.u.convex.count,
                             e->leaves[i].prim.u.convex.count);
        }
        for (int y = -4; y <= 4; y++) {
            vec3 o = v3(-5, 0.3 * y, 0.25 * y), d = v3_normalize(v3(1, 0.01, 0.02));
            assert_true(first_hit(got, o, d) == first_hit(expected, o, d));
        }
        sc_scene_release(got);
        /* exact mode draws the true shapes, whatever $fn is */
        got = load(text, 0);
        assert_int_equal(scene_tree(got)->leaves[0].prim.kind, PRIM_SPHERE);
        sc_scene_release(got);
    }
    sc_scene_release(expected);
}

/* A faithful sphere's normal at a hit is its face's: within the angle
 * between neighbouring rings of the direction to the hit, here for rays
 * from all sides down to the centre, and for a sphere of more faces
 * than a convex leaf numbers (80,000 at $fn = 400), whose normals were
 * another face's past the 65,536th. */
static void check_sphere_normals(double fn)
{
    char text[128];
    snprintf(text, sizeof text, "sphere($fn = %g, $fa = 12, $fs = 2, r = 3);\n", fn);
    sc_scene *s = load(text, 1);
    const csg_tree *t = scene_tree(s);
    arena scratch;
    arena_init(&scratch, 4096);
    double limit = cos(2 * 360 / fn * pi / 180); /* two rings apart */
    for (int k = 0; k < 400; k++) {
        double theta = 2 * pi * k / 400.0 * 7, z = -0.995 + 1.99 * k / 399.0;
        vec3 dir = v3(sqrt(1 - z * z) * cos(theta), sqrt(1 - z * z) * sin(theta), z);
        csg_ray ray = {v3_scale(dir, 10), v3_neg(dir), 0, INFINITY};
        csg_hit hit;
        assert_true(csg_first_hit(t, &ray, &scratch, &hit));
        vec3 n = csg_hit_normal(t, &ray, &hit);
        if (!(v3_dot(n, dir) > limit))
            fail_msg("$fn = %g, ray %d: normal (%g, %g, %g) against (%g, %g, %g)", fn, k,
                     n.x, n.y, n.z, dir.x, dir.y, dir.z);
        arena_reset(&scratch);
    }
    arena_free(&scratch);
    sc_scene_release(s);
}

static void test_sphere_normals(void **state)
{
    (void)state;
    check_sphere_normals(24);
    check_sphere_normals(400);
}

/* Past PRIM_CONVEX_MAX_PLANES faces, spheres, cylinders and cones are
 * mesh leaves of the same polyhedra, closed (no warning), hit where the
 * plane sets are. */
static void test_mesh_leaves(void **state)
{
    (void)state;
    const char *text = "cylinder($fn = 300, $fa = 12, $fs = 2, h = 3, r1 = 2, r2 = 2, "
                       "center = false);\n"
                       "cylinder($fn = 300, $fa = 12, $fs = 2, h = 3, r1 = 0, r2 = 2, "
                       "center = false);\n"
                       "cylinder($fn = 300, $fa = 12, $fs = 2, h = 3, r1 = 2, r2 = 0, "
                       "center = false);\n"
                       "sphere($fn = 100, $fa = 12, $fs = 2, r = 2);\n";
    static const double fns[] = {254, 255, 300};
    static const int kinds[] = {PRIM_CONVEX, PRIM_MESH, PRIM_MESH};
    for (size_t k = 0; k < 3; k++) {
        char one[256];
        snprintf(one, sizeof one,
                 "cylinder($fn = %g, $fa = 12, $fs = 2, h = 3, r1 = 2, r2 = 1);", fns[k]);
        sc_scene *s = load(one, 1);
        assert_int_equal(scene_tree(s)->leaves[0].prim.kind, kinds[k]);
        sc_scene_release(s);
    }
    /* each alone, along -x at y = 0 through the edge from point 0: the
     * prism's at x = 2, the cones' half way up at x = 1, the sphere's
     * between the rings beside the equator at 2 sin(phi) */
    const char *line = text;
    double phi = 180.0 * (24 + 0.5) / 50;
    const double expected[4] = {8, 9, 9, 10 - 2 * sin(phi * pi / 180)};
    for (int k = 0; k < 4; k++) {
        const char *end = strchr(line, '\n');
        char one[256];
        snprintf(one, sizeof one, "%.*s", (int)(end - line), line);
        line = end + 1;
        sc_scene *s = load(one, 1);
        const csg_tree *t = scene_tree(s);
        assert_int_equal(t->leaves[0].prim.kind, PRIM_MESH);
        assert_int_equal(sc_scene_warning_count(s), 0);
        double t_hit = first_hit(s, v3(10, 0, k == 3 ? 0 : 1.5), v3(-1, 0, 0));
        if (!(fabs(t_hit - expected[k]) < 1e-9))
            fail_msg("model %d: hit at %.12g, expected %.12g", k, t_hit, expected[k]);
        sc_scene_release(s);
    }
}

static void check_error(const char *text, const char *expected)
{
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = 1;
    sc_scene *s = NULL;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e),
                     SC_ERR_LIMIT);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
    /* The same model loads in exact mode. */
    o.faithful = 0;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), &o, &s, &e),
                     SC_OK);
    sc_scene_release(s);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("group() {\n  sphere($fn = 5000, r = 1);\n}\n",
                "m.csg:2:3: error: faithful mode: $fn, $fa and $fs of radius 1 give "
                "too many fragments (limit is 4096)");
    /* $fa and $fs clamped to 0.01, as OpenSCAD clamps them: 36,000 for a
     * sphere; a cylinder of as many is drawn */
    check_error("sphere($fn = 0, $fa = 0, $fs = 0, r = 100);",
                "m.csg:1:1: error: faithful mode: $fn, $fa and $fs of radius 100 give "
                "too many fragments (limit is 4096)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fragments),     cmocka_unit_test(test_degrees),
        cmocka_unit_test(test_sphere_planes), cmocka_unit_test(test_cylinder_planes),
        cmocka_unit_test(test_scene),         cmocka_unit_test(test_sphere_normals),
        cmocka_unit_test(test_mesh_leaves),   cmocka_unit_test(test_errors),
        cmocka_unit_test(test_infinite_fn),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
