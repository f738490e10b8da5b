/* Tests of distribution ray tracing (docs/distribution.md): glossy
 * reflection and transmission, rectangular area lights, the thin-lens
 * camera, and the stratified dimensions they draw (src/render/sample.h).
 *
 * Each effect is checked against an analytic figure measured on the image,
 * not against a stored picture: the energy a glossy lobe keeps under a
 * white sky against a quadrature of the lobe, the width of an area light's
 * penumbra against similar triangles, the width of a defocused edge
 * against the thin lens's circle of confusion. Widths are measured as the
 * standard deviation of the edge's spread (the derivative of a row-averaged
 * profile), which uses every pixel of the transition instead of two
 * thresholds, less the pixel filter's own share (a box one pixel wide has
 * variance 1/12 pixel^2).
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
#include "render/sample.h"
#include "spancast/spancast.h"

/* Extra options for a render: what the caller sets beyond the size. */
typedef struct extra {
    double aperture, focus; /* < 0: leave as the scene has them */
    double shutter[2];      /* open, close */
    int threads;            /* 0: all cores */
    int region[4];          /* all 0: the whole image */
} extra;

static const extra none = {-1, -1, {0, 0}, 0, {0, 0, 0, 0}};

/* Loads text, applies its camera, renders w x h at spp samples. */
static sc_framebuffer *render_with(const char *text, int w, int h, int spp, extra x)
{
    sc_scene *scene = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("t.csg", text, strlen(text), NULL, &scene, &e);
    if (st != SC_OK)
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    sc_render_options o;
    sc_render_options_init(&o);
    sc_render_options_from_scene(&o, scene);
    o.width = w;
    o.height = h;
    o.spp = spp;
    if (x.aperture >= 0)
        o.aperture = x.aperture;
    if (x.focus >= 0)
        o.focus = x.focus;
    o.threads = x.threads;
    o.shutter[0] = x.shutter[0];
    o.shutter[1] = x.shutter[1];
    memcpy(o.region, x.region, sizeof o.region);
    sc_framebuffer *fb = NULL;
    st = sc_render(scene, &o, &fb, &e);
    if (st != SC_OK)
        fail_msg("%s", e.message);
    sc_scene_release(scene);
    return fb;
}

static sc_framebuffer *render_text(const char *text, int w, int h, int spp)
{
    return render_with(text, w, h, spp, none);
}

/* The error loading text gives: "line:col: message". */
static void load_error(const char *text, char *out, size_t size)
{
    sc_scene *scene = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("t.csg", text, strlen(text), NULL, &scene, &e);
    assert_int_not_equal(st, SC_OK);
    snprintf(out, size, "%d:%d: %s", e.line, e.column, e.message);
}

/* The red channel of fb averaged over its rows, per column; caller frees. */
static double *column_profile(const sc_framebuffer *fb)
{
    double *p = calloc((size_t)fb->width, sizeof *p);
    assert_non_null(p);
    for (int j = 0; j < fb->height; j++)
        for (int i = 0; i < fb->width; i++)
            p[i] += fb->color[3 * ((size_t)j * fb->width + i)] / fb->height;
    return p;
}

/* The width in pixels of a ramp in profile p[0..n) from lo to hi: the
 * standard deviation of the profile's derivative, with the pixel box's
 * 1/12 taken off, times sqrt(12) (a linear ramp of width W has variance
 * W^2 / 12). *sigma gets the standard deviation alone. */
static double ramp_sigma(const double *p, int n)
{
    double lo = p[0], hi = p[n - 1];
    double sum = 0, mean = 0, second = 0;
    for (int i = 0; i + 1 < n; i++) {
        double w = (p[i + 1] - p[i]) / (hi - lo);
        double x = i + 1; /* the boundary between pixels i and i + 1 */
        sum += w;
        mean += w * x;
        second += w * x * x;
    }
    mean /= sum;
    double var = second / sum - mean * mean - 1.0 / 12;
    return sqrt(fmax(0.0, var));
}

/* ---- stratification ---- */

/* sample_permute is a permutation of 0..n-1 for every n and seed, and
 * sample_2d hands each of a pixel's n samples a different cell of the
 * grid in every dimension. */
static void test_permutation(void **state)
{
    (void)state;
    for (uint32_t n = 1; n <= 70; n++) {
        for (uint64_t seed = 1; seed < 40; seed++) {
            unsigned char seen[70] = {0};
            for (uint32_t s = 0; s < n; s++) {
                uint32_t i = sample_permute(s, n, sample_mix(seed));
                assert_true(i < n);
                assert_int_equal(seen[i], 0);
                seen[i] = 1;
            }
        }
    }
    int n = 24, kx = sample_grid_width(n), ky = n / kx;
    for (uint32_t dim = 0; dim < 6; dim++) {
        unsigned char seen[24] = {0};
        for (int s = 0; s < n; s++) {
            sample_pixel px = {7, 9, s, n, kx, dim};
            sample_rng r = sample_rng_for(7, 9, (uint32_t)s);
            double u, v;
            sample_2d(&px, &r, &u, &v);
            assert_true(u >= 0 && u < 1 && v >= 0 && v < 1);
            int cell = (int)(u * kx) + kx * (int)(v * ky);
            assert_int_equal(seen[cell], 0);
            seen[cell] = 1;
        }
    }
}

/* ---- glossy ---- */

/* A plate seen at 45 degrees by an orthographic camera under a white sky
 * (background 1, no light reaches the plate's colour: ambient, diffuse and
 * specular 0). Every pixel shows what the plate reflects of the sky. */
static sc_framebuffer *furnace(const char *material, int spp)
{
    char text[1024];
    snprintf(text, sizeof text,
             "camera(eye = [0, -50, 50], center = [0, 0, 0], "
             "projection = \"orthographic\", fov = 10);\n"
             "background(color = [1, 1, 1]);\n"
             "material(color = [1, 1, 1], ambient = 0, diffuse = 0, specular = 0, %s) {\n"
             "  cube(size = [1000, 1000, 2], center = true);\n"
             "}\n",
             material);
    return render_text(text, 24, 24, spp);
}

/* The share of the lobe (lobe + 1)/(2 pi) cos^lobe about the mirror
 * direction of a view 45 degrees off the normal that lies above the
 * surface, by a midpoint quadrature over (cos, phi) independent of the
 * renderer's sampling. */
static double lobe_above(double lobe)
{
    const int nc = 2000, np = 720;
    double total = 0, above = 0, s45 = sqrt(0.5);
    for (int a = 0; a < nc; a++) {
        double c = (a + 0.5) / nc;
        double w = (lobe + 1) * pow(c, lobe); /* density in cos, phi uniform */
        double sn = sqrt(1 - c * c);
        for (int b = 0; b < np; b++) {
            double phi = 2 * PI * (b + 0.5) / np;
            /* axis (0, s45, s45) in (x, y, z) with z the plate's normal;
             * e1 = x, e2 = axis x e1 = (0, s45, -s45). */
            double z = c * s45 - sn * sin(phi) * s45;
            total += w;
            above += w * (z > 0);
        }
    }
    return above / total;
}

static double mean_red(const sc_framebuffer *fb, double *lo, double *hi)
{
    size_t n = (size_t)fb->width * fb->height;
    double sum = 0;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t p = 0; p < n; p++) {
        for (int k = 0; k < 3; k++) {
            *lo = fmin(*lo, fb->color[3 * p + k]);
            *hi = fmax(*hi, fb->color[3 * p + k]);
        }
        sum += fb->color[3 * p];
    }
    return sum / n;
}

/* R = 0 is the mirror exactly; every roughness keeps the reflected light
 * within [0, 1] of the sky, at most the mirror's, and keeps the share of
 * its lobe above the surface. */
static void test_glossy_energy(void **state)
{
    (void)state;
    sc_framebuffer *mirror = furnace("reflect = 1", 4);
    sc_framebuffer *zero = furnace("reflect = 1, roughness = 0", 4);
    size_t bytes = (size_t)mirror->width * mirror->height * 3 * sizeof(float);
    assert_memory_equal(mirror->color, zero->color, bytes);
    double lo, hi;
    double mirror_mean = mean_red(mirror, &lo, &hi);
    assert_true(fabs(mirror_mean - 1) < 1e-12);
    const double roughness[] = {0.05, 0.3, 0.6, 1.0};
    for (int k = 0; k < 4; k++) {
        char material[128];
        snprintf(material, sizeof material, "reflect = 1, roughness = %g", roughness[k]);
        sc_framebuffer *fb = furnace(material, 64);
        double mean = mean_red(fb, &lo, &hi);
        double r = roughness[k], expected = lobe_above(2 / (r * r) - 2);
        print_message("roughness %g: keeps %.4f (max %.4f), lobe above %.4f\n", r, mean,
                      hi, expected);
        if (!(lo >= 0 && hi <= 1 + 1e-12 && mean <= mirror_mean + 1e-12))
            fail_msg("roughness %g: values %g..%g, mean %g: outside [0, 1]", r, lo, hi,
                     mean);
        if (fabs(mean - expected) > 0.02)
            fail_msg("roughness %g keeps %g of the sky, the lobe above the surface is %g",
                     r, mean, expected);
        sc_framebuffer_release(fb);
    }
    sc_framebuffer_release(mirror);
    sc_framebuffer_release(zero);
}

/* Transmission through a slab with no interface (ior 1): glossy exits keep
 * the light within [0, 1] and at most what the clear slab passes. */
static void test_glossy_transmission(void **state)
{
    (void)state;
    sc_framebuffer *clear = furnace("transmit = 1, ior = 1", 4);
    sc_framebuffer *rough = furnace("transmit = 1, ior = 1, roughness = 0.5", 64);
    double lo, hi;
    double clear_mean = mean_red(clear, &lo, &hi);
    assert_true(fabs(clear_mean - 1) < 1e-12);
    double mean = mean_red(rough, &lo, &hi);
    assert_true(lo >= 0 && hi <= 1 + 1e-12);
    assert_true(mean <= clear_mean);
    assert_true(mean > 0.3); /* most of the lobe goes on through */
    sc_framebuffer_release(clear);
    sc_framebuffer_release(rough);
}

/* ---- area lights ---- */

/* A floor seen from above (orthographic, 128 x 16 pixels over x in
 * [42, 58]) beside the shadow of a plate's edge at x = 0, 100 above it,
 * lit by the light given. */
static sc_framebuffer *penumbra_scene(const char *light, int spp)
{
    char text[2048];
    snprintf(text, sizeof text,
             "camera(eye = [50, 0, 500], center = [50, 0, 0], up = [0, 1, 0], "
             "projection = \"orthographic\", fov = %.17g);\n"
             "%s\n"
             "material(color = [1, 1, 1], ambient = 0, diffuse = 1, specular = 0) {\n"
             "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
             "    cube(size = [1000, 1000, 2], center = true);\n"
             "  }\n"
             "  multmatrix([[1, 0, 0, -500], [0, 1, 0, -500], [0, 0, 1, 99.99], "
             "[0, 0, 0, 1]]) {\n"
             "    cube(size = [500, 1000, 0.01]);\n"
             "  }\n"
             "}\n",
             2 * atan(1.0 / 500) * 180 / PI, light);
    return render_text(text, 128, 16, spp);
}

/* What a point of the floor at x gets fully lit by a light centred at
 * (-150, 0, 400) facing down: its intensity (1) times the Lambert factors
 * at the light and at the floor, both 400 / r. */
static double fully_lit(double x)
{
    double r2 = (x + 150) * (x + 150) + 400.0 * 400.0;
    return 400.0 * 400.0 / r2;
}

/* The profile of fb as the share of the light seen: each column's value
 * over what it gets fully lit; caller frees. */
static double *share_seen(const sc_framebuffer *fb)
{
    double *p = column_profile(fb);
    for (int i = 0; i < fb->width; i++)
        p[i] /= fully_lit(42 + (i + 0.5) * 16.0 / fb->width);
    return p;
}

/* A 12 x 12 light centred at (-150, 0, 400) facing down: the edge at
 * height 100 casts a penumbra w h / (H - h) = 12 * 100 / 300 = 4 wide on
 * the floor (x from 48 to 52), 32 pixels; the share of the light seen
 * grows linearly across it, so the profile is a ramp of that width. */
static void test_area_penumbra(void **state)
{
    (void)state;
    sc_framebuffer *fb =
        penumbra_scene("light(position = [-150, 0, 400], size = [12, 12], "
                       "normal = [0, 0, -1]);",
                       16);
    double *p = share_seen(fb);
    double width = sqrt(12) * ramp_sigma(p, fb->width);
    double expected = 4.0 / (16.0 / 128);
    print_message("penumbra %.3f pixels wide, expected %.3f\n", width, expected);
    if (fabs(width - expected) > 0.1 * expected)
        fail_msg("penumbra %g pixels wide, expected %g", width, expected);
    /* Fully lit and fully shadowed on either side, whatever the size: the
     * intensity is the whole light's. */
    for (int i = 0; i < 40; i++)
        assert_true(p[i] == 0);
    for (int i = 90; i < fb->width; i++)
        assert_true(fabs(p[i] - 1) < 0.005);
    sc_framebuffer_release(fb);
    free(p);
    sc_framebuffer *small =
        penumbra_scene("light(position = [-150, 0, 400], size = [0.5, 0.5], "
                       "normal = [0, 0, -1]);",
                       4);
    double *q = share_seen(small);
    for (int i = 90; i < small->width; i++)
        assert_true(fabs(q[i] - 1) < 0.005);
    /* A small light's shadow edge is sharp: under 2 pixels wide. */
    double narrow = sqrt(12) * ramp_sigma(q, small->width);
    assert_true(narrow < 2);
    sc_framebuffer_release(small);
    free(q);
}

/* The light emits on its normal's side only: turned to face up, it lights
 * nothing below it. */
static void test_area_one_sided(void **state)
{
    (void)state;
    sc_framebuffer *fb =
        penumbra_scene("light(position = [-150, 0, 400], size = [12, 12], "
                       "normal = [0, 0, 1]);",
                       4);
    size_t n = (size_t)fb->width * fb->height;
    for (size_t k = 0; k < 3 * n; k++)
        assert_true(fb->color[k] == 0);
    sc_framebuffer_release(fb);
}

static void test_area_errors(void **state)
{
    (void)state;
    char msg[1024];
    load_error("light(direction = [0, 0, -1], size = [1, 1]);", msg, sizeof msg);
    assert_string_equal(msg, "1:38: a directional light has no size");
    load_error("light(position = [0, 0, 1], radius = 1, size = [1, 1]);", msg,
               sizeof msg);
    assert_string_equal(msg, "1:48: a light has a radius or a size, not both");
    load_error("light(position = [0, 0, 1], size = [1, 0]);", msg, sizeof msg);
    assert_string_equal(msg, "1:40: wrong type for argument 'size' of 'light' "
                             "(expected a vector of 2 positive numbers)");
    load_error("light(position = [0, 0, 1], normal = [0, 0, 1]);", msg, sizeof msg);
    assert_string_equal(msg, "1:38: only a light with a size has a normal and an up "
                             "direction");
    load_error("light(position = [0, 0, 1], size = [1, 1], normal = [1, 0, 0], "
               "up = [2, 0, 0]);",
               msg, sizeof msg);
    assert_string_equal(msg, "1:69: the up direction of a light must not be parallel "
                             "to its normal");
    load_error("material(roughness = 2) { cube(); }", msg, sizeof msg);
    assert_string_equal(msg, "1:22: argument 'roughness' of 'material' must be a number "
                             "in 0..1");
}

/* ---- depth of field ---- */

/* A white plate (x < 0, facing the camera) whose face lies at distance
 * depth from the eye, on black, seen by a perspective camera 100 from the
 * origin whose pixels are 0.1 wide at that distance. */
static sc_framebuffer *plate(double depth, double aperture, double focus, int spp)
{
    char text[1024];
    snprintf(text, sizeof text,
             "camera(eye = [0, 0, 100], center = [0, 0, 0], up = [0, 1, 0], "
             "fov = %.17g);\n"
             "background(color = [0, 0, 0]);\n"
             "material(color = [1, 1, 1], ambient = 1, diffuse = 0, specular = 0) {\n"
             "  multmatrix([[1, 0, 0, -1000], [0, 1, 0, -1000], [0, 0, 1, %.17g], "
             "[0, 0, 0, 1]]) {\n"
             "    cube(size = [1000, 2000, 0.001]);\n"
             "  }\n"
             "}\n",
             2 * atan(0.008) * 180 / PI, 100 - depth - 0.001);
    extra x = none;
    x.aperture = aperture;
    x.focus = focus;
    return render_with(text, 128, 16, spp, x);
}

/* The profile of fb from white to black, as the share of white. */
static double *falling(const sc_framebuffer *fb)
{
    double *p = column_profile(fb);
    for (int i = 0; i < fb->width; i++)
        p[i] = 1 - p[i];
    return p;
}

/* A plate at the focus distance stays as sharp as through a pinhole: the
 * lens moves the ray but not the point it reaches at that distance. (The
 * plate is thin: a lens sees around a thick plate's edge onto its side.) */
static void test_focus_sharp(void **state)
{
    (void)state;
    sc_framebuffer *pin = plate(100, 0, 0, 16);
    sc_framebuffer *lens = plate(100, 6, 100, 16);
    double *a = falling(pin), *b = falling(lens);
    double sa = ramp_sigma(a, pin->width), sb = ramp_sigma(b, lens->width);
    assert_true(fabs(sa - sb) < 0.01);
    for (int i = 0; i < pin->width; i++)
        assert_true(fabs(a[i] - b[i]) < 1.0 / 16);
    sc_framebuffer_release(pin);
    sc_framebuffer_release(lens);
    free(a);
    free(b);
}

/* A plate at 150 seen focused at 100: a point spreads over the circle of
 * confusion, A |z - D| / z = A / 3 wide on the focal plane, A / 0.3
 * pixels. An edge's spread is the disc's chord profile, whose standard
 * deviation is a quarter of the diameter. The width grows with the
 * aperture and matches within 10 %. */
static void test_defocus_width(void **state)
{
    (void)state;
    const double apertures[] = {3, 6};
    for (int k = 0; k < 2; k++) {
        double aperture = apertures[k];
        sc_framebuffer *fb = plate(150, aperture, 100, 64);
        double *p = falling(fb);
        double measured = 4 * ramp_sigma(p, fb->width);
        double expected = aperture / 3 / 0.1;
        print_message("aperture %g: blur %.3f pixels, circle of confusion %.3f\n",
                      aperture, measured, expected);
        if (fabs(measured - expected) > 0.1 * expected)
            fail_msg("aperture %g: blur %g pixels wide, circle of confusion %g", aperture,
                     measured, expected);
        sc_framebuffer_release(fb);
        free(p);
    }
    /* Without a focus distance the lens focuses on the view's centre (the
     * origin, 100 away): the same blur. */
    sc_framebuffer *a = plate(150, 6, 100, 16), *b = plate(150, 6, 0, 16);
    size_t bytes = (size_t)a->width * a->height * 3 * sizeof(float);
    assert_memory_equal(a->color, b->color, bytes);
    sc_framebuffer_release(a);
    sc_framebuffer_release(b);
}

/* ---- motion blur ---- */

/* A white box 4 wide moving by the motion given, on black, seen from the
 * front by an orthographic camera over x in [-20, 20] (0.25 a pixel), with
 * the shutter given. */
static sc_framebuffer *moving_box(const char *motion, double open, double close, int spp)
{
    char text[1024];
    snprintf(text, sizeof text,
             "camera(eye = [0, -60, 0], center = [0, 0, 0], up = [0, 0, 1], "
             "projection = \"orthographic\", fov = %.17g);\n"
             "background(color = [0, 0, 0]);\n"
             "material(color = [1, 1, 1], ambient = 1, diffuse = 0, specular = 0) {\n"
             "  motion(%s) { cube(size = 4, center = true); }\n"
             "}\n",
             2 * atan(1.0 / 60) * 180 / PI, motion);
    extra x = none;
    x.shutter[0] = open;
    x.shutter[1] = close;
    return render_with(text, 160, 8, spp, x);
}

static const char slide[] = "from = [[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], "
                            "[0, 0, 0, 1]], to = [[1, 0, 0, 5], [0, 1, 0, 0], "
                            "[0, 0, 1, 0], [0, 0, 0, 1]]";

/* The share of the shutter during which a box 4 wide whose centre moves
 * from -5 to 5 covers x: its overlap with [x - 2, x + 2] over 10. */
static double swept(double x)
{
    double lo = fmax(-5, x - 2), hi = fmin(5, x + 2);
    return fmax(0.0, hi - lo) / 10;
}

/* A box moving along x: the coverage across the image is the swept
 * trapezoid, and its integral the box's width; the whole motion is inside
 * the bounds (nothing is clipped at the end the box moves to). A closed
 * shutter shows the box where from puts it. */
static void test_motion_swept(void **state)
{
    (void)state;
    sc_framebuffer *fb = moving_box(slide, 0, 1, 64);
    double *p = column_profile(fb);
    double integral = 0, worst = 0;
    for (int i = 0; i < fb->width; i++) {
        double x = -20 + (i + 0.5) * 0.25;
        integral += p[i] * 0.25;
        worst = fmax(worst, fabs(p[i] - swept(x)));
    }
    print_message("swept coverage: integral %.4f (box width 4), largest error %.4f\n",
                  integral, worst);
    assert_true(fabs(integral - 4) < 0.02 * 4);
    assert_true(worst < 0.05);
    sc_framebuffer_release(fb);
    free(p);
    sc_framebuffer *closed = moving_box(slide, 0, 0, 4);
    double *q = column_profile(closed);
    for (int i = 0; i < closed->width; i++) {
        double x = -20 + (i + 0.5) * 0.25;
        assert_true(q[i] == (x > -7 && x < -3 ? 1.0 : 0.0));
    }
    sc_framebuffer_release(closed);
    free(q);
}

/* A small cube 10 from the z axis turning 90 degrees about it, seen from
 * above: it sweeps the arc, so the point of the arc at 45 degrees is
 * covered part of the time and the chord's midpoint (7.07 from the axis)
 * never is, as a blend of the two matrices would have it. */
static void test_motion_arc(void **state)
{
    (void)state;
    char text[1024];
    snprintf(
        text, sizeof text,
        "camera(eye = [0, 0, 60], center = [0, 0, 0], up = [0, 1, 0], "
        "projection = \"orthographic\", fov = %.17g);\n"
        "background(color = [0, 0, 0]);\n"
        "material(color = [1, 1, 1], ambient = 1, diffuse = 0, specular = 0) {\n"
        "  motion(from = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],\n"
        "         to = [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "    multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "      cube(size = 1, center = true);\n"
        "    }\n"
        "  }\n"
        "}\n",
        2 * atan(12.0 / 60) * 180 / PI);
    extra x = none;
    x.shutter[1] = 1;
    sc_framebuffer *fb = render_with(text, 96, 96, 64, x);
    /* World (u, v) to pixel: 24 wide over 96 pixels, y up. Coverage along
     * the arc, averaged over the pixels at radius 10 from 15 to 75
     * degrees: the cube's angular width, 1 / 10 rad, over the turn. */
    double on_arc = 0;
    int count = 0;
    for (int deg = 15; deg <= 75; deg += 2, count++) {
        double a = deg * PI / 180;
        int i = (int)((10 * cos(a) + 12) * 4), j = (int)((12 - 10 * sin(a)) * 4);
        on_arc += fb->color[3 * ((size_t)j * 96 + i)];
    }
    on_arc /= count;
    double chord = 5;
    int ci = (int)((chord + 12) * 4), cj = (int)((12 - chord) * 4);
    double on_chord = fb->color[3 * ((size_t)cj * 96 + ci)];
    double expected = 0.1 / (PI / 2);
    print_message("arc %.4f (expected %.4f), chord midpoint %.3f\n", on_arc, expected,
                  on_chord);
    assert_true(fabs(on_arc - expected) < 0.15 * expected);
    assert_true(on_chord == 0);
    sc_framebuffer_release(fb);
}

/* Shadow rays take their camera ray's time: a box moving high over a
 * floor, lit at 45 degrees, casts the swept trapezoid as its shadow, 30
 * further along x (the floor seen from above, away from the box). */
static void test_motion_shadow(void **state)
{
    (void)state;
    char text[2048];
    snprintf(
        text, sizeof text,
        "camera(eye = [30, 0, 60], center = [30, 0, 0], up = [0, 1, 0], "
        "projection = \"orthographic\", fov = %.17g);\n"
        "light(direction = [1, 0, -1]);\n"
        "material(color = [1, 1, 1], ambient = 0, diffuse = 1, specular = 0) {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
        "    cube(size = [400, 400, 2], center = true);\n"
        "  }\n"
        "  motion(from = [[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 30], [0, 0, 0, 1]],\n"
        "         to = [[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 30], [0, 0, 0, 1]]) {\n"
        "    cube(size = [4, 100, 4], center = true);\n"
        "  }\n"
        "}\n",
        2 * atan(1.0 / 60) * 180 / PI);
    extra x = none;
    x.shutter[1] = 1;
    sc_framebuffer *fb = render_with(text, 160, 8, 64, x);
    double *p = column_profile(fb);
    double lit = sqrt(0.5), worst = 0;
    for (int i = 0; i < fb->width; i++) {
        double u = 30 - 20 + (i + 0.5) * 0.25; /* floor x */
        /* The box's bottom face (z 28) shades the floor from x - 28 to
         * its top (z 32) from x - 32: the shadow of a 4 x 4 section at 45
         * degrees is 8 wide at any instant. */
        double covered = 0;
        for (int k = 0; k < 1000; k++) {
            double c = -5 + 10 * (k + 0.5) / 1000; /* the box's centre */
            covered += (u - 32 < c + 2 && u - 28 > c - 2) / 1000.0;
        }
        worst = fmax(worst, fabs(p[i] / lit - (1 - covered)));
    }
    print_message("moving shadow: largest error %.4f\n", worst);
    assert_true(worst < 0.05);
    sc_framebuffer_release(fb);
    free(p);
}

static void test_motion_errors(void **state)
{
    (void)state;
    char msg[1024];
    load_error("motion(from = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
               "{ cube(); }",
               msg, sizeof msg);
    assert_string_equal(msg, "1:1: 'motion' needs from and to");
    load_error("motion(from = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "
               "to = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
               "{ cube(); }",
               msg, sizeof msg);
    assert_string_equal(msg, "1:1: 'motion': from and to must be invertible and agree "
                             "on mirroring");
    load_error(
        "motion(from = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "
        "to = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ motion(from = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "
        "to = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ cube(); } }",
        msg, sizeof msg);
    assert_string_equal(msg, "1:138: a 'motion' inside another 'motion' is not "
                             "supported");
}

/* ---- determinism ---- */

/* Every effect at once, rendered on one thread, on three, and as a crop:
 * the same pixels. */
static void test_deterministic(void **state)
{
    (void)state;
    const char *text =
        "camera(eye = [0, -40, 25], center = [0, 0, 2], aperture = 2, focus = 40);\n"
        "light(position = [0, 0, 30], size = [10, 6], normal = [0, 0, -1]);\n"
        "material(color = [0.8, 0.8, 0.8], reflect = 0.5, roughness = 0.3) {\n"
        "  cube(size = [40, 40, 1], center = true);\n"
        "}\n"
        "material(color = [0.3, 0.4, 0.9], transmit = 0.8, roughness = 0.2) {\n"
        "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
        "    sphere(r = 4);\n"
        "  }\n"
        "  motion(from = [[1, 0, 0, 8], [0, 1, 0, 0], [0, 0, 1, 3], [0, 0, 0, 1]],\n"
        "         to = [[0, -1, 0, 8], [1, 0, 0, 4], [0, 0, 1, 3], [0, 0, 0, 1]]) {\n"
        "    cube(size = [4, 1, 2], center = true);\n"
        "  }\n"
        "}\n";
    extra one = none, three = none, crop = none;
    one.threads = 1;
    three.threads = 3;
    one.shutter[1] = three.shutter[1] = crop.shutter[1] = 1;
    int region[4] = {11, 7, 37, 29};
    memcpy(crop.region, region, sizeof region);
    sc_framebuffer *a = render_with(text, 48, 36, 9, one);
    sc_framebuffer *b = render_with(text, 48, 36, 9, three);
    sc_framebuffer *c = render_with(text, 48, 36, 9, crop);
    size_t bytes = (size_t)a->width * a->height * 3 * sizeof(float);
    assert_memory_equal(a->color, b->color, bytes);
    for (int j = 0; j < c->height; j++)
        assert_memory_equal(c->color + 3 * (size_t)j * c->width,
                            a->color + 3 * ((size_t)(j + 7) * a->width + 11),
                            3 * sizeof(float) * c->width);
    sc_framebuffer_release(a);
    sc_framebuffer_release(b);
    sc_framebuffer_release(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_permutation),         cmocka_unit_test(test_glossy_energy),
        cmocka_unit_test(test_glossy_transmission), cmocka_unit_test(test_area_penumbra),
        cmocka_unit_test(test_area_one_sided),      cmocka_unit_test(test_area_errors),
        cmocka_unit_test(test_focus_sharp),         cmocka_unit_test(test_defocus_width),
        cmocka_unit_test(test_motion_swept),        cmocka_unit_test(test_motion_arc),
        cmocka_unit_test(test_motion_shadow),       cmocka_unit_test(test_motion_errors),
        cmocka_unit_test(test_deterministic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
