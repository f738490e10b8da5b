/* Cancel tokens (src/base/cancel.c) and their poll sites: a stopped
 * token ends a root finder's search within SOLVE_POLL_STEPS steps, a
 * render returns SC_ERR_CANCELLED, budgets latch the leaf that passed
 * them, and scopes nest per thread. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "base/cancel.h"
#include "implicit/expr.h"
#include "implicit/solve.h"
#include "render/render.h"

static void test_flag_latches(void **state)
{
    (void)state;
    volatile sig_atomic_t flag = 0;
    cancel_token t;
    cancel_init(&t, &flag, 0);
    assert_int_equal(cancel_check(&t), CANCEL_NONE);
    flag = 1;
    assert_int_equal(cancel_check(&t), CANCEL_FLAG);
    flag = 0; /* latched: a stop is never undone */
    assert_int_equal(cancel_check(&t), CANCEL_FLAG);
}

static void test_scopes_nest(void **state)
{
    (void)state;
    volatile sig_atomic_t stopped = 1;
    cancel_token running, done;
    cancel_init(&running, NULL, 0);
    cancel_init(&done, &stopped, 0);
    assert_false(cancel_active());
    assert_false(cancel_poll());
    cancel_scope outer, inner;
    cancel_enter(&outer, &running);
    assert_true(cancel_active());
    assert_false(cancel_poll());
    cancel_enter(&inner, &done);
    assert_true(cancel_poll());
    cancel_leave(&inner);
    assert_false(cancel_poll());
    cancel_leave(&outer);
    assert_false(cancel_active());
}

static void test_budget_and_credit(void **state)
{
    (void)state;
    cancel_token t;
    cancel_init(&t, NULL, 100);
    cancel_scope s;
    cancel_enter(&s, &t);
    int prim = 0;
    cancel_working_on(3, &prim);
    cancel_spend(80);
    assert_int_equal(cancel_check(&t), CANCEL_NONE);
    cancel_credit(&t, 50); /* now 150 allowed */
    cancel_working_on(4, &prim);
    cancel_spend(60);
    assert_int_equal(cancel_check(&t), CANCEL_NONE);
    cancel_working_on(5, &prim);
    cancel_spend(20); /* 160 > 150 */
    assert_int_equal(cancel_check(&t), CANCEL_BUDGET);
    assert_int_equal(atomic_load(&t.leaf), 5);
    assert_ptr_equal(atomic_load(&t.prim), &prim);
    cancel_stop(CANCEL_RAY_LIMIT); /* the first reason stays */
    assert_int_equal(cancel_check(&t), CANCEL_BUDGET);
    cancel_leave(&s);
}

/* A field undecided everywhere: the interval method bisects it to the
 * tolerance on every ray, up to SOLVE_MAX_EVALS. */
static void compile_hostile(expr_program *p)
{
    const char *src = "sin(1e7 * x) * cos(1e6 * y) + z";
    expr_error e;
    assert_true(expr_compile(src, strlen(src), NULL, 0, p, &e));
}

static void test_solver_stops(void **state)
{
    (void)state;
    static expr_program p;
    compile_hostile(&p);
    solve_options opt = {SOLVE_INTERVAL, 1e-6, 2e7}; /* a true bound on |grad f| */
    solve_result r;
    /* without a token: the whole bound is spent */
    solve_crossings(&p, &opt, v3(-1, 0.3, 0.001), v3(1, 0, 0), 0, 2, &r);
    assert_false(r.stopped);
    uint64_t full = r.evals;
    assert_true(full > 100 * SOLVE_POLL_STEPS);
    /* with a stopped token: ends at the first poll */
    volatile sig_atomic_t flag = 1;
    cancel_token t;
    cancel_init(&t, &flag, 0);
    cancel_scope s;
    cancel_enter(&s, &t);
    for (int m = 0; m < SOLVE_METHOD_COUNT; m++) {
        opt.method = (solve_method)m;
        solve_crossings(&p, &opt, v3(-1, 0.3, 0.001), v3(1, 0, 0), 0, 2, &r);
        assert_true(r.stopped);
        /* at most SOLVE_POLL_STEPS steps, each an evaluation, a split
         * and a Newton refinement of at most 128 */
        if (!(r.evals <= (uint64_t)SOLVE_POLL_STEPS * 131 + 2))
            fail_msg("method %d: %llu evaluations", m, (unsigned long long)r.evals);
        if (!(r.evals * 10 < full))
            fail_msg("method %d: %llu evaluations (full %llu)", m,
                     (unsigned long long)r.evals, (unsigned long long)full);
    }
    cancel_leave(&s);
}

static void test_trig_reach(void **state)
{
    (void)state;
    static expr_program p;
    expr_error e;
    const char *huge = "sin(1e118 * x) * cos(1e100 * y) + z";
    assert_true(expr_compile(huge, strlen(huge), NULL, 0, &p, &e));
    expr_op op;
    double reach =
        expr_trig_reach(&p, ix_make(-1, 1), ix_make(-1, 1), ix_make(-1, 1), &op);
    assert_true(reach >= 1e118);
    assert_int_equal(op, EXPR_SIN);
    compile_hostile(&p); /* fine, but not beyond 2^53 */
    reach = expr_trig_reach(&p, ix_make(-1, 1), ix_make(-1, 1), ix_make(-1, 1), &op);
    assert_true(reach >= 1e7 && reach < EXPR_TRIG_MAX_ARGUMENT);
    const char *none = "x * x + y * y + z * z - 1";
    assert_true(expr_compile(none, strlen(none), NULL, 0, &p, &e));
    assert_true(
        expr_trig_reach(&p, ix_make(-1, 1), ix_make(-1, 1), ix_make(-1, 1), &op) == 0);
    assert_int_equal(op, EXPR_OP_COUNT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flag_latches),      cmocka_unit_test(test_scopes_nest),
        cmocka_unit_test(test_budget_and_credit), cmocka_unit_test(test_solver_stops),
        cmocka_unit_test(test_trig_reach),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
