/* The 2D builder (build_twod.c): OpenSCAD's 2D subtrees evaluated into
 * regions of the 2D engine (twod/twod.h), as OpenSCAD 2021.01 evaluates
 * them, for the extrusions, revolutions, hulls and imports that take 2D
 * children.
 */
#ifndef SPANCAST_BUILD_BUILD_TWOD_H
#define SPANCAST_BUILD_BUILD_TWOD_H

#include "build/build_ctx.h"
#include "twod/twod.h"

/* The union of parent's 2D children, as OpenSCAD 2021.01 evaluates them:
 * circle, square, polygon, group/union/render/color, difference,
 * intersection, multmatrix (its xy part), offset, hull and minkowski.
 * '%' and '*' children are left out. out must be initialised; it is
 * replaced. Errors (bad arguments, nodes that are not 2D, limits) are set
 * at their position. */
sc_status build_twod_children(const build_ctx *c, const model_node *parent,
                              twod_region *out);
/* The region of the 2D node n itself (circle, offset, ...), evaluated the
 * same way; outer names the node that asked, for messages. */
sc_status build_twod_node(const build_ctx *c, const model_node *n, const char *outer,
                          twod_region *out);

/* The error of a failed twod_add_point into r for node n: the limit of
 * TWOD_MAX_POINTS points of every 2D shape when r is full, else memory. */
sc_status build_twod_add_error(const build_ctx *c, const model_node *n,
                               const twod_region *r);

#endif
