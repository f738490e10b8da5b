/* Tests of the interpolation of transforms (src/math/motion.c): the ends
 * are the two transforms; a turn is interpolated at a constant angular
 * speed about its axis (points stay on their circle, not on the chord); a
 * turn with a stretch and a shift splits into its parts; a mirroring pair
 * interpolates, and pairs that are singular or disagree on mirroring are
 * refused. */
#define PI 3.14159265358979323846

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>

#include "math/motion.h"

static affine make(double a, double b, double c, double d, double e, double f, double g,
                   double h, double i, double tx, double ty, double tz)
{
    affine m = {{{a, b, c, tx}, {d, e, f, ty}, {g, h, i, tz}}};
    return m;
}

static void assert_affine_near(const affine *x, const affine *y, double tol)
{
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            if (fabs(x->m[r][k] - y->m[r][k]) > tol)
                fail_msg("entry %d,%d: %.17g against %.17g", r, k, x->m[r][k],
                         y->m[r][k]);
}

static affine rot_z(double deg, double s, vec3 t)
{
    double c = cos(deg * PI / 180), n = sin(deg * PI / 180);
    return make(s * c, -s * n, 0, s * n, s * c, 0, 0, 0, s, t.x, t.y, t.z);
}

static void test_ends(void **state)
{
    (void)state;
    affine a = make(2, 0.3, 0, -0.1, 1, 0.2, 0.4, 0, 3, 1, 2, 3);
    affine b = rot_z(70, 1.5, v3(-4, 0, 1));
    motion m;
    assert_int_equal(motion_init(&m, &a, &b), 1);
    affine at0 = motion_at(&m, 0), at1 = motion_at(&m, 1);
    assert_affine_near(&at0, &a, 1e-12);
    assert_affine_near(&at1, &b, 1e-12);
}

static void test_turn_on_arc(void **state)
{
    (void)state;
    affine a = rot_z(0, 1, v3(0, 0, 0)), b = rot_z(90, 1, v3(0, 0, 0));
    motion m;
    assert_int_equal(motion_init(&m, &a, &b), 1);
    for (int k = 0; k <= 8; k++) {
        double s = k / 8.0;
        affine at = motion_at(&m, s), want = rot_z(90 * s, 1, v3(0, 0, 0));
        assert_affine_near(&at, &want, 1e-12);
        vec3 p = affine_point(&at, v3(10, 0, 0));
        assert_true(fabs(v3_length(p) - 10) < 1e-12); /* on the circle */
    }
}

static void test_parts(void **state)
{
    (void)state;
    /* From a 40 degree turn scaled 2 at (1, 0, 0) to a 100 degree turn
     * scaled 4 at (5, 4, 0): halfway is 70 degrees, scale 3, (3, 2, 0). */
    affine a = rot_z(40, 2, v3(1, 0, 0)), b = rot_z(100, 4, v3(5, 4, 0));
    motion m;
    assert_int_equal(motion_init(&m, &a, &b), 1);
    affine half = motion_at(&m, 0.5), want = rot_z(70, 3, v3(3, 2, 0));
    assert_affine_near(&half, &want, 1e-12);
    /* The shorter arc: 350 degrees from 0 is 10 degrees the other way. */
    affine c = rot_z(350, 1, v3(0, 0, 0));
    assert_int_equal(motion_init(&m, &a, &c), 1);
    affine mid = motion_at(&m, 0.5);
    want = rot_z(15, 1.5, v3(0.5, 0, 0));
    assert_affine_near(&mid, &want, 1e-12);
}

static void test_mirror_and_singular(void **state)
{
    (void)state;
    affine a = make(-1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0);
    affine b = make(0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0); /* a mirror too */
    affine id = make(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0);
    affine flat = make(1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0);
    motion m;
    assert_int_equal(motion_init(&m, &a, &b), 1);
    affine at1 = motion_at(&m, 1);
    assert_affine_near(&at1, &b, 1e-12);
    assert_int_equal(motion_init(&m, &a, &id), 0);
    assert_int_equal(motion_init(&m, &id, &flat), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ends),
        cmocka_unit_test(test_turn_on_arc),
        cmocka_unit_test(test_parts),
        cmocka_unit_test(test_mirror_and_singular),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
