/* Argument helpers of the leaf and extrusion builders: see build_curved.h. */
#include "base/error.h"
#include "scene/build_curved.h"

const parse_value *build_arg(const parse_node *n, const char *name, int position)
{
    const parse_arg *a = parse_node_arg(n, name, position);
    return a && a->value.kind != PARSE_UNDEF ? &a->value : NULL;
}

sc_location build_loc(const build_ctx *c, const parse_value *v)
{
    sc_location loc = {c->file, v->line, v->column};
    return loc;
}

sc_status build_wrong_type(const build_ctx *c, const parse_node *n, const char *param,
                           const parse_value *v, const char *expected)
{
    sc_location loc = build_loc(c, v);
    return err_set(c->error, SC_ERR_SEMANTIC, &loc,
                   "wrong type for argument '%s' of '%s' (expected %s)", param, n->name,
                   expected);
}
