/* linear_extrude(height, center, twist, scale, slices) of 2D children: the
 * choice between the two builders.
 *
 * In default (exact) mode, an extrusion without twist or scale whose 2D
 * nodes are all ones build_region.c reads (circle, square, polygon, their
 * 2D booleans and transforms) is an exact extrusion leaf (build_region.c,
 * prim_extrusion.c): circles stay circles. Everything else (--faithful,
 * twist, scale, offset, 2D hull and minkowski) is built as OpenSCAD
 * 2021.01 builds it: the 2D engine (src/twod/) evaluates the children and
 * build_extrude_faithful.c makes OpenSCAD's slices into a closed mesh.
 * Without twist or scale that mesh is the exact prism of the evaluated
 * polygons. docs/extrusions.md says which is which.
 */
#include "scene/build_extrude_faithful.h"
#include "scene/build_mesh.h"
#include "scene/build_region.h"

sc_status build_linear_extrude(const build_ctx *c, const parse_node *n, int emit,
                               prim *out, const char **empty)
{
    const parse_node *miss = NULL;
    if (!c->faithful && build_region_covers(n, &miss))
        return build_region_extrude(c, n, emit, out, empty);
    return build_linear_extrude_faithful(c, n, emit, out, empty);
}
