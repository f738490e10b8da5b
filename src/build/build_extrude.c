/* linear_extrude(height, center, twist, scale, slices) of 2D children: the
 * choice between the builders.
 *
 * In default (exact) mode, an extrusion without twist or scale whose 2D
 * nodes are all ones build_region.c reads (circle, square, polygon, their
 * 2D booleans and transforms) is an exact extrusion leaf (build_region.c,
 * prim_extrusion.c): circles stay circles. One whose 2D children are all
 * text is an exact outline prism (build_text.c, prim_outline.c): the
 * glyphs' Bezier curves. Everything else (--faithful, twist, scale,
 * offset, 2D hull and minkowski, text beside other shapes) is built as
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
static sc_status text_extrude(const build_ctx *c, const parse_node *n, int emit,
                              prim *out, const char **empty)
{
    double height = 100;
    const parse_value *h = model_arg(n, "height", 0);
    if (h && h->kind != PARSE_NUMBER)
        return model_wrong_type(BUILD_READER(c), n, "height", h, "a number");
    if (h)
        height = h->u.number;
    const parse_value *cv = model_arg(n, "center", 1);
    if (cv && cv->kind != PARSE_BOOL)
        return model_wrong_type(BUILD_READER(c), n, "center", cv, "true or false");
    return build_text_extrude(c, n, height, cv ? cv->u.boolean : 0, emit, out, empty);
}

sc_status build_linear_extrude(const build_ctx *c, const parse_node *n, int emit,
                               prim *out, const char **empty)
{
    if (!c->faithful) {
        const parse_node *miss = NULL;
        if (build_region_covers(n, &miss))
            return build_region_extrude(c, n, emit, out, empty);
        /* only text, without twist or scale: the exact outline prism */
        if (miss && build_text_only(n))
            return text_extrude(c, n, emit, out, empty);
    }
    return build_linear_extrude_faithful(c, n, emit, out, empty);
}
