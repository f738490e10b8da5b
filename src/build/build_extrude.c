/* linear_extrude(height, center, twist, scale, slices) of 2D children: the
 * choice between the builders.
 *
 * In default (exact) mode, an extrusion without twist or scale whose 2D
 * nodes are all ones build_region.c reads (circle, square, polygon, their
 * 2D booleans and transforms) is an exact extrusion leaf (build_region.c,
 * prim_extrusion.c): circles stay circles. One whose 2D children are all
 * text is an exact outline prism (build_text.c, prim_outline.c): the
 * glyphs' Bezier curves. Everything else (--faithful, twist, scale,
 * offset, 2D hull and minkowski, text beside other shapes, a square or
 * circle past the clipper's range) is built as
 * OpenSCAD 2021.01 builds it: the 2D engine (src/twod/) evaluates the
 * children and build_extrude_faithful.c makes OpenSCAD's slices into a
 * closed mesh. Without twist or scale that mesh is the exact prism of the
 * evaluated polygons. docs/extrusions.md says which is which.
 */
#include "build/build_extrude_faithful.h"
#include "build/build_mesh.h"
#include "build/build_region.h"
#include "build/build_text.h"

/* height and center, as build_region.c reads them, for the text path. */
static sc_status text_extrude(const build_ctx *c, const model_node *n, int emit,
                              prim *out, const char **empty)
{
    const model_linear_extrude *args = n->u.linear_extrude;
    if (args->exact_error) {
        *c->error = *args->exact_error;
        return args->exact_error->status;
    }
    return build_text_extrude(c, n, args->height, args->center, emit, out, empty);
}

sc_status build_linear_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty)
{
    if (!c->faithful) {
        const model_node *miss = NULL;
        if (build_region_covers(n, &miss)) {
            build_notes_place notes = build_notes_here(c);
            int far;
            sc_status st = build_region_extrude(c, n, emit, out, empty, &far);
            if (st != SC_OK || !far)
                return st;
            /* Past the clipper's range OpenSCAD draws a square or circle
             * alone but refuses one turned over or combined: its own path
             * decides, and gives the warnings again. */
            build_notes_rewind(c, notes);
            *empty = NULL;
        }
        /* only text, without twist or scale: the exact outline prism */
        else if (miss && build_text_only(n))
            return text_extrude(c, n, emit, out, empty);
    }
    return build_linear_extrude_faithful(c, n, emit, out, empty);
}
