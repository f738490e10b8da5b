/* The 2D engine: regions in the plane, evaluated from OpenSCAD's 2D nodes
 * the way OpenSCAD 2021.01 evaluates them (build/build_twod.c), with its
 * polygon clipper (Clipper 6.4, twod_clip.cpp).
 *
 * A region is a list of closed contours of double points. After
 * evaluation through the clipper ("sanitized", as OpenSCAD calls it) the
 * contours do not cross, outer contours run counter-clockwise and holes
 * clockwise, and every coordinate lies on the clipper's grid of 2^-16.
 * Shapes OpenSCAD does not pass through the clipper keep their exact
 * points: a circle or square alone, a transformed copy of either, a hull.
 */
#ifndef SPANCAST_TWOD_TWOD_H
#define SPANCAST_TWOD_TWOD_H

#include <stdint.h>

#include "math/vec.h"
#include "spancast/spancast.h"

/* OpenSCAD's clipper grid: coordinates are scaled by 2^16 and truncated to
 * integers (ClipperUtils' CLIPPER_SCALE). */
#define TWOD_CLIPPER_SCALE 65536.0
/* Clipper's range over the scale: a coordinate goes in as an integer of
 * magnitude 2^62 - 1 at most (Clipper's hiRange), so its magnitude must be
 * below 2^46, as OpenSCAD's clipper takes it; a sum that leaves the range
 * (an offset, a translation, a minkowski sum) is Clipper's range error. */
#define TWOD_MAX_COORD 0x1p46

/* Whether v is within the clipper's range (finite and below 2^46 in
 * magnitude). */
static inline int twod_in_range(double v)
{
    return v > -TWOD_MAX_COORD && v < TWOD_MAX_COORD;
}
/* Most points in one region. */
#define TWOD_MAX_POINTS 10000000u

typedef struct twod_region {
    double *xy;             /* 2 per point */
    uint32_t *start;        /* contour k is points start[k] .. start[k + 1] - 1 */
    uint32_t point_count;   /* points in all contours */
    uint32_t contour_count; /* start has contour_count + 1 entries when > 0 */
    uint32_t point_cap;     /* in points */
    uint32_t start_cap;     /* in entries */
    int sanitized;          /* passed through the clipper (OpenSCAD's flag) */
} twod_region;

void twod_init(twod_region *r);
void twod_free(twod_region *r);
void twod_clear(twod_region *r);
/* Starts a new, empty contour; 0 when memory runs out. */
int twod_begin_contour(twod_region *r);
/* Adds a point to the last contour; 0 when memory runs out or the region
 * would pass TWOD_MAX_POINTS. */
int twod_add_point(twod_region *r, double x, double y);
/* Adds the point (x, y) moved by m to the last contour (twod_add_point). */
int twod_add_moved(twod_region *r, const affine2 *m, double x, double y);
/* Ends the last contour: drops a last point equal to its first, and the
 * whole contour when fewer than 3 points are left. */
void twod_end_contour(twod_region *r);
/* Reverses the order of contour k's points. */
void twod_reverse_contour(twod_region *r, uint32_t k);
/* Signed area (positive counter-clockwise) of the closed ring of points
 * first .. end - 1 of xy (2 per point), by the shoelace formula. */
double twod_ring_area(const double *xy, uint32_t first, uint32_t end);
/* Signed area of contour k (positive counter-clockwise) and of the region. */
double twod_contour_area(const twod_region *r, uint32_t k);
double twod_area(const twod_region *r);
/* How OpenSCAD 2021.01's clipper takes the outline of the n points
 * xy[2 * index[i]] (index NULL: the points in order) of a polygon, as
 * ClipperUtils::sanitize adds it (fromOutline2d, which turns the outline
 * of a polygon not yet sanitized round when it is clockwise, then Clipper
 * 6.4's AddPath): taken; skipped untested, as fewer than 3
 * points once the repeats at its end are dropped; or refused, a point
 * past Clipper's range (RangeTest throws, which ends AddPaths: OpenSCAD's
 * "Range check failed for polygon. skipping", and the outline and those
 * after it are left out). pt: room for 2 n integers. */
enum { TWOD_OUTLINE_TAKEN, TWOD_OUTLINE_SKIPPED, TWOD_OUTLINE_REFUSED };
int twod_clipper_outline(const double *xy, const uint32_t *index, uint32_t n,
                         int sanitized, int64_t *pt);
/* Leaves out of r what OpenSCAD's sanitize leaves out of the same
 * outlines (r->sanitized is OpenSCAD's flag): the first one the clipper
 * refuses and those after it, and those it skips that have a point past
 * the range (they add nothing, and the clipper cannot take them).
 * Returns the refused outline's number + 1, 0 when none, -1 when memory
 * runs out (r unchanged). */
long twod_clipper_admit(twod_region *r);
/* Puts back on r's points the coordinates they had in from, before the
 * clipper's grid took them: each point of r on a grid point where a point
 * of from lies (the first such, in x then y order) takes that point's
 * coordinates; the points the clipper made (crossings) stay. For a result
 * OpenSCAD makes without the clipper (the exact section of
 * projection(cut = true)). 0 when memory runs out (r unchanged). */
int twod_restore_points(twod_region *r, const twod_region *from);
/* Moves src into dst (dst freed first); src is left empty. */
void twod_move(twod_region *dst, twod_region *src);
/* out = the convex hull of count points (xy, 2 per point): one
 * counter-clockwise contour without collinear points, or nothing when the
 * points span no area. 0 when memory runs out. */
int twod_hull(const double *xy, uint32_t count, twod_region *out);

/* ---- the clipper (twod_clip.cpp); each returns a TWOD_CLIP_ code ---- */

enum { TWOD_CLIP_OK = 0, TWOD_CLIP_NOMEM, TWOD_CLIP_RANGE, TWOD_CLIP_TOO_MANY };
typedef enum twod_op { TWOD_UNION, TWOD_DIFFERENCE, TWOD_INTERSECTION } twod_op;
typedef enum twod_join { TWOD_JOIN_ROUND, TWOD_JOIN_MITER, TWOD_JOIN_SQUARE } twod_join;

/* OpenSCAD's sanitize: the even-odd union of r's contours (each turned
 * counter-clockwise first unless r is already sanitized), in place. */
int twod_clip_sanitize(twod_region *r);
/* OpenSCAD's ClipperUtils::apply: children sanitized where they are not,
 * then the first as subject and the others as clip (non-zero fill);
 * intersection as a chain of binary intersections. out is replaced. */
int twod_clip_apply(twod_region *const *children, uint32_t count, twod_op op,
                    twod_region *out);
/* OpenSCAD's offset: delta and arc_tolerance in model units, miter limit
 * 1000000 as OpenSCAD fixes it. out is replaced. */
int twod_clip_offset(const twod_region *in, double delta, twod_join join,
                     double arc_tolerance, twod_region *out);
/* The non-zero union of r's contours, in place, strictly simple. With
 * orient 1, each contour is turned counter-clockwise first: OpenSCAD's
 * union of a mesh's faces projected onto z = 0 (down-facing faces
 * project clockwise), strictly simple as it asks; 2, the same without the
 * turn (contours counter-clockwise already, and the holes of faces:
 * projection(cut = false)). With 0, the contours keep their direction:
 * the oriented loops of a section, whose winding numbers sum to 1 inside
 * the solid and 0 outside. */
int twod_clip_union_nonzero(twod_region *r, int orient);
/* The union of r's contours where their winding number is positive, each
 * keeping its direction, in place, strictly simple: a face's fan of
 * triangles that overlap, some wound back, whose signed sum is the face. */
int twod_clip_union_positive(twod_region *r);
/* OpenSCAD's 2D minkowski of count >= 2 regions (NULL entries are empty
 * children, which it skips after the first). out is replaced. */
int twod_clip_minkowski(twod_region *const *children, uint32_t count, twod_region *out);

#endif
