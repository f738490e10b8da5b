/* The boolean sweep over span lists and the regularisation rule.
 *
 * span_combine walks the boundaries of both lists in increasing t, keeps
 * whether the ray is inside each operand, and emits a boundary whenever the
 * combined predicate (a or b, a and b, a and not b) changes. The boundary
 * keeps the surface reference of the operand boundary that caused it; a
 * boundary of b in a difference has its flip bit toggled, since the solid
 * that remains lies on the other side of a subtracted surface. Ties at equal
 * t may emit zero-length spans or zero-length gaps; regularisation removes
 * both, so the order in which tied boundaries are taken does not change the
 * result beyond which of two coincident surfaces is reported.
 */
#include "csg/span.h"

#include <stddef.h>

/* Boundary k of a list: even k is the entry of span k/2, odd k its exit. */
static inline const span_end *boundary(span_list l, uint32_t k)
{
    const span *s = &l.v[k >> 1];
    return (k & 1) ? &s->out : &s->in;
}

static inline int combined(span_op op, int in_a, int in_b)
{
    switch (op) {
    case SPAN_UNION:
        return in_a || in_b;
    case SPAN_INTERSECTION:
        return in_a && in_b;
    case SPAN_DIFFERENCE:
        return in_a && !in_b;
    }
    return 0;
}

/* span_merge's sweep for one op: always inlined, so that each call below
 * gets its own copy with combined() folded for that op. */
#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

static ALWAYS_INLINE uint32_t merge(span_op op, span_list a, span_list b, span *out)
{
    uint32_t n = 0;
    uint32_t na = 2 * a.n, nb = 2 * b.n, ia = 0, ib = 0;
    int in_a = 0, in_b = 0, in_r = 0;
    while (ia < na || ib < nb) {
        const span_end *e;
        int from_b;
        if (ib >= nb || (ia < na && boundary(a, ia)->t <= boundary(b, ib)->t)) {
            e = boundary(a, ia++);
            in_a = !in_a;
            from_b = 0;
        } else {
            e = boundary(b, ib++);
            in_b = !in_b;
            from_b = 1;
        }
        int now = combined(op, in_a, in_b);
        if (now == in_r)
            continue;
        span_end end = *e;
        if (from_b && op == SPAN_DIFFERENCE)
            end.flip ^= 1;
        if (now)
            out[n].in = end;
        else
            out[n++].out = end;
        in_r = now;
    }
    return n;
}

uint32_t span_merge(span_op op, span_list a, span_list b, span *out)
{
    switch (op) {
    case SPAN_UNION:
        return merge(SPAN_UNION, a, b, out);
    case SPAN_INTERSECTION:
        return merge(SPAN_INTERSECTION, a, b, out);
    case SPAN_DIFFERENCE:
        return merge(SPAN_DIFFERENCE, a, b, out);
    }
    return 0;
}

/* span_combine of two single spans by intersection (span_intersect_pair).
 * A result that is one of the operands is returned as it is, like
 * span_combine's shortcuts. */
static span_list intersect_one(span_list a, span_list b, double eps, arena *scratch,
                               int *oom)
{
    span_list r = {NULL, 0};
    const span_end *in, *out;
    if (!span_intersect_pair(&a.v[0], &b.v[0], eps, &in, &out))
        return r;
    if (in == &a.v[0].in && out == &a.v[0].out)
        return a;
    if (in == &b.v[0].in && out == &b.v[0].out)
        return b;
    r.v = arena_alloc(scratch, sizeof(span));
    if (!r.v) {
        *oom = 1;
        return r;
    }
    r.v[0].in = *in;
    r.v[0].out = *out;
    r.n = 1;
    return r;
}

span_list span_combine(span_op op, span_list a, span_list b, double eps, arena *scratch,
                       int *oom)
{
    span_list r = {NULL, 0};
    /* Shortcuts that are exact consequences of the predicates. */
    if (a.n == 0)
        return op == SPAN_UNION ? b : r;
    if (b.n == 0)
        return op == SPAN_INTERSECTION ? r : a;
    if (op == SPAN_INTERSECTION && a.n == 1 && b.n == 1)
        return intersect_one(a, b, eps, scratch, oom);

    uint32_t cap = a.n + b.n;
    r.v = arena_alloc(scratch, (size_t)cap * sizeof(span));
    if (!r.v) {
        *oom = 1;
        return r;
    }
    r.n = span_merge(op, a, b, r.v);
    r.n = span_regularize(r.v, r.n, eps);
    return r;
}

uint32_t span_regularize(span *v, uint32_t n, double eps)
{
    if (n == 0)
        return 0;
    /* 1. Close gaps no longer than eps. */
    uint32_t w = 1;
    for (uint32_t i = 1; i < n; i++) {
        if (v[i].in.t - v[w - 1].out.t <= eps)
            v[w - 1].out = v[i].out;
        else
            v[w++] = v[i];
    }
    /* 2. Remove spans no longer than eps. */
    uint32_t k = 0;
    for (uint32_t i = 0; i < w; i++) {
        if (v[i].out.t - v[i].in.t > eps)
            v[k++] = v[i];
    }
    return k;
}
