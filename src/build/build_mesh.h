/* Builder of mesh leaves (build_mesh.c): non-convex polyhedra and
 * import("file.stl" | "file.off").
 */
#ifndef SPANCAST_BUILD_BUILD_MESH_H
#define SPANCAST_BUILD_BUILD_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "build/build_ctx.h"
#include "model/model.h"

/* The largest mesh file import reads, in bytes (docs/meshes.md). */
#define BUILD_MAX_MESH_FILE (512u * 1024u * 1024u)

/* A mesh leaf from face_count polygons that a builder made (extrusions,
 * surface, hull): no merging (face f is
 * indices[face_start[f] .. face_start[f + 1]) into points). what names the node in
 * messages; numbered says the points are a polyhedron's own, numbered in the file (an
 * edge is named by its point numbers, else by its ends' coordinates, and a mesh without
 * volume is "polyhedron without volume"). A sound mesh is closed (every edge in exactly
 * two faces) and consistently oriented (the two faces run along it in opposite
 * directions); inward or outward winding are both taken (the signed volume decides).
 * One that is not sound is treated as build_mesh_solid treats a polyhedron: an error
 * with c->strict; else, with a warning in c->notes, left out in faithful mode (*empty
 * = "") and drawn by the parity rule in exact mode. Triangles and quads are split
 * into fans, larger polygons (a builder's caps) in halves, from end to end and
 * then each side, and a polyhedron's (numbered) into fans; a polygon that is not
 * convex gives triangles whose signed areas sum to it either way. A mesh without
 * volume sets *empty to a warning and fills nothing. */
sc_status build_mesh_prim(const build_ctx *c, const sc_location *loc, const char *what,
                          int numbered, const vec3 *points, uint32_t point_count,
                          const uint32_t *indices, const uint32_t *face_start,
                          uint32_t face_count, prim *out, const char **empty);

/* The mesh leaf of tri_count triangles, corners[3 t .. 3 t + 3) each (a
 * CGAL Nef polyhedron's boundary), their corners merged where they are
 * equal; drawn as it is, unchecked (build_mesh_prim otherwise). */
sc_status build_mesh_soup(const build_ctx *c, const sc_location *loc, const char *what,
                          const vec3 *corners, uint32_t tri_count, prim *out,
                          const char **empty);

/* How far the numbers of the mesh file at path (STL or OFF) may lie from
 * the surface they were written from: a binary STL's floats, half a
 * float's unit in the last place; a text file whose coordinates need 6 to
 * 14 significant digits, half a unit in the last digit of that many (a
 * file of fewer digits may be exact, and one of more is taken as exact).
 * offset bounds how far a point moves, volume (its surface area times
 * offset) the volume between the surface as written and as meant. 0 when
 * the file cannot be read or is taken as exact. */
typedef struct build_mesh_rounding_info {
    int digits; /* significant digits of a text file; 0 for binary STL */
    double offset, volume;
} build_mesh_rounding_info;

int build_mesh_rounding(const char *path, build_mesh_rounding_info *out);

/* The faces of OpenSCAD 2021.01's own mesh on a builder's points, where the
 * builder mends it into another (a linear_extrude scaled to 0 at its top,
 * whose collapsed walls it splits): what faithful mode checks is closed
 * where OpenSCAD hands the mesh to CGAL. cap_of (or NULL): for each face,
 * 0, or which cap of an extrusion it belongs to (1, 2): OpenSCAD
 * tessellates each cap's polygons (Polygon2d::tessellate, CGAL's
 * constrained Delaunay triangulation), which splits a cap's edge at any
 * point of that cap lying on it, where the side faces keep the edge whole
 * (taken here as a point within 2^-22 of the edge: edge_stops). */
typedef struct build_mesh_checks {
    const uint32_t *indices, *face_start;
    uint32_t face_count;
    const uint8_t *cap_of;
} build_mesh_checks;

/* build_mesh_prim drawing one mesh and checking another: in faithful mode,
 * where OpenSCAD hands the mesh to CGAL (not c->drawn_as_is), a mesh
 * closed as built is left out (or with c->strict an error) when openscad's
 * faces, their points merged on OpenSCAD's grid, are not closed as CGAL's
 * polyhedron builder takes them: an edge of more than two faces, or a
 * point whose faces make more than one fan. build_mesh_prim checks its own
 * faces so. */
sc_status build_mesh_prim_checked(const build_ctx *c, const sc_location *loc,
                                  const char *what, int numbered, const vec3 *points,
                                  uint32_t point_count, const uint32_t *indices,
                                  const uint32_t *face_start, uint32_t face_count,
                                  const build_mesh_checks *openscad, prim *out,
                                  const char **empty);

/* A closed mesh as its faces: a polyhedron's or an imported mesh's on merged
 * points (build_mesh_merge, with names), or a builder's for CGAL (nef.h's
 * from_mesh: extrusions, surface, imports), whose faces may have holes (with
 * face_loops). Loop k is indices[face_start[k] .. face_start[k + 1]) into
 * points. Without face_loops, face f is loop f; with it, face f is the loops
 * face_loops[f] .. face_loops[f + 1], an outline and its holes in one plane
 * (build_mesh_sound and build_mesh_solid take faces of one loop only). All
 * malloc'd, freed with build_mesh_faces_free; or, lent, the arrays of an
 * import's faces that the build's files (build_imports) hold, which
 * build_mesh_faces_free leaves to them. */
typedef struct build_mesh_faces {
    vec3 *points;
    uint32_t *names; /* NULL, or names[i]: the number in the file of merged point i */
    uint32_t point_count;
    uint32_t *indices;
    uint32_t *face_start; /* loop starts: one more than the loops */
    uint32_t *face_loops; /* NULL, or face_count + 1 entries */
    uint32_t face_count;
    /* NULL, or for each face the point OpenSCAD's face passes through
     * twice (UINT32_MAX: none), which a null ear cleaned here may hide */
    uint32_t *twice;
    /* NULL, or where merged point i is written, where the points have moved
     * (build_mesh_merge_moved): messages name an import's points so */
    vec3 *written;
    int lent; /* the arrays belong to the build's files (build_import_faces) */
} build_mesh_faces;

/* Merges the points as OpenSCAD does before it checks a mesh: snapped to
 * its grid of 2^-20, a point joins any point before it in the same or a
 * neighbouring cell (docs/meshes.md); faces lose repeated points and
 * null ears, and faces left with fewer than 3 points go. reversed: the
 * faces are a polyhedron's, which OpenSCAD reads back to front (the order
 * points are met in). In faithful mode where OpenSCAD hands the mesh to
 * CGAL (c->faithful, not c->drawn_as_is) a point becomes OpenSCAD's: its
 * cell's corner, in float; else it keeps the coordinates of the first
 * point of its cell (OpenSCAD snaps only where it makes a Nef
 * polyhedron). On success *f owns its arrays. */
sc_status build_mesh_merge(const build_ctx *c, const sc_location *loc, int reversed,
                           const vec3 *points, uint32_t point_count,
                           const uint32_t *indices, const uint32_t *face_start,
                           uint32_t face_count, build_mesh_faces *f);
/* v as OpenSCAD 2021.01's grid of 2^-20 snaps a coordinate of a mesh it
 * hands to CGAL (build_mesh_merge in faithful mode): its cell's corner,
 * toward zero, in float, into *out; 0 for one past the grid's range (2^40,
 * where a point is not snapped), *out then v. */
int build_mesh_snap(double v, double *out);
/* build_mesh_merge of the points moved by *moved (NULL: as they are),
 * each face turned where it mirrors, as OpenSCAD 2021.01's
 * PolySet::transform moves a mesh before a CGAL operation or the render
 * takes it. */
sc_status build_mesh_merge_moved(const build_ctx *c, const sc_location *loc, int reversed,
                                 const affine *moved, const vec3 *points,
                                 uint32_t point_count, const uint32_t *indices,
                                 const uint32_t *face_start, uint32_t face_count,
                                 build_mesh_faces *f);
/* Splits a frame m where a CGAL operation takes a leaf under it: since
 * is the map from that operation down to m (NULL: m is all of it),
 * returned (m where since is NULL), with *rest what takes it on to m (m
 * is *rest after it). NULL where that map cannot be undone: *rest is
 * then m. */
const affine *build_mesh_since(const affine *since, const affine *m, affine *rest);
void build_mesh_faces_free(build_mesh_faces *f);

/* Whether OpenSCAD 2021.01 finds f convex where it makes a Nef
 * polyhedron of it (createNefPolyhedronFromPolySet: is_approximately_convex
 * on the faces as its tessellation leaves them), and so takes the convex
 * hull of its points (nef.h's hull) rather than CGAL's polyhedron builder.
 * reversed: f's faces are a polyhedron's, as written. 1, 0, or -1 when
 * memory runs out. */
int build_mesh_convex_for_cgal(const build_mesh_faces *f, int reversed);

/* Whether OpenSCAD 2021.01's is_approximately_convex takes these faces as
 * written (not tessellated: PolySet::is_convex, which its minkowski asks),
 * each face's points in the order OpenSCAD holds them, equal points under
 * one number: every edge runs once each way, every fold between two faces
 * turns outward or by less than 0.1 degrees, every face is reached from
 * the first. 1, 0, or -1 when memory runs out. */
int build_mesh_convex_as_written(const vec3 *points, uint32_t point_count,
                                 const uint32_t *indices, const uint32_t *face_start,
                                 uint32_t face_count);

/* A point and a number of its own (its position, a triangle's), to sort
 * points by their coordinates, x then y then z, then by the number. */
typedef struct build_mesh_keyed {
    vec3 p;
    uint32_t index;
} build_mesh_keyed;
int build_mesh_keyed_cmp(const void *a, const void *b);

/* The pieces of a set of faces joined by their edges (either way round):
 * face f of face_count, indices[face_start[f] .. face_start[f + 1]), or
 * with face_start NULL triangle f, indices[3 f .. 3 f + 3). Fills parent
 * (face_count entries) with a union-find forest whose roots
 * (build_mesh_piece) name the pieces. 0 when memory runs out. */
int build_mesh_pieces(const uint32_t *indices, const uint32_t *face_start,
                      uint32_t face_count, uint32_t *parent);
/* The piece of face f in build_mesh_pieces' forest: its root, halving the
 * path on the way. */
uint32_t build_mesh_piece(uint32_t *parent, uint32_t f);

/* 1 when f is closed (every edge in exactly two faces) and consistently
 * oriented; else 0, with what is wrong, naming an edge, in why (what
 * names the node); -1 when memory ran out. */
int build_mesh_sound(const build_mesh_faces *f, const char *what, int numbered, char *why,
                     size_t size);
/* Whether OpenSCAD 2021.01 finds f closed where it hands it to CGAL:
 * CGAL's polyhedron builder takes its faces in order and skips one that
 * passes through a point twice, runs an edge the way a face taken runs it,
 * or meets a point whose faces already close; the faces taken must then
 * leave no edge with one face ("not closed") and no point off them
 * ("invalid"), and the faces about each point must make one fan. A mesh
 * OpenSCAD finds convex (its is_approximately_convex, the faces turned as
 * OpenSCAD holds them: a polyhedron's, numbered, back to front) it takes
 * as its hull, without the builder: sound. With planes, where OpenSCAD
 * makes a Nef polyhedron of it (a boolean's operand; not a minkowski()'s
 * own child, which OpenSCAD finds convex on its faces untriangulated),
 * also not lost on CGAL's assertions about a face out of its plane
 * (nef.h's plane_check; a plugin that does not load leaves it sound).
 * 1; 0, with what is wrong in why and OpenSCAD's message in *openscad; -1
 * when memory ran out. */
int build_mesh_cgal_sound(const build_mesh_faces *f, const char *what, int numbered,
                          int planes, char *why, size_t size, const char **openscad);
/* f's faces (one loop a face; lent arrays are copied first) as CGAL's Nef
 * polyhedron of a mesh takes them from OpenSCAD 2021.01: without the
 * faces CGAL's polyhedron builder skips (build_mesh_cgal_sound), a face
 * given twice, say, unless OpenSCAD finds the mesh convex; then made the
 * triangles OpenSCAD's tessellation makes of them, where the mesh is not
 * convex (a quad out of its plane split on OpenSCAD's diagonal, larger
 * faces out of their planes as libtess2 and OpenSCAD's mending split
 * them; larger faces in their planes stay whole, for the plugin to
 * triangulate). numbered: a polyhedron's faces (as for
 * build_mesh_solid). */
sc_status build_mesh_cgal_faces(const build_ctx *c, const sc_location *loc,
                                const char *what, build_mesh_faces *f, int numbered);
/* build_mesh_cgal_sound where faithful mode hands f to CGAL (c->faithful,
 * not c->drawn_as_is), else build_mesh_sound. */
int build_mesh_cgal_closed(const build_ctx *c, const build_mesh_faces *f,
                           const char *what, int numbered, char *why, size_t size);

/* The leaf of a polyhedron or an imported mesh on merged faces: faces that
 * are not planar split as OpenSCAD 2021.01 splits them
 * (build_mesh_face_triangles), planar faces of five or more points into fans. A mesh that
 * is not sound (build_mesh_sound) is an error when strict (--strict) or without c->note;
 * else in faithful mode it is left out as OpenSCAD leaves it out (*empty = "", the
 * warning in c->note), and in exact mode it is built with the parity rule, the warning in
 * c->note. */
sc_status build_mesh_solid(const build_ctx *c, const sc_location *loc, const char *what,
                           int numbered, int strict, const build_mesh_faces *f, prim *out,
                           const char **empty);

/* Which diagonal OpenSCAD 2021.01 splits the quad q[0..3] along: 0 for
 * q0-q2, 1 for q1-q3 (libtess2's constrained Delaunay triangulation, see
 * build_mesh.c). reversed: the quad is a polyhedron's face, which OpenSCAD
 * hands to libtess2 back to front. */
int build_mesh_quad_diagonal(const vec3 q[4], int reversed);

/* 1 when the quad q[0..3] crosses itself in the plane libtess2 projects
 * it onto (a bow tie; reversed as for build_mesh_quad_diagonal). OpenSCAD
 * 2021.01 splits such a quad by the order of its hash tables, which
 * build_mesh_solid follows (see build_mesh.c). */
int build_mesh_quad_crosses(const vec3 q[4], int reversed);

/* Splits the face p[0..n) into triangles as OpenSCAD 2021.01 does
 * (libtess2's constrained Delaunay triangulation, see build_mesh.c),
 * writing 3 positions in p per triangle into tris, which has room for cap
 * (at least n - 2) triangles, and how many into *written: n - 2, or more
 * where the projection crosses itself and OpenSCAD's mending makes more.
 * Each triangle is wound as the face. reversed: a polyhedron's face,
 * which OpenSCAD hands to libtess2 back to front. numbers: OpenSCAD's
 * number of each point of p, in the order its tessellation first meets
 * them (NULL: the order in which it holds this face), which sets how it
 * mends points that lie above one another (tess_mend.h). Returns 1 for
 * OpenSCAD's triangles; 0 for a fan about p[0] (n - 2 triangles), written
 * where libtess2's sweep is not followed (docs/meshes.md), the face has
 * no area, OpenSCAD makes more than cap triangles, or it has more than
 * 4096 points (and for fewer than 3); -1 when memory ran out. */
int build_mesh_face_triangles(const vec3 *p, uint32_t n, int reversed,
                              const uint32_t *numbers, uint32_t *tris, uint32_t cap,
                              uint32_t *written);

/* Moves the count points p, in order, onto OpenSCAD 2021.01's grid as
 * Grid3d's align moves them where it hands a mesh to CGAL (the merge's
 * rule, build_mesh.c): each coordinate to the multiple of 2^-20 towards
 * zero, exactly; a point whose cell no point before it took goes where the
 * nearest taken cell among the 26 around it went, if any. A point past
 * 2^40 stays where it is. Fails only when memory runs out (at loc). */
sc_status build_mesh_grid_align(const build_ctx *c, const sc_location *loc, vec3 *p,
                                uint32_t count);

/* The path of a file a model names: relative names are relative to the
 * directory of the file being read (c->file). malloc'd; NULL when memory
 * runs out. */
char *build_file_path(const build_ctx *c, const char *name);

struct build_prims; /* build_hull.h */

/* Frees what imports holds (build_ctx.h) and zeroes it. */
void build_imports_free(build_imports *imports);

/* How many files imports holds (read, and not yet let go). */
size_t build_imports_held(const build_imports *imports);

/* The builder of n (a hull, a minkowski, the solid CGAL makes of a subtree)
 * is done with the imports below it, the last of their readers: their
 * files are let go from c->imports, which still knows their triangles
 * were charged. The measure of a resize is not such a builder (its leaf
 * comes after), and a subtree skipped ('*', '%') is not looked into, as
 * the builders do not read it. A preview's part ('#') built afterwards
 * reads its files again. */
void build_imports_done(const build_ctx *c, const model_node *n);

/* OpenSCAD 2021.01's message for a mesh it cannot take into CGAL. */
extern const char build_openscad_not_closed[];
/* Its message for a closed mesh with a point on no face its builder takes. */
extern const char build_openscad_invalid[];
/* The *empty (an empty string) of an import of an STL file with a corner
 * that is nan or inf, which OpenSCAD 2021.01 reads and then finds not
 * closed where CGAL takes it: left out of a union, as the import is here,
 * but emptying a minkowski (build_hull.c: closed_check). */
extern const char build_import_not_finite[];

/* An import of a file whose extension no reader takes (model.h,
 * MODEL_MESH_UNSUPPORTED), as OpenSCAD 2021.01 logs it, before it opens
 * anything: "Unsupported file format while trying to import file 'NAME'",
 * and the import empty; the error at loc with strict or c->strict. */
sc_status build_import_unsupported(const build_ctx *c, const sc_location *loc,
                                   const char *name, int strict);

/* import(file) (its name checked by the lowering pass): an STL (ASCII or
 * binary), OFF, AMF or 3MF file, its path relative to the directory of the
 * file being read, built by build_mesh_solid (strict as there). An AMF or
 * 3MF file of several objects gives one leaf per object, which OpenSCAD
 * unites (the caller unites them), each object checked, turned outward,
 * left out or drawn by the parity rule on its own, with its warnings in
 * c->notes; any other file gives one leaf. out->items is malloc'd (free
 * it, also after an error); *empty is set, and out left empty, when the
 * import makes nothing ("" when its warnings were given). */
sc_status build_import_parts(const build_ctx *c, const model_import *import, int strict,
                             struct build_prims *out, const char **empty);
/* The same, strict as c->strict, for the builders that need closed
 * solids (CGAL; the joined mesh of build_import): an object that is not
 * closed, one of several or alone, is left out with its warning in both
 * modes, as OpenSCAD 2021.01 leaves it out of the objects' union (a CGAL
 * union) and of the Nef polyhedron a cut or boolean makes of it, also
 * where c takes no note. */
sc_status build_import_solids(const build_ctx *c, const model_import *import,
                              struct build_prims *out, const char **empty);
/* build_import_solids as one leaf: several objects' leaves joined into one
 * mesh (winding numbers add up to their union), for the builders that
 * take an import's triangles as a solid (projection's cut). */
sc_status build_import(const build_ctx *c, const model_import *import, prim *out,
                       const char **empty);
/* build_import for the builders that take only an import's corners or
 * faces (hull, projection without cut, and minkowski once closed_check in
 * build_hull.c has found CGAL takes it): a file of one object gives its
 * mesh closed or not, one that is not closed as the parity rule takes it
 * (its triangles as they come), without a warning and never an error, as
 * OpenSCAD 2021.01 hulls and projects the mesh it reads without asking
 * that it be closed; several objects are build_import's union, as
 * OpenSCAD's is a CGAL union. */
sc_status build_import_mesh(const build_ctx *c, const model_import *import, prim *out,
                            const char **empty);
/* An import that is left out (a 3D child of a 2D operation), read as
 * OpenSCAD 2021.01 reads it before it ignores it: its warnings (a file
 * that does not open or parse, a format no reader takes; an object of
 * several that is not closed, left out of their union) or, strict as
 * c->strict, the error; a single mesh closed or not, silently
 * (build_import_mesh). *empty is set when it makes nothing. The file is
 * not kept in c->imports. */
sc_status build_import_left_out(const build_ctx *c, const model_import *import,
                                const char **empty);
/* build_import_parts, not strict, for a file of one object (STL, OFF),
 * which hands its merged faces to *faces (for CGAL, whose faces must not
 * overlap as the leaf's fans of a face that is not convex do), with the
 * leaf's warnings; *faces empty when *empty is set and for several
 * objects (each a leaf of triangles, build_import_parts); free with
 * build_mesh_faces_free. Where c->imports keeps the file, the faces are
 * lent from there, not copied (faces->lent): read them before anything
 * else reads an import or lets the files go (build_imports_free, the leaf
 * built where the import stands). */
sc_status build_import_faces(const build_ctx *c, const model_import *import,
                             const char **empty, build_mesh_faces *faces);

/* linear_extrude (build_extrude.c): exact in default mode without twist or
 * scale over the 2D nodes build_region.h reads, else OpenSCAD's mesh of it
 * (build_extrude_faithful.h). */
sc_status build_linear_extrude(const build_ctx *c, const model_node *n, int emit,
                               prim *out, const char **empty);

#endif
