/* Affine transforms and boxes: see vec.h. */
#include "math/vec.h"

#include <stdint.h>
#include <string.h>

const affine affine_unmoved = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

affine affine_identity(void)
{
    return affine_unmoved;
}

int affine_is_identity(const affine *a)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (a->m[i][j] != affine_unmoved.m[i][j])
                return 0;
    return 1;
}

affine affine_mul(const affine *a, const affine *b)
{
    affine r;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double s = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] +
                       a->m[i][2] * b->m[2][j];
            if (j == 3)
                s += a->m[i][3];
            r.m[i][j] = s;
        }
    }
    return r;
}

double affine_det(const affine *a)
{
    const double(*m)[4] = a->m;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/* The linear part is called singular when |det| <= 1e-14 * (product of its
 * row lengths): by Hadamard's inequality |det| never exceeds that product,
 * so the ratio is a scale-free measure of how flat the map is, and 1e-14
 * leaves the inverse's entries well inside double precision. */
/* The identity's linear part bit for bit (positive zeros), for
 * affine_invert's shortcut; the bits compared as integers (memcpy of one
 * double compiles to a move). */
static int linear_is_identity(const double (*m)[4])
{
    const uint64_t one = 0x3ff0000000000000u; /* 1.0 */
    uint64_t differ = 0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            uint64_t bits;
            memcpy(&bits, &m[i][j], sizeof bits);
            differ |= bits ^ (i == j ? one : 0);
        }
    }
    return differ == 0;
}

/* A map that only moves (an identity linear part, bit for bit: every
 * positioned leaf of an export that only translates it) takes a shortcut
 * with the general path's result: its determinant and row lengths are 1
 * and its cofactors 1 and +0 exactly, so only the translation's formula
 * below is left, evaluated as it stands (0 * t is not folded away: it
 * keeps the sign of a zero and the NaN of an infinite t). */
int affine_invert(const affine *a, affine *out)
{
    const double(*m)[4] = a->m;
    if (linear_is_identity(m)) {
        affine r = affine_identity();
        for (int i = 0; i < 3; i++)
            r.m[i][3] =
                -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
        *out = r;
        return 1;
    }
    double det = affine_det(a);
    double rows = 1.0;
    for (int i = 0; i < 3; i++)
        rows *= sqrt(m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2]);
    if (!isfinite(det) || !(fabs(det) > 1e-14 * rows))
        return 0;
    double id = 1.0 / det;
    affine r;
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
    for (int i = 0; i < 3; i++)
        r.m[i][3] = -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
    *out = r;
    return 1;
}

bbox bbox_empty(void)
{
    bbox b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    return b;
}

bbox bbox_union(bbox a, bbox b)
{
    if (bbox_is_empty(&a))
        return b;
    if (bbox_is_empty(&b))
        return a;
    bbox r = {v3_min(a.lo, b.lo), v3_max(a.hi, b.hi)};
    return r;
}

bbox bbox_intersect(bbox a, bbox b)
{
    bbox r = {v3_max(a.lo, b.lo), v3_min(a.hi, b.hi)};
    if (r.lo.x > r.hi.x || r.lo.y > r.hi.y || r.lo.z > r.hi.z)
        return bbox_empty();
    return r;
}

bbox bbox_add_point(bbox b, vec3 p)
{
    if (bbox_is_empty(&b)) {
        bbox r = {p, p};
        return r;
    }
    bbox r = {v3_min(b.lo, p), v3_max(b.hi, p)};
    return r;
}

bbox bbox_transform(const affine *a, bbox b)
{
    if (bbox_is_empty(&b))
        return b;
    bbox r = bbox_empty();
    for (int i = 0; i < 8; i++) {
        vec3 c =
            v3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
        r = bbox_add_point(r, affine_point(a, c));
    }
    return r;
}
