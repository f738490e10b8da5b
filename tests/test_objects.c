/* Tests of the top-level objects API (src/api/overlap.c): loading from a
 * file and from text give the same objects, their names and positions, the
 * overlapping pairs with volumes worked out from the boxes, and the
 * argument errors of both loads.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "spancast/spancast.h"
#include "test_util.h"

/* A box [0,10]^3, a box of side 5 at (8, 7, 6) and a box [10,14]x[0,10]^2
 * that shares the face x = 10 with the first. */
static const double at[3][3] = {{0, 0, 0}, {8, 7, 6}, {10, 0, 0}};
static const double size[3][3] = {{10, 10, 10}, {5, 5, 5}, {4, 10, 10}};

static char *boxes_text(void)
{
    char *t = malloc(1024);
    assert_non_null(t);
    int n = sprintf(t, "group() {\n");
    for (int k = 0; k < 3; k++)
        n += sprintf(t + n,
                     "  multmatrix([[1, 0, 0, %g], [0, 1, 0, %g], [0, 0, 1, %g], "
                     "[0, 0, 0, 1]]) { cube(size = [%g, %g, %g]); }\n",
                     at[k][0], at[k][1], at[k][2], size[k][0], size[k][1], size[k][2]);
    sprintf(t + n, "}\n");
    return t;
}

/* The volume the boxes a and b share. */
static double shared(int a, int b)
{
    double v = 1;
    for (int i = 0; i < 3; i++) {
        double lo = fmax(at[a][i], at[b][i]);
        double hi = fmin(at[a][i] + size[a][i], at[b][i] + size[b][i]);
        v *= fmax(0, hi - lo);
    }
    return v;
}

static void check_objects(const sc_objects *o, const char *name)
{
    assert_int_equal(sc_objects_count(o), 3);
    for (size_t k = 0; k < 3; k++) {
        assert_string_equal(sc_objects_name(o, k), "multmatrix");
        sc_location loc = sc_objects_location(o, k);
        assert_string_equal(loc.file, name);
        assert_int_equal(loc.line, (int)k + 2);
        assert_int_equal(loc.column, 3);
        assert_non_null(sc_objects_scene(o, k));
    }
    assert_null(sc_objects_name(o, 3));
    sc_measure_options mo;
    sc_measure_options_init(&mo);
    mo.threads = 1;
    sc_overlap_list *pairs = NULL;
    sc_error e;
    assert_int_equal(sc_objects_overlaps(o, &mo, &pairs, &e), SC_OK);
    /* Every pair with a shared volume, and only those (the face shared by
     * the first and third boxes has none). */
    size_t want = 0;
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++)
            want += shared(a, b) > 0;
    assert_int_equal(sc_overlap_list_count(pairs), want);
    for (size_t k = 0; k < want; k++) {
        const sc_overlap *p = sc_overlap_list_get(pairs, k);
        double v = shared((int)p->a, (int)p->b);
        assert_true(v > 0);
        assert_true(fabs(p->volume.value - v) <= fmax(p->volume.error, 1e-9 * v));
        assert_int_equal(p->converged, 1);
    }
    sc_overlap_list_release(pairs);
    /* A line budget too small for the tolerance: the same pairs, each
     * saying that its volume did not reach it. */
    mo.max_lines = 100;
    assert_int_equal(sc_objects_overlaps(o, &mo, &pairs, &e), SC_OK);
    assert_int_equal(sc_overlap_list_count(pairs), want);
    for (size_t k = 0; k < want; k++)
        assert_int_equal(sc_overlap_list_get(pairs, k)->converged, 0);
    sc_overlap_list_release(pairs);
}

static void from_text_and_file(void **state)
{
    (void)state;
    char *text = boxes_text();
    sc_objects *o = NULL;
    sc_error e;
    assert_int_equal(
        sc_objects_load_string("boxes.csg", text, strlen(text), NULL, &o, &e), SC_OK);
    check_objects(o, "boxes.csg");
    sc_objects_release(o);

    char path[] = "/tmp/spancast-objects-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    assert_int_equal(sc_objects_load(path, NULL, &o, &e), SC_OK);
    check_objects(o, path);
    sc_objects_release(o);
    unlink(path);
    free(text);
}

static void load_errors(void **state)
{
    (void)state;
    sc_objects *o = (sc_objects *)1;
    sc_error e;
    char buf[1024];
    assert_int_equal(sc_objects_load_string(NULL, "cube(1);", 8, NULL, &o, &e),
                     SC_ERR_ARGUMENT);
    assert_null(o);
    assert_int_equal(sc_objects_load_string("a.csg", "cube(1);", 8, NULL, NULL, &e),
                     SC_ERR_ARGUMENT);
    o = (sc_objects *)1;
    assert_int_equal(sc_objects_load_string("a.csg", NULL, 3, NULL, &o, &e),
                     SC_ERR_ARGUMENT);
    assert_null(o);
    /* No text is an empty model. */
    assert_int_equal(sc_objects_load_string("a.csg", NULL, 0, NULL, &o, &e), SC_OK);
    assert_int_equal(sc_objects_count(o), 0);
    sc_objects_release(o);
    /* A syntax error at its position in the named text; the text need not
     * end in a NUL. */
    const char bad[] = "cube(1);\ncube(2;XXXX";
    assert_int_equal(
        sc_objects_load_string("bad.csg", bad, strlen(bad) - 4, NULL, &o, &e),
        SC_ERR_SYNTAX);
    assert_null(o);
    assert_string_equal(sc_error_format(&e, buf, sizeof buf),
                        "bad.csg:2:7: error: expected ')' (to close '(' at line 2)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(from_text_and_file),
        cmocka_unit_test(load_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
