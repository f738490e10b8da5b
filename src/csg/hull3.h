/* The convex hull of a set of points in 3D (hull3.c), for hull() and
 * minkowski(): its vertices, its triangles and its face planes (the plane
 * set the convex primitive renders).
 */
#ifndef SPANCAST_CSG_HULL3_H
#define SPANCAST_CSG_HULL3_H

#include <stdint.h>

#include "csg/prim.h"
#include "math/vec.h"

/* The largest point set hull3_compute takes (docs/hull.md). */
#define HULL3_MAX_POINTS 4000000u

/* The largest coordinate it takes: triple products of coordinates must not
 * overflow in the exact orientation test. */
#define HULL3_MAX_COORD 1e90

typedef struct hull3 {
    vec3 *vertices; /* the hull's vertices: copies of input points, no duplicates */
    uint32_t vertex_count;
    uint32_t *tris; /* 3 indices into vertices per triangle, counter-clockwise
                       seen from outside */
    uint32_t tri_count;
    plane *planes; /* outward unit normals; coplanar triangles share one plane,
                      d is the largest n . v over that plane's vertices (over
                      all vertices for a sliver's plane, whose n is rounding) */
    uint32_t plane_count;
    bbox bounds; /* of the vertices */
} hull3;

typedef enum hull3_status {
    HULL3_OK,    /* *out holds the hull */
    HULL3_FLAT,  /* fewer than 4 points off one plane: no volume, *out is empty */
    HULL3_NOMEM, /* out of memory, *out is empty */
    HULL3_RANGE  /* a coordinate is not finite or beyond HULL3_MAX_COORD, or
                    more than HULL3_MAX_POINTS points */
} hull3_status;

/* Computes the hull of points[0 .. count). Duplicate, coplanar and
 * collinear points are fine; the orientation tests are exact, so the
 * result is the exact hull of the input points (the planes are rounded).
 * On HULL3_OK *out owns malloc'd arrays (hull3_free); otherwise *out is
 * zeroed. */
hull3_status hull3_compute(const vec3 *points, uint32_t count, hull3 *out);

void hull3_free(hull3 *h);

/* The sign (-1, 0, 1) of (b - a) x (c - a) . (p - a), computed exactly:
 * 1 when p lies on the side that the normal of the counter-clockwise
 * triangle a, b, c points to. */
int hull3_orient(vec3 a, vec3 b, vec3 c, vec3 p);

/* The volume enclosed by the hull's triangles. */
double hull3_volume(const hull3 *h);

#endif
