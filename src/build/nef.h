/* Mesh booleans and convex decomposition, as OpenSCAD 2021.01 computes the
 * children of hull() and minkowski(): CGAL's Nef polyhedra, in a plugin.
 *
 * OpenSCAD evaluates a difference or intersection inside a hull or
 * minkowski to a CGAL Nef polyhedron (exact rational coordinates), hulls
 * the vertices of the result, and sums a non-convex child part by part,
 * through CGAL's convex decomposition of the Nef polyhedron. spancast does
 * the same with the same library. CGAL, GMP and MPFR are linked only by
 * the plugin spancast-cgal.so (cgal/nef_cgal.cpp), which nef_plugin_open
 * loads on the first such node, so that no other model pays for loading
 * them (docs/hull.md).
 *
 * The plugin's entry points are C functions named in nef_plugin; every one
 * catches its C++ exceptions (CGAL's failed preconditions, bad_alloc) and
 * reports them as a status and a message, so nothing is thrown across the
 * boundary. Buffers the plugin returns are malloc'd: the caller frees
 * them with free().
 */
#ifndef SPANCAST_BUILD_NEF_H
#define SPANCAST_BUILD_NEF_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A Nef polyhedron, owned by the plugin (nef_release). */
typedef struct nef_solid nef_solid;

typedef enum nef_op { NEF_UNION, NEF_DIFFERENCE, NEF_INTERSECTION } nef_op;

typedef enum nef_status {
    NEF_OK = 0,
    NEF_BAD_MESH, /* the polygons do not bound a volume (message says why) */
    NEF_NOMEM,
    NEF_FAILED /* CGAL refused (message says why) */
} nef_status;

/* Points of one or more convex parts: part k is points[3 * start[k] ..
 * 3 * start[k + 1]) (x, y, z triples); both arrays malloc'd. */
typedef struct nef_parts {
    double *points;
    uint32_t *start; /* count + 1 entries */
    uint32_t count;
} nef_parts;

/* The entry points, each named spancast_nef_<field> in the plugin. err
 * receives a message (no position, no trailing newline) on failure. */
typedef struct nef_plugin {
    /* The solid bounded by a closed polygon mesh: points are x, y, z
     * triples; loop k is indices[loop_start[k] .. loop_start[k + 1]);
     * face f is the loops face_loops[f] .. face_loops[f + 1] (its outline
     * and holes, in one plane, none crossing another), or loop f alone
     * when face_loops is NULL. Points at the same position are merged,
     * faces are triangulated (a face of several loops by the even-odd
     * rule) and the orientation is made inward, as OpenSCAD hands CGAL
     * its meshes, so either winding is taken; with written 1, the faces
     * are a polyhedron's in OpenSCAD's order (its faces as written, back
     * to front) and each is reversed, as OpenSCAD's builder reverses them,
     * whichever way that turns the mesh (which matters only for a mesh
     * that crosses itself); 2, the same mesh mirrored on its way here,
     * each face kept as it comes. The faces must not overlap one another: a fan
     * of a face that is not convex does, and so do a face and its hole
     * given as two faces. */
    nef_status (*from_mesh)(const double *points, uint32_t point_count,
                            const uint32_t *indices, const uint32_t *loop_start,
                            const uint32_t *face_loops, uint32_t face_count, int written,
                            nef_solid **out, char *err, size_t err_size);
    /* The empty solid. */
    nef_status (*empty)(nef_solid **out, char *err, size_t err_size);
    /* *a = *a op b; b is left as it is. */
    nef_status (*apply)(nef_solid *a, nef_op op, const nef_solid *b, char *err,
                        size_t err_size);
    /* *out = a copy of s (CGAL shares the two until one changes). */
    nef_status (*copy)(const nef_solid *s, nef_solid **out, char *err, size_t err_size);
    /* s = the image of s under x -> A x + t, m the rows of [A | t] (12
     * numbers), as OpenSCAD 2021.01 transforms a Nef polyhedron
     * (CGAL_Nef_polyhedron::transform): exactly, each entry the rational
     * its double is; a singular A (determinant 0 in doubles) empties s. */
    nef_status (*transform)(nef_solid *s, const double m[12], char *err, size_t err_size);
    /* Whether the solid has no volume. */
    int (*is_empty)(const nef_solid *s);
    /* The vertices of the solid, rounded to doubles, as one part. */
    nef_status (*vertices)(const nef_solid *s, nef_parts *out, char *err,
                           size_t err_size);
    /* CGAL's convex decomposition of the solid (as OpenSCAD's minkowski
     * does it): the vertices of each convex volume, one part each. The
     * solid is left as it is. */
    nef_status (*convex_parts)(const nef_solid *s, nef_parts *out, char *err,
                               size_t err_size);
    /* The boundary of the solid as triangles turned away from it, as one
     * part: triangle t is points[9 * t .. 9 * t + 9) (3 corners). */
    nef_status (*triangles)(const nef_solid *s, nef_parts *out, char *err,
                            size_t err_size);
    void (*release)(nef_solid *s);
    /* The section of the solid by the plane z = 0 as OpenSCAD 2021.01's
     * projection(cut = true) computes it (CGALUtils::project: the
     * intersection with the plane, its up-facing facets flattened into a
     * 2D Nef polyhedron), as loops of points with z = 0, one part each:
     * each face's outline counter-clockwise, then its holes clockwise.
     * *missed is 1, with no loops, where the intersection is empty
     * (OpenSCAD's "Projection() failed.": also where CGAL fails on the
     * plane and on OpenSCAD's thin box after it), 2 where CGAL fails as
     * the intersection is flattened (OpenSCAD's section is then empty,
     * with CGAL's message, in err). */
    nef_status (*section)(const nef_solid *s, nef_parts *out, int *missed, char *err,
                          size_t err_size);
    /* Whether the triangles (tri_count of them, 9 numbers each) make a
     * surface that passes through itself: *crossing 1 where two of them
     * meet other than at an edge or corner they share, 0 where none do or
     * the triangles are not a surface (an edge of three faces). */
    nef_status (*self_crossing)(const double *corners, uint32_t tri_count, int *crossing,
                                char *err, size_t err_size);
    /* Where OpenSCAD 2021.01, whose CGAL checks its assertions, stops
     * making the Nef polyhedron of a closed mesh on a face out of its
     * plane (polygon_mesh_to_nef_3's checks): CGAL's polyhedron is built
     * from the points (x, y, z triples) in the order given and the loops
     * indices[face_start[k] .. face_start[k + 1]) its builder takes, as
     * OpenSCAD builds it; then at each corner, point by point and in
     * CGAL's order about each, each face of more than three points must
     * hold the corner's neighbours in the plane through the corner along
     * its Newell normal. *verdict: 0 when every check holds; 1 when the
     * first to fail is the one OpenSCAD answers by triangulating the faces
     * and trying again (the neighbour after the corner); 2 when it is one
     * that loses the polyhedron (CGAL's expression in err), with the face
     * in where[0] and the corner in where[1]. */
    nef_status (*plane_check)(const double *points, uint32_t point_count,
                              const uint32_t *indices, const uint32_t *face_start,
                              uint32_t face_count, int *verdict, uint32_t where[2],
                              char *err, size_t err_size);
    /* CGAL's polyhedron built from an OFF file's faces as its OFF reader
     * builds it (Polyhedron_scan_OFF, which OpenSCAD 2021.01's import
     * runs): each face whole, in order, loops indices[face_start[k] ..
     * face_start[k + 1]) over point_count points. *refused: UINT32_MAX when
     * the builder takes them all; else the face it failed on (face_count:
     * none, but its points could not be cleaned), which loses the
     * polyhedron, with CGAL's reason in err. NEF_FAILED where one of
     * CGAL's assertions fails (OpenSCAD stops), on face *refused. */
    nef_status (*off_build)(uint32_t point_count, const uint32_t *indices,
                            const uint32_t *face_start, uint32_t face_count,
                            uint32_t *refused, char *err, size_t err_size);
    /* OpenSCAD 2021.01's triangles of a 2D region (Polygon2d::tessellate,
     * which makes the caps of its extrusions): each contour (x, y pairs;
     * contour k is points start[k] .. start[k + 1]) goes into CGAL's
     * constrained Delaunay triangulation from its last point on, each
     * point joined to the one before it unless the two are one; the
     * triangles nested inside an odd number of contours are kept, in the
     * triangulation's order, each counter-clockwise from its first
     * corner. *tris: 3 point indices per triangle (malloc'd; NULL when
     * there are none), *tri_count of them. NEF_FAILED where CGAL refuses
     * the contours (OpenSCAD's "CGAL error in Polygon2d::tesselate()"). */
    nef_status (*tessellate)(const double *xy, const uint32_t *start,
                             uint32_t contour_count, uint32_t **tris, uint32_t *tri_count,
                             char *err, size_t err_size);
    /* The solid OpenSCAD 2021.01 makes of a mesh it finds convex
     * (createNefPolyhedronFromPolySet, where is_approximately_convex
     * passes): CGAL's convex hull of the corners (count x, y, z triples:
     * every corner of every polygon, in OpenSCAD's order), copied into an
     * exact polyhedron and made a Nef polyhedron. 3 corners or fewer, or
     * corners in one plane, make the empty solid. */
    nef_status (*hull)(const double *corners, uint32_t count, nef_solid **out, char *err,
                       size_t err_size);
    void *handle; /* of dlopen */
} nef_plugin;

/* The plugin's file name. */
#define NEF_PLUGIN_FILE "spancast-cgal.so"

/* Loads the plugin (beside the executable, then in the build folder) into
 * *plugin. Returns 1, or 0 with "cannot load the CGAL plugin
 * (spancast-cgal.so): ..." in err. Close it with nef_plugin_close. */
int nef_plugin_open(nef_plugin *plugin, char *err, size_t err_size);
void nef_plugin_close(nef_plugin *plugin);

#ifdef __cplusplus
}
#endif

#endif
