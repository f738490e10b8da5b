/* Tests of the torus, quadric and implicit nodes (read by
 * src/model/lower_curved.c, built by src/build/build.c): what each
 * builds (membership through csg_inside), positional and named arguments,
 * defaults, every error and warning message exactly, and the position of
 * an expression's syntax error inside its string literal, through escapes
 * and raw line breaks. The three models in models/ load and hold the
 * points they should. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "build/build.h"
#include "build/scene.h"
#include "implicit/solve.h"

static sc_scene *load(const char *text)
{
    sc_scene *s = NULL;
    sc_error e;
    if (sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e) != SC_OK) {
        char buf[1024];
        fail_msg("unexpected error: %s", sc_error_format(&e, buf, sizeof buf));
    }
    return s;
}

static void check_error(const char *text, sc_status status, const char *expected)
{
    sc_scene *s = NULL;
    sc_error e;
    sc_status st = sc_scene_load_string("m.csg", text, strlen(text), NULL, &s, &e);
    assert_null(s);
    char buf[1024];
    const char *got = sc_error_format(&e, buf, sizeof buf);
    if (st != status || strcmp(got, expected) != 0)
        fail_msg("%s\n  got (%d) %s\n  expected (%d) %s", text, st, got, status,
                 expected);
}

static void check_warning(const char *text, const char *expected)
{
    sc_scene *s = load(text);
    assert_int_equal(sc_scene_warning_count(s), 1);
    char buf[1024];
    const char *got = sc_error_format(sc_scene_warning(s, 0), buf, sizeof buf);
    const char *tag = strstr(got, "error: ");
    assert_non_null(tag);
    char joined[1024];
    snprintf(joined, sizeof joined, "%.*s%s", (int)(tag - got), got, tag + 7);
    assert_string_equal(joined, expected);
    assert_int_equal(scene_tree(s)->root, CSG_EMPTY);
    sc_scene_release(s);
}

static int inside(const sc_scene *s, double x, double y, double z)
{
    return csg_inside(scene_tree(s), v3(x, y, z));
}

static void test_torus(void **state)
{
    (void)state;
    static const char *const texts[] = {"torus(r1 = 2, r2 = 0.5);", "torus(2, 0.5);",
                                        "torus(r2 = 0.5, r1 = 2);"};
    for (size_t i = 0; i < 3; i++) {
        sc_scene *s = load(texts[i]);
        assert_true(inside(s, 2, 0, 0.4) && inside(s, 0, -2.4, 0));
        assert_false(inside(s, 0, 0, 0) || inside(s, 2, 0, 0.6));
        assert_int_equal(scene_tree(s)->leaves[0].prim.kind, PRIM_TORUS);
        sc_scene_release(s);
    }
    check_error("torus(r1 = 2);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'r2' of 'torus'");
    check_error("torus(r1 = \"a\", r2 = 1);", SC_ERR_SEMANTIC,
                "m.csg:1:12: error: wrong type for argument 'r1' of 'torus' (expected a "
                "number)");
    check_error("group() {\n  torus(r1 = 1, r2 = 2);\n}", SC_ERR_SEMANTIC,
                "m.csg:2:3: error: torus minor radius r2 = 2 must be smaller than its "
                "major radius r1 = 1");
    check_warning("torus(r1 = 0, r2 = 1);",
                  "m.csg:1:1: torus with a zero, negative or non-finite radius is empty");
    check_warning("torus(r1 = 3, r2 = -1);",
                  "m.csg:1:1: torus with a zero, negative or non-finite radius is empty");
}

static void test_quadric(void **state)
{
    (void)state;
    sc_scene *s = load("quadric(a = [1, 1, -1, 0, 0, 0, 0, 0, 0, 0], "
                       "bounds = [[-1, -1, -1], [1, 1, 1]]);");
    assert_true(inside(s, 0.1, 0, 0.5) && inside(s, 0, 0.2, -0.9));
    assert_false(inside(s, 0.6, 0, 0.5) || inside(s, 0, 0, 1.2));
    sc_scene_release(s);
    s = load("quadric([1, 1, 1, 0, 0, 0, 0, 0, 0, -1], [[-2, -2, -2], [2, 2, 2]]);");
    assert_true(inside(s, 0.9, 0, 0) && !inside(s, 1.1, 0, 0));
    sc_scene_release(s);
    check_error("quadric(bounds = [[-1, -1, -1], [1, 1, 1]]);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'a' of 'quadric'");
    check_error("quadric(a = [1, 1, 1], bounds = [[-1, -1, -1], [1, 1, 1]]);",
                SC_ERR_SEMANTIC,
                "m.csg:1:13: error: wrong type for argument 'a' of 'quadric' (expected a "
                "vector of 10 numbers)");
    check_error("quadric(a = [1, 1, 1, 0, 0, 0, 0, 0, 0, inf], "
                "bounds = [[-1, -1, -1], [1, 1, 1]]);",
                SC_ERR_SEMANTIC,
                "m.csg:1:41: error: quadric coefficient 9 is not finite");
    check_error("quadric(a = [1, 1, 1, 0, 0, 0, 0, 0, 0, -1]);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'bounds' of 'quadric'");
    check_error("quadric(a = [1, 1, 1, 0, 0, 0, 0, 0, 0, -1], bounds = [1, 2]);",
                SC_ERR_SEMANTIC,
                "m.csg:1:55: error: wrong type for argument 'bounds' of 'quadric' "
                "(expected [[x0, y0, z0], [x1, y1, z1]])");
    check_error("quadric(a = [1, 1, 1, 0, 0, 0, 0, 0, 0, -1], "
                "bounds = [[-1, -1, -1], [1, nan, 1]]);",
                SC_ERR_SEMANTIC, "m.csg:1:55: error: bounds of 'quadric' must be finite");
    check_warning("quadric(a = [1, 1, 1, 0, 0, 0, 0, 0, 0, -1], "
                  "bounds = [[-1, -1, -1], [1, -1, 1]]);",
                  "m.csg:1:1: quadric with an empty box is empty");
}

static void test_implicit(void **state)
{
    (void)state;
    sc_scene *s = load("implicit(f = \"x*x + y*y + z*z - R*R\", bounds = [[-2, -2, -2], "
                       "[2, 2, 2]], params = [[\"R\", 1.5]]);");
    assert_true(inside(s, 1.4, 0, 0) && !inside(s, 1.6, 0, 0));
    const prim *p = &scene_tree(s)->leaves[0].prim;
    assert_int_equal(p->kind, PRIM_IMPLICIT);
    assert_int_equal(p->u.implicit.method, SOLVE_INTERVAL);
    assert_true(p->u.implicit.tolerance == 4e-6); /* 1e-6 of the largest side */
    sc_scene_release(s);
    /* positional f and bounds; method, tolerance and a given Lipschitz bound */
    s = load("implicit(\"max(abs(x), abs(y), abs(z)) - 1\", [[-2, -2, -2], [2, 2, 2]], "
             "method = \"lipschitz\", tolerance = 1e-4, lipschitz = 1);");
    p = &scene_tree(s)->leaves[0].prim;
    assert_int_equal(p->u.implicit.method, SOLVE_LIPSCHITZ);
    assert_true(p->u.implicit.tolerance == 1e-4 && p->u.implicit.lipschitz == 1);
    assert_true(inside(s, 0.9, 0.9, 0.9) && !inside(s, 1.1, 0, 0));
    sc_scene_release(s);
    /* an estimated Lipschitz bound: at least the gradient norm 2 |p| */
    s = load("implicit(\"x*x + y*y + z*z - 1\", [[-1, -1, -1], [1, 1, 1]], "
             "method = \"lipschitz\");");
    p = &scene_tree(s)->leaves[0].prim;
    assert_true(p->u.implicit.lipschitz >= 2 * sqrt(3) * 15 / 16);
    sc_scene_release(s);
    s = load("implicit(\"z\", [[-1, -1, -1], [1, 1, 1]], method = \"march\");");
    assert_int_equal(scene_tree(s)->leaves[0].prim.u.implicit.method, SOLVE_MARCH);
    assert_true(inside(s, 0, 0, -0.5) && !inside(s, 0, 0, 0.5));
    sc_scene_release(s);
}

static void test_implicit_errors(void **state)
{
    (void)state;
    static const char box[] = "bounds = [[-1, -1, -1], [1, 1, 1]]";
    char text[512];
    check_error("implicit(bounds = [[-1, -1, -1], [1, 1, 1]]);", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'f' of 'implicit'");
    snprintf(text, sizeof text, "implicit(f = 1, %s);", box);
    check_error(
        text, SC_ERR_SEMANTIC,
        "m.csg:1:14: error: wrong type for argument 'f' of 'implicit' (expected a "
        "string)");
    check_error("implicit(f = \"x\");", SC_ERR_SEMANTIC,
                "m.csg:1:1: error: missing argument 'bounds' of 'implicit'");
    /* the syntax error's column is that of the character in the string */
    snprintf(text, sizeof text, "implicit(f = \"x + * y\", %s);", box);
    check_error(text, SC_ERR_SYNTAX,
                "m.csg:1:19: error: unexpected character '*' in expression");
    /* escapes: \x78 is 'x' (four bytes for one); an error at an escaped
     * quote names its backslash */
    snprintf(text, sizeof text, "implicit(f = \"\\x78 + \\\"y\", %s);", box);
    check_error(text, SC_ERR_SYNTAX,
                "m.csg:1:22: error: unexpected character '\"' in expression");
    snprintf(text, sizeof text, "implicit(f = \"\\x78 + * y\", %s);", box);
    check_error(text, SC_ERR_SYNTAX,
                "m.csg:1:22: error: unexpected character '*' in expression");
    /* raw line breaks inside the string (dropped by the lexer) */
    snprintf(text, sizeof text, "group() {\n  implicit(f = \"x +\n    foo\", %s);\n}",
             box);
    check_error(text, SC_ERR_SYNTAX, "m.csg:3:5: error: unknown name 'foo'");
    snprintf(text, sizeof text, "implicit(f = \"sin(x\", %s);", box);
    check_error(text, SC_ERR_SYNTAX,
                "m.csg:1:20: error: unexpected end of expression (expected ')' to close "
                "the call of 'sin')");
    snprintf(text, sizeof text, "implicit(f = \"\", %s);", box);
    check_error(text, SC_ERR_SYNTAX, "m.csg:1:15: error: empty expression");
    snprintf(text, sizeof text, "implicit(f = \"R * x\", %s);", box);
    check_error(text, SC_ERR_SYNTAX, "m.csg:1:15: error: unknown name 'R'");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, method = \"newton\");", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:64: error: unknown method 'newton' (expected \"interval\", "
                "\"lipschitz\" or \"march\")");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, method = 2);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:64: error: wrong type for argument 'method' of 'implicit' "
                "(expected a string)");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, tolerance = 0);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:67: error: tolerance must be a positive number");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, lipschitz = -1);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:67: error: lipschitz must be a positive number");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, params = [[\"x\", 1]]);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:66: error: parameter name 'x' is reserved");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, params = [[\"2a\", 1]]);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:66: error: parameter name '2a' is not a name (letters, digits "
                "and '_', at most 31 bytes)");
    snprintf(text, sizeof text, "implicit(f = \"x\", %s, params = [[\"a\"]]);", box);
    check_error(text, SC_ERR_SEMANTIC,
                "m.csg:1:65: error: wrong type for argument 'params' of 'implicit' "
                "(expected a vector of [\"name\", number] pairs)");
    snprintf(text, sizeof text,
             "implicit(f = \"x\", bounds = [[-1, -1, -1], [1, 1, -2]]);");
    check_warning(text, "m.csg:1:1: implicit with an empty box is empty");
    /* errors under '%' are errors too; nothing is built there */
    snprintf(text, sizeof text, "%%implicit(f = \"x +\", %s);", box);
    check_error(text, SC_ERR_SYNTAX, "m.csg:1:19: error: unexpected end of expression");
}

static void test_models(void **state)
{
    (void)state;
    static const struct {
        const char *file;
        double in[3], out[3];
    } models[] = {
        {"torus.csg", {10, 0, 0}, {0, 0, 0}},
        {"quadric.csg", {0, 0, 7.9}, {7.9, 0, 0}},
        {"gyroid.csg", {9.5, 9.5, 0}, {0, 0, 0}},
    };
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/models/%s", SPANCAST_SOURCE_DIR, models[i].file);
        sc_scene *s = NULL;
        sc_error e;
        if (sc_scene_load(path, NULL, &s, &e) != SC_OK) {
            char buf[1024];
            fail_msg("%s", sc_error_format(&e, buf, sizeof buf));
        }
        assert_int_equal(sc_scene_warning_count(s), 0);
        assert_true(inside(s, models[i].in[0], models[i].in[1], models[i].in[2]));
        assert_false(inside(s, models[i].out[0], models[i].out[1], models[i].out[2]));
        sc_scene_release(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_torus),    cmocka_unit_test(test_quadric),
        cmocka_unit_test(test_implicit), cmocka_unit_test(test_implicit_errors),
        cmocka_unit_test(test_models),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
