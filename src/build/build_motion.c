/* motion(from, to) in the builder: see build_motion.h.
 *
 * The subtree is built once, at time 0 (under before . from), like any
 * other; each of its leaves then carries its motion, whose transform at
 * time s is before . path(s) . after with after = (before . from)^-1 .
 * leaf_world: the leaf's own placement below the motion node, whatever
 * built it (a primitive under transforms, or a hull or extrusion whose
 * points the builder placed itself). So the subtree moves as one rigid (or
 * stretched) body, and the CSG tree bounds each leaf over its whole motion.
 */
#include "build/build_motion.h"

#include "base/error.h"

sc_status build_motion_open(const model_node *n, int moving, affine *to_world,
                            csg_motion *out, sc_error *error)
{
    if (moving)
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "a 'motion' inside another 'motion' is not supported");
    const model_motion *m = n->u.motion;
    out->before = *to_world;
    out->after = affine_identity();
    if (!motion_init(&out->path, &m->from, &m->to))
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "'motion': from and to must be invertible and agree on "
                       "mirroring");
    *to_world = affine_mul(to_world, &m->from);
    return SC_OK;
}

sc_status build_motion_leaf(csg_builder *csg, uint32_t id, const csg_motion *m,
                            const affine *leaf_world, const model_node *n,
                            sc_error *error)
{
    if (id == CSG_EMPTY)
        return SC_OK;
    csg_motion leaf = *m;
    affine from = motion_at(&m->path, 0), inverse;
    affine start = affine_mul(&m->before, &from);
    if (!affine_invert(&start, &inverse))
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "'motion': the transform above it is singular");
    leaf.after = affine_mul(&inverse, leaf_world);
    if (!csg_builder_set_motion(csg, id, &leaf))
        return err_set(error, SC_ERR_SEMANTIC, &n->loc,
                       "'motion': the moving solid's transform becomes singular");
    return csg_builder_failed(csg) ? err_nomem(error, NULL) : SC_OK;
}
