/* Tests of the affine maps of src/math/vec.c: affine_invert's shortcut for
 * a map whose linear part is the identity bit for bit (every positioned
 * leaf of an OpenSCAD export that only moves it) gives the very bits of
 * the general inverse, signed zeros, infinities and NaNs of the
 * translation included, and maps that differ from the identity by a sign
 * or an ulp still take the general path.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "math/vec.h"

/* The general inverse's translation for an identity linear part, as its
 * formula rounds it: -(1 t_i + 0 t_j + 0 t_k), in that order. */
static double moved_back(const double t[3], int i)
{
    double row[3] = {0.0, 0.0, 0.0};
    row[i] = 1.0;
    return -(row[0] * t[0] + row[1] * t[1] + row[2] * t[2]);
}

static void test_translation_inverse_bits(void **state)
{
    (void)state;
    const double values[] = {0.0,     -0.0,     1.5,       -2.01, 1e300,
                             -1e-310, INFINITY, -INFINITY, NAN,   201.0};
    const int n = (int)(sizeof values / sizeof values[0]);
    for (int x = 0; x < n; x++) {
        for (int y = 0; y < n; y++) {
            for (int z = 0; z < n; z++) {
                double t[3] = {values[x], values[y], values[z]};
                affine a = affine_identity(), inv;
                for (int i = 0; i < 3; i++)
                    a.m[i][3] = t[i];
                assert_int_equal(affine_invert(&a, &inv), 1);
                affine want = affine_identity();
                for (int i = 0; i < 3; i++)
                    want.m[i][3] = moved_back(t, i);
                assert_memory_equal(&inv, &want, sizeof want);
            }
        }
    }
}

/* A linear part that is the identity but for a negative zero, or for a
 * diagonal one ulp off, is inverted by the general formula (whose
 * cofactors then carry the sign or the ulp), and a singular one is still
 * refused. */
static void test_near_identity_general(void **state)
{
    (void)state;
    affine a = affine_identity(), inv;
    a.m[0][1] = -0.0;
    a.m[1][2] = -0.0;
    a.m[0][3] = 3;
    assert_int_equal(affine_invert(&a, &inv), 1);
    assert_true(inv.m[0][0] == 1 && inv.m[1][1] == 1 && inv.m[2][2] == 1);
    assert_true(inv.m[0][1] == 0 && inv.m[0][3] == -3);

    affine b = affine_identity();
    b.m[1][1] = nextafter(1.0, 2.0);
    b.m[1][3] = 1;
    assert_int_equal(affine_invert(&b, &inv), 1);
    assert_true(inv.m[1][1] == 1.0 / nextafter(1.0, 2.0));
    assert_true(inv.m[1][3] == -(inv.m[1][1] * 1));

    affine c = affine_identity();
    c.m[2][2] = 0;
    assert_int_equal(affine_invert(&c, &inv), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_translation_inverse_bits),
        cmocka_unit_test(test_near_identity_general),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
