/* Tests of the outline prism (src/csg/prim_outline.c): the crossings of a
 * line with lines and quadratic and cubic Bezier segments against points
 * sampled on the curves, crossing counts against dense sampling, and span
 * lists against point membership on random outlines of all three kinds,
 * with normals that point out of the solid. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "csg/csg.h"
#include "csg/prim_outline.h"

typedef struct rng {
    uint64_t s;
} rng;

static double uniform(rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(r->s >> 11) / 9007199254740992.0;
}

static double uniform_in(rng *r, double a, double b)
{
    return a + (b - a) * uniform(r);
}

static void bezier(const outline_seg *s, double u, double *x, double *y)
{
    double v = 1 - u;
    switch (s->degree) {
    case 1:
        *x = v * s->x[0] + u * s->x[1];
        *y = v * s->y[0] + u * s->y[1];
        break;
    case 2:
        *x = v * v * s->x[0] + 2 * u * v * s->x[1] + u * u * s->x[2];
        *y = v * v * s->y[0] + 2 * u * v * s->y[1] + u * u * s->y[2];
        break;
    default:
        *x = v * v * v * s->x[0] + 3 * u * v * v * s->x[1] + 3 * u * u * v * s->x[2] +
             u * u * u * s->x[3];
        *y = v * v * v * s->y[0] + 3 * u * v * v * s->y[1] + 3 * u * u * v * s->y[2] +
             u * u * u * s->y[3];
    }
}

static outline_seg random_seg(rng *r, uint32_t degree)
{
    outline_seg s;
    memset(&s, 0, sizeof s);
    s.degree = degree;
    for (uint32_t i = 0; i <= degree; i++) {
        s.x[i] = uniform_in(r, -2, 2);
        s.y[i] = uniform_in(r, -2, 2);
    }
    return s;
}

/* A line through a point sampled on the curve crosses the curve there:
 * one of the crossings is at t = 0 (the point), unless the line is nearly
 * tangent to the curve. */
static void test_crossing_at_sampled_points(void **state)
{
    (void)state;
    rng r = {7};
    long tried = 0, found = 0, skipped = 0;
    double worst = 0;
    for (uint32_t degree = 1; degree <= 3; degree++) {
        for (int k = 0; k < 20000; k++) {
            outline_seg s = random_seg(&r, degree);
            double u = uniform_in(&r, 0.01, 0.99), px, py;
            bezier(&s, u, &px, &py);
            double a = uniform_in(&r, 0, 6.283185307179586);
            double d[2] = {cos(a), sin(a)}, o[2] = {px - 3 * d[0], py - 3 * d[1]};
            /* skip near-tangent lines: the crossing is ill-conditioned */
            double h = 1e-6, x0, y0, x1, y1;
            bezier(&s, u - h, &x0, &y0);
            bezier(&s, u + h, &x1, &y1);
            double tx = (x1 - x0) / (2 * h), ty = (y1 - y0) / (2 * h);
            double sine = fabs(tx * d[1] - ty * d[0]) / (hypot(tx, ty) + 1e-300);
            if (sine < 0.05) {
                skipped++;
                continue;
            }
            tried++;
            double t[3];
            int dw[3];
            uint32_t n = prim_outline_cross(&s, o, d, t, dw, NULL);
            assert_true(n <= degree);
            double best = INFINITY;
            for (uint32_t i = 0; i < n; i++)
                best = fmin(best, fabs(t[i] - 3));
            if (best < 1e-9)
                found++;
            else
                worst = fmax(worst, best);
        }
    }
    print_message("crossings at sampled points: %ld lines, %ld found within 1e-9, worst "
                  "miss %g, %ld near-tangent skipped\n",
                  tried, found, worst, skipped);
    assert_int_equal(found, tried);
}

/* The number of crossings and their signs agree with the sign changes of
 * the signed distance sampled densely along the curve. */
static void test_crossing_counts(void **state)
{
    (void)state;
    rng r = {11};
    long lines = 0, agree = 0, crossings = 0;
    for (uint32_t degree = 1; degree <= 3; degree++) {
        for (int k = 0; k < 5000; k++) {
            outline_seg s = random_seg(&r, degree);
            double a = uniform_in(&r, 0, 6.283185307179586);
            double d[2] = {cos(a), sin(a)};
            double o[2] = {uniform_in(&r, -1, 1), uniform_in(&r, -1, 1)};
            int sum = 0, changes = 0;
            double prev = 0;
            for (int i = 0; i <= 4000; i++) {
                double x, y;
                bezier(&s, i / 4000.0, &x, &y);
                double f = -d[1] * (x - o[0]) + d[0] * (y - o[1]);
                if (i > 0 && (f >= 0) != (prev >= 0)) {
                    changes++;
                    sum += prev >= 0 ? 1 : -1;
                }
                prev = f;
            }
            double t[3];
            int dw[3];
            uint32_t n = prim_outline_cross(&s, o, d, t, dw, NULL);
            int total = 0;
            for (uint32_t i = 0; i < n; i++)
                total += dw[i];
            lines++;
            crossings += n;
            /* two crossings closer than the sampling step can hide from the
             * sampling, never the net winding change */
            assert_int_equal(total, sum);
            if ((int)n == changes)
                agree++;
        }
    }
    print_message("crossing counts: %ld lines, %ld crossings, %ld counts equal to the "
                  "sampled sign changes\n",
                  lines, crossings, agree);
    assert_true(agree >= lines - lines / 500);
}

/* A random closed contour of k segments of mixed degree around the origin
 * (a star-shaped loop, possibly self-intersecting where the control points
 * wander), wound either way. */
static uint32_t random_contour(rng *r, outline_seg *out, uint32_t k, double cx, double cy,
                               double radius, int clockwise)
{
    double px[16], py[16];
    for (uint32_t i = 0; i < k; i++) {
        double a = 6.283185307179586 * (i + uniform_in(r, 0, 0.5)) / k;
        if (clockwise)
            a = -a;
        double rr = radius * uniform_in(r, 0.6, 1.0);
        px[i] = cx + rr * cos(a);
        py[i] = cy + rr * sin(a);
    }
    for (uint32_t i = 0; i < k; i++) {
        outline_seg *s = &out[i];
        memset(s, 0, sizeof *s);
        s->degree = 1 + (uint32_t)(uniform(r) * 3);
        uint32_t j = (i + 1) % k;
        s->x[0] = px[i];
        s->y[0] = py[i];
        s->x[s->degree] = px[j];
        s->y[s->degree] = py[j];
        for (uint32_t m = 1; m < s->degree; m++) {
            double u = (double)m / s->degree;
            s->x[m] = px[i] + u * (px[j] - px[i]) + uniform_in(r, -0.4, 0.4) * radius;
            s->y[m] = py[i] + u * (py[j] - py[i]) + uniform_in(r, -0.4, 0.4) * radius;
        }
    }
    return k;
}

static int span_inside(const span *v, uint32_t n, double t, double tol, int *near)
{
    for (uint32_t i = 0; i < n; i++) {
        if (fabs(t - v[i].in.t) < tol || fabs(t - v[i].out.t) < tol)
            *near = 1;
        if (t >= v[i].in.t && t <= v[i].out.t)
            return 1;
    }
    return 0;
}

/* Spans agree with membership along random rays (all directions, some
 * vertical and some horizontal), on random outlines with holes and
 * overlaps; entries face the ray, exits face away. */
static void test_spans_match_inside(void **state)
{
    (void)state;
    rng r = {23};
    long rays = 0, samples = 0, near = 0, disagreements = 0, spans = 0, bad_normals = 0;
    for (int shape = 0; shape < 60; shape++) {
        csg_builder *b = csg_builder_new();
        assert_non_null(b);
        outline_seg segs[64];
        uint32_t n = 0;
        n += random_contour(&r, segs + n, 6 + shape % 8, 0, 0, 2, shape % 2);
        n += random_contour(&r, segs + n, 5, 0.2, 0.1, 0.7, !(shape % 2));   /* a hole */
        n += random_contour(&r, segs + n, 4, 2.0, 0.5, 1.2, shape % 3 == 0); /* overlap */
        const prim_outline *o = prim_outline_create(b, segs, n, -0.5, 1.0);
        assert_non_null(o);
        prim p;
        memset(&p, 0, sizeof p);
        p.kind = PRIM_OUTLINE;
        p.u.outline.outline = o;
        uint32_t cap = prim_max_spans(&p);
        for (int k = 0; k < 400; k++) {
            vec3 org =
                v3(uniform_in(&r, -4, 5), uniform_in(&r, -4, 4), uniform_in(&r, -2, 3));
            vec3 dir =
                v3(uniform_in(&r, -1, 1), uniform_in(&r, -1, 1), uniform_in(&r, -1, 1));
            if (k % 10 == 0)
                dir = v3(0, 0, k % 20 ? 1 : -1);
            if (k % 10 == 1)
                dir.z = 0, org.z = uniform_in(&r, -0.4, 0.9);
            span v[PRIM_OUTLINE_MAX_SPANS];
            uint32_t m = prim_spans(&p, 0, org, dir, v, cap);
            rays++;
            spans += m;
            for (uint32_t i = 0; i < m; i++) {
                assert_true(v[i].in.t <= v[i].out.t);
                if (i > 0)
                    assert_true(v[i - 1].out.t <= v[i].in.t);
                vec3 qi = v3_madd(org, dir, v[i].in.t),
                     qo = v3_madd(org, dir, v[i].out.t);
                if (v[i].out.t - v[i].in.t > 1e-9) {
                    if (v3_dot(prim_normal(&p, qi, v[i].in.part), dir) > 0)
                        bad_normals++;
                    if (v3_dot(prim_normal(&p, qo, v[i].out.part), dir) < 0)
                        bad_normals++;
                }
            }
            for (int j = 0; j < 200; j++) {
                double t = uniform_in(&r, -6, 6);
                int close = 0;
                int a = span_inside(v, m, t, 1e-7, &close);
                int bq = prim_inside(&p, v3_madd(org, dir, t));
                samples++;
                if (close) {
                    near++;
                    continue;
                }
                if (a != bq)
                    disagreements++;
            }
        }
        csg_builder_free(b);
    }
    print_message("outline spans: %ld rays, %ld spans, %ld samples (%ld within 1e-7 of "
                  "an end), %ld disagreements, %ld normals facing the wrong way\n",
                  rays, spans, samples, near, disagreements, bad_normals);
    assert_int_equal(disagreements, 0);
    assert_int_equal(bad_normals, 0);
}

/* A unit square as four lines and a disc-like loop of quadratics: the
 * exact spans along axis rays, the caps' parts, tight bounds. */
static void test_known_shapes(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    outline_seg sq[4];
    double xs[5] = {0, 1, 1, 0, 0}, ys[5] = {0, 0, 1, 1, 0};
    for (int i = 0; i < 4; i++) {
        memset(&sq[i], 0, sizeof sq[i]);
        sq[i].degree = 1;
        sq[i].x[0] = xs[i];
        sq[i].y[0] = ys[i];
        sq[i].x[1] = xs[i + 1];
        sq[i].y[1] = ys[i + 1];
    }
    prim p;
    memset(&p, 0, sizeof p);
    p.kind = PRIM_OUTLINE;
    p.u.outline.outline = prim_outline_create(b, sq, 4, 0, 2);
    span v[8];
    /* along +x at y = 0.5, z = 1: enters at x = 0, leaves at x = 1 */
    uint32_t n = prim_spans(&p, 3, v3(-1, 0.5, 1), v3(2, 0, 0), v, 8);
    assert_int_equal(n, 1);
    assert_true(fabs(v[0].in.t - 0.5) < 1e-15 && fabs(v[0].out.t - 1.0) < 1e-15);
    assert_int_equal(v[0].in.leaf, 3);
    vec3 ni = prim_normal(&p, v3(0, 0.5, 1), v[0].in.part);
    assert_true(ni.x < 0 && fabs(ni.y) < 1e-12);
    /* through a vertex diagonally: one span, no spurious double count */
    n = prim_spans(&p, 0, v3(-1, -1, 1), v3(1, 1, 0), v, 8);
    assert_int_equal(n, 1);
    assert_true(fabs(v[0].in.t - 1) < 1e-15 && fabs(v[0].out.t - 2) < 1e-15);
    /* along an edge (y = 0): the closed region's boundary */
    n = prim_spans(&p, 0, v3(-1, 1, 1), v3(1, 0, 0), v, 8);
    assert_true(n <= 1);
    /* down the z axis through the inside: the caps */
    n = prim_spans(&p, 0, v3(0.5, 0.5, 5), v3(0, 0, -1), v, 8);
    assert_int_equal(n, 1);
    assert_int_equal(v[0].in.part, PRIM_OUTLINE_PART_TOP);
    assert_int_equal(v[0].out.part, PRIM_OUTLINE_PART_BOTTOM);
    assert_true(fabs(v[0].in.t - 3) < 1e-15 && fabs(v[0].out.t - 5) < 1e-15);
    /* a quadratic bulge: the square's top edge replaced by a curve
     * through (0.5, 1.5) (control point at (0.5, 2)) */
    outline_seg bulge[4];
    memcpy(bulge, sq, sizeof bulge);
    bulge[2].degree = 2;
    bulge[2].x[2] = 0;
    bulge[2].y[2] = 1;
    bulge[2].x[1] = 0.5;
    bulge[2].y[1] = 2;
    p.u.outline.outline = prim_outline_create(b, bulge, 4, 0, 2);
    n = prim_spans(&p, 0, v3(0.5, 5, 1), v3(0, -1, 0), v, 8);
    assert_int_equal(n, 1);
    assert_true(fabs(v[0].in.t - 3.5) < 1e-12 && fabs(v[0].out.t - 5) < 1e-12);
    bbox bb = prim_bounds(&p);
    assert_true(fabs(bb.hi.y - 1.5) < 1e-15); /* tight, not the control point's 2 */
    assert_true(bb.lo.x == 0 && bb.hi.x == 1 && bb.lo.z == 0 && bb.hi.z == 2);
    csg_builder_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crossing_at_sampled_points),
        cmocka_unit_test(test_crossing_counts),
        cmocka_unit_test(test_spans_match_inside),
        cmocka_unit_test(test_known_shapes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
