/* libtess2's sweep of a polygon, step by step, for the faces of
 * polyhedra that OpenSCAD 2021.01 triangulates with libtess2
 * (build_mesh.c). Its mesh is libtess2's half-edge mesh with the same
 * operations (tessMeshMakeEdge, tessMeshSplice, tessMeshSplitEdge,
 * tessMeshConnect, tessMeshDelete), and the sweep makes them in libtess2's
 * order: the contour as tessAddContour builds it, the two sentinels, and
 * for each point, left to right, its regions finished, its temporary
 * edges made and fixed (inside the polygon and outside it), and its right
 * edges added. Where the faces of the result come in libtess2's list, and
 * which half-edge each starts from, decide the order of its Delaunay
 * flips, and so the triangles where four points lie on one circle.
 *
 * Its degenerate cases are libtess2's too: the edge between two
 * neighbours on one point removed first (RemoveDegenerateEdges); the
 * points in the order of libtess2's event queue (pqInit's randomized
 * quicksort over its list of vertices, which orders points that are one,
 * and its heap for the points the sweep makes), those on one point
 * merged as the sweep reaches them; a point on another edge, or two
 * edges that meet at the right end of one, spliced as
 * CheckForRightSplice, CheckForLeftSplice and ConnectLeftDegenerate
 * splice them; and two edges that cross cut at a new point where
 * tesedgeIntersect puts it (CheckForIntersect). The cases libtess2 calls
 * very unusual (the new edges of a cut would pass the sweep's point on
 * the wrong side) end it (tess_sweep_faithful returns 0).
 */
#ifndef SPANCAST_BUILD_TESS_SWEEP_H
#define SPANCAST_BUILD_TESS_SWEEP_H

#include <stdint.h>

/* The mesh after the sweep, compact: half-edges 2k and 2k + 1 are the two
 * halves of edge k; org is a contour position (n for the sentinels'
 * points, n + 1 + k for the k-th point made where two edges cross, at
 * extra_s[k], extra_t[k]); face 0 heads the face list, whose order is
 * libtess2's, and face_edge is each face's anEdge. Every array malloc'd
 * (tess_swept_free). */
typedef struct tess_swept {
    uint32_t *org, *lnext, *lface;
    float *extra_s, *extra_t;
    uint32_t extra;
    uint32_t edges; /* half-edges */
    uint32_t *face_next, *face_prev, *face_edge;
    unsigned char *inside;
    uint32_t faces; /* with the head */
} tess_swept;

/* Sweeps the contour (s[i], t[i]), i = 0 .. n - 1, counter-clockwise,
 * as libtess2 does with TESS_WINDING_ODD: first the edges between two
 * neighbours that are one point go, as libtess2 removes them, one of the
 * two points merged into the other (org never names it); other points on
 * one point are merged, and points on edges spliced into them, as the
 * sweep reaches them, and edges that cross cut at a new point (above).
 * Returns 1 with *out set; 0 where the sweep meets a case it does not
 * follow; -1 when memory runs out. */
int tess_sweep_faithful(const float *s, const float *t, uint32_t n, tess_swept *out);

void tess_swept_free(tess_swept *out);

#endif
