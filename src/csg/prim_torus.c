/* Torus: major radius R about the z axis in the xy plane, minor radius r,
 * 0 < r < R.
 *
 *   implicit   F(p) = (rho - R)^2 + z^2 - r^2 <= 0, rho = |(x, y)|: the
 *              points within r of the circle rho = R, z = 0
 *   quartic    with |p|^2 = x^2 + y^2 + z^2, multiplying F by the positive
 *              (rho + R)^2 + z^2 - r^2 gives the polynomial
 *              q(p) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2),
 *              so along a ray q and F have the same sign and roots
 *   ray        p = c + s u with u = d / |d| and c the point of the line
 *              closest to the centre (shifting there removes the
 *              cancellation of a far origin); with b = c.u, g0 = c.c,
 *              e = g0 + R^2 - r^2, a2 = ux^2 + uy^2, b2 = cx ux + cy uy,
 *              c2 = cx^2 + cy^2:
 *              q(s) = s^4 + 4 b s^3 + (4 b^2 + 2 e - 4 R^2 a2) s^2
 *                     + (4 b e - 8 R^2 b2) s + (e^2 - 4 R^2 c2)
 *   normal     grad F / 2 = ((rho - R) x / rho, (rho - R) y / rho, z)
 *
 * Roots. The closed forms for quartics (Ferrari, Descartes) lose the
 * small roots to cancellation exactly in the cases that matter here (a
 * thin tube, R / r = 1000; a far origin; a grazing ray), and report
 * complex pairs for near-double real roots. Instead the roots are
 * isolated: the real line meets the torus only inside its bounding sphere
 * |p| <= R + r, so s lies in a finite [s_lo, s_hi]; the critical points of
 * q (roots of the cubic q', found the same way from the quadratic q'')
 * cut that range into pieces on which q is monotone, hence holds at most
 * one root. A piece holds a root exactly when F differs in sign at its
 * ends; that root is then polished by safeguarded Newton-bisection on F
 * itself, computed from the point, not from the coefficients, with the
 * larger of the two squares paired with r^2: (rho - R)^2 + (z - r)(z + r)
 * when |z| >= |rho - R|, else (rho - R - r)(rho - R + r) + z^2. Near the
 * surface the paired difference (z - r or rho - R - r) is exact (Sterbenz)
 * and the other term is small and accurate, so F keeps its relative
 * accuracy even for a ray grazing the top of the tube, where r^2 - z^2 is
 * tiny and (rho - R)^2 must be compared with it. Signs of F, not
 * of the ill-conditioned coefficients of q, decide which pieces hold a
 * root, so the crossings found always alternate, and a tangent ray (a
 * double root, no sign change) yields no sliver. The ends of the range lie
 * outside the bounding sphere, where F > 0, so crossings come in pairs.
 */
#include <float.h>
#include <math.h>

#include "csg/prim_curved.h"
#include "implicit/solve.h"

/* F at a local point, rho = |(x, y)| given. */
static double torus_value(double big_r, double r, double rho, double z)
{
    double w = rho - big_r;
    if (fabs(z) >= fabs(w))
        return w * w + (z - r) * (z + r);
    return (w - r) * (w + r) + z * z;
}

/* F and its derivative along u at c + s u. */
static double torus_f(double big_r, double r, vec3 c, vec3 u, double s, double *df)
{
    vec3 p = v3_madd(c, u, s);
    double rho = hypot(p.x, p.y);
    if (df) {
        double drho = rho > 0 ? (p.x * u.x + p.y * u.y) / rho : 0;
        *df = 2 * (rho - big_r) * drho + 2 * p.z * u.z;
    }
    return torus_value(big_r, r, rho, p.z);
}

static double poly_eval(const double *c, int deg, double x)
{
    double v = c[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * x + c[i];
    return v;
}

/* Root of the polynomial c (degree deg) in [a, b], where it differs in
 * sign at the ends: bisection with Newton steps when they stay inside. */
static double poly_bracketed(const double *c, int deg, double a, double b)
{
    double fa = poly_eval(c, deg, a);
    double x = 0.5 * (a + b);
    for (int it = 0; it < 200 && b - a > 2 * DBL_EPSILON * fmax(fabs(a), fabs(b)); it++) {
        double fx = poly_eval(c, deg, x);
        if (fx == 0)
            return x;
        if ((fx < 0) == (fa < 0))
            a = x;
        else
            b = x;
        double dfx = 0;
        for (int i = deg; i >= 1; i--)
            dfx = dfx * x + i * c[i];
        double next = x - fx / dfx;
        if (!(next > a && next < b))
            next = 0.5 * (a + b);
        if (next == x)
            break;
        x = next;
    }
    return x;
}

/* Sign-changing real roots of a polynomial of degree 1..3 with c[deg] != 0
 * in (lo, hi), increasing; returns their number. Its derivative's roots
 * cut (lo, hi) into monotone pieces. */
static int poly_roots(const double *c, int deg, double lo, double hi, double *roots)
{
    if (deg == 1) {
        double x = -c[0] / c[1];
        if (x > lo && x < hi) {
            roots[0] = x;
            return 1;
        }
        return 0;
    }
    double dc[3];
    for (int i = 1; i <= deg; i++)
        dc[i - 1] = i * c[i];
    double cuts[4];
    int k = poly_roots(dc, deg - 1, lo, hi, cuts);
    double ends[6];
    ends[0] = lo;
    for (int i = 0; i < k; i++)
        ends[i + 1] = cuts[i];
    ends[k + 1] = hi;
    int n = 0;
    for (int i = 0; i <= k; i++) {
        double fa = poly_eval(c, deg, ends[i]), fb = poly_eval(c, deg, ends[i + 1]);
        if ((fa < 0) != (fb < 0))
            roots[n++] = poly_bracketed(c, deg, ends[i], ends[i + 1]);
    }
    return n;
}

/* The torus along a line: F at c + s u (s is the line's t) and its
 * derivative. */
typedef struct torus_line {
    double big_r, r;
    vec3 c, u;
} torus_line;

static double torus_line_value(const void *ctx, double s, double *df)
{
    const torus_line *line = ctx;
    return torus_f(line->big_r, line->r, line->c, line->u, s, df);
}

/* The root of F along the line in [a, b], where F differs in sign at the
 * ends: safeguarded Newton-bisection to the resolution of doubles. */
static double torus_root(double big_r, double r, vec3 c, vec3 u, double a, double b)
{
    torus_line line = {big_r, r, c, u};
    int neg_a = torus_f(big_r, r, c, u, a, NULL) < 0;
    return solve_newton_bracket(torus_line_value, &line, a, b, neg_a, 200);
}

uint32_t prim_torus_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                          uint32_t cap)
{
    double big_r = p->u.torus.major, r = p->u.torus.minor;
    double len = v3_length(d);
    vec3 u = v3_scale(d, 1.0 / len);
    double tc = -v3_dot(o, u) / len; /* t of the point closest to the centre */
    vec3 c = v3_madd(o, d, tc);
    double bound = 1.01 * (big_r + r); /* F > 0 beyond R + r */
    double g0 = v3_dot(c, c);
    if (!(g0 < bound * bound))
        return 0;
    double half = sqrt(bound * bound - g0);
    double s_lo = -half, s_hi = half;

    double b = v3_dot(c, u);
    double e = g0 + big_r * big_r - r * r;
    double a2 = u.x * u.x + u.y * u.y, b2 = c.x * u.x + c.y * u.y;
    double r2 = big_r * big_r;
    /* q' = 4 s^3 + 12 b s^2 + 2 k2 s + k1, from q's coefficients. */
    double k2 = 4 * b * b + 2 * e - 4 * r2 * a2, k1 = 4 * b * e - 8 * r2 * b2;
    double dq[4] = {k1, 2 * k2, 12 * b, 4};
    double crit[3];
    int k = poly_roots(dq, 3, s_lo, s_hi, crit);
    double ends[5];
    ends[0] = s_lo;
    for (int i = 0; i < k; i++)
        ends[i + 1] = crit[i];
    ends[k + 1] = s_hi;
    double roots[4];
    int n = 0;
    double f_prev = torus_f(big_r, r, c, u, ends[0], NULL);
    for (int i = 1; i <= k + 1; i++) {
        double f_next = torus_f(big_r, r, c, u, ends[i], NULL);
        if ((f_prev < 0) != (f_next < 0))
            roots[n++] = torus_root(big_r, r, c, u, ends[i - 1], ends[i]);
        f_prev = f_next;
    }
    /* n is even: both ends lie outside. A gap whose midpoint F cannot tell
     * from zero is a double root, not a gap: a ray that touches the tube
     * from inside (along the tangent of the inner equator) has true
     * F = -r s^2 / (R - r) < 0 on both sides of the touching point, but rho
     * there rounds to the equator's radius, so F evaluates to 0 or a few ulps
     * above it over a stretch of width ~sqrt(u) (2e-8 of R) and the sign
     * test splits the chord there, wider than eps. The closure of the
     * interior holds the touching point, so the regularised set is one
     * chord: the two are merged. The test is the rounding bound of F: its
     * terms are at most (R + r)^2 and each carries a few ulps. A ray that
     * passes truly outside by more than that bound keeps its gap. */
    double f_zero = 8 * DBL_EPSILON * (big_r + r) * (big_r + r);
    int kept = 0;
    for (int i = 0; i < n; i++) {
        if (kept >= 2 && !(kept & 1) && i + 1 < n &&
            torus_f(big_r, r, c, u, 0.5 * (roots[kept - 1] + roots[i]), NULL) <= f_zero) {
            kept--; /* drop the exit; the next entry is dropped below */
            continue;
        }
        roots[kept++] = roots[i];
    }
    n = kept;
    uint32_t count = 0;
    for (int i = 0; i + 1 < n && count < cap; i += 2) {
        span *s = &out[count++];
        s->in = (span_end){tc + roots[i] / len, leaf, PRIM_PART_SURFACE, 0};
        s->out = (span_end){tc + roots[i + 1] / len, leaf, PRIM_PART_SURFACE, 0};
    }
    return count;
}

vec3 prim_torus_normal(const prim *p, vec3 q)
{
    double rho = hypot(q.x, q.y);
    if (!(rho > 0))
        return v3(0, 0, q.z >= 0 ? 1 : -1);
    double k = (rho - p->u.torus.major) / rho;
    return v3(k * q.x, k * q.y, q.z);
}

int prim_torus_inside(const prim *p, vec3 q)
{
    return torus_value(p->u.torus.major, p->u.torus.minor, hypot(q.x, q.y), q.z) <= 0;
}

bbox prim_torus_bounds(const prim *p)
{
    double w = p->u.torus.major + p->u.torus.minor, r = p->u.torus.minor;
    bbox b = {{-w, -w, -r}, {w, w, r}};
    return b;
}
