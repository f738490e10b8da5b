/* The stroke of an open SVG path, as OpenSCAD 2021.01's libsvg makes it
 * (shape::offset_path): Clipper's offset of the open polyline on a grid of
 * 1/10000 unit, by half the stroke width, with the join and the end
 * given. svg_stroke.cpp, beside the clipper. */
#ifndef SPANCAST_FORMATS_SVG_STROKE_H
#define SPANCAST_FORMATS_SVG_STROKE_H

#include <stddef.h>

#include "twod/twod.h"

typedef enum svg_join { SVG_JOIN_MITER, SVG_JOIN_ROUND, SVG_JOIN_SQUARE } svg_join;
typedef enum svg_cap { SVG_CAP_SQUARE, SVG_CAP_BUTT, SVG_CAP_ROUND } svg_cap;

/* Appends the outline of the stroke of the count points xy (2 per point)
 * to out, one contour per ring Clipper returns. Returns 1, 0 when memory
 * runs out, -1 when the points (or the width) leave Clipper's range. */
int svg_stroke(const double *xy, size_t count, double width, svg_join join, svg_cap cap,
               twod_region *out);

#endif
