/* The lexer of the .csg grammar: text in, tokens with positions out.
 *
 * The token set is what OpenSCAD's own lexer gives a file written by
 * `openscad -o model.csg`: identifiers (with an optional leading '$', as in
 * `$fn`), numbers, strings, the keywords true/false/undef, punctuation and
 * the four modifier characters. Two departures, both for files OpenSCAD
 * writes: a sign directly in front of a number belongs to the number (the
 * grammar has no arithmetic, and OpenSCAD writes `-1.5e-05`), and `inf` and
 * `nan` (also signed) are numbers, since OpenSCAD writes non-finite values
 * that way. Positions are 1-based lines and byte columns. The lexer only
 * reads the text; decoded string contents are copied into an arena the
 * caller owns.
 */
#ifndef SPANCAST_SYNTAX_LEX_H
#define SPANCAST_SYNTAX_LEX_H

#include <stddef.h>

#include "base/arena.h"
#include "spancast/spancast.h"

#define LEX_MAX_STRING 1000000 /* bytes between a string's quotes */

typedef enum lex_kind {
    LEX_EOF,
    LEX_IDENT,  /* [$]?[A-Za-z0-9_]+ not starting with a digit */
    LEX_NUMBER, /* value in number */
    LEX_STRING, /* decoded contents in string, string_length */
    LEX_TRUE,
    LEX_FALSE,
    LEX_UNDEF,
    LEX_LPAREN,    /* ( */
    LEX_RPAREN,    /* ) */
    LEX_LBRACKET,  /* [ */
    LEX_RBRACKET,  /* ] */
    LEX_LBRACE,    /* { */
    LEX_RBRACE,    /* } */
    LEX_COMMA,     /* , */
    LEX_SEMICOLON, /* ; */
    LEX_EQUALS,    /* = */
    LEX_PERCENT,   /* % background modifier */
    LEX_HASH,      /* # highlight modifier */
    LEX_BANG,      /* ! root modifier */
    LEX_STAR       /* * disable modifier */
} lex_kind;

typedef struct lex_token {
    lex_kind kind;
    int line, column;   /* of the token's first byte */
    const char *start;  /* the token's text in the input */
    size_t length;      /* bytes of text */
    double number;      /* LEX_NUMBER */
    const char *string; /* LEX_STRING: decoded, NUL-terminated, in the arena,
                           right after a NUL-terminated copy of the raw text
                           between the quotes (parse_string_raw) */
    size_t string_length;
} lex_token;

typedef struct lexer {
    const char *file; /* for error positions */
    const char *p, *end;
    const char *line_start; /* first byte of the current line */
    int line;
    arena *strings; /* where decoded strings go */
} lexer;

/* Prepares to read text[0 .. length). The text must outlive the lexer;
 * strings are allocated from the given arena. */
void lex_init(lexer *lx, const char *file, const char *text, size_t length,
              arena *strings);

/* Moves the lexer to p, a token's first byte or the whitespace before
 * it, on the given line, which starts at line_start. */
void lex_seek(lexer *lx, const char *p, int line, const char *line_start);

/* Reads the next token into *tok. Returns SC_OK, SC_ERR_SYNTAX (with the
 * position of the offending character), SC_ERR_LIMIT (a string longer than
 * LEX_MAX_STRING, at its opening quote) or SC_ERR_NOMEM. At the end of the
 * text it keeps returning LEX_EOF. */
sc_status lex_next(lexer *lx, lex_token *tok, sc_error *error);

/* Reads the number written at p (before end) as lex_next would, for the
 * parser's fast path over vectors of numbers: 1 with its value, correctly
 * rounded, and *after past it; 0 when lex_next must read it (inf, nan, a
 * malformed number or one out of range, none at all). */
int lex_number_at(const char *p, const char *end, double *value, const char **after);

/* The source position of byte `offset` of a string's decoded contents,
 * given its raw text (between the quotes, raw[0 .. raw_length)) and the
 * position of its opening quote: escapes and raw line breaks are walked as
 * the lexer decodes them, so the position names the character as written
 * (the backslash of an escape). An offset at or past the end names the
 * closing quote. */
void lex_string_locate(const char *raw, size_t raw_length, int quote_line,
                       int quote_column, size_t offset, int *line, int *column);

/* A short description of a token kind for messages: "')'", "a number", ... */
const char *lex_kind_name(lex_kind kind);

#endif
