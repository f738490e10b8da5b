/* Tests of Whitted shading (src/render/shade.c) through scenes written in
 * the model grammar and rendered with the public API: shadow acne and light
 * leaks at tiny and huge scene scales, mirror reflection, refraction through
 * the spans of a drilled glass block, Fresnel at normal incidence, total
 * internal reflection, the depth limit, soft shadows from sphere lights and
 * the scene's own camera and background.
 *
 * The checks use materials whose colour is known exactly: a surface with
 * ambient 1 and no other term shows its base colour whatever the lights do,
 * and a glass with only transmit passes the Fresnel share of what lies
 * behind it. Colours are linear in the framebuffer: a display value v in the
 * file is color_srgb_to_linear(v) there.
 */
#define PI 3.14159265358979323846

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/color.h"
#include "render/render.h"
#include "spancast/spancast.h"

/* Loads text, applies its camera, renders w x h with the given spp and max
 * depth (the image's other options at their defaults). */
static sc_framebuffer *render_text(const char *text, int w, int h, int spp, int depth)
{
    sc_scene *scene = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("t.csg", text, strlen(text), NULL, &scene, &e);
    if (st != SC_OK)
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    sc_render_options o;
    sc_render_options_init(&o);
    assert_int_equal(sc_render_options_from_scene(&o, scene), 1);
    o.width = w;
    o.height = h;
    o.spp = spp;
    o.max_depth = depth;
    o.want_mask = 1;
    sc_framebuffer *fb = NULL;
    st = sc_render(scene, &o, &fb, &e);
    if (st != SC_OK)
        fail_msg("%s", e.message);
    sc_scene_release(scene);
    return fb;
}

static int close_to(double a, double b)
{
    return fabs(a - b) <= 1e-6 * fmax(1.0, fabs(b));
}

/* ---- shadow acne ---- */

/* A slab tilted by an arbitrary rotation (so hit points carry rounding
 * error in every coordinate), lit by a directional light 2 degrees above
 * its top face, seen from straight above. The top face is flat and nothing
 * shadows it: every pixel must get the same, lit colour. A shadow ray that
 * started on or under the surface would find the slab and leave dark
 * speckles. Run at scene sizes 1e-3 and 1e4. */
static void check_no_acne(double size)
{
    /* Rotation: 30 degrees about x, then 20 about z. */
    double cx = cos(30 * PI / 180), sx = sin(30 * PI / 180);
    double cz = cos(20 * PI / 180), sz = sin(20 * PI / 180);
    double m[3][3] = {{cz, -sz * cx, sz * sx}, {sz, cz * cx, -cz * sx}, {0, sx, cx}};
    double up[3] = {m[0][2], m[1][2], m[2][2]};    /* the top face's normal */
    double along[3] = {m[0][0], m[1][0], m[2][0]}; /* a direction in it */
    double g = 2 * PI / 180;
    double centre[3] = {0.3 * size, -0.2 * size, 0.1 * size};
    char text[2048];
    snprintf(
        text, sizeof text,
        "camera(eye = [%.17g, %.17g, %.17g], center = [%.17g, %.17g, %.17g], "
        "up = [%.17g, %.17g, %.17g], fov = 10);\n"
        "light(direction = [%.17g, %.17g, %.17g]);\n"
        "material(color = [0.8, 0.8, 0.8], ambient = 0, diffuse = 1, specular = 0) {\n"
        "  multmatrix([[%.17g, %.17g, %.17g, %.17g], [%.17g, %.17g, %.17g, %.17g],\n"
        "              [%.17g, %.17g, %.17g, %.17g], [0, 0, 0, 1]]) {\n"
        "    cube(size = [%.17g, %.17g, %.17g], center = true);\n"
        "  }\n"
        "}\n",
        centre[0] + 3 * size * up[0], centre[1] + 3 * size * up[1],
        centre[2] + 3 * size * up[2], centre[0], centre[1], centre[2], along[0], along[1],
        along[2], -(cos(g) * along[0] + sin(g) * up[0]),
        -(cos(g) * along[1] + sin(g) * up[1]), -(cos(g) * along[2] + sin(g) * up[2]),
        m[0][0] * size, m[0][1] * size, m[0][2] * size, centre[0] - 0.05 * size * up[0],
        m[1][0] * size, m[1][1] * size, m[1][2] * size, centre[1] - 0.05 * size * up[1],
        m[2][0] * size, m[2][1] * size, m[2][2] * size, centre[2] - 0.05 * size * up[2],
        1.0, 1.0, 0.1);
    sc_framebuffer *fb = render_text(text, 64, 48, 1, 0);
    double lit = color_srgb_to_linear(0.8) * sin(g);
    size_t n = (size_t)fb->width * fb->height, dark = 0;
    for (size_t p = 0; p < n; p++) {
        assert_int_equal(fb->mask[p], 255);
        if (!close_to(fb->color[3 * p], lit))
            dark++;
    }
    if (dark)
        fail_msg("size %g: %zu of %zu pixels show shadow acne", size, dark, n);
    sc_framebuffer_release(fb);
}

static void test_no_acne(void **state)
{
    (void)state;
    check_no_acne(1e-3);
    check_no_acne(1e4);
}

/* ---- light leaks ---- */

/* A closed hollow box with walls `wall` thick, the camera inside, a point
 * light, a sphere light and a grazing directional light outside. No light
 * reaches the inside: every pixel must show the ambient term alone. A
 * secondary ray origin pushed through the wall would let light in. */
static void check_no_leak(double size, double wall)
{
    double h = size / 2, in = h - wall;
    char text[2048];
    snprintf(text, sizeof text,
             "camera(eye = [0, 0, %.17g], center = [%.17g, %.17g, %.17g], fov = 100);\n"
             "light(position = [%.17g, %.17g, %.17g]);\n"
             "light(position = [%.17g, %.17g, %.17g], radius = %.17g);\n"
             "light(direction = [-1, -0.3, -0.001]);\n"
             "material(color = [0.5, 0.5, 0.5], ambient = 0.2, diffuse = 0.8) {\n"
             "  difference() {\n"
             "    cube(size = %.17g, center = true);\n"
             "    cube(size = %.17g, center = true);\n"
             "  }\n"
             "}\n",
             0.4 * size, 0.3 * size, 0.1 * size, -0.3 * size, 0.2 * size, 0.3 * size,
             1.5 * size, -1.2 * size, 0.1 * size, 0.2 * size, 0.2 * size, 2 * h, 2 * in);
    sc_framebuffer *fb = render_text(text, 48, 48, 4, 0);
    double ambient = 0.2 * color_srgb_to_linear(0.5);
    size_t n = (size_t)fb->width * fb->height, leaks = 0;
    for (size_t p = 0; p < n; p++) {
        assert_int_equal(fb->mask[p], 255);
        for (int k = 0; k < 3; k++)
            if (!close_to(fb->color[3 * p + k], ambient))
                leaks++;
    }
    if (leaks)
        fail_msg("size %g, wall %g: light leaks into %zu pixel channels", size, wall,
                 leaks);
    sc_framebuffer_release(fb);
}

static void test_no_leak(void **state)
{
    (void)state;
    check_no_leak(1e-3, 1e-6); /* a wall 1e-3 of the scene */
    check_no_leak(1e4, 10);    /* the same, scaled up */
    check_no_leak(1e4, 1e-3);  /* a wall 1e-3 thick in a scene 1e4 across */
}

/* ---- reflection and refraction ---- */

/* A wall of display colour [0.2, 0.4, 0.6] shows its base colour exactly
 * (ambient 1); the background is black. */
static const char backdrop[] =
    "background(color = [0, 0, 0]);\n"
    "light(direction = [0, 0, -1]);\n"
    "material(color = [0.2, 0.4, 0.6], ambient = 1, diffuse = 0, specular = 0) {\n"
    "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 30], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
    "    cube(size = [100, 2, 100], center = true);\n"
    "  }\n"
    "}\n";

static void expect_wall(const sc_framebuffer *fb, double factor)
{
    static const double wall[3] = {0.2, 0.4, 0.6};
    for (int k = 0; k < 3; k++) {
        double want = factor * color_srgb_to_linear(wall[k]);
        if (!close_to(fb->color[k], want))
            fail_msg("channel %d: got %.9g, expected %.9g", k, fb->color[k], want);
    }
}

/* A mirror at 45 degrees turns the camera's view (along +x) to the wall
 * (along +y): the pixel shows the wall; without reflection it is black. */
static void test_mirror(void **state)
{
    (void)state;
    char text[2048];
    const char *mirror =
        "camera(eye = [-20, 0, 0], center = [0, 0, 0]);\n"
        "material(color = [1, 1, 1], ambient = 0, diffuse = 0, specular = 0, "
        "reflect = %s) {\n"
        "  multmatrix([[0.707106781186548, 0.707106781186548, 0, 0],\n"
        "              [-0.707106781186548, 0.707106781186548, 0, 0],\n"
        "              [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    cube(size = [1, 10, 10], center = true);\n"
        "  }\n"
        "}\n%s";
    snprintf(text, sizeof text, mirror, "1", backdrop);
    sc_framebuffer *fb = render_text(text, 1, 1, 1, 5);
    expect_wall(fb, 1.0);
    sc_framebuffer_release(fb);
    snprintf(text, sizeof text, mirror, "0.5", backdrop);
    fb = render_text(text, 1, 1, 1, 5);
    expect_wall(fb, 0.5);
    sc_framebuffer_release(fb);
    snprintf(text, sizeof text, mirror, "0", backdrop);
    fb = render_text(text, 1, 1, 1, 5);
    expect_wall(fb, 0.0);
    sc_framebuffer_release(fb);
}

/* The camera looks along +y through a glass block with a hole drilled
 * along z through its centre, at the wall behind. The centre ray crosses
 * four surfaces at normal incidence (into the glass, out into the hole,
 * into the glass, out), each passing 1 - R0, R0 = ((1.5 - 1) / 2.5)^2 =
 * 0.04. With max depth 4 exactly the straight path reaches the wall, so the
 * pixel is 0.96^4 of the wall. A tracer that ignored the hole (taking the
 * far face as the exit) would cross two surfaces and show 0.96^2; with max
 * depth 3 the ray stops inside the glass and the pixel is black. */
static void test_refraction_through_drilled_block(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text,
             "camera(eye = [0, -40, 0], center = [0, 0, 0]);\n"
             "material(color = [1, 1, 1], ambient = 0, diffuse = 0, specular = 0, "
             "transmit = 1, ior = 1.5) {\n"
             "  difference() {\n"
             "    cube(size = [10, 10, 10], center = true);\n"
             "    cylinder(h = 20, r1 = 2, r2 = 2, center = true);\n"
             "  }\n"
             "}\n%s",
             backdrop);
    sc_framebuffer *fb = render_text(text, 1, 1, 1, 4);
    expect_wall(fb, pow(0.96, 4));
    sc_framebuffer_release(fb);
    fb = render_text(text, 1, 1, 1, 3);
    expect_wall(fb, 0.0);
    sc_framebuffer_release(fb);
}

/* From inside a glass block, the camera looks up at its top face 60
 * degrees from the normal, beyond the critical angle asin(1 / 1.5) = 41.8:
 * all light reflects, back and forth between top and bottom until the
 * depth limit, and the red ceiling above stays invisible (black pixel).
 * With ior 1 nothing reflects and the ray reaches the ceiling. */
static void test_total_internal_reflection(void **state)
{
    (void)state;
    const char *scene =
        "camera(eye = [0, 0, 0], center = [0.866025403784439, 0, 0.5]);\n"
        "background(color = [0, 0, 0]);\n"
        "light(direction = [0, 0, -1]);\n"
        "material(color = [1, 1, 1], ambient = 0, diffuse = 0, specular = 0, "
        "transmit = 1, ior = %s) {\n"
        "  cube(size = [1000, 1000, 2], center = true);\n"
        "}\n"
        "material(color = [0.2, 0.4, 0.6], ambient = 1, diffuse = 0, specular = 0) {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 10], [0, 0, 0, 1]]) {\n"
        "    cube(size = [1000, 1000, 1], center = true);\n"
        "  }\n"
        "}\n";
    char text[2048];
    snprintf(text, sizeof text, scene, "1.5");
    sc_framebuffer *fb = render_text(text, 1, 1, 1, 8);
    expect_wall(fb, 0.0);
    sc_framebuffer_release(fb);
    snprintf(text, sizeof text, scene, "1");
    fb = render_text(text, 1, 1, 1, 8);
    expect_wall(fb, 1.0);
    sc_framebuffer_release(fb);
}

/* Between two parallel mirrors of reflect 0.5 the camera ray bounces for
 * ever; the k-th mirror ray carries 0.5^k of the pixel, so with the
 * throughput cut-off at 1/1000 exactly 9 are cast (0.5^9 > 1/1000 >
 * 0.5^10), however deep --max-depth allows, and max depth 3 allows 3. */
static uint64_t mirror_rays(int max_depth)
{
    static const char text[] =
        "camera(eye = [0, 0, 0], center = [1, 0, 0]);\n"
        "light(direction = [0, 0, -1]);\n"
        "material(reflect = 0.5) {\n"
        "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    cube(size = [1, 100, 100], center = true);\n"
        "  }\n"
        "  multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    cube(size = [1, 100, 100], center = true);\n"
        "  }\n"
        "}\n";
    sc_framebuffer *fb = render_text(text, 1, 1, 1, max_depth);
    uint64_t rays = fb->stats.reflection_rays;
    sc_framebuffer_release(fb);
    return rays;
}

static void test_depth_and_cutoff(void **state)
{
    (void)state;
    assert_int_equal(mirror_rays(64), 9);
    assert_int_equal(mirror_rays(3), 3);
    assert_int_equal(mirror_rays(0), 0);
}

/* ---- soft shadows ---- */

/* The middle row of a view from above of a floor with a wall on it, lit
 * from far off at the side: pixels strictly between shadow and full light
 * (more than 5% and less than 95% of the brightest) form the penumbra. A
 * point light's shadow edge is sharp (only antialiasing blurs it, over a
 * pixel or two); a sphere light sampled per pixel sample spreads it over
 * the width its angular size gives (about 16 pixels here). */
static int penumbra_pixels(const char *light)
{
    char text[2048];
    snprintf(
        text, sizeof text,
        "camera(eye = [-4, 0, 30], center = [-4, 0, 0], up = [0, 1, 0], "
        "projection = \"orthographic\", fov = 20);\n"
        "%s\n"
        "material(color = [1, 1, 1], ambient = 0, diffuse = 1, specular = 0) {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
        "    cube(size = [100, 100, 2], center = true);\n"
        "  }\n"
        "  multmatrix([[1, 0, 0, -20], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
        "    cube(size = [2, 100, 10], center = true);\n"
        "  }\n"
        "}\n",
        light);
    sc_framebuffer *fb = render_text(text, 80, 60, 16, 0);
    const float *row = fb->color + 3 * 30 * 80;
    float brightest = 0;
    for (int i = 0; i < 80; i++)
        brightest = fmaxf(brightest, row[3 * i]);
    int count = 0;
    for (int i = 0; i < 80; i++)
        count += row[3 * i] > 0.05f * brightest && row[3 * i] < 0.95f * brightest;
    sc_framebuffer_release(fb);
    return count;
}

static void test_soft_shadows(void **state)
{
    (void)state;
    int hard = penumbra_pixels("light(position = [-6000, 0, 4000]);");
    int soft = penumbra_pixels("light(position = [-6000, 0, 4000], radius = 600);");
    assert_true(hard <= 2);
    assert_true(soft >= 8);
}

/* ---- OpenSCAD's lighting and ambient occlusion ---- */

/* Renders text from eye at centre (orthographic, 120 x 90) with options
 * set by the caller's flags; every buffer but id. */
static sc_framebuffer *render_look(const char *text, const double eye_centre[6],
                                   int preview, int ao)
{
    sc_scene *scene = NULL;
    sc_error e;
    if (sc_scene_load_string("t.csg", text, strlen(text), NULL, &scene, &e) != SC_OK)
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    sc_render_options o;
    sc_render_options_init(&o);
    o.camera_mode = SC_CAMERA_VECTOR;
    memcpy(o.camera, eye_centre, 6 * sizeof *eye_centre);
    o.projection = SC_PROJECTION_ORTHOGRAPHIC;
    o.width = 120;
    o.height = 90;
    o.want_mask = o.want_normal = 1;
    o.lighting = SC_LIGHTING_OPENSCAD;
    o.preview = preview;
    o.ao_samples = ao;
    o.threads = 2;
    sc_framebuffer *fb = NULL;
    if (sc_render(scene, &o, &fb, &e) != SC_OK)
        fail_msg("%s", e.message);
    sc_scene_release(scene);
    return fb;
}

/* OpenSCAD lights with two lights fixed to the camera, towards (-1, 1, 1)
 * and (1, -1, -1) in eye coordinates (x right, y up, z towards the
 * viewer), diffuse 1 on top of an ambient 0.2, on display values; its
 * preview shader with the first light alone, two-sided. Every pixel of a
 * box seen from a corner, against those formulas with the normals the
 * render reports. */
static void test_openscad_lighting(void **state)
{
    (void)state;
    const char *text =
        "color([0.6, 0.3, 0.9, 1]) { cube(size = [10, 8, 6], center = true); }\n";
    const double view[6] = {40, -30, 25, 0, 0, 0};
    const double base[3] = {0.6, 0.3, 0.9};
    vec3 e = v3(view[0], view[1], view[2]);
    vec3 f = v3_normalize(v3_neg(e));
    vec3 r = v3_normalize(v3_cross(f, v3(0, 0, 1))), u = v3_cross(r, f);
    /* towards the lights, in world coordinates */
    vec3 l0 = v3_normalize(v3_add(v3_add(v3_neg(r), u), v3_neg(f)));
    vec3 l1 = v3_neg(l0);
    for (int preview = 0; preview <= 1; preview++) {
        sc_framebuffer *fb = render_look(text, view, preview, 0);
        int hits = 0;
        for (int p = 0; p < fb->width * fb->height; p++) {
            if (!fb->mask[p])
                continue;
            hits++;
            vec3 n = v3(fb->normal[3 * p], fb->normal[3 * p + 1], fb->normal[3 * p + 2]);
            double factor = preview
                                ? 0.2 + fabs(v3_dot(n, l0))
                                : 0.2 + fmax(0, v3_dot(n, l0)) + fmax(0, v3_dot(n, l1));
            for (int k = 0; k < 3; k++) {
                double want = color_srgb_to_linear(fmin(1.0, base[k] * factor));
                if (!close_to(fb->color[3 * p + k], want))
                    fail_msg("preview %d pixel %d channel %d: %g, expected %g", preview,
                             p, k, fb->color[3 * p + k], want);
            }
        }
        assert_true(hits > 1000);
        sc_framebuffer_release(fb);
    }
}

/* Ambient occlusion darkens the floor beside a wall and leaves open floor,
 * whose rays all escape, exactly as it is without it. */
static void test_ambient_occlusion(void **state)
{
    (void)state;
    const char *text =
        "cube(size = [40, 40, 1]);\n"
        "multmatrix([[1, 0, 0, 18], [0, 1, 0, 18], [0, 0, 1, 1], [0, 0, 0, 1]]) {\n"
        "    cube(size = [4, 4, 10]);\n"
        "}\n";
    const double view[6] = {20, 20, 60, 20, 20, 0}; /* straight down */
    sc_framebuffer *plain = render_look(text, view, 0, 0);
    sc_framebuffer *ao = render_look(text, view, 0, 64);
    /* The image spans 2 tan(11.25 deg) 60 = 23.9 units over 90 rows, 0.265
     * a pixel, centred on (20, 20). */
    double pixel = 2 * tan(22.5 / 2 * PI / 180) * 60 / 90;
    int open_row = 45, open_col = (int)(60 + 10 / pixel); /* x = 30: 8 from the wall */
    int corner_col = (int)(60 + 2.3 / pixel);             /* x = 22.3: beside it */
    size_t open = (size_t)open_row * 120 + open_col,
           corner = (size_t)45 * 120 + corner_col;
    assert_int_equal(plain->mask[open], 255);
    assert_int_equal(plain->mask[corner], 255);
    assert_true(fabs(plain->normal[3 * corner + 2] - 1) <
                1e-12); /* floor, not the wall */
    for (int k = 0; k < 3; k++) {
        assert_true(ao->color[3 * open + k] == plain->color[3 * open + k]);
        assert_true(ao->color[3 * corner + k] < 0.9 * plain->color[3 * corner + k]);
    }
    sc_framebuffer_release(plain);
    sc_framebuffer_release(ao);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_no_acne),
        cmocka_unit_test(test_no_leak),
        cmocka_unit_test(test_mirror),
        cmocka_unit_test(test_refraction_through_drilled_block),
        cmocka_unit_test(test_total_internal_reflection),
        cmocka_unit_test(test_depth_and_cutoff),
        cmocka_unit_test(test_soft_shadows),
        cmocka_unit_test(test_openscad_lighting),
        cmocka_unit_test(test_ambient_occlusion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
