/* Tests of the 2D engine (src/twod/) and of OpenSCAD's twisted and scaled
 * linear_extrude (src/build/build_extrude_faithful.c): areas of booleans,
 * offsets, hulls and Minkowski sums against hand-computed values, the
 * orientation of outlines and holes, OpenSCAD's even-odd polygons, exact
 * error messages and limits; extrusions are closed meshes whose volume is
 * the analytic one (frustum, pyramid, wedge, twisted prism); 2D objects in
 * a 3D model are ignored with a warning, and a model of 2D objects only is
 * an error. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build/build_extrude_faithful.h"
#include "build/build_twod.h"
#include "build/scene.h"
#include "csg/prim_mesh.h"
#include "syntax/parse.h"
#include "test_util.h"

/* The region of the children of the first node of text ("group() {...}"),
 * or the status of the failure with its message in error. */
static sc_status region_of(const char *text, twod_region *r, char *error, size_t size)
{
    parse_tree *tree = NULL;
    sc_error e;
    sc_status st = parse_text("m.csg", text, strlen(text), &tree, &e);
    assert_int_equal(st, SC_OK);
    build_ctx c = {.file = "m.csg",
                   .csg = NULL,
                   .error = &e,
                   .faithful = 1,
                   .note = NULL,
                   .notes = NULL};
    twod_init(r);
    model *lowered = NULL;
    assert_int_equal(model_lower_twod("m.csg", tree->first, &lowered, &e), SC_OK);
    st = build_twod_children(&c, lowered->first, r);
    if (st != SC_OK)
        sc_error_format(&e, error, size);
    model_free(lowered);
    parse_tree_free(tree);
    return st;
}

/* region_of with the builder's warnings into *notes (free notes->items)
 * and strict as --strict. */
static sc_status region_noted(const char *text, int strict, twod_region *r,
                              build_notes *notes, char *error, size_t size)
{
    parse_tree *tree = NULL;
    sc_error e;
    assert_int_equal(parse_text("m.csg", text, strlen(text), &tree, &e), SC_OK);
    memset(notes, 0, sizeof *notes);
    build_ctx c = {.file = "m.csg",
                   .csg = NULL,
                   .error = &e,
                   .faithful = 1,
                   .strict = strict,
                   .note = NULL,
                   .notes = notes};
    twod_init(r);
    model *lowered = NULL;
    assert_int_equal(model_lower_twod("m.csg", tree->first, &lowered, &e), SC_OK);
    sc_status st = build_twod_children(&c, lowered->first, r);
    if (st != SC_OK)
        sc_error_format(&e, error, size);
    model_free(lowered);
    parse_tree_free(tree);
    return st;
}

static void region(const char *text, twod_region *r)
{
    char message[1024];
    if (region_of(text, r, message, sizeof message) != SC_OK)
        fail_msg("unexpected error: %s", message);
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    twod_region r;
    char message[1024];
    assert_int_equal(region_of(text, &r, message, sizeof message), status);
    assert_string_equal(message, expected);
    twod_free(&r);
}

/* Area of text's region, and how many contours run each way. */
static double area_of(const char *text, int *outers, int *holes)
{
    twod_region r;
    region(text, &r);
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

/* Clipper's grid is 2^-16: every point of a clipped region is within
 * 2^-16 of the exact one, which moves an area of perimeter p by at most
 * p 2^-16. */
#define GRID (1.0 / 65536.0)
#define PI 3.14159265358979323846

static void test_booleans(void **state)
{
    (void)state;
    int outers, holes;
    /* two 2x2 squares overlapping in a 1x1 square */
    assert_true(fabs(area_of("group() { square(2); multmatrix([[1, 0, 0, 1], [0, 1, 0, "
                             "1], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(2); } }",
                             &outers, &holes) -
                     7) < 12 * GRID);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 0);
    /* a 4x4 square minus a diamond of radius 1 ($fn = 4): a hole, wound
     * clockwise */
    assert_true(fabs(area_of("group() { difference() { square(4, center = true); "
                             "circle(r = 1, $fn = 4); } }",
                             &outers, &holes) -
                     14) < 24 * GRID);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 1);
    /* intersection of three squares: [1, 2] x [1, 2] */
    assert_true(
        fabs(area_of("group() { intersection() { square(2); square(3); "
                     "multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, "
                     "0, 1]]) { square(5); } } }",
                     &outers, &holes) -
             1) < 4 * GRID);
    /* disjoint union: two outers */
    assert_true(fabs(area_of("group() { square(1); multmatrix([[1, 0, 0, 3], [0, 1, 0, "
                             "0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(1); } }",
                             &outers, &holes) -
                     2) < 8 * GRID);
    assert_int_equal(outers, 2);
    /* a mirrored square stays counter-clockwise */
    assert_true(fabs(area_of("group() { multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, "
                             "1, 0], [0, 0, 0, 1]]) { square([3, 2]); } }",
                             &outers, &holes) -
                     6) < 10 * GRID);
    assert_int_equal(holes, 0);
    /* a singular matrix empties its subtree; '%' and '*' children are out */
    assert_true(area_of("group() { multmatrix([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, "
                        "0], [0, 0, 0, 1]]) { square(3); } %square(9); *square(9); }",
                        &outers, &holes) == 0);
    /* a single square is not clipped: exact */
    twod_region r;
    region("group() { square([0.3, 0.7], center = true); }", &r);
    assert_int_equal(r.point_count, 4);
    assert_true(r.xy[0] == -0.15 && r.xy[1] == -0.35);
    twod_free(&r);
}

static void test_polygons(void **state)
{
    (void)state;
    int outers, holes;
    /* a 10x10 outline with a 4x4 path inside it: a hole (even-odd) */
    assert_true(
        fabs(area_of(
                 "group() { polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [3, "
                 "3], [7, 3], [7, 7], [3, 7]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]); }",
                 &outers, &holes) -
             84) < 56 * GRID);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 1);
    /* the hole wound the same way as the outline is still a hole */
    assert_true(
        fabs(area_of(
                 "group() { polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [3, "
                 "3], [3, 7], [7, 7], [7, 3]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]); }",
                 &outers, &holes) -
             84) < 56 * GRID);
    /* two paths overlapping by 2x4: even-odd leaves the overlap out */
    assert_true(
        fabs(
            area_of("group() { polygon(points = [[0, 0], [4, 0], [4, 4], [0, 4], [2, 0], "
                    "[6, 0], [6, 4], [2, 4]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]); }",
                    &outers, &holes) -
            16) < 40 * GRID);
    /* a clockwise polygon is turned counter-clockwise; fewer than 3
     * points is nothing */
    assert_true(fabs(area_of("group() { polygon(points = [[0, 0], [0, 2], [2, 0]]); }",
                             &outers, &holes) -
                     2) < 8 * GRID);
    assert_int_equal(outers, 1);
    assert_true(
        area_of("group() { polygon(points = [[0, 0], [0, 2]]); }", &outers, &holes) == 0);
}

/* Signed area of contour k of r clipped to the strip y0 <= y <= y1
 * (Sutherland-Hodgman against the two lines; the strip is convex, so the
 * clipped polygon's signed area is that of the contour's part inside). */
static double strip_area(const twod_region *r, uint32_t k, double y0, double y1)
{
    uint32_t n = r->start[k + 1] - r->start[k];
    const double *xy = r->xy + 2 * (size_t)r->start[k];
    double *a = malloc(4 * (n + 1) * sizeof *a), *b = a + 2 * (n + 1);
    assert_non_null(a);
    memcpy(a, xy, 2 * n * sizeof *a);
    for (int side = 0; side < 2; side++) {
        /* keep s (y - line) >= 0: y >= y0, then y1 >= y */
        double line = side ? y1 : y0, s = side ? -1 : 1;
        uint32_t m = 0;
        for (uint32_t i = 0; i < n; i++) {
            const double *p = a + 2 * i, *q = a + 2 * ((i + 1) % n);
            double dp = s * (p[1] - line), dq = s * (q[1] - line);
            if (dp >= 0) {
                b[2 * m] = p[0];
                b[2 * m++ + 1] = p[1];
            }
            if ((dp < 0) != (dq < 0)) {
                double t = dp / (dp - dq);
                b[2 * m] = p[0] + t * (q[0] - p[0]);
                b[2 * m++ + 1] = line;
            }
        }
        memcpy(a, b, 2 * m * sizeof *a);
        n = m;
    }
    double area = 0;
    for (uint32_t i = 0; i < n; i++) {
        const double *p = a + 2 * i, *q = a + 2 * ((i + 1) % n);
        area += p[0] * q[1] - q[0] * p[1];
    }
    free(a);
    return area / 2;
}

/* text: OpenSCAD's glyph polygons united; an 'o' is an outline and a hole,
 * "oo" two of each, and the united region cut by a square loses area. */
static void test_text(void **state)
{
    (void)state;
    int outers, holes;
    double one = area_of("group() { text(text = \"o\"); }", &outers, &holes);
    assert_true(one > 0 && outers == 1 && holes == 1);
    double two = area_of("group() { text(text = \"oo\"); }", &outers, &holes);
    assert_true(outers == 2 && holes == 2);
    /* the second 'o' sits elsewhere on the 2^-16 grid: each point moves by
     * at most GRID per axis, and an 'o' of size 10 has less than 50 units
     * of outline, so the area moves by less than 50 sqrt(2) GRID */
    assert_true(fabs(two - 2 * one) < 2 * 50 * 1.5 * GRID);
    double cut =
        area_of("group() { difference() { text(text = \"oo\"); square(size = [100, "
                "2]); } }",
                &outers, &holes);
    /* The square [0, 100] x [0, 2] spans the text (advance about 11 for
     * "oo" at size 10), so it removes exactly the part of "oo" with 0 <= y
     * <= 2: the sum of the contours' signed areas clipped to that strip
     * (holes run clockwise and subtract). The clipper moves only the points
     * where an outline meets y = 0 or y = 2 (the others are on its grid
     * already), each by less than GRID, and the cut region's perimeter is
     * below the outlines' plus the strip's two edges across the text. */
    twod_region oo;
    region("group() { text(text = \"oo\"); }", &oo);
    double inside = 0, perimeter = 0, x_lo = INFINITY, x_hi = -INFINITY;
    for (uint32_t k = 0; k < oo.contour_count; k++) {
        inside += strip_area(&oo, k, 0, 2);
        for (uint32_t i = oo.start[k]; i < oo.start[k + 1]; i++) {
            uint32_t next = i + 1 < oo.start[k + 1] ? i + 1 : oo.start[k];
            perimeter += hypot(oo.xy[2 * next] - oo.xy[2 * i],
                               oo.xy[2 * next + 1] - oo.xy[2 * i + 1]);
            x_lo = fmin(x_lo, oo.xy[2 * i]);
            x_hi = fmax(x_hi, oo.xy[2 * i]);
        }
    }
    twod_free(&oo);
    assert_true(x_lo >= 0 && x_hi <= 100);
    perimeter += 2 * (x_hi - x_lo);
    print_message("text cut: %.9f of %.9f, strip %.9f, off by %.3g (bound %.3g)\n", cut,
                  two, inside, fabs(cut - (two - inside)), perimeter * GRID);
    assert_true(inside > 0);
    assert_true(fabs(cut - (two - inside)) <= perimeter * GRID);
}

static void test_offset_hull_minkowski(void **state)
{
    (void)state;
    int outers, holes;
    /* delta: the square grows by 1 on each side, mitred */
    assert_true(
        fabs(area_of("group() { offset(delta = 1) { square(2); } }", &outers, &holes) -
             16) < 16 * GRID);
    /* chamfer: each corner cut at distance 1 from the square's corner,
     * removing (sqrt 2 - 1)^2 of the mitred corner: 4 + 8 sqrt 2 */
    assert_true(
        fabs(area_of("group() { offset(delta = 1, chamfer = true) { square(2); } }",
                     &outers, &holes) -
             (4 + 8 * sqrt(2))) < 16 * GRID);
    /* r: 4 + 8 + pi, the arcs inscribed within the arc tolerance
     * 1 - cos(180 / 360 degrees), so at most 2 pi (1 - cos 0.5 deg) short */
    double a =
        area_of("group() { offset(r = 1, $fn = 360) { square(2); } }", &outers, &holes);
    double sag = 2 * PI * (1 - cos(0.5 * PI / 180));
    assert_true(a <= 12 + PI + 16 * GRID);
    assert_true(a >= 12 + PI - sag - 16 * GRID);
    /* a negative r shrinks: 4x4 by -1 is 2x2 (convex corners stay sharp) */
    assert_true(
        fabs(area_of("group() { offset(r = -1) { square(4); } }", &outers, &holes) - 4) <
        16 * GRID);
    /* hull of two diamonds 4 apart: a 4x2 rectangle and two triangles */
    twod_region r;
    region(
        "group() { hull() { circle(r = 1, $fn = 4); multmatrix([[1, 0, 0, 4], [0, 1, 0, "
        "0], [0, 0, 1, 0], [0, 0, 0, 1]]) { circle(r = 1, $fn = 4); } } }",
        &r);
    assert_int_equal(r.contour_count, 1);
    assert_int_equal(r.point_count, 6);
    assert_true(fabs(twod_area(&r) - 10) < 1e-12);
    twod_free(&r);
    /* square + diamond: the square, four 2x1 sides and four quarter
     * diamonds */
    assert_true(fabs(area_of("group() { minkowski() { square(2); circle(r = 1, $fn = 4); "
                             "} }",
                             &outers, &holes) -
                     14) < 16 * GRID);
    assert_int_equal(outers, 1);
    /* OpenSCAD: an empty child after the first is skipped */
    assert_true(fabs(area_of("group() { minkowski() { square(2); square(0); circle(r = "
                             "1, $fn = 4); } }",
                             &outers, &holes) -
                     14) < 16 * GRID);
}

/* "multmatrix(translate [x, y]) { inner }" into buf. */
static const char *moved(char *buf, size_t size, double x, double y, const char *inner)
{
    snprintf(
        buf, size,
        "multmatrix([[1, 0, 0, %.17g], [0, 1, 0, %.17g], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ %s }",
        x, y, inner);
    return buf;
}

/* The sum of two convex contours is one convex polygon, made by merging
 * their edges (twod_clip.cpp) instead of uniting their quads: it must be
 * the hull of one moved to each corner of the other, and where one side
 * has two contours (the quads' path) the result must be the union of the
 * sums of each. */
static void test_minkowski_convex(void **state)
{
    (void)state;
    int outers, holes;
    char text[8192], part[512];
    const char *heptagon = "circle(r = 1, $fn = 7);";
    int len = snprintf(text, sizeof text, "group() { hull() { ");
    for (int i = 0; i < 5; i++) {
        double a = 2 * PI * i / 5;
        len += snprintf(text + len, sizeof text - (size_t)len, "%s ",
                        moved(part, sizeof part, 2 * cos(a), 2 * sin(a), heptagon));
    }
    snprintf(text + len, sizeof text - (size_t)len, "} }");
    double hull = area_of(text, &outers, &holes);
    double sum = area_of("group() { minkowski() { circle(r = 1, $fn = 7); circle(r = 2, "
                         "$fn = 5); } }",
                         &outers, &holes);
    assert_int_equal(outers, 1);
    assert_int_equal(holes, 0);
    assert_true(hull > 9);
    assert_true(fabs(sum - hull) < 64 * GRID);

    /* two squares apart (two contours: the quads) against each square's
     * convex sum, united */
    const char *disc = "circle(r = 0.75, $fn = 9);";
    char left[512], right[512];
    moved(left, sizeof left, 0, 0, "square(2);");
    moved(right, sizeof right, 5, 1, "square([1, 3]);");
    snprintf(text, sizeof text, "group() { minkowski() { union() { %s %s } %s } }", left,
             right, disc);
    double both = area_of(text, &outers, &holes);
    assert_int_equal(outers, 2);
    snprintf(text, sizeof text,
             "group() { union() { minkowski() { %s %s } minkowski() { %s %s } } }", left,
             disc, right, disc);
    double each = area_of(text, &outers, &holes);
    assert_int_equal(outers, 2);
    assert_true(both > 10);
    assert_true(fabs(both - each) < 64 * GRID);
}

static void test_errors(void **state)
{
    (void)state;
    /* arguments of the wrong kind are their defaults, as OpenSCAD 2021.01
     * takes them: a radius 1, a size 1 (its warning is the model's:
     * test_model.c), a chamfer false, a text "" */
    int outers, holes;
    assert_true(fabs(area_of("group() { circle(r = \"a\"); }", &outers, &holes) -
                     area_of("group() { circle(r = 1); }", &outers, &holes)) < 1e-12);
    assert_true(
        fabs(area_of("group() {\n  square(size = [1, 2, 3]);\n}", &outers, &holes) - 1) <
        4 * GRID);
    assert_true(fabs(area_of("group() { offset(delta = 1, chamfer = 1) { square(1); } }",
                             &outers, &holes) -
                     9) < 16 * GRID);
    assert_true(area_of("group() { text(text = 5); }", &outers, &holes) == 0);
    /* a path index that is not a number is 0, as OpenSCAD reads it */
    assert_true(
        fabs(area_of("group() { polygon(points = [[0, 0], [1, 0], [1, 1], [0, 1]], "
                     "paths = [[\"x\", 1, 2, 3]]); }",
                     &outers, &holes) -
             1) < 4 * GRID);
    /* an offset that is not finite (a .scad's 1/0, written as inf) draws
     * nothing, as in OpenSCAD 2021.01 (tests/cli_lenient.sh) */
    assert_true(area_of("group() { offset(r = inf) { square(1); } }", &outers, &holes) ==
                0);
    assert_true(area_of("group() { offset(r = -inf) { square(1); } }", &outers, &holes) ==
                0);
    assert_true(
        area_of("group() { offset(delta = nan) { square(1); } }", &outers, &holes) == 0);
    /* the finest $fa (36,000 fragments), as OpenSCAD draws it: the rounded
     * square's area, its corners a circle of radius 1e6 */
    double fine =
        area_of("group() { offset(r = 1e6, $fa = 0.01, $fs = 0.01) { square(1); } }",
                &outers, &holes);
    double rounded = 1 + 4e6 + PI * 1e12;
    assert_true(fabs(fine - rounded) < 1e-6 * rounded);
    {
        /* a 3D child of a 2D operation is left out (OpenSCAD's warnings) */
        const char *text = "group() { difference() { square(1); cube(1); } }";
        parse_tree *tree = NULL;
        sc_error e;
        assert_int_equal(parse_text("m.csg", text, strlen(text), &tree, &e), SC_OK);
        build_notes notes = {NULL, 0, 0, 0};
        build_ctx c = {.file = "m.csg",
                       .csg = NULL,
                       .error = &e,
                       .faithful = 1,
                       .note = NULL,
                       .notes = &notes};
        model *lowered = NULL;
        assert_int_equal(model_lower_twod("m.csg", tree->first, &lowered, &e), SC_OK);
        twod_region r;
        twod_init(&r);
        assert_int_equal(build_twod_children(&c, lowered->first, &r), SC_OK);
        assert_true(fabs(twod_area(&r) - 1) < 1e-12);
        assert_int_equal(notes.count, 2);
        assert_string_equal(notes.items[0].message,
                            "Mixing 2D and 3D objects is not supported");
        assert_string_equal(notes.items[1].message,
                            "Ignoring 3D child object for 2D operation");
        assert_int_equal(notes.items[1].line, 1);
        assert_int_equal(notes.items[1].column, 37);
        free(notes.items);
        twod_free(&r);
        model_free(lowered);
        parse_tree_free(tree);
    }
    check_error("group() { roof() { square(1); } }", SC_ERR_UNSUPPORTED,
                "m.csg:1:11: error: 'roof' inside group is not supported yet");
    /* past the clipper's range (2^46 at its scale), where OpenSCAD's union
     * stops on Clipper's exception: the union's error (the square alone is
     * drawn, test_range) */
    check_error(
        "group() { square(1); square(70368744177664); }", SC_ERR_LIMIT,
        "m.csg:1:1: error: group: coordinates out of range (limit is 7.03687e+13)");
    /* the depth guard: 1001 nested groups under the outer one */
    size_t depth = 1001, len = 0;
    char *text = malloc(depth * 12 + 64);
    assert_non_null(text);
    len += (size_t)sprintf(text + len, "group() {");
    for (size_t i = 0; i < depth; i++)
        len += (size_t)sprintf(text + len, "group(){");
    len += (size_t)sprintf(text + len, "square(1);");
    for (size_t i = 0; i <= depth; i++)
        len += (size_t)sprintf(text + len, "}");
    check_error(text, SC_ERR_LIMIT,
                "m.csg:1:8002: error: too many nested 2D nodes in group (limit is 1000)");
    free(text);
}

/* ---- linear_extrude ---- */

/* The mesh of the extrusion in text (one linear_extrude node). */
static double extrude_volume(const char *text, int faithful, uint32_t *triangles)
{
    parse_tree *tree = NULL;
    sc_error e;
    assert_int_equal(parse_text("m.csg", text, strlen(text), &tree, &e), SC_OK);
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    build_ctx c = {.file = "m.csg",
                   .csg = b,
                   .error = &e,
                   .faithful = faithful,
                   .note = NULL,
                   .notes = NULL};
    prim p;
    const char *empty = NULL;
    model *lowered = NULL;
    assert_int_equal(model_lower_twod("m.csg", tree->first, &lowered, &e), SC_OK);
    sc_status st = build_linear_extrude_faithful(&c, lowered->first, 1, &p, &empty);
    if (st != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    assert_null(empty);
    assert_int_equal(p.kind, PRIM_MESH);
    const prim_mesh *m = p.u.mesh.mesh;
    double volume = 0;
    for (uint32_t i = 0; i < m->tri_count; i++) {
        vec3 a = m->v[3 * i], bb = m->v[3 * i + 1], cc = m->v[3 * i + 2];
        volume += v3_dot(a, v3_cross(bb, cc)) / 6;
    }
    *triangles = m->tri_count;
    csg_builder_free(b);
    model_free(lowered);
    parse_tree_free(tree);
    return volume;
}

static void test_extrude_volumes(void **state)
{
    (void)state;
    uint32_t tris;
    /* scale 0.5: a frustum of a 2x2 square, h/3 (A1 + A2 + sqrt(A1 A2));
     * one slice, planar trapezoid sides: exact */
    double v = extrude_volume("linear_extrude(height = 10, scale = 0.5) { square(2, "
                              "center = true); }",
                              1, &tris);
    assert_true(fabs(v - 10.0 / 3 * (4 + 1 + 2)) < 1e-12 * 70);
    assert_int_equal(tris, 4 * 2 + 2 * 2); /* sides, two caps as fans */
    /* scale 0: a pyramid, A h / 3, the top merged into one apex */
    v = extrude_volume("linear_extrude(height = 6, scale = 0) { square(3); }", 1, &tris);
    assert_true(fabs(v - 9 * 6 / 3.0) < 1e-12 * 18);
    /* scale [1, 0]: a wedge whose top is a segment; the section at
     * height t h is 2 x 2 (1 - t): 2 h */
    v = extrude_volume("linear_extrude(height = 5, scale = [1, 0]) { square(2, center = "
                       "true); }",
                       1, &tris);
    assert_true(fabs(v - 10) < 1e-9);
    /* a circle onto a segment: top points fall on each other along the
     * segment, the mesh must still close (build_mesh_prim checks) */
    v = extrude_volume("linear_extrude(height = 4, scale = [1, 0], $fn = 7) { circle(r = "
                       "2, $fn = 7); }",
                       1, &tris);
    assert_true(v > 0);
    /* twisted prism: each section is the rotated square, so the volume is
     * A h; the mesh's sides are chords between slices 0.25 degrees apart,
     * cutting in by at most r (1 - cos(0.125 deg)) = 3.4e-6 over the
     * perimeter 8: |dV| <= 8 * 3.4e-6 * h */
    v = extrude_volume(
        "linear_extrude(height = 10, twist = 90, slices = 360) { square(2, "
        "center = true); }",
        1, &tris);
    /* and to first order in the slice angle more: each side quad is a
     * twisted quadrilateral split along its shorter diagonal, which bulges
     * out of the hyperbolic paraboloid through its corners by
     * d dh |e|^2 / 12 (d the slice's angle, dh its height, e the edge);
     * over the 4 edges of length 2 and n slices: 16 (pi / 2) h / (12 n).
     * The split along the longer diagonal would cut in by as much. What
     * is left is second order: the paraboloid against the true twisted
     * surface; it must be well under 1% of the first-order term here and
     * shrink 4 times when the slices double. */
    double first = 16 * (PI / 2) * 10 / (12 * 360.0);
    double rest360 = v - 40 - first;
    assert_true(fabs(rest360) < 0.01 * first);
    v = extrude_volume(
        "linear_extrude(height = 10, twist = 90, slices = 720) { square(2, "
        "center = true); }",
        1, &tris);
    double rest720 = v - 40 - first / 2;
    assert_true(fabs(rest720) < fabs(rest360) / 3);
    /* a hole: a 4x4 square minus a 2x2 one, scaled 2 at the top: the
     * frustum of the outer minus that of the hole: (7/3) h (16 - 4) */
    v = extrude_volume("linear_extrude(height = 3, scale = 2) { difference() { square(4, "
                       "center = true); square(2, center = true); } }",
                       1, &tris);
    assert_true(fabs(v - 3.0 / 3 * (12 + 48 + sqrt(12.0 * 48))) < 1e-9);
}

/* OpenSCAD's slice counts: $fn per 360 degrees of twist, at least one
 * slice per 120 degrees; $fa and $fs otherwise; $fn slices for a
 * non-uniform scale. Each slice of a square adds 4 quads, 8 triangles. */
static void test_extrude_slices(void **state)
{
    (void)state;
    uint32_t tris;
    extrude_volume(
        "linear_extrude(height = 10, twist = 90, $fn = 20) { square(2, center = "
        "true); }",
        1, &tris);
    assert_int_equal(tris, 5 * 8 + 4); /* ceil(90 / 360 * 20) = 5 */
    extrude_volume(
        "linear_extrude(height = 1, twist = 360, $fn = 1) { square(2, center = "
        "true); }",
        1, &tris);
    assert_int_equal(tris, 3 * 8 + 4); /* at least 360 / 120 */
    /* $fa = 12: 90 / 12 -> 8; the helix of radius sqrt 2 over h = 10:
     * 10.15 long / $fs 2 -> 6: the fewer */
    extrude_volume(
        "linear_extrude(height = 10, twist = 90, $fn = 0, $fa = 12, $fs = 2) { "
        "square(2, center = true); }",
        1, &tris);
    assert_int_equal(tris, 6 * 8 + 4);
    extrude_volume("linear_extrude(height = 10, scale = [2, 1], $fn = 4) { square(2, "
                   "center = true); }",
                   1, &tris);
    assert_int_equal(tris, 4 * 8 + 4);
    extrude_volume("linear_extrude(height = 10, scale = 3, $fn = 4) { square(2, center = "
                   "true); }",
                   1, &tris);
    assert_int_equal(tris, 1 * 8 + 4); /* uniform scale: one slice */
}

static void check_load_error(const char *text, sc_status status, const char *expected)
{
    test_check_error("m.csg", text, status, expected);
}

static void test_extrude_errors(void **state)
{
    (void)state;
    /* a scale that is neither a number nor [x, y] is 1, silently, as
     * OpenSCAD 2021.01 takes it: the unit cube */
    uint32_t plain_tris, odd_tris;
    double plain =
        extrude_volume("linear_extrude(height = 1) { square(); }", 1, &plain_tris);
    double odd = extrude_volume(
        "linear_extrude(height = 1, scale = \"a\", twist = [9]) { square(); }", 1,
        &odd_tris);
    assert_true(fabs(odd - 1) < 1e-9 && fabs(plain - 1) < 1e-9);
    assert_int_equal(odd_tris, plain_tris);
    check_load_error("linear_extrude(height = 1, scale = [1, inf]) { square(); }",
                     SC_ERR_SEMANTIC,
                     "m.csg:1:36: error: linear_extrude: scale must be finite");
    check_load_error("linear_extrude(height = 1, twist = inf) { square(); }",
                     SC_ERR_SEMANTIC,
                     "m.csg:1:36: error: linear_extrude: twist must be finite");
    check_load_error(
        "linear_extrude(height = 1, twist = 1, slices = 1e7) { square(); }", SC_ERR_LIMIT,
        "m.csg:1:48: error: linear_extrude: 1e+07 slices are too many (limit "
        "is 1000000)");
    check_load_error(
        "linear_extrude(height = 1, twist = 1, slices = 600000) { circle(r = "
        "1, $fn = 8); }",
        SC_ERR_LIMIT,
        "m.csg:1:1: error: linear_extrude: 600000 slices of 8 points are too "
        "many (limit is 2000000 side faces)");
    {
        /* text of the wrong kind is empty text, as OpenSCAD 2021.01 takes it */
        static const char *const empty[] = {
            "m.csg:1:1: linear_extrude without height or area is empty"};
        sc_scene_release(test_check_warnings(
            "m.csg", "linear_extrude(height = 1, twist = 10) {\n  text(text = 5);\n}", 0,
            empty, 1));
    }
    {
        /* twisted: the prism path leaves the 3D child out too */
        static const char *const ignored[] = {
            "m.csg:3:3: Ignoring 3D child object for 2D operation"};
        sc_scene_release(test_check_warnings(
            "m.csg",
            "linear_extrude(height = 1, twist = 10) {\n  square(1);\n  sphere(1);\n}", 0,
            ignored, 1));
    }
}

/* Past the clipper's range (2^46 at its scale), as OpenSCAD 2021.01 draws
 * it, each case checked against its STL or DXF export: a square or circle
 * is born sanitized and is moved as it is, so it is drawn while no clipper
 * takes it; a sanitized region turned over is sanitized again, where the
 * clipper refuses it with its warning; a union of two stops on Clipper's
 * exception in OpenSCAD, and is an error here (test_errors). */
static void test_range(void **state)
{
    (void)state;
    twod_region r;
    build_notes notes;
    char message[1024];
    region("group() { square(size = [1e14, 1e14]); }", &r);
    assert_true(twod_area(&r) == 1e28);
    twod_free(&r);
    region("group() { circle(r = 1e14, $fn = 12); }", &r);
    assert_true(fabs(twod_area(&r) - 3e28) < 1e16);
    twod_free(&r);
    /* out of the range and back: a square of side 1 at (10000, 0) */
    region("group() { multmatrix([[1e-10, 0, 0, 0], [0, 1e-10, 0, 0], [0, 0, 1, 0], "
           "[0, 0, 0, 1]]) { multmatrix([[1, 0, 0, 1e14], [0, 1, 0, 0], [0, 0, 1, 0], "
           "[0, 0, 0, 1]]) { square(size = [1e10, 1e10]); } } }",
           &r);
    assert_int_equal(r.contour_count, 1);
    assert_true(fabs(twod_area(&r) - 1) < 1e-12);
    for (uint32_t i = 0; i < r.point_count; i++)
        assert_true(fabs(r.xy[2 * i] - 10000.5) <= 0.5 + 1e-12);
    twod_free(&r);
    /* turned over: sanitized again, refused */
    static const char mirrored[] =
        "group() { multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ square(size = [1e14, 1e14]); } }";
    assert_int_equal(region_noted(mirrored, 0, &r, &notes, message, sizeof message),
                     SC_OK);
    assert_int_equal(r.contour_count, 0);
    assert_int_equal(notes.count, 1);
    assert_string_equal(
        notes.items[0].message,
        "Range check failed for polygon. skipping (outline 1 of the shape "
        "and those after it, as OpenSCAD leaves them out; --strict makes "
        "it an error)");
    assert_int_equal(notes.items[0].column, 11);
    free(notes.items);
    twod_free(&r);
    assert_int_equal(region_noted(mirrored, 1, &r, &notes, message, sizeof message),
                     SC_ERR_LIMIT);
    assert_string_equal(message, "m.csg:1:11: error: multmatrix: outline 1 has "
                                 "coordinates out of the clipper's range");
    free(notes.items);
    twod_free(&r);
    /* a polygon's outline past the range that the clipper skips untested
     * (two points): nothing, with no warning, and the rest drawn */
    assert_int_equal(
        region_noted("group() { polygon(points = [[0, 0], [10, 0], [0, 10], "
                     "[1e14, 0], [1e14, 5]], paths = [[3, 4], [0, 1, 2]]); }",
                     0, &r, &notes, message, sizeof message),
        SC_OK);
    assert_true(twod_area(&r) == 50);
    assert_int_equal(notes.count, 0);
    free(notes.items);
    twod_free(&r);
    /* extruded (faithful) and twisted: the unit model scaled by 1e14 */
    uint32_t tris, unit_tris;
    double v = extrude_volume("linear_extrude(height = 1e14, twist = 30, slices = 2) { "
                              "square(size = [1e14, 1e14], center = true); }",
                              1, &tris);
    double unit = extrude_volume("linear_extrude(height = 1, twist = 30, slices = 2) { "
                                 "square(size = [1, 1], center = true); }",
                                 1, &unit_tris);
    assert_int_equal(tris, unit_tris);
    assert_true(unit > 1 && fabs(v / 1e42 - unit) < 1e-12);
    /* a coordinate past any number */
    check_error("group() { multmatrix([[1e300, 0, 0, 0], [0, 1e300, 0, 0], [0, 0, 1, 0], "
                "[0, 0, 0, 1]]) { square(size = [1e10, 1e10]); } }",
                SC_ERR_LIMIT,
                "m.csg:1:11: error: multmatrix: coordinates are not finite");
}

/* 2D objects among 3D objects: OpenSCAD's warnings, the empty solid; a
 * model whose first object is 2D is a 2D model, drawn as a slab. */
static void test_2d_in_3d(void **state)
{
    (void)state;
    static const char *const mixed[] = {
        "m.csg:3:3: Mixing 2D and 3D objects is not supported",
        "m.csg:3:3: Ignoring 2D child object for 3D operation"};
    sc_scene *s = test_check_warnings(
        "m.csg", "union() {\n  cube(1);\n  circle(r = 5);\n}", 0, mixed, 2);
    assert_true(csg_inside(scene_tree(s), v3(0.5, 0.5, 0.5)));
    assert_false(csg_inside(scene_tree(s), v3(3, 0, 0.25)));
    sc_scene_release(s);
    /* only 2D: the union, 1 thick about z = 0 */
    s = test_load("m.csg",
                  "group() {\n  square(2);\n  offset(r = 1) { circle(r = 1); }\n}", 0);
    assert_int_equal(sc_scene_warning_count(s), 0);
    assert_true(csg_inside(scene_tree(s), v3(1.5, 1.5, 0.4)));
    assert_true(csg_inside(scene_tree(s), v3(-1.5, 0, -0.4)));
    assert_false(csg_inside(scene_tree(s), v3(1.5, 1.5, 0.6)));
    assert_false(csg_inside(scene_tree(s), v3(2.5, 2.5, 0)));
    sc_scene_release(s);
    /* still checked: OpenSCAD's warnings of its size first (openscad -o
     * x.stl prints these) */
    static const char *const unsized[] = {
        "m.csg:2:15: Unable to convert square(size=\"x\", ...) parameter to a number or "
        "a vec2 of numbers",
        "m.csg:2:1: Mixing 2D and 3D objects is not supported",
        "m.csg:2:1: Ignoring 2D child object for 3D operation"};
    sc_scene_release(
        test_check_warnings("m.csg", "cube(1);\nsquare(size = \"x\");", 0, unsized, 3));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_booleans),
        cmocka_unit_test(test_polygons),
        cmocka_unit_test(test_text),
        cmocka_unit_test(test_offset_hull_minkowski),
        cmocka_unit_test(test_minkowski_convex),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_range),
        cmocka_unit_test(test_extrude_volumes),
        cmocka_unit_test(test_extrude_slices),
        cmocka_unit_test(test_extrude_errors),
        cmocka_unit_test(test_2d_in_3d),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
