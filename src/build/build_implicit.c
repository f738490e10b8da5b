/* Building torus, quadric and implicit leaves: see build_curved.h for the
 * nodes. Messages follow build.c's: wrong types name the argument and what
 * was expected; missing required arguments are errors; sizes that make no
 * geometry are warnings (the leaf is empty), as OpenSCAD does for cubes.
 *
 * An implicit's expression is compiled here, once; a syntax error in it is
 * reported at the offending character inside the string literal (its file
 * line and column, escapes and raw line breaks accounted for by
 * lex_string_locate). The default tolerance is 1e-6 of the box's largest
 * side; the default Lipschitz bound (used only by method "lipschitz") is
 * estimated by sampling the gradient (solve_estimate_lipschitz).
 */
#include <math.h>
#include <string.h>

#include "base/error.h"
#include "build/build_curved.h"
#include "implicit/solve.h"
#include "syntax/lex.h"

static sc_status missing(const build_ctx *c, const parse_node *n, const char *param)
{
    return err_set(c->error, SC_ERR_SEMANTIC, &n->loc, "missing argument '%s' of '%s'",
                   param, n->name);
}

static sc_status number_arg(const build_ctx *c, const parse_node *n, const char *name,
                            int position, int required, double *out, int *given)
{
    const parse_value *v = build_arg(n, name, position);
    *given = 0;
    if (!v)
        return required ? missing(c, n, name) : SC_OK;
    if (v->kind != PARSE_NUMBER)
        return build_wrong_type(c, n, name, v, "a number");
    *out = v->u.number;
    *given = 1;
    return SC_OK;
}

/* Reads count numbers of the vector v into out; 0 when v is not such. */
static int numbers(const parse_value *v, uint32_t count, double *out)
{
    if (v->kind != PARSE_VECTOR || v->u.vector.count != count)
        return 0;
    for (uint32_t i = 0; i < count; i++) {
        if (v->u.vector.items[i].kind != PARSE_NUMBER)
            return 0;
        out[i] = v->u.vector.items[i].u.number;
    }
    return 1;
}

static const char bounds_expected[] = "[[x0, y0, z0], [x1, y1, z1]]";

/* bounds = [[x0, y0, z0], [x1, y1, z1]]: required, finite. *empty is set
 * when some x1 <= x0. */
static sc_status bounds_arg(const build_ctx *c, const parse_node *n, int position,
                            bbox *out, const char **empty)
{
    const parse_value *v = build_arg(n, "bounds", position);
    if (!v)
        return missing(c, n, "bounds");
    double lo[3], hi[3];
    if (v->kind != PARSE_VECTOR || v->u.vector.count != 2 ||
        !numbers(&v->u.vector.items[0], 3, lo) || !numbers(&v->u.vector.items[1], 3, hi))
        return build_wrong_type(c, n, "bounds", v, bounds_expected);
    for (int k = 0; k < 3; k++) {
        if (!isfinite(lo[k]) || !isfinite(hi[k])) {
            sc_location loc = build_loc(c, v);
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "bounds of '%s' must be finite", n->name);
        }
        if (!(lo[k] < hi[k]))
            *empty = n->name[0] == 'q' ? "quadric with an empty box is empty"
                                       : "implicit with an empty box is empty";
    }
    out->lo = v3(lo[0], lo[1], lo[2]);
    out->hi = v3(hi[0], hi[1], hi[2]);
    return SC_OK;
}

/* torus(r1, r2) */
sc_status build_torus(const build_ctx *c, const parse_node *n, int emit, prim *out,
                      const char **empty)
{
    double r1 = 0, r2 = 0;
    int given;
    sc_status st = number_arg(c, n, "r1", 0, 1, &r1, &given);
    if (st == SC_OK)
        st = number_arg(c, n, "r2", 1, 1, &r2, &given);
    if (st != SC_OK)
        return st;
    if (!(r1 > 0 && r2 > 0 && isfinite(r1) && isfinite(r2))) {
        *empty = "torus with a zero, negative or non-finite radius is empty";
        return SC_OK;
    }
    if (!(r2 < r1))
        return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                       "torus minor radius r2 = %g must be smaller than its major radius "
                       "r1 = %g",
                       r2, r1);
    if (!emit)
        return SC_OK;
    memset(out, 0, sizeof *out);
    out->kind = PRIM_TORUS;
    out->u.torus.major = r1;
    out->u.torus.minor = r2;
    return SC_OK;
}

/* quadric(a = [A, ..., J], bounds) */
sc_status build_quadric(const build_ctx *c, const parse_node *n, int emit, prim *out,
                        const char **empty)
{
    const parse_value *v = build_arg(n, "a", 0);
    if (!v)
        return missing(c, n, "a");
    double a[10];
    if (!numbers(v, 10, a))
        return build_wrong_type(c, n, "a", v, "a vector of 10 numbers");
    for (int i = 0; i < 10; i++) {
        if (!isfinite(a[i])) {
            sc_location loc = build_loc(c, &v->u.vector.items[i]);
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "quadric coefficient %d is not finite", i);
        }
    }
    bbox box;
    sc_status st = bounds_arg(c, n, 1, &box, empty);
    if (st != SC_OK || !emit || *empty)
        return st;
    memset(out, 0, sizeof *out);
    out->kind = PRIM_QUADRIC;
    memcpy(out->u.quadric.a, a, sizeof a);
    out->u.quadric.box = box;
    return SC_OK;
}

static const char params_expected[] = "a vector of [\"name\", number] pairs";

static int valid_name(const char *s, size_t len)
{
    if (len == 0 || len >= EXPR_MAX_NAME ||
        !(s[0] == '_' || (s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z')))
        return 0;
    for (size_t i = 1; i < len; i++) {
        char ch = s[i];
        if (!(ch == '_' || (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
              (ch >= '0' && ch <= '9')))
            return 0;
    }
    return 1;
}

/* params = [["name", value], ...] */
static sc_status params_arg(const build_ctx *c, const parse_node *n, expr_param *params,
                            uint32_t *count)
{
    *count = 0;
    const parse_value *v = build_arg(n, "params", -1);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return build_wrong_type(c, n, "params", v, params_expected);
    for (uint32_t i = 0; i < v->u.vector.count; i++) {
        const parse_value *pair = &v->u.vector.items[i];
        if (pair->kind != PARSE_VECTOR || pair->u.vector.count != 2 ||
            pair->u.vector.items[0].kind != PARSE_STRING ||
            pair->u.vector.items[1].kind != PARSE_NUMBER)
            return build_wrong_type(c, n, "params", pair, params_expected);
        const parse_value *name = &pair->u.vector.items[0];
        sc_location loc = build_loc(c, name);
        const char *s = name->u.string.chars;
        size_t len = name->u.string.length;
        if (!valid_name(s, len))
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "parameter name '%s' is not a name (letters, digits and '_', "
                           "at most %d bytes)",
                           s, EXPR_MAX_NAME - 1);
        if ((len == 1 && (s[0] == 'x' || s[0] == 'y' || s[0] == 'z')) ||
            strcmp(s, "pi") == 0)
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "parameter name '%s' is reserved", s);
        if (*count == EXPR_MAX_PARAMS)
            return err_set(c->error, SC_ERR_LIMIT, &loc,
                           "too many parameters (limit is %d)", EXPR_MAX_PARAMS);
        memcpy(params[*count].name, s, len + 1);
        params[*count].value = pair->u.vector.items[1].u.number;
        (*count)++;
    }
    return SC_OK;
}

/* implicit(f, bounds, method = "interval", tolerance, params, lipschitz) */
sc_status build_implicit(const build_ctx *c, const parse_node *n, int emit, prim *out,
                         const char **empty)
{
    const parse_value *f = build_arg(n, "f", 0);
    if (!f)
        return missing(c, n, "f");
    if (f->kind != PARSE_STRING)
        return build_wrong_type(c, n, "f", f, "a string");
    bbox box;
    sc_status st = bounds_arg(c, n, 1, &box, empty);
    if (st != SC_OK)
        return st;
    solve_method method = SOLVE_INTERVAL;
    const parse_value *m = build_arg(n, "method", -1);
    if (m && m->kind != PARSE_STRING)
        return build_wrong_type(c, n, "method", m, "a string");
    if (m && (method = solve_method_parse(m->u.string.chars)) == SOLVE_METHOD_COUNT) {
        sc_location loc = build_loc(c, m);
        return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                       "unknown method '%s' (expected \"interval\", \"lipschitz\" or "
                       "\"march\")",
                       m->u.string.chars);
    }
    double tolerance = 1e-6 * v3_max_abs(bbox_extent(&box)), lipschitz = 0;
    int has_tolerance, has_lipschitz;
    if ((st = number_arg(c, n, "tolerance", -1, 0, &tolerance, &has_tolerance)) != SC_OK)
        return st;
    if (has_tolerance && !(tolerance > 0 && isfinite(tolerance))) {
        sc_location loc = build_loc(c, build_arg(n, "tolerance", -1));
        return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                       "tolerance must be a positive number");
    }
    if ((st = number_arg(c, n, "lipschitz", -1, 0, &lipschitz, &has_lipschitz)) != SC_OK)
        return st;
    if (has_lipschitz && !(lipschitz > 0 && isfinite(lipschitz))) {
        sc_location loc = build_loc(c, build_arg(n, "lipschitz", -1));
        return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                       "lipschitz must be a positive number");
    }
    expr_param params[EXPR_MAX_PARAMS];
    uint32_t param_count;
    if ((st = params_arg(c, n, params, &param_count)) != SC_OK)
        return st;

    expr_program *program = NULL;
    expr_program local;
    if (emit && !*empty) {
        program = csg_builder_alloc(c->csg, sizeof *program);
        if (!program)
            return err_nomem(c->error, NULL);
    }
    expr_error e;
    if (!expr_compile(f->u.string.chars, f->u.string.length, params, param_count,
                      program ? program : &local, &e)) {
        sc_location loc = {c->file, 0, 0};
        lex_string_locate(f->u.string.raw, f->u.string.raw_length, f->line, f->column,
                          e.offset, &loc.line, &loc.column);
        return err_set(c->error, SC_ERR_SYNTAX, &loc, "%s", e.message);
    }
    if (!program)
        return SC_OK;
    if (method == SOLVE_LIPSCHITZ && !has_lipschitz)
        lipschitz = solve_estimate_lipschitz(program, box);
    memset(out, 0, sizeof *out);
    out->kind = PRIM_IMPLICIT;
    out->u.implicit.program = program;
    out->u.implicit.box = box;
    out->u.implicit.tolerance = tolerance;
    out->u.implicit.lipschitz = lipschitz;
    out->u.implicit.method = (int)method;
    return SC_OK;
}
