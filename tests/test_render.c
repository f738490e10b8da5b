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

/* A render starts no more threads than it has 16 x 16 tiles (a thread
 * without one would only start and wait), and says so in its stats; the
 * buffers are those of one thread. At 600 x 600 the colour and normal
 * buffers (4.3 MB each) take the huge-page allocation: the same bytes
 * again, whatever the thread count. */
static void test_threads_at_most_tiles(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_sphere(b, v3(0, 0, 0), 1),
                        add_box(b, v3(0, -2, 0), v3(2, 0, 2))};
    csg_tree *tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    const int sizes[][3] = {
        {8, 6, 1}, {16, 16, 1}, {20, 10, 2}, {33, 17, 3}, {600, 600, 3}};
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        sc_render_options o;
        sc_render_options_init(&o);
        o.width = sizes[k][0];
        o.height = sizes[k][1];
        o.want_depth = o.want_mask = o.want_normal = 1;
        o.threads = 1;
        sc_framebuffer *one = render(tree, &o);
        o.threads = 3;
        sc_framebuffer *three = render(tree, &o);
        assert_int_equal(one->stats.threads, 1);
        assert_int_equal(three->stats.threads, sizes[k][2]);
        assert_true(buffers_equal(one, three));
        sc_framebuffer_release(one);
        sc_framebuffer_release(three);
    }
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
    assert_string_equal(e.message, "image size 0x600 is out of range (1 to 262144 pixels "
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

/* ---- preview renders ---- */

static uint32_t add_cylinder_z(csg_builder *b, double x, double y, double r, double z0,
                               double z1)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_CYLINDER;
    p.u.cylinder.z0 = z0;
    p.u.cylinder.z1 = z1;
    p.u.cylinder.r0 = p.u.cylinder.r1 = r;
    affine to_world = translation(v3(x, y, 0));
    sc_location loc = {"test", 3, 1};
    return csg_builder_leaf(b, &p, &to_world, base_color, loc);
}

/* Options for the preview tests: an orthographic look from eye at centre,
 * OpenSCAD's lighting (no shadows), edges pure red, caps pure green, a
 * black background, so that a pixel's colour says what it shows. */
static void preview_options(sc_render_options *o, vec3 eye, vec3 centre, int size)
{
    sc_render_options_init(o);
    set_lookat(o, eye, centre);
    o->projection = SC_PROJECTION_ORTHOGRAPHIC;
    o->width = o->height = size;
    o->lighting = SC_LIGHTING_OPENSCAD;
    o->use_scheme = 1;
    memset(o->scheme.background, 0, sizeof o->scheme.background);
    const float red[3] = {1, 0, 0}, green[3] = {0, 1, 0};
    memcpy(o->scheme.edge, red, sizeof red);
    memcpy(o->scheme.render_face_back, green, sizeof green);
}

static int is_edge_pixel(const sc_framebuffer *fb, int i, int j)
{
    if (i < 0 || j < 0 || i >= fb->width || j >= fb->height)
        return 0;
    const float *c = &fb->color[3 * ((size_t)j * fb->width + i)];
    return c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.0f;
}

/* Pixel coordinates of p under the contract's orthographic camera. */
static void contract_project(const contract_camera *k, vec3 p, double *px, double *py)
{
    vec3 v = v3_sub(p, k->e);
    double dist = v3_length(v3_sub(k->c, k->e));
    double x = v3_dot(v, k->r) / dist, y = v3_dot(v, k->u) / dist;
    *px = (x / (k->a * k->w / k->h) + 1) * k->w / 2;
    *py = (1 - y / k->a) * k->h / 2;
}

static double point_segment_distance(double px, double py, double x0, double y0,
                                     double x1, double y1)
{
    double dx = x1 - x0, dy = y1 - y0;
    double t = ((px - x0) * dx + (py - y0) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x0 + t * dx - px, y0 + t * dy - py);
}

/* A cube in general position shows 9 of its 12 edges: the 6 of its
 * silhouette and the 3 that meet at the corner nearest the eye. With lines
 * 2 pixels wide (neighbour rays 1 pixel away), the pixel holding any point
 * of a visible edge is an edge pixel, and every edge pixel lies within 1.5
 * pixels of a visible edge (a marked centre is within 1 pixel of the line
 * along x or y); the 3 hidden edges, which project inside the visible
 * faces, leave no pixels. */
static void test_cube_edges(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    csg_tree *tree = finish(b, add_box(b, v3(-5, -5, -5), v3(5, 5, 5)));
    vec3 eye = v3(30, -40, 25), centre = v3(0, 0, 0);
    int size = 240;
    sc_render_options o;
    preview_options(&o, eye, centre, size);
    o.view = SC_VIEW_EDGES;
    o.edge_width = 2;
    sc_framebuffer *fb = render(tree, &o);
    contract_camera k = contract(eye, centre, o.fov_deg, size, size, 1);

    /* The 12 edges: coordinate `along` varies, the others are fixed at the
     * signs given; an edge is visible when one of its faces is, and the
     * faces x = +5, y = -5, z = +5 face the eye. */
    double seg[12][4];
    int visible[12], count = 0, shown = 0;
    for (int along = 0; along < 3; along++)
        for (int sa = -1; sa <= 1; sa += 2)
            for (int sb = -1; sb <= 1; sb += 2) {
                int a = (along + 1) % 3, bb = (along + 2) % 3;
                double p0[3], p1[3];
                p0[along] = -5, p1[along] = 5;
                p0[a] = p1[a] = 5 * sa;
                p0[bb] = p1[bb] = 5 * sb;
                const double facing[3] = {5, -5, 5};
                visible[count] = p0[a] == facing[a] || p0[bb] == facing[bb];
                contract_project(&k, v3(p0[0], p0[1], p0[2]), &seg[count][0],
                                 &seg[count][1]);
                contract_project(&k, v3(p1[0], p1[1], p1[2]), &seg[count][2],
                                 &seg[count][3]);
                shown += visible[count];
                count++;
            }
    assert_int_equal(shown, 9);
    for (int e = 0; e < 12; e++) {
        for (int step = 1; step < 20; step++) {
            double t = step / 20.0;
            double px = seg[e][0] + t * (seg[e][2] - seg[e][0]);
            double py = seg[e][1] + t * (seg[e][3] - seg[e][1]);
            int on = is_edge_pixel(fb, (int)floor(px), (int)floor(py));
            if (visible[e] && !on)
                fail_msg("visible edge %d: no line at (%.2f, %.2f)", e, px, py);
            if (visible[e] || !on)
                continue;
            /* A hidden edge ends on the silhouette: near there the
             * visible lines may cover it. */
            double nearest = INFINITY;
            for (int v = 0; v < 12; v++)
                if (visible[v])
                    nearest =
                        fmin(nearest, point_segment_distance(px, py, seg[v][0], seg[v][1],
                                                             seg[v][2], seg[v][3]));
            if (nearest > 2)
                fail_msg("hidden edge %d drawn at (%.2f, %.2f)", e, px, py);
        }
    }
    int edge_pixels = 0;
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++) {
            if (!is_edge_pixel(fb, i, j))
                continue;
            edge_pixels++;
            double nearest = INFINITY;
            for (int e = 0; e < 12; e++)
                if (visible[e])
                    nearest = fmin(nearest, point_segment_distance(i + 0.5, j + 0.5,
                                                                   seg[e][0], seg[e][1],
                                                                   seg[e][2], seg[e][3]));
            if (nearest > 1.5)
                fail_msg("edge pixel (%d, %d) is %.2f pixels from every edge", i, j,
                         nearest);
        }
    assert_true(edge_pixels > 0);
    sc_framebuffer_release(fb);
    csg_tree_free(tree);
}

/* A hole drilled through a plate, seen orthographically from above at a
 * slant: its upper rim, a circle, projects to an ellipse, and the line
 * follows it all round; the plate's top between the rim and its own edges
 * carries no line. */
static void test_hole_edge_ellipse(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_box(b, v3(-20, -20, 0), v3(20, 20, 10)),
                        add_cylinder_z(b, 0, 0, 8, -1, 11)};
    csg_tree *tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    vec3 eye = v3(20, -50, 70), centre = v3(0, 0, 5);
    int size = 300;
    sc_render_options o;
    preview_options(&o, eye, centre, size);
    o.view = SC_VIEW_EDGES;
    o.edge_width = 2;
    sc_framebuffer *fb = render(tree, &o);
    contract_camera k = contract(eye, centre, o.fov_deg, size, size, 1);
    for (int step = 0; step < 90; step++) {
        double phi = step * 2 * 3.14159265358979323846 / 90;
        double px, py;
        contract_project(&k, v3(8 * cos(phi), 8 * sin(phi), 10), &px, &py);
        if (!is_edge_pixel(fb, (int)floor(px), (int)floor(py)))
            fail_msg("no line on the rim's ellipse at %d degrees (%.2f, %.2f)", step * 4,
                     px, py);
        /* On the top face, 5 units outside the rim: no line. */
        contract_project(&k, v3(13 * cos(phi), 13 * sin(phi), 10), &px, &py);
        if (is_edge_pixel(fb, (int)floor(px), (int)floor(py)))
            fail_msg("a line on the plain top face at (%.2f, %.2f)", px, py);
    }
    sc_framebuffer_release(fb);
    csg_tree_free(tree);
}

/* Pixels showing a cap (pure green: red and blue 0) times the area of a
 * pixel, against the analytic area of the cross-section. A pixel is
 * misjudged only when the section's outline passes within half a diagonal
 * of its centre, so the count can be off by at most the outline's length
 * (in pixels) times sqrt(2) pixels. */
static void check_cap_area(const csg_tree *tree, double keep_y, double keep_x,
                           double area, double outline)
{
    vec3 eye = v3(0, 100, 0), centre = v3(0, 0, 0);
    int size = 400;
    sc_render_options o;
    preview_options(&o, eye, centre, size);
    o.section_count = 1;
    o.section[0][0] = 0;
    o.section[0][1] = 1;
    o.section[0][2] = 0;
    o.section[0][3] = keep_y;
    if (isfinite(keep_x)) {
        o.section_count = 2;
        o.section[1][0] = 1;
        o.section[1][3] = keep_x;
    }
    sc_framebuffer *fb = render(tree, &o);
    double pixel = 2 * tan(22.5 / 2 * 3.14159265358979323846 / 180) * 100 / size;
    int caps = 0;
    for (size_t p = 0; p < (size_t)size * size; p++) {
        const float *c = &fb->color[3 * p];
        caps += c[0] == 0 && c[2] == 0 && c[1] > 0;
    }
    double measured = caps * pixel * pixel;
    double bound = outline / pixel * sqrt(2) * pixel * pixel;
    print_message("cap area %.3f, analytic %.3f, bound %.3f\n", measured, area, bound);
    if (fabs(measured - area) > bound)
        fail_msg("cap area %.3f, expected %.3f (bound %.3f)", measured, area, bound);
    sc_framebuffer_release(fb);
}

/* A sphere cut through its centre shows a disc of its full radius; a box
 * drilled along z, cut through the hole's axis, a rectangle less the
 * hole's strip. */
static void test_section_cap_area(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(0, 0, 0), 10);
    double pi = 3.14159265358979323846;
    check_cap_area(s.tree, 0, INFINITY, pi * 100, 2 * pi * 10);
    csg_tree_free(s.tree);

    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_box(b, v3(-20, -15, -10), v3(20, 15, 10)),
                        add_cylinder_z(b, 0, 0, 5, -11, 11)};
    csg_tree *tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    check_cap_area(tree, 0, INFINITY, 40 * 20 - 10 * 20, 2 * (40 + 20) + 2 * 20);
    /* Two cuts intersect: also x <= 10 leaves 30 x 20 less the strip. */
    check_cap_area(tree, 0, 10, 30 * 20 - 10 * 20, 2 * (30 + 20) + 2 * 20);
    csg_tree_free(tree);
}

/* Every preview feature at once, several samples a pixel: a crop of the
 * image equals the same pixels of the whole, and the thread count changes
 * nothing. */
static void test_preview_crop_and_threads(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_box(b, v3(-20, -20, 0), v3(20, 20, 10)),
                        add_cylinder_z(b, 0, 0, 8, -1, 11)};
    csg_tree *tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 70;
    o.height = 53;
    o.spp = 4;
    o.view = SC_VIEW_EDGES | SC_VIEW_AXES | SC_VIEW_SCALES | SC_VIEW_CROSSHAIRS;
    o.section_count = 1;
    o.section[0][0] = 1;
    o.section[0][3] = 5;
    o.section_style = SC_SECTION_HATCH;
    o.ao_samples = 4;
    o.want_depth = o.want_mask = o.want_normal = 1;
    o.threads = 1;
    sc_framebuffer *whole = render(tree, &o);
    o.threads = 3;
    sc_framebuffer *threaded = render(tree, &o);
    assert_true(buffers_equal(whole, threaded));
    o.region[0] = 13;
    o.region[1] = 7;
    o.region[2] = 51;
    o.region[3] = 40;
    sc_framebuffer *crop = render(tree, &o);
    assert_int_equal(crop->width, 38);
    assert_int_equal(crop->height, 33);
    for (int j = 0; j < crop->height; j++)
        for (int i = 0; i < crop->width; i++) {
            size_t a = (size_t)j * crop->width + i;
            size_t w = (size_t)(j + 7) * whole->width + (i + 13);
            assert_memory_equal(&crop->color[3 * a], &whole->color[3 * w],
                                3 * sizeof(float));
            assert_int_equal(crop->mask[a], whole->mask[w]);
        }
    sc_framebuffer_release(whole);
    sc_framebuffer_release(threaded);
    sc_framebuffer_release(crop);
    csg_tree_free(tree);
}

/* Through the public API: a model with a light, a mirror and a lens
 * (shadow, reflection, ambient occlusion and lens rays draw on every
 * sample's random stream), rendered at 16 samples in one call and in
 * passes of 1, 3 and 12 samples summed into one buffer: the last pass's
 * colours are the single render's, bit for bit, also for a crop and over
 * threads. Passes without the buffer give each pass's own mean; samples
 * outside spp are an error. */
static void test_sample_passes(void **state)
{
    (void)state;
    static const char model[] =
        "light(position = [30, -40, 60], radius = 2);\n"
        "difference() {\n"
        "  material(reflect = 0.4) { sphere(r = 10, $fn = 0, $fa = 12, $fs = 2); }\n"
        "  cube(size = [12, 12, 12]);\n"
        "}\n"
        "cylinder(h = 2, r1 = 20, r2 = 20, center = true, $fn = 0, $fa = 12, $fs = 2);\n";
    sc_scene *scene = NULL;
    sc_error e;
    if (sc_scene_load_string("passes.csg", model, strlen(model), NULL, &scene, &e) !=
        SC_OK)
        fail_msg("%s:%d:%d: %s", e.file, e.line, e.column, e.message);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 61;
    o.height = 47;
    o.spp = 16;
    o.ao_samples = 2;
    o.aperture = 0.5;
    o.view = SC_VIEW_EDGES;
    o.threads = 2;
    sc_framebuffer *whole = NULL;
    assert_int_equal(sc_render(scene, &o, &whole, &e), SC_OK);
    size_t n = (size_t)o.width * o.height * 3;

    double *sum = calloc(n, sizeof *sum);
    assert_non_null(sum);
    const int passes[3][2] = {{0, 1}, {1, 3}, {4, 12}}; /* start, count */
    sc_framebuffer *pass = NULL;
    for (int k = 0; k < 3; k++) {
        sc_render_options p = o;
        p.threads = k + 1;
        p.sample_start = passes[k][0];
        p.sample_count = passes[k][1];
        p.sample_sum = sum;
        sc_framebuffer_release(pass);
        pass = NULL;
        assert_int_equal(sc_render(scene, &p, &pass, &e), SC_OK);
    }
    assert_memory_equal(sc_framebuffer_color(pass), sc_framebuffer_color(whole),
                        n * sizeof(float));
    /* The first pass alone is no approximation of all 16. */
    sc_render_options first = o;
    first.sample_count = 1;
    sc_framebuffer *one = NULL;
    assert_int_equal(sc_render(scene, &first, &one, &e), SC_OK);
    assert_true(memcmp(sc_framebuffer_color(one), sc_framebuffer_color(whole),
                       n * sizeof(float)) != 0);

    /* Without the buffer each pass holds its own mean: weighted by its
     * sample count they add up to the whole (to float rounding). */
    sc_render_options rest = o;
    rest.sample_start = 1;
    rest.sample_count = 0; /* up to spp */
    sc_framebuffer *fifteen = NULL;
    assert_int_equal(sc_render(scene, &rest, &fifteen, &e), SC_OK);
    const float *a = sc_framebuffer_color(one), *b = sc_framebuffer_color(fifteen);
    const float *w = sc_framebuffer_color(whole);
    for (size_t k = 0; k < n; k++)
        assert_true(fabs((a[k] + 15.0 * b[k]) / 16 - w[k]) < 1e-5);

    /* A crop in two passes is the whole image's crop. */
    sc_render_options crop = o;
    crop.region[0] = 9;
    crop.region[1] = 5;
    crop.region[2] = 40;
    crop.region[3] = 33;
    double *crop_sum = calloc((size_t)31 * 28 * 3, sizeof *crop_sum);
    assert_non_null(crop_sum);
    crop.sample_sum = crop_sum;
    crop.sample_count = 5;
    sc_framebuffer *part = NULL;
    assert_int_equal(sc_render(scene, &crop, &part, &e), SC_OK);
    sc_framebuffer_release(part);
    crop.sample_start = 5;
    crop.sample_count = 11;
    assert_int_equal(sc_render(scene, &crop, &part, &e), SC_OK);
    for (int j = 0; j < 28; j++)
        assert_memory_equal(sc_framebuffer_color(part) + (size_t)j * 31 * 3,
                            w + ((size_t)(j + 5) * o.width + 9) * 3,
                            31 * 3 * sizeof(float));

    /* Samples outside spp. */
    const int bad[3][2] = {{16, 0}, {-1, 2}, {10, 7}};
    for (int k = 0; k < 3; k++) {
        sc_render_options p = o;
        p.sample_start = bad[k][0];
        p.sample_count = bad[k][1];
        sc_framebuffer *none = NULL;
        assert_int_equal(sc_render(scene, &p, &none, &e), SC_ERR_ARGUMENT);
        assert_null(none);
    }
    sc_render_options p = o;
    p.sample_start = 10;
    p.sample_count = 7;
    sc_framebuffer *none = NULL;
    sc_render(scene, &p, &none, &e);
    assert_string_equal(e.message,
                        "sample start 10 and count 7 do not fit 16 samples per pixel");

    sc_framebuffer_release(part);
    sc_framebuffer_release(fifteen);
    sc_framebuffer_release(one);
    sc_framebuffer_release(pass);
    sc_framebuffer_release(whole);
    free(crop_sum);
    free(sum);
    sc_scene_release(scene);
}

/* A sheet of three views is a 2 x 2 grid of tiles of the options' size;
 * each view's tile shows the model, the empty fourth cell none of it. */
static void test_sheet_grid(void **state)
{
    (void)state;
    sphere_scene s = make_sphere(v3(3, 1, 2), 4);
    sc_render_options o;
    sc_render_options_init(&o);
    o.width = 40;
    o.height = 30;
    o.want_mask = 1;
    o.sheet_count = 3;
    o.sheet[0] = SC_VIEW_PRESET_FRONT;
    o.sheet[1] = SC_VIEW_PRESET_TOP;
    o.sheet[2] = SC_VIEW_PRESET_DIAGONAL;
    sc_framebuffer *fb = render(s.tree, &o);
    assert_int_equal(fb->width, 80);
    assert_int_equal(fb->height, 60);
    for (int tile = 0; tile < 4; tile++) {
        int x0 = (tile % 2) * 40, y0 = (tile / 2) * 30;
        /* framed like viewall: the model is at the tile's centre */
        int centre = fb->mask[(size_t)(y0 + 15) * fb->width + x0 + 20];
        assert_int_equal(centre, tile < 3 ? 255 : 0);
    }
    sc_framebuffer_release(fb);
    csg_tree_free(s.tree);
}

static int pixel_is(const sc_framebuffer *fb, int i, int j, const float c[3])
{
    if (i < 0 || j < 0 || i >= fb->width || j >= fb->height)
        return 0;
    const float *p = &fb->color[3 * ((size_t)j * fb->width + i)];
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
}

/* OpenSCAD's axes are drawn where they are in front of the model and
 * hidden where they pass inside it: the +x axis through a cube at the
 * origin shows beyond the cube's silhouette and not within it. */
static void test_axes_occluded(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    csg_tree *tree = finish(b, add_box(b, v3(-5, -5, -5), v3(5, 5, 5)));
    vec3 eye = v3(30, -40, 25), centre = v3(0, 0, 0);
    int size = 240;
    sc_render_options o;
    preview_options(&o, eye, centre, size);
    const float magenta[3] = {1, 0, 1};
    memcpy(o.scheme.axes, magenta, sizeof magenta);
    o.view = SC_VIEW_AXES;
    o.fov_deg = 40; /* the image is 41 units high: x = 20 projects inside */
    sc_framebuffer *fb = render(tree, &o);
    contract_camera k = contract(eye, centre, o.fov_deg, size, size, 1);
    for (double x = -4; x <= 20; x += 0.5) {
        if (x > -2 && x < 2) /* where the other axes cross */
            continue;
        double px, py;
        contract_project(&k, v3(x, 0, 0), &px, &py);
        int i = (int)floor(px), j = (int)floor(py), seen = 0;
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++)
                seen += pixel_is(fb, i + di, j + dj, magenta);
        int outside = x > 9; /* beyond the cube's silhouette (radius 8.7 at most) */
        if (x > 4 && x <= 9)
            continue; /* between the cube's face and its silhouette: either */
        if (outside && !seen)
            fail_msg("the axis at x = %g is not drawn", x);
        if (!outside && seen)
            fail_msg("the axis at x = %g, inside the cube, is drawn", x);
    }
    sc_framebuffer_release(fb);
    csg_tree_free(tree);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_mask_and_depth),
        cmocka_unit_test(test_centre_depth_double),
        cmocka_unit_test(test_threads_identical),
        cmocka_unit_test(test_threads_at_most_tiles),
        cmocka_unit_test(test_two_sided),
        cmocka_unit_test(test_auto_camera_frames_model),
        cmocka_unit_test(test_empty_scene),
        cmocka_unit_test(test_defaults_and_errors),
        cmocka_unit_test(test_cube_edges),
        cmocka_unit_test(test_hole_edge_ellipse),
        cmocka_unit_test(test_section_cap_area),
        cmocka_unit_test(test_preview_crop_and_threads),
        cmocka_unit_test(test_sample_passes),
        cmocka_unit_test(test_sheet_grid),
        cmocka_unit_test(test_axes_occluded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
