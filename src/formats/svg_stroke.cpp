/* svg_stroke.h: the stroke of an open path through Clipper's offset. The
 * grid (1/10000), the truncation of coordinates onto it, the delta (half
 * the width) and Clipper's defaults (miter limit 2, arc tolerance 0.25
 * grid units) are OpenSCAD 2021.01's (libsvg/shape.cc). */
#include <cmath>
#include <new>

#include <clipper.hpp>

extern "C" {
#include "formats/svg_stroke.h"
}

static const double grid = 10000.0;

extern "C" int svg_stroke(const double *xy, size_t count, double width, svg_join join,
                          svg_cap cap, twod_region *out)
{
    try {
        ClipperLib::Path line;
        for (size_t i = 0; i < count; i++) {
            double x = xy[2 * i] * grid, y = xy[2 * i + 1] * grid;
            if (!(std::fabs(x) < 4e18) || !(std::fabs(y) < 4e18))
                return -1;
            line.push_back(
                ClipperLib::IntPoint((ClipperLib::cInt)x, (ClipperLib::cInt)y));
        }
        ClipperLib::JoinType jt = join == SVG_JOIN_ROUND    ? ClipperLib::jtRound
                                  : join == SVG_JOIN_SQUARE ? ClipperLib::jtSquare
                                                            : ClipperLib::jtMiter;
        ClipperLib::EndType et = cap == SVG_CAP_BUTT    ? ClipperLib::etOpenButt
                                 : cap == SVG_CAP_ROUND ? ClipperLib::etOpenRound
                                                        : ClipperLib::etOpenSquare;
        if (!(std::fabs(width * grid) < 4e18))
            return -1;
        ClipperLib::ClipperOffset offset;
        offset.AddPath(line, jt, et);
        ClipperLib::Paths result;
        offset.Execute(result, width * grid / 2);
        for (const ClipperLib::Path &ring : result) {
            if (!twod_begin_contour(out))
                return 0;
            for (const ClipperLib::IntPoint &p : ring)
                if (!twod_add_point(out, p.X / grid, p.Y / grid))
                    return 0;
            twod_end_contour(out);
        }
        return 1;
    } catch (const std::bad_alloc &) {
        return 0;
    } catch (const ClipperLib::clipperException &) {
        return 0;
    }
}
