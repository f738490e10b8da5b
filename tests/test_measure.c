/* Tests of sc_scene_measure (src/api/measure.c, src/api/quad.c): the
 * estimate of every value must hold the analytic value within its error
 * bound, the bound must be small enough to mean something (a few times the
 * tolerance asked for), and the result must not depend on the number of
 * threads.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"

#define PI 3.14159265358979323846

/* A model with its analytic mass properties (unit density). */
typedef struct solid_case {
    const char *name;
    const char *text;
    double tolerance;
    double volume, area;
    double centroid[3];
    double principal[3]; /* ascending */
    double lo[3], hi[3]; /* the tight box */
} solid_case;

/* value +- error holds truth, and the error is at most limit. */
static void check(const char *what, const char *name, sc_estimate e, double truth,
                  double limit)
{
    if (!(fabs(e.value - truth) <= e.error))
        fail_msg("%s of %s: %.12g +- %.3g does not hold %.12g (off by %.3g)", what, name,
                 e.value, e.error, truth, fabs(e.value - truth));
    if (!(e.error <= limit))
        fail_msg("%s of %s: error bound %.3g is above %.3g", what, name, e.error, limit);
}

static void measure_case(const solid_case *c, int threads, sc_measure *m)
{
    sc_scene *s = test_load(c->name, c->text, 0);
    sc_measure_options o;
    sc_measure_options_init(&o);
    o.tolerance = c->tolerance;
    o.threads = threads;
    sc_measure_init(m);
    sc_error e;
    if (sc_scene_measure(s, &o, m, &e) != SC_OK)
        fail_msg("%s: %s", c->name, e.message);
    sc_scene_release(s);
}

static void check_case(const solid_case *c)
{
    sc_measure m;
    measure_case(c, 0, &m);
    /* The bound is at most 20 times the tolerance: the target of each axis,
     * the spread between the axes and, for the area, between its two
     * estimators add up, but never to orders of magnitude more. */
    double slack = 20 * c->tolerance;
    check("volume", c->name, m.volume, c->volume, slack * c->volume);
    check("area", c->name, m.area, c->area, slack * c->area);
    double size = cbrt(c->volume);
    for (int i = 0; i < 3; i++) {
        check("centroid", c->name, m.centroid[i], c->centroid[i], slack * size);
        check("principal moment", c->name, m.principal[i], c->principal[i],
              slack * c->principal[2]);
        /* The box's truth lies between the sampled extremes and the tree's
         * bounds; its error is the width of that interval. */
        assert_true(m.box_lo[i].value - m.box_lo[i].error <= c->lo[i] + 1e-12);
        assert_true(c->lo[i] <= m.box_lo[i].value + 1e-12);
        assert_true(m.box_hi[i].value - 1e-12 <= c->hi[i]);
        assert_true(c->hi[i] <= m.box_hi[i].value + m.box_hi[i].error + 1e-12);
        assert_true(m.box_hi[i].value - m.box_lo[i].value > 0.99 * (c->hi[i] - c->lo[i]));
    }
    assert_true(m.converged);
    assert_true(m.lines > 0);
}

static const char sphere_text[] =
    "multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
    "  sphere(r = 3);\n"
    "}\n";

static void test_sphere(void **state)
{
    (void)state;
    double v = 4.0 / 3 * PI * 27, i = 0.4 * v * 9;
    solid_case c = {"sphere.csg", sphere_text, 1e-4,       v,        4 * PI * 9,
                    {3, 0, 5},    {i, i, i},   {0, -3, 2}, {6, 3, 8}};
    check_case(&c);
}

static void test_box(void **state)
{
    (void)state;
    /* I = m (b^2 + c^2) / 12 about each axis. */
    solid_case c = {"box.csg",    "cube(size = [2, 3, 4]);",
                    1e-4,         24,
                    52,           {1, 1.5, 2},
                    {26, 40, 50}, {0, 0, 0},
                    {2, 3, 4}};
    check_case(&c);
}

static void test_cylinder(void **state)
{
    (void)state;
    /* r = 2, h = 5: I_z = m r^2 / 2, I_x = m (3 r^2 + h^2) / 12. */
    double m = PI * 4 * 5;
    solid_case c = {"cylinder.csg",
                    "cylinder(h = 5, r1 = 2, r2 = 2, center = false);",
                    1e-3,
                    m,
                    2 * PI * 4 + 2 * PI * 2 * 5,
                    {0, 0, 2.5},
                    {m * 2, m * 37 / 12, m * 37 / 12},
                    {-2, -2, 0},
                    {2, 2, 5}};
    check_case(&c);
}

static void test_cone(void **state)
{
    (void)state;
    /* r = 3 at the base, h = 4, slant 5: the centroid is h/4 above the
     * base, I_z = 3/10 m r^2, I_x = m (3/20 r^2 + 3/80 h^2) about it. */
    double m = PI * 9 * 4 / 3;
    solid_case c = {"cone.csg",
                    "cylinder(h = 4, r1 = 3, r2 = 0, center = false);",
                    1e-3,
                    m,
                    PI * 9 + PI * 3 * 5,
                    {0, 0, 1},
                    {m * 1.95, m * 1.95, m * 2.7},
                    {-3, -3, 0},
                    {3, 3, 4}};
    check_case(&c);
}

static void test_torus(void **state)
{
    (void)state;
    /* R = 5, r = 1: V = 2 pi^2 R r^2, A = 4 pi^2 R r, I_z = m (R^2 + 3/4 r^2),
     * I_x = m (R^2 / 2 + 5/8 r^2). */
    double m = 2 * PI * PI * 5;
    solid_case c = {"torus.csg",
                    "torus(r1 = 5, r2 = 1);",
                    1e-3,
                    m,
                    4 * PI * PI * 5,
                    {0, 0, 0},
                    {m * 13.125, m * 13.125, m * 25.75},
                    {-6, -6, -1},
                    {6, 6, 1}};
    check_case(&c);
}

static void test_hollow_sphere(void **state)
{
    (void)state;
    /* Radii 3 and 2: I = 8 pi / 15 (3^5 - 2^5) for a unit density. */
    double i = 8 * PI / 15 * (243 - 32);
    solid_case c = {"hollow.csg",
                    "difference() {\n  sphere(r = 3);\n  sphere(r = 2);\n}\n",
                    1e-3,
                    4.0 / 3 * PI * (27 - 8),
                    4 * PI * (9 + 4),
                    {0, 0, 0},
                    {i, i, i},
                    {-3, -3, -3},
                    {3, 3, 3}};
    check_case(&c);
}

static void test_drilled_box(void **state)
{
    (void)state;
    /* A 10 mm cube with a hole of radius 2 through it along z at (5, 5):
     * the cube less a cylinder of mass 40 pi, I_z = 1000 (10^2 + 10^2) / 12
     * - m_c r^2 / 2, I_x = 1000 (10^2 + 10^2) / 12 - m_c (3 r^2 + h^2) / 12. */
    double mc = 40 * PI, cube = 1000.0 * 200 / 12;
    solid_case c = {"drilled.csg",
                    "difference() {\n"
                    "  cube(size = [10, 10, 10]);\n"
                    "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, "
                    "1]]) {\n"
                    "    cylinder(h = 12, r1 = 2, r2 = 2);\n"
                    "  }\n"
                    "}\n",
                    1e-3,
                    1000 - mc,
                    600 - 8 * PI + 40 * PI,
                    {5, 5, 5},
                    {cube - mc * 112 / 12, cube - mc * 112 / 12, cube - mc * 2},
                    {0, 0, 0},
                    {10, 10, 10}};
    check_case(&c);
}

/* The same numbers, bit for bit, on one thread and on three. */
static void test_threads(void **state)
{
    (void)state;
    solid_case c = {"sphere.csg", sphere_text, 1e-3, 0, 0, {0}, {0}, {0}, {0}};
    sc_measure one, three;
    measure_case(&c, 1, &one);
    measure_case(&c, 3, &three);
    assert_int_equal(one.threads, 1);
    assert_int_equal(three.threads, 3);
    one.threads = three.threads = 0;
    assert_memory_equal(&one, &three, sizeof one);
}

/* Density scales mass and inertia, nothing else. */
static void test_density(void **state)
{
    (void)state;
    sc_scene *s = test_load("box.csg", "cube(size = [2, 3, 4]);", 0);
    sc_measure_options o;
    sc_measure_options_init(&o);
    o.density = 7.85e-3;
    sc_measure m;
    sc_measure_init(&m);
    sc_error e;
    assert_int_equal(sc_scene_measure(s, &o, &m, &e), SC_OK);
    check("mass", "box", m.mass, 24 * 7.85e-3, 1e-6);
    check("I_x", "box", m.inertia[0][0], 50 * 7.85e-3, 1e-3 * 50 * 7.85e-3);
    check("volume", "box", m.volume, 24, 1e-3);
    sc_scene_release(s);
}

static void test_empty_and_errors(void **state)
{
    (void)state;
    sc_scene *s = test_load(
        "empty.csg", "difference() {\n  cube(size = 1);\n  cube(size = 2);\n}\n", 0);
    sc_measure_options o;
    sc_measure_options_init(&o);
    sc_measure m;
    sc_measure_init(&m);
    sc_error e;
    assert_int_equal(sc_scene_measure(s, &o, &m, &e), SC_OK);
    assert_true(m.volume.value == 0 && m.volume.error == 0);
    assert_true(m.area.value == 0);
    o.tolerance = 0;
    assert_int_equal(sc_scene_measure(s, &o, &m, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "tolerance must lie between 0 and 1 (got 0)");
    o.tolerance = 1e-4;
    o.density = NAN;
    assert_int_equal(sc_scene_measure(s, &o, &m, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "density must be finite");
    sc_scene_release(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere),      cmocka_unit_test(test_box),
        cmocka_unit_test(test_cylinder),    cmocka_unit_test(test_cone),
        cmocka_unit_test(test_torus),       cmocka_unit_test(test_hollow_sphere),
        cmocka_unit_test(test_drilled_box), cmocka_unit_test(test_threads),
        cmocka_unit_test(test_density),     cmocka_unit_test(test_empty_and_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
