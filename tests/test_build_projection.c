/* Tests of projection(cut) (src/build/build_projection.c): areas of the
 * 2D result against hand-computed values (cut = true: the section at
 * z = 0 of OpenSCAD's mesh; cut = false: the outline seen along z), the
 * cases of faces and vertices lying in the plane as OpenSCAD 2021.01
 * computes them, transforms that mirror, the leaves built as meshes, a 2D
 * child ignored with a warning, a projection at the top level, and the
 * exact error messages. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build/build_nef_cache.h"
#include "build/build_twod.h"
#include "build/scene.h"
#include "syntax/parse.h"
#include "test_util.h"

/* The region of the children of the first node of text ("group() {...}"),
 * or the status of the failure with its message in error; a warning left
 * by the builder goes to note (when given). CGAL's solids go to nefs (or
 * are evaluated where they occur, when it is NULL). */
static sc_status region_with(const char *text, twod_region *r, char *error, size_t size,
                             char *note, size_t note_size, build_nef_cache *nefs)
{
    parse_tree *tree = NULL;
    sc_error e, warning;
    memset(&warning, 0, sizeof warning);
    build_notes notes = {0};
    sc_status st = parse_text("m.csg", text, strlen(text), &tree, &e);
    assert_int_equal(st, SC_OK);
    csg_builder *csg = csg_builder_new();
    assert_non_null(csg);
    build_ctx c = {.file = "m.csg",
                   .csg = csg,
                   .error = &e,
                   .faithful = 0,
                   .note = &warning,
                   .notes = &notes,
                   .nefs = nefs};
    twod_init(r);
    model *lowered = NULL;
    assert_int_equal(model_lower_twod("m.csg", tree->first, &lowered, &e), SC_OK);
    st = build_twod_children(&c, lowered->first, r);
    if (st != SC_OK)
        sc_error_format(&e, error, size);
    if (note) {
        /* the note first, then the warnings, one a line, each "line:col: " */
        size_t at = (size_t)snprintf(note, note_size, "%s", warning.message);
        for (size_t k = 0; k < notes.count && at < note_size; k++)
            at += (size_t)snprintf(note + at, note_size - at, "%s%d:%d: %s",
                                   at ? "\n" : "", notes.items[k].line,
                                   notes.items[k].column, notes.items[k].message);
    }
    free(notes.items);
    model_free(lowered);
    csg_builder_free(csg);
    parse_tree_free(tree);
    return st;
}

static sc_status region_of(const char *text, twod_region *r, char *error, size_t size,
                           char *note, size_t note_size)
{
    return region_with(text, r, error, size, note, note_size, NULL);
}

/* Area of text's region; outers and holes count the contours each way. */
static double area_of(const char *text, int *outers, int *holes)
{
    twod_region r;
    char message[1024];
    if (region_of(text, &r, message, sizeof message, NULL, 0) != SC_OK)
        fail_msg("unexpected error: %s", message);
    double a = twod_area(&r);
    *outers = *holes = 0;
    for (uint32_t k = 0; k < r.contour_count; k++) {
        if (twod_contour_area(&r, k) > 0)
            (*outers)++;
        else
            (*holes)++;
    }
    twod_free(&r);
    return a;
}

static double area(const char *text)
{
    int outers, holes;
    return area_of(text, &outers, &holes);
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    twod_region r;
    char message[1024];
    assert_int_equal(region_of(text, &r, message, sizeof message, NULL, 0), status);
    assert_string_equal(message, expected);
    twod_free(&r);
}

/* Clipper's grid is 2^-16: every point of the result is within 2^-16 of
 * the exact one, which moves an area of perimeter p by at most p 2^-16. */
#define GRID (1.0 / 65536.0)
#define PI 3.14159265358979323846
#define NEAR(a, b, perimeter) assert_true(fabs((a) - (b)) <= (perimeter)*GRID)

/* multmatrix of a rotation by deg about x, as text */
static void rot_x(char *out, size_t size, double deg)
{
    double c = cos(deg * PI / 180), s = sin(deg * PI / 180);
    snprintf(out, size,
             "multmatrix([[1, 0, 0, 0], [0, %.17g, %.17g, 0], [0, %.17g, %.17g, 0], "
             "[0, 0, 0, 1]])",
             c, -s, s, c);
}

static void test_cut(void **state)
{
    (void)state;
    char text[1024], rx[256];
    /* a cube standing on z = 0: its bottom face is the section */
    NEAR(area("group() { projection(cut = true) { cube(10); } }"), 100, 40);
    /* centred and turned 45 degrees about x: the section is 10 by 10 sqrt 2 */
    rot_x(rx, sizeof rx, 45);
    snprintf(text, sizeof text,
             "group() { projection(cut = true) { %s { cube(10, center = true); } } }",
             rx);
    NEAR(area(text), 100 * sqrt(2), 60);
    /* OpenSCAD's sphere of 8 fragments: 4 rings at 22.5, 67.5, 112.5 and
     * 157.5 degrees; z = 0 cuts between the middle two, a regular octagon
     * of radius 5 sin 67.5 */
    double R = 5 * sin(67.5 * PI / 180);
    NEAR(area("group() { projection(cut = true) { sphere(r = 5, $fn = 8); } }"),
         2 * sqrt(2) * R * R, 60);
    /* a difference: a centred cube minus a diamond prism ($fn = 4, r = 2) */
    int outers, holes;
    NEAR(area_of("group() { projection(cut = true) { difference() { cube(10, center = "
                 "true); cylinder(h = 20, r1 = 2, r2 = 2, center = true, $fn = 4); } } }",
                 &outers, &holes),
         92, 80);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 1);
    /* an intersection of a cube and a cone: the cone's circle at z = 0 of
     * radius 3 (r from 4 at z = -5 to 2 at z = 5), 6 fragments: a hexagon */
    NEAR(area("group() { projection(cut = true) { intersection() { cube(20, center = "
              "true); cylinder(h = 10, r1 = 4, r2 = 2, center = true, $fn = 6); } } }"),
         1.5 * sqrt(3) * 9, 40);
    /* a square pyramid, base [-2, 2]^2 at z = -1, apex at z = 1: [-1, 1]^2 */
    const char *pyramid =
        "polyhedron(points = [[-2, -2, -1], [2, -2, -1], [2, 2, -1], [-2, 2, -1], [0, 0, "
        "1]], faces = [[0, 1, 2, 3], [4, 1, 0], [4, 2, 1], [4, 3, 2], [4, 0, 3]])";
    snprintf(text, sizeof text, "group() { projection(cut = true) { %s; } }", pyramid);
    NEAR(area(text), 4, 20);
    /* mirrored (the triangles turn back outward) */
    snprintf(
        text, sizeof text,
        "group() { projection(cut = true) { multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], "
        "[0, 0, 1, 0], [0, 0, 0, 1]]) { %s; } } }",
        pyramid);
    NEAR(area_of(text, &outers, &holes), 4, 20);
    assert_int_equal(outers, 1);
    /* a hull of a slab [-1, 1]^2 from z = -1 to -0.5 and one [-3, 3]^2
     * from z = 1: its sides run from the small slab's bottom edges (z = -1)
     * to the big one's (z = 1), so at z = 0 the square of half-width 2 */
    NEAR(area("group() { projection(cut = true) { hull() { multmatrix([[1, 0, 0, -1], "
              "[0, 1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) { cube([2, 2, 0.5]); } "
              "multmatrix([[1, 0, 0, -3], [0, 1, 0, -3], [0, 0, 1, 1], [0, 0, 0, 1]]) { "
              "cube([6, 6, 0.5]); } } } }"),
         16, 20);
    /* a linear_extrude laid on its side: square([2, 5]) extruded 3 and
     * turned 90 degrees about x spans x in [0, 2], y in [-3, 0], z in
     * [0, 5]; moved down 2.5, z = 0 cuts it across: 2 x 3 */
    rot_x(rx, sizeof rx, 90);
    snprintf(text, sizeof text,
             "group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
             "[0, 0, 1, -2.5], [0, 0, 0, 1]]) { %s { linear_extrude(height = 3) { "
             "square([2, 5]); } } } } }",
             rx);
    NEAR(area(text), 6, 20);
}

/* Faces and vertices in the plane z = 0, as OpenSCAD 2021.01 computes
 * them (its results for these models, exported as SVG: docs/extrusions.md). */
/* OpenSCAD 2021.01 cuts a Nef polyhedron made of the mesh snapped to its
 * grid of 2^-20 where the transforms below the cut have moved it
 * (PolySet::quantizeVertices), and hands the section on exactly, not
 * through Clipper's grid of 2^-16: each corner of the section of a box
 * 0.1 wide at 0.3 is a corner of a 2^-20 cell, truncated toward zero. It
 * marks the section sanitized all the same (convertToPolygon2d), so that
 * a minkowski or offset keeps its contours' directions
 * (projection_cut_hole_sum). */
static void test_cut_off_grid(void **state)
{
    (void)state;
    twod_region r;
    char message[1024];
    const char *text = "group() { projection(cut = true) { multmatrix([[1, 0, 0, 0.3], "
                       "[0, 1, 0, -0.3], [0, 0, 1, -0.5], [0, 0, 0, 1]]) { cube(size = "
                       "[0.1, 0.1, 1], center = false); } } }";
    if (region_of(text, &r, message, sizeof message, NULL, 0) != SC_OK)
        fail_msg("unexpected error: %s", message);
    const double fine = 1048576.0; /* 2^20 */
    double xs[2] = {trunc(0.3 * fine) / fine, trunc((0.3 + 0.1) * fine) / fine};
    double ys[2] = {trunc(-0.3 * fine) / fine, trunc((-0.3 + 0.1) * fine) / fine};
    assert_int_equal(r.contour_count, 1);
    assert_int_equal(r.point_count, 4);
    for (uint32_t i = 0; i < r.point_count; i++) {
        double x = r.xy[2 * i], y = r.xy[2 * i + 1];
        assert_true(x == xs[0] || x == xs[1]);
        assert_true(y == ys[0] || y == ys[1]);
    }
    assert_true(fabs(twod_area(&r) - (xs[1] - xs[0]) * (ys[1] - ys[0])) <= 1e-18);
    assert_int_equal(r.sanitized, 1);
    twod_free(&r);
}

static void test_cut_in_plane(void **state)
{
    (void)state;
    int outers, holes;
    /* a cube on z = 0 minus a block touching its bottom face from below:
     * a square with a 4 x 4 hole */
    NEAR(area_of("group() { projection(cut = true) { difference() { cube(10); "
                 "multmatrix([[1, 0, 0, 2], [0, 1, 0, 2], [0, 0, 1, -10], [0, 0, 0, 1]]) "
                 "{ cube([4, 4, 10]); } } } }",
                 &outers, &holes),
         84, 60);
    assert_int_equal(holes, 1);
    /* two cubes that meet only in z = 0 intersect in their common face */
    NEAR(area("group() { projection(cut = true) { intersection() { multmatrix([[1, 0, 0, "
              "0], [0, 1, 0, 0], [0, 0, 1, -10], [0, 0, 0, 1]]) { cube(10); } "
              "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
              "cube(10); } } } }"),
         50, 40);
    /* and unite into both faces */
    NEAR(
        area("group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, "
             "0], [0, 0, 1, -10], [0, 0, 0, 1]]) { cube(10); } multmatrix([[1, 0, 0, 5], "
             "[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(10); } } }"),
        150, 60);
    /* a pyramid whose apex touches z = 0 from below: nothing with area */
    assert_true(
        area("group() { projection(cut = true) { polyhedron(points = [[-2, -2, "
             "-1], [2, -2, -1], [2, 2, -1], [-2, 2, -1], [0, 0, 0]], faces = [[0, "
             "1, 2, 3], [4, 1, 0], [4, 2, 1], [4, 3, 2], [4, 0, 3]]); } }") == 0);
    /* a cube below the plane: its top face */
    NEAR(
        area("group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
             "[0, 0, 1, -3], [0, 0, 0, 1]]) { cube(3); } } }"),
        9, 20);
    /* a cube wholly above or below: empty */
    assert_true(
        area("group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, "
             "0, 0], [0, 0, 1, 1], [0, 0, 0, 1]]) { cube(3); } } }") == 0);
}

static void test_outline(void **state)
{
    (void)state;
    char text[1024], rx[256];
    /* every face counts, down-facing ones too: a cube is its footprint */
    NEAR(
        area("group() { projection() { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, "
             "7], [0, 0, 0, 1]]) { cube(10); } } }"),
        100, 40);
    /* turned 45 degrees about x: 10 by 10 sqrt 2 */
    rot_x(rx, sizeof rx, 45);
    snprintf(text, sizeof text,
             "group() { projection(cut = false) { %s { cube(10, center = true); } } }",
             rx);
    NEAR(area(text), 100 * sqrt(2), 60);
    /* a sphere of 8 fragments: its widest rings, the octagon of radius
     * 5 sin 67.5 */
    double R = 5 * sin(67.5 * PI / 180);
    NEAR(area("group() { projection() { sphere(r = 5, $fn = 8); } }"),
         2 * sqrt(2) * R * R, 60);
    /* resized to 4 across: from the octagon's box, as OpenSCAD resizes
     * its mesh, not the exact sphere's (8 sqrt 2, not 0.16 of the octagon) */
    NEAR(area("group() { projection() { resize([4, 0, 0], auto = true) { sphere(r = 5, "
              "$fn = 8); } } }"),
         8 * sqrt(2), 30);
    /* the union of two overlapping squares' prisms at different heights */
    NEAR(area("group() { projection() { cube([2, 2, 1]); multmatrix([[1, 0, 0, 1], [0, "
              "1, 0, 1], [0, 0, 1, 5], [0, 0, 0, 1]]) { cube(2); } } }"),
         7, 20);
    /* a pyramid seen from above: its base */
    NEAR(
        area("group() { projection() { polyhedron(points = [[-2, -2, -1], [2, -2, -1], "
             "[2, 2, -1], [-2, 2, -1], [0, 0, 1]], faces = [[0, 1, 2, 3], [4, 1, 0], [4, "
             "2, 1], [4, 3, 2], [4, 0, 3]]); } }"),
        16, 20);
    /* a linear_extrude laid on its side: x in [0, 2], y in [-3, 0] */
    rot_x(rx, sizeof rx, 90);
    snprintf(text, sizeof text,
             "group() { projection() { %s { linear_extrude(height = 3) { square([2, 5]); "
             "} } } }",
             rx);
    NEAR(area(text), 6, 20);
    /* a rotate_extrude seen from above: OpenSCAD's ring of 8 fragments of
     * the square [2, 3] x [0, 1], an octagon of radius 3 minus one of 2 */
    int outers, holes;
    NEAR(area_of("group() { projection() { rotate_extrude($fn = 8) { "
                 "multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
                 "square(1); } } } }",
                 &outers, &holes),
         2 * sqrt(2) * (9 - 4), 60);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 1);
    /* a hull: the 2D hull of the two cubes' footprints */
    NEAR(area("group() { projection() { hull() { cube(1); multmatrix([[1, 0, 0, 3], [0, "
              "1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) { cube(1); } } } }"),
         4, 20);
    /* '%' children are left out */
    assert_true(area("group() { projection() { %cube(3); } }") == 0);
}

/* A 2D child is ignored as OpenSCAD 2021.01 ignores it: without a word by
 * projection(cut = false), with "Ignoring 2D child object for 3D
 * operation" by projection(cut = true), which unites its children as a 3D
 * operation (with no "Mixing"), and as any 3D operation deeper inside. */
static void test_2d_child(void **state)
{
    (void)state;
    twod_region r;
    char message[1024], note[1024];
    assert_int_equal(region_of("group() { projection() { cube(2); circle(r = 5); } }", &r,
                               message, sizeof message, note, sizeof note),
                     SC_OK);
    NEAR(twod_area(&r), 4, 10);
    assert_string_equal(note, "");
    twod_free(&r);
    assert_int_equal(region_of("group() { projection(cut = true) { circle(r = 5);\n"
                               "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], "
                               "[0, 0, 0, 1]]) { cube(2); } group() { square(1); } } }",
                               &r, message, sizeof message, note, sizeof note),
                     SC_OK);
    NEAR(twod_area(&r), 4, 10);
    assert_string_equal(note, "1:36: Ignoring 2D child object for 3D operation\n"
                              "2:84: Ignoring 2D child object for 3D operation");
    twod_free(&r);
    assert_int_equal(region_of("group() { projection() { union() { cube(2);\n"
                               "square(0); circle(r = 5); } } }",
                               &r, message, sizeof message, note, sizeof note),
                     SC_OK);
    NEAR(twod_area(&r), 4, 10);
    assert_string_equal(note, "2:12: Mixing 2D and 3D objects is not supported\n"
                              "2:1: Ignoring 2D child object for 3D operation\n"
                              "2:12: Ignoring 2D child object for 3D operation");
    twod_free(&r);
}

/* Booleans and minkowski sums go through the CGAL plugin: the outline of
 * the boolean's mesh, not the boolean of the outlines; a minkowski sum cut
 * and projected; a hull of a boolean takes the result's vertices. */
static void test_mesh_booleans(void **state)
{
    (void)state;
    /* a square hole through the cube shows, one that stops inside does not */
    NEAR(area("group() { projection() { difference() { cube(10, center = true); "
              "cylinder(r = 3, h = 30, center = true, $fn = 4); } } }"),
         82, 60);
    NEAR(area("group() { projection() { difference() { cube(10, center = true); "
              "cylinder(r = 3, h = 30, $fn = 4); } } }"),
         100, 60);
    /* the same below a mirroring transform, inside a union */
    NEAR(area("group() { projection() { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, "
              "-1, 0], [0, 0, 0, 1]]) { union() { difference() { cube(10, center = "
              "true); cylinder(r = 3, h = 30, center = true, $fn = 4); } } } } }"),
         82, 60);
    int outers, holes;
    NEAR(area_of("group() { projection(cut = false) { intersection() { cube(10, center "
                 "= true); multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, "
                 "0, 1]]) { cube(10, center = true); } } } }",
                 &outers, &holes),
         50, 40);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 0);
    /* a 2 x 2 square summed with a diamond of radius 1: 4 + 8 + 2 */
    const char *sum = "minkowski() { cube([2, 2, 2]); cylinder(r = 1, h = 1, $fn = 4); }";
    char text[512];
    snprintf(text, sizeof text, "group() { projection() { %s } }", sum);
    NEAR(area(text), 14, 40);
    snprintf(text, sizeof text,
             "group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
             "[0, 0, 1, -1], [0, 0, 0, 1]]) { %s } } }",
             sum);
    NEAR(area(text), 14, 40);
    /* a cube of 4 less a corner cube of 2: the hull of what is left cuts the
     * corner by x + y + z >= 2; at height 1 the section lacks a triangle
     * of 0.5, from above nothing */
    const char *cut = "hull() { difference() { cube(4); multmatrix([[1, 0, 0, -1], [0, "
                      "1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) { cube(3); } "
                      "} }";
    snprintf(text, sizeof text,
             "group() { projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
             "[0, 0, 1, -1], [0, 0, 0, 1]]) { %s } } }",
             cut);
    NEAR(area(text), 15.5, 40);
    snprintf(text, sizeof text, "group() { projection() { %s } }", cut);
    NEAR(area(text), 16, 40);
}

/* The area of text's region with CGAL's solids cached in a cache of its
 * own, and the solids it evaluated and reused. */
static double cached_area(const char *text, size_t *evaluated, size_t *reused)
{
    build_nef_cache *nefs = build_nef_cache_new();
    assert_non_null(nefs);
    twod_region r;
    char message[1024];
    if (region_with(text, &r, message, sizeof message, NULL, 0, nefs) != SC_OK)
        fail_msg("unexpected error: %s", message);
    build_nef_cache_counts(nefs, evaluated, reused);
    build_nef_cache_free(nefs);
    double a = twod_area(&r);
    twod_free(&r);
    return a;
}

/* One difference (a 4 x 3 x 2 box with a unit square hole along z),
 * projected three times, as OpenSCAD's GEB example projects one
 * intersection: as it is, and turned by two quarter turns. CGAL evaluates
 * it once, in its own frame, and each projection takes its solid moved
 * by the transform above it (OpenSCAD's order). Quarter turns are exact,
 * so the region is the one of evaluating each copy through its
 * transform: 11 (12 less the hole) united with two 4 x 2 outlines, one
 * touching it along a side, the other over 5 of it and over the hole:
 * 11 + 8 + 8 - 5 = 22. An inexact turn (30 degrees about z) moves the
 * solid as OpenSCAD moves it, each matrix entry taken exactly: the area
 * stays 11. Equal subtrees that are not booleans, or that differ in one
 * argument, are not shared. */
static void test_nef_cache(void **state)
{
    (void)state;
    static const char boolean[] =
        "group() { difference() { cube(size = [4, 3, 2], center = false); "
        "multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, -1], [0, 0, 0, 1]]) { "
        "cube(size = [1, 1, 4], center = false); } } }";
    char text[4096];
    snprintf(
        text, sizeof text,
        "group() { projection() { %s }\n"
        "projection() { multmatrix([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, "
        "0, 1]]) { %s } }\n"
        "projection() { multmatrix([[0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, "
        "0, 1]]) { %s } } }",
        boolean, boolean, boolean);
    size_t evaluated, reused;
    double cached = cached_area(text, &evaluated, &reused);
    assert_int_equal(evaluated, 1);
    assert_int_equal(reused, 2);
    assert_true(cached == area(text));
    NEAR(cached, 22, 40);

    double c = cos(30 * PI / 180), s = sin(30 * PI / 180);
    snprintf(
        text, sizeof text,
        "group() { projection() { %s }\n"
        "projection() { multmatrix([[%.17g, %.17g, 0, 10], [%.17g, %.17g, 0, 0], [0, 0, "
        "1, 0], [0, 0, 0, 1]]) { %s } } }",
        boolean, c, -s, s, c, boolean);
    cached = cached_area(text, &evaluated, &reused);
    assert_int_equal(evaluated, 1);
    assert_int_equal(reused, 1);
    NEAR(cached, 22, 60);
    NEAR(cached, area(text), 60);

    /* a cube's side differs in its last bit: two evaluations */
    snprintf(
        text, sizeof text,
        "group() { projection() { difference() { cube(size = [4, 3, 2]); cube(1); } }\n"
        "projection() { difference() { cube(size = [4, 3, 2.0000000000000004]); "
        "cube(1); } } }");
    cached = cached_area(text, &evaluated, &reused);
    assert_int_equal(evaluated, 2);
    assert_int_equal(reused, 0);
    NEAR(cached, 12, 14);
}

/* OpenSCAD 2021.01 looks a projection's child up in its cache but does not
 * put it there (it collects its children itself): a difference that is a
 * projection's child is evaluated again at the next projection of it, and
 * warns again; below a group, it is cached, and a later projection of it
 * takes it without a warning. */
static void test_nef_cache_projection_child(void **state)
{
    (void)state;
    build_nef_cache *nefs = build_nef_cache_new();
    assert_non_null(nefs);
    twod_region r;
    char message[1024], note[1024];
    assert_int_equal(
        region_with(
            "group() { projection() { difference() { cube(2); square(1); cube(1); } }\n"
            "projection() { group() { difference() { cube(2); square(1); cube(1); } } }\n"
            "projection() { difference() { cube(2); square(1); cube(1); } } }",
            &r, message, sizeof message, note, sizeof note, nefs),
        SC_OK);
    size_t evaluated, reused;
    build_nef_cache_counts(nefs, &evaluated, &reused);
    build_nef_cache_free(nefs);
    assert_int_equal(evaluated, 2);
    assert_int_equal(reused, 1);
    assert_string_equal(note, "1:50: Mixing 2D and 3D objects is not supported\n"
                              "1:50: Ignoring 2D child object for 3D operation\n"
                              "2:50: Mixing 2D and 3D objects is not supported\n"
                              "2:50: Ignoring 2D child object for 3D operation");
    NEAR(twod_area(&r), 4, 10);
    twod_free(&r);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("group() { projection(cut = true) { torus(r1 = 2, r2 = 1); } }",
                SC_ERR_UNSUPPORTED,
                "m.csg:1:36: error: 'torus' inside projection is not supported (it has "
                "no OpenSCAD polygon mesh)");
    check_error(
        "group() { projection() {\n  difference() { cube(2); torus(r1 = 2, r2 = 1); "
        "} } }",
        SC_ERR_UNSUPPORTED,
        "m.csg:2:27: error: 'torus' inside projection is not supported yet");
    /* arguments of the wrong kind, as OpenSCAD 2021.01 takes them: a cut
     * that is not true is false (the outline of a cube above the plane, not
     * its empty section), a radius that is not a number 1 */
    assert_true(fabs(area("group() { projection(cut = 1) { multmatrix([[1, 0, 0, 0], "
                          "[0, 1, 0, 0], [0, 0, 1, 2], [0, 0, 0, 1]]) { cube(1); } } }") -
                     1) < 1e-9);
    assert_true(fabs(area("group() { projection(cut = true) { sphere(r = \"x\"); } }") -
                     area("group() { projection(cut = true) { sphere(r = 1); } }")) <
                1e-12);
    check_error(
        "group() { projection() { sphere(r = 1e6, $fa = 0.01, $fs = 0.01); } }",
        SC_ERR_LIMIT,
        "m.csg:1:26: error: projection: $fn, $fa and $fs of radius 1e+06 give too "
        "many fragments (limit is 4096)");
}

/* At the top level a projection is a 2D object: evaluated (its errors
 * reported), then treated as every 2D object among 3D ones is. */
static void test_top_level(void **state)
{
    (void)state;
    const char *text = "cube(1);\nprojection() { sphere(2); }";
    sc_scene *s = NULL;
    sc_error e;
    assert_int_equal(sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e),
                     SC_OK);
    char buf[1024];
    assert_int_equal(sc_scene_warning_count(s), 2);
    assert_string_equal(sc_error_format(sc_scene_warning(s, 0), buf, sizeof buf),
                        "m.csg:2:1: error: Mixing 2D and 3D objects is not supported");
    assert_string_equal(sc_error_format(sc_scene_warning(s, 1), buf, sizeof buf),
                        "m.csg:2:1: error: Ignoring 2D child object for 3D operation");
    sc_scene_release(s);
    test_check_error(
        "m.csg",
        "cube(1);\nprojection() { difference() { cube(2); torus(r1 = 2, r2 = "
        "1); } }",
        SC_ERR_UNSUPPORTED,
        "m.csg:2:40: error: 'torus' inside projection is not supported yet");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cut),
        cmocka_unit_test(test_cut_off_grid),
        cmocka_unit_test(test_cut_in_plane),
        cmocka_unit_test(test_outline),
        cmocka_unit_test(test_2d_child),
        cmocka_unit_test(test_mesh_booleans),
        cmocka_unit_test(test_nef_cache),
        cmocka_unit_test(test_nef_cache_projection_child),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_top_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
