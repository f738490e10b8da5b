/* The SVG reader (formats/svg.c) against areas and bounds computed by hand
 * from OpenSCAD 2021.01's rules: page scaling and the y flip, each shape's
 * even-odd fill then the union, 40-point circles, strokes, transforms,
 * OpenSCAD's number rules; and bad input, which must be an error with the
 * import's position, never a crash. */
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "formats/svg.h"

static const sc_location at = {"m.csg", 3, 7};

/* Reads text; returns the status, the region in *r (initialised here). */
static sc_status read_svg(const char *text, int center, double dpi, twod_region *r,
                          sc_error *e)
{
    twod_init(r);
    svg_options o = {dpi, center};
    return svg_read(text, strlen(text), "x.svg", &at, &o, r, NULL, e);
}

static double area_of(const char *text)
{
    twod_region r;
    sc_error e;
    sc_status st = read_svg(text, 0, 72, &r, &e);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", e.message);
    double a = twod_area(&r);
    twod_free(&r);
    return a;
}

static void bounds(const twod_region *r, double b[4])
{
    b[0] = b[1] = INFINITY;
    b[2] = b[3] = -INFINITY;
    for (uint32_t i = 0; i < r->point_count; i++) {
        b[0] = fmin(b[0], r->xy[2 * i]);
        b[1] = fmin(b[1], r->xy[2 * i + 1]);
        b[2] = fmax(b[2], r->xy[2 * i]);
        b[3] = fmax(b[3], r->xy[2 * i + 1]);
    }
}

/* The clipper's grid is 2^-16: coordinates agree to its size, areas to
 * about perimeter times grid. */
#define GRID (1.0 / 65536)
#define NEAR(a, b, tol)                                                                  \
    do {                                                                                 \
        double near_a = (a), near_b = (b);                                               \
        if (!(fabs(near_a - near_b) <= (tol)))                                           \
            fail_msg("%s = %.12g, expected %.12g", #a, near_a, near_b);                  \
    } while (0)

static void test_page(void **state)
{
    (void)state;
    twod_region r;
    sc_error e;
    double b[4];
    /* a viewBox twice the page in millimetres: half the size; y up from
     * the page's bottom */
    assert_int_equal(read_svg("<svg width='100mm' height='50mm' viewBox='0 0 200 100'>"
                              "<rect x='20' y='10' width='40' height='30'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    NEAR(twod_area(&r), 20 * 15, 1e-6);
    twod_free(&r);
    /* a viewBox of zero width and height draws nothing, as in OpenSCAD,
     * where its points are not finite; with one of them zero, meet takes
     * the other's scale, and none draws nothing */
    assert_int_equal(read_svg("<svg width='100' height='100' viewBox='0 0 0 0'>"
                              "<rect x='10' y='10' width='30' height='30'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    assert_int_equal(read_svg("<svg width='100' height='100' viewBox='0 0 10 0' "
                              "preserveAspectRatio='none'>"
                              "<rect x='1' y='1' width='3' height='3'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    /* OpenSCAD: 3.53 to 14.11 on both axes (10 units across 100 pt) */
    assert_int_equal(read_svg("<svg width='100' height='100' viewBox='0 0 10 0'>"
                              "<rect x='1' y='1' width='3' height='3'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    bounds(&r, b);
    NEAR(b[0], 25.4 / 7.2, 1e-4);
    NEAR(b[2], 4 * 25.4 / 7.2, 1e-4);
    NEAR(b[1], 25.4 / 7.2, 1e-4);
    NEAR(b[3], 4 * 25.4 / 7.2, 1e-4);
    twod_free(&r);
    assert_int_equal(read_svg("<svg width='100mm' height='50mm' viewBox='0 0 200 100'>"
                              "<rect x='20' y='10' width='40' height='30'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    bounds(&r, b);
    NEAR(b[0], 10, 1e-4);
    NEAR(b[2], 30, 1e-4);
    NEAR(b[1], 50 - 20, 1e-4); /* y 10..40 of 100 -> 50 - 20 .. 50 - 5 */
    NEAR(b[3], 45, 1e-4);
    twod_free(&r);
    /* without a unit the width is at the dpi: 72 units to the inch */
    assert_int_equal(read_svg("<svg width='72' height='72' viewBox='0 0 10 10'>"
                              "<rect width='10' height='10'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    NEAR(twod_area(&r), 25.4 * 25.4, 4 * 25.4 * GRID);
    twod_free(&r);
    assert_int_equal(read_svg("<svg width='72' height='72' viewBox='0 0 10 10'>"
                              "<rect width='10' height='10'/></svg>",
                              0, 96, &r, &e),
                     SC_OK);
    NEAR(twod_area(&r), pow(25.4 * 72 / 96, 2), 4 * 25.4 * GRID);
    twod_free(&r);
    /* no viewBox: a user unit is a millimetre whatever the page */
    assert_int_equal(
        read_svg("<svg width='5in' height='2in'><rect width='10' height='4'/>"
                 "</svg>",
                 0, 72, &r, &e),
        SC_OK);
    NEAR(twod_area(&r), 40, 1e-6);
    bounds(&r, b);
    NEAR(b[3], 2 * 25.4, 1e-4);
    twod_free(&r);
    /* meet: the smaller scale, centred (xMidYMid) */
    assert_int_equal(read_svg("<svg width='100mm' height='50mm' viewBox='0 0 10 10'>"
                              "<rect width='10' height='10'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    bounds(&r, b);
    NEAR(b[0], 25, 1e-4);
    NEAR(b[2], 75, 1e-4);
    NEAR(b[1], 0, 1e-4);
    NEAR(b[3], 50, 1e-4);
    twod_free(&r);
    /* none: each axis its own scale */
    assert_int_equal(read_svg("<svg width='100mm' height='50mm' viewBox='0 0 10 10' "
                              "preserveAspectRatio='none'><rect width='10' height='10'/>"
                              "</svg>",
                              0, 72, &r, &e),
                     SC_OK);
    NEAR(twod_area(&r), 5000, 1e-4);
    twod_free(&r);
    /* center: the bounds on the origin */
    assert_int_equal(
        read_svg("<svg><rect x='3' y='5' width='4' height='2'/></svg>", 1, 72, &r, &e),
        SC_OK);
    bounds(&r, b);
    NEAR(b[0], -2, 1e-4);
    NEAR(b[2], 2, 1e-4);
    NEAR(b[1], -1, 1e-4);
    NEAR(b[3], 1, 1e-4);
    twod_free(&r);
}

static void test_shapes(void **state)
{
    (void)state;
    /* 40 points, as OpenSCAD draws circles and ellipses */
    double polygon40 = 20 * sin(2 * M_PI / 40);
    NEAR(area_of("<svg><circle cx='5' cy='5' r='3'/></svg>"), polygon40 * 9,
         2 * M_PI * 3 * GRID);
    NEAR(area_of("<svg><ellipse cx='5' cy='5' rx='4' ry='2'/></svg>"), polygon40 * 8,
         1e-5);
    NEAR(area_of("<svg><polygon points='0,0 10,0 10,10'/></svg>"), 50, 1e-6);
    /* one path's rings are even-odd: a hole; two shapes are united */
    NEAR(area_of("<svg><path d='M0 0 H10 V10 H0 Z M2 2 H8 V8 H2 Z'/></svg>"), 64, 1e-6);
    NEAR(area_of("<svg><rect width='10' height='10'/><rect x='2' y='2' width='6' "
                 "height='6'/></svg>"),
         100, 1e-6);
    /* relative commands, implicit lineto after moveto, h and v */
    NEAR(area_of("<svg><path d='m 1 1 4 0 v 3 h -4 z'/></svg>"), 12, 1e-6);
    /* a rounded rect: 4 quarter arcs of 9 steps (|90| * 10 / 180 + 4), each
     * a fan of 9 triangles about its centre (OpenSCAD: 96.502641) */
    NEAR(area_of("<svg><rect width='10' height='10' rx='2'/></svg>"),
         100 - 16 + 4 * 9 * 0.5 * 4 * sin(M_PI / 2 / 9), 40 * GRID);
    /* an arc that ends where it starts is left out (SVG F.6.2, and
     * OpenSCAD draws none): the square, not a circle about its corner */
    NEAR(area_of("<svg><path d='M 10 10 H 50 A 20 20 0 0 1 50 10 V 50 H 10 Z'/></svg>"),
         1600, 1e-6);
    /* the defs subtree is not drawn; unknown elements are transparent */
    NEAR(area_of("<svg><defs><rect width='10' height='10'/></defs>"
                 "<a><rect width='2' height='3'/></a></svg>"),
         6, 1e-6);
}

static void test_strokes(void **state)
{
    (void)state;
    /* a line is its stroke: width 1 by default, square caps */
    NEAR(area_of("<svg><line x1='0' y1='0' x2='10' y2='0'/></svg>"), 11 * 1, 1e-4);
    NEAR(area_of("<svg><line x1='0' y1='0' x2='10' y2='0' stroke-width='2' "
                 "stroke-linecap='butt'/></svg>"),
         20, 1e-4);
    /* the style's entry when there is no attribute; "2px" is no number */
    NEAR(area_of("<svg><line x1='0' y1='0' x2='10' y2='0' style='stroke-width:3;"
                 "stroke-linecap:butt'/></svg>"),
         30, 1e-4);
    NEAR(area_of("<svg><line x1='0' y1='0' x2='10' y2='0' stroke-width='2px' "
                 "stroke-linecap='butt'/></svg>"),
         10, 1e-4);
    /* an open path is stroked, unless some subpath was closed */
    NEAR(area_of("<svg><path d='M0 0 L10 0' stroke-linecap='butt'/></svg>"), 10, 1e-4);
    NEAR(area_of("<svg><path d='M0 5 H3 V8 Z M0 0 L10 0'/></svg>"), 4.5, 1e-6);
}

static void test_transforms(void **state)
{
    (void)state;
    twod_region r;
    sc_error e;
    double b[4];
    assert_int_equal(read_svg("<svg><g transform='translate(10, 20) scale(2)'>"
                              "<rect width='1' height='3' transform='rotate(90)'/></g>"
                              "</svg>",
                              0, 72, &r, &e),
                     SC_OK);
    NEAR(twod_area(&r), 12, 1e-6);
    bounds(&r, b);
    /* rotate(90) takes (1, 3) to (-3, 1); then 2x and (10, 20); then y
     * flips: x 4..10, y -22..-20 */
    NEAR(b[0], 4, 1e-4);
    NEAR(b[2], 10, 1e-4);
    NEAR(b[1], -22, 1e-4);
    NEAR(b[3], -20, 1e-4);
    twod_free(&r);
    /* matrix, and an operation with the wrong arguments is the identity */
    NEAR(area_of("<svg><rect width='1' height='1' transform='matrix(3 0 0 2 0 0) "
                 "scale(1 2 3)'/></svg>"),
         6, 1e-6);
    /* skewX keeps the area */
    NEAR(area_of("<svg><rect width='2' height='2' transform='skewX(30)'/></svg>"), 4,
         1e-6);
}

static void test_numbers(void **state)
{
    (void)state;
    /* "2.5.5" is 2.5 then .5; '-' starts a number; "1e1" is one number */
    NEAR(area_of("<svg><path d='M0 0L1e1 0L1e1-2.5.5-2.5z'/></svg>"), 24.375, 1e-6);
    NEAR(area_of("<svg><path d='M0,0L10,0L10,-2.5L0.5,-2.5z'/></svg>"), 24.375, 1e-6);
    /* "1E-1" is not: "1E" is 0 and -1 the next number, as OpenSCAD reads
     * it, so the points are (0, 0), (0, -1), then 0 (dropped) and (10, 5) */
    NEAR(area_of("<svg><path d='M0 0 L1E-1 0 L10 5 z'/></svg>"), 5, 1e-6);
}

/* Bad input: an error at the import's position naming the file (and the
 * XML line where there is one), never a crash. */
static void test_bad_input(void **state)
{
    (void)state;
    twod_region r;
    sc_error e;
    char text[256];
    assert_int_equal(
        read_svg("<svg>\n<rect width='1' height='1'>\n</svg>", 0, 72, &r, &e),
        SC_ERR_SYNTAX);
    assert_int_equal(e.line, 3);
    assert_int_equal(e.column, 7);
    assert_true(strncmp(e.message, "import: x.svg:3: ", 17) == 0);
    twod_free(&r);
    assert_int_equal(read_svg("", 0, 72, &r, &e), SC_ERR_SYNTAX);
    assert_true(strncmp(e.message, "import: x.svg:", 14) == 0);
    twod_free(&r);
    /* every prefix of a drawing, and bytes of garbage */
    const char *full = "<svg width='10mm' height='10mm' viewBox='0 0 10 10'><path "
                       "d='M0 0 C 1 2 3 4 5 5 A 2 3 0 1 1 9 9 z'/><circle r='2'/></svg>";
    for (size_t n = 0; n < strlen(full); n++) {
        twod_init(&r);
        svg_options o = {72, 0};
        sc_status st = svg_read(full, n, "x.svg", &at, &o, &r, NULL, &e);
        assert_true(st == SC_OK || st == SC_ERR_SYNTAX);
        twod_free(&r);
    }
    unsigned seed = 12345;
    for (int round = 0; round < 200; round++) {
        for (size_t i = 0; i < sizeof text; i++) {
            seed = seed * 1103515245u + 12345u;
            text[i] = (char)(seed >> 16);
        }
        if (round % 2)
            memcpy(text, "<svg><path d='", 14); /* garbage in a path's data */
        twod_init(&r);
        svg_options o = {72, 0};
        sc_status st = svg_read(text, sizeof text, "x.svg", &at, &o, &r, NULL, &e);
        assert_true(st == SC_OK || st == SC_ERR_SYNTAX);
        twod_free(&r);
    }
    /* a page scale that is not finite draws nothing, as OpenSCAD (whose
     * points are not finite there) draws nothing */
    assert_int_equal(read_svg("<svg width='1e300mm' height='1mm' viewBox='0 0 1e-300 1' "
                              "preserveAspectRatio='none'>"
                              "<rect width='1' height='1'/></svg>",
                              0, 72, &r, &e),
                     SC_OK);
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    /* a finite scale that takes coordinates out of range */
    assert_int_equal(read_svg("<svg width='1e300mm' height='1mm' viewBox='0 0 1 1' "
                              "preserveAspectRatio='none'>"
                              "<rect width='1e10' height='1'/></svg>",
                              0, 72, &r, &e),
                     SC_ERR_LIMIT);
    assert_string_equal(e.message,
                        "import: x.svg: the page's scale makes coordinates out of range");
    twod_free(&r);
    /* numbers too large for a double (inf), in an arc and in a stroke */
    assert_int_equal(
        read_svg("<svg><path d='M0 0 A 1e400 1 0 0 1 5 5 L 1e400 0 z'/></svg>", 0, 72, &r,
                 &e),
        SC_ERR_LIMIT);
    twod_free(&r);
    assert_int_equal(
        read_svg("<svg><line x1='0' y1='0' x2='1e300' y2='0'/></svg>", 0, 72, &r, &e),
        SC_ERR_LIMIT);
    twod_free(&r);
    /* a missing file */
    twod_init(&r);
    svg_options o = {72, 0};
    assert_int_equal(svg_read_file("/nonexistent/x.svg", "x.svg", &at, &o, &r, NULL, &e),
                     SC_ERR_IO);
    assert_string_equal(e.message,
                        "import: x.svg: cannot open: No such file or directory");
    twod_free(&r);
}

/* Outlines past Clipper's range (2^46 at OpenSCAD's scale of 2^16), as
 * OpenSCAD 2021.01 imports them (checked with its STL export): each shape
 * is sanitized on its own, where the clipper refuses the outline with such
 * a point and those after it in the shape, and the shapes are then united:
 * three squares of 100 here. */
static void test_range(void **state)
{
    (void)state;
    static const char text[] =
        "<svg width='100mm' height='100mm' viewBox='0 0 100 100'>"
        "<path d='M 0 0 L 10 0 L 10 10 L 0 10 Z'/>"
        "<path d='M 20 0 L 30 0 L 30 10 L 20 10 Z "
        "M 100000000000000 0 L 100000000000010 0 L 100000000000010 10 Z "
        "M 60 0 L 70 0 L 70 10 L 60 10 Z'/>"
        "<path d='M 40 0 L 50 0 L 50 10 L 40 10 Z'/></svg>";
    twod_region r;
    twod_init(&r);
    sc_error e;
    svg_options o = {72, 0};
    svg_refused refused = {7, 7};
    assert_int_equal(svg_read(text, strlen(text), "x.svg", &at, &o, &r, &refused, &e),
                     SC_OK);
    assert_int_equal(refused.shapes, 1);
    assert_int_equal(refused.first, 2);
    assert_true(fabs(twod_area(&r) - 300) < 1e-9);
    twod_free(&r);
    /* none refused */
    twod_init(&r);
    assert_int_equal(svg_read("<svg><rect width='1' height='1'/></svg>", 39, "x.svg", &at,
                              &o, &r, &refused, &e),
                     SC_OK);
    assert_int_equal(refused.shapes, 0);
    assert_int_equal(refused.first, 0);
    twod_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_page),    cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_strokes), cmocka_unit_test(test_transforms),
        cmocka_unit_test(test_numbers), cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
