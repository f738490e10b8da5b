/* The numerical stability suite (issue: stiff and extreme cases).
 *
 * Models live in tests/stability/. Each case is held to a bound stated in
 * docs/stability.md: the metamorphic cases (scale, translation,
 * ill-conditioned transforms, coincident faces against their expected
 * solids) go through stab_compare (bench/stability.c), which counts
 * mask mismatches, NaN and pixels whose depth error exceeds the derived
 * per-pixel bound; the ray cases (grazing, tangent, thin) check span lists
 * against the point-membership oracle csg_inside.
 */
#include <dirent.h>
#include <malloc.h>
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#if defined(__SANITIZE_ADDRESS__)
/* The sanitizer runtime's count (sanitizer/allocator_interface.h, which
 * Debian ships only with some compilers). */
size_t __sanitizer_get_current_allocated_bytes(void);
#endif

#include "build/scene.h"
#include "csg/csg.h"
#include "render/camera.h"
#include "bench/stability.h"
#include "test_util.h"

#define IMAGE 32 /* pixels per side of the harness images */

static char *read_model(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/stability/%s", SPANCAST_SOURCE_DIR, name);
    return test_read_file(path, NULL);
}

static sc_scene *load_text(const char *text)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e);
    if (st != SC_OK)
        fail_msg("%s", e.message);
    return s;
}

/* Compares model (or model against expected, moved by x) and requires a
 * clean result: no mask mismatch, no NaN, every depth inside its bound. */
static stab_result compare_clean(const char *model, const char *expected,
                                 const stab_similarity *x)
{
    char *a = read_model(model), *b = expected ? read_model(expected) : NULL;
    stab_result r;
    sc_error e;
    if (stab_compare(model, a, b, x, IMAGE, &r, &e) != SC_OK)
        fail_msg("%s", e.message);
    print_message("%-36s hits %4llu mismatches %llu nan %llu max rel depth %.3g\n", model,
                  (unsigned long long)r.hits, (unsigned long long)r.mask_mismatches,
                  (unsigned long long)r.nan_count, r.max_rel_depth_error);
    assert_true(r.hits > IMAGE * IMAGE / 8); /* the model fills the view */
    assert_int_equal(r.mask_mismatches, 0);
    assert_int_equal(r.nan_count, 0);
    assert_int_equal(r.depth_violations, 0);
    free(a);
    free(b);
    return r;
}

/* ---- scale and translation ---- */

static void test_scale(void **state)
{
    (void)state;
    /* Not 1: the identity compares the model with itself and proves nothing. */
    const double sizes[] = {1e-6, 1e-3, 1e3, 1e6};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        stab_similarity x = stab_scaled(sizes[i], sizes[i], sizes[i], v3(0, 0, 0));
        stab_result r = compare_clean("part.csg", NULL, &x);
        /* At the origin the derived bound is below 1e-9 for every pixel that
         * is not within 1e-3 of grazing; the largest error seen is far below. */
        assert_true(r.max_rel_depth_error <= 1e-9);
    }
}

static void test_translation(void **state)
{
    (void)state;
    const double offsets[] = {1e6, 1e8};
    for (size_t i = 0; i < 2; i++) {
        stab_similarity x =
            stab_scaled(1, 1, 1, v3(offsets[i], -0.6 * offsets[i], 0.3 * offsets[i]));
        compare_clean("part.csg", NULL, &x);
        /* Tied faces far from the origin still fuse (the rounding part of
         * eps, csg_eps). */
        compare_clean("coincident_difference_expected.csg", "coincident_difference.csg",
                      &x);
        compare_clean("coincident_union_expected.csg", "coincident_union.csg", &x);
    }
}

static void test_random_similarities(void **state)
{
    (void)state;
    /* Rotation, scale over 12 decades, translation up to 1000 model radii. */
    for (uint64_t seed = 1; seed <= 8; seed++) {
        stab_similarity x = stab_random(seed, -6, 6, 2.0, 1e3);
        compare_clean("part.csg", NULL, &x);
    }
}

/* ---- the metamorphic check over every model ---- */

typedef struct model_list {
    char paths[256][512];
    int n;
} model_list;

/* Every .csg under dir, recursively, except the hostile corpora (files that
 * must fail to load, or may crash a careless loader) and tests/real (the
 * published models, many with nodes not supported yet: tests/real/run
 * measures them). */
static void find_models(const char *dir, model_list *list)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' || !strcmp(e->d_name, "bad-input") ||
            !strcmp(e->d_name, "fuzz-regressions") || !strcmp(e->d_name, "real"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        size_t n = strlen(path);
        if (n > 4 && !strcmp(path + n - 4, ".csg")) {
            assert_true(list->n < 256);
            memcpy(list->paths[list->n++], path, n + 1);
        } else {
            find_models(path, list);
        }
    }
    closedir(d);
}

/* The pixels of stab_compare's view of t that must be hits, and those that
 * may be. The camera is the harness's (stability.c, harness_camera): the
 * fixed oblique forward, fov 30, viewall with autocenter on t's bounds. A
 * pixel whose centre ray passes through a point of the solid (csg_inside,
 * tested at `samples` evenly spaced points of the ray's stretch through the
 * bounds, and at points approaching either end of it) must be a hit; a
 * pixel whose ray misses the bounds must not be.
 * Checks both against csg_first_hit pixel by pixel and returns its hit
 * count in *hits, so the caller can tie it to stab_compare's count. */
static uint64_t must_hit(const csg_tree *t, int size, int samples, uint64_t *may,
                         uint64_t *hits)
{
    *may = *hits = 0;
    if (bbox_is_empty(&t->bounds))
        return 0;
    cam_view view;
    view.center = v3(0, 0, 0);
    view.forward = v3_normalize(v3(-0.5773, -0.6421, -0.5049));
    view.up = v3(0, 0, 1);
    cam_view_all(&view, &t->bounds, 1, 30.0);
    camera cam;
    sc_error e;
    assert_int_equal(
        cam_init(&cam, &view, 30.0, SC_PROJECTION_PERSPECTIVE, size, size, &e), SC_OK);
    arena scratch;
    arena_init(&scratch, 1 << 16);
    uint64_t must = 0;
    for (int j = 0; j < size; j++)
        for (int i = 0; i < size; i++) {
            csg_ray ray = {.tmin = 0, .tmax = INFINITY};
            cam_ray(&cam, i, j, 0.5, 0.5, &ray.o, &ray.d);
            csg_hit hit;
            int got = csg_first_hit(t, &ray, &scratch, &hit);
            arena_reset(&scratch);
            *hits += (uint64_t)got;
            /* the ray's stretch through the bounds (slabs) */
            double t0 = 0, t1 = INFINITY;
            for (int a = 0; a < 3; a++) {
                double o = v3_get(ray.o, a), d = v3_get(ray.d, a);
                double lo = v3_get(t->bounds.lo, a), hi = v3_get(t->bounds.hi, a);
                if (d == 0) {
                    if (o < lo || o > hi)
                        t1 = -1;
                    continue;
                }
                double ta = (lo - o) / d, tb = (hi - o) / d;
                t0 = fmax(t0, fmin(ta, tb));
                t1 = fmin(t1, fmax(ta, tb));
            }
            if (t0 > t1) {
                if (got)
                    fail_msg("pixel (%d, %d) hits outside the bounds", i, j);
                continue;
            }
            ++*may;
            int inside = 0;
            for (int k = 0; k < samples && !inside; k++)
                inside = csg_inside(
                    t, v3_madd(ray.o, ray.d, t0 + (t1 - t0) * (k + 0.5) / samples));
            /* a solid touches its bounds, possibly only in a thin layer:
             * also points approaching each end of the stretch */
            for (int k = 1; k <= 40 && !inside; k++) {
                double step = (t1 - t0) * ldexp(1, -k);
                inside = csg_inside(t, v3_madd(ray.o, ray.d, t0 + step)) ||
                         csg_inside(t, v3_madd(ray.o, ray.d, t1 - step));
            }
            must += (uint64_t)inside;
            if (inside && !got)
                fail_msg("pixel (%d, %d) passes through the solid but misses it", i, j);
        }
    arena_free(&scratch);
    return must;
}

static void test_metamorphic_all_models(void **state)
{
    (void)state;
    static model_list list;
    list.n = 0;
    find_models(SPANCAST_SOURCE_DIR "/models", &list);
    find_models(SPANCAST_SOURCE_DIR "/tests", &list);
    assert_true(list.n >= 10);
    uint64_t pixels = 0, hits = 0;
    for (int m = 0; m < list.n; m++) {
        char *text = test_read_file(list.paths[m], NULL);
        sc_error e;
        /* Loaded from its path, so imports resolve beside the model. */
        sc_scene *probe = NULL;
        if (sc_scene_load(list.paths[m], NULL, &probe, &e) != SC_OK)
            fail_msg("%s", e.message);
        double lo[3], hi[3], radius = 1;
        if (sc_scene_bounds(probe, lo, hi))
            radius = 0.5 * sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) +
                                (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
        /* Every model here is a solid framed by the view: some of its
         * points lie on the sampled pixel rays, and those pixels must be
         * hits (so a renderer that misses everything fails here). */
        uint64_t may, probe_hits;
        uint64_t must = must_hit(scene_tree(probe), 24, 64, &may, &probe_hits);
        sc_scene_release(probe);
        print_message("%s: %llu pixels must hit, %llu may\n", list.paths[m],
                      (unsigned long long)must, (unsigned long long)may);
        assert_true(must > 0);
        for (uint64_t k = 0; k < 3; k++) {
            /* Rotation, scale over 12 decades, translation up to 1000 times
             * the scaled model's radius. */
            stab_result r;
            stab_similarity x = stab_random(1000 * (uint64_t)m + k, -6, 6, radius, 1e3);
            if (stab_compare(list.paths[m], text, NULL, &x, 24, &r, &e) != SC_OK)
                fail_msg("%s", e.message);
            if (r.mask_mismatches || r.nan_count || r.depth_violations)
                print_message("%s (seed %llu): mismatches %llu nan %llu depth %llu "
                              "(max rel %.3g)\n",
                              list.paths[m], (unsigned long long)(1000 * m + (int)k),
                              (unsigned long long)r.mask_mismatches,
                              (unsigned long long)r.nan_count,
                              (unsigned long long)r.depth_violations,
                              r.max_rel_depth_error);
            /* the same view of the same model: the same hits, which include
             * every pixel that must hit */
            assert_int_equal(r.hits, probe_hits);
            assert_int_equal(r.mask_mismatches, 0);
            assert_int_equal(r.nan_count, 0);
            assert_int_equal(r.depth_violations, 0);
            pixels += r.pixels;
            hits += r.hits;
        }
        free(text);
    }
    print_message("metamorphic: %d models, %llu pixels, %llu hits, all identical\n",
                  list.n, (unsigned long long)pixels, (unsigned long long)hits);
}

/* ---- coincident faces ---- */

static void test_coincident(void **state)
{
    (void)state;
    stab_similarity identity = stab_scaled(1, 1, 1, v3(0, 0, 0));
    compare_clean("coincident_union_expected.csg", "coincident_union.csg", &identity);
    compare_clean("coincident_intersection_expected.csg", "coincident_intersection.csg",
                  &identity);
    compare_clean("coincident_difference_expected.csg", "coincident_difference.csg",
                  &identity);
    /* And under a similarity far from the origin. */
    stab_similarity x = stab_random(42, 2, 4, 2.0, 100);
    compare_clean("coincident_difference_expected.csg", "coincident_difference.csg", &x);
    compare_clean("coincident_union_expected.csg", "coincident_union.csg", &x);
}

/* ---- rays against the oracle ---- */

/* Checks the spans of ray against csg_inside: sorted, finite, each span's
 * midpoint inside and each gap's midpoint outside (the crossings are even and
 * none is spurious). Returns the span count. */
static uint32_t check_spans(const csg_tree *t, const csg_ray *ray)
{
    arena scratch;
    arena_init(&scratch, 1 << 14);
    span_list l;
    assert_true(csg_spans(t, ray, &scratch, &l));
    for (uint32_t i = 0; i < l.n; i++) {
        assert_true(isfinite(l.v[i].in.t) && isfinite(l.v[i].out.t));
        assert_true(l.v[i].in.t < l.v[i].out.t);
        double mid = 0.5 * (l.v[i].in.t + l.v[i].out.t);
        assert_true(csg_inside(t, v3_madd(ray->o, ray->d, mid)));
        if (i + 1 < l.n) {
            assert_true(l.v[i].out.t < l.v[i + 1].in.t);
            double gap = 0.5 * (l.v[i].out.t + l.v[i + 1].in.t);
            assert_false(csg_inside(t, v3_madd(ray->o, ray->d, gap)));
        }
    }
    csg_hit hit;
    int first = csg_first_hit(t, ray, &scratch, &hit);
    assert_int_equal(first, l.n > 0);
    if (first) {
        assert_true(isfinite(hit.t));
        assert_true(v3_is_finite(csg_hit_normal(t, ray, &hit)));
    }
    uint32_t n = l.n;
    arena_free(&scratch);
    return n;
}

static void test_tangent_sphere_cylinder_torus(void **state)
{
    (void)state;
    sc_scene *s = load_text("sphere(r = 1);");
    csg_ray r = {v3(-5, 1, 0), v3(1, 0, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 0); /* exact tangent: a point */
    r.o.y = 1 + 1e-12;
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    r.o.y = 1 - 1e-12; /* chord 2.8e-6, far above eps */
    assert_int_equal(check_spans(scene_tree(s), &r), 1);
    sc_scene_release(s);

    s = load_text("cylinder(h = 2, r = 1, center = true);");
    r = (csg_ray){v3(-5, 1, 0.3), v3(1, 0, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    r.o.y = 1 + 1e-12;
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    r.o.y = 1 - 1e-12;
    assert_int_equal(check_spans(scene_tree(s), &r), 1);
    sc_scene_release(s);

    s = load_text("torus(r1 = 1, r2 = 0.25);");
    /* Tangent to the top of the tube: touches at two points. */
    r = (csg_ray){v3(-5, 0, 0.25), v3(1, 0, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    r.o.z = 0.25 + 1e-12;
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    r.o.z = 0.25 - 1e-12;
    assert_int_equal(check_spans(scene_tree(s), &r), 2);
    /* Tangent to the outer equator. */
    r = (csg_ray){v3(1.25, -5, 0), v3(0, 1, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 0);
    /* Along the inner equator's tangent: two chords that touch (a double
     * root of the quartic), which the union rule fuses into one span. */
    r = (csg_ray){v3(0.75, -5, 0), v3(0, 1, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 1);
    /* Passing 1e-9 inside the hole keeps a true gap (7.7e-5 wide). */
    r.o.x = 0.75 - 1e-9;
    assert_int_equal(check_spans(scene_tree(s), &r), 2);
    sc_scene_release(s);
}

static void test_grazing_face(void **state)
{
    (void)state;
    /* Rays within 1e-12 rad of the top face of a box, axis-aligned and
     * rotated: the spans must agree with the oracle. */
    const char *models[] = {"cube(size = [1, 1, 1]);", NULL};
    char *rotated = read_model("coincident_union_expected.csg");
    models[1] = rotated;
    for (int m = 0; m < 2; m++) {
        sc_scene *s = load_text(models[m]);
        const csg_tree *t = scene_tree(s);
        affine to_world = test_leaf_to_world(&t->leaves[0]);
        for (int k = -3; k <= 3; k++) {
            for (int up = -1; up <= 1; up += 2) {
                /* In the box's own frame: start above or below the top plane
                 * by k * 1e-13 and climb or dive at 1e-12 rad. */
                vec3 o = v3(-0.5, 0.5, 1 + k * 1e-13), d = v3(1, 0, up * 1e-12);
                csg_ray r = {affine_point(&to_world, o), affine_vector(&to_world, d), 0,
                             INFINITY};
                check_spans(t, &r);
            }
        }
        sc_scene_release(s);
    }
    free(rotated);
}

static void test_thin_wall_and_edge_hole(void **state)
{
    (void)state;
    char *text = read_model("thin_wall.csg");
    sc_scene *s = load_text(text);
    csg_ray r = {v3(-1, 0.5, 0.5), v3(1, 0, 0), 0, INFINITY};
    assert_int_equal(check_spans(scene_tree(s), &r), 1);
    arena scratch;
    arena_init(&scratch, 1 << 14);
    span_list l;
    assert_true(csg_spans(scene_tree(s), &r, &scratch, &l));
    assert_int_equal(l.n, 1);
    /* The wall is 1e-6 thick; its faces are exact to rounding of 1. */
    assert_true(fabs((l.v[0].out.t - l.v[0].in.t) - 1e-6) <= 1e-15);
    arena_free(&scratch);
    sc_scene_release(s);
    free(text);
    stab_similarity x = stab_random(7, -3, 3, 1.0, 10);
    compare_clean("thin_wall.csg", NULL, &x);

    text = read_model("edge_hole.csg");
    s = load_text(text);
    /* Rays along and across the drilled edge. */
    for (int i = 0; i <= 10; i++) {
        double a = 0.1 * i;
        csg_ray along = {v3(a * 0.3, a * 0.3, -1), v3(0, 0, 1), 0, INFINITY};
        check_spans(scene_tree(s), &along);
        csg_ray across = {v3(-1, a * 0.5, 0.5), v3(1, 0, 0), 0, INFINITY};
        check_spans(scene_tree(s), &across);
    }
    sc_scene_release(s);
    free(text);
    x = stab_random(9, -3, 3, 1.0, 10);
    compare_clean("edge_hole.csg", NULL, &x);
}

/* ---- ill-conditioned transforms ---- */

static void test_ill_conditioned(void **state)
{
    (void)state;
    /* Scale 1e-9 along one axis: condition number 1e9, the largest stated. */
    stab_similarity flat = stab_scaled(1, 1, 1e-9, v3(0, 0, 0));
    compare_clean("part.csg", NULL, &flat);
    stab_similarity shear = stab_scaled(1, 1, 1, v3(0, 0, 0));
    shear.m[0][1] = 1e3; /* condition number about 1e6 */
    shear.m[1][2] = -200;
    compare_clean("part.csg", NULL, &shear);
    stab_similarity mirror = stab_scaled(-1, 1, 1, v3(3, 0, 0));
    compare_clean("part.csg", NULL, &mirror);
}

static void test_singular_is_empty(void **state)
{
    (void)state;
    sc_scene *s = load_text(
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]) {\n"
        "  cube(size = [1, 1, 1]);\n}\n");
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "singular transform: subtree is empty");
    double lo[3], hi[3];
    assert_int_equal(sc_scene_bounds(s, lo, hi), 0);
    uint64_t hits;
    assert_int_equal(stab_nan_scan(scene_tree(s), 8, &hits), 0);
    assert_int_equal(hits, 0);
    sc_scene_release(s);
}

/* ---- deep and wide trees ---- */

static void *deep_differences(void *unused)
{
    (void)unused;
    char *text = stab_deep_differences(9999); /* 10000 levels with the leaf */
    sc_scene *s = load_text(text);
    free(text);
    uint64_t hits;
    assert_int_equal(stab_nan_scan(scene_tree(s), 8, &hits), 0);
    assert_true(hits > 0);
    /* A ray through the centre crosses every shell. */
    csg_ray r = {v3(-5, 0.001, 0.0013), v3(1, 0, 0), 0, INFINITY};
    assert_true(check_spans(scene_tree(s), &r) > 1000);
    sc_scene_release(s);
    return NULL;
}

/* Bytes the program holds on the heap (AddressSanitizer replaces malloc and
 * keeps its own count). */
static size_t heap_in_use(void)
{
#if defined(__SANITIZE_ADDRESS__)
    return __sanitizer_get_current_allocated_bytes();
#else
    struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
#endif
}

/* Scratch bytes one ray takes through n nested shells (2n crossings). */
static size_t deep_ray_bytes(int levels)
{
    char *text = stab_deep_differences(levels);
    sc_scene *s = load_text(text);
    free(text);
    arena scratch;
    arena_init(&scratch, 1 << 12);
    size_t before = heap_in_use();
    csg_ray r = {v3(-5, 0.001, 0.0013), v3(1, 0, 0), 0, INFINITY};
    span_list l;
    assert_true(csg_spans(scene_tree(s), &r, &scratch, &l));
    assert_true(l.n >= (uint32_t)levels / 2);
    size_t bytes = heap_in_use() - before;
    arena_free(&scratch);
    sc_scene_release(s);
    return bytes;
}

static void *deep_query_memory(void *unused)
{
    (void)unused;
    /* Four times the depth, about four times the scratch memory (each level
     * used to keep its own copy of the list below it: sixteen times). */
    size_t small = deep_ray_bytes(1000), large = deep_ray_bytes(4000);
    double ratio = (double)large / (double)small;
    print_message("deep ray: %zu and %zu scratch bytes, ratio %.2f\n", small, large,
                  ratio);
    assert_true(ratio < 6);
    return NULL;
}

/* Queries recurse once per level of the compiled tree: about 200 bytes of
 * stack a level in the optimised build, several times that under the
 * sanitizers. The deep cases run on a thread with a 256 MB stack so both
 * builds test the full 10000 levels; docs/stability.md states the stack a
 * deep tree needs. */
static void run_with_stack(void *(*body)(void *))
{
    pthread_attr_t attr;
    pthread_t thread;
    assert_int_equal(pthread_attr_init(&attr), 0);
    assert_int_equal(pthread_attr_setstacksize(&attr, (size_t)256 << 20), 0);
    assert_int_equal(pthread_create(&thread, &attr, body, NULL), 0);
    assert_int_equal(pthread_join(thread, NULL), 0);
    pthread_attr_destroy(&attr);
}

static void test_deep_differences(void **state)
{
    (void)state;
    run_with_stack(deep_differences);
}

static void test_deep_query_memory(void **state)
{
    (void)state;
    run_with_stack(deep_query_memory);
}

static void test_wide_union(void **state)
{
    (void)state;
    size_t bytes[2];
    const int counts[2] = {10000, 100000};
    for (int k = 0; k < 2; k++) {
        char *text = stab_wide_union(counts[k]);
        size_t before = heap_in_use();
        sc_scene *s = load_text(text);
        bytes[k] = heap_in_use() - before;
        free(text);
        assert_int_equal(scene_tree(s)->leaf_count, (uint32_t)counts[k]);
        uint64_t hits;
        assert_int_equal(stab_nan_scan(scene_tree(s), 16, &hits), 0);
        assert_true(hits > 0);
        sc_scene_release(s);
    }
    /* Memory linear in the tree: ten times the leaves, about ten times the
     * bytes (the BVH and arrays grow by doubling, hence the slack). */
    double ratio = (double)bytes[1] / (double)bytes[0];
    print_message("wide union: %zu and %zu bytes, ratio %.2f\n", bytes[0], bytes[1],
                  ratio);
    assert_true(ratio > 5 && ratio < 20);
}

/* ---- far camera ---- */

static void test_far_camera(void **state)
{
    (void)state;
    /* The part seen from 1e9 away (a field of view of about 1e-7 degrees)
     * against the same rays from 10 radii away: same mask, and the depth
     * within 64 ulps of 1e9. At 1e9 the resolution (eps) is 2^-40 * 1e9 =
     * 9.1e-4 units: a pixel whose only spans are shorter than that (a
     * chord clipping an edge) may vanish, by the rule; at most a few. */
    char *text = read_model("part.csg");
    stab_result r;
    sc_error e;
    if (stab_far_camera("part.csg", text, 1e9, IMAGE, &r, &e) != SC_OK)
        fail_msg("%s", e.message);
    free(text);
    print_message("far camera: hits %llu mismatches %llu below resolution %llu nan %llu "
                  "max rel depth %.3g\n",
                  (unsigned long long)r.hits, (unsigned long long)r.mask_mismatches,
                  (unsigned long long)r.below_resolution, (unsigned long long)r.nan_count,
                  r.max_rel_depth_error);
    assert_true(r.hits > IMAGE * IMAGE / 8);
    assert_int_equal(r.mask_mismatches, 0);
    assert_int_equal(r.nan_count, 0);
    assert_int_equal(r.depth_violations, 0);
    assert_true(r.below_resolution <= 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scale),
        cmocka_unit_test(test_translation),
        cmocka_unit_test(test_random_similarities),
        cmocka_unit_test(test_metamorphic_all_models),
        cmocka_unit_test(test_coincident),
        cmocka_unit_test(test_tangent_sphere_cylinder_torus),
        cmocka_unit_test(test_grazing_face),
        cmocka_unit_test(test_thin_wall_and_edge_hole),
        cmocka_unit_test(test_ill_conditioned),
        cmocka_unit_test(test_singular_is_empty),
        cmocka_unit_test(test_deep_differences),
        cmocka_unit_test(test_deep_query_memory),
        cmocka_unit_test(test_wide_union),
        cmocka_unit_test(test_far_camera),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
