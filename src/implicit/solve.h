/* Root finding along a ray for implicit surfaces: every crossing of the
 * surface f = 0 by o + t d within [t0, t1], behind one interface with
 * three methods of different cost and accuracy.
 *
 * A crossing is a sign change of the predicate f < 0 (inside) between two
 * points the method evaluated; each method walks the segment in order and
 * compares neighbouring evaluations, so crossings come out sorted and
 * alternate in direction: the first enters the solid when o + t0 d is
 * outside, and so on. A double root (a tangent touch, no sign change) is no
 * crossing.
 *
 *   SOLVE_INTERVAL   interval bisection with Newton refinement (the
 *                    default). A segment whose interval enclosure of f
 *                    excludes 0 holds no root and is dropped; one whose
 *                    enclosure of f' excludes 0 is monotone and holds a
 *                    root exactly when its ends differ in sign; others are
 *                    halved down to the tolerance. Every bracketed root is
 *                    then refined by safeguarded Newton-bisection to full
 *                    precision. Guarantee: every sign change of f is found
 *                    except where two or more crossings lie within one
 *                    segment no longer than the tolerance (a sliver or gap
 *                    thinner than the tolerance), and every reported
 *                    crossing is a true sign change.
 *   SOLVE_LIPSCHITZ  sphere tracing: with |grad f| <= L the surface is at
 *                    least |f| / L away, so the step |f| / L (at least the
 *                    tolerance) cannot jump over it while the bound holds;
 *                    a sign change between steps is located by the secant.
 *                    L is given by the user or estimated by sampling
 *                    (solve_estimate_lipschitz), which is not a guarantee.
 *   SOLVE_MARCH      fixed steps of the tolerance; a sign change between
 *                    two steps is bisected to 1e-3 of a step. Misses any
 *                    pair of crossings closer than a step.
 *
 * The tolerance is a length in the frame of the ray (it is divided by |d|
 * to give a step in t). Work is bounded: at most SOLVE_MAX_EVALS
 * evaluations per call; a call that reaches the bound stops and reports
 * it. Output is bounded too: see solve_result. Every method polls the
 * calling thread's cancel token (base/cancel.h) every SOLVE_POLL_STEPS
 * steps and gives up when it has stopped, so an interrupt or a spent
 * budget ends even a ray of SOLVE_MAX_EVALS evaluations within a
 * millisecond or so.
 */
#ifndef SPANCAST_IMPLICIT_SOLVE_H
#define SPANCAST_IMPLICIT_SOLVE_H

#include <stdint.h>

#include "implicit/expr.h"
#include "math/vec.h"

typedef enum solve_method {
    SOLVE_INTERVAL,
    SOLVE_LIPSCHITZ,
    SOLVE_MARCH,
    SOLVE_METHOD_COUNT
} solve_method;

#define SOLVE_MAX_CROSSINGS 33     /* kept per call, see solve_result */
#define SOLVE_MAX_EVALS (1u << 22) /* evaluations per call */
#define SOLVE_POLL_STEPS 256       /* steps between polls of the cancel token */

typedef struct solve_options {
    solve_method method;
    double tolerance; /* length, > 0 */
    double lipschitz; /* bound on |grad f| for SOLVE_LIPSCHITZ, > 0 */
} solve_options;

/* Crossings in increasing t. When more than SOLVE_MAX_CROSSINGS are
 * found, the first SOLVE_MAX_CROSSINGS - 1 are kept and the last slot
 * holds the last crossing of all: total counts every crossing, so crossing
 * i of the kept list is crossing number i of all except the last kept one,
 * which is number total - 1. */
typedef struct solve_result {
    double t[SOLVE_MAX_CROSSINGS];
    uint32_t n;       /* kept */
    uint32_t total;   /* found */
    int inside_start; /* f(o + t0 d) < 0 */
    int exhausted;    /* the evaluation bound was reached: the rest of the
                         segment was not searched */
    int stopped;      /* the calling thread's cancel token stopped the search
                         (base/cancel.h): the result is incomplete */
    uint64_t evals;   /* evaluations made, for benchmarks */
    uint64_t charged; /* of them, reported to the cancel token so far */
} solve_result;

/* Finds the crossings of f along o + t d for t in [t0, t1] (finite,
 * t0 <= t1). */
void solve_crossings(const expr_program *f, const solve_options *opt, vec3 o, vec3 d,
                     double t0, double t1, solve_result *out);

/* A function of t along a line with its derivative in t (into *df),
 * from the context ctx: what solve_newton_bracket refines. */
typedef double (*solve_line_fn)(const void *ctx, double t, double *df);

/* Safeguarded Newton-bisection for a root of f in [a, b], where f(a) and
 * f(b) differ in the sign of f < 0 (neg_a is that sign at a). Newton steps
 * that leave the bracket or do not halve it are replaced by bisection, so
 * the bracket shrinks at least geometrically; it stops at the resolution
 * of doubles or after max_iterations evaluations. Returns the middle of
 * the last bracket. */
double solve_newton_bracket(solve_line_fn f, const void *ctx, double a, double b,
                            int neg_a, int max_iterations);

/* An estimate of max |grad f| over the box: 1.5 times the largest gradient
 * norm at the nodes of a 16 x 16 x 16 grid. Not a bound: a feature between
 * the nodes can be steeper. Returns at least 1e-300. */
double solve_estimate_lipschitz(const expr_program *f, bbox box);

/* Name of a method as written in scene files ("interval", "lipschitz",
 * "march"); solve_method_parse returns SOLVE_METHOD_COUNT for others. */
const char *solve_method_name(solve_method m);
solve_method solve_method_parse(const char *name);

#endif
