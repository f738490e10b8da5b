/* Lowering of spancast's curved leaves, torus, quadric and implicit (the
 * nodes are in model.h): every argument read and checked. Messages follow
 * the other nodes': wrong types name the argument and what was expected;
 * missing required arguments are errors; sizes that make no geometry are
 * the builder's warnings (the leaf is empty: `empty` says why), as OpenSCAD
 * does for cubes.
 *
 * An implicit's expression is compiled here, once; a syntax error in it is
 * reported at the offending character inside the string literal (its file
 * line and column, escapes and raw line breaks accounted for by
 * lex_string_locate). A field that no ray can resolve (a trigonometric
 * argument past 2^53 within the box) is refused here too, at the node. The
 * default tolerance is 1e-6 of the box's largest
 * side; the default Lipschitz bound (used only by method "lipschitz") is
 * the builder's to estimate (solve_estimate_lipschitz), where the leaf is
 * built.
 */
#include <math.h>
#include <string.h>

#include "model/lower_curved.h"

#include "base/error.h"
#include "implicit/solve.h"
#include "model/args.h"
#include "syntax/lex.h"

static sc_status missing(const model_reader *c, const parse_node *n, const char *param)
{
    return err_set(c->error, SC_ERR_SEMANTIC, &n->loc, "missing argument '%s' of '%s'",
                   param, n->name);
}

static sc_status number_arg(const model_reader *c, const parse_node *n, const char *name,
                            int position, int required, double *out, int *given)
{
    const parse_value *v = model_arg(n, name, position);
    *given = 0;
    if (!v)
        return required ? missing(c, n, name) : SC_OK;
    if (v->kind != PARSE_NUMBER)
        return model_wrong_type(c, n, name, v, "a number");
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
static sc_status bounds_arg(const model_reader *c, const parse_node *n, int position,
                            const char *empty_message, bbox *out, const char **empty)
{
    const parse_value *v = model_arg(n, "bounds", position);
    if (!v)
        return missing(c, n, "bounds");
    double lo[3], hi[3];
    if (v->kind != PARSE_VECTOR || v->u.vector.count != 2 ||
        !numbers(&v->u.vector.items[0], 3, lo) || !numbers(&v->u.vector.items[1], 3, hi))
        return model_wrong_type(c, n, "bounds", v, bounds_expected);
    for (int k = 0; k < 3; k++) {
        if (!isfinite(lo[k]) || !isfinite(hi[k])) {
            sc_location loc = model_loc(c, v);
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "bounds of '%s' must be finite", n->name);
        }
        if (!(lo[k] < hi[k]))
            *empty = empty_message;
    }
    out->lo = v3(lo[0], lo[1], lo[2]);
    out->hi = v3(hi[0], hi[1], hi[2]);
    return SC_OK;
}

/* torus(r1, r2) */
sc_status model_read_torus(const model_reader *c, const parse_node *n, model_torus *out)
{
    double r1 = 0, r2 = 0;
    int given;
    sc_status st = number_arg(c, n, "r1", 0, 1, &r1, &given);
    if (st == SC_OK)
        st = number_arg(c, n, "r2", 1, 1, &r2, &given);
    if (st != SC_OK)
        return st;
    out->r1 = r1;
    out->r2 = r2;
    if (!(r1 > 0 && r2 > 0 && isfinite(r1) && isfinite(r2))) {
        out->empty = "torus with a zero, negative or non-finite radius is empty";
        return SC_OK;
    }
    if (!(r2 < r1))
        return err_set(c->error, SC_ERR_SEMANTIC, &n->loc,
                       "torus minor radius r2 = %g must be smaller than its major radius "
                       "r1 = %g",
                       r2, r1);
    return SC_OK;
}

/* quadric(a = [A, ..., J], bounds) */
sc_status model_read_quadric(const model_reader *c, const parse_node *n,
                             model_quadric *out)
{
    const parse_value *v = model_arg(n, "a", 0);
    if (!v)
        return missing(c, n, "a");
    if (!numbers(v, 10, out->a))
        return model_wrong_type(c, n, "a", v, "a vector of 10 numbers");
    for (int i = 0; i < 10; i++) {
        if (!isfinite(out->a[i])) {
            sc_location loc = model_loc(c, &v->u.vector.items[i]);
            return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                           "quadric coefficient %d is not finite", i);
        }
    }
    return bounds_arg(c, n, 1, "quadric with an empty box is empty", &out->box,
                      &out->empty);
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
static sc_status params_arg(const model_reader *c, const parse_node *n,
                            expr_param *params, uint32_t *count)
{
    *count = 0;
    const parse_value *v = model_arg(n, "params", -1);
    if (!v)
        return SC_OK;
    if (v->kind != PARSE_VECTOR)
        return model_wrong_type(c, n, "params", v, params_expected);
    for (uint32_t i = 0; i < v->u.vector.count; i++) {
        const parse_value *pair = &v->u.vector.items[i];
        if (pair->kind != PARSE_VECTOR || pair->u.vector.count != 2 ||
            pair->u.vector.items[0].kind != PARSE_STRING ||
            pair->u.vector.items[1].kind != PARSE_NUMBER)
            return model_wrong_type(c, n, "params", pair, params_expected);
        const parse_value *name = &pair->u.vector.items[0];
        sc_location loc = model_loc(c, name);
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

/* Refuses a field whose sin, cos or tan argument can pass 2^53 within its
 * box (an interval bound): past it neighbouring doubles lie farther apart
 * than a third of the period, so the values are noise at every scale and
 * no ray could resolve the surface. Refused here, with the leaf's
 * position, so that a load fails on it rather than a render after it. */
static sc_status check_resolvable(const model_reader *c, const parse_node *n,
                                  const expr_program *program, const bbox *box)
{
    expr_op op;
    double reach = expr_trig_reach(program, ix_make(box->lo.x, box->hi.x),
                                   ix_make(box->lo.y, box->hi.y),
                                   ix_make(box->lo.z, box->hi.z), &op);
    if (reach > EXPR_TRIG_MAX_ARGUMENT)
        return err_set(c->error, SC_ERR_LIMIT, &n->loc,
                       "implicit surface is not resolvable: the argument of %s reaches "
                       "%.3g within its bounds (beyond 2^53, where doubles are farther "
                       "apart than its period)",
                       expr_op_name(op), reach);
    return SC_OK;
}

/* implicit(f, bounds, method = "interval", tolerance, params, lipschitz) */
sc_status model_read_implicit(const model_reader *c, const parse_node *n,
                              model_implicit *out)
{
    const parse_value *f = model_arg(n, "f", 0);
    if (!f)
        return missing(c, n, "f");
    if (f->kind != PARSE_STRING)
        return model_wrong_type(c, n, "f", f, "a string");
    bbox box;
    sc_status st =
        bounds_arg(c, n, 1, "implicit with an empty box is empty", &box, &out->empty);
    if (st != SC_OK)
        return st;
    solve_method method = SOLVE_INTERVAL;
    const parse_value *m = model_arg(n, "method", -1);
    if (m && m->kind != PARSE_STRING)
        return model_wrong_type(c, n, "method", m, "a string");
    if (m && (method = solve_method_parse(m->u.string.chars)) == SOLVE_METHOD_COUNT) {
        sc_location loc = model_loc(c, m);
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
        sc_location loc = model_loc(c, model_arg(n, "tolerance", -1));
        return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                       "tolerance must be a positive number");
    }
    if ((st = number_arg(c, n, "lipschitz", -1, 0, &lipschitz, &has_lipschitz)) != SC_OK)
        return st;
    if (has_lipschitz && !(lipschitz > 0 && isfinite(lipschitz))) {
        sc_location loc = model_loc(c, model_arg(n, "lipschitz", -1));
        return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                       "lipschitz must be a positive number");
    }
    expr_param params[EXPR_MAX_PARAMS];
    uint32_t param_count;
    if ((st = params_arg(c, n, params, &param_count)) != SC_OK)
        return st;
    expr_error e;
    if (!expr_compile(f->u.string.chars, f->u.string.length, params, param_count,
                      &out->program, &e)) {
        sc_location loc = {c->file, 0, 0};
        lex_string_locate(parse_string_raw(f), f->u.string.raw_length, f->line, f->column,
                          e.offset, &loc.line, &loc.column);
        return err_set(c->error, SC_ERR_SYNTAX, &loc, "%s", e.message);
    }
    if (!out->empty && (st = check_resolvable(c, n, &out->program, &box)) != SC_OK)
        return st;
    out->box = box;
    out->tolerance = tolerance;
    out->lipschitz = has_lipschitz ? lipschitz : 0;
    out->method = (int)method;
    return SC_OK;
}
