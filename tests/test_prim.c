/* Tests of src/csg/prim.c: spans, parts, normals, membership and bounds of
 * the four primitives against hit points worked out by hand, the hard cases
 * (grazing and tangent rays, rays parallel to faces or along a side, rays
 * from inside, a far-off origin), and a sampled check of spans against
 * prim_inside on seeded random rays for every kind.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "csg/prim.h"

static void check_near(double got, double want, double tol, const char *what, int line)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("line %d: %s = %.17g, expected %.17g (tolerance %g)\n", line, what,
                    got, want, tol);
        _fail(__FILE__, line);
    }
}
#define assert_near(got, want, tol) check_near((got), (want), (tol), #got, __LINE__)

enum { LEAF = 7 };

/* Spans of p along o + t d, with the invariants every answer must keep:
 * at most prim_max_spans spans, finite, ordered, leaf set, flip clear. */
static uint32_t shoot(const prim *p, vec3 o, vec3 d, span *s)
{
    span buf[4];
    uint32_t n = prim_spans(p, LEAF, o, d, buf, 4);
    assert_true(n <= prim_max_spans(p));
    for (uint32_t i = 0; i < n; i++) {
        assert_true(isfinite(buf[i].in.t) && isfinite(buf[i].out.t));
        assert_true(buf[i].in.t <= buf[i].out.t);
        assert_int_equal(buf[i].in.leaf, LEAF);
        assert_int_equal(buf[i].out.leaf, LEAF);
        assert_int_equal(buf[i].in.flip, 0);
        assert_int_equal(buf[i].out.flip, 0);
        if (i > 0)
            assert_true(buf[i - 1].out.t < buf[i].in.t);
        s[i] = buf[i];
    }
    return n;
}

/* A tangent or grazing ray may produce no span or one no longer than tol
 * around t (the regularisation removes it). */
static void assert_graze(const prim *p, vec3 o, vec3 d, double t, double tol)
{
    span s[4];
    uint32_t n = shoot(p, o, d, s);
    if (n == 1) {
        assert_true(s[0].out.t - s[0].in.t <= tol);
        assert_near(s[0].in.t, t, tol);
    }
}

static vec3 at(vec3 o, vec3 d, double t)
{
    return v3_madd(o, d, t);
}

static void assert_vec_near(vec3 got, vec3 want, double tol)
{
    assert_near(got.x, want.x, tol);
    assert_near(got.y, want.y, tol);
    assert_near(got.z, want.z, tol);
}

/* Unit normal at the point and part, for comparing directions. */
static vec3 unit_normal(const prim *p, vec3 q, uint16_t part)
{
    vec3 n = prim_normal(p, q, part);
    assert_true(v3_length(n) > 0);
    return v3_normalize(n);
}

static prim make_sphere(double r)
{
    prim p = {.kind = PRIM_SPHERE};
    p.u.sphere.r = r;
    return p;
}

static prim make_box(vec3 lo, vec3 hi)
{
    prim p = {.kind = PRIM_BOX};
    p.u.box.lo = lo;
    p.u.box.hi = hi;
    return p;
}

static prim make_frustum(double z0, double z1, double r0, double r1)
{
    prim p = {.kind = PRIM_CYLINDER};
    p.u.cylinder.z0 = z0;
    p.u.cylinder.z1 = z1;
    p.u.cylinder.r0 = r0;
    p.u.cylinder.r1 = r1;
    return p;
}

static prim make_convex(const plane *planes, uint32_t count, bbox bounds)
{
    prim p = {.kind = PRIM_CONVEX};
    p.u.convex.planes = planes;
    p.u.convex.count = count;
    p.u.convex.bounds = bounds;
    return p;
}

/* Tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1). */
static const plane tetra_planes[4] = {
    {{-1, 0, 0}, 0}, {{0, -1, 0}, 0}, {{0, 0, -1}, 0}, {{1, 1, 1}, 1}};

static prim tetrahedron(void)
{
    bbox b = {{0, 0, 0}, {1, 1, 1}};
    return make_convex(tetra_planes, 4, b);
}

/* Octahedron |x| + |y| + |z| <= 1; plane i has normal signs from its bits
 * (bit 0: x, bit 1: y, bit 2: z; set = negative). The normals have length
 * 2 sqrt(3) and d = 2: scaled planes must give the same t. */
static plane octa_planes[8];

static prim octahedron(void)
{
    for (int i = 0; i < 8; i++) {
        octa_planes[i].n = v3(i & 1 ? -2 : 2, i & 2 ? -2 : 2, i & 4 ? -2 : 2);
        octa_planes[i].d = 2;
    }
    bbox b = {{-1, -1, -1}, {1, 1, 1}};
    return make_convex(octa_planes, 8, b);
}

/* ---- sphere ---- */

/* The classic example: the ray from (1, -2, -1) along (1, 2, 4) against the
 * sphere of radius 3 about (3, 0, 5). In the sphere's frame the origin is
 * o = (1, -2, -1) - (3, 0, 5) = (-2, -2, -6), and |o + t d|^2 = 9 reads
 *   (d.d) t^2 + 2 (o.d) t + o.o - 9 = 0
 *   d.d = 1 + 4 + 16 = 21,  o.d = -2 - 4 - 24 = -30,  o.o = 4 + 4 + 36 = 44
 *   21 t^2 - 60 t + 35 = 0
 *   t = (60 -+ sqrt(3600 - 4 * 21 * 35)) / 42 = (60 -+ sqrt(660)) / 42
 *     = (30 -+ sqrt(165)) / 21
 *     = 0.81689368672...  and  2.04024917041...
 * The entry point is (1.81689..., -0.36621..., 2.26757...), the exit
 * (3.04025..., 2.08050..., 7.16100...); both lie at distance 3 from the
 * centre. */
static void test_sphere_worked_example(void **state)
{
    (void)state;
    prim p = make_sphere(3);
    vec3 o = v3_sub(v3(1, -2, -1), v3(3, 0, 5)), d = v3(1, 2, 4);
    span s[4];
    assert_int_equal(shoot(&p, o, d, s), 1);
    double t0 = (30 - sqrt(165)) / 21, t1 = (30 + sqrt(165)) / 21;
    assert_near(s[0].in.t, t0, 1e-12);
    assert_near(s[0].out.t, t1, 1e-12);
    assert_near(s[0].in.t, 0.816893686730232, 1e-12);
    assert_near(s[0].out.t, 2.040249170412625, 1e-12);
    assert_int_equal(s[0].in.part, PRIM_PART_SPHERE);
    assert_int_equal(s[0].out.part, PRIM_PART_SPHERE);
    vec3 world_in = at(v3(1, -2, -1), d, s[0].in.t);
    assert_near(v3_length(v3_sub(world_in, v3(3, 0, 5))), 3, 1e-12);
    assert_near(v3_length(at(o, d, s[0].out.t)), 3, 1e-12);
    /* The normal is the radius direction. */
    vec3 q = at(o, d, s[0].in.t);
    assert_vec_near(unit_normal(&p, q, s[0].in.part), v3_scale(q, 1.0 / 3), 1e-12);
}

static void test_sphere_inside_and_miss(void **state)
{
    (void)state;
    prim p = make_sphere(1);
    span s[4];
    /* From the centre along a direction of length 2: t = -+1/2. */
    assert_int_equal(shoot(&p, v3(0, 0, 0), v3(0, 0, 2), s), 1);
    assert_near(s[0].in.t, -0.5, 1e-15);
    assert_near(s[0].out.t, 0.5, 1e-15);
    /* Passing at distance 2 misses; a ray pointing away still has its span
     * behind the origin (callers clip). */
    assert_int_equal(shoot(&p, v3(0, 2, 0), v3(1, 0, 0), s), 0);
    assert_int_equal(shoot(&p, v3(5, 0, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, -6, 1e-14);
    assert_near(s[0].out.t, -4, 1e-14);
    /* Tangent at (0, 1, 0), t = 5. */
    assert_graze(&p, v3(-5, 1, 0), v3(1, 0, 0), 5, 1e-7);
    /* A hair inside the tangent: a short chord of half-length sqrt(2e-9). */
    double y = 1 - 1e-9; /* 1 - y and 1 + y are exact */
    assert_int_equal(shoot(&p, v3(-5, y, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].out.t - s[0].in.t, 2 * sqrt((1 - y) * (1 + y)), 1e-11);
    /* A hair outside: nothing. */
    assert_int_equal(shoot(&p, v3(-5, 1 + 1e-9, 0), v3(1, 0, 0), s), 0);
}

/* An origin 1e8 radii away: solved naively, o.o - r^2 = 1e16 - 0.75 loses
 * the 0.75 entirely and the half-chord sqrt(0.75) is lost with it. After
 * the shift to the closest point the answer keeps the accuracy of t itself
 * (an ulp of 1e8 is 1.5e-8). */
static void test_sphere_far_origin(void **state)
{
    (void)state;
    prim p = make_sphere(1);
    span s[4];
    double h = sqrt(0.75);
    assert_int_equal(shoot(&p, v3(-1e8, 0.5, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 1e8 - h, 3e-8);
    assert_near(s[0].out.t, 1e8 + h, 3e-8);
    /* Same with a short, oblique direction: t scales by 1/|d|. */
    vec3 d = v3_scale(v3_normalize(v3(1, 1, 0)), 1e-3);
    vec3 o = v3_madd(v3(0, 0, 0.5), d, -1e11); /* 1e8 units away */
    assert_int_equal(shoot(&p, o, d, s), 1);
    assert_near(s[0].in.t, 1e11 - h * 1e3, 1e-4);
    assert_near(s[0].out.t, 1e11 + h * 1e3, 1e-4);
    assert_near(s[0].out.t - s[0].in.t, 2 * h * 1e3, 1e-4);
}

/* ---- box ---- */

static void test_box_faces(void **state)
{
    (void)state;
    prim p = make_box(v3(-1, -2, -3), v3(1, 2, 3));
    span s[4];
    /* +x: through -x (part 0) at x = -1, out of +x (part 1). */
    assert_int_equal(shoot(&p, v3(-5, 0, 0), v3(2, 0, 0), s), 1);
    assert_near(s[0].in.t, 2, 0);
    assert_near(s[0].out.t, 3, 0);
    assert_int_equal(s[0].in.part, 0);
    assert_int_equal(s[0].out.part, 1);
    /* -y: in through +y (3), out of -y (2). */
    assert_int_equal(shoot(&p, v3(0.5, 5, 0), v3(0, -1, 0), s), 1);
    assert_near(s[0].in.t, 3, 0);
    assert_near(s[0].out.t, 7, 0);
    assert_int_equal(s[0].in.part, 3);
    assert_int_equal(s[0].out.part, 2);
    /* From inside along +z: the entry lies behind the origin. */
    assert_int_equal(shoot(&p, v3(0, 0, 0), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, -3, 0);
    assert_near(s[0].out.t, 3, 0);
    assert_int_equal(s[0].in.part, 4);
    assert_int_equal(s[0].out.part, 5);
    /* Oblique, from o = (-3, -3, 0.5) along (1, 1, 0): the x slab holds
     * t in [2, 4], the y slab [1, 5], the z slab all of it (d_z = 0); enters
     * by -x, leaves by +x. */
    assert_int_equal(shoot(&p, v3(-3, -3, 0.5), v3(1, 1, 0), s), 1);
    assert_near(s[0].in.t, 2, 0);
    assert_near(s[0].out.t, 4, 0);
    assert_int_equal(s[0].in.part, 0);
    assert_int_equal(s[0].out.part, 1);
    /* Oblique leaving by +y: o = (0, 0, 0), d = (1, 4, 0): x out at 1, y at
     * 0.5. */
    assert_int_equal(shoot(&p, v3(0, 0, 0), v3(1, 4, 0), s), 1);
    assert_near(s[0].in.t, -0.5, 0);
    assert_near(s[0].out.t, 0.5, 0);
    assert_int_equal(s[0].in.part, 2);
    assert_int_equal(s[0].out.part, 3);
    /* Normals per part. */
    for (uint16_t part = 0; part < 6; part++) {
        vec3 n = prim_normal(&p, v3(0, 0, 0), part);
        double sign = part & 1 ? 1 : -1;
        assert_near(v3_get(n, part >> 1), sign, 0);
        assert_near(v3_length(n), 1, 0);
    }
}

static void test_box_parallel_and_grazing(void **state)
{
    (void)state;
    prim p = make_box(v3(-1, -2, -3), v3(1, 2, 3));
    span s[4];
    /* Parallel to the y faces, outside them: nothing, and no NaN from 0/0. */
    assert_int_equal(shoot(&p, v3(-5, 2.5, 0), v3(1, 0, 0), s), 0);
    assert_int_equal(shoot(&p, v3(-5, -2.5, 0), v3(1, 0, 0), s), 0);
    /* In the plane of the +y face: the closed box holds the segment. */
    assert_int_equal(shoot(&p, v3(-5, 2, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 4, 0);
    assert_near(s[0].out.t, 6, 0);
    /* Origin on a face, moving along it: (lo - o) / d would be 0/0 on x. */
    assert_int_equal(shoot(&p, v3(1, 0, 0), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, -2, 0);
    assert_near(s[0].out.t, 2, 0);
    /* Through the edge x = 1, y = 2 diagonally: a single point. */
    assert_graze(&p, v3(0, 3, 0), v3(1, -1, 0), 1, 0);
    /* Touching the corner (1, 2, 3) only: y > 2 before it, x > 1 after. */
    assert_graze(&p, v3(0, 3, 2), v3(1, -1, 1), 1, 0);
    /* Along the diagonal through that corner, which runs inside. */
    assert_int_equal(shoot(&p, v3(2, 3, 4), v3(1, 1, 1), s), 1);
    assert_near(s[0].in.t, -3, 0);
    assert_near(s[0].out.t, -1, 0);
    assert_int_equal(s[0].in.part, 0);
    assert_int_equal(s[0].out.part, 1);
    /* Degenerate directions give nothing, not NaN. */
    assert_int_equal(shoot(&p, v3(0, 0, 0), v3(0, 0, 0), s), 0);
    /* cap = 0 writes nothing. */
    assert_int_equal(prim_spans(&p, 0, v3(-5, 0, 0), v3(1, 0, 0), s, 0), 0);
}

/* ---- cylinder and cone ---- */

static void test_cylinder_side_and_caps(void **state)
{
    (void)state;
    prim p = make_frustum(0, 2, 1, 1);
    span s[4];
    /* Across the side at z = 1. */
    assert_int_equal(shoot(&p, v3(-3, 0, 1), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 4, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_SIDE);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_SIDE);
    assert_vec_near(unit_normal(&p, v3(-1, 0, 1), PRIM_PART_CYL_SIDE), v3(-1, 0, 0), 0);
    /* Off-centre chord at y = 0.6: x = -+0.8. */
    assert_int_equal(shoot(&p, v3(-3, 0.6, 1), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 2.2, 1e-15);
    assert_near(s[0].out.t, 3.8, 1e-15);
    vec3 n = unit_normal(&p, at(v3(-3, 0.6, 1), v3(1, 0, 0), s[0].in.t), 0);
    assert_vec_near(n, v3(-0.8, 0.6, 0), 1e-15);
    /* Parallel to the axis, through both caps, both ways. */
    assert_int_equal(shoot(&p, v3(0.5, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 3, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_BOTTOM);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_TOP);
    assert_int_equal(shoot(&p, v3(0.5, 0, 5), v3(0, 0, -2), s), 1);
    assert_near(s[0].in.t, 1.5, 1e-15);
    assert_near(s[0].out.t, 2.5, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_TOP);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_BOTTOM);
    assert_vec_near(prim_normal(&p, v3(0, 0, 0), PRIM_PART_CYL_BOTTOM), v3(0, 0, -1), 0);
    assert_vec_near(prim_normal(&p, v3(0, 0, 2), PRIM_PART_CYL_TOP), v3(0, 0, 1), 0);
    /* Parallel to the axis, outside: nothing. */
    assert_int_equal(shoot(&p, v3(1.5, 0, 0), v3(0, 0, 1), s), 0);
    /* Along the side itself (x = 1): the closed solid holds the line. */
    assert_int_equal(shoot(&p, v3(1, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 3, 1e-15);
    /* In through the bottom cap, out through the side: o = (0, 0, -1),
     * d = (0.5, 0, 1) reaches z = 0 at t = 1 (x = 0.5), x = 1 at t = 2. */
    assert_int_equal(shoot(&p, v3(0, 0, -1), v3(0.5, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 2, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_BOTTOM);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_SIDE);
    /* Tangent to the side, and in the plane of the top cap. */
    assert_graze(&p, v3(-3, 1, 1), v3(1, 0, 0), 3, 1e-7);
    assert_int_equal(shoot(&p, v3(-3, 1 + 1e-9, 1), v3(1, 0, 0), s), 0);
    assert_int_equal(shoot(&p, v3(-3, 0, 2), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 4, 1e-15);
    assert_int_equal(shoot(&p, v3(-3, 0, 2 + 1e-12), v3(1, 0, 0), s), 0);
    /* From inside, obliquely. */
    assert_int_equal(shoot(&p, v3(0, 0, 1), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, -1, 1e-15);
    assert_near(s[0].out.t, 1, 1e-15);
}

static void test_cone(void **state)
{
    (void)state;
    /* Apex at the top: radius 1 at z = 0, 0 at z = 1, slope -1. */
    prim p = make_frustum(0, 1, 1, 0);
    span s[4];
    /* Horizontally at z = 0.5 (radius 0.5). */
    assert_int_equal(shoot(&p, v3(-2, 0, 0.5), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 1.5, 1e-15);
    assert_near(s[0].out.t, 2.5, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_SIDE);
    /* The side's normal leans up at 45 degrees. */
    assert_vec_near(unit_normal(&p, v3(-0.5, 0, 0.5), PRIM_PART_CYL_SIDE),
                    v3(-sqrt(0.5), 0, sqrt(0.5)), 1e-15);
    /* Up the axis: bottom cap at t = 1 to the apex at t = 2 (a double root of
     * the side quadric). */
    assert_int_equal(shoot(&p, v3(0, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 2, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_BOTTOM);
    /* Horizontally through the apex: a single point at most. */
    assert_graze(&p, v3(-2, 0, 1), v3(1, 0, 0), 2, 1e-7);
    /* Parallel to a generator (a = 0, the side equation is linear):
     * x = z - 0.5 enters the bottom at t = 1 (x = -0.5) and meets the far
     * side x = 1 - z at z = 0.75, t = 1.75. */
    assert_int_equal(shoot(&p, v3(-1.5, 0, -1), v3(1, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 1.75, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_BOTTOM);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_SIDE);
    /* Along a generator x = z - 1 itself: the closed cone holds it from the
     * rim (t = 1) to the apex (t = 2). */
    assert_int_equal(shoot(&p, v3(-2, 0, -1), v3(1, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 2, 1e-15);
    /* Apex normal points up, away from the solid. */
    assert_vec_near(unit_normal(&p, v3(0, 0, 1), PRIM_PART_CYL_SIDE), v3(0, 0, 1), 0);

    /* Apex at the bottom: radius 0 at z = 0, 2 at z = 2 (slope 1). The
     * quadric x^2 + y^2 = z^2 has a mirrored nappe below the apex, which the
     * ray x = 0.5 parallel to the axis crosses for z <= -0.5: it must not
     * show. Inside the cone it runs from z = 0.5 (t = 1.5) to the top. */
    prim q = make_frustum(0, 2, 0, 2);
    assert_int_equal(shoot(&q, v3(0.5, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1.5, 1e-15);
    assert_near(s[0].out.t, 3, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_SIDE);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_TOP);
    /* Down the axis through the apex. */
    assert_int_equal(shoot(&q, v3(0, 0, 5), v3(0, 0, -1), s), 1);
    assert_near(s[0].in.t, 3, 1e-15);
    assert_near(s[0].out.t, 5, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_TOP);
    /* Steeper than a generator, crossing below the apex into the mirrored
     * nappe and out the far side of the real one: o = (-2, 0, -1),
     * d = (1, 0, 3); x = -2 + t, z = -1 + 3t. Real nappe |x| <= z for
     * z >= 0: -2 + t >= 1 - 3t gives t >= 0.75 (z = 1.25, x = -1.25 on the
     * side), and it leaves through the top cap z = 2 at t = 1. */
    assert_int_equal(shoot(&q, v3(-2, 0, -1), v3(1, 0, 3), s), 1);
    assert_near(s[0].in.t, 0.75, 1e-15);
    assert_near(s[0].out.t, 1, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CYL_SIDE);
    assert_int_equal(s[0].out.part, PRIM_PART_CYL_TOP);
    assert_vec_near(unit_normal(&q, v3(-1.25, 0, 1.25), PRIM_PART_CYL_SIDE),
                    v3(-sqrt(0.5), 0, -sqrt(0.5)), 1e-15);
    /* A frustum with both radii > 0 (2 at z = -1, 1 at z = 1). */
    prim f = make_frustum(-1, 1, 2, 1);
    assert_int_equal(shoot(&f, v3(-5, 0, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 3.5, 1e-15);
    assert_near(s[0].out.t, 6.5, 1e-15);
}

/* ---- convex polyhedra ---- */

static void test_convex_tetrahedron(void **state)
{
    (void)state;
    prim p = tetrahedron();
    span s[4];
    /* Up through z = 0 (plane 2) at t = 1, out through x + y + z = 1
     * (plane 3) at z = 0.7, t = 1.7. */
    assert_int_equal(shoot(&p, v3(0.1, 0.2, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 1.7, 1e-15);
    assert_int_equal(s[0].in.part, 2);
    assert_int_equal(s[0].out.part, 3);
    assert_vec_near(prim_normal(&p, v3(0, 0, 0), 3), v3(1, 1, 1), 0);
    /* Parallel to plane x = 0 and outside it: nothing. */
    assert_int_equal(shoot(&p, v3(-0.1, 0.2, -1), v3(0, 0, 1), s), 0);
    /* In the plane x = 0: unconstrained by it, z from 0 to 0.8. */
    assert_int_equal(shoot(&p, v3(0, 0.2, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-15);
    assert_near(s[0].out.t, 1.8, 1e-15);
    /* From inside, downwards. */
    assert_int_equal(shoot(&p, v3(0.1, 0.1, 0.1), v3(0, 0, -1), s), 1);
    assert_near(s[0].in.t, -0.7, 1e-15);
    assert_near(s[0].out.t, 0.1, 1e-15);
    assert_int_equal(s[0].in.part, 3);
    assert_int_equal(s[0].out.part, 2);
    /* Through the vertex (0, 0, 1) only. */
    assert_graze(&p, v3(-1, 0, 1), v3(1, 0, 0), 1, 0);
    /* Past the slanted face. */
    assert_int_equal(shoot(&p, v3(0.5, 0.5, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].out.t - s[0].in.t, 0, 1e-15);
    assert_int_equal(shoot(&p, v3(0.6, 0.5, -1), v3(0, 0, 1), s), 0);
}

static void test_convex_octahedron(void **state)
{
    (void)state;
    prim p = octahedron();
    span s[4];
    /* o = (-3, 0.1, 0.2), d = (1, 0, 0): enters the face with normal
     * (-, +, +) (plane 1) where -x + 0.3 = 1, x = -0.7, t = 2.3; leaves the
     * face (+, +, +) (plane 0) where x + 0.3 = 1, t = 3.7. */
    assert_int_equal(shoot(&p, v3(-3, 0.1, 0.2), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 2.3, 1e-15);
    assert_near(s[0].out.t, 3.7, 1e-15);
    assert_int_equal(s[0].in.part, 1);
    assert_int_equal(s[0].out.part, 0);
    vec3 n = unit_normal(&p, v3(-0.7, 0.1, 0.2), 1);
    assert_vec_near(n, v3(-1 / sqrt(3), 1 / sqrt(3), 1 / sqrt(3)), 1e-15);
    /* From the centre along (1, 1, 1): the face x + y + z = 1 at t = 1/3. */
    assert_int_equal(shoot(&p, v3(0, 0, 0), v3(1, 1, 1), s), 1);
    assert_near(s[0].in.t, -1.0 / 3, 1e-15);
    assert_near(s[0].out.t, 1.0 / 3, 1e-15);
    assert_int_equal(s[0].in.part, 7);
    assert_int_equal(s[0].out.part, 0);
    /* Along the edge direction (1, -1, 0), parallel to the faces with
     * normal (+,+,*) and (-,-,*): at z = 0.5, y + x = 0 lies in... o =
     * (0, 0, 0.5): |x| + |y| <= 0.5 gives x in [-0.25, 0.25]. */
    assert_int_equal(shoot(&p, v3(0, 0, 0.5), v3(1, -1, 0), s), 1);
    assert_near(s[0].in.t, -0.25, 1e-15);
    assert_near(s[0].out.t, 0.25, 1e-15);
    /* Parallel to the face x + y + z = 1, just outside: nothing. */
    assert_int_equal(shoot(&p, v3(0.5, 0.5, 0.01), v3(1, -1, 0), s), 0);
    /* Grazing the vertex (1, 0, 0). */
    assert_graze(&p, v3(1, -2, 0), v3(0, 1, 0), 2, 0);
}

/* ---- membership and bounds ---- */

static void test_inside(void **state)
{
    (void)state;
    prim sphere = make_sphere(2);
    assert_true(prim_inside(&sphere, v3(0, 0, 0)));
    assert_true(prim_inside(&sphere, v3(0, 2, 0)));
    assert_true(prim_inside(&sphere, v3(1.1, 1.1, 1.1)));
    assert_false(prim_inside(&sphere, v3(1.2, 1.2, 1.2)));
    prim box = make_box(v3(-1, -2, -3), v3(1, 2, 3));
    assert_true(prim_inside(&box, v3(1, -2, 3)));
    assert_true(prim_inside(&box, v3(0.9, 1.9, -2.9)));
    assert_false(prim_inside(&box, v3(1.01, 0, 0)));
    assert_false(prim_inside(&box, v3(0, 0, -3.01)));
    prim cyl = make_frustum(0, 2, 1, 1);
    assert_true(prim_inside(&cyl, v3(0.6, 0.8, 1)));
    assert_true(prim_inside(&cyl, v3(0, 0, 0)));
    assert_false(prim_inside(&cyl, v3(0.7, 0.8, 1)));
    assert_false(prim_inside(&cyl, v3(0, 0, 2.01)));
    assert_false(prim_inside(&cyl, v3(0, 0, -0.01)));
    prim cone = make_frustum(0, 2, 0, 2);
    assert_true(prim_inside(&cone, v3(0, 0, 0)));
    assert_true(prim_inside(&cone, v3(0.5, 0, 0.6)));
    assert_false(prim_inside(&cone, v3(0.5, 0, 0.4)));
    assert_false(prim_inside(&cone, v3(0, 0, -0.5))); /* mirrored nappe */
    prim tet = tetrahedron();
    assert_true(prim_inside(&tet, v3(0.25, 0.25, 0.25)));
    assert_true(prim_inside(&tet, v3(0, 0, 1)));
    assert_false(prim_inside(&tet, v3(0.4, 0.4, 0.4)));
    assert_false(prim_inside(&tet, v3(-0.01, 0.1, 0.1)));
    prim oct = octahedron();
    assert_true(prim_inside(&oct, v3(0.3, -0.3, 0.3)));
    assert_false(prim_inside(&oct, v3(0.4, -0.4, 0.4)));
}

static void test_bounds(void **state)
{
    (void)state;
    prim sphere = make_sphere(2);
    bbox b = prim_bounds(&sphere);
    assert_vec_near(b.lo, v3(-2, -2, -2), 0);
    assert_vec_near(b.hi, v3(2, 2, 2), 0);
    prim box = make_box(v3(-1, -2, -3), v3(1, 2, 3));
    b = prim_bounds(&box);
    assert_vec_near(b.lo, v3(-1, -2, -3), 0);
    assert_vec_near(b.hi, v3(1, 2, 3), 0);
    prim cone = make_frustum(-1, 4, 3, 0.5);
    b = prim_bounds(&cone);
    assert_vec_near(b.lo, v3(-3, -3, -1), 0);
    assert_vec_near(b.hi, v3(3, 3, 4), 0);
    prim tet = tetrahedron();
    b = prim_bounds(&tet);
    assert_vec_near(b.lo, v3(0, 0, 0), 0);
    assert_vec_near(b.hi, v3(1, 1, 1), 0);
    assert_int_equal(prim_max_spans(&sphere), 1);
    assert_int_equal(prim_max_spans(&tet), 1);
}

/* ---- sampled agreement of spans with membership ---- */

static uint64_t rng_state;

static double uniform(void)
{
    /* xorshift64*, seeded per test */
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

static double uniform_in(double lo, double hi)
{
    return lo + (hi - lo) * uniform();
}

/* For random rays aimed near each primitive (some along axes, some from
 * inside), points well inside each span are inside and points farther than
 * tol from every span end outside the span are outside. tol is relative to
 * the primitive's size (about 3) and to |d| (about 1). */
static void test_spans_agree_with_inside(void **state)
{
    (void)state;
    rng_state = 0x9e3779b97f4a7c15ULL;
    prim shapes[] = {make_sphere(1.5),
                     make_box(v3(-1, -0.5, -2), v3(1.5, 1, 0.5)),
                     make_frustum(-1, 1.5, 1.2, 0.4),
                     make_frustum(-1, 1, 0, 1.5),
                     make_frustum(-1, 1, 1, 1),
                     tetrahedron(),
                     octahedron()};
    const double tol = 1e-9;
    long checked = 0;
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        const prim *p = &shapes[k];
        for (int i = 0; i < 4000; i++) {
            vec3 target = v3(uniform_in(-2, 2), uniform_in(-2, 2), uniform_in(-2, 2));
            vec3 d = v3(uniform_in(-1, 1), uniform_in(-1, 1), uniform_in(-1, 1));
            if (i % 4 == 1) /* along an axis */
                d = v3(i % 3 == 0, i % 3 == 1, i % 3 == 2);
            vec3 o = v3_madd(target, d, -uniform_in(0, 6));
            span s[4];
            uint32_t n = shoot(p, o, d, s);
            double len = v3_length(d);
            for (int j = 0; j < 40; j++) {
                double t = uniform_in(-8, 8);
                int in_span = 0, near_end = 0;
                for (uint32_t m = 0; m < n; m++) {
                    if (t >= s[m].in.t && t <= s[m].out.t)
                        in_span = 1;
                    if (fabs(t - s[m].in.t) * len <= tol ||
                        fabs(t - s[m].out.t) * len <= tol)
                        near_end = 1;
                }
                if (near_end)
                    continue;
                int inside = prim_inside(p, at(o, d, t));
                if (inside != in_span) {
                    print_error("shape %zu ray %d: t = %.17g inside = %d, span = %d\n", k,
                                i, t, inside, in_span);
                    fail();
                }
                checked++;
            }
        }
    }
    assert_true(checked > 1000000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_worked_example),
        cmocka_unit_test(test_sphere_inside_and_miss),
        cmocka_unit_test(test_sphere_far_origin),
        cmocka_unit_test(test_box_faces),
        cmocka_unit_test(test_box_parallel_and_grazing),
        cmocka_unit_test(test_cylinder_side_and_caps),
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_convex_tetrahedron),
        cmocka_unit_test(test_convex_octahedron),
        cmocka_unit_test(test_inside),
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_spans_agree_with_inside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
