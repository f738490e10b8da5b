/* libtess2's sweep of a simple polygon, step by step, for the faces of
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
 * Only the sweep of a simple polygon in general position is followed,
 * after libtess2's removal of an edge between two neighbours on one point
 * (RemoveDegenerateEdges): a point on another edge, two points on one
 * that are not neighbours, edges that meet or cross, and the splices that
 * mend them, end it (tess_sweep_faithful returns 0), and the caller takes
 * its own sweep.
 */
#ifndef SPANCAST_BUILD_TESS_SWEEP_H
#define SPANCAST_BUILD_TESS_SWEEP_H

#include <stdint.h>

/* The mesh after the sweep, compact: half-edges 2k and 2k + 1 are the two
 * halves of edge k; org is a contour position (n for the sentinels'
 * points); face 0 heads the face list, whose order is libtess2's, and
 * face_edge is each face's anEdge. Every array malloc'd (tess_swept_free). */
typedef struct tess_swept {
    uint32_t *org, *lnext, *lface;
    uint32_t edges; /* half-edges */
    uint32_t *face_next, *face_prev, *face_edge;
    unsigned char *inside;
    uint32_t faces; /* with the head */
} tess_swept;

/* Sweeps the contour (s[i], t[i]), i = 0 .. n - 1, counter-clockwise,
 * as libtess2 does with TESS_WINDING_ODD: first the edges between two
 * neighbours that are one point go, as libtess2 removes them, one of the
 * two points merged into the other (org never names it); every other
 * point must be distinct. Returns 1
 * with *out set; 0 where the polygon is not in general position for the
 * sweep (above); -1 when memory runs out. */
int tess_sweep_faithful(const float *s, const float *t, uint32_t n, tess_swept *out);

void tess_swept_free(tess_swept *out);

#endif
