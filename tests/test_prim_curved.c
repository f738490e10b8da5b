/* Tests of the leaves with several spans (src/csg/prim_torus.c,
 * prim_quadric.c, prim_implicit.c): hits worked out by hand, the torus's
 * hard cases (a tube 1000 times thinner than the ring, origins 1e4 radii
 * away, rays grazing the tube from outside and inside), quadrics of every
 * family against the clipping box (cones and hyperboloids with two spans,
 * rays along an asymptotic direction), implicit leaves against the exact
 * sphere, box-face parts and normals, and a sampled check of spans against
 * prim_inside on seeded random rays for each kind.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "csg/prim.h"
#include "csg/prim_curved.h"
#include "implicit/expr.h"
#include "implicit/solve.h"

static void check_near(double got, double want, double tol, const char *what, int line)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("line %d: %s = %.17g, expected %.17g (tolerance %g)\n", line, what,
                    got, want, tol);
        _fail(__FILE__, line);
    }
}
#define assert_near(got, want, tol) check_near((got), (want), (tol), #got, __LINE__)

enum { LEAF = 5, MAX = PRIM_IMPLICIT_MAX_SPANS };

/* Spans with the invariants every answer keeps: at most prim_max_spans,
 * finite, ordered and disjoint, leaf set. */
static uint32_t shoot(const prim *p, vec3 o, vec3 d, span *s)
{
    uint32_t n = prim_spans(p, LEAF, o, d, s, prim_max_spans(p));
    assert_true(n <= prim_max_spans(p));
    for (uint32_t i = 0; i < n; i++) {
        assert_true(isfinite(s[i].in.t) && isfinite(s[i].out.t));
        assert_true(s[i].in.t <= s[i].out.t);
        assert_int_equal(s[i].in.leaf, LEAF);
        assert_int_equal(s[i].out.leaf, LEAF);
        if (i > 0)
            assert_true(s[i - 1].out.t < s[i].in.t);
    }
    return n;
}

static prim torus(double major, double minor)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_TORUS;
    p.u.torus.major = major;
    p.u.torus.minor = minor;
    return p;
}

/* A quadric leaf whose coefficients are kept in *store. */
static prim quadric(prim_quadric *store, const double a[10], vec3 lo, vec3 hi)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_QUADRIC;
    memcpy(store->a, a, 10 * sizeof a[0]);
    store->box = (bbox){lo, hi};
    p.u.quadric.q = store;
    return p;
}

static prim implicit(const expr_program *f, vec3 lo, vec3 hi, double tol)
{
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_IMPLICIT;
    p.u.implicit.program = f;
    p.u.implicit.box = (bbox){lo, hi};
    p.u.implicit.tolerance = tol;
    p.u.implicit.method = SOLVE_INTERVAL;
    return p;
}

static void compile(const char *src, expr_program *p)
{
    expr_error e;
    if (!expr_compile(src, strlen(src), NULL, 0, p, &e))
        fail_msg("'%s': %s", src, e.message);
}

/* ---- torus ---- */

static void test_torus_worked_example(void **state)
{
    (void)state;
    prim p = torus(2, 0.5);
    span s[2];
    /* along x through the centre: x = -2.5, -1.5, 1.5, 2.5 */
    assert_int_equal(shoot(&p, v3(-5, 0, 0), v3(1, 0, 0), s), 2);
    assert_near(s[0].in.t, 2.5, 1e-15);
    assert_near(s[0].out.t, 3.5, 1e-15);
    assert_near(s[1].in.t, 6.5, 1e-15);
    assert_near(s[1].out.t, 7.5, 1e-15);
    /* direction length 4 gives t in quarter units */
    assert_int_equal(shoot(&p, v3(-5, 0, 0), v3(4, 0, 0), s), 2);
    assert_near(s[1].out.t, 7.5 / 4, 1e-15);
    /* along z through the tube's centre circle: one span, |z| <= 0.5 */
    assert_int_equal(shoot(&p, v3(2, 0, -3), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 2.5, 1e-15);
    assert_near(s[0].out.t, 3.5, 1e-15);
    /* down the axis: through the hole */
    assert_int_equal(shoot(&p, v3(0, 0, 5), v3(0, 0, -1), s), 0);
    /* normals: outward */
    vec3 n = prim_normal(&p, v3(2.5, 0, 0), 0);
    assert_true(n.x > 0 && fabs(n.y) < 1e-15 && fabs(n.z) < 1e-15);
    n = prim_normal(&p, v3(0, 1.5, 0), 0);
    assert_true(n.y < 0);
    n = prim_normal(&p, v3(0, -2, 0.5), 0);
    assert_true(n.z > 0 && fabs(n.y) < 1e-15);
    assert_true(prim_inside(&p, v3(0, 2, 0.49)) && !prim_inside(&p, v3(0, 2, 0.51)));
    bbox b = prim_bounds(&p);
    assert_true(b.lo.x == -2.5 && b.hi.y == 2.5 && b.lo.z == -0.5 && b.hi.z == 0.5);
    assert_int_equal(prim_max_spans(&p), 2);
}

/* A tube 1000 times thinner than the ring: R = 1000, r = 1. Rays along x
 * at height z cross at x = +-(R +- sqrt(r^2 - z^2)). */
static void test_torus_thin_tube(void **state)
{
    (void)state;
    prim p = torus(1000, 1);
    static const double heights[] = {0, 0.5, 0.9, 0.999, 0.999999};
    for (size_t i = 0; i < sizeof heights / sizeof heights[0]; i++) {
        double z = heights[i], w = sqrt(1 - z * z);
        span s[2];
        assert_int_equal(shoot(&p, v3(-3000, 0, z), v3(1, 0, 0), s), 2);
        double tol = 1e-12 * 3000;
        assert_near(s[0].in.t, 3000 - 1000 - w, tol);
        assert_near(s[0].out.t, 3000 - 1000 + w, tol);
        assert_near(s[1].in.t, 3000 + 1000 - w, tol);
        assert_near(s[1].out.t, 3000 + 1000 + w, tol);
    }
    /* through the tube crosswise, near the ring: along y at x = 1000.3 */
    span s[2];
    assert_int_equal(shoot(&p, v3(1000.3, -2, 0), v3(0, 1, 0), s), 1);
    /* rho = hypot(1000.3, y) = 1001 at y = sqrt(1001^2 - 1000.3^2) */
    double y = sqrt(1001.0 * 1001 - 1000.3 * 1000.3);
    assert_near(s[0].in.t, 2 - y, 1e-9);
    assert_near(s[0].out.t, 2 + y, 1e-9);
}

/* Origins 1e4 radii away, along random directions aimed at random points
 * of the tube: the spans agree with those of the same ray started nearby
 * (shifted along itself by a known t), to the rounding of t. */
static void test_torus_far_origin(void **state)
{
    (void)state;
    uint64_t seed = 12345;
    prim p = torus(2, 0.5);
    int hits = 0;
    for (int i = 0; i < 2000; i++) {
        double u[6];
        for (int k = 0; k < 6; k++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            u[k] = (double)(seed >> 11) * 0x1p-53;
        }
        double ang = 2 * 3.141592653589793 * u[0];
        vec3 target = v3((2 + 0.4 * (u[1] - 0.5)) * cos(ang),
                         (2 + 0.4 * (u[1] - 0.5)) * sin(ang), 0.8 * (u[2] - 0.5));
        vec3 d = v3_normalize(v3(u[3] - 0.5, u[4] - 0.5, u[5] - 0.5));
        double far = 1e4 * 2.5;
        vec3 o_far = v3_madd(target, d, -far), o_near = v3_madd(target, d, -5);
        span a[2], b[2];
        uint32_t na = shoot(&p, o_far, d, a), nb = shoot(&p, o_near, d, b);
        assert_int_equal(na, nb);
        hits += na > 0;
        for (uint32_t k = 0; k < na; k++) {
            /* o_far itself carries rounding of order 1e-16 * far */
            assert_near(a[k].in.t - (far - 5), b[k].in.t, 1e-10);
            assert_near(a[k].out.t - (far - 5), b[k].out.t, 1e-10);
        }
    }
    assert_true(hits > 1900);
}

/* Grazing rays: along x at height z just below the top of the tube
 * (z = r - eps) the tube is cut over 2 sqrt(r^2 - z^2) around x = +-R;
 * exactly at z = r the ray is tangent (no span, or one no longer than
 * rounding). Also grazing the inner equator from inside the hole. */
static void test_torus_grazing(void **state)
{
    (void)state;
    prim p = torus(2, 0.5);
    static const double eps[] = {1e-3, 1e-6, 1e-9, 1e-12};
    for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
        double z = 0.5 - eps[i], w = sqrt((0.5 - z) * (0.5 + z));
        span s[2];
        assert_int_equal(shoot(&p, v3(-5, 0, z), v3(1, 0, 0), s), 2);
        assert_near(s[0].in.t, 3 - w, 1e-14 + 1e-6 * w);
        assert_near(s[0].out.t, 3 + w, 1e-14 + 1e-6 * w);
        assert_near(s[1].in.t, 7 - w, 1e-14 + 1e-6 * w);
        assert_near(s[1].out.t, 7 + w, 1e-14 + 1e-6 * w);
    }
    span s[2];
    uint32_t n = shoot(&p, v3(-5, 0, 0.5), v3(1, 0, 0), s);
    for (uint32_t i = 0; i < n; i++)
        assert_true(s[i].out.t - s[i].in.t <= 1e-7);
    /* Along y at x = R - r - 1e-9, inside the hole, grazing the inner
     * equator rho = R - r: the ray enters the tube where
     * hypot(x, y) = R - r, y = +-sqrt((R - r - x)(R - r + x)) (written so
     * that the small difference is exact). rho itself carries one rounding
     * (hypot), which moves the root by about eps rho / (d rho / dy) =
     * eps rho^2 / y: that is the conditioning of the problem, and the
     * tolerance. */
    double x = 1.5 - 1e-9, y = sqrt((1.5 - x) * (1.5 + x));
    n = shoot(&p, v3(x, -5, 0), v3(0, 1, 0), s);
    assert_int_equal(n, 2); /* it is in the tube on both sides of y = 0 */
    double cond = 4 * 2.220446049250313e-16 * 1.5 * 1.5 / y;
    assert_near(s[0].out.t, 5 - y, cond);
    assert_near(s[1].in.t, 5 + y, cond);
}

/* ---- quadric ---- */

static void test_quadric_families(void **state)
{
    (void)state;
    vec3 lo = v3(-1, -1, -1), hi = v3(1, 1, 1);
    span s[2];
    prim_quadric store;
    /* sphere x^2 + y^2 + z^2 - 0.25 */
    static const double sphere[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, -0.25};
    prim p = quadric(&store, sphere, lo, hi);
    assert_int_equal(shoot(&p, v3(-3, 0, 0), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 2.5, 1e-15);
    assert_near(s[0].out.t, 3.5, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_SURFACE);
    /* double cone x^2 + y^2 - z^2 along z at x = 0.5: |z| >= 0.5, two
     * spans, the outer ends on the box faces z = -1 and z = 1 */
    static const double cone[10] = {1, 1, -1, 0, 0, 0, 0, 0, 0, 0};
    p = quadric(&store, cone, lo, hi);
    assert_int_equal(shoot(&p, v3(0.5, 0, -3), v3(0, 0, 1), s), 2);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 2.5, 1e-15);
    assert_near(s[1].in.t, 3.5, 1e-15);
    assert_near(s[1].out.t, 4, 1e-15);
    assert_int_equal(s[0].in.part, PRIM_PART_CLIP_FACE + 4);  /* -z face */
    assert_int_equal(s[1].out.part, PRIM_PART_CLIP_FACE + 5); /* +z face */
    assert_int_equal(s[0].out.part, PRIM_PART_SURFACE);
    vec3 n = prim_normal(&p, v3(0.5, 0, 0.5), PRIM_PART_SURFACE);
    assert_near(n.x / n.z, -1, 1e-15);
    n = prim_normal(&p, v3(0.5, 0, 1), PRIM_PART_CLIP_FACE + 5);
    assert_true(n.z == 1 && n.x == 0);
    /* through the apex: the nappes touch, one span from face to face */
    assert_int_equal(shoot(&p, v3(0, 0, -3), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 4, 1e-15);
    /* along a generator (a = 0): x = z, y = 0.2: Q = 0.04 > 0 never inside
     * and y = 0: the ray lies on the cone (Q = 0: inside, closed) */
    assert_int_equal(shoot(&p, v3(-3, 0.2, -3), v3(1, 0, 1), s), 0);
    /* hyperboloid of two sheets: x^2 + y^2 - z^2 + 0.25 <= 0 */
    static const double two_sheets[10] = {1, 1, -1, 0, 0, 0, 0, 0, 0, 0.25};
    p = quadric(&store, two_sheets, lo, hi);
    assert_int_equal(shoot(&p, v3(0, 0, -3), v3(0, 0, 1), s), 2);
    assert_near(s[0].out.t, 2.5, 1e-15);
    assert_near(s[1].in.t, 3.5, 1e-15);
    /* elliptic paraboloid x^2 + 4 y^2 - z <= 0, along x at z = 0.5 */
    static const double paraboloid[10] = {1, 4, 0, 0, 0, 0, 0, 0, -1, 0};
    p = quadric(&store, paraboloid, lo, hi);
    assert_int_equal(shoot(&p, v3(-3, 0, 0.5), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 3 - sqrt(0.5), 1e-15);
    assert_near(s[0].out.t, 3 + sqrt(0.5), 1e-15);
    /* elliptic cylinder x^2 / 0.25 + y^2 - 1 along its axis: the whole
     * box stretch (a = b = 0, c < 0) */
    static const double cylinder[10] = {4, 1, 0, 0, 0, 0, 0, 0, 0, -1};
    p = quadric(&store, cylinder, lo, hi);
    assert_int_equal(shoot(&p, v3(0.1, 0.2, -3), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 4, 1e-15);
    assert_int_equal(prim_max_spans(&p), 2);
    assert_true(prim_inside(&p, v3(0.4, 0, 0.9)) && !prim_inside(&p, v3(0.6, 0, 0)));
    assert_true(!prim_inside(&p, v3(0, 0, 1.1))); /* outside the box */
    bbox b = prim_bounds(&p);
    assert_true(b.lo.x == -1 && b.hi.z == 1);
}

/* ---- implicit ---- */

static void test_implicit_leaf(void **state)
{
    (void)state;
    expr_program f;
    compile("x*x + y*y + z*z - 1", &f);
    prim p = implicit(&f, v3(-2, -2, -2), v3(2, 2, 2), 1e-9);
    prim exact;
    memset(&exact, 0, sizeof exact);
    exact.kind = PRIM_SPHERE;
    exact.u.sphere.r = 1;
    uint64_t seed = 77;
    for (int i = 0; i < 3000; i++) {
        double u[6];
        for (int k = 0; k < 6; k++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            u[k] = (double)(seed >> 11) * 0x1p-53;
        }
        vec3 o = v3(6 * u[0] - 3, 6 * u[1] - 3, -3);
        vec3 d = v3(u[3] - 0.5, u[4] - 0.5, 0.5 + u[5]);
        span a[MAX], b[1];
        uint32_t na = shoot(&p, o, d, a);
        uint32_t nb = prim_spans(&exact, LEAF, o, d, b, 1);
        /* tangent rays may differ by a span no longer than rounding */
        if (na != nb) {
            assert_true(na + nb == 1);
            span *g = na ? &a[0] : &b[0];
            assert_true((g->out.t - g->in.t) * v3_length(d) < 1e-6);
            continue;
        }
        for (uint32_t k = 0; k < na; k++) {
            assert_near(a[k].in.t, b[k].in.t, 1e-12);
            assert_near(a[k].out.t, b[k].out.t, 1e-12);
        }
    }
    /* normal: the gradient 2p */
    vec3 n = prim_normal(&p, v3(0.6, 0.8, 0), PRIM_PART_SURFACE);
    assert_near(n.x, 1.2, 1e-15);
    assert_near(n.y, 1.6, 1e-15);
    /* f < 0 everywhere: the box, with face parts */
    expr_program all;
    compile("-1", &all);
    p = implicit(&all, v3(-1, -2, -3), v3(1, 2, 3), 1e-6);
    span s[MAX];
    assert_int_equal(shoot(&p, v3(0, -5, 0), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, 3, 0);
    assert_near(s[0].out.t, 7, 0);
    assert_int_equal(s[0].in.part, PRIM_PART_CLIP_FACE + 2);
    assert_int_equal(s[0].out.part, PRIM_PART_CLIP_FACE + 3);
    n = prim_normal(&p, v3(0, 2, 0), PRIM_PART_CLIP_FACE + 3);
    assert_true(n.y == 1);
    assert_true(prim_inside(&p, v3(1, 2, 3)) && !prim_inside(&p, v3(1, 2, 3.01)));
    /* a ray missing the box */
    assert_int_equal(shoot(&p, v3(0, -5, 4), v3(0, 1, 0), s), 0);
}

/* ---- sampled agreement ---- */

typedef struct rng {
    uint64_t s;
} rng;

static double uniform_in(rng *r, double lo, double hi)
{
    r->s = r->s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * ((double)(r->s >> 11) * 0x1p-53);
}

/* For random rays aimed into the bounds (some along axes), points farther
 * than tol (relative to the shape's size) from every span end agree with
 * prim_inside. */
static long sampled(const prim *p, rng *r, int rays, double tol)
{
    bbox b = prim_bounds(p);
    vec3 ext = bbox_extent(&b);
    double size = v3_max_abs(ext);
    long checked = 0;
    for (int i = 0; i < rays; i++) {
        vec3 target = v3(uniform_in(r, b.lo.x, b.hi.x), uniform_in(r, b.lo.y, b.hi.y),
                         uniform_in(r, b.lo.z, b.hi.z));
        vec3 d = v3(uniform_in(r, -1, 1), uniform_in(r, -1, 1), uniform_in(r, -1, 1));
        if (i % 5 == 1)
            d = v3(i % 3 == 0, i % 3 == 1, i % 3 == 2);
        vec3 o = v3_madd(target, d, -uniform_in(r, 0, 3) * size);
        span s[MAX];
        uint32_t n = shoot(p, o, d, s);
        double len = v3_length(d);
        for (int j = 0; j < 30; j++) {
            double t = uniform_in(r, -5 * size / len, 5 * size / len);
            if (j < 2 * (int)n) /* just beside each end */
                t = (j % 2 ? s[j / 2].out.t : s[j / 2].in.t) +
                    (j % 4 < 2 ? 3 : -3) * tol * size / len;
            int in_span = 0, near_end = 0;
            for (uint32_t m = 0; m < n; m++) {
                if (t >= s[m].in.t && t <= s[m].out.t)
                    in_span = 1;
                if (fabs(t - s[m].in.t) * len <= tol * size ||
                    fabs(t - s[m].out.t) * len <= tol * size)
                    near_end = 1;
            }
            if (near_end)
                continue;
            int inside = prim_inside(p, v3_madd(o, d, t));
            if (inside != in_span)
                fail_msg("kind %d ray %d: o = (%.17g %.17g %.17g) d = (%.17g %.17g "
                         "%.17g) t = %.17g inside = %d, span = %d",
                         p->kind, i, o.x, o.y, o.z, d.x, d.y, d.z, t, inside, in_span);
            checked++;
        }
    }
    return checked;
}

static void test_spans_agree_with_inside(void **state)
{
    (void)state;
    rng r = {2024};
    long checked = 0;
    static const double ratios[] = {1.5, 4, 30, 1000};
    for (size_t i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
        prim p = torus(ratios[i], 1);
        checked += sampled(&p, &r, 3000, 1e-9);
    }
    static const double families[][10] = {
        {1, 1, -1, 0, 0, 0, 0, 0, 0, 0},                       /* cone */
        {1, 1, -0.25, 0, 0, 0, 0, 0, 0, -0.5},                 /* one sheet */
        {1, 1, -1, 0, 0, 0, 0, 0, 0, 0.2},                     /* two sheets */
        {1, 2, 0, 0, 0, 0, 0, 0, -1, 0},                       /* paraboloid */
        {1, -1, 0, 0, 0, 0, 0, 0, -1, 0},                      /* saddle */
        {2, 1, 0, 0.5, 0, 0, 0.1, 0, 0, -1},                   /* elliptic cylinder */
        {0.3, 0.7, 1.1, 0.4, -0.6, 0.2, 0.1, -0.2, 0.3, -0.8}, /* general */
    };
    for (size_t i = 0; i < sizeof families / sizeof families[0]; i++) {
        prim_quadric store;
        prim p = quadric(&store, families[i], v3(-1.5, -1, -2), v3(1, 1.5, 1.2));
        checked += sampled(&p, &r, 3000, 1e-9);
    }
    static const char *const fields[] = {
        "x*x + y*y + z*z - 1",
        "abs(sin(3*x)*cos(3*y) + sin(3*y)*cos(3*z) + sin(3*z)*cos(3*x)) - 0.3",
        "smin(sqrt(x*x + y*y + z*z) - 0.8, max(abs(x - 0.9), abs(y), abs(z)) - 0.4, 0.3)",
        "(x*x + y*y + z*z - 1)^3",
        "z - 0.2 * sin(5 * x) * cos(4 * y)",
        "sqrt(x + 0.8) - 0.9 + 0.3 * y", /* NaN (outside) for x < -0.8 */
        "max(log(x + 1), -1) + y * y + z * z - 0.5",
    };
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++) {
        expr_program f;
        compile(fields[i], &f);
        prim p = implicit(&f, v3(-1.5, -1.2, -1.1), v3(1.4, 1.3, 1.2), 1e-9);
        checked += sampled(&p, &r, 1500, 1e-8);
    }
    print_message("%ld samples agree\n", checked);
    assert_true(checked > 1000000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_torus_worked_example),
        cmocka_unit_test(test_torus_thin_tube),
        cmocka_unit_test(test_torus_far_origin),
        cmocka_unit_test(test_torus_grazing),
        cmocka_unit_test(test_quadric_families),
        cmocka_unit_test(test_implicit_leaf),
        cmocka_unit_test(test_spans_agree_with_inside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
