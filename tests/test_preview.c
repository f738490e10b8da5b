/* Tests of the preview's modifiers and colour alpha (render.c, build.c's
 * modifier parts), through the public API from .csg text.
 *
 * Each scene is seen straight down through an orthographic camera, so a
 * pixel's place in the model is known: with the eye 100 above the origin
 * and the field of view 22.5 degrees, the image's half height is
 * 100 tan(11.25 degrees) world units. Each expected colour is computed
 * from other renders of the same camera (the same file without the
 * modifier, or with the colour opaque) and the blending rule (display
 * values, c = a part + (1 - a) behind), never written down as numbers.
 * A lone leaf (its own product in OpenSCAD's normal form) is drawn rear
 * faces first, then front faces, as OpenSCAD 2021.01 draws a translucent
 * one: seen from above through a box or a cylinder, its bottom, then its
 * top, both lit alike by OpenSCAD's light (which does not tell a normal
 * from its opposite), so that what lies behind keeps (1 - a)^2.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/color.h"
#include "formats/framebuffer.h"
#include "spancast/spancast.h"

#define SIZE 200

/* World units per pixel (see above). */
static double pixel_size(void)
{
    return 2 * 100 * tan(22.5 / 2 * 3.14159265358979323846 / 180) / SIZE;
}

/* The pixel index seeing world point (x, y) from above. */
static size_t pixel_at(double x, double y)
{
    int i = (int)floor(SIZE / 2.0 + x / pixel_size());
    int j = (int)floor(SIZE / 2.0 - y / pixel_size());
    return (size_t)j * SIZE + (size_t)i;
}

/* The options of every test: the camera above, SIZE x SIZE, the AOVs. */
static void options_above(sc_render_options *o, int preview)
{
    sc_render_options_init(o);
    o->camera_mode = SC_CAMERA_VECTOR;
    o->camera[2] = 100;
    o->up[1] = 1;
    o->up[2] = 0;
    o->projection = SC_PROJECTION_ORTHOGRAPHIC;
    o->width = o->height = SIZE;
    o->preview = preview;
    o->want_mask = o->want_depth = o->want_id = 1;
    o->threads = 2;
}

/* Loads text with lo (NULL: the defaults) and renders it with o. */
static sc_framebuffer *render_loaded(const char *text, const sc_load_options *lo,
                                     const sc_render_options *o)
{
    sc_scene *scene = NULL;
    sc_error error;
    if (sc_scene_load_string("test.csg", text, strlen(text), lo, &scene, &error))
        fail_msg("load: %s", error.message);
    sc_framebuffer *fb = NULL;
    if (sc_render(scene, o, &fb, &error))
        fail_msg("render: %s", error.message);
    sc_scene_release(scene);
    return fb;
}

static sc_framebuffer *render_options(const char *text, const sc_render_options *o)
{
    return render_loaded(text, NULL, o);
}

static sc_framebuffer *render_text(const char *text, int preview)
{
    sc_render_options o;
    options_above(&o, preview);
    return render_options(text, &o);
}

static double display(const sc_framebuffer *fb, size_t p, int k)
{
    return color_linear_to_srgb(fb->color[3 * p + k]);
}

/* The solid's AOVs are the same in a and b. */
static void assert_same_aovs(const sc_framebuffer *a, const sc_framebuffer *b)
{
    size_t n = (size_t)SIZE * SIZE;
    assert_memory_equal(a->mask, b->mask, n);
    assert_memory_equal(a->depth, b->depth, n * sizeof *a->depth);
    assert_memory_equal(a->id, b->id, n * sizeof *a->id);
}

static void assert_same_color(const sc_framebuffer *a, const sc_framebuffer *b)
{
    assert_memory_equal(a->color, b->color, (size_t)SIZE * SIZE * 3 * sizeof(float));
}

/* A file in two variants (format's %s replaced by a and by b), each
 * rendered with --preview and without: without it (OpenSCAD's render)
 * the two images are the same, and with it the AOVs are. */
typedef struct variants {
    sc_framebuffer *a, *b;               /* with --preview */
    sc_framebuffer *render_a, *render_b; /* without */
} variants;

static void render_variants(const char *format, const char *a, const char *b, variants *v)
{
    char text[1024];
    snprintf(text, sizeof text, format, a);
    v->a = render_text(text, 1);
    v->render_a = render_text(text, 0);
    snprintf(text, sizeof text, format, b);
    v->b = render_text(text, 1);
    v->render_b = render_text(text, 0);
    assert_same_color(v->render_a, v->render_b);
    assert_same_aovs(v->render_a, v->render_b);
    assert_same_aovs(v->a, v->b);
}

static void release_variants(variants *v)
{
    sc_framebuffer_release(v->a);
    sc_framebuffer_release(v->b);
    sc_framebuffer_release(v->render_a);
    sc_framebuffer_release(v->render_b);
}

static const char drilled[] =
    "difference() {\n"
    "  cube(size = [30, 30, 10], center = true);\n"
    "  %scylinder(h = 14, r1 = 5, r2 = 5, center = true, $fn = 0, $fa = 12, $fs = 2);\n"
    "}\n";

/* Rounding of float buffers and the sRGB conversions, display values. */
#define BLEND_TOLERANCE 1e-4

/* A '#' cylinder subtracted from a box: with --preview its bottom and
 * top caps (below and above the box) tint the hole translucent red,
 * blended over what the hole shows without it; nothing else changes, the
 * AOVs not at all; and without --preview the '#' changes nothing. */
static void test_highlight_in_hole(void **state)
{
    (void)state;
    variants v;
    render_variants(drilled, "#", "", &v);
    const sc_framebuffer *shown = v.a, *without = v.b;

    /* OpenSCAD's highlight: (255, 81, 81), alpha 128/255, twice (the
     * caps). The lit colour is 255/255 f and 81/255 f for an unknown light
     * factor f, clamped to 1; green gives f, and red and blue must
     * follow. */
    double a = 128 / 255.0, hr = 1, hg = 81 / 255.0;
    double cover = a + (1 - a) * a; /* of the two caps; (1 - a)^2 shows through */
    double radius = 5 / pixel_size();
    int inside = 0;
    for (int j = 0; j < SIZE; j++)
        for (int i = 0; i < SIZE; i++) {
            size_t p = (size_t)j * SIZE + (size_t)i;
            double r = hypot(i + 0.5 - SIZE / 2.0, j + 0.5 - SIZE / 2.0);
            if (r > radius + 1) {
                assert_memory_equal(&shown->color[3 * p], &without->color[3 * p],
                                    3 * sizeof(float));
                continue;
            }
            if (r > radius - 1)
                continue; /* the rim: either */
            inside++;
            assert_int_equal(shown->mask[p], 0); /* the hole itself */
            double under[3], got[3];
            for (int k = 0; k < 3; k++) {
                under[k] = display(without, p, k);
                got[k] = display(shown, p, k);
            }
            double f = (got[1] - (1 - cover) * under[1]) / (cover * hg);
            assert_true(f > 0.2 - 1e-3 && f < 1.2 + 1e-3);
            double want_r = cover * fmin(1.0, hr * f) + (1 - cover) * under[0];
            double want_b = cover * fmin(1.0, hg * f) + (1 - cover) * under[2];
            if (fabs(got[0] - want_r) > BLEND_TOLERANCE ||
                fabs(got[2] - want_b) > BLEND_TOLERANCE)
                fail_msg("pixel %d,%d: %.5f %.5f %.5f, expected %.5f %.5f (over %.5f "
                         "%.5f %.5f)",
                         i, j, got[0], got[1], got[2], want_r, want_b, under[0], under[1],
                         under[2]);
        }
    assert_true(inside > 2 * radius * radius); /* most of the disc */
    release_variants(&v);
}

static const char background_part[] = "cube(size = [20, 20, 10], center = true);\n"
                                      "%s";

static const char sphere_part[] =
    "multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 4], [0, 0, 0, 1]])\n"
    "{ sphere(r = 6, $fn = 0, $fa = 12, $fs = 2); }\n";

/* A '%' sphere half over a box changes no mask, depth or id pixel, and is
 * drawn translucent where it is: grey (OpenSCAD's 180, 180, 180, alpha
 * 128/255, lit) over what the pixel shows without it. Over the box its top
 * alone is in front of the solid; beyond the box its bottom shows through
 * its top, so the two grey layers leave (1 - a)^2 of the background. */
static void test_background_changes_no_aov(void **state)
{
    (void)state;
    char marked[sizeof sphere_part + 1];
    snprintf(marked, sizeof marked, "%%%s", sphere_part);
    variants v;
    render_variants(background_part, marked, "", &v);
    const sc_framebuffer *shown = v.a, *without = v.b;
    /* Without the modifier the sphere is part of the solid and the mask
     * grows there, so the comparison of the AOVs could fail. */
    char united[sizeof background_part + sizeof sphere_part];
    snprintf(united, sizeof united, background_part, sphere_part);
    sc_framebuffer *solid = render_text(united, 1);
    assert_int_equal(solid->mask[pixel_at(10.5, 0)], 255);
    assert_int_equal(without->mask[pixel_at(10.5, 0)], 0);
    sc_framebuffer_release(solid);

    double a = 128 / 255.0, grey = 180 / 255.0;
    /* Over the box (x = 8): the sphere's top. */
    size_t p = pixel_at(8, 0);
    double f = (display(shown, p, 0) - (1 - a) * display(without, p, 0)) / (a * grey);
    assert_true(f > 0.2 && f < 1.2 + 1e-3);
    for (int c = 1; c < 3; c++) {
        double want = a * fmin(1.0, grey * f) + (1 - a) * display(without, p, c);
        assert_true(fabs(display(shown, p, c) - want) < BLEND_TOLERANCE);
    }
    /* Beyond it (x = 10.5): grey layers, whatever their light, add the
     * same to each channel of the background's (1 - a)^2, which is not
     * grey (Cornfield's). */
    p = pixel_at(10.5, 0);
    assert_true(fabs(display(without, p, 0) - display(without, p, 2)) > 0.05);
    double added[3];
    for (int c = 0; c < 3; c++)
        added[c] = display(shown, p, c) - (1 - a) * (1 - a) * display(without, p, c);
    for (int c = 1; c < 3; c++)
        assert_true(fabs(added[c] - added[0]) < BLEND_TOLERANCE);
    /* each layer lit by 0.2 to 1.2 of grey, clamped to 1 */
    double cover = a + (1 - a) * a;
    assert_true(added[0] > cover * 0.2 * grey - BLEND_TOLERANCE &&
                added[0] < cover * fmin(1.0, 1.2 * grey) + BLEND_TOLERANCE);
    /* Away from the sphere nothing changes. */
    size_t far = pixel_at(-8, -8);
    assert_memory_equal(&shown->color[3 * far], &without->color[3 * far],
                        3 * sizeof(float));
    release_variants(&v);
}

static const char alpha_cube[] = "color([0.2, 0.4, 0.9, %s]) {\n"
                                 "  cube(size = [20, 20, 10], center = true);\n"
                                 "}\n";

/* A 50 % transparent cube over the background, in OpenSCAD's light:
 * alone, it shows its bottom behind its top, both in its opaque colour,
 * over 0.25 of the background; subtracted from (a product with another
 * leaf), OpenCSG keeps only its top, over 0.5 of the background. On
 * display values. Without --preview (OpenSCAD's render) it is opaque. */
static void test_alpha_blends(void **state)
{
    (void)state;
    variants v;
    render_variants(alpha_cube, "0.5", "1", &v); /* checks the render */
    release_variants(&v);
    static const char cut[] = "difference() {\n%s"
                              "  cube(size = [1, 1, 1]);\n"
                              "}\n";
    const char *forms[2] = {"%s", cut};
    const double behind[2] = {0.25, 0.5};
    for (int form = 0; form < 2; form++) {
        char text[1024], inner[512];
        sc_render_options o;
        options_above(&o, 1);
        o.lighting = SC_LIGHTING_OPENSCAD;
        snprintf(inner, sizeof inner, alpha_cube, "1");
        snprintf(text, sizeof text, forms[form], inner);
        sc_framebuffer *solid = render_options(text, &o);
        snprintf(inner, sizeof inner, alpha_cube, "0.5");
        snprintf(text, sizeof text, forms[form], inner);
        sc_framebuffer *blended = render_options(text, &o);
        size_t bg = pixel_at(-15, -15), centre = pixel_at(-3, -3);
        assert_int_equal(solid->mask[bg], 0);
        assert_int_equal(solid->mask[centre], 255);
        for (int k = 0; k < 3; k++) {
            double want = (1 - behind[form]) * display(solid, centre, k) +
                          behind[form] * display(solid, bg, k);
            double got = display(blended, centre, k);
            if (fabs(got - want) > BLEND_TOLERANCE)
                fail_msg("form %d, channel %d: %.6f, expected %.6f", form, k, got, want);
        }
        sc_framebuffer_release(solid);
        sc_framebuffer_release(blended);
    }
}

/* OpenSCAD's preview leaves a '#' operand of a union with other operands
 * out of the solid (CSGTreeEvaluator: it draws it as a part only), and
 * keeps one that is alone or whose siblings are all '#'; its render keeps
 * both. The highlighted sphere beside a box: with --preview, no mask where
 * it is, and the highlight over the background there; alone, in the
 * mask. */
static void test_highlight_leaves_union(void **state)
{
    (void)state;
    static const char beside[] =
        "cube(size = [20, 20, 10], center = true);\n"
        "%smultmatrix([[1, 0, 0, 16], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
        "{ sphere(r = 4); }\n";
    char text[512];
    size_t sphere = pixel_at(16, 0), box = pixel_at(0, 0), bg = pixel_at(-15, -15);
    snprintf(text, sizeof text, beside, "#");
    sc_framebuffer *preview = render_text(text, 1), *render = render_text(text, 0);
    assert_int_equal(preview->mask[sphere], 0);
    assert_int_equal(preview->mask[box], 255);
    assert_int_equal(render->mask[sphere], 255);
    /* red over the background: more red than green, and not the box's
     * colour */
    assert_true(display(preview, sphere, 0) > display(preview, sphere, 1) + 0.2);
    assert_true(fabs(display(preview, sphere, 2) - display(preview, bg, 2)) > 0.05);
    sc_framebuffer_release(preview);
    sc_framebuffer_release(render);
    /* both operands highlighted: the union is, and stays in the solid */
    snprintf(text, sizeof text,
             "#cube(size = [20, 20, 10], center = true);\n"
             "#multmatrix([[1, 0, 0, 16], [0, 1, 0, 0], [0, 0, 1, 0], "
             "[0, 0, 0, 1]])\n{ sphere(r = 4); }\n");
    preview = render_text(text, 1);
    assert_int_equal(preview->mask[sphere], 255);
    assert_int_equal(preview->mask[box], 255);
    sc_framebuffer_release(preview);
    /* inside a render(), whose mesh OpenSCAD builds of all its children,
     * the '#' operand stays in the solid, highlighted */
    char inside[600];
    snprintf(text, sizeof text, beside, "#");
    snprintf(inside, sizeof inside, "render(convexity = 2) { union() { %s } }", text);
    preview = render_text(inside, 1);
    assert_int_equal(preview->mask[sphere], 255);
    assert_true(display(preview, sphere, 0) > display(preview, sphere, 2) + 0.2);
    sc_framebuffer_release(preview);
}

/* OpenSCAD's RenderNode collects none of its children's terms: a '#' or
 * '%' that reaches a render() without meeting another operand is lost.
 * So a '#' sphere there is drawn as the plain sphere, and a '%' one not at
 * all, as if it were not in the file; one that a union inside the
 * render() meets is still a part. */
static void test_render_loses_terms(void **state)
{
    (void)state;
    static const char scene[] =
        "cube(size = [20, 20, 10], center = true);\n"
        "render(convexity = 2) { %smultmatrix([[1, 0, 0, 16], [0, 1, 0, 0], "
        "[0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 4); } }\n";
    char text[512], plain[512];
    snprintf(plain, sizeof plain, scene, "");
    sc_framebuffer *expected = render_text(plain, 1);
    snprintf(text, sizeof text, scene, "#");
    sc_framebuffer *got = render_text(text, 1);
    assert_same_aovs(got, expected);
    assert_same_color(got, expected);
    sc_framebuffer_release(got);
    sc_framebuffer_release(expected);
    snprintf(plain, sizeof plain, scene, "*");
    expected = render_text(plain, 1);
    snprintf(text, sizeof text, scene, "%");
    got = render_text(text, 1);
    assert_same_aovs(got, expected);
    assert_same_color(got, expected);
    sc_framebuffer_release(got);
    /* met by a union inside the render(): the '%' sphere is drawn */
    static const char met[] =
        "cube(size = [20, 20, 10], center = true);\n"
        "render(convexity = 2) { union() { cube(size = 2); %smultmatrix([[1, 0, 0, 16], "
        "[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 4); } } }\n";
    snprintf(text, sizeof text, met, "%");
    got = render_text(text, 1);
    size_t sphere = pixel_at(16, 0);
    assert_int_equal(got->mask[sphere], 0);
    assert_true(fabs(display(got, sphere, 0) - display(expected, sphere, 0)) > 0.05);
    sc_framebuffer_release(got);
    sc_framebuffer_release(expected);
}

/* A scene loaded with no_preview has neither the preview's parts nor its
 * own solid: its preview is the render's solid in the preview's colours,
 * as if the file had no modifiers; loaded by default, it differs. */
static void test_no_preview(void **state)
{
    (void)state;
    static const char beside[] =
        "cube(size = [20, 20, 10], center = true);\n"
        "%smultmatrix([[1, 0, 0, 16], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
        "{ sphere(r = 4); }\n"
        "%smultmatrix([[1, 0, 0, -16], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
        "{ cube(size = 6, center = true); }\n";
    char text[768], plain[768];
    snprintf(text, sizeof text, beside, "#", "%");
    snprintf(plain, sizeof plain, beside, "", "");
    sc_render_options o;
    options_above(&o, 1);
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.no_preview = 1;
    sc_framebuffer *bare = render_loaded(text, &lo, &o),
                   *full = render_loaded(text, NULL, &o);
    /* without modifiers, the '%' cube is part of the solid: cut it off */
    snprintf(plain, sizeof plain, beside, "", "*");
    sc_framebuffer *expected = render_loaded(plain, NULL, &o);
    assert_same_aovs(bare, expected);
    assert_same_color(bare, expected);
    size_t sphere = pixel_at(16, 0), part = pixel_at(-16, 0);
    assert_int_equal(full->mask[sphere], 0); /* the '#' operand left the union */
    assert_int_equal(bare->mask[sphere], 255);
    assert_true(fabs(display(full, part, 0) - display(bare, part, 0)) +
                    fabs(display(full, part, 2) - display(bare, part, 2)) >
                0.05); /* the '%' part is drawn */
    sc_framebuffer_release(bare);
    sc_framebuffer_release(full);
    sc_framebuffer_release(expected);
}

/* An intersection with a twisted sliver whose walls cross, which CGAL
 * fails on. */
static const char sliver_intersection[] =
    "intersection() {\n"
    "  linear_extrude(height = 2.2, twist = 90) polygon(points = [[-0.54, 0.59], "
    "[0.03, 0.56], [-0.27, 0.6], [-1.64, 1.14]]);\n"
    "  cylinder(h = 1.2, r1 = 0.83, r2 = 0.83, center = false, $fn = 10);\n"
    "}\n";

/* Faithful mode draws an intersection with a mesh that crosses itself as
 * CGAL's solid (build_cgal_crossing): CGAL fails on it, and OpenSCAD's
 * render keeps the twisted sliver alone; its preview (OpenCSG) draws the
 * intersection as written, inside the cylinder. */
static void test_faithful_cgal_as_written(void **state)
{
    (void)state;
    const char *scene = sliver_intersection;
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.faithful = 1;
    sc_render_options o;
    options_above(&o, 0);
    o.camera[2] = 10; /* the model is 3 across */
    sc_framebuffer *render = render_loaded(scene, &lo, &o);
    o.preview = 1;
    sc_framebuffer *preview = render_loaded(scene, &lo, &o);
    size_t in_render = 0, in_preview = 0, outside = 0;
    for (size_t p = 0; p < (size_t)SIZE * SIZE; p++) {
        in_render += render->mask[p] != 0;
        in_preview += preview->mask[p] != 0;
        outside += preview->mask[p] != 0 && !render->mask[p];
    }
    assert_true(in_preview > 0);
    assert_true(in_render > in_preview);
    assert_int_equal(outside, 0); /* the intersection lies in the sliver */
    sc_framebuffer_release(render);
    sc_framebuffer_release(preview);
}

/* Faithful renders of a and b (above, 3 across) draw the same mask. */
static void assert_same_faithful_mask(const char *a, const char *b)
{
    sc_load_options lo;
    sc_load_options_init(&lo);
    lo.faithful = 1;
    sc_render_options o;
    options_above(&o, 0);
    o.camera[2] = 10;
    sc_framebuffer *fa = render_loaded(a, &lo, &o), *fb = render_loaded(b, &lo, &o);
    size_t differ = 0, drawn = 0;
    for (size_t p = 0; p < (size_t)SIZE * SIZE; p++) {
        differ += (fa->mask[p] != 0) != (fb->mask[p] != 0);
        drawn += fb->mask[p] != 0;
    }
    assert_true(drawn > 0);
    assert_int_equal(differ, 0);
    sc_framebuffer_release(fa);
    sc_framebuffer_release(fb);
}

/* A '!' node is the design as its subtree alone would be, in faithful mode
 * too: the root intersection CGAL fails on is the sliver alone (it was
 * drawn as the intersection, the root's parent taking no part in the
 * render). */
static void test_faithful_cgal_root(void **state)
{
    (void)state;
    char rooted[sizeof sliver_intersection + 64];
    snprintf(rooted, sizeof rooted, "cube(0.2, center = true);\n!%s",
             sliver_intersection);
    assert_same_faithful_mask(rooted, sliver_intersection);
}

/* OpenSCAD 2021.01's render unites several objects at the file's top level
 * with CGAL (its root group), as a union() of them: a scaled extrusion
 * whose walls cross beside a minkowski sum that reaches into it makes that
 * union fail (CGALUtils::applyUnion3D), and the whole model is empty. So
 * it is in faithful mode, with OpenSCAD's error as a warning, and each
 * object is drawn in exact mode. */
static void test_faithful_cgal_top_level(void **state)
{
    (void)state;
    static const char scene[] =
        "resize(newsize = [1.56, 0, 2.34], auto = [1, 0, 1])\n"
        "  linear_extrude(height = 0.55, center = true, scale = [1.5, 0.8])\n"
        "    multmatrix([[1, 0, 0, -1.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
        "      polygon(points = [[2.34, 0.76], [2.03, -0.19], [2.65, 1.7]]);\n"
        "minkowski() {\n"
        "  multmatrix([[0.600094, -0.00368064, 0.799921, 0],\n"
        "              [0.715164, 0.450463, -0.534437, 0],\n"
        "              [-0.358368, 0.892787, 0.272953, 0], [0, 0, 0, 1]])\n"
        "    linear_extrude(height = 2.71, center = true, scale = [1.5, 0.8])\n"
        "      multmatrix([[1, 0, 0, -1.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
        "        polygon(points = [[2.99, 0.68], [0.95, 1.23], [2.42, 1.51]]);\n"
        "  resize(newsize = [3.57, 0, 3.84], auto = [1, 0, 1])\n"
        "    cube(size = [1.73, 2.55, 1.2]);\n"
        "}\n";
    sc_scene *scene_exact = NULL, *scene_faithful = NULL;
    sc_error error;
    sc_load_options lo;
    sc_load_options_init(&lo);
    if (sc_scene_load_string("test.csg", scene, strlen(scene), &lo, &scene_exact, &error))
        fail_msg("load: %s", error.message);
    lo.faithful = 1;
    if (sc_scene_load_string("test.csg", scene, strlen(scene), &lo, &scene_faithful,
                             &error))
        fail_msg("load: %s", error.message);
    int failed = 0;
    for (size_t k = 0; k < sc_scene_warning_count(scene_faithful); k++)
        failed |= strstr(sc_scene_warning(scene_faithful, k)->message,
                         "CGALUtils::applyUnion3D") != NULL;
    assert_true(failed);
    sc_render_options o;
    options_above(&o, 0);
    o.camera[2] = 20;
    sc_framebuffer *exact = NULL, *faithful = NULL;
    if (sc_render(scene_exact, &o, &exact, &error) ||
        sc_render(scene_faithful, &o, &faithful, &error))
        fail_msg("render: %s", error.message);
    size_t in_exact = 0, in_faithful = 0;
    for (size_t p = 0; p < (size_t)SIZE * SIZE; p++) {
        in_exact += exact->mask[p] != 0;
        in_faithful += faithful->mask[p] != 0;
    }
    assert_true(in_exact > 0);
    assert_int_equal(in_faithful, 0);
    sc_framebuffer_release(exact);
    sc_framebuffer_release(faithful);
    sc_scene_release(scene_exact);
    sc_scene_release(scene_faithful);
}

/* A 2D model in the render, as OpenSCAD's render draws a 2D result: flat
 * at z = 0 in colour, mask and depth, unlit in the options' 2D face
 * colour, its outlines (the hole's too) 2 pixels wide in the 2D edge
 * colour over it, and an axis in its plane over them; its preview is the slab 1
 * thick, lit, without them. */
static void test_flat_2d(void **state)
{
    (void)state;
    static const char text[] = "difference() {\n"
                               "  square(size = [30, 30], center = true);\n"
                               "  square(size = [10, 10], center = true);\n"
                               "}\n";
    sc_render_options o;
    options_above(&o, 0);
    const float face[3] = {0.2f, 0.4f, 0.6f}, edge[3] = {0.9f, 0.1f, 0.3f};
    memcpy(o.face_2d, face, sizeof face);
    memcpy(o.edge_2d, edge, sizeof edge);
    sc_framebuffer *flat = render_options(text, &o);
    o.preview = 1;
    sc_framebuffer *slab = render_options(text, &o);
    double px = pixel_size();
    size_t inside = pixel_at(10, 10), hole = pixel_at(0, 0), outside = pixel_at(18, 18);
    size_t outer = pixel_at(15, 10), inner = pixel_at(5, 0);
    assert_int_equal(flat->mask[inside], 255);
    assert_int_equal(flat->mask[hole], 0);
    assert_int_equal(flat->mask[outside], 0);
    assert_true(flat->id[inside] >= 0);
    assert_true(fabs(flat->depth[inside] - 100) < 1e-5);
    assert_true(fabs(slab->depth[inside] - 99.5) < 1e-5);
    for (int k = 0; k < 3; k++) {
        assert_true(fabs(display(flat, inside, k) - face[k]) < 1e-4);
        assert_true(fabs(display(flat, outer, k) - edge[k]) < 1e-4);
        assert_true(fabs(display(flat, inner, k) - edge[k]) < 1e-4);
        /* 3 pixels in from the outline: the face */
        assert_true(fabs(display(flat, pixel_at(15 - 3 * px, 10), k) - face[k]) < 1e-4);
    }
    assert_true(fabs(display(slab, outer, 0) - edge[0]) > 0.1);
    assert_true(fabs(display(slab, inside, 2) - face[2]) > 0.05);
    /* The x axis lies in the polygons' plane: OpenSCAD draws the axes
     * first and the polygons after with GL_LESS, so it stays over them (in
     * Cornfield's black), on one of the two rows beside y = 0. */
    o.preview = 0;
    o.view = SC_VIEW_AXES;
    sc_framebuffer *axes = render_options(text, &o);
    for (double x = 8; x <= 12; x += 2) {
        size_t above = pixel_at(x, 0.25 * px), below = pixel_at(x, -0.25 * px);
        double a = 0, b = 0;
        for (int k = 0; k < 3; k++) {
            a += display(axes, above, k);
            b += display(axes, below, k);
        }
        assert_true(fmin(a, b) < 0.05);
    }
    sc_framebuffer_release(axes);
    sc_framebuffer_release(flat);
    sc_framebuffer_release(slab);
}

/* Parts and alpha at several samples a pixel, under a section cut: the
 * thread count changes nothing, and a crop is the whole image's pixels. */
static void test_crop_and_threads(void **state)
{
    (void)state;
    static const char text[] =
        "difference() {\n"
        "  cube(size = [30, 30, 10], center = true);\n"
        "  #cylinder(h = 14, r1 = 5, r2 = 5, center = true);\n"
        "}\n"
        "%multmatrix([[1, 0, 0, 12], [0, 1, 0, 0], [0, 0, 1, 6], [0, 0, 0, 1]])\n"
        "{ sphere(r = 4); }\n"
        "color([0, 0, 1, 0.4]) { cube(size = [8, 8, 16]); }\n";
    sc_render_options o;
    options_above(&o, 1);
    o.camera[0] = 30;
    o.camera[1] = -40;
    o.up[1] = 0;
    o.up[2] = 1;
    o.projection = SC_PROJECTION_PERSPECTIVE;
    o.width = 61;
    o.height = 47;
    o.spp = 4;
    o.section_count = 1;
    o.section[0][1] = 1;
    o.section[0][3] = 6;
    o.threads = 1;
    sc_framebuffer *whole = render_options(text, &o);
    o.threads = 3;
    sc_framebuffer *threaded = render_options(text, &o);
    size_t n = (size_t)o.width * o.height;
    assert_memory_equal(whole->color, threaded->color, n * 3 * sizeof(float));
    /* The parts and the alpha are in view: F6 differs. */
    o.preview = 0;
    sc_framebuffer *render_mode = render_options(text, &o);
    assert_memory_not_equal(whole->color, render_mode->color, n * 3 * sizeof(float));
    sc_framebuffer_release(render_mode);
    o.preview = 1;
    o.region[0] = 9;
    o.region[1] = 5;
    o.region[2] = 44;
    o.region[3] = 40;
    sc_framebuffer *crop = render_options(text, &o);
    for (int j = 0; j < crop->height; j++)
        for (int i = 0; i < crop->width; i++) {
            size_t a = (size_t)j * crop->width + i;
            size_t w = (size_t)(j + 5) * whole->width + (i + 9);
            assert_memory_equal(&crop->color[3 * a], &whole->color[3 * w],
                                3 * sizeof(float));
        }
    sc_framebuffer_release(whole);
    sc_framebuffer_release(threaded);
    sc_framebuffer_release(crop);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_highlight_in_hole),
        cmocka_unit_test(test_background_changes_no_aov),
        cmocka_unit_test(test_alpha_blends),
        cmocka_unit_test(test_highlight_leaves_union),
        cmocka_unit_test(test_no_preview),
        cmocka_unit_test(test_render_loses_terms),
        cmocka_unit_test(test_crop_and_threads),
        cmocka_unit_test(test_flat_2d),
        cmocka_unit_test(test_faithful_cgal_as_written),
        cmocka_unit_test(test_faithful_cgal_root),
        cmocka_unit_test(test_faithful_cgal_top_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
