/* Tests of the solid of revolution (src/csg/prim_revolve.c): hits worked
 * out by hand (a square profile is a tube: cylinder walls and annulus
 * caps; a circle a torus, one touching the axis a horn torus; a triangle
 * on the axis a cone), rays along the axis, through it, parallel to it and
 * level (d_z = 0), partial angles clipped by the wedge with the profile as
 * end caps, normals, bounds, and a sampled check of spans against
 * prim_inside on seeded random profiles, angles and rays.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "csg/prim.h"
#include "csg/prim_revolve.h"

static void check_near(double got, double want, double tol, const char *what, int line)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("line %d: %s = %.17g, expected %.17g (tolerance %g)\n", line, what,
                    got, want, tol);
        _fail(__FILE__, line);
    }
}
#define assert_near(got, want, tol) check_near((got), (want), (tol), #got, __LINE__)

enum { LEAF = 3, MAX = PRIM_REVOLVE_MAX_EDGES + 1 };

static const double pi = 3.14159265358979323846;

/* A profile under construction: edges of closed polygons and discs. */
typedef struct shape {
    prim_revolve_edge edges[256];
    prim_revolve_disc discs[8];
    prim_revolve rev;
} shape;

static void start(shape *s)
{
    memset(s, 0, sizeof *s);
    s->rev.edges = s->edges;
    s->rev.discs = s->discs;
    s->rev.r_lo = INFINITY;
    s->rev.r_hi = -INFINITY;
    s->rev.z_lo = INFINITY;
    s->rev.z_hi = -INFINITY;
}

static void extend(shape *s, double r0, double r1, double z0, double z1)
{
    s->rev.r_lo = fmin(s->rev.r_lo, r0);
    s->rev.r_hi = fmax(s->rev.r_hi, r1);
    s->rev.z_lo = fmin(s->rev.z_lo, z0);
    s->rev.z_hi = fmax(s->rev.z_hi, z1);
}

/* A closed polygon (n points, 2 numbers each) in region `region`. */
static void polygon(shape *s, const double *rz, int n, uint32_t region)
{
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        prim_revolve_edge *e = &s->edges[s->rev.edge_count++];
        *e = (prim_revolve_edge){rz[2 * i], rz[2 * i + 1], rz[2 * j], rz[2 * j + 1],
                                 region};
        extend(s, rz[2 * i], rz[2 * i], rz[2 * i + 1], rz[2 * i + 1]);
    }
    if (region + 1 > s->rev.region_count)
        s->rev.region_count = region + 1;
}

static void disc(shape *s, double rc, double zc, double a, uint32_t region)
{
    s->discs[s->rev.disc_count++] = (prim_revolve_disc){rc, zc, a, region};
    extend(s, rc - a, rc + a, zc - a, zc + a);
    if (region + 1 > s->rev.region_count)
        s->rev.region_count = region + 1;
}

/* A wedge from phi0 over sweep degrees, counter-clockwise. */
static void wedge(shape *s, double phi0, double sweep)
{
    s->rev.partial = 1;
    s->rev.sweep = sweep;
    double a = phi0 * pi / 180, b = (phi0 + sweep) * pi / 180;
    s->rev.start[0] = cos(a);
    s->rev.start[1] = sin(a);
    s->rev.end[0] = cos(b);
    s->rev.end[1] = sin(b);
    /* exact quarter turns, as the builder's degree trigonometry gives */
    for (int k = 0; k < 2; k++) {
        double *v = k ? s->rev.end : s->rev.start;
        for (int j = 0; j < 2; j++)
            if (fabs(v[j]) < 1e-15)
                v[j] = 0;
    }
}

static prim as_prim(shape *s)
{
    s->rev.r_lo = fmax(0, s->rev.r_lo);
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_REVOLVE;
    p.u.revolve.rev = &s->rev;
    return p;
}

/* Spans with the invariants every answer keeps: at most prim_max_spans,
 * finite, ordered, not overlapping, leaf set. */
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
            assert_true(s[i - 1].out.t <= s[i].in.t);
    }
    return n;
}

/* Regularised as the tree does it: touching spans fused. */
static uint32_t shoot_fused(const prim *p, vec3 o, vec3 d, span *s)
{
    uint32_t n = shoot(p, o, d, s);
    return span_regularize(s, n, 1e-12);
}

static const double tube_rz[] = {2, 0, 4, 0, 4, 3, 2, 3};

/* Square profile r in [2, 4], z in [0, 3], counter-clockwise: edge 0 the
 * bottom annulus, 1 the outer wall, 2 the top annulus, 3 the inner wall. */
static void test_tube(void **state)
{
    (void)state;
    shape sh;
    start(&sh);
    polygon(&sh, tube_rz, 4, 0);
    prim p = as_prim(&sh);
    span s[MAX];
    /* level ray through the axis: x in [-4, -2] and [2, 4] */
    assert_int_equal(shoot(&p, v3(-10, 0, 1.5), v3(1, 0, 0), s), 2);
    assert_near(s[0].in.t, 6, 1e-12);
    assert_near(s[0].out.t, 8, 1e-12);
    assert_near(s[1].in.t, 12, 1e-12);
    assert_near(s[1].out.t, 14, 1e-12);
    assert_int_equal(s[0].in.part, 1);
    assert_int_equal(s[0].out.part, 3);
    assert_int_equal(s[1].in.part, 3);
    assert_int_equal(s[1].out.part, 1);
    vec3 n = prim_normal(&p, v3(-4, 0, 1.5), 1);
    assert_true(n.x < 0 && n.y == 0 && n.z == 0);
    n = prim_normal(&p, v3(-2, 0, 1.5), 3);
    assert_true(n.x > 0 && n.y == 0 && n.z == 0);
    /* a direction that is not unit length: t keeps its meaning */
    assert_int_equal(shoot(&p, v3(-10, 0, 1.5), v3(2, 0, 0), s), 2);
    assert_near(s[0].in.t, 3, 1e-12);
    assert_near(s[1].out.t, 7, 1e-12);
    /* vertical ray through the wall: z from 3 down to 0, the annuli */
    assert_int_equal(shoot(&p, v3(3, 0, 10), v3(0, 0, -1), s), 1);
    assert_near(s[0].in.t, 7, 1e-12);
    assert_near(s[0].out.t, 10, 1e-12);
    assert_int_equal(s[0].in.part, 2);
    assert_int_equal(s[0].out.part, 0);
    n = prim_normal(&p, v3(3, 0, 3), 2);
    assert_true(n.z > 0 && n.x == 0);
    n = prim_normal(&p, v3(3, 0, 0), 0);
    assert_true(n.z < 0 && n.x == 0);
    /* vertical rays in the hole, along the axis, outside */
    assert_int_equal(shoot(&p, v3(1, 0, 10), v3(0, 0, -1), s), 0);
    assert_int_equal(shoot(&p, v3(0, 0, -10), v3(0, 0, 1), s), 0);
    assert_int_equal(shoot(&p, v3(0, 5, -10), v3(0, 0, 1), s), 0);
    /* level ray off the axis at x = 3: rho = hypot(3, y) <= 4, never < 2 */
    assert_int_equal(shoot(&p, v3(3, -10, 1.5), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, 10 - sqrt(7), 1e-12);
    assert_near(s[0].out.t, 10 + sqrt(7), 1e-12);
    /* level ray in the plane of the top annulus, and just above it */
    assert_int_equal(shoot(&p, v3(-10, 0, 3.000001), v3(1, 0, 0), s), 0);
    /* a slanted ray: x = -10 + t, z = -1 + 0.1 t is in the wall for x in
     * [2, 4] (z = 0.2 .. 0.4); the hole side at x in [-4, -2] is below 0 */
    assert_int_equal(shoot(&p, v3(-10, 0, -1), v3(1, 0, 0.1), s), 1);
    assert_near(s[0].in.t, 12, 1e-12);
    assert_near(s[0].out.t, 14, 1e-12);
    /* membership and bounds */
    assert_true(prim_inside(&p, v3(0, 3, 1)) && prim_inside(&p, v3(-2.5, -2.5, 2)));
    assert_false(prim_inside(&p, v3(0, 1.9, 1)) || prim_inside(&p, v3(0, 3, 3.1)) ||
                 prim_inside(&p, v3(4, 0.1, 1)));
    bbox b = prim_bounds(&p);
    assert_true(b.lo.x == -4 && b.lo.y == -4 && b.lo.z == 0 && b.hi.x == 4 &&
                b.hi.y == 4 && b.hi.z == 3);
    assert_int_equal(prim_max_spans(&p), 5);
}

/* The same tube over a wedge: a quarter from +x, and 270 degrees. */
static void test_tube_wedge(void **state)
{
    (void)state;
    shape sh;
    start(&sh);
    polygon(&sh, tube_rz, 4, 0);
    wedge(&sh, 0, 90);
    prim p = as_prim(&sh);
    span s[MAX];
    /* along y at x = 3: the wedge keeps y >= 0, the start face at y = 0 */
    assert_int_equal(shoot(&p, v3(3, -10, 1.5), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, 10, 1e-12);
    assert_near(s[0].out.t, 10 + sqrt(7), 1e-12);
    assert_int_equal(s[0].in.part, PRIM_REVOLVE_PART_START);
    vec3 n = prim_normal(&p, v3(3, 0, 1.5), PRIM_REVOLVE_PART_START);
    assert_true(n.y < 0 && n.x == 0 && n.z == 0);
    /* along x at y = 3: the end face at x = 0 */
    assert_int_equal(shoot(&p, v3(-10, 3, 1.5), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 10, 1e-12);
    assert_near(s[0].out.t, 10 + sqrt(7), 1e-12);
    assert_int_equal(s[0].in.part, PRIM_REVOLVE_PART_END);
    n = prim_normal(&p, v3(0, 3, 1.5), PRIM_REVOLVE_PART_END);
    assert_true(n.x < 0 && n.y == 0 && n.z == 0);
    /* the other quadrants are empty */
    assert_int_equal(shoot(&p, v3(-3, -10, 1.5), v3(0, 1, 0), s), 0);
    assert_int_equal(shoot(&p, v3(-3, -3, -10), v3(0, 0, 1), s), 0);
    assert_int_equal(shoot(&p, v3(2.5, 1, -10), v3(0, 0, 1), s), 1);
    bbox b = prim_bounds(&p);
    assert_true(b.lo.x == 0 && b.lo.y == 0 && b.hi.x == 4 && b.hi.y == 4);
    assert_true(prim_inside(&p, v3(2, 2, 1)) && !prim_inside(&p, v3(-2, 2, 1)));

    start(&sh);
    polygon(&sh, tube_rz, 4, 0);
    wedge(&sh, 0, 270);
    p = as_prim(&sh);
    /* along y at x = 3: y < 0 is the missing quadrant */
    assert_int_equal(shoot(&p, v3(3, -10, 1.5), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, 10, 1e-12);
    assert_near(s[0].out.t, 10 + sqrt(7), 1e-12);
    /* along y at x = -3: all of it */
    assert_int_equal(shoot(&p, v3(-3, -10, 1.5), v3(0, 1, 0), s), 1);
    assert_near(s[0].in.t, 10 - sqrt(7), 1e-12);
    assert_near(s[0].out.t, 10 + sqrt(7), 1e-12);
    /* along x at y = -0.5: the left wall only */
    assert_int_equal(shoot(&p, v3(-10, -0.5, 1.5), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 10 - sqrt(15.75), 1e-12);
    assert_near(s[0].out.t, 10 - sqrt(3.75), 1e-12);
    /* the diagonal x = y through the axis: both walls are in the wedge */
    assert_int_equal(shoot(&p, v3(-10, -10, 1.5), v3(1, 1, 0), s), 2);
    /* y = x - 2: through the first and third quadrants' walls, and
     * between them through the missing one */
    assert_int_equal(shoot(&p, v3(-10, -12, 1.5), v3(1, 1, 0), s), 2);
    assert_true(s[0].out.t <= 10 + 1e-12 && s[1].in.t >= 12 - 1e-12);
    b = prim_bounds(&p);
    assert_true(b.lo.x == -4 && b.lo.y == -4 && b.hi.x == 4 && b.hi.y == 4);
}

/* A disc of radius 1 about (5, 0): a torus. A disc touching the axis: a
 * horn torus, solid through the axis. */
static void test_torus_profile(void **state)
{
    (void)state;
    shape sh;
    start(&sh);
    disc(&sh, 5, 0, 1, 0);
    prim p = as_prim(&sh);
    span s[MAX];
    assert_int_equal(shoot(&p, v3(-10, 0, 0), v3(1, 0, 0), s), 2);
    assert_near(s[0].in.t, 4, 1e-12);
    assert_near(s[0].out.t, 6, 1e-12);
    assert_near(s[1].in.t, 14, 1e-12);
    assert_near(s[1].out.t, 16, 1e-12);
    double w = sqrt(0.75);
    assert_int_equal(shoot(&p, v3(-10, 0, 0.5), v3(1, 0, 0), s), 2);
    assert_near(s[0].in.t, 10 - 5 - w, 1e-12);
    assert_near(s[0].out.t, 10 - 5 + w, 1e-12);
    assert_near(s[1].in.t, 10 + 5 - w, 1e-12);
    assert_near(s[1].out.t, 10 + 5 + w, 1e-12);
    vec3 n = prim_normal(&p, v3(0, 6, 0), 0);
    assert_true(n.y > 0 && n.x == 0 && n.z == 0);
    n = prim_normal(&p, v3(5, 0, 1), 0);
    assert_true(n.z > 0 && fabs(n.x) < 1e-15);
    /* vertical through the tube's centre circle */
    assert_int_equal(shoot(&p, v3(0, -5, 10), v3(0, 0, -1), s), 1);
    assert_near(s[0].in.t, 9, 1e-12);
    assert_near(s[0].out.t, 11, 1e-12);
    assert_true(prim_inside(&p, v3(0, 5.9, 0)) && !prim_inside(&p, v3(0, 4, 0.5)));

    start(&sh);
    disc(&sh, 1, 2, 1, 0);
    p = as_prim(&sh);
    uint32_t k = shoot_fused(&p, v3(-10, 0, 2), v3(1, 0, 0), s);
    assert_int_equal(k, 1);
    assert_near(s[0].in.t, 8, 1e-9);
    assert_near(s[0].out.t, 12, 1e-9);
    bbox b = prim_bounds(&p);
    assert_true(b.lo.x == -2 && b.hi.x == 2 && b.lo.z == 1 && b.hi.z == 3);
}

/* Triangle (0, 0), (3, 0), (0, 4): a cone of base radius 3, height 4,
 * whose profile runs along the axis. */
static void test_cone(void **state)
{
    (void)state;
    static const double tri[] = {0, 0, 3, 0, 0, 4};
    shape sh;
    start(&sh);
    polygon(&sh, tri, 3, 0);
    prim p = as_prim(&sh);
    span s[MAX];
    /* along the axis: the whole height */
    assert_int_equal(shoot_fused(&p, v3(0, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-12);
    assert_near(s[0].out.t, 5, 1e-12);
    assert_int_equal(shoot_fused(&p, v3(0, 0, 10), v3(0, 0, -2), s), 1);
    assert_near(s[0].in.t, 3, 1e-12);
    assert_near(s[0].out.t, 5, 1e-12);
    /* level through the axis at z = 2: radius 1.5 */
    assert_int_equal(shoot_fused(&p, v3(-10, 0, 2), v3(1, 0, 0), s), 1);
    assert_near(s[0].in.t, 8.5, 1e-12);
    assert_near(s[0].out.t, 11.5, 1e-12);
    /* vertical at x = 1: from the base up to z = 4 (1 - 1/3) */
    assert_int_equal(shoot(&p, v3(1, 0, -1), v3(0, 0, 1), s), 1);
    assert_near(s[0].in.t, 1, 1e-12);
    assert_near(s[0].out.t, 1 + 8.0 / 3, 1e-12);
    vec3 n = prim_normal(&p, v3(0, 1.5, 2), s[0].out.part);
    assert_true(n.x == 0 && n.y > 0 && n.z > 0);
    assert_near(n.z / n.y, 0.75, 1e-15);
    /* a slanted ray through the apex region: z = t, x = 0.1 t - 0.1 */
    uint32_t k = shoot_fused(&p, v3(-0.1, 0, 0), v3(0.1, 0, 1), s);
    assert_int_equal(k, 1);
    assert_near(s[0].in.t, 0, 1e-12);
    /* out where 0.1 t - 0.1 = 3 (1 - t / 4): t = 3.1 / 0.85 */
    assert_near(s[0].out.t, 3.1 / 0.85, 1e-12);
    assert_true(prim_inside(&p, v3(0, 0, 3.9)) && !prim_inside(&p, v3(0, 0, 4.1)));
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

/* A random star-shaped polygon about (rc, zc), clamped to r >= 0 (so some
 * touch or run along the axis); on a grid of 0.25 when snap is set, which
 * makes level and vertical edges and shared vertices common. */
static void random_polygon(shape *sh, rng *r, uint32_t region, int snap)
{
    double rz[2 * 16];
    int n = 3 + (int)uniform_in(r, 0, 10);
    double rc = uniform_in(r, 0, 3), zc = uniform_in(r, -2, 2);
    double size = uniform_in(r, 0.5, 2.5), a = uniform_in(r, 0, 2 * pi);
    for (int i = 0; i < n; i++) {
        a += uniform_in(r, 0.2, 2 * pi / n * 1.5);
        double len = size * uniform_in(r, 0.3, 1);
        double x = fmax(0, rc + len * cos(a)), y = zc + len * sin(a);
        if (snap) {
            x = round(x * 4) / 4;
            y = round(y * 4) / 4;
        }
        rz[2 * i] = x;
        rz[2 * i + 1] = y;
    }
    polygon(sh, rz, n, region);
}

/* For random rays aimed into the bounds (some along the axes, some along
 * or through the z axis, some level), points farther than tol (relative
 * to the shape's size) from every span end agree with prim_inside. */
static long sampled(const prim *p, rng *r, int rays, double tol, long *disagree)
{
    bbox b = prim_bounds(p);
    vec3 ext = bbox_extent(&b);
    double size = v3_max_abs(ext);
    long checked = 0;
    span *s = malloc(MAX * sizeof *s);
    assert_non_null(s);
    for (int i = 0; i < rays; i++) {
        vec3 target = v3(uniform_in(r, b.lo.x, b.hi.x), uniform_in(r, b.lo.y, b.hi.y),
                         uniform_in(r, b.lo.z, b.hi.z));
        vec3 d = v3(uniform_in(r, -1, 1), uniform_in(r, -1, 1), uniform_in(r, -1, 1));
        switch (i % 8) {
        case 1:
            d = v3(i % 3 == 0, i % 3 == 1, i % 3 == 2);
            break;
        case 3: /* through the axis */
            target.x = target.y = 0;
            break;
        case 5: /* level */
            d.z = 0;
            break;
        case 7: /* along the axis, or parallel to it */
            if (i % 16 == 7)
                target.x = target.y = 0;
            d = v3(0, 0, 1);
            break;
        }
        if (d.x == 0 && d.y == 0 && d.z == 0)
            d = v3(1, 0, 0);
        vec3 o = v3_madd(target, d, -uniform_in(r, 0, 3) * size);
        uint32_t n = shoot(p, o, d, s);
        n = span_regularize(s, n, 1e-12);
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
            if (inside != in_span) {
                print_error("partial %d discs %u edges %u ray %d: o = (%.17g %.17g "
                            "%.17g) d = (%.17g %.17g %.17g) "
                            "t = %.17g inside = %d, span = %d\n",
                            p->u.revolve.rev->partial, p->u.revolve.rev->disc_count,
                            p->u.revolve.rev->edge_count, i, o.x, o.y, o.z, d.x, d.y, d.z,
                            t, inside, in_span);
                (*disagree)++;
            }
            checked++;
        }
    }
    free(s);
    return checked;
}

static void test_spans_agree_with_inside(void **state)
{
    (void)state;
    rng r = {909};
    long checked = 0, disagree = 0;
    int profiles = 1000;
    for (int k = 0; k < profiles; k++) {
        shape sh;
        start(&sh);
        uint32_t regions = 1 + (uint32_t)uniform_in(&r, 0, 3);
        for (uint32_t g = 0; g < regions; g++) {
            /* some regions have two or three contours (holes, overlaps) */
            int contours = uniform_in(&r, 0, 1) < 0.3 ? 2 : 1;
            for (int c = 0; c < contours; c++)
                random_polygon(&sh, &r, g, k % 2);
        }
        int discs = (int)uniform_in(&r, 0, 3);
        for (int c = 0; c < discs; c++) {
            double rc = uniform_in(&r, 0.5, 4);
            double a = c == 1 ? rc : uniform_in(&r, 0.1, 1) * rc;
            disc(&sh, rc, uniform_in(&r, -2, 2), a, regions + (uint32_t)c);
        }
        double pick = uniform_in(&r, 0, 1);
        if (pick < 0.4) {
            static const double sweeps[] = {90, 180, 270, 45};
            wedge(&sh, 90 * (double)(k % 4), sweeps[k % 4]);
        } else if (pick < 0.7) {
            wedge(&sh, uniform_in(&r, -180, 180), uniform_in(&r, 1, 359));
        }
        prim p = as_prim(&sh);
        checked += sampled(&p, &r, 150, 1e-9, &disagree);
    }
    print_message("revolve: %d profiles, %ld points checked, %ld disagreements\n",
                  profiles, checked, disagree);
    assert_true(checked > 4000000);
    assert_int_equal(disagree, 0);
}

/* A far origin (1e6 sizes away) gives the spans of a near one, shifted. */
static void test_far_origin(void **state)
{
    (void)state;
    shape sh;
    start(&sh);
    polygon(&sh, tube_rz, 4, 0);
    disc(&sh, 6, 1, 0.5, 1);
    prim p = as_prim(&sh);
    span a[64], b[64];
    rng r = {5};
    for (int i = 0; i < 500; i++) {
        vec3 target =
            v3(uniform_in(&r, -6, 6), uniform_in(&r, -6, 6), uniform_in(&r, 0, 3));
        vec3 d = v3_normalize(
            v3(uniform_in(&r, -1, 1), uniform_in(&r, -1, 1), uniform_in(&r, -1, 1)));
        double far = 1e6;
        uint32_t na = shoot(&p, v3_madd(target, d, -far), d, a);
        uint32_t nb = shoot(&p, v3_madd(target, d, -10), d, b);
        assert_int_equal(na, nb);
        for (uint32_t k = 0; k < na; k++) {
            assert_near(a[k].in.t - (far - 10), b[k].in.t, 1e-8);
            assert_near(a[k].out.t - (far - 10), b[k].out.t, 1e-8);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tube),
        cmocka_unit_test(test_tube_wedge),
        cmocka_unit_test(test_torus_profile),
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_spans_agree_with_inside),
        cmocka_unit_test(test_far_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
