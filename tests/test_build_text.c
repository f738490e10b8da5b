/* Tests of text() (src/build/build_text.c): OpenSCAD's layout (kerning,
 * alignment, size scaling, spacing), the outline prism of real glyphs
 * against its own membership, faithful polygons that lie on the exact
 * curves, and the builder's messages for bad arguments and missing
 * fonts. Needs the Liberation fonts (fonts-liberation2). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "build/build.h"
#include "build/build_text.h"
#include "build/scene.h"
#include "csg/csg.h"
#include "csg/prim_outline.h"
#include "syntax/parse.h"
#include "test_util.h"

/* ---- layout through text_shape_build ---- */

typedef struct laid {
    parse_tree *tree;
    model *model; /* the text node, lowered in the 2D context */
    text_shape shape;
    sc_error note;
} laid;

static void lay_out(laid *l, const char *node)
{
    sc_error e;
    memset(l, 0, sizeof *l);
    assert_int_equal(parse_text("t.csg", node, strlen(node), &l->tree, &e), SC_OK);
    assert_int_equal(model_lower_twod("t.csg", l->tree->first, &l->model, &e), SC_OK);
    build_ctx c = {.file = "t.csg",
                   .csg = NULL,
                   .error = &e,
                   .faithful = 0,
                   .note = NULL,
                   .notes = NULL};
    assert_int_equal(text_shape_build(&c, l->model->first, &l->shape, &l->note), SC_OK);
}

static void done(laid *l)
{
    text_shape_free(&l->shape);
    model_free(l->model);
    parse_tree_free(l->tree);
}

/* The x extent of the text's glyph boxes (control points, in the text's
 * frame). */
static void extent(const text_shape *s, double *x0, double *x1, double *y0, double *y1)
{
    *x0 = *y0 = INFINITY;
    *x1 = *y1 = -INFINITY;
    for (uint32_t g = 0; g < s->glyph_count; g++)
        for (uint32_t i = s->contour_start[s->glyph_start[g]];
             i < s->contour_start[s->glyph_start[g + 1]]; i++)
            for (uint32_t j = 0; j <= s->segs[i].degree; j++) {
                double x =
                    s->size * ((s->segs[i].x[j] + s->offset[2 * g]) + s->advance[2 * g]);
                double y = s->size * ((s->segs[i].y[j] + s->offset[2 * g + 1]) +
                                      s->advance[2 * g + 1]);
                *x0 = fmin(*x0, x);
                *x1 = fmax(*x1, x);
                *y0 = fmin(*y0, y);
                *y1 = fmax(*y1, y);
            }
}

/* sc_font_register, as OpenSCAD's use <font.ttf>: MarVoSym (a symbol font
 * no Debian package installs, tests/data/fonts) is not found by name
 * before it, and laid out from its own glyphs after it, its characters
 * below 0x100 taken from the 0xf000 page, where its symbol charmap has
 * them (OpenSCAD's FreetypeRenderer): glyphs with outlines of another
 * width, and no warning. */
static void test_registered_font(void **state)
{
    (void)state;
    static const char node[] = "text(text = \"0A\", font = \"MarVoSym\");";
    laid before;
    lay_out(&before, node);
    assert_non_null(strstr(before.note.message, "'MarVoSym' was not found"));
    sc_error e;
    assert_int_equal(sc_font_register(NULL, &e), SC_ERR_ARGUMENT);
    assert_int_equal(
        sc_font_register(SPANCAST_SOURCE_DIR "/tests/data/fonts/OFL.txt", &e), SC_ERR_IO);
    assert_non_null(strstr(e.message, "OFL.txt': not a font fontconfig can read"));
    assert_int_equal(
        sc_font_register(SPANCAST_SOURCE_DIR "/tests/data/fonts/none.ttf", &e),
        SC_ERR_IO);
    assert_non_null(strstr(e.message, "none.ttf': No such file or directory"));
    assert_int_equal(
        sc_font_register(SPANCAST_SOURCE_DIR "/tests/data/fonts/marvosym.ttf", &e),
        SC_OK);
    laid after;
    lay_out(&after, node);
    assert_string_equal(after.note.message, "");
    assert_int_equal(after.shape.glyph_count, 2);
    for (uint32_t g = 0; g < 2; g++) /* both glyphs have outlines */
        assert_true(after.shape.glyph_start[g + 1] > after.shape.glyph_start[g]);
    double b0, b1, a0, a1, y0, y1;
    extent(&before.shape, &b0, &b1, &y0, &y1);
    extent(&after.shape, &a0, &a1, &y0, &y1);
    assert_true(fabs((a1 - a0) - (b1 - b0)) > 0.05 * (b1 - b0)); /* another font */
    done(&before);
    done(&after);
}

/* halign = "right" shifts by the whole advance width: the first glyph's
 * offset is minus the width (its own HarfBuzz offset is 0 here). */
static double width_of(const char *text)
{
    char node[256];
    snprintf(node, sizeof node, "text(text = \"%s\", halign = \"right\");", text);
    laid l;
    lay_out(&l, node);
    assert_true(l.shape.glyph_count >= 1);
    double w = -l.shape.offset[0];
    done(&l);
    return w;
}

static void test_kerning_and_alignment(void **state)
{
    (void)state;
    double wa = width_of("A"), wv = width_of("V"), wav = width_of("AV");
    double wh = width_of("HH");
    print_message("advance widths (units of size): A %.6f, V %.6f, AV %.6f (kerned by "
                  "%.6f), HH %.6f\n",
                  wa, wv, wav, wa + wv - wav, wh);
    assert_true(wa > 0 && wv > 0);
    assert_true(wav < wa + wv - 1e-3);                 /* the AV pair is kerned */
    assert_true(fabs(wh - 2 * width_of("H")) < 1e-12); /* HH is not */

    /* center shifts by half of right's shift, and spacing scales advances */
    laid c, r, s2;
    lay_out(&c, "text(text = \"spancast\", halign = \"center\");");
    lay_out(&r, "text(text = \"spancast\", halign = \"right\");");
    lay_out(&s2, "text(text = \"spancast\", spacing = 2);");
    assert_int_equal(c.shape.glyph_count, 8);
    assert_true(c.shape.offset[0] == r.shape.offset[0] / 2);
    assert_true(fabs(s2.shape.advance[2 * 7] - 2 * r.shape.advance[2 * 7]) < 1e-12);
    /* centred text spans about equally both sides of x = 0 (side bearings
     * of 's' and 't' differ a little) */
    double x0, x1, y0, y1;
    extent(&c.shape, &x0, &x1, &y0, &y1);
    print_message("centred 'spancast': x from %.4f to %.4f\n", x0, x1);
    assert_true(fabs(x0 + x1) < 0.05 * (x1 - x0));
    done(&c);
    done(&r);
    done(&s2);

    /* valign top shifts by the tallest glyph's grid-fitted top, bottom by
     * the lowest bottom; as in OpenSCAD, that shift is in HarfBuzz's units
     * (1.024e5) while outlines are in FreeType's (1e5), so the glyphs end
     * up 2.4 % of their height past the line (to within the 1/64 pixel
     * grid fit, 0.0064 at size 10) */
    laid t, b, base;
    lay_out(&t, "text(text = \"Hp\", valign = \"top\");");
    lay_out(&b, "text(text = \"Hp\", valign = \"bottom\");");
    lay_out(&base, "text(text = \"Hp\");");
    double top, bottom, bx0, bx1, by0, by1;
    extent(&base.shape, &bx0, &bx1, &by0, &by1);
    assert_true(by0 < -1 && by1 > 6);
    extent(&t.shape, &x0, &x1, &y0, &top);
    extent(&b.shape, &x0, &x1, &bottom, &y1);
    print_message("valign: baseline y from %.5f to %.5f; top's top %.5f, bottom's bottom "
                  "%.5f\n",
                  by0, by1, top, bottom);
    assert_true(fabs(top - by1 * (1 - 1 / 1.024)) < 0.0065);
    assert_true(fabs(bottom - by0 * (1 - 1 / 1.024)) < 0.0065);
    done(&t);
    done(&b);
    done(&base);

    /* size scales every point: size 20 is twice size 10 */
    laid s10, s20;
    lay_out(&s10, "text(text = \"Bo\", size = 10);");
    lay_out(&s20, "text(text = \"Bo\", size = 20);");
    double a0, a1, b0, b1, c0, c1, d0, d1;
    extent(&s10.shape, &a0, &a1, &b0, &b1);
    extent(&s20.shape, &c0, &c1, &d0, &d1);
    assert_true(fabs(c1 - 2 * a1) < 1e-12 && fabs(d0 - 2 * b0) < 1e-12);
    /* OpenSCAD's points per curve: max(floor(fragments / 8) + 1, 2) */
    assert_int_equal(s10.shape.curve_points, 4); /* 30 fragments at r = 10 */
    done(&s10);
    done(&s20);
    laid fn;
    lay_out(&fn, "text(text = \"o\", $fn = 64);");
    assert_int_equal(fn.shape.curve_points, 9);
    done(&fn);
}

/* Liberation Sans is TrueType: quadratic curves and lines only; every
 * contour closes (the last segment ends where the first starts). */
static void test_outlines_close(void **state)
{
    (void)state;
    laid l;
    lay_out(&l, "text(text = \"spancast@&%8\");");
    uint32_t quads = 0, lines = 0;
    for (uint32_t k = 0; k < l.shape.contour_count; k++) {
        uint32_t s = l.shape.contour_start[k], e = l.shape.contour_start[k + 1];
        const outline_seg *first = &l.shape.segs[s], *last = &l.shape.segs[e - 1];
        assert_true(first->x[0] == last->x[last->degree]);
        assert_true(first->y[0] == last->y[last->degree]);
        for (uint32_t i = s; i + 1 < e; i++) {
            const outline_seg *a = &l.shape.segs[i], *b = &l.shape.segs[i + 1];
            assert_true(a->x[a->degree] == b->x[0] && a->y[a->degree] == b->y[0]);
            quads += a->degree == 2;
            lines += a->degree == 1;
        }
    }
    print_message("'spancast@&%%8': %u glyphs, %u contours, %u segments (%u quadratic, "
                  "%u lines before each contour's last)\n",
                  l.shape.glyph_count, l.shape.contour_count, l.shape.seg_count, quads,
                  lines);
    assert_int_equal(l.shape.glyph_count, 12);
    assert_true(quads > 100);
    done(&l);
}

/* ---- the outline prism of real glyphs ---- */

static sc_scene *load(const char *text, int faithful)
{
    return test_load("m.csg", text, faithful);
}

typedef struct rng {
    uint64_t s;
} rng;

static double uniform_in(rng *r, double a, double b)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return a + (b - a) * ((double)(r->s >> 11) / 9007199254740992.0);
}

/* Spans against membership on random rays through real glyph outlines
 * (all directions, and rays in the text's plane along its baseline, which
 * cross many glyphs). */
static void test_glyph_spans_match_inside(void **state)
{
    (void)state;
    sc_scene *s = load("linear_extrude(height = 3) { text(\"spancast &@%8 AVWg\"); }", 0);
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 1);
    const prim *p = &t->leaves[0].prim;
    assert_int_equal(p->kind, PRIM_OUTLINE);
    bbox bb = prim_bounds(p);
    uint32_t cap = prim_max_spans(p);
    rng r = {99};
    long rays = 0, spans = 0, samples = 0, near = 0, disagreements = 0, wrong = 0;
    uint32_t most = 0;
    for (int k = 0; k < 20000; k++) {
        vec3 a = v3(uniform_in(&r, bb.lo.x, bb.hi.x), uniform_in(&r, bb.lo.y, bb.hi.y),
                    uniform_in(&r, -1, 4));
        vec3 d = v3(uniform_in(&r, -1, 1), uniform_in(&r, -1, 1), uniform_in(&r, -1, 1));
        if (k % 4 == 0)
            d = v3(1, uniform_in(&r, -0.02, 0.02), 0), a.x = bb.lo.x - 5;
        span v[PRIM_OUTLINE_MAX_SPANS];
        uint32_t n = prim_spans(p, 0, a, d, v, cap);
        rays++;
        spans += n;
        if (n > most)
            most = n;
        for (uint32_t i = 0; i < n; i++) {
            if (v[i].out.t - v[i].in.t < 1e-9)
                continue;
            if (v3_dot(prim_normal(p, v3_madd(a, d, v[i].in.t), v[i].in.part), d) > 0)
                wrong++;
            if (v3_dot(prim_normal(p, v3_madd(a, d, v[i].out.t), v[i].out.part), d) < 0)
                wrong++;
        }
        double span_len = 120 / sqrt(v3_dot(d, d));
        for (int j = 0; j < 100; j++) {
            double tt = uniform_in(&r, -span_len, span_len);
            int close = 0, in = 0;
            for (uint32_t i = 0; i < n; i++) {
                if (fabs(tt - v[i].in.t) < 1e-7 || fabs(tt - v[i].out.t) < 1e-7)
                    close = 1;
                if (tt >= v[i].in.t && tt <= v[i].out.t)
                    in = 1;
            }
            samples++;
            if (close) {
                near++;
                continue;
            }
            if (in != prim_inside(p, v3_madd(a, d, tt)))
                disagreements++;
        }
    }
    print_message("glyph spans: %ld rays, %ld spans (at most %u on one ray, cap %u), %ld "
                  "samples (%ld within 1e-7 of an end), %ld disagreements, %ld normals "
                  "facing the wrong way\n",
                  rays, spans, most, cap, samples, near, disagreements, wrong);
    assert_int_equal(disagreements, 0);
    assert_int_equal(wrong, 0);
    assert_true(spans > rays / 4);
    sc_scene_release(s);
}

/* OpenSCAD's polygons of the text node src (in "t.csg") into *poly
 * (initialised here; the caller frees it): the status of
 * text_faithful_polygons, and its error formatted into message. */
static sc_status text_polygons_of(const char *src, twod_region *poly, char *message,
                                  size_t size)
{
    sc_error e;
    parse_tree *tree;
    assert_int_equal(parse_text("t.csg", src, strlen(src), &tree, &e), SC_OK);
    model *lowered;
    assert_int_equal(model_lower_twod("t.csg", tree->first, &lowered, &e), SC_OK);
    build_ctx c = {.file = "t.csg",
                   .csg = NULL,
                   .error = &e,
                   .faithful = 1,
                   .note = NULL,
                   .notes = NULL};
    twod_init(poly);
    sc_status st = text_faithful_polygons(&c, lowered->first, poly, NULL);
    if (st != SC_OK)
        sc_error_format(&e, message, size);
    else
        message[0] = 0;
    model_free(lowered);
    parse_tree_free(tree);
    return st;
}

/* Faithful polygons: every point OpenSCAD's flattening makes lies on the
 * exact outline (within the 2^-16 snap), so membership of the exact prism
 * just inside and outside a polygon edge's midpoint agrees with the
 * polygon's side wherever the curve is flat enough. Checked simply: each
 * faithful vertex is within 2^-15 of the exact outline's boundary. */
static void test_faithful_points_on_curves(void **state)
{
    (void)state;
    twod_region poly;
    char buf[1024];
    assert_int_equal(text_polygons_of("text(text = \"Bo@\", size = 10, $fn = 32);", &poly,
                                      buf, sizeof buf),
                     SC_OK);
    sc_scene *s =
        load("linear_extrude(height = 1) { text(text = \"Bo@\", size = 10, $fn = "
             "32); }",
             0);
    const prim *p = &scene_tree(s)->leaves[0].prim;
    uint32_t off = 0;
    double h = 1.0 / 32768;
    for (uint32_t i = 0; i < poly.point_count; i++) {
        double x = poly.xy[2 * i], y = poly.xy[2 * i + 1];
        /* somewhere within h of the point, membership changes */
        int in = 0, out = 0;
        for (int k = 0; k < 16; k++) {
            double a = k * 0.39269908169872414;
            if (prim_inside(p, v3(x + h * cos(a), y + h * sin(a), 0.5)))
                in = 1;
            else
                out = 1;
        }
        if (!(in && out))
            off++;
    }
    uint32_t paths = poly.contour_count;
    double area = 0;
    for (uint32_t k = 0; k < paths; k++)
        for (uint32_t i = poly.start[k]; i < poly.start[k + 1]; i++) {
            uint32_t j = i + 1 < poly.start[k + 1] ? i + 1 : poly.start[k];
            area +=
                poly.xy[2 * i] * poly.xy[2 * j + 1] - poly.xy[2 * j] * poly.xy[2 * i + 1];
        }
    print_message("faithful 'Bo@' ($fn = 32): %u paths, %u points, area %.4f, %u points "
                  "off the exact outline\n",
                  paths, poly.point_count, area / 2, off);
    assert_int_equal(off, 0);
    assert_true(area > 0); /* outlines counter-clockwise */
    twod_free(&poly);
    sc_scene_release(s);
}

/* A long string stays one leaf with a hierarchy; a ray along it is capped
 * and the first hits stay right. */
static void test_long_text(void **state)
{
    (void)state;
    char src[3000] = "linear_extrude(height = 2) { text(\"";
    for (int i = 0; i < 250; i++)
        strcat(src, "Wm0@");
    strcat(src, "\"); }");
    sc_scene *s = load(src, 0);
    const prim *p = &scene_tree(s)->leaves[0].prim;
    const prim_outline *o = p->u.outline.outline;
    span v[PRIM_OUTLINE_MAX_SPANS];
    uint32_t n = prim_spans(p, 0, v3(-10, 3, 1), v3(1, 0, 0), v, prim_max_spans(p));
    print_message("1000 glyphs: %u segments, %u hierarchy nodes, %u spans along the "
                  "line y = 3 (cap %u)\n",
                  o->seg_count, o->node_count, n, prim_max_spans(p));
    assert_int_equal(n, PRIM_OUTLINE_MAX_SPANS);
    assert_true(v[0].in.t > 10 && v[0].in.t < 12); /* the first W's left side */
    sc_scene_release(s);
}

/* ---- builder messages ---- */

static void check_error(const char *text, sc_status status, const char *expected)
{
    test_check_error("m.csg", text, status, expected);
}

/* One warning, at line 1, column, with message. */
static void check_warning(const char *text, int faithful, int column, const char *message)
{
    sc_scene *s = load(text, faithful);
    assert_int_equal(sc_scene_warning_count(s), 1);
    const sc_error *w = sc_scene_warning(s, 0);
    assert_int_equal(w->line, 1);
    assert_int_equal(w->column, column);
    assert_string_equal(w->message, message);
    sc_scene_release(s);
}

/* a and b load to models of the same bounds. */
static void check_same_box(const char *a, const char *b)
{
    double lo[2][3], hi[2][3];
    const char *texts[2] = {a, b};
    for (int i = 0; i < 2; i++) {
        sc_scene *s = load(texts[i], 0);
        assert_int_equal(sc_scene_warning_count(s), 0);
        assert_true(sc_scene_bounds(s, lo[i], hi[i]));
        sc_scene_release(s);
    }
    for (int k = 0; k < 3; k++)
        assert_true(lo[0][k] == lo[1][k] && hi[0][k] == hi[1][k]);
}

static void test_errors(void **state)
{
    (void)state;
    /* arguments of the wrong kind are their defaults, silently, as OpenSCAD
     * 2021.01 takes them: text(5) is empty text, a size that is not a
     * number 10, a halign that is not a string "left" */
    check_warning("linear_extrude(height = 1) { text(text = 5); }", 0, 1,
                  "linear_extrude without height or area is empty");
    check_same_box(
        "linear_extrude(height = 1) { text(\"a\", size = \"big\", halign = 1); }",
        "linear_extrude(height = 1) { text(\"a\", size = 10, halign = \"left\"); }");
    /* a size that is not finite (a .scad's 1/0, written as inf) draws
     * nothing, as in OpenSCAD 2021.01 (tests/cli_lenient.sh), in both modes */
    for (int faithful = 0; faithful < 2; faithful++) {
        check_warning("linear_extrude(height = 1) { text(\"a\", size = inf); }", faithful,
                      1, "linear_extrude without height or area is empty");
        check_warning("linear_extrude(height = 1) { text(\"a\", size = nan); }", faithful,
                      1, "linear_extrude without height or area is empty");
    }
    /* a spacing that is not finite puts every glyph after the first at no
     * finite place, and OpenSCAD 2021.01 draws none there: left-aligned
     * text keeps its first glyph, centred text none (tests/cli_lenient.sh) */
    check_same_box("linear_extrude(height = 1) { text(\"abc\", spacing = inf); }",
                   "linear_extrude(height = 1) { text(\"a\"); }");
    check_same_box("linear_extrude(height = 1) { text(\"abc\", spacing = nan); }",
                   "linear_extrude(height = 1) { text(\"a\"); }");
    for (int faithful = 0; faithful < 2; faithful++)
        check_warning(
            "linear_extrude(height = 1) { text(\"abc\", spacing = inf, halign = "
            "\"center\"); }",
            faithful, 1, "linear_extrude without height or area is empty");
    /* text beside other 2D shapes goes through the 2D engine */
    sc_scene *mixed = load("linear_extrude(height = 1) { text(\"a\"); square(2); }", 0);
    assert_true(csg_inside(scene_tree(mixed), v3(1, 1, 0.5)));   /* the square */
    assert_false(csg_inside(scene_tree(mixed), v3(20, 1, 0.5))); /* past the text */
    sc_scene_release(mixed);
    /* a 3D child of the extrusion is ignored with OpenSCAD's warning */
    static const char *const ignored[] = {
        "m.csg:1:41: Ignoring 3D child object for 2D operation"};
    sc_scene_release(test_check_warnings(
        "m.csg", "linear_extrude(height = 1) { text(\"a\"); sphere(2); }", 0, ignored,
        1));
    /* text alone is a 2D model, drawn flat: the slab OpenSCAD draws */
    sc_scene *flat = test_load("m.csg", "text(\"a\", size = 10);", 0);
    assert_int_equal(sc_scene_warning_count(flat), 0);
    assert_true(scene_tree(flat)->root != CSG_EMPTY);
    sc_scene_release(flat);
    /* the finest $fa and $fs (36,000 fragments, 4,501 points a curve) in
     * faithful mode as in exact mode, as OpenSCAD draws them: the glyph's
     * inside at the same points */
    const char *fine =
        "linear_extrude(height = 1) { text(\"o\", size = 10, $fa = 0.01, $fs = 0.001); }";
    sc_scene *exact = load(fine, 0), *faithful = load(fine, 1);
    assert_int_equal(sc_scene_warning_count(faithful), 0);
    double lo[3], hi[3];
    assert_true(sc_scene_bounds(exact, lo, hi));
    int inside = 0;
    for (int k = 0; k < 200; k++) {
        vec3 p = v3(lo[0] + (hi[0] - lo[0]) * (k + 0.5) / 200, (lo[1] + hi[1]) / 2, 0.5);
        int in = csg_inside(scene_tree(exact), p);
        assert_int_equal(csg_inside(scene_tree(faithful), p), in);
        inside += in;
    }
    assert_true(inside > 20); /* the ring's two sides */
    sc_scene_release(exact);
    sc_scene_release(faithful);
}

/* OpenSCAD's polygons of a text obey the one rule of every 2D shape: at
 * most TWOD_MAX_POINTS points (the glyphs' points were unbounded before),
 * an error at the text node past it. 2000 '@' of 513 points per curve
 * are more than 2e7 points. */
static void test_faithful_point_limit(void **state)
{
    (void)state;
    size_t n = 2000;
    char *src = malloc(n + 64);
    strcpy(src, "text(text = \"");
    size_t at = strlen(src);
    memset(src + at, '@', n);
    strcpy(src + at + n, "\", $fn = 4096);");
    twod_region poly;
    char buf[1024];
    assert_int_equal(text_polygons_of(src, &poly, buf, sizeof buf), SC_ERR_LIMIT);
    assert_string_equal(
        buf, "t.csg:1:1: error: text: too many points in a 2D shape (limit is 10000000)");
    twod_free(&poly);
    free(src);
}

static void test_long_and_fonts(void **state)
{
    (void)state;
    size_t n = TEXT_MAX_BYTES + 1;
    char *src = malloc(n + 64);
    strcpy(src, "linear_extrude(height = 1) { text(\"");
    size_t at = strlen(src);
    memset(src + at, 'a', n);
    strcpy(src + at + n, "\"); }");
    check_error(src, SC_ERR_LIMIT,
                "m.csg:1:35: error: text is too long (10001 bytes; limit is 10000)");
    free(src);
    check_warning("linear_extrude(height = 1) { text(\"a\", font = \"No Such Font\"); }",
                  0, 30,
                  "text: font 'No Such Font' was not found; using "
                  "'DejaVu Sans'");
    check_warning("linear_extrude(height = 1) { text(\"a\", font = \"No Such Font\"); }",
                  1, 30,
                  "text: font 'No Such Font' was not found; using "
                  "'DejaVu Sans'");
    /* a 2D model's text warns too (its walk takes no leaf's note) */
    check_warning("text(\"a\", font = \"No Such Font\");", 0, 1,
                  "text: font 'No Such Font' was not found; using "
                  "'DejaVu Sans'");
    check_warning("union() { square(1); text(\"a\", font = \"No Such Font\"); }", 1, 22,
                  "text: font 'No Such Font' was not found; using "
                  "'DejaVu Sans'");
    check_warning("linear_extrude(height = 1) { text(\"a\", halign = \"middle\"); }", 0,
                  30,
                  "text: unknown halign 'middle' (use \"left\", "
                  "\"right\" or \"center\")");
    check_warning("linear_extrude(height = 1) { text(\"\"); }", 0, 1,
                  "linear_extrude without height or area is empty");
    check_warning("linear_extrude(height = 1) { text(\" \"); }", 1, 1,
                  "linear_extrude without height or area is empty");
    check_warning("linear_extrude(height = 1) { text(\"a\", size = 0); }", 0, 1,
                  "linear_extrude without height or area is empty");
    /* a known font, by family and style: no warning */
    sc_scene *s = load("linear_extrude(height = 1) { text(\"a\", font = \"Liberation "
                       "Serif:style=Bold\"); }",
                       0);
    assert_int_equal(sc_scene_warning_count(s), 0);
    sc_scene_release(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registered_font),
        cmocka_unit_test(test_kerning_and_alignment),
        cmocka_unit_test(test_outlines_close),
        cmocka_unit_test(test_glyph_spans_match_inside),
        cmocka_unit_test(test_faithful_points_on_curves),
        cmocka_unit_test(test_long_text),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_long_and_fonts),
        cmocka_unit_test(test_faithful_point_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
