/* The .csg lexer: see lex.h.
 *
 * Strings follow OpenSCAD's lexer rule for rule: the escapes \n \t \r \\ \"
 * are the usual characters; \xHH with H in 00..7f is that byte (\x00 is a
 * space); \uHHHH and \UHHHHHH are a code point written as UTF-8 (zero, a
 * surrogate or a value past U+10FFFF is a space); a backslash before
 * anything else is dropped and the next character kept; a raw line break
 * inside a string is dropped. Whitespace is space, tab, CR, LF and the UTF-8
 * no-break space, as in OpenSCAD. Names are OpenSCAD's [a-zA-Z0-9_]+, by
 * its longest match: 1e and 0x10 are names, 1e5 a number.
 *
 * Numbers: most have at most 15 significant digits and a small decimal
 * exponent (OpenSCAD writes 6 digits), and those are converted exactly by
 * Clinger's fast path: the digits as an integer W < 10^15 < 2^53 and the
 * power 10^k, |k| <= 22, are both exact doubles, so W * 10^k or W / 10^-k
 * is one correctly rounded IEEE operation, the same double strtod gives.
 * Every other number goes to strtod, after the '.' is replaced by the
 * current locale's decimal point, so the library reads the same numbers
 * whatever locale the host program has set.
 */
#include "syntax/lex.h"

#include <errno.h>
#include <float.h>
#include <locale.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"

void lex_init(lexer *lx, const char *file, const char *text, size_t length,
              arena *strings)
{
    lx->file = file;
    lx->p = text;
    lx->end = text + length;
    lx->line_start = text;
    lx->line = 1;
    lx->strings = strings;
}

void lex_seek(lexer *lx, const char *p, int line, const char *line_start)
{
    lx->p = p;
    lx->line = line;
    lx->line_start = line_start;
}

const char *lex_kind_name(lex_kind kind)
{
    switch (kind) {
    case LEX_EOF:
        return "end of file";
    case LEX_IDENT:
        return "a name";
    case LEX_NUMBER:
        return "a number";
    case LEX_STRING:
        return "a string";
    case LEX_TRUE:
        return "'true'";
    case LEX_FALSE:
        return "'false'";
    case LEX_UNDEF:
        return "'undef'";
    case LEX_LPAREN:
        return "'('";
    case LEX_RPAREN:
        return "')'";
    case LEX_LBRACKET:
        return "'['";
    case LEX_RBRACKET:
        return "']'";
    case LEX_LBRACE:
        return "'{'";
    case LEX_RBRACE:
        return "'}'";
    case LEX_COMMA:
        return "','";
    case LEX_SEMICOLON:
        return "';'";
    case LEX_EQUALS:
        return "'='";
    case LEX_PERCENT:
        return "'%'";
    case LEX_HASH:
        return "'#'";
    case LEX_BANG:
        return "'!'";
    case LEX_STAR:
        return "'*'";
    }
    return "a token";
}

static int is_digit(int c)
{
    return c >= '0' && c <= '9';
}

static int is_ident_char(int c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || is_digit(c) || c == '_';
}

static int hex_value(int c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

static sc_location here(const lexer *lx, const char *at, int line, const char *line_start)
{
    sc_location loc = {lx->file, line, (int)(at - line_start) + 1};
    return loc;
}

/* Moves past a line break at lx->p (LF; a CR is plain whitespace). */
static void new_line(lexer *lx)
{
    lx->p++;
    lx->line++;
    lx->line_start = lx->p;
}

/* Length of a valid UTF-8 sequence of 2 to 4 bytes at p, or 0. */
static size_t utf8_length(const char *p, const char *end)
{
    const unsigned char *s = (const unsigned char *)p;
    size_t avail = (size_t)(end - p);
    size_t n = s[0] >= 0xc2 && s[0] <= 0xdf   ? 2
               : s[0] >= 0xe0 && s[0] <= 0xef ? 3
               : s[0] >= 0xf0 && s[0] <= 0xf4 ? 4
                                              : 0;
    if (n == 0 || n > avail)
        return 0;
    for (size_t i = 1; i < n; i++) {
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    }
    return n;
}

/* Writes code point c as UTF-8 to out (which has room for 4); returns the
 * byte count. */
static size_t utf8_encode(unsigned long c, char *out)
{
    if (c < 0x80) {
        out[0] = (char)c;
        return 1;
    }
    if (c < 0x800) {
        out[0] = (char)(0xc0 | (c >> 6));
        out[1] = (char)(0x80 | (c & 0x3f));
        return 2;
    }
    if (c < 0x10000) {
        out[0] = (char)(0xe0 | (c >> 12));
        out[1] = (char)(0x80 | ((c >> 6) & 0x3f));
        out[2] = (char)(0x80 | (c & 0x3f));
        return 3;
    }
    out[0] = (char)(0xf0 | (c >> 18));
    out[1] = (char)(0x80 | ((c >> 12) & 0x3f));
    out[2] = (char)(0x80 | ((c >> 6) & 0x3f));
    out[3] = (char)(0x80 | (c & 0x3f));
    return 4;
}

/* Whether byte c starts neither whitespace nor a comment, so that
 * skip_space has nothing to skip before it. */
static int is_plain(unsigned char c)
{
    return c > ' ' && c != '/' && c != 0xc2;
}

/* Skips whitespace and comments. Returns SC_OK or the error of an
 * unterminated block comment. */
static sc_status skip_space(lexer *lx, sc_error *error)
{
    for (;;) {
        if (lx->p >= lx->end)
            return SC_OK;
        unsigned char c = (unsigned char)*lx->p;
        if (c == '\n') {
            new_line(lx);
        } else if (c == ' ' || c == '\t' || c == '\r') {
            lx->p++;
        } else if (c == 0xc2 && lx->end - lx->p >= 2 && (unsigned char)lx->p[1] == 0xa0) {
            lx->p += 2; /* UTF-8 no-break space */
        } else if (c == '/' && lx->end - lx->p >= 2 && lx->p[1] == '/') {
            while (lx->p < lx->end && *lx->p != '\n')
                lx->p++;
        } else if (c == '/' && lx->end - lx->p >= 2 && lx->p[1] == '*') {
            sc_location loc = here(lx, lx->p, lx->line, lx->line_start);
            lx->p += 2;
            for (;;) {
                if (lx->p >= lx->end)
                    return err_set(error, SC_ERR_SYNTAX, &loc, "unterminated comment");
                if (*lx->p == '*' && lx->end - lx->p >= 2 && lx->p[1] == '/') {
                    lx->p += 2;
                    break;
                }
                if (*lx->p == '\n')
                    new_line(lx);
                else
                    lx->p++;
            }
        } else {
            return SC_OK;
        }
    }
}

/* "inf" or "nan" as a whole word at p. Returns the value's magnitude kind:
 * 1 inf, 2 nan, 0 neither. */
static int special_word(const char *p, const char *end)
{
    if (p >= end || (*p != 'i' && *p != 'n') || end - p < 3)
        return 0;
    if (end - p > 3 && is_ident_char((unsigned char)p[3]))
        return 0;
    if (memcmp(p, "inf", 3) == 0)
        return 1;
    if (memcmp(p, "nan", 3) == 0)
        return 2;
    return 0;
}

/* W * 10^k by Clinger's fast path (see the top of the file): 1 and *v when
 * it applies (W < 10^15, |k| <= 22), else 0. Needs double arithmetic
 * without extra precision (FLT_EVAL_METHOD 0), which every SSE2 or ARM64
 * target has. */
static int fast_number(uint64_t w, int k, int negative, double *v)
{
#if FLT_EVAL_METHOD == 0
    static const double powers[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    double value;
    if (w == 0)
        value = 0;
    else if (k >= 0 && k <= 22)
        value = (double)w * powers[k];
    else if (k < 0 && k >= -22)
        value = (double)w / powers[-k];
    else
        return 0;
    *v = negative ? -value : value;
    return 1;
#else
    (void)w;
    (void)k;
    (void)negative;
    (void)v;
    return 0;
#endif
}

/* What scan_number found. */
typedef enum number_scan {
    NUMBER_OK,        /* *value and *after set */
    NUMBER_MALFORMED, /* *after: the first byte that cannot follow */
    NUMBER_RANGE,     /* finite text, infinite value */
    NUMBER_NOMEM
} number_scan;

static sc_status unexpected(lexer *lx, sc_error *error)
{
    sc_location loc = here(lx, lx->p, lx->line, lx->line_start);
    unsigned char c = (unsigned char)*lx->p;
    if (c > 0x20 && c < 0x7f)
        return err_set(error, SC_ERR_SYNTAX, &loc, "unexpected character '%c'", c);
    size_t n = utf8_length(lx->p, lx->end);
    if (n)
        return err_set(error, SC_ERR_SYNTAX, &loc, "unexpected character '%.*s'", (int)n,
                       lx->p);
    return err_set(error, SC_ERR_SYNTAX, &loc, "unexpected byte 0x%02x", c);
}

/* number := [+-]? ( D+ ('.' D*)? | '.' D+ ) ([eE] [+-]? D+)?
 * (without inf and nan, which lex_number reads). Any letter, digit, '_'
 * or '.' directly after a number makes it malformed. One pass reads the
 * number and gathers, as it goes, what the fast path needs: the digits as
 * an integer W (leading zeros do not count towards its 15 significant
 * digits), the digits after the point, and an exponent of at most 4
 * digits. The caller has seen a digit, or '.' or a sign before one. */
static number_scan scan_number(const char *s, const char *end, double *value,
                               const char **after)
{
    const char *p = s;
    int negative = 0;
    if (*p == '+' || *p == '-') {
        negative = *p == '-';
        p++;
    }
    /* Leading zeros first, then every digit counts; W keeps the first 19
     * (no overflow), of which the fast path uses at most 15. */
    uint64_t w = 0;
    int significant = 0, fraction = 0;
    while (p < end && *p == '0')
        p++;
    for (; p < end && is_digit((unsigned char)*p); p++, significant++) {
        if (significant < 19)
            w = 10 * w + (uint64_t)(*p - '0');
    }
    if (p < end && *p == '.') {
        p++;
        if (significant == 0) {
            for (; p < end && *p == '0'; p++)
                fraction++;
        }
        for (; p < end && is_digit((unsigned char)*p); p++, significant++, fraction++) {
            if (significant < 19)
                w = 10 * w + (uint64_t)(*p - '0');
        }
    }
    int exponent = 0, exp_digits = 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        const char *q = p + 1;
        int exp_negative = 0;
        if (q < end && (*q == '+' || *q == '-'))
            exp_negative = *q++ == '-';
        if (q < end && is_digit((unsigned char)*q)) {
            for (; q < end && is_digit((unsigned char)*q); q++, exp_digits++) {
                if (exp_digits < 4)
                    exponent = 10 * exponent + (*q - '0');
            }
            if (exp_negative)
                exponent = -exponent;
            p = q;
        }
    }
    *after = p;
    if (p < end && (is_ident_char((unsigned char)*p) || *p == '.'))
        return NUMBER_MALFORMED;
    if (significant <= 15 && exp_digits <= 4 &&
        fast_number(w, exponent - fraction, negative, value))
        return NUMBER_OK;
    size_t n = (size_t)(p - s);
    char small[128];
    char *buf = n < sizeof small ? small : malloc(n + 1);
    if (!buf)
        return NUMBER_NOMEM;
    memcpy(buf, s, n);
    buf[n] = '\0';
    const char *point = localeconv()->decimal_point;
    if (point && point[0] && point[0] != '.' && !point[1]) {
        char *dot = strchr(buf, '.');
        if (dot)
            *dot = point[0];
    }
    errno = 0;
    double v = strtod(buf, NULL);
    int overflow = errno == ERANGE && isinf(v);
    if (buf != small)
        free(buf);
    if (overflow)
        return NUMBER_RANGE;
    *value = v;
    return NUMBER_OK;
}

/* The form almost every number of a file OpenSCAD writes takes, read
 * inline before scan_number: [+-]? D+ ('.' D*)? with at most 15 digits in
 * all (leading zeros included) and no exponent. Then W < 10^15 and the
 * point's place k = -(digits after it) >= -15, so fast_number converts it
 * exactly as scan_number would (the same W, the same k; leading zeros
 * change neither). 1 with *value and *after as scan_number's NUMBER_OK;
 * 0 for every other text (scan_number reads it, and reports what is
 * malformed). */
static inline int simple_number(const char *p, const char *end, double *value,
                                const char **after)
{
    int negative = 0;
    if (p < end && (*p == '+' || *p == '-')) {
        negative = *p == '-';
        p++;
    }
    const char *first = p;
    uint64_t w = 0; /* may wrap past 19 digits: then rejected below */
    while (p < end && (unsigned)(*p - '0') < 10u)
        w = 10 * w + (uint64_t)(*p++ - '0');
    size_t digits = (size_t)(p - first);
    if (digits == 0)
        return 0;
    const char *point = p;
    if (p < end && *p == '.') {
        p++;
        while (p < end && (unsigned)(*p - '0') < 10u)
            w = 10 * w + (uint64_t)(*p++ - '0');
    }
    size_t fraction = p > point ? (size_t)(p - point - 1) : 0;
    if (digits + fraction > 15 ||
        (p < end && (is_ident_char((unsigned char)*p) || *p == '.')))
        return 0;
    if (!fast_number(w, -(int)fraction, negative, value))
        return 0;
    *after = p;
    return 1;
}

int lex_number_at(const char *p, const char *end, double *value, const char **after)
{
    if (p >= end)
        return 0;
    if (simple_number(p, end, value, after))
        return 1;
    const char *q = p + (*p == '+' || *p == '-');
    /* The forms lex_next hands to lex_number, but inf and nan. */
    if (!(q < end && (is_digit((unsigned char)*q) ||
                      (*q == '.' && q + 1 < end && is_digit((unsigned char)q[1])))))
        return 0;
    return scan_number(p, end, value, after) == NUMBER_OK;
}

/* number := [+-]? ( the form of scan_number | 'inf' | 'nan' ) */
static sc_status lex_number(lexer *lx, lex_token *tok, sc_error *error)
{
    const char *s = lx->p, *p = lx->p, *end = lx->end;
    int negative = 0;
    if (*p == '+' || *p == '-') {
        negative = *p == '-';
        p++;
    }
    int special = special_word(p, end);
    if (special) {
        p += 3;
        tok->kind = LEX_NUMBER;
        tok->number = special == 1 ? INFINITY : NAN;
        if (negative)
            tok->number = -tok->number;
        tok->length = (size_t)(p - s);
        lx->p = p;
        return SC_OK;
    }
    double v = 0;
    if (simple_number(s, end, &v, &p)) {
        tok->kind = LEX_NUMBER;
        tok->number = v;
        tok->length = (size_t)(p - s);
        lx->p = p;
        return SC_OK;
    }
    switch (scan_number(s, end, &v, &p)) {
    case NUMBER_OK:
        break;
    case NUMBER_MALFORMED: {
        /* OpenSCAD's lexer takes the longest match, and its names are
         * [a-zA-Z0-9_]+: digits that run on into letters past the number
         * (1e, 0x10, 12abc, 1e5x) are a name, read as one here (a name
         * where a value goes); with a sign before them, the sign is an
         * operator on that name. */
        const char *digits = s + (s < end && (*s == '+' || *s == '-'));
        const char *name_end = digits;
        while (name_end < end && is_ident_char((unsigned char)*name_end))
            name_end++;
        if (name_end > p) {
            if (digits > s)
                return unexpected(lx, error);
            tok->kind = LEX_IDENT;
            tok->length = (size_t)(name_end - s);
            lx->p = name_end;
            return SC_OK;
        }
        sc_location loc = here(lx, s, lx->line, lx->line_start);
        while (p < end && (is_ident_char((unsigned char)*p) || *p == '.' ||
                           ((*p == '+' || *p == '-') && (p[-1] == 'e' || p[-1] == 'E'))))
            p++;
        return err_set(error, SC_ERR_SYNTAX, &loc, "malformed number '%.*s'",
                       (int)(p - s), s);
    }
    case NUMBER_RANGE: {
        sc_location loc = here(lx, s, lx->line, lx->line_start);
        return err_set(error, SC_ERR_SYNTAX, &loc, "number out of range '%.*s'",
                       (int)(p - s), s);
    }
    case NUMBER_NOMEM:
        return err_nomem(error, NULL);
    }
    tok->kind = LEX_NUMBER;
    tok->number = v;
    tok->length = (size_t)(p - s);
    lx->p = p;
    return SC_OK;
}

/* Finds the closing quote of the string opening at lx->p; returns it, or
 * NULL at the end of the text. */
static const char *string_end(const char *p, const char *end)
{
    for (p++; p < end; p++) {
        if (*p == '\\') {
            if (p + 1 < end)
                p++;
        } else if (*p == '"') {
            return p;
        }
    }
    return NULL;
}

/* Decodes the escapes of raw[0 .. n) into out (at least n bytes); returns
 * the decoded length. With stop_at set, stops as soon as the decoded
 * length would pass *stop_at and stores there the raw offset reached
 * (lex_string_locate). */
static size_t decode_string(const char *raw, size_t n, char *out, size_t *stop_at)
{
    size_t k = 0;
    const char *p = raw, *end = raw + n;
    while (p < end) {
        char c = *p;
        if (c == '\n' || c == '\r') {
            p++;
            continue;
        }
        if (stop_at && k >= *stop_at)
            break;
        if (c != '\\') {
            out[k++] = c;
            p++;
            continue;
        }
        /* p + 1 < end: string_end never stops right after a lone backslash. */
        char e = p[1];
        if (e == 'n' || e == 't' || e == 'r' || e == '\\' || e == '"') {
            out[k++] = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
            p += 2;
            continue;
        }
        if (e == 'x' && end - p >= 4 && p[2] >= '0' && p[2] <= '7' &&
            hex_value(p[3]) >= 0) {
            int v = hex_value(p[2]) * 16 + hex_value(p[3]);
            out[k++] = v == 0 ? ' ' : (char)v;
            p += 4;
            continue;
        }
        int digits = e == 'u' ? 4 : e == 'U' ? 6 : 0;
        if (digits && end - p >= 2 + digits) {
            unsigned long v = 0;
            int ok = 1;
            for (int i = 0; i < digits; i++) {
                int h = hex_value(p[2 + i]);
                if (h < 0) {
                    ok = 0;
                    break;
                }
                v = v * 16 + (unsigned long)h;
            }
            if (ok) {
                int valid = v != 0 && v <= 0x10ffff && !(v >= 0xd800 && v <= 0xdfff);
                if (valid)
                    k += utf8_encode(v, out + k);
                else
                    out[k++] = ' ';
                p += 2 + digits;
                continue;
            }
        }
        /* Any other backslash is dropped; the next character is kept. */
        p++;
    }
    out[k] = '\0';
    if (stop_at)
        *stop_at = (size_t)(p - raw);
    return k;
}

void lex_string_locate(const char *raw, size_t raw_length, int quote_line,
                       int quote_column, size_t offset, int *line, int *column)
{
    /* Decoding never lengthens (lex_string), so raw_length + 1 bytes hold
     * any prefix; a small buffer serves strings up to its size, longer
     * ones are decoded in the same pass without keeping the bytes. */
    char buf[256];
    char *out = buf;
    char *heap = NULL;
    if (raw_length + 1 > sizeof buf) {
        heap = malloc(raw_length + 1);
        out = heap;
    }
    size_t stop = offset;
    if (out)
        decode_string(raw, raw_length, out, &stop);
    else
        stop = offset < raw_length ? offset : raw_length; /* no memory: approximate */
    free(heap);
    /* Skip raw line breaks that come before the character. */
    while (stop < raw_length && (raw[stop] == '\n' || raw[stop] == '\r'))
        stop++;
    int l = quote_line, c = quote_column + 1;
    for (size_t i = 0; i < stop; i++) {
        if (raw[i] == '\n') {
            l++;
            c = 1;
        } else {
            c++;
        }
    }
    *line = l;
    *column = c;
}

static sc_status lex_string(lexer *lx, lex_token *tok, sc_error *error)
{
    sc_location loc = here(lx, lx->p, lx->line, lx->line_start);
    const char *close = string_end(lx->p, lx->end);
    if (!close)
        return err_set(error, SC_ERR_SYNTAX, &loc, "unterminated string");
    const char *raw = lx->p + 1;
    size_t n = (size_t)(close - raw);
    if (n > LEX_MAX_STRING)
        return err_set(error, SC_ERR_LIMIT, &loc, "string too long (limit is %d bytes)",
                       LEX_MAX_STRING);
    /* Decoding never lengthens: every escape is at least as long as its
     * UTF-8 result (\uHHHH: 6 bytes for at most 3, \UHHHHHH: 8 for 4).
     * The raw text goes first, NUL-terminated, then the decoded one. */
    char *raw_copy = arena_alloc(lx->strings, 2 * (n + 1));
    if (!raw_copy)
        return err_nomem(error, NULL);
    memcpy(raw_copy, raw, n);
    raw_copy[n] = '\0';
    char *out = raw_copy + n + 1;
    tok->kind = LEX_STRING;
    tok->string = out;
    tok->string_length = decode_string(raw, n, out, NULL);
    /* Keep line numbers right across raw line breaks in the string. */
    for (const char *q = raw; q < close; q++) {
        if (*q == '\n') {
            lx->line++;
            lx->line_start = q + 1;
        }
    }
    lx->p = close + 1;
    tok->length = (size_t)(lx->p - tok->start);
    return SC_OK;
}

/* The one-character tokens by their character; LEX_EOF for every other
 * byte. */
static const lex_kind single_tokens[256] = {
    ['('] = LEX_LPAREN, [')'] = LEX_RPAREN,  ['['] = LEX_LBRACKET, [']'] = LEX_RBRACKET,
    ['{'] = LEX_LBRACE, ['}'] = LEX_RBRACE,  [','] = LEX_COMMA,    [';'] = LEX_SEMICOLON,
    ['='] = LEX_EQUALS, ['%'] = LEX_PERCENT, ['#'] = LEX_HASH,     ['!'] = LEX_BANG,
    ['*'] = LEX_STAR,
};

sc_status lex_next(lexer *lx, lex_token *tok, sc_error *error)
{
    /* Most tokens follow one space, or none: skip_space only past that. */
    if (lx->p < lx->end && *lx->p == ' ')
        lx->p++;
    if (lx->p >= lx->end || !is_plain((unsigned char)*lx->p)) {
        sc_status st = skip_space(lx, error);
        if (st != SC_OK)
            return st;
    }
    /* Each kind sets the fields it has; the rest are cleared here rather
     * than the whole token, which is most of a small token's cost. */
    tok->start = lx->p;
    tok->line = lx->line;
    tok->column = (int)(lx->p - lx->line_start) + 1;
    tok->length = 0;
    tok->number = 0;
    tok->string = NULL;
    tok->string_length = 0;
    if (lx->p >= lx->end) {
        tok->kind = LEX_EOF;
        return SC_OK;
    }
    unsigned char c = (unsigned char)*lx->p;
    /* Punctuation first: it is most of a matrix's tokens. */
    lex_kind single = single_tokens[c];
    if (single != LEX_EOF) {
        tok->kind = single;
        tok->length = 1;
        lx->p++;
        return SC_OK;
    }
    const char *next = lx->p + 1;
    int next_c = next < lx->end ? (unsigned char)*next : -1;
    int next2_c = next + 1 < lx->end ? (unsigned char)next[1] : -1;
    if (is_digit(c) || (c == '.' && is_digit(next_c)))
        return lex_number(lx, tok, error);
    if ((c == '-' || c == '+') &&
        (is_digit(next_c) || (next_c == '.' && is_digit(next2_c)) ||
         special_word(next, lx->end)))
        return lex_number(lx, tok, error);
    if (is_ident_char(c) || (c == '$' && is_ident_char(next_c))) {
        const char *p = lx->p + 1;
        while (p < lx->end && is_ident_char((unsigned char)*p))
            p++;
        size_t n = (size_t)(p - lx->p);
        if (special_word(lx->p, lx->end))
            return lex_number(lx, tok, error);
        tok->kind = LEX_IDENT;
        if (n == 4 && memcmp(lx->p, "true", 4) == 0)
            tok->kind = LEX_TRUE;
        else if (n == 5 && memcmp(lx->p, "false", 5) == 0)
            tok->kind = LEX_FALSE;
        else if (n == 5 && memcmp(lx->p, "undef", 5) == 0)
            tok->kind = LEX_UNDEF;
        tok->length = n;
        lx->p = p;
        return SC_OK;
    }
    if (c == '"')
        return lex_string(lx, tok, error);
    return unexpected(lx, error);
}
