/* text() (build_text.c): OpenSCAD 2021.01's text layout through fontconfig,
 * HarfBuzz and FreeType, as glyph outlines of lines and quadratic and
 * cubic Bezier curves, and what linear_extrude makes of them: an exact
 * outline prism (prim_outline.h), or in faithful mode OpenSCAD's polygons
 * extruded as a prism mesh.
 */
#ifndef SPANCAST_BUILD_BUILD_TEXT_H
#define SPANCAST_BUILD_BUILD_TEXT_H

#include <stdint.h>

#include "build/build_ctx.h"
#include "csg/prim_outline.h"
#include "twod/twod.h"

/* The longest text one node may lay out, in bytes of UTF-8. */
#define TEXT_MAX_BYTES MODEL_MAX_TEXT_BYTES

/* A laid-out text in the text node's own 2D frame. Segments are in
 * FreeType's units over 1e5 ("v" below); glyph g's contours are
 * glyph_start[g] .. glyph_start[g + 1] - 1, contour k's segments
 * contour_start[k] .. contour_start[k + 1] - 1, and a point v of glyph g
 * lies at size * ((v + offset[g]) + advance[g]), OpenSCAD's own order of
 * operations. */
typedef struct text_shape {
    outline_seg *segs;
    uint32_t seg_count, seg_cap;
    uint32_t *contour_start; /* contour_count + 1 entries */
    uint32_t contour_count, contour_cap;
    uint32_t *glyph_start;    /* glyph_count + 1 entries */
    double *offset, *advance; /* 2 per glyph */
    uint32_t glyph_count, glyph_cap;
    double size;
    uint32_t curve_points; /* OpenSCAD's points per curve segment */
} text_shape;

/* Lays out text node n. A font that fontconfig does not have (it matches
 * another family) fills *note with a warning at the node naming both,
 * when note is not NULL. On failure nothing needs freeing. */
sc_status text_shape_build(const build_ctx *c, const model_node *n, text_shape *out,
                           sc_error *note);
void text_shape_free(text_shape *s);

/* Registers the font file at path with the text plugin's fontconfig
 * (text_register_fn), for every later text() of the process; the plugin
 * then stays loaded, as the registration lives in it. Thread safe.
 * SC_ERR_IO when the plugin does not load or fontconfig cannot read the
 * file. */
sc_status text_register_font(const char *path, sc_error *error);

/* OpenSCAD's polygons of a text node into out (initialised; replaced), in
 * its 2D frame: the curves flattened as its DrawingCallback does, each
 * glyph's contours oriented so that outlines run counter-clockwise and
 * holes clockwise (the region is where the winding number is positive),
 * points snapped as OpenSCAD's Clipper union snaps them (truncated to
 * multiples of 2^-16), no repeated points. More than TWOD_MAX_POINTS
 * points is SC_ERR_LIMIT, as for every 2D shape. */
sc_status text_faithful_polygons(const build_ctx *c, const model_node *n,
                                 twod_region *out, sc_error *note);

/* Does linear_extrude n have a text node among its 2D children (under
 * group, union, render, color and multmatrix)? */
int build_text_wanted(const model_node *n);
/* ... and are all its 2D children text (build_extrude.c takes the exact
 * outline prism then)? */
int build_text_only(const model_node *n);

/* linear_extrude(height, center) of text children (build_extrude.c calls
 * this when build_text_wanted): an exact outline prism, or with
 * c->faithful OpenSCAD's polygons as a prism mesh. Other 2D shapes beside
 * the text are SC_ERR_UNSUPPORTED; no area or height sets *empty. */
sc_status build_text_extrude(const build_ctx *c, const model_node *n, double height,
                             int center, int emit, prim *out, const char **empty);

#endif
