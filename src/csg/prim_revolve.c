/* Solid of revolution: rotate_extrude's exact leaf.
 *
 * The profile is a set of regions in the (r, z) half-plane r >= 0: polygons
 * (their edges; a point is in a polygon when a half-line from it crosses
 * the polygon's edges an odd number of times, OpenSCAD's even-odd reading
 * of paths) and discs. The profile is their union. Revolved about the z
 * axis, the point p = (x, y, z) is inside when (rho, z), rho = |(x, y)|,
 * is in the profile and, for a partial angle, p lies in the wedge between
 * the unit directions `start` and `end` (counter-clockwise, sweep degrees).
 *
 * The ray o + t d, seen in the (r, z) plane, is the trace
 *   r(t)^2 = |o_xy + t d_xy|^2 = A t^2 + 2 B t + C,   z(t) = o_z + t d_z,
 * A = |d_xy|^2, B = o_xy . d_xy, C = |o_xy|^2.
 *
 * Edges, d_z != 0. Then t = (z - o_z) / d_z is a function of z, and the
 * trace is the graph r = rho(z) over the whole z axis. Let
 *   G(r, z) = r^2 - rho(z)^2,
 * a polynomial in (r, z), positive right of the trace. Since r >= 0 on
 * the profile, G = 0 on an edge exactly where the trace crosses it (the
 * mirror branch r = -rho lies in r < 0). Along the edge
 * (r0 + s dr, z0 + s dz), s in [0, 1], G is the quadratic
 *   g(s) = (dr^2 - A tau^2) s^2 + 2 (r0 dr - tau (x0 . d_xy)) s + G(r0, z0)
 * with tau = dz / d_z and x0 the ray's xy point at z0 (a cone, or a
 * cylinder for dr = 0, or a disc for dz = 0, where every root has the same
 * t). Its parity of crossings is decided by signs only: the edge crosses
 * the trace an odd number of times exactly when G differs in sign at its
 * two ends (a zero counting as negative: the trace is taken a hair to the
 * right, so a ray along the axis runs inside a profile that touches the
 * axis, as the solid's interior does), and G at a vertex is one number
 * shared by the vertex's two edges. So each closed contour crosses the
 * trace an even number of times, whatever rounding does to the root
 * positions, and a ray through a vertex counts it once or not at all,
 * consistently. An edge with a sign change gives its one root in [0, 1];
 * an edge without gives two roots when the quadratic has two distinct
 * ones in [0, 1], else none. G at a vertex is (r - rho)(r + rho), the
 * difference of the square roots exact near the trace (Sterbenz), so the
 * sign holds for grazing rays.
 *
 * Edges, d_z = 0. The trace is the half-line z = o_z, r >= r_min (the
 * ray's distance from the axis), covered twice: r falls from infinity to
 * r_min at t_c = -B / A and rises again. Each crossing r* of the line
 * z = o_z with the profile (half-open in z, the usual point-in-polygon
 * rule, so a vertex on the line is counted once) gives
 *   t = t_c -+ sqrt((r* - r_min)(r* + r_min) / A)   when r* >= r_min.
 * Walking from t = -inf (outside every region) through these keeps every
 * region's parity right: the crossings below r_min are never reached, on
 * either side.
 *
 * Discs: the torus (rho - rc)^2 + (z - zc)^2 <= a^2 (prim_torus.c, its
 * quartic isolated by the critical points and polished on the distance
 * function), shifted by zc; a <= rc, so a disc touching the axis is a horn
 * torus.
 *
 * The crossings, each tagged with its region, are sorted (heap sort: no
 * allocation, n log n), and swept: a region's parity flips at each of its
 * crossings, and the line is inside while any region is. Before the sweep
 * the origin moves to the point of the line closest to the profile's
 * middle on the axis, which keeps C accurate for far rays.
 *
 * Wedge (partial angles): the line's xy projection crosses each face's
 * half-line {s e : s >= 0} at most once, so it is in the wedge on at most
 * two stretches, classified by a point inside each piece. The spans of the
 * full solid are clipped to those stretches; a clipped end is on a face,
 * whose outward normal is the face direction turned a quarter away from
 * the wedge. The faces are the profile itself, the end caps.
 *
 * Normals: an edge's outward normal in (r, z) is (dz, -dr) (regions lie
 * left of their edges), turned by the point's azimuth: (n_r x / rho,
 * n_r y / rho, n_z); a disc's is ((rho - rc) x / rho, (rho - rc) y / rho,
 * z - zc).
 *
 * Buffers: at most 2 crossings an edge and 4 a disc, so
 * 2 * PRIM_REVOLVE_MAX_EDGES crossings, on the stack.
 */
#include "csg/prim_revolve.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "csg/prim_curved.h"

typedef struct crossing {
    double t;
    uint32_t region;
    uint16_t part;
} crossing;

static const prim_revolve *rev_of(const prim *p)
{
    return p->u.revolve.rev;
}

/* Is (x, y) in the closed wedge? The axis (0, 0) is. */
static int in_wedge(const prim_revolve *r, double x, double y)
{
    double c0 = r->start[0] * y - r->start[1] * x; /* >= 0: not clockwise of start */
    double c1 = x * r->end[1] - y * r->end[0]; /* >= 0: not counter-clockwise of end */
    if (r->sweep <= 180)
        return c0 >= 0 && c1 >= 0;
    return c0 >= 0 || c1 >= 0;
}

/* The stretches of the line o + t d inside the wedge, at most two, with
 * the face each finite end lies on. Returns their number. The line's xy
 * projection crosses the two faces' planes at most once each, so the
 * wedge's membership is constant on the three pieces between. */
static int wedge_stretches(const prim_revolve *r, vec3 o, vec3 d, double lo[2],
                           double hi[2], uint16_t lo_part[2], uint16_t hi_part[2])
{
    if (d.x == 0 && d.y == 0) {
        if (!in_wedge(r, o.x, o.y))
            return 0;
        lo[0] = -INFINITY;
        hi[0] = INFINITY;
        lo_part[0] = hi_part[0] = PRIM_REVOLVE_PART_START;
        return 1;
    }
    double cut[2];
    uint16_t cut_part[2];
    int n = 0;
    const double *face[2] = {r->start, r->end};
    for (int k = 0; k < 2; k++) {
        const double *e = face[k];
        double den = e[0] * d.y - e[1] * d.x;
        if (den == 0)
            continue; /* parallel: the line never crosses this face's plane */
        /* Where the line crosses the face's plane. On the far side of the
         * axis that is no face, but the cut is kept all the same: pieces
         * are classified by a point inside them, so a cut where nothing
         * changes only splits a piece in two that join again below, and a
         * line through the axis (both cuts at the axis, where rounding
         * puts the crossing on either side) needs both. */
        double t = -(e[0] * o.y - e[1] * o.x) / den;
        if (!isfinite(t))
            continue;
        cut[n] = t;
        cut_part[n] = k == 0 ? PRIM_REVOLVE_PART_START : PRIM_REVOLVE_PART_END;
        n++;
    }
    if (n == 2 && cut[1] < cut[0]) {
        double t = cut[0];
        cut[0] = cut[1];
        cut[1] = t;
        uint16_t q = cut_part[0];
        cut_part[0] = cut_part[1];
        cut_part[1] = q;
    }
    /* Pieces between the cuts; each is classified at a point well inside
     * it: a step of the profile's radius in xy beyond a cut for the
     * unbounded ones, the midpoint for the bounded one. */
    double dxy = hypot(d.x, d.y);
    double step = fmax(r->r_hi, DBL_MIN) / dxy;
    double ends[4] = {-INFINITY, 0, 0, INFINITY};
    uint16_t parts[4] = {PRIM_REVOLVE_PART_START, 0, 0, PRIM_REVOLVE_PART_START};
    for (int k = 0; k < n; k++) {
        ends[k + 1] = cut[k];
        parts[k + 1] = cut_part[k];
    }
    ends[n + 1] = INFINITY;
    int count = 0;
    for (int k = 0; k <= n; k++) {
        double a = ends[k], b = ends[k + 1], t;
        if (n == 0)
            t = 0;
        else if (k == 0)
            t = b - step - fabs(b);
        else if (k == n)
            t = a + step + fabs(a);
        else
            t = 0.5 * (a + b);
        if (!(a <= b) || !in_wedge(r, o.x + t * d.x, o.y + t * d.y))
            continue;
        if (count > 0 && hi[count - 1] == a) {
            hi[count - 1] = b; /* the line passed the axis inside the wedge */
            hi_part[count - 1] = parts[k + 1];
            continue;
        }
        lo[count] = a;
        hi[count] = b;
        lo_part[count] = parts[k];
        hi_part[count] = parts[k + 1];
        count++;
    }
    return count;
}

/* G = r^2 - rho^2 at a profile point (r, z), the trace's rho at z. */
static double trace_g(vec3 o, vec3 d, double r, double z, double *x, double *y)
{
    double tau = (z - o.z) / d.z;
    *x = o.x + tau * d.x;
    *y = o.y + tau * d.y;
    double rho = hypot(*x, *y);
    return (r - rho) * (r + rho);
}

static void sift(crossing *v, uint32_t root, uint32_t n)
{
    for (;;) {
        uint32_t child = 2 * root + 1;
        if (child >= n)
            return;
        if (child + 1 < n && v[child + 1].t > v[child].t)
            child++;
        if (!(v[child].t > v[root].t))
            return;
        crossing c = v[root];
        v[root] = v[child];
        v[child] = c;
        root = child;
    }
}

static void sort_crossings(crossing *v, uint32_t n)
{
    if (n <= 16) {
        for (uint32_t i = 1; i < n; i++) {
            crossing c = v[i];
            uint32_t j = i;
            for (; j > 0 && v[j - 1].t > c.t; j--)
                v[j] = v[j - 1];
            v[j] = c;
        }
        return;
    }
    for (uint32_t i = n / 2; i-- > 0;)
        sift(v, i, n);
    for (uint32_t end = n; end-- > 1;) {
        crossing c = v[0];
        v[0] = v[end];
        v[end] = c;
        sift(v, 0, end);
    }
}

/* Newton steps on the trace's signed distance from the line of edge e,
 *   h(t) = n_r (rho(t) - r0) + n_z (z(t) - z0),
 * from the estimate t. The root found through the edge's parameter s is
 * right in count but can lose digits in t: for a nearly level ray t =
 * t(z0) + s dz / d_z adds large numbers, and the two crossings of an edge
 * with both sides of the trace near the axis are a near-double root in s
 * while far apart in t. In t, near the ray's closest point to the
 * profile, h is well conditioned. A step longer than limit, or one not
 * shorter than the one before, is refused: the estimate stays with its
 * own root. */
static double polish(const prim_revolve_edge *e, vec3 o, vec3 d, double t, double limit)
{
    double n_r = e->z1 - e->z0, n_z = e->r0 - e->r1, last = limit;
    for (int it = 0; it < 4; it++) {
        double x = o.x + t * d.x, y = o.y + t * d.y, rho = hypot(x, y);
        if (!(rho > 0))
            break;
        double h = n_r * (rho - e->r0) + n_z * (o.z + t * d.z - e->z0);
        double dh = n_r * (x * d.x + y * d.y) / rho + n_z * d.z;
        double step = h / dh;
        if (!(fabs(step) < last))
            break;
        t -= step;
        last = fabs(step);
    }
    return t;
}

/* Crossings of the edges for d_z != 0 (see the top). */
static uint32_t edge_crossings_slanted(const prim_revolve *r, vec3 o, vec3 d, crossing *v,
                                       uint32_t n)
{
    double a_xy = d.x * d.x + d.y * d.y;
    /* Newton's reach: a ten-thousandth of the profile's size along the ray */
    double limit = 1e-4 * fmax(r->r_hi, r->z_hi - r->z_lo) / sqrt(v3_dot(d, d));
    for (uint32_t i = 0; i < r->edge_count; i++) {
        const prim_revolve_edge *e = &r->edges[i];
        double xa, ya, xb, yb;
        double ga = trace_g(o, d, e->r0, e->z0, &xa, &ya);
        double gb = trace_g(o, d, e->r1, e->z1, &xb, &yb);
        int odd = (ga > 0) != (gb > 0);
        double ta = (e->z0 - o.z) / d.z, tau = (e->z1 - e->z0) / d.z;
        double dr = e->r1 - e->r0;
        double alpha = dr * dr - a_xy * tau * tau;
        double half_b = e->r0 * dr - tau * (xa * d.x + ya * d.y);
        double s[2];
        int roots = 0;
        if (alpha == 0) {
            if (half_b != 0) {
                s[0] = -ga / (2 * half_b);
                roots = 1;
            }
        } else {
            double disc = half_b * half_b - alpha * ga;
            if (disc >= 0) {
                double q = -(half_b + copysign(sqrt(disc), half_b));
                double r0 = q != 0 ? q / alpha : 0, r1 = q != 0 ? ga / q : 0;
                s[0] = fmin(r0, r1);
                s[1] = fmax(r0, r1);
                roots = 2;
            }
        }
        if (odd) {
            /* One root in [0, 1]: the one nearest it, clamped (rounding can
             * put it a hair outside, or lose it in a negative
             * discriminant, then bisect on the signs). */
            double best = NAN, miss = INFINITY;
            for (int k = 0; k < roots; k++) {
                double m = fmax(0, fmax(-s[k], s[k] - 1));
                if (isfinite(s[k]) && m < miss) {
                    miss = m;
                    best = s[k];
                }
            }
            if (!(miss <= 1e-6)) {
                double lo = 0, hi = 1;
                int pos_lo = ga > 0;
                for (int it = 0; it < 64; it++) {
                    double mid = 0.5 * (lo + hi), x, y;
                    double g = trace_g(o, d, e->r0 + mid * dr,
                                       e->z0 + mid * (e->z1 - e->z0), &x, &y);
                    if ((g > 0) == pos_lo)
                        lo = mid;
                    else
                        hi = mid;
                }
                best = 0.5 * (lo + hi);
            }
            best = fmin(1, fmax(0, best));
            v[n++] = (crossing){polish(e, o, d, ta + best * tau, limit), e->region,
                                (uint16_t)i};
        } else if (e->r0 == 0 && e->r1 == 0) {
            /* An edge on the axis: G = -rho^2 <= 0 along it, touching 0 only
             * where the ray meets the axis; with the trace a hair to the
             * right it is never crossed (a rounded pair of roots there
             * would cut a gap into the solid's interior). */
        } else if (roots == 2 && s[0] >= 0 && s[1] <= 1 && s[0] < s[1]) {
            v[n++] = (crossing){polish(e, o, d, ta + s[0] * tau, limit), e->region,
                                (uint16_t)i};
            v[n++] = (crossing){polish(e, o, d, ta + s[1] * tau, limit), e->region,
                                (uint16_t)i};
        }
    }
    return n;
}

/* Crossings of the edges for d_z = 0 (see the top). */
static uint32_t edge_crossings_level(const prim_revolve *r, vec3 o, vec3 d, crossing *v,
                                     uint32_t n)
{
    double a_xy = d.x * d.x + d.y * d.y;
    double tc = -(o.x * d.x + o.y * d.y) / a_xy;
    double r_min = hypot(o.x + tc * d.x, o.y + tc * d.y);
    for (uint32_t i = 0; i < r->edge_count; i++) {
        const prim_revolve_edge *e = &r->edges[i];
        if ((e->z0 > o.z) == (e->z1 > o.z))
            continue;
        double rs = e->r0 + (o.z - e->z0) * (e->r1 - e->r0) / (e->z1 - e->z0);
        if (!(rs > r_min))
            continue; /* missed, or touched: no crossing (the trace a hair
                         to the right, as above) */
        double h = sqrt((rs - r_min) * (rs + r_min) / a_xy);
        v[n++] = (crossing){tc - h, e->region, (uint16_t)i};
        v[n++] = (crossing){tc + h, e->region, (uint16_t)i};
    }
    return n;
}

uint32_t prim_revolve_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap)
{
    const prim_revolve *r = rev_of(p);
    /* Wedge first: a ray that misses it needs nothing else. */
    double w_lo[2], w_hi[2];
    uint16_t w_lo_part[2], w_hi_part[2];
    int stretches = 1;
    w_lo[0] = -INFINITY;
    w_hi[0] = INFINITY;
    if (r->partial) {
        stretches = wedge_stretches(r, o, d, w_lo, w_hi, w_lo_part, w_hi_part);
        if (stretches == 0)
            return 0;
    }

    /* Move the origin to the point of the line nearest the profile's middle
     * on the axis; t is shifted back at the end. */
    vec3 mid = v3(0, 0, 0.5 * (r->z_lo + r->z_hi));
    double shift = -v3_dot(v3_sub(o, mid), d) / v3_dot(d, d);
    vec3 os = v3_madd(o, d, shift);

    crossing v[2 * PRIM_REVOLVE_MAX_EDGES];
    uint32_t n = 0;
    if (d.z != 0)
        n = edge_crossings_slanted(r, os, d, v, n);
    else
        n = edge_crossings_level(r, os, d, v, n);
    for (uint32_t i = 0; i < r->disc_count; i++) {
        const prim_revolve_disc *c = &r->discs[i];
        prim torus = {.kind = PRIM_TORUS};
        torus.u.torus.major = c->rc;
        torus.u.torus.minor = c->a;
        span s[2];
        uint32_t k =
            prim_torus_spans(&torus, leaf, v3(os.x, os.y, os.z - c->zc), d, s, 2);
        uint16_t part = (uint16_t)(r->edge_count + i);
        for (uint32_t j = 0; j < k; j++) {
            v[n++] = (crossing){s[j].in.t, c->region, part};
            v[n++] = (crossing){s[j].out.t, c->region, part};
        }
    }
    sort_crossings(v, n);

    uint8_t parity[PRIM_REVOLVE_MAX_EDGES];
    memset(parity, 0, r->region_count);
    uint32_t inside = 0, count = 0;
    double t_in = 0;
    uint16_t part_in = 0;
    for (uint32_t i = 0; i < n; i++) {
        parity[v[i].region] ^= 1;
        if (parity[v[i].region]) {
            if (inside++ == 0) {
                t_in = v[i].t;
                part_in = v[i].part;
            }
            continue;
        }
        if (--inside > 0)
            continue;
        /* [t_in, v[i].t] is in the full solid: clip it to the wedge. */
        for (int k = 0; k < stretches && count < cap; k++) {
            double a = shift + t_in, b = shift + v[i].t;
            uint16_t pa = part_in, pb = v[i].part;
            if (w_lo[k] > a) {
                a = w_lo[k];
                pa = w_lo_part[k];
            }
            if (w_hi[k] < b) {
                b = w_hi[k];
                pb = w_hi_part[k];
            }
            if (!(a <= b) || !isfinite(a) || !isfinite(b))
                continue;
            out[count].in = (span_end){a, leaf, pa, 0};
            out[count].out = (span_end){b, leaf, pb, 0};
            count++;
        }
    }
    return count;
}

vec3 prim_revolve_normal(const prim *p, vec3 q, uint16_t part)
{
    const prim_revolve *r = rev_of(p);
    if (part == PRIM_REVOLVE_PART_START)
        return v3(r->start[1], -r->start[0], 0);
    if (part == PRIM_REVOLVE_PART_END)
        return v3(-r->end[1], r->end[0], 0);
    double rho = hypot(q.x, q.y);
    double n_r, n_z;
    if (part < r->edge_count) {
        const prim_revolve_edge *e = &r->edges[part];
        n_r = e->z1 - e->z0;
        n_z = e->r0 - e->r1;
    } else if (part - r->edge_count < r->disc_count) {
        const prim_revolve_disc *c = &r->discs[part - r->edge_count];
        n_r = rho - c->rc;
        n_z = q.z - c->zc;
    } else {
        return v3(0, 0, 1);
    }
    if (rho > 0)
        return v3(n_r * q.x / rho, n_r * q.y / rho, n_z);
    /* On the axis only the axial part is defined. */
    return v3(0, 0, n_z >= 0 ? 1 : -1);
}

int prim_revolve_inside(const prim *p, vec3 q)
{
    const prim_revolve *r = rev_of(p);
    if (r->partial && !in_wedge(r, q.x, q.y))
        return 0;
    double rho = hypot(q.x, q.y);
    for (uint32_t i = 0; i < r->disc_count; i++) {
        const prim_revolve_disc *c = &r->discs[i];
        double dr = rho - c->rc, dz = q.z - c->zc;
        if (dr * dr + dz * dz <= c->a * c->a)
            return 1;
    }
    uint8_t parity[PRIM_REVOLVE_MAX_EDGES];
    memset(parity, 0, r->region_count);
    for (uint32_t i = 0; i < r->edge_count; i++) {
        const prim_revolve_edge *e = &r->edges[i];
        if ((e->z0 > q.z) == (e->z1 > q.z))
            continue;
        double rs = e->r0 + (q.z - e->z0) * (e->r1 - e->r0) / (e->z1 - e->z0);
        if (rho < rs)
            parity[e->region] ^= 1;
    }
    for (uint32_t k = 0; k < r->region_count; k++)
        if (parity[k])
            return 1;
    return 0;
}

bbox prim_revolve_bounds(const prim *p)
{
    const prim_revolve *r = rev_of(p);
    double w = r->r_hi;
    if (!r->partial) {
        bbox b = {{-w, -w, r->z_lo}, {w, w, r->z_hi}};
        return b;
    }
    /* The annular sector r_lo..r_hi over the wedge: its corners, and the
     * outer arc's extremes along the axes that lie in the wedge. */
    bbox b = bbox_empty();
    const double *face[2] = {r->start, r->end};
    for (int k = 0; k < 2; k++) {
        for (int j = 0; j < 2; j++) {
            double s = j ? r->r_hi : r->r_lo;
            b = bbox_add_point(b, v3(s * face[k][0], s * face[k][1], r->z_lo));
        }
    }
    static const double axes[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int k = 0; k < 4; k++)
        if (in_wedge(r, axes[k][0], axes[k][1]))
            b = bbox_add_point(b, v3(w * axes[k][0], w * axes[k][1], r->z_lo));
    b.lo.z = r->z_lo;
    b.hi.z = r->z_hi;
    return b;
}

uint32_t prim_revolve_max_spans(const prim *p)
{
    const prim_revolve *r = rev_of(p);
    /* Half the crossings, and one more where a wedge stretch splits a span. */
    return r->edge_count + 2 * r->disc_count + 1;
}
