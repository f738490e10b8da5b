/* Intervals with outward rounding: guaranteed enclosures of real values.
 *
 * An ix is the closed set [lo, hi] of reals (lo <= hi; the ends may be
 * infinite; an interval holding NaN stands for "anything", see ix_entire).
 * Every operation returns an interval that contains f(a) for every a in its
 * arguments (where f is defined). Rounding is made outward without touching
 * the FPU rounding mode (fesetround is global state, slow to switch, and
 * not honoured by every libm): each end is computed in round-to-nearest and
 * then moved outward by x -+ (|x| 2^-52 + 2^-1074), a step of at least one
 * ulp (nextafter's single ulp, without its libm call; sometimes two). For
 * + - * / and sqrt IEEE 754 gives the correctly rounded result, which lies
 * within half an ulp of the exact one, so one ulp outward encloses it. For
 * libm functions (exp, log,
 * sin, cos, tan, atan2), whose results are not correctly rounded, the ends
 * are widened by 4 ulps relative plus the smallest subnormal, more than the
 * documented error of glibc's implementations (at most 1-2 ulps).
 *
 * Functions with domains (sqrt, log) enclose f over the part of the
 * argument inside the domain; an argument wholly outside gives the empty
 * result NaN, which ix_entire-checks treat as unknown.
 */
#ifndef SPANCAST_IMPLICIT_INTERVAL_H
#define SPANCAST_IMPLICIT_INTERVAL_H

typedef struct ix {
    double lo, hi;
} ix;

static inline ix ix_make(double lo, double hi)
{
    ix r = {lo, hi};
    return r;
}
static inline ix ix_point(double v)
{
    return ix_make(v, v);
}
/* 1 when x may be any value (infinite ends or NaN). */
int ix_is_unbounded(ix x);
/* 1 when v lies in x (NaN ends count as containing everything). */
int ix_contains(ix x, double v);

ix ix_entire(void);
ix ix_hull(ix a, ix b);
ix ix_add(ix a, ix b);
ix ix_sub(ix a, ix b);
ix ix_neg(ix a);
ix ix_mul(ix a, ix b);
ix ix_div(ix a, ix b);
ix ix_sqr(ix a);
ix ix_powi(ix a, int n); /* integer power, n may be negative */
ix ix_sqrt(ix a);
ix ix_abs(ix a);
ix ix_min(ix a, ix b);
ix ix_max(ix a, ix b);
ix ix_exp(ix a);
ix ix_log(ix a);
ix ix_sin(ix a);
ix ix_cos(ix a);
void ix_sincos(ix a, ix *s, ix *c); /* both, for about the price of one */
ix ix_tan(ix a);
ix ix_atan2(ix y, ix x);
ix ix_floor(ix a);

#endif
