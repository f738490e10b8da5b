/* Outward-rounded interval arithmetic: see interval.h for the rounding
 * rule (a step of one or two ulps outward after correctly rounded
 * operations, a relative 4-ulp widening after libm functions). */
#include "implicit/interval.h"

#include <float.h>
#include <math.h>

static const double PI = 3.14159265358979323846;

/* One step outward, of at least one ulp: |x| 2^-52 is at least the ulp of
 * a normal x (and at least the spacing below it, which is smaller at a
 * power of two), so the exact x - |x| 2^-52 lies at least one spacing
 * below x and rounding to nearest cannot bring it back to x; the smallest
 * subnormal covers zero and subnormals. Cheaper than nextafter (a libm
 * call), at the price of sometimes stepping two ulps. Infinite ends stay. */
static double down(double x)
{
    return isfinite(x) ? x - (fabs(x) * DBL_EPSILON + DBL_TRUE_MIN) : x;
}
static double up(double x)
{
    return isfinite(x) ? x + (fabs(x) * DBL_EPSILON + DBL_TRUE_MIN) : x;
}
/* Widening for results of libm functions. */
static double wdown(double x)
{
    return isfinite(x) ? x - (fabs(x) * 4 * DBL_EPSILON + DBL_TRUE_MIN) : x;
}
static double wup(double x)
{
    return isfinite(x) ? x + (fabs(x) * 4 * DBL_EPSILON + DBL_TRUE_MIN) : x;
}

int ix_is_unbounded(ix x)
{
    return !(isfinite(x.lo) && isfinite(x.hi));
}

int ix_contains(ix x, double v)
{
    if (isnan(x.lo) || isnan(x.hi))
        return 1;
    return x.lo <= v && v <= x.hi;
}

ix ix_entire(void)
{
    return ix_make(-INFINITY, INFINITY);
}

ix ix_hull(ix a, ix b)
{
    if (isnan(a.lo) || isnan(a.hi))
        return b;
    if (isnan(b.lo) || isnan(b.hi))
        return a;
    return ix_make(fmin(a.lo, b.lo), fmax(a.hi, b.hi));
}

ix ix_add(ix a, ix b)
{
    return ix_make(down(a.lo + b.lo), up(a.hi + b.hi));
}

ix ix_sub(ix a, ix b)
{
    return ix_make(down(a.lo - b.hi), up(a.hi - b.lo));
}

ix ix_neg(ix a)
{
    return ix_make(-a.hi, -a.lo);
}

/* x * y with 0 * inf = 0: a zero factor makes the product zero whatever
 * the other end's magnitude (the infinite end stands for large finite
 * values). */
static double times(double x, double y)
{
    return x == 0 || y == 0 ? 0 : x * y;
}

ix ix_mul(ix a, ix b)
{
    double p0 = times(a.lo, b.lo), p1 = times(a.lo, b.hi);
    double p2 = times(a.hi, b.lo), p3 = times(a.hi, b.hi);
    if (isnan(p0) || isnan(p1) || isnan(p2) || isnan(p3))
        return ix_make(NAN, NAN);
    /* plain comparisons: no NaN is left, and fmin is a libm call */
    double lo0 = p0 < p1 ? p0 : p1, lo1 = p2 < p3 ? p2 : p3;
    double hi0 = p0 < p1 ? p1 : p0, hi1 = p2 < p3 ? p3 : p2;
    return ix_make(down(lo0 < lo1 ? lo0 : lo1), up(hi0 < hi1 ? hi1 : hi0));
}

ix ix_div(ix a, ix b)
{
    if (isnan(a.lo) || isnan(a.hi) || isnan(b.lo) || isnan(b.hi))
        return ix_make(NAN, NAN);
    if (b.lo <= 0 && b.hi >= 0)
        return ix_entire();
    double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 4; i++) {
        if (isnan(q[i])) /* inf / inf: any magnitude */
            return ix_entire();
        lo = fmin(lo, q[i]);
        hi = fmax(hi, q[i]);
    }
    return ix_make(down(lo), up(hi));
}

ix ix_sqr(ix a)
{
    double l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.lo >= 0)
        return ix_make(fmax(0, down(l)), up(h));
    if (a.hi <= 0)
        return ix_make(fmax(0, down(h)), up(l));
    if (isnan(l) || isnan(h))
        return ix_make(NAN, NAN);
    return ix_make(0, up(fmax(l, h)));
}

/* x^n for n >= 1 by repeated squaring: at most 2 log2(n) roundings of
 * half an ulp each, so within n + 2 ulps relative for any n >= 1 (the
 * slack ix_powi widens by). */
static double ipow(double x, int n)
{
    double r = 1;
    while (n > 0) {
        if (n & 1)
            r *= x;
        x *= x;
        n >>= 1;
    }
    return r;
}
static double pdown(double x, double rel)
{
    return isfinite(x) ? x - (fabs(x) * rel + DBL_TRUE_MIN) : x;
}
static double pup(double x, double rel)
{
    return isfinite(x) ? x + (fabs(x) * rel + DBL_TRUE_MIN) : x;
}

ix ix_powi(ix a, int n)
{
    if (n == 0)
        return ix_point(1);
    if (n < 0)
        return ix_div(ix_point(1), ix_powi(a, -n));
    if (n == 1)
        return a;
    if (n == 2)
        return ix_sqr(a);
    double l = ipow(a.lo, n), h = ipow(a.hi, n);
    double slack = (n + 2) * DBL_EPSILON;
    if (n % 2 == 1)
        return ix_make(pdown(l, slack), pup(h, slack)); /* increasing */
    if (a.lo >= 0)
        return ix_make(fmax(0, pdown(l, slack)), pup(h, slack));
    if (a.hi <= 0)
        return ix_make(fmax(0, pdown(h, slack)), pup(l, slack));
    if (isnan(l) || isnan(h))
        return ix_make(NAN, NAN);
    return ix_make(0, pup(fmax(l, h), slack));
}

ix ix_sqrt(ix a)
{
    if (!(a.hi >= 0))
        return ix_make(NAN, NAN);
    double lo = a.lo > 0 ? sqrt(a.lo) : 0;
    return ix_make(fmax(0, down(lo)), up(sqrt(a.hi)));
}

ix ix_abs(ix a)
{
    if (a.lo >= 0)
        return a;
    if (a.hi <= 0)
        return ix_neg(a);
    return ix_make(0, fmax(-a.lo, a.hi));
}

ix ix_min(ix a, ix b)
{
    return ix_make(fmin(a.lo, b.lo), fmin(a.hi, b.hi));
}

ix ix_max(ix a, ix b)
{
    return ix_make(fmax(a.lo, b.lo), fmax(a.hi, b.hi));
}

ix ix_exp(ix a)
{
    return ix_make(fmax(0, wdown(exp(a.lo))), wup(exp(a.hi)));
}

ix ix_log(ix a)
{
    if (!(a.hi >= 0))
        return ix_make(NAN, NAN);
    double lo = a.lo > 0 ? wdown(log(a.lo)) : -INFINITY;
    return ix_make(lo, wup(log(a.hi)));
}

/* 1 when some point c + k * period (k an integer) may lie in [lo, hi]. The
 * test is made on the interval grown by a relative 16 ulps and checks two
 * neighbouring k, so rounding in the computation of k can only make the
 * answer "yes" where "no" was right, which only loosens the enclosure. */
static int hits_lattice(double lo, double hi, double c, double period)
{
    double slack = 16 * DBL_EPSILON * fmax(1, fmax(fabs(lo), fabs(hi)));
    double k = ceil((lo - c) / period);
    for (int i = -1; i <= 0; i++) {
        double p = c + (k + i) * period;
        if (p >= lo - slack && p <= hi + slack)
            return 1;
    }
    return 0;
}

/* sin or cos (phase 0 or pi/2 for the peak at phase + 2 k pi). */
/* sin or cos over a from its values l, h at the ends: the range of the
 * ends, extended to 1 or -1 where a peak (phase + 2 k pi) or a trough
 * lies inside. */
static ix periodic(ix a, double l, double h, double peak)
{
    /* Beyond 2^50 the spacing of doubles nears the period: no structure
     * is left to follow. */
    if (!(a.hi - a.lo < 2 * PI) || !(fabs(a.lo) < 0x1p50) || !(fabs(a.hi) < 0x1p50))
        return ix_make(-1, 1);
    double lo = wdown(fmin(l, h)), hi = wup(fmax(l, h));
    if (hits_lattice(a.lo, a.hi, peak, 2 * PI))
        hi = 1;
    if (hits_lattice(a.lo, a.hi, peak + PI, 2 * PI))
        lo = -1;
    return ix_make(fmax(-1, lo), fmin(1, hi));
}

ix ix_sin(ix a)
{
    return periodic(a, sin(a.lo), sin(a.hi), PI / 2);
}

ix ix_cos(ix a)
{
    return periodic(a, cos(a.lo), cos(a.hi), 0);
}

void ix_sincos(ix a, ix *s, ix *c)
{
    /* sin and cos of the same argument side by side: compilers merge
     * them into one sincos call. */
    double sl = sin(a.lo), cl = cos(a.lo), sh = sin(a.hi), ch = cos(a.hi);
    *s = periodic(a, sl, sh, PI / 2);
    *c = periodic(a, cl, ch, 0);
}

ix ix_tan(ix a)
{
    if (!(a.hi - a.lo < PI) || !(fabs(a.lo) < 0x1p50) || !(fabs(a.hi) < 0x1p50) ||
        hits_lattice(a.lo, a.hi, PI / 2, PI))
        return ix_entire();
    return ix_make(wdown(tan(a.lo)), wup(tan(a.hi)));
}

/* atan2 is continuous off its cut (x <= 0, y = 0) and has no critical
 * point; along a box edge one coordinate is fixed and the derivative in
 * the other (x / r^2 or -y / r^2) keeps its sign, so on a box that misses
 * the cut the extremes lie at the corners. */
ix ix_atan2(ix y, ix x)
{
    if (isnan(x.lo) || isnan(x.hi) || isnan(y.lo) || isnan(y.hi))
        return ix_make(NAN, NAN);
    if (x.lo <= 0 && y.lo <= 0 && y.hi >= 0)
        return ix_make(-up(PI), up(PI));
    double c[4] = {atan2(y.lo, x.lo), atan2(y.lo, x.hi), atan2(y.hi, x.lo),
                   atan2(y.hi, x.hi)};
    double lo = fmin(fmin(c[0], c[1]), fmin(c[2], c[3]));
    double hi = fmax(fmax(c[0], c[1]), fmax(c[2], c[3]));
    return ix_make(wdown(lo), wup(hi));
}

ix ix_floor(ix a)
{
    return ix_make(floor(a.lo), floor(a.hi));
}
