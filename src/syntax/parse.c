/* The .csg parser: see parse.h for the grammar.
 *
 * One token of lookahead is enough: a statement starts with a modifier or a
 * name, an argument that starts with a name is named (a value never is a
 * name), and a value's first token says what it is.
 *
 * Neither nodes nor vectors recurse. An open node is the parent of the
 * statements that follow until its '}', so the parse of nested blocks is a
 * walk up and down parent pointers. Vectors use a value stack: an open '['
 * remembers where its items start on the stack; its ']' copies them into
 * the arena as one array and leaves the vector itself on the stack as an
 * item of the enclosing vector.
 *
 * A streamed parse (parse_stream) is the same walk with two differences:
 * a node goes to the sink once its arguments are read and again when it
 * closes, and a closed node's memory (the node, its arguments and values,
 * its children's) is handed back to the arena by restoring the mark taken
 * before the node was made. Nodes are then not linked into their parent's
 * list, which would point into freed memory; only inside a subtree the
 * sink keeps are they linked, and freed with the kept node.
 */
#include "syntax/parse.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "syntax/lex.h"

typedef struct open_vector {
    size_t start; /* index of its first item on the value stack */
    int line;     /* of its '[' */
} open_vector;

/* A name stored once: an entry of the parser's table of names. */
typedef struct name_entry {
    const char *chars;    /* in the tree's strings arena; NULL: a free slot */
    const char *language; /* language_word(chars), found once per name */
    uint32_t length;
    uint32_t hash;
} name_entry;

enum { RECENT_NAMES = 32 };

typedef struct parser {
    lexer lx;
    lex_token tok; /* the current token */
    parse_tree *tree;
    sc_error *error;
    parse_value *values; /* the value stack */
    size_t value_count, value_cap;
    open_vector *open; /* vectors not yet closed */
    size_t open_count, open_cap;
    parse_arg *args; /* the arguments of the node being read */
    size_t arg_count, arg_cap;
    name_entry *names; /* open addressing, a power of two slots, at most half full */
    size_t name_count, name_cap;
    /* The names met lately, by recent_slot: a file repeats a few names
     * (multmatrix, sphere, $fn, $fa, $fs, r) a million times, and a hit
     * here costs one comparison rather than a hash of the name and a
     * probe. Copies of table entries; an empty one has no chars. */
    name_entry recent[RECENT_NAMES];
    const parse_sink *sink; /* a streamed parse (parse_stream); NULL: keep the tree */
    arena_mark *marks;      /* streamed: the arena before each open node, by depth */
    size_t mark_cap;
    uint32_t kept_depth;  /* streamed: depth of the kept subtree's node, 0 if none */
    struct split *split;  /* the first part of a split parse: the second's state */
    atomic_int *cancel;   /* the second part of one: set when it is not wanted */
    const char *prev_end; /* the end of the token before the current one */
} parser;

static sc_location token_loc(const parser *ps)
{
    sc_location loc = {ps->tree->file, ps->tok.line, ps->tok.column};
    return loc;
}

/* An error at loc: what, a construct of OpenSCAD's language that its CSG
 * export never writes (parse_error_is_language). */
static sc_status language_error(parser *ps, sc_location loc, const char *format, ...)
    SC_PRINTF(3, 4);
static sc_status language_error(parser *ps, sc_location loc, const char *format, ...)
{
    char what[SC_ERROR_MESSAGE_MAX / 2];
    va_list args;
    va_start(args, format);
    vsnprintf(what, sizeof what, format, args);
    va_end(args);
    return err_set(ps->error, SC_ERR_UNSUPPORTED, &loc, "%s%s", what, PARSE_LANGUAGE);
}

/* The characters that are OpenSCAD's operators and appear in no token of
 * the CSG grammar: arithmetic, comparison, logic, ranges, member access,
 * the conditional. ('*', '%' and '!' are tokens, the modifiers.) */
static int operator_char(int c)
{
    return c && strchr("+-/<>:?^&|.", c) != NULL;
}

/* The next token. A character the lexer does not know that is one of
 * OpenSCAD's operators is the language beyond the CSG export. */
static sc_status advance(parser *ps)
{
    ps->prev_end = ps->tok.start + ps->tok.length;
    sc_status st = lex_next(&ps->lx, &ps->tok, ps->error);
    static const char unexpected[] = "unexpected character '";
    const char *m = ps->error->message;
    if (st == SC_ERR_SYNTAX && strncmp(m, unexpected, sizeof unexpected - 1) == 0) {
        const char *c = m + sizeof unexpected - 1;
        if (operator_char(c[0]) && c[1] == '\'' && !c[2]) {
            sc_location loc = {ps->tree->file, ps->error->line, ps->error->column};
            return language_error(ps, loc, "an operator ('%c')", c[0]);
        }
    }
    return st;
}

/* Whether a token that cannot follow a value here continues an expression
 * of OpenSCAD's language: an operator token, an index, a call. */
static int continues_expression(lex_kind kind)
{
    return kind == LEX_STAR || kind == LEX_PERCENT || kind == LEX_BANG ||
           kind == LEX_LBRACKET || kind == LEX_LPAREN;
}

static sc_status expression_error(parser *ps)
{
    return language_error(ps, token_loc(ps), "an expression ('%.*s')",
                          (int)ps->tok.length, ps->tok.start);
}

/* A syntax error at the current token. */
static sc_status syntax_error(parser *ps, const char *format, ...) SC_PRINTF(2, 3);
static sc_status syntax_error(parser *ps, const char *format, ...)
{
    sc_location loc = token_loc(ps);
    char message[SC_ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return err_set(ps->error, SC_ERR_SYNTAX, &loc, "%s", message);
}

static uint32_t name_hash(const char *s, size_t n)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

/* Doubles the table of names (or makes its first 64 slots); 0 when out of
 * memory. */
static int grow_names(parser *ps)
{
    size_t cap = ps->name_cap ? ps->name_cap * 2 : 64;
    name_entry *slots =
        cap <= SIZE_MAX / sizeof *slots ? calloc(cap, sizeof *slots) : NULL;
    if (!slots)
        return 0;
    for (size_t i = 0; i < ps->name_cap; i++) {
        const name_entry *e = &ps->names[i];
        if (!e->chars)
            continue;
        size_t k = e->hash & (cap - 1);
        while (slots[k].chars)
            k = (k + 1) & (cap - 1);
        slots[k] = *e;
    }
    free(ps->names);
    ps->names = slots;
    ps->name_cap = cap;
    return 1;
}

/* What a name at the start of a statement says when OpenSCAD's language
 * uses it and its CSG export never writes it: the keywords, the flow
 * control and echo modules (intersection_for is written as the
 * intersection it makes), the transforms (the export writes every
 * transform as multmatrix), and OpenSCAD 2021.01's deprecated modules,
 * which it writes as the import or extrusion they are. NULL for every
 * other name, which is a node. */
static const char *language_word(const char *name)
{
    static const char *const words[] = {
        "module",
        "function",
        "include",
        "use",
        "for",
        "if",
        "else",
        "let",
        "each",
        "echo",
        "assert",
        "assign",
        "children",
        "child",
        "intersection_for",
        "translate",
        "rotate",
        "scale",
        "mirror",
        "import_stl",
        "import_off",
        "import_dxf",
        "dxf_linear_extrude",
        "dxf_rotate_extrude",
    };
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strcmp(words[i], name) == 0)
            return words[i];
    return NULL;
}

/* The current token's text (a name) as a C string in the tree's strings
 * arena, stored once per distinct name: a file of a million spheres
 * writes "sphere", "multmatrix" and "$fn" a million times each. NULL when
 * out of memory. */
static const char *token_name(parser *ps, const char **language);

static const char *find_name(parser *ps, const char *text, size_t n, name_entry *seen);

static const char *token_text(parser *ps)
{
    return token_name(ps, NULL);
}

/* token_text, and when language is not NULL, language_word of the name
 * into *language, looked up once per distinct name rather than per node. */
/* The slot in parser.recent of the name text[0 .. n): its length
 * and its first and last bytes, which tell the names a file repeats
 * apart. */
static size_t recent_slot(const char *text, size_t n)
{
    return n ? (n + (unsigned char)text[0] + (unsigned char)text[n - 1]) &
                   (RECENT_NAMES - 1)
             : 0;
}

static const char *token_name(parser *ps, const char **language)
{
    const char *text = ps->tok.start;
    size_t n = ps->tok.length;
    name_entry *seen = &ps->recent[recent_slot(text, n)];
    if (seen->chars && seen->length == n && memcmp(seen->chars, text, n) == 0) {
        if (language)
            *language = seen->language;
        return seen->chars;
    }
    const char *name = find_name(ps, text, n, seen);
    if (name && language)
        *language = seen->language;
    return name;
}

/* token_name past parser.recent: the name from the table, stored there
 * first if new, and copied into *seen. NULL when out of memory. */
static const char *find_name(parser *ps, const char *text, size_t n, name_entry *seen)
{
    uint32_t h = name_hash(text, n);
    if (ps->name_count + 1 > ps->name_cap / 2 && !grow_names(ps))
        return NULL;
    size_t k = h & (ps->name_cap - 1);
    for (;; k = (k + 1) & (ps->name_cap - 1)) {
        name_entry *e = &ps->names[k];
        if (!e->chars)
            break;
        if (e->hash == h && e->length == n && memcmp(e->chars, text, n) == 0) {
            *seen = *e;
            return e->chars;
        }
    }
    char *s = arena_alloc(&ps->tree->strings, n + 1);
    if (!s)
        return NULL;
    memcpy(s, text, n);
    s[n] = '\0';
    /* Names are identifiers, far shorter than 2^32 bytes. */
    ps->names[k] = (name_entry){s, language_word(s), (uint32_t)n, h};
    ps->name_count++;
    *seen = ps->names[k];
    return s;
}

static sc_status push_value(parser *ps, const parse_value *v)
{
    if (ps->value_count == ps->value_cap &&
        !grow_array((void **)&ps->values, &ps->value_cap, ps->value_count + 1,
                    sizeof *ps->values))
        return err_nomem(ps->error, NULL);
    ps->values[ps->value_count++] = *v;
    return SC_OK;
}

/* Closes the innermost open vector at its ']' (the current token): its
 * items leave the stack and become one arena array in *v. */
static sc_status close_vector(parser *ps, parse_value *v)
{
    open_vector *o = &ps->open[--ps->open_count];
    size_t count = ps->value_count - o->start;
    /* The '[' token's position was saved as the vector's placeholder. */
    *v = ps->values[o->start - 1];
    if (count > UINT32_MAX)
        return err_set(ps->error, SC_ERR_LIMIT, NULL, "vector too long");
    parse_value *items = NULL;
    if (count) {
        /* count is below PARSE_MAX_VECTOR: the size cannot overflow. */
        items = arena_alloc(&ps->tree->mem, count * sizeof *items);
        if (!items)
            return err_nomem(ps->error, NULL);
        memcpy(items, &ps->values[o->start], count * sizeof *items);
    }
    v->u.vector.items = items;
    v->u.vector.count = (uint32_t)count;
    ps->value_count = o->start - 1; /* drop the items and the placeholder */
    return advance(ps);
}

/* The fast path for vectors of numbers, which are most of a file
 * OpenSCAD writes (a multmatrix is 20 numbers in 5 vectors): the text
 * after a '[' is read directly, without tokens, as long as it is numbers,
 * nested '[' (at most FAST_DEPTH open), ',' and ']' on one line, with
 * spaces and tabs between them. The values are those the token path makes,
 * positions included, and numbers are read by the lexer's own routine
 * (lex_number_at). Anything else (a line break, a comment, a string, a
 * name, inf, an error, a limit reached) gives up without a trace: the
 * values, the arena and the lexer are as they were, and the token path
 * reads the vector, with its messages. */
enum { FAST_DEPTH = 16 };

/* A new, cleared slot on top of the value stack; NULL when out of
 * memory. */
static inline parse_value *fast_slot(parser *ps)
{
    if (ps->value_count == ps->value_cap &&
        !grow_array((void **)&ps->values, &ps->value_cap, ps->value_count + 1,
                    sizeof *ps->values))
        return NULL;
    parse_value *slot = &ps->values[ps->value_count++];
    memset(slot, 0, sizeof *slot);
    return slot;
}

static const char *skip_blanks(const char *p, const char *end)
{
    /* Every byte past ' ' ends the blanks: one test for most bytes. */
    while (p < end && (unsigned char)*p <= ' ' && (*p == ' ' || *p == '\t' || *p == '\r'))
        p++;
    return p;
}

/* Reads the vector whose '[' is the current token. *done is 1 when it was
 * read (into *out, the lexer past its ']' and the next token read), 0 when
 * the token path must read it; the status is SC_OK unless memory ran out
 * or the next token is an error. */
static sc_status fast_vector(parser *ps, parse_value *out, int *done)
{
    *done = 0;
    lexer *lx = &ps->lx;
    const char *p = lx->p, *end = lx->end, *line_start = lx->line_start;
    const int line = ps->tok.line;
    const size_t base = ps->value_count;
    const arena_mark mark = arena_save(&ps->tree->mem);
    struct {
        size_t start; /* of its items on the value stack */
        int column;   /* of its '[' */
    } open[FAST_DEPTH];
    int depth = 1;
    open[0].start = base;
    open[0].column = ps->tok.column;
    parse_value v;
    sc_status st = SC_OK;
    for (;;) {
        /* After '[' or ',': an item, or ']'. */
        p = skip_blanks(p, end);
        if (p >= end)
            goto give_up;
        if (*p == '[') {
            if (depth == FAST_DEPTH)
                goto give_up;
            open[depth].start = ps->value_count;
            open[depth].column = (int)(p - line_start) + 1;
            depth++;
            p++;
            continue;
        }
        if (*p != ']') {
            double x;
            const char *after;
            if (!lex_number_at(p, end, &x, &after) ||
                ps->value_count - open[depth - 1].start >= PARSE_MAX_VECTOR)
                goto give_up;
            parse_value *slot = fast_slot(ps);
            if (!slot) {
                st = err_nomem(ps->error, NULL);
                goto give_up;
            }
            slot->kind = PARSE_NUMBER;
            slot->line = line;
            slot->column = (int)(p - line_start) + 1;
            slot->u.number = x;
            p = skip_blanks(after, end);
            if (p < end && *p == ',') {
                p++;
                continue;
            }
        }
        /* ']' closes vectors, each an item of the one around it, until
         * a ',' comes or the outermost one is closed. */
        for (;;) {
            if (p >= end || *p != ']')
                goto give_up;
            p++;
            depth--;
            size_t count = ps->value_count - open[depth].start;
            parse_value *items = NULL;
            if (count) {
                /* count is at most PARSE_MAX_VECTOR: the size cannot
                 * overflow. */
                items = arena_alloc(&ps->tree->mem, count * sizeof *items);
                if (!items) {
                    st = err_nomem(ps->error, NULL);
                    goto give_up;
                }
                memcpy(items, &ps->values[open[depth].start], count * sizeof *items);
            }
            memset(&v, 0, sizeof v);
            v.kind = PARSE_VECTOR;
            v.line = line;
            v.column = open[depth].column;
            v.u.vector.items = items;
            v.u.vector.count = (uint32_t)count;
            ps->value_count = open[depth].start;
            if (depth == 0) {
                *out = v;
                *done = 1;
                lx->p = p;
                return advance(ps);
            }
            if (ps->value_count - open[depth - 1].start >= PARSE_MAX_VECTOR)
                goto give_up;
            parse_value *slot = fast_slot(ps);
            if (!slot) {
                st = err_nomem(ps->error, NULL);
                goto give_up;
            }
            *slot = v;
            p = skip_blanks(p, end);
            if (p < end && *p == ',') {
                p++;
                break;
            }
        }
    }
give_up:
    ps->value_count = base;
    arena_restore(&ps->tree->mem, mark);
    return st;
}

/* value  := NUMBER | STRING | 'true' | 'false' | 'undef' | vector
 * vector := '[' [ value { ',' value } [ ',' ] ] ']'
 * Reads one value into *out, nested vectors included, without recursion. */
static sc_status parse_value_into(parser *ps, parse_value *out)
{
    sc_status st;
    size_t base = ps->open_count;
    for (;;) {
        parse_value v;
        memset(&v, 0, sizeof v);
        v.line = ps->tok.line;
        v.column = ps->tok.column;
        if (ps->tok.kind == LEX_LBRACKET &&
            ps->open_count - base + FAST_DEPTH <= PARSE_MAX_DEPTH) {
            int done = 0;
            if ((st = fast_vector(ps, &v, &done)) != SC_OK)
                return st;
            if (done)
                goto complete;
        }
        switch (ps->tok.kind) {
        case LEX_NUMBER:
            v.kind = PARSE_NUMBER;
            v.u.number = ps->tok.number;
            break;
        case LEX_STRING:
            /* The lexer keeps the raw text right before the decoded one
             * (parse_string_raw); both are at most LEX_MAX_STRING bytes. */
            v.kind = PARSE_STRING;
            v.u.string.chars = ps->tok.string;
            v.u.string.length = (uint32_t)ps->tok.string_length;
            v.u.string.raw_length = (uint32_t)(ps->tok.length - 2);
            break;
        case LEX_TRUE:
        case LEX_FALSE:
            v.kind = PARSE_BOOL;
            v.u.boolean = ps->tok.kind == LEX_TRUE;
            break;
        case LEX_UNDEF:
            v.kind = PARSE_UNDEF;
            break;
        case LEX_LBRACKET:
            if (ps->open_count - base >= PARSE_MAX_DEPTH) {
                sc_location loc = token_loc(ps);
                return err_set(ps->error, SC_ERR_LIMIT, &loc,
                               "too many nested vectors (limit is %d)", PARSE_MAX_DEPTH);
            }
            /* The placeholder keeps the '[' position until the ']'. */
            v.kind = PARSE_VECTOR;
            if ((st = push_value(ps, &v)) != SC_OK)
                return st;
            if (!grow_array((void **)&ps->open, &ps->open_cap, ps->open_count + 1,
                            sizeof *ps->open))
                return err_nomem(ps->error, NULL);
            ps->open[ps->open_count].start = ps->value_count;
            ps->open[ps->open_count].line = ps->tok.line;
            ps->open_count++;
            if ((st = advance(ps)) != SC_OK)
                return st;
            if (ps->tok.kind != LEX_RBRACKET)
                continue; /* read the first item */
            if ((st = close_vector(ps, &v)) != SC_OK)
                return st;
            goto complete;
        case LEX_IDENT:
            return language_error(ps, token_loc(ps), "a variable or function ('%.*s')",
                                  (int)ps->tok.length, ps->tok.start);
        case LEX_LPAREN:
        case LEX_BANG:
            return expression_error(ps);
        default:
            return syntax_error(ps, "expected a value, found %s",
                                lex_kind_name(ps->tok.kind));
        }
        if ((st = advance(ps)) != SC_OK)
            return st;
    complete:
        /* v is complete: it is the result, or an item of the open vector,
         * after which comes ',' or ']'. */
        for (;;) {
            if (ps->open_count == base) {
                *out = v;
                return SC_OK;
            }
            if (ps->value_count - ps->open[ps->open_count - 1].start >=
                PARSE_MAX_VECTOR) {
                sc_location loc = {ps->tree->file, v.line, v.column};
                return err_set(ps->error, SC_ERR_LIMIT, &loc,
                               "too many items in a vector (limit is %d)",
                               PARSE_MAX_VECTOR);
            }
            if ((st = push_value(ps, &v)) != SC_OK)
                return st;
            if (ps->tok.kind == LEX_COMMA) {
                if ((st = advance(ps)) != SC_OK)
                    return st;
                if (ps->tok.kind != LEX_RBRACKET)
                    break; /* read the next item */
            } else if (continues_expression(ps->tok.kind)) {
                return expression_error(ps);
            } else if (ps->tok.kind != LEX_RBRACKET) {
                return syntax_error(ps, "expected ']' (to close '[' at line %d)",
                                    ps->open[ps->open_count - 1].line);
            }
            if ((st = close_vector(ps, &v)) != SC_OK)
                return st;
        }
    }
}

/* Moves the arguments read (ps->args) into the arena as node's. */
static sc_status store_arguments(parser *ps, parse_node *node)
{
    if (ps->arg_count) {
        if (ps->arg_count > UINT32_MAX)
            return err_set(ps->error, SC_ERR_LIMIT, NULL, "too many arguments");
        parse_arg *args = arena_alloc(&ps->tree->mem, ps->arg_count * sizeof *args);
        if (!args)
            return err_nomem(ps->error, NULL);
        memcpy(args, ps->args, ps->arg_count * sizeof *args);
        node->args = args;
        node->arg_count = (uint32_t)ps->arg_count;
    }
    return SC_OK;
}

/* The fast path for a named number argument, `NAME = NUMBER` followed by
 * ',' or ')', which is most of the arguments OpenSCAD writes ($fn, $fa,
 * $fs, r, h, ...): at the current token, a name, the text after it is read
 * directly, without tokens, as long as it is '=', a number (read by
 * lex_number_at, as fast_vector does) and ',' or ')' on the same line with
 * spaces and tabs between them. Returns 1 when it was read: arg holds the
 * name and the value, with the positions the token path gives, and the
 * lexer stands past the ',' or ')' (*closed says which), the next token
 * not yet read. Returns 0 when the token path must read the argument:
 * then nothing has moved. */
static int fast_named_number(parser *ps, parse_arg *arg, int *closed)
{
    lexer *lx = &ps->lx;
    const char *p = skip_blanks(lx->p, lx->end), *end = lx->end;
    if (p >= end || *p != '=')
        return 0;
    p = skip_blanks(p + 1, end);
    const char *number = p;
    double x;
    if (!lex_number_at(p, end, &x, &p))
        return 0;
    p = skip_blanks(p, end);
    if (p >= end || (*p != ',' && *p != ')'))
        return 0;
    *closed = *p == ')';
    arg->value.kind = PARSE_NUMBER;
    arg->value.line = lx->line;
    arg->value.column = (int)(number - lx->line_start) + 1;
    arg->value.u.number = x;
    lx->p = p + 1;
    return 1;
}

/* arguments := [ argument { ',' argument } [ ',' ] ]
 * argument  := NAME '=' value | value
 * Reads the arguments after '(' (at line paren_line) through ')'. */
static sc_status parse_arguments(parser *ps, parse_node *node, int paren_line)
{
    sc_status st;
    ps->arg_count = 0;
    while (ps->tok.kind != LEX_RPAREN) {
        parse_arg arg;
        memset(&arg, 0, sizeof arg);
        arg.loc = token_loc(ps);
        if (ps->tok.kind == LEX_IDENT) {
            if (!(arg.name = token_text(ps)))
                return err_nomem(ps->error, NULL);
            int closed;
            if (fast_named_number(ps, &arg, &closed)) {
                if (ps->arg_count == ps->arg_cap &&
                    !grow_array((void **)&ps->args, &ps->arg_cap, ps->arg_count + 1,
                                sizeof *ps->args))
                    return err_nomem(ps->error, NULL);
                ps->args[ps->arg_count++] = arg;
                if (closed && (st = store_arguments(ps, node)) != SC_OK)
                    return st;
                if ((st = advance(ps)) != SC_OK || closed)
                    return st;
                continue;
            }
            if ((st = advance(ps)) != SC_OK)
                return st;
            if (ps->tok.kind == LEX_COMMA || ps->tok.kind == LEX_RPAREN ||
                continues_expression(ps->tok.kind))
                return language_error(ps, arg.loc, "a variable or function ('%s')",
                                      arg.name);
            if (ps->tok.kind != LEX_EQUALS)
                return syntax_error(ps, "expected '=' after argument name '%s'",
                                    arg.name);
            if ((st = advance(ps)) != SC_OK)
                return st;
        }
        if ((st = parse_value_into(ps, &arg.value)) != SC_OK)
            return st;
        if (ps->arg_count == ps->arg_cap &&
            !grow_array((void **)&ps->args, &ps->arg_cap, ps->arg_count + 1,
                        sizeof *ps->args))
            return err_nomem(ps->error, NULL);
        ps->args[ps->arg_count++] = arg;
        if (ps->tok.kind == LEX_COMMA) {
            if ((st = advance(ps)) != SC_OK)
                return st;
        } else if (continues_expression(ps->tok.kind)) {
            return expression_error(ps);
        } else if (ps->tok.kind != LEX_RPAREN) {
            return syntax_error(ps, "expected ')' (to close '(' at line %d)", paren_line);
        }
    }
    if ((st = store_arguments(ps, node)) != SC_OK)
        return st;
    return advance(ps); /* past ')' */
}

static unsigned modifier_flag(lex_kind kind)
{
    switch (kind) {
    case LEX_STAR:
        return PARSE_MOD_DISABLE;
    case LEX_BANG:
        return PARSE_MOD_ROOT;
    case LEX_HASH:
        return PARSE_MOD_HIGHLIGHT;
    case LEX_PERCENT:
        return PARSE_MOD_BACKGROUND;
    default:
        return 0;
    }
}

static void append_child(parse_node *parent, parse_node *node)
{
    node->parent = parent;
    if (parent->last_child)
        parent->last_child->next = node;
    else
        parent->first_child = node;
    parent->last_child = node;
    parent->child_count++;
}

/* Whether node, just read, is linked into the tree: always in a whole
 * parse; in a streamed one only below a kept node. */
static int links(const parser *ps, uint32_t depth)
{
    return !ps->sink || (ps->kept_depth && depth > ps->kept_depth);
}

/* Hands a node just read to the sink, after remembering the arena mark
 * taken before it was made. */
static sc_status open_node(parser *ps, parse_node *node, arena_mark mark)
{
    if (!ps->sink)
        return SC_OK;
    if (!grow_array((void **)&ps->marks, &ps->mark_cap, node->depth + 1u,
                    sizeof *ps->marks))
        return err_nomem(ps->error, NULL);
    ps->marks[node->depth] = mark;
    int keep = 0;
    sc_status st = ps->sink->open(ps->sink->user, node, &keep, ps->error);
    if (st == SC_OK && keep && !ps->kept_depth)
        ps->kept_depth = node->depth;
    return st;
}

/* Hands a closed node to the sink and frees it with its subtree, unless it
 * lies below a kept node. */
static sc_status close_node(parser *ps, parse_node *node)
{
    if (!ps->sink)
        return SC_OK;
    uint32_t depth = node->depth;
    sc_status st = ps->sink->close(ps->sink->user, node, ps->error);
    if (st != SC_OK || (ps->kept_depth && depth > ps->kept_depth))
        return st;
    if (ps->kept_depth == depth)
        ps->kept_depth = 0;
    arena_restore(&ps->tree->mem, ps->marks[depth]);
    return SC_OK;
}

/* One open statement of the walk in parse_statements: a node whose child
 * statement has not begun (AWAIT) or is a block (BLOCK), or a block
 * without a node (BARE), whose statements belong to the enclosing node. */
typedef enum frame_kind { FRAME_AWAIT, FRAME_BLOCK, FRAME_BARE } frame_kind;

typedef struct frame {
    parse_node *node; /* NULL for FRAME_BARE */
    int line;         /* FRAME_BARE: the line of its '{' */
    frame_kind kind;
    const char *brace; /* FRAME_BLOCK, FRAME_BARE: its '{' */
} frame;

typedef struct walk {
    frame *frames;
    size_t count, cap;
    parse_node *parent; /* the innermost frame's node, NULL at top level */
    size_t base;        /* the second part of a split parse: the frames below
                           it are the first part's, and its list ends at the
                           '}' that would close frames[base - 1] */
} walk;

static sc_status push_frame(parser *ps, walk *w, parse_node *node, frame_kind kind,
                            int line)
{
    if (w->count >= PARSE_MAX_DEPTH) {
        sc_location loc = token_loc(ps);
        return err_set(ps->error, SC_ERR_LIMIT, &loc, "too many nested %s (limit is %d)",
                       node ? "nodes" : "blocks", PARSE_MAX_DEPTH);
    }
    if (!grow_array((void **)&w->frames, &w->cap, w->count + 1, sizeof *w->frames))
        return err_nomem(ps->error, NULL);
    w->frames[w->count++] = (frame){node, line, kind, ps->tok.start};
    if (node)
        w->parent = node;
    return SC_OK;
}

/* Pops the innermost frame, closing its node, if any. */
static sc_status pop_frame(parser *ps, walk *w)
{
    frame f = w->frames[--w->count];
    w->parent = NULL;
    for (size_t i = w->count; i-- > 0;) {
        if (w->frames[i].node) {
            w->parent = w->frames[i].node;
            break;
        }
    }
    return f.node ? close_node(ps, f.node) : SC_OK;
}

/* A statement is complete: each node waiting for its one child statement
 * (this one, or the node that this one completed) is complete too. */
static sc_status statement_done(parser *ps, walk *w)
{
    sc_status st = SC_OK;
    while (st == SC_OK && w->count && w->frames[w->count - 1].kind == FRAME_AWAIT)
        st = pop_frame(ps, w);
    return st;
}

/* Reads one node statement's head at its first modifier or name: the
 * node, linked under w->parent, handed to the sink, and pushed waiting
 * for its child statement. */
static sc_status parse_node_head(parser *ps, walk *w, parse_node **top_tail)
{
    sc_status st;
    parse_tree *tree = ps->tree;
    parse_node *parent = w->parent;
    unsigned modifiers = 0;
    while (modifier_flag(ps->tok.kind)) {
        modifiers |= modifier_flag(ps->tok.kind);
        if ((st = advance(ps)) != SC_OK)
            return st;
    }
    if (ps->tok.kind == LEX_LBRACE)
        return syntax_error(ps, "expected a node name before '{'");
    if (ps->tok.kind != LEX_IDENT)
        return syntax_error(ps, "expected a node name, found %s",
                            lex_kind_name(ps->tok.kind));
    uint32_t depth = parent ? parent->depth + 1 : 1;
    if (depth > PARSE_MAX_DEPTH) {
        sc_location loc = token_loc(ps);
        return err_set(ps->error, SC_ERR_LIMIT, &loc,
                       "too many nested nodes (limit is %d)", PARSE_MAX_DEPTH);
    }
    if (tree->node_count >= PARSE_MAX_NODES) {
        sc_location loc = token_loc(ps);
        return err_set(ps->error, SC_ERR_LIMIT, &loc, "too many nodes (limit is %d)",
                       PARSE_MAX_NODES);
    }
    arena_mark mark = arena_save(&tree->mem);
    parse_node *node = arena_calloc(&tree->mem, 1, sizeof *node);
    const char *word = NULL;
    if (!node || !(node->name = token_name(ps, &word)))
        return err_nomem(ps->error, NULL);
    node->loc = token_loc(ps);
    node->modifiers = (uint8_t)modifiers;
    node->depth = (uint16_t)depth;
    if (word)
        return language_error(ps, node->loc, "'%s'", word);
    if ((st = advance(ps)) != SC_OK)
        return st;
    if (ps->tok.kind == LEX_EQUALS && !modifiers)
        return language_error(ps, node->loc, "an assignment ('%s = ...')", node->name);
    if (ps->tok.kind != LEX_LPAREN)
        return syntax_error(ps, "expected '(' after node name '%s'", node->name);
    int paren_line = ps->tok.line;
    if ((st = advance(ps)) != SC_OK)
        return st;
    if ((st = parse_arguments(ps, node, paren_line)) != SC_OK)
        return st;
    if (!links(ps, depth)) {
        node->parent = parent;
        if (parent)
            parent->child_count++;
        else
            tree->count++;
    } else if (parent) {
        append_child(parent, node);
    } else {
        if (*top_tail)
            (*top_tail)->next = node;
        else
            tree->first = node;
        *top_tail = node;
        tree->count++;
    }
    tree->node_count++;
    if ((st = open_node(ps, node, mark)) != SC_OK)
        return st;
    return push_frame(ps, w, node, FRAME_AWAIT, 0);
}

/* file      := statement* EOF
 * statement := ';' | '{' statement* '}' | modifier* NAME '(' arguments ')' statement
 * A node's statement is its child: ';' (none), a block (its statements),
 * or one node statement, as in OpenSCAD's grammar, so that
 * `multmatrix(m) cube(1);` is `multmatrix(m) { cube(1); }`; a block that
 * follows no node holds statements of the enclosing node (or of the
 * file). The walk keeps the open statements on a stack of frames (walk)
 * rather than recursing. */
static sc_status split_poll(parser *ps, walk *w);

static sc_status parse_statements(parser *ps, walk *w)
{
    sc_status st;
    parse_node *top_tail = NULL;
    for (;;) {
        if (ps->split && (st = split_poll(ps, w)) != SC_OK)
            return st;
        if (ps->cancel && atomic_load_explicit(ps->cancel, memory_order_relaxed))
            return SC_ERR_CANCELLED;
        lex_kind kind = ps->tok.kind;
        frame *top = w->count ? &w->frames[w->count - 1] : NULL;
        if (top && top->kind == FRAME_AWAIT && kind != LEX_SEMICOLON &&
            kind != LEX_LBRACE && kind != LEX_IDENT && !modifier_flag(kind))
            return syntax_error(ps, "expected ';', '{' or a child node after node '%s'",
                                top->node->name);
        if (kind == LEX_EOF) {
            if (top && w->count > w->base)
                return syntax_error(ps, "expected '}' (to close '{' at line %d)",
                                    top->node ? top->node->block_line : top->line);
            return SC_OK;
        }
        if (kind == LEX_RBRACE) {
            if (w->base && w->count == w->base)
                return SC_OK; /* the end of a second part: the first reads on */
            if (!top)
                return syntax_error(ps, "unmatched '}'");
            if ((st = pop_frame(ps, w)) != SC_OK || (st = advance(ps)) != SC_OK ||
                (st = statement_done(ps, w)) != SC_OK)
                return st;
            continue;
        }
        if (kind == LEX_SEMICOLON) {
            if ((st = advance(ps)) != SC_OK || (st = statement_done(ps, w)) != SC_OK)
                return st;
            continue;
        }
        if (kind == LEX_LBRACE) {
            if (top && top->kind == FRAME_AWAIT) {
                top->kind = FRAME_BLOCK;
                top->brace = ps->tok.start;
                top->node->has_block = 1;
                top->node->block_line = ps->tok.line;
            } else if ((st = push_frame(ps, w, NULL, FRAME_BARE, ps->tok.line)) !=
                       SC_OK) {
                return st;
            }
            if ((st = advance(ps)) != SC_OK)
                return st;
            continue;
        }
        if ((st = parse_node_head(ps, w, &top_tail)) != SC_OK)
            return st;
    }
}

/* A split parse (parse_sink's fork): the first thread reads the text up
 * to a statement boundary, a second one from there to the end of that
 * statement list, and the first joins the second's result and reads on.
 *
 * The second thread first scans the text for a boundary near the target
 * (split_scan), without parsing: braces, strings and comments are enough
 * to know the depth. It publishes the boundary and the '{' of its list;
 * the first thread, once it has that list open and has not yet passed the
 * boundary, hands it the consumer (fork) and its open frames, and the
 * second parses on its own tree and lexer. When the first reaches the
 * boundary at the list's own level, exactly at the byte the scan chose,
 * the scan was right: it joins the second part (its names, counts and
 * consumer) and moves its lexer to where the second stopped, the list's
 * '}' or the end. Whatever else happens (a scan that misread the text, an
 * error in the second part, a consumer that cannot join) the first thread
 * drops the second part and reads it itself, so that errors are found
 * and reported exactly as by a whole parse. */
typedef enum split_state {
    SPLIT_SCANNING, /* the second thread looks for a boundary */
    SPLIT_FOUND,    /* it has one and waits for the first thread */
    SPLIT_NONE,     /* it found none and has ended */
    SPLIT_GO,       /* the first thread has forked: the second parses */
    SPLIT_CANCEL    /* the first thread does not want the second part */
} split_state;

typedef struct split {
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    atomic_int state;  /* split_state, changed under lock */
    atomic_int cancel; /* the second part is not wanted any more */
    const char *file, *text;
    size_t length, target;
    int wait; /* the target was given: the first thread awaits the scan */
    /* The boundary (SPLIT_FOUND): the '{' of its list (NULL: the top
     * level), the byte after the ';' or '}' that ends the statement
     * before it, and the lexer's line there. */
    const char *brace, *at, *line_start;
    int line;
    /* Given by the first thread (SPLIT_GO). */
    parse_sink sink;       /* the forked consumer's */
    parse_node parent;     /* a copy of the list's node, whose children the
                              second part counts */
    parse_node *list_node; /* the first part's node itself (NULL: top level) */
    frame *frames;         /* the first part's open frames, the last one the
                              list's, its node the copy */
    size_t frame_count;
    /* The second part's result. */
    sc_status status;
    sc_error error;
    int first_line, first_column; /* its first token's, which the first
                                     thread checks against its own */
    parse_tree *tree;
    lexer lx;
    lex_token tok;
} split;

/* The bytes the boundary scan must look at: the ones that open or close
 * a block, a string or a comment, end a statement, or a line. */
static int scan_stop(unsigned char c)
{
    return c == '{' || c == '}' || c == ';' || c == '"' || c == '/' || c == '\n';
}

/* Scans the text for the boundary: the first statement end (a ';', or a
 * '}' that closes a block) after target in the shallowest list that has
 * one within a window past target. Returns 1 with sp's boundary set. */
static int split_scan(split *sp)
{
    unsigned char stop[256];
    for (int c = 0; c < 256; c++)
        stop[c] = (unsigned char)scan_stop((unsigned char)c);
    const char *p = sp->text, *end = sp->text + sp->length;
    const char *target = sp->text + sp->target;
    size_t window = sp->length / 8 > 4096 ? sp->length / 8 : 4096;
    const char *limit = (size_t)(end - target) > window ? target + window : end;
    const char **braces = NULL;
    size_t depth = 0, cap = 0, at_target = SIZE_MAX, best = SIZE_MAX;
    const char *line_start = p;
    int line = 1, found = 0;
    while (p < end) {
        if (p >= target && at_target == SIZE_MAX)
            at_target = depth;
        if (at_target != SIZE_MAX && p >= limit)
            break;
        if (((uintptr_t)p & 0xfffff) == 0 &&
            atomic_load_explicit(&sp->cancel, memory_order_relaxed))
            break;
        unsigned char c = (unsigned char)*p;
        if (!stop[c]) {
            p++;
            continue;
        }
        if (c == '\n') {
            line++;
            line_start = ++p;
            continue;
        }
        if (c == '"') {
            for (p++; p < end && *p != '"'; p++) {
                if (*p == '\\' && p + 1 < end)
                    p++;
                if (*p == '\n') {
                    line++;
                    line_start = p + 1;
                }
            }
            if (p >= end)
                break;
            p++;
            continue;
        }
        if (c == '/' && p + 1 < end && p[1] == '/') {
            while (p < end && *p != '\n')
                p++;
            continue;
        }
        if (c == '/' && p + 1 < end && p[1] == '*') {
            for (p += 2; p + 1 < end && !(p[0] == '*' && p[1] == '/'); p++)
                if (*p == '\n') {
                    line++;
                    line_start = p + 1;
                }
            if (p + 1 >= end)
                break;
            p += 2;
            continue;
        }
        if (c == '{') {
            if (!grow_array((void **)&braces, &cap, depth + 1, sizeof *braces))
                break;
            braces[depth++] = p++;
            continue;
        }
        if (c == '}') {
            if (!depth)
                break; /* unmatched: the parse stops there */
            depth--;
        }
        p++;
        /* A statement ends at p in the list at this depth. */
        if ((c == ';' || c == '}') && at_target != SIZE_MAX && depth <= at_target &&
            depth < best) {
            best = depth;
            sp->brace = depth ? braces[depth - 1] : NULL;
            sp->at = p;
            sp->line = line;
            sp->line_start = line_start;
            found = 1;
            if (depth == 0)
                break;
        }
    }
    free(braces);
    return found;
}

static void split_parse(split *sp);

static void set_state(split *sp, split_state state)
{
    pthread_mutex_lock(&sp->lock);
    atomic_store_explicit(&sp->state, state, memory_order_release);
    pthread_cond_broadcast(&sp->changed);
    pthread_mutex_unlock(&sp->lock);
}

static void *split_main(void *arg)
{
    split *sp = arg;
    if (!split_scan(sp)) {
        set_state(sp, SPLIT_NONE);
        return NULL;
    }
    pthread_mutex_lock(&sp->lock);
    if (atomic_load_explicit(&sp->state, memory_order_relaxed) == SPLIT_SCANNING) {
        atomic_store_explicit(&sp->state, SPLIT_FOUND, memory_order_release);
        pthread_cond_broadcast(&sp->changed);
    }
    while (atomic_load_explicit(&sp->state, memory_order_relaxed) == SPLIT_FOUND)
        pthread_cond_wait(&sp->changed, &sp->lock);
    int go = atomic_load_explicit(&sp->state, memory_order_relaxed) == SPLIT_GO;
    pthread_mutex_unlock(&sp->lock);
    if (go)
        split_parse(sp);
    return NULL;
}

/* The second part: the statements of the list from the boundary to its
 * '}' (or the end), on a tree of its own. */
static void split_parse(split *sp)
{
    sp->status = SC_ERR_NOMEM;
    parse_tree *tree = calloc(1, sizeof *tree);
    if (!tree)
        return;
    arena_init(&tree->mem, 64 * 1024);
    arena_init(&tree->strings, 16 * 1024);
    tree->file = sp->file;
    sp->tree = tree;
    parser ps;
    memset(&ps, 0, sizeof ps);
    ps.tree = tree;
    ps.error = &sp->error;
    ps.sink = &sp->sink;
    ps.cancel = &sp->cancel;
    ps.tok.start = sp->at;
    lex_init(&ps.lx, sp->file, sp->text, sp->length, &tree->strings);
    lex_seek(&ps.lx, sp->at, sp->line, sp->line_start);
    walk w = {sp->frames, sp->frame_count, sp->frame_count,
              sp->list_node ? &sp->parent : NULL, sp->frame_count};
    sc_status st = advance(&ps);
    sp->first_line = ps.tok.line;
    sp->first_column = ps.tok.column;
    if (st == SC_OK)
        st = parse_statements(&ps, &w);
    sp->frames = w.frames;
    free(ps.values);
    free(ps.open);
    free(ps.args);
    free(ps.names);
    free(ps.marks);
    sp->status = st;
    sp->lx = ps.lx;
    sp->tok = ps.tok;
}

/* Starts the second thread when the sink can take a split parse of a
 * text this long. */
static void split_start(parser *ps, const char *file, const char *text, size_t length)
{
    const parse_sink *sink = ps->sink;
    if (!sink || !sink->fork || !sink->split_min || length < sink->split_min ||
        length < 2)
        return;
    split *sp = calloc(1, sizeof *sp);
    if (!sp)
        return;
    sp->file = file;
    sp->text = text;
    sp->length = length;
    /* a little past the middle: the second thread scans up to it first */
    sp->wait = sink->split_at && sink->split_at < length;
    sp->target = sp->wait ? sink->split_at : length / 32 * 17;
    atomic_init(&sp->state, SPLIT_SCANNING);
    atomic_init(&sp->cancel, 0);
    if (pthread_mutex_init(&sp->lock, NULL) != 0) {
        free(sp);
        return;
    }
    if (pthread_cond_init(&sp->changed, NULL) != 0 ||
        pthread_create(&sp->thread, NULL, split_main, sp) != 0) {
        pthread_cond_destroy(&sp->changed);
        pthread_mutex_destroy(&sp->lock);
        free(sp);
        return;
    }
    ps->split = sp;
}

/* Ends the split: the second thread told to stop, waited for, its part
 * dropped unless joined; the first thread reads on alone. */
static void split_end(parser *ps)
{
    split *sp = ps->split;
    if (!sp)
        return;
    ps->split = NULL;
    atomic_store_explicit(&sp->cancel, 1, memory_order_relaxed);
    pthread_mutex_lock(&sp->lock);
    int state = atomic_load_explicit(&sp->state, memory_order_relaxed);
    if (state == SPLIT_SCANNING || state == SPLIT_FOUND)
        atomic_store_explicit(&sp->state, SPLIT_CANCEL, memory_order_release);
    pthread_cond_broadcast(&sp->changed);
    pthread_mutex_unlock(&sp->lock);
    pthread_join(sp->thread, NULL);
    if (state == SPLIT_GO)
        ps->sink->drop(sp->sink.user);
    parse_tree_free(sp->tree);
    free(sp->frames);
    pthread_cond_destroy(&sp->changed);
    pthread_mutex_destroy(&sp->lock);
    free(sp);
}

/* Whether the walk is at the boundary's list, between its statements. */
static int at_list(const walk *w, const char *brace)
{
    if (!brace)
        return w->count == 0;
    const frame *top = w->count ? &w->frames[w->count - 1] : NULL;
    return top && top->kind == FRAME_BLOCK && top->brace == brace;
}

/* Hands the second thread its part, once the list is open here. */
static void split_fork(parser *ps, walk *w)
{
    split *sp = ps->split;
    const frame *top = w->count ? &w->frames[w->count - 1] : NULL;
    uint32_t depth = top ? top->node->depth : 0;
    if (ps->kept_depth || !(sp->frames = malloc((w->count + 1) * sizeof *sp->frames))) {
        split_end(ps);
        return;
    }
    void *user = ps->sink->fork(ps->sink->user, depth);
    if (!user) {
        split_end(ps);
        return;
    }
    if (w->count)
        memcpy(sp->frames, w->frames, w->count * sizeof *sp->frames);
    sp->frame_count = w->count;
    sp->list_node = top ? top->node : NULL;
    if (top) {
        sp->parent = *top->node;
        sp->parent.child_count = 0;
        sp->frames[w->count - 1].node = &sp->parent;
    }
    sp->sink = *ps->sink;
    sp->sink.user = user;
    sp->sink.split_min = 0;
    set_state(sp, SPLIT_GO);
}

/* The first thread at the boundary: the second part joined, and the
 * lexer moved past it, when it is whole and the consumer takes it. */
static sc_status split_join(parser *ps)
{
    split *sp = ps->split;
    pthread_join(sp->thread, NULL);
    ps->split = NULL;
    parse_tree *tree = ps->tree, *part = sp->tree;
    int joined = sp->status == SC_OK && part && sp->first_line == ps->tok.line &&
                 sp->first_column == ps->tok.column &&
                 (uint64_t)tree->node_count + part->node_count <= PARSE_MAX_NODES &&
                 ps->sink->join(ps->sink->user, sp->sink.user);
    if (joined) {
        if (sp->list_node)
            sp->list_node->child_count += sp->parent.child_count;
        else
            tree->count += part->count;
        tree->node_count += part->node_count;
        tree->split = 1;
        arena_adopt(&tree->strings, &part->strings);
        lex_seek(&ps->lx, sp->lx.p, sp->lx.line, sp->lx.line_start);
        ps->tok = sp->tok;
    } else {
        ps->sink->drop(sp->sink.user);
    }
    parse_tree_free(part);
    free(sp->frames);
    pthread_cond_destroy(&sp->changed);
    pthread_mutex_destroy(&sp->lock);
    free(sp);
    return SC_OK;
}

/* The first thread, between two statements: fork when the boundary's
 * list is open and the boundary still ahead, join at the boundary, and
 * give up the split when the walk passes it elsewhere or the scan found
 * none. */
static sc_status split_poll(parser *ps, walk *w)
{
    split *sp = ps->split;
    int state = atomic_load_explicit(&sp->state, memory_order_acquire);
    if (state == SPLIT_SCANNING && sp->wait) {
        /* a boundary asked for: the scan's answer is awaited */
        pthread_mutex_lock(&sp->lock);
        while ((state = atomic_load_explicit(&sp->state, memory_order_relaxed)) ==
               SPLIT_SCANNING)
            pthread_cond_wait(&sp->changed, &sp->lock);
        pthread_mutex_unlock(&sp->lock);
    }
    if (state == SPLIT_SCANNING)
        return SC_OK;
    if (state == SPLIT_FOUND) {
        if (ps->prev_end >= sp->at)
            split_end(ps);
        else if (at_list(w, sp->brace))
            split_fork(ps, w);
        return SC_OK;
    }
    if (state == SPLIT_GO && ps->prev_end < sp->at)
        return SC_OK;
    if (state == SPLIT_GO && ps->prev_end == sp->at && at_list(w, sp->brace))
        return split_join(ps);
    split_end(ps);
    return SC_OK;
}

static sc_status parse(const char *file, const char *text, size_t length,
                       const parse_sink *sink, parse_tree **out, sc_error *error)
{
    *out = NULL;
    parse_tree *tree = calloc(1, sizeof *tree);
    if (!tree)
        return err_nomem(error, NULL);
    arena_init(&tree->mem, 64 * 1024);
    arena_init(&tree->strings, 16 * 1024);
    tree->file = file;
    parser ps;
    memset(&ps, 0, sizeof ps);
    ps.tree = tree;
    ps.error = error;
    ps.sink = sink;
    ps.tok.start = text;
    lex_init(&ps.lx, file, text, length, &tree->strings);
    walk w;
    memset(&w, 0, sizeof w);
    split_start(&ps, file, text, length);
    sc_status st = advance(&ps);
    if (st == SC_OK)
        st = parse_statements(&ps, &w);
    split_end(&ps);
    free(w.frames);
    free(ps.values);
    free(ps.open);
    free(ps.args);
    free(ps.names);
    free(ps.marks);
    if (st != SC_OK) {
        parse_tree_free(tree);
        return st;
    }
    *out = tree;
    return SC_OK;
}

sc_status parse_text(const char *file, const char *text, size_t length, parse_tree **out,
                     sc_error *error)
{
    return parse(file, text, length, NULL, out, error);
}

sc_status parse_stream(const char *file, const char *text, size_t length,
                       const parse_sink *sink, parse_tree **out, sc_error *error)
{
    sc_status st = parse(file, text, length, sink, out, error);
    if (st == SC_OK)
        arena_free(&(*out)->mem); /* the blocks the open nodes used */
    return st;
}

void parse_tree_free(parse_tree *tree)
{
    if (!tree)
        return;
    arena_free(&tree->mem);
    arena_free(&tree->strings);
    free(tree);
}

void parse_tree_release_nodes(parse_tree *tree)
{
    if (!tree)
        return;
    arena_free(&tree->mem);
    tree->first = NULL;
    tree->count = 0;
}

int parse_error_is_language(const sc_error *error)
{
    size_t n = strlen(error->message), k = sizeof PARSE_LANGUAGE - 1;
    return error->status == SC_ERR_UNSUPPORTED && n >= k &&
           strcmp(error->message + n - k, PARSE_LANGUAGE) == 0;
}

const parse_arg *parse_node_arg(const parse_node *node, const char *name, int position)
{
    const parse_arg *found = NULL;
    int positional = 0;
    for (uint32_t i = 0; i < node->arg_count; i++) {
        const parse_arg *a = &node->args[i];
        if (a->name) {
            if (a->name[0] == name[0] && strcmp(a->name, name) == 0)
                found = a;
        } else if (positional++ == position) {
            found = a;
        }
    }
    return found;
}

const parse_node *parse_next_node(const parse_node *node, int skip_children)
{
    if (!skip_children && node->first_child)
        return node->first_child;
    while (node) {
        if (node->next)
            return node->next;
        node = node->parent;
    }
    return NULL;
}
