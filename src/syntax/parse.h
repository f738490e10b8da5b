/* The parser of the .csg grammar: tokens in, a syntax tree out.
 *
 *   file      := statement* EOF
 *   statement := ';' | '{' statement* '}' | modifier* NAME '(' arguments ')' statement
 *   modifier  := '%' | '#' | '!' | '*'
 *   arguments := [ argument { ',' argument } [ ',' ] ]
 *   argument  := NAME '=' value | value
 *   value     := NUMBER | STRING | 'true' | 'false' | 'undef' | vector
 *   vector    := '[' [ value { ',' value } [ ',' ] ] ']'
 *
 * This is OpenSCAD's grammar for its module instantiations with literal
 * arguments: a node's child statement is ';' (no children), a block, or
 * one node (`multmatrix(m) cube(1);`); a block after no node adds its
 * statements to the enclosing node, and ';' alone is an empty statement.
 * Where a file goes on in the rest of OpenSCAD's language (an
 * assignment, a variable or an expression as a value, module or function
 * definitions, include/use, for/if/let, the transforms that the export
 * writes as multmatrix), the error is SC_ERR_UNSUPPORTED at that place,
 * its message ending in PARSE_LANGUAGE (parse_error_is_language), so
 * that a caller that can run OpenSCAD converts the file instead.
 *
 * The tree keeps everything the file says, meaning nothing yet: node names
 * are not checked here (the builder does that), every argument is kept in
 * source order, including `$fn`, `$fa`, `$fs`, which exact rendering does
 * not use but OpenSCAD-faithful rendering will. Every node, argument and
 * value carries its source position.
 *
 * Nesting is handled with explicit stacks, never recursion, so no input can
 * overflow the C stack; nodes and vectors are each limited to
 * PARSE_MAX_DEPTH levels. A file holds at most PARSE_MAX_NODES nodes and a
 * vector at most PARSE_MAX_VECTOR items (docs/limits.md), so memory stays
 * proportional to what a real model needs. Everything lives in two arenas
 * owned by the tree: the nodes with their arguments and values, and the
 * names and strings. A name (of a node or of an argument) is stored once
 * however often the file writes it.
 */
#ifndef SPANCAST_SYNTAX_PARSE_H
#define SPANCAST_SYNTAX_PARSE_H

#include <stddef.h>
#include <stdint.h>

#include "base/arena.h"
#include "spancast/spancast.h"

#define PARSE_MAX_DEPTH 10000 /* nested nodes, and nested vectors */

#define PARSE_MAX_NODES 4000000  /* nodes in a file */
#define PARSE_MAX_VECTOR 1000000 /* items in one vector */
/* The smallest text loading reads in two threads (parse_sink's split_min):
 * below it, the second thread's start and scan cost more than they save. */
#define PARSE_SPLIT_MIN ((size_t)1 << 20)

typedef enum parse_value_kind {
    PARSE_UNDEF,
    PARSE_BOOL,
    PARSE_NUMBER,
    PARSE_STRING,
    PARSE_VECTOR
} parse_value_kind;

/* 32 bytes: a million positioned leaves hold about twenty million values
 * (a 4x4 matrix is 21 of them), so every byte here is 20 MB there. */
typedef struct parse_value parse_value;
struct parse_value {
    parse_value_kind kind;
    int line, column; /* of the value's first token */
    union {
        int boolean;
        double number; /* may be inf or nan: OpenSCAD writes them */
        struct {
            const char *chars;   /* decoded, NUL-terminated; the text as written
                                    comes before it (parse_string_raw) */
            uint32_t length;     /* bytes of chars */
            uint32_t raw_length; /* bytes as written between the quotes */
        } string;
        struct {
            const parse_value *items;
            uint32_t count;
        } vector;
    } u;
};

/* A string value's text as written between the quotes, raw_length bytes
 * and a NUL (for positions inside the string, see lex_string_locate). */
static inline const char *parse_string_raw(const parse_value *v)
{
    return v->u.string.chars - v->u.string.raw_length - 1;
}

typedef struct parse_arg {
    const char *name; /* NULL for a positional argument */
    sc_location loc;  /* of the name, or of the value when positional */
    parse_value value;
} parse_arg;

/* Modifier flags, in the order OpenSCAD documents them. */
enum {
    PARSE_MOD_DISABLE = 1,   /* '*': the node is dropped */
    PARSE_MOD_ROOT = 2,      /* '!': the node is the whole design */
    PARSE_MOD_HIGHLIGHT = 4, /* '#': shown highlighted, part of the solid */
    PARSE_MOD_BACKGROUND = 8 /* '%': shown, not part of the solid */
};

/* 80 bytes, packed for the same reason as parse_value. */
typedef struct parse_node parse_node;
struct parse_node {
    const char *name; /* NUL-terminated, shared by every node of that name */
    sc_location loc;  /* of the name */
    const parse_arg *args;
    uint32_t arg_count;
    uint32_t child_count;
    parse_node *parent; /* NULL at top level */
    parse_node *first_child, *last_child, *next;
    int block_line;    /* line of the '{' */
    uint16_t depth;    /* 1 for a top-level node (at most PARSE_MAX_DEPTH) */
    uint8_t modifiers; /* PARSE_MOD_* flags */
    uint8_t has_block; /* written with '{ ... }' (maybe empty) rather than ';' */
};

typedef struct parse_tree {
    arena mem;         /* owns every node, argument and value */
    arena strings;     /* owns every name and string, which outlive the nodes
                          (parse_tree_release_nodes) */
    const char *file;  /* as passed to parse_text; not owned */
    parse_node *first; /* top-level statements, linked by next */
    uint32_t count;
    uint32_t node_count; /* all nodes */
    int split;           /* a streamed parse read it in two joined parts */
} parse_tree;

/* Parses text[0 .. length). file names the text in positions and must
 * outlive the tree. On success *out owns the tree (free with
 * parse_tree_free); on failure *out is NULL and error says where and why:
 * SC_ERR_SYNTAX, SC_ERR_LIMIT or SC_ERR_NOMEM. */
sc_status parse_text(const char *file, const char *text, size_t length, parse_tree **out,
                     sc_error *error);

void parse_tree_free(parse_tree *tree);

/* The end of the message of an error at OpenSCAD's language beyond its CSG
 * export, after what the file says there ("an assignment ('x = ...')"). */
#define PARSE_LANGUAGE " is OpenSCAD's language beyond its CSG export"

/* 1 when error is the parser's error at OpenSCAD's language beyond its
 * CSG export: the text is OpenSCAD source that OpenSCAD can convert. */
int parse_error_is_language(const sc_error *error);

/* The consumer of a streamed parse (parse_stream), called node by node in
 * file order. Each call gets the parser's error to fill; a status other
 * than SC_OK stops the parse with it. */
typedef struct parse_sink {
    void *user;
    /* A node's name, position, modifiers and arguments are read; its
     * children are not yet (child_count is 0 and grows as they come).
     * node->parent is its open parent (NULL at top level), whose syntax
     * lives until it closes. Setting *keep (read only outside a kept
     * subtree) keeps the node's subtree whole, children linked as
     * parse_text links them, until the node closes. */
    sc_status (*open)(void *user, parse_node *node, int *keep, sc_error *error);
    /* The node's last child is read: child_count is final. When close
     * returns, the node's syntax (arguments, values, children) is freed,
     * unless the node lies inside a kept subtree (below the kept node),
     * which is freed with the kept node. */
    sc_status (*close)(void *user, parse_node *node, sc_error *error);
    /* Optional: a split parse. When fork is set and the text has at least
     * split_min bytes (0: never), parse_stream reads it in two threads: a
     * second one finds a statement boundary near split_at (0: the middle)
     * in the list of some open node P (or at the top level) and reads
     * from there to P's '}' while the first reads up to the boundary.
     * fork makes the second part's consumer once the first thread has
     * opened P (depth: P's, 0 at the top level), or returns NULL when it
     * cannot (the first part's state does not allow it); the second
     * part's calls then go to it, with the same nodes and depths a whole
     * parse would give, P's syntax standing in as a copy. When the first
     * thread reaches the boundary, join appends the second part to user
     * and returns 1, or returns 0 when the two cannot be joined as one
     * parse would have made them; drop then frees the second consumer,
     * and the first thread reads the second part again itself. drop also
     * frees a part that failed or was never reached. So a split parse
     * calls the sink, in each part, as a whole parse would, and its
     * result and errors are a whole parse's. A split_at given is awaited:
     * the first thread reads on once the scan has found the boundary, so
     * that the split is made there (the tests' way to split at every
     * place). */
    void *(*fork)(void *user, uint32_t depth);
    int (*join)(void *user, void *forked);
    void (*drop)(void *forked);
    size_t split_min, split_at;
} parse_sink;

/* Parses text[0 .. length) as parse_text does, with the same errors at
 * the same positions, but hands every node to sink as it is read and
 * frees its syntax when it closes, so that memory stays that of the open
 * nodes (and the kept subtrees) rather than of the whole file. *out holds
 * only the names and strings (first is NULL), which outlive the nodes as
 * after parse_tree_release_nodes; free it with parse_tree_free. On failure
 * *out is NULL. */
sc_status parse_stream(const char *file, const char *text, size_t length,
                       const parse_sink *sink, parse_tree **out, sc_error *error);

/* Frees the tree's nodes, arguments and values, keeping its names and
 * strings (which a lowered model points to) until parse_tree_free. The
 * tree is then empty (first is NULL). Loading frees the syntax this way
 * once a model that no longer reads it is made. */
void parse_tree_release_nodes(parse_tree *tree);

/* The argument that sets parameter `name`, which also takes the position-th
 * positional argument (position < 0: by name only). When several set it,
 * the last in source order wins, as in OpenSCAD. NULL when none does. */
const parse_arg *parse_node_arg(const parse_node *node, const char *name, int position);

/* The next node after `node` in file order (depth-first, children first),
 * not descending into node's children when skip_children is set; NULL at
 * the end. Walks the tree without a stack. */
const parse_node *parse_next_node(const parse_node *node, int skip_children);

#endif
