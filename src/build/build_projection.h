/* projection(cut) (build_projection.c): a 2D region from 3D children, as
 * OpenSCAD 2021.01 computes it. See docs/extrusions.md.
 */
#ifndef SPANCAST_BUILD_BUILD_PROJECTION_H
#define SPANCAST_BUILD_BUILD_PROJECTION_H

#include "build/build_ctx.h"
#include "twod/twod.h"

/* Nesting below a projection node that its walk follows. */
#define BUILD_PROJECTION_MAX_DEPTH 1000

/* The region of projection node n in its own frame (out initialised, and
 * replaced): with cut, the section of the union of its 3D children by the
 * plane z = 0; without, the union of their outlines seen along z. Errors
 * (a child that has no polygon mesh, cut = false of a difference or
 * intersection, the children's own errors) are set at their position; a
 * 2D child is ignored with a warning in c->note. */
sc_status build_projection(const build_ctx *c, const model_node *n, twod_region *out);

#endif
