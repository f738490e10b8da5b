/* General quadric clipped to a box, and the box clipping the clipped
 * leaves share.
 *
 *   implicit   Q(p) = A x^2 + B y^2 + C z^2 + D xy + E yz + F xz
 *                     + G x + H y + I z + J <= 0, and lo <= p <= hi
 *   ray        p = c + t d with c the point of the line closest to the
 *              box centre (shifted as for the sphere, to keep Q(c) free of
 *              the cancellation of a far origin); Q(c + t d) =
 *              a t^2 + 2 b t + k with
 *              a = Q2(d) (the quadratic part at d),
 *              b = Q2(c, d) + (G dx + H dy + I dz) / 2, the polar form
 *                  A cx dx + B cy dy + C cz dz + (D (cx dy + cy dx)
 *                  + E (cy dz + cz dy) + F (cx dz + cz dx)) / 2,
 *              k = Q(c)
 *   normal     grad Q = (2A x + D y + F z + G, 2B y + D x + E z + H,
 *                        2C z + E y + F x + I); box faces: their axes
 *
 * The line's part inside Q <= 0 is one interval for a > 0 (between the
 * roots), the whole line or two half-lines for a < 0 (hyperboloids, cones:
 * outside the roots), a half-line or all or nothing for a = 0 (the ray
 * along an asymptotic direction: Q is linear in t). Each piece is clipped
 * to the box, so a ray has at most two spans (a cone's two nappes, both
 * sheets of a hyperboloid). Roots come from the stable quadratic formula.
 */
#include <math.h>

#include "csg/prim_curved.h"

vec3 prim_clip_face_normal(uint16_t part)
{
    int face = part - PRIM_PART_CLIP_FACE, axis = face >> 1;
    double sign = (face & 1) ? 1.0 : -1.0;
    return v3(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
}

int prim_box_clip(const bbox *b, vec3 o, vec3 d, double *t0, uint16_t *face0, double *t1,
                  uint16_t *face1)
{
    const double *lo = &b->lo.x, *hi = &b->hi.x, *po = &o.x, *pd = &d.x;
    double t_in = -INFINITY, t_out = INFINITY;
    uint16_t in = 0, out = 1;
    for (int k = 0; k < 3; k++) {
        if (pd[k] == 0) {
            if (po[k] < lo[k] || po[k] > hi[k])
                return 0;
            continue;
        }
        double ta = (lo[k] - po[k]) / pd[k], tb = (hi[k] - po[k]) / pd[k];
        double tn = pd[k] > 0 ? ta : tb, tf = pd[k] > 0 ? tb : ta;
        if (tn > t_in) {
            t_in = tn;
            in = (uint16_t)(2 * k + (pd[k] > 0 ? 0 : 1));
        }
        if (tf < t_out) {
            t_out = tf;
            out = (uint16_t)(2 * k + (pd[k] > 0 ? 1 : 0));
        }
    }
    if (!(t_in <= t_out) || !isfinite(t_in) || !isfinite(t_out))
        return 0;
    *t0 = t_in;
    *t1 = t_out;
    *face0 = in;
    *face1 = out;
    return 1;
}

double prim_quadric_value(const double *a, vec3 q)
{
    return a[0] * q.x * q.x + a[1] * q.y * q.y + a[2] * q.z * q.z + a[3] * q.x * q.y +
           a[4] * q.y * q.z + a[5] * q.x * q.z + a[6] * q.x + a[7] * q.y + a[8] * q.z +
           a[9];
}

/* Stable roots of a t^2 + 2 b t + c (a != 0), increasing; 0 when none. */
static int quadratic(double a, double b, double c, double *lo, double *hi)
{
    double disc = b * b - a * c;
    if (!(disc >= 0))
        return 0;
    double q = -(b + copysign(sqrt(disc), b));
    double r0 = q == 0 ? 0 : q / a, r1 = q == 0 ? 0 : c / q;
    *lo = fmin(r0, r1);
    *hi = fmax(r0, r1);
    return 1;
}

uint32_t prim_quadric_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap)
{
    const double *q = p->u.quadric.q->a;
    const bbox *box = &p->u.quadric.q->box;
    double t0, t1;
    uint16_t f0, f1;
    if (!prim_box_clip(box, o, d, &t0, &f0, &t1, &f1))
        return 0;
    vec3 ctr = bbox_center(box);
    double tc = -v3_dot(v3_sub(o, ctr), d) / v3_dot(d, d);
    vec3 c = v3_madd(o, d, tc);
    double a = q[0] * d.x * d.x + q[1] * d.y * d.y + q[2] * d.z * d.z + q[3] * d.x * d.y +
               q[4] * d.y * d.z + q[5] * d.x * d.z;
    double b =
        q[0] * c.x * d.x + q[1] * c.y * d.y + q[2] * c.z * d.z +
        0.5 * (q[3] * (c.x * d.y + c.y * d.x) + q[4] * (c.y * d.z + c.z * d.y) +
               q[5] * (c.x * d.z + c.z * d.x) + q[6] * d.x + q[7] * d.y + q[8] * d.z);
    double k = prim_quadric_value(q, c);
    /* Pieces of the line (in t - tc) inside Q <= 0. */
    double lo[2], hi[2];
    int pieces = 0;
    double r0, r1;
    if (a == 0) {
        if (b == 0) {
            if (k <= 0)
                lo[0] = -INFINITY, hi[0] = INFINITY, pieces = 1;
        } else if (b > 0) {
            lo[0] = -INFINITY, hi[0] = -k / (2 * b), pieces = 1;
        } else {
            lo[0] = -k / (2 * b), hi[0] = INFINITY, pieces = 1;
        }
    } else if (quadratic(a, b, k, &r0, &r1)) {
        if (a > 0) {
            lo[0] = r0, hi[0] = r1, pieces = 1;
        } else {
            lo[0] = -INFINITY, hi[0] = r0;
            lo[1] = r1, hi[1] = INFINITY;
            pieces = 2;
        }
    } else if (a < 0) {
        lo[0] = -INFINITY, hi[0] = INFINITY, pieces = 1;
    }
    uint32_t n = 0;
    for (int i = 0; i < pieces && n < cap; i++) {
        double s_in = tc + lo[i], s_out = tc + hi[i];
        uint16_t part_in = PRIM_PART_SURFACE, part_out = PRIM_PART_SURFACE;
        if (!(s_in > t0)) {
            s_in = t0;
            part_in = (uint16_t)(PRIM_PART_CLIP_FACE + f0);
        }
        if (!(s_out < t1)) {
            s_out = t1;
            part_out = (uint16_t)(PRIM_PART_CLIP_FACE + f1);
        }
        if (!(s_in <= s_out) || !isfinite(s_in) || !isfinite(s_out))
            continue;
        if (n > 0 && !(out[n - 1].out.t < s_in)) {
            /* The two pieces touch (a double root): one span. */
            out[n - 1].out = (span_end){s_out, leaf, part_out, 0};
            continue;
        }
        out[n].in = (span_end){s_in, leaf, part_in, 0};
        out[n].out = (span_end){s_out, leaf, part_out, 0};
        n++;
    }
    return n;
}

vec3 prim_quadric_normal(const prim *p, vec3 x, uint16_t part)
{
    if (part >= PRIM_PART_CLIP_FACE)
        return prim_clip_face_normal(part);
    const double *q = p->u.quadric.q->a;
    vec3 g = v3(2 * q[0] * x.x + q[3] * x.y + q[5] * x.z + q[6],
                2 * q[1] * x.y + q[3] * x.x + q[4] * x.z + q[7],
                2 * q[2] * x.z + q[4] * x.y + q[5] * x.x + q[8]);
    /* A cone's apex has no tangent plane: any direction will do. */
    return v3_dot(g, g) > 0 ? g : v3(0, 0, 1);
}

int prim_quadric_inside(const prim *p, vec3 x)
{
    const bbox *b = &p->u.quadric.q->box;
    if (!(x.x >= b->lo.x && x.x <= b->hi.x && x.y >= b->lo.y && x.y <= b->hi.y &&
          x.z >= b->lo.z && x.z <= b->hi.z))
        return 0;
    return prim_quadric_value(p->u.quadric.q->a, x) <= 0;
}
