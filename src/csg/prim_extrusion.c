/* Extrusions: a 2D region R extruded straight along z, the solid
 * { (x, y, z) : (x, y) in R, z0 <= z <= z1 }, with R a small CSG tree of
 * ellipses and even-odd polygon sets under union, intersection and
 * difference (linear_extrude without twist or scale, exactly).
 *
 * A ray o + t d splits into its z motion and its shadow in the plane, the
 * line p(t) = o_xy + t d_xy. The ray is in the solid exactly when its
 * shadow is in R and its z in the slab, so its spans are R's spans along
 * the shadow (same t), intersected with the slab interval
 *   t in [(z0 - o_z) / d_z, (z1 - o_z) / d_z]   (ends swapped for d_z < 0;
 *   the whole line or nothing when d_z = 0).
 * A vertical ray (d_xy = 0) has a point for a shadow: the slab interval
 * when o_xy is in R, nothing otherwise.
 *
 * R's spans along the line come from its leaves, combined by the boolean
 * sweep of the 3D tree (span_merge, span.c) in postfix order:
 *   ellipse  |m (p - c)| <= 1: with u0 = m (o_xy - c), u1 = m d_xy,
 *            |u0 + t u1|^2 = 1 is a t^2 + 2 b t + c = 0, a = u1.u1,
 *            b = u0.u1, c = u0.u0 - 1, solved after moving the origin to
 *            the line's point closest to the centre (as for the sphere,
 *            prim.c) with c as (|u| - 1)(|u| + 1).
 *            normal  grad |m (p - c)|^2 / 2 = m^T u.
 *   polygon  an edge a -> b crosses the line where the sides
 *            s(x) = d_xy x (x - o_xy) (2D cross product) of its ends
 *            differ, counting s = 0 with the negative side (a half-open
 *            rule): a vertex on the line is seen the same way by both of
 *            its edges, so each closed path crosses the line an even
 *            number of times and the parity along the line is that of
 *            the points beside it. s is computed with Kahan's difference
 *            of products, so every evaluation of it at a vertex gives the
 *            same number. The crossing is the edge's point at
 *            lambda = s(a) / (s(a) - s(b)), projected on the line; the
 *            crossings sorted by t, pairs of them are the spans (even-odd).
 *            Edges are boxed 16 at a time (padded like the leaves' boxes,
 *            below): a box the line misses skips its edges.
 *            normal  the edge's left normal (-(b - a)_y, (b - a)_x), or its
 *            opposite: the side the ray comes from at an entry, the side
 *            it goes to at an exit.
 * Each leaf's list is regularised with eps = 0 (touching spans join,
 * empty ones vanish) and so is each combination; the tree's own
 * regularisation at its scene tolerance follows in csg.c.
 *
 * Surface parts: 0 the bottom cap (normal -z), 1 the top cap (+z); a wall
 * of surface g (edge g, or ellipse g - edge_count) is
 * 2 + 2 (g mod 32767) + side, side 1 meaning the surface's normal above
 * taken the other way round. The side records the polygon's facing and
 * every difference the wall went through as a subtrahend (the flip that
 * span_merge sets is folded into it), so the leaf's spans never carry a
 * flip and prim_normal is the outward normal of the extruded region. With
 * more than 32767 surfaces a part is shared, and the normal is that of the
 * surface among them closest to the point.
 *
 * Memory: the sweep keeps its operands in the output buffer, which the
 * caller sizes by prim_max_spans: the leaves give at most S spans in all
 * (an ellipse 1, a polygon set of n edges n / 2), a combination at most as
 * many as its operands, so the operands waiting plus the result being
 * built never need more than 2 S spans. With a smaller buffer a local one
 * of 64 spans is used when that is enough, and no span
 * is written otherwise. Nothing is allocated.
 *
 * Membership: z in the slab and the postfix program over the leaves'
 * closed memberships (an ellipse's |u| <= 1; a polygon set's even-odd
 * count along +x, a point on an edge inside).
 */
#include "csg/prim_extrusion.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "csg/csg.h"

enum {
    PART_BOTTOM = 0,
    PART_TOP = 1,
    PART_WALL = 2,
    PART_RESIDUES = 32767, /* walls per side that parts can tell apart */
    LOCAL_SPANS = 64,      /* the local sweep buffer (see above) */
    CHUNK = PRIM_EXTRUSION_CHUNK
};

/* ---- describing a region ---- */

static int grow(void **v, uint32_t *cap, uint32_t need, size_t size)
{
    if (need <= *cap)
        return 1;
    uint64_t n = *cap ? *cap : 8;
    while (n < need)
        n *= 2;
    if (n > UINT32_MAX || n * size > SIZE_MAX / 2)
        return 0;
    void *p = realloc(*v, (size_t)n * size);
    if (!p)
        return 0;
    *v = p;
    *cap = (uint32_t)n;
    return 1;
}

static int push_node(prim_region *r, prim_region_node node)
{
    if (!grow((void **)&r->nodes, &r->node_cap, r->node_count + 1, sizeof *r->nodes))
        return 0;
    r->nodes[r->node_count++] = node;
    return 1;
}

int prim_region_add_polygon(prim_region *r, const double *xy, const uint32_t *start,
                            uint32_t paths, int *pushed)
{
    *pushed = 0;
    uint32_t first = r->edge_count;
    double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (uint32_t k = 0; k < paths; k++) {
        uint32_t s = start[k], e = start[k + 1];
        if (e - s < 3)
            continue;
        for (uint32_t i = s; i < e; i++) {
            uint32_t j = i + 1 < e ? i + 1 : s;
            const double *a = &xy[2 * i], *b = &xy[2 * j];
            if (a[0] == b[0] && a[1] == b[1])
                continue; /* no length: never crosses a line */
            if (!grow((void **)&r->edges, &r->edge_cap, r->edge_count + 1,
                      4 * sizeof *r->edges))
                return 0;
            double *out = &r->edges[4 * r->edge_count++];
            out[0] = a[0];
            out[1] = a[1];
            out[2] = b[0];
            out[3] = b[1];
            box[0] = fmin(box[0], a[0]);
            box[1] = fmin(box[1], a[1]);
            box[2] = fmax(box[2], a[0]);
            box[3] = fmax(box[3], a[1]);
        }
    }
    if (r->edge_count == first)
        return 1;
    prim_region_node n;
    memset(&n, 0, sizeof n);
    n.op = PRIM_REGION_POLYGON;
    n.index = first;
    n.count = r->edge_count - first;
    memcpy(n.box, box, sizeof box);
    if (!push_node(r, n))
        return 0;
    *pushed = 1;
    return 1;
}

int prim_region_add_ellipse(prim_region *r, const double map[2][3], double radius,
                            int *pushed)
{
    *pushed = 0;
    double a = radius * map[0][0], b = radius * map[0][1];
    double c = radius * map[1][0], d = radius * map[1][1];
    double det = a * d - b * c;
    if (!(det != 0) || !isfinite(det))
        return 1; /* a segment or a point: no area */
    if (!grow((void **)&r->ellipses, &r->ellipse_cap, r->ellipse_count + 1,
              sizeof *r->ellipses))
        return 0;
    prim_region_ellipse *e = &r->ellipses[r->ellipse_count];
    e->m[0][0] = d / det;
    e->m[0][1] = -b / det;
    e->m[1][0] = -c / det;
    e->m[1][1] = a / det;
    e->c[0] = map[0][2];
    e->c[1] = map[1][2];
    /* The ellipse is c + A v, |v| <= 1 (A = radius * map's linear part):
     * its half-widths are the lengths of A's rows. */
    double hx = hypot(a, b), hy = hypot(c, d);
    prim_region_node n;
    memset(&n, 0, sizeof n);
    n.op = PRIM_REGION_ELLIPSE;
    n.index = r->ellipse_count;
    n.box[0] = e->c[0] - hx;
    n.box[1] = e->c[1] - hy;
    n.box[2] = e->c[0] + hx;
    n.box[3] = e->c[1] + hy;
    if (!push_node(r, n))
        return 0;
    r->ellipse_count++;
    *pushed = 1;
    return 1;
}

int prim_region_add_op(prim_region *r, prim_region_op op)
{
    prim_region_node n;
    memset(&n, 0, sizeof n);
    n.op = (uint8_t)op;
    return push_node(r, n);
}

void prim_region_free(prim_region *r)
{
    free(r->nodes);
    free(r->edges);
    free(r->ellipses);
    memset(r, 0, sizeof *r);
}

/* 2D boxes of the program's results: union of boxes, intersection of
 * boxes, the first operand's box for a difference. Returns 0 when the
 * program is malformed. */
static int program_box(const prim_region *r, double out[4], uint32_t *max_stack,
                       uint64_t *leaf_spans)
{
    double(*stack)[4] = malloc((size_t)PRIM_REGION_MAX_STACK * sizeof *stack);
    if (!stack)
        return 0;
    uint32_t top = 0, most = 0;
    uint64_t spans = 0;
    int ok = 1;
    for (uint32_t i = 0; ok && i < r->node_count; i++) {
        const prim_region_node *n = &r->nodes[i];
        if (n->op == PRIM_REGION_ELLIPSE || n->op == PRIM_REGION_POLYGON) {
            ok = top < PRIM_REGION_MAX_STACK &&
                 (n->op == PRIM_REGION_ELLIPSE
                      ? n->index < r->ellipse_count
                      : (uint64_t)n->index + n->count <= r->edge_count);
            if (ok) {
                memcpy(stack[top++], n->box, sizeof n->box);
                spans += n->op == PRIM_REGION_ELLIPSE ? 1 : n->count / 2;
            }
        } else if (top < 2 || n->op > PRIM_REGION_DIFFERENCE) {
            ok = 0;
        } else {
            double *a = stack[top - 2], *b = stack[top - 1];
            if (n->op == PRIM_REGION_UNION) {
                a[0] = fmin(a[0], b[0]);
                a[1] = fmin(a[1], b[1]);
                a[2] = fmax(a[2], b[2]);
                a[3] = fmax(a[3], b[3]);
            } else if (n->op == PRIM_REGION_INTERSECTION) {
                a[0] = fmax(a[0], b[0]);
                a[1] = fmax(a[1], b[1]);
                a[2] = fmin(a[2], b[2]);
                a[3] = fmin(a[3], b[3]);
            }
            top--;
        }
        if (top > most)
            most = top;
    }
    ok = ok && top == 1;
    if (ok)
        memcpy(out, stack[0], 4 * sizeof *out);
    free(stack);
    *max_stack = most;
    *leaf_spans = spans;
    return ok;
}

const prim_extrusion *prim_extrusion_create(csg_builder *b, const prim_region *r,
                                            double z0, double z1)
{
    double box[4];
    uint32_t max_stack;
    uint64_t leaf_spans;
    if (!(z0 < z1) || r->edge_count > PRIM_EXTRUSION_MAX_EDGES ||
        !program_box(r, box, &max_stack, &leaf_spans))
        return NULL;
    prim_extrusion *e = csg_builder_alloc(b, sizeof *e);
    prim_region_node *nodes = csg_builder_alloc(b, (size_t)r->node_count * sizeof *nodes);
    double *edges = csg_builder_alloc(b, (size_t)(r->edge_count ? r->edge_count : 1) * 4 *
                                             sizeof *edges);
    prim_region_ellipse *ellipses = csg_builder_alloc(
        b, (size_t)(r->ellipse_count ? r->ellipse_count : 1) * sizeof *ellipses);
    uint32_t chunks = (r->edge_count + CHUNK - 1) / CHUNK;
    double *chunk_boxes =
        csg_builder_alloc(b, (size_t)(chunks ? chunks : 1) * 4 * sizeof *chunk_boxes);
    if (!e || !nodes || !edges || !ellipses || !chunk_boxes)
        return NULL;
    memcpy(nodes, r->nodes, (size_t)r->node_count * sizeof *nodes);
    /* Leaf boxes are padded by 1e-9 of the region's size, far more than the
     * rounding of the line-box test and far less than anything visible, so
     * the test never skips a leaf the line touches. */
    double size =
        fmax(fmax(box[2] - box[0], box[3] - box[1]),
             fmax(fmax(fabs(box[0]), fabs(box[1])), fmax(fabs(box[2]), fabs(box[3]))));
    double pad = 1e-9 * size + 1e-300;
    for (uint32_t i = 0; i < r->node_count; i++) {
        nodes[i].box[0] -= pad;
        nodes[i].box[1] -= pad;
        nodes[i].box[2] += pad;
        nodes[i].box[3] += pad;
    }
    if (r->edge_count)
        memcpy(edges, r->edges, (size_t)r->edge_count * 4 * sizeof *edges);
    for (uint32_t c = 0; c < chunks; c++) {
        double *cb = &chunk_boxes[4 * c];
        cb[0] = cb[1] = INFINITY;
        cb[2] = cb[3] = -INFINITY;
        uint32_t end =
            r->edge_count - c * CHUNK < CHUNK ? r->edge_count : (c + 1) * CHUNK;
        for (uint32_t i = c * CHUNK; i < end; i++) {
            const double *g = &edges[4 * i];
            cb[0] = fmin(cb[0], fmin(g[0], g[2]));
            cb[1] = fmin(cb[1], fmin(g[1], g[3]));
            cb[2] = fmax(cb[2], fmax(g[0], g[2]));
            cb[3] = fmax(cb[3], fmax(g[1], g[3]));
        }
        cb[0] -= pad;
        cb[1] -= pad;
        cb[2] += pad;
        cb[3] += pad;
    }
    if (r->ellipse_count)
        memcpy(ellipses, r->ellipses, (size_t)r->ellipse_count * sizeof *ellipses);
    e->nodes = nodes;
    e->node_count = r->node_count;
    e->edges = edges;
    e->edge_count = r->edge_count;
    e->chunk_boxes = chunk_boxes;
    e->ellipses = ellipses;
    e->ellipse_count = r->ellipse_count;
    e->max_stack = max_stack;
    e->work_spans = (uint32_t)(2 * leaf_spans + 2);
    e->z0 = z0;
    e->z1 = z1;
    e->bounds.lo = v3(box[0], box[1], z0);
    e->bounds.hi = v3(box[2], box[3], z1);
    return e;
}

/* ---- membership ---- */

static int in_ellipse(const prim_region_ellipse *e, double x, double y)
{
    double px = x - e->c[0], py = y - e->c[1];
    double u = e->m[0][0] * px + e->m[0][1] * py, v = e->m[1][0] * px + e->m[1][1] * py;
    return hypot(u, v) <= 1;
}

/* Even-odd along +x; a point on an edge is inside. */
static int in_polygon(const prim_extrusion *e, const prim_region_node *n, double x,
                      double y)
{
    int in = 0;
    for (uint32_t i = n->index; i < n->index + n->count; i++) {
        const double *g = &e->edges[4 * i];
        double ax = g[0], ay = g[1], bx = g[2], by = g[3];
        double cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
        if (cross == 0 && x >= fmin(ax, bx) && x <= fmax(ax, bx) && y >= fmin(ay, by) &&
            y <= fmax(ay, by))
            return 1;
        if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay))
            in = !in;
    }
    return in;
}

int prim_extrusion_inside_2d(const prim_extrusion *e, double x, double y)
{
    uint8_t stack[PRIM_REGION_MAX_STACK];
    uint32_t top = 0;
    for (uint32_t i = 0; i < e->node_count; i++) {
        const prim_region_node *n = &e->nodes[i];
        switch (n->op) {
        case PRIM_REGION_ELLIPSE:
            stack[top++] = (uint8_t)in_ellipse(&e->ellipses[n->index], x, y);
            break;
        case PRIM_REGION_POLYGON:
            stack[top++] = (uint8_t)in_polygon(e, n, x, y);
            break;
        default: {
            int b = stack[--top], a = stack[top - 1];
            stack[top - 1] = (uint8_t)(n->op == PRIM_REGION_UNION          ? a || b
                                       : n->op == PRIM_REGION_INTERSECTION ? a && b
                                                                           : a && !b);
        }
        }
    }
    return top == 1 && stack[0];
}

int prim_extrusion_inside(const prim *p, vec3 q)
{
    const prim_extrusion *e = p->u.extrusion.ext;
    return e && q.z >= e->z0 && q.z <= e->z1 && prim_extrusion_inside_2d(e, q.x, q.y);
}

/* ---- spans ---- */

typedef struct line2 {
    double ox, oy, dx, dy, dd; /* dd = dx^2 + dy^2 */
    uint32_t leaf;
    int bad; /* a crossing came out NaN */
} line2;

static uint16_t wall_part(uint32_t surface, int side)
{
    return (uint16_t)(PART_WALL + 2 * (surface % PART_RESIDUES) + (side ? 1 : 0));
}

/* a b - c d with the sign of the exact result (Kahan). */
static double diff_of_products(double a, double b, double c, double d)
{
    double w = c * d;
    double e = fma(-c, d, w);
    double f = fma(a, b, -w);
    return f + e;
}

/* Does the line miss the (padded) box? All four corners strictly on one
 * side. */
static int misses_box(const line2 *l, const double box[4])
{
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        double x = box[(k & 1) ? 2 : 0], y = box[(k & 2) ? 3 : 1];
        double s = l->dx * (y - l->oy) - l->dy * (x - l->ox);
        pos += s > 0;
        neg += s < 0;
    }
    return pos == 4 || neg == 4;
}

static uint32_t ellipse_spans(const prim_extrusion *e, const prim_region_node *n,
                              line2 *l, span *out)
{
    const prim_region_ellipse *el = &e->ellipses[n->index];
    double px = l->ox - el->c[0], py = l->oy - el->c[1];
    double u0x = el->m[0][0] * px + el->m[0][1] * py;
    double u0y = el->m[1][0] * px + el->m[1][1] * py;
    double u1x = el->m[0][0] * l->dx + el->m[0][1] * l->dy;
    double u1y = el->m[1][0] * l->dx + el->m[1][1] * l->dy;
    double a = u1x * u1x + u1y * u1y;
    if (!(a > 0) || !isfinite(a))
        return 0;
    double tc = -(u0x * u1x + u0y * u1y) / a;
    double ucx = u0x + tc * u1x, ucy = u0y + tc * u1y;
    double b = ucx * u1x + ucy * u1y; /* ~0 after the shift */
    double len = hypot(ucx, ucy);
    double c = (len - 1) * (len + 1);
    double disc = b * b - a * c;
    if (!(disc >= 0))
        return 0;
    double q = -(b + copysign(sqrt(disc), b));
    double r0 = q == 0 ? 0 : q / a, r1 = q == 0 ? 0 : c / q;
    double t0 = tc + fmin(r0, r1), t1 = tc + fmax(r0, r1);
    if (!isfinite(t0) || !isfinite(t1)) {
        l->bad = 1;
        return 0;
    }
    uint16_t part = wall_part(e->edge_count + n->index, 0);
    out->in = (span_end){t0, l->leaf, part, 0};
    out->out = (span_end){t1, l->leaf, part, 0};
    return 1;
}

static span_end *end_at(span *v, uint32_t k)
{
    return (k & 1) ? &v[k >> 1].out : &v[k >> 1].in;
}

static void sift(span *v, uint32_t root, uint32_t n)
{
    for (;;) {
        uint32_t child = 2 * root + 1;
        if (child >= n)
            return;
        if (child + 1 < n && end_at(v, child + 1)->t > end_at(v, child)->t)
            child++;
        if (!(end_at(v, child)->t > end_at(v, root)->t))
            return;
        span_end tmp = *end_at(v, root);
        *end_at(v, root) = *end_at(v, child);
        *end_at(v, child) = tmp;
        root = child;
    }
}

/* Heap sort of the first n ends of v by t, in place. */
static void sort_ends(span *v, uint32_t n)
{
    for (uint32_t i = n / 2; i-- > 0;)
        sift(v, i, n);
    for (uint32_t i = n; i-- > 1;) {
        span_end tmp = *end_at(v, 0);
        *end_at(v, 0) = *end_at(v, i);
        *end_at(v, i) = tmp;
        sift(v, 0, i);
    }
}

static uint32_t polygon_spans(const prim_extrusion *e, const prim_region_node *n,
                              line2 *l, span *out)
{
    uint32_t room = 2 * (n->count / 2), k = 0, end = n->index + n->count;
    for (uint32_t i = n->index; i < end; i++) {
        if ((i == n->index || i % CHUNK == 0) &&
            misses_box(l, &e->chunk_boxes[4 * (i / CHUNK)])) {
            /* none of this chunk's edges meets the line: skip to the next */
            i = (i / CHUNK + 1) * CHUNK - 1;
            continue;
        }
        const double *g = &e->edges[4 * i];
        double sa = diff_of_products(l->dx, g[1] - l->oy, l->dy, g[0] - l->ox);
        double sb = diff_of_products(l->dx, g[3] - l->oy, l->dy, g[2] - l->ox);
        if ((sa > 0) == (sb > 0))
            continue;
        if (k == room)
            break; /* cannot happen: the paths are closed (see above) */
        double lambda = sa / (sa - sb);
        double qx = g[0] + lambda * (g[2] - g[0]), qy = g[1] + lambda * (g[3] - g[1]);
        double t = ((qx - l->ox) * l->dx + (qy - l->oy) * l->dy) / l->dd;
        if (isnan(t)) {
            l->bad = 1;
            return 0;
        }
        /* side 1 while the left normal points along the line (sa > 0);
         * exits turn it round below */
        *end_at(out, k++) = (span_end){t, l->leaf, wall_part(i, sa > 0), 0};
    }
    k &= ~1u;
    sort_ends(out, k);
    for (uint32_t i = 1; i < k; i += 2)
        end_at(out, i)->part ^= 1;
    return span_regularize(out, k / 2, 0);
}

/* The region's spans along the line into w (room e->work_spans); returns
 * their count. */
static uint32_t region_spans(const prim_extrusion *e, line2 *l, span *w)
{
    uint32_t counts[PRIM_REGION_MAX_STACK];
    uint32_t top = 0, used = 0;
    for (uint32_t i = 0; i < e->node_count && !l->bad; i++) {
        const prim_region_node *n = &e->nodes[i];
        if (n->op == PRIM_REGION_ELLIPSE || n->op == PRIM_REGION_POLYGON) {
            uint32_t k = 0;
            if (!misses_box(l, n->box))
                k = n->op == PRIM_REGION_ELLIPSE ? ellipse_spans(e, n, l, w + used)
                                                 : polygon_spans(e, n, l, w + used);
            counts[top++] = k;
            used += k;
            continue;
        }
        uint32_t nb = counts[--top], na = counts[--top];
        span_list a = {w + used - na - nb, na}, b = {w + used - nb, nb};
        span_op op = n->op == PRIM_REGION_UNION          ? SPAN_UNION
                     : n->op == PRIM_REGION_INTERSECTION ? SPAN_INTERSECTION
                                                         : SPAN_DIFFERENCE;
        span *r = w + used;
        uint32_t nr = span_merge(op, a, b, r);
        nr = span_regularize(r, nr, 0);
        memmove(a.v, r, (size_t)nr * sizeof *r);
        used = used - na - nb + nr;
        counts[top++] = nr;
    }
    return l->bad || top != 1 ? 0 : counts[0];
}

uint32_t prim_extrusion_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                              uint32_t cap)
{
    const prim_extrusion *e = p->u.extrusion.ext;
    if (!e || cap == 0)
        return 0;
    /* the slab */
    double tz0 = -INFINITY, tz1 = INFINITY;
    uint16_t pz0 = PART_BOTTOM, pz1 = PART_TOP;
    if (d.z == 0) {
        if (!(o.z >= e->z0 && o.z <= e->z1))
            return 0;
    } else {
        double ta = (e->z0 - o.z) / d.z, tb = (e->z1 - o.z) / d.z;
        tz0 = d.z > 0 ? ta : tb;
        tz1 = d.z > 0 ? tb : ta;
        if (d.z < 0) {
            pz0 = PART_TOP;
            pz1 = PART_BOTTOM;
        }
        if (!isfinite(tz0) || !isfinite(tz1))
            return 0;
    }
    line2 l = {o.x, o.y, d.x, d.y, d.x * d.x + d.y * d.y, leaf, 0};
    /* A shadow too short for its square to be a normal number is a point
     * (its motion across the slab is below 1e-150 of the slab's t range). */
    if (!(l.dd >= DBL_MIN)) {
        if (!isfinite(tz0) || !isfinite(tz1) || !prim_extrusion_inside_2d(e, o.x, o.y))
            return 0;
        out[0].in = (span_end){tz0, leaf, pz0, 0};
        out[0].out = (span_end){tz1, leaf, pz1, 0};
        return 1;
    }
    span local[LOCAL_SPANS];
    span *w = cap >= e->work_spans ? out : e->work_spans <= LOCAL_SPANS ? local : NULL;
    if (!w)
        return 0;
    uint32_t n = region_spans(e, &l, w), k = 0;
    for (uint32_t i = 0; i < n && k < cap; i++) {
        span s = w[i];
        if (s.in.t < tz0)
            s.in = (span_end){tz0, leaf, pz0, 0};
        if (s.out.t > tz1)
            s.out = (span_end){tz1, leaf, pz1, 0};
        if (!(s.in.t <= s.out.t))
            continue;
        /* fold a subtrahend's flip into its wall's side */
        if (s.in.flip && s.in.part >= PART_WALL)
            s.in.part ^= 1;
        if (s.out.flip && s.out.part >= PART_WALL)
            s.out.part ^= 1;
        s.in.flip = s.out.flip = 0;
        out[k++] = s;
    }
    return k;
}

/* ---- normals ---- */

static vec3 surface_normal(const prim_extrusion *e, uint32_t g, double x, double y)
{
    if (g < e->edge_count) {
        const double *v = &e->edges[4 * g];
        return v3(-(v[3] - v[1]), v[2] - v[0], 0);
    }
    const prim_region_ellipse *el = &e->ellipses[g - e->edge_count];
    double px = x - el->c[0], py = y - el->c[1];
    double u = el->m[0][0] * px + el->m[0][1] * py,
           v = el->m[1][0] * px + el->m[1][1] * py;
    vec3 n = v3(el->m[0][0] * u + el->m[1][0] * v, el->m[0][1] * u + el->m[1][1] * v, 0);
    /* the centre is no surface point; any direction will do */
    return v3_dot(n, n) > 0 ? n : v3(1, 0, 0);
}

/* Distance-like measure from (x, y) to surface g, to pick among surfaces
 * sharing a part. */
static double surface_distance(const prim_extrusion *e, uint32_t g, double x, double y)
{
    if (g < e->edge_count) {
        const double *v = &e->edges[4 * g];
        double ex = v[2] - v[0], ey = v[3] - v[1];
        double s = ((x - v[0]) * ex + (y - v[1]) * ey) / (ex * ex + ey * ey);
        s = fmin(1, fmax(0, s));
        return hypot(x - (v[0] + s * ex), y - (v[1] + s * ey));
    }
    const prim_region_ellipse *el = &e->ellipses[g - e->edge_count];
    double px = x - el->c[0], py = y - el->c[1];
    double u = el->m[0][0] * px + el->m[0][1] * py,
           v = el->m[1][0] * px + el->m[1][1] * py;
    vec3 n = surface_normal(e, g, x, y);
    /* |f| / |grad f| for f = |u|^2 - 1 */
    return fabs(u * u + v * v - 1) / (2 * v3_length(n));
}

vec3 prim_extrusion_normal(const prim *p, vec3 q, uint16_t part)
{
    const prim_extrusion *e = p->u.extrusion.ext;
    if (part == PART_BOTTOM)
        return v3(0, 0, -1);
    if (!e || part == PART_TOP)
        return v3(0, 0, 1);
    uint32_t residue = (uint32_t)(part - PART_WALL) / 2;
    uint32_t surfaces = e->edge_count + e->ellipse_count;
    if (residue >= surfaces)
        return v3(0, 0, 1);
    uint32_t best = residue;
    if (surfaces > PART_RESIDUES) {
        double best_dist = INFINITY;
        for (uint32_t g = residue; g < surfaces; g += PART_RESIDUES) {
            double dist = surface_distance(e, g, q.x, q.y);
            if (dist < best_dist) {
                best_dist = dist;
                best = g;
            }
        }
    }
    vec3 n = surface_normal(e, best, q.x, q.y);
    return (part - PART_WALL) & 1 ? v3_neg(n) : n;
}

uint32_t prim_extrusion_max_spans(const prim *p)
{
    const prim_extrusion *e = p->u.extrusion.ext;
    return e ? e->work_spans : 1;
}
