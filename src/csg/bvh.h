/* Bounding volume hierarchies over the operands of wide boolean nodes.
 *
 * Built once when the tree is compiled, by binned surface-area heuristic:
 * at each node the operands' box centres are sorted into 16 bins along the
 * widest axis, and the split that minimises area(left)·count(left) +
 * area(right)·count(right) is taken; a node of at most 4 operands, or one
 * where no split beats keeping them together, is a leaf. Past depth 40 the
 * split falls back to the median, so no hierarchy is deeper than 40 +
 * log2(count) levels and traversal can use a fixed stack.
 *
 * Over 65,536 operands or more, outside a parallel region, the build runs
 * on OpenMP's threads: every right subtree of 32,768 operands or more is
 * a task that builds into nodes of its own, appended once its left
 * sibling is done, so the nodes come out as one thread makes them.
 */
#ifndef SPANCAST_CSG_BVH_H
#define SPANCAST_CSG_BVH_H

#include <stdint.h>

#include "csg/csg.h"

/* The deepest a hierarchy can be; traversal stacks use this size. */
#define BVH_MAX_DEPTH 96

typedef struct bvh_nodes {
    csg_bvh_node *v;
    uint32_t count, cap;
} bvh_nodes;

/* Builds a hierarchy over count >= 1 operands (ids[i] with box boxes[i];
 * both arrays are reordered in place into leaf order) and appends its nodes
 * to *out; leaf index fields count from items_base, the position of ids[0]
 * in the tree's child_ids. Returns the root's index in out->v, or
 * CSG_NO_BVH when memory ran out. */
uint32_t bvh_build(bvh_nodes *out, uint32_t *ids, bbox *boxes, uint32_t count,
                   uint32_t items_base);

#endif
