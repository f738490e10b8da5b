/* Tests of src/csg/csg.c through csg_builder and the three queries.
 *
 * 1. Coincident faces. difference() { cube(10); cube([10, 10, 5]); } and
 *    two cubes sharing a face, whose exact solids are boxes, under the
 *    identity and under rotations by non-axis angles (with a mirror and a
 *    non-uniform scale): grids of rays through the shared faces from many
 *    directions, including rays lying in the coincident planes, must give
 *    the box's span (no slivers, no speckles), and the first hit must lie on
 *    the box face that the ray enters.
 * 2. The property test. Seeded random trees (every primitive kind built,
 *    the torus, clipped quadrics, implicit surfaces, triangle meshes,
 *    outlines, solids of revolution and extrusions with several spans per
 *    ray among them, boolean depth 4, random affine maps with mirrors and
 *    non-uniform scales composed down the tree) and random rays through
 *    their bounds: every span list is sorted, disjoint and finite, agrees
 *    with an oracle of membership that shares no code with the leaves'
 *    spans (the generator's own tree, and for meshes, outlines, revolves
 *    and extrusions winding numbers from angles, see "independent
 *    membership") except within a tolerance of a span end, sampled along
 *    the ray where the answer puts them (inside each span, in each gap,
 *    just beyond every end; csg_inside must agree with the oracle there
 *    too) and where it does not: at random, on an even grid, and beside
 *    and between every leaf's own crossings, so that a span the answer
 *    misses is found however thin; csg_first_hit / csg_any_hit agree with
 *    the span list.
 *    Every fifth tree is wide (unions and differences of 8 or more
 *    operands), so the BVHs built for those are part of the test.
 * 3. Bounds culling. Every ray of (2) is also evaluated by brute force
 *    (every leaf, no boxes, no clipping of the operands) and the two span
 *    lists must be identical; rays that miss the root's box yield nothing.
 * 4. A buffer given to the builder becomes its leaves' array.
 */
#define _DEFAULT_SOURCE /* getrusage */

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

#include "csg/csg.h"
#include "csg/prim_extrusion.h"
#include "csg/prim_mesh.h"
#include "csg/prim_outline.h"
#include "csg/prim_revolve.h"
#include "implicit/expr.h"
#include "implicit/solve.h"
#include "test_faults.h"

static const double PI = 3.14159265358979323846;

static const float white[4] = {1, 1, 1, 1};
static const sc_location no_loc = {NULL, 0, 0};

/* ---- random numbers (xorshift64*, seeded per test) ---- */

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t next_u64(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1DULL;
}

static double uniform(rng *r)
{
    return (double)(next_u64(r) >> 11) * 0x1p-53;
}

static double uniform_in(rng *r, double lo, double hi)
{
    return lo + (hi - lo) * uniform(r);
}

static uint32_t below(rng *r, uint32_t n)
{
    return (uint32_t)(next_u64(r) % n);
}

static vec3 unit_vector(rng *r)
{
    for (;;) {
        vec3 v = v3(uniform_in(r, -1, 1), uniform_in(r, -1, 1), uniform_in(r, -1, 1));
        double l = v3_dot(v, v);
        if (l > 1e-4 && l <= 1)
            return v3_scale(v, 1 / sqrt(l));
    }
}

/* ---- affine maps ---- */

/* Rotation by angle about the unit axis (Rodrigues). */
static affine rotation(vec3 axis, double angle)
{
    vec3 k = v3_normalize(axis);
    double c = cos(angle), s = sin(angle), u = 1 - c;
    affine a = {
        {{c + k.x * k.x * u, k.x * k.y * u - k.z * s, k.x * k.z * u + k.y * s, 0},
         {k.y * k.x * u + k.z * s, c + k.y * k.y * u, k.y * k.z * u - k.x * s, 0},
         {k.z * k.x * u - k.y * s, k.z * k.y * u + k.x * s, c + k.z * k.z * u, 0}}};
    return a;
}

static affine scaling(vec3 s)
{
    affine a = {{{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}}};
    return a;
}

static affine translation(vec3 t)
{
    affine a = affine_identity();
    a.m[0][3] = t.x;
    a.m[1][3] = t.y;
    a.m[2][3] = t.z;
    return a;
}

/* translate * rotate * scale, scale per axis in [0.2, 5] (log-uniform) with
 * a random sign, so mirrors and strong non-uniform scales are common. */
static affine random_affine(rng *r)
{
    vec3 s;
    double *sv = &s.x;
    for (int k = 0; k < 3; k++) {
        sv[k] = exp(uniform_in(r, log(0.2), log(5.0)));
        if (next_u64(r) & 1)
            sv[k] = -sv[k];
    }
    affine rs = scaling(s);
    affine rot = rotation(unit_vector(r), uniform_in(r, 0, 2 * PI));
    affine tr =
        translation(v3(uniform_in(r, -1, 1), uniform_in(r, -1, 1), uniform_in(r, -1, 1)));
    affine a = affine_mul(&rot, &rs);
    return affine_mul(&tr, &a);
}

/* ---- span list checks shared by the tests ---- */

static int list_is_well_formed(const csg_tree *t, const csg_ray *ray, span_list s)
{
    for (uint32_t i = 0; i < s.n; i++) {
        const span *v = &s.v[i];
        if (!isfinite(v->in.t) || !isfinite(v->out.t) || !(v->in.t <= v->out.t))
            return 0;
        if (v->in.t < ray->tmin || v->out.t > ray->tmax)
            return 0;
        if (i > 0 && !(s.v[i - 1].out.t < v->in.t))
            return 0;
        const span_end *ends[2] = {&v->in, &v->out};
        for (int k = 0; k < 2; k++) {
            if (ends[k]->leaf == SPAN_NO_LEAF) {
                /* Only a clipped end refers to no surface. */
                if (ends[k]->t != ray->tmin && ends[k]->t != ray->tmax)
                    return 0;
            } else if (ends[k]->leaf >= t->leaf_count) {
                return 0;
            }
        }
    }
    return 1;
}

/* csg_first_hit must report the first span end at or after tmin that lies
 * on a surface, and csg_any_hit whether there is one. */
static int first_hit_agrees(const csg_tree *t, const csg_ray *ray, span_list s,
                            arena *scratch)
{
    const span_end *want = NULL;
    int exiting = 0;
    if (s.n > 0) {
        if (s.v[0].in.leaf != SPAN_NO_LEAF) {
            want = &s.v[0].in;
        } else if (s.v[0].out.leaf != SPAN_NO_LEAF) {
            want = &s.v[0].out;
            exiting = 1;
        }
    }
    csg_hit hit;
    int got = csg_first_hit(t, ray, scratch, &hit);
    if (got != (want != NULL) || csg_any_hit(t, ray, scratch) != got)
        return 0;
    if (!got)
        return 1;
    if (hit.t != want->t || hit.leaf != want->leaf || hit.part != want->part ||
        hit.flip != want->flip || hit.exiting != exiting)
        return 0;
    vec3 n = csg_hit_normal(t, ray, &hit);
    return v3_is_finite(n) && fabs(v3_length(n) - 1) < 1e-12;
}

/* ---- 1. coincident faces ---- */

typedef struct box_scene {
    const char *name;
    csg_tree *tree;
    bbox exact;      /* the solid, a box, in model coordinates */
    bbox leaves[2];  /* the two cubes, in model coordinates */
    affine to_world; /* model to world */
    int map;         /* index of to_world in the test's list */
} box_scene;

static uint32_t add_box(csg_builder *b, vec3 lo, vec3 hi, const affine *to_world)
{
    prim p = {.kind = PRIM_BOX};
    p.u.box.lo = lo;
    p.u.box.hi = hi;
    uint32_t id = csg_builder_leaf(b, &p, to_world, white, no_loc);
    assert_int_not_equal(id, CSG_EMPTY);
    return id;
}

static csg_tree *finish(csg_builder *b, uint32_t root)
{
    csg_tree *t = NULL;
    sc_error err;
    assert_int_equal(csg_builder_finish(b, root, &t, &err), SC_OK);
    assert_non_null(t);
    return t;
}

/* tree's leaf counts (t->leaf_counts: kinds and materials, counted as the
 * builder made the leaves) against a walk over its leaves. */
static void check_leaf_counts(const csg_tree *t)
{
    assert_true(t->leaf_counts);
    uint32_t kinds[PRIM_KIND_COUNT] = {0};
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        kinds[t->leaves[i].prim.kind]++;
        assert_true(t->leaves[i].material < t->material_slots);
    }
    for (int k = 0; k < PRIM_KIND_COUNT; k++)
        assert_int_equal(t->kind_leaves[k], kinds[k]);
    for (uint32_t m = 0; m < t->material_slots; m++) {
        uint32_t n = 0;
        for (uint32_t i = 0; i < t->leaf_count; i++)
            n += t->leaves[i].material == m;
        assert_int_equal(t->material_leaves[m], n);
    }
}

/* A sphere leaf of radius r at c, with material m. */
static uint32_t add_sphere_in(csg_builder *b, vec3 c, double r, uint32_t m)
{
    prim p = {.kind = PRIM_SPHERE};
    p.u.sphere.r = r;
    affine w = affine_identity();
    w.m[0][3] = c.x;
    w.m[1][3] = c.y;
    w.m[2][3] = c.z;
    uint32_t id = csg_builder_leaf(b, &p, &w, white, no_loc);
    assert_int_not_equal(id, CSG_EMPTY);
    csg_builder_set_material(b, id, m);
    return id;
}

/* The counts statistics read instead of every leaf (sc_scene_get_info):
 * every leaf kept in order (the builder's counts, a material set twice);
 * leaves the compile drops (a subtrahend whose box misses, an
 * intersection of disjoint boxes), so the kept ones are copied and
 * counted; and a material index past those counted, where no counts are
 * kept and statistics read the leaves. */
static void test_leaf_counts(void **state)
{
    (void)state;
    affine id = affine_identity();
    for (int drop = 0; drop < 2; drop++) {
        csg_builder *b = csg_builder_new();
        uint32_t kids[6], n = 0;
        kids[n++] = add_box(b, v3(0, 0, 0), v3(1, 1, 1), &id);
        kids[n++] = add_sphere_in(b, v3(3, 0, 0), 1, 2);
        kids[n++] = add_sphere_in(b, v3(6, 0, 0), 1, 5);
        csg_builder_set_material(b, kids[1], 3); /* counted once, as 3 */
        if (drop) {
            uint32_t cut[2] = {add_sphere_in(b, v3(9, 0, 0), 1, 1),
                               add_box(b, v3(50, 50, 50), v3(51, 51, 51), &id)};
            kids[n++] = csg_builder_op(b, CSG_DIFFERENCE, cut, 2);
            uint32_t apart[2] = {add_box(b, v3(0, 5, 0), v3(1, 6, 1), &id),
                                 add_sphere_in(b, v3(20, 5, 0), 1, 4)};
            kids[n++] = csg_builder_op(b, CSG_INTERSECTION, apart, 2);
        }
        csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, n));
        check_leaf_counts(t);
        assert_int_equal(t->leaf_count, drop ? 4 : 3);
        assert_int_equal(t->kind_leaves[PRIM_SPHERE], drop ? 3 : 2);
        assert_int_equal(t->material_leaves[3], 1);
        assert_int_equal(t->material_leaves[2], 0);
        csg_tree_free(t);
    }
    csg_builder *b = csg_builder_new();
    uint32_t kids[2] = {add_box(b, v3(0, 0, 0), v3(1, 1, 1), &id),
                        add_sphere_in(b, v3(3, 0, 0), 1, UINT32_MAX - 1)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, 2));
    assert_false(t->leaf_counts);
    csg_tree_free(t);
}

/* The scenes, under the model-to-world map m:
 *   0 difference() { cube(10); cube([10, 10, 5]); }       -> [0,10]^2 x [5,10]
 *   1 the same with the subtrahend written as
 *     scale([1, 1, 0.5]) cube(10) (a different map, so its faces coincide
 *     with the first cube's only up to rounding)            -> [0,10]^2 x [5,10]
 *   2 union() { cube(10); translate([10, 0, 0]) cube(10); } -> [0,20] x [0,10]^2 */
static box_scene make_box_scene(int which, const affine *m)
{
    box_scene s = {0};
    s.to_world = *m;
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    vec3 zero = v3(0, 0, 0), ten = v3(10, 10, 10);
    uint32_t kids[2];
    kids[0] = add_box(b, zero, ten, m);
    if (which == 0) {
        s.name = "difference, same map";
        kids[1] = add_box(b, zero, v3(10, 10, 5), m);
        s.tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
        s.exact = (bbox){v3(0, 0, 5), ten};
        s.leaves[1] = (bbox){zero, v3(10, 10, 5)};
    } else if (which == 1) {
        s.name = "difference, scaled subtrahend";
        affine half = scaling(v3(1, 1, 0.5));
        affine mb = affine_mul(m, &half);
        kids[1] = add_box(b, zero, ten, &mb);
        s.tree = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
        s.exact = (bbox){v3(0, 0, 5), ten};
        s.leaves[1] = (bbox){zero, v3(10, 10, 5)};
    } else {
        s.name = "union sharing a face";
        affine shift = translation(v3(10, 0, 0));
        affine mb = affine_mul(m, &shift);
        kids[1] = add_box(b, zero, ten, &mb);
        s.tree = finish(b, csg_builder_op(b, CSG_UNION, kids, 2));
        s.exact = (bbox){zero, v3(20, 10, 10)};
        s.leaves[1] = (bbox){v3(10, 0, 0), v3(20, 10, 10)};
    }
    s.leaves[0] = (bbox){zero, ten};
    return s;
}

/* The exact span of the model-space ray o + t d (|d| = 1) in the box, and
 * whether the ray is a graze: lying within tol of the plane of a face it is
 * parallel to, or meeting the box in no more than tol. A graze may give the
 * span or nothing. *face is the entered face (box part numbering). */
static int exact_box_span(const bbox *b, vec3 o, vec3 d, double tol, double *t0,
                          double *t1, int *face, int *graze)
{
    const double *po = &o.x, *pd = &d.x, *lo = &b->lo.x, *hi = &b->hi.x;
    double a = -INFINITY, z = INFINITY;
    *graze = 0;
    *face = -1;
    for (int k = 0; k < 3; k++) {
        if (fabs(pd[k]) < 1e-12) {
            if (fabs(po[k] - lo[k]) <= tol || fabs(po[k] - hi[k]) <= tol)
                *graze = 1;
            if (po[k] < lo[k] || po[k] > hi[k])
                return 0;
            continue;
        }
        double ta = (lo[k] - po[k]) / pd[k], tb = (hi[k] - po[k]) / pd[k];
        double tn = fmin(ta, tb), tf = fmax(ta, tb);
        if (tn > a) {
            a = tn;
            *face = 2 * k + (pd[k] > 0 ? 0 : 1);
        }
        z = fmin(z, tf);
    }
    if (z - a <= 1e-6) /* a corner or an edge: a point, or a sliver eps removes */
        *graze = 1;
    if (!(a <= z))
        return 0;
    *t0 = a;
    *t1 = z;
    return 1;
}

/* Whether the model point p on the entered face lies within tol of an edge
 * of the solid or of one of its two cubes. There two faces meet and either
 * may be reported: where the ray enters the union through the edge that a
 * cube's face shares with the seam plane x = 10, the cube on the far side
 * enters through that edge and its tie between two slabs decides which face
 * it names (the other cube's span there has length zero and is gone), so
 * the seam face may be named even though the union's surface there is the
 * other one. Only rays that meet the edge exactly see this. */
static int near_edge(const box_scene *s, vec3 p, int face, double tol)
{
    const bbox *boxes[3] = {&s->exact, &s->leaves[0], &s->leaves[1]};
    for (int k = 0; k < 3; k++) {
        if (k == face / 2)
            continue;
        double x = v3_get(p, k);
        for (int i = 0; i < 3; i++) {
            if (fabs(x - v3_get(boxes[i]->lo, k)) <= tol ||
                fabs(x - v3_get(boxes[i]->hi, k)) <= tol)
                return 1;
        }
    }
    return 0;
}

typedef struct coincident_stats {
    long rays, grazes, seams, seam_cracks, spans, failures;
} coincident_stats;

static void shoot_box_scene(const box_scene *s, vec3 target, vec3 dir, arena *scratch,
                            coincident_stats *st)
{
    const double tol = 1e-9; /* model units: 1e-10 of the scene's size */
    vec3 d = v3_normalize(dir);
    vec3 o = v3_madd(target, d, -40);
    csg_ray ray = {affine_point(&s->to_world, o), affine_vector(&s->to_world, d), 0,
                   INFINITY};
    double e0 = 0, e1 = 0;
    int face, graze;
    int want = exact_box_span(&s->exact, o, d, tol, &e0, &e1, &face, &graze);
    span_list got;
    assert_true(csg_spans(s->tree, &ray, scratch, &got));
    assert_true(list_is_well_formed(s->tree, &ray, got));
    assert_true(first_hit_agrees(s->tree, &ray, got, scratch));
    /* A ray in the plane of a cube's face inside the solid (the seam
     * x = 10 of the union, the plane z = 5 where the subtrahend's top meets
     * the remaining solid's bottom is a face, not a seam). Under the
     * identity it lies exactly in that plane in both cubes' frames and must
     * give the whole span. Under any other map each cube's frame holds its
     * own rounding of it, about 1e-16 of the scene's size to either side,
     * and where the two roundings fall on the outer sides of the seam the
     * ray misses both cubes: a crack as wide as the rounding, which no
     * tolerance along the ray can close. Such rays are counted and checked
     * like grazes. */
    int seam = 0;
    for (int k = 0; k < 3; k++) {
        double dk = v3_get(d, k), ok_ = v3_get(o, k);
        for (int i = 0; i < 2 && fabs(dk) < 1e-12; i++) {
            double planes[2] = {v3_get(s->leaves[i].lo, k), v3_get(s->leaves[i].hi, k)};
            for (int j = 0; j < 2; j++) {
                if (fabs(ok_ - planes[j]) <= tol && ok_ > v3_get(s->exact.lo, k) + tol &&
                    ok_ < v3_get(s->exact.hi, k) - tol)
                    seam = 1;
            }
        }
    }
    int loose = graze || (seam && s->map != 0);
    st->rays++;
    st->grazes += graze;
    st->seams += seam;
    st->spans += got.n;
    int ok = 1;
    if (loose) {
        /* The ray lies within rounding of a face plane: its rounded copy in
         * each leaf's frame may cross that plane anywhere, so any part of
         * the exact span may show, but nothing outside it. */
        for (uint32_t i = 0; ok && i < got.n; i++)
            ok = want && got.v[i].in.t >= e0 - tol && got.v[i].out.t <= e1 + tol;
        if (seam && !graze && got.n != 1)
            st->seam_cracks++;
    } else {
        ok = (int)got.n == want;
        if (ok && got.n == 1)
            ok = fabs(got.v[0].in.t - e0) <= tol && fabs(got.v[0].out.t - e1) <= tol;
    }
    if (ok && got.n == 1 && !loose && !near_edge(s, v3_madd(o, d, e0), face, tol)) {
        /* The first hit is on the entered face: its world normal is the
         * face's model normal carried to the world. */
        csg_hit hit;
        assert_true(csg_first_hit(s->tree, &ray, scratch, &hit));
        vec3 n = csg_hit_normal(s->tree, &ray, &hit);
        vec3 fn = v3(0, 0, 0);
        double sign = (face & 1) ? 1 : -1;
        if (face / 2 == 0)
            fn.x = sign;
        else if (face / 2 == 1)
            fn.y = sign;
        else
            fn.z = sign;
        affine to_model;
        assert_true(affine_invert(&s->to_world, &to_model));
        vec3 wn = v3_normalize(affine_vector_transposed(&to_model, fn));
        ok = v3_length(v3_sub(n, wn)) < 1e-9;
        if (!ok && st->failures < 10)
            print_error(
                "normal (%g %g %g) (leaf %u part %u flip %u), expected (%g %g %g) "
                "face %d\n",
                n.x, n.y, n.z, hit.leaf, hit.part, hit.flip, wn.x, wn.y, wn.z, face);
    }
    if (!ok && ++st->failures <= 10) {
        print_error(
            "%s (map %d): ray through (%.17g %.17g %.17g) along (%.17g %.17g %.17g): "
            "expected %d span [%.17g, %.17g]%s, got %u",
            s->name, s->map, target.x, target.y, target.z, d.x, d.y, d.z, want, e0, e1,
            graze ? " (graze)" : "", got.n);
        for (uint32_t i = 0; i < got.n; i++)
            print_error(" [%.17g, %.17g]", got.v[i].in.t, got.v[i].out.t);
        print_error("\n");
    }
    arena_reset(scratch);
}

/* Directions: along each axis both ways, in each coordinate plane, and
 * oblique. With the grids below, the axis and in-plane directions put rays
 * exactly in the coincident planes and along the shared edges. */
static const double directions[][3] = {
    {1, 0, 0},    {-1, 0, 0},   {0, 1, 0},       {0, -1, 0},     {0, 0, 1},
    {0, 0, -1},   {1, 1, 0},    {1, -2, 0},      {0, 1, 1},      {0, -1, 3},
    {1, 0, 1},    {-2, 0, 1},   {0.3, -0.2, 1},  {1, 0.7, -0.4}, {-0.6, 0.8, 0.1},
    {-1, -1, -1}, {1, 1e-3, 0}, {0.05, 1, -0.02}};

static void test_coincident_faces(void **state)
{
    (void)state;
    affine maps[4];
    maps[0] = affine_identity();
    {
        affine r = rotation(v3(1, 2, 3), 0.7), t = translation(v3(3, -2, 1));
        maps[1] = affine_mul(&t, &r);
    }
    {
        /* A mirror and a non-uniform scale under a rotation by 2.1 rad. */
        affine r = rotation(v3(-2, 1, 0.5), 2.1), s = scaling(v3(-1.5, 2, 0.7));
        affine t = translation(v3(-40, 25, 7));
        affine rs = affine_mul(&r, &s);
        maps[2] = affine_mul(&t, &rs);
    }
    {
        affine r = rotation(v3(0.3, -0.1, 1), PI / 7), s = scaling(v3(0.01, 0.01, 0.01));
        maps[3] = affine_mul(&r, &s);
    }
    arena scratch;
    arena_init(&scratch, 0);
    coincident_stats st = {0};
    for (int which = 0; which < 3; which++) {
        for (int mi = 0; mi < 4; mi++) {
            box_scene s = make_box_scene(which, &maps[mi]);
            s.map = mi;
            for (size_t di = 0; di < sizeof directions / sizeof directions[0]; di++) {
                vec3 dir = v3(directions[di][0], directions[di][1], directions[di][2]);
                /* A grid over the coincident faces, edges included: for the
                 * differences the plane z = 5 and the side faces x = 0,
                 * x = 10 below it; for the union the plane x = 10. */
                for (int i = 0; i <= 8; i++) {
                    for (int j = 0; j <= 8; j++) {
                        double u = 1.25 * i, v = 1.25 * j, w = 0.625 * j;
                        if (which < 2) {
                            shoot_box_scene(&s, v3(u, v, 5), dir, &scratch, &st);
                            shoot_box_scene(&s, v3(0, u, w), dir, &scratch, &st);
                            shoot_box_scene(&s, v3(10, u, w), dir, &scratch, &st);
                            shoot_box_scene(&s, v3(u, 0, w), dir, &scratch, &st);
                        } else {
                            shoot_box_scene(&s, v3(10, u, v), dir, &scratch, &st);
                            shoot_box_scene(&s, v3(10 + 0.5 * u, u, 10), dir, &scratch,
                                            &st);
                        }
                    }
                }
            }
            csg_tree_free(s.tree);
        }
    }
    arena_free(&scratch);
    print_message("coincident faces: %ld rays (%ld grazing a face, %ld in a seam plane, "
                  "%ld of those cracked by rounding), %ld spans, %ld failures\n",
                  st.rays, st.grazes, st.seams, st.seam_cracks, st.spans, st.failures);
    assert_int_equal(st.failures, 0);
}

/* ---- 2 and 3. random trees ---- */

enum { TREE_LEVELS = 4 };

/* Closed paths of a 2D polygon set: path k is the points start[k] ..
 * start[k + 1] - 1 of xy (2 numbers each). */
typedef struct poly2 {
    const double *xy;
    const uint32_t *start;
    uint32_t paths;
} poly2;

/* One step of an extrusion's region as the generator wrote it (postfix). */
typedef struct region_item {
    prim_region_op op;
    double inv[2][2], c[2], r; /* ellipse: |inv (p - c)| <= r */
    poly2 poly;                /* polygon set, read even-odd */
} region_item;

/* What the generator knows about a leaf, kept apart from what the library
 * made of it, so the property test's membership oracle can be independent
 * of the code under test (see "independent membership"). The arrays are
 * in the tree's memory. */
typedef struct oracle_leaf {
    prim p;          /* as built: its kind, and prim_inside for the simple kinds */
    affine to_local; /* inverse of the map the generator composed */
    bbox box;        /* local bounds, from the generator's own numbers */
    /* mesh: triangles of three indices into pts, wound outward */
    const vec3 *pts;
    const uint32_t *tris;
    uint32_t tri_count;
    /* outline: closed contours, nonzero rule, z0 <= z <= z1 */
    const outline_seg *segs;
    uint32_t seg_count;
    double z0, z1; /* outline and extrusion slab */
    /* revolve: (r, z) regions, each an even-odd polygon set, and discs
     * (rc, zc, a); a wedge of sweep radians from phi0 when partial */
    const poly2 *regions;
    uint32_t region_count;
    const double *discs;
    uint32_t disc_count;
    int partial;
    double phi0, sweep;
    /* extrusion: the region's postfix program */
    const region_item *items;
    uint32_t item_count;
} oracle_leaf;

/* The tree as generated, before the builder simplifies or compiles it. */
typedef struct oracle_node {
    csg_op op;
    uint32_t leaf;         /* CSG_LEAF: index into gen.oleaves */
    uint32_t first, count; /* others: children gen.okids[first ..] */
} oracle_node;

/* Generous for the largest tree random_wide makes: 31 level-2 subtrees of
 * at most 9 leaves and 4 boolean nodes each, and 15 subtracted leaves. */
enum { ORACLE_LEAVES = 512, ORACLE_NODES = 1024 };

typedef struct gen {
    rng r;
    csg_builder *b;
    uint32_t kinds_used; /* bit per prim_kind, of the leaves actually built */
    uint32_t leaves;
    oracle_leaf *oleaves; /* ORACLE_LEAVES */
    oracle_node *onodes;  /* ORACLE_NODES */
    uint32_t *okids;      /* ORACLE_NODES */
    uint32_t oleaf_count, onode_count, okid_count;
} gen;

/* A node id from the builder and the same node in the generator's tree. */
typedef struct made {
    uint32_t id, node;
} made;

/* Memory that lives as long as the tree. */
static void *tree_alloc(gen *g, size_t size)
{
    void *m = csg_builder_alloc(g->b, size);
    assert_non_null(m);
    return m;
}

static void add_plane(plane *p, vec3 n, vec3 through)
{
    p->n = n;
    p->d = v3_dot(n, through);
}

/* A random convex polyhedron: a random tetrahedron, an octahedron with
 * random face offsets, or a box clipped by random planes. */
static int random_convex(gen *g, prim *p)
{
    plane *planes = csg_builder_alloc(g->b, 10 * sizeof(plane));
    assert_non_null(planes);
    uint32_t flavour = below(&g->r, 3), count = 0;
    bbox bounds = bbox_empty();
    if (flavour == 0) {
        vec3 v[4];
        for (;;) {
            for (int i = 0; i < 4; i++)
                v[i] = v3(uniform_in(&g->r, -1.5, 1.5), uniform_in(&g->r, -1.5, 1.5),
                          uniform_in(&g->r, -1.5, 1.5));
            vec3 e1 = v3_sub(v[1], v[0]), e2 = v3_sub(v[2], v[0]),
                 e3 = v3_sub(v[3], v[0]);
            if (fabs(v3_dot(v3_cross(e1, e2), e3)) > 0.5)
                break;
        }
        static const int face[4][4] = {
            {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
        for (int f = 0; f < 4; f++) {
            vec3 a = v[face[f][0]], b = v[face[f][1]], c = v[face[f][2]];
            vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
            if (v3_dot(n, v3_sub(v[face[f][3]], a)) > 0)
                n = v3_neg(n);
            add_plane(&planes[count++], n, a);
        }
        for (int i = 0; i < 4; i++)
            bounds = bbox_add_point(bounds, v[i]);
    } else if (flavour == 1) {
        for (int i = 0; i < 8; i++) {
            vec3 n = v3(i & 1 ? -1 : 1, i & 2 ? -1 : 1, i & 4 ? -1 : 1);
            planes[count].n = n;
            planes[count++].d = uniform_in(&g->r, 0.6, 1.4);
        }
        /* Every point satisfies |x| + |y| + |z| <= max d. */
        double m = 0;
        for (uint32_t i = 0; i < count; i++)
            m = fmax(m, planes[i].d);
        bounds = (bbox){v3(-m, -m, -m), v3(m, m, m)};
    } else {
        vec3 h = v3(uniform_in(&g->r, 0.4, 1.5), uniform_in(&g->r, 0.4, 1.5),
                    uniform_in(&g->r, 0.4, 1.5));
        const double *hv = &h.x;
        for (int k = 0; k < 3; k++) {
            vec3 n = v3(k == 0, k == 1, k == 2);
            planes[count].n = n;
            planes[count++].d = hv[k];
            planes[count].n = v3_neg(n);
            planes[count++].d = hv[k];
        }
        for (int i = 0; i < 4; i++) {
            vec3 n = v3_scale(unit_vector(&g->r), uniform_in(&g->r, 0.5, 3));
            planes[count].n = n;
            planes[count++].d = v3_length(n) * uniform_in(&g->r, 0.2, 1.0);
        }
        bounds = (bbox){v3_neg(h), h};
    }
    p->kind = PRIM_CONVEX;
    p->u.convex.planes = planes;
    p->u.convex.count = count;
    p->u.convex.bounds = bounds;
    return 1;
}

/* A random closed mesh, non-convex: a sphere with a random radius at each
 * vertex (star-shaped), or a torus of triangles (two spans along many
 * rays). */
static void random_mesh(gen *g, prim *p, oracle_leaf *ol)
{
    enum { RINGS = 7, SEGMENTS = 9 };
    vec3 pts[RINGS * SEGMENTS + 2];
    uint32_t tris[3 * 2 * RINGS * SEGMENTS], np = 0, nt = 0;
#define TRI(a, b, c)                                                                     \
    do {                                                                                 \
        tris[3 * nt] = (a);                                                              \
        tris[3 * nt + 1] = (b);                                                          \
        tris[3 * nt + 2] = (c);                                                          \
        nt++;                                                                            \
    } while (0)
    const double pi = 3.14159265358979323846;
    if (below(&g->r, 2)) {
        double big = uniform_in(&g->r, 0.7, 1.3),
               small = big * uniform_in(&g->r, 0.2, 0.6);
        for (uint32_t i = 0; i < RINGS; i++)
            for (uint32_t j = 0; j < SEGMENTS; j++) {
                double u = 2 * pi * j / SEGMENTS, v = 2 * pi * i / RINGS;
                double w = big + small * cos(v);
                pts[np++] = v3(w * cos(u), w * sin(u), small * sin(v));
            }
        for (uint32_t i = 0; i < RINGS; i++)
            for (uint32_t j = 0; j < SEGMENTS; j++) {
                uint32_t a = i * SEGMENTS + j, b = i * SEGMENTS + (j + 1) % SEGMENTS;
                uint32_t c = ((i + 1) % RINGS) * SEGMENTS + (j + 1) % SEGMENTS,
                         d = ((i + 1) % RINGS) * SEGMENTS + j;
                TRI(a, c, d);
                TRI(a, b, c);
            }
    } else {
        pts[np++] = v3(0, 0, -uniform_in(&g->r, 0.5, 1.5));
        for (uint32_t i = 1; i < RINGS; i++)
            for (uint32_t j = 0; j < SEGMENTS; j++) {
                double th = pi * i / RINGS - pi / 2, ph = 2 * pi * j / SEGMENTS;
                double r = uniform_in(&g->r, 0.5, 1.5);
                pts[np++] = v3(r * cos(th) * cos(ph), r * cos(th) * sin(ph), r * sin(th));
            }
        pts[np++] = v3(0, 0, uniform_in(&g->r, 0.5, 1.5));
        uint32_t top = np - 1;
        for (uint32_t j = 0; j < SEGMENTS; j++) {
            uint32_t j1 = (j + 1) % SEGMENTS;
            TRI(0, 1 + j1, 1 + j);
            TRI(top, 1 + (RINGS - 2) * SEGMENTS + j, 1 + (RINGS - 2) * SEGMENTS + j1);
            for (uint32_t i = 1; i + 1 < RINGS; i++) {
                uint32_t a = 1 + (i - 1) * SEGMENTS;
                TRI(a + j, a + j1, a + SEGMENTS + j1);
                TRI(a + j, a + SEGMENTS + j1, a + SEGMENTS + j);
            }
        }
    }
#undef TRI
    p->kind = PRIM_MESH;
    p->u.mesh.mesh = prim_mesh_create(g->b, pts, tris, nt);
    assert_non_null(p->u.mesh.mesh);
    vec3 *own_pts = tree_alloc(g, np * sizeof *own_pts);
    uint32_t *own_tris = tree_alloc(g, 3 * nt * sizeof *own_tris);
    memcpy(own_pts, pts, np * sizeof *own_pts);
    memcpy(own_tris, tris, 3 * nt * sizeof *own_tris);
    ol->pts = own_pts;
    ol->tris = own_tris;
    ol->tri_count = nt;
    ol->box = bbox_empty();
    for (uint32_t i = 0; i < np; i++)
        ol->box = bbox_add_point(ol->box, pts[i]);
}

/* An outline prism: a star-shaped loop of lines and quadratic and cubic
 * curves (possibly crossing itself) with a loop wound the other way
 * inside it, between random heights. */
static void random_outline(gen *g, prim *p, oracle_leaf *ol)
{
    outline_seg segs[16];
    uint32_t n = 0;
    for (int loop = 0; loop < 2; loop++) {
        uint32_t k = loop ? 3 : 5 + below(&g->r, 5), first = n;
        double radius = loop ? 0.4 : 1.4, sign = loop ? -1 : 1;
        for (uint32_t i = 0; i < k; i++) {
            double a = sign * 6.283185307179586 * (i + uniform_in(&g->r, 0, 0.4)) / k;
            double rr = radius * uniform_in(&g->r, 0.6, 1.0);
            memset(&segs[n + i], 0, sizeof segs[n + i]);
            segs[n + i].x[0] = rr * cos(a);
            segs[n + i].y[0] = rr * sin(a);
        }
        for (uint32_t i = 0; i < k; i++) {
            outline_seg *s = &segs[n + i];
            const outline_seg *next = &segs[first + (i + 1) % k];
            s->degree = 1 + below(&g->r, 3);
            s->x[s->degree] = next->x[0];
            s->y[s->degree] = next->y[0];
            for (uint32_t m = 1; m < s->degree; m++) {
                double u = (double)m / s->degree;
                s->x[m] = s->x[0] + u * (next->x[0] - s->x[0]) +
                          uniform_in(&g->r, -0.3, 0.3) * radius;
                s->y[m] = s->y[0] + u * (next->y[0] - s->y[0]) +
                          uniform_in(&g->r, -0.3, 0.3) * radius;
            }
        }
        n += k;
    }
    ol->z0 = -uniform_in(&g->r, 0.2, 1.5);
    ol->z1 = uniform_in(&g->r, 0.2, 1.5);
    p->kind = PRIM_OUTLINE;
    p->u.outline.outline = prim_outline_create(g->b, segs, n, ol->z0, ol->z1);
    assert_non_null(p->u.outline.outline);
    outline_seg *own = tree_alloc(g, n * sizeof *own);
    memcpy(own, segs, n * sizeof *own);
    ol->segs = own;
    ol->seg_count = n;
    /* A Bezier curve lies in the hull of its control points. */
    ol->box = bbox_empty();
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t m = 0; m <= segs[i].degree; m++) {
            ol->box = bbox_add_point(ol->box, v3(segs[i].x[m], segs[i].y[m], ol->z0));
            ol->box = bbox_add_point(ol->box, v3(segs[i].x[m], segs[i].y[m], ol->z1));
        }
}

/* k points (2 numbers each) of a star-shaped loop about (cx, cy), at radii
 * from 0.6 to 1 of `radius` and jittered angles, counter-clockwise when
 * sign > 0. Consecutive angles differ by less than pi, so the loop is
 * simple. */
static void star(gen *g, double *xy, uint32_t k, double cx, double cy, double radius,
                 double sign)
{
    for (uint32_t i = 0; i < k; i++) {
        double a = sign * 2 * PI * (i + uniform_in(&g->r, 0, 0.4)) / k;
        double rr = radius * uniform_in(&g->r, 0.6, 1.0);
        xy[2 * i] = cx + rr * cos(a);
        xy[2 * i + 1] = cy + rr * sin(a);
    }
}

/* A solid of revolution: one or two regions of the (r, z) half-plane, each
 * a star-shaped polygon (with a loop wound the other way about the same
 * centre half the time, read even-odd with it; vertices left of the axis
 * are moved onto it, so profiles touch the axis along an edge) or a disc
 * (a horn torus a quarter of the time), revolved through a full turn or,
 * half the time, a wedge of 20 to 340 degrees. */
static void random_revolve(gen *g, prim *p, oracle_leaf *ol)
{
    enum { MAX_POINTS = 2 * 8 };
    uint32_t region_count = 1 + below(&g->r, 2);
    prim_revolve *rev = tree_alloc(g, sizeof *rev);
    prim_revolve_edge *edges = tree_alloc(g, region_count * MAX_POINTS * sizeof *edges);
    prim_revolve_disc *discs = tree_alloc(g, region_count * sizeof *discs);
    poly2 *regions = tree_alloc(g, region_count * sizeof *regions);
    double *own_discs = tree_alloc(g, 3 * region_count * sizeof *own_discs);
    memset(rev, 0, sizeof *rev);
    rev->edges = edges;
    rev->discs = discs;
    rev->region_count = region_count;
    double r_lo = INFINITY, r_hi = -INFINITY, z_lo = INFINITY, z_hi = -INFINITY;
    uint32_t polygons = 0;
    for (uint32_t k = 0; k < region_count; k++) {
        double rc = uniform_in(&g->r, 0.3, 1.2), zc = uniform_in(&g->r, -0.6, 0.6);
        if (below(&g->r, 3) == 0) {
            double a = below(&g->r, 4) == 0 ? rc : rc * uniform_in(&g->r, 0.2, 0.9);
            a = fmin(a, 0.7);
            discs[rev->disc_count] = (prim_revolve_disc){rc, zc, a, k};
            double *d = &own_discs[3 * rev->disc_count++];
            d[0] = rc, d[1] = zc, d[2] = a;
            r_lo = fmin(r_lo, rc - a), r_hi = fmax(r_hi, rc + a);
            z_lo = fmin(z_lo, zc - a), z_hi = fmax(z_hi, zc + a);
            continue;
        }
        uint32_t outer = 4 + below(&g->r, 5), hole = below(&g->r, 2) ? 3 : 0;
        double *xy = tree_alloc(g, 2 * (outer + hole) * sizeof *xy);
        uint32_t *start = tree_alloc(g, 3 * sizeof *start);
        double radius = uniform_in(&g->r, 0.3, 0.8);
        star(g, xy, outer, rc, zc, radius, 1);
        star(g, xy + 2 * outer, hole, rc, zc, 0.3 * radius, -1);
        start[0] = 0, start[1] = outer, start[2] = outer + hole;
        for (uint32_t i = 0; i < outer + hole; i++) {
            xy[2 * i] = fmax(0, xy[2 * i]);
            r_lo = fmin(r_lo, xy[2 * i]), r_hi = fmax(r_hi, xy[2 * i]);
            z_lo = fmin(z_lo, xy[2 * i + 1]), z_hi = fmax(z_hi, xy[2 * i + 1]);
        }
        uint32_t paths = hole ? 2 : 1;
        for (uint32_t path = 0; path < paths; path++)
            for (uint32_t i = start[path]; i < start[path + 1]; i++) {
                uint32_t j = i + 1 < start[path + 1] ? i + 1 : start[path];
                edges[rev->edge_count++] = (prim_revolve_edge){
                    xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1], k};
            }
        regions[polygons++] = (poly2){xy, start, paths};
    }
    rev->r_lo = fmax(0, r_lo), rev->r_hi = r_hi, rev->z_lo = z_lo, rev->z_hi = z_hi;
    if (below(&g->r, 2)) {
        double phi0 = uniform_in(&g->r, 0, 360), sweep = uniform_in(&g->r, 20, 340);
        rev->partial = 1;
        rev->sweep = sweep;
        rev->start[0] = cos(phi0 * PI / 180), rev->start[1] = sin(phi0 * PI / 180);
        rev->end[0] = cos((phi0 + sweep) * PI / 180);
        rev->end[1] = sin((phi0 + sweep) * PI / 180);
        ol->partial = 1;
        ol->phi0 = phi0 * PI / 180;
        ol->sweep = sweep * PI / 180;
    }
    p->kind = PRIM_REVOLVE;
    p->u.revolve.rev = rev;
    ol->regions = regions;
    ol->region_count = polygons;
    ol->discs = own_discs;
    ol->disc_count = rev->disc_count;
    ol->box = (bbox){v3(-r_hi, -r_hi, z_lo), v3(r_hi, r_hi, z_hi)};
}

/* An extrusion: a postfix program of two or three operands (star-shaped
 * polygon sets of one or two loops, possibly overlapping, and ellipses
 * under random 2D maps with mirrors) joined by random operations, between
 * random heights. */
static void random_extrusion(gen *g, prim *p, oracle_leaf *ol)
{
    prim_region region;
    memset(&region, 0, sizeof region);
    uint32_t operands = 2 + below(&g->r, 2), count = 0;
    region_item *items = tree_alloc(g, (2 * operands - 1) * sizeof *items);
    bbox box = bbox_empty();
    for (uint32_t k = 0; k < operands; k++) {
        region_item *it = &items[count++];
        memset(it, 0, sizeof *it);
        double cx = uniform_in(&g->r, -0.6, 0.6), cy = uniform_in(&g->r, -0.6, 0.6);
        int pushed = 0;
        if (below(&g->r, 2)) {
            /* A p + c with A a rotation times a scale (mirrored half the
             * time); the ellipse is the image of the disc of radius r. */
            double a = uniform_in(&g->r, 0, 2 * PI), r = uniform_in(&g->r, 0.4, 1.0);
            double sx = uniform_in(&g->r, 0.4, 1.5), sy = uniform_in(&g->r, 0.4, 1.5);
            if (below(&g->r, 2))
                sx = -sx;
            double m[2][3] = {{cos(a) * sx, -sin(a) * sy, cx},
                              {sin(a) * sx, cos(a) * sy, cy}};
            assert_true(prim_region_add_ellipse(&region, m, r, &pushed));
            double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
            it->op = PRIM_REGION_ELLIPSE;
            it->inv[0][0] = m[1][1] / det, it->inv[0][1] = -m[0][1] / det;
            it->inv[1][0] = -m[1][0] / det, it->inv[1][1] = m[0][0] / det;
            it->c[0] = cx, it->c[1] = cy, it->r = r;
            /* p = c + A u with |u| <= r: |p_x - c_x| <= r |row 0 of A|. */
            double hx = r * hypot(m[0][0], m[0][1]), hy = r * hypot(m[1][0], m[1][1]);
            box = bbox_add_point(box, v3(cx - hx, cy - hy, 0));
            box = bbox_add_point(box, v3(cx + hx, cy + hy, 0));
        } else {
            uint32_t first = 3 + below(&g->r, 6), second = below(&g->r, 2) ? 3 : 0;
            double *xy = tree_alloc(g, 2 * (first + second) * sizeof *xy);
            uint32_t *start = tree_alloc(g, 3 * sizeof *start);
            double radius = uniform_in(&g->r, 0.5, 1.3);
            star(g, xy, first, cx, cy, radius, 1);
            star(g, xy + 2 * first, second, cx + uniform_in(&g->r, -0.4, 0.4),
                 cy + uniform_in(&g->r, -0.4, 0.4), 0.5 * radius,
                 below(&g->r, 2) ? 1 : -1);
            start[0] = 0, start[1] = first, start[2] = first + second;
            uint32_t paths = second ? 2 : 1;
            assert_true(prim_region_add_polygon(&region, xy, start, paths, &pushed));
            it->op = PRIM_REGION_POLYGON;
            it->poly = (poly2){xy, start, paths};
            for (uint32_t i = 0; i < first + second; i++)
                box = bbox_add_point(box, v3(xy[2 * i], xy[2 * i + 1], 0));
        }
        assert_true(pushed);
        if (k > 0) {
            static const prim_region_op ops[3] = {
                PRIM_REGION_UNION, PRIM_REGION_INTERSECTION, PRIM_REGION_DIFFERENCE};
            prim_region_op op = ops[below(&g->r, 3)];
            assert_true(prim_region_add_op(&region, op));
            memset(&items[count], 0, sizeof items[count]);
            items[count++].op = op;
        }
    }
    ol->z0 = -uniform_in(&g->r, 0.2, 1.5);
    ol->z1 = uniform_in(&g->r, 0.2, 1.5);
    p->kind = PRIM_EXTRUSION;
    p->u.extrusion.ext = prim_extrusion_create(g->b, &region, ol->z0, ol->z1);
    assert_non_null(p->u.extrusion.ext);
    prim_region_free(&region);
    ol->items = items;
    ol->item_count = count;
    box.lo.z = ol->z0;
    box.hi.z = ol->z1;
    ol->box = box;
}

/* A leaf of the requested kind; *ol gets what the oracle needs. */
static prim random_prim(gen *g, uint32_t kind, oracle_leaf *ol)
{
    prim p = {.kind = (prim_kind)kind};
    switch (kind) {
    case PRIM_SPHERE:
        p.u.sphere.r = uniform_in(&g->r, 0.4, 1.8);
        break;
    case PRIM_BOX: {
        vec3 c = v3(uniform_in(&g->r, -0.5, 0.5), uniform_in(&g->r, -0.5, 0.5),
                    uniform_in(&g->r, -0.5, 0.5));
        vec3 h = v3(uniform_in(&g->r, 0.2, 1.5), uniform_in(&g->r, 0.2, 1.5),
                    uniform_in(&g->r, 0.2, 1.5));
        p.u.box.lo = v3_sub(c, h);
        p.u.box.hi = v3_add(c, h);
        break;
    }
    case PRIM_CYLINDER: {
        p.u.cylinder.z0 = -uniform_in(&g->r, 0.2, 1.5);
        p.u.cylinder.z1 = uniform_in(&g->r, 0.2, 1.5);
        double r0 = uniform_in(&g->r, 0.3, 1.5), r1 = uniform_in(&g->r, 0.3, 1.5);
        switch (below(&g->r, 4)) {
        case 0:
            r0 = 0; /* cone, apex at the bottom */
            break;
        case 1:
            r1 = 0; /* apex at the top */
            break;
        case 2:
            r1 = r0; /* cylinder */
            break;
        default:
            break;
        }
        p.u.cylinder.r0 = r0;
        p.u.cylinder.r1 = r1;
        break;
    }
    case PRIM_TORUS:
        p.u.torus.major = uniform_in(&g->r, 0.6, 1.5);
        p.u.torus.minor = p.u.torus.major * uniform_in(&g->r, 0.1, 0.6);
        break;
    case PRIM_QUADRIC: {
        /* a family (cone, hyperboloids, paraboloid, saddle, cylinder,
         * sphere), perturbed, in a random box about the origin */
        static const double families[6][10] = {
            {1, 1, -1, 0, 0, 0, 0, 0, 0, 0},   {1, 1, -0.5, 0, 0, 0, 0, 0, 0, -0.3},
            {1, 1, -1, 0, 0, 0, 0, 0, 0, 0.2}, {1, 2, 0, 0, 0, 0, 0, 0, -1, 0},
            {1, -1, 0, 0, 0, 0, 0, 0, -1, 0},  {2, 1, 0, 0.5, 0, 0, 0, 0, 0, -0.8}};
        const double *f = families[below(&g->r, 6)];
        prim_quadric *q = tree_alloc(g, sizeof *q);
        for (int i = 0; i < 10; i++)
            q->a[i] = f[i] + (f[i] != 0 ? uniform_in(&g->r, -0.2, 0.2) : 0);
        q->box.lo = v3(-uniform_in(&g->r, 0.4, 1.5), -uniform_in(&g->r, 0.4, 1.5),
                       -uniform_in(&g->r, 0.4, 1.5));
        q->box.hi = v3(uniform_in(&g->r, 0.4, 1.5), uniform_in(&g->r, 0.4, 1.5),
                       uniform_in(&g->r, 0.4, 1.5));
        p.u.quadric.q = q;
        break;
    }
    case PRIM_IMPLICIT: {
        /* smooth, kinked (min, max, abs), blended (smin) and periodic
         * fields, with the default method; the bytecode belongs to the
         * tree */
        static const char *const fields[5] = {
            "x*x + y*y + z*z - R*R + 0.1 * sin(4 * x) * cos(3 * y)",
            "abs(sin(2*x)*cos(2*y) + sin(2*y)*cos(2*z) + sin(2*z)*cos(2*x)) - 0.4",
            "smin(sqrt(x*x + y*y + z*z) - R, max(abs(x - 0.6), abs(y), abs(z)) - 0.3, "
            "0.2)",
            "(x*x + y*y + z*z - R*R)^3",
            "max(abs(x) + abs(y) + abs(z) - 1.2 * R, 0.3 - sqrt(x*x + y*y))"};
        const char *src = fields[below(&g->r, 5)];
        expr_program *prog = csg_builder_alloc(g->b, sizeof *prog);
        assert_non_null(prog);
        expr_param param = {"R", uniform_in(&g->r, 0.5, 1.2)};
        expr_error e;
        assert_true(expr_compile(src, strlen(src), &param, 1, prog, &e));
        double h = uniform_in(&g->r, 0.8, 1.6);
        p.u.implicit.program = prog;
        p.u.implicit.box = (bbox){v3(-h, -h, -h), v3(h, h, h)};
        p.u.implicit.tolerance = 1e-9 * h;
        p.u.implicit.method = SOLVE_INTERVAL;
        break;
    }
    case PRIM_CONVEX:
        random_convex(g, &p);
        break;
    case PRIM_MESH:
        random_mesh(g, &p, ol);
        break;
    case PRIM_REVOLVE:
        random_revolve(g, &p, ol);
        break;
    case PRIM_EXTRUSION:
        random_extrusion(g, &p, ol);
        break;
    case PRIM_OUTLINE:
        random_outline(g, &p, ol);
        break;
    default:
        fail_msg("no generator for primitive kind %u", kind);
    }
    /* Local bounds of the simple kinds, from the numbers drawn above. */
    switch (p.kind) {
    case PRIM_SPHERE: {
        double r = p.u.sphere.r;
        ol->box = (bbox){v3(-r, -r, -r), v3(r, r, r)};
        break;
    }
    case PRIM_BOX:
        ol->box = (bbox){p.u.box.lo, p.u.box.hi};
        break;
    case PRIM_CYLINDER: {
        double r = fmax(p.u.cylinder.r0, p.u.cylinder.r1);
        ol->box = (bbox){v3(-r, -r, p.u.cylinder.z0), v3(r, r, p.u.cylinder.z1)};
        break;
    }
    case PRIM_CONVEX:
        ol->box = p.u.convex.bounds;
        break;
    case PRIM_TORUS: {
        double r = p.u.torus.major + p.u.torus.minor, h = p.u.torus.minor;
        ol->box = (bbox){v3(-r, -r, -h), v3(r, r, h)};
        break;
    }
    case PRIM_QUADRIC:
        ol->box = p.u.quadric.q->box;
        break;
    case PRIM_IMPLICIT:
        ol->box = p.u.implicit.box;
        break;
    default:
        break;
    }
    ol->p = p;
    return p;
}

/* A subtree below the accumulated map parent; the first child of every
 * boolean node is itself boolean down to TREE_LEVELS, so the tree has that
 * many boolean levels. */
static uint32_t add_oracle_node(gen *g, csg_op op, uint32_t leaf, const made *kids,
                                uint32_t count)
{
    assert_true(g->onode_count < ORACLE_NODES && g->okid_count + count <= ORACLE_NODES);
    oracle_node *n = &g->onodes[g->onode_count];
    *n = (oracle_node){op, leaf, g->okid_count, count};
    for (uint32_t k = 0; k < count; k++)
        g->okids[g->okid_count++] = kids[k].node;
    return g->onode_count++;
}

static made random_node(gen *g, const affine *parent, int level)
{
    /* Every leaf gets a map of its own, half the boolean nodes one for their
     * whole subtree (OpenSCAD's nested multmatrix). */
    affine m = *parent;
    if (level == TREE_LEVELS || below(&g->r, 2)) {
        affine local = random_affine(&g->r);
        m = affine_mul(parent, &local);
    }
    if (level == TREE_LEVELS) {
        assert_true(g->oleaf_count < ORACLE_LEAVES);
        oracle_leaf *ol = &g->oleaves[g->oleaf_count];
        memset(ol, 0, sizeof *ol);
        prim p = random_prim(g, below(&g->r, PRIM_KIND_COUNT), ol);
        /* The kind built, which is what the test covers. */
        g->kinds_used |= 1u << p.kind;
        g->leaves++;
        assert_true(affine_invert(&m, &ol->to_local));
        made leaf = {csg_builder_leaf(g->b, &p, &m, white, no_loc), 0};
        assert_int_not_equal(leaf.id, CSG_EMPTY);
        leaf.node = add_oracle_node(g, CSG_LEAF, g->oleaf_count++, NULL, 0);
        return leaf;
    }
    made kids[3];
    uint32_t ids[3], count = 2 + below(&g->r, 2);
    for (uint32_t k = 0; k < count; k++) {
        kids[k] = random_node(g, &m, k == 0 || below(&g->r, 2) ? level + 1 : TREE_LEVELS);
        ids[k] = kids[k].id;
    }
    /* Intersections and differences of random shapes are often empty:
     * weight union 3, difference 2, intersection 1. */
    static const csg_op ops[6] = {CSG_UNION,      CSG_UNION,      CSG_UNION,
                                  CSG_DIFFERENCE, CSG_DIFFERENCE, CSG_INTERSECTION};
    csg_op op = ops[below(&g->r, 6)];
    made node = {csg_builder_op(g->b, op, ids, count), 0};
    assert_int_not_equal(node.id, CSG_EMPTY);
    node.node = add_oracle_node(g, op, 0, kids, count);
    return node;
}

/* A wide tree: a difference whose first operand is a union of 8 to 31
 * random subtrees and which subtracts 8 to 15 random leaves, so that both
 * get a BVH when compiled (with few set, 1 to 4, so only the union does);
 * as deep as random_node's trees. */
static made random_wide(gen *g, int few)
{
    affine id = affine_identity();
    made parts[32], cut[16];
    uint32_t part_ids[32], cut_ids[16];
    uint32_t n = 8 + below(&g->r, 24),
             m = few ? 1 + below(&g->r, 4) : 8 + below(&g->r, 8);
    for (uint32_t k = 0; k < n; k++) {
        parts[k] = random_node(g, &id, 2);
        part_ids[k] = parts[k].id;
    }
    cut[0].id = cut_ids[0] = csg_builder_op(g->b, CSG_UNION, part_ids, n);
    cut[0].node = add_oracle_node(g, CSG_UNION, 0, parts, n);
    for (uint32_t k = 1; k <= m; k++) {
        cut[k] = random_node(g, &id, TREE_LEVELS);
        cut_ids[k] = cut[k].id;
    }
    made root = {csg_builder_op(g->b, CSG_DIFFERENCE, cut_ids, m + 1), 0};
    root.node = add_oracle_node(g, CSG_DIFFERENCE, 0, cut, m + 1);
    return root;
}

/* ---- independent membership ---- */

/* The property test's truth, from the generator's own description of each
 * leaf and its own tree, not from prim_inside and csg_inside: for meshes,
 * outlines, solids of revolution and extrusions prim_inside shares its
 * crossing code with the span code under test, or could, so these decide
 * membership by predicates that count no crossings of any line:
 *   mesh        the generalised winding number, the sum of the solid
 *               angles of the triangles (Van Oosterom and Strackee) over
 *               4 pi: 1 inside a closed mesh wound outward, 0 outside;
 *   outline     the winding number as the sum of the angles the curves
 *               subtend, each curve split (de Casteljau) until the point
 *               lies outside the box of a piece's control points: a piece
 *               then lies in a half-plane through the point (the box is
 *               convex and holds the piece), so the angle it sweeps is
 *               under pi and equals the angle between its ends;
 *   polygons    (the revolve's profile in (|(x, y)|, z), an extrusion's
 *               polygon sets) the winding number as a sum of the angles
 *               the edges subtend, odd for even-odd inside;
 *   ellipses, discs and wedges  the closed-form tests.
 * The simple kinds (sphere, box, frustum, convex, torus, quadric,
 * implicit) use prim_inside, which is their closed form. Each answer is
 * 1 (in), 0 (out) or -1 (no answer: the point lies on a surface, where
 * rounding decides, or the sum is not near a whole number). The sums are
 * whole numbers up to rounding, about 1e-15 per term, so 0.25 separates
 * an answer from none with room to spare. */

static int whole_number(double w, long *n)
{
    *n = lround(w);
    return fabs(w - (double)*n) < 0.25;
}

static int mesh_member(const oracle_leaf *ol, vec3 q)
{
    double omega = 0;
    for (uint32_t i = 0; i < ol->tri_count; i++) {
        const uint32_t *tri = &ol->tris[3 * i];
        vec3 a = v3_sub(ol->pts[tri[0]], q), b = v3_sub(ol->pts[tri[1]], q),
             c = v3_sub(ol->pts[tri[2]], q);
        double la = v3_length(a), lb = v3_length(b), lc = v3_length(c);
        /* tan(omega / 2) = a . (b x c) / (la lb lc + (a . b) lc + (a . c) lb
         * + (b . c) la), positive for a triangle wound counter-clockwise
         * as seen from outside when q is inside. */
        double num = v3_dot(a, v3_cross(b, c));
        double den =
            la * lb * lc + v3_dot(a, b) * lc + v3_dot(a, c) * lb + v3_dot(b, c) * la;
        omega += 2 * atan2(num, den);
    }
    long n;
    if (!whole_number(omega / (4 * PI), &n))
        return -1;
    return n > 0;
}

/* Halves of the Bezier curve of the given degree at u = 1/2. */
static void split_curve(const double *x, const double *y, uint32_t degree, double *lx,
                        double *ly, double *rx, double *ry)
{
    double wx[4], wy[4];
    memcpy(wx, x, (degree + 1) * sizeof *wx);
    memcpy(wy, y, (degree + 1) * sizeof *wy);
    for (uint32_t level = 0; level <= degree; level++) {
        lx[level] = wx[0];
        ly[level] = wy[0];
        rx[degree - level] = wx[degree - level];
        ry[degree - level] = wy[degree - level];
        for (uint32_t m = 0; m + level < degree; m++) {
            wx[m] = 0.5 * (wx[m] + wx[m + 1]);
            wy[m] = 0.5 * (wy[m] + wy[m + 1]);
        }
    }
}

/* Adds the angle the curve sweeps about (px, py) to *angle; 0 when the
 * point is on it or closer than `depth` halvings can tell. */
static int curve_angle(const double *x, const double *y, uint32_t degree, double px,
                       double py, int depth, double *angle)
{
    double ax = x[0] - px, ay = y[0] - py, bx = x[degree] - px, by = y[degree] - py;
    double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
    double lox = INFINITY, hix = -INFINITY, loy = INFINITY, hiy = -INFINITY;
    for (uint32_t m = 0; m <= degree; m++) {
        lox = fmin(lox, x[m]), hix = fmax(hix, x[m]);
        loy = fmin(loy, y[m]), hiy = fmax(hiy, y[m]);
    }
    if (degree == 1) {
        if (cross == 0 && dot <= 0)
            return 0; /* on the segment */
    } else if (!(px < lox || px > hix || py < loy || py > hiy)) {
        double l[2][4], r[2][4];
        if (depth == 0)
            return 0;
        split_curve(x, y, degree, l[0], l[1], r[0], r[1]);
        return curve_angle(l[0], l[1], degree, px, py, depth - 1, angle) &&
               curve_angle(r[0], r[1], degree, px, py, depth - 1, angle);
    }
    *angle += atan2(cross, dot);
    return 1;
}

static int outline_member(const oracle_leaf *ol, vec3 q)
{
    if (q.z < ol->z0 || q.z > ol->z1)
        return 0;
    double angle = 0;
    for (uint32_t i = 0; i < ol->seg_count; i++) {
        const outline_seg *s = &ol->segs[i];
        /* 52 halvings bring a piece to the last bit of its coordinates. */
        if (!curve_angle(s->x, s->y, s->degree, q.x, q.y, 52, &angle))
            return -1;
    }
    long n;
    if (!whole_number(angle / (2 * PI), &n))
        return -1;
    return n != 0;
}

/* The winding number of the closed paths about (x, y), from the angles
 * their edges subtend; 0 when the point is on an edge. */
static int poly_winding(const poly2 *p, double x, double y, long *w)
{
    double angle = 0;
    for (uint32_t path = 0; path < p->paths; path++) {
        for (uint32_t i = p->start[path]; i < p->start[path + 1]; i++) {
            uint32_t j = i + 1 < p->start[path + 1] ? i + 1 : p->start[path];
            if (!curve_angle((double[]){p->xy[2 * i], p->xy[2 * j]},
                             (double[]){p->xy[2 * i + 1], p->xy[2 * j + 1]}, 1, x, y, 0,
                             &angle))
                return 0;
        }
    }
    return whole_number(angle / (2 * PI), w);
}

static int revolve_member(const oracle_leaf *ol, vec3 q)
{
    if (ol->partial) {
        double phi = fmod(atan2(q.y, q.x) - ol->phi0, 2 * PI);
        if (phi < 0)
            phi += 2 * PI;
        if (phi > ol->sweep)
            return 0;
    }
    double rho = hypot(q.x, q.y);
    for (uint32_t i = 0; i < ol->disc_count; i++) {
        const double *c = &ol->discs[3 * i];
        if ((rho - c[0]) * (rho - c[0]) + (q.z - c[1]) * (q.z - c[1]) <= c[2] * c[2])
            return 1;
    }
    int unsure = 0;
    for (uint32_t k = 0; k < ol->region_count; k++) {
        long w;
        if (!poly_winding(&ol->regions[k], rho, q.z, &w))
            unsure = 1;
        else if (w % 2 != 0)
            return 1;
    }
    return unsure ? -1 : 0;
}

/* a and b, a or b, a and not b in three values (-1: unknown). */
static int and3(int a, int b)
{
    return a == 0 || b == 0 ? 0 : a == 1 && b == 1 ? 1 : -1;
}

static int not3(int a)
{
    return a < 0 ? -1 : !a;
}

static int or3(int a, int b)
{
    return not3(and3(not3(a), not3(b)));
}

static int extrusion_member(const oracle_leaf *ol, vec3 q)
{
    if (q.z < ol->z0 || q.z > ol->z1)
        return 0;
    int stack[8], top = 0;
    for (uint32_t i = 0; i < ol->item_count; i++) {
        const region_item *it = &ol->items[i];
        if (it->op == PRIM_REGION_ELLIPSE) {
            double px = q.x - it->c[0], py = q.y - it->c[1];
            double ux = it->inv[0][0] * px + it->inv[0][1] * py,
                   uy = it->inv[1][0] * px + it->inv[1][1] * py;
            stack[top++] = ux * ux + uy * uy <= it->r * it->r;
        } else if (it->op == PRIM_REGION_POLYGON) {
            long w;
            stack[top++] = poly_winding(&it->poly, q.x, q.y, &w) ? w % 2 != 0 : -1;
        } else {
            int b = stack[--top], a = stack[top - 1];
            stack[top - 1] = it->op == PRIM_REGION_UNION          ? or3(a, b)
                             : it->op == PRIM_REGION_INTERSECTION ? and3(a, b)
                                                                  : and3(a, not3(b));
        }
    }
    return stack[0];
}

static int leaf_member(const oracle_leaf *ol, vec3 q)
{
    switch (ol->p.kind) {
    case PRIM_MESH:
        return mesh_member(ol, q);
    case PRIM_OUTLINE:
        return outline_member(ol, q);
    case PRIM_REVOLVE:
        return revolve_member(ol, q);
    case PRIM_EXTRUSION:
        return extrusion_member(ol, q);
    default:
        return prim_inside(&ol->p, q);
    }
}

/* A ray in a leaf's frame, and the stretch [t0, t1] of it in the leaf's
 * box (empty when t0 > t1): outside it the leaf is not asked. */
typedef struct leaf_ray {
    vec3 o, d;
    double t0, t1;
    /* mesh: where the ray crosses the planes of its triangles within them
     * (sorted), and the winding number's answer on each stretch between
     * (memo[i] for the stretch before cuts[i], -2 until asked) */
    double *cuts;
    uint32_t cut_count;
    signed char *memo;
} leaf_ray;

static leaf_ray to_leaf(const oracle_leaf *ol, const csg_ray *ray)
{
    leaf_ray l = {affine_point(&ol->to_local, ray->o),
                  affine_vector(&ol->to_local, ray->d),
                  -INFINITY,
                  INFINITY,
                  NULL,
                  0,
                  NULL};
    /* The box grown by 1e-9 of its size, far more than the rounding of the
     * local ray, so no point of the solid is cut off. */
    double pad = 1e-9 * v3_max_abs(bbox_extent(&ol->box));
    for (int k = 0; k < 3; k++) {
        double lo = v3_get(ol->box.lo, k) - pad, hi = v3_get(ol->box.hi, k) + pad;
        double o = v3_get(l.o, k), d = v3_get(l.d, k);
        if (d == 0) {
            if (o < lo || o > hi)
                l.t0 = INFINITY, l.t1 = -INFINITY;
            continue;
        }
        double ta = (lo - o) / d, tb = (hi - o) / d;
        l.t0 = fmax(l.t0, fmin(ta, tb));
        l.t1 = fmin(l.t1, fmax(ta, tb));
    }
    return l;
}

/* ---- surfaces to sample near ---- */

/* Ray parameters in [lo, hi]. */
typedef struct t_list {
    double *v;
    uint32_t n, cap;
    double lo, hi;
} t_list;

static void t_push(t_list *l, double t)
{
    if (!(t >= l->lo && t <= l->hi))
        return;
    assert_true(l->n < l->cap);
    l->v[l->n++] = t;
}

/* Where the ray crosses the planes of the mesh's triangles inside them
 * (with a little room at the edges: these are places to look, not
 * answers). */
static void mesh_crossings(const oracle_leaf *ol, const leaf_ray *l, t_list *out)
{
    for (uint32_t i = 0; i < ol->tri_count; i++) {
        const uint32_t *tri = &ol->tris[3 * i];
        vec3 a = ol->pts[tri[0]], b = ol->pts[tri[1]], c = ol->pts[tri[2]];
        vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
        double den = v3_dot(n, l->d);
        if (den == 0)
            continue;
        double t = v3_dot(n, v3_sub(a, l->o)) / den, slack = -1e-9 * v3_dot(n, n);
        vec3 q = v3_madd(l->o, l->d, t);
        if (v3_dot(v3_cross(v3_sub(b, a), v3_sub(q, a)), n) >= slack &&
            v3_dot(v3_cross(v3_sub(c, b), v3_sub(q, b)), n) >= slack &&
            v3_dot(v3_cross(v3_sub(a, c), v3_sub(q, c)), n) >= slack)
            t_push(out, t);
    }
}

/* Where the ray's xy line crosses a curve: pieces whose control points
 * straddle the line are halved, 40 times (a piece 1e-12 of the curve's
 * size), then crossed at their chord. */
static void curve_crossings(const double *x, const double *y, uint32_t degree,
                            const leaf_ray *l, int depth, t_list *out)
{
    double nx = -l->d.y, ny = l->d.x, f[4];
    int pos = 0, neg = 0;
    for (uint32_t m = 0; m <= degree; m++) {
        f[m] = nx * (x[m] - l->o.x) + ny * (y[m] - l->o.y);
        pos |= f[m] >= 0;
        neg |= f[m] <= 0;
    }
    if (!pos || !neg)
        return;
    if (degree == 1 || depth == 0) {
        double s = f[0] != f[degree] ? f[0] / (f[0] - f[degree]) : 0.5;
        double px = x[0] + s * (x[degree] - x[0]), py = y[0] + s * (y[degree] - y[0]);
        t_push(out, (l->d.x * (px - l->o.x) + l->d.y * (py - l->o.y)) /
                        (l->d.x * l->d.x + l->d.y * l->d.y));
        return;
    }
    double lx[4], ly[4], rx[4], ry[4];
    split_curve(x, y, degree, lx, ly, rx, ry);
    curve_crossings(lx, ly, degree, l, depth - 1, out);
    curve_crossings(rx, ry, degree, l, depth - 1, out);
}

static void poly_crossings(const poly2 *p, const leaf_ray *l, t_list *out)
{
    for (uint32_t path = 0; path < p->paths; path++) {
        for (uint32_t i = p->start[path]; i < p->start[path + 1]; i++) {
            uint32_t j = i + 1 < p->start[path + 1] ? i + 1 : p->start[path];
            double x[2] = {p->xy[2 * i], p->xy[2 * j]},
                   y[2] = {p->xy[2 * i + 1], p->xy[2 * j + 1]};
            curve_crossings(x, y, 1, l, 0, out);
        }
    }
}

static void slab_crossings(double z0, double z1, const leaf_ray *l, t_list *out)
{
    if (l->d.z != 0) {
        t_push(out, (z0 - l->o.z) / l->d.z);
        t_push(out, (z1 - l->o.z) / l->d.z);
    }
}

/* A revolved edge is a cone (a plane when level): its crossings are among
 * the roots of (r0 + k (z(t) - z0))^2 = |xy(t)|^2, k = dr / dz (the others
 * are on the mirror cone or past the edge's ends: only more places to
 * look). The wedge's faces are the planes through the axis. The discs'
 * tori are left to the leaf's own crossings and the even grid. */
static void revolve_crossings(const oracle_leaf *ol, const leaf_ray *l, t_list *out)
{
    double qa = l->d.x * l->d.x + l->d.y * l->d.y, qb = l->o.x * l->d.x + l->o.y * l->d.y,
           qc = l->o.x * l->o.x + l->o.y * l->o.y;
    for (uint32_t k = 0; k < ol->region_count; k++) {
        const poly2 *p = &ol->regions[k];
        for (uint32_t path = 0; path < p->paths; path++) {
            for (uint32_t i = p->start[path]; i < p->start[path + 1]; i++) {
                uint32_t j = i + 1 < p->start[path + 1] ? i + 1 : p->start[path];
                double r0 = p->xy[2 * i], z0 = p->xy[2 * i + 1], r1 = p->xy[2 * j],
                       z1 = p->xy[2 * j + 1];
                if (z1 == z0) {
                    slab_crossings(z0, z0, l, out);
                    continue;
                }
                double slope = (r1 - r0) / (z1 - z0);
                double alpha = r0 + slope * (l->o.z - z0), beta = slope * l->d.z;
                double a = beta * beta - qa, b = alpha * beta - qb,
                       c = alpha * alpha - qc;
                double disc = b * b - a * c;
                if (a == 0) {
                    if (b != 0)
                        t_push(out, -c / (2 * b));
                } else if (disc >= 0) {
                    t_push(out, (-b + sqrt(disc)) / a);
                    t_push(out, (-b - sqrt(disc)) / a);
                }
            }
        }
    }
    if (ol->partial) {
        double faces[2] = {ol->phi0, ol->phi0 + ol->sweep};
        for (int k = 0; k < 2; k++) {
            double nx = -sin(faces[k]), ny = cos(faces[k]);
            double den = nx * l->d.x + ny * l->d.y;
            if (den != 0)
                t_push(out, -(nx * l->o.x + ny * l->o.y) / den);
        }
    }
}

static void extrusion_crossings(const oracle_leaf *ol, const leaf_ray *l, t_list *out)
{
    slab_crossings(ol->z0, ol->z1, l, out);
    for (uint32_t i = 0; i < ol->item_count; i++) {
        const region_item *it = &ol->items[i];
        if (it->op == PRIM_REGION_POLYGON) {
            poly_crossings(&it->poly, l, out);
        } else if (it->op == PRIM_REGION_ELLIPSE) {
            /* |u0 + t du|^2 = r^2 with u = inv (p - c). */
            double px = l->o.x - it->c[0], py = l->o.y - it->c[1];
            double u0x = it->inv[0][0] * px + it->inv[0][1] * py,
                   u0y = it->inv[1][0] * px + it->inv[1][1] * py;
            double dux = it->inv[0][0] * l->d.x + it->inv[0][1] * l->d.y,
                   duy = it->inv[1][0] * l->d.x + it->inv[1][1] * l->d.y;
            double a = dux * dux + duy * duy, b = u0x * dux + u0y * duy,
                   c = u0x * u0x + u0y * u0y - it->r * it->r, disc = b * b - a * c;
            if (a > 0 && disc >= 0) {
                t_push(out, (-b + sqrt(disc)) / a);
                t_push(out, (-b - sqrt(disc)) / a);
            }
        }
    }
}

/* The crossings the oracle knows for the leaf, computed here. */
static void leaf_crossings(const oracle_leaf *ol, const leaf_ray *l, t_list *out)
{
    if (!(l->t0 <= l->t1))
        return;
    switch (ol->p.kind) {
    case PRIM_MESH:
        for (uint32_t i = 0; i < l->cut_count; i++)
            t_push(out, l->cuts[i]);
        break;
    case PRIM_OUTLINE:
        slab_crossings(ol->z0, ol->z1, l, out);
        for (uint32_t i = 0; i < ol->seg_count; i++)
            curve_crossings(ol->segs[i].x, ol->segs[i].y, ol->segs[i].degree, l, 40, out);
        break;
    case PRIM_REVOLVE:
        revolve_crossings(ol, l, out);
        break;
    case PRIM_EXTRUSION:
        extrusion_crossings(ol, l, out);
        break;
    default:
        break; /* the leaf's own spans (brute_node) give these */
    }
}

/* The ray as the generator's tree sees it: leaf k's frame and box in
 * leaves[k], and for node k a stretch [t0, t1] of the ray outside which the
 * node's solid is not (from its leaves' boxes), in nodes[k]. */
typedef struct tree_ray {
    leaf_ray *leaves;
    double (*nodes)[2];
} tree_ray;

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Fills r for the ray (memory from scratch); nodes come after their
 * children in g->onodes. */
static void tree_ray_set(const gen *g, const csg_ray *ray, arena *scratch, tree_ray *r)
{
    for (uint32_t k = 0; k < g->oleaf_count; k++) {
        const oracle_leaf *ol = &g->oleaves[k];
        leaf_ray *l = &r->leaves[k];
        *l = to_leaf(ol, ray);
        if (ol->p.kind != PRIM_MESH || !(l->t0 <= l->t1))
            continue;
        t_list cuts = {arena_alloc(scratch, ol->tri_count * sizeof(double)), 0,
                       ol->tri_count, -INFINITY, INFINITY};
        l->memo = arena_alloc(scratch, ol->tri_count + 1);
        assert_true(cuts.v && l->memo);
        mesh_crossings(ol, l, &cuts);
        qsort(cuts.v, cuts.n, sizeof *cuts.v, compare_doubles);
        memset(l->memo, -2, cuts.n + 1);
        l->cuts = cuts.v;
        l->cut_count = cuts.n;
    }
    for (uint32_t k = 0; k < g->onode_count; k++) {
        const oracle_node *n = &g->onodes[k];
        double *v = r->nodes[k];
        if (n->op == CSG_LEAF) {
            v[0] = r->leaves[n->leaf].t0;
            v[1] = r->leaves[n->leaf].t1;
            continue;
        }
        const uint32_t *kids = &g->okids[n->first];
        v[0] = r->nodes[kids[0]][0];
        v[1] = r->nodes[kids[0]][1];
        for (uint32_t c = 1; c < n->count && n->op != CSG_DIFFERENCE; c++) {
            const double *w = r->nodes[kids[c]];
            if (n->op == CSG_INTERSECTION) {
                v[0] = fmax(v[0], w[0]);
                v[1] = fmin(v[1], w[1]);
            } else if (!(v[0] <= v[1])) {
                v[0] = w[0];
                v[1] = w[1];
            } else if (w[0] <= w[1]) {
                v[0] = fmin(v[0], w[0]);
                v[1] = fmax(v[1], w[1]);
            }
        }
    }
}

/* Membership of the point at t of the generator's tree. */
static int tree_member(const gen *g, const tree_ray *r, uint32_t node, double t)
{
    const oracle_node *n = &g->onodes[node];
    if (!(t >= r->nodes[node][0] && t <= r->nodes[node][1]))
        return 0;
    if (n->op == CSG_LEAF) {
        const oracle_leaf *ol = &g->oleaves[n->leaf];
        const leaf_ray *l = &r->leaves[n->leaf];
        if (ol->p.kind != PRIM_MESH)
            return leaf_member(ol, v3_madd(l->o, l->d, t));
        /* The mesh's surface meets the ray only at l->cuts (a superset of
         * its crossings), so its membership is constant between them: the
         * winding number is asked once per stretch, at its middle, which
         * keeps it affordable at hundreds of samples a ray. */
        uint32_t lo = 0, hi = l->cut_count;
        while (lo < hi) {
            uint32_t mid = (lo + hi) / 2;
            if (l->cuts[mid] <= t)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (l->memo[lo] == -2) {
            double a = lo > 0 ? l->cuts[lo - 1] : l->t0,
                   b = lo < l->cut_count ? l->cuts[lo] : l->t1;
            l->memo[lo] =
                (signed char)mesh_member(ol, v3_madd(l->o, l->d, 0.5 * (a + b)));
        }
        return l->memo[lo];
    }
    const uint32_t *kids = &g->okids[n->first];
    int acc = tree_member(g, r, kids[0], t);
    for (uint32_t k = 1; k < n->count; k++) {
        if (n->op == CSG_UNION) {
            if (acc == 1)
                return 1;
            acc = or3(acc, tree_member(g, r, kids[k], t));
        } else {
            if (acc == 0)
                return 0;
            int b = tree_member(g, r, kids[k], t);
            acc = and3(acc, n->op == CSG_INTERSECTION ? b : not3(b));
        }
    }
    return acc;
}

/* Brute force: every leaf's spans, combined with no box tests and no
 * narrowing of the operands, then clipped as csg_spans clips. The ends of
 * every leaf's own spans go to *ends when it is not NULL. */
static span_list brute_node(const csg_tree *t, uint32_t id, vec3 o, vec3 d, double eps,
                            arena *a, t_list *ends)
{
    const csg_node *n = &t->nodes[id];
    if (n->op == CSG_LEAF) {
        const csg_leaf *l = &t->leaves[n->leaf];
        uint32_t cap = prim_max_spans(&l->prim);
        span_list r = {arena_alloc(a, cap * sizeof(span)), 0};
        assert_non_null(r.v);
        r.n = prim_spans(&l->prim, n->leaf, affine_point(&l->to_local, o),
                         affine_vector(&l->to_local, d), r.v, cap);
        for (uint32_t i = 0; ends && i < r.n; i++) {
            t_push(ends, r.v[i].in.t);
            t_push(ends, r.v[i].out.t);
        }
        r.n = span_regularize(r.v, r.n, eps);
        return r;
    }
    const uint32_t *kids = &t->child_ids[n->first_child];
    span_list acc = brute_node(t, kids[0], o, d, eps, a, ends);
    span_op op = n->op == CSG_UNION          ? SPAN_UNION
                 : n->op == CSG_INTERSECTION ? SPAN_INTERSECTION
                                             : SPAN_DIFFERENCE;
    for (uint32_t k = 1; k < n->child_count; k++) {
        int oom = 0;
        acc = span_combine(op, acc, brute_node(t, kids[k], o, d, eps, a, ends), eps, a,
                           &oom);
        assert_int_equal(oom, 0);
    }
    return acc;
}

static span_list brute_spans(const csg_tree *t, const csg_ray *ray, arena *a,
                             t_list *ends)
{
    span_list none = {NULL, 0};
    if (t->root == CSG_EMPTY)
        return none;
    span_list all =
        brute_node(t, t->root, ray->o, ray->d, csg_eps(t, ray->o, ray->d), a, ends);
    span *v = arena_alloc(a, (all.n + 1) * sizeof(span));
    assert_non_null(v);
    uint32_t n = 0;
    for (uint32_t i = 0; i < all.n; i++) {
        span s = all.v[i];
        if (s.out.t <= ray->tmin || s.in.t >= ray->tmax)
            continue;
        if (s.in.t < ray->tmin)
            s.in = (span_end){ray->tmin, SPAN_NO_LEAF, 0, 0};
        if (s.out.t > ray->tmax)
            s.out = (span_end){ray->tmax, SPAN_NO_LEAF, 0, 0};
        v[n++] = s;
    }
    span_list r = {v, n};
    return r;
}

static int same_lists(span_list a, span_list b)
{
    if (a.n != b.n)
        return 0;
    for (uint32_t i = 0; i < a.n; i++) {
        const span_end *x[2] = {&a.v[i].in, &a.v[i].out},
                       *y[2] = {&b.v[i].in, &b.v[i].out};
        for (int k = 0; k < 2; k++) {
            if (x[k]->t != y[k]->t || x[k]->leaf != y[k]->leaf ||
                x[k]->part != y[k]->part || x[k]->flip != y[k]->flip)
                return 0;
        }
    }
    return 1;
}

typedef struct property_stats {
    long trees, leaves, rays, misses, rays_with_spans, spans, samples, skipped, undecided,
        disagreements, inside_mismatches, near_surface;
    long bad_lists, bad_first_hits, culling_mismatches, bvh_nodes;
    uint32_t max_depth;
} property_stats;

/* Compares the span list at t with the generator's tree (root `root`)
 * and, when with_inside, csg_inside with
 * that tree too. Returns 1 when the span list agrees, t lies within tol of
 * a span end (where either answer is right) or the oracle has no answer
 * there. */
static int sample(const gen *g, const tree_ray *rays, uint32_t root, const csg_tree *t,
                  const csg_ray *ray, span_list s, double t_s, double tol,
                  int with_inside, property_stats *st)
{
    int in_span = 0;
    double nearest = INFINITY;
    for (uint32_t i = 0; i < s.n; i++) {
        if (t_s >= s.v[i].in.t && t_s <= s.v[i].out.t)
            in_span = 1;
        nearest = fmin(nearest, fmin(fabs(t_s - s.v[i].in.t), fabs(t_s - s.v[i].out.t)));
    }
    if (nearest <= tol) {
        st->skipped++;
        return 1;
    }
    int want = tree_member(g, rays, root, t_s);
    if (want < 0) {
        st->undecided++;
        return 1;
    }
    st->samples++;
    if (with_inside && csg_inside(t, v3_madd(ray->o, ray->d, t_s)) != want)
        st->inside_mismatches++;
    return want == in_span;
}

static void report_disagreement(const csg_tree *t, const csg_ray *ray, span_list s,
                                double t_s, int want, uint64_t seed, long tree_index)
{
    print_error("tree %ld (seed %#llx): ray o = (%.17g %.17g %.17g) d = (%.17g %.17g "
                "%.17g) [%g, %g]: at t = %.17g the oracle says %d, csg_inside %d; spans:",
                tree_index, (unsigned long long)seed, ray->o.x, ray->o.y, ray->o.z,
                ray->d.x, ray->d.y, ray->d.z, ray->tmin, ray->tmax, t_s, want,
                csg_inside(t, v3_madd(ray->o, ray->d, t_s)));
    for (uint32_t i = 0; i < s.n; i++)
        print_error(" [%.17g (leaf %u part %u), %.17g (leaf %u part %u)]", s.v[i].in.t,
                    s.v[i].in.leaf, s.v[i].in.part, s.v[i].out.t, s.v[i].out.leaf,
                    s.v[i].out.part);
    print_error("\n");
}

/* One random ray through the tree's bounds: aimed at a random point of
 * the bounds, or (more often, since random trees are sparse) at a point
 * near the centre of a random leaf. */
static csg_ray random_ray(rng *r, const csg_tree *t)
{
    const bbox *b = &t->bounds;
    vec3 ext = bbox_extent(b);
    double diag = v3_length(ext);
    vec3 target = v3(uniform_in(r, b->lo.x, b->hi.x), uniform_in(r, b->lo.y, b->hi.y),
                     uniform_in(r, b->lo.z, b->hi.z));
    if (below(r, 3) != 0) {
        const csg_leaf *l = &t->leaves[below(r, t->leaf_count)];
        bbox local = prim_bounds(&l->prim);
        vec3 c = bbox_center(&local), h = v3_scale(bbox_extent(&local), 0.3);
        vec3 p = v3(c.x + h.x * uniform_in(r, -1, 1), c.y + h.y * uniform_in(r, -1, 1),
                    c.z + h.z * uniform_in(r, -1, 1));
        affine to_world;
        if (affine_invert(&l->to_local, &to_world))
            target = affine_point(&to_world, p);
    }
    vec3 dir = unit_vector(r);
    uint32_t kind = below(r, 10);
    if (kind == 0) {
        /* along an axis: zero direction components */
        int axis = (int)below(r, 3);
        dir = v3(axis == 0, axis == 1, axis == 2);
        if (next_u64(r) & 1)
            dir = v3_neg(dir);
    } else if (kind == 1) {
        /* in a coordinate plane */
        int axis = (int)below(r, 3);
        if (axis == 0)
            dir.x = 0;
        else if (axis == 1)
            dir.y = 0;
        else
            dir.z = 0;
        dir = v3_normalize(dir);
    }
    /* Origins from inside the bounds to a few diagonals away; direction
     * lengths from 0.1 to 10. */
    vec3 o = v3_madd(target, dir, -uniform_in(r, 0, 3) * diag);
    double len = exp(uniform_in(r, log(0.1), log(10.0)));
    csg_ray ray = {o, v3_scale(dir, len), -INFINITY, INFINITY};
    return ray;
}

/* The even grid of samples along each ray: a span of more than 1/GRID of
 * the ray's stretch in the bounds holds a grid point; thinner ones are
 * found by the samples beside every leaf's crossings. */
enum { GRID = 256 };

/* Room for the leaf crossings of one ray: a wide tree has about 300
 * leaves, and a ray through the boxes of all of them meets each a few
 * times (a mesh up to 2 * 32, an outline a few dozen). */
enum { NEAR_CAP = 1 << 14 };

static void test_random_trees(void **state)
{
    (void)state;
    /* 130 rays a tree. Each ray now gets about 330 samples (the grid's
     * 256 and 3 for each of about 26 leaf crossings) instead of about 9, and
     * CI runs the test in the sanitizer build too, where a ray's spans take
     * about 1 ms and its samples about 0.45 ms: 440 rays a tree took 107 s
     * there, 130 take about 50 s on a loaded machine (and about 7 s in a
     * release build), leaving room under a minute. */
    const long tree_count = 250, rays_per_tree = 130;
    property_stats st = {0};
    arena scratch, brute;
    arena_init(&scratch, 0);
    arena_init(&brute, 0);
    uint32_t kinds = 0;
    clock_t start = clock();
    rng rays = {0x853c49e6748fea9bULL};
    oracle_leaf *oleaves = malloc(ORACLE_LEAVES * sizeof *oleaves);
    oracle_node *onodes = malloc(ORACLE_NODES * sizeof *onodes);
    uint32_t *okids = malloc(ORACLE_NODES * sizeof *okids);
    tree_ray tray = {malloc(ORACLE_LEAVES * sizeof *tray.leaves),
                     malloc(ORACLE_NODES * sizeof *tray.nodes)};
    assert_true(oleaves && onodes && okids && tray.leaves && tray.nodes);
    for (long ti = 0; ti < tree_count; ti++) {
        uint64_t seed =
            0x9e3779b97f4a7c15ULL * (uint64_t)(ti + 1) ^ 0xda942042e4dd58b5ULL;
        gen g = {{seed}, csg_builder_new(), 0, 0, oleaves, onodes, okids, 0, 0, 0};
        assert_non_null(g.b);
        affine id = affine_identity();
        /* Every fifth tree is wide, to exercise the BVHs; every other one
         * of those subtracts only a few solids from its wide union, which
         * the queries evaluate before the union (csg.c, cuts_first). */
        made root = ti % 5 == 4 ? random_wide(&g, ti % 10 == 9) : random_node(&g, &id, 0);
        csg_tree *t = finish(g.b, root.id);
        st.bvh_nodes += t->bvh_node_count;
        kinds |= g.kinds_used;
        st.trees++;
        st.leaves += g.leaves;
        if (t->source_depth > st.max_depth)
            st.max_depth = t->source_depth;
        /* The tree as generated; compiling may flatten it. */
        assert_true(t->source_depth >= TREE_LEVELS + 1);
        if (t->root == CSG_EMPTY || bbox_is_empty(&t->bounds)) {
            csg_tree_free(t);
            continue;
        }
        for (long ri = 0; ri < rays_per_tree; ri++) {
            csg_ray ray = random_ray(&rays, t);
            double dlen = v3_length(ray.d);
            /* Where the ray crosses the bounds, grown by a tenth: samples
             * are taken there. */
            bbox grown = t->bounds;
            vec3 pad = v3_scale(bbox_extent(&t->bounds), 0.1);
            grown.lo = v3_sub(grown.lo, pad);
            grown.hi = v3_add(grown.hi, pad);
            double c0 = -INFINITY, c1 = INFINITY;
            vec3 inv = v3(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z);
            if (!bbox_ray(&grown, ray.o, inv, &c0, &c1)) {
                /* Aimed at a leaf outside the solid's bounds (clipped away by
                 * an intersection or a difference): nothing to see. */
                span_list s;
                assert_true(csg_spans(t, &ray, &scratch, &s));
                assert_int_equal(s.n, 0);
                assert_true(first_hit_agrees(t, &ray, s, &scratch));
                st.rays++;
                st.misses++;
                arena_reset(&scratch);
                continue;
            }
            if (below(&rays, 2)) {
                /* A finite range inside that stretch, so ends get clipped. */
                double a = uniform_in(&rays, c0, c1), b = uniform_in(&rays, c0, c1);
                ray.tmin = fmin(a, b);
                ray.tmax = fmax(a, b);
                c0 = ray.tmin;
                c1 = ray.tmax;
            }
            /* The tolerance at span ends: 1e-7 of the scene's scale, in
             * units of t. */
            double tol = 1e-7 * t->scale / dlen;

            span_list s;
            assert_true(csg_spans(t, &ray, &scratch, &s));
            st.rays++;
            st.spans += s.n;
            st.rays_with_spans += s.n > 0;
            if (!list_is_well_formed(t, &ray, s)) {
                st.bad_lists++;
                report_disagreement(t, &ray, s, NAN, -1, seed, ti);
            }
            if (!first_hit_agrees(t, &ray, s, &scratch))
                st.bad_first_hits++;
            /* Every leaf's own crossings, from its span code and from the
             * oracle's, to sample near. */
            t_list near = {arena_alloc(&scratch, NEAR_CAP * sizeof(double)), 0, NEAR_CAP,
                           c0, c1};
            assert_non_null(near.v);
            span_list ref = brute_spans(t, &ray, &brute, &near);
            tree_ray_set(&g, &ray, &scratch, &tray);
            for (uint32_t k = 0; k < g.oleaf_count; k++)
                leaf_crossings(&g.oleaves[k], &tray.leaves[k], &near);
            if (!same_lists(s, ref)) {
                st.culling_mismatches++;
                if (st.culling_mismatches <= 3) {
                    print_error("culling changed the answer:\n");
                    report_disagreement(t, &ray, s, NAN, -1, seed, ti);
                    report_disagreement(t, &ray, ref, NAN, -1, seed, ti);
                }
            }

            /* Samples from the answer: the middle of every span and gap,
             * 2 tol inside and outside every end, and random points; at
             * these csg_inside is compared with the oracle too. */
            double ts[64];
            int nt = 0;
            double prev = c0;
            /* 6 a span, then 5 more: stop while all of them fit */
            for (uint32_t i = 0; i < s.n && nt + 6 + 5 <= 64; i++) {
                ts[nt++] = 0.5 * (prev + s.v[i].in.t);
                ts[nt++] = 0.5 * (s.v[i].in.t + s.v[i].out.t);
                ts[nt++] = s.v[i].in.t - 2 * tol;
                ts[nt++] = s.v[i].in.t + 2 * tol;
                ts[nt++] = s.v[i].out.t - 2 * tol;
                ts[nt++] = s.v[i].out.t + 2 * tol;
                prev = s.v[i].out.t;
            }
            ts[nt++] = 0.5 * (prev + c1);
            for (int k = 0; k < 4; k++)
                ts[nt++] = uniform_in(&rays, c0, c1);
            /* Samples that do not depend on the answer: an even grid over
             * [c0, c1], and 2 tol either side of every leaf surface found
             * above and midway between consecutive ones. */
            qsort(near.v, near.n, sizeof *near.v, compare_doubles);
            uint32_t total = (uint32_t)nt + GRID + 3 * near.n;
            double *all = arena_alloc(&scratch, total * sizeof *all);
            assert_non_null(all);
            memcpy(all, ts, (size_t)nt * sizeof *all);
            uint32_t na = (uint32_t)nt;
            for (int k = 0; k < GRID; k++)
                all[na++] = c0 + (c1 - c0) * (k + 0.5) / GRID;
            for (uint32_t i = 0; i < near.n; i++) {
                all[na++] = near.v[i] - 2 * tol;
                all[na++] = near.v[i] + 2 * tol;
                all[na++] = 0.5 * (near.v[i] + (i + 1 < near.n ? near.v[i + 1] : c1));
            }
            st.near_surface += near.n;
            for (uint32_t k = 0; k < na; k++) {
                if (!(all[k] >= c0 && all[k] <= c1))
                    continue;
                if (!sample(&g, &tray, root.node, t, &ray, s, all[k], tol,
                            k < (uint32_t)nt, &st)) {
                    st.disagreements++;
                    if (st.disagreements <= 5)
                        report_disagreement(t, &ray, s, all[k],
                                            tree_member(&g, &tray, root.node, all[k]),
                                            seed, ti);
                }
            }
            arena_reset(&scratch);
            arena_reset(&brute);
        }
        csg_tree_free(t);
    }
    double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    arena_free(&scratch);
    arena_free(&brute);
    free(oleaves);
    free(onodes);
    free(okids);
    free(tray.leaves);
    free(tray.nodes);
    print_message(
        "random trees: %ld trees (%ld leaves, kinds %#x of %#x, depth up to %u), "
        "%ld rays (%ld missing the bounds, %ld with spans, %ld spans, %ld leaf "
        "crossings), %ld samples (%ld within tolerance of an end, %ld on a "
        "surface to rounding), %ld disagreements, %ld csg_inside mismatches, "
        "%ld bad lists, %ld bad first hits, %ld culling mismatches, %ld BVH "
        "nodes, %.2f s\n",
        st.trees, st.leaves, kinds, (1u << PRIM_KIND_COUNT) - 1, st.max_depth, st.rays,
        st.misses, st.rays_with_spans, st.spans, st.near_surface, st.samples, st.skipped,
        st.undecided, st.disagreements, st.inside_mismatches, st.bad_lists,
        st.bad_first_hits, st.culling_mismatches, st.bvh_nodes, seconds);
    /* Every kind was built (the mask is of the leaves made, not asked for). */
    assert_int_equal(kinds, (1u << PRIM_KIND_COUNT) - 1);
    /* Only a tree whose solid is empty gets no rays. */
    assert_true(st.rays > tree_count * rays_per_tree / 2);
    assert_true(st.rays_with_spans > st.rays / 4);
    assert_int_equal(st.disagreements, 0);
    assert_int_equal(st.inside_mismatches, 0);
    assert_int_equal(st.bad_lists, 0);
    assert_int_equal(st.bad_first_hits, 0);
    assert_int_equal(st.culling_mismatches, 0);
    assert_true(st.bvh_nodes > 0);
}

/* ---- 3. bounds culling, directly ---- */

/* union() { sphere at the origin; difference() { far box; sphere } } with
 * the far part 100 units away: rays that miss the root box or the far
 * part's box give what brute force gives, and nothing at all when they miss
 * the root box. */
static void test_bounds_culling(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    prim sphere = {.kind = PRIM_SPHERE};
    sphere.u.sphere.r = 1;
    prim box = {.kind = PRIM_BOX};
    box.u.box.lo = v3(-2, -2, -2);
    box.u.box.hi = v3(2, 2, 2);
    affine id = affine_identity(), far = translation(v3(100, 0, 0));
    affine far_sphere = translation(v3(101.5, 0, 0));
    uint32_t near_id = csg_builder_leaf(b, &sphere, &id, white, no_loc);
    uint32_t diff[2] = {csg_builder_leaf(b, &box, &far, white, no_loc),
                        csg_builder_leaf(b, &sphere, &far_sphere, white, no_loc)};
    uint32_t far_id = csg_builder_op(b, CSG_DIFFERENCE, diff, 2);
    uint32_t kids[2] = {near_id, far_id};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, 2));
    /* The root box spans x in [-1, 102], y and z in [-2, 2]. */
    assert_true(t->bounds.lo.x == -1 && t->bounds.hi.x == 102);
    arena scratch, ref;
    arena_init(&scratch, 0);
    arena_init(&ref, 0);
    rng r = {0x1234567887654321ULL};
    for (int i = 0; i < 20000; i++) {
        vec3 o =
            v3(uniform_in(&r, -10, 110), uniform_in(&r, -6, 6), uniform_in(&r, -6, 6));
        vec3 d = unit_vector(&r);
        if (i % 3 == 0)
            d = v3(0, uniform_in(&r, -1, 1), uniform_in(&r, -1, 1)); /* d.x = 0 */
        csg_ray ray = {o, d, uniform_in(&r, -20, 0), uniform_in(&r, 0, 20)};
        span_list s, want = brute_spans(t, &ray, &ref, NULL);
        assert_true(csg_spans(t, &ray, &scratch, &s));
        assert_true(same_lists(s, want));
        double t0 = ray.tmin, t1 = ray.tmax;
        vec3 inv = v3(1 / d.x, 1 / d.y, 1 / d.z);
        if (!bbox_ray(&t->bounds, o, inv, &t0, &t1)) {
            assert_int_equal(s.n, 0);
            csg_hit hit;
            assert_false(csg_first_hit(t, &ray, &scratch, &hit));
            assert_false(csg_any_hit(t, &ray, &scratch));
        }
        arena_reset(&scratch);
        arena_reset(&ref);
    }
    /* Hits on each part with the other part's box missed. */
    csg_ray ray = {v3(-5, 0, 0), v3(1, 0, 0), 0, 10};
    csg_hit hit;
    assert_true(csg_first_hit(t, &ray, &scratch, &hit));
    assert_true(hit.t == 4 && hit.leaf == 0 && hit.flip == 0);
    ray = (csg_ray){v3(100, 0, 10), v3(0, 0, -1), 0, INFINITY};
    assert_true(csg_first_hit(t, &ray, &scratch, &hit));
    assert_true(hit.t == 8 && hit.leaf == 1 && hit.part == 5);
    ray = (csg_ray){v3(110, 0, 0), v3(-1, 0, 0), 0, INFINITY};
    assert_true(csg_first_hit(t, &ray, &scratch, &hit));
    /* Enters the box's +x face at x = 102, inside the subtracted sphere
     * (x from 100.5 to 102.5): the first surface is the sphere, flipped, at
     * x = 100.5. */
    assert_true(fabs(hit.t - 9.5) < 1e-12 && hit.leaf == 2 && hit.flip == 1);
    vec3 n = csg_hit_normal(t, &ray, &hit);
    assert_true(fabs(n.x - 1) < 1e-12);
    /* Missing everything: the gap between the parts. */
    ray = (csg_ray){v3(50, 0, -10), v3(0, 0, 1), 0, INFINITY};
    span_list s;
    assert_true(csg_spans(t, &ray, &scratch, &s));
    assert_int_equal(s.n, 0);
    assert_false(csg_any_hit(t, &ray, &scratch));
    arena_free(&scratch);
    arena_free(&ref);
    csg_tree_free(t);
}

/* A union of a few convex leaves with no BVH takes csg.c's flat path
 * (eval_flat_union), which must give what the general union path gives:
 * unions of 2 to 7 spheres, boxes and cylinders on a half-unit grid (so
 * faces touch and coincide), some of them intersected with or less other
 * leaves, alone and as the first operand of a
 * difference (asked for its first crossing in windows), against the
 * brute-force spans, with the first hit and any hit of each ray. */
static void test_flat_union(void **state)
{
    (void)state;
    rng r = {0x6a09e667f3bcc908ULL};
    arena scratch, ref;
    arena_init(&scratch, 0);
    arena_init(&ref, 0);
    long mismatches = 0, bad_hits = 0, with_spans = 0;
    for (int ti = 0; ti < 400; ti++) {
        csg_builder *b = csg_builder_new();
        assert_non_null(b);
        uint32_t kids[7];
        uint32_t count = 2 + below(&r, 6);
        for (uint32_t k = 0; k < count; k++) {
            prim p = {.kind = PRIM_SPHERE};
            switch (below(&r, 3)) {
            case 0:
                p.u.sphere.r = 0.5 * (1 + below(&r, 3));
                break;
            case 1:
                p.kind = PRIM_BOX;
                p.u.box.lo = v3(-0.5 * below(&r, 3), -0.5 * below(&r, 3), -0.5);
                p.u.box.hi = v3(0.5 * (1 + below(&r, 3)), 0.5, 0.5 * (1 + below(&r, 2)));
                break;
            default:
                p.kind = PRIM_CYLINDER;
                p.u.cylinder.z0 = -0.5 * below(&r, 3);
                p.u.cylinder.z1 = 0.5 * (1 + below(&r, 3));
                p.u.cylinder.r0 = 0.5 * (1 + below(&r, 2));
                p.u.cylinder.r1 = 0.5 * below(&r, 3);
                break;
            }
            affine at = translation(
                v3(0.5 * below(&r, 5), 0.5 * below(&r, 5), 0.5 * below(&r, 3)));
            kids[k] = csg_builder_leaf(b, &p, &at, white, no_loc);
            assert_int_not_equal(kids[k], CSG_EMPTY);
            if (below(&r, 3) == 0) {
                /* A boolean of leaves: the leaf cut by a sphere, or a comb
                 * (a bar less six slots: up to 7 spans, so that three
                 * outgrow the flat path's arrays). */
                prim cut = {.kind = PRIM_SPHERE};
                cut.u.sphere.r = 0.5 * (1 + below(&r, 3));
                affine cut_at =
                    translation(v3(0.5 * below(&r, 5), 0.5 * below(&r, 5), 0));
                uint32_t ops[7] = {kids[k],
                                   csg_builder_leaf(b, &cut, &cut_at, white, no_loc)};
                uint32_t n_ops = 2;
                if (below(&r, 2)) {
                    p = (prim){.kind = PRIM_BOX};
                    p.u.box.lo = v3(0, 0, 0);
                    p.u.box.hi = v3(3.5, 0.5, 0.5);
                    ops[0] = csg_builder_leaf(b, &p, &at, white, no_loc);
                    for (n_ops = 1; n_ops < 7; n_ops++) {
                        p.u.box.lo = v3(0.5 * n_ops - 0.25, -1, -1);
                        p.u.box.hi = v3(0.5 * n_ops, 1, 1);
                        ops[n_ops] = csg_builder_leaf(b, &p, &at, white, no_loc);
                    }
                }
                kids[k] = csg_builder_op(
                    b, below(&r, 2) ? CSG_DIFFERENCE : CSG_INTERSECTION, ops, n_ops);
            }
        }
        uint32_t root = csg_builder_op(b, CSG_UNION, kids, count);
        if (ti % 2) {
            prim hole = {.kind = PRIM_CYLINDER};
            hole.u.cylinder.z0 = -5;
            hole.u.cylinder.z1 = 5;
            hole.u.cylinder.r0 = hole.u.cylinder.r1 = 0.5;
            affine at = translation(v3(1, 1, 0));
            uint32_t ops[2] = {root, csg_builder_leaf(b, &hole, &at, white, no_loc)};
            root = csg_builder_op(b, CSG_DIFFERENCE, ops, 2);
        }
        csg_tree *t = finish(b, root);
        for (int ri = 0; ri < 200; ri++) {
            /* From outside or inside the solid, along a random or an axis
             * direction (rays in face planes), over a random range; d is
             * not unit length. */
            vec3 o =
                v3(uniform_in(&r, -2, 5), uniform_in(&r, -2, 5), uniform_in(&r, -2, 4));
            if (ri % 4 == 0)
                o = v3(0.5 * below(&r, 8), 0.5 * below(&r, 8), 0.5 * below(&r, 6));
            /* Most rays aim at a point where the leaves lie. */
            vec3 at = v3(uniform_in(&r, 0, 2.5), uniform_in(&r, 0, 2.5),
                         uniform_in(&r, 0, 1.5));
            vec3 d = ri % 6 == 1 ? unit_vector(&r) : v3_sub(at, o);
            if (!(v3_length(d) > 0))
                d = unit_vector(&r);
            if (ri % 3 == 0) {
                double axis[3] = {0, 0, 0};
                axis[below(&r, 3)] = below(&r, 2) ? 1 : -1;
                d = v3(axis[0], axis[1], axis[2]);
            }
            csg_ray ray = {o, d, ri % 2 ? 0 : uniform_in(&r, -3, 3), INFINITY};
            if (ri % 5 == 0)
                ray.tmax = ray.tmin + uniform_in(&r, 0, 6);
            span_list s, want = brute_spans(t, &ray, &ref, NULL);
            assert_true(csg_spans(t, &ray, &scratch, &s));
            with_spans += want.n > 0;
            mismatches += !same_lists(s, want);
            bad_hits += !first_hit_agrees(t, &ray, want, &scratch);
            arena_reset(&scratch);
            arena_reset(&ref);
        }
        csg_tree_free(t);
    }
    arena_free(&scratch);
    arena_free(&ref);
    print_message("flat unions: %ld rays with spans, %ld span mismatches, %ld bad hits\n",
                  with_spans, mismatches, bad_hits);
    assert_true(with_spans > 400 * 200 / 4);
    assert_int_equal(mismatches, 0);
    assert_int_equal(bad_hits, 0);
}

/* A ray lying in the plane of a box face, parallel to it. bbox_ray meets
 * 0 * inf = NaN at the slab of that plane; the box culling must keep the
 * ray (the closed box holds the line), or rays along the seam of
 * union() { cube(10); translate([10, 0, 0]) cube(10); } see a crack where
 * both cubes are culled. */
static void test_ray_in_face_plane(void **state)
{
    (void)state;
    bbox cube = {v3(0, 0, 0), v3(10, 10, 10)};
    double t0 = -INFINITY, t1 = INFINITY;
    assert_true(bbox_ray(&cube, v3(10, -5, 5), v3(INFINITY, 1, INFINITY), &t0, &t1));
    assert_true(t0 == 5 && t1 == 15);
    t0 = -INFINITY, t1 = INFINITY;
    assert_true(bbox_ray(&cube, v3(0, -5, 10), v3(-INFINITY, 1, -INFINITY), &t0, &t1));
    assert_true(t0 == 5 && t1 == 15);
    t0 = -INFINITY, t1 = INFINITY;
    assert_false(bbox_ray(&cube, v3(10.5, -5, 5), v3(INFINITY, 1, INFINITY), &t0, &t1));

    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    affine id = affine_identity(), shift = translation(v3(10, 0, 0));
    uint32_t kids[2] = {add_box(b, v3(0, 0, 0), v3(10, 10, 10), &id),
                        add_box(b, v3(0, 0, 0), v3(10, 10, 10), &shift)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, kids, 2));
    arena scratch;
    arena_init(&scratch, 0);
    const csg_ray rays[3] = {{v3(10, -5, 5), v3(0, 1, 0), 0, INFINITY},
                             {v3(10, 5, -5), v3(0, 0, 1), 0, INFINITY},
                             {v3(10, 15, 15), v3(0, -1, -1), 0, INFINITY}};
    for (int i = 0; i < 3; i++) {
        span_list s;
        assert_true(csg_spans(t, &rays[i], &scratch, &s));
        assert_int_equal(s.n, 1);
        assert_true(s.v[0].in.t == 5);
        assert_true(s.v[0].out.t == 15);
    }
    arena_free(&scratch);
    csg_tree_free(t);
}

/* A first-hit query on difference() { union() { box, box }; cylinder }
 * tests each leaf once, and each node's box once: a first operand as small
 * as this flat union is evaluated once, in full, and the window where the
 * first crossing lies cuts its spans (asking it first for its first
 * crossing, then again in the window, tested every box twice and merged
 * the union twice). A ray beside the hole meets one leaf, a ray through it
 * two; the hits and spans agree with brute force. */
static void test_first_hit_tests_each_leaf_once(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    affine id = affine_identity(), shift = translation(v3(20, 0, 0));
    uint32_t boxes[2] = {add_box(b, v3(0, 0, 0), v3(10, 10, 10), &id),
                         add_box(b, v3(0, 0, 0), v3(10, 10, 10), &shift)};
    prim hole = {.kind = PRIM_CYLINDER};
    hole.u.cylinder.z0 = -1;
    hole.u.cylinder.z1 = 11;
    hole.u.cylinder.r0 = hole.u.cylinder.r1 = 1;
    affine at = translation(v3(5, 5, 0));
    uint32_t kids[2] = {csg_builder_op(b, CSG_UNION, boxes, 2),
                        csg_builder_leaf(b, &hole, &at, white, no_loc)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    arena scratch, ref;
    arena_init(&scratch, 0);
    arena_init(&ref, 0);
    const struct {
        vec3 o;
        uint64_t leaves; /* distinct leaves the ray meets */
    } cases[2] = {{v3(3, -10, 5), 1}, {v3(5, -10, 5), 2}};
    for (int i = 0; i < 2; i++) {
        csg_ray ray = {cases[i].o, v3(0, 1, 0), 0, INFINITY};
        csg_counters counters = {0, 0, 0, 0, 0};
        csg_hit hit;
        assert_true(csg_first_hit_counted(t, &ray, &scratch, &counters, &hit));
        assert_true(hit.t == 10);
        assert_int_equal(hit.leaf, 0);
        if (counters.prim_tests != cases[i].leaves)
            fail_msg("ray %d: %llu primitive tests for %llu leaves", i,
                     (unsigned long long)counters.prim_tests,
                     (unsigned long long)cases[i].leaves);
        if (counters.nodes > t->node_count)
            fail_msg("ray %d: %llu node boxes tested for %u nodes", i,
                     (unsigned long long)counters.nodes, t->node_count);
        span_list s, want = brute_spans(t, &ray, &ref, NULL);
        assert_true(csg_spans(t, &ray, &scratch, &s));
        assert_true(same_lists(s, want));
        arena_reset(&scratch);
        arena_reset(&ref);
    }
    arena_free(&scratch);
    arena_free(&ref);
    csg_tree_free(t);
}

/* difference() { cube(10); a sphere of radius 3 at [12, 12, 5] }: the
 * sphere's box reaches into the cube, so a ray along x at y = 9.5, z = 5
 * meets both boxes, but it leaves the cube at x = 10 and meets the sphere
 * only from x = 12 - sqrt(2.75) on. A subtrahend beside what is left
 * changes nothing and costs no span operation: the spans are the cube's,
 * as brute force says, in every query. */
static void test_subtrahend_beside_costs_no_merge(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    affine id = affine_identity(), at = translation(v3(12, 12, 5));
    prim ball = {.kind = PRIM_SPHERE};
    ball.u.sphere.r = 3;
    uint32_t kids[2] = {add_box(b, v3(0, 0, 0), v3(10, 10, 10), &id),
                        csg_builder_leaf(b, &ball, &at, white, no_loc)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    arena scratch, ref;
    arena_init(&scratch, 0);
    arena_init(&ref, 0);
    csg_ray ray = {v3(-5, 9.5, 5), v3(1, 0, 0), 0, INFINITY};
    span_list s, want = brute_spans(t, &ray, &ref, NULL);
    assert_int_equal(want.n, 1);
    assert_true(want.v[0].in.t == 5 && want.v[0].out.t == 15);
    for (int first = 0; first < 2; first++) {
        csg_counters counters = {0, 0, 0, 0, 0};
        if (first) {
            csg_hit hit;
            assert_true(csg_first_hit_counted(t, &ray, &scratch, &counters, &hit));
            assert_true(hit.t == 5);
        } else {
            assert_true(csg_spans_counted(t, &ray, &scratch, &counters, &s));
            assert_true(same_lists(s, want));
        }
        assert_int_equal(counters.prim_tests, 2);
        if (counters.span_ops != 0)
            fail_msg("%s: %llu span operations", first ? "first hit" : "spans",
                     (unsigned long long)counters.span_ops);
    }
    arena_free(&scratch);
    arena_free(&ref);
    csg_tree_free(t);
}

/* csg_mechanical's chamfered plate: cube([60, 40, 10], center = true)
 * cut by three boxes turned 45 degrees about x, y and z, an intersection
 * of convex leaves alone, which the queries compute in place. The mark is
 * set there and not on an intersection with a torus in it, and on 2000
 * rays (through the plate, along its edges, from inside it) the spans
 * agree with brute force, and the first hit and the blocked segment with
 * the spans. */
static void test_flat_intersection(void **state)
{
    (void)state;
    for (int with_torus = 0; with_torus < 2; with_torus++) {
        csg_builder *b = csg_builder_new();
        assert_non_null(b);
        affine id = affine_identity();
        affine turn[3] = {rotation(v3(1, 0, 0), 0.7853981633974483),
                          rotation(v3(0, 1, 0), 0.7853981633974483),
                          rotation(v3(0, 0, 1), 0.7853981633974483)};
        const vec3 half[3] = {v3(50, 16.2635, 16.2635), v3(23.3345, 50, 23.3345),
                              v3(32.527, 32.527, 50)};
        uint32_t kids[4] = {add_box(b, v3(-30, -20, -5), v3(30, 20, 5), &id)};
        for (int k = 0; k < 3; k++)
            kids[k + 1] = add_box(b, v3_neg(half[k]), half[k], &turn[k]);
        if (with_torus) {
            prim ring = {.kind = PRIM_TORUS};
            ring.u.torus.major = 30;
            ring.u.torus.minor = 15;
            kids[3] = csg_builder_leaf(b, &ring, &id, white, no_loc);
        }
        csg_tree *t = finish(b, csg_builder_op(b, CSG_INTERSECTION, kids, 4));
        assert_int_equal(t->nodes[t->root].op, CSG_INTERSECTION);
        assert_int_equal(t->nodes[t->root].flat, !with_torus);
        arena scratch, ref;
        arena_init(&scratch, 0);
        arena_init(&ref, 0);
        rng r = {0x2545f4914f6cdd1dULL + (uint64_t)with_torus};
        for (int i = 0; i < 2000; i++) {
            csg_ray ray = random_ray(&r, t);
            span_list s, want = brute_spans(t, &ray, &ref, NULL);
            assert_true(csg_spans(t, &ray, &scratch, &s));
            if (!same_lists(s, want))
                fail_msg("ray %d: the spans differ from brute force", i);
            if (!first_hit_agrees(t, &ray, s, &scratch))
                fail_msg("ray %d: the first hit or the blocked segment disagrees", i);
            arena_reset(&scratch);
            arena_reset(&ref);
        }
        arena_free(&scratch);
        arena_free(&ref);
        csg_tree_free(t);
    }
}

/* Whether a segment is blocked, on a sphere of radius 1: from outside
 * through it, from inside out of it (a shadow ray from the inner face of
 * glass), from inside and staying in, and beside it. The answer is the
 * solid's surface crossing the segment, and no segment costs more than two
 * queries: one for whether the solid meets it, one for its first crossing
 * (a third, for whether the start lies inside, is not needed). */
static void test_any_hit_queries(void **state)
{
    (void)state;
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    affine id = affine_identity();
    prim ball = {.kind = PRIM_SPHERE};
    ball.u.sphere.r = 1;
    csg_tree *t = finish(b, csg_builder_leaf(b, &ball, &id, white, no_loc));
    arena scratch;
    arena_init(&scratch, 0);
    const struct {
        csg_ray ray;
        int blocked;
    } cases[4] = {{{v3(-5, 0, 0), v3(1, 0, 0), 0, 10}, 1},
                  {{v3(0, 0, 0), v3(1, 0, 0), 0, 5}, 1},
                  {{v3(0, 0, 0), v3(1, 0, 0), 0, 0.5}, 0},
                  {{v3(-5, 2, 0), v3(1, 0, 0), 0, 10}, 0}};
    for (int i = 0; i < 4; i++) {
        csg_counters counters = {0, 0, 0, 0, 0};
        assert_int_equal(csg_any_hit_counted(t, &cases[i].ray, &scratch, &counters),
                         cases[i].blocked);
        if (counters.queries > 2)
            fail_msg("segment %d: %llu queries", i, (unsigned long long)counters.queries);
        arena_reset(&scratch);
    }
    arena_free(&scratch);
    csg_tree_free(t);
}

/* A ray onto the face that a box cuts into a wide union: difference() {
 * union() { 200 overlapping spheres in a row along x }; a box over the
 * first half }. Along the row the union is one long span, so a ray that
 * leaves the box inside it starts inside the first operand: its first hit
 * is the cut face, flipped, where it leaves the box. That answer needs the
 * spheres near the face, not the whole row: the counters bound the
 * primitive tests (walking the row made it about 100). Brute force agrees
 * on every ray. */
static void test_cut_face_first_hit(void **state)
{
    (void)state;
    enum { ROW = 200 };
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    prim sphere = {.kind = PRIM_SPHERE};
    sphere.u.sphere.r = 1.2;
    uint32_t balls[ROW];
    for (uint32_t k = 0; k < ROW; k++) {
        affine m = translation(v3(2.0 * k, 0, 0));
        balls[k] = csg_builder_leaf(b, &sphere, &m, white, no_loc);
    }
    affine id = affine_identity();
    uint32_t kids[2] = {csg_builder_op(b, CSG_UNION, balls, ROW),
                        add_box(b, v3(-5, -5, -5), v3(199.5, 5, 5), &id)};
    csg_tree *t = finish(b, csg_builder_op(b, CSG_DIFFERENCE, kids, 2));
    assert_true(t->bvh_node_count > 0);
    arena scratch, ref;
    arena_init(&scratch, 0);
    arena_init(&ref, 0);
    rng r = {0xc0ffee11ULL};
    for (int i = 0; i < 200; i++) {
        /* From inside the box towards the cut face at x = 199.5. */
        vec3 o = v3(uniform_in(&r, 150, 190), uniform_in(&r, -0.3, 0.3),
                    uniform_in(&r, -0.3, 0.3));
        vec3 d =
            v3_normalize(v3(1, uniform_in(&r, -0.01, 0.01), uniform_in(&r, -0.01, 0.01)));
        csg_ray ray = {o, d, 0, INFINITY};
        csg_counters counters = {0, 0, 0, 0, 0};
        csg_hit hit;
        assert_true(csg_first_hit_counted(t, &ray, &scratch, &counters, &hit));
        assert_true(hit.flip == 1);
        assert_true(fabs(o.x + hit.t * d.x - 199.5) < 1e-9);
        if (counters.prim_tests > 24)
            fail_msg("ray %d: %llu primitive tests for a hit on the cut face", i,
                     (unsigned long long)counters.prim_tests);
        span_list s, want = brute_spans(t, &ray, &ref, NULL);
        assert_true(csg_spans(t, &ray, &scratch, &s));
        assert_true(same_lists(s, want));
        assert_true(want.n > 0 && want.v[0].in.t == hit.t);
        arena_reset(&scratch);
        arena_reset(&ref);
    }
    arena_free(&scratch);
    arena_free(&ref);
    csg_tree_free(t);
}

/* csg_eps as csg.h defines it, computed in full for every query. */
static double eps_by_definition(const csg_tree *t, vec3 o, vec3 d)
{
    vec3 center = bbox_center(&t->bounds);
    double extent = v3_max_abs(bbox_extent(&t->bounds));
    double dist = v3_length(v3_sub(o, center)), len = v3_length(d);
    return fmax(1e-9 * extent, 0x1p-40 * fmax(t->scale, dist)) / len;
}

/* csg_eps skips the distance's square root near the scene: its value must
 * stay the definition's bit for bit on both sides of the distance where
 * the distance term starts to win, and at that distance itself, for a
 * scene at the origin and one far from it. */
static void test_eps_near_and_far(void **state)
{
    (void)state;
    const vec3 places[2] = {v3(0, 0, 0), v3(1e8, -3e7, 5)};
    const vec3 dirs[3] = {v3(1, 0, 0), v3(0.3, -2, 0.7), v3(1e-3, 0, 0)};
    for (int i = 0; i < 2; i++) {
        csg_builder *b = csg_builder_new();
        assert_non_null(b);
        affine m = translation(places[i]);
        csg_tree *t = finish(b, add_box(b, v3(0, 0, 0), v3(10, 4, 6), &m));
        vec3 center = bbox_center(&t->bounds);
        double extent = v3_max_abs(bbox_extent(&t->bounds));
        /* Where 2^-40 dist reaches the larger of the other two terms. */
        double turn = 0x1p40 * fmax(1e-9 * extent, 0x1p-40 * t->scale);
        const double dists[] = {0,
                                1,
                                turn * 0.5,
                                nextafter(turn, 0),
                                turn,
                                nextafter(turn, INFINITY),
                                turn * (1 + 1e-12),
                                turn * 2,
                                1e30};
        for (size_t k = 0; k < sizeof dists / sizeof *dists; k++) {
            for (int j = 0; j < 3; j++) {
                vec3 axis = v3_normalize(v3(1, 2, -2));
                vec3 o = v3_madd(center, axis, dists[k]);
                double want = eps_by_definition(t, o, dirs[j]);
                double got = csg_eps(t, o, dirs[j]);
                if (got != want)
                    fail_msg("scene %d, distance %.17g, direction %d: csg_eps %.17g, "
                             "by definition %.17g",
                             i, dists[k], j, got, want);
            }
        }
        csg_tree_free(t);
    }
}

/* Builds a union of count boxes in a row after csg_builder_give(spare,
 * spare_size) (none when spare is NULL), checks every leaf of the tree,
 * and returns the page faults that reserving and filling the leaves took. */
static long build_row(void *spare, size_t spare_size, uint32_t count)
{
    csg_builder *b = csg_builder_new();
    assert_non_null(b);
    uint32_t *ids = malloc(count * sizeof *ids);
    assert_non_null(ids);
    memset(ids, 0, count * sizeof *ids);
    if (spare)
        csg_builder_give(b, spare, spare_size);
    long before = test_minor_faults();
    assert_int_equal(csg_builder_reserve(b, count), 1);
    for (uint32_t i = 0; i < count; i++) {
        affine at = translation(v3(2.0 * i, 0, 0));
        ids[i] = add_box(b, v3(0, 0, 0), v3(1, 1, 1), &at);
    }
    long faults = test_minor_faults() - before;
    csg_tree *t = finish(b, csg_builder_op(b, CSG_UNION, ids, count));
    free(ids);
    assert_int_equal(t->leaf_count, count);
    for (uint32_t i = 0; i < count; i++) {
        const csg_leaf *l = &t->leaves[i];
        assert_int_equal(l->prim.kind, PRIM_BOX);
        assert_true(l->to_local.m[0][3] == -2.0 * i);
        assert_int_equal(l->object_id, i);
        assert_int_equal(l->material, 0);
        assert_null(l->motion);
    }
    assert_true(t->bounds.lo.x == 0 && t->bounds.hi.x == 2.0 * count - 1);
    csg_tree_free(t);
    return faults;
}

/* A buffer given to the builder (the file's text, once parsed) becomes its
 * leaves' array, whatever it held: every leaf reads back as built, from a
 * buffer larger or smaller than the leaves, and a small one. With the C
 * library's allocator, which keeps blocks this large in mappings of their
 * own and moves them by remapping, the leaves then reuse the pages the
 * buffer has touched: with huge pages off for the count (one fault a 4 KiB
 * page), filling them faults far fewer pages than fresh memory takes.
 * The nodes fault beside them, up to their own pages, or fewer when the
 * allocator hands them memory a former tree touched (as it may, once
 * threads have built a hierarchy); so the faults a run may take are its
 * leaves' share plus all the nodes' pages, and a run with fresh leaves
 * takes at least the leaves' pages. AddressSanitizer's realloc copies, so
 * there only the leaves are checked. */
static void test_builder_takes_buffer(void **state)
{
    (void)state;
    const uint32_t count = 400000; /* 93 MB of leaves */
    size_t sizes[3] = {(size_t)count * sizeof(csg_leaf) / 2,
                       (size_t)count * sizeof(csg_leaf) * 2, 1000};
    long given[3];
    int counted = test_huge_pages_off();
    for (int k = 0; k < 3; k++) {
        unsigned char *spare = malloc(sizes[k]);
        assert_non_null(spare);
        memset(spare, 0xa5, sizes[k]); /* touched, as read text is */
        given[k] = build_row(spare, sizes[k], count);
    }
    test_huge_pages_on(counted);
    print_message("leaves in a given buffer: %ld, %ld and %ld faults (half, twice and "
                  "too small)\n",
                  given[0], given[1], given[2]);
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
    long leaf_pages = (long)((size_t)count * sizeof(csg_leaf) / 4096);
    /* the nodes csg_builder_reserve makes room for, and a page at each end */
    long node_pages =
        (long)(((size_t)count + count / 16 + 16) * sizeof(csg_node) / 4096) + 2;
    assert_true(counted);
    assert_true(given[2] >= leaf_pages); /* too small: fresh leaves */
    assert_true(given[1] * 20 < node_pages * 20 + leaf_pages); /* larger: all there */
    assert_true(given[0] * 20 <
                node_pages * 20 + leaf_pages * 11); /* smaller: half there */
#else
    (void)given;
    (void)counted;
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_coincident_faces),
        cmocka_unit_test(test_leaf_counts),
        cmocka_unit_test(test_random_trees),
        cmocka_unit_test(test_bounds_culling),
        cmocka_unit_test(test_ray_in_face_plane),
        cmocka_unit_test(test_eps_near_and_far),
        cmocka_unit_test(test_flat_union),
        cmocka_unit_test(test_cut_face_first_hit),
        cmocka_unit_test(test_first_hit_tests_each_leaf_once),
        cmocka_unit_test(test_subtrahend_beside_costs_no_merge),
        cmocka_unit_test(test_any_hit_queries),
        cmocka_unit_test(test_flat_intersection),
        cmocka_unit_test(test_builder_takes_buffer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
