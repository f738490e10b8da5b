/* Tests of the extrusion leaf (src/csg/prim_extrusion.c) and of the exact
 * linear_extrude builder (src/build/build_region.c): hits worked out by
 * hand (a circle's wall, a square's slab, a hole, a polygon with a hole, an
 * ellipse, vertical and horizontal rays, normals of walls, subtracted walls
 * and caps), a sampled check of spans against prim_inside on seeded random
 * 2D trees (ellipses and polygon sets under union, intersection and
 * difference, random 2D affine maps with mirrors) and random rays, normals
 * facing the ray at entries and exits, the shared parts of regions with
 * more than 32767 walls, and the builder: which path a linear_extrude
 * takes, what the exact one builds, and its messages.
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

#include "build/scene.h"
#include "csg/csg.h"
#include "csg/prim_extrusion.h"
#include "test_util.h"

static const double PI = 3.14159265358979323846;

enum { LEAF = 3 };

static void check_near(double got, double want, double tol, const char *what, int line)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("line %d: %s = %.17g, expected %.17g (tolerance %g)\n", line, what,
                    got, want, tol);
        _fail(__FILE__, line);
    }
}
#define assert_near(got, want, tol) check_near((got), (want), (tol), #got, __LINE__)

/* A region under construction and the leaf made of it. */
typedef struct fixture {
    csg_builder *b;
    prim_region r;
    prim p;
} fixture;

static void start(fixture *f)
{
    memset(f, 0, sizeof *f);
    f->b = csg_builder_new();
    assert_non_null(f->b);
}

static void finish(fixture *f, double z0, double z1)
{
    const prim_extrusion *e = prim_extrusion_create(f->b, &f->r, z0, z1);
    assert_non_null(e);
    memset(&f->p, 0, sizeof f->p);
    f->p.kind = PRIM_EXTRUSION;
    f->p.u.extrusion.ext = e;
}

static void stop(fixture *f)
{
    prim_region_free(&f->r);
    csg_builder_free(f->b);
}

static void add_circle(fixture *f, double cx, double cy, double r)
{
    double m[2][3] = {{1, 0, cx}, {0, 1, cy}};
    int pushed;
    assert_true(prim_region_add_ellipse(&f->r, m, r, &pushed));
    assert_true(pushed);
}

static void add_rect(fixture *f, double x0, double y0, double x1, double y1)
{
    double xy[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    uint32_t st[2] = {0, 4};
    int pushed;
    assert_true(prim_region_add_polygon(&f->r, xy, st, 1, &pushed));
    assert_true(pushed);
}

static void add_op(fixture *f, prim_region_op op)
{
    assert_true(prim_region_add_op(&f->r, op));
}

/* Spans with the invariants every answer keeps: at most prim_max_spans,
 * finite, ordered and disjoint, leaf set, flip clear. */
static uint32_t shoot(const prim *p, vec3 o, vec3 d, span *s)
{
    uint32_t cap = prim_max_spans(p);
    uint32_t n = prim_spans(p, LEAF, o, d, s, cap);
    assert_true(n <= cap);
    for (uint32_t i = 0; i < n; i++) {
        assert_true(isfinite(s[i].in.t) && isfinite(s[i].out.t));
        assert_true(s[i].in.t <= s[i].out.t);
        assert_int_equal(s[i].in.leaf, LEAF);
        assert_int_equal(s[i].out.leaf, LEAF);
        assert_int_equal(s[i].in.flip, 0);
        assert_int_equal(s[i].out.flip, 0);
        if (i > 0)
            assert_true(s[i - 1].out.t <= s[i].in.t);
    }
    return n;
}

static vec3 unit_normal(const prim *p, vec3 o, vec3 d, const span_end *e)
{
    return v3_normalize(prim_normal(p, v3_madd(o, d, e->t), e->part));
}

static void assert_vec(vec3 got, vec3 want, int line)
{
    check_near(got.x, want.x, 1e-12, "x", line);
    check_near(got.y, want.y, 1e-12, "y", line);
    check_near(got.z, want.z, 1e-12, "z", line);
}
#define assert_vec_near(got, want) assert_vec((got), (want), __LINE__)

/* A circle of radius 2 extruded from z = 0 to 3: its wall along x, its
 * caps along z, a vertical ray through the hole of a square minus it. */
static void test_circle_wall_and_caps(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    add_circle(&f, 0, 0, 2);
    finish(&f, 0, 3);
    span s[8];
    vec3 o = v3(-5, 0, 1), d = v3(1, 0, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 1);
    assert_near(s[0].in.t, 3, 1e-15);
    assert_near(s[0].out.t, 7, 1e-15);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(-1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(1, 0, 0));
    /* a chord at y = 1.2: x = +-1.6 */
    o = v3(-5, 1.2, 2);
    assert_int_equal(shoot(&f.p, o, d, s), 1);
    assert_near(s[0].in.t, 5 - 1.6, 1e-14);
    assert_near(s[0].out.t, 5 + 1.6, 1e-14);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(-0.8, 0.6, 0));
    /* down the axis, with d not unit: caps */
    o = v3(0.5, 0.5, 10);
    d = v3(0, 0, -2);
    assert_int_equal(shoot(&f.p, o, d, s), 1);
    assert_near(s[0].in.t, 3.5, 0);
    assert_near(s[0].out.t, 5, 0);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(0, 0, 1));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(0, 0, -1));
    /* vertical, outside the circle */
    assert_int_equal(shoot(&f.p, v3(1.5, 1.5, 10), d, s), 0);
    /* slanted: enters through the bottom cap, leaves through the wall */
    o = v3(0, 0, -1);
    d = v3(1, 0, 1);
    assert_int_equal(shoot(&f.p, o, d, s), 1);
    assert_near(s[0].in.t, 1, 0);
    assert_near(s[0].out.t, 2, 1e-15);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(0, 0, -1));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(1, 0, 0));
    /* horizontal, above the slab */
    assert_int_equal(shoot(&f.p, v3(-5, 0, 3.5), v3(1, 0, 0), s), 0);
    assert_true(prim_inside(&f.p, v3(1.9, 0, 2.9)));
    assert_false(prim_inside(&f.p, v3(1.5, 1.5, 1)));
    assert_false(prim_inside(&f.p, v3(0, 0, 3.1)));
    bbox b = prim_bounds(&f.p);
    assert_near(b.lo.x, -2, 1e-8);
    assert_near(b.hi.y, 2, 1e-8);
    assert_near(b.lo.z, 0, 0);
    assert_near(b.hi.z, 3, 0);
    stop(&f);
}

/* The square [0, 10]^2 minus a circle of radius 2 at (5, 5) and one of
 * radius 1 at (9, 5), which reaches the square's edge: along y = 5 the
 * solid is x in [0, 3] and [7, 8], with the holes' walls' normals
 * pointing into the holes. */
static void test_square_minus_circles(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    add_rect(&f, 0, 0, 10, 10);
    add_circle(&f, 5, 5, 2);
    add_op(&f, PRIM_REGION_DIFFERENCE);
    add_circle(&f, 9, 5, 1);
    add_op(&f, PRIM_REGION_DIFFERENCE);
    finish(&f, -1, 1);
    span s[16];
    vec3 o = v3(-2, 5, 0), d = v3(1, 0, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 2);
    assert_near(s[0].in.t, 2, 1e-15);
    assert_near(s[0].out.t, 5, 1e-15);
    assert_near(s[1].in.t, 9, 1e-15);
    assert_near(s[1].out.t, 10, 1e-15);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(-1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(1, 0, 0)); /* into the hole */
    assert_vec_near(unit_normal(&f.p, o, d, &s[1].in), v3(-1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[1].out), v3(1, 0, 0)); /* second hole */
    /* the same from the other side */
    o = v3(12, 5, 0);
    d = v3(-1, 0, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 2);
    assert_near(s[0].in.t, 4, 1e-15);
    assert_near(s[0].out.t, 5, 1e-15);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(-1, 0, 0));
    /* vertical rays: through the hole, through the plate */
    assert_int_equal(shoot(&f.p, v3(5, 5, 4), v3(0, 0, -1), s), 0);
    assert_int_equal(shoot(&f.p, v3(1, 1, 4), v3(0, 0, -1), s), 1);
    assert_near(s[0].in.t, 3, 0);
    assert_near(s[0].out.t, 5, 0);
    assert_false(prim_inside(&f.p, v3(5, 6.9, 0)));
    assert_true(prim_inside(&f.p, v3(5, 7.1, 0)));
    assert_false(prim_inside(&f.p, v3(9.5, 5, 0)));
    /* the bounds are the square's (a difference keeps its first operand's) */
    bbox b = prim_bounds(&f.p);
    assert_near(b.hi.x, 10, 1e-7);
    stop(&f);
}

/* A polygon set with a hole (two paths, even-odd), mirrored: the square
 * [0, 20]^2 with [5, 15]^2 taken out, wound clockwise (x -> -x). */
static void test_polygon_with_hole(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    double xy[16] = {0, 0, -20, 0, -20, 20, 0, 20, -5, 5, -15, 5, -15, 15, -5, 15};
    uint32_t st[3] = {0, 4, 8};
    int pushed;
    assert_true(prim_region_add_polygon(&f.r, xy, st, 2, &pushed));
    assert_true(pushed);
    finish(&f, 0, 10);
    span s[16];
    vec3 o = v3(-30, 10, 5), d = v3(1, 0, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 2);
    assert_near(s[0].in.t, 10, 0);
    assert_near(s[0].out.t, 15, 0);
    assert_near(s[1].in.t, 25, 0);
    assert_near(s[1].out.t, 30, 0);
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].in), v3(-1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[0].out), v3(1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[1].in), v3(-1, 0, 0));
    assert_vec_near(unit_normal(&f.p, o, d, &s[1].out), v3(1, 0, 0));
    /* through a vertex of the hole and of the outline, diagonally: (0, 0)
     * and (-5, 5) are crossed once each */
    o = v3(1, -1, 5);
    d = v3(-1, 1, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 2);
    assert_near(s[0].in.t, 1, 1e-14);
    assert_near(s[0].out.t, 6, 1e-14);
    assert_near(s[1].in.t, 16, 1e-14);
    assert_near(s[1].out.t, 21, 1e-14);
    /* along an edge of the outline (y = 0): the boundary, zero thick;
     * along an edge of the hole: the outline's part on either side */
    assert_true(prim_inside(&f.p, v3(-10, 0, 5)));
    assert_false(prim_inside(&f.p, v3(-10, 10, 5)));
    assert_true(prim_inside(&f.p, v3(-2, 10, 5)));
    stop(&f);
}

/* An ellipse: the circle of radius 1 under x -> 3x, y -> y/2, rotated by
 * 30 degrees, mirrored, translated; along its major axis it is 6 long. */
static void test_ellipse(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    double c = cos(PI / 6), s30 = sin(PI / 6);
    /* A = R(30 degrees) diag(3, 0.5), centre (7, -2) */
    double m[2][3] = {{3 * c, -0.5 * s30, 7}, {3 * s30, 0.5 * c, -2}};
    int pushed;
    assert_true(prim_region_add_ellipse(&f.r, m, 1, &pushed));
    assert_true(pushed);
    finish(&f, 0, 1);
    span sp[8];
    vec3 o = v3(7 - 10 * c, -2 - 10 * s30, 0.5), d = v3(c, s30, 0);
    assert_int_equal(shoot(&f.p, o, d, sp), 1);
    assert_near(sp[0].in.t, 7, 1e-13);
    assert_near(sp[0].out.t, 13, 1e-13);
    assert_vec_near(unit_normal(&f.p, o, d, &sp[0].in), v3(-c, -s30, 0));
    /* across the minor axis: 1 long */
    o = v3(7 + 5 * s30, -2 - 5 * c, 0.5);
    d = v3(-s30, c, 0);
    assert_int_equal(shoot(&f.p, o, d, sp), 1);
    assert_near(sp[0].in.t, 4.5, 1e-13);
    assert_near(sp[0].out.t, 5.5, 1e-13);
    assert_vec_near(unit_normal(&f.p, o, d, &sp[0].out), v3(-s30, c, 0));
    /* a mirror of the same: the same spans */
    fixture g;
    start(&g);
    double mm[2][3] = {{3 * c, 0.5 * s30, 7}, {3 * s30, -0.5 * c, -2}};
    assert_true(prim_region_add_ellipse(&g.r, mm, 1, &pushed));
    finish(&g, 0, 1);
    assert_int_equal(shoot(&g.p, o, d, sp), 1);
    assert_near(sp[0].in.t, 4.5, 1e-13);
    assert_vec_near(unit_normal(&g.p, o, d, &sp[0].out), v3(-s30, c, 0));
    /* a singular map has no area */
    double flat[2][3] = {{1, 2, 0}, {2, 4, 0}};
    assert_true(prim_region_add_ellipse(&g.r, flat, 1, &pushed));
    assert_false(pushed);
    stop(&g);
    stop(&f);
}

/* The intersection of two circles (a lens) and a union that fuses. */
static void test_intersection_and_union(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    add_circle(&f, -1, 0, 2);
    add_circle(&f, 1, 0, 2);
    add_op(&f, PRIM_REGION_INTERSECTION);
    add_rect(&f, 5, -1, 7, 1);
    add_rect(&f, 7, -1, 9, 1);
    add_op(&f, PRIM_REGION_UNION);
    add_op(&f, PRIM_REGION_UNION);
    finish(&f, 0, 1);
    span s[16];
    vec3 o = v3(-5, 0, 0.5), d = v3(1, 0, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 2);
    assert_near(s[0].in.t, 4, 1e-15);
    assert_near(s[0].out.t, 6, 1e-15);
    assert_near(s[1].in.t, 10, 0); /* the two squares touch: one span */
    assert_near(s[1].out.t, 14, 0);
    /* the lens's tips at (0, +-sqrt 3) */
    o = v3(0, -5, 0.5);
    d = v3(0, 1, 0);
    assert_int_equal(shoot(&f.p, o, d, s), 1);
    assert_near(s[0].in.t, 5 - sqrt(3), 1e-14);
    assert_near(s[0].out.t, 5 + sqrt(3), 1e-14);
    stop(&f);
}

/* ---- random regions against membership ---- */

typedef struct rng {
    uint64_t s;
} rng;

static double uniform(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

static double between(rng *r, double lo, double hi)
{
    return lo + (hi - lo) * uniform(r);
}

static void random_map(rng *r, double m[2][3])
{
    double a = between(r, 0, 2 * PI), sx = between(r, 0.3, 2), sy = between(r, 0.3, 2);
    double mirror = uniform(r) < 0.5 ? -1 : 1, shear = between(r, -0.5, 0.5);
    /* rotation . diag(sx, mirror sy) . shear */
    double l00 = sx, l01 = sx * shear, l10 = 0, l11 = mirror * sy;
    m[0][0] = cos(a) * l00 - sin(a) * l10;
    m[0][1] = cos(a) * l01 - sin(a) * l11;
    m[1][0] = sin(a) * l00 + cos(a) * l10;
    m[1][1] = sin(a) * l01 + cos(a) * l11;
    m[0][2] = between(r, -3, 3);
    m[1][2] = between(r, -3, 3);
}

/* A random leaf: an ellipse, or a polygon set of one to three random
 * paths (often self-intersecting), mapped by a random affine map. */
static void random_leaf(rng *r, fixture *f)
{
    double m[2][3];
    random_map(r, m);
    int pushed = 0;
    if (uniform(r) < 0.4) {
        assert_true(prim_region_add_ellipse(&f->r, m, between(r, 0.5, 3), &pushed));
        assert_true(pushed);
        return;
    }
    double xy[2 * 24];
    uint32_t st[4], n = 0, paths = 1 + (uint32_t)(uniform(r) * 3);
    for (uint32_t k = 0; k < paths; k++) {
        st[k] = n;
        uint32_t len = 3 + (uint32_t)(uniform(r) * 5);
        int star = uniform(r) < 0.5;
        for (uint32_t i = 0; i < len; i++, n++) {
            double x, y;
            if (star) { /* a star-shaped outline */
                double a = 2 * PI * (i + between(r, 0, 0.8)) / len,
                       rad = between(r, 0.5, 3);
                x = rad * cos(a);
                y = rad * sin(a);
            } else {
                x = between(r, -3, 3);
                y = between(r, -3, 3);
            }
            xy[2 * n] = m[0][0] * x + m[0][1] * y + m[0][2];
            xy[2 * n + 1] = m[1][0] * x + m[1][1] * y + m[1][2];
        }
    }
    st[paths] = n;
    assert_true(prim_region_add_polygon(&f->r, xy, st, paths, &pushed));
    assert_true(pushed);
}

static void random_tree(rng *r, fixture *f, int depth)
{
    if (depth == 0 || uniform(r) < 0.25) {
        random_leaf(r, f);
        return;
    }
    random_tree(r, f, depth - 1);
    random_tree(r, f, depth - 1);
    double u = uniform(r);
    add_op(f, u < 0.34   ? PRIM_REGION_UNION
              : u < 0.67 ? PRIM_REGION_INTERSECTION
                         : PRIM_REGION_DIFFERENCE);
}

static void test_random_regions(void **state)
{
    (void)state;
    rng r = {20261125};
    enum { TREES = 400, RAYS = 100, SAMPLES = 200 };
    uint64_t rays = 0, samples = 0, checked = 0, spans_seen = 0, disagree = 0;
    uint64_t normals = 0, bad_normals = 0, vertical = 0, level = 0, through_vertex = 0;
    span *s = NULL;
    for (int tree = 0; tree < TREES; tree++) {
        fixture f;
        start(&f);
        random_tree(&r, &f, 1 + tree % 4);
        double z0 = between(&r, -2, 0), z1 = z0 + between(&r, 0.5, 4);
        finish(&f, z0, z1);
        uint32_t cap = prim_max_spans(&f.p);
        s = realloc(s, (size_t)cap * sizeof *s);
        assert_non_null(s);
        for (int k = 0; k < RAYS; k++, rays++) {
            /* aimed through a point of the leaf's box */
            bbox b = prim_bounds(&f.p);
            vec3 aim = v3(between(&r, b.lo.x, b.hi.x), between(&r, b.lo.y, b.hi.y),
                          between(&r, b.lo.z, b.hi.z));
            vec3 d = v3(between(&r, -1, 1), between(&r, -1, 1), between(&r, -1, 1));
            if (k % 10 == 0) { /* vertical */
                d = v3(0, 0, uniform(&r) < 0.5 ? -1.5 : 0.7);
                vertical++;
            } else if (k % 10 == 1) { /* level */
                d.z = 0;
                level++;
            }
            const prim_extrusion *e = f.p.u.extrusion.ext;
            if (k % 10 >= 2 && k % 10 <= 4 && e->edge_count > 0) {
                /* through a polygon vertex: level, slanted, or along an edge */
                const double *g = &e->edges[4 * (uint32_t)(uniform(&r) * e->edge_count)];
                aim.x = g[0];
                aim.y = g[1];
                if (k % 10 == 2)
                    d.z = 0;
                if (k % 10 == 4)
                    d = v3(g[2] - g[0], g[3] - g[1], 0);
                through_vertex++;
            }
            double back = between(&r, 0, 10);
            vec3 o = v3_madd(aim, d, -back);
            /* a ray along an edge lies in the boundary there, where spans
             * and closed membership may differ: those samples are skipped */
            double on_lo = INFINITY, on_hi = -INFINITY;
            if (k % 10 == 4 && e->edge_count > 0) {
                on_lo = back;
                on_hi = back + 1;
            }
            uint32_t n = shoot(&f.p, o, d, s);
            spans_seen += n;
            double len = v3_length(d), tol = 1e-9 / len;
            for (uint32_t i = 0; i < n; i++) {
                vec3 nin = prim_normal(&f.p, v3_madd(o, d, s[i].in.t), s[i].in.part);
                vec3 nout = prim_normal(&f.p, v3_madd(o, d, s[i].out.t), s[i].out.part);
                normals += 2;
                /* strictly facing, but for a ray along an edge, which
                 * may meet that edge's wall (parallel to it) at either end */
                double din = v3_dot(nin, d), dout = v3_dot(nout, d);
                int along = k % 10 == 4;
                bad_normals +=
                    (along ? din > 0 : !(din < 0)) + (along ? dout < 0 : !(dout > 0));
            }
            for (int j = 0; j < SAMPLES; j++, samples++) {
                double t = between(&r, -20, 20) / len;
                int in_spans = 0, near = 0;
                for (uint32_t i = 0; i < n; i++) {
                    if (t >= s[i].in.t && t <= s[i].out.t)
                        in_spans = 1;
                    if (fabs(t - s[i].in.t) < tol || fabs(t - s[i].out.t) < tol)
                        near = 1;
                }
                if (near || (t >= on_lo - tol && t <= on_hi + tol))
                    continue;
                checked++;
                if (in_spans != prim_inside(&f.p, v3_madd(o, d, t)))
                    disagree++;
            }
        }
        stop(&f);
    }
    free(s);
    printf("extrusion property test: %d random 2D trees, %llu rays (%llu vertical, %llu "
           "level, %llu through a polygon vertex), %llu spans, %llu of %llu samples "
           "checked, %llu disagreements; %llu "
           "normals, %llu facing the wrong way\n",
           TREES, (unsigned long long)rays, (unsigned long long)vertical,
           (unsigned long long)level, (unsigned long long)through_vertex,
           (unsigned long long)spans_seen, (unsigned long long)checked,
           (unsigned long long)samples, (unsigned long long)disagree,
           (unsigned long long)normals, (unsigned long long)bad_normals);
    assert_true(spans_seen > rays / 4);
    assert_true(checked > samples * 99 / 100);
    assert_int_equal(disagree, 0);
    assert_int_equal(bad_normals, 0);
}

/* More walls than parts can tell apart: a 40000-gon's normals still come
 * from the wall that was hit. */
static void test_many_walls(void **state)
{
    (void)state;
    enum { N = 40000 };
    fixture f;
    start(&f);
    double *xy = malloc(2 * N * sizeof *xy);
    assert_non_null(xy);
    for (int i = 0; i < N; i++) {
        xy[2 * i] = 10 * cos(2 * PI * i / N);
        xy[2 * i + 1] = 10 * sin(2 * PI * i / N);
    }
    uint32_t st[2] = {0, N};
    int pushed;
    assert_true(prim_region_add_polygon(&f.r, xy, st, 1, &pushed));
    free(xy);
    finish(&f, 0, 1);
    span *s = malloc(prim_max_spans(&f.p) * sizeof *s);
    assert_non_null(s);
    /* edges past 32767 lie below the x axis (angles over 295 degrees) */
    for (int k = 0; k < 8; k++) {
        double a = 2 * PI * (0.83 + 0.02 * k);
        vec3 o = v3(0, 0, 0.5), d = v3(cos(a), sin(a), 0);
        assert_int_equal(shoot(&f.p, o, d, s), 1);
        vec3 n = unit_normal(&f.p, o, d, &s[0].out);
        assert_near(n.x, d.x, 1e-3);
        assert_near(n.y, d.y, 1e-3);
        assert_near(s[0].out.t, 10, 1e-6);
    }
    /* a buffer smaller than the sweep needs gets no spans */
    span small[4];
    assert_int_equal(prim_spans(&f.p, 0, v3(-20, 0, 0.5), v3(1, 0, 0), small, 4), 0);
    free(s);
    stop(&f);
}

/* A small region with a buffer smaller than prim_max_spans still gets its
 * spans (the local buffer), cut to the buffer. */
static void test_small_buffer(void **state)
{
    (void)state;
    fixture f;
    start(&f);
    add_rect(&f, 0, 0, 1, 1);
    add_rect(&f, 2, 0, 3, 1);
    add_op(&f, PRIM_REGION_UNION);
    finish(&f, 0, 1);
    span s[2];
    assert_int_equal(prim_spans(&f.p, 0, v3(-1, 0.5, 0.5), v3(1, 0, 0), s, 2), 2);
    assert_int_equal(prim_spans(&f.p, 0, v3(-1, 0.5, 0.5), v3(1, 0, 0), s, 1), 1);
    assert_near(s[0].out.t, 2, 0);
    stop(&f);
}

/* ---- the builder ---- */

static sc_scene *load_with(const char *text, int faithful)
{
    return test_load("m.csg", text, faithful);
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    test_check_error("m.csg", text, status, expected);
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static prim_kind only_kind(const sc_scene *s)
{
    const csg_tree *t = scene_tree(s);
    assert_int_equal(t->leaf_count, 1);
    return t->leaves[0].prim.kind;
}

static void check_empty(const char *text)
{
    sc_scene *s = load_with(text, 0);
    assert_int_equal(scene_tree(s)->root, CSG_EMPTY);
    assert_int_equal(sc_scene_warning_count(s), 1);
    assert_string_equal(sc_scene_warning(s, 0)->message,
                        "linear_extrude without height or area is empty");
    sc_scene_release(s);
}

#define PLATE                                                                            \
    "linear_extrude(height = 4, center = true, convexity = 1, scale = [1, 1], $fn = 0, " \
    "$fa = 12, $fs = 2) {\n"                                                             \
    "  difference() {\n"                                                                 \
    "    square(size = [20, 10], center = false);\n"                                     \
    "    multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"       \
    "      circle($fn = 6, $fa = 12, $fs = 2, r = 3);\n    }\n"                          \
    "    multmatrix([[2, 0, 0, 15], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"      \
    "      circle($fn = 0, $fa = 12, $fs = 2, d = 4);\n    }\n  }\n}"

/* Default mode: one exact leaf, circles as circles, a difference, an
 * ellipse from a scaled circle; faithful mode: OpenSCAD's mesh through the
 * 2D engine. */
static void test_build_exact(void **state)
{
    (void)state;
    sc_scene *s = load_with(PLATE, 0);
    assert_int_equal(only_kind(s), PRIM_EXTRUSION);
    assert_true(inside(s, 1, 1, 1.9));
    assert_false(inside(s, 1, 1, 2.1));
    assert_false(inside(s, 5, 7.9, 0)); /* in the true circle, outside its hexagon */
    assert_true(inside(s, 5, 8.1, 0));
    assert_false(inside(s, 18.9, 5, 0)); /* the ellipse reaches x = 19 */
    assert_true(inside(s, 19.1, 5, 0));
    assert_true(inside(s, 15, 7.1, 0));
    assert_false(inside(s, 15, 6.9, 0));
    sc_scene_release(s);
    sc_error e;
    sc_scene *f = NULL;
    sc_load_options o;
    sc_load_options_init(&o);
    o.faithful = 1;
    /* faithful mode: OpenSCAD's mesh, where the hole is its hexagon */
    assert_int_equal(sc_scene_load_string("m.csg", PLATE, strlen(PLATE), &o, &f, &e),
                     SC_OK);
    assert_int_equal(only_kind(f), PRIM_MESH);
    assert_true(inside(f, 5, 7.9, 0));
    assert_false(inside(f, 5, 5, 0));
    sc_scene_release(f);

    /* intersection, polygon with a hole, '%' and '*' children left out */
    s = load_with(
        "linear_extrude(height = 2) {\n"
        "  intersection() {\n"
        "    polygon(points = [[0, 0], [20, 0], [20, 20], [0, 20], [5, 5], [15, "
        "5], [15, 15], [5, 15]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);\n"
        "    circle(r = 12);\n    %square(1);\n    *square(1);\n  }\n"
        "  %square(100);\n}",
        0);
    assert_int_equal(only_kind(s), PRIM_EXTRUSION);
    assert_true(inside(s, 2, 2, 1));
    assert_false(inside(s, 10, 10, 1)); /* the hole */
    assert_false(inside(s, 19, 19, 1)); /* outside the circle */
    assert_true(inside(s, 11.9, 0.1, 1));
    assert_false(inside(s, 50, 50, 1));
    sc_scene_release(s);

    /* a polygon without paths, and with an empty vector of them */
    s = load_with(
        "linear_extrude(height = 1) { polygon(points = [[0, 0], [4, 0], [0, 4]], "
        "paths = []); polygon([[10, 0], [14, 0], [10, 4]]); }",
        0);
    assert_true(inside(s, 1, 1, 0.5));
    assert_true(inside(s, 11, 1, 0.5));
    assert_false(inside(s, 3, 3, 0.5));
    sc_scene_release(s);

    /* mirrored and nested 2D transforms */
    s = load_with(
        "linear_extrude(height = 1) { multmatrix([[-1, 0, 0, 0], [0, 1, 0, 0], "
        "[0, 0, 1, 0], [0, 0, 0, 1]]) { multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], "
        "[0, 0, 1, 7], [0, 0, 0, 1]]) { square(size = [2, 1]); } } }",
        0);
    assert_true(inside(s, -4, 0.5, 0.5));
    assert_false(inside(s, 4, 0.5, 0.5));
    sc_scene_release(s);

    /* twist, scale and 2D nodes the exact path does not read take
     * OpenSCAD's mesh (build_extrude_faithful.c) */
    static const char *const mesh_path[] = {
        "linear_extrude(height = 1, twist = 90) { square(); }",
        "linear_extrude(height = 1, scale = [2, 1]) { square(); }",
        "linear_extrude(height = 1) {\n  difference() {\n    square(2);\n    "
        "offset(r = 1) { square(1); }\n  }\n}",
        "linear_extrude(height = 1) { hull() { circle(); } }"};
    for (size_t i = 0; i < sizeof mesh_path / sizeof mesh_path[0]; i++) {
        s = load_with(mesh_path[i], 0);
        assert_int_equal(only_kind(s), PRIM_MESH);
        sc_scene_release(s);
    }
}

static void test_build_empty(void **state)
{
    (void)state;
    check_empty("linear_extrude(height = 0) { circle(r = 1); }");
    check_empty("linear_extrude(height = -1) { circle(r = 1); }");
    check_empty("linear_extrude(height = 1) { circle(r = 0); square(size = [1, -1]); }");
    check_empty(
        "linear_extrude(height = 1) { difference() { circle(r = 0); square(); } }");
    check_empty("linear_extrude(height = 1) { intersection() { circle(); square(0); } }");
    /* a singular 2D transform removes its children with OpenSCAD's warning */
    sc_scene *flat =
        load_with("linear_extrude(height = 1) { multmatrix([[1, 0, 0, 0], [2, "
                  "0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(); circle(); } }",
                  0);
    assert_int_equal(scene_tree(flat)->root, CSG_EMPTY);
    assert_int_equal(sc_scene_warning_count(flat), 2);
    assert_string_equal(sc_scene_warning(flat, 0)->message,
                        "Scaling a 2D object with 0 - removing object");
    assert_string_equal(sc_scene_warning(flat, 1)->message,
                        "linear_extrude without height or area is empty");
    sc_scene_release(flat);
    check_empty("linear_extrude(height = 1) { polygon(points = [[0, 0], [1, 1]]); }");
    /* an empty subtrahend changes nothing, an empty union member neither */
    sc_scene *s = load_with(
        "linear_extrude(height = 1) { difference() { square(2); circle(r = 0); } }", 0);
    assert_true(inside(s, 1, 1, 0.5));
    sc_scene_release(s);
}

static void test_build_errors(void **state)
{
    (void)state;
    /* arguments of the wrong kind are their defaults, as OpenSCAD 2021.01
     * takes them: silently (a radius 1, a center false, a $fn 0), but for
     * a square's size */
    static const char *const silent[] = {
        "linear_extrude(height = 1) { circle(r = \"a\"); }",
        "linear_extrude(height = 1) { circle(r = 2, d = [1], $fn = true); }",
        "linear_extrude(height = 1) { square(1, center = 1); }",
    };
    static const double reach[] = {1, 2, 1}; /* the shape's extent in +x */
    for (size_t i = 0; i < sizeof silent / sizeof silent[0]; i++) {
        sc_scene *s = load_with(silent[i], 0);
        assert_int_equal(sc_scene_warning_count(s), 0);
        assert_true(inside(s, reach[i] - 0.05, 0.01, 0.5));
        assert_false(inside(s, reach[i] + 0.05, 0.01, 0.5));
        sc_scene_release(s);
    }
    sc_scene *sq = load_with("linear_extrude(height = 1) { square(size = [3]); }", 0);
    assert_int_equal(sc_scene_warning_count(sq), 1);
    assert_string_equal(
        sc_scene_warning(sq, 0)->message,
        "Unable to convert square(size=[3], ...) parameter to a number or "
        "a vec2 of numbers");
    assert_true(inside(sq, 0.9, 0.9, 0.5) && !inside(sq, 1.1, 0.5, 0.5));
    sc_scene_release(sq);
    /* a point OpenSCAD 2021.01 cannot convert empties the polygon, with
     * its message as the warning (--strict: the error) */
    const char *bad_point =
        "linear_extrude(height = 1) {\n  polygon(points = [[0, 0], [1, 0], [1]]);\n  "
        "square(1);\n}";
    const char *bad_inf =
        "linear_extrude(height = 1) {\n  polygon(points = [[0, 0], [1, 0], [1, "
        "inf]]);\n  square(1);\n}";
    const char *const unable[] = {
        "m.csg:2:37: Unable to convert points[2] = [1] to a vec2 of numbers; the polygon "
        "is empty, as OpenSCAD leaves it out (--strict makes it an error)"};
    const char *const unable_inf[] = {
        "m.csg:2:37: Unable to convert points[2] = [1, inf] to a vec2 of numbers; the "
        "polygon is empty, as OpenSCAD leaves it out (--strict makes it an error)"};
    const test_point square[] = {{0.5, 0.5, 0.5, 1}, {1.5, 0.5, 0.5, 0}};
    test_check_warnings_both("m.csg", bad_point, unable, 1, square, 2);
    test_check_warnings_both("m.csg", bad_inf, unable_inf, 1, NULL, 0);
    for (int faithful = 0; faithful <= 1; faithful++) {
        test_check_strict_error("m.csg", bad_point, faithful, SC_ERR_SEMANTIC,
                                "m.csg:2:37: error: wrong type for argument 'points' of "
                                "'polygon' (expected a vector of [x, y] points)");
        test_check_strict_error("m.csg", bad_inf, faithful, SC_ERR_SEMANTIC,
                                "m.csg:2:37: error: wrong type for argument 'points' of "
                                "'polygon' (expected a vector of [x, y] points)");
    }
    /* a path index that is not a number is 0, as OpenSCAD reads it */
    sc_scene *unit =
        load_with("linear_extrude(height = 1) {\n  polygon(points = [[0, 0], "
                  "[1, 0], [1, 1], [0, 1]], paths = [[0, 1, 2, true]]);\n}",
                  0);
    assert_true(inside(unit, 0.9, 0.1, 0.5));
    assert_false(inside(unit, 0.1, 0.9, 0.5)); /* [0, 1, 2, 0]: the lower triangle */
    sc_scene_release(unit);
    /* a path that is not a vector is an empty one, paths that are not a
     * vector none (all the points), as OpenSCAD reads them */
    for (int k = 0; k < 2; k++) {
        sc_scene *s = test_check_warnings(
            "m.csg",
            k ? "linear_extrude(height = 1) {\n  polygon(points = [[0, 0], [1, 0], [1, "
                "1]], paths = [[0, 1, 2], 1.5]);\n}"
              : "linear_extrude(height = 1) {\n  polygon(points = [[0, 0], [1, 0], [1, "
                "1]], paths = \"x\");\n}",
            0, NULL, 0);
        assert_true(inside(s, 0.7, 0.3, 0.5));
        assert_false(inside(s, 0.3, 0.7, 0.5));
        sc_scene_release(s);
    }
    /* as OpenSCAD 2021.01: an index out of range left out with its
     * warning, a fraction truncated (the triangle 0, 1, 2) */
    const char *const bounds[] = {
        "m.csg:2:67: Point index 3 is out of bounds (from paths[0][3])"};
    const test_point triangle[] = {{0.7, 0.3, 0.5, 1}, {0.3, 0.7, 0.5, 0}};
    test_check_warnings_both(
        "m.csg",
        "linear_extrude(height = 1) {\n  polygon(points = [[0, 0], [1, 0], [1, 1]], "
        "paths = [[0, 1, 2.5, 3]]);\n}",
        bounds, 1, triangle, 2);
    /* a height that is not a number is 100, a center that is not true
     * false, as OpenSCAD 2021.01 exports them */
    sc_scene *tall =
        load_with("linear_extrude(height = \"x\", center = 0) { square(); }", 0);
    assert_int_equal(sc_scene_warning_count(tall), 0);
    assert_true(inside(tall, 0.5, 0.5, 99.5) && !inside(tall, 0.5, 0.5, -0.5));
    sc_scene_release(tall);

    /* the depth guard: 1001 nested 2D groups */
    size_t levels = 1001;
    char *text = malloc(64 + levels * 12);
    assert_non_null(text);
    char *p = text + sprintf(text, "linear_extrude(height = 1) {");
    for (size_t i = 0; i < levels; i++)
        p += sprintf(p, "group() {");
    p += sprintf(p, "square();");
    for (size_t i = 0; i < levels; i++)
        *p++ = '}';
    strcpy(p, "}");
    char expected[128];
    snprintf(
        expected, sizeof expected,
        "m.csg:1:%zu: error: too many nested nodes in linear_extrude (limit is 1000)",
        (size_t)29 + 9 * 1000);
    check_error(text, SC_ERR_LIMIT, expected);
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_wall_and_caps),
        cmocka_unit_test(test_square_minus_circles),
        cmocka_unit_test(test_polygon_with_hole),
        cmocka_unit_test(test_ellipse),
        cmocka_unit_test(test_intersection_and_union),
        cmocka_unit_test(test_random_regions),
        cmocka_unit_test(test_many_walls),
        cmocka_unit_test(test_small_buffer),
        cmocka_unit_test(test_build_exact),
        cmocka_unit_test(test_build_empty),
        cmocka_unit_test(test_build_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
