/* Tests of the mesh builder (src/build/build_mesh.c): non-convex polyhedra
 * become mesh leaves with the right solid, convex ones keep the planes,
 * either winding is taken, open and inconsistently wound meshes are errors
 * naming an edge, import reads ASCII STL, binary STL and OFF files
 * relative to the model file, with exact messages for what it cannot
 * read, and linear_extrude (build_extrude.c) builds prisms. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "build/build.h"
#include "build/scene.h"
#include "test_util.h"

static sc_scene *load_with(const char *name, const char *text, int faithful)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    sc_status st = sc_scene_load_string(name, text, strlen(text), &o, &s, &e);
    if (st != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    return s;
}

static sc_scene *load(const char *name, const char *text)
{
    return load_with(name, text, 0);
}

/* The prism path of linear_extrude is faithful mode's (exact mode has its
 * own, tested in test_prim_extrusion.c). */
static sc_scene *load_faithful(const char *name, const char *text)
{
    return load_with(name, text, 1);
}

static void check_error_with(const char *name, const char *text, sc_status status,
                             const char *expected, int faithful)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    assert_int_equal(sc_scene_load_string(name, text, strlen(text), &o, &s, &e), status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

static void check_error(const char *name, const char *text, sc_status status,
                        const char *expected)
{
    check_error_with(name, text, status, expected, 0);
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static prim_kind only_kind(const sc_scene *s)
{
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 1);
    return t->leaves[0].prim.kind;
}

/* A 2-cube with a pyramid notch from its top face down to (1, 1, 1). */
#define NOTCH_POINTS                                                                     \
    "[[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], [2, 0, 2], [2, 2, 2], "     \
    "[0, 2, 2], [1, 1, 1]]"
#define NOTCH_FACES                                                                      \
    "[[0, 1, 2, 3], [4, 5, 1, 0], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [4, 8, 5], " \
    "[5, 8, 6], [6, 8, 7], [7, 8, 4]]"
#define NOTCH_FACES_REVERSED                                                             \
    "[[3, 2, 1, 0], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7], [5, 8, 4], " \
    "[6, 8, 5], [7, 8, 6], [4, 8, 7]]"

static void check_notch(const sc_scene *s)
{
    assert_int_equal(only_kind(s), PRIM_MESH);
    assert_true(inside(s, 1, 1, 0.5));
    assert_true(inside(s, 0.1, 1, 1.5));
    assert_true(inside(s, 1.9, 1.9, 1.9));
    assert_false(inside(s, 1, 1, 1.5)); /* in the notch */
    assert_false(inside(s, 1, 1.5, 1.9));
    assert_false(inside(s, 3, 1, 1));
}

static void test_nonconvex_polyhedron(void **state)
{
    (void)state;
    sc_scene *s =
        load("m.csg", "polyhedron(points = " NOTCH_POINTS ", faces = " NOTCH_FACES ");");
    check_notch(s);
    sc_scene_release(s);
    /* the other winding: the signed volume turns it round */
    s = load("m.csg",
             "polyhedron(points = " NOTCH_POINTS ", faces = " NOTCH_FACES_REVERSED ");");
    check_notch(s);
    sc_scene_release(s);
    /* two disjoint tetrahedra: one closed mesh, not convex */
    s = load(
        "m.csg",
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [5, 0, 0], "
        "[6, 0, 0], [5, 1, 0], [5, 0, 1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], "
        "[1, 3, 2], [4, 5, 6], [4, 7, 5], [4, 6, 7], [5, 7, 6]]);");
    assert_int_equal(only_kind(s), PRIM_MESH);
    assert_true(inside(s, 0.2, 0.2, 0.2));
    assert_true(inside(s, 5.2, 0.2, 0.2));
    assert_false(inside(s, 3, 0.2, 0.2));
    sc_scene_release(s);
    /* a convex one keeps the plane path */
    s = load("m.csg", "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
                      "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);");
    assert_int_equal(only_kind(s), PRIM_CONVEX);
    sc_scene_release(s);
}

static void test_mesh_errors(void **state)
{
    (void)state;
    check_error(
        "m.csg",
        "polyhedron(points = " NOTCH_POINTS ", faces = [[0, 1, 2, 3], [4, 5, 1, 0], "
        "[5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [4, 8, 5], [5, 8, 6], [6, 8, "
        "7], [7, 4, 8]]);",
        SC_ERR_SEMANTIC,
        "m.csg:1:1: error: polyhedron is not consistently oriented (edge 4-8 runs "
        "the same way in two faces)");
    /* flat and not convex: no volume, a warning, the empty solid */
    sc_scene *s =
        load("m.csg", "polyhedron(points = [[0, 0, 0], [2, 0, 0], [1, 1, 0], [2, 2, 0], "
                      "[0, 2, 0]], faces = [[0, 1, 2, 3, 4], [4, 3, 2, 1, 0]]);");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "polyhedron without volume is empty");
    sc_scene_release(s);
}

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

/* The notch as triangles, corners as floats. */
static const int notch_tris[][3] = {{0, 1, 2}, {0, 2, 3}, {4, 5, 1}, {4, 1, 0}, {5, 6, 2},
                                    {5, 2, 1}, {6, 7, 3}, {6, 3, 2}, {7, 4, 0}, {7, 0, 3},
                                    {4, 8, 5}, {5, 8, 6}, {6, 8, 7}, {7, 8, 4}};
static const float notch_pts[][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0},
                                     {0, 2, 0}, {0, 0, 2}, {2, 0, 2},
                                     {2, 2, 2}, {0, 2, 2}, {1, 1, 1}};
enum { NOTCH_TRIS = 14 };

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

static void write_notch_files(void)
{
    /* ASCII STL */
    char text[8192], *p = text;
    p += sprintf(p, "solid notch\n");
    for (int t = 0; t < NOTCH_TRIS; t++) {
        p += sprintf(p, "  facet normal 0 0 0\n    outer loop\n");
        for (int k = 0; k < 3; k++) {
            const float *v = notch_pts[notch_tris[t][k]];
            p += sprintf(p, "      vertex %g %g %g\n", v[0], v[1], v[2]);
        }
        p += sprintf(p, "    endloop\n  endfacet\n");
    }
    p += sprintf(p, "endsolid notch\n");
    write_file("notch.stl", text, (size_t)(p - text));
    /* binary STL: the header may start with "solid", as some writers do */
    unsigned char bin[84 + 50 * NOTCH_TRIS];
    memset(bin, 0, sizeof bin);
    memcpy(bin, "solid but binary", 16);
    put_u32(bin + 80, NOTCH_TRIS);
    for (int t = 0; t < NOTCH_TRIS; t++)
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++) {
                uint32_t u;
                memcpy(&u, &notch_pts[notch_tris[t][k]][c], 4);
                put_u32(bin + 84 + 50 * t + 12 + 12 * k + 4 * c, u);
            }
    write_file("sub/notch_bin.stl", bin, sizeof bin);
    /* OFF, with a comment and a colour after a face */
    p = text;
    p += sprintf(p, "OFF\n# the notch\n9 9 0\n");
    for (int i = 0; i < 9; i++)
        p += sprintf(p, "%g %g %g\n", notch_pts[i][0], notch_pts[i][1], notch_pts[i][2]);
    p += sprintf(p, "4 0 1 2 3 255 0 0\n4 4 5 1 0\n4 5 6 2 1\n4 6 7 3 2\n4 7 4 0 3\n"
                    "3 4 8 5\n3 5 8 6\n3 6 8 7\n3 7 8 4\n");
    write_file("notch.off", text, (size_t)(p - text));
    /* open: the notch without its last triangle */
    p = text;
    p += sprintf(p, "solid open\n");
    for (int t = 0; t + 1 < NOTCH_TRIS; t++) {
        p += sprintf(p, "facet normal 0 0 0\nouter loop\n");
        for (int k = 0; k < 3; k++) {
            const float *v = notch_pts[notch_tris[t][k]];
            p += sprintf(p, "vertex %g %g %g\n", v[0], v[1], v[2]);
        }
        p += sprintf(p, "endloop\nendfacet\n");
    }
    p += sprintf(p, "endsolid open\n");
    write_file("open.stl", text, (size_t)(p - text));
    write_file("bad.stl", "solid x\nvertex 1 2\n", 19);
}

static void test_import(void **state)
{
    (void)state;
    char dir[512], model[600], sub[600];
    snprintf(dir, sizeof dir, "%s", work());
    snprintf(sub, sizeof sub, "%s/sub", dir);
    mkdir(sub, 0777);
    write_notch_files();
    snprintf(model, sizeof model, "%s/m.csg", dir);
    static const char *files[] = {"notch.stl", "sub/notch_bin.stl", "notch.off"};
    for (int i = 0; i < 3; i++) {
        char text[256];
        snprintf(text, sizeof text,
                 "import(file = \"%s\", layer = \"\", origin = [0, 0], scale = 1, "
                 "convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 0);",
                 files[i]);
        sc_scene *s = load(model, text);
        check_notch(s);
        sc_scene_release(s);
    }
    /* an absolute path is taken as it is */
    char text[1400];
    snprintf(text, sizeof text,
             "multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], "
             "[0, 0, 0, 1]]) { import(\"%s/notch.off\"); }",
             dir);
    sc_scene *s = load("elsewhere/m.csg", text);
    assert_true(inside(s, 11, 1, 0.5));
    assert_false(inside(s, 11, 1, 1.5));
    sc_scene_release(s);

    char expected[2400];
    snprintf(expected, sizeof expected,
             "%s:1:8: error: imported mesh is not closed (edge (0, 0, 2)-(0, 2, 2) is "
             "used by 1 face)",
             model);
    check_error(model, "import(\"open.stl\");", SC_ERR_SEMANTIC, expected);
    snprintf(expected, sizeof expected,
             "%s:1:8: error: import: '%s/bad.stl' is not a valid STL file (a 'vertex' "
             "without three numbers)",
             model, dir);
    check_error(model, "import(\"bad.stl\");", SC_ERR_SEMANTIC, expected);
    /* a file that cannot be opened: OpenSCAD's warning, an empty part,
     * the rest rendered */
    snprintf(expected, sizeof expected,
             "%s:2:1: Can't open import file '%s/none.off': No such file or "
             "directory (the import is empty)",
             model, dir);
    const char *const missing[] = {expected};
    sc_scene *rest =
        test_check_warnings(model, "cube(1);\nimport(\"none.off\");", 0, missing, 1);
    assert_true(inside(rest, 0.5, 0.5, 0.5));
    sc_scene_release(rest);
    check_error("m.csg", "import(\"a.dxf\");", SC_ERR_UNSUPPORTED,
                "m.csg:1:8: error: import of 'a.dxf' is not supported yet (only .stl and "
                ".off files)");
    check_error("m.csg", "import();", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'file' of 'import'");
    check_error(
        "m.csg", "import(file = 3);", SC_ERR_SEMANTIC,
        "m.csg:1:15: error: wrong type for argument 'file' of 'import' (expected a "
        "file name)");
    /* under '%' it is checked but not read */
    s = load("m.csg", "%import(\"none.stl\"); cube();");
    assert_int_equal(only_kind(s), PRIM_BOX);
    sc_scene_release(s);
}

/* linear_extrude in faithful mode of square, circle and polygon children:
 * holes by nesting, circles as OpenSCAD's polygons, unions of children, 2D
 * transforms, centring; a scale builds OpenSCAD's slices, a 2D difference
 * goes through the 2D engine, a 3D child is an error. */
static void test_linear_extrude(void **state)
{
    (void)state;
    sc_scene *s = load_faithful(
        "m.csg",
        "linear_extrude(height = 10, center = false, convexity = 1, scale = [1, 1], $fn "
        "= 0, $fa = 12, $fs = 2) {\n polygon(points = [[0, 0], [20, 0], [20, 20], [0, "
        "20], [5, 5], [15, 5], [15, 15], [5, 15]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]], "
        "convexity = 1);\n}");
    assert_int_equal(only_kind(s), PRIM_MESH);
    assert_true(inside(s, 2, 2, 5));
    assert_true(inside(s, 18, 10, 9.9));
    assert_false(inside(s, 10, 10, 5)); /* the hole */
    assert_false(inside(s, 2, 2, 10.1));
    assert_false(inside(s, 2, 2, -0.1));
    sc_scene_release(s);

    s = load_faithful(
        "m.csg",
        "linear_extrude(height = 5, center = true) {\n"
        "  circle($fn = 6, $fa = 12, $fs = 2, r = 8);\n"
        "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    square(size = [10, 4], center = true);\n  }\n"
        "  polygon(points = [[0, 10], [4, 20], [0, 14], [-4, 20]]);\n"
        "  %square(size = 100);\n}");
    assert_true(inside(s, 0, 0, 2.4));
    assert_false(inside(s, 0, 0, 2.6));
    assert_true(inside(s, 7.9, 0, 0));
    assert_false(inside(s, 0, 7.5, 0)); /* outside the hexagon, inside the circle */
    assert_true(inside(s, 9.5, 0, 0));  /* the square alone */
    assert_true(inside(s, 5, 1.9, 0));  /* both */
    assert_true(inside(s, 0, 12, 0));   /* the arrow */
    assert_false(inside(s, 0, 16, 0));  /* its notch */
    assert_false(inside(s, 50, 50, 0)); /* '%' is not part of it */
    sc_scene_release(s);

    /* a mirrored child keeps its solid */
    s = load_faithful("m.csg",
                      "linear_extrude(height = 1) { multmatrix([[-1, 0, 0, 0], [0, 1, 0, "
                      "0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = [2, 1]); } }");
    assert_true(inside(s, -1, 0.5, 0.5));
    assert_false(inside(s, 1, 0.5, 0.5));
    sc_scene_release(s);

    /* a scale goes to OpenSCAD's slices (build_extrude_faithful.c) */
    s = load("m.csg", "linear_extrude(height = 1, scale = 2) { square(); }");
    assert_true(inside(s, 1.5, 1.5, 0.9));
    assert_false(inside(s, 1.5, 1.5, 0.1));
    sc_scene_release(s);
    s = load_faithful(
        "m.csg",
        "linear_extrude(height = 1) {\n  difference() { square(2); square(1); }\n}");
    assert_true(inside(s, 1.5, 1.5, 0.5));
    assert_false(inside(s, 0.5, 0.5, 0.5));
    sc_scene_release(s);
    /* a 3D child: ignored with OpenSCAD's warning, the rest extruded */
    static const char *const ignored[] = {
        "m.csg:1:40: Ignoring 3D child object for 2D operation"};
    s = test_check_warnings("m.csg", "linear_extrude(height = 1) { square(); sphere(); }",
                            1, ignored, 1);
    assert_true(inside(s, 0.5, 0.5, 0.5));
    assert_false(inside(s, -0.5, -0.5, 0.5));
    sc_scene_release(s);
    s = load_faithful("m.csg", "linear_extrude(height = 0) { square(); }");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "linear_extrude without height or area is empty");
    sc_scene_release(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nonconvex_polyhedron),
        cmocka_unit_test(test_mesh_errors),
        cmocka_unit_test(test_import),
        cmocka_unit_test(test_linear_extrude),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
