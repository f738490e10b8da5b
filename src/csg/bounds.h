/* The box of the solid itself, as against its tree's box (csg_tree's
 * bounds), which holds every leaf a union reaches and every minuend of a
 * difference, whatever the booleans cut away.
 *
 * OpenSCAD frames its render by the box of the mesh it computed, so a
 * sphere with its top cut off is framed without the top. The box here is
 * found with the span engine, along whole lines parallel to the axes:
 *   - a grid of lines along each axis over the tree's box, every span end
 *     met adding its point to the box;
 *   - then, for each of the six sides, a pattern search from the best few
 *     points seen (OpenSCAD's box is its vertices' box, and a polyhedron's
 *     extreme is a vertex, where the farthest span end along lines near it
 *     rises to a peak): the eight neighbours of the line at a step, the
 *     best taken while one is better, the step halved while none is, down
 *     to 2^-30 of the box. A face square to the axis is found exactly by
 *     the first line that meets it; a vertex or a smooth extreme (a
 *     sphere's pole) to the last step.
 * Every point is on the solid's surface, so the box lies inside the true
 * one; what the grid does not meet (a spike narrower than a grid cell at
 * the extreme, seen by no line of another axis) is left out. The result is
 * clipped to the tree's box. */
#ifndef SPANCAST_CSG_BOUNDS_H
#define SPANCAST_CSG_BOUNDS_H

#include "csg/csg.h"

/* The solid's box into *out: the tree's box where the tree is empty, moves
 * (its box then holds every time's), is not finite, or no line met it.
 * Returns 0 when memory ran out (*out is then the tree's box). */
int csg_solid_bounds(const csg_tree *t, bbox *out);

#endif
