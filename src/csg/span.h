/* Spans: the intervals of a ray inside a solid, and the boolean sweep that
 * combines them.
 *
 * A span is [in.t, out.t] with a reference at each end to the surface that
 * bounds it: the leaf, the part of the leaf (a face of a box, the side or a
 * cap of a cylinder, ...) and whether its normal is flipped (a subtracted
 * surface seen from the solid that remains). A span list is sorted and
 * disjoint: list[i].out.t < list[i+1].in.t. No span holds NaN or Inf.
 *
 * Regularisation, the one rule for coincident faces (span_regularize):
 * after every boolean, with eps the query's scene-relative tolerance in ray
 * parameter units,
 *   1. a gap between consecutive spans no longer than eps is closed: the two
 *      spans become one, keeping the outer surfaces (touching solids fuse);
 *   2. then a span no longer than eps is removed (slivers left by coincident
 *      faces, tangent grazes, zero-thickness solids vanish).
 * The same rule is applied to leaves' raw spans. It is the regularised set
 * operation (closure of the interior) at resolution eps.
 */
#ifndef SPANCAST_CSG_SPAN_H
#define SPANCAST_CSG_SPAN_H

#include <stdint.h>

#include "base/arena.h"

#define SPAN_NO_LEAF UINT32_MAX

typedef struct span_end {
    double t;
    uint32_t leaf; /* leaf index in the compiled tree, SPAN_NO_LEAF when clipped */
    uint16_t part; /* which surface of the leaf (primitive-specific) */
    uint8_t flip;  /* 1: the surface's normal points the other way here */
} span_end;

typedef struct span {
    span_end in, out;
} span;

typedef struct span_list {
    span *v;
    uint32_t n;
} span_list;

typedef enum span_op { SPAN_UNION, SPAN_INTERSECTION, SPAN_DIFFERENCE } span_op;

/* Combines a and b by op (difference: a minus b, b's surfaces flipped) into a
 * new list allocated from scratch, regularised with eps. Linear in
 * a.n + b.n. Returns a list with n == 0 and v == NULL on allocation failure
 * only if both inputs are empty; otherwise sets *oom on failure. */
span_list span_combine(span_op op, span_list a, span_list b, double eps, arena *scratch,
                       int *oom);

/* The sweep of span_combine without regularisation: writes the spans of a
 * op b to out, which has room for a.n + b.n spans and may not overlap
 * a or b; returns their count. Ties may leave zero-length spans or gaps. */
uint32_t span_merge(span_op op, span_list a, span_list b, span *out);

/* span_combine's intersection of two single spans a and b (two convex
 * leaves), without the sweep: sets *in to the later entry and *out to the
 * earlier exit and returns 1, or returns 0 when that is no longer than eps.
 * Only [later entry, earlier exit] can come out of the sweep. When that is
 * longer than eps, both entries come before both exits: the sweep is
 * inside both from the second entry it takes (on a tie, b's, since it
 * takes a's boundary first) to the first exit (on a tie, a's), and
 * regularisation keeps the span. Otherwise whatever the sweep emits is no
 * longer than eps and regularisation removes it. Inline: the queries'
 * flat intersections call it per operand. */
static inline int span_intersect_pair(const span *a, const span *b, double eps,
                                      const span_end **in, const span_end **out)
{
    *in = a->in.t <= b->in.t ? &b->in : &a->in;
    *out = a->out.t <= b->out.t ? &a->out : &b->out;
    return (*out)->t - (*in)->t > eps;
}

/* Applies the regularisation rule above in place; returns the new count. */
uint32_t span_regularize(span *v, uint32_t n, double eps);

#endif
