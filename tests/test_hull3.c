/* Tests of the 3D convex hull (src/csg/hull3.c): the exact orientation
 * test, and hulls of seeded random point sets (uniform in a cube, on a
 * sphere, on a lattice full of coplanar and collinear points, with
 * duplicates): the surface is closed and consistently wound (Euler's
 * formula holds), every input point is inside or on every triangle
 * (exactly) and every plane, every hull vertex is an input point, and the
 * volume of known hulls is right. Flat, collinear, tiny and non-finite
 * sets are refused as they should be. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "csg/hull3.h"

static uint64_t rng_state;

static double uniform(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* Every property a hull of points must have. */
static void check_hull(const vec3 *points, uint32_t count, const hull3 *h)
{
    assert_true(h->tri_count >= 4);
    assert_true(h->plane_count >= 4);
    /* closed and consistently wound: each directed edge once, its reverse once */
    uint64_t *edges = malloc(3 * (size_t)h->tri_count * sizeof *edges);
    assert_non_null(edges);
    for (uint32_t t = 0; t < h->tri_count; t++) {
        for (int k = 0; k < 3; k++) {
            uint64_t a = h->tris[3 * t + (uint32_t)k];
            uint64_t b = h->tris[3 * t + (uint32_t)(k + 1) % 3];
            assert_true(a != b);
            edges[3 * t + (uint32_t)k] = a << 32 | b;
        }
    }
    size_t ne = 3 * (size_t)h->tri_count;
    qsort(edges, ne, sizeof *edges, compare_u64);
    for (size_t i = 0; i + 1 < ne; i++)
        assert_true(edges[i] != edges[i + 1]);
    for (size_t i = 0; i < ne; i++) {
        uint64_t reverse = (edges[i] & 0xffffffffu) << 32 | edges[i] >> 32;
        assert_non_null(bsearch(&reverse, edges, ne, sizeof *edges, compare_u64));
    }
    free(edges);
    /* Euler: V - E + F = 2 for a sphere-like surface */
    assert_int_equal((long)h->vertex_count - (long)(ne / 2) + (long)h->tri_count, 2);
    /* every vertex is an input point */
    for (uint32_t v = 0; v < h->vertex_count; v++) {
        int found = 0;
        for (uint32_t i = 0; i < count && !found; i++)
            found = memcmp(&h->vertices[v], &points[i], sizeof(vec3)) == 0;
        assert_true(found);
    }
    /* every point inside or on: exactly against triangles, within rounding
     * against planes */
    double scale = 0;
    for (uint32_t i = 0; i < count; i++)
        scale = fmax(scale, v3_max_abs(points[i]));
    for (uint32_t i = 0; i < count; i++) {
        for (uint32_t t = 0; t < h->tri_count; t++) {
            const uint32_t *tri = &h->tris[3 * t];
            assert_true(hull3_orient(h->vertices[tri[0]], h->vertices[tri[1]],
                                     h->vertices[tri[2]], points[i]) <= 0);
        }
        for (uint32_t k = 0; k < h->plane_count; k++)
            assert_true(v3_dot(h->planes[k].n, points[i]) <=
                        h->planes[k].d + 1e-12 * scale);
    }
    /* every vertex lies on some plane */
    for (uint32_t v = 0; v < h->vertex_count; v++) {
        int on = 0;
        for (uint32_t k = 0; k < h->plane_count && !on; k++)
            on = fabs(v3_dot(h->planes[k].n, h->vertices[v]) - h->planes[k].d) <=
                 1e-12 * scale;
        assert_true(on);
    }
    assert_true(hull3_volume(h) > 0);
}

static void test_orient(void **state)
{
    (void)state;
    vec3 a = v3(0, 0, 0), b = v3(1, 0, 0), c = v3(0, 1, 0);
    assert_int_equal(hull3_orient(a, b, c, v3(0, 0, 1)), 1);
    assert_int_equal(hull3_orient(a, b, c, v3(0, 0, -1)), -1);
    assert_int_equal(hull3_orient(a, b, c, v3(5, 7, 0)), 0);
    /* points exactly on the plane z = x + y, far from the origin, where the
     * floating-point determinant is pure rounding noise; one ulp off it the
     * sign must be right */
    rng_state = 7;
    for (int i = 0; i < 2000; i++) {
        vec3 p[4];
        for (int k = 0; k < 4; k++) {
            double x = 1e6 + ldexp(floor(uniform() * 1048576), -20);
            double y = -3e5 + ldexp(floor(uniform() * 1048576), -20);
            p[k] = v3(x, y, x + y);
        }
        assert_int_equal(hull3_orient(p[0], p[1], p[2], p[3]), 0);
        vec3 up = p[3], down = p[3];
        up.z = nextafter(up.z, INFINITY);
        down.z = nextafter(down.z, -INFINITY);
        int su = hull3_orient(p[0], p[1], p[2], up);
        int sd = hull3_orient(p[0], p[1], p[2], down);
        /* a degenerate (collinear) triangle gives 0 on both sides */
        assert_int_equal(su, -sd);
        if (su != 0) {
            vec3 n = v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0]));
            assert_int_equal(su, n.z > 0 ? 1 : -1);
        }
    }
}

static void test_random_cube(void **state)
{
    (void)state;
    rng_state = 1;
    for (int round = 0; round < 10; round++) {
        uint32_t n = 50 + 50 * (uint32_t)round;
        vec3 *p = malloc(n * sizeof *p);
        for (uint32_t i = 0; i < n; i++)
            p[i] = v3(uniform() * 2 - 1, uniform() * 2 - 1, uniform() * 2 - 1);
        hull3 h;
        assert_int_equal(hull3_compute(p, n, &h), HULL3_OK);
        check_hull(p, n, &h);
        assert_true(hull3_volume(&h) < 8);
        hull3_free(&h);
        free(p);
    }
}

static void test_random_sphere(void **state)
{
    (void)state;
    rng_state = 2;
    uint32_t n = 400;
    vec3 *p = malloc(n * sizeof *p);
    for (uint32_t i = 0; i < n; i++) {
        double z = uniform() * 2 - 1, phi = uniform() * 6.283185307179586;
        double r = sqrt(1 - z * z);
        p[i] = v3(100 + 3 * r * cos(phi), -50 + 3 * r * sin(phi), 7 + 3 * z);
    }
    hull3 h;
    assert_int_equal(hull3_compute(p, n, &h), HULL3_OK);
    check_hull(p, n, &h);
    assert_int_equal(h.vertex_count, n); /* points in convex position */
    /* the inscribed volume approaches the ball's from below */
    double ball = 4.0 / 3.0 * 3.141592653589793 * 27;
    assert_true(hull3_volume(&h) < ball && hull3_volume(&h) > 0.9 * ball);
    hull3_free(&h);
    free(p);
}

/* A 5x5x5 lattice, shuffled, each point three times: the hull is the cube
 * [0, 4]^3, with its coplanar triangles merged into six planes. */
static void test_lattice(void **state)
{
    (void)state;
    rng_state = 3;
    uint32_t n = 3 * 125;
    vec3 *p = malloc(n * sizeof *p);
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = i % 125;
        p[i] = v3(k % 5, (k / 5) % 5, k / 25);
    }
    for (uint32_t i = n - 1; i > 0; i--) {
        uint32_t j = (uint32_t)(uniform() * (i + 1));
        vec3 t = p[i];
        p[i] = p[j];
        p[j] = t;
    }
    hull3 h;
    assert_int_equal(hull3_compute(p, n, &h), HULL3_OK);
    check_hull(p, n, &h);
    assert_int_equal(h.plane_count, 6);
    assert_true(fabs(hull3_volume(&h) - 64) <= 1e-12);
    assert_true(h.bounds.lo.x == 0 && h.bounds.hi.z == 4);
    hull3_free(&h);
    free(p);
}

/* Known volumes: a unit cube's corners with points inside and on its
 * faces; a tetrahedron with points on its edges. */
static void test_known_volumes(void **state)
{
    (void)state;
    rng_state = 4;
    vec3 p[200];
    uint32_t n = 0;
    for (int k = 0; k < 8; k++)
        p[n++] = v3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    for (int i = 0; i < 100; i++)
        p[n++] = v3(uniform(), uniform(), uniform());
    for (int i = 0; i < 50; i++)
        p[n++] = v3(uniform(), uniform(), i & 1);
    hull3 h;
    assert_int_equal(hull3_compute(p, n, &h), HULL3_OK);
    check_hull(p, n, &h);
    assert_true(h.vertex_count >= 8); /* points on faces may stay as vertices */
    assert_int_equal(h.plane_count, 6);
    assert_true(fabs(hull3_volume(&h) - 1) <= 1e-14);
    hull3_free(&h);

    n = 0;
    vec3 corner[4] = {v3(0, 0, 0), v3(3, 0, 0), v3(0, 3, 0), v3(0, 0, 3)};
    for (int k = 0; k < 4; k++)
        p[n++] = corner[k];
    for (int i = 0; i < 60; i++) {
        double t = floor(uniform() * 16) / 16; /* exactly on the edge */
        vec3 a = corner[i % 4], b = corner[(i / 4 + i + 1) % 4];
        p[n++] = v3_add(v3_scale(a, 1 - t), v3_scale(b, t));
    }
    assert_int_equal(hull3_compute(p, n, &h), HULL3_OK);
    check_hull(p, n, &h);
    assert_int_equal(h.plane_count, 4);
    assert_true(fabs(hull3_volume(&h) - 4.5) <= 1e-13);
    hull3_free(&h);
}

static void test_degenerate(void **state)
{
    (void)state;
    hull3 h;
    vec3 p[64] = {{0, 0, 0}};
    assert_int_equal(hull3_compute(p, 0, &h), HULL3_FLAT);
    p[0] = v3(0, 0, 0);
    p[1] = v3(1, 0, 0);
    p[2] = v3(0, 1, 0);
    assert_int_equal(hull3_compute(p, 3, &h), HULL3_FLAT);
    /* on one plane, exactly */
    rng_state = 5;
    for (int i = 0; i < 64; i++) {
        double x = floor(uniform() * 64), y = floor(uniform() * 64);
        p[i] = v3(x, y, 3 * x - 2 * y + 0.5);
    }
    assert_int_equal(hull3_compute(p, 64, &h), HULL3_FLAT);
    /* on one line */
    for (int i = 0; i < 64; i++)
        p[i] = v3(i, 2 * i, -i);
    assert_int_equal(hull3_compute(p, 64, &h), HULL3_FLAT);
    /* one point, repeated */
    for (int i = 0; i < 64; i++)
        p[i] = v3(1, 2, 3);
    assert_int_equal(hull3_compute(p, 64, &h), HULL3_FLAT);
    assert_null(h.vertices);
    /* a tiny tetrahedron still has volume */
    p[0] = v3(0, 0, 0);
    p[1] = v3(1e-100, 0, 0);
    p[2] = v3(0, 1e-100, 0);
    p[3] = v3(0, 0, 1e-100);
    assert_int_equal(hull3_compute(p, 4, &h), HULL3_OK);
    assert_int_equal(h.vertex_count, 4);
    hull3_free(&h);
    /* non-finite and huge coordinates */
    p[3] = v3(0, NAN, 1);
    assert_int_equal(hull3_compute(p, 4, &h), HULL3_RANGE);
    p[3] = v3(0, 0, 1e300);
    assert_int_equal(hull3_compute(p, 4, &h), HULL3_RANGE);
}

/* A face whose corners are nearly collinear (a sliver): the rounded cross
 * product of its edges points anywhere, so an offset taken over its own
 * corners alone cut the hull in half. The five points are a part of
 * CGAL's convex decomposition of a rotate_extrude summed with a small
 * cube (a minkowski): points 0, 1 and 2 lie within 1e-16 of a line, and
 * the hull is the tetrahedron 0, 1, 3, 4. */
static void test_sliver_face(void **state)
{
    (void)state;
    vec3 p[5] = {
        {-2.4270013920603892, -1.7633061658129663, 4.530048370361328},
        {-0.5015493397893865, -0.3643833642028818, 4.9591064453125e-05},
        {-0.6742430592189828, -0.4898526956879091, 0.4063450048015077},
        {-4.255496896918263, -0.20797935589567218, 0.5343694404397445},
        {-4.38163814594173, -0.3643833642028818, -4.9591064453125e-05},
    };
    hull3 h;
    assert_int_equal(hull3_compute(p, 5, &h), HULL3_OK);
    check_hull(p, 5, &h);
    assert_true(fabs(hull3_volume(&h) - 0.9416484848155497) <= 1e-12);
    hull3_free(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_orient),        cmocka_unit_test(test_random_cube),
        cmocka_unit_test(test_random_sphere), cmocka_unit_test(test_lattice),
        cmocka_unit_test(test_known_volumes), cmocka_unit_test(test_degenerate),
        cmocka_unit_test(test_sliver_face),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
