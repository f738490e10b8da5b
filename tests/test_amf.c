/* The AMF reader (formats/amf.c): OpenSCAD's element paths, indices per
 * object, values that carry over, and bad input as an error with the
 * import's position and the file's line, never a crash. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "formats/amf.h"

static const sc_location at = {"m.csg", 2, 5};

static sc_status read_amf(const char *text, amf_mesh *m, sc_error *e)
{
    return amf_read(text, strlen(text), "x.amf", &at, m, e);
}

#define VERTEX(x, y, z)                                                                  \
    "<vertex><coordinates><x>" #x "</x><y>" #y "</y><z>" #z "</z></coordinates></"       \
    "vertex>"
#define TRIANGLE(a, b, c)                                                                \
    "<triangle><v1>" #a "</v1><v2>" #b "</v2><v3>" #c "</v3></triangle>"

static void test_objects(void **state)
{
    (void)state;
    amf_mesh m;
    sc_error e;
    /* two objects: the second's indices count from its own first vertex */
    const char *text =
        "<?xml version='1.0'?><amf unit='inch'><metadata>x</metadata>"
        "<object id='0'><mesh><vertices>" VERTEX(0, 0, 0) VERTEX(1, 0, 0)
            VERTEX(0, 1, 0) "</vertices><volume>" TRIANGLE(
                0, 1, 2) "</volume></mesh></object>"
                         "<object id='1'><mesh><vertices>" VERTEX(5, 5, 5) VERTEX(6, 5, 5)
                             VERTEX(5, 6, 5.5) "</vertices><volume>" TRIANGLE(
                                 2, 1, 0) "</volume></mesh></object></amf>";
    assert_int_equal(read_amf(text, &m, &e), SC_OK);
    assert_int_equal(m.object_count, 2);
    assert_int_equal(m.point_count, 6);
    assert_int_equal(m.face_count, 2);
    assert_int_equal(m.indices[3], 5);
    assert_int_equal(m.indices[5], 3);
    assert_true(m.points[5].z == 5.5); /* units are not read, as OpenSCAD */
    assert_int_equal(m.face_start[2], 6);
    /* each object's points and triangles, which OpenSCAD unites as solids */
    assert_int_equal(m.object_points[0], 0);
    assert_int_equal(m.object_points[1], 3);
    assert_int_equal(m.object_points[2], 6);
    assert_int_equal(m.object_faces[0], 0);
    assert_int_equal(m.object_faces[1], 1);
    assert_int_equal(m.object_faces[2], 2);
    amf_mesh_free(&m);
    /* an object's volumes and meshes are one solid, its indices counting
     * across its meshes; an object without triangles is still an object */
    static const char volumes[] =
        "<amf><object><mesh><vertices>" VERTEX(0, 0, 0) VERTEX(1, 0, 0) VERTEX(0, 1, 0)
        /* two volumes of the first mesh */
        "</vertices><volume>" TRIANGLE(0, 1, 2) "</volume><volume>" TRIANGLE(2, 1, 0)
        /* a second mesh, its vertex numbered after the first mesh's */
        "</volume></mesh><mesh><vertices>" VERTEX(0, 0, 1) "</vertices><volume>" TRIANGLE(
            3, 1, 0) "</volume></mesh></object><object/></amf>";
    assert_int_equal(read_amf(volumes, &m, &e), SC_OK);
    assert_int_equal(m.object_count, 2);
    assert_int_equal(m.face_count, 3);
    assert_int_equal(m.indices[6], 3);
    assert_int_equal(m.object_faces[1], 3);
    assert_int_equal(m.object_faces[2], 3);
    assert_int_equal(m.object_points[1], 4);
    assert_int_equal(m.object_points[2], 4);
    amf_mesh_free(&m);
    /* a coordinate left out keeps the previous vertex's */
    assert_int_equal(
        read_amf("<amf><object><mesh><vertices>" VERTEX(
                     1, 2, 3) "<vertex><coordinates><x>4</x></coordinates></vertex>"
                              "</vertices></mesh></object></amf>",
                 &m, &e),
        SC_OK);
    assert_true(m.points[1].x == 4 && m.points[1].y == 2 && m.points[1].z == 3);
    amf_mesh_free(&m);
    /* elements off OpenSCAD's paths are not read */
    assert_int_equal(
        read_amf("<amf><mesh><vertices>" VERTEX(1, 2, 3) "</vertices></mesh></amf>", &m,
                 &e),
        SC_OK);
    assert_int_equal(m.point_count, 0);
    amf_mesh_free(&m);
}

static void test_bad_input(void **state)
{
    (void)state;
    amf_mesh m;
    sc_error e;
    assert_int_equal(
        read_amf(
            "<amf><object><mesh><vertices>\n" VERTEX(
                1, 2,
                3) "</vertices><volume>\n" TRIANGLE(0, 0,
                                                    3) "</volume></mesh></object></amf>",
            &m, &e),
        SC_ERR_SEMANTIC);
    assert_string_equal(
        e.message, "import: x.amf:3: vertex index 3 is not one of the object's vertices");
    assert_int_equal(e.line, 2);
    assert_int_equal(e.column, 5);
    amf_mesh_free(&m);
    assert_int_equal(read_amf("<amf><object><mesh><vertices>\n<vertex><coordinates>"
                              "<x> 1</x></coordinates></vertex></vertices></mesh>"
                              "</object></amf>",
                              &m, &e),
                     SC_ERR_SYNTAX);
    assert_string_equal(e.message, "import: x.amf:2: ' 1' is not a number");
    amf_mesh_free(&m);
    assert_int_equal(read_amf("<svg/>", &m, &e), SC_ERR_SYNTAX);
    assert_string_equal(e.message,
                        "import: x.amf:1: the root element is <svg>, not <amf>");
    amf_mesh_free(&m);
    /* every prefix of a file */
    const char *full = "<amf><object><mesh><vertices>" VERTEX(0, 0, 0) VERTEX(1, 0, 0)
        VERTEX(0, 1, 0) "</vertices><volume>" TRIANGLE(
            0, 1, 2) "</volume></mesh></object></amf>";
    for (size_t n = 0; n < strlen(full); n++) {
        sc_status st = amf_read(full, n, "x.amf", &at, &m, &e);
        assert_true(st == SC_OK || st == SC_ERR_SYNTAX);
        amf_mesh_free(&m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_objects),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
