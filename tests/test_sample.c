/* Tests of sampling (src/render/sample.h) and of what it promises the
 * render loop: stratified samples fill their cells, the generator depends
 * only on (pixel, sample), and so an image rendered with several samples
 * per pixel and a sphere light is the same byte for byte with one thread or
 * two, and a --region crop equals the same crop of the full image. Also the
 * render's counters and the id AOV.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render.h"
#include "render/sample.h"
#include "spancast/spancast.h"

/* A scene with soft shadows, a mirror and glass, so every kind of random
 * number and ray is used. */
static const char scene_text[] =
    "camera(eye = [30, -40, 25], center = [0, 0, 3]);\n"
    "light(position = [-20, -10, 40], radius = 5);\n"
    "material(color = [0.9, 0.9, 0.9], color2 = [0.3, 0.3, 0.3], checker = 4) {\n"
    "  multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
    "    cube(size = [60, 60, 2], center = true);\n"
    "  }\n"
    "}\n"
    "material(reflect = 0.7) {\n"
    "  multmatrix([[1, 0, 0, -6], [0, 1, 0, 4], [0, 0, 1, 5], [0, 0, 0, 1]]) {\n"
    "    sphere(r = 5);\n"
    "  }\n"
    "}\n"
    "material(transmit = 0.9, ior = 1.5, diffuse = 0.05) {\n"
    "  difference() {\n"
    "    multmatrix([[1, 0, 0, 6], [0, 1, 0, -3], [0, 0, 1, 4], [0, 0, 0, 1]]) {\n"
    "      cube(size = 8, center = true);\n"
    "    }\n"
    "    multmatrix([[1, 0, 0, 6], [0, 1, 0, -3], [0, 0, 1, 4], [0, 0, 0, 1]]) {\n"
    "      cylinder(h = 10, r1 = 2, r2 = 2, center = true);\n"
    "    }\n"
    "  }\n"
    "}\n";

static sc_scene *load_scene(void)
{
    sc_scene *scene = NULL;
    sc_error e;
    if (sc_scene_load_string("s.csg", scene_text, strlen(scene_text), NULL, &scene, &e))
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    return scene;
}

static sc_framebuffer *render(const sc_scene *scene, const sc_render_options *o)
{
    sc_framebuffer *fb = NULL;
    sc_error e;
    if (sc_render(scene, o, &fb, &e))
        fail_msg("%s", e.message);
    return fb;
}

static void options(sc_render_options *o, const sc_scene *scene)
{
    sc_render_options_init(o);
    assert_int_equal(sc_render_options_from_scene(o, scene), 1);
    o->width = 67; /* not a multiple of the tile size */
    o->height = 45;
    o->spp = 6;
    o->want_depth = o->want_mask = o->want_normal = o->want_id = 1;
}

/* Sample offsets: each of the n samples lies in its own cell of the
 * kx x ky grid, and the generator is a function of (x, y, s) alone. */
static void test_stratified(void **state)
{
    (void)state;
    for (int n = 1; n <= 17; n++) {
        int kx = sample_grid_width(n), ky = n / kx;
        assert_int_equal(kx * ky, n);
        assert_true(kx <= ky);
        int *seen = calloc((size_t)n, sizeof *seen);
        for (int s = 0; s < n; s++) {
            sample_rng r = sample_rng_for(3, 5, (uint32_t)s);
            double sx, sy;
            sample_offset(s, n, kx, &r, &sx, &sy);
            assert_true(sx >= 0 && sx < 1 && sy >= 0 && sy < 1);
            int cell = (int)(sy * ky) * kx + (int)(sx * kx);
            seen[cell]++;
        }
        for (int c = 0; c < n; c++)
            assert_int_equal(seen[c], 1);
        free(seen);
    }
    sample_rng a = sample_rng_for(7, 9, 2), b = sample_rng_for(7, 9, 2);
    sample_rng c = sample_rng_for(9, 7, 2), d = sample_rng_for(7, 9, 3);
    double va = sample_next(&a);
    assert_true(va == sample_next(&b));
    assert_true(va != sample_next(&c));
    assert_true(va != sample_next(&d));
}

static void expect_same(const sc_framebuffer *a, const sc_framebuffer *b)
{
    assert_int_equal(a->width, b->width);
    assert_int_equal(a->height, b->height);
    size_t n = (size_t)a->width * a->height;
    assert_memory_equal(a->color, b->color, n * 3 * sizeof(float));
    assert_memory_equal(a->depth, b->depth, n * sizeof(float));
    assert_memory_equal(a->mask, b->mask, n);
    assert_memory_equal(a->normal, b->normal, n * 3 * sizeof(float));
    assert_memory_equal(a->id, b->id, n * sizeof(int32_t));
}

static void test_threads_identical(void **state)
{
    (void)state;
    sc_scene *scene = load_scene();
    sc_render_options o;
    options(&o, scene);
    o.threads = 1;
    sc_framebuffer *one = render(scene, &o);
    o.threads = 2;
    sc_framebuffer *two = render(scene, &o);
    expect_same(one, two);
    /* every kind of ray was cast, and the counters do not depend on the
     * thread count either */
    const sc_render_stats *s = &one->stats;
    assert_true(s->camera_rays == (uint64_t)o.width * o.height * (o.spp + 1));
    assert_true(s->shadow_rays > 0 && s->reflection_rays > 0 && s->refraction_rays > 0);
    assert_true(s->primitive_tests > s->camera_rays);
    assert_true(s->span_operations > 0);
    assert_true(s->camera_rays == two->stats.camera_rays);
    assert_true(s->shadow_rays == two->stats.shadow_rays);
    assert_true(s->primitive_tests == two->stats.primitive_tests);
    assert_true(s->span_operations == two->stats.span_operations);
    assert_int_equal(one->stats.threads, 1);
    assert_int_equal(two->stats.threads, 2);
    sc_framebuffer_release(one);
    sc_framebuffer_release(two);
    sc_scene_release(scene);
}

static void test_region_is_crop(void **state)
{
    (void)state;
    sc_scene *scene = load_scene();
    sc_render_options o;
    options(&o, scene);
    sc_framebuffer *full = render(scene, &o);
    static const int regions[][4] = {{0, 0, 67, 45}, {13, 7, 40, 31}, {66, 44, 67, 45}};
    for (size_t r = 0; r < sizeof regions / sizeof regions[0]; r++) {
        memcpy(o.region, regions[r], sizeof o.region);
        sc_framebuffer *crop = render(scene, &o);
        int w = regions[r][2] - regions[r][0], h = regions[r][3] - regions[r][1];
        assert_int_equal(crop->width, w);
        assert_int_equal(crop->height, h);
        for (int j = 0; j < h; j++) {
            size_t from = (size_t)(regions[r][1] + j) * full->width + regions[r][0];
            size_t to = (size_t)j * w;
            assert_memory_equal(crop->color + 3 * to, full->color + 3 * from,
                                (size_t)w * 3 * sizeof(float));
            assert_memory_equal(crop->id + to, full->id + from,
                                (size_t)w * sizeof(int32_t));
        }
        sc_framebuffer_release(crop);
    }
    /* a region outside the image is an argument error */
    int bad[4] = {10, 10, 68, 20};
    memcpy(o.region, bad, sizeof bad);
    sc_framebuffer *fb = NULL;
    sc_error e;
    assert_int_equal(sc_render(scene, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message,
                        "region 10,10,68,20 is not a non-empty crop of the 67x45 image");
    assert_null(fb);
    sc_framebuffer_release(full);
    sc_scene_release(scene);
}

/* The id AOV names the leaf in source order: the floor is leaf 0, the
 * mirror sphere 1, the glass block 2 and its hole 3; -1 on a miss. */
static void test_id_aov(void **state)
{
    (void)state;
    sc_scene *scene = load_scene();
    sc_render_options o;
    options(&o, scene);
    sc_framebuffer *fb = render(scene, &o);
    int counts[5] = {0};
    size_t n = (size_t)fb->width * fb->height;
    for (size_t p = 0; p < n; p++) {
        int32_t id = fb->id[p];
        assert_true(id >= -1 && id <= 3);
        assert_int_equal(id >= 0, fb->mask[p] == 255);
        counts[id + 1]++;
    }
    for (int k = 0; k < 5; k++)
        assert_true(counts[k] > 0); /* sky, floor, sphere, block, hole wall */
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
}

typedef struct progress_log {
    int calls;
    double last;
    int decreasing;
} progress_log;

static void record_progress(void *user, double fraction)
{
    progress_log *log = user;
    if (fraction < log->last)
        log->decreasing = 1;
    log->last = fraction;
    log->calls++;
}

static void test_progress(void **state)
{
    (void)state;
    sc_scene *scene = load_scene();
    sc_render_options o;
    options(&o, scene);
    o.spp = 1;
    o.threads = 1; /* the reporting thread then renders every tile */
    progress_log log = {0, 0, 0};
    o.progress = record_progress;
    o.progress_user = &log;
    sc_framebuffer *fb = render(scene, &o);
    assert_int_equal(log.calls,
                     5 * 3 + 1); /* after each of the 15 tiles, and at the end */
    assert_false(log.decreasing);
    assert_true(log.last == 1.0);
    sc_framebuffer_release(fb);
    sc_scene_release(scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stratified),     cmocka_unit_test(test_threads_identical),
        cmocka_unit_test(test_region_is_crop), cmocka_unit_test(test_id_aov),
        cmocka_unit_test(test_progress),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
