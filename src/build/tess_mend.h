/* OpenSCAD 2021.01's mending of libtess2's triangles of one face
 * (GeometryUtils::tessellatePolygonWithHoles), for the faces of polyhedra
 * it triangulates with libtess2 (build_mesh.c).
 *
 * libtess2 merges points that lie on one point of the face's projection
 * and drops every triangle that has a point it made where edges cross.
 * OpenSCAD keeps a table of the face's edges (its EdgeDict): each of
 * libtess2's triangles, turned round where it runs against the face,
 * takes its edges out of the table and puts the reverse of the others in.
 * What is left is a set of loops, which it cuts into ears
 * (EdgeDict::triangulateLoops): the ear is cut at the first point of its
 * table of points by outgoing edge that has one such edge. Both tables
 * are hash tables, so which point comes first is their order of
 * iteration, which is reproduced here: OpenSCAD's numbers of the points
 * (the order in which its tessellation first meets them, face by face),
 * the edges keyed by boost::hash of the pair (1.74, 64-bit), the points
 * by their number, and libstdc++'s unordered_map (its buckets, and the
 * place of a new key in its list).
 */
#ifndef SPANCAST_BUILD_TESS_MEND_H
#define SPANCAST_BUILD_TESS_MEND_H

#include <stdint.h>

/* The triangles OpenSCAD makes of a face of n points whose numbers,
 * as OpenSCAD holds the face, are face[0 .. n), from libtess2's count
 * triangles tris (positions in face, each in libtess2's order: from its
 * face's anEdge) and the ears cut from the loops left: into out, as
 * positions in face (the first where a number is held twice), libtess2's
 * first. Returns how many; -1 when memory runs out; -2 where OpenSCAD's
 * loops do not close (a loop of fewer than three points, or more than
 * out_cap triangles), which it does not handle either. */
long tess_mend(const uint32_t *face, uint32_t n, const uint32_t *tris, uint32_t count,
               uint32_t *out, uint32_t out_cap);

#endif
