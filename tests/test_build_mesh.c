/* Tests of the mesh builder (src/build/build_mesh.c): non-convex polyhedra
 * become mesh leaves with the right solid, convex ones keep the planes,
 * either winding is taken, open and inconsistently wound meshes are
 * warnings naming an edge (left out in faithful mode, drawn by parity in
 * exact mode, errors with strict), equal points are merged as OpenSCAD
 * merges them, quads are split along OpenSCAD's diagonal, import reads ASCII STL, binary
 * STL and OFF files relative to the model file, with exact messages for what it cannot
 * read, a build reads, merges and charges an import once however many builders take
 * it, lends its faces and lets its file go after the last of them, and linear_extrude
 * (build_extrude.c) builds prisms. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "build/build.h"
#include "build/tess_sweep.h"
#include "build/build_hull.h"
#include "build/build_mesh.h"
#include "build/scene.h"
#include "formats/file.h"
#include "syntax/parse.h"
#include "test_util.h"

/* Every file_read of the library comes through here (the test links with
 * -Wl,--wrap=file_read): reads counts the reads of files whose name ends
 * in counted. */
char *__real_file_read(const char *path, size_t limit, size_t *size, const char **why);
char *__wrap_file_read(const char *path, size_t limit, size_t *size, const char **why);
static const char *counted = "";
static int reads;

char *__wrap_file_read(const char *path, size_t limit, size_t *size, const char **why)
{
    size_t n = strlen(path), k = strlen(counted);
    if (k && n >= k && strcmp(path + n - k, counted) == 0)
        reads++;
    return __real_file_read(path, limit, size, why);
}

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

/* Loading text fails with status and the message expected; faithful and
 * strict as sc_load_options has them. */
static void check_error_with(const char *name, const char *text, sc_status status,
                             const char *expected, int faithful, int strict)
{
    sc_scene *s = (sc_scene *)1;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    o.strict = strict;
    assert_int_equal(sc_scene_load_string(name, text, strlen(text), &o, &s, &e), status);
    assert_null(s);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

/* With --strict (sc_load_options.strict): the error a bad mesh gives. */
static void check_error_strict(const char *name, const char *text, sc_status status,
                               const char *expected, int faithful)
{
    check_error_with(name, text, status, expected, faithful, 1);
}

/* Loads text (faithful or not) and checks its one warning, message and
 * position, and how many leaves were built. */
static sc_scene *load_one_warning(const char *name, const char *text, int faithful,
                                  int line, int column, const char *expected,
                                  uint32_t leaves)
{
    sc_scene *s = load_with(name, text, faithful);
    assert_int_equal(sc_scene_warning_count(s), 1);
    const sc_error *w = sc_scene_warning(s, 0);
    assert_int_equal(w->status, SC_OK);
    assert_int_equal(w->line, line);
    assert_int_equal(w->column, column);
    assert_string_equal(w->message, expected);
    assert_int_equal(scene_tree(s)->leaf_count, leaves);
    return s;
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

/* A prism of n sides (n < 1000) about the z axis, radius 1, z from 0 to 1,
 * as a polyhedron: n + 2 faces (static text, rewritten each call). */
static const char *prism_text(int n)
{
    static char text[120000];
    size_t at = (size_t)snprintf(text, sizeof text, "polyhedron(points = [");
    for (int z = 0; z < 2; z++)
        for (int k = 0; k < n; k++) {
            double a = 2 * 3.14159265358979323846 * k / n;
            at += (size_t)snprintf(text + at, sizeof text - at, "%s[%.17g, %.17g, %d]",
                                   z || k ? ", " : "", cos(a), sin(a), z);
        }
    at += (size_t)snprintf(text + at, sizeof text - at, "], faces = [[");
    for (int k = 0; k < n; k++) /* the bottom, seen from below */
        at += (size_t)snprintf(text + at, sizeof text - at, "%s%d", k ? ", " : "", k);
    at += (size_t)snprintf(text + at, sizeof text - at, "], [");
    for (int k = n; k-- > 0;)
        at += (size_t)snprintf(text + at, sizeof text - at, "%d%s", n + k, k ? ", " : "");
    for (int k = 0; k < n; k++)
        at += (size_t)snprintf(text + at, sizeof text - at, "], [%d, %d, %d, %d", k,
                               n + k, n + (k + 1) % n, (k + 1) % n);
    snprintf(text + at, sizeof text - at, "]]);");
    return text;
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
    /* up to PRIM_CONVEX_MAX_PLANES planes: a prism of n sides has n + 2;
     * past it a convex polyhedron is a mesh, which a ray descends rather
     * than testing every plane, with the same inside */
    static const int sides[] = {254, 255};
    for (int k = 0; k < 2; k++) {
        s = load("m.csg", prism_text(sides[k]));
        assert_int_equal(only_kind(s), k ? PRIM_MESH : PRIM_CONVEX);
        assert_true(inside(s, 0, 0, 0.5));
        assert_true(inside(s, 0.99, 0, 0.5));
        assert_false(inside(s, 1.01, 0, 0.5));
        assert_false(inside(s, 0, 0, 1.01));
        sc_scene_release(s);
    }
}

/* A notch whose last face is wound the wrong way, and a cube without its
 * top, next to a closed cube: errors with --strict; else warnings at the
 * node, the mesh left out in faithful mode (as OpenSCAD leaves it out) and
 * drawn by the parity rule in exact mode, and the rest rendered. */
#define TURNED_NOTCH                                                                     \
    "polyhedron(points = " NOTCH_POINTS ", faces = [[0, 1, 2, 3], [4, 5, 1, 0], "        \
    "[5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3], [4, 8, 5], [5, 8, 6], [6, 8, "            \
    "7], [7, 4, 8]]);"
#define OPEN_BOX                                                                         \
    "polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 2], "       \
    "[2, 0, 2], [2, 2, 2], [0, 2, 2]], faces = [[0, 1, 2, 3], [4, 5, 1, 0], "            \
    "[5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);"
#define BESIDE                                                                           \
    " multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(1); }"

static void test_mesh_errors(void **state)
{
    (void)state;
    const char *turned = "m.csg:1:1: error: polyhedron is not consistently oriented "
                         "(edge 4-8 runs the same way in two faces)";
    check_error_strict("m.csg", TURNED_NOTCH, SC_ERR_SEMANTIC, turned, 0);
    check_error_strict("m.csg", TURNED_NOTCH, SC_ERR_SEMANTIC, turned, 1);
    const char *open = "m.csg:1:1: error: polyhedron is not closed (edge 4-5 is used by "
                       "1 face)";
    check_error_strict("m.csg", "group() {" OPEN_BOX BESIDE "}", SC_ERR_SEMANTIC,
                       "m.csg:1:10: error: polyhedron is not closed (edge 4-5 is used by "
                       "1 face)",
                       0);
    check_error_strict("m.csg", OPEN_BOX, SC_ERR_SEMANTIC, open, 1);

    /* exact: the parity rule, the whole notch */
    sc_scene *s = load_one_warning(
        "m.csg", TURNED_NOTCH, 0, 1, 1,
        "polyhedron is not consistently oriented (edge 4-8 runs the same way in two "
        "faces); rendered by the parity rule (--strict makes it an error)",
        1);
    check_notch(s);
    sc_scene_release(s);
    /* faithful: left out, with OpenSCAD's message; the cube beside stays */
    s = load_one_warning(
        "m.csg", "group() {" TURNED_NOTCH BESIDE "}", 1, 1, 10,
        "polyhedron is not consistently oriented (edge 4-8 runs the same way in two "
        "faces); left out, as OpenSCAD leaves it out (\"The given mesh is not closed! "
        "Unable to convert to CGAL_Nef_Polyhedron.\")",
        1);
    assert_false(inside(s, 1, 1, 0.5));
    assert_true(inside(s, 5.5, 0.5, 0.5));
    sc_scene_release(s);
    /* an open box: exact, the walls seen from the side; faithful, left out */
    s = load_one_warning(
        "m.csg", "group() {" OPEN_BOX BESIDE "}", 0, 1, 10,
        "polyhedron is not closed (edge 4-5 is used by 1 face); rendered "
        "by the parity rule (--strict makes it an error)",
        2);
    assert_true(inside(s, 5.5, 0.5, 0.5));
    sc_scene_release(s);
    s = load_one_warning(
        "m.csg", "group() {" OPEN_BOX BESIDE "}", 1, 1, 10,
        "polyhedron is not closed (edge 4-5 is used by 1 face); left out, "
        "as OpenSCAD leaves it out (\"The given mesh is not closed! "
        "Unable to convert to CGAL_Nef_Polyhedron.\")",
        1);
    sc_scene_release(s);
    /* flat and not convex: no volume, a warning, the empty solid */
    s = load("m.csg", "polyhedron(points = [[0, 0, 0], [2, 0, 0], [1, 1, 0], [2, 2, 0], "
                      "[0, 2, 0]], faces = [[0, 1, 2, 3, 4], [4, 3, 2, 1, 0]]);");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "polyhedron without volume is empty");
    sc_scene_release(s);
    /* flat in a tilted plane, whose volume is rounding noise: the same */
    s = load("m.csg", "polyhedron(points = [[0.1, 0.2, 0.7], [0.3, 0.3, 0.4], "
                      "[0.6, 0.1, 0.3], [0.2, 0.6, 0.2]], faces = [[0, 1, 2, 3], "
                      "[3, 2, 1, 0]]);");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "polyhedron without volume is empty");
    sc_scene_release(s);
    /* two small cubes 9e6 apart, in one polyhedron: each shell's volume
     * about a point of its own keeps its digits (about the centre of the
     * bounds it was noise, and the solid "without volume") */
    s = load(
        "m.csg",
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], "
        "[1, 0, 1], [1, 1, 1], [0, 1, 1], [9e6, 9e6, 9e6], [9000001, 9e6, 9e6], "
        "[9000001, 9000001, 9e6], [9e6, 9000001, 9e6], [9e6, 9e6, 9000001], "
        "[9000001, 9e6, 9000001], [9000001, 9000001, 9000001], [9e6, 9000001, "
        "9000001]], faces = [[0, 1, 2, 3], [4, 7, 6, 5], [0, 4, 5, 1], [1, 5, 6, 2], "
        "[2, 6, 7, 3], [3, 7, 4, 0], [8, 9, 10, 11], [12, 15, 14, 13], [8, 12, 13, 9], "
        "[9, 13, 14, 10], [10, 14, 15, 11], [11, 15, 12, 8]]);");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(inside(s, 0.5, 0.5, 0.5));
    assert_true(inside(s, 9000000.5, 9000000.5, 9000000.5));
    sc_scene_release(s);
    /* a dented prism of size 2 at 1e5: its dent (0.6 deep) is within 1e-5
     * of the largest coordinate, so the plane test took it as convex and
     * filled the dent; its tolerance is bounded by the solid's own size */
    s = load(
        "m.csg",
        "polyhedron(points = [[1e5, 1e5, 0], [100002, 1e5, 0], [100002, 100001, 0], "
        "[100000.5, 100000.5, 0], [100001, 100002, 0], [1e5, 100002, 0], [1e5, 1e5, "
        "1], [100002, 1e5, 1], [100002, 100001, 1], [100000.5, 100000.5, 1], "
        "[100001, 100002, 1], [1e5, 100002, 1]], faces = [[5, 4, 3, 2, 1, 0], [6, 7, "
        "8, 9, 10, 11], [0, 1, 7, 6], [1, 2, 8, 7], [2, 3, 9, 8], [3, 4, 10, 9], [4, "
        "5, 11, 10], [5, 0, 6, 11]]);");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(inside(s, 100000.25, 100001, 0.5));
    assert_true(inside(s, 100001.5, 100000.25, 0.5));
    assert_false(inside(s, 100001.5, 100001.5, 0.5)); /* in the dent */
    assert_false(inside(s, 100001, 100001, 0.5));
    sc_scene_release(s);
    /* the same in 2D (a DXF drawing's squares), drawn as a flat slab */
    s = load("m.csg", "polygon(points = [[0, 0], [5, 0], [5, 5], [0, 5], [9e6, 9e6], "
                      "[9000010, 9e6], [9000010, 9000010], [9e6, 9000010]], paths = "
                      "[[0, 1, 2, 3], [4, 5, 6, 7]]);");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(inside(s, 2.5, 2.5, 0));
    assert_true(inside(s, 9000005, 9000005, 0));
    sc_scene_release(s);
    /* long and thin (2e6 by 2): a solid, as OpenSCAD keeps it */
    s = load("m.csg",
             "polyhedron(points = [[0, 0, 0], [2e6, 0, 0], [0, 2, 0], [0, 0, 2]], "
             "faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]);");
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(inside(s, 1e6, 0.2, 0.2));
    assert_false(inside(s, 1e6, 0.6, 0.6));
    sc_scene_release(s);
}

/* BOSL's patches: every face lists its own copies of its corners. The
 * notch so written is closed once equal points are merged; copies off by
 * less than OpenSCAD's grid (2^-20) merge too, copies 1e-5 apart do not. */
static void append_copies(char *text, size_t size, const char *const *corners,
                          const int faces[][4], int face_count, double jitter)
{
    size_t at = strlen(text);
    at += (size_t)snprintf(text + at, size - at, "polyhedron(points = [");
    for (int f = 0; f < face_count; f++)
        for (int k = 0; k < 4 && faces[f][k] >= 0; k++) {
            double x, y, z;
            sscanf(corners[faces[f][k]], "%lf %lf %lf", &x, &y, &z);
            double j = jitter * (double)((f * 7 + k * 3) % 5 - 2) / 2;
            at += (size_t)snprintf(text + at, size - at, "%s[%.17g, %.17g, %.17g]",
                                   f || k ? ", " : "", x + j, y - j, z + j);
        }
    at += (size_t)snprintf(text + at, size - at, "], faces = [");
    int n = 0;
    for (int f = 0; f < face_count; f++) {
        at += (size_t)snprintf(text + at, size - at, "%s[", f ? ", " : "");
        for (int k = 0; k < 4 && faces[f][k] >= 0; k++)
            at += (size_t)snprintf(text + at, size - at, "%s%d", k ? ", " : "", n++);
        at += (size_t)snprintf(text + at, size - at, "]");
    }
    snprintf(text + at, size - at, "]);");
}

/* OpenSCAD 2021.01 leaves an index out of range out of its face with a
 * warning, truncates a fraction and drops a face of fewer than 3 points:
 * the faces left here are those of the closed tetrahedron. The indices out
 * of range are warned of, each with its value (the last face's, read
 * before the points it drops, kept its value), and then, once, the faces
 * of fewer than 3 points, as OpenSCAD's tessellation warns of them
 * (--strict: test_build.c). */
static void test_bad_indices(void **state)
{
    (void)state;
    const char *const out_of_range[] = {
        "m.csg:1:129: Point index 4 is out of bounds (from faces[4][2])",
        "m.csg:1:134: Point index -1 is out of bounds (from faces[5][0])",
        "m.csg:1:148: Point index 9 is out of bounds (from faces[7][0])",
        "m.csg:1:122: PolySet has degenerate polygons (faces[4] and 3 more have fewer "
        "than 3 points; left out, as OpenSCAD leaves them out)"};
    const char *text =
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2.5], [0, 1, 4], [-1, 2], [3], [9, 0, "
        "1]]);";
    for (int faithful = 0; faithful <= 1; faithful++) {
        sc_scene *s = test_check_warnings("m.csg", text, faithful, out_of_range, 4);
        assert_true(inside(s, 0.1, 0.1, 0.1));
        assert_false(inside(s, 0.5, 0.5, 0.5));
        sc_scene_release(s);
    }
}

static void test_merged_copies(void **state)
{
    (void)state;
    static const char *const corners[] = {"0 0 0", "2 0 0", "2 2 0", "0 2 0", "0 0 2",
                                          "2 0 2", "2 2 2", "0 2 2", "1 1 1"};
    static const int faces[][4] = {{0, 1, 2, 3},  {4, 5, 1, 0},  {5, 6, 2, 1},
                                   {6, 7, 3, 2},  {7, 4, 0, 3},  {4, 8, 5, -1},
                                   {5, 8, 6, -1}, {6, 8, 7, -1}, {7, 8, 4, -1}};
    char text[8192] = "";
    append_copies(text, sizeof text, corners, faces, 9, 0);
    sc_scene *s = load("m.csg", text);
    assert_int_equal(sc_scene_warning_count(s), 0);
    check_notch(s);
    sc_scene_release(s);
    for (int faithful = 0; faithful < 2; faithful++) {
        text[0] = 0;
        append_copies(text, sizeof text, corners, faces, 9, 3e-7);
        s = load_with("m.csg", text, faithful);
        assert_int_equal(sc_scene_warning_count(s), 0);
        check_notch(s);
        sc_scene_release(s);
    }
    text[0] = 0;
    append_copies(text, sizeof text, corners, faces, 9, 1e-5);
    s = load("m.csg", text);
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_non_null(strstr(sc_scene_warning(s, 0)->message, "polyhedron is not closed"));
    sc_scene_release(s);
}

/* Which diagonal splits a non-planar quad: OpenSCAD 2021.01's own choice
 * for each of these faces, read back from its STL export. */
static void test_quad_diagonal(void **state)
{
    (void)state;
    static const struct {
        double p[4][3];
        int diagonal;
    } cases[] = {
        /* the first triangulation flipped by the Delaunay rule */
        {{{8.998, 0, 3.44},
          {8.0987, 0, 1.1208},
          {6.2316, 3.5978, 0.7397},
          {7.4307, 4.2901, 1.5471}},
         0},
        {{{9.1, 0, -3.0155},
          {10.7929, 0, -2.8751},
          {10.5979, 6.1187, -2.8054},
          {8.789, 5.0743, -2.1505}},
         1},
        /* opposite angles summing to pi .. pi + 0.01: the first one stays,
         * though the other is the Delaunay one */
        {{{-9.9433, 0, 2.6861},
          {-8.423, 0, 2.3619},
          {-7.0097, -4.047, 1.1195},
          {-7.8179, -4.5137, 2.8094}},
         0},
        {{{6.3506, -10.9995, -0.1651},
          {6.0641, -10.5033, 1.0826},
          {10.2839, -5.9374, 2.965},
          {11.2021, -6.4675, 0.8499}},
         1},
        /* plain Delaunay */
        {{{12.415, 0, 0},
          {12.7685, 0, 1.8144},
          {10.3973, 6.0029, 2.9644},
          {10.4694, 6.0445, 0.8237}},
         1},
        /* two corners on one point of the projection */
        {{{7.13122, 2.36308, 0.141891},
          {6.18934, 2.85873, -0.174403},
          {6.18934, 2.85873, -0.681548},
          {6.4757, 2.14586, -0.558831}},
         0},
        {{{-6.18934, -2.85873, -0.174403},
          {-5.56081, -3.41357, -0.289547},
          {-6.12372, -3.75912, -0.651657},
          {-6.18934, -2.85873, -0.681548}},
         0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        vec3 q[4];
        for (int k = 0; k < 4; k++)
            q[k] = v3(cases[i].p[k][0], cases[i].p[k][1], cases[i].p[k][2]);
        if (build_mesh_quad_diagonal(q, 1) != cases[i].diagonal)
            fail_msg("case %zu: diagonal %d, OpenSCAD's %d", i,
                     build_mesh_quad_diagonal(q, 1), cases[i].diagonal);
    }
    /* A twisted cell split along its 1-3 diagonal is a different solid
     * from the fan about point 0: a point beside that diagonal is in
     * one and not the other. */
    sc_scene *s =
        load("m.csg", "polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], "
                      "[0, 1, 0], [0, 0, 1], [1, 0, 1.4], [1, 1, 1], [0, 1, 1.4]], "
                      "faces = [[0, 1, 2, 3], [4, 7, 6, 5], [0, 4, 5, 1], "
                      "[1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);");
    vec3 top[4] = {v3(0, 0, 1), v3(0, 1, 1.4), v3(1, 1, 1), v3(1, 0, 1.4)};
    int diagonal = build_mesh_quad_diagonal(top, 1);
    /* The top's two splits: along 4-6 the surface is at z = 1 at the
     * centre, along 5-7 at z = 1.4. */
    assert_int_equal(inside(s, 0.5, 0.5, 1.2), diagonal == 1);
    sc_scene_release(s);
}

/* Bow ties: a box whose top and back faces cross themselves in the plane
 * libtess2 projects them onto. OpenSCAD 2021.01's STL export of this
 * polyhedron splits both along their 0-2 diagonals (4-6 and 2-7), set by
 * the order of its hash tables; the Delaunay rule of
 * build_mesh_quad_diagonal picks the other ones. The point (0.5, 0.5,
 * 1.2), under the top's 5-7 diagonal, has winding number 0 about
 * OpenSCAD's split and the body's winding number about the other one
 * (from the solid angles of the triangles): outside, not inside. */
static void test_bowtie(void **state)
{
    (void)state;
    vec3 top[4] = {v3(0, 0, 1), v3(0.8, 1, 1.4), v3(0.2, 1, 1), v3(1, 0, 1.4)};
    vec3 back[4] = {v3(1, 1, 0), v3(0.2, 1, 1), v3(0.8, 1, 1.4), v3(0, 1, 0)};
    assert_int_equal(build_mesh_quad_crosses(top, 1), 1);
    assert_int_equal(build_mesh_quad_crosses(back, 1), 1);
    assert_int_equal(build_mesh_quad_diagonal(top, 1), 1);
    sc_scene *s =
        load("m.csg", "polyhedron(points = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], "
                      "[0, 0, 1], [1, 0, 1.4], [0.2, 1, 1], [0.8, 1, 1.4]], "
                      "faces = [[0, 1, 2, 3], [4, 7, 6, 5], [0, 4, 5, 1], "
                      "[1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);");
    assert_false(inside(s, 0.5, 0.5, 1.2));
    assert_true(inside(s, 0.5, 0.5, 0.5));
    assert_false(inside(s, 0.5, 0.5, 1.6));
    sc_scene_release(s);
}

/* The triangles of face p[0..n) (a polyhedron's: reversed; numbers as for
 * build_mesh_face_triangles) against the count expected ones (n - 2, or
 * more where OpenSCAD's mending of a face that crosses itself makes
 * more), each a set of three positions, in any order. */
static void check_numbered(const char *name, const double (*p)[3], uint32_t n,
                           const uint32_t *numbers, const uint32_t (*expected)[3],
                           uint32_t count, int split)
{
    vec3 q[16];
    uint32_t tris[3 * 32], written;
    int used[32] = {0};
    for (uint32_t k = 0; k < n; k++)
        q[k] = v3(p[k][0], p[k][1], p[k][2]);
    assert_int_equal(build_mesh_face_triangles(q, n, 1, numbers, tris, 32, &written),
                     split);
    assert_int_equal(written, count);
    for (uint32_t i = 0; i < count; i++) {
        /* wound as the face: positions ascending up to a turn */
        uint32_t *t = &tris[3 * i];
        int turns = (t[0] > t[1]) + (t[1] > t[2]) + (t[2] > t[0]);
        if (turns != 1)
            fail_msg("%s: triangle %u %u %u is not wound as the face", name, t[0], t[1],
                     t[2]);
        uint32_t j = 0;
        for (; j < count; j++) {
            const uint32_t *e = expected[j];
            int hits = 0;
            for (int a = 0; a < 3; a++)
                hits += t[a] == e[0] || t[a] == e[1] || t[a] == e[2];
            if (hits == 3 && !used[j])
                break;
        }
        if (j == count)
            fail_msg("%s: triangle %u %u %u is not OpenSCAD's", name, t[0], t[1], t[2]);
        used[j] = 1;
    }
}

/* check_numbered for a polyhedron of the one face: OpenSCAD numbers its
 * points as it holds the face. */
static void check_triangles(const char *name, const double (*p)[3], uint32_t n,
                            const uint32_t (*expected)[3], int split)
{
    check_numbered(name, p, n, NULL, expected, n - 2, split);
}

/* Faces of more than four points: the triangles of each are OpenSCAD
 * 2021.01's, read back from its STL export of a polyhedron with that face
 * (the faces of random drums with non-planar caps, tests/crosscheck has
 * such models). */
static void test_face_triangles(void **state)
{
    (void)state;
    /* Six points on the unit circle, lifted a little: all within
     * libtess2's 0.01 of one circle, so no edge is flipped and the
     * first triangulation of the monotone region stays (not a fan). */
    static const double hexagon[6][3] = {
        {1, 0, 0.009264},   {0.5, 0.866025, -0.036958},  {-0.5, 0.866025, 0.041594},
        {-1, 0, -0.002595}, {-0.5, -0.866025, 0.008085}, {0.5, -0.866025, 0.01056}};
    static const uint32_t hexagon_tris[4][3] = {
        {0, 1, 5}, {1, 2, 4}, {1, 4, 5}, {2, 3, 4}};
    check_triangles("hexagon", hexagon, 6, hexagon_tris, 1);
    /* a convex nonagon: the monotone rule, then Delaunay flips */
    static const double nonagon[9][3] = {
        {8.93982, 0.031994, 0.050551},   {8.833235, 0.809458, 0.257367},
        {7.975022, 1.142287, 0.102764},  {7.464155, 0.679345, 0.27878},
        {6.897625, 0.367057, 0.12829},   {7.216196, -0.409761, 0.044119},
        {7.412445, -0.700103, 0.212365}, {8.011887, -1.195863, 0.180357},
        {8.645117, -0.716572, -0.123665}};
    static const uint32_t nonagon_tris[7][3] = {
        {0, 1, 3}, {0, 3, 5}, {0, 5, 8}, {1, 2, 3}, {3, 4, 5}, {5, 6, 8}, {6, 7, 8}};
    check_triangles("nonagon", nonagon, 9, nonagon_tris, 1);
    /* a star whose projection is not monotone */
    static const double star[9][3] = {
        {16.48335, 4.019469, 0.241053},  {16.692902, 4.34504, 0.295674},
        {15.980456, 4.396562, 0.169869}, {15.730244, 4.882913, 0.246536},
        {15.105755, 4.252253, 0.1664},   {15.613472, 3.918523, -0.147497},
        {15.65065, 3.139608, -0.217512}, {16.195434, 3.271519, -0.277944},
        {16.621973, 3.272737, -0.272987}};
    static const uint32_t star_tris[7][3] = {{0, 1, 2}, {0, 2, 5}, {0, 5, 7}, {0, 7, 8},
                                             {2, 3, 4}, {2, 4, 5}, {5, 6, 7}};
    check_triangles("star", star, 9, star_tris, 1);
    /* A star of four points whose inner points 1, 3, 5, 7 lie on one
     * circle: not monotone, so libtess2's sweep splits it into regions
     * first, and which of the square's diagonals stays is decided by
     * that split and the order of its faces (not by the Delaunay rule). */
    static const double square_star[8][3] = {
        {40.1272, 98.7203, 0},        {36.4246, 98.0665, -0.0467},
        {33.2797, 100.1272, -0.0056}, {33.9316, 96.425, 0.0308},
        {31.8728, 93.2797, 0},        {35.5771, 93.9416, 0},
        {38.7171, 91.8776, -0.0291},  {38.0665, 95.5754, 0}};
    static const uint32_t square_star_tris[6][3] = {{0, 1, 7}, {1, 2, 3}, {1, 3, 5},
                                                    {1, 5, 7}, {3, 4, 5}, {5, 6, 7}};
    check_triangles("square star", square_star, 8, square_star_tris, 1);
    /* a star of six points at random radii: an edge within libtess2's
     * 0.01 of the Delaunay tie, where its regions decide */
    static const double six_star[12][3] = {
        {3.0651, 2.6145, 0.027},     {0.3624, 1.0214, 0},
        {-0.6676, 3.615, -0.0294},   {-0.5831, 0.6836, 0.0097},
        {-3.8405, 1.3627, 0.0224},   {-0.8345, -0.1541, 0.0163},
        {-2.0655, -1.7619, -0.0448}, {-0.3148, -0.8872, -0.0365},
        {0.6732, -3.6453, 0.0296},   {0.7006, -0.8213, -0.0414},
        {2.7594, -0.9791, -0.0061},  {1.0925, 0.2018, 0}};
    static const uint32_t six_star_tris[10][3] = {
        {0, 1, 11}, {1, 2, 3},  {1, 3, 11}, {3, 4, 5},  {3, 5, 11},
        {5, 6, 7},  {5, 7, 11}, {7, 8, 9},  {7, 9, 11}, {9, 10, 11}};
    check_triangles("six star", six_star, 12, six_star_tris, 1);
    /* A regular octagon with two points pulled in (2 and 5), lifted a
     * little: after a flip, libtess2 (as OpenSCAD 2021.01 bundles it)
     * stacks three of the four edges around the flipped one, not all
     * four, so edge 2-4 stays where the Delaunay rule would go on to
     * flip it to 3-5. */
    static const double two_notches[8][3] = {
        {-0.1194, -0.9928, 0.0113}, {0.6176, -0.7865, 0.0711}, {0.3671, -0.0442, 0.0108},
        {0.7865, 0.6176, 0.0671},   {0.1194, 0.9928, -0.0714}, {-0.1401, 0.1785, 0.0777},
        {-0.9928, 0.1194, -0.0112}, {-0.7865, -0.6176, 0.0154}};
    static const uint32_t two_notches_tris[6][3] = {{0, 1, 2}, {0, 2, 5}, {0, 5, 7},
                                                    {2, 3, 4}, {2, 4, 5}, {5, 6, 7}};
    check_triangles("two notches", two_notches, 8, two_notches_tris, 1);
    /* Not monotone (points 1 and 6 dent it), with a tie: which edge the
     * Delaunay stack flips first follows the order of libtess2's faces,
     * which its sweep's temporary edges outside the polygon (to its
     * sentinels, too) also move (tess_sweep.c). */
    static const double dented[8][3] = {
        {0.019, -0.5219, -0.7032},  {-0.068, 0.06, -0.6446},   {-0.0102, 0.3209, -0.2815},
        {-0.0042, 0.2986, 0.0675},  {-0.0705, 0.4288, 0.4767}, {0.0903, -0.0786, 0.9341},
        {-0.0407, -0.2476, 0.1919}, {0.0957, -0.4974, -0.0726}};
    static const uint32_t dented_tris[6][3] = {{0, 1, 7}, {1, 2, 7}, {2, 3, 6},
                                               {2, 6, 7}, {3, 4, 6}, {4, 5, 6}};
    check_triangles("dented", dented, 8, dented_tris, 1);
    /* points 2 and 3 on one point of the projection: libtess2 keeps 3
     * (listed first), OpenSCAD mends the sliver 1 2 3 */
    static const double pinched[6][3] = {
        {8.34369, 1.78855, 0.670807},  {7.13122, 2.36308, 0.141891},
        {6.18934, 2.85873, -0.174403}, {6.18934, 2.85873, -0.681548},
        {6.4757, 2.14586, -0.558831},  {7.07732, 1.51709, -0.172382}};
    static const uint32_t pinched_tris[4][3] = {
        {0, 1, 5}, {1, 2, 3}, {1, 3, 4}, {1, 4, 5}};
    check_triangles("pinched", pinched, 6, pinched_tris, 1);
    /* Points 4 and 5 above one another (one point of the projection),
     * in a polygon that is not monotone: libtess2 removes the edge
     * between them from its mesh before it sweeps (RemoveDegenerateEdges),
     * keeping 5, and the sweep and the Delaunay stack follow the mesh
     * that leaves, not that of the polygon without 4; OpenSCAD mends the
     * sliver 3 4 5. */
    static const double above[10][3] = {
        {3, -0.0018, 0}, {1, 0.0042, 1},  {0, 0.0027, 1},   {-1, 0, 2},
        {-1, -0.006, 0}, {-1, 0.0064, 0}, {-1, 0.0007, -1}, {0, -0.0045, -2},
        {1, 0.0001, -3}, {2, -0.0017, -1}};
    static const uint32_t above_tris[8][3] = {{0, 1, 9}, {1, 2, 9}, {2, 3, 5}, {2, 5, 9},
                                              {3, 4, 5}, {5, 6, 9}, {6, 7, 9}, {7, 8, 9}};
    check_triangles("above", above, 10, above_tris, 1);
    /* the same with 4 and 5 in another polygon */
    static const double above_too[9][3] = {
        {-0.0466, 1, 0},  {0.0324, 2, 2},  {0.0494, 0, 2},
        {-0.0168, -2, 2}, {0.0057, -1, 0}, {0.0519, -1, 0},
        {0.0042, 0, -2},  {0.0121, 0, -1}, {-0.0094, 1, -1}};
    static const uint32_t above_too_tris[7][3] = {
        {0, 1, 2}, {0, 2, 5}, {0, 5, 7}, {0, 7, 8}, {2, 3, 5}, {3, 4, 5}, {5, 6, 7}};
    check_triangles("above too", above_too, 9, above_too_tris, 1);
    /* two such pairs (1 and 2, 7 and 8), each merged and mended on its own */
    static const double above_twice[10][3] = {
        {1, 0, -0.0199},  {1, 2, 0.005},   {1, 2, -0.0083},  {-1, 3, 0.0157},
        {-1, 1, 0.0254},  {-1, 0, 0.0229}, {-2, -2, 0.0254}, {0, -1, 0.0194},
        {0, -1, -0.0054}, {1, -1, -0.0053}};
    static const uint32_t above_twice_tris[8][3] = {{0, 1, 2}, {0, 2, 4}, {0, 4, 5},
                                                    {0, 5, 8}, {0, 8, 9}, {2, 3, 4},
                                                    {5, 6, 8}, {6, 7, 8}};
    check_triangles("above twice", above_twice, 10, above_twice_tris, 1);
    /* Four points above one another (1 to 4): libtess2 merges them into
     * one, and OpenSCAD cuts the loop of five edges it leaves into ears,
     * in the order of its hash tables (tess_mend.h). */
    static const double above_four[8][3] = {
        {-0.011243023, 5, 0},   {0.00594063103, 1, 4},  {-0.00521628279, 1, 4},
        {-0.00539857475, 1, 4}, {0.0147352293, 1, 4},   {0.00807262212, -4, 0},
        {0.0131502459, -1, -1}, {0.000512888422, 3, -3}};
    static const uint32_t above_four_tris[6][3] = {{0, 1, 2}, {0, 2, 4}, {0, 4, 6},
                                                   {0, 6, 7}, {2, 3, 4}, {4, 5, 6}};
    check_triangles("above four", above_four, 8, above_four_tris, 1);
    /* Three above one another (0 to 2) in a polyhedron whose face
     * [1, 0, 3] comes first, so that OpenSCAD numbers the points 1, 2, 6,
     * 0, 5, 4, 3: the ears of the loop of four edges follow the numbers. */
    static const double above_three[7][3] = {
        {5, 1, 0.0483537167}, {5, 1, -0.0591212958}, {5, 1, 0.00969020277},
        {0, 3, 0.0143731963}, {-3, 2, 0.0692786723}, {-5, -5, 0.0524260812},
        {2, -5, 0.0648107082}};
    static const uint32_t above_three_numbers[7] = {1, 2, 6, 0, 5, 4, 3};
    static const uint32_t above_three_tris[5][3] = {
        {0, 1, 2}, {0, 2, 6}, {2, 3, 6}, {3, 4, 6}, {4, 5, 6}};
    check_numbered("above three", above_three, 7, above_three_numbers, above_three_tris,
                   5, 1);
    /* A projection that touches itself: point 3 on the edge from 0 to 1,
     * which libtess2 splices into it (the sliver 0 1 3 is OpenSCAD's
     * mending), and points 1 and 4 on one point, which it merges */
    static const double on_edge[5][3] = {
        {0, 0, 0.01}, {4, 0, -0.02}, {4, 4, 0.03}, {2, 0, 0.05}, {0, 4, -0.01}};
    static const uint32_t on_edge_tris[3][3] = {{0, 3, 4}, {1, 2, 3}, {0, 1, 3}};
    check_triangles("on an edge", on_edge, 5, on_edge_tris, 1);
    static const double touching[6][3] = {{0, 0, 0.01}, {2, 2, -0.02}, {4, 0, 0.03},
                                          {4, 4, 0.02}, {2, 2, 0.04},  {0, 4, -0.03}};
    static const uint32_t touching_tris[4][3] = {
        {0, 4, 5}, {2, 3, 4}, {0, 1, 4}, {1, 2, 4}};
    check_triangles("touching", touching, 6, touching_tris, 1);
    /* A projection that crosses itself (edges 0-1 and 4-5, in the plane
     * libtess2 picks): libtess2 cuts the two at a new point, OpenSCAD drops
     * its triangles with that point and mends the loops they leave. */
    static const double folded[6][3] = {
        {7.07732, 1.51709, -0.172382}, {6.4757, 2.14586, -0.558831},
        {6.18934, 2.85873, -0.681548}, {7.13314, 3.29466, -0.928364},
        {6.87558, 2.27837, -1.0461},   {6.79716, 1.45703, -0.949727}};
    static const uint32_t folded_tris[4][3] = {
        {2, 3, 4}, {1, 2, 4}, {0, 4, 5}, {0, 1, 4}};
    check_triangles("folded", folded, 6, folded_tris, 1);
    /* one whose mending makes more than n - 2 triangles: 8 of 8 points */
    static const double folded_more[8][3] = {{-0.536078572, -0.844168067, 1.89432597},
                                             {0.0537296385, -0.240709752, 1.21096659},
                                             {0.844168067, -0.536078572, 1.53439569},
                                             {0.975981772, 0.21785219, 1.28362119},
                                             {0.536078572, 0.844168067, 0.861151755},
                                             {-0.126651302, 0.567400098, -0.818307459},
                                             {-0.844168067, 0.536078572, -1.49674737},
                                             {-0.975981772, -0.21785219, -1.60354924}};
    static const uint32_t folded_more_tris[8][3] = {{0, 1, 2}, {0, 2, 7}, {1, 2, 3},
                                                    {1, 2, 7}, {1, 3, 4}, {1, 4, 5},
                                                    {1, 5, 7}, {5, 6, 7}};
    check_numbered("folded more", folded_more, 8, NULL, folded_more_tris, 8, 1);
}

/* Inside faces of a swept mesh, and which of the first n contour points
 * its edges start from (seen, may be NULL). */
static uint32_t swept_inside(const tess_swept *out, uint32_t n, int *seen)
{
    uint32_t inside = 0;
    for (uint32_t f = out->face_next[0]; f != 0; f = out->face_next[f])
        inside += out->inside[f];
    for (uint32_t e = 0; seen && e < out->edges; e++)
        if (out->org[e] < n)
            seen[out->org[e]] = 1;
    return inside;
}

/* libtess2's sweep (tess_sweep.c) follows a polygon as libtess2 sweeps
 * it: two neighbours on one point merged first, points on one point
 * merged as the sweep reaches them, a point on another edge spliced into
 * it, and two edges that cross cut at a new point. */
static void test_sweep_degenerate(void **state)
{
    (void)state;
    /* a C opening to the right, not monotone: two regions inside */
    static const float ws[8] = {0, 4, 4.5f, 1, 1.2f, 4.2f, 4, 0.2f};
    static const float wt[8] = {0, 0, 1, 1.2f, 3, 3, 4, 4};
    tess_swept out;
    assert_int_equal(tess_sweep_faithful(ws, wt, 8, &out), 1);
    uint32_t inside = 0, listed = 0;
    for (uint32_t f = out.face_next[0]; f != 0 && listed < out.faces;
         f = out.face_next[f]) {
        listed++;
        inside += out.inside[f];
        uint32_t e = out.face_edge[f];
        assert_int_equal(out.lface[e], f);
    }
    assert_int_equal(listed + 1, out.faces);
    assert_int_equal(inside, 2);
    tess_swept_free(&out);
    /* point 3 on the edge from 0 to 1: spliced into it, which parts the
     * polygon into two triangles, every point kept */
    static const float ts[5] = {0, 4, 4, 2, 0}, tt[5] = {0, 0, 4, 0, 4};
    assert_int_equal(tess_sweep_faithful(ts, tt, 5, &out), 1);
    int on_edge[5] = {0};
    assert_int_equal(swept_inside(&out, 5, on_edge), 2);
    assert_int_equal(on_edge[0] + on_edge[1] + on_edge[2] + on_edge[3] + on_edge[4], 5);
    tess_swept_free(&out);
    /* edge 2-3 crosses 0-1 at (2, 2) and 4-0 at (1, 3): each pair cut at
     * a new point, n + 1 and n + 2, in the order the sweep meets them */
    static const float xs[5] = {0, 4, 4, 0, 2}, xt[5] = {0, 4, 0, 4, 6};
    assert_int_equal(tess_sweep_faithful(xs, xt, 5, &out), 1);
    assert_int_equal(out.extra, 2);
    assert_true(out.extra_s[0] == 1 && out.extra_t[0] == 3);
    assert_true(out.extra_s[1] == 2 && out.extra_t[1] == 2);
    int crossing[8] = {0};
    swept_inside(&out, 8, crossing);
    assert_true(crossing[6] && crossing[7]);
    tess_swept_free(&out);
    /* two points on one, not neighbours (1 and 4): the polygon touches
     * itself; merged into the one the sweep reaches first, which parts it
     * into two triangles */
    static const float ds[6] = {0, 2, 4, 4, 2, 0}, dt[6] = {0, 2, 0, 4, 2, 4};
    assert_int_equal(tess_sweep_faithful(ds, dt, 6, &out), 1);
    int touching[6] = {0};
    assert_int_equal(swept_inside(&out, 6, touching), 2);
    assert_int_equal(touching[1] + touching[4], 1);
    tess_swept_free(&out);
    /* two neighbours on one point (2 and 3): the edge between them goes
     * first, as libtess2 removes it, 3 merged into 2; the square left is
     * one region */
    static const float ns[5] = {0, 4, 4, 4, 0}, nt[5] = {0, 0, 4, 4, 4};
    assert_int_equal(tess_sweep_faithful(ns, nt, 5, &out), 1);
    int seen[5] = {0};
    assert_int_equal(swept_inside(&out, 5, seen), 1);
    assert_int_equal(seen[0] + seen[1] + seen[2] + seen[4], 4);
    assert_int_equal(seen[3], 0);
    tess_swept_free(&out);
}

/* A mesh a builder makes that is not closed (here a cube without its
 * top, as an extrusion, surface or hull could make): as a polyhedron,
 * left out with a warning in faithful mode, drawn by the parity rule
 * with a warning in exact mode, an error with --strict. */
static void test_builder_open_mesh(void **state)
{
    (void)state;
    static const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const uint32_t indices[20] = {0, 3, 2, 1, 0, 1, 5, 4, 1, 2,
                                         6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    static const uint32_t starts[6] = {0, 4, 8, 12, 16, 20};
    vec3 points[8];
    for (int k = 0; k < 8; k++)
        points[k] = v3(corners[k][0], corners[k][1], corners[k][2]);
    const sc_location loc = {"m.csg", 3, 5};
    const char *why =
        "linear_extrude is not closed (edge (0, 0, 1)-(1, 0, 1) is used by 1 "
        "face)";
    for (int mode = 0; mode < 3; mode++) { /* faithful, exact, strict */
        csg_builder *csg = csg_builder_new();
        assert_non_null(csg);
        sc_error e;
        memset(&e, 0, sizeof e);
        build_notes notes = {NULL, 0, 0, 0};
        build_ctx c = {.file = "m.csg",
                       .csg = csg,
                       .error = &e,
                       .faithful = mode == 0,
                       .notes = &notes,
                       .strict = mode == 2};
        prim p;
        memset(&p, 0, sizeof p);
        const char *empty = NULL;
        sc_status st = build_mesh_prim(&c, &loc, "linear_extrude", 0, points, 8, indices,
                                       starts, 5, &p, &empty);
        char expected[512];
        if (mode == 2) {
            assert_int_equal(st, SC_ERR_SEMANTIC);
            assert_string_equal(e.message, why);
            assert_int_equal(notes.count, 0);
        } else {
            assert_int_equal(st, SC_OK);
            assert_int_equal(notes.count, 1);
            assert_int_equal(notes.items[0].line, 3);
            snprintf(expected, sizeof expected, "%s; %s", why,
                     mode == 0
                         ? "left out, as OpenSCAD leaves it out (\"The given mesh is "
                           "not closed! Unable to convert to CGAL_Nef_Polyhedron.\")"
                         : "rendered by the parity rule (--strict makes it an error)");
            assert_string_equal(notes.items[0].message, expected);
            if (mode == 0) {
                assert_non_null(empty);
                assert_string_equal(empty, "");
            } else {
                assert_null(empty);
                assert_int_equal(p.kind, PRIM_MESH);
            }
        }
        free(notes.items);
        csg_builder_free(csg);
    }
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
    /* the same with every 0 of every other triangle written -0: equal
     * corners, which the import merges all the same */
    p = text;
    p += sprintf(p, "solid notch\n");
    for (int t = 0; t < NOTCH_TRIS; t++) {
        p += sprintf(p, "  facet normal 0 0 0\n    outer loop\n");
        for (int k = 0; k < 3; k++) {
            const float *v = notch_pts[notch_tris[t][k]];
            p += sprintf(p, "      vertex");
            for (int c = 0; c < 3; c++)
                p += sprintf(p, t % 2 && v[c] == 0 ? " -0" : " %g", v[c]);
            p += sprintf(p, "\n");
        }
        p += sprintf(p, "    endloop\n  endfacet\n");
    }
    p += sprintf(p, "endsolid notch\n");
    write_file("notch_negative_zero.stl", text, (size_t)(p - text));
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
    /* a line OpenSCAD's reader cannot parse (its "can't parse vertex
     * line"), and one it passes over (two words after "vertex") */
    write_file("bad.stl", "solid x\nouter loop\nvertex 1 2\nvertex 1 2 x\n", 43);
}

/* tet.off, a tetrahedron; two.amf, two tetrahedra (objects 1 and 2) of 4
 * triangles each. */
static void write_object_files(void)
{
    static const char tet[] = "OFF\n4 4 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    write_file("tet.off", tet, strlen(tet));
#define TET_AMF(x)                                                                       \
    "<object id='" #x "'><mesh><vertices>"                                               \
    "<vertex><coordinates><x>" #x "</x><y>0</y><z>0</z></coordinates></vertex>"          \
    "<vertex><coordinates><x>" #x ".5</x><y>0</y><z>0</z></coordinates></vertex>"        \
    "<vertex><coordinates><x>" #x "</x><y>1</y><z>0</z></coordinates></vertex>"          \
    "<vertex><coordinates><x>" #x "</x><y>0</y><z>1</z></coordinates></vertex>"          \
    "</vertices><volume><triangle><v1>0</v1><v2>2</v2><v3>1</v3></triangle>"             \
    "<triangle><v1>0</v1><v2>1</v2><v3>3</v3></triangle>"                                \
    "<triangle><v1>0</v1><v2>3</v2><v3>2</v3></triangle>"                                \
    "<triangle><v1>1</v1><v2>2</v2><v3>3</v3></triangle></volume></mesh></object>"
    static const char two[] = "<?xml version='1.0'?><amf>" TET_AMF(0) TET_AMF(3) "</amf>";
#undef TET_AMF
    write_file("two.amf", two, strlen(two));
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
    static const char *files[] = {"notch.stl", "sub/notch_bin.stl", "notch.off",
                                  "notch_negative_zero.stl"};
    for (int i = 0; i < 4; i++) {
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
    check_error_strict(model, "import(\"open.stl\");", SC_ERR_SEMANTIC, expected, 0);
    /* faithful: left out where OpenSCAD hands it to CGAL (beside another
     * object), drawn as it is, by the parity rule, where nothing does */
    s = load_one_warning(
        model, "import(\"open.stl\"); cube(1);", 1, 1, 8,
        "imported mesh is not closed (edge (0, 0, 2)-(0, 2, 2) is used by "
        "1 face); left out, as OpenSCAD leaves it out (\"The given mesh is "
        "not closed! Unable to convert to CGAL_Nef_Polyhedron.\")",
        1);
    sc_scene_release(s);
    s = load_one_warning(
        model, "import(\"open.stl\");", 1, 1, 8,
        "imported mesh is not closed (edge (0, 0, 2)-(0, 2, 2) is used by "
        "1 face); rendered by the parity rule (--strict makes it an error)",
        1);
    sc_scene_release(s);
    /* a line OpenSCAD cannot parse: it imports nothing and renders the
     * rest; with --strict the error */
    snprintf(expected, sizeof expected,
             "import: '%s/bad.stl' is not a valid STL file (line 4: can't parse vertex "
             "line 'vertex 1 2 x'); the import is empty, as OpenSCAD leaves it out "
             "(--strict makes it an error)",
             dir);
    for (int faithful = 0; faithful < 2; faithful++) {
        s = load_one_warning(model, "cube(1);\nimport(\"bad.stl\");", faithful, 2, 8,
                             expected, 1);
        assert_true(inside(s, 0.5, 0.5, 0.5));
        sc_scene_release(s);
    }
    snprintf(expected, sizeof expected,
             "%s:1:8: error: import: '%s/bad.stl' is not a valid STL file (line 4: can't "
             "parse vertex line 'vertex 1 2 x')",
             model, dir);
    check_error_strict(model, "import(\"bad.stl\");", SC_ERR_SEMANTIC, expected, 0);
    /* a file that cannot be opened: OpenSCAD's warning, an empty part,
     * the rest rendered */
    snprintf(expected, sizeof expected,
             "%s:2:8: Can't open import file '%s/none.off': No such file or "
             "directory; the import is empty, as OpenSCAD leaves it out (--strict makes "
             "it an error)",
             model, dir);
    const char *const missing[] = {expected};
    sc_scene *rest =
        test_check_warnings(model, "cube(1);\nimport(\"none.off\");", 0, missing, 1);
    assert_true(inside(rest, 0.5, 0.5, 0.5));
    sc_scene_release(rest);
    /* a .dxf or .svg is a 2D import (tests/cli_lenient.sh); any other
     * extension, OpenSCAD 2021.01's "Unsupported file format while trying
     * to import file" and an empty import, whether the file is there or
     * not (--strict: an error) */
    const char *const unsupported[] = {
        "m.csg:2:8: Unsupported file format while trying to import file '\"a.obj\"' "
        "(import() reads .stl, .off, .amf, .3mf, .dxf and .svg files); the import is "
        "empty, as OpenSCAD leaves it out (--strict makes it an error)"};
    for (int faithful = 0; faithful < 2; faithful++) {
        sc_scene *rest = test_check_warnings("m.csg", "cube(1);\nimport(\"a.obj\");",
                                             faithful, unsupported, 1);
        assert_true(inside(rest, 0.5, 0.5, 0.5));
        assert_int_equal(scene_tree(rest)->leaf_count, 1);
        sc_scene_release(rest);
    }
    check_error_strict(
        "m.csg", "import(\"a.obj\");", SC_ERR_UNSUPPORTED,
        "m.csg:1:8: error: Unsupported file format while trying to import "
        "file '\"a.obj\"' (import() reads .stl, .off, .amf, .3mf, .dxf and .svg "
        "files)",
        0);
    /* no file: OpenSCAD imports the file "" (its export writes file = "") */
    sc_scene_release(load_one_warning(
        "m.csg", "import(); cube();", 0, 1, 1,
        "Unsupported file format while trying to import file '\"\"' (import() reads "
        ".stl, "
        ".off, .amf, .3mf, .dxf and .svg files); the import is empty, as OpenSCAD leaves "
        "it out (--strict makes it an error)",
        1));
    /* a file name that is not a string is its text, as OpenSCAD 2021.01
     * takes it (its "Unsupported file format" for import(3)) */
    sc_scene_release(load_one_warning(
        "m.csg", "import(file = 3);", 0, 1, 15,
        "Unsupported file format while trying to import file '\"3\"' (import() reads "
        ".stl, "
        ".off, .amf, .3mf, .dxf and .svg files); the import is empty, as OpenSCAD leaves "
        "it out (--strict makes it an error)",
        0));
    /* the name quoted as OpenSCAD 2021.01 prints it: '"', '\\', tab, line
     * feed and carriage return escaped */
    sc_scene_release(
        load_one_warning("m.csg", "import(\"a \\\"b\\\\c\\td\\ne\\rf.obj\");", 0, 1, 8,
                         "Unsupported file format while trying to import file '\"a "
                         "\\\"b\\\\c\\td\\ne\\rf.obj\"' "
                         "(import() reads .stl, .off, .amf, .3mf, .dxf and .svg files); "
                         "the import is empty, "
                         "as OpenSCAD leaves it out (--strict makes it an error)",
                         0));
    /* under '%' it is checked but not read */
    s = load("m.csg", "%import(\"none.stl\"); cube();");
    assert_int_equal(only_kind(s), PRIM_BOX);
    sc_scene_release(s);
}

/* An import is read once per build, in both modes, also where a hull or
 * minkowski checks that it is closed before it takes it (a union of
 * several solids, a minkowski) and where resize measures it before it is
 * built; what is built and warned of is as before. */
static void test_import_read_once(void **state)
{
    (void)state;
    char dir[512], model[600];
    snprintf(dir, sizeof dir, "%s", work());
    write_notch_files();
    /* a convex file: a tetrahedron */
    static const char tet[] = "OFF\n4 4 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    write_file("tet.off", tet, strlen(tet));
    snprintf(model, sizeof model, "%s/m.csg", dir);
    static const struct {
        const char *file, *text;
        double inside[3], outside[3];
    } cases[] = {
        /* checked as a part of a union, then its corners taken */
        {"notch.stl",
         "hull() { group() { import(\"notch.stl\"); cube(1); } }",
         {1, 1, 1.5},
         {3, 1, 1}},
        /* checked as a summand, then summed */
        {"tet.off",
         "minkowski() { import(\"tet.off\"); cube(1); }",
         {2, 1, 0.5},
         {2.5, 2.5, 2.5}},
        /* measured (in the model's own copy of resize's children), then
         * built */
        {"notch.stl",
         "resize(newsize = [4, 4, 4]) import(\"notch.stl\");",
         {3, 1, 1},
         {2, 2, 3}},
        /* at the top: read where it is built */
        {"notch.off", "import(\"notch.off\");", {1, 1, 0.5}, {1, 1, 1.5}},
    };
    for (int faithful = 0; faithful < 2; faithful++) {
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            counted = cases[i].file;
            reads = 0;
            sc_scene *s = load_with(model, cases[i].text, faithful);
            counted = "";
            assert_int_equal(sc_scene_warning_count(s), 0);
            assert_true(
                inside(s, cases[i].inside[0], cases[i].inside[1], cases[i].inside[2]));
            assert_false(
                inside(s, cases[i].outside[0], cases[i].outside[1], cases[i].outside[2]));
            sc_scene_release(s);
            if (reads != 1)
                fail_msg("%s (faithful %d): '%s' read %d times", cases[i].text, faithful,
                         cases[i].file, reads);
        }
        /* not closed, in a union under hull: read once, left out with its
         * warning */
        counted = "open.stl";
        reads = 0;
        char expected[2400];
        snprintf(expected, sizeof expected,
                 "imported mesh is not closed (edge (0, 0, 2)-(0, 2, 2) is used by 1 "
                 "face); left out, as OpenSCAD leaves it out (\"The given mesh is not "
                 "closed! Unable to convert to CGAL_Nef_Polyhedron.\")");
        sc_scene *s = load_one_warning(
            model, "hull() { group() { import(\"open.stl\"); cube(1); } }", faithful, 1,
            27, expected, 1);
        counted = "";
        sc_scene_release(s);
        assert_int_equal(reads, 1);
    }
}

/* The merged faces of an import that the build's table holds are lent to
 * the builders that want them (a hull's or minkowski's check that the
 * mesh is closed, CGAL's faces), not copied: two readers get the same
 * arrays, which hold the faces a build without the table merges, and
 * build_mesh_faces_free leaves them to the table, which frees them once
 * (build_imports_free). */
static void test_import_faces_lent(void **state)
{
    (void)state;
    write_notch_files();
    char model[600];
    snprintf(model, sizeof model, "%s/m.csg", work());
    model_import import = {"notch.off", {model, 1, 8}, MODEL_MESH_OFF, NULL};
    for (int faithful = 0; faithful < 2; faithful++) {
        csg_builder *csg = csg_builder_new();
        assert_non_null(csg);
        sc_error e, note;
        memset(&e, 0, sizeof e);
        memset(&note, 0, sizeof note);
        build_imports imports;
        memset(&imports, 0, sizeof imports);
        build_ctx c = {.file = model,
                       .csg = csg,
                       .error = &e,
                       .faithful = faithful,
                       .note = &note,
                       .imports = &imports};
        build_ctx alone = c;
        alone.imports = NULL;
        build_mesh_faces first, second, own;
        const char *empty = NULL;
        counted = "notch.off";
        reads = 0;
        assert_int_equal(build_import_faces(&c, &import, &empty, &first), SC_OK);
        assert_null(empty);
        assert_int_equal(build_import_faces(&c, &import, &empty, &second), SC_OK);
        assert_null(empty);
        assert_int_equal(reads, 1);
        assert_ptr_equal(second.points, first.points);
        assert_ptr_equal(second.names, first.names);
        assert_ptr_equal(second.indices, first.indices);
        assert_ptr_equal(second.face_start, first.face_start);
        assert_int_equal(build_import_faces(&alone, &import, &empty, &own), SC_OK);
        counted = "";
        assert_null(empty);
        assert_int_equal(reads, 2);
        assert_true(own.points != first.points);
        assert_int_equal(own.point_count, first.point_count);
        assert_int_equal(own.face_count, first.face_count);
        assert_int_equal(own.face_count, 9);
        assert_memory_equal(own.points, first.points,
                            own.point_count * sizeof *own.points);
        assert_memory_equal(own.names, first.names, own.point_count * sizeof *own.names);
        assert_memory_equal(own.face_start, first.face_start,
                            (own.face_count + 1) * sizeof *own.face_start);
        assert_memory_equal(own.indices, first.indices,
                            own.face_start[own.face_count] * sizeof *own.indices);
        assert_null(first.face_loops);
        build_mesh_faces_free(&first);
        build_mesh_faces_free(&second);
        build_mesh_faces_free(&own);
        build_imports_free(&imports);
        csg_builder_free(csg);
    }
}

/* A hull or minkowski model built alone through build_hull or
 * build_minkowski, with a table of imports of its own (hull_run_start),
 * then freed (hull_run_end). */
typedef struct hull_run {
    parse_tree *tree;
    model *m;
    csg_builder *csg;
    build_imports imports;
    build_notes notes;
    build_resize_cache *cache;
    build_prims out;
    const char *empty;
    sc_error e;
} hull_run;

static void hull_run_start(hull_run *r, const char *model_path, const char *text,
                           int faithful)
{
    memset(r, 0, sizeof *r);
    assert_int_equal(parse_text(model_path, text, strlen(text), &r->tree, &r->e), SC_OK);
    assert_int_equal(model_lower(r->tree, &r->m, &r->e), SC_OK);
    r->csg = csg_builder_new();
    assert_non_null(r->csg);
    build_ctx c = {.file = model_path,
                   .csg = r->csg,
                   .error = &r->e,
                   .faithful = faithful,
                   .notes = &r->notes,
                   .imports = &r->imports};
    const model_node *n = r->m->first;
    sc_status st = n->kind == MODEL_HULL
                       ? build_hull(&c, n, 1, &r->cache, &r->out, &r->empty)
                       : build_minkowski(&c, n, 1, &r->cache, &r->out, &r->empty);
    if (st != SC_OK)
        fail_msg("%s: %s", text, r->e.message);
}

static void hull_run_end(hull_run *r)
{
    free(r->out.items);
    free(r->notes.items);
    build_resize_cache_free(r->cache);
    build_imports_free(&r->imports);
    csg_builder_free(r->csg);
    model_free(r->m);
    parse_tree_free(r->tree);
}

/* A hull, a minkowski or a boolean that CGAL evaluates is the last reader
 * of the imports below it: once it is built, the build's table lets their
 * files go (build_imports_held), the meshes built the same as before. */
static void test_import_let_go(void **state)
{
    (void)state;
    write_notch_files();
    write_object_files();
    static const char square[] = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n4\n"
                                 "70\n1\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n"
                                 "10\n0\n20\n1\n0\nENDSEC\n0\nEOF\n";
    write_file("sq.dxf", square, strlen(square));
    char model_path[600];
    snprintf(model_path, sizeof model_path, "%s/m.csg", work());
    static const struct {
        const char *text;
        uint32_t leaves;
    } cases[] = {
        {"hull() { group() { import(\"notch.stl\"); cube(1); } }", 1},
        {"minkowski() { import(\"tet.off\"); cube(1); }", 1},
        /* not convex: CGAL's convex parts, each summed with the cube */
        {"minkowski() { import(\"notch.off\"); cube(1); }", 0},
        {"hull() { difference() { import(\"notch.stl\"); cube(1); } }", 1},
        /* the extrusions' imports are drawings, not meshes */
        {"hull() { import(\"tet.off\"); linear_extrude(height = 5) { "
         "import(\"sq.dxf\"); } linear_extrude(file = \"sq.dxf\", height = 3); }",
         1},
    };
    for (int faithful = 0; faithful < 2; faithful++) {
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            const char *text = cases[i].text;
            hull_run r;
            hull_run_start(&r, model_path, text, faithful);
            assert_null(r.empty);
            assert_int_equal(r.notes.count, 0);
            if (cases[i].leaves)
                assert_int_equal(r.out.count, cases[i].leaves);
            else
                assert_true(r.out.count > 1);
            if (build_imports_held(&r.imports) != 0)
                fail_msg("%s (faithful %d): %zu files held after the build", text,
                         faithful, build_imports_held(&r.imports));
            hull_run_end(&r);
        }
    }
}

/* Each mesh of an import is merged once per build (build_imports.merges),
 * however many builders take it: each object of a file of several, and in
 * --faithful a file of one object, whose closed check merges as exact
 * mode does, so that its warning names an edge by the file's coordinates
 * where the leaf names it by OpenSCAD's. */
static void test_import_merged_once(void **state)
{
    (void)state;
    write_notch_files();
    write_object_files();
    static const char open[] = "solid o\n"
                               "facet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
                               "vertex 0 0.1 0\nvertex 0.1 0 0\nendloop\nendfacet\n"
                               "facet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
                               "vertex 0.1 0 0\nvertex 0 0 0.1\nendloop\nendfacet\n"
                               "facet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
                               "vertex 0 0 0.1\nvertex 0 0.1 0\nendloop\nendfacet\n"
                               "endsolid o\n";
    write_file("open01.stl", open, strlen(open));
    char model_path[600];
    snprintf(model_path, sizeof model_path, "%s/m.csg", work());
    static const struct {
        const char *text;
        size_t merges;
    } cases[] = {
        {"hull() { group() { import(\"notch.stl\"); cube(1); } }", 1},
        {"hull() { group() { import(\"two.amf\"); cube(1); } }", 2},
        {"minkowski() { import(\"two.amf\"); cube(1); }", 2},
        {"minkowski() { import(\"notch.off\"); cube(1); }", 1},
        {"hull() { group() { import(\"open01.stl\"); cube(1); } }", 1},
    };
    for (int faithful = 0; faithful < 2; faithful++) {
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            const char *text = cases[i].text;
            hull_run r;
            hull_run_start(&r, model_path, text, faithful);
            if (r.imports.merges != cases[i].merges)
                fail_msg("%s (faithful %d): %zu merges, not %zu", text, faithful,
                         r.imports.merges, cases[i].merges);
            hull_run_end(&r);
        }
    }
    /* the check's edge in the file's coordinates, the leaf's in OpenSCAD's */
    static const char *const left_out =
        "; left out, as OpenSCAD leaves it out (\"The given mesh is not closed! "
        "Unable to convert to CGAL_Nef_Polyhedron.\")";
    char expected[600];
    snprintf(expected, sizeof expected,
             "imported mesh is not closed (edge (0, 0.1, 0)-(0.1, 0, 0) is used by 1 "
             "face)%s",
             left_out);
    for (int faithful = 0; faithful < 2; faithful++) {
        sc_scene *s = load_one_warning(
            model_path, "hull() { group() { import(\"open01.stl\"); cube(1); } }",
            faithful, 1, 27, expected, 1);
        sc_scene_release(s);
    }
    snprintf(expected, sizeof expected,
             "imported mesh is not closed (edge (0, 0.0999994, 0)-(0.0999994, 0, 0) is "
             "used by 1 face)%s",
             left_out);
    sc_scene *s = load_with(model_path, "import(\"open01.stl\"); cube(1);", 1);
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message, expected);
    sc_scene_release(s);
}

/* A builder of the other mode (the closed check, exact in --faithful,
 * then the faithful leaf) gets the faces merged once: the same faces, and
 * the points of its mode, equal to those a merge in that mode makes. */
static void test_import_modes_share(void **state)
{
    (void)state;
    static const char tet[] = "OFF\n4 4 0\n0 0 0\n0.1 0 0\n0 0.1 0\n0 0 0.1\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    write_file("tet01.off", tet, strlen(tet));
    char model[600];
    snprintf(model, sizeof model, "%s/m.csg", work());
    model_import import = {"tet01.off", {model, 1, 8}, MODEL_MESH_OFF, NULL};
    for (int first_mode = 0; first_mode < 2; first_mode++) {
        csg_builder *csg = csg_builder_new();
        assert_non_null(csg);
        sc_error e, note;
        memset(&e, 0, sizeof e);
        memset(&note, 0, sizeof note);
        build_imports imports;
        memset(&imports, 0, sizeof imports);
        build_ctx c[2];
        for (int mode = 0; mode < 2; mode++)
            c[mode] = (build_ctx){.file = model,
                                  .csg = csg,
                                  .error = &e,
                                  .faithful = mode,
                                  .note = &note,
                                  .imports = &imports};
        build_mesh_faces f[2], own;
        const char *empty = NULL;
        assert_int_equal(
            build_import_faces(&c[first_mode], &import, &empty, &f[first_mode]), SC_OK);
        assert_int_equal(
            build_import_faces(&c[!first_mode], &import, &empty, &f[!first_mode]), SC_OK);
        assert_null(empty);
        assert_int_equal(imports.merges, 1);
        assert_ptr_equal(f[0].indices, f[1].indices);
        assert_ptr_equal(f[0].face_start, f[1].face_start);
        assert_int_equal(f[0].point_count, 4);
        /* the file's 0.1, and OpenSCAD's point of its cell, as float */
        double tenth = (double)(float)(104857.0 / 1048576.0);
        for (uint32_t u = 0; u < 4; u++) {
            uint32_t name = f[0].names[u];
            assert_int_equal(f[1].names[u], name);
            assert_true(f[0].points[u].x == (name == 1 ? 0.1 : 0));
            assert_true(f[1].points[u].x == (name == 1 ? tenth : 0));
        }
        for (int mode = 0; mode < 2; mode++) {
            build_ctx alone = c[mode];
            alone.imports = NULL;
            assert_int_equal(build_import_faces(&alone, &import, &empty, &own), SC_OK);
            assert_int_equal(own.point_count, f[mode].point_count);
            assert_memory_equal(own.points, f[mode].points,
                                own.point_count * sizeof *own.points);
            assert_memory_equal(own.indices, f[mode].indices,
                                own.face_start[own.face_count] * sizeof *own.indices);
            build_mesh_faces_free(&own);
        }
        build_mesh_faces_free(&f[0]);
        build_mesh_faces_free(&f[1]);
        build_imports_free(&imports);
        csg_builder_free(csg);
    }
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

/* Loads text as the file name with sc_load_options.max_triangles at
 * limit: the status, and the error in message (empty on success). */
static sc_status load_budget_at(const char *name, const char *text, size_t limit,
                                int faithful, char *message, size_t size)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = faithful;
    o.max_triangles = limit;
    sc_status st = sc_scene_load_string(name, text, strlen(text), &o, &s, &e);
    if (st == SC_OK) {
        assert_non_null(s);
        message[0] = 0;
    } else {
        assert_null(s);
        sc_error_format(&e, message, size);
    }
    sc_scene_release(s);
    return st;
}

static sc_status load_budget(const char *text, size_t limit, int faithful, char *message,
                             size_t size)
{
    return load_budget_at("m.csg", text, limit, faithful, message, size);
}

/* A load's meshes share one budget of triangles (sc_load_options
 * .max_triangles): a twisted extrusion of a square in s slices is 8 s side
 * triangles and two caps of 2; a mesh past what is left fails at its own
 * node, before it is checked or indexed, and an extrusion whose 4 s side
 * faces alone pass it fails before it makes them. */
static void test_triangle_budget(void **state)
{
    (void)state;
    const char *twisted =
        "linear_extrude(height = 10, center = false, convexity = 1, twist = 30, slices = "
        "10, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {\n"
        "  square(size = [4, 4], center = true);\n}\n";
    size_t need = 8 * 10 + 4;
    char message[1024], expected[256];
    for (int faithful = 0; faithful < 2; faithful++) {
        assert_int_equal(load_budget(twisted, need, faithful, message, sizeof message),
                         SC_OK);
        assert_int_equal(load_budget(twisted, 0, faithful, message, sizeof message),
                         SC_OK);
        assert_int_equal(
            load_budget(twisted, need - 1, faithful, message, sizeof message),
            SC_ERR_LIMIT);
        snprintf(expected, sizeof expected,
                 "m.csg:1:1: error: linear_extrude: too many mesh triangles (%zu more, "
                 "past the limit of %zu in one model)",
                 need, need - 1);
        assert_string_equal(message, expected);
        /* below its 40 side faces, before any face is made */
        assert_int_equal(load_budget(twisted, 39, faithful, message, sizeof message),
                         SC_ERR_LIMIT);
        assert_string_equal(message, "m.csg:1:1: error: linear_extrude: too many mesh "
                                     "triangles (at least 40 more, past the limit of 39 "
                                     "in one model)");
    }
    /* two non-convex polyhedra: the second passes the budget, at its node */
    char two[4096];
    snprintf(two, sizeof two, "group() {\n%s\n%s\n}\n", TURNED_NOTCH, TURNED_NOTCH);
    size_t notch = 0;
    for (size_t limit = 1; limit < 200 && !notch; limit++)
        if (load_budget(TURNED_NOTCH, limit, 0, message, sizeof message) == SC_OK)
            notch = limit;
    assert_true(notch > 4);
    assert_int_equal(load_budget(two, 2 * notch, 0, message, sizeof message), SC_OK);
    assert_int_equal(load_budget(two, 2 * notch - 1, 0, message, sizeof message),
                     SC_ERR_LIMIT);
    snprintf(expected, sizeof expected,
             "m.csg:3:1: error: polyhedron: too many mesh triangles (%zu more, past the "
             "limit of %zu in one model)",
             notch, 2 * notch - 1);
    assert_string_equal(message, expected);
}

/* An import's triangles are charged to the budget once per import
 * statement, however many builders take them (a hull's or minkowski's
 * check that the mesh is closed, its corners, CGAL's faces of a summand
 * that is not convex, resize's measure, the objects of an AMF file joined
 * into one mesh): a model of T imported triangles loads with a budget of
 * T, and with T - 1 fails at the import with the message it always had.
 * Two statements importing one file are two meshes, charged twice, as two
 * polyhedra are. */
static void test_import_budget_once(void **state)
{
    (void)state;
    char dir[512], model[600];
    snprintf(dir, sizeof dir, "%s", work());
    snprintf(model, sizeof model, "%s/m.csg", dir);
    write_notch_files();
    write_object_files();
    static const struct {
        const char *text;
        size_t triangles, more; /* in all; what the mesh that fails asks for */
        int column;             /* of the file name, where the import fails */
        const char *what;       /* the mesh named in the error */
    } cases[] = {
        /* checked as a part of a union, then its corners taken */
        {"hull() { group() { import(\"notch.stl\"); cube(1); } }", 14, 14, 27,
         "imported mesh"},
        /* checked as a summand, then summed */
        {"minkowski() { import(\"tet.off\"); cube(1); }", 4, 4, 22, "imported mesh"},
        /* a summand that is not convex: also CGAL's check and faces */
        {"minkowski() { import(\"notch.stl\"); cube(1); }", 14, 14, 22, "imported mesh"},
        /* measured, then built */
        {"resize(newsize = [4, 4, 4]) import(\"notch.stl\");", 14, 14, 36,
         "imported mesh"},
        /* two objects joined into one mesh for the hull: the second passes */
        {"hull() { import(\"two.amf\"); }", 8, 4, 17, "object 2 of the imported file"},
        /* two statements of one file: each its own mesh */
        {"hull() { import(\"tet.off\"); import(\"tet.off\"); }", 8, 4, 36,
         "imported mesh"},
    };
    char message[1024], expected[1400];
    for (int faithful = 0; faithful < 2; faithful++) {
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            size_t t = cases[i].triangles;
            sc_status st = load_budget_at(model, cases[i].text, t, faithful, message,
                                          sizeof message);
            if (st != SC_OK)
                fail_msg("%s (faithful %d, budget %zu): %s", cases[i].text, faithful, t,
                         message);
            assert_int_equal(load_budget_at(model, cases[i].text, t - 1, faithful,
                                            message, sizeof message),
                             SC_ERR_LIMIT);
            snprintf(expected, sizeof expected,
                     "%s:1:%d: error: %s: too many mesh triangles (%zu more, past the "
                     "limit of %zu in one model)",
                     model, cases[i].column, cases[i].what, cases[i].more, t - 1);
            assert_string_equal(message, expected);
        }
    }
}

/* Malformed polyhedron points and faces (how the model reads them:
 * test_model.c), built as OpenSCAD 2021.01 builds them: a point it cannot
 * convert is its error "Unable to convert points[3] = [0, 0, "a"] to a
 * vec3 of numbers", here a warning at the point, and the faces read
 * before it are kept: here one triangle, which is not closed, so exact
 * mode draws it by the parity rule and faithful mode leaves it out, each
 * with its warning; with --strict the point is the error. A face that is
 * not a vector, and faces that are not a vector, are read silently; a
 * polyhedron left without faces by a warning is not warned of again. */
static void test_polyhedron_malformed(void **state)
{
    (void)state;
    const char *bad_point =
        "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, \"a\"]], faces = "
        "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);";
    const char *unable = "m.csg:1:55: Unable to convert points[3] = [0, 0, \"a\"] to a "
                         "vec3 of numbers; the polyhedron keeps the faces before it, as "
                         "OpenSCAD does (--strict makes it an error)";
    /* the face it stops in keeps the point before the bad one, and OpenSCAD
     * warns of that degenerate face as it tessellates */
    const char *degenerate = "m.csg:1:89: PolySet has degenerate polygons (faces[1] has "
                             "fewer than 3 points; left out, as OpenSCAD leaves it out)";
    const char *const exact[] = {
        unable, degenerate,
        "m.csg:1:1: polyhedron is not closed (edge 0-1 is used "
        "by 1 face); rendered by the parity rule (--strict makes "
        "it an error)"};
    sc_scene *s = test_check_warnings("m.csg", bad_point, 0, exact, 3);
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    sc_scene_release(s);
    /* faithful: alone, drawn as it is (OpenSCAD hands it to no CGAL
     * operation); beside another object, left out */
    s = test_check_warnings("m.csg", bad_point, 1, exact, 3);
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    sc_scene_release(s);
    const char *const faithful[] = {
        unable, degenerate,
        "m.csg:1:1: polyhedron is not closed (edge 0-1 is used by 1 face); left "
        "out, as OpenSCAD leaves it out (\"The given mesh is not closed! Unable "
        "to convert to CGAL_Nef_Polyhedron.\")"};
    char beside[512];
    snprintf(beside, sizeof beside, "%s cube(1);", bad_point);
    s = test_check_warnings("m.csg", beside, 1, faithful, 3);
    assert_int_equal(scene_tree(s)->leaf_count, 1);
    sc_scene_release(s);
    for (int mode = 0; mode <= 1; mode++) {
        check_error_strict("m.csg", bad_point, SC_ERR_SEMANTIC,
                           "m.csg:1:55: error: wrong type for argument 'points' of "
                           "'polyhedron' (expected a vector of [x, y, z] points)",
                           mode);
        check_error_strict(
            "m.csg",
            "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, inf], [0, 0, 1]], faces = "
            "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);",
            SC_ERR_SEMANTIC, "m.csg:1:44: error: polyhedron point 2 is not finite", mode);
        /* a bad point no face reads is never read; the faces without
         * points are warned of */
        const char *const no_points[] = {
            "m.csg:1:125: PolySet has degenerate polygons (faces[4] and 1 more have "
            "fewer "
            "than 3 points; left out, as OpenSCAD leaves them out)"};
        s = test_check_warnings(
            "m.csg",
            "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], \"x\"], "
            "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2], 7, []]);",
            mode, no_points, 1);
        assert_int_equal(scene_tree(s)->leaf_count, 1);
        assert_true(inside(s, 0.2, 0.2, 0.2));
        sc_scene_release(s);
        /* [x, y] is [x, y, 0]: the apex at the origin */
        s = test_check_warnings("m.csg",
                                "polyhedron(points = [[0, 0, 1], [1, 0, 1], [0, 1, 1], "
                                "[0, 0]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, "
                                "3, 2]]);",
                                mode, NULL, 0);
        assert_true(inside(s, 0.1, 0.1, 0.8));
        assert_false(inside(s, 0.1, 0.1, 0.05));
        sc_scene_release(s);
        /* no face left: the warning that emptied it, and OpenSCAD's of the
         * face it stopped in, but not that the polyhedron is empty */
        const char *const only[] = {
            "m.csg:1:22: Unable to convert points[0] = [0, 0, inf] to a vec3 of numbers; "
            "the polyhedron keeps the faces before it, as OpenSCAD does (--strict makes "
            "it an error)",
            "m.csg:1:45: PolySet has degenerate polygons (faces[0] has fewer than 3 "
            "points; "
            "left out, as OpenSCAD leaves it out)"};
        s = test_check_warnings(
            "m.csg", "polyhedron(points = [[0, 0, inf]], faces = [[0, 0, 0]]);", mode,
            only, 2);
        sc_scene_release(s);
        const char *const bounds[] = {
            "m.csg:1:34: Point index 0 is out of bounds (from faces[0][0])",
            "m.csg:1:37: Point index 1 is out of bounds (from faces[0][1])",
            "m.csg:1:40: Point index 2 is out of bounds (from faces[0][2])",
            "m.csg:1:33: PolySet has degenerate polygons (faces[0] has fewer than 3 "
            "points; "
            "left out, as OpenSCAD leaves it out)"};
        s = test_check_warnings("m.csg", "polyhedron(points = 5, faces = [[0, 1, 2]]);",
                                mode, bounds, 4);
        assert_int_equal(scene_tree(s)->leaf_count, 0);
        sc_scene_release(s);
        const char *const none[] = {"m.csg:1:1: polyhedron without faces is empty"};
        s = test_check_warnings("m.csg",
                                "polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
                                "faces = \"x\");",
                                mode, none, 1);
        sc_scene_release(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nonconvex_polyhedron),
        cmocka_unit_test(test_mesh_errors),
        cmocka_unit_test(test_bad_indices),
        cmocka_unit_test(test_merged_copies),
        cmocka_unit_test(test_quad_diagonal),
        cmocka_unit_test(test_bowtie),
        cmocka_unit_test(test_face_triangles),
        cmocka_unit_test(test_sweep_degenerate),
        cmocka_unit_test(test_builder_open_mesh),
        cmocka_unit_test(test_import),
        cmocka_unit_test(test_import_read_once),
        cmocka_unit_test(test_import_faces_lent),
        cmocka_unit_test(test_import_let_go),
        cmocka_unit_test(test_import_merged_once),
        cmocka_unit_test(test_import_modes_share),
        cmocka_unit_test(test_linear_extrude),
        cmocka_unit_test(test_triangle_budget),
        cmocka_unit_test(test_import_budget_once),
        cmocka_unit_test(test_polyhedron_malformed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
