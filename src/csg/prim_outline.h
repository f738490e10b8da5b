/* Outline-prism leaves (prim_outline.c): the region enclosed by closed
 * contours of lines and quadratic and cubic Bezier curves in the xy plane
 * (glyph outlines from text()), extruded over z0 <= z <= z1. prim.c
 * dispatches to the operations below; they mean what they mean in prim.h.
 */
#ifndef SPANCAST_CSG_PRIM_OUTLINE_H
#define SPANCAST_CSG_PRIM_OUTLINE_H

#include <stdint.h>

#include "csg/prim.h"

/* The most spans an outline leaf gives one ray, and the most crossings of
 * the ray's z window it sorts; past either, the rest of the window up to
 * the last crossing is filled (see prim_outline.c). */
#define PRIM_OUTLINE_MAX_SPANS 64
#define PRIM_OUTLINE_MAX_CROSSINGS 512

/* Surface parts: the caps, and walls. A wall part is 2 + (the segment's
 * index modulo PRIM_OUTLINE_WALL_PARTS) * PRIM_OUTLINE_BINS + the bin of
 * the crossing's curve parameter (floor(u * PRIM_OUTLINE_BINS)), with
 * PRIM_OUTLINE_PART_RIGHT set when the solid lies to the left of the
 * segment's direction there (its outward normal is the tangent turned
 * clockwise). */
#define PRIM_OUTLINE_PART_BOTTOM 0
#define PRIM_OUTLINE_PART_TOP 1
#define PRIM_OUTLINE_WALL_PARTS 2046u
#define PRIM_OUTLINE_BINS 16u
#define PRIM_OUTLINE_PART_RIGHT 0x8000u

/* One segment of a closed contour: a line (degree 1, points 0 and 1), a
 * quadratic (degree 2) or a cubic (degree 3) Bezier curve; the segments of
 * a contour follow each other end to start, the last ending where the
 * first starts. */
typedef struct outline_seg {
    double x[4], y[4];
    uint32_t degree;
} outline_seg;

/* A node of the segment hierarchy: a leaf when count > 0 (segments start
 * .. start + count - 1), else an inner node whose children are the next
 * node and node start. */
typedef struct prim_outline_node {
    double lo[2], hi[2]; /* control-point box, padded (see prim_outline.c) */
    uint32_t start, count;
} prim_outline_node;

typedef struct prim_outline {
    const outline_seg *segs; /* in hierarchy order */
    const prim_outline_node *nodes;
    uint32_t seg_count, node_count;
    double z0, z1; /* z0 < z1 */
    bbox bounds;   /* tight: the curves' extremes, z0 and z1 */
} prim_outline;

struct csg_builder;

/* Builds the leaf of count segments (whole closed contours, filled by the
 * nonzero winding rule) between z0 < z1 in b's arena; points must be
 * finite. Returns NULL when memory ran out or count is 0. */
const prim_outline *prim_outline_create(struct csg_builder *b, const outline_seg *segs,
                                        uint32_t count, double z0, double z1);

/* The crossings of the line o + t d (d != 0) with segment s, in the
 * order of the segment's parameter: up to 3 line parameters t, the
 * segment's parameters u there (when u is not NULL) and the change of
 * winding number (+1 or -1) at each, counting a point on the
 * line's left side (f = n . (p - o) >= 0 with n = (-d.y, d.x)) apart from
 * one on its right. Returns the count. Exposed for the tests. */
uint32_t prim_outline_cross(const outline_seg *s, const double o[2], const double d[2],
                            double t[3], int dw[3], double u[3]);

uint32_t prim_outline_spans(const prim *p, uint32_t leaf, vec3 o, vec3 d, span *out,
                            uint32_t cap);
vec3 prim_outline_normal(const prim *p, vec3 q, uint16_t part);
int prim_outline_inside(const prim *p, vec3 q);
uint32_t prim_outline_max_spans(const prim *p);

#endif
