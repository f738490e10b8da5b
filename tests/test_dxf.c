/* Tests of the DXF reader (src/formats/dxf.c) and of import("x.dxf") in the
 * 2D engine: a hand-written drawing with LINE, LWPOLYLINE, CIRCLE, ARC and
 * an INSERT of a block, each on its own layer, gives the areas computed by
 * hand (points snapped to OpenSCAD's 2^-10 grid); the layer filter, origin
 * and scale; open paths closed; ignored entities named; malformed files
 * read as OpenSCAD 2021.01 reads them, with its warnings (errors with
 * --strict); and every prefix and many one-byte mutations of the drawing
 * read, warn or fail with a message, never crash. */
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

#include "build/build_twod.h"
#include "build/scene.h"
#include "formats/dxf.h"
#include "syntax/parse.h"

/* Layers: "sq" a 10 x 10 square of four LINEs in scrambled order and
 * direction with a CIRCLE of radius 2 inside; "poly" a closed LWPOLYLINE
 * 4 x 3 at (30, 0); "arc" an ARC of radius 1 at (20, 0) from 0 to 180
 * degrees closed by a LINE; "open" an open LWPOLYLINE (0, 20) (4, 20)
 * (0, 23); "ins" an INSERT of block "tri" (the triangle (0, 0) (1, 0)
 * (0, 1)) at (50, 0), x scaled by 2; "sp" a SPLINE. */
static const char drawing[] =
    "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n0\nENDSEC\n"
    "0\nSECTION\n2\nBLOCKS\n"
    "0\nBLOCK\n8\n0\n2\ntri\n10\n0.0\n20\n0.0\n"
    "0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n"
    "0\nLINE\n8\n0\n10\n1\n20\n0\n11\n0\n21\n1\n"
    "0\nLINE\n8\n0\n10\n0\n20\n1\n11\n0\n21\n0\n"
    "0\nENDBLK\n8\n0\n"
    "0\nENDSEC\n"
    "0\nSECTION\n2\nENTITIES\n"
    "0\nLINE\n8\nsq\n10\n10\n20\n10\n11\n0\n21\n10\n"
    "0\nLINE\n8\nsq\n10\n0\n20\n0\n11\n10\n21\n0\n"
    "0\nLINE\n8\nsq\n10\n0\n20\n10\n11\n0\n21\n0\n"
    "0\nLINE\n8\nsq\n10\n10\n20\n0\n11\n10\n21\n10\n"
    "0\nCIRCLE\n8\nsq\n10\n5\n20\n5\n30\n0\n40\n2\n"
    "0\nLWPOLYLINE\n8\npoly\n90\n4\n70\n1\n"
    "10\n30\n20\n0\n10\n34\n20\n0\n10\n34\n20\n3\n10\n30\n20\n3\n"
    "0\nARC\n8\narc\n10\n20\n20\n0\n40\n1\n50\n0\n51\n180\n"
    "0\nLINE\n8\narc\n10\n19\n20\n0\n11\n21\n21\n0\n"
    "0\nLWPOLYLINE\n8\nopen\n90\n3\n70\n0\n"
    "10\n0\n20\n20\n10\n4\n20\n20\n10\n0\n20\n23\n"
    "0\nINSERT\n8\nins\n2\ntri\n10\n50\n20\n0\n41\n2\n"
    "0\nSPLINE\n8\nsp\n10\n0\n20\n0\n"
    "0\nENDSEC\n0\nEOF\n";

/* the ARC at $fn = 8: half an octagon whose 45-degree points snap to
 * 724 / 1024 */
#define HALF_OCTAGON (2.0 * 724.0 / 1024.0)

/* The reader's warnings in the last read: how many, the first as
 * "d.dxf:line:column: warning: message", and whether one changed the
 * drawing; strict_read makes one that changes it the error, as --strict. */
static int warn_count, warn_changes, strict_read;
static char first_warning[600];

static sc_status collect_warning(void *ctx, const sc_location *at, int changes,
                                 const char *message)
{
    if (changes && strict_read)
        return err_set(ctx, SC_ERR_SEMANTIC, at, "%s", message);
    if (!warn_count++)
        snprintf(first_warning, sizeof first_warning, "%s:%d:%d: warning: %s", at->file,
                 at->line, at->column, message);
    warn_changes |= changes;
    return SC_OK;
}

static sc_status read(const char *text, const char *layer, double origin_x, double scale,
                      twod_region *r, char *unsupported, char *message, size_t size)
{
    sc_error e;
    dxf_options o = {8, 12, 2, layer, origin_x, 0, scale, collect_warning, &e};
    warn_count = warn_changes = 0;
    first_warning[0] = 0;
    twod_init(r);
    sc_status st = dxf_read(text, strlen(text), "d.dxf", &o, r, unsupported, &e);
    if (st == SC_OK && r->contour_count) {
        r->sanitized = 0;
        /* past the clipper's range is the build's warning (test_range):
         * a changed drawing can read a value as 5e30 */
        int clip = twod_clip_sanitize(r);
        assert_true(clip == TWOD_CLIP_OK || clip == TWOD_CLIP_RANGE);
    }
    if (st != SC_OK && message)
        sc_error_format(&e, message, size);
    return st;
}

static double area(const char *layer, double origin_x, double scale, uint32_t *contours)
{
    twod_region r;
    char message[600];
    char unsupported[32];
    if (read(drawing, layer, origin_x, scale, &r, unsupported, message, sizeof message) !=
        SC_OK)
        fail_msg("unexpected error: %s", message);
    double a = twod_area(&r);
    if (contours)
        *contours = r.contour_count;
    twod_free(&r);
    return a;
}

static void test_layers(void **state)
{
    (void)state;
    uint32_t contours;
    /* the square with the circle's diamond (radius 2, $fn = 8: an octagon
     * snapped to the grid) as a hole */
    double c = round(2 * sqrt(0.5) * 1024) / 1024; /* the snapped 45-degree point */
    double octagon = 4 * 2 * c;                    /* 8 triangles of 2 * c / 2 */
    assert_true(fabs(area("sq", 0, 1, &contours) - (100 - octagon)) < 1e-12);
    assert_int_equal(contours, 2);
    assert_true(fabs(area("poly", 0, 1, &contours) - 12) < 1e-12);
    assert_int_equal(contours, 1);
    assert_true(fabs(area("arc", 0, 1, &contours) - HALF_OCTAGON) < 1e-12);
    assert_int_equal(contours, 1);
    /* the open polyline is closed by its last edge */
    assert_true(fabs(area("open", 0, 1, &contours) - 6) < 1e-12);
    assert_int_equal(contours, 1);
    /* the block's triangle, x scaled by 2 */
    assert_true(fabs(area("ins", 0, 1, &contours) - 1) < 1e-12);
    assert_int_equal(contours, 1);
    assert_true(fabs(area("no such layer", 0, 1, &contours)) == 0);
    assert_int_equal(contours, 0);
    /* all layers: disjoint shapes, areas add up */
    assert_true(fabs(area(NULL, 0, 1, NULL) -
                     (100 - octagon + 12 + HALF_OCTAGON + 6 + 1)) < 1e-12);
    assert_true(fabs(area("", 0, 1, NULL) - (100 - octagon + 12 + HALF_OCTAGON + 6 + 1)) <
                1e-12);
}

static void test_origin_scale(void **state)
{
    (void)state;
    twod_region r;
    char message[600];
    assert_int_equal(read(drawing, "poly", 30, 2, &r, NULL, message, sizeof message),
                     SC_OK);
    assert_true(fabs(twod_area(&r) - 48) < 1e-12);
    double min_x = INFINITY, max_x = -INFINITY;
    for (uint32_t i = 0; i < r.point_count; i++) {
        min_x = fmin(min_x, r.xy[2 * i]);
        max_x = fmax(max_x, r.xy[2 * i]);
    }
    assert_true(min_x == 0 && max_x == 8);
    twod_free(&r);
    /* the radius scales with the drawing */
    assert_true(fabs(area("arc", 0, 2, NULL) - 4 * HALF_OCTAGON) < 1e-12);
}

static void test_unsupported(void **state)
{
    (void)state;
    twod_region r;
    char unsupported[32];
    assert_int_equal(read(drawing, NULL, 0, 1, &r, unsupported, NULL, 0), SC_OK);
    assert_string_equal(unsupported, "SPLINE");
    twod_free(&r);
    assert_int_equal(read(drawing, "sq", 0, 1, &r, unsupported, NULL, 0), SC_OK);
    assert_string_equal(unsupported, "");
    twod_free(&r);
}

/* Two segments meeting at one end and a third alone: the open paths come
 * first, each from the lowest segment with a free end. */
static void test_open_paths(void **state)
{
    (void)state;
    const char *text = "0\nSECTION\n2\nENTITIES\n"
                       "0\nLINE\n10\n0\n20\n0\n11\n2\n21\n0\n"
                       "0\nLINE\n10\n2\n20\n0\n11\n2\n21\n2\n"
                       "0\nLINE\n10\n5\n20\n5\n11\n6\n21\n5\n"
                       "0\nENDSEC\n0\nEOF\n";
    twod_region r;
    assert_int_equal(read(text, NULL, 0, 1, &r, NULL, NULL, 0), SC_OK);
    /* the triangle (0, 0) (2, 0) (2, 2); the lone segment has no area */
    assert_true(fabs(twod_area(&r) - 2) < 1e-12);
    twod_free(&r);
}

/* OpenSCAD's order of open paths, where taking one path leaves a lower
 * segment with a free end: segment 1 (Q Y) is shared at both ends until
 * the path from segment 2's free end R takes segment 0 at Q; the next path
 * must start from segment 1 at Q, not from segment 4's free end H. */
static void test_open_path_order(void **state)
{
    (void)state;
    const char *text = "0\nSECTION\n2\nENTITIES\n"
                       "0\nLINE\n10\n1\n20\n0\n11\n1\n21\n1\n"   /* 0: Q D */
                       "0\nLINE\n10\n1\n20\n0\n11\n2\n21\n-1\n"  /* 1: Q Y */
                       "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n"   /* 2: R Q */
                       "0\nLINE\n10\n1\n20\n1\n11\n2\n21\n1\n"   /* 3: D F */
                       "0\nLINE\n10\n2\n20\n-1\n11\n3\n21\n-1\n" /* 4: Y H */
                       "0\nENDSEC\n0\nEOF\n";
    dxf_options o = {0, 12, 2, NULL, 0, 0, 1, NULL, NULL};
    sc_error e;
    twod_region r;
    twod_init(&r);
    assert_int_equal(dxf_read(text, strlen(text), "d.dxf", &o, &r, NULL, &e), SC_OK);
    assert_int_equal(r.contour_count, 2);
    /* R Q D F reversed, then Q Y H reversed */
    static const double want[] = {2, 1, 1, 1, 1, 0, 0, 0, 3, -1, 2, -1, 1, 0};
    assert_int_equal(r.point_count, 7);
    assert_int_equal(r.start[1], 4);
    for (int i = 0; i < 14; i++)
        assert_true(r.xy[i] == want[i]);
    twod_free(&r);
}

static void check_error(const char *text, const char *expected)
{
    twod_region r;
    char message[600];
    assert_int_not_equal(read(text, NULL, 0, 1, &r, NULL, message, sizeof message),
                         SC_OK);
    assert_string_equal(message, expected);
    twod_free(&r);
}

/* text reads with count warnings, the first expected; with --strict it
 * is that warning's error. */
static void check_warning(const char *text, const char *expected, int count)
{
    twod_region r;
    char message[600];
    if (read(text, NULL, 0, 1, &r, NULL, message, sizeof message) != SC_OK)
        fail_msg("unexpected error: %s", message);
    twod_free(&r);
    assert_string_equal(first_warning, expected);
    assert_int_equal(warn_count, count);
    assert_true(warn_changes);
    strict_read = 1;
    char error[600];
    const char *w = strstr(expected, ": warning: ");
    assert_non_null(w);
    snprintf(error, sizeof error, "%.*s: error: %s", (int)(w - expected), expected,
             w + strlen(": warning: "));
    check_error(text, error);
    strict_read = 0;
}

/* Where OpenSCAD 2021.01 warns and reads on, the reader does too, with
 * OpenSCAD's warning at the DXF line; --strict makes it the error. */
static void test_errors(void **state)
{
    (void)state;
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nx\n10\nabc\n",
                  "d.dxf:10:1: warning: Illegal value 'abc' (group code 10): OpenSCAD "
                  "skips it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1e999\n",
                  "d.dxf:8:1: warning: Illegal value '1e999' (group code 10): OpenSCAD "
                  "skips it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0x10\n",
                  "d.dxf:8:1: warning: Illegal value '0x10' (group code 10): OpenSCAD "
                  "skips it",
                  1);
    check_warning("0\nSECTION\nzz\nENTITIES\n",
                  "d.dxf:3:1: warning: Illegal ID 'zz': OpenSCAD reads no further in "
                  "the DXF file",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n70\n1.5\n",
                  "d.dxf:8:1: warning: Illegal value '1.5' (group code 70): OpenSCAD "
                  "skips it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1\n20\n1\n0\nEOF\n",
                  "d.dxf:6:1: warning: Not enough input values for EOF: OpenSCAD leaves "
                  "out the LINE that lacks them, and reads the values after it as more "
                  "of it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n40\n1\n0\nEOF\n",
                  "d.dxf:6:1: warning: Not enough input values for EOF: OpenSCAD leaves "
                  "out the CIRCLE that lacks them, and reads the values after it as "
                  "more of it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n10\n1\n20\n1\n10\n2\n0\nEOF\n",
                  "d.dxf:6:1: warning: Not enough input values for EOF: OpenSCAD leaves "
                  "out the LWPOLYLINE that lacks them, and reads the values after it as "
                  "more of it",
                  1);
    check_warning("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n70\n1\n0\nEOF\n",
                  "d.dxf:6:1: warning: Not enough input values for EOF: OpenSCAD leaves "
                  "out the LWPOLYLINE that lacks them, and reads the values after it as "
                  "more of it",
                  1);
    check_error(
        "0\nSECTION\n2\nENTITIES\n0\nARC\n10\n0\n20\n0\n40\n1\n50\n0\n51\n-1e300\n"
        "0\nEOF\n",
        "d.dxf:6:1: error: DXF ARC angles are too far apart");
    /* a start 1e6 degrees past the end: 2778 turns added, as OpenSCAD adds
     * them (it draws the arc) */
    {
        twod_region r;
        char message[600];
        assert_int_equal(
            read("0\nSECTION\n2\nENTITIES\n0\nARC\n10\n0\n20\n0\n40\n1\n50\n1000000\n"
                 "51\n0\n0\nEOF\n",
                 NULL, 0, 1, &r, NULL, message, sizeof message),
            SC_OK);
        assert_true(r.point_count > 0);
        twod_free(&r);
    }
    check_error(
        "0\nSECTION\n2\nENTITIES\n0\nARC\n10\n0\n20\n0\n40\n1\n50\n0\n51\n1e9\n"
        "0\nEOF\n",
        "d.dxf:6:1: error: too many line segments in a DXF drawing (limit is 50000)");
    /* blank lines at the end end the reading, with OpenSCAD's warning
     * where the file goes on after them, which draws nothing more: not an
     * error with --strict */
    twod_region r;
    assert_int_equal(read("0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n\n\n \n", NULL, 0,
                          1, &r, NULL, NULL, 0),
                     SC_OK);
    assert_string_equal(first_warning,
                        "d.dxf:9:1: warning: Illegal ID '': OpenSCAD reads "
                        "no further in the DXF file");
    assert_false(warn_changes);
    twod_free(&r);
    assert_int_equal(read("0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n\n", NULL, 0, 1,
                          &r, NULL, NULL, 0),
                     SC_OK);
    assert_int_equal(warn_count, 0); /* the text ends in the blank line's pair */
    twod_free(&r);
}

/* The area of text read at $fn = 8, with warn_count warnings. */
static double text_area(const char *text)
{
    twod_region r;
    char message[600];
    if (read(text, NULL, 0, 1, &r, NULL, message, sizeof message) != SC_OK)
        fail_msg("unexpected error: %s", message);
    double a = twod_area(&r);
    twod_free(&r);
    return a;
}

/* text_area after OpenSCAD's sanitize (even-odd), as the import does */
static double text_area_filled(const char *text)
{
    twod_region r;
    char message[600];
    if (read(text, NULL, 0, 1, &r, NULL, message, sizeof message) != SC_OK)
        fail_msg("unexpected error: %s", message);
    assert_int_equal(twod_clip_sanitize(&r), TWOD_CLIP_OK);
    double a = twod_area(&r);
    twod_free(&r);
    return a;
}

#define SQUARE_AT(x)                                                                     \
    "0\nLINE\n10\n" x "\n20\n0\n11\n" x "9\n21\n0\n"                                     \
    "0\nLINE\n10\n" x "9\n20\n0\n11\n" x "9\n21\n10\n"                                   \
    "0\nLINE\n10\n" x "9\n20\n10\n11\n" x "\n21\n10\n"                                   \
    "0\nLINE\n10\n" x "\n20\n10\n11\n" x "\n21\n0\n"

/* OpenSCAD 2021.01's DxfData: a value that is not a number skips its
 * pair; an entity short of points is left out and the next one's values
 * add to its own; a code that is not an integer ends the reading; nan and
 * inf are numbers. */
static void test_lenient(void **state)
{
    (void)state;
    static const char head[] = "0\nSECTION\n2\nENTITIES\n";
    char text[2000];
    /* squares 0 to 9 and 10 to 19 (x "1" gives 1 and 19: a 10 x 18 box) */
    snprintf(text, sizeof text, "%s%s0\nEOF\n", head, SQUARE_AT("1"));
    double box = text_area(text);
    assert_true(box == 180);
    assert_int_equal(warn_count, 0);
    /* a bad value before the good one: skipped, the square drawn */
    snprintf(text, sizeof text, "%s0\nLINE\n10\n1d1\n%s0\nEOF\n", head,
             SQUARE_AT("1") + strlen("0\nLINE\n"));
    assert_true(text_area(text) == box);
    assert_int_equal(warn_count, 1);
    assert_string_equal(first_warning, "d.dxf:8:1: warning: Illegal value '1d1' (group "
                                       "code 10): OpenSCAD skips it");
    /* a CIRCLE without its centre carries over: the LINE's first point is
     * its centre */
    snprintf(text, sizeof text,
             "%s0\nCIRCLE\n40\n2\n0\nLINE\n10\n5\n20\n5\n11\n50\n21\n50\n0\nEOF\n", head);
    double carried = text_area(text);
    assert_int_equal(warn_count, 1);
    assert_non_null(strstr(first_warning, "d.dxf:6:1: warning: Not enough input values "
                                          "for LINE: OpenSCAD leaves out the CIRCLE"));
    snprintf(text, sizeof text, "%s0\nCIRCLE\n10\n5\n20\n5\n40\n2\n0\nEOF\n", head);
    double circle = text_area(text);
    assert_true(circle > 11 && carried == circle);
    /* six LINEs, one drawn twice (once each way), two points met by three:
     * one closed path A B C E D A D, which OpenSCAD's fixup_path_direction
     * turns, so that its contour is A B C E D: even-odd, 1010/23 (as
     * openscad draws it, 43.91304016 on its clipper's grid; the contour
     * D A D E C B is 72) */
    snprintf(
        text, sizeof text,
        "%s0\nLINE\n10\n0\n20\n-6\n11\n6\n21\n2\n0\nLINE\n10\n6\n20\n2\n11\n10\n21\n0\n"
        "0\nLINE\n10\n2\n20\n8\n11\n0\n21\n-10\n0\nLINE\n10\n0\n20\n-10\n11\n10\n21\n0\n"
        "0\nLINE\n10\n2\n20\n8\n11\n0\n21\n-6\n0\nLINE\n10\n0\n20\n-6\n11\n2\n21\n8\n"
        "0\nEOF\n",
        head);
    /* within the clipper's grid (2^-16) along the outline's 55 units */
    assert_true(fabs(text_area_filled(text) - 1010.0 / 23) < 55 * 0x1p-16);
    assert_int_equal(warn_count, 0);
    /* a LWPOLYLINE with an x value too few: the edges it has, then left
     * out; the next entity adds its points to the polyline, whose path
     * passes (0, 0) twice: OpenSCAD's fixup_path_direction turns it, and
     * the contour drops the other (0, 0), leaving the triangle (0, 0),
     * (0, 3), (4, 3) with a spike to (4, 0): 6, as openscad draws it */
    snprintf(text, sizeof text,
             "%s0\nLWPOLYLINE\n70\n1\n10\n0\n20\n0\n10\n4\n20\n0\n20\n3\n"
             "0\nPOINT\n10\n4\n10\n0\n20\n3\n0\nEOF\n",
             head);
    assert_true(text_area(text) == 6);
    assert_int_equal(warn_count, 1);
    /* a blank line ends the reading: the second square is not read */
    snprintf(text, sizeof text, "%s%s0\nENDSEC\n\n0\nSECTION\n2\nENTITIES\n%s0\nEOF\n",
             head, SQUARE_AT("1"), SQUARE_AT("5"));
    assert_true(text_area(text) == box);
    assert_string_equal(first_warning, "d.dxf:47:1: warning: Illegal ID '': OpenSCAD "
                                       "reads no further in the DXF file");
    assert_true(warn_changes);
    /* text after 0 EOF is read */
    snprintf(text, sizeof text, "%s%s%s0\nEOF\n", head, SQUARE_AT("1"), SQUARE_AT("5"));
    double both = text_area(text);
    assert_true(both > box);
    snprintf(text, sizeof text, "%s%s0\nEOF\n0\nSECTION\n2\nENTITIES\n%s0\nEOF\n", head,
             SQUARE_AT("1"), SQUARE_AT("5"));
    assert_true(text_area(text) == both);
    assert_int_equal(warn_count, 0);
    /* a last code that is not an integer: the end, no warning */
    snprintf(text, sizeof text, "%s%s0\nEOF\ngarbage\n", head, SQUARE_AT("1"));
    assert_true(text_area(text) == box);
    assert_int_equal(warn_count, 0);
    /* CR line ends: one line, not a code, the last: nothing, no warning */
    assert_true(text_area("0\rSECTION\r2\rENTITIES\r0\rLINE\r10\r0\r20\r0\r") == 0);
    assert_int_equal(warn_count, 0);
    /* nan and inf are numbers: an ARC whose segment count is not a number
     * draws nothing, with no warning */
    snprintf(text, sizeof text,
             "%s%s0\nARC\n10\n0\n20\n0\n40\n1\n50\nnan\n51\n-INF\n0\nEOF\n", head,
             SQUARE_AT("1"));
    assert_true(text_area(text) == box);
    assert_int_equal(warn_count, 0);
    /* what boost::lexical_cast<double> reads */
    static const char *const good[] = {"nan", "-NaN", "nan(x1)", "inf",    "+Infinity",
                                       "1.",  ".5",   "+1e+1",   "1e-400", "007"};
    static const char *const bad[] = {"1e400", "1d1",   "0x0A", "10abc", "1 0",
                                      "nan(",  "infin", "+-1",  ".",     "1e",
                                      "e5",    "1.0.0", ""};
    for (size_t i = 0; i < sizeof good / sizeof *good + sizeof bad / sizeof *bad; i++) {
        int ok = i < sizeof good / sizeof *good;
        const char *v = ok ? good[i] : bad[i - sizeof good / sizeof *good];
        snprintf(text, sizeof text, "%s0\nLINE\n10\n%s\n20\n0\n11\n1\n21\n1\n0\nEOF\n",
                 head, v);
        text_area(text);
        if (warn_count != (ok ? 0 : 2))
            fail_msg("value '%s': %d warnings", v, warn_count);
    }
    /* past DXF_MAX_WARNINGS the warnings are counted in one more */
    size_t used = (size_t)snprintf(text, sizeof text, "%s", head);
    for (int i = 0; i < 150; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "40\nx\n");
    snprintf(text + used, sizeof text - used, "0\nEOF\n");
    text_area(text);
    assert_int_equal(warn_count, DXF_MAX_WARNINGS + 1);
    /* what boost::lexical_cast<int> reads, as a code */
    static const char *const codes[] = {"+0", "-0", "0000", "2147483648", "1.0", "+"};
    for (size_t i = 0; i < sizeof codes / sizeof *codes; i++) {
        snprintf(text, sizeof text, "%s%s\nEOF\n0\nEOF\n", head, codes[i]);
        text_area(text);
        assert_int_equal(warn_count, i < 3 ? 0 : 1);
    }
}

/* What a changed drawing must do: read without a word, warn (or fail), or
 * either (not derived). */
enum { EITHER, READS, FAILS };

/* Group codes whose value the reader parses: a finite number (10-16, 20-26,
 * 40-42, 50, 51) or an integer (70). Any other value is kept as text. */
static int parsed_code(long code)
{
    return (code >= 10 && code <= 16) || (code >= 20 && code <= 26) ||
           (code >= 40 && code <= 42) || code == 50 || code == 51 || code == 70;
}

/* For each byte of the drawing: the line's role, its group code's kind,
 * and where it ends. The drawing alternates code and value lines. */
typedef struct byte_role {
    int code_line; /* on a group code line (its newline included) */
    int parsed;    /* on a code line or value line of a parsed_code */
    int newline;
    size_t line_end; /* offset of the newline ending this line */
} byte_role;

static void byte_roles(byte_role *role, size_t n)
{
    long code = 0;
    size_t line = 0;
    for (size_t a = 0; a < n; line++) {
        size_t e = a;
        while (drawing[e] != '\n')
            e++;
        if (line % 2 == 0)
            code = strtol(drawing + a, NULL, 10);
        for (size_t i = a; i <= e; i++)
            role[i] = (byte_role){line % 2 == 0, parsed_code(code), i == e, e};
        a = e + 1;
    }
}

/* The prefix of length cut. Entities take effect at the next code 0, so a
 * prefix acts only on complete entities and is then cut inside the last
 * pair. Every shorter code is still an integer, every value's prefix is
 * still a number ("0.0" gives "0." and "0"), and no shorter code is parsed
 * (1, 2, 4, 5, 7). So it warns (an empty value is an Illegal value)
 * exactly when a parsed code stands complete
 * without its value: cut right after the code's digits or after its
 * newline, 2 prefixes per parsed code. */
static int prefix_expect(const byte_role *role, size_t cut)
{
    if (cut == 0)
        return READS;
    const byte_role *r = &role[cut - 1];
    int code_done = r->code_line && r->parsed &&
                    (r->newline || (r + 1)->newline); /* digits or newline last */
    return code_done ? FAILS : READS;
}

/* Byte i replaced by 'A', which is neither a digit nor part of a number:
 *   on a code line, the code is not an integer, or (the newline) the code
 *   and its value make one line that is not (Illegal ID), except the
 *   newline of the last code: that line is then the last, which ends the
 *   reading without a word, as in OpenSCAD;
 *   on a parsed value, the value is not a number, or (the newline) the
 *   value and the next code make one line that is not;
 *   inside any other value (a name, a layer, an entity, a section), the
 *   text no longer matches what the reader looks for: an entity or section
 *   not recognised is ignored, a block not found inserts nothing, and no
 *   layer filter is set, so the drawing reads;
 *   the newline of any other value shifts every later line between code and
 *   value: not derived here. */
static int mutation_expect(const byte_role *role, size_t i)
{
    size_t n = strlen(drawing);
    if (role[i].code_line && role[i].newline && role[i + 1].line_end == n - 1)
        return READS;
    if (role[i].code_line || role[i].parsed)
        return FAILS;
    return role[i].newline ? EITHER : READS;
}

/* Reads text; checks the outcome against expect, and that a warning or a
 * failure has a message at a line of the drawing. Returns 1 when it warned
 * or failed. */
static int read_checked(const char *text, int expect, const char *what, size_t at)
{
    twod_region r;
    char message[600] = "";
    int failed = read(text, NULL, 0, 1, &r, NULL, message, sizeof message) != SC_OK;
    twod_free(&r);
    if (!failed && warn_count) {
        failed = 1;
        snprintf(message, sizeof message, "%s", first_warning);
    }
    if (failed)
        assert_true(strncmp(message, "d.dxf:", 6) == 0);
    if (expect != EITHER && failed != (expect == FAILS))
        fail_msg("%s at byte %zu: expected to %s, %s %s", what, at,
                 expect == FAILS ? "warn" : "read", failed ? "warned:" : "read", message);
    return failed;
}

/* Every prefix of the drawing, and the drawing with each byte replaced by
 * each of a few others, reads or fails with a message; where the outcome
 * follows from the reader's rules (prefixes, 'A') it is the one derived. */
static void test_malformed(void **state)
{
    (void)state;
    size_t n = strlen(drawing);
    char *text = malloc(n + 1);
    byte_role *role = malloc(n * sizeof *role);
    assert_non_null(text);
    assert_non_null(role);
    byte_roles(role, n);
    size_t parsed_codes = 0;
    for (size_t i = 0; i < n; i++)
        parsed_codes += role[i].code_line && role[i].parsed && role[i].newline;

    size_t prefix_failures = 0;
    for (size_t cut = 0; cut <= n; cut++) {
        memcpy(text, drawing, cut);
        text[cut] = 0;
        prefix_failures += read_checked(text, prefix_expect(role, cut), "prefix", cut);
    }
    assert_int_equal(prefix_failures, 2 * parsed_codes);

    static const char replacements[] = {'\n', '0', '9', '-', 'e', ' ', 'A', '\r'};
    size_t a_failures = 0, a_expected = 0, a_either = 0;
    for (size_t i = 0; i < n; i++) {
        for (size_t k = 0; k < sizeof replacements; k++) {
            memcpy(text, drawing, n + 1);
            text[i] = replacements[k];
            int expect = replacements[k] == 'A' ? mutation_expect(role, i) : EITHER;
            int failed = read_checked(text, expect, "'A'", i);
            if (replacements[k] == 'A' && expect != EITHER) {
                a_failures += (size_t)failed;
                a_expected += expect == FAILS;
            }
            a_either += replacements[k] == 'A' && expect == EITHER;
        }
    }
    print_message("%zu parsed codes, %zu prefixes warn; 'A': %zu of %zu derived warn, "
                  "%zu not derived\n",
                  parsed_codes, prefix_failures, a_failures, a_expected, a_either);
    assert_int_equal(a_failures, a_expected);
    free(role);
    free(text);
}

/* ---- import() in the 2D engine ---- */

static const char *work_dir(void)
{
    mkdir(SPANCAST_TEST_WORK, 0777);
    return SPANCAST_TEST_WORK;
}

/* The region of csg's 2D children (d.dxf is the drawing above), into r;
 * message: the first warning or the error; strict as --strict. */
static sc_status import_region_as(const char *csg, int strict, twod_region *r,
                                  char *message, size_t size)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/d.dxf", work_dir());
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs(drawing, f);
    fclose(f);
    char file[1024];
    snprintf(file, sizeof file, "%s/m.csg", work_dir());
    parse_tree *tree = NULL;
    sc_error e;
    assert_int_equal(parse_text(file, csg, strlen(csg), &tree, &e), SC_OK);
    build_notes notes = {NULL, 0, 0, 0};
    build_ctx c = {.file = file,
                   .csg = NULL,
                   .error = &e,
                   .faithful = 1,
                   .strict = strict,
                   .note = NULL,
                   .notes = &notes};
    twod_init(r);
    model *lowered = NULL;
    assert_int_equal(model_lower_twod(file, tree->first, &lowered, &e), SC_OK);
    sc_status st = build_twod_children(&c, lowered->first, r);
    message[0] = 0;
    if (st == SC_OK && notes.count) {
        /* the first warning, "m.csg:line:col: message" */
        const sc_error *w = &notes.items[0];
        snprintf(message, size, "m.csg:%d:%d: %s", w->line, w->column, w->message);
    }
    free(notes.items);
    if (st != SC_OK) {
        /* the work folder's path is not part of the expected text */
        char full[1200];
        sc_error_format(&e, full, sizeof full);
        const char *tail = strstr(full, "m.csg:");
        snprintf(message, size, "%s", tail ? tail : full);
    }
    model_free(lowered);
    parse_tree_free(tree);
    return st;
}

static sc_status import_region(const char *csg, twod_region *r, char *message,
                               size_t size)
{
    return import_region_as(csg, 0, r, message, size);
}

/* Writes the DXF drawing of count squares of side 10, one at each
 * (x[k], 0), as four LINEs each, into the work folder as name. */
static void write_squares(const char *name, const double *x, int count)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs("0\nSECTION\n2\nENTITIES\n", f);
    for (int k = 0; k < count; k++) {
        double c[5][2] = {
            {x[k], 0}, {x[k] + 10, 0}, {x[k] + 10, 10}, {x[k], 10}, {x[k], 0}};
        for (int i = 0; i < 4; i++)
            fprintf(f, "0\nLINE\n8\n0\n10\n%.17g\n20\n%.17g\n11\n%.17g\n21\n%.17g\n",
                    c[i][0], c[i][1], c[i + 1][0], c[i + 1][1]);
    }
    fputs("0\nENDSEC\n0\nEOF\n", f);
    fclose(f);
}

/* Outlines past Clipper's range (2^46 at OpenSCAD's scale of 2^16), as
 * OpenSCAD 2021.01 imports them, each case checked with its DXF export:
 * its sanitize refuses the first outline with such a point, with the
 * warning, and leaves out those after it; an outline whose points the DXF
 * grid merges into fewer than 3 (past 2^53 they all go to one index) is
 * skipped untested. */
static void test_range(void **state)
{
    (void)state;
    static const char csg[] = "linear_extrude(height = 1) { import(file = \"r.dxf\"); }";
    twod_region r;
    char message[1200];
    const double second[] = {0, 8e13, 20};
    write_squares("r.dxf", second, 3);
    assert_int_equal(import_region(csg, &r, message, sizeof message), SC_OK);
    assert_true(twod_area(&r) == 100);
    assert_string_equal(message, "m.csg:1:30: Range check failed for polygon. skipping "
                                 "(outline 2 of the drawing and those after it, as "
                                 "OpenSCAD leaves them out; --strict makes it an error)");
    twod_free(&r);
    assert_int_equal(import_region_as(csg, 1, &r, message, sizeof message), SC_ERR_LIMIT);
    assert_string_equal(message, "m.csg:1:30: error: import: outline 2 has coordinates "
                                 "out of the clipper's range");
    twod_free(&r);
    const double first[] = {-8e13, 0};
    write_squares("r.dxf", first, 2);
    assert_int_equal(import_region(csg, &r, message, sizeof message), SC_OK);
    assert_int_equal(r.contour_count, 0);
    assert_non_null(strstr(message, "(outline 1 of the drawing and those after it"));
    twod_free(&r);
    /* just below the range: kept, with no warning */
    const double below[] = {0, 7e13};
    write_squares("r.dxf", below, 2);
    assert_int_equal(import_region(csg, &r, message, sizeof message), SC_OK);
    assert_int_equal(r.contour_count, 2);
    assert_string_equal(message, "");
    twod_free(&r);
    /* past 2^53 the points of the square at 1e300 go to one index in x,
     * so its outline is a segment, skipped untested, without a warning */
    const double far[] = {0, 1e300, 20};
    write_squares("r.dxf", far, 3);
    assert_int_equal(import_region(csg, &r, message, sizeof message), SC_OK);
    assert_true(twod_area(&r) == 200);
    assert_string_equal(message, "");
    twod_free(&r);
}

static void test_import(void **state)
{
    (void)state;
    twod_region r;
    char message[1200];
    sc_status st = import_region("linear_extrude(height = 1) { import(file = \"d.dxf\", "
                                 "layer = \"poly\", origin = "
                                 "[30, 0], scale = 2, convexity = 1, $fn = 8, $fa = 12, "
                                 "$fs = 2, timestamp = 0); }",
                                 &r, message, sizeof message);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", message);
    assert_true(fabs(twod_area(&r) - 48) < 1e-12);
    twod_free(&r);
    /* the old file forms of the extrusions, as OpenSCAD 2021.01 still reads
     * them: the same drawing, linear_extrude's scale [x, y] scaling it by x */
    st = import_region(
        "linear_extrude(file = \"d.dxf\", layer = \"poly\", origin = [30, 0], "
        "timestamp = 0, height = 1, center = false, convexity = 1, scale = "
        "[2, 2], $fn = 8, $fa = 12, $fs = 2) { square(100); }",
        &r, message, sizeof message);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", message);
    assert_true(fabs(twod_area(&r) - 48) < 1e-12);
    twod_free(&r);
    st = import_region(
        "rotate_extrude(file = \"d.dxf\", layer = \"poly\", origin = [30, 0], "
        "scale = -1, timestamp = 0, angle = 360, convexity = 2);",
        &r, message, sizeof message);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", message);
    assert_true(fabs(twod_area(&r) - 12) < 1e-12); /* a scale <= 0 is 1 */
    twod_free(&r);
    /* union with a square overlapping the half disc's flat side */
    st = import_region("linear_extrude(height = 1) { import(file = \"d.dxf\", layer = "
                       "\"arc\", $fn = 8); multmatrix([[1, 0, 0, 19], [0, 1, 0, -1], [0, "
                       "0, 1, 0], [0, 0, 0, 1]]) { square([2, 1]); } }",
                       &r, message, sizeof message);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", message);
    assert_true(fabs(twod_area(&r) - (HALF_OCTAGON + 2)) < 1e-12);
    twod_free(&r);
    assert_int_equal(import_region("linear_extrude(height = 1) { import(file = "
                                   "\"missing.dxf\"); }",
                                   &r, message, sizeof message),
                     SC_OK);
    /* as OpenSCAD: a warning, and nothing imported */
    assert_true(strstr(message, "m.csg:1:30: Can't open DXF file '") == message);
    assert_non_null(
        strstr(message, "missing.dxf': No such file or directory; the import is empty"));
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    /* a missing SVG file too */
    assert_int_equal(
        import_region("linear_extrude(height = 1) { import(file = \"a.svg\"); }", &r,
                      message, sizeof message),
        SC_OK);
    assert_true(strstr(message, "m.csg:1:30: Can't open SVG file '") == message);
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    /* a 3D file is a 3D child, read (here it is missing, with OpenSCAD's
     * warning), then left out as OpenSCAD leaves it out */
    assert_int_equal(import_region("rotate_extrude() { import(file = \"a.stl\"); }", &r,
                                   message, sizeof message),
                     SC_OK);
    assert_true(strstr(message, "m.csg:1:34: Can't open import file '") == message);
    assert_int_equal(r.contour_count, 0);
    twod_free(&r);
    /* a layer that is not a string is its text, as OpenSCAD 2021.01 takes
     * it: layer = 3 is layer "3" */
    twod_region named;
    char named_message[1024];
    assert_int_equal(
        import_region(
            "linear_extrude(height = 1) { import(file = \"d.dxf\", layer = 3); }", &r,
            message, sizeof message),
        SC_OK);
    assert_int_equal(
        import_region(
            "linear_extrude(height = 1) { import(file = \"d.dxf\", layer = \"3\"); }",
            &named, named_message, sizeof named_message),
        SC_OK);
    assert_string_equal(message, named_message);
    assert_int_equal(r.contour_count, named.contour_count);
    assert_true(twod_area(&r) == twod_area(&named));
    twod_free(&named);
    twod_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layers),          cmocka_unit_test(test_origin_scale),
        cmocka_unit_test(test_unsupported),     cmocka_unit_test(test_open_paths),
        cmocka_unit_test(test_open_path_order), cmocka_unit_test(test_errors),
        cmocka_unit_test(test_lenient),         cmocka_unit_test(test_malformed),
        cmocka_unit_test(test_import),          cmocka_unit_test(test_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
