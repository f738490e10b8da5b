/* Tests of the triangle-mesh leaf (src/csg/prim_mesh.c): rays through
 * vertices and edges counted once (watertightness), entries and exits by
 * facing, non-convex spans against membership, the span and crossing caps
 * and what happens past them, normals of meshes with more than 65536
 * triangles, winding membership, and the parity rule of meshes that are
 * not closed. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "csg/csg.h"
#include "csg/prim_mesh.h"

static const double PI = 3.14159265358979323846;

typedef struct soup {
    vec3 *p;
    uint32_t *t;
    uint32_t np, nt;
} soup;

static void soup_point(soup *s, vec3 p)
{
    s->p = realloc(s->p, (s->np + 1) * sizeof *s->p);
    assert_non_null(s->p);
    s->p[s->np++] = p;
}

static void soup_tri(soup *s, uint32_t a, uint32_t b, uint32_t c)
{
    s->t = realloc(s->t, (s->nt + 1) * 3 * sizeof *s->t);
    assert_non_null(s->t);
    s->t[3 * s->nt] = a;
    s->t[3 * s->nt + 1] = b;
    s->t[3 * s->nt + 2] = c;
    s->nt++;
}

/* An outward-wound box lo..hi, each face split along a diagonal. */
static void soup_box(soup *s, vec3 lo, vec3 hi)
{
    uint32_t b = s->np;
    for (int i = 0; i < 8; i++)
        soup_point(s, v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        soup_tri(s, b + q[f][0], b + q[f][1], b + q[f][2]);
        soup_tri(s, b + q[f][0], b + q[f][2], b + q[f][3]);
    }
}

/* A UV sphere of radius r, outward: rings * segments quads. */
static void soup_sphere(soup *s, double r, int rings, int segments)
{
    uint32_t b = s->np;
    soup_point(s, v3(0, 0, -r));
    for (int i = 1; i < rings; i++) {
        double th = PI * i / rings - PI / 2;
        for (int j = 0; j < segments; j++) {
            double ph = 2 * PI * j / segments;
            soup_point(s, v3(r * cos(th) * cos(ph), r * cos(th) * sin(ph), r * sin(th)));
        }
    }
    soup_point(s, v3(0, 0, r));
    uint32_t top = s->np - 1;
#define RING(i, j) (b + 1 + (uint32_t)((i)-1) * segments + (uint32_t)((j) % segments))
    for (int j = 0; j < segments; j++) {
        soup_tri(s, b, RING(1, j + 1), RING(1, j));
        soup_tri(s, top, RING(rings - 1, j), RING(rings - 1, j + 1));
        for (int i = 1; i + 1 < rings; i++) {
            soup_tri(s, RING(i, j), RING(i, j + 1), RING(i + 1, j + 1));
            soup_tri(s, RING(i, j), RING(i + 1, j + 1), RING(i + 1, j));
        }
    }
#undef RING
}

/* t from barycentric interpolation: exact up to a few roundings. */
static int near(double a, double b)
{
    return fabs(a - b) <= 1e-12 * fmax(1, fabs(b));
}

static prim make(csg_builder *b, soup *s)
{
    prim p = {.kind = PRIM_MESH};
    p.u.mesh.mesh = prim_mesh_create(b, s->p, s->t, s->nt);
    assert_non_null(p.u.mesh.mesh);
    free(s->p);
    free(s->t);
    s->p = NULL;
    s->t = NULL;
    s->np = s->nt = 0;
    return p;
}

static uint64_t next(uint64_t *x)
{
    *x ^= *x << 13;
    *x ^= *x >> 7;
    *x ^= *x << 17;
    return *x;
}

static double uniform(uint64_t *x, double lo, double hi)
{
    return lo + (hi - lo) * (double)(next(x) >> 11) / 9007199254740992.0;
}

/* The unit cube: rays along each axis through the face centres (on the
 * diagonal of the two triangles of each face) give exactly one span [1, 2]
 * (from one unit before the near face), entering at a face whose normal
 * faces the ray; rays along the cube's faces and edges (the rest of the
 * grid {0, 0.5, 1}^2) give that span or none. */
static void test_cube_edges_and_vertices(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    soup_box(&s, v3(0, 0, 0), v3(1, 1, 1));
    prim p = make(b, &s);
    assert_int_equal(prim_max_spans(&p), 6);
    for (int axis = 0; axis < 3; axis++) {
        for (int sign = -1; sign <= 1; sign += 2) {
            for (int i = 0; i <= 2; i++) {
                for (int j = 0; j <= 2; j++) {
                    double u = i / 2.0, v = j / 2.0, start = sign > 0 ? -1 : 2;
                    vec3 o = axis == 0   ? v3(start, u, v)
                             : axis == 1 ? v3(u, start, v)
                                         : v3(u, v, start);
                    vec3 d = v3(axis == 0 ? sign : 0, axis == 1 ? sign : 0,
                                axis == 2 ? sign : 0);
                    span out[8];
                    uint32_t n = prim_spans(&p, 7, o, d, out, 8);
                    /* a ray along the boundary is tangent: the
                     * perturbation puts it inside or outside, whole */
                    int boundary = i != 1 || j != 1;
                    if (boundary && n == 0)
                        continue;
                    assert_int_equal(n, 1);
                    assert_true(near(out[0].in.t, 1) && near(out[0].out.t, 2));
                    assert_int_equal(out[0].in.leaf, 7);
                    vec3 nin = prim_normal(&p, v3_madd(o, d, 1), out[0].in.part);
                    vec3 nout = prim_normal(&p, v3_madd(o, d, 2), out[0].out.part);
                    assert_true(v3_dot(nin, d) < 0);
                    assert_true(v3_dot(nout, d) > 0);
                }
            }
        }
    }
    csg_builder_free(b);
}

/* A closed sphere mesh: every line from the centre through a vertex or a
 * point of an edge (where two or more triangles meet) crosses the surface
 * exactly twice, one span; no ray slips between faces. */
static void test_watertight_sphere(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    soup_sphere(&s, 1.3, 9, 14);
    vec3 *pts = malloc(s.np * sizeof *pts);
    uint32_t *tris = malloc(s.nt * 3 * sizeof *tris);
    assert_true(pts && tris);
    uint32_t np = s.np, nt = s.nt;
    for (uint32_t i = 0; i < np; i++)
        pts[i] = s.p[i];
    for (uint32_t i = 0; i < 3 * nt; i++)
        tris[i] = s.t[i];
    prim p = make(b, &s);
    uint64_t rng = 12345;
    uint32_t rays = 0;
    for (uint32_t t = 0; t < nt; t++) {
        vec3 a = pts[tris[3 * t]], c = pts[tris[3 * t + 1]];
        for (int k = 0; k < 4; k++) {
            /* a vertex, then points along an edge */
            double w = k == 0 ? 0 : uniform(&rng, 0, 1);
            vec3 target = v3_add(v3_scale(a, 1 - w), v3_scale(c, w));
            vec3 centre = v3(uniform(&rng, -0.1, 0.1), uniform(&rng, -0.1, 0.1),
                             uniform(&rng, -0.1, 0.1));
            vec3 d = v3_sub(target, centre);
            span out[8];
            uint32_t n = prim_spans(&p, 0, centre, d, out, 8);
            assert_int_equal(n, 1);
            assert_true(out[0].in.t < 0 && fabs(out[0].out.t - 1) < 1e-12);
            rays++;
        }
    }
    assert_int_equal(rays, 4 * nt);
    free(pts);
    free(tris);
    csg_builder_free(b);
}

/* A U shape (three boxes touching face to face would not be one closed
 * mesh, so two disjoint prongs and a bar under them): random rays agree
 * with membership at the midpoints of spans and gaps. */
static void test_nonconvex_against_inside(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    soup_box(&s, v3(-2, -1, -1), v3(-1, 1, 1));
    soup_box(&s, v3(1, -1, -1), v3(2, 1, 1));
    soup_sphere(&s, 0.8, 7, 11);
    prim p = make(b, &s);
    uint64_t rng = 99;
    uint32_t multi = 0;
    for (int r = 0; r < 3000; r++) {
        vec3 o = v3(uniform(&rng, -4, 4), uniform(&rng, -4, 4), uniform(&rng, -4, 4));
        vec3 d = v3_sub(
            v3(uniform(&rng, -2, 2), uniform(&rng, -1, 1), uniform(&rng, -1, 1)), o);
        span out[PRIM_MESH_MAX_SPANS];
        uint32_t n = prim_spans(&p, 0, o, d, out, prim_max_spans(&p));
        multi += n > 1;
        for (uint32_t k = 0; k < n; k++) {
            assert_true(out[k].in.t <= out[k].out.t);
            if (k > 0)
                assert_true(out[k - 1].out.t <= out[k].in.t);
            double len = out[k].out.t - out[k].in.t;
            if (len > 1e-6)
                assert_true(prim_inside(&p, v3_madd(o, d, out[k].in.t + 0.5 * len)));
            if (k > 0 && out[k].in.t - out[k - 1].out.t > 1e-6)
                assert_false(prim_inside(
                    &p, v3_madd(o, d, 0.5 * (out[k - 1].out.t + out[k].in.t))));
        }
        if (n > 0) {
            assert_false(prim_inside(&p, v3_madd(o, d, out[0].in.t - 0.01)));
            assert_false(prim_inside(&p, v3_madd(o, d, out[n - 1].out.t + 0.01)));
        } else {
            assert_false(prim_inside(&p, o));
        }
    }
    assert_true(multi > 100);
    assert_true(prim_inside(&p, v3(-1.5, 0, 0)));
    assert_true(prim_inside(&p, v3(0, 0, 0)));
    assert_false(prim_inside(&p, v3(0.9, 0, 0)));
    assert_true(prim_inside(&p, v3(-1, 0.5, 0.5))); /* on the surface: closed */
    csg_builder_free(b);
}

/* count disjoint unit boxes in a row along x, gaps of 1. */
static prim comb(csg_builder *b, int count)
{
    soup s = {0};
    for (int i = 0; i < count; i++)
        soup_box(&s, v3(2 * i, 0, 0), v3(2 * i + 1, 1, 1));
    return make(b, &s);
}

/* Past the span cap: the first cap - 1 spans are exact and the last one
 * runs from the cap-th entry to the mesh's last exit. Past the crossing
 * cap (256, 128 boxes): the spans of the 256 nearest crossings are exact
 * and the last one reaches the last exit. */
static void test_caps(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    vec3 o = v3(-0.5, 0.3, 0.6), d = v3(1, 0, 0);
    prim p = comb(b, 40);
    assert_int_equal(prim_max_spans(&p), PRIM_MESH_MAX_SPANS);
    span out[200];
    uint32_t n = prim_spans(&p, 0, o, d, out, prim_max_spans(&p));
    assert_int_equal(n, PRIM_MESH_MAX_SPANS);
    for (uint32_t k = 0; k + 1 < n; k++) {
        assert_true(near(out[k].in.t, 2 * k + 0.5));
        assert_true(near(out[k].out.t, 2 * k + 1.5));
    }
    assert_true(near(out[n - 1].in.t, 2 * (n - 1) + 0.5));
    assert_true(near(out[n - 1].out.t, 2 * 39 + 1.5));
    /* with room for all 40 */
    n = prim_spans(&p, 0, o, d, out, 200);
    assert_int_equal(n, 40);
    assert_true(near(out[39].in.t, 78.5) && near(out[39].out.t, 79.5));

    prim q = comb(b, 150);
    n = prim_spans(&q, 0, o, d, out, 200);
    assert_int_equal(n, PRIM_MESH_MAX_CROSSINGS / 2);
    for (uint32_t k = 0; k + 1 < n; k++)
        assert_true(near(out[k].in.t, 2 * k + 0.5) && near(out[k].out.t, 2 * k + 1.5));
    assert_true(near(out[n - 1].in.t, 2 * (n - 1) + 0.5));
    assert_true(near(out[n - 1].out.t, 2 * 149 + 1.5));
    /* membership counts every crossing, however many */
    assert_true(prim_inside(&q, v3(2 * 140 + 0.5, 0.5, 0.5)));
    assert_false(prim_inside(&q, v3(2 * 140 + 1.5, 0.5, 0.5)));
    csg_builder_free(b);
}

/* A sphere mesh of more than 65536 triangles: the 16-bit part names the
 * triangle modulo 65536; the normal at each first hit is still the hit
 * triangle's (close to the radial direction). */
static void test_normals_of_large_meshes(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    soup_sphere(&s, 1, 130, 270);
    assert_true(s.nt > 65536);
    prim p = make(b, &s);
    uint64_t rng = 7;
    for (int r = 0; r < 400; r++) {
        vec3 o = v3(uniform(&rng, -3, 3), uniform(&rng, -3, 3), 5);
        vec3 d = v3_sub(v3(uniform(&rng, -0.6, 0.6), uniform(&rng, -0.6, 0.6), 0), o);
        span out[PRIM_MESH_MAX_SPANS];
        uint32_t n = prim_spans(&p, 0, o, d, out, prim_max_spans(&p));
        assert_int_equal(n, 1);
        vec3 q = v3_madd(o, d, out[0].in.t);
        vec3 nrm = prim_normal(&p, q, out[0].in.part);
        double c = v3_dot(nrm, q) / (v3_length(nrm) * v3_length(q));
        assert_true(c > 0.999);
    }
    csg_builder_free(b);
}

/* A sphere so small that its boxes, as floats relative to its centre,
 * are subnormal: the hierarchy's bins must still split it (a float scale
 * of 16 over such a width is infinite, and 0 times it NaN, whose cast to
 * int is undefined), and every ray through it meets it once. */
static void test_subnormal_extent(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    double r = 1e-40;
    soup_sphere(&s, r, 8, 16);
    prim p = make(b, &s);
    for (int k = 0; k < 16; k++) {
        double a = 2 * PI * k / 16;
        vec3 d = v3(cos(a), sin(a), 0.25);
        vec3 o = v3_scale(d, -4 * r / v3_length(d));
        span out[4];
        uint32_t n = prim_spans(&p, 0, o, d, out, 4);
        assert_int_equal(n, 1);
        assert_true(out[0].in.t < out[0].out.t);
    }
    csg_builder_free(b);
}

/* A triangle without area makes no mesh; a zero direction gives nothing;
 * a ray along a face's plane meets only the faces across it. */
static void test_degenerate(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    vec3 pts[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    uint32_t tri[3] = {0, 1, 2};
    assert_null(prim_mesh_create(b, pts, tri, 1)); /* no area */
    prim p = comb(b, 1);
    span out[4];
    assert_int_equal(prim_spans(&p, 0, v3(0, 0, 0), v3(0, 0, 0), out, 4), 0);
    /* a ray in the plane of a face, along it: only the side faces count */
    uint32_t n = prim_spans(&p, 0, v3(-1, 0, 0.5), v3(1, 0, 0), out, 4);
    assert_true(n <= 1);
    if (n == 1)
        assert_true(near(out[0].in.t, 1) && near(out[0].out.t, 2));
    csg_builder_free(b);
}

/* The spans of l that meet [lo, hi] (closed), compacted in place. */
static uint32_t meeting(span *l, uint32_t n, double lo, double hi)
{
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++)
        if (l[i].out.t >= lo && l[i].in.t <= hi)
            l[k++] = l[i];
    return k;
}

static int same_end(span_end a, span_end b)
{
    return a.t == b.t && a.leaf == b.leaf && a.part == b.part && a.flip == b.flip;
}

/* A first-crossing answer (part, np) against the whole line's spans (full,
 * nf), both regularised: the first span after lo within [lo, hi] has the
 * same in end when it begins at or after lo, the same out end (and an in
 * end before lo) when it begins before; nothing there in one is nothing in
 * the other. Returns 1 when there was a span to compare. */
static int same_first(const span *full, uint32_t nf, const span *part, uint32_t np,
                      double lo, double hi)
{
    uint32_t a = 0, g = 0;
    while (a < nf && !(full[a].out.t > lo))
        a++;
    while (g < np && !(part[g].out.t > lo))
        g++;
    if (a == nf || !(full[a].in.t < hi)) {
        /* nothing after lo within the range: the answer shows nothing
         * there either */
        assert_true(g == np || !(part[g].in.t < hi));
        return 0;
    }
    assert_true(g < np);
    if (full[a].in.t >= lo)
        assert_true(same_end(part[g].in, full[a].in));
    else
        assert_true(same_end(part[g].out, full[a].out) && part[g].in.t < lo);
    return 1;
}

/* prim_spans_range against the whole line's spans (prim_spans), both
 * regularised, on random rays and ranges through a mesh of many pieces,
 * some touching (gaps that regularisation closes) and some thin (slivers
 * it removes) at the larger eps: every span that meets the range has the
 * same ends, and a first-crossing query gets the same first crossing after
 * the range start. The walk then starts inside and outside the mesh, ends
 * inside spans, and narrows. */
static void test_range_walk(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    for (int i = 0; i < 6; i++)
        soup_box(&s, v3(2 * i, 0, 0), v3(2 * i + 1, 1, 1));
    soup_box(&s, v3(1, 0, 0), v3(1.0005, 1, 1));    /* touches the first box */
    soup_box(&s, v3(4, 0, 0), v3(4.0001, 1, 1));    /* touches the third */
    soup_box(&s, v3(3.3, 0, 0), v3(3.30005, 1, 1)); /* thin, on its own */
    soup_sphere(&s, 0.7, 9, 13);
    prim p = make(b, &s);
    uint64_t rng = 7;
    uint32_t cap = prim_max_spans(&p), checked = 0, first_checked = 0;
    const double epsilons[] = {1e-9, 1e-3, 0.05};
    for (int r = 0; r < 20000; r++) {
        vec3 o = v3(uniform(&rng, -3, 14), uniform(&rng, -2, 3), uniform(&rng, -2, 3));
        vec3 target = v3(uniform(&rng, -1, 12), uniform(&rng, 0, 1), uniform(&rng, 0, 1));
        if (r % 3 == 0)
            target.y = target.z = 0.5;
        vec3 d = v3_sub(target, o);
        double eps = epsilons[r % 3];
        double lo = uniform(&rng, -0.5, 1.5), hi = lo + uniform(&rng, 0, 1.5);
        if (r % 7 == 0)
            hi = INFINITY;
        if (r % 11 == 0)
            lo = -INFINITY;
        span full[PRIM_MESH_MAX_SPANS], part[PRIM_MESH_MAX_SPANS];
        uint32_t nf = prim_spans(&p, 3, o, d, full, cap);
        nf = span_regularize(full, nf, eps);
        for (int first = 0; first < 2; first++) {
            uint32_t np = prim_spans_range(&p, 3, o, d, lo, hi, eps, first, part, cap);
            np = span_regularize(part, np, eps);
            if (!first) {
                span want[PRIM_MESH_MAX_SPANS];
                memcpy(want, full, nf * sizeof *full);
                uint32_t nw = meeting(want, nf, lo, hi);
                uint32_t ng = meeting(part, np, lo, hi);
                assert_int_equal(ng, nw);
                for (uint32_t k = 0; k < nw; k++) {
                    assert_true(same_end(part[k].in, want[k].in));
                    assert_true(same_end(part[k].out, want[k].out));
                }
                checked += nw;
                continue;
            }
            first_checked += same_first(full, nf, part, np, lo, hi);
        }
    }
    assert_true(checked > 5000);
    assert_true(first_checked > 3000);
    csg_builder_free(b);
}

/* A prism over a star of 2 n corners (radii 1 and 0.4, z from z0 to z1),
 * each cap a fan from one corner: the fan's triangles overlap and some face
 * the other way, and cancel by winding number. */
static void soup_star(soup *s, int n, double z0, double z1)
{
    uint32_t b = s->np, m = 2 * (uint32_t)n;
    for (int k = 0; k < 2; k++)
        for (uint32_t i = 0; i < m; i++) {
            double r = i % 2 ? 0.4 : 1, a = 2 * PI * i / m;
            soup_point(s, v3(r * cos(a), r * sin(a), k ? z1 : z0));
        }
    for (uint32_t i = 1; i + 1 < m; i++) {
        soup_tri(s, b, b + i + 1, b + i);
        soup_tri(s, b + m, b + m + i, b + m + i + 1);
    }
    for (uint32_t i = 0; i < m; i++) {
        uint32_t j = (i + 1) % m;
        soup_tri(s, b + i, b + j, b + m + j);
        soup_tri(s, b + i, b + m + j, b + m + i);
    }
}

/* First-crossing queries whose range starts inside the mesh's box, where a
 * closed mesh may take the winding at the start from the crossings after
 * it instead of before: a star prism with fan caps, two boxes that
 * overlap and a sphere through the prism (winding 2 where they overlap).
 * Every answer against the whole line's spans, from origins all over the
 * box, in every direction and along the caps' planes. */
static void test_first_from_inside(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {0};
    soup_star(&s, 7, -1, 1);
    soup_box(&s, v3(1.5, -1, -1), v3(3, 1, 0.5));
    soup_box(&s, v3(2, -0.5, -0.5), v3(3.5, 0.5, 1));
    soup_sphere(&s, 0.9, 9, 13);
    prim p = make(b, &s);
    const double epsilons[] = {1e-9, 1e-3, 0.05};
    uint64_t rng = 23;
    uint32_t cap = prim_max_spans(&p), checked = 0, inside = 0;
    for (int r = 0; r < 30000; r++) {
        vec3 o = v3(uniform(&rng, -1.2, 3.7), uniform(&rng, -1.2, 1.2),
                    uniform(&rng, -1.2, 1.2));
        vec3 d = v3(uniform(&rng, -1, 1), uniform(&rng, -1, 1), uniform(&rng, -1, 1));
        if (r % 5 == 0)
            d.z = 0; /* along the caps' planes */
        double eps = epsilons[r % 3];
        double lo = r % 4 ? 0 : uniform(&rng, -0.5, 0.5);
        double hi = r % 2 ? INFINITY : lo + uniform(&rng, 0, 3);
        span full[PRIM_MESH_MAX_SPANS], part[PRIM_MESH_MAX_SPANS];
        uint32_t nf = span_regularize(full, prim_spans(&p, 3, o, d, full, cap), eps);
        uint32_t np = prim_spans_range(&p, 3, o, d, lo, hi, eps, 1, part, cap);
        np = span_regularize(part, np, eps);
        checked += same_first(full, nf, part, np, lo, hi);
        inside += prim_inside(&p, v3_madd(o, d, lo));
    }
    assert_true(checked > 10000);
    assert_true(inside > 3000);
    csg_builder_free(b);
}

/* The parity rule (prim_mesh_create_rule with parity 1), for meshes that
 * are not closed or not consistently wound. A unit cube with one face
 * turned inward: by winding number the line down through that face never
 * comes back to zero (-1 past the top, -2 past the bottom), so the cube's
 * membership is wrong (its centre is inside from one direction, outside
 * from another); by parity the cube is whole, and the entry on the turned
 * face carries the flip bit so its normal still faces the ray. The same cube without
 * its top: a line through the side walls has its span; a line down
 * through the open top crosses the bottom alone, and its unpaired
 * crossing makes no span. Membership counts crossings the same way. */
static void test_parity_rule(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {NULL, NULL, 0, 0};
    soup_box(&s, v3(0, 0, 0), v3(1, 1, 1));
    /* turn the top face (triangles 2 and 3: 4 5 7 6) inward */
    for (uint32_t k = 2; k < 4; k++) {
        uint32_t t = s.t[3 * k + 1];
        s.t[3 * k + 1] = s.t[3 * k + 2];
        s.t[3 * k + 2] = t;
    }
    prim winding = {.kind = PRIM_MESH};
    winding.u.mesh.mesh = prim_mesh_create(b, s.p, s.t, s.nt);
    prim parity = {.kind = PRIM_MESH};
    parity.u.mesh.mesh = prim_mesh_create_rule(b, s.p, s.t, s.nt, 1);
    assert_non_null(winding.u.mesh.mesh);
    assert_non_null(parity.u.mesh.mesh);
    span out[8];
    /* down through the turned top face */
    vec3 o = v3(0.3, 0.4, 3), d = v3(0, 0, -1);
    uint32_t n = prim_mesh_spans(&parity, 0, o, d, out, 8);
    assert_int_equal(n, 1);
    assert_true(near(out[0].in.t, 2) && near(out[0].out.t, 3));
    assert_int_equal(out[0].in.flip, 1);  /* the turned face, faced back */
    assert_int_equal(out[0].out.flip, 0); /* the bottom, as wound */
    vec3 nin = prim_mesh_normal(&parity, v3(0.3, 0.4, 1), out[0].in.part);
    assert_true((out[0].in.flip ? -1 : 1) * v3_dot(nin, d) < 0);
    /* by winding number, the centre is inside seen along membership's
     * direction (one crossing, the turned top: -1) and the line down
     * through it never closes */
    assert_true(prim_mesh_inside(&winding, v3(0.5, 0.5, 0.5)));
    assert_true(prim_mesh_inside(&parity, v3(0.5, 0.5, 0.5)));
    assert_false(prim_mesh_inside(&winding, v3(0.5, 0.5, -0.5))); /* -1 + 1 */
    assert_true(prim_mesh_inside(&parity, v3(0.5, 0.5, 0.5)));
    assert_false(prim_mesh_inside(&parity, v3(0.5, 0.5, 1.5)));
    /* the cube without its top */
    free(s.p);
    free(s.t);
    s = (soup){NULL, NULL, 0, 0};
    soup_box(&s, v3(0, 0, 0), v3(1, 1, 1));
    memmove(&s.t[6], &s.t[12], (size_t)(s.nt - 4) * 3 * sizeof *s.t);
    s.nt -= 2;
    prim open = {.kind = PRIM_MESH};
    open.u.mesh.mesh = prim_mesh_create_rule(b, s.p, s.t, s.nt, 1);
    assert_non_null(open.u.mesh.mesh);
    n = prim_mesh_spans(&open, 0, v3(-1, 0.5, 0.5), v3(1, 0, 0), out, 8);
    assert_int_equal(n, 1);
    assert_true(near(out[0].in.t, 1) && near(out[0].out.t, 2));
    assert_int_equal(out[0].in.flip, 0);
    /* Down through the opening, and slanting through it onto a wall: one
     * crossing each, which opens a span to where the line leaves the
     * mesh's box (the floor, the wall: both on the box), so that the face
     * is seen, as OpenSCAD draws every face of such a mesh. */
    n = prim_mesh_spans(&open, 0, v3(0.5, 0.5, 3), v3(0, 0, -1), out, 8);
    assert_int_equal(n, 1);
    assert_true(near(out[0].in.t, 3) && out[0].out.t > out[0].in.t);
    n = prim_mesh_spans(&open, 0, v3(0.2, 0.5, 1.2), v3(1, 0, -0.5), out, 8);
    assert_int_equal(n, 1);
    assert_true(near(out[0].in.t, 0.8) && out[0].out.t > out[0].in.t);
    free(s.p);
    free(s.t);
    csg_builder_free(b);
}

/* The winding rule on a closed, consistently wound mesh that crosses
 * itself: the line is inside where the winding number is not zero. A
 * prism on the bow-tie (0,0) (1,1) (1,0) (0,1), its faces fans of that
 * quad: the lobe x < 1/2 turns counter-clockwise (+1), the lobe x > 1/2
 * clockwise (-1), as a twisted extrusion's side faces fold through one
 * another. OpenSCAD draws such a mesh's triangles as they are, so both
 * lobes are solid, the inverted one with its ends flipped to face out of
 * the span; by the rule "positive", the inverted lobe was empty. */
static void test_winding_nonzero(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    soup s = {NULL, NULL, 0, 0};
    static const double q[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    for (int z = 0; z < 2; z++)
        for (int i = 0; i < 4; i++)
            soup_point(&s, v3(q[i][0], q[i][1], z));
    soup_tri(&s, 0, 2, 1); /* the bottom: the fan, turned down */
    soup_tri(&s, 0, 3, 2);
    soup_tri(&s, 4, 5, 6); /* the top: the fan */
    soup_tri(&s, 4, 6, 7);
    for (uint32_t i = 0; i < 4; i++) { /* each side on edge a -> b */
        uint32_t a = i, c = (i + 1) % 4;
        soup_tri(&s, a, c, c + 4);
        soup_tri(&s, a, c + 4, a + 4);
    }
    prim mesh = {.kind = PRIM_MESH};
    mesh.u.mesh.mesh = prim_mesh_create(b, s.p, s.t, s.nt);
    assert_non_null(mesh.u.mesh.mesh);
    span out[8];
    for (int lobe = 0; lobe < 2; lobe++) {
        vec3 o = v3(lobe ? 0.8 : 0.2, 0.5, 3), d = v3(0, 0, -1);
        uint32_t n = prim_mesh_spans(&mesh, 0, o, d, out, 8);
        assert_int_equal(n, 1);
        assert_true(near(out[0].in.t, 2) && near(out[0].out.t, 3));
        assert_int_equal(out[0].in.flip, lobe);
        assert_int_equal(out[0].out.flip, lobe);
        vec3 nin = prim_mesh_normal(&mesh, v3(o.x, 0.5, 1), out[0].in.part);
        assert_true((out[0].in.flip ? -1 : 1) * v3_dot(nin, d) < 0);
        assert_true(prim_mesh_inside(&mesh, v3(o.x, 0.5, 0.5)));
        assert_false(prim_mesh_inside(&mesh, v3(o.x, 0.5, 1.5)));
    }
    free(s.p);
    free(s.t);
    csg_builder_free(b);
}

/* A triangle listed twice (issue1876 of OpenSCAD's tests lists a face
 * twice) is one face of a parity mesh, whichever way each copy is wound:
 * OpenSCAD draws it once. Counted twice, its crossings cancelled, and the
 * line down through it saw the bottom's crossing alone. */
static void test_parity_duplicate(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    for (int turned = 0; turned < 2; turned++) {
        soup s = {NULL, NULL, 0, 0};
        soup_box(&s, v3(0, 0, 0), v3(1, 1, 1));
        /* the top face (triangles 2 and 3) again, the second time turned */
        for (uint32_t k = 2; k < 4; k++) {
            const uint32_t *t = &s.t[3 * k];
            uint32_t a = t[0], bb = t[1], c = t[2];
            soup_tri(&s, a, turned ? c : bb, turned ? bb : c);
        }
        prim m = {.kind = PRIM_MESH};
        m.u.mesh.mesh = prim_mesh_create_rule(b, s.p, s.t, s.nt, 1);
        assert_non_null(m.u.mesh.mesh);
        assert_int_equal(m.u.mesh.mesh->tri_count, 12);
        span out[8];
        uint32_t n = prim_mesh_spans(&m, 0, v3(0.3, 0.4, 3), v3(0, 0, -1), out, 8);
        assert_int_equal(n, 1);
        assert_true(near(out[0].in.t, 2) && near(out[0].out.t, 3));
        assert_true(prim_mesh_inside(&m, v3(0.5, 0.5, 0.5)));
        assert_false(prim_mesh_inside(&m, v3(0.5, 0.5, 1.5)));
        free(s.p);
        free(s.t);
    }
    csg_builder_free(b);
}

/* A mesh of enough triangles has its hierarchy built in OpenMP tasks,
 * each large right subtree into nodes of its own, appended once its left
 * sibling is done. It must be the hierarchy one thread builds: the same
 * nodes in the same order, and the triangles in the same order. */
static void test_tasks_build_one_thread_tree(void **state)
{
    (void)state;
    enum { RINGS = 180, SEGMENTS = 400 };
    uint32_t np = (RINGS - 1) * SEGMENTS + 2, nt = 2 * SEGMENTS * (RINGS - 1);
    vec3 *p = malloc(np * sizeof *p);
    uint32_t *t = malloc((size_t)3 * nt * sizeof *t);
    assert_non_null(p);
    assert_non_null(t);
    /* a sphere, its radius rippled so no two rings are alike */
    p[0] = v3(0, 0, -1);
    for (int i = 1; i < RINGS; i++) {
        double th = PI * i / RINGS - PI / 2;
        for (int j = 0; j < SEGMENTS; j++) {
            double ph = 2 * PI * j / SEGMENTS, r = 1 + 0.05 * sin(7 * ph + 3 * th);
            p[1 + (i - 1) * SEGMENTS + j] =
                v3(r * cos(th) * cos(ph), r * cos(th) * sin(ph), r * sin(th));
        }
    }
    p[np - 1] = v3(0, 0, 1);
    uint32_t k = 0;
#define RING(i, j) (1 + (uint32_t)((i)-1) * SEGMENTS + (uint32_t)((j) % SEGMENTS))
    for (int j = 0; j < SEGMENTS; j++) {
        uint32_t tri[][3] = {{0, RING(1, j + 1), RING(1, j)},
                             {np - 1, RING(RINGS - 1, j), RING(RINGS - 1, j + 1)}};
        memcpy(&t[3 * k], tri, sizeof tri);
        k += 2;
        for (int i = 1; i + 1 < RINGS; i++) {
            uint32_t quad[][3] = {{RING(i, j), RING(i, j + 1), RING(i + 1, j + 1)},
                                  {RING(i, j), RING(i + 1, j + 1), RING(i + 1, j)}};
            memcpy(&t[3 * k], quad, sizeof quad);
            k += 2;
        }
    }
#undef RING
    assert_int_equal(k, nt);
    const prim_mesh *m[2];
    csg_builder *b = csg_builder_new();
    int threads = omp_get_max_threads();
    for (int i = 0; i < 2; i++) {
        omp_set_num_threads(i ? 2 : 1);
        m[i] = prim_mesh_create(b, p, t, nt);
        assert_non_null(m[i]);
    }
    omp_set_num_threads(threads);
    assert_int_equal(m[0]->tri_count, nt);
    assert_int_equal(m[1]->tri_count, nt);
    assert_int_equal(m[1]->node_count, m[0]->node_count);
    assert_memory_equal(m[1]->nodes, m[0]->nodes, m[0]->node_count * sizeof *m[0]->nodes);
    assert_memory_equal(m[1]->v, m[0]->v, (size_t)3 * nt * sizeof *m[0]->v);
    csg_builder_free(b);
    free(p);
    free(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cube_edges_and_vertices),
        cmocka_unit_test(test_watertight_sphere),
        cmocka_unit_test(test_nonconvex_against_inside),
        cmocka_unit_test(test_caps),
        cmocka_unit_test(test_normals_of_large_meshes),
        cmocka_unit_test(test_degenerate),
        cmocka_unit_test(test_subnormal_extent),
        cmocka_unit_test(test_range_walk),
        cmocka_unit_test(test_first_from_inside),
        cmocka_unit_test(test_parity_rule),
        cmocka_unit_test(test_parity_duplicate),
        cmocka_unit_test(test_winding_nonzero),
        cmocka_unit_test(test_tasks_build_one_thread_tree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
