/* The split parse against the whole one, on one input: for the fuzzer
 * (fuzz/fuzz_split.c) and the tests (tests/test_model.c,
 * tests/test_fuzz_regressions.c).
 *
 * split_one parses and lowers a text as one stream (parse_stream with
 * model_stream's sink), then again split in two threads at the statement
 * boundary nearest a given place (parse_sink's split_at: the first thread
 * waits for the second's scan, so the split is made there when the text
 * has a boundary near it). Both must give the same status and message, or
 * the same model (split_same_nodes) and the same warnings. Returns 0 when
 * they do, -1 otherwise; *split says whether the second parse was read in
 * two joined parts. It lives in a header so that the fuzzer and the tests
 * share it without a library of its own.
 */
#ifndef SPANCAST_FUZZ_SPLIT_HARNESS_H
#define SPANCAST_FUZZ_SPLIT_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "base/error.h"
#include "model/model.h"
#include "syntax/parse.h"

/* Whether two lists of model nodes are the same node for node: kind,
 * name, position, flags, children, errors, a sphere's radius, and the
 * subtree a resize measures. */
static inline int split_same_nodes(const model_node *a, const model_node *b)
{
    for (; a || b; a = a->next, b = b->next) {
        if (!a || !b || a->kind != b->kind || strcmp(a->name, b->name) != 0 ||
            a->loc.line != b->loc.line || a->loc.column != b->loc.column ||
            a->modifiers != b->modifiers || a->is_root != b->is_root ||
            a->child_count != b->child_count)
            return 0;
        if (a->kind == MODEL_ERROR) {
            char ma[1024], mb[1024];
            if (strcmp(sc_error_format(a->u.error, ma, sizeof ma),
                       sc_error_format(b->u.error, mb, sizeof mb)) != 0)
                return 0;
        }
        /* the same bits: a nan radius is the same as itself */
        if (a->kind == MODEL_SPHERE &&
            memcmp(&a->u.sphere.r, &b->u.sphere.r, sizeof a->u.sphere.r) != 0)
            return 0;
        if (a->kind == MODEL_RESIZE) {
            const model_node *ma = a->u.resize->measured, *mb = b->u.resize->measured;
            if ((ma == NULL) != (mb == NULL))
                return 0;
            /* the detached subtree the builder measures */
            if (ma && ma != a && !split_same_nodes(ma, mb))
                return 0;
        }
        if (!split_same_nodes(a->first_child, b->first_child))
            return 0;
    }
    return 1;
}

/* Whether two models have the same warnings, in the same order. */
static inline int split_same_notes(const model *a, const model *b)
{
    if (a->notes.count != b->notes.count)
        return 0;
    for (size_t i = 0; i < a->notes.count; i++) {
        const sc_error *x = &a->notes.items[i], *y = &b->notes.items[i];
        if (x->line != y->line || x->column != y->column ||
            strcmp(x->message, y->message) != 0)
            return 0;
    }
    return 1;
}

/* Parses and lowers text as a stream, split at the boundary nearest
 * split_at when it is not 0. Returns the parse's status; *m and *names
 * are the results on success, *split whether the parse was split. */
static inline sc_status split_stream(const char *text, size_t length, size_t split_at,
                                     model **m, parse_tree **names, int *split,
                                     sc_error *e)
{
    *m = NULL;
    *names = NULL;
    *split = 0;
    model_stream *s;
    sc_status st = model_stream_new("fuzz.csg", &s, e);
    if (st != SC_OK)
        return st;
    parse_sink sink = model_stream_sink(s);
    sink.split_min = split_at ? 1 : 0;
    sink.split_at = split_at;
    st = parse_stream("fuzz.csg", text, length, &sink, names, e);
    if (st != SC_OK) {
        model_stream_free(s);
        return st;
    }
    *split = (*names)->split;
    return model_stream_finish(s, m);
}

/* The place the fuzzer splits an input at (1 to length - 1, length >= 2):
 * a hash of the input, so that its mutations move the place too. */
static inline size_t split_place(const char *text, size_t length)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (size_t i = 0; i < length; i++)
        h = (h ^ (unsigned char)text[i]) * 16777619u;
    return 1 + h % (length - 1);
}

static inline int split_one(const char *text, size_t length, size_t place, int *split)
{
    model *whole, *part;
    parse_tree *whole_names, *part_names;
    sc_error we, pe;
    int whole_split;
    *split = 0;
    sc_status ws = split_stream(text, length, 0, &whole, &whole_names, &whole_split, &we);
    sc_status ps = split_stream(text, length, place, &part, &part_names, split, &pe);
    int same = ws == ps && !whole_split;
    if (same && ws != SC_OK) {
        char a[1024], b[1024];
        same = strcmp(sc_error_format(&we, a, sizeof a),
                      sc_error_format(&pe, b, sizeof b)) == 0;
    } else if (same) {
        same =
            whole->has_root == part->has_root && whole->leaf_count == part->leaf_count &&
            whole_names->count == part_names->count &&
            whole_names->node_count == part_names->node_count &&
            split_same_nodes(whole->first, part->first) && split_same_notes(whole, part);
    }
    model_free(whole);
    model_free(part);
    parse_tree_free(whole_names);
    parse_tree_free(part_names);
    return same ? 0 : -1;
}

#endif
