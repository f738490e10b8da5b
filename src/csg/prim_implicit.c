/* Implicit surface: f(p) < 0 inside, clipped to a box, f compiled to
 * bytecode (src/implicit/expr.h) and owned by the tree's arena.
 *
 *   ray      the line is clipped to the box: [t0, t1], entered and left
 *            through box faces; solve_crossings finds the sign changes of
 *            f < 0 in between with the leaf's method and tolerance
 *            (src/implicit/solve.h); they alternate, starting from the
 *            sign at t0, so spans run from an entering crossing (or the
 *            box face at t0 when f(o + t0 d) < 0) to the next leaving one
 *            (or the face at t1).
 *   normal   grad f, from three forward-mode evaluations; box faces:
 *            their axes
 *
 * Span cap. A ray may cross an implicit surface any number of times (a
 * gyroid crosses it every half period), but span buffers have a fixed size:
 * at most PRIM_IMPLICIT_MAX_SPANS spans. When a ray has more, the first
 * PRIM_IMPLICIT_MAX_SPANS - 1 spans are exact and the last one runs from
 * the start of the cap-th span to the end of the last span: the gaps past
 * the cap are filled in. The first hit, and every crossing before the
 * cap, stay exact, which is what a camera ray needs; only the far side of
 * a ray with that many crossings is approximate.
 *
 * Work. Each call reports its evaluations to the calling thread's cancel
 * token (base/cancel.h), which holds the budget of the whole render or
 * measure; a call that reaches the per-ray bound SOLVE_MAX_EVALS stops
 * the token (CANCEL_RAY_LIMIT), so that the caller fails with an error
 * naming the leaf instead of using a span list whose far part was never
 * searched. Without a token (a bare query) the list holds what was found.
 */
#include <math.h>

#include "base/cancel.h"
#include "csg/prim_curved.h"
#include "implicit/solve.h"

/* Appends [a, b] to out, or past the cap extends the last span to b. */
static void add_span(span *out, uint32_t *n, uint32_t cap, span_end a, span_end b)
{
    if (*n < cap) {
        out[*n].in = a;
        out[*n].out = b;
        (*n)++;
    } else {
        out[cap - 1].out = b;
    }
}

uint32_t prim_implicit_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                             uint32_t cap)
{
    double t0, t1;
    uint16_t f0, f1;
    if (!p->u.implicit.program || cap == 0 ||
        !prim_box_clip(&p->u.implicit.box, o, d, &t0, &f0, &t1, &f1))
        return 0;
    if (cap > PRIM_IMPLICIT_MAX_SPANS)
        cap = PRIM_IMPLICIT_MAX_SPANS;
    solve_options opt = {(solve_method)p->u.implicit.method, p->u.implicit.tolerance,
                         p->u.implicit.lipschitz};
    solve_result r;
    cancel_working_on(leaf, p);
    solve_crossings(p->u.implicit.program, &opt, o, d, t0, t1, &r);
    cancel_spend(r.evals - r.charged);
    if (r.exhausted)
        cancel_stop(CANCEL_RAY_LIMIT);
    uint32_t n = 0;
    int inside = r.inside_start;
    span_end start = {t0, leaf, (uint16_t)(PRIM_PART_CLIP_FACE + f0), 0};
    for (uint32_t i = 0; i < r.n; i++) {
        /* The last kept crossing is crossing number total - 1 of all. */
        uint32_t number = i + 1 == r.n ? r.total - 1 : i;
        int entering = (number % 2 == 0) != r.inside_start;
        span_end e = {r.t[i], leaf, PRIM_PART_SURFACE, 0};
        if (i + 1 == r.n && number != i) {
            /* Past the cap: close the open span here if this crossing
             * leaves; an entering one leaves the solid open to t1. */
            if (!inside && entering) {
                start = e;
                inside = 1;
            } else if (inside && !entering) {
                add_span(out, &n, cap, start, e);
                inside = 0;
            } else if (!inside && !entering && n > 0) {
                out[n - 1].out = e; /* the last span so far reaches it */
            } else if (inside && entering) {
                /* keep the open span; it runs to t1 */
            }
            continue;
        }
        if (entering) {
            start = e;
            inside = 1;
        } else {
            add_span(out, &n, cap, start, e);
            inside = 0;
        }
    }
    if (inside)
        add_span(out, &n, cap, start,
                 (span_end){t1, leaf, (uint16_t)(PRIM_PART_CLIP_FACE + f1), 0});
    return n;
}

vec3 prim_implicit_normal(const prim *p, vec3 q, uint16_t part)
{
    if (part >= PRIM_PART_CLIP_FACE)
        return prim_clip_face_normal(part);
    const expr_program *f = p->u.implicit.program;
    double gx, gy, gz;
    expr_eval_dual(f, q, v3(1, 0, 0), &gx);
    expr_eval_dual(f, q, v3(0, 1, 0), &gy);
    expr_eval_dual(f, q, v3(0, 0, 1), &gz);
    vec3 g = v3(gx, gy, gz);
    return v3_is_finite(g) && v3_dot(g, g) > 0 ? g : v3(0, 0, 1);
}

int prim_implicit_inside(const prim *p, vec3 q)
{
    const bbox *b = &p->u.implicit.box;
    if (!(q.x >= b->lo.x && q.x <= b->hi.x && q.y >= b->lo.y && q.y <= b->hi.y &&
          q.z >= b->lo.z && q.z <= b->hi.z))
        return 0;
    return p->u.implicit.program && expr_eval(p->u.implicit.program, q) < 0;
}
