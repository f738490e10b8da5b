/* The exact linear_extrude (build_region.c): without twist or scale, in
 * default (exact) mode, the 2D children become a region tree of ellipses
 * and polygon sets (prim_extrusion.h) and the leaf is that region
 * extruded. build_extrude.c decides which path a linear_extrude takes.
 */
#ifndef SPANCAST_BUILD_BUILD_REGION_H
#define SPANCAST_BUILD_BUILD_REGION_H

#include "build/build_ctx.h"

/* 1 when the exact path takes this linear_extrude: every 2D node below one
 * of circle, square, polygon, group, union, render, color, multmatrix,
 * difference, intersection ('%' and '*' subtrees are not looked at), twist
 * absent or 0, scale absent, 1 or [1, 1]. Otherwise 0, with *miss the
 * first node (in file order) the exact path cannot read, or NULL when
 * twist or scale is the reason. Arguments are not checked here. */
int build_region_covers(const model_node *n, const model_node **miss);

/* Builds the exact extrusion of n: height (default 100) and center are
 * read and checked, and the 2D subtree is walked with exact positions for
 * bad arguments. A zero height or an empty region sets *empty to a warning
 * instead; with emit unset only the checks run. *far says that a square
 * or circle reaches past the clipper's range (TWOD_MAX_COORD), where
 * OpenSCAD's clipper decides what is drawn: then nothing is built. */
sc_status build_region_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty, int *far);

#endif
