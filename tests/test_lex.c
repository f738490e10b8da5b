/* Tests of the .csg lexer (src/syntax/lex.c): every token kind with its
 * value and position, OpenSCAD's string escapes, comments, and every lexer
 * error message, exactly. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "syntax/lex.h"

typedef struct lexed {
    arena mem;
    lex_token tokens[64];
    int count;
    sc_status status;
    sc_error error;
} lexed;

/* Reads every token of text (or up to the first error). */
static void lex_all(lexed *out, const char *text)
{
    memset(out, 0, sizeof *out);
    arena_init(&out->mem, 0);
    lexer lx;
    lex_init(&lx, "t.csg", text, strlen(text), &out->mem);
    for (;;) {
        lex_token tok;
        out->status = lex_next(&lx, &tok, &out->error);
        if (out->status != SC_OK)
            return;
        assert_true(out->count < 64);
        out->tokens[out->count++] = tok;
        if (tok.kind == LEX_EOF)
            return;
    }
}

static void check_error(const char *text, const char *expected)
{
    lexed l;
    lex_all(&l, text);
    char buf[1024];
    assert_int_equal(l.status, SC_ERR_SYNTAX);
    assert_string_equal(sc_error_format(&l.error, buf, sizeof buf), expected);
    arena_free(&l.mem);
}

static void test_punctuation_and_modifiers(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "( ) [ ] { } , ; = % # ! *");
    const lex_kind kinds[] = {LEX_LPAREN, LEX_RPAREN,  LEX_LBRACKET, LEX_RBRACKET,
                              LEX_LBRACE, LEX_RBRACE,  LEX_COMMA,    LEX_SEMICOLON,
                              LEX_EQUALS, LEX_PERCENT, LEX_HASH,     LEX_BANG,
                              LEX_STAR,   LEX_EOF};
    assert_int_equal(l.count, 14);
    assert_int_equal(l.tokens[13].kind, LEX_EOF);
    assert_int_equal(l.tokens[13].column, 26);
    for (int i = 0; i < 13; i++) {
        assert_int_equal(l.tokens[i].kind, kinds[i]);
        assert_int_equal(l.tokens[i].line, 1);
        assert_int_equal(l.tokens[i].column, 1 + 2 * i);
    }
    assert_string_equal(lex_kind_name(LEX_RPAREN), "')'");
    assert_string_equal(lex_kind_name(LEX_NUMBER), "a number");
    assert_string_equal(lex_kind_name(LEX_EOF), "end of file");
    arena_free(&l.mem);
}

static void test_identifiers_and_keywords(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "cube $fn _x1 $1 true false undef trueish infinity");
    const lex_kind kinds[] = {LEX_IDENT, LEX_IDENT, LEX_IDENT, LEX_IDENT, LEX_TRUE,
                              LEX_FALSE, LEX_UNDEF, LEX_IDENT, LEX_IDENT, LEX_EOF};
    assert_int_equal(l.count, 10);
    for (int i = 0; i < 10; i++)
        assert_int_equal(l.tokens[i].kind, kinds[i]);
    assert_int_equal(l.tokens[1].length, 3);
    assert_memory_equal(l.tokens[1].start, "$fn", 3);
    assert_int_equal(l.tokens[1].column, 6);
    assert_memory_equal(l.tokens[7].start, "trueish", 7);
    arena_free(&l.mem);
    /* OpenSCAD's names are [a-zA-Z0-9_]+, the longest match: digits that
     * run on past a number into letters are a name, a number as long as
     * the name is a number. */
    lex_all(&l, "1e 0x10 12abc 1e5x 2d_part 1e5 1.e5");
    const lex_kind digit_kinds[] = {LEX_IDENT, LEX_IDENT,  LEX_IDENT,  LEX_IDENT,
                                    LEX_IDENT, LEX_NUMBER, LEX_NUMBER, LEX_EOF};
    const size_t lengths[] = {2, 4, 5, 4, 7, 3, 4, 0};
    assert_int_equal(l.count, 8);
    for (int i = 0; i < 8; i++) {
        assert_int_equal(l.tokens[i].kind, digit_kinds[i]);
        assert_int_equal(l.tokens[i].length, lengths[i]);
    }
    assert_true(l.tokens[6].number == 1e5);
    arena_free(&l.mem);
}

static void test_numbers(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "0 42 -1.5e-3 1e+10 .5 5. +2 -.25 1E5 2.5e2 -0 1e-07 -1.5e-05 "
                "0.707107 1e-400");
    const double values[] = {0,   42,  -1.5e-3, 1e10, .5,      5.0,      2, -.25,
                             1e5, 250, -0.0,    1e-7, -1.5e-5, 0.707107, 0};
    int n = (int)(sizeof values / sizeof values[0]);
    assert_int_equal(l.count, n + 1);
    for (int i = 0; i < n; i++) {
        assert_int_equal(l.tokens[i].kind, LEX_NUMBER);
        assert_true(l.tokens[i].number == values[i]);
    }
    assert_true(signbit(l.tokens[10].number)); /* -0 keeps its sign */
    assert_int_equal(l.tokens[2].column, 6);
    assert_int_equal(l.tokens[2].length, 7);
    arena_free(&l.mem);
}

/* Every number is the double strtod makes of it, bit for bit, whether the
 * lexer's fast path takes it or not: random decimals of 1 to 19 digits
 * with the point anywhere, signs and exponents from -40 to 40, and
 * OpenSCAD's 6-digit %g forms of random doubles. */
static void test_number_rounding(void **state)
{
    (void)state;
    uint64_t r = 0x9e3779b97f4a7c15ULL;
    arena mem;
    arena_init(&mem, 0);
    char text[96];
    for (int i = 0; i < 200000; i++) {
        r ^= r << 13;
        r ^= r >> 7;
        r ^= r << 17;
        int len = 0;
        if (i % 4 == 3) {
            double x;
            uint64_t bits = r;
            memcpy(&x, &bits, sizeof x);
            if (!isfinite(x))
                continue;
            len = snprintf(text, sizeof text, "%g", x);
        } else {
            uint64_t q = r;
            int digits = 1 + (int)(q % 19);
            q /= 19;
            int point = (int)(q % (uint64_t)(digits + 2)) - 1; /* -1: no point */
            q /= (uint64_t)(digits + 2);
            if (q % 3 == 0)
                text[len++] = '-';
            q /= 3;
            for (int k = 0; k < digits; k++) {
                if (k == point)
                    text[len++] = '.';
                text[len++] = (char)('0' + q % 10);
                q = q / 10 ^ (q << 7);
            }
            if (point == digits)
                text[len++] = '.';
            if (r % 5 < 2)
                len += snprintf(text + len, sizeof text - (size_t)len, "e%d",
                                (int)(r % 81) - 40);
            text[len] = 0;
        }
        if (text[0] == '.' && len == 1)
            continue;
        lexer lx;
        lex_token tok;
        lex_init(&lx, "t.csg", text, (size_t)len, &mem);
        assert_int_equal(lex_next(&lx, &tok, NULL), SC_OK);
        assert_int_equal(tok.kind, LEX_NUMBER);
        assert_int_equal(tok.length, (size_t)len);
        double want = strtod(text, NULL);
        if (memcmp(&want, &tok.number, sizeof want) != 0)
            fail_msg("'%s': lexed %.17g, strtod %.17g", text, tok.number, want);
        /* The parser's fast path over vectors reads numbers alone. */
        double fast = 0;
        const char *after = NULL;
        assert_int_equal(lex_number_at(text, text + len, &fast, &after), 1);
        assert_ptr_equal(after, text + len);
        if (memcmp(&want, &fast, sizeof want) != 0)
            fail_msg("'%s': lex_number_at %.17g, strtod %.17g", text, fast, want);
    }
    arena_free(&mem);
}

/* The edges of the inline path for plain decimals (simple_number in
 * lex.c, at most 15 digits with leading zeros, no exponent): on both
 * sides of 15 digits, past 19 (where its running integer wraps), signed
 * zeros, a '+', a bare point at the end, and what must stop it (a letter,
 * a second point, an exponent) give strtod's double bit for bit, or the
 * token path's error. */
static void test_number_simple_edges(void **state)
{
    (void)state;
    static const char *const texts[] = {"123456789012345",
                                        "1234567890123456",
                                        "000000000000001",
                                        "0000000000000001",
                                        "12345678901234567890123",
                                        "99999999999999.9",
                                        "9999999999999.99",
                                        "0.000000000000001",
                                        "0.0000000000000001",
                                        "-0",
                                        "-0.000",
                                        "+1.5",
                                        "7.",
                                        "-12.0600",
                                        "1e5",
                                        "1.5E-3",
                                        "0.1",
                                        "+0.30000000000000004"};
    arena mem;
    arena_init(&mem, 0);
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        const char *t = texts[i];
        size_t n = strlen(t);
        double want = strtod(t, NULL);
        lexer lx;
        lex_token tok;
        lex_init(&lx, "t.csg", t, n, &mem);
        assert_int_equal(lex_next(&lx, &tok, NULL), SC_OK);
        assert_int_equal(tok.kind, LEX_NUMBER);
        assert_int_equal(tok.length, n);
        if (memcmp(&want, &tok.number, sizeof want) != 0)
            fail_msg("'%s': lexed %.17g, strtod %.17g", t, tok.number, want);
        double fast = 0;
        const char *after = NULL;
        assert_int_equal(lex_number_at(t, t + n, &fast, &after), 1);
        assert_ptr_equal(after, t + n);
        if (memcmp(&want, &fast, sizeof want) != 0)
            fail_msg("'%s': lex_number_at %.17g, strtod %.17g", t, fast, want);
    }
    /* No number: a malformed one, or a name (OpenSCAD's, which may start
     * with digits). */
    static const char *const bad[] = {"12a", "1.2.3", "15_"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double v = 0;
        const char *after = NULL;
        if (lex_number_at(bad[i], bad[i] + strlen(bad[i]), &v, &after))
            fail_msg("'%s' read as %g", bad[i], v);
        lexer lx;
        lex_token tok;
        sc_error e;
        lex_init(&lx, "t.csg", bad[i], strlen(bad[i]), &mem);
        sc_status st = lex_next(&lx, &tok, &e);
        assert_true(st == SC_ERR_SYNTAX || (st == SC_OK && tok.kind == LEX_IDENT));
    }
    arena_free(&mem);
}

/* lex_number_at leaves to lex_next what it reads otherwise. */
static void test_number_at_declines(void **state)
{
    (void)state;
    static const char *const texts[] = {"inf",  "-inf",  "nan", "+nan", "1x",
                                        "2.5.", "1e999", "-",   "+.",   ".",
                                        "",     "x1",    "- 1", "1_"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        double v = 0;
        const char *after = NULL;
        const char *t = texts[i];
        if (lex_number_at(t, t + strlen(t), &v, &after))
            fail_msg("'%s' read as %g", t, v);
    }
    double v = 0;
    const char *after = NULL;
    const char *t = "1e5,2";
    assert_int_equal(lex_number_at(t, t + 5, &v, &after), 1);
    assert_ptr_equal(after, t + 3);
    assert_true(v == strtod("1e5", NULL));
}

static void test_inf_and_nan(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "inf -inf +inf nan -nan [inf]");
    assert_int_equal(l.count, 9);
    assert_true(isinf(l.tokens[0].number) && l.tokens[0].number > 0);
    assert_true(isinf(l.tokens[1].number) && l.tokens[1].number < 0);
    assert_true(isinf(l.tokens[2].number) && l.tokens[2].number > 0);
    assert_true(isnan(l.tokens[3].number));
    assert_true(isnan(l.tokens[4].number));
    for (int i = 0; i < 5; i++)
        assert_int_equal(l.tokens[i].kind, LEX_NUMBER);
    assert_int_equal(l.tokens[6].kind, LEX_NUMBER);
    arena_free(&l.mem);
}

static void check_string(const char *text, const char *expected, size_t length)
{
    lexed l;
    lex_all(&l, text);
    assert_int_equal(l.status, SC_OK);
    assert_int_equal(l.tokens[0].kind, LEX_STRING);
    assert_int_equal(l.tokens[0].string_length, length);
    assert_memory_equal(l.tokens[0].string, expected, length);
    assert_int_equal(l.tokens[0].string[length], '\0');
    assert_int_equal(l.tokens[1].kind, LEX_EOF);
    arena_free(&l.mem);
}

static void test_strings(void **state)
{
    (void)state;
    check_string("\"\"", "", 0);
    check_string("\"plain text\"", "plain text", 10);
    check_string("\"a\\\"b\\\\c\"", "a\"b\\c", 5);
    check_string("\"\\n\\t\\r\"", "\n\t\r", 3);
    check_string("\"\\x41\\x7e\\x00\"", "A~ ", 3);
    check_string("\"\\x80\"", "x80", 3); /* only 00..7f: the backslash is dropped */
    check_string("\"\\u00e9\"", "\xc3\xa9", 2); /* U+00E9 in UTF-8 */
    check_string("\"\\u20AC\"", "\xe2\x82\xac", 3);
    check_string("\"\\U01F600\"", "\xf0\x9f\x98\x80", 4);
    check_string("\"\\u0000\\ud800\\U110000\"", "   ", 3); /* invalid code points */
    check_string("\"\\q\\u12\"", "qu12", 4); /* unknown escapes lose the backslash */
    check_string("\"a\nb\r\nc\"", "abc", 3); /* raw line breaks are dropped */
    check_string("\"caf\xc3\xa9\"", "caf\xc3\xa9", 5);
}

static void test_string_lines(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "\"a\nb\" x");
    assert_int_equal(l.tokens[1].kind, LEX_IDENT);
    assert_int_equal(l.tokens[1].line, 2);
    assert_int_equal(l.tokens[1].column, 4);
    arena_free(&l.mem);
}

static void test_comments_and_positions(void **state)
{
    (void)state;
    lexed l;
    lex_all(&l, "// line comment\n"
                "a /* block\n"
                "comment */ b\r\n"
                "\tc\xc2\xa0"
                "d // end");
    assert_int_equal(l.count, 5);
    assert_int_equal(l.tokens[0].line, 2);
    assert_int_equal(l.tokens[0].column, 1);
    assert_int_equal(l.tokens[1].line, 3);
    assert_int_equal(l.tokens[1].column, 12);
    assert_int_equal(l.tokens[2].line, 4);
    assert_int_equal(l.tokens[2].column, 2);
    assert_int_equal(l.tokens[3].line, 4);
    assert_int_equal(l.tokens[3].column, 5); /* after the 2-byte no-break space */
    assert_int_equal(l.tokens[4].kind, LEX_EOF);
    assert_int_equal(l.tokens[4].line, 4);
    arena_free(&l.mem);
}

static void test_eof_repeats(void **state)
{
    (void)state;
    arena mem;
    arena_init(&mem, 0);
    lexer lx;
    lex_init(&lx, "t.csg", "", 0, &mem);
    lex_token tok;
    for (int i = 0; i < 3; i++) {
        assert_int_equal(lex_next(&lx, &tok, NULL), SC_OK);
        assert_int_equal(tok.kind, LEX_EOF);
        assert_int_equal(tok.line, 1);
        assert_int_equal(tok.column, 1);
    }
    arena_free(&mem);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("cube @", "t.csg:1:6: error: unexpected character '@'");
    check_error("\n  \xc3\xa9", "t.csg:2:3: error: unexpected character '\xc3\xa9'");
    check_error("a\x01", "t.csg:1:2: error: unexpected byte 0x01");
    check_error("\xff", "t.csg:1:1: error: unexpected byte 0xff");
    check_error("x = - 1", "t.csg:1:5: error: unexpected character '-'");
    check_error("$", "t.csg:1:1: error: unexpected character '$'");
    check_error("a(\"abc", "t.csg:1:3: error: unterminated string");
    check_error("\"abc\\\"", "t.csg:1:1: error: unterminated string");
    check_error("a\n  /* never closed\n", "t.csg:2:3: error: unterminated comment");
    check_error("1.2.3", "t.csg:1:1: error: malformed number '1.2.3'");
    check_error("1.5e", "t.csg:1:1: error: malformed number '1.5e'");
    check_error("1.5x", "t.csg:1:1: error: malformed number '1.5x'");
    /* Digits that run on into a name are OpenSCAD's name; a sign before
     * them is an operator. */
    check_error("-1x", "t.csg:1:1: error: unexpected character '-'");
    check_error("x 1e+", "t.csg:1:5: error: unexpected character '+'");
    check_error("[1e999]", "t.csg:1:2: error: number out of range '1e999'");
    check_error("-1e999", "t.csg:1:1: error: number out of range '-1e999'");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_punctuation_and_modifiers),
        cmocka_unit_test(test_identifiers_and_keywords),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_number_rounding),
        cmocka_unit_test(test_number_simple_edges),
        cmocka_unit_test(test_number_at_declines),
        cmocka_unit_test(test_inf_and_nan),
        cmocka_unit_test(test_strings),
        cmocka_unit_test(test_string_lines),
        cmocka_unit_test(test_comments_and_positions),
        cmocka_unit_test(test_eof_repeats),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
