/* Expression compiler and evaluators: see expr.h for the grammar, the code
 * and what each evaluator computes.
 *
 * The parser is recursive descent over the decoded string; the depth of
 * its recursion is bounded by EXPR_MAX_DEPTH (every level that nests,
 * parentheses, calls and unary signs, counts). Each parse function returns
 * the register that holds its value, or -1 after filling the error. */
#include "implicit/expr.h"

#include <ctype.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

typedef struct parser {
    const char *s;
    size_t n, pos;
    int depth;
    const expr_param *params;
    uint32_t param_count;
    expr_program *out;
    expr_error *error;
} parser;

static int fail(parser *p, size_t at, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(p->error->message, sizeof p->error->message, format, args);
    va_end(args);
    p->error->offset = at;
    return -1;
}

static void skip_space(parser *p)
{
    while (p->pos < p->n && (p->s[p->pos] == ' ' || p->s[p->pos] == '\t' ||
                             p->s[p->pos] == '\n' || p->s[p->pos] == '\r'))
        p->pos++;
}

/* The next non-blank character, 0 at the end. */
static char peek(parser *p)
{
    skip_space(p);
    return p->pos < p->n ? p->s[p->pos] : 0;
}

/* The scalar rule of each operation, shared by the double evaluator and
 * constant folding. */
static double apply(int op, double a, double b, int32_t n)
{
    switch (op) {
    case EXPR_ADD:
        return a + b;
    case EXPR_SUB:
        return a - b;
    case EXPR_MUL:
        return a * b;
    case EXPR_DIV:
        return a / b;
    case EXPR_NEG:
        return -a;
    case EXPR_POWI:
        return pow(a, n);
    case EXPR_SQRT:
        return sqrt(a);
    case EXPR_ABS:
        return fabs(a);
    case EXPR_MIN:
        return fmin(a, b);
    case EXPR_MAX:
        return fmax(a, b);
    case EXPR_SIN:
        return sin(a);
    case EXPR_COS:
        return cos(a);
    case EXPR_TAN:
        return tan(a);
    case EXPR_EXP:
        return exp(a);
    case EXPR_LOG:
        return log(a);
    case EXPR_ATAN2:
        return atan2(a, b);
    case EXPR_FLOOR:
        return floor(a);
    default:
        return NAN;
    }
}

static int is_const(const parser *p, int r)
{
    return p->out->code[r].op == EXPR_CONST;
}

static int emit_const(parser *p, double v)
{
    expr_program *o = p->out;
    if (o->count >= EXPR_MAX_CODE)
        return fail(p, p->pos, "expression is too long (limit is %d operations)",
                    EXPR_MAX_CODE);
    expr_insn in = {EXPR_CONST, 0, 0, 0};
    o->code[o->count] = in;
    o->constant[o->count] = v;
    return (int)o->count++;
}

/* Appends op over registers a and b (b unused by one-operand ops); folds it
 * when its operands are constants. */
static int emit(parser *p, int op, int a, int b, int32_t n)
{
    if (a < 0 || b < 0)
        return -1;
    int unary = op == EXPR_NEG || op == EXPR_POWI || op == EXPR_SQRT || op == EXPR_ABS ||
                (op >= EXPR_SIN && op <= EXPR_LOG) || op == EXPR_FLOOR;
    if (is_const(p, a) && (unary || is_const(p, b)))
        return emit_const(
            p, apply(op, p->out->constant[a], unary ? 0 : p->out->constant[b], n));
    expr_program *o = p->out;
    if (o->count >= EXPR_MAX_CODE)
        return fail(p, p->pos, "expression is too long (limit is %d operations)",
                    EXPR_MAX_CODE);
    expr_insn in = {(uint8_t)op, (uint16_t)a, (uint16_t)(unary ? a : b), n};
    o->code[o->count] = in;
    o->constant[o->count] = 0;
    return (int)o->count++;
}

static int parse_expr(parser *p);
static int parse_unary(parser *p);

static int enter(parser *p)
{
    if (++p->depth > EXPR_MAX_DEPTH)
        return fail(p, p->pos, "expression is nested too deeply (limit is %d levels)",
                    EXPR_MAX_DEPTH);
    return 0;
}

/* a ^ b: POWI for a constant integer exponent, exp(b log a) otherwise. */
static int emit_pow(parser *p, int a, int b)
{
    if (a < 0 || b < 0)
        return -1;
    if (is_const(p, b)) {
        double e = p->out->constant[b];
        if (e == floor(e) && fabs(e) <= 64)
            return emit(p, EXPR_POWI, a, a, (int32_t)e);
    }
    return emit(p, EXPR_EXP, emit(p, EXPR_MUL, b, emit(p, EXPR_LOG, a, 0, 0), 0), 0, 0);
}

static int emit_clamp(parser *p, int v, int lo, int hi)
{
    return emit(p, EXPR_MIN, emit(p, EXPR_MAX, v, lo, 0), hi, 0);
}

/* smin(a, b, k) as in expr.h. */
static int emit_smin(parser *p, int a, int b, int k)
{
    int half = emit_const(p, 0.5), zero = emit_const(p, 0), one = emit_const(p, 1);
    int diff = emit(p, EXPR_SUB, b, a, 0);
    int h = emit(p, EXPR_ADD, half,
                 emit(p, EXPR_DIV, emit(p, EXPR_MUL, half, diff, 0), k, 0), 0);
    h = emit_clamp(p, h, zero, one);
    int blend =
        emit(p, EXPR_ADD, b, emit(p, EXPR_MUL, emit(p, EXPR_SUB, a, b, 0), h, 0), 0);
    int bump =
        emit(p, EXPR_MUL, emit(p, EXPR_MUL, k, h, 0), emit(p, EXPR_SUB, one, h, 0), 0);
    return emit(p, EXPR_SUB, blend, bump, 0);
}

static const struct {
    const char *name;
    int min_args, max_args; /* max 0: no upper limit */
    int op;                 /* for the one- and two-argument operations */
} functions[] = {
    {"sqrt", 1, 1, EXPR_SQRT}, {"abs", 1, 1, EXPR_ABS},     {"sin", 1, 1, EXPR_SIN},
    {"cos", 1, 1, EXPR_COS},   {"tan", 1, 1, EXPR_TAN},     {"exp", 1, 1, EXPR_EXP},
    {"log", 1, 1, EXPR_LOG},   {"floor", 1, 1, EXPR_FLOOR}, {"min", 2, 0, EXPR_MIN},
    {"max", 2, 0, EXPR_MAX},   {"pow", 2, 2, -1},           {"atan2", 2, 2, EXPR_ATAN2},
    {"mod", 2, 2, -1},         {"clamp", 3, 3, -1},         {"smin", 3, 3, -1},
};

static int parse_call(parser *p, const char *name, size_t name_len, size_t name_at)
{
    int f = -1;
    for (size_t i = 0; i < sizeof functions / sizeof functions[0]; i++) {
        if (strlen(functions[i].name) == name_len &&
            memcmp(functions[i].name, name, name_len) == 0)
            f = (int)i;
    }
    if (f < 0)
        return fail(p, name_at, "unknown function '%.*s'", (int)name_len, name);
    if (enter(p) < 0)
        return -1;
    p->pos++; /* '(' */
    int args[EXPR_MAX_CODE];
    int count = 0;
    if (peek(p) != ')') {
        for (;;) {
            if (count == EXPR_MAX_CODE)
                return fail(p, p->pos, "expression is too long (limit is %d operations)",
                            EXPR_MAX_CODE);
            int r = parse_expr(p);
            if (r < 0)
                return -1;
            args[count++] = r;
            if (peek(p) != ',')
                break;
            p->pos++;
        }
    }
    if (peek(p) != ')')
        return p->pos < p->n ? fail(p, p->pos, "expected ',' or ')' in call of '%s'",
                                    functions[f].name)
                             : fail(p, p->pos,
                                    "unexpected end of expression (expected "
                                    "')' to close the call of '%s')",
                                    functions[f].name);
    p->pos++;
    p->depth--;
    int lo = functions[f].min_args, hi = functions[f].max_args;
    if (count < lo || (hi && count > hi)) {
        if (lo == hi)
            return fail(p, name_at, "'%s' takes %d argument%s, not %d", functions[f].name,
                        lo, lo == 1 ? "" : "s", count);
        return fail(p, name_at, "'%s' takes at least %d arguments, not %d",
                    functions[f].name, lo, count);
    }
    const char *fn = functions[f].name;
    if (strcmp(fn, "min") == 0 || strcmp(fn, "max") == 0) {
        int r = args[0];
        for (int i = 1; i < count; i++)
            r = emit(p, functions[f].op, r, args[i], 0);
        return r;
    }
    if (strcmp(fn, "pow") == 0)
        return emit_pow(p, args[0], args[1]);
    if (strcmp(fn, "mod") == 0) {
        int q = emit(p, EXPR_FLOOR, emit(p, EXPR_DIV, args[0], args[1], 0), 0, 0);
        return emit(p, EXPR_SUB, args[0], emit(p, EXPR_MUL, args[1], q, 0), 0);
    }
    if (strcmp(fn, "clamp") == 0)
        return emit_clamp(p, args[0], args[1], args[2]);
    if (strcmp(fn, "smin") == 0)
        return emit_smin(p, args[0], args[1], args[2]);
    return emit(p, functions[f].op, args[0], count > 1 ? args[1] : args[0], 0);
}

/* NUMBER := digits [ '.' digits ] [ ('e' | 'E') [sign] digits ], or '.' digits. */
static int parse_number(parser *p)
{
    size_t start = p->pos, i = p->pos;
    while (i < p->n && isdigit((unsigned char)p->s[i]))
        i++;
    if (i < p->n && p->s[i] == '.') {
        i++;
        while (i < p->n && isdigit((unsigned char)p->s[i]))
            i++;
    }
    if (i < p->n && (p->s[i] == 'e' || p->s[i] == 'E')) {
        size_t j = i + 1;
        if (j < p->n && (p->s[j] == '+' || p->s[j] == '-'))
            j++;
        if (j < p->n && isdigit((unsigned char)p->s[j])) {
            while (j < p->n && isdigit((unsigned char)p->s[j]))
                j++;
            i = j;
        }
    }
    char buf[64];
    size_t len = i - start;
    if (len >= sizeof buf)
        return fail(p, start, "number is too long");
    memcpy(buf, p->s + start, len);
    buf[len] = '\0';
    /* strtod reads the locale's decimal point. */
    char point = localeconv()->decimal_point[0];
    for (size_t k = 0; k < len; k++) {
        if (buf[k] == '.')
            buf[k] = point;
    }
    char *end;
    double v = strtod(buf, &end);
    if (end != buf + len || len == 0 || (len == 1 && p->s[start] == '.'))
        return fail(p, start, "malformed number");
    p->pos = i;
    return emit_const(p, v);
}

/* primary := NUMBER | NAME | NAME '(' args ')' | '(' expr ')' */
static int parse_primary(parser *p)
{
    char c = peek(p);
    size_t at = p->pos;
    if (c == 0)
        return fail(p, at, "unexpected end of expression");
    if (isdigit((unsigned char)c) || c == '.')
        return parse_number(p);
    if (c == '(') {
        if (enter(p) < 0)
            return -1;
        p->pos++;
        int r = parse_expr(p);
        if (r < 0)
            return -1;
        if (peek(p) != ')')
            return p->pos < p->n
                       ? fail(p, p->pos, "expected ')'")
                       : fail(p, p->pos, "unexpected end of expression (expected ')')");
        p->pos++;
        p->depth--;
        return r;
    }
    if (isalpha((unsigned char)c) || c == '_') {
        size_t i = at;
        while (i < p->n && (isalnum((unsigned char)p->s[i]) || p->s[i] == '_'))
            i++;
        const char *name = p->s + at;
        size_t len = i - at;
        p->pos = i;
        if (peek(p) == '(')
            return parse_call(p, name, len, at);
        if (len == 1 && (*name == 'x' || *name == 'y' || *name == 'z')) {
            int op = *name == 'x' ? EXPR_X : *name == 'y' ? EXPR_Y : EXPR_Z;
            if (p->out->count >= EXPR_MAX_CODE)
                return fail(p, at, "expression is too long (limit is %d operations)",
                            EXPR_MAX_CODE);
            expr_insn in = {(uint8_t)op, 0, 0, 0};
            p->out->code[p->out->count] = in;
            p->out->constant[p->out->count] = 0;
            return (int)p->out->count++;
        }
        for (uint32_t k = p->param_count; k-- > 0;) {
            if (strlen(p->params[k].name) == len &&
                memcmp(p->params[k].name, name, len) == 0)
                return emit_const(p, p->params[k].value);
        }
        if (len == 2 && memcmp(name, "pi", 2) == 0)
            return emit_const(p, PI);
        return fail(p, at, "unknown name '%.*s'", (int)len, name);
    }
    if ((unsigned char)c > 0x20 && (unsigned char)c < 0x7f)
        return fail(p, at, "unexpected character '%c' in expression", c);
    return fail(p, at, "unexpected byte 0x%02x in expression", (unsigned char)c);
}

/* power := primary [ '^' unary ] */
static int parse_power(parser *p)
{
    int base = parse_primary(p);
    if (base < 0)
        return -1;
    if (peek(p) != '^')
        return base;
    p->pos++;
    int e = parse_unary(p);
    return emit_pow(p, base, e);
}

/* unary := ('-' | '+') unary | power */
static int parse_unary(parser *p)
{
    char c = peek(p);
    if (c != '-' && c != '+')
        return parse_power(p);
    if (enter(p) < 0)
        return -1;
    p->pos++;
    int r = parse_unary(p);
    p->depth--;
    return c == '-' ? emit(p, EXPR_NEG, r, r, 0) : r;
}

/* term := unary { ('*' | '/') unary } */
static int parse_term(parser *p)
{
    int r = parse_unary(p);
    for (;;) {
        char c = peek(p);
        if (r < 0 || (c != '*' && c != '/'))
            return r;
        p->pos++;
        int rhs = parse_unary(p);
        r = emit(p, c == '*' ? EXPR_MUL : EXPR_DIV, r, rhs, 0);
    }
}

/* expr := term { ('+' | '-') term } */
static int parse_expr(parser *p)
{
    int r = parse_term(p);
    for (;;) {
        char c = peek(p);
        if (r < 0 || (c != '+' && c != '-'))
            return r;
        p->pos++;
        int rhs = parse_term(p);
        r = emit(p, c == '+' ? EXPR_ADD : EXPR_SUB, r, rhs, 0);
    }
}

/* Drops the instructions the result does not use (constants that folding
 * consumed) and renumbers the rest, keeping their order, so that the
 * result is the last register. */
static void compact(expr_program *o, uint32_t result)
{
    uint8_t live[EXPR_MAX_CODE] = {0};
    uint16_t renumber[EXPR_MAX_CODE];
    live[result] = 1;
    for (uint32_t i = result + 1; i-- > 0;) {
        if (!live[i] || o->code[i].op <= EXPR_CONST)
            continue;
        live[o->code[i].a] = 1;
        live[o->code[i].b] = 1;
    }
    uint32_t n = 0;
    for (uint32_t i = 0; i <= result; i++) {
        if (!live[i])
            continue;
        expr_insn in = o->code[i];
        in.a = renumber[in.a];
        in.b = renumber[in.b];
        if (in.op <= EXPR_CONST)
            in.a = in.b = 0;
        o->code[n] = in;
        o->constant[n] = o->constant[i];
        renumber[i] = (uint16_t)n++;
    }
    o->count = n;
}

int expr_compile(const char *source, size_t length, const expr_param *params,
                 uint32_t param_count, expr_program *out, expr_error *error)
{
    parser p = {source, length, 0, 0, params, param_count, out, error};
    out->count = 0;
    error->offset = 0;
    error->message[0] = '\0';
    if (peek(&p) == 0)
        return fail(&p, p.pos, "empty expression") + 1;
    int r = parse_expr(&p);
    if (r < 0)
        return 0;
    if (peek(&p) != 0) {
        char c = p.s[p.pos];
        if (c == ')')
            return fail(&p, p.pos, "unmatched ')'") + 1;
        if ((unsigned char)c > 0x20 && (unsigned char)c < 0x7f)
            return fail(&p, p.pos, "unexpected character '%c' in expression", c) + 1;
        return fail(&p, p.pos, "unexpected byte 0x%02x in expression", (unsigned char)c) +
               1;
    }
    compact(out, (uint32_t)r);
    return 1;
}

/* ---- evaluators ---- */

double expr_eval(const expr_program *p, vec3 q)
{
    double r[EXPR_MAX_CODE];
    for (uint32_t i = 0; i < p->count; i++) {
        const expr_insn *in = &p->code[i];
        switch (in->op) {
        case EXPR_X:
            r[i] = q.x;
            break;
        case EXPR_Y:
            r[i] = q.y;
            break;
        case EXPR_Z:
            r[i] = q.z;
            break;
        case EXPR_CONST:
            r[i] = p->constant[i];
            break;
        default:
            r[i] = apply(in->op, r[in->a], r[in->b], in->n);
            break;
        }
    }
    return p->count ? r[p->count - 1] : NAN;
}

double expr_eval_dual(const expr_program *p, vec3 q, vec3 seed, double *derivative)
{
    double v[EXPR_MAX_CODE], d[EXPR_MAX_CODE];
    for (uint32_t i = 0; i < p->count; i++) {
        const expr_insn *in = &p->code[i];
        double a = v[in->a], b = v[in->b], da = d[in->a], db = d[in->b];
        switch (in->op) {
        case EXPR_X:
            v[i] = q.x, d[i] = seed.x;
            continue;
        case EXPR_Y:
            v[i] = q.y, d[i] = seed.y;
            continue;
        case EXPR_Z:
            v[i] = q.z, d[i] = seed.z;
            continue;
        case EXPR_CONST:
            v[i] = p->constant[i], d[i] = 0;
            continue;
        default:
            break;
        }
        if (in->op == EXPR_SIN || in->op == EXPR_COS) {
            double s = sin(a), c = cos(a); /* one sincos call */
            v[i] = in->op == EXPR_SIN ? s : c;
            d[i] = (in->op == EXPR_SIN ? c : -s) * da;
            continue;
        }
        double r = apply(in->op, a, b, in->n), dr = 0;
        switch (in->op) {
        case EXPR_ADD:
            dr = da + db;
            break;
        case EXPR_SUB:
            dr = da - db;
            break;
        case EXPR_MUL:
            dr = da * b + a * db;
            break;
        case EXPR_DIV:
            dr = (da - r * db) / b;
            break;
        case EXPR_NEG:
            dr = -da;
            break;
        case EXPR_POWI:
            dr = da == 0 ? 0 : in->n * pow(a, in->n - 1) * da;
            break;
        case EXPR_SQRT:
            dr = da == 0 ? 0 : da / (2 * r);
            break;
        case EXPR_ABS:
            dr = a < 0 ? -da : da;
            break;
        case EXPR_MIN:
            dr = a <= b ? da : db;
            break;
        case EXPR_MAX:
            dr = a >= b ? da : db;
            break;
        case EXPR_TAN:
            dr = (1 + r * r) * da;
            break;
        case EXPR_EXP:
            dr = r * da;
            break;
        case EXPR_LOG:
            dr = da / a;
            break;
        case EXPR_ATAN2:
            dr = (b * da - a * db) / (a * a + b * b);
            break;
        default: /* floor: piecewise constant */
            dr = 0;
            break;
        }
        v[i] = r;
        d[i] = dr;
    }
    if (!p->count) {
        *derivative = NAN;
        return NAN;
    }
    *derivative = d[p->count - 1];
    return v[p->count - 1];
}

/* Enclosure of the derivative of op at the operand enclosures. For the
 * Lipschitz but non-smooth abs, min and max the hull of the one-sided
 * derivatives (Clarke's generalised gradient) keeps the mean value
 * inclusion f(b) - f(a) in (b - a) F' that the solver relies on; floor
 * jumps, so across a step nothing bounds its difference quotient. */
static ix ix_derivative(const expr_insn *in, ix a, ix b, ix r, ix da, ix db)
{
    switch (in->op) {
    case EXPR_ADD:
        return ix_add(da, db);
    case EXPR_SUB:
        return ix_sub(da, db);
    case EXPR_MUL:
        return ix_add(ix_mul(da, b), ix_mul(a, db));
    case EXPR_DIV:
        return ix_div(ix_sub(da, ix_mul(r, db)), b);
    case EXPR_NEG:
        return ix_neg(da);
    case EXPR_POWI:
        return ix_mul(ix_mul(ix_point(in->n), ix_powi(a, in->n - 1)), da);
    case EXPR_SQRT:
        if (da.lo == 0 && da.hi == 0)
            return da;
        return ix_div(da, ix_mul(ix_point(2), r));
    case EXPR_ABS:
        if (a.lo > 0)
            return da;
        if (a.hi < 0)
            return ix_neg(da);
        return ix_hull(da, ix_neg(da));
    case EXPR_MIN:
        if (a.hi < b.lo)
            return da;
        if (b.hi < a.lo)
            return db;
        return ix_hull(da, db);
    case EXPR_MAX:
        if (a.lo > b.hi)
            return da;
        if (b.lo > a.hi)
            return db;
        return ix_hull(da, db);
    case EXPR_SIN:
        return ix_mul(ix_cos(a), da);
    case EXPR_COS:
        return ix_mul(ix_neg(ix_sin(a)), da);
    case EXPR_TAN:
        return ix_mul(ix_add(ix_point(1), ix_sqr(r)), da);
    case EXPR_EXP:
        return ix_mul(r, da);
    case EXPR_LOG:
        return ix_div(da, a);
    case EXPR_ATAN2:
        /* a is y, b is x: (x y' - y x') / (x^2 + y^2) */
        return ix_div(ix_sub(ix_mul(b, da), ix_mul(a, db)), ix_add(ix_sqr(a), ix_sqr(b)));
    default: /* floor */
        if (floor(a.lo) == floor(a.hi) || (da.lo == 0 && da.hi == 0))
            return ix_point(0);
        return ix_entire();
    }
}

static ix ix_apply(const expr_insn *in, ix a, ix b)
{
    switch (in->op) {
    case EXPR_ADD:
        return ix_add(a, b);
    case EXPR_SUB:
        return ix_sub(a, b);
    case EXPR_MUL:
        return in->a == in->b ? ix_sqr(a) : ix_mul(a, b);
    case EXPR_DIV:
        return ix_div(a, b);
    case EXPR_NEG:
        return ix_neg(a);
    case EXPR_POWI:
        return ix_powi(a, in->n);
    case EXPR_SQRT:
        return ix_sqrt(a);
    case EXPR_ABS:
        return ix_abs(a);
    case EXPR_MIN:
        return ix_min(a, b);
    case EXPR_MAX:
        return ix_max(a, b);
    case EXPR_SIN:
        return ix_sin(a);
    case EXPR_COS:
        return ix_cos(a);
    case EXPR_TAN:
        return ix_tan(a);
    case EXPR_EXP:
        return ix_exp(a);
    case EXPR_LOG:
        return ix_log(a);
    case EXPR_ATAN2:
        return ix_atan2(a, b);
    default:
        return ix_floor(a);
    }
}

/* Where f is NaN. The double evaluator gives NaN for sqrt of a negative
 * and log of a negative number, and NaN spreads through every operation
 * but min and max (fmin and fmax return the other operand); the solvers
 * read NaN as outside. Each register carries, beside the enclosure of its
 * values where they are numbers, whether it may be NaN at some point of
 * the box (some) and whether it is NaN at every point (all). */
typedef struct nan_state {
    uint8_t some, all;
} nan_state;

ix expr_eval_ix(const expr_program *p, ix x, ix y, ix z, vec3 seed, ix *derivative,
                int *undefined)
{
    ix v[EXPR_MAX_CODE], d[EXPR_MAX_CODE];
    nan_state nan[EXPR_MAX_CODE];
    int want = derivative != NULL;
    for (uint32_t i = 0; i < p->count; i++) {
        const expr_insn *in = &p->code[i];
        nan[i].some = nan[i].all = 0;
        switch (in->op) {
        case EXPR_X:
            v[i] = x, d[i] = ix_point(seed.x);
            continue;
        case EXPR_Y:
            v[i] = y, d[i] = ix_point(seed.y);
            continue;
        case EXPR_Z:
            v[i] = z, d[i] = ix_point(seed.z);
            continue;
        case EXPR_CONST:
            v[i] = ix_point(p->constant[i]), d[i] = ix_point(0);
            continue;
        default:
            break;
        }
        ix a = v[in->a], b = v[in->b];
        nan_state na = nan[in->a], nb = nan[in->b];
        /* An operand with a NaN bound is undefined over the whole box (an
         * operation on infinities, or a NaN constant): nothing bounds it. */
        if (isnan(a.lo) || isnan(a.hi))
            na.some = na.all = 1;
        if (isnan(b.lo) || isnan(b.hi))
            nb.some = nb.all = 1;
        if (in->op == EXPR_MIN || in->op == EXPR_MAX) {
            /* NaN only where both are; where one is, the other is taken */
            nan[i].some = na.some && nb.some;
            nan[i].all = na.all && nb.all;
            if (na.all || nb.all) {
                v[i] = na.all ? b : a;
                d[i] = na.all ? d[in->b] : d[in->a];
                continue;
            }
            v[i] = ix_apply(in, a, b);
            if (want)
                d[i] = ix_derivative(in, a, b, v[i], d[in->a], d[in->b]);
            if (na.some) {
                v[i] = ix_hull(v[i], b);
                d[i] = ix_hull(d[i], d[in->b]);
            }
            if (nb.some) {
                v[i] = ix_hull(v[i], a);
                d[i] = ix_hull(d[i], d[in->a]);
            }
            continue;
        }
        int unary = in->a == in->b;
        nan[i].some = na.some || (!unary && nb.some);
        nan[i].all = na.all || (!unary && nb.all);
        if ((in->op == EXPR_SQRT || in->op == EXPR_LOG) && !(a.lo >= 0)) {
            nan[i].some = 1;
            nan[i].all |= a.hi < 0;
        }
        if ((in->op == EXPR_SIN || in->op == EXPR_COS || in->op == EXPR_TAN) &&
            !(isfinite(a.lo) && isfinite(a.hi))) {
            /* sin, cos and tan of an infinite argument are NaN, which their
             * interval forms (bounded by 1, or by the poles) would hide: a
             * field with an infinite coefficient then looked defined and
             * undecided everywhere, and every ray bisected it down to the
             * tolerance until the evaluation budget ran out. */
            nan[i].some = 1;
            nan[i].all |= a.lo == a.hi;
        }
        if (in->op == EXPR_POWI && in->n == 0) /* pow(NaN, 0) = 1 */
            nan[i].some = nan[i].all = 0;
        if (want && (in->op == EXPR_SIN || in->op == EXPR_COS)) {
            /* the derivative needs the other function over a */
            ix sa, ca;
            ix_sincos(a, &sa, &ca);
            v[i] = in->op == EXPR_SIN ? sa : ca;
            d[i] = ix_mul(in->op == EXPR_SIN ? ca : ix_neg(sa), d[in->a]);
            continue;
        }
        v[i] = ix_apply(in, a, b);
        if (want)
            d[i] = ix_derivative(in, a, b, v[i], d[in->a], d[in->b]);
    }
    int state = 0;
    if (!p->count)
        state = 1;
    else if (nan[p->count - 1].all || isnan(v[p->count - 1].lo) ||
             isnan(v[p->count - 1].hi))
        state = 2;
    else if (nan[p->count - 1].some)
        state = 1;
    if (undefined)
        *undefined = state;
    /* Where f may be NaN nothing bounds its sign: say so (NaN ends). */
    if (state) {
        if (want)
            *derivative = ix_make(NAN, NAN);
        return ix_make(NAN, NAN);
    }
    if (want)
        *derivative = d[p->count - 1];
    return v[p->count - 1];
}

double expr_trig_reach(const expr_program *p, ix x, ix y, ix z, expr_op *op)
{
    ix v[EXPR_MAX_CODE];
    double reach = 0;
    *op = EXPR_OP_COUNT;
    for (uint32_t i = 0; i < p->count; i++) {
        const expr_insn *in = &p->code[i];
        switch (in->op) {
        case EXPR_X:
            v[i] = x;
            continue;
        case EXPR_Y:
            v[i] = y;
            continue;
        case EXPR_Z:
            v[i] = z;
            continue;
        case EXPR_CONST:
            v[i] = ix_point(p->constant[i]);
            continue;
        default:
            break;
        }
        ix a = v[in->a];
        if (in->op == EXPR_SIN || in->op == EXPR_COS || in->op == EXPR_TAN) {
            /* NaN bounds compare false: an undefined argument is not a reach */
            double m = fmax(fabs(a.lo), fabs(a.hi));
            if (m > reach) {
                reach = m;
                *op = (expr_op)in->op;
            }
        }
        v[i] = ix_apply(in, a, v[in->b]);
    }
    return reach;
}

const char *expr_op_name(expr_op op)
{
    static const char *const names[EXPR_OP_COUNT] = {
        "x",   "y",   "z",   "const", "add", "sub", "mul", "div", "neg",   "powi", "sqrt",
        "abs", "min", "max", "sin",   "cos", "tan", "exp", "log", "atan2", "floor"};
    return op < EXPR_OP_COUNT ? names[op] : "?";
}
