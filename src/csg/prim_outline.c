/* Outline prisms: a region of the xy plane bounded by closed contours of
 * lines and quadratic and cubic Bezier curves, extruded over z0 <= z <= z1.
 * text() builds these from glyph outlines, so extruded text is exactly its
 * curves, not a polygon.
 *
 * Region: a point p of the plane is inside when the winding number of the
 * contours about it is not zero (the nonzero rule, OpenSCAD's union of
 * glyph polygons).
 *
 * Ray: o + t d. The z slab gives the window t in [ta, tb] (the whole line
 * when d.z = 0 and o.z is within the slab, nothing when it is not). The
 * ray's xy projection is the line L(t) = o_xy + t d_xy. With the line's
 * left normal n = (-d.y, d.x), a segment B(s), s in [0, 1], has the signed
 * distance
 *   f(s) = n . (B(s) - o_xy) = sum_i f_i b_i(s),   f_i = n . (P_i - o_xy),
 * a Bernstein polynomial of the segment's degree in the f values of its
 * control points P_i. The line crosses the segment where f changes class
 * (f >= 0 or f < 0): the class at s = 0 and s = 1 comes from the end points
 * themselves, so two segments sharing an end point agree on it exactly,
 * and a line through a vertex or along an edge is counted consistently
 * (a crossing there is counted once, a touch twice with opposite signs).
 * Between the end points, the roots of f' (none for a line, one for a
 * quadratic, up to two for a cubic: a stable quadratic formula) split
 * [0, 1] into pieces where f is monotone, so a change of class between two
 * consecutive break points holds exactly one crossing; it is found by
 * bisection on the class (which cannot miss it and needs no derivative),
 * to the last bit of s. At the crossing B(s) gives
 *   t = d_xy . (B(s) - o_xy) / |d_xy|^2
 * and the winding number of the line's points changes by +1 where f
 * decreases (the contour passes from the line's left to its right, as a
 * counter-clockwise contour does where the line enters it) and by -1 where
 * it increases.
 *
 * Spans: the winding number at ta is the sum of the changes at crossings
 * with t < ta (the line far behind is outside every contour); the
 * crossings within the window are sorted and walked; the ray is inside
 * where the winding number is not zero, and the window's ends are the
 * caps. At most PRIM_OUTLINE_MAX_CROSSINGS crossings in the window are
 * kept, the smallest t first, and at most prim_max_spans spans written;
 * past either, the last span is stretched to the last crossing in the
 * window (the spans before it, and every first hit, stay exact; only the
 * far side of a very long string seen along its length is filled).
 *
 * A ray whose xy direction is under 1e-12 of its z direction moves less
 * than 1e-12 of the slab's height sideways inside it: it is taken as
 * vertical, inside over the whole window when the point of the line at the
 * window's middle is inside the region.
 *
 * Normals: caps are -z and +z. A wall's part holds the segment's index
 * (modulo PRIM_OUTLINE_WALL_PARTS), which sixteenth of its parameter range
 * the crossing lies in (so a cubic that loops back near itself is not
 * asked about the wrong branch) and which side is out: entering the
 * region the outward normal is against d_xy, so it is the tangent turned
 * clockwise, (B'.y, -B'.x), when f decreases there; leaving, when f
 * increases. The normal at a hit point q is that turn of B'(s) at the s
 * of the segment closest to q within that sixteenth (a coarse search
 * refined by Newton steps; among segments sharing the index residue, the
 * closest wins).
 *
 * Membership: the winding number of q from the crossings of the line
 * through q along +x with t < 0; a crossing at t = 0 puts q on the
 * boundary, which is inside (closed).
 *
 * Hierarchy: median splits of the segments' box centres along the wider
 * axis down to 4 segments a leaf (depth at most log2(n) + 1 < 64). Boxes
 * hold the control points (the convex hull holds the curve), padded by
 * 1e-9 of the outline's extent so a rounding in the line-box test never
 * drops a segment. A box whose corners lie strictly on one side of the
 * line holds no crossing; a box entirely beyond tb holds none that
 * matter.
 */
#include "csg/prim_outline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "csg/csg.h"

enum { LEAF_SIZE = 4, STACK = 64 };

/* ---- Bezier evaluation ---- */

/* The Bernstein polynomial of degree deg with coefficients c at s, by de
 * Casteljau's steps written as (1 - s) a + s b, exact at s = 0 and s = 1. */
static double bern(const double *c, uint32_t deg, double s)
{
    double w[4];
    for (uint32_t i = 0; i <= deg; i++)
        w[i] = c[i];
    double r = 1 - s;
    for (uint32_t k = deg; k > 0; k--)
        for (uint32_t i = 0; i < k; i++)
            w[i] = r * w[i] + s * w[i + 1];
    return w[0];
}

/* Derivative (with respect to s) of the Bernstein polynomial. */
static double bern_d(const double *c, uint32_t deg, double s)
{
    double g[3];
    for (uint32_t i = 0; i < deg; i++)
        g[i] = (double)deg * (c[i + 1] - c[i]);
    return deg == 1 ? g[0] : bern(g, deg - 1, s);
}

/* The roots in (0, 1) of the derivative of a Bernstein polynomial of
 * degree <= 3, sorted; returns their count (0 to 2). */
static uint32_t critical_points(const double *c, uint32_t deg, double out[2])
{
    if (deg < 2)
        return 0;
    double g0 = deg * (c[1] - c[0]), g1 = deg * (c[2] - c[1]);
    uint32_t n = 0;
    if (deg == 2) {
        /* g0 (1 - s) + g1 s */
        if ((g0 < 0) != (g1 < 0) && g0 != g1) {
            double s = g0 / (g0 - g1);
            if (s > 0 && s < 1)
                out[n++] = s;
        }
        return n;
    }
    double g2 = deg * (c[3] - c[2]);
    /* g0 (1-s)^2 + 2 g1 s (1-s) + g2 s^2 = A s^2 + B s + C */
    double A = g0 - 2 * g1 + g2, B = 2 * (g1 - g0), C = g0;
    double roots[2];
    uint32_t k = 0;
    double scale = fmax(fabs(g0), fmax(fabs(g1), fabs(g2)));
    if (!(scale > 0))
        return 0;
    if (fabs(A) <= 1e-14 * scale) {
        if (B != 0)
            roots[k++] = -C / B;
    } else {
        double disc = B * B - 4 * A * C;
        if (disc >= 0) {
            double q = -0.5 * (B + copysign(sqrt(disc), B));
            roots[k++] = q / A;
            if (q != 0)
                roots[k++] = C / q;
        }
    }
    for (uint32_t i = 0; i < k; i++)
        if (roots[i] > 0 && roots[i] < 1)
            out[n++] = roots[i];
    if (n == 2 && out[0] > out[1]) {
        double tmp = out[0];
        out[0] = out[1];
        out[1] = tmp;
    }
    return n;
}

/* ---- line crossings ---- */

uint32_t prim_outline_cross(const outline_seg *s, const double o[2], const double d[2],
                            double t[3], int dw[3], double u[3])
{
    uint32_t deg = s->degree;
    double f[4];
    double nx = -d[1], ny = d[0];
    for (uint32_t i = 0; i <= deg; i++)
        f[i] = nx * (s->x[i] - o[0]) + ny * (s->y[i] - o[1]);
    double bs[4], bf[4];
    uint32_t nb = 0;
    bs[nb] = 0;
    bf[nb++] = f[0];
    double crit[2];
    uint32_t nc = critical_points(f, deg, crit);
    for (uint32_t i = 0; i < nc; i++) {
        bs[nb] = crit[i];
        bf[nb++] = bern(f, deg, crit[i]);
    }
    bs[nb] = 1;
    bf[nb++] = f[deg];
    double dd = d[0] * d[0] + d[1] * d[1];
    uint32_t n = 0;
    for (uint32_t i = 0; i + 1 < nb; i++) {
        int ca = bf[i] >= 0, cb = bf[i + 1] >= 0;
        if (ca == cb)
            continue;
        double sv;
        if (bf[i + 1] == 0) {
            sv = bs[i + 1];
        } else if (bf[i] == 0) {
            sv = bs[i];
        } else {
            double lo = bs[i], hi = bs[i + 1];
            for (int k = 0; k < 80; k++) {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi)
                    break;
                if ((bern(f, deg, mid) >= 0) == ca)
                    lo = mid;
                else
                    hi = mid;
            }
            sv = 0.5 * (lo + hi);
        }
        double px = bern(s->x, deg, sv), py = bern(s->y, deg, sv);
        t[n] = (d[0] * (px - o[0]) + d[1] * (py - o[1])) / dd;
        dw[n] = ca ? 1 : -1; /* + to -: f decreases */
        if (u)
            u[n] = sv;
        n++;
    }
    return n;
}

/* Does the padded box hold a crossing that matters: corners on both sides
 * of the line (or on it), and not all beyond t = tb? */
static int box_relevant(const prim_outline_node *b, const double o[2], const double d[2],
                        double tb)
{
    double nx = -d[1], ny = d[0];
    int neg = 0, pos = 0, before = 0;
    double dd = d[0] * d[0] + d[1] * d[1];
    for (int k = 0; k < 4; k++) {
        double x = (k & 1) ? b->hi[0] : b->lo[0], y = (k & 2) ? b->hi[1] : b->lo[1];
        double f = nx * (x - o[0]) + ny * (y - o[1]);
        if (f < 0)
            neg = 1;
        else
            pos = 1;
        if ((d[0] * (x - o[0]) + d[1] * (y - o[1])) <= tb * dd)
            before = 1;
    }
    return neg && pos && before;
}

typedef struct crossing {
    double t;
    int dw;           /* +1 or -1 */
    uint32_t segment; /* index in segs */
    double u;         /* the segment's parameter there */
} crossing;

typedef struct crossing_set {
    crossing *v;
    uint32_t n, cap;
    int w0;        /* winding number just before ta */
    int overflow;  /* some window crossings were dropped */
    double t_last; /* largest window crossing, dropped or kept */
    int on_ta;     /* a crossing exactly at ta */
} crossing_set;

static void keep_crossing(crossing_set *cs, double t, int dw, uint32_t seg, double u)
{
    if (t > cs->t_last)
        cs->t_last = t;
    if (cs->n < cs->cap) {
        cs->v[cs->n++] = (crossing){t, dw, seg, u};
        return;
    }
    /* full: keep the smallest t; replace the largest when t is smaller */
    cs->overflow = 1;
    uint32_t big = 0;
    for (uint32_t i = 1; i < cs->n; i++)
        if (cs->v[i].t > cs->v[big].t)
            big = i;
    if (t < cs->v[big].t)
        cs->v[big] = (crossing){t, dw, seg, u};
}

/* Collects the crossings of the line o + t d with the outline: those with
 * t < ta summed into cs->w0, those in [ta, tb] kept in cs. */
static void collect(const prim_outline *m, const double o[2], const double d[2],
                    double ta, double tb, crossing_set *cs)
{
    uint32_t stack[STACK], top = 0;
    stack[top++] = 0;
    while (top) {
        const prim_outline_node *b = &m->nodes[stack[--top]];
        if (!box_relevant(b, o, d, tb))
            continue;
        if (b->count == 0) {
            uint32_t self = (uint32_t)(b - m->nodes);
            stack[top++] = b->start;
            stack[top++] = self + 1;
            continue;
        }
        for (uint32_t i = b->start; i < b->start + b->count; i++) {
            double t[3], u[3];
            int dw[3];
            uint32_t k = prim_outline_cross(&m->segs[i], o, d, t, dw, u);
            for (uint32_t j = 0; j < k; j++) {
                if (!isfinite(t[j]))
                    continue;
                if (t[j] < ta) {
                    cs->w0 += dw[j];
                } else if (t[j] <= tb) {
                    if (t[j] == ta)
                        cs->on_ta = 1;
                    keep_crossing(cs, t[j], dw[j], i, u[j]);
                }
            }
        }
    }
}

static int crossing_less(const void *a, const void *b)
{
    const crossing *x = a, *y = b;
    if (x->t != y->t)
        return x->t < y->t ? -1 : 1;
    return (x->segment > y->segment) - (x->segment < y->segment);
}

static uint16_t wall_part(const crossing *x, int right)
{
    uint32_t bin = (uint32_t)(x->u * PRIM_OUTLINE_BINS);
    if (bin >= PRIM_OUTLINE_BINS)
        bin = PRIM_OUTLINE_BINS - 1;
    uint32_t code = (x->segment % PRIM_OUTLINE_WALL_PARTS) * PRIM_OUTLINE_BINS + bin;
    return (uint16_t)(2 + code) | (uint16_t)(right ? PRIM_OUTLINE_PART_RIGHT : 0);
}

/* Winding number of the plane point (x, y); on the boundary counts as 1. */
static int winding(const prim_outline *m, double x, double y)
{
    crossing none[1];
    crossing_set cs = {none, 0, 1, 0, 0, -INFINITY, 0};
    double o[2] = {x, y}, d[2] = {1, 0};
    collect(m, o, d, 0, 0, &cs);
    if (cs.n > 0 || cs.on_ta)
        return 1;
    return cs.w0;
}

uint32_t prim_outline_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap)
{
    const prim_outline *m = p->u.outline.outline;
    double ta, tb;
    uint16_t part_a, part_b;
    if (d.z != 0) {
        double t0 = (m->z0 - o.z) / d.z, t1 = (m->z1 - o.z) / d.z;
        int up = d.z > 0;
        ta = up ? t0 : t1;
        tb = up ? t1 : t0;
        part_a = up ? PRIM_OUTLINE_PART_BOTTOM : PRIM_OUTLINE_PART_TOP;
        part_b = up ? PRIM_OUTLINE_PART_TOP : PRIM_OUTLINE_PART_BOTTOM;
        if (!(ta < tb) || !isfinite(ta) || !isfinite(tb))
            return 0;
    } else {
        if (!(o.z >= m->z0 && o.z <= m->z1))
            return 0;
        ta = -INFINITY;
        tb = INFINITY;
        part_a = part_b = PRIM_OUTLINE_PART_TOP; /* never used: no cap is met */
    }
    if (cap == 0)
        return 0;
    double dd = d.x * d.x + d.y * d.y;
    if (!(dd > 1e-24 * d.z * d.z)) {
        double tm = 0.5 * (ta + tb);
        if (winding(m, o.x + tm * d.x, o.y + tm * d.y) == 0)
            return 0;
        out[0].in = (span_end){ta, leaf, part_a, 0};
        out[0].out = (span_end){tb, leaf, part_b, 0};
        return 1;
    }
    crossing buf[PRIM_OUTLINE_MAX_CROSSINGS];
    crossing_set cs = {buf, 0, PRIM_OUTLINE_MAX_CROSSINGS, 0, 0, -INFINITY, 0};
    double o2[2] = {o.x, o.y}, d2[2] = {d.x, d.y};
    collect(m, o2, d2, ta, tb, &cs);
    qsort(cs.v, cs.n, sizeof *cs.v, crossing_less);
    uint32_t limit = prim_outline_max_spans(p);
    if (limit > cap)
        limit = cap;
    uint32_t n = 0;
    int w = cs.w0;
    if (w != 0) {
        if (!isfinite(ta))
            w = 0; /* inconsistent: the far line is outside */
        else
            out[n].in = (span_end){ta, leaf, part_a, 0};
    }
    int open = w != 0;
    for (uint32_t i = 0; i < cs.n; i++) {
        const crossing *x = &cs.v[i];
        int nw = w + x->dw;
        /* f decreases at dw = +1 */
        if (w == 0 && nw != 0) {
            if (n == limit)
                break;
            out[n].in = (span_end){x->t, leaf, wall_part(x, x->dw > 0), 0};
            open = 1;
        } else if (w != 0 && nw == 0) {
            out[n].out = (span_end){x->t, leaf, wall_part(x, x->dw < 0), 0};
            open = 0;
            n++;
            if (n == limit) {
                w = nw;
                if (i + 1 < cs.n) {
                    /* cap reached: stretch the last span to the last crossing */
                    out[n - 1].out =
                        (span_end){cs.v[cs.n - 1].t, leaf,
                                   wall_part(&cs.v[cs.n - 1], cs.v[cs.n - 1].dw < 0), 0};
                }
                break;
            }
        }
        w = nw;
    }
    if (open) {
        if (isfinite(tb) && !cs.overflow) {
            out[n].out = (span_end){tb, leaf, part_b, 0};
            n++;
        } else if (cs.overflow) {
            out[n].out = (span_end){fmin(cs.t_last, tb), leaf, part_b, 0};
            n++;
        }
        /* else: inconsistent crossings on an infinite window; dropped */
    } else if (cs.overflow && n > 0 && n < limit) {
        if (cs.t_last > out[n - 1].out.t)
            out[n - 1].out.t = cs.t_last;
    }
    /* zero-length spans (a touch) are left to the caller's regularisation,
     * but a span must have in <= out */
    return n;
}

/* ---- normals ---- */

/* Refines u towards the point of s closest to (x, y) by Newton steps on
 * g(u) = (B(u) - q) . B'(u), kept within [lo, hi]; returns the distance
 * squared at the result. */
static double refine(const outline_seg *s, double x, double y, double lo, double hi,
                     double *u)
{
    uint32_t deg = s->degree;
    double best = *u;
    double ex = bern(s->x, deg, best) - x, ey = bern(s->y, deg, best) - y;
    double bd = ex * ex + ey * ey;
    for (int it = 0; it < 16; it++) {
        double bx = bern(s->x, deg, best) - x, by = bern(s->y, deg, best) - y;
        double tx = bern_d(s->x, deg, best), ty = bern_d(s->y, deg, best);
        /* B'' by a difference of B' (exact for a quadratic's linear B') */
        double h = 1e-6;
        double ax = (bern_d(s->x, deg, best + h) - bern_d(s->x, deg, best - h)) / (2 * h);
        double ay = (bern_d(s->y, deg, best + h) - bern_d(s->y, deg, best - h)) / (2 * h);
        double g = bx * tx + by * ty, gd = tx * tx + ty * ty + bx * ax + by * ay;
        if (!(gd > 0))
            break;
        double next = fmin(hi, fmax(lo, best - g / gd));
        double fx = bern(s->x, deg, next) - x, fy = bern(s->y, deg, next) - y;
        double e = fx * fx + fy * fy;
        if (!(e < bd))
            break;
        bd = e;
        best = next;
    }
    *u = best;
    return bd;
}

/* The parameter in [a, b] of the point of s closest to (x, y): every
 * local minimum of 16 samples refined, the closest kept (a cubic may pass
 * near the point on two branches); *dist2 is its distance squared. */
static double closest_s(const outline_seg *s, double x, double y, double a, double b,
                        double *dist2)
{
    enum { SAMPLES = 16 };
    uint32_t deg = s->degree;
    double e[SAMPLES + 1];
    double step = (b - a) / SAMPLES;
    for (int k = 0; k <= SAMPLES; k++) {
        double u = a + k * step;
        double dx = bern(s->x, deg, u) - x, dy = bern(s->y, deg, u) - y;
        e[k] = dx * dx + dy * dy;
    }
    double best = 0, bd = INFINITY;
    for (int k = 0; k <= SAMPLES; k++) {
        if ((k > 0 && e[k - 1] < e[k]) || (k < SAMPLES && e[k + 1] < e[k]))
            continue;
        double u = a + k * step;
        double d2 = refine(s, x, y, fmax(a, u - step), fmin(b, u + step), &u);
        if (d2 < bd) {
            bd = d2;
            best = u;
        }
    }
    *dist2 = bd;
    return best;
}

vec3 prim_outline_normal(const prim *p, vec3 q, uint16_t part)
{
    const prim_outline *m = p->u.outline.outline;
    if (part == PRIM_OUTLINE_PART_BOTTOM)
        return v3(0, 0, -1);
    if (part == PRIM_OUTLINE_PART_TOP)
        return v3(0, 0, 1);
    int right = (part & PRIM_OUTLINE_PART_RIGHT) != 0;
    uint32_t code = (uint32_t)(part & ~PRIM_OUTLINE_PART_RIGHT) - 2;
    uint32_t residue = code / PRIM_OUTLINE_BINS, bin = code % PRIM_OUTLINE_BINS;
    /* the bin, widened by a quarter bin each way for a rounding at its edge */
    double a = fmax(0, (bin - 0.25) / PRIM_OUTLINE_BINS);
    double b = fmin(1, (bin + 1.25) / PRIM_OUTLINE_BINS);
    double best_d = INFINITY, best_s = 0;
    const outline_seg *best = NULL;
    for (uint32_t i = residue; i < m->seg_count; i += PRIM_OUTLINE_WALL_PARTS) {
        double e;
        double s = closest_s(&m->segs[i], q.x, q.y, a, b, &e);
        if (e < best_d) {
            best_d = e;
            best_s = s;
            best = &m->segs[i];
        }
    }
    if (!best)
        return v3(0, 0, 1);
    uint32_t deg = best->degree;
    double tx = bern_d(best->x, deg, best_s), ty = bern_d(best->y, deg, best_s);
    if (!(tx * tx + ty * ty > 0)) {
        /* a degenerate end (control point on the end point): the chord */
        tx = best->x[deg] - best->x[0];
        ty = best->y[deg] - best->y[0];
    }
    return right ? v3(ty, -tx, 0) : v3(-ty, tx, 0);
}

int prim_outline_inside(const prim *p, vec3 q)
{
    const prim_outline *m = p->u.outline.outline;
    if (!(q.z >= m->z0 && q.z <= m->z1))
        return 0;
    return winding(m, q.x, q.y) != 0;
}

uint32_t prim_outline_max_spans(const prim *p)
{
    /* a line crosses a segment at most 3 times; spans need two crossings */
    uint64_t n = (uint64_t)p->u.outline.outline->seg_count * 3 / 2 + 1;
    return n < PRIM_OUTLINE_MAX_SPANS ? (uint32_t)n : PRIM_OUTLINE_MAX_SPANS;
}

/* ---- building ---- */

typedef struct keyed {
    double key;
    uint32_t index;
} keyed;

static int keyed_less(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    return (x->index > y->index) - (x->index < y->index);
}

typedef struct build_state {
    const outline_seg *segs;
    keyed *order;
    prim_outline_node *nodes;
    uint32_t node_count;
    double pad;
} build_state;

static void seg_box(const outline_seg *s, double lo[2], double hi[2])
{
    lo[0] = hi[0] = s->x[0];
    lo[1] = hi[1] = s->y[0];
    for (uint32_t i = 1; i <= s->degree; i++) {
        lo[0] = fmin(lo[0], s->x[i]);
        hi[0] = fmax(hi[0], s->x[i]);
        lo[1] = fmin(lo[1], s->y[i]);
        hi[1] = fmax(hi[1], s->y[i]);
    }
}

/* Builds the subtree over order[lo .. hi); returns its index. The depth is
 * that of median splits, log2 of the count. */
static uint32_t build_node(build_state *st, uint32_t lo, uint32_t hi)
{
    uint32_t index = st->node_count++;
    prim_outline_node *n = &st->nodes[index];
    double blo[2] = {INFINITY, INFINITY}, bhi[2] = {-INFINITY, -INFINITY};
    double clo[2] = {INFINITY, INFINITY}, chi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = lo; i < hi; i++) {
        double a[2], b[2];
        seg_box(&st->segs[st->order[i].index], a, b);
        for (int k = 0; k < 2; k++) {
            blo[k] = fmin(blo[k], a[k]);
            bhi[k] = fmax(bhi[k], b[k]);
            double c = 0.5 * (a[k] + b[k]);
            clo[k] = fmin(clo[k], c);
            chi[k] = fmax(chi[k], c);
        }
    }
    for (int k = 0; k < 2; k++) {
        n->lo[k] = blo[k] - st->pad;
        n->hi[k] = bhi[k] + st->pad;
    }
    if (hi - lo <= LEAF_SIZE) {
        n->start = lo;
        n->count = hi - lo;
        return index;
    }
    int axis = (chi[0] - clo[0]) >= (chi[1] - clo[1]) ? 0 : 1;
    for (uint32_t i = lo; i < hi; i++) {
        double a[2], b[2];
        seg_box(&st->segs[st->order[i].index], a, b);
        st->order[i].key = 0.5 * (a[axis] + b[axis]);
    }
    qsort(st->order + lo, hi - lo, sizeof *st->order, keyed_less);
    uint32_t mid = lo + (hi - lo) / 2;
    n->count = 0;
    build_node(st, lo, mid);
    uint32_t right = build_node(st, mid, hi);
    st->nodes[index].start = right;
    return index;
}

/* Extremes of one coordinate of a segment: its ends and the roots of the
 * derivative. */
static void coord_range(const double *c, uint32_t deg, double *lo, double *hi)
{
    *lo = fmin(c[0], c[deg]);
    *hi = fmax(c[0], c[deg]);
    double r[2];
    uint32_t k = critical_points(c, deg, r);
    for (uint32_t i = 0; i < k; i++) {
        double v = bern(c, deg, r[i]);
        *lo = fmin(*lo, v);
        *hi = fmax(*hi, v);
    }
}

const prim_outline *prim_outline_create(struct csg_builder *b, const outline_seg *segs,
                                        uint32_t count, double z0, double z1)
{
    if (count == 0)
        return NULL;
    build_state st;
    memset(&st, 0, sizeof st);
    st.segs = segs;
    st.order = malloc((size_t)count * sizeof *st.order);
    st.nodes = malloc((size_t)2 * count * sizeof *st.nodes);
    const prim_outline *result = NULL;
    if (!st.order || !st.nodes)
        goto done;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < count; i++) {
        st.order[i] = (keyed){0, i};
        double a, c;
        coord_range(segs[i].x, segs[i].degree, &a, &c);
        lo[0] = fmin(lo[0], a);
        hi[0] = fmax(hi[0], c);
        coord_range(segs[i].y, segs[i].degree, &a, &c);
        lo[1] = fmin(lo[1], a);
        hi[1] = fmax(hi[1], c);
    }
    double ext =
        fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]),
             fmax(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fabs(lo[1]), fabs(hi[1]))));
    st.pad = 1e-9 * ext + 1e-300;
    build_node(&st, 0, count);
    prim_outline *m = csg_builder_alloc(b, sizeof *m);
    outline_seg *v = csg_builder_alloc(b, (size_t)count * sizeof *v);
    prim_outline_node *nodes =
        csg_builder_alloc(b, (size_t)st.node_count * sizeof *nodes);
    if (!m || !v || !nodes)
        goto done;
    for (uint32_t i = 0; i < count; i++)
        v[i] = segs[st.order[i].index];
    memcpy(nodes, st.nodes, (size_t)st.node_count * sizeof *nodes);
    m->segs = v;
    m->nodes = nodes;
    m->seg_count = count;
    m->node_count = st.node_count;
    m->z0 = z0;
    m->z1 = z1;
    m->bounds.lo = v3(lo[0], lo[1], z0);
    m->bounds.hi = v3(hi[0], hi[1], z1);
    result = m;
done:
    free(st.order);
    free(st.nodes);
    return result;
}
