/* Primitives: ray spans, normals, membership and bounds of the four convex
 * leaf shapes, in their local frame. The ray is p(t) = o + t d with d not
 * normalised; every t returned means the same point as in the world frame.
 *
 * Sphere, radius r about the origin.
 *   implicit   f(p) = p.p - r^2 <= 0
 *   ray        (d.d) t^2 + 2 (o.d) t + (o.o - r^2) = 0, i.e. a t^2 + 2 b t + c
 *              with the half coefficient b = o.d
 *   normal     grad f / 2 = p
 *
 * Box lo <= p <= hi (slabs).
 *   For each axis k with d_k != 0 the ray is inside the slab for t between
 *   (lo_k - o_k) / d_k and (hi_k - o_k) / d_k; the entry is the largest near
 *   end, the exit the smallest far end. With d_k = 0 the slab holds the
 *   whole line (lo_k <= o_k <= hi_k) or none of it.
 *   normal     the face's axis, signed: part 2k is -axis k, part 2k+1 is +k.
 *
 * Frustum along z: z0 <= z <= z1 with radius w(z) = r0 + s (z - z0),
 * s = (r1 - r0) / (z1 - z0) the slope (0: cylinder; r0 or r1 = 0: cone).
 *   implicit   side  g(p) = x^2 + y^2 - w(z)^2 <= 0, and z0 <= z <= z1
 *   ray        with w_o = w(o_z), so that w(z(t)) = w_o + s d_z t:
 *              a t^2 + 2 b t + c = 0,
 *              a = d_x^2 + d_y^2 - s^2 d_z^2
 *              b = o_x d_x + o_y d_y - s w_o d_z
 *              c = o_x^2 + o_y^2 - w_o^2
 *              caps: z(t) = z0 and z(t) = z1.
 *   normal     side: grad g / 2 = (x, y, -s w(z)); caps: -z and +z.
 *   The quadric g <= 0 alone is a double cone (w < 0 is the mirrored
 *   nappe), but inside the slab w >= 0, so slab and quadric together are the
 *   convex frustum and a ray meets it in at most one interval.
 *
 * Convex polyhedron: the halfspaces n_i . p <= d_i.
 *   ray        n_i . o + t n_i . d <= d_i. A plane with n_i . d < 0 faces
 *              the ray (front-facing): it bounds t from below at
 *              (d_i - n_i . o) / (n_i . d); one with n_i . d > 0 bounds it
 *              from above. Entry = farthest front-facing plane, exit =
 *              nearest back-facing plane. With n_i . d = 0 the ray is
 *              wholly inside the halfspace or wholly outside it.
 *   normal     n_i of the plane hit (part i).
 *
 * Every shape here is convex, so a ray yields at most one span. Membership
 * is closed (a point on the surface is inside), matching the spans, which
 * include their ends. No span holds NaN or Inf: a degenerate ray (d = 0)
 * or a computation that overflowed yields no span.
 */
#include "csg/prim.h"

#include <math.h>

#include "csg/prim_curved.h"
#include "csg/prim_extrusion.h"
#include "csg/prim_mesh.h"
#include "csg/prim_revolve.h"
#include "csg/prim_outline.h"

/* Writes the span [t_in, t_out] when it is finite and ordered; returns the
 * number of spans written (0 or 1). */
static uint32_t emit(uint32_t leaf, double t_in, uint16_t part_in, double t_out,
                     uint16_t part_out, span *out, uint32_t cap)
{
    if (cap == 0 || !isfinite(t_in) || !isfinite(t_out) || !(t_in <= t_out))
        return 0;
    out->in.t = t_in;
    out->in.leaf = leaf;
    out->in.part = part_in;
    out->in.flip = 0;
    out->out.t = t_out;
    out->out.leaf = leaf;
    out->out.part = part_out;
    out->out.flip = 0;
    return 1;
}

/* Real roots of a t^2 + 2 b t + c = 0 with a != 0, in increasing order;
 * returns 0 when there are none. The stable form: q = -(b + sign(b) sqrt(D)),
 * D = b^2 - a c, gives t = q / a and t = c / q. Adding two numbers of the
 * same sign never cancels, so both roots keep full relative accuracy even
 * when |a c| << b^2, where the textbook (-b +- sqrt(D)) / a loses the small
 * root. q = 0 only when b = 0 and D = 0, i.e. c = 0: the double root 0. */
static int solve_quadratic(double a, double b, double c, double *lo, double *hi)
{
    double disc = b * b - a * c;
    if (!(disc >= 0))
        return 0;
    double q = -(b + copysign(sqrt(disc), b));
    double r0, r1;
    if (q == 0) {
        r0 = r1 = 0;
    } else {
        r0 = q / a;
        r1 = c / q;
    }
    *lo = fmin(r0, r1);
    *hi = fmax(r0, r1);
    return 1;
}

/* t of the point of the line o + t d closest to the point c. Moving the
 * origin there before solving a quadric removes the cancellation in its
 * constant term (|o|^2 - r^2 with |o| >> r loses every digit of the answer
 * that lies below the rounding of |o|^2). The shifted origin o + tc d itself
 * carries only the rounding of one multiply-add, of the order of the error
 * already present in o, and tc is added back to every root. */
static double closest_t(vec3 o, vec3 d, vec3 c)
{
    return -v3_dot(v3_sub(o, c), d) / v3_dot(d, d);
}

/* ---- sphere ---- */

static uint32_t sphere_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                             uint32_t cap)
{
    double r = p->u.sphere.r;
    double a = v3_dot(d, d);
    double tc = closest_t(o, d, v3(0, 0, 0));
    vec3 oc = v3_madd(o, d, tc);
    double b = v3_dot(oc, d); /* ~0 after the shift, kept for what rounding left */
    /* |oc|^2 - r^2 as a product of a difference and a sum: the difference
     * |oc| - r is exact when the two are close (Sterbenz), so a ray that
     * grazes the sphere keeps the sign of its discriminant. */
    double len = v3_length(oc);
    double c = (len - r) * (len + r);
    double lo, hi;
    if (!solve_quadratic(a, b, c, &lo, &hi))
        return 0;
    return emit(leaf, tc + lo, PRIM_PART_SPHERE, tc + hi, PRIM_PART_SPHERE, out, cap);
}

/* ---- box ---- */

static uint32_t box_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                          uint32_t cap)
{
    const double *lo = &p->u.box.lo.x, *hi = &p->u.box.hi.x;
    const double *po = &o.x, *pd = &d.x;
    double t_in = -INFINITY, t_out = INFINITY;
    uint16_t part_in = 0, part_out = 1;
    for (int k = 0; k < 3; k++) {
        if (pd[k] == 0) {
            /* Parallel to the slab: the division would give Inf or NaN
             * (0/0 for an origin on a face); decide by the origin alone. */
            if (po[k] < lo[k] || po[k] > hi[k])
                return 0;
            continue;
        }
        double ta = (lo[k] - po[k]) / pd[k];
        double tb = (hi[k] - po[k]) / pd[k];
        /* d_k > 0 enters through the low face (part 2k), leaves through the
         * high face (2k+1); d_k < 0 the other way round. */
        double t_near = pd[k] > 0 ? ta : tb, t_far = pd[k] > 0 ? tb : ta;
        uint16_t near_part = (uint16_t)(2 * k + (pd[k] > 0 ? 0 : 1));
        uint16_t far_part = (uint16_t)(2 * k + (pd[k] > 0 ? 1 : 0));
        if (t_near > t_in) {
            t_in = t_near;
            part_in = near_part;
        }
        if (t_far < t_out) {
            t_out = t_far;
            part_out = far_part;
        }
    }
    return emit(leaf, t_in, part_in, t_out, part_out, out, cap);
}

/* ---- frustum ---- */

static uint32_t cylinder_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                               uint32_t cap)
{
    double z0 = p->u.cylinder.z0, z1 = p->u.cylinder.z1;
    double r0 = p->u.cylinder.r0, r1 = p->u.cylinder.r1;
    double s = (r1 - r0) / (z1 - z0);
    double tc = closest_t(o, d, v3(0, 0, 0.5 * (z0 + z1)));
    vec3 oc = v3_madd(o, d, tc);
    /* With d_z = 0 the shift leaves o_z as it was (oc.z = o.z + tc * 0), so
     * the in-slab decision below is made on the exact origin. */

    /* Slab z0 <= z <= z1; the interval is written as [t_in, t_out] with the
     * caps as parts. */
    double t_in, t_out;
    uint16_t part_in = PRIM_PART_CYL_BOTTOM, part_out = PRIM_PART_CYL_TOP;
    if (d.z == 0) {
        if (oc.z < z0 || oc.z > z1)
            return 0;
        t_in = -INFINITY;
        t_out = INFINITY;
    } else {
        double ta = (z0 - oc.z) / d.z, tb = (z1 - oc.z) / d.z;
        if (d.z > 0) {
            t_in = ta;
            t_out = tb;
        } else {
            t_in = tb;
            t_out = ta;
            part_in = PRIM_PART_CYL_TOP;
            part_out = PRIM_PART_CYL_BOTTOM;
        }
    }

    /* Side quadric. Both a and c are differences of squares, computed as a
     * product of difference and sum of the square roots: when the two sides
     * are close (a ray nearly along a generator of the cone, an origin near
     * the side) the difference of the roots is exact by Sterbenz's lemma,
     * whereas the difference of the rounded squares would keep only the
     * rounding error and could take the wrong sign. */
    double w_o = r0 + s * (oc.z - z0);
    double dxy = hypot(d.x, d.y), sdz = fabs(s * d.z);
    double oxy = hypot(oc.x, oc.y), aw = fabs(w_o);
    double a = (dxy - sdz) * (dxy + sdz);
    double b = oc.x * d.x + oc.y * d.y - s * w_o * d.z;
    double c = (oxy - aw) * (oxy + aw);

    /* The part of the line inside the quadric, g(t) = a t^2 + 2 b t + c <= 0:
     * one interval [q_in, q_out] (ends may be infinite), or, for a < 0 with
     * real roots, the two half-lines outside them. */
    double q_in = -INFINITY, q_out = INFINITY;
    if (a == 0) {
        /* The ray is parallel to a generator (or to the axis of a cylinder):
         * g is linear, 2 b t + c. */
        if (b == 0) {
            if (c > 0)
                return 0;
        } else if (b > 0) {
            q_out = -c / (2 * b);
        } else {
            q_in = -c / (2 * b);
        }
    } else {
        double lo, hi;
        int real = solve_quadratic(a, b, c, &lo, &hi);
        if (a > 0) {
            if (!real)
                return 0;
            q_in = lo;
            q_out = hi;
        } else if (real) {
            /* a < 0 only when d_z != 0, so the slab interval is finite.
             * Of the half-lines (-inf, lo] and [hi, inf) at most one meets
             * the slab in more than a point: both lie in the quadric, the
             * slab keeps only w >= 0, and the frustum is convex, so were
             * both to meet it, the gap (lo, hi) between them would lie
             * inside too. Rounding near the apex can make both meet it;
             * then that convexity argument says the whole slab interval is
             * the answer. */
            int first = lo >= t_in;   /* (-inf, lo] meets [t_in, t_out] */
            int second = hi <= t_out; /* [hi, inf) meets it */
            if (first && second) {
                /* keep the slab interval */
            } else if (first) {
                q_out = lo;
            } else if (second) {
                q_in = hi;
            } else {
                return 0;
            }
        }
        /* a < 0 without real roots: g < 0 on the whole line. */
    }
    if (q_in > t_in) {
        t_in = q_in;
        part_in = PRIM_PART_CYL_SIDE;
    }
    if (q_out < t_out) {
        t_out = q_out;
        part_out = PRIM_PART_CYL_SIDE;
    }
    return emit(leaf, tc + t_in, part_in, tc + t_out, part_out, out, cap);
}

/* ---- convex polyhedron ---- */

static uint32_t convex_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                             uint32_t cap)
{
    double t_in = -INFINITY, t_out = INFINITY;
    uint16_t part_in = 0, part_out = 0;
    for (uint32_t i = 0; i < p->u.convex.count; i++) {
        const plane *pl = &p->u.convex.planes[i];
        double nd = v3_dot(pl->n, d);
        double dist = pl->d - v3_dot(pl->n, o); /* >= 0: the origin is inside */
        if (nd == 0) {
            /* Parallel: the division would give Inf or NaN (0/0 for a ray in
             * the plane); the origin alone decides. */
            if (dist < 0)
                return 0;
            continue;
        }
        double t = dist / nd;
        if (nd < 0) {
            if (t > t_in) {
                t_in = t;
                part_in = (uint16_t)i;
            }
        } else if (t < t_out) {
            t_out = t;
            part_out = (uint16_t)i;
        }
    }
    /* An unbounded set of planes leaves an infinite end: emit refuses it. */
    return emit(leaf, t_in, part_in, t_out, part_out, out, cap);
}

/* ---- dispatch ---- */

bbox prim_bounds(const prim *p)
{
    bbox b = bbox_empty();
    switch (p->kind) {
    case PRIM_SPHERE: {
        double r = p->u.sphere.r;
        b.lo = v3(-r, -r, -r);
        b.hi = v3(r, r, r);
        break;
    }
    case PRIM_BOX:
        b.lo = p->u.box.lo;
        b.hi = p->u.box.hi;
        break;
    case PRIM_CYLINDER: {
        double r = fmax(p->u.cylinder.r0, p->u.cylinder.r1);
        b.lo = v3(-r, -r, p->u.cylinder.z0);
        b.hi = v3(r, r, p->u.cylinder.z1);
        break;
    }
    case PRIM_CONVEX:
        b = p->u.convex.bounds;
        break;
    case PRIM_TORUS:
        b = prim_torus_bounds(p);
        break;
    case PRIM_QUADRIC:
        b = p->u.quadric.q->box;
        break;
    case PRIM_IMPLICIT:
        b = p->u.implicit.box;
        break;
    case PRIM_MESH:
        b = p->u.mesh.mesh->bounds;
        break;
    case PRIM_REVOLVE:
        b = prim_revolve_bounds(p);
        break;
    case PRIM_EXTRUSION:
        b = p->u.extrusion.ext->bounds;
        break;
    case PRIM_OUTLINE:
        b = p->u.outline.outline->bounds;
        break;
    case PRIM_KIND_COUNT:
        break;
    }
    return b;
}

uint32_t prim_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out, uint32_t cap)
{
    /* A zero direction is no ray: every t names the same point. */
    if (!(v3_dot(d, d) > 0) || !v3_is_finite(o) || !v3_is_finite(d))
        return 0;
    switch (p->kind) {
    case PRIM_SPHERE:
        return sphere_spans(p, leaf, o, d, out, cap);
    case PRIM_BOX:
        return box_spans(p, leaf, o, d, out, cap);
    case PRIM_CYLINDER:
        return cylinder_spans(p, leaf, o, d, out, cap);
    case PRIM_CONVEX:
        return convex_spans(p, leaf, o, d, out, cap);
    case PRIM_TORUS:
        return prim_torus_spans(p, leaf, o, d, out, cap);
    case PRIM_QUADRIC:
        return prim_quadric_spans(p, leaf, o, d, out, cap);
    case PRIM_IMPLICIT:
        return prim_implicit_spans(p, leaf, o, d, out, cap);
    case PRIM_MESH:
        return prim_mesh_spans(p, leaf, o, d, out, cap);
    case PRIM_REVOLVE:
        return prim_revolve_spans(p, leaf, o, d, out, cap);
    case PRIM_EXTRUSION:
        return prim_extrusion_spans(p, leaf, o, d, out, cap);
    case PRIM_OUTLINE:
        return prim_outline_spans(p, leaf, o, d, out, cap);
    case PRIM_KIND_COUNT:
        break;
    }
    return 0;
}

uint32_t prim_spans_range(const prim *p, uint32_t leaf, vec3 o, vec3 d, double lo,
                          double hi, double eps, int first, span *out, uint32_t cap)
{
    if (p->kind != PRIM_MESH || !(v3_dot(d, d) > 0) || !v3_is_finite(o) ||
        !v3_is_finite(d))
        return prim_spans(p, leaf, o, d, out, cap);
    return prim_mesh_spans_range(p, leaf, o, d, lo, hi, eps, first, out, cap);
}

vec3 prim_normal(const prim *p, vec3 q, uint16_t part)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        /* At the centre (never a surface point) any direction will do. */
        return v3_dot(q, q) > 0 ? q : v3(0, 0, 1);
    case PRIM_BOX: {
        double sign = (part & 1) ? 1.0 : -1.0;
        int axis = part >> 1;
        return v3(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    }
    case PRIM_CYLINDER: {
        if (part == PRIM_PART_CYL_BOTTOM)
            return v3(0, 0, -1);
        if (part == PRIM_PART_CYL_TOP)
            return v3(0, 0, 1);
        double s =
            (p->u.cylinder.r1 - p->u.cylinder.r0) / (p->u.cylinder.z1 - p->u.cylinder.z0);
        /* (x, y, -s w(z)) with w(z) replaced by the point's own radius
         * rho = |(x, y)|: on the surface the two agree, and for a point that
         * rounding left slightly off it this stays rho (x/rho, y/rho, -s),
         * the normal of the side along that generator. */
        double rho = hypot(q.x, q.y);
        if (rho > 0)
            return v3(q.x, q.y, -s * rho);
        /* The apex of a cone (no tangent plane): point along the axis, away
         * from the solid. A point on the axis of a cylinder is no side
         * point; any radial direction will do. */
        if (s > 0)
            return v3(0, 0, -1);
        if (s < 0)
            return v3(0, 0, 1);
        return v3(1, 0, 0);
    }
    case PRIM_CONVEX:
        if (part < p->u.convex.count)
            return p->u.convex.planes[part].n;
        return v3(0, 0, 1);
    case PRIM_TORUS:
        return prim_torus_normal(p, q);
    case PRIM_QUADRIC:
        return prim_quadric_normal(p, q, part);
    case PRIM_IMPLICIT:
        return prim_implicit_normal(p, q, part);
    case PRIM_MESH:
        return prim_mesh_normal(p, q, part);
    case PRIM_REVOLVE:
        return prim_revolve_normal(p, q, part);
    case PRIM_EXTRUSION:
        return prim_extrusion_normal(p, q, part);
    case PRIM_OUTLINE:
        return prim_outline_normal(p, q, part);
    case PRIM_KIND_COUNT:
        break;
    }
    return v3(0, 0, 1);
}

int prim_inside(const prim *p, vec3 q)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        return v3_dot(q, q) <= p->u.sphere.r * p->u.sphere.r;
    case PRIM_BOX:
        return q.x >= p->u.box.lo.x && q.x <= p->u.box.hi.x && q.y >= p->u.box.lo.y &&
               q.y <= p->u.box.hi.y && q.z >= p->u.box.lo.z && q.z <= p->u.box.hi.z;
    case PRIM_CYLINDER: {
        double z0 = p->u.cylinder.z0, z1 = p->u.cylinder.z1;
        if (!(q.z >= z0 && q.z <= z1))
            return 0;
        double s = (p->u.cylinder.r1 - p->u.cylinder.r0) / (z1 - z0);
        double w = p->u.cylinder.r0 + s * (q.z - z0);
        return hypot(q.x, q.y) <= w;
    }
    case PRIM_CONVEX:
        for (uint32_t i = 0; i < p->u.convex.count; i++) {
            const plane *pl = &p->u.convex.planes[i];
            if (v3_dot(pl->n, q) > pl->d)
                return 0;
        }
        return 1;
    case PRIM_TORUS:
        return prim_torus_inside(p, q);
    case PRIM_QUADRIC:
        return prim_quadric_inside(p, q);
    case PRIM_IMPLICIT:
        return prim_implicit_inside(p, q);
    case PRIM_MESH:
        return prim_mesh_inside(p, q);
    case PRIM_REVOLVE:
        return prim_revolve_inside(p, q);
    case PRIM_EXTRUSION:
        return prim_extrusion_inside(p, q);
    case PRIM_OUTLINE:
        return prim_outline_inside(p, q);
    case PRIM_KIND_COUNT:
        break;
    }
    return 0;
}

uint32_t prim_max_spans(const prim *p)
{
    switch (p->kind) {
    case PRIM_TORUS:
        return 2; /* a line meets a torus at most four times */
    case PRIM_QUADRIC:
        return 2; /* two pieces of the line (a < 0), each clipped to the box */
    case PRIM_IMPLICIT:
        return PRIM_IMPLICIT_MAX_SPANS;
    case PRIM_MESH:
        return prim_mesh_max_spans(p);
    case PRIM_REVOLVE:
        return prim_revolve_max_spans(p);
    case PRIM_EXTRUSION:
        return prim_extrusion_max_spans(p);
    case PRIM_OUTLINE:
        return prim_outline_max_spans(p);
    default:
        return 1; /* convex */
    }
}
