/* Tests of the renderer (src/render/render.c) against analytic answers.
 *
 * Trees are built through csg_builder directly, so no parser is involved.
 * The pixel rays are recomputed here from the camera contract
 * (docs/camera.md) rather than taken from camera.c, so the tests also check
 * that the renderer shoots the rays the contract promises: a sphere's mask
 * must agree pixel for pixel with the exact ray-sphere test, its depth with
 * the analytic distance, and the buffers must not depend on the thread
 * count.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>
#include <stdlib.h>
#include <string.h>

#include "build/scene.h"
#include "formats/color.h"
#include "render/render.h"

typedef struct sphere_scene {
    vec3 center;
    double radius;
    csg_tree *tree;
} sphere_scene;

static const float base_color[4] = {0.2f, 0.6f, 0.9f, 1.0f};

static affine translation(vec3 t)
{
    affine a = affine_identity();
    a.m[0][3] = t.x;
    a.m[1][3] = t.y;
    a.m[2][3] = t.z;
    return a;
}

static uint32_t add_sphere(csg_builder *b, vec3 c, double r)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_SPHERE;
    p.u.sphere.r = r;
    affine to_world = translation(c);
    sc_location loc = {"test", 1, 1};
    return csg_builder_leaf(b, &p, &to_world, base_color, loc);
}

static uint32_t add_box(csg_builder *b, vec3 lo, vec3 hi)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_BOX;
    p.u.box.lo = lo;
    p.u.box.hi = hi;
    affine to_world = affine_identity();
    sc_location loc = {"test", 2, 1};
    return csg_builder_leaf(b, &p, &to_world, base_color, loc);
}

static csg_tree *finish(csg_builder *b, uint32_t root)
{
    csg_tree *tree = NULL;
    sc_error e;
    assert_int_equal(csg_builder_finish(b, root, &tree, &e), SC_OK);
    return tree;
}

static sphere_scene make_sphere(vec3 c, double r)
{
    sphere_scene s = {c, r, NULL};
    csg_builder *b = csg_builder_new();
    s.tree = finish(b, add_sphere(b, c, r));
    return s;
}

/* The contract, written out again: the ray through pixel (i, j) at its
 * centre for the vector camera (eye, centre). */
typedef struct contract_camera {
    vec3 e, c, f, r, u;
    double a;
    int w, h;
    int ortho;
} contract_camera;

static contract_camera contract(vec3 e, vec3 c, double fov_deg, int w, int h, int ortho)
{
    contract_camera k;
    k.e = e;
    k.c = c;
    k.f = v3_normalize(v3_sub(c, e));
    k.r = v3_normalize(v3_cross(k.f, v3(0, 0, 1)));
    k.u = v3_cross(k.r, k.f);
    k.a = tan(fov_deg / 2 * 3.14159265358979323846 / 180);
    k.w = w;
    k.h = h;
    k.ortho = ortho;
    return k;
}

static void contract_ray(const contract_camera *k, int i, int j, vec3 *o, vec3 *d)
{
    double x = (2 * (i + 0.5) / k->w - 1) * k->a * k->w / k->h;
    double y = (1 - 2 * (j + 0.5) / k->h) * k->a;
    vec3 off = v3_add(v3_scale(k->r, x), v3_scale(k->u, y));
    if (k->ortho) {
        *o = v3_madd(k->e, off, v3_length(v3_sub(k->c, k->e)));
        *d = k->f;
    } else {
        *o = k->e;
        *d = v3_add(k->f, off);
    }
}

/* Exact ray-sphere test for t >= 0; *dist is the distance to the first hit
 * in front of the origin. */
static int ray_hits_sphere(vec3 o, vec3 d, vec3 c, double r, double *dist)
{
    vec3 oc = v3_sub(o, c);
    double a = v3_dot(d, d), b = v3_dot(oc, d), cc = v3_dot(oc, oc) - r * r;
    double disc = b * b - a * cc;
    if (disc <= 0)
        return 0;
    double s = sqrt(disc);
    double q = -(b + (b >= 0 ? s : -s));
    double t0 = q / a, t1 = cc / q;
    if (t0 > t1) {
        double tmp = t0;
        t0 = t1;
        t1 = tmp;
    }
    double t = t0 >= 0 ? t0 : t1;
    if (t < 0)
        return 0;
    *dist = t * sqrt(a);
    return 1;
}

static void set_lookat(sc_render_options *o, vec3 e, vec3 c)
{
    o->camera_mode = SC_CAMERA_VECTOR;
    o->camera[0] = e.x;
    o->camera[1] = e.y;
    o->camera[2] = e.z;
    o->camera[3] = c.x;
    o->camera[4] = c.y;
    o->camera[5] = c.z;
}

static sc_framebuffer *render(const csg_tree *tree, const sc_render_options *o)
{
    sc_scene scene;
    memset(&scene, 0, sizeof scene);
    scene.tree = (csg_tree *)tree;
    sc_framebuffer *fb = NULL;
    sc_error e;
    sc_status st = sc_render(&scene, o, &fb, &e);
    if (st != SC_OK)
        fail_msg("sc_render: %s", e.message);
    return fb;
}

/* Mask and depth of every pixel against the exact sphere. */
static void check_sphere(const sphere_scene *s, vec3 eye, vec3 look_at, double fov, int w,
                         int h, int ortho)
{
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = w;
    o.height = h;
    o.fov_deg = fov;
    o.projection = ortho ? SC_PROJECTION_ORTHOGRAPHIC : SC_PROJECTION_PERSPECTIVE;
    set_lookat(&o, eye, look_at);
    o.want_color = 0;
    o.want_mask = 1;
    o.want_depth = 1;
    sc_framebuffer *fb = render(s->tree, &o);
    assert_null(fb->color);
    assert_null(fb->normal);

    contract_camera k = contract(eye, look_at, fov, w, h, ortho);
    int disagree = 0, hits = 0;
    double worst = 0;
    for (int j = 0; j < h; j++) {
        for (int i = 0; i < w; i++) {
            vec3 ro, rd;
            contract_ray(&k, i, j, &ro, &rd);
            double dist = 0;
            int want = ray_hits_sphere(ro, rd, s->center, s->radius, &dist);
            size_t p = (size_t)j * w + i;
            int got = fb->mask[p] == 255;
            assert_true(fb->mask[p] == 0 || fb->mask[p] == 255);
            if (got != want)
                disagree++;
            if (want && got) {
                hits++;
                double rel = fabs(fb->depth[p] - dist) / dist;
                worst = fmax(worst, rel);
            }
            if (!got)
                assert_true(isinf(fb->depth[p]) && fb->depth[p] > 0);
        }
    }
    assert_int_equal(disagree, 0);
    assert_true(hits > w * h / 20); /* the sphere fills a fair part of the image */
    assert_true(worst < 2e-7);      /* float rounding of the depth buffer */

    /* When the camera looks at the sphere's centre, the centre pixel (odd
     * sizes) has depth |c - e| - r. */
    if (look_at.x == s->center.x && look_at.y == s->center.y &&
        look_at.z == s->center.z) {
        size_t centre = (size_t)(h / 2) * w + w / 2;
        double want = v3_length(v3_sub(s->center, eye)) - s->radius;
        assert_true(fabs(fb->depth[centre] - want) <= want * 1.2e-7);
    }
    sc_framebuffer_release(fb);
}

static void test_sphere_mask_and_depth(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(0.3, -0.2, 0.5), 1.5);
    /* centred, then off-centre in the image (which also pins down the
     * directions of r and u: a centred sphere is symmetric) */
    check_sphere(&s, v3(7, -9, 4), s.center, 30, 161, 121, 0);
    check_sphere(&s, v3(7, -9, 4), v3(1.0, 0.4, 0.2), 30, 161, 121, 0);
    check_sphere(&s, v3(-3, 2, -8), v3(0, 0, 0), 22.5, 101, 151, 0);
    check_sphere(&s, v3(7, -9, 4), s.center, 30, 161, 121, 1);
    check_sphere(&s, v3(7, -9, 4), v3(-0.5, 0.3, 0.9), 30, 161, 121, 1);
    csg_tree_free(s.tree);

    /* far from the origin and small */
    s = make_sphere(v3(1e4, -2e4, 3e3), 0.01);
    check_sphere(&s, v3(1e4 + 0.05, -2e4 - 0.06, 3e3 + 0.03), s.center, 20, 81, 81, 0);
    check_sphere(&s, v3(1e4 + 0.05, -2e4 - 0.06, 3e3 + 0.03),
                 v3(1e4 + 0.004, -2e4, 3e3 + 0.003), 20, 81, 81, 0);
    csg_tree_free(s.tree);
}

/* The centre pixel's first hit, in double precision through the same query
 * the renderer makes, matches the analytic distance to 1e-9. */
static void test_centre_depth_double(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(0.3, -0.2, 0.5), 1.5);
    vec3 eye = v3(7, -9, 4);
    contract_camera k = contract(eye, s.center, 30, 161, 121, 0);
    csg_ray ray;
    contract_ray(&k, 80, 60, &ray.o, &ray.d);
    ray.tmin = 0;
    ray.tmax = INFINITY;
    arena scratch;
    arena_init(&scratch, 0);
    csg_hit hit;
    assert_int_equal(csg_first_hit(s.tree, &ray, &scratch, &hit), 1);
    double got = hit.t * v3_length(ray.d);
    double want = v3_length(v3_sub(s.center, eye)) - s.radius;
    assert_true(fabs(got - want) <= 1e-9 * want);
    arena_free(&scratch);
    csg_tree_free(s.tree);
}

static int buffers_equal(const sc_framebuffer *a, const sc_framebuffer *b)
{
    size_t n = (size_t)a->width * a->height;
    return a->width == b->width && a->height == b->height &&
           !memcmp(a->color, b->color, n * 3 * sizeof(float)) &&
           !memcmp(a->depth, b->depth, n * sizeof(float)) &&
           !memcmp(a->mask, b->mask, n) &&
           !memcmp(a->normal, b->normal, n * 3 * sizeof(float));
}

/* A sphere with a box bitten out, every buffer: byte-identical for 1, 2
 * and 3 threads. */
static void test_threads_identical(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_sphere(b, v3(0, 0, 0), 1),
                        add_box(b, v3(0, -2, 0), v3(2, 0, 2))};
    csg_tree *tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 97; /* not a multiple of the tile size */
    o.height = 83;
    o.want_depth = o.want_mask = o.want_normal = 1;
    o.threads = 1;
    sc_framebuffer *one = render(tree, &o);
    o.threads = 2;
    sc_framebuffer *two = render(tree, &o);
    o.threads = 3;
    sc_framebuffer *three = render(tree, &o);
    assert_true(buffers_equal(one, two));
    assert_true(buffers_equal(one, three));

    /* Colours lie in [0, 1], normals are unit or 0 on a miss, and the
     * background is Cornfield's #ffffe5. */
    size_t n = (size_t)o.width * o.height;
    int misses = 0;
    for (size_t p = 0; p < n; p++) {
        for (int k = 0; k < 3; k++)
            assert_true(one->color[3 * p + k] >= 0 && one->color[3 * p + k] <= 1);
        vec3 nv = v3(one->normal[3 * p], one->normal[3 * p + 1], one->normal[3 * p + 2]);
        if (one->mask[p]) {
            assert_true(fabs(v3_length(nv) - 1) < 1e-6);
        } else {
            misses++;
            assert_true(v3_length(nv) == 0);
            assert_true(one->color[3 * p] == 1.0f && one->color[3 * p + 1] == 1.0f);
            assert_true(one->color[3 * p + 2] ==
                        (float)color_srgb_to_linear(229.0f / 255.0f));
        }
    }
    assert_true(misses > 0 && misses < (int)n);
    sc_framebuffer_release(one);
    sc_framebuffer_release(two);
    sc_framebuffer_release(three);
    csg_tree_free(tree);
}

/* Seen from inside a sphere every pixel hits its far wall, whose outward
 * normal faces away from the viewer; shading uses the reversed normal, so
 * the centre is lit by a point light beside the eye (inside the solid too,
 * so nothing shadows it), not only by the ambient term. */
static void test_two_sided(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(0, 0, 0), 5);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 31;
    o.height = 21;
    o.want_mask = o.want_normal = 1;
    set_lookat(&o, v3(0, -1, 0), v3(0, 1, 0));
    shading *look = shading_new();
    assert_non_null(look);
    shading_light light;
    memset(&light, 0, sizeof light);
    light.kind = SHADING_LIGHT_POINT;
    light.position = v3(0.5, -1, 0.5);
    light.color[0] = light.color[1] = light.color[2] = 1;
    light.intensity = 1;
    assert_true(shading_add_light(look, &light));
    sc_framebuffer *fb = NULL;
    sc_error e;
    assert_int_equal(render_scene(s.tree, look, &o, &fb, &e), SC_OK);
    shading_free(look);
    size_t n = (size_t)o.width * o.height;
    for (size_t p = 0; p < n; p++)
        assert_int_equal(fb->mask[p], 255);
    size_t centre = (size_t)(o.height / 2) * o.width + o.width / 2;
    /* the normal AOV keeps the outward normal: +y at the far wall */
    assert_true(fb->normal[3 * centre + 1] > 0.99f);
    for (int k = 0; k < 3; k++)
        assert_true(fb->color[3 * centre + k] >
                    color_srgb_to_linear(base_color[k]) * SHADING_DEFAULT_AMBIENT * 1.5);
    sc_framebuffer_release(fb);
    csg_tree_free(s.tree);
}

/* The automatic camera frames the whole solid: no hit touches the image's
 * border, and the solid is seen. */
static void test_auto_camera_frames_model(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(10, 20, -5), 3);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 64;
    o.height = 48;
    o.want_color = 0;
    o.want_mask = 1;
    sc_framebuffer *fb = render(s.tree, &o);
    int hits = 0;
    for (int j = 0; j < o.height; j++) {
        for (int i = 0; i < o.width; i++) {
            int hit = fb->mask[(size_t)j * o.width + i] != 0;
            hits += hit;
            if (i == 0 || j == 0 || i == o.width - 1 || j == o.height - 1)
                assert_false(hit);
        }
    }
    assert_true(hits > 100);
    sc_framebuffer_release(fb);
    csg_tree_free(s.tree);
}

static void test_empty_scene(void **state)
{
    (void)state;
    csg_tree *tree = finish(csg_builder_new(), CSG_EMPTY);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 20;
    o.height = 10;
    o.want_depth = o.want_mask = 1;
    sc_framebuffer *fb = render(tree, &o);
    for (size_t p = 0; p < 200; p++) {
        assert_int_equal(fb->mask[p], 0);
        assert_true(isinf(fb->depth[p]));
        assert_true(fb->color[3 * p + 2] == (float)color_srgb_to_linear(229.0f / 255.0f));
    }
    sc_framebuffer_release(fb);
    csg_tree_free(tree);
}

static void test_defaults_and_errors(void **state)
{
    (void)state;
    sc_render_options o;
    sc_render_options_init(&o);
    assert_int_equal(o.width, 800);
    assert_int_equal(o.height, 600);
    assert_true(o.fov_deg == 22.5);
    assert_int_equal(o.projection, SC_PROJECTION_PERSPECTIVE);
    assert_int_equal(o.camera_mode, SC_CAMERA_AUTO);
    assert_int_equal(o.threads, 0);
    assert_int_equal(o.want_color, 1);
    assert_int_equal(
        o.want_depth + o.want_mask + o.want_normal + o.viewall + o.autocenter, 0);

    sphere_scene s = make_sphere(v3(0, 0, 0), 1);
    sc_scene scene;
    memset(&scene, 0, sizeof scene);
    scene.tree = s.tree;
    sc_framebuffer *fb = (sc_framebuffer *)&o; /* must be reset to NULL */
    sc_error e;
    o.width = 0;
    assert_int_equal(sc_render(&scene, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_null(fb);
    assert_string_equal(e.message, "image size 0x600 is out of range (1 to 32768 pixels "
                                   "a side)");
    o.width = 10;
    o.threads = -1;
    assert_int_equal(sc_render(&scene, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message, "thread count must not be negative (got -1)");
    o.threads = 0;
    o.fov_deg = 0;
    assert_int_equal(sc_render(&scene, &o, &fb, &e), SC_ERR_ARGUMENT);
    assert_string_equal(e.message,
                        "field of view must be between 0 and 180 degrees (got 0)");
    assert_int_equal(sc_render(NULL, &o, &fb, &e), SC_ERR_ARGUMENT);
    csg_tree_free(s.tree);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_mask_and_depth),
        cmocka_unit_test(test_centre_depth_double),
        cmocka_unit_test(test_threads_identical),
        cmocka_unit_test(test_two_sided),
        cmocka_unit_test(test_auto_camera_frames_model),
        cmocka_unit_test(test_empty_scene),
        cmocka_unit_test(test_defaults_and_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
