/* Building motion(from, to) nodes (build_motion.c): the transform their
 * subtree gets at time 0, and the motion each leaf below them carries. */
#ifndef SPANCAST_BUILD_BUILD_MOTION_H
#define SPANCAST_BUILD_BUILD_MOTION_H

#include "csg/csg.h"
#include "model/model.h"

/* Opens motion node n under the transform *to_world: fills *out (before =
 * *to_world, the path from n's from to its to) and sets *to_world to the
 * subtree's transform at time 0, *to_world . from. moving says whether an
 * enclosing motion node is open: nesting is an error at n. */
sc_status build_motion_open(const model_node *n, int moving, affine *to_world,
                            csg_motion *out, sc_error *error);

/* Makes leaf id, whose world transform at time 0 is leaf_world, move with
 * m: its transform at time s is m->before . path(s) . after, after being
 * what lies between the motion node and the leaf. */
sc_status build_motion_leaf(csg_builder *csg, uint32_t id, const csg_motion *m,
                            const affine *leaf_world, const model_node *n,
                            sc_error *error);

#endif
