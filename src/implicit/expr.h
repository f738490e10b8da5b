/* Implicit-surface expressions: a parser to bytecode and three evaluators
 * over the same code.
 *
 *   expr    := term { ('+' | '-') term }
 *   term    := unary { ('*' | '/') unary }
 *   unary   := ('-' | '+') unary | power
 *   power   := primary [ '^' unary ]          right-associative: 2^3^2 = 2^9
 *   primary := NUMBER | NAME | NAME '(' expr { ',' expr } ')' | '(' expr ')'
 *
 * Names are x, y, z, pi and the parameters passed to expr_compile. The
 * functions are sqrt, abs, sin, cos, tan, exp, log, floor (one argument),
 * min and max (two or more), pow, atan2, mod (two: mod(a, b) = a - b
 * floor(a / b)), clamp(v, lo, hi) and smin(a, b, k), the polynomial smooth
 * minimum: with h = clamp(1/2 + (b - a) / (2k), 0, 1),
 * smin = b + (a - b) h - k h (1 - h), which equals min(a, b) where
 * |a - b| >= k and blends the two within k of each other.
 *
 * Code: one instruction per value, in the order they are computed; the
 * value of instruction i lives in register i, and the last instruction is
 * the result (static single assignment, so evaluation is one pass without
 * a stack). Operations on constants are folded at compile time. mod,
 * clamp, smin and pow with a non-integer exponent compile to sequences of
 * the basic operations below; a ^ n and pow(a, n) with a constant integer
 * |n| <= 64 use POWI, which has a tight interval rule.
 *
 * Evaluators (all reentrant, registers on the C stack, no allocation):
 *   expr_eval       double value at a point;
 *   expr_eval_dual  value and directional derivative along a seed vector
 *                   (forward mode): the seed d gives df/dt along o + t d,
 *                   the seeds e_x, e_y, e_z give the gradient;
 *   expr_eval_ix    an interval enclosure of the value over a box of
 *                   points, and optionally of the derivative along a seed
 *                   (the points x = X(t) with X' = seed): a guaranteed
 *                   enclosure with outward rounding (interval.h). Where
 *                   f is NaN on part of the box (sqrt or log of a
 *                   negative, whose NaN min and max do not drop) it says
 *                   so instead.
 */
#ifndef SPANCAST_IMPLICIT_EXPR_H
#define SPANCAST_IMPLICIT_EXPR_H

#include <stddef.h>
#include <stdint.h>

#include "implicit/interval.h"
#include "math/vec.h"

#define EXPR_MAX_CODE 256  /* instructions in one program */
#define EXPR_MAX_DEPTH 64  /* nesting of parentheses, calls and unary signs */
#define EXPR_MAX_PARAMS 64 /* named constants */
#define EXPR_MAX_NAME 32   /* bytes in a parameter name, with the NUL */

typedef enum expr_op {
    EXPR_X,     /* r = x */
    EXPR_Y,     /* r = y */
    EXPR_Z,     /* r = z */
    EXPR_CONST, /* r = constant[i] (i is the instruction's own index) */
    EXPR_ADD,   /* r = r[a] + r[b] */
    EXPR_SUB,   /* r = r[a] - r[b] */
    EXPR_MUL,   /* r = r[a] * r[b] */
    EXPR_DIV,   /* r = r[a] / r[b] */
    EXPR_NEG,   /* r = -r[a] */
    EXPR_POWI,  /* r = r[a] ^ n, n an integer (the field n) */
    EXPR_SQRT,  /* r = sqrt(r[a]) */
    EXPR_ABS,   /* r = |r[a]| */
    EXPR_MIN,   /* r = min(r[a], r[b]) */
    EXPR_MAX,   /* r = max(r[a], r[b]) */
    EXPR_SIN,   /* r = sin(r[a]) */
    EXPR_COS,   /* r = cos(r[a]) */
    EXPR_TAN,   /* r = tan(r[a]) */
    EXPR_EXP,   /* r = exp(r[a]) */
    EXPR_LOG,   /* r = log(r[a]) */
    EXPR_ATAN2, /* r = atan2(r[a], r[b]): a is y, b is x */
    EXPR_FLOOR, /* r = floor(r[a]) */
    EXPR_OP_COUNT
} expr_op;

typedef struct expr_insn {
    uint8_t op;    /* expr_op */
    uint16_t a, b; /* operand registers */
    int32_t n;     /* POWI exponent */
} expr_insn;

typedef struct expr_program {
    uint32_t count; /* instructions; the result is register count - 1 */
    expr_insn code[EXPR_MAX_CODE];
    double constant[EXPR_MAX_CODE]; /* EXPR_CONST values, by instruction */
} expr_program;

typedef struct expr_param {
    char name[EXPR_MAX_NAME];
    double value;
} expr_param;

typedef struct expr_error {
    size_t offset; /* byte offset in the source of the offending character */
    char message[160];
} expr_error;

/* Compiles source[0 .. length) into *out (caller-owned). Returns 1 on
 * success, 0 with *error filled on a syntax error or a limit. */
int expr_compile(const char *source, size_t length, const expr_param *params,
                 uint32_t param_count, expr_program *out, expr_error *error);

double expr_eval(const expr_program *p, vec3 q);

/* Value and derivative along seed at q. */
double expr_eval_dual(const expr_program *p, vec3 q, vec3 seed, double *derivative);

/* Encloses f over the box X x Y x Z; when derivative is not NULL, also
 * encloses the derivative along seed (constant over the box). When
 * undefined is not NULL it is set to 0 when f is a number at every point
 * of the box, 1 when it may be NaN at some point, 2 when it is NaN at
 * every point; in the last two cases the enclosures are NaN (unknown). */
ix expr_eval_ix(const expr_program *p, ix x, ix y, ix z, vec3 seed, ix *derivative,
                int *undefined);

/* The largest magnitude the argument of a sin, cos or tan can take over
 * the box X x Y x Z (an interval bound: it may overestimate), 0 without
 * trigonometric functions; *op is the function reaching it
 * (EXPR_OP_COUNT when none). Past 2^53 neighbouring doubles are farther
 * apart than a period over 3, so the function's values are noise: a
 * field that reaches there is not resolvable at any scale. */
#define EXPR_TRIG_MAX_ARGUMENT 9007199254740992.0 /* 2^53 */
double expr_trig_reach(const expr_program *p, ix x, ix y, ix z, expr_op *op);

/* The name of an operation, for dumps and tests. */
const char *expr_op_name(expr_op op);

#endif
