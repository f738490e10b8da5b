/* Vectors, affine transforms and axis-aligned boxes in double precision.
 *
 * All small and inline: they sit in the inner loop of every ray query.
 * An affine transform is the top three rows of a 4x4 matrix (the bottom row
 * is always 0 0 0 1): p' = L p + t, with L row-major in m[r][0..2] and t in
 * m[r][3].
 */
#ifndef SPANCAST_MATH_VEC_H
#define SPANCAST_MATH_VEC_H

#include <math.h>

typedef struct vec3 {
    double x, y, z;
} vec3;

typedef struct affine {
    double m[3][4];
} affine;

typedef struct bbox {
    vec3 lo, hi; /* empty when lo.x > hi.x */
} bbox;

static inline vec3 v3(double x, double y, double z)
{
    vec3 v = {x, y, z};
    return v;
}
static inline vec3 v3_add(vec3 a, vec3 b)
{
    return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline vec3 v3_sub(vec3 a, vec3 b)
{
    return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline vec3 v3_scale(vec3 a, double s)
{
    return v3(a.x * s, a.y * s, a.z * s);
}
static inline vec3 v3_mul(vec3 a, vec3 b)
{
    return v3(a.x * b.x, a.y * b.y, a.z * b.z);
}
static inline vec3 v3_neg(vec3 a)
{
    return v3(-a.x, -a.y, -a.z);
}
static inline double v3_dot(vec3 a, vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* The term of the edge a -> b in Newell's normal of a polygon: the sum of
 * the terms of its edges is the normal, twice its area long. */
static inline vec3 v3_newell(vec3 a, vec3 b)
{
    return v3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
              (a.x - b.x) * (a.y + b.y));
}
static inline double v3_length(vec3 a)
{
    return sqrt(v3_dot(a, a));
}
static inline vec3 v3_normalize(vec3 a)
{
    double l = v3_length(a);
    return l > 0 ? v3_scale(a, 1.0 / l) : a;
}
/* a + s b */
static inline vec3 v3_madd(vec3 a, vec3 b, double s)
{
    return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}
static inline vec3 v3_min(vec3 a, vec3 b)
{
    return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
}
static inline vec3 v3_max(vec3 a, vec3 b)
{
    return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
}
static inline double v3_max_abs(vec3 a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}
static inline double v3_get(vec3 a, int axis)
{
    return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}
static inline int v3_is_finite(vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

/* ---- 2D affine maps ---- */

/* A map of the plane as rows [a b tx; c d ty]: x' = a x + b y + tx,
 * y' = c x + d y + ty (OpenSCAD's 2D children under a multmatrix). */
typedef struct affine2 {
    double m[2][3];
} affine2;

static inline affine2 affine2_identity(void)
{
    affine2 id = {{{1, 0, 0}, {0, 1, 0}}};
    return id;
}

/* The image of (x, y) under m into (*ox, *oy); the outputs may be the
 * inputs' variables. */
static inline void affine2_apply(const affine2 *m, double x, double y, double *ox,
                                 double *oy)
{
    *ox = m->m[0][0] * x + m->m[0][1] * y + m->m[0][2];
    *oy = m->m[1][0] * x + m->m[1][1] * y + m->m[1][2];
}

/* ---- affine transforms ---- */

affine affine_identity(void);
/* The identity, for a pointer to one. */
extern const affine affine_unmoved;
/* Whether a is the identity, entry for entry. */
int affine_is_identity(const affine *a);
/* a * b: apply b first, then a. */
affine affine_mul(const affine *a, const affine *b);
/* Determinant of the linear part. */
double affine_det(const affine *a);
/* Inverse; returns 0 (and leaves *out untouched) when the linear part is
 * singular relative to its own magnitude (see vec.c). */
int affine_invert(const affine *a, affine *out);

static inline vec3 affine_point(const affine *a, vec3 p)
{
    return v3(a->m[0][0] * p.x + a->m[0][1] * p.y + a->m[0][2] * p.z + a->m[0][3],
              a->m[1][0] * p.x + a->m[1][1] * p.y + a->m[1][2] * p.z + a->m[1][3],
              a->m[2][0] * p.x + a->m[2][1] * p.y + a->m[2][2] * p.z + a->m[2][3]);
}
static inline vec3 affine_vector(const affine *a, vec3 v)
{
    return v3(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
              a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
              a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}
/* Applies the transpose of the linear part: with a = the world-to-local
 * inverse, this carries a local normal to the world (inverse transpose). */
static inline vec3 affine_vector_transposed(const affine *a, vec3 v)
{
    return v3(a->m[0][0] * v.x + a->m[1][0] * v.y + a->m[2][0] * v.z,
              a->m[0][1] * v.x + a->m[1][1] * v.y + a->m[2][1] * v.z,
              a->m[0][2] * v.x + a->m[1][2] * v.y + a->m[2][2] * v.z);
}

/* ---- boxes ---- */

bbox bbox_empty(void);
static inline int bbox_is_empty(const bbox *b)
{
    return !(b->lo.x <= b->hi.x);
}
bbox bbox_union(bbox a, bbox b);
bbox bbox_intersect(bbox a, bbox b);
bbox bbox_add_point(bbox b, vec3 p);
/* Box of the eight transformed corners: conservative bounds of a
 * transformed box. */
bbox bbox_transform(const affine *a, bbox b);
static inline vec3 bbox_center(const bbox *b)
{
    return v3_scale(v3_add(b->lo, b->hi), 0.5);
}
static inline vec3 bbox_extent(const bbox *b)
{
    return v3_sub(b->hi, b->lo);
}

/* Slab test of the ray o + t d against b, restricted to [*t0, *t1]; narrows
 * them to the overlap and returns 1 when it is not empty. A zero direction
 * component is handled by IEEE infinities: off the slab both ends are
 * infinite of the same sign (a miss), inside it of opposite signs (no
 * bound). With the origin on one of the slab's planes that end is
 * 0 * inf = NaN while the other is infinite; the closed slab then holds the
 * whole line, so the axis is skipped (ordering a NaN against the other end
 * would instead drop the ray). */
static inline int bbox_ray(const bbox *b, vec3 o, vec3 inv_d, double *t0, double *t1)
{
    double lo = *t0, hi = *t1;
    const double *bo = &o.x, *bi = &inv_d.x, *blo = &b->lo.x, *bhi = &b->hi.x;
    for (int k = 0; k < 3; k++) {
        double ta = (blo[k] - bo[k]) * bi[k];
        double tb = (bhi[k] - bo[k]) * bi[k];
        if (isnan(ta) || isnan(tb))
            continue;
        double tn = ta < tb ? ta : tb;
        double tf = ta < tb ? tb : ta;
        if (tn > lo)
            lo = tn;
        if (tf < hi)
            hi = tf;
    }
    *t0 = lo;
    *t1 = hi;
    return lo <= hi;
}

#endif
