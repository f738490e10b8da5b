/* motion(from = M0, to = M1) { children }: spancast's node for motion blur
 * within one render (docs/distribution.md). from and to are row-major 4x4
 * affine matrices like multmatrix's m; both are required. The subtree
 * stands under from when the shutter opens and under to when it closes,
 * in between under their interpolation (math/motion.h: rotation by slerp,
 * stretch and translation linearly), so both must be invertible and agree
 * on mirroring, which is checked here, at the node.
 */
#include "model/lower_motion.h"

#include <math.h>

#include "base/error.h"
#include "math/motion.h"

static const char expected[] = "a 4x4 matrix of numbers with bottom row [0, 0, 0, 1]";

/* The matrix argument name of n into *out; *given says whether it was there. */
static sc_status matrix(const model_reader *r, const parse_node *n, const char *name,
                        affine *out, int *given)
{
    const parse_value *v = model_arg(n, name, -1);
    *given = v != NULL;
    if (!v)
        return SC_OK;
    int ok = v->kind == PARSE_VECTOR && v->u.vector.count == 4;
    double m[4][4];
    for (uint32_t i = 0; ok && i < 4; i++) {
        const parse_value *row = &v->u.vector.items[i];
        ok = row->kind == PARSE_VECTOR && row->u.vector.count == 4;
        for (uint32_t k = 0; ok && k < 4; k++) {
            const parse_value *x = &row->u.vector.items[k];
            ok = x->kind == PARSE_NUMBER && isfinite(x->u.number);
            if (ok)
                m[i][k] = x->u.number;
        }
    }
    if (ok)
        ok = m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1;
    if (!ok)
        return model_wrong_type(r, n, name, v, expected);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            out->m[i][k] = m[i][k];
    return SC_OK;
}

sc_status model_read_motion(const model_reader *r, const parse_node *n, model_motion *out)
{
    int has_from, has_to;
    sc_status st = matrix(r, n, "from", &out->from, &has_from);
    if (!st)
        st = matrix(r, n, "to", &out->to, &has_to);
    if (st)
        return st;
    if (!has_from || !has_to)
        return err_set(r->error, SC_ERR_SEMANTIC, &n->loc, "'motion' needs from and to");
    motion path;
    if (!motion_init(&path, &out->from, &out->to))
        return err_set(r->error, SC_ERR_SEMANTIC, &n->loc,
                       "'motion': from and to must be invertible and agree on "
                       "mirroring");
    return SC_OK;
}
