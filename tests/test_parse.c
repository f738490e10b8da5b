/* Tests of the .csg parser (src/syntax/parse.c): the syntax tree (names,
 * modifiers, named and positional arguments, nested vectors, children,
 * positions), argument lookup, the nesting limits, and every parser error
 * message, exactly. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "syntax/parse.h"

static parse_tree *parse_ok(const char *text)
{
    parse_tree *t = NULL;
    sc_error e;
    sc_status st = parse_text("m.csg", text, strlen(text), &t, &e);
    if (st != SC_OK)
        fail_msg("unexpected error: %s", e.message);
    assert_non_null(t);
    return t;
}

/* A sink that records what a streamed parse hands it. */
typedef struct events {
    int opens, closes, kept_opens;
    uint32_t depth;         /* deepest node seen */
    uint32_t keep_depth;    /* keep nodes opened at this depth (0: none) */
    uint32_t top_children;  /* child_count of the last top-level node closed */
    const parse_node *kept; /* the kept node while open */
    uint32_t kept_linked;   /* its linked children, counted at its close */
} events;

static sc_status on_open(void *user, parse_node *node, int *keep, sc_error *error)
{
    (void)error;
    events *ev = user;
    ev->opens++;
    assert_int_equal(node->child_count, 0);
    assert_true(node->depth == 1 ? !node->parent : node->parent != NULL);
    if (node->depth > ev->depth)
        ev->depth = node->depth;
    if (ev->kept)
        ev->kept_opens++;
    if (node->depth == ev->keep_depth && !ev->kept) {
        *keep = 1;
        ev->kept = node;
    }
    return SC_OK;
}

static sc_status on_close(void *user, parse_node *node, sc_error *error)
{
    (void)error;
    events *ev = user;
    ev->closes++;
    if (node->depth == 1)
        ev->top_children = node->child_count;
    if (node == ev->kept) {
        for (const parse_node *c = node->first_child; c; c = c->next)
            ev->kept_linked++;
        ev->kept = NULL;
    }
    return SC_OK;
}

static parse_tree *stream(const char *text, events *ev, sc_status *st, sc_error *e)
{
    parse_sink sink = {.user = ev, .open = on_open, .close = on_close};
    parse_tree *t = (parse_tree *)1;
    *st = parse_stream("m.csg", text, strlen(text), &sink, &t, e);
    return t;
}

/* text fails with the message expected, read whole and streamed. */
static void check_error_status(const char *text, sc_status status, const char *expected)
{
    parse_tree *t = (parse_tree *)1;
    sc_error e;
    assert_int_equal(parse_text("m.csg", text, strlen(text), &t, &e), status);
    assert_null(t);
    char buf[1024];
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
    events ev = {0};
    sc_status st;
    assert_null(stream(text, &ev, &st, &e));
    assert_int_equal(st, status);
    assert_string_equal(sc_error_format(&e, buf, sizeof buf), expected);
}

static void check_error(const char *text, const char *expected)
{
    check_error_status(text, SC_ERR_SYNTAX, expected);
}

static void test_empty(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("  // nothing\n ; ;");
    assert_null(t->first);
    assert_int_equal(t->count, 0);
    assert_int_equal(t->node_count, 0);
    parse_tree_free(t);
}

static void test_openscad_export(void **state)
{
    (void)state;
    /* As OpenSCAD 2021.01 writes it. */
    parse_tree *t = parse_ok(
        "group() {\n"
        "\tmultmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
        "\t\tcylinder($fn = 0, $fa = 12, $fs = 2, h = 10, r1 = 2, r2 = 2, center = "
        "false);\n"
        "\t}\n"
        "\tcolor([1, 0, 0, 1]) {\n"
        "\t\tcube(size = [1, 2, 3], center = true);\n"
        "\t}\n"
        "\tgroup();\n"
        "}\n");
    assert_int_equal(t->count, 1);
    assert_int_equal(t->node_count, 6);
    const parse_node *g = t->first;
    assert_string_equal(g->name, "group");
    assert_int_equal(g->arg_count, 0);
    assert_int_equal(g->child_count, 3);
    assert_true(g->has_block);
    assert_int_equal(g->block_line, 1);
    assert_int_equal(g->depth, 1);
    assert_null(g->parent);

    const parse_node *mm = g->first_child;
    assert_string_equal(mm->name, "multmatrix");
    assert_int_equal(mm->loc.line, 2);
    assert_int_equal(mm->loc.column, 2);
    assert_string_equal(mm->loc.file, "m.csg");
    assert_int_equal(mm->arg_count, 1);
    assert_null(mm->args[0].name);
    const parse_value *m = &mm->args[0].value;
    assert_int_equal(m->kind, PARSE_VECTOR);
    assert_int_equal(m->u.vector.count, 4);
    assert_int_equal(m->line, 2);
    assert_int_equal(m->column, 13);
    assert_int_equal(m->u.vector.items[0].kind, PARSE_VECTOR);
    assert_int_equal(m->u.vector.items[0].u.vector.count, 4);
    assert_true(m->u.vector.items[0].u.vector.items[3].u.number == 10);
    assert_int_equal(m->u.vector.items[0].u.vector.items[3].column, 24);
    assert_true(m->u.vector.items[3].u.vector.items[3].u.number == 1);
    assert_ptr_equal(mm->parent, g);
    assert_int_equal(mm->depth, 2);

    const parse_node *cyl = mm->first_child;
    assert_string_equal(cyl->name, "cylinder");
    assert_int_equal(cyl->depth, 3);
    assert_false(cyl->has_block);
    assert_int_equal(cyl->arg_count, 7);
    assert_string_equal(cyl->args[0].name, "$fn");
    assert_int_equal(cyl->args[0].loc.column, 12);
    assert_string_equal(cyl->args[6].name, "center");
    assert_int_equal(cyl->args[6].value.kind, PARSE_BOOL);
    assert_false(cyl->args[6].value.u.boolean);

    const parse_node *col = mm->next;
    assert_string_equal(col->name, "color");
    assert_int_equal(col->child_count, 1);
    const parse_node *empty = col->next;
    assert_string_equal(empty->name, "group");
    assert_false(empty->has_block);
    assert_int_equal(empty->child_count, 0);
    assert_null(empty->next);
    parse_tree_free(t);
}

/* A name is stored once however often the file writes it; strings keep
 * their text as written (for positions inside them) beside the decoded
 * one; releasing the nodes keeps both. */
static void test_names_and_strings_outlive_nodes(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("sphere($fn = 0, r = 1);\n"
                             "sphere($fn = 0, s = \"a\\tb\\u00e9\");\n"
                             "group() { sphere(r = 2); }");
    const parse_node *a = t->first, *b = a->next, *c = b->next->first_child;
    assert_ptr_equal(a->name, b->name);
    assert_ptr_equal(a->name, c->name);
    assert_ptr_equal(a->args[0].name, b->args[0].name);
    assert_ptr_equal(a->args[1].name, c->args[0].name);
    assert_ptr_not_equal(a->name, b->next->name);
    /* Names that share a slot of the parser's recent names (the same
     * length, first and last bytes: "ab" and "ba", "axb" and "ayb") are
     * still told apart, each stored once. */
    parse_tree *u =
        parse_ok("n(ab = 1, ba = 2, ab = 3, axb = 4, ayb = 5, ba = 6, axb = 7);");
    const parse_arg *args = u->first->args;
    static const char *const want[] = {"ab", "ba", "ab", "axb", "ayb", "ba", "axb"};
    for (int i = 0; i < 7; i++)
        assert_string_equal(args[i].name, want[i]);
    assert_ptr_equal(args[0].name, args[2].name);
    assert_ptr_equal(args[1].name, args[5].name);
    assert_ptr_equal(args[3].name, args[6].name);
    assert_ptr_not_equal(args[0].name, args[1].name);
    assert_ptr_not_equal(args[3].name, args[4].name);
    parse_tree_free(u);
    const parse_value *s = &b->args[1].value;
    assert_int_equal(s->kind, PARSE_STRING);
    assert_string_equal(s->u.string.chars, "a\tb\xc3\xa9");
    assert_int_equal(s->u.string.length, 5);
    assert_int_equal(s->u.string.raw_length, 10);
    assert_string_equal(parse_string_raw(s), "a\\tb\\u00e9");
    const char *name = a->name, *arg = a->args[1].name, *chars = s->u.string.chars;
    parse_tree_release_nodes(t);
    assert_null(t->first);
    assert_int_equal(t->count, 0);
    assert_string_equal(name, "sphere");
    assert_string_equal(arg, "r");
    assert_string_equal(chars, "a\tb\xc3\xa9");
    parse_tree_release_nodes(t); /* twice is harmless */
    parse_tree_free(t);
}

static void test_values(void **state)
{
    (void)state;
    parse_tree *t =
        parse_ok("n(1, -2.5e-1, \"s\\n\", true, false, undef, [], [[]], [1, [2, "
                 "[3]],], x = [1, 2, ],);");
    const parse_node *n = t->first;
    assert_int_equal(n->arg_count, 10);
    assert_int_equal(n->args[0].value.kind, PARSE_NUMBER);
    assert_true(n->args[1].value.u.number == -0.25);
    assert_int_equal(n->args[2].value.kind, PARSE_STRING);
    assert_string_equal(n->args[2].value.u.string.chars, "s\n");
    assert_int_equal(n->args[2].value.u.string.length, 2);
    assert_true(n->args[3].value.kind == PARSE_BOOL && n->args[3].value.u.boolean);
    assert_true(n->args[4].value.kind == PARSE_BOOL && !n->args[4].value.u.boolean);
    assert_int_equal(n->args[5].value.kind, PARSE_UNDEF);
    assert_int_equal(n->args[6].value.kind, PARSE_VECTOR);
    assert_int_equal(n->args[6].value.u.vector.count, 0);
    assert_int_equal(n->args[7].value.u.vector.count, 1);
    assert_int_equal(n->args[7].value.u.vector.items[0].u.vector.count, 0);
    const parse_value *v = &n->args[8].value;
    assert_int_equal(v->u.vector.count, 2);
    const parse_value *inner = &v->u.vector.items[1];
    assert_int_equal(inner->u.vector.count, 2);
    assert_true(inner->u.vector.items[0].u.number == 2);
    assert_int_equal(inner->u.vector.items[1].u.vector.count, 1);
    assert_true(inner->u.vector.items[1].u.vector.items[0].u.number == 3);
    assert_string_equal(n->args[9].name, "x");
    assert_int_equal(n->args[9].value.u.vector.count, 2);
    parse_tree_free(t);
}

static void test_modifiers(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("%a(); #b(); !c(); *d(); #%e(); * ! # % f(); g();");
    const unsigned expected[] = {PARSE_MOD_BACKGROUND,
                                 PARSE_MOD_HIGHLIGHT,
                                 PARSE_MOD_ROOT,
                                 PARSE_MOD_DISABLE,
                                 PARSE_MOD_HIGHLIGHT | PARSE_MOD_BACKGROUND,
                                 PARSE_MOD_DISABLE | PARSE_MOD_ROOT |
                                     PARSE_MOD_HIGHLIGHT | PARSE_MOD_BACKGROUND,
                                 0};
    const parse_node *n = t->first;
    for (int i = 0; i < 7; i++, n = n->next) {
        assert_non_null(n);
        assert_int_equal(n->modifiers, expected[i]);
    }
    assert_null(n);
    /* The node's position is its name's, after the modifiers. */
    assert_int_equal(t->first->next->next->next->next->loc.column, 27);
    parse_tree_free(t);
}

static void test_arg_lookup(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("cylinder(5, 1, r2 = 3, h = 7, 9, h = 8, center = true);");
    const parse_node *n = t->first;
    const parse_arg *h = parse_node_arg(n, "h", 0);
    assert_non_null(h);
    assert_true(h->value.u.number == 8); /* the last of three wins */
    assert_true(parse_node_arg(n, "r1", 1)->value.u.number == 1);
    assert_true(parse_node_arg(n, "r2", 2)->value.u.number == 9); /* positional after */
    assert_null(parse_node_arg(n, "r", -1));
    assert_null(parse_node_arg(n, "x", 5));
    assert_true(parse_node_arg(n, "center", 3)->value.u.boolean);
    parse_tree_free(t);
}

static void test_next_node(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("a() { b() { c(); } d(); } e() { f(); }");
    const char *order = "abcdef";
    const parse_node *n = t->first;
    for (int i = 0; i < 6; i++, n = parse_next_node(n, 0))
        assert_int_equal(n->name[0], order[i]);
    assert_null(n);
    n = parse_next_node(t->first->first_child, 1); /* skip c */
    assert_string_equal(n->name, "d");
    assert_null(parse_next_node(t->first->next, 1));
    parse_tree_free(t);
}

static void test_empty_block(void **state)
{
    (void)state;
    parse_tree *t = parse_ok("union() { }\nunion() {}");
    assert_true(t->first->has_block);
    assert_int_equal(t->first->child_count, 0);
    assert_int_equal(t->count, 2);
    parse_tree_free(t);
}

/* n levels of "group() {", a cube, then n "}". */
static char *nested(int n, const char *open, const char *leaf, const char *close)
{
    size_t lo = strlen(open), ll = strlen(leaf), lc = strlen(close);
    char *s = malloc((size_t)n * (lo + lc) + ll + 1);
    assert_non_null(s);
    char *p = s;
    for (int i = 0; i < n; i++, p += lo)
        memcpy(p, open, lo);
    memcpy(p, leaf, ll);
    p += ll;
    for (int i = 0; i < n; i++, p += lc)
        memcpy(p, close, lc);
    *p = '\0';
    return s;
}

/* The tree as text: each node as NAME/MODIFIERS/ARGUMENTS(CHILDREN), for
 * comparing the forms of one tree. */
static void shape(const parse_node *n, char *out, size_t size)
{
    for (; n; n = n->next) {
        size_t used = strlen(out);
        snprintf(out + used, size - used, "%s/%u/%u(", n->name, n->modifiers,
                 n->arg_count);
        shape(n->first_child, out, size);
        used = strlen(out);
        snprintf(out + used, size - used, ")");
    }
}

/* a and b parse to the same tree, whole and streamed (the same number of
 * nodes opened and closed, the same top-level child count). */
static void check_same(const char *a, const char *b)
{
    char sa[1024] = "", sb[1024] = "";
    parse_tree *ta = parse_ok(a), *tb = parse_ok(b);
    shape(ta->first, sa, sizeof sa);
    shape(tb->first, sb, sizeof sb);
    assert_string_equal(sa, sb);
    assert_int_equal(ta->count, tb->count);
    assert_int_equal(ta->node_count, tb->node_count);
    parse_tree_free(ta);
    parse_tree_free(tb);
    events ea = {0}, eb = {0};
    sc_status st;
    sc_error e;
    parse_tree_free(stream(a, &ea, &st, &e));
    assert_int_equal(st, SC_OK);
    parse_tree_free(stream(b, &eb, &st, &e));
    assert_int_equal(st, SC_OK);
    assert_int_equal(ea.opens, eb.opens);
    assert_int_equal(ea.closes, eb.closes);
    assert_int_equal(ea.opens, ea.closes);
    assert_int_equal(ea.top_children, eb.top_children);
}

/* OpenSCAD's grammar: a node's child statement may be one node without
 * braces, a block, or ';'; a block after no node and ';' alone are
 * statements of the enclosing node. */
static void test_braceless(void **state)
{
    (void)state;
    check_same("multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]) cube(1);",
               "multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]) { cube(1); }");
    check_same("color(\"red\", 0.5) sphere(5);", "color(\"red\", 0.5) { sphere(5); }");
    check_same(
        "group() multmatrix(m = []) color(\"red\") cube(1); sphere(2);",
        "group() { multmatrix(m = []) { color(\"red\") { cube(1); } } } sphere(2);");
    check_same(
        "difference() { cube(2); multmatrix([]) cylinder(h = 3); sphere(1); }",
        "difference() { cube(2); multmatrix([]) { cylinder(h = 3); } sphere(1); }");
    check_same("union() { { cube(1); { sphere(1); } } ; ; } ;; {} {;}",
               "union() { cube(1); sphere(1); }");
    check_same("{ cube(1); } sphere(2);", "cube(1); sphere(2);");
    check_same("group() ;", "group() { }");
    check_same("#multmatrix([]) %cube(1);", "#multmatrix([]) { %cube(1); }");
    check_same("!group() *cube(1); #%sphere(1);", "!group() { *cube(1); } #%sphere(1);");
    check_same("cube(1) sphere(2);", "cube(1) { sphere(2); }");
    parse_tree *t = parse_ok("multmatrix([]) cube(1);");
    assert_false(t->first->has_block);
    assert_int_equal(t->first->child_count, 1);
    assert_ptr_equal(t->first->first_child->parent, t->first);
    parse_tree_free(t);
    /* A chain without braces is as deep as the limit allows, without
     * recursion, and one level more is the limit's error. */
    char *text = nested(PARSE_MAX_DEPTH - 1, "group() ", "cube();", "");
    t = parse_ok(text);
    assert_int_equal(t->node_count, PARSE_MAX_DEPTH);
    parse_tree_free(t);
    free(text);
    text = nested(PARSE_MAX_DEPTH, "group() ", "cube();", "");
    check_error_status(text, SC_ERR_LIMIT,
                       "m.csg:1:80001: error: too many nested nodes (limit is 10000)");
    free(text);
    text = nested(PARSE_MAX_DEPTH + 1, "{", "", "}");
    check_error_status(text, SC_ERR_LIMIT,
                       "m.csg:1:10001: error: too many nested blocks (limit is 10000)");
    free(text);
}

static void check_language(const char *text, const char *expected)
{
    check_error_status(text, SC_ERR_UNSUPPORTED, expected);
    parse_tree *t = NULL;
    sc_error e;
    assert_int_equal(parse_text("m.csg", text, strlen(text), &t, &e), SC_ERR_UNSUPPORTED);
    assert_true(parse_error_is_language(&e));
}

/* Where a file goes on in OpenSCAD's language, the error says so, at the
 * first place the CSG grammar ends; a plain syntax error does not. */
static void test_language(void **state)
{
    (void)state;
    const char *tail = " is OpenSCAD's language beyond its CSG export";
    char want[256];
#define LANGUAGE(text, pos, what)                                                        \
    do {                                                                                 \
        snprintf(want, sizeof want, "m.csg:%s: error: %s%s", pos, what, tail);           \
        check_language(text, want);                                                      \
    } while (0)
    LANGUAGE("cube(1);\nsize = 2;", "2:1", "an assignment ('size = ...')");
    LANGUAGE("$fn = 32;", "1:1", "an assignment ('$fn = ...')");
    LANGUAGE("module m() { cube(1); }", "1:1", "'module'");
    LANGUAGE("function f(x) = x;", "1:1", "'function'");
    LANGUAGE("include <lib.scad>", "1:1", "'include'");
    LANGUAGE("use <lib.scad>\ncube(1);", "1:1", "'use'");
    LANGUAGE("group() for (i = [1, 2]) cube(1);", "1:9", "'for'");
    LANGUAGE("if (true) cube(1);", "1:1", "'if'");
    LANGUAGE("translate([1, 0, 0]) rotate(45) cube(1);", "1:1", "'translate'");
    /* written by the export as the intersection, import or extrusion
     * they make */
    LANGUAGE("intersection_for(i = [0, 1]) cube(2);", "1:1", "'intersection_for'");
    LANGUAGE("child(0);", "1:1", "'child'");
    LANGUAGE("group() import_stl(\"a.stl\");", "1:9", "'import_stl'");
    LANGUAGE("import_off(\"a.off\");", "1:1", "'import_off'");
    LANGUAGE("linear_extrude(height = 2) import_dxf(file = \"a.dxf\");", "1:28",
             "'import_dxf'");
    LANGUAGE("dxf_linear_extrude(file = \"a.dxf\", height = 2);", "1:1",
             "'dxf_linear_extrude'");
    LANGUAGE("dxf_rotate_extrude(file = \"a.dxf\");", "1:1", "'dxf_rotate_extrude'");
    LANGUAGE("cube(size);", "1:6", "a variable or function ('size')");
    LANGUAGE("cube(size, center = true);", "1:6", "a variable or function ('size')");
    LANGUAGE("cube(size = s);", "1:13", "a variable or function ('s')");
    LANGUAGE("cube(f(2));", "1:6", "a variable or function ('f')");
    LANGUAGE("cube([1, 2, x]);", "1:13", "a variable or function ('x')");
    /* OpenSCAD's names may start with digits (its lexer's longest match) */
    LANGUAGE("cube(1e);", "1:6", "a variable or function ('1e')");
    LANGUAGE("cube([0x10, 1, 1]);", "1:7", "a variable or function ('0x10')");
    LANGUAGE("cube(-1e);", "1:6", "an operator ('-')");
    LANGUAGE("cube(2 * 3);", "1:8", "an expression ('*')");
    LANGUAGE("cube([1, 2] * 3);", "1:13", "an expression ('*')");
    LANGUAGE("cube([1, 2 % 3]);", "1:12", "an expression ('%')");
    LANGUAGE("cube((2));", "1:6", "an expression ('(')");
    LANGUAGE("cube(1 + 2);", "1:8", "an operator ('+')");
    LANGUAGE("cube(-s);", "1:6", "an operator ('-')");
    LANGUAGE("cube(a < 2);", "1:8", "an operator ('<')");
    LANGUAGE("cube(1 < 2);", "1:8", "an operator ('<')");
    LANGUAGE("a(v = [0 : 3]);", "1:10", "an operator (':')");
    LANGUAGE("a(v = [1, 2][0]);", "1:13", "an expression ('[')");
#undef LANGUAGE
    /* Plain syntax errors stay syntax errors. */
    check_error("cube(1;", "m.csg:1:7: error: expected ')' (to close '(' at line 1)");
    check_error("cube(1) }", "m.csg:1:9: error: expected ';', '{' or a child node after "
                             "node 'cube'");
    check_error("cube(@);", "m.csg:1:6: error: unexpected character '@'");
}

static void test_deep_nodes(void **state)
{
    (void)state;
    char *text = nested(PARSE_MAX_DEPTH - 1, "group(){", "cube();", "}");
    parse_tree *t = parse_ok(text);
    assert_int_equal(t->node_count, PARSE_MAX_DEPTH);
    const parse_node *n = t->first;
    while (n->first_child)
        n = n->first_child;
    assert_int_equal(n->depth, PARSE_MAX_DEPTH);
    parse_tree_free(t);
    free(text);

    text = nested(PARSE_MAX_DEPTH, "group(){", "cube();", "}");
    check_error_status(text, SC_ERR_LIMIT,
                       "m.csg:1:80001: error: too many nested nodes (limit is 10000)");
    free(text);
}

static void test_deep_vectors(void **state)
{
    (void)state;
    char *text = nested(PARSE_MAX_DEPTH, "[", "1", "]");
    size_t n = strlen(text);
    char *call = malloc(n + 8);
    memcpy(call, "a(", 2);
    memcpy(call + 2, text, n);
    memcpy(call + 2 + n, ");", 3);
    parse_tree *t = parse_ok(call);
    const parse_value *v = &t->first->args[0].value;
    int depth = 0;
    while (v->kind == PARSE_VECTOR) {
        v = &v->u.vector.items[0];
        depth++;
    }
    assert_int_equal(depth, PARSE_MAX_DEPTH);
    assert_true(v->u.number == 1);
    parse_tree_free(t);
    free(call);
    free(text);

    text = nested(PARSE_MAX_DEPTH + 1, "[", "1", "]");
    n = strlen(text);
    call = malloc(n + 8);
    memcpy(call, "a(", 2);
    memcpy(call + 2, text, n);
    memcpy(call + 2 + n, ");", 3);
    check_error_status(call, SC_ERR_LIMIT,
                       "m.csg:1:10003: error: too many nested vectors (limit is 10000)");
    free(call);
    free(text);
}

static void test_errors(void **state)
{
    (void)state;
    check_error("cube(size = 1;",
                "m.csg:1:14: error: expected ')' (to close '(' at line 1)");
    check_error("group() {\n"
                "  multmatrix(\n"
                "    m = [[1, 0, 0, 0]]\n"
                "    x = 1) {}\n"
                "}",
                "m.csg:4:5: error: expected ')' (to close '(' at line 2)");
    check_error("a(m = [[1, 2], [3, 4]);",
                "m.csg:1:22: error: expected ']' (to close '[' at line 1)");
    check_error("a(m = [1\n2]);",
                "m.csg:2:1: error: expected ']' (to close '[' at line 1)");
    check_error("group() {\n  cube();\n",
                "m.csg:3:1: error: expected '}' (to close '{' at line 1)");
    check_error("cube();\n}", "m.csg:2:1: error: unmatched '}'");
    check_error("# { cube(); }", "m.csg:1:3: error: expected a node name before '{'");
    check_error("cube(); 5;", "m.csg:1:9: error: expected a node name, found a number");
    check_error("%", "m.csg:1:2: error: expected a node name, found end of file");
    check_error("cube(); = 1", "m.csg:1:9: error: expected a node name, found '='");
    check_error("cube;", "m.csg:1:5: error: expected '(' after node name 'cube'");
    check_error("cube()",
                "m.csg:1:7: error: expected ';', '{' or a child node after node 'cube'");
    check_error("cube() 5;",
                "m.csg:1:8: error: expected ';', '{' or a child node after node 'cube'");
    check_error("group() multmatrix([]) }", "m.csg:1:24: error: expected ';', '{' or a "
                                            "child node after node 'multmatrix'");
    check_error("{ cube(); ", "m.csg:1:11: error: expected '}' (to close '{' at line 1)");
    check_error("cube(size = );", "m.csg:1:13: error: expected a value, found ')'");
    check_error("cube(, 1);", "m.csg:1:6: error: expected a value, found ','");
    check_error("a([1, , 2]);", "m.csg:1:7: error: expected a value, found ','");
    check_error("a([1, 2", "m.csg:1:8: error: expected ']' (to close '[' at line 1)");
    check_error("a(x 1);", "m.csg:1:5: error: expected '=' after argument name 'x'");
    check_error("a(", "m.csg:1:3: error: expected a value, found end of file");
    /* Lexer errors come through unchanged. */
    check_error("cube(size = @);", "m.csg:1:13: error: unexpected character '@'");
    check_error("text(t = \"abc);", "m.csg:1:10: error: unterminated string");
}

/* Vectors of numbers take a fast path past the tokens (fast_vector in
 * parse.c) that must make the very values the token path makes. Random
 * nested vectors, some deeper than the fast path goes, with random blanks,
 * trailing commas, and now and then a line break or a comment that sends
 * them down the token path, are checked value by value against what the
 * generator wrote: kind, item count, line and column, and each number
 * against strtod of its text, bit for bit. */
typedef struct written {
    int vector; /* 1: a vector of count items; 0: a number */
    int line, column;
    uint32_t count;
    double number;
} written;

typedef struct writer {
    char *text;
    size_t length, cap;
    int line;
    size_t line_start;
    written *values;
    size_t count, cap_values;
    uint64_t r;
} writer;

static uint64_t next_random(writer *w)
{
    w->r ^= w->r << 13;
    w->r ^= w->r >> 7;
    w->r ^= w->r << 17;
    return w->r;
}

static void put(writer *w, const char *s)
{
    size_t n = strlen(s);
    if (w->length + n + 1 > w->cap) {
        w->cap = 2 * (w->length + n + 1);
        w->text = realloc(w->text, w->cap);
        assert_non_null(w->text);
    }
    for (size_t i = 0; i < n; i++) {
        w->text[w->length++] = s[i];
        if (s[i] == '\n') {
            w->line++;
            w->line_start = w->length;
        }
    }
    w->text[w->length] = '\0';
}

static size_t record(writer *w, int vector)
{
    if (w->count == w->cap_values) {
        w->cap_values = w->cap_values ? 2 * w->cap_values : 256;
        w->values = realloc(w->values, w->cap_values * sizeof *w->values);
        assert_non_null(w->values);
    }
    written *v = &w->values[w->count];
    memset(v, 0, sizeof *v);
    v->vector = vector;
    v->line = w->line;
    v->column = (int)(w->length - w->line_start) + 1;
    return w->count++;
}

static void blank(writer *w)
{
    static const char *const blanks[] = {"", " ", "", "  ", "\t", " \r", "\n", "/* c */"};
    uint64_t k = next_random(w) % 64;
    /* Line breaks and comments rarely, so most vectors stay fast. */
    put(w, blanks[k < 56 ? k % 6 : 6 + k % 2]);
}

static void write_number(writer *w)
{
    char text[64];
    uint64_t q = next_random(w);
    int len = 0;
    if (q % 5 == 0) {
        /* OpenSCAD's %g of a random double. */
        double x;
        uint64_t bits = next_random(w);
        memcpy(&x, &bits, sizeof x);
        len = snprintf(text, sizeof text, "%g", isfinite(x) ? x : 0.5);
    } else {
        int digits = 1 + (int)(q % 19);
        q /= 19;
        int point = (int)(q % (uint64_t)(digits + 1)) - 1; /* -1: no point */
        q /= (uint64_t)(digits + 1);
        if (q % 3 == 0)
            text[len++] = '-';
        q /= 3;
        for (int k = 0; k < digits; k++) {
            if (k == point && k > 0)
                text[len++] = '.';
            text[len++] = (char)('0' + q % 10);
            q = q / 10 ^ (q << 7);
        }
        if (next_random(w) % 4 == 0)
            len += snprintf(text + len, sizeof text - (size_t)len, "e%d",
                            (int)(next_random(w) % 61) - 30);
        text[len] = '\0';
    }
    size_t at = record(w, 0);
    w->values[at].number = strtod(text, NULL);
    put(w, text);
}

static void write_vector(writer *w, int depth)
{
    size_t at = record(w, 1);
    put(w, "[");
    uint32_t count = (uint32_t)(next_random(w) % 5);
    for (uint32_t i = 0; i < count; i++) {
        blank(w);
        if (depth < 20 && next_random(w) % 3 == 0)
            write_vector(w, depth + 1);
        else
            write_number(w);
        blank(w);
        if (i + 1 < count || next_random(w) % 8 == 0)
            put(w, ",");
    }
    blank(w);
    put(w, "]");
    w->values[at].count = count;
}

/* Checks v and its items in the generator's order from *k. */
static void check_written(const writer *w, const parse_value *v, size_t *k)
{
    assert_true(*k < w->count);
    const written *want = &w->values[(*k)++];
    assert_int_equal(v->line, want->line);
    assert_int_equal(v->column, want->column);
    if (!want->vector) {
        assert_int_equal(v->kind, PARSE_NUMBER);
        if (memcmp(&v->u.number, &want->number, sizeof want->number) != 0)
            fail_msg("line %d column %d: %.17g, strtod %.17g", v->line, v->column,
                     v->u.number, want->number);
        return;
    }
    assert_int_equal(v->kind, PARSE_VECTOR);
    assert_int_equal(v->u.vector.count, want->count);
    for (uint32_t i = 0; i < v->u.vector.count; i++)
        check_written(w, &v->u.vector.items[i], k);
}

static void test_number_vectors(void **state)
{
    (void)state;
    for (int round = 0; round < 400; round++) {
        writer w = {0};
        w.line = 1;
        w.r = 0x2545f4914f6cdd1dULL + (uint64_t)round * 0x9e3779b97f4a7c15ULL;
        put(&w, "a(");
        int args = 1 + (int)(next_random(&w) % 4);
        for (int i = 0; i < args; i++) {
            put(&w, i ? ", v = " : "v = ");
            write_vector(&w, 0);
        }
        put(&w, ");\n");
        parse_tree *t = parse_ok(w.text);
        assert_int_equal(t->first->arg_count, (uint32_t)args);
        size_t k = 0;
        for (int i = 0; i < args; i++)
            check_written(&w, &t->first->args[i].value, &k);
        assert_int_equal(k, w.count);
        parse_tree_free(t);
        free(w.text);
        free(w.values);
    }
    /* What the fast path gives up on reads as before: errors at the same
     * places, and the values around them. */
    check_error("a(m = [[1, 2], [3, 4 5]]);",
                "m.csg:1:22: error: expected ']' (to close '[' at line 1)");
    check_error("a(m = [1, 2.5.]);", "m.csg:1:11: error: malformed number '2.5.'");
    check_error("a(m = [1, 1e999]);", "m.csg:1:11: error: number out of range '1e999'");
    check_language("a(m = [1, - 2]);",
                   "m.csg:1:11: error: an operator ('-') is OpenSCAD's "
                   "language beyond its CSG export");
    check_error("a(m = [[1, 2]",
                "m.csg:1:14: error: expected ']' (to close '[' at line 1)");
    parse_tree *t = parse_ok("a(m = [1, inf, [-nan], \"s\", [2, true]]);");
    const parse_value *m = &t->first->args[0].value;
    assert_int_equal(m->u.vector.count, 5);
    assert_true(isinf(m->u.vector.items[1].u.number));
    assert_true(isnan(m->u.vector.items[2].u.vector.items[0].u.number));
    assert_int_equal(m->u.vector.items[3].kind, PARSE_STRING);
    assert_int_equal(m->u.vector.items[4].u.vector.items[1].kind, PARSE_BOOL);
    assert_int_equal(m->u.vector.items[4].column, 29);
    parse_tree_free(t);
}

/* Named number arguments (`r = 0.6`) take a fast path past the tokens
 * too (fast_named_number in parse.c). Random argument lists of named
 * numbers and vectors, with random blanks, now and then a line break or
 * a comment (the token path) and a trailing comma, must give each
 * argument its name, the name's position, and the value the generator
 * wrote, at its line and column, bit for bit. */
static void test_named_numbers(void **state)
{
    (void)state;
    static const char *const names[] = {"r", "$fn", "$fa", "$fs", "h", "center_x"};
    for (int round = 0; round < 400; round++) {
        writer w = {0};
        w.line = 1;
        w.r = 0x9e3779b97f4a7c15ULL + (uint64_t)round * 0x2545f4914f6cdd1dULL;
        put(&w, "a(");
        int args = 1 + (int)(next_random(&w) % 5);
        int name_line[5], name_column[5];
        const char *name[5];
        for (int i = 0; i < args; i++) {
            if (i)
                put(&w, ",");
            blank(&w);
            name[i] = names[next_random(&w) % 6];
            name_line[i] = w.line;
            name_column[i] = (int)(w.length - w.line_start) + 1;
            put(&w, name[i]);
            blank(&w);
            put(&w, "=");
            blank(&w);
            if (next_random(&w) % 4 == 0)
                write_vector(&w, 0);
            else
                write_number(&w);
            blank(&w);
        }
        if (next_random(&w) % 8 == 0)
            put(&w, ",");
        put(&w, ");\n");
        parse_tree *t = parse_ok(w.text);
        assert_int_equal(t->first->arg_count, (uint32_t)args);
        size_t k = 0;
        for (int i = 0; i < args; i++) {
            const parse_arg *a = &t->first->args[i];
            assert_string_equal(a->name, name[i]);
            assert_int_equal(a->loc.line, name_line[i]);
            assert_int_equal(a->loc.column, name_column[i]);
            check_written(&w, &a->value, &k);
        }
        assert_int_equal(k, w.count);
        parse_tree_free(t);
        free(w.text);
        free(w.values);
    }
    /* What the fast path gives up on reads as before: errors at the same
     * places. */
    check_error("a(r = 1 2);", "m.csg:1:9: error: expected ')' (to close '(' at line 1)");
    check_error("a(r = 1.5.);", "m.csg:1:7: error: malformed number '1.5.'");
    check_error("a(r = 1e999);", "m.csg:1:7: error: number out of range '1e999'");
    check_language("a(r = 1x);", "m.csg:1:7: error: a variable or function ('1x') is "
                                 "OpenSCAD's language beyond its CSG export");
    check_error("a(r = 1, s = 2",
                "m.csg:1:15: error: expected ')' (to close '(' at line 1)");
    check_error("a(r = 1,, s = 2);", "m.csg:1:9: error: expected a value, found ','");
    check_error("a(r = 1)", "m.csg:1:9: error: expected ';', '{' or a child node after "
                            "node 'a'");
    check_error("a(r = 1 ,$fn=2 ) b(r = 7 @);",
                "m.csg:1:26: error: unexpected character '@'");
    check_language("a(r = 1 * 2);", "m.csg:1:9: error: an expression ('*') is "
                                    "OpenSCAD's language beyond its CSG export");
    check_language("a(r = - 1);", "m.csg:1:7: error: an operator ('-') is OpenSCAD's "
                                  "language beyond its CSG export");
    parse_tree *t = parse_ok("a(r = -inf, s = nan,t=1);");
    assert_int_equal(t->first->arg_count, 3);
    assert_true(isinf(t->first->args[0].value.u.number));
    assert_true(isnan(t->first->args[1].value.u.number));
    assert_int_equal(t->first->args[2].value.column, 23);
    parse_tree_free(t);
}

/* A streamed parse hands over every node once opened and once closed,
 * with its final child count; a kept subtree is linked as parse_text
 * links it; and a closed node's memory is reused, so that a union of
 * 10^5 spheres takes one block of the arena where the whole tree takes
 * hundreds. */
static void test_stream(void **state)
{
    (void)state;
    events ev = {0};
    sc_status st;
    sc_error e;
    parse_tree *t = stream("union() { group() { cube(); sphere(); } cube(); }\n"
                           "%sphere(r = 1, \"s\");\n",
                           &ev, &st, &e);
    assert_int_equal(st, SC_OK);
    assert_int_equal(ev.opens, 6);
    assert_int_equal(ev.closes, 6);
    assert_int_equal(ev.depth, 3);
    assert_int_equal(ev.top_children, 0); /* the sphere */
    assert_null(t->first);
    assert_int_equal(t->count, 2);
    assert_int_equal(t->node_count, 6);
    parse_tree_free(t);

    memset(&ev, 0, sizeof ev);
    ev.keep_depth = 2;
    t = stream("union() { group() { cube(); sphere() { cube(); } } cube(); }", &ev, &st,
               &e);
    assert_int_equal(st, SC_OK);
    assert_int_equal(ev.kept_opens, 3); /* below the kept group */
    assert_int_equal(ev.kept_linked, 2);
    assert_int_equal(ev.top_children, 2);
    parse_tree_free(t);

    size_t n = 100000, len = 0;
    const char *leaf = "multmatrix([[1, 0, 0, 2], [0, 1, 0, 3], [0, 0, 1, 4], [0, 0, 0, "
                       "1]]) { sphere($fn = 0, $fa = 12, $fs = 2, r = 0.6); }\n";
    size_t leaf_len = strlen(leaf);
    char *text = malloc(n * leaf_len + 32);
    assert_non_null(text);
    len += (size_t)sprintf(text, "union() {\n");
    for (size_t i = 0; i < n; i++, len += leaf_len)
        memcpy(text + len, leaf, leaf_len);
    memcpy(text + len, "}\n", 3);
    memset(&ev, 0, sizeof ev);
    t = stream(text, &ev, &st, &e);
    assert_int_equal(st, SC_OK);
    assert_int_equal(ev.top_children, n);
    assert_int_equal(t->mem.block_allocs, 1);
    parse_tree_free(t);
    assert_int_equal(parse_text("m.csg", text, strlen(text), &t, &e), SC_OK);
    assert_true(t->mem.block_allocs > 100);
    parse_tree_free(t);
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_names_and_strings_outlive_nodes),
        cmocka_unit_test(test_empty),
        cmocka_unit_test(test_openscad_export),
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_modifiers),
        cmocka_unit_test(test_arg_lookup),
        cmocka_unit_test(test_next_node),
        cmocka_unit_test(test_empty_block),
        cmocka_unit_test(test_deep_nodes),
        cmocka_unit_test(test_deep_vectors),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_braceless),
        cmocka_unit_test(test_language),
        cmocka_unit_test(test_stream),
        cmocka_unit_test(test_number_vectors),
        cmocka_unit_test(test_named_numbers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
