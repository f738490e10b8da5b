/* Root finding along a ray: see solve.h for the three methods and what
 * each guarantees.
 *
 * The sign that matters is that of the predicate f < 0; NaN counts as
 * outside, as in prim_inside. Every method evaluates f at increasing t and
 * reports a crossing between neighbouring evaluations of different sign,
 * so crossings alternate. The interval method's segments share their ends
 * (a split at m evaluates f(m) once for both halves), which keeps that
 * chain of signs unbroken across dropped segments. */
#include "implicit/solve.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "base/cancel.h"

static int neg(double f)
{
    return f < 0;
}

static double eval_at(const expr_program *f, vec3 o, vec3 d, double t)
{
    return expr_eval(f, v3_madd(o, d, t));
}

static void record(solve_result *r, double t)
{
    if (r->n < SOLVE_MAX_CROSSINGS)
        r->t[r->n++] = t;
    else
        r->t[SOLVE_MAX_CROSSINGS - 1] = t;
    r->total++;
}

/* Whether the search must end now: every SOLVE_POLL_STEPS calls (counted
 * in *steps), reports the evaluations made since the last time to the
 * calling thread's cancel token (whose budget may stop it then) and asks
 * whether it has stopped. */
static int must_stop(uint32_t *steps, solve_result *r)
{
    if (++*steps % SOLVE_POLL_STEPS != 0)
        return 0;
    cancel_spend(r->evals - r->charged);
    r->charged = r->evals;
    if (!cancel_poll())
        return 0;
    r->stopped = 1;
    return 1;
}

double solve_newton_bracket(solve_line_fn f, const void *ctx, double a, double b,
                            int neg_a, int max_iterations)
{
    double x = 0.5 * (a + b), width = b - a;
    for (int it = 0; it < max_iterations; it++) {
        double df;
        double fx = f(ctx, x, &df);
        if (neg(fx) == neg_a)
            a = x;
        else
            b = x;
        if (b - a <= 2 * DBL_EPSILON * fmax(fabs(a), fabs(b)) || b - a <= DBL_MIN)
            break;
        double next = x - fx / df;
        if (!(next > a && next < b) || fabs(next - x) > 0.5 * width)
            next = 0.5 * (a + b);
        width = fabs(next - x);
        if (next == x)
            break;
        x = next;
    }
    return 0.5 * (a + b);
}

/* The line o + t d through an implicit function, counting evaluations. */
typedef struct expr_line {
    const expr_program *f;
    vec3 o, d;
    uint64_t *evals;
} expr_line;

static double expr_line_value(const void *ctx, double t, double *df)
{
    const expr_line *line = ctx;
    (*line->evals)++;
    return expr_eval_dual(line->f, v3_madd(line->o, line->d, t), line->d, df);
}

/* solve_newton_bracket on f along the line, adding its evaluations to
 * *evals. */
static double refine_newton(const expr_program *f, vec3 o, vec3 d, double a, double b,
                            int neg_a, uint64_t *evals)
{
    expr_line line = {f, o, d, evals};
    return solve_newton_bracket(expr_line_value, &line, a, b, neg_a, 128);
}

/* Plain bisection on [a, b] down to width w. */
static double refine_bisect(const expr_program *f, vec3 o, vec3 d, double a, double b,
                            int neg_a, double w, uint64_t *evals)
{
    for (int it = 0; it < 128 && b - a > w; it++) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b)
            break;
        (*evals)++;
        if (neg(eval_at(f, o, d, m)) == neg_a)
            a = m;
        else
            b = m;
    }
    return 0.5 * (a + b);
}

typedef struct segment {
    double a, b, fa, fb;
} segment;

static void solve_interval(const expr_program *f, const solve_options *opt, vec3 o,
                           vec3 d, double t0, double t1, double f0, double f1,
                           solve_result *r)
{
    /* Depth 80 halvings would take any finite segment below the spacing of
     * doubles; the stack holds one pending right half per level. */
    enum { MAX_LEVELS = 80 };
    segment stack[MAX_LEVELS + 1];
    int top = 0;
    double step = opt->tolerance / v3_length(d);
    stack[top++] = (segment){t0, t1, f0, f1};
    int levels[MAX_LEVELS + 1];
    levels[0] = 0;
    uint32_t steps = 0;
    while (top > 0) {
        segment s = stack[--top];
        int level = levels[top];
        if (must_stop(&steps, r))
            return;
        if (r->evals >= SOLVE_MAX_EVALS) {
            r->exhausted = 1;
            return;
        }
        ix tt = ix_make(s.a, s.b);
        ix x = ix_add(ix_point(o.x), ix_mul(tt, ix_point(d.x)));
        ix y = ix_add(ix_point(o.y), ix_mul(tt, ix_point(d.y)));
        ix z = ix_add(ix_point(o.z), ix_mul(tt, ix_point(d.z)));
        ix df;
        int undefined;
        ix fv = expr_eval_ix(f, x, y, z, d, &df, &undefined);
        r->evals++;
        if (undefined == 2)
            continue; /* NaN throughout: outside throughout */
        int unknown = isnan(fv.lo) || isnan(fv.hi);
        if (!unknown && (fv.lo >= 0 || fv.hi < 0))
            continue; /* one sign throughout: no crossing */
        int changes = neg(s.fa) != neg(s.fb);
        int monotone = !isnan(df.lo) && !isnan(df.hi) && (df.lo > 0 || df.hi < 0);
        if (monotone || s.b - s.a <= step || level >= MAX_LEVELS) {
            if (changes)
                record(r, refine_newton(f, o, d, s.a, s.b, neg(s.fa), &r->evals));
            continue;
        }
        double m = 0.5 * (s.a + s.b);
        if (!(m > s.a && m < s.b)) {
            if (changes)
                record(r, m);
            continue;
        }
        double fm = eval_at(f, o, d, m);
        r->evals++;
        stack[top] = (segment){m, s.b, fm, s.fb};
        levels[top++] = level + 1;
        stack[top] = (segment){s.a, m, s.fa, fm};
        levels[top++] = level + 1;
    }
}

static void solve_lipschitz(const expr_program *f, const solve_options *opt, vec3 o,
                            vec3 d, double t0, double t1, double f0, solve_result *r)
{
    double len = v3_length(d);
    double min_step = opt->tolerance / len, inv = 1.0 / (opt->lipschitz * len);
    double t = t0, ft = f0;
    uint32_t steps = 0;
    while (t < t1) {
        if (must_stop(&steps, r))
            return;
        if (r->evals >= SOLVE_MAX_EVALS) {
            r->exhausted = 1;
            return;
        }
        double step = fabs(ft) * inv;
        if (!(step >= min_step)) /* also NaN */
            step = min_step;
        double tn = fmin(t + step, t1);
        if (!(tn > t))
            break;
        double fn = eval_at(f, o, d, tn);
        r->evals++;
        if (neg(fn) != neg(ft)) {
            double s = ft / (ft - fn);
            double tc = t + (tn - t) * (isfinite(s) ? fmin(fmax(s, 0), 1) : 0.5);
            record(r, tc);
        }
        t = tn;
        ft = fn;
    }
}

static void solve_march(const expr_program *f, const solve_options *opt, vec3 o, vec3 d,
                        double t0, double t1, double f0, solve_result *r)
{
    double step = opt->tolerance / v3_length(d);
    double span = t1 - t0;
    double count = ceil(span / step);
    if (!(count >= 1))
        count = 1;
    if (count > SOLVE_MAX_EVALS) {
        count = SOLVE_MAX_EVALS;
        r->exhausted = 1;
    }
    uint32_t n = (uint32_t)count;
    double prev_t = t0, prev_f = f0;
    uint32_t steps = 0;
    for (uint32_t i = 1; i <= n; i++) {
        if (must_stop(&steps, r))
            return;
        double t = i == n ? t1 : t0 + span * ((double)i / n);
        double ft = eval_at(f, o, d, t);
        r->evals++;
        if (neg(ft) != neg(prev_f))
            record(r, refine_bisect(f, o, d, prev_t, t, neg(prev_f), 1e-3 * (t - prev_t),
                                    &r->evals));
        prev_t = t;
        prev_f = ft;
    }
}

void solve_crossings(const expr_program *f, const solve_options *opt, vec3 o, vec3 d,
                     double t0, double t1, solve_result *out)
{
    memset(out, 0, sizeof *out);
    double f0 = eval_at(f, o, d, t0);
    out->inside_start = neg(f0);
    out->evals = 1;
    if (!(t1 > t0) || !(v3_dot(d, d) > 0) || !(opt->tolerance > 0))
        return;
    switch (opt->method) {
    case SOLVE_LIPSCHITZ:
        if (opt->lipschitz > 0)
            solve_lipschitz(f, opt, o, d, t0, t1, f0, out);
        break;
    case SOLVE_MARCH:
        solve_march(f, opt, o, d, t0, t1, f0, out);
        break;
    default: {
        double f1 = eval_at(f, o, d, t1);
        out->evals++;
        solve_interval(f, opt, o, d, t0, t1, f0, f1, out);
        break;
    }
    }
}

double solve_estimate_lipschitz(const expr_program *f, bbox box)
{
    enum { N = 16 };
    double best = 0;
    vec3 ext = bbox_extent(&box);
    for (int i = 0; i < N; i++) {
        for (int j = 0; j < N; j++) {
            for (int k = 0; k < N; k++) {
                vec3 q =
                    v3(box.lo.x + ext.x * (i + 0.5) / N, box.lo.y + ext.y * (j + 0.5) / N,
                       box.lo.z + ext.z * (k + 0.5) / N);
                double gx, gy, gz;
                expr_eval_dual(f, q, v3(1, 0, 0), &gx);
                expr_eval_dual(f, q, v3(0, 1, 0), &gy);
                expr_eval_dual(f, q, v3(0, 0, 1), &gz);
                double g = sqrt(gx * gx + gy * gy + gz * gz);
                if (g > best) /* NaN and Inf are skipped */
                    best = isfinite(g) ? g : best;
            }
        }
    }
    return fmax(1.5 * best, 1e-300);
}

const char *solve_method_name(solve_method m)
{
    switch (m) {
    case SOLVE_INTERVAL:
        return "interval";
    case SOLVE_LIPSCHITZ:
        return "lipschitz";
    case SOLVE_MARCH:
        return "march";
    default:
        return "?";
    }
}

solve_method solve_method_parse(const char *name)
{
    for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
        if (strcmp(name, solve_method_name((solve_method)m)) == 0)
            return (solve_method)m;
    }
    return SOLVE_METHOD_COUNT;
}
