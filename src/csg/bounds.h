/* The box of the solid itself, as against its tree's box (csg_tree's
 * bounds), which holds every leaf a union reaches and every minuend of a
 * difference, whatever the booleans cut away, and a rotated leaf's
 * rotated box.
 *
 * OpenSCAD frames its render by the box of the mesh it computed, so a
 * sphere with its top cut off is framed without the top. Each side of the
 * box (how far the solid reaches along +x, -x, ...) is found down the
 * tree (bounds.c's side_of):
 *   - a union's is its farthest operand's, the operands tried in the order
 *     of how far their boxes reach, until one cannot beat what was found;
 *   - a leaf's is its box's where that is exact (a box; a sphere,
 *     cylinder, polyhedron, mesh or torus under a transform that keeps
 *     the axes);
 *   - a difference's or an intersection's is the farthest of its first
 *     operand's parts (the operands of a union found down the first
 *     operands of cuts, else the operand), each the part's own side where
 *     it is the difference's first operand and no subtrahend's box reaches
 *     as far, else searched over the part's box;
 *   - the rest (a rotated cylinder, an extrusion) is searched over its box.
 * A search runs along whole lines parallel to the side's axis, on the
 * node alone (csg_spans_node): a 32 x 32 grid over the part's box, every
 * span end met adding its point, then a pattern search from the three
 * farthest points seen. A round tries the eight neighbouring lines at the
 * step, the ridge where the line's surface meets a neighbour's (from their
 * normals) and the wall a neighbour falls off (a hole's rim); it moves to
 * the best while one is better and halves the step while none is, down to
 * 2^-26 of the part's box. A polyhedron's extreme is a vertex, where the
 * search ends; a face square to the axis is found by the first line that
 * meets it; a round rim of an exact cylinder to about 1e-6 of the model.
 * Every point is on the solid's surface, so the box is never larger than
 * the solid's; a spike narrower than a grid cell of its part's box at the
 * extreme is left out. A tree with an implicit leaf keeps its boxes (a
 * line there is a root search), and past 400,000 lines in all the parts
 * still to search keep theirs. */
#ifndef SPANCAST_CSG_BOUNDS_H
#define SPANCAST_CSG_BOUNDS_H

#include "csg/csg.h"

/* The solid's box into *out: the tree's box where the tree is empty, moves
 * (its box then holds every time's) or is not finite; a side that no line
 * met keeps the tree's side (a slab thinner than the grid across it is met
 * only by the lines along its thickness). *met is 0 where a search ran and
 * no line met the solid on any side (a cut that leaves nothing, or a
 * solid thinner than a grid cell in two directions), else 1. Returns 0
 * when memory ran out (*out is then the tree's box). */
int csg_solid_bounds(const csg_tree *t, bbox *out, int *met);

#endif
