/* Tests of src/implicit/: the expression compiler (values, precedence,
 * folding, parameters, every error message and its offset, the limits), the
 * three evaluators (the interval evaluator encloses the double and the
 * forward-mode evaluators at random points of random boxes, for every
 * opcode; forward-mode derivatives match central differences), and the
 * root finders on functions with known roots: simple, double (tangent),
 * near-double at separations down to just above the tolerance, triple, and
 * a ray with more crossings than an implicit leaf keeps.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "csg/prim.h"
#include "implicit/expr.h"
#include "implicit/solve.h"

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t next_u64(rng *r)
{
    r->s += 0x9e3779b97f4a7c15ULL;
    uint64_t z = r->s;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static double uniform(rng *r)
{
    return (double)(next_u64(r) >> 11) * 0x1p-53;
}

static double uniform_in(rng *r, double lo, double hi)
{
    return lo + (hi - lo) * uniform(r);
}

static void compile(const char *src, expr_program *p)
{
    expr_error e;
    if (!expr_compile(src, strlen(src), NULL, 0, p, &e))
        fail_msg("'%s': %s at %zu", src, e.message, e.offset);
}

static double value_of(const char *src, vec3 q)
{
    expr_program p;
    compile(src, &p);
    return expr_eval(&p, q);
}

/* ---- compiler ---- */

static void test_values(void **state)
{
    (void)state;
    vec3 q = v3(3, -2, 0.5);
    assert_true(value_of("x + y * z", q) == 2);
    assert_true(value_of("(x + y) * z", q) == 0.5);
    assert_true(value_of("-x^2", q) == -9);
    assert_true(value_of("2^3^2", q) == 512);
    assert_true(value_of("x - y - z", q) == 4.5);
    assert_true(value_of("x / y / z", q) == -3);
    assert_true(value_of("x^-2", q) == 1.0 / 9);
    assert_true(value_of("pow(z, 0.5)", q) == exp(0.5 * log(0.5)));
    assert_true(value_of("min(x, y, z)", q) == -2);
    assert_true(value_of("max(x, y, z, 7)", q) == 7);
    assert_true(value_of("mod(7, 3) + mod(-1, 3)", q) == 3);
    assert_true(value_of("clamp(x, 0, 1) + clamp(y, 0, 1)", q) == 1);
    assert_true(value_of("abs(y) + floor(z) + sqrt(4)", q) == 4);
    assert_true(fabs(value_of("atan2(1, 0) - pi / 2", q)) < 1e-15);
    assert_true(value_of("1e2 + .5 + 2.5E-1", q) == 100.75);
    /* smooth minimum: min far apart, blended within k */
    assert_true(value_of("smin(0, 5, 1)", q) == 0);
    assert_true(value_of("smin(1, 1, 1)", q) == 0.75); /* min - k / 4 */
    /* folding: only the variable part is left */
    expr_program p;
    compile("2 * 3 + sin(0) * 4 + x", &p);
    assert_true(p.count <= 3);
    assert_true(expr_eval(&p, q) == 9);
    /* parameters, the last of a repeated name winning */
    expr_param params[3] = {{"R", 2}, {"r_1", 0.5}, {"R", 4}};
    expr_error e;
    assert_true(expr_compile("R * x + r_1", 11, params, 3, &p, &e));
    assert_true(expr_eval(&p, q) == 12.5);
}

static void check_compile_error(const char *src, size_t offset, const char *message)
{
    expr_program p;
    expr_error e;
    if (expr_compile(src, strlen(src), NULL, 0, &p, &e))
        fail_msg("'%s' compiled", src);
    if (strcmp(e.message, message) != 0 || e.offset != offset)
        fail_msg("'%s': got '%s' at %zu, expected '%s' at %zu", src, e.message, e.offset,
                 message, offset);
}

static void test_errors(void **state)
{
    (void)state;
    check_compile_error("", 0, "empty expression");
    check_compile_error("  \t", 3, "empty expression");
    check_compile_error("x + * y", 4, "unexpected character '*' in expression");
    check_compile_error("x + foo", 4, "unknown name 'foo'");
    check_compile_error("x + frob(y)", 4, "unknown function 'frob'");
    check_compile_error("sin(x", 5,
                        "unexpected end of expression (expected ')' to close the call "
                        "of 'sin')");
    check_compile_error("sin(x y)", 6, "expected ',' or ')' in call of 'sin'");
    check_compile_error("(x + 1", 6, "unexpected end of expression (expected ')')");
    check_compile_error("(x + 1 y", 7, "expected ')'");
    check_compile_error("x)", 1, "unmatched ')'");
    check_compile_error("x y", 2, "unexpected character 'y' in expression");
    check_compile_error("x +", 3, "unexpected end of expression");
    check_compile_error("min(x)", 0, "'min' takes at least 2 arguments, not 1");
    check_compile_error("1 + clamp(x, 1)", 4, "'clamp' takes 3 arguments, not 2");
    check_compile_error("sin(x, y)", 0, "'sin' takes 1 argument, not 2");
    check_compile_error("1.2.3", 3, "unexpected character '.' in expression");
    check_compile_error("x + .", 4, "malformed number");
    check_compile_error("x # 2", 2, "unexpected character '#' in expression");
    check_compile_error("x \xc3\xa9", 2, "unexpected byte 0xc3 in expression");

    char deep[200];
    memset(deep, '(', 100);
    deep[100] = 'x';
    memset(deep + 101, ')', 98);
    deep[199] = '\0';
    check_compile_error(deep, 64, "expression is nested too deeply (limit is 64 levels)");
    char minus[100];
    memset(minus, '-', 98);
    minus[98] = 'x';
    minus[99] = '\0';
    check_compile_error(minus, 64,
                        "expression is nested too deeply (limit is 64 levels)");
    char sum[1200] = "x";
    for (int i = 0; i < 300; i++)
        strcat(sum, "+x");
    expr_program p;
    expr_error e;
    assert_false(expr_compile(sum, strlen(sum), NULL, 0, &p, &e));
    assert_string_equal(e.message, "expression is too long (limit is 256 operations)");
}

/* ---- evaluators ---- */

/* Programs that cover every opcode, alone or composed. */
static const char *const enclosure_cases[] = {
    "x + y",
    "x - y",
    "x * y",
    "x / y",
    "-x",
    "x * x",
    "x^3",
    "x^4",
    "x^-2",
    "x^-3",
    "sqrt(x)",
    "abs(x)",
    "min(x, y)",
    "max(x, y)",
    "sin(x)",
    "cos(x)",
    "tan(x)",
    "exp(x)",
    "log(x)",
    "atan2(y, x)",
    "floor(x)",
    "mod(x, y)",
    "clamp(x, y, z)",
    "smin(x, y, 0.5)",
    "pow(x, y)",
    "sin(3*x) * cos(2*y) + sqrt(x*x + z*z) - exp(-y*y)",
    "abs(sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)) - 0.3",
    "(x*x + y*y + z*z - 1)^3",
    "atan2(z - 1, y + x) * floor(2 * z) / (1 + x*x)",
    "max(sqrt(x), 0.1) + min(log(y), z)",
};

static void test_interval_enclosure(void **state)
{
    (void)state;
    rng r = {42};
    unsigned ops_seen = 0;
    long checks = 0, derivative_checks = 0;
    static const double centres[] = {1, 10, 1e3};
    for (size_t c = 0; c < sizeof enclosure_cases / sizeof enclosure_cases[0]; c++) {
        expr_program p;
        compile(enclosure_cases[c], &p);
        for (uint32_t i = 0; i < p.count; i++)
            ops_seen |= 1u << p.code[i].op;
        for (int box = 0; box < 600; box++) {
            double scale = centres[box % 3];
            double lo[3], hi[3];
            for (int k = 0; k < 3; k++) {
                double mid = uniform_in(&r, -scale, scale);
                double w = exp(uniform_in(&r, log(1e-12), log(10.0)));
                if (box % 7 == 0)
                    w = 0; /* a point */
                lo[k] = mid - w * uniform(&r);
                hi[k] = lo[k] + w;
            }
            vec3 seed =
                v3(uniform_in(&r, -2, 2), uniform_in(&r, -2, 2), uniform_in(&r, -2, 2));
            ix dF;
            int undefined;
            ix F = expr_eval_ix(&p, ix_make(lo[0], hi[0]), ix_make(lo[1], hi[1]),
                                ix_make(lo[2], hi[2]), seed, &dF, &undefined);
            for (int s = 0; s < 24; s++) {
                double u[3];
                for (int k = 0; k < 3; k++) {
                    /* corners first, then random points */
                    double a = s < 8 ? (double)((s >> k) & 1) : uniform(&r);
                    u[k] = fmin(hi[k], lo[k] + a * (hi[k] - lo[k]));
                }
                vec3 q = v3(u[0], u[1], u[2]);
                double v = expr_eval(&p, q);
                double dv;
                double v2 = expr_eval_dual(&p, q, seed, &dv);
                if (isnan(v)) {
                    /* outside the domain: the evaluator must have said so */
                    assert_true(undefined != 0);
                    continue;
                }
                assert_true(undefined != 2);
                assert_true(v == v2 || (isnan(v) && isnan(v2)));
                checks++;
                if (!ix_contains(F, v))
                    fail_msg("%s: f(%.17g, %.17g, %.17g) = %.17g outside [%.17g, %.17g]",
                             enclosure_cases[c], q.x, q.y, q.z, v, F.lo, F.hi);
                if (isfinite(dv)) {
                    derivative_checks++;
                    if (!ix_contains(dF, dv))
                        fail_msg("%s: f'(%.17g, %.17g, %.17g) = %.17g outside [%.17g, "
                                 "%.17g]",
                                 enclosure_cases[c], q.x, q.y, q.z, dv, dF.lo, dF.hi);
                }
            }
        }
    }
    print_message("interval enclosure: %ld values, %ld derivatives checked\n", checks,
                  derivative_checks);
    assert_int_equal(ops_seen, (1u << EXPR_OP_COUNT) - 1);
    assert_true(checks > 200000);
}

/* Interval rules at their hard spots: extremes inside the interval,
 * poles, the atan2 cut, zero times infinity. */
static void test_interval_rules(void **state)
{
    (void)state;
    ix s = ix_sin(ix_make(1, 2)); /* holds pi / 2 */
    assert_true(s.hi == 1 && s.lo <= sin(1));
    ix c = ix_cos(ix_make(3, 3.5)); /* holds pi */
    assert_true(c.lo == -1 && c.hi >= cos(3.5));
    assert_true(ix_is_unbounded(ix_tan(ix_make(1.5, 1.6))));
    ix a = ix_atan2(ix_make(-1, 1), ix_make(-2, -1)); /* across the cut */
    assert_true(a.lo <= -3.14159 && a.hi >= 3.14159);
    ix q = ix_sqr(ix_make(-2, 1));
    assert_true(q.lo == 0 && q.hi >= 4);
    ix z = ix_mul(ix_point(0), ix_entire()); /* 0, not NaN, widened by an ulp */
    assert_true(z.lo <= 0 && z.hi >= 0 && z.hi < 1e-300 && z.lo > -1e-300);
    assert_true(ix_is_unbounded(ix_div(ix_point(1), ix_make(-1, 1))));
    ix f = ix_floor(ix_make(0.5, 2.5));
    assert_true(f.lo == 0 && f.hi == 2);
    ix e = ix_add(ix_point(0.1), ix_point(0.2));
    assert_true(e.lo < 0.1 + 0.2 && e.hi > 0.1 + 0.2); /* outward */
}

static void test_dual_derivatives(void **state)
{
    (void)state;
    rng r = {7};
    for (size_t c = 0; c < sizeof enclosure_cases / sizeof enclosure_cases[0]; c++) {
        expr_program p;
        compile(enclosure_cases[c], &p);
        for (int i = 0; i < 200; i++) {
            vec3 q = v3(uniform_in(&r, 0.2, 2), uniform_in(&r, 0.2, 2),
                        uniform_in(&r, 0.2, 2));
            vec3 seed =
                v3(uniform_in(&r, -1, 1), uniform_in(&r, -1, 1), uniform_in(&r, -1, 1));
            double h = 1e-6, d;
            double v = expr_eval_dual(&p, q, seed, &d);
            double fp = expr_eval(&p, v3_madd(q, seed, h));
            double fm = expr_eval(&p, v3_madd(q, seed, -h));
            double fd = (fp - fm) / (2 * h);
            /* floor, mod, clamp, min, max and abs have kinks or steps:
             * skip points where the two sides disagree with the middle. */
            double d_left = (v - fm) / h, d_right = (fp - v) / h;
            if (!isfinite(fd) || fabs(d_left - d_right) > 1e-3 * (1 + fabs(fd)))
                continue;
            if (!(fabs(d - fd) <= 1e-5 * (1 + fabs(fd))))
                fail_msg("%s: derivative %.17g, central difference %.17g",
                         enclosure_cases[c], d, fd);
        }
    }
}

/* ---- solvers ---- */

static solve_result crossings(const char *src, solve_method m, double tol, vec3 o, vec3 d,
                              double t0, double t1)
{
    expr_program p;
    compile(src, &p);
    solve_options opt = {m, tol, 1.0};
    if (m == SOLVE_LIPSCHITZ) {
        bbox box = {v3(-2, -2, -2), v3(2, 2, 2)};
        opt.lipschitz = solve_estimate_lipschitz(&p, box);
    }
    solve_result r;
    solve_crossings(&p, &opt, o, d, t0, t1, &r);
    assert_false(r.exhausted);
    return r;
}

static void test_known_roots(void **state)
{
    (void)state;
    vec3 o = v3(0, 0, 0), dx = v3(1, 0, 0);
    /* simple root, every method */
    for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
        solve_result r = crossings("x - 0.3", (solve_method)m, 1e-4, o, dx, -1, 1);
        assert_int_equal(r.total, 1);
        assert_true(r.inside_start); /* x - 0.3 < 0 at x = -1 */
        assert_true(fabs(r.t[0] - 0.3) <= (m == SOLVE_INTERVAL ? 1e-15 : 1e-4));
    }
    /* the unit sphere along a diagonal, with a direction of length 2 */
    vec3 d = v3(2 / sqrt(3), 2 / sqrt(3), 2 / sqrt(3));
    for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
        solve_result r =
            crossings("x*x + y*y + z*z - 1", (solve_method)m, 1e-5, o, d, -1.5, 1.5);
        assert_int_equal(r.total, 2);
        assert_true(fabs(r.t[0] + 0.5) <= 1e-5 && fabs(r.t[1] - 0.5) <= 1e-5);
    }
    /* a double root (tangent touch): no sign change, no crossing */
    solve_result r = crossings("(x - 0.3)^2", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_int_equal(r.total, 0);
    r = crossings("(x - 0.3)^2 + y*y", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_int_equal(r.total, 0);
    /* a triple root: one crossing, found to full precision */
    r = crossings("(x - 0.3)^3", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_int_equal(r.total, 1);
    assert_true(r.inside_start);
    assert_true(fabs(r.t[0] - 0.3) <= 1e-15);
    r = crossings("(x*x + y*y + z*z - 1)^3", SOLVE_INTERVAL, 1e-9, v3(0, 0.6, 0), dx, -2,
                  2);
    assert_int_equal(r.total, 2);
    assert_true(fabs(r.t[0] + 0.8) <= 1e-14 && fabs(r.t[1] - 0.8) <= 1e-14);
}

/* Fields undefined on part of the ray (NaN counts as outside): the sign
 * change at the edge of the domain is a crossing like any other, so the
 * crossings still alternate. sqrt(x) - 0.5 < 0 on [0, 0.25); log(x) + 1
 * < 0 on (0, 1/e); max(sqrt(x), 0.1) - 0.5 < 0 on x < 0.25, since fmax
 * drops a NaN operand: there it is inside from x = -1 on. */
static void test_domain_edges(void **state)
{
    (void)state;
    vec3 o = v3(0, 0, 0), dx = v3(1, 0, 0);
    solve_result r = crossings("sqrt(x) - 0.5", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_false(r.inside_start);
    assert_int_equal(r.total, 2);
    assert_true(fabs(r.t[0]) <= 1e-9 && fabs(r.t[1] - 0.25) <= 1e-15);
    r = crossings("log(x) + 1", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_int_equal(r.total, 2);
    assert_true(fabs(r.t[0]) <= 1e-9 && fabs(r.t[1] - exp(-1)) <= 1e-15);
    r = crossings("max(sqrt(x), 0.1) - 0.5", SOLVE_INTERVAL, 1e-9, o, dx, -1, 1);
    assert_true(r.inside_start);
    assert_int_equal(r.total, 1);
    assert_true(fabs(r.t[0] - 0.25) <= 1e-15);
}

/* Near-double roots: (x - a)(x - a - delta) has two crossings delta
 * apart. The interval method finds both for every delta above its
 * tolerance, at random positions; fixed steps longer than delta cannot. */
static void test_near_double_roots(void **state)
{
    (void)state;
    rng rr = {99};
    const double tol = 1e-9;
    vec3 o = v3(0, 0, 0), dx = v3(1, 0, 0);
    for (int i = 0; i < 300; i++) {
        double a = uniform_in(&rr, -0.9, 0.8);
        double delta = exp(uniform_in(&rr, log(2 * tol), log(1e-2)));
        expr_program p;
        expr_param params[2] = {{"a", a}, {"b", a + delta}};
        expr_error e;
        const char *src = "(x - a) * (x - b)";
        assert_true(expr_compile(src, strlen(src), params, 2, &p, &e));
        double b = a + delta; /* as the program holds it */
        solve_options opt = {SOLVE_INTERVAL, tol, 0};
        solve_result r;
        solve_crossings(&p, &opt, o, dx, -1, 1, &r);
        if (r.total != 2)
            fail_msg("delta %.3g at %.17g: %u crossings", delta, a, r.total);
        assert_true(fabs(r.t[0] - a) <= 1e-15 && fabs(r.t[1] - b) <= 1e-15);
    }
    /* roots between the march's grid points x = k / 100 */
    solve_result r =
        crossings("(x - 0.3033) * (x - 0.3034)", SOLVE_MARCH, 1e-2, o, dx, 0, 1);
    assert_int_equal(r.total, 0);
    r = crossings("(x - 0.3033) * (x - 0.3034)", SOLVE_MARCH, 1e-5, o, dx, 0, 1);
    assert_int_equal(r.total, 2);
}

/* A thin feature between two evaluation points of sphere tracing is seen
 * as long as the Lipschitz bound holds; an exponential steepness makes the
 * estimate the hard part. */
static void test_lipschitz(void **state)
{
    (void)state;
    expr_program p;
    compile("sqrt(x*x + y*y + z*z) - 1", &p);
    solve_options opt = {SOLVE_LIPSCHITZ, 1e-6, 1.0};
    solve_result r;
    solve_crossings(&p, &opt, v3(-5, 0.3, 0), v3(1, 0, 0), 0, 10, &r);
    assert_int_equal(r.total, 2);
    double w = sqrt(1 - 0.09);
    assert_true(fabs(r.t[0] - (5 - w)) < 1e-6 && fabs(r.t[1] - (5 + w)) < 1e-6);
    /* The estimate exceeds the true bound 1 of a distance function. */
    bbox box = {v3(-2, -2, -2), v3(2, 2, 2)};
    double l = solve_estimate_lipschitz(&p, box);
    assert_true(l >= 1 && l <= 1.6);
}

/* A ray crossing more often than the cap: sin(20 x) < 0 on [-10, 10] has
 * 127 crossings. The leaf keeps PRIM_IMPLICIT_MAX_SPANS spans: the first
 * ones exact, the last from the cap-th span's entry to the last exit. */
static void test_span_cap(void **state)
{
    (void)state;
    expr_program p;
    compile("sin(20 * x)", &p);
    prim leaf;
    memset(&leaf, 0, sizeof leaf);
    leaf.kind = PRIM_IMPLICIT;
    leaf.u.implicit.program = &p;
    leaf.u.implicit.box = (bbox){v3(-10, -1, -1), v3(10, 1, 1)};
    leaf.u.implicit.tolerance = 1e-9;
    leaf.u.implicit.method = SOLVE_INTERVAL;
    assert_int_equal(prim_max_spans(&leaf), PRIM_IMPLICIT_MAX_SPANS);
    span s[PRIM_IMPLICIT_MAX_SPANS];
    uint32_t n =
        prim_spans(&leaf, 3, v3(-20, 0, 0), v3(1, 0, 0), s, PRIM_IMPLICIT_MAX_SPANS);
    assert_int_equal(n, PRIM_IMPLICIT_MAX_SPANS);
    const double pi = 3.14159265358979323846;
    /* Every end but the last is exact: the box face x = -10 when
     * sin(-200) < 0, else a zero of sin(20 x), where the sign changes. */
    for (uint32_t i = 0; i < n; i++) {
        double ends[2] = {s[i].in.t - 20, s[i].out.t - 20};
        for (int k = 0; k < 2; k++) {
            if (i + 1 == n && k == 1)
                continue;
            if (i == 0 && k == 0 && sin(-200.0) < 0) {
                assert_true(ends[0] == -10 && s[0].in.part != 0);
                continue;
            }
            double m = round(ends[k] * 20 / pi);
            assert_true(fabs(ends[k] - m * pi / 20) < 1e-12);
            assert_int_equal(k == 0 ? s[i].in.part : s[i].out.part, 0);
        }
    }
    /* The last span runs to the last exit: the last zero below x = 10
     * where sin(20 x) turns positive, or the box face when sin(200) < 0. */
    if (sin(200.0) < 0) {
        assert_true(s[n - 1].out.t == 30);
    } else {
        double last = floor(200 / (2 * pi)) * 2 * pi / 20;
        assert_true(fabs(s[n - 1].out.t - 20 - last) < 1e-12);
    }
    assert_true(s[n - 1].out.t - s[n - 1].in.t > 1); /* gaps past the cap filled */
    assert_true(s[n - 2].out.t - s[n - 2].in.t < pi / 20 + 1e-12);
}

static void test_methods(void **state)
{
    (void)state;
    assert_int_equal(solve_method_parse("interval"), SOLVE_INTERVAL);
    assert_int_equal(solve_method_parse("lipschitz"), SOLVE_LIPSCHITZ);
    assert_int_equal(solve_method_parse("march"), SOLVE_MARCH);
    assert_int_equal(solve_method_parse("newton"), SOLVE_METHOD_COUNT);
    assert_string_equal(expr_op_name(EXPR_ATAN2), "atan2");
}

/* sin, cos and tan of an infinite argument are NaN: the interval
 * evaluator must say the field is undefined there, not hand back [-1, 1].
 * (A fuzzed model with an infinite coefficient made every ray bisect an
 * undecided interval down to the tolerance: 28 s for an 8x8 render.) */
static void test_trig_of_infinity(void **state)
{
    (void)state;
    const char *fields[] = {"cos(1e308 * 1e308 * y) - 0.5", "sin(1e308 * 1e308 * y)",
                            "tan(1e308 * 1e308 * y) + 1",
                            /* 0 * inf is NaN: undefined everywhere */
                            "cos(0 * 10001e308 * y) - 0.5", "10001e308 * 0 + x"};
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++) {
        expr_program p;
        compile(fields[k], &p);
        ix df;
        int undefined = 0;
        /* y > 0 throughout: the argument is infinite (or NaN) everywhere */
        expr_eval_ix(&p, ix_make(-1, 1), ix_make(1, 2), ix_make(-1, 1), v3(0, 1, 0), &df,
                     &undefined);
        assert_int_equal(undefined, 2);
        /* y spans 0: infinite on both sides, 0 * inf at 0 */
        expr_eval_ix(&p, ix_make(-1, 1), ix_make(-1, 1), ix_make(-1, 1), v3(0, 1, 0), &df,
                     &undefined);
        assert_true(undefined >= 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_trig_of_infinity),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_interval_enclosure),
        cmocka_unit_test(test_interval_rules),
        cmocka_unit_test(test_dual_derivatives),
        cmocka_unit_test(test_known_roots),
        cmocka_unit_test(test_domain_edges),
        cmocka_unit_test(test_near_double_roots),
        cmocka_unit_test(test_lipschitz),
        cmocka_unit_test(test_span_cap),
        cmocka_unit_test(test_methods),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
