/* Allocation-failure injection in the parser, the builder and compile, as
 * STYLE.md asks: for N = 1, 2, ... the N-th allocation the library makes
 * while loading a model fails, until a load makes fewer than N allocations
 * and succeeds. Every failing load must return SC_ERR_NOMEM with the message
 * "out of memory" and no scene; the sanitizer build of scripts/test checks
 * that nothing leaks on any of those paths. Then the same for sc_render's
 * buffers.
 *
 * No source changes are needed: this program is linked with
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc (tests/CMakeLists.txt), so
 * every call the library's objects make goes through the wrappers below,
 * while calls from shared libraries (the C library, cmocka, OpenImageIO)
 * do not. The counter is armed only around the call under test.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spancast/spancast.h"
#include "test_util.h"

void *__real_malloc(size_t size);
void *__real_calloc(size_t count, size_t size);
void *__real_realloc(void *p, size_t size);
void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t count, size_t size);
void *__wrap_realloc(void *p, size_t size);

static long fail_at; /* 0: never fail; else the 1-based call that fails */
static long calls;   /* calls since the counter was armed */

static int should_fail(void)
{
    return fail_at && ++calls == fail_at;
}

void *__wrap_malloc(size_t size)
{
    return should_fail() ? NULL : __real_malloc(size);
}

void *__wrap_calloc(size_t count, size_t size)
{
    return should_fail() ? NULL : __real_calloc(count, size);
}

void *__wrap_realloc(void *p, size_t size)
{
    return should_fail() ? NULL : __real_realloc(p, size);
}

/* Reads a model file of the source tree into memory. */
static char *read_model(const char *relative, size_t *length)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", SPANCAST_SOURCE_DIR, relative);
    return test_read_file(path, length);
}

/* Fails every allocation of a load in turn; returns how many there were. */
static long fail_each_load(const char *name, const char *text, size_t length)
{
    for (long n = 1;; n++) {
        sc_scene *scene = NULL;
        sc_error e;
        calls = 0;
        fail_at = n;
        sc_status st = sc_scene_load_string(name, text, length, NULL, &scene, &e);
        fail_at = 0;
        if (calls < n) { /* nothing failed: the load must have worked */
            if (st != SC_OK)
                fail_msg("%s: load failed without an allocation failure: %s", name,
                         e.message);
            assert_non_null(scene);
            sc_scene_release(scene);
            return n - 1;
        }
        if (st != SC_ERR_NOMEM || scene != NULL || strcmp(e.message, "out of memory"))
            fail_msg("%s: allocation %ld failed, load returned %d (%s)", name, n, (int)st,
                     e.message);
    }
}

static void test_models(void **state)
{
    (void)state;
    const char *files[] = {"models/bracket.csg",    "tests/data/openscad_export.csg",
                           "models/pulley.csg",     "models/extruded_plate.csg",
                           "models/name_plate.csg", "tests/data/hand_written.csg"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        size_t length;
        char *text = read_model(files[k], &length);
        long count = fail_each_load(files[k], text, length);
        print_message("%s: %ld allocations, each failed in turn\n", files[k], count);
        assert_true(count > 5);
        free(text);
    }
}

/* A model that reaches every allocating path of the builder: warnings, a
 * polyhedron (points, faces, edges, planes, a face split as OpenSCAD splits
 * it), colours, modifiers, a render() (the preview's solid), nested
 * vectors and strings, and enough nodes to grow every array. */
static void test_every_path(void **state)
{
    (void)state;
    char text[65536];
    size_t n = 0;
    n +=
        (size_t)snprintf(text + n, sizeof text - n,
                         "// comment\n/* block */\n"
                         "color(\"#ff000080\") { sphere(r = 0); cube(-1); }\n"
                         "color([2, 0, 0]) { cube(1) { sphere(1); } }\n"
                         "%%sphere(1); *cube(1); #cylinder(h = 1, r1 = 1, r2 = 0);\n"
                         "group(s = \"\\u00e9\\x41\\n\", v = [[[1], []], [\"a\", true, "
                         "undef]]);\n"
                         "multmatrix([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, "
                         "0, 1]]) { cube(1); }\n"
                         "difference() { cube(2); intersection() { sphere(1.5); "
                         "cube(1.9, center = true); } }\n"
                         /* the preview's solid, with a render()'s own hole,
                          * and slabs in it and in a part */
                         "render() { difference() { cube(3); sphere(1); } }\n"
                         "square(1); %%multmatrix([[1, 0, 0, 0], [0, 1, 0, 9], [0, 0, "
                         "1, 0], [0, 0, 0, 1]]) { square(1); }\n"
                         "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, "
                         "1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);\n"
                         /* a non-planar face with points above one another
                          * (tess_mend.c) */
                         "polyhedron(points = [[7.5, 0, 0.6], [7.5, 0, 1.4], [7.5, 0, "
                         "2.2], [4.4, 3.2, 1.1], [1.4, 4.5, 0.1], [-2.2, 6.8, -1], "
                         "[-5.2, 3.7, -0.8], [-4.5, 0, 0.6], [-4.5, 0, 1.4], [-5.2, "
                         "-3.7, 1.1], [-2.2, -6.8, 0.1], [1.4, -4.5, -1], [4.4, -3.2, "
                         "-0.8], [0, 0, -4]], faces = [[12, 11, 10, 9, 8, 7, 6, 5, 4, 3, "
                         "2, 1, 0], [13, 0, 1], [13, 1, 2], [13, 2, 3], [13, 3, 4], [13, "
                         "4, 5], [13, 5, 6], [13, 6, 7], [13, 7, 8], [13, 8, 9], [13, 9, "
                         "10], [13, 10, 11], [13, 11, 12], [13, 12, 0]]);\n");
    for (int i = 0; i < 300; i++)
        n +=
            (size_t)snprintf(text + n, sizeof text - n,
                             "multmatrix([[1, 0, 0, %d], [0, 1, 0, 0], [0, 0, 1, 0], [0, "
                             "0, 0, 1]]) { sphere(r = 1, $fn = 12); }\n",
                             i);
    assert_true(n < sizeof text - 1);
    long count = fail_each_load("every.csg", text, n);
    print_message("every.csg: %ld allocations, each failed in turn\n", count);
    assert_true(count > 20);
}

/* The 2D engine and OpenSCAD's extrusions (src/twod/,
 * build_extrude_faithful.c): regions, booleans, offset, hull, Minkowski
 * sums, slices, merged and split tops, and a 2D object in a 3D model.
 * (Clipper's own C++ allocations are not wrapped; the C paths are.) */
static void test_extrusions(void **state)
{
    (void)state;
    const char *text =
        "linear_extrude(height = 5, twist = 90, scale = [0.5, 1], $fn = 8) {\n"
        "  difference() { offset(r = 1, $fn = 8) { square(4); } circle(r = 1, $fn = 6); "
        "}\n"
        "  hull() { square(1); multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, "
        "0, 0, 1]]) { circle(r = 1, $fn = 5); } }\n"
        "  minkowski() { square(1); circle(r = 1, $fn = 4); }\n"
        "  polygon(points = [[0, 0], [9, 0], [9, 9], [3, 3], [6, 3], [6, 6]], paths = "
        "[[0, 1, 2], [3, 4, 5]]);\n}\n"
        "linear_extrude(height = 2, scale = 0) { circle(r = 2, $fn = 7); }\n"
        "linear_extrude(height = 2, scale = [1, 0]) { circle(r = 2, $fn = 7); }\n"
        "square(2);\n";
    long count = fail_each_load("extrude.csg", text, strlen(text));
    print_message("extrude.csg: %ld allocations, each failed in turn\n", count);
    assert_true(count > 20);
}

/* sc_render of text: every allocation, in turn; returns their count. */
static long fail_each_render(const char *text, int preview)
{
    sc_scene *scene = NULL;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &scene, &e),
                     SC_OK);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = o.height = 8;
    o.threads = 1;
    o.preview = preview;
    o.want_color = o.want_depth = o.want_mask = o.want_normal = 1;
    long n = 1;
    for (;; n++) {
        sc_framebuffer *fb = NULL;
        calls = 0;
        fail_at = n;
        sc_status st = sc_render(scene, &o, &fb, &e);
        fail_at = 0;
        if (calls < n) {
            assert_int_equal(st, SC_OK);
            sc_framebuffer_release(fb);
            break;
        }
        if (st != SC_ERR_NOMEM || fb != NULL)
            fail_msg("render: allocation %ld failed, sc_render returned %d (%s)", n,
                     (int)st, e.message);
    }
    sc_scene_release(scene);
    return n - 1;
}

/* sc_render: every allocation of its buffers, in turn; and of the
 * preview's: its products, the boxes it frames, its parts and the solid
 * without a '#' operand of a union, and its render()s, each one product. */
static void test_render(void **state)
{
    (void)state;
    long n = fail_each_render("sphere(r = 1);", 0);
    print_message("render: %ld allocations, each failed in turn\n", n);
    assert_true(n >= 5); /* the framebuffer, four buffers, the scratch arena */
    long p =
        fail_each_render("intersection() { sphere(r = 1); cube(size = [1, 1, 1]); }\n"
                         "#cube(size = [1, 1, 1]); %sphere(r = 0.5);\n"
                         "color([1, 0, 0, 0.5]) { cube(size = [2, 1, 1]); }\n"
                         "render() { difference() { cube(2); sphere(1); } }\n"
                         "%render() { difference() { cube(2); sphere(1); } }\n",
                         1);
    print_message("preview: %ld allocations, each failed in turn\n", p);
    assert_true(p > n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_models),
        cmocka_unit_test(test_extrusions),
        cmocka_unit_test(test_every_path),
        cmocka_unit_test(test_render),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
