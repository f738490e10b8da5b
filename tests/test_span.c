/* Tests of src/csg/span.c: the boolean table and the regularisation rule.
 *
 * The table crosses two span lists A and B in every configuration that
 * matters (disjoint, touching, overlapping, containing both ways, equal,
 * zero-length, behind the ray, near-touching and near-overlapping by half
 * and twice the tolerance, several spans each) with union, intersection and
 * difference, in both operand orders. Every expected list names the input
 * surface at each end: "Ai0" is the entry of A's span 0, "Bo1" the exit of
 * B's span 1, a trailing ' says the surface's flip bit is toggled (a
 * subtracted surface). The t, leaf, part and flip of each expected end are
 * read from that input end, so the table checks which surface bounds every
 * span, not only where.
 *
 * Ties: where boundaries of both operands fall at the same t, the sweep
 * takes the first operand's boundary first; the zero-length spans and gaps
 * this leaves are removed by the regularisation, and the surface reported
 * at a fused boundary follows from that order. The table spells out the
 * outcome for both orders.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "csg/span.h"

enum { LEAF_A = 1, LEAF_B = 2, MAX_SPANS = 8 };

static const double EPS = 1e-6;

/* Span k of A has parts 10 + 2k (entry) and 11 + 2k (exit); of B, 20 + 2k
 * and 21 + 2k. */
static void fill(span *v, uint32_t n, const double *t, uint32_t leaf, uint16_t base,
                 uint8_t flip)
{
    for (uint32_t k = 0; k < n; k++) {
        v[k].in = (span_end){t[2 * k], leaf, (uint16_t)(base + 2 * k), flip};
        v[k].out = (span_end){t[2 * k + 1], leaf, (uint16_t)(base + 2 * k + 1), flip};
    }
}

typedef struct row {
    const char *name;
    uint32_t na, nb;
    double a[2 * 3], b[2 * 3]; /* span ends in order */
    /* Expected lists for A op B and B op A, op in union, intersection,
     * difference. */
    const char *expect[3][2];
} row;

static const char *op_name[3] = {"union", "intersection", "difference"};

/* Resolves one token ("Ai0", "Bo1'") to the input end it names. */
static span_end resolve(const char *tok, const span *a, const span *b)
{
    const span *list = tok[0] == 'A' ? a : b;
    int k = tok[2] - '0';
    span_end e = tok[1] == 'i' ? list[k].in : list[k].out;
    if (tok[3] == '\'')
        e.flip ^= 1;
    return e;
}

/* Parses "[Ai0 Bo0'] [..]" into spans. */
static uint32_t parse_expect(const char *text, const span *a, const span *b, span *out)
{
    uint32_t n = 0;
    char tok_in[8], tok_out[8];
    int used;
    while (sscanf(text, " [%7s %7[^]]]%n", tok_in, tok_out, &used) == 2) {
        assert_true(n < MAX_SPANS);
        out[n].in = resolve(tok_in, a, b);
        out[n].out = resolve(tok_out, a, b);
        n++;
        text += used;
    }
    while (*text == ' ')
        text++;
    assert_true(*text == '\0'); /* the table itself is well formed */
    return n;
}

static int same_end(span_end x, span_end y)
{
    return x.t == y.t && x.leaf == y.leaf && x.part == y.part && x.flip == y.flip;
}

static void print_list(const char *label, const span *v, uint32_t n)
{
    print_error("  %s:", label);
    for (uint32_t i = 0; i < n; i++)
        print_error(" [%.9g (leaf %u part %u flip %u), %.9g (leaf %u part %u flip %u)]",
                    v[i].in.t, v[i].in.leaf, v[i].in.part, v[i].in.flip, v[i].out.t,
                    v[i].out.leaf, v[i].out.part, v[i].out.flip);
    print_error("\n");
}

static int check_row(const row *r, arena *scratch)
{
    span a[3], b[3];
    fill(a, r->na, r->a, LEAF_A, 10, 0);
    fill(b, r->nb, r->b, LEAF_B, 20, 0);
    span_list la = {a, r->na}, lb = {b, r->nb};
    int failures = 0;
    for (int op = 0; op < 3; op++) {
        for (int order = 0; order < 2; order++) {
            span want[MAX_SPANS];
            uint32_t nwant = parse_expect(r->expect[op][order], a, b, want);
            int oom = 0;
            span_list got = order == 0
                                ? span_combine((span_op)op, la, lb, EPS, scratch, &oom)
                                : span_combine((span_op)op, lb, la, EPS, scratch, &oom);
            assert_int_equal(oom, 0);
            int ok = got.n == nwant;
            for (uint32_t i = 0; ok && i < nwant; i++)
                ok = same_end(got.v[i].in, want[i].in) &&
                     same_end(got.v[i].out, want[i].out);
            if (!ok) {
                print_error("%s: %s %s: expected %s\n", r->name, order == 0 ? "A" : "B",
                            op_name[op], r->expect[op][order]);
                print_list("expected", want, nwant);
                print_list("got", got.v, got.n);
                failures++;
            }
            /* Inputs are never modified. */
            for (uint32_t k = 0; k < r->na; k++)
                assert_true(a[k].in.t == r->a[2 * k] && a[k].out.t == r->a[2 * k + 1]);
        }
    }
    return failures;
}

#define HALF (0.5 * 1e-6)
#define TWICE (2 * 1e-6)

static const row table[] = {
    {"disjoint",
     1,
     1,
     {1, 2},
     {3, 4},
     {{"[Ai0 Ao0] [Bi0 Bo0]", "[Ai0 Ao0] [Bi0 Bo0]"},
      {"", ""},
      {"[Ai0 Ao0]", "[Bi0 Bo0]"}}},
    {"touching",
     1,
     1,
     {1, 2},
     {2, 3},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"}, {"", ""}, {"[Ai0 Ao0]", "[Ao0' Bo0]"}}},
    {"overlapping",
     1,
     1,
     {1, 3},
     {2, 4},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"},
      {"[Bi0 Ao0]", "[Bi0 Ao0]"},
      {"[Ai0 Bi0']", "[Ao0' Bo0]"}}},
    {"A contains B",
     1,
     1,
     {1, 4},
     {2, 3},
     {{"[Ai0 Ao0]", "[Ai0 Ao0]"},
      {"[Bi0 Bo0]", "[Bi0 Bo0]"},
      {"[Ai0 Bi0'] [Bo0' Ao0]", ""}}},
    {"B contains A",
     1,
     1,
     {2, 3},
     {1, 4},
     {{"[Bi0 Bo0]", "[Bi0 Bo0]"},
      {"[Ai0 Ao0]", "[Ai0 Ao0]"},
      {"", "[Bi0 Ai0'] [Ao0' Bo0]"}}},
    {"equal",
     1,
     1,
     {1, 2},
     {1, 2},
     {{"[Ai0 Bo0]", "[Bi0 Ao0]"}, {"[Bi0 Ao0]", "[Ai0 Bo0]"}, {"", ""}}},
    /* A zero-length A inside B: it neither adds to a union nor leaves
     * anything in an intersection, and subtracting it cuts nothing: the
     * zero-length gap it would leave is closed. */
    {"zero-length",
     1,
     1,
     {2, 2},
     {1, 3},
     {{"[Bi0 Bo0]", "[Bi0 Bo0]"}, {"", ""}, {"", "[Bi0 Bo0]"}}},
    {"behind the ray",
     1,
     1,
     {-4, -1},
     {-2, 3},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"},
      {"[Bi0 Ao0]", "[Bi0 Ao0]"},
      {"[Ai0 Bi0']", "[Ao0' Bo0]"}}},
    {"gap of half eps",
     1,
     1,
     {1, 2},
     {2 + HALF, 3},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"}, {"", ""}, {"[Ai0 Ao0]", "[Bi0 Bo0]"}}},
    {"gap of twice eps",
     1,
     1,
     {1, 2},
     {2 + TWICE, 3},
     {{"[Ai0 Ao0] [Bi0 Bo0]", "[Ai0 Ao0] [Bi0 Bo0]"},
      {"", ""},
      {"[Ai0 Ao0]", "[Bi0 Bo0]"}}},
    {"overlap of half eps",
     1,
     1,
     {1, 2},
     {2 - HALF, 3},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"}, {"", ""}, {"[Ai0 Bi0']", "[Ao0' Bo0]"}}},
    {"overlap of twice eps",
     1,
     1,
     {1, 2},
     {2 - TWICE, 3},
     {{"[Ai0 Bo0]", "[Ai0 Bo0]"},
      {"[Bi0 Ao0]", "[Bi0 Ao0]"},
      {"[Ai0 Bi0']", "[Ao0' Bo0]"}}},
    {"several spans",
     3,
     2,
     {0, 2, 4, 6, 8, 10},
     {1, 5, 7, 9},
     {{"[Ai0 Ao1] [Bi1 Ao2]", "[Ai0 Ao1] [Bi1 Ao2]"},
      {"[Bi0 Ao0] [Ai1 Bo0] [Ai2 Bo1]", "[Bi0 Ao0] [Ai1 Bo0] [Ai2 Bo1]"},
      {"[Ai0 Bi0'] [Bo0' Ao1] [Bo1' Ao2]", "[Ao0' Ai1'] [Bi1 Ai2']"}}},
    /* Spans of A touching B's at both ends: B fills A's gaps exactly. In
     * A - B, A's second span starts where B's first ends; the sweep meets
     * A's entry first (still inside B), so the surface reported is B's exit,
     * flipped. */
    {"interleaved, touching",
     2,
     2,
     {0, 1, 2, 3},
     {1, 2, 3, 4},
     {{"[Ai0 Bo1]", "[Ai0 Bo1]"},
      {"", ""},
      {"[Ai0 Ao0] [Bo0' Ao1]", "[Ao0' Bo0] [Ao1' Bo1]"}}},
};

static void test_boolean_table(void **state)
{
    (void)state;
    arena scratch;
    arena_init(&scratch, 0);
    int failures = 0;
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        failures += check_row(&table[i], &scratch);
    arena_free(&scratch);
    assert_int_equal(failures, 0);
}

/* Difference toggles the flip bit of the subtracted surfaces, so a surface
 * subtracted twice (A - (B - C)) is seen unflipped; the first operand's
 * flips are kept. */
static void test_difference_toggles_flip(void **state)
{
    (void)state;
    arena scratch;
    arena_init(&scratch, 0);
    span a[1], b[1];
    const double ta[2] = {0, 10}, tb[2] = {2, 5};
    fill(a, 1, ta, LEAF_A, 10, 1);
    fill(b, 1, tb, LEAF_B, 20, 1);
    int oom = 0;
    span_list r = span_combine(SPAN_DIFFERENCE, (span_list){a, 1}, (span_list){b, 1}, EPS,
                               &scratch, &oom);
    assert_int_equal(r.n, 2);
    assert_true(same_end(r.v[0].in, a[0].in));
    assert_true(r.v[0].out.t == 2 && r.v[0].out.leaf == LEAF_B && r.v[0].out.part == 20);
    assert_int_equal(r.v[0].out.flip, 0);
    assert_true(r.v[1].in.t == 5 && r.v[1].in.part == 21);
    assert_int_equal(r.v[1].in.flip, 0);
    assert_true(same_end(r.v[1].out, a[0].out));
    assert_int_equal(r.v[1].out.flip, 1);
    /* Union and intersection never touch the flip bits. */
    r = span_combine(SPAN_INTERSECTION, (span_list){a, 1}, (span_list){b, 1}, EPS,
                     &scratch, &oom);
    assert_int_equal(r.n, 1);
    assert_true(same_end(r.v[0].in, b[0].in) && same_end(r.v[0].out, b[0].out));
    assert_int_equal(oom, 0);
    arena_free(&scratch);
}

/* An empty operand: union gives the other, intersection nothing, difference
 * the first (or nothing when the first is empty). */
static void test_empty_operands(void **state)
{
    (void)state;
    arena scratch;
    arena_init(&scratch, 0);
    span a[1];
    const double ta[2] = {1, 2};
    fill(a, 1, ta, LEAF_A, 10, 0);
    span_list la = {a, 1}, none = {NULL, 0};
    int oom = 0;
    span_list r = span_combine(SPAN_UNION, none, la, EPS, &scratch, &oom);
    assert_true(r.n == 1 && same_end(r.v[0].in, a[0].in) &&
                same_end(r.v[0].out, a[0].out));
    r = span_combine(SPAN_UNION, la, none, EPS, &scratch, &oom);
    assert_true(r.n == 1 && same_end(r.v[0].in, a[0].in));
    assert_int_equal(span_combine(SPAN_INTERSECTION, la, none, EPS, &scratch, &oom).n, 0);
    assert_int_equal(span_combine(SPAN_INTERSECTION, none, la, EPS, &scratch, &oom).n, 0);
    r = span_combine(SPAN_DIFFERENCE, la, none, EPS, &scratch, &oom);
    assert_true(r.n == 1 && same_end(r.v[0].out, a[0].out) && r.v[0].out.flip == 0);
    assert_int_equal(span_combine(SPAN_DIFFERENCE, none, la, EPS, &scratch, &oom).n, 0);
    assert_int_equal(span_combine(SPAN_UNION, none, none, EPS, &scratch, &oom).n, 0);
    assert_int_equal(oom, 0);
    arena_free(&scratch);
}

/* The rule on its own, with eps = 0.25 so every boundary case is exact:
 * a gap of exactly eps closes (the outer surfaces are kept), a span of
 * exactly eps vanishes, and gaps close before short spans are judged, so a
 * chain of short spans with short gaps fuses into one long span. */
static void test_regularize(void **state)
{
    (void)state;
    const double e = 0.25;
    span v[8];
    const double t1[] = {0, 1, 1.25, 2, 3, 3.25, 5, 6};
    fill(v, 4, t1, LEAF_A, 10, 0);
    uint32_t n = span_regularize(v, 4, e);
    assert_int_equal(n, 2);
    assert_true(v[0].in.t == 0 && v[0].in.part == 10);
    assert_true(v[0].out.t == 2 && v[0].out.part == 13); /* exit of the second span */
    assert_true(v[1].in.t == 5 && v[1].out.t == 6);      /* [3, 3.25] is gone */

    /* A gap just over eps stays, a span just over eps stays. */
    const double t2[] = {0, 1, 1.2500001, 1.5000002};
    fill(v, 2, t2, LEAF_A, 10, 0);
    assert_int_equal(span_regularize(v, 2, e), 2);

    /* Slivers 0.125 long with gaps 0.125: fuse to [0, 0.625], longer than
     * eps, so they stay as one span. */
    const double t3[] = {0, 0.125, 0.25, 0.375, 0.5, 0.625};
    fill(v, 3, t3, LEAF_A, 10, 0);
    n = span_regularize(v, 3, e);
    assert_int_equal(n, 1);
    assert_true(v[0].in.t == 0 && v[0].in.part == 10);
    assert_true(v[0].out.t == 0.625 && v[0].out.part == 15);

    /* Zero-length spans alone vanish; an empty list stays empty. */
    const double t4[] = {1, 1, 4, 4};
    fill(v, 2, t4, LEAF_A, 10, 0);
    assert_int_equal(span_regularize(v, 2, e), 0);
    assert_int_equal(span_regularize(v, 0, e), 0);

    /* With eps = 0 only exact coincidences are repaired. */
    const double t5[] = {0, 1, 1, 2, 3, 3};
    fill(v, 3, t5, LEAF_A, 10, 0);
    n = span_regularize(v, 3, 0);
    assert_int_equal(n, 1);
    assert_true(v[0].in.t == 0 && v[0].out.t == 2);
}

/* A long sweep of many spans against many, checked against a pointwise
 * evaluation of the predicate at every midpoint between boundaries. */
static void test_sweep_against_predicate(void **state)
{
    (void)state;
    arena scratch;
    arena_init(&scratch, 0);
    uint64_t x = 0x2545F4914F6CDD1DULL;
    for (int round = 0; round < 2000; round++) {
        span a[6], b[6];
        uint32_t na = 0, nb = 0;
        double t = 0;
        for (; na < 6; na++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            double len = 0.5 + (double)(x % 8) * 0.25,
                   gap = 0.25 + (double)(x >> 60) * 0.25;
            a[na].in = (span_end){t, LEAF_A, 0, 0};
            a[na].out = (span_end){t + len, LEAF_A, 1, 0};
            t += len + gap;
        }
        t = (double)(x % 3) * 0.5;
        for (; nb < 6; nb++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            double len = 0.25 + (double)(x % 8) * 0.25,
                   gap = 0.5 + (double)(x >> 61) * 0.25;
            b[nb].in = (span_end){t, LEAF_B, 0, 0};
            b[nb].out = (span_end){t + len, LEAF_B, 1, 0};
            t += len + gap;
        }
        for (int op = 0; op < 3; op++) {
            int oom = 0;
            span_list r = span_combine((span_op)op, (span_list){a, na},
                                       (span_list){b, nb}, EPS, &scratch, &oom);
            assert_int_equal(oom, 0);
            /* Boundaries lie on the 1/4 grid, so midpoints of the 1/8 grid
             * lie strictly between them. */
            for (double s = -0.125; s < 100; s += 0.25) {
                int in_a = 0, in_b = 0, in_r = 0;
                for (uint32_t i = 0; i < na; i++)
                    in_a |= s > a[i].in.t && s < a[i].out.t;
                for (uint32_t i = 0; i < nb; i++)
                    in_b |= s > b[i].in.t && s < b[i].out.t;
                for (uint32_t i = 0; i < r.n; i++)
                    in_r |= s > r.v[i].in.t && s < r.v[i].out.t;
                int want = op == SPAN_UNION          ? in_a || in_b
                           : op == SPAN_INTERSECTION ? in_a && in_b
                                                     : in_a && !in_b;
                assert_int_equal(in_r, want);
            }
            for (uint32_t i = 0; i < r.n; i++) {
                assert_true(r.v[i].out.t - r.v[i].in.t > EPS);
                if (i > 0)
                    assert_true(r.v[i].in.t - r.v[i - 1].out.t > EPS);
            }
        }
        arena_reset(&scratch);
    }
    arena_free(&scratch);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_boolean_table),
        cmocka_unit_test(test_difference_toggles_flip),
        cmocka_unit_test(test_empty_operands),
        cmocka_unit_test(test_regularize),
        cmocka_unit_test(test_sweep_against_predicate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
