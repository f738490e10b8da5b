/* The scene builder: syntax tree in, CSG tree out.
 *
 * It gives each node name its meaning, as OpenSCAD 2021.01 does:
 *   group, union, render, color, multmatrix   union of the children
 *   difference                                first child minus the others
 *   intersection                              intersection of the children
 *   cube, sphere, cylinder, polyhedron        leaves (polyhedron: convex ones as
 *                                             planes, others as meshes)
 *   import                                    an STL or OFF mesh (build_mesh.h)
 *   linear_extrude                            a prism of its 2D children (build_mesh.h)
 *   hull, minkowski, surface, resize          build_hull.h
 *   material                                  union; sets its children's material
 *   light, camera, background                 no geometry (build_shading.h)
 *   torus, quadric, implicit                  spancast's curved leaves
 *                                             (build_implicit.c)
 * Transforms (multmatrix, row-major 4x4) nest and accumulate into each
 * leaf's to_world; an inner colour wins over an outer one; leaves without a
 * colour get OpenSCAD's default face colour (Cornfield, #f9d72c).
 *
 * Modifiers: '*' drops the node (its subtree is not looked at); '%' keeps
 * the subtree out of the solid, and out of its parent's operation, but still
 * checks it; '#' changes nothing in the solid; the first '!' in file order
 * (outside dropped subtrees) makes its subtree the whole design, without
 * its ancestors' transforms or colours, as OpenSCAD's root modifier does.
 *
 * Every node OpenSCAD can write is known by name; those spancast cannot
 * render yet, and spancast's own geometry extension nodes, are SC_ERR_UNSUPPORTED
 * at their name; any other name is an error too. Unknown arguments are
 * ignored and the last of repeated ones wins, as in OpenSCAD.
 *
 * Things OpenSCAD turns into no geometry (a zero or negative size, a
 * singular transform) become the empty solid with a warning at their
 * position. The walk over the syntax tree uses an explicit stack.
 */
#ifndef SPANCAST_BUILD_BUILD_H
#define SPANCAST_BUILD_BUILD_H

#include <stddef.h>

#include "csg/csg.h"
#include "model/shading.h"
#include "spancast/spancast.h"
#include "syntax/parse.h"

/* The largest $fn a node may set: it is the number of polygon sides that
 * OpenSCAD-faithful rendering builds, so an absurd value must not reach it.
 * A larger or non-finite $fn is an error at the value (docs/limits.md). */
#define BUILD_MAX_FN 10000

/* The largest polyhedron the convex plane-set path takes, as faces times
 * points (its cost): 100000000 is about 10000 faces over 10000 points, a
 * fraction of a second. */
#define BUILD_MAX_POLYHEDRON_WORK 100000000

/* OpenSCAD's default face colour, Cornfield #f9d72c, alpha 1. */
#define BUILD_DEFAULT_COLOR                                                              \
    {                                                                                    \
        249 / 255.0f, 215 / 255.0f, 44 / 255.0f, 1.0f                                    \
    }

/* Builds the CSG tree of syntax; with faithful set, spheres and cylinders
 * become OpenSCAD's polyhedra for their $fn, $fa, $fs (faithful.h). On success *out owns
 * the tree (free with csg_tree_free) and *warnings is a malloc'd array of *warning_count
 * warnings in source order (NULL when there are none; free with free()).
 * On failure nothing is returned and error says where and why. */
sc_status build_tree(const parse_tree *syntax, int faithful, csg_tree **out,
                     sc_error **warnings, size_t *warning_count, sc_error *error);

/* The same, and also the scene's shading record (lights, materials, camera,
 * background: build_shading.h) in *look when look is not NULL (free with
 * shading_free). */
sc_status build_scene(const parse_tree *syntax, int faithful, csg_tree **out,
                      shading **look, sc_error **warnings, size_t *warning_count,
                      sc_error *error);

/* Looks up an OpenSCAD colour: a CSS/SVG name (any case) or "#rgb",
 * "#rgba", "#rrggbb", "#rrggbbaa". Returns 1 and fills rgba (0..1) when
 * known, else 0. (colors.c) */
int colors_lookup(const char *name, size_t length, float rgba[4]);

/* The colour table, for tests: its size and the index-th name. */
size_t colors_count(void);
const char *colors_name(size_t index);

#endif
